//! The blocking contour drawn like the printed atlases: x1 across, x2 up, the
//! allowed region shaded, each boundary labelled, the chosen point marked.

use tmm_gears::contour::{Boundary, Contour};

use crate::svg::{Anchor, Canvas, Style};

fn color(b: &Boundary) -> (&'static str, Style) {
    match b {
        Boundary::Undercut(_) => ("#000000", Style::THICK.widened(0.6)),
        Boundary::Interference(_) => ("#7a3b00", Style::THICK.colored("#7a3b00").widened(0.6)),
        Boundary::TipThickness(_, k) if *k == 0.0 => ("#c00000", Style::THICK.colored("#c00000").widened(0.6)),
        Boundary::TipThickness(_, _) => ("#c00000", Style::DASHED.colored("#c00000").widened(0.35)),
        Boundary::ContactRatio(e) if *e == 1.0 => ("#1f5fbf", Style::THICK.colored("#1f5fbf").widened(0.6)),
        Boundary::ContactRatio(_) => ("#1f5fbf", Style::DASHED.colored("#1f5fbf").widened(0.4)),
        Boundary::EqualSliding => ("#008000", Style::AXIS.colored("#008000").widened(0.45)),
        Boundary::TipInterference => ("#6a1b9a", Style::THICK.colored("#6a1b9a").widened(0.6)),
    }
}

/// The contour as an A4 (landscape) SVG; `chosen` marks a point with its label.
pub fn contour_svg(c: &Contour, chosen: Option<((f64, f64), String)>) -> String {
    let (pw, ph) = (297.0, 210.0);
    let mut cv = Canvas::new(pw, ph);
    let world = (c.x1.0, c.x1.1, c.x2.0, c.x2.1);
    cv.fit(world, (22.0, 16.0, 190.0, 176.0));
    cv.text_paper(
        (120.0, 9.0),
        &format!(
            "Blocking contour z1 = {}, z2 = {} (α = {:.1}°, ha* = {}, c* = {})",
            c.base.z1,
            c.base.z2,
            c.base.rack.alpha.to_degrees(),
            c.base.rack.ha,
            c.base.rack.c
        ),
        4.0,
        Anchor::Middle,
        "#000",
    );
    // shaded allowed cells
    cv.begin_group("allowed");
    let n = c.n;
    for j in 0..n - 1 {
        for i in 0..n - 1 {
            if c.feasible[j * n + i] && c.feasible[j * n + i + 1] && c.feasible[(j + 1) * n + i] && c.feasible[(j + 1) * n + i + 1] {
                let (a, b) = (c.node(i, j), c.node(i + 1, j + 1));
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
    }
    cv.end_group();
    // frame, grid and ticks
    let grid = Style {
        width: 0.1,
        color: "#bbbbbb",
        dash: None,
        fill: None,
    };
    let tx = crate::svg::Ticks::new(c.x1.0, c.x1.1, 10);
    for i in tx.first..=tx.last {
        let x = tx.value(i);
        if x >= c.x1.0 - 1e-9 && x <= c.x1.1 + 1e-9 {
            cv.line((x, c.x2.0), (x, c.x2.1), grid);
            cv.text((x, c.x2.0), &tx.label(i), 2.6, Anchor::Middle);
        }
    }
    let ty = crate::svg::Ticks::new(c.x2.0, c.x2.1, 10);
    for i in ty.first..=ty.last {
        let y = ty.value(i);
        if y >= c.x2.0 - 1e-9 && y <= c.x2.1 + 1e-9 {
            cv.line((c.x1.0, y), (c.x1.1, y), grid);
            cv.text((c.x1.0, y), &format!("{} ", ty.label(i)), 2.6, Anchor::End);
        }
    }
    cv.polygon(
        &[(c.x1.0, c.x2.0), (c.x1.1, c.x2.0), (c.x1.1, c.x2.1), (c.x1.0, c.x2.1)],
        Style::THIN,
    );
    cv.text(
        (0.5 * (c.x1.0 + c.x1.1), c.x2.0 - 0.06 * (c.x2.1 - c.x2.0)),
        "x1",
        3.5,
        Anchor::Middle,
    );
    cv.text(
        (c.x1.0 - 0.07 * (c.x1.1 - c.x1.0), 0.5 * (c.x2.0 + c.x2.1)),
        "x2",
        3.5,
        Anchor::Middle,
    );
    // lines
    let mut legend_y = 24.0;
    for l in &c.lines {
        let (col, st) = color(&l.boundary);
        cv.begin_group(&l.boundary.key());
        for pl in &l.polylines {
            cv.polyline(pl, st);
        }
        if let Some(pl) = l.polylines.iter().max_by_key(|p| p.len()) {
            let mid = pl[pl.len() / 2];
            cv.text_colored(mid, &l.boundary.label(), 2.4, Anchor::Start, col);
        }
        cv.end_group();
        if !l.polylines.is_empty() {
            cv.line_paper((222.0, legend_y - 1.0), (230.0, legend_y - 1.0), st);
            cv.text_paper((232.0, legend_y), &l.boundary.label(), 2.8, Anchor::Start, col);
            legend_y += 5.0;
        }
    }
    cv.text_paper(
        (222.0, legend_y + 3.0),
        "shaded: every blocking condition holds",
        2.6,
        Anchor::Start,
        "#000",
    );
    if let Some(((x1, x2), label)) = chosen {
        cv.dot((x1, x2), 1.2, "#000");
        cv.text((x1, x2), &format!("  {label} ({x1:.3}, {x2:.3})"), 3.0, Anchor::Start);
    }
    cv.finish()
}
