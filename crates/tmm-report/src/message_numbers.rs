//! Numbers in messages (числа в сообщениях об ошибках): a value written in
//! full by a library's message — `1e300` becomes 301 digits, `1e-300 mm` 300
//! zeros, `0.1 + 0.2` seventeen digits — is shown with six significant digits,
//! in exponent form when it is very large or very small.
//!
//! Every input error passes through [`crate::Error::input`] or
//! [`crate::Error::at`], which apply [`tidy`] to the message and its help, so
//! no message of any section, on the command line or in the page, can carry
//! such a number.

use tmm_geom::units::exponent_end;
use tmm_linkage::synthesis::error::show;

/// The most digits a number in a message keeps as written; longer ones are
/// shown by [`show`]. Twelve keeps every tooth number (`u32::MAX` has 10
/// digits) and every value printed to four decimals below 10⁷.
pub const MAX_DIGITS: usize = 12;

/// `text` with every number of more than [`MAX_DIGITS`] digits rewritten by
/// [`show`]; all else is kept as it is. A number is a run of digits with at
/// most one decimal point and an optional exponent, not glued to a letter,
/// digit or `_` before it (so `z1`, `x2` and `task.toml:12:9` are left alone).
///
/// ```
/// use tmm_report::message_numbers::tidy;
/// let huge = format!("the shift sum {:.4} is too large", 1e300);
/// assert_eq!(tidy(&huge), "the shift sum 1e300 is too large");
/// let tiny = format!("got {} mm", 1e-300);
/// assert_eq!(tidy(&tiny), "got 1e-300 mm");
/// assert_eq!(tidy("x = 0.30000000000000004, z1 = 4294967295"), "x = 0.3, z1 = 4294967295");
/// assert_eq!(tidy("task.toml:12:9: gear.z1: -999999999999.0000"), "task.toml:12:9: gear.z1: -1e12");
/// ```
pub fn tidy(text: &str) -> String {
    let b = text.as_bytes();
    let mut out = String::with_capacity(text.len());
    let mut done = 0; // bytes of `text` already copied
    let mut i = 0;
    while i < b.len() {
        let glued = i > 0 && (b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'_' || b[i - 1] == b'.');
        if !b[i].is_ascii_digit() || glued {
            i += 1;
            continue;
        }
        let (end, digits) = number_end(b, i);
        if digits > MAX_DIGITS
            && let Ok(v) = text[i..end].parse::<f64>()
            && v.is_finite()
        {
            out.push_str(&text[done..i]);
            out.push_str(&show(v));
            done = end;
        }
        i = end;
    }
    out.push_str(&text[done..]);
    out
}

/// The end of the number that starts at `b[start]` (a digit) and how many
/// digits its mantissa has.
fn number_end(b: &[u8], start: usize) -> (usize, usize) {
    let mut i = start;
    let mut digits = 0;
    let mut point = false;
    while i < b.len() {
        if b[i].is_ascii_digit() {
            digits += 1;
        } else if b[i] == b'.' && !point && b.get(i + 1).is_some_and(u8::is_ascii_digit) {
            point = true;
        } else {
            break;
        }
        i += 1;
    }
    (exponent_end(b, i), digits)
}
