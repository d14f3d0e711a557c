//! The game: every Bevy plugin, wired here once. [`GameLogicPlugin`] is the game without a
//! screen (what the headless tests run), [`GamePlugin`] adds the screen.
//!
//! Rooms:
//! - [`play`]: the play command's set-up, the window, and the run;
//! - [`schedule`]: the frame's order, every system set declared and ordered in one place;
//! - [`shared`]: the resources several plugins read (the scene's name, the status line, what
//!   shows) and [`shared::Apply`], the message a part of the setup is sent to its owner in;
//! - [`theme`]: the fonts, the type scale, the palette and the spacing every text reads;
//! - [`layout`]: the window's regions: the scene's viewport, the status and hint lines, the
//!   dock of instrument cards;
//! - [`simulation`]: the physics plugin that steps the core in `FixedUpdate`;
//! - [`budget`]: the wall time and the steps one frame's fixed loop may take;
//! - [`mod@pointer`]: the mouse and the finger, which hold the band;
//! - [`camera`]: what the scene shows (home, following the box, zoomed and panned) and the
//!   map between the window and the world;
//! - [`setup`]: what the game is set to, read whole and sent part by part to each part's
//!   owner (learn mode keeps it across the mode);
//! - [`replays`]: the game's side of replays and scenes: recording, playback, the scenes on
//!   the number keys, links opened and shared;
//! - [`ghosts`]: every integrator and a reference stepping beside the live box;
//! - [`learn`]: learn mode, the tutorial's chapters with their equations live;
//! - [`stability`]: each integrator's distance from instability at the present settings;
//! - [`input`]: the keys and the on-screen panel, which send the same actions;
//! - [`readouts`]: the Readouts card: the scene, the integrator, the clock, the parameters;
//! - [`hud`]: the status line over the scene and the hint under it;
//! - [`energy`]: the Energy card: the energies, the ledger, and their graph;
//! - [`mod@plot`]: the Speed against error card: each ghost a point on the report's axes;
//! - [`access`]: what a screen reader hears: names, roles, labels, the scene in words;
//! - [`screen`]: the cameras, interpolation, drawing and the dock's charts (need a window);
//! - `web`, in the browser only: the page's side (downloads, files opened, what the page
//!   reads back).

pub mod access;
pub mod budget;
pub mod camera;
pub mod energy;
pub mod ghosts;
pub mod hud;
pub mod input;
pub mod layout;
pub mod learn;
pub mod play;
pub mod plot;
pub mod pointer;
pub mod readouts;
pub mod replays;
pub mod schedule;
pub mod screen;
pub mod setup;
pub mod shared;
pub mod simulation;
pub mod stability;
pub mod theme;
#[cfg(target_arch = "wasm32")]
pub mod web;

use bevy::prelude::*;

/// The game without a screen: physics, pointer, camera's view, keys, the HUD and the cards.
///
/// They run in the frame's order ([`schedule`]), under `MinimalPlugins`.
pub struct GameLogicPlugin;

impl Plugin for GameLogicPlugin {
    fn build(&self, app: &mut App) {
        schedule::order_the_frame(app);
        app.add_plugins((
            shared::SharedPlugin,
            theme::ThemePlugin,
            layout::LayoutPlugin,
            (simulation::SimulationPlugin, budget::BudgetPlugin),
            (pointer::PointerPlugin, camera::CameraPlugin),
            input::controls::ControlsPlugin,
            replays::ReplaysPlugin,
            learn::LearnPlugin,
            ghosts::GhostsPlugin,
            stability::StabilityPlugin,
            (input::panel::PanelPlugin, input::focus::FocusPlugin),
            (
                readouts::ReadoutsPlugin,
                energy::EnergyPlugin,
                plot::PlotPlugin,
                hud::HudPlugin,
                access::AccessPlugin,
            ),
        ));
    }
}

/// Everything the game needs on top of `DefaultPlugins` and lyon's `ShapePlugin`.
pub struct GamePlugin;

impl Plugin for GamePlugin {
    fn build(&self, app: &mut App) {
        app.add_plugins((GameLogicPlugin, GameScreenPlugin));
    }
}

/// What needs a window: the screen, and the cards' charts drawn by its chart camera.
///
/// The game adds it; so do the tests that draw.
pub struct GameScreenPlugin;

impl Plugin for GameScreenPlugin {
    fn build(&self, app: &mut App) {
        // Each feature that draws adds its drawing when it finds the screen (`shared::Screen`).
        app.init_resource::<shared::Screen>()
            .add_plugins(screen::ScreenPlugin);
    }
}
