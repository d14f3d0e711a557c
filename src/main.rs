use std::io;
use std::process::ExitCode;

use bevy::prelude::*;
use bevy_prototype_lyon::prelude::ShapePlugin;
use clap::Parser;

use rubber_band_box::GamePlugin;
use rubber_band_box::cli::{Cli, Command, PlayArgs, SimulateError, simulate};
use rubber_band_box::physics::SceneParams;

fn main() -> ExitCode {
    let cli = Cli::parse();
    match cli.command {
        None => play(PlayArgs::default()),
        Some(Command::Play(args)) => play(args),
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
            // A closed pipe (`| head`) is not an error worth a message.
            Err(SimulateError::Output(error)) if error.kind() == io::ErrorKind::BrokenPipe => {
                ExitCode::SUCCESS
            }
            Err(SimulateError::Output(error)) => {
                eprintln!("error: cannot write the trajectory: {error}");
                ExitCode::FAILURE
            }
        },
        Some(Command::Report(args)) => match rubber_band_box::report::run(&args) {
            Ok(()) => ExitCode::SUCCESS,
            Err(error) => {
                eprintln!("error: {error}");
                ExitCode::FAILURE
            }
        },
    }
}

fn play(args: PlayArgs) -> ExitCode {
    let mut params = SceneParams::seed();
    if let Some(rate) = args.step_rate {
        params.step_rate_hz = rate;
    }
    App::new()
        .insert_resource(ClearColor(Color::BLACK))
        .insert_resource(params)
        .insert_resource(args.integrator.unwrap_or_default())
        .add_plugins(DefaultPlugins.set(WindowPlugin {
            primary_window: Some(Window {
                title: "Rubber Band Box".into(),
                resolution: (960, 720).into(),
                ..default()
            }),
            ..default()
        }))
        .add_plugins((ShapePlugin, GamePlugin))
        .run();
    ExitCode::SUCCESS
}
