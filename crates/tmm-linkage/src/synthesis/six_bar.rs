//! Six-bars synthesised in two stages (двухэтапный синтез шестизвенника): a
//! rocker-slider part whose rocker is a lever pivoted on the frame, then the
//! four-bar that swings that lever by K ([`super::pivot`]).
//!
//! - By kinematic inversion (метод обращения движения), seed 002, example 4:
//!   the slider's start E′ and its travel H along the guide, the coupler l_ED
//!   and the lever's swing γ are given, the lever's arm O3D is not. Fixing the
//!   lever and turning the frame by −γ about O3 carries E″ to E″ᵢ; D′ is at
//!   l_ED from both E′ and E″ᵢ — the intersection of two circles, closed form.
//!   The lever's other arm O3B (given) gives B′, B″ on the extensions.
//! - By the pressure angle, seed 003 §§ 3–4: the lever BEC (arms l_EB, l_EC)
//!   swings by ψ symmetric about the perpendicular to the guide; the four-bar
//!   has the given largest pressure angle; the coupler CD is the shortest that
//!   keeps the slider's pressure angle within the same limit:
//!   l_CD = max |y_C − y_guide| / sin ϑ over the swing (sin ϑ = |y_C − y_g|/l_CD
//!   for a coupler driving a slider on a guide along x).
//!
//! Names (seed 002, ex. 4): crank O1A (1), coupler AB (2), lever B-O3-D (3),
//! coupler DE (4), slider E (5). Seed 003: crank OA (1), coupler AB (2), lever
//! B-E-C (3), coupler CD (4), slider D (5).

use std::f64::consts::{FRAC_PI_2, PI};

use tmm_geom::Vec2;

use crate::model::{AssemblyHint, HintKind, InputDef, LinkDef, MechanismDef, SliderDef};

use super::check::{ASSEMBLY_OFFSET, Expect, check_cycle, check_extremes, check_limits};
use super::error::{SynthesisError, finite, positive};
use super::limits::{Drive, Limits};
use super::locus::Locus;
use super::pivot::{PivotChoice, PivotCondition, choose, polar};
use super::result::{Construction, FreeParameter, Kind, Stroke, Synthesis};
use super::time_ratio::theta_from_k;

fn rot(v: Vec2, a: f64) -> Vec2 {
    let (s, c) = a.sin_cos();
    Vec2::new(c * v.x - s * v.y, s * v.x + c * v.y)
}

/// The six-bar by kinematic inversion (seed 002, example 4).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InversionRequest {
    /// K ≥ 1.
    pub k: f64,
    /// Signed travel of the slider along +x from E′ to E″, m (H = |travel|).
    pub travel: f64,
    /// Height of the slider's guide above O3 (negative: below), m.
    pub guide: f64,
    /// Abscissa of the slider's start E′ from O3, m.
    pub start: f64,
    /// Coupler l_ED, m.
    pub coupler: f64,
    /// Signed swing γ of the lever from D′ to D″, rad (> 0 counter-clockwise).
    pub swing: f64,
    /// The lever's other arm l_O3B, m.
    pub lever: f64,
    /// The four-bar's crank pivot condition (seed 002: on the line at a = 0.2 m
    /// from O3).
    pub pivot: PivotCondition,
    /// Crank direction and speed.
    pub drive: Drive,
    /// Limits.
    pub limits: Limits,
}

/// Synthesise the six-bar by inversion and check it.
pub fn by_inversion(r: &InversionRequest) -> Result<Synthesis, SynthesisError> {
    let theta = theta_from_k(r.k)?;
    let travel = finite("travel", r.travel)?;
    let h = travel.abs();
    positive("travel", h)?;
    let yg = finite("guide", r.guide)?;
    let x0 = finite("start", r.start)?;
    let led = positive("coupler", r.coupler)?;
    let gamma = finite("swing", r.swing)?;
    if !(gamma.abs() > 0.0 && gamma.abs() < PI) {
        return Err(SynthesisError::input(
            "swing",
            "the lever's swing must lie in (0°, 180°) either way",
        ));
    }
    let lb = positive("lever", r.lever)?;
    r.limits.validate()?;
    let omega = r.drive.signed_omega()?;
    let e1 = Vec2::new(x0, yg);
    let e2 = Vec2::new(x0 + travel, yg);
    // inversion: the frame turned by −γ about O3 carries E″ here
    let e2i = rot(e2, -gamma);
    let dv = e2i - e1;
    let dd = dv.hypot();
    if !(dd > 1e-12 && dd < 2.0 * led) {
        return Err(SynthesisError::infeasible(
            "coupler",
            format!(
                "the coupler ED must be longer than half the distance |E′E″ᵢ| = {} m between the slider's start and its inverted end",
                super::error::show(0.5 * dd)
            ),
            Some(0.5 * dd * (1.0 + 1e-6)),
        ));
    }
    let mid = e1 + dv * 0.5;
    let off = (led * led - 0.25 * dd * dd).sqrt();
    let n = Vec2::new(-dv.y, dv.x) * (1.0 / dd);
    // a candidate D′ is valid when the slider moves monotonically from E′ to
    // E″ while the lever turns from D′ by γ on one assembly branch: the
    // derivative dx_E/dβ = ẋ_D + s·(y_g − y_D)·ẏ_D/√(l_ED² − (y_g − y_D)²) keeps
    // the sign of the travel at every sample and at both ends (it vanishes
    // only where DE lies along the lever, a dead position of the
    // rocker-slider)
    let valid = |d1: Vec2| -> Option<f64> {
        let rho = d1.hypot();
        if rho < 1e-9 * led {
            return None;
        }
        let s = (e1.x - d1.x).signum();
        let steps = 256;
        let mut worst = 0.0f64;
        let mut x = e1.x;
        for k in 0..=steps {
            let d = rot(d1, gamma * k as f64 / steps as f64);
            let dy = yg - d.y;
            let root = (led * led - dy * dy).sqrt();
            if root.is_nan() || root <= 1e-9 * led {
                return None;
            }
            let v = Vec2::new(-d.y, d.x) * gamma.signum();
            let dx = v.x + s * dy * v.y / root;
            if dx * travel.signum() <= 1e-9 * rho {
                return None;
            }
            x = d.x + s * root;
            worst = worst.max((dy.abs() / led).asin());
        }
        ((x - e2.x).abs() < 1e-9 * h.max(1.0)).then_some(worst)
    };
    let mut cands: Vec<(Vec2, f64)> = [mid + n * off, mid - n * off]
        .into_iter()
        .filter_map(|d| valid(d).map(|w| (d, w)))
        .collect();
    cands.sort_by(|a, b| a.1.total_cmp(&b.1));
    let Some(&(d1, _)) = cands.first() else {
        return Err(SynthesisError::infeasible(
            "coupler",
            "neither intersection of the circles about E′ and E″ᵢ moves the slider monotonically over the lever's swing on one assembly branch",
            None,
        ));
    };
    let d2 = rot(d1, gamma);
    let rho = d1.hypot();
    let b1 = d1 * (-lb / rho);
    let b2 = d2 * (-lb / rho);
    let locus = Locus::new(b1, b2, theta)?;
    let choice = choose(locus, Vec2::ZERO, omega.signum(), r.pivot, &r.limits, "pivot", None)?;
    let b = choice.bar;
    let (d_ext, e_ext) = if (b.c_ext - b1).hypot() < (b.c_ext - b2).hypot() {
        (d1, e1)
    } else {
        (d2, e2)
    };
    let lever = LinkDef {
        name: "3".into(),
        points: vec![
            ("O3".into(), Vec2::ZERO),
            ("B".into(), Vec2::new(lb, 0.0)),
            ("D".into(), Vec2::new(-rho, 0.0)),
        ],
        mass_center: Vec2::ZERO,
    };
    let def = six_bar_def(
        ("O1", "O3"),
        b.o,
        [b.l1, b.l2],
        lever,
        ("D", "E", led),
        yg,
        omega,
        [("B", b.c_ext), ("D", d_ext), ("E", e_ext)],
        b.phi_ext + ASSEMBLY_OFFSET,
    );
    let check = check_cycle(
        &def,
        &Expect {
            k: Some(r.k),
            stroke: Some(Stroke::Linear(h)),
        },
        "B, D and E near their extreme positions found by the construction",
    )?;
    check_limits(&r.limits, &check)?;
    check_extremes(&check, "B", [b1, b2])?;
    check_extremes(&check, "E", [e1, e2])?;
    Ok(Synthesis {
        kind: Kind::SixBar,
        given: vec![
            ("k".into(), r.k),
            ("travel".into(), travel),
            ("guide".into(), yg),
            ("start".into(), x0),
            ("coupler".into(), led),
            ("swing".into(), gamma),
            ("lever".into(), lb),
        ],
        lengths: vec![
            ("O1A".into(), b.l1),
            ("AB".into(), b.l2),
            ("O3B".into(), lb),
            ("O3D".into(), rho),
            ("DE".into(), led),
            ("O1O3".into(), b.frame),
        ],
        frame: def.fixed.clone(),
        k: r.k,
        theta,
        stroke: Some(Stroke::Linear(h)),
        free_parameter: Some(free(
            &choice,
            "the lever's arm O3D follows from the inversion (the intersection with the smaller pressure angle on the slider)",
        )),
        construction: Construction {
            point: "B".into(),
            extremes: [b1, b2],
            locus: locus.circle(b.side),
            pivot: b.o,
            lines: {
                let mut v = vec![
                    ("E'-D'".into(), e1, d1),
                    ("E''i-D'".into(), e2i, d1),
                    ("E''-D''".into(), e2, d2),
                    (
                        "guide".into(),
                        Vec2::new(0.0f64.min(e1.x).min(e2.x), yg),
                        Vec2::new(0.0f64.max(e1.x).max(e2.x), yg),
                    ),
                ];
                // the seed's condition: the crank pivot on a given line
                if let PivotCondition::OnLine { point, .. } = r.pivot {
                    v.push(("pivot line".into(), point, b.o));
                }
                v
            },
        },
        def,
        check,
        angles: vec![],
        coordinates: vec![],
        shown: vec![],
    })
}

fn free(choice: &PivotChoice, stage1: &str) -> FreeParameter {
    FreeParameter {
        name: "position of the four-bar's crank pivot on the locus".into(),
        value: choice.bar.l1,
        reason: format!("{stage1}; {}", choice.reason),
    }
}

/// The six-bar by the pressure angle (seed 003).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PressureRequest {
    /// K ≥ 1.
    pub k: f64,
    /// Swing ψ of the lever, rad.
    pub swing: f64,
    /// The lever's arm l_EB to the four-bar's coupler, m.
    pub arm_b: f64,
    /// The lever's arm l_EC to the slider's coupler, m.
    pub arm_c: f64,
    /// The angle from EB to EC on the lever, rad (π: a straight lever).
    pub arm_angle: f64,
    /// The slider's guide: its signed height above E, m (seed 003: −0.2).
    pub guide: f64,
    /// The largest pressure angle allowed in the joints B and D, rad.
    pub max_pressure: f64,
    /// The four-bar's crank pivot condition (seed 003: the largest pressure
    /// angle, [`PivotCondition::MaxPressure`]).
    pub pivot: PivotCondition,
    /// Crank direction and speed.
    pub drive: Drive,
    /// Limits.
    pub limits: Limits,
}

/// Synthesise the six-bar by the pressure angle and check it.
///
/// ```
/// use tmm_linkage::synthesis::six_bar::*;
/// use tmm_linkage::synthesis::pivot::PivotCondition;
/// let p = 38f64.to_radians();
/// let s = by_pressure(&PressureRequest { k: 1.07, swing: 55f64.to_radians(), arm_b: 0.6, arm_c: 0.6,
///     arm_angle: std::f64::consts::PI, guide: -0.2, max_pressure: p, pivot: PivotCondition::ExtremePressure(p),
///     drive: Default::default(), limits: Default::default() }).unwrap();
/// // seed 003: l_CD = 0.4 m / sin 38° ≈ 0.65 m
/// assert!((s.length("CD").unwrap() - 0.4 / p.sin()).abs() < 1e-12);
/// assert!((s.check.k.unwrap() - 1.07).abs() < 1e-9);
/// ```
pub fn by_pressure(r: &PressureRequest) -> Result<Synthesis, SynthesisError> {
    let theta = theta_from_k(r.k)?;
    let psi = positive("swing", r.swing)?;
    if psi >= PI {
        return Err(SynthesisError::input("swing", "the lever's swing must be less than 180°"));
    }
    let lb = positive("arm_b", r.arm_b)?;
    let lc = positive("arm_c", r.arm_c)?;
    let arm = finite("arm_angle", r.arm_angle)?;
    let yg = finite("guide", r.guide)?;
    let p = finite("max_pressure", r.max_pressure)?;
    if !(p > 0.0 && p < FRAC_PI_2) {
        return Err(SynthesisError::input(
            "max_pressure",
            "the pressure angle must lie between 0° and 90°",
        ));
    }
    r.limits.validate()?;
    let omega = r.drive.signed_omega()?;
    // B swings symmetric about +y; C at `arm` from EB
    let (a1, a2) = (FRAC_PI_2 + 0.5 * psi, FRAC_PI_2 - 0.5 * psi);
    let b1 = polar(a1) * lb;
    let b2 = polar(a2) * lb;
    // the largest distance of C from the guide over the swing
    let cy = |a: f64| lc * (a + arm).sin();
    let mut far = (cy(a1) - yg).abs().max((cy(a2) - yg).abs());
    for t in [FRAC_PI_2, -FRAC_PI_2] {
        let a = tmm_geom::angle::wrap_pi(t - arm - a2);
        if (0.0..=psi).contains(&(a.rem_euclid(2.0 * PI))) {
            far = far.max((lc * t.sin() - yg).abs());
        }
    }
    if far.is_nan() || far <= 0.0 {
        return Err(SynthesisError::input("guide", "the guide passes through every position of C"));
    }
    let lcd = far / p.sin();
    let locus = Locus::new(b1, b2, theta)?;
    let pivot = match r.pivot {
        PivotCondition::MaxPressure(x) => PivotCondition::MaxPressure(finite("pivot.max_pressure", x)?),
        PivotCondition::ExtremePressure(x) => PivotCondition::ExtremePressure(finite("pivot.extreme_pressure", x)?),
        other => other,
    };
    let choice = choose(locus, Vec2::ZERO, omega.signum(), pivot, &r.limits, "pivot", None)?;
    let b = choice.bar;
    let c_of = |bb: Vec2| polar(bb.atan2() + arm) * lc;
    let c_ext = c_of(b.c_ext);
    let d_ext = Vec2::new(c_ext.x + (lcd * lcd - (yg - c_ext.y).powi(2)).max(0.0).sqrt(), yg);
    let lever = LinkDef {
        name: "3".into(),
        points: vec![
            ("E".into(), Vec2::ZERO),
            ("B".into(), Vec2::new(lb, 0.0)),
            ("C".into(), polar(arm) * lc),
        ],
        mass_center: Vec2::ZERO,
    };
    let def = six_bar_def(
        ("O", "E"),
        b.o,
        [b.l1, b.l2],
        lever,
        ("C", "D", lcd),
        yg,
        omega,
        [("B", b.c_ext), ("C", c_ext), ("D", d_ext)],
        b.phi_ext + ASSEMBLY_OFFSET,
    );
    let check = check_cycle(
        &def,
        &Expect {
            k: Some(r.k),
            stroke: None,
        },
        "B, C and D near their extreme positions found by the construction",
    )?;
    check_limits(&r.limits, &check)?;
    check_extremes(&check, "B", [b1, b2])?;
    Ok(Synthesis {
        kind: Kind::SixBar,
        given: vec![
            ("k".into(), r.k),
            ("swing".into(), psi),
            ("arm_b".into(), lb),
            ("arm_c".into(), lc),
            ("arm_angle".into(), arm),
            ("guide".into(), yg),
            ("max_pressure".into(), p),
        ],
        lengths: vec![
            ("OA".into(), b.l1),
            ("AB".into(), b.l2),
            ("EB".into(), lb),
            ("EC".into(), lc),
            ("CD".into(), lcd),
            ("OE".into(), b.frame),
        ],
        frame: def.fixed.clone(),
        k: r.k,
        theta,
        stroke: check.stroke,
        free_parameter: Some(free(
            &choice,
            "the coupler CD is the shortest keeping the slider's pressure angle within the limit",
        )),
        construction: Construction {
            point: "B".into(),
            extremes: [b1, b2],
            locus: locus.circle(b.side),
            pivot: b.o,
            lines: vec![("guide".into(), Vec2::new(-lc, yg), d_ext)],
        },
        def,
        check,
        angles: vec![],
        coordinates: vec![],
        shown: vec![],
    })
}

/// The description of a six-bar: crank pivot and lever pivot, crank and
/// coupler, the lever, the slider's coupler (from, to, length), the guide's
/// height, ω1, assembly hints, assembly angle.
#[allow(clippy::too_many_arguments)]
fn six_bar_def(
    (crank_pivot, lever_pivot): (&str, &str),
    o: Vec2,
    [l1, l2]: [f64; 2],
    lever: LinkDef,
    (from, to, l4): (&str, &str, f64),
    yg: f64,
    omega: f64,
    hints: [(&str, Vec2); 3],
    assembly_angle: f64,
) -> MechanismDef {
    MechanismDef {
        slider_input: None,
        fixed: vec![(crank_pivot.into(), o), (lever_pivot.into(), Vec2::ZERO)],
        links: vec![
            LinkDef::bar("1", crank_pivot, "A", l1),
            LinkDef::bar("2", "A", "B", l2),
            lever,
            LinkDef::bar("4", from, to, l4),
            LinkDef::block("5", to),
        ],
        sliders: vec![SliderDef {
            slider: "5".into(),
            point: to.into(),
            guide_link: crate::model::FRAME.into(),
            through: Vec2::new(0.0, yg),
            angle: 0.0,
            angle_on_slider: 0.0,
        }],
        input: Some(InputDef {
            link: "1".into(),
            pivot: crank_pivot.into(),
            pin: "A".into(),
            omega,
            epsilon: 0.0,
        }),
        hints: hints
            .iter()
            .map(|&(p, q)| AssemblyHint {
                point: p.into(),
                kind: HintKind::Near(q),
            })
            .collect(),
        assembly_angle,
        output: Some("5".into()),
    }
}
