//! A drawing as made (чертёж): the typed elements a [`Canvas`](crate::svg::Canvas)
//! collects — lines of a style, arrows, texts with their indices, fills,
//! groups — in paper millimetres, from which both renderings come: the SVG
//! text ([`Picture::svg`], the markup the tests, the page and the note read)
//! and the [`tmm_draw::Scene`] ([`Picture::scene`]) that the sheets place
//! and write to DXF. Nothing is parsed back from the SVG.
//!
//! The canvas' styles become GOST 2.303 line types in the scene: a solid
//! line of 0.5 mm or more is the main line, a thinner one the thin line, a
//! dash longer than 12 mm the dash-dot (the axes) or, for
//! [`DASH_DOT_DOT`](crate::labels::DASH_DOT_DOT), the two-dot line, a dash
//! over 8 mm the dash-dot, a shorter one the dashed line. Black strokes
//! lie on the scene's standard layers (MAIN, THIN, AXIS, HIDDEN); a
//! coloured stroke or text on a layer of its colour (`C_0050C0`, with the
//! nearest AutoCAD colour index), so the DXF keeps the colours. A text
//! height becomes the nearest size of GOST 2.304's series, never under
//! 2.5 mm (`tmm_draw::TextHeight` has no smaller one).

use std::fmt::Write as _;

use kurbo::{Point, Vec2};
use tmm_draw::{Geom, Hatch, LineType, Rich, Scene, Shape, Span, Text, TextHeight, Thickness};

use crate::svg::{Anchor, FONT, Style, escape, rich, slant};

/// A point on the paper, mm from the top-left corner (y down).
pub type P = (f64, f64);

/// The path data of a `<path>`.
#[derive(Debug, Clone, PartialEq)]
pub enum PathData {
    /// Polylines, one per run (written `M x,y L x,y …`).
    Runs(Vec<Vec<P>>),
    /// Separate segments (written `M x,y H x` / `V y` / `L x,y`).
    Segments(Vec<(P, P)>),
}

/// One element of a drawing, in paper mm (y down).
#[derive(Debug, Clone, PartialEq)]
pub enum Element {
    /// A segment; `round` writes round caps.
    Line {
        /// From.
        a: P,
        /// To.
        b: P,
        /// The style.
        style: Style,
        /// Round caps.
        round: bool,
    },
    /// A segment of a class, its ends written to 0.1 µm (a measured chord).
    Classed {
        /// The class.
        class: String,
        /// From.
        a: P,
        /// To.
        b: P,
        /// The style.
        style: Style,
    },
    /// A polyline or a polygon.
    Poly {
        /// The vertices.
        points: Vec<P>,
        /// The style (a polygon may be filled).
        style: Style,
        /// A polygon.
        closed: bool,
    },
    /// A circle.
    Circle {
        /// Centre.
        c: P,
        /// Radius, mm.
        r: f64,
        /// The style.
        style: Style,
    },
    /// A joint or a point: a small filled circle with a thin black rim.
    Dot {
        /// Centre.
        c: P,
        /// Radius, mm.
        r: f64,
        /// Fill colour.
        fill: &'static str,
    },
    /// A fixed pivot's ground: the triangle and its hatch strokes.
    Ground {
        /// The triangle: apex, left, right.
        triangle: [P; 3],
        /// The hatch strokes under it.
        hatch: Vec<(P, P)>,
    },
    /// A filled arrowhead: tip, then the two back corners.
    Head {
        /// The corners.
        points: [P; 3],
        /// Fill colour.
        color: &'static str,
    },
    /// A text; `rich` typesets the course's index markup (`a^τ_CB`).
    Text {
        /// The baseline point.
        at: P,
        /// The words.
        text: String,
        /// Letter size, mm.
        size: f64,
        /// Where the point is along the text.
        anchor: Anchor,
        /// Colour.
        color: String,
        /// Typeset indices.
        rich: bool,
    },
    /// A text turned by 90° to read upwards (an axis' name).
    Upward {
        /// The baseline's middle.
        at: P,
        /// The words.
        text: String,
        /// Letter size, mm.
        size: f64,
    },
    /// A label placed by [`crate::labels::Placer`]: its box's middle at
    /// `c` (or its start, with `start`).
    Label {
        /// The box's middle (or the start of the text, with `start`).
        c: P,
        /// The words with index marks.
        text: String,
        /// Letter size, mm.
        size: f64,
        /// Colour.
        color: String,
        /// Anchored at the start.
        start: bool,
    },
    /// A path of one class (a curve, a grid).
    Path {
        /// The class written on it.
        class: Option<String>,
        /// The geometry.
        data: PathData,
        /// The style.
        style: Style,
    },
    /// An open marker circle of a class (the points of a curve, a legend sample).
    Marker {
        /// The class.
        class: String,
        /// Centre.
        c: P,
        /// Radius, mm.
        r: f64,
        /// The style.
        style: Style,
    },
    /// The start of a group with an id or a class and data attributes.
    GroupOpen {
        /// The id.
        id: Option<String>,
        /// The class.
        class: Option<String>,
        /// Data attributes (`data-label`).
        data: Vec<(String, String)>,
    },
    /// The end of the last group.
    GroupClose,
}

/// A finished drawing: its paper, the root's attributes and its elements.
/// It reads as its SVG text (`Deref<Target = str>`).
#[derive(Debug, Clone, PartialEq)]
pub struct Picture {
    /// Paper width, mm.
    pub width: f64,
    /// Paper height, mm.
    pub height: f64,
    /// Attributes of the root (`data-scale`, `data-mu-l`), in order.
    pub root: Vec<(String, String)>,
    /// The elements in drawing order.
    pub elements: Vec<Element>,
    svg: String,
}

impl Picture {
    /// A drawing of `elements` on a paper `width × height` mm.
    ///
    /// Polylines, polygons and the runs of paths keep only the vertices
    /// Douglas–Peucker keeps at [`tmm_draw::simplify::TOLERANCE_MM`]
    /// (0.01 mm on paper), so the SVG, the scene (the sheets, the DXF) and
    /// the PDFs made from them carry one simplified geometry.
    pub fn new(width: f64, height: f64, root: Vec<(String, String)>, mut elements: Vec<Element>) -> Picture {
        for e in &mut elements {
            simplify_element(e);
            if let Element::Text { text, .. } | Element::Label { text, .. } | Element::Upward { text, .. } = e {
                minus_signs(text);
            }
        }
        let mut p = Picture {
            width,
            height,
            root,
            elements,
            svg: String::new(),
        };
        p.svg = p.render_svg();
        p
    }

    /// The same drawing with more elements at the end and attributes on
    /// the root (a root attribute already there keeps its place).
    pub fn extended(self, more: Vec<Element>, root: Vec<(String, String)>) -> Picture {
        let Picture {
            width,
            height,
            root: mut r,
            mut elements,
            ..
        } = self;
        elements.extend(more);
        for (k, v) in root {
            match r.iter_mut().find(|(n, _)| *n == k) {
                Some(slot) => slot.1 = v,
                None => r.push((k, v)),
            }
        }
        Picture::new(width, height, r, elements)
    }

    /// The SVG document's bytes.
    pub fn into_bytes(self) -> Vec<u8> {
        self.svg.into_bytes()
    }

    /// The SVG document.
    pub fn svg(&self) -> &str {
        &self.svg
    }

    /// A root attribute's value.
    pub fn attr(&self, name: &str) -> Option<&str> {
        self.root.iter().find(|(k, _)| k == name).map(|(_, v)| v.as_str())
    }

    /// The drawing's name (наименование изображения) as it prints: the
    /// words of every text inside a [`TITLE`] group (see
    /// [`Canvas::title`](crate::svg::Canvas::title)), lines joined by a
    /// space; `None` when the drawing has no name.
    ///
    /// ```
    /// use tmm_report::svg::{Anchor, Canvas};
    /// let mut c = Canvas::new(100.0, 50.0);
    /// c.title((50.0, 8.0), "Plan of velocities", 5.0, Anchor::Middle);
    /// c.rich_paper((50.0, 14.0), "μ_v = 0,1 (m/s)/mm", 3.5, Anchor::Middle, "#000");
    /// let p = c.finish();
    /// assert_eq!(p.title().as_deref(), Some("Plan of velocities"));
    /// assert!(p.svg().contains("<g class=\"title\">"));
    /// ```
    pub fn title(&self) -> Option<String> {
        let words: Vec<&str> = self
            .elements
            .iter()
            .zip(in_title(&self.elements))
            .filter(|(_, t)| *t)
            .filter_map(|(e, _)| match e {
                Element::Text { text, .. } | Element::Label { text, .. } | Element::Upward { text, .. } => Some(text.as_str()),
                _ => None,
            })
            .collect();
        (!words.is_empty()).then(|| words.join(" "))
    }

    /// The drawing without its name: every element inside a [`TITLE`]
    /// group left out, the rest (the scale, μ and the drawing's parameters
    /// printed under the name) where it was. The note's figures are set
    /// so ([`crate::run::note_figures`]): GOST 2.105, 6.5 puts the name in
    /// the caption under the figure, and one title per figure.
    ///
    /// ```
    /// use tmm_report::svg::{Anchor, Canvas};
    /// let mut c = Canvas::new(100.0, 50.0);
    /// c.title((50.0, 8.0), "Plan of velocities", 5.0, Anchor::Middle);
    /// c.rich_paper((50.0, 14.0), "μ_v = 0,1 (m/s)/mm", 3.5, Anchor::Middle, "#000");
    /// let p = c.finish().without_title();
    /// assert!(p.title().is_none());
    /// assert!(!p.svg().contains("Plan of") && p.svg().contains("(m/s)/mm"));
    /// ```
    pub fn without_title(&self) -> Picture {
        let keep: Vec<Element> = self
            .elements
            .iter()
            .zip(in_title(&self.elements))
            .filter(|(_, t)| !*t)
            .map(|(e, _)| e.clone())
            .collect();
        Picture::new(self.width, self.height, self.root.clone(), keep)
    }

    /// The drawing's GOST 2.302 scale (`data-scale`), when it is drawn to one.
    pub fn scale(&self) -> Option<tmm_draw::Scale> {
        self.attr("data-scale").and_then(gost_scale)
    }

    fn render_svg(&self) -> String {
        let (w, h) = (self.width, self.height);
        let mut root = String::new();
        for (k, v) in &self.root {
            let _ = write!(root, " {k}=\"{}\"", escape(v));
        }
        let mut s = String::with_capacity(64 * self.elements.len() + 256);
        // the drawing's scale first, as the sheets and the page read it
        let _ = writeln!(s, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>");
        let _ = writeln!(
            s,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}mm\" height=\"{h}mm\" viewBox=\"0 0 {w} {h}\"{root}>\n<rect x=\"0\" y=\"0\" width=\"{w}\" height=\"{h}\" fill=\"#ffffff\"/>"
        );
        self.body_into(&mut s, "");
        s.push_str("</svg>\n");
        s
    }

    /// The elements' markup alone, every group id prefixed by `prefix`
    /// (unique ids when several drawings share a sheet).
    pub fn body(&self, prefix: &str) -> String {
        let mut s = String::with_capacity(64 * self.elements.len());
        self.body_into(&mut s, prefix);
        s
    }

    fn body_into(&self, s: &mut String, prefix: &str) {
        for e in &self.elements {
            write_element(s, e, prefix);
        }
    }

    /// The drawing as a scene of `tmm_draw` in paper mm (y up), at its
    /// scale (1:1 for a diagram), s = 0.7 mm.
    pub fn scene(&self) -> Scene {
        let scale = self.scale().unwrap_or(tmm_draw::Scale::NATURAL);
        let mut sc = Scene::new(self.width.max(1.0), self.height.max(1.0), scale, Thickness::A1).unwrap_or_else(|_| unreachable_scene());
        let h = self.height;
        for e in &self.elements {
            add_to_scene(&mut sc, e, h);
        }
        sc
    }
}

/// The class of the group that holds a drawing's name
/// ([`Canvas::title`](crate::svg::Canvas::title)).
pub const TITLE: &str = "title";

/// For each element, whether it lies in a [`TITLE`] group (the group's
/// own marks included).
fn in_title(elements: &[Element]) -> Vec<bool> {
    let mut depth = 0usize;
    let mut title_at: Option<usize> = None;
    elements
        .iter()
        .map(|e| match e {
            Element::GroupOpen { class, .. } => {
                depth += 1;
                if title_at.is_none() && class.as_deref() == Some(TITLE) {
                    title_at = Some(depth);
                }
                title_at.is_some()
            }
            Element::GroupClose => {
                let inside = title_at.is_some();
                if title_at == Some(depth) {
                    title_at = None;
                }
                depth = depth.saturating_sub(1);
                inside
            }
            _ => title_at.is_some(),
        })
        .collect()
}

/// A negative number's sign as GOST 2.304 writes it: the minus sign −
/// (U+2212), not the hyphen-minus, in every text of every drawing (a
/// legend's "T_I max = −49,302 Дж", a level's value, a tick). A hyphen is
/// a sign where a digit (or a decimal point and a digit) follows it and
/// it opens the text or follows a space, a bracket, `=`, `;`, `:`, `…`,
/// `/`, `·` or an index mark; a hyphen between words or digits ("0-1",
/// "двух-") stays.
///
/// ```
/// use tmm_report::svg::{Anchor, Canvas};
/// let mut c = Canvas::new(50.0, 20.0);
/// c.rich_paper((5.0, 5.0), "T_I max = -49,302 Дж; (-1; -0.5) 0-1 a-b", 3.5, Anchor::Start, "#000");
/// let p = c.finish();
/// let tmm_report::picture::Element::Text { text, .. } = &p.elements[0] else { panic!() };
/// assert_eq!(text, "T_I max = \u{2212}49,302 Дж; (\u{2212}1; \u{2212}0.5) 0-1 a-b");
/// ```
fn minus_signs(text: &mut String) {
    if !text.contains('-') {
        return;
    }
    let chars: Vec<char> = text.chars().collect();
    let is_sign = |i: usize| {
        let next = chars.get(i + 1).copied();
        let digit_next = next.is_some_and(|c| c.is_ascii_digit())
            || (matches!(next, Some('.' | ',')) && chars.get(i + 2).is_some_and(char::is_ascii_digit));
        let opens = i == 0
            || matches!(
                chars[i - 1],
                ' ' | '(' | '[' | '{' | '=' | ';' | ':' | '…' | '/' | '·' | '_' | '^' | '\u{a0}' | '\u{2009}'
            );
        digit_next && opens
    };
    *text = chars
        .iter()
        .enumerate()
        .map(|(i, &c)| if c == '-' && is_sign(i) { '\u{2212}' } else { c })
        .collect();
}

/// Drops the vertices of a polyline, polygon or path run that lie within
/// [`tmm_draw::simplify::TOLERANCE_MM`] of the line through the others
/// (its ends, and a polygon's first vertex, stay), its vertices taken at
/// the 0.001 mm the files print.
fn simplify_element(e: &mut Element) {
    use tmm_draw::simplify::{TOLERANCE_MM, simplify, simplify_closed};
    let run = |pts: &[P], closed: bool| -> Option<Vec<P>> {
        if pts.len() < 3 {
            return None;
        }
        // the vertices at the files' 0.001 mm first: the kept ones print
        // the same, and which are kept no longer hangs on the last bits of
        // a coordinate, which WebAssembly's libm and the machine's may set
        // apart (the page and the CLI then keep the same vertices)
        let grid = |v: f64| (v * 1000.0).round() / 1000.0;
        let v: Vec<Point> = pts.iter().map(|&(x, y)| Point::new(grid(x), grid(y))).collect();
        let s = if closed {
            simplify_closed(&v, TOLERANCE_MM)
        } else {
            simplify(&v, TOLERANCE_MM)
        };
        (s.len() < pts.len()).then(|| s.iter().map(|p| (p.x, p.y)).collect())
    };
    match e {
        Element::Poly { points, closed, .. } => {
            if let Some(s) = run(points, *closed) {
                *points = s;
            }
        }
        Element::Path {
            data: PathData::Runs(runs),
            ..
        } => {
            for r in runs.iter_mut() {
                if let Some(s) = run(r, false) {
                    *r = s;
                }
            }
        }
        _ => {}
    }
}

fn unreachable_scene() -> Scene {
    // a positive finite size always makes a scene
    Scene::new(1.0, 1.0, tmm_draw::Scale::NATURAL, Thickness::A1).expect("a 1 × 1 mm scene")
}

impl std::ops::Deref for Picture {
    type Target = str;
    fn deref(&self) -> &str {
        &self.svg
    }
}

impl std::fmt::Display for Picture {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.svg)
    }
}

impl From<Picture> for String {
    fn from(p: Picture) -> String {
        p.svg
    }
}

/// The letter size (em, mm) a text of size `size` is written at: never
/// under the lettering floor ([`crate::labels::with_lettering_floor`]).
pub fn em(size: f64) -> f64 {
    size.max(crate::labels::lettering_floor())
}

/// The letter size of an index (sub- or superscript) of a text of size
/// `size`: 0.7 of it (GOST 2.304's next smaller size), never under the
/// lettering floor.
pub fn index_em(size: f64) -> f64 {
    (0.7 * size).max(crate::labels::lettering_floor())
}

/// A scale as written (`1:2,5`, `2:1`, `1:1`) as a GOST 2.302 scale, from
/// the table of [`crate::paper::STANDARD_SCALES`].
pub fn gost_scale(text: &str) -> Option<tmm_draw::Scale> {
    let t = text.trim().replace('.', ",");
    let (f, _) = crate::paper::STANDARD_SCALES.iter().find(|(_, k)| *k == t)?;
    if *f >= 1.0 {
        tmm_draw::Scale::enlargement(*f).ok()
    } else {
        tmm_draw::Scale::reduction((1.0 / f * 10.0).round() / 10.0).ok()
    }
}

/// A coordinate with three decimals, as `{:.3}` writes it (without its
/// slow exact expansion: [`tmm_draw::fixed::Fixed`]).
fn f3(v: f64) -> tmm_draw::fixed::Fixed {
    tmm_draw::fixed::Fixed(v, 3)
}

fn style_attr(s: &Style) -> String {
    let mut a = format!(
        "stroke=\"{}\" stroke-width=\"{:.3}\" fill=\"{}\"",
        s.color,
        s.width,
        s.fill.unwrap_or("none")
    );
    if let Some((d, g)) = s.dash {
        // the markers of GOST 2.303's dash-dot lines (crate::labels)
        if d == 12.01 {
            a.push_str(" stroke-dasharray=\"12 3 1 3\"");
        } else if d == 12.02 {
            a.push_str(" stroke-dasharray=\"12 3 1 3 1 3\"");
        } else if d > 8.0 {
            // dash-dot: the dot in the middle of the gap
            let h = 0.5 * (g - 0.5).max(0.5);
            let _ = write!(a, " stroke-dasharray=\"{d:.2} {h:.2} 0.50 {h:.2}\"");
        } else {
            let _ = write!(a, " stroke-dasharray=\"{d:.2} {g:.2}\"");
        }
    }
    a
}

fn anchor_word(a: Anchor) -> &'static str {
    match a {
        Anchor::Start => "start",
        Anchor::Middle => "middle",
        Anchor::End => "end",
    }
}

fn write_element(s: &mut String, e: &Element, prefix: &str) {
    match e {
        Element::Line { a, b, style, round } => {
            let cap = if *round { " stroke-linecap=\"round\"" } else { "" };
            let _ = writeln!(
                s,
                "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" {}{cap}/>",
                f3(a.0),
                f3(a.1),
                f3(b.0),
                f3(b.1),
                style_attr(style)
            );
        }
        Element::Classed { class, a, b, style } => {
            let _ = writeln!(
                s,
                "<line class=\"{}\" x1=\"{:.4}\" y1=\"{:.4}\" x2=\"{:.4}\" y2=\"{:.4}\" stroke=\"{}\" stroke-width=\"{}\"/>",
                escape(class),
                a.0,
                a.1,
                b.0,
                b.1,
                style.color,
                style.width
            );
        }
        Element::Poly { points, style, closed } => {
            let tag = if *closed { "polygon" } else { "polyline" };
            // the points written straight into the text: a plot has
            // thousands, and a string for each was most of the drawing's cost
            let _ = write!(s, "<{tag} points=\"");
            for (i, p) in points.iter().enumerate() {
                let sep = if i == 0 { "" } else { " " };
                let _ = write!(s, "{sep}{},{}", f3(p.0), f3(p.1));
            }
            let _ = writeln!(s, "\" {} stroke-linejoin=\"round\"/>", style_attr(style));
        }
        Element::Circle { c, r, style } => {
            let _ = writeln!(
                s,
                "<circle cx=\"{:.3}\" cy=\"{:.3}\" r=\"{:.3}\" {}/>",
                c.0,
                c.1,
                r,
                style_attr(style)
            );
        }
        Element::Dot { c, r, fill } => {
            let _ = writeln!(
                s,
                "<circle cx=\"{:.3}\" cy=\"{:.3}\" r=\"{r:.3}\" fill=\"{fill}\" stroke=\"#000\" stroke-width=\"0.25\"/>",
                c.0, c.1
            );
        }
        Element::Ground {
            triangle: [a, b, c],
            hatch,
        } => {
            let _ = writeln!(
                s,
                "<polygon points=\"{:.3},{:.3} {:.3},{:.3} {:.3},{:.3}\" fill=\"none\" stroke=\"#000\" stroke-width=\"0.35\"/>",
                a.0, a.1, b.0, b.1, c.0, c.1
            );
            for (p, q) in hatch {
                let _ = writeln!(
                    s,
                    "<line x1=\"{:.3}\" y1=\"{:.3}\" x2=\"{:.3}\" y2=\"{:.3}\" stroke=\"#000\" stroke-width=\"0.25\"/>",
                    p.0, p.1, q.0, q.1
                );
            }
        }
        Element::Head { points: [t, l, r], color } => {
            let _ = writeln!(
                s,
                "<polygon points=\"{:.3},{:.3} {:.3},{:.3} {:.3},{:.3}\" fill=\"{color}\" stroke=\"none\"/>",
                t.0, t.1, l.0, l.1, r.0, r.1
            );
        }
        Element::Text {
            at,
            text,
            size,
            anchor,
            color,
            rich: r,
        } => {
            let a = anchor_word(*anchor);
            let size = &em(*size);
            if *r {
                let _ = writeln!(
                    s,
                    "<text x=\"{:.3}\" y=\"{:.3}\" font-size=\"{size:.2}\" font-family=\"{FONT}\" transform=\"{}\" text-anchor=\"{a}\" fill=\"{color}\" xml:space=\"preserve\">{}</text>",
                    at.0,
                    at.1,
                    slant(at.0, at.1),
                    rich(text, *size)
                );
            } else {
                let _ = writeln!(
                    s,
                    "<text x=\"{:.3}\" y=\"{:.3}\" font-size=\"{size:.2}\" font-family=\"{FONT}\" transform=\"{}\" text-anchor=\"{a}\" fill=\"{color}\">{}</text>",
                    at.0,
                    at.1,
                    slant(at.0, at.1),
                    tmm_draw::svg::lettering(text)
                );
            }
        }
        Element::Upward { at, text, size } => {
            let size = em(*size);
            let _ = writeln!(
                s,
                "<text x=\"{}\" y=\"{:.2}\" font-size=\"{size}\" font-family=\"{FONT}\" text-anchor=\"middle\" transform=\"rotate(-90 {} {:.2}) {}\">{}</text>",
                at.0,
                at.1,
                at.0,
                at.1,
                slant(at.0, at.1),
                tmm_draw::svg::lettering(text)
            );
        }
        Element::Label {
            c,
            text,
            size: h,
            color,
            start,
        } => {
            let n = crate::labels::plain(text).chars().count();
            let h = &em(*h);
            let _ = write!(
                s,
                "<text class=\"label\" xml:space=\"preserve\" x=\"{:.3}\" y=\"{:.3}\" font-size=\"{h:.2}\" font-family=\"{FONT}\" transform=\"{}\" text-anchor=\"{}\" fill=\"{color}\" data-chars=\"{n}\">",
                c.0,
                c.1 + 0.35 * h,
                slant(c.0, c.1 + 0.35 * h),
                if *start { "start" } else { "middle" }
            );
            let mut level = 0i8;
            for (t, sh) in crate::labels::parts(text) {
                let dy = f64::from(level - sh) * 0.35 * h;
                if sh == 0 {
                    let _ = write!(s, "<tspan dy=\"{dy:.3}\">{}</tspan>", tmm_draw::svg::lettering(&t));
                } else {
                    let _ = write!(
                        s,
                        "<tspan dy=\"{dy:.3}\" font-size=\"{:.2}\">{}</tspan>",
                        index_em(*h),
                        tmm_draw::svg::lettering(&t)
                    );
                }
                level = sh;
            }
            s.push_str("</text>\n");
        }
        Element::Path { class, data, style } => {
            let mut d = String::new();
            match data {
                PathData::Runs(runs) => {
                    for run in runs {
                        for (i, p) in run.iter().enumerate() {
                            let _ = write!(d, "{}{},{} ", if i == 0 { "M" } else { "L" }, f3(p.0), f3(p.1));
                        }
                    }
                }
                PathData::Segments(segs) => {
                    for (a, b) in segs {
                        let _ = write!(d, "M{},{}", f3(a.0), f3(a.1));
                        if a.1 == b.1 {
                            let _ = write!(d, "H{}", f3(b.0));
                        } else if a.0 == b.0 {
                            let _ = write!(d, "V{}", f3(b.1));
                        } else {
                            let _ = write!(d, "L{},{}", f3(b.0), f3(b.1));
                        }
                    }
                }
            }
            let class = class.as_ref().map_or(String::new(), |c| format!(" class=\"{}\"", escape(c)));
            let dash = style.dash.map_or(String::new(), |(a, b)| format!(" stroke-dasharray=\"{a} {b}\""));
            let _ = writeln!(
                s,
                "<path{class} d=\"{}\" stroke=\"{}\" stroke-width=\"{}\" fill=\"none\"{dash}/>",
                d.trim_end(),
                style.color,
                style.width
            );
        }
        Element::Marker { class, c, r, style } => {
            let _ = writeln!(
                s,
                "<circle class=\"{}\" cx=\"{:.3}\" cy=\"{:.3}\" r=\"{r}\" stroke=\"{}\" stroke-width=\"{}\" fill=\"none\"/>",
                escape(class),
                c.0,
                c.1,
                style.color,
                style.width
            );
        }
        Element::GroupOpen { id, class, data } => {
            s.push_str("<g");
            if let Some(c) = class {
                let _ = write!(s, " class=\"{}\"", escape(c));
            }
            if let Some(i) = id {
                let _ = write!(s, " id=\"{}{}\"", escape(prefix), escape(i));
            }
            for (k, v) in data {
                let _ = write!(s, " {k}=\"{}\"", escape(v));
            }
            s.push_str(">\n");
        }
        Element::GroupClose => s.push_str("</g>\n"),
    }
}

/// The GOST 2.303 line type of a canvas style.
///
/// ```
/// use tmm_report::{picture::line_type, svg::Style, labels::{DASH_DOT, DASH_DOT_DOT}};
/// use tmm_draw::LineType;
/// assert_eq!(line_type(&Style::THICK), LineType::Main);
/// assert_eq!(line_type(&Style::THIN), LineType::Thin);
/// assert_eq!(line_type(&Style::AXIS), LineType::Axis);
/// assert_eq!(line_type(&Style::DASHED), LineType::Dashed);
/// assert_eq!(line_type(&DASH_DOT), LineType::Axis);
/// assert_eq!(line_type(&DASH_DOT_DOT), LineType::Phantom);
/// ```
pub fn line_type(s: &Style) -> LineType {
    match s.dash {
        Some((d, _)) if (d - 12.02).abs() < 1e-9 => LineType::Phantom,
        Some((d, _)) if d > 8.0 => LineType::Axis,
        Some(_) => LineType::Dashed,
        None if s.width >= 0.5 - 1e-9 => LineType::Main,
        None => LineType::Thin,
    }
}

/// The nearest GOST 2.304 letter size to `mm`, 2.5 mm at least.
///
/// ```
/// use tmm_report::picture::text_height;
/// assert_eq!(text_height(2.2).mm(), 2.5);
/// assert_eq!(text_height(3.2).mm(), 3.5);
/// assert_eq!(text_height(4.0).mm(), 3.5);
/// assert_eq!(text_height(4.5).mm(), 5.0);
/// ```
pub fn text_height(mm: f64) -> TextHeight {
    let mut best = TextHeight::H2_5;
    for h in TextHeight::series() {
        if (h.mm() - mm).abs() < (best.mm() - mm).abs() {
            best = h;
        }
    }
    best
}

/// A colour as written (`#0050c0`, `#000`, `black`) as RGB.
fn rgb(c: &str) -> Option<(u8, u8, u8)> {
    let h = c.trim().strip_prefix('#')?;
    let v = |s: &str| u8::from_str_radix(s, 16).ok();
    match h.len() {
        6 => Some((v(&h[0..2])?, v(&h[2..4])?, v(&h[4..6])?)),
        3 => {
            let d = |i: usize| v(&h[i..=i]).map(|x| x * 17);
            Some((d(0)?, d(1)?, d(2)?))
        }
        _ => None,
    }
}

/// The layer of a colour: `None` for black (the standard layers), else
/// the layer's name and the nearest AutoCAD colour index.
fn colour_layer(c: &str) -> Option<(String, u8)> {
    let (r, g, b) = match c.trim() {
        "black" | "none" | "" => return None,
        "red" => (255, 0, 0),
        "blue" => (0, 0, 255),
        "green" => (0, 128, 0),
        "gray" | "grey" => (128, 128, 128),
        other => rgb(other)?,
    };
    if (r, g, b) == (0, 0, 0) {
        return None;
    }
    // AutoCAD's first colours: 1 red, 2 yellow, 3 green, 4 cyan, 5 blue, 6 magenta, 8 grey, 9 light grey
    const ACI: [(u8, (i32, i32, i32)); 8] = [
        (1, (255, 0, 0)),
        (2, (255, 255, 0)),
        (3, (0, 255, 0)),
        (4, (0, 255, 255)),
        (5, (0, 0, 255)),
        (6, (255, 0, 255)),
        (8, (128, 128, 128)),
        (9, (192, 192, 192)),
    ];
    let (ri, gi, bi) = (i32::from(r), i32::from(g), i32::from(b));
    // grey when the channels are close, else the nearest hue
    let aci = ACI
        .iter()
        .min_by_key(|(_, (a, bb, cc))| (a - ri).pow(2) + (bb - gi).pow(2) + (cc - bi).pow(2))
        .map_or(7, |x| x.0);
    Some((format!("C_{r:02X}{g:02X}{b:02X}"), aci))
}

/// The layer an element of colour `color` and line type `line` goes on,
/// declared in the scene when it is new.
fn layer_for(sc: &mut Scene, color: &str, line: LineType, text: bool) -> String {
    match colour_layer(color) {
        Some((name, aci)) => {
            if !sc.layers().iter().any(|l| l.name == name) {
                sc.layer(&name, aci, LineType::Thin);
            }
            name
        }
        None if text => "TEXT".to_string(),
        None => match line {
            LineType::Main => "MAIN",
            LineType::Axis | LineType::Phantom => "AXIS",
            LineType::Dashed => "HIDDEN",
            _ => "THIN",
        }
        .to_string(),
    }
}

/// The course's index markup (`a^τ_CB`, `R_{12}`) as rich text: the same
/// reading as [`rich`] — `^` raises and `_` lowers up to the next space,
/// mark or closing brace.
pub fn rich_text(s: &str) -> Rich {
    #[derive(PartialEq, Clone, Copy)]
    enum Level {
        Base,
        Up,
        Down,
    }
    let mut spans: Vec<Span> = Vec::new();
    let mut level = Level::Base;
    let mut run = String::new();
    let mut braced = false;
    let flush = |spans: &mut Vec<Span>, run: &mut String, level: Level| {
        if run.is_empty() {
            return;
        }
        let t = std::mem::take(run);
        match level {
            Level::Base => spans.push(Span {
                base: t,
                ..Span::default()
            }),
            Level::Up | Level::Down => {
                let fresh = match spans.last() {
                    Some(l) => (level == Level::Up && l.sup.is_some()) || (level == Level::Down && l.sub.is_some()),
                    None => true,
                };
                if fresh {
                    spans.push(Span::default());
                }
                if let Some(l) = spans.last_mut() {
                    if level == Level::Up {
                        l.sup = Some(t);
                    } else {
                        l.sub = Some(t);
                    }
                }
            }
        }
    };
    for ch in s.chars() {
        match ch {
            '^' | '_' => {
                flush(&mut spans, &mut run, level);
                level = if ch == '^' { Level::Up } else { Level::Down };
                braced = false;
            }
            '{' if level != Level::Base && run.is_empty() => braced = true,
            '}' if braced => {
                flush(&mut spans, &mut run, level);
                level = Level::Base;
                braced = false;
            }
            ' ' if level != Level::Base && !braced => {
                flush(&mut spans, &mut run, level);
                level = Level::Base;
                run.push(' ');
            }
            c => run.push(c),
        }
    }
    flush(&mut spans, &mut run, level);
    Rich { spans }
}

fn pt(p: P, h: f64) -> Point {
    Point::new(p.0, h - p.1)
}

fn ok(p: &P) -> bool {
    p.0.is_finite() && p.1.is_finite()
}

fn stroke(sc: &mut Scene, style: &Style, geom: Geom) {
    let line = line_type(style);
    let layer = layer_for(sc, style.color, line, false);
    // an element the scene refuses (degenerate) is left out of it
    let _ = sc.stroke(&layer, line, geom);
}

#[allow(clippy::too_many_arguments)] // the text's own fields, one call per canvas element kind
fn text(sc: &mut Scene, at: Point, s: &str, size: f64, anchor: tmm_draw::Anchor, color: &str, rich: bool, rot: f64) {
    let r = if rich { rich_text(s) } else { Rich::plain_text(s) };
    if r.is_empty() {
        return;
    }
    let layer = layer_for(sc, color, LineType::Thin, true);
    let t = Text {
        at,
        height: text_height(size),
        rich: r,
        anchor,
        rotation_deg: 0.0,
        width_factor: 1.0,
    }
    .rotated(rot);
    let _ = sc.text(&layer, t);
}

fn anchor(a: Anchor) -> tmm_draw::Anchor {
    match a {
        Anchor::Start => tmm_draw::Anchor::Start,
        Anchor::Middle => tmm_draw::Anchor::Middle,
        Anchor::End => tmm_draw::Anchor::End,
    }
}

fn fill_of(sc: &mut Scene, color: &str, loops: Vec<Vec<Point>>) {
    // a filled region is hatched (GOST 2.306) on its colour's layer
    let size = loops
        .iter()
        .flatten()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| (lo.min(p.x), hi.max(p.x)));
    let spacing = ((size.1 - size.0) / 12.0).clamp(2.0, 10.0);
    if let Ok(h) = Hatch::gost(loops, spacing, false) {
        let layer = match colour_layer(color) {
            Some(_) => layer_for(sc, color, LineType::Thin, false),
            None => "HATCH".to_string(),
        };
        let _ = sc.add(&layer, Shape::Hatch(h));
    }
}

fn add_to_scene(sc: &mut Scene, e: &Element, h: f64) {
    match e {
        Element::Line { a, b, style, .. } | Element::Classed { a, b, style, .. } => {
            if ok(a) && ok(b) && a != b {
                stroke(sc, style, Geom::Line(pt(*a, h), pt(*b, h)));
            }
        }
        Element::Poly { points, style, closed } => {
            let pts: Vec<Point> = points.iter().filter(|p| ok(p)).map(|&p| pt(p, h)).collect();
            if pts.len() < 2 {
                return;
            }
            if let (Some(f), true) = (style.fill, *closed) {
                if f != "none" && pts.len() >= 3 {
                    fill_of(sc, f, vec![pts.clone()]);
                }
            }
            if style.color != "none" && style.width > 0.0 {
                stroke(
                    sc,
                    style,
                    Geom::Polyline {
                        points: pts,
                        closed: *closed,
                    },
                );
            }
        }
        Element::Circle { c, r, style } => {
            if ok(c) && r.is_finite() && *r > 0.0 {
                stroke(
                    sc,
                    style,
                    Geom::Circle {
                        center: pt(*c, h),
                        radius: *r,
                    },
                );
            }
        }
        Element::Dot { c, r, .. } => {
            if ok(c) && *r > 0.0 {
                stroke(
                    sc,
                    &Style::THIN,
                    Geom::Circle {
                        center: pt(*c, h),
                        radius: *r,
                    },
                );
            }
        }
        Element::Ground { triangle, hatch } => {
            stroke(
                sc,
                &Style::THIN,
                Geom::Polyline {
                    points: triangle.iter().map(|&p| pt(p, h)).collect(),
                    closed: true,
                },
            );
            for (a, b) in hatch {
                stroke(sc, &Style::THIN, Geom::Line(pt(*a, h), pt(*b, h)));
            }
        }
        Element::Head { points: [t, l, r], color } => {
            let back = ((l.0 + r.0) / 2.0, (l.1 + r.1) / 2.0);
            let dir = Vec2::new(t.0 - back.0, back.1 - t.1);
            if dir.hypot() > 1e-9 {
                let layer = layer_for(sc, color, LineType::Thin, false);
                let _ = sc.add(
                    &layer,
                    Shape::Arrow(tmm_draw::Arrow {
                        tip: pt(*t, h),
                        dir: dir.normalize(),
                    }),
                );
            }
        }
        Element::Text {
            at,
            text: s,
            size,
            anchor: a,
            color,
            rich,
        } => {
            if ok(at) {
                text(sc, pt(*at, h), s, *size, anchor(*a), color, *rich, 0.0);
            }
        }
        Element::Upward { at, text: s, size } => {
            text(sc, pt(*at, h), s, *size, tmm_draw::Anchor::Middle, "#000", false, 90.0);
        }
        Element::Label {
            c,
            text: s,
            size,
            color,
            start,
        } => {
            let a = if *start {
                tmm_draw::Anchor::Start
            } else {
                tmm_draw::Anchor::Middle
            };
            text(sc, pt((c.0, c.1 + 0.35 * size), h), s, *size, a, color, true, 0.0);
        }
        Element::Path { data, style, .. } => match data {
            PathData::Runs(runs) => {
                for run in runs {
                    let pts: Vec<Point> = run.iter().filter(|p| ok(p)).map(|&p| pt(p, h)).collect();
                    if pts.len() >= 2 {
                        stroke(
                            sc,
                            style,
                            Geom::Polyline {
                                points: pts,
                                closed: false,
                            },
                        );
                    }
                }
            }
            PathData::Segments(segs) => {
                for (a, b) in segs {
                    if ok(a) && ok(b) && a != b {
                        stroke(sc, style, Geom::Line(pt(*a, h), pt(*b, h)));
                    }
                }
            }
        },
        Element::Marker { c, r, style, .. } => {
            if ok(c) && *r > 0.0 {
                stroke(
                    sc,
                    style,
                    Geom::Circle {
                        center: pt(*c, h),
                        radius: *r,
                    },
                );
            }
        }
        Element::GroupOpen { .. } | Element::GroupClose => {}
    }
}
