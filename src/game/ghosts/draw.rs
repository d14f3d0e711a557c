//! The ghosts drawn over the scene: each a thin outline in its colour with its band, and their
//! names in a column beside the reference that stays in view. It needs a window: the ghosts'
//! plugin adds it when the game has a screen.

use bevy::prelude::*;

use super::steppers::{Ghost, GhostKind, Ghosts};
use crate::game::camera::{SceneView, shown_area, world_per_pixel};
use crate::game::schedule::ScreenSystems;
use crate::game::simulation::RenderSnapshots;
use crate::physics::{BodyState, Integrator, SCENE_SIZE};

/// Draws the ghosts and their names.
pub(super) fn plugin(app: &mut App) {
    app.add_systems(Update, draw_ghosts.in_set(ScreenSystems::Draw));
}

/// A ghost's name, drawn beside its outline.
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
pub struct GhostLabel(pub GhostKind);

/// The names' size in the world, and on screen at the least (on a phone the scene is small).
const GHOST_LABEL_SIZE: f32 = 11.0;
const GHOST_LABEL_PIXELS: f32 = 11.0;

/// Returns where a column of names goes beside an outline: the first side that stays in view.
///
/// The column holds `lines` names, each `line` high and at most `width` wide; the outline is at
/// `centre` and reaches `reach` from it. The column goes above, below, right or left of it, the
/// first that lies inside `shown` (the part of the world in view); above when none does. Returned
/// as the offset from `centre` of the column's first line and the step to the next (names that
/// coincide, most ghosts on a soft band, keep apart).
fn label_column(
    centre: Vec2,
    reach: f32,
    lines: usize,
    (line, width): (f32, f32),
    shown: Rect,
) -> (Vec2, Vec2) {
    let height = lines as f32 * line;
    let half_line = line / 2.0;
    let up = Vec2::new(0.0, line);
    // (The first line's centre, the step), for above, below, right and left.
    let sides = [
        (Vec2::new(0.0, reach + half_line), up),
        (Vec2::new(0.0, -reach - half_line), -up),
        (
            Vec2::new(reach + width / 2.0, height / 2.0 - half_line),
            -up,
        ),
        (
            Vec2::new(-reach - width / 2.0, height / 2.0 - half_line),
            -up,
        ),
    ];
    let column = |(first, step): (Vec2, Vec2)| {
        let last = first + step * (lines.max(1) - 1) as f32;
        Rect::from_corners(centre + first, centre + last)
            .inflate(half_line)
            .union(Rect::from_center_size(
                centre + first,
                Vec2::new(width, 0.0),
            ))
    };
    sides
        .into_iter()
        .find(|&side| {
            let rect = column(side);
            shown.union(rect) == shown
        })
        .unwrap_or(sides[0])
}

/// Draws each ghost as a thin outline in its colour, with its band and its name.
///
/// A ghost is drawn between its last two steps as the live box is; a diverged one is crossed out
/// where it froze, with the step. The ghost of the live box's own integrator is not drawn (it lies
/// under the box).
fn draw_ghosts(
    mut commands: Commands,
    mut gizmos: Gizmos,
    fixed_time: Res<Time<Fixed>>,
    ghosts: Res<Ghosts>,
    integrator: Res<Integrator>,
    view: SceneView,
    mut labels: Query<(
        Entity,
        &GhostLabel,
        &mut Text2d,
        &mut TextFont,
        &mut Transform,
        &mut Visibility,
    )>,
) {
    let alpha = fixed_time.overstep_fraction_f64().clamp(0.0, 1.0);
    let names = ghost_names(&ghosts);
    // However far the camera widens, the names keep their size on screen.
    let font_size = GHOST_LABEL_SIZE.max(GHOST_LABEL_PIXELS * world_per_pixel(&view.frame));
    let column = name_column(&ghosts, alpha, font_size, &names, &view);
    let live = GhostKind::Method(*integrator);
    let mut unlabelled: Vec<GhostKind> = ghosts.ghosts.iter().map(|g| g.kind).collect();
    for (entity, label, mut text, mut font, mut transform, mut visibility) in &mut labels {
        let Some((index, ghost)) = ghosts
            .ghosts
            .iter()
            .enumerate()
            .find(|(_, g)| g.kind == label.0)
        else {
            commands.entity(entity).despawn();
            continue;
        };
        unlabelled.retain(|&kind| kind != label.0);
        if font.font_size != FontSize::Px(font_size) {
            font.font_size = FontSize::Px(font_size);
        }
        let hidden = ghost.kind == live;
        visibility.set_if_neq(if hidden {
            Visibility::Hidden
        } else {
            Visibility::Inherited
        });
        if hidden {
            continue;
        }
        draw_outline(&mut gizmos, ghost, interpolated(ghost, alpha));
        if text.0 != names[index] {
            text.0.clone_from(&names[index]);
        }
        // Each name on its own line of the column, by the ghost's place among those drawn.
        let place = ghosts
            .ghosts
            .iter()
            .filter(|g| g.kind != live)
            .position(|g| g.kind == ghost.kind)
            .unwrap_or(0);
        if let Some((first, step)) = column {
            transform.translation = (first + step * place as f32).extend(2.0);
        }
    }
    for kind in unlabelled {
        commands.spawn(ghost_label(kind));
    }
}

/// Returns each ghost's name, in the list's order: a diverged one with the step it diverged at.
fn ghost_names(ghosts: &Ghosts) -> Vec<String> {
    ghosts
        .ghosts
        .iter()
        .map(|ghost| match ghost.diverged_at {
            Some(step) => format!("{} diverged @{step}", ghost.kind.name()),
            None => ghost.kind.name().to_owned(),
        })
        .collect()
}

/// Returns a ghost's state drawn between its last two steps (where it froze, if diverged).
fn interpolated(ghost: &Ghost, alpha: f64) -> BodyState {
    RenderSnapshots {
        previous: ghost.previous,
        current: ghost.stepper.state,
    }
    .interpolate(if ghost.diverged_at.is_some() {
        1.0
    } else {
        alpha
    })
}

/// Returns where the names' column starts and the step to its next line, beside the reference.
///
/// One column for every name, beside the reference, which follows the live box: a column
/// beside each ghost's own outline would start a few px from the next one's, and the names of
/// two ghosts close together would be drawn over each other. The list always holds the
/// reference.
fn name_column(
    ghosts: &Ghosts,
    alpha: f64,
    font_size: f32,
    names: &[String],
    view: &SceneView,
) -> Option<(Vec2, Vec2)> {
    let line = font_size * 1.2;
    let shown = view
        .window
        .as_deref()
        .and_then(|window| shown_area(&view.frame, &view.viewport, window))
        .unwrap_or(Rect::from_center_size(Vec2::ZERO, SCENE_SIZE.as_vec2()));
    let widest = names.iter().map(String::len).max().unwrap_or(0) as f32 * font_size * 0.6;
    let reference = ghosts
        .ghosts
        .iter()
        .find(|ghost| ghost.kind == GhostKind::Reference)?;
    let beside = interpolated(reference, alpha).linear.position.as_vec2();
    let reach = reference.stepper.mass.size().as_vec2().length() / 2.0 + 4.0;
    let lines = ghosts.ghosts.len().saturating_sub(1);
    let (first, step) = label_column(beside, reach, lines, (line, widest), shown);
    Some((beside + first, step))
}

/// Draws a ghost's outline and band in its colour, crossed out if it diverged.
fn draw_outline(gizmos: &mut Gizmos, ghost: &Ghost, state: BodyState) {
    let colour = ghost.kind.colour().with_alpha(0.8);
    let centre = state.linear.position.as_vec2();
    let rotation = Rot2::radians(state.angular.orientation as f32);
    let size = ghost.stepper.mass.size().as_vec2();
    gizmos.rect_2d(Isometry2d::new(centre, rotation), size, colour);
    if let Some(band) = ghost.stepper.band {
        let corner = band.attachment(&state).as_vec2();
        gizmos.line_2d(corner, band.anchor.as_vec2(), colour.with_alpha(0.35));
    }
    if ghost.diverged_at.is_some() {
        let half = size / 2.0;
        for corner in [half, Vec2::new(half.x, -half.y)] {
            let a = centre + rotation * corner;
            let b = centre - rotation * corner;
            gizmos.line_2d(a, b, colour);
        }
    }
}

/// Returns a ghost's name label, hidden until the drawing places it.
fn ghost_label(kind: GhostKind) -> impl Bundle {
    (
        Name::new("Ghost label"),
        GhostLabel(kind),
        Text2d::new(kind.name()),
        TextFont::from_font_size(GHOST_LABEL_SIZE),
        TextColor(kind.colour()),
        Transform::default(),
        Visibility::Hidden,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Checks that the ghosts' names stay in view.
    ///
    /// They go above the box, or where that would leave the view, below it, right or left of it.
    #[test]
    fn the_ghosts_names_stay_in_view() {
        let (reach, lines, line, width) = (45.0, 7, 13.2, 90.0);
        let shown = Rect::from_center_size(Vec2::ZERO, SCENE_SIZE.as_vec2());
        let (first, step) = label_column(Vec2::ZERO, reach, lines, (line, width), shown);
        assert!(first.x == 0.0 && first.y > reach && step == Vec2::new(0.0, line));
        // At the top edge: not above.
        let top = Vec2::new(0.0, 200.0);
        let (first, _) = label_column(top, reach, lines, (line, width), shown);
        assert!(first.y < 0.0 || first.x != 0.0, "{first}");
    }
}
