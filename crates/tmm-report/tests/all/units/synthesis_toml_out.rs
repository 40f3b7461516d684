//! Tests of `tmm_report::synthesis::toml_out`, kept outside the library so that the
//! test command compiles it once.

use tmm_geom::Vec2;
use tmm_linkage::synthesis::crank_rocker::{CrankRockerRequest, RockerCondition};
use tmm_linkage::synthesis::crank_slider::{CrankSliderRequest, SliderCondition};
use tmm_linkage::synthesis::knee_press::{KneePivot, KneeRequest};
use tmm_linkage::synthesis::pivot::PivotCondition;
use tmm_linkage::synthesis::six_bar::{InversionRequest, PressureRequest};
use tmm_linkage::synthesis::slotted::{Coupler, Lever, SlottedRequest};
use tmm_linkage::synthesis::{Drive, Request, Rotation, synthesize};
use tmm_linkage::{FRAME, MechanismDef};
use tmm_linkage::{LinkDef, Mechanism, SliderDef};
use tmm_report::TaskSource;
use tmm_report::synthesis::toml_out::*;

/// Compile both descriptions and compare every point of `a` at
/// several crank angles.
fn same_motion(a: &MechanismDef, b: &MechanismDef) {
    let (ma, mb) = (Mechanism::new(a).unwrap(), Mechanism::new(b).unwrap());
    let (mut sa, mut sb) = (ma.solution(), mb.solution());
    let base = a.assembly_angle;
    for k in 0..8 {
        let phi = base + 0.05 * k as f64;
        ma.solve(phi, &mut sa).unwrap();
        mb.solve(phi, &mut sb).unwrap();
        for (i, p) in ma.points.iter().enumerate() {
            let j = mb.point(&p.name).unwrap_or_else(|| panic!("{} is missing", p.name));
            let d = (sa.points[i].p - sb.points[j].p).hypot();
            assert!(d < 1e-12, "{} at φ = {phi}: {d}", p.name);
        }
    }
}

fn round_trip(def: &MechanismDef) -> MechanismDef {
    let text = linkage_toml(def).unwrap();
    let back = tmm_report::linkage::task::read(&TaskSource::new("t.toml", text.clone()))
        .unwrap_or_else(|e| panic!("{e}\n{text}"))
        .unwrap();
    back.def
}

fn deg(x: f64) -> f64 {
    x.to_radians()
}

fn requests() -> Vec<Request> {
    let d = Drive::default();
    let cw = Drive {
        rotation: Rotation::Cw,
        omega: 94.2,
    };
    vec![
        Request::CrankSlider(CrankSliderRequest {
            stroke: 0.3,
            k: 1.2,
            condition: SliderCondition::Lambda(3.5),
            drive: cw,
            limits: Default::default(),
        }),
        Request::CrankRocker(CrankRockerRequest {
            k: 1.28,
            rocker: 0.245,
            swing: deg(60.0),
            condition: RockerCondition::Crank(0.1),
            drive: d,
            limits: Default::default(),
        }),
        Request::Slotted(SlottedRequest {
            stroke: 0.4,
            k: 1.5,
            pivots: 0.05,
            coupler: Coupler::Ratio(3.0),
            lever: Lever::Rotating,
            drive: d,
            limits: Default::default(),
        }),
        Request::Knee(KneeRequest {
            stroke: 0.09,
            k: 1.12,
            rocker: 0.22,
            link: 0.22,
            delta: deg(5.0),
            pivot: KneePivot::Horizontal(0.28),
            drive: cw,
            limits: Default::default(),
        }),
        Request::SixBarInversion(InversionRequest {
            k: 1.15,
            travel: 0.36,
            guide: -0.32,
            start: 0.18,
            coupler: 0.32,
            swing: deg(70.0),
            lever: 0.36,
            pivot: PivotCondition::OnLine {
                point: Vec2::new(0.0, 0.2),
                dir: Vec2::new(1.0, 0.0),
            },
            drive: d,
            limits: Default::default(),
        }),
        Request::SixBarPressure(PressureRequest {
            k: 1.07,
            swing: deg(55.0),
            arm_b: 0.6,
            arm_c: 0.6,
            arm_angle: std::f64::consts::PI,
            guide: -0.2,
            max_pressure: deg(38.0),
            pivot: PivotCondition::ExtremePressure(deg(38.0)),
            drive: d,
            limits: Default::default(),
        }),
    ]
}

#[test]
fn every_synthesised_kind_reads_back_with_the_same_motion() {
    for r in requests() {
        let syn = synthesize(&r).unwrap();
        let back = round_trip(&syn.def);
        assert_eq!(back.input.as_ref().unwrap().omega, syn.def.input.as_ref().unwrap().omega);
        same_motion(&syn.def, &back);
    }
}

#[test]
fn a_link_off_its_axis_and_a_guide_on_it_keep_their_global_places() {
    // A slotted lever whose local frame is not the task format's: its
    // second point is off the x-axis and it carries the slot.
    let mut def = synthesize(&requests()[2]).unwrap().def;
    let a = 0.7_f64;
    let (sn, cs) = a.sin_cos();
    let rot = |p: Vec2| Vec2::new(cs * p.x - sn * p.y, sn * p.x + cs * p.y) + Vec2::new(0.01, -0.02);
    let lever = def.links.iter_mut().find(|l| l.name == "3").unwrap();
    for p in &mut lever.points {
        p.1 = rot(p.1);
    }
    lever.mass_center = rot(lever.mass_center);
    for sl in &mut def.sliders {
        if sl.guide_link == "3" {
            sl.through = rot(sl.through);
            sl.angle += a;
        }
    }
    let back = round_trip(&def);
    same_motion(&def, &back);
    // the lever's points read back in the task's frame: E at the origin
    let l3 = back.links.iter().find(|l| l.name == "3").unwrap();
    assert_eq!(l3.points[0].1, Vec2::ZERO);
    assert!(l3.points[1].1.y.abs() < 1e-15);
}

#[test]
fn names_the_format_cannot_hold_are_refused() {
    let def = MechanismDef {
        fixed: vec![("A".into(), Vec2::ZERO)],
        links: vec![LinkDef::bar("crank one", "A", "B", 0.1)],
        ..Default::default()
    };
    assert!(linkage_toml(&def).is_err());
    let mut def2 = round_trip(&synthesize(&requests()[0]).unwrap().def);
    def2.sliders.push(SliderDef {
        slider: "3".into(),
        point: "B".into(),
        guide_link: FRAME.into(),
        through: Vec2::ZERO,
        angle: 0.0,
        angle_on_slider: 0.3,
    });
    assert!(linkage_toml(&def2).is_err());
}
