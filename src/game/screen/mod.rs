//! The screen: the cameras and the interpolation between fixed steps ([`view`]), the box, the
//! band and the overlays drawn ([`draw`]), and the chart camera the dock's charts draw with
//! ([`chart`]; the Energy card's graph is in `game::energy`, the plot of speed against error
//! in `game::plot`). Needs rendering; reads the game's state, never the other way round.

pub mod chart;
pub mod draw;
pub mod view;

use bevy::prelude::*;

/// Every plugin of the screen, wired once (the game adds it; so do the tests that draw).
pub struct ScreenPlugin;

impl Plugin for ScreenPlugin {
    fn build(&self, app: &mut App) {
        app.add_plugins((view::ViewPlugin, chart::ChartPlugin, draw::DrawPlugin));
    }
}
