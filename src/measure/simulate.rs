//! `simulate`'s runner: a scene's run or a replay stepped with the core, its trajectory
//! written as CSV (the header, row 0 for the initial state, a row per step) or, with `--hash`,
//! only the hash of the states after each step. The command line (`cli`) turns its arguments
//! into the run or the replay.

use std::io::{self, BufWriter, Write};
use std::path::Path;

use crate::physics::{AutoSettings, BodyState, Diverged, Integrator, Run};
use crate::replay::run::ReplayRun;
use crate::replay::{Replay, TrajectoryHash};

pub const CSV_HEADER: &str =
    "step,t,x,y,theta,vx,vy,omega,energy,band,substeps,fallbacks,ledger_residual";

/// One CSV row: a state and what the step that led to it did.
struct Row {
    step: u64,
    time: f64,
    state: BodyState,
    energy: f64,
    band: bool,
    substeps: u32,
    fallbacks: u64,
    residual: f64,
}

impl Row {
    fn of_run(run: &Run) -> Self {
        Self {
            step: run.step,
            time: run.time(),
            state: run.stepper.state,
            energy: run.stepper.energy(),
            band: run.stepper.band.is_some(),
            substeps: run.last_step.substeps,
            fallbacks: run.fallbacks,
            residual: run.books.residual(),
        }
    }

    fn of_replay(run: &ReplayRun) -> Self {
        Self {
            step: run.step,
            time: run.time,
            state: run.stepper.state,
            energy: run.stepper.energy(),
            band: run.stepper.band.is_some(),
            substeps: run.last_step.substeps,
            fallbacks: run.fallbacks,
            residual: run.residual(),
        }
    }
}

impl std::fmt::Display for Row {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let [x, y, theta, vx, vy, omega] = self.state.to_array();
        write!(
            f,
            "{},{},{x},{y},{theta},{vx},{vy},{omega},{},{},{},{},{}",
            self.step,
            self.time,
            self.energy,
            u8::from(self.band),
            self.substeps,
            self.fallbacks,
            self.residual,
        )
    }
}

/// Why `simulate` stopped early.
#[derive(Debug)]
pub enum SimulateError {
    Arguments(String),
    Diverged(Diverged),
    Output(io::Error),
    /// A replay run with its recorded integrators did not give the recorded states.
    Mismatch(String),
}

/// Where `simulate` writes: the CSV, or with `--hash` only a hash.
///
/// The CSV holds the header, row 0 for the initial state and a row per step; the hash is that of
/// the states after each step.
struct Output<W: Write> {
    out: BufWriter<W>,
    hash: Option<TrajectoryHash>,
}

impl<W: Write> Output<W> {
    fn new(out: W, hash: bool, initial: &Row) -> io::Result<Self> {
        let mut output = Self {
            out: BufWriter::new(out),
            hash: hash.then(TrajectoryHash::default),
        };
        if !hash {
            writeln!(output.out, "{CSV_HEADER}\n{initial}")?;
        }
        Ok(output)
    }

    /// Records the state after a step; its row is made only for the CSV.
    fn step(&mut self, state: &BodyState, row: impl FnOnce() -> Row) -> io::Result<()> {
        match self.hash.as_mut() {
            Some(hash) => {
                hash.add(state);
                Ok(())
            }
            None => writeln!(self.out, "{}", row()),
        }
    }

    fn finish(mut self) -> io::Result<()> {
        if let Some(hash) = self.hash {
            writeln!(self.out, "{hash}")?;
        }
        self.out.flush()
    }
}

/// Runs a scene for `steps` steps, written to `out` (see `Output`); a diverged step stops it.
pub fn write_run(
    mut run: Run,
    steps: u64,
    hash: bool,
    out: impl Write,
) -> Result<(), SimulateError> {
    let mut output = Output::new(out, hash, &Row::of_run(&run)).map_err(SimulateError::Output)?;
    for _ in 0..steps {
        if let Err(diverged) = run.advance() {
            output.out.flush().map_err(SimulateError::Output)?;
            return Err(SimulateError::Diverged(diverged));
        }
        output
            .step(&run.stepper.state, || Row::of_run(&run))
            .map_err(SimulateError::Output)?;
    }
    output.finish().map_err(SimulateError::Output)
}

/// A replay to step again, and how.
pub struct ReplayJob<'a> {
    pub replay: &'a Replay,
    /// Where it was read from, for the messages.
    pub path: &'a Path,
    /// Another integrator than the recorded ones.
    pub integrator: Option<Integrator>,
    /// `auto`'s settings from the recorded ones.
    pub auto: &'a dyn Fn(AutoSettings) -> AutoSettings,
    /// Whether the states must be the recorded ones (the recorded integrators and settings).
    pub check_hash: bool,
}

/// Steps the recorded game again and writes it to `out` (`simulate --replay FILE`).
pub fn write_replay(job: &ReplayJob, hash: bool, out: impl Write) -> Result<(), SimulateError> {
    let path = job.path;
    let mut run = ReplayRun::new(job.replay, job.integrator)
        .map_err(|error| SimulateError::Arguments(format!("{}: {error}", path.display())))?
        .with_auto(job.auto);
    let mut output =
        Output::new(out, hash, &Row::of_replay(&run)).map_err(SimulateError::Output)?;
    while run.advance().is_some() {
        output
            .step(&run.stepper.state, || Row::of_replay(&run))
            .map_err(SimulateError::Output)?;
    }
    output.finish().map_err(SimulateError::Output)?;
    if job.check_hash && run.hash != job.replay.hash {
        return Err(SimulateError::Mismatch(format!(
            "{}: {}",
            path.display(),
            run.explain_mismatch()
        )));
    }
    Ok(())
}
