//! Reading a typeset PDF back for the drawing checks: every text shown on
//! a page with its capital height at print size (the font size through the
//! text and graphics matrices times the font's own cap height), and every
//! embedded drawing with its size on paper. typst writes an SVG figure
//! inline, clipped to the figure's box (a rectangle path, `W n`), and its
//! first element is the drawing's white paper: so a drawing is a clip set
//! while no other clip is, its size the clip's, and `unit_mm` the paper
//! length of one SVG unit (1 when the drawing is printed at its own size).
//!
//! The PDF is walked as PDF 1.7 (ISO 32000-1) defines its content: `q`/`Q`
//! and `cm` keep the current transformation matrix (8.4.4), `m l re h W n`
//! the clipping path (8.5.2, 8.5.4), `BT Tf Tm Td TD T*` the text matrix
//! and size (9.4.2, 9.3.1), `Do` draws a form XObject through its
//! `/Matrix` (8.10.1). The capital height of a run of
//! text is the font's `/CapHeight` (its font descriptor, 9.8.1, in
//! 1/1000 of the text space unit) times the font size, measured at right
//! angles to the baseline after every matrix (so a slanted or turned text
//! is measured as it stands); points are converted at 25.4/72 mm. Stroked
//! straight horizontal lines outside the drawings are kept as rules (`S`
//! after one `m … l` segment), for the layout checks of `checklist.rs`.
//! For the scale checks (`scales_pdf.rs`) every clip (with the clip it
//! lies in), every painted path (its pieces, straight or curved, through
//! the matrices) and every text run decoded through its font's
//! `/ToUnicode` CMap (9.10.3) are kept too.

use std::collections::HashMap;

use pdf_extract::{Dictionary, Document, Object, ObjectId, content::Content};

/// A 2-D affine matrix [a b c d e f] as PDF writes it.
type M = [f64; 6];

const IDENTITY: M = [1.0, 0.0, 0.0, 1.0, 0.0, 0.0];
/// Millimetres per PDF point.
pub const MM_PER_PT: f64 = 25.4 / 72.0;

/// `a` then `b` (PDF's row-vector convention: a point goes through `a` first).
fn mul(a: &M, b: &M) -> M {
    [
        a[0] * b[0] + a[1] * b[2],
        a[0] * b[1] + a[1] * b[3],
        a[2] * b[0] + a[3] * b[2],
        a[2] * b[1] + a[3] * b[3],
        a[4] * b[0] + a[5] * b[2] + b[4],
        a[4] * b[1] + a[5] * b[3] + b[5],
    ]
}

/// The height at right angles to the baseline of a unit-high text through `m`.
fn upright_height(m: &M) -> f64 {
    let det = (m[0] * m[3] - m[1] * m[2]).abs();
    let base = m[0].hypot(m[1]);
    if base > 0.0 { det / base } else { 0.0 }
}

/// A text shown on a page.
#[derive(Debug, Clone)]
pub struct Shown {
    /// 1-based page number.
    pub page: u32,
    /// The capital height at print size, mm.
    pub cap_mm: f64,
    /// Drawn inside an embedded drawing (a clip).
    pub in_figure: bool,
    /// The font's resource name.
    pub font: String,
}

/// An embedded drawing on a page.
#[derive(Debug, Clone)]
pub struct Placed {
    /// 1-based page number.
    pub page: u32,
    /// Its width and height on paper (the clip's box), mm.
    pub size_mm: (f64, f64),
    /// The paper length of one unit of the drawing's first transformation
    /// (its SVG units, mm), horizontally and vertically.
    pub unit_mm: Option<(f64, f64)>,
    /// Its box on the page in PDF points (x0, y0, x1, y1; y up from the
    /// page's foot).
    pub rect_pt: (f64, f64, f64, f64),
    /// Its clip in [`Read::clips`].
    pub clip: usize,
}

/// A stroked straight horizontal line outside the drawings (a table's
/// rule, a fraction bar, a frame or title-block line), in PDF points.
#[derive(Debug, Clone)]
pub struct Rule {
    /// 1-based page number.
    pub page: u32,
    /// Its height above the page's foot.
    pub y_pt: f64,
}

/// A clipping rectangle (an SVG viewport: a note's figure, a sheet, a
/// drawing on a sheet), inside the clip `parent`, in the page its walk
/// was on.
#[derive(Debug, Clone)]
pub struct Clip {
    /// Its box in PDF points (x0, y0, x1, y1; y up from the page's foot).
    pub rect_pt: (f64, f64, f64, f64),
    /// The clip it is drawn inside.
    pub parent: Option<usize>,
}

/// One subpath of a painted path, on the page in PDF points: the points
/// its pieces end at (a straight piece from each to the next; a curved
/// piece is kept as its end points, so the points of a circle drawn as
/// four Bézier quarters are its four extreme points).
#[derive(Debug, Clone, Default)]
pub struct Subpath {
    pub pts: Vec<(f64, f64)>,
    /// Which pieces are straight: `straight[i]` for the piece from
    /// `pts[i]` to `pts[i + 1]`.
    pub straight: Vec<bool>,
    /// Closed by `h` (or a rectangle).
    pub closed: bool,
}

/// A painted path (`S`, `f`, `B` …) with every matrix applied.
#[derive(Debug, Clone)]
pub struct Painted {
    /// The innermost clip it is drawn in.
    pub clip: Option<usize>,
    /// Stroked (its outline is a line), not only filled.
    pub stroked: bool,
    pub subpaths: Vec<Subpath>,
}

/// A text run decoded to Unicode (through its font's `/ToUnicode`).
#[derive(Debug, Clone)]
pub struct Run {
    /// The innermost clip it is drawn in.
    pub clip: Option<usize>,
    pub text: String,
}

/// What a PDF shows: its texts and its top-level forms.
#[derive(Debug, Default)]
pub struct Read {
    /// Every text run with at least one glyph.
    pub texts: Vec<Shown>,
    /// Every embedded drawing.
    pub forms: Vec<Placed>,
    /// Every horizontal stroked line outside the drawings.
    pub rules: Vec<Rule>,
    /// Every clipping rectangle, in the order set.
    pub clips: Vec<Clip>,
    /// Every painted path.
    pub paths: Vec<Painted>,
    /// Every text run, decoded, in the order shown.
    pub runs: Vec<Run>,
}

impl Read {
    /// Whether the clip `inner` is `outer` or lies inside it.
    pub fn within(&self, inner: Option<usize>, outer: usize) -> bool {
        let mut c = inner;
        while let Some(i) = c {
            if i == outer {
                return true;
            }
            c = self.clips[i].parent;
        }
        false
    }
}

fn num(o: &Object) -> f64 {
    match o {
        Object::Integer(i) => *i as f64,
        Object::Real(r) => *r as f64,
        _ => 0.0,
    }
}

fn deref<'a>(doc: &'a Document, o: &'a Object) -> &'a Object {
    doc.dereference(o).map(|(_, o)| o).unwrap_or(o)
}

fn dict<'a>(doc: &'a Document, o: &'a Object) -> Option<&'a Dictionary> {
    match deref(doc, o) {
        Object::Dictionary(d) => Some(d),
        Object::Stream(s) => Some(&s.dict),
        _ => None,
    }
}

/// The cap height per font size unit of the font `name` of `resources`.
fn cap_of(doc: &Document, resources: Option<&Dictionary>, name: &[u8], cache: &mut HashMap<Vec<u8>, f64>) -> f64 {
    let look = || -> Option<f64> {
        let fonts = dict(doc, resources?.get(b"Font").ok()?)?;
        let font = dict(doc, fonts.get(name).ok()?)?;
        let desc_holder = match font.get(b"DescendantFonts") {
            Ok(arr) => match deref(doc, arr) {
                Object::Array(a) => dict(doc, a.first()?)?,
                _ => font,
            },
            Err(_) => font,
        };
        let fd = dict(doc, desc_holder.get(b"FontDescriptor").ok()?)?;
        Some(num(deref(doc, fd.get(b"CapHeight").ok()?)) / 1000.0)
    };
    // a font without a cap height would be unmeasurable: count it as zero
    // (the check then fails and names it)
    let v = look().unwrap_or(0.0);
    cache.insert(name.to_vec(), v);
    v
}

/// The Unicode map of a font's `/ToUnicode` CMap (`bfchar` and `bfrange`
/// entries, ISO 32000-1 9.10.3) and the width of its codes in bytes (2 for
/// a composite font, 1 otherwise).
fn unicode_of(doc: &Document, resources: Option<&Dictionary>, name: &[u8]) -> (HashMap<u32, String>, usize) {
    let mut map = HashMap::new();
    let look = || -> Option<(Vec<u8>, usize)> {
        let fonts = dict(doc, resources?.get(b"Font").ok()?)?;
        let font = dict(doc, fonts.get(name).ok()?)?;
        let wide = font.get(b"Subtype").ok().and_then(|o| o.as_name().ok()) == Some(b"Type0".as_slice());
        let Object::Stream(s) = deref(doc, font.get(b"ToUnicode").ok()?) else {
            return None;
        };
        Some((
            s.decompressed_content().unwrap_or_else(|_| s.content.clone()),
            if wide { 2 } else { 1 },
        ))
    };
    let Some((cmap, width)) = look() else { return (map, 1) };
    let text = String::from_utf8_lossy(&cmap);
    let hex = |t: &str| u32::from_str_radix(t.trim_matches(|c| c == '<' || c == '>'), 16).ok();
    let utf16 = |t: &str| -> String {
        let t = t.trim_matches(|c| c == '<' || c == '>');
        let units: Vec<u16> = (0..t.len() / 4)
            .filter_map(|i| u16::from_str_radix(&t[4 * i..4 * i + 4], 16).ok())
            .collect();
        String::from_utf16_lossy(&units)
    };
    let mut mode = "";
    for line in text.lines() {
        let line = line.trim();
        if line.ends_with("beginbfchar") {
            mode = "char";
        } else if line.ends_with("beginbfrange") {
            mode = "range";
        } else if line.starts_with("end") {
            mode = "";
        } else {
            let parts: Vec<&str> = line.split_whitespace().collect();
            match (mode, parts.as_slice()) {
                ("char", [code, uni]) => {
                    if let Some(c) = hex(code) {
                        map.insert(c, utf16(uni));
                    }
                }
                ("range", [lo, hi, uni]) if uni.starts_with('<') => {
                    if let (Some(lo), Some(hi), Some(u0)) = (hex(lo), hex(hi), hex(uni)) {
                        for (k, c) in (lo..=hi).enumerate() {
                            if let Some(ch) = char::from_u32(u0 + k as u32) {
                                map.insert(c, ch.to_string());
                            }
                        }
                    }
                }
                _ => {}
            }
        }
    }
    (map, width)
}

struct Walker<'a> {
    doc: &'a Document,
    page: u32,
    out: Read,
}

impl Walker<'_> {
    fn walk(&mut self, content: &[u8], resources: Option<&Dictionary>, ctm0: M, clip0: bool, clip_id0: Option<usize>) {
        let Ok(ops) = Content::decode(content) else {
            return;
        };
        let mut caps: HashMap<Vec<u8>, f64> = HashMap::new();
        let mut unicode: HashMap<Vec<u8>, (HashMap<u32, String>, usize)> = HashMap::new();
        // (matrix, inside a drawing's clip, the innermost clip)
        let mut stack: Vec<(M, bool, Option<usize>)> = Vec::new();
        let mut ctm = ctm0;
        let mut clip = clip0;
        let mut clip_id = clip_id0;
        let mut path: Vec<(f64, f64)> = Vec::new();
        let mut subs: Vec<Subpath> = Vec::new();
        let at = |m: &M, x: f64, y: f64| (x * m[0] + y * m[2] + m[4], x * m[1] + y * m[3] + m[5]);
        let mut clipping = false;
        // the drawing just placed waits for its first matrix
        let mut fresh: Option<usize> = None;
        let (mut tm, mut tlm) = (IDENTITY, IDENTITY);
        let (mut font, mut size, mut leading) = (Vec::<u8>::new(), 0.0f64, 0.0f64);
        for op in &ops.operations {
            let a = &op.operands;
            match op.operator.as_str() {
                "q" => stack.push((ctm, clip, clip_id)),
                "Q" => (ctm, clip, clip_id) = stack.pop().unwrap_or((ctm0, clip0, clip_id0)),
                "cm" if a.len() == 6 => {
                    let m = [num(&a[0]), num(&a[1]), num(&a[2]), num(&a[3]), num(&a[4]), num(&a[5])];
                    ctm = mul(&m, &ctm);
                    if let Some(i) = fresh.take() {
                        self.out.forms[i].unit_mm = Some((ctm[0].hypot(ctm[1]) * MM_PER_PT, ctm[2].hypot(ctm[3]) * MM_PER_PT));
                    }
                }
                "m" | "l" if a.len() == 2 => {
                    if op.operator == "m" && !clipping {
                        path.clear();
                    }
                    let (x, y) = (num(&a[0]), num(&a[1]));
                    path.push((x * ctm[0] + y * ctm[2] + ctm[4], x * ctm[1] + y * ctm[3] + ctm[5]));
                    if op.operator == "m" || subs.is_empty() {
                        subs.push(Subpath::default());
                    } else if let Some(s) = subs.last_mut() {
                        s.straight.push(true);
                    }
                    if let Some(s) = subs.last_mut() {
                        s.pts.push(at(&ctm, x, y));
                    }
                }
                "c" | "v" | "y" if a.len() >= 4 => {
                    let n = a.len();
                    let p = at(&ctm, num(&a[n - 2]), num(&a[n - 1]));
                    if subs.is_empty() {
                        subs.push(Subpath::default());
                    }
                    if let Some(s) = subs.last_mut() {
                        s.straight.push(false);
                        s.pts.push(p);
                    }
                }
                "h" => {
                    if let Some(s) = subs.last_mut() {
                        s.closed = true;
                    }
                }
                "re" if a.len() == 4 => {
                    let (x, y, w, h) = (num(&a[0]), num(&a[1]), num(&a[2]), num(&a[3]));
                    for (px, py) in [(x, y), (x + w, y), (x + w, y + h), (x, y + h)] {
                        path.push((px * ctm[0] + py * ctm[2] + ctm[4], px * ctm[1] + py * ctm[3] + ctm[5]));
                    }
                    subs.push(Subpath {
                        pts: [(x, y), (x + w, y), (x + w, y + h), (x, y + h), (x, y)]
                            .iter()
                            .map(|&(px, py)| at(&ctm, px, py))
                            .collect(),
                        straight: vec![true; 4],
                        closed: true,
                    });
                }
                "W" | "W*" => clipping = true,
                "n" | "f" | "F" | "f*" | "S" | "s" | "B" | "B*" | "b" | "b*" => {
                    if op.operator == "S" && !clipping && !clip && path.len() == 2 && (path[0].1 - path[1].1).abs() < 0.01 {
                        self.out.rules.push(Rule {
                            page: self.page,
                            y_pt: path[0].1,
                        });
                    }
                    if op.operator != "n" && !subs.is_empty() {
                        self.out.paths.push(Painted {
                            clip: clip_id,
                            stroked: matches!(op.operator.as_str(), "S" | "s" | "B" | "B*" | "b" | "b*"),
                            subpaths: std::mem::take(&mut subs),
                        });
                    }
                    subs.clear();
                    if clipping && path.len() >= 4 {
                        let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
                        for &(x, y) in &path {
                            (x0, x1, y0, y1) = (x0.min(x), x1.max(x), y0.min(y), y1.max(y));
                        }
                        self.out.clips.push(Clip {
                            rect_pt: (x0, y0, x1, y1),
                            parent: clip_id,
                        });
                        clip_id = Some(self.out.clips.len() - 1);
                    }
                    if clipping && !clip && path.len() >= 4 {
                        let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
                        for &(x, y) in &path {
                            (x0, x1, y0, y1) = (x0.min(x), x1.max(x), y0.min(y), y1.max(y));
                        }
                        self.out.forms.push(Placed {
                            page: self.page,
                            size_mm: ((x1 - x0) * MM_PER_PT, (y1 - y0) * MM_PER_PT),
                            unit_mm: None,
                            rect_pt: (x0, y0, x1, y1),
                            clip: self.out.clips.len() - 1,
                        });
                        fresh = Some(self.out.forms.len() - 1);
                        clip = true;
                    }
                    clipping = false;
                    path.clear();
                }
                "BT" => {
                    tm = IDENTITY;
                    tlm = IDENTITY;
                }
                "Tf" if a.len() == 2 => {
                    font = a[0].as_name().map(<[u8]>::to_vec).unwrap_or_default();
                    size = num(&a[1]);
                }
                "TL" if a.len() == 1 => leading = num(&a[0]),
                "Tm" if a.len() == 6 => {
                    tm = [num(&a[0]), num(&a[1]), num(&a[2]), num(&a[3]), num(&a[4]), num(&a[5])];
                    tlm = tm;
                }
                "Td" | "TD" if a.len() == 2 => {
                    if op.operator == "TD" {
                        leading = -num(&a[1]);
                    }
                    tlm = mul(&[1.0, 0.0, 0.0, 1.0, num(&a[0]), num(&a[1])], &tlm);
                    tm = tlm;
                }
                "T*" => {
                    tlm = mul(&[1.0, 0.0, 0.0, 1.0, 0.0, -leading], &tlm);
                    tm = tlm;
                }
                "Tj" | "TJ" | "'" | "\"" => {
                    let has_glyphs = a.iter().any(|o| match o {
                        Object::String(s, _) => !s.is_empty(),
                        Object::Array(v) => v.iter().any(|x| matches!(x, Object::String(s, _) if !s.is_empty())),
                        _ => false,
                    });
                    if has_glyphs {
                        let (map, width) = unicode
                            .entry(font.clone())
                            .or_insert_with(|| unicode_of(self.doc, resources, &font));
                        let mut text = String::new();
                        let mut push = |bytes: &[u8]| {
                            for code in bytes.chunks(*width) {
                                let c = code.iter().fold(0u32, |v, b| v * 256 + *b as u32);
                                text.push_str(map.get(&c).map(String::as_str).unwrap_or("\u{fffd}"));
                            }
                        };
                        for o in a {
                            match o {
                                Object::String(s, _) => push(s),
                                Object::Array(v) => {
                                    for x in v {
                                        if let Object::String(s, _) = x {
                                            push(s);
                                        }
                                    }
                                }
                                _ => {}
                            }
                        }
                        self.out.runs.push(Run { clip: clip_id, text });
                        let cap = match caps.get(&font) {
                            Some(c) => *c,
                            None => cap_of(self.doc, resources, &font, &mut caps),
                        };
                        let m = mul(&tm, &ctm);
                        self.out.texts.push(Shown {
                            page: self.page,
                            cap_mm: cap * size * upright_height(&m) * MM_PER_PT,
                            in_figure: clip,
                            font: String::from_utf8_lossy(&font).into_owned(),
                        });
                    }
                }
                "Do" if a.len() == 1 => {
                    let Ok(name) = a[0].as_name() else { continue };
                    let Some(xo) = resources.and_then(|r| r.get(b"XObject").ok()).and_then(|x| dict(self.doc, x)) else {
                        continue;
                    };
                    let Ok(obj) = xo.get(name) else { continue };
                    let Object::Stream(s) = deref(self.doc, obj) else { continue };
                    if s.dict.get(b"Subtype").ok().and_then(|o| o.as_name().ok()) != Some(b"Form".as_slice()) {
                        continue;
                    }
                    let matrix = match s.dict.get(b"Matrix").map(|o| deref(self.doc, o)) {
                        Ok(Object::Array(v)) if v.len() == 6 => [num(&v[0]), num(&v[1]), num(&v[2]), num(&v[3]), num(&v[4]), num(&v[5])],
                        _ => IDENTITY,
                    };
                    let m = mul(&matrix, &ctm);
                    let inner_res = s.dict.get(b"Resources").ok().and_then(|r| dict(self.doc, r));
                    let body = s.decompressed_content().unwrap_or_else(|_| s.content.clone());
                    self.walk(&body, inner_res.or(resources), m, clip, clip_id);
                }
                _ => {}
            }
        }
    }
}

/// Read the texts and forms of every page of `pdf`.
pub fn read(pdf: &[u8]) -> Read {
    let doc = Document::load_mem(pdf).expect("the PDF loads");
    read_doc(&doc)
}

/// [`read`] of a loaded document.
pub fn read_doc(doc: &Document) -> Read {
    let mut w = Walker {
        doc,
        page: 0,
        out: Read::default(),
    };
    let pages: Vec<(u32, ObjectId)> = doc.get_pages().into_iter().collect();
    for (n, id) in pages {
        w.page = n;
        let content = doc.get_page_content(id).unwrap_or_default();
        let res = doc
            .get_dictionary(id)
            .ok()
            .and_then(|p| p.get(b"Resources").ok())
            .and_then(|r| dict(doc, r));
        w.walk(&content, res, IDENTITY, false, None);
    }
    w.out
}
