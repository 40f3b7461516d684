//! Picking the shift coefficients on the blocking contour (выбор
//! коэффициентов смещения по блокирующему контуру): where the contour's
//! axes lie on its drawing, so that a click becomes (x1, x2), and the pair
//! recomputed with the picked (x1, x2) — the same `[gear]` section run with
//! `x1`, `x2` written into the task, so the numbers, checks and drawings are
//! the CLI's for that task.

use serde_json::{Value, json};
use tmm_gears::Pair;
use tmm_gears::contour::{ContourOptions, blocking_contour, with_shifts};
use tmm_report::gear::contour_plot::plot_canvas;
use tmm_report::gear::input::Raw;
use tmm_report::{Error, TaskSource};

use crate::page::Page;
use crate::reply;

/// The linear map from (x1, x2) to the drawing's coordinates (mm, y down):
/// `svg = origin + scale · (x1, −x2)`.
#[derive(Debug, Clone, PartialEq)]
pub struct ContourAxes {
    /// The x1 range of the contour.
    pub x1: (f64, f64),
    /// The x2 range of the contour.
    pub x2: (f64, f64),
    /// The drawing point of (0, 0), mm.
    pub origin: (f64, f64),
    /// mm per unit of x.
    pub scale: f64,
    /// Nodes per side of the contour's grid.
    pub n: usize,
    /// `feasible[j * n + i]`: the node (x1_i, x2_j) lies inside the hard
    /// blocking contour (no undercut, no interference, no pointed tip,
    /// εα ≥ 1).
    pub feasible: Vec<bool>,
    /// `passes[j * n + i]`: every check of the task passes at the node
    /// (εα and sa at least the task's limits, no undercut, no interference).
    pub passes: Vec<bool>,
}

impl ContourAxes {
    /// (x1, x2) of the drawing point `(u, v)` mm.
    ///
    /// ```
    /// let a = tmm_web::gear_pick::ContourAxes { x1: (-1.0, 2.0), x2: (-1.0, 2.0), origin: (50.0, 100.0), scale: 40.0, n: 0, feasible: vec![], passes: vec![] };
    /// assert_eq!(a.shifts(90.0, 20.0), (1.0, 2.0));
    /// ```
    pub fn shifts(&self, u: f64, v: f64) -> (f64, f64) {
        ((u - self.origin.0) / self.scale, (self.origin.1 - v) / self.scale)
    }
}

/// The contour's axes for the task's `[gear]` section, from the canvas its
/// drawing is made on ([`tmm_report::gear::contour_plot::plot_canvas`], the
/// task's sheet format), and the nodes where the task's checks all pass;
/// `None` without a `[gear]` section.
pub fn axes(task: &TaskSource) -> Result<Option<ContourAxes>, Error> {
    let Some((raw, origin)) = Raw::from_task(task)? else {
        return Ok(None);
    };
    let job = raw.job(&origin, true)?;
    let c = blocking_contour(&job.spec, &ContourOptions::default()).map_err(|e| tmm_report::gear::input::gear_error(&origin, &e))?;
    let cv = plot_canvas(&c, task.sheet);
    let n = c.n;
    let mut passes = vec![false; n * n];
    for j in 0..n {
        for i in 0..n {
            let (x1, x2) = c.node(i, j);
            passes[j * n + i] =
                c.feasible[j * n + i] && Pair::compute(&with_shifts(&job.spec, x1, x2)).is_ok_and(|p| p.checks(&job.limits).all_pass());
        }
    }
    Ok(Some(ContourAxes {
        x1: c.x1,
        x2: c.x2,
        origin: cv.to_paper(0.0, 0.0),
        scale: cv.scale(),
        n,
        feasible: c.feasible,
        passes,
    }))
}

/// `{"ok", "x1": [lo, hi], "x2": [lo, hi], "origin": [u, v], "scale"}`, or
/// `{"none": true}` without a `[gear]` section.
pub fn contour_axes(p: &Page) -> String {
    match axes(&p.task) {
        Ok(Some(a)) => json!({
            "ok": true,
            "x1": [a.x1.0, a.x1.1],
            "x2": [a.x2.0, a.x2.1],
            "origin": [a.origin.0, a.origin.1],
            "scale": a.scale,
            "n": a.n,
            "feasible": a.feasible.iter().map(|&b| if b { '1' } else { '0' }).collect::<String>(),
            "passes": a.passes.iter().map(|&b| if b { '1' } else { '0' }).collect::<String>(),
        })
        .to_string(),
        Ok(None) => json!({ "none": true }).to_string(),
        Err(e) => reply::from_error(&p.task, &e).to_string(),
    }
}

/// The task with `[gear] x1`, `x2` set (a given centre distance or a
/// criterion dropped, since the shifts now fix the pair).
pub fn task_with_shifts(task: &TaskSource, x1: f64, x2: f64) -> Result<TaskSource, Error> {
    let mut t: toml::Table = task
        .text
        .parse()
        .map_err(|e| Error::input(&task.name, format!("the task is not valid TOML: {e}")))?;
    let Some(toml::Value::Table(g)) = t.get_mut("gear") else {
        return Err(Error::input("gear", "the task has no [gear] section"));
    };
    g.insert("x1".into(), toml::Value::Float(x1));
    g.insert("x2".into(), toml::Value::Float(x2));
    g.remove("aw");
    g.remove("criterion");
    let text = toml::to_string(&t).map_err(|e| Error::input("gear", e))?;
    Ok(TaskSource::new(task.name.clone(), text).with_lang(task.lang).with_sheet(task.sheet))
}

/// The pair at (x1, x2): `{"ok", "gear": <gear.json>, "text", "files":
/// {"gear/mesh.svg", "gear/contour.svg", "gear/sliding.svg", …}}`, or the
/// error (an undercut or a pointed tooth is reported, not hidden).
pub fn gear_at(p: &Page, x1: f64, x2: f64) -> String {
    if !(x1.is_finite() && x2.is_finite()) {
        return reply::error_json("x1 and x2 must be finite numbers", None, None);
    }
    let run = || -> Result<Value, Error> {
        let t = task_with_shifts(&p.task, x1, x2)?;
        let Some(out) = tmm_report::gear::run_section(&t)? else {
            return Ok(json!({ "none": true }));
        };
        let mut files = serde_json::Map::new();
        for d in out.docs.iter().filter(|d| d.extension() == "svg") {
            files.insert(d.path.clone(), d.as_text().unwrap_or_default().into());
        }
        Ok(json!({ "ok": true, "gear": out.json, "text": out.text, "files": files }))
    };
    match run() {
        Ok(v) => v.to_string(),
        Err(e) => {
            let mut v = reply::from_error(&p.task, &e);
            v["x1"] = x1.into();
            v["x2"] = x2.into();
            v.to_string()
        }
    }
}

/// The task text with the picked shifts written into its `[gear]` section:
/// `x1 = …` and `x2 = …` (rounded to 0.001, the contour's resolution) in
/// place of the old ones, or after the header; a given centre distance
/// `aw` or a `criterion`, which the shifts now replace, commented out. The
/// rest of the text, comments included, is kept line for line.
///
/// ```
/// let t = "[gear]\n# a comment\nz1 = 15\ncriterion = \"equal-sliding\"\n\n[cam]\nx1 = 5\n";
/// let w = tmm_web::gear_pick::write_shifts(t, 0.2, 0.85).unwrap();
/// assert_eq!(w, "[gear]\nx1 = 0.2\nx2 = 0.85\n# a comment\nz1 = 15\n# criterion = \"equal-sliding\"\n\n[cam]\nx1 = 5\n");
/// ```
pub fn write_shifts(text: &str, x1: f64, x2: f64) -> Result<String, String> {
    if !(x1.is_finite() && x2.is_finite()) {
        return Err("x1 and x2 must be finite numbers".into());
    }
    let r = |x: f64| format!("{:?}", (x * 1000.0).round() / 1000.0 + 0.0);
    let lines: Vec<&str> = text.split('\n').collect();
    let is_header = |l: &str| l.trim_start().starts_with('[');
    let key_of = |l: &str| -> Option<String> {
        let t = l.trim_start();
        let (k, _) = t.split_once('=')?;
        let k = k.trim().trim_matches('"');
        Some(k.to_string())
    };
    let Some(h) = lines.iter().position(|l| {
        let t = l.trim();
        t == "[gear]" || t.starts_with("[gear]") && t[6..].trim_start().starts_with('#')
    }) else {
        return Err("the task has no [gear] section to write the shifts into".into());
    };
    let end = lines[h + 1..].iter().position(|l| is_header(l)).map_or(lines.len(), |k| h + 1 + k);
    let mut out: Vec<String> = lines[..=h].iter().map(|l| l.to_string()).collect();
    out.push(format!("x1 = {}", r(x1)));
    out.push(format!("x2 = {}", r(x2)));
    for l in &lines[h + 1..end] {
        match key_of(l).as_deref() {
            Some("x1" | "x2") if !l.trim_start().starts_with('#') => {}
            Some("aw" | "criterion") if !l.trim_start().starts_with('#') => out.push(format!("# {}", l.trim_start())),
            _ => out.push(l.to_string()),
        }
    }
    out.extend(lines[end..].iter().map(|l| l.to_string()));
    Ok(out.join("\n"))
}
