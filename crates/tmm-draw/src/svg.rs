//! The SVG rendering of a scene (SVG-представление): one `<svg>` sized in
//! millimetres with a viewBox in paper mm (y flipped to SVG's downward
//! axis), every element drawn with its GOST 2.303 width and dash array,
//! text as `<text>` with `<tspan baseline-shift>` for indices. Output is
//! deterministic: the same scene gives the same bytes.
//!
//! Lettering names osifont (an open ISO 3098 face, the letter shapes of
//! GOST 2.304 type B, with Cyrillic and Greek; drawn upright) first, then
//! upright common faces, and slants every text to GOST 2.304's 75° by an
//! exact `skewX(-15)` about its anchor rather than `font-style="italic"`,
//! whose synthetic oblique differs between viewers (and would slant an
//! already slanted face twice). Slanted faces such as KOMPAS's "GOST type
//! B" are therefore not listed. The letters osifont draws as boxes (Э э Ё
//! ё) and the signs it lacks are set in tmm's own supplement font
//! ([`SUPPLEMENT_FAMILY`], [`lettering`]).

use std::fmt::Write;

use kurbo::Point;

use crate::{Anchor, Geom, Hatch, Rich, Scene, Shape, Text, Thickness};

/// The font-family list of every text.
pub const FONT_FAMILY: &str = "osifont, 'DejaVu Sans', Arial, sans-serif";

/// The slant of GOST 2.304's slanted type: letters lean 15° from upright
/// (75° to the baseline).
pub const SLANT_DEG: f64 = 15.0;

/// The capital height per em of the lowest-capped face the SVG may be
/// printed in: osifont 1510/2048 = 0.737 (named first), DejaVu Sans
/// 0.729, and the faces a PDF typesetter without them falls back to, New
/// Computer Modern 683/1000 and Libertinus Serif 658/1000, its italic
/// 645/1000 (each font's OS/2 `sCapHeight` over its units per em). A
/// font-size of h / CAP_EM gives capitals at least h mm high in every one
/// of them (h · 0.737 / 0.645 = 1.14 h in osifont).
pub const CAP_EM: f64 = 0.645;

/// A number for SVG: at most three decimals, no trailing zeros, no "-0".
pub fn num(v: f64) -> String {
    let mut s = String::new();
    num_into(&mut s, v);
    s
}

/// [`num`] written at the end of `out`, for the many numbers of a
/// polyline (no string each).
fn num_into(out: &mut String, v: f64) {
    let start = out.len();
    let _ = write!(out, "{}", crate::fixed::Fixed(v, 3));
    if out[start..].contains('.') {
        while out.ends_with('0') {
            out.pop();
        }
        if out.ends_with('.') {
            out.pop();
        }
    }
    if &out[start..] == "-0" {
        out.truncate(start);
        out.push('0');
    }
}

/// The family of tmm's supplement to osifont (`tmm GOST supplement`, drawn
/// for tmm by `scripts/gost-supplement.py` from GOST 2.304 type B's
/// construction at osifont's metrics; MIT OR Apache-2.0): the letters
/// osifont 0.1.20220224 draws as filled boxes (Э э Ё ё) and signs it lacks.
pub const SUPPLEMENT_FAMILY: &str = "tmm GOST supplement";

/// The characters set in [`SUPPLEMENT_FAMILY`]: every one the supplement
/// font draws.
pub const SUPPLEMENT_CHARS: &str = "ЭэЁё−′″…→₀";

/// The font-family list of a run of [`SUPPLEMENT_CHARS`]: the supplement,
/// then the fallbacks without osifont, so a viewer that lacks the
/// supplement prints those letters in an upright common face rather than
/// osifont's boxes.
pub const SUPPLEMENT_FONT_FAMILY: &str = "'tmm GOST supplement', 'DejaVu Sans', Arial, sans-serif";

/// An empty mark of no width, in the supplement and in no other face,
/// that [`mark_supplement_runs`] puts at the end of every text that has a
/// run set in the supplement, before the SVG is typeset. usvg (the SVG
/// reader of the note's typesetter) shapes the whole line (a text's chunk)
/// in the font of each run and, when a substitute face has every character
/// of the line, takes all of them from it — osifont's boxed Э would come
/// back. With the mark somewhere in the line no other face has the whole
/// line, so each face gives only the characters of its own run. One mark
/// per line, at its end, so a word copied or searched in the PDF reads as
/// written (only the line's last character is followed by the mark). The
/// loose SVG files do not carry it (a browser could show it as a missing
/// glyph).
pub const RUN_MARK: char = '\u{10FFFD}';

/// `svg` with [`RUN_MARK`], in a run of its own set in the supplement, at
/// the end of every `<text>` that has a run [`lettering`] set in the
/// supplement: for the typesetter only. A text's only chunk ends there:
/// the drawings position indices by `dy`, which starts no new chunk.
///
/// ```
/// use tmm_draw::svg::{RUN_MARK, SUPPLEMENT_FONT_FAMILY, lettering, mark_supplement_runs};
/// let svg = format!("<g><text x=\"1\">{}</text><text>Epure</text></g>", lettering("Эпюра"));
/// let marked = mark_supplement_runs(&svg);
/// let mark = format!("<tspan font-family=\"{SUPPLEMENT_FONT_FAMILY}\">{RUN_MARK}</tspan></text>");
/// assert!(marked.contains(&format!("Э</tspan>пюра{mark}")));
/// assert_eq!(marked.matches(RUN_MARK).count(), 1);
/// assert_eq!(mark_supplement_runs("<text>Epure</text>"), "<text>Epure</text>");
/// ```
pub fn mark_supplement_runs(svg: &str) -> String {
    let open = format!("font-family=\"{SUPPLEMENT_FONT_FAMILY}\"");
    let mark = format!("<tspan {open}>{RUN_MARK}</tspan>");
    let mut out = String::with_capacity(svg.len());
    let mut rest = svg;
    while let Some(i) = rest.find(&open) {
        // the text the run stands in ends at the next `</text>` (texts do
        // not nest)
        let Some(j) = rest[i..].find("</text>") else { break };
        out.push_str(&rest[..i + j]);
        out.push_str(&mark);
        out.push_str("</text>");
        rest = &rest[i + j + "</text>".len()..];
    }
    out.push_str(rest);
    out
}

/// Whether `c` is set in the supplement font.
pub fn in_supplement(c: char) -> bool {
    SUPPLEMENT_CHARS.contains(c)
}

/// `s` cut into runs of characters set in osifont (`false`) and in the
/// supplement (`true`), in order; empty for an empty `s`.
///
/// ```
/// let r = tmm_draw::svg::font_runs("Эпюра ёмкости");
/// assert_eq!(r, [(true, "Э"), (false, "пюра "), (true, "ё"), (false, "мкости")]);
/// ```
pub fn font_runs(s: &str) -> Vec<(bool, &str)> {
    let mut out = Vec::new();
    let mut start = 0;
    let mut cur = None;
    for (i, c) in s.char_indices() {
        let sup = in_supplement(c);
        if cur.is_some_and(|k| k != sup) {
            out.push((!sup, &s[start..i]));
            start = i;
        }
        cur = Some(sup);
    }
    if let Some(k) = cur {
        out.push((k, &s[start..]));
    }
    out
}

/// XML-escaped text for SVG, each run of the supplement's characters in a
/// `<tspan>` naming [`SUPPLEMENT_FONT_FAMILY`] (no other attribute, so it
/// may sit inside any text or tspan).
///
/// ```
/// let t = tmm_draw::svg::lettering("Эпюра <M>");
/// assert!(t.starts_with("<tspan font-family=\"'tmm GOST supplement'"));
/// assert!(t.ends_with(">Э</tspan>пюра &lt;M&gt;"));
/// ```
pub fn lettering(s: &str) -> String {
    let mut o = String::with_capacity(s.len());
    for (sup, run) in font_runs(s) {
        if sup {
            let _ = write!(o, "<tspan font-family=\"{SUPPLEMENT_FONT_FAMILY}\">{}</tspan>", esc(run));
        } else {
            o.push_str(&esc(run));
        }
    }
    o
}

/// XML-escaped text for the SVG.
fn esc(s: &str) -> String {
    let mut o = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => o.push_str("&amp;"),
            '<' => o.push_str("&lt;"),
            '>' => o.push_str("&gt;"),
            '"' => o.push_str("&quot;"),
            _ => o.push(c),
        }
    }
    o
}

struct Svg {
    out: String,
    h: f64,
    s: Thickness,
}

impl Svg {
    fn p(&self, p: Point) -> (String, String) {
        (num(p.x), num(self.h - p.y))
    }

    fn stroke_attrs(&self, line: crate::LineType) -> String {
        let mut a = format!(
            " fill=\"none\" stroke=\"#000\" stroke-width=\"{}\" stroke-linecap=\"butt\" stroke-linejoin=\"round\"",
            num(line.width(self.s))
        );
        let d = line.dashes(self.s);
        if !d.is_empty() {
            let list: Vec<String> = d.iter().map(|&v| num(v)).collect();
            let _ = write!(a, " stroke-dasharray=\"{}\"", list.join(" "));
        }
        a
    }

    fn geom(&mut self, layer: &str, line: crate::LineType, g: &Geom) {
        let attrs = self.stroke_attrs(line);
        match g {
            Geom::Line(a, b) => {
                let ((x1, y1), (x2, y2)) = (self.p(*a), self.p(*b));
                let _ = writeln!(
                    self.out,
                    "<line class=\"{layer}\" x1=\"{x1}\" y1=\"{y1}\" x2=\"{x2}\" y2=\"{y2}\"{attrs}/>"
                );
            }
            Geom::Polyline { points, closed } => {
                let tag = if *closed { "polygon" } else { "polyline" };
                // the points written straight into the text, no string each
                let _ = write!(self.out, "<{tag} class=\"{layer}\" points=\"");
                let h = self.h;
                for (i, q) in points.iter().enumerate() {
                    if i > 0 {
                        self.out.push(' ');
                    }
                    // as `p`: x, then y from the top
                    num_into(&mut self.out, q.x);
                    self.out.push(',');
                    num_into(&mut self.out, h - q.y);
                }
                let _ = writeln!(self.out, "\"{attrs}/>");
            }
            Geom::Circle { center, radius } => {
                let (x, y) = self.p(*center);
                let _ = writeln!(
                    self.out,
                    "<circle class=\"{layer}\" cx=\"{x}\" cy=\"{y}\" r=\"{}\"{attrs}/>",
                    num(*radius)
                );
            }
            Geom::Arc {
                center,
                radius,
                start_deg,
                end_deg,
            } => {
                let sweep = crate::scene::sweep_deg(*start_deg, *end_deg);
                if sweep >= 360.0 - 1e-9 {
                    return self.geom(
                        layer,
                        line,
                        &Geom::Circle {
                            center: *center,
                            radius: *radius,
                        },
                    );
                }
                let at = |deg: f64| {
                    let (s, c) = deg.to_radians().sin_cos();
                    Point::new(center.x + radius * c, center.y + radius * s)
                };
                let ((x0, y0), (x1, y1)) = (self.p(at(*start_deg)), self.p(at(*end_deg)));
                let large = if sweep > 180.0 { 1 } else { 0 };
                // counter-clockwise with y up is sweep-flag 0 with y down
                let r = num(*radius);
                let _ = writeln!(
                    self.out,
                    "<path class=\"{layer}\" d=\"M{x0} {y0}A{r} {r} 0 {large} 0 {x1} {y1}\"{attrs}/>"
                );
            }
            Geom::Curve(c) => {
                let (x, y) = self.p(c[0].p0);
                let mut d = format!("M{x} {y}");
                for b in c {
                    let (a1, b1) = self.p(b.p1);
                    let (a2, b2) = self.p(b.p2);
                    let (a3, b3) = self.p(b.p3);
                    let _ = write!(d, "C{a1} {b1} {a2} {b2} {a3} {b3}");
                }
                let _ = writeln!(self.out, "<path class=\"{layer}\" d=\"{d}\"{attrs}/>");
            }
        }
    }

    fn hatch(&mut self, layer: &str, h: &Hatch) {
        let attrs = self.stroke_attrs(crate::LineType::Thin);
        let _ = writeln!(self.out, "<g class=\"{layer}\"{attrs}>");
        for (a, b) in h.lines() {
            let ((x1, y1), (x2, y2)) = (self.p(a), self.p(b));
            let _ = writeln!(self.out, "<line x1=\"{x1}\" y1=\"{y1}\" x2=\"{x2}\" y2=\"{y2}\"/>");
        }
        self.out.push_str("</g>\n");
    }

    fn text(&mut self, layer: &str, t: &Text) {
        let (x, y) = self.p(t.at);
        let anchor = match t.anchor {
            Anchor::Start => "start",
            Anchor::Middle => "middle",
            Anchor::End => "end",
        };
        let size = num(t.height.mm() / CAP_EM);
        // the text is drawn at the origin of a frame moved to the anchor,
        // turned, and sheared to the 75° slant
        let rot = if t.rotation_deg.abs() > 1e-9 {
            format!(" rotate({})", num(-t.rotation_deg))
        } else {
            String::new()
        };
        let _ = write!(
            self.out,
            "<text class=\"{layer}\" transform=\"translate({x} {y}){rot} skewX({})\" font-size=\"{size}\" font-family=\"{}\" text-anchor=\"{anchor}\" fill=\"#000\" xml:space=\"preserve\">",
            num(-SLANT_DEG),
            esc(FONT_FAMILY).replace("&quot;", "'")
        );
        self.out.push_str(&rich_tspans(&t.rich, t.height, t.width_factor));
        self.out.push_str("</text>\n");
    }
}

/// The tspans of rich text at height `h`: base text plain, a superscript
/// raised by half the capital height, a subscript lowered by a third of
/// it, both at the index height ([`crate::TextHeight::index`]); when a
/// span has both, the subscript is moved back under the superscript;
/// `width` narrows every run by that factor ([`Text::width_factor`]).
pub fn rich_tspans(r: &Rich, h: crate::TextHeight, width: f64) -> String {
    let ih = h.index();
    let isize = num(ih.mm() / CAP_EM);
    // The text is set to type B's width (GOST 2.304, table 2): a face wider
    // than type B prints the standard's letter widths, so a text wrapped to
    // fit a cell by them fits it printed. Every run (of one font, or an
    // index) is narrowed by the same factor, its share of that width in
    // proportion to its width in the face that prints it
    // ([`crate::face`]); usvg scales each run about the text's anchor, so
    // runs narrowed by different factors would open gaps between them.
    let face = |s: &str, h: crate::TextHeight| -> f64 {
        s.chars()
            .map(|c| crate::face::advance_em(c).map_or(h.advance(c), |em| em * h.mm() / CAP_EM))
            .sum()
    };
    let type_b = |s: &str, h: crate::TextHeight| -> f64 { s.chars().map(|c| h.advance(c)).sum() };
    let (mut wb, mut wf) = (0.0, 0.0);
    for sp in &r.spans {
        for (s, h) in [(Some(sp.base.as_str()), h), (sp.sup.as_deref(), ih), (sp.sub.as_deref(), ih)] {
            if let Some(s) = s {
                wb += type_b(s, h);
                wf += face(s, h);
            }
        }
    }
    let k = if wf > 0.0 { wb / wf } else { 1.0 } * width;
    let len = |s: &str, h: crate::TextHeight| format!(" textLength=\"{}\" lengthAdjust=\"spacingAndGlyphs\"", num(k * face(s, h)));
    // each run of one font is its own tspan with its own length: a
    // textLength applies to the characters of its own element only
    let runs = |o: &mut String, s: &str, h: crate::TextHeight, pre: &str, first: &str, post: &str| {
        for (i, (sup, run)) in font_runs(s).into_iter().enumerate() {
            let font = if sup {
                format!(" font-family=\"{SUPPLEMENT_FONT_FAMILY}\"")
            } else {
                String::new()
            };
            let _ = write!(
                o,
                "<tspan{pre}{}{}{post}{font}>{}</tspan>",
                if i == 0 { first } else { "" },
                len(run, h),
                esc(run)
            );
        }
    };
    let mut o = String::new();
    for sp in &r.spans {
        if sp.base.is_empty() {
            o.push_str("<tspan></tspan>");
        } else {
            runs(&mut o, &sp.base, h, "", "", "");
        }
        let pre = format!(" font-size=\"{isize}\"");
        if let Some(sup) = &sp.sup {
            let post = format!(" baseline-shift=\"{}\"", num(0.5 * h.mm()));
            runs(&mut o, sup, ih, &pre, "", &post);
        }
        if let Some(sub) = &sp.sub {
            let back = match &sp.sup {
                Some(sup) => format!(" dx=\"{}\"", num(-k * face(sup, ih))),
                None => String::new(),
            };
            let post = format!(" baseline-shift=\"{}\"", num(-h.mm() / 3.0));
            runs(&mut o, sub, ih, &pre, &back, &post);
        }
    }
    o
}

/// The scene as an SVG document: `width`/`height` in mm, viewBox in mm.
///
/// ```
/// use tmm_draw::{Scale, Scene, Thickness};
/// let s = Scene::new(210.0, 297.0, Scale::NATURAL, Thickness::A4).unwrap();
/// let svg = tmm_draw::svg::render(&s);
/// assert!(svg.starts_with("<svg") && svg.contains("width=\"210mm\""));
/// ```
pub fn render(scene: &Scene) -> String {
    let mut g = Svg {
        out: String::new(),
        h: scene.height,
        s: scene.s,
    };
    let (w, h) = (num(scene.width), num(scene.height));
    let _ = writeln!(
        g.out,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}mm\" height=\"{h}mm\" viewBox=\"0 0 {w} {h}\" data-scale=\"{}\">",
        scene.scale.caption('.')
    );
    for item in scene.items() {
        let layer = scene.layers()[item.layer].name.clone();
        draw(&mut g, &layer, &item.shape);
    }
    g.out.push_str("</svg>\n");
    g.out
}

/// The elements of `scene` that `keep` accepts, as SVG markup without the
/// root, in a document of the scene's size (y flipped as in [`render`]):
/// a sheet writes its frame, graph 26 and title block in groups of their
/// own this way.
///
/// ```
/// use tmm_draw::{Geom, LineType, Scale, Scene, Thickness};
/// use kurbo::Point;
/// let mut s = Scene::new(100.0, 50.0, Scale::NATURAL, Thickness::A1).unwrap();
/// s.stroke("MAIN", LineType::Main, Geom::Line(Point::new(0.0, 0.0), Point::new(10.0, 0.0))).unwrap();
/// s.stroke("THIN", LineType::Thin, Geom::Line(Point::new(0.0, 5.0), Point::new(10.0, 5.0))).unwrap();
/// let m = tmm_draw::svg::items_markup(&s, |it| it.layer == 0);
/// assert!(m.contains("y1=\"50\"") && !m.contains("y1=\"45\""));
/// ```
pub fn items_markup(scene: &Scene, keep: impl Fn(&crate::Item) -> bool) -> String {
    let mut g = Svg {
        out: String::new(),
        h: scene.height,
        s: scene.s,
    };
    for item in scene.items().iter().filter(|it| keep(it)) {
        let layer = scene.layers()[item.layer].name.clone();
        draw(&mut g, &layer, &item.shape);
    }
    g.out
}

fn draw(g: &mut Svg, layer: &str, shape: &Shape) {
    match shape {
        Shape::Stroke { line, geom } => g.geom(layer, *line, geom),
        Shape::Arrow(a) => {
            let c = a.corners(g.s);
            let pts: Vec<String> = c
                .iter()
                .map(|&q| {
                    let (x, y) = g.p(q);
                    format!("{x},{y}")
                })
                .collect();
            let _ = writeln!(
                g.out,
                "<polygon class=\"{layer}\" points=\"{}\" fill=\"#000\" stroke=\"none\"/>",
                pts.join(" ")
            );
        }
        Shape::Hatch(h) => g.hatch(layer, h),
        Shape::Text(t) => g.text(layer, t),
        Shape::Dimension(d) => {
            for part in d.parts(g.s) {
                draw(g, layer, &part);
            }
        }
    }
}
