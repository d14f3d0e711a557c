//! Every action a player can take, recorded and replayed (issue 51): a headless game is played
//! through one action (with pulls before, during and after it, and a reset), its recording is
//! written, read back and stepped again with the core, and must reach the hash of the states the
//! game itself had, which an observer of the game's steps keeps apart from the recorder. A
//! recording that replays to another game is lost data. Then the messages of a replay that does
//! not reach its hash: each says its own cause.

use crate::common;

use common::*;
use rubber_band_box::game::input::controls::{Action, Parameter};
use rubber_band_box::game::replays::recording::Recorder;
use rubber_band_box::game::shared::Learn;
use rubber_band_box::game::shared::{Overlay, StatusMessage};
use rubber_band_box::physics::{AutoSettings, BodyState, Scene};
use rubber_band_box::replay::run::ReplayRun;
use rubber_band_box::replay::{Header, Integrity, Replay, Settings};

/// A game at 100 Hz, one step a frame, that keeps every state its steps left.
fn game() -> Game {
    Game::keeping_trajectory(Duration::from_millis(10), |_| {})
}

/// A pull that circles for `frames` frames from a point right of the centre.
fn pull(game: &mut Game, frames: usize) {
    game.press_at(DVec2::new(150.0, 60.0));
    for frame in 0..frames {
        let t = frame as f64 * 0.15;
        let at = game.window_point(DVec2::new(150.0 * t.cos(), 90.0 * t.sin()));
        game.cursor(Some(at));
        game.update(1);
    }
    game.mouse(ButtonState::Released);
    game.update(1);
}

fn send(game: &mut Game, action: Action) {
    game.world().write_message(action);
}

/// Plays `action` with a pull held across it, another after it, a reset and a last pull.
fn played_through(action: Action) -> Game {
    let mut game = game();
    pull(&mut game, 20);
    game.press_at(DVec2::new(-100.0, 80.0));
    game.update(5);
    send(&mut game, action);
    game.update(15);
    game.mouse(ButtonState::Released);
    game.update(10);
    // Paused by the action: a few single steps, then on again.
    if game.world().resource::<Time<Virtual>>().is_paused() {
        for _ in 0..3 {
            send(&mut game, Action::Step);
            game.update(2);
        }
        send(&mut game, Action::TogglePause);
        game.update(1);
    }
    pull(&mut game, 15);
    send(&mut game, action);
    game.update(10);
    send(&mut game, Action::Reset);
    game.update(5);
    pull(&mut game, 15);
    game
}

/// Every action but the ones that only write a file or a link (the save control is
/// tested in tests/replay.rs).
fn actions() -> Vec<Action> {
    use rubber_band_box::physics::Integrator;
    let mut actions = vec![
        Action::TogglePause,
        Action::Step,
        Action::Reset,
        Action::NextIntegrator,
        Action::Softer,
        Action::Stiffer,
        Action::Slower,
        Action::Faster,
        Action::FewerSteps,
        Action::MoreSteps,
        Action::Toggle(Overlay::Vectors),
        Action::Toggle(Overlay::Trail),
        Action::Toggle(Overlay::Ghosts),
        Action::Toggle(Overlay::Plot),
        Action::ToggleDock,
        Action::HomeView,
        Action::Open,
        Action::ShareLink,
        Action::ShareGame,
        Action::Learn,
        Action::NextChapter,
        Action::PreviousChapter,
    ];
    actions.extend(Integrator::ALL.map(Action::Integrator));
    let values = [
        (Parameter::Stiffness, 3e4),
        (Parameter::Mass, 3.0),
        (Parameter::Size, 90.0),
        (Parameter::LinearDamping, 0.0),
        (Parameter::AngularDamping, 7.0),
    ];
    actions.extend(values.map(|(parameter, value)| Action::Set(parameter, value)));
    actions.extend((0..Scene::NAMES.len()).map(Action::Scene));
    actions
}

#[test]
fn every_action_records_a_game_that_replays_to_the_games_own_hash() {
    for action in actions() {
        let mut game = played_through(action);
        assert_replays(&mut game, &format!("{action:?}"));
    }
}

/// The case that found the class (issue 51): a scene whose box starts moving, then a reset,
/// typed as a player types them, and stepped by `simulate --replay FILE --hash`.
#[test]
fn spin_and_reset_by_their_keys_replay_in_simulate() {
    let mut game = game();
    game.tap_key(KeyCode::Digit5);
    game.update(30);
    game.tap_key(KeyCode::KeyR);
    game.update(20);
    pull(&mut game, 20);
    game.tap_key(KeyCode::KeyR);
    game.update(10);
    assert_replays(&mut game, "spin, R, a pull, R");
    let path = scratch("spin-reset.jsonl");
    let replay = game.world().resource::<Recorder>().replay.clone().unwrap();
    std::fs::write(&path, replay.to_bytes()).unwrap();
    let out = binary("simulate")
        .args(["--replay", path.to_str().unwrap(), "--hash"])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(
        String::from_utf8_lossy(&out.stdout).trim(),
        replay.hash.to_string()
    );
}

/// Every scene loaded, learn mode entered and left, a replay opened: one recording holds the
/// whole session, from its first step, and the player is told it goes on.
#[test]
fn learn_mode_and_an_opened_replay_keep_the_game_before_them() {
    let mut game = game();
    pull(&mut game, 40);
    let before = game.world().resource::<Recorder>().steps();
    send(&mut game, Action::Learn);
    game.update(5);
    // The chapter waits, paused, for its answer.
    game.world().trigger(Learn::Predict(0));
    send(&mut game, Action::TogglePause);
    pull(&mut game, 20);
    send(&mut game, Action::NextChapter);
    game.update(1);
    game.world().trigger(Learn::Predict(0));
    send(&mut game, Action::TogglePause);
    game.update(10);
    send(&mut game, Action::Learn);
    game.update(1);
    // The log says the recording goes on; the status line is the player's, without step counts.
    let status = game.world().resource::<StatusMessage>().0.clone();
    assert!(
        !status.as_deref().is_some_and(|said| said.contains("steps")),
        "{status:?}"
    );
    pull(&mut game, 10);
    game.world()
        .commands()
        .queue(|world: &mut World| open_replay(world, small_replay()));
    game.update(30);
    pull(&mut game, 10);
    let recorder = game.world().resource::<Recorder>();
    let replay = recorder.replay.as_ref().unwrap();
    assert!(
        replay.steps >= before + 70,
        "the earlier game is kept: {} steps, {before} before",
        replay.steps
    );
    assert_replays(&mut game, "learn mode, then a replay opened");
}

/// A link that opens a scene whose box starts moving (before the first step), then a reset.
#[test]
fn a_link_to_a_moving_scene_then_a_reset_replays() {
    use rubber_band_box::game::play::{PlayOptions, prepare};
    let options = PlayOptions {
        link: Some("?scene=spin&integrator=rk4&rate=64".to_owned()),
        ..default()
    };
    let mut game = Game::keeping_trajectory(Duration::from_millis(10), |app| {
        prepare(app, &options).unwrap();
    });
    game.update(20);
    send(&mut game, Action::Reset);
    game.update(20);
    pull(&mut game, 10);
    assert_replays(&mut game, "a link to spin, then R");
}

/// A tap (pressed and released in one frame) acts for one step and is recorded as such.
#[test]
fn a_tap_replays() {
    let mut game = game();
    let at = game.window_point(DVec2::new(120.0, -40.0));
    game.cursor(Some(at));
    game.mouse(ButtonState::Pressed);
    game.mouse(ButtonState::Released);
    game.update(10);
    assert_replays(&mut game, "a tap");
}

/// A replay whose box starts moving, made as the recorder before issue 51 made one: a reset
/// the game put elsewhere than the file's start, with no record of where.
fn a_reset_the_file_cannot_replay() -> Replay {
    let spin = Scene::named("spin").unwrap();
    let settings = Settings::new(&spin.params, 0.01, Default::default());
    let start = spin.initial;
    let mut replay = Replay::start("spin", settings, AutoSettings::default(), start);
    let mut stepper = replay.stepper().unwrap();
    for step in 0..40 {
        if step == 20 {
            replay.push_reset();
            // The game's reset: at rest at the centre, not the scene's start.
            stepper.state = BodyState::default();
        }
        stepper.step(0.01);
        replay.push_step(None, &stepper.state);
        replay.push_check_if_due(&stepper.state);
    }
    replay
}

#[test]
fn a_reset_that_cannot_be_replayed_is_named_with_its_step() {
    let replay = a_reset_the_file_cannot_replay();
    let read = Replay::from_bytes(&replay.to_bytes()).unwrap();
    let mut run = ReplayRun::new(&read, None).unwrap();
    assert_ne!(run.finish(), read.hash);
    let said = run.explain_mismatch();
    assert!(said.contains("contradict each other"), "{said}");
    assert!(
        said.contains("a reset before step 21 does not put the box where the game had it"),
        "{said}"
    );
    assert!(!said.contains("computes the steps differently"), "{said}");
}

#[test]
fn a_file_changed_after_it_was_written_says_so() {
    let text = String::from_utf8(small_replay().to_bytes()).unwrap();
    let changed = text.replacen("[200.0,120.0]", "[200.0,121.0]", 1);
    assert_ne!(text, changed);
    let read = Replay::from_bytes(changed.as_bytes()).unwrap();
    assert_eq!(read.integrity, Integrity::Changed);
    let mut run = ReplayRun::new(&read, None).unwrap();
    assert_ne!(run.finish(), read.hash);
    let said = run.explain_mismatch();
    assert!(said.contains("changed after it was written"), "{said}");
}

/// Only a file read back as written, by another version or platform, blames the build or the
/// machine: here a last bit of a check differs, as another machine's step would.
#[test]
fn only_another_build_or_machine_is_blamed_for_computing_differently() {
    let mut replay = small_replay();
    replay.header = Header {
        made_by: Some("0.0.1 riscv64-linux".to_owned()),
        ..replay.header
    };
    // One step more, whose state differs from this build's in its last bit.
    let base = replay.clone();
    let mut run = ReplayRun::new(&base, None).unwrap();
    run.finish();
    let mut stepper = run.stepper.clone();
    stepper.band = None;
    stepper.step(0.01);
    let mut state = stepper.state.to_array();
    state[0] = f64::from_bits(state[0].to_bits() ^ 1);
    let after = BodyState::from_array(state);
    replay.push_step(None, &after);
    replay.push_check_if_due(&after);
    let read = Replay::from_bytes(&replay.to_bytes()).unwrap();
    let mut run = ReplayRun::new(&read, None).unwrap();
    assert_ne!(run.finish(), read.hash);
    let said = run.explain_mismatch();
    assert!(said.contains("computes the steps differently"), "{said}");
    assert!(said.contains("0.0.1 riscv64-linux"), "{said}");
    assert!(said.contains("first differ at step 13"), "{said}");
}

/// FNV-1a over a recording's file, with the build's own marks (its version and platform) left
/// out: the same game records these bytes in every build.
fn digest(replay: &Replay) -> String {
    let mut replay = replay.clone();
    replay.header.crate_version = String::new();
    replay.header.made_by = None;
    let hash = replay
        .to_bytes()
        .iter()
        .fold(0xcbf2_9ce4_8422_2325_u64, |hash, byte| {
            (hash ^ u64::from(*byte)).wrapping_mul(0x0100_0000_01b3)
        });
    format!("{hash:016x}")
}

/// A game opened by `link`, then pulled, reset and pulled again.
fn linked(link: &str) -> Game {
    use rubber_band_box::game::play::{PlayOptions, prepare};
    let options = PlayOptions {
        link: Some(link.to_owned()),
        ..default()
    };
    let mut game = Game::keeping_trajectory(Duration::from_millis(10), |app| {
        prepare(app, &options).unwrap();
    });
    game.update(10);
    pull(&mut game, 15);
    send(&mut game, Action::Reset);
    game.update(5);
    pull(&mut game, 10);
    game
}

/// Several actions in one frame, between pulls.
fn in_one_frame(actions: &[Action]) -> Game {
    let mut game = game();
    pull(&mut game, 15);
    if actions.contains(&Action::Step) {
        send(&mut game, Action::TogglePause);
        game.update(2);
    }
    for action in actions {
        send(&mut game, *action);
    }
    game.update(10);
    pull(&mut game, 15);
    game
}

/// Every chapter of learn mode, entered by its number, pulled, the next, then left.
fn every_chapter() -> Game {
    use rubber_band_box::game::learn::chapters::CHAPTERS;
    let mut game = game();
    pull(&mut game, 10);
    send(&mut game, Action::Learn);
    game.update(3);
    for _ in 0..CHAPTERS.len() {
        pull(&mut game, 10);
        send(&mut game, Action::NextChapter);
        game.update(3);
    }
    send(&mut game, Action::PreviousChapter);
    game.update(3);
    send(&mut game, Action::Learn);
    game.update(3);
    pull(&mut game, 10);
    game
}

/// A replay opened mid-game, played, then taken over.
fn an_opened_replay() -> Game {
    let mut game = game();
    pull(&mut game, 10);
    game.world()
        .commands()
        .queue(|world: &mut World| open_replay(world, small_replay()));
    game.update(20);
    pull(&mut game, 10);
    game
}

/// Every case the golden recordings hold: each action played through, each link key, every
/// chapter, several actions in one frame and a replay opened.
fn recorded_cases() -> Vec<(String, Game)> {
    let mut cases: Vec<(String, Game)> = actions()
        .into_iter()
        .map(|action| (format!("{action:?}"), played_through(action)))
        .collect();
    let links = [
        "?scene=spin&integrator=rk4&rate=64",
        "?v=1&scene=far&integrator=euler&rate=8&dock=off",
        "?scene=tutorial&k=40&mass=3&size=90&linear-damping=1&angular-damping=3",
        "?scene=diagonal&time=0.5&ghosts=on&plot=on&vectors=on&trail=on",
        "?scene=stiff&rate=4096&time=16&ghosts=on&k=1e12",
        "?learn=3",
        "?learn=7&integrator=seed",
    ];
    cases.extend(links.map(|link| (format!("link {link}"), linked(link))));
    let frames: [&[Action]; 5] = [
        &[Action::Scene(2), Action::NextIntegrator],
        &[Action::Toggle(Overlay::Vectors), Action::Learn],
        &[Action::Learn, Action::Scene(3)],
        &[Action::Step, Action::TogglePause],
        &[Action::Stiffer, Action::Reset],
    ];
    cases.extend(frames.map(|frame| (format!("one frame {frame:?}"), in_one_frame(frame))));
    cases.push(("every chapter".to_owned(), every_chapter()));
    cases.push(("a replay opened".to_owned(), an_opened_replay()));
    cases
}

/// Every case records the bytes it recorded before the game's settings went through their
/// owners (issue 61), in tests/fixtures/recordings.txt. `RBB_WRITE_RECORDINGS=1` writes the
/// file from this build.
#[test]
fn every_case_records_the_bytes_it_always_recorded() {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/recordings.txt");
    let found: Vec<String> = recorded_cases()
        .into_iter()
        .map(|(case, mut game)| {
            // A chapter waiting for its answer takes no step, and records none.
            let recorded = game.world().resource::<Recorder>().replay.clone();
            let digest = recorded.map_or("no steps".to_owned(), |replay| digest(&replay));
            format!("{digest}\t{case}")
        })
        .collect();
    let found = found.join("\n") + "\n";
    if std::env::var_os("RBB_WRITE_RECORDINGS").is_some() {
        std::fs::write(&path, &found).unwrap();
    }
    let wanted = std::fs::read_to_string(&path).unwrap();
    let differ: Vec<String> = found
        .lines()
        .zip(wanted.lines())
        .filter(|(a, b)| a != b)
        .map(|(a, b)| format!("now {a}\nwas {b}"))
        .collect();
    assert!(
        differ.is_empty() && found.lines().count() == wanted.lines().count(),
        "recordings differ from tests/fixtures/recordings.txt:\n{}",
        differ.join("\n")
    );
}
