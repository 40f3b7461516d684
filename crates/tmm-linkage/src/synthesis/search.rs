//! One-parameter searches used where a free parameter is chosen as an
//! optimum: a grid scan that needs no first guess, then golden-section
//! refinement of the best grid cell (Kiefer 1953; Press et al., Numerical
//! Recipes, § 10.2). Values that are not finite count as infeasible.

/// Maximise `f` over the open interval (a, b): `n` interior grid points, then
/// golden section on the cell around the best one. Returns (x, f(x)) or
/// `None` when no grid point is feasible (finite).
pub fn maximize(mut f: impl FnMut(f64) -> f64, a: f64, b: f64, n: usize) -> Option<(f64, f64)> {
    let n = n.max(3);
    let h = (b - a) / (n + 1) as f64;
    let mut best: Option<(f64, f64)> = None;
    for k in 1..=n {
        let x = a + h * k as f64;
        let v = f(x);
        if v.is_finite() && best.is_none_or(|(_, bv)| v > bv) {
            best = Some((x, v));
        }
    }
    let (x0, v0) = best?;
    let g = |x: f64, f: &mut dyn FnMut(f64) -> f64| {
        let v = f(x);
        if v.is_finite() { v } else { f64::NEG_INFINITY }
    };
    let (mut lo, mut hi) = ((x0 - h).max(a + 1e-3 * h), (x0 + h).min(b - 1e-3 * h));
    let r = 0.5 * (5f64.sqrt() - 1.0);
    let mut c = hi - r * (hi - lo);
    let mut d = lo + r * (hi - lo);
    let mut fc = g(c, &mut f);
    let mut fd = g(d, &mut f);
    for _ in 0..80 {
        if fc > fd {
            hi = d;
            d = c;
            fd = fc;
            c = hi - r * (hi - lo);
            fc = g(c, &mut f);
        } else {
            lo = c;
            c = d;
            fc = fd;
            d = lo + r * (hi - lo);
            fd = g(d, &mut f);
        }
        if hi - lo < 1e-13 * (1.0 + x0.abs()) {
            break;
        }
    }
    let (x1, v1) = if fc > fd { (c, fc) } else { (d, fd) };
    Some(if v1 >= v0 { (x1, v1) } else { (x0, v0) })
}

#[cfg(test)]
mod tests {
    #[test]
    fn finds_the_maximum_of_a_parabola_and_skips_infeasible_points() {
        let (x, v) = super::maximize(|x| if x < 0.2 { f64::NAN } else { -(x - 0.7) * (x - 0.7) }, 0.0, 1.0, 20).unwrap();
        assert!((x - 0.7).abs() < 1e-6 && v.abs() < 1e-12);
        assert!(super::maximize(|_| f64::NAN, 0.0, 1.0, 10).is_none());
    }
}
