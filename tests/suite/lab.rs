//! The game as a lab: the core's named scenes played in the game by number keys, and the
//! ghosts (every integrator and a reference beside the live box, under the same band).

use crate::common;

use common::*;
use rubber_band_box::game::ghosts::{GhostKind, Ghosts};
use rubber_band_box::game::replays::playback::{Playback, PlaybackEnd};
use rubber_band_box::game::shared::SceneName;
use rubber_band_box::physics::{BodyState, Integrator, Scene};

fn lab() -> Game {
    Game::keeping_trajectory(Duration::from_secs_f64(1.0 / 60.0), |_| {})
}

/// A hand: a drag with circles, a stiffer band, another integrator, a release, a reset.
fn play_a_hand(game: &mut Game, ghosts_on_at: Option<usize>) {
    for frame in 0..240 {
        if Some(frame) == ghosts_on_at {
            game.tap_key(key(Action::Toggle(Overlay::Ghosts)));
        }
        match frame {
            10 => game.press_at(DVec2::new(180.0, 90.0)),
            60 => game.tap_key(key(Action::Stiffer)),
            100 => game.tap_key(key(Action::NextIntegrator)),
            150 => game.mouse(ButtonState::Released),
            200 => game.tap_key(key(Action::Reset)),
            210 => game.press_at(DVec2::new(-150.0, 40.0)),
            _ => {}
        }
        if (10..150).contains(&frame) {
            let t = frame as f64 * 0.05;
            game.cursor(Some(world_to_screen(DVec2::new(
                180.0 * t.cos(),
                120.0 * t.sin(),
            ))));
        }
        game.update(1);
    }
}

#[test]
fn ghosts_never_change_what_the_live_box_does() {
    let mut without = lab();
    play_a_hand(&mut without, None);
    let mut with = lab();
    play_a_hand(&mut with, Some(5));
    assert!(!with.world().resource::<Ghosts>().ghosts.is_empty());
    let (a, b) = (
        bits(&without.world().resource::<Trajectory>().0),
        bits(&with.world().resource::<Trajectory>().0),
    );
    assert!(a.len() > 300);
    assert_eq!(a, b);
}

/// Every integrator and the reference follow the live band: the ghost of the live box's own
/// integrator (`auto`) is the live box to the bit, the reference agrees with it closely, and
/// the methods rank by their order.
#[test]
fn every_ghost_steps_under_the_live_band() {
    let mut game = lab();
    game.tap_key(key(Action::Toggle(Overlay::Ghosts)));
    game.update(1);
    game.press_at(DVec2::new(180.0, 90.0));
    game.update(30);
    game.cursor(Some(world_to_screen(DVec2::new(-120.0, 100.0))));
    game.update(60);
    let band = game.the_band().ends;
    let (linear, angular) = game.state();
    let live = BodyState { linear, angular };
    let ghosts = game.world().resource::<Ghosts>();
    let kinds: Vec<GhostKind> = ghosts.ghosts.iter().map(|g| g.kind).collect();
    let expected: Vec<GhostKind> = Integrator::ALL
        .map(GhostKind::Method)
        .into_iter()
        .chain([GhostKind::Reference])
        .collect();
    assert_eq!(kinds, expected);
    for ghost in &ghosts.ghosts {
        assert_eq!(ghost.stepper.band, Some(band), "{}", ghost.kind.name());
        assert_eq!(ghost.diverged_at, None, "{}", ghost.kind.name());
        assert_eq!(ghost.steps, ghosts.ghosts[0].steps);
    }
    let of = |integrator| {
        ghosts
            .ghosts
            .iter()
            .find(|g| g.kind == GhostKind::Method(integrator))
            .unwrap()
    };
    assert_eq!(of(Integrator::Auto).stepper.state, live);
    let distance = |integrator| ghosts.distance_from_reference(of(integrator)).unwrap();
    assert!(
        distance(Integrator::Auto) < 1e-6,
        "{}",
        distance(Integrator::Auto)
    );
    assert!(distance(Integrator::Rk4) < distance(Integrator::Verlet));
    assert!(distance(Integrator::Verlet) < distance(Integrator::Euler));
    assert!(distance(Integrator::Euler) > 1e-3);
    // The books: auto's residual is tiny, explicit Euler's is not.
    assert!(of(Integrator::Auto).residual().abs() < 1e-3 * of(Integrator::Euler).residual().abs());
    let hud = game.ghost_table();
    assert!(
        hud.contains("auto (live)") && hud.contains("reference"),
        "{hud}"
    );
    assert_eq!(hud.lines().count(), 9, "{hud}");
}

/// At k = 1e5 explicit Euler leaves the bounds: its ghost freezes with the step, the others
/// and the live box go on.
#[test]
fn a_diverged_ghost_freezes_with_its_step() {
    let mut game = lab();
    for _ in 0..4 {
        game.tap_key(key(Action::Stiffer));
        game.update(1);
    }
    game.tap_key(key(Action::Toggle(Overlay::Ghosts)));
    game.update(1);
    game.press_at(DVec2::new(180.0, 90.0));
    game.update(60);
    let ghosts = game.world().resource::<Ghosts>();
    let euler = &ghosts.ghosts[0];
    assert_eq!(euler.kind, GhostKind::Method(Integrator::Euler));
    let step = euler.diverged_at.expect("euler diverges at k = 1e5, 60 Hz");
    assert!(euler.stepper.state.is_sane());
    let frozen = euler.stepper.state;
    let implicit = ghosts
        .ghosts
        .iter()
        .find(|g| g.kind == GhostKind::Method(Integrator::Implicit))
        .unwrap();
    assert_eq!(implicit.diverged_at, None);
    game.update(10);
    let ghosts = game.world().resource::<Ghosts>();
    assert_eq!(ghosts.ghosts[0].stepper.state, frozen);
    assert!(game.ghost_table().contains(&format!("DIVERGED  @{step}")));
}

/// A reset, and a scene loaded, start the ghosts again from the live box; switched off they
/// are gone.
#[test]
fn ghosts_restart_with_a_reset_and_a_scene_and_go_when_switched_off() {
    let mut game = lab();
    game.tap_key(key(Action::Toggle(Overlay::Ghosts)));
    game.press_at(DVec2::new(180.0, 90.0));
    game.update(40);
    game.tap_key(key(Action::Reset));
    game.update(1);
    let steps = game.world().resource::<Ghosts>().ghosts[0].steps;
    assert!(steps <= 2, "{steps}");
    game.tap_key(key(Action::Scene(2)));
    game.update(1);
    let (linear, angular) = game.state();
    let ghosts = game.world().resource::<Ghosts>();
    assert!(ghosts.ghosts[0].steps <= 2);
    let reference = ghosts.reference().unwrap();
    assert!(
        reference
            .stepper
            .state
            .pose_error(&BodyState { linear, angular }, &reference.stepper.mass)
            < 1e-6
    );
    game.tap_key(key(Action::Toggle(Overlay::Ghosts)));
    game.update(1);
    assert!(game.world().resource::<Ghosts>().ghosts.is_empty());
    assert_eq!(game.ghost_table(), "");
}

/// Each number key loads the scene at its place in the core's table: its parameters (at the
/// player's step rate), its name and what makes it hard in the HUD, and its scripted pull,
/// which the game steps to the core's bits.
#[test]
fn number_keys_load_the_core_scenes_and_play_their_scripts() {
    for (key, name) in scene_keys().iter().zip(Scene::NAMES) {
        let scene = Scene::named(name).unwrap();
        let mut game = lab();
        game.tap_key(*key);
        game.update(2);
        let params = *game.world().resource::<SceneParams>();
        assert_eq!(params.stiffness, scene.params.stiffness, "{name}");
        assert_eq!(params.mass, scene.params.mass, "{name}");
        assert_eq!(params.step_rate_hz, 100.0, "{name}");
        assert_eq!(game.world().resource::<SceneName>().0, name);
        let line = game.line("Readouts Scene");
        assert_eq!(line, format!("scene {name}: {}", scene.summary));
        assert_eq!(
            game.bands().len(),
            usize::from(!scene.pulls.is_empty()),
            "{name}"
        );
        for _ in 0..1000 {
            if !game.world().resource::<Playback>().is_playing() {
                break;
            }
            game.update(1);
        }
        let ended = game.world().resource::<Playback>().ended;
        assert!(
            matches!(ended, Some(PlaybackEnd::Finished { hash, recorded, .. }) if hash == recorded),
            "{name}: {ended:?}"
        );
    }
}

/// The tutorial's script pulls for 2 s and lets go; a press during it takes over.
#[test]
fn a_scene_script_releases_on_time_and_a_press_takes_over() {
    let mut game = lab();
    game.tap_key(key(Action::Scene(0)));
    game.update(60);
    assert_eq!(game.bands().len(), 1);
    game.update(70);
    assert_eq!(game.bands().len(), 0, "released after 2 s");

    let mut game = lab();
    game.tap_key(key(Action::Scene(7)));
    game.update(30);
    let there = DVec2::new(-200.0, -100.0);
    game.press_at(there);
    game.update(1);
    assert!(!game.world().resource::<Playback>().is_playing());
    assert!(game.the_band().ends.anchor.distance(there) < 1e-4);
}
