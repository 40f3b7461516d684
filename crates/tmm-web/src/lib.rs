//! The browser page of tmm (страница в браузере): the same task runs,
//! numbers and drawings as the command line, compiled to WebAssembly.
//!
//! The page's JavaScript (`web/app.js`) calls the functions exported here
//! through `wasm-bindgen`; each returns plain text (JSON or SVG) so that the
//! JavaScript side stays small and holds no mechanics:
//!
//! | export | what |
//! | --- | --- |
//! | [`analyse`] | run the task, only the sections whose tables changed ([`page::Page::after`]); tables, report or the located error |
//! | [`files`] | the files of one section of the last run (its drawings made when first asked) |
//! | [`file_text`], [`file_bytes`] | one file of the last run (the same bytes the CLI writes) |
//! | [`frames`] | the mechanism over the cycle for the animation and traced paths |
//! | [`at_angle`] | the plans, forces and Zhukovsky's lever at one crank angle |
//! | [`plan_vectors`] | the plans' vectors at one crank angle, for a frame of the animation |
//! | [`gear_contour`], [`gear_at`], [`gear_write`] | the blocking contour's axes and the nodes where every check passes; the pair at a picked (x1, x2); the pick written into the task |
//! | [`drag`] | the task with a dragged point's coordinates or its links' lengths changed |
//! | [`words`] | the page's own words in Russian, Ukrainian or English |
//! | [`say`] | a message of the solver in Russian or Ukrainian ([`messages::translate`]) |
//!
//! The state between calls is the last successful run ([`page::Page`]); the
//! logic lives in plain Rust modules that the native tests exercise, and the
//! exports below only hold that state.

pub mod angle;
pub mod drag;
pub mod examples;
pub mod gear_pick;
pub mod messages;
pub mod page;
pub mod reply;
pub mod ui_words;

use std::cell::RefCell;

use wasm_bindgen::prelude::*;

thread_local! {
    static PAGE: RefCell<Option<page::Page>> = const { RefCell::new(None) };
}

/// The embedded default task (the one `tmm run` runs with no file).
#[wasm_bindgen]
pub fn default_task() -> String {
    tmm_report::run::DEFAULT_TASK.to_string()
}

/// The examples shipped with tmm, as JSON `[{"name", "text"}, …]`.
#[wasm_bindgen]
pub fn examples() -> String {
    examples::json()
}

/// Run the task `text` (named `name` in messages) with the drawings' words
/// in `lang` (`ru`, `uk`, `en`; anything else: the task's own language).
/// Returns the reply as JSON (see [`page::analyse_reply`]); a successful run
/// becomes the page's state for the other calls.
#[wasm_bindgen]
pub fn analyse(name: &str, text: &str, lang: &str) -> String {
    let (reply, page) = PAGE.with(|s| page::analyse_reply_after(s.borrow().as_ref(), name, text, lang));
    if let Some(p) = page {
        PAGE.with(|s| *s.borrow_mut() = Some(p));
    }
    reply
}

/// One text file of the last successful run (`linkage/positions.svg`, …).
#[wasm_bindgen]
pub fn file_text(path: &str) -> Option<String> {
    PAGE.with(|s| {
        s.borrow()
            .as_ref()
            .and_then(|p| p.file(path))
            .and_then(|d| d.as_text().map(str::to_string))
    })
}

/// The files of the section `name` of the last successful run (`"report"`
/// for `report.json`), as JSON `{"ok", "files": [{"path", "size"}]}`; the
/// section's drawings are made on the first call (see [`page::Page::files`]).
#[wasm_bindgen]
pub fn files(name: &str) -> String {
    with_page(|p| p.files(name).to_string())
}

/// The bytes of one file of the last successful run, for a download.
#[wasm_bindgen]
pub fn file_bytes(path: &str) -> Option<Vec<u8>> {
    PAGE.with(|s| s.borrow().as_ref().and_then(|p| p.file(path)).map(|d| d.bytes.clone()))
}

/// The mechanism at `n` crank angles over one revolution, as JSON (see
/// [`angle::frames`]); `{"none": true}` when the task has no linkage.
#[wasm_bindgen]
pub fn frames(n: usize) -> String {
    with_page(|p| angle::frames(p, n))
}

/// The velocity and acceleration plans, the force drawings and Zhukovsky's
/// lever at the crank angle `phi` (rad), as JSON (see [`angle::at_angle`]);
/// the forces only when `with_forces`.
#[wasm_bindgen]
pub fn at_angle(phi: f64, with_forces: bool) -> String {
    with_page(|p| angle::at_angle(p, phi, with_forces))
}

/// The plans' vectors at the crank angle `phi` (rad) for a frame of the
/// animation, as JSON (see [`angle::plan_vectors`]).
#[wasm_bindgen]
pub fn plan_vectors(phi: f64) -> String {
    with_page(|p| angle::plan_vectors(p, phi))
}

/// The blocking contour's axes and where they lie on its drawing, as JSON
/// (see [`gear_pick::contour_axes`]).
#[wasm_bindgen]
pub fn gear_contour() -> String {
    with_page(gear_pick::contour_axes)
}

/// The gear pair with the shift coefficients (x1, x2), as JSON (see
/// [`gear_pick::gear_at`]).
#[wasm_bindgen]
pub fn gear_at(x1: f64, x2: f64) -> String {
    with_page(|p| gear_pick::gear_at(p, x1, x2))
}

/// The task `text` with the picked shifts written into its `[gear]`
/// section, as JSON `{"ok", "text"}` (see [`gear_pick::write_shifts`]).
#[wasm_bindgen]
pub fn gear_write(text: &str, x1: f64, x2: f64) -> String {
    match gear_pick::write_shifts(text, x1, x2) {
        Ok(t) => serde_json::json!({ "ok": true, "text": t }).to_string(),
        Err(m) => reply::error_json(&m, None, None),
    }
}

/// The task `text` after the mechanism's point `point` is dragged to
/// `(x, y)` (m) with the crank at `phi` (rad), as JSON `{"ok", "text"}` or
/// the reason it cannot be (see [`drag::drag`]).
#[wasm_bindgen]
pub fn drag(text: &str, point: &str, x: f64, y: f64, phi: f64) -> String {
    with_page(|p| match drag::drag(p, text, point, x, y, phi) {
        Ok(t) => serde_json::json!({ "ok": true, "text": t }).to_string(),
        Err(m) => reply::error_json(&m, None, None),
    })
}

/// The page's own words in `lang` (`ru`, `uk`, `en`; anything else:
/// English), as JSON (see [`ui_words::json`]).
#[wasm_bindgen]
pub fn words(lang: &str) -> String {
    ui_words::json(lang)
}

/// The message `text` (English, as the solver makes it) in `lang`, as JSON
/// `{"text": …}`, the text `null` when a part of it has no wording in the
/// page's word file (see [`messages::translate`]).
#[wasm_bindgen]
pub fn say(text: &str, lang: &str) -> String {
    let l = tmm_report::project::Language::from_code(lang).unwrap_or(tmm_report::project::Language::En);
    serde_json::json!({ "text": messages::translate(text, l) }).to_string()
}

fn with_page(f: impl FnOnce(&page::Page) -> String) -> String {
    PAGE.with(|s| match s.borrow().as_ref() {
        Some(p) => f(p),
        None => reply::error_json("no task has been run yet", None, None),
    })
}
