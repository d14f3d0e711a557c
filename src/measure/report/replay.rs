//! The speed-against-error sweep on a recorded game (`report --replay FILE`): every
//! integrator over the player's own hand, at the recorded step rate and at 2, 4, 8 and 16
//! times it. Finer rates split each recorded step into equal steps with the same band, so
//! every run feels exactly the same hand (a rate that is not a multiple would move the grabs
//! and releases). The reference is the tightest Taylor series (order 32 at 1e-15 px) at the
//! recorded rate; the error is the largest corner distance from it over the whole game.

use crate::measure::references::{ReplayReference, replay_trajectory};
use crate::measure::timing::median_ns;
use crate::physics::Integrator;
use crate::replay::Replay;

use super::table::{Cell, Column, Table};
use super::work_precision::WorkPoint;

/// Returns the subdivisions: how many steps per recorded step each run takes.
pub(super) fn subdivisions(quick: bool) -> &'static [u32] {
    if quick { &[1, 4] } else { &[1, 2, 4, 8, 16] }
}

/// Runs the sweep on the recorded game: one point per integrator and rate.
pub(super) fn sweep(replay: &Replay, reference: &ReplayReference, quick: bool) -> Vec<WorkPoint> {
    let mut points = Vec::new();
    for &substeps in subdivisions(quick) {
        for integrator in Integrator::ALL {
            let outcome = replay_trajectory(replay, integrator, substeps, None);
            let error = outcome
                .as_ref()
                .ok()
                .map(|(states, _)| reference.largest_error(states));
            let reps = if quick { 3 } else { 7 };
            let ns = median_ns(reps, || {
                let _ = std::hint::black_box(replay_trajectory(replay, integrator, substeps, None));
            });
            points.push(WorkPoint {
                scene: "replay",
                integrator,
                dt: replay.header.settings.dt / f64::from(substeps),
                steps: replay.steps * u64::from(substeps),
                error,
                diverged_at: outcome.err(),
                energy_drift: None,
                ns_per_simulated_second: ns / reference.seconds,
            });
        }
    }
    points
}

/// Builds the replay's table: one column per integrator, a line per rate.
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
