//! Every force polygon drawn — each Assur group's and the input link's with
//! the balancing force — closes to 1e-9 of its largest force, at every one
//! of many crank angles of every example with loads. The closure and the
//! forces are read back from the drawing itself.

use std::path::Path;

use tmm_report::TaskSource;
use tmm_report::forces::{analyse, drawings, load};

use crate::svg_read::shown;

fn read_back(svg: &str) -> (f64, f64) {
    let mut closure = None;
    let mut largest = 0.0f64;
    for line in svg.lines().filter(|l| l.contains("<text")) {
        // the words are Russian (the default), numbers with a decimal comma
        // and the subscripts' markup (tspans) dropped: the text as shown
        let inner = &line[line.find('>').unwrap() + 1..line.rfind("</text>").unwrap()];
        let text = shown(inner).replace(',', ".");
        if let Some(v) = text.strip_prefix("замыкание ").and_then(|t| t.strip_suffix(" Н")) {
            closure = Some(v.parse::<f64>().unwrap());
        } else if let Some(v) = text.strip_suffix(" Н") {
            // "R12 5199.3 N": a force arrow's label with its magnitude
            if let Some(num) = v.rsplit(' ').next().and_then(|n| n.parse::<f64>().ok()) {
                largest = largest.max(num);
            }
        }
    }
    (closure.expect("the polygon's closure is printed"), largest)
}

#[test]
fn every_drawn_polygon_closes() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    let mut checked = 0;
    for name in ["seed-001-fourbar.toml", "seed-003-sixbar.toml", "seed-004-two-sliders.toml"] {
        let text = std::fs::read_to_string(dir.join(name)).unwrap();
        let task = TaskSource::new(name, text);
        let (l, t) = load(&task).unwrap().unwrap();
        for k in 0..24 {
            let at = (k as f64 * 15.0 + 7.0).to_radians();
            let Ok(a) = analyse(&task, &l, &t, Some(at)) else { continue };
            let docs = drawings(&l, &t, &a, &task).unwrap();
            for d in docs.iter().filter(|d| d.path.starts_with("group-") || d.path == "input-link.svg") {
                let (closure, largest) = read_back(d.as_text().unwrap());
                assert!(largest > 0.0, "{name} {}: no force read", d.path);
                assert!(
                    closure <= 1e-9 * largest,
                    "{name} at {:.0}°, {}: closure {closure} N against {largest} N",
                    at.to_degrees(),
                    d.path
                );
                checked += 1;
            }
        }
    }
    assert!(checked > 100, "only {checked} polygons checked");
}
