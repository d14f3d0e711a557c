//! What the player sees: lyon fills the box and the band's pin; gizmos draw the box's outline,
//! its centre, the band (red, turning magenta as it stretches, as in the tutorial), the
//! tutorial's 640 x 480 screen, and the overlays the controls switch on (force and velocity
//! arrows, the pulled corner's trail, which this module owns and a reset clears). Needs a
//! window; reads the physics' render snapshots, never the other way round.

use std::collections::VecDeque;

use bevy::math::DVec2;
use bevy::prelude::*;
use bevy_prototype_lyon::prelude::*;

use crate::game::camera::{SceneView, shown_area, viewport_rect, world_per_pixel};
use crate::game::ghosts::{Ghost, GhostKind, Ghosts};
use crate::game::learn::Learning;
use crate::game::learn::chapters::{CHAPTERS, Equation};
use crate::game::learn::twin::CentreTwin;
use crate::game::schedule::ScreenSystems;
use crate::game::shared::{Mode, Overlays};
use crate::game::simulation::{Band, RenderSnapshots, ResetScene, RigidBox, interpolated_state};
use crate::game::theme::colour;
use crate::physics::{BodyState, Integrator, MassProperties, SCENE_SIZE, SceneParams};

const BOX_FILL: Color = Color::srgb(0.16, 0.42, 0.72);
pub const BOX_OUTLINE: Color = Color::WHITE;
pub const PIN_FILL: Color = Color::srgb(1.0, 0.85, 0.2);
const SCENE_BORDER: Color = colour::FRAME;
const PIN_RADIUS: f32 = 5.0;
/// The tutorial's band colour is [255, 0, min(length / 2, 255)]: fully magenta at this length.
const BAND_MAGENTA_LENGTH: f64 = 510.0;

pub struct DrawPlugin;

impl Plugin for DrawPlugin {
    fn build(&self, app: &mut App) {
        app.add_observer(fill_box)
            .add_observer(pin_band)
            .add_observer(clear_trail_on_reset)
            .init_resource::<Trail>()
            .add_systems(Startup, thicken_lines)
            .add_systems(
                Update,
                (
                    draw_scene_border,
                    refill_resized_boxes,
                    draw_boxes,
                    draw_bands,
                    draw_vectors.run_if(|overlays: Res<Overlays>| overlays.vectors),
                    draw_learning.run_if(in_state(Mode::Learn)),
                    (record_trail, draw_trail).chain(),
                    draw_ghosts,
                )
                    .in_set(ScreenSystems::Draw),
            );
    }
}

fn thicken_lines(mut store: ResMut<GizmoConfigStore>) {
    let (config, _) = store.config_mut::<DefaultGizmoConfigGroup>();
    config.line.width = 2.0;
}

/// The size a box's filled body was built for.
#[derive(Component, Debug, Clone, Copy, PartialEq)]
struct FilledSize(DVec2);

/// Builds a box's filled body for its size.
fn box_fill(size: DVec2) -> impl Bundle {
    let rectangle = shapes::Rectangle {
        extents: size.as_vec2(),
        origin: RectangleOrigin::Center,
        radii: None,
    };
    (
        ShapeBuilder::with(&rectangle).fill(BOX_FILL).build(),
        FilledSize(size),
    )
}

/// Gives a new box its filled body.
fn fill_box(add: On<Add, RigidBox>, boxes: Query<&MassProperties>, mut commands: Commands) {
    if let Ok(mass) = boxes.get(add.entity) {
        commands.entity(add.entity).insert(box_fill(mass.size()));
    }
}

/// Builds a box's body again when its size changes (the size slider, a link, a replay).
fn refill_resized_boxes(
    boxes: Query<(Entity, &MassProperties, &FilledSize), Changed<MassProperties>>,
    mut commands: Commands,
) {
    for (entity, mass, filled) in &boxes {
        if mass.size() != filled.0 {
            commands.entity(entity).insert(box_fill(mass.size()));
        }
    }
}

/// Gives a new band a pin at its anchor.
fn pin_band(add: On<Add, Band>, bands: Query<&Band>, mut commands: Commands) {
    let Ok(band) = bands.get(add.entity) else {
        return;
    };
    let circle = shapes::Circle {
        radius: PIN_RADIUS,
        center: Vec2::ZERO,
    };
    commands.entity(add.entity).insert((
        ShapeBuilder::with(&circle).fill(PIN_FILL).build(),
        Transform::from_translation(band.ends.anchor.as_vec2().extend(1.0)),
    ));
}

fn draw_scene_border(mut gizmos: Gizmos) {
    gizmos.rect_2d(Isometry2d::IDENTITY, SCENE_SIZE.as_vec2(), SCENE_BORDER);
}

fn draw_boxes(
    mut gizmos: Gizmos,
    fixed_time: Res<Time<Fixed>>,
    boxes: Query<(&RenderSnapshots, &MassProperties)>,
) {
    for (snapshots, mass) in &boxes {
        let state = interpolated_state(snapshots, &fixed_time);
        let centre = state.linear.position.as_vec2();
        let rotation = Rot2::radians(state.angular.orientation as f32);
        gizmos.rect_2d(
            Isometry2d::new(centre, rotation),
            mass.size().as_vec2(),
            BOX_OUTLINE,
        );
        gizmos.cross_2d(Isometry2d::new(centre, rotation), 4.0, BOX_OUTLINE);
    }
}

fn draw_bands(
    mut gizmos: Gizmos,
    fixed_time: Res<Time<Fixed>>,
    bands: Query<&Band>,
    bodies: Query<&RenderSnapshots>,
) {
    for band in &bands {
        let Ok(snapshots) = bodies.get(band.body) else {
            continue;
        };
        let state = interpolated_state(snapshots, &fixed_time);
        let corner = band.ends.attachment(&state);
        gizmos.line_2d(
            corner.as_vec2(),
            band.ends.anchor.as_vec2(),
            band_colour(corner.distance(band.ends.anchor)),
        );
    }
}

/// Returns the band's colour: red when slack, toward magenta as the band stretches.
fn band_colour(length: f64) -> Color {
    Color::srgb(1.0, 0.0, (length / BAND_MAGENTA_LENGTH).min(1.0) as f32)
}

const VELOCITY_COLOUR: Color = colour::VELOCITY;
const FORCE_COLOUR: Color = colour::FORCE;
/// The velocity arrow shows where the centre will be in this many seconds.
const VELOCITY_ARROW_SECONDS: f32 = 0.25;
/// Returns the force arrow's length, which grows with the logarithm of the force.
///
/// That way k = 20 and k = 1e9 both fit.
fn force_arrow_length(force: f64) -> f64 {
    (30.0 * (1.0 + force / 10.0).log10()).min(300.0)
}

/// Returns the arrow drawn for `force`: along it, [`force_arrow_length`] long.
fn force_arrow(force: DVec2) -> DVec2 {
    force.normalize_or_zero() * force_arrow_length(force.length())
}

/// Draws the velocity at the centre and the band's force at its corner.
fn draw_vectors(
    mut gizmos: Gizmos,
    params: Res<SceneParams>,
    fixed_time: Res<Time<Fixed>>,
    bodies: Query<&RenderSnapshots>,
    bands: Query<&Band>,
) {
    for snapshots in &bodies {
        let state = interpolated_state(snapshots, &fixed_time);
        let centre = state.linear.position.as_vec2();
        let velocity = state.linear.velocity.as_vec2() * VELOCITY_ARROW_SECONDS;
        gizmos.arrow_2d(centre, centre + velocity, VELOCITY_COLOUR);
    }
    for band in &bands {
        let Ok(snapshots) = bodies.get(band.body) else {
            continue;
        };
        let state = interpolated_state(snapshots, &fixed_time);
        let corner = band.ends.attachment(&state);
        let arrow = force_arrow(band.ends.wrench(&state, params.stiffness).force);
        gizmos.arrow_2d(corner.as_vec2(), (corner + arrow).as_vec2(), FORCE_COLOUR);
    }
}

/// How far the torque's arc sweeps about the centre, in its sense, and its radius (world px).
const TORQUE_SWEEP: f32 = 1.5 * std::f32::consts::PI;
const TORQUE_RADIUS: f32 = 22.0;

/// Draws learn mode's pictures of its equations, in their colours.
///
/// It draws the arm r from the centre to the band's corner, the torque τ as an arc about the centre
/// in its sense; with no band, the corner a press would take, nearest where the press would
/// put the anchor (the pointer's own map, `CameraFrame::anchor_at`: the rubber band's chapter);
/// the centre twin with the band's force at its centre.
fn draw_learning(
    mut gizmos: Gizmos,
    learning: Res<Learning>,
    (params, fixed_time): (Res<SceneParams>, Res<Time<Fixed>>),
    twin: Res<CentreTwin>,
    bodies: Query<(Entity, &RenderSnapshots, &MassProperties), With<RigidBox>>,
    bands: Query<&Band>,
    view: SceneView,
) {
    let SceneView {
        window,
        viewport,
        frame,
    } = view;
    let Some(chapter) = CHAPTERS.get(learning.chapter) else {
        return;
    };
    let shows = |equation: Equation| chapter.equations.contains(&equation);
    let [left, _, _, top] = chapter.frame;
    axes_marker(&mut gizmos, Vec2::new(left + 14.0, top - 44.0));
    for (body, snapshots, mass) in &bodies {
        let state = interpolated_state(snapshots, &fixed_time);
        let centre = state.linear.position.as_vec2();
        let band = bands.iter().find(|band| band.body == body);
        if let Some(twin) = &twin.body {
            let beside = twin.beside(&state).linear.position;
            let angle = Rot2::radians(twin.orientation as f32);
            let pose = Isometry2d::new(beside.as_vec2(), angle);
            gizmos.rect_2d(pose, mass.size().as_vec2(), colour::TWIN);
            gizmos.cross_2d(pose, 4.0, colour::TWIN);
            // The box's band force, the same arrow as at the box's corner, at the twin's centre.
            if let Some(band) = band {
                let arrow = force_arrow(band.ends.wrench(&state, params.stiffness).force);
                gizmos.arrow_2d(beside.as_vec2(), (beside + arrow).as_vec2(), FORCE_COLOUR);
            }
        }
        if shows(Equation::PointMasses) {
            point_masses(&mut gizmos, &state, mass.size(), learning.point_masses);
        }
        if let Some(band) = band
            && shows(Equation::PointVelocity)
        {
            point_velocity(&mut gizmos, snapshots, &state, band, &fixed_time);
        }
        if let Some(band) = band {
            let corner = band.ends.attachment(&state).as_vec2();
            if shows(Equation::Arm) || shows(Equation::Torque) {
                gizmos.arrow_2d(centre, corner, colour::ARM);
            }
            let torque = band.ends.wrench(&state, params.stiffness).torque;
            if shows(Equation::Torque) && torque != 0.0 {
                torque_arc(
                    &mut gizmos,
                    centre,
                    state.angular.orientation as f32,
                    torque,
                );
            }
        } else if shows(Equation::NearestCorner)
            && let Some(window) = window.as_deref()
            && let Some(cursor) = window.cursor_position()
        {
            let area = viewport_rect(&viewport, window);
            let span = mass.size().length() as f32;
            let anchor = frame.anchor_at(area, span, cursor);
            let nearest = mass.nearest_corner(&state, anchor);
            let corner = state.local_to_world(nearest).as_vec2();
            gizmos.circle_2d(corner, 6.0, colour::FORCE);
            gizmos.line_2d(corner, anchor.as_vec2(), colour::FORCE.with_alpha(0.4));
        }
    }
}

/// Draws the axes, x to the right and y up, and an arc from x to y: positive θ, counter-clockwise.
fn axes_marker(gizmos: &mut Gizmos, origin: Vec2) {
    const LENGTH: f32 = 30.0;
    let dim = colour::DIM;
    gizmos.arrow_2d(origin, origin + Vec2::X * LENGTH, dim);
    gizmos.arrow_2d(origin, origin + Vec2::Y * LENGTH, dim);
    let radius = 0.6 * LENGTH;
    let at = |angle: f32| origin + radius * Vec2::from_angle(angle);
    let quarter = std::f32::consts::FRAC_PI_2;
    gizmos.linestrip_2d((2..=14).map(|k| at(quarter * k as f32 / 16.0)), dim);
    let tip = at(quarter * 14.0 / 16.0);
    let ahead = Vec2::from_angle(quarter * 14.0 / 16.0 + quarter);
    for side in [-0.5f32, 0.5] {
        gizmos.line_2d(tip, tip + Vec2::from_angle(side).rotate(-ahead) * 5.0, dim);
    }
}

/// Draws the band's corner's velocity v + ω r⊥ (green) beside its latest step's move / dt (grey).
///
/// The two agree as the step is small.
fn point_velocity(
    gizmos: &mut Gizmos,
    snapshots: &RenderSnapshots,
    state: &BodyState,
    band: &Band,
    fixed_time: &Time<Fixed>,
) {
    let corner = band.ends.attachment(state);
    let arm = corner - state.linear.position;
    let omega = state.angular.angular_velocity;
    let velocity = state.linear.velocity + omega * DVec2::new(-arm.y, arm.x);
    let seconds = f64::from(VELOCITY_ARROW_SECONDS);
    let from = corner.as_vec2();
    gizmos.arrow_2d(
        from,
        (corner + velocity * seconds).as_vec2(),
        VELOCITY_COLOUR,
    );
    let dt = fixed_time.timestep().as_secs_f64();
    let moved =
        band.ends.attachment(&snapshots.current) - band.ends.attachment(&snapshots.previous);
    if moved != DVec2::ZERO {
        let stepped = moved / dt * seconds;
        gizmos.arrow_2d(from, (corner + stepped).as_vec2(), colour::DIM);
    }
}

/// Draws the n × n point masses whose Σ mₖ |rₖ|² the moment of inertia's chapter sums.
fn point_masses(gizmos: &mut Gizmos, state: &BodyState, size: DVec2, n: u32) {
    let n = n.max(1);
    let cell = size / f64::from(n);
    let radius = (0.25 * cell.min_element()).clamp(0.6, 3.0) as f32;
    for i in 0..n {
        for j in 0..n {
            let local = DVec2::new(
                (f64::from(i) + 0.5) * cell.x - 0.5 * size.x,
                (f64::from(j) + 0.5) * cell.y - 0.5 * size.y,
            );
            let at = state.local_to_world(local).as_vec2();
            gizmos.circle_2d(at, radius, colour::TEXT);
        }
    }
}

/// Draws an arc about `centre` sweeping in the torque's sense, with its head at the end.
///
/// The arc runs counter-clockwise for a positive torque.
fn torque_arc(gizmos: &mut Gizmos, centre: Vec2, from: f32, torque: f64) {
    let sense = if torque > 0.0 { 1.0 } else { -1.0 };
    let at = |angle: f32| centre + TORQUE_RADIUS * Vec2::from_angle(angle);
    let points = (0..=32).map(|k| at(from + sense * TORQUE_SWEEP * k as f32 / 32.0));
    gizmos.linestrip_2d(points, colour::TORQUE);
    let end = from + sense * TORQUE_SWEEP;
    let tip = at(end);
    // The tangent at the end, in the sweep's sense.
    let ahead = Vec2::from_angle(end + sense * std::f32::consts::FRAC_PI_2);
    for side in [-0.5f32, 0.5] {
        let back = Vec2::from_angle(side).rotate(-ahead) * 8.0;
        gizmos.line_2d(tip, tip + back, colour::TORQUE);
    }
}

/// Where the pulled corner has been, newest last; the corner is the last one a band held.
#[derive(Resource, Default)]
struct Trail {
    corner: Option<DVec2>,
    points: VecDeque<Vec2>,
}

const TRAIL_LENGTH: usize = 240;

fn record_trail(
    overlays: Res<Overlays>,
    fixed_time: Res<Time<Fixed>>,
    bodies: Query<&RenderSnapshots, With<RigidBox>>,
    bands: Query<&Band>,
    mut trail: ResMut<Trail>,
) {
    if !overlays.trail {
        trail.points.clear();
        return;
    }
    if let Some(band) = bands.iter().next() {
        trail.corner = Some(band.ends.local_point);
    }
    let (Some(corner), Some(snapshots)) = (trail.corner, bodies.iter().next()) else {
        return;
    };
    let point = interpolated_state(snapshots, &fixed_time).local_to_world(corner);
    trail.points.push_back(point.as_vec2());
    while trail.points.len() > TRAIL_LENGTH {
        trail.points.pop_front();
    }
}

fn clear_trail_on_reset(_reset: On<ResetScene>, mut trail: ResMut<Trail>) {
    *trail = Trail::default();
}

/// Draws the pulled corner's trail; older points fade out.
fn draw_trail(mut gizmos: Gizmos, trail: Res<Trail>) {
    let n = trail.points.len().max(1) as f32;
    gizmos.linestrip_gradient_2d(
        trail
            .points
            .iter()
            .enumerate()
            .map(|(i, &p)| (p, PIN_FILL.with_alpha(i as f32 / n))),
    );
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
    let SceneView {
        window,
        viewport,
        frame,
    } = view;
    let alpha = fixed_time.overstep_fraction_f64().clamp(0.0, 1.0);
    // Each ghost's name, in the list's order, written once a frame.
    let names: Vec<String> = ghosts
        .ghosts
        .iter()
        .map(|ghost| match ghost.diverged_at {
            Some(step) => format!("{} diverged @{step}", ghost.kind.name()),
            None => ghost.kind.name().to_owned(),
        })
        .collect();
    // However far the camera widens, the names keep their size on screen.
    let font_size = GHOST_LABEL_SIZE.max(GHOST_LABEL_PIXELS * world_per_pixel(&frame));
    let line = font_size * 1.2;
    let shown = window
        .as_deref()
        .and_then(|window| shown_area(&frame, &viewport, window))
        .unwrap_or(Rect::from_center_size(Vec2::ZERO, SCENE_SIZE.as_vec2()));
    let widest = names.iter().map(String::len).max().unwrap_or(0) as f32 * font_size * 0.6;
    // One column for every name, beside the reference, which follows the live box: a column
    // beside each ghost's own outline would start a few px from the next one's, and the names
    // of two ghosts close together would be drawn over each other.
    let interpolated = |ghost: &Ghost| {
        RenderSnapshots {
            previous: ghost.previous,
            current: ghost.stepper.state,
        }
        .interpolate(if ghost.diverged_at.is_some() {
            1.0
        } else {
            alpha
        })
    };
    // (Where the first name goes, the step to the next.) The list always holds the reference.
    let column = ghosts
        .ghosts
        .iter()
        .find(|ghost| ghost.kind == GhostKind::Reference)
        .map(|reference| {
            let beside = interpolated(reference).linear.position.as_vec2();
            let reach = reference.stepper.mass.size().as_vec2().length() / 2.0 + 4.0;
            let lines = ghosts.ghosts.len().saturating_sub(1);
            let (first, step) = label_column(beside, reach, lines, (line, widest), shown);
            (beside + first, step)
        });
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
        let hidden = ghost.kind == GhostKind::Method(*integrator);
        visibility.set_if_neq(if hidden {
            Visibility::Hidden
        } else {
            Visibility::Inherited
        });
        if hidden {
            continue;
        }
        let state = interpolated(ghost);
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
        if text.0 != names[index] {
            text.0.clone_from(&names[index]);
        }
        // Each name on its own line of the column, by the ghost's place among those drawn.
        let place = ghosts
            .ghosts
            .iter()
            .filter(|g| g.kind != GhostKind::Method(*integrator))
            .position(|g| g.kind == ghost.kind)
            .unwrap_or(0);
        if let Some((first, step)) = column {
            transform.translation = (first + step * place as f32).extend(2.0);
        }
    }
    for kind in unlabelled {
        commands.spawn((
            Name::new("Ghost label"),
            GhostLabel(kind),
            Text2d::new(kind.name()),
            TextFont::from_font_size(GHOST_LABEL_SIZE),
            TextColor(kind.colour()),
            Transform::default(),
            Visibility::Hidden,
        ));
    }
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
