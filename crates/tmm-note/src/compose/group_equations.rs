//! The vector equations of the velocity and acceleration plans written from
//! the mechanism's own structure (уравнения планов скоростей и ускорений по
//! группам Ассура): the input link's equation with its own letters, then one
//! equation per Assur group in the order the groups are attached, each with
//! the group's own points and link numbers, and the lines of the symbols
//! under them (GOST 2.105, 4.2.15) naming exactly the symbols used.
//!
//! The forms are the course's (Артоболевский И. И. Теория механизмов и
//! машин, 1988, § 13–15; Попов С. А., Тимофеев Г. А. Курсовое
//! проектирование по ТММ, 2002, гл. 2):
//! - a group whose inner pair K is a turning pair: K belongs to both links,
//!   each outer pair gives one side: a turning pair X of link g,
//!   v_K = v_X + v_KX (a_K = a_X + a^n_KX + a^τ_KX, a^n_KX = ω_g² l_XK);
//!   a sliding pair on the guide o, v_K = v_Ko + v_KKo (a_K = a_Ko +
//!   a^k_KKo + a^r_KKo, a^k_KKo = 2 ω_o v_KKo, zero for a guide that does
//!   not turn, written without it);
//! - a group whose inner pair is a sliding pair at K between the links a
//!   (its outer pair at K: the point K_a is known) and b: the point K_b of
//!   b, v_Kb = v_Ka + v_KbKa (a_Kb = a_Ka + a^k_KbKa + a^r_KbKa,
//!   a^k_KbKa = 2 ω_b v_KbKa, ω_a = ω_b across a sliding pair), equal to
//!   the side of b's outer pair as above;
//! - a group of a higher class: for each of its links, each pair's point
//!   against the link's first pair, v_P = v_Q + v_PQ (the equations the
//!   plan is built from with the group's special points).

use std::collections::BTreeSet;

use serde_json::Value;

use super::context::Ctx;
use super::linkage::math_name;
use crate::error::NoteError;
use crate::model::{Block, Text};
use crate::notation::{MATH_CLOSE, MATH_OPEN};

/// A kinematic pair of the report's structure.
#[derive(Clone, Debug)]
struct Pair {
    point: String,
    links: [String; 2],
    sliding: bool,
}

/// An Assur group of the report's structure: its kind and links, and its
/// pairs (inner: both links in the group; outer: one).
struct Group {
    links: Vec<String>,
    pairs: Vec<Pair>,
    class: u64,
}

/// The symbols a set of formulas uses, by kind, in their first order.
#[derive(Default)]
struct Symbols {
    points: Vec<String>,
    coincident: Vec<String>,
    rotation: Vec<String>,
    sliding: Vec<String>,
    normal: Vec<String>,
    tangential: Vec<String>,
    coriolis: Vec<String>,
    relative: Vec<String>,
    omegas: Vec<String>,
    epsilons: Vec<String>,
    lengths: Vec<String>,
    /// the input slider's given speed v or acceleration a along its guide
    slider: Vec<String>,
}

fn add(list: &mut Vec<String>, s: &str) {
    if !list.iter().any(|x| x == s) {
        list.push(s.to_string());
    }
}

/// The formulas (velocity, acceleration, the magnitudes of the normal and
/// Coriolis accelerations) with their lines of symbols.
pub(crate) struct Equations {
    pub velocity: String,
    pub acceleration: String,
    pub magnitudes: String,
    velocity_symbols: Symbols,
    acceleration_symbols: Symbols,
    magnitude_symbols: Symbols,
}

/// A link's number as a subscript: the frame (стойка) is 0.
fn link_no(link: &str) -> String {
    if link == "frame" { "0".to_string() } else { math_name(link) }
}

/// A point of a link, `B_3` (the point of link 3 at B).
fn on(point: &str, link: &str) -> String {
    format!("{}_{}", math_name(point), link_no(link))
}

/// A subscript of two points, `B A` or `B_3 B_2`.
fn two(a: &str, b: &str) -> String {
    format!("{a} {b}")
}

fn read_pairs(cx: &Ctx) -> Vec<Pair> {
    let list = cx.report.pointer("/linkage/structure/pairs").and_then(Value::as_array);
    list.map(|l| {
        l.iter()
            .filter_map(|p| {
                let links: Vec<&str> = p.get("links")?.as_array()?.iter().filter_map(Value::as_str).collect();
                let [a, b] = links.as_slice() else { return None };
                Some(Pair {
                    point: p.get("point")?.as_str()?.to_string(),
                    links: [a.to_string(), b.to_string()],
                    sliding: p.get("kind").and_then(Value::as_str) == Some("P"),
                })
            })
            .collect()
    })
    .unwrap_or_default()
}

fn read_groups(cx: &Ctx, pairs: &[Pair]) -> Vec<Group> {
    let list = cx.report.pointer("/linkage/structure/groups").and_then(Value::as_array);
    list.map(|l| {
        l.iter()
            .filter_map(|g| {
                let links: Vec<String> = g
                    .get("links")?
                    .as_array()?
                    .iter()
                    .filter_map(|s| s.as_str().map(str::to_string))
                    .collect();
                let points: Vec<&str> = g.get("pairs")?.as_array()?.iter().filter_map(Value::as_str).collect();
                let pairs = pairs
                    .iter()
                    .filter(|p| points.contains(&p.point.as_str()) && p.links.iter().any(|l| links.contains(l)))
                    .cloned()
                    .collect();
                Some(Group {
                    links,
                    pairs,
                    class: g.get("class").and_then(Value::as_u64).unwrap_or(2),
                })
            })
            .collect()
    })
    .unwrap_or_default()
}

/// The links that do not turn: the frame and every link joined to one of
/// them by a sliding pair (a slider on a fixed guide, a ram and its block).
fn not_turning(pairs: &[Pair]) -> BTreeSet<String> {
    let mut set: BTreeSet<String> = ["frame".to_string()].into();
    loop {
        let before = set.len();
        for p in pairs.iter().filter(|p| p.sliding) {
            if set.contains(&p.links[0]) || set.contains(&p.links[1]) {
                set.extend(p.links.iter().cloned());
            }
        }
        if set.len() == before {
            return set;
        }
    }
}

impl Group {
    fn inner(&self) -> Vec<&Pair> {
        self.pairs
            .iter()
            .filter(|p| p.links.iter().all(|l| self.links.contains(l)))
            .collect()
    }
    /// The outer pair of a link of the group and the link outside.
    fn outer(&self, link: &str) -> Option<(&Pair, String)> {
        self.pairs.iter().find_map(|p| {
            let other = p.links.iter().find(|l| !self.links.contains(l))?;
            p.links.iter().any(|l| l == link).then(|| (p, other.clone()))
        })
    }
}

/// What a group's line adds after its equation: the zero velocities and
/// accelerations of the frame's points, and the magnitudes' formulas.
#[derive(Default)]
struct Extra {
    v: Vec<String>,
    a: Vec<String>,
    mags: Vec<String>,
}

/// The builder of the three formulas.
struct Builder<'a> {
    still: &'a BTreeSet<String>,
    v: Symbols,
    a: Symbols,
    m: Symbols,
    v_lines: Vec<String>,
    a_lines: Vec<String>,
    m_lines: Vec<String>,
}

impl Builder<'_> {
    /// A point whose velocity and acceleration the plans find (v_B, a_B).
    fn point(&mut self, p: &str) {
        add(&mut self.v.points, p);
        add(&mut self.a.points, p);
    }

    /// A point of a link at a pair's place (v_B3, a_B3).
    fn coincident(&mut self, p: &str) {
        add(&mut self.v.coincident, p);
        add(&mut self.a.coincident, p);
    }

    /// The Coriolis acceleration of a sliding `rel` along the guide `guide`
    /// that turns: a^k = 2·ω·v_r (Артоболевский 1988, § 15).
    fn coriolis(&mut self, rel: &str, guide: &str, ex: &mut Extra) {
        add(&mut self.a.coriolis, rel);
        let omega = format!("omega_{}", link_no(guide));
        add(&mut self.m.omegas, &omega);
        add(&mut self.m.coriolis, rel);
        add(&mut self.m.sliding, rel);
        ex.mags.push(format!("a^k_({rel}) = 2 {omega} v_({rel})"));
    }

    /// A sliding along a guide: its velocity v_KKo and relative
    /// acceleration a^r_KKo.
    fn slide(&mut self, rel: &str) {
        add(&mut self.v.sliding, rel);
        add(&mut self.a.relative, rel);
    }

    /// One side through a turning pair at `x` of link `g`: the unknown
    /// point `k` (math) turns about `x` with `g`.
    fn turning(&mut self, k: &str, x: &str, g: &str, on_frame: bool, ex: &mut Extra) -> (String, String) {
        let xm = math_name(x);
        self.point(&xm);
        let rel = two(k, &xm);
        add(&mut self.v.rotation, &rel);
        add(&mut self.a.normal, &rel);
        add(&mut self.a.tangential, &rel);
        if on_frame {
            ex.v.push(format!("v_({xm}) = 0"));
            ex.a.push(format!("a_({xm}) = 0"));
        }
        let omega = format!("omega_{}", link_no(g));
        add(&mut self.m.omegas, &omega);
        let len = format!("l_({} {})", xm, strip_link(k));
        add(&mut self.m.lengths, &len);
        add(&mut self.m.normal, &rel);
        ex.mags.push(format!("a^n_({rel}) = {omega}^2 {len}"));
        (
            format!("arrow(v)_({xm}) + arrow(v)_({rel})"),
            format!("arrow(a)_({xm}) + arrow(a)^n_({rel}) + arrow(a)^tau_({rel})"),
        )
    }

    /// One side through a sliding pair: the point `k` (math) of link
    /// `slider` against the coincident point of the guide `guide` at `at`.
    fn sliding(&mut self, k: &str, at: &str, guide: &str, ex: &mut Extra) -> (String, String) {
        let ko = on(at, guide);
        self.coincident(&ko);
        let rel = two(k, &ko);
        self.slide(&rel);
        if guide == "frame" {
            ex.v.push(format!("v_({ko}) = 0"));
            ex.a.push(format!("a_({ko}) = 0"));
        }
        let acc = if self.still.contains(guide) {
            format!("arrow(a)_({ko}) + arrow(a)^r_({rel})")
        } else {
            self.coriolis(&rel, guide, ex);
            format!("arrow(a)_({ko}) + arrow(a)^k_({rel}) + arrow(a)^r_({rel})")
        };
        (format!("arrow(v)_({ko}) + arrow(v)_({rel})"), acc)
    }

    fn finish_line(&mut self, k: &str, sides: &[(String, String)], ex: Extra) {
        let mut v = format!(
            "arrow(v)_({k}) = {}",
            sides.iter().map(|s| s.0.as_str()).collect::<Vec<_>>().join(" = ")
        );
        let mut a = format!(
            "arrow(a)_({k}) = {}",
            sides.iter().map(|s| s.1.as_str()).collect::<Vec<_>>().join(" = ")
        );
        for z in ex.v {
            v.push_str(&format!(", quad {z}"));
        }
        for z in ex.a {
            a.push_str(&format!(", quad {z}"));
        }
        self.v_lines.push(v);
        self.a_lines.push(a);
        if !ex.mags.is_empty() {
            self.m_lines.push(ex.mags.join(", quad "));
        }
    }

    fn group(&mut self, g: &Group) {
        let inner = g.inner();
        match inner.as_slice() {
            [k] if g.class == 2 && g.links.len() == 2 && !k.sliding => {
                let km = math_name(&k.point);
                self.point(&km);
                let (mut ex, mut sides) = (Extra::default(), Vec::new());
                for link in &g.links {
                    let Some((p, other)) = g.outer(link) else { continue };
                    let side = if p.sliding {
                        self.sliding(&km, &k.point, &other, &mut ex)
                    } else {
                        self.turning(&km, &p.point, link, other == "frame", &mut ex)
                    };
                    sides.push(side);
                }
                self.finish_line(&km, &sides, ex);
            }
            [k] if g.class == 2 && g.links.len() == 2 => {
                // the link whose outer pair is at K carries the known point
                let at_k = |l: &String| g.outer(l).is_some_and(|(p, _)| p.point == k.point);
                let a = g.links.iter().find(|l| at_k(l)).unwrap_or(&g.links[0]).clone();
                let b = g.links.iter().find(|l| **l != a).cloned().unwrap_or_default();
                let (ka, kb) = (on(&k.point, &a), on(&k.point, &b));
                self.coincident(&ka);
                self.coincident(&kb);
                let rel = two(&kb, &ka);
                self.slide(&rel);
                let mut ex = Extra::default();
                let first_a = if self.still.contains(&b) {
                    format!("arrow(a)_({ka}) + arrow(a)^r_({rel})")
                } else {
                    self.coriolis(&rel, &b, &mut ex);
                    format!("arrow(a)_({ka}) + arrow(a)^k_({rel}) + arrow(a)^r_({rel})")
                };
                let mut sides = vec![(format!("arrow(v)_({ka}) + arrow(v)_({rel})"), first_a)];
                if let Some((p, other)) = g.outer(&b) {
                    sides.push(if p.sliding {
                        self.sliding(&kb, &k.point, &other, &mut ex)
                    } else {
                        self.turning(&kb, &p.point, &b, other == "frame", &mut ex)
                    });
                }
                self.finish_line(&kb, &sides, ex);
            }
            _ => self.general(g),
        }
    }

    /// A group of a higher class (or of an unusual form): for each link,
    /// each further pair's point against its first pair's (outer first).
    fn general(&mut self, g: &Group) {
        let mut eqs = Vec::new();
        let mut aeqs = Vec::new();
        let mut ex = Extra::default();
        for link in &g.links {
            let mut mine: Vec<&Pair> = g.pairs.iter().filter(|p| p.links.contains(link)).collect();
            mine.sort_by_key(|p| p.links.iter().all(|l| g.links.contains(l)));
            let Some(first) = mine.first() else { continue };
            let q = math_name(&first.point);
            for p in &mine[1..] {
                if p.sliding || p.point == first.point {
                    let (ko, kl) = (on(&p.point, &p.links[0]), on(&p.point, &p.links[1]));
                    let rel = two(&kl, &ko);
                    self.coincident(&ko);
                    self.coincident(&kl);
                    self.slide(&rel);
                    self.coriolis(&rel, &p.links[0], &mut ex);
                    eqs.push(format!("arrow(v)_({kl}) = arrow(v)_({ko}) + arrow(v)_({rel})"));
                    aeqs.push(format!(
                        "arrow(a)_({kl}) = arrow(a)_({ko}) + arrow(a)^k_({rel}) + arrow(a)^r_({rel})"
                    ));
                    continue;
                }
                let pm = math_name(&p.point);
                self.point(&q);
                self.point(&pm);
                let rel = two(&pm, &q);
                add(&mut self.v.rotation, &rel);
                add(&mut self.a.normal, &rel);
                add(&mut self.a.tangential, &rel);
                let omega = format!("omega_{}", link_no(link));
                let len = format!("l_({q} {pm})");
                add(&mut self.m.omegas, &omega);
                add(&mut self.m.lengths, &len);
                add(&mut self.m.normal, &rel);
                ex.mags.push(format!("a^n_({rel}) = {omega}^2 {len}"));
                eqs.push(format!("arrow(v)_({pm}) = arrow(v)_({q}) + arrow(v)_({rel})"));
                aeqs.push(format!(
                    "arrow(a)_({pm}) = arrow(a)_({q}) + arrow(a)^n_({rel}) + arrow(a)^tau_({rel})"
                ));
            }
        }
        if !eqs.is_empty() {
            self.v_lines.push(eqs.join(", quad "));
            self.a_lines.push(aeqs.join(", quad "));
        }
        if !ex.mags.is_empty() {
            self.m_lines.push(ex.mags.join(", quad "));
        }
    }
}

/// A point's math without a link index (`B_3` → `B`) for a length.
fn strip_link(k: &str) -> String {
    k.split('_').next().unwrap_or(k).to_string()
}

/// The equations of a mechanism: the input link's lines written by
/// `input` (`None` if it has none), then every Assur group's.
fn equations(cx: &Ctx, input: impl FnOnce(&mut Builder, &[Pair], &str) -> Option<()>) -> Option<Equations> {
    let pairs = read_pairs(cx);
    let groups = read_groups(cx, &pairs);
    if groups.is_empty() {
        return None;
    }
    let link = cx.s("/linkage/input/link")?.to_string();
    let still = not_turning(&pairs);
    let mut b = Builder {
        still: &still,
        v: Symbols::default(),
        a: Symbols::default(),
        m: Symbols::default(),
        v_lines: Vec::new(),
        a_lines: Vec::new(),
        m_lines: Vec::new(),
    };
    input(&mut b, &pairs, &link)?;
    for g in &groups {
        b.group(g);
    }
    Some(Equations {
        velocity: b.v_lines.join(" \\ "),
        acceleration: b.a_lines.join(" \\ "),
        magnitudes: b.m_lines.join(" \\ "),
        velocity_symbols: b.v,
        acceleration_symbols: b.a,
        magnitude_symbols: b.m,
    })
}

/// The equations of the crank-driven mechanism: the input link (its axis
/// `axis` on the frame, its other joints) turning at ω_1 (v_A = ω_1·l_OA,
/// a^n_AO = ω_1²·l_OA, a^τ_AO = ε_1·l_OA), then every Assur group.
pub(crate) fn crank_equations(cx: &Ctx, axis: &str) -> Option<Equations> {
    let eps = cx.opt("/linkage/input/epsilon").unwrap_or(0.0);
    equations(cx, |b, pairs, input| {
        // the input link's moving joints (A of OA; A and D of the engine's crank)
        let mut joints: Vec<String> = Vec::new();
        for p in pairs.iter().filter(|p| p.links.iter().any(|l| l == input) && p.point != axis) {
            add(&mut joints, &p.point);
        }
        if joints.is_empty() {
            return None;
        }
        let one = link_no(input);
        let omega = format!("omega_{one}");
        let am = math_name(axis);
        let (mut v, mut a, mut m) = (Vec::new(), Vec::new(), Vec::new());
        add(&mut b.v.omegas, &omega);
        add(&mut b.m.omegas, &omega);
        for j in &joints {
            let jm = math_name(j);
            let len = format!("l_({am} {jm})");
            let rel = two(&jm, &am);
            add(&mut b.v.points, &jm);
            add(&mut b.v.lengths, &len);
            add(&mut b.a.points, &jm);
            add(&mut b.a.normal, &rel);
            add(&mut b.m.normal, &rel);
            add(&mut b.m.lengths, &len);
            v.push(format!("v_({jm}) = {omega} {len}"));
            m.push(format!("a^n_({rel}) = {omega}^2 {len}"));
            if eps.abs() > 1e-12 {
                add(&mut b.a.tangential, &rel);
                add(&mut b.m.tangential, &rel);
                let e = format!("epsilon_{one}");
                add(&mut b.m.epsilons, &e);
                m.push(format!("a^tau_({rel}) = {e} {len}"));
                a.push(format!("arrow(a)_({jm}) = arrow(a)^n_({rel}) + arrow(a)^tau_({rel})"));
            } else {
                a.push(format!("arrow(a)_({jm}) = arrow(a)^n_({rel})"));
            }
        }
        b.v_lines.push(v.join(", quad "));
        b.a_lines.push(a.join(", quad "));
        b.m_lines.push(m.join(", quad "));
        Some(())
    })
}

/// The equations of a mechanism driven by a slider on a fixed guide
/// (ведущий ползун): the slider moves along its guide with the given speed
/// v and acceleration a, and so does each of its joints (a body that does
/// not turn: every point has the same velocity and acceleration,
/// Артоболевский 1988, § 13): v_B = v, a_B = a, no ω·l; then every Assur
/// group.
pub(crate) fn slider_equations(cx: &Ctx) -> Option<Equations> {
    let accel = cx.opt("/linkage/input/acceleration").unwrap_or(0.0);
    equations(cx, |b, pairs, input| {
        let mine = || pairs.iter().filter(|p| p.links.iter().any(|l| l == input));
        // the slider's joints with the driven links, else its guide's point
        let mut joints: Vec<String> = Vec::new();
        for p in mine().filter(|p| !p.sliding) {
            add(&mut joints, &p.point);
        }
        if joints.is_empty() {
            for p in mine() {
                add(&mut joints, &p.point);
            }
        }
        if joints.is_empty() {
            return None;
        }
        let (mut v, mut a) = (Vec::new(), Vec::new());
        add(&mut b.v.slider, "v");
        add(&mut b.a.slider, "a");
        let a_value = if accel.abs() > 1e-12 { "a" } else { "a = 0" };
        for j in &joints {
            let jm = math_name(j);
            b.point(&jm);
            v.push(format!("v_({jm}) = v"));
            a.push(format!("a_({jm}) = {a_value}"));
        }
        b.v_lines.push(v.join(", quad "));
        b.a_lines.push(a.join(", quad "));
        Some(())
    })
}

/// Symbols as math runs, `v_A, v_(B A)`: the subscripts after `prefix`
/// (none: the symbols whole, `omega_1`).
fn list(prefix: &str, syms: &[String]) -> String {
    syms.iter()
        .map(|s| {
            if prefix.is_empty() {
                format!("{MATH_OPEN}{s}{MATH_CLOSE}")
            } else {
                format!("{MATH_OPEN}{prefix}({s}){MATH_CLOSE}")
            }
        })
        .collect::<Vec<_>>()
        .join(", ")
}

/// Plain names as math runs (points `A, B`; links `1, 2`).
fn names(syms: &[String], strip: impl Fn(&str) -> String) -> String {
    syms.iter()
        .map(|s| format!("{MATH_OPEN}{}{MATH_CLOSE}", strip(s)))
        .collect::<Vec<_>>()
        .join(", ")
}

impl Equations {
    fn line(cx: &Ctx, entries: Vec<(String, &str, String)>) -> Result<Block, NoteError> {
        let mut parts = Vec::new();
        for (syms, key, arg) in entries {
            if syms.is_empty() {
                continue;
            }
            parts.push(format!("{syms} {}", cx.w(key)?.replace("{1}", &arg)));
        }
        Ok(Block::Paragraph(Text::plain(format!(
            "{} {}.",
            cx.w("eqw_where")?,
            parts.join("; ")
        ))))
    }

    /// The line under the velocity equations.
    pub fn where_velocity(&self, cx: &Ctx) -> Result<Block, NoteError> {
        let s = &self.velocity_symbols;
        Self::line(
            cx,
            vec![
                (list("v_", &s.points), "eqw_v_points", names(&s.points, str::to_string)),
                (list("v_", &s.coincident), "eqw_v_coincident", String::new()),
                (list("v_", &s.rotation), "eqw_v_rotation", String::new()),
                (list("v_", &s.sliding), "eqw_v_sliding", String::new()),
                (list("", &s.omegas), "eqw_omega_input", String::new()),
                (list("", &s.lengths), "eqw_lengths", String::new()),
                (list("", &s.slider), "eqw_v_slider", String::new()),
            ],
        )
    }

    /// The line under the acceleration equations.
    pub fn where_acceleration(&self, cx: &Ctx) -> Result<Block, NoteError> {
        let s = &self.acceleration_symbols;
        Self::line(
            cx,
            vec![
                (list("a_", &s.points), "eqw_a_points", names(&s.points, str::to_string)),
                (list("a_", &s.coincident), "eqw_a_coincident", String::new()),
                (list("a^n_", &s.normal), "eqw_a_normal", String::new()),
                (list("a^tau_", &s.tangential), "eqw_a_tangential", String::new()),
                (list("a^k_", &s.coriolis), "eqw_a_coriolis", String::new()),
                (list("a^r_", &s.relative), "eqw_a_relative", String::new()),
                (list("", &s.slider), "eqw_a_slider", String::new()),
            ],
        )
    }

    /// The line under the magnitudes of the normal and Coriolis accelerations.
    pub fn where_magnitudes(&self, cx: &Ctx) -> Result<Block, NoteError> {
        let s = &self.magnitude_symbols;
        let link = |o: &str| o.trim_start_matches("omega_").trim_start_matches("epsilon_").to_string();
        Self::line(
            cx,
            vec![
                (list("a^n_", &s.normal), "eqw_a_normal", String::new()),
                (list("a^tau_", &s.tangential), "eqw_a_tangential", String::new()),
                (list("a^k_", &s.coriolis), "eqw_a_coriolis", String::new()),
                (list("", &s.omegas), "eqw_omegas", names(&s.omegas, link)),
                (list("", &s.epsilons), "eqw_epsilon", names(&s.epsilons, link)),
                (list("", &s.lengths), "eqw_lengths", String::new()),
                (list("v_", &s.sliding), "eqw_v_sliding", String::new()),
            ],
        )
    }
}
