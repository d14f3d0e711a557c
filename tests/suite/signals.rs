//! What a player's Ctrl-C and a SIGTERM do to a recorded game: the game ends and the
//! recording is saved. The test runs the game in a child process (this test binary again,
//! running only `signals::signalled_game`, headless: `GameLogicPlugin` with Bevy's Ctrl-C handler and
//! the game's SIGTERM handler, as `play --record` installs them), signals it once it has
//! recorded some steps, and reads the file it saved.
#![cfg(unix)]

use crate::common;

use std::io::{BufRead, BufReader};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use bevy::app::TerminalCtrlCHandlerPlugin;
use common::*;
use rubber_band_box::game::replays::recording::{Recorder, sigterm};
use rubber_band_box::replay::Replay;

/// Set in the child: where it records to.
const CHILD: &str = "RBB_SIGNALLED_GAME_RECORDS_TO";

/// The child: a headless game recording to the file the parent names, running until a
/// signal ends it. In the parent (no such variable) it does nothing.
#[test]
fn signalled_game() {
    let Ok(target) = std::env::var(CHILD) else {
        return;
    };
    // As a terminal starts a game: SIGINT at its default (a shell's background job would
    // have it ignored, and Bevy's handler would never be called).
    // SAFETY: setting a signal's disposition to its default in a single-threaded start.
    unsafe {
        libc::signal(libc::SIGINT, libc::SIG_DFL);
    }
    let mut game = Game::with(Duration::from_millis(10), |app| {
        app.add_plugins(TerminalCtrlCHandlerPlugin)
            .insert_resource(Recorder::to_file(target.into()));
        sigterm::exit_on_sigterm(app);
    });
    game.press_at(DVec2::new(200.0, 120.0));
    game.update(20);
    println!("recording");
    let started = Instant::now();
    while game.app.should_exit().is_none() {
        assert!(
            started.elapsed() < Duration::from_secs(20),
            "no signal came"
        );
        game.update(1);
        std::thread::sleep(Duration::from_millis(2));
    }
}

/// Runs the child, signals it with `signal` once it records, and returns the replay it saved.
fn signalled(signal: libc::c_int, name: &str) -> Replay {
    let folder = std::env::temp_dir().join(format!("rbb-signals-{}", std::process::id()));
    std::fs::create_dir_all(&folder).unwrap();
    let target = folder.join(name);
    let _ = std::fs::remove_file(&target);
    let mut child = Command::new(std::env::current_exe().unwrap())
        .args([
            "--exact",
            "signals::signalled_game",
            "--nocapture",
            "--test-threads",
            "1",
        ])
        .env(CHILD, &target)
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .expect("the test binary runs again");
    let mut lines = BufReader::new(child.stdout.take().unwrap()).lines();
    assert!(
        lines.any(|line| line.is_ok_and(|line| line.contains("recording"))),
        "the child never started recording"
    );
    // SAFETY: a signal to our own child process.
    assert_eq!(unsafe { libc::kill(child.id() as libc::pid_t, signal) }, 0);
    let status = child.wait().expect("the child ends");
    assert!(status.success(), "the child ended badly: {status}");
    Replay::read_file(&target).unwrap_or_else(|message| panic!("no saved game: {message}"))
}

#[test]
fn ctrl_c_ends_a_recorded_game_and_saves_it() {
    let replay = signalled(libc::SIGINT, "ctrl-c.jsonl");
    assert!(replay.steps >= 20, "{} steps", replay.steps);
}

#[test]
fn sigterm_ends_a_recorded_game_and_saves_it() {
    let replay = signalled(libc::SIGTERM, "sigterm.jsonl");
    assert!(replay.steps >= 20, "{} steps", replay.steps);
}
