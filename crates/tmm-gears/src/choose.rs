//! Choosing x1, x2 by a named criterion (выбор коэффициентов смещения),
//! always inside the blocking contour with every check passing.

use tmm_geom::root::{all_roots, brent};

use crate::contour::{Boundary, default_range, value_at, with_shifts};
use crate::{GearError, Kind, Limits, Pair, PairSpec};

/// How to pick the shifts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Criterion {
    /// Equal extreme specific sliding ϑ1max = ϑ2max, with the least sliding.
    EqualSliding,
    /// The largest contact ratio εα.
    MaxContactRatio,
    /// The DIN 3992 split of the sum (balanced sliding and strength).
    Balanced,
}

impl Criterion {
    /// The name used on the command line and in task files.
    pub fn name(&self) -> &'static str {
        match self {
            Criterion::EqualSliding => "equal-sliding",
            Criterion::MaxContactRatio => "max-contact-ratio",
            Criterion::Balanced => "balanced",
        }
    }

    /// Parse a criterion name.
    pub fn parse(s: &str) -> Option<Criterion> {
        match s.trim() {
            "equal-sliding" => Some(Criterion::EqualSliding),
            "max-contact-ratio" => Some(Criterion::MaxContactRatio),
            "balanced" => Some(Criterion::Balanced),
            _ => None,
        }
    }

    /// Why this criterion is the default.
    pub const DEFAULT_REASON: &'static str = "no criterion given: equal-sliding was used — equal extreme specific sliding of the two wheels evens out their wear and the risk of scoring, the usual criterion of the course project (seed 003 §14), and of the points on that line the one with the least sliding where every check passes";
}

/// The chosen shifts and the pair they give.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Choice {
    /// The criterion used.
    pub criterion: Criterion,
    /// The computed pair (every check passes).
    pub pair: Pair,
}

/// The DIN 3992 split of a shift sum: `x1 = xΣ/2 + (0.5 − xΣ/2)·lg u / lg(z1 z2 / 100)`
/// (DIN 3992:1964, eq. for the split lines; also Maitra G.M., Handbook of Gear
/// Design, 1994, §1). The log ratio is clamped to [0, 1] (it is undefined for
/// z1·z2 ≤ 100).
///
/// ```
/// // Equal wheels split the sum equally.
/// assert!((tmm_gears::choose::din_split(20, 20, 0.6) - 0.3).abs() < 1e-15);
/// ```
pub fn din_split(z1: u32, z2: u32, x_sum: f64) -> f64 {
    let u = z2 as f64 / z1 as f64;
    let zz = z1 as f64 * z2 as f64 / 100.0;
    let ratio = if zz > 1.0 { (u.log10() / zz.log10()).clamp(0.0, 1.0) } else { 1.0 };
    x_sum / 2.0 + (0.5 - x_sum / 2.0) * ratio
}

fn ok_pair(base: &PairSpec, x1: f64, x2: f64, lim: &Limits) -> Option<Pair> {
    let p = Pair::compute(&with_shifts(base, x1, x2)).ok()?;
    (p.checks(lim).all_pass() && p.theta1_max().is_some() && p.theta2_max().is_some()).then_some(p)
}

/// x2 from x1 on the line of a fixed shift sum.
#[inline]
fn x2_on_line(kind: Kind, xs: f64, x1: f64) -> f64 {
    match kind {
        Kind::External => xs - x1,
        Kind::Internal => xs + x1,
    }
}

fn sliding(p: &Pair) -> f64 {
    p.theta1_max().unwrap_or(f64::INFINITY).max(p.theta2_max().unwrap_or(f64::INFINITY))
}

/// Pick x1, x2 for `base` (its shifts are ignored) by `crit`; with `x_sum`
/// (from a required centre distance) the point stays on that sum's line.
///
/// ```
/// use tmm_gears::{PairSpec, Limits, choose::{choose, Criterion}};
/// let c = choose(&PairSpec::external(16, 20, 0.030, 0.0, 0.0), Criterion::EqualSliding, None, &Limits::default()).unwrap();
/// let p = c.pair;
/// assert!((p.theta1_max().unwrap() - p.theta2_max().unwrap()).abs() < 1e-6);
/// assert!(p.eps_alpha >= 1.2);
/// ```
pub fn choose(base: &PairSpec, crit: Criterion, x_sum: Option<f64>, lim: &Limits) -> Result<Choice, GearError> {
    base.validate()?;
    let kind = base.kind;
    let (lo1, hi1) = default_range(base.z1, base, false);
    let (lo2, hi2) = default_range(base.z2, base, kind == Kind::Internal);
    let done = |p: Option<Pair>| p.map(|pair| Choice { criterion: crit, pair });
    let fail = |why: &str| GearError::NoFeasibleSplit(format!(" ({}){why}", crit.name()));
    let nline = 600;
    if let Some(xs) = x_sum {
        if !xs.is_finite() {
            return Err(fail(": the shift sum is not finite"));
        }
        let along = |i: usize| lo1 + (hi1 - lo1) * i as f64 / nline as f64;
        let result = match crit {
            Criterion::EqualSliding => {
                let f = |x1: f64| value_at(base, Boundary::EqualSliding, x1, x2_on_line(kind, xs, x1));
                let roots = all_roots(f, lo1, hi1, nline, 1e-12);
                roots
                    .iter()
                    .filter_map(|&x1| ok_pair(base, x1, x2_on_line(kind, xs, x1), lim))
                    .min_by(|a, b| sliding(a).total_cmp(&sliding(b)))
            }
            Criterion::MaxContactRatio => {
                let best = (0..=nline)
                    .filter_map(|i| ok_pair(base, along(i), x2_on_line(kind, xs, along(i)), lim))
                    .max_by(|a, b| a.eps_alpha.total_cmp(&b.eps_alpha));
                best.map(|p| {
                    refine_1d(
                        base,
                        lim,
                        p,
                        (hi1 - lo1) / nline as f64,
                        |x1| (x1, x2_on_line(kind, xs, x1)),
                        |p| p.eps_alpha,
                    )
                })
            }
            Criterion::Balanced => {
                let x1 = din_split(base.z1, base.z2, xs);
                ok_pair(base, x1, x2_on_line(kind, xs, x1), lim).or_else(|| {
                    // the nearest feasible point on the line
                    (0..=nline)
                        .filter_map(|i| ok_pair(base, along(i), x2_on_line(kind, xs, along(i)), lim))
                        .min_by(|a, b| (a.w1.x - x1).abs().total_cmp(&(b.w1.x - x1).abs()))
                })
            }
        };
        return done(result).ok_or_else(|| {
            fail(&format!(
                " on the line of the shift sum {xs:.4}; change the centre distance or relax the limits"
            ))
        });
    }
    let result = match crit {
        Criterion::EqualSliding => {
            let mut best: Option<Pair> = None;
            for i in 0..=nline {
                let x1 = lo1 + (hi1 - lo1) * i as f64 / nline as f64;
                let f = |x2: f64| value_at(base, Boundary::EqualSliding, x1, x2);
                for x2 in all_roots(f, lo2, hi2, 80, 1e-12) {
                    if let Some(p) = ok_pair(base, x1, x2, lim)
                        && best.is_none_or(|b| sliding(&p) < sliding(&b))
                    {
                        best = Some(p);
                    }
                }
            }
            best
        }
        Criterion::MaxContactRatio => {
            let ng = 160;
            let mut best: Option<Pair> = None;
            for j in 0..=ng {
                for i in 0..=ng {
                    let x1 = lo1 + (hi1 - lo1) * i as f64 / ng as f64;
                    let x2 = lo2 + (hi2 - lo2) * j as f64 / ng as f64;
                    if let Some(p) = ok_pair(base, x1, x2, lim)
                        && best.is_none_or(|b| p.eps_alpha > b.eps_alpha)
                    {
                        best = Some(p);
                    }
                }
            }
            best.map(|p| refine_2d(base, lim, p, ((hi1 - lo1) / ng as f64, (hi2 - lo2) / ng as f64)))
        }
        Criterion::Balanced => {
            // The DIN split of the smallest non-negative sum (on a 0.01 grid) whose split passes every check.
            (0..=300).find_map(|k| {
                let xs = k as f64 * 0.01;
                let x1 = din_split(base.z1, base.z2, xs);
                ok_pair(base, x1, x2_on_line(kind, xs, x1), lim)
            })
        }
    };
    done(result).ok_or_else(|| fail(": relax --sa-min or --eps-min, or change the tooth numbers"))
}

/// Golden-section refinement of a 1-D maximum around a feasible start.
fn refine_1d(base: &PairSpec, lim: &Limits, start: Pair, h: f64, xy: impl Fn(f64) -> (f64, f64), obj: impl Fn(&Pair) -> f64) -> Pair {
    let mut best = start;
    let mut step = h;
    for _ in 0..40 {
        let x = best.w1.x;
        let mut moved = false;
        for cand in [x - step, x + step] {
            let (a, b) = xy(cand);
            if let Some(p) = ok_pair(base, a, b, lim)
                && obj(&p) > obj(&best)
            {
                best = p;
                moved = true;
            }
        }
        if !moved {
            step *= 0.5;
        }
    }
    best
}

/// Compass search refinement of a 2-D maximum of εα staying feasible.
fn refine_2d(base: &PairSpec, lim: &Limits, start: Pair, h: (f64, f64)) -> Pair {
    let mut best = start;
    let (mut h1, mut h2) = h;
    for _ in 0..60 {
        let (x1, x2) = (best.w1.x, best.w2.x);
        let mut moved = false;
        for (d1, d2) in [
            (h1, 0.0),
            (-h1, 0.0),
            (0.0, h2),
            (0.0, -h2),
            (h1, h2),
            (-h1, -h2),
            (h1, -h2),
            (-h1, h2),
        ] {
            if let Some(p) = ok_pair(base, x1 + d1, x2 + d2, lim)
                && p.eps_alpha > best.eps_alpha
            {
                best = p;
                moved = true;
            }
        }
        if !moved {
            h1 *= 0.5;
            h2 *= 0.5;
        }
    }
    best
}

/// Solve the equal-sliding line for x2 at a given x1 (Brent on the bracket).
pub fn equal_sliding_x2(base: &PairSpec, x1: f64, lo: f64, hi: f64) -> Option<f64> {
    brent(|x2| value_at(base, Boundary::EqualSliding, x1, x2), lo, hi, 1e-13)
}
