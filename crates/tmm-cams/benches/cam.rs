//! Sizing plus a 3600-point profile (the target: under 2 ms), and the
//! pieces on their own.

use divan::{Bencher, black_box};
use tmm_cams::design::{CamTask, FollowerSpec};
use tmm_cams::mechanism::{Mechanism, Rotation};
use tmm_cams::profile::Profile;
use tmm_cams::program::Program;
use tmm_cams::{sizing, spec};

fn main() {
    divan::main();
}

const SEED: &str = "rise 108 const-accel(u=1/3); dwell 15; return 108 const-accel(u=1/3); dwell 129";

fn task(follower: FollowerSpec, h: f64) -> CamTask {
    CamTask {
        program: Program::new(h, spec::parse_phases(SEED).unwrap()).unwrap(),
        follower,
        rotation: Rotation::Ccw,
        limits: spec::parse_limits("rise 75, return 60", true).unwrap(),
        min_curvature: None,
        face_margin: 0.005,
        omega: 200.0,
        points: 3600,
    }
}

#[divan::bench]
fn translating_roller_design_3600(b: Bencher) {
    let t = task(
        FollowerSpec::TranslatingRoller {
            offset: None,
            roller: None,
        },
        0.013,
    );
    b.bench(|| black_box(&t).solve().unwrap());
}

#[divan::bench]
fn translating_flat_design_3600(b: Bencher) {
    let t = task(FollowerSpec::TranslatingFlat { offset: 0.0 }, 0.013);
    b.bench(|| black_box(&t).solve().unwrap());
}

#[divan::bench]
fn oscillating_roller_design_3600(b: Bencher) {
    let t = task(
        FollowerSpec::OscillatingRoller {
            arm: 0.1,
            pivot: None,
            roller: None,
        },
        20f64.to_radians(),
    );
    b.bench(|| black_box(&t).solve().unwrap());
}

#[divan::bench]
fn translating_roller_sizing_only(b: Bencher) {
    let t = task(
        FollowerSpec::TranslatingRoller {
            offset: None,
            roller: None,
        },
        0.013,
    );
    b.bench(|| sizing::translating_roller(black_box(&t.program), 1.0, t.limits, None).unwrap());
}

#[divan::bench]
fn profile_3600_points(b: Bencher) {
    let t = task(
        FollowerSpec::TranslatingRoller {
            offset: None,
            roller: None,
        },
        0.013,
    );
    let m = Mechanism::TranslatingRoller {
        e: 0.0058,
        s0: 0.024,
        roller: 0.01,
    };
    b.bench(|| Profile::new(black_box(&t.program), &m, 1.0, 3600));
}

/// A `table(…)` law of 10 000 values (the most accepted), designed whole:
/// each value is a piece, found by binary search (the linear search made
/// this quadratic, 19 s).
#[divan::bench(sample_count = 5, sample_size = 1)]
fn table_10000_design() {
    let n = 10_000;
    let vals: Vec<String> = (0..n)
        .map(|i| format!("{:.4}", (std::f64::consts::TAU * i as f64 / (n - 1) as f64).sin()))
        .collect();
    let phases = format!("rise 108 table({}); dwell 15; return 108 sine; dwell 129", vals.join(", "));
    let t = CamTask {
        program: Program::new(0.013, spec::parse_phases(&phases).unwrap()).unwrap(),
        follower: FollowerSpec::TranslatingRoller {
            offset: None,
            roller: None,
        },
        rotation: Rotation::Ccw,
        limits: spec::parse_limits("rise 30, return 30", true).unwrap(),
        min_curvature: None,
        face_margin: 0.005,
        omega: 200.0,
        points: 3600,
    };
    black_box(&t).solve().unwrap();
}

/// The textbook's law of appendix П6 (two half sines up, two constants down).
const P6: &str = "rise 120 accel(sine 1, sine -3); dwell 30; return 180 accel(const -1, const 2.5); dwell 30";

fn p6_task(follower: FollowerSpec, h: f64, rotation: Rotation) -> CamTask {
    CamTask {
        program: Program::new(h, spec::parse_phases(P6).unwrap()).unwrap(),
        follower,
        rotation,
        limits: spec::parse_limits("rise 30, return 50", false).unwrap(),
        min_curvature: None,
        face_margin: 0.005,
        omega: 1.0,
        points: 720,
    }
}

#[divan::bench]
fn textbook_tangent_methods_p6(b: Bencher) {
    let t = p6_task(
        FollowerSpec::TranslatingRoller {
            offset: None,
            roller: Some(0.02),
        },
        0.08,
        Rotation::Cw,
    );
    let d = t.solve().unwrap();
    b.bench(|| tmm_cams::textbook::compare(black_box(&t), black_box(&d)).unwrap());
}

#[divan::bench]
fn textbook_level_lines_p6(b: Bencher) {
    let t = p6_task(
        FollowerSpec::OscillatingRoller {
            arm: 0.15,
            pivot: None,
            roller: Some(0.0),
        },
        0.08 / 0.15,
        Rotation::Ccw,
    );
    let d = t.solve().unwrap();
    b.bench(|| tmm_cams::textbook::compare(black_box(&t), black_box(&d)).unwrap());
}
