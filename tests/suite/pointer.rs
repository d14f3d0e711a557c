//! The pointer, as a player uses it: a press grabs the nearest corner, the anchor follows the
//! cursor or the finger, a release, a lost focus, a second finger, a reset in the same frame,
//! a resize. Headless `App`s (`MinimalPlugins` and the game without its screen), input sent as
//! the messages winit would send, the cursor turned into world coordinates by a camera set up
//! exactly as the game's.

use crate::common;

use common::*;

#[test]
fn the_camera_maps_the_window_onto_the_scene() {
    let mut game = Game::stepping();
    game.cursor(Some(Vec2::new(640.0 + 90.0, 360.0 - 60.0)));
    game.mouse(ButtonState::Pressed);
    game.update(1);
    let anchor = game.the_band().ends.anchor;
    let expected = DVec2::new(90.0, 60.0) * HOME_SCALE;
    assert!((anchor - expected).length() < 1e-4, "{anchor}");
    assert_eq!(screen_to_world(Vec2::new(730.0, 300.0)), expected);
}

#[test]
fn a_press_spawns_one_band_at_the_nearest_corner_that_follows_the_cursor_until_release() {
    let mut game = Game::stepping();
    assert!(game.bands().is_empty());

    game.press_at(DVec2::new(150.0, -120.0));
    game.update(1);
    let band = game.the_band();
    assert_eq!(band.ends.local_point, DVec2::new(30.0, -30.0));
    assert!((band.ends.anchor - DVec2::new(150.0, -120.0)).length() < 1e-4);

    for target in [DVec2::new(0.0, 150.0), DVec2::new(-250.0, 10.0)] {
        game.cursor(Some(world_to_screen(target)));
        game.update(1);
        let band = game.the_band();
        assert!((band.ends.anchor - target).length() < 1e-4);
        // The corner is chosen at the press and kept while held.
        assert_eq!(band.ends.local_point, DVec2::new(30.0, -30.0));
    }
    assert_eq!(
        game.world().resource::<Grip>().0,
        Some(PointerSource::Mouse)
    );

    game.mouse(ButtonState::Released);
    game.update(1);
    assert!(game.bands().is_empty());
    assert_eq!(game.world().resource::<Grip>().0, None);
}

#[test]
fn a_press_and_release_in_one_frame_pulls_for_exactly_one_step() {
    let mut game = Game::stepping();
    let anchor = DVec2::new(180.0, 90.0);
    game.press_at(anchor);
    game.mouse(ButtonState::Released);
    game.update(1);
    assert!(game.bands().is_empty(), "a tap's band lasts one step");
    game.update(9);

    let mut probe = Game::stepping();
    probe.press_at(anchor);
    probe.update(1);
    let mut stepper = Stepper::new(SceneParams::tutorial()).unwrap();
    stepper.grab(probe.the_band().ends.anchor);
    stepper.step(0.01);
    stepper.release();
    for _ in 0..9 {
        stepper.step(0.01);
    }
    let (linear, angular) = game.state();
    assert!(linear.velocity.length() > 0.0);
    assert_eq!(
        (linear, angular),
        (stepper.state.linear, stepper.state.angular)
    );
}

#[test]
fn the_anchor_stays_put_while_the_cursor_is_outside_the_window() {
    let mut game = Game::stepping();
    game.press_at(DVec2::new(100.0, 100.0));
    game.update(1);
    let held = game.the_band().ends.anchor;
    game.cursor(None);
    game.update(5);
    assert_eq!(game.the_band().ends.anchor, held);
    let back = DVec2::new(-100.0, 50.0);
    game.cursor(Some(world_to_screen(back)));
    game.update(1);
    assert!((game.the_band().ends.anchor - back).length() < 1e-4);
}

#[test]
fn losing_focus_releases_the_band() {
    let mut game = Game::stepping();
    game.press_at(DVec2::new(100.0, 100.0));
    game.update(3);
    assert_eq!(game.bands().len(), 1);
    let window = game.window;
    game.world().write_message(WindowFocused {
        window,
        focused: false,
    });
    game.update(1);
    assert!(game.bands().is_empty());
    assert_eq!(game.world().resource::<Grip>().0, None);
    // The button's release that arrives later changes nothing.
    game.mouse(ButtonState::Released);
    game.update(1);
    assert!(game.bands().is_empty());
}

#[test]
fn one_finger_holds_the_band_and_a_second_is_ignored() {
    let mut game = Game::stepping();
    game.touch(7, TouchPhase::Started, DVec2::new(-150.0, 100.0));
    game.update(1);
    let band = game.the_band();
    assert_eq!(band.ends.local_point, DVec2::new(-30.0, 30.0));

    game.touch(8, TouchPhase::Started, DVec2::new(200.0, -200.0));
    game.touch(7, TouchPhase::Moved, DVec2::new(-160.0, 60.0));
    game.update(1);
    let band = game.the_band();
    assert_eq!(band.ends.local_point, DVec2::new(-30.0, 30.0));
    assert!((band.ends.anchor - DVec2::new(-160.0, 60.0)).length() < 1e-4);

    game.touch(8, TouchPhase::Ended, DVec2::new(200.0, -200.0));
    game.update(1);
    assert_eq!(
        game.bands().len(),
        1,
        "the other finger's lift changes nothing"
    );

    game.touch(7, TouchPhase::Ended, DVec2::new(-160.0, 60.0));
    game.update(1);
    assert!(game.bands().is_empty());
}

#[test]
fn a_second_press_while_a_band_exists_replaces_it() {
    let mut game = Game::stepping();
    game.touch(1, TouchPhase::Started, DVec2::new(-150.0, 100.0));
    game.update(2);
    assert_eq!(game.the_band().ends.local_point, DVec2::new(-30.0, 30.0));

    // The mouse presses while the finger still holds: the mouse takes over.
    game.press_at(DVec2::new(200.0, -200.0));
    game.update(1);
    let band = game.the_band();
    assert_eq!(band.ends.local_point, DVec2::new(30.0, -30.0));

    // The finger's lift no longer owns the band.
    game.touch(1, TouchPhase::Ended, DVec2::new(-150.0, 100.0));
    game.update(1);
    assert_eq!(game.bands().len(), 1);
    game.mouse(ButtonState::Released);
    game.update(1);
    assert!(game.bands().is_empty());
}

/// R in the frame of a press: the frame's order puts the pointer before the controls, so the
/// reset always lets go of the band that press made, and leaves the grip and the band agreeing
/// (before the order was written down, the two wrote both with no order between them).
#[test]
fn a_reset_in_the_frame_of_a_press_lets_go_and_leaves_no_band_behind() {
    let mut game = Game::stepping();
    game.press_at(DVec2::new(200.0, 100.0));
    game.update(10);
    game.mouse(ButtonState::Released);
    game.update(1);
    assert_ne!(
        game.state(),
        (LinearState::default(), AngularState::default())
    );

    game.press_at(DVec2::new(-200.0, 100.0));
    game.tap_key(key(Action::Reset));
    game.update(1);
    assert!(game.bands().is_empty(), "{:?}", game.bands());
    assert_eq!(*game.world().resource::<Grip>(), Grip(None));
    let rest = (LinearState::default(), AngularState::default());
    assert_eq!(game.state(), rest);

    // The button is still down: moving it grabs nothing, and the box stays at rest.
    game.cursor(Some(world_to_screen(DVec2::new(-250.0, 150.0))));
    game.update(5);
    assert!(game.bands().is_empty());
    assert_eq!(game.state(), rest);
    // Its release is nothing to let go of; the next press grabs as usual.
    game.mouse(ButtonState::Released);
    game.update(1);
    game.press_at(DVec2::new(200.0, 100.0));
    game.update(1);
    assert_eq!(game.bands().len(), 1);
}

/// A resize changes what the player sees, never the simulation: the box moves on exactly as
/// in a game that was not resized, and the pointer maps through the new view (the scene's
/// width now fills the window).
#[test]
fn the_state_survives_a_resize_and_the_pointer_follows_the_new_view() {
    let mut resized = Game::stepping();
    let mut twin = Game::stepping();
    for game in [&mut resized, &mut twin] {
        game.press_at(DVec2::new(200.0, 100.0));
        game.update(30);
        game.mouse(ButtonState::Released);
        game.update(1);
    }
    resized.resize(UVec2::new(720, 1280)); // portrait
    resized.update(20);
    twin.update(20);
    assert_eq!(resized.state(), twin.state());

    // Portrait: the scene's 640 units and their 4% margin fill the 720 px width, centred.
    let scale = 640.0 * 1.04 / 720.0;
    let to_screen =
        |w: DVec2| Vec2::new((360.0 + w.x / scale) as f32, (640.0 - w.y / scale) as f32);
    let target = DVec2::new(100.0, -150.0);
    resized.cursor(Some(to_screen(target)));
    resized.mouse(ButtonState::Pressed);
    resized.update(1);
    let anchor = resized.the_band().ends.anchor;
    assert!(anchor.distance(target) < 1e-3, "{anchor} for {target}");
}

/// At most one band after the pointer's system, whatever was there: of two bands on the box
/// (none of the game's paths makes a second), one is removed.
#[test]
fn of_two_bands_one_is_removed() {
    let mut game = Game::stepping();
    game.press_at(DVec2::new(200.0, 100.0));
    game.update(1);
    let held = game.the_band();
    let mut second = held;
    second.ends.anchor = DVec2::new(-150.0, -90.0);
    game.world().spawn(second);
    assert_eq!(game.bands().len(), 2);
    game.update(1);
    let left = game.the_band();
    assert!([held.ends.anchor, second.ends.anchor].contains(&left.ends.anchor));
}

/// A held band's anchor stops at the reach (the home frame less the box's diagonal), however
/// far the pointer goes: past the window's edge it stops at the viewport's edge, mapped and
/// clamped, and a press near the edge grabs at the reach's edge.
#[test]
fn the_anchor_stops_at_the_reach() {
    let mut game = Game::stepping();
    // The home frame at 1280 x 720: 1280 and 720 pixels at HOME_SCALE, less 60 * sqrt 2.
    let diagonal = 60.0 * std::f64::consts::SQRT_2;
    let reach = DVec2::new(640.0, 360.0) * HOME_SCALE - DVec2::splat(diagonal);
    game.press_at(DVec2::new(10.0, 10.0));
    game.update(1);
    for (cursor, expected) in [
        (Vec2::new(640.0, 5.0), DVec2::new(0.0, reach.y)),
        (Vec2::new(1279.0, 700.0), DVec2::new(reach.x, -reach.y)),
        (Vec2::new(0.0, 360.0), DVec2::new(-reach.x, 0.0)),
    ] {
        game.cursor(Some(cursor));
        game.update(1);
        let anchor = game.the_band().ends.anchor;
        assert!(
            (anchor - expected).length() < 1e-3,
            "{cursor}: {anchor}, not {expected}"
        );
    }
    // Inside the reach the anchor is under the cursor.
    let inside = DVec2::new(reach.x - 1.0, 1.0 - reach.y);
    game.cursor(Some(world_to_screen(inside)));
    game.update(1);
    assert!((game.the_band().ends.anchor - inside).length() < 1e-3);
}
