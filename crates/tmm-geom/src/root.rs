//! Scalar root finding: Brent's method on a bracket, and a scan that finds
//! brackets of sign changes on a grid.
//!
//! Source: R. P. Brent, *Algorithms for Minimization without Derivatives*
//! (1973), ch. 4 — the `zero` procedure, transcribed.

/// Find `x ∈ [a, b]` with `f(x) = 0` given `f(a)·f(b) ≤ 0`, to absolute
/// tolerance `tol` on `x`. Returns `None` when the bracket holds no sign change
/// or a value is not finite.
///
/// ```
/// let r = tmm_geom::root::brent(|x| x * x - 2.0, 0.0, 2.0, 1e-14).unwrap();
/// assert!((r - 2f64.sqrt()).abs() < 1e-13);
/// ```
pub fn brent(mut f: impl FnMut(f64) -> f64, a: f64, b: f64, tol: f64) -> Option<f64> {
    let (mut a, mut b) = (a, b);
    let (mut fa, mut fb) = (f(a), f(b));
    if !fa.is_finite() || !fb.is_finite() {
        return None;
    }
    if fa == 0.0 {
        return Some(a);
    }
    if fb == 0.0 {
        return Some(b);
    }
    if fa.signum() == fb.signum() {
        return None;
    }
    let (mut c, mut fc) = (a, fa);
    let mut d = b - a;
    let mut e = d;
    for _ in 0..200 {
        if fb.signum() == fc.signum() {
            c = a;
            fc = fa;
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            a = b;
            b = c;
            c = a;
            fa = fb;
            fb = fc;
            fc = fa;
        }
        let tol1 = 2.0 * f64::EPSILON * b.abs() + 0.5 * tol;
        let m = 0.5 * (c - b);
        if m.abs() <= tol1 || fb == 0.0 {
            return Some(b);
        }
        if e.abs() >= tol1 && fa.abs() > fb.abs() {
            let s = fb / fa;
            let (mut p, mut q);
            if a == c {
                p = 2.0 * m * s;
                q = 1.0 - s;
            } else {
                let qq = fa / fc;
                let r = fb / fc;
                p = s * (2.0 * m * qq * (qq - r) - (b - a) * (r - 1.0));
                q = (qq - 1.0) * (r - 1.0) * (s - 1.0);
            }
            if p > 0.0 {
                q = -q;
            } else {
                p = -p;
            }
            if 2.0 * p < (3.0 * m * q - (tol1 * q).abs()).min((e * q).abs()) {
                e = d;
                d = p / q;
            } else {
                d = m;
                e = m;
            }
        } else {
            d = m;
            e = m;
        }
        a = b;
        fa = fb;
        b += if d.abs() > tol1 { d } else { tol1.copysign(m) };
        fb = f(b);
        if !fb.is_finite() {
            return None;
        }
    }
    Some(b)
}

/// Scan `[a, b]` in `n` equal steps and return every sub-interval on which
/// `f` changes sign (both ends finite), refined by [`brent`] to `tol`.
///
/// ```
/// let roots = tmm_geom::root::all_roots(|x: f64| x.sin(), 0.5, 10.0, 100, 1e-13);
/// assert_eq!(roots.len(), 3);
/// assert!((roots[0] - std::f64::consts::PI).abs() < 1e-12);
/// ```
pub fn all_roots(mut f: impl FnMut(f64) -> f64, a: f64, b: f64, n: usize, tol: f64) -> Vec<f64> {
    let n = n.max(1);
    let h = (b - a) / n as f64;
    let mut out = Vec::new();
    let mut x0 = a;
    let mut f0 = f(x0);
    for i in 1..=n {
        let x1 = if i == n { b } else { a + h * i as f64 };
        let f1 = f(x1);
        if f0.is_finite() && f1.is_finite() {
            if f0 == 0.0 {
                if out.last().is_none_or(|&l: &f64| (l - x0).abs() > tol) {
                    out.push(x0);
                }
            } else if f0.signum() != f1.signum() && f1 != 0.0 {
                if let Some(r) = brent(&mut f, x0, x1, tol) {
                    out.push(r);
                }
            }
        }
        x0 = x1;
        f0 = f1;
    }
    if f0 == 0.0 && out.last().is_none_or(|&l: &f64| (l - x0).abs() > tol) {
        out.push(x0);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn brent_cubic() {
        // x^3 - x - 2 has its single real root at 1.5213797068045676 (Cardano).
        let cardano = {
            let q: f64 = 2.0;
            let p: f64 = -1.0;
            let d = (q * q / 4.0 + p * p * p / 27.0).sqrt();
            (q / 2.0 + d).cbrt() + (q / 2.0 - d).cbrt()
        };
        let r = brent(|x| x * x * x - x - 2.0, 1.0, 2.0, 1e-15).unwrap();
        assert!((r - cardano).abs() < 1e-14);
    }

    #[test]
    fn brent_no_bracket() {
        assert!(brent(|x| x * x + 1.0, -1.0, 1.0, 1e-12).is_none());
    }
}
