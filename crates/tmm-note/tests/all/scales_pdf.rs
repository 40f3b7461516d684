//! The scales as printed, measured on the PDFs (`pdf_read`): for every
//! figure of the note and every drawing on the sheets, the scale or μ its
//! caption prints is read from the PDF's own text, one known length of the
//! mechanism is taken from the run's results (a crank, a centre distance, a
//! base circle, a velocity, one cycle of φ), and the element drawn for it
//! is measured on the paper from the PDF's vector paths (through every
//! matrix of the content stream): its length must be the true length over
//! the printed scale within 0.5 %. The worst error of each drawing is
//! printed.

use tmm_note::{Block, Note};
use tmm_report::run::run_task;

use super::fixtures::{sheet_svgs, task};
use super::pdf_read::{MM_PER_PT, Read, read};

/// The caption and the SVG of every figure of the note, in order.
fn note_svgs(note: &Note) -> Vec<(&str, &str)> {
    super::fixtures::note_figures(note)
        .into_iter()
        .filter_map(|b| match b {
            Block::Figure { caption, svg, .. } => Some((caption.as_str(), svg.as_str())),
            _ => None,
        })
        .collect()
}

/// One drawing as printed: its clip in the PDF and what is drawn in it.
struct Printed {
    /// Where it is (the note's figure number or the sheet's drawing file).
    name: String,
    /// Its text, the runs joined in the order shown.
    text: String,
    /// Every straight stroked piece, mm on the paper.
    segments: Vec<((f64, f64), (f64, f64))>,
    /// Every closed stroked curve: its box (x0, y0, x1, y1), mm.
    loops: Vec<(f64, f64, f64, f64)>,
    /// Every stroked polyline of more than 20 points: its box, mm.
    curves: Vec<(f64, f64, f64, f64)>,
}

fn printed(r: &Read, clip: usize, name: String) -> Printed {
    // no-break and thin spaces read as spaces
    let text: String = r
        .runs
        .iter()
        .filter(|t| r.within(t.clip, clip))
        .flat_map(|t| t.text.chars())
        .map(|c| if c.is_whitespace() { ' ' } else { c })
        .collect();
    let mm = |p: (f64, f64)| (p.0 * MM_PER_PT, p.1 * MM_PER_PT);
    let mut segments = Vec::new();
    let mut loops = Vec::new();
    let mut curves = Vec::new();
    for p in r.paths.iter().filter(|p| p.stroked && r.within(p.clip, clip)) {
        for s in &p.subpaths {
            let pts: Vec<(f64, f64)> = s.pts.iter().map(|&q| mm(q)).collect();
            for (i, w) in pts.windows(2).enumerate() {
                if s.straight.get(i).copied().unwrap_or(false) {
                    segments.push((w[0], w[1]));
                }
            }
            let bx = pts.iter().fold((f64::MAX, f64::MAX, f64::MIN, f64::MIN), |b, q| {
                (b.0.min(q.0), b.1.min(q.1), b.2.max(q.0), b.3.max(q.1))
            });
            if s.closed && s.straight.iter().all(|x| !x) && !pts.is_empty() {
                loops.push(bx);
            }
            if pts.len() > 20 {
                curves.push(bx);
            }
        }
    }
    Printed {
        name,
        text,
        segments,
        loops,
        curves,
    }
}

/// Every drawing of `name`'s note and sheets, as printed, and the run's
/// `report.json`.
fn drawings(name: &str) -> (Vec<Printed>, serde_json::Value) {
    let task = task(name);
    let run = run_task(&task).expect("the task runs");
    let report: serde_json::Value =
        serde_json::from_str(run.docs.get("report.json").and_then(|d| d.as_text()).expect("report.json")).expect("report.json parses");
    let note = tmm_note::compose(&run, &task).expect("the note composes");
    let pdf = tmm_note::typeset(&note).expect("the note typesets");
    let r = read(&pdf);
    let svgs = note_svgs(&note);
    assert_eq!(r.forms.len(), svgs.len(), "{name}: one drawing per figure");
    let mut out = Vec::new();
    for (i, (f, (caption, _))) in r.forms.iter().zip(&svgs).enumerate() {
        // a note's figure leaves its name to the caption under it: the
        // caption tells what the drawing is, the drawing its scale
        let mut p = printed(&r, f.clip, format!("{name}: note figure {} (page {})", i + 1, f.page));
        p.text = format!("{caption} {}", p.text);
        out.push(p);
    }
    for (path, svg) in sheet_svgs(&run) {
        let pdf = tmm_note::sheet_pdf(svg).expect("the sheet typesets");
        let r = read(&pdf);
        let page_h = r.clips.first().map(|c| c.rect_pt.3).expect("a sheet has its clip");
        for (source, (x, y, w, h)) in sheet_boxes(svg) {
            let to_pt = |v: f64| v / MM_PER_PT;
            let want = (to_pt(x), page_h - to_pt(y + h), to_pt(x + w), page_h - to_pt(y));
            let clip = r
                .clips
                .iter()
                .position(|c| {
                    (c.rect_pt.0 - want.0).abs() < 0.5
                        && (c.rect_pt.1 - want.1).abs() < 0.5
                        && (c.rect_pt.2 - want.2).abs() < 0.5
                        && (c.rect_pt.3 - want.3).abs() < 0.5
                })
                .unwrap_or_else(|| panic!("{name}: {path}: the clip of {source}"));
            out.push(printed(&r, clip, format!("{name}: {path} {source}")));
        }
    }
    (out, report)
}

/// The drawings placed on a sheet: their files and boxes (x, y, w, h from
/// the sheet's top-left corner, mm), as the sheet's SVG places them.
fn sheet_boxes(svg: &str) -> Vec<(String, (f64, f64, f64, f64))> {
    let attr = |tag: &str, k: &str| -> Option<String> {
        let at = tag.find(&format!(" {k}=\""))? + k.len() + 3;
        Some(tag[at..at + tag[at..].find('"')?].to_string())
    };
    let mut out = Vec::new();
    for part in svg.split("<svg ").skip(1) {
        let tag = &part[..part.find('>').unwrap_or(part.len())];
        if !tag.contains("class=\"drawing\"") {
            continue;
        }
        let n = |k: &str| attr(tag, k).and_then(|v| v.parse::<f64>().ok()).unwrap_or(f64::NAN);
        out.push((
            attr(tag, "data-source").unwrap_or_default(),
            (n("x"), n("y"), n("width"), n("height")),
        ));
    }
    out
}

/// A decimal number as the drawings print it ("0,0025", "2,5", "−1"),
/// from the start of `s`, and the rest of `s`.
fn number(s: &str) -> Option<(f64, &str)> {
    let s = s.trim_start();
    let end = s
        .char_indices()
        .find(|&(i, c)| !(c.is_ascii_digit() || c == ',' || (i == 0 && (c == '-' || c == '−'))))
        .map_or(s.len(), |(i, _)| i);
    let t = s[..end].trim_end_matches(',').replace(',', ".").replace('−', "-");
    Some((t.parse().ok()?, &s[t.len().min(end)..]))
}

/// The length scale a caption prints ("М 1:2,5", "Масштаб 2:1"): paper
/// length over true length.
fn printed_scale(text: &str) -> Option<f64> {
    for key in ["Масштаб ", "М "] {
        let mut rest = text;
        while let Some(i) = rest.find(key) {
            rest = &rest[i + key.len()..];
            if let Some((a, r)) = number(rest)
                && let Some(r) = r.strip_prefix(':')
                && let Some((b, _)) = number(r)
                && a > 0.0
                && b > 0.0
            {
                return Some(a / b);
            }
        }
    }
    None
}

/// The value of "μ{sub} = X" a caption prints; with `after`, the one
/// whose words up to the next μ contain it ("μF = 100 Н/мм (в плане сил)").
fn printed_mu(text: &str, sub: &str, after: Option<&str>) -> Option<f64> {
    let key = format!("μ{sub}");
    let mut rest = text;
    while let Some(i) = rest.find(&key) {
        rest = &rest[i + key.len()..];
        let Some(r) = rest.trim_start().strip_prefix('=') else { continue };
        let Some((v, tail)) = number(r) else { continue };
        let upto = &tail[..tail.find('μ').unwrap_or(tail.len())];
        if after.is_none_or(|a| upto.contains(a)) {
            return Some(v);
        }
    }
    None
}

fn len(s: &((f64, f64), (f64, f64))) -> f64 {
    (s.1.0 - s.0.0).hypot(s.1.1 - s.0.1)
}

/// The straight stroked piece nearest in length to `want` mm, its length.
fn nearest_segment(p: &Printed, want: f64) -> Option<f64> {
    p.segments
        .iter()
        .map(len)
        .min_by(|a, b| (a - want).abs().total_cmp(&(b - want).abs()))
}

/// The closed curve (a circle) nearest in diameter to `want` mm, its
/// diameter (the mean of its box's sides).
fn nearest_loop(p: &Printed, want: f64) -> Option<f64> {
    p.loops
        .iter()
        .map(|b| 0.5 * ((b.2 - b.0) + (b.3 - b.1)))
        .min_by(|a, b| (a - want).abs().total_cmp(&(b - want).abs()))
}

/// The widest plotted curve: its width and height, mm.
fn widest_curve(p: &Printed) -> Option<(f64, f64)> {
    p.curves.iter().map(|b| (b.2 - b.0, b.3 - b.1)).max_by(|a, b| a.0.total_cmp(&b.0))
}

fn f(v: &serde_json::Value, path: &[&str]) -> Option<f64> {
    let mut v = v;
    for k in path {
        v = v.get(*k)?;
    }
    v.as_f64()
}

/// The span of a sampled angle, degrees.
fn span_deg(v: &serde_json::Value, path: &[&str]) -> Option<f64> {
    let mut v = v;
    for k in path {
        v = v.get(*k)?;
    }
    let a = v.as_array()?;
    Some((a.last()?.as_f64()? - a.first()?.as_f64()?).to_degrees())
}

/// The crank's length and the input's ω, ε (from the task's geometry).
fn crank(report: &serde_json::Value) -> Option<(f64, f64, f64)> {
    let link = match &report["linkage"]["input"]["link"] {
        serde_json::Value::String(s) => s.clone(),
        v => v.as_u64()?.to_string(),
    };
    let lengths = report["linkage"]["geometry"]["links"][&link]["lengths"].as_object()?;
    let l = lengths.values().filter_map(|v| v.as_f64()).fold(0.0, f64::max);
    // a clockwise crank turns at a negative ω: its vectors are as long
    Some((
        l,
        f(report, &["linkage", "input", "omega"])?.abs(),
        f(report, &["linkage", "input", "epsilon"]).unwrap_or(0.0),
    ))
}

/// What one drawing is checked by: the element measured, the length it
/// must have on paper (the true length over the printed scale, mm) and
/// the length measured, mm. `None` when the drawing prints no scale (a
/// structural scheme, a graph with graduated axes) or is not of a kind
/// with a known length.
fn probe(p: &Printed, report: &serde_json::Value) -> Option<(&'static str, f64, Option<f64>)> {
    let t = p.text.as_str();
    let scale = printed_scale(t);
    // the assignment's scheme: the mechanism the task is about
    let scheme = t.starts_with("Схема механизма");
    if let Some(l) = f(report, &["cylinder", "geometry", "l_AB"])
        && (scheme || t.starts_with("Механизм "))
    {
        // a lever driven by an oscillating cylinder: the lever A–B
        let want = l * 1000.0 * scale?;
        return Some(("the lever A–B between its pair centres", want, nearest_segment(p, want)));
    }
    if t.contains("Кинематическая схема") || scheme && report.get("linkage").is_some() {
        let (l, _, _) = crank(report)?;
        let want = l * 1000.0 * scale?;
        return Some(("the crank between its pair centres", want, nearest_segment(p, want)));
    }
    if t.contains("Синтез механизма") || t.starts_with("Построение схемы механизма") {
        let want = f(report, &["synthesis", "lengths", "AB"])? * 1000.0 * scale?;
        return Some(("the connecting rod A–B in an extreme position", want, nearest_segment(p, want)));
    }
    if t.contains("Станочное зацепление") {
        // the tool's tooth is (h*a + h*a + c*)·m high, its flank straight
        // at the profile angle α (GOST 13755's rack, the tool's fillet
        // drawn on the generated tooth)
        let rack = &report["gear"]["rack"];
        let m = f(report, &["gear", "m"])?;
        let h = (2.0 * f(rack, &["ha"])? + f(rack, &["c"])?) * m;
        let want = h / f(rack, &["alpha"])?.cos() * 1000.0 * scale?;
        return Some(("the tool's straight flank (2h*a + c*)·m / cos α", want, nearest_segment(p, want)));
    }
    if t.contains("Картина зацепления") {
        // N1N2 = (rb2 ± rb1)·tg αw, the line of action between the
        // points of tangency with the base circles (+ external, − internal)
        let sign = if report["gear"]["kind"].as_str() == Some("internal") {
            -1.0
        } else {
            1.0
        };
        let rb = 0.5 * (f(report, &["gear", "db2"])? + sign * f(report, &["gear", "db1"])?).abs();
        let want = rb * f(report, &["gear", "alpha_w"])?.tan() * 1000.0 * scale?;
        return Some(("the line of action N1–N2 = (rb2 ± rb1)·tg αw", want, nearest_segment(p, want)));
    }
    if t.contains("Планетарный механизм") || t.starts_with("Схема планетарной передачи") || scheme && report.get("planetary").is_some()
    {
        let want = 2.0 * f(report, &["planetary", "best", "centre_distance"])? * 1000.0 * scale?;
        return Some(("the carrier between the two planets' axes, 2·aw", want, nearest_segment(p, want)));
    }
    if t.contains("основной шайбы") || scheme && report.get("cam").is_some() {
        let want = 2.0 * f(report, &["cam", "r0"])? * 1000.0 * scale?;
        return Some(("the base circle's diameter 2·r0", want, nearest_loop(p, want)));
    }
    if t.contains("область центра кулачка") || t.starts_with("Определение минимального радиуса кулачка")
    {
        let want = f(report, &["cam", "r0"])? / printed_mu(t, "s", None)?;
        return Some(("O–B₀ = r0 at μs", want, nearest_segment(p, want)));
    }
    let group = t.starts_with("Группа ") && t.contains("план сил");
    if group || t.starts_with("Силы, действующие на группу Ассура") {
        // the reactions at the group's outer pairs close its force plan;
        // the note draws the first group (`forces/group-1.svg`)
        let pairs: Vec<String> = if group {
            let pairs = &t[t.find("(пары:")? + "(пары:".len()..];
            pairs[..pairs.find(')')?].split(',').map(|p| p.trim().to_string()).collect()
        } else {
            report["linkage"]["structure"]["groups"][0]["pairs"]
                .as_array()?
                .iter()
                .filter_map(|p| p.as_str().map(str::to_string))
                .collect()
        };
        let r = report["forces"]["detail"]["reactions"]
            .as_array()?
            .iter()
            .find(|r| r["pair"].as_str().is_some_and(|p| pairs.iter().any(|q| q == p)))?;
        let want = r["magnitude"].as_f64()? / printed_mu(t, "F", Some("в плане сил"))?;
        return Some((
            "a reaction at one of the group's pairs at μF (the force plan)",
            want,
            nearest_segment(p, want),
        ));
    }
    if t.starts_with("Начальное звено") || t.starts_with("Силы, действующие на начальное звено")
    {
        let want = f(report, &["forces", "detail", "balancing_force"])?.abs() / printed_mu(t, "F", Some("в плане сил"))?;
        return Some(("the balancing force Pb at μF (the force plan)", want, nearest_segment(p, want)));
    }
    if t.starts_with("План скоростей") || t.starts_with("Рычаг Жуковского") {
        let (l, w, _) = crank(report)?;
        let want = w * l / printed_mu(t, "v", None)?;
        return Some(("the crank pin's velocity ω1·l1 at μv", want, nearest_segment(p, want)));
    }
    if t.starts_with("План ускорений") {
        let (l, w, e) = crank(report)?;
        let want = l * (w.powi(4) + e * e).sqrt() / printed_mu(t, "a", None)?;
        return Some(("the crank pin's acceleration l1·√(ω1⁴ + ε1²) at μa", want, nearest_segment(p, want)));
    }
    if t.contains("Виттенбауэра") {
        let a = report["dynamics"]["kinetic_energy_change"].as_array()?;
        let (lo, hi) = a
            .iter()
            .filter_map(|v| v.as_f64())
            .fold((f64::MAX, f64::MIN), |b, v| (b.0.min(v), b.1.max(v)));
        let want = (hi - lo) / printed_mu(t, "ΔT", None)?;
        return Some(("the curve's height ΔT_max − ΔT_min at μΔT", want, widest_curve(p).map(|c| c.1)));
    }
    if let Some(travel) = f(report, &["cylinder", "geometry", "travel"])
        && let Some(mu_s) = printed_mu(t, "s", None)
        && !t.starts_with("Время")
    {
        // a graph over the piston's travel s: the whole travel along s
        // (t(s) stops a sample short of an end reached only
        // asymptotically; its axis is the others' μs)
        let want = travel / mu_s;
        return Some((
            "the curve's length along s: the piston's travel at μs",
            want,
            widest_curve(p).map(|c| c.0),
        ));
    }
    let mu_phi = printed_mu(t, "φ", None)?;
    let cycle = if t.contains("толкателя") || t.contains("Угол давления за цикл") {
        // one turn of the cam (its samples stop a step short of it)
        360.0
    } else if t.contains("выходного звена") || t.contains("Уравновешивающий момент") {
        span_deg(report, &["linkage", "diagrams", "phi"])?
    } else {
        span_deg(report, &["dynamics", "phi"])?
    };
    let want = cycle / mu_phi;
    Some(("the curve's length along φ: one cycle at μφ", want, widest_curve(p).map(|c| c.0)))
}

/// Every drawing of every task of `names` measured; the worst error of
/// each printed; those off by 0.5 % or more, or with nothing of the
/// length to measure, returned.
fn check(names: &[&str]) {
    let mut bad = Vec::new();
    let mut measured = 0;
    for name in names {
        let (drawings, report) = drawings(name);
        for p in &drawings {
            let title: String = p.text.chars().take(60).collect();
            match probe(p, &report) {
                Some((what, want, Some(got))) => {
                    let err = (got - want) / want;
                    eprintln!(
                        "{}: {what}: {got:.3} mm on paper, {want:.3} mm by the scale: {:+.3} % — \"{title}\"",
                        p.name,
                        err * 100.0
                    );
                    if err.abs() >= 5e-3 {
                        bad.push(format!(
                            "{}: {what}: {got:.3} mm on paper, {want:.3} mm by the scale ({:+.2} %)",
                            p.name,
                            err * 100.0
                        ));
                    }
                    measured += 1;
                }
                Some((what, want, None)) => bad.push(format!("{}: {what}: nothing drawn to measure ({want:.3} mm expected)", p.name)),
                // a drawing that prints a length scale is measured
                None if printed_scale(&p.text).is_some() => {
                    bad.push(format!("{}: prints a scale but has no length to measure — \"{title}\"", p.name))
                }
                None => eprintln!(
                    "{}: no length scale printed (graduated axes or a scheme without scale) — \"{title}\"",
                    p.name
                ),
            }
        }
    }
    assert!(measured > 0, "something measured");
    assert!(bad.is_empty(), "scales not as printed:\n{}", bad.join("\n"));
}

#[test]
fn default_project_drawings_measure_as_their_scales() {
    check(&["default"]);
}

#[test]
fn seed_003_drawings_measure_as_their_scales() {
    check(&["seed-003-sixbar.toml"]);
}

#[test]
fn synthesis_and_linkage_examples_drawings_measure_as_their_scales() {
    check(&["synth-seed-003-six-bar.toml", "class3-triad.toml"]);
}

#[test]
fn forces_and_dynamics_examples_drawings_measure_as_their_scales() {
    check(&["seed-004-two-sliders.toml", "textbook/p4-press.toml"]);
}

#[test]
fn gear_and_planetary_examples_drawings_measure_as_their_scales() {
    check(&["gear-internal.toml", "planetary-ext-int.toml"]);
}

#[test]
fn cam_and_cylinder_examples_drawings_measure_as_their_scales() {
    check(&["cam-oscillating-roller.toml", "textbook/p5-pneumatic-cylinder.toml"]);
}
