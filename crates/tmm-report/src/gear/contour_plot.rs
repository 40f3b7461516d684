//! The blocking contour (блокирующий контур) drawn like the printed atlases:
//! x1 across, x2 up, the allowed region shaded, every line in its own colour
//! and dash with a legend of the same styles, the chosen point marked; made
//! for the Small slot of the sheet, words in the project's language.

use tmm_gears::contour::{Boundary, Contour};

use crate::labels::{CHAR_WIDTH, Placer, finish, num, plain};
use crate::paper::{Slot, slot_mm};
use crate::picture::Picture;
use crate::project::{Language, SheetFormat};
use crate::svg::{Canvas, Style};
use crate::words::word;

/// Colours of the lines, in order of the contour's lines.
const COLORS: [&str; 6] = ["#000000", "#c00000", "#1f5fbf", "#008000", "#7a3b00", "#6a1b9a"];
/// Dash patterns on paper, mm (None: solid), cycled slower than the colours
/// so that no two of the first 36 lines share a style.
const DASHES: [Option<(f64, f64)>; 6] = [
    None,
    Some((4.0, 1.5)),
    Some((1.2, 1.2)),
    Some((8.0, 2.0)),
    Some((2.5, 2.5)),
    Some((0.6, 2.0)),
];

/// The style of the `k`-th line: a colour and a dash of its own.
///
/// ```
/// use tmm_report::gear::contour_plot::line_style;
/// let s: Vec<_> = (0..36).map(line_style).collect();
/// for i in 0..36 { for j in 0..i { assert!((s[i].color, s[i].dash) != (s[j].color, s[j].dash)); } }
/// ```
pub fn line_style(k: usize) -> Style {
    let color = COLORS[k % COLORS.len()];
    let dash = DASHES[(k + k / COLORS.len()) % DASHES.len()];
    Style {
        width: if dash.is_none() { 0.6 } else { 0.45 },
        color,
        dash,
        fill: None,
    }
}

/// The line's name in `lang`, indices marked for typesetting.
fn line_name(b: &Boundary, lang: Language) -> String {
    let n = |v: f64| num(lang, v, 2).trim_end_matches('0').trim_end_matches([',', '.']).to_string();
    match *b {
        Boundary::Undercut(i) => format!("{} {i}", word(lang, "gear.undercut")),
        Boundary::Interference(i) => format!("{} {i}", word(lang, "gear.interference")),
        Boundary::TipThickness(i, 0.0) => format!("s_a{i} = 0"),
        Boundary::TipThickness(i, k) => format!("s_a{i} = {}m", n(k)),
        Boundary::ContactRatio(e) => format!("ε_α = {}", n(e)),
        Boundary::EqualSliding => "ϑ_1max = ϑ_2max".into(),
        Boundary::TipInterference => word(lang, "gear.tip_interference").to_string(),
    }
}

/// The width a label's box takes for `text` at size `h` (mm), as the
/// placer counts it.
fn plain_width(text: &str, h: f64) -> f64 {
    CHAR_WIDTH * crate::picture::em(h) * plain(text).chars().count() as f64
}

/// The paper of the contour drawing for `sheet` with the contour's
/// (x1, x2) box fitted into its plot area: the map from (x1, x2) to the
/// drawing's coordinates (mm, y down) is `canvas.to_paper(x1, x2)`. The
/// drawing of [`contour_svg`] is made on this canvas, so a click on the
/// drawing maps back through the same numbers.
///
/// ```
/// use tmm_gears::{PairSpec, contour::{blocking_contour, ContourOptions}};
/// use tmm_report::{gear::contour_plot::plot_canvas, project::SheetFormat};
/// let c = blocking_contour(&PairSpec::external(15, 20, 0.005, 0.0, 0.0), &ContourOptions::default()).unwrap();
/// let cv = plot_canvas(&c, SheetFormat::A1);
/// let (a, b) = (cv.to_paper(c.x1.0, c.x2.0), cv.to_paper(c.x1.1, c.x2.1));
/// assert!(a.0 < b.0 && a.1 > b.1); // x1 to the right, x2 up
/// ```
pub fn plot_canvas(c: &Contour, sheet: SheetFormat) -> Canvas {
    let (pw, ph) = slot_mm(Slot::Small, sheet);
    // the letter sizes as printed (raised to the lettering floor), so the
    // margins and the rows are laid out for them
    let h = crate::picture::em(if pw >= 190.0 { 3.5 } else { 2.5 });
    let hs = crate::picture::em(2.5);
    let mut cv = Canvas::new(pw, ph);
    // the legend's column: wider on the small paper of A2, where its
    // names wrap at the printed letter size
    let legend_w = if pw >= 190.0 { 0.34 } else { 0.42 } * pw;
    // the left margin holds the x2 ticks and the axis' name beside them
    let (left, bottom) = (12.0 + 3.0 * hs, 6.0 + 2.5 * h);
    let (aw, ah) = (pw - legend_w - left - 4.0, ph - bottom - 4.0 - 2.0 * h);
    let world = (c.x1.0, c.x1.1, c.x2.0, c.x2.1);
    cv.fit(world, (left, bottom, aw, ah));
    cv
}

/// The contour as SVG for the Small slot of `sheet`; `chosen` marks a point
/// with its label (the label is written in English drawings only; the
/// shifts are written in every language).
pub fn contour_svg(c: &Contour, chosen: Option<((f64, f64), String)>, lang: Language, sheet: SheetFormat) -> Picture {
    let (pw, ph) = slot_mm(Slot::Small, sheet);
    // the letter sizes as printed (raised to the lettering floor), so the
    // margins and the rows are laid out for them
    let h = crate::picture::em(if pw >= 190.0 { 3.5 } else { 2.5 });
    let hs = crate::picture::em(2.5);
    let mut cv = plot_canvas(c, sheet);
    let mut lab = Placer::new(pw, ph);
    // the legend's column: wider on the small paper of A2, where its
    // names wrap at the printed letter size
    let legend_w = if pw >= 190.0 { 0.34 } else { 0.42 } * pw;
    // the name at the left of the top row; the pair's tooth numbers over
    // the legend's column (the note keeps these only)
    lab.put_title(
        (2.0 + 0.5 * plain_width(word(lang, "gear.contour_title"), h), 1.0 + 0.6 * h),
        word(lang, "gear.contour_title"),
        h,
    );
    lab.put_left(
        (pw - legend_w + 2.0, 1.0 + 0.6 * h),
        &format!("z_1 = {}, z_2 = {}", c.base.z1, c.base.z2),
        h,
        "#000",
    );
    // shaded allowed cells: each row's run of whole cells as one rectangle
    // (the same area as cell by cell, a fraction of the elements to draw)
    cv.begin_group("allowed");
    let n = c.n;
    let whole = |i: usize, j: usize| {
        c.feasible[j * n + i] && c.feasible[j * n + i + 1] && c.feasible[(j + 1) * n + i] && c.feasible[(j + 1) * n + i + 1]
    };
    for j in 0..n - 1 {
        let mut i = 0;
        while i < n - 1 {
            if !whole(i, j) {
                i += 1;
                continue;
            }
            let start = i;
            while i < n - 1 && whole(i, j) {
                i += 1;
            }
            let (a, b) = (c.node(start, j), c.node(i, j + 1));
            cv.polygon(
                &[(a.0, a.1), (b.0, a.1), (b.0, b.1), (a.0, b.1)],
                Style {
                    width: 0.0,
                    color: "none",
                    dash: None,
                    fill: Some("#e8f2e0"),
                },
            );
        }
    }
    cv.end_group();
    let grid = Style {
        width: 0.1,
        color: "#bbbbbb",
        dash: None,
        fill: None,
    };
    let tx = crate::svg::Ticks::new(c.x1.0, c.x1.1, 8);
    // every tick's number when they are wider apart than the widest one
    // at the printed size, else every second (or third …) one
    let step_mm = (cv.to_paper(tx.value(tx.first + 1), c.x2.0).0 - cv.to_paper(tx.value(tx.first), c.x2.0).0).abs();
    let widest = (tx.first..=tx.last)
        .map(|i| CHAR_WIDTH * hs * tx.label(i).chars().count() as f64)
        .fold(0.0, f64::max);
    let stride = ((widest + 1.0) / step_mm.max(1e-9)).ceil().max(1.0) as i64;
    for i in tx.first..=tx.last {
        let x = tx.value(i);
        if x >= c.x1.0 - 1e-9 && x <= c.x1.1 + 1e-9 {
            cv.line((x, c.x2.0), (x, c.x2.1), grid);
            if (i - tx.first) % stride == 0 {
                let p = cv.to_paper(x, c.x2.0);
                lab.put((p.0, p.1 + 0.9 * hs + 0.5), &tx.printed(i, lang), hs, "#000");
            }
        }
    }
    let ty = crate::svg::Ticks::new(c.x2.0, c.x2.1, 8);
    let mut widest: f64 = 0.0;
    for i in ty.first..=ty.last {
        let y = ty.value(i);
        if y >= c.x2.0 - 1e-9 && y <= c.x2.1 + 1e-9 {
            cv.line((c.x1.0, y), (c.x1.1, y), grid);
            let p = cv.to_paper(c.x1.0, y);
            let t = ty.printed(i, lang);
            let w = CHAR_WIDTH * hs * t.chars().count() as f64;
            widest = widest.max(w);
            lab.put((p.0 - 1.0 - 0.5 * w, p.1), &t, hs, "#000");
        }
    }
    cv.polygon(
        &[(c.x1.0, c.x2.0), (c.x1.1, c.x2.0), (c.x1.1, c.x2.1), (c.x1.0, c.x2.1)],
        Style::THIN,
    );
    let p = cv.to_paper(c.x1.1, c.x2.0);
    lab.put((p.0 - 4.0, p.1 + 2.0 * hs + 1.0), "x_1", h, "#000");
    // x2 left of its ticks, half-way up the axis
    let (p, q) = (cv.to_paper(c.x1.0, c.x2.1), cv.to_paper(c.x1.0, c.x2.0));
    let wx = CHAR_WIDTH * h * 2.0;
    lab.put(
        ((p.0 - 2.0 - widest - 0.5 * wx).max(0.6 + 0.5 * wx), 0.5 * (p.1 + q.1)),
        "x_2",
        h,
        "#000",
    );
    // the lines, each with its own style, and the legend in the same styles
    let lx = pw - legend_w + 2.0;
    let mut ly = 4.0 + 2.5 * h;
    let mut k = 0;
    for l in &c.lines {
        if l.polylines.is_empty() {
            continue;
        }
        let st = line_style(k);
        k += 1;
        cv.begin_group(&l.boundary.key());
        for pl in &l.polylines {
            cv.polyline(pl, st);
        }
        cv.end_group();
        let name = line_name(&l.boundary, lang);
        cv.line_paper((lx, ly), (lx + 9.0, ly), st.widened(0.6));
        // each name broken into lines that stay on the paper
        let size = hs.max(h - 1.0);
        // (the labels' boxes are CHAR_WIDTH = 0.62 of the size a letter, the
        // wrapping's 0.6: the room taken 4 % narrower)
        let lines = crate::labels::wrap_text(&name, size, 0.96 * (pw - lx - 11.0 - 0.6));
        for (i, t) in lines.iter().enumerate() {
            lab.put_left((lx + 11.0, ly + 1.25 * size * i as f64), t, size, st.color);
        }
        ly += 1.25 * size * (lines.len() as f64 - 1.0) + 1.3 * size + 0.4;
    }
    for (i, t) in crate::labels::wrap_text(word(lang, "gear.contour_allowed"), hs, 0.96 * (pw - lx - 0.6))
        .iter()
        .enumerate()
    {
        lab.put_left((lx, ly + 1.0 + 1.25 * hs * i as f64), t, hs, "#000");
    }
    if let Some(((x1, x2), label)) = chosen {
        cv.dot((x1, x2), 1.0, "#000");
        let t = if lang == Language::En {
            format!("{label} ({}; {})", num(lang, x1, 3), num(lang, x2, 3))
        } else {
            format!("({}; {})", num(lang, x1, 3), num(lang, x2, 3))
        };
        let q = cv.to_paper(x1, x2);
        lab.place(&Placer::around(q, &t, hs, 1.0), &t, hs, "#000");
        let _ = plain(&t);
    }
    finish(cv.finish(), &lab, None)
}
