//! Learn mode's pictures of its equations, drawn over the scene in their colours: the arm and
//! the torque's arc, the corner a press would take, the centre twin, the corner's velocity, the
//! point masses and the axes' marker of positive θ. It needs a window: learn mode's plugin adds
//! it when the game has a screen.

use bevy::math::DVec2;
use bevy::prelude::*;

use super::chapters::{CHAPTERS, Equation};
use super::equations::point_mass_arms;
use super::learning::Learning;
use super::twin::CentreTwin;
use crate::game::camera::{SceneView, viewport_rect};
use crate::game::schedule::ScreenSystems;
use crate::game::shared::Mode;
use crate::game::simulation::{Band, RenderSnapshots, RigidBox, interpolated_state};
use crate::game::theme::{VELOCITY_ARROW_SECONDS, colour, force_arrow};
use crate::physics::{BodyState, MassProperties, SceneParams};

/// Draws learn mode's pictures while the mode is on.
pub(super) fn plugin(app: &mut App) {
    app.add_systems(
        Update,
        draw_learning
            .run_if(in_state(Mode::Learn))
            .in_set(ScreenSystems::Draw),
    );
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
                gizmos.arrow_2d(beside.as_vec2(), (beside + arrow).as_vec2(), colour::FORCE);
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
        colour::VELOCITY,
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
    let cell = size / f64::from(n.max(1));
    let radius = (0.25 * cell.min_element()).clamp(0.6, 3.0) as f32;
    for arm in point_mass_arms(size, n) {
        let at = state.local_to_world(arm).as_vec2();
        gizmos.circle_2d(at, radius, colour::TEXT);
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
