//! The force laws the scene needs, and nothing else: a zero-length rubber band between a body
//! point and a world point, linear drag and angular drag.

use std::ops::{Add, AddAssign};

use bevy::math::DVec2;

use super::body::{BodyState, MassProperties};

/// A force through the centre of mass plus a torque about it (counter-clockwise positive).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Wrench {
    pub force: DVec2,
    pub torque: f64,
}

impl Wrench {
    pub const ZERO: Self = Self {
        force: DVec2::ZERO,
        torque: 0.0,
    };

    /// A force applied at world offset `arm` from the centre of mass: the same force through the
    /// centre, plus the torque τ = r × F (the tutorial's equation 22).
    pub fn at_arm(force: DVec2, arm: DVec2) -> Self {
        Self {
            force,
            torque: arm.perp_dot(force),
        }
    }
}

impl Add for Wrench {
    type Output = Self;
    fn add(self, rhs: Self) -> Self {
        Self {
            force: self.force + rhs.force,
            torque: self.torque + rhs.torque,
        }
    }
}

impl AddAssign for Wrench {
    fn add_assign(&mut self, rhs: Self) {
        *self = *self + rhs;
    }
}

/// The band: a zero-rest-length Hooke spring from `local_point` on the body (body coordinates)
/// to `anchor` (world coordinates).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BandEnds {
    pub local_point: DVec2,
    pub anchor: DVec2,
}

impl BandEnds {
    /// The band's end on the body, in world coordinates.
    pub fn attachment(&self, state: &BodyState) -> DVec2 {
        state.local_to_world(self.local_point)
    }

    /// The band's length (it has zero rest length, so this is also its stretch).
    pub fn length(&self, state: &BodyState) -> f64 {
        self.attachment(state).distance(self.anchor)
    }

    /// Force k·(anchor − point) applied at the attachment point.
    pub fn wrench(&self, state: &BodyState, stiffness: f64) -> Wrench {
        let point = self.attachment(state);
        Wrench::at_arm(
            stiffness * (self.anchor - point),
            point - state.linear.position,
        )
    }

    /// Elastic energy ½ k |point − anchor|².
    pub fn potential_energy(&self, state: &BodyState, stiffness: f64) -> f64 {
        0.5 * stiffness * self.attachment(state).distance_squared(self.anchor)
    }
}

/// Damping as a force and a torque: F = −b v, τ = −c I ω, so that the velocity decays at the
/// rate b/m and the angular velocity at the rate c (both per second).
pub fn damping_wrench(
    state: &BodyState,
    mass: &MassProperties,
    linear_damping: f64,
    angular_damping: f64,
) -> Wrench {
    Wrench {
        force: -linear_damping * state.linear.velocity,
        torque: -angular_damping * mass.inertia() * state.angular.angular_velocity,
    }
}

/// Kinetic energy, linear plus rotational: ½ m |v|² + ½ I ω².
pub fn kinetic_energy(state: &BodyState, mass: &MassProperties) -> f64 {
    0.5 * mass.mass() * state.linear.velocity.length_squared()
        + 0.5 * mass.inertia() * state.angular.angular_velocity.powi(2)
}
