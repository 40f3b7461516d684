//! A mechanism compiled from its description into a solution plan: links and
//! pairs numbered, the crank, and the ordered Assur groups each with its own
//! solver (closed form for the five dyads, Newton for larger groups).
//! Kinematics, forces and dynamics all walk this one plan.

use std::collections::HashMap;
use std::f64::consts::PI;

use tmm_geom::{Vec2, perp};

use crate::constraints::{self, Mode};
use crate::dyad::{DyadFail, DyadGeom, KnownGuide, KnownPoint};
use crate::error::LinkageError;
use crate::limits;
use crate::model::{FRAME, HintKind, MechanismDef};
use crate::state::{LinkState, PointState, conj, rot};
use crate::structure::{self, GroupInfo, PairKind, PairLink, Structure, roman};

/// A lower pair between two links.
#[derive(Debug, Clone, PartialEq)]
pub enum Pair {
    /// Revolute pair at a point: local coordinates on each link.
    R {
        /// One link.
        a: usize,
        /// The other link.
        b: usize,
        /// The point on `a`, local.
        la: Vec2,
        /// The point on `b`, local.
        lb: Vec2,
        /// Index of the named point.
        point: usize,
    },
    /// Prismatic pair: `slider` moves along a line of `guide`.
    P {
        /// The sliding link.
        slider: usize,
        /// The link carrying the guide.
        guide: usize,
        /// The slider's point on the line, slider-local.
        ps: Vec2,
        /// A point of the line, guide-local.
        q: Vec2,
        /// Unit direction of the line, guide-local.
        d: Vec2,
        /// `u_slider = u_guide · rel`.
        rel: Vec2,
        /// Index of the slider's named point.
        point: usize,
    },
}

impl Pair {
    /// The two links of the pair.
    pub fn links(&self) -> (usize, usize) {
        match *self {
            Pair::R { a, b, .. } => (a, b),
            Pair::P { slider, guide, .. } => (slider, guide),
        }
    }
    /// The named point of the pair.
    pub fn point(&self) -> usize {
        match *self {
            Pair::R { point, .. } | Pair::P { point, .. } => point,
        }
    }
    /// R or P.
    pub fn kind(&self) -> PairKind {
        match self {
            Pair::R { .. } => PairKind::R,
            Pair::P { .. } => PairKind::P,
        }
    }
}

/// A named point: the link it is fixed on and its local coordinates there.
#[derive(Debug, Clone, PartialEq)]
pub struct NamedPoint {
    /// The name (`A`, `S2`).
    pub name: String,
    /// The link (0: frame).
    pub link: usize,
    /// Local coordinates, m.
    pub local: Vec2,
}

/// The input crank.
#[derive(Debug, Clone, PartialEq)]
pub struct Crank {
    /// The crank link.
    pub link: usize,
    /// Global position of the fixed pivot.
    pub pivot: Vec2,
    /// The pivot on the crank, local.
    pub pivot_local: Vec2,
    /// Unit direction pivot → pin on the crank, local.
    pub dir_local: Vec2,
    /// Crank radius |pivot → pin|, m.
    pub radius: f64,
    /// ω1, rad/s (signed).
    pub omega: f64,
    /// ε1, rad/s².
    pub eps: f64,
    /// The pin's point index.
    pub pin: usize,
    /// The pivot's point index.
    pub pivot_point: usize,
}

/// The input slider (ведущий ползун) on a guide fixed to the frame, driven
/// along it: at travel s its point P is at `Q + s·d` with velocity `v·d`
/// and acceleration `a·d`, and it does not turn (its orientation is the
/// guide's, `u = rel`, ω = ε = 0). Derived in docs/linkage.md, "A slider as
/// the input".
#[derive(Debug, Clone, PartialEq)]
pub struct SliderDrive {
    /// The slider link.
    pub link: usize,
    /// The slider's point index (P).
    pub point: usize,
    /// The index of its prismatic pair with the frame.
    pub pair: usize,
    /// The guide's point Q (global), m: s = 0 there.
    pub through: Vec2,
    /// The guide's unit direction d (global).
    pub dir: Vec2,
    /// P on the slider, local.
    pub ps: Vec2,
    /// The slider's orientation (constant).
    pub u: Vec2,
    /// v = ds/dt, m/s (signed).
    pub speed: f64,
    /// a = d²s/dt², m/s².
    pub accel: f64,
}

impl SliderDrive {
    /// The drive of link `cl` described by `si`: its prismatic pair must
    /// have the frame as the guide.
    fn new(cl: usize, names: &[String], pairs: &[Pair], si: &crate::model::SliderInputDef) -> Result<Self, LinkageError> {
        let mut found = None;
        for (k, p) in pairs.iter().enumerate() {
            if let Pair::P { slider, guide, .. } = *p {
                if slider == cl {
                    if guide == 0 {
                        found = Some(k);
                        break;
                    }
                    found = found.or(Some(k));
                }
            }
        }
        let Some(k) = found else {
            return Err(de(
                "input.slider",
                format!(
                    "`{}` slides on no guide: a driving slider needs its prismatic pair with the frame (a `sliders` entry with guide.link = \"frame\")",
                    si.link
                ),
            ));
        };
        let Pair::P {
            guide,
            ps,
            q,
            d,
            rel,
            point,
            ..
        } = pairs[k]
        else {
            unreachable!("a prismatic pair was found")
        };
        if guide != 0 {
            return Err(de(
                "input.slider",
                format!(
                    "the guide of `{}` is on the moving link `{}`; a driving slider moves on a guide fixed to the frame (guide.link = \"frame\")",
                    si.link, names[guide]
                ),
            ));
        }
        limits::slider_speed(si.speed, si.acceleration)?;
        Ok(SliderDrive {
            link: cl,
            point,
            pair: k,
            through: q,
            dir: d,
            ps,
            u: rel,
            speed: si.speed,
            accel: si.acceleration,
        })
    }

    /// The slider's state at travel `s`, m.
    ///
    /// ```
    /// # use tmm_linkage::*; use tmm_geom::Vec2;
    /// // an inverted slider-crank: slider B on the x-axis, coupler BC, rocker DC
    /// let def = MechanismDef {
    ///     fixed: vec![("D".into(), Vec2::new(0.1, 0.2))],
    ///     links: vec![LinkDef::block("1", "B"), LinkDef::bar("2", "B", "C", 0.25), LinkDef::bar("3", "D", "C", 0.12)],
    ///     sliders: vec![SliderDef { slider: "1".into(), point: "B".into(), guide_link: FRAME.into(),
    ///         through: Vec2::ZERO, angle: 0.0, angle_on_slider: 0.0 }],
    ///     slider_input: Some(SliderInputDef::new("1", 0.5)),
    ///     assembly_angle: 0.05,
    ///     ..Default::default()
    /// };
    /// let m = Mechanism::new(&def).unwrap();
    /// let d = m.drive.as_ref().unwrap();
    /// let st = d.state(0.04);
    /// assert_eq!((st.o, st.v, st.omega), (Vec2::new(0.04, 0.0), Vec2::new(0.5, 0.0), 0.0));
    /// ```
    #[inline(always)]
    pub fn state(&self, s: f64) -> LinkState {
        let p = PointState {
            p: self.through + self.dir * s,
            v: self.dir * self.speed,
            a: self.dir * self.accel,
        };
        LinkState::from_point(&p, self.ps, self.u, 0.0, 0.0)
    }

    /// The travel s of a solved position, m.
    pub fn travel(&self, sol: &Solution) -> f64 {
        (sol.points[self.point].p - self.through).dot(self.dir)
    }
}

/// The row that holds the input in the rank count: the crank's rotation,
/// or the slider's displacement along its guide.
fn held_row(drive: &Option<SliderDrive>) -> [f64; 3] {
    match drive {
        Some(d) => [d.dir.x, d.dir.y, 0.0],
        None => [0.0, 0.0, 1.0],
    }
}

#[derive(Debug, Clone, PartialEq)]
enum Solver {
    Dyad(DyadGeom),
    General,
}

/// One Assur group with its solver.
#[derive(Debug, Clone, PartialEq)]
pub struct Group {
    /// Class, order, kind, links.
    pub info: GroupInfo,
    solver: Solver,
    /// Assembly branch of a dyad (±1).
    pub sign: f64,
    /// The pairs of the group (outer and inner), for general solves.
    pairs: Vec<usize>,
}

impl Group {
    /// Short label: `II(2,3) RRR`.
    pub fn label(&self) -> String {
        format!("{}({}) {}", roman(self.info.class), self.info.links.join(","), self.info.kind)
    }
    /// The dyad geometry, when the group is a dyad.
    pub fn dyad(&self) -> Option<&DyadGeom> {
        match &self.solver {
            Solver::Dyad(d) => Some(d),
            Solver::General => None,
        }
    }
}

/// A compiled mechanism.
#[derive(Debug, Clone)]
pub struct Mechanism {
    /// Link names; `[0]` is the frame.
    pub link_names: Vec<String>,
    /// Centres of mass, local.
    pub mass_centers: Vec<Vec2>,
    /// All named points.
    pub points: Vec<NamedPoint>,
    /// All pairs.
    pub pairs: Vec<Pair>,
    /// The crank; for a slider input ([`Mechanism::drive`]) its fields say
    /// of the slider: `link` the slider, `pivot` the guide's point Q,
    /// `pin` and `pivot_point` the slider's point, `radius` 0, `omega` the
    /// speed v (m/s) and `eps` the acceleration (m/s²).
    pub crank: Crank,
    /// The input slider on a fixed guide, when the input is not a crank.
    pub drive: Option<SliderDrive>,
    /// Assur groups in solving order.
    pub groups: Vec<Group>,
    /// Structure (W, groups, formula, class).
    pub structure: Structure,
    /// The output link.
    pub output: usize,
    /// Crank angle at which the assembly branch was chosen, rad.
    pub assembly_angle: f64,
    /// The assembled state at `assembly_angle` (warm start for Newton groups).
    init: Vec<LinkState>,
    /// Points not on the frame at a link's origin: (point, link). The frame's
    /// points are set once per buffer.
    origin_points: Vec<(usize, usize)>,
    /// Other points not on the frame: (point, link, local).
    offset_points: Vec<(usize, usize, Vec2)>,
    has_general: bool,
    scale: f64,
}

/// A solved position; reused between solves so that solving allocates nothing.
#[derive(Debug, Clone)]
pub struct Solution {
    /// Crank angle φ, rad (absolute angle of pivot → pin).
    pub phi: f64,
    /// Link states, indexed as [`Mechanism::link_names`].
    pub links: Vec<LinkState>,
    /// Point states, indexed as [`Mechanism::points`].
    pub points: Vec<PointState>,
    jac: Vec<f64>,
    rhs: Vec<f64>,
    warm: Option<f64>,
}

/// Groups whose branches are chosen together, and the hints that score them
/// (indices into [`MechanismDef::hints`]).
#[derive(Debug, Default)]
struct AssemblyUnit {
    groups: Vec<usize>,
    hints: Vec<usize>,
}

/// The most dyads whose branches are chosen together (2^12 = 4096
/// combinations): hints that tie more together are refused.
pub const MAX_COUPLED: usize = 12;

/// Whether two assemblies place some point more than `tol` apart.
fn differs(a: &[Vec2], b: &[Vec2], tol: f64) -> bool {
    a.iter().zip(b).any(|(p, q)| (*p - *q).hypot() > tol)
}

/// The penalty of a violated side hint, in sizes of the mechanism (far more
/// than any `near` distance).
const VIOLATION: f64 = 1e6;

fn de(field: impl Into<String>, message: impl Into<String>) -> LinkageError {
    LinkageError::desc(field, message)
}

fn unit(v: Vec2) -> Vec2 {
    v * (1.0 / v.hypot())
}

fn polar(a: f64) -> Vec2 {
    Vec2::new(a.cos(), a.sin())
}

impl Mechanism {
    /// Compile a description: check it, number it, find its structure, build
    /// the solvers and choose the assembly branch from the hints.
    pub fn new(def: &MechanismDef) -> Result<Self, LinkageError> {
        if def.links.len() > limits::MAX_LINKS {
            return Err(de(
                "links",
                format!("{} links given; at most {} are taken", def.links.len(), limits::MAX_LINKS),
            ));
        }
        // --- links
        let mut link_names = vec![FRAME.to_string()];
        let mut mass_centers = vec![Vec2::ZERO];
        let mut index: HashMap<&str, usize> = HashMap::new();
        index.insert(FRAME, 0);
        for (i, l) in def.links.iter().enumerate() {
            if l.name.is_empty() {
                return Err(de(format!("links[{i}].name"), "a link needs a name"));
            }
            if index.insert(l.name.as_str(), link_names.len()).is_some() {
                return Err(de(
                    format!("links[{i}].name"),
                    format!("duplicate link name `{}` (link names must be unique; `frame` is reserved)", l.name),
                ));
            }
            if l.points.is_empty() {
                return Err(de(format!("links.{}", l.name), "a link needs at least one point"));
            }
            for (k, (pn, p)) in l.points.iter().enumerate() {
                limits::coordinate(&format!("links.{}.{pn}.x", l.name), p.x)?;
                limits::coordinate(&format!("links.{}.{pn}.y", l.name), p.y)?;
                if l.points[..k].iter().any(|(q, _)| q == pn) {
                    return Err(de(
                        format!("links.{}.{pn}", l.name),
                        format!("duplicate point `{pn}` on link `{}`", l.name),
                    ));
                }
            }
            limits::coordinate(&format!("links.{}.mass_center.x", l.name), l.mass_center.x)?;
            limits::coordinate(&format!("links.{}.mass_center.y", l.name), l.mass_center.y)?;
            if l.points.len() >= 2 && (l.points[1].1 - l.points[0].1).hypot() == 0.0 {
                return Err(de(
                    format!("links.{}.length", l.name),
                    format!(
                        "zero length: `{}` and `{}` coincide; a link length must be > 0",
                        l.points[0].0, l.points[1].0
                    ),
                ));
            }
            link_names.push(l.name.clone());
            mass_centers.push(l.mass_center);
        }
        let nl = link_names.len();
        // --- points and revolute pairs
        let mut points: Vec<NamedPoint> = Vec::new();
        let mut occ: Vec<Vec<(usize, Vec2)>> = Vec::new();
        let mut pidx: HashMap<String, usize> = HashMap::new();
        for (name, p) in &def.fixed {
            if pidx.contains_key(name) {
                return Err(de(format!("fixed.{name}"), format!("duplicate fixed point `{name}`")));
            }
            limits::coordinate(&format!("fixed.{name}.x"), p.x)?;
            limits::coordinate(&format!("fixed.{name}.y"), p.y)?;
            pidx.insert(name.clone(), points.len());
            points.push(NamedPoint {
                name: name.clone(),
                link: 0,
                local: *p,
            });
            occ.push(vec![(0, *p)]);
        }
        for (li, l) in def.links.iter().enumerate() {
            for (pn, p) in &l.points {
                match pidx.get(pn) {
                    Some(&k) => occ[k].push((li + 1, *p)),
                    None => {
                        pidx.insert(pn.clone(), points.len());
                        points.push(NamedPoint {
                            name: pn.clone(),
                            link: li + 1,
                            local: *p,
                        });
                        occ.push(vec![(li + 1, *p)]);
                    }
                }
            }
        }
        // a point shared by links is read off the one where it is the local
        // origin, if any (no rotation needed)
        for (k, o) in occ.iter().enumerate() {
            if points[k].link != 0 {
                if let Some(&(l, p)) = o.iter().find(|(l, p)| *l != 0 && *p == Vec2::ZERO) {
                    points[k].link = l;
                    points[k].local = p;
                }
            }
        }
        let mut pairs = Vec::new();
        for (k, o) in occ.iter().enumerate() {
            for &(lb, pb) in &o[1..] {
                pairs.push(Pair::R {
                    a: o[0].0,
                    b: lb,
                    la: o[0].1,
                    lb: pb,
                    point: k,
                });
            }
        }
        // --- prismatic pairs
        for (i, s) in def.sliders.iter().enumerate() {
            let f = |x: &str| format!("sliders[{i}].{x}");
            let slider = *index
                .get(s.slider.as_str())
                .ok_or_else(|| de(f("link"), format!("unknown link `{}`", s.slider)))?;
            if slider == 0 {
                return Err(de(f("link"), "the frame cannot slide"));
            }
            let guide = *index
                .get(s.guide_link.as_str())
                .ok_or_else(|| de(f("guide.link"), format!("unknown link `{}` (a link name or `frame`)", s.guide_link)))?;
            if guide == slider {
                return Err(de(f("guide.link"), "a link cannot slide on itself"));
            }
            let ps = def.links[slider - 1]
                .point(&s.point)
                .ok_or_else(|| de(f("point"), format!("unknown point `{}` on link `{}`", s.point, s.slider)))?;
            limits::coordinate(&f("guide.through.x"), s.through.x)?;
            limits::coordinate(&f("guide.through.y"), s.through.y)?;
            limits::angle(&f("guide.angle"), s.angle)?;
            limits::angle(&f("angle_on_slider"), s.angle_on_slider)?;
            let dd = polar(s.angle);
            let rel = rot(dd, conj(polar(s.angle_on_slider)));
            pairs.push(Pair::P {
                slider,
                guide,
                ps,
                q: s.through,
                d: dd,
                rel,
                point: pidx[&s.point],
            });
        }
        // --- the input: a crank, or a slider on a fixed guide
        let (crank, drive, radius) = match (&def.input, &def.slider_input) {
            (Some(_), Some(_)) => {
                return Err(de(
                    "input",
                    "give the input as a crank (input.link) or as a slider (input.slider), not both",
                ));
            }
            (None, None) => {
                return Err(de(
                    "input",
                    "the mechanism needs an input crank (input.link) or an input slider (input.slider)",
                ));
            }
            (Some(inp), None) => {
                let cl = *index
                    .get(inp.link.as_str())
                    .ok_or_else(|| de("input.link", format!("unknown link `{}`", inp.link)))?;
                if cl == 0 {
                    return Err(de("input.link", "the input must be a moving link"));
                }
                let cdef = &def.links[cl - 1];
                let pivot_local = cdef
                    .point(&inp.pivot)
                    .ok_or_else(|| de("input.pivot", format!("`{}` is not a point of the crank `{}`", inp.pivot, inp.link)))?;
                let pin_local = cdef
                    .point(&inp.pin)
                    .ok_or_else(|| de("input.pin", format!("`{}` is not a point of the crank `{}`", inp.pin, inp.link)))?;
                let pivot = def
                    .fixed
                    .iter()
                    .find(|(n, _)| *n == inp.pivot)
                    .map(|(_, p)| *p)
                    .ok_or_else(|| de("input.pivot", format!("the crank pivot `{}` must be a fixed point", inp.pivot)))?;
                let radius = (pin_local - pivot_local).hypot();
                limits::speed(inp.omega, inp.epsilon)?;
                let crank = Crank {
                    link: cl,
                    pivot,
                    pivot_local,
                    dir_local: unit(pin_local - pivot_local),
                    radius,
                    omega: inp.omega,
                    eps: inp.epsilon,
                    pin: pidx[&inp.pin],
                    pivot_point: pidx[&inp.pivot],
                };
                (crank, None, radius)
            }
            (None, Some(si)) => {
                let cl = *index
                    .get(si.link.as_str())
                    .filter(|&&l| l != 0)
                    .ok_or_else(|| de("input.slider", format!("unknown link `{}` (a slider listed in `sliders`)", si.link)))?;
                let drive = SliderDrive::new(cl, &link_names, &pairs, si)?;
                let crank = Crank {
                    link: cl,
                    pivot: drive.through,
                    pivot_local: drive.ps,
                    dir_local: Vec2::new(1.0, 0.0),
                    radius: 0.0,
                    omega: si.speed,
                    eps: si.acceleration,
                    pin: drive.point,
                    pivot_point: drive.point,
                };
                (crank, Some(drive), 0.0)
            }
        };
        let cl = crank.link;
        limits::angle("assembly_angle", def.assembly_angle)?;
        // the size of the mechanism: the largest extent of a link, of the
        // frame's points and of the guides' points; every tolerance is relative to it
        let size = scale_of(def, radius);
        if drive.is_none() {
            limits::link_length("input (crank length)", radius, size)?;
        }
        for l in &def.links {
            if l.points.len() >= 2 {
                limits::link_length(&format!("links.{}.length", l.name), (l.points[1].1 - l.points[0].1).hypot(), size)?;
            }
        }
        // --- connectivity
        for (l, name) in link_names.iter().enumerate().skip(1) {
            if !pairs.iter().any(|p| {
                let (a, b) = p.links();
                a == l || b == l
            }) {
                return Err(de(
                    format!("links.{name}"),
                    format!("link `{name}` shares no point with any other link or the frame"),
                ));
            }
        }
        // --- structure
        let plinks: Vec<PairLink> = pairs
            .iter()
            .map(|p| PairLink {
                a: p.links().0,
                b: p.links().1,
                kind: p.kind(),
            })
            .collect();
        let n = nl - 1;
        let p5 = pairs.len();
        let w = 3 * n as i64 - 2 * p5 as i64;
        let decomposed = structure::decompose(nl, &plinks, cl);
        let raw_groups = match decomposed {
            Ok(g) => g,
            Err(left) => {
                let names: Vec<&str> = left.iter().map(|&l| link_names[l].as_str()).collect();
                // points of the leftover links that join nothing: often a joint
                // whose other side was never defined
                let lone: Vec<String> = occ
                    .iter()
                    .enumerate()
                    .filter(|(k, o)| {
                        o.len() == 1
                            && left.contains(&o[0].0)
                            && !def.sliders.iter().any(|s| s.point == points[*k].name)
                            && def.links[o[0].0 - 1].points.len() >= 2
                            // a link's own centre of mass `S<link>` is meant to join nothing
                            && points[*k].name != format!("S{}", link_names[o[0].0])
                    })
                    .map(|(k, o)| format!("`{}` (on link `{}`)", points[k].name, link_names[o[0].0]))
                    .collect();
                let lone_text = if lone.is_empty() {
                    String::new()
                } else {
                    format!(
                        "; the points {} are on no other link and are not fixed points, so they join nothing — if one is a joint, put it on its other link or among the fixed points",
                        lone.join(", ")
                    )
                };
                // the rank of the whole mechanism at an assembled position:
                // at a special crank angle (a parallelogram with every link
                // on the frame line, φ = 0) the rank drops, the assembly
                // fails or the solve lands on an isolated locked
                // configuration, so it is counted at five crank angles and the
                // count met most often is the mechanism's (a tie goes to the
                // smaller mobility)
                let size = scale_of(def, radius);
                let input_at = |q: f64| {
                    let mut st = vec![LinkState::default(); nl];
                    st[cl] = match &drive {
                        Some(d) => d.state(q),
                        None => {
                            let (sc, cc) = q.sin_cos();
                            let u = crate::state::unrotate(Vec2::new(cc, sc), crank.dir_local);
                            let piv = PointState {
                                p: crank.pivot,
                                v: Vec2::ZERO,
                                a: Vec2::ZERO,
                            };
                            LinkState::from_point(&piv, crank.pivot_local, u, crank.omega, crank.eps)
                        }
                    };
                    st
                };
                let near: Vec<(usize, Vec2, Vec2)> = def
                    .hints
                    .iter()
                    .filter_map(|h| match h.kind {
                        HintKind::Near(q) => {
                            let k = *pidx.get(&h.point)?;
                            Some(
                                occ[k]
                                    .iter()
                                    .filter(|(l, _)| *l != 0)
                                    .map(move |&(l, lp)| (l, lp, q))
                                    .collect::<Vec<_>>(),
                            )
                        }
                        _ => None,
                    })
                    .flatten()
                    .collect();
                let fixed: Vec<Vec2> = def.fixed.iter().map(|(_, p)| *p).collect();
                let centre = fixed.iter().fold(Vec2::ZERO, |a, b| a + *b) * (1.0 / fixed.len().max(1) as f64);
                let mut counts: Vec<(crate::whole::RankCount, usize)> = Vec::new();
                // a slider's travel is shifted by parts of the mechanism's size
                let unit_shift = if drive.is_some() { 0.05 * size } else { 1.0 };
                for shift in [0.0, 0.7, 1.9, 3.4, 4.6] {
                    let st = input_at(def.assembly_angle + shift * unit_shift);
                    let Some(asm) = crate::whole::assemble_all(&pairs, &st, cl, &near, centre, size, 64) else {
                        continue;
                    };
                    let rc = crate::whole::rank_count(&pairs, nl, cl, held_row(&drive), &asm, size);
                    match counts.iter_mut().find(|(c, _)| *c == rc) {
                        Some((_, k)) => *k += 1,
                        None => counts.push((rc, 1)),
                    }
                }
                let count = counts
                    .iter()
                    .max_by(|(a, ka), (b, kb)| ka.cmp(kb).then(b.dof.cmp(&a.dof)))
                    .map(|(c, _)| *c);
                return Err(match count {
                    Some(rc) if rc.redundant > 0 || rc.dof != w => LinkageError::Redundant {
                        w,
                        n,
                        p5,
                        dof: rc.dof,
                        redundant: rc.redundant,
                        passive: rc.passive,
                        detail: format!(
                            "the Assur groups on the {} `{}` leave {} over, whose pairs repeat constraints the groups already impose{lone_text}",
                            if drive.is_some() { "input slider" } else { "crank" },
                            link_names[cl],
                            left.iter()
                                .map(|&l| {
                                    let joints: Vec<&str> = def.links[l - 1]
                                        .points
                                        .iter()
                                        .filter(|(p, _)| pidx.get(p).is_some_and(|&k| occ[k].len() > 1))
                                        .map(|(p, _)| p.as_str())
                                        .collect();
                                    format!("link `{}` ({})", link_names[l], joints.join("–"))
                                })
                                .collect::<Vec<_>>()
                                .join(", ")
                        ),
                    },
                    _ if w != 1 => LinkageError::Mobility {
                        dof: w,
                        w,
                        n,
                        p5,
                        p4: 0,
                        detail: format!("; links {} do not form Assur groups{lone_text}", names.join(", ")),
                    },
                    _ => LinkageError::Structure(format!(
                        "links {} do not form Assur groups on the {} `{}`{lone_text}",
                        names.join(", "),
                        if drive.is_some() { "input slider" } else { "crank" },
                        link_names[cl]
                    )),
                });
            }
        };
        let mut groups = Vec::new();
        let mut infos = Vec::new();
        for (mut set, mut pids) in raw_groups {
            let (class, order, kind) = structure::classify(&mut set, &mut pids, &plinks);
            let info = GroupInfo {
                class,
                order,
                kind,
                links: set.iter().map(|&l| link_names[l].clone()).collect(),
                link_ids: set.clone(),
                pair_ids: pids.clone(),
            };
            let solver = if class == 2 {
                Solver::Dyad(build_dyad(&set, &pids, &pairs)?)
            } else {
                Solver::General
            };
            infos.push(info.clone());
            groups.push(Group {
                info,
                solver,
                sign: 1.0,
                pairs: pids,
            });
        }
        let class = infos.iter().map(|g| g.class).max().unwrap_or(1);
        let mut formula = format!("I(0,{})", link_names[cl]);
        for g in &infos {
            // as the course writes it: numbers in ascending order, names as given
            let mut names: Vec<&str> = g.link_ids.iter().map(|&l| link_names[l].as_str()).collect();
            names.sort_by_key(|n| (n.parse::<u64>().unwrap_or(u64::MAX), n.to_string()));
            formula.push_str(&format!(" → {}({})", roman(g.class), names.join(",")));
        }
        let output = match &def.output {
            Some(o) => *index
                .get(o.as_str())
                .filter(|&&i| i != 0)
                .ok_or_else(|| de("output", format!("unknown link `{o}`")))?,
            None => default_output(&groups, &pairs, cl),
        };
        let scale = size;
        let structure = Structure {
            dof: w,
            n,
            p5,
            p4: 0,
            groups: infos,
            formula,
            class,
            dof_rank: w,
            redundant: 0,
            passive: 0,
        };
        let has_general = groups.iter().any(|g| g.solver == Solver::General);
        let origin_points: Vec<(usize, usize)> = (0..points.len())
            .filter(|&i| points[i].link != 0 && points[i].local == Vec2::ZERO)
            .map(|i| (i, points[i].link))
            .collect();
        let offset_points: Vec<(usize, usize, Vec2)> = (0..points.len())
            .filter(|&i| points[i].link != 0 && points[i].local != Vec2::ZERO)
            .map(|i| (i, points[i].link, points[i].local))
            .collect();
        let mut m = Mechanism {
            link_names,
            mass_centers,
            points,
            pairs,
            crank,
            drive,
            groups,
            structure,
            output,
            assembly_angle: def.assembly_angle,
            init: Vec::new(),
            origin_points,
            offset_points,
            has_general,
            scale,
        };
        m.choose_branches(def)?;
        m.count_rank()?;
        Ok(m)
    }

    /// The input coordinate as text: `φ = 12.000°` for a crank, `s =
    /// 40.000 mm` for a slider.
    pub fn at_text(&self, q: f64) -> String {
        match self.drive {
            Some(_) => format!("s = {:.3} mm", q * 1e3),
            None => format!("φ = {:.3}°", q.to_degrees()),
        }
    }

    /// An error for a calculation that needs a crank when the input is a
    /// slider: `what` names it.
    pub fn require_crank(&self, what: &str) -> Result<(), LinkageError> {
        match &self.drive {
            None => Ok(()),
            Some(d) => Err(de(
                "input.slider",
                format!(
                    "{what} needs a crank as the input; this mechanism is driven by the slider `{}`",
                    self.link_names[d.link]
                ),
            )),
        }
    }

    /// Index of a link by name.
    pub fn link(&self, name: &str) -> Option<usize> {
        self.link_names.iter().position(|n| n == name)
    }

    /// Index of a point by name.
    pub fn point(&self, name: &str) -> Option<usize> {
        self.points.iter().position(|p| p.name == name)
    }

    /// The state of a link's centre of mass S (центр масс) in a solved
    /// position: for every link, slider blocks included (whose S is at their
    /// joint unless given otherwise). The frame's is at rest at the origin.
    ///
    /// ```
    /// # use tmm_linkage::*; use tmm_geom::Vec2;
    /// # let def = MechanismDef { fixed: vec![("A".into(), Vec2::ZERO), ("D".into(), Vec2::new(0.51, 0.0))],
    /// #   links: vec![LinkDef::bar("1", "A", "B", 0.12), LinkDef::bar("2", "B", "C", 0.48), LinkDef::bar("3", "D", "C", 0.38)],
    /// #   input: Some(InputDef { link: "1".into(), pivot: "A".into(), pin: "B".into(), omega: 10.0, epsilon: 0.0 }), ..Default::default() };
    /// let m = Mechanism::new(&def).unwrap();
    /// let mut s = m.solution();
    /// m.solve(0.4, &mut s).unwrap();
    /// let (b, c) = (s.points[m.point("B").unwrap()], s.points[m.point("C").unwrap()]);
    /// let s2 = m.mass_center(&s, 2); // mid-way on BC
    /// assert!((s2.p - (b.p + c.p) * 0.5).hypot() < 1e-15);
    /// assert!((s2.a - (b.a + c.a) * 0.5).hypot() < 1e-12);
    /// ```
    pub fn mass_center(&self, sol: &Solution, link: usize) -> PointState {
        if link == 0 || link >= self.link_names.len() {
            return PointState::default();
        }
        sol.links[link].point(self.mass_centers[link])
    }

    /// A fresh solution buffer for this mechanism.
    pub fn solution(&self) -> Solution {
        // Newton's buffers only for a mechanism with a larger group (a dyad
        // needs none): a stored solution stays small
        let n = if self.has_general {
            3 * self.groups.iter().map(|g| g.info.link_ids.len()).max().unwrap_or(2)
        } else {
            0
        };
        Solution {
            phi: f64::NAN,
            links: if self.init.is_empty() {
                vec![LinkState::default(); self.link_names.len()]
            } else {
                self.init.clone()
            },
            points: self
                .points
                .iter()
                .map(|p| {
                    if p.link == 0 {
                        PointState {
                            p: p.local,
                            ..Default::default()
                        }
                    } else {
                        PointState::default()
                    }
                })
                .collect(),
            jac: vec![0.0; n * n],
            rhs: vec![0.0; n],
            warm: None,
        }
    }

    /// Solve positions, velocities and accelerations of every link and point at
    /// crank angle `phi` (rad; |φ| ≤ [`limits::MAX_ANGLE`]). Allocates nothing.
    pub fn solve(&self, phi: f64, sol: &mut Solution) -> Result<(), LinkageError> {
        limits::angle("phi", phi)?;
        if self.has_general {
            // Newton groups follow their branch from the nearest solved angle.
            let from = sol.warm.unwrap_or_else(|| {
                sol.links.clone_from(&self.init);
                self.assembly_angle
            });
            // steps of 2° of the crank, or of 1 % of the size along a slider
            let (gap, step) = match self.drive {
                Some(_) => (phi - from, 0.01 * self.scale),
                None => (tmm_geom::angle::diff(from, phi), 2.0 * PI / 180.0),
            };
            let steps = (gap.abs() / step).ceil() as usize;
            for k in 1..steps {
                let p = from + gap * k as f64 / steps as f64;
                self.solve_once(p, sol)?;
            }
        }
        self.solve_once(phi, sol)
    }

    /// Solve `n` positions from `phi0` in steps of `dphi` (rad), calling `f`
    /// with the index and the solution of each. The crank direction follows
    /// by complex rotation (exact `sin_cos` every 32 steps), so a sweep costs
    /// no trigonometry per position. Allocates nothing.
    ///
    /// ```
    /// # use tmm_linkage::*; use tmm_geom::Vec2;
    /// # let def = MechanismDef { fixed: vec![("A".into(), Vec2::ZERO), ("D".into(), Vec2::new(0.51, 0.0))],
    /// #   links: vec![LinkDef::bar("1", "A", "B", 0.12), LinkDef::bar("2", "B", "C", 0.48), LinkDef::bar("3", "D", "C", 0.38)],
    /// #   input: Some(InputDef { link: "1".into(), pivot: "A".into(), pin: "B".into(), omega: 10.0, epsilon: 0.0 }), ..Default::default() };
    /// let m = Mechanism::new(&def).unwrap();
    /// let (mut s1, mut s2) = (m.solution(), m.solution());
    /// let mut worst = 0.0f64;
    /// m.sweep(0.0, 0.01, 628, &mut s1, |k, s| {
    ///     m.solve(0.01 * k as f64, &mut s2).unwrap();
    ///     let c = m.point("C").unwrap();
    ///     worst = worst.max((s.points[c].a - s2.points[c].a).hypot() / s2.points[c].a.hypot());
    /// }).unwrap();
    /// assert!(worst < 1e-12);
    /// ```
    pub fn sweep(
        &self,
        phi0: f64,
        dphi: f64,
        n: usize,
        sol: &mut Solution,
        mut f: impl FnMut(usize, &Solution),
    ) -> Result<(), LinkageError> {
        limits::angle("phi0", phi0)?;
        limits::angle("phi0 + n·dphi", phi0 + dphi * n as f64)?;
        if self.has_general || self.drive.is_some() {
            for k in 0..n {
                self.solve(phi0 + dphi * k as f64, sol)?;
                f(k, sol);
            }
            return Ok(());
        }
        let (sd, cd) = dphi.sin_cos();
        let step = Vec2::new(cd, sd);
        let mut dir = Vec2::new(1.0, 0.0);
        for k in 0..n {
            let phi = phi0 + dphi * k as f64;
            dir = if k % 32 == 0 {
                let (s, c) = phi.sin_cos();
                Vec2::new(c, s)
            } else {
                rot(dir, step)
            };
            self.solve_dir(phi, dir, sol)?;
            f(k, sol);
        }
        Ok(())
    }

    #[inline]
    fn solve_once(&self, phi: f64, sol: &mut Solution) -> Result<(), LinkageError> {
        if self.drive.is_some() {
            return self.solve_dir(phi, Vec2::ZERO, sol);
        }
        let (s, co) = phi.sin_cos();
        self.solve_dir(phi, Vec2::new(co, s), sol)
    }

    /// Solve at crank angle `phi` whose direction `(cos φ, sin φ)` is `dir`.
    #[inline(always)]
    fn solve_dir(&self, phi: f64, dir: Vec2, sol: &mut Solution) -> Result<(), LinkageError> {
        sol.phi = phi;
        let c = &self.crank;
        sol.links[c.link] = match &self.drive {
            Some(d) => d.state(phi),
            None => {
                let u = crate::state::unrotate(dir, c.dir_local);
                let piv = PointState {
                    p: c.pivot,
                    v: Vec2::ZERO,
                    a: Vec2::ZERO,
                };
                LinkState::from_point(&piv, c.pivot_local, u, c.omega, c.eps)
            }
        };
        for g in &self.groups {
            match &g.solver {
                Solver::Dyad(dy) => {
                    if let Err(e) = dy.solve(g.sign, &mut sol.links) {
                        sol.warm = None;
                        return Err(self.fail(g, phi, e));
                    }
                }
                Solver::General => {
                    if let Err(e) = self.solve_general(g, sol) {
                        sol.warm = None;
                        return Err(self.fail(g, phi, e));
                    }
                }
            }
        }
        let links = &sol.links;
        for &(i, l) in &self.origin_points {
            let l = &links[l];
            sol.points[i] = PointState { p: l.o, v: l.v, a: l.a };
        }
        for &(i, l, local) in &self.offset_points {
            sol.points[i] = links[l].point(local);
        }
        // one sum catches any overflow (inside the ranges of `limits` none
        // occurs): a non-finite position or velocity makes the accelerations
        // non-finite too, so only they are summed — one short dependency chain
        let mut sum = 0.0;
        for l in links {
            sum += (l.a.x + l.a.y) + l.eps;
        }
        if !sum.is_finite() {
            sol.warm = None;
            return Err(LinkageError::NonFinite {
                phi_deg: phi.to_degrees(),
                what: "the positions, velocities or accelerations".into(),
            });
        }
        if self.has_general {
            sol.warm = Some(phi);
        }
        Ok(())
    }

    fn fail(&self, g: &Group, phi: f64, e: DyadFail) -> LinkageError {
        if self.drive.is_some() {
            return match e {
                DyadFail::Singular { .. } => LinkageError::SingularAtTravel {
                    s_mm: phi * 1e3,
                    group: g.label(),
                    reason: e.to_string(),
                },
                _ => LinkageError::AssemblyAtTravel {
                    s_mm: phi * 1e3,
                    group: g.label(),
                    reason: e.to_string(),
                },
            };
        }
        match e {
            DyadFail::Singular { .. } => LinkageError::Singular {
                phi_deg: phi.to_degrees(),
                group: g.label(),
                reason: e.to_string(),
            },
            _ => LinkageError::Assembly {
                phi_deg: phi.to_degrees(),
                group: g.label(),
                reason: e.to_string(),
            },
        }
    }

    fn solve_general(&self, g: &Group, sol: &mut Solution) -> Result<(), DyadFail> {
        // the group's pairs on the stack (a class-III triad has 6, a
        // class-IV group 8): no allocation per position below 32 pairs
        let mut buf = [&self.pairs[0]; 32];
        let heap: Vec<&Pair>;
        let prs: &[&Pair] = if g.pairs.len() <= buf.len() {
            for (b, &i) in buf.iter_mut().zip(&g.pairs) {
                *b = &self.pairs[i];
            }
            &buf[..g.pairs.len()]
        } else {
            heap = g.pairs.iter().map(|&i| &self.pairs[i]).collect();
            &heap
        };
        let unknown = &g.info.link_ids;
        let n = 3 * unknown.len();
        constraints::newton(prs, unknown, &mut sol.links, &mut sol.jac, &mut sol.rhs, self.scale).ok_or(DyadFail::NoClosure)?;
        for mode in [Mode::Velocity, Mode::Acceleration] {
            constraints::assemble(prs, unknown, &sol.links, mode, &mut sol.jac, &mut sol.rhs);
            // angles as arc lengths at the size of the mechanism, so that the
            // pivot test does not depend on the unit of length
            constraints::scale_angle_columns(&mut sol.jac[..n * n], n, n, 1.0 / self.scale);
            if !constraints::solve_dense(&mut sol.jac[..n * n], &mut sol.rhs[..n], n, 1e-11) {
                return Err(DyadFail::Singular { sine: f64::NAN });
            }
            for (k, &l) in unknown.iter().enumerate() {
                let s = &mut sol.links[l];
                let x = Vec2::new(sol.rhs[3 * k], sol.rhs[3 * k + 1]);
                let t = sol.rhs[3 * k + 2] / self.scale;
                if mode == Mode::Velocity {
                    s.v = x;
                    s.omega = t;
                } else {
                    s.a = x;
                    s.eps = t;
                }
            }
        }
        Ok(())
    }

    /// Choose each dyad's branch and each general group's start from the
    /// assembly hints at the assembly angle.
    ///
    /// The choice is made unit by unit, so its cost is linear in the groups
    /// for hints that each speak of one dyad. A hint's score depends on the
    /// groups that place its points and on every group upstream of them (its
    /// cone); groups whose cones meet form one unit, searched over all its
    /// branch combinations (at most 2^[`MAX_COUPLED`], refused past that),
    /// exactly as the whole mechanism once was. Units share no group and no
    /// hint, so the best assembly of the whole is the best of each unit. A
    /// group that no hint depends on is a unit of its own: its first branch
    /// (+1) that assembles, and with any hint given, an error if its other
    /// branch assembles elsewhere (the hints do not choose it). With a Newton
    /// group, whose 48 starting guesses are shared by all groups, the whole
    /// mechanism is one unit.
    fn choose_branches(&mut self, def: &MechanismDef) -> Result<(), LinkageError> {
        let mut resolved = Vec::with_capacity(def.hints.len());
        for (i, h) in def.hints.iter().enumerate() {
            let check = |n: &str| {
                self.point(n)
                    .ok_or_else(|| LinkageError::desc(format!("assembly[{i}]"), format!("unknown point `{n}`")))
            };
            let p = check(&h.point)?;
            let line = match &h.kind {
                HintKind::Above(a, b) | HintKind::Below(a, b) | HintKind::LeftOf(a, b) | HintKind::RightOf(a, b) => {
                    Some((check(a)?, check(b)?))
                }
                HintKind::Near(_) => None,
            };
            resolved.push((p, line));
        }
        let mut group_of = vec![usize::MAX; self.link_names.len()];
        for (g, grp) in self.groups.iter().enumerate() {
            for &l in &grp.info.link_ids {
                group_of[l] = g;
            }
        }
        // where each point is known first: a joint is on several links, and
        // its position is known once the earliest of them is solved (the
        // frame and the crank before every group)
        let rank = |l: usize| {
            if l == 0 || group_of[l] == usize::MAX {
                -1
            } else {
                group_of[l] as i64
            }
        };
        let mut carrier: Vec<(usize, Vec2)> = self.points.iter().map(|p| (p.link, p.local)).collect();
        for pair in &self.pairs {
            let on: &[(usize, Vec2)] = match *pair {
                Pair::R { a, b, la, lb, .. } => &[(a, la), (b, lb)],
                Pair::P { slider, ps, .. } => &[(slider, ps)],
            };
            let c = &mut carrier[pair.point()];
            for &(l, local) in on {
                if rank(l) < rank(c.0) {
                    *c = (l, local);
                }
            }
        }
        let units = self.assembly_units(&resolved, &carrier, &group_of);
        let phi = self.assembly_angle;
        let mut sol = self.solution();
        // the crank and the frame: hints on their points alone are scored here
        self.solve_groups(phi, &[], &mut sol)?;
        let fixed_hints: Vec<usize> = (0..resolved.len())
            .filter(|&i| !units.iter().any(|u| u.hints.contains(&i)))
            .collect();
        let s = self.score(def, &resolved, &carrier, &fixed_hints, &sol)?;
        if s >= VIOLATION * self.scale {
            return Err(self.unsatisfied(def));
        }
        for unit in &units {
            self.choose_unit(def, &resolved, &carrier, unit, &mut sol)?;
        }
        if self.has_general {
            self.init = sol.links;
        } else {
            let mut fresh = self.solution();
            self.solve_once(phi, &mut fresh)?;
            self.init = fresh.links;
        }
        Ok(())
    }

    /// Split the groups into units chosen independently: the hinted units
    /// (unions of the hints' cones) first, then every other group alone, in
    /// solving order, so that each unit's upstream groups are chosen before it.
    fn assembly_units(
        &self,
        hints: &[(usize, Option<(usize, usize)>)],
        carrier: &[(usize, Vec2)],
        group_of: &[usize],
    ) -> Vec<AssemblyUnit> {
        let ng = self.groups.len();
        // the groups each group takes its outer joints from
        let upstream: Vec<Vec<usize>> = self
            .groups
            .iter()
            .enumerate()
            .map(|(g, grp)| {
                let mut up: Vec<usize> = grp
                    .info
                    .pair_ids
                    .iter()
                    .flat_map(|&p| {
                        let (a, b) = self.pairs[p].links();
                        [a, b]
                    })
                    .map(|l| group_of[l])
                    .filter(|&h| h != usize::MAX && h != g)
                    .collect();
                up.sort_unstable();
                up.dedup();
                up
            })
            .collect();
        // union-find over groups; a unit's root is its smallest group
        let mut root: Vec<usize> = (0..ng).collect();
        fn find(root: &mut [usize], mut g: usize) -> usize {
            while root[g] != g {
                root[g] = root[root[g]];
                g = root[g];
            }
            g
        }
        let mut hinted = vec![false; ng];
        let mut hint_unit = vec![usize::MAX; hints.len()];
        let mut seen = vec![usize::MAX; ng];
        for (i, &(p, line)) in hints.iter().enumerate() {
            let mut stack: Vec<usize> = [Some(p), line.map(|l| l.0), line.map(|l| l.1)]
                .into_iter()
                .flatten()
                .map(|q| group_of[carrier[q].0])
                .filter(|&g| g != usize::MAX)
                .collect();
            let mut cone = Vec::new();
            while let Some(g) = stack.pop() {
                if seen[g] == i {
                    continue;
                }
                seen[g] = i;
                cone.push(g);
                stack.extend(upstream[g].iter().copied());
            }
            if let Some(&first) = cone.first() {
                hint_unit[i] = first;
                for &g in &cone {
                    hinted[g] = true;
                    let (a, b) = (find(&mut root, first), find(&mut root, g));
                    root[a.max(b)] = a.min(b);
                }
            }
        }
        if self.has_general {
            // one set of starting guesses for every Newton group: one unit
            for (g, h) in hinted.iter_mut().enumerate() {
                *h = true;
                let (a, b) = (find(&mut root, 0), find(&mut root, g));
                root[a.max(b)] = a.min(b);
            }
        }
        let mut units: Vec<AssemblyUnit> = Vec::new();
        let mut unit_of_root = vec![usize::MAX; ng];
        for g in (0..ng).filter(|&g| hinted[g]) {
            let r = find(&mut root, g);
            if unit_of_root[r] == usize::MAX {
                unit_of_root[r] = units.len();
                units.push(AssemblyUnit::default());
            }
            units[unit_of_root[r]].groups.push(g);
        }
        for (i, &g) in hint_unit.iter().enumerate() {
            if g != usize::MAX {
                let r = find(&mut root, g);
                units[unit_of_root[r]].hints.push(i);
            }
        }
        for g in (0..ng).filter(|&g| !hinted[g]) {
            units.push(AssemblyUnit {
                groups: vec![g],
                hints: Vec::new(),
            });
        }
        units
    }

    /// Choose the branches of one unit: every combination of its dyads'
    /// branches (and every start of its Newton groups) is assembled with the
    /// groups chosen before kept; the best score of the unit's hints wins, the
    /// first found among equal ones; `sol` is left holding it.
    fn choose_unit(
        &mut self,
        def: &MechanismDef,
        resolved: &[(usize, Option<(usize, usize)>)],
        carrier: &[(usize, Vec2)],
        unit: &AssemblyUnit,
        sol: &mut Solution,
    ) -> Result<(), LinkageError> {
        let branchy: Vec<usize> = unit
            .groups
            .iter()
            .copied()
            .filter(|&g| self.groups[g].dyad().is_some_and(|d| d.has_branches()))
            .collect();
        if branchy.len() > MAX_COUPLED {
            let labels: Vec<String> = branchy.iter().map(|&g| self.groups[g].label()).collect();
            let h: Vec<String> = unit.hints.iter().map(|&i| def.hints[i].to_string()).collect();
            return Err(LinkageError::desc(
                "assembly",
                format!(
                    "choosing the assembly would try the 2^{} branch combinations of the dyads {} together (at most 2^{MAX_COUPLED} are tried){}; give each dyad a hint on its own points (e.g. \"C above BD\" for the dyad BCD), so that each is chosen alone",
                    branchy.len(),
                    labels.join(", "),
                    if h.is_empty() {
                        String::new()
                    } else {
                        format!(", because the hints ({}) depend on all of them", h.join("; "))
                    }
                ),
            ));
        }
        let phi = self.assembly_angle;
        let starts = if self.has_general { 48 } else { 1 };
        let tol = 1e-6 * self.scale;
        let tie_tol = 1e-9 * self.scale;
        // the best so far: (score, combination·starts + start, links, point
        // positions, the order found)
        #[allow(clippy::type_complexity)]
        let mut best: Option<(f64, usize, Vec<LinkState>, Vec<Vec2>, usize)> = None;
        // assemblies as good as the best but elsewhere, in the order found
        let mut ties: Vec<(usize, f64, Vec<Vec2>)> = Vec::new();
        let mut first_err = None;
        let mut order = 0usize;
        for combo in 0..(1usize << branchy.len()) {
            for (k, &g) in branchy.iter().enumerate() {
                self.groups[g].sign = if combo >> k & 1 == 0 { 1.0 } else { -1.0 };
            }
            for start in 0..starts {
                let mut fresh;
                let s = if self.has_general {
                    fresh = self.solution();
                    self.seed_general(start, def, &mut fresh);
                    &mut fresh
                } else {
                    &mut *sol
                };
                match self.solve_groups(phi, &unit.groups, s) {
                    Ok(()) => {
                        let score = self.score(def, resolved, carrier, &unit.hints, s)?;
                        let pts: Vec<Vec2> = s.points.iter().map(|p| p.p).collect();
                        order += 1;
                        match &best {
                            Some(b) if score.total_cmp(&b.0).is_ge() => {
                                if !def.hints.is_empty() && ties.len() < 64 && (score - b.0).abs() <= tie_tol && differs(&pts, &b.3, tol) {
                                    ties.push((order, score, pts));
                                }
                            }
                            _ => {
                                if let Some(b) = best.take() {
                                    if !def.hints.is_empty() {
                                        ties.push((b.4, b.0, b.3));
                                    }
                                }
                                ties.retain(|t| (t.1 - score).abs() <= tie_tol);
                                let links = s.links.clone();
                                best = Some((score, combo * starts + start, links, pts, order));
                            }
                        }
                        if def.hints.is_empty() && best.is_some() {
                            break;
                        }
                    }
                    Err(e) => {
                        if first_err.is_none() {
                            first_err = Some(e);
                        }
                    }
                }
            }
            if def.hints.is_empty() && best.is_some() {
                break;
            }
        }
        let Some((score, pick, links, pts, _)) = best else {
            return Err(first_err.unwrap_or_else(|| LinkageError::Structure("no assembly found".into())));
        };
        if score >= VIOLATION * self.scale {
            return Err(self.unsatisfied(def));
        }
        if !def.hints.is_empty() {
            ties.sort_by_key(|t| t.0);
            if let Some(t) = ties.iter().find(|t| (t.1 - score).abs() <= tie_tol && differs(&t.2, &pts, tol)) {
                let differ: Vec<String> =
                    t.2.iter()
                        .zip(&pts)
                        .enumerate()
                        .filter(|(i, (p, q))| self.points[*i].link != 0 && (**p - **q).hypot() > tol)
                        .map(|(i, (p, q))| {
                            format!(
                                "{} at ({:.6}, {:.6}) m or ({:.6}, {:.6}) m",
                                self.points[i].name, q.x, q.y, p.x, p.y
                            )
                        })
                        .collect();
                let h: Vec<String> = def.hints.iter().map(|h| h.to_string()).collect();
                return Err(LinkageError::desc(
                    "assembly",
                    format!(
                        "the hints ({}) do not choose one assembly at {}: two assemblies satisfy them equally well ({}); add a hint that tells them apart, e.g. on the side of a line",
                        h.join("; "),
                        self.at_text(phi),
                        differ.join("; ")
                    ),
                ));
            }
        }
        let combo = pick / starts;
        for (k, &g) in branchy.iter().enumerate() {
            self.groups[g].sign = if combo >> k & 1 == 0 { 1.0 } else { -1.0 };
        }
        for &g in &unit.groups {
            for &l in &self.groups[g].info.link_ids {
                sol.links[l] = links[l];
            }
        }
        for (p, q) in sol.points.iter_mut().zip(&pts) {
            p.p = *q;
        }
        Ok(())
    }

    /// The error of hints that no assembly satisfies.
    fn unsatisfied(&self, def: &MechanismDef) -> LinkageError {
        let h: Vec<String> = def.hints.iter().map(|h| h.to_string()).collect();
        LinkageError::desc(
            "assembly",
            format!(
                "no assembly at {} satisfies every hint ({})",
                self.at_text(self.assembly_angle),
                h.join("; ")
            ),
        )
    }

    /// Solve the crank and the listed groups (in solving order; the others
    /// keep their links in `sol`) at crank angle `phi`, then every point.
    fn solve_groups(&self, phi: f64, groups: &[usize], sol: &mut Solution) -> Result<(), LinkageError> {
        sol.phi = phi;
        let c = &self.crank;
        sol.links[c.link] = match &self.drive {
            Some(d) => d.state(phi),
            None => {
                let (s, co) = phi.sin_cos();
                let u = crate::state::unrotate(Vec2::new(co, s), c.dir_local);
                let piv = PointState {
                    p: c.pivot,
                    v: Vec2::ZERO,
                    a: Vec2::ZERO,
                };
                LinkState::from_point(&piv, c.pivot_local, u, c.omega, c.eps)
            }
        };
        for &gi in groups {
            let g = &self.groups[gi];
            match &g.solver {
                Solver::Dyad(dy) => dy.solve(g.sign, &mut sol.links).map_err(|e| self.fail(g, phi, e))?,
                Solver::General => self.solve_general(g, sol).map_err(|e| self.fail(g, phi, e))?,
            }
        }
        let links = &sol.links;
        for &(i, l) in &self.origin_points {
            let l = &links[l];
            sol.points[i] = PointState { p: l.o, v: l.v, a: l.a };
        }
        for &(i, l, local) in &self.offset_points {
            sol.points[i] = links[l].point(local);
        }
        let mut sum = 0.0;
        for l in links {
            sum += (l.a.x + l.a.y) + l.eps;
        }
        if !sum.is_finite() {
            return Err(LinkageError::NonFinite {
                phi_deg: phi.to_degrees(),
                what: "the positions, velocities or accelerations".into(),
            });
        }
        Ok(())
    }

    /// Score an assembly by the listed hints (each point taken on its
    /// `carrier`, the link that places it first): [`VIOLATION`]·size per violated
    /// side hint, plus distances to `near`. A side hint about a line with no
    /// such side (a vertical line for above/below, a horizontal one for
    /// left/right) is an error.
    fn score(
        &self,
        def: &MechanismDef,
        resolved: &[(usize, Option<(usize, usize)>)],
        carrier: &[(usize, Vec2)],
        which: &[usize],
        sol: &Solution,
    ) -> Result<f64, LinkageError> {
        // on the link that places the point first (the frame's points as given)
        let pos = |i: usize| {
            let (l, local) = carrier[i];
            if l == 0 { local } else { sol.links[l].point(local).p }
        };
        let mut s = 0.0;
        for &i in which {
            let h = &def.hints[i];
            let (pi, line) = resolved[i];
            let p = pos(pi);
            let ok = match &h.kind {
                HintKind::Above(a, b) | HintKind::Below(a, b) | HintKind::LeftOf(a, b) | HintKind::RightOf(a, b) => {
                    let (ia, ib) = line.unwrap_or((pi, pi));
                    let (pa, pb) = (pos(ia), pos(ib));
                    let d = pb - pa;
                    let len = d.hypot();
                    let vertical = matches!(h.kind, HintKind::Above(..) | HintKind::Below(..));
                    // the component that must not vanish: dx for above/below, dy for left/right
                    let along = if vertical { d.x } else { d.y };
                    if along.abs() <= 1e-9 * len || len == 0.0 {
                        return Err(LinkageError::desc(
                            format!("assembly[{i}]"),
                            format!(
                                "`{h}`: at {} the line {a}–{b} is {}, so it has no {}; use {}",
                                self.at_text(self.assembly_angle),
                                if len == 0.0 {
                                    "not a line (the points coincide)"
                                } else if vertical {
                                    "vertical"
                                } else {
                                    "horizontal"
                                },
                                if vertical {
                                    "\"above\" or \"below\""
                                } else {
                                    "\"left\" or \"right\""
                                },
                                if vertical {
                                    "\"left of\" or \"right of\""
                                } else {
                                    "\"above\" or \"below\""
                                }
                            ),
                        ));
                    }
                    // the side of P: cross(d, P − A) > 0 is to the left of A→B;
                    // "above" is that side when B is to the right of A
                    let c = tmm_geom::cross(d, p - pa);
                    match h.kind {
                        HintKind::Above(..) => c * d.x.signum() > 0.0,
                        HintKind::Below(..) => c * d.x.signum() < 0.0,
                        HintKind::LeftOf(..) => c * d.y.signum() > 0.0,
                        _ => c * d.y.signum() < 0.0,
                    }
                }
                HintKind::Near(q) => {
                    s += (p - *q).hypot();
                    true
                }
            };
            if !ok {
                s += VIOLATION * self.scale;
            }
        }
        Ok(s)
    }

    /// Starting guesses for Newton groups: a `near` hint places its point; other
    /// links get pseudo-random orientations about the known joints.
    fn seed_general(&self, start: usize, def: &MechanismDef, sol: &mut Solution) {
        let mut rng = 0x9E37_79B9_7F4A_7C15u64 ^ (start as u64).wrapping_mul(0x2545_F491_4F6C_DD1D);
        let mut next = || {
            rng ^= rng << 13;
            rng ^= rng >> 7;
            rng ^= rng << 17;
            (rng >> 11) as f64 / (1u64 << 53) as f64
        };
        let centre = self
            .points
            .iter()
            .filter(|p| p.link == 0)
            .map(|p| p.local)
            .fold(Vec2::ZERO, |a, b| a + b)
            * (1.0 / self.points.iter().filter(|p| p.link == 0).count().max(1) as f64);
        for g in &self.groups {
            if g.solver != Solver::General {
                continue;
            }
            for &l in &g.info.link_ids {
                let th = 2.0 * PI * next();
                let u = polar(th);
                let mut o = centre + Vec2::new(next() - 0.5, next() - 0.5) * self.scale;
                for h in &def.hints {
                    if let HintKind::Near(q) = h.kind {
                        if let Some(pi) = self.point(&h.point) {
                            if self.points[pi].link == l && start % 2 == 0 {
                                o = q - rot(u, self.points[pi].local);
                            }
                        }
                    }
                }
                sol.links[l] = LinkState {
                    o,
                    u,
                    ..Default::default()
                };
            }
        }
    }

    /// Rank of the constraint equations at the assembly: the true DOF,
    /// redundant constraints and passive freedoms.
    fn count_rank(&mut self) -> Result<(), LinkageError> {
        let rc = crate::whole::rank_count(
            &self.pairs,
            self.link_names.len(),
            self.crank.link,
            held_row(&self.drive),
            &self.init,
            self.scale,
        );
        let s = &mut self.structure;
        s.dof_rank = rc.dof;
        s.redundant = rc.redundant;
        s.passive = rc.passive;
        if s.dof_rank != 1 {
            return Err(LinkageError::Mobility {
                dof: s.dof_rank,
                w: s.dof,
                n: s.n,
                p5: s.p5,
                p4: s.p4,
                detail: String::new(),
            });
        }
        Ok(())
    }
}

/// The size of a described mechanism, m: the largest distance between two
/// points of one link, between two fixed points, or between a fixed point and
/// a frame guide's point. Scaling every coordinate by k scales it by k.
fn mechanism_size(def: &MechanismDef) -> f64 {
    let mut size = 0.0f64;
    for l in &def.links {
        for (i, (_, p)) in l.points.iter().enumerate() {
            for (_, q) in &l.points[..i] {
                size = size.max((*p - *q).hypot());
            }
        }
    }
    let mut frame: Vec<Vec2> = def.fixed.iter().map(|(_, p)| *p).collect();
    frame.extend(def.sliders.iter().filter(|s| s.guide_link == FRAME).map(|s| s.through));
    for (i, p) in frame.iter().enumerate() {
        for q in &frame[..i] {
            size = size.max((*p - *q).hypot());
        }
    }
    size
}

/// The size every tolerance is relative to: [`mechanism_size`], at least
/// the crank radius.
fn scale_of(def: &MechanismDef, radius: f64) -> f64 {
    mechanism_size(def).max(radius)
}

/// The default output link: in the last group, a link with a pair to the frame;
/// else the last link of the last group.
fn default_output(groups: &[Group], pairs: &[Pair], crank: usize) -> usize {
    let Some(g) = groups.last() else { return crank };
    for &l in g.info.link_ids.iter().rev() {
        if pairs.iter().any(|p| p.links() == (l, 0) || p.links() == (0, l)) {
            return l;
        }
    }
    *g.info.link_ids.last().unwrap_or(&crank)
}

/// Build the closed-form solver of a dyad from its ordered links and pairs
/// (outer 1, inner, outer 2).
fn build_dyad(set: &[usize], pids: &[usize], pairs: &[Pair]) -> Result<DyadGeom, LinkageError> {
    let (l1, l2) = (set[0], set[1]);
    let (e1, m, e2) = (&pairs[pids[0]], &pairs[pids[1]], &pairs[pids[2]]);
    // local of a revolute pair's point on link `l`, and the known side
    let r_on = |p: &Pair, l: usize| -> (Vec2, KnownPoint) {
        match *p {
            Pair::R { a, b, la, lb, .. } => {
                if a == l {
                    (la, KnownPoint { link: b, local: lb })
                } else {
                    (lb, KnownPoint { link: a, local: la })
                }
            }
            Pair::P { .. } => unreachable!("revolute expected"),
        }
    };
    let r_both = |p: &Pair, x: usize| -> Vec2 {
        match *p {
            Pair::R { a, la, lb, .. } => {
                if a == x {
                    la
                } else {
                    lb
                }
            }
            Pair::P { .. } => unreachable!("revolute expected"),
        }
    };
    let kind: String = [e1.kind(), m.kind(), e2.kind()]
        .iter()
        .map(|k| if *k == PairKind::R { 'R' } else { 'P' })
        .collect();
    let bad = |why: &str| LinkageError::Structure(format!("dyad of links {l1}, {l2} ({kind}): {why}"));
    match kind.as_str() {
        "RRR" => {
            let (a1, a) = r_on(e1, l1);
            let (c2, c) = r_on(e2, l2);
            let b1 = r_both(m, l1);
            let b2 = r_both(m, l2);
            let len1 = (b1 - a1).hypot();
            let len2 = (b2 - c2).hypot();
            if len1 <= 1e-12 || len2 <= 1e-12 {
                return Err(bad("zero link length"));
            }
            Ok(DyadGeom::Rrr {
                l1,
                l2,
                a,
                a1,
                dir1: unit(b1 - a1),
                len1,
                c,
                c2,
                dir2: unit(b2 - c2),
                len2,
                inv: (1.0 / len1, 1.0 / len2, len1 * len1 - len2 * len2),
            })
        }
        "RRP" => {
            let (a1, a) = r_on(e1, l1);
            let b1 = r_both(m, l1);
            let b2 = r_both(m, l2);
            let Pair::P {
                slider,
                guide,
                ps,
                q,
                d,
                rel,
                ..
            } = *e2
            else {
                return Err(bad("prismatic pair expected"));
            };
            if slider != l2 {
                return Err(bad("the outer guide must carry the slider of the group, not be carried by it"));
            }
            let len1 = (b1 - a1).hypot();
            if len1 <= 1e-12 {
                return Err(bad("zero link length"));
            }
            Ok(DyadGeom::Rrp {
                l1,
                l2,
                a,
                a1,
                dir1: unit(b1 - a1),
                len1,
                b_off: b2 - ps,
                b2,
                guide: KnownGuide {
                    link: guide,
                    through: q,
                    dir: d,
                },
                rel,
            })
        }
        "RPR" => {
            let Pair::P {
                slider,
                guide,
                ps,
                q,
                d,
                rel,
                ..
            } = *m
            else {
                return Err(bad("prismatic pair expected"));
            };
            let (g, s) = (guide, slider);
            let (eg, es) = if r_on_link(e1, g) { (e1, e2) } else { (e2, e1) };
            let (xg, x) = r_on(eg, g);
            let (ys, y) = r_on(es, s);
            Ok(DyadGeom::Rpr {
                g,
                s,
                x,
                xg,
                y,
                ys,
                w: q + rot(rel, ys - ps),
                dir: d,
                rel,
            })
        }
        "PRP" => {
            let (
                Pair::P {
                    slider: s1,
                    guide: k1,
                    ps: p1,
                    q: q1,
                    d: d1,
                    rel: rel1,
                    ..
                },
                Pair::P {
                    slider: s2,
                    guide: k2,
                    ps: p2,
                    q: q2,
                    d: d2,
                    rel: rel2,
                    ..
                },
            ) = (e1.clone(), e2.clone())
            else {
                return Err(bad("prismatic pairs expected"));
            };
            if s1 != l1 || s2 != l2 {
                return Err(bad("each outer guide must carry a slider of the group"));
            }
            let b1 = r_both(m, l1);
            let b2 = r_both(m, l2);
            Ok(DyadGeom::Prp {
                l1,
                l2,
                g1: KnownGuide {
                    link: k1,
                    through: q1,
                    dir: d1,
                },
                rel1,
                off1: b1 - p1,
                b1,
                g2: KnownGuide {
                    link: k2,
                    through: q2,
                    dir: d2,
                },
                rel2,
                off2: b2 - p2,
                b2,
            })
        }
        "RPP" => {
            let (a1, a) = r_on(e1, l1);
            let Pair::P {
                slider: so,
                guide: ko,
                ps: p2,
                q,
                d,
                rel: rel2,
                ..
            } = *e2
            else {
                return Err(bad("prismatic pair expected"));
            };
            if so != l2 {
                return Err(bad("the outer guide must carry the slider of the group"));
            }
            let Pair::P {
                slider: sm,
                ps: pm,
                q: qm,
                d: dm,
                rel: relm_raw,
                ..
            } = *m
            else {
                return Err(bad("prismatic pair expected"));
            };
            let guide_on_l2 = sm == l1;
            // u_slider = u_guide·rel ⇒ u1 = u2·rel (guide on l2) or u1 = u2·conj(rel)
            let relm = if guide_on_l2 { relm_raw } else { conj(relm_raw) };
            Ok(DyadGeom::Rpp {
                l1,
                l2,
                a,
                a1,
                guide: KnownGuide {
                    link: ko,
                    through: q,
                    dir: d,
                },
                rel2,
                p2,
                relm,
                qm,
                dm,
                pm,
                guide_on_l2,
            })
        }
        _ => Err(bad("not a dyad kind (RRR, RRP, RPR, PRP, RPP)")),
    }
}

fn r_on_link(p: &Pair, l: usize) -> bool {
    matches!(*p, Pair::R { a, b, .. } if a == l || b == l)
}

/// The unit vector perpendicular to `v` (for callers drawing plans).
pub fn normal(v: Vec2) -> Vec2 {
    unit(perp(v))
}
