//! Writing a run's documents to disk, all or nothing, and printing to
//! standard output without panicking on a closed pipe or a full disk.
//!
//! A run folder (`tmm run --out DIR`, `--svg DIR`) is built complete in a
//! temporary folder beside its target and then moved into place, so a failed
//! run leaves nothing and a finished one leaves exactly its own files. A
//! folder tmm made carries a marker file listing what it wrote; the next run
//! replaces such a folder as a whole. tmm never deletes a file it did not
//! write: a folder with other files is refused (or, for `--svg`, written
//! into file by file), and since every file is created fresh and renamed
//! into place, no write follows a symbolic link planted in the folder.

use std::io::Write;
use std::path::{Path, PathBuf};

use tmm_report::Error;
use tmm_report::output::{Document, Documents, check_finite_in};

/// The marker file of a folder tmm made.
pub const MARKER: &str = ".tmm-out";

/// The first line of the marker; the following lines list the files.
const MARKER_HEAD: &str = "# written by tmm; the next run replaces this folder and the files listed here";

/// How a folder that already exists is treated.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Existing {
    /// Refuse a folder that holds files tmm did not write.
    Refuse,
    /// Write the files into such a folder one by one (each atomically),
    /// deleting nothing.
    AddFiles,
}

/// Write `docs` as the folder `out`: created fresh, or replacing a folder
/// tmm made (or an empty one) as a whole. Returns the paths written.
pub fn write_folder(out: &Path, docs: &Documents, existing: Existing) -> Result<Vec<PathBuf>, Error> {
    for d in docs {
        check_relative(&d.path)?;
    }
    match folder_state(out)? {
        State::Absent | State::Empty | State::Ours => replace_folder(out, docs),
        State::Foreign(file) => match existing {
            Existing::AddFiles => {
                let files: Vec<(PathBuf, &[u8])> = docs.iter().map(|d| (out.join(&d.path), d.bytes.as_slice())).collect();
                write_files(&files)?;
                Ok(files.into_iter().map(|f| f.0).collect())
            }
            Existing::Refuse => Err(Error::input(
                "--out",
                format!(
                    "the folder {} already holds files tmm did not write (e.g. {}); tmm never deletes them",
                    out.display(),
                    file.display()
                ),
            )
            .with_help("choose a new or empty folder with --out, or remove the folder first")),
        },
    }
}

/// Write each file atomically (a temporary file beside it, then a rename):
/// all are written before any is renamed into place, and on a failure the
/// temporary files are removed.
pub fn write_files(files: &[(PathBuf, &[u8])]) -> Result<(), Error> {
    let mut temps: Vec<(PathBuf, &Path)> = Vec::new();
    let result = (|| {
        for (path, bytes) in files {
            if path.is_dir() {
                return Err(Error::Io(format!("cannot write {}: it is a folder", path.display())));
            }
            let dir = parent(path);
            std::fs::create_dir_all(dir).map_err(|e| Error::io(dir, e))?;
            let tmp = dir.join(format!(".{}.tmm-tmp-{}", file_name(path), std::process::id()));
            write_new(&tmp, bytes)?;
            temps.push((tmp, path));
        }
        for (tmp, path) in &temps {
            std::fs::rename(tmp, path).map_err(|e| Error::io(path, e))?;
        }
        Ok(())
    })();
    if result.is_err() {
        for (tmp, _) in &temps {
            let _ = std::fs::remove_file(tmp);
        }
    }
    result
}

/// Print text on standard output. A closed pipe (`tmm … | head -1`) ends
/// the program quietly with exit code 0, as Unix tools do; any other failure
/// (a full disk) is an error with exit code 1. The text passes the same
/// non-finite check as every file.
pub fn print(text: &str) -> Result<(), Error> {
    check_finite_in(&Document::text("standard output", text), crate::cmd::common::excused())?;
    let mut out = std::io::stdout().lock();
    let r = out.write_all(text.as_bytes()).and_then(|()| out.flush());
    match r {
        Ok(()) => Ok(()),
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => std::process::exit(0),
        Err(e) => Err(Error::Io(format!("cannot write to standard output: {e}"))),
    }
}

/// What is at the output folder's place now.
enum State {
    Absent,
    Empty,
    /// A folder tmm made, holding only the files its marker lists.
    Ours,
    /// A folder with this file, which tmm did not write.
    Foreign(PathBuf),
}

fn folder_state(out: &Path) -> Result<State, Error> {
    let meta = match std::fs::symlink_metadata(out) {
        Ok(m) => m,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(State::Absent),
        Err(e) => return Err(Error::io(out, e)),
    };
    if meta.file_type().is_symlink() {
        return Err(Error::input(
            "--out",
            format!("{} is a symbolic link; tmm does not write through links", out.display()),
        )
        .with_help("give the real folder's path"));
    }
    if !meta.is_dir() {
        return Err(
            Error::input("--out", format!("{} exists and is not a folder", out.display())).with_help("choose a new or empty folder")
        );
    }
    let listed = match std::fs::read_to_string(out.join(MARKER)) {
        Ok(text) if text.starts_with(MARKER_HEAD) => Some(
            text.lines()
                .skip(1)
                .filter(|l| !l.is_empty())
                .map(PathBuf::from)
                .collect::<Vec<_>>(),
        ),
        _ => None,
    };
    let mut found = Vec::new();
    list_tree(out, Path::new(""), &mut found).map_err(|e| Error::io(out, e))?;
    match listed {
        None if found.is_empty() => Ok(State::Empty),
        None => Ok(State::Foreign(out.join(&found[0]))),
        Some(listed) => match found.iter().find(|f| f.as_path() != Path::new(MARKER) && !listed.contains(f)) {
            Some(f) => Ok(State::Foreign(out.join(f))),
            None => Ok(State::Ours),
        },
    }
}

/// Every file (and link) under `dir`, relative to the top.
fn list_tree(top: &Path, rel: &Path, found: &mut Vec<PathBuf>) -> std::io::Result<()> {
    for entry in std::fs::read_dir(top.join(rel))? {
        let entry = entry?;
        let r = rel.join(entry.file_name());
        if entry.file_type()?.is_dir() {
            list_tree(top, &r, found)?;
        } else {
            found.push(r);
        }
    }
    Ok(())
}

/// Build the folder complete beside `out`, then swap it in.
fn replace_folder(out: &Path, docs: &Documents) -> Result<Vec<PathBuf>, Error> {
    let dir = parent(out);
    std::fs::create_dir_all(dir).map_err(|e| Error::io(dir, e))?;
    let name = file_name(out);
    let pid = std::process::id();
    let tmp = dir.join(format!(".{name}.tmm-tmp-{pid}"));
    let old = dir.join(format!(".{name}.tmm-old-{pid}"));
    let _ = std::fs::remove_dir_all(&tmp);
    let built = build_folder(&tmp, docs);
    if let Err(e) = built {
        let _ = std::fs::remove_dir_all(&tmp);
        return Err(e);
    }
    let had_old = out.exists();
    if had_old {
        if let Err(e) = std::fs::rename(out, &old) {
            let _ = std::fs::remove_dir_all(&tmp);
            return Err(Error::io(out, e));
        }
    }
    if let Err(e) = std::fs::rename(&tmp, out) {
        if had_old {
            let _ = std::fs::rename(&old, out);
        }
        let _ = std::fs::remove_dir_all(&tmp);
        return Err(Error::io(out, e));
    }
    if had_old {
        // Only tmm's own files (checked by `folder_state`) or nothing.
        let _ = std::fs::remove_dir_all(&old);
    }
    Ok(docs.iter().map(|d| out.join(&d.path)).collect())
}

fn build_folder(tmp: &Path, docs: &Documents) -> Result<(), Error> {
    std::fs::create_dir(tmp).map_err(|e| Error::io(tmp, e))?;
    let mut marker = String::from(MARKER_HEAD);
    marker.push('\n');
    for d in docs {
        let p = tmp.join(&d.path);
        std::fs::create_dir_all(parent(&p)).map_err(|e| Error::io(&p, e))?;
        write_new(&p, &d.bytes)?;
        marker.push_str(&d.path);
        marker.push('\n');
    }
    write_new(&tmp.join(MARKER), marker.as_bytes())
}

/// Create a new file (never opening an existing one, so never following a
/// link) and write it whole.
fn write_new(path: &Path, bytes: &[u8]) -> Result<(), Error> {
    let _ = std::fs::remove_file(path);
    let mut f = std::fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(path)
        .map_err(|e| Error::io(path, e))?;
    f.write_all(bytes).and_then(|()| f.sync_data()).map_err(|e| Error::io(path, e))
}

fn check_relative(p: &str) -> Result<(), Error> {
    let path = Path::new(p);
    if p.is_empty() || path.is_absolute() || path.components().any(|c| !matches!(c, std::path::Component::Normal(_))) {
        return Err(Error::Io(format!("refusing to write outside the output folder: {p}")));
    }
    Ok(())
}

fn parent(p: &Path) -> &Path {
    match p.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    }
}

fn file_name(p: &Path) -> String {
    p.file_name()
        .map_or_else(|| "out".to_string(), |n| n.to_string_lossy().into_owned())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn docs(names: &[&str]) -> Documents {
        let mut d = Documents::new();
        for n in names {
            d.add_text(*n, format!("content of {n}")).unwrap();
        }
        d
    }

    fn tempdir(tag: &str) -> PathBuf {
        let p = std::env::temp_dir().join(format!("tmm-write-{tag}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&p);
        std::fs::create_dir_all(&p).unwrap();
        p
    }

    #[test]
    fn a_second_run_replaces_the_first_as_a_whole() {
        let top = tempdir("replace");
        let out = top.join("out");
        write_folder(&out, &docs(&["a/x.svg", "a/y.svg", "report.json"]), Existing::Refuse).unwrap();
        assert!(out.join("a/y.svg").exists());
        write_folder(&out, &docs(&["a/x.svg", "report.json"]), Existing::Refuse).unwrap();
        assert!(out.join("a/x.svg").exists());
        assert!(!out.join("a/y.svg").exists(), "a file of the earlier run survived");
        // nothing left beside the folder
        let beside: Vec<_> = std::fs::read_dir(&top).unwrap().map(|e| e.unwrap().file_name()).collect();
        assert_eq!(beside.len(), 1, "{beside:?}");
        std::fs::remove_dir_all(&top).unwrap();
    }

    #[test]
    fn a_foreign_file_is_never_deleted() {
        let top = tempdir("foreign");
        let out = top.join("out");
        write_folder(&out, &docs(&["report.json"]), Existing::Refuse).unwrap();
        std::fs::write(out.join("mine.txt"), "user's").unwrap();
        let e = write_folder(&out, &docs(&["report.json"]), Existing::Refuse).unwrap_err();
        assert_eq!(e.exit_code(), 2);
        assert_eq!(std::fs::read_to_string(out.join("mine.txt")).unwrap(), "user's");
        // adding files leaves it too
        write_folder(&out, &docs(&["b.svg"]), Existing::AddFiles).unwrap();
        assert!(out.join("mine.txt").exists() && out.join("b.svg").exists());
        std::fs::remove_dir_all(&top).unwrap();
    }

    #[cfg(unix)]
    #[test]
    fn a_planted_link_is_replaced_not_followed() {
        let top = tempdir("link");
        let target = top.join("target.txt");
        std::fs::write(&target, "keep").unwrap();
        let dir = top.join("svg");
        std::fs::create_dir_all(&dir).unwrap();
        std::os::unix::fs::symlink(&target, dir.join("a.svg")).unwrap();
        write_files(&[(dir.join("a.svg"), b"new".as_slice())]).unwrap();
        assert_eq!(std::fs::read_to_string(&target).unwrap(), "keep");
        assert_eq!(std::fs::read_to_string(dir.join("a.svg")).unwrap(), "new");
        std::fs::remove_dir_all(&top).unwrap();
    }

    #[test]
    fn paths_stay_inside() {
        assert!(check_relative("../x").is_err());
        assert!(check_relative("/etc/x").is_err());
        assert!(check_relative("a/b.svg").is_ok());
    }
}
