//! The unsteady single stroke (неустановившееся движение за один цикл;
//! the single-stroke mode of a press, Chernaya & Timofeev 2019, appendix
//! П4, p. 137–142): the machine starts at the beginning of its cycle at a
//! given crank speed and is driven through one cycle by an induction motor
//! ([`KlossMotor`]) through a reducer, against the loads of the kinetostatics
//! (a force by travel on one stroke, gravity). No steady cycle, no flywheel
//! design: the question is whether, how fast and how slowly the machine gets
//! through the one cycle.
//!
//! The equation of motion of the link of reduction (Артоболевский 1988; the
//! book's p. 139), integrated in time:
//!
//!   dφ/dt = ω, dω/dt = (u·M(ω) + M_c(φ) − ½·I′_II(φ)·ω²)/(I_I + I_II(φ)),
//!
//! with I_II, I′_II and M_c solved exactly at every stage from the linkage
//! ([`Reducer`]), M the motor's torque. With the optional dynamic
//! characteristic (динамическая характеристика двигателя) the torque lags
//! its static value by a time constant τ: τ·dM/dt + M = M_st(u·ω)
//! (a first-order lag; docs/dynamics.md), else M = M_st. The motor's work
//! at the crank, W = ∫u·M·ω dt, rides along as a fourth component for the
//! energy balance. Integrated by the adaptive Dormand–Prince 5(4) pair
//! ([`super::rk`]) from t = 0, φ = 0 until the event φ = 2π (the cycle time),
//! every output angle and every crossing of the motor's breakdown speed
//! located on the step's interpolant and taken by an exact step (Newton).
//! A crank that stops (ω reaches 0) before φ = 2π is a stall, reported with
//! the angle, the time and the output's travel where it stops.
//!
//! The second model, [`EnergyStroke`] (the book's variant 2), drives with a
//! constant moment and is solved by the energy equation
//! (single_stroke_energy.rs); the check [`by_angle`] integrates the first
//! model's energy equation in φ by a fixed-step RK4 (an independent second
//! integrator).

use std::f64::consts::PI;

use super::error::{DynamicsError, show};
use super::kloss::KlossMotor;
use super::reduced::Reducer;
use super::rk::{Adaptive, rk4};
use crate::forces::Loads;
use crate::forces::stroke::Working;
use crate::{Mechanism, Solution};

use super::single_stroke_energy::EnergyStroke;

/// Relative tolerance of the stroke's time integration.
pub const STROKE_RTOL: f64 = 1e-12;

/// The most output intervals over the cycle.
pub const MAX_STROKE_POINTS: usize = 36_000;

/// The largest time constant of the motor's dynamic characteristic, s.
pub const MAX_TIME_CONSTANT: f64 = 10.0;

/// The least nonzero one, s: a shorter lag changes nothing a course
/// project sees, and would make the explicit integration take a step per
/// fraction of it (stiff); 0 is the static characteristic.
pub const MIN_TIME_CONSTANT: f64 = 1e-3;

/// The most steps of the check by RK4 in the crank angle.
pub const MAX_CHECK_STEPS: usize = 200_000;

/// The most accepted steps of one stroke: a crank creeping towards a
/// standstill without reaching it is reported as a stall there.
pub const MAX_STROKE_STEPS: usize = 200_000;

/// What the single stroke is given.
#[derive(Debug, Clone, PartialEq)]
pub struct StrokeSpec {
    /// The motor and its reducer.
    pub motor: KlossMotor,
    /// Constant inertia on the crank shaft besides the crank itself (the
    /// flywheel, the gear, the clutch reduced to the crank: the book's
    /// I_I^пр), kg·m².
    pub inertia_constant: f64,
    /// The crank speed at the start, rad/s (> 0; the book: the motor's
    /// synchronous speed seen at the crank, ω₀/u).
    pub start_speed: f64,
    /// The motor shaft's constant torque of the second model, N·m (the
    /// book: the breakdown torque M_K).
    pub constant_torque: f64,
    /// Time constant τ of the motor's dynamic characteristic, s (0: the
    /// static characteristic).
    pub time_constant: f64,
    /// Intervals of the output tables over the cycle.
    pub points: usize,
    /// The design position (расчётное положение), cycle angle, rad, if any.
    pub design_angle: Option<f64>,
    /// The working stroke of the output (where the cycle starts).
    pub working: Working,
}

impl StrokeSpec {
    /// The book's defaults for a motor: start at the synchronous speed,
    /// the constant torque of the second model the breakdown torque, the
    /// static characteristic, 360 intervals, no design position, the cycle
    /// from the start of the slower stroke.
    ///
    /// ```
    /// use tmm_linkage::dynamics::{KlossMotor, StrokeSpec};
    /// let m = KlossMotor { synchronous_speed: 104.9, breakdown_speed: 77.3, breakdown_torque: 5240.0, ratio: 18.6 };
    /// let s = StrokeSpec::new(m, 1.4e5);
    /// assert!((s.start_speed - 104.9 / 18.6).abs() < 1e-12);
    /// assert_eq!(s.constant_torque, 5240.0);
    /// assert!(s.check().is_ok());
    /// ```
    pub fn new(motor: KlossMotor, inertia_constant: f64) -> Self {
        StrokeSpec {
            motor,
            inertia_constant,
            start_speed: motor.crank_synchronous_speed(),
            constant_torque: motor.breakdown_torque,
            time_constant: 0.0,
            points: 360,
            design_angle: None,
            working: Working::Slower,
        }
    }

    /// Check every field on its own; the field names are those of the task
    /// file (`dynamics.motor.breakdown_speed`).
    pub fn check(&self) -> Result<(), DynamicsError> {
        let e = |f: &str, m: String| Err(DynamicsError::spec(f, m));
        let m = &self.motor;
        if !(m.synchronous_speed.is_finite() && m.synchronous_speed > 0.0 && m.synchronous_speed <= super::spec::MAX_MOTOR_SPEED) {
            return e(
                "dynamics.motor.synchronous_speed",
                format!(
                    "must be > 0 and at most {:e} rad/s, not {} rad/s",
                    super::spec::MAX_MOTOR_SPEED,
                    show(m.synchronous_speed)
                ),
            );
        }
        if !(m.breakdown_speed.is_finite() && m.breakdown_speed > 0.0 && m.breakdown_speed < m.synchronous_speed) {
            return e(
                "dynamics.motor.breakdown_speed",
                format!(
                    "the breakdown (critical) speed must be > 0 and below the synchronous speed {} rad/s, not {} rad/s",
                    show(m.synchronous_speed),
                    show(m.breakdown_speed)
                ),
            );
        }
        if !(m.breakdown_torque.is_finite() && m.breakdown_torque > 0.0 && m.breakdown_torque <= super::spec::MAX_TORQUE) {
            return e(
                "dynamics.motor.breakdown_torque",
                format!(
                    "must be > 0 and at most {:e} N·m, not {}",
                    super::spec::MAX_TORQUE,
                    show(m.breakdown_torque)
                ),
            );
        }
        if !(m.ratio.is_finite() && (1.0 / super::spec::MAX_RATIO..=super::spec::MAX_RATIO).contains(&m.ratio)) {
            return e(
                "dynamics.motor.ratio",
                format!(
                    "the reducer ratio ω_motor/ω_crank must be from {:e} to {:e}, not {}",
                    1.0 / super::spec::MAX_RATIO,
                    super::spec::MAX_RATIO,
                    show(m.ratio)
                ),
            );
        }
        if !(self.inertia_constant.is_finite() && (0.0..=super::spec::MAX_INERTIA).contains(&self.inertia_constant)) {
            return e(
                "dynamics.inertia.crank_shaft",
                format!(
                    "a moment of inertia must be ≥ 0 and at most {:e} kg·m², not {}",
                    super::spec::MAX_INERTIA,
                    show(self.inertia_constant)
                ),
            );
        }
        let top = 2.0 * m.crank_synchronous_speed();
        if !(self.start_speed.is_finite() && self.start_speed > 0.0 && self.start_speed <= top) {
            return e(
                "dynamics.stroke.start_speed",
                format!(
                    "the crank's speed at the start must be > 0 and at most twice the motor's synchronous speed seen at the crank ({} rad/s), not {} rad/s",
                    show(top),
                    show(self.start_speed)
                ),
            );
        }
        if !(self.constant_torque.is_finite() && self.constant_torque > 0.0 && self.constant_torque <= super::spec::MAX_TORQUE) {
            return e(
                "dynamics.stroke.constant_torque",
                format!(
                    "the second model's constant motor torque must be > 0 and at most {:e} N·m, not {}",
                    super::spec::MAX_TORQUE,
                    show(self.constant_torque)
                ),
            );
        }
        let tau = self.time_constant;
        if !(tau.is_finite() && (tau == 0.0 || (MIN_TIME_CONSTANT..=MAX_TIME_CONSTANT).contains(&tau))) {
            return e(
                "dynamics.stroke.time_constant",
                format!(
                    "the motor's time constant τ must be 0 (the static characteristic) or from {MIN_TIME_CONSTANT} to {MAX_TIME_CONSTANT} s (induction motors have some 0.01…0.1 s), not {} s",
                    show(tau)
                ),
            );
        }
        if !(12..=MAX_STROKE_POINTS).contains(&self.points) {
            return e(
                "dynamics.points",
                format!(
                    "the stroke's tables need 12 to {MAX_STROKE_POINTS} intervals over the cycle, not {}",
                    self.points
                ),
            );
        }
        if let Some(f) = self.design_angle
            && !(f.is_finite() && (0.0..=2.0 * PI).contains(&f))
        {
            return e(
                "dynamics.stroke.design_angle",
                format!(
                    "the design position must be a cycle angle from 0° to 360°, not {}°",
                    show(f.to_degrees())
                ),
            );
        }
        Ok(())
    }
}

/// One row of the motor-driven stroke, at one cycle angle.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct StrokeRow {
    /// Cycle angle φ from the start, rad.
    pub phi: f64,
    /// Absolute crank angle, rad.
    pub crank_angle: f64,
    /// The output's travel from the start of its working stroke, m or rad.
    pub travel: f64,
    /// I_II, kg·m².
    pub inertia_variable: f64,
    /// dI_II/dφ, kg·m²/rad.
    pub inertia_derivative: f64,
    /// I_Σ = I_I + I_II, kg·m².
    pub inertia_total: f64,
    /// M_c, the loads' reduced moment, N·m.
    pub moment_loads: f64,
    /// u·M, the motor's moment reduced to the crank, N·m.
    pub moment_motor: f64,
    /// ω, rad/s.
    pub omega: f64,
    /// ε, rad/s².
    pub epsilon: f64,
    /// t, s.
    pub time: f64,
    /// The motor's speed, rad/s (u·ω).
    pub motor_speed: f64,
    /// The motor's work at the crank since the start, J.
    pub motor_work: f64,
}

/// Where the crank's speed crosses the motor's breakdown speed ω_K/u.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BreakdownCrossing {
    /// Time, s.
    pub time: f64,
    /// Cycle angle, rad.
    pub phi: f64,
    /// The output's travel there, m or rad.
    pub travel: f64,
    /// `true` when the speed falls below it (the motor passes onto the
    /// unstable branch of its characteristic), `false` when it rises back.
    pub falling: bool,
}

/// The energy balance of the stroke: W_motor + A_c = T(end) − T(0).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EnergyBalance {
    /// The motor's work at the crank, ∫u·M·ω dt along the integration, J.
    pub motor_work: f64,
    /// The loads' work ∫M_c dφ over the cycle, by [`work`] on every
    /// interval of the output angles (independent of the time
    /// integration), J.
    pub loads_work: f64,
    /// Kinetic energy at the start, ½·I_Σ(0)·ω(0)², J.
    pub kinetic_start: f64,
    /// At the end, J.
    pub kinetic_end: f64,
    /// (W + A_c − ΔT) relative to the largest of |W|, |A_c|, |ΔT|.
    pub residual: f64,
}

/// The motor-driven stroke (the book's variant 1).
#[derive(Debug, Clone, PartialEq)]
pub struct MotorStroke {
    /// The rows at the output angles (`points` + 1 uniform angles and the
    /// design position, increasing).
    pub rows: Vec<StrokeRow>,
    /// The row of the design position, if one is given.
    pub design: Option<StrokeRow>,
    /// The cycle time t_ц: when φ reaches 2π, s.
    pub cycle_time: f64,
    /// ω at the end, rad/s.
    pub omega_end: f64,
    /// The smallest speed over the stroke, rad/s.
    pub omega_min: f64,
    /// Its cycle angle, rad.
    pub phi_omega_min: f64,
    /// Its time, s.
    pub time_omega_min: f64,
    /// The largest motor torque reached (on the motor shaft), N·m.
    pub torque_max: f64,
    /// The crossings of the breakdown speed.
    pub crossings: Vec<BreakdownCrossing>,
    /// Time spent below the breakdown speed, s.
    pub time_below_breakdown: f64,
    /// The energy balance.
    pub balance: EnergyBalance,
    /// Steps accepted and rejected.
    pub steps: (usize, usize),
}

/// The check of the motor-driven stroke by a second integrator.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AngleCheck {
    /// RK4 steps in the angle.
    pub steps: usize,
    /// The cycle time, s.
    pub cycle_time: f64,
    /// ω at the end, rad/s.
    pub omega_end: f64,
    /// The motor's work, J.
    pub motor_work: f64,
}

/// The whole single stroke: both models.
#[derive(Debug, Clone)]
pub struct SingleStroke {
    /// What it was computed for.
    pub spec: StrokeSpec,
    /// The reduced model.
    pub reducer: Reducer,
    /// The constant inertia on the crank shaft, the crank's own included, kg·m².
    pub inertia_constant: f64,
    /// The motor-driven stroke.
    pub motor: MotorStroke,
    /// The constant-moment stroke by the energy equation.
    pub energy: EnergyStroke,
    /// The motor-driven stroke again by RK4 in the angle (`None` when the
    /// motor's lag is so short against the slowest crank travel that the
    /// fixed steps would be more than [`MAX_CHECK_STEPS`], or when the crank
    /// comes so near a standstill that they fail).
    pub check: Option<AngleCheck>,
}

impl SingleStroke {
    /// Both models and the check, for mechanism `m` under `loads`.
    pub fn compute(m: &Mechanism, loads: &Loads, spec: &StrokeSpec) -> Result<Self, DynamicsError> {
        spec.check()?;
        let red = Reducer::new(m, loads, spec.working)?;
        let mut sol = red.solution();
        let motor = integrate(&red, spec, &mut sol)?;
        let energy = EnergyStroke::compute(&red, spec, &mut sol)?;
        // with the lag, RK4 in φ is stable for steps below some τ·ω
        let n = if spec.time_constant > 0.0 {
            (red.period / (spec.time_constant * motor.omega_min)).ceil().max(20_000.0)
        } else {
            20_000.0
        };
        // near a standstill 1/ω is too steep for fixed steps: the check is
        // then left out rather than the stroke refused
        let check = if n <= MAX_CHECK_STEPS as f64 {
            by_angle(&red, spec, n as usize, &mut sol).ok()
        } else {
            None
        };
        Ok(SingleStroke {
            spec: spec.clone(),
            inertia_constant: red.inertia_crank + spec.inertia_constant,
            reducer: red,
            motor,
            energy,
            check,
        })
    }
}

/// The output angles: `points` + 1 uniform angles over the cycle and the
/// design position, increasing; and the design position's index.
pub(crate) fn angles(spec: &StrokeSpec, period: f64) -> (Vec<f64>, Option<usize>) {
    let n = spec.points;
    let mut a: Vec<f64> = (0..=n).map(|k| period * k as f64 / n as f64).collect();
    let mut at = None;
    if let Some(f) = spec.design_angle {
        let f = f.min(period);
        let k = a.partition_point(|&x| x < f - 1e-12);
        if k < a.len() && (a[k] - f).abs() <= 1e-12 {
            at = Some(k);
        } else {
            a.insert(k, f);
            at = Some(k);
        }
    }
    (a, at)
}

/// The output's travel at the solved position `sol`, m or rad (0 without
/// a stroke).
#[inline]
pub(crate) fn travel(red: &Reducer, sol: &Solution) -> f64 {
    red.stroke.as_ref().map_or(0.0, |s| s.phase(sol).travel)
}

/// The stall at cycle angle `phi`, time `time` (when the model has one).
pub(crate) fn stall(red: &Reducer, model: &str, phi: f64, time: Option<f64>, motor: f64, sol: &mut Solution) -> DynamicsError {
    let (mc, h) = match red.eval(phi, sol) {
        Ok(r) => (r.moment, travel(red, sol)),
        Err(e) => return e,
    };
    let out = red.stroke.as_ref().map(|s| {
        let name = red.unit.link_names.get(s.output).cloned().unwrap_or_default();
        let unit = if s.angular { "rad" } else { "m" };
        (name, s.travel, unit, s.phase(sol).working)
    });
    let place = match out {
        Some((name, stroke, unit, working)) => format!(
            ", the output link `{name}` {} {unit} ({:.1} % of its stroke {} {unit}) from the start of its working stroke, on its {} stroke",
            show_short(h),
            100.0 * h / stroke.max(f64::MIN_POSITIVE),
            show_short(stroke),
            if working { "working" } else { "return" }
        ),
        None => String::new(),
    };
    DynamicsError::spec(
        "dynamics",
        format!(
            "the machine stalls in the {model}: the crank stops at φ = {:.3}° of the cycle{}{place}; there the loads' reduced moment is {} N·m against the drive's {} N·m and the kinetic energy is spent, so the cycle never reaches φ = 360°",
            phi.to_degrees(),
            time.map_or(String::new(), |t| format!(" (t = {t:.4} s)")),
            show_short(mc),
            show_short(motor)
        ),
    )
}

fn show_short(x: f64) -> String {
    if x == 0.0 || (1e-3..1e7).contains(&x.abs()) {
        format!("{:.4}", x)
    } else {
        format!("{x:.4e}")
    }
}

/// ∫ M_c dφ from `a` to `b` (a short interval, a ≤ b): 3-point
/// Gauss–Legendre ([`Reducer::work`], cut at the output's dead positions),
/// the interval halved until the whole and its halves agree to 1e-10 — a
/// load table's knots (where M_c kinks inside an interval) are so resolved
/// without knowing where they are (at most 24 halvings).
pub fn work(red: &Reducer, a: f64, b: f64, sol: &mut Solution) -> Result<f64, DynamicsError> {
    fn go(red: &Reducer, a: f64, b: f64, whole: f64, depth: u32, sol: &mut Solution) -> Result<f64, DynamicsError> {
        let m = 0.5 * (a + b);
        let (l, r) = (red.work(a, m, sol)?, red.work(m, b, sol)?);
        let halves = l + r;
        if depth == 0 || (halves - whole).abs() <= 1e-10 * halves.abs().max(whole.abs()) {
            return Ok(halves);
        }
        Ok(go(red, a, m, l, depth - 1, sol)? + go(red, m, b, r, depth - 1, sol)?)
    }
    let whole = red.work(a, b, sol)?;
    go(red, a, b, whole, 24, sol)
}

/// The motor-driven stroke, integrated in time.
pub fn integrate(red: &Reducer, spec: &StrokeSpec, sol: &mut Solution) -> Result<MotorStroke, DynamicsError> {
    let mo = spec.motor;
    let u = mo.ratio;
    let tau = spec.time_constant;
    let i_const = red.inertia_crank + spec.inertia_constant;
    let period = red.period;
    let sol_cell = std::cell::RefCell::new(sol);
    let rhs = |_t: f64, y: &[f64; 4]| -> Result<[f64; 4], DynamicsError> {
        let r = red.eval(y[0], &mut sol_cell.borrow_mut())?;
        let w = y[1];
        let mst = mo.torque(u * w);
        let (m, dm) = if tau > 0.0 { (y[2], (mst - y[2]) / tau) } else { (mst, 0.0) };
        let md = u * m;
        let i = i_const + r.inertia;
        Ok([w, (md + r.moment - 0.5 * r.inertia_derivative * w * w) / i, dm, md * w])
    };
    let w0 = spec.start_speed;
    let y0 = [0.0, w0, if tau > 0.0 { mo.torque(u * w0) } else { 0.0 }, 0.0];
    let f0 = rhs(0.0, &y0)?;
    let t_est = period / w0;
    let h_max = if tau > 0.0 { (t_est / 200.0).min(tau) } else { t_est / 200.0 };
    let w_scale = w0.max(mo.crank_synchronous_speed());
    let atol = [
        STROKE_RTOL * period,
        STROKE_RTOL * w_scale,
        STROKE_RTOL * mo.breakdown_torque,
        STROKE_RTOL * mo.breakdown_torque * u * period,
    ];
    let mut d = Adaptive::new(0.0, y0, f0, t_est / 2000.0, h_max, STROKE_RTOL, atol);
    let (targets, design_at) = angles(spec, period);
    let wk = mo.crank_breakdown_speed();
    let torque = |y: &[f64; 4]| if tau > 0.0 { y[2] } else { mo.torque(u * y[1]) };
    let mut rows = Vec::with_capacity(targets.len());
    let row = |t: f64, y: &[f64; 4], f: &[f64; 4]| -> Result<StrokeRow, DynamicsError> {
        let mut s = sol_cell.borrow_mut();
        let r = red.eval(y[0], &mut s)?;
        Ok(StrokeRow {
            phi: y[0],
            crank_angle: red.crank_angle(y[0]),
            travel: travel(red, &s),
            inertia_variable: r.inertia,
            inertia_derivative: r.inertia_derivative,
            inertia_total: i_const + r.inertia,
            moment_loads: r.moment,
            moment_motor: u * torque(y),
            omega: y[1],
            epsilon: f[1],
            time: t,
            motor_speed: u * y[1],
            motor_work: y[3],
        })
    };
    rows.push(row(0.0, &y0, &f0)?);
    let mut next = 1;
    let mut crossings = Vec::new();
    let (mut w_min, mut phi_min, mut t_min) = (w0, 0.0, 0.0);
    let mut torque_max = torque(&y0);
    let mut below_since = if w0 < wk { Some(0.0) } else { None };
    let mut below = 0.0;
    let end = loop {
        d.step(rhs)?;
        // the cycle's end and every output angle passed in this step
        while next < targets.len() && d.y[0] >= targets[next] && d.y[1] > 0.0 {
            let (t, y, f) = d.locate(0, targets[next], rhs)?;
            let mut y = y;
            y[0] = targets[next];
            rows.push(row(t, &y, &f)?);
            next += 1;
        }
        // breakdown speed crossed
        let (a, b) = (d.y_prev[1] - wk, d.y[1] - wk);
        if a * b < 0.0 || (a != 0.0 && b == 0.0) {
            let (t, y, _) = d.locate(1, wk, rhs)?;
            let mut s = sol_cell.borrow_mut();
            red.unit.solve(red.crank_angle(y[0]), &mut s)?;
            crossings.push(BreakdownCrossing {
                time: t,
                phi: y[0],
                travel: travel(red, &s),
                falling: a > 0.0,
            });
            if a > 0.0 {
                below_since = Some(t);
            } else if let Some(t0) = below_since.take() {
                below += t - t0;
            }
        }
        // the least speed: where ε changes sign from − to + in the step
        if d.f_prev[1] < 0.0 && d.f[1] >= 0.0 && d.y[1] > 0.0 {
            let (mut lo, mut hi) = (d.t_prev, d.t);
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                let (_, f) = d.state_at(mid, rhs)?;
                if f[1] < 0.0 {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            let (y, _) = d.state_at(0.5 * (lo + hi), rhs)?;
            if y[1] < w_min {
                (w_min, phi_min, t_min) = (y[1], y[0], 0.5 * (lo + hi));
            }
        }
        if d.y[1] < w_min && d.y[1] > 0.0 {
            (w_min, phi_min, t_min) = (d.y[1], d.y[0], d.t);
        }
        torque_max = torque_max.max(torque(&d.y));
        if next >= targets.len() {
            break rows.last().copied().unwrap_or_default();
        }
        if d.y[1] <= 0.0 {
            let (t, y, _) = d.locate(1, 0.0, rhs)?;
            let mut s = sol_cell.borrow_mut();
            return Err(stall(red, "motor-driven stroke", y[0], Some(t), u * torque(&y), &mut s));
        }
        if d.accepted > MAX_STROKE_STEPS {
            let y = d.y;
            let mut s = sol_cell.borrow_mut();
            return Err(stall(red, "motor-driven stroke", y[0], Some(d.t), u * torque(&y), &mut s));
        }
    };
    if let Some(t0) = below_since {
        below += end.time - t0;
    }
    let design = design_at.map(|k| rows[k]);
    let mut s = sol_cell.borrow_mut();
    // ∫M_c dφ piecewise over the output angles (Gauss–Legendre on each)
    let mut loads_work = 0.0;
    for w in targets.windows(2) {
        loads_work += work(red, w[0], w[1], &mut s)?;
    }
    let kinetic_start = 0.5 * rows[0].inertia_total * w0 * w0;
    let kinetic_end = 0.5 * end.inertia_total * end.omega * end.omega;
    let de = kinetic_end - kinetic_start;
    let scale = end.motor_work.abs().max(loads_work.abs()).max(de.abs()).max(f64::MIN_POSITIVE);
    Ok(MotorStroke {
        design,
        cycle_time: end.time,
        omega_end: end.omega,
        omega_min: w_min,
        phi_omega_min: phi_min,
        time_omega_min: t_min,
        torque_max,
        crossings,
        time_below_breakdown: below,
        balance: EnergyBalance {
            motor_work: end.motor_work,
            loads_work,
            kinetic_start,
            kinetic_end,
            residual: (end.motor_work + loads_work - de) / scale,
        },
        steps: (d.accepted, d.rejected),
        rows,
    })
}

/// The motor-driven stroke by a second, independent integrator: its energy
/// equation integrated in the crank angle by the classical RK4 with `n`
/// equal steps (derived in docs/dynamics.md): with the kinetic energy
/// T = ½·I_Σ·ω² as the state, dT/dφ = u·M + M_c, dt/dφ = 1/ω,
/// dM/dφ = (M_st − M)/(τ·ω), dW/dφ = u·M, ω = √(2T/I_Σ(φ)). Needs ω > 0
/// throughout (a stall is reported where T reaches 0).
pub fn by_angle(red: &Reducer, spec: &StrokeSpec, n: usize, sol: &mut Solution) -> Result<AngleCheck, DynamicsError> {
    let mo = spec.motor;
    let u = mo.ratio;
    let tau = spec.time_constant;
    let i_const = red.inertia_crank + spec.inertia_constant;
    let sol_cell = std::cell::RefCell::new(sol);
    let rhs = |phi: f64, y: &[f64; 4]| -> Result<[f64; 4], DynamicsError> {
        let r = red.eval(phi, &mut sol_cell.borrow_mut())?;
        let i = i_const + r.inertia;
        if y[0].is_nan() || y[0] <= 0.0 {
            return Err(DynamicsError::NonFinite {
                what: format!("the crank speed at φ = {:.3}° (the machine stops)", phi.to_degrees()),
            });
        }
        let w = (2.0 * y[0] / i).sqrt();
        let mst = mo.torque(u * w);
        let (m, dm) = if tau > 0.0 { (y[2], (mst - y[2]) / (tau * w)) } else { (mst, 0.0) };
        Ok([u * m + r.moment, 1.0 / w, dm, u * m])
    };
    let w0 = spec.start_speed;
    let i0 = i_const + red.eval(0.0, &mut sol_cell.borrow_mut())?.inertia;
    let y0 = [0.5 * i0 * w0 * w0, 0.0, if tau > 0.0 { mo.torque(u * w0) } else { 0.0 }, 0.0];
    let y = rk4(0.0, y0, red.period, n, rhs)?;
    let i1 = i_const + red.eval(red.period, &mut sol_cell.borrow_mut())?.inertia;
    Ok(AngleCheck {
        steps: n,
        cycle_time: y[1],
        omega_end: (2.0 * y[0].max(0.0) / i1).sqrt(),
        motor_work: y[3],
    })
}
