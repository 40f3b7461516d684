//! The page's state: the last successful run of the task in the editor, and
//! the task as the sections see it (language and sheet applied, a
//! synthesised mechanism written in), for the views at one crank angle and
//! one gear correction.

use serde_json::{Value, json};
use tmm_report::output::Document;
use tmm_report::project::Language;
use tmm_report::run::{Run, run_task_in};
use tmm_report::{Error, TaskSource};

use crate::reply;

/// The last successful run and the task it ran.
#[derive(Debug, Clone)]
pub struct Page {
    /// The task as the sections read it (synthesis applied).
    pub task: TaskSource,
    /// Everything the run produced.
    pub run: Run,
    /// The `[linkage]` section read and compiled once, for the views at
    /// one crank angle.
    pub linkage: Option<tmm_report::linkage::Loaded>,
    /// The `[forces]` section with its mechanism, read once.
    pub forces: Option<(tmm_report::linkage::Loaded, tmm_report::forces::ForcesTask)>,
}

impl Page {
    /// Run `text` as `tmm run` does; the drawings' words in `lang` when
    /// given, else in the task's `[project]` language.
    ///
    /// ```
    /// let p = tmm_web::page::Page::new("t.toml", tmm_report::run::DEFAULT_TASK, None).unwrap();
    /// assert!(p.file("linkage/positions.svg").is_some());
    /// ```
    pub fn new(name: &str, text: &str, lang: Option<Language>) -> Result<Self, Error> {
        let src = TaskSource::new(name, text);
        let run = run_task_in(&src, lang)?;
        let prepared = src.with_lang(run.project.lang).with_sheet(run.project.sheet);
        let task = tmm_report::synthesis::with_linkage(&prepared)?.into_owned();
        let linkage = tmm_report::linkage::load(&task)?;
        let forces = tmm_report::forces::load(&task)?;
        Ok(Page {
            task,
            run,
            linkage,
            forces,
        })
    }

    /// One file of the run.
    pub fn file(&self, path: &str) -> Option<&Document> {
        self.run.docs.get(path)
    }

    /// Whether the run has the section `name`.
    pub fn has(&self, name: &str) -> bool {
        self.run.sections.iter().any(|s| s.section == name)
    }
}

/// Run the task and build the page's reply: on success
/// `{"ok": true, "report", "sections": [{"section", "text"}], "files": [{"path", "size"}]}`
/// and the new state; on failure the located error (see
/// [`reply::from_error`]) and no state.
///
/// ```
/// let (r, page) = tmm_web::page::analyse_reply("t.toml", "[gear]\nz1 = 2\n", "en");
/// let v: serde_json::Value = serde_json::from_str(&r).unwrap();
/// assert_eq!(v["ok"], false);
/// assert!(page.is_none());
/// ```
pub fn analyse_reply(name: &str, text: &str, lang: &str) -> (String, Option<Page>) {
    let lang = Language::from_code(lang);
    match Page::new(name, text, lang) {
        Ok(p) => {
            let sections: Vec<Value> = p
                .run
                .sections
                .iter()
                .map(|s| json!({ "section": s.section, "text": s.text }))
                .collect();
            let files: Vec<Value> = p
                .run
                .docs
                .iter()
                .map(|d| json!({ "path": d.path, "size": d.bytes.len() }))
                .collect();
            let v = json!({
                "ok": true,
                "report": p.run.report,
                "sections": sections,
                "files": files,
            });
            (v.to_string(), Some(p))
        }
        Err(e) => (reply::from_error(&TaskSource::new(name, text), &e).to_string(), None),
    }
}
