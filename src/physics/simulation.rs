//! One box and at most one band, stepped without Bevy: what the tests, and later the CLI and
//! the benchmarks, drive directly. The ECS systems call the same functions, one set at a time.

use bevy::math::DVec2;

use super::body::{BodyState, MassProperties};
use super::forces::{BandEnds, Wrench, damping_wrench, kinetic_energy};
use super::integrate::symplectic_euler;
use super::scene::{ParamError, SceneParams};

#[derive(Clone, Debug)]
pub struct Simulation {
    pub params: SceneParams,
    pub mass: MassProperties,
    pub state: BodyState,
    pub band: Option<BandEnds>,
}

impl Simulation {
    /// The box at rest at the origin, no band.
    pub fn new(params: SceneParams) -> Result<Self, ParamError> {
        params.validate()?;
        Ok(Self {
            params,
            mass: params.mass_properties()?,
            state: BodyState::at_rest(DVec2::ZERO),
            band: None,
        })
    }

    /// Attaches the band to the corner nearest `anchor`, pulling toward `anchor`.
    pub fn grab(&mut self, anchor: DVec2) {
        self.band = Some(BandEnds {
            local_point: self.mass.nearest_corner(&self.state, anchor),
            anchor,
        });
    }

    pub fn release(&mut self) {
        self.band = None;
    }

    /// Steps 1 and 3 of the total reaction: the sum of all forces and of their torques.
    pub fn total_wrench(&self) -> Wrench {
        let p = &self.params;
        let band = self
            .band
            .map_or(Wrench::ZERO, |band| band.wrench(&self.state, p.stiffness));
        band + damping_wrench(&self.state, &self.mass, p.linear_damping, p.angular_damping)
    }

    /// One fixed step of `dt` seconds.
    pub fn step(&mut self, dt: f64) {
        let total = self.total_wrench();
        symplectic_euler(&mut self.state, &self.mass, total, dt);
    }

    /// Kinetic plus band energy.
    pub fn energy(&self) -> f64 {
        kinetic_energy(&self.state, &self.mass)
            + self.band.map_or(0.0, |band| {
                band.potential_energy(&self.state, self.params.stiffness)
            })
    }
}
