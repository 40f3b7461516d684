//! The BMSTU textbook's cams (appendix П6) through the command line: each
//! `examples/textbook/p6-*.toml` runs through `tmm run` with every quantity
//! GIVENS.md lists under "Asked" in its JSON and tables, checked against
//! references derived here — the law in closed form, the book's equations
//! solved by Cramer's rule, its lines intersected, its profile formula — and
//! bad input is refused with a located message and exit code 2.

use std::f64::consts::{FRAC_PI_2, PI, TAU};
use std::path::PathBuf;

use crate::common::{self, run};

fn tmp(name: &str) -> PathBuf {
    common::tmp("textbook-cams", name)
}

/// `tmm run FILE --no-pdf --json` and the tables of `tmm run FILE --no-pdf`.
fn run_example(file: &str) -> (serde_json::Value, String) {
    // a folder of its own for each call: several tests run the same example
    // at once
    static CALLS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let n = CALLS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let d = tmp(&format!("{file}-{n}"));
    let f = common::repo().join("examples/textbook").join(file);
    let out = d.join("out");
    let (code, stdout, err) = run(&["run", "--no-pdf", f.to_str().unwrap(), "-o", out.to_str().unwrap(), "--json"]);
    assert_eq!(code, 0, "{file}: {err}");
    let out2 = d.join("out2");
    let (code, text, err) = run(&["run", "--no-pdf", f.to_str().unwrap(), "-o", out2.to_str().unwrap()]);
    assert_eq!(code, 0, "{file}: {err}");
    (serde_json::from_str(&stdout).unwrap(), text)
}

fn f(v: &serde_json::Value, ptr: &str) -> f64 {
    v.pointer(ptr)
        .and_then(|x| x.as_f64())
        .unwrap_or_else(|| panic!("no number at {ptr}"))
}

fn arr(v: &serde_json::Value, ptr: &str) -> Vec<f64> {
    v.pointer(ptr)
        .and_then(|x| x.as_array())
        .unwrap_or_else(|| panic!("no array at {ptr}"))
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect()
}

fn d(x: f64) -> f64 {
    x.to_radians()
}

/// The book's law (GIVENS.md П6.1–П6.3) in closed form, `[S, v_q, a_q]` for
/// a stroke h: rise of two half sines split at f₁ = 3ψ_у/4 (scale h/ψ_у),
/// return of −a₃, +2.5·a₃ split at f₄ = f₃ + 2.5ψ_с/3.5, a₃ = 2h/(L₃ψ_с).
fn book(h: f64, phi: f64) -> [f64; 3] {
    let (psu, psc) = (d(120.0), d(180.0));
    let (f1, f2, f3, f5) = (d(90.0), psu, d(150.0), d(330.0));
    let f4 = f3 + 2.5 * psc / 3.5;
    let (l2, l3) = (f2 - f1, f4 - f3);
    let k = h / psu;
    let a3 = 2.0 * h / (l3 * psc);
    let p = phi.rem_euclid(TAU);
    if p < f1 {
        let x = PI * p / f1;
        [k * (p - f1 / PI * x.sin()), k * (1.0 - x.cos()), k * PI / f1 * x.sin()]
    } else if p < f2 {
        let t = p - f1;
        let x = PI * t / l2;
        [k * (f1 + t + l2 / PI * x.sin()), k * (1.0 + x.cos()), -k * PI / l2 * x.sin()]
    } else if p < f3 {
        [h, 0.0, 0.0]
    } else if p < f4 {
        let t = p - f3;
        [h - a3 * t * t / 2.0, -a3 * t, -a3]
    } else if p < f5 {
        let t = p - f4;
        [
            h - a3 * l3 * l3 / 2.0 - a3 * l3 * t + 1.25 * a3 * t * t,
            -a3 * l3 + 2.5 * a3 * t,
            2.5 * a3,
        ]
    } else {
        [0.0, 0.0, 0.0]
    }
}

/// The φ maximizing `g` on [a, b], on a grid of `n` steps.
fn argmax(a: f64, b: f64, n: usize, g: impl Fn(f64) -> f64) -> f64 {
    (0..=n)
        .map(|i| a + (b - a) * i as f64 / n as f64)
        .max_by(|x, y| g(*x).total_cmp(&g(*y)))
        .unwrap()
}

#[test]
fn p6_translating_runs_with_every_asked_quantity() {
    let (v, text) = run_example("p6-cam-translating.toml");
    let c = &v["cam"];
    let b = &c["book"];
    let h = 0.08;
    let (tu, tc) = (d(30.0).tan(), d(50.0).tan());
    // the book's equations (ω_q1 = −1, v_q = s′): tan θ_п (s₀ + S) = v − e_b,
    // tan θ_л (s₀ + S) = −v + e_b, by Cramer's rule
    let solve = |pp: f64, pl: f64| {
        let ([sp, vp, _], [sl, vl, _]) = (book(h, pp), book(h, pl));
        let (b1, b2) = (vp - tu * sp, -vl - tc * sl);
        let det = -tu - tc;
        ((-b1 - b2) / det, (tu * b2 - b1 * tc) / det)
    };
    // 1. step 1 at f₁ = 90°, f₄ = 278.571°
    let (s0, eb) = solve(d(90.0), d(150.0 + 2.5 * 180.0 / 3.5));
    assert!((f(b, "/phi_speed_rise") - d(90.0)).abs() < 1e-7);
    assert!((f(b, "/approximate/s0") - s0).abs() < 1e-9 && (f(b, "/approximate/e_book") - eb).abs() < 1e-9);
    assert!((f(b, "/approximate/r0") - s0.hypot(eb)).abs() < 1e-9);
    // 2. the tangency points: the maxima of v − tS, −v − tS on a 10⁵-step grid
    let pr = argmax(0.0, d(120.0), 100_000, |x| book(h, x)[1] - tu * book(h, x)[0]);
    let pl = argmax(d(150.0), d(330.0), 100_000, |x| -book(h, x)[1] - tc * book(h, x)[0]);
    assert!(
        (f(b, "/phi_tangent_rise") - pr).abs() < 3e-5,
        "{}",
        f(b, "/phi_tangent_rise").to_degrees()
    );
    assert!((f(b, "/phi_tangent_return") - pl).abs() < 3e-5);
    // 3. methods 1 and 2 at the tangency points
    let (s0, eb) = solve(f(b, "/phi_tangent_rise"), f(b, "/phi_tangent_return"));
    for m in ["method_1", "method_2"] {
        assert!((f(b, &format!("/{m}/s0")) - s0).abs() < 1e-9, "{m}");
        assert!((f(b, &format!("/{m}/e_book")) - eb).abs() < 1e-9, "{m}");
    }
    assert!((f(b, "/method_1/X") - eb).abs() < 1e-9 && (f(b, "/method_1/Y") + s0).abs() < 1e-9);
    // 4. Δr, Δe and θ(φ) of the book's centre at every profile angle
    let (r1, rp) = (s0.hypot(eb), f(b, "/approximate/r0"));
    assert!((f(b, "/delta_r") - (r1 - rp) / r1).abs() < 1e-9);
    assert!((f(b, "/delta_e") - (eb - f(b, "/approximate/e_book")) / eb).abs() < 1e-9);
    let phi = arr(c, "/phi");
    let theta = arr(b, "/theta");
    assert_eq!(phi.len(), theta.len());
    for (p, t) in phi.iter().zip(&theta) {
        let [s, vq, _] = book(h, *p);
        assert!((t - ((vq - eb) / (s0 + s)).atan()).abs() < 1e-9, "θ at {}°", p.to_degrees());
    }
    assert!((f(b, "/method_1/pressure_rise_max") - d(30.0)).abs() < 1e-9);
    assert!((f(b, "/method_1/pressure_return_min") + d(50.0)).abs() < 1e-9);
    // 5. the centre profile by the book's formula for tmm's centre, plotted as
    //    (−x_C, y_C): x_C = e_b cos φ − ω_q1 (s₀ + S) sin φ, y_C = ω_q1 e_b sin φ + (s₀ + S) cos φ
    let (s0x, ebx) = (f(c, "/s0"), -f(c, "/e"));
    let (px, py) = (arr(c, "/pitch_x"), arr(c, "/pitch_y"));
    let (wx, wy) = (arr(c, "/working_x"), arr(c, "/working_y"));
    let r = f(c, "/roller_radius");
    assert!((r - 0.02).abs() < 1e-15);
    for i in 0..phi.len() {
        let (p, s) = (phi[i], book(h, phi[i])[0]);
        let xc = ebx * p.cos() + (s0x + s) * p.sin();
        let yc = -ebx * p.sin() + (s0x + s) * p.cos();
        assert!(
            (px[i] + xc).abs() < 1e-12 && (py[i] - yc).abs() < 1e-12,
            "pitch at {}°",
            p.to_degrees()
        );
        // the working profile is the roller's equidistant
        assert!(((wx[i] - px[i]).hypot(wy[i] - py[i]) - r).abs() < 1e-12);
    }
    // the base circle r0 is the pitch curve's smallest radius
    let rmin = px.iter().zip(&py).map(|(x, y)| x.hypot(*y)).fold(f64::INFINITY, f64::min);
    assert!((rmin - f(c, "/r0")).abs() < 1e-12 && (f(c, "/rb") - (f(c, "/r0") - r)).abs() < 1e-15);
    // the roller rules (p. 111)
    let rr = &b["roller_rules"];
    assert!((f(rr, "/range_high") - 0.4 * f(c, "/r0")).abs() < 1e-15);
    assert!((f(rr, "/range_low") - 0.25 * f(c, "/r0")).abs() < 1e-15);
    assert_eq!(rr["in_range"].as_bool(), Some(r >= 0.25 * f(c, "/r0") && r <= 0.4 * f(c, "/r0")));
    assert_eq!(rr["above_range_low"].as_bool(), Some(r >= 0.25 * f(c, "/r0")));
    assert_eq!(rr["below_range_high"].as_bool(), Some(r <= 0.4 * f(c, "/r0")));
    assert!((f(rr, "/rho_bound") - 0.8 * f(c, "/rho_min_pitch")).abs() < 1e-15);
    assert_eq!(rr["below_rho_min"].as_bool(), Some(r < f(c, "/rho_min_pitch")));
    // the tables carry the same
    for s in [
        "step 1",
        "method 1",
        "method 2",
        "Δr",
        "Δe",
        "roller rules",
        "0.25·r0",
        "tangents",
        "θ(φ) at the book's centre",
    ] {
        assert!(text.contains(s), "the tables lack {s}");
    }
    assert!(text.contains(&format!("{:.4}", s0 * 1e3)) && text.contains(&format!("{:.4}", s0.hypot(eb) * 1e3)));
}

/// The book's П6.5 line at φ: κ = +1, ω_q1 = +1, v_q = l·s′ (arc), N = (l − v_q)e(φ₂),
/// k = tan(φ₂ + π/2 ± θ), b = N_y − k N_x.
fn book_line(l: f64, phi: f64) -> (f64, f64) {
    let [s, vq, _] = book(0.08, phi);
    let ph2 = s / l;
    let rho = l - vq;
    let n = (rho * ph2.cos(), rho * ph2.sin());
    let ang = if phi <= d(120.0) {
        ph2 + FRAC_PI_2 + d(30.0)
    } else {
        ph2 + FRAC_PI_2 - d(50.0)
    };
    let k = ang.tan();
    (k, n.1 - k * n.0)
}

fn meet(a: (f64, f64), b: (f64, f64)) -> (f64, f64) {
    let x = (b.1 - a.1) / (a.0 - b.0);
    (x, a.0 * x + a.1)
}

#[test]
fn p6_oscillating_runs_with_every_asked_quantity() {
    let (v, text) = run_example("p6-cam-oscillating.toml");
    let c = &v["cam"];
    let b = &c["book"];
    let l = 0.15;
    // the stroke is the tip's arc: 80 mm on 150 mm
    assert!((f(c, "/stroke") - 0.08 / l).abs() < 1e-15);
    let (x1, y1) = meet(book_line(l, d(90.0)), book_line(l, d(150.0 + 2.5 * 180.0 / 3.5)));
    assert!((f(b, "/point_1/0") - x1).abs() < 1e-12 && (f(b, "/point_1/1") - y1).abs() < 1e-12);
    let xv = |phi: f64| {
        let (k, bb) = book_line(l, phi);
        (y1 - bb) / k - x1
    };
    let vmin = argmax(d(60.0), d(120.0), 100_000, |x| -xv(x));
    let vmax = argmax(d(220.0), d(320.0), 100_000, xv);
    assert!((f(b, "/phi_v_min") - vmin).abs() < 3e-5, "{}", f(b, "/phi_v_min").to_degrees());
    assert!((f(b, "/phi_v_max") - vmax).abs() < 3e-5);
    assert!((f(b, "/x_v_min") - xv(vmin)).abs() < 1e-9);
    let (x2, y2) = meet(book_line(l, vmin), book_line(l, vmax));
    assert!((f(b, "/point_2/x") - x2).abs() < 1e-6 && (f(b, "/point_2/y") - y2).abs() < 1e-6);
    let aw = x2.hypot(y2);
    let f20 = (y2 / x2).abs().atan();
    assert!((f(b, "/point_2/centre_distance") - aw).abs() < 1e-6);
    assert!((f(b, "/point_2/initial_angle") - f20).abs() < 1e-5);
    // θ(φ) = atan{[v_q + a_w cos(φ₂₀ + φ₂) − l_T]/[a_w sin(φ₂₀ + φ₂)]} at every profile angle
    let (aw, f20) = (f(b, "/point_2/centre_distance"), f(b, "/point_2/initial_angle"));
    let phi = arr(c, "/phi");
    let theta = arr(b, "/theta");
    assert_eq!(phi.len(), theta.len());
    for (p, t) in phi.iter().zip(&theta) {
        let [s, vq, _] = book(0.08, *p);
        let ph2 = s / l;
        let want = ((vq + aw * (f20 + ph2).cos() - l) / (aw * (f20 + ph2).sin())).atan();
        assert!((t - want).abs() < 1e-9, "θ at {}°", p.to_degrees());
    }
    // point 2 passes the rise's limit a little; the vertex and tmm's design meet both
    assert!(f(b, "/point_2/limit_excess") > 0.0);
    // (tmm's sizing cuts the region by the cones of 1440 positions a phase:
    // between them the envelope may pass by some 10⁻⁷ rad, docs/cams.md §3)
    assert!(f(b, "/vertex/limit_excess") < 1e-9 && f(b, "/exact/limit_excess") < 1e-6);
    assert!(f(c, "/pressure_angle_max_rise") <= d(30.0) + 1e-6 && f(c, "/pressure_angle_max_return") <= d(50.0) + 1e-6);
    for s in [
        "level-line",
        "point 1",
        "φVmin",
        "φVmax",
        "point 2",
        "vertex",
        "aw mm",
        "φ20",
        "θ(φ) at point 2",
    ] {
        assert!(text.contains(s), "the tables lack {s}");
    }
}

/// Write a task file with the П6 law and one field changed; run it.
fn bad(name: &str, body: &str) -> (i32, String) {
    let dir = tmp(name);
    let file = dir.join("bad.toml");
    std::fs::write(&file, body).unwrap();
    let (code, _, err) = run(&["run", "--no-pdf", file.to_str().unwrap(), "-o", dir.join("out").to_str().unwrap()]);
    (code, err)
}

const LAW: &str = "rise 120 accel(sine 1, sine -3); dwell 30; return 180 accel(const -1, const 2.5); dwell 30";

#[test]
fn bad_p6_input_is_located_and_explained() {
    // allowed pressure angles of 0 and of 90° and more
    for (lim, word) in [
        ("rise 0, return 50", "rise"),
        ("rise 30, return 90", "return"),
        ("rise 95, return 50", "rise"),
    ] {
        let (code, e) = bad(
            "limit",
            &format!(
                "[cam]\nfollower = \"translating-roller\"\nstroke = \"80 mm\"\nphases = \"{LAW}\"\nmax_pressure = \"{lim}\"\nbook_methods = true\n"
            ),
        );
        assert_eq!(code, 2, "{e}");
        assert!(
            e.contains("bad.toml:5:") && e.contains("cam.max_pressure") && e.contains(word) && e.contains("90"),
            "{e}"
        );
    }
    // pieces of the law whose angles do not fill the phase
    let (code, e) = bad(
        "pieces",
        "[cam]\nfollower = \"translating-roller\"\nstroke = \"80 mm\"\nphases = \"rise 120 accel(sine 1 90°, sine -3 20°); dwell 30; return 180 accel(const -1, const 2.5); dwell 30\"\nmax_pressure = \"rise 30, return 50\"\n",
    );
    assert_eq!(code, 2, "{e}");
    assert!(
        e.contains("bad.toml:4:") && e.contains("cam.phases") && e.contains("add up to 110") && e.contains("120"),
        "{e}"
    );
    // pieces of one sign
    let (code, e) = bad(
        "sign",
        "[cam]\nfollower = \"translating-roller\"\nstroke = \"80 mm\"\nphases = \"rise 120 accel(sine 1, sine 3); dwell 30; return 180 cosine; dwell 30\"\nmax_pressure = \"30\"\n",
    );
    assert_eq!(code, 2, "{e}");
    assert!(e.contains("bad.toml:4:") && e.contains("same sign"), "{e}");
    // the book's constructions with two rises
    let (code, e) = bad(
        "two-rises",
        "[cam]\nfollower = \"translating-roller\"\nphases = \"rise 60 cosine 10mm; dwell 30; rise 60 cosine 10mm; return 120 cosine 20mm; dwell 90\"\nmax_pressure = \"30\"\nbook_methods = true\n",
    );
    assert_eq!(code, 2, "{e}");
    assert!(
        e.contains("bad.toml:5:") && e.contains("cam.book_methods") && e.contains("2 rises"),
        "{e}"
    );
    // an arc stroke without the arm
    let (code, e) = bad(
        "arc",
        &format!("[cam]\nfollower = \"oscillating-roller\"\nstroke = \"80 mm\"\nphases = \"{LAW}\"\nmax_pressure = \"30\"\n"),
    );
    assert_eq!(code, 2, "{e}");
    assert!(e.contains("bad.toml:3:") && e.contains("cam.stroke") && e.contains("arm"), "{e}");
    // a flat face has no book construction here
    let (code, e) = bad(
        "flat",
        &format!("[cam]\nfollower = \"translating-flat\"\nstroke = \"80 mm\"\nphases = \"{LAW}\"\nbook_methods = true\n"),
    );
    assert_eq!(code, 2, "{e}");
    assert!(e.contains("cam.book_methods") && e.contains("roller"), "{e}");
}

#[test]
fn tmm_cam_gives_the_book_methods_from_its_options() {
    let (code, out, err) = run(&[
        "cam",
        "--follower",
        "translating-roller",
        "--stroke",
        "80 mm",
        "--phases",
        LAW,
        "--max-pressure",
        "rise 30, return 50",
        "--rotation",
        "cw",
        "--roller",
        "20 mm",
        "--book-methods",
        "--json",
    ]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["book"]["method"], "tangents");
    // the same centre as the task file's run
    let (run_v, _) = run_example("p6-cam-translating.toml");
    assert_eq!(v["book"]["method_1"]["r0"], run_v["cam"]["book"]["method_1"]["r0"]);
    // a file and --book-methods together are refused
    let f = common::repo().join("examples/textbook/p6-cam-translating.toml");
    let (code, _, err) = run(&["cam", f.to_str().unwrap(), "--book-methods"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("--book-methods"), "{err}");
}
