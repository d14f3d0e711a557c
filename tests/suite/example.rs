//! The example for Bevy readers (`examples/band.rs`) runs as it says: its plugin, headless, with
//! the real input system behind a real camera. A press grabs the nearest corner, the band held
//! moves and turns the box exactly as the core's own stepper does, and a release lets go.

#[path = "../../examples/band.rs"]
#[allow(dead_code)]
mod band;

use std::time::Duration;

use bevy::input::ButtonState;
use bevy::input::mouse::MouseButtonInput;
use bevy::math::DVec2;
use bevy::prelude::*;
use bevy::window::{PrimaryWindow, WindowResolution};
use rubber_band_box::physics::{
    AngularState, BandEnds, BodyState, LinearState, SceneParams, Stepper,
};

use crate::common::{compute_camera, headless_app};
use band::{Band, BandPlugin};

const WINDOW: UVec2 = UVec2::new(640, 480);

/// The example's plugin in a headless app stepped 10 ms a frame, with a 640 x 480 window and a
/// 2D camera at the origin as bevy_render would compute them: a window pixel is a world unit.
fn app() -> (App, Entity) {
    let mut app = headless_app(Duration::from_millis(10));
    app.add_plugins(BandPlugin);
    let window = app
        .world_mut()
        .spawn((
            Window {
                resolution: WindowResolution::new(WINDOW.x, WINDOW.y),
                ..default()
            },
            PrimaryWindow,
        ))
        .id();
    let mut projection = Projection::Orthographic(OrthographicProjection::default_2d());
    let mut camera = Camera::default();
    compute_camera(&mut camera, &mut projection, WINDOW);
    app.world_mut()
        .spawn((Camera2d, camera, projection, GlobalTransform::IDENTITY));
    // The first update starts the clock: Startup, and no fixed step.
    app.update();
    (app, window)
}

fn mouse(app: &mut App, window: Entity, state: ButtonState) {
    app.world_mut().write_message(MouseButtonInput {
        button: MouseButton::Left,
        state,
        window,
    });
}

fn body(app: &mut App) -> BodyState {
    let mut query = app.world_mut().query::<(&LinearState, &AngularState)>();
    let (linear, angular) = query.single(app.world()).unwrap();
    BodyState {
        linear: *linear,
        angular: *angular,
    }
}

fn bands(app: &mut App) -> Vec<BandEnds> {
    let mut query = app.world_mut().query::<&Band>();
    query.iter(app.world()).map(|band| band.0).collect()
}

#[test]
fn a_band_held_moves_and_turns_the_box_as_the_core_steps_it() {
    let (mut app, window) = app();
    // 100 px right of the centre and 40 px up: world (100, 40), nearest the top-right corner,
    // off the line through the centre.
    app.world_mut()
        .get_mut::<Window>(window)
        .unwrap()
        .set_cursor_position(Some(Vec2::new(420.0, 200.0)));
    mouse(&mut app, window, ButtonState::Pressed);
    // The press's frame steps the box at rest, then spawns the band.
    app.update();
    let [ends] = bands(&mut app)[..] else {
        panic!("a press spawns one band");
    };
    // The camera's f32 maths puts the pointer within a hair of where it was pressed.
    assert!(
        ends.anchor.distance(DVec2::new(100.0, 40.0)) < 1e-3,
        "{ends:?}"
    );
    assert_eq!(
        ends.local_point,
        DVec2::new(30.0, 30.0),
        "the nearest corner"
    );
    assert_eq!(
        body(&mut app),
        BodyState::default(),
        "at rest before the band acts"
    );

    const HELD: usize = 80;
    for _ in 0..HELD {
        app.update();
    }
    let mut core = Stepper::new(SceneParams::tutorial()).unwrap();
    core.grab(ends.anchor);
    for _ in 0..HELD {
        core.step(core.params.dt());
    }
    let now = body(&mut app);
    assert_eq!(
        now, core.state,
        "the example steps as the core does, to the bit"
    );
    assert!(
        now.linear.position.x > 10.0 && now.linear.position.y > 10.0,
        "{now:?}"
    );
    assert!(
        now.angular.orientation.abs() > 0.05,
        "a pull at a corner turns it: {now:?}"
    );

    mouse(&mut app, window, ButtonState::Released);
    app.update();
    assert!(bands(&mut app).is_empty(), "a release despawns the band");
}

/// The door stays short: what a Bevy reader reads before the 20,000 lines behind it.
#[test]
fn the_example_stays_under_150_lines() {
    let lines = include_str!("../../examples/band.rs").lines().count();
    assert!(lines <= 150, "examples/band.rs has {lines} lines");
}
