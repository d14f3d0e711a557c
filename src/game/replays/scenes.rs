//! The named scenes in the game: the core's table ([`Scene::NAMES`]), loaded by number
//! keys (and the panel) as a replay of their scripted pull (`replay::script`), which the
//! playback plays until the player presses. The player's step rate and integrator stay.

use bevy::prelude::*;

use crate::game::replays::playback;
use crate::game::shared::Say;
use crate::physics::{AutoSettings, Integrator, Scene, SceneParams};
use crate::replay::script::scene_replay;

pub struct ScenesPlugin;

impl Plugin for ScenesPlugin {
    fn build(&self, app: &mut App) {
        app.add_observer(load);
    }
}

/// Load the named scene (one of [`Scene::NAMES`]).
#[derive(Event, Debug, Clone, Copy)]
pub struct LoadScene(pub &'static str);

fn load(load: On<LoadScene>, mut commands: Commands) {
    let name = load.0;
    commands.queue(move |world: &mut World| load_scene(world, name));
}

/// Loads a scene: its parameters at the player's step rate, its start, and its script playing.
pub(crate) fn load_scene(world: &mut World, name: &str) {
    let loaded = Scene::named(name)
        .map_err(|unknown| unknown.to_string())
        .and_then(|mut scene| {
            scene.params.step_rate_hz = world.resource::<SceneParams>().step_rate_hz;
            let dt = world.resource::<Time<Fixed>>().timestep().as_secs_f64();
            let integrator = *world.resource::<Integrator>();
            let auto = *world.resource::<AutoSettings>();
            scene_replay(&scene, dt, integrator, auto).map_err(|error| error.to_string())
        });
    match loaded {
        Ok(replay) => playback::open(world, replay),
        Err(error) => world.trigger(Say(format!("cannot load {name}: {error}"))),
    }
}
