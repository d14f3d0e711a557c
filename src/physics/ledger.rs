//! The energy ledger: where the box's mechanical energy came from and went. With the anchor
//! fixed during a step, energy only changes by the work the hand does (attaching, moving or
//! releasing the band) and by what damping takes out; whatever else changes it is the
//! integrator's numerical error, the ledger's residual.

/// Energies in the scene's units (mass · px² / s²).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct EnergyLedger {
    /// Mechanical energy when the ledger started.
    pub initial: f64,
    /// Net work of the hand: the band's energy at each attachment and anchor move, less the
    /// band's energy taken away at each release.
    pub work_in: f64,
    /// The same without the signs: all the energy the hand moved in or out.
    pub work_moved: f64,
    /// Energy damping took out (never negative).
    pub dissipated: f64,
}

impl EnergyLedger {
    pub fn starting_at(energy: f64) -> Self {
        Self {
            initial: energy,
            ..Self::default()
        }
    }

    /// The hand changed the band's energy by `delta` (attach, move or release).
    pub fn hand(&mut self, delta: f64) {
        self.work_in += delta;
        self.work_moved += delta.abs();
    }

    /// What the energy should be now.
    pub fn expected(&self) -> f64 {
        self.initial + self.work_in - self.dissipated
    }

    /// The integrator's error: energy now minus what the ledger says it should be.
    pub fn residual(&self, energy_now: f64) -> f64 {
        energy_now - self.expected()
    }

    /// All the energy that passed through: the scale to judge the residual by.
    pub fn throughput(&self) -> f64 {
        self.initial + self.work_moved + self.dissipated
    }
}
