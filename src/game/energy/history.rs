//! The energies over the last seconds of simulated time, recorded after each fixed step for
//! the graph; started over by a reset.

use std::collections::VecDeque;

use bevy::prelude::*;

use crate::game::schedule::PhysicsSystems;
use crate::game::simulation::{EnergyBooks, ResetScene};
use crate::physics::Energies;

/// Keeps the history.
pub(super) fn plugin(app: &mut App) {
    app.init_resource::<EnergyHistory>()
        .add_observer(restart_on_reset)
        .add_systems(
            FixedUpdate,
            record_energy_history.in_set(PhysicsSystems::AfterStep),
        );
}

/// The energies over the last [`EnergyHistory::SPAN`] seconds of simulated time, for the graph.
///
/// It holds at most [`EnergyHistory::SAMPLES`] samples whatever the step rate. A reset starts it
/// over.
#[derive(Resource, Debug, Default, Clone)]
pub struct EnergyHistory {
    pub samples: VecDeque<(f64, Energies)>,
}

impl EnergyHistory {
    pub const SPAN: f64 = 10.0;
    pub const SAMPLES: usize = 500;

    pub fn record(&mut self, time: f64, energies: Energies) {
        let spacing = Self::SPAN / Self::SAMPLES as f64;
        if let Some(&(last, _)) = self.samples.back() {
            if time < last {
                // The clock went back (it never does in play): start over.
                self.samples.clear();
            } else if time - last < spacing {
                return;
            }
        }
        self.samples.push_back((time, energies));
        while self
            .samples
            .front()
            .is_some_and(|&(t, _)| t < time - Self::SPAN)
        {
            self.samples.pop_front();
        }
    }
}

fn record_energy_history(
    time: Res<Time<Fixed>>,
    books: Res<EnergyBooks>,
    mut history: ResMut<EnergyHistory>,
) {
    history.record(time.elapsed_secs_f64(), books.energies);
}

fn restart_on_reset(_reset: On<ResetScene>, mut history: ResMut<EnergyHistory>) {
    history.samples.clear();
}
