//! Generated tooth profiles as points (CSV) and as polylines (SVG, DXF).

use std::fmt::Write as _;

use tmm_gears::generate::ToothProfile;

use crate::dxf_out::DxfDoc;
use crate::picture::Picture;
use crate::project::Language;
use crate::svg::{Anchor, Canvas, Style};
use crate::words::word;

/// One tooth of each wheel as CSV: `wheel,part,x_mm,y_mm,r_mm,psi_rad` (the
/// tooth centred on +y; the half profile from the root to the tip, right side).
pub fn profiles_csv(t1: &ToothProfile, t2: &ToothProfile) -> String {
    let mut s = String::from("wheel,part,x_mm,y_mm,r_mm,psi_rad\n");
    for (w, t) in [(1, t1), (2, t2)] {
        for q in &t.half {
            let _ = writeln!(
                s,
                "{w},{},{:.9},{:.9},{:.9},{:.12}",
                q.part.name(),
                q.r * 1e3 * q.psi.sin(),
                q.r * 1e3 * q.psi.cos(),
                q.r * 1e3,
                q.psi
            );
        }
    }
    s
}

/// One tooth of each wheel side by side as SVG polylines, captioned in `lang`.
pub fn profiles_svg(t1: &ToothProfile, t2: &ToothProfile, lang: Language) -> Picture {
    let mut c = Canvas::new(297.0, 210.0);
    // the drawing's name over the teeth (their paper 25 … 195 mm down):
    // the sheets print it, the note leaves it to the figure's caption
    c.title(
        (148.5, 12.0),
        &crate::sheets::caption("gear/profiles.svg", lang),
        crate::labels::H_HEAD,
        Anchor::Middle,
    );
    for (k, t) in [t1, t2].iter().enumerate() {
        let pts: Vec<(f64, f64)> = t.tooth_outline().iter().map(|&(x, y)| (x * 1e3, y * 1e3)).collect();
        let (xmin, xmax) = pts
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |a, p| (a.0.min(p.0), a.1.max(p.0)));
        let (ymin, ymax) = pts
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |a, p| (a.0.min(p.1), a.1.max(p.1)));
        let left = 10.0 + 143.0 * k as f64;
        c.fit((xmin, xmax, ymin, ymax), (left, 15.0, 133.0, 170.0));
        c.polyline(&pts, Style::THICK.widened(0.5));
        c.text_paper(
            (left + 66.0, 200.0),
            &format!(
                "{} {}: z = {}, {}",
                word(lang, "gear.profiles_wheel"),
                k + 1,
                t.z,
                word(lang, "gear.profiles_generated")
            ),
            3.5,
            Anchor::Middle,
            "#000",
        );
    }
    c.finish()
}

/// One tooth of each wheel as DXF polylines (mm), layers TOOTH1 and TOOTH2.
pub fn profiles_dxf(t1: &ToothProfile, t2: &ToothProfile) -> DxfDoc {
    let mut d = DxfDoc::new();
    for (k, t) in [t1, t2].iter().enumerate() {
        d.layer(if k == 0 { "TOOTH1" } else { "TOOTH2" }, 7);
        let dx = if k == 0 { 0.0 } else { 3.0 * t1.ra * 1e3 };
        let pts: Vec<(f64, f64)> = t.tooth_outline().iter().map(|&(x, y)| (dx + x * 1e3, y * 1e3)).collect();
        d.polyline(&pts, false);
    }
    d
}
