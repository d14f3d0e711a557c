//! What the window shows, in logical pixels: a node's rectangle cut to its clip, where a text's
//! glyphs lie, and every text shown; the layout's checks read it (no two texts meet, none on
//! the scene, all in the window), and in the browser the page is told it (`publish_texts`).

use bevy::prelude::*;
use bevy::ui::{CalculatedClip, UiGlobalTransform};

/// Returns the part of a node the window shows: its rectangle, in logical pixels, cut to its clip.
///
/// The clip is that of a node above, such as the scrolled dock. `None` when the node has no
/// size (it, or a node above it, is not displayed) or is cut away.
pub fn visible_rect(
    node: &ComputedNode,
    transform: &UiGlobalTransform,
    clip: Option<&CalculatedClip>,
    ui_scale: &UiScale,
) -> Option<Rect> {
    clipped(window_rect(node, transform, ui_scale), node, clip, ui_scale)
}

/// Cuts `rect`, in logical pixels, to the node's clip; `None` if nothing is left.
fn clipped(
    mut rect: Rect,
    node: &ComputedNode,
    clip: Option<&CalculatedClip>,
    ui_scale: &UiScale,
) -> Option<Rect> {
    let scale = node.inverse_scale_factor() * ui_scale.0;
    if let Some(clip) = clip {
        let cut = Rect::from_corners(clip.clip.min * scale, clip.clip.max * scale);
        rect = rect.intersect(cut);
    }
    (rect.width() > 0.0 && rect.height() > 0.0).then_some(rect)
}

/// Returns where a text's glyphs may lie, in logical pixels.
///
/// They lie in its node's content box (inside its padding), cut to its clip.
fn visible_text_rect(
    node: &ComputedNode,
    transform: &UiGlobalTransform,
    clip: Option<&CalculatedClip>,
    ui_scale: &UiScale,
) -> Option<Rect> {
    let scale = node.inverse_scale_factor() * ui_scale.0;
    let content = node.content_box();
    let rect = Rect::from_corners(
        (transform.translation + content.min) * scale,
        (transform.translation + content.max) * scale,
    );
    clipped(rect, node, clip, ui_scale)
}

/// Lists every text the window shows and where, in logical pixels.
///
/// The layout's checks read it (no two meet, none on the scene, all in the window).
pub fn shown_texts(
    texts: &Query<(
        &Text,
        &ComputedNode,
        &UiGlobalTransform,
        Option<&CalculatedClip>,
    )>,
    ui_scale: &UiScale,
) -> Vec<(String, Rect)> {
    texts
        .iter()
        .filter(|(text, ..)| !text.0.trim().is_empty())
        .filter_map(|(text, node, transform, clip)| {
            visible_text_rect(node, transform, clip, ui_scale).map(|rect| (text.0.clone(), rect))
        })
        .collect()
}

/// Returns where a UI node lies in the window, in logical pixels.
///
/// Logical pixels are what the pointer and the page use. It is the node's physical rectangle over
/// the window's scale factor; `ComputedNode`'s inverse scale factor also divides by the UI scale,
/// which is put back.
pub fn window_rect(node: &ComputedNode, transform: &UiGlobalTransform, ui_scale: &UiScale) -> Rect {
    let scale = node.inverse_scale_factor() * ui_scale.0;
    Rect::from_center_size(transform.translation * scale, node.size() * scale)
}
