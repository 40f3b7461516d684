//! A sheet's DXF draws what its PDF draws (issue: "its rendering overlaps
//! the PDF's rendering of the same sheet"): every sheet of the default
//! project and of seed 003 is written as DXF and typeset as PDF, and
//! `scripts/dxf-vs-pdf.py` draws both (ezdxf's drawing add-on, poppler's
//! `pdftoppm`, 60 dpi) and compares their ink. The tolerance: the frames
//! have the same proportions within 0.5 %, and at least 80 % of each
//! rendering's ink lies within 1 mm of the other's (lines, arcs, hatches
//! and the frame coincide; the letters are drawn in each renderer's own
//! face, which is where the rest differs). Runs when `TMM_EZDXF_PYTHON`
//! names a Python with ezdxf, matplotlib and Pillow and `pdftoppm` is
//! installed; says it was skipped otherwise.

use tmm_report::TaskSource;
use tmm_report::run::{DEFAULT_TASK, run_task};

use super::fixtures::sheet_svgs;

#[test]
fn every_sheets_dxf_overlaps_its_pdf() {
    let py = std::env::var("TMM_EZDXF_PYTHON").unwrap_or_else(|_| "python3".to_string());
    let has = |cmd: &mut std::process::Command| cmd.output().is_ok_and(|o| o.status.success());
    if !has(std::process::Command::new(&py).args(["-c", "import ezdxf, matplotlib, PIL, numpy"]))
        || !has(std::process::Command::new("pdftoppm").arg("-v"))
    {
        eprintln!("every_sheets_dxf_overlaps_its_pdf: skipped, needs TMM_EZDXF_PYTHON with ezdxf, matplotlib and Pillow, and pdftoppm");
        return;
    }
    let dir = std::env::temp_dir().join(format!("tmm-dxf-vs-pdf-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let seed = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/seed-003-sixbar.toml")).unwrap();
    let mut args = Vec::new();
    for (name, text) in [("default", DEFAULT_TASK), ("seed-003", seed.as_str())] {
        let run = run_task(&TaskSource::new(name, text)).unwrap();
        let sheets = sheet_svgs(&run);
        assert!(!sheets.is_empty(), "{name}: no sheet");
        for (path, svg) in sheets {
            let stem = path.trim_start_matches("sheets/").trim_end_matches(".svg");
            let dxf = run
                .docs
                .get(&format!("sheets/{stem}.dxf"))
                .unwrap_or_else(|| panic!("{name}: {stem}.dxf"));
            let pdf = tmm_note::sheet_pdf(svg).unwrap();
            let (fd, fp) = (dir.join(format!("{name}-{stem}.dxf")), dir.join(format!("{name}-{stem}.pdf")));
            std::fs::write(&fd, &dxf.bytes).unwrap();
            std::fs::write(&fp, pdf).unwrap();
            args.push(fd);
            args.push(fp);
        }
    }
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/../../scripts/dxf-vs-pdf.py");
    let o = std::process::Command::new(&py).arg(script).args(&args).output().unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    let report = String::from_utf8_lossy(&o.stdout);
    eprintln!("{report}");
    assert!(o.status.success(), "{report}{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(report.lines().filter(|l| l.starts_with("ok ")).count(), args.len() / 2, "{report}");
}
