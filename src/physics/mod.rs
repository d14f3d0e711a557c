//! The numerical core: plain Rust over f64 state, with no `App` and no `World`.
//!
//! The Bevy plugins, the tests and the benchmarks all call into this module, so that there is
//! one implementation of each force law and each integration step.

pub mod auto;
pub mod body;
pub mod dop853;
pub mod engine_state;
pub mod forces;
pub mod integrators;
pub mod ledger;
pub mod scenario;
pub mod scene;
pub mod simulation;
pub mod taylor;

pub use auto::{AutoSettings, StepInfo};
pub use body::{AngularState, BodyState, LinearState, MassProperties, rotate};
pub use forces::{
    BandEnds, ForceModel, Forces, Wrench, angular_momentum_about, damping_wrench, kinetic_energy,
};
pub use integrators::{Integrator, UnknownIntegrator, symplectic_euler};
pub use ledger::{Energies, EnergyLedger};
pub use scenario::{Diverged, Drag, Run, Scenario};
pub use scene::{ParamError, SCENE_SIZE, SceneParams};
pub use simulation::Simulation;
