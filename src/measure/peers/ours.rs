//! Our own plugin as a contender: the same headless `App` as the peers, with the game's
//! default integrator.

use bevy::prelude::*;

use super::{Contender, HeldBox, headless_app, start};
use crate::game::simulation::{RigidBox, SimulationPlugin, rigid_box};
use crate::physics::{BandEnds, BodyState, SceneParams};

pub struct Ours(HeldBox);

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
        Self(HeldBox::new(app, body))
    }

    fn set_band(&mut self, ends: Option<BandEnds>) {
        self.0.set_band(ends);
    }

    fn state(&mut self) -> BodyState {
        self.0.state()
    }

    fn app(&mut self) -> &mut App {
        &mut self.0.app
    }
}
