//! Our own plugin as a contender: the same headless `App` as the peers, with the game's
//! default integrator.

use bevy::prelude::*;

use super::{Contender, headless_app, start};
use crate::game::simulation::{Band, RigidBox, SimulationPlugin, body_state, rigid_box};
use crate::physics::{BandEnds, BodyState, SceneParams};

pub struct Ours {
    app: App,
    body: Entity,
    band: Option<Entity>,
}

impl Contender for Ours {
    const NAME: &'static str = "ours (auto)";

    fn new(params: &SceneParams, initial: BodyState, rate_hz: f64) -> Self {
        let mut app = headless_app(rate_hz);
        app.insert_resource(SceneParams {
            step_rate_hz: rate_hz,
            ..*params
        })
        .add_plugins(SimulationPlugin);
        start(&mut app);
        let world = app.world_mut();
        let body = world
            .query_filtered::<Entity, With<RigidBox>>()
            .single(world)
            .expect("the plugin spawns one box");
        let mass = params.mass_properties().expect("the plugin spawned it");
        world.entity_mut(body).insert(rigid_box(mass, initial));
        Self {
            app,
            body,
            band: None,
        }
    }

    fn set_band(&mut self, ends: Option<BandEnds>) {
        let world = self.app.world_mut();
        match (self.band, ends) {
            (Some(band), Some(ends)) => {
                world.entity_mut(band).insert(Band {
                    body: self.body,
                    ends,
                });
            }
            (None, Some(ends)) => {
                self.band = Some(
                    world
                        .spawn(Band {
                            body: self.body,
                            ends,
                        })
                        .id(),
                );
            }
            (Some(band), None) => {
                world.despawn(band);
                self.band = None;
            }
            (None, None) => {}
        }
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
