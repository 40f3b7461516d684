//! Quantities as people write them, turned into SI.
//!
//! Convention (DESIGN.md, "Units"): a task file or command line may give a
//! value as a string with a unit (`"120 mm"`, `"0.12 m"`, `"900 rpm"`,
//! `"94.2 rad/s"`, `"20 deg"`, `"15°"`, `"1 in"`, `"3 kN"`) or as a plain
//! number, which is SI — except angles, where a plain number is degrees.
//! A decimal comma (`"0,12 m"`) is accepted, as Russian and Ukrainian texts
//! write it. Results are SI: m, rad, s, kg, N, N·m, kg·m², Pa.

use std::fmt;

/// The physical dimension a value must have (размерность).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dim {
    /// Length, SI m.
    Length,
    /// Plane angle, SI rad; a plain number is degrees.
    Angle,
    /// Angular velocity, SI rad/s (`rpm` = 2π/60 rad/s).
    AngularVelocity,
    /// Angular acceleration, SI rad/s².
    AngularAcceleration,
    /// Linear velocity, SI m/s.
    Velocity,
    /// Linear acceleration, SI m/s².
    Acceleration,
    /// Time, SI s.
    Time,
    /// Mass, SI kg.
    Mass,
    /// Mass per unit length of a link, SI kg/m.
    LinearDensity,
    /// Force, SI N.
    Force,
    /// Moment of a force or torque, SI N·m.
    Moment,
    /// Moment of inertia, SI kg·m².
    Inertia,
    /// Stress or pressure, SI Pa.
    Stress,
    /// A pure number (a ratio, a coefficient).
    Ratio,
}

impl Dim {
    /// The SI unit the dimension is stored in.
    pub fn si(self) -> &'static str {
        match self {
            Dim::Length => "m",
            Dim::Angle => "rad",
            Dim::AngularVelocity => "rad/s",
            Dim::AngularAcceleration => "rad/s²",
            Dim::Velocity => "m/s",
            Dim::Acceleration => "m/s²",
            Dim::Time => "s",
            Dim::Mass => "kg",
            Dim::LinearDensity => "kg/m",
            Dim::Force => "N",
            Dim::Moment => "N·m",
            Dim::Inertia => "kg·m²",
            Dim::Stress => "Pa",
            Dim::Ratio => "",
        }
    }

    /// Units accepted for the dimension, for error messages.
    pub fn accepted(self) -> &'static str {
        match self {
            Dim::Length => "m, mm, cm, dm, km, in, ft (a plain number is m)",
            Dim::Angle => "deg, °, rad, ' (arc minutes) (a plain number is degrees)",
            Dim::AngularVelocity => "rad/s, 1/s, s^-1, rpm, rev/min, об/мин, deg/s (a plain number is rad/s)",
            Dim::AngularAcceleration => "rad/s^2, rad/s², 1/s^2 (a plain number is rad/s²)",
            Dim::Velocity => "m/s, mm/s, km/h (a plain number is m/s)",
            Dim::Acceleration => "m/s^2, m/s², mm/s^2, g (a plain number is m/s²)",
            Dim::Time => "s, ms, min, h (a plain number is s)",
            Dim::Mass => "kg, g, t (a plain number is kg)",
            Dim::LinearDensity => "kg/m, g/mm, kg/mm (a plain number is kg/m)",
            Dim::Force => "N, kN, MN, kgf, кН, Н (a plain number is N)",
            Dim::Moment => "N·m, N*m, Nm, N m, kN·m, N·mm, Н·м (a plain number is N·m)",
            Dim::Inertia => "kg·m², kg*m^2, kg m2, kg·mm² (a plain number is kg·m²)",
            Dim::Stress => "Pa, kPa, MPa, GPa, N/mm², МПа (a plain number is Pa)",
            Dim::Ratio => "a plain number, a fraction like 1/3, or a percentage",
        }
    }

    /// A typical example of a well-formed value.
    pub fn example(self) -> &'static str {
        match self {
            Dim::Length => "\"120 mm\"",
            Dim::Angle => "\"15 deg\"",
            Dim::AngularVelocity => "\"900 rpm\"",
            Dim::AngularAcceleration => "\"0 rad/s^2\"",
            Dim::Velocity => "\"1.2 m/s\"",
            Dim::Acceleration => "\"9.81 m/s^2\"",
            Dim::Time => "\"0.5 s\"",
            Dim::Mass => "\"4.8 kg\"",
            Dim::LinearDensity => "\"10 kg/m\"",
            Dim::Force => "\"3 kN\"",
            Dim::Moment => "\"380 N·m\"",
            Dim::Inertia => "\"0.09 kg·m²\"",
            Dim::Stress => "\"120 MPa\"",
            Dim::Ratio => "0.25",
        }
    }
}

impl Dim {
    /// The indefinite article of the dimension's English name ("an angle").
    ///
    /// ```
    /// use tmm_geom::units::Dim;
    /// assert_eq!(format!("{} {}", Dim::Angle.article(), Dim::Angle), "an angle");
    /// assert_eq!(format!("{} {}", Dim::Length.article(), Dim::Length), "a length");
    /// ```
    pub fn article(self) -> &'static str {
        match self {
            Dim::Angle | Dim::AngularVelocity | Dim::AngularAcceleration | Dim::Acceleration => "an",
            _ => "a",
        }
    }
}

impl fmt::Display for Dim {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let s = match self {
            Dim::Length => "length",
            Dim::Angle => "angle",
            Dim::AngularVelocity => "angular velocity",
            Dim::AngularAcceleration => "angular acceleration",
            Dim::Velocity => "velocity",
            Dim::Acceleration => "acceleration",
            Dim::Time => "time",
            Dim::Mass => "mass",
            Dim::LinearDensity => "mass per length",
            Dim::Force => "force",
            Dim::Moment => "moment",
            Dim::Inertia => "moment of inertia",
            Dim::Stress => "stress",
            Dim::Ratio => "number",
        };
        f.write_str(s)
    }
}

/// A value that could not be read as the required quantity.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("cannot read `{input}` as {article} {dim}: {reason}; accepted units: {accepted}; e.g. {example}", article = dim.article(), accepted = dim.accepted(), example = dim.example())]
pub struct UnitError {
    /// The text as given.
    pub input: String,
    /// The dimension that was expected.
    pub dim: Dim,
    /// What went wrong.
    pub reason: String,
}

/// Parse a plain number (SI, or degrees for an angle) into SI.
///
/// ```
/// use tmm_geom::units::{from_number, Dim};
/// assert!((from_number(90.0, Dim::Angle).unwrap() - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
/// assert_eq!(from_number(0.12, Dim::Length).unwrap(), 0.12);
/// ```
pub fn from_number(x: f64, dim: Dim) -> Result<f64, UnitError> {
    if !x.is_finite() {
        return Err(UnitError {
            input: x.to_string(),
            dim,
            reason: "the number is not finite".into(),
        });
    }
    Ok(if dim == Dim::Angle { x.to_radians() } else { x })
}

/// Parse a quantity written with or without a unit into SI.
///
/// ```
/// use tmm_geom::units::{parse, Dim};
/// assert!((parse("120 mm", Dim::Length).unwrap() - 0.12).abs() < 1e-15);
/// assert!((parse("900 rpm", Dim::AngularVelocity).unwrap() - 30.0 * std::f64::consts::PI).abs() < 1e-12);
/// assert!((parse("15°", Dim::Angle).unwrap() - 15f64.to_radians()).abs() < 1e-15);
/// assert!((parse("0,51 m", Dim::Length).unwrap() - 0.51).abs() < 1e-15);
/// assert_eq!(parse("3 kN", Dim::Force).unwrap(), 3000.0);
/// assert!(parse("12 kg", Dim::Length).is_err());
/// ```
pub fn parse(text: &str, dim: Dim) -> Result<f64, UnitError> {
    let err = |reason: String| UnitError {
        input: text.to_string(),
        dim,
        reason,
    };
    let t = text.trim();
    if t.is_empty() {
        return Err(err("the value is empty".into()));
    }
    let (num, unit) = split_number(t).ok_or_else(|| err("it does not start with a number".into()))?;
    let unit = normalise(unit);
    if dim == Dim::Ratio {
        return match unit.as_str() {
            "" => from_number(num, dim),
            "%" => Ok(num / 100.0),
            u if u.starts_with('/') => {
                let den: f64 = u[1..]
                    .replace(',', ".")
                    .parse()
                    .map_err(|_| err(format!("`{u}` is not a fraction")))?;
                if den == 0.0 {
                    return Err(err("division by zero".into()));
                }
                Ok(num / den)
            }
            u => Err(err(format!("a plain number takes no unit, found `{u}`"))),
        };
    }
    if unit.is_empty() {
        return from_number(num, dim);
    }
    let factor = factor(dim, &unit).ok_or_else(|| err(format!("`{unit}` is not a unit of {dim}")))?;
    let v = num * factor;
    if !v.is_finite() {
        return Err(err("the value is not finite".into()));
    }
    Ok(v)
}

/// Split the leading number from the unit. Accepts `1.5e3`, `-2`, `0,12`.
fn split_number(t: &str) -> Option<(f64, &str)> {
    let bytes = t.as_bytes();
    let mut i = 0;
    if i < bytes.len() && (bytes[i] == b'+' || bytes[i] == b'-') {
        i += 1;
    }
    let start_digits = i;
    while i < bytes.len() && (bytes[i].is_ascii_digit() || bytes[i] == b'.' || bytes[i] == b',') {
        i += 1;
    }
    if i == start_digits {
        return None;
    }
    let i = exponent_end(bytes, i);
    let num_txt = t[..i].replace(',', ".");
    let num: f64 = num_txt.parse().ok()?;
    Some((num, t[i..].trim()))
}

/// The end of the exponent (`e`, an optional sign, digits) that may follow a
/// mantissa ending at `i`; `i` itself when there is none. Shared by every
/// scan of numbers in text, so that they agree on what an exponent is.
///
/// ```
/// use tmm_geom::units::exponent_end;
/// assert_eq!(exponent_end(b"1.5e-3 m", 3), 6);
/// assert_eq!(exponent_end(b"2 mm", 1), 1);
/// assert_eq!(exponent_end(b"3e m", 1), 1); // an `e` without digits is not one
/// ```
pub fn exponent_end(bytes: &[u8], i: usize) -> usize {
    if i < bytes.len() && (bytes[i] == b'e' || bytes[i] == b'E') {
        let mut j = i + 1;
        if j < bytes.len() && (bytes[j] == b'+' || bytes[j] == b'-') {
            j += 1;
        }
        let digits = j;
        while j < bytes.len() && bytes[j].is_ascii_digit() {
            j += 1;
        }
        if j > digits {
            return j;
        }
    }
    i
}

/// Fold the many ways of writing a unit into one spelling.
fn normalise(u: &str) -> String {
    let mut s = String::with_capacity(u.len());
    for c in u.chars() {
        match c {
            ' ' | '\t' => {}
            '·' | '⋅' | '•' | '×' => s.push('*'),
            '²' => s.push_str("^2"),
            '³' => s.push_str("^3"),
            '⁻' => s.push_str("^-"),
            '¹' => s.push('1'),
            'µ' | 'μ' => s.push('u'),
            _ => s.push(c),
        }
    }
    // "N m" became "Nm"; "kg m2" became "kgm2": make exponents explicit.
    s.replace("m2", "m^2").replace("s2", "s^2").replace("^^", "^")
}

fn factor(dim: Dim, u: &str) -> Option<f64> {
    use std::f64::consts::PI;
    let len = |u: &str| -> Option<f64> {
        Some(match u {
            "m" | "м" => 1.0,
            "mm" | "мм" => 1e-3,
            "cm" | "см" => 1e-2,
            "dm" | "дм" => 1e-1,
            "km" | "км" => 1e3,
            "um" | "мкм" => 1e-6,
            "in" | "\"" => 0.0254,
            "ft" => 0.3048,
            _ => return None,
        })
    };
    let force = |u: &str| -> Option<f64> {
        Some(match u {
            "N" | "Н" => 1.0,
            "kN" | "кН" => 1e3,
            "MN" | "МН" => 1e6,
            "kgf" | "кгс" => 9.80665,
            _ => return None,
        })
    };
    let time = |u: &str| -> Option<f64> {
        Some(match u {
            "s" | "с" | "sec" => 1.0,
            "ms" | "мс" => 1e-3,
            "min" | "мин" => 60.0,
            "h" | "ч" => 3600.0,
            _ => return None,
        })
    };
    let mass = |u: &str| -> Option<f64> {
        Some(match u {
            "kg" | "кг" => 1.0,
            "g" | "г" => 1e-3,
            "t" | "т" => 1e3,
            _ => return None,
        })
    };
    match dim {
        Dim::Length => len(u),
        Dim::Angle => match u {
            "deg" | "°" | "degree" | "degrees" | "град" => Some(PI / 180.0),
            "rad" | "рад" => Some(1.0),
            "'" | "arcmin" | "′" => Some(PI / 180.0 / 60.0),
            "rev" | "об" | "turn" => Some(2.0 * PI),
            _ => None,
        },
        Dim::AngularVelocity => match u {
            "rad/s" | "1/s" | "s^-1" | "рад/с" | "1/с" | "с^-1" => Some(1.0),
            "rpm" | "rev/min" | "об/мин" | "r/min" | "min^-1" | "мин^-1" => Some(2.0 * PI / 60.0),
            "deg/s" | "°/s" => Some(PI / 180.0),
            "rps" | "rev/s" | "об/с" => Some(2.0 * PI),
            _ => None,
        },
        Dim::AngularAcceleration => match u {
            "rad/s^2" | "1/s^2" | "s^-2" | "рад/с^2" | "1/с^2" => Some(1.0),
            "deg/s^2" => Some(PI / 180.0),
            _ => None,
        },
        Dim::Velocity => {
            if u == "km/h" || u == "км/ч" {
                return Some(1.0 / 3.6);
            }
            let (l, t) = u.split_once('/')?;
            Some(len(l)? / time(t)?)
        }
        Dim::Acceleration => {
            if u == "g" {
                return Some(9.80665);
            }
            let (l, t) = u.split_once('/')?;
            let t = t.strip_suffix("^2")?;
            let tt = time(t)?;
            Some(len(l)? / (tt * tt))
        }
        Dim::Time => time(u),
        Dim::Mass => mass(u),
        Dim::LinearDensity => {
            let (m, l) = u.split_once('/')?;
            Some(mass(m)? / len(l)?)
        }
        Dim::Force => force(u),
        Dim::Moment => {
            // N*m, Nm, kN*m, N*mm
            let (f, l) = if let Some((f, l)) = u.split_once('*') {
                (f, l)
            } else {
                let idx = u
                    .char_indices()
                    .find(|&(i, _)| i > 0 && force(&u[..i]).is_some() && len(&u[i..]).is_some())?
                    .0;
                (&u[..idx], &u[idx..])
            };
            Some(force(f)? * len(l)?)
        }
        Dim::Inertia => {
            let rest = u.strip_prefix("kg").or_else(|| u.strip_prefix("кг"))?;
            let rest = rest.strip_prefix('*').unwrap_or(rest);
            let l = rest.strip_suffix("^2")?;
            let f = len(l)?;
            Some(f * f)
        }
        Dim::Stress => match u {
            "Pa" | "Па" => Some(1.0),
            "kPa" | "кПа" => Some(1e3),
            "MPa" | "МПа" | "N/mm^2" | "Н/мм^2" => Some(1e6),
            "GPa" | "ГПа" => Some(1e9),
            _ => None,
        },
        Dim::Ratio => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() <= 1e-12 * b.abs().max(1.0)
    }

    #[test]
    fn spellings() {
        assert!(close(parse("380 N·m", Dim::Moment).unwrap(), 380.0));
        assert!(close(parse("380 Nm", Dim::Moment).unwrap(), 380.0));
        assert!(close(parse("380 N m", Dim::Moment).unwrap(), 380.0));
        assert!(close(parse("2 kN*m", Dim::Moment).unwrap(), 2000.0));
        assert!(close(parse("1500 N·mm", Dim::Moment).unwrap(), 1.5));
        assert!(close(parse("0.5 kg·m²", Dim::Inertia).unwrap(), 0.5));
        assert!(close(parse("0.5 kg m2", Dim::Inertia).unwrap(), 0.5));
        assert!(close(parse("2e6 kg*mm^2", Dim::Inertia).unwrap(), 2.0));
        assert!(close(parse("10 kg/m", Dim::LinearDensity).unwrap(), 10.0));
        assert!(close(parse("120 MPa", Dim::Stress).unwrap(), 120e6));
        assert!(close(parse("120 N/mm²", Dim::Stress).unwrap(), 120e6));
        assert!(close(parse("200 s⁻¹", Dim::AngularVelocity).unwrap(), 200.0));
        assert!(close(parse("60 об/мин", Dim::AngularVelocity).unwrap(), 2.0 * PI));
        assert!(close(parse("9.81 m/s²", Dim::Acceleration).unwrap(), 9.81));
        assert!(close(parse("1 in", Dim::Length).unwrap(), 0.0254));
        assert!(close(parse("1/3", Dim::Ratio).unwrap(), 1.0 / 3.0));
        assert!(close(parse("-1.5e-3 m", Dim::Length).unwrap(), -1.5e-3));
        assert!(close(parse("36 km/h", Dim::Velocity).unwrap(), 10.0));
        assert!(close(parse("30'", Dim::Angle).unwrap(), 0.5f64.to_radians()));
    }

    #[test]
    fn malformed() {
        for (t, d) in [
            ("", Dim::Length),
            ("mm", Dim::Length),
            ("12 furlongs", Dim::Length),
            ("3 kg", Dim::Force),
            ("1/0", Dim::Ratio),
            ("1e999 m", Dim::Length),
        ] {
            let e = parse(t, d).unwrap_err();
            assert!(e.to_string().contains("accepted units"), "{e}");
        }
    }
}
