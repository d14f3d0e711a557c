//! One box and at most one band, stepped without Bevy: what scripted runs ([`super::Run`],
//! so the CLI and the report), the tests and the benchmarks drive directly. The game's step
//! system calls the same force model and integrators over the box's components.

use bevy::math::DVec2;

use super::body::{BodyState, MassProperties};
use super::forces::{BandEnds, ForceModel};
use super::integrators::Integrator;
use super::integrators::{AutoSettings, StepInfo};
use super::param_error::ParamError;
use super::scene::SceneParams;

#[derive(Clone, Debug)]
pub struct Stepper {
    pub params: SceneParams,
    pub mass: MassProperties,
    pub state: BodyState,
    pub band: Option<BandEnds>,
    pub integrator: Integrator,
    pub auto: AutoSettings,
}

impl Stepper {
    /// Builds a stepper with the box at rest at the origin and no band.
    pub fn new(params: SceneParams) -> Result<Self, ParamError> {
        params.validate()?;
        Ok(Self {
            params,
            mass: params.mass_properties()?,
            state: BodyState::at_rest(DVec2::ZERO),
            band: None,
            integrator: Integrator::default(),
            auto: AutoSettings::default(),
        })
    }

    /// Attaches the band to the corner nearest `anchor`, pulling toward `anchor`.
    pub fn grab(&mut self, anchor: DVec2) {
        self.band = Some(BandEnds::grabbing(&self.mass, &self.state, anchor));
    }

    pub fn release(&mut self) {
        self.band = None;
    }

    /// Returns every force law acting on the box now.
    pub fn model(&self) -> ForceModel {
        self.params.force_model(self.mass, self.band)
    }

    /// Advances the box one step of `dt` seconds with the chosen integrator.
    pub fn step(&mut self, dt: f64) -> StepInfo {
        let model = self.model();
        let start = model.forces(&self.state);
        self.integrator
            .step_with(&mut self.state, &model, start, dt, &self.auto)
    }

    /// Returns the kinetic plus band energy.
    pub fn energy(&self) -> f64 {
        self.model().energy(&self.state)
    }
}
