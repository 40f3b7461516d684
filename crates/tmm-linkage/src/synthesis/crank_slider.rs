//! Crank-slider mechanism, axial or offset (синтез кривошипно-ползунного
//! механизма), seed 000 § 1.2:
//!
//! - by the stroke H and K with λ2 = l2/l1, or the offset e, or the largest
//!   pressure angle given, or the offset that best respects the limits;
//! - by two crank positions and the slider travel between them (§ 1.2.2);
//! - by the mean slider speed and n1 (§ 1.2.3).
//!
//! Closed form (derived here, docs/synthesis.md § 3): at the dead positions
//! the crank and coupler are collinear, |OB_ext| = a = l2 + l1,
//! |OB_fold| = b = l2 − l1, the angle B_ext O B_fold is θ and both points are
//! on the guide at distance e from O, so (law of cosines and twice the area)
//! a² + b² − 2ab·cos θ = H², a·b·sin θ = H·e, whence with t = tan(θ/2)
//! 2·l2 = a + b = √(H² + 2He/t), 2·l1 = a − b = √(H² − 2He·t).
//! Both dead positions lie on one side of the foot of the perpendicular from
//! O to the guide only while b > e, i.e. e < H·cot θ (so θ < 90°, K < 3);
//! with λ2 given this is 1 < λ2 < cot²(θ/2).
//!
//! Placement: crank pivot O at the origin, the guide along x at distance e
//! below O for a counter-clockwise crank (above for clockwise), the slider B
//! to the right; the working (slower) stroke moves the slider away from O.
//! Names: crank OA (1), coupler AB (2), slider B (3).

use tmm_geom::Vec2;
use tmm_geom::root::brent;

use crate::model::{AssemblyHint, HintKind, InputDef, LinkDef, MechanismDef, SliderDef};

use super::check::{ASSEMBLY_OFFSET, Expect, check_cycle, check_extremes, check_limits};
use super::error::{SynthesisError, finite, positive, show};
use super::limits::{Drive, Limits};
use super::locus::Locus;
use super::result::{Construction, FreeParameter, Kind, Stroke, Synthesis};
use super::search::maximize;
use super::time_ratio::theta_from_k;

/// The extra condition of a crank-slider request by H and K.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SliderCondition {
    /// λ2 = l2/l1.
    Lambda(f64),
    /// The offset e ≥ 0 (внеосность), m.
    Offset(f64),
    /// The largest pressure angle over the cycle, rad:
    /// ϑ_max = arcsin((l1 + e)/l2) (seed 000 § 1.2.3).
    MaxPressure(f64),
    /// The offset with the best margin against the pressure-angle limits
    /// (no limits: the smallest largest pressure angle).
    Optimum,
}

/// A crank-slider request by the stroke and K.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CrankSliderRequest {
    /// Stroke H, m.
    pub stroke: f64,
    /// K = v_return/v_working ≥ 1.
    pub k: f64,
    /// The extra condition.
    pub condition: SliderCondition,
    /// Crank direction and speed.
    pub drive: Drive,
    /// Pressure-angle limits.
    pub limits: Limits,
}

/// Lengths of a crank-slider from H, θ, e: (l1, l2), or `None` outside
/// 0 < e < H·cot θ (θ > 0). Derived here (module docs).
pub fn lengths_by_offset(h: f64, theta: f64, e: f64) -> Option<(f64, f64)> {
    if theta <= 0.0 || e <= 0.0 || theta >= std::f64::consts::FRAC_PI_2 || e >= h / theta.tan() {
        return None;
    }
    let t = (0.5 * theta).tan();
    let s = (h * h + 2.0 * h * e / t).sqrt();
    let d = (h * h - 2.0 * h * e * t).sqrt();
    let (l1, l2) = (0.5 * d, 0.5 * s);
    (l1 > 0.0 && l2 > l1 + e && l1.is_finite() && l2.is_finite()).then_some((l1, l2))
}

/// Lengths and offset from H, θ, λ2: (l1, l2, e) (derived here):
/// l1 = H / √((λ+1)² + (λ−1)² − 2(λ²−1)cos θ), e = l1²(λ²−1) sin θ / H.
pub fn lengths_by_lambda(h: f64, theta: f64, lambda: f64) -> (f64, f64, f64) {
    let den = (lambda + 1.0).powi(2) + (lambda - 1.0).powi(2) - 2.0 * (lambda * lambda - 1.0) * theta.cos();
    let l1 = h / den.sqrt();
    let e = l1 * l1 * (lambda * lambda - 1.0) * theta.sin() / h;
    (l1, lambda * l1, e)
}

/// The largest pressure angles on the working and return strokes of the
/// placed mechanism (derived here, docs/synthesis.md § 3): sin ϑ =
/// |l1·sin φ + e|/l2; the working stroke passes φ = 270°, the return 90°;
/// at the folded dead position sin ϑ = e/(l2 − l1).
pub fn pressure(l1: f64, l2: f64, e: f64) -> (f64, f64) {
    let w = ((l1 - e).abs() / l2).min(1.0).asin().max((e / (l2 - l1)).min(1.0).asin());
    let r = ((l1 + e) / l2).min(1.0).asin();
    (w, r)
}

fn ratio(h: f64, theta: f64, e: f64) -> f64 {
    match lengths_by_offset(h, theta, e) {
        Some((l1, l2)) => (l1 + e) / l2,
        None => f64::NAN,
    }
}

/// Synthesise by stroke and K.
pub fn synthesize(r: &CrankSliderRequest) -> Result<Synthesis, SynthesisError> {
    let h = positive("stroke", r.stroke)?;
    let theta = theta_from_k(r.k)?;
    r.limits.validate()?;
    if theta >= std::f64::consts::FRAC_PI_2 {
        return Err(SynthesisError::infeasible(
            "k",
            format!(
                "a crank-slider sees its stroke at θ < 90° from the crank pivot, so K < 3; K = {} gives θ = {:.4}°",
                show(r.k),
                theta.to_degrees()
            ),
            Some(3.0 - 1e-9),
        ));
    }
    let e_max = if theta > 0.0 { h / theta.tan() } else { 0.0 };
    let (l1, l2, e, free) = match r.condition {
        SliderCondition::Lambda(lambda) => {
            let lambda = positive("lambda", lambda)?;
            let top = if theta > 0.0 { (0.5 * theta).tan().powi(-2) } else { f64::INFINITY };
            if lambda <= 1.0 || lambda >= top {
                return Err(SynthesisError::infeasible(
                    "lambda",
                    format!(
                        "λ2 = l2/l1 must lie in (1, cot²(θ/2) = {top:.6}) for K = {}: beyond it the folded dead position passes the foot of the perpendicular from O to the guide and the crank cannot turn (l2 > l1 + e fails)",
                        show(r.k)
                    ),
                    Some(if lambda <= 1.0 { 1.0 + 1e-9 } else { top * (1.0 - 1e-9) }),
                ));
            }
            let (l1, l2, e) = lengths_by_lambda(h, theta, lambda);
            (
                l1,
                l2,
                e,
                FreeParameter {
                    name: "offset e".into(),
                    value: e,
                    reason: format!("follows from λ2 = {lambda} given"),
                },
            )
        }
        SliderCondition::Offset(e) => {
            let e = finite("offset", e)?;
            if theta == 0.0 {
                return Err(SynthesisError::infeasible(
                    "offset",
                    "K = 1 needs an axial mechanism (e = 0) and then λ2 or the pressure angle fixes the coupler; give --lambda or --max-pressure",
                    Some(0.0),
                ));
            }
            let Some((l1, l2)) = lengths_by_offset(h, theta, e) else {
                return Err(SynthesisError::infeasible(
                    "offset",
                    format!(
                        "the offset must lie in (0, H·cot θ = {} m) for H = {} m and K = {}; {} m was given",
                        show(e_max),
                        show(h),
                        show(r.k),
                        show(e)
                    ),
                    Some(e.clamp(1e-9 * e_max, e_max * (1.0 - 1e-9))),
                ));
            };
            (
                l1,
                l2,
                e,
                FreeParameter {
                    name: "offset e".into(),
                    value: e,
                    reason: "given".into(),
                },
            )
        }
        SliderCondition::MaxPressure(p) => {
            let p = finite("max_pressure", p)?;
            if !(p > 0.0 && p < std::f64::consts::FRAC_PI_2) {
                return Err(SynthesisError::input(
                    "max_pressure",
                    "the pressure angle must lie between 0° and 90°",
                ));
            }
            let sp = p.sin();
            if theta == 0.0 {
                let (l1, l2) = (0.5 * h, 0.5 * h / sp);
                (
                    l1,
                    l2,
                    0.0,
                    FreeParameter {
                        name: "λ2 = l2/l1".into(),
                        value: 1.0 / sp,
                        reason: "axial (K = 1): sin ϑ_max = l1/l2".into(),
                    },
                )
            } else {
                // (l1 + e)/l2 → 1 at both ends of (0, e_max): its minimum is
                // the smallest largest pressure angle this H and K allow
                let (em, gm) = maximize(|e| -ratio(h, theta, e), 0.0, e_max, 200)
                    .ok_or_else(|| SynthesisError::Check("no offset gives a crank-slider".into()))?;
                let gmin = -gm;
                if gmin > sp {
                    return Err(SynthesisError::infeasible(
                        "max_pressure",
                        format!(
                            "the largest pressure angle of a crank-slider with H = {} m and K = {} is at least {:.4}° (at e = {} m); {:.4}° was given",
                            show(h),
                            show(r.k),
                            gmin.asin().to_degrees(),
                            show(em),
                            p.to_degrees()
                        ),
                        Some(gmin.asin()),
                    ));
                }
                let f = |e: f64| ratio(h, theta, e) - sp;
                let mut sols = Vec::with_capacity(2);
                for (a, b) in [(e_max * 1e-12, em), (em, e_max * (1.0 - 1e-12))] {
                    if let Some(e) = brent(f, a, b, 1e-15 * e_max) {
                        if let Some((l1, l2)) = lengths_by_offset(h, theta, e) {
                            sols.push((l1, l2, e));
                        }
                    }
                }
                let score = |&(l1, l2, e): &(f64, f64, f64)| {
                    let (w, rr) = pressure(l1, l2, e);
                    r.limits.margin(w, rr) - 1e-6 * w
                };
                let n = sols.len();
                let Some(best) = sols.into_iter().max_by(|a, b| score(a).total_cmp(&score(b))) else {
                    return Err(SynthesisError::infeasible(
                        "max_pressure",
                        "no offset reaches this pressure angle",
                        Some(gmin.asin()),
                    ));
                };
                (
                    best.0,
                    best.1,
                    best.2,
                    FreeParameter {
                        name: "offset e".into(),
                        value: best.2,
                        reason: format!(
                            "arcsin((l1 + e)/l2) = {:.4}° given; of the {n} offsets meeting it, the one with the smaller pressure angle on the working stroke",
                            p.to_degrees()
                        ),
                    },
                )
            }
        }
        SliderCondition::Optimum => {
            if theta == 0.0 {
                let (lw, lr) = r.limits.pressure();
                let Some(lim) = [lw, lr].into_iter().flatten().reduce(f64::min) else {
                    return Err(SynthesisError::input(
                        "optimum",
                        "with K = 1 (axial) the pressure angle falls as λ2 grows without end: give λ2, the largest pressure angle or a limit",
                    ));
                };
                let lam = 1.0 / lim.sin();
                (
                    0.5 * h,
                    0.5 * h * lam,
                    0.0,
                    FreeParameter {
                        name: "λ2 = l2/l1".into(),
                        value: lam,
                        reason: "the shortest coupler meeting the pressure-angle limit (axial: sin ϑ_max = l1/l2)".into(),
                    },
                )
            } else {
                let score = |e: f64| match lengths_by_offset(h, theta, e) {
                    Some((l1, l2)) => {
                        let (w, rr) = pressure(l1, l2, e);
                        r.limits.margin(w, rr)
                    }
                    None => f64::NAN,
                };
                let (e, _) =
                    maximize(score, 0.0, e_max, 200).ok_or_else(|| SynthesisError::Check("no offset gives a crank-slider".into()))?;
                let (l1, l2) =
                    lengths_by_offset(h, theta, e).ok_or_else(|| SynthesisError::Check("the optimum offset is not feasible".into()))?;
                (
                    l1,
                    l2,
                    e,
                    FreeParameter {
                        name: "offset e".into(),
                        value: e,
                        reason: if r.limits.any() {
                            "the offset with the largest margin against the pressure-angle limits".into()
                        } else {
                            "the offset with the smallest largest pressure angle".into()
                        },
                    },
                )
            }
        }
    };
    let mut given = vec![("stroke".into(), h), ("k".into(), r.k)];
    match r.condition {
        SliderCondition::Lambda(x) => given.push(("lambda".into(), x)),
        SliderCondition::Offset(x) => given.push(("offset".into(), x)),
        SliderCondition::MaxPressure(x) => given.push(("max_pressure".into(), x)),
        SliderCondition::Optimum => {}
    }
    build(
        Kind::CrankSlider,
        given,
        l1,
        l2,
        e,
        r.k,
        theta,
        Some(h),
        Some(free),
        r.drive,
        &r.limits,
    )
}

/// The placed mechanism, its construction and its check.
#[allow(clippy::too_many_arguments)]
fn build(
    kind: Kind,
    given: Vec<(String, f64)>,
    l1: f64,
    l2: f64,
    e: f64,
    k: f64,
    theta: f64,
    stroke: Option<f64>,
    free: Option<FreeParameter>,
    drive: Drive,
    limits: &Limits,
) -> Result<Synthesis, SynthesisError> {
    let omega = drive.signed_omega()?;
    let yg = -omega.signum() * e;
    let x_ext = ((l1 + l2).powi(2) - e * e).sqrt();
    let x_fold = ((l2 - l1).powi(2) - e * e).sqrt();
    let b_ext = Vec2::new(x_ext, yg);
    let b_fold = Vec2::new(x_fold, yg);
    let def = mechanism(l1, l2, yg, omega, b_ext);
    let check = check_cycle(
        &def,
        &Expect {
            k: stroke.map(|_| k),
            stroke: stroke.map(Stroke::Linear),
        },
        "B on the side of O's projection on the guide away from O (x > 0)",
    )?;
    check_limits(limits, &check)?;
    if stroke.is_some() {
        check_extremes(&check, "B", [b_fold, b_ext])?;
    }
    let locus = if theta > 0.0 { Locus::new(b_fold, b_ext, theta).ok() } else { None };
    let side = if tmm_geom::cross(b_ext - b_fold, -b_fold) > 0.0 {
        1.0
    } else {
        -1.0
    };
    Ok(Synthesis {
        kind,
        given,
        lengths: vec![("OA".into(), l1), ("AB".into(), l2), ("e".into(), e)],
        frame: def.fixed.clone(),
        k,
        theta,
        stroke: stroke.map(Stroke::Linear),
        free_parameter: free,
        construction: Construction {
            point: "B".into(),
            extremes: [b_fold, b_ext],
            locus: locus.and_then(|l| l.circle(side)),
            pivot: Vec2::ZERO,
            lines: vec![("guide".into(), Vec2::new(0.0, yg), Vec2::new(x_ext, yg))],
        },
        def,
        check,
        angles: vec![],
        coordinates: vec![],
        shown: vec![],
    })
}

/// The mean-speed request (seed 000 § 1.2.3): the crank turns once in
/// t = 1/n1 and the slider goes there and back, H = v_mean·t/2 = v_mean/(2·n1);
/// the rest as [`synthesize`] (axial, K = 1: l1 = H/2 = v_mean/(4·n1)).
///
/// ```
/// use tmm_linkage::synthesis::crank_slider::*;
/// use tmm_linkage::synthesis::Drive;
/// // v = 2 m/s, n1 = 5 rev/s, axial with λ2 = 4: l1 = 2/(4·5) = 0.1 m
/// let s = by_mean_speed(2.0, 5.0, 1.0, SliderCondition::Lambda(4.0), Drive::default(), Default::default()).unwrap();
/// assert!((s.length("OA").unwrap() - 0.1).abs() < 1e-12);
/// ```
pub fn by_mean_speed(
    v_mean: f64,
    n1: f64,
    k: f64,
    condition: SliderCondition,
    drive: Drive,
    limits: Limits,
) -> Result<Synthesis, SynthesisError> {
    let v = positive("v_mean", v_mean)?;
    let n = positive("n1", n1)?;
    let mut s = synthesize(&CrankSliderRequest {
        stroke: v / (2.0 * n),
        k,
        condition,
        drive,
        limits,
    })?;
    s.given.insert(0, ("n1".into(), n));
    s.given.insert(0, ("v_mean".into(), v));
    Ok(s)
}

/// The two-positions request (seed 000 § 1.2.2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TwoPositionsRequest {
    /// λ2 = l2/l1.
    pub lambda: f64,
    /// λe = e/l1 (signed: the guide at y = e).
    pub lambda_e: f64,
    /// Initial crank angle φ1н, rad.
    pub phi_start: f64,
    /// Final crank angle φ1к, rad.
    pub phi_end: f64,
    /// Slider travel h_C = x_Cн − x_Cк between them, m (signed).
    pub travel: f64,
    /// Crank direction and speed.
    pub drive: Drive,
    /// Pressure-angle limits, checked over the cycle.
    pub limits: Limits,
}

/// Synthesis by two crank positions and the slider travel between them
/// (seed 000 § 1.2.2, system 1.4): φ2 = arcsin((λe − sin φ1)/λ2),
/// l1 = h_C / [cos φ1н − cos φ1к + λ2 (cos φ2н − cos φ2к)], l2 = λ2·l1,
/// e = λe·l1; the pressure angles at the two positions are |φ2н|, |φ2к|.
/// The slider is on the branch x_C > x_A (cos φ2 > 0), the guide at y = e.
pub fn by_two_positions(r: &TwoPositionsRequest) -> Result<Synthesis, SynthesisError> {
    let lam = positive("lambda", r.lambda)?;
    let le = finite("lambda_e", r.lambda_e)?;
    let (p0, p1) = (finite("phi_start", r.phi_start)?, finite("phi_end", r.phi_end)?);
    let hc = finite("travel", r.travel)?;
    r.limits.validate()?;
    if lam <= 1.0 + le.abs() {
        return Err(SynthesisError::infeasible(
            "lambda",
            format!("the crank turns fully only when λ2 > 1 + |λe| = {}", show(1.0 + le.abs())),
            Some(1.0 + le.abs() + 1e-9),
        ));
    }
    let phi2 = |p: f64| ((le - p.sin()) / lam).asin();
    let (a0, a1) = (phi2(p0), phi2(p1));
    let den = p0.cos() - p1.cos() + lam * (a0.cos() - a1.cos());
    let l1 = hc / den;
    if !(l1.is_finite() && l1 > 0.0) {
        return Err(SynthesisError::infeasible(
            "travel",
            format!(
                "the slider moves by {:.6}·l1 from φ1н to φ1к, so the travel must have that sign and not be zero; {} m was given",
                den,
                show(hc)
            ),
            None,
        ));
    }
    let e = le * l1;
    let (l2, omega) = (lam * l1, r.drive.signed_omega()?);
    let x_ext = ((l1 + l2).powi(2) - e * e).sqrt();
    let b_ext = Vec2::new(x_ext, e);
    let def = mechanism(l1, l2, e, omega, b_ext);
    let check = check_cycle(&def, &Expect { k: None, stroke: None }, "B on the side x > x_A")?;
    let s_at = |p: f64| -> Result<Vec2, SynthesisError> {
        let pts = super::check::points_at(&crate::mechanism::Mechanism::new(&def)?, p)?;
        Ok(pts.iter().find(|(n, _)| n == "B").map(|(_, q)| *q).unwrap_or(Vec2::ZERO))
    };
    let moved = s_at(p0)?.x - s_at(p1)?.x;
    if (moved - hc).abs() > 1e-9 * hc.abs().max(1e-3) {
        return Err(SynthesisError::Check(format!(
            "the slider moves {moved:.12} m between the two positions, {hc:.12} m requested"
        )));
    }
    let k = check.k.unwrap_or(1.0);
    let theta = check.theta.unwrap_or(0.0);
    let stroke = check.stroke;
    Ok(Synthesis {
        kind: Kind::CrankSlider,
        given: vec![
            ("lambda".into(), lam),
            ("lambda_e".into(), le),
            ("phi_start".into(), p0),
            ("phi_end".into(), p1),
            ("travel".into(), hc),
        ],
        lengths: vec![("OA".into(), l1), ("AB".into(), l2), ("e".into(), e)],
        frame: def.fixed.clone(),
        k,
        theta,
        stroke,
        free_parameter: Some(FreeParameter {
            name: "pressure angles at the two positions φ2н, φ2к".into(),
            value: a0.abs().max(a1.abs()),
            reason: format!(
                "follow from the given λ2, λe: ϑн = {:.4}°, ϑк = {:.4}°",
                a0.abs().to_degrees(),
                a1.abs().to_degrees()
            ),
        }),
        construction: Construction {
            point: "B".into(),
            extremes: [point_of(&check, 0, "B"), point_of(&check, 1, "B")],
            locus: None,
            pivot: Vec2::ZERO,
            lines: vec![("guide".into(), Vec2::new(0.0, e), b_ext)],
        },
        def,
        check,
        // the book's unknowns φ2н, φ2к (rod angle at A from +x) and X_Cн
        // (seed 000 § 1.2.2, system 1.4; GIVENS.md П1.1)
        angles: vec![("phi2_start".into(), a0), ("phi2_end".into(), a1)],
        coordinates: vec![("X_C_start".into(), l1 * p0.cos() + l2 * a0.cos())],
        shown: vec![p0, p1],
    })
}

/// A named point at dead position `i` as found by the check.
fn point_of(check: &super::result::CheckReport, i: usize, name: &str) -> Vec2 {
    check
        .dead_positions
        .get(i)
        .and_then(|v| v.iter().find(|(n, _)| n == name))
        .map_or(Vec2::ZERO, |(_, p)| *p)
}

/// The crank-slider O–A–B with the slider block 3 on a horizontal guide at
/// height `yg` through the frame, assembled with B near `b_ext` (the
/// extended dead position).
fn mechanism(l1: f64, l2: f64, yg: f64, omega: f64, b_ext: Vec2) -> MechanismDef {
    MechanismDef {
        slider_input: None,
        fixed: vec![("O".into(), Vec2::ZERO)],
        links: vec![
            LinkDef::bar("1", "O", "A", l1),
            LinkDef::bar("2", "A", "B", l2),
            LinkDef::block("3", "B"),
        ],
        sliders: vec![SliderDef {
            slider: "3".into(),
            point: "B".into(),
            guide_link: crate::model::FRAME.into(),
            through: Vec2::new(0.0, yg),
            angle: 0.0,
            angle_on_slider: 0.0,
        }],
        input: Some(InputDef::crank("1", "O", "A", omega)),
        hints: vec![AssemblyHint {
            point: "B".into(),
            kind: HintKind::Near(b_ext),
        }],
        assembly_angle: b_ext.atan2() + ASSEMBLY_OFFSET,
        output: Some("3".into()),
    }
}
