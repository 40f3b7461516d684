//! The indicator diagram of a cylinder (индикаторная диаграмма): gauge
//! pressure against the piston's travel from its outer dead centre
//! (верхняя мёртвая точка), one table per process of the working cycle —
//! intake, compression, expansion, exhaust of a four-stroke engine
//! (всасывание, сжатие, расширение, выпуск); compression, delivery,
//! re-expansion, suction of a compressor — each process chosen by the
//! angle of the machine's cycle (Chernaya & Timofeev 2019, П2: "the phase is
//! chosen by the φ interval [kπ, (k+1)π)").
//!
//! The tables give the travel in metres or as a fraction h/H of the stroke,
//! and the pressure in any unit (a scale to pascals is given: 1 for Pa,
//! 1e5 for bar, 1e6 for MPa, p_max for a fraction of the largest pressure).

use super::error::ForceError;
use super::spline::Curve;

/// How the travel of a table is given.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TravelScale {
    /// In metres.
    Metres,
    /// As a fraction of the stroke H (0…1).
    Stroke,
}

impl TravelScale {
    /// The table's abscissa for travel `s` (m) of a stroke `h` (m).
    #[inline]
    pub fn abscissa(self, s: f64, h: f64) -> f64 {
        match self {
            TravelScale::Metres => s,
            TravelScale::Stroke => s / h,
        }
    }

    /// The end of the stroke in the table's abscissa.
    pub fn end(self, h: f64) -> f64 {
        match self {
            TravelScale::Metres => h,
            TravelScale::Stroke => 1.0,
        }
    }
}

/// One process of the cycle: the span of the machine's cycle angle where a
/// table applies.
#[derive(Debug, Clone, PartialEq)]
pub struct Process {
    /// Its name (for messages and tables): `intake`, `compression`, …
    pub name: String,
    /// Start, cycle angle, rad (inclusive).
    pub from: f64,
    /// End, cycle angle, rad (exclusive, the last one inclusive).
    pub to: f64,
    /// Index into [`Indicator::tables`].
    pub table: usize,
}

/// The indicator diagram of one cylinder.
#[derive(Debug, Clone, PartialEq)]
pub struct Indicator {
    /// Pressure tables by travel (pressure in the given unit).
    pub tables: Vec<Curve>,
    /// Their names (`expansion`, …), as `tables`.
    pub names: Vec<String>,
    /// How the travel is given.
    pub travel: TravelScale,
    /// Pascals per unit of the tables' pressure.
    pub pressure_scale: f64,
    /// The processes over the machine's cycle, in increasing order, tiling it.
    pub processes: Vec<Process>,
}

impl Indicator {
    /// Check against the machine's cycle `period` (rad) and the stroke `h`
    /// (m): every table covers the stroke, the processes tile the cycle
    /// without gaps or overlaps. `field` names the diagram in messages.
    pub fn check(&self, period: f64, h: f64, field: &str) -> Result<(), ForceError> {
        if !(self.pressure_scale.is_finite() && self.pressure_scale > 0.0) {
            return Err(ForceError::load(
                format!("{field}.pressure"),
                format!("the pressure unit must be > 0 Pa, not {}", self.pressure_scale),
            ));
        }
        let end = self.travel.end(h);
        let tol = 1e-9 * end;
        for (t, name) in self.tables.iter().zip(&self.names) {
            if t.first() > tol || t.last() < end - tol {
                let unit = match self.travel {
                    TravelScale::Metres => " m",
                    TravelScale::Stroke => "·H",
                };
                return Err(ForceError::load(
                    format!("{field}.tables.{name}"),
                    format!(
                        "the table covers travel {}{unit}…{}{unit} but the stroke is 0…{}{unit}; give pressures over the whole stroke",
                        t.first(),
                        t.last(),
                        end
                    ),
                ));
            }
        }
        let ptol = 1e-9 * period;
        let mut at = 0.0;
        for p in &self.processes {
            if p.table >= self.tables.len() {
                return Err(ForceError::load(
                    format!("{field}.processes.{}", p.name),
                    format!("no pressure table `{}` for this process", p.name),
                ));
            }
            if (p.from - at).abs() > ptol || p.to <= p.from {
                return Err(ForceError::load(
                    format!("{field}.processes"),
                    format!(
                        "the processes must follow one another over the cycle without gaps or overlaps: `{}` starts at {:.4}° where the cycle is at {:.4}°",
                        p.name,
                        p.from.to_degrees(),
                        at.to_degrees()
                    ),
                ));
            }
            at = p.to;
        }
        if (at - period).abs() > ptol {
            return Err(ForceError::load(
                format!("{field}.processes"),
                format!(
                    "the processes cover the cycle up to {:.4}° of its {:.4}°; every angle of the cycle needs a process",
                    at.to_degrees(),
                    period.to_degrees()
                ),
            ));
        }
        Ok(())
    }

    /// The process at cycle angle `psi` (rad, in [0, period]).
    #[inline]
    pub fn process(&self, psi: f64) -> &Process {
        let last = self.processes.len() - 1;
        self.processes[..last].iter().find(|p| psi < p.to).unwrap_or(&self.processes[last])
    }

    /// Gauge pressure, Pa, at cycle angle `psi` (rad) and travel `s` (m)
    /// from the outer dead centre of a stroke `h` (m). Allocates nothing.
    #[inline]
    pub fn pressure(&self, psi: f64, s: f64, h: f64) -> f64 {
        let p = self.process(psi);
        self.tables[p.table].eval(self.travel.abscissa(s, h)) * self.pressure_scale
    }
}
