//! Every linkage example: velocities are central finite differences of
//! positions and accelerations of velocities (relative 1e-6), link lengths and
//! guide constraints hold to 1e-12, and W and the structure formula are as
//! worked by hand from each file's description.

use std::f64::consts::TAU;
use std::path::PathBuf;

use tmm_linkage::Mechanism;
use tmm_linkage::mechanism::Pair;
use tmm_linkage::state::rot;
use tmm_report::TaskSource;
use tmm_report::linkage::load;

/// The linkage examples: name, mechanism, and whether it is analysed over
/// its assembly ranges only (then the tests take the angles where it assembles).
fn examples() -> Vec<(String, Mechanism, bool)> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    let mut out = Vec::new();
    for e in std::fs::read_dir(&dir).unwrap() {
        let p = e.unwrap().path();
        if p.extension().is_some_and(|x| x == "toml") {
            let text = std::fs::read_to_string(&p).unwrap();
            let t = TaskSource::new(p.display().to_string(), text);
            if let Some(l) = load(&t).unwrap_or_else(|e| panic!("{}: {e}", p.display())) {
                if l.mech.drive.is_some() {
                    // driven by a slider over its travel, not a crank's turn:
                    // checked by tmm-linkage's and tmm-cli's slider_input tests
                    continue;
                }
                let partial = l.task.range == tmm_report::linkage::RangeMode::Partial;
                out.push((p.file_name().unwrap().to_string_lossy().into_owned(), l.mech, partial));
            }
        }
    }
    assert!(out.len() >= 8, "expected the linkage examples, found {}", out.len());
    out
}

#[test]
fn velocities_and_accelerations_are_finite_differences() {
    for (name, m, partial) in examples() {
        let w = m.crank.omega;
        let h = 1e-6;
        let (mut s0, mut sm, mut sp) = (m.solution(), m.solution(), m.solution());
        for k in 0..48 {
            let phi = TAU * (k as f64 + 0.37) / 48.0;
            if partial && [phi - h, phi, phi + h].iter().any(|&x| m.solve(x, &mut s0).is_err()) {
                continue;
            }
            m.solve(phi, &mut s0).unwrap();
            m.solve(phi - h, &mut sm).unwrap();
            m.solve(phi + h, &mut sp).unwrap();
            // d/dt = ω1 · d/dφ (ε1 = 0)
            for i in 0..m.points.len() {
                let v_fd = (sp.points[i].p - sm.points[i].p) * (w / (2.0 * h));
                let a_fd = (sp.points[i].v - sm.points[i].v) * (w / (2.0 * h));
                let (v, a) = (s0.points[i].v, s0.points[i].a);
                let vs = v.hypot().max(w.abs() * 1e-3);
                let as_ = a.hypot().max(w * w * 1e-3);
                assert!(
                    (v - v_fd).hypot() <= 1e-6 * vs,
                    "{name} {} v {v:?} vs {v_fd:?} at {phi}",
                    m.points[i].name
                );
                assert!(
                    (a - a_fd).hypot() <= 1e-6 * as_,
                    "{name} {} a {a:?} vs {a_fd:?} at {phi}",
                    m.points[i].name
                );
            }
            for l in 1..m.link_names.len() {
                let om_fd = tmm_geom::angle::wrap_pi(sp.links[l].angle() - sm.links[l].angle()) * (w / (2.0 * h));
                let ep_fd = (sp.links[l].omega - sm.links[l].omega) * (w / (2.0 * h));
                assert!(
                    (s0.links[l].omega - om_fd).abs() <= 1e-6 * w.abs().max(s0.links[l].omega.abs()),
                    "{name} ω{l}"
                );
                assert!(
                    (s0.links[l].eps - ep_fd).abs() <= 1e-6 * (w * w).max(s0.links[l].eps.abs()),
                    "{name} ε{l}"
                );
            }
        }
    }
}

#[test]
fn lengths_and_guides_hold() {
    for (name, m, partial) in examples() {
        let mut s = m.solution();
        for k in 0..360 {
            let phi = TAU * k as f64 / 360.0;
            if partial && m.solve(phi, &mut s).is_err() {
                continue;
            }
            m.solve(phi, &mut s).unwrap();
            // every pair closes: a revolute joint is one point on both links,
            // a slider point lies on its guide and turns with it
            for p in &m.pairs {
                match *p {
                    Pair::R { a, b, la, lb, .. } => {
                        let d = s.links[a].pos(la) - s.links[b].pos(lb);
                        assert!(d.hypot() < 1e-12, "{name}: joint open by {} at {phi}", d.hypot());
                    }
                    Pair::P {
                        slider,
                        guide,
                        ps,
                        q,
                        d,
                        rel,
                        ..
                    } => {
                        let g = &s.links[guide];
                        let n = rot(g.u, tmm_geom::perp(d));
                        let off = (s.links[slider].pos(ps) - g.pos(q)).dot(n);
                        assert!(off.abs() < 1e-12, "{name}: slider off its guide by {off}");
                        let turn = rot(s.links[slider].u, tmm_linkage::state::conj(rot(g.u, rel)));
                        assert!(turn.y.abs() < 1e-12 && turn.x > 0.0, "{name}: slider turned on its guide");
                    }
                }
            }
            // distances between points of one link are the local distances
            for (i, pi) in m.points.iter().enumerate() {
                for (j, pj) in m.points.iter().enumerate().skip(i + 1) {
                    if pi.link == pj.link {
                        let d = (s.points[i].p - s.points[j].p).hypot();
                        let d0 = (pi.local - pj.local).hypot();
                        assert!((d - d0).abs() < 1e-12, "{name}: |{}{}| = {d} vs {d0}", pi.name, pj.name);
                    }
                }
            }
        }
    }
}

#[test]
fn structure_of_every_example() {
    // (file, W = 3n − 2p5, formula), counted by hand from each description
    let want = [
        ("seed-001-fourbar.toml", 3, 4, "I(0,1) → II(2,3)", 2),
        ("crank-slider-axial.toml", 3, 4, "I(0,1) → II(2,3)", 2),
        ("crank-slider-offset.toml", 3, 4, "I(0,1) → II(2,3)", 2),
        ("seed-003-sixbar.toml", 5, 7, "I(0,1) → II(2,3) → II(4,5)", 2),
        ("seed-004-two-sliders.toml", 5, 7, "I(0,1) → II(2,3) → II(4,5)", 2),
        ("seed-002-shaper.toml", 5, 7, "I(0,1) → II(2,3) → II(4,5)", 2),
        ("seed-002-knee-press.toml", 5, 7, "I(0,1) → II(2,3) → II(4,5)", 2),
        ("class3-triad.toml", 5, 7, "I(0,1) → III(2,3,4,5)", 3),
    ];
    let ex = examples();
    for (file, n, p5, formula, class) in want {
        let m = &ex.iter().find(|(f, _, _)| f == file).unwrap_or_else(|| panic!("{file} missing")).1;
        let s = &m.structure;
        assert_eq!((s.n, s.p5), (n, p5), "{file}");
        assert_eq!(s.dof, 3 * n as i64 - 2 * p5 as i64, "{file}");
        assert_eq!(s.dof, 1, "{file}");
        assert_eq!(s.formula, formula, "{file}");
        assert_eq!(s.class, class, "{file}");
        assert_eq!((s.redundant, s.passive), (0, 0), "{file}");
    }
    // the kinds of the dyads
    let kinds = |f: &str| {
        ex.iter()
            .find(|(x, _, _)| x == f)
            .unwrap()
            .1
            .structure
            .groups
            .iter()
            .map(|g| g.kind.clone())
            .collect::<Vec<_>>()
    };
    assert_eq!(kinds("seed-002-shaper.toml"), ["RPR", "RRP"]);
    assert_eq!(kinds("seed-003-sixbar.toml"), ["RRR", "RRP"]);
    assert_eq!(kinds("crank-slider-offset.toml"), ["RRP"]);
}

#[test]
fn offset_crank_slider_dead_positions_closed_form() {
    // Extreme slider positions: crank and coupler collinear; with offset e the
    // slider is at x = ±√((l2 ± l1)² − e²) and the crank at
    // φ = atan2(−e, x) (extended) or atan2(e, −x) (folded) — seed 000 § 1.2.
    let ex = examples();
    let m = &ex.iter().find(|(f, _, _)| f == "crank-slider-offset.toml").unwrap().1;
    let c = tmm_linkage::cycle::Cycle::new(m, tmm_linkage::cycle::Working::Slower).unwrap();
    let (l1, l2, e) = (0.1f64, 0.35f64, -0.04f64);
    let x_ext = ((l2 + l1).powi(2) - e * e).sqrt();
    let x_fold = ((l2 - l1).powi(2) - e * e).sqrt();
    let phi_ext = tmm_geom::angle::wrap_2pi(e.atan2(x_ext));
    let phi_fold = tmm_geom::angle::wrap_2pi((-e).atan2(-x_fold));
    let mut got = c.dead.clone();
    got.sort_by(f64::total_cmp);
    let mut want = [phi_ext, phi_fold];
    want.sort_by(f64::total_cmp);
    for (g, w) in got.iter().zip(want) {
        assert!((g - w).abs() < 1e-9, "{g} vs {w}");
    }
    assert!((c.stroke - (x_ext - x_fold)).abs() < 1e-9);
}
