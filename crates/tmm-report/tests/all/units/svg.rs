//! Tests of `tmm_report::svg`, kept outside the library so that the
//! test command compiles it once.

use tmm_report::svg::*;

/// Every label parses back to its tick's value, and the ticks cover the range.
#[test]
fn labels_are_exact_and_cover() {
    let mut seed = 0x2545_f491_4f6c_dd1du64;
    let mut rnd = || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    for _ in 0..5000 {
        let scale = 10f64.powf(rnd() * 16.0 - 8.0);
        let lo = (rnd() - 0.5) * scale;
        let hi = lo + rnd() * scale + 1e-300;
        let n = 2 + (rnd() * 10.0) as usize;
        let t = Ticks::new(lo, hi, n);
        let slack = 1e-9 * t.step();
        assert!(t.value(t.first) <= lo + slack && t.value(t.last) >= hi - slack, "{lo} {hi} {t:?}");
        assert!((t.last - t.first) as usize <= 3 * n + 2, "{lo} {hi} {n} {t:?}");
        for i in t.first..=t.last {
            let v: f64 = t.label(i).parse().unwrap();
            assert!(
                (v - t.value(i)).abs() <= 1e-12 * t.step().max(v.abs()),
                "{} vs {}",
                t.label(i),
                t.value(i)
            );
        }
    }
}

#[test]
fn the_reported_cases() {
    let t = Ticks {
        first: 0,
        last: 4,
        k: 25,
        e: -1,
    };
    assert_eq!(t.label(1), "2.5");
    assert_eq!(t.label(3), "7.5");
    let t = Ticks {
        first: 0,
        last: 4,
        k: 25,
        e: -2,
    };
    assert_eq!((t.label(1), t.label(3)), ("0.25".into(), "0.75".into()));
    let t = Ticks::new(0.0, 0.8, 4);
    assert_eq!(t.step(), 0.2);
    assert_eq!(t.label(3), "0.6");
    assert_eq!(Ticks::new(0.0, 3e6, 3).label(1), "1e6");
    assert_eq!(Ticks::new(-2e-5, 0.0, 2).label(-1), "-1e-5");
}

/// Read the x-axis labels of a plot back against their positions: the
/// label's value and its place on the paper lie on one straight line.
#[test]
fn plot_labels_read_back_against_positions() {
    let pts: Vec<(f64, f64)> = (0..=100).map(|k| (k as f64 * 0.075, (k as f64 * 0.1).sin() * 0.75)).collect();
    let svg = plot(
        "t",
        "x",
        "y",
        &[Series {
            name: "s",
            points: &pts,
            color: "#000",
        }],
        200.0,
        120.0,
    );
    // x labels: anchored middle, font-size 2.6 raised to the lettering
    // floor (the numbers among the texts of that size)
    let size = format!("font-size=\"{:.2}\"", tmm_report::picture::em(2.6));
    let mut xs: Vec<(f64, f64)> = Vec::new();
    let mut ys: Vec<(f64, f64)> = Vec::new();
    for line in svg.lines().filter(|l| l.starts_with("<text") && l.contains(&size)) {
        let attr = |name: &str| -> f64 {
            let i = line.find(&format!(" {name}=\"")).unwrap() + name.len() + 3;
            line[i..i + line[i..].find('"').unwrap()].parse().unwrap()
        };
        let Ok(label) = line[line.find('>').unwrap() + 1..line.find("</text>").unwrap()].parse::<f64>() else {
            continue;
        };
        if line.contains("text-anchor=\"middle\"") {
            xs.push((attr("x"), label));
        } else {
            ys.push((attr("y"), label));
        }
    }
    for set in [&xs, &ys] {
        assert!(set.len() >= 4, "{svg}");
        let (p0, v0) = set[0];
        let (p1, v1) = set[set.len() - 1];
        for &(p, v) in set.iter() {
            let expect = v0 + (p - p0) * (v1 - v0) / (p1 - p0);
            assert!(
                (expect - v).abs() < 0.002 * (v1 - v0).abs(),
                "label {v} at {p}: the axis says {expect}"
            );
        }
    }
}
