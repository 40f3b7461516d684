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
//! The drawings of the linkage, forces and dynamics sections are made only
//! when a view or a download asks for one of their files
//! ([`tmm_report::run::run_staged`]), once per run of the section.

use std::cell::OnceCell;
use std::rc::Rc;

use serde_json::{Value, json};
use tmm_report::output::{Document, Documents, to_json_text};
use tmm_report::project::Language;
use tmm_report::run::{SECTION_TABLES, Staged, prepare, run_staged};
use tmm_report::{Error, TaskSource};

use crate::reply;

/// One section's output, kept between runs.
#[derive(Debug)]
struct Kept {
    /// What the output depends on (see the module's header).
    key: String,
    /// The section's numbers and its deferred drawings; `None` when the
    /// task has no such section.
    staged: Option<Staged>,
    /// The section's JSON as compact text, made once.
    json_text: OnceCell<String>,
    /// The drawings once made, or the reply of the error that stopped them.
    drawn: OnceCell<Result<Documents, Value>>,
}

/// The last successful run and the task it ran.
#[derive(Debug)]
pub struct Page {
    /// The task as the sections read it (synthesis applied).
    pub task: TaskSource,
    /// The task's title.
    pub title: Option<String>,
    /// The `[linkage]` section read and compiled once, for the views at
    /// one crank angle.
    pub linkage: Option<tmm_report::linkage::Loaded>,
    /// The `[forces]` section with its mechanism, read once.
    pub forces: Option<(tmm_report::linkage::Loaded, tmm_report::forces::ForcesTask)>,
    /// The start of the working stroke (rad) of the linkage's cycle.
    pub cycle_start: Option<f64>,
    /// The sections this run computed (the others were kept from the
    /// previous run).
    pub rerun: Vec<&'static str>,
    /// Each section's output, in the order of [`SECTION_TABLES`].
    kept: Vec<Rc<Kept>>,
    /// `report.json`, made when asked.
    report_doc: OnceCell<Documents>,
    /// The `[project]` data (sheet format, title block) for the sheets.
    project: tmm_report::project::Project,
    /// The drawing sheets (`sheets/…`), made when asked.
    sheets: OnceCell<Result<Documents, Value>>,
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
            match prev.and_then(|p| p.kept.get(i)).filter(|k| k.key == key) {
                Some(k) => kept.push(Rc::clone(k)),
                None => {
                    rerun.push(*section);
                    kept.push(Rc::new(Kept {
                        key,
                        staged: run_staged(section, &prepared.task)?,
                        json_text: OnceCell::new(),
                        drawn: OnceCell::new(),
                    }));
                }
            }
        }
        let task = prepared.task;
        let linkage = tmm_report::linkage::load(&task)?;
        let forces = tmm_report::forces::load(&task)?;
        let cycle_start = linkage
            .as_ref()
            .and_then(|l| tmm_linkage::cycle::Cycle::new(&l.mech, l.task.working).ok())
            .map(|c| c.start);
        let title = match prepared.table.get("title") {
            Some(toml::Value::String(t)) => Some(t.clone()),
            _ => None,
        };
        Ok(Page {
            task,
            title,
            linkage,
            forces,
            cycle_start,
            rerun,
            kept,
            report_doc: OnceCell::new(),
            project: prepared.project,
            sheets: OnceCell::new(),
        })
    }

    /// The sections of the run, in course order.
    fn sections(&self) -> impl Iterator<Item = (&Kept, &Staged)> {
        self.kept.iter().filter_map(|k| k.staged.as_ref().map(|s| (&**k, s)))
    }

    /// The combined JSON report, as `tmm run` writes it to `report.json`.
    pub fn report(&self) -> Value {
        let mut doc = serde_json::Map::new();
        doc.insert("units".into(), "SI".into());
        if let Some(t) = &self.title {
            doc.insert("title".into(), t.clone().into());
        }
        for (_, s) in self.sections() {
            doc.insert(s.output.section.into(), s.output.json.clone());
        }
        Value::Object(doc)
    }

    /// The combined report as compact JSON text, made from each section's
    /// text kept since that section ran.
    fn report_text(&self) -> String {
        let mut t = String::from("{\"units\":\"SI\"");
        if let Some(title) = &self.title {
            t.push_str(",\"title\":");
            t.push_str(&Value::from(title.as_str()).to_string());
        }
        for (k, s) in self.sections() {
            t.push_str(&format!(",\"{}\":", s.output.section));
            t.push_str(k.json_text.get_or_init(|| s.output.json.to_string()));
        }
        t.push('}');
        t
    }

    /// The drawings of one section, made on the first call.
    fn drawn<'a>(&self, k: &'a Kept, s: &Staged) -> &'a Result<Documents, Value> {
        k.drawn.get_or_init(|| s.drawings().map_err(|e| reply::from_error(&self.task, &e)))
    }

    /// One file of the run; a section's drawings are made when one of its
    /// files is first asked for.
    pub fn file(&self, path: &str) -> Option<&Document> {
        if path == "report.json" {
            let d = self.report_doc.get_or_init(|| {
                let mut d = Documents::new();
                // a report of finite numbers (each section checked its own)
                let _ = d.add_text("report.json", to_json_text(&self.report()));
                d
            });
            return d.get(path);
        }
        let (dir, _) = path.split_once('/')?;
        if dir == "sheets" {
            return self.sheets().as_ref().ok()?.get(path);
        }
        let (k, s) = self.sections().find(|(_, s)| s.output.section == dir)?;
        s.output.docs.get(path).or_else(|| self.drawn(k, s).as_ref().ok()?.get(path))
    }

    /// The files of the section `name` (`report.json` for `"report"`), as
    /// `[{"path", "size"}]`, its drawings made if they were not; the error
    /// reply when a drawing fails.
    pub fn files(&self, name: &str) -> Value {
        if name == "report" {
            let size = self.file("report.json").map_or(0, |d| d.bytes.len());
            return json!({ "ok": true, "files": [{ "path": "report.json", "size": size }] });
        }
        if name == "sheets" {
            return match self.sheets() {
                Ok(d) => {
                    let files: Vec<Value> = d.iter().map(|d| json!({ "path": d.path, "size": d.bytes.len() })).collect();
                    json!({ "ok": true, "files": files })
                }
                Err(e) => e.clone(),
            };
        }
        let Some((k, s)) = self.sections().find(|(_, s)| s.output.section == name) else {
            return json!({ "ok": true, "files": [] });
        };
        let drawn = match self.drawn(k, s) {
            Ok(d) => d,
            Err(e) => return e.clone(),
        };
        let files: Vec<Value> = drawn
            .iter()
            .chain(s.output.docs.iter())
            .map(|d| json!({ "path": d.path, "size": d.bytes.len() }))
            .collect();
        json!({ "ok": true, "files": files })
    }

    /// Every file of the run in `tmm run`'s order (all drawings made).
    pub fn docs(&self) -> Result<Vec<&Document>, Value> {
        let mut all = self.section_docs()?;
        all.extend(self.sheets().as_ref().map_err(Clone::clone)?.iter());
        Ok(all)
    }

    /// `report.json` and every section's files, in `tmm run`'s order.
    fn section_docs(&self) -> Result<Vec<&Document>, Value> {
        let mut all: Vec<&Document> = self.file("report.json").into_iter().collect();
        for (k, s) in self.sections() {
            let drawn = self.drawn(k, s).as_ref().map_err(Clone::clone)?;
            all.extend(drawn.iter());
            all.extend(s.output.docs.iter());
        }
        Ok(all)
    }

    /// The drawing sheets of the run ([`tmm_report::sheets::sheet_documents`]
    /// over every section's files), made on the first call.
    fn sheets(&self) -> &Result<Documents, Value> {
        self.sheets.get_or_init(|| {
            // each section's files with the drawings they were written from
            let mut docs = Documents::new();
            if let Some(r) = self.file("report.json") {
                docs.append(single(r));
            }
            for (k, s) in self.sections() {
                let drawn = self.drawn(k, s).as_ref().map_err(Clone::clone)?;
                for d in drawn.iter() {
                    docs.add_copy(drawn, d);
                }
                for d in s.output.docs.iter() {
                    docs.add_copy(&s.output.docs, d);
                }
            }
            tmm_report::sheets::sheet_documents(&docs, &self.project).map_err(|e| reply::from_error(&self.task, &e))
        })
    }

    /// Whether the run has the section `name`.
    pub fn has(&self, name: &str) -> bool {
        self.sections().any(|(_, s)| s.output.section == name)
    }
}

/// One document as a set of one (its bytes were checked when first made).
fn single(d: &Document) -> Documents {
    let mut one = Documents::new();
    // a path taken from a set of documents is a valid path
    let _ = one.add_bytes(d.path.clone(), d.bytes.clone());
    one
}

/// Run the task and build the page's reply: on success
/// `{"ok": true, "report", "sections": [{"section", "text"}], "rerun": [names],
/// "lang": the drawings' language code}`
/// and the new state; on failure the located error (see
/// [`reply::from_error`]) and no state. The files of a section are listed
/// by [`Page::files`].
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
/// [`Page::after`]).
pub fn analyse_reply_after(prev: Option<&Page>, name: &str, text: &str, lang: &str) -> (String, Option<Page>) {
    let lang = Language::from_code(lang);
    match Page::after(prev, name, text, lang) {
        Ok(p) => {
            let sections: Vec<Value> = p
                .sections()
                .map(|(_, s)| json!({ "section": s.output.section, "text": s.output.text }))
                .collect();
            let rest = json!({ "sections": sections, "rerun": p.rerun, "lang": p.task.lang.code() }).to_string();
            // the report goes in as the text kept per section
            let v = format!("{{\"ok\":true,\"report\":{},{}", p.report_text(), &rest[1..]);
            (v, Some(p))
        }
        Err(e) => (reply::from_error(&TaskSource::new(name, text), &e).to_string(), None),
    }
}
