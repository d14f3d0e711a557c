//! One box and at most one band, stepped without Bevy, and the one booked step: the step with
//! its energy books kept and a state past its caller's bound refused. The game's step system,
//! the ghosts, a replay's run and the scripted runs ([`super::Run`], so the CLI and the report)
//! all take [`Books::step`]; the tests and the benchmarks drive the stepper directly.

use bevy::math::DVec2;

use super::body::{BodyState, MassProperties};
use super::energy::{Energies, EnergyLedger};
use super::forces::{BandEnds, ForceModel, Forces};
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
        let start = self.model().forces(&self.state);
        self.step_from(start, dt)
    }

    /// Advances the box one step of `dt` seconds from `start`, the forces at the state now.
    ///
    /// The game's step accumulates them on the box's components first.
    pub fn step_from(&mut self, start: Forces, dt: f64) -> StepInfo {
        let model = self.model();
        self.integrator
            .step_with(&mut self.state, &model, start, dt, &self.auto)
    }

    /// Returns the kinetic plus band energy.
    pub fn energy(&self) -> f64 {
        self.energies().total()
    }

    /// Returns the energies by kind: linear, rotational and the band's.
    pub fn energies(&self) -> Energies {
        Energies::of(
            &self.state,
            &self.mass,
            self.band.as_ref(),
            self.params.stiffness,
        )
    }
}

/// The bound a booked step keeps the state in: past it, the step is refused.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Bound {
    /// Finite, every component within 1e12 ([`BodyState::is_sane`]).
    ///
    /// The ghosts and the scripted runs keep it.
    Sane,
    /// Sane, and the centre within 1e7 px ([`BodyState::is_playable`]).
    ///
    /// The game keeps it, and so does a replay's run, which steps as the game stepped.
    Playable,
}

impl Bound {
    pub fn holds(self, state: &BodyState) -> bool {
        match self {
            Self::Sane => state.is_sane(),
            Self::Playable => state.is_playable(),
        }
    }
}

/// A stepper's energy books: where its mechanical energy came from and went.
///
/// Between two steps only the hand changes the energy (attaching, moving or releasing the band,
/// changing k), so whatever the energy did between the end of one step and the start of the next
/// is booked as the hand's work; damping's share comes from the integrator. The residual is the
/// integrator's error.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Books {
    pub ledger: EnergyLedger,
    /// Mechanical energy right after the latest step.
    ///
    /// None at the start and after a reset: the next step starts the ledger over.
    pub settled: Option<f64>,
}

/// What a booked step did: the integrator's account, and whether the state was refused.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Booked {
    pub info: StepInfo,
    /// The step left the bound: the state is the one before it, and damping's share unbooked.
    pub refused: bool,
    /// The energies by kind of the state kept, which the books settled at.
    pub energies: Energies,
}

impl Books {
    /// Starts the books at `energy`, as if a step had just settled there.
    pub fn starting_at(energy: f64) -> Self {
        Self {
            ledger: EnergyLedger::starting_at(energy),
            settled: Some(energy),
        }
    }

    /// Takes `stepper`'s next step of `dt`, booked, from the forces at its state now.
    ///
    /// It books the hand's work since the latest step, then steps. A state outside `bound` is
    /// refused: the stepper keeps the state before, and damping's share is not booked. Either
    /// way the step settles at the energy of the state kept.
    pub fn step(&mut self, stepper: &mut Stepper, dt: f64, bound: Bound) -> Booked {
        let start = stepper.model().forces(&stepper.state);
        self.step_accumulated(stepper, start, dt, bound)
    }

    /// Takes the step [`Books::step`] takes, from `start`: the forces accumulated at the state now.
    ///
    /// The game's step accumulates them on the box's components first.
    pub fn step_accumulated(
        &mut self,
        stepper: &mut Stepper,
        start: Forces,
        dt: f64,
        bound: Bound,
    ) -> Booked {
        self.ledger.open_step(self.settled, stepper.energy());
        let before = stepper.state;
        let info = stepper.step_from(start, dt);
        let refused = !bound.holds(&stepper.state);
        if refused {
            stepper.state = before;
        } else {
            self.ledger.dissipated += info.dissipated;
        }
        let energies = stepper.energies();
        self.settled = Some(energies.total());
        Booked {
            info,
            refused,
            energies,
        }
    }

    /// Returns the ledger's residual after the latest step: the integrator's energy error.
    ///
    /// The hand's work since is booked by the next step. 0 before the first step.
    pub fn residual(&self) -> f64 {
        self.settled
            .map_or(0.0, |energy| self.ledger.residual(energy))
    }
}
