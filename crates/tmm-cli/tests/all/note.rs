//! `tmm note` and the PDFs of `tmm run`, through the binary: the note is
//! written, has the language's headings, `--no-pdf` writes none, bad input
//! exits with 2 and an unwritable folder with 1, never a panic.

use std::path::PathBuf;

use crate::common::{self, run};

fn tempdir(tag: &str) -> PathBuf {
    common::tmp("note", tag)
}

fn text(pdf: &std::path::Path) -> String {
    let raw = pdf_extract::extract_text_from_mem(&std::fs::read(pdf).unwrap()).unwrap();
    raw.replace('\u{00AD}', "").split_whitespace().collect::<Vec<_>>().join(" ")
}

#[test]
fn tmm_note_writes_the_note_in_the_language_asked() {
    let dir = tempdir("lang");
    let task = dir.join("gear.toml");
    std::fs::write(&task, "[gear]\nz1 = 15\nz2 = 20\nmodule = \"5 mm\"\nx1 = 0.2\nx2 = 0.85\n").unwrap();
    let out = dir.join("out");
    let (code, stdout, stderr) = run(&["note", task.to_str().unwrap(), "--lang", "uk", "--out", out.to_str().unwrap()]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stdout.contains("note.pdf"));
    for stage in ["computing", "typesetting the note", "writing"] {
        assert!(stderr.contains(stage), "no progress line {stage:?}: {stderr}");
    }
    let t = text(&out.join("note.pdf"));
    assert!(t.contains("Синтез евольвентного зубчастого зачеплення"), "{t}");
    // ε_α is typeset as mathematics: ε with the index α, which the PDF's
    // text gives as the mathematical italic letters 𝜀 (U+1D700) and 𝛼 (U+1D6FC)
    // (the text reader puts a space between the letter and its index)
    let flat: String = t.chars().filter(|c| !c.is_whitespace()).collect();
    assert!(flat.contains("\u{1D700}\u{1D6FC}=1,205"), "{t}");
    assert!(!t.contains("Структурний і кінематичний аналіз"));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn tmm_note_bad_input_exits_2() {
    let dir = tempdir("bad");
    let (code, _, stderr) = run(&["note", dir.join("missing.toml").to_str().unwrap(), "--out", dir.to_str().unwrap()]);
    assert_eq!(code, 2, "{stderr}");
    let bad = dir.join("bad.toml");
    std::fs::write(&bad, "[gear]\nz1 = -15\nz2 = 20\nmodule = \"5 mm\"\n").unwrap();
    let (code, _, stderr) = run(&["note", bad.to_str().unwrap(), "--out", dir.to_str().unwrap()]);
    assert_eq!(code, 2, "{stderr}");
    assert!(!stderr.contains("panicked"));
    let (code, _, _) = run(&["note", "--lang", "de"]);
    assert_eq!(code, 2);
    assert!(!dir.join("note.pdf").exists());
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn tmm_note_unwritable_out_exits_1() {
    let dir = tempdir("unwritable");
    let task = dir.join("gear.toml");
    std::fs::write(&task, "[gear]\nz1 = 15\nz2 = 20\nmodule = \"5 mm\"\n").unwrap();
    // the output folder's place is taken by a file
    let file = dir.join("a-file");
    std::fs::write(&file, "x").unwrap();
    let (code, _, stderr) = run(&["note", task.to_str().unwrap(), "--out", file.join("sub").to_str().unwrap()]);
    assert_eq!(code, 1, "{stderr}");
    assert!(!stderr.contains("panicked"));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn tmm_run_no_pdf_writes_no_pdf_and_run_writes_the_note() {
    let dir = tempdir("run");
    let task = dir.join("gear.toml");
    std::fs::write(&task, "[gear]\nz1 = 15\nz2 = 20\nmodule = \"5 mm\"\nx1 = 0.2\nx2 = 0.85\n").unwrap();
    let out = dir.join("out");
    let (code, _, stderr) = run(&["run", task.to_str().unwrap(), "--no-pdf", "--out", out.to_str().unwrap()]);
    assert_eq!(code, 0, "{stderr}");
    assert!(out.join("gear/mesh.svg").exists());
    let pdfs: Vec<_> = walk(&out)
        .into_iter()
        .filter(|p| p.extension().is_some_and(|e| e == "pdf"))
        .collect();
    assert!(pdfs.is_empty(), "{pdfs:?}");
    assert!(!stderr.contains("typesetting"));
    let (code, _, stderr) = run(&["run", task.to_str().unwrap(), "--lang", "en", "--out", out.to_str().unwrap()]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stderr.contains("typesetting the note"));
    let t = text(&out.join("note.pdf"));
    assert!(t.contains("Synthesis of the involute gear pair"));
    let flat: String = t.chars().filter(|c| !c.is_whitespace()).collect();
    assert!(flat.contains("Thepairpasseseveryqualitycheck;\u{1D700}\u{1D6FC}=1.205"), "{t}");
    std::fs::remove_dir_all(&dir).unwrap();
}

fn walk(dir: &std::path::Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            out.extend(walk(&p));
        } else {
            out.push(p);
        }
    }
    out
}
