//! Extremes of a smooth function on an interval: a uniform scan followed by
//! golden-section refinement around the best sample.
//!
//! Source: golden-section search — Press et al., *Numerical Recipes*, 3rd ed.,
//! §10.2. The scan guards against several local maxima; the refinement makes
//! the result exact to rounding for the smooth pieces of a motion law.

/// The maximum of `f` on `[a, b]`: `(x, f(x))`, from `n + 1` samples and a
/// golden-section refinement of the best one.
///
/// ```
/// let (x, y) = tmm_cams::extreme::maximize(|x: f64| -(x - 0.3).powi(2), 0.0, 1.0, 16);
/// assert!((x - 0.3).abs() < 1e-7 && y.abs() < 1e-14);
/// ```
pub fn maximize(mut f: impl FnMut(f64) -> f64, a: f64, b: f64, n: usize) -> (f64, f64) {
    let n = n.max(2);
    let h = (b - a) / n as f64;
    let (mut bx, mut by) = (a, f(a));
    for i in 1..=n {
        let x = if i == n { b } else { a + h * i as f64 };
        let y = f(x);
        if y > by {
            bx = x;
            by = y;
        }
    }
    // golden section on [bx − h, bx + h] ∩ [a, b]
    let (mut lo, mut hi) = ((bx - h).max(a), (bx + h).min(b));
    let g = 0.5 * (5f64.sqrt() - 1.0);
    let mut x1 = hi - g * (hi - lo);
    let mut x2 = lo + g * (hi - lo);
    let (mut f1, mut f2) = (f(x1), f(x2));
    for _ in 0..80 {
        if hi - lo <= 1e-13 * (1.0 + a.abs().max(b.abs())) {
            break;
        }
        if f1 >= f2 {
            hi = x2;
            x2 = x1;
            f2 = f1;
            x1 = hi - g * (hi - lo);
            f1 = f(x1);
        } else {
            lo = x1;
            x1 = x2;
            f1 = f2;
            x2 = lo + g * (hi - lo);
            f2 = f(x2);
        }
    }
    for (x, y) in [(x1, f1), (x2, f2)] {
        if y > by {
            bx = x;
            by = y;
        }
    }
    (bx, by)
}

/// The minimum of `f` on `[a, b]`, as [`maximize`] of `−f`.
///
/// ```
/// let (x, y) = tmm_cams::extreme::minimize(|x: f64| (x - 2.0).powi(2) + 1.0, 0.0, 5.0, 10);
/// assert!((x - 2.0).abs() < 1e-7 && (y - 1.0).abs() < 1e-14);
/// ```
pub fn minimize(mut f: impl FnMut(f64) -> f64, a: f64, b: f64, n: usize) -> (f64, f64) {
    let (x, y) = maximize(|x| -f(x), a, b, n);
    (x, -y)
}
