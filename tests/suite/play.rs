//! The play command's set-up (`game::play::prepare`), without a window: every option checked
//! before anything is put in place, so a bad one leaves the app as it was, and a replay given
//! starts the game with its scene, settings and integrator.

use crate::common;

use common::scratch;

use bevy::prelude::*;
use rubber_band_box::game::play::{PlayOptions, prepare};
use rubber_band_box::game::replays::playback::Playback;
use rubber_band_box::game::replays::recording::Recorder;
use rubber_band_box::game::shared::SceneName;
use rubber_band_box::physics::{AutoSettings, Integrator, Scene, SceneParams};
use rubber_band_box::replay::script::scene_replay;

/// Nothing of the game's was put in the app.
fn untouched(app: &App) -> bool {
    let world = app.world();
    !world.contains_resource::<SceneParams>()
        && !world.contains_resource::<Integrator>()
        && !world.contains_resource::<Playback>()
        && !world.contains_resource::<Recorder>()
        && !world.contains_resource::<SceneName>()
}

#[test]
fn the_options_put_the_scene_and_the_integrator_in_place() {
    let mut app = App::new();
    let options = PlayOptions {
        integrator: Some(Integrator::Rk4),
        step_rate: Some(64.0),
        ..default()
    };
    prepare(&mut app, &options).expect("good options");
    let params = app.world().resource::<SceneParams>();
    assert_eq!(params.step_rate_hz, 64.0);
    assert_eq!(params.stiffness, SceneParams::tutorial().stiffness);
    assert_eq!(*app.world().resource::<Integrator>(), Integrator::Rk4);
    assert!(!app.world().contains_resource::<Recorder>());
}

#[test]
fn a_bad_step_rate_is_refused_and_leaves_the_app_untouched() {
    for rate in [-5.0, 0.0, f64::NAN] {
        let mut app = App::new();
        let options = PlayOptions {
            step_rate: Some(rate),
            ..default()
        };
        let error = prepare(&mut app, &options).expect_err("a bad rate");
        assert!(error.contains("step"), "{error}");
        assert!(untouched(&app), "after {rate}");
    }
}

#[test]
fn recording_into_a_missing_folder_is_refused_before_the_game_starts() {
    let mut app = App::new();
    let target = scratch("no-such-folder").join("game.jsonl");
    let options = PlayOptions {
        record: Some(target.clone()),
        ..default()
    };
    let error = prepare(&mut app, &options).expect_err("a missing folder");
    assert!(error.contains("is not a folder"), "{error}");
    assert!(untouched(&app));

    let target = scratch("game.jsonl");
    prepare(
        &mut app,
        &PlayOptions {
            record: Some(target.clone()),
            ..default()
        },
    )
    .expect("a folder that exists");
    assert_eq!(app.world().resource::<Recorder>().target, Some(target));
}

#[test]
fn a_replay_starts_the_game_with_its_scene_settings_and_integrator() {
    let scene = Scene::named("stiff").unwrap();
    let replay = scene_replay(
        &scene,
        1.0 / 128.0,
        Integrator::Verlet,
        AutoSettings::default(),
    )
    .expect("a scene's replay");
    let path = scratch("stiff.jsonl");
    std::fs::write(&path, replay.to_bytes()).unwrap();
    let mut app = App::new();
    let options = PlayOptions {
        replay: Some(path),
        ..default()
    };
    prepare(&mut app, &options).expect("a good replay");
    let world = app.world();
    assert_eq!(world.resource::<SceneName>().0, "stiff");
    assert_eq!(
        world.resource::<SceneParams>().stiffness,
        scene.params.stiffness
    );
    assert_eq!(*world.resource::<Integrator>(), Integrator::Verlet);
    assert!(world.resource::<Playback>().is_playing());
}

#[test]
fn a_bad_replay_file_is_named_and_leaves_the_app_untouched() {
    let path = scratch("bad.jsonl");
    std::fs::write(&path, "{\"not\": \"a replay\"}\n").unwrap();
    let mut app = App::new();
    let options = PlayOptions {
        replay: Some(path.clone()),
        record: Some(scratch("kept.jsonl")),
        ..default()
    };
    let error = prepare(&mut app, &options).expect_err("a bad file");
    assert!(
        error.contains("bad.jsonl") && error.contains("line 1"),
        "{error}"
    );
    assert!(untouched(&app));
}
