//! The reactions over the whole machine's cycle (реакции за цикл;
//! Chernaya & Timofeev 2019, П3, p. 134–136): every reaction R_ij (on link
//! i by link j, 0 the frame) at every step of the cycle with the crank's
//! motion of the kinetostatics, the guide's reaction couple of each
//! prismatic pair about the slider's centre of mass (the book's M_50, with
//! R_50Y taken at X_S5), the balancing moment and — with the true motion
//! of `[dynamics]` — the book's check of it against the constant moment;
//! the chosen reactions drawn against the cycle angle and as hodographs
//! (годограф), Cartesian and polar, marked every 30°.

use std::fmt::Write;

use serde_json::{Value, json};
use tmm_geom::Vec2;
use tmm_linkage::forces::ForceSolution;

use crate::output::num;
use crate::picture::Picture;
use crate::project::Language;
use crate::svg::{Anchor, Canvas, Series, Style, plot_in};
use crate::words::word;

/// The book's check of the balancing moment with the true motion: the
/// constant inertia of the crank shaft lumped on the crank (M_Φ1 = −I·ε₁)
/// makes the balancing moment equal the constant moment at every angle
/// (docs/dynamics.md, "Engines and cycles of two turns").
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Lumped {
    /// The constant inertia not modelled as a link (flywheel, rotor,
    /// parts on the shaft): I_I − the crank's own, kg·m².
    pub inertia: f64,
    /// The constant moment the balancing moment must equal, signed
    /// counter-clockwise (the driving moment of a working machine, the
    /// resistance of an engine), N·m.
    pub moment: f64,
}

/// The reactions at every step of the cycle.
#[derive(Debug, Clone)]
pub struct ReactionCycle {
    /// The step, rad.
    pub step: f64,
    /// The reactions' names R_ij: each reaction of the solution as found
    /// (on link i by link j), then the opposite one R_ji = −R_ij of each
    /// pair between moving links.
    pub names: Vec<String>,
    /// Whether each reaction is a prismatic pair's (it has a guide couple M_ij).
    pub prismatic: Vec<bool>,
    /// For each name: the solution's reaction, its sign, and the link i it acts on.
    source: Vec<(usize, f64, usize)>,
    /// How many names are the solution's own (the rest are opposites).
    own: usize,
    /// Which names the text table shows: the own ones and the drawn opposites.
    shown: Vec<bool>,
    /// The cycle angle ψ of each step, rad (0 … the cycle, both ends).
    pub psi: Vec<f64>,
    /// The absolute crank angle of each step, rad.
    pub phi: Vec<f64>,
    /// ε₁ of each step, rad/s² (signed like the crank's ω).
    pub epsilon: Vec<f64>,
    /// The reactions, step after step (`names.len()` per step), N.
    pub forces: Vec<Vec2>,
    /// The guide couples about the centre of mass of the link `on`,
    /// step after step (0 for a revolute pair), N·m.
    pub couples: Vec<f64>,
    /// The balancing moment of each step, N·m.
    pub balancing: Vec<f64>,
    /// The lumped check, with the true motion.
    pub lumped: Option<Lumped>,
    /// The names drawn over the cycle (`R50`, `M50`).
    pub diagrams: Vec<String>,
    /// The reactions drawn as hodographs.
    pub hodographs: Vec<String>,
}

/// The course's name R_ij of a reaction on link `on` by link `from` (0 the frame).
pub fn reaction_name(names: &[String], on: usize, from: usize) -> String {
    let n = |i: usize| if i == 0 { "0" } else { names[i].as_str() };
    format!("R{}{}", n(on), n(from))
}

/// The moment of a prismatic pair's reaction `f`, acting at `at`, about the
/// centre of mass `s` of the link it acts on: the reaction equals `f` at `s`
/// plus this couple, (at − s) × f (derived here; the book's M_50 with R_50Y
/// at X_S5).
///
/// ```
/// use tmm_geom::Vec2;
/// // 100 N up, acting 0.2 m to the right of S: a couple of +20 N·m about S
/// let m = tmm_report::forces::reaction_cycle::couple_about(Vec2::new(0.3, 1.0), Vec2::new(0.1, 1.0), Vec2::new(0.0, 100.0));
/// assert!((m - 20.0).abs() < 1e-12);
/// ```
pub fn couple_about(at: Vec2, s: Vec2, f: Vec2) -> f64 {
    tmm_geom::cross(at - s, f)
}

impl ReactionCycle {
    /// An empty table for the reactions of `fs` (names of the links `links`).
    pub fn new(
        step: f64,
        links: &[String],
        fs: &ForceSolution,
        diagrams: Vec<String>,
        hodographs: Vec<String>,
        lumped: Option<Lumped>,
    ) -> Self {
        let mut source: Vec<(usize, f64, usize)> = fs.reactions.iter().enumerate().map(|(j, x)| (j, 1.0, x.on)).collect();
        let own = source.len();
        source.extend(
            fs.reactions
                .iter()
                .enumerate()
                .filter(|(_, x)| x.from != 0)
                .map(|(j, x)| (j, -1.0, x.from)),
        );
        let names: Vec<String> = source
            .iter()
            .map(|&(j, sg, on)| {
                let x = &fs.reactions[j];
                reaction_name(links, on, if sg > 0.0 { x.from } else { x.on })
            })
            .collect();
        let shown = names
            .iter()
            .enumerate()
            .map(|(i, n)| {
                let m = format!("M{}", &n[1..]);
                i < own || diagrams.iter().chain(&hodographs).any(|d| *d == *n || *d == m)
            })
            .collect();
        ReactionCycle {
            step,
            prismatic: source.iter().map(|&(j, _, _)| fs.reactions[j].prismatic).collect(),
            names,
            source,
            own,
            shown,
            psi: Vec::new(),
            phi: Vec::new(),
            epsilon: Vec::new(),
            forces: Vec::new(),
            couples: Vec::new(),
            balancing: Vec::new(),
            lumped,
            diagrams,
            hodographs,
        }
    }

    /// Every name that may be drawn: each R_ij, and M_ij of each prismatic pair.
    pub fn drawable(&self) -> Vec<String> {
        let mut v = self.names.clone();
        for (n, p) in self.names.iter().zip(&self.prismatic) {
            if *p {
                v.push(format!("M{}", &n[1..]));
            }
        }
        v
    }

    /// Add one step.
    pub fn push(&mut self, psi: f64, phi: f64, epsilon: f64, fs: &ForceSolution) {
        self.psi.push(psi);
        self.phi.push(phi);
        self.epsilon.push(epsilon);
        for &(j, sg, on) in &self.source {
            let x = &fs.reactions[j];
            let f = x.force * sg;
            self.forces.push(f);
            self.couples
                .push(if x.prismatic { couple_about(x.at, fs.links[on].s, f) } else { 0.0 });
        }
        self.balancing.push(fs.balancing_moment);
    }

    /// The number of steps stored.
    pub fn len(&self) -> usize {
        self.psi.len()
    }

    /// No step stored.
    pub fn is_empty(&self) -> bool {
        self.psi.is_empty()
    }

    /// How many of the names are the solution's own reactions.
    pub fn own(&self) -> usize {
        self.own
    }

    /// The reaction `j` at step `k`.
    pub fn force(&self, k: usize, j: usize) -> Vec2 {
        self.forces[k * self.names.len() + j]
    }

    /// The guide couple of reaction `j` at step `k`.
    pub fn couple(&self, k: usize, j: usize) -> f64 {
        self.couples[k * self.names.len() + j]
    }

    /// The balancing moment with the constant inertia lumped on the crank,
    /// M_1 = M_b + I·ε₁ (the crank's equation about its pivot with the
    /// inertia torque −I·ε₁ added), at step `k`.
    pub fn lumped_moment(&self, k: usize) -> Option<f64> {
        self.lumped.map(|l| self.balancing[k] + l.inertia * self.epsilon[k])
    }

    /// The largest |M_1 − M| over the cycle (the book's Δ), with the true motion.
    pub fn lumped_deviation(&self) -> Option<f64> {
        let l = self.lumped?;
        Some(
            (0..self.len())
                .filter_map(|k| self.lumped_moment(k))
                .map(|m| (m - l.moment).abs())
                .fold(0.0, f64::max),
        )
    }

    /// The text table: every reaction as magnitude and angle, the guide
    /// couples, M_b and the check.
    pub fn text(&self, out: &mut String) {
        let deg = self.step.to_degrees();
        let _ = writeln!(
            out,
            "\nReactions over the cycle every {deg:.4}°: |R|, N and its angle atan2(R_y, R_x), °; M_ij: the guide's reaction couple about the centre of mass of link i (the reaction = R_ij there plus M_ij), N·m; M_b: the balancing moment, N·m{}",
            if self.lumped.is_some() {
                "; M_1 = M_b + I·ε₁: with the constant inertia of the crank shaft lumped on the crank, which must equal the constant moment M"
            } else {
                ""
            }
        );
        let mut head = format!("  {:>9} {:>9}", "ψ, °", "φ, °");
        for ((n, p), _) in self.names.iter().zip(&self.prismatic).zip(&self.shown).filter(|x| *x.1) {
            head.push_str(&format!(" {:>10} {:>8}", format!("|{n}|"), "∠"));
            if *p {
                head.push_str(&format!(" {:>10}", format!("M{}", &n[1..])));
            }
        }
        head.push_str(&format!(" {:>11}", "M_b"));
        if self.lumped.is_some() {
            head.push_str(&format!(" {:>11} {:>10}", "M_1", "M_1 − M"));
        }
        let _ = writeln!(out, "{head}");
        for k in 0..self.len() {
            let mut line = format!("  {:>9.3} {:>9.3}", self.psi[k].to_degrees(), self.phi[k].to_degrees());
            for (j, p) in self.prismatic.iter().enumerate().filter(|(j, _)| self.shown[*j]) {
                let f = self.force(k, j);
                line.push_str(&format!(" {:>10.3} {:>8.2}", f.hypot(), f.y.atan2(f.x).to_degrees()));
                if *p {
                    line.push_str(&format!(" {:>10.4}", self.couple(k, j)));
                }
            }
            line.push_str(&format!(" {:>11.4}", self.balancing[k]));
            if let (Some(l), Some(m1)) = (self.lumped, self.lumped_moment(k)) {
                line.push_str(&format!(" {:>11.4} {:>10.2e}", m1, m1 - l.moment));
            }
            let _ = writeln!(out, "{line}");
        }
        if let (Some(l), Some(d)) = (self.lumped, self.lumped_deviation()) {
            let _ = writeln!(
                out,
                "  the book's check: M_1 = M_b + I·ε₁ with I = {:.6} kg·m² against the constant moment M = {:.6} N·m: max |M_1 − M| = {:.3e} N·m",
                l.inertia, l.moment, d
            );
        }
    }

    /// The JSON object (SI, radians).
    pub fn json(&self) -> Value {
        let n = self.names.len();
        let reactions: Vec<Value> = (0..n)
            .map(|j| {
                let mut o = json!({
                    "name": self.names[j],
                    "kind": if self.prismatic[j] { "P" } else { "R" },
                    "fx": (0..self.len()).map(|k| num(self.force(k, j).x)).collect::<Vec<_>>(),
                    "fy": (0..self.len()).map(|k| num(self.force(k, j).y)).collect::<Vec<_>>(),
                    "magnitude": (0..self.len()).map(|k| num(self.force(k, j).hypot())).collect::<Vec<_>>(),
                    "angle": (0..self.len()).map(|k| { let f = self.force(k, j); num(f.y.atan2(f.x)) }).collect::<Vec<_>>(),
                });
                if self.prismatic[j] {
                    o["couple_name"] = json!(format!("M{}", &self.names[j][1..]));
                    o["couple"] = json!((0..self.len()).map(|k| num(self.couple(k, j))).collect::<Vec<_>>());
                }
                o
            })
            .collect();
        let mut v = json!({
            "step": num(self.step),
            "psi": self.psi.iter().map(|&x| num(x)).collect::<Vec<_>>(),
            "phi": self.phi.iter().map(|&x| num(x)).collect::<Vec<_>>(),
            "epsilon1": self.epsilon.iter().map(|&x| num(x)).collect::<Vec<_>>(),
            "reactions": reactions,
            "balancing_moment": self.balancing.iter().map(|&x| num(x)).collect::<Vec<_>>(),
            "diagrams": self.diagrams,
            "hodographs": self.hodographs,
        });
        if let Some(l) = self.lumped {
            v["lumped"] = json!({
                "inertia": num(l.inertia),
                "constant_moment": num(l.moment),
                "balancing_moment": (0..self.len()).filter_map(|k| self.lumped_moment(k)).map(num).collect::<Vec<_>>(),
                "max_deviation": num(self.lumped_deviation().unwrap_or(0.0)),
            });
        }
        v
    }

    /// The index of reaction `name` (`R50`), or of the reaction of the couple `M50`.
    fn index(&self, name: &str) -> Option<(usize, bool)> {
        if let Some(j) = self.names.iter().position(|n| n == name) {
            return Some((j, false));
        }
        let rest = name.strip_prefix('M')?;
        self.names
            .iter()
            .zip(&self.prismatic)
            .position(|(n, p)| *p && &n[1..] == rest)
            .map(|j| (j, true))
    }

    /// The diagram of `name` over the cycle: a reaction's x and y
    /// components and magnitude, or a guide couple; 200 mm wide and
    /// `height` mm high.
    pub fn diagram(&self, lang: Language, name: &str, height: f64) -> Option<Picture> {
        let (j, couple) = self.index(name)?;
        let x = |k: usize| self.psi[k].to_degrees();
        let xl = word(lang, "forces.cycle_angle");
        if couple {
            let pts: Vec<(f64, f64)> = (0..self.len()).map(|k| (x(k), self.couple(k, j))).collect();
            let s = [Series {
                name,
                points: &pts,
                color: "#c00000",
            }];
            return Some(plot_in(
                lang,
                &format!("{}: {}", word(lang, "forces.couple_title"), typeset(name, "")),
                xl,
                &format!("M, {}", word(lang, "forces.unit_nm")),
                &s,
                200.0,
                height,
            ));
        }
        let comp = |c: usize| -> Vec<(f64, f64)> {
            (0..self.len())
                .map(|k| {
                    let f = self.force(k, j);
                    (x(k), [f.x, f.y, f.hypot()][c])
                })
                .collect()
        };
        let (px, py, pm) = (comp(0), comp(1), comp(2));
        let (nx, ny, nm) = (typeset(name, "x"), typeset(name, "y"), format!("|{}|", typeset(name, "")));
        let s = [
            Series {
                name: &nx,
                points: &px,
                color: "#0050c0",
            },
            Series {
                name: &ny,
                points: &py,
                color: "#c00000",
            },
            Series {
                name: &nm,
                points: &pm,
                color: "#000000",
            },
        ];
        Some(plot_in(
            lang,
            &format!("{}: {}", word(lang, "forces.reaction_title"), typeset(name, "")),
            xl,
            &format!("R, {}", word(lang, "forces.unit_n")),
            &s,
            200.0,
            height,
        ))
    }

    /// The hodograph of reaction `name`: the path of its tip from a common
    /// origin over the cycle, on equal scales, marked every 30° of the
    /// cycle; `polar` draws it on a polar grid (circles of |R|, rays every
    /// 30° of its angle) instead of Cartesian axes.
    pub fn hodograph(&self, lang: Language, name: &str, polar: bool) -> Option<Picture> {
        let (j, couple) = self.index(name)?;
        if couple {
            return None;
        }
        let w = 200.0;
        let pts: Vec<(f64, f64)> = (0..self.len()).map(|k| self.force(k, j)).map(|f| (f.x, f.y)).collect();
        let rmax = pts.iter().map(|p| p.0.hypot(p.1)).fold(0.0, f64::max).max(1e-9);
        let reach = 1.08 * rmax;
        let (xmin, xmax, ymin, ymax) = if polar {
            (-reach, reach, -reach, reach)
        } else {
            let f = |sel: fn(&(f64, f64)) -> f64, lo: bool| pts.iter().map(sel).fold(0.0f64, |a, b| if lo { a.min(b) } else { a.max(b) });
            let (x0, x1, y0, y1) = (f(|p| p.0, true), f(|p| p.0, false), f(|p| p.1, true), f(|p| p.1, false));
            let pad = 0.08 * (x1 - x0).max(y1 - y0).max(1e-9);
            (x0 - pad, x1 + pad, y0 - pad, y1 + pad)
        };
        // equal scales: the Cartesian plot is as tall as its data over the
        // plot's 150 mm width (a flat hodograph leaves no empty square on
        // the sheet or the note's page), between 90 and 200 mm in all
        let h = if polar {
            200.0
        } else {
            (48.0 + (w - 50.0) * (ymax - ymin) / (xmax - xmin).max(1e-12)).clamp(90.0, 200.0)
        };
        let mut c = Canvas::new(w, h);
        c.fit((xmin, xmax, ymin, ymax), (18.0, 14.0, w - 32.0, h - 34.0));
        let title = format!(
            "{} {}{}",
            word(lang, "forces.hodograph_title"),
            typeset(name, ""),
            if polar {
                format!(" ({})", word(lang, "forces.hodograph_polar"))
            } else {
                String::new()
            }
        );
        c.title((w / 2.0, 8.0), &title, 4.0, Anchor::Middle);
        let unit = word(lang, "forces.unit_n");
        if polar {
            // circles of |R| at round values, rays every 30° of the angle
            let step = nice(rmax / 4.0);
            let mut r = step;
            while r <= reach + 1e-12 {
                c.circle((0.0, 0.0), r, Style::THIN.colored("#a0a0a0"));
                c.text_colored(
                    (r * std::f64::consts::FRAC_1_SQRT_2, r * std::f64::consts::FRAC_1_SQRT_2),
                    &crate::svg::num(r, 0, lang),
                    2.5,
                    Anchor::Start,
                    "#606060",
                );
                r += step;
            }
            for k in 0..12 {
                let a = (30.0 * k as f64).to_radians();
                let e = (reach * a.cos(), reach * a.sin());
                c.line((0.0, 0.0), e, Style::THIN.colored("#a0a0a0"));
                c.text_colored((e.0 * 1.02, e.1 * 1.02), &format!("{}°", 30 * k), 2.5, Anchor::Middle, "#606060");
            }
            c.rich_paper(
                (w - 10.0, h - 6.0),
                &format!("|{}|, {unit}", typeset(name, "")),
                3.0,
                Anchor::End,
                "#000000",
            );
        } else {
            c.arrow((xmin, 0.0), (xmax, 0.0), Style::THIN, 2.5);
            c.arrow((0.0, ymin), (0.0, ymax), Style::THIN, 2.5);
            let (px, py) = (c.to_paper(xmax, 0.0), c.to_paper(0.0, ymax));
            c.rich_paper(px, &format!("{}, {unit}", typeset(name, "x")), 3.0, Anchor::End, "#000000");
            c.rich_paper(py, &format!(" {}, {unit}", typeset(name, "y")), 3.0, Anchor::Start, "#000000");
            let t = nice((xmax - xmin).max(ymax - ymin) / 6.0);
            let mut v = (xmin / t).ceil() * t;
            while v <= xmax {
                if v.abs() > 1e-9 * t {
                    c.line((v, 0.0), (v, 0.015 * (ymax - ymin)), Style::THIN);
                    c.text_colored(
                        (v, -0.04 * (ymax - ymin)),
                        &crate::svg::num(v, 0, lang),
                        2.2,
                        Anchor::Middle,
                        "#606060",
                    );
                }
                v += t;
            }
            let mut v = (ymin / t).ceil() * t;
            while v <= ymax {
                if v.abs() > 1e-9 * t {
                    c.line((0.0, v), (0.015 * (xmax - xmin), v), Style::THIN);
                    c.text_colored(
                        (-0.01 * (xmax - xmin), v),
                        &crate::svg::num(v, 0, lang),
                        2.2,
                        Anchor::End,
                        "#606060",
                    );
                }
                v += t;
            }
        }
        c.polyline(&pts, Style::THICK.colored("#c00000").widened(0.5));
        // marks every 30° of the cycle, and the vector at the start
        let every = ((30f64.to_radians() / self.step).round() as usize).max(1);
        for k in (0..self.len()).step_by(every) {
            let p = pts[k];
            if k + 1 == self.len() && self.len() > 1 {
                break;
            }
            c.dot(p, 0.8, "#000000");
            c.text(p, &format!(" {:.0}", self.psi[k].to_degrees()), 2.5, Anchor::Start);
        }
        if let Some(&p0) = pts.first() {
            c.arrow((0.0, 0.0), p0, Style::THIN.colored("#0050c0"), 2.0);
        }
        c.dot((0.0, 0.0), 0.6, "#000000");
        Some(c.finish())
    }
}

/// A round step (1, 2 or 5 times a power of ten) at least `x`.
fn nice(x: f64) -> f64 {
    if !(x.is_finite() && x > 0.0) {
        return 1.0;
    }
    let p = 10f64.powf(x.log10().floor());
    for m in [1.0, 2.0, 5.0, 10.0] {
        if m * p >= x {
            return m * p;
        }
    }
    10.0 * p
}

/// A reaction's or a couple's task name in the course's notation: `R30` →
/// `R_{30}` (R₃₀), `M50` → `M_{50}`, with `extra` appended to the index
/// (`R_{30x}`, the component along x).
///
/// ```
/// assert_eq!(tmm_report::forces::reaction_cycle::typeset("R30", ""), "R_{30}");
/// assert_eq!(tmm_report::forces::reaction_cycle::typeset("R21", "x"), "R_{21x}");
/// ```
pub fn typeset(name: &str, extra: &str) -> String {
    let mut chars = name.chars();
    match chars.next() {
        Some(head) if !chars.as_str().is_empty() => format!("{head}_{{{}{extra}}}", chars.as_str()),
        _ => format!("{name}{extra}"),
    }
}
