//! Full kinematic solve (positions, velocities, accelerations of every link
//! and point) over one revolution of 3600 positions: the seed-001 four-bar and
//! the seed-003 six-bar.

use std::f64::consts::TAU;

use divan::black_box;
use tmm_geom::Vec2;
use tmm_linkage::{AssemblyHint, HintKind, InputDef, LinkDef, Mechanism, MechanismDef, SliderDef};

fn main() {
    divan::main();
}

fn fourbar() -> Mechanism {
    Mechanism::new(&MechanismDef {
        fixed: vec![("A".into(), Vec2::new(0.0, 0.0)), ("D".into(), Vec2::new(0.51, 0.0))],
        links: vec![
            LinkDef::bar("1", "A", "B", 0.12),
            LinkDef::bar("2", "B", "C", 0.48),
            LinkDef::bar("3", "D", "C", 0.38),
        ],
        input: Some(InputDef {
            link: "1".into(),
            pivot: "A".into(),
            pin: "B".into(),
            omega: 94.25,
            epsilon: 0.0,
        }),
        hints: vec![AssemblyHint {
            point: "C".into(),
            kind: HintKind::Below("A".into(), "D".into()),
        }],
        ..Default::default()
    })
    .unwrap()
}

fn sixbar() -> Mechanism {
    let mut rocker = LinkDef::bar("3", "E", "B", 0.6);
    rocker.points.push(("C".into(), Vec2::new(-0.6, 0.0)));
    Mechanism::new(&MechanismDef {
        fixed: vec![("O".into(), Vec2::new(-1.25, 0.0)), ("E".into(), Vec2::new(0.0, 0.0))],
        links: vec![
            LinkDef::bar("1", "O", "A", 0.27),
            LinkDef::bar("2", "A", "B", 1.25),
            rocker,
            LinkDef::bar("4", "C", "D", 0.65),
            LinkDef::block("5", "D"),
        ],
        sliders: vec![SliderDef {
            slider: "5".into(),
            point: "D".into(),
            guide_link: "frame".into(),
            through: Vec2::new(0.0, -0.2),
            angle: 0.0,
            angle_on_slider: 0.0,
        }],
        input: Some(InputDef {
            link: "1".into(),
            pivot: "O".into(),
            pin: "A".into(),
            omega: 12.0,
            epsilon: 0.0,
        }),
        hints: vec![
            AssemblyHint {
                point: "B".into(),
                kind: HintKind::Above("O".into(), "E".into()),
            },
            AssemblyHint {
                point: "D".into(),
                kind: HintKind::Near(Vec2::new(0.5, -0.2)),
            },
        ],
        ..Default::default()
    })
    .unwrap()
}

const N: usize = 3600;

/// One revolution as a sweep (the course's positions, the diagrams).
fn revolution(m: &Mechanism, bencher: divan::Bencher) {
    let mut sol = m.solution();
    bencher.counter(divan::counter::ItemsCount::new(N)).bench_local(|| {
        let mut acc = 0.0;
        m.sweep(black_box(0.0), TAU / N as f64, N, &mut sol, |_, s| {
            acc += s.points[s.points.len() - 1].a.x
        })
        .unwrap();
        black_box(acc)
    });
}

/// One revolution by independent solves at each angle (random access).
fn each_angle(m: &Mechanism, bencher: divan::Bencher) {
    let mut sol = m.solution();
    bencher.counter(divan::counter::ItemsCount::new(N)).bench_local(|| {
        let mut acc = 0.0;
        for k in 0..N {
            let phi = TAU * k as f64 / N as f64;
            m.solve(black_box(phi), &mut sol).unwrap();
            acc += sol.points[sol.points.len() - 1].a.x;
        }
        black_box(acc)
    });
}

/// Seed-001 four-bar, 3600 positions in one sweep.
#[divan::bench]
fn fourbar_revolution(bencher: divan::Bencher) {
    revolution(&fourbar(), bencher);
}

/// Seed-001 four-bar, 3600 independent solves.
#[divan::bench]
fn fourbar_each_angle(bencher: divan::Bencher) {
    each_angle(&fourbar(), bencher);
}

/// Seed-003 six-bar, 3600 positions in one sweep.
#[divan::bench]
fn sixbar_revolution(bencher: divan::Bencher) {
    revolution(&sixbar(), bencher);
}

/// Seed-003 six-bar, 3600 independent solves.
#[divan::bench]
fn sixbar_each_angle(bencher: divan::Bencher) {
    each_angle(&sixbar(), bencher);
}
