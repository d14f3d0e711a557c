//! The game's side of replays: the recorder keeps what reached the physics, the playback
//! plays a replay back, and the scenes on the number keys are played as replays of their
//! scripted pulls.

pub mod playback;
pub mod recording;
pub mod scenes;
