//! The centre twin of the chapter on a force at a point: a copy of the box, set beside it,
//! that the same band pulls at its centre instead of a corner, so the player sees side by side
//! that both centres accelerate by F / m and only the box pulled at a corner turns. It is the
//! core's [`Stepper`] under the live band's anchor moved by the twin's offset; the live box
//! never reads it.

use bevy::math::DVec2;
use bevy::prelude::*;

use crate::game::simulation::{Band, Bodies, ResetScene, acting_band};
use crate::physics::{AutoSettings, BandEnds, BodyState, Integrator, SceneParams, Stepper};

/// Where the twin sits from the box, in world px: below it.
///
/// The tutorial's pull up and to the right then keeps both in the scene.
pub const TWIN_OFFSET: DVec2 = DVec2::new(0.0, -160.0);

/// The twin, while a chapter shows it.
#[derive(Resource, Debug, Default)]
pub struct CentreTwin {
    /// Whether the chapter shown has a twin (learn mode sets it as it shows a chapter).
    pub wanted: bool,
    pub body: Option<Twin>,
    restart: bool,
}

#[derive(Debug, Clone)]
pub struct Twin {
    pub stepper: Stepper,
    /// The state before the latest step, for drawing between the two.
    pub previous: BodyState,
}

impl Twin {
    /// Returns the band the twin takes for the box's `band`.
    ///
    /// It has the same anchor moved by the offset, and is held at the twin's centre.
    fn band_for(band: BandEnds) -> BandEnds {
        BandEnds {
            local_point: DVec2::ZERO,
            anchor: band.anchor + TWIN_OFFSET,
        }
    }

    /// Returns the twin's band's anchor, while a band pulls it.
    pub fn anchor(&self) -> Option<DVec2> {
        self.stepper.band.map(|band| band.anchor)
    }
}

pub fn restart_on_reset(_reset: On<ResetScene>, mut twin: ResMut<CentreTwin>) {
    twin.restart = true;
}

/// Steps the twin before the live box's step: the same step under the same band.
///
/// The band is held at the twin's centre, and the step uses the settings in force. Out of its
/// chapter the twin is dropped, to start again from the box, moved by the offset, when the
/// chapter is shown.
pub fn step_twin(
    mut twin: ResMut<CentreTwin>,
    time: Res<Time<Fixed>>,
    (params, integrator, auto): (Res<SceneParams>, Res<Integrator>, Res<AutoSettings>),
    boxes: Bodies,
    bands: Query<&Band>,
) {
    if !twin.wanted {
        if twin.body.is_some() {
            twin.body = None;
        }
        return;
    }
    let Ok(body) = boxes.single() else {
        return;
    };
    let mass = body.mass;
    let restart = std::mem::take(&mut twin.restart);
    if twin.body.is_none() || restart {
        let mut start = body.state();
        start.linear.position += TWIN_OFFSET;
        twin.body = Some(Twin {
            stepper: Stepper {
                params: *params,
                mass: *mass,
                state: start,
                band: None,
                integrator: *integrator,
                auto: *auto,
            },
            previous: start,
        });
    }
    let Some(twin) = twin.body.as_mut() else {
        return;
    };
    let stepper = &mut twin.stepper;
    stepper.params = *params;
    stepper.mass = *mass;
    stepper.integrator = *integrator;
    stepper.auto = *auto;
    stepper.band = acting_band(body.entity, &bands).map(Twin::band_for);
    let before = stepper.state;
    stepper.step(time.timestep().as_secs_f64());
    if stepper.state.is_sane() {
        twin.previous = before;
    } else {
        // A step that leaves the bounds is undone: the twin waits where it was.
        stepper.state = before;
        twin.previous = before;
    }
}
