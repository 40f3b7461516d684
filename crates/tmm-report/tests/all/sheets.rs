//! The drawing sheets, checked on their geometry read back from the files:
//! every drawing inside the frame, off the title block and off the other
//! drawings; the title block's grid where GOST 2.104 puts it; the DXF read
//! back by the `dxf` crate; the same bytes for the same task; the words of
//! the frame in the sheet's language.

use std::path::PathBuf;

use crate::xml::{Token, tokens};
use tmm_report::TaskSource;
use tmm_report::output::Documents;
use tmm_report::project::{Language, SheetFormat};
use tmm_report::run::{DEFAULT_TASK, run_task, run_task_in};
use tmm_report::sheets::layout::Rect;
use tmm_report::words::word;

/// The task text with `[project] sheet` set to `format`.
fn with_sheet(text: &str, format: &str) -> String {
    let lines: Vec<String> = text
        .lines()
        .filter(|l| !l.trim_start().starts_with("sheet ="))
        .map(str::to_string)
        .collect();
    let mut t = lines.join("\n");
    if t.contains("[project]") {
        t = t.replacen("[project]", &format!("[project]\nsheet = \"{format}\""), 1);
    } else {
        t.push_str(&format!("\n[project]\nsheet = \"{format}\"\n"));
    }
    t
}

fn tasks() -> Vec<(String, String)> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    let mut out = vec![("default".to_string(), DEFAULT_TASK.to_string())];
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    files.sort();
    for p in files {
        out.push((
            p.file_name().unwrap().to_string_lossy().into_owned(),
            std::fs::read_to_string(&p).unwrap(),
        ));
    }
    assert!(out.len() > 10);
    out
}

fn num(t: &Token<'_>, k: &str) -> f64 {
    t.attr(k).unwrap_or_else(|| panic!("no {k}")).parse().unwrap()
}

/// The nested drawings of a sheet: (source, box).
fn drawings(svg: &str) -> Vec<(String, Rect)> {
    tokens(svg)
        .unwrap()
        .iter()
        .filter(|t| matches!(t, Token::Start { name: "svg", .. }) && t.attr("class") == Some("drawing"))
        .map(|t| {
            (
                t.attr("data-source").unwrap().to_string(),
                Rect {
                    x: num(t, "x"),
                    y: num(t, "y"),
                    w: num(t, "width"),
                    h: num(t, "height"),
                },
            )
        })
        .collect()
}

/// A line's ends: x1, y1, x2, y2.
type Segment = (f64, f64, f64, f64);

/// The lines and texts inside `<g id="{group}">`.
fn group(svg: &str, id: &str) -> (Vec<Segment>, Vec<String>) {
    let toks = tokens(svg).unwrap();
    let (mut lines, mut texts) = (Vec::new(), Vec::new());
    let mut inside = 0usize;
    let mut in_text = false;
    for t in &toks {
        match t {
            Token::Start { name, empty, .. } => {
                if inside > 0 && !empty {
                    inside += 1;
                } else if *name == "g" && t.attr("id") == Some(id) {
                    inside = 1;
                }
                if inside > 0 && *name == "line" {
                    lines.push((num(t, "x1"), num(t, "y1"), num(t, "x2"), num(t, "y2")));
                }
                // a text's words may stand in its tspans
                in_text = inside > 0 && (*name == "text" || (in_text && *name == "tspan"));
            }
            Token::End { .. } => {
                inside = inside.saturating_sub(1);
                in_text = false;
            }
            Token::Text(s) if in_text => texts.push(s.clone()),
            _ => {}
        }
    }
    (lines, texts)
}

fn sheets(docs: &Documents) -> Vec<(String, String)> {
    docs.iter()
        .filter(|d| d.path.starts_with("sheets/") && d.extension() == "svg")
        .map(|d| (d.path.clone(), d.as_text().unwrap().to_string()))
        .collect()
}

#[test]
fn drawings_stay_inside_the_frame_off_the_title_block_and_apart() {
    for (name, text) in tasks() {
        for (format, fmt) in [("A1", SheetFormat::A1), ("A2", SheetFormat::A2)] {
            let run = run_task(&TaskSource::new(&name, with_sheet(&text, format))).unwrap_or_else(|e| panic!("{name}: {e}"));
            let (w, h) = fmt.size_mm();
            let frame = Rect {
                x: 20.0,
                y: 5.0,
                w: w - 25.0,
                h: h - 10.0,
            };
            let tb = Rect {
                x: w - 5.0 - 185.0,
                y: h - 5.0 - 55.0,
                w: 185.0,
                h: 55.0,
            };
            let svgs = run
                .docs
                .iter()
                .filter(|d| d.extension() == "svg" && !d.path.starts_with("sheets/"))
                .count();
            let sh = sheets(&run.docs);
            assert_eq!(sh.is_empty(), svgs == 0, "{name} {format}: {svgs} drawings, {} sheets", sh.len());
            for (path, svg) in &sh {
                assert!(svg.contains(&format!("width=\"{w}mm\" height=\"{h}mm\"")), "{name} {path}");
                let mut ds = drawings(svg);
                assert!(!ds.is_empty(), "{name} {path}: a sheet without drawings");
                // the note of what was left out takes its own box, checked as a drawing
                if let Some(t) = tokens(svg).unwrap().iter().find(|t| t.attr("id") == Some("note")) {
                    let v: Vec<f64> = t.attr("data-box").unwrap().split(' ').map(|x| x.parse().unwrap()).collect();
                    ds.push((
                        "note".to_string(),
                        Rect {
                            x: v[0],
                            y: v[1],
                            w: v[2],
                            h: v[3],
                        },
                    ));
                }
                for (i, (src, r)) in ds.iter().enumerate() {
                    assert!(frame.contains(r), "{name} {format} {path}: {src} {r:?} leaves the frame");
                    assert!(!r.intersects(&tb), "{name} {format} {path}: {src} {r:?} meets the title block");
                    for (src2, r2) in &ds[i + 1..] {
                        assert!(!r.intersects(r2), "{name} {format} {path}: {src} and {src2} overlap");
                    }
                    if src == "note" {
                        continue;
                    }
                    // placed at 1:1: the box is the drawing's own size
                    let own = run.docs.get(src).unwrap().as_text().unwrap();
                    assert!(own.contains(&format!("width=\"{}mm\"", r.w)), "{name} {src}: not at 1:1 ({})", r.w);
                }
            }
        }
    }
}

#[test]
fn the_title_block_is_185_by_55_in_the_corner_and_filled() {
    let run = run_task(&TaskSource::new("default", DEFAULT_TASK)).unwrap();
    let sh = sheets(&run.docs);
    assert!(sh.len() >= 4, "the default project has the four course sheets");
    for (path, svg) in &sh {
        let (lines, texts) = group(svg, "title-block");
        let xs = lines.iter().flat_map(|l| [l.0, l.2]);
        let ys = lines.iter().flat_map(|l| [l.1, l.3]);
        let (x0, x1) = xs.clone().fold((f64::MAX, f64::MIN), |a, v| (a.0.min(v), a.1.max(v)));
        let (y0, y1) = ys.fold((f64::MAX, f64::MIN), |a, v| (a.0.min(v), a.1.max(v)));
        assert_eq!((x0, x1, y0, y1), (841.0 - 5.0 - 185.0, 836.0, 594.0 - 5.0 - 55.0, 589.0), "{path}");
        // the column grid of form 1 (GOST 2.104): 7, 10, 23, 15, 10 | 70 | 5, 5, 5, 17, 18
        let verticals: Vec<f64> = lines.iter().filter(|l| l.0 == l.2).map(|l| l.0 - x0).collect();
        for x in [7.0, 17.0, 40.0, 55.0, 65.0, 135.0, 140.0, 145.0, 150.0, 167.0, 155.0] {
            assert!(verticals.iter().any(|v| (v - x).abs() < 1e-9), "{path}: no column at {x}");
        }
        let rows: Vec<f64> = lines.iter().filter(|l| l.1 == l.3 && l.0 == x0).map(|l| l.1 - y0).collect();
        for k in 1..11 {
            assert!(
                rows.iter().any(|v| (v - 5.0 * k as f64).abs() < 1e-9),
                "{path}: no row at {}",
                5 * k
            );
        }
        let all = texts.join("|");
        assert!(
            all.contains("ТММ.КП.017.00.000") && all.contains("Иванов И. И.") && all.contains("Петров П. П."),
            "{path}: {all}"
        );
        assert!(all.contains(&format!("|{}|", sh.len())), "{path}: the sheet count");
    }
}

/// The texts inside `<g id="{group}">` as `tmm_draw::svg` writes them
/// (`transform="translate(x y) rotate(r) skewX(-15)"`, the words in
/// tspans): (x, y, capital height, rotation in degrees as written, text).
fn group_texts(svg: &str, id: &str) -> Vec<(f64, f64, f64, f64, String)> {
    let toks = tokens(svg).unwrap();
    let mut out = Vec::new();
    let mut inside = 0usize;
    let mut open: Option<(f64, f64, f64, f64, String)> = None;
    for t in &toks {
        match t {
            Token::Start { name, empty, .. } => {
                if inside > 0 && !empty {
                    inside += 1;
                } else if *name == "g" && t.attr("id") == Some(id) {
                    inside = 1;
                }
                if inside > 0 && *name == "text" {
                    let tr = t.attr("transform").unwrap_or("").to_string();
                    let at = transform_args(&tr, "translate").unwrap();
                    let rot = transform_args(&tr, "rotate").map_or(0.0, |r| r[0]);
                    let cap = num(t, "font-size") * tmm_draw::svg::CAP_EM;
                    open = Some((at[0], at[1], cap, rot, String::new()));
                }
            }
            Token::End { name, .. } => {
                inside = inside.saturating_sub(1);
                if *name == "text"
                    && let Some(o) = open.take()
                {
                    out.push(o);
                }
            }
            Token::Text(s) => {
                if let Some(o) = open.as_mut() {
                    o.4.push_str(s);
                }
            }
        }
    }
    out
}

/// The numbers of `name(…)` in a transform list.
fn transform_args(tr: &str, name: &str) -> Option<Vec<f64>> {
    let i = tr.find(&format!("{name}("))? + name.len() + 1;
    let j = i + tr[i..].find(')')?;
    Some(
        tr[i..j]
            .split([' ', ','])
            .filter(|s| !s.is_empty())
            .map(|s| s.parse().unwrap())
            .collect(),
    )
}

#[test]
fn graph_26_holds_the_designation_upside_down_in_the_top_left_corner() {
    // GOST 2.104-2006, 4.1: graph 26, 70 × 14 mm, in the top-left corner of
    // the frame, the designation turned by 180° (the title block runs along
    // the long side of the sheet)
    for (format, h_sheet) in [("A1", 594.0), ("A2", 420.0)] {
        let run = run_task(&TaskSource::new("default", with_sheet(DEFAULT_TASK, format))).unwrap();
        let sh = sheets(&run.docs);
        assert!(sh.len() >= 4);
        for (path, svg) in &sh {
            let (lines, _) = group(svg, "graph-26");
            // its right side at x = 20 + 70 from the frame's top (y = 5) to
            // 5 + 14, its bottom at y = 19 from the frame's left (x = 20) to 90
            let has = |l: Segment| {
                lines.iter().any(|m| {
                    let same = |a: Segment, b: Segment| {
                        (a.0 - b.0).abs() < 1e-9 && (a.1 - b.1).abs() < 1e-9 && (a.2 - b.2).abs() < 1e-9 && (a.3 - b.3).abs() < 1e-9
                    };
                    same(*m, l) || same(*m, (l.2, l.3, l.0, l.1))
                })
            };
            assert!(
                has((90.0, 5.0, 90.0, 19.0)),
                "{format} {path}: no right side of graph 26 in {lines:?}"
            );
            assert!(has((20.0, 19.0, 90.0, 19.0)), "{format} {path}: no bottom of graph 26 in {lines:?}");
            let texts = group_texts(svg, "graph-26");
            assert_eq!(texts.len(), 1, "{format} {path}: {texts:?}");
            let (x, y, size, rot, text) = &texts[0];
            assert_eq!(text, "ТММ.КП.017.00.000", "{format} {path}");
            // turned by 180° about its anchor, the middle of its baseline
            assert!((rot.abs() - 180.0).abs() < 1e-9, "{format} {path}: turned by {rot}");
            // the text's box (0.6 of the size per character, the capitals'
            // height above the baseline) turned about the anchor lies below
            // it on the paper (y down) and stays in the box, 1 mm to spare
            let w = 0.6 * size * text.chars().count() as f64;
            for (qx, qy) in [
                (x - w / 2.0, *y),
                (x + w / 2.0, *y),
                (x - w / 2.0, y + size),
                (x + w / 2.0, y + size),
            ] {
                assert!(
                    (21.0..=89.0).contains(&qx) && (6.0..=18.0).contains(&qy),
                    "{format} {path}: the designation leaves graph 26 at ({qx}, {qy})"
                );
            }
            // GOST 2.304 sizes only
            assert!(
                [3.5, 5.0, 7.0].iter().any(|s| (s - size).abs() < 1e-3),
                "{format} {path}: {size} mm"
            );
            // no drawing on it
            let g26 = Rect {
                x: 20.0,
                y: 5.0,
                w: 70.0,
                h: 14.0,
            };
            for (src, d) in drawings(svg) {
                assert!(!d.intersects(&g26), "{format} {path}: {src} {d:?} covers graph 26");
            }
        }
        // the DXF: one text turned by 180° inside the box (y up: 589 … 575 mm on A1)
        let d = run.docs.get("sheets/sheet-1.dxf").unwrap();
        let drawing = dxf::Drawing::load(&mut d.bytes.as_slice()).unwrap();
        let turned: Vec<_> = drawing
            .entities()
            .filter_map(|e| match &e.specific {
                dxf::entities::EntityType::Text(t) if t.value == "ТММ.КП.017.00.000" => Some(t.clone()),
                _ => None,
            })
            .filter(|t| (t.rotation.rem_euclid(360.0) - 180.0).abs() < 1e-6)
            .collect();
        assert_eq!(turned.len(), 1, "{format}: the turned designation in the DXF");
        let t = &turned[0];
        let p = &t.location;
        assert!(
            (20.0..=90.0).contains(&p.x) && (h_sheet - 19.0..=h_sheet - 5.0).contains(&p.y),
            "{format}: the DXF's designation at {p:?}"
        );
    }
}

#[test]
fn the_dxf_reads_back_with_its_layers_and_inside_the_sheet() {
    for format in ["A1", "A2"] {
        let run = run_task(&TaskSource::new("default", with_sheet(DEFAULT_TASK, format))).unwrap();
        let (w, h) = if format == "A1" { (841.0, 594.0) } else { (594.0, 420.0) };
        let dxfs: Vec<_> = run
            .docs
            .iter()
            .filter(|d| d.path.starts_with("sheets/") && d.extension() == "dxf")
            .collect();
        assert!(dxfs.len() >= 4);
        for d in dxfs {
            let drawing = dxf::Drawing::load(&mut d.bytes.as_slice()).unwrap_or_else(|e| panic!("{}: {e}", d.path));
            let layers: Vec<String> = drawing.layers().map(|l| l.name.clone()).collect();
            for l in ["MAIN", "THIN", "AXIS", "DIM", "TEXT", "FRAME"] {
                assert!(layers.iter().any(|x| x == l), "{}: no layer {l}", d.path);
            }
            let mut n = 0;
            let mut on = std::collections::BTreeSet::new();
            let inside = |x: f64, y: f64| (-1e-6..=w + 1e-6).contains(&x) && (-1e-6..=h + 1e-6).contains(&y);
            for e in drawing.entities() {
                n += 1;
                on.insert(e.common.layer.clone());
                use dxf::entities::EntityType as E;
                match &e.specific {
                    E::Line(l) => assert!(inside(l.p1.x, l.p1.y) && inside(l.p2.x, l.p2.y), "{}: line {:?}", d.path, l.p1),
                    E::LwPolyline(p) => assert!(p.vertices.iter().all(|v| inside(v.x, v.y)), "{}: polyline", d.path),
                    E::Circle(c) => assert!(
                        inside(c.center.x - c.radius, c.center.y - c.radius) && inside(c.center.x + c.radius, c.center.y + c.radius)
                    ),
                    E::Text(t) => assert!(inside(t.location.x, t.location.y), "{}: text {}", d.path, t.value),
                    _ => {}
                }
            }
            assert!(n > 100, "{}: {n} entities", d.path);
            for l in ["MAIN", "THIN", "TEXT", "FRAME"] {
                assert!(on.contains(l), "{}: nothing on {l}", d.path);
            }
        }
        // the frame: the inner rectangle on `FRAME`, 20 mm from the left, 5 mm elsewhere (y up)
        let d = run.docs.get("sheets/sheet-1.dxf").unwrap();
        let drawing = dxf::Drawing::load(&mut d.bytes.as_slice()).unwrap();
        let frames = drawing
            .entities()
            .filter(|e| e.common.layer == "FRAME")
            .filter_map(|e| match &e.specific {
                dxf::entities::EntityType::LwPolyline(p) => Some(p.vertices.iter().map(|v| (v.x, v.y)).collect::<Vec<_>>()),
                _ => None,
            })
            .filter(|v| {
                let near = |a: f64, b: f64| (a - b).abs() < 1e-9;
                v.len() == 4
                    && [(20.0, 5.0), (w - 5.0, 5.0), (w - 5.0, h - 5.0), (20.0, h - 5.0)]
                        .iter()
                        .all(|c| v.iter().any(|p| near(p.0, c.0) && near(p.1, c.1)))
            })
            .count();
        assert_eq!(frames, 1, "{format}: the frame 20 mm from the left, 5 mm from the others");
    }
}

#[test]
fn the_same_task_gives_the_same_bytes() {
    let a = run_task(&TaskSource::new("t", DEFAULT_TASK)).unwrap();
    let b = run_task(&TaskSource::new("t", DEFAULT_TASK)).unwrap();
    let pick = |r: &tmm_report::run::Run| r.docs.iter().filter(|d| d.path.starts_with("sheets/")).cloned().collect::<Vec<_>>();
    let (x, y) = (pick(&a), pick(&b));
    assert!(x.len() >= 8);
    assert_eq!(x, y);
}

#[test]
fn the_frame_speaks_the_sheets_language() {
    let fields = ["ТММ.КП.017.00.000", "Иванов И. И.", "Петров П. П.", "2бАТ1"];
    for lang in [Language::Ru, Language::Uk, Language::En] {
        let run = run_task_in(&TaskSource::new("t", DEFAULT_TASK), Some(lang)).unwrap();
        for (path, svg) in sheets(&run.docs) {
            let (_, texts) = group(&svg, "title-block");
            for k in [
                "sheet.tb_drawn",
                "sheet.tb_checked",
                "sheet.tb_scale",
                "sheet.tb_sheets",
                "sheet.tb_document",
            ] {
                assert!(texts.iter().any(|t| t == word(lang, k)), "{path} {}: no {k}", lang.code());
            }
            if lang != Language::En {
                // the letter of a student's document, У (GOST 2.103), under Лит.
                assert!(texts.iter().any(|t| t == "У"), "{path} {}: no letter У: {texts:?}", lang.code());
                for t in texts
                    .iter()
                    .filter(|t| !fields.contains(&t.as_str()) && !t.contains("МАДИ") && !t.contains("Кафедра"))
                {
                    assert!(
                        !t.chars().any(|c| c.is_ascii_alphabetic()),
                        "{path} {}: English in the title block: {t}",
                        lang.code()
                    );
                }
                // one title per drawing: the drawing's own, no sheet caption above it
                let caps = tokens(&svg).unwrap().iter().filter(|t| t.attr("class") == Some("caption")).count();
                assert_eq!(caps, 0, "{path}: a sheet caption besides the drawing's own title");
            } else {
                assert!(texts.iter().all(|t| !t.contains("Разраб.")));
            }
        }
    }
}

/// A drawing of `w × h` mm: one main line in a group `x`, the scale given.
fn fake(w: f64, h: f64, scale: Option<&str>) -> tmm_report::picture::Picture {
    use tmm_report::picture::{Element, Picture};
    let root = scale.map(|s| vec![("data-scale".to_string(), s.to_string())]).unwrap_or_default();
    Picture::new(
        w,
        h,
        root,
        vec![
            Element::GroupOpen {
                id: Some("x".into()),
                class: None,
                data: Vec::new(),
            },
            Element::Line {
                a: (0.0, 0.0),
                b: (w, h),
                style: tmm_report::svg::Style::THICK,
                round: false,
            },
            Element::GroupClose,
        ],
    )
}

#[test]
fn the_scale_comes_from_the_main_drawing_and_what_cannot_fit_is_left_off_the_sheet() {
    use tmm_report::project::Project;
    use tmm_report::sheets::layout_sheets;
    let mut docs = Documents::new();
    docs.add_text("cam/cam.svg", fake(200.0, 200.0, Some("2:1"))).unwrap();
    docs.add_text("cam/cam-motion.svg", fake(200.0, 150.0, Some("1:5"))).unwrap();
    docs.add_text("cam/cam-pressure.svg", fake(900.0, 100.0, None)).unwrap(); // wider than any A1 field
    docs.add_text("cam/extra-7.svg", fake(100.0, 100.0, None)).unwrap();
    let sheets = layout_sheets(&docs, &Project::default());
    assert_eq!(sheets.len(), 1);
    let s = &sheets[0];
    assert_eq!(s.scale, "2:1");
    assert_eq!(s.placed.len(), 3);
    assert_eq!(s.left_out, vec![word(Language::Ru, "sheet.fig_cam_cam_pressure").to_string()]);
    // a sheet shows what it holds: no list of what is not on it
    assert!(!s.svg.contains(word(Language::Ru, "sheet.left_out")));
    assert!(!s.svg.contains(word(Language::Ru, "sheet.fig_cam_cam_pressure")));
    let (_, texts) = group(&s.svg, "title-block");
    // the name is wrapped in its cell: its lines in order
    assert!(
        texts.iter().any(|t| t == "2:1") && texts.join(" ").contains("Кулачковый механизм"),
        "{texts:?}"
    );
    // ids of the nested drawings are made unique
    assert!(!s.svg.contains("id=\"x\""));
    let mut ids: Vec<&str> = s
        .svg
        .split("id=\"")
        .skip(1)
        .filter_map(|t| t.split('"').next())
        .filter(|t| t.ends_with("-x"))
        .collect();
    assert_eq!(ids.len(), 3, "one prefixed id per drawing");
    ids.sort_unstable();
    ids.dedup();
    assert_eq!(ids.len(), 3, "the ids differ");
    // the placed boxes are the drawings' own sizes
    let mut sizes: Vec<(f64, f64)> = drawings(&s.svg).iter().map(|(_, r)| (r.w, r.h)).collect();
    sizes.sort_by(|a, b| a.partial_cmp(b).unwrap());
    assert_eq!(sizes, vec![(100.0, 100.0), (200.0, 150.0), (200.0, 200.0)]);
}

/// Graph 9 of the title block wraps inside its cell: the default project's
/// university, department and group are too long for 50 × 15 mm at 2.5 mm,
/// so the university's index stands for its name, and nothing is cut.
#[test]
fn the_organisation_wraps_inside_its_cell() {
    let run = run_task(&TaskSource::new("t", DEFAULT_TASK)).unwrap();
    for (path, svg) in sheets(&run.docs) {
        let (_, texts) = group(&svg, "title-block");
        assert!(texts.iter().all(|t| !t.contains('…')), "{path}: a cut field: {texts:?}");
        let all = texts.join(" ");
        assert!(all.contains("МАДИ") && all.contains("2бАТ1"), "{path}: {all}");
        assert!(!all.contains("автомобильно-дорожный"), "{path}: the long name does not fit: {all}");
    }
}

/// Every title block of the default project, seed 003 and the synthesised
/// seed-003 six-bar, in ru, uk and en, as `sheet_documents` draws it: no
/// field cut, every text at 2.5 mm or more with its printed ink
/// (`tmm_draw::eskd::clearances`) 1 mm from the edges of the lines beside
/// it and above and below it; in a 5 mm row centred between its lines and
/// off them; the changes' row captions and the letter cell 0.5 mm from
/// the sides; no two texts overlapping.
#[test]
fn title_blocks_keep_their_texts_clear_of_the_lines() {
    use tmm_draw::eskd::{CLEAR_MM, FORM_CLEAR_MM, TIGHT_MM, clearances, sheet};
    let all = tasks();
    let picked: Vec<_> = all
        .iter()
        .filter(|(n, _)| ["default", "seed-003-sixbar.toml", "synth-seed-003-six-bar.toml"].contains(&n.as_str()))
        .collect();
    assert_eq!(picked.len(), 3);
    for (name, src) in picked {
        for lang in [Language::Ru, Language::Uk, Language::En] {
            let run = run_task_in(&TaskSource::new(name, src), Some(lang)).unwrap();
            let sheets = tmm_report::sheets::layout_sheets(&run.docs, &run.project);
            assert!(!sheets.is_empty(), "{name}");
            let format = match run.project.sheet {
                SheetFormat::A2 => tmm_draw::eskd::Format::A2,
                _ => tmm_draw::eskd::Format::A1,
            };
            for s in &sheets {
                let what = format!("{name} {} sheet {}", lang.code(), s.number);
                let tb = tmm_report::sheets::title_block_of(s, &run.project, sheets.len());
                let (scene, cut) = sheet(format, &tb).unwrap();
                assert!(cut.is_empty(), "{what}: cut {cut:?}");
                let c = clearances(&scene);
                assert!(c.len() > 20, "{what}: {c:?}");
                // the form's left part ends 65 mm from the block's left
                let left_part = scene.width - 5.0 - 185.0 + 65.0;
                for t in &c {
                    assert!(t.height >= 2.5, "{what}: {t:?}");
                    let form_row = t.cell.1 <= 5.0 + 1e-6 && t.ink.2 < left_part && t.ink.1 > 35.0 && t.ink.3 < 40.0;
                    let sides = if form_row || t.cell.0 <= 10.0 + 1e-6 {
                        FORM_CLEAR_MM
                    } else {
                        CLEAR_MM
                    };
                    assert!(t.sides >= sides - 1e-6, "{what}: {:?} {:.2} mm from a side line", t.text, t.sides);
                    if t.cell.1 > 5.0 + 1e-6 {
                        assert!(t.above.min(t.below) >= CLEAR_MM - 1e-6, "{what}: {:?} {t:?}", t.text);
                    } else {
                        assert!(t.above.min(t.below) >= TIGHT_MM - 1e-6, "{what}: {t:?}");
                        assert!((t.above - t.below).abs() < 1e-6, "{what}: {t:?}");
                    }
                }
                for (i, a) in c.iter().enumerate() {
                    for b in &c[i + 1..] {
                        let apart = a.ink.2 <= b.ink.0 || b.ink.2 <= a.ink.0 || a.ink.3 <= b.ink.1 || b.ink.3 <= a.ink.1;
                        assert!(apart, "{what}: {:?} and {:?} overlap", a.text, b.text);
                    }
                }
                // the scale field is filled: a scale or the dash of a sheet without one
                assert!(!tb.scale.trim().is_empty(), "{what}");
                assert!(c.iter().any(|t| t.text == tb.scale), "{what}: no scale {:?}", tb.scale);
            }
        }
    }
}
