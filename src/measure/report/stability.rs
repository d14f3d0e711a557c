//! The stability table: for each integrator, the largest band stiffness at which the tutorial
//! scene with the band held stays bounded, at 64 and 100 Hz. `run` makes its table
//! (`stability.csv`).

use crate::physics::scenes::TUTORIAL_PULL_TARGET;
use crate::physics::{Integrator, Run, Scene, SceneParams};

use super::table::{Cell, Column, Table};

/// Tells whether the tutorial scene with the band held at stiffness `k` stays bounded for 20 s.
fn stable_at(integrator: Integrator, k: f64, rate: f64) -> bool {
    let mut scene = Scene::named("tutorial").expect("built-in");
    scene.params.stiffness = k;
    scene.pulls = vec![(0.0, f64::INFINITY, TUTORIAL_PULL_TARGET)];
    let dt = 1.0 / rate;
    let mut run = Run::of(&scene, integrator, dt).expect("valid");
    run.advance_by((20.0 * rate) as u64).is_ok()
}

/// The stiffest band tried.
pub const STIFFEST_TRIED: f64 = 1e12;

#[derive(Clone, Debug)]
pub struct StabilityRow {
    pub integrator: Integrator,
    pub rate: f64,
    /// None: stable at every k tried, up to [`STIFFEST_TRIED`].
    pub largest_stable_k: Option<f64>,
}

impl StabilityRow {
    /// Returns ω·dt of the stiffest mode, ω = 2·sqrt(k/m), at the largest stable k.
    pub fn omega_dt(&self) -> Option<f64> {
        let mass = SceneParams::tutorial().mass;
        self.largest_stable_k
            .map(|k| 2.0 * (k / mass).sqrt() / self.rate)
    }
}

/// Steps of log10 k in the scan.
///
/// A coarse pass, then a fine one from the last coarse k that held.
const COARSE: f64 = 0.25;
const FINE: f64 = 0.01;

/// Finds the largest k, scanning upward from 1e-2, below which every k tried holds.
///
/// A coarse pass runs to the first failure, then a fine one from the last k that held to the
/// next failure. Scanning, not bisecting: above the first failure lie islands of stability
/// (the box swings onto the band's line, where the stiffest mode is half as fast), and a
/// bisection that lands in one reports a limit that a last-bit change moves by 0.4 in ω·dt.
fn largest_stable_k(integrator: Integrator, rate: f64) -> Option<f64> {
    if stable_at(integrator, STIFFEST_TRIED, rate) {
        return None;
    }
    let first_failure = |from: f64, by: f64| {
        let mut exponent = from;
        while exponent + by <= STIFFEST_TRIED.log10()
            && stable_at(integrator, 10f64.powf(exponent + by), rate)
        {
            exponent += by;
        }
        exponent
    };
    let coarse = first_failure(-2.0, COARSE);
    Some(10f64.powf(first_failure(coarse, FINE)))
}

fn stability_table() -> Vec<StabilityRow> {
    let mut rows = Vec::new();
    for rate in [64.0, 100.0] {
        for integrator in Integrator::ALL {
            let largest_stable_k = largest_stable_k(integrator, rate);
            rows.push(StabilityRow {
                integrator,
                rate,
                largest_stable_k,
            });
        }
    }
    rows
}

/// Builds the stability table: a line per integrator, k and ω·dt side by side for each rate.
///
/// The CSV has a row per rate of each integrator.
pub(super) fn table() -> Table {
    let mut table = Table::new(
        "Stability: largest stable k (tutorial scene, band held, 20 s)",
        Some("stability.csv"),
        vec![
            Column::new("integrator", "integrator"),
            Column::csv("rate_hz"),
            Column::new("k at {}", "largest_stable_k").each(),
            Column::new("omega dt", "omega_dt").each(),
        ],
    )
    .across(1);
    let rows = stability_table();
    let value = |value: Option<f64>, missing: &str| {
        Cell::new(
            value.map_or(missing.to_owned(), |v| format!("{v:.3e}")),
            value.map_or("inf".to_owned(), |v| v.to_string()),
        )
    };
    for integrator in Integrator::ALL {
        for r in rows.iter().filter(|r| r.integrator == integrator) {
            table.row(vec![
                Cell::same(integrator),
                Cell::new(format!("{} Hz", r.rate), r.rate.to_string()),
                value(r.largest_stable_k, &format!("> {STIFFEST_TRIED:e}")),
                value(r.omega_dt(), "any"),
            ]);
        }
    }
    table
}
