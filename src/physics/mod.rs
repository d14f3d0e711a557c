//! The numerical core: plain Rust over f64 state, with no `App` and no `World`.
//!
//! The Bevy plugins, the CLI, the report, the tests and the benchmarks all call into this
//! module, so that there is one implementation of each force law, each integration step and
//! each named scene. Its modules import in one direction, from the leaves up:
//! `param_error`, `maths` → `body` → `forces` → `energy`, `scene` → `integrators` → `stepper`
//! → `scene`, `stability`.

pub mod body;
pub mod energy;
pub mod forces;
pub mod integrators;
pub mod maths;
pub mod param_error;
pub mod scene;
pub mod scenes;
pub mod stability;
pub mod stepper;

pub use body::{AngularState, BodyState, LinearState, MassProperties, rotate};
pub use energy::{Energies, EnergyLedger, kinetic_energy};
pub use forces::{BandEnds, ForceModel, Forces, Wrench, angular_momentum_about, damping_wrench};
pub use integrators::{AutoSettings, Integrator, StepInfo, UnknownIntegrator, symplectic_euler};
pub use param_error::{ParamError, Range};
pub use scene::{
    ANGULAR_DAMPING_RANGE, LINEAR_DAMPING_RANGE, MASS_RANGE, MIN_STEP, SCENE_SIZE, SIZE_RANGE,
    STEP_RATE_RANGE, STIFFNESS_RANGE, SceneParams, TIME_SCALE_RANGE,
};
pub use scenes::{Diverged, Pull, Run, Scene};
pub use stepper::{Booked, Books, Bound, Stepper};
