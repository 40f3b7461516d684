//! Planar lever mechanisms (рычажные механизмы) of revolute and prismatic
//! pairs: description, structural analysis (Assur groups), exact kinematics.
//!
//! ```
//! use tmm_linkage::{LinkDef, MechanismDef, InputDef, AssemblyHint, HintKind, Mechanism};
//! use tmm_geom::Vec2;
//! // Seed 001 four-bar: A(0,0), D(0.51,0), AB = 0.12, BC = 0.48, DC = 0.38 m.
//! let def = MechanismDef {
//!     fixed: vec![("A".into(), Vec2::new(0.0, 0.0)), ("D".into(), Vec2::new(0.51, 0.0))],
//!     links: vec![LinkDef::bar("1", "A", "B", 0.12), LinkDef::bar("2", "B", "C", 0.48), LinkDef::bar("3", "D", "C", 0.38)],
//!     input: Some(InputDef { link: "1".into(), pivot: "A".into(), pin: "B".into(), omega: 94.2, epsilon: 0.0 }),
//!     hints: vec![AssemblyHint { point: "C".into(), kind: HintKind::Above("A".into(), "D".into()) }],
//!     ..Default::default()
//! };
//! let m = Mechanism::new(&def).unwrap();
//! assert_eq!(m.structure.formula, "I(0,1) → II(2,3)");
//! let mut sol = m.solution();
//! m.solve(0.3, &mut sol).unwrap();
//! let (b, c) = (sol.points[m.point("B").unwrap()].p, sol.points[m.point("C").unwrap()].p);
//! assert!(((c - b).hypot() - 0.48).abs() < 1e-12);
//! assert!(c.y > 0.0);
//! ```

pub mod constraints;
pub mod cycle;
pub mod dyad;
pub mod dynamics;
pub mod error;
pub mod forces;
pub mod limits;
pub mod linear;
pub mod mechanism;
pub mod model;
pub mod plans;
pub mod ranges;
pub mod state;
pub mod structure;
pub mod synthesis;
pub mod whole;

pub use error::LinkageError;
pub use mechanism::{MAX_COUPLED, Mechanism, SliderDrive, Solution};
pub use model::{AssemblyHint, FRAME, HintKind, InputDef, LinkDef, MechanismDef, SliderDef, SliderInputDef};
pub use state::{LinkState, PointState};
pub use structure::Structure;
