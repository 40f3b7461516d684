//! The compact text forms of a cam task, shared by the command line and the
//! task file: the phase list (`rise 108 const-accel(u=1/3); dwell 15; …`) and
//! the pressure-angle limits (`rise 15, return 30`, or one value for both).

use crate::CamError;
use crate::law::{AccelPiece, AccelShape, LAW_NAMES, Law, LawKind};
use crate::program::{Phase, PhaseKind, Stroke};
use tmm_geom::units::{self, Dim};

/// Read a phase list: phases separated by `;`, each `KIND ANGLE [LAW [STROKE]]`
/// where KIND is `rise`, `dwell` or `return` (also `upper-dwell`,
/// `lower-dwell`), ANGLE takes a unit or is degrees, LAW is one of
/// [`LAW_NAMES`] (rises and returns only), and STROKE, with its unit, is the
/// phase's own stroke (`20mm`, or `15°` for an oscillating follower; without
/// it the program's stroke). With strokes per phase the rises must add up to
/// the returns ([`crate::program::Program::from_phases`]); docs/cams.md §2a.
///
/// ```
/// let p = tmm_cams::spec::parse_phases("rise 108 const-accel(u=1/3); dwell 15; return 108° sine; dwell 129").unwrap();
/// assert_eq!(p.len(), 4);
/// assert!((p[1].angle - 15f64.to_radians()).abs() < 1e-15);
/// assert!(tmm_cams::spec::parse_phases("rise 108 bogus; dwell 252").is_err());
/// let q = tmm_cams::spec::parse_phases("rise 90 cosine 20 mm; return 90 deg sine 20mm; dwell 180").unwrap();
/// assert_eq!(q[0].stroke, Some(tmm_cams::program::Stroke::Length(0.020)));
/// assert!(tmm_cams::spec::parse_phases("rise 90 cosine 20; return 90 sine 20mm; dwell 180").is_err());
/// // 10 000 table values in all: two tables of 6000 are refused together
/// let t = format!("table({})", vec!["1"; 3000].into_iter().chain(vec!["-1"; 3000]).collect::<Vec<_>>().join(","));
/// assert!(tmm_cams::spec::parse_phases(&format!("rise 90 {t}; return 90 {t}; dwell 180")).is_err());
/// assert!(tmm_cams::spec::parse_phases(&format!("rise 90 {t}; return 90 cosine; dwell 180")).is_ok());
/// ```
pub fn parse_phases(text: &str) -> Result<Vec<Phase>, CamError> {
    let mut out = Vec::new();
    let mut table_values = 0usize;
    for piece in split_top(text, ';') {
        let piece = piece.trim();
        if piece.is_empty() {
            continue;
        }
        // a phase is echoed in its message, cut to 80 characters (a table
        // law can be thousands of values long)
        let shown: String = match piece.char_indices().nth(80) {
            Some((i, _)) => format!("{}…", &piece[..i]),
            None => piece.to_string(),
        };
        let err = |reason: String| CamError::Phase {
            text: shown.clone(),
            reason,
        };
        let (kw, rest) = piece
            .split_once(char::is_whitespace)
            .ok_or_else(|| err("write KIND ANGLE [LAW], e.g. `rise 108 cosine`".into()))?;
        let kind = match kw.to_ascii_lowercase().as_str() {
            "rise" | "подъем" | "подъём" => PhaseKind::Rise,
            "return" | "fall" | "опускание" => PhaseKind::Return,
            "dwell" | "upper-dwell" | "lower-dwell" | "выстой" => PhaseKind::Dwell,
            k => return Err(err(format!("`{k}` is not a phase; use rise, dwell or return"))),
        };
        let rest = rest.trim();
        let (angle_txt, law, stroke) = if kind == PhaseKind::Dwell {
            (rest.to_string(), None, None)
        } else {
            // KIND ANGLE LAW [STROKE]: the law is the first word that names one
            let words = words_top(rest);
            let found = words
                .iter()
                .position(|w| !matches!(parse_law(w), Err(CamError::UnknownLaw { .. })))
                .filter(|&i| i > 0);
            if found.is_none() {
                // name the unknown law: the word after the longest prefix that reads as an angle
                if let Some(i) = (1..words.len())
                    .rev()
                    .find(|&i| units::parse(&words[..i].join(" "), Dim::Angle).is_ok())
                {
                    parse_law(words[i])?;
                }
            }
            let at = found.ok_or_else(|| {
                err(format!(
                    "give the angle and the law, e.g. `{kw} 108 cosine` or `{kw} 108 cosine 20mm`; laws: {LAW_NAMES}"
                ))
            })?;
            let stroke_txt = words[at + 1..].join(" ");
            let stroke = if stroke_txt.is_empty() {
                None
            } else {
                Some(parse_stroke(&stroke_txt).map_err(err)?)
            };
            (words[..at].join(" "), Some(words[at]), stroke)
        };
        let angle = units::parse(&angle_txt, Dim::Angle).map_err(|e| err(e.to_string()))?;
        // the law once the phase is known: the pieces of `accel(…)` take
        // their signs from the phase and their angles from its angle
        let law = match law {
            Some(w) => Some(parse_law_in(w, Some((kind, angle)))?),
            None => None,
        };
        // the cost is in the table values of all phases together (each
        // value a piece searched on its own), so the limit is on their sum
        if let Some(LawKind::Table(v)) = law.as_ref().map(Law::kind) {
            table_values += v.len();
            if table_values > crate::law::MAX_TABLE {
                return Err(err(format!(
                    "the table laws of all phases together take at most {} values; with this one they have {table_values}",
                    crate::law::MAX_TABLE
                )));
            }
        }
        out.push(Phase { kind, angle, law, stroke });
    }
    if out.is_empty() {
        return Err(CamError::Phase {
            text: text.to_string(),
            reason: "no phases given".into(),
        });
    }
    Ok(out)
}

/// Read one law: `name` or `name(args)`.
///
/// ```
/// use tmm_cams::law::LawKind;
/// let l = tmm_cams::spec::parse_law("const-accel(u=1/3)").unwrap();
/// assert_eq!(l.kind(), &LawKind::ConstAccel { u: 1.0 / 3.0 });
/// let t = tmm_cams::spec::parse_law("table(1, 1, -1, -1)").unwrap();
/// assert_eq!(t.kind(), &LawKind::Table(vec![1.0, 1.0, -1.0, -1.0]));
/// ```
pub fn parse_law(text: &str) -> Result<Law, CamError> {
    parse_law_in(text, None)
}

/// Read one law of a phase of kind `kind` and angle `angle` (rad), when
/// known: an `accel(…)` law on a return is written with the signs of the
/// return's acceleration analog (negative first, as the book draws it), and
/// its pieces' angles must add up to the phase angle. Without a phase the
/// law is read as a rise whose pieces give no angles.
///
/// ```
/// use tmm_cams::{law::{AccelShape, LawKind}, program::PhaseKind, spec::parse_law_in};
/// let l = parse_law_in("accel(sine 1, sine -3)", Some((PhaseKind::Rise, 120f64.to_radians()))).unwrap();
/// let LawKind::Accel(p) = l.kind() else { panic!() };
/// // the areas balance: 1·L₁ = 3·L₂, so L₁ = 3/4 of the phase (the book's f₁ = a₂ψ/(a₁ + a₂))
/// assert!((p[0].length - 0.75).abs() < 1e-15 && p[0].shape == AccelShape::Sine);
/// let r = parse_law_in("accel(const -1 90°, const 1 90°)", Some((PhaseKind::Return, std::f64::consts::PI))).unwrap();
/// let LawKind::Accel(q) = r.kind() else { panic!() };
/// assert_eq!(q[0].amplitude, 1.0); // turned into a rise law
/// assert!(parse_law_in("accel(const -1 90°, const 1 80°)", Some((PhaseKind::Return, std::f64::consts::PI))).is_err());
/// ```
pub fn parse_law_in(text: &str, phase: Option<(PhaseKind, f64)>) -> Result<Law, CamError> {
    let t = text.trim();
    let (name, args) = match t.find('(') {
        Some(p) => {
            let close = t
                .rfind(')')
                .filter(|&c| c > p && c == t.len() - 1)
                .ok_or_else(|| CamError::LawParameter {
                    law: t.to_string(),
                    reason: "the parenthesis is not closed".into(),
                })?;
            (t[..p].trim(), Some(&t[p + 1..close]))
        }
        None => (t, None),
    };
    let lname = name.to_ascii_lowercase().replace('_', "-");
    let no_args = |k: LawKind| -> Result<LawKind, CamError> {
        match args {
            Some(a) if !a.trim().is_empty() => Err(CamError::LawParameter {
                law: t.to_string(),
                reason: "this law takes no parameters".into(),
            }),
            _ => Ok(k),
        }
    };
    let kind = match lname.as_str() {
        "const-accel" | "constant-acceleration" | "parabolic" => {
            let u = match args {
                None => 0.5,
                Some(a) => {
                    let a = a.trim();
                    let v = a.strip_prefix("u").map(|r| r.trim_start().trim_start_matches('=')).unwrap_or(a);
                    units::parse(v, Dim::Ratio).map_err(|e| CamError::LawParameter {
                        law: t.to_string(),
                        reason: format!("{e}; write const-accel(u=1/3)"),
                    })?
                }
            };
            LawKind::ConstAccel { u }
        }
        "cosine" | "harmonic" => no_args(LawKind::Cosine)?,
        "sine" | "cycloidal" => no_args(LawKind::Sine)?,
        "linear-decreasing" => no_args(LawKind::LinearDecreasing)?,
        "trapezoid" | "trapezoidal" => no_args(LawKind::Trapezoid)?,
        "mod-trapezoid" | "modified-trapezoid" => no_args(LawKind::ModTrapezoid)?,
        "mod-sine" | "modified-sine" => no_args(LawKind::ModSine)?,
        "poly345" | "3-4-5" => no_args(LawKind::Poly345)?,
        "poly4567" | "4-5-6-7" => no_args(LawKind::Poly4567)?,
        "const-velocity" | "constant-velocity" | "linear" | "uniform" => no_args(LawKind::ConstVelocity)?,
        "table" => {
            let a = args.unwrap_or("");
            let vals: Result<Vec<f64>, CamError> = a
                .split(|c: char| c == ',' || c.is_whitespace())
                .filter(|w| !w.is_empty())
                .map(|w| {
                    units::parse(w, Dim::Ratio).map_err(|e| CamError::LawParameter {
                        law: "table".into(),
                        reason: format!("{e}; separate the values with commas and use a decimal point"),
                    })
                })
                .collect();
            LawKind::Table(vals?)
        }
        "accel" | "acceleration" => parse_accel(args.unwrap_or(""), phase)?,
        _ => return Err(CamError::UnknownLaw { name: name.to_string() }),
    };
    Law::new(kind)
}

/// The pieces of `accel(SHAPE AMPLITUDE [ANGLE], …)`: SHAPE `const` or
/// `sine` (a half sine wave), the signed amplitude of the phase's
/// acceleration analog (a rise starts positive, a return negative), the
/// piece's angle with its unit (degrees when bare). Angles are given for all
/// pieces (adding up to the phase angle), for all but one (which takes the
/// rest), or for none of two pieces, which then split the phase so that
/// their areas balance: `L₁·|A₁|·k₁ = L₂·|A₂|·k₂`, k the shape's area factor
/// ([`AccelShape::area_factor`]), i.e. `L₁ = β·|A₂|k₂/(|A₁|k₁ + |A₂|k₂)` —
/// for equal shapes the book's `f₁ = a₂ψ/(a₁ + a₂)` (Chernaya, Timofeev 2019,
/// appendix П6, p. 149).
fn parse_accel(args: &str, phase: Option<(PhaseKind, f64)>) -> Result<LawKind, CamError> {
    let bad = |reason: String| CamError::LawParameter {
        law: "accel".into(),
        reason,
    };
    let mut shapes = Vec::new();
    for (i, piece) in args.split(',').enumerate() {
        let words: Vec<&str> = piece.split_whitespace().collect();
        if words.len() < 2 {
            return Err(bad(format!(
                "piece {} `{}`: write SHAPE AMPLITUDE [ANGLE], e.g. `sine 1 90°` or `const -2.5`",
                i + 1,
                piece.trim()
            )));
        }
        let shape = match words[0].to_ascii_lowercase().as_str() {
            "const" | "constant" => AccelShape::Const,
            "sine" | "sin" | "half-sine" => AccelShape::Sine,
            w => {
                return Err(bad(format!(
                    "piece {}: `{w}` is not a shape; use const or sine (a half sine wave)",
                    i + 1
                )));
            }
        };
        let amplitude =
            units::parse(words[1], Dim::Ratio).map_err(|e| bad(format!("piece {}: the amplitude `{}`: {e}", i + 1, words[1])))?;
        if amplitude == 0.0 || !amplitude.is_finite() {
            return Err(bad(format!("piece {}: the amplitude must be a finite number other than 0", i + 1)));
        }
        let angle = if words.len() > 2 {
            let a_txt = words[2..].join(" ");
            let a = units::parse(&a_txt, Dim::Angle).map_err(|e| bad(format!("piece {}: the angle `{a_txt}`: {e}", i + 1)))?;
            if !(a.is_finite() && a > 0.0) {
                return Err(bad(format!("piece {}: the angle must be positive, got {a_txt}", i + 1)));
            }
            Some(a)
        } else {
            None
        };
        shapes.push((shape, amplitude, angle));
    }
    if shapes.len() < 2 || shapes.len() > crate::law::MAX_ACCEL_PIECES {
        return Err(bad(format!(
            "give from 2 to {} pieces, a positive and a negative one at least; got {}",
            crate::law::MAX_ACCEL_PIECES,
            shapes.len()
        )));
    }
    let (sign, beta) = match phase {
        Some((PhaseKind::Return, b)) => (-1.0, Some(b)),
        Some((_, b)) => (1.0, Some(b)),
        None => (1.0, None),
    };
    let missing = shapes.iter().filter(|s| s.2.is_none()).count();
    let lengths: Vec<f64> = if missing == 0 || missing == 1 && shapes.len() > 2 {
        let Some(beta) = beta else {
            return Err(bad("the pieces' angles need the phase angle: write the law in a phase list".into()));
        };
        let given: f64 = shapes.iter().filter_map(|s| s.2).sum();
        if missing == 0 {
            if (given - beta).abs() > 1e-6f64.to_radians() {
                return Err(bad(format!(
                    "the pieces' angles add up to {:.6}° but the phase is {:.6}°; make them equal, or leave the angle out of one piece to give it the rest",
                    given.to_degrees(),
                    beta.to_degrees()
                )));
            }
        } else if given >= beta - 1e-6f64.to_radians() {
            return Err(bad(format!(
                "the given pieces' angles add up to {:.6}°, leaving nothing of the phase's {:.6}° for the piece without an angle",
                given.to_degrees(),
                beta.to_degrees()
            )));
        }
        // the angles as fractions of their own sum (equal to β to 1e-6°)
        let rest = beta - given;
        let total = if missing == 0 { given } else { beta };
        shapes.iter().map(|s| s.2.unwrap_or(rest) / total).collect()
    } else if missing == 2 && shapes.len() == 2 {
        let (s1, a1, _) = shapes[0];
        let (s2, a2, _) = shapes[1];
        if a1.signum() == a2.signum() {
            return Err(bad(
                "the two pieces have the same sign: the velocity would not come back to zero; give one positive and one negative amplitude"
                    .into(),
            ));
        }
        // the areas balance: L₁|A₁|k₁ = L₂|A₂|k₂ with L₁ + L₂ = 1
        let (w1, w2) = (a1.abs() * s1.area_factor(), a2.abs() * s2.area_factor());
        vec![w2 / (w1 + w2), w1 / (w1 + w2)]
    } else {
        return Err(bad(format!(
            "{missing} of the {} pieces have no angle: give every piece its angle, or leave it out of one piece only (or of both of two pieces, which then split the phase so their areas balance)",
            shapes.len()
        )));
    };
    Ok(LawKind::Accel(
        shapes
            .iter()
            .zip(lengths)
            .map(|(&(shape, amplitude, _), length)| AccelPiece {
                shape,
                amplitude: sign * amplitude,
                length,
            })
            .collect(),
    ))
}

/// Pressure-angle limits for the rise and the return, rad.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Limits {
    /// Allowed pressure angle on the rise.
    pub rise: f64,
    /// Allowed pressure angle on the return.
    pub ret: f64,
}

impl Limits {
    /// Check that both lie strictly between 0 and 90°.
    pub fn check(self) -> Result<Self, CamError> {
        for (phase, v) in [("rise", self.rise), ("return", self.ret)] {
            if !(v > 0.0 && v < std::f64::consts::FRAC_PI_2) {
                return Err(CamError::PressureLimit {
                    phase,
                    deg: v.to_degrees(),
                });
            }
        }
        Ok(self)
    }
}

/// Read `rise 15, return 30` or `30` (both phases). With `transmission`, the
/// values are transmission angles γ and the limits are ϑ = 90° − γ
/// (DESIGN.md glossary: угол передачи γ = 90° − ϑ).
///
/// ```
/// let l = tmm_cams::spec::parse_limits("rise 75, return 60", true).unwrap();
/// assert!((l.rise - 15f64.to_radians()).abs() < 1e-15 && (l.ret - 30f64.to_radians()).abs() < 1e-15);
/// assert!(tmm_cams::spec::parse_limits("95", false).is_err());
/// ```
pub fn parse_limits(text: &str, transmission: bool) -> Result<Limits, CamError> {
    let conv = |v: f64| if transmission { std::f64::consts::FRAC_PI_2 - v } else { v };
    let bad = |reason: String| CamError::Limits {
        text: text.to_string(),
        reason,
    };
    let t = text.trim();
    let (mut rise, mut ret) = (None, None);
    if t.contains("rise") || t.contains("return") {
        for part in t.split([',', ';']) {
            let part = part.trim();
            if part.is_empty() {
                continue;
            }
            let (k, v) = part
                .split_once(char::is_whitespace)
                .ok_or_else(|| bad(format!("`{part}`: write `rise 15, return 30`")))?;
            let v = conv(units::parse(v.trim_start_matches('=').trim(), Dim::Angle).map_err(|e| bad(e.to_string()))?);
            match k {
                "rise" => rise = Some(v),
                "return" => ret = Some(v),
                _ => return Err(bad(format!("`{k}` is not a phase; write `rise 15, return 30`"))),
            }
        }
        let (Some(rise), Some(ret)) = (rise, ret) else {
            return Err(bad("give both `rise` and `return`, or one value for both".into()));
        };
        Limits { rise, ret }.check()
    } else {
        let v = conv(units::parse(t, Dim::Angle).map_err(|e| bad(e.to_string()))?);
        Limits { rise: v, ret: v }.check()
    }
}

/// Split on `sep` outside parentheses.
fn split_top(text: &str, sep: char) -> Vec<&str> {
    let mut out = Vec::new();
    let (mut depth, mut start) = (0i32, 0);
    for (i, c) in text.char_indices() {
        match c {
            '(' => depth += 1,
            ')' => depth -= 1,
            c if c == sep && depth == 0 => {
                out.push(&text[start..i]);
                start = i + c.len_utf8();
            }
            _ => {}
        }
    }
    out.push(&text[start..]);
    out
}

/// A phase's stroke with its unit: a length (`20mm`, `0.02 m`) or an angle
/// (`15°`, `15 deg`, `0.2 rad`); a bare number is refused, since it could be
/// read either way.
fn parse_stroke(text: &str) -> Result<Stroke, String> {
    let t = text.trim();
    if t.ends_with(|c: char| c.is_ascii_digit() || c == '.') {
        return Err(format!(
            "give the stroke `{t}` with its unit: a length such as `20mm` (translating follower) or an angle such as `15°` (oscillating)"
        ));
    }
    if let Ok(v) = units::parse(t, Dim::Length) {
        return Ok(Stroke::Length(v));
    }
    units::parse(t, Dim::Angle)
        .map(Stroke::Angle)
        .map_err(|_| format!("`{t}` is neither a length (`20mm`) nor an angle (`15°`) for the phase's stroke"))
}

/// Whitespace-separated words, parentheses kept together.
fn words_top(text: &str) -> Vec<&str> {
    let mut out = Vec::new();
    let (mut depth, mut start) = (0i32, None);
    for (i, c) in text.char_indices() {
        match c {
            '(' => depth += 1,
            ')' => depth -= 1,
            _ => {}
        }
        if c.is_whitespace() && depth == 0 {
            if let Some(s) = start.take() {
                out.push(&text[s..i]);
            }
        } else if start.is_none() {
            start = Some(i);
        }
    }
    if let Some(s) = start {
        out.push(&text[s..]);
    }
    out
}
