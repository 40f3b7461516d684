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
use crate::paper::{Slot, slot_mm, standard_scale};
use crate::project::{Language, SheetFormat};
use crate::svg::{Anchor, Canvas, Impulse, Series, Style, plot, plot_with_impulses};
use crate::words::word;

/// Put several whole SVG documents one under another in one page.
fn stack(docs: &[String], w: f64, h: f64) -> String {
    let mut body = String::new();
    for (i, d) in docs.iter().enumerate() {
        let inner = d.split_once("?>").map_or(d.as_str(), |x| x.1).trim();
        // nested documents in user units (the parent's viewBox is in mm)
        let inner = inner
            .replacen("<svg ", &format!("<svg x=\"0\" y=\"{}\" ", i as f64 * h), 1)
            .replacen(&format!("width=\"{w}mm\""), &format!("width=\"{w}\""), 1)
            .replacen(&format!("height=\"{h}mm\""), &format!("height=\"{h}\""), 1);
        body.push_str(&inner);
        body.push('\n');
    }
    format!(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}mm\" height=\"{th}mm\" viewBox=\"0 0 {w} {th}\">\n{body}</svg>\n",
        th = h * docs.len() as f64
    )
}

/// s, ds/dφ, d²s/dφ² over the cam angle (degrees; mm or degrees).
pub fn analogs(task: &CamTask) -> String {
    let osc = task.follower.oscillating();
    let k = if osc { 180.0 / std::f64::consts::PI } else { 1e3 };
    let u = if osc { "deg" } else { "mm" };
    // one closed turn with both sides of every jump, ending at 360° with the
    // last phase's value (no false spike at the wrap)
    let diag = task.program.diagram(720);
    let pts = |f: &dyn Fn(&Motion) -> f64| -> Vec<(f64, f64)> { diag.iter().map(|(phi, m)| (phi.to_degrees(), f(m))).collect() };
    let s = pts(&|m| m.s * k);
    let v = pts(&|m| m.v * k);
    let a = pts(&|m| m.a * k);
    let (w, h) = (200.0, 80.0);
    stack(
        &[
            plot(
                "Displacement s(φ)",
                "cam angle φ, deg",
                &format!("s, {u}"),
                &[Series {
                    name: "s",
                    points: &s,
                    color: "#1f4e9c",
                }],
                w,
                h,
            ),
            plot(
                "Velocity analog ds/dφ",
                "cam angle φ, deg",
                &format!("ds/dφ, {u}"),
                &[Series {
                    name: "ds/dφ",
                    points: &v,
                    color: "#2e7d32",
                }],
                w,
                h,
            ),
            plot(
                "Acceleration analog d²s/dφ²",
                "cam angle φ, deg",
                &format!("d²s/dφ², {u}"),
                &[Series {
                    name: "d²s/dφ²",
                    points: &a,
                    color: "#c62828",
                }],
                w,
                h,
            ),
        ],
        w,
        h,
    )
}

/// s, v, a, jerk over time for the cam's ω.
pub fn motion(task: &CamTask) -> String {
    let osc = task.follower.oscillating();
    let w = task.omega;
    let diag = task.program.diagram(720);
    let ms = |phi: f64| phi / w * 1e3;
    let pts = |f: &dyn Fn(&Motion) -> f64| -> Vec<(f64, f64)> { diag.iter().map(|(phi, m)| (ms(*phi), f(m))).collect() };
    let s = pts(&|m| m.s * if osc { 1.0 } else { 1e3 });
    let v = pts(&|m| m.v * w);
    let a = pts(&|m| m.a * w * w);
    let j = pts(&|m| m.j * w * w * w);
    let (su, vu, au, ju) = if osc {
        ("rad", "rad/s", "rad/s²", "rad/s³")
    } else {
        ("mm", "m/s", "m/s²", "m/s³")
    };
    // a jump of velocity is an impulse of acceleration (rigid impact), a jump
    // of acceleration an impulse of jerk (soft impact): marked as the course does
    let jumps = task.program.jumps();
    let impulses = |kind: JumpKind, scale: f64, unit: &str| -> Vec<Impulse> {
        jumps
            .iter()
            .filter(|x| x.kind == kind)
            .map(|x| Impulse {
                x: ms(x.phi),
                weight: x.size(),
                label: format!(
                    "{} = {:+.3} {unit}",
                    if kind == JumpKind::Velocity { "Δv" } else { "Δa" },
                    x.size() * scale
                ),
            })
            .collect()
    };
    let a_imp = impulses(JumpKind::Velocity, w, vu);
    let j_imp = impulses(JumpKind::Acceleration, w * w, au);
    let (pw, ph) = (200.0, 70.0);
    stack(
        &[
            plot(
                "Follower displacement",
                "time t, ms",
                &format!("s, {su}"),
                &[Series {
                    name: "s",
                    points: &s,
                    color: "#1f4e9c",
                }],
                pw,
                ph,
            ),
            plot(
                "Follower velocity",
                "time t, ms",
                &format!("v, {vu}"),
                &[Series {
                    name: "v",
                    points: &v,
                    color: "#2e7d32",
                }],
                pw,
                ph,
            ),
            plot_with_impulses(
                "Follower acceleration (arrows: impulses where the velocity jumps)",
                "time t, ms",
                &format!("a, {au}"),
                &[Series {
                    name: "a",
                    points: &a,
                    color: "#c62828",
                }],
                &a_imp,
                pw,
                ph,
            ),
            plot_with_impulses(
                "Follower jerk (arrows: impulses where the acceleration jumps)",
                "time t, ms",
                &format!("j, {ju}"),
                &[Series {
                    name: "j",
                    points: &j,
                    color: "#6a1b9a",
                }],
                &j_imp,
                pw,
                ph,
            ),
        ],
        pw,
        ph,
    )
}

/// Pressure angle over the cycle with the limits.
pub fn pressure(task: &CamTask, d: &CamDesign) -> String {
    let p = &d.profile;
    let th: Vec<(f64, f64)> = (0..p.phi.len())
        .map(|i| (p.phi[i].to_degrees(), p.pressure[i].to_degrees()))
        .chain([(360.0, p.pressure[0].to_degrees())])
        .collect();
    let lr = [(0.0, task.limits.rise.to_degrees()), (360.0, task.limits.rise.to_degrees())];
    let lt = [(0.0, task.limits.ret.to_degrees()), (360.0, task.limits.ret.to_degrees())];
    let mut series = vec![Series {
        name: "ϑ",
        points: &th,
        color: "#1f4e9c",
    }];
    if !d.mechanism.is_flat() {
        series.push(Series {
            name: "allowed, rise",
            points: &lr,
            color: "#c62828",
        });
        series.push(Series {
            name: "allowed, return",
            points: &lt,
            color: "#ef6c00",
        });
    }
    plot("Pressure angle over the cycle", "cam angle φ, deg", "ϑ, deg", &series, 200.0, 90.0)
}

/// The s–ds/dφ diagram (translating roller) or its oscillating counterpart:
/// the curve of points K, the admissible region of the cam centre, the
/// chosen centre O and the lowest roller centre B₀. Flat faces get Geronimus'
/// s(d²s/dφ²) diagram instead. Coordinates in mm.
pub fn sizing_diagram(task: &CamTask, d: &CamDesign) -> String {
    let sigma = task.rotation.sign();
    let prog = &task.program;
    let n = d.profile.phi.len();
    let mut c = Canvas::new(200.0, 200.0);
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
                "s–ds/dφ diagram: admissible region of the cam centre",
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
                "Points K (arm ψ′ laid off along the arm) and the admissible region of the cam centre",
            )
        }
        _ => {
            // Geronimus: s against d²s/dφ², r₀ read on the s axis
            let curve = (0..n).map(|i| (d.profile.motion[i].a * 1e3, d.profile.motion[i].s * 1e3)).collect();
            (
                curve,
                None,
                (0.0, -d.r0 * 1e3),
                (0.0, 0.0),
                "Geronimus' diagram s(d²s/dφ²): base circle from convexity",
            )
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
    c.fit(world, (10.0, 10.0, 180.0, 170.0));
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
        c.text_colored(
            (0.0, m),
            &format!("  ρmin = {:.1} mm", d.rho_min_convex * 1e3),
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
    c.text_paper((100.0, 8.0), title, 3.5, Anchor::Middle, "#000");
    c.text_paper((100.0, 195.0), &format!("r0 = {:.3} mm", d.r0 * 1e3), 3.5, Anchor::Middle, "#000");
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
pub fn cam(task: &CamTask, d: &CamDesign, lang: Language, sheet: SheetFormat) -> String {
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
    let mut ly = 8.0;
    lab.put_left((lx, ly), &format!("{} {}", word(lang, "common.scale"), scale.text), H_LABEL, "#000");
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
        lab.put_left((lx + 12.0, ly), &t, 3.0, "#000");
    }
    finish(c.finish(), &lab, Some(scale.text))
}
