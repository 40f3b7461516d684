//! The cam drawings (SVG): kinematic diagrams over the cam angle and over
//! time, the s–ds/dφ diagram with the admissible region of the cam centre and
//! the chosen centre, and the cam with its follower in the starting position.

use tmm_cams::design::{CamDesign, CamTask};
use tmm_cams::halfplane::Region;
use tmm_cams::mechanism::Mechanism;
use tmm_cams::sizing;
use tmm_geom::Vec2;

use tmm_cams::program::{JumpKind, Motion, PhaseKind};

use crate::labels::{DASH_DOT, H_LABEL, Placer, finish, num};
use crate::paper::{Slot, round_mu, slot_mm, standard_scale};
use crate::picture::Picture;
use crate::project::{Language, SheetFormat};
use crate::svg::{Anchor, Canvas, Style};

use super::diagrams::{self, Arrow, Level, Panel};
use crate::words::word;

/// The units of the follower's quantities in `lang`: (s, ds/dφ and
/// d²s/dφ², v, a, j) — mm and m/s… for a translating follower, degrees and
/// rad/s… for an oscillating one.
fn units(task: &CamTask, lang: Language) -> [String; 5] {
    let u = |k: &str| word(lang, k).to_string();
    if task.follower.oscillating() {
        [
            u("cam.unit_deg"),
            u("cam.unit_deg"),
            u("cam.unit_radps"),
            u("cam.unit_radps2"),
            u("cam.unit_radps3"),
        ]
    } else {
        [u("cam.mm"), u("cam.mm"), u("cam.unit_mps"), u("cam.unit_mps2"), u("cam.unit_mps3")]
    }
}

/// s, ds/dφ, d²s/dφ² over the cam angle 0 … 360° (mm, or degrees for an
/// oscillating follower), one `Slot::Diagram` panel each, words in `lang`.
pub fn analogs(task: &CamTask, lang: Language, sheet: SheetFormat) -> Picture {
    let osc = task.follower.oscillating();
    let k = if osc { 180.0 / std::f64::consts::PI } else { 1e3 };
    let [su, au, ..] = units(task, lang);
    // one closed turn with both sides of every jump, ending at 360° with the
    // last phase's value (no false spike at the wrap)
    let diag = task.program.diagram(720);
    let pts = |f: &dyn Fn(&Motion) -> f64| -> Vec<(f64, f64)> { diag.iter().map(|(phi, m)| (phi.to_degrees(), f(m))).collect() };
    let panel = |key: &str, sym: &str, mu_sym: &str, unit: &str, pts: Vec<(f64, f64)>| Panel {
        title: word(lang, key).to_string(),
        sym: sym.to_string(),
        mu_sym: mu_sym.to_string(),
        unit: unit.to_string(),
        pts,
        arrows: Vec::new(),
        levels: Vec::new(),
    };
    // a rocker turns by ψ: its own symbols and titles (коромысло)
    let panels = if osc {
        [
            panel("cam.analog_psi", "ψ", "ψ", &su, pts(&|m| m.s * k)),
            panel("cam.analog_dpsi", "dψ/dφ", "{dψ/dφ}", &au, pts(&|m| m.v * k)),
            panel("cam.analog_ddpsi", "d²ψ/dφ²", "{d²ψ/dφ²}", &au, pts(&|m| m.a * k)),
        ]
    } else {
        [
            panel("cam.analog_s", "s", "s", &su, pts(&|m| m.s * k)),
            panel("cam.analog_ds", "ds/dφ", "{ds/dφ}", &au, pts(&|m| m.v * k)),
            panel("cam.analog_dds", "d²s/dφ²", "{d²s/dφ²}", &au, pts(&|m| m.a * k)),
        ]
    };
    let name = crate::sheets::caption("cam/cam-analogs.svg", lang);
    diagrams::draw(task, &panels, Some(&name), lang, sheet, None)
}

/// s, v, a and the jerk j for the cam's ω over the cam angle 0 … 360° (the
/// time scale μ_t written beside μ_φ), the impacts as arrows: a jump of
/// velocity is an impulse of acceleration (rigid impact), a jump of
/// acceleration an impulse of jerk (soft impact), as the course marks them.
pub fn motion(task: &CamTask, lang: Language, sheet: SheetFormat) -> Picture {
    let osc = task.follower.oscillating();
    let w = task.omega;
    let diag = task.program.diagram(720);
    let pts = |f: &dyn Fn(&Motion) -> f64| -> Vec<(f64, f64)> { diag.iter().map(|(phi, m)| (phi.to_degrees(), f(m))).collect() };
    let [su, _, vu, au, ju] = units(task, lang);
    let s = pts(&|m| m.s * if osc { 180.0 / std::f64::consts::PI } else { 1e3 });
    let v = pts(&|m| m.v * w);
    let a = pts(&|m| m.a * w * w);
    let j = pts(&|m| m.j * w * w * w);
    let jumps = task.program.jumps();
    // (title key, symbol, the symbol as μ's subscript) of s, v, a, j: a
    // rocker turns by ψ at ω with ε, a translating follower moves by s at v
    // with a (толкатель, коромысло)
    let names: [(&str, &str, &str); 4] = if osc {
        [
            ("cam.motion_psi", "ψ", "ψ"),
            ("cam.motion_omega", "ω", "ω"),
            ("cam.motion_eps", "ε", "ε"),
            ("cam.motion_jerk_osc", "j", "j"),
        ]
    } else {
        [
            ("cam.motion_s", "s", "s"),
            ("cam.motion_v", "v", "v"),
            ("cam.motion_a", "a", "a"),
            ("cam.motion_j", "j", "j"),
        ]
    };
    let arrows = |kind: JumpKind, scale: f64, unit: &str| -> Vec<Arrow> {
        // a jump of v (ω) is drawn on a (ε), a jump of a (ε) on j
        let of = if kind == JumpKind::Velocity { names[1].1 } else { names[2].1 };
        jumps
            .iter()
            .filter(|x| x.kind == kind)
            .map(|x| Arrow {
                phi_deg: x.phi.to_degrees(),
                sign: x.size(),
                label: format!("Δ{of} = {} {unit}", signed3(lang, x.size() * scale)),
            })
            .collect()
    };
    let panel = |(key, sym, mu_sym): (&str, &str, &str), unit: &str, pts: Vec<(f64, f64)>, arrows: Vec<Arrow>| Panel {
        title: word(lang, key).to_string(),
        sym: sym.to_string(),
        mu_sym: mu_sym.to_string(),
        unit: unit.to_string(),
        pts,
        arrows,
        levels: Vec::new(),
    };
    let name = crate::sheets::caption("cam/cam-motion.svg", lang);
    diagrams::draw(
        task,
        &[
            panel(names[0], &su, s, Vec::new()),
            panel(names[1], &vu, v, Vec::new()),
            panel(names[2], &au, a, arrows(JumpKind::Velocity, w, &vu)),
            panel(names[3], &ju, j, arrows(JumpKind::Acceleration, w * w, &au)),
        ],
        Some(&name),
        lang,
        sheet,
        Some(w),
    )
}

/// A signed value with three decimals and the sign written (`+2,600`).
fn signed3(lang: Language, v: f64) -> String {
    let t = num(lang, v.abs(), 3);
    if v < 0.0 { format!("−{t}") } else { format!("+{t}") }
}

/// The pressure angle ϑ over the cam angle 0 … 360° (degrees) with the
/// allowed values on the rise and the return as dashed levels.
pub fn pressure(task: &CamTask, d: &CamDesign, lang: Language, sheet: SheetFormat) -> Picture {
    let p = &d.profile;
    let th: Vec<(f64, f64)> = (0..p.phi.len())
        .map(|i| (p.phi[i].to_degrees(), p.pressure[i].to_degrees()))
        .chain([(360.0, p.pressure[0].to_degrees())])
        .collect();
    let deg = word(lang, "cam.unit_deg");
    let mut levels = Vec::new();
    if !d.mechanism.is_flat() {
        for (v, key) in [(task.limits.rise, "cam.allowed_rise"), (task.limits.ret, "cam.allowed_return")] {
            levels.push(Level {
                value: v.to_degrees(),
                label: format!("{} = {}{deg}", word(lang, key), num(lang, v.to_degrees(), 0)),
            });
        }
    }
    let panel = Panel {
        title: word(lang, "cam.pressure_title").to_string(),
        sym: "ϑ".to_string(),
        mu_sym: "ϑ".to_string(),
        unit: deg.to_string(),
        pts: th,
        arrows: Vec::new(),
        levels,
    };
    diagrams::draw(task, &[panel], None, lang, sheet, None)
}

/// The s–ds/dφ diagram (translating roller) or its oscillating counterpart:
/// the curve of points K, the admissible region of the cam centre, the
/// chosen centre O and the lowest roller centre B₀. Flat faces get Geronimus'
/// s(d²s/dφ²) diagram instead. Coordinates in mm.
pub fn sizing_diagram(task: &CamTask, d: &CamDesign, lang: Language, sheet: SheetFormat) -> Picture {
    let sigma = task.rotation.sign();
    let prog = &task.program;
    let n = d.profile.phi.len();
    let (pw, ph) = slot_mm(Slot::Plan, sheet);
    let mut c = Canvas::new(pw, ph);
    let region_style = Style {
        width: 0.2,
        color: "#2e7d32",
        dash: None,
        fill: Some("#c8e6c9"),
    };
    type Pt = (f64, f64);
    let (curve, region, centre, b0, title): (Vec<Pt>, Option<Region>, Pt, Pt, &str) = match d.mechanism {
        Mechanism::TranslatingRoller { e, s0, .. } => {
            let curve = (0..n)
                .map(|i| (-sigma * d.profile.motion[i].v * 1e3, d.profile.motion[i].s * 1e3))
                .collect();
            let size = 4.0 * d.r0.max(prog.stroke());
            let region = sizing::translating_region(prog, sigma, task.limits, size);
            let region = Region::from_vertices(region.vertices.iter().map(|v| *v * 1e3).collect());
            (
                curve,
                Some(region),
                (-e * 1e3, -s0 * 1e3),
                (0.0, 0.0),
                word(lang, "cam.sizing_translating"),
            )
        }
        Mechanism::OscillatingRoller { pivot, arm, kappa, .. } => {
            // frame of the construction: pivot at the origin, B₀ = (l, 0)
            let curve = (0..n)
                .map(|i| {
                    let m = d.profile.motion[i];
                    let psi = kappa * m.s;
                    let u = Vec2::new(psi.cos(), psi.sin());
                    let k = u * arm - u * (sigma * kappa * arm * m.v);
                    (k.x * 1e3, k.y * 1e3)
                })
                .collect();
            let region = sizing::oscillating_region(prog, sigma, task.limits, arm, kappa, 360);
            let region = Region::from_vertices(region.vertices.iter().map(|v| *v * 1e3).collect());
            (
                curve,
                Some(region),
                (-pivot.x * 1e3, -pivot.y * 1e3),
                (arm * 1e3, 0.0),
                word(lang, "cam.sizing_oscillating"),
            )
        }
        _ => {
            // Geronimus: s against d²s/dφ², r₀ read on the s axis
            let curve = (0..n).map(|i| (d.profile.motion[i].a * 1e3, d.profile.motion[i].s * 1e3)).collect();
            (curve, None, (0.0, -d.r0 * 1e3), (0.0, 0.0), word(lang, "cam.sizing_flat"))
        }
    };
    // world box: the curve, the centre, B₀ (and the pivot at the origin of an
    // oscillating follower's construction), with a margin
    let (mut x0, mut x1, mut y0, mut y1) = (centre.0.min(b0.0), centre.0.max(b0.0), centre.1.min(b0.1), centre.1.max(b0.1));
    if let Mechanism::OscillatingRoller { .. } = d.mechanism {
        (x0, x1, y0, y1) = (x0.min(0.0), x1.max(0.0), y0.min(0.0), y1.max(0.0));
    }
    for &(x, y) in &curve {
        x0 = x0.min(x);
        x1 = x1.max(x);
        y0 = y0.min(y);
        y1 = y1.max(y);
    }
    let span = (x1 - x0).max(y1 - y0).max(1e-9);
    let pad = 0.15 * span;
    // show the region below the centre too
    let extra = if region.is_some() { 0.35 * span } else { 0.0 };
    let world = (x0 - pad, x1 + pad, y0 - pad - extra, y1 + pad);
    // one round μ for both axes (mm of the diagram per mm of paper)
    let (top, margin) = (20.0, 8.0);
    let mu = round_mu(((world.1 - world.0) / (pw - 2.0 * margin)).max((world.3 - world.2) / (ph - top - margin)));
    c.set_transform(
        1.0 / mu,
        (
            0.5 * pw - 0.5 * (world.0 + world.1) / mu,
            0.5 * (ph - top) - 0.5 * (world.2 + world.3) / mu,
        ),
    );
    c.root_attr("data-mu", &format!("{mu}"));
    if let Some(mut r) = region {
        // the boundary rays of the region, across the view (translating follower:
        // at most four lines, each tangent to the diagram at the allowed angle)
        if matches!(d.mechanism, Mechanism::TranslatingRoller { .. }) {
            let m = r.vertices.len();
            let big = r.vertices.iter().fold(0.0f64, |a, v| a.max(v.x.abs()).max(v.y.abs()));
            for i in 0..m {
                let (a, b) = (r.vertices[i], r.vertices[(i + 1) % m]);
                let on_square = |v: Vec2| v.x.abs() >= 0.98 * big || v.y.abs() >= 0.98 * big;
                if (on_square(a) && on_square(b)) || (b - a).hypot() < 1e-12 {
                    continue;
                }
                let dir = (b - a) * (1.0 / (b - a).hypot());
                let l = 3.0 * span;
                if let Some((p, q)) = clip_line(world, a - dir * l, a + dir * l) {
                    c.line((p.x, p.y), (q.x, q.y), Style::DASHED.colored("#2e7d32"));
                }
            }
        }
        // clip the region to the view
        for (nx, ny, cc) in [
            (1.0, 0.0, world.0),
            (-1.0, 0.0, -world.1),
            (0.0, 1.0, world.2),
            (0.0, -1.0, -world.3),
        ] {
            r.clip(tmm_cams::halfplane::HalfPlane {
                n: Vec2::new(nx, ny),
                c: cc,
            });
        }
        let pts: Vec<(f64, f64)> = r.vertices.iter().map(|v| (v.x, v.y)).collect();
        c.polygon(&pts, region_style);
    }
    if let Mechanism::OscillatingRoller { arm, kappa, .. } = d.mechanism {
        // the pivot A, the arm at the start and the arc of the roller centres
        let l = arm * 1e3;
        let h = kappa * prog.stroke();
        let (a0, a1) = if h > 0.0 { (0.0, h) } else { (h, 0.0) };
        c.arc((0.0, 0.0), l, a0 - 0.1, a1 + 0.1, Style::AXIS);
        c.line((0.0, 0.0), b0, Style::THIN);
        c.fixed_pivot((0.0, 0.0), 1.0);
        c.text((0.0, 0.0), "  A", 3.5, Anchor::Start);
    } else {
        c.line((world.0, 0.0), (world.1, 0.0), Style::AXIS);
        c.line((b0.0, world.2), (b0.0, world.3), Style::AXIS);
    }
    if let Mechanism::TranslatingFlat { r0, .. } = d.mechanism {
        // Geronimus: the 45° line s + s″ = min(s + s″) tangent to the diagram;
        // it meets the s axis at that minimum, and O lies ρ_min below it
        let m = (d.rho_min_convex - r0) * 1e3;
        if let Some((p, q)) = clip_line(
            world,
            Vec2::new(-10.0 * span, m + 10.0 * span),
            Vec2::new(10.0 * span, m - 10.0 * span),
        ) {
            c.line((p.x, p.y), (q.x, q.y), Style::DASHED.colored("#2e7d32"));
        }
        let q = c.to_paper(0.0, m);
        c.rich_paper(
            q,
            &format!("  ρ_min = {} {}", num(lang, d.rho_min_convex * 1e3, 1), word(lang, "cam.mm")),
            3.0,
            Anchor::Start,
            "#2e7d32",
        );
    }
    c.polyline(&curve, Style::THICK.widened(0.5).colored("#1f4e9c"));
    c.line(b0, centre, Style::THIN.colored("#c62828"));
    c.dot(centre, 1.0, "#c62828");
    c.text_colored((centre.0, centre.1), "  O", 3.5, Anchor::Start, "#c62828");
    c.dot(b0, 0.8, "#000000");
    c.text((b0.0, b0.1), "  B₀", 3.5, Anchor::Start);
    c.title((0.5 * pw, 7.0), title, H_LABEL + 1.5, Anchor::Middle);
    c.rich_paper(
        (0.5 * pw, 13.5),
        &format!(
            "μ_s = {} {},   r_0 = {} {}",
            crate::svg::mu_text(mu * 1e-3, lang),
            word(lang, "cam.m_per_mm"),
            num(lang, d.r0 * 1e3, 2),
            word(lang, "cam.mm")
        ),
        3.0,
        Anchor::Middle,
        "#000",
    );
    c.finish()
}

/// The part of the segment `a`–`b` inside the box `(xmin, xmax, ymin, ymax)`
/// (Liang–Barsky clipping).
fn clip_line(b: (f64, f64, f64, f64), p: Vec2, q: Vec2) -> Option<(Vec2, Vec2)> {
    let d = q - p;
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (pk, qk) in [(-d.x, p.x - b.0), (d.x, b.1 - p.x), (-d.y, p.y - b.2), (d.y, b.3 - p.y)] {
        if pk == 0.0 {
            if qk < 0.0 {
                return None;
            }
        } else {
            let r = qk / pk;
            if pk < 0.0 {
                t0 = t0.max(r);
            } else {
                t1 = t1.min(r);
            }
        }
    }
    (t0 < t1).then(|| (p + d * t0, p + d * t1))
}

/// The cam (working and theoretical profiles, base circles) with the
/// follower in its lowest position (φ = 0), made for the Scheme slot of
/// `sheet` at a GOST 2.302 scale, words in `lang`: the direction of rotation
/// ω_1 as an arc arrow, the rays dividing the phases at the cam angles of the
/// task (turned against the rotation: the profile meets the follower at
/// θ0 − σ·φ), the phase angles, and a legend of the circles and profiles.
pub fn cam(task: &CamTask, d: &CamDesign, lang: Language, sheet: SheetFormat) -> Picture {
    let p = &d.profile;
    let work: Vec<(f64, f64)> = p.working.iter().map(|v| (v.x * 1e3, v.y * 1e3)).collect();
    let pitch: Vec<(f64, f64)> = p.pitch.iter().map(|v| (v.x * 1e3, v.y * 1e3)).collect();
    let mut pts = work.clone();
    pts.extend(pitch.iter().copied());
    let mut extra: Vec<(f64, f64)> = Vec::new();
    let r0 = d.r0 * 1e3;
    match d.mechanism {
        Mechanism::TranslatingRoller { e, s0, roller } => {
            extra.push((e * 1e3, (s0 + 2.0 * roller) * 1e3 + 2.5 * task.program.stroke() * 1e3));
        }
        Mechanism::TranslatingFlat { e, r0: b } => {
            let hw = d.face.map_or(0.0, |f| f.width / 2.0);
            extra.push(((e - hw) * 1e3, b * 1e3));
            extra.push(((e + hw) * 1e3, b * 1e3 + 2.5 * task.program.stroke() * 1e3));
        }
        _ => {
            if let Some(a) = d.mechanism.pivot() {
                extra.push((a.x * 1e3, a.y * 1e3));
            }
        }
    }
    pts.extend(extra.iter().copied());
    let (mut x0, mut x1, mut y0, mut y1) = (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY);
    for &(x, y) in &pts {
        x0 = x0.min(x);
        x1 = x1.max(x);
        y0 = y0.min(y);
        y1 = y1.max(y);
    }
    // the rays reach beyond the profile
    let r_ray = 1.12 * pitch.iter().chain(work.iter()).fold(0.0_f64, |m, q| m.max(q.0.hypot(q.1)));
    for q in [(r_ray, r_ray), (-r_ray, -r_ray)] {
        x0 = x0.min(q.0);
        x1 = x1.max(q.0);
        y0 = y0.min(q.1);
        y1 = y1.max(q.1);
    }
    let (pw, ph) = slot_mm(Slot::Scheme, sheet);
    let legend_w = 0.3 * pw;
    let (aw, ah) = (pw - legend_w - 8.0, ph - 16.0);
    let scale = standard_scale((x1 - x0).max(1e-9), aw - 10.0)
        .zip(standard_scale((y1 - y0).max(1e-9), ah - 10.0))
        .map(|(a, b)| if a.factor < b.factor { a } else { b })
        .unwrap_or(crate::paper::Scale { factor: 1.0, text: "1:1" });
    let sf = scale.factor;
    let mut c = Canvas::new(pw, ph);
    c.set_transform(sf, (4.0 + 0.5 * aw - sf * 0.5 * (x0 + x1), 4.0 + 0.5 * ah - sf * 0.5 * (y0 + y1)));
    let mut lab = Placer::new(pw, ph);
    let sigma = task.rotation.sign();
    c.polyline(&[(x0, 0.0), (x1, 0.0)], DASH_DOT);
    c.polyline(&[(0.0, y0), (0.0, y1)], DASH_DOT);
    // the phases: rays from O at the boundaries, the angles between them
    let theta0 = p.pitch.first().map_or(std::f64::consts::FRAC_PI_2, |q| q.y.atan2(q.x));
    let phases = task.program.phases();
    let mut bounds = vec![0.0];
    for (i, ph_) in phases.iter().enumerate() {
        bounds.push(task.program.start(i) + ph_.angle);
    }
    c.begin_group("phase-rays");
    for &b in &bounds[..bounds.len().saturating_sub(1)] {
        let th = theta0 - sigma * b;
        c.line((0.0, 0.0), (r_ray * th.cos(), r_ray * th.sin()), Style::THIN);
    }
    c.end_group();
    c.begin_group("phase-angles");
    for (i, ph_) in phases.iter().enumerate() {
        let (a0, a1) = (theta0 - sigma * bounds[i], theta0 - sigma * bounds[i + 1]);
        let r_arc = r_ray * (0.93 - 0.05 * (i % 2) as f64);
        c.arc((0.0, 0.0), r_arc, a0.min(a1), a0.max(a1), Style::THIN);
        let key = match ph_.kind {
            PhaseKind::Rise => "cam.phase_rise",
            PhaseKind::Return => "cam.phase_return",
            PhaseKind::Dwell if task.program.level_before(i) > 0.5 * task.program.stroke() => "cam.phase_far",
            PhaseKind::Dwell => "cam.phase_near",
        };
        let t = format!("{} = {}°", word(lang, key), num(lang, ph_.angle.to_degrees(), 1));
        let am = 0.5 * (a0 + a1);
        let cand: Vec<(f64, f64)> = (0..10)
            .map(|k| {
                let r = r_ray * (1.0 + 0.03 * k as f64);
                let q = c.to_paper(r * am.cos(), r * am.sin());
                let w = crate::labels::CHAR_WIDTH * H_LABEL * crate::labels::plain(&t).chars().count() as f64;
                (q.0 + 0.5 * w * am.cos(), q.1 - 0.7 * H_LABEL * am.sin())
            })
            .collect();
        lab.place(&cand, &t, H_LABEL, "#000");
    }
    c.end_group();
    c.polygon(&pitch, DASH_DOT.colored("#1f4e9c"));
    c.polygon(&work, Style::THICK.filled("#eeeeee"));
    c.circle((0.0, 0.0), r0, Style::DASHED);
    if d.rb > 0.0 && (d.rb - d.r0).abs() > 1e-12 {
        c.circle((0.0, 0.0), d.rb * 1e3, Style::DASHED.colored("#777777"));
    }
    // the direction of rotation: an arc arrow ω_1 around O
    c.begin_group("rotation");
    let r_w = 0.45 * r0.max(1e-9);
    let (b0, b1) = (theta0 + 0.6, theta0 + 0.6 + sigma * 1.4);
    c.arc((0.0, 0.0), r_w, b0.min(b1), b0.max(b1), Style::THIN.widened(0.35));
    let tip = (r_w * b1.cos(), r_w * b1.sin());
    let tang = (-sigma * b1.sin(), sigma * b1.cos());
    let tail = (tip.0 - tang.0 * 3.0 / sf, tip.1 - tang.1 * 3.0 / sf);
    c.arrow(tail, tip, Style::THIN.widened(0.35), 3.0);
    let qm = c.to_paper(r_w * (0.5 * (b0 + b1)).cos(), r_w * (0.5 * (b0 + b1)).sin());
    lab.place(&Placer::around(qm, "ω_1", H_LABEL, 1.0), "ω_1", H_LABEL, "#000");
    c.end_group();
    c.fixed_pivot((0.0, 0.0), 1.2);
    let qo = c.to_paper(0.0, 0.0);
    lab.reserve(crate::labels::label_box(qo, 3, 3.0));
    lab.place(&Placer::around(qo, "O", H_LABEL, 2.0), "O", H_LABEL, "#000");
    let follower = Style::THICK.colored("#1f4e9c");
    match d.mechanism {
        Mechanism::TranslatingRoller { e, s0, roller } => {
            let (x, y) = (e * 1e3, s0 * 1e3);
            let top = y + roller * 1e3 + 2.5 * task.program.stroke() * 1e3;
            if e != 0.0 {
                c.circle((0.0, 0.0), e.abs() * 1e3, Style::DASHED.colored("#999999"));
            }
            c.line((x, y), (x, top), follower);
            if roller > 0.0 {
                c.circle((x, y), roller * 1e3, follower);
            }
            c.joint((x, y), 0.8);
            let q = c.to_paper(x, y);
            lab.place(&Placer::around(q, "B_0", H_LABEL, 1.0), "B_0", H_LABEL, "#000");
        }
        Mechanism::TranslatingFlat { e, r0: b } => {
            let hw = d.face.map_or(0.0, |f| f.width / 2.0) * 1e3;
            let (x, y) = (e * 1e3, b * 1e3);
            c.line((x - hw, y), (x + hw, y), follower);
            c.line((x, y), (x, y + 2.5 * task.program.stroke() * 1e3), follower);
        }
        Mechanism::OscillatingRoller {
            pivot, arm, psi0, roller, ..
        } => {
            let a = (pivot.x * 1e3, pivot.y * 1e3);
            let b = pivot + Vec2::new(psi0.cos(), psi0.sin()) * arm;
            let b = (b.x * 1e3, b.y * 1e3);
            c.line(a, b, follower);
            if roller > 0.0 {
                c.circle(b, roller * 1e3, follower);
            }
            c.fixed_pivot(a, 1.2);
            let q = c.to_paper(a.0, a.1);
            lab.place(&Placer::around(q, "A", H_LABEL, 2.0), "A", H_LABEL, "#000");
            c.joint(b, 0.8);
        }
        Mechanism::OscillatingFlat { a, delta0 } => {
            let len = d.face.map_or(0.0, |f| f.contact_max + task.face_margin);
            let u = Vec2::new(-delta0.cos(), -delta0.sin());
            let end = Vec2::new(a, 0.0) + u * len;
            c.line((a * 1e3, 0.0), (end.x * 1e3, end.y * 1e3), follower);
            c.fixed_pivot((a * 1e3, 0.0), 1.2);
            let q = c.to_paper(a * 1e3, 0.0);
            lab.place(&Placer::around(q, "A", H_LABEL, 2.0), "A", H_LABEL, "#000");
        }
    }
    // the legend and the sizes on the right
    let lx = pw - legend_w;
    // the drawing's name heads the legend's column (the note leaves it to
    // the figure's caption)
    lab.put_title(
        (0.5 * (lx + pw), 8.0),
        &crate::sheets::caption("cam/cam.svg", lang),
        crate::labels::H_HEAD,
    );
    let mut ly = 16.0;
    lab.put_left(
        (lx, ly),
        &format!("{} {}", word(lang, "common.scale"), crate::svg::scale_text(scale.text, lang)),
        H_LABEL,
        "#000",
    );
    let mm = word(lang, "cam.mm");
    let mut rows: Vec<(Option<Style>, String)> = vec![
        (Some(Style::THICK), word(lang, "cam.legend_working").to_string()),
        (Some(DASH_DOT.colored("#1f4e9c")), word(lang, "cam.legend_pitch").to_string()),
        (Some(Style::DASHED), word(lang, "cam.legend_base").to_string()),
        (None, format!("r_0 = {} {mm}", num(lang, d.r0 * 1e3, 2))),
    ];
    if d.rb > 0.0 && (d.rb - d.r0).abs() > 1e-12 {
        rows.push((
            Some(Style::DASHED.colored("#777777")),
            word(lang, "cam.legend_working_base").to_string(),
        ));
        rows.push((None, format!("r_b = {} {mm}", num(lang, d.rb * 1e3, 2))));
    }
    rows.push((Some(Style::THIN), word(lang, "cam.legend_rays").to_string()));
    if d.roller > 0.0 {
        rows.push((
            None,
            format!("{}: r_r = {} {mm}", word(lang, "cam.roller"), num(lang, d.roller * 1e3, 2)),
        ));
    }
    rows.push((None, format!("ρ_min = {} {mm}", num(lang, d.rho_min * 1e3, 2))));
    for (st, t) in rows {
        ly += 6.0;
        if let Some(st) = st {
            c.line_paper((lx, ly), (lx + 10.0, ly), st);
        }
        // broken into lines that stay on the paper at the printed size (the
        // labels' boxes are CHAR_WIDTH = 0.62 of it a letter, the
        // wrapping's 0.6: 4 % narrower room)
        let lines = crate::labels::wrap_text(&t, 3.0, 0.96 * (pw - lx - 12.0 - 0.6));
        for (i, l) in lines.iter().enumerate() {
            if i > 0 {
                ly += 1.25 * crate::picture::em(3.0);
            }
            lab.put_left((lx + 12.0, ly), l, 3.0, "#000");
        }
    }
    finish(c.finish(), &lab, Some(scale.text))
}
