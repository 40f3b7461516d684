//! Kinetostatics of the seed-003 six-bar over one revolution of 3600
//! positions: the reactions of all groups, the balancing torque and the
//! Zhukovsky check at each, from precomputed kinematics; the same with the
//! kinematics solved in the loop; and the kinematics alone
//! (`benches/ratios.rs` measures the same loops in interleaved rounds and
//! prints their ratios, which a busy machine cannot distort the way it
//! distorts absolute times).

use std::f64::consts::TAU;

use divan::black_box;
use tmm_linkage::Solution;
use tmm_linkage::forces::Kinetostatics;

#[path = "../tests/common/mod.rs"]
mod common;

fn main() {
    divan::main();
}

const N: usize = 3600;

#[divan::bench]
fn reactions_3600_positions(bencher: divan::Bencher) {
    let m = common::seed003();
    let mut k = Kinetostatics::new(&m, common::seed003_example_loads(&m)).unwrap();
    let mut sol = m.solution();
    let sols: Vec<Solution> = (0..N)
        .map(|i| {
            m.solve(TAU * i as f64 / N as f64, &mut sol).unwrap();
            sol.clone()
        })
        .collect();
    let mut f = k.result();
    bencher.bench_local(|| {
        let mut acc = 0.0;
        for s in &sols {
            k.solve(s, &mut f).unwrap();
            acc += f.balancing_moment;
        }
        black_box(acc)
    });
}

#[divan::bench]
fn kinematics_and_reactions_3600_positions(bencher: divan::Bencher) {
    let m = common::seed003();
    let mut k = Kinetostatics::new(&m, common::seed003_example_loads(&m)).unwrap();
    let mut sol = m.solution();
    let mut f = k.result();
    bencher.bench_local(|| {
        let mut acc = 0.0;
        for i in 0..N {
            k.solve_at(TAU * i as f64 / N as f64, &mut sol, &mut f).unwrap();
            acc += f.balancing_moment;
        }
        black_box(acc)
    });
}

#[divan::bench]
fn kinematics_3600_positions(bencher: divan::Bencher) {
    let m = common::seed003();
    let mut sol = m.solution();
    bencher.bench_local(|| {
        let mut acc = 0.0;
        for i in 0..N {
            m.solve(TAU * i as f64 / N as f64, &mut sol).unwrap();
            acc += sol.links[5].a.x;
        }
        black_box(acc)
    });
}
