//! The browser page's PDF module (модуль PDF страницы): the explanatory
//! note and the drawing sheets of a task typeset in the page, with the
//! same code and fonts as `tmm run` ([`tmm_note::documents`]).
//!
//! The typesetter and its fonts make this module several times the size of
//! the page's own (`tmm-web`), so it is a second WebAssembly module that
//! the page loads only when the PDFs are asked for; the first load stays
//! small. Built by `scripts/build-web.sh` into `web/dist/tmm_web_pdf*`.
//!
//! The drawings' GOST lettering font osifont is not linked in (its licence
//! frees the documents that embed it, not a program that carries it):
//! `scripts/build-web.sh` copies the unaltered `osifont.ttf` beside this
//! module, the PDF worker fetches it on the first request and gives its
//! bytes to [`use_gost_font`]; without it the drawings fall back to the
//! linked faces ([`tmm_note::fonts`]).
//!
//! It is not built for the host by the README's commands (its
//! `wasm-bindgen` macros would make them build the typesetter twice, as
//! for `tmm-web`); the browser test (`scripts/test-web.sh`) makes the
//! default project's PDFs in the page and compares them with `tmm run`'s.

use tmm_report::TaskSource;
use tmm_report::output::Documents;
use tmm_report::project::Language;
use wasm_bindgen::prelude::*;

/// The PDFs of one task: `note.pdf` first, then `sheets/sheet-N.pdf`.
#[wasm_bindgen]
pub struct Pdfs {
    docs: Documents,
}

#[wasm_bindgen]
impl Pdfs {
    /// The paths of the PDFs, in order.
    pub fn names(&self) -> Vec<String> {
        self.docs.iter().map(|d| d.path.clone()).collect()
    }

    /// The count of PDFs.
    #[allow(clippy::len_without_is_empty)]
    pub fn len(&self) -> usize {
        self.docs.len()
    }

    /// The bytes of the `i`-th PDF (`None` past the end).
    pub fn bytes(&self, i: usize) -> Option<Vec<u8>> {
        self.docs.iter().nth(i).map(|d| d.bytes.clone())
    }
}

/// Run the task `text` (named `name` in messages) and typeset its note and
/// sheets, in `lang` (`ru`, `uk`, `en`; anything else: the task's own
/// language). A refused task gives the command line's message (the page
/// translates it as it does the analysis' messages).
///
/// # Errors
/// The task's message, or the typesetter's naming the document.
#[wasm_bindgen]
pub fn typeset(name: &str, text: &str, lang: &str) -> Result<Pdfs, String> {
    let task = TaskSource::new(name, text);
    let run = tmm_report::run::run_task_in(&task, Language::from_code(lang)).map_err(|e| e.to_string())?;
    let docs = tmm_note::documents::pdf_documents(&run, &task, |_| {}).map_err(|e| e.to_string())?;
    Ok(Pdfs { docs })
}

/// Give the typesetter the drawings' GOST lettering font osifont, the bytes
/// of the unaltered `osifont.ttf` the page serves beside this module, for
/// every PDF typeset after it in this page ([`tmm_note::fonts::with_gost_font`]).
///
/// # Errors
/// Why the bytes were refused (no font, or not osifont); the PDFs then
/// keep the fallback faces.
#[wasm_bindgen]
pub fn use_gost_font(bytes: Vec<u8>) -> Result<(), String> {
    tmm_note::fonts::with_gost_font(bytes).map_err(|e| e.to_string())
}

/// Whether the PDFs typeset now embed osifont (else the fallback faces).
#[wasm_bindgen]
pub fn has_gost_font() -> bool {
    tmm_note::fonts::current().has_gost_font()
}
