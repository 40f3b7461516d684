//! Scales of drawings (масштабы), GOST 2.302-68: the ratio of a length on
//! the paper to the same length on the object, taken only from the
//! standard's series. A scene declares one; model lengths become paper
//! millimetres through it and back, and its caption ("М 1:2,5") is
//! written from the same value, so what is printed is what is measured.

use crate::DrawError;

/// The reduction denominators of GOST 2.302-68 (1:n), times ten (2.5 → 25).
const REDUCTION_X10: [u32; 17] = [
    20, 25, 40, 50, 100, 150, 200, 250, 400, 500, 750, 1000, 2000, 4000, 5000, 8000, 10000,
];
/// The enlargement numerators of GOST 2.302-68 (n:1), times ten.
const ENLARGEMENT_X10: [u32; 9] = [20, 25, 40, 50, 100, 200, 400, 500, 1000];

/// A GOST 2.302 scale: 1:1, a reduction 1:n or an enlargement n:1.
///
/// ```
/// use tmm_draw::Scale;
/// let s = Scale::reduction(2.5).unwrap();
/// assert_eq!(s.to_paper(250.0), 100.0);
/// assert_eq!(s.caption(','), "1:2,5");
/// assert!(Scale::reduction(3.0).is_err());
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub struct Scale {
    /// `true` for n:1, `false` for 1:n (1:1 is `false`, n = 1).
    enlarge: bool,
    /// n times ten, so 2.5 is exact.
    n_x10: u32,
}

impl Scale {
    /// Natural size, 1:1.
    pub const NATURAL: Scale = Scale { enlarge: false, n_x10: 10 };

    /// The reduction 1:n, if n is in the GOST 2.302 series (1 gives 1:1).
    pub fn reduction(n: f64) -> Result<Scale, DrawError> {
        Self::pick(n, false)
    }

    /// The enlargement n:1, if n is in the GOST 2.302 series (1 gives 1:1).
    pub fn enlargement(n: f64) -> Result<Scale, DrawError> {
        Self::pick(n, true)
    }

    fn pick(n: f64, enlarge: bool) -> Result<Scale, DrawError> {
        let x10 = (n * 10.0).round();
        if n.is_finite() && (n * 10.0 - x10).abs() < 1e-9 && (10.0..=1e5).contains(&x10) {
            let k = x10 as u32;
            if k == 10 {
                return Ok(Scale::NATURAL);
            }
            let list: &[u32] = if enlarge { &ENLARGEMENT_X10 } else { &REDUCTION_X10 };
            if list.contains(&k) {
                return Ok(Scale { enlarge, n_x10: k });
            }
        }
        let (paper, real) = if enlarge { (n, 1.0) } else { (1.0, n) };
        Err(DrawError::Scale {
            paper,
            real,
            valid: Self::all().map(|s| s.caption('.')).collect::<Vec<_>>().join(", "),
        })
    }

    /// Every GOST 2.302 scale, from the largest enlargement to the smallest reduction.
    pub fn all() -> impl Iterator<Item = Scale> {
        ENLARGEMENT_X10
            .iter()
            .rev()
            .map(|&n_x10| Scale { enlarge: true, n_x10 })
            .chain(std::iter::once(Scale::NATURAL))
            .chain(REDUCTION_X10.iter().map(|&n_x10| Scale { enlarge: false, n_x10 }))
    }

    /// The paper length per model length (2.5 for 2.5:1, 0.4 for 1:2.5).
    pub fn factor(self) -> f64 {
        let n = self.n_x10 as f64 / 10.0;
        if self.enlarge { n } else { 1.0 / n }
    }

    /// The largest GOST scale whose factor is at most `max_factor` (the
    /// scale that fits a space), or `None` if even the smallest does not.
    ///
    /// ```
    /// use tmm_draw::Scale;
    /// assert_eq!(Scale::fit(0.3).unwrap(), Scale::reduction(4.0).unwrap());
    /// assert_eq!(Scale::fit(1.0).unwrap(), Scale::NATURAL);
    /// ```
    pub fn fit(max_factor: f64) -> Option<Scale> {
        Self::all().find(|s| s.factor() <= max_factor * (1.0 + 1e-12))
    }

    /// A model length (mm on the object) as paper millimetres.
    pub fn to_paper(self, model_mm: f64) -> f64 {
        let n = self.n_x10 as f64;
        if self.enlarge { model_mm * n / 10.0 } else { model_mm * 10.0 / n }
    }

    /// A paper length (mm) as the model length it shows.
    pub fn to_model(self, paper_mm: f64) -> f64 {
        let n = self.n_x10 as f64;
        if self.enlarge { paper_mm * 10.0 / n } else { paper_mm * n / 10.0 }
    }

    /// The caption as written on a drawing, with the given decimal
    /// separator: "1:1", "1:2,5", "2,5:1" (the "М" prefix is the caller's).
    pub fn caption(self, decimal: char) -> String {
        let n = if self.n_x10 % 10 == 0 {
            (self.n_x10 / 10).to_string()
        } else {
            format!("{}{}{}", self.n_x10 / 10, decimal, self.n_x10 % 10)
        };
        if self.enlarge { format!("{n}:1") } else { format!("1:{n}") }
    }
}
