//! The numbers of the note's headings, figures, tables and formulas
//! (нумерация разделов, рисунков, таблиц и формул), counted in Rust.
//!
//! [`crate::markup`] walks the note in the order it writes it and asks a
//! [`Counters`] for each numbered element's number, which it writes into
//! the typst source as literal text: the body then needs no typst counter
//! and no query, so it is final after typst's first layout pass, and a
//! reference ([`crate::Span::Ref`]) is the literal number of its label.
//!
//! The rules (GOST 2.105-95, the clauses cited in template.typ's header):
//! sections "1", subsections "1.1", "1.1.1"; figures, tables and formulas
//! numbered within their section, "1.2", the formula's number in
//! parentheses "(1.3)"; before the first numbered section (the technical
//! assignment, the introduction) without the section, "2"; appendices
//! "Приложение А" with their subsections "А.1" and objects "А.2".
//!
//! The counting is typst's: the heading counter steps at every numbered
//! heading (a level missing above it is filled with 0, so a subsection of
//! an unnumbered section is "0.1"), the three object counters restart at
//! every level-1 heading, numbered or not, and the section part of an
//! object's number is the first number of the heading counter, none while
//! it is 0.

/// The running counters at one point of the note.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Counters {
    /// The heading counter (1, 2 … per level), `[0]` before the first
    /// numbered heading.
    heading: Vec<usize>,
    /// The appendix letters once the appendices have begun.
    appendix: Option<Vec<String>>,
    /// The word before an appendix's letter ("Приложение").
    appendix_word: String,
    figures: usize,
    tables: usize,
    equations: usize,
}

/// Which kind of numbered object.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Object {
    /// A figure (рисунок).
    Figure,
    /// A table (таблица).
    Table,
    /// A display formula (формула).
    Equation,
}

impl Counters {
    /// The counters at the start of the note: nothing counted yet.
    pub fn new() -> Self {
        Counters {
            heading: vec![0],
            ..Counters::default()
        }
    }

    /// A heading of `level` (1-based): its printed number when `numbered`
    /// ("2.1", "Приложение А", "А.1"), `None` for an unnumbered one. A
    /// level-1 heading restarts the figures, tables and formulas.
    pub fn heading(&mut self, level: usize, numbered: bool) -> Option<String> {
        let level = level.max(1);
        if level == 1 {
            self.figures = 0;
            self.tables = 0;
            self.equations = 0;
        }
        if !numbered {
            return None;
        }
        while self.heading.len() < level {
            self.heading.push(0);
        }
        self.heading[level - 1] += 1;
        self.heading.truncate(level);
        Some(match &self.appendix {
            None => join(self.heading.iter().map(ToString::to_string)),
            Some(letters) => {
                let letter = letter_of(letters, self.heading[0]);
                if level == 1 {
                    format!("{} {letter}", self.appendix_word)
                } else {
                    join(std::iter::once(letter).chain(self.heading[1..].iter().map(ToString::to_string)))
                }
            }
        })
    }

    /// The appendices begin: the heading counter starts again, the
    /// sections are the `letters` ("А", "Б" …) after `word` ("Приложение").
    pub fn start_appendices(&mut self, word: &str, letters: &[&str]) {
        self.heading = vec![0];
        self.appendix = Some(letters.iter().map(|s| (*s).to_owned()).collect());
        self.appendix_word = word.to_owned();
    }

    /// The next object of `kind`: its number as printed in its caption and
    /// in a reference, "1.2" (a formula's in parentheses, "(1.3)").
    pub fn object(&mut self, kind: Object) -> String {
        let n = match kind {
            Object::Figure => &mut self.figures,
            Object::Table => &mut self.tables,
            Object::Equation => &mut self.equations,
        };
        *n += 1;
        let n = *n;
        let number = match self.chapter() {
            None => n.to_string(),
            Some(c) => format!("{c}.{n}"),
        };
        match kind {
            Object::Equation => format!("({number})"),
            Object::Figure | Object::Table => number,
        }
    }

    /// The section part of an object's number: "2", "Б", or none before
    /// the first numbered section.
    fn chapter(&self) -> Option<String> {
        let h = self.heading.first().copied().unwrap_or(0);
        if h == 0 {
            return None;
        }
        Some(match &self.appendix {
            None => h.to_string(),
            Some(letters) => letter_of(letters, h),
        })
    }
}

/// The letter of appendix `n` (1-based), its number past the last letter.
fn letter_of(letters: &[String], n: usize) -> String {
    match n.checked_sub(1).and_then(|i| letters.get(i)) {
        Some(l) => l.clone(),
        None => n.to_string(),
    }
}

fn join(parts: impl Iterator<Item = String>) -> String {
    parts.collect::<Vec<_>>().join(".")
}

#[cfg(test)]
mod tests {
    use super::{Counters, Object};

    #[test]
    fn sections_subsections_and_their_objects() {
        let mut c = Counters::new();
        // the technical assignment: an unnumbered level-1 heading, its
        // table numbered without a section
        assert_eq!(c.heading(1, false), None);
        assert_eq!(c.object(Object::Table), "1");
        assert_eq!(c.object(Object::Table), "2");
        assert_eq!(c.heading(1, true).as_deref(), Some("1"));
        assert_eq!(c.object(Object::Table), "1.1");
        assert_eq!(c.heading(2, true).as_deref(), Some("1.1"));
        assert_eq!(c.heading(3, true).as_deref(), Some("1.1.1"));
        assert_eq!(c.heading(2, true).as_deref(), Some("1.2"));
        assert_eq!(c.object(Object::Figure), "1.1");
        assert_eq!(c.object(Object::Equation), "(1.1)");
        assert_eq!(c.object(Object::Equation), "(1.2)");
        assert_eq!(c.heading(1, true).as_deref(), Some("2"));
        assert_eq!(c.object(Object::Equation), "(2.1)");
        assert_eq!(c.object(Object::Figure), "2.1");
        // the conclusion: unnumbered, its objects restart under section 2
        assert_eq!(c.heading(1, false), None);
        assert_eq!(c.object(Object::Figure), "2.1");
    }

    #[test]
    fn a_missing_level_is_zero() {
        let mut c = Counters::new();
        assert_eq!(c.heading(1, false), None);
        assert_eq!(c.heading(2, true).as_deref(), Some("0.1"));
        assert_eq!(c.object(Object::Figure), "1");
        assert_eq!(c.heading(1, true).as_deref(), Some("1"));
        assert_eq!(c.heading(3, true).as_deref(), Some("1.0.1"));
    }

    #[test]
    fn appendices_take_letters() {
        let mut c = Counters::new();
        c.heading(1, true);
        c.heading(1, true);
        c.start_appendices("Приложение", &["А", "Б"]);
        assert_eq!(c.heading(1, true).as_deref(), Some("Приложение А"));
        assert_eq!(c.object(Object::Table), "А.1");
        assert_eq!(c.heading(2, true).as_deref(), Some("А.1"));
        assert_eq!(c.heading(1, true).as_deref(), Some("Приложение Б"));
        assert_eq!(c.object(Object::Table), "Б.1");
        assert_eq!(c.object(Object::Equation), "(Б.1)");
        // past the letters, the number
        assert_eq!(c.heading(1, true).as_deref(), Some("Приложение 3"));
        assert_eq!(c.object(Object::Figure), "3.1");
    }
}
