//! The specific-sliding diagram ϑ1, ϑ2 over the active line of action, made
//! for the Diagram slot of the sheet, words in the project's language.

use tmm_gears::Pair;

use crate::paper::{Slot, slot_mm};
use crate::picture::Picture;
use crate::project::{Language, SheetFormat};
use crate::svg::{Series, plot_in};
use crate::words::word;

/// The specific-sliding diagram over the active line (ϑ clipped to [−4, 1]).
pub fn sliding_svg(pair: &Pair, lang: Language, sheet: SheetFormat) -> Picture {
    let tab = pair.sliding_table(101);
    let clip = |v: f64| if v.is_finite() { v.clamp(-4.0, 1.0) } else { f64::NAN };
    let a: Vec<(f64, f64)> = tab.iter().map(|q| (q.s * 1e3, clip(q.theta1))).collect();
    let b: Vec<(f64, f64)> = tab.iter().map(|q| (q.s * 1e3, clip(q.theta2))).collect();
    let (w, h) = slot_mm(Slot::Diagram, sheet);
    let svg = plot_in(
        lang,
        word(lang, "gear.sliding_title"),
        word(lang, "gear.sliding_x"),
        "ϑ",
        &[
            Series {
                name: word(lang, "gear.sliding_1"),
                points: &a,
                color: "#c00000",
            },
            Series {
                name: word(lang, "gear.sliding_2"),
                points: &b,
                color: "#1f5fbf",
            },
        ],
        w,
        h,
    );
    // the plot writes its tick labels with the decimal comma of ru and uk
    svg
}

/// Turn the decimal points of the numbers inside `<text>` elements into
/// commas (GOST 2.105 for ru/uk).
pub fn decimal_comma(svg: &str) -> String {
    let mut out = String::with_capacity(svg.len());
    for line in svg.split_inclusive('\n') {
        if let (true, Some(i), Some(j)) = (line.starts_with("<text"), line.find('>'), line.rfind("</text>")) {
            let inner = &line[i + 1..j];
            let b = inner.as_bytes();
            let fixed: String = inner
                .char_indices()
                .map(|(k, ch)| {
                    let digit = |m: Option<&u8>| m.is_some_and(|c| c.is_ascii_digit());
                    if ch == '.' && k > 0 && digit(b.get(k - 1)) && digit(b.get(k + 1)) {
                        ','
                    } else {
                        ch
                    }
                })
                .collect();
            out.push_str(&line[..=i]);
            out.push_str(&fixed);
            out.push_str(&line[j..]);
        } else {
            out.push_str(line);
        }
    }
    out
}
