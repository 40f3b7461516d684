//! Writing a run's documents to disk, all or nothing, never touching a file
//! tmm did not write, and printing to standard output without panicking on a
//! closed pipe or a full disk.
//!
//! Every folder tmm writes into carries a marker file, `.tmm-out`, listing
//! the files tmm wrote there; a file it does not list is the user's, and tmm
//! neither deletes nor replaces it.
//!
//! - A new `--out`/`--svg` folder is built complete in a temporary folder
//!   beside its place and renamed in (never over anything that appeared
//!   meanwhile).
//! - A folder tmm made (its marker says so, and it holds only listed files)
//!   is replaced by building the new one beside it and exchanging the two
//!   atomically (`renameat2(RENAME_EXCHANGE)`), so there is never a moment
//!   without a complete folder; then only the listed files are deleted from
//!   the old one, and anything else found there (a file dropped in while the
//!   run wrote) is moved into the new folder.
//! - An existing empty folder (a mount point, `.`), or a folder that cannot
//!   be swapped, is written into in place, keeping its inode, mode and owner.
//! - Into a folder holding other files, `tmm run --out` writes nothing
//!   (exit 2); `--svg DIR` and `tmm note --out DIR` add their files one by
//!   one, refusing (exit 2) any name that exists and is not listed.
//! - Files named on the command line (`--task t.toml`) replace what is there.
//!
//! Each file is written to a temporary name beside it (`.NAME.tmm-tmp-PID-N`,
//! NAME cut to fit 255 bytes) and renamed into place, so no write follows a
//! symbolic link planted in the folder. A failed run, SIGINT, SIGTERM or
//! SIGHUP removes the temporary files and the folders the run created; the
//! leftovers of a killed run (SIGKILL) are removed by the next run that
//! writes beside them, once their process is gone. Messages name the user's
//! path, never a temporary one.

use std::ffi::{CString, OsStr, OsString};
use std::io::Write;
use std::os::unix::ffi::{OsStrExt, OsStringExt};
use std::os::unix::fs::MetadataExt;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU32, Ordering};
use std::sync::{Mutex, MutexGuard};

use tmm_report::Error;
use tmm_report::output::{Document, Documents, check_finite_in};

/// The marker file of a folder tmm wrote into.
pub const MARKER: &str = ".tmm-out";

/// The first line of the marker of a folder tmm made; the following lines
/// list the files.
const MARKER_HEAD: &str = "# written by tmm; the next run replaces this folder and the files listed here";

/// The first line of the marker of a folder tmm did not make but wrote
/// files into.
const MARKER_HEAD_ADDED: &str = "# files written by tmm into this folder; the next run replaces them and nothing else";

/// The longest file name the common file systems take, in bytes.
const NAME_MAX: usize = 255;

/// How a folder that already holds other files is treated.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Existing {
    /// Refuse a folder that holds files tmm did not write.
    Refuse,
    /// Write the files into such a folder one by one (each atomically),
    /// refusing a name that exists and was not written by tmm.
    AddFiles,
}

/// Write `docs` as the folder `out` (given on the command line as
/// `option`): see the module's header for the cases. Returns the paths
/// written.
pub fn write_folder(out: &Path, docs: &Documents, existing: Existing, option: &str) -> Result<Vec<PathBuf>, Error> {
    for d in docs {
        check_relative(&d.path)?;
    }
    check_name_length(out, option)?;
    match folder_state(out, option)? {
        State::Absent => new_folder(out, docs),
        State::Listed { made: true, listed } if can_swap(out) => replace_folder(out, docs, &listed, option),
        State::Empty => write_in_place(out, docs, &[], true, option),
        State::Listed { listed, .. } => write_in_place(out, docs, &listed, true, option),
        State::Foreign { file, listed } => match existing {
            Existing::AddFiles => write_in_place(out, docs, &listed, false, option),
            Existing::Refuse => Err(Error::input(
                option,
                format!(
                    "the folder {} already holds files tmm did not write (e.g. {}); tmm never deletes them",
                    out.display(),
                    file.display()
                ),
            )
            .with_help("choose a new or empty folder, or remove the folder first")),
        },
    }
}

/// Write files named on the command line (`--task t.toml`), replacing what
/// is there: all are written to temporary files before any is renamed into
/// place, and on a failure the temporary files and the folders made for
/// them are removed.
pub fn write_files(files: &[(PathBuf, &[u8])]) -> Result<(), Error> {
    let mut run = Run::default();
    let result = (|| {
        for (path, _) in files {
            check_name_length(path, "the file name")?;
            if path.is_dir() {
                return Err(Error::Io(format!("cannot write {}: it is a folder", path.display())));
            }
        }
        for (path, bytes) in files {
            let dir = parent(path);
            run.create_dirs(dir, path)?;
            clean_leftovers(dir);
            let tmp = run.temp_file(path);
            write_new(&tmp, bytes).map_err(|e| write_error(path, &e))?;
        }
        let mut commit = lock();
        for (i, (path, _)) in files.iter().enumerate() {
            std::fs::rename(&run.files[i], path).map_err(|e| write_error(path, &e))?;
        }
        run.keep(&mut commit);
        Ok(())
    })();
    run.discard();
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

/// Print an error message on standard error. A message that cannot be
/// written (`2>/dev/full`, a closed pipe) is dropped: the exit code still
/// tells the error.
pub fn print_error(text: &str) {
    let mut err = std::io::stderr().lock();
    let _ = err.write_all(text.as_bytes()).and_then(|()| err.flush());
}

/// On SIGINT, SIGTERM or SIGHUP remove the temporary files and folders of
/// the write under way (waiting for a rename into place that has begun to
/// finish), then end as the signal would have.
pub fn clean_up_on_signals() {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
    let Ok(mut signals) = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP]) else {
        return;
    };
    std::thread::spawn(move || {
        if let Some(sig) = signals.forever().next() {
            let mut temps = lock();
            for t in temps.drain(..).rev() {
                t.discard();
            }
            let _ = signal_hook::low_level::emulate_default_handler(sig);
            std::process::exit(128 + sig);
        }
    });
}

/// A temporary file or folder of the write under way, or a folder it made.
enum Temp {
    File(PathBuf),
    Folder(PathBuf),
    MadeDir(PathBuf),
}

impl Temp {
    fn discard(&self) {
        match self {
            Temp::File(p) => {
                let _ = std::fs::remove_file(p);
            }
            Temp::Folder(p) => {
                let _ = remove_ours(p);
            }
            Temp::MadeDir(p) => {
                let _ = std::fs::remove_dir(p);
            }
        }
    }
}

/// What a signal must remove; held locked while files are renamed into
/// place, so a signal waits for a started commit to finish.
static TEMPS: Mutex<Vec<Temp>> = Mutex::new(Vec::new());

fn lock() -> MutexGuard<'static, Vec<Temp>> {
    TEMPS.lock().unwrap_or_else(std::sync::PoisonError::into_inner)
}

/// Run `f` with the registry locked, so a signal's clean-up cannot happen
/// in the middle.
fn lock_then<T>(f: impl FnOnce() -> T) -> T {
    let _temps = lock();
    f()
}

fn register(t: Temp) {
    lock().push(t);
}

fn unregister(p: &Path) {
    unregister_in(&mut lock(), p);
}

fn unregister_in(temps: &mut Vec<Temp>, p: &Path) {
    temps.retain(|t| !matches!(t, Temp::File(q) | Temp::Folder(q) | Temp::MadeDir(q) if q == p));
}

/// The temporary names and made folders of one write, removed by
/// [`Run::discard`] unless cleared after the commit.
#[derive(Default)]
struct Run {
    files: Vec<PathBuf>,
    dirs: Vec<PathBuf>,
}

impl Run {
    /// A registered temporary name beside `target`.
    fn temp_file(&mut self, target: &Path) -> PathBuf {
        let tmp = temp_name(target, "tmp");
        register(Temp::File(tmp.clone()));
        self.files.push(tmp.clone());
        tmp
    }

    /// Create `dir` and the folders above it that are missing, remembering
    /// each made; an error names `target`.
    fn create_dirs(&mut self, dir: &Path, target: &Path) -> Result<(), Error> {
        let mut missing = Vec::new();
        let mut d = dir;
        while std::fs::symlink_metadata(d).is_err() {
            missing.push(d.to_path_buf());
            match d.parent() {
                Some(p) if !p.as_os_str().is_empty() => d = p,
                _ => break,
            }
        }
        for m in missing.into_iter().rev() {
            let mut temps = lock();
            match std::fs::create_dir(&m) {
                Ok(()) => {
                    temps.push(Temp::MadeDir(m.clone()));
                    self.dirs.push(m);
                }
                Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => {}
                Err(e) => return Err(write_error(target, &e)),
            }
        }
        Ok(())
    }

    /// Remove what is left (after a failure), newest first.
    fn discard(&mut self) {
        for f in self.files.drain(..) {
            let _ = std::fs::remove_file(&f);
            unregister(&f);
        }
        for d in self.dirs.drain(..).rev() {
            let _ = std::fs::remove_dir(&d);
            unregister(&d);
        }
    }

    /// Forget the made folders and temporary names (after the commit,
    /// with the registry `temps` locked).
    fn keep(&mut self, temps: &mut Vec<Temp>) {
        for p in self.files.drain(..).chain(self.dirs.drain(..)) {
            unregister_in(temps, &p);
        }
    }
}

/// What is at the output folder's place now.
enum State {
    Absent,
    Empty,
    /// A folder holding only the files its marker lists; `made` if tmm made
    /// the folder itself.
    Listed {
        made: bool,
        listed: Vec<PathBuf>,
    },
    /// A folder with this file, which tmm did not write.
    Foreign {
        file: PathBuf,
        listed: Vec<PathBuf>,
    },
}

fn folder_state(out: &Path, option: &str) -> Result<State, Error> {
    let meta = match std::fs::symlink_metadata(out) {
        Ok(m) => m,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(State::Absent),
        Err(e) => return Err(write_error(out, &e)),
    };
    if meta.file_type().is_symlink() {
        return Err(Error::input(
            option,
            format!("{} is a symbolic link; tmm does not write through links", out.display()),
        )
        .with_help("give the real folder's path"));
    }
    if !meta.is_dir() {
        return Err(Error::input(option, format!("{} exists and is not a folder", out.display())).with_help("choose a new or empty folder"));
    }
    let Some((made, listed)) = read_marker(out) else {
        // No marker: the first entry found is the user's; nothing below it
        // is listed (so `--out /` is refused at once).
        let first = std::fs::read_dir(out)
            .map_err(|e| write_error(out, &e))?
            .next()
            .transpose()
            .map_err(|e| write_error(out, &e))?;
        return Ok(match first {
            None => State::Empty,
            Some(e) => State::Foreign {
                file: out.join(e.file_name()),
                listed: Vec::new(),
            },
        });
    };
    match first_unlisted(out, Path::new(""), &listed).map_err(|e| write_error(out, &e))? {
        Some(f) => Ok(State::Foreign { file: out.join(f), listed }),
        None => Ok(State::Listed { made, listed }),
    }
}

/// The marker of `dir`: whether tmm made the folder, and the files listed.
fn read_marker(dir: &Path) -> Option<(bool, Vec<PathBuf>)> {
    let text = std::fs::read_to_string(dir.join(MARKER)).ok()?;
    let made = if text.starts_with(MARKER_HEAD) {
        true
    } else if text.starts_with(MARKER_HEAD_ADDED) {
        false
    } else {
        return None;
    };
    let listed = text
        .lines()
        .skip(1)
        .filter(|l| check_relative(l).is_ok())
        .map(PathBuf::from)
        .collect();
    Some((made, listed))
}

/// The first file (or link) under `top/rel` that is neither the marker nor
/// listed; the walk stops there.
fn first_unlisted(top: &Path, rel: &Path, listed: &[PathBuf]) -> std::io::Result<Option<PathBuf>> {
    for entry in std::fs::read_dir(top.join(rel))? {
        let entry = entry?;
        let r = rel.join(entry.file_name());
        if entry.file_type()?.is_dir() {
            if let Some(f) = first_unlisted(top, &r, listed)? {
                return Ok(Some(f));
            }
        } else if r.as_path() != Path::new(MARKER) && !listed.contains(&r) {
            return Ok(Some(r));
        }
    }
    Ok(None)
}

/// Whether `out` can be swapped for a folder built beside it: it has a name
/// (not `.` or `/`) and is not a mount point.
fn can_swap(out: &Path) -> bool {
    if !matches!(out.components().next_back(), Some(std::path::Component::Normal(_))) {
        return false;
    }
    match (std::fs::metadata(out), std::fs::metadata(parent(out))) {
        (Ok(a), Ok(b)) => a.dev() == b.dev() && a.ino() != b.ino(),
        _ => false,
    }
}

/// Build the folder complete beside `out` (which does not exist) and
/// rename it in, never over anything that appeared meanwhile.
fn new_folder(out: &Path, docs: &Documents) -> Result<Vec<PathBuf>, Error> {
    let mut run = Run::default();
    let result = (|| {
        let dir = parent(out);
        run.create_dirs(dir, out)?;
        clean_leftovers(dir);
        let tmp = build_beside(out, docs)?;
        let mut commit = lock();
        if let Err(e) = rename_noreplace(&tmp, out) {
            remove_ours(&tmp);
            unregister_in(&mut commit, &tmp);
            return Err(write_error(out, &e));
        }
        unregister_in(&mut commit, &tmp);
        run.keep(&mut commit);
        Ok(docs.iter().map(|d| out.join(&d.path)).collect())
    })();
    run.discard();
    result
}

/// Replace the folder tmm made at `out` (holding the files `listed`): build
/// the new one beside it, exchange the two atomically, delete the listed
/// files from the old one and move anything else in it into the new one.
fn replace_folder(out: &Path, docs: &Documents, listed: &[PathBuf], option: &str) -> Result<Vec<PathBuf>, Error> {
    check_writable(out, listed, option)?;
    let dir = parent(out);
    clean_leftovers(dir);
    let tmp = build_beside(out, docs)?;
    let mut commit = lock();
    if let Err(e) = exchange(&tmp, out) {
        remove_ours(&tmp);
        unregister_in(&mut commit, &tmp);
        return Err(write_error(out, &e));
    }
    // `tmp` now holds the old folder.
    let kept = retire(&tmp, out);
    unregister_in(&mut commit, &tmp);
    drop(commit);
    match kept {
        None => Ok(docs.iter().map(|d| out.join(&d.path)).collect()),
        Some(f) => Err(Error::Io(format!(
            "{} was replaced, but a file put into it while tmm wrote could not be moved into the new folder; it is kept at {}",
            out.display(),
            f.display()
        ))),
    }
}

/// Remove the old folder `old` (exchanged out of `new`'s place): its listed
/// files are deleted, any other file is moved to the same place in `new`.
/// Returns a file that could not be moved (and so stays in `old`).
fn retire(old: &Path, new: &Path) -> Option<PathBuf> {
    if remove_ours(old) {
        return None;
    }
    let mut rest = Vec::new();
    let _ = leaves(old, Path::new(""), &mut rest);
    let mut stuck = None;
    for r in rest {
        let to = new.join(&r);
        let _ = std::fs::create_dir_all(parent(&to));
        if rename_noreplace(&old.join(&r), &to).is_err() {
            stuck.get_or_insert(old.join(&r));
        }
    }
    prune_empty(old);
    let _ = std::fs::remove_dir(old);
    stuck
}

/// Every entry under `top/rel` that is not a folder, relative to `top`.
fn leaves(top: &Path, rel: &Path, found: &mut Vec<PathBuf>) -> std::io::Result<()> {
    for entry in std::fs::read_dir(top.join(rel))? {
        let entry = entry?;
        let r = rel.join(entry.file_name());
        if entry.file_type()?.is_dir() {
            leaves(top, &r, found)?;
        } else {
            found.push(r);
        }
    }
    Ok(())
}

/// Delete the files the marker of `dir` lists, the marker, the folders left
/// empty and `dir` itself if it is empty then; whether `dir` is gone.
fn remove_ours(dir: &Path) -> bool {
    if let Some((_, listed)) = read_marker(dir) {
        for f in &listed {
            let _ = std::fs::remove_file(dir.join(f));
        }
    }
    let _ = std::fs::remove_file(dir.join(MARKER));
    prune_empty(dir);
    std::fs::remove_dir(dir).is_ok() || std::fs::symlink_metadata(dir).is_err()
}

/// Remove the empty folders under `dir` (not `dir` itself), deepest first.
fn prune_empty(dir: &Path) {
    let Ok(entries) = std::fs::read_dir(dir) else { return };
    for entry in entries.flatten() {
        if entry.file_type().is_ok_and(|t| t.is_dir()) {
            let p = entry.path();
            prune_empty(&p);
            let _ = std::fs::remove_dir(&p);
        }
    }
}

/// Build the new folder at a registered temporary name beside `out`; its
/// marker is written first, so a folder left by a killed run lists every
/// file in it.
fn build_beside(out: &Path, docs: &Documents) -> Result<PathBuf, Error> {
    let tmp = temp_name(out, "tmp");
    register(Temp::Folder(tmp.clone()));
    let built = (|| {
        lock_then(|| std::fs::create_dir(&tmp)).map_err(|e| beside_error(out, &e))?;
        let mut made = Vec::new();
        write_new(
            &tmp.join(MARKER),
            marker_text(MARKER_HEAD, docs.iter().map(|d| Path::new(&d.path))).as_bytes(),
        )
        .map_err(|e| write_error(out, &e))?;
        for d in docs {
            let p = tmp.join(&d.path);
            let dir = parent(&p);
            if !made.iter().any(|m: &PathBuf| m == dir) {
                let _temps = lock();
                std::fs::create_dir_all(dir).map_err(|e| write_error(&out.join(&d.path), &e))?;
                made.push(dir.to_path_buf());
            }
            write_new(&p, &d.bytes).map_err(|e| write_error(&out.join(&d.path), &e))?;
        }
        Ok(())
    })();
    if let Err(e) = built {
        remove_ours(&tmp);
        unregister(&tmp);
        return Err(e);
    }
    Ok(tmp)
}

/// Write `docs` into the existing folder `out` file by file. A name that
/// exists and is not in `listed` is refused before anything is written.
/// With `prune`, the listed files the new run does not write are deleted
/// (the folder is replaced in place); without, they are kept (files added).
/// At every moment the marker lists every file tmm wrote there.
fn write_in_place(out: &Path, docs: &Documents, listed: &[PathBuf], prune: bool, option: &str) -> Result<Vec<PathBuf>, Error> {
    let new: Vec<PathBuf> = docs.iter().map(|d| PathBuf::from(&d.path)).collect();
    for rel in &new {
        let target = out.join(rel);
        match std::fs::symlink_metadata(&target) {
            Ok(m) if m.is_dir() => {
                return Err(Error::input(
                    option,
                    format!("{} is a folder, where tmm writes a file", target.display()),
                ));
            }
            Ok(_) if !listed.contains(rel) => {
                return Err(Error::input(
                    option,
                    format!(
                        "{} already exists and tmm did not write it; tmm does not replace it",
                        target.display()
                    ),
                )
                .with_help("move the file away, or choose another folder"));
            }
            _ => {}
        }
    }
    let mut both: Vec<&Path> = listed.iter().map(PathBuf::as_path).collect();
    for n in &new {
        if !both.contains(&n.as_path()) {
            both.push(n);
        }
    }
    let kept: Vec<&Path> = if prune {
        new.iter().map(PathBuf::as_path).collect()
    } else {
        both.clone()
    };
    let mut run = Run::default();
    let result = (|| {
        clean_leftovers(out);
        let mut temps = Vec::new();
        for d in docs {
            let target = out.join(&d.path);
            run.create_dirs(parent(&target), &target)?;
            clean_leftovers(parent(&target));
            let tmp = run.temp_file(&target);
            write_new(&tmp, &d.bytes).map_err(|e| write_error(&target, &e))?;
            temps.push((tmp, target, listed.contains(&PathBuf::from(&d.path))));
        }
        let marker = out.join(MARKER);
        let during = run.temp_file(&marker);
        write_new(&during, marker_text(MARKER_HEAD_ADDED, both.iter().copied()).as_bytes()).map_err(|e| write_error(out, &e))?;
        let after = run.temp_file(&marker);
        write_new(&after, marker_text(MARKER_HEAD_ADDED, kept.iter().copied()).as_bytes()).map_err(|e| write_error(out, &e))?;
        let mut commit = lock();
        std::fs::rename(&during, &marker).map_err(|e| write_error(out, &e))?;
        for (tmp, target, ours) in &temps {
            let placed = if *ours {
                std::fs::rename(tmp, target)
            } else {
                rename_noreplace(tmp, target)
            };
            placed.map_err(|e| write_error(target, &e))?;
        }
        if prune {
            for old in listed.iter().filter(|l| !new.contains(l)) {
                let _ = std::fs::remove_file(out.join(old));
            }
        }
        std::fs::rename(&after, &marker).map_err(|e| write_error(out, &e))?;
        run.keep(&mut commit);
        Ok(new.iter().map(|n| out.join(n)).collect())
    })();
    run.discard();
    result
}

fn marker_text<'a>(head: &str, files: impl Iterator<Item = &'a Path>) -> String {
    let mut s = String::from(head);
    s.push('\n');
    for f in files {
        s.push_str(&f.to_string_lossy());
        s.push('\n');
    }
    s
}

/// A tmm-made folder whose files cannot be deleted (read-only) is refused
/// before anything is written, so no old folder is left behind.
fn check_writable(out: &Path, listed: &[PathBuf], option: &str) -> Result<(), Error> {
    let mut dirs = vec![out.to_path_buf()];
    for f in listed {
        let d = parent(&out.join(f)).to_path_buf();
        if !dirs.contains(&d) {
            dirs.push(d);
        }
    }
    for d in dirs {
        let Ok(c) = CString::new(d.as_os_str().as_bytes()) else { continue };
        // SAFETY: `c` is a valid NUL-terminated path; faccessat only reads it.
        let r = unsafe { libc::faccessat(libc::AT_FDCWD, c.as_ptr(), libc::W_OK | libc::X_OK, libc::AT_EACCESS) };
        if r != 0 && std::io::Error::last_os_error().raw_os_error() == Some(libc::EACCES) {
            return Err(Error::input(
                option,
                format!(
                    "{} is read-only, so tmm cannot remove the files it wrote there before (in {})",
                    out.display(),
                    d.display()
                ),
            )
            .with_help(format!(
                "make it writable (chmod -R u+w {}) or choose another folder",
                out.display()
            )));
        }
    }
    Ok(())
}

/// A short temporary name beside `target`: `.NAME.tmm-KIND-PID-N`, NAME cut
/// so the whole fits in 255 bytes.
fn temp_name(target: &Path, kind: &str) -> PathBuf {
    static SEQ: AtomicU32 = AtomicU32::new(0);
    let n = SEQ.fetch_add(1, Ordering::Relaxed);
    let name = target.file_name().map_or(&b"out"[..], OsStr::as_bytes);
    let name = &name[..name.len().min(200)];
    let mut t = vec![b'.'];
    t.extend_from_slice(name);
    t.extend_from_slice(format!(".tmm-{kind}-{}-{n}", std::process::id()).as_bytes());
    parent(target).join(OsString::from_vec(t))
}

/// The process id in a temporary name of tmm's (`.NAME.tmm-tmp-PID-N`, or
/// `.NAME.tmm-tmp-PID` / `.NAME.tmm-old-PID` of earlier versions).
fn temp_pid(name: &OsStr) -> Option<u32> {
    let s = name.to_str()?;
    if !s.starts_with('.') {
        return None;
    }
    let at = s.rfind(".tmm-tmp-").or_else(|| s.rfind(".tmm-old-"))?;
    let mut parts = s[at + 9..].split('-');
    let pid = parts.next()?;
    let seq = parts.next();
    let digits = |t: &str| !t.is_empty() && t.bytes().all(|b| b.is_ascii_digit());
    if !digits(pid) || seq.is_some_and(|q| !digits(q)) || parts.next().is_some() {
        return None;
    }
    pid.parse().ok()
}

/// Whether the process `pid` has ended (so its temporary names are left
/// over).
fn gone(pid: u32) -> bool {
    let Ok(p) = libc::pid_t::try_from(pid) else { return false };
    if p <= 0 || pid == std::process::id() {
        return false;
    }
    // SAFETY: signal 0 only checks whether the process exists.
    let r = unsafe { libc::kill(p, 0) };
    r != 0 && std::io::Error::last_os_error().raw_os_error() == Some(libc::ESRCH)
}

/// Remove the temporary files and folders of earlier tmm runs in `dir`
/// whose process is gone (killed with SIGKILL, or at a power cut). A folder
/// loses only the files its marker lists.
fn clean_leftovers(dir: &Path) {
    let Ok(entries) = std::fs::read_dir(dir) else { return };
    for e in entries.flatten() {
        let Some(pid) = temp_pid(&e.file_name()) else { continue };
        if !gone(pid) {
            continue;
        }
        match e.file_type() {
            Ok(t) if t.is_dir() => {
                remove_ours(&e.path());
            }
            Ok(_) => {
                let _ = std::fs::remove_file(e.path());
            }
            Err(_) => {}
        }
    }
}

/// Rename `from` to `to` unless `to` exists.
fn rename_noreplace(from: &Path, to: &Path) -> std::io::Result<()> {
    #[cfg(target_os = "linux")]
    match renameat2(from, to, libc::RENAME_NOREPLACE) {
        Err(e) if e.raw_os_error() == Some(libc::EINVAL) || e.raw_os_error() == Some(libc::ENOSYS) => {}
        r => return r,
    }
    // A file system without renameat2: check, then rename.
    if std::fs::symlink_metadata(to).is_ok() {
        return Err(std::io::Error::from(std::io::ErrorKind::AlreadyExists));
    }
    std::fs::rename(from, to)
}

/// Exchange `a` and `b` atomically.
fn exchange(a: &Path, b: &Path) -> std::io::Result<()> {
    #[cfg(target_os = "linux")]
    match renameat2(a, b, libc::RENAME_EXCHANGE) {
        Err(e) if e.raw_os_error() == Some(libc::EINVAL) || e.raw_os_error() == Some(libc::ENOSYS) => {}
        r => return r,
    }
    // A file system without renameat2: three renames.
    let mid = temp_name(b, "old");
    std::fs::rename(b, &mid)?;
    if let Err(e) = std::fs::rename(a, b) {
        let _ = std::fs::rename(&mid, b);
        return Err(e);
    }
    std::fs::rename(&mid, a)
}

#[cfg(target_os = "linux")]
fn renameat2(from: &Path, to: &Path, flags: libc::c_uint) -> std::io::Result<()> {
    let f = CString::new(from.as_os_str().as_bytes())?;
    let t = CString::new(to.as_os_str().as_bytes())?;
    // SAFETY: both are valid NUL-terminated paths that renameat2 only reads.
    let r = unsafe { libc::renameat2(libc::AT_FDCWD, f.as_ptr(), libc::AT_FDCWD, t.as_ptr(), flags) };
    if r == 0 { Ok(()) } else { Err(std::io::Error::last_os_error()) }
}

/// Create a new file (never opening an existing one, so never following a
/// link) and write it whole. The registry is held locked meanwhile, so a
/// signal's clean-up finds every temporary file whole or not begun.
fn write_new(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let _temps = lock();
    let _ = std::fs::remove_file(path);
    let mut f = std::fs::OpenOptions::new().write(true).create_new(true).open(path)?;
    f.write_all(bytes).and_then(|()| f.sync_data())
}

/// A failed write, naming the user's path.
fn write_error(path: &Path, e: &std::io::Error) -> Error {
    Error::io(path, e)
}

/// A new folder could not be made beside `out`: say that its parent must
/// be writable.
fn beside_error(out: &Path, e: &std::io::Error) -> Error {
    if e.kind() == std::io::ErrorKind::PermissionDenied {
        Error::Io(format!(
            "cannot write {}: tmm builds it beside its place, so the folder {} must be writable too: {e}",
            out.display(),
            parent(out).display()
        ))
    } else {
        write_error(out, e)
    }
}

/// A file or folder name longer than a file system takes is refused as bad
/// input, naming it.
fn check_name_length(p: &Path, option: &str) -> Result<(), Error> {
    for c in p.components() {
        let n = c.as_os_str().len();
        if n > NAME_MAX {
            return Err(Error::input(
                option,
                format!(
                    "the name {} is too long: {n} bytes, where a file name can have at most {NAME_MAX}",
                    p.display()
                ),
            )
            .with_help("choose a shorter name"));
        }
    }
    Ok(())
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
        write_folder(&out, &docs(&["a/x.svg", "a/y.svg", "report.json"]), Existing::Refuse, "--out").unwrap();
        assert!(out.join("a/y.svg").exists());
        write_folder(&out, &docs(&["a/x.svg", "report.json"]), Existing::Refuse, "--out").unwrap();
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
        write_folder(&out, &docs(&["report.json"]), Existing::Refuse, "--out").unwrap();
        std::fs::write(out.join("mine.txt"), "user's").unwrap();
        let e = write_folder(&out, &docs(&["report.json"]), Existing::Refuse, "--out").unwrap_err();
        assert_eq!(e.exit_code(), 2);
        assert_eq!(std::fs::read_to_string(out.join("mine.txt")).unwrap(), "user's");
        // adding files leaves it too
        write_folder(&out, &docs(&["b.svg"]), Existing::AddFiles, "--out").unwrap();
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
