//! A table of values interpolated over its abscissa (интерполяция таблицы):
//! piecewise linear (Mathcad `linterp`), or a cubic spline (кубический
//! сплайн) with natural ends (S″ = 0 at both ends, Mathcad `lspline`) or
//! not-a-knot ends (S‴ continuous at the second and the last-but-one node,
//! which reproduces Mathcad `cspline` in the textbook's П2 — Chernaya &
//! Timofeev 2019, the П2 indicator diagram; de Boor, *A Practical Guide to
//! Splines*, 1978, ch. IV for the end conditions).
//!
//! The spline is stored as its second derivatives Mᵢ at the nodes, found
//! once when the table is built; between nodes xᵢ, xᵢ₊₁ (h = xᵢ₊₁ − xᵢ,
//! t = x − xᵢ, u = xᵢ₊₁ − x) it is
//! S = (Mᵢ·u³ + Mᵢ₊₁·t³)/(6h) + (yᵢ/h − Mᵢ·h/6)·u + (yᵢ₊₁/h − Mᵢ₊₁·h/6)·t
//! (Press et al., *Numerical Recipes*, 3rd ed., §3.3, eq. 3.3.3), and the
//! interior equations are hᵢ₋₁Mᵢ₋₁ + 2(hᵢ₋₁ + hᵢ)Mᵢ + hᵢMᵢ₊₁ = 6(dᵢ − dᵢ₋₁),
//! dᵢ = (yᵢ₊₁ − yᵢ)/hᵢ (ibid., eq. 3.3.7, multiplied by 6). Evaluation
//! allocates nothing; outside the table the end values are held.

use super::error::ForceError;

/// How a table is interpolated.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Interpolation {
    /// Piecewise linear (Mathcad `linterp`).
    Linear,
    /// Cubic spline, S″ = 0 at both ends (Mathcad `lspline`).
    Natural,
    /// Cubic spline with not-a-knot ends (reproduces Mathcad `cspline`).
    NotAKnot,
}

/// A table y(x) with its interpolation, ready to evaluate.
#[derive(Debug, Clone, PartialEq)]
pub struct Curve {
    /// The abscissae, strictly increasing.
    pub x: Vec<f64>,
    /// The values.
    pub y: Vec<f64>,
    /// Second derivatives at the nodes (all zero for a linear table).
    m: Vec<f64>,
    /// How it is interpolated.
    pub interpolation: Interpolation,
}

impl Curve {
    /// Build from points `(x, y)`; `field` names the table in messages.
    /// The abscissae must increase; a spline needs at least 3 points (with
    /// 3 the not-a-knot spline is the parabola through them), a line 2.
    ///
    /// ```
    /// use tmm_linkage::forces::spline::{Curve, Interpolation};
    /// // a not-a-knot spline reproduces any cubic from four points or more
    /// let f = |x: f64| 1.0 - 2.0 * x + 0.5 * x * x * x;
    /// let pts: Vec<(f64, f64)> = [0.0, 0.3, 1.0, 1.5, 2.0].iter().map(|&x| (x, f(x))).collect();
    /// let c = Curve::new(&pts, Interpolation::NotAKnot, "t").unwrap();
    /// assert!((c.eval(1.23) - f(1.23)).abs() < 1e-12);
    /// ```
    pub fn new(points: &[(f64, f64)], interpolation: Interpolation, field: &str) -> Result<Self, ForceError> {
        let need = if interpolation == Interpolation::Linear { 2 } else { 3 };
        if points.len() < need {
            return Err(ForceError::load(
                field,
                format!(
                    "a {} table needs at least {need} points, not {}",
                    match interpolation {
                        Interpolation::Linear => "linear",
                        _ => "spline",
                    },
                    points.len()
                ),
            ));
        }
        for (i, &(x, y)) in points.iter().enumerate() {
            if !(x.is_finite() && y.is_finite()) {
                return Err(ForceError::load(format!("{field}[{i}]"), "must be finite"));
            }
            if i > 0 && x <= points[i - 1].0 {
                return Err(ForceError::load(
                    format!("{field}[{i}]"),
                    format!("the travel must increase from point to point: {x} after {}", points[i - 1].0),
                ));
            }
        }
        let x: Vec<f64> = points.iter().map(|p| p.0).collect();
        let y: Vec<f64> = points.iter().map(|p| p.1).collect();
        let m = match interpolation {
            Interpolation::Linear => vec![0.0; x.len()],
            Interpolation::Natural | Interpolation::NotAKnot => second_derivatives(&x, &y, interpolation),
        };
        if m.iter().any(|v| !v.is_finite()) {
            return Err(ForceError::load(field, "the spline through these points is not finite"));
        }
        Ok(Curve { x, y, m, interpolation })
    }

    /// The first abscissa.
    pub fn first(&self) -> f64 {
        self.x[0]
    }

    /// The last abscissa.
    pub fn last(&self) -> f64 {
        self.x[self.x.len() - 1]
    }

    /// The value at `x` (the end values beyond the table). Allocates nothing.
    #[inline]
    pub fn eval(&self, x: f64) -> f64 {
        let n = self.x.len();
        if x <= self.x[0] {
            return self.y[0];
        }
        if x >= self.x[n - 1] {
            return self.y[n - 1];
        }
        // tables are short: a linear scan
        let mut i = 1;
        while self.x[i] < x {
            i += 1;
        }
        let (x0, x1, y0, y1) = (self.x[i - 1], self.x[i], self.y[i - 1], self.y[i]);
        let h = x1 - x0;
        let (t, u) = (x - x0, x1 - x);
        if self.interpolation == Interpolation::Linear {
            return y0 + (y1 - y0) * t / h;
        }
        let (m0, m1) = (self.m[i - 1], self.m[i]);
        (m0 * u * u * u + m1 * t * t * t) / (6.0 * h) + (y0 / h - m0 * h / 6.0) * u + (y1 / h - m1 * h / 6.0) * t
    }

    /// The second derivative S″ at node `i` (zero for a linear table).
    pub fn node_second_derivative(&self, i: usize) -> f64 {
        self.m[i]
    }
}

/// The spline's second derivatives at the nodes: the interior equations
/// (Numerical Recipes eq. 3.3.7) and two end rows — Mᵢ = 0 at the ends
/// (natural), or S‴ equal on both sides of x₁ and of xₙ₋₂:
/// (M₁ − M₀)/h₀ = (M₂ − M₁)/h₁ (not-a-knot; de Boor 1978, ch. IV). With
/// three points the not-a-knot rows make M constant: the parabola. Solved
/// by Gaussian elimination with partial pivoting (the tables have a few
/// dozen points, once per run).
fn second_derivatives(x: &[f64], y: &[f64], kind: Interpolation) -> Vec<f64> {
    let n = x.len();
    let h: Vec<f64> = (0..n - 1).map(|i| x[i + 1] - x[i]).collect();
    let d: Vec<f64> = (0..n - 1).map(|i| (y[i + 1] - y[i]) / h[i]).collect();
    let mut a = vec![vec![0.0; n + 1]; n];
    for i in 1..n - 1 {
        a[i][i - 1] = h[i - 1];
        a[i][i] = 2.0 * (h[i - 1] + h[i]);
        a[i][i + 1] = h[i];
        a[i][n] = 6.0 * (d[i] - d[i - 1]);
    }
    match kind {
        Interpolation::NotAKnot if n >= 4 => {
            // h₁·(M₁ − M₀) − h₀·(M₂ − M₁) = 0, and the same at the other end
            a[0][0] = -h[1];
            a[0][1] = h[0] + h[1];
            a[0][2] = -h[0];
            let (p, q) = (h[n - 3], h[n - 2]);
            a[n - 1][n - 3] = -q;
            a[n - 1][n - 2] = p + q;
            a[n - 1][n - 1] = -p;
        }
        Interpolation::NotAKnot => {
            // three points: one parabola, M₀ = M₁ = M₂
            a[0][0] = 1.0;
            a[0][1] = -1.0;
            a[n - 1][n - 2] = -1.0;
            a[n - 1][n - 1] = 1.0;
        }
        _ => {
            a[0][0] = 1.0;
            a[n - 1][n - 1] = 1.0;
        }
    }
    solve_dense(&mut a)
}

/// Solve the augmented system `a` (n rows, n + 1 columns) in place.
fn solve_dense(a: &mut [Vec<f64>]) -> Vec<f64> {
    let n = a.len();
    for c in 0..n {
        let p = (c..n).max_by(|&i, &j| a[i][c].abs().total_cmp(&a[j][c].abs())).unwrap_or(c);
        a.swap(c, p);
        let piv = a[c][c];
        if piv == 0.0 {
            return vec![f64::NAN; n];
        }
        let (top, rest) = a.split_at_mut(c + 1);
        let pivot_row = &top[c];
        for row in rest.iter_mut() {
            let f = row[c] / piv;
            if f != 0.0 {
                for (x, p) in row[c..=n].iter_mut().zip(&pivot_row[c..=n]) {
                    *x -= f * p;
                }
            }
        }
    }
    let mut m = vec![0.0; n];
    for r in (0..n).rev() {
        let mut s = a[r][n];
        for k in r + 1..n {
            s -= a[r][k] * m[k];
        }
        m[r] = s / a[r][r];
    }
    m
}
