//! The shaper of the BMSTU textbook (Chernaya & Timofeev 2019), appendix
//! П3, p. 127–129: crank 1 (OA) about O at the origin, coupler 2 (AB),
//! rocker 3 (C–B–D) about the fixed C, slider 4 pinned to the rocker at D
//! and sliding in the vertical slot of the ram 5, the ram on a horizontal
//! guide (синтез механизма поперечно-строгального станка). Given: the ram's
//! stroke H, the time ratio K (K_V5), λ = l_CD/l_BC, l_BC and the distance
//! l_OC; found: l_OA, l_AB, the crank angle φ₀ of the extended extreme
//! position and the direction β of OC, then the guide's height and the
//! centres of mass by the book's rules.
//!
//! **The book's four equations, solved here by one (derived here,
//! docs/synthesis.md § 18).** The rocker points up and swings symmetrically
//! about the vertical: γ = asin(H/(2 l_CD)) (D travels 2 l_CD sin γ = H
//! along X), B_н = C + l_BC·e(π/2 − γ) at the extended position (crank and
//! coupler in line, |OB_н| = l_OA + l_AB), B_к = C + l_BC·e(π/2 + γ) at the
//! folded one (|OB_к| = l_AB − l_OA), C = l_OC·e(β). The book writes
//! B_н = (l_OA + l_AB)·e(φ₀), B_к = (l_OA − l_AB)·e(φ₀ + Δφ_PX) with
//! Δφ_PX = 2πK/(K + 1) for a clockwise crank; so the crank pivot O sees the
//! chord B_нB_к at arg B_к − arg B_н = Δφ_PX + π ≡ θ = π(K − 1)/(K + 1)
//! (−θ for a counter-clockwise crank). That is one equation in β; with its
//! root, l_OA = (|OB_н| − |OB_к|)/2, l_AB = (|OB_н| + |OB_к|)/2,
//! φ₀ = arg B_н. A counter-clockwise crank takes the mirror image (the
//! rocker at 90° ± γ, the working stroke −X). The equation is scanned over β ∈ (−π, π] and every sign
//! change refined by Brent's method; a root with l_OA ≤ 0 is the extended
//! and folded positions exchanged (the same mechanism turning the other
//! way) and is rejected. Book's rules: Y_S5 = Y_C + l_CD − l_CD(1 − cos γ)/2
//! (the guide halves the sag of D's arc), l_AS2 = l_AB/2, l_CS3 = l_CD/2.

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use tmm_geom::Vec2;
use tmm_geom::angle::wrap_pi;
use tmm_geom::root::brent;

use crate::model::{AssemblyHint, FRAME, HintKind, InputDef, LinkDef, MechanismDef, SliderDef};

use super::check::{ASSEMBLY_OFFSET, Expect, check_cycle, check_extremes, check_limits};
use super::error::{SynthesisError, finite, positive, show};
use super::limits::{Drive, Limits};
use super::pivot::polar;
use super::result::{Construction, FreeParameter, Kind, Stroke, Synthesis};
use super::time_ratio::theta_from_k;

/// A request: the book's givens of П3.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShaperRequest {
    /// The ram's stroke H, m.
    pub stroke: f64,
    /// The time ratio K = K_V5 ≥ 1 (the working stroke the slower one).
    pub k: f64,
    /// l_BC: the rocker's pivot C to the coupler's joint B, m.
    pub rocker: f64,
    /// λ = l_CD/l_BC: the rocker's arm to the slider D over l_BC.
    pub lambda: f64,
    /// l_OC: the crank's pivot O to the rocker's pivot C, m.
    pub frame: f64,
    /// l_S5: the ram's centre of mass ahead of D along +X, m (a given of
    /// the masses, written into the `[linkage]`).
    pub ram_center: f64,
    /// Crank direction and speed.
    pub drive: Drive,
    /// Limits.
    pub limits: Limits,
}

/// The shaper's mechanism: O at the origin, C, the links and points named as
/// the book (1 OA, 2 AB, 3 C–B–D, 4 the slider at D, 5 the ram with its
/// point E on the guide at height `y_s5` and its slot through E).
pub fn mechanism(
    c: Vec2,
    (l_oa, l_ab, l_bc, l_cd): (f64, f64, f64, f64),
    y_s5: f64,
    ram_center: f64,
    omega: f64,
    b_near: Vec2,
    phi: f64,
) -> MechanismDef {
    let rocker = LinkDef {
        name: "3".into(),
        points: vec![
            ("C".into(), Vec2::ZERO),
            ("B".into(), Vec2::new(l_bc, 0.0)),
            ("D".into(), Vec2::new(l_cd, 0.0)),
        ],
        mass_center: Vec2::new(0.5 * l_cd, 0.0),
    };
    let mut ram = LinkDef::block("5", "E");
    ram.mass_center = Vec2::new(ram_center, 0.0);
    MechanismDef {
        slider_input: None,
        fixed: vec![("O".into(), Vec2::ZERO), ("C".into(), c)],
        links: vec![
            LinkDef::bar("1", "O", "A", l_oa),
            LinkDef::bar("2", "A", "B", l_ab),
            rocker,
            LinkDef::block("4", "D"),
            ram,
        ],
        sliders: vec![
            SliderDef {
                slider: "5".into(),
                point: "E".into(),
                guide_link: FRAME.into(),
                through: Vec2::new(0.0, y_s5),
                angle: 0.0,
                angle_on_slider: 0.0,
            },
            SliderDef {
                slider: "4".into(),
                point: "D".into(),
                guide_link: "5".into(),
                through: Vec2::ZERO,
                angle: FRAC_PI_2,
                angle_on_slider: 0.0,
            },
        ],
        input: Some(InputDef::crank("1", "O", "A", omega)),
        hints: vec![AssemblyHint {
            point: "B".into(),
            kind: HintKind::Near(b_near),
        }],
        assembly_angle: phi,
        output: Some("5".into()),
    }
}

/// The rocker's angles at the extended and the folded positions: 90° ∓ γ
/// for a clockwise crank (the book's: the ram's working stroke +X), the
/// mirror image 90° ± γ for a counter-clockwise one (working stroke −X).
fn rocker_angles(gamma: f64, sg: f64) -> (f64, f64) {
    (FRAC_PI_2 + sg * gamma, FRAC_PI_2 - sg * gamma)
}

/// B at the two extreme positions for a direction β of OC: (B_н, B_к, C);
/// `sg` the sign of the crank's rotation.
fn extremes(beta: f64, l_oc: f64, l_bc: f64, gamma: f64, sg: f64) -> (Vec2, Vec2, Vec2) {
    let c = polar(beta) * l_oc;
    let (r0, r1) = rocker_angles(gamma, sg);
    (c + polar(r0) * l_bc, c + polar(r1) * l_bc, c)
}

/// Every root β ∈ (−π, π] of arg B_к − arg B_н = `seen` (the signed angle
/// at which O sees the chord B_нB_к), the crank turning in the sense `sg`.
pub fn frame_directions(l_oc: f64, l_bc: f64, gamma: f64, sg: f64, seen: f64) -> Vec<f64> {
    let g = |beta: f64| {
        let (b0, b1, _) = extremes(beta, l_oc, l_bc, gamma, sg);
        wrap_pi(b1.atan2() - b0.atan2()) - seen
    };
    let n = 3600;
    let mut roots: Vec<f64> = Vec::new();
    let mut prev = (-PI, g(-PI));
    for i in 1..=n {
        let x = -PI + TAU * i as f64 / n as f64;
        let v = g(x);
        // a sign change that is not the jump of arg by 2π
        if v.is_finite() && prev.1.is_finite() && (v > 0.0) != (prev.1 > 0.0) && (v - prev.1).abs() < PI {
            if let Some(root) = brent(g, prev.0, x, 1e-15) {
                if g(root).abs() < 1e-9 && roots.iter().all(|q| (q - root).abs() > 1e-9) {
                    roots.push(root);
                }
            }
        }
        prev = (x, v);
    }
    roots
}

/// Synthesise and check over the cycle.
///
/// ```
/// use tmm_linkage::synthesis::shaper::*;
/// use tmm_linkage::synthesis::{Drive, Rotation};
/// // the textbook's П3: H = 0.3 m, K = 1.4, l_BC = 0.5 m, λ = 1.4, l_OC = 0.3 m
/// let s = synthesize(&ShaperRequest { stroke: 0.3, k: 1.4, rocker: 0.5, lambda: 1.4, frame: 0.3,
///     ram_center: 0.164, drive: Drive { rotation: Rotation::Cw, omega: 6.0 }, limits: Default::default() }).unwrap();
/// let (a, b) = (s.length("OA").unwrap(), s.length("AB").unwrap());
/// // the extended extreme: |OB| = l_OA + l_AB with the rocker at 90° − γ
/// let g = (0.3f64 / (2.0 * 0.7)).asin();
/// let c = s.frame[1].1;
/// let bn = tmm_geom::Vec2::new(c.x + 0.5 * (90f64.to_radians() - g).cos(), c.y + 0.5 * (90f64.to_radians() - g).sin());
/// assert!((a + b - bn.hypot()).abs() < 1e-12);
/// // the linkage core finds the ram's stroke and K over the cycle
/// let Some(tmm_linkage::synthesis::Stroke::Linear(h)) = s.check.stroke else { panic!() };
/// assert!((h - 0.3).abs() < 1e-9 && (s.check.k.unwrap() - 1.4).abs() < 1e-9);
/// ```
pub fn synthesize(r: &ShaperRequest) -> Result<Synthesis, SynthesisError> {
    let h = positive("stroke", r.stroke)?;
    let l_bc = positive("rocker", r.rocker)?;
    let lambda = positive("lambda", r.lambda)?;
    let l_oc = positive("frame", r.frame)?;
    finite("ram_center", r.ram_center)?;
    r.limits.validate()?;
    let omega = r.drive.signed_omega()?;
    let theta = theta_from_k(r.k)?;
    let l_cd = lambda * l_bc;
    if h >= 2.0 * l_cd {
        return Err(SynthesisError::infeasible(
            "stroke",
            format!(
                "the ram's stroke H = {} m needs the rocker's arm l_CD = λ·l_BC = {} m longer than H/2 (γ = asin(H/(2 l_CD)))",
                show(h),
                show(l_cd)
            ),
            Some(2.0 * l_cd * 0.99),
        ));
    }
    let gamma = (h / (2.0 * l_cd)).asin();
    // a clockwise crank (the book's) sees the chord from B_н to B_к at +θ
    let sg = omega.signum();
    let seen = -sg * theta;
    let roots = frame_directions(l_oc, l_bc, gamma, sg, seen);
    let mut notes = Vec::new();
    let mut best: Option<(Synthesis, f64)> = None;
    for &beta in &roots {
        let (b0, b1, _) = extremes(beta, l_oc, l_bc, gamma, sg);
        let l_oa = 0.5 * (b0.hypot() - b1.hypot());
        if l_oa <= 0.0 {
            notes.push(format!(
                "β = {:.6}°: rejected, l_OA = (|OB_н| − |OB_к|)/2 = {} m ≤ 0 (the extreme positions are exchanged and the crank would turn the other way)",
                beta.to_degrees(),
                show(l_oa)
            ));
            continue;
        }
        match solve_at(r, beta, gamma, theta, omega) {
            Ok(s) => {
                let t = s.check.transmission_angle_min;
                notes.push(format!("β = {:.6}°: a shaper turning fully", beta.to_degrees()));
                if best.as_ref().is_none_or(|b| t > b.1) {
                    best = Some((s, t));
                }
            }
            Err(e) => notes.push(format!("β = {:.6}°: rejected, {e}", beta.to_degrees())),
        }
    }
    let Some((mut s, _)) = best else {
        return Err(SynthesisError::infeasible(
            "frame",
            format!(
                "no direction β of OC gives a shaper whose crank pivot sees B_нB_к at θ = {:.4}°: {}",
                theta.to_degrees(),
                if notes.is_empty() {
                    "the equation arg B_к − arg B_н = θ has no root (l_OC too long for this chord)".into()
                } else {
                    notes.join("; ")
                }
            ),
            None,
        ));
    };
    let valid = notes.iter().filter(|n| !n.contains("rejected")).count();
    if valid > 1 {
        s.free_parameter = Some(FreeParameter {
            name: "direction β of OC, rad (a root of arg B_к − arg B_н = θ)".into(),
            value: s.angles.iter().find(|(n, _)| n == "beta").map_or(0.0, |a| a.1),
            reason: format!(
                "{} root(s) in (−180°, 180°]: {}; taken: {}",
                roots.len(),
                notes.join("; "),
                "the shaper with the largest smallest transmission angle"
            ),
        });
    }
    Ok(s)
}

/// The mechanism for one root β, checked by the linkage core.
fn solve_at(r: &ShaperRequest, beta: f64, gamma: f64, theta: f64, omega: f64) -> Result<Synthesis, SynthesisError> {
    let (l_bc, l_cd, h) = (r.rocker, r.lambda * r.rocker, r.stroke);
    let sg = omega.signum();
    let (b0, b1, c) = extremes(beta, r.frame, l_bc, gamma, sg);
    let l_oa = 0.5 * (b0.hypot() - b1.hypot());
    let l_ab = 0.5 * (b0.hypot() + b1.hypot());
    let phi0 = b0.atan2();
    // the working stroke (the slower) from the folded position to the
    // extended one: Δφ_PX = 2πK/(K + 1) = π + θ
    let d_px = PI + theta;
    let start = (phi0 + -sg * d_px).rem_euclid(TAU);
    let y_s5 = c.y + l_cd - l_cd * (1.0 - gamma.cos()) / 2.0;
    let def = mechanism(
        c,
        (l_oa, l_ab, l_bc, l_cd),
        y_s5,
        r.ram_center,
        omega,
        b0,
        phi0 + sg * ASSEMBLY_OFFSET,
    );
    let check = check_cycle(
        &def,
        &Expect {
            k: Some(r.k),
            stroke: Some(Stroke::Linear(h)),
        },
        "B near its extended extreme position: the rocker pointing up",
    )?;
    check_limits(&r.limits, &check)?;
    let (r0, r1) = rocker_angles(gamma, sg);
    let (d0, d1) = (c + polar(r0) * l_cd, c + polar(r1) * l_cd);
    check_extremes(&check, "B", [b0, b1])?;
    check_extremes(&check, "D", [d0, d1])?;
    Ok(Synthesis {
        kind: Kind::Shaper,
        given: vec![
            ("stroke".into(), h),
            ("k".into(), r.k),
            ("rocker".into(), l_bc),
            ("lambda".into(), r.lambda),
            ("frame".into(), r.frame),
            ("ram_center".into(), r.ram_center),
        ],
        lengths: vec![
            ("OA".into(), l_oa),
            ("AB".into(), l_ab),
            ("BC".into(), l_bc),
            ("CD".into(), l_cd),
            ("OC".into(), r.frame),
            ("AS2".into(), 0.5 * l_ab),
            ("CS3".into(), 0.5 * l_cd),
        ],
        frame: def.fixed.clone(),
        k: r.k,
        theta,
        stroke: Some(Stroke::Linear(h)),
        free_parameter: None,
        construction: Construction {
            point: "B".into(),
            // the start of the working stroke (the folded position) first
            extremes: [b1, b0],
            locus: None,
            pivot: Vec2::ZERO,
            lines: vec![
                ("folded O-B'".into(), Vec2::ZERO, b1),
                ("extended O-B''".into(), Vec2::ZERO, b0),
                ("rocker C-D'".into(), c, d1),
                ("rocker C-D''".into(), c, d0),
                ("guide".into(), Vec2::new(d0.x.min(d1.x), y_s5), Vec2::new(d0.x.max(d1.x), y_s5)),
            ],
        },
        def,
        check,
        angles: vec![
            ("phi0".into(), phi0),
            ("beta".into(), beta),
            ("phi_start".into(), start),
            ("gamma".into(), gamma),
            ("dphi_working".into(), d_px),
            ("dphi_idle".into(), TAU - d_px),
        ],
        coordinates: vec![("X_C".into(), c.x), ("Y_C".into(), c.y), ("Y_S5".into(), y_s5)],
        shown: vec![],
    })
}
