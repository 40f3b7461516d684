//! A sized cam mechanism in the fixed frame: cam centre O at the origin, and
//! the follower placed by its dimensions. For one cam angle it gives the
//! follower's pitch point (roller centre, or the face point on a flat
//! follower's axis) or its face line, with derivatives with respect to the cam
//! angle, and the pressure angle.
//!
//! Kinematic inversion (метод обращения движения): the cam turns by `σφ`
//! (σ = +1 counter-clockwise); a frame point `X(φ)` seen from the cam is
//! `R(−σφ)·X(φ)`, whose derivatives are `R(−σφ)(X′ − σJX)` and
//! `R(−σφ)(X″ − 2σJX′ − X)`, J the quarter turn (derived here, docs/cams.md §4).

use crate::program::Motion;
use tmm_geom::Vec2;

/// Quarter turn counter-clockwise: `J(x, y) = (−y, x)`.
#[inline]
pub fn quarter(v: Vec2) -> Vec2 {
    Vec2::new(-v.y, v.x)
}

/// Rotate by the angle `a`.
#[inline]
pub fn rotate(v: Vec2, a: f64) -> Vec2 {
    let (s, c) = a.sin_cos();
    Vec2::new(c * v.x - s * v.y, s * v.x + c * v.y)
}

/// Direction of the cam's rotation.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Rotation {
    /// Counter-clockwise (σ = +1).
    Ccw,
    /// Clockwise (σ = −1).
    Cw,
}

impl Rotation {
    /// σ: +1 counter-clockwise, −1 clockwise.
    pub fn sign(self) -> f64 {
        match self {
            Rotation::Ccw => 1.0,
            Rotation::Cw => -1.0,
        }
    }
    /// `ccw` or `cw`.
    pub fn name(self) -> &'static str {
        match self {
            Rotation::Ccw => "ccw",
            Rotation::Cw => "cw",
        }
    }
}

/// The sized mechanism.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Mechanism {
    /// Translating follower moving along +y on the line `x = e` (эксцентриситет e);
    /// its roller centre is at `(e, s₀ + s)`, `s₀ = √(r₀² − e²)`.
    TranslatingRoller {
        /// Offset e of the follower axis from the cam centre, m.
        e: f64,
        /// Height of the lowest roller centre above the cam centre, m.
        s0: f64,
        /// Roller radius, m (0 for a knife edge).
        roller: f64,
    },
    /// Translating flat face perpendicular to the axis `x = e`, at `y = r₀ + s`.
    TranslatingFlat {
        /// Offset of the follower axis, m.
        e: f64,
        /// Base circle radius r₀, m.
        r0: f64,
    },
    /// Oscillating (rocker) follower: pivot A, arm l to the roller centre
    /// B = A + l·(cos ψ, sin ψ), ψ = ψ₀ + κ·s (s the follower angle).
    OscillatingRoller {
        /// The pivot A relative to the cam centre, m.
        pivot: Vec2,
        /// Arm length l = AB, m.
        arm: f64,
        /// Arm angle at the lowest position, rad.
        psi0: f64,
        /// +1 when the arm turns counter-clockwise on the rise.
        kappa: f64,
        /// Roller radius, m.
        roller: f64,
    },
    /// Oscillating flat face through the pivot A = (a, 0), at the angle
    /// ψ = π + δ₀ + s from the x-axis, `a·sin δ₀ = r₀`.
    OscillatingFlat {
        /// Pivot distance a = OA, m.
        a: f64,
        /// Initial face angle δ₀ = asin(r₀/a), rad.
        delta0: f64,
    },
}

/// A point seen from the frame with its derivatives by the cam angle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Jet {
    /// Position.
    pub p: Vec2,
    /// d/dφ.
    pub d1: Vec2,
    /// d²/dφ².
    pub d2: Vec2,
}

/// A line `n·X = p` with `n = (cos α, sin α)`, with derivatives by the cam angle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LineJet {
    /// Normal angle α and its derivatives.
    pub alpha: [f64; 3],
    /// Distance p from the cam centre and its derivatives.
    pub p: [f64; 3],
}

impl Mechanism {
    /// `true` for a flat-faced follower.
    pub fn is_flat(&self) -> bool {
        matches!(self, Mechanism::TranslatingFlat { .. } | Mechanism::OscillatingFlat { .. })
    }

    /// Roller radius (0 for a knife edge or a flat face).
    pub fn roller(&self) -> f64 {
        match *self {
            Mechanism::TranslatingRoller { roller, .. } | Mechanism::OscillatingRoller { roller, .. } => roller,
            _ => 0.0,
        }
    }

    /// The pitch point in the frame with its φ-derivatives: the roller centre,
    /// or for a flat face the foot of the perpendicular from O to the face
    /// (its distance from O is the base radius r₀ + s, so r₀ is the smallest
    /// radius of this theoretical profile).
    #[inline]
    pub fn frame_point(&self, m: &Motion) -> Jet {
        match *self {
            Mechanism::TranslatingRoller { e, s0, .. } => Jet {
                p: Vec2::new(e, s0 + m.s),
                d1: Vec2::new(0.0, m.v),
                d2: Vec2::new(0.0, m.a),
            },
            Mechanism::TranslatingFlat { r0, .. } => Jet {
                p: Vec2::new(0.0, r0 + m.s),
                d1: Vec2::new(0.0, m.v),
                d2: Vec2::new(0.0, m.a),
            },
            Mechanism::OscillatingRoller {
                pivot, arm, psi0, kappa, ..
            } => {
                let psi = psi0 + kappa * m.s;
                let u = Vec2::new(psi.cos(), psi.sin());
                let (w, dw) = (kappa * m.v, kappa * m.a);
                Jet {
                    p: pivot + u * arm,
                    d1: quarter(u) * (arm * w),
                    d2: quarter(u) * (arm * dw) - u * (arm * w * w),
                }
            }
            Mechanism::OscillatingFlat { .. } => {
                let l = self.frame_line(m);
                let n = Vec2::new(l.alpha[0].cos(), l.alpha[0].sin());
                let t = quarter(n);
                let (a1, a2) = (l.alpha[1], l.alpha[2]);
                // foot point F = p·n: F′ = p′n + p·α′·t, F″ = p″n + 2p′α′t + p(α″t − α′²n)
                Jet {
                    p: n * l.p[0],
                    d1: n * l.p[1] + t * (l.p[0] * a1),
                    d2: n * l.p[2] + t * (2.0 * l.p[1] * a1 + l.p[0] * a2) - n * (l.p[0] * a1 * a1),
                }
            }
        }
    }

    /// The face line of a flat follower in the frame (None for a roller).
    #[inline]
    pub fn frame_line(&self, m: &Motion) -> LineJet {
        match *self {
            Mechanism::TranslatingFlat { r0, .. } => LineJet {
                alpha: [std::f64::consts::FRAC_PI_2, 0.0, 0.0],
                p: [r0 + m.s, m.v, m.a],
            },
            Mechanism::OscillatingFlat { a, delta0 } => {
                // face through A = (a, 0) at the angle ψ = π + δ, δ = δ₀ + s;
                // unit normal n = J·u = (sin δ, −cos δ), α = δ − π/2, p = n·A = a·sin δ
                let d = delta0 + m.s;
                let (sd, cd) = d.sin_cos();
                LineJet {
                    alpha: [d - std::f64::consts::FRAC_PI_2, m.v, m.a],
                    p: [a * sd, a * cd * m.v, a * (cd * m.a - sd * m.v * m.v)],
                }
            }
            _ => LineJet {
                alpha: [0.0; 3],
                p: [0.0; 3],
            },
        }
    }

    /// The pivot of an oscillating follower (None for a translating one).
    pub fn pivot(&self) -> Option<Vec2> {
        match *self {
            Mechanism::OscillatingRoller { pivot, .. } => Some(pivot),
            Mechanism::OscillatingFlat { a, .. } => Some(Vec2::new(a, 0.0)),
            _ => None,
        }
    }

    /// The pressure angle ϑ (угол давления) of a roller or knife-edge follower:
    /// the angle between the contact normal and the velocity of the roller
    /// centre, from the point K of the s–ds/dφ construction: K lies on the
    /// follower's line through B (the arm, or the perpendicular to a
    /// translating axis) at `K = B − σ·(ds/dφ)·m`, and O–K is parallel to the
    /// contact normal, so `tan ϑ = |(O − K)·m| / ((O − K)·(−d))`, d the
    /// direction of the rise. For a translating follower this is
    /// `tan ϑ = (σ·ds/dφ − e)/(s₀ + s)` (Norton, Design of Machinery, ch. 8, cam sizing;
    /// the oscillating case derived here, docs/cams.md §3).
    ///
    /// For a flat face it is the angle between the face normal and the
    /// velocity of the contact point (0 for a translating flat face).
    #[inline]
    pub fn pressure_angle(&self, m: &Motion, sigma: f64) -> f64 {
        match *self {
            Mechanism::TranslatingRoller { e, s0, .. } => ((sigma * m.v - e).abs()).atan2(s0 + m.s),
            Mechanism::TranslatingFlat { .. } => 0.0,
            Mechanism::OscillatingRoller {
                pivot, arm, psi0, kappa, ..
            } => {
                let psi = psi0 + kappa * m.s;
                let u = Vec2::new(psi.cos(), psi.sin());
                let b = pivot + u * arm;
                let d = quarter(u) * kappa;
                let k = b - u * (sigma * kappa * arm * m.v);
                let w = -k;
                (w.dot(u).abs()).atan2(-w.dot(d))
            }
            Mechanism::OscillatingFlat { a, .. } => {
                let c = self.contact_frame(m, sigma);
                let l = self.frame_line(m);
                let n = Vec2::new(l.alpha[0].cos(), l.alpha[0].sin());
                let r = c - Vec2::new(a, 0.0);
                let v = quarter(r);
                let h = v.hypot();
                if h == 0.0 { 0.0 } else { (n.dot(v) / h).abs().min(1.0).acos() }
            }
        }
    }

    /// The contact point of a flat face in the frame: the envelope point
    /// `X = p·n + (dp/dα)·J·n` of the face lines seen from the cam, with
    /// dα/dφ = α′ − σ (derived here, docs/cams.md §5).
    #[inline]
    pub fn contact_frame(&self, m: &Motion, sigma: f64) -> Vec2 {
        let l = self.frame_line(m);
        let n = Vec2::new(l.alpha[0].cos(), l.alpha[0].sin());
        let da = l.alpha[1] - sigma;
        n * l.p[0] + quarter(n) * (l.p[1] / da)
    }
}
