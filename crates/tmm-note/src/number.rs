//! Numbers for the note: a fixed count of significant digits, the decimal
//! comma for ru/uk and the point for en, the minus sign (U+2212), and a thin
//! space before the unit.
//!
//! The digits come from Rust's `{:e}` formatting, which rounds the exact
//! binary value correctly (round half to even on the decimal expansion), and
//! are then placed by string manipulation, so no second rounding happens.
//! Fixed notation is used for 10⁻³ ≤ |x| < 10⁶, otherwise `1,23·10⁵`.
//!
//! The space between a number and its unit is U+202F NARROW NO-BREAK SPACE:
//! a thin space (GOST 8.417 writes a space between the number and the unit)
//! that never breaks the line between them. Degrees, minutes and seconds of
//! angle stand without a space (`30°`), as GOST 8.417 prescribes.

use std::fmt;

use crate::error::NoteError;
use crate::model::Lang;

/// The thin, non-breaking space placed between a number and its unit.
pub const UNIT_SPACE: char = '\u{202F}';

/// The minus sign (not the hyphen-minus).
pub const MINUS: char = '\u{2212}';

/// A number formatted for a language: the mantissa with its decimal separator
/// and, for very large or small values, a power of ten.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Formatted {
    /// The digits with the sign and the decimal separator, e.g. `−12,35`.
    pub mantissa: String,
    /// The power of ten, if the value is written as `mantissa·10^exponent`.
    pub exponent: Option<i32>,
}

impl fmt::Display for Formatted {
    /// Plain text with superscript digits for the exponent: `1,23·10⁵`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.mantissa)?;
        if let Some(e) = self.exponent {
            f.write_str("·10")?;
            for c in e.to_string().chars() {
                let sup = match c {
                    '-' => '⁻',
                    '0' => '⁰',
                    '1' => '¹',
                    '2' => '²',
                    '3' => '³',
                    '4' => '⁴',
                    '5' => '⁵',
                    '6' => '⁶',
                    '7' => '⁷',
                    '8' => '⁸',
                    _ => '⁹',
                };
                write!(f, "{sup}")?;
            }
        }
        Ok(())
    }
}

/// Formats `value` with `digits` significant digits for `lang`.
///
/// ```
/// use tmm_note::{Lang, number::format_number};
/// assert_eq!(format_number(12.3456, 4, Lang::Ru).unwrap().to_string(), "12,35");
/// assert_eq!(format_number(12.3456, 4, Lang::En).unwrap().to_string(), "12.35");
/// assert_eq!(format_number(-0.0012345, 3, Lang::Uk).unwrap().to_string(), "\u{2212}0,00123");
/// assert_eq!(format_number(1.5e7, 2, Lang::Ru).unwrap().to_string(), "1,5·10⁷");
/// assert!(format_number(f64::NAN, 3, Lang::Ru).is_err());
/// ```
///
/// # Errors
/// [`NoteError::NonFinite`] for NaN or infinity, [`NoteError::Digits`] when
/// `digits` is not in 1 … 17.
pub fn format_number(value: f64, digits: u8, lang: Lang) -> Result<Formatted, NoteError> {
    if !value.is_finite() {
        return Err(NoteError::NonFinite { value: value.to_string() });
    }
    if !(1..=17).contains(&digits) {
        return Err(NoteError::Digits { digits });
    }
    // a zero is written `0`: four significant digits of nothing ("0,000")
    // say nothing
    if value == 0.0 {
        return Ok(Formatted {
            mantissa: "0".to_string(),
            exponent: None,
        });
    }
    let sci = format!("{:.*e}", usize::from(digits - 1), value.abs());
    // `sci` is `d.ddddde±x` (or `de±x` for one digit); split it.
    let (mant, exp) = sci.split_once('e').unwrap_or((sci.as_str(), "0"));
    let exp: i32 = exp.parse().unwrap_or(0);
    let sig: String = mant.chars().filter(char::is_ascii_digit).collect();
    let negative = value < 0.0 && sig.chars().any(|c| c != '0');
    let sep = lang.decimal_separator();

    let (body, exponent) = if (-3..6).contains(&exp) {
        (place_point(&sig, exp, sep), None)
    } else {
        (place_point(&sig, 0, sep), Some(exp))
    };
    let mut mantissa = String::with_capacity(body.len() + 3);
    if negative {
        mantissa.push(MINUS);
    }
    mantissa.push_str(&body);
    Ok(Formatted { mantissa, exponent })
}

/// The resolution of the run's computations relative to a quantity's
/// scale: a value whose magnitude is at most `RESOLUTION` times the largest
/// magnitude of its kind (its table column, the terms of its formula, a
/// full turn for an angle) is the solver's noise around an exact zero and
/// is printed `0`. The solvers close their loops to 10⁻⁶ of the
/// mechanism's size (tmm-linkage's assembly tolerance) or better, so a
/// value under it carries no digit of its own; four printed significant
/// digits resolve 5·10⁻⁴ of a value, so nothing printed is lost.
/// docs/note.md, "Numbers", gives the rule.
pub const RESOLUTION: f64 = 1e-6;

/// A magnitude under which a value is an exact zero's rounding noise
/// whatever its scale (a quantity with no scale known, a column of zeros).
pub const ZERO_FLOOR: f64 = 1e-9;

/// `value`, or 0 where it is under the computation's resolution relative
/// to `scale`, the largest magnitude of its kind ([`RESOLUTION`]), or under
/// [`ZERO_FLOOR`].
///
/// ```
/// use tmm_note::number::zero_noise;
/// // 1,2·10⁻⁶° against a full turn is the solver's noise
/// assert_eq!(zero_noise(1.2e-6, 360.0), 0.0);
/// // a small value of its own column's size is kept
/// assert_eq!(zero_noise(0.0012, 0.005), 0.0012);
/// assert_eq!(zero_noise(3e-4, 100.0), 3e-4);
/// assert_eq!(zero_noise(3e-4, 1000.0), 0.0);
/// assert_eq!(zero_noise(3e-12, 0.0), 0.0);
/// ```
pub fn zero_noise(value: f64, scale: f64) -> f64 {
    let a = value.abs();
    if a <= RESOLUTION * scale.abs() || a < ZERO_FLOOR {
        0.0
    } else {
        value
    }
}

/// Writes the significant digits `sig` (the first one of weight 10^exp) in
/// fixed notation with the separator `sep`.
fn place_point(sig: &str, exp: i32, sep: char) -> String {
    let mut out = String::with_capacity(sig.len() + 8);
    if exp < 0 {
        out.push('0');
        out.push(sep);
        for _ in 0..(-exp - 1) {
            out.push('0');
        }
        out.push_str(sig);
    } else {
        let int_len = usize::try_from(exp).unwrap_or(0) + 1;
        if sig.len() <= int_len {
            out.push_str(sig);
            for _ in sig.len()..int_len {
                out.push('0');
            }
        } else {
            out.push_str(&sig[..int_len]);
            out.push(sep);
            out.push_str(&sig[int_len..]);
        }
    }
    out
}

/// Formats a quantity: the number as [`format_number`] does, then the unit
/// after a thin non-breaking space ([`UNIT_SPACE`]); `°`, `′` and `″` follow
/// the number directly; an empty unit adds nothing.
///
/// ```
/// use tmm_note::{Lang, number::format_quantity};
/// assert_eq!(format_quantity(1234.5, 3, "Н", Lang::Ru).unwrap(), "1230\u{202F}Н");
/// assert_eq!(format_quantity(0.25, 2, "m", Lang::En).unwrap(), "0.25\u{202F}m");
/// assert_eq!(format_quantity(30.0, 2, "°", Lang::Uk).unwrap(), "30°");
/// ```
///
/// # Errors
/// As [`format_number`].
pub fn format_quantity(value: f64, digits: u8, unit: &str, lang: Lang) -> Result<String, NoteError> {
    let mut s = format_number(value, digits, lang)?.to_string();
    push_unit(&mut s, unit);
    Ok(s)
}

/// Appends `unit` to a formatted number with the right spacing.
pub(crate) fn push_unit(s: &mut String, unit: &str) {
    if unit.is_empty() {
        return;
    }
    if !matches!(unit.chars().next(), Some('°' | '′' | '″')) {
        s.push(UNIT_SPACE);
    }
    s.push_str(unit);
}

/// A number as a fragment of typst math (for [`crate::Block::Formula`]):
/// quoted as text, so the decimal comma is not read as math punctuation, and
/// `"1,5" dot 10^(−7)` for a power of ten.
///
/// ```
/// use tmm_note::{Lang, number::math_number};
/// assert_eq!(math_number(12.3456, 4, Lang::Ru).unwrap(), "\"12,35\"");
/// assert_eq!(math_number(1.5e-7, 2, Lang::En).unwrap(), "\"1.5\" dot 10^(\u{2212}7)");
/// ```
///
/// # Errors
/// As [`format_number`].
pub fn math_number(value: f64, digits: u8, lang: Lang) -> Result<String, NoteError> {
    let f = format_number(value, digits, lang)?;
    Ok(match f.exponent {
        None => format!("\"{}\"", f.mantissa),
        Some(e) => format!("\"{}\" dot 10^({})", f.mantissa, e.to_string().replace('-', "\u{2212}")),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ru(v: f64, d: u8) -> String {
        format_number(v, d, Lang::Ru).unwrap().to_string()
    }

    #[test]
    fn significant_digits_and_comma() {
        assert_eq!(ru(3.14659, 3), "3,15");
        assert_eq!(ru(3.14659, 1), "3");
        assert_eq!(ru(0.5, 3), "0,500");
        assert_eq!(ru(100.0, 3), "100");
        assert_eq!(ru(100.0, 4), "100,0");
        assert_eq!(ru(123456.0, 3), "123000");
        assert_eq!(ru(0.001, 2), "0,0010");
        assert_eq!(ru(0.0, 3), "0");
        assert_eq!(ru(-0.0, 3), "0");
        assert_eq!(format_number(2.5, 2, Lang::En).unwrap().to_string(), "2.5");
        assert_eq!(format_number(2.5, 2, Lang::Uk).unwrap().to_string(), "2,5");
    }

    #[test]
    fn rounding_carries_into_a_new_digit() {
        // 9.996 to 3 digits is 10.0, not 9.100 or 10.00.
        assert_eq!(ru(9.996, 3), "10,0");
        assert_eq!(ru(999_999.7, 3), "1,00·10⁶");
        assert_eq!(ru(0.000_999_96, 3), "0,00100");
    }

    #[test]
    fn sign_uses_the_minus_and_drops_on_a_rounded_zero() {
        assert_eq!(ru(-2.0, 2), "\u{2212}2,0");
        assert_eq!(ru(-0.0, 2), "0");
    }

    #[test]
    fn scientific_outside_the_fixed_range() {
        let f = format_number(1.234e-5, 3, Lang::Ru).unwrap();
        assert_eq!(f.mantissa, "1,23");
        assert_eq!(f.exponent, Some(-5));
        assert_eq!(f.to_string(), "1,23·10⁻⁵");
        let f = format_number(-4.0e8, 2, Lang::En).unwrap();
        assert_eq!(f.to_string(), "\u{2212}4.0·10⁸");
    }

    #[test]
    fn bad_input_is_an_error() {
        assert!(matches!(
            format_number(f64::INFINITY, 3, Lang::Ru),
            Err(NoteError::NonFinite { .. })
        ));
        assert!(matches!(format_number(1.0, 0, Lang::Ru), Err(NoteError::Digits { digits: 0 })));
        assert!(matches!(format_number(1.0, 18, Lang::Ru), Err(NoteError::Digits { digits: 18 })));
    }

    #[test]
    fn units_take_a_thin_space_except_angles() {
        assert_eq!(format_quantity(12.0, 3, "рад/с", Lang::Ru).unwrap(), "12,0\u{202F}рад/с");
        assert_eq!(format_quantity(45.0, 2, "°", Lang::Ru).unwrap(), "45°");
        assert_eq!(format_quantity(7.0, 1, "", Lang::Ru).unwrap(), "7");
    }
}
