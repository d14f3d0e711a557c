//! The binary: with no command (and always on the web) it plays; natively `simulate` and
//! `report` run the core headless (see `cli`). The game's plugins are wired in the library
//! (`GamePlugin`); this file only adds Bevy's own and the window.

use std::process::ExitCode;

use bevy::prelude::*;
use bevy_prototype_lyon::prelude::ShapePlugin;

use rubber_band_box::game::GamePlugin;
use rubber_band_box::physics::{Integrator, SceneParams};

/// How to start the game: `play` on the command line, defaults on the web.
#[derive(Debug, Default)]
struct PlayArgs {
    integrator: Option<Integrator>,
    step_rate: Option<f64>,
    #[cfg(not(target_arch = "wasm32"))]
    record: Option<std::path::PathBuf>,
    #[cfg(not(target_arch = "wasm32"))]
    replay: Option<std::path::PathBuf>,
}

#[cfg(not(target_arch = "wasm32"))]
fn main() -> ExitCode {
    use clap::Parser;
    use rubber_band_box::cli::{Cli, Command, SimulateError, simulate};
    use std::io;

    let cli = Cli::parse();
    match cli.command {
        None => play(PlayArgs::default()),
        Some(Command::Play(args)) => play(PlayArgs {
            integrator: args.integrator,
            step_rate: args.step_rate,
            record: args.record,
            replay: args.replay,
        }),
        Some(Command::Simulate(args)) => match simulate(&args, io::stdout().lock()) {
            Ok(()) => ExitCode::SUCCESS,
            Err(SimulateError::Arguments(message)) => {
                eprintln!("error: {message}");
                ExitCode::from(2)
            }
            Err(SimulateError::Diverged(diverged)) => {
                eprintln!("error: {diverged}");
                ExitCode::from(3)
            }
            Err(SimulateError::Mismatch(message)) => {
                eprintln!("error: {message}");
                ExitCode::from(4)
            }
            // A closed pipe (`| head`) is not an error worth a message.
            Err(SimulateError::Output(error)) if error.kind() == io::ErrorKind::BrokenPipe => {
                ExitCode::SUCCESS
            }
            Err(SimulateError::Output(error)) => {
                eprintln!("error: cannot write the trajectory: {error}");
                ExitCode::FAILURE
            }
        },
        Some(Command::Report(args)) => match rubber_band_box::measure::report::run(&args) {
            Ok(()) => ExitCode::SUCCESS,
            Err(error) => {
                eprintln!("error: {error}");
                if error.is::<rubber_band_box::measure::report::BadInput>() {
                    ExitCode::from(2)
                } else {
                    ExitCode::FAILURE
                }
            }
        },
    }
}

/// The web build has no command line: it plays.
#[cfg(target_arch = "wasm32")]
fn main() -> ExitCode {
    play(PlayArgs::default())
}

fn play(args: PlayArgs) -> ExitCode {
    let mut params = SceneParams::tutorial();
    if let Some(rate) = args.step_rate {
        params.step_rate_hz = rate;
    }
    if let Err(error) = params.validate() {
        eprintln!("error: {error}");
        return ExitCode::from(2);
    }
    // A replay (native only) may start with another.
    #[cfg_attr(target_arch = "wasm32", allow(unused_mut))]
    let mut integrator = args.integrator.unwrap_or_default();
    let mut app = App::new();
    #[cfg(not(target_arch = "wasm32"))]
    if let Some(path) = args.replay {
        let replay = match rubber_band_box::replay::Replay::read_file(&path) {
            Ok(replay) => replay,
            Err(message) => {
                eprintln!("error: {message}");
                return ExitCode::from(2);
            }
        };
        app.insert_resource(rubber_band_box::game::shared::SceneName(
            replay.header.scene.clone(),
        ));
        let playback = rubber_band_box::game::replays::playback::Playback::of(replay);
        if let Some((start, recorded, auto)) = playback.start() {
            (params, integrator) = (start, recorded);
            app.insert_resource(auto);
        }
        app.insert_resource(playback);
    }
    #[cfg(not(target_arch = "wasm32"))]
    if let Some(target) = args.record {
        // Said now, not when the game ends.
        let folder = match target.parent() {
            Some(folder) if !folder.as_os_str().is_empty() => folder,
            _ => std::path::Path::new("."),
        };
        if !folder.is_dir() {
            eprintln!(
                "error: cannot record to {}: {} is not a folder",
                target.display(),
                folder.display()
            );
            return ExitCode::from(2);
        }
        app.insert_resource(rubber_band_box::game::replays::recording::Recorder::to_file(target));
        #[cfg(unix)]
        rubber_band_box::game::replays::recording::sigterm::exit_on_sigterm(&mut app);
    }
    app.insert_resource(ClearColor(Color::BLACK))
        .insert_resource(params)
        .insert_resource(integrator)
        .add_plugins(DefaultPlugins.set(WindowPlugin {
            primary_window: Some(Window {
                title: "Rubber Band Box".into(),
                resolution: (960, 720).into(),
                // On the web: draw into the page's canvas, fill its parent, keep the
                // browser's own gestures (scroll, zoom) off the canvas.
                canvas: Some("#bevy".into()),
                fit_canvas_to_parent: true,
                prevent_default_event_handling: true,
                ..default()
            }),
            ..default()
        }))
        .add_plugins((ShapePlugin, GamePlugin))
        .run();
    ExitCode::SUCCESS
}
