//! The `auto` integrator: every fixed step split into as many RK4 substeps as the current
//! stiffness and motion need for the error per step to stay under a tolerance, capped by a
//! per-step budget; where the cap binds, one backward Euler step instead, which is stable at
//! any stiffness. So `auto` is accurate where it can afford to be, and never unstable.

use bevy::prelude::Resource;

use super::body::BodyState;
use super::forces::{ForceModel, Forces};

/// The settings of `auto`; defaults from the report's stiffness sweep (see README).
#[derive(Resource, Clone, Copy, Debug, PartialEq)]
pub struct AutoSettings {
    /// Target error per fixed step, in world units (px) of corner displacement.
    pub tolerance: f64,
    /// Most RK4 substeps per fixed step (about 80 ns each) before falling back to `implicit`.
    /// Counted in substeps, not measured time, so that runs stay bit-identical everywhere.
    pub max_substeps: u32,
}

impl Default for AutoSettings {
    fn default() -> Self {
        Self {
            tolerance: 1e-7,
            max_substeps: 512,
        }
    }
}

/// What one fixed step cost: how many substeps, and whether it fell back to `implicit`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct StepInfo {
    pub substeps: u32,
    pub fell_back: bool,
}

impl StepInfo {
    pub const SINGLE: Self = Self {
        substeps: 1,
        fell_back: false,
    };
}

/// The fastest rate in the system right now (per second): the band's stiffest mode
/// ω = sqrt(k (1/m + |r|²/I)) (2·sqrt(k/m) for a square pulled at a corner), the damping
/// rates, and the spin.
pub fn fastest_rate(state: &BodyState, model: &ForceModel) -> f64 {
    let mass = &model.mass;
    let band = model.band.map_or(0.0, |band| {
        let arm_squared = band.local_point.length_squared();
        (model.stiffness * (mass.inverse_mass() + arm_squared * mass.inverse_inertia())).sqrt()
    });
    let (linear_rate, angular_rate) = model.damping_rates();
    band.max(linear_rate)
        .max(angular_rate)
        .max(state.angular.angular_velocity.abs())
}

/// How far the step's error can reach (px): the band's stretch, the distance the velocities
/// cover on the fastest time scale, and the corners' reach.
fn length_scale(state: &BodyState, model: &ForceModel, rate: f64) -> f64 {
    let stretch = model.band.map_or(0.0, |band| band.length(state));
    let reach = 0.5 * model.mass.size().length();
    let speed = state.linear.velocity.length() + reach * state.angular.angular_velocity.abs();
    stretch + speed / rate.max(1.0) + reach
}

/// RK4's local error on a mode of rate λ over a substep h is about A (λh)⁵ / 120 for a motion
/// of amplitude A; over n substeps of dt/n, n A (λ dt/n)⁵ / 120 <= tolerance gives n.
pub fn substeps_needed(
    state: &BodyState,
    model: &ForceModel,
    dt: f64,
    settings: &AutoSettings,
) -> u64 {
    let rate = fastest_rate(state, model);
    let amplitude = length_scale(state, model, rate);
    let x = rate * dt; // λ·dt of the whole step
    if !(x.is_finite() && amplitude.is_finite()) {
        return u64::MAX;
    }
    // n⁴ >= A x⁵ / (120 tol)
    let n = (amplitude * x.powi(5) / (120.0 * settings.tolerance)).powf(0.25);
    // RK4 is stable for λh < 2.78: never take a substep near that.
    let stable = x / 2.0;
    n.max(stable).ceil().clamp(1.0, u64::MAX as f64) as u64
}

/// One fixed step of `auto`.
pub fn auto_step(
    state: &mut BodyState,
    model: &ForceModel,
    start: Forces,
    dt: f64,
    settings: &AutoSettings,
    rk4: impl Fn(&mut BodyState, &ForceModel, Forces, f64),
    implicit: impl Fn(&mut BodyState, &ForceModel, f64),
) -> StepInfo {
    let n = substeps_needed(state, model, dt, settings);
    if n > u64::from(settings.max_substeps) {
        implicit(state, model, dt);
        return StepInfo {
            substeps: 1,
            fell_back: true,
        };
    }
    let h = dt / n as f64;
    rk4(state, model, start, h);
    for _ in 1..n {
        let forces = model.forces(state);
        rk4(state, model, forces, h);
    }
    StepInfo {
        substeps: n as u32,
        fell_back: false,
    }
}
