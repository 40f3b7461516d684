//! Piecewise acceleration analogs integrated in closed form: the engine behind
//! the laws drawn as an acceleration diagram (constant acceleration,
//! linearly decreasing, trapezoid, modified trapezoid, modified sine) and the
//! user's acceleration table.
//!
//! On each piece `t = x − x₀ ∈ [0, L]` the acceleration analog is
//! `a(t) = c₀ + c₁·t + A·sin(wt) + B·cos(wt)`; its integrals are exact
//! (derived here, docs/cams.md §2):
//!
//! - `v(t) = v₀ + c₀t + c₁t²/2 + A(1 − cos wt)/w + B·sin(wt)/w`
//! - `y(t) = y₀ + v₀t + c₀t²/2 + c₁t³/6 + A(t/w − sin(wt)/w²) + B(1 − cos wt)/w²`
//! - `j(t) = c₁ + A·w·cos wt − B·w·sin wt`
//!
//! The shape is built with amplitude 1 and then scaled so that `y(1) = 1`.

/// One piece of an acceleration analog (участок диаграммы аналога ускорения).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Piece {
    /// Start of the piece, fraction of the phase.
    pub x0: f64,
    /// Constant term of the acceleration.
    pub c0: f64,
    /// Linear term (per unit of phase fraction).
    pub c1: f64,
    /// Sine amplitude.
    pub a: f64,
    /// Cosine amplitude.
    pub b: f64,
    /// Circular frequency of the sine/cosine terms (per unit of phase fraction).
    pub w: f64,
    v0: f64,
    y0: f64,
}

impl Piece {
    /// A piece starting at `x0`: `a(t) = c0 + c1·t + a·sin(wt) + b·cos(wt)`.
    pub const fn new(x0: f64, c0: f64, c1: f64, a: f64, b: f64, w: f64) -> Self {
        Piece {
            x0,
            c0,
            c1,
            a,
            b,
            w,
            v0: 0.0,
            y0: 0.0,
        }
    }
    /// A piece with a linear acceleration `c0 + c1·t`.
    pub const fn linear(x0: f64, c0: f64, c1: f64) -> Self {
        Piece::new(x0, c0, c1, 0.0, 0.0, 0.0)
    }

    /// `[y, v, a, j]` at `t` from the piece start (unscaled).
    #[inline]
    fn eval(&self, t: f64) -> [f64; 4] {
        let (c0, c1) = (self.c0, self.c1);
        let mut y = self.y0 + self.v0 * t + c0 * t * t / 2.0 + c1 * t * t * t / 6.0;
        let mut v = self.v0 + c0 * t + c1 * t * t / 2.0;
        let mut a = c0 + c1 * t;
        let mut j = c1;
        if self.w != 0.0 {
            let w = self.w;
            let (s, c) = (w * t).sin_cos();
            y += self.a * (t / w - s / (w * w)) + self.b * (1.0 - c) / (w * w);
            v += self.a * (1.0 - c) / w + self.b * s / w;
            a += self.a * s + self.b * c;
            j += self.a * w * c - self.b * w * s;
        }
        [y, v, a, j]
    }
}

/// A whole normalized law made of pieces: `y(0) = 0`, `y(1) = 1`.
#[derive(Debug, Clone, PartialEq)]
pub struct Pieces {
    pieces: Vec<Piece>,
    scale: f64,
}

/// Why a piecewise shape cannot be a rise law.
#[derive(Debug, Clone, PartialEq)]
pub enum ShapeError {
    /// The velocity analog at the end of the phase is not zero: the areas of
    /// the positive and the negative acceleration differ.
    Unbalanced {
        /// ∫a over the phase divided by ∫|a|.
        ratio: f64,
    },
    /// The shape gives no net displacement (or a negative one).
    NoRise,
}

impl Pieces {
    /// Integrate the pieces (sorted by `x0`, the first at 0) and scale to
    /// `y(1) = 1`. The velocity at `x = 1` must vanish to a relative `tol`.
    pub fn new(mut pieces: Vec<Piece>, tol: f64) -> Result<Self, ShapeError> {
        let (mut y, mut v) = (0.0, 0.0);
        let mut abs_area = 0.0;
        let n = pieces.len();
        for i in 0..n {
            pieces[i].y0 = y;
            pieces[i].v0 = v;
            let end = if i + 1 < n { pieces[i + 1].x0 } else { 1.0 };
            let len = end - pieces[i].x0;
            let [y1, v1, ..] = pieces[i].eval(len);
            // ∫|a| by a fine midpoint sum (only to judge the balance)
            let m = 64;
            for k in 0..m {
                abs_area += pieces[i].eval(len * (k as f64 + 0.5) / m as f64)[2].abs() * len / m as f64;
            }
            y = y1;
            v = v1;
        }
        if abs_area > 0.0 && (v / abs_area).abs() > tol {
            return Err(ShapeError::Unbalanced { ratio: v / abs_area });
        }
        if !(y.is_finite() && y > 0.0) {
            return Err(ShapeError::NoRise);
        }
        Ok(Pieces { pieces, scale: 1.0 / y })
    }

    /// `[y, y′, y″, y‴]` at the phase fraction `x ∈ [0, 1]`.
    #[inline]
    pub fn eval(&self, x: f64) -> [f64; 4] {
        // the last piece starting at or before x (the first for x < 0 or NaN);
        // a binary search: a table law has one piece per value
        let k = self.pieces.partition_point(|p| p.x0 <= x).max(1) - 1;
        let p = &self.pieces[k];
        let r = p.eval(x - p.x0);
        [r[0] * self.scale, r[1] * self.scale, r[2] * self.scale, r[3] * self.scale]
    }

    /// `[y, y′, y″, y‴]` just before `x` (the left-hand limit): at a piece
    /// boundary the piece that ends there.
    #[inline]
    pub fn eval_left(&self, x: f64) -> [f64; 4] {
        let k = self.pieces.partition_point(|p| p.x0 < x).max(1) - 1;
        let p = &self.pieces[k];
        let r = p.eval(x - p.x0);
        [r[0] * self.scale, r[1] * self.scale, r[2] * self.scale, r[3] * self.scale]
    }

    /// The pieces' start fractions (where acceleration or jerk may jump).
    pub fn breaks(&self) -> impl Iterator<Item = f64> + '_ {
        self.pieces.iter().map(|p| p.x0)
    }
}
