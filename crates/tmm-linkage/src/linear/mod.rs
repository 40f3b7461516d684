//! A linear input and a linear generalized coordinate (линейная обобщённая
//! координата): a mechanism driven by a cylinder, whose coordinate is the
//! relative displacement s of the piston in its oscillating cylinder — the
//! prismatic pair as the driver. BMSTU textbook (Chernaya & Timofeev 2019),
//! appendix П5, p. 143–148: the pneumatic-cylinder lifting mechanism.
//!
//! Module map, one concept per file:
//! - [`cylinder`]: the mechanism's positions and its analogues d/ds in
//!   closed form, solved into a reusable buffer;
//! - [`reduced`]: the reduced mass m_пр(s), its derivative and the reduced
//!   force of gravity F_пр(s);
//! - [`control`]: the piecewise-linear control force whose level is found
//!   from zero work over the travel;
//! - [`motion`]: A_Σ(s), V(s), a(s), t(s) by the energy equation in s, and
//!   how the end of the travel is reached;
//! - [`kinetostatics`]: the reactions and the balancing force at one s with
//!   the true V and a.
//!
//! Derivations: docs/dynamics.md, "A linear generalized coordinate".
//!
//! ```
//! use tmm_linkage::linear::cylinder::{CylinderDrive, CylinderState};
//! use tmm_geom::Vec2;
//! // a lever of 0.3 m about A = (0, 0), the cylinder pivoted at D = (0.6, 0.05)
//! let drive = CylinderDrive::new(Vec2::new(0.6, 0.05), 0.3, 0.05, 0.3, 0.39, 90f64.to_radians()).unwrap();
//! let mut st = CylinderState::default();
//! drive.solve(0.1, &mut st).unwrap();
//! // |DB| is the cylinder's h_min + s + rod, |AB| the lever
//! assert!(((st.b.p - Vec2::new(0.6, 0.05)).hypot() - 0.54).abs() < 1e-12);
//! assert!((st.b.p.hypot() - 0.3).abs() < 1e-12);
//! ```

pub mod control;
pub mod cylinder;
pub mod kinetostatics;
pub mod motion;
pub mod reduced;

pub use control::ControlLaw;
pub use cylinder::{CylinderDrive, CylinderState, PointQ};
pub use kinetostatics::{CylinderReactions, kinetostatics};
pub use motion::{CylinderMotion, EndReached, MotionRow};
pub use reduced::{CylinderMasses, ReducedPoint};

/// Five-point Gauss–Legendre nodes and weights on [−1, 1] (Abramowitz &
/// Stegun, table 25.4), exact for polynomials of degree 9.
pub(crate) const GL5: [(f64, f64); 5] = [
    (-0.906_179_845_938_664, 0.236_926_885_056_189_1),
    (-0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
    (0.0, 0.568_888_888_888_888_9),
    (0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
    (0.906_179_845_938_664, 0.236_926_885_056_189_1),
];

/// ∫ f over [a, b] by [`GL5`].
pub(crate) fn gauss<E>(a: f64, b: f64, mut f: impl FnMut(f64) -> Result<f64, E>) -> Result<f64, E> {
    let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
    let mut s = 0.0;
    for (x, w) in GL5 {
        s += w * f(mid + half * x)?;
    }
    Ok(s * half)
}
