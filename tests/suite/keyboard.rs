//! The band by keyboard (docs/controls.md): the arrows move a cursor on the scene, B grabs the
//! corner nearest it and lets go. It is the mouse's band: the same entity, the same steps to
//! the bit, the same recording, the same clamps.

use crate::common;

use bevy::input::ButtonState;
use bevy::prelude::*;

use common::{Game, assert_replays, bits, keys_of};
use rubber_band_box::game::pointer::{Grip, KeyCursor, PointerSource};
use rubber_band_box::game::simulation::body_state;

/// What the keyboard does, a frame at a time: the keys held down, and whether B is tapped.
type Frame = (&'static [KeyCode], bool);

/// A pull: the cursor moved up and right, B, a pull left, a slow pull down, B, then rest.
const PULL: [(Frame, usize); 6] = [
    ((&[KeyCode::ArrowRight, KeyCode::ArrowUp], false), 12),
    ((&[], true), 1),
    ((&[KeyCode::ArrowLeft], false), 30),
    ((&[KeyCode::ShiftLeft, KeyCode::ArrowDown], false), 20),
    ((&[], true), 1),
    ((&[], false), 20),
];

/// Plays [`PULL`] by keyboard; returns the cursor on the window at each frame and whether B
/// was tapped in it, and the box's state after each frame.
fn pull_by_keyboard(game: &mut Game) -> (Vec<(Vec2, bool)>, Vec<[u64; 6]>) {
    let mut path = Vec::new();
    let mut states = Vec::new();
    let mut held: Vec<KeyCode> = Vec::new();
    for ((keys, tap), frames) in PULL {
        for key in held.drain(..) {
            game.key(key, ButtonState::Released);
        }
        for &key in keys {
            game.key(key, ButtonState::Pressed);
            held.push(key);
        }
        for frame in 0..frames {
            if tap && frame == 0 {
                game.tap_key(keys_of("band")[0]);
            }
            game.update(1);
            let cursor = game
                .world()
                .resource::<KeyCursor>()
                .screen
                .expect("a cursor");
            path.push((cursor, tap && frame == 0));
            let (linear, angular) = game.state();
            states.extend(bits(&[body_state(&linear, &angular)]));
        }
    }
    (path, states)
}

#[test]
fn the_keyboard_band_pulls_as_the_mouse_does_along_the_same_path() {
    let mut keyboard = Game::keeping_trajectory(std::time::Duration::from_millis(10), |_| {});
    keyboard.update(2);
    let (path, by_keys) = pull_by_keyboard(&mut keyboard);
    // It pulled: the box moved, and the cursor went where the arrows sent it.
    assert_ne!(by_keys.first(), by_keys.last(), "the box moved");
    let centre = keyboard.viewport().center();
    let grabbed = path.iter().find(|(_, tap)| *tap).unwrap().0;
    assert!(
        grabbed.x > centre.x && grabbed.y < centre.y,
        "{grabbed} from {centre}"
    );
    assert_eq!(keyboard.bands().len(), 0, "B again let go");
    assert_replays(&mut keyboard, "a pull by keyboard");

    // The mouse along the same path, pressed and released in the same frames.
    let mut mouse = Game::keeping_trajectory(std::time::Duration::from_millis(10), |_| {});
    mouse.update(2);
    let mut by_mouse = Vec::new();
    let mut holding = false;
    for (at, tap) in &path {
        mouse.cursor(Some(*at));
        if *tap {
            holding = !holding;
            mouse.mouse(if holding {
                ButtonState::Pressed
            } else {
                ButtonState::Released
            });
        }
        mouse.update(1);
        let (linear, angular) = mouse.state();
        by_mouse.extend(bits(&[body_state(&linear, &angular)]));
    }
    assert_eq!(by_keys, by_mouse, "the same states to the bit");
}

#[test]
fn the_band_key_grabs_and_lets_go_and_the_cursor_stays_on_the_scene() {
    let mut game = Game::stepping();
    game.update(2);
    assert_eq!(game.world().resource::<KeyCursor>().screen, None);
    game.tap_key(keys_of("band")[0]);
    game.update(1);
    assert_eq!(
        game.world().resource::<Grip>().0,
        Some(PointerSource::Keyboard)
    );
    let band = game.the_band();
    // Held far to the left for many seconds: the cursor stops at the viewport's edge, and the
    // anchor inside the camera's reach, as the mouse's does.
    game.key(KeyCode::ArrowLeft, ButtonState::Pressed);
    game.update(600);
    let cursor = *game.world().resource::<KeyCursor>();
    let viewport = game.viewport();
    let screen = cursor.screen.unwrap();
    assert_eq!(screen.x, viewport.min.x);
    assert!(cursor.shown);
    let anchor = game.the_band().ends.anchor;
    assert!(
        anchor.is_finite() && anchor.x < band.ends.anchor.x,
        "{anchor}"
    );
    game.key(KeyCode::ArrowLeft, ButtonState::Released);
    game.tap_key(keys_of("band")[0]);
    game.update(1);
    assert!(game.bands().is_empty());
    assert_eq!(game.world().resource::<Grip>().0, None);
    // The mouse pressing hides the keyboard's cursor and takes the band.
    game.tap_key(keys_of("band")[0]);
    game.update(1);
    game.cursor(Some(Vec2::new(600.0, 300.0)));
    game.mouse(ButtonState::Pressed);
    game.update(1);
    assert_eq!(
        game.world().resource::<Grip>().0,
        Some(PointerSource::Mouse)
    );
    assert!(!game.world().resource::<KeyCursor>().shown);
    assert_eq!(game.bands().len(), 1);
}
