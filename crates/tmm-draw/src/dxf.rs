//! The DXF rendering of a scene (DXF-представление) for KOMPAS-3D and
//! AutoCAD: an AutoCAD 2007 (AC1021) file, UTF-8 so Cyrillic reads back as
//! written, in millimetres (`$INSUNITS` 4) at paper size (the scene's
//! scale is the drawing's), with
//!
//! - an LTYPE table holding GOST 2.303's dashed, dash-dot and dash-dot-dot
//!   patterns for the scene's s ([`crate::LineType::dashes`]);
//! - one layer per scene layer with its colour, linetype and lineweight
//!   (main lines s, thin lines s/3 rounded to a pen: 0.7 and 0.25 mm at
//!   s = 0.7); an element whose type differs from its layer's carries its
//!   own linetype and lineweight;
//! - a text style "GOST type B" on KOMPAS's Unicode type B font file
//!   (`gost_bu.ttf`, installed with KOMPAS-3D and so visible to AutoCAD on
//!   the same machine) and "Standard" on the open osifont (`osifont.ttf`);
//!   never `txt`, which has no Cyrillic;
//! - plain text as TEXT on its baseline, text with indices as MTEXT with
//!   AutoCAD's stacking codes (`K\S^v;` a subscript, `x\S2^;` a
//!   superscript, `R\Sτ^12;` both);
//! - hatches as HATCH entities with a user-defined 45° pattern, arrows as
//!   SOLID triangles, dimensions as their lines, arrows and text on the
//!   dimension layer;
//! - every table, block record and the root dictionary with valid handles
//!   and owners, so an `ezdxf` audit has nothing to fix.
//!
//! The file is written directly as group-code pairs: the `dxf` crate
//! (used to read the file back in the tests) writes neither HATCH
//! entities nor table heads with handles.

use std::fmt::Write;

use kurbo::Point;

use crate::{Anchor, Geom, Hatch, LineType, Rich, Scene, Shape, Text, Thickness};

/// The valid DXF lineweights, hundredths of a millimetre.
const LINEWEIGHTS: [i32; 24] = [
    0, 5, 9, 13, 15, 18, 20, 25, 30, 35, 40, 50, 53, 60, 70, 80, 90, 100, 106, 120, 140, 158, 200, 211,
];

/// The nearest valid DXF lineweight (code 370) to a width in mm.
///
/// ```
/// assert_eq!(tmm_draw::dxf::lineweight(0.7), 70);
/// assert_eq!(tmm_draw::dxf::lineweight(0.25), 25);
/// assert_eq!(tmm_draw::dxf::lineweight(0.18), 18);
/// ```
pub fn lineweight(mm: f64) -> i32 {
    let h = mm * 100.0;
    *LINEWEIGHTS
        .iter()
        .min_by(|a, b| ((**a as f64) - h).abs().total_cmp(&((**b as f64) - h).abs()))
        .unwrap_or(&25)
}

/// The text style every text uses.
pub const TEXT_STYLE: &str = "GOST type B";
/// Its font file: KOMPAS-3D's Unicode GOST 2.304 type B.
pub const TEXT_FONT: &str = "gost_bu.ttf";
/// The font file of the "Standard" style: the open osifont.
pub const FALLBACK_FONT: &str = "osifont.ttf";

/// A number for DXF written at the end of `out`: six decimals at most, no
/// trailing zeros, no "-0" (a drawing writes hundreds of thousands of
/// them: no string each).
fn num_into(out: &mut String, v: f64) {
    let start = out.len();
    let _ = write!(out, "{}", crate::fixed::Fixed(v, 6));
    // six decimals always write a point, so the zeros end at it
    while out.ends_with('0') {
        out.pop();
    }
    if out.ends_with('.') {
        out.push('0');
    }
    if &out[start..] == "-0.0" {
        out.truncate(start);
        out.push_str("0.0");
    }
}

struct Out {
    s: String,
    next: u32,
}

impl Out {
    /// One group: the code and the value, a string value in DXF's caret
    /// notation (a literal `^` is `^ `, a control character `^` + its
    /// letter), so MTEXT's stacking `^` and line breaks survive reading.
    fn pair(&mut self, code: i32, v: &str) {
        let _ = writeln!(self.s, "{code:>3}");
        if v.bytes().all(|b| b >= 0x20 && b != b'^') {
            // nothing to escape (every number, most names): as it is
            self.s.push_str(v);
            self.s.push('\n');
            return;
        }
        for c in v.chars() {
            match c {
                '^' => self.s.push_str("^ "),
                c if (c as u32) < 0x20 => {
                    self.s.push('^');
                    self.s.push(char::from_u32(c as u32 + 0x40).unwrap_or('?'));
                }
                c => self.s.push(c),
            }
        }
        self.s.push('\n');
    }
    fn f(&mut self, code: i32, v: f64) {
        let v = if v.is_finite() { v } else { 0.0 };
        // a number has nothing to escape: written straight in
        let _ = writeln!(self.s, "{code:>3}");
        num_into(&mut self.s, v);
        self.s.push('\n');
    }
    fn i(&mut self, code: i32, v: i64) {
        self.pair(code, &v.to_string());
    }
    fn handle(&mut self) -> String {
        let h = format!("{:X}", self.next);
        self.next += 1;
        h
    }
    fn xy(&mut self, code: i32, p: Point) {
        self.f(code, p.x);
        self.f(code + 10, p.y);
        self.f(code + 20, 0.0);
    }
}

/// The DXF pattern of a line type: (total length, elements), dots as 0,
/// gaps negative (DXF's convention).
fn ltype_pattern(line: LineType, s: Thickness) -> (f64, Vec<f64>) {
    let d = line.dashes(s);
    if d.is_empty() {
        return (0.0, Vec::new());
    }
    let w = line.width(s);
    // the pattern's dots (the dash as long as the line is wide) become DXF
    // dots of length 0, their length added to the gaps beside them
    let mut el: Vec<f64> = Vec::new();
    for (k, &v) in d.iter().enumerate() {
        let is_dot = k > 0 && k % 2 == 0 && (v - w).abs() < 1e-12;
        if k % 2 == 0 && !is_dot {
            el.push(v);
        } else if is_dot {
            if let Some(last) = el.last_mut() {
                *last -= v / 2.0;
            }
            el.push(0.0);
            el.push(-v / 2.0);
        } else {
            match el.last_mut() {
                Some(last) if *last < 0.0 => *last -= v,
                _ => el.push(-v),
            }
        }
    }
    (el.iter().map(|v| v.abs()).sum(), el)
}

/// MTEXT content of rich text: `\` `{` `}` escaped, indices as stacks.
fn mtext(r: &Rich) -> String {
    let esc = |s: &str| s.replace('\\', "\\\\").replace('{', "\\{").replace('}', "\\}");
    let stack = |s: &str| {
        esc(s)
            .replace('^', "\\^")
            .replace('/', "\\/")
            .replace('#', "\\#")
            .replace(';', "\\;")
    };
    let mut o = String::new();
    for sp in &r.spans {
        o.push_str(&esc(&sp.base));
        match (&sp.sup, &sp.sub) {
            (None, None) => {}
            (sup, sub) => {
                let _ = write!(
                    o,
                    "\\S{}^{};",
                    stack(sup.as_deref().unwrap_or("")),
                    stack(sub.as_deref().unwrap_or(""))
                );
            }
        }
    }
    o
}

/// The scene as DXF text.
pub fn render(scene: &Scene) -> String {
    let mut o = Out {
        s: String::new(),
        next: 0x20,
    };
    let s = scene.s;
    let layers = scene.layers();
    // handles fixed up front for the objects that others point to
    let h_vport_t = o.handle();
    let h_ltype_t = o.handle();
    let h_layer_t = o.handle();
    let h_style_t = o.handle();
    let h_view_t = o.handle();
    let h_ucs_t = o.handle();
    let h_appid_t = o.handle();
    let h_dimstyle_t = o.handle();
    let h_br_t = o.handle();
    let h_ms = o.handle();
    let h_ps = o.handle();
    let h_root = o.handle();
    let h_group = o.handle();

    let line_types: Vec<LineType> = vec![LineType::Dashed, LineType::Axis, LineType::Phantom];

    // TABLES
    o.pair(0, "SECTION");
    o.pair(2, "TABLES");
    let table = |o: &mut Out, name: &str, h: &str, n: usize| {
        o.pair(0, "TABLE");
        o.pair(2, name);
        o.pair(5, h);
        o.pair(330, "0");
        o.pair(100, "AcDbSymbolTable");
        o.i(70, n as i64);
    };
    let record = |o: &mut Out, kind: &str, sub: &str, owner: &str, name: &str| {
        o.pair(0, kind);
        let h = o.handle();
        o.pair(if kind == "DIMSTYLE" { 105 } else { 5 }, &h);
        o.pair(330, owner);
        o.pair(100, "AcDbSymbolTableRecord");
        o.pair(100, sub);
        o.pair(2, name);
        o.i(70, 0);
    };
    // VPORT: the active view shows the whole sheet
    table(&mut o, "VPORT", &h_vport_t, 1);
    record(&mut o, "VPORT", "AcDbViewportTableRecord", &h_vport_t, "*Active");
    for (c, v) in [(10, 0.0), (20, 0.0), (11, 1.0), (21, 1.0)] {
        o.f(c, v);
    }
    o.f(12, scene.width / 2.0);
    o.f(22, scene.height / 2.0);
    for (c, v) in [
        (13, 0.0),
        (23, 0.0),
        (14, 10.0),
        (24, 10.0),
        (15, 10.0),
        (25, 10.0),
        (16, 0.0),
        (26, 0.0),
        (36, 1.0),
        (17, 0.0),
        (27, 0.0),
        (37, 0.0),
    ] {
        o.f(c, v);
    }
    o.f(40, scene.height * 1.05);
    o.f(41, scene.width / scene.height);
    o.f(42, 50.0);
    o.f(43, 0.0);
    o.f(44, 0.0);
    o.f(50, 0.0);
    o.f(51, 0.0);
    for (c, v) in [(71, 0), (72, 100), (73, 1), (74, 3), (75, 0), (76, 0), (77, 0), (78, 0)] {
        o.i(c, v);
    }
    o.pair(0, "ENDTAB");
    // LTYPE
    table(&mut o, "LTYPE", &h_ltype_t, 3 + line_types.len());
    for name in ["ByBlock", "ByLayer", "Continuous"] {
        record(&mut o, "LTYPE", "AcDbLinetypeTableRecord", &h_ltype_t, name);
        o.pair(3, if name == "Continuous" { "Solid line" } else { "" });
        o.i(72, 65);
        o.i(73, 0);
        o.f(40, 0.0);
    }
    for lt in &line_types {
        let (total, el) = ltype_pattern(*lt, s);
        record(&mut o, "LTYPE", "AcDbLinetypeTableRecord", &h_ltype_t, lt.dxf_name());
        o.pair(3, &format!("{} (GOST 2.303)", lt.name_ru()));
        o.i(72, 65);
        o.i(73, el.len() as i64);
        o.f(40, total);
        for v in el {
            o.f(49, v);
            o.i(74, 0);
        }
    }
    o.pair(0, "ENDTAB");
    // LAYER: "0" and the scene's
    let ltname = |lt: LineType| if lt.dashes(s).is_empty() { "Continuous" } else { lt.dxf_name() };
    table(&mut o, "LAYER", &h_layer_t, 1 + layers.len());
    record(&mut o, "LAYER", "AcDbLayerTableRecord", &h_layer_t, "0");
    o.i(62, 7);
    o.pair(6, "Continuous");
    o.i(370, lineweight(s.thin()) as i64);
    for l in layers {
        record(&mut o, "LAYER", "AcDbLayerTableRecord", &h_layer_t, &l.name);
        o.i(62, l.aci.clamp(1, 255) as i64);
        o.pair(6, ltname(l.line));
        o.i(370, lineweight(l.line.width(s)) as i64);
    }
    o.pair(0, "ENDTAB");
    // STYLE
    table(&mut o, "STYLE", &h_style_t, 2);
    // gost_bu.ttf is slanted by design; osifont is upright and gets
    // GOST 2.304's 15° oblique angle from its style
    for (name, font, oblique) in [("Standard", FALLBACK_FONT, 15.0), (TEXT_STYLE, TEXT_FONT, 0.0)] {
        record(&mut o, "STYLE", "AcDbTextStyleTableRecord", &h_style_t, name);
        o.f(40, 0.0);
        o.f(41, 1.0);
        o.f(50, oblique);
        o.i(71, 0);
        o.f(42, 3.5);
        o.pair(3, font);
        o.pair(4, "");
    }
    o.pair(0, "ENDTAB");
    table(&mut o, "VIEW", &h_view_t, 0);
    o.pair(0, "ENDTAB");
    table(&mut o, "UCS", &h_ucs_t, 0);
    o.pair(0, "ENDTAB");
    table(&mut o, "APPID", &h_appid_t, 1);
    record(&mut o, "APPID", "AcDbRegAppTableRecord", &h_appid_t, "ACAD");
    o.pair(0, "ENDTAB");
    table(&mut o, "DIMSTYLE", &h_dimstyle_t, 1);
    o.pair(100, "AcDbDimStyleTable");
    o.i(71, 0);
    record(&mut o, "DIMSTYLE", "AcDbDimStyleTableRecord", &h_dimstyle_t, "Standard");
    o.pair(0, "ENDTAB");
    table(&mut o, "BLOCK_RECORD", &h_br_t, 2);
    for (h, name) in [(&h_ms, "*Model_Space"), (&h_ps, "*Paper_Space")] {
        o.pair(0, "BLOCK_RECORD");
        o.pair(5, h);
        o.pair(330, &h_br_t);
        o.pair(100, "AcDbSymbolTableRecord");
        o.pair(100, "AcDbBlockTableRecord");
        o.pair(2, name);
        o.i(70, 0);
        o.i(280, 1);
        o.i(281, 0);
    }
    o.pair(0, "ENDTAB");
    o.pair(0, "ENDSEC");

    // BLOCKS
    o.pair(0, "SECTION");
    o.pair(2, "BLOCKS");
    for (owner, name, paper) in [(&h_ms, "*Model_Space", false), (&h_ps, "*Paper_Space", true)] {
        o.pair(0, "BLOCK");
        let h = o.handle();
        o.pair(5, &h);
        o.pair(330, owner);
        o.pair(100, "AcDbEntity");
        if paper {
            o.i(67, 1);
        }
        o.pair(8, "0");
        o.pair(100, "AcDbBlockBegin");
        o.pair(2, name);
        o.i(70, 0);
        o.xy(10, Point::ZERO);
        o.pair(3, name);
        o.pair(1, "");
        o.pair(0, "ENDBLK");
        let h = o.handle();
        o.pair(5, &h);
        o.pair(330, owner);
        o.pair(100, "AcDbEntity");
        if paper {
            o.i(67, 1);
        }
        o.pair(8, "0");
        o.pair(100, "AcDbBlockEnd");
    }
    o.pair(0, "ENDSEC");

    // ENTITIES
    o.pair(0, "SECTION");
    o.pair(2, "ENTITIES");
    let mut e = Entities {
        o: &mut o,
        owner: h_ms.clone(),
        s,
    };
    for item in scene.items() {
        let layer = &layers[item.layer];
        e.shape(layer, &item.shape);
    }
    o.pair(0, "ENDSEC");

    // OBJECTS: the root dictionary and the (empty) group dictionary
    o.pair(0, "SECTION");
    o.pair(2, "OBJECTS");
    o.pair(0, "DICTIONARY");
    o.pair(5, &h_root);
    o.pair(330, "0");
    o.pair(100, "AcDbDictionary");
    o.i(281, 1);
    o.pair(3, "ACAD_GROUP");
    o.pair(350, &h_group);
    o.pair(0, "DICTIONARY");
    o.pair(5, &h_group);
    o.pair(330, &h_root);
    o.pair(100, "AcDbDictionary");
    o.i(281, 1);
    o.pair(0, "ENDSEC");
    o.pair(0, "EOF");

    // HEADER last, when the handle seed is known
    let mut hd = Out { s: String::new(), next: 0 };
    hd.pair(0, "SECTION");
    hd.pair(2, "HEADER");
    hd.pair(9, "$ACADVER");
    hd.pair(1, "AC1021");
    hd.pair(9, "$DWGCODEPAGE");
    hd.pair(3, "ANSI_1251");
    hd.pair(9, "$HANDSEED");
    hd.pair(5, &format!("{:X}", o.next));
    hd.pair(9, "$INSUNITS");
    hd.i(70, 4);
    hd.pair(9, "$MEASUREMENT");
    hd.i(70, 1);
    hd.pair(9, "$LUNITS");
    hd.i(70, 2);
    hd.pair(9, "$EXTMIN");
    hd.xy(10, Point::ZERO);
    hd.pair(9, "$EXTMAX");
    hd.xy(10, Point::new(scene.width, scene.height));
    hd.pair(9, "$LIMMIN");
    hd.f(10, 0.0);
    hd.f(20, 0.0);
    hd.pair(9, "$LIMMAX");
    hd.f(10, scene.width);
    hd.f(20, scene.height);
    hd.pair(9, "$LTSCALE");
    hd.f(40, 1.0);
    hd.pair(9, "$CELTSCALE");
    hd.f(40, 1.0);
    hd.pair(9, "$LWDISPLAY");
    hd.i(290, 1);
    hd.pair(9, "$TEXTSTYLE");
    hd.pair(7, TEXT_STYLE);
    hd.pair(9, "$TEXTSIZE");
    hd.f(40, 3.5);
    hd.pair(9, "$CLAYER");
    hd.pair(8, "0");
    hd.pair(9, "$CELTYPE");
    hd.pair(6, "ByLayer");
    hd.pair(9, "$CELWEIGHT");
    hd.i(370, -1);
    hd.pair(0, "ENDSEC");
    hd.pair(0, "SECTION");
    hd.pair(2, "CLASSES");
    hd.pair(0, "ENDSEC");
    hd.s.push_str(&o.s);
    hd.s
}

struct Entities<'a> {
    o: &'a mut Out,
    owner: String,
    s: Thickness,
}

impl Entities<'_> {
    /// The common part of an entity: handle, owner, layer, and the linetype
    /// and lineweight when they differ from the layer's.
    fn head(&mut self, kind: &str, layer: &crate::Layer, line: Option<LineType>) {
        let o = &mut *self.o;
        o.pair(0, kind);
        let h = o.handle();
        o.pair(5, &h);
        o.pair(330, &self.owner);
        o.pair(100, "AcDbEntity");
        o.pair(8, &layer.name);
        if let Some(lt) = line {
            let own = |t: LineType| (t.dashes(self.s).is_empty(), t.dxf_name(), crate::dxf::lineweight(t.width(self.s)));
            let (mine, theirs) = (own(lt), own(layer.line));
            if mine.0 != theirs.0 || mine.1 != theirs.1 {
                o.pair(6, if mine.0 { "Continuous" } else { lt.dxf_name() });
            }
            if mine.2 != theirs.2 {
                o.i(370, mine.2 as i64);
            }
        }
    }

    fn shape(&mut self, layer: &crate::Layer, shape: &Shape) {
        match shape {
            Shape::Stroke { line, geom } => self.geom(layer, *line, geom),
            Shape::Arrow(a) => {
                let c = a.corners(self.s);
                self.head("SOLID", layer, None);
                let o = &mut *self.o;
                o.pair(100, "AcDbTrace");
                o.xy(10, c[0]);
                o.xy(11, c[1]);
                o.xy(12, c[2]);
                o.xy(13, c[2]);
            }
            Shape::Hatch(h) => self.hatch(layer, h),
            Shape::Text(t) => self.text(layer, t),
            Shape::Dimension(d) => {
                for part in d.parts(self.s) {
                    self.shape(layer, &part);
                }
            }
        }
    }

    fn geom(&mut self, layer: &crate::Layer, line: LineType, g: &Geom) {
        match g {
            Geom::Line(a, b) => {
                self.head("LINE", layer, Some(line));
                self.o.pair(100, "AcDbLine");
                self.o.xy(10, *a);
                self.o.xy(11, *b);
            }
            Geom::Polyline { points, closed } => self.lwpoly(layer, line, points, *closed),
            Geom::Circle { center, radius } => {
                self.head("CIRCLE", layer, Some(line));
                self.o.pair(100, "AcDbCircle");
                self.o.xy(10, *center);
                self.o.f(40, *radius);
            }
            Geom::Arc {
                center,
                radius,
                start_deg,
                end_deg,
            } => {
                self.head("ARC", layer, Some(line));
                self.o.pair(100, "AcDbCircle");
                self.o.xy(10, *center);
                self.o.f(40, *radius);
                self.o.pair(100, "AcDbArc");
                self.o.f(50, start_deg.rem_euclid(360.0));
                self.o.f(51, end_deg.rem_euclid(360.0));
            }
            Geom::Curve(_) => {
                let pts = g.flatten(0.02);
                self.lwpoly(layer, line, &pts, false);
            }
        }
    }

    fn lwpoly(&mut self, layer: &crate::Layer, line: LineType, pts: &[Point], closed: bool) {
        self.head("LWPOLYLINE", layer, Some(line));
        let o = &mut *self.o;
        o.pair(100, "AcDbPolyline");
        o.i(90, pts.len() as i64);
        o.i(70, if closed { 1 } else { 0 } | 128);
        o.f(43, 0.0);
        for p in pts {
            o.f(10, p.x);
            o.f(20, p.y);
        }
    }

    fn hatch(&mut self, layer: &crate::Layer, h: &Hatch) {
        self.head("HATCH", layer, Some(LineType::Thin));
        let o = &mut *self.o;
        o.pair(100, "AcDbHatch");
        o.xy(10, Point::ZERO);
        o.f(210, 0.0);
        o.f(220, 0.0);
        o.f(230, 1.0);
        o.pair(2, "_USER");
        o.i(70, 0);
        o.i(71, 0);
        o.i(91, h.loops.len() as i64);
        for (k, l) in h.loops.iter().enumerate() {
            // 2: a polyline path; 1: the outermost (first) loop
            o.i(92, if k == 0 { 3 } else { 2 });
            o.i(72, 0);
            o.i(73, 1);
            o.i(93, l.len() as i64);
            for p in l {
                o.f(10, p.x);
                o.f(20, p.y);
            }
            o.i(97, 0);
        }
        o.i(75, 0);
        o.i(76, 0);
        o.f(52, h.angle_deg);
        o.f(41, h.spacing);
        o.i(77, 0);
        o.i(78, 1);
        let (sn, cs) = h.angle_deg.to_radians().sin_cos();
        o.f(53, h.angle_deg);
        o.f(43, 0.0);
        o.f(44, 0.0);
        o.f(45, -h.spacing * sn);
        o.f(46, h.spacing * cs);
        o.i(79, 0);
        o.i(98, 0);
    }

    fn text(&mut self, layer: &crate::Layer, t: &Text) {
        let plain = t.rich.spans.iter().all(|s| s.sub.is_none() && s.sup.is_none());
        let h = t.height.mm();
        if plain {
            self.head("TEXT", layer, None);
            let o = &mut *self.o;
            o.pair(100, "AcDbText");
            o.xy(10, t.at);
            o.f(40, h);
            o.pair(1, &t.rich.plain());
            if t.rotation_deg != 0.0 {
                o.f(50, t.rotation_deg.rem_euclid(360.0));
            }
            if t.width_factor != 1.0 {
                o.f(41, t.width_factor);
            }
            o.pair(7, TEXT_STYLE);
            let j = match t.anchor {
                Anchor::Start => 0,
                Anchor::Middle => 1,
                Anchor::End => 2,
            };
            if j != 0 {
                o.i(72, j);
                o.xy(11, t.at);
            }
            o.pair(100, "AcDbText");
        } else {
            // MTEXT has no baseline attachment: its middle is put half a
            // capital height above the baseline
            let (sn, cs) = t.rotation_deg.to_radians().sin_cos();
            let up = kurbo::Vec2::new(-sn, cs);
            let at = t.at + up * (h / 2.0);
            self.head("MTEXT", layer, None);
            let o = &mut *self.o;
            o.pair(100, "AcDbMText");
            o.xy(10, at);
            o.f(40, h);
            o.f(41, 0.0);
            o.i(
                71,
                match t.anchor {
                    Anchor::Start => 4,
                    Anchor::Middle => 5,
                    Anchor::End => 6,
                },
            );
            o.i(72, 1);
            let mut content = mtext(&t.rich);
            if t.width_factor != 1.0 {
                content = format!("\\W{};{content}", crate::fixed::Fixed(t.width_factor, 3));
            }
            let chars: Vec<char> = content.chars().collect();
            let chunks: Vec<String> = chars.chunks(240).map(|c| c.iter().collect()).collect();
            for (k, c) in chunks.iter().enumerate() {
                o.pair(if k + 1 == chunks.len() { 1 } else { 3 }, c);
            }
            if chunks.is_empty() {
                o.pair(1, "");
            }
            o.pair(7, TEXT_STYLE);
            o.f(11, cs);
            o.f(21, sn);
            o.f(31, 0.0);
        }
    }
}
