//! The full tooth-number enumeration, z up to 200, ratios up to 30 (target:
//! under 50 ms each).

use divan::{Bencher, black_box};
use tmm_planetary::{Request, Scheme, enumerate_into, synthesize};

fn main() {
    divan::main();
}

/// (scheme, u_1H): the reducers by u_1H, the carrier-driven schemes by u_H1 = 1/u_1H.
const CASES: [(Scheme, f64); 8] = [
    (Scheme::SunPlanetRing, 4.0),
    (Scheme::SunPlanetRing, 12.0),
    (Scheme::ExtInt, 12.5),
    (Scheme::ExtInt, 30.0),
    (Scheme::ExtExt, 1.0 / 30.0),
    (Scheme::ExtExt, -29.0),
    (Scheme::IntInt, -1.0 / 30.0),
    (Scheme::IntInt, 1.0 / 30.0),
];

fn request(i: usize, tolerance: f64) -> Request {
    let (scheme, u) = CASES[i];
    Request {
        tolerance,
        ..Request::new(scheme, u, 3)
    }
}

/// Exact ratio, every condition, into a reused buffer.
#[divan::bench(args = [0, 1, 2, 3, 4, 5, 6, 7])]
fn exact(b: Bencher, i: usize) {
    let r = request(i, 0.0);
    let mut buf = Vec::with_capacity(1 << 16);
    b.bench_local(|| enumerate_into(black_box(&r), &mut buf).map(|c| c.ratio));
}

/// 1 % tolerance: many more sets pass the ratio stage.
#[divan::bench(args = [0, 1, 2, 3, 4, 5, 6, 7])]
fn tolerance_1pct(b: Bencher, i: usize) {
    let r = request(i, 0.01);
    let mut buf = Vec::with_capacity(1 << 20);
    b.bench_local(|| enumerate_into(black_box(&r), &mut buf).map(|c| c.ratio));
}

/// The whole search with ranking, as `tmm planetary` runs it (ext-int, u = 30, 1 %).
#[divan::bench]
fn synthesize_ranked() -> usize {
    synthesize(black_box(&request(3, 0.01))).map(|s| s.candidates.len()).unwrap_or(0)
}

/// Two modules per double planet (all GOST 9563 ratios), ext-int u = 12.5 exact.
#[divan::bench]
fn two_modules() -> usize {
    let r = Request {
        two_modules: true,
        ..request(2, 0.0)
    };
    synthesize(black_box(&r)).map(|s| s.candidates.len()).unwrap_or(0)
}
