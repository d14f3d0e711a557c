//! Replays: the game records what reached its physics; the file round-trips; stepping it again
//! gives the game's states to the bit; bad files are refused with the line and what is wrong,
//! never a panic; saving never leaves a half-written file.

use crate::common;

use std::path::PathBuf;

use proptest::prelude::*;

use common::*;

use rubber_band_box::game::replays::playback::{Playback, PlaybackEnd};
use rubber_band_box::game::replays::recording::Recorder;
use rubber_band_box::game::shared::StatusMessage;
use rubber_band_box::physics::BodyState;
use rubber_band_box::replay::run::ReplayRun;
use rubber_band_box::replay::save::write_atomically;
use rubber_band_box::replay::{MAX_LINE_BYTES, Replay, TrajectoryHash};

/// A headless game at 60 frames per second that keeps its trajectory.
fn recorded_game() -> Game {
    Game::keeping_trajectory(Duration::from_secs_f64(1.0 / 60.0), |_| {})
}

/// What a hand does in one frame.
#[derive(Clone, Copy, Debug)]
enum Hand {
    Press(f64, f64),
    Move(f64, f64),
    Release,
    Tap(f64, f64),
    Key(usize),
    Idle,
}

/// The keys a random hand presses, found by what they do.
fn keys() -> [KeyCode; 9] {
    [
        key(Action::NextIntegrator),
        key(Action::Softer),
        key(Action::Stiffer),
        key(Action::FewerSteps),
        key(Action::MoreSteps),
        key(Action::Reset),
        key(Action::TogglePause),
        key(Action::Step),
        key(Action::Faster),
    ]
}

fn hand() -> impl Strategy<Value = Hand> {
    let at = || (-300.0..300.0, -220.0..220.0);
    prop_oneof![
        2 => at().prop_map(|(x, y)| Hand::Press(x, y)),
        6 => at().prop_map(|(x, y)| Hand::Move(x, y)),
        2 => Just(Hand::Release),
        1 => at().prop_map(|(x, y)| Hand::Tap(x, y)),
        2 => (0..keys().len()).prop_map(Hand::Key),
        4 => Just(Hand::Idle),
    ]
}

fn play(game: &mut Game, hands: &[Hand]) {
    for &hand in hands {
        match hand {
            Hand::Press(x, y) => game.press_at(DVec2::new(x, y)),
            Hand::Move(x, y) => game.cursor(Some(world_to_screen(DVec2::new(x, y)))),
            Hand::Release => game.mouse(ButtonState::Released),
            Hand::Tap(x, y) => {
                game.press_at(DVec2::new(x, y));
                game.mouse(ButtonState::Released);
            }
            Hand::Key(index) => game.tap_key(keys()[index]),
            Hand::Idle => {}
        }
        game.update(1);
    }
}

/// The game's recording, through its file format.
fn saved_replay(game: &mut Game) -> Replay {
    let replay = game.world().resource::<Recorder>().replay.clone();
    let bytes = replay.expect("a step has run").to_bytes();
    Replay::from_bytes(&bytes).expect("the game's own recording reads back")
}

/// Steps `replay` with its recorded integrators, every state after each step.
fn replayed(replay: &Replay) -> (Vec<BodyState>, TrajectoryHash) {
    let mut run = ReplayRun::new(replay, None).unwrap();
    let mut states = Vec::new();
    while run.advance().is_some() {
        states.push(run.stepper.state);
    }
    (states, run.hash)
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 12,
        failure_persistence: None,
        ..ProptestConfig::default()
    })]

    /// Random input into the game (drags, taps, every control that reaches the physics,
    /// pause and single steps), recorded, written, read and stepped again: every step's state
    /// is the game's, to the bit, and so is the hash.
    #[test]
    fn a_recorded_game_replays_to_the_bit(hands in prop::collection::vec(hand(), 50..250)) {
        let mut game = recorded_game();
        play(&mut game, &hands);
        let played = game.world().resource::<Trajectory>().0.clone();
        prop_assume!(!played.is_empty());
        let replay = saved_replay(&mut game);
        prop_assert_eq!(replay.steps, played.len() as u64);
        let (states, hash) = replayed(&replay);
        prop_assert_eq!(bits(&states), bits(&played));
        prop_assert_eq!(hash, replay.hash);
    }
}

/// A drag, a reset, the integrator and k changed mid-drag, a pause with single steps: every
/// kind of record is in the file and the replay is exact. A different integrator gives a
/// different trajectory, and says so through the hash.
#[test]
fn every_kind_of_record_replays_exactly_and_another_integrator_differs() {
    let mut game = recorded_game();
    game.press_at(DVec2::new(150.0, 100.0));
    game.update(20);
    game.tap_key(key(Action::NextIntegrator));
    game.update(5);
    game.tap_key(key(Action::Stiffer));
    game.tap_key(key(Action::MoreSteps));
    game.cursor(Some(world_to_screen(DVec2::new(-120.0, 40.0))));
    game.update(20);
    game.tap_key(key(Action::Reset));
    game.update(3);
    game.press_at(DVec2::new(-50.0, -150.0));
    game.update(10);
    game.tap_key(key(Action::TogglePause));
    game.update(1);
    game.tap_key(key(Action::Step));
    game.update(2);
    let played = game.world().resource::<Trajectory>().0.clone();
    let replay = saved_replay(&mut game);
    let text = String::from_utf8(replay.to_bytes()).unwrap();
    for kind in ["settings", "reset", "step", "end"] {
        assert!(
            text.contains(&format!("\"kind\":\"{kind}\"")),
            "no {kind} record"
        );
    }
    let (states, hash) = replayed(&replay);
    assert_eq!(bits(&states), bits(&played));
    assert_eq!(hash, replay.hash);

    let mut other = ReplayRun::new(&replay, Some(Integrator::Rk4)).unwrap();
    assert_ne!(other.finish(), replay.hash);
}

/// The S key saves the game so far (to `--record`'s file here) and the HUD says where; the
/// game's end saves it again, whole.
#[test]
fn the_save_key_and_the_games_end_write_a_replay_that_loads() {
    let path = scratch("saved.jsonl");
    let target = path.clone();
    let mut game = Game::with(Duration::from_millis(10), move |app| {
        app.insert_resource(Recorder::to_file(target));
    });
    game.press_at(DVec2::new(150.0, 100.0));
    game.update(30);
    game.tap_key(key(Action::Save));
    game.update(1);
    let status = game.world().resource::<StatusMessage>().0.clone().unwrap();
    assert_eq!(status, format!("saved the game to {}", path.display()));
    assert!(game.line("Readouts Replay").contains(&status));
    assert_eq!(read(&path).steps, 30);

    game.update(9);
    game.world().write_message(AppExit::Success);
    game.update(1);
    // Saved at the end of the frame, after its step: 41 in all.
    assert_eq!(read(&path).steps, 41);
}

/// A save into a folder that does not exist says so, and the game plays on.
#[test]
fn a_save_that_cannot_be_written_says_why_and_the_game_plays_on() {
    let path = scratch("no-such-folder").join("replay.jsonl");
    let target = path.clone();
    let mut game = Game::with(Duration::from_millis(10), move |app| {
        app.insert_resource(Recorder::to_file(target));
    });
    game.update(5);
    game.tap_key(key(Action::Save));
    game.update(5);
    let status = game.world().resource::<StatusMessage>().0.clone().unwrap();
    assert!(
        status.starts_with(&format!("cannot save {}: ", path.display())),
        "{status}"
    );
    assert_eq!(game.steps(), 10);
    assert!(!path.exists());
}

#[test]
fn an_interrupted_save_leaves_the_old_file_whole_and_nothing_beside_it() {
    let folder = scratch("atomic");
    std::fs::create_dir_all(&folder).unwrap();
    let path = folder.join("replay.jsonl");
    std::fs::write(&path, "the old replay").unwrap();
    let error = write_atomically(&path, |file| {
        use std::io::Write;
        file.write_all(b"half a new one")?;
        Err(std::io::Error::other("the disk is full"))
    })
    .unwrap_err();
    assert_eq!(
        error.to_string(),
        format!("cannot save {}: the disk is full", path.display())
    );
    assert_eq!(std::fs::read_to_string(&path).unwrap(), "the old replay");
    assert_eq!(std::fs::read_dir(&folder).unwrap().count(), 1);

    write_atomically(&path, |file| {
        use std::io::Write;
        file.write_all(b"the new replay")
    })
    .unwrap();
    assert_eq!(std::fs::read_to_string(&path).unwrap(), "the new replay");
    assert_eq!(std::fs::read_dir(&folder).unwrap().count(), 1);
}

fn read(path: &std::path::Path) -> Replay {
    Replay::from_bytes(&std::fs::read(path).unwrap()).unwrap()
}

fn error_of(text: &str) -> String {
    Replay::from_bytes(text.as_bytes()).unwrap_err().to_string()
}

#[test]
fn a_small_replay_round_trips_and_steps_as_its_stepper_did() {
    let replay = small_replay();
    let text = String::from_utf8(replay.to_bytes()).unwrap();
    assert_eq!(text.lines().count(), 1 + 2 + 12 + 1);
    let back = Replay::from_bytes(text.as_bytes()).unwrap();
    assert_eq!(back, replay);
    assert_eq!(ReplayRun::new(&back, None).unwrap().finish(), replay.hash);
}

/// Each kind of bad file is refused with the line and what is wrong in it.
#[test]
fn bad_replay_files_name_the_line_and_what_is_wrong() {
    let good = String::from_utf8(small_replay().to_bytes()).unwrap();
    let lines: Vec<&str> = good.lines().collect();
    let with_line = |index: usize, line: &str| {
        let mut edited = lines.clone();
        edited[index] = line;
        edited.join("\n") + "\n"
    };
    let cases: Vec<(String, &str)> = vec![
        (String::new(), "empty: no replay header"),
        (lines[..5].join("\n") + "\n", "line 5: truncated"),
        (good[..good.len() - 20].to_owned(), "line 16: "),
        (
            good.replacen("\"version\":2", "\"version\":3", 1),
            "line 1: replay format version 3; this build reads versions 1 to 2",
        ),
        (
            good.replacen("rubber-band-box replay", "a shopping list", 1),
            "line 1: format 'a shopping list' is not 'rubber-band-box replay'",
        ),
        (
            with_line(2, r#"{"kind":"step","step":"two"}"#),
            "line 3: invalid type: string \"two\"",
        ),
        (
            with_line(
                2,
                r#"{"kind":"step","step":1,"band":{"point":[30.0,30.0],"anchor":[NaN,1.0]}}"#,
            ),
            "line 3: ",
        ),
        (
            with_line(
                2,
                r#"{"kind":"step","step":1,"band":{"point":[30.0,30.0],"anchor":[1e999,1.0]}}"#,
            ),
            "line 3: ",
        ),
        (
            with_line(
                2,
                r#"{"kind":"step","step":2,"band":{"point":[30.0,30.0],"anchor":[1e300,1.0]}}"#,
            ),
            "line 3: band.anchor: each coordinate must be finite and within 1e12 of zero, got 1e300",
        ),
        (
            with_line(2, r#"{"kind":"step","step":7}"#),
            "line 3: a step for step 7 out of order: the next step is 2",
        ),
        (
            with_line(2, r#"{"kind":"flip","step":2}"#),
            "line 3: unknown variant `flip`",
        ),
        (
            with_line(2, &"x".repeat(MAX_LINE_BYTES + 10)),
            "line 3: longer than 4096 bytes",
        ),
        (
            good.replacen("\"mass\":5.0", "\"mass\":-5.0", 1),
            "line 1: settings: mass must be a finite number greater than zero, got -5",
        ),
        (
            good.replacen("\"dt\":0.01", "\"dt\":0.0", 1),
            "line 1: settings: dt must be",
        ),
        (
            good.replacen("\"stiffness\":2000.0", "\"stiffness\":-1.0", 1),
            "line 11: settings: stiffness k must be",
        ),
        (
            good.clone() + "{}\n",
            "line 17: a line after the end record",
        ),
        (
            good.replacen(
                "\"kind\":\"end\",\"steps\":12",
                "\"kind\":\"end\",\"steps\":13",
                1,
            ),
            "line 16: the end record counts 13 steps, the file holds 12",
        ),
    ];
    for (text, expected) in cases {
        let error = error_of(&text);
        assert!(
            error.starts_with(expected),
            "expected '{expected}', got '{error}'"
        );
    }
    let junk: Vec<u8> = (0..=255u8).rev().cycle().take(3000).collect();
    assert!(
        Replay::from_bytes(&junk)
            .unwrap_err()
            .to_string()
            .starts_with("line 1: not UTF-8 text")
    );
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 2000,
        failure_persistence: None,
        ..ProptestConfig::default()
    })]

    /// Mutated files (bytes cut, changed, inserted; lines dropped, repeated or swapped) never
    /// panic the reader; what it accepts steps without panic or a non-finite state.
    #[test]
    fn mutated_replay_files_are_read_or_refused_without_panic(
        edits in prop::collection::vec((0..6u8, any::<prop::sample::Index>(), any::<u8>()), 1..4)
    ) {
        let mut bytes = small_replay().to_bytes();
        for (kind, at, byte) in edits {
            let i = at.index(bytes.len().max(1));
            match kind {
                0 => bytes.truncate(i),
                1 if !bytes.is_empty() => bytes[i] = byte,
                2 => bytes.insert(i.min(bytes.len()), byte),
                3 if !bytes.is_empty() => { bytes.remove(i); }
                _ => {
                    let mut lines: Vec<Vec<u8>> = bytes.split(|&b| b == b'\n').map(<[u8]>::to_vec).collect();
                    let n = lines.len();
                    let j = at.index(n);
                    if kind == 4 { lines.insert(j, lines[(j + 1) % n].clone()); } else { lines.swap(j, (j + 1) % n); }
                    bytes = lines.join(&b'\n');
                }
            }
        }
        if let Ok(replay) = Replay::from_bytes(&bytes) {
            let mut run = ReplayRun::new(&replay, None).unwrap();
            while run.advance().is_some() {
                prop_assert!(run.stepper.state.is_sane());
            }
        }
    }
}

/// The game playing `replay` back from its start, at `frame` per update, with its trajectory
/// kept; it runs until the playback ends.
fn played_back(replay: Replay, frame: Duration) -> Game {
    let (params, integrator, auto) = Playback::of(replay.clone()).start().unwrap();
    let mut game = Game::keeping_trajectory(frame, move |app| {
        app.insert_resource(params)
            .insert_resource(integrator)
            .insert_resource(auto)
            .insert_resource(Playback::of(replay));
    });
    for _ in 0..100_000 {
        if !game.world().resource::<Playback>().is_playing() {
            break;
        }
        game.update(1);
    }
    game
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 6,
        failure_persistence: None,
        ..ProptestConfig::default()
    })]

    /// A recorded game played back in the game, at another frame rate: the same states, to the
    /// bit, and its own recording of the playback is the same replay.
    #[test]
    fn a_replay_plays_back_in_the_game_to_the_bit(hands in prop::collection::vec(hand(), 50..200)) {
        let mut game = recorded_game();
        play(&mut game, &hands);
        let played = game.world().resource::<Trajectory>().0.clone();
        prop_assume!(!played.is_empty());
        let replay = saved_replay(&mut game);

        let mut again = played_back(replay.clone(), Duration::from_secs_f64(1.0 / 25.0));
        // The game goes on after the replay's end, to the end of its frame at least.
        let states = again.world().resource::<Trajectory>().0.clone();
        prop_assert!(states.len() >= played.len());
        prop_assert_eq!(bits(&states[..played.len()]), bits(&played));
        let recorded_again = saved_replay(&mut again);
        prop_assert_eq!(&recorded_again.records[..replay.records.len()], &replay.records[..]);
        // And the game says so at the end.
        let ended = again.world().resource::<Playback>().ended;
        prop_assert_eq!(ended, Some(PlaybackEnd::Finished {
            steps: replay.steps,
            hash: replay.hash,
            recorded: replay.hash,
        }));
    }
}

/// Plays the game until its playback ends.
fn until_the_playback_ends(game: &mut Game) {
    for _ in 0..100_000 {
        if !game.world().resource::<Playback>().is_playing() {
            return;
        }
        game.update(1);
    }
    panic!("the playback never ended");
}

/// A replay opened while a game runs (dropped on the window, or chosen in the browser) starts
/// over from the replay's start, whatever the game had done, and steps to its bits; a replay
/// whose recorded hash is not the game's says so.
#[test]
fn a_replay_opened_mid_game_plays_from_its_start_and_says_whether_it_matched() {
    let mut recorded = recorded_game();
    play(
        &mut recorded,
        &[Hand::Key(2), Hand::Key(2), Hand::Press(150.0, 100.0)],
    );
    recorded.update(40);
    play(&mut recorded, &[Hand::Move(-100.0, 50.0), Hand::Key(0)]);
    recorded.update(40);
    let played = recorded.world().resource::<Trajectory>().0.clone();
    let replay = saved_replay(&mut recorded);

    let mut game = recorded_game();
    play(
        &mut game,
        &[Hand::Key(1), Hand::Press(-200.0, 0.0), Hand::Key(3)],
    );
    game.update(30);
    let before = game.world().resource::<Trajectory>().0.len();
    open_replay(game.world(), replay.clone());
    until_the_playback_ends(&mut game);
    let states = game.world().resource::<Trajectory>().0[before..].to_vec();
    assert_eq!(bits(&states[..played.len()]), bits(&played));
    assert_eq!(
        game.world().resource::<Playback>().ended,
        Some(PlaybackEnd::Finished {
            steps: replay.steps,
            hash: replay.hash,
            recorded: replay.hash
        })
    );

    let mut tampered = replay.clone();
    tampered.hash = TrajectoryHash(1);
    open_replay(game.world(), tampered);
    until_the_playback_ends(&mut game);
    let Some(PlaybackEnd::Finished { hash, recorded, .. }) =
        game.world().resource::<Playback>().ended
    else {
        panic!("the playback did not finish");
    };
    assert_eq!((hash, recorded), (replay.hash, TrajectoryHash(1)));
    let said = PlaybackEnd::Finished {
        steps: 1,
        hash,
        recorded,
    }
    .describe();
    assert!(said.contains("DIFFER"), "{said}");
}

/// A file dropped on the window plays if it is a replay, and is refused with the reason in
/// the HUD's status if not, the game playing on.
#[test]
fn a_dropped_file_plays_or_is_refused_with_the_reason() {
    let mut recorded = recorded_game();
    play(&mut recorded, &[Hand::Press(150.0, 100.0)]);
    recorded.update(20);
    let replay = saved_replay(&mut recorded);
    let good = scratch("dropped.jsonl");
    std::fs::write(&good, replay.to_bytes()).unwrap();
    let bad = scratch("dropped.txt");
    std::fs::write(&bad, "not a replay\n").unwrap();

    let mut game = recorded_game();
    let window = game.window;
    let drop = |game: &mut Game, path: &PathBuf| {
        game.world()
            .write_message(bevy::window::FileDragAndDrop::DroppedFile {
                window,
                path_buf: path.clone(),
            });
        game.update(1);
    };
    drop(&mut game, &bad);
    let status = game.world().resource::<StatusMessage>().0.clone().unwrap();
    assert!(
        status.starts_with("cannot play") && status.contains("line 1"),
        "{status}"
    );
    assert!(!game.world().resource::<Playback>().is_playing());

    drop(&mut game, &good);
    let status = game.world().resource::<StatusMessage>().0.clone().unwrap();
    assert!(status.starts_with("playing"), "{status}");
    assert!(game.world().resource::<Playback>().is_playing());
    until_the_playback_ends(&mut game);
    assert!(matches!(
        game.world().resource::<Playback>().ended,
        Some(PlaybackEnd::Finished { hash, recorded, .. }) if hash == recorded
    ));
}

/// A press during playback takes over: the playback ends, the band is the pointer's.
#[test]
fn a_press_takes_over_a_playback() {
    let mut game = recorded_game();
    game.press_at(DVec2::new(150.0, 100.0));
    game.update(60);
    game.mouse(ButtonState::Released);
    game.update(30);
    let replay = saved_replay(&mut game);

    let (params, integrator, auto) = Playback::of(replay.clone()).start().unwrap();
    let mut again = Game::with(Duration::from_secs_f64(1.0 / 60.0), move |app| {
        app.insert_resource(params)
            .insert_resource(integrator)
            .insert_resource(auto)
            .insert_resource(Playback::of(replay));
    });
    again.update(20);
    let recorded = again.the_band().ends.anchor;
    assert!(
        recorded.distance(DVec2::new(150.0, 100.0)) < 1e-4,
        "{recorded:?}"
    );
    assert!(again.world().resource::<Playback>().is_playing());
    let there = DVec2::new(-120.0, -90.0);
    again.press_at(there);
    again.update(1);
    assert!(!again.world().resource::<Playback>().is_playing());
    assert!(matches!(
        again.world().resource::<Playback>().ended,
        Some(PlaybackEnd::TakenOver { step }) if step > 0
    ));
    let band = again.the_band();
    assert!(
        band.ends.anchor.distance(there) < 1e-4,
        "{:?}",
        band.ends.anchor
    );
    again.update(10);
    assert!(again.the_band().ends.anchor.distance(there) < 1e-4);
}

/// A record in memory is small: a long game at a high step rate stays well under the memory
/// a replay's longest allowed length implies (docs/replays.md).
#[test]
fn a_record_takes_at_most_48_bytes() {
    assert!(std::mem::size_of::<rubber_band_box::replay::Record>() <= 48);
}

/// The replay the browser test steps inside the page (`tests/fixtures/cross-platform.jsonl`),
/// whose recorded hash is the one stepped here: every integrator in turn, each at a stiffness
/// it holds (up to 1e6), a hand that circles, lets go and grabs another corner, a reset, a
/// mass change and a step-rate change. It calls every transcendental function the core has.
fn cross_platform_replay() -> Replay {
    use rubber_band_box::physics::{AutoSettings, BandEnds, Integrator, SceneParams};
    use rubber_band_box::replay::Settings;

    let tutorial = SceneParams::tutorial();
    let start = Settings::new(&tutorial, 0.01, Integrator::Auto);
    let mut replay = Replay::start(
        "tutorial",
        start,
        AutoSettings::default(),
        BodyState::default(),
    );
    let stiffness = [20.0, 2e3, 5e3, 2e4, 1e6, 1e3, 1e5];
    let corners = [(30.0, 30.0), (-30.0, 30.0), (-30.0, -30.0), (30.0, -30.0)];
    let mut settings = start;
    for step in 0..700_u64 {
        let (phase, within) = ((step / 100) as usize, step % 100);
        if within == 0 {
            settings.integrator = Integrator::ALL[phase];
            settings.stiffness = stiffness[phase];
        }
        if step == 250 {
            settings.mass = 2.0;
        }
        if step == 350 {
            replay.push_reset();
        }
        if step == 450 {
            settings.step_rate_hz = 240.0;
            settings.dt = Duration::from_secs_f64(1.0 / 240.0).as_secs_f64();
        }
        replay.push_settings(settings);
        let t = step as f64 * 0.05;
        let (x, y) = corners[phase % 4];
        let (u, v) = corners[(phase + 2) % 4];
        let band = match within {
            0..60 => Some(BandEnds {
                local_point: DVec2::new(x, y),
                anchor: DVec2::new(150.0 * t.cos(), 100.0 * (2.0 * t).sin()),
            }),
            60..80 => None,
            _ => Some(BandEnds {
                local_point: DVec2::new(u, v),
                anchor: DVec2::new(250.0, -150.0),
            }),
        };
        replay.push_step(band, &BodyState::default());
    }
    let mut run = ReplayRun::new(&replay, None).unwrap();
    let hash = run.finish();
    assert_eq!(run.refused, None, "the fixture stays inside every bound");
    replay.hash = hash;
    replay
}

/// The fixture is the script above stepped natively, so its recorded hash is this platform's;
/// the browser test steps it in the page and must read back the same hash
/// (`.ci/web/browser-test.mjs`). A change to the core that moves a bit fails here first:
/// regenerate with `UPDATE_FIXTURES=1 cargo test --test suite replay::cross_platform`.
#[test]
fn the_cross_platform_fixture_is_its_script_stepped_here() {
    let path =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/cross-platform.jsonl");
    let replay = cross_platform_replay();
    if std::env::var_os("UPDATE_FIXTURES").is_some() {
        write_atomically(&path, |file| replay.write(file)).unwrap();
    }
    let on_disk = Replay::read_file(&path).unwrap();
    assert_eq!(
        on_disk, replay,
        "regenerate the fixture if the change is meant"
    );
    // Not an independent check: the file is this crate's own output (a golden file), so the
    // hash agrees by construction. The independent check is the browser's: the wasm build
    // steps this fixture in the page and must reach this hash (.ci/web/browser-test.mjs).
    assert_eq!(on_disk.hash, replayed(&on_disk).1);
}

/// A recording stops at `MAX_STEPS` (8 hours at 100 Hz): the game goes on, the recording keeps
/// what it has.
#[test]
fn a_recording_stops_at_its_step_cap_and_the_game_goes_on() {
    use rubber_band_box::game::replays::recording::Recorder;
    use rubber_band_box::replay::MAX_STEPS;
    let mut game = Game::stepping();
    game.update(3);
    // Three steps short of the cap (a replay counts its steps; the records are not needed).
    let recorded = {
        let mut recorder = game.world().resource_mut::<Recorder>();
        let replay = recorder
            .replay
            .as_mut()
            .expect("recording from the first step");
        replay.steps = MAX_STEPS - 3;
        replay.records.len()
    };
    let steps = game.steps();
    game.update(10);
    assert_eq!(game.steps(), steps + 10, "the game goes on");
    let recorder = game.world().resource::<Recorder>();
    let replay = recorder.replay.as_ref().unwrap();
    assert_eq!(replay.steps, MAX_STEPS);
    assert_eq!(
        replay.records.len(),
        recorded + 3,
        "three steps more, then none"
    );
}

/// A replay that starts away from the centre is drawn from its start: the box put there has
/// both render snapshots at the start, so the first frame drawn never slides in from the
/// centre (after one step, the previous snapshot is still the start).
#[test]
fn a_replay_starting_away_from_the_centre_is_drawn_from_its_start() {
    use rubber_band_box::game::simulation::RenderSnapshots;
    use rubber_band_box::physics::AutoSettings;
    use rubber_band_box::replay::Settings;
    let params = SceneParams::tutorial();
    let settings = Settings::new(&params, 0.01, Integrator::Auto);
    let mut start = BodyState::at_rest(DVec2::new(120.0, -40.0));
    start.angular.orientation = 0.7;
    let mut replay = Replay::start("tutorial", settings, AutoSettings::default(), start);
    let mut stepper = replay.stepper().unwrap();
    for _ in 0..3 {
        stepper.step(0.01);
        replay.push_step(None, &stepper.state);
    }
    let mut game = Game::stepping();
    open_replay(game.world(), replay);
    game.update(1);
    let world = game.world();
    let snapshots = *world
        .query_filtered::<&RenderSnapshots, With<RigidBox>>()
        .single(world)
        .unwrap();
    assert_eq!(snapshots.previous, start);
    assert_eq!(snapshots.current.linear.position, DVec2::new(120.0, -40.0));
}
