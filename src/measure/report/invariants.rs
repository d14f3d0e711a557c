//! The invariants of the undamped stiff band (k = 1e5, 100 Hz, 10 s): energy and angular
//! momentum about the anchor, for every integrator (the report's Markdown only).

use crate::physics::scenes::TUTORIAL_PULL_TARGET;
use crate::physics::{Integrator, Run, Scene, angular_momentum_about};

use super::table::{Cell, Column, Table, diverged};

/// Largest energy error and angular momentum change, or the step where the run diverged.
type InvariantDrift = Result<(f64, f64), u64>;

/// Measures the undamped stiff band's invariants (k = 1e5, 100 Hz, 10 s) for every integrator.
///
/// They are the largest energy error relative to the energy the band put in, and the largest
/// change of the angular momentum about the anchor.
fn stiff_invariants(quick: bool) -> Vec<(Integrator, InvariantDrift)> {
    let mut scene = Scene::named("undamped").expect("built-in");
    scene.params.stiffness = 1e5;
    let steps = if quick { 100 } else { 1000 };
    Integrator::ALL
        .iter()
        .map(|&integrator| {
            let mut run = Run::of(&scene, integrator, 0.01).expect("valid");
            let mass = run.stepper.mass;
            let e0 = run.stepper.energy();
            let l0 = angular_momentum_about(&run.stepper.state, &mass, TUTORIAL_PULL_TARGET);
            let (mut energy, mut momentum) = (0.0_f64, 0.0_f64);
            for _ in 0..steps {
                if let Err(d) = run.advance() {
                    return (integrator, Err(d.step));
                }
                energy = energy.max((run.stepper.energy() - e0).abs() / e0);
                let l = angular_momentum_about(&run.stepper.state, &mass, TUTORIAL_PULL_TARGET);
                momentum = momentum.max((l - l0).abs());
            }
            (integrator, Ok((energy, momentum)))
        })
        .collect()
}

/// Builds the invariants' table: a line per integrator, in the Markdown only.
pub(super) fn table(quick: bool) -> Table {
    let mut table = Table::new(
        "Undamped stiff band (k = 1e5, 100 Hz, 10 s): largest energy error relative to the \
         energy put in, and largest change of angular momentum about the anchor",
        None,
        vec![
            Column::markdown("integrator"),
            Column::markdown("energy"),
            Column::markdown("angular momentum"),
        ],
    );
    for (integrator, outcome) in stiff_invariants(quick) {
        let [energy, momentum] = match outcome {
            Ok((energy, momentum)) => [format!("{energy:.1e}"), format!("{momentum:.1e}")],
            Err(step) => [diverged(step), String::new()],
        };
        table.row(vec![
            Cell::same(integrator),
            Cell::markdown(energy),
            Cell::markdown(momentum),
        ]);
    }
    table
}
