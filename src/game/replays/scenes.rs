//! The named scenes in the game: the core's table ([`Scene::NAMES`]), loaded by number
//! keys (and the panel) as a replay of their scripted pull (`replay::script`), which the
//! playback plays until the player presses. The player's step rate and integrator stay; a
//! scene restarted (`R`) keeps every setting the player has, the sliders' too.

use bevy::prelude::*;

use crate::game::replays::playback::PlayScene;
use crate::game::shared::{Apply, Say, SceneName};
use crate::game::simulation::ResetScene;
use crate::physics::{AutoSettings, Integrator, Scene, SceneParams};
use crate::replay::script::scene_replay;

/// Loads the scene asked.
pub(super) fn plugin(app: &mut App) {
    app.init_resource::<Loaded>()
        .add_observer(load)
        .add_observer(note_the_scene_shown)
        .add_observer(restart);
}

/// The scene shown, when it was loaded with its scripted pull (none in a fresh game).
///
/// `R` plays it again; a fresh game, a replay opened or a scene put back by learn mode is put
/// back at rest instead.
#[derive(Resource, Debug, Default)]
struct Loaded {
    shown: Option<&'static str>,
    /// The scene being loaded, until its name is put in place.
    loading: Option<&'static str>,
}

/// Play the scene shown from its start, its scripted pull with it, the settings as they are.
#[derive(Event, Debug, Clone, Copy, Default)]
pub struct RestartScene;

/// Load the named scene (one of [`Scene::NAMES`]).
#[derive(Event, Debug, Clone, Copy)]
pub struct LoadScene(pub &'static str);

/// The player's settings and step, which a scene is played with.
#[derive(bevy::ecs::system::SystemParam)]
struct Playing<'w> {
    params: Res<'w, SceneParams>,
    time: Res<'w, Time<Fixed>>,
    integrator: Res<'w, Integrator>,
    auto: Res<'w, AutoSettings>,
}

impl Playing<'_> {
    /// Plays `scene` from its start, with `params` for its own.
    fn play(&self, commands: &mut Commands, mut scene: Scene, params: SceneParams) {
        let name = scene.name;
        scene.params = params;
        let dt = self.time.timestep().as_secs_f64();
        match scene_replay(&scene, dt, *self.integrator, *self.auto) {
            Ok(replay) => commands.trigger(PlayScene(replay)),
            Err(error) => commands.trigger(Say(format!("cannot load {name}: {error}"))),
        }
    }
}

/// Loads a scene: its parameters at the player's step rate, its start, and its script playing.
///
/// The integrator, `auto`'s settings and the step rate are the player's, as sent before it.
fn load(load: On<LoadScene>, mut commands: Commands, playing: Playing, mut loaded: ResMut<Loaded>) {
    match Scene::named(load.0) {
        Ok(scene) => {
            loaded.loading = Some(scene.name);
            let params = SceneParams {
                step_rate_hz: playing.params.step_rate_hz,
                ..scene.params
            };
            playing.play(&mut commands, scene, params);
        }
        Err(unknown) => commands.trigger(Say(format!("cannot load {}: {unknown}", load.0))),
    }
}

/// Notes whether the scene put in place is one loaded here, with its scripted pull.
fn note_the_scene_shown(apply: On<Apply<SceneName>>, mut loaded: ResMut<Loaded>) {
    let loading = loaded.loading.take();
    loaded.shown = loading.filter(|&name| name == apply.0.0);
}

/// Restarts the scene loaded with the settings in force, while it is the one shown.
///
/// A fresh game, or a replay opened since, has its box put back at rest at the centre.
fn restart(
    _restart: On<RestartScene>,
    mut commands: Commands,
    shown: Res<SceneName>,
    mut loaded: ResMut<Loaded>,
    playing: Playing,
) {
    match loaded
        .shown
        .filter(|&name| name == shown.0)
        .map(Scene::named)
    {
        Some(Ok(scene)) => {
            loaded.loading = Some(scene.name);
            let params = *playing.params;
            playing.play(&mut commands, scene, params);
        }
        _ => commands.trigger(ResetScene),
    }
}
