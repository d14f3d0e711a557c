//! A replay stepped again with the core, exactly as the game stepped it: the same band at
//! each step, the settings and resets where the controls made them, a step that would leave
//! the state not sane refused (the state kept, the replay going on), and the energy books kept
//! as the game keeps them. With the recorded integrator it gives the game's states to the bit.

use crate::physics::{
    BandEnds, BodyState, EnergyLedger, Integrator, ParamError, StepInfo, Stepper,
};

use super::{Record, Replay, TrajectoryHash};

pub struct ReplayRun<'a> {
    replay: &'a Replay,
    /// The next record to play.
    next: usize,
    /// Runs the whole replay with this integrator instead of the recorded ones.
    integrator: Option<Integrator>,
    pub stepper: Stepper,
    pub dt: f64,
    /// Steps taken so far.
    pub step: u64,
    /// Simulated time: the sum of the steps taken.
    pub time: f64,
    pub last_step: StepInfo,
    pub fallbacks: u64,
    /// The latest step refused because its state was not sane, if any.
    pub refused: Option<u64>,
    pub ledger: EnergyLedger,
    /// Mechanical energy right after the latest step (None at the start and after a reset).
    settled: Option<f64>,
    pub hash: TrajectoryHash,
    /// Steps of the integrator per recorded step (1: as the game stepped).
    substeps: u32,
}

impl<'a> ReplayRun<'a> {
    pub fn new(replay: &'a Replay, integrator: Option<Integrator>) -> Result<Self, ParamError> {
        let mut stepper = replay.stepper()?;
        if let Some(integrator) = integrator {
            stepper.integrator = integrator;
        }
        Ok(Self {
            replay,
            next: 0,
            integrator,
            dt: replay.header.settings.dt,
            stepper,
            step: 0,
            time: 0.0,
            last_step: StepInfo::SINGLE,
            fallbacks: 0,
            refused: None,
            ledger: EnergyLedger::default(),
            settled: None,
            hash: TrajectoryHash::default(),
            substeps: 1,
        })
    }

    /// Splits each recorded step into `substeps` equal steps with the same band.
    ///
    /// The hand is the same, at a step rate that many times the recorded one (the report's
    /// sweep).
    pub fn subdivided(mut self, substeps: u32) -> Self {
        self.substeps = substeps.max(1);
        self
    }

    /// Plays the records up to and including the next step; `None` after the last.
    pub fn advance(&mut self) -> Option<StepInfo> {
        loop {
            let record = self.replay.records.get(self.next)?;
            self.next += 1;
            match record {
                Record::Reset { .. } => {
                    self.stepper.state = BodyState::from_array(self.replay.header.initial);
                    self.stepper.band = None;
                    self.settled = None;
                    self.refused = None;
                    self.fallbacks = 0;
                }
                Record::Settings { settings, .. } => {
                    // Checked when the file was read.
                    if let Ok(mass) = settings.params().mass_properties() {
                        self.stepper.mass = mass;
                    }
                    self.stepper.params = settings.params();
                    self.stepper.integrator = self.integrator.unwrap_or(settings.integrator);
                    self.dt = settings.dt;
                }
                Record::Step { band, .. } => {
                    return Some(self.step_with(band.map(BandEnds::from)));
                }
                Record::End { .. } => return None,
            }
        }
    }

    /// Takes one step as the game's fixed step takes it.
    fn step_with(&mut self, band: Option<BandEnds>) -> StepInfo {
        self.stepper.band = band;
        self.ledger.open_step(self.settled, self.stepper.energy());
        let before = self.stepper.state;
        let step = self.dt / f64::from(self.substeps);
        let mut info = StepInfo::default();
        for _ in 0..self.substeps {
            let taken = self.stepper.step(step);
            info.substeps += taken.substeps;
            info.evaluations += taken.evaluations;
            info.fell_back |= taken.fell_back;
            info.dissipated += taken.dissipated;
        }
        self.fallbacks += u64::from(info.fell_back);
        self.step += 1;
        self.time += self.dt;
        if self.stepper.state.is_sane() {
            self.ledger.dissipated += info.dissipated;
        } else {
            self.stepper.state = before;
            self.refused = Some(self.step);
        }
        self.last_step = info;
        self.settled = Some(self.stepper.energy());
        self.hash.add(&self.stepper.state);
        info
    }

    /// Returns the ledger's residual after the latest step: the integrator's energy error.
    pub fn residual(&self) -> f64 {
        self.ledger.residual(self.stepper.energy())
    }

    /// Plays every remaining step and returns the hash of all the states.
    pub fn finish(&mut self) -> TrajectoryHash {
        while self.advance().is_some() {}
        self.hash
    }
}
