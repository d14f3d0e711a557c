//! The keyboard controls in the headless game: each one's effect on the state and the clock.

use crate::common;

use common::*;
use rubber_band_box::game::input::controls::{CONTROLS, help_line};
use rubber_band_box::game::shared::{Overlay, Overlays, StatusMessage};

#[test]
fn pause_stops_the_fixed_steps_and_resume_continues() {
    let mut game = Game::stepping();
    game.update(5);
    assert_eq!(game.steps(), 5);
    // Bevy advances its clocks before it reads input, so the frame in which the key arrives
    // still runs its step; from the next frame on, none.
    game.tap_key(key(Action::TogglePause));
    game.update(1);
    assert_eq!(game.steps(), 6);
    game.update(10);
    assert_eq!(game.steps(), 6, "paused: no fixed step");
    game.tap_key(key(Action::TogglePause));
    game.update(1);
    game.update(3);
    assert_eq!(game.steps(), 9);
}

#[test]
fn a_single_step_while_paused_advances_exactly_one() {
    let mut game = Game::stepping();
    game.press_at(DVec2::new(200.0, 100.0));
    game.update(3);
    game.tap_key(key(Action::TogglePause));
    game.update(2);
    let before = (game.steps(), game.state());
    game.tap_key(key(Action::Step));
    game.update(1);
    assert_eq!(game.steps(), before.0 + 1);
    assert_ne!(game.state(), before.1);
    game.update(5);
    assert_eq!(game.steps(), before.0 + 1, "still paused");

    // Not paused, the key does nothing extra.
    game.tap_key(key(Action::TogglePause));
    game.update(1);
    let running = game.steps();
    game.tap_key(key(Action::Step));
    game.update(1);
    assert_eq!(game.steps(), running + 1);
}

#[test]
fn reset_restores_the_initial_state_and_removes_the_band() {
    let mut game = Game::stepping();
    let initial = game.state();
    game.press_at(DVec2::new(200.0, 100.0));
    game.update(30);
    assert_ne!(game.state(), initial);
    game.tap_key(key(Action::Reset));
    game.update(1);
    assert!(game.bands().is_empty());
    assert_eq!(
        game.state(),
        initial,
        "reset, then one step with no band: still at rest"
    );
    assert_eq!(game.world().resource::<Grip>().0, None);
}

#[test]
fn k_moves_by_factors_of_ten_within_its_range_and_the_next_step_uses_it() {
    let mut game = Game::stepping();
    game.tap_key(key(Action::Stiffer));
    game.update(1);
    assert_eq!(game.world().resource::<SceneParams>().stiffness, 200.0);
    for _ in 0..2 {
        game.tap_key(key(Action::Softer));
        game.update(1);
    }
    assert!((game.world().resource::<SceneParams>().stiffness - 2.0).abs() < 1e-12);
    for _ in 0..20 {
        game.tap_key(key(Action::Stiffer));
        game.update(1);
    }
    assert_eq!(game.world().resource::<SceneParams>().stiffness, 1e12);

    // The step after a change uses the new k: compare with the core.
    let mut game = Game::stepping();
    game.press_at(DVec2::new(200.0, 100.0));
    game.update(1);
    let anchor = game.the_band().ends.anchor;
    game.tap_key(key(Action::Stiffer));
    game.update(1);
    let mut stepper = Stepper::new(SceneParams::tutorial()).unwrap();
    stepper.grab(anchor);
    stepper.step(0.01);
    stepper.params.stiffness = 200.0;
    stepper.step(0.01);
    assert_eq!(game.state(), (stepper.state.linear, stepper.state.angular));
}

#[test]
fn the_time_scale_changes_the_fixed_steps_per_second_of_real_time() {
    let mut game = Game::stepping();
    // A change of scale applies from the frame after the key (the clocks advance first).
    game.tap_key(key(Action::Faster));
    game.update(2);
    let start = game.steps();
    game.update(10);
    assert_eq!(game.steps() - start, 20, "x2: two steps per 10 ms frame");

    for _ in 0..2 {
        game.tap_key(key(Action::Slower));
        game.update(1);
    }
    game.update(1);
    let start = game.steps();
    game.update(10);
    assert_eq!(game.steps() - start, 5, "x0.5: a step every other frame");
}

#[test]
fn the_step_rate_changes_the_fixed_step() {
    let mut game = Game::stepping();
    game.tap_key(key(Action::MoreSteps));
    game.update(1);
    assert_eq!(game.world().resource::<SceneParams>().step_rate_hz, 200.0);
    let step = game.world().resource::<Time<Fixed>>().timestep();
    assert_eq!(step, Duration::from_millis(5));
    let start = game.steps();
    game.update(10);
    assert_eq!(game.steps() - start, 20);
}

#[test]
fn page_down_halves_the_step_rate_down_to_its_lower_end() {
    let mut game = Game::stepping();
    let rates: Vec<f64> = (0..6)
        .map(|_| {
            game.tap_key(key(Action::FewerSteps));
            game.update(1);
            game.world().resource::<SceneParams>().step_rate_hz
        })
        .collect();
    assert_eq!(rates, [50.0, 25.0, 12.5, 8.0, 8.0, 8.0]);
    let step = game.world().resource::<Time<Fixed>>().timestep();
    assert_eq!(step, Duration::from_millis(125));
}

#[test]
fn vectors_and_trail_toggle() {
    let mut game = Game::stepping();
    assert_eq!(*game.world().resource::<Overlays>(), Overlays::default());
    game.tap_key(key(Action::Toggle(Overlay::Vectors)));
    game.tap_key(key(Action::Toggle(Overlay::Trail)));
    game.update(1);
    let overlays = *game.world().resource::<Overlays>();
    assert!(overlays.on(Overlay::Vectors) && overlays.on(Overlay::Trail));
    game.tap_key(key(Action::Toggle(Overlay::Vectors)));
    game.update(1);
    assert!(!game.world().resource::<Overlays>().on(Overlay::Vectors));
}

/// G shows and hides the ghosts, P the plot (and shows the ghosts, its points), H the HUD;
/// each toggles only its own overlay.
#[test]
fn ghosts_plot_and_hud_toggle() {
    let mut game = Game::stepping();
    let overlays = |game: &mut Game| *game.world().resource::<Overlays>();
    let after = |game: &mut Game, key: KeyCode| {
        game.tap_key(key);
        game.update(1);
        *game.world().resource::<Overlays>()
    };
    assert_eq!(overlays(&mut game), Overlays::default());
    let shown = after(&mut game, KeyCode::KeyG);
    let mut ghosts = Overlays::default();
    ghosts.set(Overlay::Ghosts, true);
    assert_eq!(shown, ghosts);
    assert_eq!(after(&mut game, KeyCode::KeyG), Overlays::default());
    // The plot brings the ghosts; hiding it leaves them.
    let dock_hidden = |game: &mut Game| {
        game.world()
            .resource::<rubber_band_box::game::shared::DockHidden>()
            .0
    };
    let plotted = after(&mut game, KeyCode::KeyP);
    assert!(
        plotted.on(Overlay::Plot) && plotted.on(Overlay::Ghosts),
        "{plotted:?}"
    );
    assert!(!dock_hidden(&mut game));
    let unplotted = after(&mut game, KeyCode::KeyP);
    assert!(
        !unplotted.on(Overlay::Plot) && unplotted.on(Overlay::Ghosts),
        "{unplotted:?}"
    );
    // H hides the dock, which is not an overlay: the overlays stay as they were.
    let hidden = after(&mut game, KeyCode::KeyH);
    assert!(dock_hidden(&mut game));
    assert_eq!(hidden, unplotted);
    after(&mut game, KeyCode::KeyH);
    assert!(!dock_hidden(&mut game));
}

/// The keys are listed once (`CONTROLS`): README's table and the help line are both written
/// from that list, so neither can name a key the game does not read or miss one.
#[test]
fn readme_and_the_help_line_name_every_control_as_the_list_does() {
    let readme = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/README.md"))
        .expect("README.md");
    let help = help_line();
    let mut control_rows = Vec::new();
    for control in CONTROLS {
        let keys: Vec<String> = control
            .label
            .split(' ')
            .map(|key| format!("`{key}`"))
            .collect();
        let row = format!("| {} | {} |", keys.join(" / "), control.effect);
        assert!(readme.contains(&row), "README lacks the row\n{row}");
        control_rows.push(row);
        let item = format!("{}: {}", control.label, control.name).replace(' ', "\u{a0}");
        assert!(help.contains(&item), "{help}");
    }
    // And the other way: every row of README's table is a pointer's or a control's, so a
    // stale row (a key the game no longer reads) or a duplicate fails.
    let mut lines = readme
        .lines()
        .skip_while(|line| *line != "| input | effect |")
        .skip(1);
    assert_eq!(lines.next(), Some("|---|---|"), "README's keys table");
    let table: Vec<&str> = lines.take_while(|line| !line.trim().is_empty()).collect();
    let pointer = [
        "| left mouse button, held |",
        "| release |",
        "| one finger (touch screen) |",
    ];
    for line in &table {
        assert!(
            pointer.iter().any(|row| line.starts_with(row))
                || control_rows.iter().any(|row| row == line),
            "README's row is neither a pointer's nor a control's\n{line}"
        );
    }
    assert_eq!(table.len(), pointer.len() + CONTROLS.len(), "{table:#?}");
    let mut game = Game::stepping();
    game.update(1);
    // The Controls card's own line of keys, dim as a caption.
    let world = game.world();
    let (_, keys, shade) = world
        .query::<(&Name, &Text, &TextColor)>()
        .iter(world)
        .find(|(name, ..)| name.as_str() == "Keys")
        .expect("the Controls card has its line of keys");
    assert_eq!(keys.0, help);
    assert_eq!(shade.0, rubber_band_box::game::theme::colour::DIM);
}

#[test]
fn k_and_the_time_scale_stop_at_their_lower_ends_and_climb_back() {
    let mut game = Game::stepping();
    for _ in 0..8 {
        game.tap_key(key(Action::Softer));
        game.update(1);
    }
    assert_eq!(game.world().resource::<SceneParams>().stiffness, 1e-2);
    game.tap_key(key(Action::Stiffer));
    game.update(1);
    let k = game.world().resource::<SceneParams>().stiffness;
    assert!((k - 0.1).abs() < 1e-15, "{k}");

    let speed = |game: &mut Game| {
        game.world()
            .resource::<Time<Virtual>>()
            .relative_speed_f64()
    };
    for _ in 0..6 {
        game.tap_key(key(Action::Slower));
        game.update(1);
    }
    assert_eq!(speed(&mut game), 1.0 / 16.0);
    for _ in 0..10 {
        game.tap_key(key(Action::Faster));
        game.update(1);
    }
    assert_eq!(speed(&mut game), 16.0);
}

/// O on the desktop: a replay is opened by dropping it on the window, and the status line
/// says so (in the browser O opens a file chooser; the browser test clicks it). Dropping one
/// is `tests/replay.rs`'s.
#[test]
fn the_open_key_says_how_to_open_a_replay() {
    let mut game = Game::stepping();
    assert_eq!(game.world().resource::<StatusMessage>().0, None);
    game.tap_key(key(Action::Open));
    game.update(1);
    assert_eq!(
        game.world().resource::<StatusMessage>().0.as_deref(),
        Some("drop a replay file on the window to play it")
    );
}

/// The keys are one list (`CONTROLS`, which the help line, README and the link's
/// docs read), so a key bound twice shows there: none is, and every control has a key.
#[test]
fn no_key_is_bound_to_two_controls() {
    let mut seen = std::collections::HashMap::new();
    for control in &CONTROLS {
        assert!(!control.keys.is_empty(), "{} has no key", control.name);
        for key in control.keys {
            if let Some(before) = seen.insert(*key, control.name) {
                panic!("{key:?} is bound to {before} and to {}", control.name);
            }
        }
    }
}
