//! The efficiency of a 2K-H train (КПД планетарного механизма) from the mesh
//! efficiencies, by the method of the carrier-fixed (relative) motion.

use serde::Serialize;

use crate::scheme::{Driver, Mesh, Scheme};

/// The efficiencies of one mesh (КПД зацепления), carrier fixed.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct MeshEfficiency {
    /// An external mesh, default 0.99.
    pub external: f64,
    /// An internal mesh, default 0.995.
    pub internal: f64,
}

impl Default for MeshEfficiency {
    fn default() -> Self {
        MeshEfficiency {
            external: 0.99,
            internal: 0.995,
        }
    }
}

/// The efficiency `η^H_13` of the train with the carrier fixed: the product of
/// the efficiencies of its two meshes.
///
/// ```
/// use tmm_planetary::{efficiency::{carrier_fixed, MeshEfficiency}, Scheme};
/// assert!((carrier_fixed(Scheme::SunPlanetRing, MeshEfficiency::default()) - 0.99 * 0.995).abs() < 1e-15);
/// ```
pub fn carrier_fixed(scheme: Scheme, e: MeshEfficiency) -> f64 {
    let one = |m: Mesh| if m == Mesh::External { e.external } else { e.internal };
    let (a, b) = scheme.meshes();
    one(a) * one(b)
}

/// Efficiency of the train with wheel 3 fixed, `driver` driving, for the ratio
/// `u = u_1H` and the carrier-fixed efficiency `eta_h` = `η^H_13`.
///
/// With the sun driving: `η_1H = (1 + η^H·(u − 1))/u` when wheel 1 also drives
/// in the relative motion (`(u − 1)/u > 0`, e.g. `u > 1`), which is the course's
/// `η_1H = 1 − (1 − η^H)·(u_1H − 1)/u_1H`; else `η_1H = (1 + (u − 1)/η^H)/u`.
/// With the carrier driving: `η_H1 = u/(1 + η^H·(u − 1))` when `(u − 1)/u < 0`
/// (`0 < u < 1`), else `η_H1 = u/(1 + (u − 1)/η^H)`.
/// A value ≤ 0 means the train locks itself (самоторможение) in that direction.
///
/// Source: the method of relative motion (Kreines; Kudryavtsev V.N.,
/// Планетарные передачи, 1966), derived here in docs/planetary.md §6.
///
/// ```
/// use tmm_planetary::{efficiency::train_efficiency, Driver};
/// // u = 4, η^H = 0.98505: 1 − 0.01495·3/4
/// assert!((train_efficiency(4.0, 0.98505, Driver::Sun) - (1.0 - 0.01495 * 0.75)).abs() < 1e-12);
/// // ideal meshes: no loss whatever the ratio
/// assert!((train_efficiency(-0.02, 1.0, Driver::Carrier) - 1.0).abs() < 1e-12);
/// ```
pub fn train_efficiency(u: f64, eta_h: f64, driver: Driver) -> f64 {
    // With the sun driving, wheel 1 drives in the relative motion when (u − 1)/u > 0;
    // with the carrier driving, when (u − 1)/u < 0 (docs/planetary.md §6).
    let positive = (u - 1.0) / u > 0.0;
    match driver {
        Driver::Sun if positive => (1.0 + eta_h * (u - 1.0)) / u,
        Driver::Sun => (1.0 + (u - 1.0) / eta_h) / u,
        Driver::Carrier if !positive => u / (1.0 + eta_h * (u - 1.0)),
        Driver::Carrier => u / (1.0 + (u - 1.0) / eta_h),
    }
}
