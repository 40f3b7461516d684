//! The document model of the explanatory note (пояснительная записка),
//! independent of typst syntax.
//!
//! A [`Note`] is what the caller builds from a task's results: the project's
//! data for the title page and the title block, the technical assignment, the
//! numbered sections, the list of sources and the appendices. Text is stored as
//! plain strings; the typst markup is generated (and every string escaped) by
//! [`crate::typeset`], so a name such as `O'Neil #1 *_$@<` typesets literally.

use serde::{Deserialize, Serialize};

/// The language of the note (язык записки): every fixed word comes from the
/// translation file `lang/<code>.toml`, numbers take the decimal comma in
/// Russian and Ukrainian and the point in English.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Lang {
    /// Russian (русский), the default.
    #[default]
    Ru,
    /// Ukrainian (українська).
    Uk,
    /// English.
    En,
}

impl Lang {
    /// All languages, in the order of their translation files.
    pub const ALL: [Lang; 3] = [Lang::Ru, Lang::Uk, Lang::En];

    /// The ISO 639-1 code, also typst's `text(lang: ..)` (it selects the
    /// hyphenation patterns).
    ///
    /// ```
    /// assert_eq!(tmm_note::Lang::Uk.code(), "uk");
    /// ```
    pub fn code(self) -> &'static str {
        match self {
            Lang::Ru => "ru",
            Lang::Uk => "uk",
            Lang::En => "en",
        }
    }

    /// The decimal separator: the comma for ru/uk (GOST 8.417 practice), the
    /// point for en.
    ///
    /// ```
    /// assert_eq!(tmm_note::Lang::Ru.decimal_separator(), ',');
    /// assert_eq!(tmm_note::Lang::En.decimal_separator(), '.');
    /// ```
    pub fn decimal_separator(self) -> char {
        match self {
            Lang::Ru | Lang::Uk => ',',
            Lang::En => '.',
        }
    }
}

/// The project's data shown on the title page and in the title block
/// (основная надпись).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct ProjectInfo {
    /// The university (вуз), first line of the title page.
    pub university: String,
    /// The department (кафедра).
    pub department: String,
    /// The student's name (студент, «Разраб.»).
    pub student: String,
    /// The student's group (группа).
    pub group: String,
    /// The teacher's name (руководитель, «Пров.»).
    pub teacher: String,
    /// The variant of the task (вариант задания).
    pub variant: String,
    /// The city printed above the year on the title page (город).
    pub city: String,
    /// The year (год).
    pub year: String,
    /// The project's title (тема проекта), e.g. the mechanism's name.
    pub title: String,
    /// The document's designation code (обозначение документа), e.g.
    /// `ТММ.КП.012.00.000 ПЗ`.
    pub designation: String,
}

/// A run of text inside a paragraph, a list item or a table cell.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub enum Span {
    /// Plain text, typeset literally.
    Plain(String),
    /// Bold text.
    Strong(String),
    /// Italic text.
    Emph(String),
    /// Inline math in typst math syntax (without the `$` delimiters), e.g.
    /// `omega_1 = 12.5 "рад/с"`.
    Math(String),
    /// A number formatted for the note's language with `digits` significant
    /// digits and an optional unit after a thin space (see
    /// [`crate::number::format_quantity`]).
    Number {
        /// The value.
        value: f64,
        /// Significant digits, 1 … 17.
        digits: u8,
        /// The unit, e.g. `Н·м`; empty for none.
        unit: String,
    },
    /// A reference to a labelled formula, figure or table: typeset as its
    /// number, `(1.3)` for a formula, `1.2` for a figure or a table.
    Ref(String),
    /// A citation of the list of sources by its 1-based position: `[3]`.
    Cite(usize),
}

/// Rich text: a sequence of [`Span`]s.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct Text(pub Vec<Span>);

impl Text {
    /// Plain text.
    ///
    /// ```
    /// let t = tmm_note::Text::plain("ω₁ = 10 рад/с");
    /// assert_eq!(t.0.len(), 1);
    /// ```
    pub fn plain(s: impl Into<String>) -> Self {
        Text(vec![Span::Plain(s.into())])
    }

    /// Appends a span (builder style).
    ///
    /// ```
    /// use tmm_note::{Span, Text};
    /// let t = Text::plain("Сила ").with(Span::Math("F_21".into()));
    /// assert_eq!(t.0.len(), 2);
    /// ```
    pub fn with(mut self, span: Span) -> Self {
        self.0.push(span);
        self
    }
}

impl From<&str> for Text {
    fn from(s: &str) -> Self {
        Text::plain(s)
    }
}

impl From<String> for Text {
    fn from(s: String) -> Self {
        Text::plain(s)
    }
}

/// A table cell (ячейка таблицы).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub enum Cell {
    /// Text.
    Text(Text),
    /// A number formatted for the note's language (no unit: the column's unit
    /// stands in the header).
    Number {
        /// The value.
        value: f64,
        /// Significant digits, 1 … 17.
        digits: u8,
    },
    /// An empty cell.
    Empty,
}

impl From<&str> for Cell {
    fn from(s: &str) -> Self {
        Cell::Text(Text::plain(s))
    }
}

/// A block of a section's body.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub enum Block {
    /// A paragraph (абзац), first line indented.
    Paragraph(Text),
    /// A display formula in typst math syntax (without the `$` delimiters),
    /// numbered at the right, `(1.3)`.
    Formula {
        /// The formula, e.g. `v_B = omega_1 l_(O A)`.
        typst_math: String,
        /// A label to refer to it with [`Span::Ref`], or `None`.
        label: Option<String>,
    },
    /// A table numbered `Таблица 1.1 – caption` above it (GOST 2.105, 4.4).
    Table {
        /// The caption.
        caption: String,
        /// The column headings.
        header: Vec<String>,
        /// The rows; every row has `header.len()` cells.
        rows: Vec<Vec<Cell>>,
        /// The unit of each column, printed after its heading as
        /// `heading, unit`; empty (or an empty string) for none.
        units: Vec<String>,
        /// A label to refer to it with [`Span::Ref`], or `None`.
        label: Option<String>,
    },
    /// A figure from an SVG document, numbered `Рисунок 1.2 – caption` below it.
    Figure {
        /// The caption.
        caption: String,
        /// The SVG document (as the drawings of tmm produce it).
        svg: String,
        /// The width on the page in mm (at most the text width; wider is
        /// shrunk to the text width).
        width_mm: f64,
        /// A label to refer to it with [`Span::Ref`], or `None`.
        label: Option<String>,
    },
    /// A bulleted list (перечисление), marked with the dash.
    List(Vec<Text>),
    /// A worked formula (расчётная формула с подстановкой): symbols, the
    /// run's numbers substituted, the result; numbered like a formula. Held
    /// as data, so the numbers it shows can be checked
    /// ([`crate::calc::Calculation::check`]).
    Calculation(crate::calc::Calculation),
}

/// A section (раздел) or subsection (подраздел).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct Section {
    /// The heading, without its number.
    pub title: String,
    /// The body.
    pub blocks: Vec<Block>,
    /// The subsections, numbered `1.1`, `1.2` … under section 1.
    pub subsections: Vec<Section>,
}

impl Section {
    /// A section with a title and no content yet.
    pub fn new(title: impl Into<String>) -> Self {
        Section {
            title: title.into(),
            ..Section::default()
        }
    }
}

/// The explanatory note (пояснительная записка) of the course project.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct Note {
    /// The language of every fixed word and of the numbers.
    pub lang: Lang,
    /// The project's data (title page, title block).
    pub project: ProjectInfo,
    /// Draw the ESKD frame (GOST 2.104) with the title block on every page
    /// from the contents on.
    pub frame: bool,
    /// The body of the technical assignment (техническое задание), placed
    /// before the contents: the task's data tables. Empty: a line saying the
    /// assignment form is attached.
    pub assignment: Vec<Block>,
    /// The introduction (введение): an unnumbered section before section 1
    /// (its title is the heading), or `None`.
    #[serde(default)]
    pub introduction: Option<Section>,
    /// The numbered sections 1, 2 ….
    pub sections: Vec<Section>,
    /// The conclusion (заключение): an unnumbered section after the last
    /// numbered one, before the list of sources, or `None`.
    #[serde(default)]
    pub conclusion: Option<Section>,
    /// The list of sources (список использованных источников), one entry each.
    pub sources: Vec<String>,
    /// The appendices (приложения) А, Б ….
    pub appendices: Vec<Section>,
}
