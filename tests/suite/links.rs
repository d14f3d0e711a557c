//! Links (docs/links.md): a link opens the state it names in a headless game and the share
//! control writes the same link back; a game rides in a link's fragment and replays to its
//! recorded hash; every way into the game (a link, a replay file, `play`'s flags) is held to
//! the game's ranges, and refused with the bound named, never with a panic.

use crate::common;

use std::process::Output;
use std::time::Duration;

use bevy::input::ButtonState;
use bevy::math::DVec2;
use bevy::prelude::*;

use bevy::ecs::system::SystemState;
use common::{Game, small_replay, world_to_screen};
use rubber_band_box::game::hud::{HINT, NEWS_SECONDS};
use rubber_band_box::game::input::controls::Action;
use rubber_band_box::game::play::{PlayOptions, prepare};
use rubber_band_box::game::replays::links::link_of;
use rubber_band_box::game::replays::playback::{Playback, PlaybackEnd};
use rubber_band_box::game::replays::recording::Recorder;
use rubber_band_box::game::setup::CurrentSetup;
use rubber_band_box::game::shared::{Learn, Overlay, Overlays, SceneName};
use rubber_band_box::physics::{Integrator, SceneParams, TIME_SCALE_RANGE};
use rubber_band_box::replay::link::{Key, Link, MAX_FRAGMENT_BYTES, decode_replay, encode_replay};
use rubber_band_box::replay::{Record, Replay, Settings};

/// A headless game at 100 frames per second that opens `link` as `play --link` does.
fn opened(link: &str) -> Game {
    let options = PlayOptions {
        link: Some(link.to_owned()),
        ..default()
    };
    Game::with(Duration::from_millis(10), |app| {
        prepare(app, &options).expect("a link never fails `prepare`");
    })
}

/// Returns the link the share control writes of the game now.
fn shared(game: &mut Game, with_game: bool) -> String {
    let world = game.world();
    let mut state = SystemState::<(CurrentSetup, Res<Recorder>)>::new(world);
    let (setup, recorder) = state.get(world).expect("the game is set up");
    link_of(&setup.get(), recorder.replay.as_ref(), with_game)
        .and_then(|link| link.to_query())
        .expect("a link of the game")
}

/// The query of a teacher's link: every key set, none at the game's default.
const SET_UP: &str = "?v=1&scene=stiff&integrator=rk4&k=2e5&mass=0.5&size=90&\
                      linear-damping=0.25&angular-damping=3&rate=64&time=0.5&ghosts=on&vectors=on&trail=on&dock=off";

#[test]
fn a_link_opens_what_it_names_and_the_share_control_writes_it_back() {
    let mut game = opened(SET_UP);
    game.update(3);
    let world = game.world();
    let params = *world.resource::<SceneParams>();
    assert_eq!(params.stiffness, 2e5);
    assert_eq!(params.mass, 0.5);
    assert_eq!(params.size, bevy::math::DVec2::splat(90.0));
    assert_eq!(params.linear_damping, 0.25);
    assert_eq!(params.angular_damping, 3.0);
    assert_eq!(params.step_rate_hz, 64.0);
    assert_eq!(
        world.resource::<Time<Fixed>>().timestep(),
        Duration::from_secs_f64(1.0 / 64.0)
    );
    assert_eq!(*world.resource::<Integrator>(), Integrator::Rk4);
    assert_eq!(world.resource::<SceneName>().0, "stiff");
    // The scene's scripted pull plays, as its number key would have it.
    assert!(world.resource::<Playback>().is_playing());
    assert_eq!(world.resource::<Time<Virtual>>().relative_speed_f64(), 0.5);
    let overlays = *world.resource::<Overlays>();
    assert!(
        [Overlay::Ghosts, Overlay::Vectors, Overlay::Trail].map(|o| overlays.on(o)) == [true; 3]
    );
    assert!(
        world
            .resource::<rubber_band_box::game::shared::DockHidden>()
            .0
    );
    assert!(!overlays.on(Overlay::Plot));
    // The box has the link's mass and size.
    let mass = *world
        .query::<&rubber_band_box::physics::MassProperties>()
        .single(world)
        .unwrap();
    assert_eq!(mass.mass(), 0.5);
    assert_eq!(mass.size(), bevy::math::DVec2::splat(90.0));
    assert_eq!(game.status(), "", "nothing was left");
    assert_eq!(shared(&mut game, false), SET_UP);
}

#[test]
fn a_fresh_game_shares_a_bare_link_and_every_parsed_link_writes_back_alike() {
    let mut game = opened("");
    game.update(2);
    assert_eq!(shared(&mut game, false), "?v=1");
    for query in [
        SET_UP,
        "?v=1&plot=on",
        "?v=1&integrator=euler&rate=4096&time=16",
    ] {
        let (link, problems) = Link::parse(query);
        assert!(problems.is_empty(), "{query}: {problems:?}");
        assert_eq!(link.to_query().unwrap(), query);
        // A whole address and a bare query read the same.
        let whole = format!("https://example.org/box/index.html{query}");
        assert_eq!(Link::parse(&whole).0, link);
        assert_eq!(Link::parse(&query[1..]).0, link);
    }
}

/// Each key the game cannot take is named with why, and the rest is opened.
#[test]
fn a_link_is_taken_in_part_and_what_was_left_is_named() {
    let mut game = opened(
        "?k=1e20&rate=1e9&scene=nowhere&ghosts=maybe&frobnicate=1&mass=0.5&v=2&time=0&\
         integrator=rk5&plot=on#replay=not-a-replay",
    );
    game.update(2);
    let said = game.status();
    for named in [
        "k: must be from 0.01 to 1e12, got 1e20",
        "rate: must be from 8 to 4096 Hz, got 1e9",
        "scene: ",
        "ghosts: 'maybe' is not on or off",
        "frobnicate: not a key",
        "v: version '2'",
        "time: must be from 0.0625 to 16, got 0",
        "integrator: ",
        "replay: ",
    ] {
        assert!(said.contains(named), "'{named}' not in: {said}");
    }
    let params = *game.world().resource::<SceneParams>();
    assert_eq!(params.mass, 0.5);
    assert_eq!(params.stiffness, SceneParams::tutorial().stiffness);
    assert_eq!(params.step_rate_hz, 100.0);
    assert!(game.world().resource::<Overlays>().on(Overlay::Plot));
    // Said under the scene, where a player sees it with every card folded, for a while.
    let hint = game.line("HUD Hint");
    assert!(hint.contains("frobnicate: not a key"), "{hint}");
    game.update((NEWS_SECONDS * 100.0) as usize + 10);
    assert_eq!(game.line("HUD Hint"), HINT);
}

/// Pulls the box about for a second of play, then lets go.
fn pull_about(game: &mut Game) {
    game.press_at(DVec2::new(20.0, 20.0));
    for frame in 0..60 {
        let t = f64::from(frame) / 60.0;
        let at = DVec2::new(150.0 * t, -100.0 * t * t);
        game.cursor(Some(world_to_screen(at)));
        game.update(1);
    }
    game.mouse(ButtonState::Released);
    game.update(40);
}

/// Plays until the playback ends, then how it ended.
fn played_to_the_end(game: &mut Game) -> Option<PlaybackEnd> {
    for _ in 0..10_000 {
        if !game.world().resource::<Playback>().is_playing() {
            break;
        }
        game.update(1);
    }
    game.world().resource::<Playback>().ended
}

#[test]
fn a_game_in_a_link_replays_to_its_recorded_hash() {
    let mut game = opened("?integrator=verlet&k=200&ghosts=on");
    pull_about(&mut game);
    let link = shared(&mut game, true);
    let recorded = game.world().resource::<Recorder>().replay.clone().unwrap();
    assert!(link.starts_with("?v=1&ghosts=on#replay="), "{link}");

    let mut again = opened(&format!("https://example.org/{link}"));
    again.update(1);
    let Some(PlaybackEnd::Finished {
        steps,
        hash,
        recorded: in_the_link,
    }) = played_to_the_end(&mut again)
    else {
        panic!("the playback did not finish: {}", again.status());
    };
    assert_eq!(steps, recorded.steps);
    assert_eq!(in_the_link, recorded.hash);
    assert_eq!(hash, recorded.hash, "the game stepped to other states");
    assert!(again.world().resource::<Overlays>().on(Overlay::Ghosts));
    assert_eq!(*again.world().resource::<Integrator>(), Integrator::Verlet);
    // The link's settings keys are the replay's to set: named, not applied.
    let mut mixed = opened(&format!("?k=5{}", &link[link.find('#').unwrap()..]));
    mixed.update(2);
    assert!(mixed.status().contains("k: left"), "{}", mixed.status());
    assert_eq!(mixed.world().resource::<SceneParams>().stiffness, 200.0);
}

#[test]
fn a_replay_survives_the_fragment_to_the_bit_and_a_broken_one_is_refused() {
    let replay = small_replay();
    let data = encode_replay(&replay);
    let back = decode_replay(&data).expect("its own encoding");
    assert_eq!(back.to_bytes(), replay.to_bytes());
    for (bad, why) in [
        ("!!!", "not base64url"),
        ("AAAA", "not a deflated replay"),
        // Cut at a whole number of base64 quads: the text decodes, the deflate stream breaks.
        (&data[..data.len() / 8 * 4], "deflated"),
    ] {
        let error = decode_replay(bad).expect_err(bad);
        assert!(error.contains(why), "{bad}: {error}");
    }
    let huge = "A".repeat(MAX_FRAGMENT_BYTES + 1);
    assert!(decode_replay(&huge).unwrap_err().contains("longer than"));
}

/// docs/links.md lists every key with its values and default, as the core has them.
#[test]
fn the_docs_list_every_key_with_its_values_and_default() {
    let docs = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/links.md"))
        .expect("docs/links.md");
    for key in Key::ALL {
        let row = format!(
            "| `{}` | {} | {} | {} |",
            key.name(),
            key.meaning(),
            key.values(),
            key.default_value()
        );
        assert!(docs.contains(&row), "docs/links.md lacks the row\n{row}");
    }
    assert!(TIME_SCALE_RANGE.contains(1.0));
}

/// The header of a replay at `rate` Hz (its step as the clock would take it).
fn header_at(rate: f64) -> String {
    let mut replay = small_replay();
    replay.header.settings.step_rate_hz = rate;
    replay.header.settings.dt = 1.0 / rate;
    String::from_utf8(replay.to_bytes()).unwrap()
}

/// A replay whose settings record (the game's first) asks for `rate` Hz.
fn settings_record_at(rate: f64) -> String {
    let mut replay = small_replay();
    for record in &mut replay.records {
        if let Record::Settings { settings, .. } = record {
            **settings = Settings {
                step_rate_hz: rate,
                dt: 1.0 / rate,
                ..**settings
            };
        }
    }
    String::from_utf8(replay.to_bytes()).unwrap()
}

/// The crafted files of issue 32: a step no clock keeps is refused by the reader, one the game
/// does not keep by the game, each with the bound named.
#[test]
fn crafted_replays_are_refused_with_the_bound_named() {
    let read = |text: &str| Replay::from_bytes(text.as_bytes());
    // A step of 0.1 ns: no clock keeps it, `simulate` included.
    let error = read(&settings_record_at(1e10)).unwrap_err().to_string();
    assert!(error.contains("step rate must be from 0 to 1e6"), "{error}");
    let error = read(&header_at(1e10)).unwrap_err().to_string();
    assert!(
        error.starts_with("line 1: ") && error.contains("1e6"),
        "{error}"
    );
    // A megahertz: `simulate` may step it, the game may not.
    for text in [header_at(1e6), settings_record_at(1e6), header_at(4.0)] {
        let replay = read(&text).expect("within simulate's range");
        let error = replay.check_playable().unwrap_err().to_string();
        assert!(error.contains("from 8 to 4096 Hz"), "{error}");
    }
    let replay = read(&settings_record_at(1e6)).unwrap();
    let line = replay
        .records
        .iter()
        .position(|r| matches!(r, Record::Settings { .. }))
        .unwrap()
        + 2;
    let error = replay.check_playable().unwrap_err().to_string();
    assert!(error.starts_with(&format!("line {line}: ")), "{error}");
    // A file cannot grow without steps.
    let text = header_at(100.0);
    let mut lines: Vec<&str> = text.lines().collect();
    let reset = lines
        .iter()
        .position(|line| line.contains("\"reset\""))
        .unwrap();
    let again = lines[reset];
    lines.insert(reset, again);
    let error = read(&(lines.join("\n") + "\n")).unwrap_err().to_string();
    assert!(error.contains("a second reset"), "{error}");
}

/// A refused replay, dropped on the window or given to `play`, leaves the game as it was.
#[test]
fn a_refused_replay_leaves_the_game_whole() {
    let path = common::scratch("refused.jsonl");
    std::fs::write(&path, settings_record_at(1e6)).unwrap();
    let mut app = App::new();
    let options = PlayOptions {
        replay: Some(path.clone()),
        ..default()
    };
    let error = prepare(&mut app, &options).unwrap_err();
    assert!(error.contains("from 8 to 4096 Hz"), "{error}");
    assert!(!app.world().contains_resource::<SceneParams>());

    let mut game = Game::stepping();
    game.update(5);
    let before = *game.world().resource::<SceneParams>();
    game.world()
        .write_message(bevy::window::FileDragAndDrop::DroppedFile {
            window: Entity::PLACEHOLDER,
            path_buf: path.clone(),
        });
    game.update(5);
    assert!(game.status().contains("cannot play"), "{}", game.status());
    assert!(game.status().contains("4096"));
    assert_eq!(*game.world().resource::<SceneParams>(), before);
    assert!(!game.world().resource::<Playback>().is_playing());
    let (linear, angular) = game.state();
    assert!(linear.position.is_finite() && angular.orientation.is_finite());
    std::fs::remove_file(path).ok();
}

fn play(args: &[&str], display: bool) -> Output {
    let mut command = common::binary("play");
    command.args(args);
    if !display {
        command.env_remove("DISPLAY").env_remove("WAYLAND_DISPLAY");
    }
    command.output().expect("the binary runs")
}

/// `play`'s flags out of the game's range, and no display, each end in one line and status 2.
#[test]
fn play_refuses_rates_out_of_range_and_a_missing_display_in_one_line() {
    for (args, said) in [
        (&["--step-rate", "1e9"][..], "from 8 to 4096 Hz"),
        (&["--step-rate", "0.001"][..], "from 8 to 4096 Hz"),
        (&[][..], "DISPLAY is not set"),
        (&["--link", "?scene=stiff"][..], "DISPLAY is not set"),
    ] {
        let output = play(args, false);
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(stderr.contains(said), "{args:?}: {stderr}");
        // One line says it (clap adds its usual pointer to `--help` after a blank line).
        let errors = stderr
            .lines()
            .filter(|line| line.starts_with("error"))
            .count();
        assert_eq!(errors, 1, "{args:?}: {stderr}");
        assert!(stderr.lines().count() <= 3, "{args:?}: {stderr}");
        assert!(!stderr.contains("panicked"), "{stderr}");
    }
}

/// A `DISPLAY` that names no X server (a stale one over ssh or in tmux) ends the game in one
/// line naming it, with status 2, and no backtrace.
#[test]
fn play_says_a_display_it_cannot_open_in_one_line() {
    // No X server listens at display 97 here (its socket would be this file).
    assert!(!std::path::Path::new("/tmp/.X11-unix/X97").exists());
    let output = common::binary("play")
        .env("DISPLAY", ":97")
        .env_remove("WAYLAND_DISPLAY")
        .output()
        .expect("the binary runs");
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(2), "{stderr}");
    let errors: Vec<&str> = stderr
        .lines()
        .filter(|line| line.starts_with("error"))
        .collect();
    assert_eq!(errors.len(), 1, "{stderr}");
    assert!(errors[0].contains("DISPLAY=\":97\""), "{stderr}");
    assert!(
        !stderr.contains("panicked") && !stderr.contains("backtrace"),
        "{stderr}"
    );
}

/// How many seconds of a game fit in a link of 8 KB and of 64 KB (docs/links.md's table): a
/// game at 100 Hz in which the hand moves every frame (60 a second), and one in which it
/// pulls and lets go once a second. `cargo test --test suite links::link_sizes -- --nocapture`.
#[test]
fn link_sizes() {
    for (name, hold) in [("moving every frame", 60), ("a pull a second", 30)] {
        let mut game = Game::new(Duration::from_secs_f64(1.0 / 60.0));
        let mut fits = [None, None];
        let mut pressed = false;
        for frame in 0..60 * 120 {
            if frame % 60 == 0 {
                game.press_at(DVec2::new(10.0, 10.0));
                pressed = true;
            } else if frame % 60 == hold && pressed {
                game.mouse(ButtonState::Released);
                pressed = false;
            }
            let t = f64::from(frame) / 60.0;
            let at = DVec2::new(150.0 * (t * 1.3).sin(), 100.0 * (t * 0.7).cos());
            game.cursor(Some(world_to_screen(at)));
            game.update(1);
            if frame % 30 == 29 {
                let length = shared(&mut game, true).len();
                for (fit, limit) in fits.iter_mut().zip([8 << 10, 64 << 10]) {
                    if length <= limit {
                        // Seconds of play: the steps at 100 Hz.
                        *fit = Some(game.world().resource::<Recorder>().steps() as f64 / 100.0);
                    }
                }
                if length > 64 << 10 {
                    break;
                }
            }
        }
        let steps = game.world().resource::<Recorder>().steps();
        println!(
            "{name}: 8 KB holds {:?} s, 64 KB {:?} s ({steps} steps)",
            fits[0], fits[1]
        );
        // A short game always fits: the format has not grown past what docs/links.md says.
        assert!(fits[0].is_some_and(|s| s >= 2.0), "{name}: {fits:?}");
        assert!(fits[1].is_some_and(|s| s >= 15.0), "{name}: {fits:?}");
    }
}

/// A scene opened by a link as the game starts plays its scripted pull to the recorded bits: the
/// fixed clock is at the scene's rate before the first frame (it once built the scene's steps
/// on Bevy's default 64 Hz, and the replay ended after 192 steps, its states differing).
#[test]
fn a_scene_opened_by_a_link_at_start_plays_to_its_recorded_bits() {
    for link in ["?v=1&scene=tutorial", "?v=1&learn=3"] {
        let mut game = opened(link);
        if link.contains("learn") {
            // A chapter waits, paused, for its answer.
            game.world().trigger(Learn::Predict(0));
            game.world().write_message(Action::TogglePause);
        }
        game.update(400);
        let ended = game.world().resource::<Playback>().ended;
        assert!(
            matches!(ended, Some(PlaybackEnd::Finished { steps: 300, hash, recorded }) if hash == recorded),
            "{link}: {ended:?}"
        );
        // A scene's scripted pull ending is no news for the status line (a learner sees no hash).
        assert!(!game.status().contains("replay over"), "{link}");
    }
}

/// A teacher's link opens learn mode at its chapter, and C there writes that link back; a
/// chapter past the last is named, and settings keys beside a chapter are left and named.
#[test]
fn a_link_opens_a_chapter_and_the_share_control_writes_the_chapters_link() {
    use rubber_band_box::game::input::controls::Action;
    use rubber_band_box::game::learn::chapter_shown;
    let mut game = opened("?v=1&learn=4");
    game.update(2);
    assert_eq!(chapter_shown(game.world()), Some(3));
    game.world().write_message(Action::ShareLink);
    game.update(1);
    assert!(game.status().ends_with("?v=1&learn=4"), "{}", game.status());
    let mut game = opened("?v=1&learn=9");
    game.update(2);
    assert_eq!(chapter_shown(game.world()), None);
    assert!(
        game.status().contains("no chapter 9 (there are 8)"),
        "{}",
        game.status()
    );
    let mut game = opened("?v=1&k=1e5&learn=2");
    game.update(2);
    assert_eq!(chapter_shown(game.world()), Some(1));
    let said = game.status();
    assert!(
        said.contains("k: left: the link's chapter sets the scene and its settings"),
        "{said}"
    );
    let (_, problems) = Link::parse("?learn=0");
    assert_eq!(problems.len(), 1);
}
