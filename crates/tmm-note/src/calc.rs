//! Worked formulas (расчётная формула с подстановкой чисел): a formula held
//! as data — the quantity sought, an expression tree of named quantities
//! (symbol + value) and exact constants — from which both the typeset text
//! and the numeric check come.
//!
//! A [`Calculation`] typesets as the course's notes write a calculation
//! (seeds 001, 003, 004): the symbol, `=`, the formula in symbols, `=`, the
//! same formula with the run's numbers as printed, `=`, the result with its
//! unit, e.g. `θ = 180° (K_v − 1)/(K_v + 1) = 180° ("1,107" − 1)/("1,107" + 1)
//! = "9,100°"`; a long one breaks after the symbolic part.
//!
//! [`Calculation::check`] evaluates the substituted expression with every
//! number *as printed* (rounded to its digits) and requires it to equal the
//! printed result within the rounding of the inputs and of the result
//! (a first-order bound: each input moved by half a unit of its last printed
//! digit). So a formula whose sign, factor or term is wrong as typeset fails,
//! whatever the code that computed the result did.

use crate::error::NoteError;
use crate::model::Lang;
use crate::number::{format_number, math_number};

/// A named quantity of a formula: its typst-math symbol, its value in the
/// unit printed (degrees for an angle) and the significant digits printed.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Quantity {
    /// The symbol in typst math, e.g. `K_v`, `omega_1`, `l_(O A)`.
    pub symbol: String,
    /// The value in the unit printed.
    pub value: f64,
    /// The unit printed after the result (`Н·м`, `°`); empty for none.
    pub unit: String,
    /// Significant digits printed; 0 for a count (an exact integer, printed
    /// whole).
    pub digits: u8,
}

impl Quantity {
    /// A count: an exact integer printed whole.
    pub fn count(symbol: &str, n: f64) -> Self {
        Quantity {
            digits: 0,
            ..Quantity::new(symbol, n, "")
        }
    }

    /// A quantity printed with [`crate::compose::DIGITS`] digits.
    ///
    /// ```
    /// let q = tmm_note::calc::Quantity::new("omega_1", 94.25, "рад/с");
    /// assert_eq!(q.digits, 4);
    /// ```
    pub fn new(symbol: &str, value: f64, unit: &str) -> Self {
        Quantity {
            symbol: symbol.to_string(),
            value,
            unit: unit.to_string(),
            digits: crate::compose::DIGITS,
        }
    }

    /// The value as printed: rounded to `digits` significant digits.
    fn printed(&self) -> Result<(f64, f64), NoteError> {
        printed_and_half_ulp(self.value, self.digits)
    }
}

/// A function of an angle given in degrees, or the involute.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Func {
    /// sin of an angle in degrees.
    Sin,
    /// cos of an angle in degrees.
    Cos,
    /// tan of an angle in degrees.
    Tan,
    /// The involute inv α = tan α − α of an angle in degrees.
    Inv,
}

impl Func {
    fn name(self) -> &'static str {
        match self {
            Func::Sin => "sin",
            Func::Cos => "cos",
            Func::Tan => "tan",
            Func::Inv => "\"inv\"",
        }
    }

    fn eval(self, deg: f64) -> f64 {
        let a = deg.to_radians();
        match self {
            Func::Sin => a.sin(),
            Func::Cos => a.cos(),
            Func::Tan => a.tan(),
            Func::Inv => a.tan() - a,
        }
    }
}

/// An expression of a worked formula.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub enum Expr {
    /// A named quantity: its symbol in the symbolic line, its printed value
    /// in the numeric line.
    Q(Quantity),
    /// An exact constant, printed the same in both lines (`2`, `180°`, `pi`).
    Exact {
        /// The typst math of the constant.
        math: String,
        /// Its value.
        value: f64,
    },
    /// `a + b + …` (a negative number after the first term in parentheses).
    Sum(Vec<Expr>),
    /// `a − b`.
    Sub(Box<Expr>, Box<Expr>),
    /// `a · b · …`: juxtaposed in symbols, with `·` between numbers.
    Mul(Vec<Expr>),
    /// `a / b` as a fraction.
    Div(Box<Expr>, Box<Expr>),
    /// `−a`.
    Neg(Box<Expr>),
    /// `a^n`.
    Pow(Box<Expr>, i32),
    /// `(a)`.
    Paren(Box<Expr>),
    /// `f a` with the argument in degrees.
    Func(Func, Box<Expr>),
    /// A sum written as one symbol (`sum_i P_i`) in the symbolic line and
    /// term by term in the numeric line.
    Terms {
        /// The typst math of the sum in symbols.
        symbol: String,
        /// The terms.
        terms: Vec<Expr>,
    },
}

/// Builders, so a composer writes `mul([exact(180.0, "180°"), …])`.
impl Expr {
    /// The value with every quantity as printed (`printed = true`) or exact.
    fn eval(&self, printed: bool, bump: Option<(usize, f64)>, counter: &mut usize) -> Result<f64, NoteError> {
        Ok(match self {
            Expr::Q(q) => {
                let i = *counter;
                *counter += 1;
                let v = if printed { q.printed()?.0 } else { q.value };
                match bump {
                    Some((j, d)) if j == i => v + d,
                    _ => v,
                }
            }
            Expr::Exact { value, .. } => *value,
            Expr::Sum(v) | Expr::Terms { terms: v, .. } => {
                let mut s = 0.0;
                for e in v {
                    s += e.eval(printed, bump, counter)?;
                }
                s
            }
            Expr::Sub(a, b) => a.eval(printed, bump, counter)? - b.eval(printed, bump, counter)?,
            Expr::Mul(v) => {
                let mut p = 1.0;
                for e in v {
                    p *= e.eval(printed, bump, counter)?;
                }
                p
            }
            Expr::Div(a, b) => a.eval(printed, bump, counter)? / b.eval(printed, bump, counter)?,
            Expr::Neg(a) => -a.eval(printed, bump, counter)?,
            Expr::Pow(a, n) => a.eval(printed, bump, counter)?.powi(*n),
            Expr::Paren(a) => a.eval(printed, bump, counter)?,
            Expr::Func(f, a) => f.eval(a.eval(printed, bump, counter)?),
        })
    }

    /// Calls `f` on each quantity (not a count) that is a term of the
    /// expression's sum (`terms`: under sums, differences, negations and
    /// parentheses only), or on every quantity (`terms` false).
    fn denoise(&mut self, f: &mut dyn FnMut(&mut Quantity), terms: bool) {
        match self {
            Expr::Q(q) => {
                if q.digits > 0 {
                    f(q);
                }
            }
            Expr::Exact { .. } => {}
            Expr::Sum(v) | Expr::Terms { terms: v, .. } => v.iter_mut().for_each(|e| e.denoise(f, terms)),
            Expr::Sub(a, b) => {
                a.denoise(f, terms);
                b.denoise(f, terms);
            }
            Expr::Neg(a) | Expr::Paren(a) => a.denoise(f, terms),
            Expr::Mul(v) if !terms => v.iter_mut().for_each(|e| e.denoise(f, terms)),
            Expr::Div(a, b) if !terms => {
                a.denoise(f, terms);
                b.denoise(f, terms);
            }
            Expr::Pow(a, _) | Expr::Func(_, a) if !terms => a.denoise(f, terms),
            Expr::Mul(_) | Expr::Div(..) | Expr::Pow(..) | Expr::Func(..) => {}
        }
    }

    /// The quantities in the order [`Expr::eval`] meets them.
    fn quantities<'a>(&'a self, out: &mut Vec<&'a Quantity>) {
        match self {
            Expr::Q(q) => out.push(q),
            Expr::Exact { .. } => {}
            Expr::Sum(v) | Expr::Mul(v) | Expr::Terms { terms: v, .. } => v.iter().for_each(|e| e.quantities(out)),
            Expr::Sub(a, b) | Expr::Div(a, b) => {
                a.quantities(out);
                b.quantities(out);
            }
            Expr::Neg(a) | Expr::Pow(a, _) | Expr::Paren(a) | Expr::Func(_, a) => a.quantities(out),
        }
    }

    /// The typst math: symbols (`numbers = false`) or printed numbers.
    fn math(&self, numbers: bool, lang: Lang) -> Result<String, NoteError> {
        Ok(match self {
            Expr::Q(q) => {
                if numbers {
                    let (p, _) = q.printed()?;
                    let mut m = number_math(p, q.digits, lang)?;
                    if q.unit.starts_with('°') {
                        // the degree sign follows the number inside the quotes
                        m.insert(m.rfind('"').unwrap_or(m.len()), '°');
                    }
                    if p < 0.0 { format!("({m})") } else { m }
                } else {
                    q.symbol.clone()
                }
            }
            Expr::Exact { math, .. } => math.clone(),
            Expr::Terms { symbol, .. } if !numbers => symbol.clone(),
            Expr::Sum(v) | Expr::Terms { terms: v, .. } => join_terms(&sum_terms(v, numbers, lang)?, usize::MAX),
            Expr::Sub(a, b) => format!("{} - {}", a.math(numbers, lang)?, b.math(numbers, lang)?),
            Expr::Mul(v) => {
                let sep = if numbers { " dot " } else { " " };
                let mut parts = Vec::new();
                for e in v {
                    parts.push(e.math(numbers, lang)?);
                }
                parts.join(sep)
            }
            Expr::Div(a, b) => format!("({})/({})", a.math(numbers, lang)?, b.math(numbers, lang)?),
            Expr::Neg(a) => format!("-{}", a.math(numbers, lang)?),
            Expr::Pow(a, n) => format!("{}^{n}", a.math(numbers, lang)?),
            Expr::Paren(a) => format!("lr(({}))", a.math(numbers, lang)?),
            Expr::Func(f, a) => format!("{} {}", f.name(), a.math(numbers, lang)?),
        })
    }
}

/// A named quantity.
pub fn q(symbol: &str, value: f64, unit: &str) -> Expr {
    Expr::Q(Quantity::new(symbol, value, unit))
}

/// A count (an exact integer: a number of links, of teeth).
pub fn count(symbol: &str, n: f64) -> Expr {
    qd(symbol, n, "", 0)
}

/// A named quantity printed with `digits` significant digits.
pub fn qd(symbol: &str, value: f64, unit: &str, digits: u8) -> Expr {
    Expr::Q(Quantity {
        digits,
        ..Quantity::new(symbol, value, unit)
    })
}

/// An exact constant printed as `math`.
pub fn exact(value: f64, math: &str) -> Expr {
    Expr::Exact {
        math: math.to_string(),
        value,
    }
}

/// An integer constant.
pub fn int(n: i64) -> Expr {
    exact(n as f64, &n.to_string().replace('-', "−"))
}

/// `a / b`.
pub fn div(a: Expr, b: Expr) -> Expr {
    Expr::Div(Box::new(a), Box::new(b))
}

/// `a − b`.
pub fn sub(a: Expr, b: Expr) -> Expr {
    Expr::Sub(Box::new(a), Box::new(b))
}

/// `−a`.
pub fn neg(a: Expr) -> Expr {
    Expr::Neg(Box::new(a))
}

/// `(a)`.
pub fn paren(a: Expr) -> Expr {
    Expr::Paren(Box::new(a))
}

/// `a^n`.
pub fn pow(a: Expr, n: i32) -> Expr {
    Expr::Pow(Box::new(a), n)
}

/// `f a`.
pub fn func(f: Func, a: Expr) -> Expr {
    Expr::Func(f, Box::new(a))
}

/// A worked formula: `result = rhs` with symbols, then with numbers.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Calculation {
    /// The quantity computed (its value is the run's result).
    pub result: Quantity,
    /// The formula's right side.
    pub rhs: Expr,
}

impl Calculation {
    /// A calculation.
    ///
    /// A quantity under the computation's resolution relative to the
    /// largest of the formula ([`crate::number::zero_noise`]) is the noise
    /// of a zero and is held, printed and checked as 0 (`P = 0 − 30610 + …`,
    /// not `0,000 − 30610 + …`).
    pub fn new(result: Quantity, rhs: Expr) -> Self {
        let mut c = Calculation { result, rhs };
        // the scale: the largest of the result and the terms added to it
        // (quantities of its kind; a factor's own unit is another)
        let mut scale = c.result.value.abs();
        c.rhs.denoise(&mut |q| scale = scale.max(q.value.abs()), true);
        if c.result.digits > 0 {
            c.result.value = crate::number::zero_noise(c.result.value, scale);
        }
        c.rhs.denoise(&mut |q| q.value = crate::number::zero_noise(q.value, scale), true);
        c.rhs.denoise(&mut |q| q.value = crate::number::zero_noise(q.value, 0.0), false);
        c
    }

    /// The typst math of the whole calculation (without `$`): on one line,
    /// or broken after the symbolic part when it would be long.
    ///
    /// ```
    /// use tmm_note::calc::{Calculation, Quantity, q, sub};
    /// let c = Calculation::new(Quantity::new("y", 1.5, "м"), sub(q("a", 2.0, ""), q("b", 0.5, "")));
    /// assert_eq!(c.typst(tmm_note::Lang::En).unwrap(), "y = a - b = \"2.000\" - \"0.5000\" = \"1.500\u{202F}м\"");
    /// ```
    ///
    /// # Errors
    /// A non-finite number.
    pub fn typst(&self, lang: Lang) -> Result<String, NoteError> {
        let sym = self.rhs.math(false, lang)?;
        let num = self.rhs.math(true, lang)?;
        let (p, _) = self.result.printed()?;
        let mut value = number_math(p, self.result.digits, lang)?;
        let unit = &self.result.unit;
        if !unit.is_empty() {
            let sep = if unit.starts_with('°') { "" } else { "\u{202F}" };
            if value.contains(" dot 10^") {
                value.push_str(&format!(" \"{unit}\""));
            } else if let Some(end) = value.rfind('"') {
                value.insert_str(end, &format!("{sep}{unit}"));
            }
        }
        // a long sum of numbers breaks after every fourth term, at a plus
        if let Expr::Sum(v) | Expr::Terms { terms: v, .. } = &self.rhs
            && visible_len(&num) > 40
        {
            let terms = join_terms(&sum_terms(v, true, lang)?, 4);
            return Ok(format!("{} &= {sym} \\\n &= {terms} \\\n &= {value}", self.result.symbol));
        }
        // a formula too long for the line breaks after a sign (GOST 2.105, 4.2.15)
        if visible_len(&sym) + visible_len(&num) > 48 {
            Ok(format!("{} &= {sym} \\\n &= {num} = {value}", self.result.symbol))
        } else {
            Ok(format!("{} = {sym} = {num} = {value}", self.result.symbol))
        }
    }

    /// Checks the calculation as printed: the right side evaluated with the
    /// printed inputs equals the printed result within their rounding.
    ///
    /// ```
    /// use tmm_note::calc::{Calculation, Quantity, q, neg, sub};
    /// let right = Calculation::new(Quantity::new("y", 1.5, ""), sub(q("a", 2.0, ""), q("b", 0.5, "")));
    /// assert!(right.check().is_ok());
    /// let wrong = Calculation::new(Quantity::new("y", 1.5, ""), neg(sub(q("a", 2.0, ""), q("b", 0.5, ""))));
    /// assert!(wrong.check().is_err());
    /// ```
    ///
    /// # Errors
    /// A text naming the formula, the two sides and the tolerance.
    pub fn check(&self) -> Result<(), String> {
        let err = |e: NoteError| format!("{}: {e}", self.result.symbol);
        let mut qs = Vec::new();
        self.rhs.quantities(&mut qs);
        let e = self.rhs.eval(true, None, &mut 0).map_err(err)?;
        let (lhs, lhs_half) = self.result.printed().map_err(err)?;
        let mut tol = lhs_half;
        for (i, qty) in qs.iter().enumerate() {
            let (_, h) = qty.printed().map_err(err)?;
            let up = self.rhs.eval(true, Some((i, h)), &mut 0).map_err(err)?;
            let down = self.rhs.eval(true, Some((i, -h)), &mut 0).map_err(err)?;
            tol += (up - e).abs().max((down - e).abs());
        }
        // the float noise of the evaluation itself
        tol += 1e-12 * e.abs().max(lhs.abs());
        if e.is_finite() && (e - lhs).abs() <= tol * 1.000_001 {
            Ok(())
        } else {
            Err(format!(
                "{} = {} as typeset evaluates to {e}, the printed result is {lhs} (tolerance {tol})",
                self.result.symbol,
                self.rhs.math(false, Lang::En).unwrap_or_default()
            ))
        }
    }
}

/// The value rounded as printed with `digits` significant digits, and half
/// a unit of its last printed digit.
fn printed_and_half_ulp(value: f64, digits: u8) -> Result<(f64, f64), NoteError> {
    if digits == 0 {
        if !value.is_finite() {
            return Err(NoteError::NonFinite { value: value.to_string() });
        }
        return Ok((value.round(), 0.0));
    }
    let f = format_number(value, digits, Lang::En)?;
    // an exact zero (or the noise of one, made 0 by `Calculation::new`) is
    // printed "0" and is exact
    if value == 0.0 {
        return Ok((0.0, 0.0));
    }
    let m = f.mantissa.replace('\u{2212}', "-");
    let decimals = m.split_once('.').map_or(0, |(_, d)| d.len()) as i32;
    let exp = f.exponent.unwrap_or(0);
    let mv: f64 = m.parse().map_err(|_| NoteError::NonFinite { value: m.clone() })?;
    let scale = 10f64.powi(exp);
    let printed = mv * scale;
    // the last significant digit: 46 130 to four digits is good to the tens
    let ulp = if printed == 0.0 {
        10f64.powi(-decimals) * scale
    } else {
        10f64.powi(printed.abs().log10().floor() as i32 - i32::from(digits) + 1)
    };
    Ok((printed, 0.5 * ulp))
}

/// The terms of a sum as (the sign before it, its math): a quantity printed
/// negative after the first term is written `− |x|`, not `+ (−x)`.
fn sum_terms(v: &[Expr], numbers: bool, lang: Lang) -> Result<Vec<(char, String)>, NoteError> {
    let mut out = Vec::new();
    for (i, e) in v.iter().enumerate() {
        let negative = match e {
            Expr::Q(q) if numbers && i > 0 => Some((q.printed()?.0, q.digits)).filter(|(p, _)| *p < 0.0),
            _ => None,
        };
        match negative {
            Some((p, digits)) => out.push(('-', number_math(-p, digits, lang)?)),
            None => out.push(('+', e.math(numbers, lang)?)),
        }
    }
    Ok(out)
}

/// Joins the terms of [`sum_terms`]; every `per_line` terms the line
/// breaks at the sign, the sign repeated on the new line (GOST 2.105, 4.2.15).
fn join_terms(terms: &[(char, String)], per_line: usize) -> String {
    let mut s = String::new();
    for (i, (sign, m)) in terms.iter().enumerate() {
        if i > 0 {
            let op = if *sign == '-' { "-" } else { "+" };
            if i % per_line == 0 {
                let _ = std::fmt::Write::write_fmt(&mut s, format_args!(" {op} \\\n &quad {op} "));
            } else {
                let _ = std::fmt::Write::write_fmt(&mut s, format_args!(" {op} "));
            }
        }
        s.push_str(m);
    }
    s
}

/// A printed number as typst math; a count (`digits` 0) whole.
fn number_math(value: f64, digits: u8, lang: Lang) -> Result<String, NoteError> {
    if digits == 0 {
        Ok(format!("\"{}\"", format!("{value:.0}").replace('-', "\u{2212}")))
    } else {
        math_number(value, digits, lang)
    }
}

/// A rough count of the characters a math string shows (quotes, spaces and
/// the words `dot`, `lr` dropped), to decide a line break.
fn visible_len(m: &str) -> usize {
    m.replace(" dot ", "·")
        .replace("lr(", "(")
        .replace("omega", "ω")
        .replace("alpha", "α")
        .replace("theta", "θ")
        .chars()
        .filter(|c| !matches!(c, '"' | ' ' | '_' | '^'))
        .count()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn half_ulp_follows_the_printed_digits() {
        let (p, h) = printed_and_half_ulp(1.10654, 4).unwrap();
        assert_eq!(p, 1.107);
        assert!((h - 0.0005).abs() < 1e-15);
        let (p, h) = printed_and_half_ulp(-46134.0, 4).unwrap();
        assert_eq!(p, -46130.0);
        assert!((h - 5.0).abs() < 1e-9);
    }

    #[test]
    fn the_angle_of_overlap_checks_and_a_wrong_factor_fails() {
        // θ = 180°(K − 1)/(K + 1), K = 1.1065 → 9.100…°, derived by hand:
        // 180 · 0.1065 / 2.1065 = 9.1004
        let k = || q("K_v", 1.1065, "");
        let rhs = |c: f64| Expr::Mul(vec![exact(c, "180°"), div(sub(k(), int(1)), Expr::Sum(vec![k(), int(1)]))]);
        let ok = Calculation::new(Quantity::new("theta", 9.1004, "°"), rhs(180.0));
        ok.check().unwrap();
        let bad = Calculation::new(Quantity::new("theta", 9.1004, "°"), rhs(90.0));
        assert!(bad.check().is_err());
        let t = ok.typst(Lang::Ru).unwrap();
        assert!(t.contains("\"9,100°\""), "{t}");
    }
}
