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
