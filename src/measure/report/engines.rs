//! The engines `auto` could step with, compared on the stiff pulls at 100 Hz (`engines.csv`):
//! each candidate at several settings, restarted at every fixed step as the game runs it.

use crate::measure::references::{Engine, StiffCase, run_engine};
use crate::measure::timing::median_ns;

use super::table::{Cell, Column, Table, or_empty};

/// The engine comparison: each candidate at several settings on the stiff pulls at 100 Hz.
///
/// Error at the horizon against the reference, cost per fixed step of the core alone.
pub struct EnginePoint {
    pub k: f64,
    pub engine: Engine,
    pub error: Option<f64>,
    pub ns_per_tick: f64,
    pub evaluations_per_tick: f64,
}

fn engines_compared(cases: &[StiffCase], quick: bool) -> Vec<EnginePoint> {
    let engines: Vec<Engine> = if quick {
        vec![
            Engine::Rk4(100),
            Engine::Dop853(1e-9),
            Engine::Taylor(20, 1e-9),
        ]
    } else {
        let mut all: Vec<Engine> = [25, 100, 400, 1600].map(Engine::Rk4).to_vec();
        all.extend([1e-8, 1e-9, 1e-10, 1e-11].map(Engine::Dop853));
        for order in [16, 20, 24, 28, 32] {
            all.extend([1e-9, 1e-10, 3e-11, 1e-11].map(|t| Engine::Taylor(order, t)));
        }
        all
    };
    let mut points = Vec::new();
    for case in cases.iter().filter(|c| c.rate == 100.0 && c.k >= 1e3) {
        let Some(reference) = case.reference else {
            continue;
        };
        let mass = case.scene.params.mass_properties().expect("valid");
        for &engine in &engines {
            let outcome = run_engine(&case.scene, case.rate, case.ticks, engine);
            let ns = median_ns(if quick { 1 } else { 5 }, || {
                std::hint::black_box(run_engine(&case.scene, case.rate, case.ticks, engine));
            });
            points.push(EnginePoint {
                k: case.k,
                engine,
                error: outcome.map(|(state, _)| state.pose_error(&reference.state, &mass)),
                ns_per_tick: ns / case.ticks as f64,
                evaluations_per_tick: outcome.map_or(0.0, |o| o.1),
            });
        }
    }
    points
}

/// Builds the engine comparison's table: a line per case and engine.
pub(super) fn table(cases: &[StiffCase], quick: bool) -> Table {
    let mut table = Table::new(
        "Engines for auto: candidates on the stiff pulls at 100 Hz, restarted every fixed \
         step (error in px at the horizon against the reference; ns per fixed step of the core \
         alone; force evaluations per fixed step, for Taylor series coefficient orders)",
        Some("engines.csv"),
        vec![
            Column::new("k", "k"),
            Column::new("engine", "engine"),
            Column::new("error", "error_px"),
            Column::new("ns per step", "ns_per_tick"),
            Column::new("evaluations", "evaluations_per_tick"),
        ],
    );
    for p in engines_compared(cases, quick) {
        table.row(vec![
            Cell::new(format!("{:e}", p.k), p.k.to_string()),
            Cell::same(p.engine.name()),
            Cell::new(
                p.error.map_or("gave up".to_owned(), |e| format!("{e:.1e}")),
                or_empty(p.error),
            ),
            Cell::new(format!("{:.0}", p.ns_per_tick), p.ns_per_tick.to_string()),
            Cell::new(
                format!("{:.0}", p.evaluations_per_tick),
                p.evaluations_per_tick.to_string(),
            ),
        ]);
    }
    table
}
