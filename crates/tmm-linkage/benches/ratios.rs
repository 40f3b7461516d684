//! Speed as ratios measured side by side in one process, for a shared
//! machine whose absolute times swing by a factor of two while another
//! build runs: the variants are measured in interleaved rounds — each round
//! runs every variant once, in an order that turns from round to round — so
//! that whatever slows the machine slows all of them alike. Printed: the
//! fastest and the median time of each variant and the median of the
//! rounds' ratios.
//!
//! - `cargo bench -p tmm-linkage --bench ratios` (or `-- sixbar ROUNDS`):
//!   the seed-003 six-bar under its loads, 3600 positions: the kinematics
//!   alone, the kinetostatics alone (from stored solutions), and both in
//!   one loop; ratios to the kinematics.
//! - `-- fourbar SWEEPS`: the seed-001 four-bar, the fastest of SWEEPS
//!   sweeps of 3600 full solves, printed as `ns_per_solve <ns>` for
//!   `scripts/bench-vs-pylinkage.sh`, which alternates it with pylinkage.
//!
//! A divan benchmark gives the same loops one after another, minutes
//! apart (`benches/forces.rs`, `benches/kinematics.rs`).

use std::f64::consts::TAU;
use std::hint::black_box;
use std::time::Instant;

use tmm_linkage::Solution;
use tmm_linkage::forces::Kinetostatics;

#[path = "../tests/common/mod.rs"]
mod common;

const N: usize = 3600;

fn main() {
    // `cargo bench` passes `--bench`; the rest is the mode and its count
    let args: Vec<String> = std::env::args().skip(1).filter(|a| !a.starts_with("--")).collect();
    let count = |default: usize| args.get(1).and_then(|s| s.parse().ok()).unwrap_or(default);
    match args.first().map(String::as_str) {
        Some("fourbar") => fourbar(count(20)),
        None | Some("sixbar") => sixbar(count(301)),
        Some(other) => eprintln!("unknown mode `{other}`: sixbar [ROUNDS] or fourbar [SWEEPS]"),
    }
}

/// Seconds taken by `f`.
fn time(f: impl FnOnce() -> f64) -> f64 {
    let t = Instant::now();
    black_box(f());
    t.elapsed().as_secs_f64()
}

fn median(v: &[f64]) -> f64 {
    let mut s = v.to_vec();
    s.sort_by(f64::total_cmp);
    let n = s.len();
    if n % 2 == 1 { s[n / 2] } else { 0.5 * (s[n / 2 - 1] + s[n / 2]) }
}

fn fastest(v: &[f64]) -> f64 {
    v.iter().copied().fold(f64::INFINITY, f64::min)
}

/// The seed-003 six-bar: kinematics, kinetostatics, both, interleaved.
fn sixbar(rounds: usize) {
    let m = common::seed003();
    let mut k = Kinetostatics::new(&m, common::seed003_example_loads(&m)).expect("the seed-003 loads are valid");
    let mut sol = m.solution();
    let angle = |i: usize| TAU * i as f64 / N as f64;
    let sols: Vec<Solution> = (0..N)
        .map(|i| {
            m.solve(angle(i), &mut sol).expect("the seed-003 six-bar turns fully");
            sol.clone()
        })
        .collect();
    let mut f = k.result();
    let mut t = [vec![], vec![], vec![]];
    // a round of warm-up, not counted
    for round in 0..=rounds {
        for j in 0..3 {
            let which = (j + round) % 3;
            let s = match which {
                0 => time(|| {
                    let mut acc = 0.0;
                    for i in 0..N {
                        m.solve(angle(i), &mut sol).expect("solves");
                        acc += sol.links[5].a.x;
                    }
                    acc
                }),
                1 => time(|| {
                    let mut acc = 0.0;
                    for s in &sols {
                        k.solve(s, &mut f).expect("solves");
                        acc += f.balancing_moment;
                    }
                    acc
                }),
                _ => time(|| {
                    let mut acc = 0.0;
                    for i in 0..N {
                        k.solve_at(angle(i), &mut sol, &mut f).expect("solves");
                        acc += f.balancing_moment;
                    }
                    acc
                }),
            };
            if round > 0 {
                t[which].push(s);
            }
        }
    }
    let [kin, kst, both] = &t;
    let ratio = |a: &[f64], b: &[f64]| median(&a.iter().zip(b).map(|(x, y)| x / y).collect::<Vec<_>>());
    let diff: Vec<f64> = both.iter().zip(kin).map(|(b, k)| b - k).collect();
    println!("seed-003 six-bar, {N} positions, {rounds} interleaved rounds (ms: fastest, median; ratio: median of the rounds' ratios)");
    let ms = 1e3;
    println!(
        "  kinematics                         {:7.3} {:7.3}",
        fastest(kin) * ms,
        median(kin) * ms
    );
    println!(
        "  kinetostatics (stored solutions)   {:7.3} {:7.3}   {:5.2} × kinematics",
        fastest(kst) * ms,
        median(kst) * ms,
        ratio(kst, kin)
    );
    println!(
        "  kinematics + kinetostatics         {:7.3} {:7.3}   {:5.2} × kinematics",
        fastest(both) * ms,
        median(both) * ms,
        ratio(both, kin)
    );
    println!(
        "  kinetostatics in the loop (diff.)          {:7.3}   {:5.2} × kinematics",
        median(&diff) * ms,
        ratio(&diff, kin)
    );
}

/// The seed-001 four-bar: the fastest of `sweeps` sweeps of 3600 positions.
fn fourbar(sweeps: usize) {
    let m = common::seed001();
    let mut sol = m.solution();
    let mut t = Vec::with_capacity(sweeps);
    for _ in 0..=sweeps {
        t.push(time(|| {
            let mut acc = 0.0;
            m.sweep(black_box(0.0), TAU / N as f64, N, &mut sol, |_, s| {
                acc += s.points[s.points.len() - 1].a.x
            })
            .expect("the seed-001 four-bar turns fully");
            acc
        }));
    }
    // the first sweep warms the caches
    let t = &t[1..];
    println!("ns_per_solve {:.2}", fastest(t) / N as f64 * 1e9);
    println!("ns_per_solve_median {:.2}", median(t) / N as f64 * 1e9);
}
