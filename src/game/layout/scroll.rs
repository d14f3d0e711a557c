//! The dock's scrolling: the wheel or a drag over a dock taller than the window scrolls it,
//! and its scrollbar shows only while its cards overflow.

use bevy::prelude::*;
use bevy::window::PrimaryWindow;

use super::visible::window_rect;
use crate::game::theme::colour;

/// The dock's cards, in a column that scrolls when they are taller than the dock.
#[derive(Component, Debug)]
pub struct DockCards;

/// The dock's scrollbar: seen only while the cards overflow, a sign that there is more.
#[derive(Component, Debug)]
pub struct DockScrollbar;

/// Scrolls the dock with the wheel over it or a finger's drag that starts on it.
///
/// Over the scene the wheel zooms the view instead.
pub(super) fn scroll_the_dock(
    mut wheel: MessageReader<bevy::input::mouse::MouseWheel>,
    touches: Res<Touches>,
    windows: Query<&Window, With<PrimaryWindow>>,
    ui_scale: Res<UiScale>,
    mut docks: Query<(&ComputedNode, &UiGlobalTransform, &mut ScrollPosition), With<DockCards>>,
) {
    let cursor = windows.iter().next().and_then(Window::cursor_position);
    for event in wheel.read() {
        let lines = match event.unit {
            bevy::input::mouse::MouseScrollUnit::Line => event.y * 24.0,
            bevy::input::mouse::MouseScrollUnit::Pixel => event.y,
        };
        for (node, transform, mut scroll) in &mut docks {
            let rect = window_rect(node, transform, &ui_scale);
            if cursor.is_some_and(|at| rect.contains(at)) {
                scroll.0.y = (scroll.0.y - lines).max(0.0);
            }
        }
    }
    for touch in touches.iter() {
        let moved = touch.delta().y;
        for (node, transform, mut scroll) in &mut docks {
            let rect = window_rect(node, transform, &ui_scale);
            if moved != 0.0 && rect.contains(touch.start_position()) {
                scroll.0.y = (scroll.0.y - moved / ui_scale.0).max(0.0);
            }
        }
    }
}

/// Shows the dock's scrollbar while its cards are taller than the dock, and hides it when not.
///
/// Only colours change: the bar keeps its width either way, so the layout never moves.
pub(super) fn show_the_dock_scrollbar(
    cards: Query<&ComputedNode, With<DockCards>>,
    bars: Query<(&Children, Entity), With<DockScrollbar>>,
    mut colours: Query<&mut BackgroundColor>,
) {
    let Some(node) = cards.iter().next() else {
        return;
    };
    let (track, thumb) = if tells_overflow(node) {
        (colour::CARD, colour::DIM)
    } else {
        (Color::NONE, Color::NONE)
    };
    for (thumbs, bar) in &bars {
        if let Ok(mut background) = colours.get_mut(bar) {
            background.set_if_neq(BackgroundColor(track));
        }
        for thumb_entity in thumbs {
            if let Ok(mut background) = colours.get_mut(*thumb_entity) {
                background.set_if_neq(BackgroundColor(thumb));
            }
        }
    }
}

/// Tells whether a scrolled node's content is taller than the node (by more than a pixel).
fn tells_overflow(node: &ComputedNode) -> bool {
    let scale = node.inverse_scale_factor();
    (node.content_size().y - node.size().y) * scale > 1.0
}
