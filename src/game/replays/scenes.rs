//! The named scenes in the game: the core's table ([`Scene::NAMES`]), loaded by number
//! keys (and the panel) as a replay of their scripted pull (`replay::script`), which the
//! playback plays until the player presses. The player's step rate and integrator stay.

use bevy::prelude::*;

use crate::game::replays::playback::PlayScene;
use crate::game::shared::Say;
use crate::physics::{AutoSettings, Integrator, Scene, SceneParams};
use crate::replay::script::scene_replay;

/// Loads the scene asked.
pub(super) fn plugin(app: &mut App) {
    app.add_observer(load);
}

/// Load the named scene (one of [`Scene::NAMES`]).
#[derive(Event, Debug, Clone, Copy)]
pub struct LoadScene(pub &'static str);

/// Loads a scene: its parameters at the player's step rate, its start, and its script playing.
///
/// The integrator, `auto`'s settings and the step rate are the player's, as sent before it.
fn load(
    load: On<LoadScene>,
    mut commands: Commands,
    params: Res<SceneParams>,
    time: Res<Time<Fixed>>,
    integrator: Res<Integrator>,
    auto: Res<AutoSettings>,
) {
    let name = load.0;
    let loaded = Scene::named(name)
        .map_err(|unknown| unknown.to_string())
        .and_then(|mut scene| {
            scene.params.step_rate_hz = params.step_rate_hz;
            let dt = time.timestep().as_secs_f64();
            scene_replay(&scene, dt, *integrator, *auto).map_err(|error| error.to_string())
        });
    match loaded {
        Ok(replay) => commands.trigger(PlayScene(replay)),
        Err(error) => commands.trigger(Say(format!("cannot load {name}: {error}"))),
    }
}
