//! The energy ledger: how well each integrator's books balance, the largest residual of the
//! energy ledger over a run relative to the energy that passed through it, on the tutorial
//! scene and the damped stiff band. `run` shows its table (Markdown only).

use crate::physics::{Integrator, Run, Scene};

use super::table::{Cell, Column, Table, diverged};

/// Returns the largest |ledger residual| over a run, relative to the energy that passed through.
///
/// If the run diverged, returns the step where it did instead.
fn ledger_residual(scene: &Scene, integrator: Integrator, steps: u64) -> Result<f64, u64> {
    let mut run = Run::of(scene, integrator, 0.01).expect("valid");
    let mut worst: f64 = 0.0;
    for _ in 0..steps {
        run.advance().map_err(|d| d.step)?;
        worst = worst.max(run.books.residual().abs());
    }
    Ok(worst / run.books.ledger.throughput())
}

/// Builds the energy ledger's table: a line per integrator, in the Markdown only.
pub(super) fn table(quick: bool) -> Table {
    let mut table = Table::new(
        "Energy ledger at 100 Hz: largest |residual| relative to the energy that passed \
         through (tutorial: 4 s; stiff, k = 1e5 with damping: 10 s)",
        None,
        vec![
            Column::markdown("integrator"),
            Column::markdown("tutorial"),
            Column::markdown("stiff"),
        ],
    );
    let tutorial = Scene::named("tutorial").expect("built-in");
    let stiff = Scene::named("stiff").expect("built-in");
    let steps = if quick { 100 } else { 1000 };
    let cell = |outcome: Result<f64, u64>| {
        Cell::markdown(match outcome {
            Ok(residual) => format!("{residual:.1e}"),
            Err(step) => diverged(step),
        })
    };
    for integrator in Integrator::ALL {
        table.row(vec![
            Cell::same(integrator),
            cell(ledger_residual(&tutorial, integrator, 400)),
            cell(ledger_residual(&stiff, integrator, steps)),
        ]);
    }
    table
}
