//! The state of one rigid body in the plane, and its mass properties.
//!
//! World units are logical pixels and seconds, y up, angles counter-clockwise in radians.
//! Everything is f64: accuracy is half of this product, and f32 cannot show errors below 1e-7.

use bevy::math::DVec2;
use bevy::prelude::Component;

use super::maths;
use super::param_error::ParamError;

/// Linear state: where the centre of mass is and how fast it moves.
#[derive(Component, Clone, Copy, Debug, Default, PartialEq)]
pub struct LinearState {
    pub position: DVec2,
    pub velocity: DVec2,
}

/// Angular state: how far the body has turned and how fast it turns.
///
/// The orientation is an unwrapped angle, so that interpolation between two steps and the
/// count of turns stay meaningful.
#[derive(Component, Clone, Copy, Debug, Default, PartialEq)]
pub struct AngularState {
    pub orientation: f64,
    pub angular_velocity: f64,
}

/// The whole dynamic state of one body, as the integrators see it.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BodyState {
    pub linear: LinearState,
    pub angular: AngularState,
}

impl BodyState {
    /// Returns a body at rest at `position` with orientation zero.
    pub fn at_rest(position: DVec2) -> Self {
        Self {
            linear: LinearState {
                position,
                velocity: DVec2::ZERO,
            },
            angular: AngularState::default(),
        }
    }

    /// Flattens the state into six numbers: x, y, θ, vx, vy, ω.
    ///
    /// The order is that of the CLI's CSV columns and `--init`. The one place the state is
    /// flattened and rebuilt.
    pub fn to_array(&self) -> [f64; 6] {
        let (p, v) = (self.linear.position, self.linear.velocity);
        let a = &self.angular;
        [p.x, p.y, a.orientation, v.x, v.y, a.angular_velocity]
    }

    /// Rebuilds the state from x, y, θ, vx, vy, ω (see [`Self::to_array`]).
    pub fn from_array([x, y, orientation, vx, vy, angular_velocity]: [f64; 6]) -> Self {
        Self {
            linear: LinearState {
                position: DVec2::new(x, y),
                velocity: DVec2::new(vx, vy),
            },
            angular: AngularState {
                orientation,
                angular_velocity,
            },
        }
    }

    /// Expresses a body-local point in world coordinates.
    pub fn local_to_world(&self, local: DVec2) -> DVec2 {
        self.linear.position + rotate(local, self.angular.orientation)
    }

    /// Tells whether the state is finite, with every component within [`STATE_LIMIT`].
    ///
    /// Such a state is what the game accepts from a step.
    pub fn is_sane(&self) -> bool {
        self.to_array()
            .iter()
            .all(|v| v.is_finite() && v.abs() <= STATE_LIMIT)
    }

    /// Tells whether the game plays this state: sane, and its centre within [`PLAYABLE_LIMIT`].
    ///
    /// The game refuses a step past it, and a replay's run refuses it alike.
    pub fn is_playable(&self) -> bool {
        self.is_sane() && self.linear.position.abs().max_element() <= PLAYABLE_LIMIT
    }

    /// Measures how far this pose is from `other`, in px.
    ///
    /// The measure is the largest distance between corresponding corners of the box `mass`
    /// describes. It weighs the orientation by the box's size, as the corner's 30√2·θ for the
    /// tutorial's 60 px box.
    pub fn pose_error(&self, other: &BodyState, mass: &MassProperties) -> f64 {
        mass.corners()
            .iter()
            .map(|&c| self.local_to_world(c).distance(other.local_to_world(c)))
            .fold(0.0, f64::max)
    }

    pub fn is_finite(&self) -> bool {
        self.to_array().iter().all(|v| v.is_finite())
    }
}

/// The bound no component of a sane state exceeds: a step past it has diverged.
///
/// It is a billion times the scene, far beyond any hard case (the far anchor is 1e6 away; a
/// band of k = 1e9 moves the box at about 6e6 px/s), and still inside f32's range for drawing.
pub const STATE_LIMIT: f64 = 1e12;

/// The farthest from the centre the game plays the box (px).
///
/// The screen draws in f32, whose steps are a pixel at 1.6e7: past it a box would be drawn as a
/// point. The far anchor's pull (1e6 away) stays well inside; a box flung there has diverged.
pub const PLAYABLE_LIMIT: f64 = 1e7;

/// Rotates `v` counter-clockwise by `angle` radians.
///
/// It is written out as the tutorial's `rotateCopy` does, so that the two round the same way.
pub fn rotate(v: DVec2, angle: f64) -> DVec2 {
    let (sin, cos) = maths::sin_cos(angle);
    DVec2::new(cos * v.x - sin * v.y, sin * v.x + cos * v.y)
}

/// Mass, moment of inertia about the centre of mass, their inverses, and the box's size.
///
/// Built only through [`MassProperties::rectangle`], which validates, so the inverses are
/// always finite and positive.
#[derive(Component, Clone, Copy, Debug, PartialEq)]
pub struct MassProperties {
    mass: f64,
    inverse_mass: f64,
    inertia: f64,
    inverse_inertia: f64,
    size: DVec2,
}

impl MassProperties {
    /// Builds a uniform solid rectangle: I = m (w² + h²) / 12 (the tutorial's section 4.3.4).
    pub fn rectangle(mass: f64, size: DVec2) -> Result<Self, ParamError> {
        ParamError::check_positive("mass", mass)?;
        ParamError::check_positive("width", size.x)?;
        ParamError::check_positive("height", size.y)?;
        let inertia = mass * (size.x * size.x + size.y * size.y) / 12.0;
        ParamError::check_positive("moment of inertia", inertia)?;
        Ok(Self {
            mass,
            inverse_mass: 1.0 / mass,
            inertia,
            inverse_inertia: 1.0 / inertia,
            size,
        })
    }

    pub fn mass(&self) -> f64 {
        self.mass
    }
    pub fn inverse_mass(&self) -> f64 {
        self.inverse_mass
    }
    pub fn inertia(&self) -> f64 {
        self.inertia
    }
    pub fn inverse_inertia(&self) -> f64 {
        self.inverse_inertia
    }
    pub fn size(&self) -> DVec2 {
        self.size
    }

    /// Returns the four corners in body coordinates, in the tutorial's order.
    ///
    /// The order is upper-left, upper-right, lower-right, lower-left (y up here; the tutorial's
    /// screen is y down).
    pub fn corners(&self) -> [DVec2; 4] {
        let h = self.size * 0.5;
        [
            DVec2::new(-h.x, h.y),
            DVec2::new(h.x, h.y),
            DVec2::new(h.x, -h.y),
            DVec2::new(-h.x, -h.y),
        ]
    }

    /// Returns the corner (body coordinates) nearest to the world point `target`.
    ///
    /// On a tie the first in [`Self::corners`] order wins, as in the tutorial.
    pub fn nearest_corner(&self, state: &BodyState, target: DVec2) -> DVec2 {
        let mut best = self.corners()[0];
        let mut best_distance = f64::INFINITY;
        for corner in self.corners() {
            let distance = state.local_to_world(corner).distance_squared(target);
            if distance < best_distance {
                best = corner;
                best_distance = distance;
            }
        }
        best
    }
}
