//! Editing the mechanism by dragging it (правка механизма перетаскиванием):
//! a fixed point dragged to a new place gets new coordinates in
//! `[linkage] fixed`, a joint dragged to a new place gives the links it ends
//! new lengths (the distance to the link's other joint, as solved at the
//! crank angle shown). The values are rounded to whole millimetres and
//! written over the old ones where the user typed them (the spans the
//! linkage reader keeps), so the rest of the text, the assembly branch
//! (`assembly`) included, stays as it was.

use crate::page::Page;

/// A length in mm as the task writes it (`"480 mm"`), rounded to 1 mm.
fn mm(v: f64) -> String {
    format!("\"{} mm\"", (v * 1000.0).round() + 0.0)
}

/// The task text after the point `point` of the page's mechanism is dragged
/// to `(x, y)` (m) with the crank at `phi` (rad); `text` must be the text
/// the page ran. An error says why the point cannot be dragged.
///
/// ```
/// use tmm_web::page::Page;
/// let t = "[linkage]\nfixed = { A = [0, 0], D = [\"510 mm\", \"0 mm\"] }\ninput = { link = \"1\", speed = \"900 rpm\" }\nassembly = [\"C below AD\"]\n\n[[linkage.links]]\nname = \"1\"\njoints = [\"A\", \"B\"]\nlength = \"120 mm\"\n\n[[linkage.links]]\nname = \"2\"\njoints = [\"B\", \"C\"]\nlength = \"480 mm\"\n\n[[linkage.links]]\nname = \"3\"\njoints = [\"D\", \"C\"]\nlength = \"380 mm\"\n";
/// let p = Page::new("t.toml", t, None).unwrap();
/// let moved = tmm_web::drag::drag(&p, t, "D", 0.5204, 0.0101, 0.0).unwrap();
/// assert!(moved.contains("D = [\"520 mm\", \"10 mm\"]"));
/// ```
pub fn drag(p: &Page, text: &str, point: &str, x: f64, y: f64, phi: f64) -> Result<String, String> {
    if !(x.is_finite() && y.is_finite() && phi.is_finite()) {
        return Err("the dragged position must be finite numbers".into());
    }
    let Some(l) = &p.linkage else {
        return Err("the task has no [linkage] section".into());
    };
    if p.task.text != text {
        return Err("the mechanism is written by the [synthesis] section: change its givens instead".into());
    }
    let spans = &l.task.spans;
    let mut edits: Vec<(std::ops::Range<usize>, String)> = Vec::new();
    if let Some(s) = spans.get(&format!("fixed.{point}")) {
        edits.push((s.clone(), format!("[{}, {}]", mm(x), mm(y))));
    } else {
        let m = &l.mech;
        let mut sol = m.solution();
        m.solve(phi, &mut sol).map_err(|e| e.to_string())?;
        let at = |name: &str| m.points.iter().position(|q| q.name == name).map(|i| sol.points[i].p);
        for link in &l.def.links {
            let ends: Vec<&str> = link.points.iter().take(2).map(|(n, _)| n.as_str()).collect();
            if ends.len() < 2 || !ends.contains(&point) {
                continue;
            }
            let other = if ends[0] == point { ends[1] } else { ends[0] };
            let (Some(s), Some(o)) = (spans.get(&format!("links.{}.length", link.name)), at(other)) else {
                continue;
            };
            let len = (x - o.x).hypot(y - o.y);
            if len < 0.0005 {
                return Err(format!("link {} would have no length", link.name));
            }
            edits.push((s.clone(), mm(len)));
        }
        if edits.is_empty() {
            return Err(format!(
                "{point} is neither a fixed point nor an end of a link with a length, so dragging it changes nothing in the task"
            ));
        }
    }
    edits.sort_by_key(|(s, _)| std::cmp::Reverse(s.start));
    let mut out = text.to_string();
    for (s, v) in edits {
        if s.end > out.len() || !out.is_char_boundary(s.start) || !out.is_char_boundary(s.end) {
            return Err("the task's text changed under the drag".into());
        }
        out.replace_range(s, &v);
    }
    Ok(out)
}
