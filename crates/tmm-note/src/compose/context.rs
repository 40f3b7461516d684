//! What every section's composer reads: the report, the drawings, the task
//! and the words, with helpers that format numbers for the language.

use serde_json::Value;
use tmm_report::output::Documents;

use super::words::Words;
use crate::error::NoteError;
use crate::model::{Block, Cell, Lang, Text};
use crate::number::{format_quantity, zero_noise};

/// Significant digits of every number the note prints (the stated rounding:
/// four significant digits, the accuracy a course project reports).
pub const DIGITS: u8 = 4;

/// The composing context.
pub(crate) struct Ctx<'a> {
    pub lang: Lang,
    pub words: &'a Words,
    pub report: &'a Value,
    pub docs: &'a Documents,
    /// The drawings made for the note's page
    /// ([`tmm_report::run::note_figures`]), at their own sizes and scales.
    pub figures: &'a Documents,
    pub task: &'a toml::Table,
}

impl Ctx<'_> {
    /// A word, its notation (`K_v`, `M_ур`, a lone `θ`; in Russian and
    /// Ukrainian a lone Latin letter too) marked as math
    /// ([`crate::notation::notation_with`]); a line of the symbols under a
    /// formula (a `where_*` key) with every symbol it explains marked
    /// ([`crate::notation::where_line`]), so each is set as in its formula.
    pub fn w(&self, key: &str) -> Result<String, NoteError> {
        let text = self.words.get(key)?;
        let lone_latin = self.lang != Lang::En;
        Ok(if key.starts_with("where_") {
            crate::notation::where_line(text, lone_latin)
        } else {
            crate::notation::notation_with(text, lone_latin)
        })
    }

    /// A word as written: the typst math of a formula's symbol (`sym_*`).
    pub fn sym(&self, key: &str) -> Result<String, NoteError> {
        self.words.get(key).map(str::to_string)
    }

    /// A word with its notation marked and its places filled; the
    /// arguments (numbers, the caller's names) stay literal.
    pub fn fill(&self, key: &str, args: &[String]) -> Result<String, NoteError> {
        let mut s = self.w(key)?;
        // from the last place down, so {1} does not eat the start of {10}
        for (i, a) in args.iter().enumerate().rev() {
            s = s.replace(&format!("{{{}}}", i + 1), &crate::notation::strip(a));
        }
        Ok(s)
    }

    /// A paragraph of a word with its places filled.
    pub fn para(&self, key: &str, args: &[String]) -> Result<Block, NoteError> {
        Ok(Block::Paragraph(Text::plain(self.fill(key, args)?)))
    }

    /// The value at a JSON pointer (`/gear/eps_alpha`), if it is a number.
    pub fn opt(&self, ptr: &str) -> Option<f64> {
        self.report.pointer(ptr).and_then(Value::as_f64)
    }

    /// The number at a JSON pointer.
    pub fn v(&self, ptr: &str) -> Result<f64, NoteError> {
        self.opt(ptr).ok_or_else(|| NoteError::MissingValue { path: ptr.to_string() })
    }

    /// The text at a JSON pointer.
    pub fn s(&self, ptr: &str) -> Option<&str> {
        self.report.pointer(ptr).and_then(Value::as_str)
    }

    /// A number with the unit of the words key `unit` (empty: none).
    ///
    /// A zero (or the noise of one: [`crate::number::zero_noise`], an
    /// angle against a full turn, another value under 10⁻⁹ in the unit
    /// printed) is written `0`, not `0,000`: four significant digits of
    /// nothing say nothing (θ = 0° of a centric crank-slider, an eccentricity
    /// e = 0 мм, the largest pressure angle 0° of an oscillating cylinder,
    /// not the solver's 1,2·10⁻⁶°).
    pub fn q(&self, value: f64, unit: &str) -> Result<String, NoteError> {
        let u = if unit.is_empty() { String::new() } else { self.w(unit)? };
        self.quantity(value, &u)
    }

    /// `value` and the unit text `u`, a zero as `0` (see [`Ctx::q`]).
    fn quantity(&self, value: f64, u: &str) -> Result<String, NoteError> {
        // an angle's scale is a full turn; another value of a sentence
        // stands alone, only its absolute floor applies
        let scale = if u.starts_with('°') { 360.0 } else { 0.0 };
        format_quantity(zero_noise(value, scale), DIGITS, u, self.lang)
    }

    /// A relative difference `x` (a ratio) in per cent: `0 %` where it is
    /// the rounding noise of an exact agreement (under 10⁻⁹), not the
    /// "0,000" four significant digits of zero would print; otherwise its
    /// four significant digits in per cent.
    pub fn relative(&self, x: f64) -> Result<String, NoteError> {
        self.q(zero_noise(x, 0.0) * 100.0, "u_percent")
    }

    /// A given value at `ptr`, scaled by `scale`, as the task gives it: its
    /// printed digits without the trailing zeros (δ = 0,02, not 0,02000), a
    /// unit after it.
    pub fn given(&self, ptr: &str, scale: f64, unit: &str) -> Result<String, NoteError> {
        let f = crate::number::format_number(self.v(ptr)? * scale, DIGITS, self.lang)?;
        if f.exponent.is_some() || !f.mantissa.contains([',', '.']) {
            return self.qv(ptr, scale, unit);
        }
        let mut s = f.mantissa.trim_end_matches('0').trim_end_matches([',', '.']).to_string();
        let u = if unit.is_empty() { String::new() } else { self.w(unit)? };
        crate::number::push_unit(&mut s, &u);
        Ok(s)
    }

    /// The significant digits of the given value at `ptr` as [`Ctx::given`]
    /// prints it (δ = 0,02: one), for a formula that substitutes it.
    pub fn given_digits(&self, ptr: &str) -> Result<u8, NoteError> {
        let f = crate::number::format_number(self.v(ptr)?, DIGITS, self.lang)?;
        if f.exponent.is_some() {
            return Ok(DIGITS);
        }
        let trimmed = f.mantissa.trim_end_matches('0').trim_end_matches([',', '.']);
        let digits = trimmed
            .trim_start_matches(['0', ',', '.', '\u{2212}'])
            .chars()
            .filter(char::is_ascii_digit);
        // the integer's trailing zeros (δ = 100) stay significant
        let whole = if f.mantissa.contains([',', '.']) {
            0
        } else {
            f.mantissa.len() - trimmed.len()
        };
        Ok(u8::try_from((digits.count() + whole).clamp(1, usize::from(DIGITS))).unwrap_or(DIGITS))
    }

    /// The number at `ptr` with a unit, scaled by `scale` (1000 for mm).
    pub fn qv(&self, ptr: &str, scale: f64, unit: &str) -> Result<String, NoteError> {
        self.q(self.v(ptr)? * scale, unit)
    }

    /// An angle in radians at `ptr`, printed in degrees.
    pub fn deg(&self, ptr: &str) -> Result<String, NoteError> {
        self.quantity(self.v(ptr)?.to_degrees(), "°")
    }

    /// The figure of the run's drawing `path`, or `None` if the run has
    /// none: the drawing as made for the note's page, set at its own width
    /// (never scaled), so its printed scale and μ are the page's.
    pub fn figure(&self, path: &str, caption_key: &str) -> Result<Option<Block>, NoteError> {
        if self.docs.get(path).is_none() {
            return Ok(None);
        }
        let Some(p) = self.figures.picture(path) else {
            return Ok(None);
        };
        Ok(Some(Block::Figure {
            caption: self.w(caption_key)?,
            svg: p.svg().to_string(),
            width_mm: p.width,
            label: None,
        }))
    }

    /// A table with headings and units from words keys.
    pub fn table(&self, caption: &str, columns: &[(&str, &str)], rows: Vec<Vec<Cell>>) -> Result<Block, NoteError> {
        let mut header = Vec::new();
        let mut units = Vec::new();
        for (h, u) in columns {
            header.push(self.w(h)?);
            units.push(if u.is_empty() { String::new() } else { self.w(u)? });
        }
        Ok(Block::Table {
            caption: self.w(caption)?,
            header,
            rows,
            units,
            label: None,
        })
    }

    /// A two-column table "quantity | value" with the value's unit in the cell.
    pub fn quantities(&self, caption: &str, rows: Vec<(String, String)>) -> Result<Block, NoteError> {
        Ok(Block::Table {
            caption: self.w(caption)?,
            header: vec![self.w("col_quantity")?, self.w("col_value")?],
            rows: rows.into_iter().map(|(a, b)| vec![text(a), text(b)]).collect(),
            units: Vec::new(),
            label: None,
        })
    }
}

/// A number cell with [`DIGITS`] significant digits.
///
/// A value below 10⁻⁹ in magnitude is the rounding noise of an exact zero
/// (a rocker's speed at its dead position) and prints as 0; the table
/// prints 0 also for a value under the resolution of its column's largest
/// ([`crate::number::zero_noise`], applied where the table is set).
pub fn num(value: f64) -> Cell {
    let value = zero_noise(value, 0.0);
    Cell::Number { value, digits: DIGITS }
}

/// A text cell.
pub fn text(s: impl Into<String>) -> Cell {
    Cell::Text(Text::plain(s))
}

/// A formula block.
pub fn formula(math: &str) -> Block {
    Block::Formula {
        typst_math: math.to_string(),
        label: None,
    }
}

/// A section with the four subsections of the course's order.
pub fn four_parts(
    cx: &Ctx,
    title_key: &str,
    statement: Vec<Block>,
    formulas: Vec<Block>,
    results: Vec<Block>,
    conclusions: Vec<Block>,
) -> Result<crate::model::Section, NoteError> {
    use crate::model::Section;
    let mut s = Section::new(cx.w(title_key)?);
    for (key, blocks) in [
        ("sub_statement", statement),
        ("sub_formulas", formulas),
        ("sub_results", results),
        ("sub_conclusions", conclusions),
    ] {
        if blocks.is_empty() {
            continue;
        }
        let mut sub = Section::new(cx.w(key)?);
        sub.blocks = blocks;
        s.subsections.push(sub);
    }
    Ok(s)
}
