//! The work-precision sweep: every integrator on every work scene over a range of steps, its
//! final pose error against the scene's reference and its cost. `run` makes its table
//! (`work_precision.csv`); the plots draw its points (`work_precision.svg`).

use crate::measure::references::{work_reference, work_scenes};
use crate::measure::timing::median_ns;
use crate::physics::{Integrator, Run};

use super::table::{Cell, Column, Table, diverged};

/// Returns the steps swept, from 1/30 s to 1/10000 s.
fn steps_swept(quick: bool) -> Vec<f64> {
    let rates: &[f64] = if quick {
        &[30.0, 100.0, 1000.0]
    } else {
        &[30.0, 64.0, 100.0, 300.0, 1000.0, 3000.0, 10000.0]
    };
    rates.iter().map(|rate| 1.0 / rate).collect()
}

/// One integrator on one work scene at one step.
#[derive(Clone, Debug)]
pub struct WorkPoint {
    pub scene: &'static str,
    pub integrator: Integrator,
    pub dt: f64,
    pub steps: u64,
    /// None where the run diverged.
    pub error: Option<f64>,
    pub diverged_at: Option<u64>,
    pub energy_drift: Option<f64>,
    pub ns_per_simulated_second: f64,
}

impl WorkPoint {
    /// Formats the Markdown cell: "error, dE drift / cost", or where it diverged.
    pub(super) fn outcome(&self) -> String {
        match (self.error, self.diverged_at) {
            (Some(error), _) => {
                let drift = self
                    .energy_drift
                    .map_or(String::new(), |d| format!(", dE {d:.1e}"));
                format!("{error:.1e}{drift} / {:.0}", self.ns_per_simulated_second)
            }
            (None, Some(step)) => diverged(step),
            (None, None) => "?".to_owned(),
        }
    }
}

/// Runs the sweep over every work scene, step and integrator, in that order.
pub(super) fn sweep(quick: bool) -> Vec<WorkPoint> {
    let mut points = Vec::new();
    for work in work_scenes() {
        let name = work.scene.name;
        let mass = work.scene.params.mass_properties().expect("valid");
        for dt in steps_swept(quick) {
            let steps = (work.horizon / dt).round() as u64;
            let t = steps as f64 * dt;
            let reference = work_reference(&work, t);
            for integrator in Integrator::ALL {
                let fresh = || Run::of(&work.scene, integrator, dt).expect("valid");
                let mut run = fresh();
                let mut energy_drift: f64 = 0.0;
                let e0 = run.stepper.energy();
                let mut outcome = Ok(());
                for _ in 0..steps {
                    outcome = run.advance();
                    if outcome.is_err() {
                        break;
                    }
                    energy_drift = energy_drift.max((run.stepper.energy() - e0).abs() / e0);
                }
                let diverged_at = outcome.err().map(|d| d.step);
                let reps = if quick { 3 } else { 7 };
                let ns = median_ns(reps, || {
                    let mut run = fresh();
                    let _ = std::hint::black_box(run.advance_by(steps));
                });
                points.push(WorkPoint {
                    scene: name,
                    integrator,
                    dt,
                    steps,
                    error: diverged_at
                        .is_none()
                        .then(|| run.stepper.state.pose_error(&reference, &mass)),
                    diverged_at,
                    energy_drift: (work.energy_invariant && diverged_at.is_none())
                        .then_some(energy_drift),
                    ns_per_simulated_second: ns / t,
                });
            }
        }
    }
    points
}

/// Builds the work-precision table: one column per integrator, a line per scene and step.
///
/// The CSV has a row per point.
pub(super) fn table(points: &[WorkPoint]) -> Table {
    let mut table = Table::new(
        "Work-precision (final pose error in px; cost in ns per simulated second)",
        Some("work_precision.csv"),
        vec![
            Column::new("scene", "scene"),
            Column::csv("integrator"),
            Column::new("dt (s)", "dt"),
            Column::csv("steps"),
            Column::csv("error_px"),
            Column::csv("energy_drift"),
            Column::csv("ns_per_simulated_second"),
            Column::csv("diverged_at_step"),
            Column::markdown("{}").each(),
        ],
    )
    .across(1);
    for p in points {
        table.row(vec![
            Cell::same(p.scene),
            Cell::same(p.integrator),
            Cell::new(format!("1/{:.0}", 1.0 / p.dt), p.dt.to_string()),
            Cell::csv(p.steps),
            Cell::csv_option(p.error),
            Cell::csv_option(p.energy_drift),
            Cell::csv(p.ns_per_simulated_second),
            Cell::csv_option(p.diverged_at),
            Cell::markdown(p.outcome()),
        ]);
    }
    table
}
