//! Where over a turn of the crank a mechanism assembles (области сборки), and
//! the analysis of a mechanism whose crank cannot turn fully over the ranges
//! where it does — a double rocker driven over its swing is a designer's real
//! case. The full-turn cycle ([`crate::cycle::Cycle`]) still refuses such a
//! mechanism; [`PartialCycle`] is the explicit choice to analyse it anyway.
//!
//! The turn is scanned at 0.25° from φ = 0 and every change between a
//! position that solves and one that does not is refined by bisection to
//! 1e-12 rad; a range's ends are the last angles that solve. A position
//! "does not solve" when a group cannot close or is within
//! [`crate::dyad::MIN_SINE`] of its dead centre (where the velocities grow
//! without bound), so a range ends just short of the group's dead centre.

use std::f64::consts::TAU;

use crate::cycle::{Output, periodic_roots};
use crate::error::LinkageError;
use crate::mechanism::{Mechanism, Solution};

/// Scan steps over a turn.
const STEPS: usize = 1440;

/// One range of crank angles over which the mechanism assembles.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AssemblyRange {
    /// First angle, rad in [0, 2π) (counter-clockwise order).
    pub from: f64,
    /// Last angle, rad; `to > from`, possibly beyond 2π when the range wraps
    /// through 0.
    pub to: f64,
}

impl AssemblyRange {
    /// The range's span, rad.
    pub fn span(&self) -> f64 {
        self.to - self.from
    }
}

/// Where a mechanism assembles over a turn.
#[derive(Debug, Clone, PartialEq)]
pub struct AssemblyMap {
    /// The ranges that assemble, counter-clockwise from the first after 0.
    /// A single range of span 2π when the crank turns fully.
    pub ok: Vec<AssemblyRange>,
    /// The gaps between them (where it does not), same convention.
    pub gaps: Vec<AssemblyRange>,
    /// Why the first failing position fails.
    pub reason: Option<String>,
}

impl AssemblyMap {
    /// Scan a turn of the crank.
    pub fn scan(m: &Mechanism) -> Self {
        let mut sol = m.solution();
        let mut reason = None;
        let ok: Vec<bool> = (0..STEPS)
            .map(|k| match m.solve(TAU * k as f64 / STEPS as f64, &mut sol) {
                Ok(()) => true,
                Err(e) => {
                    reason.get_or_insert_with(|| e.to_string());
                    false
                }
            })
            .collect();
        if ok.iter().all(|&x| x) {
            return AssemblyMap {
                ok: vec![AssemblyRange { from: 0.0, to: TAU }],
                gaps: vec![],
                reason: None,
            };
        }
        if ok.iter().all(|&x| !x) {
            return AssemblyMap {
                ok: vec![],
                gaps: vec![AssemblyRange { from: 0.0, to: TAU }],
                reason,
            };
        }
        let at = |k: usize| TAU * k as f64 / STEPS as f64;
        // boundaries: (angle of the change, true when entering an ok range)
        let mut edges: Vec<(f64, f64, bool)> = Vec::new();
        for k in 0..STEPS {
            let (a, b) = (ok[k], ok[(k + 1) % STEPS]);
            if a != b {
                let (last_ok, first_ok) = bisect(m, &mut sol, at(k), at(k + 1), a);
                edges.push((last_ok, first_ok, b));
            }
        }
        // start from the first entry into an ok range
        let first = edges.iter().position(|e| e.2).unwrap_or(0);
        edges.rotate_left(first);
        let mut ranges: Vec<AssemblyRange> = Vec::new();
        for i in (0..edges.len()).step_by(2) {
            let from = edges[i].1.rem_euclid(TAU);
            let mut to = edges[(i + 1) % edges.len()].0;
            while to < from {
                to += TAU;
            }
            ranges.push(AssemblyRange { from, to });
        }
        let gaps = (0..ranges.len())
            .map(|i| {
                let from = ranges[i].to.rem_euclid(TAU);
                let mut to = ranges[(i + 1) % ranges.len()].from;
                while to <= from {
                    to += TAU;
                }
                AssemblyRange { from, to }
            })
            .collect();
        AssemblyMap { ok: ranges, gaps, reason }
    }

    /// `true` when the crank turns fully.
    pub fn full_turn(&self) -> bool {
        self.gaps.is_empty() && !self.ok.is_empty()
    }

    /// The gaps as text, `102.5000°…157.5000°, …`.
    pub fn gaps_text(&self) -> String {
        let r: Vec<String> = self
            .gaps
            .iter()
            .map(|g| format!("{:.4}°…{:.4}°", g.from.to_degrees(), g.to.to_degrees()))
            .collect();
        r.join(", ")
    }
}

/// Bisection between a solving angle and a failing one (`a_ok` says which of
/// `a`, `b` solves) by 44 halvings of a 0.25° step (below 1e-14 rad): the
/// angle nearest the boundary that still solves, returned twice (as the end
/// of the range being left and the start of the range being entered).
fn bisect(m: &Mechanism, sol: &mut Solution, a: f64, b: f64, a_ok: bool) -> (f64, f64) {
    let (mut good, mut bad) = if a_ok { (a, b) } else { (b, a) };
    for _ in 0..44 {
        let mid = 0.5 * (good + bad);
        if m.solve(mid, sol).is_ok() {
            good = mid;
        } else {
            bad = mid;
        }
    }
    (good, good)
}

/// One range of a partial cycle with the output's extremes on it.
#[derive(Debug, Clone, PartialEq)]
pub struct RangeCycle {
    /// The crank angles, rad.
    pub range: AssemblyRange,
    /// The output's dead positions inside the range (zeros of ds/dφ where
    /// it changes sign), rad, counter-clockwise.
    pub dead: Vec<f64>,
    /// The output coordinate's least and greatest value over the range
    /// (at a dead position or at an end), m or rad.
    pub s_min: f64,
    /// See `s_min`.
    pub s_max: f64,
}

/// The analysis of a mechanism over the ranges where it assembles, for a
/// crank that cannot turn fully (or can: then one range of 2π).
#[derive(Debug, Clone, PartialEq)]
pub struct PartialCycle {
    /// How the output coordinate is read.
    pub output: Output,
    /// The ranges with their extremes.
    pub ranges: Vec<RangeCycle>,
    /// Where it does not assemble, and why.
    pub map: AssemblyMap,
}

impl PartialCycle {
    /// Analyse over the assembly ranges. An error only when the mechanism
    /// assembles nowhere.
    ///
    /// ```
    /// use tmm_linkage::{LinkDef, MechanismDef, InputDef, Mechanism, ranges::PartialCycle};
    /// use tmm_geom::Vec2;
    /// // a triple rocker: crank 0.3, coupler 0.25, rocker 0.2, frame 0.4 m;
    /// // |BD|² = 0.25 − 0.24 cos φ ≤ 0.45² ⇒ cos φ ≥ 0.0475/0.24
    /// let def = MechanismDef {
    ///     fixed: vec![("A".into(), Vec2::ZERO), ("D".into(), Vec2::new(0.4, 0.0))],
    ///     links: vec![LinkDef::bar("1", "A", "B", 0.3), LinkDef::bar("2", "B", "C", 0.25), LinkDef::bar("3", "D", "C", 0.2)],
    ///     input: Some(InputDef { link: "1".into(), pivot: "A".into(), pin: "B".into(), omega: 1.0, epsilon: 0.0 }),
    ///     ..Default::default()
    /// };
    /// let m = Mechanism::new(&def).unwrap();
    /// let p = PartialCycle::new(&m).unwrap();
    /// assert_eq!(p.ranges.len(), 1);
    /// let lim = (0.0475f64 / 0.24).acos();
    /// assert!((p.ranges[0].range.from - (std::f64::consts::TAU - lim)).abs() < 1e-6);
    /// assert!((p.ranges[0].range.to - (std::f64::consts::TAU + lim)).abs() < 1e-6);
    /// ```
    pub fn new(m: &Mechanism) -> Result<Self, LinkageError> {
        m.require_crank("the map of assembly ranges")?;
        let map = AssemblyMap::scan(m);
        if map.ok.is_empty() {
            return Err(LinkageError::AssemblyRanges {
                ranges: "0°…360° (every angle)".into(),
                reason: map.reason.clone().unwrap_or_default(),
            });
        }
        let output = Output::of(m);
        let w = m.crank.omega;
        let mut sol = m.solution();
        let mut ranges = Vec::new();
        for r in &map.ok {
            // ds/dφ over the range only (NaN outside, which breaks the scan)
            let span = r.span();
            let n = ((span / TAU) * 720.0).ceil().max(8.0) as usize;
            let inside = |x: f64| x >= r.from && x <= r.to;
            let mut f = |x: f64| -> f64 {
                if !map.full_turn() && !inside(x) {
                    return f64::NAN;
                }
                match m.solve(x, &mut sol) {
                    Ok(()) => output.read(&sol, 0.0).v / w,
                    Err(_) => f64::NAN,
                }
            };
            let dead: Vec<f64> = if map.full_turn() {
                periodic_roots(0.0, 1.0, 720, &mut f)
            } else {
                // sample the range's own grid, ends included, then one NaN step closes it
                let step = span / n as f64;
                let g = |k: usize| if k == n { r.to } else { r.from + step * k as f64 };
                let vals: Vec<f64> = (0..=n).map(|k| f(g(k))).collect();
                let mut out = Vec::new();
                for k in 0..n {
                    let (a, b) = (vals[k], vals[k + 1]);
                    if a.is_finite() && b.is_finite() && a != 0.0 && b != 0.0 && a.signum() != b.signum() {
                        if let Some(x) = tmm_geom::root::brent(&mut f, g(k), g(k + 1), 1e-13) {
                            out.push(x);
                        }
                    } else if a == 0.0 && k > 0 && vals[k - 1].is_finite() && b.is_finite() && vals[k - 1].signum() != b.signum() {
                        out.push(g(k));
                    }
                }
                out
            };
            // an angle continuous about its value at the range's start
            let reference = match m.solve(r.from, &mut sol) {
                Ok(()) => output.read(&sol, 0.0).s,
                Err(_) => 0.0,
            };
            let mut s_at = |x: f64| -> Option<f64> { m.solve(x, &mut sol).ok().map(|()| output.read(&sol, reference).s) };
            let mut vals: Vec<f64> = dead.iter().filter_map(|&x| s_at(x)).collect();
            if !map.full_turn() {
                vals.extend(s_at(r.from));
                vals.extend(s_at(r.to));
            }
            if vals.is_empty() {
                vals.extend(s_at(r.from));
            }
            let s_min = vals.iter().copied().fold(f64::INFINITY, f64::min);
            let s_max = vals.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            ranges.push(RangeCycle {
                range: *r,
                dead,
                s_min,
                s_max,
            });
        }
        Ok(PartialCycle { output, ranges, map })
    }

    /// `n` equally spaced crank angles over each range, ends included
    /// (n ≥ 2), rad, as (range index, φ).
    pub fn positions(&self, n: usize) -> Vec<(usize, f64)> {
        let n = n.max(2);
        let mut out = Vec::new();
        for (i, r) in self.ranges.iter().enumerate() {
            for k in 0..n {
                let phi = r.range.from + r.range.span() * k as f64 / (n - 1) as f64;
                out.push((i, phi));
            }
        }
        out
    }
}
