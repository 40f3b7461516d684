//! Lettering (шрифты чертёжные), GOST 2.304-81: letter heights from the
//! standard's series, type B slanted 75°, and rich text — a symbol with its
//! subscript and superscript kept as structure (`K_v`, `R^τ_{12}`,
//! `M_{ур}`), so every renderer writes them in its own way (SVG tspans,
//! DXF MTEXT stacking) instead of flattening them to "Kv".

use crate::DrawError;

/// A letter height h (размер шрифта: the height of capitals), mm, from
/// GOST 2.304's series 2.5, 3.5, 5, 7, 10, 14, 20. There is no way to make
/// a smaller one: [`TextHeight::new`] refuses 1.8 mm and anything not in
/// the series.
///
/// ```
/// use tmm_draw::TextHeight;
/// assert_eq!(TextHeight::new(3.5).unwrap().mm(), 3.5);
/// assert!(TextHeight::new(1.8).is_err());
/// assert!(TextHeight::new(3.0).is_err());
/// assert_eq!(TextHeight::H3_5.index().mm(), 2.5);
/// assert_eq!(TextHeight::H2_5.index().mm(), 2.5);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, PartialOrd, serde::Serialize, serde::Deserialize)]
pub struct TextHeight(f64);

/// GOST 2.304's heights, mm (1.8 is left out: the standard discourages
/// it, and the course's sheets are refused with it).
const SERIES: [f64; 7] = [2.5, 3.5, 5.0, 7.0, 10.0, 14.0, 20.0];

impl TextHeight {
    /// 2.5 mm, the smallest allowed.
    pub const H2_5: TextHeight = TextHeight(2.5);
    /// 3.5 mm, the usual size of dimensions and labels.
    pub const H3_5: TextHeight = TextHeight(3.5);
    /// 5 mm, titles of views and the title block's name field.
    pub const H5: TextHeight = TextHeight(5.0);
    /// 7 mm, the sheet's designation.
    pub const H7: TextHeight = TextHeight(7.0);

    /// A height from the series.
    pub fn new(mm: f64) -> Result<TextHeight, DrawError> {
        SERIES
            .iter()
            .find(|&&h| (h - mm).abs() < 1e-9)
            .map(|&h| TextHeight(h))
            .ok_or(DrawError::TextHeight(mm))
    }

    /// The largest height of the series not above `mm`; an error if `mm`
    /// is under 2.5 (there is no smaller allowed size to fall back to).
    ///
    /// ```
    /// use tmm_draw::TextHeight;
    /// assert_eq!(TextHeight::at_most(4.2).unwrap().mm(), 3.5);
    /// assert!(TextHeight::at_most(2.0).is_err());
    /// ```
    pub fn at_most(mm: f64) -> Result<TextHeight, DrawError> {
        SERIES
            .iter()
            .rev()
            .find(|&&h| h <= mm + 1e-9)
            .map(|&h| TextHeight(h))
            .ok_or(DrawError::TextHeight(mm))
    }

    /// Every height, smallest first.
    pub fn series() -> impl DoubleEndedIterator<Item = TextHeight> {
        SERIES.iter().map(|&h| TextHeight(h))
    }

    /// The height in mm.
    pub fn mm(self) -> f64 {
        self.0
    }

    /// The height of indices (sub- and superscripts): the next smaller size
    /// of the series, never under 2.5 mm.
    pub fn index(self) -> TextHeight {
        SERIES
            .iter()
            .rev()
            .find(|&&h| h < self.0 - 1e-9)
            .map_or(TextHeight::H2_5, |&h| TextHeight(h))
    }

    /// The width of one average character, mm, for type B: capitals are
    /// 6/10 h wide with a 2/10 h gap, lower case 5/10 h with the same gap
    /// (GOST 2.304-81, table 2), so a letter takes 0.8 h or 0.7 h; narrow
    /// signs 0.35 h, a space 0.6 h and the wide letters more (Ж Ш Щ Ю Ы W
    /// 1.1 h, М Ф 0.95 h, ж м ш щ ю ф ы 0.9 h, m w 1.05 h), from osifont's
    /// advances for those classes (its capitals average 0.84 h, lower case
    /// 0.72 h, digits 0.78 h: within 5 % of type B's; each wide letter is
    /// at most the figure given).
    pub fn advance(self, c: char) -> f64 {
        // one `match` (a jump table), not a search of each class's string:
        // the labels' placement measures every candidate's text
        let k = match c {
            ' ' => 0.6,
            'Ж' | 'Ш' | 'Щ' | 'Ю' | 'Ы' | 'W' => 1.1,
            'М' | 'Ф' => 0.95,
            'ж' | 'м' | 'ш' | 'щ' | 'ю' | 'ф' | 'ы' => 0.9,
            'm' | 'w' => 1.05,
            'A'..='Z' | '0'..='9' => 0.8,
            '.' | ',' | ':' | ';' | '!' | '|' | '\'' | 'i' | 'l' | '(' | ')' => 0.35,
            c if c.is_ascii() => 0.7,
            c if c.is_uppercase() => 0.8,
            _ => 0.7,
        };
        k * self.0
    }
}

/// One piece of rich text: a base with an optional subscript and
/// superscript stacked after it (`R^τ_{12}` is base "R", sup "τ", sub "12").
#[derive(Clone, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Span {
    /// The text on the baseline.
    pub base: String,
    /// The subscript after it, if any.
    pub sub: Option<String>,
    /// The superscript after it, if any.
    pub sup: Option<String>,
}

/// Rich text (текст с индексами): spans of base text with their indices.
///
/// ```
/// use tmm_draw::Rich;
/// let r = Rich::parse("R^τ_{12} = 5 кН").unwrap();
/// assert_eq!(r.spans[0].base, "R");
/// assert_eq!(r.spans[0].sup.as_deref(), Some("τ"));
/// assert_eq!(r.spans[0].sub.as_deref(), Some("12"));
/// assert_eq!(r.spans[1].base, " = 5 кН");
/// assert_eq!(r.plain(), "Rτ12 = 5 кН");
/// ```
#[derive(Clone, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Rich {
    /// The spans in reading order.
    pub spans: Vec<Span>,
}

impl Rich {
    /// Plain text without indices.
    pub fn plain_text(s: &str) -> Rich {
        Rich {
            spans: vec![Span {
                base: s.to_string(),
                ..Span::default()
            }],
        }
    }

    /// Text from a TeX-like markup: `_x` and `^x` take one character,
    /// `_{…}` and `^{…}` a group; `\_`, `\^`, `\{`, `\\` are the characters
    /// themselves. An index attaches to the text before it.
    pub fn parse(s: &str) -> Result<Rich, DrawError> {
        let mut spans: Vec<Span> = Vec::new();
        let mut base = String::new();
        let mut it = s.chars().peekable();
        let flush = |base: &mut String, spans: &mut Vec<Span>| {
            if !base.is_empty() {
                spans.push(Span {
                    base: std::mem::take(base),
                    ..Span::default()
                });
            }
        };
        while let Some(c) = it.next() {
            match c {
                '\\' => base.push(it.next().unwrap_or('\\')),
                '_' | '^' => {
                    let arg: String = match it.next() {
                        Some('{') => {
                            let mut g = String::new();
                            loop {
                                match it.next() {
                                    Some('}') => break,
                                    Some('\\') => g.push(it.next().unwrap_or('\\')),
                                    Some(x) => g.push(x),
                                    None => return Err(DrawError::Markup(s.to_string())),
                                }
                            }
                            g
                        }
                        Some(x) => x.to_string(),
                        None => String::new(),
                    };
                    // the index belongs to the last span if that span has
                    // no index of this kind and no text was written after it
                    if base.is_empty() {
                        if let Some(last) = spans.last_mut() {
                            let slot = if c == '_' { &mut last.sub } else { &mut last.sup };
                            if slot.is_none() {
                                *slot = Some(arg);
                                continue;
                            }
                        }
                    }
                    // split the base: its last character carries the index
                    let mut head = std::mem::take(&mut base);
                    let last = head.pop().map(String::from).unwrap_or_default();
                    flush(&mut head, &mut spans);
                    let mut sp = Span {
                        base: last,
                        ..Span::default()
                    };
                    if c == '_' {
                        sp.sub = Some(arg);
                    } else {
                        sp.sup = Some(arg);
                    }
                    spans.push(sp);
                }
                _ => base.push(c),
            }
        }
        flush(&mut base, &mut spans);
        Ok(Rich { spans })
    }

    /// The text with indices written inline (for searches and alt text).
    pub fn plain(&self) -> String {
        let mut s = String::new();
        for sp in &self.spans {
            s.push_str(&sp.base);
            if let Some(x) = &sp.sup {
                s.push_str(x);
            }
            if let Some(x) = &sp.sub {
                s.push_str(x);
            }
        }
        s
    }

    /// The width of the text at height `h`, mm, by type B's letter widths;
    /// an index takes the wider of its sub- and superscript at the index height.
    pub fn width(&self, h: TextHeight) -> f64 {
        let i = h.index();
        let w = |s: &str, h: TextHeight| s.chars().map(|c| h.advance(c)).sum::<f64>();
        self.spans
            .iter()
            .map(|sp| {
                w(&sp.base, h)
                    + sp.sub
                        .as_deref()
                        .map_or(0.0, |x| w(x, i))
                        .max(sp.sup.as_deref().map_or(0.0, |x| w(x, i)))
            })
            .sum()
    }

    /// Whether there is no text at all.
    pub fn is_empty(&self) -> bool {
        self.spans.iter().all(|s| s.base.is_empty() && s.sub.is_none() && s.sup.is_none())
    }
}

/// Where the anchor point sits along the text (выравнивание).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Anchor {
    /// The anchor is at the start of the baseline.
    #[default]
    Start,
    /// The anchor is at the middle of the baseline.
    Middle,
    /// The anchor is at the end of the baseline.
    End,
}

/// A text element: rich text at a paper point, with a height from the
/// series, turned by `rotation_deg` counter-clockwise about its anchor.
#[derive(Clone, Debug, PartialEq)]
pub struct Text {
    /// The anchor point on the baseline, paper mm (y up).
    pub at: kurbo::Point,
    /// Capital height.
    pub height: TextHeight,
    /// The text.
    pub rich: Rich,
    /// Where `at` is along the baseline.
    pub anchor: Anchor,
    /// Rotation, degrees counter-clockwise.
    pub rotation_deg: f64,
    /// The letters' width over type B's (ширина букв): 1 for type B; under
    /// 1 only for the title block form's own captions, narrowed where the
    /// form's narrow columns hold no type B word (`eskd`), as the forms
    /// printed by KOMPAS-3D and the like do.
    pub width_factor: f64,
}

impl Text {
    /// Text from markup (see [`Rich::parse`]) anchored at its start.
    pub fn new(at: kurbo::Point, height: TextHeight, markup: &str) -> Result<Text, DrawError> {
        if !(at.x.is_finite() && at.y.is_finite()) {
            return Err(DrawError::NotFinite("text position"));
        }
        Ok(Text {
            at,
            height,
            rich: Rich::parse(markup)?,
            anchor: Anchor::Start,
            rotation_deg: 0.0,
            width_factor: 1.0,
        })
    }

    /// The same text with another anchor.
    pub fn anchored(mut self, anchor: Anchor) -> Text {
        self.anchor = anchor;
        self
    }

    /// The same text turned by `deg` counter-clockwise.
    pub fn rotated(mut self, deg: f64) -> Text {
        self.rotation_deg = if deg.is_finite() { deg } else { 0.0 };
        self
    }
}

/// Break `text` into lines no wider than `width` mm at height `h`, at
/// spaces; a word longer than a line is broken between letters. Returns
/// `None` if even one letter does not fit.
///
/// ```
/// use tmm_draw::{wrap, TextHeight};
/// let lines = wrap("Национальный технический университет", TextHeight::H3_5, 60.0).unwrap();
/// assert!(lines.len() >= 2);
/// ```
pub fn wrap(text: &str, h: TextHeight, width: f64) -> Option<Vec<String>> {
    if text.chars().any(|c| !c.is_whitespace() && h.advance(c) > width) {
        return None;
    }
    wrap_with(text, |s| s.chars().map(|c| h.advance(c)).sum::<f64>() <= width, true)
}

/// `text` broken greedily into lines for which `fits` holds, at spaces;
/// with `break_words`, a word that fits no line alone is broken between
/// letters (a letter that fits no line alone after a full line stands on
/// a line of its own). `None` when a word must be broken and
/// `break_words` is off, or a line would start with a letter that does
/// not fit. The breaking of [`wrap`] (type B advances) and of the title
/// block's fields (printed ink, [`crate::eskd::fit`]).
pub(crate) fn wrap_with(text: &str, fits: impl Fn(&str) -> bool, break_words: bool) -> Option<Vec<String>> {
    let mut lines: Vec<String> = Vec::new();
    let mut cur = String::new();
    for word in text.split_whitespace() {
        let cand = if cur.is_empty() {
            word.to_string()
        } else {
            format!("{cur} {word}")
        };
        if fits(&cand) {
            cur = cand;
            continue;
        }
        if !cur.is_empty() {
            lines.push(std::mem::take(&mut cur));
        }
        if fits(word) {
            cur = word.to_string();
        } else if !break_words {
            return None;
        } else {
            for c in word.chars() {
                let mut next = cur.clone();
                next.push(c);
                if !fits(&next) {
                    if cur.is_empty() {
                        return None;
                    }
                    lines.push(std::mem::take(&mut cur));
                    next = c.to_string();
                }
                cur = next;
            }
        }
    }
    if !cur.is_empty() {
        lines.push(cur);
    }
    Some(lines)
}

#[cfg(test)]
mod advance_tests {
    use super::TextHeight;

    /// The classes of [`TextHeight::advance`] written as its doc comment
    /// lists them, one search of each class's letters at a time.
    fn by_classes(c: char) -> f64 {
        if c == ' ' {
            0.6
        } else if "ЖШЩЮЫW".contains(c) {
            1.1
        } else if "МФ".contains(c) {
            0.95
        } else if "жмшщюфы".contains(c) {
            0.9
        } else if "mw".contains(c) {
            1.05
        } else if c.is_uppercase() || c.is_ascii_digit() {
            0.8
        } else if ".,:;!|'il()".contains(c) {
            0.35
        } else {
            0.7
        }
    }

    #[test]
    fn advance_is_the_documented_class_of_every_character() {
        let h = TextHeight::H5;
        // ASCII, Latin-1, Greek, Cyrillic, the symbols of the drawings
        let chars = (' '..='\u{4ff}').chain("−′″…→·≈°²³₁₂".chars());
        for c in chars {
            assert_eq!(h.advance(c), by_classes(c) * 5.0, "{c:?}");
        }
    }
}
