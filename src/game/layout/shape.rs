//! The window's shape and sizes: wide or tall, the dock's width at the side, the share of a
//! tall window the scene keeps, and the UI's scale for a window.

use bevy::prelude::*;

/// The game's window when it opens, in logical pixels.
pub const WINDOW_SIZE: UVec2 = UVec2::new(960, 720);

/// The window's shape: the dock at the side of a wide window, below the scene on a tall one.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shape {
    Wide,
    Tall,
}

impl Shape {
    pub fn of(window: Vec2) -> Self {
        if window.x >= window.y {
            Shape::Wide
        } else {
            Shape::Tall
        }
    }
}

/// Returns the dock's width at the side of a wide window, in logical pixels before the UI scale.
///
/// It takes a share of the window, with a floor (the plot's 300 px and the ghosts' table) and a
/// ceiling.
pub(super) fn dock_width(window_width: f32) -> f32 {
    (window_width * 0.34).clamp(350.0, 460.0)
}

/// A tall window's sheet keeps the scene at least this share of the height.
pub(super) const SHEET_SHARE: f32 = 0.45;

/// Returns the UI's scale for a window: 1 at the game's own size and above.
///
/// On a phone it is a little smaller, never so small that text cannot be read.
pub fn ui_scale_for(size: Vec2) -> f32 {
    (size.min_element() / WINDOW_SIZE.y as f32).clamp(0.85, 1.0)
}
