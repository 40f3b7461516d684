//! The gear's diameters are written with their indices set as indices
//! (issue 22, point 3; `d_w`, `d_b`, `d_a`, `d_f` as the formulas set them):
//! in every drawing of the runs below — the default project, the gear
//! examples, the drawings made for the note's page and the sheets — no
//! text run on the line of a text in the drawing's scene (what the SVG,
//! the PDF and the DXF's MTEXT are written from) holds `dw`, `db`, `da`
//! or `df` as a word of its own or followed by a wheel's number (`dw1`),
//! where a subscript is meant. The scene is read, not the file.

use tmm_draw::Shape;
use tmm_report::TaskSource;
use tmm_report::output::Documents;
use tmm_report::project::Language;
use tmm_report::run::{DEFAULT_TASK, note_figures, run_task_in};
use tmm_testkit::examples;

/// The words of `s` that are a diameter's symbol written flat: `d`, one of
/// w b a f, then nothing or digits.
fn flat_diameters(s: &str) -> Vec<String> {
    s.split(|c: char| !c.is_alphanumeric())
        .filter(|w| {
            let mut ch = w.chars();
            ch.next() == Some('d') && matches!(ch.next(), Some('w' | 'b' | 'a' | 'f')) && ch.all(|c| c.is_ascii_digit())
        })
        .map(str::to_string)
        .collect()
}

/// Every flat diameter in the base runs of every drawing of `docs`.
fn faults(name: &str, docs: &Documents, out: &mut Vec<String>, runs: &mut usize) {
    for d in docs.iter() {
        let Some(p) = docs.picture(&d.path) else { continue };
        let scene = p.scene();
        for item in scene.items() {
            if let Shape::Text(t) = &item.shape {
                for s in &t.rich.spans {
                    *runs += 1;
                    for w in flat_diameters(&s.base) {
                        out.push(format!("{name}: {}: \"{w}\" in \"{}\"", d.path, s.base));
                    }
                }
            }
        }
    }
}

#[test]
fn the_flat_index_finder_finds_what_it_must() {
    assert_eq!(flat_diameters("начальные окружности dw"), vec!["dw"]);
    assert_eq!(flat_diameters("db1 = 3; da, df2"), vec!["db1", "da", "df2"]);
    assert!(flat_diameters("d_w dwell dbx d1 add").is_empty());
}

#[test]
fn no_drawing_writes_a_diameter_index_flat() {
    let tasks = [
        ("default.toml", DEFAULT_TASK.to_string()),
        ("gear-seed001.toml", examples::text("gear-seed001.toml")),
        ("gear-internal.toml", examples::text("gear-internal.toml")),
        ("gear-seed003.toml", examples::text("gear-seed003.toml")),
    ];
    let (mut out, mut runs) = (Vec::new(), 0);
    for (name, text) in &tasks {
        for lang in [Language::Ru, Language::Uk, Language::En] {
            let task = TaskSource::new(*name, text.as_str());
            let label = format!("{name} {lang:?}");
            faults(&label, &run_task_in(&task, Some(lang)).unwrap().docs, &mut out, &mut runs);
            faults(
                &format!("{label} (note)"),
                &note_figures(&task, Some(lang)).unwrap(),
                &mut out,
                &mut runs,
            );
        }
    }
    println!("text runs read: {runs}");
    assert!(runs > 1000, "{runs}");
    assert!(out.is_empty(), "{} flat indices:\n{}", out.len(), out.join("\n"));
}
