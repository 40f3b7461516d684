//! Speed of metric synthesis: one synthesis of each kind with its check over
//! the whole cycle by the linkage core (target: under 1 ms each), and a sweep
//! of 1000 variants (target: under 0.5 s).

use divan::black_box;
use tmm_linkage::synthesis::crank_rocker::{CrankRockerRequest, RockerCondition};
use tmm_linkage::synthesis::crank_slider::{CrankSliderRequest, SliderCondition};
use tmm_linkage::synthesis::knee_press::{KneePivot, KneeRequest};
use tmm_linkage::synthesis::pivot::PivotCondition;
use tmm_linkage::synthesis::six_bar::PressureRequest;
use tmm_linkage::synthesis::slotted::{Coupler, Lever, SlottedRequest};
use tmm_linkage::synthesis::{Drive, Limits, Request, sweep::sweep, synthesize};

fn main() {
    divan::main();
}

fn slider(c: SliderCondition) -> Request {
    Request::CrankSlider(CrankSliderRequest {
        stroke: 0.3,
        k: 1.2,
        condition: c,
        drive: Drive::default(),
        limits: Limits::default(),
    })
}

fn rocker(c: RockerCondition) -> Request {
    Request::CrankRocker(CrankRockerRequest {
        k: 1.28,
        rocker: 0.245,
        swing: 60f64.to_radians(),
        condition: c,
        drive: Drive::default(),
        limits: Limits::default(),
    })
}

#[divan::bench]
fn crank_slider_lambda() {
    black_box(synthesize(&slider(SliderCondition::Lambda(3.5))).unwrap());
}

#[divan::bench]
fn crank_slider_max_pressure() {
    black_box(synthesize(&slider(SliderCondition::MaxPressure(45f64.to_radians()))).unwrap());
}

#[divan::bench]
fn crank_rocker_crank() {
    black_box(synthesize(&rocker(RockerCondition::Crank(0.1))).unwrap());
}

#[divan::bench]
fn crank_rocker_optimum() {
    black_box(synthesize(&rocker(RockerCondition::Optimum)).unwrap());
}

#[divan::bench]
fn slotted_lever() {
    black_box(
        synthesize(&Request::Slotted(SlottedRequest {
            stroke: 0.4,
            k: 1.5,
            pivots: 0.05,
            coupler: Coupler::Ratio(3.0),
            lever: Lever::Rotating,
            drive: Drive::default(),
            limits: Limits::default(),
        }))
        .unwrap(),
    );
}

#[divan::bench]
fn knee_press() {
    black_box(
        synthesize(&Request::Knee(KneeRequest {
            stroke: 0.09,
            k: 1.12,
            rocker: 0.22,
            link: 0.22,
            delta: 5f64.to_radians(),
            pivot: KneePivot::Horizontal(0.28),
            drive: Drive::default(),
            limits: Limits::default(),
        }))
        .unwrap(),
    );
}

#[divan::bench]
fn six_bar_seed_003() {
    let p = 38f64.to_radians();
    black_box(
        synthesize(&Request::SixBarPressure(PressureRequest {
            k: 1.07,
            swing: 55f64.to_radians(),
            arm_b: 0.6,
            arm_c: 0.6,
            arm_angle: std::f64::consts::PI,
            guide: -0.2,
            max_pressure: p,
            pivot: PivotCondition::ExtremePressure(p),
            drive: Drive::default(),
            limits: Limits::default(),
        }))
        .unwrap(),
    );
}

#[divan::bench(sample_count = 5, sample_size = 1)]
fn sweep_1000_crank_rocker_frame() {
    let t = sweep(&rocker(RockerCondition::Frame(0.3)), "frame", 0.25, 0.6, 1000).unwrap();
    black_box(t);
}

#[divan::bench(sample_count = 5, sample_size = 1)]
fn sweep_1000_crank_slider_lambda() {
    let t = sweep(&slider(SliderCondition::Lambda(3.5)), "lambda", 1.5, 8.0, 1000).unwrap();
    black_box(t);
}

/// The parts of one check: compiling the description, and the cycle analysis.
#[divan::bench]
fn part_mechanism_new(bencher: divan::Bencher) {
    let s = synthesize(&rocker(RockerCondition::Crank(0.1))).unwrap();
    bencher.bench_local(|| black_box(tmm_linkage::Mechanism::new(black_box(&s.def)).unwrap()));
}

#[divan::bench]
fn part_cycle_new(bencher: divan::Bencher) {
    let s = synthesize(&rocker(RockerCondition::Crank(0.1))).unwrap();
    let m = tmm_linkage::Mechanism::new(&s.def).unwrap();
    bencher.bench_local(|| black_box(tmm_linkage::cycle::Cycle::new(black_box(&m), tmm_linkage::cycle::Working::Slower).unwrap()));
}
