//! Section size of a link for an allowed stress [σ] under tension–compression
//! with bending, σ = |N|/A + |M|/W ≤ [σ] (seed 004 §2.6; Feodosiev,
//! *Сопротивление материалов*, § 4.6), for
//! - a round bar: A = πd²/4, W = πd³/32;
//! - a rectangle h = k·b bending about the axis across b: A = k·b², W = b·h²/6 = k²b³/6;
//! - a rolled I-section (двутавр) from a small table of GOST 8239-89.
//!
//! The worst section of the link is taken among the sampled diagram points.

use super::beam::{Beam, BeamSample};
use super::error::ForceError;

/// A rolled I-section of GOST 8239-89 (двутавр стальной горячекатаный).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IBeam {
    /// Profile number (height in cm).
    pub number: &'static str,
    /// Height h, m.
    pub h: f64,
    /// Area A, m².
    pub area: f64,
    /// Section modulus W_x, m³.
    pub w: f64,
}

/// GOST 8239-89, No. 10…30: h, A (cm²), W_x (cm³), in SI.
pub const IBEAMS: &[IBeam] = &[
    IBeam {
        number: "10",
        h: 0.100,
        area: 12.0e-4,
        w: 39.7e-6,
    },
    IBeam {
        number: "12",
        h: 0.120,
        area: 14.7e-4,
        w: 58.4e-6,
    },
    IBeam {
        number: "14",
        h: 0.140,
        area: 17.4e-4,
        w: 81.7e-6,
    },
    IBeam {
        number: "16",
        h: 0.160,
        area: 20.2e-4,
        w: 109.0e-6,
    },
    IBeam {
        number: "18",
        h: 0.180,
        area: 23.4e-4,
        w: 143.0e-6,
    },
    IBeam {
        number: "20",
        h: 0.200,
        area: 26.8e-4,
        w: 184.0e-6,
    },
    IBeam {
        number: "22",
        h: 0.220,
        area: 30.6e-4,
        w: 232.0e-6,
    },
    IBeam {
        number: "24",
        h: 0.240,
        area: 34.8e-4,
        w: 289.0e-6,
    },
    IBeam {
        number: "27",
        h: 0.270,
        area: 40.2e-4,
        w: 371.0e-6,
    },
    IBeam {
        number: "30",
        h: 0.300,
        area: 46.5e-4,
        w: 472.0e-6,
    },
];

/// The sizes found.
#[derive(Debug, Clone, PartialEq)]
pub struct SectionSizes {
    /// Round bar diameter d, m.
    pub round_d: f64,
    /// Index of the dangerous section (in the samples) for the round bar.
    pub round_at: usize,
    /// Rectangle width b, m.
    pub rect_b: f64,
    /// Rectangle height h = k·b, m.
    pub rect_h: f64,
    /// Index of the dangerous section for the rectangle.
    pub rect_at: usize,
    /// The smallest I-section of the table that holds, if any.
    pub ibeam: Option<(IBeam, usize, f64)>,
}

/// Size the sections for allowed stress `allowed` (Pa) and rectangle ratio
/// `k = h/b` from the diagram samples.
///
/// ```
/// use tmm_linkage::forces::{BeamSample, size_sections};
/// // pure bending M = 100 N·m, [σ] = 100 MPa: πd³/32 = 1e-6 m³
/// let s = [BeamSample { z: 0.0, n: 0.0, q: 0.0, m: 100.0 }];
/// let r = size_sections(&s, 100e6, 2.0).unwrap();
/// assert!((std::f64::consts::PI * r.round_d.powi(3) / 32.0 - 1e-6).abs() < 1e-15);
/// assert!((4.0 * r.rect_b.powi(3) / 6.0 - 1e-6).abs() < 1e-15);
/// ```
pub fn size_sections(samples: &[BeamSample], allowed: f64, k: f64) -> Result<SectionSizes, ForceError> {
    if !(allowed.is_finite() && allowed > 0.0) {
        return Err(ForceError::load("strength.allowed_stress", "the allowed stress must be > 0"));
    }
    if !(k.is_finite() && k > 0.0) {
        return Err(ForceError::load("strength.h_over_b", "the ratio h/b must be > 0"));
    }
    let worst = |area: f64, w: f64| Beam::dangerous(samples, area, w);
    if worst(1.0, 1.0).1 == 0.0 {
        return Err(ForceError::load(
            "strength",
            "the link carries no load at this position: nothing to size",
        ));
    }
    let size = |f: &dyn Fn(f64) -> (f64, f64)| -> Result<f64, ForceError> {
        let g = |x: f64| {
            let (a, w) = f(x);
            worst(a, w).1 / allowed - 1.0
        };
        tmm_geom::root::brent(g, 1e-9, 100.0, 1e-15)
            .ok_or_else(|| ForceError::load("strength", "no section size between 1 nm and 100 m holds the stress"))
    };
    let round = |d: f64| (std::f64::consts::PI * d * d / 4.0, std::f64::consts::PI * d.powi(3) / 32.0);
    let rect = |b: f64| (k * b * b, k * k * b.powi(3) / 6.0);
    let d = size(&round)?;
    let b = size(&rect)?;
    let (ra, rw) = round(d);
    let (qa, qw) = rect(b);
    let ibeam = IBEAMS.iter().find_map(|ib| {
        let (i, s) = worst(ib.area, ib.w);
        (s <= allowed).then_some((*ib, i, s))
    });
    Ok(SectionSizes {
        round_d: d,
        round_at: worst(ra, rw).0,
        rect_b: b,
        rect_h: k * b,
        rect_at: worst(qa, qw).0,
        ibeam,
    })
}
