//! The technical assignment (техническое задание): the mechanism's scheme
//! and the task's data as tables, one per part of the project, each value as
//! the task gives it (380 Н·м, 10 кг/м, k = 0,1, the frame's 510 мм), with
//! the kinetostatics' givens (the mass rule, the centres of mass, gravity,
//! the resistance and its law), the cam's phases and laws and the planetary
//! train's scheme in words.

use super::context::{Ctx, num, text};
use super::linkage::link_lengths;
use crate::error::NoteError;
use crate::model::{Block, Cell};

/// The assignment's blocks.
pub(crate) fn blocks(cx: &Ctx) -> Result<Vec<Block>, NoteError> {
    let mut b = vec![cx.para("assign_intro", &[])?];
    if let Some(f) = scheme_figure(cx)? {
        b.push(f);
    }
    // a synthesised mechanism: the task gives the synthesis' data (П3's
    // H, K, λ, l_BC, l_OC), not the lengths it finds
    let synthesised = cx.report.get("synthesis").is_some();
    if synthesised {
        b.push(cx.quantities("assign_synthesis", super::synthesis::given_rows(cx)?)?);
    }
    if cx.report.get("linkage").is_some() {
        // the analysed mechanism's lengths are given when the task has its
        // own [linkage] (a synthesised one's are found, not given)
        if !synthesised || task_linkage(cx).is_some() {
            let rows = length_rows(cx)?;
            b.push(cx.table("assign_links", &[("col_link", ""), ("col_length", "u_mm")], rows)?);
        }
        if cx.s("/linkage/input/kind") == Some("slider") {
            let mm = |ptr: &str| -> Result<String, NoteError> { as_given(cx, &["linkage"], cx.v(ptr)? * 1e3, "u_mm") };
            let q = vec![
                (
                    cx.w("q_slider_speed")?,
                    as_given(cx, &["linkage"], cx.v("/linkage/input/speed")?, "u_m_s")?,
                ),
                (cx.w("q_slider_from")?, mm("/linkage/input/travel/from")?),
                (cx.w("q_slider_to")?, mm("/linkage/input/travel/to")?),
                (cx.w("q_slider_position")?, mm("/linkage/plans/s")?),
            ];
            b.push(cx.quantities("assign_linkage", q)?);
        } else {
            let omega = cx.v("/linkage/input/omega")?;
            let mut q = vec![
                (cx.w("q_omega1")?, as_given(cx, &["linkage"], omega, "u_rad_s")?),
                (
                    cx.w("q_n1")?,
                    as_given(cx, &["linkage"], omega.abs() * 30.0 / std::f64::consts::PI, "u_rpm")?,
                ),
            ];
            // the time of one turn T = 60/n1
            if omega != 0.0 {
                q.push((cx.w("q_revolution_time")?, cx.q(std::f64::consts::TAU / omega.abs(), "cy_u_s")?));
            }
            q.push((
                cx.w("q_position")?,
                as_given(cx, &["linkage"], cx.v("/linkage/plans/phi")?.to_degrees(), "u_deg")?,
            ));
            b.push(cx.quantities("assign_linkage", q)?);
        }
    }
    if cx.report.get("forces").is_some() {
        let given = forces_rows(cx)?;
        if !given.is_empty() {
            b.push(cx.quantities("assign_forces", given)?);
        }
        let mut rows = Vec::new();
        // the masses and inertias the task gives link by link are among
        // the givens above as written: the table lists those the mass rule
        // computes
        let given = |key: &str| {
            cx.task
                .get("forces")
                .and_then(|f| f.get("links"))
                .and_then(toml::Value::as_table)
                .map_or(0, |ls| ls.values().filter(|l| l.get(key).is_some()).count())
        };
        let links_n = cx
            .report
            .pointer("/forces/links")
            .and_then(|v| v.as_object())
            .map_or(0, |l| l.len());
        let all_given = links_n > 0 && given("mass") >= links_n && given("inertia") >= links_n;
        if let Some(links) = cx
            .report
            .pointer("/forces/links")
            .and_then(|v| v.as_object())
            .filter(|_| !all_given)
        {
            for (name, l) in links {
                let m = l.get("mass").and_then(|v| v.as_f64()).unwrap_or(0.0);
                let j = l.get("inertia").and_then(|v| v.as_f64()).unwrap_or(0.0);
                rows.push(vec![text(cx.fill("link_n", std::slice::from_ref(name))?), num(m), num(j)]);
            }
        }
        if !rows.is_empty() {
            b.push(cx.table(
                "assign_masses",
                &[("col_link", ""), ("col_mass", "u_kg"), ("col_inertia", "u_kgm2")],
                rows,
            )?);
        }
    }
    if cx.report.get("dynamics").is_some() && cx.s("/dynamics/motion") != Some("single-stroke") {
        b.push(cx.quantities(
            "assign_dynamics",
            vec![
                (
                    cx.w("q_delta")?,
                    as_given(cx, &["dynamics"], cx.v("/dynamics/delta_requested")?, "")?,
                ),
                (cx.w("q_omega_m")?, cx.qv("/dynamics/omega_nominal", 1.0, "u_rad_s")?),
            ],
        )?);
    }
    if cx.report.get("gear").is_some() {
        b.push(cx.quantities("assign_gear", super::gear::given_rows(cx)?)?);
    }
    if cx.report.get("planetary").is_some() {
        if let Some(p) = planetary_scheme(cx)? {
            b.push(p);
        }
        let omega = cx.v("/planetary/request/omega1")?;
        let pl = &["planetary"];
        let mut rows = vec![(cx.w("q_ratio")?, as_given(cx, pl, cx.v("/planetary/request/ratio")?, "")?)];
        // the ratio's allowed deviation where the task gives it: as written,
        // a plain share with its per cent beside it (0,01 (1 %))
        if let Some(mut t) = task_given(cx, "planetary", "tolerance", "")? {
            if !t.contains('%')
                && let Some(x) = task_share(cx, "planetary", "tolerance")
            {
                let mut p = given_number(cx, x * 100.0)?;
                crate::number::push_unit(&mut p, &cx.w("u_percent")?);
                t = format!("{t} ({p})");
            }
            rows.push((cx.w("q_ratio_tolerance")?, t));
        }
        rows.extend([
            (cx.w("q_planets")?, format!("{}", cx.v("/planetary/request/planets")?)),
            (
                cx.w("q_module")?,
                as_given(cx, pl, cx.v("/planetary/request/module")? * 1e3, "u_mm")?,
            ),
            (cx.w("q_omega_sun")?, as_given(cx, pl, omega, "u_rad_s")?),
            (
                cx.w("q_n_sun")?,
                as_given(cx, pl, omega.abs() * 30.0 / std::f64::consts::PI, "u_rpm")?,
            ),
        ]);
        b.push(cx.quantities("assign_planetary", rows)?);
    }
    if cx.report.get("cam").is_some() {
        b.push(cx.quantities("assign_cam", super::cam::given_rows(cx)?)?);
        let rows = cam_phase_rows(cx)?;
        if !rows.is_empty() {
            b.push(cx.table(
                "assign_cam_phases",
                &[("col_phase", ""), ("col_phase_angle", "u_deg"), ("col_law", "")],
                rows,
            )?);
        }
    }
    if cx.report.get("cylinder").is_some() {
        b.push(cx.quantities("assign_cylinder", super::cylinder::given_rows(cx)?)?);
    }
    b.push(cx.para("assign_rounding", &[super::DIGITS.to_string()])?);
    Ok(b)
}

/// The mechanism's scheme for the assignment: the first of the run's
/// drawings that shows the mechanism itself (the linkage's kinematic scheme
/// at the computed position, the cylinder's mechanism, the planetary train's
/// scheme, the cam with its follower), as the sections print it.
fn scheme_figure(cx: &Ctx) -> Result<Option<Block>, NoteError> {
    for path in [
        "linkage/positions.svg",
        "cylinder/mechanism.svg",
        "planetary/planetary.svg",
        "cam/cam.svg",
    ] {
        if let Some(f) = cx.figure(path, "fig_assign_scheme")? {
            return Ok(Some(f));
        }
    }
    Ok(None)
}

/// A number as the task gives it: four significant digits at most, the
/// trailing zeros dropped (510, not 510,0; 0,1, not 0,1000; 3,5·10⁷, not
/// 3,500·10⁷), as [`Ctx::given`] prints a value of the report.
fn given_number(cx: &Ctx, value: f64) -> Result<String, NoteError> {
    given_digits(cx, value, super::DIGITS)
}

/// [`given_number`] with at most `digits` significant digits.
fn given_digits(cx: &Ctx, value: f64, digits: u8) -> Result<String, NoteError> {
    let mut f = crate::number::format_number(crate::number::zero_noise(value, 0.0), digits, cx.lang)?;
    if f.mantissa.contains([',', '.']) {
        f.mantissa = f.mantissa.trim_end_matches('0').trim_end_matches([',', '.']).to_string();
    }
    Ok(f.to_string())
}

/// The significant digits of a number as the task writes it (`1.1065`:
/// five, `380`: three, `0.0833333333333333`: sixteen), at least one.
fn written_digits(text: &str) -> usize {
    let mantissa = text.split(['e', 'E']).next().unwrap_or("");
    let digits: String = mantissa.chars().filter(char::is_ascii_digit).collect();
    let d = digits.trim_start_matches('0');
    let d = if mantissa.contains(['.', ',']) {
        d
    } else {
        d.trim_end_matches('0')
    };
    d.len().max(1)
}

/// A quantity of the task file (`"380 N m"`, `"10 kg/m"`, `0.1`) split
/// into its number and its unit as written (spaces, `·` and `*` removed).
fn task_quantity(v: &toml::Value) -> Option<(f64, String)> {
    match v {
        toml::Value::Float(f) => Some((*f, String::new())),
        toml::Value::Integer(i) => Some((*i as f64, String::new())),
        toml::Value::String(s) => {
            let s = s.trim();
            let end = s
                .char_indices()
                .find(|&(i, c)| {
                    !(c.is_ascii_digit()
                        || c == '.'
                        || c == ','
                        || ((c == '-' || c == '+') && (i == 0 || s[..i].ends_with(['e', 'E'])))
                        || ((c == 'e' || c == 'E')
                            && i > 0
                            && s[i + 1..].starts_with(|d: char| d.is_ascii_digit() || d == '-' || d == '+')))
                })
                .map_or(s.len(), |(i, _)| i);
            let value: f64 = s[..end].replace(',', ".").parse().ok()?;
            let unit: String = s[end..].chars().filter(|c| !matches!(c, ' ' | '·' | '*' | '⋅')).collect();
            Some((value, unit))
        }
        _ => None,
    }
}

/// A quantity of the task file in the note's words, its value as given:
/// `"380 N m"` → «380 Н·м», `"10 kg/m"` → «10 кг/м», `"9.81 m/s^2"` →
/// «9,81 м/с²»; a multiple (kN, m of a length) in the note's unit (Н, мм).
/// A unit the note does not know is printed as the task writes it.
pub(crate) fn quantity_text(cx: &Ctx, v: &toml::Value) -> Result<String, NoteError> {
    let Some((value, unit)) = task_quantity(v) else {
        return Ok(match v {
            toml::Value::String(s) => s.clone(),
            other => other.to_string(),
        });
    };
    let (scale, key) = match unit.as_str() {
        "" => (1.0, ""),
        "N" => (1.0, "u_n"),
        "kN" => (1e3, "u_n"),
        "MN" => (1e6, "u_n"),
        "Nm" => (1.0, "u_nm"),
        "kNm" => (1e3, "u_nm"),
        "kg" => (1.0, "u_kg"),
        "t" => (1e3, "u_kg"),
        "kg/m" => (1.0, "u_kg_per_m"),
        "kgm^2" | "kgm2" | "kgm²" => (1.0, "u_kgm2"),
        "m/s^2" | "m/s2" | "m/s²" => (1.0, "u_m_s2"),
        "MPa" => (1.0, "u_mpa"),
        "kPa" => (1e-3, "u_mpa"),
        "Pa" => (1e-6, "u_mpa"),
        "bar" => (0.1, "u_mpa"),
        "mm" => (1.0, "u_mm"),
        "cm" => (10.0, "u_mm"),
        "m" => (1e3, "u_mm"),
        "deg" | "°" => (1.0, "u_deg"),
        "rpm" => (1.0, "u_rpm"),
        "rad/s" => (1.0, "u_rad_s"),
        "m/s" => (1.0, "u_m_s"),
        "%" => (1.0, "u_percent"),
        _ => {
            let s = match v {
                toml::Value::String(s) => s.clone(),
                other => other.to_string(),
            };
            return Ok(s);
        }
    };
    // the task's own digits (1.1065 stays 1,1065), four of a longer number
    let written = match v {
        toml::Value::String(t) => written_digits(
            t.trim()
                .split(|c: char| c.is_whitespace() || c.is_alphabetic() && c != 'e' && c != 'E')
                .next()
                .unwrap_or(""),
        ),
        toml::Value::Float(x) => written_digits(&x.to_string()),
        _ => usize::from(super::DIGITS),
    };
    let digits = if written <= 6 {
        written.max(usize::from(super::DIGITS))
    } else {
        usize::from(super::DIGITS)
    };
    let mut s = given_digits(cx, value * scale, u8::try_from(digits).unwrap_or(super::DIGITS))?;
    let u = if key.is_empty() { String::new() } else { cx.w(key)? };
    crate::number::push_unit(&mut s, &u);
    Ok(s)
}

/// The kind of a quantity, for matching a value to the task's text: a
/// length, an angle, an angular speed ω (рад/с) and a frequency of rotation
/// n (об/мин) apart, a speed, a mass, a force, a moment, an inertia, an
/// acceleration, a pressure, a time; `Bare` a plain number (SI, any kind).
#[derive(Clone, Copy, PartialEq, Eq)]
enum Kind {
    Bare,
    Length,
    Angle,
    AngularSpeed,
    Rotation,
    Speed,
    Mass,
    Force,
    Moment,
    Inertia,
    Acceleration,
    Pressure,
    Time,
}

/// The factor to SI and the kind of a unit as the task file writes it
/// (`mm` → 10⁻³, `deg` → π/180, `rpm` → 1 for n; ГОСТ 8.417), `None` for a
/// unit not known.
fn task_unit_si(unit: &str) -> Option<(f64, Kind)> {
    use std::f64::consts::PI;
    Some(match unit {
        "" => (1.0, Kind::Bare),
        "m" => (1.0, Kind::Length),
        "mm" => (1e-3, Kind::Length),
        "cm" => (1e-2, Kind::Length),
        "rad" => (1.0, Kind::Angle),
        "deg" | "°" => (PI / 180.0, Kind::Angle),
        "rad/s" => (1.0, Kind::AngularSpeed),
        "rpm" => (1.0, Kind::Rotation),
        "m/s" => (1.0, Kind::Speed),
        "kg" => (1.0, Kind::Mass),
        "t" => (1e3, Kind::Mass),
        "N" => (1.0, Kind::Force),
        "kN" => (1e3, Kind::Force),
        "MN" => (1e6, Kind::Force),
        "Nm" => (1.0, Kind::Moment),
        "kNm" => (1e3, Kind::Moment),
        "kgm^2" | "kgm2" | "kgm²" => (1.0, Kind::Inertia),
        "m/s^2" | "m/s2" | "m/s²" => (1.0, Kind::Acceleration),
        "Pa" => (1.0, Kind::Pressure),
        "kPa" => (1e3, Kind::Pressure),
        "MPa" => (1e6, Kind::Pressure),
        "bar" => (1e5, Kind::Pressure),
        "s" => (1.0, Kind::Time),
        _ => return None,
    })
}

/// The factor to SI and the kind of the note's unit of the words key `key`
/// (`""`: a number without a unit, matched by a plain number only).
fn note_unit_si(key: &str) -> Option<(f64, Kind)> {
    use std::f64::consts::PI;
    Some(match key {
        "" => (1.0, Kind::Bare),
        "cy_u_m" => (1.0, Kind::Length),
        "u_mm" => (1e-3, Kind::Length),
        "u_deg" => (PI / 180.0, Kind::Angle),
        "u_rad_s" => (1.0, Kind::AngularSpeed),
        "u_rpm" => (1.0, Kind::Rotation),
        "u_m_s" => (1.0, Kind::Speed),
        "u_kg" => (1.0, Kind::Mass),
        "u_n" => (1.0, Kind::Force),
        "u_nm" => (1.0, Kind::Moment),
        "u_kgm2" => (1.0, Kind::Inertia),
        "u_m_s2" => (1.0, Kind::Acceleration),
        "u_mpa" => (1e6, Kind::Pressure),
        "cy_u_s" => (1.0, Kind::Time),
        _ => return None,
    })
}

/// A fraction as the task writes a ratio (`"1/30"`, `"-1/20"`).
fn task_fraction(v: &toml::Value) -> Option<f64> {
    let (a, b) = v.as_str()?.trim().split_once('/')?;
    let (a, b): (f64, f64) = (a.trim().parse().ok()?, b.trim().parse().ok()?);
    (b != 0.0).then(|| a / b).filter(|x| x.is_finite())
}

/// The task's own text of a given: among the values of the task's tables
/// `sections` (their sub-tables and lists too), the one equal to `x` in the
/// note's unit `unit` (to 10⁻⁹ of it), with its unit as written.
/// A value of the task with a unit matches a value of the same kind only
/// (0.5 m is not 0.5 m/s; an angular speed ω is not a frequency n); a
/// plain number (SI) matches any.
fn task_value<'a>(cx: &Ctx<'a>, sections: &[&str], x: f64, unit: &str) -> Option<&'a toml::Value> {
    fn find(v: &toml::Value, si: f64, kind: Kind) -> Option<&toml::Value> {
        let same = |a: f64| (a - si).abs() <= 1e-9 * a.abs().max(si.abs()) || a == si;
        match v {
            toml::Value::Table(t) => t.values().find_map(|w| find(w, si, kind)),
            toml::Value::Array(a) => a.iter().find_map(|w| find(w, si, kind)),
            _ => {
                if kind == Kind::Bare && task_fraction(v).is_some_and(same) {
                    return Some(v);
                }
                let (value, u) = task_quantity(v)?;
                let (scale, k) = task_unit_si(&u)?;
                ((k == kind || k == Kind::Bare) && same(value * scale)).then_some(v)
            }
        }
    }
    let (scale, kind) = note_unit_si(unit)?;
    sections.iter().find_map(|s| find(cx.task.get(*s)?, x * scale, kind))
}

/// The digits a value of the task is printed with: as many as the task
/// writes (four at least), four of a longer number (a computed value
/// pasted into the task).
fn value_digits(v: &toml::Value) -> u8 {
    let written = match v {
        toml::Value::String(t) => written_digits(t.trim()),
        toml::Value::Float(f) => written_digits(&f.to_string()),
        other => written_digits(&other.to_string()),
    };
    let digits = if written <= 6 {
        written.max(usize::from(super::DIGITS))
    } else {
        usize::from(super::DIGITS)
    };
    u8::try_from(digits).unwrap_or(super::DIGITS)
}

/// The digits of the given `x` as [`as_given`] prints it, for a value
/// computed against it (K_v = 1,1065 given: the synthesised 1,1065 with
/// five digits too, not 1,107).
pub(crate) fn given_precision(cx: &Ctx, sections: &[&str], x: f64, unit: &str) -> u8 {
    task_value(cx, sections, x, unit).map_or(super::DIGITS, value_digits)
}

/// A given of the task printed as the task writes it: the value `x` (in
/// the note's unit of the words key `unit`) found among the task's tables
/// `sections` keeps the task's digits and unit (k = 1.1065 → «1,1065»,
/// `"150 rpm"` → «150 об/мин», `"1/30"` as written); a plain number of
/// the task keeps its digits in the note's unit; a value the task does not
/// state (a default) prints with four digits at most, its trailing zeros
/// dropped (20°, not 20,00°).
pub(crate) fn as_given(cx: &Ctx, sections: &[&str], x: f64, unit: &str) -> Result<String, NoteError> {
    let u = if unit.is_empty() { String::new() } else { cx.w(unit)? };
    match task_value(cx, sections, x, unit) {
        Some(v) if task_fraction(v).is_some() => Ok(v.as_str().unwrap_or("").trim().replace('-', "\u{2212}")),
        Some(v) if task_quantity(v).is_some_and(|(_, w)| !w.is_empty()) => quantity_text(cx, v),
        Some(v) => {
            let mut s = given_digits(cx, x, value_digits(v))?;
            crate::number::push_unit(&mut s, &u);
            Ok(s)
        }
        None => {
            let mut s = given_number(cx, x)?;
            crate::number::push_unit(&mut s, &u);
            Ok(s)
        }
    }
}

/// The task's `[section]`'s `key` as the task writes it, `None` where the
/// task does not give it: a quantity with its unit in the note's words
/// (`"10 mm"` → «10 мм», `"1 %"` → «1 %»), a fraction as written
/// (`"1/4"`), a plain number (SI, as the task reader takes it) in the
/// note's unit of the words key `unit` with its own digits (`0.01` of a
/// length → «10 мм»).
pub(crate) fn task_given(cx: &Ctx, section: &str, key: &str, unit: &str) -> Result<Option<String>, NoteError> {
    let Some(v) = cx.task.get(section).and_then(|s| s.get(key)) else {
        return Ok(None);
    };
    match task_quantity(v) {
        Some((x, u)) if u.is_empty() => {
            let si = note_unit_si(unit).map_or(1.0, |(f, _)| f);
            as_given(cx, &[section], x / si, unit).map(Some)
        }
        _ => quantity_text(cx, v).map(Some),
    }
}

/// A share the task gives as `key` of `[section]` (`0.3`, `"1/4"`,
/// `"30 %"`) as a number (0,3; 0,25; 0,3).
pub(crate) fn task_share(cx: &Ctx, section: &str, key: &str) -> Option<f64> {
    let v = cx.task.get(section)?.get(key)?;
    if let Some(x) = task_fraction(v) {
        return Some(x);
    }
    match task_quantity(v)? {
        (x, u) if u.is_empty() => Some(x),
        (x, u) if u == "%" => Some(x / 100.0),
        _ => None,
    }
    .filter(|x| x.is_finite())
}

/// The task's `[section]`'s `key` as written where it is a length
/// (`stroke = "80 mm"` of an oscillating follower: the arc its roller's
/// centre travels, given beside the swing the note computes from it).
pub(crate) fn task_length_text(cx: &Ctx, section: &str, key: &str) -> Result<Option<String>, NoteError> {
    let Some(v) = cx.task.get(section).and_then(|s| s.get(key)) else {
        return Ok(None);
    };
    let length = task_quantity(v)
        .and_then(|(_, u)| task_unit_si(&u))
        .is_some_and(|(_, k)| k == Kind::Length);
    if !length {
        return Ok(None);
    }
    quantity_text(cx, v).map(Some)
}

/// A length of the task file in mm, as a number (`"120 mm"`, `"0.12 m"`).
fn task_mm(v: &toml::Value) -> Option<f64> {
    let (value, unit) = task_quantity(v)?;
    match unit.as_str() {
        "mm" => Some(value),
        "cm" => Some(value * 10.0),
        "m" | "" => Some(value * 1e3),
        _ => None,
    }
}

/// The task's `[linkage]` (not a synthesised one: its lengths are found,
/// not given).
fn task_linkage<'a>(cx: &Ctx<'a>) -> Option<&'a toml::Table> {
    cx.task.get("linkage").and_then(toml::Value::as_table)
}

/// The rows of the links' lengths: each link's length as the task gives it
/// (or as the joints' distance in the first position), then the frame (стойка)
/// between each two of the fixed joints, by their coordinates.
fn length_rows(cx: &Ctx) -> Result<Vec<Vec<Cell>>, NoteError> {
    let given: Vec<(String, Option<f64>)> = task_linkage(cx)
        .and_then(|l| l.get("links"))
        .and_then(toml::Value::as_array)
        .map(|a| {
            a.iter()
                .filter_map(|l| Some((l.get("name")?.as_str()?.to_string(), l.get("length").and_then(task_mm))))
                .collect()
        })
        .unwrap_or_default();
    let mut rows: Vec<Vec<Cell>> = Vec::new();
    for (name, l) in link_lengths(cx) {
        let as_given = given.iter().find(|(n, _)| *n == name).and_then(|(_, g)| *g);
        let cell = match as_given {
            Some(mm) => text(given_number(cx, mm)?),
            None => num(l * 1000.0),
        };
        rows.push(vec![text(cx.fill("link_n", &[name])?), cell]);
    }
    // the frame: the distance of each two fixed joints (AD = 510 mm)
    if let Some(fixed) = task_linkage(cx).and_then(|l| l.get("fixed")).and_then(toml::Value::as_table) {
        let points: Vec<(&String, f64, f64)> = fixed
            .iter()
            .filter_map(|(n, v)| {
                let a = v.as_array()?;
                Some((n, task_mm(a.first()?)?, task_mm(a.get(1)?)?))
            })
            .collect();
        for (i, a) in points.iter().enumerate() {
            for b in &points[i + 1..] {
                let d = (a.1 - b.1).hypot(a.2 - b.2);
                if d > 0.0 && d.is_finite() {
                    rows.push(vec![
                        text(cx.fill("link_frame", &[format!("{}{}", a.0, b.0)])?),
                        text(given_number(cx, d)?),
                    ]);
                }
            }
        }
    }
    Ok(rows)
}

/// The kinetostatics' givens as the task states them (`[forces]`): the mass
/// rule (q kg per metre, J_S = k·m·l²) or the masses given per link, the
/// centres of mass, gravity, the resistance (its link, value, law and
/// sense), the gas forces of an engine's cylinders, the forces by the
/// slider's travel, friction, the crank's motion.
fn forces_rows(cx: &Ctx) -> Result<Vec<(String, String)>, NoteError> {
    let Some(f) = cx.task.get("forces").and_then(toml::Value::as_table) else {
        return Ok(Vec::new());
    };
    let mut rows = Vec::new();
    let links = f.get("links").and_then(toml::Value::as_table);
    if let Some(q) = f.get("mass_per_length") {
        rows.push((cx.w("q_mass_per_length")?, quantity_text(cx, q)?));
    }
    // k of J_S = k·m·l² serves every link with a mass and no inertia given
    let by_rule = f.get("mass_per_length").is_some()
        || links.is_some_and(|ls| {
            ls.values()
                .any(|l| (l.get("mass").is_some() || l.get("mass_per_length").is_some()) && l.get("inertia").is_none())
        });
    if f.get("k").is_some() || by_rule {
        let k = match f.get("k") {
            Some(k) => quantity_text(cx, k)?,
            None => given_number(cx, 0.1)?,
        };
        rows.push((cx.w("q_inertia_k")?, k));
    }
    for (name, l) in links.into_iter().flatten() {
        for (key, word) in [
            ("mass", "q_link_mass"),
            ("mass_per_length", "q_link_mass_per_length"),
            ("inertia", "q_link_inertia"),
            ("k", "q_link_k"),
            ("moment", "q_link_moment"),
        ] {
            if let Some(v) = l.get(key) {
                rows.push((cx.fill(word, std::slice::from_ref(name))?, quantity_text(cx, v)?));
            }
        }
    }
    rows.push((cx.w("q_mass_centres")?, mass_centres(cx)?));
    let gravity = match f.get("gravity") {
        Some(g) => cx.fill("gravity_on", &[quantity_text(cx, g)?])?,
        None => cx.w("gravity_off")?,
    };
    rows.push((cx.w("q_gravity")?, gravity));
    for r in f.get("resistance").and_then(toml::Value::as_array).into_iter().flatten() {
        rows.push(resistance_row(cx, r)?);
    }
    for c in f.get("cylinders").and_then(toml::Value::as_array).into_iter().flatten() {
        let link = c.get("link").and_then(toml::Value::as_str).unwrap_or("").to_string();
        let mut value = cx.w("gas_by_indicator")?;
        if let Some(b) = c.get("bore") {
            value.push_str(&cx.fill("gas_bore", &[quantity_text(cx, b)?])?);
        }
        if let Some(p) = c.get("p_max") {
            value.push_str(&cx.fill("gas_p_max", &[quantity_text(cx, p)?])?);
        }
        rows.push((cx.fill("q_gas_force", &[link])?, value));
    }
    for s in f.get("stroke_forces").and_then(toml::Value::as_array).into_iter().flatten() {
        let link = s.get("link").and_then(toml::Value::as_str).unwrap_or("").to_string();
        let largest = s
            .get("force")
            .and_then(toml::Value::as_array)
            .map(|a| a.iter().filter_map(|v| task_quantity(v).map(|q| q.0.abs())).fold(0.0, f64::max))
            .unwrap_or(0.0);
        let mut value = cx.w("stroke_force_table")?;
        if largest > 0.0 {
            let mut n = given_number(cx, largest)?;
            crate::number::push_unit(&mut n, &cx.w("u_n")?);
            value.push_str(&cx.fill("stroke_force_largest", &[n])?);
        }
        rows.push((cx.fill("q_stroke_force", &[link])?, value));
    }
    for s in f.get("friction").and_then(toml::Value::as_array).into_iter().flatten() {
        let link = s.get("link").and_then(toml::Value::as_str).unwrap_or("").to_string();
        let value = match s.get("force") {
            Some(v) => cx.fill("friction_value", &[quantity_text(cx, v)?])?,
            None => cx.w("res_dir_opposes_force")?,
        };
        rows.push((cx.fill("q_friction", &[link])?, value));
    }
    let motion = if f.get("crank_motion").and_then(toml::Value::as_str) == Some("dynamics") {
        "crank_motion_dynamics"
    } else {
        "crank_motion_constant"
    };
    rows.push((cx.w("q_crank_motion")?, cx.w(motion)?));
    Ok(rows)
}

/// One resistance (`[[forces.resistance]]`) as a row: «Момент сопротивления
/// на звене 3 | 380 Н·м, постоянный на всём цикле, против вращения звена».
fn resistance_row(cx: &Ctx, r: &toml::Value) -> Result<(String, String), NoteError> {
    let link = r.get("link").and_then(toml::Value::as_str).unwrap_or("").to_string();
    let moment = r.get("moment");
    let label = match (moment, r.get("point").and_then(toml::Value::as_str)) {
        (Some(_), _) => cx.fill("q_res_moment", std::slice::from_ref(&link))?,
        (None, Some(p)) => cx.fill("q_res_force_at", &[link.clone(), p.to_string()])?,
        (None, None) => cx.fill("q_res_force", std::slice::from_ref(&link))?,
    };
    let mut parts = Vec::new();
    if let Some(v) = moment.or_else(|| r.get("force")) {
        parts.push(quantity_text(cx, v)?);
    }
    let law = r.get("law").and_then(toml::Value::as_str).unwrap_or("constant");
    let over_crank = r.get("over").and_then(toml::Value::as_str) == Some("crank");
    let law_key = match law {
        "constant" => "res_law_constant",
        "working" => "res_law_working",
        "sine" => "res_law_sine",
        "table" if over_crank => "res_law_table_crank",
        "table" => "res_law_table",
        _ => "",
    };
    parts.push(if law_key.is_empty() { law.to_string() } else { cx.w(law_key)? });
    let sense = match (moment.is_some(), r.get("direction").and_then(toml::Value::as_str), r.get("angle")) {
        (true, Some("ccw"), _) => cx.w("res_dir_ccw")?,
        (true, Some("cw"), _) => cx.w("res_dir_cw")?,
        (true, _, _) => cx.w("res_dir_opposes_moment")?,
        (false, _, Some(a)) => cx.fill("res_dir_angle", &[quantity_text(cx, a)?])?,
        (false, _, None) => cx.w("res_dir_opposes_force")?,
    };
    parts.push(sense);
    Ok((label, parts.join(", ")))
}

/// Where the centres of mass are: in the middle of every link unless the
/// task's `mass_center` of a link says otherwise (a share of the link's
/// first two joints' distance from the first, or as given).
fn mass_centres(cx: &Ctx) -> Result<String, NoteError> {
    let links = task_linkage(cx).and_then(|l| l.get("links")).and_then(toml::Value::as_array);
    let mut own = Vec::new();
    for l in links.into_iter().flatten() {
        let (Some(name), Some(mc)) = (l.get("name").and_then(toml::Value::as_str), l.get("mass_center")) else {
            continue;
        };
        let joints: Vec<&str> = l
            .get("joints")
            .and_then(toml::Value::as_array)
            .map(|a| a.iter().filter_map(toml::Value::as_str).collect())
            .unwrap_or_default();
        let along = mc
            .get("along")
            .and_then(|a| task_quantity(a).filter(|(_, u)| u.is_empty()).map(|q| q.0));
        let only_along = mc.as_table().is_some_and(|t| t.len() == 1);
        own.push(match (along, only_along, joints.as_slice()) {
            (Some(a), true, [j0, j1, ..]) if a.abs() < 1e-12 => {
                cx.fill("cm_at_joint", &[name.to_string(), (*j0).to_string(), (*j1).to_string()])?
            }
            (Some(a), true, [j0, j1, ..]) => cx.fill(
                "cm_along",
                &[name.to_string(), given_number(cx, a)?, format!("{j0}{j1}"), (*j0).to_string()],
            )?,
            _ => cx.fill("cm_given", &[name.to_string()])?,
        });
    }
    if own.is_empty() {
        return cx.w("cm_middle");
    }
    own.push(cx.w("cm_rest_middle")?);
    Ok(own.join("; "))
}

/// The planetary train's scheme in words: its wheels, the fixed one and the
/// carrier (a single-row train: sun 1, planets 2, fixed ring 3, carrier H).
fn planetary_scheme(cx: &Ctx) -> Result<Option<Block>, NoteError> {
    let Some(scheme) = cx.s("/planetary/scheme") else { return Ok(None) };
    let key = format!("pl_scheme_{}", scheme.replace('-', "_"));
    // the scheme's words are the note's own: their symbols (carrier H) stay
    // marked, unlike a caller's string filled into a place
    let words = cx.w(&key).unwrap_or_else(|_| crate::notation::strip(scheme));
    let text = cx.w("assign_pl_scheme")?.replace("{1}", &words);
    Ok(Some(Block::Paragraph(crate::model::Text::plain(text))))
}

/// The cam's phases as the task gives them: each phase's kind, angle and
/// motion law (`rise 108 const-accel(u=1/3)` → подъём | 108 | равноускоренный,
/// u = 1/3), the angles from the report's phases, the laws from the task's
/// text (the report's parameters are rounded).
fn cam_phase_rows(cx: &Ctx) -> Result<Vec<Vec<Cell>>, NoteError> {
    let phases = cx.report.pointer("/cam/phases").and_then(serde_json::Value::as_array);
    let pieces: Vec<String> = cx
        .task
        .get("cam")
        .and_then(|c| c.get("phases"))
        .and_then(toml::Value::as_str)
        .map(|s| s.split(';').map(str::trim).filter(|p| !p.is_empty()).map(str::to_string).collect())
        .unwrap_or_default();
    let mut rows = Vec::new();
    for (i, p) in phases.into_iter().flatten().enumerate() {
        let kind = p.get("kind").and_then(serde_json::Value::as_str).unwrap_or("");
        let angle = p.get("angle").and_then(serde_json::Value::as_f64).unwrap_or(0.0).to_degrees();
        // the law as the task writes it: the words after the kind and the angle
        let from_task = pieces.get(i).and_then(|piece| {
            let mut w = piece
                .split_whitespace()
                .skip(1)
                .skip_while(|w| w.starts_with(|c: char| c.is_ascii_digit() || c == '.' || c == '-') || matches!(*w, "deg" | "°"));
            let first = w.next()?;
            Some(std::iter::once(first).chain(w).collect::<Vec<_>>().join(" "))
        });
        let law = from_task.or_else(|| p.get("law").and_then(serde_json::Value::as_str).map(str::to_string));
        let law = match law {
            Some(l) => law_words(cx, &l)?,
            None => "—".to_string(),
        };
        rows.push(vec![
            text(cx.w(&format!("phase_{kind}")).unwrap_or_else(|_| kind.to_string())),
            text(given_number(cx, angle)?),
            text(law),
        ]);
    }
    Ok(rows)
}

/// A motion law's name in words with its parameters as written
/// (`const-accel(u=1/3)` → «равноускоренный (u=1/3)»); a table law without
/// its values.
fn law_words(cx: &Ctx, law: &str) -> Result<String, NoteError> {
    let (name, args) = match law.split_once('(') {
        Some((n, a)) => (n.trim(), a.trim_end().trim_end_matches(')').trim()),
        None => (law.trim(), ""),
    };
    let Ok(w) = cx.w(&format!("law_{}", name.replace('-', "_"))) else {
        return Ok(law.to_string());
    };
    Ok(if args.is_empty() || name == "table" {
        w
    } else {
        format!("{w} ({})", args.replace('-', "\u{2212}"))
    })
}
