//! Numbers in the note's sentences at a sensible precision (issue 22,
//! point 8): a sentence never writes an exact zero as "0,000" (four
//! significant digits of nothing: the relative difference of the two
//! balancing moments, the synthesised K_v's error), and a value set beside
//! the given it meets ("δ = 0,02 при заданном 0,02") is written as the given
//! is, not "0,02000 при заданном 0,02".
//!
//! Read from the composed note's paragraphs (their plain text), for the
//! default project in ru, uk and en and every example in Russian.

use tmm_note::{Block, Section, Span, compose};
use tmm_report::project::Language;
use tmm_report::run::{DEFAULT_TASK, run_task_in};

/// The plain text of every paragraph of a section and its subsections.
fn paragraphs(s: &Section, out: &mut Vec<String>) {
    for b in &s.blocks {
        if let Block::Paragraph(t) = b {
            let mut p = String::new();
            for span in &t.0 {
                if let Span::Plain(x) = span {
                    p.push_str(x);
                }
            }
            out.push(p);
        }
    }
    for ss in &s.subsections {
        paragraphs(ss, out);
    }
}

/// The decimal numbers of a text (digits with one `,` or `.` inside), with
/// their byte ranges.
fn decimals(t: &str) -> Vec<(usize, usize, String)> {
    let b = t.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        if b[i].is_ascii_digit() && (i == 0 || !(b[i - 1].is_ascii_digit() || b[i - 1] == b',' || b[i - 1] == b'.')) {
            let s = i;
            while i < b.len() && b[i].is_ascii_digit() {
                i += 1;
            }
            if i + 1 < b.len() && (b[i] == b',' || b[i] == b'.') && b[i + 1].is_ascii_digit() {
                i += 1;
                while i < b.len() && b[i].is_ascii_digit() {
                    i += 1;
                }
                out.push((s, i, t[s..i].to_string()));
            }
        } else {
            i += 1;
        }
    }
    out
}

fn value(s: &str) -> f64 {
    s.replace(',', ".").parse().unwrap()
}

/// The faults of one note's sentences.
fn faults_of(name: &str, paras: &[String], faults: &mut Vec<String>) {
    for p in paras {
        let nums = decimals(p);
        for (_, _, n) in &nums {
            if value(n) == 0.0 {
                faults.push(format!("{name}: an exact zero written \"{n}\" in \"{p}\""));
            }
        }
        for w in nums.windows(2) {
            let (a, b) = (&w[0], &w[1]);
            let between = &p[a.1..b.0];
            let meets = ["при заданном", "за заданого", "for the given"]
                .iter()
                .any(|k| between.trim() == *k);
            if meets && value(&a.2) == value(&b.2) && a.2 != b.2 {
                faults.push(format!("{name}: \"{}{between}{}\" writes one value two ways in \"{p}\"", a.2, b.2));
            }
        }
    }
}

#[test]
fn the_finders_find_what_they_must() {
    let mut f = Vec::new();
    faults_of(
        "self-test",
        &[
            "относительная погрешность 0,000; всё".into(),
            "δ = 0,02000 при заданном 0,02.".into(),
            "δ = 0,02 при заданном 0,02, погрешность 0 %, ход 10,05 мм".into(),
        ],
        &mut f,
    );
    assert_eq!(f.len(), 2, "{f:#?}");
}

#[test]
fn sentences_write_zeros_and_met_givens_sensibly() {
    let mut tasks = vec![(
        "default".to_string(),
        tmm_report::TaskSource::new("default.toml", DEFAULT_TASK),
        vec![Language::Ru, Language::Uk, Language::En],
    )];
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    for dir in [root.clone(), root.join("textbook")] {
        let mut files: Vec<_> = std::fs::read_dir(&dir)
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|x| x == "toml"))
            .collect();
        files.sort();
        for p in files {
            let text = std::fs::read_to_string(&p).unwrap();
            tasks.push((
                p.file_name().unwrap().to_string_lossy().into_owned(),
                tmm_report::TaskSource::new(p.display().to_string(), text),
                vec![Language::Ru],
            ));
        }
    }
    let mut faults = Vec::new();
    let mut sentences = 0;
    for (name, task, langs) in &tasks {
        for &lang in langs {
            let run = run_task_in(task, Some(lang)).unwrap();
            let note = compose(&run, task).unwrap();
            let mut paras = Vec::new();
            for s in note.sections.iter().chain(&note.introduction).chain(&note.conclusion) {
                paragraphs(s, &mut paras);
            }
            sentences += paras.len();
            faults_of(&format!("{name} {lang:?}"), &paras, &mut faults);
        }
    }
    println!("{} notes, {sentences} paragraphs read", tasks.len());
    assert!(faults.is_empty(), "{} faults:\n{}", faults.len(), faults.join("\n"));
}
