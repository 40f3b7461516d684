//! Reading a drawing back for the tests: attributes and numbers of an SVG
//! element (`tmm_testkit::svg`'s, a missing number failing the test), the
//! paper's size, and each text's shown characters with a box estimated
//! independently of the drawing code; and running an example with the sheet
//! and language asked.

use tmm_report::TaskSource;
use tmm_report::run::{Run, run_task};
use tmm_testkit::examples;
pub use tmm_testkit::svg::{attr as attr_s, shown};

/// [`attr_s`] as an owned string.
pub fn attr(tag: &str, name: &str) -> Option<String> {
    attr_s(tag, name).map(str::to_string)
}

/// A numeric attribute (a trailing `mm` dropped); panics if it is missing.
pub fn num(tag: &str, name: &str) -> f64 {
    tmm_testkit::svg::num(tag, name).unwrap_or_else(|| panic!("no number {name} in {tag}"))
}

/// The paper's width and height, mm, and the root element.
pub fn paper(svg: &str) -> (f64, f64, String) {
    let root = svg.lines().find(|l| l.starts_with("<svg")).unwrap();
    (num(root, "width"), num(root, "height"), root.to_string())
}

/// Each text's shown characters (the tspans' markup dropped) and its box:
/// 0.6 of the height per character, 0.85 above and 0.35 below the baseline.
/// Rotated texts are left out when `skip_rotated`.
pub fn texts(svg: &str, skip_rotated: bool) -> Vec<(String, [f64; 4])> {
    let mut out = Vec::new();
    for l in svg
        .lines()
        .filter(|l| l.starts_with("<text") && !(skip_rotated && l.contains("rotate(")))
    {
        let inner = &l[l.find('>').unwrap() + 1..l.rfind("</text>").unwrap()];
        let shown = shown(inner).replace("&amp;", "&").replace("&lt;", "<").replace("&gt;", ">");
        let (x, y, s) = (num(l, "x"), num(l, "y"), num(l, "font-size"));
        let w = 0.6 * s * shown.chars().count() as f64;
        let x0 = match attr(l, "text-anchor").as_deref() {
            Some("middle") => x - w / 2.0,
            Some("end") => x - w,
            _ => x,
        };
        out.push((shown, [x0, y - 0.85 * s, x0 + w, y + 0.35 * s]));
    }
    out
}

/// `tmm run` in memory on an example, on the sheet and in the language given.
pub fn run_example(name: &str, sheet: &str, lang: &str) -> Run {
    let text = format!("{}\n[project]\nsheet = \"{sheet}\"\nlang = \"{lang}\"\n", examples::text(name));
    run_task(&TaskSource::new(name, text)).unwrap()
}
