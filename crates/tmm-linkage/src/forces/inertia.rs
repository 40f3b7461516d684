//! Inertia loads by d'Alembert's principle (силы инерции): the inertia force
//! F_u = −m·a_S applied at the centre of mass and the inertia torque
//! (главный момент сил инерции) M_u = −J_S·ε of every link
//! (Artobolevsky 1988, § 13; seed 001 sheet 3: "Pu = m·aS, Mu = ε·Js",
//! directed against the acceleration).
//!
//! ```
//! use tmm_linkage::state::LinkState;
//! use tmm_linkage::forces::inertia::inertia_load;
//! use tmm_geom::Vec2;
//! // a bar turning at ω = 2 rad/s, ε = 3 rad/s² about its origin, S at (0.5, 0):
//! // a_S = ε·k×r − ω²·r = (−2, 1.5); F_u = −m·a_S; M_u = −J·ε.
//! let s = LinkState { omega: 2.0, eps: 3.0, ..Default::default() };
//! let (f, p, m) = inertia_load(&s, Vec2::new(0.5, 0.0), 4.0, 0.25);
//! assert!((f - Vec2::new(8.0, -6.0)).hypot() < 1e-12);
//! assert_eq!(p, Vec2::new(0.5, 0.0));
//! assert!((m + 0.75).abs() < 1e-12);
//! ```

use tmm_geom::Vec2;

use crate::state::LinkState;

/// The inertia force (at the returned global centre of mass) and inertia
/// torque of a link of mass `mass` and central moment of inertia `inertia`
/// whose centre of mass is at `s_local`.
#[inline]
pub fn inertia_load(s: &LinkState, s_local: Vec2, mass: f64, inertia: f64) -> (Vec2, Vec2, f64) {
    let p = s.pos(s_local);
    let (_, a) = s.kin_at(p);
    (a * -mass, p, -inertia * s.eps)
}
