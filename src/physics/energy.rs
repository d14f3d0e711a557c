//! Energy: the body's mechanical energy by kind, and the energy ledger. Built on the force
//! laws (the band's potential), never the other way round.
//!
//! The ledger: where the box's mechanical energy came from and went. With the anchor
//! fixed during a step, energy only changes by the work the hand does (attaching, moving or
//! releasing the band) and by what damping takes out; whatever else changes it is the
//! integrator's numerical error, the ledger's residual.

use super::body::{BodyState, MassProperties};
use super::forces::{BandEnds, ForceModel};

/// A body's mechanical energy by kind, in the scene's units (mass · px² / s²).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Energies {
    /// ½ m |v|².
    pub linear: f64,
    /// ½ I ω².
    pub rotational: f64,
    /// ½ k |stretch|², zero without a band.
    pub band: f64,
}

impl Energies {
    pub fn of(
        state: &BodyState,
        mass: &MassProperties,
        band: Option<&BandEnds>,
        stiffness: f64,
    ) -> Self {
        Self {
            linear: 0.5 * mass.mass() * state.linear.velocity.length_squared(),
            rotational: 0.5 * mass.inertia() * state.angular.angular_velocity.powi(2),
            band: band.map_or(0.0, |band| band.potential_energy(state, stiffness)),
        }
    }

    pub fn kinetic(&self) -> f64 {
        self.linear + self.rotational
    }

    pub fn total(&self) -> f64 {
        self.kinetic() + self.band
    }
}

impl std::ops::Add for Energies {
    type Output = Self;
    fn add(self, other: Self) -> Self {
        Self {
            linear: self.linear + other.linear,
            rotational: self.rotational + other.rotational,
            band: self.band + other.band,
        }
    }
}

impl std::iter::Sum for Energies {
    fn sum<I: Iterator<Item = Self>>(iter: I) -> Self {
        iter.fold(Self::default(), |a, b| a + b)
    }
}

/// Returns the kinetic energy, linear plus rotational: ½ m |v|² + ½ I ω².
pub fn kinetic_energy(state: &BodyState, mass: &MassProperties) -> f64 {
    Energies::of(state, mass, None, 0.0).kinetic()
}

impl ForceModel {
    /// Returns the band potential plus kinetic energy.
    pub fn energy(&self, state: &BodyState) -> f64 {
        Energies::of(state, &self.mass, self.band.as_ref(), self.stiffness).total()
    }
}

/// Energies in the scene's units (mass · px² / s²).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct EnergyLedger {
    /// Mechanical energy when the ledger started.
    pub initial: f64,
    /// Net work of the hand: the energy it put into the band less what it took away.
    ///
    /// It counts the band's energy at each attachment and anchor move, less the band's energy
    /// taken away at each release.
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

    /// Opens a step: books the hand's work since the previous one.
    ///
    /// That work is the change from `settled` (the energy right after the previous step) to
    /// `now` (the band has moved, attached or let go since); with no previous step (`None`: the
    /// start, a reset), the ledger starts at `now`.
    pub fn open_step(&mut self, settled: Option<f64>, now: f64) {
        match settled {
            Some(settled) => self.hand(now - settled),
            None => *self = Self::starting_at(now),
        }
    }

    /// Records that the hand changed the band's energy by `delta` (attach, move or release).
    pub fn hand(&mut self, delta: f64) {
        self.work_in += delta;
        self.work_moved += delta.abs();
    }

    /// Returns what the energy should be now.
    pub fn expected(&self) -> f64 {
        self.initial + self.work_in - self.dissipated
    }

    /// Returns the integrator's error: energy now minus what the ledger says it should be.
    pub fn residual(&self, energy_now: f64) -> f64 {
        energy_now - self.expected()
    }

    /// Returns all the energy that passed through: the scale to judge the residual by.
    pub fn throughput(&self) -> f64 {
        self.initial + self.work_moved + self.dissipated
    }
}
