//! The numbers of each figure equal its table's (issue 22, points 1 and 10):
//! every value a figure of the composed note prints next to a symbol
//! (`R03 1291,8 Н`, `M_д = 81,447 Н·м`, `a_w = 92,000 мм`) is paired with
//! the quantity of the same symbol in the tables of its section, and the
//! two must agree at the printed precision of both.
//!
//! How the two sides are read, independently of the code that wrote them:
//!
//! - a figure's values come from its SVG's texts (the subscripts' markup
//!   dropped: `M<tspan>д</tspan>` reads `Mд`): a symbol, `=` or a space,
//!   a number and its unit; texts are cut at `;`, `: ` and `, `;
//! - a table's quantities come from its cells: in a "quantity | value"
//!   table, the symbol that ends the quantity's name (`Движущий момент
//!   M_д`) and the number of the value; in a table with a column per
//!   quantity, the column's symbol and the row's key (`Звено 2` → 2, the
//!   links of a reaction `0→3` → 03, either order: R₀₃ = −R₃₀); in a table
//!   of wheels (`Колесо 1`), the row's symbol and the wheel's number;
//! - symbols compare without their markup (`M_"д"`, `Mд`, `M_{д}` are one);
//!   a figure's value without a sign is a magnitude (arrows carry the
//!   direction);
//! - a symbol that a figure prints with several values labels levels or
//!   positions (the blocking contour's ε_α = 1 and 1,2 isolines), not a
//!   quantity, and is left out.
//!
//! The test prints the figures checked and the pairs compared per note,
//! and requires the force plans, the lever, the flywheel's and the gear,
//! planetary and cam figures of the default project to be paired.

use tmm_note::notation::{MATH_CLOSE, MATH_OPEN};
use tmm_note::{Block, Cell, Note, Section, Span, Text, compose};
use tmm_report::TaskSource;
use tmm_report::project::Language;
use tmm_report::run::{DEFAULT_TASK, run_task_in};
use tmm_testkit::examples;

/// A printed number: its value, half a unit of its last digit, and whether
/// a sign was written.
#[derive(Debug, Clone, Copy)]
struct Printed {
    value: f64,
    half_ulp: f64,
    signed: bool,
}

/// A value a figure shows: its symbol (as compared) and number, and the text
/// it stands in.
#[derive(Debug, Clone)]
struct Shown {
    symbol: String,
    number: Printed,
    text: String,
}

/// A quantity of a table: its symbol (as compared), number and where.
#[derive(Debug, Clone)]
struct Tabled {
    symbol: String,
    number: Printed,
    place: String,
}

/// A symbol without its markup: the math run's markers, `_`, `^`, braces,
/// brackets, quotes, bars and spaces dropped.
fn canon(s: &str) -> String {
    s.chars()
        .filter(|c| {
            !matches!(
                c,
                '_' | '^' | '(' | ')' | '{' | '}' | '[' | ']' | '"' | '|' | ' ' | '\u{202f}' | '\u{a0}'
            ) && *c != MATH_OPEN
                && *c != MATH_CLOSE
        })
        .collect()
}

/// A symbol's characters: letters, digits, primes, `+` (`Fи1+G1`), `Δ`, `*`.
fn symbol_like(s: &str) -> bool {
    let mut ch = s.chars();
    ch.next().is_some_and(|c| c.is_alphabetic() || c == '|' || c == '[')
        && s.chars()
            .all(|c| c.is_alphanumeric() || matches!(c, '\'' | '′' | '″' | '+' | '*' | '_' | '^' | '|' | '[' | ']' | '"'))
}

/// The number at the start of `s` (after spaces): an optional sign (`−`,
/// `-`, `+`), digits, a decimal comma or point followed by digits. `None`
/// when none, or when a letter or a power of ten follows at once (`0,3m`,
/// `1,2·10⁵`: not a plain value). Returns the number and the rest.
fn number_at(s: &str) -> Option<(Printed, &str)> {
    let t = s.trim_start();
    let mut chars = t.char_indices().peekable();
    let mut signed = false;
    let mut neg = false;
    let mut digits = String::new();
    if let Some(&(_, c)) = chars.peek()
        && matches!(c, '−' | '-' | '+')
    {
        signed = true;
        neg = c != '+';
        chars.next();
    }
    let mut decimals: Option<usize> = None;
    let mut end = t.len();
    while let Some(&(i, c)) = chars.peek() {
        if c.is_ascii_digit() {
            digits.push(c);
            if let Some(d) = decimals.as_mut() {
                *d += 1;
            }
            chars.next();
        } else if matches!(c, ',' | '.')
            && decimals.is_none()
            && !digits.is_empty()
            && t[i + c.len_utf8()..].starts_with(|d: char| d.is_ascii_digit())
        {
            digits.push('.');
            decimals = Some(0);
            chars.next();
        } else {
            end = i;
            break;
        }
    }
    if digits.is_empty() || digits == "." {
        return None;
    }
    let rest = &t[end..];
    if rest.starts_with(|c: char| c.is_alphanumeric() || c == '·' || c == '/' || c == ':') {
        return None;
    }
    let v: f64 = digits.parse().ok()?;
    Some((
        Printed {
            value: if neg { -v } else { v },
            half_ulp: 0.5 * 10f64.powi(-(decimals.unwrap_or(0) as i32)),
            signed,
        },
        rest,
    ))
}

/// The values a figure's texts show.
fn shown(texts: &[String]) -> Vec<Shown> {
    let mut out = Vec::new();
    // every value written after a symbol, plain or not (`s_a1 = 0,3m`)
    let mut written: Vec<(String, String)> = Vec::new();
    for t in texts {
        let t = t.replace(['\u{202f}', '\u{a0}'], " ");
        for seg in t.split([';', '\n']).flat_map(|s| s.split(": ")).flat_map(|s| s.split(", ")) {
            let seg = seg.trim();
            let found = if seg.contains(" = ") {
                let parts: Vec<&str> = seg.split(" = ").collect();
                let symbol = parts[0].split_whitespace().last().unwrap_or("");
                written.push((canon(symbol), parts[parts.len() - 1].trim().to_string()));
                number_at(parts[parts.len() - 1]).map(|(n, _)| (symbol.to_string(), n))
            } else {
                // a force's label: `R03 1291,8 Н`
                let w: Vec<&str> = seg.split_whitespace().collect();
                if (2..=3).contains(&w.len()) {
                    number_at(w[1])
                        .filter(|(_, rest)| rest.is_empty())
                        .map(|(n, _)| (w[0].to_string(), n))
                } else {
                    None
                }
            };
            if let Some((symbol, number)) = found
                && symbol_like(&symbol)
            {
                out.push(Shown {
                    symbol: canon(&symbol),
                    number,
                    text: t.clone(),
                });
            }
        }
    }
    // a symbol shown with several values labels levels, not a quantity
    // (the blocking contour's s_a1 = 0, 0,3m, 0,4m)
    let several = |s: &str| {
        let vals: Vec<&String> = written.iter().filter(|x| x.0 == s).map(|x| &x.1).collect();
        vals.iter().any(|v| *v != vals[0])
    };
    let keep: Vec<bool> = out.iter().map(|x| !several(&x.symbol)).collect();
    out.into_iter().zip(keep).filter(|(_, k)| *k).map(|(x, _)| x).collect()
}

/// The texts of an SVG document, the markup inside each dropped (also
/// read by `figure_titles`).
pub fn svg_texts(svg: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = svg;
    while let Some(i) = rest.find("<text") {
        let r = &rest[i..];
        let Some(end) = r.find("</text>") else { break };
        let body = &r[r.find('>').map_or(end, |g| g + 1).min(end)..end];
        let mut s = String::new();
        let mut in_tag = false;
        for c in body.chars() {
            match c {
                '<' => in_tag = true,
                '>' => in_tag = false,
                _ if !in_tag => s.push(c),
                _ => {}
            }
        }
        out.push(s.replace("&amp;", "&").replace("&lt;", "<").replace("&gt;", ">"));
        rest = &r[end..];
    }
    out
}

/// A text's characters as written in the note (math runs with their
/// markers, numbers as printed).
fn flat(t: &Text) -> String {
    t.0.iter()
        .map(|s| match s {
            Span::Plain(p) | Span::Strong(p) | Span::Emph(p) => p.clone(),
            Span::Math(m) => format!("{MATH_OPEN}{m}{MATH_CLOSE}"),
            Span::Number { value, digits, unit } => {
                format!("{} {unit}", printed_number(*value, *digits).0)
            }
            Span::Ref(_) | Span::Cite(_) => String::new(),
        })
        .collect()
}

/// A number with `digits` significant digits as a plain decimal and half
/// its last unit.
fn printed_number(value: f64, digits: u8) -> (String, f64) {
    if value == 0.0 {
        return ("0".into(), 0.5);
    }
    let e = value.abs().log10().floor() as i32;
    let dec = (digits as i32 - 1 - e).max(0) as usize;
    (format!("{value:.dec$}"), 0.5 * 10f64.powi(-(digits as i32 - 1 - e)))
}

/// The symbol of a quantity's name: its last math run, or its last word
/// when that is a symbol of at most four characters (`θ`, `a`, `z1`, `εα`).
fn name_symbol(name: &str) -> Option<String> {
    if let Some(open) = name.rfind(MATH_OPEN) {
        let close = name[open..].find(MATH_CLOSE)? + open;
        return Some(canon(&name[open..close]));
    }
    let last = name.split_whitespace().last()?;
    (last.chars().count() <= 4 && symbol_like(last)).then(|| canon(last))
}

fn cell_number(c: &Cell) -> Option<Printed> {
    match c {
        Cell::Number { value, digits } => {
            let (_, half_ulp) = printed_number(*value, *digits);
            Some(Printed {
                value: *value,
                half_ulp,
                signed: true,
            })
        }
        Cell::Text(t) => number_at(&flat(t).replace('\u{202f}', " ")).map(|(n, _)| Printed { signed: true, ..n }),
        Cell::Empty => None,
    }
}

fn cell_text(c: &Cell) -> String {
    match c {
        Cell::Text(t) => flat(t),
        _ => String::new(),
    }
}

/// The quantities of a table, each with its symbol.
fn tabled(caption: &str, header: &[String], rows: &[Vec<Cell>]) -> Vec<Tabled> {
    let mut out = Vec::new();
    let mut push = |symbol: String, number: Printed, place: String| {
        if !symbol.is_empty() {
            out.push(Tabled { symbol, number, place });
        }
    };
    let two = header.len() == 2 && rows.iter().all(|r| r.len() == 2 && matches!(r[0], Cell::Text(_)));
    if two {
        // quantity | value
        for r in rows {
            let name = cell_text(&r[0]);
            if let (Some(s), Some(n)) = (name_symbol(&name), cell_number(&r[1])) {
                push(s, n, format!("{caption}: {name}"));
            }
        }
        return out;
    }
    // the key columns: the text cells at the row's start
    let col_symbol: Vec<Option<String>> = header.iter().map(|h| name_symbol(h)).collect();
    for r in rows {
        let keys: Vec<String> = r.iter().take_while(|c| matches!(c, Cell::Text(_))).map(cell_text).collect();
        let Some(first) = keys.first() else { continue };
        // a row of a table of positions (0, 1 … 6′) has no quantity's key
        if first.trim().chars().all(|c| c.is_ascii_digit() || matches!(c, '\'' | '′')) {
            continue;
        }
        let mut row_keys: Vec<String> = Vec::new();
        if let Some(k) = keys.iter().find_map(|k| k.split_once('→')) {
            // the links of a reaction; frame is link 0 in the figures
            let (a, b) = (canon(k.0), canon(k.1));
            row_keys.push(format!("{a}{b}"));
            row_keys.push(format!("{b}{a}"));
        } else if let Some(last) = first.split_whitespace().last()
            && first.split_whitespace().count() == 2
            && last.chars().all(|c| c.is_ascii_digit())
        {
            // "Звено 2"
            row_keys.push(last.to_string());
        } else if symbol_like(first.trim()) && first.trim().chars().count() <= 3 {
            // a point or a pair: B, S1
            row_keys.push(canon(first));
        }
        let row_symbol = name_symbol(first);
        for (j, c) in r.iter().enumerate().skip(keys.len()) {
            let Some(n) = cell_number(c) else { continue };
            let h = header.get(j).map(String::as_str).unwrap_or("");
            let wheel = h.split_whitespace().last().filter(|w| w.chars().all(|c| c.is_ascii_digit()));
            match (wheel, &row_symbol, col_symbol.get(j).cloned().flatten()) {
                // a table of wheels: the row's symbol and the wheel's number
                (Some(w), Some(rs), _) => push(format!("{rs}{w}"), n, format!("{caption}: {first}, {h}")),
                (None, _, Some(cs)) => {
                    for k in &row_keys {
                        push(format!("{cs}{k}"), n, format!("{caption}: {first}, {h}"));
                    }
                }
                _ => {}
            }
        }
    }
    out
}

/// A figure of a section: its caption and the values it shows.
struct Figure {
    caption: String,
    shown: Vec<Shown>,
}

fn collect(s: &Section, figures: &mut Vec<Figure>, tables: &mut Vec<Tabled>) {
    for b in &s.blocks {
        match b {
            Block::Figure { caption, svg, .. } => figures.push(Figure {
                caption: caption.clone(),
                shown: shown(&svg_texts(svg)),
            }),
            Block::Table { caption, header, rows, .. } => tables.extend(tabled(caption, header, rows)),
            _ => {}
        }
    }
    for ss in &s.subsections {
        collect(ss, figures, tables);
    }
}

/// The counts of one note: figures checked (those with a value paired),
/// pairs compared, and the captions of the figures checked.
#[derive(Debug, Default)]
struct Counts {
    figures: usize,
    pairs: usize,
    paired: Vec<String>,
    /// The figures that show values none of which is paired: (caption,
    /// the symbols shown).
    unpaired: Vec<(String, Vec<String>)>,
}

/// Pairs every value of every figure with its section's tables; a value
/// that differs from every quantity of its symbol is a fault.
fn check(name: &str, note: &Note, faults: &mut Vec<String>) -> Counts {
    let mut counts = Counts::default();
    for s in note.sections.iter().chain(&note.appendices) {
        let (mut figures, mut tables) = (Vec::new(), Vec::new());
        collect(s, &mut figures, &mut tables);
        for f in &figures {
            let mut paired = 0;
            for x in &f.shown {
                let candidates: Vec<&Tabled> = tables.iter().filter(|t| t.symbol == x.symbol).collect();
                if candidates.is_empty() {
                    continue;
                }
                paired += 1;
                let agrees = |t: &Tabled| {
                    let (a, b) = if x.number.signed {
                        (x.number.value, t.number.value)
                    } else {
                        (x.number.value.abs(), t.number.value.abs())
                    };
                    (a - b).abs() <= t.number.half_ulp + x.number.half_ulp + 1e-9 * b.abs()
                };
                if !candidates.iter().any(|t| agrees(t)) {
                    faults.push(format!(
                        "{name}, section \"{}\", figure \"{}\": {} = {} (in \"{}\"), the tables give {}",
                        s.title,
                        f.caption,
                        x.symbol,
                        x.number.value,
                        x.text,
                        candidates
                            .iter()
                            .map(|t| format!("{} ({})", t.number.value, t.place))
                            .collect::<Vec<_>>()
                            .join(", ")
                    ));
                }
            }
            if paired > 0 {
                counts.figures += 1;
                counts.pairs += paired;
                counts.paired.push(f.caption.clone());
            } else if !f.shown.is_empty() {
                counts
                    .unpaired
                    .push((f.caption.clone(), f.shown.iter().map(|x| x.symbol.clone()).collect()));
            }
        }
    }
    counts
}

fn svg(texts: &[&str]) -> String {
    let mut s = String::from(r#"<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="50mm" viewBox="0 0 100 50">"#);
    for t in texts {
        s.push_str(&format!(r#"<text x="1" y="5" font-size="3.5">{t}</text>"#));
    }
    s.push_str("</svg>");
    s
}

fn one_section(figure_texts: &[&str]) -> Note {
    let mut s = Section::new("Раздел");
    s.blocks.push(Block::Table {
        caption: "Результаты".into(),
        header: vec!["Величина".into(), "Значение".into()],
        rows: vec![
            vec![
                Cell::Text(Text::plain(format!("Движущий момент {MATH_OPEN}M_\"д\"{MATH_CLOSE}"))),
                Cell::Text(Text::plain("81,45\u{202f}Н·м")),
            ],
            vec![
                Cell::Text(Text::plain("Коэффициент торцового перекрытия ε_α")),
                Cell::Text(Text::plain("1,205")),
            ],
        ],
        units: vec![],
        label: None,
    });
    s.blocks.push(Block::Table {
        caption: "Реакции".into(),
        header: vec!["Пара".into(), "Звенья".into(), "Реакция |R|".into()],
        rows: vec![vec![
            Cell::Text(Text::plain("A")),
            Cell::Text(Text::plain("0→1")),
            Cell::Number { value: 5618.2, digits: 4 },
        ]],
        units: vec![String::new(), String::new(), "Н".into()],
        label: None,
    });
    s.blocks.push(Block::Table {
        caption: "Колёса".into(),
        header: vec!["Величина".into(), "Колесо 1".into(), "Колесо 2".into()],
        rows: vec![vec![
            Cell::Text(Text::plain(format!("Основной диаметр {MATH_OPEN}d_b{MATH_CLOSE}"))),
            Cell::Number { value: 70.4769, digits: 4 },
            Cell::Number { value: 93.9693, digits: 4 },
        ]],
        units: vec![String::new(), "мм".into(), "мм".into()],
        label: None,
    });
    s.blocks.push(Block::Figure {
        caption: "Рисунок".into(),
        svg: svg(figure_texts),
        width_mm: 100.0,
        label: None,
    });
    Note {
        sections: vec![s],
        ..Note::default()
    }
}

#[test]
fn the_figure_finders_find_what_they_must() {
    assert_eq!(canon(&format!("{MATH_OPEN}M_\"д\"{MATH_CLOSE}")), "Mд");
    assert_eq!(canon("Δ T_\"max\""), "ΔTmax");
    let n = number_at("−1317,175 м/с²").unwrap().0;
    assert!((n.value + 1317.175).abs() < 1e-12 && n.signed && (n.half_ulp - 0.0005).abs() < 1e-15);
    assert!(number_at("0,3m").is_none() && number_at("1,2·10⁵").is_none() && number_at("Н").is_none());
    let s = shown(&[
        "P<tspan>b</tspan> = 4078,808 Н;  кинетостатика: M<tspan>b</tspan> = 489,457 Н·м"
            .replace("<tspan>", "")
            .replace("</tspan>", ""),
        "R03 1291,8 Н".into(),
        "z1 = 15, z2 = 20, m = 5,000 мм".into(),
        "εα = 1".into(),
        "εα = 1,2".into(),
    ]);
    let syms: Vec<&str> = s.iter().map(|x| x.symbol.as_str()).collect();
    assert_eq!(syms, ["Pb", "Mb", "R03", "z1", "z2", "m"], "{s:#?}");
    // levels: one plain value among others that are not (the blocking
    // contour's s_a1 = 0 beside s_a1 = 0,3m)
    assert!(shown(&["sa1 = 0".into(), "sa1 = 0,3m".into()]).is_empty());
    // the values of the tables, a figure that shows them: every pair agrees
    let good = one_section(&[
        "Mд = 81,447 Н·м",
        "R01 5618,2 Н",
        "db1 = 70,477, db2 = 93,969 мм",
        "εα = 1,2048",
        "εα = 1",
        "εα = 1,2",
        "ωmax = 95,19 рад/с",
    ]);
    let mut faults = Vec::new();
    let c = check("good", &good, &mut faults);
    assert!(faults.is_empty(), "{faults:#?}");
    assert_eq!((c.figures, c.pairs), (1, 4));
    // a figure value altered: each one fails
    for bad in ["Mд = 82,447 Н·м", "R01 3863,6 Н", "R10 5628,2 Н", "db2 = 93,989 мм", "εα = 1,2148"] {
        let mut faults = Vec::new();
        let c = check("bad", &one_section(&[bad]), &mut faults);
        assert_eq!((c.pairs, faults.len()), (1, 1), "{bad}: {faults:#?}");
    }
    // a signed figure value against its table's sign
    let mut faults = Vec::new();
    check("sign", &one_section(&["Mд = −81,45 Н·м"]), &mut faults);
    assert_eq!(faults.len(), 1);
}

/// The figures of the default project that must have a value paired with
/// their tables, by a word of their caption in ru.
const DEFAULT_PAIRED: [&str; 8] = [
    "группу Ассура",
    "начальное звено",
    "Рычаг Жуковского",
    "Приведённые моменты",
    "Угловая скорость кривошипа",
    "Картина зацепления",
    "планетарной передачи",
    "Профиль кулачка",
];

#[test]
fn the_numbers_of_each_figure_equal_its_tables() {
    let tasks: Vec<(&str, String)> = vec![
        ("default.toml", DEFAULT_TASK.to_string()),
        ("seed-003-sixbar.toml", examples::text("seed-003-sixbar.toml")),
        ("synth-seed-003-six-bar.toml", examples::text("synth-seed-003-six-bar.toml")),
        ("gear-seed001.toml", examples::text("gear-seed001.toml")),
        ("planetary-ext-int.toml", examples::text("planetary-ext-int.toml")),
        ("cam-oscillating-roller.toml", examples::text("cam-oscillating-roller.toml")),
        ("textbook/p2-engine.toml", examples::text("textbook/p2-engine.toml")),
        (
            "textbook/p5-pneumatic-cylinder.toml",
            examples::text("textbook/p5-pneumatic-cylinder.toml"),
        ),
    ];
    let langs = [Language::Ru, Language::Uk, Language::En];
    let jobs: Vec<(&str, &String, Language)> = tasks.iter().flat_map(|(n, t)| langs.iter().map(move |l| (*n, t, *l))).collect();
    let results: Vec<(String, Counts, Vec<String>)> = std::thread::scope(|s| {
        let handles: Vec<_> = jobs
            .chunks(jobs.len().div_ceil(2))
            .map(|chunk| {
                s.spawn(move || {
                    chunk
                        .iter()
                        .map(|(name, text, lang)| {
                            let task = TaskSource::new(*name, text.as_str());
                            let run = run_task_in(&task, Some(*lang)).unwrap();
                            let note = compose(&run, &task).unwrap();
                            let label = format!("{name} {lang:?}");
                            let mut faults = Vec::new();
                            let counts = check(&label, &note, &mut faults);
                            (label, counts, faults)
                        })
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        handles.into_iter().flat_map(|h| h.join().unwrap()).collect()
    });
    let mut faults = Vec::new();
    let (mut figures, mut pairs) = (0, 0);
    for (label, c, f) in &results {
        println!("{label}: {} figures checked, {} pairs compared", c.figures, c.pairs);
        for (caption, symbols) in &c.unpaired {
            println!("  not paired: \"{caption}\" shows {symbols:?}");
        }
        figures += c.figures;
        pairs += c.pairs;
        faults.extend(f.iter().cloned());
    }
    println!(
        "figures against tables: {} notes, {figures} figures checked, {pairs} pairs compared",
        results.len()
    );
    let (_, default_ru, _) = results.iter().find(|r| r.0 == "default.toml Ru").unwrap();
    for word in DEFAULT_PAIRED {
        assert!(
            default_ru.paired.iter().any(|c| c.contains(word)),
            "no value of the figure \"{word}…\" paired with a table: {:#?}",
            default_ru.paired
        );
    }
    assert!(faults.is_empty(), "{} faults:\n{}", faults.len(), faults.join("\n"));
}
