//! Lines of drawings (линии чертежа), GOST 2.303-68: the types a drawing
//! uses, their widths as a function of the main line's thickness s, and
//! their dash patterns.
//!
//! Widths: the solid main line is s (0.5 … 1.4 mm); the thin, wavy, dashed
//! and dash-dot lines are s/3 … s/2. tmm draws them s/3 rounded up to the
//! ISO 128 pen series (0.18, 0.25, 0.35, 0.5, 0.7 mm), so s = 0.7 gives
//! thin lines of 0.25 mm, which is also a DXF lineweight.
//!
//! Dashes: GOST 2.303 gives ranges in millimetres (dashed: dashes 2 … 8,
//! gaps 1 … 2; thin dash-dot: dashes 5 … 30, gaps 3 … 5; dash-dot with two
//! dots: dashes 5 … 30, gaps 4 … 6). Inside those ranges the lengths follow
//! ISO 128-20's proportions to the line width d (dashed 12d, gap 3d; long
//! dash 24d, gap 3d, dot 0.5d), so a heavier drawing gets longer dashes, and
//! are clamped to the GOST range.

use crate::DrawError;

/// The thickness s of the solid main line (толщина основной линии), mm.
///
/// ```
/// use tmm_draw::Thickness;
/// assert_eq!(Thickness::A1.mm(), 0.7);
/// assert!(Thickness::new(0.3).is_err());
/// ```
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Thickness(f64);

/// The ISO 128 pen widths, mm: thin lines are rounded up to one of them.
const PENS: [f64; 8] = [0.13, 0.18, 0.25, 0.35, 0.5, 0.7, 1.0, 1.4];

impl Thickness {
    /// s = 0.7 mm, tmm's choice for A1 sheets.
    pub const A1: Thickness = Thickness(0.7);
    /// s = 0.5 mm, tmm's choice for A4 pages (the note's figures).
    pub const A4: Thickness = Thickness(0.5);

    /// A thickness in GOST 2.303's range 0.5 … 1.4 mm.
    pub fn new(s_mm: f64) -> Result<Thickness, DrawError> {
        if s_mm.is_finite() && (0.5..=1.4).contains(&s_mm) {
            Ok(Thickness(s_mm))
        } else {
            Err(DrawError::Thickness(s_mm))
        }
    }

    /// s in millimetres.
    pub fn mm(self) -> f64 {
        self.0
    }

    /// The width of thin lines: s/3 rounded up to the ISO 128 pen series
    /// (always within GOST 2.303's s/3 … s/2).
    ///
    /// ```
    /// use tmm_draw::Thickness;
    /// assert_eq!(Thickness::A1.thin(), 0.25);
    /// assert_eq!(Thickness::A4.thin(), 0.18);
    /// ```
    pub fn thin(self) -> f64 {
        let third = self.0 / 3.0;
        PENS.iter().copied().find(|&p| p >= third - 1e-9).unwrap_or(self.0 / 2.0)
    }
}

impl Default for Thickness {
    fn default() -> Self {
        Thickness::A1
    }
}

/// A GOST 2.303 line type (тип линии).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub enum LineType {
    /// Solid main line (сплошная толстая основная): visible outlines, s.
    Main,
    /// Solid thin line (сплошная тонкая): dimension, extension, hatch, construction.
    Thin,
    /// Solid wavy line (сплошная волнистая): break lines.
    Wavy,
    /// Dashed line (штриховая): hidden outlines.
    Dashed,
    /// Thin dash-dot line (штрихпунктирная тонкая): axes, centre lines, pitch circles.
    Axis,
    /// Dash-dot line with two dots (штрихпунктирная с двумя точками):
    /// extreme positions of moving parts.
    Phantom,
}

impl LineType {
    /// Every type, in the order of GOST 2.303's table.
    pub const ALL: [LineType; 6] = [
        LineType::Main,
        LineType::Thin,
        LineType::Wavy,
        LineType::Dashed,
        LineType::Axis,
        LineType::Phantom,
    ];

    /// The stroke width for main-line thickness `s`, mm.
    pub fn width(self, s: Thickness) -> f64 {
        match self {
            LineType::Main => s.mm(),
            _ => s.thin(),
        }
    }

    /// The dash pattern for thickness `s`: alternating dash and gap
    /// lengths in mm, starting with a dash; empty for a solid line. A dot
    /// is a dash as long as the line is wide (ISO 128-20's 0.5d dot drawn
    /// with round caps covers the same d), drawn with butt caps so every
    /// length is what the pattern says.
    ///
    /// ```
    /// use tmm_draw::{LineType, Thickness};
    /// let p = LineType::Axis.dashes(Thickness::A1);
    /// assert_eq!(p.len(), 4);
    /// assert!(p[0] >= 5.0 && p[0] <= 30.0);
    /// assert!((3.0..=5.0).contains(&(p[1] + p[2] + p[3])));
    /// ```
    pub fn dashes(self, s: Thickness) -> Vec<f64> {
        let d = self.width(s);
        let dot = d;
        match self {
            LineType::Main | LineType::Thin | LineType::Wavy => Vec::new(),
            LineType::Dashed => {
                let gap = (3.0 * d).clamp(1.0, 2.0);
                vec![(12.0 * d).clamp(2.0, 8.0), gap]
            }
            LineType::Axis => {
                // GOST 2.303 measures the gap between dashes, dot included
                let gap = ((3.0 * d).clamp(3.0, 5.0) - dot) / 2.0;
                vec![(24.0 * d).clamp(5.0, 30.0), gap, dot, gap]
            }
            LineType::Phantom => {
                let gap = (3.0 * d).clamp(4.0, 6.0);
                let part = (gap - 2.0 * dot) / 3.0;
                vec![(24.0 * d).clamp(5.0, 30.0), part, dot, part, dot, part]
            }
        }
    }

    /// The gap between two dashes as GOST 2.303 measures it (from the end
    /// of one dash to the start of the next, dots included), mm; 0 for a
    /// solid line.
    pub fn gost_gap(self, s: Thickness) -> f64 {
        let p = self.dashes(s);
        p.iter().skip(1).sum()
    }

    /// The line type's name as the DXF LTYPE table and legends use it.
    pub fn dxf_name(self) -> &'static str {
        match self {
            LineType::Main | LineType::Thin | LineType::Wavy => "CONTINUOUS",
            LineType::Dashed => "GOST_DASHED",
            LineType::Axis => "GOST_DASHDOT",
            LineType::Phantom => "GOST_DASHDOTDOT",
        }
    }

    /// The standard's name of the type (Russian), for legends and the DXF
    /// LTYPE description.
    pub fn name_ru(self) -> &'static str {
        match self {
            LineType::Main => "Сплошная толстая основная",
            LineType::Thin => "Сплошная тонкая",
            LineType::Wavy => "Сплошная волнистая",
            LineType::Dashed => "Штриховая",
            LineType::Axis => "Штрихпунктирная тонкая",
            LineType::Phantom => "Штрихпунктирная с двумя точками",
        }
    }
}

/// How a legend tells series apart in black and white (легенда): a line
/// type and an optional marker, so no legend relies on colour alone.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct LegendStyle {
    /// The line type of the series.
    pub line: LineType,
    /// A marker drawn at the series' points and in the legend sample.
    pub marker: Option<Marker>,
}

/// A point marker for legends and plotted series.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Marker {
    /// An open circle.
    Circle,
    /// An open square.
    Square,
    /// An open triangle, apex up.
    Triangle,
    /// A cross ×.
    Cross,
}

impl LegendStyle {
    /// The `i`-th of a sequence of styles that differ in black and white:
    /// solid, dashed, dash-dot, two-dot, then the same with markers.
    ///
    /// ```
    /// use tmm_draw::LegendStyle;
    /// let a = LegendStyle::nth(0);
    /// assert!((1..8).all(|i| LegendStyle::nth(i) != a));
    /// ```
    pub fn nth(i: usize) -> LegendStyle {
        const LINES: [LineType; 4] = [LineType::Main, LineType::Dashed, LineType::Axis, LineType::Phantom];
        const MARKS: [Option<Marker>; 5] = [
            None,
            Some(Marker::Circle),
            Some(Marker::Square),
            Some(Marker::Triangle),
            Some(Marker::Cross),
        ];
        LegendStyle {
            line: LINES[i % 4],
            marker: MARKS[(i / 4) % 5],
        }
    }
}
