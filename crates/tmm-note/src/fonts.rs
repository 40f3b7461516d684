//! The fonts of the typesetter (шрифты): the faces linked into the binary
//! and the GOST lettering face, read from the machine or given as bytes.
//!
//! - `typst-assets` (feature `fonts`): New Computer Modern (the note's
//!   text, full Cyrillic with the Ukrainian і ї є ґ in all four styles),
//!   New Computer Modern Math, DejaVu Sans Mono, Libertinus Serif.
//! - tmm's **GOST supplement** ([`SUPPLEMENT`], family
//!   [`tmm_draw::svg::SUPPLEMENT_FAMILY`]): Э э Ё ё − ′ ″ … →, drawn for tmm
//!   by `scripts/gost-supplement.py` from GOST 2.304 type B's construction
//!   at osifont's metrics; MIT OR Apache-2.0 like tmm, so it is linked in.
//! - **osifont** (GOST 2.304 / ISO 3098 letter shapes; Debian's
//!   `fonts-osifont`), the drawings' lettering, never linked in: its
//!   licence (GPL with the font exception) frees the documents that embed
//!   it, not a program that carries it. The command line reads it from the
//!   disk when found ([`gost_font_path`]); the browser page, which has no
//!   disk, serves the unaltered file beside its PDF module and gives its
//!   bytes to [`with_gost_font`]. Without it the drawings fall back to the
//!   faces above.
//!
//! The linked faces and the disk's osifont are looked up and parsed once per
//! process; the set the typesetter chooses from ([`current`]) changes only
//! through [`with_gost_font`].

use std::path::{Path, PathBuf};
use std::sync::{Arc, LazyLock, PoisonError, RwLock};

use typst::foundations::Bytes;
use typst::text::{Font, FontBook};
use typst::utils::LazyHash;

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

/// The GOST font file found on the disk, if one was found and parses: the
/// one the PDFs embed unless [`with_gost_font`] gave another.
pub fn gost_font() -> Option<&'static Path> {
    GOST.as_ref().map(|(p, _)| p.as_path())
}

/// The family name of the GOST font, as the drawings' SVG names it first
/// ([`tmm_draw::svg::FONT_FAMILY`]).
///
/// ```
/// assert!(tmm_draw::svg::FONT_FAMILY.starts_with(tmm_note::fonts::GOST_FAMILY));
/// ```
pub const GOST_FAMILY: &str = "osifont";

/// The faces linked into the binary: `typst-assets`' and the supplement,
/// parsed once.
static LINKED: LazyLock<Vec<Font>> = LazyLock::new(|| {
    let mut fonts: Vec<Font> = typst_assets::fonts().flat_map(|data| Font::iter(Bytes::new(data))).collect();
    fonts.extend(Font::iter(Bytes::new(SUPPLEMENT)));
    fonts
});

/// The faces the typesetter chooses from (набор шрифтов) and their book:
/// the linked ones, then the GOST font's when there is one.
pub struct FontSet {
    book: LazyHash<FontBook>,
    fonts: Vec<Font>,
    gost: bool,
}

impl FontSet {
    /// The linked faces and `gost` (the GOST font's faces; none: the
    /// drawings fall back to the linked faces).
    fn new(gost: &[Font]) -> Self {
        let mut fonts = LINKED.clone();
        fonts.extend(gost.iter().cloned());
        FontSet {
            book: LazyHash::new(FontBook::from_fonts(&fonts)),
            fonts,
            gost: !gost.is_empty(),
        }
    }

    /// The book of the faces, in the typesetter's form.
    pub fn book(&self) -> &LazyHash<FontBook> {
        &self.book
    }

    /// The `index`-th face of the book.
    pub fn font(&self, index: usize) -> Option<Font> {
        self.fonts.get(index).cloned()
    }

    /// Every face, in the book's order.
    pub fn fonts(&self) -> &[Font] {
        &self.fonts
    }

    /// Whether the GOST font osifont is among the faces (else the drawings
    /// use the fallback faces).
    pub fn has_gost_font(&self) -> bool {
        self.gost
    }
}

/// The set the typesetter uses now: the disk's osifont until
/// [`with_gost_font`] gives another.
static CURRENT: LazyLock<RwLock<Arc<FontSet>>> = LazyLock::new(|| {
    let gost = GOST.as_ref().map_or(&[][..], |(_, faces)| faces.as_slice());
    RwLock::new(Arc::new(FontSet::new(gost)))
});

/// The set of faces a document typeset now is made with (each note and
/// sheet takes it once, when its world is made).
pub fn current() -> Arc<FontSet> {
    CURRENT.read().unwrap_or_else(PoisonError::into_inner).clone()
}

/// Why the bytes given to [`with_gost_font`] were refused; the set in use
/// is kept (the fallback faces, or the osifont it had).
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum GostFontError {
    /// No face could be read from the bytes.
    #[error("the GOST lettering font's file holds no font the typesetter can read ({0} bytes): the PDFs' drawings use the fallback face")]
    NotAFont(usize),
    /// The bytes are a font, but not osifont, which the drawings name.
    #[error(
        "the GOST lettering font's file is the font \"{0}\", not osifont, which the drawings name: the PDFs' drawings use the fallback face"
    )]
    NotOsifont(String),
}

/// The faces of the osifont file `bytes`.
///
/// # Errors
/// [`GostFontError`] when they hold no font, or a font of another family.
fn gost_faces(bytes: Vec<u8>) -> Result<Vec<Font>, GostFontError> {
    let len = bytes.len();
    let faces: Vec<Font> = Font::iter(Bytes::new(bytes)).collect();
    let Some(first) = faces.first() else {
        return Err(GostFontError::NotAFont(len));
    };
    if !first.info().family.eq_ignore_ascii_case(GOST_FAMILY) {
        return Err(GostFontError::NotOsifont(first.info().family.clone()));
    }
    Ok(faces)
}

/// Give the typesetter the GOST font osifont as the bytes of its file, in
/// place of the one read from the disk (if any), for every document typeset
/// after it in this process: how the browser page, which has no file
/// system, embeds osifont (it serves the unaltered file beside its PDF
/// module and fetches it on the first PDF request).
///
/// ```
/// use tmm_note::fonts::{GostFontError, with_gost_font};
/// // bytes that are no font are refused, and the set in use is kept
/// let had = tmm_note::fonts::current().has_gost_font();
/// assert_eq!(with_gost_font(b"no font".to_vec()), Err(GostFontError::NotAFont(7)));
/// assert_eq!(tmm_note::fonts::current().has_gost_font(), had);
/// ```
///
/// # Errors
/// [`GostFontError`] when `bytes` hold no font or a font other than osifont;
/// the faces in use are kept.
pub fn with_gost_font(bytes: Vec<u8>) -> Result<(), GostFontError> {
    let faces = gost_faces(bytes)?;
    let set = Arc::new(FontSet::new(&faces));
    *CURRENT.write().unwrap_or_else(PoisonError::into_inner) = set;
    Ok(())
}

/// Every face the typesetter may use now: the linked ones, the supplement
/// and the GOST font when there is one ([`current`]).
pub fn all() -> Vec<Font> {
    current().fonts().to_vec()
}
