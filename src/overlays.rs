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
