//! Reading the `[forces]` section of a task file into the core's [`Loads`]:
//! masses (kg, or kg per metre of link), moments of inertia (kg·m², or
//! J_S = k·m·l²), gravity, external forces at points and moments on links, the
//! useful resistance and its law, and the link to size for strength.
//!
//! ```toml
//! [forces]
//! mass_per_length = "10 kg/m"   # every link m = q·l unless given
//! k = 0.1                       # J_S = k·m·l² unless given
//! gravity = "9.81 m/s^2"        # absent: weight neglected; direction −y unless gravity_angle
//! at = "15 deg"                 # the position shown in detail (default: linkage.at)
//! crank_motion = "constant"     # or "dynamics": the true ω1(φ), ε1(φ) of [dynamics]
//! [forces.links.5]
//! mass = "19.5 kg"
//! [[forces.resistance]]
//! link = "3"
//! moment = "380 N m"            # or force = "3 kN" with point and (optionally) angle
//! law = "constant"              # constant | working | sine | table
//! [forces.strength]
//! link = "2"
//! allowed_stress = "120 MPa"
//! h_over_b = 2
//! ```

use std::collections::BTreeMap;
use std::ops::Range;

use serde::Deserialize;
use tmm_geom::Vec2;
use tmm_geom::units::Dim;
use tmm_linkage::forces::loads::{inertia_k, link_length, mass_per_length};
use tmm_linkage::forces::resistance::direction;
use tmm_linkage::forces::{Action, Law, Loads, PointForce, Resistance};
use tmm_linkage::{Mechanism, MechanismDef};

use crate::task::{Qty, RawQty, qty};
use crate::{Error, TaskSource};

type S<T> = toml::Spanned<T>;

#[derive(Deserialize)]
struct File {
    forces: Option<S<ForcesSec>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ForcesSec {
    mass_per_length: Option<Qty>,
    k: Option<Qty>,
    gravity: Option<Qty>,
    gravity_angle: Option<Qty>,
    at: Option<Qty>,
    crank_motion: Option<S<String>>,
    links: Option<BTreeMap<String, S<LinkSec>>>,
    resistance: Option<Vec<S<ResistSec>>>,
    strength: Option<S<StrengthSec>>,
    cycle: Option<S<super::slider_task::CycleSec>>,
    cylinders: Option<Vec<S<super::slider_task::CylinderSec>>>,
    stroke_forces: Option<Vec<S<super::slider_task::StrokeForceSec>>>,
    friction: Option<Vec<S<super::slider_task::FrictionSec>>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct LinkSec {
    mass: Option<Qty>,
    mass_per_length: Option<Qty>,
    inertia: Option<Qty>,
    k: Option<Qty>,
    moment: Option<Qty>,
    forces: Option<Vec<S<ForceSec>>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ForceSec {
    point: S<String>,
    force: Option<S<Vec<Qty>>>,
    value: Option<Qty>,
    angle: Option<Qty>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ResistSec {
    link: S<String>,
    force: Option<Qty>,
    moment: Option<Qty>,
    point: Option<S<String>>,
    angle: Option<Qty>,
    direction: Option<S<String>>,
    law: Option<S<String>>,
    over: Option<S<String>>,
    table: Option<S<Vec<Vec<RawQty>>>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct StrengthSec {
    link: S<String>,
    between: Option<S<Vec<String>>>,
    allowed_stress: Qty,
    h_over_b: Option<Qty>,
}

/// The link to size for strength.
#[derive(Debug, Clone)]
pub struct Strength {
    /// The link.
    pub link: usize,
    /// The beam's axis: two local points and their names.
    pub axis: (Vec2, Vec2),
    /// Names of the two axis points.
    pub names: (String, String),
    /// Allowed stress [σ], Pa.
    pub allowed: f64,
    /// h/b of the rectangle.
    pub k: f64,
}

/// How the crank moves in the kinetostatics.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CrankMotion {
    /// At the constant input speed of `[linkage]`, ε₁ = 0 (the default).
    Constant,
    /// With the true ω₁(φ), ε₁(φ) of the machine with its flywheel, from the
    /// `[dynamics]` section.
    Dynamics,
}

/// The `[forces]` section, read and checked against the mechanism.
#[derive(Debug, Clone)]
pub struct ForcesTask {
    /// How the crank moves.
    pub crank_motion: CrankMotion,
    /// Span of `crank_motion`, when given.
    pub crank_motion_span: Option<Range<usize>>,
    /// The loads for the core.
    pub loads: Loads,
    /// The crank angle shown in detail, rad (absolute), if given.
    pub at: Option<f64>,
    /// Strength of a link, if asked.
    pub strength: Option<Strength>,
    /// Spans of fields, to locate core errors (`links.2.mass`, `resistance[0]`).
    pub spans: BTreeMap<String, Range<usize>>,
    /// Span of the whole section.
    pub section: Range<usize>,
    /// The task's name of each slider load (`cylinders[0]`,
    /// `stroke_forces[0]`, `friction[0]`), as [`Loads::sliders`].
    pub slider_fields: Vec<String>,
    /// The reactions over the whole cycle, when asked (`[forces.cycle] step`).
    pub reaction_cycle: Option<super::slider_task::ReactionCycleSpec>,
}

fn link_index(task: &TaskSource, m: &Mechanism, field: &str, name: &S<String>) -> Result<usize, Error> {
    match m.link(name.get_ref()) {
        Some(0) => Err(Error::at(
            task,
            name.span(),
            field,
            "the frame carries no loads here; name a moving link",
        )),
        Some(i) => Ok(i),
        None => Err(Error::at(task, name.span(), field, format!("unknown link `{}`", name.get_ref()))
            .with_help(format!("the links are {}", m.link_names[1..].join(", ")))),
    }
}

/// Local coordinates of a point on a link: a named point of the link, or `S`
/// (its centre of mass).
fn point_on(task: &TaskSource, def: &MechanismDef, m: &Mechanism, link: usize, field: &str, name: &S<String>) -> Result<Vec2, Error> {
    let n = name.get_ref();
    if n == "S" {
        return Ok(m.mass_centers[link]);
    }
    let ld = &def.links[link - 1];
    ld.point(n).ok_or_else(|| {
        let names: Vec<&str> = ld.points.iter().map(|p| p.0.as_str()).collect();
        Error::at(task, name.span(), field, format!("unknown point `{n}` on link `{}`", ld.name)).with_help(format!(
            "the points of link `{}` are {} and S (its centre of mass)",
            ld.name,
            names.join(", ")
        ))
    })
}

fn nonneg(task: &TaskSource, field: &str, q: &Qty, dim: Dim) -> Result<f64, Error> {
    let v = qty(task, field, q, dim)?;
    if v < 0.0 {
        return Err(Error::at(task, q.span(), field, format!("must be ≥ 0, not {v}")).with_help(format!("e.g. {}", dim.example())));
    }
    Ok(v)
}

/// Read the `[forces]` section for a compiled mechanism; `None` when the file has none.
pub fn read(task: &TaskSource, def: &MechanismDef, m: &Mechanism) -> Result<Option<ForcesTask>, Error> {
    let f: File = task.parse("forces")?;
    let Some(sec) = f.forces else { return Ok(None) };
    let section = sec.span();
    let sec = sec.into_inner();
    let mut spans = BTreeMap::new();
    let mut loads = Loads::new(m);
    let q_all = match &sec.mass_per_length {
        Some(q) => Some(nonneg(task, "forces.mass_per_length", q, Dim::LinearDensity)?),
        None => None,
    };
    let k_all = match &sec.k {
        Some(q) => nonneg(task, "forces.k", q, Dim::Ratio)?,
        None => 0.1,
    };
    if let Some(g) = &sec.gravity {
        let gv = nonneg(task, "forces.gravity", g, Dim::Acceleration)?;
        let ang = match &sec.gravity_angle {
            Some(a) => qty(task, "forces.gravity_angle", a, Dim::Angle)?,
            None => -std::f64::consts::FRAC_PI_2,
        };
        loads.gravity = direction(ang) * gv;
    } else if let Some(a) = &sec.gravity_angle {
        return Err(
            Error::at(task, a.span(), "forces.gravity_angle", "gravity_angle without gravity").with_help("add gravity = \"9.81 m/s^2\"")
        );
    }
    let at = match &sec.at {
        Some(a) => Some(qty(task, "forces.at", a, Dim::Angle)?),
        None => None,
    };
    let crank_motion = match sec.crank_motion.as_ref().map(|c| (c.get_ref().as_str(), c.span())) {
        None | Some(("constant", _)) => CrankMotion::Constant,
        Some(("dynamics", sp)) => {
            if !crate::dynamics::task::present(task)? {
                return Err(Error::at(
                    task,
                    sp,
                    "forces.crank_motion",
                    "crank_motion = \"dynamics\" takes the true ω1, ε1 from the dynamics of the machine, and the task has no [dynamics] section",
                )
                .with_help("add [dynamics] with delta = 0.02 (the coefficient of speed fluctuation), or say crank_motion = \"constant\""));
            }
            CrankMotion::Dynamics
        }
        Some((other, sp)) => {
            return Err(Error::at(task, sp, "forces.crank_motion", format!("unknown crank motion `{other}`")).with_help(
                "crank_motion = \"constant\" (the [linkage] input speed, ε1 = 0; the default) or \"dynamics\" (the true ω1(φ), ε1(φ) with the flywheel of [dynamics])",
            ));
        }
    };
    // defaults for every moving link
    for l in 1..m.link_names.len() {
        let len = link_length(m, l);
        let mass = q_all.map_or(0.0, |q| mass_per_length(q, len));
        loads.links[l].mass = mass;
        loads.links[l].inertia = inertia_k(k_all, mass, len);
    }
    if let Some(links) = &sec.links {
        for (name, ls) in links {
            let field = format!("forces.links.{name}");
            let li = link_index(task, m, &field, &S::new(ls.span(), name.clone()))?;
            spans.insert(format!("links.{name}"), ls.span());
            let ls = ls.get_ref();
            let len = link_length(m, li);
            let mass = match (&ls.mass, &ls.mass_per_length) {
                (Some(a), Some(_)) => {
                    return Err(Error::at(
                        task,
                        a.span(),
                        &format!("{field}.mass"),
                        "give mass or mass_per_length, not both",
                    ));
                }
                (Some(a), None) => nonneg(task, &format!("{field}.mass"), a, Dim::Mass)?,
                (None, Some(q)) => mass_per_length(nonneg(task, &format!("{field}.mass_per_length"), q, Dim::LinearDensity)?, len),
                (None, None) => loads.links[li].mass,
            };
            let inertia = match (&ls.inertia, &ls.k) {
                (Some(a), Some(_)) => {
                    return Err(Error::at(
                        task,
                        a.span(),
                        &format!("{field}.inertia"),
                        "give inertia or k, not both",
                    ));
                }
                (Some(a), None) => nonneg(task, &format!("{field}.inertia"), a, Dim::Inertia)?,
                (None, Some(k)) => inertia_k(nonneg(task, &format!("{field}.k"), k, Dim::Ratio)?, mass, len),
                (None, None) => inertia_k(k_all, mass, len),
            };
            loads.links[li].mass = mass;
            loads.links[li].inertia = inertia;
            if let Some(mo) = &ls.moment {
                loads.links[li].moment = qty(task, &format!("{field}.moment"), mo, Dim::Moment)?;
            }
            for (k, fs) in ls.forces.iter().flatten().enumerate() {
                let ff = format!("{field}.forces[{k}]");
                let fsr = fs.get_ref();
                let local = point_on(task, def, m, li, &format!("{ff}.point"), &fsr.point)?;
                let force = match (&fsr.force, &fsr.value, &fsr.angle) {
                    (Some(v), None, None) => {
                        let r = v.get_ref();
                        if r.len() != 2 {
                            return Err(Error::at(
                                task,
                                v.span(),
                                &format!("{ff}.force"),
                                format!("expected two components [Fx, Fy], found {}", r.len()),
                            )
                            .with_help("force = [\"100 N\", \"-50 N\"]"));
                        }
                        Vec2::new(
                            qty(task, &format!("{ff}.force[0]"), &r[0], Dim::Force)?,
                            qty(task, &format!("{ff}.force[1]"), &r[1], Dim::Force)?,
                        )
                    }
                    (None, Some(v), Some(a)) => {
                        direction(qty(task, &format!("{ff}.angle"), a, Dim::Angle)?) * qty(task, &format!("{ff}.value"), v, Dim::Force)?
                    }
                    _ => {
                        return Err(Error::at(task, fs.span(), &ff, "give either force = [Fx, Fy] or value with angle")
                            .with_help("{ point = \"C\", value = \"100 N\", angle = \"-90 deg\" }"));
                    }
                };
                loads.links[li].forces.push(PointForce { local, force });
            }
        }
    }
    for (k, rs) in sec.resistance.iter().flatten().enumerate() {
        let field = format!("forces.resistance[{k}]");
        spans.insert(format!("resistance[{k}]"), rs.span());
        if let Some(t) = &rs.get_ref().table {
            spans.insert(format!("resistance[{k}].table"), t.span());
        }
        loads.resistance.push(resistance(task, def, m, &field, rs)?);
    }
    let strength = match &sec.strength {
        Some(s) => Some(strength(task, def, m, s)?),
        None => None,
    };
    let (cyl, strk, fric) = (
        sec.cylinders.as_deref().unwrap_or_default(),
        sec.stroke_forces.as_deref().unwrap_or_default(),
        sec.friction.as_deref().unwrap_or_default(),
    );
    super::slider_task::read(
        task,
        m,
        sec.cycle.as_ref(),
        cyl,
        strk,
        fric,
        &mut loads.cycle,
        &mut loads.sliders,
        &mut spans,
    )?;
    let reaction_cycle = super::slider_task::reaction_cycle(task, sec.cycle.as_ref(), loads.cycle.turns)?;
    let slider_fields = (0..cyl.len())
        .map(|k| format!("cylinders[{k}]"))
        .chain((0..strk.len()).map(|k| format!("stroke_forces[{k}]")))
        .chain((0..fric.len()).map(|k| format!("friction[{k}]")))
        .collect();
    Ok(Some(ForcesTask {
        crank_motion,
        crank_motion_span: sec.crank_motion.as_ref().map(|c| c.span()),
        loads,
        at,
        strength,
        spans,
        section,
        slider_fields,
        reaction_cycle,
    }))
}

fn resistance(task: &TaskSource, def: &MechanismDef, m: &Mechanism, field: &str, rs: &S<ResistSec>) -> Result<Resistance, Error> {
    let r = rs.get_ref();
    let link = link_index(task, m, &format!("{field}.link"), &r.link)?;
    let (value, dim, action) = match (&r.force, &r.moment) {
        (Some(f), None) => {
            let local = match &r.point {
                Some(p) => point_on(task, def, m, link, &format!("{field}.point"), p)?,
                None => def.links[link - 1].points[0].1,
            };
            let dir = match (&r.angle, &r.direction) {
                (Some(a), None) => Some(direction(qty(task, &format!("{field}.angle"), a, Dim::Angle)?)),
                (None, None) => None,
                (None, Some(d)) if d.get_ref() == "opposes" => None,
                (_, Some(d)) => {
                    return Err(Error::at(
                        task,
                        d.span(),
                        &format!("{field}.direction"),
                        "for a force, give angle = \"…deg\" for a fixed direction, or direction = \"opposes\" (against the point's velocity, the default)",
                    ));
                }
            };
            (
                qty(task, &format!("{field}.force"), f, Dim::Force)?,
                Dim::Force,
                Action::Force { local, dir },
            )
        }
        (None, Some(mo)) => {
            let sign = match r.direction.as_ref().map(|d| (d.get_ref().as_str(), d.span())) {
                None | Some(("opposes", _)) => None,
                Some(("ccw", _)) => Some(1.0),
                Some(("cw", _)) => Some(-1.0),
                Some((_, sp)) => {
                    return Err(Error::at(
                        task,
                        sp,
                        &format!("{field}.direction"),
                        "expected \"opposes\" (against the link's rotation, the default), \"ccw\" or \"cw\"",
                    ));
                }
            };
            (
                qty(task, &format!("{field}.moment"), mo, Dim::Moment)?,
                Dim::Moment,
                Action::Moment { sign },
            )
        }
        _ => {
            return Err(Error::at(task, rs.span(), field, "give either force = \"…N\" or moment = \"…N·m\"")
                .with_help("[[forces.resistance]]\nlink = \"3\"\nmoment = \"380 N m\""));
        }
    };
    if value < 0.0 {
        return Err(Error::at(
            task,
            rs.span(),
            field,
            "the magnitude of the resistance must be ≥ 0; its sense is set by direction/angle",
        ));
    }
    let law_name = r.law.as_ref().map_or("constant", |l| l.get_ref().as_str());
    let law_span = r.law.as_ref().map_or(rs.span(), |l| l.span());
    let law = match law_name {
        "constant" => Law::Constant(value),
        "working" => Law::WorkingStroke(value),
        "sine" => Law::SineOfTravel(value),
        "table" => {
            let t = r.table.as_ref().ok_or_else(|| Error::at(task, law_span.clone(), &format!("{field}.table"), "law = \"table\" needs table = [[x, value], …]"))?;
            let over = r.over.as_ref().map_or("travel", |o| o.get_ref().as_str());
            let xdim = match over {
                "travel" => {
                    if resist_angular(m) {
                        Dim::Angle
                    } else {
                        Dim::Length
                    }
                }
                "crank" => Dim::Angle,
                _ => return Err(Error::at(task, r.over.as_ref().map_or(rs.span(), |o| o.span()), &format!("{field}.over"), "expected \"travel\" (of the output from the start of the working stroke) or \"crank\" (crank angle from the start of the working stroke)")),
            };
            let mut pts = Vec::new();
            for (i, row) in t.get_ref().iter().enumerate() {
                let tf = format!("{field}.table[{i}]");
                if row.len() != 2 {
                    return Err(Error::at(task, t.span(), &tf, format!("expected a pair [x, value], found {} numbers", row.len())).with_help("table = [[\"0 mm\", \"0 N\"], [\"50 mm\", \"3 kN\"]]"));
                }
                let x = qty(task, &tf, &S::new(t.span(), row[0].clone()), xdim)?;
                let y = qty(task, &tf, &S::new(t.span(), row[1].clone()), dim)?;
                pts.push((x, y));
            }
            if over == "crank" { Law::AngleTable(pts) } else { Law::TravelTable(pts) }
        }
        other => return Err(Error::at(task, law_span, &format!("{field}.law"), format!("unknown law `{other}`")).with_help("law = \"constant\" | \"working\" (value on the working stroke, 0 on the return) | \"sine\" (value·sin(π·s/H) on the working stroke) | \"table\"")),
    };
    if !matches!(law, Law::TravelTable(_) | Law::AngleTable(_)) && r.table.is_some() {
        return Err(Error::at(
            task,
            r.table.as_ref().map_or(rs.span(), |t| t.span()),
            &format!("{field}.table"),
            "a table needs law = \"table\"",
        ));
    }
    Ok(Resistance { link, action, law })
}

/// `true` when the travel of the output is an angle (no slider on the frame).
fn resist_angular(m: &Mechanism) -> bool {
    !m.pairs
        .iter()
        .any(|p| matches!(*p, tmm_linkage::mechanism::Pair::P { slider, guide: 0, .. } if slider == m.output))
}

fn strength(task: &TaskSource, def: &MechanismDef, m: &Mechanism, s: &S<StrengthSec>) -> Result<Strength, Error> {
    let r = s.get_ref();
    let link = link_index(task, m, "forces.strength.link", &r.link)?;
    let ld = &def.links[link - 1];
    let (a, b, names) = match &r.between {
        Some(bw) => {
            let v = bw.get_ref();
            if v.len() != 2 {
                return Err(Error::at(
                    task,
                    bw.span(),
                    "forces.strength.between",
                    "expected two points of the link [\"B\", \"C\"]",
                ));
            }
            let pa = point_on(task, def, m, link, "forces.strength.between[0]", &S::new(bw.span(), v[0].clone()))?;
            let pb = point_on(task, def, m, link, "forces.strength.between[1]", &S::new(bw.span(), v[1].clone()))?;
            (pa, pb, (v[0].clone(), v[1].clone()))
        }
        None => {
            if ld.points.len() < 2 {
                return Err(Error::at(
                    task,
                    r.link.span(),
                    "forces.strength.link",
                    format!("link `{}` has one point: it is a slider block, not a bar", ld.name),
                ));
            }
            // the two points farthest apart
            let mut best = (0, 1, 0.0);
            for i in 0..ld.points.len() {
                for j in i + 1..ld.points.len() {
                    let d = (ld.points[i].1 - ld.points[j].1).hypot();
                    if d > best.2 {
                        best = (i, j, d);
                    }
                }
            }
            (
                ld.points[best.0].1,
                ld.points[best.1].1,
                (ld.points[best.0].0.clone(), ld.points[best.1].0.clone()),
            )
        }
    };
    if (a - b).hypot() <= 1e-12 {
        return Err(Error::at(task, s.span(), "forces.strength.between", "the two axis points coincide"));
    }
    let allowed = qty(task, "forces.strength.allowed_stress", &r.allowed_stress, Dim::Stress)?;
    if allowed <= 0.0 {
        return Err(
            Error::at(task, r.allowed_stress.span(), "forces.strength.allowed_stress", "must be > 0")
                .with_help("allowed_stress = \"120 MPa\" (steel St3)"),
        );
    }
    let k = match &r.h_over_b {
        Some(q) => qty(task, "forces.strength.h_over_b", q, Dim::Ratio)?,
        None => 2.0,
    };
    if k <= 0.0 {
        return Err(Error::at(
            task,
            r.h_over_b.as_ref().map_or(s.span(), |q| q.span()),
            "forces.strength.h_over_b",
            "must be > 0",
        ));
    }
    Ok(Strength {
        link,
        axis: (a, b),
        names,
        allowed,
        k,
    })
}
