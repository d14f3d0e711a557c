//! The `auto` integrator: every fixed step split into as many Taylor-series steps as the
//! series' own error estimate needs to stay under a tolerance (see [`super::taylor`]), within
//! a per-step budget; a step that would need more falls back to one backward Euler step
//! ([`super::implicit`]), which is stable at any stiffness. So `auto` is accurate where it can
//! afford to be, and never unstable.

use bevy::prelude::Resource;

use super::implicit::backward_euler;
use super::step_info::StepInfo;
use super::taylor::{self, TaylorSettings};
use crate::physics::body::BodyState;
use crate::physics::forces::ForceModel;

/// The settings of `auto`.
///
/// The defaults come from the report's engine comparison and stiffness sweep
/// (docs/integrators.md).
#[derive(Resource, Clone, Copy, Debug, PartialEq)]
pub struct AutoSettings {
    /// Target error per Taylor step, in world units (px) of corner displacement.
    pub tolerance: f64,
    /// The order of the Taylor series.
    pub order: usize,
    /// Most Taylor steps per fixed step before falling back to `implicit`.
    ///
    /// Counted in steps, not measured time, so that runs stay bit-identical everywhere.
    pub max_substeps: u32,
}

/// The order of `auto`'s series by default.
///
/// Chosen by measured cost and error on the stiff pulls at the default tolerance
/// (docs/integrators.md).
pub const DEFAULT_ORDER: usize = 28;

impl Default for AutoSettings {
    fn default() -> Self {
        Self {
            tolerance: 3e-11,
            order: DEFAULT_ORDER,
            max_substeps: 200,
        }
    }
}

/// Advances `state` by one fixed step of `auto`.
pub fn auto_step(
    state: &mut BodyState,
    model: &ForceModel,
    dt: f64,
    settings: &AutoSettings,
) -> StepInfo {
    let engine = TaylorSettings {
        order: settings.order,
        tolerance: settings.tolerance,
        max_steps: settings.max_substeps,
    };
    match taylor::integrate(state, model, dt, &engine) {
        Some(done) => {
            *state = done.state;
            StepInfo {
                substeps: done.steps,
                evaluations: done.orders,
                fell_back: false,
                dissipated: done.dissipated,
            }
        }
        None => {
            let before = *state;
            let evaluations = backward_euler(state, model, dt);
            StepInfo {
                substeps: 1,
                evaluations,
                fell_back: true,
                dissipated: model.dissipated_by_trapezoid(&before, state, dt),
            }
        }
    }
}
