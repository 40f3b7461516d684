//! Kinetostatics (кинетостатика) of lever mechanisms: the loads on every link
//! (inertia force and torque by d'Alembert, weight, external forces and
//! moments, the useful resistance), the reaction in every kinematic pair
//! solved group by group from the group farthest from the input, the
//! balancing torque and force on the crank (уравновешивающий момент / сила),
//! the independent check by Zhukovsky's lever (рычаг Жуковского, virtual
//! power), and the strength of a chosen link as a beam (эпюры N, Q, M,
//! подбор сечения).
//!
//! Friction in the pairs is neglected (seed 000, assumption 1.4): every
//! revolute reaction passes through the joint centre, every prismatic
//! reaction is normal to the guide.
//!
//! Module map, one concept per file:
//! - [`loads`]: what the user gives (masses, inertia, gravity, forces, moments);
//! - [`resistance`]: the useful resistance and its law over the cycle;
//! - [`slider_load`]: gas forces, forces on one stroke and friction on sliders;
//! - [`indicator`]: a cylinder's indicator diagram, a table per process;
//! - [`spline`]: tables interpolated linearly or by a cubic spline;
//! - [`stroke`]: dead positions and travel of the output link (for the law);
//! - [`inertia`]: inertia force −m·a_S and torque −J_S·ε;
//! - [`group`]: the reactions of one Assur group from its constraint Jacobian;
//! - [`dyads`]: the RRR and RRP dyads' reactions written out, prepared once;
//! - [`kinetostatics`]: the whole mechanism, group by group, then the crank;
//! - [`polygon`]: each group's and the crank's force polygon, closed;
//! - [`zhukovsky`]: the balancing torque by virtual power, and the lever's geometry;
//! - [`beam`]: a link as a beam: N(z), Q(z), M(z);
//! - [`section`]: the section size for an allowed stress;
//! - [`error`]: what can go wrong.
//!
//! ```
//! use tmm_linkage::{LinkDef, MechanismDef, InputDef, Mechanism};
//! use tmm_linkage::forces::{Loads, Kinetostatics};
//! use tmm_geom::Vec2;
//! // A crank with a 1 kg mass at its pin turning at 10 rad/s, nothing else:
//! // the reaction at the pivot is the centrifugal force m·ω²·r = 1·100·0.1 = 10 N.
//! let def = MechanismDef {
//!     fixed: vec![("O".into(), Vec2::ZERO), ("C".into(), Vec2::new(0.3, 0.0))],
//!     links: vec![
//!         LinkDef { mass_center: Vec2::new(0.1, 0.0), ..LinkDef::bar("1", "O", "A", 0.1) },
//!         LinkDef::bar("2", "A", "B", 0.3),
//!         LinkDef::bar("3", "C", "B", 0.25),
//!     ],
//!     input: Some(InputDef { link: "1".into(), pivot: "O".into(), pin: "A".into(), omega: 10.0, epsilon: 0.0 }),
//!     ..Default::default()
//! };
//! let m = Mechanism::new(&def).unwrap();
//! let mut loads = Loads::new(&m);
//! loads.links[1].mass = 1.0;
//! let mut k = Kinetostatics::new(&m, loads).unwrap();
//! let mut sol = m.solution();
//! let mut f = k.result();
//! k.solve_at(0.7, &mut sol, &mut f).unwrap();
//! let pivot = f.reactions.iter().find(|r| r.from == 0 && r.on == 1).unwrap();
//! assert!((pivot.force.hypot() - 10.0).abs() < 1e-9);
//! assert!(f.balancing_moment.abs() < 1e-12);
//! ```

pub mod beam;
pub mod dyads;
pub mod error;
pub mod group;
pub mod indicator;
pub mod inertia;
pub mod kinetostatics;
pub mod loads;
pub mod polygon;
pub mod resistance;
pub mod section;
pub mod slider_load;
pub mod spline;
pub mod stroke;
pub mod zhukovsky;

pub use beam::{Beam, BeamSample};
pub use error::ForceError;
pub use indicator::{Indicator, Process, TravelScale};
pub use kinetostatics::{ForceSolution, Kinetostatics, LinkForces, Reaction};
pub use loads::{LinkLoad, Loads, MachineCycle, PointForce};
pub use polygon::{ForcePolygon, PolygonForce, PolygonForceKind};
pub use resistance::{Action, Law, Resistance};
pub use section::{IBeam, SectionSizes, size_sections};
pub use slider_load::{ActiveSliderLoad, SliderLoad, SliderLoadKind};
pub use spline::{Curve, Interpolation};
pub use stroke::Stroke;
