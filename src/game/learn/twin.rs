//! The centre twin of the chapter on a force at a point: a copy of the box, set beside it, that
//! the box's own band force pushes at its centre, with the same damping. Its equations are the
//! box's linear ones (x' = v, m v' = F_band − b v) with the same right-hand side, so its centre
//! moves as the box's does, by the offset, and with r = 0 it never turns: the tutorial's "the
//! linear response is the same as if the force acted on the centre of mass" (§4).
//!
//! Every integrator here updates x and v from the forces alone, so stepping the twin would
//! repeat the box's linear step on the same numbers; it is read off the box instead.
//! tests/learn.rs steps a twin on its own under the box's force and finds the same path.

use bevy::math::DVec2;
use bevy::prelude::*;

use crate::game::simulation::{Bodies, ResetScene};
use crate::physics::{AngularState, BodyState, LinearState};

/// Where the twin sits from the box, in world px: below it.
///
/// The tutorial's pull up and to the right then keeps both in the scene.
pub const TWIN_OFFSET: DVec2 = DVec2::new(0.0, -130.0);

/// The twin, while a chapter shows it.
#[derive(Resource, Debug, Default)]
pub struct CentreTwin {
    pub body: Option<Twin>,
    restart: bool,
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Twin {
    /// The orientation it started with, which nothing changes.
    pub orientation: f64,
}

impl Twin {
    /// Returns the twin's state beside a box in `state`.
    ///
    /// The centre and its velocity are the box's, moved by the offset; the twin does not spin.
    pub fn beside(&self, state: &BodyState) -> BodyState {
        BodyState {
            linear: LinearState {
                position: state.linear.position + TWIN_OFFSET,
                velocity: state.linear.velocity,
            },
            angular: AngularState {
                orientation: self.orientation,
                angular_velocity: 0.0,
            },
        }
    }
}

pub(super) fn restart_on_reset(_reset: On<ResetScene>, mut twin: ResMut<CentreTwin>) {
    twin.restart = true;
}

/// Sets the twin beside the box when its chapter is shown (`wanted`) or the scene starts over.
///
/// Out of its chapter the twin is dropped.
pub(super) fn place_twin(twin: &mut CentreTwin, wanted: bool, boxes: &Bodies) {
    if !wanted {
        if twin.body.is_some() {
            twin.body = None;
        }
        return;
    }
    let restart = std::mem::take(&mut twin.restart);
    if twin.body.is_none() || restart {
        twin.body = boxes.single().ok().map(|body| Twin {
            orientation: body.angular.orientation,
        });
    }
}
