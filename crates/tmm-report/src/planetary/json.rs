//! The JSON document of a planetary run (SI, angles in radians).
//!
//! `z` lists the tooth numbers in the scheme's order (`z_order`):
//! `[z1, z2, z3]` for `sun-planet-ring`, `[z1, z2, z2′, z3]` for `ext-int`,
//! `ext-ext` and `int-int`. `radial_size` is in modules of row I.

use serde_json::{Value, json};
use tmm_planetary::{Candidate, Scheme};

use super::analysis::Analysis;
use crate::output::num;

fn candidate(scheme: Scheme, c: &Candidate) -> Value {
    json!({
        "z": c.teeth.to_vec(scheme),
        "ratio": num(c.ratio.value()),
        "ratio_fraction": [c.ratio.num, c.ratio.den],
        "error": num(c.error),
        "radial_size": num(c.radial_size),
        "module_ratio": [c.modules.num, c.modules.den],
        "assembly_positions": c.positions,
        "equal_spacing": c.equal_spacing,
    })
}

/// The document.
pub fn document(a: &Analysis) -> Value {
    let r = &a.params.request;
    let sc = r.scheme;
    let b = &a.best;
    let mut best = candidate(sc, b);
    let p = &a.picture;
    let extra = json!({
        "radial_size_m": num(b.radial_size * a.params.module),
        "centre_distance": num(a.centre_distance),
        "planet_angles": a.planet_angles.iter().map(|x| num(*x)).collect::<Vec<_>>(),
        "ratio_from_picture": num(p.ratio),
        "ratio_from_angular_diagram": num(a.diagram.ratio),
        "efficiency": {
            "carrier_fixed": num(a.eta_h),
            "driver": a.driver,
            "value": num(a.efficiency),
            "reverse": num(a.efficiency_reverse),
        },
        "velocity_picture": {
            "a": {"r": num(p.a.r), "v": num(p.a.v)},
            "b": {"r": num(p.b.r), "v": num(p.b.v)},
            "c": {"r": num(p.c.r), "v": num(p.c.v)},
            "omega1": num(p.omega1),
            "omega_carrier": num(p.omega_h),
            "omega_planet": num(p.omega_planet),
        },
    });
    if let (Value::Object(m), Value::Object(e)) = (&mut best, extra) {
        m.extend(e);
    }
    let c = &a.synthesis.counts;
    json!({
        "units": "SI",
        "scheme": sc.name(),
        "z_order": sc.teeth_names(),
        "request": {
            "ratio": num(r.ratio),
            "planets": r.planets,
            "tolerance": num(r.tolerance),
            "zmin": r.limits.zmin,
            "zmax": r.limits.zmax,
            "ring_zmin": r.limits.ring_zmin,
            "min_difference": r.limits.min_difference,
            "addendum": num(r.limits.addendum),
            "two_modules": r.two_modules,
            "module": num(a.params.module),
            "omega1": num(a.params.omega1),
            "efficiency_external": num(a.params.efficiency.external),
            "efficiency_internal": num(a.params.efficiency.internal),
        },
        "equal_spacing": a.synthesis.equal_spacing,
        "counts": {
            "ratio_coaxiality": c.ratio,
            "no_undercut": c.undercut,
            "internal_mesh": c.internal,
            "assembly": c.assembly,
            "assembly_equal": c.equal,
            "neighbour": c.neighbour,
            "unequal": c.unequal,
        },
        "best": best,
        "candidates_total": a.synthesis.candidates.len(),
        "candidates": a.synthesis.candidates.iter().take(a.params.top).map(|c| candidate(sc, c)).collect::<Vec<_>>(),
    })
}
