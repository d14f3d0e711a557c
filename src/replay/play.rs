//! The one reader of a replay's records: what each record puts in place before a step, told in
//! the file's order to whoever plays them. The core's [`super::run::ReplayRun`] (so
//! `simulate --replay`), the game's playback, and the writer itself, which keeps what a reader
//! would have in place ([`InPlace`]) so that it records only what differs, all read the records
//! through [`cue`]; the writer's model is [`InPlace`].

use crate::physics::{AutoSettings, BandEnds, BodyState};

use super::format::{InPlace, Record, Replay, Settings};

/// Whoever plays a replay's records, told what each puts in place before the next step.
///
/// `step` is the step the record comes before (a check's: the step it checks).
pub trait Player {
    /// Resets the scene: the box at the replay's start, no band, the books started over.
    fn reset(&mut self, start: BodyState, step: u64);
    /// Takes these settings for the next steps.
    fn settings(&mut self, settings: &Settings, step: u64);
    /// Takes `auto`'s settings for the next steps.
    fn auto(&mut self, auto: AutoSettings, step: u64);
    /// Puts the box at `state`.
    fn state(&mut self, state: BodyState, step: u64);
    /// Compares what the recorded game had after step `step`, for a player that steps.
    fn check(&mut self, _step: u64, _state: &[f64; 6]) {}
}

/// What a record is, once its part is put in place.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Cue {
    /// It put something in place (or checked): the next record follows.
    InPlace,
    /// A step, taken with this band.
    Step(Option<BandEnds>),
    /// The end of the file.
    End,
}

/// Tells `player` what `record` puts in place, `start` being the replay's start.
///
/// The one place a record is read for what it does.
pub fn cue(record: &Record, start: &[f64; 6], player: &mut impl Player) -> Cue {
    match record {
        Record::Reset { step } => player.reset(BodyState::from_array(*start), *step),
        Record::Settings { settings, step } => player.settings(settings, *step),
        Record::Auto { auto, step } => player.auto((*auto).into(), *step),
        Record::State { state, step } => player.state(BodyState::from_array(**state), *step),
        Record::Check { step, state } => player.check(*step, state),
        Record::Step { band, .. } => return Cue::Step(band.map(BandEnds::from)),
        Record::End { .. } => return Cue::End,
    }
    Cue::InPlace
}

/// How far a reading of a replay has got: the next record.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Reader {
    next: usize,
}

impl Reader {
    /// Tells `player` the records before the next step, and returns that step's band.
    ///
    /// `None` after the last step.
    pub fn next_step(
        &mut self,
        replay: &Replay,
        player: &mut impl Player,
    ) -> Option<Option<BandEnds>> {
        loop {
            let record = replay.records.get(self.next)?;
            self.next += 1;
            match cue(record, &replay.header.initial, player) {
                Cue::InPlace => {}
                Cue::Step(band) => return Some(band),
                Cue::End => return None,
            }
        }
    }

    /// Tells whether nothing has been read yet.
    pub fn at_start(&self) -> bool {
        self.next == 0
    }
}

impl Player for InPlace {
    fn reset(&mut self, start: BodyState, _step: u64) {
        self.state = start.to_array();
    }

    fn settings(&mut self, settings: &Settings, _step: u64) {
        self.settings = *settings;
    }

    fn auto(&mut self, auto: AutoSettings, _step: u64) {
        self.auto = auto.into();
    }

    fn state(&mut self, state: BodyState, _step: u64) {
        self.state = state.to_array();
    }
}
