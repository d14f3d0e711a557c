//! The force laws the scene needs, and nothing else: a zero-length rubber band between a body
//! point and a world point, linear and angular damping.

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

    /// Builds the wrench of a force applied at world offset `arm` from the centre of mass.
    ///
    /// It is the same force through the centre, plus the torque τ = r × F (the tutorial's
    /// equation 22).
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

/// The band: a zero-rest-length Hooke spring from a point on the body to a world point.
///
/// It runs from `local_point` on the body (body coordinates) to `anchor` (world coordinates).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BandEnds {
    pub local_point: DVec2,
    pub anchor: DVec2,
}

impl BandEnds {
    /// Returns the band a press at `anchor` makes: a corner of the body pulled toward `anchor`.
    ///
    /// It grabs the corner nearest to `anchor` (the tutorial's rule).
    pub fn grabbing(mass: &MassProperties, state: &BodyState, anchor: DVec2) -> Self {
        Self {
            local_point: mass.nearest_corner(state, anchor),
            anchor,
        }
    }

    /// Returns the band's end on the body, in world coordinates.
    pub fn attachment(&self, state: &BodyState) -> DVec2 {
        state.local_to_world(self.local_point)
    }

    /// Returns the band's length (it has zero rest length, so this is also its stretch).
    pub fn length(&self, state: &BodyState) -> f64 {
        self.attachment(state).distance(self.anchor)
    }

    /// Returns the force k·(anchor − point), applied at the attachment point.
    pub fn wrench(&self, state: &BodyState, stiffness: f64) -> Wrench {
        let point = self.attachment(state);
        Wrench::at_arm(
            stiffness * (self.anchor - point),
            point - state.linear.position,
        )
    }

    /// Returns the elastic energy ½ k |point − anchor|².
    pub fn potential_energy(&self, state: &BodyState, stiffness: f64) -> f64 {
        0.5 * stiffness * self.attachment(state).distance_squared(self.anchor)
    }
}

/// Returns damping as a force and a torque: F = −b v, τ = −c I ω.
///
/// The velocity then decays at the rate b/m and the angular velocity at the rate c (both per
/// second).
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

/// What acts on a body during one step: the forces the scene applies (the band), and damping.
///
/// The two parts are kept apart because the integrators treat them differently.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Forces {
    pub applied: Wrench,
    pub damping: Wrench,
}

impl Forces {
    pub const ZERO: Self = Self {
        applied: Wrench::ZERO,
        damping: Wrench::ZERO,
    };

    pub fn total(&self) -> Wrench {
        self.applied + self.damping
    }
}

/// Every force law acting on one body during a step.
///
/// They are kept together so that an integrator can evaluate the forces at any intermediate state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ForceModel {
    pub mass: MassProperties,
    pub band: Option<BandEnds>,
    pub stiffness: f64,
    pub linear_damping: f64,
    pub angular_damping: f64,
}

impl ForceModel {
    /// Returns the band's force and torque (zero without a band).
    pub fn applied(&self, state: &BodyState) -> Wrench {
        self.band
            .map_or(Wrench::ZERO, |band| band.wrench(state, self.stiffness))
    }

    pub fn damping(&self, state: &BodyState) -> Wrench {
        damping_wrench(state, &self.mass, self.linear_damping, self.angular_damping)
    }

    /// Returns every force and torque at `state`: steps 1 and 3 of the total reaction.
    pub fn forces(&self, state: &BodyState) -> Forces {
        Forces {
            applied: self.applied(state),
            damping: self.damping(state),
        }
    }

    /// Returns the velocity decay rates: b/m for the linear velocity, c for the angular one.
    pub fn damping_rates(&self) -> (f64, f64) {
        (
            self.linear_damping * self.mass.inverse_mass(),
            self.angular_damping,
        )
    }

    /// Returns the rate of the band's stiffest mode (zero without a band).
    ///
    /// It is sqrt(k (1/m + |r|²/I)), 2·sqrt(k/m) for a square pulled at a corner.
    pub fn band_rate(&self) -> f64 {
        let mass = &self.mass;
        self.band.map_or(0.0, |band| {
            let arm_squared = band.local_point.length_squared();
            (self.stiffness * (mass.inverse_mass() + arm_squared * mass.inverse_inertia())).sqrt()
        })
    }

    /// Returns the fastest rate in the motion at `state`.
    ///
    /// The rates compared are the band's stiffest mode, the spin and the damping rates.
    pub fn fastest_rate(&self, state: &BodyState) -> f64 {
        let (linear_rate, angular_rate) = self.damping_rates();
        self.band_rate()
            .max(linear_rate)
            .max(angular_rate)
            .max(state.angular.angular_velocity.abs())
    }

    /// Returns the rate at which damping takes energy out: b |v|² + c I ω² (never negative).
    pub fn damping_power(&self, velocity: DVec2, angular_velocity: f64) -> f64 {
        self.linear_damping * velocity.length_squared()
            + self.angular_damping * self.mass.inertia() * angular_velocity * angular_velocity
    }

    /// Returns the energy damping took out over a step from `before` to `after`.
    ///
    /// It uses the trapezoidal rule: second order, as accurate as any first- or second-order
    /// integrator.
    pub fn dissipated_by_trapezoid(&self, before: &BodyState, after: &BodyState, dt: f64) -> f64 {
        let power =
            |s: &BodyState| self.damping_power(s.linear.velocity, s.angular.angular_velocity);
        0.5 * dt * (power(before) + power(after))
    }
}

/// Returns the angular momentum about a fixed world point: m (x − a) × v + I ω.
///
/// The band's force passes through its anchor, so with no damping this is an invariant about
/// the anchor.
pub fn angular_momentum_about(state: &BodyState, mass: &MassProperties, point: DVec2) -> f64 {
    mass.mass() * (state.linear.position - point).perp_dot(state.linear.velocity)
        + mass.inertia() * state.angular.angular_velocity
}
