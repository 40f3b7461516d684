//! The costs of the largest inputs accepted: choosing the assembly of a crank
//! driving N independent RRR dyads, each with a side hint of its own (linear
//! in N; the exhaustive search once doubled its memory per dyad), and the
//! largest sweep of the slowest synthesis kind (10 000 six-bars with the
//! optimum pivot).

use divan::black_box;
use tmm_geom::Vec2;
use tmm_linkage::synthesis::pivot::PivotCondition;
use tmm_linkage::synthesis::six_bar::PressureRequest;
use tmm_linkage::synthesis::{Drive, Limits, Request, sweep::sweep};
use tmm_linkage::{AssemblyHint, HintKind, InputDef, LinkDef, Mechanism, MechanismDef};

fn main() {
    divan::main();
}

/// Crank A–B driving `n` dyads B–Ck, Dk–Ck, each with "Ck below B Dk".
fn fan(n: usize) -> MechanismDef {
    let mut fixed = vec![("A".to_string(), Vec2::ZERO)];
    let mut links = vec![LinkDef::bar("1", "A", "B", 0.1)];
    let mut hints = Vec::new();
    for k in 0..n {
        fixed.push((format!("D{k}"), Vec2::new(1.2 + 0.0005 * k as f64, 0.5)));
        links.push(LinkDef::bar(&format!("c{k}"), "B", &format!("C{k}"), 1.0));
        links.push(LinkDef::bar(&format!("r{k}"), &format!("D{k}"), &format!("C{k}"), 1.0));
        hints.push(AssemblyHint {
            point: format!("C{k}"),
            kind: HintKind::Below("B".into(), format!("D{k}")),
        });
    }
    MechanismDef {
        fixed,
        links,
        input: Some(InputDef {
            link: "1".into(),
            pivot: "A".into(),
            pin: "B".into(),
            omega: 10.0,
            epsilon: 0.0,
        }),
        hints,
        ..Default::default()
    }
}

#[divan::bench(args = [16, 64, 74], sample_count = 5, sample_size = 1)]
fn assembly_of_n_dyads(n: usize) {
    let def = fan(n);
    black_box(Mechanism::new(black_box(&def)).unwrap());
}

#[divan::bench(sample_count = 2, sample_size = 1)]
fn sweep_10000_six_bar_optimum() {
    let p = 38f64.to_radians();
    let r = Request::SixBarPressure(PressureRequest {
        k: 1.07,
        swing: 55f64.to_radians(),
        arm_b: 0.6,
        arm_c: 0.6,
        arm_angle: std::f64::consts::PI,
        guide: -0.2,
        max_pressure: p,
        pivot: PivotCondition::Optimum,
        drive: Drive::default(),
        limits: Limits::default(),
    });
    black_box(sweep(&r, "k", 1.01, 1.3, 10_000).unwrap());
}
