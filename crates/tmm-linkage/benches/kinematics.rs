//! Full kinematic solve (positions, velocities, accelerations of every link
//! and point) over one revolution of 3600 positions: the seed-001 four-bar and
//! the seed-003 six-bar.

use std::f64::consts::TAU;

use divan::black_box;
use tmm_linkage::Mechanism;

#[path = "../tests/common/mod.rs"]
mod common;

fn main() {
    divan::main();
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
    revolution(&common::seed001(), bencher);
}

/// Seed-001 four-bar, 3600 independent solves.
#[divan::bench]
fn fourbar_each_angle(bencher: divan::Bencher) {
    each_angle(&common::seed001(), bencher);
}

/// Seed-003 six-bar, 3600 positions in one sweep.
#[divan::bench]
fn sixbar_revolution(bencher: divan::Bencher) {
    revolution(&common::seed003(), bencher);
}

/// Seed-003 six-bar, 3600 independent solves.
#[divan::bench]
fn sixbar_each_angle(bencher: divan::Bencher) {
    each_angle(&common::seed003(), bencher);
}
