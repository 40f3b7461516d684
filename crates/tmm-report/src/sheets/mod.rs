//! The drawing sheets of the course project (листы графической части):
//! A1 or A2, landscape, with the ESKD frame and the main title block, the
//! run's drawings placed at 1:1 in the course's order:
//!
//! 1. the lever mechanism — synthesis, the 12 positions, the velocity and
//!    acceleration plans, the kinematic diagrams (`synthesis/`, `linkage/`);
//! 2. dynamics and kinetostatics — the diagrams of the dynamics section,
//!    the force plans of each group, Zhukovsky's lever (`dynamics/`, `forces/`),
//!    and a cylinder-driven mechanism's drawings (`cylinder/`);
//! 3. the gear pair and the planetary train (`gear/`, `planetary/`);
//! 4. the cam (`cam/`).
//!
//! The sheets place the drawings as made ([`Picture`], kept by the run's
//! [`Documents`] beside their SVG text), nothing is read back from SVG:
//! `sheets/sheet-N.svg` nests each drawing's elements as an `<svg>`
//! viewport of its own size (so its scales and μ stay true) and draws the
//! frame, graph 26 and the title block form 1 of [`tmm_draw::eskd`];
//! `sheets/sheet-N.dxf` is [`tmm_draw::dxf`]'s rendering of one scene
//! holding the same frame and every drawing's scene moved to its place.
//! The drawings are packed by [`layout`] without overlap and off the title
//! block; what does not fit goes to a continuation sheet (the drawings the
//! course requires) or is left out of the sheet (the optional
//! ones). See `docs/sheets.md`.

pub mod frame;
pub mod layout;
pub mod title_block;

use std::fmt::Write as _;
use std::sync::Arc;

use kurbo::{Point, Vec2};
use tmm_draw::{Scene, TextHeight};

use crate::Error;
use crate::output::Documents;
use crate::picture::Picture;
use crate::project::{Language, Project};
use crate::svg::escape;
use crate::words::word;
use frame::inner_frame;
use layout::{Packer, Rect};

/// The clear distance between drawings and from the frame, mm.
pub const GAP_MM: f64 = 5.0;

/// One sheet of the course: its title key and the drawings it holds, in
/// the course's order; `*` ends a prefix (`forces/group-*`); `!` marks a
/// drawing the sheet must show (it goes to a continuation sheet rather
/// than be left out).
struct Template {
    folders: &'static [&'static str],
    order: &'static [&'static str],
}

const TEMPLATES: [Template; 4] = [
    Template {
        folders: &["synthesis", "linkage"],
        order: &[
            "!linkage/positions",
            "!synthesis/construction",
            "!linkage/velocity-plan",
            "!linkage/acceleration-plan",
            "!linkage/diagram-s",
            "!linkage/diagram-v",
            "!linkage/diagram-a",
            "linkage/diagram-ds",
            "linkage/diagram-dds",
            "synthesis/pressure",
        ],
    },
    Template {
        folders: &["dynamics", "forces", "cylinder"],
        order: &[
            "!forces/group-*",
            "!forces/input-link",
            "!forces/zhukovsky-lever",
            "!forces/balancing-torque",
            "!dynamics/indicator-*",
            "!dynamics/moments",
            "!dynamics/work",
            "!dynamics/inertia",
            "!dynamics/wittenbauer",
            "!dynamics/omega",
            "!dynamics/stroke-moments",
            "!dynamics/stroke-omega",
            "!dynamics/stroke-time",
            "!forces/hodograph-*",
            "forces/reaction-*",
            "dynamics/epsilon",
            "dynamics/stroke-epsilon",
            "dynamics/energy-constant",
            "forces/strength-*",
            "!cylinder/mechanism",
            "!cylinder/speed",
            "!cylinder/time",
            "!cylinder/forces",
            "cylinder/mass",
            "cylinder/accel",
        ],
    },
    Template {
        folders: &["gear", "planetary"],
        order: &[
            "!gear/mesh",
            "!gear/machine-mesh",
            "!gear/contour",
            "!gear/sliding",
            "!planetary/planetary",
        ],
    },
    Template {
        folders: &["cam"],
        order: &[
            "!cam/cam",
            "!cam/cam-motion",
            "!cam/cam-sizing",
            "cam/cam-analogs",
            "cam/cam-pressure",
        ],
    },
];

/// A drawing read from the run's documents.
#[derive(Debug, Clone)]
#[doc(hidden)]
pub struct Drawing {
    pub path: String,
    pub caption: String,
    pub required: bool,
    pub w: f64,
    pub h: f64,
    pub scale: Option<String>,
    /// The drawing as made.
    pub pic: Arc<Picture>,
    /// Its number on the sheets: the prefix of its ids (`d7-`).
    pub id: usize,
}

/// A drawing as placed on a sheet.
#[derive(Debug, Clone, PartialEq)]
pub struct Placed {
    /// The document it comes from (`linkage/positions.svg`).
    pub source: String,
    /// Its caption on the sheet.
    pub caption: String,
    /// The drawing's box on the sheet, mm, y down (the caption above it).
    pub rect: Rect,
}

/// One sheet as laid out.
#[derive(Debug, Clone)]
pub struct Sheet {
    /// The sheet's number in the set, from 1.
    pub number: usize,
    /// The sheet's title (наименование) in the title block.
    pub title: String,
    /// The scale of the main drawing (`1:2`), "—" when none carries one.
    pub scale: String,
    /// The drawings on it.
    pub placed: Vec<Placed>,
    /// Captions of optional drawings left out of it (they are in the note
    /// and the drawing files; the sheet itself does not list them).
    pub left_out: Vec<String>,
    /// The note's box, when there is one.
    pub note: Option<Rect>,
    /// The SVG text.
    pub svg: String,
    /// The whole sheet as one scene (its DXF's source).
    pub scene: Scene,
}

/// The caption of a drawing in `lang`: the `[sheet]` word for its path
/// (`linkage/velocity-plan.svg` → `sheet.fig_linkage_velocity_plan`); a
/// numbered file (`forces/group-2.svg`) takes its family's word and the
/// number; an unknown file the word for a figure and its name.
///
/// ```
/// use tmm_report::{project::Language, sheets::caption};
/// assert_eq!(caption("linkage/velocity-plan.svg", Language::Ru), "План скоростей");
/// assert_eq!(caption("forces/group-2.svg", Language::En), "Force plan of group 2");
/// ```
pub fn caption(path: &str, lang: Language) -> String {
    let stem = path.trim_end_matches(".svg");
    let key = |s: &str| format!("sheet.fig_{}", s.replace(['/', '-'], "_"));
    let k = key(stem);
    if word(lang, &k) != k {
        return word(lang, &k).to_string();
    }
    if let Some((base, n)) = stem.rsplit_once('-')
        && !n.is_empty()
        && n.chars().all(|c| c.is_ascii_digit())
    {
        let k = key(base);
        if word(lang, &k) != k {
            return format!("{} {n}", word(lang, &k));
        }
    }
    // the reactions over the cycle, named by the reaction they draw
    if let Some(r) = stem.strip_prefix("forces/hodograph-") {
        return match r.strip_suffix("-polar") {
            Some(r) => format!(
                "{} {r} ({})",
                word(lang, "forces.hodograph_title"),
                word(lang, "forces.hodograph_polar")
            ),
            None => format!("{} {r}", word(lang, "forces.hodograph_title")),
        };
    }
    if let Some(r) = stem.strip_prefix("forces/reaction-") {
        let title = if r.starts_with('M') {
            "forces.couple_title"
        } else {
            "forces.reaction_title"
        };
        return format!("{}: {r}", word(lang, title));
    }
    let name = stem.rsplit('/').next().unwrap_or(stem);
    format!("{} «{name}»", word(lang, "sheet.figure"))
}

fn matches(pattern: &str, stem: &str) -> bool {
    match pattern.strip_suffix('*') {
        Some(prefix) => stem.starts_with(prefix),
        None => stem == pattern,
    }
}

/// A drawing of the run at `path` as the sheets take it: its size, scale
/// and caption; `None` when the document is no drawing made by the canvas.
#[doc(hidden)]
pub fn drawing_of(docs: &Documents, path: &str, lang: Language, required: bool, id: usize) -> Option<Drawing> {
    let pic = docs.picture_shared(path)?;
    if !(pic.width > 0.0 && pic.height > 0.0) {
        return None;
    }
    Some(Drawing {
        path: path.to_string(),
        caption: caption(path, lang),
        required,
        w: pic.width,
        h: pic.height,
        scale: pic.attr("data-scale").map(str::to_string).filter(|s| !s.trim().is_empty()),
        pic,
        id,
    })
}

/// The drawings of one template found in the run, in the course's order.
fn collect(docs: &Documents, t: &Template, lang: Language, next_id: &mut usize) -> (Vec<Drawing>, Vec<String>) {
    let svgs: Vec<&str> = docs
        .iter()
        .filter(|d| d.extension() == "svg")
        .filter(|d| t.folders.iter().any(|f| d.path.starts_with(&format!("{f}/"))))
        .map(|d| d.path.as_str())
        .collect();
    let mut picked: Vec<(usize, bool, &str)> = Vec::new();
    for path in &svgs {
        let stem = path.trim_end_matches(".svg");
        let pos = t.order.iter().position(|p| matches(p.trim_start_matches('!'), stem));
        let (rank, required) = match pos {
            Some(p) => (p, t.order[p].starts_with('!')),
            None => (t.order.len(), false),
        };
        picked.push((rank, required, path));
    }
    picked.sort_by_key(|p| p.0); // stable: the run's order within a rank
    let mut out = Vec::new();
    let mut unreadable = Vec::new();
    for (_, required, path) in picked {
        *next_id += 1;
        match drawing_of(docs, path, lang, required, *next_id) {
            Some(d) => out.push(d),
            None => unreadable.push(caption(path, lang)),
        }
    }
    (out, unreadable)
}

/// The size of a drawing's box: (width, height). A drawing carries its
/// own title (with its scale and μ) inside its paper, so the sheet adds no
/// caption of its own: one title per drawing.
fn item_size(d: &Drawing) -> (f64, f64) {
    (d.w, d.h)
}

/// The field the drawings may take: the inner frame less [`GAP_MM`].
fn field(format: crate::project::SheetFormat) -> Rect {
    let f = inner_frame(format);
    Rect {
        x: f.x + GAP_MM,
        y: f.y + GAP_MM,
        w: f.w - 2.0 * GAP_MM,
        h: f.h - 2.0 * GAP_MM,
    }
}

/// Pack `items` (indices into `ds`) in the given order; the boxes carry a
/// trailing gap, the title block (and the note strip, when `note_h > 0`)
/// is occupied first. Returns the placed (index, box without the gap) and
/// the note's box.
fn pack(ds: &[Drawing], order: &[usize], format: crate::project::SheetFormat, note: Option<(f64, f64)>, columns: bool) -> Packing {
    let f = field(format);
    let tb = title_block::place(inner_frame(format));
    let mut p = Packer::new(Rect {
        w: f.w + GAP_MM,
        h: f.h + GAP_MM,
        ..f
    });
    // graph 26 in the top-left corner, with the gap below and right of it
    let g26 = frame::graph_26_place(inner_frame(format));
    p.occupy(Rect {
        x: f.x,
        y: f.y,
        w: g26.right() + GAP_MM - f.x,
        h: g26.bottom() + GAP_MM - f.y,
    });
    p.occupy(Rect {
        x: tb.x - GAP_MM + GAP_MM,
        y: tb.y - GAP_MM + GAP_MM,
        w: f.right() + GAP_MM - tb.x,
        h: f.bottom() + GAP_MM - tb.y,
    });
    let mut note_rect = None;
    if let Some((nw, nh)) = note {
        // the note sits right above the title block
        let r = Rect {
            x: tb.right() - nw,
            y: tb.y - GAP_MM - nh,
            w: nw,
            h: nh,
        };
        p.occupy(Rect {
            w: nw + GAP_MM,
            h: nh + GAP_MM,
            ..r
        });
        note_rect = Some(r);
    }
    let mut placed = Vec::new();
    for &i in order {
        let (w, h) = item_size(&ds[i]);
        if let Some(r) = p.place_by(w + GAP_MM, h + GAP_MM, columns) {
            placed.push((i, Rect { x: r.x, y: r.y, w, h }));
        }
    }
    (placed, note_rect)
}

/// The best of several packings: the course's order, the tallest first,
/// the widest first and the largest first, each filling rows and filling
/// columns; the best places the most required drawings, then the most
/// drawings, then the most area.
fn best_pack(ds: &[Drawing], left: &[usize], format: crate::project::SheetFormat, note: Option<(f64, f64)>) -> Packing {
    let sorted = |key: &dyn Fn(f64, f64) -> f64| {
        let mut v = left.to_vec();
        v.sort_by(|&a, &b| {
            let (wa, ha) = item_size(&ds[a]);
            let (wb, hb) = item_size(&ds[b]);
            (ds[b].required, key(wb, hb))
                .partial_cmp(&(ds[a].required, key(wa, ha)))
                .unwrap_or(std::cmp::Ordering::Equal)
        });
        v
    };
    let orders = [left.to_vec(), sorted(&|_, h| h), sorted(&|w, _| w), sorted(&|w, h| w * h)];
    let score = |p: &Packing| {
        let area: f64 = p.0.iter().map(|(_, r)| r.w * r.h).sum();
        (p.0.iter().filter(|(i, _)| ds[*i].required).count(), p.0.len(), area)
    };
    let mut best: Option<Packing> = None;
    for columns in [false, true] {
        for o in &orders {
            let p = pack(ds, o, format, note, columns);
            if best.as_ref().is_none_or(|b| score(&p) > score(b)) {
                best = Some(p);
            }
        }
    }
    best.unwrap_or_default()
}

/// A packing: the placed (drawing index, box) and the note's box.
type Packing = (Vec<(usize, Rect)>, Option<Rect>);

/// A page before numbering: template, drawings, placed, left out, note, continued.
type Page = (usize, Vec<Drawing>, Vec<Placed>, Vec<String>, Option<Rect>, bool);

/// Lay out the sheets of a run: the drawings of each course sheet found in
/// `docs`, in `project`'s language and format. Sheets without drawings are
/// not made. Numbers and the count are set over the whole set.
pub fn layout_sheets(docs: &Documents, project: &Project) -> Vec<Sheet> {
    let lang = project.lang;
    let format = project.sheet;
    if format == crate::project::SheetFormat::A4 {
        // the note's page: its figures are set in the note, not on a sheet
        return Vec::new();
    }
    let mut next_id = 0;
    // (template index, drawings placed, left out, note box, continued)
    let mut pages: Vec<Page> = Vec::new();
    for (ti, t) in TEMPLATES.iter().enumerate() {
        let (ds, unreadable) = collect(docs, t, lang, &mut next_id);
        if ds.is_empty() && unreadable.is_empty() {
            continue;
        }
        let empty = field(format);
        let tb = title_block::place(inner_frame(format));
        // a drawing larger than an empty field can never be placed
        let fits_empty = |d: &Drawing| {
            let (w, h) = item_size(d);
            (w <= empty.w && h <= empty.h - (tb.h + GAP_MM)) || (w <= empty.w - (tb.w + GAP_MM) && h <= empty.h)
        };
        let mut left_out: Vec<String> = unreadable;
        let mut left: Vec<usize> = Vec::new();
        for (i, d) in ds.iter().enumerate() {
            if fits_empty(d) {
                left.push(i);
            } else {
                left_out.push(d.caption.clone());
            }
        }
        let mut continued = false;
        loop {
            let (placed, _) = best_pack(&ds, &left, format, None);
            let rest: Vec<usize> = left.iter().copied().filter(|i| !placed.iter().any(|(j, _)| j == i)).collect();
            let more_required = rest.iter().any(|&i| ds[i].required);
            if more_required && !placed.is_empty() {
                // a sheet to be continued shows the required drawings first;
                // the optional ones wait for the last sheet of the topic
                let required: Vec<usize> = left.iter().copied().filter(|&i| ds[i].required).collect();
                let (only, _) = best_pack(&ds, &required, format, None);
                let placed = if only.is_empty() { placed } else { only };
                pages.push((ti, ds.clone(), to_placed(&ds, &placed), Vec::new(), None, continued));
                left = left.iter().copied().filter(|i| !placed.iter().any(|(j, _)| j == i)).collect();
                continued = true;
                continue;
            }
            // the optional rest is left out: it is in the note and the
            // drawing files, and a sheet shows no list of what is not on it
            let mut out = left_out.clone();
            out.extend(rest.iter().map(|&i| ds[i].caption.clone()));
            let note = None;
            pages.push((ti, ds.clone(), to_placed(&ds, &placed), out, note, continued));
            break;
        }
    }
    let count = pages.len();
    let mut sheets = Vec::new();
    for (n, (ti, ds, placed, left_out, note, continued)) in pages.into_iter().enumerate() {
        let has = |f: &str| ds.iter().any(|d| d.path.starts_with(f));
        let key = match ti {
            0 => "sheet.title_lever",
            1 if has("dynamics/") && has("forces/") => "sheet.title_dynamics_forces",
            1 if has("dynamics/") => "sheet.title_dynamics",
            1 => "sheet.title_forces",
            2 if has("gear/") && has("planetary/") => "sheet.title_gears_planetary",
            2 if has("gear/") => "sheet.title_gears",
            2 => "sheet.title_planetary",
            _ => "sheet.title_cam",
        };
        let mut title = word(lang, key).to_string();
        if continued {
            let _ = write!(title, " ({})", word(lang, "sheet.continued"));
        }
        // the scale of the main drawing: the first placed, in the course's order, that carries one
        let scale = ds
            .iter()
            .filter(|d| placed.iter().any(|p| p.source == d.path))
            .find_map(|d| d.scale.clone())
            // a sheet of diagrams drawn to no one scale: a dash in the
            // scale field, as ESKD fills a field that does not apply
            .unwrap_or_else(|| "—".to_string());
        let mut sheet = Sheet {
            number: n + 1,
            title,
            scale,
            placed,
            left_out,
            note,
            svg: String::new(),
            scene: Scene::new(1.0, 1.0, tmm_draw::Scale::NATURAL, tmm_draw::Thickness::A1)
                .unwrap_or_else(|_| unreachable!("a 1 × 1 mm scene")),
        };
        (sheet.svg, sheet.scene) = sheet_parts(&sheet, &ds, project, count);
        sheets.push(sheet);
    }
    sheets
}

fn to_placed(ds: &[Drawing], placed: &[(usize, Rect)]) -> Vec<Placed> {
    let mut v: Vec<Placed> = placed
        .iter()
        .map(|&(i, r)| {
            let d = &ds[i];
            Placed {
                source: d.path.clone(),
                caption: d.caption.clone(),
                rect: Rect {
                    x: r.x,
                    y: r.y,
                    w: d.w,
                    h: d.h,
                },
            }
        })
        .collect();
    // the course's order in the file, whatever order packed them
    v.sort_by_key(|p| ds.iter().position(|d| d.path == p.source));
    v
}

fn num(x: f64) -> String {
    if !x.is_finite() {
        return crate::output::NONFINITE.to_string();
    }
    let s = format!("{x:.3}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" { "0".to_string() } else { s.to_string() }
}

/// Graph 9 of the title block (GOST 2.104: the name *or the distinctive
/// index* of the organisation): the university, the department and the
/// group; when that does not fit the 50 × 15 mm cell at 2.5 mm, the
/// university's index, the abbreviation it ends with in brackets
/// ("… университет (МАДИ)" → "МАДИ"), so the field wraps inside its cell
/// rather than being cut.
fn organisation(project: &Project) -> String {
    let join = |university: &str| {
        [university, &project.department, &project.group]
            .into_iter()
            .map(str::trim)
            .filter(|s| !s.is_empty())
            .collect::<Vec<_>>()
            .join(", ")
    };
    let full = join(&project.university);
    // the rule `tmm_draw::eskd::sheet` fits the cell by (1 mm clear of its lines)
    let (w, h) = ORGANISATION_CELL_MM;
    let (_, _, cut) = tmm_draw::eskd::fit(&full, TextHeight::H3_5, w, h);
    let u = project.university.trim();
    match (cut, u.strip_suffix(')').and_then(|v| v.rsplit_once('('))) {
        (Some(_), Some((_, index))) if !index.trim().is_empty() => join(index.trim()),
        _ => full,
    }
}

/// The organisation's cell (graph 9) of title block form 1, mm.
const ORGANISATION_CELL_MM: (f64, f64) = (50.0, 15.0);

/// The title block's words and fields of a sheet (`count` sheets in the set).
pub fn title_block_of(sheet: &Sheet, project: &Project, count: usize) -> tmm_draw::eskd::TitleBlock {
    let lang = project.lang;
    let w = |k: &str| word(lang, k).to_string();
    let five = |k: [&str; 5]| k.map(w);
    let organisation = organisation(project);
    tmm_draw::eskd::TitleBlock {
        captions: tmm_draw::eskd::Captions {
            changes: five([
                "sheet.tb_change",
                "sheet.tb_sheet",
                "sheet.tb_document",
                "sheet.tb_signature",
                "sheet.tb_date",
            ]),
            roles: five([
                "sheet.tb_drawn",
                "sheet.tb_checked",
                "sheet.tb_tech_control",
                "sheet.tb_norm_control",
                "sheet.tb_approved",
            ]),
            right: five([
                "sheet.tb_letter",
                "sheet.tb_mass",
                "sheet.tb_scale",
                "sheet.tb_sheet",
                "sheet.tb_sheets",
            ]),
        },
        designation: project.designation.clone(),
        title: sheet.title.clone(),
        scale: sheet.scale.clone(),
        sheet: sheet.number,
        sheets: count,
        student: project.student.clone(),
        teacher: project.teacher.clone(),
        organisation,
        letter: w("sheet.tb_letter_value"),
    }
}

/// Where an element of the ESKD sheet belongs: 0 the frame, 1 graph 26,
/// 2 the title block (by the corner it lies in).
fn frame_part(it: &tmm_draw::Item, w: f64, h: f64) -> u8 {
    let pts: Vec<Point> = match &it.shape {
        tmm_draw::Shape::Stroke { geom, .. } => geom.flatten(0.5),
        tmm_draw::Shape::Text(t) => vec![t.at],
        _ => Vec::new(),
    };
    let all = |f: &dyn Fn(&Point) -> bool| !pts.is_empty() && pts.iter().all(f);
    let (l, e) = (frame::LEFT_MM, frame::EDGE_MM);
    if all(&|p| p.x >= w - e - title_block::WIDTH_MM - 1e-6 && p.y <= e + title_block::HEIGHT_MM + 1e-6) {
        2
    } else if all(&|p| p.x <= l + 70.0 + 1e-6 && p.y >= h - e - 14.0 - 1e-6) {
        1
    } else {
        0
    }
}

/// A sheet's SVG and its whole scene (the frame, the title block and every
/// drawing's scene at its place), from which the DXF is written.
fn sheet_parts(sheet: &Sheet, ds: &[Drawing], project: &Project, count: usize) -> (String, Scene) {
    let (w, h) = project.sheet.size_mm();
    let format = match project.sheet {
        crate::project::SheetFormat::A2 => tmm_draw::eskd::Format::A2,
        // the note's page has no sheets (`layout_sheets` makes none)
        crate::project::SheetFormat::A1 | crate::project::SheetFormat::A4 => tmm_draw::eskd::Format::A1,
    };
    let tb = title_block_of(sheet, project, count);
    let mut scene = match tmm_draw::eskd::sheet(format, &tb) {
        Ok((sc, _)) => sc,
        // the ESKD sheet is made of finite, checked numbers: it cannot fail
        Err(_) => Scene::new(w, h, tmm_draw::Scale::NATURAL, tmm_draw::Thickness::A1)
            .unwrap_or_else(|_| unreachable!("a sheet's size is positive")),
    };
    let frame_scene = scene.clone();
    let mut s = String::new();
    let _ = writeln!(
        s,
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}mm\" height=\"{h}mm\" viewBox=\"0 0 {w} {h}\" xml:lang=\"{}\" data-format=\"{}\" data-sheet=\"{}\">",
        project.lang.code(),
        project.sheet.name(),
        sheet.number
    );
    let _ = writeln!(
        s,
        "<rect x=\"0\" y=\"0\" width=\"{w}\" height=\"{h}\" fill=\"#ffffff\" stroke=\"none\"/>"
    );
    s.push_str("<g id=\"drawings\">\n");
    for p in &sheet.placed {
        let Some(d) = ds.iter().find(|d| d.path == p.source) else {
            continue;
        };
        let scale = d.scale.as_ref().map_or(String::new(), |k| format!(" data-scale=\"{}\"", escape(k)));
        let _ = writeln!(
            s,
            "\n<svg class=\"drawing\" data-source=\"{}\" x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" viewBox=\"0 0 {} {}\"{scale} overflow=\"hidden\">{}</svg>",
            escape(&d.path),
            num(p.rect.x),
            num(p.rect.y),
            num(p.rect.w),
            num(p.rect.h),
            num(d.w),
            num(d.h),
            d.pic.body(&format!("d{}-", d.id))
        );
        // the same on the scene: the drawing moved to its box (y up)
        scene.insert(&d.pic.scene(), Vec2::new(p.rect.x, h - p.rect.bottom()));
    }
    s.push_str("</g>\n");
    for (id, part) in [("frame", 0u8), ("graph-26", 1), ("title-block", 2)] {
        let _ = writeln!(s, "<g id=\"{id}\">");
        s.push_str(&tmm_draw::svg::items_markup(&frame_scene, |it| frame_part(it, w, h) == part));
        s.push_str("</g>\n");
    }
    s.push_str("</svg>\n");
    (s, scene)
}

/// The sheets of a run as documents: `sheets/sheet-N.svg` and
/// `sheets/sheet-N.dxf` for every sheet that has drawings.
///
/// ```
/// use tmm_report::{TaskSource, run::{run_task, DEFAULT_TASK}};
/// let run = run_task(&TaskSource::new("t.toml", DEFAULT_TASK)).unwrap();
/// let svg = run.docs.get("sheets/sheet-1.svg").unwrap().as_text().unwrap();
/// assert!(svg.contains("width=\"841mm\"") && svg.contains("data-source=\"linkage/positions.svg\""));
/// assert!(run.docs.get("sheets/sheet-1.dxf").is_some());
/// ```
pub fn sheet_documents(docs: &Documents, project: &Project) -> Result<Documents, Error> {
    let mut out = Documents::like(docs);
    for sheet in layout_sheets(docs, project) {
        let dxf = tmm_draw::dxf::render(&sheet.scene);
        out.add_text(format!("sheets/sheet-{}.svg", sheet.number), sheet.svg)?;
        out.add_text(format!("sheets/sheet-{}.dxf", sheet.number), dxf)?;
    }
    Ok(out)
}
