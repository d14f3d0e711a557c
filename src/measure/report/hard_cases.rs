//! The hard cases: stiff bands, light, spinning, far and undamped boxes, each run for every
//! integrator to see whether it stays bounded. `run` makes its table (`hard_cases.csv`);
//! `tests/integrators.rs` runs the same cases ([`hard_cases`]).

use crate::physics::{Integrator, Run, Scene};

use super::table::{Cell, Column, Table, diverged, or_empty, quoted};

/// A hard case: a scene with its overrides, the rate, and how many fixed steps.
pub struct HardCase {
    pub name: String,
    pub scene: Scene,
    pub rate: f64,
    pub steps: u64,
}

/// Builds the hard cases: the stiff band at 100 and 64 Hz over k, then the hard scenes.
///
/// `undamped` runs ten times shorter when `quick`.
pub fn hard_cases(quick: bool) -> Vec<HardCase> {
    let named = |name: &str| Scene::named(name).expect("built-in");
    let mut cases = Vec::new();
    for rate in [100.0, 64.0] {
        for k in [20.0, 1e3, 1e5, 1e7, 1e9] {
            let mut scene = named("stiff");
            scene.params.stiffness = k;
            cases.push(HardCase {
                name: format!("stiff band k = {k:e} at {rate} Hz"),
                scene,
                rate,
                steps: (10.0 * rate) as u64,
            });
        }
    }
    for (name, steps) in [
        ("light", 1000),
        ("spin", 1000),
        ("spin-band", 1000),
        ("far", 1000),
        ("zero-length", 1000),
        ("diagonal", 1000),
        ("undamped", if quick { 100_000 } else { 1_000_000 }),
    ] {
        cases.push(HardCase {
            name: format!("{name}: {}", named(name).summary),
            scene: named(name),
            rate: 100.0,
            steps,
        });
    }
    cases
}

/// Runs every hard case with each integrator.
///
/// For each case and integrator: `None` if bounded throughout, else the diverging step.
fn run_hard_cases(quick: bool) -> Vec<(HardCase, Vec<Option<u64>>)> {
    hard_cases(quick)
        .into_iter()
        .map(|case| {
            let outcomes = Integrator::ALL
                .iter()
                .map(|&integrator| {
                    let mut run = Run::of(&case.scene, integrator, 1.0 / case.rate).expect("valid");
                    run.advance_by(case.steps).err().map(|d| d.step)
                })
                .collect();
            (case, outcomes)
        })
        .collect()
}

/// Builds the hard cases' table: a line per case, one column per integrator.
///
/// The CSV has a row per case and integrator.
pub(super) fn table(quick: bool) -> Table {
    let mut table = Table::new(
        "Hard cases: bounded (ok) or diverged at step N",
        Some("hard_cases.csv"),
        vec![
            Column::new("case", "case"),
            Column::csv("rate_hz"),
            Column::new("steps", "steps"),
            Column::csv("integrator"),
            Column::new("{}", "diverged_at_step").each(),
        ],
    )
    .across(3);
    for (case, outcomes) in run_hard_cases(quick) {
        for (integrator, outcome) in Integrator::ALL.iter().zip(outcomes) {
            table.row(vec![
                Cell::new(case.name.clone(), quoted(&case.name)),
                Cell::csv(case.rate),
                Cell::same(case.steps),
                Cell::same(integrator),
                Cell::new(outcome.map_or("ok".to_owned(), diverged), or_empty(outcome)),
            ]);
        }
    }
    table
}
