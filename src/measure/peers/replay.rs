//! A recorded game on a contender (`report --replay FILE --peers`): each recorded step taken
//! as one or more fixed steps with the recorded band. The peers cannot change a scene's
//! parameters in place, so a settings change builds the contender again from the state it
//! had, a reset from the replay's start and a state record from that state; a change of
//! integrator alone changes nothing for them.

use std::time::Instant;

use super::Contender;
use super::avian::Avian;
use super::ours::Ours;
use super::rapier::Rapier;
use crate::measure::references::ReplayReference;
use crate::measure::timing::median;
use crate::physics::{AutoSettings, BandEnds, BodyState};
use crate::replay::play::{Player, Reader};
use crate::replay::{Replay, Settings};

/// A replay played on contender `C`.
pub struct PeerReplay<'a, C: Contender> {
    replay: &'a Replay,
    /// How far the records are read.
    reader: Reader,
    settings: Settings,
    substeps: u32,
    contender: C,
    band: Option<BandEnds>,
}

impl<'a, C: Contender> PeerReplay<'a, C> {
    /// Starts the replay on `C`, taking each recorded step as `substeps` fixed steps.
    pub fn new(replay: &'a Replay, substeps: u32) -> Self {
        let settings = replay.header.settings;
        let substeps = substeps.max(1);
        Self {
            replay,
            reader: Reader::default(),
            settings,
            substeps,
            contender: build(
                &settings,
                substeps,
                BodyState::from_array(replay.header.initial),
            ),
            band: None,
        }
    }

    /// Plays the records up to and including the next step; `None` after the last.
    pub fn advance(&mut self) -> Option<()> {
        let mut reader = self.reader;
        let band = reader.next_step(self.replay, self);
        self.reader = reader;
        let band = band?;
        if band != self.band {
            self.band = band;
            self.contender.set_band(band);
        }
        for _ in 0..self.substeps {
            self.contender.app().update();
        }
        // Read after every step: peers that keep (cos, sin) count whole turns.
        self.contender.state();
        Some(())
    }

    pub fn state(&mut self) -> BodyState {
        self.contender.state()
    }
}

/// What the records put in place, on the contender.
///
/// `auto`'s settings and the recorder's checks are nothing for a peer.
impl<C: Contender> Player for PeerReplay<'_, C> {
    fn reset(&mut self, start: BodyState, _step: u64) {
        self.contender = build(&self.settings, self.substeps, start);
        self.band = None;
    }

    fn settings(&mut self, settings: &Settings, _step: u64) {
        let integrator = settings.integrator;
        let changed = Settings {
            integrator,
            ..self.settings
        } != *settings;
        self.settings = *settings;
        if changed {
            let now = self.contender.state();
            self.contender = build(&self.settings, self.substeps, now);
            self.contender.set_band(self.band);
        }
    }

    fn auto(&mut self, _auto: AutoSettings, _step: u64) {}

    fn state(&mut self, state: BodyState, _step: u64) {
        self.contender = build(&self.settings, self.substeps, state);
        self.contender.set_band(self.band);
    }
}

fn build<C: Contender>(settings: &Settings, substeps: u32, state: BodyState) -> C {
    C::new(&settings.params(), state, f64::from(substeps) / settings.dt)
}

/// One contender on a replay at one subdivision.
#[derive(Clone, Debug)]
pub struct PeerReplayPoint {
    pub contender: &'static str,
    pub substeps: u32,
    /// The largest corner distance from the reference over the game (px).
    ///
    /// None if a state went non-finite.
    pub error: Option<f64>,
    /// Wall time per simulated second of the whole replay, building the `App`s included.
    ///
    /// A settings change costs a peer that much in a game too.
    pub ns_per_simulated_second: f64,
}

fn point<C: Contender>(
    replay: &Replay,
    substeps: u32,
    reference: &ReplayReference,
    reps: usize,
) -> PeerReplayPoint {
    let mut run = PeerReplay::<C>::new(replay, substeps);
    let mut states = Vec::with_capacity(replay.steps as usize);
    while run.advance().is_some() {
        states.push(run.state());
    }
    let error = states
        .iter()
        .all(BodyState::is_finite)
        .then(|| reference.largest_error(&states));
    let times = (0..reps)
        .map(|_| {
            let start = Instant::now();
            let mut run = PeerReplay::<C>::new(replay, substeps);
            while run.advance().is_some() {}
            std::hint::black_box(run.state());
            start.elapsed().as_nanos() as f64
        })
        .collect();
    PeerReplayPoint {
        contender: C::NAME,
        substeps,
        error,
        ns_per_simulated_second: median(times) / reference.seconds,
    }
}

/// Measures every contender on `replay` at each subdivision, against `reference`.
pub fn sweep(
    replay: &Replay,
    subdivisions: &[u32],
    reference: &ReplayReference,
    quick: bool,
) -> Vec<PeerReplayPoint> {
    let reps = if quick { 1 } else { 3 };
    subdivisions
        .iter()
        .flat_map(|&substeps| {
            [
                point::<Ours>(replay, substeps, reference, reps),
                point::<Avian>(replay, substeps, reference, reps),
                point::<Rapier>(replay, substeps, reference, reps),
            ]
        })
        .collect()
}
