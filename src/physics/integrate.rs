//! Advancing the state by one step from the total force and torque.

use super::body::{BodyState, MassProperties};
use super::forces::Wrench;

/// The tutorial's total reaction (section 4.4), steps 2 to 5, given the summed force and
/// torque of steps 1 and 3: a = F/m, α = τ/I, then semi-implicit (symplectic) Euler: the
/// velocities first, then the position and orientation from the new velocities.
pub fn symplectic_euler(state: &mut BodyState, mass: &MassProperties, total: Wrench, dt: f64) {
    let acceleration = total.force * mass.inverse_mass();
    let angular_acceleration = total.torque * mass.inverse_inertia();

    state.linear.velocity += acceleration * dt;
    state.angular.angular_velocity += angular_acceleration * dt;
    state.linear.position += state.linear.velocity * dt;
    state.angular.orientation += state.angular.angular_velocity * dt;
}
