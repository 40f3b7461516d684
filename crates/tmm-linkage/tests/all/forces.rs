//! Kinetostatics checked against independent references: virtual power
//! computed here from the kinematics, free bodies summed here, a crank-slider
//! solved by hand, seed 001 sheet 3 recomputed from its own data with
//! kinematics by finite differences, and the beam diagrams' closure and M' = Q.

use crate::common;

use common::*;
use tmm_geom::{Vec2, cross};
use tmm_linkage::forces::{Action, Beam, ForceError, Kinetostatics, Law, Loads, PointForce, Resistance, size_sections};
use tmm_linkage::mechanism::Pair;
use tmm_linkage::{InputDef, LinkDef, Mechanism, MechanismDef, SliderDef};

/// Virtual power of all given loads at a solved position, computed here from
/// the link states (not from the crate's reductions).
fn power(
    m: &Mechanism,
    loads: &Loads,
    sol: &tmm_linkage::Solution,
    extra: impl Fn(usize, &tmm_linkage::LinkState) -> (Vec2, Vec2, f64),
) -> (f64, f64) {
    let (mut p, mut scale) = (0.0, 0.0);
    for i in 1..m.link_names.len() {
        let s = &sol.links[i];
        let ld = &loads.links[i];
        let sp = s.o + tmm_linkage::state::rot(s.u, m.mass_centers[i]);
        let d = sp - s.o;
        let vs = s.v + tmm_geom::perp(d) * s.omega;
        let as_ = s.a + tmm_geom::perp(d) * s.eps - d * (s.omega * s.omega);
        let terms = [
            (loads.gravity * ld.mass - as_ * ld.mass).dot(vs),
            (ld.moment - ld.inertia * s.eps) * s.omega,
            ld.forces.iter().map(|f| f.force.dot(s.point(f.local).v)).sum::<f64>(),
        ];
        let (f, at, c) = extra(i, s);
        let t4 = f.dot(s.v + tmm_geom::perp(at - s.o) * s.omega) + c * s.omega;
        for t in terms.into_iter().chain([t4]) {
            p += t;
            scale += t.abs();
        }
    }
    (p, scale)
}

/// Σ forces and Σ moments (about the origin) on a set of links from the
/// solution's loads and reactions.
fn free_body(m: &Mechanism, f: &tmm_linkage::forces::ForceSolution, links: &[usize]) -> (Vec2, f64, f64) {
    let (mut sf, mut sm, mut scale) = (Vec2::ZERO, 0.0, 0.0);
    for &l in links {
        let lf = &f.links[l];
        sf += lf.force;
        sm += lf.moment + cross(lf.s, lf.force);
        scale += lf.force.hypot() * (1.0 + lf.s.hypot()) + lf.moment.abs();
    }
    for r in &f.reactions {
        for (link, sign) in [(r.on, 1.0), (r.from, -1.0)] {
            if links.contains(&link) {
                sf += r.force * sign;
                sm += cross(r.at, r.force * sign);
                scale += r.force.hypot() * (1.0 + r.at.hypot());
            }
        }
    }
    let _ = m;
    (sf, sm, scale)
}

fn all_examples() -> Vec<(&'static str, Mechanism)> {
    vec![
        ("seed001", seed001()),
        ("seed003", seed003()),
        ("seed004", seed004()),
        ("triad", triad()),
        ("slotted", slotted()),
    ]
}

#[test]
fn virtual_power_balances_at_every_position_of_every_example() {
    let mut rng = Rng(0x1234_5678_9abc_def1);
    for (name, m) in all_examples() {
        for trial in 0..3 {
            let loads = random_loads(&m, &mut rng);
            let mut k = Kinetostatics::new(&m, loads.clone()).unwrap();
            let mut sol = m.solution();
            let mut f = k.result();
            let mut solved = 0;
            for i in 0..72 {
                let phi = m.assembly_angle + (i as f64 + 0.37) * 5f64.to_radians();
                k.solve_at(phi, &mut sol, &mut f).unwrap_or_else(|e| panic!("{name} φ={phi}: {e}"));
                let w1 = sol.links[m.crank.link].omega;
                let (p, scale) = power(&m, &loads, &sol, |_, _| (Vec2::ZERO, Vec2::ZERO, 0.0));
                // M_b·ω1 + Σ F·v + Σ M·ω = 0
                let resid = f.balancing_moment * w1 + p;
                assert!(
                    resid.abs() <= 1e-9 * (scale + (f.balancing_moment * w1).abs()),
                    "{name} trial {trial} φ={phi}: {resid} vs {scale}"
                );
                assert!(f.relative_difference() < 1e-9 || (f.balancing_moment - f.zhukovsky_moment).abs() < 1e-9 * scale / w1.abs());
                let zh = tmm_linkage::forces::zhukovsky::balancing_moment(&m, &loads, &sol, &f.resistance);
                assert!((zh - f.zhukovsky_moment).abs() <= 1e-9 * scale / w1.abs());
                solved += 1;
            }
            assert_eq!(solved, 72, "{name}: every position solves");
        }
    }
}

#[test]
fn every_group_and_link_free_body_sums_to_zero() {
    let mut rng = Rng(0xdead_beef_cafe_f00d);
    for (name, m) in all_examples() {
        let loads = random_loads(&m, &mut rng);
        let mut k = Kinetostatics::new(&m, loads).unwrap();
        let mut sol = m.solution();
        let mut f = k.result();
        for i in 0..24 {
            let phi = m.assembly_angle + (i as f64 + 0.21) * 15f64.to_radians();
            k.solve_at(phi, &mut sol, &mut f).unwrap_or_else(|e| panic!("{name} φ={phi}: {e}"));
            let mut sets: Vec<Vec<usize>> = m.groups.iter().map(|g| g.info.link_ids.clone()).collect();
            sets.extend((1..m.link_names.len()).map(|l| vec![l]).filter(|s| s[0] != m.crank.link));
            for s in &sets {
                let (sf, sm, scale) = free_body(&m, &f, s);
                assert!(sf.hypot() <= 1e-9 * scale && sm.abs() <= 1e-9 * scale, "{name} {s:?}: {sf:?} {sm}");
            }
            // the crank: its loads, reactions and the balancing torque
            let (sf, sm, scale) = free_body(&m, &f, &[m.crank.link]);
            assert!(sf.hypot() <= 1e-9 * scale, "{name} crank force");
            assert!(
                (sm + f.balancing_moment).abs() <= 1e-9 * (scale + f.balancing_moment.abs()),
                "{name} crank moment"
            );
            // prismatic reactions are normal to their guides (no friction)
            for r in f.reactions.iter().filter(|r| r.prismatic) {
                if let Pair::P { guide, d, .. } = m.pairs[r.pair] {
                    let dg = tmm_linkage::state::rot(sol.links[guide].u, d);
                    assert!(r.force.dot(dg).abs() <= 1e-9 * r.force.hypot().max(1.0));
                }
            }
        }
    }
}

/// A crank-slider at rest, solved by hand: crank OA = r at φ, rod AB = l
/// (massless), slider B on the x-axis with mass m3 under gravity and a
/// horizontal force P acting at a point h above B. The crank has mass m1 at
/// its middle. With sin β = r·sin φ / l:
/// rod force S = P / cos β (compression), guide force N = P·tan β + m3·g,
/// acting at x = −h·P/N along the guide from B, and the balancing torque
/// M_b = −S·r·sin(φ + β) + m1·g·(r/2)·cos φ.
#[test]
fn crank_slider_static_case_by_hand() {
    let (r, l, phi, p, h, m1, m3, g) = (0.1, 0.35, 50f64.to_radians(), 800.0, 0.02, 2.0, 3.0, 9.81);
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
            through: v(0.0, 0.0),
            angle: 0.0,
            angle_on_slider: 0.0,
        }],
        input: Some(InputDef {
            link: "1".into(),
            pivot: "O".into(),
            pin: "A".into(),
            omega: 1e-7,
            epsilon: 0.0,
        }),
        hints: vec![tmm_linkage::AssemblyHint {
            point: "B".into(),
            kind: tmm_linkage::HintKind::Near(v(0.4, 0.0)),
        }],
        ..Default::default()
    };
    let m = Mechanism::new(&def).unwrap();
    let mut loads = Loads::new(&m);
    loads.gravity = v(0.0, -g);
    loads.links[1].mass = m1;
    loads.links[3].mass = m3;
    loads.links[3].forces.push(PointForce {
        local: v(0.0, h),
        force: v(-p, 0.0),
    });
    let mut k = Kinetostatics::new(&m, loads).unwrap();
    let mut sol = m.solution();
    let mut f = k.result();
    k.solve_at(phi, &mut sol, &mut f).unwrap();
    let beta = (r * phi.sin() / l).asin();
    let s = p / beta.cos();
    let n = p * beta.tan() + m3 * g;
    let mb = -s * r * (phi + beta).sin() + m1 * g * (r / 2.0) * phi.cos();
    assert!((f.balancing_moment - mb).abs() < 1e-9 * mb.abs(), "{} vs {mb}", f.balancing_moment);
    let guide = f.reactions.iter().find(|x| x.prismatic).unwrap();
    assert_eq!((guide.from, guide.on), (0, 3));
    assert!((guide.force - v(0.0, n)).hypot() < 1e-9 * n);
    assert!((guide.offset - (-h * p / n)).abs() < 1e-12);
    // rod on slider at B: S along A→B
    let b = f.reactions.iter().find(|x| !x.prismatic && (x.on == 3 || x.from == 3)).unwrap();
    let ab = sol.points[m.point("B").unwrap()].p - sol.points[m.point("A").unwrap()].p;
    let on3 = if b.on == 3 { b.force } else { -b.force };
    assert!((on3 - ab * (s / l)).hypot() < 1e-9 * s);
    // balancing force at the pin ⟂ crank: M_b / r
    assert!((f.balancing_force - mb / r).abs() < 1e-9 * (mb / r).abs());
}

/// Seed 001 sheet 3 redone exactly. The kinematics here is independent of
/// the crate: positions by intersecting circles, velocities and accelerations
/// by central finite differences in φ. Loads as the seed: 10 kg/m, J_S =
/// 0.1·m·l², S mid-link, no gravity, 380 N·m on the rocker against its
/// rotation, ω1 = 900 rpm constant, φ1 = 15°.
#[test]
fn seed001_sheet3_balancing_force_by_independent_virtual_power() {
    let m = seed001();
    let w1 = 900.0 * std::f64::consts::PI / 30.0;
    let lens = [0.12, 0.48, 0.38];
    let mut k = Kinetostatics::new(&m, seed001_loads(&m)).unwrap();
    let mut sol = m.solution();
    let mut f = k.result();
    let phi = 15f64.to_radians();
    k.solve_at(phi, &mut sol, &mut f).unwrap();

    // independent positions: B on the crank, C below AD on circles about B and D
    let pos = |t: f64| {
        let b = v(0.12 * t.cos(), 0.12 * t.sin());
        let d = v(0.51, 0.0);
        let bd = d - b;
        let dist = bd.hypot();
        let x = (0.48f64.powi(2) - 0.38f64.powi(2) + dist * dist) / (2.0 * dist);
        let y = (0.48f64.powi(2) - x * x).sqrt();
        let e = bd * (1.0 / dist);
        let n = v(-e.y, e.x);
        let c1 = b + e * x + n * y;
        let c2 = b + e * x - n * y;
        let c = if c1.y < c2.y { c1 } else { c2 };
        (b, c)
    };
    let hh = 1e-4;
    // time derivatives from φ-derivatives: d/dt = ω1·d/dφ (ε1 = 0)
    let centres = |t: f64| {
        let (b, c) = pos(t);
        let th2 = (c - b).y.atan2((c - b).x);
        let th3 = (c - v(0.51, 0.0)).y.atan2((c - v(0.51, 0.0)).x);
        [b * 0.5, (b + c) * 0.5, (c + v(0.51, 0.0)) * 0.5, v(th2, 0.0), v(th3, 0.0), c]
    };
    let (xm, x0, xp) = (centres(phi - hh), centres(phi), centres(phi + hh));
    let vel = |i: usize| (xp[i] - xm[i]) * (w1 / (2.0 * hh));
    let acc = |i: usize| (xp[i] - x0[i] * 2.0 + xm[i]) * (w1 * w1 / (hh * hh));
    let mut pw = 0.0;
    for (i, &len) in lens.iter().enumerate() {
        let mass = 10.0 * len;
        let j = 0.1 * mass * len * len;
        let omega = if i == 0 { w1 } else { vel(i + 2).x };
        let eps = if i == 0 { 0.0 } else { acc(i + 2).x };
        pw += (-acc(i) * mass).dot(vel(i)) + (-j * eps) * omega;
    }
    let w3 = vel(4).x;
    pw += -380.0 * w3.signum() * w3;
    let mb = -pw / w1;
    let pb = mb / 0.12;
    // the finite differences are accurate to about 1e-7 relative
    assert!(
        (f.balancing_moment - mb).abs() < 1e-6 * mb.abs(),
        "kinetostatics {} vs virtual power {mb}",
        f.balancing_moment
    );
    assert!((f.balancing_force - pb).abs() < 1e-6 * pb.abs());
    assert!(f.relative_difference() < 1e-12);
    // the rocker's own check: its speed matches the seed's plan within the seed's 1–2 %
    let vc = vel(5).hypot();
    assert!((vc - 13.23).abs() / 13.23 < 0.03, "v_C = {vc}");
}

#[test]
fn seed001_dyad_reactions_by_the_course_method() {
    // RRR dyad BC–DC: R^τ_12 from moments of link 2 about C, R^τ_03 from
    // moments of link 3 about C, R^n from the force polygon (projections).
    let m = seed001();
    let mut loads = Loads::new(&m);
    for (i, l) in [(1, 0.12), (2, 0.48), (3, 0.38)] {
        loads.links[i].mass = 10.0 * l;
        loads.links[i].inertia = 0.1 * 10.0 * l * l * l;
    }
    loads.resistance.push(Resistance {
        link: 3,
        action: Action::Moment { sign: None },
        law: Law::Constant(380.0),
    });
    let mut k = Kinetostatics::new(&m, loads).unwrap();
    let mut sol = m.solution();
    let mut f = k.result();
    k.solve_at(15f64.to_radians(), &mut sol, &mut f).unwrap();
    let p = |n: &str| sol.points[m.point(n).unwrap()].p;
    let (b, c, d) = (p("B"), p("C"), p("D"));
    let (l2, l3) = (&f.links[2], &f.links[3]);
    // moments about C of link 2: M2 + (S2−C)×F2 + (B−C)×R12 = 0, R12 = Rn·e + Rτ·n
    let e2 = (c - b) * (1.0 / 0.48);
    let n2 = v(-e2.y, e2.x);
    let rt12 = -(l2.moment + cross(l2.s - c, l2.force)) / cross(b - c, n2);
    let e3 = (c - d) * (1.0 / 0.38);
    let n3 = v(-e3.y, e3.x);
    let rt03 = -(l3.moment + cross(l3.s - c, l3.force)) / cross(d - c, n3);
    // polygon: Rn12·e2 + Rn03·e3 = −(F2 + F3 + Rτ12·n2 + Rτ03·n3)
    let rhs = -(l2.force + l3.force + n2 * rt12 + n3 * rt03);
    let det = cross(e2, e3);
    let rn12 = cross(rhs, e3) / det;
    let rn03 = cross(e2, rhs) / det;
    let r12 = e2 * rn12 + n2 * rt12;
    let r03 = e3 * rn03 + n3 * rt03;
    let find = |from: usize, on: usize| {
        let r = f
            .reactions
            .iter()
            .find(|r| (r.from, r.on) == (from, on) || (r.from, r.on) == (on, from))
            .unwrap();
        if r.on == on { r.force } else { -r.force }
    };
    assert!((find(1, 2) - r12).hypot() < 1e-9 * r12.hypot());
    assert!((find(0, 3) - r03).hypot() < 1e-9 * r03.hypot());
    // the split reported for the pair on link 2 at B (axis of link 2 is B→C)
    let rb = f.reactions.iter().find(|r| r.on == 2 && r.from == 1).unwrap();
    assert!((rb.normal - rn12).abs() < 1e-9 * r12.hypot() && (rb.tangential - rt12).abs() < 1e-9 * r12.hypot());
}

#[test]
fn beam_diagrams_close_and_moment_derivative_is_shear() {
    let mut rng = Rng(42);
    for (name, m, link) in [
        ("seed004", seed004(), "4"),
        ("seed001", seed001(), "2"),
        ("seed003", seed003(), "3"),
    ] {
        let mut loads = random_loads(&m, &mut rng);
        let li = m.link(link).unwrap();
        // S mid-way so the rod model is uniform except seed003's rocker (S at E, the middle)
        loads.links[li].forces[0].local = v(0.3 * rng.uniform(), 0.0);
        let mut k = Kinetostatics::new(&m, loads.clone()).unwrap();
        let mut sol = m.solution();
        let mut f = k.result();
        k.solve_at(m.assembly_angle + 0.7, &mut sol, &mut f).unwrap();
        let pts: Vec<Vec2> = m
            .pairs
            .iter()
            .filter_map(|p| match *p {
                Pair::R { a, b, la, lb, .. } => {
                    if a == li {
                        Some(la)
                    } else if b == li {
                        Some(lb)
                    } else {
                        None
                    }
                }
                _ => None,
            })
            .collect();
        let (mut a, mut b) = (pts[0], pts[1]);
        for p in &pts {
            for q in &pts {
                if (*p - *q).hypot() > (a - b).hypot() {
                    a = *p;
                    b = *q;
                }
            }
        }
        let beam = Beam::new(&m, &loads, &sol, &f, li, a, b).unwrap();
        let scale: f64 = beam.loads.iter().map(|l| l.fe.abs() + l.fn_.abs()).sum::<f64>() + 1.0;
        let c = beam.closure();
        assert!(
            c.n.abs() < 1e-9 * scale && c.q.abs() < 1e-9 * scale && c.m.abs() < 1e-9 * scale * beam.length,
            "{name}: {c:?}"
        );
        // dM/dz = Q between loads, by central differences
        let zs: Vec<f64> = beam.loads.iter().map(|l| l.z).collect();
        let (z0, z1) = beam.z_range;
        for i in 1..50 {
            let z = z0 + (z1 - z0) * i as f64 / 50.0;
            let hz = 1e-6 * beam.length;
            if zs.iter().any(|&zl| (zl - z).abs() < 2.0 * hz) {
                continue;
            }
            let dm = (beam.at(z + hz, true).m - beam.at(z - hz, true).m) / (2.0 * hz);
            let q = beam.at(z, true).q;
            assert!((dm - q).abs() < 1e-5 * scale, "{name} z={z}: {dm} vs {q}");
        }
        // the distributed load integrates to the link's weight + inertia resultant (rod model)
        let s = size_sections(&beam.diagrams(400), 120e6, 2.0).unwrap();
        assert!(s.round_d > 0.0 && (s.rect_h - 2.0 * s.rect_b).abs() < 1e-15);
    }
}

#[test]
fn uniform_rotating_rod_inertia_is_linearly_distributed() {
    // crank of mass m turning at ω about its pivot, nothing else: the rod's
    // inertia load is q(z) = ρ·ω²·z along the rod (outward), so
    // N(z) = −∫₀^z ρω²t dt = … and at the pivot the reaction m·ω²·L/2 pulls in.
    // With the section cut at z the outer part pulls: N(z) = ρω²(L² − z²)/2.
    let def = MechanismDef {
        fixed: vec![("O".into(), v(0.0, 0.0)), ("D".into(), v(0.3, 0.0))],
        links: vec![
            LinkDef::bar("1", "O", "A", 0.2),
            LinkDef::bar("2", "A", "B", 0.3),
            LinkDef::bar("3", "D", "B", 0.3),
        ],
        input: Some(InputDef {
            link: "1".into(),
            pivot: "O".into(),
            pin: "A".into(),
            omega: 30.0,
            epsilon: 0.0,
        }),
        ..Default::default()
    };
    let m = Mechanism::new(&def).unwrap();
    let mut loads = Loads::new(&m);
    let (mass, len, w) = (2.0, 0.2, 30.0);
    loads.links[1].mass = mass;
    loads.links[1].inertia = mass * len * len / 12.0;
    let mut k = Kinetostatics::new(&m, loads.clone()).unwrap();
    let mut sol = m.solution();
    let mut f = k.result();
    k.solve_at(0.4, &mut sol, &mut f).unwrap();
    let beam = Beam::new(&m, &loads, &sol, &f, 1, v(0.0, 0.0), v(len, 0.0)).unwrap();
    let rho = mass / len;
    for z in [0.03, 0.1, 0.17] {
        let s = beam.at(z, true);
        assert!((s.n - rho * w * w * (len * len - z * z) / 2.0).abs() < 1e-9, "{} at {z}", s.n);
        assert!(s.q.abs() < 1e-9 && s.m.abs() < 1e-9);
    }
}

#[test]
fn bad_loads_are_reported() {
    let m = seed001();
    let mut loads = Loads::new(&m);
    loads.links[2].mass = -1.0;
    let e = Kinetostatics::new(&m, loads).unwrap_err();
    assert!(matches!(&e, ForceError::Load { field, .. } if field == "links.2.mass"), "{e}");
    // a load diagram that stops short of the stroke
    let m = seed003();
    let mut loads = Loads::new(&m);
    loads.resistance.push(Resistance {
        link: 5,
        action: Action::Force {
            local: v(0.0, 0.0),
            dir: None,
        },
        law: Law::TravelTable(vec![(0.0, 100.0), (0.05, 100.0)]),
    });
    let e = Kinetostatics::new(&m, loads).unwrap_err();
    assert!(e.to_string().contains("covers travel"), "{e}");
    // a malformed table
    let mut loads = Loads::new(&m);
    loads.resistance.push(Resistance {
        link: 5,
        action: Action::Force {
            local: v(0.0, 0.0),
            dir: None,
        },
        law: Law::TravelTable(vec![(0.0, 1.0), (0.0, 2.0)]),
    });
    assert!(Kinetostatics::new(&m, loads).is_err());
}

#[test]
fn seed003_sine_resistance_acts_on_the_working_stroke_only() {
    let m = seed003();
    let mut loads = Loads::new(&m);
    loads.resistance.push(Resistance {
        link: 5,
        action: Action::Force {
            local: v(0.0, 0.0),
            dir: None,
        },
        law: Law::SineOfTravel(3000.0),
    });
    let mut k = Kinetostatics::new(&m, loads).unwrap();
    let st = k.stroke.clone().unwrap();
    // the working stroke is the slower one
    assert!(st.work_span > std::f64::consts::PI);
    let mut sol = m.solution();
    let mut f = k.result();
    let (mut work, mut ret) = (0, 0);
    for i in 0..36 {
        let phi = st.phi_start + m.crank.omega.signum() * (i as f64 + 0.5) * 10f64.to_radians();
        k.solve_at(phi, &mut sol, &mut f).unwrap();
        let ph = f.phase.unwrap();
        let expect = if ph.working {
            3000.0 * (std::f64::consts::PI * ph.travel / st.travel).sin()
        } else {
            0.0
        };
        assert!((f.resistance[0] - expect).abs() < 1e-9);
        // travel from the dead position, computed here from the slider's x
        if ph.working { work += 1 } else { ret += 1 }
    }
    assert!(work > ret);
}

#[test]
fn dyad_elimination_agrees_with_the_general_group_solve() {
    let mut rng = Rng(7);
    for (name, m) in all_examples() {
        let loads = random_loads(&m, &mut rng);
        let mut fast = Kinetostatics::new(&m, loads.clone()).unwrap();
        let mut slow = Kinetostatics::new(&m, loads).unwrap();
        slow.general = true;
        let (mut s1, mut f1, mut f2) = (m.solution(), fast.result(), slow.result());
        for i in 0..36 {
            let phi = m.assembly_angle + (i as f64 + 0.5) * 10f64.to_radians();
            fast.solve_at(phi, &mut s1, &mut f1)
                .unwrap_or_else(|e| panic!("{name} φ={phi}: {e}"));
            slow.solve(&s1, &mut f2).unwrap();
            let scale = f2.reactions.iter().map(|r| r.force.hypot()).fold(1.0, f64::max);
            for (a, b) in f1.reactions.iter().zip(&f2.reactions) {
                assert!(
                    (a.force - b.force).hypot() < 1e-9 * scale && (a.offset - b.offset).abs() < 1e-9 * (1.0 + a.offset.abs()),
                    "{name} φ={phi}"
                );
            }
            assert!((f1.balancing_moment - f2.balancing_moment).abs() < 1e-9 * f2.balancing_moment.abs().max(1.0));
        }
    }
}

/// An RRP dyad whose guide is on a moving link: a four-bar O–A–B–E whose
/// rocker 3 (E–B) carries the guide of block 5, joined at D to link 4
/// pivoted at F on the frame. The dyad's written-out reactions against the
/// general Jᵀλ solve, and the whole mechanism's balancing torque against
/// virtual power computed here, at every position that assembles.
#[test]
fn rrp_dyad_on_a_moving_guide_agrees_with_the_general_solve_and_virtual_power() {
    let def = MechanismDef {
        fixed: vec![("O".into(), v(0.0, 0.0)), ("E".into(), v(0.4, 0.0)), ("F".into(), v(0.45, 0.3))],
        links: vec![
            LinkDef::bar("1", "O", "A", 0.1),
            LinkDef::bar("2", "A", "B", 0.45),
            LinkDef::bar("3", "E", "B", 0.35),
            LinkDef::bar("4", "F", "D", 0.2),
            LinkDef::block("5", "D"),
        ],
        sliders: vec![SliderDef {
            slider: "5".into(),
            point: "D".into(),
            guide_link: "3".into(),
            through: v(0.0, 0.0),
            angle: 0.0,
            angle_on_slider: 0.0,
        }],
        input: Some(InputDef {
            link: "1".into(),
            pivot: "O".into(),
            pin: "A".into(),
            omega: 8.0,
            epsilon: 3.0,
        }),
        hints: vec![
            tmm_linkage::AssemblyHint {
                point: "B".into(),
                kind: tmm_linkage::HintKind::Above("O".into(), "E".into()),
            },
            tmm_linkage::AssemblyHint {
                point: "D".into(),
                kind: tmm_linkage::HintKind::Near(v(0.3, 0.15)),
            },
        ],
        assembly_angle: 1.2,
        ..Default::default()
    };
    let m = Mechanism::new(&def).unwrap();
    let mut rng = Rng(99);
    let loads = random_loads(&m, &mut rng);
    let mut fast = Kinetostatics::new(&m, loads.clone()).unwrap();
    let mut slow = Kinetostatics::new(&m, loads.clone()).unwrap();
    slow.general = true;
    let (mut sol, mut f1, mut f2) = (m.solution(), fast.result(), slow.result());
    let mut solved = 0;
    for i in 0..72 {
        let phi = 1.2 + (i as f64 - 36.0) * 0.01;
        if m.solve(phi, &mut sol).is_err() {
            continue;
        }
        fast.solve(&sol, &mut f1).unwrap();
        slow.solve(&sol, &mut f2).unwrap();
        let scale = f2.reactions.iter().map(|r| r.force.hypot()).fold(1.0, f64::max);
        for (a, b) in f1.reactions.iter().zip(&f2.reactions) {
            assert!((a.force - b.force).hypot() < 1e-9 * scale, "φ={phi}");
            assert!((a.at - b.at).hypot() < 1e-9, "φ={phi}");
        }
        // M_b·ω1 + Σ F·v + Σ M·ω = 0
        let w1 = sol.links[m.crank.link].omega;
        let (p, scale) = power(&m, &loads, &sol, |_, _| (Vec2::ZERO, Vec2::ZERO, 0.0));
        let resid = f1.balancing_moment * w1 + p;
        assert!(
            resid.abs() <= 1e-9 * (scale + (f1.balancing_moment * w1).abs()),
            "φ={phi}: {resid} vs {scale}"
        );
        solved += 1;
    }
    assert!(solved > 36, "{solved} positions assembled");
}
