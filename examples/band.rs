//! The game's shape at its smallest: a box pulled by a rubber band, on the crate's own core.
//!
//! - Components hold the box's linear state, angular state and mass properties.
//! - In `FixedUpdate`, one system sums the band's and damping's force and torque, then
//!   integrates them over the step with the core's default integrator (`auto`).
//! - An input system spawns the band entity on a press and despawns it on release.
//! - Gizmos draw the box and the band.
//!
//! `cargo run --example band`. The full game (`src/game`) adds around this loop a drawing
//! between steps, the pointer on touch and keyboard, the dock, the lab, learn mode and
//! replays (docs/architecture.md); a headless test drives [`BandPlugin`] (tests/suite/example.rs).

use bevy::prelude::*;
use bevy::window::PrimaryWindow;
use rubber_band_box::physics::{
    AngularState, BandEnds, BodyState, Integrator, LinearState, MassProperties, SceneParams,
};

fn main() {
    App::new()
        .add_plugins((DefaultPlugins, BandPlugin))
        .add_systems(Startup, |mut commands: Commands| {
            commands.spawn(Camera2d);
        })
        .add_systems(Update, draw)
        .run();
}

/// The physics and the input: all but the drawing, so that a test runs it without a window.
pub struct BandPlugin;

impl Plugin for BandPlugin {
    fn build(&self, app: &mut App) {
        // The tutorial's box and band, in pixels and seconds (y up), stepped 100 times a second.
        let scene = SceneParams::tutorial();
        app.insert_resource(scene)
            .insert_resource(Time::<Fixed>::from_hz(scene.step_rate_hz))
            .add_systems(Startup, spawn_box)
            .add_systems(Update, grab_and_release)
            .add_systems(FixedUpdate, step);
    }
}

/// Marks the box; its state and its mass are the core's own components.
#[derive(Component)]
#[require(LinearState, AngularState)]
pub struct RigidBox;

/// The band, an entity of its own while the button is held: a spring of zero rest length from
/// a corner of the box (`local_point`, in the box's frame) to the pointer (`anchor`).
#[derive(Component)]
pub struct Band(pub BandEnds);

fn spawn_box(mut commands: Commands, scene: Res<SceneParams>) {
    let mass = scene
        .mass_properties()
        .expect("the tutorial's box is valid");
    commands.spawn((RigidBox, mass));
}

fn state(linear: &LinearState, angular: &AngularState) -> BodyState {
    BodyState {
        linear: *linear,
        angular: *angular,
    }
}

/// A press grabs the corner nearest the pointer; the band's end follows the pointer while the
/// button is held; a release lets go.
fn grab_and_release(
    mut commands: Commands,
    buttons: Res<ButtonInput<MouseButton>>,
    window: Single<&Window, With<PrimaryWindow>>,
    camera: Single<(&Camera, &GlobalTransform)>,
    body: Single<(&LinearState, &AngularState, &MassProperties), With<RigidBox>>,
    mut bands: Query<(Entity, &mut Band)>,
) {
    if buttons.just_released(MouseButton::Left) {
        bands
            .iter()
            .for_each(|(band, _)| commands.entity(band).despawn());
        return;
    }
    let (camera, at) = *camera;
    let Some(pointer) = window
        .cursor_position()
        .and_then(|cursor| camera.viewport_to_world_2d(at, cursor).ok())
    else {
        return;
    };
    let (linear, angular, mass) = *body;
    if buttons.just_pressed(MouseButton::Left) {
        let ends = BandEnds::grabbing(mass, &state(linear, angular), pointer.as_dvec2());
        commands.spawn(Band(ends));
    }
    for (_, mut band) in &mut bands {
        band.0.anchor = pointer.as_dvec2();
    }
}

/// Sums the force and the torque on the box (the band's pull at its corner, and damping), then
/// integrates them over the fixed step with the core's default integrator (`auto`).
fn step(
    scene: Res<SceneParams>,
    time: Res<Time>,
    band: Option<Single<&Band>>,
    body: Single<(&mut LinearState, &mut AngularState, &MassProperties)>,
) {
    let (mut linear, mut angular, mass) = body.into_inner();
    let mut next = state(&linear, &angular);
    // The band goes with the sum: `auto` evaluates its force again inside the step.
    let model = scene.force_model(*mass, band.map(|band| band.0));
    let sum = model.forces(&next);
    Integrator::default().step(&mut next, &model, sum, time.delta_secs_f64());
    (*linear, *angular) = (next.linear, next.angular);
}

/// Outlines the box at its latest step and draws the band.
fn draw(
    mut gizmos: Gizmos,
    body: Single<(&LinearState, &AngularState, &MassProperties)>,
    band: Option<Single<&Band>>,
) {
    let (linear, angular, mass) = *body;
    let now = state(linear, angular);
    let corners = mass.corners().map(|c| now.local_to_world(c).as_vec2());
    gizmos.linestrip_2d(corners.into_iter().chain([corners[0]]), Color::WHITE);
    if let Some(band) = band {
        let (from, to) = (band.0.attachment(&now), band.0.anchor);
        gizmos.line_2d(from.as_vec2(), to.as_vec2(), Color::srgb(1.0, 0.35, 0.3));
    }
}
