//! The `[project]` section (данные проекта): who hands the course project
//! in, to whom, and how its documents look — the title page of the note and
//! the title block (основная надпись) of every sheet are filled from it.
//!
//! Every field is optional; a task without `[project]` gets empty fields,
//! a Russian note without the frame, and A1 sheets.

use serde::Deserialize;

use crate::{Error, TaskSource};

/// The language of the note and the sheets (язык документов).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Language {
    /// Russian, the course's language (default).
    #[default]
    Ru,
    /// Ukrainian.
    Uk,
    /// English.
    En,
}

impl Language {
    /// The codes accepted in `[project] lang` and `--lang`.
    pub const CODES: &[&str] = &["ru", "uk", "en"];

    /// The language of a code, if it is one of [`Language::CODES`].
    ///
    /// ```
    /// use tmm_report::project::Language;
    /// assert_eq!(Language::from_code("uk"), Some(Language::Uk));
    /// assert_eq!(Language::from_code("de"), None);
    /// ```
    pub fn from_code(code: &str) -> Option<Self> {
        match code {
            "ru" => Some(Language::Ru),
            "uk" => Some(Language::Uk),
            "en" => Some(Language::En),
            _ => None,
        }
    }

    /// The code: `ru`, `uk` or `en`.
    pub fn code(self) -> &'static str {
        match self {
            Language::Ru => "ru",
            Language::Uk => "uk",
            Language::En => "en",
        }
    }
}

/// The sheet format of the drawings (формат листа, GOST 2.301).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum SheetFormat {
    /// A1, 841 × 594 mm (default, the course's format).
    #[default]
    A1,
    /// A2, 594 × 420 mm.
    A2,
    /// A4 portrait, 210 × 297 mm: the page of the explanatory note. Only
    /// the note's figures are made for it (each for the text width, at a
    /// standard scale that fits, [`crate::paper::slot_mm`]); no sheet is,
    /// and `[project] sheet` is A1 or A2.
    A4,
}

impl SheetFormat {
    /// Width and height in millimetres, landscape (GOST 2.301).
    ///
    /// ```
    /// use tmm_report::project::SheetFormat;
    /// assert_eq!(SheetFormat::A1.size_mm(), (841.0, 594.0));
    /// assert_eq!(SheetFormat::A2.size_mm(), (594.0, 420.0));
    /// assert_eq!(SheetFormat::A4.size_mm(), (210.0, 297.0));
    /// ```
    pub fn size_mm(self) -> (f64, f64) {
        match self {
            SheetFormat::A1 => (841.0, 594.0),
            SheetFormat::A2 => (594.0, 420.0),
            SheetFormat::A4 => (210.0, 297.0),
        }
    }

    /// The format's name, `A1`, `A2` or `A4`.
    pub fn name(self) -> &'static str {
        match self {
            SheetFormat::A1 => "A1",
            SheetFormat::A2 => "A2",
            SheetFormat::A4 => "A4",
        }
    }
}

/// The project's data (данные проекта) from `[project]`.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Project {
    /// The university (вуз).
    pub university: String,
    /// The department (кафедра).
    pub department: String,
    /// The student (студент, «Разраб.»).
    pub student: String,
    /// The student's group (группа).
    pub group: String,
    /// The teacher (руководитель, «Пров.»).
    pub teacher: String,
    /// The variant of the assignment (вариант).
    pub variant: String,
    /// The city on the title page (город).
    pub city: String,
    /// The year (год).
    pub year: String,
    /// The project's title (тема); the task's `title` when not given.
    pub title: String,
    /// The designation code (обозначение), e.g. `ТММ.КП.017.00.000`.
    pub designation: String,
    /// The language of the note and the sheets.
    pub lang: Language,
    /// The ESKD frame with the title block on every page of the note.
    pub frame: bool,
    /// The sheets' format.
    pub sheet: SheetFormat,
}

#[derive(Deserialize)]
struct File {
    title: Option<String>,
    project: Option<Raw>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Raw {
    university: Option<String>,
    department: Option<String>,
    student: Option<String>,
    group: Option<String>,
    teacher: Option<String>,
    variant: Option<toml::Spanned<toml::Value>>,
    city: Option<String>,
    year: Option<toml::Spanned<toml::Value>>,
    title: Option<String>,
    designation: Option<String>,
    lang: Option<toml::Spanned<String>>,
    frame: Option<bool>,
    sheet: Option<toml::Spanned<String>>,
}

/// The longest text accepted in a `[project]` field, in characters (a title
/// block's field holds far less; this only keeps nonsense out): the limit
/// of every name and title, checked with its place before this section is
/// read ([`crate::user_text`]).
pub const MAX_FIELD_CHARS: usize = crate::user_text::MAX_TEXT_CHARS;

/// Read `[project]` (all fields optional).
///
/// ```
/// use tmm_report::{TaskSource, project::{load, Language, SheetFormat}};
/// let t = TaskSource::new("t.toml", "title = \"Four-bar\"\n[project]\nstudent = \"Ivanov I. I.\"\nvariant = 17\nlang = \"uk\"\nsheet = \"A2\"\n");
/// let p = load(&t).unwrap();
/// assert_eq!((p.student.as_str(), p.variant.as_str(), p.title.as_str()), ("Ivanov I. I.", "17", "Four-bar"));
/// assert_eq!((p.lang, p.sheet, p.frame), (Language::Uk, SheetFormat::A2, false));
/// let bad = TaskSource::new("t.toml", "[project]\nlang = \"de\"\n");
/// let e = load(&bad).unwrap_err();
/// assert_eq!(e.exit_code(), 2);
/// assert!(e.to_string().contains("project.lang") && e.to_string().contains(":2:"));
/// ```
pub fn load(task: &TaskSource) -> Result<Project, Error> {
    let f: File = task.parse("project")?;
    let task_title = f.title.unwrap_or_default();
    let Some(r) = f.project else {
        return Ok(Project {
            title: task_title,
            ..Project::default()
        });
    };
    // the length and the characters were checked with their place by task.parse
    let text = |_field: &str, v: Option<String>| -> Result<String, Error> { Ok(v.unwrap_or_default().trim().to_string()) };
    let word = |field: &str, v: Option<toml::Spanned<toml::Value>>| -> Result<String, Error> {
        match v {
            None => Ok(String::new()),
            Some(s) => match s.get_ref() {
                toml::Value::String(t) => text(field, Some(t.clone())),
                toml::Value::Integer(i) => Ok(i.to_string()),
                _ => Err(Error::at(
                    task,
                    s.span(),
                    &format!("project.{field}"),
                    "expected a text or a whole number",
                )),
            },
        }
    };
    let lang = match r.lang {
        None => Language::Ru,
        Some(s) => Language::from_code(s.get_ref()).ok_or_else(|| {
            Error::at(task, s.span(), "project.lang", format!("unknown language \"{}\"", s.get_ref()))
                .with_help(format!("the note is written in {}", Language::CODES.join(", ")))
        })?,
    };
    let sheet = match r.sheet {
        None => SheetFormat::A1,
        Some(s) => match s.get_ref().to_ascii_uppercase().as_str() {
            "A1" => SheetFormat::A1,
            "A2" => SheetFormat::A2,
            _ => {
                return Err(
                    Error::at(task, s.span(), "project.sheet", format!("unknown sheet format \"{}\"", s.get_ref()))
                        .with_help("the sheets are A1 (default) or A2"),
                );
            }
        },
    };
    let title = text("title", r.title)?;
    Ok(Project {
        university: text("university", r.university)?,
        department: text("department", r.department)?,
        student: text("student", r.student)?,
        group: text("group", r.group)?,
        teacher: text("teacher", r.teacher)?,
        variant: word("variant", r.variant)?,
        city: text("city", r.city)?,
        year: word("year", r.year)?,
        title: if title.is_empty() { task_title.trim().to_string() } else { title },
        designation: text("designation", r.designation)?,
        lang,
        frame: r.frame.unwrap_or(false),
        sheet,
    })
}
