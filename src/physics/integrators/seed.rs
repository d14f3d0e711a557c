//! The `seed` integrator: the tutorial's own per-frame update (its section 5 and appendix).

use bevy::math::DVec2;

use crate::physics::body::BodyState;
use crate::physics::forces::{ForceModel, Forces};
use crate::physics::maths;

/// The tutorial's update's stages for one step, in its order.
///
/// What learn mode's update loop shows, and all that [`tutorial_update`] does.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SeedStages {
    /// e^(−c·dt), the factor that scales ω first (0.98 at the tutorial's c and 100 Hz).
    pub damping_factor: f64,
    /// ω after that scale.
    pub damped_angular_velocity: f64,
    /// The band's force and the damping force −b v, at the step's start.
    pub band_force: DVec2,
    pub damping_force: DVec2,
    /// a = F_band / m + F_damp / m.
    pub acceleration: DVec2,
    /// The band's torque r × F at the step's start; the damping acts on ω by the factor.
    pub torque: f64,
    /// α = τ / I.
    pub angular_acceleration: f64,
    /// The state after the step: ω, then θ, then v, then x, each from the one just updated.
    pub after: BodyState,
}

/// Returns the tutorial's update's stages (its section 5 and appendix) at a step of `dt`.
///
/// The step is `dt` instead of one frame: the angular damping scales ω by exp(−c·dt) (0.98 at
/// 0.01 s); the damping force from the current velocity and the band's force and torque from
/// the current position and orientation are summed (`start`); then ω, θ, v, x in that order,
/// each from the one just updated. Its acceleration is the sum of each force divided by m, as
/// the tutorial's `addForce` scales each force before summing.
pub fn tutorial_stages(
    state: &BodyState,
    model: &ForceModel,
    start: Forces,
    dt: f64,
) -> SeedStages {
    let mass = &model.mass;
    let mut after = *state;
    let damping_factor = maths::exp(-model.angular_damping * dt);
    after.angular.angular_velocity *= damping_factor;
    let damped_angular_velocity = after.angular.angular_velocity;
    let acceleration =
        start.applied.force * mass.inverse_mass() + start.damping.force * mass.inverse_mass();
    let angular_acceleration = start.applied.torque / mass.inertia();
    after.angular.angular_velocity += angular_acceleration * dt;
    after.angular.orientation += after.angular.angular_velocity * dt;
    after.linear.velocity += acceleration * dt;
    after.linear.position += after.linear.velocity * dt;
    SeedStages {
        damping_factor,
        damped_angular_velocity,
        band_force: start.applied.force,
        damping_force: start.damping.force,
        acceleration,
        torque: start.applied.torque,
        angular_acceleration,
        after,
    }
}

/// Applies the tutorial's update ([`tutorial_stages`]) to `state`.
pub fn tutorial_update(state: &mut BodyState, model: &ForceModel, start: Forces, dt: f64) {
    *state = tutorial_stages(state, model, start, dt).after;
}
