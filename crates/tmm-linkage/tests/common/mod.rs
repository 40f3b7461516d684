//! Mechanisms of the examples, built in Rust, shared by the tests and the
//! benchmarks (included with `#[path]`).
#![allow(dead_code)]

use tmm_geom::Vec2;
use tmm_linkage::forces::{Action, Law, LinkLoad, Loads, PointForce, Resistance};
use tmm_linkage::{AssemblyHint, HintKind, InputDef, LinkDef, Mechanism, MechanismDef, SliderDef};

pub fn v(x: f64, y: f64) -> Vec2 {
    Vec2::new(x, y)
}

fn near(p: &str, x: f64, y: f64) -> AssemblyHint {
    AssemblyHint {
        point: p.into(),
        kind: HintKind::Near(v(x, y)),
    }
}

fn input(link: &str, pivot: &str, pin: &str, omega: f64) -> Option<InputDef> {
    Some(InputDef {
        link: link.into(),
        pivot: pivot.into(),
        pin: pin.into(),
        omega,
        epsilon: 0.0,
    })
}

fn slider(link: &str, point: &str, through: Vec2, angle_deg: f64) -> SliderDef {
    SliderDef {
        slider: link.into(),
        point: point.into(),
        guide_link: "frame".into(),
        through,
        angle: angle_deg.to_radians(),
        angle_on_slider: 0.0,
    }
}

/// Seed 001 four-bar: A(0,0), D(0.51,0), AB 0.12, BC 0.48, DC 0.38 m, 900 rpm ccw, C below AD.
pub fn seed001_def() -> MechanismDef {
    MechanismDef {
        fixed: vec![("A".into(), v(0.0, 0.0)), ("D".into(), v(0.51, 0.0))],
        links: vec![
            LinkDef::bar("1", "A", "B", 0.12),
            LinkDef::bar("2", "B", "C", 0.48),
            LinkDef::bar("3", "D", "C", 0.38),
        ],
        input: input("1", "A", "B", 900.0 * std::f64::consts::PI / 30.0),
        hints: vec![AssemblyHint {
            point: "C".into(),
            kind: HintKind::Below("A".into(), "D".into()),
        }],
        assembly_angle: 15f64.to_radians(),
        ..Default::default()
    }
}

/// Seed 003 six-bar (examples/seed-003-sixbar.toml).
pub fn seed003_def() -> MechanismDef {
    let rocker = LinkDef {
        name: "3".into(),
        points: vec![("E".into(), v(0.0, 0.0)), ("B".into(), v(0.6, 0.0)), ("C".into(), v(-0.6, 0.0))],
        mass_center: v(0.0, 0.0),
    };
    MechanismDef {
        fixed: vec![("O".into(), v(-1.25, 0.0)), ("E".into(), v(0.0, 0.0))],
        links: vec![
            LinkDef::bar("1", "O", "A", 0.27),
            LinkDef::bar("2", "A", "B", 1.25),
            rocker,
            LinkDef::bar("4", "C", "D", 0.65),
            LinkDef::block("5", "D"),
        ],
        sliders: vec![slider("5", "D", v(0.0, -0.2), 0.0)],
        input: input("1", "O", "A", 12.0),
        hints: vec![
            AssemblyHint {
                point: "B".into(),
                kind: HintKind::Above("O".into(), "E".into()),
            },
            near("D", 0.5, -0.2),
        ],
        assembly_angle: 80f64.to_radians(),
        ..Default::default()
    }
}

/// The seed-003 loads (examples/seed-003-sixbar.toml, [forces]): 30 kg/m,
/// J = m·l²/12, gravity, 3000 N·sin(π·s/H) against the slider's motion.
pub fn seed003_example_loads(m: &Mechanism) -> Loads {
    let mut l = Loads::new(m);
    l.gravity = v(0.0, -9.81);
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

/// Seed 004 six-bar with two sliders (examples/seed-004-two-sliders.toml).
pub fn seed004_def() -> MechanismDef {
    let coupler = LinkDef {
        points: vec![("B".into(), v(0.0, 0.0)), ("C".into(), v(0.09, 0.0)), ("E".into(), v(0.045, 0.0))],
        ..LinkDef::bar("2", "B", "C", 0.09)
    };
    MechanismDef {
        fixed: vec![("A".into(), v(0.0, 0.0))],
        links: vec![
            LinkDef::bar("1", "A", "B", 0.03),
            coupler,
            LinkDef::bar("4", "E", "D", 0.115),
            LinkDef::block("3", "C"),
            LinkDef::block("5", "D"),
        ],
        sliders: vec![slider("3", "C", v(0.0, 0.0), 0.0), slider("5", "D", v(0.06, 0.0), 90.0)],
        input: input("1", "A", "B", 40.82),
        hints: vec![near("C", 0.12, 0.0), near("D", 0.06, 0.12)],
        ..Default::default()
    }
}

/// Class-III mechanism (examples/class3-triad.toml): an equilateral base
/// link B, C, D on links 2 (AB), 4 (CE), 5 (DF).
pub fn triad_def() -> MechanismDef {
    let a = 60f64.to_radians();
    let base = LinkDef {
        name: "3".into(),
        points: vec![
            ("B".into(), v(0.0, 0.0)),
            ("C".into(), v(0.3, 0.0)),
            ("D".into(), v(0.3 * a.cos(), 0.3 * a.sin())),
        ],
        mass_center: v(0.15, 0.0866),
    };
    MechanismDef {
        fixed: vec![("O1".into(), v(0.0, 0.2)), ("E".into(), v(0.85, 0.05)), ("F".into(), v(0.25, 0.6))],
        links: vec![
            LinkDef::bar("1", "O1", "A", 0.05),
            LinkDef::bar("2", "A", "B", 0.4002),
            base,
            LinkDef::bar("4", "C", "E", 0.2583),
            LinkDef::bar("5", "D", "F", 0.2803),
        ],
        input: input("1", "O1", "A", 10.0),
        hints: vec![near("B", 0.35, 0.2134), near("C", 0.65, 0.2134), near("D", 0.5, 0.4732)],
        assembly_angle: std::f64::consts::PI,
        ..Default::default()
    }
}

/// Slotted-link (кулисный) mechanism: crank OA, block on link 3 (the slotted
/// link) pivoted at C: an RPR dyad.
pub fn slotted_def() -> MechanismDef {
    MechanismDef {
        fixed: vec![("O".into(), v(0.0, 0.0)), ("C".into(), v(0.0, -0.3))],
        links: vec![
            LinkDef::bar("1", "O", "A", 0.1),
            LinkDef::block("2", "A"),
            LinkDef::bar("3", "C", "K", 0.6),
        ],
        sliders: vec![SliderDef {
            slider: "2".into(),
            point: "A".into(),
            guide_link: "3".into(),
            through: v(0.0, 0.0),
            angle: 0.0,
            angle_on_slider: 0.0,
        }],
        input: input("1", "O", "A", -7.0),
        ..Default::default()
    }
}

/// A tiny deterministic random generator for test loads.
pub struct Rng(pub u64);
impl Rng {
    pub fn uniform(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    pub fn sym(&mut self, a: f64) -> f64 {
        a * (2.0 * self.uniform() - 1.0)
    }
}

/// [`seed001_def`] compiled.
pub fn seed001() -> Mechanism {
    Mechanism::new(&seed001_def()).unwrap()
}

/// [`seed003_def`] compiled.
pub fn seed003() -> Mechanism {
    Mechanism::new(&seed003_def()).unwrap()
}

/// [`seed004_def`] compiled.
pub fn seed004() -> Mechanism {
    Mechanism::new(&seed004_def()).unwrap()
}

/// [`triad_def`] compiled.
pub fn triad() -> Mechanism {
    Mechanism::new(&triad_def()).unwrap()
}

/// [`slotted_def`] compiled.
pub fn slotted() -> Mechanism {
    Mechanism::new(&slotted_def()).unwrap()
}

/// Seed 001 loads: 10 kg/m, J_S = 0.1·m·l², S mid-link, no gravity, 380 N·m
/// on the rocker against its rotation.
pub fn seed001_loads(m: &Mechanism) -> Loads {
    let lens = [0.12, 0.48, 0.38];
    let mut loads = Loads::new(m);
    for i in 1..=3 {
        let mass = 10.0 * lens[i - 1];
        loads.links[i].mass = mass;
        loads.links[i].inertia = 0.1 * mass * lens[i - 1] * lens[i - 1];
    }
    loads.resistance.push(Resistance {
        link: 3,
        action: Action::Moment { sign: None },
        law: Law::Constant(380.0),
    });
    loads
}

/// Random masses, inertias, gravity, external forces and moments.
pub fn random_loads(m: &Mechanism, rng: &mut Rng) -> Loads {
    let mut l = Loads::new(m);
    l.gravity = v(rng.sym(3.0), -9.81 + rng.sym(3.0));
    for i in 1..m.link_names.len() {
        l.links[i] = LinkLoad {
            mass: 0.1 + 5.0 * rng.uniform(),
            inertia: 0.01 + 0.2 * rng.uniform(),
            forces: vec![PointForce {
                local: v(rng.sym(0.2), rng.sym(0.2)),
                force: v(rng.sym(300.0), rng.sym(300.0)),
            }],
            moment: rng.sym(50.0),
        };
    }
    l
}

/// The textbook's П4 press (Chernaya & Timofeev 2019, p. 137–142;
/// examples/textbook/p4-press.toml): crank OA = H/2 = 0.2 m, rod
/// AB = 4.7·OA, S₂ at 2/3 of AB from A, the ram 3 at B on the vertical guide
/// through O below it; the crank turns clockwise, assembled up (the ram at
/// its top).
pub fn press_def() -> MechanismDef {
    let (r, l) = (0.2, 0.94);
    let mut rod = LinkDef::bar("2", "A", "B", l);
    rod.mass_center = v(2.0 * l / 3.0, 0.0);
    MechanismDef {
        fixed: vec![("O".into(), v(0.0, 0.0))],
        links: vec![LinkDef::bar("1", "O", "A", r), rod, LinkDef::block("3", "B")],
        sliders: vec![slider("3", "B", v(0.0, 0.0), 90.0)],
        input: input("1", "O", "A", -2.0 * std::f64::consts::PI * 16.7 / 18.6),
        hints: vec![near("B", 0.0, -0.74)],
        assembly_angle: 90f64.to_radians(),
        ..Default::default()
    }
}

pub fn press() -> Mechanism {
    Mechanism::new(&press_def()).unwrap()
}

/// П4's loads: rod 30 t, 5000 kg·m²; ram 50 t; gravity; the deformation
/// force F/F_max = 0, 0, 0.1, 0.2, 1 at h/H = 0, 0.6, 0.62, 0.75, 1 (linear)
/// with F_max = `f_max`, against the ram's motion on the down-stroke only.
pub fn press_loads(m: &Mechanism, f_max: f64) -> Loads {
    use tmm_linkage::forces::stroke::Working;
    use tmm_linkage::forces::{Curve, Interpolation, SliderLoad, SliderLoadKind, TravelScale};
    let mut l = Loads::new(m);
    l.gravity = v(0.0, -9.81);
    l.links[2].mass = 30e3;
    l.links[2].inertia = 5e3;
    l.links[3].mass = 50e3;
    let pts: Vec<(f64, f64)> = [(0.0, 0.0), (0.6, 0.0), (0.62, 0.1), (0.75, 0.2), (1.0, 1.0)]
        .iter()
        .map(|&(h, f)| (h, f * f_max))
        .collect();
    l.sliders.push(SliderLoad {
        link: 3,
        kind: SliderLoadKind::StrokeForce {
            table: Curve::new(&pts, Interpolation::Linear, "press").unwrap(),
            travel: TravelScale::Stroke,
            working: Working::Decreasing,
            window: (0.0, 1.0),
            arm: 0.0,
        },
    });
    l
}
