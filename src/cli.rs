//! The command line: play (the default), `simulate` and `report`.
//!
//! Every value is checked before anything runs: a bad argument gets a message naming it and
//! exit status 2, never a panic.

use std::io::{self, Write};
use std::path::PathBuf;
use std::process::ExitCode;

use bevy::math::DVec2;
use clap::{Args, Parser, Subcommand};

use crate::game;
use crate::game::play::PlayOptions;
use crate::measure::simulate::{ReplayJob, SimulateError, write_replay, write_run};
use crate::physics::{
    AutoSettings, BodyState, Integrator, MIN_STEP, Pull, Run, STEP_RATE_RANGE, Scene, SceneParams,
};
use crate::replay::{AUTO_ORDERS, Replay};

#[derive(Parser, Debug)]
#[command(
    name = "rubber_band_box",
    version,
    about = "A 2D rigid box pulled by a rubber band. With no command, play."
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Option<Command>,
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// Open the game window (the default).
    Play(PlayArgs),
    /// Run a scene headless and write its trajectory as CSV to stdout.
    Simulate(Box<SimulateArgs>),
    /// Measure each integrator's speed against its error; print and write tables and a plot.
    Report(crate::measure::report::ReportArgs),
}

#[derive(Args, Debug, Default)]
pub struct PlayArgs {
    #[arg(long, value_parser = parse_integrator,
          help = format!("Integrator to start with (the I key cycles them): {}", integrator_help()))]
    pub integrator: Option<Integrator>,
    /// Fixed physics steps per second, from 8 to 4096 (the game's range).
    #[arg(long, value_parser = playable_step_rate)]
    pub step_rate: Option<f64>,
    /// Record the game and save it to FILE when it ends, as a replay for `simulate --replay`.
    ///
    /// The game ends when its window is closed, on Ctrl-C or on SIGTERM.
    #[arg(long, value_name = "FILE")]
    pub record: Option<PathBuf>,
    /// Play a replay back (its scene, settings and hand); a press takes over.
    #[arg(long, value_name = "FILE", conflicts_with_all = ["integrator", "step_rate"])]
    pub replay: Option<PathBuf>,
    /// Open a link (docs/links.md): a whole address, or its query and fragment.
    ///
    /// For example '?scene=stiff&integrator=rk4&ghosts=on' or '#replay=...'. What it cannot set
    /// is named on stderr and the rest is opened.
    #[arg(long, value_name = "LINK", conflicts_with_all = ["integrator", "step_rate", "replay"])]
    pub link: Option<String>,
}

#[derive(Args, Debug)]
pub struct SimulateArgs {
    // The lists in the help come from the core's tables, not a copy.
    #[arg(long, default_value = "tutorial", value_parser = parse_scene,
          help = format!("Named scene: {}", Scene::NAMES.join(", ")))]
    pub scene: Scene,
    #[arg(long, value_parser = parse_integrator, help = integrator_help())]
    pub integrator: Option<Integrator>,
    /// Fixed step in seconds, at least a microsecond.
    ///
    /// The range is wider than the game's, for convergence studies; no clock keeps a shorter step.
    #[arg(long, default_value_t = 0.01, value_parser = step, allow_hyphen_values = true)]
    pub dt: f64,
    /// Number of steps.
    #[arg(long, default_value_t = 600, allow_hyphen_values = true)]
    pub steps: u64,
    /// START:END:X,Y: the band pulls the corner nearest (X,Y) toward it for START <= step < END.
    ///
    /// Repeatable; replaces the scene's own pulls.
    #[arg(long = "pull", value_parser = parse_pull, allow_hyphen_values = true)]
    pub pulls: Vec<Pull>,
    /// Band stiffness k.
    #[arg(long, value_parser = non_negative, allow_hyphen_values = true)]
    pub k: Option<f64>,
    /// Box mass.
    #[arg(long, value_parser = positive, allow_hyphen_values = true)]
    pub mass: Option<f64>,
    /// Box width.
    #[arg(long, value_parser = positive, allow_hyphen_values = true)]
    pub width: Option<f64>,
    /// Box height.
    #[arg(long, value_parser = positive, allow_hyphen_values = true)]
    pub height: Option<f64>,
    /// Linear damping b (force −b·v).
    #[arg(long, value_parser = non_negative, allow_hyphen_values = true)]
    pub linear_damping: Option<f64>,
    /// Angular damping rate c per second.
    #[arg(long, value_parser = non_negative, allow_hyphen_values = true)]
    pub angular_damping: Option<f64>,
    #[arg(long, value_parser = positive, allow_hyphen_values = true,
          help = auto_help(AutoHelp::Tolerance))]
    pub auto_tolerance: Option<f64>,
    #[arg(long, value_parser = clap::value_parser!(u32).range(AUTO_ORDER_RANGE),
          help = auto_help(AutoHelp::Order))]
    pub auto_order: Option<u32>,
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..),
          help = auto_help(AutoHelp::MaxSubsteps))]
    pub auto_max_substeps: Option<u32>,
    /// X,Y,THETA,VX,VY,OMEGA: the initial state.
    #[arg(long, value_parser = parse_init, allow_hyphen_values = true)]
    pub init: Option<BodyState>,
    /// Step a replay file (a game the game recorded) instead of a scene.
    ///
    /// Its band, settings and resets are applied at every step. With the recorded integrators
    /// the states are the game's, to the bit (checked against the recording's hash); an
    /// integrator given runs it with that.
    #[arg(long, value_name = "FILE", conflicts_with_all = [
        "scene", "dt", "steps", "pulls", "k", "mass", "width", "height", "linear_damping",
        "angular_damping", "init",
    ])]
    pub replay: Option<PathBuf>,
    /// Print only the hash of every step's state (16 hex digits), not the trajectory.
    #[arg(long)]
    pub hash: bool,
}

impl SimulateArgs {
    /// Returns the scene's parameters with the overrides applied.
    pub fn params(&self) -> SceneParams {
        let mut params = self.scene.params;
        if let Some(k) = self.k {
            params.stiffness = k;
        }
        if let Some(mass) = self.mass {
            params.mass = mass;
        }
        if let Some(width) = self.width {
            params.size.x = width;
        }
        if let Some(height) = self.height {
            params.size.y = height;
        }
        if let Some(b) = self.linear_damping {
            params.linear_damping = b;
        }
        if let Some(c) = self.angular_damping {
            params.angular_damping = c;
        }
        params.step_rate_hz = 1.0 / self.dt;
        params
    }

    /// Returns `auto`'s settings with the overrides applied.
    pub fn auto(&self, mut auto: AutoSettings) -> AutoSettings {
        if let Some(tolerance) = self.auto_tolerance {
            auto.tolerance = tolerance;
        }
        if let Some(order) = self.auto_order {
            auto.order = order as usize;
        }
        if let Some(max) = self.auto_max_substeps {
            auto.max_substeps = max;
        }
        auto
    }

    /// Tells whether an `auto` setting is overridden.
    fn overrides_auto(&self) -> bool {
        self.auto_tolerance.is_some()
            || self.auto_order.is_some()
            || self.auto_max_substeps.is_some()
    }

    pub fn run(&self) -> Result<Run, String> {
        let pulls = if self.pulls.is_empty() {
            self.scene.pulls_in_steps(self.dt)
        } else {
            self.pulls.clone()
        };
        let mut run = Run::new(
            self.params(),
            self.init.unwrap_or(self.scene.initial),
            pulls,
            self.integrator.unwrap_or_default(),
            self.dt,
        )
        .map_err(|error| error.to_string())?;
        run.stepper.auto = self.auto(run.stepper.auto);
        Ok(run)
    }
}

/// Steps the scene or the replay the arguments name and writes its trajectory to `out`.
///
/// The `simulate` command runs it; `measure::simulate` does the work.
pub fn simulate(args: &SimulateArgs, out: impl Write) -> Result<(), SimulateError> {
    if let Some(path) = &args.replay {
        let replay = Replay::read_file(path).map_err(SimulateError::Arguments)?;
        let as_recorded = args.integrator.is_none() && !args.overrides_auto();
        let job = ReplayJob {
            replay: &replay,
            path,
            integrator: args.integrator,
            auto: &|auto| args.auto(auto),
            check_hash: as_recorded,
        };
        return write_replay(&job, args.hash, out);
    }
    let run = args.run().map_err(SimulateError::Arguments)?;
    write_run(run, args.steps, args.hash, out)
}

fn parse_number(text: &str) -> Result<f64, String> {
    let value: f64 = text
        .trim()
        .parse()
        .map_err(|_| format!("'{text}' is not a number"))?;
    if value.is_finite() {
        Ok(value)
    } else {
        Err(format!("'{text}' is not a finite number"))
    }
}

fn positive(text: &str) -> Result<f64, String> {
    let value = parse_number(text)?;
    if value > 0.0 {
        Ok(value)
    } else {
        Err(format!("must be greater than zero, got {value}"))
    }
}

/// Parses a step no shorter than [`MIN_STEP`].
fn step(text: &str) -> Result<f64, String> {
    let value = positive(text)?;
    if value >= MIN_STEP {
        Ok(value)
    } else {
        Err(format!(
            "must be at least {MIN_STEP:e} s (no clock keeps a shorter step), got {value:e}"
        ))
    }
}

/// Parses a step rate the game keeps (`physics::STEP_RATE_RANGE`).
fn playable_step_rate(text: &str) -> Result<f64, String> {
    let value = parse_number(text)?;
    if STEP_RATE_RANGE.contains(value) {
        Ok(value)
    } else {
        Err(format!("must be {STEP_RATE_RANGE}, got {value}"))
    }
}

fn non_negative(text: &str) -> Result<f64, String> {
    let value = parse_number(text)?;
    if value >= 0.0 {
        Ok(value)
    } else {
        Err(format!("must be zero or more, got {value}"))
    }
}

/// The orders `--auto-order` takes: the replay format's, the engine's.
const AUTO_ORDER_RANGE: std::ops::RangeInclusive<i64> =
    (AUTO_ORDERS.0 as i64)..=(AUTO_ORDERS.1 as i64);

/// One of `auto`'s settings, for its help line.
enum AutoHelp {
    Tolerance,
    Order,
    MaxSubsteps,
}

/// Returns the help line of one of `auto`'s settings, its default read from the core.
fn auto_help(setting: AutoHelp) -> String {
    let defaults = AutoSettings::default();
    match setting {
        AutoHelp::Tolerance => format!(
            "`auto`: target error per Taylor step (px) [default: {:e}]",
            defaults.tolerance
        ),
        AutoHelp::Order => format!(
            "`auto`: the order of its Taylor series, {} to {} [default: {}]",
            AUTO_ORDERS.0, AUTO_ORDERS.1, defaults.order
        ),
        AutoHelp::MaxSubsteps => format!(
            "`auto`: most Taylor steps per fixed step before falling back to `implicit` \
             [default: {}]",
            defaults.max_substeps
        ),
    }
}

/// Returns the integrators for the help: "euler, symplectic, ..., auto [default: auto]".
fn integrator_help() -> String {
    let names: Vec<&str> = Integrator::ALL.iter().map(|i| i.name()).collect();
    format!("{} [default: {}]", names.join(", "), Integrator::default())
}

fn parse_integrator(text: &str) -> Result<Integrator, String> {
    text.parse().map_err(|error| format!("{error}"))
}

fn parse_scene(text: &str) -> Result<Scene, String> {
    Scene::named(text).map_err(|error| error.to_string())
}

fn parse_numbers<const N: usize>(text: &str, what: &str) -> Result<[f64; N], String> {
    let parts: Vec<&str> = text.split(',').collect();
    if parts.len() != N {
        return Err(format!(
            "expected {what} ({N} numbers separated by commas), got '{text}'"
        ));
    }
    let mut values = [0.0; N];
    for (value, part) in values.iter_mut().zip(parts) {
        *value = parse_number(part)?;
    }
    Ok(values)
}

fn parse_pull(text: &str) -> Result<Pull, String> {
    let malformed = || format!("expected START:END:X,Y (for example 0:300:200,120), got '{text}'");
    let mut parts = text.splitn(3, ':');
    let (Some(start), Some(end), Some(target)) = (parts.next(), parts.next(), parts.next()) else {
        return Err(malformed());
    };
    let step = |s: &str| {
        s.trim()
            .parse::<u64>()
            .map_err(|_| format!("'{s}' is not a step number (in '{text}')"))
    };
    let (start, end) = (step(start)?, step(end)?);
    if start >= end {
        return Err(format!("the pull must end after it starts, got '{text}'"));
    }
    let [x, y] = parse_numbers::<2>(target, "X,Y")?;
    Ok(Pull {
        start,
        end,
        target: DVec2::new(x, y),
    })
}

fn parse_init(text: &str) -> Result<BodyState, String> {
    parse_numbers::<6>(text, "X,Y,THETA,VX,VY,OMEGA").map(BodyState::from_array)
}

/// Runs a parsed command line and returns its exit status.
///
/// The statuses are those docs/simulate.md gives: 2 for a bad argument or file, 3 for a
/// diverged run, 4 for a replay that stepped to other states.
pub fn run(cli: Cli) -> ExitCode {
    match cli.command {
        None => play(&PlayOptions::default()),
        Some(Command::Play(args)) => play(&PlayOptions {
            integrator: args.integrator,
            step_rate: args.step_rate,
            record: args.record,
            replay: args.replay,
            link: args.link,
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
        Some(Command::Report(args)) => match crate::measure::report::run(&args) {
            Ok(()) => ExitCode::SUCCESS,
            Err(error) => {
                eprintln!("error: {error}");
                if error.is::<crate::measure::report::BadInput>() {
                    ExitCode::from(2)
                } else {
                    ExitCode::FAILURE
                }
            }
        },
    }
}

/// Plays the game; a bad option exits 2 before any window opens.
fn play(options: &PlayOptions) -> ExitCode {
    match game::play::play(options) {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("error: {message}");
            ExitCode::from(2)
        }
    }
}
