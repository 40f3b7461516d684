//! Tests of `tmm_report::gear`'s section run: the numbers kept between the
//! A1 and the note's A4 drawings, and the machine meshing's line names.

use tmm_report::TaskSource;
use tmm_report::project::SheetFormat;

/// The gear section's files of `text` drawn for `sheet`.
fn files(text: &str, sheet: SheetFormat) -> Vec<(String, Vec<u8>)> {
    let task = TaskSource::new("t.toml", text).with_sheet(sheet);
    let out = tmm_report::gear::run_section(&task).unwrap().unwrap();
    out.docs.iter().map(|d| (d.path.clone(), d.bytes.clone())).collect()
}

/// The numbers kept from the last job change nothing: each sheet's files
/// are the same whether the section ran before with the same job, with
/// another job, or not at all — the reference is the section computed
/// right after another job has replaced the kept one.
#[test]
fn kept_numbers_draw_the_same_files() {
    let a = "[gear]\nz1 = 15\nz2 = 20\nmodule = \"5 mm\"\nx1 = 0.2\nx2 = 0.85\n";
    let b = "[gear]\nz1 = 13\nz2 = 31\nmodule = \"4 mm\"\nx1 = 0.3\nx2 = 0.1\n";
    for sheet in [SheetFormat::A1, SheetFormat::A4] {
        let _ = files(b, sheet);
        let fresh = files(a, sheet);
        // the same job again, drawn from the kept numbers (or, if another
        // test replaced them meanwhile, computed again)
        assert_eq!(files(a, sheet), fresh);
        let _ = files(a, SheetFormat::A1);
        assert_eq!(files(a, sheet), fresh);
        assert_ne!(files(b, sheet), fresh);
    }
}

/// The note's page gets the drawings only: no DXF or CSV.
#[test]
fn the_a4_run_makes_drawings_only() {
    let a = "[gear]\nz1 = 15\nz2 = 20\nmodule = \"5 mm\"\nx1 = 0.2\nx2 = 0.85\n";
    let a4 = files(a, SheetFormat::A4);
    assert!(a4.iter().all(|(p, _)| !p.ends_with(".dxf") && !p.ends_with(".csv")));
    let a1 = files(a, SheetFormat::A1);
    assert!(a1.iter().any(|(p, _)| p == "gear/mesh.dxf") && a1.iter().any(|(p, _)| p == "gear/profiles.csv"));
    let svgs = |v: &[(String, Vec<u8>)]| {
        v.iter()
            .filter(|(p, _)| p.ends_with(".svg"))
            .map(|(p, _)| p.clone())
            .collect::<Vec<_>>()
    };
    assert_eq!(svgs(&a4), svgs(&a1));
}

/// The names stand on their shelves under the tool's body, each 1 mm
/// clear of the lines over and under it: "делительная прямая
/// инструмента" (the lower line's, capitals over 2 mm high at print size)
/// first, "станочно-начальная прямая" (descenders р, у about 0.8 mm)
/// under it.
#[test]
fn the_line_names_keep_clear_of_their_shelves() {
    let (low, top) = ("делительная прямая инструмента", "станочно-начальная прямая");
    let [(b1, s1), (b2, s2)] = tmm_report::gear::machine_mesh::name_shelves(100.0, low, top);
    let h = tmm_draw::TextHeight::H2_5;
    let (kl, kt) = (tmm_draw::face::ink(low, h), tmm_draw::face::ink(top, h));
    // the ink as printed at the lettering floor (2.5 mm capitals)
    assert!(kl.above > 2.0 && kt.below > 0.5);
    assert!((b1 - kl.above) - 100.0 >= 1.0 - 1e-9, "under the body");
    assert!(s1 - (b1 + kl.below) >= 1.0 - 1e-9, "over its shelf");
    assert!((b2 - kt.above) - s1 >= 1.0 - 1e-9, "under the first shelf");
    assert!(s2 - (b2 + kt.below) >= 1.0 - 1e-9, "over its shelf");
}
