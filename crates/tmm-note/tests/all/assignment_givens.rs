//! The technical assignment states every given of its task, as the task
//! gives it: for the default project and examples of an engine, the shaper,
//! a six-bar with a force of resistance, cams and a planetary train, in ru,
//! uk and en, the assignment's text (its paragraphs and tables) holds each
//! value read here from the task's TOML — the resistance on its link, the
//! mass per length, k of J_S = k·m·l², gravity on or off, each link's length
//! and the frame between the fixed joints, an engine's bore and peak
//! pressure, the cam's phase angles, the planetary train's scheme — and the
//! mechanism's scheme as its first figure; and every number of the task's
//! `[synthesis]`, `[cam]`, `[gear]`, `[planetary]`, `[cylinder]`, δ and the
//! input's speed and position, read from the task's text, printed as the
//! task writes it (K_v = 1,1065, 13 мм, 0,5 м/с, 1/30). Failed before: the assignment had
//! no figure, no resistance, no mass rule, no gravity statement, no frame
//! and no phases, and printed 900,0 об/мин; then K_v 1,107, 13,00 мм,
//! 20,00°, 0,5000 м/с, 0,03333 for 1/30.

use tmm_note::notation::{MATH_CLOSE, MATH_OPEN};
use tmm_note::{Block, Cell, Lang, Span, Text, compose};
use tmm_report::TaskSource;
use tmm_report::project::Language;
use tmm_report::run::{DEFAULT_TASK, run_task_in};

/// A text with its math markers and every kind of space removed (the note
/// sets a narrow no-break space between a number and its unit).
fn squeeze(s: &str) -> String {
    s.chars()
        .filter(|c| !c.is_whitespace() && !matches!(*c, '\u{202F}' | '\u{00A0}' | '\u{2009}') && *c != MATH_OPEN && *c != MATH_CLOSE)
        .collect()
}

/// A text without its math markers.
fn unmark(s: &str) -> String {
    s.chars().filter(|c| *c != MATH_OPEN && *c != MATH_CLOSE).collect()
}

fn text_of(t: &Text) -> String {
    t.0.iter()
        .map(|s| match s {
            Span::Plain(x) | Span::Strong(x) | Span::Emph(x) | Span::Math(x) => x.clone(),
            _ => String::new(),
        })
        .collect()
}

fn cell_text(c: &Cell, lang: Lang) -> String {
    match c {
        Cell::Text(t) => text_of(t),
        Cell::Number { value, digits } => tmm_note::number::format_number(*value, *digits, lang)
            .map(|f| f.to_string())
            .unwrap_or_default(),
        Cell::Empty => String::new(),
    }
}

/// The assignment as read: its paragraphs (squeezed), its tables' rows
/// (each row's cells without math markers), the captions of its figures.
struct Assignment {
    paragraphs: Vec<String>,
    rows: Vec<Vec<String>>,
    figures: Vec<String>,
}

impl Assignment {
    fn all(&self) -> String {
        let mut s = self.paragraphs.join(" ");
        for r in &self.rows {
            s.push(' ');
            s.push_str(&squeeze(&r.join(" ")));
        }
        s
    }

    /// Whether a row holds `value` in one cell and every one of `names` as a
    /// word of its cells (the link «3», the joints «A», «D»).
    fn row_with(&self, value: &str, names: &[&str]) -> bool {
        let value = squeeze(value);
        self.rows.iter().any(|r| {
            r.iter().any(|c| squeeze(c).contains(&value))
                && names
                    .iter()
                    .all(|n| r.iter().any(|c| c.split(|ch: char| !ch.is_alphanumeric()).any(|w| w == *n)))
        })
    }
}

fn read(blocks: &[Block], lang: Lang) -> Assignment {
    let mut a = Assignment {
        paragraphs: Vec::new(),
        rows: Vec::new(),
        figures: Vec::new(),
    };
    for b in blocks {
        match b {
            Block::Paragraph(t) => a.paragraphs.push(squeeze(&text_of(t))),
            Block::Table { rows, .. } => {
                for r in rows {
                    a.rows.push(r.iter().map(|c| unmark(&cell_text(c, lang))).collect());
                }
            }
            Block::Figure { caption, .. } => a.figures.push(squeeze(caption)),
            _ => {}
        }
    }
    a
}

fn language(lang: Lang) -> Language {
    match lang {
        Lang::Ru => Language::Ru,
        Lang::Uk => Language::Uk,
        Lang::En => Language::En,
    }
}

/// A number of the task with four significant digits at most and no
/// trailing zeros, with the language's decimal separator (0.1 → «0,1»,
/// 0.0833… → «0,08333», 510 → «510»).
fn as_given(x: f64, lang: Lang) -> String {
    let decimals = if x == 0.0 {
        0
    } else {
        (3 - x.abs().log10().floor() as i32).max(0) as usize
    };
    let mut s = format!("{x:.decimals$}");
    if s.contains('.') {
        s = s.trim_end_matches('0').trim_end_matches('.').to_string();
    }
    if lang != Lang::En {
        s = s.replace('.', ",");
    }
    s.replace('-', "\u{2212}")
}

/// A quantity of the task file: its number and its unit as written.
fn quantity(v: &toml::Value) -> (f64, String) {
    match v {
        toml::Value::Float(f) => (*f, String::new()),
        toml::Value::Integer(i) => (*i as f64, String::new()),
        toml::Value::String(s) => {
            let (n, u) = s.trim().split_once(' ').unwrap_or((s.trim(), ""));
            (n.parse().unwrap_or_else(|_| panic!("a number in {s}")), u.replace(' ', ""))
        }
        other => panic!("not a quantity: {other}"),
    }
}

/// The unit as the note writes it in `lang`, for the units of these tasks.
fn unit(u: &str, lang: Lang) -> &'static str {
    let en = lang == Lang::En;
    match u {
        "Nm" => {
            if en {
                "N·m"
            } else {
                "Н·м"
            }
        }
        "N" => {
            if en {
                "N"
            } else {
                "Н"
            }
        }
        "kg/m" => {
            if en {
                "kg/m"
            } else {
                "кг/м"
            }
        }
        "m/s^2" => {
            if en {
                "m/s²"
            } else {
                "м/с²"
            }
        }
        "mm" => {
            if en {
                "mm"
            } else {
                "мм"
            }
        }
        "MPa" => {
            if en {
                "MPa"
            } else {
                "МПа"
            }
        }
        "deg" => "°",
        "%" => "%",
        "rad/s" => {
            if en {
                "rad/s"
            } else {
                "рад/с"
            }
        }
        "rpm" => match lang {
            Lang::Ru => "об/мин",
            Lang::Uk => "об/хв",
            Lang::En => "rpm",
        },
        "m/s" => {
            if en {
                "m/s"
            } else {
                "м/с"
            }
        }
        "kg" => {
            if en {
                "kg"
            } else {
                "кг"
            }
        }
        "kgm^2" => {
            if en {
                "kg·m²"
            } else {
                "кг·м²"
            }
        }
        other => panic!("a unit the test does not know: {other}"),
    }
}

/// A given of the task's text as the note must print it: the number as the
/// task writes it (its own digits, the language's decimal separator, the
/// minus sign), a length in metres in millimetres (the course's unit; the
/// digits of x·1000), a fraction as written (`1/30`), the unit in the
/// note's words; `None` for a text that is no number (a law, a kind) or a
/// number written with more than six significant digits (a computed value
/// pasted into the task: the note prints four of them).
fn written(v: &toml::Value, lang: Lang) -> Option<String> {
    let sep = |t: &str| {
        let t = if lang == Lang::En { t.to_string() } else { t.replace('.', ",") };
        t.replace('-', "\u{2212}")
    };
    let digits = |t: &str| t.trim_start_matches(['-', '0', '.']).chars().filter(char::is_ascii_digit).count();
    let (number, u) = match v {
        toml::Value::Integer(i) => (i.to_string(), String::new()),
        toml::Value::Float(f) => (f.to_string(), String::new()),
        toml::Value::String(s) => {
            let s = s.trim();
            if let Some((a, b)) = s.split_once('/') {
                let int = |t: &str| t.trim().trim_start_matches('-').chars().all(|c| c.is_ascii_digit());
                return (int(a) && int(b)).then(|| s.replace('-', "\u{2212}"));
            }
            let (n, u) = s.split_once(' ').unwrap_or((s, ""));
            n.parse::<f64>().ok()?;
            (n.to_string(), u.replace(' ', ""))
        }
        _ => return None,
    };
    if digits(&number) > 6 {
        return None;
    }
    Some(match u.as_str() {
        "m" => {
            let mm = (number.parse::<f64>().ok()? * 1e3 * 1e6).round() / 1e6;
            format!("{}{}", sep(&mm.to_string()), unit("mm", lang))
        }
        "" => sep(&number),
        other => format!("{}{}", sep(&number), unit(other, lang)),
    })
}

/// The givens of the task's tables the assignment states as rows, each
/// with its text: every number of `[synthesis]`, `[cam]`, `[gear]`,
/// `[planetary]`, `[cylinder]`, δ of `[dynamics]` and the input's speed,
/// position and travel of `[linkage]` (a cam's least radius of curvature
/// and face margin, the gear pair's least tip thickness, the planetary
/// ratio's tolerance among them). Left out: the dynamics' number of
/// integration points (not a given of the machine).
fn task_givens(task: &toml::Table) -> Vec<(String, &toml::Value)> {
    fn walk<'a>(path: &str, v: &'a toml::Value, out: &mut Vec<(String, &'a toml::Value)>) {
        match v {
            toml::Value::Table(t) => t.iter().for_each(|(k, w)| walk(&format!("{path}.{k}"), w, out)),
            toml::Value::Array(a) => a.iter().for_each(|w| walk(path, w, out)),
            _ => out.push((path.to_string(), v)),
        }
    }
    let mut out = Vec::new();
    for section in ["synthesis", "cam", "gear", "planetary", "cylinder"] {
        if let Some(v) = task.get(section) {
            walk(section, v, &mut out);
        }
    }
    if let Some(d) = task.get("dynamics").and_then(|d| d.get("delta")) {
        out.push(("dynamics.delta".to_string(), d));
    }
    if let Some(l) = task.get("linkage") {
        for key in ["at", "travel", "input"] {
            if let Some(v) = l.get(key) {
                walk(&format!("linkage.{key}"), v, &mut out);
            }
        }
    }
    out
}

/// A length of the task in mm.
fn mm(v: &toml::Value) -> f64 {
    let (x, u) = quantity(v);
    match u.as_str() {
        "mm" => x,
        // a plain number is SI (metres), as the task reader takes it
        "m" | "" => x * 1e3,
        other => panic!("a length in {other}"),
    }
}

/// Checks one note's assignment against its task; the faults found.
fn check(name: &str, task_text: &str, lang: Lang, a: &Assignment) -> Vec<String> {
    let task: toml::Table = toml::from_str(task_text).unwrap();
    let mut faults = Vec::new();
    let all = a.all();
    let mut want = |ok: bool, what: String| {
        if !ok {
            faults.push(format!("{name} {lang:?}: {what}"));
        }
    };
    let scheme = match lang {
        Lang::Ru => "Схема механизма",
        Lang::Uk => "Схема механізму",
        Lang::En => "Scheme of the mechanism",
    };
    // a mechanism's scheme (a gear pair alone has none drawn)
    let mechanism = ["linkage", "synthesis", "cylinder", "planetary", "cam"]
        .iter()
        .any(|k| task.contains_key(*k));
    want(
        !mechanism || a.figures.first().is_some_and(|f| *f == squeeze(scheme)),
        format!("the first figure is not «{scheme}»: {:?}", a.figures),
    );
    if let Some(f) = task.get("forces") {
        if let Some(q) = f.get("mass_per_length") {
            let (x, u) = quantity(q);
            let s = format!("{}{}", as_given(x, lang), unit(&u, lang));
            want(all.contains(&squeeze(&s)), format!("no mass per length {s}"));
            // k of J_S = k·m·l², 0.1 unless the task gives it
            let k = f.get("k").map_or(0.1, |k| quantity(k).0);
            want(a.row_with(&as_given(k, lang), &[]), format!("no k = {}", as_given(k, lang)));
        }
        match f.get("gravity") {
            Some(g) => {
                let (x, u) = quantity(g);
                let s = format!("{}{}", as_given(x, lang), unit(&u, lang));
                want(all.contains(&squeeze(&s)), format!("no gravity {s}"));
            }
            None => {
                let off = match lang {
                    Lang::Ru => "не учитываются",
                    Lang::Uk => "не враховуються",
                    Lang::En => "neglected",
                };
                want(all.contains(&squeeze(off)), format!("no «{off}» of gravity"));
            }
        }
        for r in f.get("resistance").and_then(toml::Value::as_array).into_iter().flatten() {
            let link = r["link"].as_str().unwrap();
            let v = r.get("moment").or_else(|| r.get("force")).unwrap();
            let (x, u) = quantity(v);
            let s = format!("{}{}", as_given(x, lang), unit(&u, lang));
            let mut names = vec![link];
            if let Some(p) = r.get("point").and_then(toml::Value::as_str) {
                names.push(p);
            }
            want(a.row_with(&s, &names), format!("no row of the resistance {s} on link {link}"));
        }
        for c in f.get("cylinders").and_then(toml::Value::as_array).into_iter().flatten() {
            let link = c["link"].as_str().unwrap();
            for key in ["bore", "p_max"] {
                if let Some(v) = c.get(key) {
                    let (x, u) = quantity(v);
                    let s = format!("{}{}", as_given(x, lang), unit(&u, lang));
                    want(a.row_with(&s, &[link]), format!("no {key} {s} of the cylinder of link {link}"));
                }
            }
        }
        for fr in f.get("friction").and_then(toml::Value::as_array).into_iter().flatten() {
            let link = fr["link"].as_str().unwrap();
            let (x, u) = quantity(&fr["force"]);
            let s = format!("{}{}", as_given(x, lang), unit(&u, lang));
            want(a.row_with(&s, &[link]), format!("no friction {s} on link {link}"));
        }
    }
    if let Some(l) = task.get("linkage") {
        for link in l.get("links").and_then(toml::Value::as_array).into_iter().flatten() {
            if let Some(len) = link.get("length") {
                let name = link["name"].as_str().unwrap();
                let s = as_given(mm(len), lang);
                want(a.row_with(&s, &[name]), format!("no length {s} mm of link {name}"));
            }
        }
        let fixed: Vec<(&String, f64, f64)> = l["fixed"]
            .as_table()
            .unwrap()
            .iter()
            .map(|(n, p)| (n, mm(&p[0]), mm(&p[1])))
            .collect();
        for (i, p) in fixed.iter().enumerate() {
            for q in &fixed[i + 1..] {
                let s = as_given((p.1 - q.1).hypot(p.2 - q.2), lang);
                want(
                    a.row_with(&s, &[&format!("{}{}", p.0, q.0)]),
                    format!("no frame {}{} = {s} mm", p.0, q.0),
                );
            }
        }
    }
    if let Some(c) = task.get("cam") {
        for piece in c["phases"].as_str().unwrap().split(';') {
            let mut w = piece.split_whitespace();
            let (Some(_), Some(angle)) = (w.next(), w.next()) else { continue };
            let s = as_given(angle.parse().unwrap(), lang);
            want(a.row_with(&s, &[]), format!("no phase angle {s}"));
        }
    }
    // every given as the task writes it (K_v = 1,1065, not 1,107; 13 мм,
    // not 13,00 мм)
    for (key, v) in task_givens(&task) {
        if let Some(w) = written(v, lang) {
            want(all.contains(&squeeze(&w)), format!("{key} = {v} not as written «{w}»"));
        }
    }
    if let Some(p) = task.get("planetary") {
        if p["scheme"].as_str() == Some("sun-planet-ring") {
            let ring = match lang {
                Lang::Ru => "неподвижное корончатое колесо 3",
                Lang::Uk => "нерухоме коронне колесо 3",
                Lang::En => "fixed ring gear 3",
            };
            want(all.contains(&squeeze(ring)), format!("no «{ring}» in the scheme's words"));
        }
        // a fraction (`"1/30"`) is read as written above, with the givens
        let ratio = match &p["ratio"] {
            toml::Value::String(r) if r.contains('/') => None,
            r => Some(as_given(quantity(r).0, lang)),
        };
        if let Some(ratio) = ratio {
            want(a.row_with(&ratio, &[]), format!("no ratio {ratio} as given"));
        }
    }
    faults
}

fn example(path: &str) -> TaskSource {
    let p = format!("{}/../../examples/{path}", env!("CARGO_MANIFEST_DIR"));
    TaskSource::new(p.clone(), std::fs::read_to_string(&p).unwrap())
}

#[test]
fn the_assignment_states_every_given_of_its_task_with_the_scheme() {
    let tasks = [
        TaskSource::new("default.toml", DEFAULT_TASK),
        example("textbook/p2-engine.toml"),
        example("textbook/p3-shaper.toml"),
        example("seed-003-sixbar.toml"),
        example("cam-seed-001-roller.toml"),
        example("textbook/p6-cam-translating.toml"),
        example("planetary-sun-planet-ring.toml"),
        example("planetary-ext-ext.toml"),
        example("slider-input.toml"),
        example("textbook/p5-pneumatic-cylinder.toml"),
        example("textbook/p1-5-oscillating-cylinder-v2.toml"),
        example("textbook/p1-4-four-bar-three-positions.toml"),
        example("synth-seed-003-six-bar.toml"),
        example("cam-oscillating-roller.toml"),
        example("gear-seed001.toml"),
        example("gear-seed003.toml"),
        example("textbook/p6-cam-oscillating.toml"),
        example("synth-seed-002-ex1-crank-rocker.toml"),
        example("synth-seed-002-ex2-knee-press.toml"),
        example("synth-seed-002-ex4-six-bar.toml"),
        example("cam-seed-001-flat.toml"),
        example("planetary-ext-int.toml"),
    ];
    let mut faults = Vec::new();
    for task in &tasks {
        for lang in [Lang::Ru, Lang::Uk, Lang::En] {
            let run = run_task_in(task, Some(language(lang))).unwrap();
            let note = compose(&run, task).unwrap();
            let a = read(&note.assignment, lang);
            faults.extend(check(&task.name, &task.text, lang, &a));
        }
    }
    assert!(faults.is_empty(), "{} faults:\n{}", faults.len(), faults.join("\n"));
}

/// The default project's rows in detail: the 380 N·m on link 3 with its
/// sense, 10 kg/m and k = 0,1, the frame AD 510 mm, n₁ = 900 rpm as given
/// (not 900,0), the cam's laws beside their angles.
#[test]
fn the_default_assignment_gives_the_resisting_moment_frame_and_laws_as_given() {
    let task = TaskSource::new("default.toml", DEFAULT_TASK);
    let run = run_task_in(&task, Some(Language::Ru)).unwrap();
    let note = compose(&run, &task).unwrap();
    let a = read(&note.assignment, Lang::Ru);
    assert!(a.row_with("380 Н·м", &["3"]), "{:?}", a.rows);
    assert!(
        a.rows.iter().any(|r| r.iter().any(|c| c.contains("против вращения звена"))),
        "{:?}",
        a.rows
    );
    assert!(a.row_with("510", &["AD"]), "{:?}", a.rows);
    assert!(a.row_with("900об/мин", &[]), "{:?}", a.rows);
    assert!(!a.all().contains("900,0"), "{:?}", a.rows);
    // the rise of 108° by the constant-acceleration law with u = 1/3
    assert!(
        a.rows.iter().any(|r| r.len() == 3 && r[1] == "108" && r[2].contains("(u=1/3)")),
        "{:?}",
        a.rows
    );
}

/// The cam's least radius of curvature and face margin, the gear pair's
/// least tip thickness and the planetary ratio's tolerance each in a row of
/// its own words, the value as the task writes it: ρ_min = 10 мм and 5 мм
/// of the flat-faced cam, s_a min = 0,3·m with its millimetres (0,3 of the
/// task's 5 mm module), the ratio within 1 %. Failed before: none of the
/// four was printed.
#[test]
fn the_profile_tip_and_ratio_limits_are_given_in_their_rows() {
    let cases: [(&str, Lang, &str, String); 7] = [
        ("cam-seed-001-flat.toml", Lang::Ru, "радиус кривизны профиля", "10мм".into()),
        ("cam-seed-001-flat.toml", Lang::Ru, "Запас ширины тарелки", "5мм".into()),
        ("cam-seed-001-flat.toml", Lang::En, "Margin of the follower's face", "5mm".into()),
        ("gear-seed001.toml", Lang::Ru, "толщина зуба на окружности вершин", String::new()),
        ("gear-seed001.toml", Lang::Uk, "товщина зуба на колі вершин", String::new()),
        (
            "planetary-ext-int.toml",
            Lang::Ru,
            "отклонение передаточного отношения",
            "1%".into(),
        ),
        ("planetary-ext-int.toml", Lang::En, "deviation of the ratio", "1%".into()),
    ];
    for (file, lang, label, want) in cases {
        let task = example(file);
        let run = run_task_in(&task, Some(language(lang))).unwrap();
        let note = compose(&run, &task).unwrap();
        let a = read(&note.assignment, lang);
        let want = if want.is_empty() {
            // the share of the task's text times its module, both read here
            let t: toml::Table = toml::from_str(&task.text).unwrap();
            let share = quantity(&t["gear"]["sa_min"]).0;
            let m = mm(&t["gear"]["module"]);
            squeeze(&format!("{}·m = {}", as_given(share, lang), as_given(share * m, lang)))
        } else {
            want
        };
        let row = a.rows.iter().find(|r| r.first().is_some_and(|c| c.contains(label)));
        assert!(
            row.is_some_and(|r| r.get(1).is_some_and(|v| squeeze(v).starts_with(&want))),
            "{file} {lang:?}: no row «{label}» with «{want}»: {row:?}"
        );
    }
}
