//! What the player sees: lyon fills the box and the band's pin; gizmos draw the box's outline,
//! its centre, the band (red, turning magenta as it stretches, as in the tutorial), the
//! tutorial's 640 x 480 screen, and the overlays the controls switch on (force and velocity
//! arrows, the pulled corner's trail, which this module owns and a reset clears). Needs a
//! window; reads the physics' render snapshots, never the other way round.

use std::collections::VecDeque;

use bevy::math::DVec2;
use bevy::prelude::*;
use bevy_prototype_lyon::prelude::*;

use crate::game::pointer::KeyCursor;
use crate::game::schedule::ScreenSystems;
use crate::game::shared::{Overlay, Overlays};
use crate::game::simulation::{Band, RenderSnapshots, ResetScene, RigidBox, interpolated_state};
use crate::game::theme::{VELOCITY_ARROW_SECONDS, colour, force_arrow};
use crate::physics::{MassProperties, SCENE_SIZE, SceneParams};

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
                    draw_vectors.run_if(|overlays: Res<Overlays>| overlays.on(Overlay::Vectors)),
                    (record_trail, draw_trail).chain(),
                    draw_key_cursor,
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
        ShapeBuilder::with(&rectangle)
            .fill(colour::BOX_FILL)
            .build(),
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
        ShapeBuilder::with(&circle).fill(colour::PIN_FILL).build(),
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
            colour::BOX_OUTLINE,
        );
        gizmos.cross_2d(Isometry2d::new(centre, rotation), 4.0, colour::BOX_OUTLINE);
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
    if !overlays.on(Overlay::Trail) {
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
            .map(|(i, &p)| (p, colour::PIN_FILL.with_alpha(i as f32 / n))),
    );
}

/// The keyboard's cursor's radius, in logical pixels.
const KEY_CURSOR_PIXELS: f32 = 9.0;

/// Draws the keyboard's cursor, a ringed cross, while the keyboard uses it.
fn draw_key_cursor(cursor: Res<KeyCursor>, mut gizmos: Gizmos) {
    let (true, Some((at, world_per_pixel))) = (cursor.shown, cursor.world) else {
        return;
    };
    let at = at.as_vec2();
    let radius = KEY_CURSOR_PIXELS * world_per_pixel;
    gizmos.circle_2d(at, radius, colour::FOCUS);
    for way in [Vec2::X, Vec2::Y] {
        gizmos.line_2d(
            at - way * radius * 1.6,
            at - way * radius * 0.5,
            colour::FOCUS,
        );
        gizmos.line_2d(
            at + way * radius * 0.5,
            at + way * radius * 1.6,
            colour::FOCUS,
        );
    }
}
