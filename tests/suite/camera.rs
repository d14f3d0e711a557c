//! The hand and the camera together: the real pointer system and the real camera systems in one
//! headless game laid out by Bevy's UI (no renderer), at a desktop's 960 x 720 with the dock
//! and a phone's 390 x 844 with the bottom sheet. A band held by the mouse over the dock, over
//! the status line, at the window's corners, off the window and back, near the viewport's
//! edge; by a finger dragged onto the bottom sheet, with a second finger; with the window
//! resized, the dock hidden and shown and `F` pressed while holding. At every frame the view
//! is within its bound, every corner of the box lies in the viewport, and the box is drawn at
//! least half as large as at rest; three seconds after letting go the view is home.
//!
//! The box's place on the window is read from the scene camera's transform and projection
//! (as `screen::view` placed them) against the body's state.

use crate::common;

use common::*;
use rubber_band_box::game::camera::{CameraFrame, MAX_WIDEN};
use rubber_band_box::game::layout::{Card, Cards, SceneViewport};
use rubber_band_box::game::pointer::PointerAction;
use rubber_band_box::game::shared::DockHidden;

const DESKTOP: UVec2 = UVec2::new(960, 720);
const PHONE: UVec2 = UVec2::new(390, 844);
/// The tutorial box's side, in world units.
const SIDE: f32 = 60.0;

/// A laid-out game at `size`, a few frames on so that the layout has placed the viewport.
fn game_at(size: UVec2) -> Game {
    let mut game = Game::laid_out();
    game.resize(size);
    game.update(4);
    game
}

fn viewport(game: &mut Game) -> Rect {
    game.world().resource::<SceneViewport>().0.unwrap()
}

/// World units a logical pixel at home: the 640 x 480 screen and its 4% margin fitted.
fn home_scale(viewport: Rect) -> f32 {
    (640.0 * 1.04 / viewport.width()).max(480.0 * 1.04 / viewport.height())
}

/// Checks one frame and returns how many times home's width the view shows.
///
/// The view within its bound, every corner of the box in the viewport, the box at least half
/// its size at home on the window.
fn check(game: &mut Game, name: &str) -> f32 {
    check_sized(game, name, true)
}

/// [`check`], the box's size on the window checked only if `sized`.
///
/// A resize from a phone's tall frame to a desktop's wide one leaves the box out of the new
/// frame: the view rightly widens past twice home to hold it while it comes back. A scene's
/// scripted pull far past the frame does too.
fn check_sized(game: &mut Game, name: &str, sized: bool) -> f32 {
    let viewport = viewport(game);
    let home = home_scale(viewport);
    let shown = game
        .world()
        .resource::<CameraFrame>()
        .shown
        .unwrap_or_else(|| panic!("{name}: no view"));
    let widened = shown.world_per_pixel / home;
    assert!(
        widened <= MAX_WIDEN * 1.0001,
        "{name}: the view {widened} times home, past its bound"
    );
    let corners: Vec<Vec2> = game
        .drawn_corners()
        .into_iter()
        .map(|corner| game.on_window(corner))
        .collect();
    for at in &corners {
        assert!(
            viewport.inflate(0.5).contains(*at),
            "{name}: a corner at {at}, out of the viewport {viewport:?}"
        );
    }
    let side = corners[0].distance(corners[1]);
    assert!(
        !sized || side >= 0.5 * SIDE / home,
        "{name}: the box {side} px across, at rest {}",
        SIDE / home
    );
    widened
}

/// Runs `frames` frames (10 ms each), checking each; returns the widest view seen.
fn run(game: &mut Game, frames: usize, name: &str) -> f32 {
    (0..frames)
        .map(|frame| {
            game.update(1);
            check(game, &format!("{name}, frame {frame}"))
        })
        .fold(0.0, f32::max)
}

/// Checks that the view is home: the tutorial's screen fitted, centred on the world's origin.
fn assert_home(game: &mut Game, name: &str) {
    let home = home_scale(viewport(game));
    let shown = game.world().resource::<CameraFrame>().shown.unwrap();
    assert!(
        (shown.world_per_pixel / home - 1.0).abs() < 1e-3 && shown.centre.length() < 0.5,
        "{name}: the view {shown:?} is not home ({home} world units a pixel)"
    );
}

/// The box's centre on the window.
fn box_on_window(game: &mut Game) -> Vec2 {
    let corners = game.drawn_corners();
    let centre = corners.iter().sum::<Vec2>() / 4.0;
    game.on_window(centre)
}

/// Moves the held mouse from where it is to `to` in 30 frames, checking each.
fn drag_mouse(game: &mut Game, from: Vec2, to: Vec2, name: &str) -> f32 {
    (1..=30)
        .map(|frame| {
            game.cursor(Some(from.lerp(to, frame as f32 / 30.0)));
            game.update(1);
            check(game, &format!("{name}, dragged, frame {frame}"))
        })
        .fold(0.0, f32::max)
}

/// Runs frames, checking each, until the box is all but at rest (at most 40 s); returns the
/// widest view seen.
///
/// The tutorial's band swings the box a long while (its damping ratio is 0.15): a box let go
/// while it swings coasts on, and the view holds it wherever it stops. Under 5 px/s it coasts
/// at most 5 px more (its velocity decays at b/m = 1 /s): the swing is over, and waiting for
/// 0.5 px/s would take 4.6 s more of every pull.
fn settle(game: &mut Game, name: &str) -> f32 {
    let mut widest = 0.0f32;
    for second in 0..40 {
        widest = widest.max(run(game, 100, &format!("{name}, second {second}")));
        let (linear, angular) = game.state();
        if linear.velocity.length() < 5.0 && angular.angular_velocity.abs() < 0.1 {
            return widest;
        }
    }
    panic!("{name}: the box never came to rest");
}

/// Presses the mouse on the box, `offset` from its centre, for a frame; returns where.
fn press_the_box(game: &mut Game, offset: Vec2, name: &str) -> Vec2 {
    let start = box_on_window(game) + offset;
    game.cursor(Some(start));
    game.mouse(ButtonState::Pressed);
    game.update(1);
    assert_eq!(game.bands().len(), 1, "{name}: the press grabs the box");
    start
}

/// Releases the mouse and runs three seconds, checking each frame; the view then home.
fn let_go_and_come_home(game: &mut Game, name: &str) -> f32 {
    game.mouse(ButtonState::Released);
    let widest = run(game, 300, &format!("{name}, let go"));
    assert!(game.bands().is_empty());
    assert_home(game, name);
    widest
}

/// A press near the box, a drag to `to`, held there until the box is at rest, a release,
/// three seconds: checked at every frame, home at the end. Returns the widest view seen.
fn pull_to(game: &mut Game, to: Vec2, name: &str) -> f32 {
    let start = press_the_box(game, Vec2::new(8.0, -8.0), name);
    let widest = drag_mouse(game, start, to, name).max(settle(game, &format!("{name}, held")));
    widest.max(let_go_and_come_home(game, name))
}

/// Where a player drags on a desktop: over the dock, over the status line and the hint line,
/// the window's four corners, near the viewport's corner inside it.
fn desktop_targets(game: &mut Game) -> Vec<(String, Vec2)> {
    let viewport = viewport(game);
    let window = DESKTOP.as_vec2();
    assert!(
        viewport.max.x < 900.0,
        "the dock lies right of {viewport:?}"
    );
    let mut targets = vec![
        ("over the dock".to_owned(), Vec2::new(940.0, 140.0)),
        (
            "over the status line".to_owned(),
            Vec2::new(viewport.center().x, viewport.min.y / 2.0),
        ),
        (
            "over the hint line".to_owned(),
            Vec2::new(viewport.center().x, (viewport.max.y + window.y) / 2.0),
        ),
        (
            "20 px inside the viewport's lower left".to_owned(),
            Vec2::new(viewport.min.x + 20.0, viewport.max.y - 20.0),
        ),
    ];
    for corner in [
        Vec2::new(0.0, 0.0),
        Vec2::new(window.x - 1.0, 0.0),
        Vec2::new(window.x - 1.0, window.y - 1.0),
        Vec2::new(0.0, window.y - 1.0),
    ] {
        targets.push((format!("the window's corner {corner}"), corner));
    }
    targets
}

#[test]
fn a_mouse_held_anywhere_keeps_the_box_in_view_and_the_view_comes_home() {
    let mut game = game_at(DESKTOP);
    // The lab on: ghosts, plot, vectors, trail.
    for key in [KeyCode::KeyG, KeyCode::KeyP, KeyCode::KeyV, KeyCode::KeyT] {
        game.tap_key(key);
    }
    game.update(2);
    assert_home(&mut game, "at rest");
    let mut widest = Vec::new();
    for (name, to) in desktop_targets(&mut game) {
        widest.push((pull_to(&mut game, to, &name), name));
    }
    // The widest view any of them needed, for the record: well inside the bound.
    let most = widest.iter().map(|(w, _)| *w).fold(0.0, f32::max);
    assert!(most < MAX_WIDEN, "{widest:?}");
}

#[test]
fn a_mouse_that_leaves_the_window_while_held_leaves_the_box_in_view() {
    let mut game = game_at(DESKTOP);
    let start = press_the_box(&mut game, Vec2::ZERO, "at the start");
    let edge = Vec2::new(DESKTOP.x as f32 - 1.0, 300.0);
    drag_mouse(&mut game, start, edge, "to the window's edge");
    // Off the window: no position at all, for three seconds.
    game.cursor(None);
    run(&mut game, 300, "off the window");
    // Back over the scene, then let go.
    let back = viewport(&mut game).center() + Vec2::new(-60.0, 40.0);
    game.cursor(Some(back));
    run(&mut game, 100, "back on the scene");
    let anchor = game.the_band().ends.anchor.as_vec2();
    assert!(
        game.on_window(anchor).distance(back) < 0.5,
        "the anchor follows the cursor again: {anchor}"
    );
    settle(&mut game, "back on the scene");
    let_go_and_come_home(&mut game, "back on the scene");
}

#[test]
fn resizing_hiding_the_dock_and_framing_while_holding_keep_the_box_in_view() {
    let mut game = game_at(DESKTOP);
    let start = press_the_box(&mut game, Vec2::ZERO, "at the start");
    drag_mouse(&mut game, start, Vec2::new(940.0, 140.0), "to the dock");
    run(&mut game, 100, "held over the dock");
    // The dock hidden (H): the scene takes the window, the pointer now over it.
    game.tap_key(KeyCode::KeyH);
    run(&mut game, 150, "the dock hidden");
    assert!(game.world().resource::<DockHidden>().0);
    game.tap_key(KeyCode::KeyH);
    run(&mut game, 150, "the dock shown");
    // The window resized under the held band, larger and then a phone's.
    for size in [UVec2::new(1280, 800), PHONE, DESKTOP] {
        game.resize(size);
        game.cursor(Some(size.as_vec2() - Vec2::ONE));
        for frame in 0..150 {
            game.update(1);
            check_sized(
                &mut game,
                &format!("resized to {size}, frame {frame}"),
                false,
            );
        }
    }
    // F: home at once, the box still in it.
    game.tap_key(KeyCode::KeyF);
    run(&mut game, 150, "framed");
    settle(&mut game, "held after framing");
    let_go_and_come_home(&mut game, "framed");
}

#[test]
fn a_finger_dragged_onto_the_sheet_with_a_second_finger_keeps_the_box_in_view() {
    let mut game = game_at(PHONE);
    // The energy card open: the sheet takes the lower part of the window.
    let mut cards = Cards::default();
    cards.set(Card::ENERGY, true);
    *game.world().resource_mut::<Cards>() = cards;
    game.update(2);
    let viewport = viewport(&mut game);
    assert!(
        viewport.max.y < 700.0,
        "the sheet lies below the scene {viewport:?}"
    );
    let start = box_on_window(&mut game);
    game.touch_screen(1, TouchPhase::Started, start);
    game.update(1);
    assert_eq!(game.bands().len(), 1, "the finger grabs the box");
    let sheet = Vec2::new(300.0, (viewport.max.y + PHONE.y as f32) / 2.0);
    for frame in 1..=30 {
        let at = start.lerp(sheet, frame as f32 / 30.0);
        game.touch_screen(1, TouchPhase::Moved, at);
        game.update(1);
        check(&mut game, &format!("dragged to the sheet, frame {frame}"));
    }
    run(&mut game, 200, "held on the sheet");
    // A second finger lands on the scene and spreads away: no pinch while the first holds.
    let zoom_before = game.world().resource::<CameraFrame>().zoom;
    game.touch_screen(2, TouchPhase::Started, viewport.center());
    game.update(1);
    for frame in 1..=30 {
        let at = viewport.center() + Vec2::new(3.0, -2.0) * frame as f32;
        game.touch_screen(2, TouchPhase::Moved, at);
        game.touch_screen(1, TouchPhase::Moved, sheet);
        game.update(1);
        check(&mut game, &format!("a second finger, frame {frame}"));
    }
    assert_eq!(game.world().resource::<CameraFrame>().zoom, zoom_before);
    game.touch_screen(2, TouchPhase::Ended, viewport.center());
    run(&mut game, 100, "the second finger lifted");
    assert_eq!(game.bands().len(), 1, "the first finger still holds");
    settle(&mut game, "held on the sheet");
    game.touch_screen(1, TouchPhase::Ended, sheet);
    run(&mut game, 300, "lifted");
    assert!(game.bands().is_empty());
    assert_home(&mut game, "lifted");
}

/// The tutorial's scripted pull keeps the box in view too (it holds the band at world points
/// of its own, not through the pointer), and a hand's band set far past the screen by a
/// message: the view widens for the box, within its bound.
#[test]
fn the_tutorials_pull_and_a_scripted_far_pull_keep_the_box_in_view() {
    for size in [DESKTOP, PHONE] {
        let mut game = game_at(size);
        game.tap_key(KeyCode::KeyP);
        game.update(3);
        game.tap_key(KeyCode::Digit1);
        for frame in 0..500 {
            game.update(1);
            let name = format!("{size}, the tutorial's pull, frame {frame}");
            check_sized(&mut game, &name, false);
        }
        game.tap_key(KeyCode::KeyR);
        game.update(2);
        game.world()
            .write_message(PointerAction::Press(DVec2::new(20.0, 20.0)));
        for frame in 0..300 {
            let t = (frame as f64 / 100.0).min(1.0);
            game.world()
                .write_message(PointerAction::Move(DVec2::new(500.0, 380.0) * t));
            game.update(1);
            check_sized(
                &mut game,
                &format!("{size}, a far pull, frame {frame}"),
                false,
            );
        }
    }
}

/// Learn mode frames each chapter's picture: the box drawn at least 1.8 times as large as at
/// home and across at least a sixth of the viewport's shorter side, at a desktop and a phone; for
/// three seconds of the chapter's scene (its scripted pull), every corner of the box, and of
/// the centre twin where the chapter has one, lies in the viewport. A pull to the window's
/// corner, held until the box rests, keeps it in view as out of learn mode. Leaving comes home.
#[test]
fn learn_mode_frames_each_chapter_close_and_keeps_the_box_and_its_twin_in_view() {
    use rubber_band_box::game::learn::Learn;
    use rubber_band_box::game::learn::chapters::CHAPTERS;
    use rubber_band_box::game::learn::twin::TWIN_OFFSET;
    for size in [DESKTOP, PHONE] {
        let mut game = game_at(size);
        for (index, chapter) in CHAPTERS.iter().enumerate() {
            game.world().trigger(Learn::Chapter(index));
            game.update(2);
            let viewport = viewport(&mut game);
            let name = format!("{size}, chapter {}", index + 1);
            let corners: Vec<Vec2> = game.drawn_corners();
            let side = game
                .on_window(corners[0])
                .distance(game.on_window(corners[1]));
            let at_home = SIDE / home_scale(viewport);
            let share = side / viewport.size().min_element();

            assert!(
                side >= 1.8 * at_home,
                "{name}: the box {side} px, at home {at_home}"
            );
            assert!(
                share >= 1.0 / 6.0,
                "{name}: the box {share} of the viewport"
            );
            for frame in 0..300 {
                game.update(1);
                let mut drawn = game.drawn_corners();
                if chapter.centre_twin {
                    let twin: Vec<Vec2> =
                        drawn.iter().map(|c| *c + TWIN_OFFSET.as_vec2()).collect();
                    drawn.extend(twin);
                }
                for corner in drawn {
                    let at = game.on_window(corner);
                    assert!(
                        viewport.inflate(0.5).contains(at),
                        "{name}, frame {frame}: a corner at {at}, out of {viewport:?}"
                    );
                }
            }
        }
        let start = press_the_box(&mut game, Vec2::new(8.0, -8.0), "learn mode");
        drag_mouse(
            &mut game,
            start,
            Vec2::ZERO,
            "learn mode, to the window's corner",
        );
        settle(&mut game, "learn mode, held at the window's corner");
        game.mouse(ButtonState::Released);
        run(&mut game, 300, "learn mode, let go");
        game.world().trigger(Learn::Toggle);
        game.update(300);
        assert_home(&mut game, &format!("{size}, left learn mode"));
    }
}

/// The wheel's zoom for the keyboard: Z zooms in about the viewport's centre (the world there
/// stays there, the box drawn larger), X zooms out, F goes home.
#[test]
fn the_zoom_keys_zoom_about_the_centre_and_f_goes_home() {
    let mut game = game_at(DESKTOP);
    let frame = |game: &mut Game| *game.world().resource::<CameraFrame>();
    let side = |game: &mut Game| {
        let corners = game.drawn_corners();
        let (a, b) = (game.on_window(corners[0]), game.on_window(corners[1]));
        a.distance(b)
    };
    let before = side(&mut game);
    game.tap_key(keys_of("zoom")[0]);
    game.update(30);
    let zoomed = frame(&mut game);
    assert!(zoomed.zoom < 1.0, "{zoomed:?}");
    let larger = side(&mut game);
    assert!(larger > before * 1.2, "{before} -> {larger} px");
    game.tap_key(keys_of("zoom")[1]);
    game.tap_key(keys_of("zoom")[1]);
    game.update(30);
    assert!(frame(&mut game).zoom > 1.0);
    game.tap_key(KeyCode::KeyF);
    game.update(30);
    assert_eq!(frame(&mut game).zoom, 1.0);
    assert_eq!(frame(&mut game).pan, Vec2::ZERO);
}
