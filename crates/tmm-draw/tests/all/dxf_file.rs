//! The DXF rendering read back by an independent reader (the `dxf` crate)
//! and audited by ezdxf when it is available.

use dxf::entities::EntityType;
use tmm_draw::{LineType, Thickness, dxf as out, sample};

fn load(text: &str) -> dxf::Drawing {
    dxf::Drawing::load(&mut text.as_bytes()).expect("the dxf crate reads the file")
}

#[test]
fn dxf_is_deterministic() {
    let s = sample::scene();
    assert_eq!(out::render(&s), out::render(&s));
}

#[test]
fn layers_linetypes_and_lineweights_read_back() {
    let d = load(&out::render(&sample::scene()));
    assert_eq!(d.header.version, dxf::enums::AcadVersion::R2007);
    assert_eq!(d.header.default_drawing_units, dxf::enums::Units::Millimeters);
    let layer = |n: &str| d.layers().find(|l| l.name == n).unwrap_or_else(|| panic!("layer {n}"));
    // main lines 0.7 mm, thin lines 0.25 mm at s = 0.7 (GOST 2.303: s and s/3 … s/2)
    assert_eq!(layer("MAIN").line_weight.raw_value(), 70);
    assert_eq!(layer("THIN").line_weight.raw_value(), 25);
    assert_eq!(layer("AXIS").line_type_name, "GOST_DASHDOT");
    assert_eq!(layer("HIDDEN").line_type_name, "GOST_DASHED");
    assert_eq!(layer("AXIS").color.index(), Some(1));
    // the dash-dot pattern: a dash, a gap, a dot (0), a gap; GOST's gap (dot included) 3 … 5 mm
    let lt = d.line_types().find(|l| l.name == "GOST_DASHDOT").expect("dash-dot linetype");
    assert_eq!(lt.element_count, 4);
    let el = &lt.dash_dot_space_lengths;
    assert_eq!(el.len(), 4);
    let axis = LineType::Axis.dashes(Thickness::A1);
    assert!(
        (el[0] - axis[0]).abs() < 1e-6 && el[2] == 0.0 && el[1] < 0.0 && el[3] < 0.0,
        "{el:?}"
    );
    let gap = -(el[1] + el[3]);
    assert!((3.0..=5.0).contains(&gap), "{gap}");
    assert!((lt.total_pattern_length - (el[0] - el[1] - el[3])).abs() < 1e-6);
    assert!(d.line_types().any(|l| l.name == "GOST_DASHED" && l.element_count == 2));
    // the phantom line on the THIN layer carries its own linetype
    assert!(
        d.entities()
            .any(|e| e.common.layer == "THIN" && e.common.line_type_name == "GOST_DASHDOTDOT")
    );
    // the text style names a GOST font, never txt
    let styles: Vec<_> = d.styles().collect();
    assert!(
        styles
            .iter()
            .any(|s| s.name == "GOST type B" && s.primary_font_file_name == "gost_bu.ttf")
    );
    assert!(
        styles
            .iter()
            .all(|s| !s.primary_font_file_name.to_ascii_lowercase().starts_with("txt"))
    );
}

#[test]
fn cyrillic_and_indices_read_back_as_written() {
    let d = load(&out::render(&sample::scene()));
    let texts: Vec<String> = d
        .entities()
        .filter_map(|e| match &e.specific {
            EntityType::Text(t) => Some(t.value.clone()),
            EntityType::MText(t) => Some(format!("{}{}", t.extended_text.join(""), t.text)),
            _ => None,
        })
        .collect();
    assert!(texts.iter().any(|t| t == "Кривошип ОА"), "{texts:?}");
    let m = texts.iter().find(|t| t.contains("ω")).expect("the indexed line");
    assert!(
        m.contains("K\\S^v;") && m.contains("R\\Sτ^12;") && m.contains("M\\S^ур;") && m.contains("ω\\S^1;"),
        "{m}"
    );
    // every text is at least 2.5 mm high
    for e in d.entities() {
        match &e.specific {
            EntityType::Text(t) => assert!(t.text_height >= 2.5),
            EntityType::MText(t) => assert!(t.initial_text_height >= 2.5),
            _ => {}
        }
    }
}

/// The python interpreter with ezdxf: `TMM_EZDXF_PYTHON`, else `python3`
/// if it imports ezdxf.
fn ezdxf_python() -> Option<String> {
    let py = std::env::var("TMM_EZDXF_PYTHON").unwrap_or_else(|_| "python3".to_string());
    let ok = std::process::Command::new(&py)
        .args(["-c", "import ezdxf"])
        .output()
        .is_ok_and(|o| o.status.success());
    ok.then_some(py)
}

#[test]
fn ezdxf_audit_makes_no_fixes() {
    let Some(py) = ezdxf_python() else {
        eprintln!("ezdxf_audit_makes_no_fixes: skipped, no python with ezdxf (set TMM_EZDXF_PYTHON)");
        return;
    };
    let dir = std::env::temp_dir().join(format!("tmm-draw-audit-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("sample.dxf");
    std::fs::write(&file, out::render(&sample::scene())).unwrap();
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/../../scripts/dxf-audit.py");
    let o = std::process::Command::new(py).arg(script).arg(&file).output().unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    let report = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "ezdxf audit: {report}{}", String::from_utf8_lossy(&o.stderr));
    assert!(report.contains(": 0 fixes, 0 errors"), "{report}");
}
