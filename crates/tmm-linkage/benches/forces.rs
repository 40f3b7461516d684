//! Kinetostatics of the seed-003 six-bar over one revolution of 3600
//! positions: the reactions of all groups, the balancing torque and the
//! Zhukovsky check at each, from precomputed kinematics; the same with the
//! kinematics solved in the loop; and the kinematics alone, in the same run,
//! so that `scripts/bench-ratios.sh` can print what the forces cost relative
//! to the kinematics measured side by side (a ratio a busy machine cannot
//! distort the way it distorts absolute times).

use std::f64::consts::TAU;

use divan::black_box;
use tmm_geom::Vec2;
use tmm_linkage::forces::{Action, Kinetostatics, Law, Loads, Resistance};
use tmm_linkage::{Mechanism, Solution};

#[path = "../tests/common/mod.rs"]
mod common;

fn main() {
    divan::main();
}

/// The seed-003 loads: 30 kg/m, J = m·l²/12, gravity, 3000 N·sin(π·s/H).
fn loads(m: &Mechanism) -> Loads {
    let mut l = Loads::new(m);
    l.gravity = Vec2::new(0.0, -9.81);
    for (i, mass, len) in [(2, 37.5, 1.25), (3, 18.0, 0.6), (4, 19.5, 0.65), (5, 19.5, 0.0)] {
        l.links[i].mass = mass;
        l.links[i].inertia = mass * len * len / 12.0;
    }
    l.resistance.push(Resistance {
        link: 5,
        action: Action::Force {
            local: Vec2::ZERO,
            dir: None,
        },
        law: Law::SineOfTravel(3000.0),
    });
    l
}

const N: usize = 3600;

#[divan::bench]
fn reactions_3600_positions(bencher: divan::Bencher) {
    let m = common::seed003();
    let mut k = Kinetostatics::new(&m, loads(&m)).unwrap();
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
    let mut k = Kinetostatics::new(&m, loads(&m)).unwrap();
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
