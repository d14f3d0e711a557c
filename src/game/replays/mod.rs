//! The game's side of replays: the recorder keeps what reached the physics, the playback
//! plays a replay back, the scenes on the number keys are played as replays of their
//! scripted pulls, and links open a game's settings (and a whole game) or share them.

pub mod links;
pub mod playback;
pub mod recording;
pub mod scenes;

use bevy::prelude::*;

/// The game's side of replays: the recorder, the playback, the scenes and the links.
pub struct ReplaysPlugin;

impl Plugin for ReplaysPlugin {
    fn build(&self, app: &mut App) {
        app.add_plugins((
            recording::plugin,
            playback::plugin,
            scenes::plugin,
            links::plugin,
        ));
    }
}
