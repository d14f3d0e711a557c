//! Keyboard focus (docs/controls.md): Tab and Shift+Tab visit every button and slider shown,
//! and only those, in the UI's reading order; a focused button takes Space and Enter and a
//! focused slider the arrows, and the game's key of the same name does not fire; Escape gives
//! focus back to the scene, where every key works as before.

use crate::common;

use bevy::input::ButtonState;
use bevy::input_focus::{InputFocus, InputFocusVisible};
use bevy::prelude::*;
use bevy::ui_widgets::{Button, Slider};

use common::{Game, key};
use rubber_band_box::game::input::controls::{Action, Parameter};
use rubber_band_box::game::input::panel::PanelButton;
use rubber_band_box::physics::{Integrator, SceneParams};

fn focused(game: &mut Game) -> Option<Entity> {
    game.world().resource::<InputFocus>().get()
}

fn paused(game: &mut Game) -> bool {
    game.world().resource::<Time<Virtual>>().is_paused()
}

/// Every button and slider with no hidden node above it.
fn shown_controls(game: &mut Game) -> Vec<Entity> {
    let world = game.world();
    let mut controls = world.query_filtered::<Entity, Or<(With<Button>, With<Slider>)>>();
    let controls: Vec<Entity> = controls.iter(world).collect();
    controls
        .into_iter()
        .filter(|&entity| {
            let mut at = Some(entity);
            while let Some(node) = at {
                if world
                    .get::<Node>(node)
                    .is_some_and(|n| n.display == Display::None)
                {
                    return false;
                }
                at = world.get::<ChildOf>(node).map(ChildOf::parent);
            }
            true
        })
        .collect()
}

/// Gives `entity` focus as the keyboard does (its ring shown).
fn focus_on(game: &mut Game, entity: Entity) {
    game.world()
        .resource_mut::<InputFocus>()
        .set(entity, bevy::input_focus::FocusCause::Navigated);
    game.world().resource_mut::<InputFocusVisible>().0 = true;
    game.update(1);
}

#[test]
fn tab_visits_every_shown_control_once_in_order_and_shift_tab_goes_back() {
    let mut game = Game::stepping();
    game.update(3);
    // The Controls card open: its buttons and sliders are shown.
    let controls_title = {
        let world = game.world();
        let mut titles = world.query::<(Entity, &rubber_band_box::game::layout::CardButton)>();
        titles
            .iter(world)
            .find(|(_, t)| t.0 == rubber_band_box::game::layout::Card::CONTROLS)
            .map(|(e, _)| e)
            .expect("the Controls card's title")
    };
    focus_on(&mut game, controls_title);
    game.tap_key(KeyCode::Enter);
    game.update(2);
    game.world().resource_mut::<InputFocus>().clear();
    game.update(1);
    let shown = shown_controls(&mut game);
    assert!(shown.len() > 30, "{} controls shown", shown.len());
    let mut visited = Vec::new();
    for _ in 0..shown.len() {
        game.tap_key(KeyCode::Tab);
        game.update(1);
        visited.push(focused(&mut game).expect("Tab gives focus"));
    }
    let mut sorted = visited.clone();
    sorted.sort();
    sorted.dedup();
    assert_eq!(sorted.len(), shown.len(), "each shown control once");
    assert!(
        visited.iter().all(|v| shown.contains(v)),
        "a hidden control got focus"
    );
    assert!(
        game.world().resource::<InputFocusVisible>().0,
        "focus by key shows its ring"
    );
    // One more Tab goes round to the first; Shift+Tab back to the last.
    game.tap_key(KeyCode::Tab);
    game.update(1);
    assert_eq!(focused(&mut game), Some(visited[0]));
    game.key(KeyCode::ShiftLeft, ButtonState::Pressed);
    game.update(1);
    game.tap_key(KeyCode::Tab);
    game.update(1);
    game.key(KeyCode::ShiftLeft, ButtonState::Released);
    game.update(1);
    assert_eq!(focused(&mut game), visited.last().copied());
    // The game's keys did not fire: nothing paused.
    assert!(!paused(&mut game));
}

#[test]
fn space_presses_a_focused_button_and_does_not_pause() {
    let mut game = Game::stepping();
    game.update(3);
    let rk4 = game.button(PanelButton::Send(Action::Integrator(Integrator::Rk4)));
    focus_on(&mut game, rk4);
    game.tap_key(key(Action::TogglePause));
    game.update(2);
    assert_eq!(*game.world().resource::<Integrator>(), Integrator::Rk4);
    assert!(!paused(&mut game), "Space went to the button, not to pause");
    // Escape gives focus back to the scene, where Space pauses again.
    game.tap_key(KeyCode::Escape);
    game.update(1);
    assert_eq!(focused(&mut game), None);
    game.tap_key(key(Action::TogglePause));
    game.update(2);
    assert!(paused(&mut game));
}

#[test]
fn the_arrows_move_a_focused_slider_and_nothing_else() {
    let mut game = Game::stepping();
    game.update(3);
    let slider = game.slider(Parameter::Mass);
    let before = *game.world().resource::<SceneParams>();
    focus_on(&mut game, slider);
    game.tap_key(KeyCode::ArrowRight);
    game.update(2);
    let after = *game.world().resource::<SceneParams>();
    assert!(
        after.mass > before.mass,
        "{} -> {}",
        before.mass,
        after.mass
    );
    assert_eq!(after.stiffness, before.stiffness);
    assert!(!paused(&mut game));
}

/// A click on a control keeps no keyboard focus: Space after a click on `rk4` pauses the game.
#[test]
fn a_click_keeps_no_focus_and_space_still_pauses() {
    let mut game = Game::stepping();
    game.update(3);
    let rk4 = game.button(PanelButton::Send(Action::Integrator(Integrator::Rk4)));
    common::click(&mut game, rk4, bevy::picking::pointer::PointerId::Mouse);
    game.update(2);
    assert_eq!(*game.world().resource::<Integrator>(), Integrator::Rk4);
    assert_eq!(focused(&mut game), None);
    game.tap_key(key(Action::TogglePause));
    game.update(2);
    assert!(paused(&mut game), "Space after a click pauses");
}

fn position(game: &mut Game, slider: Entity) -> f32 {
    game.world()
        .get::<bevy::ui_widgets::SliderValue>(slider)
        .expect("a slider's value")
        .0
}

/// Each key a focused slider takes moves it as on the web: ← → ↑ ↓ a step, Shift a tenth of
/// one, PageUp and PageDown ten, Home and End to its ends; the Page keys no longer change the
/// step rate, and the slider's accessible value is the value with its unit.
#[test]
fn a_focused_slider_moves_by_every_key_and_the_game_keeps_its_own() {
    let mut game = Game::stepping();
    game.update(3);
    let size = game.slider(Parameter::Size);
    focus_on(&mut game, size);
    let rate = game.world().resource::<SceneParams>().step_rate_hz;
    // The size's slider: log10 of the side, a step 0.05 of a decade. The value in force is
    // rounded to three figures, so a position lies within 0.003 of a decade of the exact one.
    let step = 0.05;
    let press = |game: &mut Game, keys: &[KeyCode]| {
        for key in keys {
            game.key(*key, ButtonState::Pressed);
        }
        game.update(1);
        for key in keys.iter().rev() {
            game.key(*key, ButtonState::Released);
        }
        game.update(2);
    };
    for (keys, moved) in [
        (&[KeyCode::ArrowRight][..], step),
        (&[KeyCode::ArrowLeft], -step),
        (&[KeyCode::ArrowUp], step),
        (&[KeyCode::ArrowDown], -step),
        (&[KeyCode::ShiftLeft, KeyCode::ArrowRight], step / 10.0),
        (&[KeyCode::ShiftLeft, KeyCode::ArrowDown], -step / 10.0),
        (&[KeyCode::PageUp], step * 10.0),
        (&[KeyCode::PageDown], -step * 10.0),
    ] {
        let before = position(&mut game, size);
        press(&mut game, keys);
        let after = position(&mut game, size);
        assert!(
            ((after - before) - moved).abs() < 0.003,
            "{keys:?}: {before} -> {after}, not by {moved}"
        );
    }
    // Two presses in one frame are two steps.
    let before = position(&mut game, size);
    game.tap_key(KeyCode::ArrowRight);
    game.tap_key(KeyCode::ArrowRight);
    game.update(3);
    let after = position(&mut game, size);
    assert!(
        ((after - before) - 2.0 * step).abs() < 0.003,
        "two presses in a frame: {before} -> {after}"
    );
    press(&mut game, &[KeyCode::End]);
    let params = *game.world().resource::<SceneParams>();
    assert_eq!(params.size.x, rubber_band_box::physics::SIZE_RANGE.high);
    let said = game
        .world()
        .get::<bevy::a11y::AccessibilityNode>(size)
        .and_then(|node| node.value().map(str::to_owned));
    assert_eq!(said.as_deref(), Some("640 px"));
    press(&mut game, &[KeyCode::Home]);
    let params = *game.world().resource::<SceneParams>();
    assert_eq!(params.size.x, rubber_band_box::physics::SIZE_RANGE.low);
    assert_eq!(params.step_rate_hz, rate, "the Page keys were the slider's");
    assert!(!paused(&mut game));
}
