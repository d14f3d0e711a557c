//! The Stability card, a feature in one folder: each integrator's distance from instability at
//! the present settings (the core's one-step amplification of the band's stiffest mode,
//! `physics::stability`). [`margins`] keeps them, [`card`] says the live integrator's in the
//! dock; the ghosts' table reads each one's from [`StabilityMargins`].

pub mod card;
pub mod margins;

use bevy::prelude::*;

pub use margins::StabilityMargins;

pub struct StabilityPlugin;

impl Plugin for StabilityPlugin {
    fn build(&self, app: &mut App) {
        app.add_plugins((margins::plugin, card::plugin));
    }
}
