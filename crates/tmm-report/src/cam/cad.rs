//! The working profile for CAD and CNC: DXF (mm, layers) and CSV (mm).

use std::fmt::Write as _;

use tmm_cams::design::CamDesign;

use crate::Error;
use crate::dxf_out::DxfDoc;

/// The DXF drawing: `PROFILE` (working profile, closed polyline), `PITCH`
/// (theoretical profile), `BASE` (r0 and rb circles), `CENTRE` (the axes).
pub fn dxf(d: &CamDesign) -> DxfDoc {
    let mut doc = DxfDoc::new();
    let p = &d.profile;
    doc.layer("PROFILE", 7);
    let work: Vec<(f64, f64)> = p.working.iter().map(|v| (v.x * 1e3, v.y * 1e3)).collect();
    doc.polyline(&work, true);
    doc.layer("PITCH", 5);
    let pitch: Vec<(f64, f64)> = p.pitch.iter().map(|v| (v.x * 1e3, v.y * 1e3)).collect();
    doc.polyline(&pitch, true);
    doc.layer("BASE", 3);
    doc.circle((0.0, 0.0), d.r0 * 1e3);
    if d.rb > 0.0 && (d.rb - d.r0).abs() > 1e-12 {
        doc.circle((0.0, 0.0), d.rb * 1e3);
    }
    doc.layer("CENTRE", 1);
    let r = d.r0 * 1e3 * 1.5;
    doc.line((-r, 0.0), (r, 0.0));
    doc.line((0.0, -r), (0.0, r));
    doc
}

/// The CSV table: one row per profile point.
pub fn csv(d: &CamDesign) -> Result<String, Error> {
    let p = &d.profile;
    let mut s = String::from("phi_deg,x_mm,y_mm,pitch_x_mm,pitch_y_mm,curvature_1_per_mm,pressure_angle_deg\n");
    for i in 0..p.phi.len() {
        let _ = writeln!(
            s,
            "{:.6},{:.6},{:.6},{:.6},{:.6},{:.9},{:.6}",
            p.phi[i].to_degrees(),
            p.working[i].x * 1e3,
            p.working[i].y * 1e3,
            p.pitch[i].x * 1e3,
            p.pitch[i].y * 1e3,
            p.curvature[i] / 1e3,
            p.pressure[i].to_degrees()
        );
    }
    Ok(s)
}
