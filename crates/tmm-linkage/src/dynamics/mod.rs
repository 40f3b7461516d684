//! Dynamics of the machine (динамический анализ и синтез машинного
//! агрегата), stage 3 of the course project: the mechanism reduced to its
//! crank, the flywheel (маховик) for a given coefficient of speed
//! fluctuation δ by Mertsalov's method, by Wittenbauer's energy–mass diagram
//! and exactly, its size, the true motion of the crank over the steady
//! cycle, and the motion by time integration (the steady cycle re-integrated
//! and, with a motor, the run-up from rest).
//!
//! Module map, one concept per file:
//! - [`spec`]: what the user gives (δ, the driving moment, shafts, flywheel);
//! - [`reduced`]: I_II, I_II′ and M_c at one crank angle, from the analogues;
//! - [`reduction`]: the same over the cycle, the work and ΔT;
//! - [`extremum`]: extremes over the cycle, refined between the nodes;
//! - [`load_period`]: the period of the summed loads within the cycle;
//! - [`mertsalov`], [`wittenbauer`], [`exact`]: the three ways to the inertia;
//! - [`flywheel`]: the flywheel's size;
//! - [`motion`]: ω(φ), ε(φ), t(φ) over the steady cycle;
//! - [`ode`]: the Dormand–Prince 5(4) integrator;
//! - [`simulate`]: the time integration: steady cycle and run-up;
//! - [`kloss`]: an induction motor by Kloss's formula;
//! - [`rk`]: Runge–Kutta integrators of any number of components;
//! - [`single_stroke`], [`single_stroke_energy`]: the unsteady single
//!   stroke driven by the motor, and under a constant moment by the energy
//!   method;
//! - [`error`]: what can go wrong.
//!
//! Derivations and the seed-001 flywheel: docs/dynamics.md.
//!
//! ```
//! use tmm_linkage::{LinkDef, MechanismDef, InputDef, Mechanism};
//! use tmm_linkage::forces::{Loads, Resistance, Action, Law};
//! use tmm_linkage::dynamics::{Dynamics, DynamicsSpec};
//! use tmm_geom::Vec2;
//! // Seed 001: four-bar, 900 rpm, 10 kg/m, J_S = 0.1·m·l², 380 N·m on the rocker, δ = 0.02.
//! let def = MechanismDef {
//!     fixed: vec![("A".into(), Vec2::ZERO), ("D".into(), Vec2::new(0.51, 0.0))],
//!     links: vec![LinkDef::bar("1", "A", "B", 0.12), LinkDef::bar("2", "B", "C", 0.48), LinkDef::bar("3", "D", "C", 0.38)],
//!     input: Some(InputDef { link: "1".into(), pivot: "A".into(), pin: "B".into(), omega: 30.0 * std::f64::consts::PI, epsilon: 0.0 }),
//!     ..Default::default()
//! };
//! let m = Mechanism::new(&def).unwrap();
//! let mut loads = Loads::new(&m);
//! for (l, len) in [(1, 0.12), (2, 0.48), (3, 0.38)] {
//!     loads.links[l].mass = 10.0 * len;
//!     loads.links[l].inertia = 0.1 * 10.0 * len * len * len;
//! }
//! loads.resistance.push(Resistance { link: 3, action: Action::Moment { sign: None }, law: Law::Constant(380.0) });
//! let d = Dynamics::compute(&m, &loads, &DynamicsSpec::new(0.02)).unwrap();
//! // Wittenbauer's construction done exactly is the exact steady motion
//! assert!((d.required.wittenbauer / d.required.exact - 1.0).abs() < 1e-6);
//! // and the time integration gives back δ
//! assert!((d.simulated.delta - 0.02).abs() < 1e-4);
//! ```

pub mod error;
pub mod exact;
pub mod extremum;
pub mod flywheel;
pub mod kloss;
pub mod load_period;
pub mod mertsalov;
pub mod motion;
pub mod ode;
pub mod reduced;
pub mod reduction;
pub mod rk;
pub mod simulate;
pub mod single_stroke;
pub mod single_stroke_energy;
pub mod spec;
pub mod wittenbauer;

pub use error::DynamicsError;
use error::show;
pub use exact::{Steady, Target};
pub use flywheel::FlywheelSize;
pub use kloss::KlossMotor;
pub use mertsalov::Mertsalov;
pub use motion::Motion;
pub use reduced::{Reduced, Reducer, kinetic_energy, with_crank_motion};
pub use reduction::{EnergyPoint, ReducedCycle};
pub use simulate::{Runup, SimulatedCycle, Simulator};
pub use single_stroke::{AngleCheck, BreakdownCrossing, EnergyBalance, MotorStroke, SingleStroke, StrokeRow, StrokeSpec};
pub use single_stroke_energy::{EnergyRow, EnergyStroke};
pub use spec::{DrivingMoment, DynamicsSpec, FlywheelPlace, FlywheelShape, FlywheelSpec, Motor, STEEL_DENSITY};
pub use wittenbauer::{Tangent, Wittenbauer};

use crate::Mechanism;
use crate::Solution;
use crate::forces::Loads;

/// The constant inertia required on the crank shaft by each method, kg·m².
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RequiredInertia {
    /// Mertsalov's method.
    pub mertsalov: f64,
    /// Wittenbauer's diagram (done exactly).
    pub wittenbauer: f64,
    /// The exact steady motion.
    pub exact: f64,
}

/// The constant inertia already on the crank shaft, reduced to it, kg·m².
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GivenInertia {
    /// The crank's own about its pivot, J_S1 + m₁·|AS₁|².
    pub crank: f64,
    /// Other parts on the crank shaft.
    pub crank_shaft: f64,
    /// The motor shaft's, reduced: u²·J_motor.
    pub motor_shaft: f64,
    /// Their sum.
    pub total: f64,
}

/// One of the course's 12 positions (every 30° from the start of the cycle).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Position {
    /// Its number, 0…11.
    pub index: usize,
    /// Cycle angle from the start of the cycle in the direction of rotation, rad.
    pub phi: f64,
    /// Absolute crank angle, rad.
    pub crank_angle: f64,
    /// I_II, kg·m².
    pub inertia: f64,
    /// M_c, N·m.
    pub moment: f64,
    /// M_d, N·m.
    pub driving_moment: f64,
    /// A_c, J.
    pub work_loads: f64,
    /// A_d, J.
    pub work_driving: f64,
    /// ΔT, J.
    pub energy: f64,
    /// T_I = ΔT − I_II·ω_m²/2 (Mertsalov), J.
    pub energy_constant: f64,
    /// ω₁, rad/s (in the direction of rotation).
    pub omega: f64,
    /// ε₁, rad/s² (in the direction of rotation).
    pub epsilon: f64,
}

/// The whole dynamics of one machine.
#[derive(Debug, Clone)]
pub struct Dynamics {
    /// The specification it was computed for.
    pub spec: DynamicsSpec,
    /// The nominal (mean) crank speed ω_m, rad/s (> 0).
    pub omega_nominal: f64,
    /// The reduced model at any angle.
    pub reducer: Reducer,
    /// The reduced model and energy over the cycle.
    pub cycle: ReducedCycle,
    /// The least period of the summed loads M_c and of I_II within the
    /// machine's cycle, rad ([`load_period`]): the cycle itself, or a part
    /// of it (one turn of П2's opposed engine, whose cylinders' cycles are
    /// two turns), over which the flywheel is the same. Mertsalov's,
    /// Wittenbauer's and the exact method search their extremes over
    /// 0…load_period and give their angles there; the motion, the positions
    /// and the time integration cover the whole cycle.
    pub load_period: f64,
    /// The constant inertia already on the crank shaft.
    pub inertia_given: GivenInertia,
    /// Mertsalov's method in detail.
    pub mertsalov: Mertsalov,
    /// Wittenbauer's construction in detail.
    pub wittenbauer: Wittenbauer,
    /// The exact steady motion for δ.
    pub exact: Steady,
    /// The required constant inertia by the three methods.
    pub required: RequiredInertia,
    /// The flywheel's inertia reduced to the crank shaft (0 when none is needed), kg·m².
    pub flywheel_inertia_crank: f64,
    /// The flywheel's own inertia on its shaft, kg·m².
    pub flywheel_inertia: f64,
    /// Its size (none when the shaft already carries enough inertia).
    pub flywheel: Option<FlywheelSize>,
    /// The steady motion with the flywheel.
    pub motion: Motion,
    /// The 12 positions.
    pub positions: Vec<Position>,
    /// One steady cycle by time integration: from the exact start with a
    /// constant moment, the run-up's last cycle with a motor.
    pub simulated: SimulatedCycle,
    /// The run-up from rest (with a motor).
    pub runup: Option<Runup>,
}

impl Dynamics {
    /// Everything, for mechanism `m` (its input speed is the nominal one)
    /// under `loads`.
    pub fn compute(m: &Mechanism, loads: &Loads, spec: &DynamicsSpec) -> Result<Self, DynamicsError> {
        spec.check()?;
        let omega_m = m.crank.omega.abs();
        let red = Reducer::new(m, loads, spec.working)?;
        let mut sol = red.solution();
        let cycle = match spec.driving {
            DrivingMoment::Engine => ReducedCycle::for_engine(&red, spec.points, &mut sol)?,
            _ => ReducedCycle::new(&red, spec.points, &mut sol)?,
        };
        let load_period = load_period::of_cycle(&cycle, red.period, loads.cycle.turns);
        let md = cycle.driving_moment;
        let ratio = spec.motor_ratio(omega_m);
        if let Some(mo) = spec.motor() {
            check_motor(mo, md, omega_m, spec.delta)?;
        }
        let given = GivenInertia {
            crank: red.inertia_crank,
            crank_shaft: spec.inertia_crank_shaft,
            motor_shaft: ratio * ratio * spec.inertia_motor_shaft,
            total: red.inertia_crank + spec.inertia_crank_shaft + ratio * ratio * spec.inertia_motor_shaft,
        };
        let delta = spec.delta;
        let (wmax, wmin) = (omega_m * (1.0 + 0.5 * delta), omega_m * (1.0 - 0.5 * delta));
        // each method walks the period of the summed loads, as the book
        // does (П2: 0…2π of the 4π cycle): where the loads repeat within the
        // cycle so do ΔT, T_I, the energy–mass curve and ω(φ), and the
        // extremes over the first period are those over the cycle; each is
        // given at its first angle, within 0…load_period (П2's Φ_A in
        // 140°…180°, Φ_B in 0°…30°)
        let span = load_period;
        let mertsalov = mertsalov::mertsalov(&red, &cycle, &mut sol, omega_m, delta, span)?;
        let wittenbauer = wittenbauer::wittenbauer(&red, &cycle, &mut sol, wmax, wmin, span)?;
        let exact = exact::steady(&red, &cycle, &mut sol, omega_m, Target::Delta(delta), mertsalov.inertia, span)?;
        let required = RequiredInertia {
            mertsalov: mertsalov.inertia,
            wittenbauer: wittenbauer.inertia,
            exact: exact.inertia,
        };
        let fw_crank = (exact.inertia - given.total).max(0.0);
        let (fw, size) = if fw_crank > 0.0 {
            let on = match spec.flywheel.place {
                FlywheelPlace::Crank => fw_crank,
                FlywheelPlace::Motor => fw_crank / (ratio * ratio),
                // equal kinetic energy through a speed ratio i: J_shaft = J_crank/i²
                FlywheelPlace::Shaft => fw_crank / (spec.flywheel.speed_ratio * spec.flywheel.speed_ratio),
            };
            (on, Some(flywheel::size(on, &spec.flywheel)))
        } else {
            (0.0, None)
        };
        // the motion with the flywheel: exactly δ; without one, the given
        // inertia at mean speed ω_m (δ smaller than asked)
        let st = if fw_crank > 0.0 {
            exact
        } else {
            exact::steady(&red, &cycle, &mut sol, omega_m, Target::Inertia(given.total), given.total, span)?
        };
        let motion = Motion::new(&cycle, st.inertia, st.energy_start, st.omega_max, st.omega_min)?;
        let n = cycle.len();
        let positions = (0..12)
            .map(|i| {
                let k = i * n / 12;
                Position {
                    index: i,
                    phi: cycle.phi[k],
                    crank_angle: red.crank_angle(cycle.phi[k]),
                    inertia: cycle.inertia[k],
                    moment: cycle.moment[k],
                    driving_moment: md,
                    work_loads: cycle.work_loads[k],
                    work_driving: cycle.work_driving[k],
                    energy: cycle.energy[k],
                    energy_constant: mertsalov.energy_constant[k],
                    omega: motion.omega[k],
                    epsilon: motion.epsilon[k],
                }
            })
            .collect();
        let inertia_total = st.inertia;
        let (simulated, runup) = {
            let mut sim = Simulator::new(&red, &mut sol, inertia_total, spec.driving, md, omega_m);
            match spec.driving {
                DrivingMoment::Constant | DrivingMoment::Engine => (sim.cycle(motion.omega[0])?, None),
                DrivingMoment::Motor(_) => {
                    let r = sim.runup(simulate::MAX_RUNUP_CYCLES)?;
                    (r.steady, Some(r))
                }
            }
        };
        Ok(Dynamics {
            spec: spec.clone(),
            omega_nominal: omega_m,
            reducer: red,
            cycle,
            load_period,
            inertia_given: given,
            mertsalov,
            wittenbauer,
            exact,
            required,
            flywheel_inertia_crank: fw_crank,
            flywheel_inertia: fw,
            flywheel: size,
            motion,
            positions,
            simulated,
            runup,
        })
    }

    /// A solution buffer for [`Dynamics::crank_motion_at`].
    pub fn solution(&self) -> Solution {
        self.reducer.solution()
    }

    /// The crank's true speed and acceleration (ω₁, ε₁) at absolute crank
    /// angle `phi`, signed as the mechanism's input.
    pub fn crank_motion_at(&self, phi: f64, sol: &mut Solution) -> Result<(f64, f64), DynamicsError> {
        self.motion.at(&self.reducer, &self.cycle, phi, sol)
    }

    /// As [`Dynamics::crank_motion_at`] at cycle angle `psi` (rad from the
    /// start of the machine's cycle, 0…period).
    pub fn crank_motion_at_cycle(&self, psi: f64, sol: &mut Solution) -> Result<(f64, f64), DynamicsError> {
        let phi = self.reducer.crank_angle(psi);
        self.motion.at_cycle(&self.reducer, &self.cycle, psi, phi, sol)
    }
}

/// The mean crank speed at which an induction motor's linear characteristic,
/// reduced to the crank, delivers the mean driving moment `md` (N·m), rad/s.
/// Derived here (docs/dynamics.md): the motor's work over a steady cycle,
/// ∮ u·M(u·ω) dφ with M linear in ω, is 2π·u·M(u·ω̄) where ω̄ = ∮ω dφ/2π is
/// the crank speed averaged over the angle; equal to the loads' work 2π·M_d,
/// it gives u·M_n·(ω_s − u·ω̄)/(ω_s − ω_n) = M_d, so
/// ω̄ = (ω_s − (M_d/u)·(ω_s − ω_n)/M_n)/u.
///
/// ```
/// use tmm_linkage::dynamics::{Motor, balance_speed};
/// let m = Motor { synchronous_speed: 150.0, nominal_speed: 140.0, nominal_torque: 20.0, ratio: 2.0 };
/// // at the nominal torque on the motor shaft the crank turns at ω_n/u
/// assert!((balance_speed(&m, 40.0) - 70.0).abs() < 1e-12);
/// // unloaded, at ω_s/u
/// assert!((balance_speed(&m, 0.0) - 75.0).abs() < 1e-12);
/// ```
pub fn balance_speed(m: &Motor, md: f64) -> f64 {
    (m.synchronous_speed - md / m.ratio * (m.synchronous_speed - m.nominal_speed) / m.nominal_torque) / m.ratio
}

/// The motor against the machine: it must turn the crank faster than its
/// nominal speed `omega_m` unloaded (ω_s/u > ω_m), carry the mean moment
/// `md` within its nominal torque, and settle, under that moment, at a mean
/// speed no lower than the slowest the flywheel allows, ω_m·(1 − δ/2):
/// a slower motor would turn the crank slower than it needs, with a larger
/// fluctuation than δ.
fn check_motor(mo: &Motor, md: f64, omega_m: f64, delta: f64) -> Result<(), DynamicsError> {
    let sync = mo.synchronous_speed / mo.ratio;
    if sync <= omega_m {
        return Err(DynamicsError::spec(
            "dynamics.motor.synchronous_speed",
            format!(
                "the motor is too slow: its synchronous speed {} rad/s through the ratio {} turns the crank at most at {} rad/s, below the crank's nominal speed {} rad/s; choose a faster motor or a smaller ratio",
                show(mo.synchronous_speed),
                show(mo.ratio),
                show(sync),
                show(omega_m)
            ),
        ));
    }
    let need = md / mo.ratio;
    if need > mo.nominal_torque {
        return Err(DynamicsError::spec(
            "dynamics.motor.nominal_torque",
            format!(
                "the motor is too weak: the machine needs {} N·m on the motor shaft on average, above its nominal torque {} N·m",
                show(need),
                show(mo.nominal_torque)
            ),
        ));
    }
    let w_bal = balance_speed(mo, md);
    let w_min = omega_m * (1.0 - 0.5 * delta);
    if w_bal < w_min {
        // the largest ratio that keeps ω̄ ≥ ω_min: ω_min·u² − ω_s·u + M_d·(ω_s − ω_n)/M_n ≤ 0
        let (ws, slip) = (mo.synchronous_speed, mo.synchronous_speed - mo.nominal_speed);
        let disc = ws * ws - 4.0 * w_min * md * slip / mo.nominal_torque;
        let hint = if disc >= 0.0 {
            format!("a ratio of at most {:.4}", (ws + disc.sqrt()) / (2.0 * w_min))
        } else {
            "a faster or stronger motor".to_string()
        };
        return Err(DynamicsError::spec(
            "dynamics.motor.ratio",
            format!(
                "the motor is slower than the crank needs: under the mean driving moment M_d = {} N·m its characteristic through the ratio {} settles the crank at a mean speed of {:.4} rad/s ({:.2} rpm), below the slowest speed the flywheel allows, ω_min = ω_m·(1 − δ/2) = {:.4} rad/s (ω_m = {:.4} rad/s, the [linkage] input speed); choose {hint}, or a motor of higher nominal speed",
                show(md),
                show(mo.ratio),
                w_bal,
                w_bal * 30.0 / std::f64::consts::PI,
                w_min,
                omega_m
            ),
        ));
    }
    Ok(())
}
