//! Paper: the boxes the drawings are made for, the standard scales of
//! GOST 2.302 (масштабы) and the round scale factors μ of the plans.
//!
//! Every drawing is made once, in paper millimetres, for its slot on the
//! sheet (A1 or A2, from `[project] sheet`); the loose SVG/DXF files and the
//! sheets show the same drawing at 1:1, so the scale written on a drawing is
//! the scale on the sheet.

use crate::project::SheetFormat;

/// The kind of place a drawing takes on a sheet (место на листе).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Slot {
    /// A mechanism, a meshing, a cam profile or a planetary scheme drawn
    /// to a length scale (схема, картина зацепления, профиль кулачка).
    Scheme,
    /// A velocity, acceleration or force plan, Zhukovsky's lever
    /// (план скоростей, ускорений, сил; рычаг Жуковского).
    Plan,
    /// A diagram (диаграмма, график) with axes.
    Diagram,
    /// A small construction (the synthesis construction, a velocity picture).
    Small,
}

/// The width and height in mm of a slot on a sheet of `format`. The A2
/// boxes are the A1 ones reduced by 1/√2 (a sheet of half the area) and
/// rounded down to 5 mm. On A4 (the note's page) every drawing is as wide
/// as the note's figures ([`NOTE_WIDTH_MM`]) and at most [`NOTE_HEIGHT_MM`]
/// high, so it is printed in the note at its own size and scale.
///
/// ```
/// use tmm_report::{paper::{slot_mm, Slot, NOTE_HEIGHT_MM}, project::SheetFormat};
/// assert_eq!(slot_mm(Slot::Scheme, SheetFormat::A1), (400.0, 280.0));
/// let (w, h) = slot_mm(Slot::Plan, SheetFormat::A2);
/// assert!(w < 200.0 && h < 200.0);
/// let (w, h) = slot_mm(Slot::Scheme, SheetFormat::A4);
/// assert!(w == 165.0 && h <= NOTE_HEIGHT_MM);
/// ```
pub fn slot_mm(slot: Slot, format: SheetFormat) -> (f64, f64) {
    let a1 = match slot {
        Slot::Scheme => (400.0, 280.0),
        Slot::Plan => (200.0, 200.0),
        Slot::Diagram => (260.0, 120.0),
        Slot::Small => (200.0, 150.0),
    };
    match format {
        SheetFormat::A4 => {
            let h = match slot {
                Slot::Scheme => NOTE_HEIGHT_MM,
                Slot::Plan => 165.0,
                Slot::Diagram => 95.0,
                Slot::Small => 125.0,
            };
            (NOTE_WIDTH_MM, h)
        }
        SheetFormat::A1 => a1,
        SheetFormat::A2 => {
            let r = |x: f64| (x / std::f64::consts::SQRT_2 / 5.0).floor() * 5.0;
            (r(a1.0), r(a1.1))
        }
    }
}

/// A drawing of a fixed size `wh` (mm) on a sheet, reduced with its
/// proportions to the note's width on the note's page (A4).
///
/// ```
/// use tmm_report::{paper::fit_page, project::SheetFormat};
/// assert_eq!(fit_page((200.0, 110.0), SheetFormat::A1), (200.0, 110.0));
/// assert_eq!(fit_page((200.0, 110.0), SheetFormat::A4), (165.0, 90.75));
/// ```
pub fn fit_page(wh: (f64, f64), format: SheetFormat) -> (f64, f64) {
    match format {
        SheetFormat::A4 if wh.0 > NOTE_WIDTH_MM || wh.1 > NOTE_HEIGHT_MM => {
            let k = (NOTE_WIDTH_MM / wh.0).min(NOTE_HEIGHT_MM / wh.1);
            (wh.0 * k, wh.1 * k)
        }
        _ => wh,
    }
}

/// The width of a figure in the note, mm: the text width of an A4 page
/// (175 mm inside the frame, 165 mm with the GOST 7.32 margins).
pub const NOTE_WIDTH_MM: f64 = 165.0;

/// The tallest figure in the note, mm: the text height of an A4 page with
/// the frame (252 mm) less the room the note keeps for the caption (30 mm).
pub const NOTE_HEIGHT_MM: f64 = 215.0;

/// A scale of a drawing (масштаб изображения), paper : nature.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Scale {
    /// Paper length per natural length (0.5 for 1:2, 2 for 2:1).
    pub factor: f64,
    /// As written on the drawing and in the title block: `1:2`, `2:1`, `1:1`.
    pub text: &'static str,
}

/// The standard scales of GOST 2.302-68, largest first: enlargement 100:1 …
/// 2:1, natural 1:1, reduction 1:2 … 1:1000.
pub const STANDARD_SCALES: &[(f64, &str)] = &[
    (100.0, "100:1"),
    (50.0, "50:1"),
    (40.0, "40:1"),
    (20.0, "20:1"),
    (10.0, "10:1"),
    (5.0, "5:1"),
    (4.0, "4:1"),
    (2.5, "2,5:1"),
    (2.0, "2:1"),
    (1.0, "1:1"),
    (0.5, "1:2"),
    (0.4, "1:2,5"),
    (0.25, "1:4"),
    (0.2, "1:5"),
    (0.1, "1:10"),
    (1.0 / 15.0, "1:15"),
    (0.05, "1:20"),
    (0.04, "1:25"),
    (0.025, "1:40"),
    (0.02, "1:50"),
    (0.0133333333333333, "1:75"),
    (0.01, "1:100"),
    (0.005, "1:200"),
    (0.004, "1:250"),
    (0.0025, "1:400"),
    (0.002, "1:500"),
    (0.00125, "1:800"),
    (0.001, "1:1000"),
];

/// The largest standard scale at which a natural length `nature_mm` fits in
/// `paper_mm`; the smallest standard scale when nothing fits, `None` when a
/// length is not positive and finite.
///
/// ```
/// use tmm_report::paper::standard_scale;
/// assert_eq!(standard_scale(1000.0, 380.0).unwrap().text, "1:4");   // 1:2,5 would need 400 mm
/// assert_eq!(standard_scale(100.0, 380.0).unwrap().text, "2,5:1");
/// assert!(standard_scale(0.0, 380.0).is_none());
/// ```
pub fn standard_scale(nature_mm: f64, paper_mm: f64) -> Option<Scale> {
    if !(nature_mm.is_finite() && paper_mm.is_finite() && nature_mm > 0.0 && paper_mm > 0.0) {
        return None;
    }
    let last = STANDARD_SCALES[STANDARD_SCALES.len() - 1];
    let (factor, text) = STANDARD_SCALES
        .iter()
        .copied()
        .find(|(f, _)| nature_mm * f <= paper_mm * (1.0 + 1e-12))
        .unwrap_or(last);
    Some(Scale { factor, text })
}

/// A round scale factor μ (масштабный коэффициент) not smaller than `raw`:
/// 1, 2, 2.5, 4 or 5 times a power of ten, as the course writes them
/// (μ_v = 0.05 m·s⁻¹/mm, μ_F = 20 N/mm). `raw` is units per paper mm.
///
/// ```
/// use tmm_report::paper::round_mu;
/// assert_eq!(round_mu(156.15), 200.0);
/// assert_eq!(round_mu(0.0213), 0.025);
/// assert_eq!(round_mu(40.0), 40.0);
/// assert!(round_mu(0.0).is_nan() == false && round_mu(0.0) > 0.0);
/// ```
pub fn round_mu(raw: f64) -> f64 {
    if !(raw.is_finite() && raw > 0.0) {
        return 1.0;
    }
    let p = 10f64.powf(raw.log10().floor());
    for m in [1.0, 2.0, 2.5, 4.0, 5.0, 10.0] {
        let v = m * p;
        if v >= raw * (1.0 - 1e-12) {
            // print-exact: round to the significant digits of m·10^k
            return (v / p * 10.0).round() / 10.0 * p;
        }
    }
    10.0 * p
}

/// The grid values k·step inside [lo, hi], with their index k (k = 0 is
/// zero): the ticks of an axis at a round scale factor. The tolerance is
/// relative to the step, as the values may be of any size (accelerations of
/// 1e-17 m/s² at a crank speed of 1e-7 rpm once got half a million ticks
/// from an absolute one).
///
/// ```
/// use tmm_report::paper::grid_values;
/// let v: Vec<(i64, f64)> = grid_values(-25.0, 31.0, 10.0).collect();
/// assert_eq!(v.first(), Some(&(-2, -20.0)));
/// assert_eq!(v.last(), Some(&(3, 30.0)));
/// assert_eq!(grid_values(-2e-17, 3e-17, 1e-17).count(), 6);
/// ```
pub fn grid_values(lo: f64, hi: f64, step: f64) -> impl Iterator<Item = (i64, f64)> {
    let first = (lo / step - 1e-9).ceil() as i64;
    (first..)
        .take_while(move |&k| (k as f64 - 1e-9) * step <= hi)
        .map(move |k| (k, k as f64 * step))
}
