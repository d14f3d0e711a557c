//! A replay stepped again with the core, exactly as the game stepped it: the same band at
//! each step, the settings and resets where the controls made them, and the core's booked
//! step, as the game takes it (a state past the playable bound refused, the replay going on).
//! With the recorded integrator it gives the game's states to the bit.

use crate::physics::{
    AutoSettings, BandEnds, BodyState, Books, Bound, Integrator, ParamError, StepInfo, Stepper,
};

use super::play::{Player, Reader};
use super::{Integrity, Replay, Settings, TrajectoryHash, made_by};

/// Where a replay first went its own way: the first check record it did not meet.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Departure {
    /// The step the check was of.
    pub step: u64,
    /// The latest check the replay met (0: the start).
    pub agreed_until: u64,
    /// The latest record that put the box or the settings in place before `step`, and its step.
    ///
    /// "a reset", "a state", "settings"; None: only steps since the last agreement.
    pub after: Option<(&'static str, u64)>,
    /// The largest difference of a component, relative to the component's size (at least 1).
    pub relative: f64,
}

pub struct ReplayRun<'a> {
    replay: &'a Replay,
    /// How far the records are read.
    reader: Reader,
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
    /// The energy books (started over at a reset).
    pub books: Books,
    pub hash: TrajectoryHash,
    /// Steps of the integrator per recorded step (1: as the game stepped).
    substeps: u32,
    /// The first check record the run did not meet, if any.
    ///
    /// Only a run as recorded is checked: the recorded integrators, one step a recorded step.
    pub departure: Option<Departure>,
    agreed_until: u64,
    /// The latest record that put the box or the settings in place.
    latest_change: Option<(&'static str, u64)>,
    /// `auto`'s settings made from the recorded ones (`simulate --auto-order`, say).
    auto_from: Option<&'a dyn Fn(AutoSettings) -> AutoSettings>,
    /// `auto`'s settings as recorded, in force now.
    recorded_auto: AutoSettings,
}

impl<'a> ReplayRun<'a> {
    pub fn new(replay: &'a Replay, integrator: Option<Integrator>) -> Result<Self, ParamError> {
        let mut stepper = replay.stepper()?;
        if let Some(integrator) = integrator {
            stepper.integrator = integrator;
        }
        Ok(Self {
            replay,
            reader: Reader::default(),
            integrator,
            dt: replay.header.settings.dt,
            stepper,
            step: 0,
            time: 0.0,
            last_step: StepInfo::SINGLE,
            fallbacks: 0,
            refused: None,
            books: Books::default(),
            hash: TrajectoryHash::default(),
            substeps: 1,
            departure: None,
            agreed_until: 0,
            latest_change: None,
            auto_from: None,
            recorded_auto: replay.header.auto.into(),
        })
    }

    /// Steps with `auto`'s settings made from the recorded ones by `from`.
    ///
    /// They are made at the start and at every auto record.
    pub fn with_auto(mut self, from: &'a dyn Fn(AutoSettings) -> AutoSettings) -> Self {
        self.stepper.auto = from(self.stepper.auto);
        self.auto_from = Some(from);
        self
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
        let mut reader = self.reader;
        let band = reader.next_step(self.replay, self);
        self.reader = reader;
        Some(self.step_under(band?))
    }

    /// Takes one step as the game's fixed step takes it: the core's booked step.
    ///
    /// A state past the playable bound is refused, as the game refuses it.
    ///
    /// A step split into parts is that many booked steps under the same band.
    fn step_under(&mut self, band: Option<BandEnds>) -> StepInfo {
        self.stepper.band = band;
        let part = self.dt / f64::from(self.substeps);
        let mut info = StepInfo::default();
        for _ in 0..self.substeps {
            let booked = self.books.step(&mut self.stepper, part, Bound::Playable);
            info.substeps += booked.info.substeps;
            info.evaluations += booked.info.evaluations;
            info.fell_back |= booked.info.fell_back;
            info.dissipated += booked.info.dissipated;
            if booked.refused {
                self.refused = Some(self.step + 1);
            }
        }
        self.fallbacks += u64::from(info.fell_back);
        self.step += 1;
        self.time += self.dt;
        self.last_step = info;
        self.hash.add(&self.stepper.state);
        info
    }

    /// Compares the state with a check record, and notes the first one it does not meet.
    ///
    /// Only a run as recorded can meet them: another integrator or substeps go their own way.
    fn check_against(&mut self, step: u64, recorded: &[f64; 6]) {
        let as_recorded = self.integrator.is_none()
            && self.substeps == 1
            && self.stepper.auto == self.recorded_auto;
        if !as_recorded || self.departure.is_some() {
            return;
        }
        let now = self.stepper.state.to_array();
        if now.map(f64::to_bits) == recorded.map(f64::to_bits) {
            self.agreed_until = step;
            return;
        }
        let relative = now
            .iter()
            .zip(recorded)
            .map(|(a, b)| (a - b).abs() / a.abs().max(b.abs()).max(1.0))
            .fold(0.0, f64::max);
        self.departure = Some(Departure {
            step,
            agreed_until: self.agreed_until,
            after: self
                .latest_change
                .filter(|&(_, changed)| changed > self.agreed_until),
            relative,
        });
    }

    /// Says why the run did not reach the recorded hash, for a replay that did not.
    ///
    /// Only a file read back as written, made by another version or platform, can blame the
    /// build or the machine; a file whose own records contradict each other says where.
    pub fn explain_mismatch(&self) -> String {
        let replay = self.replay;
        let states = format!(
            "the states differ from the recorded game's (hash {}, recorded {})",
            self.hash, replay.hash
        );
        if replay.integrity == Integrity::Changed {
            return format!(
                "{states}: the file was changed after it was written (its lines do not hash to \
                 its end record's `lines`)"
            );
        }
        let made_here = replay.header.made_by.as_deref() == Some(made_by().as_str());
        let where_ = match self.departure {
            Some(departure) => {
                let after = departure
                    .after
                    .map(|(what, step)| format!(", after {what} before step {step}"))
                    .unwrap_or_default();
                format!(
                    "; they first differ at step {} (the recorded states held to step {}{after}, \
                     by {:.1e} of a component)",
                    departure.step, departure.agreed_until, departure.relative
                )
            }
            None => String::new(),
        };
        // A jump, not a drift of the last bits: the record before it does not hold the game.
        let jumped = self
            .departure
            .is_some_and(|departure| departure.after.is_some() && departure.relative > 1e-6);
        if made_here || jumped {
            let culprit = match self.departure.and_then(|departure| departure.after) {
                Some(("a reset", step)) if jumped => {
                    format!("a reset before step {step} does not put the box where the game had it")
                }
                Some((what, step)) if jumped => format!(
                    "from step {step} (where {what} record stands) the box is not where the game \
                     had it"
                ),
                _ => "the records do not hold the game that was played".to_owned(),
            };
            let maker = if made_here {
                format!(
                    " (written by this version on this platform, {}, which steps the same \
                     every time)",
                    made_by()
                )
            } else {
                String::new()
            };
            return format!(
                "{states}{where_}: the file's own records contradict each other: {culprit}{maker}"
            );
        }
        let maker = replay
            .header
            .made_by
            .as_deref()
            .map_or("an earlier build (format version 1)".to_owned(), |by| {
                format!("version {by}")
            });
        format!(
            "{states}{where_}: the file was written by {maker}; this build ({}) or this machine \
             computes the steps differently",
            made_by()
        )
    }

    /// Returns the ledger's residual after the latest step: the integrator's energy error.
    pub fn residual(&self) -> f64 {
        self.books.residual()
    }

    /// Plays every remaining step and returns the hash of all the states.
    pub fn finish(&mut self) -> TrajectoryHash {
        while self.advance().is_some() {}
        self.hash
    }
}

/// What the records put in place, in the run's stepper.
impl Player for ReplayRun<'_> {
    fn reset(&mut self, start: BodyState, step: u64) {
        self.stepper.state = start;
        self.stepper.band = None;
        self.books.settled = None;
        self.refused = None;
        self.fallbacks = 0;
        self.latest_change = Some(("a reset", step));
    }

    fn settings(&mut self, settings: &Settings, step: u64) {
        // Checked when the file was read.
        if let Ok(mass) = settings.params().mass_properties() {
            self.stepper.mass = mass;
        }
        self.stepper.params = settings.params();
        self.stepper.integrator = self.integrator.unwrap_or(settings.integrator);
        self.dt = settings.dt;
        self.latest_change = Some(("settings", step));
    }

    fn auto(&mut self, auto: AutoSettings, _step: u64) {
        self.recorded_auto = auto;
        self.stepper.auto = match &self.auto_from {
            Some(from) => from(auto),
            None => auto,
        };
    }

    fn state(&mut self, state: BodyState, step: u64) {
        self.stepper.state = state;
        self.latest_change = Some(("a state", step));
    }

    fn check(&mut self, step: u64, state: &[f64; 6]) {
        self.check_against(step, state);
    }
}
