//! Planetary (2K-H) gear trains (планетарные механизмы): the tooth numbers for
//! a ratio and a number of planets, every condition of the course, the
//! efficiency, and the linear- and angular-velocity pictures. No I/O.
//!
//! - [`scheme`]: the four schemes, tooth numbers, Willis' ratio, coaxiality,
//!   radial size.
//! - [`conditions`]: no undercut, internal-mesh limits, assembly, neighbour.
//! - [`search`]: the enumeration and ranking ([`synthesize`]).
//! - [`efficiency`]: the efficiency from the mesh efficiencies.
//! - [`picture`]: the velocity picture and the angular-velocity diagram.
//! - [`error`]: typed errors.
//!
//! ```
//! use tmm_planetary::{synthesize, Request, Scheme};
//! let s = synthesize(&Request::new(Scheme::SunPlanetRing, 4.0, 3)).unwrap();
//! assert_eq!(s.best().teeth.to_vec(Scheme::SunPlanetRing), vec![30, 30, 90]);
//! ```

pub mod conditions;
pub mod efficiency;
pub mod error;
pub mod picture;
pub mod scheme;
pub mod search;

pub use conditions::Limits;
pub use efficiency::MeshEfficiency;
pub use error::{Condition, PlanetaryError};
pub use scheme::{Driver, Mesh, ModuleRatio, Scheme, Teeth};
pub use search::{Candidate, Counts, Request, Synthesis, enumerate_into, synthesize};
