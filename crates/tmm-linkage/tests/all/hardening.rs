//! Regression tests of the hardening issue, each against an independent
//! reference: the Scotch yoke's closed form (s = r·cos(φ − α)), the offset
//! crank-slider's closed form, brute-force sampling, and exact scaling.

use crate::common;

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use common::v;
use tmm_geom::Vec2;
use tmm_linkage::cycle::{Cycle, Working};
use tmm_linkage::{AssemblyHint, HintKind, InputDef, LinkDef, LinkageError, Mechanism, MechanismDef, SliderDef};

fn input(omega: f64) -> Option<InputDef> {
    Some(InputDef {
        link: "1".into(),
        pivot: "O".into(),
        pin: "A".into(),
        omega,
        epsilon: 0.0,
    })
}

/// Scotch yoke (RPP dyad): crank OA = r, block 2 at A in the slot of yoke 3
/// (the slot perpendicular to the yoke's guide), the yoke on a frame guide
/// through O at angle `alpha`. The yoke's travel along its guide is
/// s = (A − O)·ĝ = r·cos(φ − α): dead positions at φ = α and α + π, stroke 2r.
fn yoke_def(r: f64, alpha: f64, omega: f64, assembly: f64) -> MechanismDef {
    MechanismDef {
        fixed: vec![("O".into(), v(0.0, 0.0))],
        links: vec![LinkDef::bar("1", "O", "A", r), LinkDef::block("2", "A"), LinkDef::block("3", "Y")],
        sliders: vec![
            SliderDef {
                slider: "2".into(),
                point: "A".into(),
                guide_link: "3".into(),
                through: v(0.0, 0.0),
                angle: FRAC_PI_2,
                angle_on_slider: 0.0,
            },
            SliderDef {
                slider: "3".into(),
                point: "Y".into(),
                guide_link: "frame".into(),
                through: v(0.0, 0.0),
                angle: alpha,
                angle_on_slider: 0.0,
            },
        ],
        input: input(omega),
        assembly_angle: assembly,
        output: Some("3".into()),
        ..Default::default()
    }
}

fn same_angle(a: f64, b: f64) -> bool {
    tmm_geom::angle::wrap_pi(a - b).abs() < 1e-9
}

#[test]
fn scotch_yoke_dead_positions_on_grid_points_do_not_depend_on_the_scan_start() {
    let r = 0.1;
    // extremes exactly on the 0.5° scan grid: at its very start, and 40 steps in
    for (alpha_deg, start_deg) in [(0.0, 0.0), (30.0, 10.0), (90.0, 0.0), (180.0, 0.0), (45.0, 45.0)] {
        for omega in [10.0, -10.0] {
            let (alpha, start) = (f64::to_radians(alpha_deg), f64::to_radians(start_deg));
            let m = Mechanism::new(&yoke_def(r, alpha, omega, start)).unwrap();
            assert_eq!(m.structure.groups[0].kind, "RPP");
            let c = Cycle::new(&m, Working::Increasing).unwrap_or_else(|e| panic!("α = {alpha_deg}°: {e}"));
            assert_eq!(c.dead.len(), 2, "α = {alpha_deg}°, ω = {omega}");
            // s = r cos(φ − α): minimum at α + π starts the increasing stroke
            assert!(same_angle(c.start, alpha + PI), "α = {alpha_deg}°: start {}", c.start.to_degrees());
            assert!(same_angle(c.dead[1], alpha), "α = {alpha_deg}°: other {}", c.dead[1].to_degrees());
            assert!((c.stroke - 2.0 * r).abs() < 1e-12, "stroke {}", c.stroke);
            assert!((c.kv - 1.0).abs() < 1e-9);
        }
    }
}

#[test]
fn kv_of_one_needs_an_explicit_working_stroke() {
    let m = Mechanism::new(&yoke_def(0.1, 0.0, 10.0, 0.0)).unwrap();
    let e = Cycle::new(&m, Working::Slower).unwrap_err();
    let msg = e.to_string();
    assert!(
        matches!(e, LinkageError::Description { ref field, .. } if field == "working"),
        "{msg}"
    );
    assert!(msg.contains("increasing") && msg.contains("Kv = 1"), "{msg}");
    // the force module's stroke refuses the same
    let e = tmm_linkage::forces::Stroke::find(&m, m.output, tmm_linkage::forces::stroke::Working::Slower).unwrap_err();
    assert!(e.to_string().contains("Kv = 1"), "{e}");
    // with the guide tilted 0.5° the answer is the same (Kv does not depend on α)
    let m = Mechanism::new(&yoke_def(0.1, 0.5f64.to_radians(), 10.0, 0.0)).unwrap();
    assert!(Cycle::new(&m, Working::Slower).is_err());
    let c = Cycle::new(&m, Working::Decreasing).unwrap();
    assert!((c.stroke - 0.2).abs() < 1e-12);
}

/// Offset crank-slider: crank OA = r, rod AB = l, slider B on the line
/// y = −e. Closed form: B.x = r cos φ + √(l² − (r sin φ + e)²).
fn crank_slider(r: f64, l: f64, e: f64) -> Mechanism {
    let def = MechanismDef {
        fixed: vec![("O".into(), v(0.0, 0.0))],
        links: vec![
            LinkDef::bar("1", "O", "A", r),
            LinkDef::bar("2", "A", "B", l),
            LinkDef::block("3", "B"),
        ],
        sliders: vec![SliderDef {
            slider: "3".into(),
            point: "B".into(),
            guide_link: "frame".into(),
            through: v(0.0, -e),
            angle: 0.0,
            angle_on_slider: 0.0,
        }],
        input: input(10.0),
        hints: vec![AssemblyHint {
            point: "B".into(),
            kind: HintKind::Near(v(0.4, -e)),
        }],
        assembly_angle: 0.3,
        ..Default::default()
    };
    Mechanism::new(&def).unwrap()
}

#[test]
fn near_singular_group_is_refused_by_a_relative_measure() {
    // e = l − r: the rod stands perpendicular to the guide at φ = 90°, the
    // RRP dyad's dead centre (its two branches meet)
    let (r, l) = (0.1, 0.3);
    let m = crank_slider(r, l, l - r);
    let mut s = m.solution();
    for d in [0.0, 1e-8, 1e-6, -1e-6] {
        let e = m.solve(FRAC_PI_2 + d, &mut s).unwrap_err();
        assert!(
            matches!(e, LinkageError::Singular { .. } | LinkageError::Assembly { .. }),
            "δ = {d}: {e}"
        );
        assert!(e.to_string().contains("dead centre") || e.to_string().contains("guide line"), "{e}");
    }
    // 0.6° away it solves, and matches the closed form
    let b = m.point("B").unwrap();
    for phi in [FRAC_PI_2 + 0.01, FRAC_PI_2 - 0.01, 1.0, 4.0] {
        m.solve(phi, &mut s).unwrap();
        let h = r * phi.sin() + (l - r);
        let x = r * phi.cos() + (l * l - h * h).sqrt();
        assert!((s.points[b].p.x - x).abs() < 1e-12, "φ = {phi}");
    }
    // the whole cycle says where instead of giving numbers
    let e = Cycle::new(&m, Working::Slower).unwrap_err();
    assert!(e.to_string().contains("90.0"), "{e}");
}

/// The shaper of examples/seed-002-shaper.toml with its old hint only.
fn shaper(hints: Vec<AssemblyHint>) -> Result<Mechanism, LinkageError> {
    let def = MechanismDef {
        fixed: vec![("O".into(), v(-0.05, 0.0)), ("E".into(), v(0.0, 0.0))],
        links: vec![
            LinkDef::bar("1", "O", "A", 0.17),
            LinkDef::block("2", "A"),
            LinkDef::bar("3", "E", "C", 0.2),
            LinkDef::bar("4", "C", "D", 0.6),
            LinkDef::block("5", "D"),
        ],
        sliders: vec![
            SliderDef {
                slider: "2".into(),
                point: "A".into(),
                guide_link: "3".into(),
                through: v(0.0, 0.0),
                angle: FRAC_PI_2,
                angle_on_slider: 0.0,
            },
            SliderDef {
                slider: "5".into(),
                point: "D".into(),
                guide_link: "frame".into(),
                through: v(0.0, 0.0),
                angle: 0.0,
                angle_on_slider: 0.0,
            },
        ],
        input: input(2.0 * PI),
        hints,
        ..Default::default()
    };
    Mechanism::new(&def)
}

#[test]
fn ambiguous_hints_are_an_error_naming_the_tie() {
    let near_d = AssemblyHint {
        point: "D".into(),
        kind: HintKind::Near(v(0.6, 0.0)),
    };
    // at φ = 0 the slot is horizontal, C = (0, ±0.2) and D = (+0.5657, 0) in both
    let e = shaper(vec![near_d.clone()]).unwrap_err();
    let msg = e.to_string();
    assert!(msg.contains("do not choose one assembly"), "{msg}");
    assert!(
        msg.contains("C at (0.000000, 0.200000) m") || msg.contains("C at (0.000000, -0.200000) m"),
        "{msg}"
    );
    assert!(msg.contains("D near (0.6, 0) m"), "{msg}");
    // a side hint tells them apart
    let above = AssemblyHint {
        point: "C".into(),
        kind: HintKind::Above("O".into(), "E".into()),
    };
    let m = shaper(vec![near_d, above]).unwrap();
    let mut s = m.solution();
    m.solve(0.0, &mut s).unwrap();
    let (c, d) = (s.points[m.point("C").unwrap()].p, s.points[m.point("D").unwrap()].p);
    assert!((c - v(0.0, 0.2)).hypot() < 1e-12, "{c:?}");
    assert!((d - v((0.36f64 - 0.04).sqrt(), 0.0)).hypot() < 1e-12, "{d:?}");
}

#[test]
fn side_hints_on_sloped_and_vertical_lines() {
    // four-bar with C above / below the sloped line A–D (D up and to the right)
    let def = |kind: HintKind| MechanismDef {
        fixed: vec![("O".into(), v(0.0, 0.0)), ("D".into(), v(0.4, 0.3))],
        links: vec![
            LinkDef::bar("1", "O", "A", 0.1),
            LinkDef::bar("2", "A", "C", 0.45),
            LinkDef::bar("3", "D", "C", 0.4),
        ],
        input: input(1.0),
        hints: vec![AssemblyHint { point: "C".into(), kind }],
        ..Default::default()
    };
    let line_y = |x: f64| 0.3 / 0.4 * x;
    for above in [true, false] {
        let k = if above {
            HintKind::Above("O".into(), "D".into())
        } else {
            HintKind::Below("D".into(), "O".into())
        };
        let m = Mechanism::new(&def(k)).unwrap();
        let mut s = m.solution();
        m.solve(0.0, &mut s).unwrap();
        let c = s.points[m.point("C").unwrap()].p;
        assert_eq!(c.y > line_y(c.x), above, "{c:?}");
    }
    // a vertical line has no above
    let mut d = def(HintKind::Above("O".into(), "X".into()));
    d.fixed.push(("X".into(), v(0.0, 1.0)));
    let e = Mechanism::new(&d).unwrap_err().to_string();
    assert!(e.contains("vertical") && e.contains("left of"), "{e}");
    assert!(!e.contains("Above(") && !e.contains("Vec2"), "{e}");
}

#[test]
fn messages_carry_no_debug_output() {
    let mut d = common_fourbar();
    d.hints = vec![
        AssemblyHint {
            point: "C".into(),
            kind: HintKind::Below("A".into(), "D".into()),
        },
        AssemblyHint {
            point: "C".into(),
            kind: HintKind::Above("A".into(), "D".into()),
        },
    ];
    let e = Mechanism::new(&d).unwrap_err().to_string();
    assert!(e.contains("C below line A–D") && e.contains("C above line A–D"), "{e}");
    assert!(!e.contains("Below(") && !e.contains("\"A\""), "{e}");
    d.hints = vec![AssemblyHint {
        point: "C".into(),
        kind: HintKind::Near(v(9.0, 9.0)),
    }];
    d.hints.push(AssemblyHint {
        point: "C".into(),
        kind: HintKind::Above("A".into(), "Q".into()),
    });
    let e = Mechanism::new(&d).unwrap_err().to_string();
    assert!(e.contains("`Q`") && !e.contains("Vec2"), "{e}");
}

fn common_fourbar() -> MechanismDef {
    MechanismDef {
        fixed: vec![("A".into(), v(0.0, 0.0)), ("D".into(), v(0.51, 0.0))],
        links: vec![
            LinkDef::bar("1", "A", "B", 0.12),
            LinkDef::bar("2", "B", "C", 0.48),
            LinkDef::bar("3", "D", "C", 0.38),
        ],
        input: Some(InputDef {
            link: "1".into(),
            pivot: "A".into(),
            pin: "B".into(),
            omega: 94.2,
            epsilon: 0.0,
        }),
        ..Default::default()
    }
}

#[test]
fn out_of_range_values_are_refused_with_the_field() {
    let range = |d: &MechanismDef, field: &str| {
        let e = Mechanism::new(d).unwrap_err();
        assert!(matches!(e, LinkageError::Range { .. }), "{e}");
        assert!(e.to_string().contains(field), "{e}");
    };
    let mut d = common_fourbar();
    d.input.as_mut().unwrap().omega = 1e300 * PI / 30.0;
    range(&d, "input.speed");
    let mut d = common_fourbar();
    d.links[0] = LinkDef::bar("1", "A", "B", 1e160);
    range(&d, "links.1.B.x");
    let mut d = common_fourbar();
    d.links[0] = LinkDef::bar("1", "A", "B", 1e-9);
    range(&d, "crank");
    // the whole mechanism scaled to 1e9 m
    let mut d = common_fourbar();
    for (_, p) in &mut d.fixed {
        *p *= 1e9;
    }
    for l in &mut d.links {
        for (_, p) in &mut l.points {
            *p *= 1e9;
        }
    }
    range(&d, "links.1.B.x");
    // a point far along a link
    let mut d = common_fourbar();
    d.links[1].points.push(("K".into(), v(0.48 * 1e300, 0.0)));
    range(&d, "links.2.K.x");
    let mut d = common_fourbar();
    d.links[1].mass_center = v(f64::NAN, 0.0);
    range(&d, "links.2.mass_center.x");
    let mut d = common_fourbar();
    d.assembly_angle = 1e300;
    range(&d, "assembly_angle");
    // solving at a crank angle out of range
    let m = Mechanism::new(&common_fourbar()).unwrap();
    let mut s = m.solution();
    let e = m.solve(1e300, &mut s).unwrap_err();
    assert!(matches!(e, LinkageError::Range { .. }) && e.to_string().contains("phi"), "{e}");
    assert!(m.solve(1e4, &mut s).is_ok());
}

/// Scale every length of a description by k.
fn scaled(mut d: MechanismDef, k: f64) -> MechanismDef {
    for (_, p) in &mut d.fixed {
        *p *= k;
    }
    for l in &mut d.links {
        for (_, p) in &mut l.points {
            *p *= k;
        }
        l.mass_center *= k;
    }
    for s in &mut d.sliders {
        s.through *= k;
    }
    for h in &mut d.hints {
        if let HintKind::Near(p) = &mut h.kind {
            *p *= k;
        }
    }
    d
}

#[test]
fn a_mechanism_scaled_by_1e3_or_1e_3_behaves_identically() {
    let yoke = yoke_def(0.1, 0.3, 7.0, 0.0);
    let defs = [
        common_fourbar(),
        common::seed003_def(),
        common::seed004_def(),
        common::triad_def(),
        common::slotted_def(),
        yoke,
    ];
    for d in defs {
        let m0 = Mechanism::new(&d).unwrap();
        let c0 = Cycle::new(&m0, Working::Increasing).ok();
        for k in [1e-3, 1e3] {
            let m = Mechanism::new(&scaled(d.clone(), k)).unwrap_or_else(|e| panic!("×{k}: {e}"));
            assert_eq!(m.structure, m0.structure);
            let (mut s0, mut s) = (m0.solution(), m.solution());
            for j in 0..72 {
                let phi = TAU * (j as f64 + 0.3) / 72.0;
                let r0 = m0.solve(phi, &mut s0);
                let r = m.solve(phi, &mut s);
                assert_eq!(r0.is_ok(), r.is_ok(), "×{k} at {phi}");
                if r0.is_err() {
                    continue;
                }
                for (p0, p) in s0.points.iter().zip(&s.points) {
                    let tol = 1e-9 * (1.0 + p0.p.hypot());
                    assert!((p.p * (1.0 / k) - p0.p).hypot() < tol, "×{k}: {p:?} vs {p0:?}");
                    assert!((p.v * (1.0 / k) - p0.v).hypot() < 1e-9 * (1.0 + p0.v.hypot()));
                    assert!((p.a * (1.0 / k) - p0.a).hypot() < 1e-9 * (1.0 + p0.a.hypot()));
                }
                for (l0, l) in s0.links.iter().zip(&s.links) {
                    assert!((l.omega - l0.omega).abs() < 1e-9 * (1.0 + l0.omega.abs()));
                }
            }
            let c = Cycle::new(&m, Working::Increasing).ok();
            assert_eq!(c0.is_some(), c.is_some());
            if let (Some(c0), Some(c)) = (&c0, &c) {
                assert!(
                    (c.kv - c0.kv).abs() < 1e-9,
                    "×{k}: Kv {} vs {}, dead {:?} vs {:?}",
                    c.kv,
                    c0.kv,
                    c.dead,
                    c0.dead
                );
                for (a, b) in c.dead.iter().zip(&c0.dead) {
                    assert!(same_angle(*a, *b));
                }
            }
        }
    }
}

#[test]
fn a_vec2_is_not_printed_in_near_hint_errors() {
    let mut d = common_fourbar();
    d.hints = vec![AssemblyHint {
        point: "C".into(),
        kind: HintKind::Near(Vec2::new(0.3, 0.35)),
    }];
    assert!(Mechanism::new(&d).is_ok());
}

#[test]
fn double_parallelogram_is_refused_with_its_rank_count() {
    // frame A(0,0), D(0.4,0); cranks AB, DC and FE of 0.1 m, all parallel;
    // coupler B–E–C of 0.4 m: W = 3·4 − 2·6 = 0, yet it moves (q = 1)
    let coupler = LinkDef {
        name: "2".into(),
        points: vec![("B".into(), v(0.0, 0.0)), ("C".into(), v(0.4, 0.0)), ("E".into(), v(0.2, 0.0))],
        mass_center: v(0.2, 0.0),
    };
    let phi: f64 = 0.5;
    let def = MechanismDef {
        fixed: vec![("A".into(), v(0.0, 0.0)), ("D".into(), v(0.4, 0.0)), ("F".into(), v(0.2, 0.0))],
        links: vec![
            LinkDef::bar("1", "A", "B", 0.1),
            coupler,
            LinkDef::bar("3", "D", "C", 0.1),
            LinkDef::bar("4", "F", "E", 0.1),
        ],
        input: Some(InputDef {
            link: "1".into(),
            pivot: "A".into(),
            pin: "B".into(),
            omega: 1.0,
            epsilon: 0.0,
        }),
        hints: vec![AssemblyHint {
            point: "C".into(),
            kind: HintKind::Near(v(0.4 + 0.1 * phi.cos(), 0.1 * phi.sin())),
        }],
        assembly_angle: phi,
        ..Default::default()
    };
    let e = Mechanism::new(&def).unwrap_err();
    match e {
        LinkageError::Redundant {
            w,
            dof,
            redundant,
            passive,
            ..
        } => assert_eq!((w, dof, redundant, passive), (0, 1, 1, 0)),
        other => panic!("{other}"),
    }
    let msg = Mechanism::new(&def).unwrap_err().to_string();
    assert!(msg.contains("W = 3n − 2p5 = 3·4 − 2·6 = 0") && msg.contains("mobility 1"), "{msg}");
    // without the third crank the same motion is analysed
    let mut d3 = def.clone();
    d3.links.pop();
    d3.fixed.pop();
    let m = Mechanism::new(&d3).unwrap();
    assert_eq!((m.structure.dof, m.structure.dof_rank, m.structure.redundant), (1, 1, 0));
}

#[test]
fn a_joint_never_defined_on_its_other_link_is_named() {
    let mut d = common_fourbar();
    d.links[2] = LinkDef::bar("3", "D", "X", 0.38);
    let e = Mechanism::new(&d).unwrap_err().to_string();
    assert!(e.contains("`X` (on link `3`)") && e.contains("`C` (on link `2`)"), "{e}");
    assert!(e.contains("3·3 − 2·3"), "{e}");
}

#[test]
fn a_triple_rocker_is_analysed_over_its_range_when_asked() {
    use tmm_linkage::ranges::PartialCycle;
    // crank 0.3, coupler 0.25, rocker 0.2, frame 0.4 (s + l = 0.6 > p + q = 0.55)
    let def = MechanismDef {
        fixed: vec![("O".into(), v(0.0, 0.0)), ("D".into(), v(0.4, 0.0))],
        links: vec![
            LinkDef::bar("1", "O", "A", 0.3),
            LinkDef::bar("2", "A", "C", 0.25),
            LinkDef::bar("3", "D", "C", 0.2),
        ],
        input: input(2.0),
        ..Default::default()
    };
    let m = Mechanism::new(&def).unwrap();
    // a full turn is still refused, with the ranges
    let e = Cycle::new(&m, Working::Slower).unwrap_err();
    assert!(matches!(e, LinkageError::AssemblyRanges { .. }), "{e}");
    // |OC|... the assembly limit: |AD|² = 0.25 − 0.24 cos φ ≤ (0.25 + 0.2)²
    let lim = ((0.25f64 - 0.45 * 0.45) / 0.24).acos();
    let p = PartialCycle::new(&m).unwrap();
    assert_eq!(p.ranges.len(), 1);
    assert_eq!(p.map.gaps.len(), 1);
    let r = p.ranges[0].range;
    assert!(
        (r.from - (TAU - lim)).abs() < 1e-6 && (r.to - (TAU + lim)).abs() < 1e-6,
        "{r:?} vs ±{lim}"
    );
    assert!((p.map.gaps[0].from - lim).abs() < 1e-6 && (p.map.gaps[0].to - (TAU - lim)).abs() < 1e-6);
    // the rocker's dead positions inside: crank and coupler in line, |OC| = 0.55
    assert!(!p.ranges[0].dead.is_empty());
    let mut s = m.solution();
    let c = m.point("C").unwrap();
    for &d in &p.ranges[0].dead {
        m.solve(d, &mut s).unwrap();
        assert!((s.points[c].p.hypot() - 0.55).abs() < 1e-9, "{}", s.points[c].p.hypot());
    }
    // every listed position solves, ends included
    for (_, phi) in p.positions(13) {
        m.solve(phi, &mut s).unwrap();
    }
    assert!(p.ranges[0].s_max > p.ranges[0].s_min);
    // a crank that turns fully gives one range of a whole turn
    let p = PartialCycle::new(&Mechanism::new(&common_fourbar()).unwrap()).unwrap();
    assert!(p.map.full_turn() && (p.ranges[0].range.span() - TAU).abs() < 1e-15);
    assert_eq!(p.ranges[0].dead.len(), 2);
}

#[test]
fn link_length_is_the_largest_distance_between_its_points() {
    // seed 003's rocker E–B–C with B and C 0.6 m either side of E: |BC| = 1.2
    let m = common::seed003();
    assert!((tmm_linkage::forces::loads::link_length(&m, m.link("3").unwrap()) - 1.2).abs() < 1e-12);
    assert!((tmm_linkage::forces::loads::link_length(&m, m.link("2").unwrap()) - 1.25).abs() < 1e-12);
}

#[test]
fn block_centres_of_mass_are_exposed() {
    let m = common::seed004();
    let mut s = m.solution();
    m.solve(0.7, &mut s).unwrap();
    for name in ["3", "5"] {
        let l = m.link(name).unwrap();
        let joint = m.points.iter().position(|p| p.link == l).unwrap();
        let sc = m.mass_center(&s, l);
        assert!((sc.p - s.points[joint].p).hypot() < 1e-15);
        assert!((sc.a - s.points[joint].a).hypot() < 1e-12);
    }
}

#[test]
fn double_parallelogram_assembled_flat_is_still_counted_by_rank() {
    // the task file's double parallelogram: frame A(0,0), D(0.3,0), E(0.15,0);
    // cranks AB, DC, EF of 0.1 m, coupler B–F–C of 0.3 m with F its middle.
    // The assembly angle φ = 0 lays every link on the frame line, where the
    // solve of all pairs can land on a locked configuration of full rank; the
    // count met at most crank angles is the mechanism's: W = 0, mobility 1, q = 1
    let coupler = LinkDef {
        name: "2".into(),
        points: vec![("B".into(), v(0.0, 0.0)), ("C".into(), v(0.3, 0.0)), ("F".into(), v(0.15, 0.0))],
        mass_center: v(0.15, 0.0),
    };
    for phi in [0.0, 0.5] {
        let def = MechanismDef {
            fixed: vec![("A".into(), v(0.0, 0.0)), ("D".into(), v(0.3, 0.0)), ("E".into(), v(0.15, 0.0))],
            links: vec![
                LinkDef::bar("1", "A", "B", 0.1),
                coupler.clone(),
                LinkDef::bar("3", "D", "C", 0.1),
                LinkDef::bar("4", "E", "F", 0.1),
            ],
            input: Some(InputDef {
                link: "1".into(),
                pivot: "A".into(),
                pin: "B".into(),
                omega: 10.0,
                epsilon: 0.0,
            }),
            hints: vec![AssemblyHint {
                point: "C".into(),
                kind: HintKind::Above("A".into(), "D".into()),
            }],
            assembly_angle: phi,
            ..Default::default()
        };
        match Mechanism::new(&def).unwrap_err() {
            LinkageError::Redundant {
                w,
                dof,
                redundant,
                passive,
                detail,
                ..
            } => {
                assert_eq!((w, dof, redundant, passive), (0, 1, 1, 0), "φ = {phi}");
                assert!(detail.contains("link `4` (E–F)"), "{detail}");
            }
            other => panic!("φ = {phi}: {other}"),
        }
    }
}
