//! The floor under every contender's tick: the same headless `App` with no physics at all,
//! holding the box's state and the band as our plugin does, driven through the same calls
//! ([`super::PeerRun`]). Our plugin's own cost is then the difference of two ticks timed alike.

use bevy::prelude::*;

use super::{Contender, headless_app, start};
use crate::game::simulation::{Band, body_state};
use crate::physics::{BandEnds, BodyState, SceneParams};

pub struct Empty {
    app: App,
    body: Entity,
    band: Option<Entity>,
}

impl Contender for Empty {
    const NAME: &'static str = "an empty App";

    fn new(_params: &SceneParams, initial: BodyState, rate_hz: f64) -> Self {
        let mut app = headless_app(rate_hz);
        start(&mut app);
        let body = app
            .world_mut()
            .spawn((initial.linear, initial.angular))
            .id();
        Self {
            app,
            body,
            band: None,
        }
    }

    fn set_band(&mut self, ends: Option<BandEnds>) {
        let world = self.app.world_mut();
        if let Some(band) = self.band.take() {
            world.despawn(band);
        }
        self.band = ends.map(|ends| {
            world
                .spawn(Band {
                    body: self.body,
                    ends,
                })
                .id()
        });
    }

    fn state(&mut self) -> BodyState {
        let entity = self.app.world().entity(self.body);
        body_state(
            entity.get().expect("a body has a linear state"),
            entity.get().expect("a body has an angular state"),
        )
    }

    fn app(&mut self) -> &mut App {
        &mut self.app
    }
}
