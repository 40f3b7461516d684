//! The sheets' DXF as a CAD program reads it, for the default project,
//! seed 003 and an example of the gear, planetary and cam sections: every letter at least 2.5 mm high (GOST
//! 2.304), the main line 0.7 mm and the thin lines 0.25 mm by layer, the
//! dash-dot pattern in the LTYPE table and used by the axes, a text style
//! that is not `txt`, indices as MTEXT stacks, and an ezdxf audit that
//! makes no fix (when a Python with ezdxf is at hand: `TMM_EZDXF_PYTHON`).
//! The references are GOST's numbers, not the code's output.

use dxf::entities::EntityType;
use tmm_report::TaskSource;
use tmm_report::run::{DEFAULT_TASK, Run, run_task};

/// The sheets' DXF of a run, parsed, with their paths and bytes.
fn sheet_dxfs(run: &Run) -> Vec<(String, Vec<u8>, dxf::Drawing)> {
    run.docs
        .iter()
        .filter(|d| d.path.starts_with("sheets/") && d.extension() == "dxf")
        .map(|d| {
            let dr = dxf::Drawing::load(&mut d.bytes.as_slice()).unwrap_or_else(|e| panic!("{}: {e}", d.path));
            (d.path.clone(), d.bytes.clone(), dr)
        })
        .collect()
}

fn runs() -> Vec<(String, Run)> {
    let mut v = vec![("default".to_string(), run_task(&TaskSource::new("default", DEFAULT_TASK)).unwrap())];
    // seed 003 and one example of the gear, planetary and cam sections
    for name in [
        "seed-003-sixbar.toml",
        "gear-seed003.toml",
        "planetary-ext-int.toml",
        "cam-seed-001-roller.toml",
    ] {
        let text = tmm_testkit::examples::text(name);
        v.push((name.to_string(), run_task(&TaskSource::new(name, text)).unwrap()));
    }
    v
}

#[test]
fn every_letter_on_a_sheet_is_at_least_2_5_mm() {
    for (name, run) in runs() {
        let dxfs = sheet_dxfs(&run);
        assert!(!dxfs.is_empty(), "{name}: no sheets");
        for (path, _, d) in &dxfs {
            let mut n = 0;
            let mut smallest = f64::INFINITY;
            for e in d.entities() {
                let h = match &e.specific {
                    EntityType::Text(t) => t.text_height,
                    EntityType::MText(t) => t.initial_text_height,
                    _ => continue,
                };
                n += 1;
                smallest = smallest.min(h);
            }
            assert!(n > 20, "{name} {path}: {n} texts");
            assert!(smallest >= 2.5 - 1e-9, "{name} {path}: a letter {smallest} mm high");
            eprintln!("{name} {path}: {n} texts, the smallest {smallest} mm");
        }
    }
}

#[test]
fn lines_carry_gost_types_and_weights() {
    let run = run_task(&TaskSource::new("default", DEFAULT_TASK)).unwrap();
    for (path, _, d) in &sheet_dxfs(&run) {
        let layer = |n: &str| {
            d.layers()
                .find(|l| l.name == n)
                .unwrap_or_else(|| panic!("{path}: no layer {n}"))
                .clone()
        };
        // GOST 2.303: the main line s = 0.5 … 1.4 mm, thin s/3 … s/2
        let main = f64::from(layer("MAIN").line_weight.raw_value()) / 100.0;
        let thin = f64::from(layer("THIN").line_weight.raw_value()) / 100.0;
        assert!((0.5..=1.4).contains(&main), "{path}: main {main} mm");
        assert!(thin >= main / 3.0 - 1e-9 && thin <= main / 2.0 + 1e-9, "{path}: thin {thin} mm");
        assert_eq!(layer("AXIS").line_type_name, "GOST_DASHDOT", "{path}");
        // the dash-dot pattern: a dash of 5 … 30 mm, a gap of 3 … 5 mm holding a dot
        let lt = d
            .line_types()
            .find(|l| l.name == "GOST_DASHDOT")
            .unwrap_or_else(|| panic!("{path}: no dash-dot"));
        let el: Vec<f64> = lt.dash_dot_space_lengths.iter().map(|x| x.abs()).collect();
        assert_eq!(el.len(), 4, "{path}: {el:?}");
        assert!((5.0..=30.0).contains(&el[0]), "{path}: dash {}", el[0]);
        assert!((3.0..=5.0).contains(&(el[1] + el[2] + el[3])), "{path}: gap {el:?}");
        // the text style maps to a GOST face, never `txt` (no Cyrillic)
        assert!(
            d.styles()
                .all(|s| !s.primary_font_file_name.to_ascii_lowercase().starts_with("txt")),
            "{path}: a txt style"
        );
        // something is drawn in the main line on every sheet
        assert!(d.entities().any(|e| e.common.layer == "MAIN"), "{path}: no main line");
    }
    // the axes of the mechanism and the gears are dash-dot
    let on_axis = |p: &str| {
        let d = run.docs.get(p).unwrap();
        let dr = dxf::Drawing::load(&mut d.bytes.as_slice()).unwrap();
        dr.entities()
            .filter(|e| e.common.layer == "AXIS" || e.common.line_type_name == "GOST_DASHDOT")
            .count()
    };
    assert!(on_axis("sheets/sheet-3.dxf") > 0, "the gears' pitch circles and axes");
    // the indices of the plans' labels are MTEXT stacks (a^τ_CB, not "aτCB")
    let d = run.docs.get("sheets/sheet-1.dxf").unwrap();
    let dr = dxf::Drawing::load(&mut d.bytes.as_slice()).unwrap();
    let stacks = dr
        .entities()
        .filter(|e| matches!(&e.specific, EntityType::MText(t) if t.text.contains("\\S")))
        .count();
    assert!(stacks > 10, "sheet 1: {stacks} stacked indices");
}

/// The Python that has ezdxf (`TMM_EZDXF_PYTHON`, else `python3`), or
/// `None` after saying the test `test` is skipped.
fn ezdxf_python(test: &str) -> Option<String> {
    let py = std::env::var("TMM_EZDXF_PYTHON").unwrap_or_else(|_| "python3".to_string());
    let ok = std::process::Command::new(&py)
        .args(["-c", "import ezdxf"])
        .output()
        .is_ok_and(|o| o.status.success());
    if !ok {
        eprintln!("{test}: skipped, no python with ezdxf (set TMM_EZDXF_PYTHON)");
    }
    ok.then_some(py)
}

#[test]
fn the_sheets_dxf_pass_an_ezdxf_audit_without_fixes() {
    let Some(py) = ezdxf_python("the_sheets_dxf_pass_an_ezdxf_audit_without_fixes") else {
        return;
    };
    let dir = std::env::temp_dir().join(format!("tmm-sheets-audit-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut files = Vec::new();
    for (name, run) in runs() {
        for (path, bytes, _) in sheet_dxfs(&run) {
            let f = dir.join(format!("{}-{}", name.replace('.', "_"), path.replace('/', "-")));
            std::fs::write(&f, bytes).unwrap();
            files.push(f);
        }
    }
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/../../scripts/dxf-audit.py");
    let o = std::process::Command::new(py).arg(script).args(&files).output().unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    let report = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "ezdxf audit: {report}{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(report.matches(": 0 fixes, 0 errors").count(), files.len(), "{report}");
}

/// The scale a sheet prints is the scale its DXF measures: on sheet 1 of
/// the default project the mechanism's frame AD, 510 mm in the task, lies
/// between the apexes of the two fixed pivots' ground triangles, which
/// must be 510 mm × the ratio of the scale in the title block ("1:2,5")
/// apart on the paper.
#[test]
fn the_frame_of_the_mechanism_measures_its_printed_scale() {
    let run = run_task(&TaskSource::new("default", DEFAULT_TASK)).unwrap();
    let d = run.docs.get("sheets/sheet-1.dxf").unwrap();
    let dr = dxf::Drawing::load(&mut d.bytes.as_slice()).unwrap();
    // the scale field of the title block form 1: its cell 167 … 185 mm from
    // the block's left and 20 … 35 mm from its top (block at x 651, top y 60)
    let field = dr
        .entities()
        .find_map(|e| match &e.specific {
            EntityType::Text(t)
                if (818.0..=836.0).contains(&t.location.x) && (25.0..=40.0).contains(&t.location.y) && t.value.contains(':') =>
            {
                Some(t.value.clone())
            }
            _ => None,
        })
        .expect("the scale field");
    let (a, b) = field.split_once(':').unwrap();
    let n = |s: &str| s.replace(',', ".").parse::<f64>().unwrap();
    let ratio = n(a) / n(b);
    assert_eq!(field, "1:2,5", "the default mechanism's scale");
    // the apexes of the ground triangles (closed three-point polylines, the apex highest)
    let apexes: Vec<(f64, f64)> = dr
        .entities()
        .filter_map(|e| match &e.specific {
            EntityType::LwPolyline(p) if p.vertices.len() == 3 && p.is_closed() => {
                p.vertices.iter().map(|v| (v.x, v.y)).max_by(|a, b| a.1.partial_cmp(&b.1).unwrap())
            }
            _ => None,
        })
        .collect();
    let want = 510.0 * ratio;
    let found = apexes
        .iter()
        .enumerate()
        .flat_map(|(i, p)| apexes[i + 1..].iter().map(move |q| (p.0 - q.0).hypot(p.1 - q.1)))
        .any(|dist| (dist - want).abs() < 0.01);
    assert!(found, "no two pivots {want} mm apart among {apexes:?}");
}

/// Graph 26 of GOST 2.104-2006 as a CAD program reads it, on every sheet's
/// DXF of the default project (A1 and A2) and of seed 003: read back by
/// ezdxf (when at hand: `TMM_EZDXF_PYTHON`), the cell's right and bottom
/// sides as FRAME lines (x = 90 from the frame's top down 14 mm, y = top −
/// 14 from x = 20 to 90) on a layer of the main line (0.5 … 1.4 mm, GOST
/// 2.303), and the designation as one TEXT turned by 180° whose box, as
/// ezdxf measures it (its own font metrics, not tmm's), lies inside the
/// 70 × 14 mm cell (seed 003 names no designation: no turned text). The
/// cell's numbers are the standard's.
#[test]
fn graph_26_reads_back_from_every_sheets_dxf() {
    let Some(py) = ezdxf_python("graph_26_reads_back_from_every_sheets_dxf") else {
        return;
    };
    // every FRAME line, the FRAME layer's weight and every turned FRAME
    // text with ezdxf's box of it, one record a line
    const SCRIPT: &str = r#"
import sys, ezdxf
from ezdxf import bbox
doc = ezdxf.readfile(sys.argv[1])
print("WEIGHT", doc.layers.get("FRAME").dxf.lineweight)
for e in doc.modelspace():
    if e.dxf.layer != "FRAME":
        continue
    if e.dxftype() == "LINE":
        s, t = e.dxf.start, e.dxf.end
        print("LINE", s.x, s.y, t.x, t.y, e.dxf.get("lineweight", -1))
    elif e.dxftype() == "TEXT" and abs(e.dxf.get("rotation", 0.0) % 360.0 - 180.0) < 1e-6:
        b = bbox.extents([e])
        print("TEXT", b.extmin.x, b.extmin.y, b.extmax.x, b.extmax.y, e.dxf.text)
"#;
    let dir = std::env::temp_dir().join(format!("tmm-graph-26-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut cases = vec![];
    for format in ["A1", "A2"] {
        let kept: Vec<&str> = DEFAULT_TASK.lines().filter(|l| !l.trim_start().starts_with("sheet =")).collect();
        let text = kept
            .join("\n")
            .replacen("[project]", &format!("[project]\nsheet = \"{format}\""), 1);
        cases.push((format!("default {format}"), run_task(&TaskSource::new("default", text)).unwrap()));
    }
    let name = "seed-003-sixbar.toml";
    cases.push((
        name.to_string(),
        run_task(&TaskSource::new(name, tmm_testkit::examples::text(name))).unwrap(),
    ));
    let mut checked = 0;
    for (what, run) in &cases {
        // seed 003 names no designation: its cell is drawn empty
        let designation = run.project.designation.clone();
        for (path, bytes, _) in sheet_dxfs(run) {
            let f = dir.join(format!("{}-{}", what.replace([' ', '.'], "_"), path.replace('/', "-")));
            std::fs::write(&f, &bytes).unwrap();
            let o = std::process::Command::new(&py).args(["-c", SCRIPT]).arg(&f).output().unwrap();
            assert!(o.status.success(), "{what} {path}: {}", String::from_utf8_lossy(&o.stderr));
            let out = String::from_utf8_lossy(&o.stdout).to_string();
            let h = if what.ends_with("A2") { 420.0 } else { 594.0 };
            let top = h - 5.0;
            let (mut weight, mut lines, mut texts) = (0.0, vec![], vec![]);
            for l in out.lines() {
                let w: Vec<&str> = l.split_whitespace().collect();
                let n = |i: usize| w[i].parse::<f64>().unwrap();
                match w[0] {
                    "WEIGHT" => weight = n(1) / 100.0,
                    "LINE" => lines.push([n(1), n(2), n(3), n(4)]),
                    "TEXT" => texts.push(([n(1), n(2), n(3), n(4)], w[5..].join(" "))),
                    _ => {}
                }
            }
            assert!((0.5..=1.4).contains(&weight), "{what} {path}: FRAME {weight} mm");
            let has = |a: [f64; 4]| {
                lines.iter().any(|l| {
                    let same = |p: [f64; 4]| p.iter().zip(a).all(|(x, y)| (x - y).abs() < 1e-6);
                    same(*l) || same([l[2], l[3], l[0], l[1]])
                })
            };
            assert!(has([90.0, top, 90.0, top - 14.0]), "{what} {path}: no right side of graph 26");
            assert!(has([20.0, top - 14.0, 90.0, top - 14.0]), "{what} {path}: no bottom of graph 26");
            if designation.trim().is_empty() {
                assert!(texts.is_empty(), "{what} {path}: turned texts {texts:?} with no designation");
                checked += 1;
                continue;
            }
            assert_eq!(texts.len(), 1, "{what} {path}: turned texts {texts:?}");
            let ([x0, y0, x1, y1], t) = &texts[0];
            assert_eq!(t, &designation, "{what} {path}");
            assert!(
                *x0 > 20.0 && *x1 < 90.0 && *y0 > top - 14.0 && *y1 < top,
                "{what} {path}: the designation's box ({x0}, {y0}) … ({x1}, {y1}) leaves graph 26"
            );
            checked += 1;
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    assert!(checked >= 10, "{checked} sheets");
}
