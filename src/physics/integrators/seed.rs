//! The `seed` integrator: the tutorial's own per-frame update (its section 5 and appendix).

use crate::physics::body::BodyState;
use crate::physics::forces::{ForceModel, Forces};
use crate::physics::maths;

/// Applies the tutorial's update (its section 5 and appendix), in its order, at a step of `dt`.
///
/// The step is `dt` instead of one frame: the angular damping scales ω by exp(−c·dt) (0.98 at
/// 0.01 s); the damping force from the current velocity and the band's force and torque from
/// the current position and orientation are summed (`start`); then ω, θ, v, x in that order,
/// each from the one just updated. Its acceleration is the sum of each force divided by m, as
/// the tutorial's `addForce` scales each force before summing.
pub fn tutorial_update(state: &mut BodyState, model: &ForceModel, start: Forces, dt: f64) {
    let mass = &model.mass;
    state.angular.angular_velocity *= maths::exp(-model.angular_damping * dt);
    let acceleration =
        start.applied.force * mass.inverse_mass() + start.damping.force * mass.inverse_mass();
    let angular_acceleration = start.applied.torque / mass.inertia();
    state.angular.angular_velocity += angular_acceleration * dt;
    state.angular.orientation += state.angular.angular_velocity * dt;
    state.linear.velocity += acceleration * dt;
    state.linear.position += state.linear.velocity * dt;
}
