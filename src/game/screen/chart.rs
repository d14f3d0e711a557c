//! What the dock's charts share: their gizmos, drawn by the chart camera only (their own
//! render layer), and their canvases, nodes of the dock with no background under which the
//! chart camera draws, in window pixels.

use bevy::camera::visibility::RenderLayers;
use bevy::gizmos::config::{GizmoConfig, GizmoConfigGroup, GizmoLineConfig};
use bevy::prelude::*;
use bevy::ui::UiGlobalTransform;

use crate::game::layout::window_rect;
use crate::game::screen::view::CHART_LAYER;

pub struct ChartPlugin;

impl Plugin for ChartPlugin {
    fn build(&self, app: &mut App) {
        app.insert_gizmo_config(
            ChartGizmos,
            GizmoConfig {
                render_layers: RenderLayers::layer(CHART_LAYER),
                line: GizmoLineConfig {
                    width: 1.5,
                    ..default()
                },
                ..default()
            },
        );
    }
}

/// The charts' gizmos.
#[derive(Default, Reflect, GizmoConfigGroup)]
pub struct ChartGizmos;

/// A chart's canvas on the window, in logical pixels, and the UI's scale.
///
/// A canvas's children are placed in the UI's units, which the scale multiplies.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Canvas {
    pub rect: Rect,
    pub ui_scale: f32,
}

impl Canvas {
    pub fn of(node: &ComputedNode, transform: &UiGlobalTransform, ui_scale: &UiScale) -> Self {
        Self {
            rect: window_rect(node, transform, ui_scale),
            ui_scale: ui_scale.0,
        }
    }

    /// Returns the canvas's size in the UI's units.
    pub fn size(&self) -> Vec2 {
        self.rect.size() / self.ui_scale
    }

    /// Returns where the chart camera draws a point given from the canvas's top left.
    ///
    /// `point` is in the UI's units; the chart camera's origin is at the window's centre, y up.
    pub fn to_chart(&self, point: Vec2, window: Vec2) -> Vec2 {
        let on_window = self.rect.min + point * self.ui_scale;
        Vec2::new(on_window.x - window.x / 2.0, window.y / 2.0 - on_window.y)
    }
}

/// Returns a text's box in the UI's units: what the labels' placer avoids.
///
/// It is measured as the figures' face sets it (every glyph 0.602 of the font's size wide, a line
/// 1.2 of it high).
pub(crate) fn text_box(at: Vec2, text: &str, font_size: f32) -> Rect {
    let size = Vec2::new(
        text.chars().count() as f32 * 0.602 * font_size,
        1.2 * font_size,
    );
    Rect::from_corners(at, at + size)
}
