//! The speed-against-error sweep on a recorded game (`report --replay FILE`): every
//! integrator over the player's own hand, at the recorded step rate and at 2, 4, 8 and 16
//! times it. Finer rates split each recorded step into equal steps with the same band, so
//! every run feels exactly the same hand (a rate that is not a multiple would move the grabs
//! and releases). The reference is the tightest Taylor series (order 24 at 1e-15 px) at the
//! recorded rate; the error is the largest corner distance from it over the whole game.

use crate::physics::{AutoSettings, BodyState, Integrator};
use crate::replay::Replay;
use crate::replay::run::ReplayRun;
use crate::timing::median_ns;

use super::table::{Cell, Column, Table};
use super::work_precision::WorkPoint;

/// How many steps per recorded step each run takes.
pub(super) fn subdivisions(quick: bool) -> &'static [u32] {
    if quick { &[1, 4] } else { &[1, 2, 4, 8, 16] }
}

/// The reference: `auto` with its tightest series and no budget, so it never falls back.
fn reference_settings() -> AutoSettings {
    AutoSettings {
        tolerance: 1e-15,
        order: 24,
        max_substeps: u32::MAX,
    }
}

/// Every state after each recorded step and the seconds simulated, or the step where the run
/// left every bound.
fn trajectory(
    replay: &Replay,
    integrator: Integrator,
    substeps: u32,
    auto: Option<AutoSettings>,
) -> Result<(Vec<BodyState>, f64), u64> {
    let mut run = ReplayRun::new(replay, Some(integrator))
        .expect("a replay read from a file is valid")
        .subdivided(substeps);
    if let Some(auto) = auto {
        run.stepper.auto = auto;
    }
    let mut states = Vec::with_capacity(replay.steps as usize);
    while run.advance().is_some() {
        if let Some(step) = run.refused {
            return Err(step);
        }
        states.push(run.stepper.state);
    }
    Ok((states, run.time))
}

/// The reference's state after each recorded step, and the seconds simulated.
pub(super) fn reference(replay: &Replay) -> (Vec<BodyState>, f64) {
    trajectory(replay, Integrator::Auto, 1, Some(reference_settings()))
        .expect("the tightest series never leaves the bounds")
}

/// One point per integrator and rate.
pub(super) fn sweep(replay: &Replay, quick: bool) -> Vec<WorkPoint> {
    let (reference, seconds) = reference(replay);
    let mass = replay
        .header
        .settings
        .params()
        .mass_properties()
        .expect("a replay read from a file is valid");
    let mut points = Vec::new();
    for &substeps in subdivisions(quick) {
        for integrator in Integrator::ALL {
            let outcome = trajectory(replay, integrator, substeps, None);
            let error = outcome.as_ref().ok().map(|(states, _)| {
                states
                    .iter()
                    .zip(&reference)
                    .map(|(state, reference)| state.pose_error(reference, &mass))
                    .fold(0.0, f64::max)
            });
            let reps = if quick { 3 } else { 7 };
            let ns = median_ns(reps, || {
                let _ = std::hint::black_box(trajectory(replay, integrator, substeps, None));
            });
            points.push(WorkPoint {
                scene: "replay",
                integrator,
                dt: replay.header.settings.dt / f64::from(substeps),
                steps: replay.steps * u64::from(substeps),
                error,
                diverged_at: outcome.err(),
                energy_drift: None,
                ns_per_simulated_second: ns / seconds,
            });
        }
    }
    points
}

/// One column per integrator, a line per rate.
pub(super) fn table(replay: &Replay, name: &str, points: &[WorkPoint]) -> Table {
    let mut table = Table::new(
        format!(
            "Replay {name}: {} recorded steps (largest corner error over the game in px, \
             against taylor 24 at 1e-15; cost in ns per simulated second)",
            replay.steps
        ),
        Some("replay.csv"),
        vec![
            Column::csv("integrator"),
            Column::new("steps per recorded step", "substeps"),
            Column::csv("dt"),
            Column::csv("error_px"),
            Column::csv("ns_per_simulated_second"),
            Column::csv("diverged_at_step"),
            Column::markdown("{}").each(),
        ],
    )
    .across(0);
    for p in points {
        let substeps = (replay.header.settings.dt / p.dt).round();
        table.row(vec![
            Cell::same(p.integrator),
            Cell::same(substeps),
            Cell::csv(p.dt),
            Cell::csv_option(p.error),
            Cell::csv(p.ns_per_simulated_second),
            Cell::csv_option(p.diverged_at),
            Cell::markdown(p.outcome()),
        ]);
    }
    table
}
