//! The whole cycle of the crank (цикл): the output coordinate, dead (extreme)
//! positions (мёртвые/крайние положения), working and return strokes and the
//! time ratio Kv, the 12 positions of the course project, kinematic diagrams
//! of the output, pressure and transmission angles, and where a mechanism
//! cannot be assembled.
//!
//! Sources: seed 002 § 2 (12 positions from the dead position that starts the
//! working stroke; Kv = φ_work/φ_return for a uniformly rotating crank);
//! seed 000 § 1.2 (Kv = (180° + θ)/(180° − θ)). Dead positions are the roots of
//! ds/dφ = v_s/ω1 = 0 refined by Brent's method to 1e-12 rad.

use std::f64::consts::{PI, TAU};

use tmm_geom::{Vec2, perp, root};

use crate::error::LinkageError;
use crate::mechanism::{Mechanism, Pair, Solution};

/// What the output coordinate s is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OutputKind {
    /// Travel of a slider along its fixed guide, m.
    Linear,
    /// Angle of a rotating link, rad.
    Angular,
}

/// Which stroke is the working one (рабочий ход).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Working {
    /// The slower stroke (the longer crank angle): Kv ≥ 1. The course default.
    #[default]
    Slower,
    /// The stroke on which s increases.
    Increasing,
    /// The stroke on which s decreases.
    Decreasing,
}

/// Output coordinate with its first and second time derivatives.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OutputState {
    /// s (m or rad).
    pub s: f64,
    /// ds/dt.
    pub v: f64,
    /// d²s/dt².
    pub a: f64,
}

/// How the output coordinate is read off a solution.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Output {
    /// The output link.
    pub link: usize,
    /// Linear or angular.
    pub kind: OutputKind,
    point: usize,
    origin: Vec2,
    dir: Vec2,
}

impl Output {
    /// The output of a mechanism: a slider on a fixed guide gives a linear
    /// coordinate along the guide; any other link its angle.
    pub fn of(m: &Mechanism) -> Self {
        for p in &m.pairs {
            if let Pair::P {
                slider,
                guide: 0,
                q,
                d,
                point,
                ..
            } = *p
            {
                if slider == m.output {
                    return Output {
                        link: slider,
                        kind: OutputKind::Linear,
                        point,
                        origin: q,
                        dir: d,
                    };
                }
            }
        }
        Output {
            link: m.output,
            kind: OutputKind::Angular,
            point: 0,
            origin: Vec2::ZERO,
            dir: Vec2::ZERO,
        }
    }

    /// The output's s, ds/dt, d²s/dt². An angle is continuous near `near`.
    #[inline]
    pub fn read(&self, sol: &Solution, near: f64) -> OutputState {
        match self.kind {
            OutputKind::Linear => {
                let p = &sol.points[self.point];
                OutputState {
                    s: (p.p - self.origin).dot(self.dir),
                    v: p.v.dot(self.dir),
                    a: p.a.dot(self.dir),
                }
            }
            OutputKind::Angular => {
                let l = &sol.links[self.link];
                let th = l.angle();
                let s = near + tmm_geom::angle::wrap_pi(th - near);
                OutputState { s, v: l.omega, a: l.eps }
            }
        }
    }
}

/// One of the positions of the 12-position table.
#[derive(Debug, Clone, PartialEq)]
pub struct Position {
    /// Label: `0` … `11`, and the other dead position as `k'`.
    pub label: String,
    /// Absolute crank angle φ, rad.
    pub phi: f64,
    /// Crank rotation from the starting dead position ψ ∈ [0, 2π), rad.
    pub psi: f64,
}

/// The cycle of a mechanism.
#[derive(Debug, Clone, PartialEq)]
pub struct Cycle {
    /// Output coordinate reader.
    pub output: Output,
    /// Dead positions of the output (absolute φ, rad), the one starting the
    /// working stroke first. Empty when the output turns fully.
    pub dead: Vec<f64>,
    /// φ of the position 0.
    pub start: f64,
    /// Crank angle of the working stroke, rad.
    pub working_angle: f64,
    /// Crank angle of the return stroke, rad.
    pub return_angle: f64,
    /// Kv = φ_work / φ_return.
    pub kv: f64,
    /// Angle θ (угол перекрытия): φ_work − π, rad.
    pub theta: f64,
    /// Stroke of the output, m or rad.
    pub stroke: f64,
    /// s at the starting dead position.
    pub s_start: f64,
    /// +1 when s increases on the working stroke, −1 otherwise.
    pub work_sign: f64,
}

/// Two strokes whose crank angles differ by less than this fraction of a turn
/// take the same time (Kv = 1): which one is "slower" is round-off.
pub const KV_TIE: f64 = 1e-9;

/// The error for `working = slower` when Kv = 1.
pub fn kv_tie(up: f64, down: f64) -> LinkageError {
    LinkageError::desc(
        "working",
        format!(
            "both strokes take the same crank angle ({:.6}° and {:.6}°, Kv = 1), so neither is the slower one; \
             say which stroke works: `increasing` or `decreasing` (the output coordinate on the working stroke)",
            up.to_degrees(),
            down.to_degrees()
        ),
    )
}

/// The zeros of a periodic function of the crank angle at which it changes
/// sign, over one turn from `phi0` in the direction `sg` (±1): sampled at `n`
/// equal steps, the last step closing the turn onto the first sample, each
/// sign change refined by Brent's method to 1e-13 rad. A sample that is
/// exactly zero is a root when the nearest non-zero samples on either side
/// differ in sign. Non-finite samples (positions that do not assemble) break
/// the scan there. So a root on a grid point — the start included — is found
/// once, wherever the scan starts. Returned in order of crank travel.
///
/// ```
/// // cos φ changes sign at 90° and 270°; the scan starts on a root of sin φ
/// let r = tmm_linkage::cycle::periodic_roots(0.0, 1.0, 720, |x| x.cos());
/// assert_eq!(r.len(), 2);
/// assert!((r[0] - std::f64::consts::FRAC_PI_2).abs() < 1e-12);
/// let r = tmm_linkage::cycle::periodic_roots(0.0, -1.0, 720, |x| x.sin());
/// assert_eq!(r.len(), 2);
/// assert!(r[0].abs() < 1e-12 && (r[1] + std::f64::consts::PI).abs() < 1e-12);
/// ```
pub fn periodic_roots(phi0: f64, sg: f64, n: usize, mut f: impl FnMut(f64) -> f64) -> Vec<f64> {
    let n = n.max(4);
    let at = |k: usize| phi0 + sg * TAU * k as f64 / n as f64;
    let v: Vec<f64> = (0..n).map(|k| f(at(k))).collect();
    let ok = |x: f64| x.is_finite();
    let mut roots = Vec::new();
    for k in 0..n {
        let (a, b) = (v[k], v[(k + 1) % n]);
        if a == 0.0 {
            // only the first of a run of zeros; compare the signs around the run
            let before = (1..n).map(|j| v[(k + n - j) % n]).find(|x| *x != 0.0);
            if v[(k + n - 1) % n] == 0.0 {
                continue;
            }
            let after = (1..n).map(|j| v[(k + j) % n]).find(|x| *x != 0.0);
            if let (Some(p), Some(q)) = (before, after) {
                if ok(p) && ok(q) && p.signum() != q.signum() {
                    roots.push(at(k));
                }
            }
        } else if b != 0.0 && ok(a) && ok(b) && a.signum() != b.signum() {
            // the last step ends exactly on the first sample's angle (one turn
            // back), so that the bracket's end is the very value sampled there
            let (x0, x1) = if k + 1 == n { (at(k) - sg * TAU, phi0) } else { (at(k), at(k + 1)) };
            let r = root::brent(&mut f, x0.min(x1), x0.max(x1), 1e-13)
                // a re-evaluation that disagrees in sign with the sample (a root
                // within round-off of the bracket's end): the end nearer zero
                .unwrap_or(if a.abs() <= b.abs() { x0 } else { x1 });
            roots.push(r);
        }
    }
    roots
}

/// Direction of crank rotation: +1 counter-clockwise, −1 clockwise.
fn dir(m: &Mechanism) -> f64 {
    m.crank.omega.signum()
}

/// Scan a full turn: every crank angle range where the mechanism cannot be
/// assembled, with boundaries refined to 1e-9 rad, as an error.
pub fn check_assembly(m: &Mechanism, sol: &mut Solution) -> Result<(), LinkageError> {
    let n = 1440;
    // the common case, a crank that turns fully, by the swept solver (each
    // position starts from the last one's crank direction): only when some
    // grid angle fails is the turn scanned again position by position to
    // find and refine the failing ranges
    if m.sweep(0.0, TAU / n as f64, n + 1, sol, |_, _| {}).is_ok() {
        // leave the solution where the scan below leaves it (φ = 2π solved on
        // its own), which the cycle's later solves start from
        return m.solve(TAU, sol);
    }
    let mut bad: Vec<(f64, f64)> = Vec::new();
    let mut reason = None;
    let ok_at = |phi: f64, sol: &mut Solution| m.solve(phi, sol);
    let mut prev_ok = true;
    let mut last_ok_phi = 0.0;
    for k in 0..=n {
        let phi = TAU * k as f64 / n as f64;
        match ok_at(phi, sol) {
            Ok(()) => {
                if !prev_ok {
                    let hi = refine(m, sol, last_ok_phi, phi, false);
                    if let Some(r) = bad.last_mut() {
                        r.1 = hi;
                    }
                }
                prev_ok = true;
                last_ok_phi = phi;
            }
            Err(e) => {
                if reason.is_none() {
                    reason = Some(e.to_string());
                }
                if prev_ok {
                    let lo = if k == 0 { 0.0 } else { refine(m, sol, last_ok_phi, phi, true) };
                    bad.push((lo, TAU));
                }
                prev_ok = false;
                last_ok_phi = phi;
            }
        }
    }
    if bad.is_empty() {
        return Ok(());
    }
    let ranges: Vec<String> = bad
        .iter()
        .map(|(a, b)| format!("{:.4}°…{:.4}°", a.to_degrees(), b.to_degrees()))
        .collect();
    Err(LinkageError::AssemblyRanges {
        ranges: ranges.join(", "),
        reason: reason.unwrap_or_default(),
    })
}

/// Bisection on the boundary between an assembling and a failing angle.
fn refine(m: &Mechanism, sol: &mut Solution, a: f64, b: f64, a_ok: bool) -> f64 {
    let (mut ok, mut bad) = if a_ok { (a, b) } else { (b, a) };
    for _ in 0..40 {
        let mid = 0.5 * (ok + bad);
        if m.solve(mid, sol).is_ok() {
            ok = mid;
        } else {
            bad = mid;
        }
    }
    let _ = m.solve(ok, sol);
    0.5 * (ok + bad)
}

impl Cycle {
    /// Analyse the cycle: assembly over the whole turn, dead positions, Kv,
    /// stroke.
    pub fn new(m: &Mechanism, working: Working) -> Result<Self, LinkageError> {
        m.require_crank("the cycle of a full turn")?;
        let mut sol = m.solution();
        check_assembly(m, &mut sol)?;
        let output = Output::of(m);
        let sg = dir(m);
        let w = m.crank.omega;
        // ds/dψ along the direction of rotation, ψ the crank travel
        let f = |phi: f64, sol: &mut Solution| -> f64 {
            match m.solve(phi, sol) {
                Ok(()) => output.read(sol, 0.0).v / w,
                Err(_) => f64::NAN,
            }
        };
        let phi0 = m.assembly_angle;
        let roots = periodic_roots(phi0, sg, 720, |x| f(x, &mut sol));
        // an angle is read continuous about its value at the assembly angle, so
        // that a swing across ±180° is not cut in two
        let reference = match m.solve(phi0, &mut sol) {
            Ok(()) => output.read(&sol, 0.0).s,
            Err(_) => 0.0,
        };
        let stroke_and = |phi: f64, sol: &mut Solution| -> f64 {
            let _ = m.solve(phi, sol);
            output.read(sol, reference).s
        };
        if roots.len() < 2 || output.kind == OutputKind::Angular && rotates_fully(m, &output) {
            let s = stroke_and(phi0, &mut sol);
            return Ok(Cycle {
                output,
                dead: vec![],
                start: phi0,
                working_angle: TAU,
                return_angle: 0.0,
                kv: 1.0,
                theta: 0.0,
                stroke: 0.0,
                s_start: s,
                work_sign: 1.0,
            });
        }
        // the two extremes: the global min and max of s among the roots
        let mut ext: Vec<(f64, f64)> = roots.iter().map(|&r| (r, stroke_and(r, &mut sol))).collect();
        ext.sort_by(|a, b| a.1.total_cmp(&b.1));
        let (pmin, smin) = ext[0];
        let (pmax, smax) = ext[ext.len() - 1];
        // travel from min to max in the direction of rotation
        let travel = |from: f64, to: f64| (sg * (to - from)).rem_euclid(TAU);
        let up = travel(pmin, pmax);
        let down = TAU - up;
        let (start, work, ret, sign) = match working {
            Working::Increasing => (pmin, up, down, 1.0),
            Working::Decreasing => (pmax, down, up, -1.0),
            Working::Slower => {
                if (up - down).abs() <= KV_TIE * TAU {
                    return Err(kv_tie(up, down));
                }
                if up >= down {
                    (pmin, up, down, 1.0)
                } else {
                    (pmax, down, up, -1.0)
                }
            }
        };
        let other = if start == pmin { pmax } else { pmin };
        let s_start = if start == pmin { smin } else { smax };
        Ok(Cycle {
            output,
            dead: vec![tmm_geom::angle::wrap_2pi(start), tmm_geom::angle::wrap_2pi(other)],
            start: tmm_geom::angle::wrap_2pi(start),
            working_angle: work,
            return_angle: ret,
            kv: work / ret,
            theta: work - PI,
            stroke: smax - smin,
            s_start,
            work_sign: sign,
        })
    }

    /// `n` equally spaced positions from the start in the direction of
    /// rotation, plus the other dead position, in order of crank travel.
    pub fn positions(&self, m: &Mechanism, n: usize) -> Vec<Position> {
        let sg = dir(m);
        let n = n.max(1);
        let mut out: Vec<Position> = (0..n)
            .map(|k| {
                let psi = TAU * k as f64 / n as f64;
                Position {
                    label: k.to_string(),
                    phi: tmm_geom::angle::wrap_2pi(self.start + sg * psi),
                    psi,
                }
            })
            .collect();
        if self.dead.len() == 2 {
            let psi = self.working_angle;
            let k = (psi / (TAU / n as f64)).floor() as usize;
            let on_grid = (psi - TAU * k as f64 / n as f64).abs() < 1e-9;
            if !on_grid {
                out.insert(
                    k + 1,
                    Position {
                        label: format!("{k}'"),
                        phi: self.dead[1],
                        psi,
                    },
                );
            }
        }
        out
    }

    /// The output's displacement from the start along the working direction,
    /// and its first and second derivatives with respect to the crank travel ψ
    /// (ds/dψ = v/|ω1|, d²s/dψ² = (a − ds/dψ·ε1·sgn ω1)/ω1²).
    pub fn analogs(&self, m: &Mechanism, sol: &Solution) -> (f64, f64, f64) {
        let o = self.output.read(sol, self.s_start);
        let w = m.crank.omega.abs();
        let s = self.work_sign * (o.s - self.s_start);
        let ds = self.work_sign * o.v / w;
        let dds = (self.work_sign * o.a - ds * m.crank.eps * m.crank.omega.signum()) / (w * w);
        (s, ds, dds)
    }
}

fn rotates_fully(m: &Mechanism, out: &Output) -> bool {
    let mut sol = m.solution();
    let mut total = 0.0;
    let mut prev: Option<f64> = None;
    for k in 0..=360 {
        let phi = TAU * k as f64 / 360.0;
        if m.solve(phi, &mut sol).is_err() {
            return false;
        }
        let th = sol.links[out.link].angle();
        if let Some(p) = prev {
            total += tmm_geom::angle::wrap_pi(th - p);
        }
        prev = Some(th);
    }
    total.abs() > PI
}

/// Pressure angle ϑ (угол давления) at the inner joint of each dyad where it is
/// defined: the angle between the force a two-force link (or a frictionless
/// guide) transmits and the velocity direction of the driven point. The
/// transmission angle is γ = 90° − ϑ (seed 000, § 1.2; Artobolevsky § 26).
/// Returns (inner joint point index, ϑ) for RRR, RRP and RPR dyads.
pub fn pressure_angles(m: &Mechanism, sol: &Solution, out: &mut Vec<(usize, f64)>) {
    out.clear();
    for g in &m.groups {
        let Some(dy) = g.dyad() else { continue };
        let ids = &g.info.pair_ids;
        let (e1, mid, e2) = (&m.pairs[ids[0]], &m.pairs[ids[1]], &m.pairs[ids[2]]);
        let p = |i: usize| sol.points[i].p;
        let angle = |f: Vec2, v: Vec2| {
            let c = (f.dot(v) / (f.hypot() * v.hypot())).abs().min(1.0);
            c.acos()
        };
        match dy.kind() {
            "RRR" => {
                // force along link 1 (outer A → inner B); B driven about C on link 2
                let (a, b, c) = (p(e1.point()), p(mid.point()), p(e2.point()));
                out.push((mid.point(), angle(b - a, perp(b - c))));
            }
            "RRP" => {
                let (a, b) = (p(e1.point()), p(mid.point()));
                if let Pair::P { guide, d, .. } = *e2 {
                    let gd = crate::state::rot(sol.links[guide].u, d);
                    out.push((mid.point(), angle(b - a, gd)));
                }
            }
            "RPR" => {
                if let Pair::P { guide, d, point, .. } = *mid {
                    let n = perp(crate::state::rot(sol.links[guide].u, d));
                    // the guide link turns about its own outer joint
                    let x = if e1.links().0 == guide || e1.links().1 == guide {
                        e1.point()
                    } else {
                        e2.point()
                    };
                    out.push((point, angle(n, perp(p(point) - p(x)))));
                }
            }
            _ => {}
        }
    }
}
