//! The dock's Energy card: where the energy is (kinetic, linear and rotational, the band's
//! potential, their total), the ledger (the hand's work in, damping's out) and the integrator's
//! error against it ([`lines`]), over the graph of the last seconds ([`history`], [`graph`]),
//! whose colours the lines are the legend of. Registered with the dock here; nothing outside
//! this folder names it but the game's wiring and the tests.

pub mod graph;
pub mod history;
pub mod lines;

use bevy::prelude::*;

use crate::game::shared::has_screen;

pub use history::EnergyHistory;

/// The card, its lines and the history (headless too), and its graph with a screen.
pub struct EnergyPlugin;

impl Plugin for EnergyPlugin {
    fn build(&self, app: &mut App) {
        app.add_plugins((lines::plugin, history::plugin));
    }

    /// Adds the card's graph, which needs the screen's chart camera.
    fn finish(&self, app: &mut App) {
        if has_screen(app) {
            graph::plugin(app);
        }
    }
}
