//! A [`MechanismDef`] written as the `[linkage]` section of a task file
//! (описание механизма в файле задания), in the format that
//! [`crate::linkage::task::read`] reads (docs/linkage.md): fixed points,
//! links with their joints and further points, sliders with their guides,
//! the input crank, the assembly hints and angle, the output link.
//!
//! Every number is written in the shortest form that reads back to the same
//! `f64` (lengths in m); angles in degrees (read back to within one rounding
//! of π/180). A link whose second point is not on its local x-axis is written
//! in the task format's own local frame (origin at its first joint, x-axis
//! towards its second): its points, centre of mass and any guide it carries
//! are moved into that frame, which changes no global position.

use std::fmt::Write as _;

use tmm_geom::Vec2;
use tmm_linkage::{FRAME, HintKind, LinkDef, MechanismDef};

use crate::Error;

/// A TOML string literal (quoted and escaped).
fn s(text: &str) -> String {
    toml::Value::String(text.to_string()).to_string()
}

/// A length as a TOML value: a plain number (m) in the shortest form that
/// reads back to the same `f64` (`{:?}` writes `0.1`, `5.0`, `1e-5`, all valid
/// TOML floats).
fn len(x: f64) -> String {
    format!("{x:?}")
}

/// An angle as a TOML string in degrees.
fn deg(a: f64) -> String {
    format!("\"{:?} deg\"", a.to_degrees())
}

fn pair(p: Vec2) -> String {
    format!("[{}, {}]", len(p.x), len(p.y))
}

/// The frame of a link in the task format: origin at its first point, x-axis
/// towards its second. Returns (origin, unit direction) in the link's own
/// local coordinates.
fn task_frame(l: &LinkDef) -> (Vec2, Vec2) {
    let o = l.points.first().map_or(Vec2::ZERO, |p| p.1);
    let dir = match l.points.get(1) {
        Some((_, q)) if (*q - o).hypot() > 0.0 => (*q - o) * (1.0 / (*q - o).hypot()),
        _ => Vec2::new(1.0, 0.0),
    };
    (o, dir)
}

/// A local point moved into the task frame (o, u): R(−angle u)·(p − o).
fn to_frame(p: Vec2, o: Vec2, u: Vec2) -> Vec2 {
    let q = p - o;
    Vec2::new(u.x * q.x + u.y * q.y, -u.y * q.x + u.x * q.y)
}

fn check_name(what: &str, name: &str) -> Result<(), Error> {
    if name.is_empty() || name.chars().any(|c| c.is_whitespace() || c == '-' || c == ',') {
        return Err(Error::input(
            "synthesis",
            format!("the {what} name `{name}` cannot be written into a task file (no spaces, `-` or `,`)"),
        ));
    }
    Ok(())
}

/// Write `def` as a `[linkage]` section. `speed_note` is an optional comment
/// put after the input line (e.g. the speed as the user gave it).
///
/// ```
/// use tmm_linkage::{LinkDef, MechanismDef, InputDef};
/// use tmm_geom::Vec2;
/// let def = MechanismDef {
///     fixed: vec![("A".into(), Vec2::ZERO), ("D".into(), Vec2::new(0.51, 0.0))],
///     links: vec![LinkDef::bar("1", "A", "B", 0.12), LinkDef::bar("2", "B", "C", 0.48), LinkDef::bar("3", "D", "C", 0.38)],
///     input: Some(InputDef { link: "1".into(), pivot: "A".into(), pin: "B".into(), omega: 94.0, epsilon: 0.0 }),
///     ..Default::default()
/// };
/// let t = tmm_report::synthesis::linkage_toml(&def).unwrap();
/// assert!(t.starts_with("[linkage]\n"));
/// let back = tmm_report::linkage::task::read(&tmm_report::TaskSource::new("t.toml", t)).unwrap().unwrap();
/// assert_eq!(back.def.links[1].points[1].1.x, 0.48);
/// ```
pub fn linkage_toml(def: &MechanismDef) -> Result<String, Error> {
    let mut t = String::from("[linkage]\n");
    let fixed: Vec<String> = def
        .fixed
        .iter()
        .map(|(n, p)| {
            check_name("point", n)?;
            Ok(format!("{} = {}", s(n), pair(*p)))
        })
        .collect::<Result<_, Error>>()?;
    let _ = writeln!(t, "fixed = {{ {} }}", fixed.join(", "));
    let inp = def
        .input
        .as_ref()
        .ok_or_else(|| Error::input("synthesis", "the mechanism has no input crank"))?;
    let _ = write!(
        t,
        "input = {{ link = {}, pivot = {}, pin = {}, speed = \"{:?} rad/s\", direction = \"{}\"",
        s(&inp.link),
        s(&inp.pivot),
        s(&inp.pin),
        inp.omega.abs(),
        if inp.omega < 0.0 { "cw" } else { "ccw" }
    );
    if inp.epsilon != 0.0 {
        let _ = write!(t, ", epsilon = \"{:?} rad/s^2\"", inp.epsilon);
    }
    t.push_str(" }\n");
    if !def.hints.is_empty() {
        let hints: Vec<String> = def
            .hints
            .iter()
            .map(|h| {
                check_name("point", &h.point)?;
                let side = |w: &str, a: &str, b: &str| -> Result<String, Error> {
                    check_name("point", a)?;
                    check_name("point", b)?;
                    Ok(s(&format!("{} {w} {a}-{b}", h.point)))
                };
                match &h.kind {
                    HintKind::Above(a, b) => side("above", a, b),
                    HintKind::Below(a, b) => side("below", a, b),
                    HintKind::LeftOf(a, b) => side("left of", a, b),
                    HintKind::RightOf(a, b) => side("right of", a, b),
                    HintKind::Near(p) => Ok(format!("{{ point = {}, near = {} }}", s(&h.point), pair(*p))),
                }
            })
            .collect::<Result<_, Error>>()?;
        let _ = writeln!(t, "assembly = [{}]", hints.join(", "));
    }
    if def.assembly_angle != 0.0 {
        let _ = writeln!(t, "assembly_angle = {}", deg(def.assembly_angle));
    }
    if let Some(o) = &def.output {
        let _ = writeln!(t, "output = {}", s(o));
    }
    for l in &def.links {
        check_name("link", &l.name)?;
        // a bare slider block is made by its [[linkage.sliders]] entry (the
        // reader gives a listed link a centre-of-mass point, which on a
        // one-point block would coincide with its joint)
        if l.points.len() == 1 && l.mass_center == l.points[0].1 && def.sliders.iter().any(|s| s.slider == l.name) {
            continue;
        }
        let (o, u) = task_frame(l);
        let _ = write!(t, "\n[[linkage.links]]\nname = {}\n", s(&l.name));
        let joints: Vec<String> = l.points.iter().take(2).map(|(n, _)| s(n)).collect();
        let _ = writeln!(t, "joints = [{}]", joints.join(", "));
        let length = match l.points.get(1) {
            Some((_, q)) => {
                let d = (*q - o).hypot();
                if d <= 0.0 {
                    return Err(Error::input(
                        "synthesis",
                        format!("link `{}`: its first two points coincide", l.name),
                    ));
                }
                let _ = writeln!(t, "length = {}", len(d));
                d
            }
            None => 0.0,
        };
        for (n, p) in l.points.iter().skip(2) {
            check_name("point", n)?;
            let _ = writeln!(t, "points.{} = {{ at = {} }}", s(n), pair(to_frame(*p, o, u)));
        }
        let mc = to_frame(l.mass_center, o, u);
        if mc != Vec2::new(0.5 * length, 0.0) {
            let _ = writeln!(t, "mass_center = {{ at = {} }}", pair(mc));
        }
    }
    for sl in &def.sliders {
        if sl.angle_on_slider != 0.0 {
            return Err(Error::input(
                "synthesis",
                format!(
                    "slider `{}`: a guide at an angle to the slider's own axis cannot be written into a task file",
                    sl.slider
                ),
            ));
        }
        let (through, angle) = if sl.guide_link == FRAME {
            (sl.through, sl.angle)
        } else {
            let g = def.links.iter().find(|l| l.name == sl.guide_link).ok_or_else(|| {
                Error::input(
                    "synthesis",
                    format!("slider `{}`: no link `{}` carries its guide", sl.slider, sl.guide_link),
                )
            })?;
            let (o, u) = task_frame(g);
            (to_frame(sl.through, o, u), sl.angle - u.atan2())
        };
        let _ = write!(
            t,
            "\n[[linkage.sliders]]\nlink = {}\npoint = {}\nguide = {{ link = {}, through = {}, angle = {} }}\n",
            s(&sl.slider),
            s(&sl.point),
            s(&sl.guide_link),
            pair(through),
            deg(angle)
        );
    }
    Ok(t)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::TaskSource;
    use tmm_linkage::synthesis::crank_rocker::{CrankRockerRequest, RockerCondition};
    use tmm_linkage::synthesis::crank_slider::{CrankSliderRequest, SliderCondition};
    use tmm_linkage::synthesis::knee_press::{KneePivot, KneeRequest};
    use tmm_linkage::synthesis::pivot::PivotCondition;
    use tmm_linkage::synthesis::six_bar::{InversionRequest, PressureRequest};
    use tmm_linkage::synthesis::slotted::{Coupler, Lever, SlottedRequest};
    use tmm_linkage::synthesis::{Drive, Request, Rotation, synthesize};
    use tmm_linkage::{LinkDef, Mechanism, SliderDef};

    /// Compile both descriptions and compare every point of `a` at
    /// several crank angles.
    fn same_motion(a: &MechanismDef, b: &MechanismDef) {
        let (ma, mb) = (Mechanism::new(a).unwrap(), Mechanism::new(b).unwrap());
        let (mut sa, mut sb) = (ma.solution(), mb.solution());
        let base = a.assembly_angle;
        for k in 0..8 {
            let phi = base + 0.05 * k as f64;
            ma.solve(phi, &mut sa).unwrap();
            mb.solve(phi, &mut sb).unwrap();
            for (i, p) in ma.points.iter().enumerate() {
                let j = mb.point(&p.name).unwrap_or_else(|| panic!("{} is missing", p.name));
                let d = (sa.points[i].p - sb.points[j].p).hypot();
                assert!(d < 1e-12, "{} at φ = {phi}: {d}", p.name);
            }
        }
    }

    fn round_trip(def: &MechanismDef) -> MechanismDef {
        let text = linkage_toml(def).unwrap();
        let back = crate::linkage::task::read(&TaskSource::new("t.toml", text.clone()))
            .unwrap_or_else(|e| panic!("{e}\n{text}"))
            .unwrap();
        back.def
    }

    fn deg(x: f64) -> f64 {
        x.to_radians()
    }

    fn requests() -> Vec<Request> {
        let d = Drive::default();
        let cw = Drive {
            rotation: Rotation::Cw,
            omega: 94.2,
        };
        vec![
            Request::CrankSlider(CrankSliderRequest {
                stroke: 0.3,
                k: 1.2,
                condition: SliderCondition::Lambda(3.5),
                drive: cw,
                limits: Default::default(),
            }),
            Request::CrankRocker(CrankRockerRequest {
                k: 1.28,
                rocker: 0.245,
                swing: deg(60.0),
                condition: RockerCondition::Crank(0.1),
                drive: d,
                limits: Default::default(),
            }),
            Request::Slotted(SlottedRequest {
                stroke: 0.4,
                k: 1.5,
                pivots: 0.05,
                coupler: Coupler::Ratio(3.0),
                lever: Lever::Rotating,
                drive: d,
                limits: Default::default(),
            }),
            Request::Knee(KneeRequest {
                stroke: 0.09,
                k: 1.12,
                rocker: 0.22,
                link: 0.22,
                delta: deg(5.0),
                pivot: KneePivot::Horizontal(0.28),
                drive: cw,
                limits: Default::default(),
            }),
            Request::SixBarInversion(InversionRequest {
                k: 1.15,
                travel: 0.36,
                guide: -0.32,
                start: 0.18,
                coupler: 0.32,
                swing: deg(70.0),
                lever: 0.36,
                pivot: PivotCondition::OnLine {
                    point: Vec2::new(0.0, 0.2),
                    dir: Vec2::new(1.0, 0.0),
                },
                drive: d,
                limits: Default::default(),
            }),
            Request::SixBarPressure(PressureRequest {
                k: 1.07,
                swing: deg(55.0),
                arm_b: 0.6,
                arm_c: 0.6,
                arm_angle: std::f64::consts::PI,
                guide: -0.2,
                max_pressure: deg(38.0),
                pivot: PivotCondition::ExtremePressure(deg(38.0)),
                drive: d,
                limits: Default::default(),
            }),
        ]
    }

    #[test]
    fn every_synthesised_kind_reads_back_with_the_same_motion() {
        for r in requests() {
            let syn = synthesize(&r).unwrap();
            let back = round_trip(&syn.def);
            assert_eq!(back.input.as_ref().unwrap().omega, syn.def.input.as_ref().unwrap().omega);
            same_motion(&syn.def, &back);
        }
    }

    #[test]
    fn a_link_off_its_axis_and_a_guide_on_it_keep_their_global_places() {
        // A slotted lever whose local frame is not the task format's: its
        // second point is off the x-axis and it carries the slot.
        let mut def = synthesize(&requests()[2]).unwrap().def;
        let a = 0.7_f64;
        let (sn, cs) = a.sin_cos();
        let rot = |p: Vec2| Vec2::new(cs * p.x - sn * p.y, sn * p.x + cs * p.y) + Vec2::new(0.01, -0.02);
        let lever = def.links.iter_mut().find(|l| l.name == "3").unwrap();
        for p in &mut lever.points {
            p.1 = rot(p.1);
        }
        lever.mass_center = rot(lever.mass_center);
        for sl in &mut def.sliders {
            if sl.guide_link == "3" {
                sl.through = rot(sl.through);
                sl.angle += a;
            }
        }
        let back = round_trip(&def);
        same_motion(&def, &back);
        // the lever's points read back in the task's frame: E at the origin
        let l3 = back.links.iter().find(|l| l.name == "3").unwrap();
        assert_eq!(l3.points[0].1, Vec2::ZERO);
        assert!(l3.points[1].1.y.abs() < 1e-15);
    }

    #[test]
    fn names_the_format_cannot_hold_are_refused() {
        let def = MechanismDef {
            fixed: vec![("A".into(), Vec2::ZERO)],
            links: vec![LinkDef::bar("crank one", "A", "B", 0.1)],
            ..Default::default()
        };
        assert!(linkage_toml(&def).is_err());
        let mut def2 = round_trip(&synthesize(&requests()[0]).unwrap().def);
        def2.sliders.push(SliderDef {
            slider: "3".into(),
            point: "B".into(),
            guide_link: FRAME.into(),
            through: Vec2::ZERO,
            angle: 0.0,
            angle_on_slider: 0.3,
        });
        assert!(linkage_toml(&def2).is_err());
    }
}
