//! The state DOP853 integrates, in the world's frame: the body with its orientation carried
//! also as a unit vector, plus the energy damping takes out, and how its errors are weighed.
//! The Taylor engine carries its own, in the frame that turns with the box (`taylor.rs`), and
//! shares the relative tolerance.

use bevy::math::DVec2;

use crate::physics::body::{AngularState, BodyState, LinearState};
use crate::physics::forces::ForceModel;
use crate::physics::maths;

/// x, y, cos θ, sin θ, θ, vx, vy, ω, and the energy damping took out (from zero).
pub const COMPONENTS: usize = 9;
pub type Components = [f64; COMPONENTS];

/// The index of the energy damping took out.
pub const DISSIPATED: usize = 8;

/// The error allowed per unit of a component's size, on top of the tolerance.
///
/// It comes to some thousand times f64's round-off, so that round-off far from the origin (the
/// anchor a million px away) is never asked to beat the tolerance.
pub const RELATIVE_TOLERANCE: f64 = 1e-13;

pub fn pack(state: &BodyState) -> Components {
    let (sin, cos) = maths::sin_cos(state.angular.orientation);
    [
        state.linear.position.x,
        state.linear.position.y,
        cos,
        sin,
        state.angular.orientation,
        state.linear.velocity.x,
        state.linear.velocity.y,
        state.angular.angular_velocity,
        0.0,
    ]
}

pub fn unpack(y: &Components) -> BodyState {
    BodyState {
        linear: LinearState {
            position: DVec2::new(y[0], y[1]),
            velocity: DVec2::new(y[5], y[6]),
        },
        angular: AngularState {
            orientation: y[4],
            angular_velocity: y[7],
        },
    }
}

/// Returns the error weights for a fixed step `dt` from `state`.
///
/// Positions count in px, the orientation (and its unit vector) as the displacement of the
/// farthest corner, velocities over the time in which they move the box that far (the faster of
/// the motion's rate and the fixed step); the energy has no weight.
pub fn error_weights(state: &BodyState, model: &ForceModel, dt: f64) -> Components {
    let reach = 0.5 * model.mass.size().length();
    let rate = model.fastest_rate(state).max(1.0 / dt);
    [
        1.0,
        1.0,
        reach,
        reach,
        reach,
        1.0 / rate,
        1.0 / rate,
        reach / rate,
        0.0,
    ]
}
