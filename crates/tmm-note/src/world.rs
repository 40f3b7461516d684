//! The typst `World` of a note: the generated `/main.typ`, the template
//! `/template.typ`, the figures' SVG documents as virtual files, and the
//! fonts of [`crate::fonts`] (those linked into the binary, and the GOST
//! lettering face osifont when the machine has it — the one thing read from
//! the disk — or when the browser page gave its bytes; nothing from the
//! network).
//!
//! Fonts: `typst-assets` (feature `fonts`) — New Computer Modern (text, full
//! Cyrillic with the Ukrainian і ї є ґ in all four styles), New Computer
//! Modern Math (formulas; Cyrillic inside formulas falls back to the text
//! face), DejaVu Sans Mono (code), Libertinus Serif (not used by the
//! template); tmm's GOST supplement and osifont (the drawings' lettering).
//! The fonts and the standard library are parsed once per process; each
//! world keeps the font set in use when it was made
//! ([`crate::fonts::current`]).

use std::collections::HashMap;
use std::sync::{Arc, LazyLock};

use typst::diag::{FileError, FileResult};
use typst::foundations::{Bytes, Datetime, Duration};
use typst::syntax::{FileId, RootedPath, Source, VirtualPath, VirtualRoot};
use typst::text::{Font, FontBook};
use typst::utils::LazyHash;
use typst::{Library, LibraryExt, World};

use crate::error::NoteError;
use crate::fonts::FontSet;

static LIBRARY: LazyLock<LazyHash<Library>> = LazyLock::new(|| LazyHash::new(Library::default()));

/// The template, embedded.
pub const TEMPLATE: &str = include_str!("template.typ");

/// A file id in the project root.
fn file_id(path: &str) -> Result<FileId, NoteError> {
    let vpath = VirtualPath::new(path).map_err(|e| NoteError::Typst {
        messages: vec![format!("{path}: {e:?}")],
    })?;
    Ok(RootedPath::new(VirtualRoot::Project, vpath).intern())
}

/// The world a note is compiled in.
pub struct NoteWorld {
    main: Source,
    template: Source,
    files: HashMap<FileId, Bytes>,
    fonts: Arc<FontSet>,
}

impl NoteWorld {
    /// A world serving `main` as `/main.typ` and each `(path, svg)` figure.
    ///
    /// # Errors
    /// [`NoteError::Typst`] if a path is not a valid virtual path.
    pub fn new(main: String, figures: Vec<(String, String)>) -> Result<Self, NoteError> {
        let main = Source::new(file_id("/main.typ")?, main);
        let template = Source::new(file_id("/template.typ")?, TEMPLATE.to_owned());
        let mut files = HashMap::with_capacity(figures.len());
        for (path, svg) in figures {
            // the supplement's runs marked for usvg's font fallback
            let svg = tmm_draw::svg::mark_supplement_runs(&svg);
            files.insert(file_id(&path)?, Bytes::from_string(svg));
        }
        Ok(NoteWorld {
            main,
            template,
            files,
            fonts: crate::fonts::current(),
        })
    }

    /// The file and line of a byte offset in one of the sources, for messages.
    pub fn describe(&self, id: Option<FileId>, range: Option<std::ops::Range<usize>>) -> String {
        let Some(id) = id else { return String::from("(no file)") };
        let path = id.vpath().get_with_slash().to_owned();
        let source = if id == self.main.id() {
            Some(&self.main)
        } else if id == self.template.id() {
            Some(&self.template)
        } else {
            None
        };
        match (source, range) {
            (Some(s), Some(r)) => match s.lines().byte_to_line(r.start) {
                Some(line) => format!("{path}:{}", line + 1),
                None => path,
            },
            _ => path,
        }
    }
}

impl World for NoteWorld {
    fn library(&self) -> &LazyHash<Library> {
        &LIBRARY
    }

    fn book(&self) -> &LazyHash<FontBook> {
        self.fonts.book()
    }

    fn main(&self) -> FileId {
        self.main.id()
    }

    fn source(&self, id: FileId) -> FileResult<Source> {
        if id == self.main.id() {
            Ok(self.main.clone())
        } else if id == self.template.id() {
            Ok(self.template.clone())
        } else {
            Err(FileError::NotFound(id.vpath().get_without_slash().into()))
        }
    }

    fn file(&self, id: FileId) -> FileResult<Bytes> {
        if let Some(b) = self.files.get(&id) {
            Ok(b.clone())
        } else if id == self.main.id() {
            Ok(Bytes::from_string(self.main.clone()))
        } else if id == self.template.id() {
            Ok(Bytes::from_string(self.template.clone()))
        } else {
            Err(FileError::NotFound(id.vpath().get_without_slash().into()))
        }
    }

    fn font(&self, index: usize) -> Option<Font> {
        self.fonts.font(index)
    }

    /// No date: the note prints none, and the PDF stays reproducible.
    fn today(&self, _offset: Option<Duration>) -> Option<Datetime> {
        None
    }
}
