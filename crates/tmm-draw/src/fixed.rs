//! Fixed-point numbers for the writers (число с фиксированной точкой): the
//! text `format!("{v:.N}")` gives, written without the standard library's
//! exact decimal expansion.
//!
//! Writing a sheet's SVG and DXF formats some hundred thousand coordinates,
//! and `{:.3}` spends most of its time in the exact (arbitrary-precision)
//! rounding it needs for any float. A coordinate on paper is far from the
//! cases that need it: for |v| < 2⁵³ / 10^N the value v·10^N is rounded to
//! the nearest integer, which is the exact rounding unless v·10^N lies
//! within its own rounding error of a half; such ties (and huge, tiny or
//! non-finite values) go to the standard formatting, so the text is always
//! the same as `format!("{v:.N}")` (tested against it on 200 000 values in six precisions).

use std::fmt::{self, Write};

/// The largest number of decimals written by the fast path.
const MAX_DECIMALS: usize = 9;

/// `v` with `decimals` digits after the point, exactly as
/// `format!("{v:.decimals$}")` writes it.
///
/// ```
/// use tmm_draw::fixed::Fixed;
/// assert_eq!(Fixed(2.0 / 3.0, 3).to_string(), "0.667");
/// assert_eq!(Fixed(-12.5, 2).to_string(), "-12.50");
/// assert_eq!(Fixed(1e300, 1).to_string(), format!("{:.1}", 1e300));
/// ```
#[derive(Clone, Copy, Debug)]
pub struct Fixed(pub f64, pub usize);

impl fmt::Display for Fixed {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let Fixed(v, d) = *self;
        match fast(v, d) {
            Some((negative, int, frac)) => {
                if negative {
                    f.write_char('-')?;
                }
                write!(f, "{int}")?;
                if d > 0 {
                    // `frac` < 10^d, written with its leading zeros
                    let mut digits = [b'0'; MAX_DECIMALS];
                    let mut x = frac;
                    for slot in digits[..d].iter_mut().rev() {
                        *slot = b'0' + (x % 10) as u8;
                        x /= 10;
                    }
                    f.write_char('.')?;
                    // the digits are ASCII by construction
                    f.write_str(std::str::from_utf8(&digits[..d]).unwrap_or("0"))?;
                }
                Ok(())
            }
            None => write!(f, "{v:.d$}"),
        }
    }
}

/// The sign, integer part and fraction (in units of 10^-d) of `v` rounded to
/// `d` decimals, or `None` where the standard formatting must decide.
fn fast(v: f64, d: usize) -> Option<(bool, u64, u64)> {
    if d > MAX_DECIMALS || !v.is_finite() {
        return None;
    }
    let p = 10u64.pow(d as u32);
    let scaled = v.abs() * p as f64;
    // below 2^52 the product's rounding error is under 2^-1 of a unit…
    if scaled >= 4.0e15 {
        return None;
    }
    let floor = scaled.floor();
    let rest = scaled - floor;
    // …and a value this close to a half may round either way exactly
    if (rest - 0.5).abs() < 1e-6 * scaled.max(1.0) * f64::EPSILON * 1e9 {
        return None;
    }
    let n = if rest > 0.5 { floor as u64 + 1 } else { floor as u64 };
    // std writes the sign of a negative value even when it rounds to zero
    Some((v.is_sign_negative(), n / p, n % p))
}

/// Append `v` with `decimals` digits to `out` (see [`Fixed`]).
///
/// ```
/// let mut s = String::from("x=");
/// tmm_draw::fixed::push(&mut s, 0.1 + 0.2, 3);
/// assert_eq!(s, "x=0.300");
/// ```
pub fn push(out: &mut String, v: f64, decimals: usize) {
    let _ = write!(out, "{}", Fixed(v, decimals));
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A small deterministic generator (xorshift), so the test needs no crate.
    fn next(state: &mut u64) -> u64 {
        *state ^= *state << 13;
        *state ^= *state >> 7;
        *state ^= *state << 17;
        *state
    }

    #[test]
    fn equals_the_standard_formatting_on_random_and_tie_values() {
        let mut s = 0x9e37_79b9_7f4a_7c15u64;
        for i in 0..200_000u64 {
            let r = next(&mut s);
            let v = match i % 4 {
                // paper coordinates
                0 => (r % 2_000_000_000) as f64 / 1e6 - 1000.0,
                // exact decimal ties and their neighbours
                1 => ((r % 200_000) as f64 + 0.5) / 1000.0 * if r & 1 == 0 { 1.0 } else { -1.0 },
                // any bit pattern
                2 => f64::from_bits(r),
                // small magnitudes around the rounding to zero
                _ => ((r % 20_000) as f64 - 10_000.0) * 1e-7,
            };
            for d in [0usize, 1, 2, 3, 4, 6] {
                assert_eq!(Fixed(v, d).to_string(), format!("{v:.d$}"), "{v:e} with {d} decimals");
            }
        }
    }

    #[test]
    fn specials_are_as_the_standard_writes_them() {
        for v in [
            0.0,
            -0.0,
            f64::NAN,
            f64::INFINITY,
            -f64::INFINITY,
            1e300,
            -1e-300,
            4.5e15,
            0.0005,
            1.0005,
        ] {
            for d in [0usize, 3, 9, 12] {
                assert_eq!(Fixed(v, d).to_string(), format!("{v:.d$}"));
            }
        }
    }
}
