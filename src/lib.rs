//! Rubber Band Box: a 2D rigid box pulled by a rubber band, on Bevy.
//!
//! Layers, each importing only the ones before it:
//! - [`physics`]: the numerical core, plain Rust over f64 state (no `App`);
//! - [`schedule`] and [`overlays`]: leaves the plugins share (the frame's order, what shows);
//! - [`simulation`]: the Bevy plugin that steps the core in `FixedUpdate` (headless);
//! - [`replay`]: a game's input as data, read, written and stepped again with the core;
//! - [`pointer`] and [`controls`]: mouse, touch and keys, and [`panel`], the same controls on
//!   screen (headless); [`recording`]: what
//!   reached the physics, kept as a replay, and [`playback`], a replay played back in the game;
//!   [`scenes`], the core's named scenes played as replays of their scripted pulls;
//!   [`ghosts`], every integrator and a reference stepping beside the live box (headless);
//! - [`hud`]: the heads-up display, its energy graph and the window title (headless, but the
//!   graph, which needs gizmos);
//! - [`view`] and [`draw`]: camera, interpolation and drawing (need a window);
//! - [`cli`], [`report`], [`references`] and [`peers`]: the native tools on top of the core;
//!   `web`, in the browser only: the page's side (downloads, files opened, what the page
//!   reads back), a leaf the recorder and the playback call.
//!
//! The plugins are wired here, once: [`GameLogicPlugin`] is the game without a screen (what
//! the headless tests run), [`GamePlugin`] adds the screen.

#[cfg(not(target_arch = "wasm32"))]
pub mod cli;
pub mod controls;
pub mod draw;
pub mod ghosts;
pub mod hud;
pub mod overlays;
pub mod panel;
#[cfg(all(feature = "peers", not(target_arch = "wasm32")))]
pub mod peers;
pub mod physics;
pub mod playback;
pub mod pointer;
pub mod recording;
#[cfg(not(target_arch = "wasm32"))]
pub mod references;
pub mod replay;
#[cfg(not(target_arch = "wasm32"))]
pub mod report;
pub mod scenes;
pub mod schedule;
pub mod simulation;
#[cfg(not(target_arch = "wasm32"))]
pub mod timing;
pub mod view;
#[cfg(target_arch = "wasm32")]
pub mod web;

use bevy::prelude::*;

/// The game without a screen: the physics, the pointer, the keys and the HUD's text, in the
/// frame's order ([`schedule`]). Runs under `MinimalPlugins`.
pub struct GameLogicPlugin;

impl Plugin for GameLogicPlugin {
    fn build(&self, app: &mut App) {
        schedule::order_the_frame(app);
        app.add_plugins((
            simulation::SimulationPlugin,
            pointer::PointerPlugin,
            controls::ControlsPlugin,
            recording::RecordingPlugin,
            playback::PlaybackPlugin,
            scenes::ScenesPlugin,
            ghosts::GhostsPlugin,
            panel::PanelPlugin,
            hud::HudPlugin,
        ));
    }
}

/// Everything the game needs on top of `DefaultPlugins` and lyon's `ShapePlugin`.
pub struct GamePlugin;

impl Plugin for GamePlugin {
    fn build(&self, app: &mut App) {
        app.add_plugins((
            GameLogicPlugin,
            view::ViewPlugin,
            draw::DrawPlugin,
            hud::graph::EnergyGraphPlugin,
        ));
    }
}
