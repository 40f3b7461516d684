//! The page's state: the last successful run of the task in the editor, and
//! the task as the sections see it (language and sheet applied, a
//! synthesised mechanism written in), for the views at one crank angle and
//! one gear correction.
//!
//! An edit reruns only the sections whose input changed: each section's
//! output is kept with a key made of the tables it reads
//! ([`tmm_report::run::SECTION_TABLES`]), the language, the sheet and the
//! task's name, and a section whose key is unchanged hands back its kept
//! output (the sections are deterministic, so the run equals a fresh one).

use serde_json::{Value, json};
use tmm_report::output::Document;
use tmm_report::output::SectionOutput;
use tmm_report::project::Language;
use tmm_report::run::{Run, SECTION_TABLES, assemble, prepare, run_section};
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
    /// The start of the working stroke (rad) of the linkage's cycle.
    pub cycle_start: Option<f64>,
    /// Each section's key and output (`None`: the task has no such
    /// section), in the order of [`SECTION_TABLES`].
    kept: Vec<(String, Option<SectionOutput>)>,
    /// The sections this run computed (the others were kept from the
    /// previous run).
    pub rerun: Vec<&'static str>,
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
        Self::after(None, name, text, lang)
    }

    /// Run `text` as [`Page::new`] does, taking from `prev` (the page of
    /// the last successful run) the output of every section whose input
    /// is unchanged.
    ///
    /// ```
    /// use tmm_web::page::Page;
    /// use tmm_report::run::DEFAULT_TASK;
    /// let p = Page::new("t.toml", DEFAULT_TASK, None).unwrap();
    /// let edited = DEFAULT_TASK.replace("[gear]", "[gear]\n# a comment");
    /// let q = Page::after(Some(&p), "t.toml", &edited, None).unwrap();
    /// assert_eq!(q.rerun, Vec::<&str>::new());
    /// ```
    pub fn after(prev: Option<&Page>, name: &str, text: &str, lang: Option<Language>) -> Result<Self, Error> {
        let src = TaskSource::new(name, text);
        let prepared = prepare(&src, lang)?;
        let seen = prepared.task.check_sections()?;
        let generated = !prepared.table.contains_key("linkage") && seen.contains_key("linkage");
        let mut kept = Vec::with_capacity(SECTION_TABLES.len());
        let mut rerun = Vec::new();
        for (i, (section, tables)) in SECTION_TABLES.iter().enumerate() {
            let mut key = format!("{name}\u{0}{:?}\u{0}{:?}\u{0}{generated}", prepared.task.lang, prepared.task.sheet);
            for t in *tables {
                key.push('\u{0}');
                key.push_str(&format!("{:?}", seen.get(*t)));
            }
            let out = match prev.and_then(|p| p.kept.get(i)).filter(|k| k.0 == key) {
                Some((_, out)) => out.clone(),
                None => {
                    rerun.push(*section);
                    run_section(section, &prepared.task)?
                }
            };
            kept.push((key, out));
        }
        let run = assemble(&prepared, kept.iter().filter_map(|k| k.1.clone()).collect())?;
        let task = prepared.task;
        let linkage = tmm_report::linkage::load(&task)?;
        let forces = tmm_report::forces::load(&task)?;
        let cycle_start = linkage
            .as_ref()
            .and_then(|l| tmm_linkage::cycle::Cycle::new(&l.mech, l.task.working).ok())
            .map(|c| c.start);
        Ok(Page {
            task,
            run,
            linkage,
            forces,
            cycle_start,
            kept,
            rerun,
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
    analyse_reply_after(None, name, text, lang)
}

/// [`analyse_reply`] taking the unchanged sections from `prev` (see
/// [`Page::after`]); the reply also lists the sections computed anew
/// (`"rerun"`).
pub fn analyse_reply_after(prev: Option<&Page>, name: &str, text: &str, lang: &str) -> (String, Option<Page>) {
    let lang = Language::from_code(lang);
    match Page::after(prev, name, text, lang) {
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
                "rerun": p.rerun,
            });
            (v.to_string(), Some(p))
        }
        Err(e) => (reply::from_error(&TaskSource::new(name, text), &e).to_string(), None),
    }
}
