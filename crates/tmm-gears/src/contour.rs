//! The blocking contour (блокирующий контур) of a pair in the x1–x2 plane,
//! computed numerically for any tooth numbers and basic rack: the region where
//! the teeth are neither undercut nor pointed, the pair has no interference and
//! εα ≥ 1, with the quality lines (sa = 0.3m, 0.4m, εα = 1.2, equal specific
//! sliding) inside it.
//!
//! Method (derived here, docs/gears.md §Blocking contour): every boundary is
//! the zero set of a function of (x1, x2) evaluated through [`Pair::compute`];
//! a grid of n × n nodes is evaluated once, each boundary is traced by marching
//! squares, every crossing is refined on its cell edge by Brent's method to
//! 1e-10, and the segments are chained into polylines.

use std::collections::HashMap;

use tmm_geom::root::brent;

use crate::spec::{lone_tip_thickness, xmin};
use crate::{GearError, Kind, Pair, PairSpec};

/// One boundary or quality line of the contour, as the zero set of
/// [`Boundary::value`] (positive on the allowed side).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Boundary {
    /// Undercut of wheel i: `ρl_i = 0`, i.e. `x_i − xmin_i = 0`.
    Undercut(u8),
    /// Interference at wheel i: `ρp_i − max(ρl_i, 0) = 0` (ring: `ρl2 − ρp2 = 0`).
    Interference(u8),
    /// Tip thickness of wheel i equal to `k·m` (`k = 0`: the pointed tip).
    TipThickness(u8, f64),
    /// Contact ratio equal to the value.
    ContactRatio(f64),
    /// Equal extreme specific sliding, ϑ1max = ϑ2max.
    EqualSliding,
    /// Tip interference of an internal pair (margin = 0).
    TipInterference,
}

impl Boundary {
    /// The defining function at a computed pair, in modules or plain numbers;
    /// zero on the boundary, positive on the allowed side; NaN where undefined.
    pub fn value(&self, p: &Pair) -> f64 {
        let m = p.spec.m;
        let w = |i: u8| if i == 1 { &p.w1 } else { &p.w2 };
        match *self {
            Boundary::Undercut(i) => w(i).xmin.map_or(f64::NAN, |xm| w(i).x - xm),
            Boundary::Interference(i) => {
                let wh = w(i);
                if i == 2 && p.spec.kind == Kind::Internal {
                    (wh.rho_l - wh.rho_p) / m
                } else {
                    (wh.rho_p - wh.rho_l.max(0.0)) / m
                }
            }
            Boundary::TipThickness(i, k) => w(i).sa / m - k,
            Boundary::ContactRatio(e) => p.eps_alpha - e,
            Boundary::EqualSliding => {
                // ϑ1(A) = 1 − ρ2A/(u ρ1A), ϑ2(B) = 1 − u ρ1B/ρ2B: equal magnitudes when
                // ρ2A/(u ρ1A) = u ρ1B/ρ2B (both extremes are negative inside the contour).
                let (sa, sb) = (p.s_start, p.s_end);
                let r2a = p.rho2_at(sa);
                let r2b = p.rho2_at(sb);
                if sa <= 0.0 || r2b <= 0.0 {
                    f64::NAN
                } else {
                    u_ratio(r2a / (p.u * sa)) - u_ratio(p.u * sb / r2b)
                }
            }
            Boundary::TipInterference => p.tip_interference.unwrap_or(f64::NAN),
        }
    }

    /// `true` for the boundaries that close the contour (the rest are quality
    /// lines drawn inside it).
    pub fn is_blocking(&self) -> bool {
        match *self {
            Boundary::Undercut(_) | Boundary::Interference(_) | Boundary::TipInterference => true,
            Boundary::TipThickness(_, k) => k == 0.0,
            Boundary::ContactRatio(e) => e == 1.0,
            Boundary::EqualSliding => false,
        }
    }

    /// A stable key for JSON.
    pub fn key(&self) -> String {
        match *self {
            Boundary::Undercut(i) => format!("undercut{i}"),
            Boundary::Interference(i) => format!("interference{i}"),
            Boundary::TipThickness(i, k) => format!("sa{i}={k}m"),
            Boundary::ContactRatio(e) => format!("eps_alpha={e}"),
            Boundary::EqualSliding => "equal_sliding".into(),
            Boundary::TipInterference => "tip_interference".into(),
        }
    }

    /// A label for the drawing.
    pub fn label(&self) -> String {
        match *self {
            Boundary::Undercut(i) => format!("undercut {i}"),
            Boundary::Interference(i) => format!("interference {i}"),
            Boundary::TipThickness(i, 0.0) => format!("sa{i} = 0"),
            Boundary::TipThickness(i, k) => format!("sa{i} = {k}m"),
            Boundary::ContactRatio(e) => format!("εα = {e}"),
            Boundary::EqualSliding => "ϑ1max = ϑ2max".into(),
            Boundary::TipInterference => "tip interference".into(),
        }
    }
}

/// Log of a ratio keeps the equal-sliding function well scaled near N1, N2.
#[inline]
fn u_ratio(v: f64) -> f64 {
    if v > 0.0 { v.ln() } else { f64::NAN }
}

/// The spec with other shifts.
#[inline]
pub fn with_shifts(base: &PairSpec, x1: f64, x2: f64) -> PairSpec {
    PairSpec { x1, x2, ..*base }
}

/// A boundary's defining function at (x1, x2); NaN where the pair cannot be computed.
pub fn value_at(base: &PairSpec, b: Boundary, x1: f64, x2: f64) -> f64 {
    Pair::compute(&with_shifts(base, x1, x2)).map_or(f64::NAN, |p| b.value(&p))
}

/// The x range of the plot (and of the search for x1, x2) for one wheel: from
/// below the undercut limit to just past a lone tooth's pointing, clamped to
/// [−2, 3].
pub fn default_range(z: u32, base: &PairSpec, ring: bool) -> (f64, f64) {
    if ring {
        return (-0.5, 1.5);
    }
    let r = &base.rack;
    let xm = xmin(z, r);
    // Bracket the pointing shift from max(xmin, 0): there the tooth of any
    // cuttable z has sa > 0 and its tip circle lies outside the base circle.
    let lo_b = xm.max(0.0);
    let sa = |x: f64| lone_tip_thickness(z, x, r).unwrap_or(-1.0);
    let mut hi_b = lo_b + 4.0;
    while sa(hi_b) > 0.0 && hi_b < lo_b + 1e4 {
        hi_b = lo_b + 2.0 * (hi_b - lo_b);
    }
    let point = if sa(lo_b) > 0.0 {
        brent(sa, lo_b, hi_b, 1e-9).unwrap_or(2.0)
    } else {
        2.0
    };
    let lo = (xm.min(0.0) - 0.5).max(-2.0);
    // tip shortening in a pair delays pointing: leave room past the lone tooth's value
    let hi = (point + 0.6).clamp(lo + 0.5, 3.0);
    (lo, hi)
}

/// Options of the contour computation.
#[derive(Debug, Clone, PartialEq)]
pub struct ContourOptions {
    /// Nodes per side of the grid (≥ 8); 121 is fine for an A4 plot.
    pub n: usize,
    /// x1 range (None: [`default_range`]).
    pub x1: Option<(f64, f64)>,
    /// x2 range.
    pub x2: Option<(f64, f64)>,
    /// Quality lines of tip thickness (fractions of m) drawn inside.
    pub sa_lines: Vec<f64>,
    /// Quality lines of εα drawn inside.
    pub eps_lines: Vec<f64>,
}

impl Default for ContourOptions {
    fn default() -> Self {
        ContourOptions {
            n: 121,
            x1: None,
            x2: None,
            sa_lines: vec![crate::checks::SA_MIN_THROUGH_HARDENED, crate::checks::SA_MIN_CASE_HARDENED],
            eps_lines: vec![1.2],
        }
    }
}

/// One traced line: its boundary and its polylines in (x1, x2).
#[derive(Debug, Clone, PartialEq)]
pub struct Line {
    /// Which boundary.
    pub boundary: Boundary,
    /// Polylines of points (x1, x2).
    pub polylines: Vec<Vec<(f64, f64)>>,
}

/// The computed contour.
#[derive(Debug, Clone, PartialEq)]
pub struct Contour {
    /// The pair's data (the shifts are ignored).
    pub base: PairSpec,
    /// x1 range.
    pub x1: (f64, f64),
    /// x2 range.
    pub x2: (f64, f64),
    /// Nodes per side.
    pub n: usize,
    /// `feasible[j * n + i]`: node (x1_i, x2_j) lies inside the contour.
    pub feasible: Vec<bool>,
    /// The boundaries and quality lines.
    pub lines: Vec<Line>,
}

impl Contour {
    /// The node coordinates (x1_i, x2_j).
    pub fn node(&self, i: usize, j: usize) -> (f64, f64) {
        let h1 = (self.x1.1 - self.x1.0) / (self.n - 1) as f64;
        let h2 = (self.x2.1 - self.x2.0) / (self.n - 1) as f64;
        (self.x1.0 + h1 * i as f64, self.x2.0 + h2 * j as f64)
    }
}

/// The boundaries of a pair's contour in drawing order.
pub fn boundaries(base: &PairSpec, opts: &ContourOptions) -> Vec<Boundary> {
    let internal = base.kind == Kind::Internal;
    let mut v = vec![Boundary::Undercut(1)];
    if !internal {
        v.push(Boundary::Undercut(2));
    }
    v.extend([
        Boundary::Interference(1),
        Boundary::Interference(2),
        Boundary::TipThickness(1, 0.0),
        Boundary::TipThickness(2, 0.0),
        Boundary::ContactRatio(1.0),
    ]);
    if internal {
        v.push(Boundary::TipInterference);
    }
    for &k in &opts.sa_lines {
        v.push(Boundary::TipThickness(1, k));
        v.push(Boundary::TipThickness(2, k));
    }
    for &e in &opts.eps_lines {
        v.push(Boundary::ContactRatio(e));
    }
    v.push(Boundary::EqualSliding);
    v
}

/// Compute the blocking contour of `base` (its shifts are ignored).
///
/// ```
/// use tmm_gears::{PairSpec, contour::{blocking_contour, ContourOptions}};
/// let c = blocking_contour(&PairSpec::external(15, 20, 0.005, 0.0, 0.0), &ContourOptions::default()).unwrap();
/// // Seed 001's point (0.2, 0.85) lies inside the contour.
/// let inside = |x1: f64, x2: f64| {
///     let (i, j) = (((x1 - c.x1.0) / (c.x1.1 - c.x1.0) * (c.n - 1) as f64).round() as usize,
///                   ((x2 - c.x2.0) / (c.x2.1 - c.x2.0) * (c.n - 1) as f64).round() as usize);
///     c.feasible[j * c.n + i]
/// };
/// assert!(inside(0.2, 0.85));
/// assert!(!inside(-0.4, 0.0)); // the pinion would be undercut
/// ```
pub fn blocking_contour(base: &PairSpec, opts: &ContourOptions) -> Result<Contour, GearError> {
    base.validate()?;
    let n = opts.n.clamp(8, 2001);
    let internal = base.kind == Kind::Internal;
    let x1r = opts.x1.unwrap_or_else(|| default_range(base.z1, base, false));
    let x2r = opts.x2.unwrap_or_else(|| default_range(base.z2, base, internal));
    for (lo, hi) in [x1r, x2r] {
        if !(lo.is_finite() && hi.is_finite() && hi > lo) {
            return Err(GearError::NoFeasibleSplit(format!(": the x range [{lo}, {hi}] is empty")));
        }
    }
    let bs = boundaries(base, opts);
    let nb = bs.len();
    let mut vals = vec![f64::NAN; nb * n * n];
    let mut feasible = vec![false; n * n];
    let mut c = Contour {
        base: *base,
        x1: x1r,
        x2: x2r,
        n,
        feasible: Vec::new(),
        lines: Vec::new(),
    };
    for j in 0..n {
        for i in 0..n {
            let (x1, x2) = c.node(i, j);
            if let Ok(p) = Pair::compute(&with_shifts(base, x1, x2)) {
                let mut ok = true;
                for (k, b) in bs.iter().enumerate() {
                    let v = b.value(&p);
                    vals[k * n * n + j * n + i] = v;
                    if b.is_blocking() && (v.is_nan() || v < 0.0) {
                        ok = false;
                    }
                }
                feasible[j * n + i] = ok;
            }
        }
    }
    c.feasible = feasible;
    for (k, b) in bs.iter().enumerate() {
        let polylines = trace(&c, *b, &vals[k * n * n..(k + 1) * n * n]);
        c.lines.push(Line { boundary: *b, polylines });
    }
    Ok(c)
}

/// Marching squares on one boundary's grid values, refined with Brent on the
/// cell edges, chained into polylines.
fn trace(c: &Contour, b: Boundary, v: &[f64]) -> Vec<Vec<(f64, f64)>> {
    let n = c.n;
    let at = |i: usize, j: usize| v[j * n + i];
    // Edge ids: horizontal (i,j)-(i+1,j) = 2(jn+i); vertical (i,j)-(i,j+1) = 2(jn+i)+1.
    let mut points: HashMap<usize, (f64, f64)> = HashMap::new();
    let mut adj: HashMap<usize, Vec<usize>> = HashMap::new();
    let edge_point = |id: usize, pts: &mut HashMap<usize, (f64, f64)>| -> Option<(f64, f64)> {
        if let Some(p) = pts.get(&id) {
            return Some(*p);
        }
        let (i, j) = ((id / 2) % n, (id / 2) / n);
        let (a, bnode) = if id % 2 == 0 { ((i, j), (i + 1, j)) } else { ((i, j), (i, j + 1)) };
        let pa = c.node(a.0, a.1);
        let pb = c.node(bnode.0, bnode.1);
        let f = |t: f64| value_at(&c.base, b, pa.0 + t * (pb.0 - pa.0), pa.1 + t * (pb.1 - pa.1));
        let t = brent(f, 0.0, 1.0, 1e-12)?;
        let p = (pa.0 + t * (pb.0 - pa.0), pa.1 + t * (pb.1 - pa.1));
        pts.insert(id, p);
        Some(p)
    };
    for j in 0..n - 1 {
        for i in 0..n - 1 {
            let q = [at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)];
            if q.iter().any(|x| !x.is_finite()) {
                continue;
            }
            // edges in order: bottom, right, top, left
            let ids = [2 * (j * n + i), 2 * (j * n + i + 1) + 1, 2 * ((j + 1) * n + i), 2 * (j * n + i) + 1];
            let mut cross = [0usize; 4];
            let mut k = 0;
            for e in 0..4 {
                let (va, vb) = (q[e], q[(e + 1) % 4]);
                if (va >= 0.0) != (vb >= 0.0) && edge_point(ids[e], &mut points).is_some() {
                    cross[k] = ids[e];
                    k += 1;
                }
            }
            let mut link = |a: usize, bb: usize| {
                adj.entry(a).or_default().push(bb);
                adj.entry(bb).or_default().push(a);
            };
            if k == 2 {
                link(cross[0], cross[1]);
            } else if k == 4 {
                link(cross[0], cross[1]);
                link(cross[2], cross[3]);
            }
        }
    }
    chain(&adj, &points)
}

/// Chain linked edge points into polylines (open chains first, then loops).
fn chain(adj: &HashMap<usize, Vec<usize>>, points: &HashMap<usize, (f64, f64)>) -> Vec<Vec<(f64, f64)>> {
    let mut keys: Vec<usize> = adj.keys().copied().collect();
    keys.sort_unstable();
    let mut used: HashMap<usize, bool> = HashMap::new();
    let mut out = Vec::new();
    let starts: Vec<usize> = keys
        .iter()
        .copied()
        .filter(|k| adj[k].len() == 1)
        .chain(keys.iter().copied())
        .collect();
    for s in starts {
        if used.contains_key(&s) {
            continue;
        }
        let mut line = vec![points[&s]];
        used.insert(s, true);
        let mut cur = s;
        loop {
            let next = adj[&cur].iter().copied().find(|e| !used.contains_key(e));
            match next {
                Some(e) => {
                    used.insert(e, true);
                    line.push(points[&e]);
                    cur = e;
                }
                None => {
                    // close a loop
                    if adj[&cur].contains(&s) && line.len() > 2 {
                        line.push(points[&s]);
                    }
                    break;
                }
            }
        }
        if line.len() >= 2 {
            out.push(line);
        }
    }
    out
}
