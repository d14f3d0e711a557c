//! The `auto` integrator: every fixed step split into as many Taylor-series steps as the
//! series' own error estimate needs to stay under a tolerance (see [`super::taylor`]), capped
//! by a per-step budget; where the cap binds, one backward Euler step instead, which is stable
//! at any stiffness. So `auto` is accurate where it can afford to be, and never unstable.

use bevy::prelude::Resource;

use super::body::BodyState;
use super::forces::ForceModel;
use super::taylor::{self, TaylorSettings};

/// The settings of `auto`; defaults from the report's engine comparison and stiffness sweep
/// (see README).
#[derive(Resource, Clone, Copy, Debug, PartialEq)]
pub struct AutoSettings {
    /// Target error per Taylor step, in world units (px) of corner displacement.
    pub tolerance: f64,
    /// The order of the Taylor series.
    pub order: usize,
    /// Most Taylor steps per fixed step before falling back to `implicit`. Counted in steps,
    /// not measured time, so that runs stay bit-identical everywhere.
    pub max_substeps: u32,
}

impl Default for AutoSettings {
    fn default() -> Self {
        Self {
            tolerance: 1e-10,
            order: 20,
            max_substeps: 200,
        }
    }
}

/// What one fixed step did: how many substeps and how much work, whether it fell back to
/// `implicit`, and the energy damping took out during it (for the energy ledger).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct StepInfo {
    pub substeps: u32,
    /// Force-law evaluations the step made, the one at its start included (for `auto`, one
    /// per order of each Taylor step): the work done, counted rather than timed.
    pub evaluations: u32,
    pub fell_back: bool,
    pub dissipated: f64,
}

impl StepInfo {
    pub const SINGLE: Self = Self {
        substeps: 1,
        evaluations: 1,
        fell_back: false,
        dissipated: 0.0,
    };
}

/// One fixed step of `auto`.
pub fn auto_step(
    state: &mut BodyState,
    model: &ForceModel,
    dt: f64,
    settings: &AutoSettings,
    implicit: impl Fn(&mut BodyState, &ForceModel, f64) -> u32,
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
            let evaluations = implicit(state, model, dt);
            StepInfo {
                substeps: 1,
                evaluations,
                fell_back: true,
                dissipated: model.dissipated_by_trapezoid(&before, state, dt),
            }
        }
    }
}
