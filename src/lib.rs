//! Rubber Band Box: a 2D rigid box pulled by a rubber band, on Bevy.
//!
//! Layers, each usable without the ones after it:
//! - [`physics`]: the numerical core, plain Rust over f64 state;
//! - [`simulation`]: the Bevy plugin that steps the core in `FixedUpdate` (headless);
//! - [`pointer`]: mouse and touch to the band entity (headless);
//! - [`hud`]: the heads-up display's text and energy history (headless too);
//! - [`view`] and [`draw`]: camera, interpolation and drawing (need a window).

#[cfg(not(target_arch = "wasm32"))]
pub mod cli;
pub mod controls;
pub mod draw;
pub mod hud;
#[cfg(all(feature = "peers", not(target_arch = "wasm32")))]
pub mod peers;
pub mod physics;
pub mod pointer;
#[cfg(not(target_arch = "wasm32"))]
pub mod report;
pub mod simulation;
pub mod view;

use bevy::prelude::*;

/// Everything the game needs on top of `DefaultPlugins` and lyon's `ShapePlugin`.
pub struct GamePlugin;

impl Plugin for GamePlugin {
    fn build(&self, app: &mut App) {
        app.add_plugins((
            simulation::SimulationPlugin,
            pointer::PointerPlugin,
            controls::ControlsPlugin,
            hud::HudPlugin,
            view::ViewPlugin,
            draw::DrawPlugin,
        ));
    }
}
