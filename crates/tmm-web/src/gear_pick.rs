//! Picking the shift coefficients on the blocking contour (выбор
//! коэффициентов смещения по блокирующему контуру): where the contour's
//! axes lie on its drawing, so that a click becomes (x1, x2), and the pair
//! recomputed with the picked (x1, x2) — the same `[gear]` section run with
//! `x1`, `x2` written into the task, so the numbers, checks and drawings are
//! the CLI's for that task.

use serde_json::{Value, json};
use tmm_gears::contour::{ContourOptions, blocking_contour};
use tmm_report::gear::input::Raw;
use tmm_report::svg::Canvas;
use tmm_report::{Error, TaskSource};

use crate::page::Page;
use crate::reply;

/// The paper of the contour drawing, mm (A4 landscape), and the box its
/// plot is fitted into, `(left, bottom, width, height)` mm — the values of
/// `tmm_report::gear::contour_plot::contour_svg`; the test
/// `click_maps_to_the_marked_point` checks them against its drawing.
const PAPER: (f64, f64) = (297.0, 210.0);
const PLOT_BOX: (f64, f64, f64, f64) = (22.0, 16.0, 190.0, 176.0);

/// The linear map from (x1, x2) to the drawing's coordinates (mm, y down):
/// `svg = origin + scale · (x1, −x2)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContourAxes {
    /// The x1 range of the contour.
    pub x1: (f64, f64),
    /// The x2 range of the contour.
    pub x2: (f64, f64),
    /// The drawing point of (0, 0), mm.
    pub origin: (f64, f64),
    /// mm per unit of x.
    pub scale: f64,
}

impl ContourAxes {
    /// (x1, x2) of the drawing point `(u, v)` mm.
    ///
    /// ```
    /// let a = tmm_web::gear_pick::ContourAxes { x1: (-1.0, 2.0), x2: (-1.0, 2.0), origin: (50.0, 100.0), scale: 40.0 };
    /// assert_eq!(a.shifts(90.0, 20.0), (1.0, 2.0));
    /// ```
    pub fn shifts(&self, u: f64, v: f64) -> (f64, f64) {
        ((u - self.origin.0) / self.scale, (self.origin.1 - v) / self.scale)
    }
}

/// The contour's axes for the task's `[gear]` section; `None` without one.
pub fn axes(task: &TaskSource) -> Result<Option<ContourAxes>, Error> {
    let Some((raw, origin)) = Raw::from_task(task)? else {
        return Ok(None);
    };
    let job = raw.job(&origin, false)?;
    let c = blocking_contour(&job.spec, &ContourOptions::default()).map_err(|e| tmm_report::gear::input::gear_error(&origin, &e))?;
    let mut cv = Canvas::new(PAPER.0, PAPER.1);
    let scale = cv.fit((c.x1.0, c.x1.1, c.x2.0, c.x2.1), PLOT_BOX);
    Ok(Some(ContourAxes {
        x1: c.x1,
        x2: c.x2,
        origin: cv.to_paper(0.0, 0.0),
        scale,
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
