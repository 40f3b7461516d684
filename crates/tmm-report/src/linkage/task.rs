//! The `[linkage]` section of a task file, read into a
//! [`tmm_linkage::MechanismDef`] with every span kept, so that errors from the
//! core can point at the field that caused them.
//!
//! ```toml
//! [linkage]
//! fixed = { A = ["0 mm", "0 mm"], D = ["510 mm", "0 mm"] }
//! input = { link = "1", speed = "900 rpm", direction = "ccw" }
//! assembly = ["C below AD"]
//! # or a slider on a fixed guide as the input, over a travel:
//! # input = { slider = "1", speed = "0.5 m/s" }
//! # travel = ["0 mm", "120 mm"]
//! [[linkage.links]]
//! name = "1"
//! joints = ["A", "B"]
//! length = "120 mm"
//! ```

use std::collections::{BTreeMap, HashMap};
use std::ops::Range;

use serde::Deserialize;
use tmm_geom::Vec2;
use tmm_geom::units::Dim;
use tmm_linkage::cycle::Working;
use tmm_linkage::{AssemblyHint, FRAME, HintKind, InputDef, LinkDef, MechanismDef, SliderDef, SliderInputDef};

use crate::task::{Qty, RawQty, qty};
use crate::{Error, TaskSource};

type S<T> = toml::Spanned<T>;

#[derive(Deserialize)]
struct File {
    linkage: Option<S<LinkageSec>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct LinkageSec {
    #[allow(dead_code)]
    name: Option<String>,
    fixed: S<BTreeMap<String, S<Vec<Qty>>>>,
    links: S<Vec<S<LinkSec>>>,
    #[serde(default)]
    sliders: Vec<S<SliderSec>>,
    input: S<InputSec>,
    output: Option<S<String>>,
    #[serde(default)]
    assembly: Vec<S<HintSec>>,
    assembly_angle: Option<Qty>,
    working: Option<S<String>>,
    positions: Option<S<i64>>,
    at: Option<Qty>,
    range: Option<S<String>>,
    travel: Option<S<Vec<Qty>>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct LinkSec {
    name: S<String>,
    joints: S<Vec<S<String>>>,
    length: Option<Qty>,
    #[serde(default)]
    points: BTreeMap<String, S<PointSec>>,
    mass_center: Option<S<PointSec>>,
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct PointSec {
    along: Option<Qty>,
    offset: Option<Qty>,
    at: Option<S<Vec<Qty>>>,
    from: Option<S<String>>,
    toward: Option<S<String>>,
    angle: Option<Qty>,
    length: Option<Qty>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SliderSec {
    link: S<String>,
    point: S<String>,
    guide: S<GuideSec>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct GuideSec {
    #[serde(default = "frame")]
    link: S<String>,
    through: S<Through>,
    angle: Option<Qty>,
    offset: Option<Qty>,
}

fn frame() -> S<String> {
    toml::Spanned::new(0..0, FRAME.to_string())
}

#[derive(Deserialize)]
#[serde(untagged)]
enum Through {
    Point(String),
    Coords(Vec<RawQty>),
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct InputSec {
    link: Option<S<String>>,
    slider: Option<S<String>>,
    pivot: Option<S<String>>,
    pin: Option<S<String>>,
    speed: Qty,
    direction: Option<S<String>>,
    epsilon: Option<Qty>,
    acceleration: Option<Qty>,
}

#[derive(Deserialize)]
#[serde(untagged)]
enum HintSec {
    Text(String),
    Near { point: String, near: Vec<RawQty> },
}

/// The most positions a table may have (0.1° apart): every position is
/// solved, kept and written, so the bound keeps memory and files small.
pub const MAX_POSITIONS: usize = 3600;

/// Over which crank angles the mechanism is analysed (`range` in `[linkage]`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum RangeMode {
    /// A full turn of the crank (полный оборот); a mechanism whose crank
    /// cannot turn fully is refused.
    #[default]
    Full,
    /// Only the ranges of the crank angle where the mechanism assembles
    /// (области сборки): a double rocker driven over its swing.
    Partial,
}

/// The travel of an input slider (ход ведущего ползуна): s from `from` to
/// `to`, m, along its guide from the guide's `through` point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Travel {
    /// The first s, m.
    pub from: f64,
    /// The last s, m (> `from`).
    pub to: f64,
}

/// The `[linkage]` section, read and checked.
#[derive(Debug, Clone)]
pub struct LinkageTask {
    /// The mechanism description for the core.
    pub def: MechanismDef,
    /// Which stroke is the working one.
    pub working: Working,
    /// Number of equal positions (12 by default).
    pub positions: usize,
    /// The crank angle for the plans (absolute, rad), or the slider's s
    /// (m) for a slider input, if given.
    pub at: Option<f64>,
    /// The travel of a slider input (`travel` in `[linkage]`); `None` for a crank.
    pub travel: Option<Travel>,
    /// A full turn (default) or the assembly ranges only.
    pub range: RangeMode,
    /// Where `range` was written, if it was.
    pub range_span: Option<Range<usize>>,
    /// Field path → span, to locate core errors.
    pub spans: HashMap<String, Range<usize>>,
    /// Span of the whole section.
    pub section: Range<usize>,
}

/// Values read inside an untagged form carry no span of their own: give them the form's.
fn respan(span: Range<usize>, v: &[RawQty]) -> S<Vec<Qty>> {
    toml::Spanned::new(
        span.clone(),
        v.iter().map(|q| toml::Spanned::new(span.clone(), q.clone())).collect(),
    )
}

fn pair(task: &TaskSource, field: &str, v: &S<Vec<Qty>>, dim: Dim) -> Result<Vec2, Error> {
    let r = v.get_ref();
    if r.len() != 2 {
        return Err(
            Error::at(task, v.span(), field, format!("expected two coordinates [x, y], found {}", r.len()))
                .with_help("e.g. [\"510 mm\", \"0 mm\"]"),
        );
    }
    Ok(Vec2::new(
        qty(task, &format!("{field}[0]"), &r[0], dim)?,
        qty(task, &format!("{field}[1]"), &r[1], dim)?,
    ))
}

/// Read the `[linkage]` section; `None` when the file has none.
pub fn read(task: &TaskSource) -> Result<Option<LinkageTask>, Error> {
    let f: File = task.parse("linkage")?;
    let Some(sec) = f.linkage else { return Ok(None) };
    let section = sec.span();
    let sec = sec.into_inner();
    let mut spans = HashMap::new();
    let mut def = MechanismDef::default();
    // fixed points
    for (name, v) in sec.fixed.get_ref() {
        let p = pair(task, &format!("linkage.fixed.{name}"), v, Dim::Length)?;
        spans.insert(format!("fixed.{name}"), v.span());
        def.fixed.push((name.clone(), p));
    }
    if def.fixed.is_empty() {
        return Err(Error::at(
            task,
            sec.fixed.span(),
            "linkage.fixed",
            "at least one fixed point (the crank pivot) is needed",
        )
        .with_help("fixed = { A = [0, 0] }"));
    }
    // links
    for (i, ls) in sec.links.get_ref().iter().enumerate() {
        let l = ls.get_ref();
        let name = l.name.get_ref().clone();
        let field = format!("linkage.links[{i}] ({name})");
        spans.insert(format!("links[{i}].name"), l.name.span());
        spans.insert(format!("links.{name}"), l.name.span());
        let joints = l.joints.get_ref();
        if joints.is_empty() {
            return Err(
                Error::at(task, l.joints.span(), &format!("{field}.joints"), "a link needs at least one joint")
                    .with_help("joints = [\"B\", \"C\"]"),
            );
        }
        let mut pts: Vec<(String, Vec2)> = vec![(joints[0].get_ref().clone(), Vec2::ZERO)];
        let mut length = 0.0;
        if joints.len() >= 2 {
            let lq = l.length.as_ref().ok_or_else(|| {
                Error::at(
                    task,
                    ls.span(),
                    &format!("{field}.length"),
                    format!("missing length of link `{name}` (|{}{}|)", joints[0].get_ref(), joints[1].get_ref()),
                )
                .with_help("length = \"120 mm\"")
            })?;
            length = qty(task, &format!("{field}.length"), lq, Dim::Length)?;
            spans.insert(format!("links.{name}.length"), lq.span());
            if length <= 0.0 {
                return Err(Error::at(task, lq.span(), &format!("{field}.length"), "a link length must be > 0"));
            }
            pts.push((joints[1].get_ref().clone(), Vec2::new(length, 0.0)));
        }
        let first_two: Vec<String> = joints.iter().take(2).map(|j| j.get_ref().clone()).collect();
        let mut defined: BTreeMap<String, Vec2> = pts.iter().cloned().collect();
        // further points, in an order that resolves `from`/`toward` references
        let mut pending: Vec<(&String, &S<PointSec>)> = l.points.iter().collect();
        while !pending.is_empty() {
            let before = pending.len();
            let mut rest = Vec::new();
            for (pn, ps) in pending {
                match local_point(task, &format!("{field}.points.{pn}"), ps, &first_two, length, &defined)? {
                    Some(p) => {
                        defined.insert(pn.clone(), p);
                        pts.push((pn.clone(), p));
                    }
                    None => rest.push((pn, ps)),
                }
            }
            if rest.len() == before {
                let (pn, ps) = rest[0];
                return Err(Error::at(
                    task,
                    ps.span(),
                    &format!("{field}.points.{pn}"),
                    "refers to a point that is not on this link",
                )
                .with_help(format!(
                    "points of `{name}`: {}",
                    defined.keys().cloned().collect::<Vec<_>>().join(", ")
                )));
            }
            pending = rest;
        }
        for (k, j) in joints.iter().enumerate().skip(2) {
            if !defined.contains_key(j.get_ref()) {
                return Err(Error::at(
                    task,
                    j.span(),
                    &format!("{field}.joints[{k}]"),
                    format!("joint `{}` needs its place on the link", j.get_ref()),
                )
                .with_help(format!(
                    "add e.g. points.{} = {{ from = \"{}\", toward = \"{}\", angle = \"180 deg\", length = \"0.6 m\" }}",
                    j.get_ref(),
                    first_two[0],
                    first_two.get(1).cloned().unwrap_or_default()
                )));
            }
        }
        let mc = match &l.mass_center {
            Some(ps) => local_point(task, &format!("{field}.mass_center"), ps, &first_two, length, &defined)?.ok_or_else(|| {
                Error::at(
                    task,
                    ps.span(),
                    &format!("{field}.mass_center"),
                    "refers to a point that is not on this link",
                )
            })?,
            None => Vec2::new(0.5 * length, 0.0),
        };
        let sname = format!("S{name}");
        if !defined.contains_key(&sname) {
            pts.push((sname, mc));
        }
        def.links.push(LinkDef {
            name,
            points: pts,
            mass_center: mc,
        });
    }
    // sliders
    for (i, ss) in sec.sliders.iter().enumerate() {
        let s = ss.get_ref();
        let field = format!("linkage.sliders[{i}]");
        spans.insert(format!("sliders[{i}].link"), s.link.span());
        spans.insert(format!("sliders[{i}].point"), s.point.span());
        spans.insert(format!("sliders[{i}].guide.link"), s.guide.get_ref().link.span());
        spans.insert(format!("sliders[{i}].guide"), s.guide.span());
        let sl = s.link.get_ref().clone();
        if sl.trim().is_empty() {
            return Err(
                Error::at(task, s.link.span(), &format!("{field}.link"), "the slider's link needs a name")
                    .with_help("the name of the slider block, e.g. link = \"3\" (a new block is made when no link has that name)"),
            );
        }
        if !def.links.iter().any(|l| l.name == sl) {
            def.links.push(LinkDef::block(&sl, s.point.get_ref()));
        }
        let g = s.guide.get_ref();
        let gl = g.link.get_ref().clone();
        let angle = match &g.angle {
            Some(a) => qty(task, &format!("{field}.guide.angle"), a, Dim::Angle)?,
            None => 0.0,
        };
        let mut through = match g.through.get_ref() {
            Through::Coords(c) => pair(task, &format!("{field}.guide.through"), &respan(g.through.span(), c), Dim::Length)?,
            Through::Point(pn) => {
                let found = if gl == FRAME {
                    def.fixed.iter().find(|(n, _)| n == pn).map(|(_, p)| *p)
                } else {
                    def.links.iter().find(|l| l.name == gl).and_then(|l| l.point(pn))
                };
                found.ok_or_else(|| {
                    Error::at(
                        task,
                        g.through.span(),
                        &format!("{field}.guide.through"),
                        format!("`{pn}` is not a point of `{gl}`"),
                    )
                    .with_help("give a point of the guide's link, or coordinates [x, y]")
                })?
            }
        };
        if let Some(o) = &g.offset {
            let off = qty(task, &format!("{field}.guide.offset"), o, Dim::Length)?;
            through += Vec2::new(-angle.sin(), angle.cos()) * off;
        }
        def.sliders.push(SliderDef {
            slider: sl,
            point: s.point.get_ref().clone(),
            guide_link: gl,
            through,
            angle,
            angle_on_slider: 0.0,
        });
    }
    // input
    let inp = sec.input.get_ref();
    spans.insert("input".into(), sec.input.span());
    let travel = match (&inp.link, &inp.slider) {
        (Some(_), Some(sl)) => {
            return Err(Error::at(task, sl.span(), "linkage.input.slider", "the input is a crank (`link`) or a slider (`slider`), not both")
                .with_help("a crank takes input.link and input.speed in rpm; a slider takes input.slider and input.speed in m/s with travel in [linkage]"));
        }
        (None, None) => {
            return Err(Error::at(task, sec.input.span(), "linkage.input", "the input needs `link` (a crank) or `slider` (a slider on a fixed guide)")
                .with_help("a crank takes input.link and input.speed in rpm; a slider takes input.slider and input.speed in m/s with travel in [linkage]"));
        }
        (Some(link), None) => {
            if let Some(t) = &sec.travel {
                return Err(Error::at(
                    task,
                    t.span(),
                    "linkage.travel",
                    "a travel is the range of a slider input; this input is a crank",
                )
                .with_help("remove `travel` or drive the mechanism by a slider (input.slider)"));
            }
            if let Some(a) = &inp.acceleration {
                return Err(Error::at(
                    task,
                    a.span(),
                    "linkage.input.acceleration",
                    "`acceleration` belongs to a slider input; a crank's is `epsilon`",
                )
                .with_help("epsilon = \"10 rad/s^2\""));
            }
            read_crank(task, &mut def, &mut spans, inp, link)?;
            None
        }
        (None, Some(sl)) => Some(read_slider_input(task, &mut def, &mut spans, &sec, inp, sl)?),
    };
    def.output = sec.output.as_ref().map(|o| {
        spans.insert("output".into(), o.span());
        o.get_ref().clone()
    });
    // hints
    for (i, h) in sec.assembly.iter().enumerate() {
        spans.insert(format!("assembly[{i}]"), h.span());
        let field = format!("linkage.assembly[{i}]");
        let hint = match h.get_ref() {
            HintSec::Text(t) => parse_hint(t, &def).map_err(|m| Error::at(task, h.span(), &field, m).with_help("e.g. \"C above AD\", \"C below A-D\", \"C left of AD\", \"C right of AD\", or { point = \"C\", near = [\"0.3 m\", \"0.35 m\"] }"))?,
            HintSec::Near { point, near } => AssemblyHint { point: point.clone(), kind: HintKind::Near(pair(task, &format!("{field}.near"), &respan(h.span(), near), Dim::Length)?) },
        };
        def.hints.push(hint);
    }
    def.assembly_angle = match (&sec.assembly_angle, travel) {
        (Some(a), Some(_)) => {
            return Err(Error::at(
                task,
                a.span(),
                "linkage.assembly_angle",
                "a slider input has no crank angle: its assembly hints hold at the start of the travel",
            )
            .with_help("remove `assembly_angle`; the hints choose the assembly at the first s of `travel`"));
        }
        (Some(a), None) => qty(task, "linkage.assembly_angle", a, Dim::Angle)?,
        (None, Some(t)) => t.from,
        (None, None) => 0.0,
    };
    if travel.is_some() {
        for (key, v) in [
            ("working", sec.working.as_ref().map(|w| w.span())),
            ("range", sec.range.as_ref().map(|r| r.span())),
        ] {
            if let Some(span) = v {
                return Err(Error::at(
                    task,
                    span,
                    &format!("linkage.{key}"),
                    format!("`{key}` speaks of a crank's turn; a slider input is analysed over its travel"),
                )
                .with_help("remove it; `travel` gives the slider's range"));
            }
        }
    }
    let working = match sec.working.as_ref() {
        None => Working::Slower,
        Some(w) => match w.get_ref().as_str() {
            "slower" => Working::Slower,
            "increasing" => Working::Increasing,
            "decreasing" => Working::Decreasing,
            other => return Err(Error::at(task, w.span(), "linkage.working", format!("unknown working stroke `{other}`")).with_help("\"slower\" (default: the longer crank angle), \"increasing\" or \"decreasing\" (the output coordinate on the working stroke)")),
        },
    };
    let positions = match &sec.positions {
        None => 12,
        Some(p) => {
            let n = *p.get_ref();
            if !(1..=MAX_POSITIONS as i64).contains(&n) {
                return Err(Error::at(task, p.span(), "linkage.positions", format!("{n} positions"))
                    .with_help(format!("a number from 1 to {MAX_POSITIONS}; the course uses 12")));
            }
            n as usize
        }
    };
    let at = match &sec.at {
        Some(a) => {
            spans.insert("at".into(), a.span());
            match travel {
                None => Some(qty(task, "linkage.at", a, Dim::Angle)?),
                Some(t) => {
                    let x = qty(task, "linkage.at", a, Dim::Length)?;
                    if !(t.from..=t.to).contains(&x) {
                        return Err(Error::at(
                            task,
                            a.span(),
                            "linkage.at",
                            format!(
                                "s = {:.3} mm is outside the travel {:.3} … {:.3} mm",
                                x * 1e3,
                                t.from * 1e3,
                                t.to * 1e3
                            ),
                        )
                        .with_help("for a slider input `at` is the slider's s inside `travel`"));
                    }
                    Some(x)
                }
            }
        }
        None => None,
    };
    let range = match sec.range.as_ref() {
        None => RangeMode::Full,
        Some(r) => match r.get_ref().as_str() {
            "full" => RangeMode::Full,
            "partial" => RangeMode::Partial,
            other => {
                return Err(Error::at(task, r.span(), "linkage.range", format!("unknown range `{other}`")).with_help(
                    "\"full\" (default: the crank turns a full revolution) or \"partial\" (only the crank angles where the mechanism assembles)",
                ));
            }
        },
    };
    if let (RangeMode::Partial, Some(w)) = (range, sec.working.as_ref()) {
        return Err(
            Error::at(task, w.span(), "linkage.working", "a working stroke needs a full turn of the crank")
                .with_help("remove `working`, or remove range = \"partial\""),
        );
    }
    Ok(Some(LinkageTask {
        def,
        working,
        positions,
        at,
        travel,
        range,
        range_span: sec.range.as_ref().map(|r| r.span()),
        spans,
        section,
    }))
}

/// The crank input: `input = { link, pivot, pin, speed, direction, epsilon }`.
fn read_crank(
    task: &TaskSource,
    def: &mut MechanismDef,
    spans: &mut HashMap<String, Range<usize>>,
    inp: &InputSec,
    link: &S<String>,
) -> Result<(), Error> {
    spans.insert("input.link".into(), link.span());
    let cl = link.get_ref().clone();
    let cdef = def.links.iter().find(|l| l.name == cl).ok_or_else(|| {
        Error::at(task, link.span(), "linkage.input.link", format!("unknown link `{cl}`")).with_help(format!(
            "links: {}",
            def.links.iter().map(|l| l.name.as_str()).collect::<Vec<_>>().join(", ")
        ))
    })?;
    let pivot = match &inp.pivot {
        Some(p) => {
            spans.insert("input.pivot".into(), p.span());
            p.get_ref().clone()
        }
        None => cdef
            .points
            .iter()
            .find(|(n, _)| def.fixed.iter().any(|(f, _)| f == n))
            .map(|(n, _)| n.clone())
            .ok_or_else(|| {
                Error::at(
                    task,
                    link.span(),
                    "linkage.input.pivot",
                    format!("the crank `{cl}` has no fixed joint"),
                )
                .with_help("one of the crank's joints must be a fixed point; or give input.pivot")
            })?,
    };
    let pin = match &inp.pin {
        Some(p) => {
            spans.insert("input.pin".into(), p.span());
            p.get_ref().clone()
        }
        None => cdef
            .points
            .iter()
            .take(2)
            .find(|(n, _)| *n != pivot)
            .map(|(n, _)| n.clone())
            .unwrap_or_default(),
    };
    let speed = qty(task, "linkage.input.speed", &inp.speed, Dim::AngularVelocity)?;
    spans.insert("input.speed".into(), inp.speed.span());
    let sign = match inp.direction.as_ref().map(|d| (d.get_ref().to_lowercase(), d.span())) {
        None => 1.0,
        Some((d, span)) => match d.as_str() {
            "ccw" | "counter-clockwise" | "counterclockwise" | "против часовой" | "проти годинникової" => 1.0,
            "cw" | "clockwise" | "по часовой" | "за годинниковою" => -1.0,
            _ => {
                return Err(Error::at(task, span, "linkage.input.direction", format!("unknown direction `{d}`"))
                    .with_help("\"ccw\" (counter-clockwise) or \"cw\" (clockwise)"));
            }
        },
    };
    let epsilon = match &inp.epsilon {
        Some(e) => qty(task, "linkage.input.epsilon", e, Dim::AngularAcceleration)?,
        None => 0.0,
    };
    def.input = Some(InputDef {
        link: cl,
        pivot,
        pin,
        omega: sign * speed,
        epsilon,
    });
    Ok(())
}

/// The slider input: `input = { slider, speed, acceleration }` with
/// `travel = [from, to]` in the section. The speed is signed along the
/// guide's direction (> 0: s increases); the travel must increase.
fn read_slider_input(
    task: &TaskSource,
    def: &mut MechanismDef,
    spans: &mut HashMap<String, Range<usize>>,
    sec: &LinkageSec,
    inp: &InputSec,
    sl: &S<String>,
) -> Result<Travel, Error> {
    spans.insert("input.slider".into(), sl.span());
    spans.insert("input.link".into(), sl.span());
    for (key, span) in [
        ("pivot", inp.pivot.as_ref().map(|x| x.span())),
        ("pin", inp.pin.as_ref().map(|x| x.span())),
        ("direction", inp.direction.as_ref().map(|x| x.span())),
        ("epsilon", inp.epsilon.as_ref().map(|x| x.span())),
    ] {
        if let Some(span) = span {
            return Err(Error::at(
                task,
                span,
                &format!("linkage.input.{key}"),
                format!("`{key}` belongs to a crank input; this input is the slider `{}`", sl.get_ref()),
            )
            .with_help("a slider input takes `slider` and `speed` (signed along the guide) and `acceleration` (default 0)"));
        }
    }
    let speed = qty(task, "linkage.input.speed", &inp.speed, Dim::Velocity)?;
    spans.insert("input.speed".into(), inp.speed.span());
    let acceleration = match &inp.acceleration {
        Some(a) => {
            spans.insert("input.acceleration".into(), a.span());
            qty(task, "linkage.input.acceleration", a, Dim::Acceleration)?
        }
        None => 0.0,
    };
    let t = sec.travel.as_ref().ok_or_else(|| {
        Error::at(
            task,
            sl.span(),
            "linkage.travel",
            "a slider input needs its travel: the s range to analyse",
        )
        .with_help("give travel = [from, to] in [linkage] (s along the guide from its `through` point)")
    })?;
    spans.insert("travel".into(), t.span());
    let ends = t.get_ref();
    if ends.len() != 2 {
        return Err(Error::at(
            task,
            t.span(),
            "linkage.travel",
            format!("expected two values [from, to], found {}", ends.len()),
        )
        .with_help("give travel = [from, to] in [linkage] (s along the guide from its `through` point)"));
    }
    let from = qty(task, "linkage.travel[0]", &ends[0], Dim::Length)?;
    let to = qty(task, "linkage.travel[1]", &ends[1], Dim::Length)?;
    if from >= to {
        return Err(Error::at(
            task,
            t.span(),
            "linkage.travel",
            format!("the travel must increase: from {:.3} mm to {:.3} mm does not", from * 1e3, to * 1e3),
        )
        .with_help("give [from, to] with from < to; the direction of motion is the sign of `speed`"));
    }
    def.slider_input = Some(SliderInputDef {
        link: sl.get_ref().clone(),
        speed,
        acceleration,
    });
    Ok(Travel { from, to })
}

/// A point on a link from one of its forms; `None` while a referenced point
/// is not yet placed.
fn local_point(
    task: &TaskSource,
    field: &str,
    ps: &S<PointSec>,
    first_two: &[String],
    length: f64,
    defined: &BTreeMap<String, Vec2>,
) -> Result<Option<Vec2>, Error> {
    let p = ps.get_ref();
    let off = match &p.offset {
        Some(o) => qty(task, &format!("{field}.offset"), o, Dim::Length)?,
        None => 0.0,
    };
    if let Some(a) = &p.along {
        if first_two.len() < 2 {
            return Err(Error::at(
                task,
                a.span(),
                &format!("{field}.along"),
                "`along` needs a link with two joints",
            ));
        }
        let r = qty(task, &format!("{field}.along"), a, Dim::Ratio)?;
        return Ok(Some(Vec2::new(r * length, off)));
    }
    if let Some(at) = &p.at {
        return pair(task, &format!("{field}.at"), at, Dim::Length).map(Some);
    }
    if let Some(from) = &p.from {
        let Some(&o) = defined.get(from.get_ref()) else { return Ok(None) };
        let toward = match &p.toward {
            Some(t) => t.get_ref().clone(),
            None => first_two.iter().find(|n| *n != from.get_ref()).cloned().unwrap_or_default(),
        };
        let Some(&t) = defined.get(&toward) else { return Ok(None) };
        let dir = t - o;
        if dir.hypot() <= 0.0 {
            return Err(Error::at(task, ps.span(), field, "`from` and `toward` coincide"));
        }
        let base = dir.atan2();
        let ang = match &p.angle {
            Some(a) => qty(task, &format!("{field}.angle"), a, Dim::Angle)?,
            None => 0.0,
        };
        let lq = p.length.as_ref().ok_or_else(|| {
            Error::at(task, ps.span(), &format!("{field}.length"), "missing the distance from `from`").with_help("length = \"0.6 m\"")
        })?;
        let len = qty(task, &format!("{field}.length"), lq, Dim::Length)?;
        if len <= 0.0 {
            return Err(Error::at(task, lq.span(), &format!("{field}.length"), "a length must be > 0"));
        }
        let a = base + ang;
        return Ok(Some(o + Vec2::new(a.cos(), a.sin()) * len));
    }
    Err(
        Error::at(task, ps.span(), field, "a point needs `along`, `at`, or `from` with `length`").with_help(
            "{ along = 0.5 } | { at = [\"100 mm\", \"0 mm\"] } | { from = \"E\", toward = \"B\", angle = \"180 deg\", length = \"0.6 m\" }",
        ),
    )
}

/// Parse "C above AD", "C below A-D", "C left of AD", "C right of line AD".
fn parse_hint(t: &str, def: &MechanismDef) -> Result<AssemblyHint, String> {
    let words: Vec<&str> = t.split_whitespace().filter(|w| *w != "of" && *w != "line").collect();
    if words.len() != 3 {
        return Err(format!("cannot read the assembly hint `{t}`"));
    }
    let known = |n: &str| def.fixed.iter().any(|(f, _)| f == n) || def.links.iter().any(|l| l.point(n).is_some());
    let line = words[2];
    let (a, b) = if let Some((a, b)) = line.split_once(['-', ',']) {
        (a.to_string(), b.to_string())
    } else {
        let mut found = None;
        for (k, _) in line.char_indices().skip(1) {
            let (a, b) = line.split_at(k);
            if known(a) && known(b) {
                found = Some((a.to_string(), b.to_string()));
                break;
            }
        }
        found.ok_or_else(|| format!("`{line}` is not two point names"))?
    };
    let kind = match words[1] {
        "above" => HintKind::Above(a, b),
        "below" => HintKind::Below(a, b),
        "left" => HintKind::LeftOf(a, b),
        "right" => HintKind::RightOf(a, b),
        w => return Err(format!("unknown side `{w}` in `{t}`")),
    };
    Ok(AssemblyHint {
        point: words[0].to_string(),
        kind,
    })
}
