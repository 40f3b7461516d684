//! The description of a planar lever mechanism (описание механизма): links
//! as rigid bodies with named points in local coordinates, fixed points of the
//! frame (стойка), prismatic pairs (поступательные пары) as a slider on a guide
//! line carried by another link, the input crank (кривошип) and assembly hints.
//!
//! Revolute pairs (вращательные пары) are not listed: a point name that appears
//! on two links (or on a link and in the frame's fixed points) *is* a revolute
//! pair there. This is how the course's assignments name mechanisms (A, B, C…).
//!
//! Local frame of a link: origin at its first point, x-axis towards its second
//! point (for a link with a single point — a slider block — the x-axis is the
//! direction of the guide it slides on).

use tmm_geom::Vec2;

/// The name of the frame (стойка, link 0) in descriptions.
pub const FRAME: &str = "frame";

/// A moving link (звено) with its named points in local coordinates.
#[derive(Debug, Clone, PartialEq)]
pub struct LinkDef {
    /// The user's name (`"1"`, `"crank"`, `"BEC"`).
    pub name: String,
    /// Named points on the link in local coordinates, m. Joints (pairs) and any
    /// other point of interest (centre of mass `S…`, a tracer point).
    pub points: Vec<(String, Vec2)>,
    /// Centre of mass in local coordinates (центр масс), m.
    pub mass_center: Vec2,
}

/// A prismatic pair: the slider (ползун, камень кулисы) `slider` moves along
/// a straight guide (направляющая) fixed on link `guide_link`.
#[derive(Debug, Clone, PartialEq)]
pub struct SliderDef {
    /// Link that slides.
    pub slider: String,
    /// Point of the slider that stays on the guide line (a point of `slider`).
    pub point: String,
    /// Link carrying the guide, or [`FRAME`].
    pub guide_link: String,
    /// A point of the guide line in the guide link's local coordinates
    /// (global coordinates for the frame), m.
    pub through: Vec2,
    /// Direction of the guide in the guide link's local frame (global for the
    /// frame), rad.
    pub angle: f64,
    /// Direction of the guide as seen in the slider's own local frame, rad
    /// (0 for a slider block, whose x-axis is the guide).
    pub angle_on_slider: f64,
}

/// The input link: a crank turning about a fixed pivot at constant speed.
#[derive(Debug, Clone, PartialEq)]
pub struct InputDef {
    /// The crank link.
    pub link: String,
    /// The fixed pivot of the crank (a point of the crank and of the frame).
    pub pivot: String,
    /// The crank pin: the crank angle φ is the absolute angle of pivot → pin.
    pub pin: String,
    /// Angular velocity, rad/s, signed (> 0 counter-clockwise).
    pub omega: f64,
    /// Angular acceleration of the crank, rad/s² (0: uniform rotation).
    pub epsilon: f64,
}

impl InputDef {
    /// A crank `link` turning uniformly about `pivot` at `omega` (rad/s,
    /// > 0 counter-clockwise), its angle measured towards `pin`.
    ///
    /// ```
    /// let i = tmm_linkage::InputDef::crank("1", "O", "A", 94.2);
    /// assert_eq!((i.pin.as_str(), i.omega, i.epsilon), ("A", 94.2, 0.0));
    /// ```
    pub fn crank(link: &str, pivot: &str, pin: &str, omega: f64) -> Self {
        InputDef {
            link: link.into(),
            pivot: pivot.into(),
            pin: pin.into(),
            omega,
            epsilon: 0.0,
        }
    }
}

/// The input link as a slider (ведущий ползун) on a guide fixed to the
/// frame, driven along it at a given speed: the input coordinate is the
/// slider's travel s (m) along the guide from the guide's `through` point,
/// `s = (P − Q)·d` with P the slider's point, Q `through` and d the guide's
/// unit direction (docs/linkage.md, "A slider as the input").
#[derive(Debug, Clone, PartialEq)]
pub struct SliderInputDef {
    /// The driving slider: a link listed in [`MechanismDef::sliders`] on a
    /// guide of the frame.
    pub link: String,
    /// ds/dt, m/s, signed (> 0: s increases).
    pub speed: f64,
    /// d²s/dt², m/s² (0: constant speed).
    pub acceleration: f64,
}

impl SliderInputDef {
    /// A slider `link` driven at the constant speed `speed` (m/s).
    ///
    /// ```
    /// let i = tmm_linkage::SliderInputDef::new("3", 0.5);
    /// assert_eq!((i.link.as_str(), i.speed, i.acceleration), ("3", 0.5, 0.0));
    /// ```
    pub fn new(link: &str, speed: f64) -> Self {
        SliderInputDef {
            link: link.into(),
            speed,
            acceleration: 0.0,
        }
    }
}

/// Where a point should be at assembly, to choose the branch (вариант сборки).
#[derive(Debug, Clone, PartialEq)]
pub enum HintKind {
    /// Above the line through two points: larger y than the line at the
    /// same x, for any slope. A line within 1e-9 rad of vertical has no
    /// "above": the hint is refused (use left of / right of).
    Above(String, String),
    /// Below the line through two points (smaller y at the same x).
    Below(String, String),
    /// Left of the line through two points: smaller x than the line at the
    /// same y. A line within 1e-9 rad of horizontal has no "left": refused
    /// (use above / below).
    LeftOf(String, String),
    /// Right of the line through two points (larger x at the same y).
    RightOf(String, String),
    /// Near a global position (the closest assembly wins).
    Near(Vec2),
}

impl std::fmt::Display for HintKind {
    /// As a task file writes it: `above line A–D`, `near (0.6, 0) m`.
    ///
    /// ```
    /// use tmm_linkage::HintKind;
    /// assert_eq!(HintKind::Below("A".into(), "D".into()).to_string(), "below line A–D");
    /// assert_eq!(HintKind::Near(tmm_geom::Vec2::new(0.6, 0.0)).to_string(), "near (0.6, 0) m");
    /// ```
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            HintKind::Above(a, b) => write!(f, "above line {a}–{b}"),
            HintKind::Below(a, b) => write!(f, "below line {a}–{b}"),
            HintKind::LeftOf(a, b) => write!(f, "left of line {a}–{b}"),
            HintKind::RightOf(a, b) => write!(f, "right of line {a}–{b}"),
            HintKind::Near(p) => write!(f, "near ({}, {}) m", p.x, p.y),
        }
    }
}

impl std::fmt::Display for AssemblyHint {
    /// `C below line A–D`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{} {}", self.point, self.kind)
    }
}

/// An assembly hint for one point, evaluated at the assembly crank angle.
#[derive(Debug, Clone, PartialEq)]
pub struct AssemblyHint {
    /// The point the hint is about.
    pub point: String,
    /// The condition.
    pub kind: HintKind,
}

/// A whole mechanism as described by the user.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct MechanismDef {
    /// Fixed points of the frame in global coordinates, m.
    pub fixed: Vec<(String, Vec2)>,
    /// Moving links.
    pub links: Vec<LinkDef>,
    /// Prismatic pairs.
    pub sliders: Vec<SliderDef>,
    /// The input crank (none when the input is a slider).
    pub input: Option<InputDef>,
    /// The input slider on a fixed guide, instead of a crank.
    pub slider_input: Option<SliderInputDef>,
    /// Assembly hints.
    pub hints: Vec<AssemblyHint>,
    /// The input coordinate at which the hints hold: the crank angle, rad,
    /// or for a slider input its travel s, m.
    pub assembly_angle: f64,
    /// The output link (выходное звено), whose motion gives the dead positions,
    /// the stroke and Kv. Default: the last link of the last group.
    pub output: Option<String>,
}

impl LinkDef {
    /// A two-point link (a bar) of the given length along its x-axis, mass
    /// centre mid-way: `joints[0]` at the origin, `joints[1]` at `(length, 0)`.
    ///
    /// ```
    /// let l = tmm_linkage::LinkDef::bar("2", "B", "C", 0.48);
    /// assert_eq!(l.points[1].1.x, 0.48);
    /// assert_eq!(l.mass_center.x, 0.24);
    /// ```
    pub fn bar(name: &str, a: &str, b: &str, length: f64) -> Self {
        LinkDef {
            name: name.to_string(),
            points: vec![(a.to_string(), Vec2::ZERO), (b.to_string(), Vec2::new(length, 0.0))],
            mass_center: Vec2::new(0.5 * length, 0.0),
        }
    }

    /// A slider block with one point at its origin.
    pub fn block(name: &str, point: &str) -> Self {
        LinkDef {
            name: name.to_string(),
            points: vec![(point.to_string(), Vec2::ZERO)],
            mass_center: Vec2::ZERO,
        }
    }

    /// Local coordinates of a named point.
    pub fn point(&self, name: &str) -> Option<Vec2> {
        self.points.iter().find(|(n, _)| n == name).map(|(_, p)| *p)
    }
}
