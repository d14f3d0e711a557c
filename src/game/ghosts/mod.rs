//! Ghosts (G), a feature in one folder: every integrator, and a reference, stepping beside the
//! live box under the live band ([`steppers`]), and the dock's card that tabulates them
//! ([`table`]). Drawn by the screen (their outlines) and plotted by the lab's plot.

pub mod draw;
pub mod steppers;
pub mod table;

use bevy::prelude::*;

use crate::game::shared::has_screen;

pub use steppers::{Ghost, GhostKind, Ghosts};

pub struct GhostsPlugin;

impl Plugin for GhostsPlugin {
    fn build(&self, app: &mut App) {
        app.add_plugins((steppers::plugin, table::plugin));
    }

    fn finish(&self, app: &mut App) {
        if has_screen(app) {
            draw::plugin(app);
        }
    }
}
