//! Metric synthesis of lever mechanisms (метрический синтез рычажных
//! механизмов), stage 1 of the course project: the lengths and the frame of a
//! mechanism from what the task gives — the time ratio K (Kv, Kω), the stroke
//! or swing, extreme or given positions, the mean speed, the allowed pressure
//! angles — each problem solved exactly (closed form where one exists, else a
//! search that needs no first guess), each stating the extra condition it
//! uses when the data leave a free parameter, and each result checked by the
//! linkage core over the whole cycle ([`check`]).
//!
//! Derivations: docs/synthesis.md. Sources: seed 000 § 1.2 (crank-slider),
//! seed 002 examples 1–4, seed 003 §§ 3–4, Artobolevsky, ТММ, 1988, § 26;
//! the BMSTU textbook's appendix П1 (Chernaya & Timofeev 2019).
//!
//! ```
//! use tmm_linkage::synthesis::crank_slider::*;
//! use tmm_linkage::synthesis::Drive;
//! // H = 0.3 m, K = 1.2, λ2 = l2/l1 = 3.5
//! let r = CrankSliderRequest { stroke: 0.3, k: 1.2, condition: SliderCondition::Lambda(3.5),
//!     drive: Drive::default(), limits: Default::default() };
//! let s = synthesize(&r).unwrap();
//! let (l1, l2) = (s.length("OA").unwrap(), s.length("AB").unwrap());
//! assert!((l2 / l1 - 3.5).abs() < 1e-12);
//! assert!((s.check.k.unwrap() - 1.2).abs() < 1e-9);
//! ```

pub mod check;
pub mod crank_rocker;
pub mod crank_slider;
pub mod cylinder;
pub mod error;
pub mod function_gen;
pub mod knee_bell_crank;
pub mod knee_press;
pub mod limits;
pub mod locus;
pub mod pivot;
pub mod placement;
pub mod request;
pub mod result;
pub mod rocker_extremes;
pub mod search;
pub mod shaper;
pub mod six_bar;
pub mod slotted;
pub mod sweep;
pub mod three_positions;
pub mod time_ratio;

pub use error::SynthesisError;
pub use limits::{Drive, Limits, Rotation};
pub use request::{Request, synthesize};
pub use result::{CheckReport, Construction, FreeParameter, Kind, LocusCircle, Stroke, Synthesis};
