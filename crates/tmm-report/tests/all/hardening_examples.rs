//! The examples after the hardening issue, loaded through the public API:
//! every force polygon closes (groups and the crank with its balancing
//! force), the PRP and RPP examples match their geometry built by hand, the
//! shaper's hints pick one assembly, the class III example has a real crank.

use std::f64::consts::TAU;
use std::path::PathBuf;

use tmm_geom::{Vec2, perp};
use tmm_linkage::forces::{Kinetostatics, PolygonForceKind};
use tmm_report::TaskSource;

fn source(file: &str) -> TaskSource {
    let p = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples").join(file);
    let text = std::fs::read_to_string(&p).unwrap();
    TaskSource::new(p.display().to_string(), text)
}

fn linkage_examples() -> Vec<String> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    let mut out: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|f| {
            f.ends_with(".toml")
                && std::fs::read_to_string(dir.join(f))
                    .unwrap()
                    .lines()
                    .any(|l| l.trim() == "[linkage]")
        })
        .collect();
    out.sort();
    out
}

#[test]
fn every_force_polygon_of_every_example_closes() {
    let mut checked = 0;
    for file in linkage_examples() {
        let src = source(&file);
        let Some((l, t)) = tmm_report::forces::load(&src).unwrap_or_else(|e| panic!("{file}: {e}")) else {
            continue;
        };
        let m = &l.mech;
        let mut k = Kinetostatics::with_working(
            m,
            t.loads.clone(),
            match l.task.working {
                tmm_linkage::cycle::Working::Slower => tmm_linkage::forces::stroke::Working::Slower,
                tmm_linkage::cycle::Working::Increasing => tmm_linkage::forces::stroke::Working::Increasing,
                tmm_linkage::cycle::Working::Decreasing => tmm_linkage::forces::stroke::Working::Decreasing,
            },
        )
        .unwrap();
        let (mut sol, mut f) = (m.solution(), k.result());
        for j in 0..360 {
            let phi = TAU * (j as f64 + 0.5) / 360.0;
            k.solve_at(phi, &mut sol, &mut f).unwrap_or_else(|e| panic!("{file} at {phi}: {e}"));
            let polys = f.polygons(m);
            assert_eq!(polys.len(), m.groups.len() + 1);
            for p in &polys {
                let gap = p.closure().hypot();
                assert!(gap <= 1e-9 * p.largest(), "{file} φ = {phi}: polygon {:?} open by {gap} N", p.group);
                checked += 1;
            }
            // the crank's polygon: P_b and the frame's reaction for that model;
            // the torque model's reaction would leave exactly P_b open
            let crank = polys.last().unwrap();
            let pb = crank.forces.iter().find(|x| x.kind == PolygonForceKind::BalancingForce).unwrap();
            let r01 = crank
                .forces
                .iter()
                .find(|x| matches!(x.kind, PolygonForceKind::Reaction { from: 0, .. }))
                .unwrap();
            let pivot = f.reactions.iter().find(|r| r.from == 0 && r.on == m.crank.link).unwrap();
            assert!((r01.force - (pivot.force - pb.force)).hypot() <= 1e-9 * crank.largest());
            // P_b's moment about the pivot is the balancing torque
            let arm = pb.at - m.crank.pivot;
            assert!((tmm_geom::cross(arm, pb.force) - f.balancing_moment).abs() <= 1e-9 * f.balancing_moment.abs().max(1.0));
        }
    }
    assert!(checked >= 3 * 360 * 2, "checked {checked} polygons");
}

fn points(file: &str) -> (tmm_linkage::Mechanism, Vec<String>) {
    let l = tmm_report::linkage::load(&source(file)).unwrap().unwrap();
    let names = l.mech.points.iter().map(|p| p.name.clone()).collect();
    (l.mech, names)
}

/// Intersection of the lines p + t·d and q + s·e (Cramer's rule).
fn cross_lines(p: Vec2, d: Vec2, q: Vec2, e: Vec2) -> Vec2 {
    let det = d.x * (-e.y) - d.y * (-e.x);
    let r = q - p;
    let t = (r.x * (-e.y) - r.y * (-e.x)) / det;
    p + d * t
}

#[test]
fn prp_example_puts_k_where_the_two_slots_cross() {
    let (m, _) = points("prp-moving-guides.toml");
    let kinds: Vec<&str> = m.structure.groups.iter().map(|g| g.kind.as_str()).collect();
    assert_eq!(kinds, ["RRR", "PRP"]);
    assert_eq!(m.structure.formula, "I(0,1) → II(2,3) → II(4,5)");
    assert_eq!((m.structure.dof, m.structure.dof_rank, m.structure.redundant), (1, 1, 0));
    let c = tmm_linkage::cycle::Cycle::new(&m, tmm_linkage::cycle::Working::Slower).unwrap();
    assert_eq!(c.dead.len(), 2);
    let mut s = m.solution();
    let p = |s: &tmm_linkage::Solution, n: &str| s.points[m.point(n).unwrap()].p;
    for j in 0..72 {
        let phi = TAU * j as f64 / 72.0;
        m.solve(phi, &mut s).unwrap();
        let (b, cc, d, k) = (p(&s, "B"), p(&s, "C"), p(&s, "D"), p(&s, "K"));
        // slot of 2: parallel to BC, 80 mm to its left, through B + 0.24·BC/|BC| + 0.08·n
        let u2 = (cc - b) * (1.0 / (cc - b).hypot());
        let u3 = (cc - d) * (1.0 / (cc - d).hypot());
        let p2 = b + u2 * 0.24 + perp(u2) * 0.08;
        let p3 = d + u3 * 0.19 - perp(u3) * 0.06;
        let want = cross_lines(p2, u2, p3, u3);
        assert!((k - want).hypot() < 1e-12, "φ = {phi}: {k:?} vs {want:?}");
    }
}

#[test]
fn rpp_example_slides_the_yoke_to_the_projection_of_e() {
    let (m, _) = points("rpp-moving-guides.toml");
    let kinds: Vec<&str> = m.structure.groups.iter().map(|g| g.kind.as_str()).collect();
    assert_eq!(kinds, ["RRR", "RPP"]);
    assert_eq!((m.structure.dof, m.structure.dof_rank, m.structure.redundant), (1, 1, 0));
    let mut s = m.solution();
    let p = |s: &tmm_linkage::Solution, n: &str| s.points[m.point(n).unwrap()];
    let h = 1e-6;
    let (mut sm, mut sp) = (m.solution(), m.solution());
    for j in 0..72 {
        let phi = TAU * (j as f64 + 0.2) / 72.0;
        m.solve(phi, &mut s).unwrap();
        let (b, cc, d, e, y) = (p(&s, "B").p, p(&s, "C").p, p(&s, "D").p, p(&s, "E").p, p(&s, "Y").p);
        assert!((e - (b + cc) * 0.5).hypot() < 1e-12);
        let u3 = (cc - d) * (1.0 / (cc - d).hypot());
        let want = d + u3 * (e - d).dot(u3);
        assert!((y - want).hypot() < 1e-12, "φ = {phi}: {y:?} vs {want:?}");
        // the yoke's velocity: central differences of its position
        m.solve(phi - h, &mut sm).unwrap();
        m.solve(phi + h, &mut sp).unwrap();
        let w = m.crank.omega;
        let v_fd = (p(&sp, "Y").p - p(&sm, "Y").p) * (w / (2.0 * h));
        let v = p(&s, "Y").v;
        assert!((v - v_fd).hypot() < 1e-6 * v.hypot().max(1e-3), "{v:?} vs {v_fd:?}");
    }
}

#[test]
fn shaper_hints_pick_one_assembly_and_the_old_hint_is_refused() {
    let src = source("seed-002-shaper.toml");
    let l = tmm_report::linkage::load(&src).unwrap().unwrap();
    let mut s = l.mech.solution();
    l.mech.solve(0.0, &mut s).unwrap();
    let c = s.points[l.mech.point("C").unwrap()].p;
    assert!((c - Vec2::new(0.0, 0.2)).hypot() < 1e-12, "{c:?}");
    // the example's former hint alone ties
    let text = src.text.replace(r#", "C above line O-E""#, "");
    assert_ne!(text, src.text);
    let e = tmm_report::linkage::load(&TaskSource::new("old.toml", text)).expect_err("refused");
    assert!(e.to_string().contains("do not choose one assembly"), "{e}");
}

#[test]
fn class_iii_example_has_a_real_crank() {
    let (m, _) = points("class3-triad.toml");
    assert_eq!(m.structure.class, 3);
    let longest = (2..m.link_names.len())
        .map(|l| tmm_linkage::forces::loads::link_length(&m, l))
        .fold(0.0, f64::max);
    assert!(
        m.crank.radius >= 0.1 * longest,
        "crank {} against links up to {longest}",
        m.crank.radius
    );
    let c = tmm_linkage::cycle::Cycle::new(&m, tmm_linkage::cycle::Working::Slower).unwrap();
    assert_eq!(c.dead.len(), 2);
    assert!(c.stroke > 5f64.to_radians(), "the output swings {}°", c.stroke.to_degrees());
}

#[test]
fn force_polygons_close_for_every_linkage_example_under_weights_and_inertia() {
    // examples without a [forces] section: 5 kg per link, J = 0.05 kg·m², gravity
    for file in linkage_examples() {
        let l = tmm_report::linkage::load(&source(&file)).unwrap().unwrap();
        if l.mech.drive.is_some() {
            // a slider input has no crank to balance (refused by [forces]);
            // its kinematics is checked by tmm-cli's slider_input tests
            continue;
        }
        let m = &l.mech;
        let mut loads = tmm_linkage::forces::Loads::new(m);
        loads.gravity = Vec2::new(0.0, -9.81);
        for i in 1..m.link_names.len() {
            loads.links[i].mass = 5.0;
            loads.links[i].inertia = 0.05;
        }
        let mut k = Kinetostatics::new(m, loads).unwrap();
        let (mut sol, mut f) = (m.solution(), k.result());
        // a linkage analysed over its assembly ranges: the angles inside them
        let partial = l.task.range == tmm_report::linkage::RangeMode::Partial;
        for j in 0..120 {
            let phi = TAU * (j as f64 + 0.25) / 120.0;
            if partial && m.solve(phi, &mut sol).is_err() {
                continue;
            }
            k.solve_at(phi, &mut sol, &mut f).unwrap_or_else(|e| panic!("{file} at {phi}: {e}"));
            for p in f.polygons(m) {
                assert!(p.closure().hypot() <= 1e-9 * p.largest(), "{file} φ = {phi}: {:?}", p.group);
            }
        }
    }
}

/// The diagrams' axes at any crank or cam speed: at 1e-7 rpm the
/// accelerations are of order 1e-17 m/s², and a tick loop with an absolute
/// tolerance once wrote half a million ticks (166 MB) into one diagram. Every
/// drawing keeps a handful of ticks whatever the scale of its values.
#[test]
fn diagrams_keep_few_ticks_at_extreme_speeds() {
    for (file, from, speeds) in [
        ("seed-001-fourbar.toml", "speed = \"900 rpm\"", ["1e-7 rpm", "1e7 rpm"]),
        ("synth-seed-002-ex2-knee-press.toml", "speed = \"90 rpm\"", ["1e-7 rpm", "1e7 rpm"]),
        ("cam-seed-001-roller.toml", "omega = \"200 rad/s\"", ["1e-7 rad/s", "1e6 rad/s"]),
    ] {
        let base = source(file);
        assert!(base.text.contains(from), "{file}: no {from}");
        for s in speeds {
            let key = from.split(" = ").next().unwrap_or(from);
            let text = base.text.replace(from, &format!("{key} = \"{s}\""));
            let src = TaskSource::new(file, text);
            let run = match tmm_report::run::run_task(&src) {
                Ok(r) => r,
                // a speed out of the core's range is refused with a message: fine
                Err(e) => {
                    assert_eq!(e.exit_code(), 2, "{file} at {s}: {e}");
                    continue;
                }
            };
            let mut svgs = 0;
            for d in run
                .docs
                .iter()
                .filter(|d| d.path.ends_with(".svg") && !d.path.starts_with("sheets/"))
            {
                let t = d.as_text().unwrap_or_default();
                let texts = t.matches("<text").count();
                assert!(texts < 400, "{file} at {s}: {} has {texts} texts", d.path);
                assert!(t.len() < 2_000_000, "{file} at {s}: {} is {} bytes", d.path, t.len());
                svgs += 1;
            }
            assert!(svgs > 0, "{file} at {s}: no drawings");
        }
    }
}
