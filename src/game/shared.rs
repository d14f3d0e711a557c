//! What the screen shows besides the box and the band: written by the controls, read by the
//! HUD and the drawing. A leaf, so that neither of those imports the other.

use bevy::prelude::*;

/// Which overlays show.
#[derive(Resource, Debug, Default, Clone, Copy, PartialEq, Eq)]
pub struct Overlays {
    /// Force and velocity arrows.
    pub vectors: bool,
    /// The pulled corner's trail.
    pub trail: bool,
    /// Every integrator and a reference beside the live box (`ghosts`).
    pub ghosts: bool,
    /// The HUD (text, energy graph, help line) shows unless hidden.
    pub hud_hidden: bool,
}

/// The latest thing the game has to tell the player (a save, a replay opened or refused, a
/// value refused), shown on the HUD's replay line until the next.
#[derive(Resource, Debug, Default, Clone, PartialEq)]
pub struct StatusMessage(pub Option<String>);

/// Where the on-screen controls lie, in logical window pixels: a press there goes to them, not
/// to the band. The panel writes it after each layout; the pointer reads it.
#[derive(Resource, Debug, Default, Clone, PartialEq)]
pub struct ControlsArea(pub Vec<Rect>);

impl ControlsArea {
    pub fn contains(&self, point: Vec2) -> bool {
        self.0.iter().any(|rect| rect.contains(point))
    }
}
