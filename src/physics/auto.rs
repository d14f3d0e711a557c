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
            tolerance: 1e-8,
            max_substeps: 2048,
        }
    }
}

/// What one fixed step did: how many substeps, whether it fell back to `implicit`, and the
/// energy damping took out during it (for the energy ledger).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct StepInfo {
    pub substeps: u32,
    pub fell_back: bool,
    pub dissipated: f64,
}

impl StepInfo {
    pub const SINGLE: Self = Self {
        substeps: 1,
        fell_back: false,
        dissipated: 0.0,
    };
}

/// The band's stiffest mode: ω = sqrt(k (1/m + |r|²/I)), 2·sqrt(k/m) for a square pulled at
/// a corner.
pub fn band_rate(model: &ForceModel) -> f64 {
    let mass = &model.mass;
    model.band.map_or(0.0, |band| {
        let arm_squared = band.local_point.length_squared();
        (model.stiffness * (mass.inverse_mass() + arm_squared * mass.inverse_inertia())).sqrt()
    })
}

/// C in RK4's local error C·h⁵ per substep of length h, from the motion now.
///
/// Each mode of rate λ and amplitude A contributes A λ⁵ / 120 (the first term RK4 drops):
/// the band's oscillation (amplitude: its stretch plus how far the corner's speed carries it
/// on the band's time scale), the band's force turning with the spin ω (its displacement scale
/// A λ²/ω² changing at the rate ω: A λ² ω³), and the two decays of the velocities.
fn error_coefficient(state: &BodyState, model: &ForceModel) -> f64 {
    let lambda = band_rate(model);
    let spin = state.angular.angular_velocity.abs();
    let (linear_rate, angular_rate) = model.damping_rates();
    let reach = 0.5 * model.mass.size().length();
    let band = model.band.map_or(0.0, |band| {
        let corner_speed = state.linear.velocity.length() + reach * spin;
        let amplitude = band.length(state) + corner_speed / lambda.max(1e-300) + reach;
        amplitude * (lambda.powi(5) + lambda * lambda * spin.powi(3))
    });
    let decay =
        state.linear.velocity.length() * linear_rate.powi(4) + reach * spin * angular_rate.powi(4);
    (band + decay) / 120.0
}

/// Substeps for the error per step to stay under the tolerance: n substeps of dt/n make an
/// error of about n C (dt/n)⁵, so n⁴ >= C dt⁵ / tolerance. Never a substep near RK4's
/// stability limit (λh < 2.78) either.
pub fn substeps_needed(
    state: &BodyState,
    model: &ForceModel,
    dt: f64,
    settings: &AutoSettings,
) -> u64 {
    let (linear_rate, angular_rate) = model.damping_rates();
    let fastest = band_rate(model)
        .max(linear_rate)
        .max(angular_rate)
        .max(state.angular.angular_velocity.abs());
    let accurate = (error_coefficient(state, model) * dt.powi(5) / settings.tolerance).powf(0.25);
    let stable = fastest * dt / 1.5;
    let n = accurate.max(stable).ceil();
    if n.is_finite() {
        n.clamp(1.0, u64::MAX as f64) as u64
    } else {
        u64::MAX
    }
}

/// One fixed step of `auto`.
pub fn auto_step(
    state: &mut BodyState,
    model: &ForceModel,
    start: Forces,
    dt: f64,
    settings: &AutoSettings,
    rk4: impl Fn(&mut BodyState, &ForceModel, Forces, f64) -> f64,
    implicit: impl Fn(&mut BodyState, &ForceModel, f64),
) -> StepInfo {
    let n = substeps_needed(state, model, dt, settings);
    if n > u64::from(settings.max_substeps) {
        let before = *state;
        implicit(state, model, dt);
        return StepInfo {
            substeps: 1,
            fell_back: true,
            dissipated: model.dissipated_by_trapezoid(&before, state, dt),
        };
    }
    let h = dt / n as f64;
    let mut dissipated = rk4(state, model, start, h);
    for _ in 1..n {
        let forces = model.forces(state);
        dissipated += rk4(state, model, forces, h);
    }
    StepInfo {
        substeps: n as u32,
        fell_back: false,
        dissipated,
    }
}
