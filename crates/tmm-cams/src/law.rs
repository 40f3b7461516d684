//! Motion laws of one rise (закон движения толкателя на фазе), normalized:
//! the phase fraction `x ∈ [0, 1]` maps to the lift fraction `y ∈ [0, 1]`,
//! with `y(0) = 0`, `y(1) = 1`, `y′(0) = y′(1) = 0` (constant velocity alone
//! has `y′ = 1` throughout and jumps at the ends).
//!
//! A phase of angle β and stroke h then has `s = h·y`, `ds/dφ = h·y′/β`,
//! `d²s/dφ² = h·y″/β²`, `d³s/dφ³ = h·y‴/β³`; a return runs the same law as
//! `s = h·(1 − y)`.
//!
//! The course names a law by the shape of its acceleration analog (seed 001:
//! "закон задан диаграммой аналога ускорения"); Norton names the standard
//! double-dwell laws. Both are here, each in closed form.

use crate::CamError;
use crate::segments::{Piece, Pieces, ShapeError};
use std::f64::consts::PI;

/// Which motion law, with its parameters.
#[derive(Debug, Clone, PartialEq)]
pub enum LawKind {
    /// Constant acceleration (равноускоренный / параболический): +a over the
    /// first `u` of the phase, −a·u/(1−u) over the rest; `u = 1/2` is the
    /// symmetric parabolic law.
    ConstAccel {
        /// Fraction of the phase with positive acceleration, `0 < u < 1`.
        u: f64,
    },
    /// Cosine (гармонический, simple harmonic motion).
    Cosine,
    /// Sine (синусоидальный, cycloidal).
    Sine,
    /// Linearly decreasing acceleration (линейно убывающее ускорение): the cubic `3x² − 2x³`.
    LinearDecreasing,
    /// Trapezoidal acceleration (трапецеидальный), ramps of 1/8 of the phase.
    Trapezoid,
    /// Norton's modified trapezoid (sine ramps of 1/8).
    ModTrapezoid,
    /// Norton's modified sine.
    ModSine,
    /// The 3-4-5 polynomial.
    Poly345,
    /// The 4-5-6-7 polynomial.
    Poly4567,
    /// The user's acceleration analog at equal steps over the phase, linear in
    /// between, integrated and scaled to the stroke.
    Table(Vec<f64>),
    /// Constant velocity (равномерное движение, линейный закон): `y = x`,
    /// `y′ = 1`, `y″ = 0` inside the phase. The velocity jumps at both ends,
    /// so the acceleration has impulses there (жёсткий удар, rigid impact;
    /// [`crate::program::Program::jumps`] lists them). The only law here with
    /// `y′(0) = y′(1) = 1` instead of 0.
    ConstVelocity,
    /// The acceleration analog drawn as pieces (участки диаграммы аналога
    /// ускорения), each a constant or a half sine wave of its own amplitude
    /// and length, integrated exactly and scaled to the stroke — the law of
    /// the BMSTU textbook's appendix П6 (Chernaya, Timofeev 2019, p. 149–150):
    /// two half sines of amplitudes a₁, a₂ = ν·a₁ on the rise, two constants
    /// on the return. The pieces are given as a rise law (positive first);
    /// a return phase written with the book's signs is turned by
    /// [`crate::spec::parse_phases`].
    Accel(Vec<AccelPiece>),
}

/// The shape of one piece of an [`LawKind::Accel`] law.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AccelShape {
    /// A constant acceleration analog (прямоугольник).
    Const,
    /// A half wave of a sine, `A·sin(πt/L)` over the piece of length L
    /// (полуволна синусоиды); its area is `2AL/π`.
    Sine,
}

impl AccelShape {
    /// The area of a piece of unit amplitude and unit length: 1 for a
    /// constant, `∫₀¹ sin πt dt = 2/π` for a half sine.
    pub fn area_factor(self) -> f64 {
        match self {
            AccelShape::Const => 1.0,
            AccelShape::Sine => 2.0 / PI,
        }
    }
    /// `const` or `sine`.
    pub fn name(self) -> &'static str {
        match self {
            AccelShape::Const => "const",
            AccelShape::Sine => "sine",
        }
    }
}

/// One piece of an [`LawKind::Accel`] law.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AccelPiece {
    /// Constant or half sine.
    pub shape: AccelShape,
    /// The signed amplitude (relative: the law is scaled to the stroke).
    pub amplitude: f64,
    /// The piece's length as a fraction of the phase; the lengths add up to 1.
    pub length: f64,
}

/// A motion law ready to evaluate.
#[derive(Debug, Clone, PartialEq)]
pub struct Law {
    kind: LawKind,
    pieces: Option<Pieces>,
}

/// The most values of a `table(…)` law: each value is a piece of the
/// law, searched for extremes on its own.
pub const MAX_TABLE: usize = 10_000;

/// The shape of an unbalanced or empty table, for [`CamError::LawParameter`].
fn shape_error(name: &str, e: ShapeError) -> CamError {
    let what = if name == "accel" { "pieces" } else { "table" };
    let reason = match e {
        ShapeError::Unbalanced { ratio } => format!(
            "the positive and negative areas of the acceleration {what} differ (net area {:.3} % of the total): the velocity would not return to zero at the end of the phase; balance the {what}",
            ratio * 100.0
        ),
        ShapeError::NoRise => format!(
            "the acceleration {what} give{} no lift (its double integral is not positive){}",
            if name == "accel" { "" } else { "s" },
            if name == "accel" {
                "; a rise starts with a positive piece, a return with a negative one"
            } else {
                ""
            }
        ),
    };
    CamError::LawParameter {
        law: name.to_string(),
        reason,
    }
}

impl Law {
    /// Check the parameters and prepare the law.
    ///
    /// ```
    /// use tmm_cams::law::{Law, LawKind};
    /// let l = Law::new(LawKind::ConstAccel { u: 1.0 / 3.0 }).unwrap();
    /// let [y, v, ..] = l.eval(1.0);
    /// assert!((y - 1.0).abs() < 1e-12 && v.abs() < 1e-12);
    /// assert!(Law::new(LawKind::ConstAccel { u: 1.5 }).is_err());
    /// ```
    pub fn new(kind: LawKind) -> Result<Self, CamError> {
        let pieces = match &kind {
            LawKind::ConstAccel { u } => {
                let u = *u;
                if !(u > 0.0 && u < 1.0) {
                    return Err(CamError::LawParameter {
                        law: "const-accel".into(),
                        reason: format!("u must lie strictly between 0 and 1, got {u}"),
                    });
                }
                // areas +1 and −1: the velocity returns to zero (docs/cams.md §2)
                Some(vec![Piece::linear(0.0, 1.0 / u, 0.0), Piece::linear(u, -1.0 / (1.0 - u), 0.0)])
            }
            LawKind::LinearDecreasing => Some(vec![Piece::linear(0.0, 1.0, -2.0)]),
            // Norton, Design of Machinery, ch. 8 (double-dwell functions): ramps over 1/8
            LawKind::Trapezoid => Some(vec![
                Piece::linear(0.0, 0.0, 8.0),
                Piece::linear(0.125, 1.0, 0.0),
                Piece::linear(0.375, 1.0, -8.0),
                Piece::linear(0.625, -1.0, 0.0),
                Piece::linear(0.875, -1.0, 8.0),
            ]),
            // Norton, ch. 8, modified trapezoid: sine ramps of period 1/2 over 1/8
            LawKind::ModTrapezoid => Some(vec![
                Piece::new(0.0, 0.0, 0.0, 1.0, 0.0, 4.0 * PI),
                Piece::linear(0.125, 1.0, 0.0),
                Piece::new(0.375, 0.0, 0.0, 0.0, 1.0, 4.0 * PI),
                Piece::linear(0.625, -1.0, 0.0),
                Piece::new(0.875, 0.0, 0.0, 0.0, -1.0, 4.0 * PI),
            ]),
            // Norton, ch. 8, modified sine: 1/8 of a fast sine, a slow cosine, 1/8 of a fast cosine
            LawKind::ModSine => Some(vec![
                Piece::new(0.0, 0.0, 0.0, 1.0, 0.0, 4.0 * PI),
                Piece::new(0.125, 0.0, 0.0, 0.0, 1.0, 4.0 * PI / 3.0),
                Piece::new(0.875, 0.0, 0.0, 0.0, -1.0, 4.0 * PI),
            ]),
            LawKind::Table(v) => {
                if v.len() < 2 {
                    return Err(CamError::LawParameter {
                        law: "table".into(),
                        reason: "give at least two values of the acceleration analog".into(),
                    });
                }
                if v.len() > MAX_TABLE {
                    return Err(CamError::LawParameter {
                        law: "table".into(),
                        reason: format!(
                            "give at most {MAX_TABLE} values of the acceleration analog (this table has {})",
                            v.len()
                        ),
                    });
                }
                if v.iter().any(|a| !a.is_finite()) {
                    return Err(CamError::LawParameter {
                        law: "table".into(),
                        reason: "every value must be a finite number".into(),
                    });
                }
                let n = v.len() - 1;
                let dx = 1.0 / n as f64;
                Some((0..n).map(|i| Piece::linear(i as f64 * dx, v[i], (v[i + 1] - v[i]) / dx)).collect())
            }
            LawKind::Accel(p) => Some(accel_pieces(p)?),
            _ => None,
        };
        let name = kind.name();
        let pieces = match pieces {
            Some(p) => Some(Pieces::new(p, 1e-6).map_err(|e| shape_error(name, e))?),
            None => None,
        };
        Ok(Law { kind, pieces })
    }

    /// The law's parameters.
    pub fn kind(&self) -> &LawKind {
        &self.kind
    }

    /// `[y, y′, y″, y‴]` at the phase fraction `x ∈ [0, 1]` (derivatives with
    /// respect to `x`).
    ///
    /// Sources: cosine and sine — Artobolevsky, ТММ (1988), the chapter on cam mechanisms;
    /// polynomials — Norton, Design of Machinery, ch. 8, polynomial functions (3-4-5 and
    /// 4-5-6-7); the piecewise laws — [`crate::segments`].
    ///
    /// ```
    /// use tmm_cams::law::{Law, LawKind};
    /// let l = Law::new(LawKind::Sine).unwrap();
    /// let [y, v, a, _] = l.eval(0.5);
    /// assert!((y - 0.5).abs() < 1e-15 && (v - 2.0).abs() < 1e-15 && a.abs() < 1e-12);
    /// ```
    #[inline]
    pub fn eval(&self, x: f64) -> [f64; 4] {
        let x = x.clamp(0.0, 1.0);
        if let Some(p) = &self.pieces {
            return p.eval(x);
        }
        match self.kind {
            LawKind::Cosine => {
                let (s, c) = (PI * x).sin_cos();
                [(1.0 - c) / 2.0, PI / 2.0 * s, PI * PI / 2.0 * c, -PI * PI * PI / 2.0 * s]
            }
            LawKind::Sine => {
                let (s, c) = (2.0 * PI * x).sin_cos();
                [x - s / (2.0 * PI), 1.0 - c, 2.0 * PI * s, 4.0 * PI * PI * c]
            }
            LawKind::Poly345 => {
                let (x2, x3) = (x * x, x * x * x);
                [
                    10.0 * x3 - 15.0 * x3 * x + 6.0 * x3 * x2,
                    30.0 * x2 - 60.0 * x3 + 30.0 * x2 * x2,
                    60.0 * x - 180.0 * x2 + 120.0 * x3,
                    60.0 - 360.0 * x + 360.0 * x2,
                ]
            }
            LawKind::Poly4567 => {
                let (x2, x3) = (x * x, x * x * x);
                let x4 = x2 * x2;
                [
                    35.0 * x4 - 84.0 * x4 * x + 70.0 * x3 * x3 - 20.0 * x4 * x3,
                    140.0 * x3 - 420.0 * x4 + 420.0 * x4 * x - 140.0 * x3 * x3,
                    420.0 * x2 - 1680.0 * x3 + 2100.0 * x4 - 840.0 * x4 * x,
                    840.0 * x - 5040.0 * x2 + 8400.0 * x3 - 4200.0 * x4,
                ]
            }
            // constant velocity (Artobolevsky, ТММ, 1988, cam mechanisms: the linear law)
            LawKind::ConstVelocity => [x, 1.0, 0.0, 0.0],
            // piecewise kinds always have pieces
            _ => [x, 1.0, 0.0, 0.0],
        }
    }

    /// [`Law::eval`] from the left: at a joint inside a piecewise law, the
    /// values of the piece that ends there.
    #[inline]
    pub fn eval_left(&self, x: f64) -> [f64; 4] {
        match &self.pieces {
            Some(p) => p.eval_left(x.clamp(0.0, 1.0)),
            None => self.eval(x),
        }
    }

    /// Fractions of the phase inside which the acceleration or jerk may jump
    /// (piece joints), for the extreme searches.
    pub fn breaks(&self) -> Vec<f64> {
        self.pieces
            .as_ref()
            .map(|p| p.breaks().filter(|&x| x > 0.0).collect())
            .unwrap_or_default()
    }

    /// The order of continuity at a joint with a dwell: 0 — the velocity
    /// jumps (acceleration impulses, "rigid impact"), 1 — velocity continuous
    /// (acceleration jumps, "soft impact"), 2 — acceleration continuous (jerk
    /// jumps), 3 — jerk continuous.
    pub fn continuity(&self) -> u8 {
        match &self.kind {
            LawKind::ConstVelocity => 0,
            LawKind::ConstAccel { .. } | LawKind::Cosine | LawKind::LinearDecreasing => 1,
            LawKind::Sine | LawKind::Trapezoid | LawKind::ModTrapezoid | LawKind::ModSine | LawKind::Poly345 => 2,
            LawKind::Poly4567 => 3,
            LawKind::Table(v) => {
                if v[0] == 0.0 && v[v.len() - 1] == 0.0 {
                    2
                } else {
                    1
                }
            }
            // a half sine starts and ends at 0: C2 where both ends are sines
            LawKind::Accel(p) => {
                if p.first().is_some_and(|q| q.shape == AccelShape::Sine) && p.last().is_some_and(|q| q.shape == AccelShape::Sine) {
                    2
                } else {
                    1
                }
            }
        }
    }
}

impl LawKind {
    /// The name used in phase lists (`const-accel`, `cosine`, …).
    pub fn name(&self) -> &'static str {
        match self {
            LawKind::ConstAccel { .. } => "const-accel",
            LawKind::Cosine => "cosine",
            LawKind::Sine => "sine",
            LawKind::LinearDecreasing => "linear-decreasing",
            LawKind::Trapezoid => "trapezoid",
            LawKind::ModTrapezoid => "mod-trapezoid",
            LawKind::ModSine => "mod-sine",
            LawKind::Poly345 => "poly345",
            LawKind::Poly4567 => "poly4567",
            LawKind::Table(_) => "table",
            LawKind::ConstVelocity => "const-velocity",
            LawKind::Accel(_) => "accel",
        }
    }
}

impl std::fmt::Display for LawKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            LawKind::ConstAccel { u } => write!(f, "const-accel(u={u:.4})"),
            LawKind::Table(v) => write!(f, "table({} values)", v.len()),
            LawKind::Accel(p) => {
                f.write_str("accel(")?;
                for (i, q) in p.iter().enumerate() {
                    if i > 0 {
                        f.write_str(", ")?;
                    }
                    write!(f, "{} {} on {:.4}", q.shape.name(), q.amplitude, q.length)?;
                }
                f.write_str(")")
            }
            k => f.write_str(k.name()),
        }
    }
}

/// The law names a phase list accepts, for messages.
pub const LAW_NAMES: &str = "const-accel(u=1/3), cosine, sine, linear-decreasing, trapezoid, mod-trapezoid, mod-sine, poly345, poly4567, table(a0, a1, …), const-velocity, accel(sine 1, sine -3) (pieces of the acceleration analog, each `const` or `sine` with its amplitude and, optionally, its angle)";

/// The most pieces of an [`LawKind::Accel`] law.
pub const MAX_ACCEL_PIECES: usize = 64;

/// The pieces of an [`LawKind::Accel`] law as [`Piece`]s: a constant `A` on
/// its length, a half sine `A·sin(πt/L)` (frequency π/L per unit of the
/// phase fraction). Checked: at least two pieces, finite amplitudes, positive
/// lengths that add up to 1.
fn accel_pieces(p: &[AccelPiece]) -> Result<Vec<Piece>, CamError> {
    let bad = |reason: String| CamError::LawParameter {
        law: "accel".into(),
        reason,
    };
    if p.len() < 2 || p.len() > MAX_ACCEL_PIECES {
        return Err(bad(format!(
            "give from 2 to {MAX_ACCEL_PIECES} pieces (a positive and a negative one at least), got {}",
            p.len()
        )));
    }
    if let Some((i, _)) = p.iter().enumerate().find(|(_, q)| !q.amplitude.is_finite()) {
        return Err(bad(format!("piece {}: the amplitude must be a finite number", i + 1)));
    }
    if let Some((i, q)) = p.iter().enumerate().find(|(_, q)| !(q.length.is_finite() && q.length > 0.0)) {
        return Err(bad(format!(
            "piece {}: its length must be positive, got {} of the phase",
            i + 1,
            q.length
        )));
    }
    let sum: f64 = p.iter().map(|q| q.length).sum();
    if (sum - 1.0).abs() > 1e-9 {
        return Err(bad(format!(
            "the pieces cover {:.6} of the phase: their angles must add up to the phase angle",
            sum
        )));
    }
    let mut x0 = 0.0;
    let mut out = Vec::with_capacity(p.len());
    for q in p {
        out.push(match q.shape {
            AccelShape::Const => Piece::linear(x0, q.amplitude, 0.0),
            AccelShape::Sine => Piece::new(x0, 0.0, 0.0, q.amplitude, 0.0, PI / q.length),
        });
        x0 += q.length;
    }
    Ok(out)
}
