//! The fonts of the typesetter (шрифты): the faces linked into the binary
//! and the GOST lettering face read from the machine.
//!
//! - `typst-assets` (feature `fonts`): New Computer Modern (the note's
//!   text, full Cyrillic with the Ukrainian і ї є ґ in all four styles),
//!   New Computer Modern Math, DejaVu Sans Mono, Libertinus Serif.
//! - tmm's **GOST supplement** ([`SUPPLEMENT`], family
//!   [`tmm_draw::svg::SUPPLEMENT_FAMILY`]): Э э Ё ё − ′ ″ … →, drawn for tmm
//!   by `scripts/gost-supplement.py` from GOST 2.304 type B's construction
//!   at osifont's metrics; MIT OR Apache-2.0 like tmm, so it is linked in.
//! - **osifont** (GOST 2.304 / ISO 3098 letter shapes; Debian's
//!   `fonts-osifont`), the drawings' lettering, read from the disk when
//!   found ([`gost_font_path`]) and never linked in: its licence (GPL with
//!   the font exception) frees the documents that embed it, not a program
//!   that carries it. Without it the drawings fall back to the faces above.
//!
//! The fonts are looked up and parsed once per process.

use std::path::{Path, PathBuf};
use std::sync::LazyLock;

use typst::foundations::Bytes;
use typst::text::Font;

/// tmm's GOST type B supplement to osifont (a TrueType font of 9 glyphs).
pub const SUPPLEMENT: &[u8] = include_bytes!("../fonts/tmm-gost-supplement.ttf");

/// The environment variable naming the GOST font: a font file, or a
/// folder searched for `osifont*.ttf`.
pub const FONT_PATH_VAR: &str = "TMM_FONT_PATH";

/// How to get the GOST font, for the message printed when it is missing.
pub const INSTALL_HINT: &str = "the drawings' GOST lettering font osifont was not found, so the PDFs' drawings use a fallback face; install it (Debian/Ubuntu: apt install fonts-osifont; elsewhere osifont.ttf from github.com/hikikomori82/osifont into the fonts folder) or name the file in TMM_FONT_PATH";

/// Whether a file name is osifont's (`osifont.ttf`, `osifont-lgpl3fe.ttf`
/// …; any case).
///
/// ```
/// use tmm_note::fonts::is_gost_font_name;
/// assert!(is_gost_font_name("osifont-lgpl3fe.ttf") && is_gost_font_name("OSIFONT.TTF"));
/// assert!(!is_gost_font_name("DejaVuSans.ttf") && !is_gost_font_name("osifont.otf.txt"));
/// ```
pub fn is_gost_font_name(name: &str) -> bool {
    let n = name.to_ascii_lowercase();
    n.starts_with("osifont") && n.ends_with(".ttf")
}

/// The folders a system keeps its fonts in, in the order searched: the
/// user's, then the machine's (Linux, macOS, Windows).
fn system_font_dirs() -> Vec<PathBuf> {
    let mut dirs = Vec::new();
    let home = std::env::var_os("HOME").map(PathBuf::from);
    if let Some(h) = &home {
        dirs.push(h.join(".local/share/fonts"));
        dirs.push(h.join(".fonts"));
        dirs.push(h.join("Library/Fonts"));
    }
    if let Some(d) = std::env::var_os("XDG_DATA_HOME") {
        dirs.push(PathBuf::from(d).join("fonts"));
    }
    dirs.push(PathBuf::from("/usr/local/share/fonts"));
    dirs.push(PathBuf::from("/usr/share/fonts"));
    dirs.push(PathBuf::from("/Library/Fonts"));
    if let Some(l) = std::env::var_os("LOCALAPPDATA") {
        dirs.push(PathBuf::from(l).join("Microsoft/Windows/Fonts"));
    }
    if let Some(w) = std::env::var_os("WINDIR") {
        dirs.push(PathBuf::from(w).join("Fonts"));
    }
    dirs
}

/// The first `osifont*.ttf` under `dir`, searched to `depth` folders down
/// (names only: no font is opened), in name order so the answer is the
/// same on every run.
fn find_in(dir: &Path, depth: u32) -> Option<PathBuf> {
    let mut entries: Vec<_> = std::fs::read_dir(dir).ok()?.filter_map(Result::ok).collect();
    entries.sort_by_key(std::fs::DirEntry::file_name);
    let mut subdirs = Vec::new();
    for e in entries {
        let Ok(kind) = e.file_type() else { continue };
        let path = e.path();
        if kind.is_dir() || (kind.is_symlink() && path.is_dir()) {
            subdirs.push(path);
        } else if e.file_name().to_str().is_some_and(is_gost_font_name) {
            return Some(path);
        }
    }
    if depth == 0 {
        return None;
    }
    subdirs.into_iter().find_map(|d| find_in(&d, depth - 1))
}

/// Where the GOST font is read from: [`FONT_PATH_VAR`] (a file taken as it
/// is, a folder searched for `osifont*.ttf`), else the first `osifont*.ttf`
/// in the system's font folders (the user's `~/.local/share/fonts`,
/// `~/.fonts`, `~/Library/Fonts`; `/usr/local/share/fonts`,
/// `/usr/share/fonts`, `/Library/Fonts`; Windows' per-user and
/// `%WINDIR%\Fonts`), each searched four folders deep. `None` when there
/// is none (and always in the browser, which has no file system).
pub fn gost_font_path() -> Option<PathBuf> {
    if let Some(p) = std::env::var_os(FONT_PATH_VAR).filter(|p| !p.is_empty()) {
        let p = PathBuf::from(p);
        if p.is_file() {
            return Some(p);
        }
        if let Some(f) = find_in(&p, 4) {
            return Some(f);
        }
    }
    system_font_dirs().iter().find_map(|d| find_in(d, 4))
}

/// The GOST font found on the machine: its path and faces, read once.
static GOST: LazyLock<Option<(PathBuf, Vec<Font>)>> = LazyLock::new(|| {
    let path = gost_font_path()?;
    let data = std::fs::read(&path).ok()?;
    let faces: Vec<Font> = Font::iter(Bytes::new(data)).collect();
    (!faces.is_empty()).then_some((path, faces))
});

/// The GOST font file the PDFs embed, if one was found and parses.
pub fn gost_font() -> Option<&'static Path> {
    GOST.as_ref().map(|(p, _)| p.as_path())
}

/// Every face the typesetter may use: the linked ones, the supplement and
/// the GOST font when found.
pub fn all() -> Vec<Font> {
    let mut fonts: Vec<Font> = typst_assets::fonts().flat_map(|data| Font::iter(Bytes::new(data))).collect();
    fonts.extend(Font::iter(Bytes::new(SUPPLEMENT)));
    if let Some((_, faces)) = GOST.as_ref() {
        fonts.extend(faces.iter().cloned());
    }
    fonts
}
