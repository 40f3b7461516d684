//! The textbook's П3 shaper as a task file (examples/textbook/p3-shaper.toml),
//! checked against references computed here and nowhere else: the book's
//! synthesis solved again by Newton's method, the mechanism's positions by
//! circle intersection, its analogues by central differences, the cutting
//! and friction forces from the book's own table and rules, the work by
//! Simpson's rule between the jumps of the cutting force (located here by
//! bisection), the kinetic energy link by link, the ram's reactions by its
//! own equilibrium in closed form and the balancing moment by virtual
//! power. Bad input of the new keys is refused, located, with exit code 2.

use std::f64::consts::PI;

use serde_json::Value;

use crate::common::{repo, tmm_in, tmp};

fn p3() -> String {
    std::fs::read_to_string(repo().join("examples/textbook/p3-shaper.toml")).unwrap()
}

/// Run `text` as `task.toml`: (exit code, stdout, stderr, output dir).
fn run_text(name: &str, text: &str) -> (i32, String, String, std::path::PathBuf) {
    let d = tmp("shaper", name);
    std::fs::write(d.join("task.toml"), text).unwrap();
    let o = tmm_in(&d, &["run", "--no-pdf", "task.toml", "-o", "out"]);
    (
        o.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
        d.join("out"),
    )
}

fn read_json(p: &std::path::Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(p).unwrap()).unwrap()
}

fn arr(v: &Value) -> Vec<f64> {
    v.as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect()
}

// ---- the book's givens (GIVENS.md, П3) ----
const H: f64 = 0.3;
const K: f64 = 1.4;
const L_BC: f64 = 0.5;
const L_CD: f64 = 1.4 * 0.5;
const L_OC: f64 = 0.3;
const L_S5: f64 = 0.164;
const L_P: f64 = 0.09;
const M2: f64 = 25.0;
const M3: f64 = 38.0;
const M5: f64 = 60.0;
const I2: f64 = 0.6;
const I3: f64 = 1.2;
const G: f64 = 9.81;
const F_FR: f64 = 100.0;

#[allow(clippy::needless_range_loop)]
/// The book's synthesis: (l_OA, l_AB, φ₀, β) from its four equations by
/// Newton's method with a forward-difference Jacobian, from its guesses.
fn synthesis() -> [f64; 4] {
    let d_px = 2.0 * PI - 2.0 * PI / (K + 1.0);
    let g = (H / (2.0 * L_CD)).asin();
    let f = |x: &[f64; 4]| -> [f64; 4] {
        let (a, b, p0, be) = (x[0], x[1], x[2], x[3]);
        let c = (L_OC * be.cos(), L_OC * be.sin());
        let b1 = (c.0 + L_BC * (PI / 2.0 - g).cos(), c.1 + L_BC * (PI / 2.0 - g).sin());
        let b2 = (c.0 + L_BC * (PI / 2.0 + g).cos(), c.1 + L_BC * (PI / 2.0 + g).sin());
        [
            (a + b) * p0.cos() - b1.0,
            (a + b) * p0.sin() - b1.1,
            (a - b) * (p0 + d_px).cos() - b2.0,
            (a - b) * (p0 + d_px).sin() - b2.1,
        ]
    };
    let mut x = [0.1, 0.3, 45f64.to_radians(), -45f64.to_radians()];
    for _ in 0..40 {
        let f0 = f(&x);
        let mut m = [[0.0; 5]; 4];
        for j in 0..4 {
            let mut y = x;
            y[j] += 1e-8;
            let fj = f(&y);
            for i in 0..4 {
                m[i][j] = (fj[i] - f0[i]) / 1e-8;
            }
        }
        for i in 0..4 {
            m[i][4] = -f0[i];
        }
        // Gauss–Jordan with partial pivoting
        for c in 0..4 {
            let p = (c..4).max_by(|&a, &b| m[a][c].abs().total_cmp(&m[b][c].abs())).unwrap();
            m.swap(c, p);
            for r in 0..4 {
                if r != c {
                    let k = m[r][c] / m[c][c];
                    let pivot = m[c];
                    for (e, pv) in m[r].iter_mut().zip(pivot) {
                        *e -= k * pv;
                    }
                }
            }
        }
        for i in 0..4 {
            x[i] += m[i][4] / m[i][i];
        }
    }
    x
}

/// The shaper solved here: positions at cycle angle ψ (the crank clockwise
/// from the start of the working stroke).
struct Shaper {
    l_oa: f64,
    l_ab: f64,
    start: f64,
    c: (f64, f64),
    y_s5: f64,
}

/// Positions at one ψ: S2, S3, X_S5, φ2, φ3, D.
#[derive(Clone, Copy)]
struct Pos {
    s2: (f64, f64),
    s3: (f64, f64),
    x5: f64,
    p2: f64,
    p3: f64,
    d: (f64, f64),
}

impl Shaper {
    fn new() -> Self {
        let [l_oa, l_ab, p0, be] = synthesis();
        let c = (L_OC * be.cos(), L_OC * be.sin());
        let g = (H / (2.0 * L_CD)).asin();
        Shaper {
            l_oa,
            l_ab,
            start: p0 + 2.0 * PI - 2.0 * PI / (K + 1.0),
            c,
            y_s5: c.1 + L_CD - L_CD * (1.0 - g.cos()) / 2.0,
        }
    }

    fn pos(&self, psi: f64) -> Pos {
        let f1 = self.start - psi;
        let a = (self.l_oa * f1.cos(), self.l_oa * f1.sin());
        // B: the circles about A (l_AB) and C (l_BC); the rocker points up
        let (dx, dy) = (self.c.0 - a.0, self.c.1 - a.1);
        let dd = dx.hypot(dy);
        let x = (self.l_ab * self.l_ab - L_BC * L_BC + dd * dd) / (2.0 * dd);
        let h = (self.l_ab * self.l_ab - x * x).sqrt();
        let (ex, ey) = (dx / dd, dy / dd);
        let cand = [
            (a.0 + x * ex - h * ey, a.1 + x * ey + h * ex),
            (a.0 + x * ex + h * ey, a.1 + x * ey - h * ex),
        ];
        let b = if cand[0].1 > cand[1].1 { cand[0] } else { cand[1] };
        let p3 = (b.1 - self.c.1).atan2(b.0 - self.c.0);
        let p2 = (b.1 - a.1).atan2(b.0 - a.0);
        let d = (self.c.0 + L_CD * p3.cos(), self.c.1 + L_CD * p3.sin());
        Pos {
            s2: ((a.0 + b.0) / 2.0, (a.1 + b.1) / 2.0),
            s3: (self.c.0 + L_CD / 2.0 * p3.cos(), self.c.1 + L_CD / 2.0 * p3.sin()),
            x5: d.0 + L_S5,
            p2,
            p3,
            d,
        }
    }

    /// First and second analogues by central differences, as flat
    /// vectors (S2x, S2y, S3x, S3y, X5, φ2, φ3).
    fn analogues(&self, psi: f64) -> ([f64; 7], [f64; 7]) {
        let h = 1e-4;
        let v = |p: Pos| [p.s2.0, p.s2.1, p.s3.0, p.s3.1, p.x5, p.p2, p.p3];
        let (m, z, pl) = (v(self.pos(psi - h)), v(self.pos(psi)), v(self.pos(psi + h)));
        let mut d1 = [0.0; 7];
        let mut d2 = [0.0; 7];
        for i in 0..7 {
            d1[i] = (pl[i] - m[i]) / (2.0 * h);
            d2[i] = (pl[i] - 2.0 * z[i] + m[i]) / (h * h);
        }
        (d1, d2)
    }

    /// The ram's travel from the start of the working stroke.
    fn s5(&self, psi: f64) -> f64 {
        self.pos(psi).x5 - self.pos(0.0).x5
    }

    /// The book's cutting force F_резX: −F(s₅) on the working stroke
    /// within l_пер…H − l_пер, its table linear between 400 N at l_пер,
    /// 800 N at 0.35H and 600 N at H − l_пер.
    fn cutting(&self, psi: f64, v: f64) -> f64 {
        let s = self.s5(psi);
        let lp = 0.05 * H;
        if v <= 0.0 || s < lp || s > H - lp {
            return 0.0;
        }
        let f = if s <= 0.35 * H {
            400.0 + (800.0 - 400.0) * (s - lp) / (0.35 * H - lp)
        } else {
            800.0 + (600.0 - 800.0) * (s - 0.35 * H) / (H - lp - 0.35 * H)
        };
        -f
    }

    /// The book's reduced moment of the loads M_прC and I_прII.
    fn reduced(&self, psi: f64) -> (f64, f64) {
        let (v, _) = self.analogues(psi);
        let fr = -F_FR * v[4].signum();
        let m = -M2 * G * v[1] - M3 * G * v[3] + (self.cutting(psi, v[4]) + fr) * v[4];
        let i =
            I2 * v[5] * v[5] + M2 * (v[0] * v[0] + v[1] * v[1]) + I3 * v[6] * v[6] + M3 * (v[2] * v[2] + v[3] * v[3]) + M5 * v[4] * v[4];
        (m, i)
    }

    /// ψ in (lo, hi) where the travel crosses `s` (bisection).
    fn crossing(&self, s: f64, mut lo: f64, mut hi: f64) -> f64 {
        let up = self.s5(hi) > self.s5(lo);
        for _ in 0..80 {
            let mid = 0.5 * (lo + hi);
            if (self.s5(mid) < s) == up {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    }

    /// The work of the loads from 0 to ψ by composite Simpson on the
    /// pieces between the cutting force's jumps and the dead positions.
    fn work(&self, psi: f64) -> f64 {
        let d_px = 2.0 * PI - 2.0 * PI / (K + 1.0);
        let on = self.crossing(0.05 * H, 0.0, d_px);
        let off = self.crossing(0.95 * H, 0.0, d_px);
        let mut cuts = vec![0.0, on, off, d_px, 2.0 * PI];
        cuts.retain(|&c| c < psi);
        cuts.push(psi);
        let mut a = 0.0;
        for w in cuts.windows(2) {
            let n = 400;
            let h = (w[1] - w[0]) / n as f64;
            if h <= 0.0 {
                continue;
            }
            // the ends of a piece are its one-sided limits: 1e-12 inside
            let f = |k: usize| {
                let x = (w[0] + k as f64 * h).clamp(w[0] + 1e-12, w[1] - 1e-12);
                self.reduced(x).0
            };
            let mut s = f(0) + f(n);
            for k in 1..n {
                s += if k % 2 == 1 { 4.0 } else { 2.0 } * f(k);
            }
            a += s * h / 3.0;
        }
        a
    }
}

struct Run {
    forces: Value,
    dynamics: Value,
    linkage: Value,
    synthesis: Value,
}

fn run_p3(name: &str) -> Run {
    let (code, _, err, out) = run_text(name, &p3());
    assert_eq!(code, 0, "{err}");
    Run {
        forces: read_json(&out.join("forces/forces.json")),
        dynamics: read_json(&out.join("dynamics/dynamics.json")),
        linkage: read_json(&out.join("linkage/linkage.json")),
        synthesis: read_json(&out.join("synthesis/synthesis.json")),
    }
}

/// The task poses the book's givens (`[synthesis] kind = "shaper"`): the
/// synthesis must give the roots of the book's four equations (Newton's
/// method here, from the book's guesses), every quantity of "Asked 1", and a
/// [linkage] whose analysis (tmm's cycle: the dead positions as roots of
/// the ram's velocity) measures the stroke H, K and the start of the cycle.
#[test]
fn p3_synthesis_reproduces_the_book() {
    let s = Shaper::new();
    let [l_oa, l_ab, p0, be] = synthesis();
    let r = run_p3("p3-1");
    let y = &r.synthesis;
    assert_eq!(y["kind"], "shaper");
    let v = |p: &str| y.pointer(p).and_then(Value::as_f64).unwrap_or_else(|| panic!("{p}"));
    assert!((v("/lengths/OA") - l_oa).abs() < 1e-13, "{}", v("/lengths/OA"));
    assert!((v("/lengths/AB") - l_ab).abs() < 1e-13);
    assert!((v("/angles/phi0") - p0).abs() < 1e-12);
    assert!((v("/angles/beta") - be).abs() < 1e-12);
    assert!((v("/coordinates/X_C") - s.c.0).abs() < 1e-13);
    assert!((v("/coordinates/Y_C") - s.c.1).abs() < 1e-13);
    assert!((v("/coordinates/Y_S5") - s.y_s5).abs() < 1e-13);
    assert!((v("/lengths/AS2") - l_ab / 2.0).abs() < 1e-13);
    assert!((v("/lengths/CS3") - L_CD / 2.0).abs() < 1e-13);
    let start = s.start.rem_euclid(2.0 * PI);
    assert!((v("/angles/phi_start") - start).abs() < 1e-12);
    // ω_cp = Δφ_PX·V_рез/H: the working stroke H takes H/V_рез
    let w = (7.0 * PI / 6.0) * 0.5 / 0.3;
    assert!(
        (r.linkage["input"]["omega"].as_f64().unwrap().abs() - w).abs() < 1e-12,
        "{}",
        r.linkage["input"]
    );
    // the analysed [linkage]: the stroke, K and the start of the cycle
    let l = &r.linkage;
    let stroke = l["stroke"].as_f64().unwrap();
    assert!((stroke - H).abs() < 1e-9, "{stroke}");
    assert!((l["kv"].as_f64().unwrap() - K).abs() < 1e-9);
    assert!((l["working_angle"].as_f64().unwrap() - 7.0 * PI / 6.0).abs() < 1e-9);
    let start = l["dead_positions"][0]["phi"].as_f64().unwrap();
    assert!(((start - s.start).rem_euclid(2.0 * PI)).min((s.start - start).rem_euclid(2.0 * PI)) < 1e-9);
}

#[test]
fn p3_reduction_against_finite_differences_and_zero_work() {
    let s = Shaper::new();
    let r = run_p3("p3-2");
    let d = &r.dynamics;
    let (phi, mc, ii) = (arr(&d["phi"]), arr(&d["reduced_moment"]), arr(&d["reduced_inertia_variable"]));
    assert_eq!(phi.len(), 361);
    let on = s.crossing(0.05 * H, 0.0, 7.0 * PI / 6.0);
    let off = s.crossing(0.95 * H, 0.0, 7.0 * PI / 6.0);
    let (mut em, mut ei) = (0.0f64, 0.0f64);
    let (mmax, imax) = (
        mc.iter().fold(0.0f64, |a, b| a.max(b.abs())),
        ii.iter().fold(0.0f64, |a, b| a.max(b.abs())),
    );
    for k in 0..phi.len() {
        let p = phi[k];
        // the jumps of the cutting force and the dead positions, where
        // a one-sided value is a matter of convention
        if [0.0, on, off, 7.0 * PI / 6.0, 2.0 * PI].iter().any(|&c| (p - c).abs() < 1e-3) {
            continue;
        }
        let (m, i) = s.reduced(p);
        em = em.max((m - mc[k]).abs() / mmax);
        ei = ei.max((i - ii[k]).abs() / imax);
    }
    assert!(em < 1e-6, "reduced moment differs by {em:e} of its largest value");
    assert!(ei < 1e-6, "reduced inertia differs by {ei:e} of its largest value");
    // zero work over the steady cycle: M_d = −A_c(2π)/2π
    let a = s.work(2.0 * PI);
    let md = d["driving_moment"].as_f64().unwrap();
    assert!((md + a / (2.0 * PI)).abs() < 1e-6 * md.abs(), "{md} vs {}", -a / (2.0 * PI));
    let work = arr(&d["work"]);
    assert!((work[work.len() - 1] + md * 2.0 * PI).abs() < 1e-9 * md.abs() * 2.0 * PI);
}

#[test]
fn p3_energy_balance_and_time_integration() {
    let s = Shaper::new();
    let r = run_p3("p3-3");
    let d = &r.dynamics;
    let (phi, omega) = (arr(&d["phi"]), arr(&d["omega"]));
    let ic = d["inertia_constant"].as_f64().unwrap();
    let md = d["driving_moment"].as_f64().unwrap();
    let t = |k: usize| 0.5 * (ic + s.reduced(phi[k]).1) * omega[k] * omega[k];
    let t0 = t(0);
    for k in (30..phi.len()).step_by(30) {
        let a = s.work(phi[k]) + md * phi[k];
        assert!(
            (t(k) - t0 - a).abs() < 5e-7 * t0,
            "at {}°: ΔT = {}, work {a}",
            phi[k].to_degrees(),
            t(k) - t0
        );
    }
    // δ of the motion, and of the steady cycle integrated in time
    let (wmax, wmin) = (d["omega_max"].as_f64().unwrap(), d["omega_min"].as_f64().unwrap());
    let wm = (7.0 * PI / 6.0) * 0.5 / 0.3;
    assert!(((wmax - wmin) / wm - 0.05).abs() < 1e-9);
    assert!((d["runup"]["delta"].as_f64().unwrap() - 0.05).abs() < 1e-4);
    // the flywheel: the rotor reduced by (ω_rot/ω_cp)², the rest on the
    // shaft turning 22/12 as fast, a rim D1 = 0.8·D2, b = 0.2·D2 of steel
    let i_rotor = 0.2 * (950.0 * 2.0 * PI / 60.0 / wm).powi(2);
    let j = (ic - i_rotor) * (12.0f64 / 22.0).powi(2);
    let fw = &d["flywheel"];
    assert!((fw["inertia"].as_f64().unwrap() - j).abs() < 1e-9 * j);
    let rho = 7850.0;
    let d2 = (32.0 * j / (rho * PI * 0.2 * (1.0 - 0.8f64.powi(4)))).powf(0.2);
    assert!((fw["diameter"].as_f64().unwrap() - d2).abs() < 1e-9 * d2);
    let mass = rho * PI * 0.2 * d2 * (d2 * d2 - 0.64 * d2 * d2) / 4.0;
    assert!((fw["mass"].as_f64().unwrap() - mass).abs() < 1e-9 * mass);
}

#[test]
fn p3_reactions_by_the_ram_and_virtual_power() {
    let s = Shaper::new();
    let r = run_p3("p3-4");
    let rc = &r.forces["reaction_cycle"];
    let psi = arr(&rc["psi"]);
    assert_eq!(psi.len(), 361);
    let omega = arr(&r.dynamics["omega"]);
    let eps1 = arr(&rc["epsilon1"]);
    let find = |name: &str| {
        rc["reactions"]
            .as_array()
            .unwrap()
            .iter()
            .find(|x| x["name"] == name)
            .unwrap()
            .clone()
    };
    let (r50, r54) = (find("R50"), find("R54"));
    let (r50y, r54x, m50) = (arr(&r50["fy"]), arr(&r54["fx"]), arr(&r50["couple"]));
    let mb = arr(&rc["balancing_moment"]);
    let on = s.crossing(0.05 * H, 0.0, 7.0 * PI / 6.0);
    let off = s.crossing(0.95 * H, 0.0, 7.0 * PI / 6.0);
    let mbmax = mb.iter().fold(0.0f64, |a, b| a.max(b.abs()));
    for k in 0..psi.len() {
        let p = psi[k];
        if [0.0, on, off, 7.0 * PI / 6.0, 2.0 * PI].iter().any(|&c| (p - c).abs() < 1e-3) {
            continue;
        }
        // ψ grows as the crank turns clockwise: dψ/dt = ω, d²ψ/dt² = −ε₁
        let (w, e) = (omega[k], -eps1[k]);
        let (v, a) = s.analogues(p);
        let acc = |i: usize| a[i] * w * w + v[i] * e;
        let pos = s.pos(p);
        let fc = s.cutting(p, v[4]);
        let ff = -F_FR * v[4].signum();
        // the ram: everything on it but R54 is horizontal or at S5, so
        // R50 carries its weight; R54 balances the rest along X; its
        // moments about S5 give the guide's couple M50
        assert!((r50y[k] - M5 * G).abs() < 1e-9 * M5 * G, "R50y at {}°", p.to_degrees());
        let x54 = M5 * acc(4) - fc - ff;
        assert!(
            (r54x[k] - x54).abs() < 1e-5 * 1000.0,
            "R54x at {}°: {} vs {x54}",
            p.to_degrees(),
            r54x[k]
        );
        let m = (pos.d.1 - s.y_s5) * x54 - fc * L_P;
        assert!((m50[k] - m).abs() < 1e-5 * 100.0, "M50 at {}°: {} vs {m}", p.to_degrees(), m50[k]);
        // virtual power of every load and inertia force with the crank's
        // balancing moment (ω₁ = −dψ/dt): M_b·(−ω) + Σ P = 0
        let pw = (-M2 * acc(0)) * v[0] * w
            + (-M2 * acc(1) - M2 * G) * v[1] * w
            + (-M3 * acc(2)) * v[2] * w
            + (-M3 * acc(3) - M3 * G) * v[3] * w
            + (-M5 * acc(4) + fc + ff) * v[4] * w
            - I2 * acc(5) * v[5] * w
            - I3 * acc(6) * v[6] * w;
        assert!(
            (mb[k] - pw / w).abs() < 1e-5 * mbmax,
            "M_b at {}°: {} vs {}",
            p.to_degrees(),
            mb[k],
            pw / w
        );
    }
    // the book's check: with the crank shaft's inertia lumped on the crank,
    // the balancing moment is the constant moment at every degree
    let dev = rc["lumped"]["max_deviation"].as_f64().unwrap();
    let md = r.dynamics["driving_moment"].as_f64().unwrap();
    assert!(dev < 1e-9 * md.abs(), "{dev}");
    // the cut's crank angles φ′, φ″ and the overrun angle
    let w = &r.forces["stroke_windows"][0];
    let back = s.crossing(0.05 * H, 7.0 * PI / 6.0, 2.0 * PI);
    assert!((w["start"].as_f64().unwrap() - on).abs() < 1e-8);
    assert!((w["end"].as_f64().unwrap() - off).abs() < 1e-8);
    assert!((w["return"].as_f64().unwrap() - back).abs() < 1e-8);
    assert!((w["overrun"].as_f64().unwrap() - (on + 2.0 * PI - back)).abs() < 1e-8);
}

#[test]
fn p3_writes_the_diagrams_and_hodographs() {
    let (code, out, err, dir) = run_text("drawings", &p3());
    assert_eq!(code, 0, "{err}");
    for f in [
        "reaction-R50.svg",
        "reaction-M50.svg",
        "reaction-R54.svg",
        "hodograph-R21.svg",
        "hodograph-R21-polar.svg",
    ] {
        let svg = std::fs::read_to_string(dir.join("forces").join(f)).unwrap_or_else(|e| panic!("{f}: {e}"));
        assert!(svg.starts_with("<svg") || svg.contains("<svg"), "{f}");
    }
    assert!(out.contains("the book's check: M_1 = M_b + I·ε₁"), "{out}");
    assert!(out.contains("φ′ ="), "{out}");
}

/// Run `text` and expect exit code 2 with `field`, located at `line`, and `what`.
fn refused(name: &str, text: &str, field: &str, line: usize, what: &str) {
    let (code, _, err, _) = run_text(name, text);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains(field), "no `{field}` in: {err}");
    assert!(err.contains(&format!("task.toml:{line}:")), "not located at line {line}: {err}");
    assert!(err.contains(what), "no `{what}` in: {err}");
}

fn line_of(text: &str, needle: &str) -> usize {
    let at = text.find(needle).unwrap_or_else(|| panic!("`{needle}` not in the task"));
    text[..at].matches('\n').count() + 1
}

fn with(from: &str, to: &str) -> String {
    let t = p3();
    assert!(t.contains(from), "`{from}` not in the task");
    t.replacen(from, to, 1)
}

#[test]
fn bad_shaper_input_is_refused_and_located() {
    // the synthesis' givens
    let t = with("stroke = \"0.3 m\"", "stroke = \"1.5 m\"");
    refused("stroke", &t, "synthesis.stroke", line_of(&t, "stroke = "), "l_CD");
    let t = with("frame = \"0.3 m\"", "frame = \"50 m\"");
    refused("frame", &t, "synthesis.frame", line_of(&t, "frame = \"50"), "no direction");
    let t = with("lambda = 1.4", "lambda = -1.4");
    refused("lambda", &t, "synthesis.lambda", line_of(&t, "lambda = "), "positive");
    let t = with("design_position = \"90 deg\"", "design_position = \"400 deg\"");
    refused(
        "design",
        &t,
        "synthesis.design_position",
        line_of(&t, "design_position = "),
        "0 to 360",
    );
    let t = with("cutting_speed = \"0.5 m/s\"", "cutting_speed = \"0.5 m/s\"\nspeed = \"60 rpm\"");
    refused(
        "speeds",
        &t,
        "synthesis.cutting_speed",
        line_of(&t, "cutting_speed = "),
        "only one of",
    );
    let t = with("cutting_speed = \"0.5 m/s\"", "cutting_speed = \"0.5 kg\"");
    refused(
        "cut-unit",
        &t,
        "synthesis.cutting_speed",
        line_of(&t, "cutting_speed = "),
        "velocity",
    );
    let t = with("arm = \"0.09 m\"", "arm = \"0.09 kg\"");
    refused("arm", &t, "forces.stroke_forces[0].arm", line_of(&t, "arm = "), "length");
    let t = with("step = \"1 deg\"", "step = \"7 deg\"");
    refused("step", &t, "forces.cycle.step", line_of(&t, "step = "), "divide the cycle");
    let t = with("diagrams = [\"R50\"", "diagrams = [\"R57\"");
    refused("diagram", &t, "forces.cycle.diagrams[0]", line_of(&t, "diagrams = "), "R50");
    let t = with("hodographs = [\"R21\"]", "hodographs = [\"M50\"]");
    refused("hodograph", &t, "forces.cycle.hodographs[0]", line_of(&t, "hodographs = "), "R21");
    let t = with("place = \"shaft\"\n", "place = \"crank\"\n");
    refused(
        "ratio",
        &t,
        "dynamics.flywheel.speed_ratio",
        line_of(&t, "speed_ratio = "),
        "place = \"shaft\"",
    );
    let t = with("speed_ratio = 1.83333333333333\n", "");
    refused(
        "no-ratio",
        &t,
        "dynamics.flywheel.speed_ratio",
        line_of(&t, "place = \"shaft\""),
        "speed ratio",
    );
    let t = with("speed_ratio = 1.83333333333333", "speed_ratio = 0");
    refused(
        "zero-ratio",
        &t,
        "dynamics.flywheel.speed_ratio",
        line_of(&t, "speed_ratio = "),
        "1e-6",
    );
    let t = with("inner_ratio = 0.8", "inner_ratio = 0.8\nthickness_ratio = 0.1");
    refused(
        "both",
        &t,
        "dynamics.flywheel.inner_ratio",
        line_of(&t, "inner_ratio = "),
        "not both",
    );
    let t = with("inner_ratio = 0.8", "inner_ratio = 1.2");
    refused("inner", &t, "dynamics.flywheel.inner_ratio", line_of(&t, "inner_ratio = "), "0.998");
    let t = with("motor_speed = \"950 rpm\"", "motor_speed = \"-950 rpm\"");
    refused(
        "motor-speed",
        &t,
        "dynamics.inertia.motor_speed",
        line_of(&t, "motor_speed = "),
        "> 0",
    );
    let t = with("motor_speed = \"950 rpm\"\n", "");
    refused(
        "no-motor-speed",
        &t,
        "dynamics.inertia.motor_shaft",
        line_of(&t, "motor_shaft = "),
        "motor_speed",
    );
}

/// The assumptions say that friction is neglected only where the task gives
/// none: П3's friction on the ram's guide is taken, the four-bar's pairs
/// have no friction at all.
#[test]
fn the_assumptions_name_the_given_friction() {
    let assumptions = |file: &str| {
        let o = crate::common::tmm_in(&crate::common::repo(), &["forces", file, "--json"]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        crate::common::json(&o)["assumptions"].as_str().unwrap().to_string()
    };
    let p3 = assumptions("examples/textbook/p3-shaper.toml");
    assert!(p3.contains("the given sliding friction on the guides taken"), "{p3}");
    let fourbar = assumptions("examples/seed-001-fourbar.toml");
    assert!(fourbar.contains("friction neglected (seed 000"), "{fourbar}");
}
