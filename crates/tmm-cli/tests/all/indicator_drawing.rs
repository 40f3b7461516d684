//! The indicator diagrams drawn by the dynamics section (`dynamics/indicator-k.svg`)
//! read back against the task's own tables: at every travel of each process
//! table the drawn curve passes through the table's pressure, measured on
//! the paper from the drawing's origin (s = 0, p = 0) at the scale factors
//! μ_s and μ_p printed on it. The tables are read here from the task file's
//! text, the stroke from the design rule H = 2·l_OA of a slider-crank whose
//! guide passes through the crank's pivot (both examples).

use tmm_testkit::plane::point_segment;
use tmm_testkit::svg::{attr, points, shown};

use crate::common::{repo, tmm_in, tmp};

/// A number list `[a, b, …]` after `key = ` on a line.
fn list(line: &str, key: &str) -> Option<Vec<f64>> {
    let rest = line.trim().strip_prefix(key)?.trim_start().strip_prefix('=')?;
    let inner = rest.trim().strip_prefix('[')?.strip_suffix(']')?;
    Some(inner.split(',').map(|v| v.trim().parse().unwrap()).collect())
}

/// The string value of `key = "…"` on a line.
fn string<'a>(line: &'a str, key: &str) -> Option<&'a str> {
    let rest = line.trim().strip_prefix(key)?.trim_start().strip_prefix('=')?;
    Some(rest.trim().trim_matches('"'))
}

/// One cylinder of the task: MPa per unit of its pressure tables and the
/// tables (name, travel, pressure) in the file's order.
struct Cylinder {
    mpa_per_unit: f64,
    tables: Vec<(String, Vec<f64>, Vec<f64>)>,
}

/// The cylinders of a task and its crank's length (m): read from the text.
fn cylinders(text: &str) -> (Vec<Cylinder>, f64) {
    let mut out: Vec<Cylinder> = Vec::new();
    let mut crank = None;
    let mut in_crank = false;
    let mut unit = 1.0;
    let mut travel: Option<Vec<f64>> = None;
    let length = |v: &str| -> f64 {
        let (n, u) = v.split_once(' ').unwrap();
        let n: f64 = n.parse().unwrap();
        match u {
            "m" => n,
            "mm" => n / 1000.0,
            _ => panic!("unit {u}"),
        }
    };
    for line in text.lines() {
        let t = line.trim();
        if t.starts_with('[') {
            in_crank = false;
        }
        if t == "[[forces.cylinders]]" {
            out.push(Cylinder {
                mpa_per_unit: 1e-6,
                tables: Vec::new(),
            });
        } else if let Some(name) = t.strip_prefix("[forces.cylinders.tables.") {
            let c = out.last_mut().unwrap();
            c.tables.push((name.trim_end_matches(']').to_string(), Vec::new(), Vec::new()));
        } else if t == "name = \"1\"" {
            in_crank = true;
        } else if let (true, Some(v)) = (in_crank, string(t, "length")) {
            crank = Some(length(v));
        } else if let Some(u) = string(t, "pressure_unit") {
            unit = match u {
                "MPa" => 1.0,
                "bar" => 0.1,
                "Pa" => 1e-6,
                "p_max" => f64::NAN,
                _ => panic!("unit {u}"),
            };
            out.last_mut().unwrap().mpa_per_unit = unit;
        } else if let Some(p) = string(t, "p_max") {
            let (n, u) = p.split_once(' ').unwrap();
            assert_eq!(u, "MPa");
            assert!(unit.is_nan());
            out.last_mut().unwrap().mpa_per_unit = n.parse().unwrap();
        } else if let Some(v) = list(t, "travel") {
            travel = Some(v);
        } else if let Some(v) = list(t, "pressure")
            && let Some(c) = out.last_mut()
            && let Some(tab) = c.tables.last_mut()
        {
            tab.1 = travel.take().unwrap();
            tab.2 = v;
        }
    }
    (out, crank.unwrap())
}

/// The number printed after `μ{sym} = ` (a decimal comma read as a point).
fn printed_mu(svg: &str, sym: &str) -> f64 {
    let t = shown(svg);
    let key = format!("μ{sym} = ");
    let at = t.find(&key).unwrap_or_else(|| panic!("no {key} on the drawing")) + key.len();
    let n: String = t[at..]
        .chars()
        .take_while(|c| c.is_ascii_digit() || *c == ',' || *c == '.')
        .collect();
    n.replace(',', ".").parse().unwrap()
}

/// The vertices of the curve drawn in the group of table `name`.
fn curve(svg: &str, name: &str) -> Vec<(f64, f64)> {
    let g = format!("<g class=\"indicator-table\" data-table=\"{name}\">");
    let at = svg.find(&g).unwrap_or_else(|| panic!("no curve of `{name}`"));
    points(attr(&svg[at..], "d").unwrap())
}

fn check(example: &str, name: &str) {
    let text = std::fs::read_to_string(repo().join(example)).unwrap();
    let (cyls, crank) = cylinders(&text);
    let h = 2.0 * crank;
    let d = tmp("indicator_drawing", name);
    let o = tmm_in(&d, &["run", "--no-pdf", repo().join(example).to_str().unwrap(), "-o", "out"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(!cyls.is_empty());
    for (k, c) in cyls.iter().enumerate() {
        let svg = std::fs::read_to_string(d.join(format!("out/dynamics/indicator-{}.svg", k + 1))).unwrap();
        let (mu_p, mu_s) = (printed_mu(&svg, "p"), printed_mu(&svg, "s"));
        let (ox, oy) = attr(&svg, "data-origin").unwrap().split_once(' ').unwrap();
        let (ox, oy): (f64, f64) = (ox.parse().unwrap(), oy.parse().unwrap());
        assert_eq!(c.tables.len(), svg.matches("class=\"indicator-table\"").count());
        for (tname, travel, pressure) in &c.tables {
            assert!(!travel.is_empty() && travel.len() == pressure.len(), "table `{tname}` not read");
            let pts = curve(&svg, tname);
            for (&x, &p) in travel.iter().zip(pressure) {
                // travel_unit = "H": the table's travel is a fraction of the stroke
                let want = (ox + x * h / mu_s, oy - p * c.mpa_per_unit / mu_p);
                // the drawn line passes through the table's point: a kept vertex,
                // or a vertex Douglas–Peucker dropped, within its 0.01 mm of the
                // line drawn instead (tmm_draw::simplify), the path's
                // coordinates written to 0.001 mm
                let got = pts
                    .windows(2)
                    .map(|w| point_segment(want, w[0], w[1]))
                    .fold(f64::INFINITY, f64::min);
                assert!(
                    got < 0.01 + 2e-3,
                    "{example} cylinder {} `{tname}` at travel {x}: the curve passes {got} mm from the table's point {want:?}",
                    k + 1
                );
            }
        }
    }
}

#[test]
fn p2_indicator_diagrams_pass_through_the_tables() {
    check("examples/textbook/p2-engine.toml", "p2");
}

#[test]
fn compressor_indicator_diagrams_pass_through_the_tables() {
    check("examples/compressor-two-stage.toml", "compressor");
}
