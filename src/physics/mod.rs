//! The numerical core: plain Rust over f64 state, with no `App` and no `World`.
//!
//! The Bevy plugins, the tests and the benchmarks all call into this module, so that there is
//! one implementation of each force law and each integration step.

pub mod body;
pub mod forces;
pub mod integrate;
pub mod scene;
pub mod simulation;

pub use body::{AngularState, BodyState, LinearState, MassProperties, rotate};
pub use forces::{BandEnds, Wrench, damping_wrench, kinetic_energy};
pub use integrate::symplectic_euler;
pub use scene::{ParamError, SCENE_SIZE, SceneParams};
pub use simulation::Simulation;
