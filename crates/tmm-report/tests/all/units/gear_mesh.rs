//! Tests of `tmm_report::gear::mesh`, kept outside the library so that the
//! test command compiles it once.

use std::f64::consts::PI;
use tmm_gears::{Kind, Pair};
use tmm_gears::{PairSpec, generate::generate};
use tmm_report::gear::mesh::*;

fn dist_to_polyline(p: Pt, pl: &[Pt]) -> f64 {
    pl.windows(2)
        .map(|w| {
            let (a, b) = (w[0], w[1]);
            let (dx, dy) = (b.0 - a.0, b.1 - a.1);
            let t = (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / (dx * dx + dy * dy).max(1e-300)).clamp(0.0, 1.0);
            ((a.0 + t * dx - p.0).powi(2) + (a.1 + t * dy - p.1).powi(2)).sqrt()
        })
        .fold(f64::INFINITY, f64::min)
}

/// Both working profiles pass through the pole, and their tangents there are
/// perpendicular to N1N2 (the placement derived in docs/gears.md).
#[test]
fn working_profiles_meet_at_the_pole() {
    let cases = [
        (15u32, 20u32, 0.2, 0.85, Kind::External),
        (17, 40, 0.0, 0.0, Kind::External),
        (12, 31, 0.5, -0.1, Kind::External),
        (20, 60, 0.5, 0.8, Kind::Internal),
    ];
    for &(z1, z2, x1, x2, kind) in &cases {
        let pair = Pair::new(&PairSpec {
            kind,
            ..PairSpec::external(z1, z2, 0.005, x1, x2)
        })
        .unwrap();
        let (t1, t2) = tmm_report::gear::profiles(&pair, &tmm_report::gear::input::Origin::Cli).unwrap();
        let sc = scene(&pair, &t1, &t2);
        let line = (sc.n2.0 - sc.n1.0, sc.n2.1 - sc.n1.1);
        for (w, work) in [(1, &sc.work1), (2, &sc.work2)] {
            assert!(
                dist_to_polyline(sc.p, work) < 0.02,
                "{z1}/{z2}: wheel {w} misses P by {} first {:?} last {:?} P {:?}",
                dist_to_polyline(sc.p, work),
                work.first(),
                work.last(),
                sc.p
            );
            let near = work
                .windows(2)
                .min_by(|a, b| dist_to_polyline(sc.p, a).total_cmp(&dist_to_polyline(sc.p, b)))
                .unwrap();
            let tang = (near[1].0 - near[0].0, near[1].1 - near[0].1);
            let cos = (tang.0 * line.0 + tang.1 * line.1) / (tang.0.hypot(tang.1) * line.0.hypot(line.1));
            assert!(cos.abs() < 0.03, "{z1}/{z2} wheel {w}: cos {cos}");
        }
        // A and B lie on the tip circles of wheel 2 and wheel 1
        let d = |a: Pt, b: Pt| (a.0 - b.0).hypot(a.1 - b.1);
        assert!((d(sc.a, sc.o2) - pair.w2.da / 2.0 * 1e3).abs() < 1e-9);
        assert!((d(sc.b, sc.o1) - pair.w1.da / 2.0 * 1e3).abs() < 1e-9);
    }
}

/// The arcs of action: turning wheel 1 to the start of its arc brings its
/// working profile through A, to the end through B; each arc over the
/// angular pitch is εα (seed 003 §17 measures εα this way off the drawing).
#[test]
fn arcs_of_action() {
    let cases = [
        (15u32, 20u32, 0.2, 0.85, Kind::External),
        (17, 40, 0.0, 0.0, Kind::External),
        (20, 60, 0.5, 0.8, Kind::Internal),
    ];
    for &(z1, z2, x1, x2, kind) in &cases {
        let pair = Pair::new(&PairSpec {
            kind,
            ..PairSpec::external(z1, z2, 0.005, x1, x2)
        })
        .unwrap();
        let (t1, t2) = tmm_report::gear::profiles(&pair, &tmm_report::gear::input::Origin::Cli).unwrap();
        let sc = scene(&pair, &t1, &t2);
        let (c1, r1, a0, a1) = sc.arcs[0];
        assert_eq!(c1, sc.o1);
        let tau1 = 2.0 * PI / z1 as f64;
        assert!(((a1 - a0) / tau1 - pair.eps_alpha).abs() < 1e-12);
        let (_, _, b0, b1) = sc.arcs[1];
        assert!(((b1 - b0) / (2.0 * PI / z2 as f64) - pair.eps_alpha).abs() < 1e-12);
        assert!(a0 < PI / 2.0 && PI / 2.0 < a1 && (r1 - pair.w1.dw / 2.0 * 1e3).abs() < 1e-9);
        // the arc's ends, reached from the pole position
        let full: Vec<Pt> = t1
            .half
            .iter()
            .map(|q| turn((q.r * 1e3 * q.psi.sin(), q.r * 1e3 * q.psi.cos()), sc.rot1, sc.o1))
            .collect();
        let at = |turn_by: f64| -> Vec<Pt> { full.iter().map(|&q| turn(q, turn_by, sc.o1)).collect() };
        // wheel 1 turns clockwise while the contact runs from A to B
        assert!(dist_to_polyline(sc.a, &at(a1 - PI / 2.0)) < 0.02, "{z1}/{z2}: wheel 1 misses A");
        assert!(dist_to_polyline(sc.b, &at(a0 - PI / 2.0)) < 0.02, "{z1}/{z2}: wheel 1 misses B");
        // wheel 2 the other way (a ring the same way)
        let ring = kind == Kind::Internal;
        let sgn = if ring { -1.0 } else { 1.0 };
        let full2: Vec<Pt> = t2
            .half
            .iter()
            .map(|q| turn((sgn * q.r * 1e3 * q.psi.sin(), q.r * 1e3 * q.psi.cos()), sc.rot2, sc.o2))
            .collect();
        let at2 = |turn_by: f64| -> Vec<Pt> {
            full2
                .iter()
                .map(|&q| turn((q.0 - sc.o2.0, q.1 - sc.o2.1), turn_by, sc.o2))
                .collect()
        };
        let mid = if ring { PI / 2.0 } else { -PI / 2.0 };
        let (ta, tb) = if ring { (b1 - mid, b0 - mid) } else { (b0 - mid, b1 - mid) };
        assert!(dist_to_polyline(sc.a, &at2(ta)) < 0.02, "{z1}/{z2}: wheel 2 misses A");
        assert!(dist_to_polyline(sc.b, &at2(tb)) < 0.02, "{z1}/{z2}: wheel 2 misses B");
    }
}

/// The DXF reads back with its layers and one closed outline per wheel.
#[test]
fn dxf_reads_back_with_layers() {
    let pair = Pair::new(&PairSpec::external(15, 20, 0.005, 0.2, 0.85)).unwrap();
    let r = pair.spec.rack;
    let t1 = generate(15, 0.005, 0.2, &r, pair.w1.da / 2.0, 40).unwrap();
    let t2 = generate(20, 0.005, 0.85, &r, pair.w2.da / 2.0, 40).unwrap();
    let text = mesh_dxf(&pair, &t1, &t2).to_text().unwrap();
    let back = dxf::Drawing::load(&mut text.as_bytes()).unwrap();
    let layers: Vec<String> = back.layers().map(|l| l.name.clone()).collect();
    for l in [
        "WHEEL1",
        "WHEEL2",
        "LINE_OF_ACTION",
        "ACTIVE_LINE",
        "WORKING_PROFILES",
        "ARCS_OF_ACTION",
        "CIRCLE_BASE",
        "SLIDING",
        "TABLE",
    ] {
        assert!(layers.iter().any(|x| x == l), "{l}");
    }
    let outlines = back
        .entities()
        .filter(|e| matches!(e.specific, dxf::entities::EntityType::LwPolyline(_)) && e.common.layer.starts_with("WHEEL"))
        .count();
    assert_eq!(outlines, 2);
}
