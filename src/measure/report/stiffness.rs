//! The stiffness sweep: every integrator on the stiff pulls from k = 20 to 1e12, judged at the
//! horizon its references resolve (`stiffness.csv`); the plots draw it (`stiffness.svg`), and
//! the engines for `auto` ([`super::engines`]) and the side-by-side (`super::peers`) run the
//! same cases.

use crate::measure::references::{StiffCase, UNRESOLVABLE_SECONDS};
use crate::measure::timing::median_ns;
use crate::physics::{Integrator, Run};

use super::table::{Cell, Column, Table, diverged};

/// One integrator on one [`StiffCase`].
#[derive(Clone, Debug)]
pub struct StiffPoint {
    pub k: f64,
    pub rate: f64,
    pub integrator: Integrator,
    pub ns_per_tick: f64,
    /// Pose error at the horizon against the case's reference.
    ///
    /// The reference is the Taylor series of order 32 at 1e-15 px. None if diverged or beyond
    /// any horizon.
    pub error: Option<f64>,
    /// Beyond any horizon: the largest (E − E0) / E0 of the undamped run (positive: it grew).
    pub energy_growth: Option<f64>,
    pub diverged_at: Option<u64>,
    pub mean_substeps: f64,
    pub mean_evaluations: f64,
    pub fallbacks: u64,
}

/// Returns the k swept, 20 to 1e12.
pub fn ks_swept(quick: bool) -> &'static [f64] {
    if quick {
        &[20.0, 1e5, 1e9]
    } else {
        &[20.0, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e12]
    }
}

/// The rates of the stiffness sweep.
pub const SWEEP_RATES: [f64; 2] = [100.0, 64.0];

/// Builds every case of the stiffness sweep, its references computed once.
pub fn stiff_cases(quick: bool) -> Vec<StiffCase> {
    SWEEP_RATES
        .iter()
        .flat_map(|&rate| {
            ks_swept(quick)
                .iter()
                .map(move |&k| StiffCase::new(k, rate))
        })
        .collect()
}

/// Runs every integrator on every case, in the cases' order.
pub(super) fn sweep(cases: &[StiffCase], quick: bool) -> Vec<StiffPoint> {
    let mut points = Vec::new();
    for case in cases {
        let scene = &case.scene;
        let mass = scene.params.mass_properties().expect("valid");
        let dt = 1.0 / case.rate;
        for integrator in Integrator::ALL {
            let fresh = || Run::of(scene, integrator, dt).expect("valid");
            let mut run = fresh();
            let e0 = run.stepper.energy();
            let (mut substeps, mut evaluations) = (0u64, 0u64);
            let mut growth = f64::NEG_INFINITY;
            let mut outcome = Ok(());
            for _ in 0..case.ticks {
                outcome = run.advance();
                if outcome.is_err() {
                    break;
                }
                substeps += u64::from(run.last_step.substeps);
                evaluations += u64::from(run.last_step.evaluations);
                growth = growth.max((run.stepper.energy() - e0) / e0);
            }
            let diverged_at = outcome.err().map(|d| d.step);
            let ns = median_ns(if quick { 3 } else { 15 }, || {
                let mut run = fresh();
                let _ = std::hint::black_box(run.advance_by(case.ticks));
            });
            let steps = run.step.max(1) as f64;
            points.push(StiffPoint {
                k: case.k,
                rate: case.rate,
                integrator,
                ns_per_tick: ns / case.ticks as f64,
                error: case
                    .reference
                    .filter(|_| diverged_at.is_none())
                    .map(|r| run.stepper.state.pose_error(&r.state, &mass)),
                energy_growth: (case.reference.is_none() && diverged_at.is_none())
                    .then_some(growth),
                diverged_at,
                mean_substeps: substeps as f64 / steps,
                mean_evaluations: evaluations as f64 / steps,
                fallbacks: run.fallbacks,
            });
        }
    }
    points
}

/// Builds the cells of a case's horizon and of its references' agreement.
///
/// They are the first two cells after k and the rate in the stiffness tables, ours and the
/// side-by-side's.
pub(super) fn horizon_cells(case: &StiffCase) -> [Cell; 2] {
    let seconds = case.seconds();
    let agreement = case.reference.map(|r| r.agreement);
    match agreement {
        Some(agreement) => [
            Cell::same(seconds),
            Cell::new(format!("{agreement:.0e}"), agreement.to_string()),
        ],
        None => [
            Cell::new(format!("{seconds} undamped"), seconds.to_string()),
            Cell::new("-", ""),
        ],
    }
}

/// Builds the cells of k and the rate, the first cells of the stiffness tables.
pub(super) fn case_cells(k: f64, rate: f64) -> [Cell; 2] {
    [
        Cell::new(format!("{k:e}"), k.to_string()),
        Cell::new(format!("{rate} Hz"), rate.to_string()),
    ]
}

/// Builds the stiffness table: a line per case, one column per integrator.
///
/// The CSV has a row per case and integrator.
pub(super) fn table(cases: &[StiffCase], points: &[StiffPoint]) -> Table {
    let mut table = Table::new(
        format!(
            "Stiffness sweep: stiff pulls from rest, each k judged at the horizon its \
             references resolve (error in px against the order-32 Taylor reference / ns per step; auto: \
             mean substeps and force evaluations per step, fall-backs). Beyond k = 1e7 no \
             horizon resolves a state: undamped for {UNRESOLVABLE_SECONDS} s, bounded or not, \
             and the largest energy growth (E - E0) / E0"
        ),
        Some("stiffness.csv"),
        vec![
            Column::new("k", "k"),
            Column::new("rate", "rate_hz"),
            Column::new("horizon (s)", "horizon_s"),
            Column::new("refs agree (px)", "references_agree_px"),
            Column::csv("integrator"),
            Column::csv("ns_per_tick"),
            Column::csv("error_px"),
            Column::csv("energy_growth"),
            Column::csv("diverged_at_step"),
            Column::csv("mean_substeps"),
            Column::csv("mean_evaluations"),
            Column::csv("fallbacks"),
            Column::markdown("{}").each(),
        ],
    )
    .across(4);
    for (case, chunk) in cases
        .iter()
        .zip(points.chunk_by(|a, b| a.k == b.k && a.rate == b.rate))
    {
        for p in chunk {
            let auto = if p.integrator == Integrator::Auto {
                format!(
                    " ({:.0}, {:.0}, {})",
                    p.mean_substeps, p.mean_evaluations, p.fallbacks
                )
            } else {
                String::new()
            };
            let outcome = match (p.error, p.energy_growth, p.diverged_at) {
                (Some(e), _, _) => format!("{e:.1e} / {:.0}{auto}", p.ns_per_tick),
                (None, Some(g), _) => format!("dE {g:+.0e} / {:.0}{auto}", p.ns_per_tick),
                (_, _, Some(s)) => diverged(s),
                _ => "?".to_owned(),
            };
            let mut cells = Vec::from(case_cells(p.k, p.rate));
            cells.extend(horizon_cells(case));
            cells.extend([
                Cell::same(p.integrator),
                Cell::csv(p.ns_per_tick),
                Cell::csv_option(p.error),
                Cell::csv_option(p.energy_growth),
                Cell::csv_option(p.diverged_at),
                Cell::csv(p.mean_substeps),
                Cell::csv(p.mean_evaluations),
                Cell::csv(p.fallbacks),
                Cell::markdown(outcome),
            ]);
            table.row(cells);
        }
    }
    table
}
