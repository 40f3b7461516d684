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

/// The names clear their lines by 1 mm: "станочно-начальная прямая"
/// has descenders (р, у: about 0.8 mm at 2.5 mm), "делительная прямая
/// инструмента" letters over 2 mm high at print size.
#[test]
fn the_line_names_keep_clear_of_their_lines() {
    let (top, low) = ("станочно-начальная прямая", "делительная прямая инструмента");
    let (a, b) = tmm_report::gear::machine_mesh::name_baselines(100.0, 102.0, top, low);
    let h = tmm_draw::TextHeight::H2_5;
    let (ka, kb) = (tmm_draw::face::ink(top, h), tmm_draw::face::ink(low, h));
    // the upper name's feet over the upper line, the lower name's tops under the lower
    assert!(100.0 - (a + ka.below) >= 1.0 - 1e-9 && ka.below > 0.5);
    assert!((b - kb.above) - 102.0 >= 1.0 - 1e-9 && kb.above > 2.0);
}
