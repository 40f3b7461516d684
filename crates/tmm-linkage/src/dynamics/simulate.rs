//! The motion by time integration of the equation of motion of the link of
//! reduction (уравнение движения в дифференциальной форме,
//! Артоболевский 1988, the equation of motion of the machine):
//!
//! dφ/dt = ω, dω/dt = (M_d(ω) + M_c(φ) − ½·I′(φ)·ω²)/(I_I + I_II(φ)),
//!
//! with I_II, I′ and M_c solved exactly at every stage from the linkage and
//! M_d constant or the motor's characteristic. Integrated by the adaptive
//! Dormand–Prince 5(4) pair ([`super::ode`]), cycle by cycle: each cycle's
//! extreme speeds are where the step's cubic interpolant of ω is stationary,
//! the speed there taken by an exact Dormand–Prince step from the step's
//! start; the cycle's end is located the same way (Newton on φ(t) = 2π).
//!
//! Two uses: the steady cycle re-integrated from the exact start (an
//! independent check of the flywheel: δ and ω_m must come back), and, with
//! a motor, the run-up from rest (разбег) to the steady cycle. With a
//! constant driving moment there is no run-up: the work over each cycle is
//! zero whatever the speed, so the machine neither gains nor loses speed on
//! average (the steady cycle is neutral, every T₀ is one).

use super::error::DynamicsError;
use super::ode::{Dopri, State};
use super::reduced::Reducer;
use super::spec::DrivingMoment;
use crate::Solution;

/// The speed at the start of a cycle counts as settled within this fraction
/// of its steady value (the run-up time).
pub const SETTLE: f64 = 0.01;

/// Relative tolerance of the steady cycle's integration.
pub const STEADY_RTOL: f64 = 1e-12;

/// Relative tolerance of the run-up's integration.
pub const RUNUP_RTOL: f64 = 1e-9;

/// The least crank travel over the time constant of the motor-driven run-up,
/// τ·ω_m, rad: below it the equation of motion is too stiff for the explicit
/// integration and the crank turns at the motor's speed anyway.
pub const MIN_SETTLE_ANGLE: f64 = 1e-4;

/// The most cycles the run-up from rest is integrated over (about 50 µs of
/// computing each, so a second at most): a machine that needs more — a huge
/// inertia against a stiff motor characteristic — is refused beforehand by
/// its time constant (see [`Simulator::runup`]) or when it reaches this.
pub const MAX_RUNUP_CYCLES: usize = 20_000;

/// One simulated cycle.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SimulatedCycle {
    /// Time at its start, s.
    pub start: f64,
    /// Its duration, s.
    pub period: f64,
    /// Speed at its start, rad/s.
    pub omega_start: f64,
    /// Speed at its end, rad/s.
    pub omega_end: f64,
    /// Largest speed, rad/s.
    pub omega_max: f64,
    /// Smallest speed, rad/s.
    pub omega_min: f64,
    /// (ω_max + ω_min)/2, rad/s.
    pub omega_mean: f64,
    /// (ω_max − ω_min)/ω_mean.
    pub delta: f64,
}

/// The run-up from rest.
#[derive(Debug, Clone, PartialEq)]
pub struct Runup {
    /// Time until the speed at the start of a cycle is within [`SETTLE`] of
    /// its steady value, s.
    pub time: f64,
    /// Cycles simulated from rest until the cycle repeated itself to 1e-7
    /// (the steady cycle is then found by shooting).
    pub cycles: usize,
    /// The last (steady) cycle.
    pub steady: SimulatedCycle,
    /// ω(t): times of the accepted steps, s.
    pub trace_time: Vec<f64>,
    /// ω(t): speeds there, rad/s.
    pub trace_omega: Vec<f64>,
}

/// The time integrator of one machine.
pub struct Simulator<'a> {
    red: &'a Reducer,
    sol: &'a mut Solution,
    inertia: f64,
    driving: DrivingMoment,
    md: f64,
    omega_ref: f64,
}

impl<'a> Simulator<'a> {
    /// A machine of constant inertia `inertia` on the crank shaft, driven by
    /// `driving` (with `md` the constant moment), nominal speed `omega_ref`.
    pub fn new(red: &'a Reducer, sol: &'a mut Solution, inertia: f64, driving: DrivingMoment, md: f64, omega_ref: f64) -> Self {
        Simulator {
            red,
            sol,
            inertia,
            driving,
            md,
            omega_ref,
        }
    }

    /// Integrate from cycle angle 0 at speed `omega0` (0: from rest) to
    /// relative tolerance `rtol` until `stop` says so after a completed cycle
    /// (at most `max_cycles`), recording ω(t) at every accepted step when
    /// `trace` is given. Returns the last cycle.
    pub fn run(
        &mut self,
        omega0: f64,
        rtol: f64,
        max_cycles: usize,
        mut stop: impl FnMut(&SimulatedCycle) -> bool,
        mut trace: Option<(&mut Vec<f64>, &mut Vec<f64>)>,
    ) -> Result<SimulatedCycle, DynamicsError> {
        let (red, inertia, driving, md) = (self.red, self.inertia, self.driving, self.md);
        let sol = &mut *self.sol;
        let mut rhs = |_t: f64, y: &State| -> Result<State, DynamicsError> {
            let r = red.eval(y[0].rem_euclid(red.period), sol)?;
            let w = y[1];
            let d = match driving {
                DrivingMoment::Constant | DrivingMoment::Engine => md,
                DrivingMoment::Motor(m) => m.crank_moment(w),
            };
            let i = inertia + r.inertia;
            Ok([w, (d + r.moment - 0.5 * r.inertia_derivative * w * w) / i])
        };
        let y0 = [0.0, omega0];
        let f0 = rhs(0.0, &y0)?;
        let period = self.red.period / self.omega_ref;
        let h0 = if omega0 > 0.0 { period / 200.0 } else { period * 1e-3 };
        let mut d = Dopri::new(0.0, y0, f0, h0, period / 16.0, rtol, [rtol, rtol * self.omega_ref]);
        if omega0 <= 0.0 && f0[1] <= 0.0 {
            return Err(DynamicsError::Stall { time: 0.0, phi_deg: 0.0 });
        }
        let mut cyc = SimulatedCycle {
            omega_start: omega0,
            omega_max: omega0,
            omega_min: omega0,
            ..Default::default()
        };
        let mut k = 0usize;
        // extremes found in a step after the cycle's end, for the next cycle
        let mut next_ext = (f64::NEG_INFINITY, f64::INFINITY);
        if let Some((t, w)) = trace.as_mut() {
            t.push(0.0);
            w.push(omega0);
        }
        while k < max_cycles {
            d.step(&mut rhs)?;
            // a crank creeping towards a standstill never ends its cycle: a
            // cycle taking a hundred thousand steps more than usual is a stall
            if d.y[1] <= 0.0 || d.accepted > 100_000 + 5_000 * (k + 1) {
                return Err(DynamicsError::Stall {
                    time: d.t,
                    phi_deg: d.y[0].rem_euclid(self.red.period).to_degrees(),
                });
            }
            if let Some((t, w)) = trace.as_mut() {
                t.push(d.t);
                w.push(d.y[1]);
            }
            let end = self.red.period * (k + 1) as f64;
            // the cycle's end: the interpolant's estimate, then Newton steps
            // on exact Dormand–Prince steps from the step's start
            let mut tc = f64::INFINITY;
            let mut wc = 0.0;
            if d.y[0] >= end {
                tc = d.crossing(0, end);
                for _ in 0..3 {
                    let (y, _) = d.state_at(tc, &mut rhs)?;
                    tc -= (y[0] - end) / y[1];
                    wc = y[1];
                }
            }
            // speed extremes inside the step: where the interpolant's slope
            // vanishes, the speed there by an exact step
            for ts in d.stationary(1) {
                if ts.is_finite() {
                    let (y, _) = d.state_at(ts, &mut rhs)?;
                    if ts <= tc {
                        cyc.omega_max = cyc.omega_max.max(y[1]);
                        cyc.omega_min = cyc.omega_min.min(y[1]);
                    } else {
                        next_ext = (next_ext.0.max(y[1]), next_ext.1.min(y[1]));
                    }
                }
            }
            if tc.is_finite() {
                cyc.omega_max = cyc.omega_max.max(wc);
                cyc.omega_min = cyc.omega_min.min(wc);
                cyc.omega_end = wc;
                cyc.period = tc - cyc.start;
                cyc.omega_mean = 0.5 * (cyc.omega_max + cyc.omega_min);
                cyc.delta = (cyc.omega_max - cyc.omega_min) / cyc.omega_mean;
                k += 1;
                if stop(&cyc) {
                    return Ok(cyc);
                }
                // the next cycle: from the crossing, with the rest of this step
                cyc = SimulatedCycle {
                    start: tc,
                    omega_start: wc,
                    omega_max: wc.max(next_ext.0).max(d.y[1]),
                    omega_min: wc.min(next_ext.1).min(d.y[1]),
                    ..Default::default()
                };
            } else {
                cyc.omega_max = cyc.omega_max.max(d.y[1]);
                cyc.omega_min = cyc.omega_min.min(d.y[1]);
            }
            next_ext = (f64::NEG_INFINITY, f64::INFINITY);
        }
        Err(DynamicsError::NoConvergence {
            what: format!("the run-up to the steady cycle (no steady cycle after {max_cycles} cycles)"),
        })
    }

    /// One steady cycle from cycle angle 0 at speed `omega0`, integrated to
    /// the tolerance [`STEADY_RTOL`].
    pub fn cycle(&mut self, omega0: f64) -> Result<SimulatedCycle, DynamicsError> {
        self.run(omega0, STEADY_RTOL, 1, |_| true, None)
    }

    /// The periodic cycle near the start speed `omega0`: the fixed point of
    /// the one-cycle map ω(0) ↦ ω(2π) by the secant method (shooting).
    pub fn periodic(&mut self, omega0: f64) -> Result<SimulatedCycle, DynamicsError> {
        let mut x0 = omega0;
        let mut c0 = self.cycle(x0)?;
        let mut r0 = c0.omega_end - x0;
        let mut x1 = c0.omega_end;
        for _ in 0..30 {
            let c1 = self.cycle(x1)?;
            let r1 = c1.omega_end - x1;
            if r1.abs() <= 1e-11 * x1 {
                return Ok(c1);
            }
            let x2 = if r1 != r0 { x1 - r1 * (x1 - x0) / (r1 - r0) } else { c1.omega_end };
            (x0, r0, c0) = (x1, r1, c1);
            x1 = if x2 > 0.0 && x2.is_finite() { x2 } else { c0.omega_end };
        }
        Err(DynamicsError::NoConvergence {
            what: format!("the periodic steady cycle (last start speed {x1:.9} rad/s)"),
        })
    }

    /// The run-up from rest to the steady cycle: integrated from rest until
    /// the speed at the start of a cycle changes by less than 1e-7 from one
    /// cycle to the next, then the periodic cycle by shooting; the run-up
    /// time is when the speed at the start of a cycle first comes within
    /// [`SETTLE`] of the periodic one.
    ///
    /// Refused before integrating when the run-up would take more than
    /// `max_cycles` cycles by the linearised estimate (derived here): near
    /// the steady speed the motor's moment reduced to the crank falls with
    /// slope k = u²·M_n/(ω_s − ω_n), so the speed settles as e^(−t/τ) with
    /// τ = I/k, I ≥ the constant inertia; reaching 1e-7 takes ln(1e7)·τ,
    /// that is ln(1e7)·τ·ω_m/(2π) cycles.
    pub fn runup(&mut self, max_cycles: usize) -> Result<Runup, DynamicsError> {
        let (driving, inertia) = (self.driving, self.inertia);
        let too_long = move |cycles: Option<f64>| {
            let DrivingMoment::Motor(m) = driving else {
                return DynamicsError::NoConvergence {
                    what: format!("the run-up to the steady cycle (no steady cycle after {max_cycles} cycles)"),
                };
            };
            let k = m.ratio * m.ratio * m.nominal_torque / (m.synchronous_speed - m.nominal_speed);
            let tau = inertia / k;
            DynamicsError::spec(
                "dynamics.inertia",
                format!(
                    "the run-up from rest {}: the inertia at the crank {:.6e} kg·m² against the motor's slope k = u²·M_n/(ω_s − ω_n) = {:.6e} N·m·s gives a time constant τ = I/k = {:.4e} s; reduce the inertia on the shafts or choose a motor with a larger nominal torque",
                    cycles.map_or_else(
                        || format!("does not settle within the {max_cycles} cycles of the crank simulated at most"),
                        |c| format!(
                            "would take about {} cycles of the crank, more than the {max_cycles} simulated at most",
                            super::error::show(c.round())
                        )
                    ),
                    inertia,
                    k,
                    tau
                ),
            )
        };
        if let DrivingMoment::Motor(m) = self.driving {
            let k = m.ratio * m.ratio * m.nominal_torque / (m.synchronous_speed - m.nominal_speed);
            let cycles = 1e7f64.ln() * (self.inertia / k) * self.omega_ref / self.red.period;
            if cycles.is_finite() && cycles > max_cycles as f64 {
                return Err(too_long(Some(cycles)));
            }
            // the other extreme: a characteristic so steep that the speed
            // settles within MIN_SETTLE_ANGLE of crank travel (τ·ω_m) makes
            // the equation stiff for the explicit integration
            let settle = self.inertia / k * self.omega_ref;
            if !(settle.is_finite() && settle >= MIN_SETTLE_ANGLE) {
                return Err(DynamicsError::spec(
                    "dynamics.motor.nominal_torque",
                    format!(
                        "the motor's characteristic is so steep (k = u²·M_n/(ω_s − ω_n) = {k:.4e} N·m·s against the inertia {:.4e} kg·m² at the crank) that the speed settles within {settle:.2e} rad of crank travel, below {MIN_SETTLE_ANGLE:e} rad: the crank turns at the motor's speed, use driving = \"constant\" or check the nominal torque and the gear ratio",
                        self.inertia
                    ),
                ));
            }
        }
        let mut starts: Vec<(f64, f64)> = Vec::new();
        let (mut tt, mut ww) = (Vec::new(), Vec::new());
        let last = self
            .run(
                0.0,
                RUNUP_RTOL,
                max_cycles,
                |c| {
                    starts.push((c.start, c.omega_start));
                    starts.len() >= 3 && (c.omega_end - c.omega_start).abs() <= 1e-7 * c.omega_end
                },
                Some((&mut tt, &mut ww)),
            )
            .map_err(|e| match e {
                DynamicsError::NoConvergence { .. } => too_long(None),
                other => other,
            })?;
        let mut steady = self.periodic(last.omega_end)?;
        steady.start = last.start + last.period;
        let target = steady.omega_start;
        let time = starts
            .iter()
            .find(|(_, w)| (w - target).abs() <= SETTLE * target)
            .map(|(t, _)| *t)
            .unwrap_or(steady.start);
        Ok(Runup {
            time,
            cycles: starts.len(),
            steady,
            trace_time: tt,
            trace_omega: ww,
        })
    }
}
