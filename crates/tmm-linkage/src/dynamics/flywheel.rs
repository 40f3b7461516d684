//! The flywheel (маховик): its own moment of inertia — the required constant
//! inertia less what the crank shaft already carries, moved to the chosen
//! shaft — and its size as a disc or a rim of a given material.
//!
//! A ring of outer diameter D, inner diameter d = D − 2h and width b has
//! J = ρ·π·b·(D⁴ − d⁴)/32 and m = ρ·π·b·(D² − d²)/4 (Тимошенко С. П.,
//! Янг Д. Х., *Техническая механика*, table of moments of inertia; the disc
//! is d = 0). With b = ψ_b·D and h = ψ_h·D:
//! J = ρ·π·ψ_b·D⁵·(1 − (1 − 2ψ_h)⁴)/32, so D = (32·J/(ρ·π·ψ_b·(1 − (1 − 2ψ_h)⁴)))^(1/5).

use std::f64::consts::PI;

use super::spec::{FlywheelShape, FlywheelSpec};

/// The size of the flywheel.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FlywheelSize {
    /// Outer diameter D, m.
    pub diameter: f64,
    /// Width b, m.
    pub width: f64,
    /// Radial thickness of the rim h, m (D/2 for a disc).
    pub thickness: f64,
    /// Mass, kg.
    pub mass: f64,
}

/// The size of a flywheel of moment of inertia `inertia` (kg·m², > 0) of the
/// given shape and material.
///
/// ```
/// use tmm_linkage::dynamics::{FlywheelSpec, FlywheelShape, flywheel::size};
/// // a steel disc, b = 0.2·D, of J = 2 kg·m²: J = m·D²/8 must hold
/// let s = size(2.0, &FlywheelSpec::default());
/// assert!((s.mass * s.diameter * s.diameter / 8.0 - 2.0).abs() < 1e-12);
/// assert!((s.width - 0.2 * s.diameter).abs() < 1e-15);
/// ```
pub fn size(inertia: f64, spec: &FlywheelSpec) -> FlywheelSize {
    let (pb, ph) = match spec.shape {
        FlywheelShape::Disc { width_ratio } => (width_ratio, 0.5),
        FlywheelShape::Rim {
            width_ratio,
            thickness_ratio,
        } => (width_ratio, thickness_ratio),
    };
    let inner = 1.0 - 2.0 * ph;
    let k4 = 1.0 - inner.powi(4);
    let k2 = 1.0 - inner * inner;
    let d = (32.0 * inertia / (spec.density * PI * pb * k4)).powf(0.2);
    FlywheelSize {
        diameter: d,
        width: pb * d,
        thickness: ph * d,
        mass: spec.density * PI * pb * d * d * d * k2 / 4.0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A rim against the hollow cylinder's J = m·(D² + d²)/8 (its own formula,
    /// not the fifth-power form the code inverts) and its proportions.
    #[test]
    fn rim_matches_the_hollow_cylinder() {
        let spec = FlywheelSpec {
            place: super::super::spec::FlywheelPlace::Crank,
            density: 7200.0,
            shape: FlywheelShape::Rim {
                width_ratio: 0.15,
                thickness_ratio: 0.08,
            },
            speed_ratio: 1.0,
        };
        let s = size(3.5, &spec);
        let d_in = s.diameter - 2.0 * s.thickness;
        let j = s.mass * (s.diameter * s.diameter + d_in * d_in) / 8.0;
        assert!((j - 3.5).abs() < 1e-12, "{j}");
        assert!((s.width - 0.15 * s.diameter).abs() < 1e-15);
        assert!((s.thickness - 0.08 * s.diameter).abs() < 1e-15);
        // the mass from the volume of the ring
        let vol = PI / 4.0 * (s.diameter * s.diameter - d_in * d_in) * s.width;
        assert!((s.mass - 7200.0 * vol).abs() < 1e-9);
    }
}
