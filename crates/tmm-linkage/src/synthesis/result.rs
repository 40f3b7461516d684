//! The result of a synthesis (результат синтеза): everything the note, the
//! JSON output and the construction drawing need — the given data, the
//! lengths found, the frame points, K and θ, the stroke or swing, the pressure
//! and transmission angles found by the linkage core over the whole cycle, the
//! free parameter that was chosen and why, the construction geometry, and a
//! [`MechanismDef`] ready for analysis.

use tmm_geom::Vec2;

use crate::model::MechanismDef;

/// The kind of problem solved.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// Crank-slider (кривошипно-ползунный), axial or offset.
    CrankSlider,
    /// Crank-rocker four-bar (кривошипно-коромысловый).
    CrankRocker,
    /// Four-bar generating a function by given positions (Freudenstein).
    FunctionGeneration,
    /// Slotted-lever (кулисный) shaper mechanism.
    SlottedLever,
    /// Crank-knee press (кривошипно-коленный).
    KneePress,
    /// Six-bar in two stages (шестизвенный).
    SixBar,
    /// Lever driven by an oscillating (rocking) cylinder (механизм с
    /// качающимся гидро- или пневмоцилиндром).
    OscillatingCylinder,
    /// The textbook's П3 shaper: crank, coupler and a rocker driving the ram
    /// through a slider in its slot (поперечно-строгальный станок).
    Shaper,
}

impl Kind {
    /// Stable name for outputs.
    pub fn as_str(self) -> &'static str {
        match self {
            Kind::CrankSlider => "crank-slider",
            Kind::CrankRocker => "crank-rocker",
            Kind::FunctionGeneration => "function-generation",
            Kind::SlottedLever => "slotted-lever",
            Kind::KneePress => "knee-press",
            Kind::SixBar => "six-bar",
            Kind::OscillatingCylinder => "oscillating-cylinder",
            Kind::Shaper => "shaper",
        }
    }
}

/// The stroke of the output: travel of a slider or swing of a rocker.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Stroke {
    /// Slider travel H, m.
    Linear(f64),
    /// Rocker swing ψ, rad.
    Angular(f64),
}

/// The free parameter left by the given data and how it was fixed.
#[derive(Debug, Clone, PartialEq)]
pub struct FreeParameter {
    /// What it is (`offset e`, `position of the crank pivot on the locus`).
    pub name: String,
    /// Its value (SI, rad).
    pub value: f64,
    /// Why this value: the extra condition given, or the optimum chosen.
    pub reason: String,
}

/// The inscribed-angle locus (геометрическое место центров вращения
/// кривошипа): the circle through the two extreme positions whose centre sees
/// the chord between them at 2θ, and the arc of it from which the chord is
/// seen at θ.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LocusCircle {
    /// Centre O* of the circle, m.
    pub center: Vec2,
    /// Radius R* = |C1C2| / (2 sin θ), m.
    pub radius: f64,
    /// Where the arc of the locus starts, as the angle of (point − centre), rad.
    pub arc_start: f64,
    /// Signed sweep of the arc, rad (positive counter-clockwise).
    pub arc_sweep: f64,
}

/// The construction of the graphical method, for the drawing.
#[derive(Debug, Clone, PartialEq)]
pub struct Construction {
    /// Name of the point whose two extreme positions start the construction.
    pub point: String,
    /// Its two extreme positions (C′, C″), m (for a function generator: its
    /// positions at the first and the last given crank angle).
    pub extremes: [Vec2; 2],
    /// The circle seen at 2θ from its centre and its arc of pivots, when the
    /// construction uses one (θ > 0); for θ = 0 the pivot lies on the line
    /// through the extremes.
    pub locus: Option<LocusCircle>,
    /// The chosen crank pivot, m.
    pub pivot: Vec2,
    /// Other lines of the construction as segments (e.g. the rays of the
    /// pressure-angle condition, the inverted guide of a six-bar), m.
    pub lines: Vec<(String, Vec2, Vec2)>,
}

/// Values found by the linkage core over the whole cycle.
#[derive(Debug, Clone, PartialEq)]
pub struct CheckReport {
    /// K achieved (slower stroke over the faster), when the crank turns fully.
    pub k: Option<f64>,
    /// θ achieved, rad.
    pub theta: Option<f64>,
    /// Stroke or swing of the output.
    pub stroke: Option<Stroke>,
    /// Largest pressure angle on the working and return strokes, rad (the
    /// largest over the whole range for a function generator, twice).
    pub pressure_angle_max: (f64, f64),
    /// Smallest transmission angle γ = 90° − ϑ over the cycle, rad.
    pub transmission_angle_min: f64,
    /// Whether the crank turns fully (проворачиваемость кривошипа).
    pub crank_turns_fully: bool,
    /// The assembly branch, in words (the hint the description uses).
    pub branch: String,
    /// Crank angles of the two dead positions (start of the working stroke
    /// first), rad.
    pub dead_phi: Vec<f64>,
    /// Every named point at each dead position, m.
    pub dead_positions: Vec<Vec<(String, Vec2)>>,
}

/// A synthesised mechanism.
#[derive(Debug, Clone, PartialEq)]
pub struct Synthesis {
    /// The problem kind.
    pub kind: Kind,
    /// The given data, SI (angles in rad), by name.
    pub given: Vec<(String, f64)>,
    /// The lengths found, m, by name (`OA`, `AB`, `e`, …).
    pub lengths: Vec<(String, f64)>,
    /// Fixed points of the frame, m.
    pub frame: Vec<(String, Vec2)>,
    /// K requested (1 for a function generator).
    pub k: f64,
    /// θ requested, rad.
    pub theta: f64,
    /// The stroke or swing requested.
    pub stroke: Option<Stroke>,
    /// The free parameter and how it was chosen.
    pub free_parameter: Option<FreeParameter>,
    /// The construction geometry.
    pub construction: Construction,
    /// The mechanism, ready for analysis (assembly hint and ω1 included).
    pub def: MechanismDef,
    /// The independent check by the linkage core.
    pub check: CheckReport,
    /// Further unknowns found that are angles (φ1н, θ, φ2j, φ3н, …), rad,
    /// by name; empty for the kinds whose lengths say everything.
    pub angles: Vec<(String, f64)>,
    /// Further unknowns found that are coordinates (X_D, X_Cн, …), m, by name.
    pub coordinates: Vec<(String, f64)>,
    /// Crank angles at which the drawing shows the mechanism (the given
    /// positions of a problem by positions), rad; empty: the dead positions.
    pub shown: Vec<f64>,
}

impl Synthesis {
    /// A length by name.
    pub fn length(&self, name: &str) -> Option<f64> {
        self.lengths.iter().find(|(n, _)| n == name).map(|(_, v)| *v)
    }
    /// Largest pressure angle on the working and return strokes found by the
    /// check, rad.
    pub fn pressure_angle_max(&self) -> (f64, f64) {
        self.check.pressure_angle_max
    }
    /// Smallest transmission angle found by the check, rad.
    pub fn transmission_angle_min(&self) -> f64 {
        self.check.transmission_angle_min
    }
    /// Overall size: the diagonal of the box holding every point at both dead
    /// positions and the frame points, m.
    pub fn overall_size(&self) -> f64 {
        let mut lo = Vec2::new(f64::INFINITY, f64::INFINITY);
        let mut hi = Vec2::new(f64::NEG_INFINITY, f64::NEG_INFINITY);
        let pts = self
            .frame
            .iter()
            .map(|(_, p)| *p)
            .chain(self.check.dead_positions.iter().flat_map(|v| v.iter().map(|(_, p)| *p)));
        for p in pts {
            lo = Vec2::new(lo.x.min(p.x), lo.y.min(p.y));
            hi = Vec2::new(hi.x.max(p.x), hi.y.max(p.y));
        }
        if lo.x.is_finite() { (hi - lo).hypot() } else { 0.0 }
    }
}
