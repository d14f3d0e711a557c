//! Writing a replay: the recorder's records, each added only where a reader would not have its
//! value in place anyway. What a reader has in place is told by the one reader ([`cue`]), so the
//! writer and every reader agree on what each record does.

use crate::physics::{AutoSettings, BandEnds, BodyState};

use super::format::{AutoRecord, BandRecord, CHECK_EVERY, Record, Replay, Settings};
use super::play::cue;

impl Replay {
    /// Returns the settings in force after every record so far.
    pub fn current_settings(&self) -> Settings {
        self.in_place.settings
    }

    /// Adds `record`, and puts what it says in place as a reader would ([`cue`]).
    pub(super) fn push(&mut self, record: Record) {
        cue(&record, &self.header.initial, &mut self.in_place);
        self.records.push(record);
    }

    /// Records that the scene was reset before the next step: the box at the header's start.
    pub fn push_reset(&mut self) {
        self.push(Record::Reset {
            step: self.steps + 1,
        });
        self.check_next = true;
    }

    /// Records these settings before the next step, if they differ from those in force.
    pub fn push_settings(&mut self, settings: Settings) {
        if settings != self.in_place.settings {
            self.push(Record::Settings {
                step: self.steps + 1,
                settings: Box::new(settings),
            });
            self.check_next = true;
        }
    }

    /// Records `auto`'s settings before the next step, if they differ from those in force.
    pub fn push_auto(&mut self, auto: AutoSettings) {
        let auto = AutoRecord::from(auto);
        if auto != self.in_place.auto {
            self.push(Record::Auto {
                step: self.steps + 1,
                auto,
            });
        }
    }

    /// Records the state the next step starts from, unless a reader has it there anyway.
    ///
    /// A reader has the previous step's state there, or the start after a reset; compared
    /// to the bit.
    pub fn push_state(&mut self, state: &BodyState) {
        let state = state.to_array();
        if self.in_place.state.map(f64::to_bits) != state.map(f64::to_bits) {
            self.push(Record::State {
                step: self.steps + 1,
                state: Box::new(state),
            });
            self.check_next = true;
        }
    }

    /// Records that the next step ran with `band` and left the body in `after`.
    pub fn push_step(&mut self, band: Option<BandEnds>, after: &BodyState) {
        self.steps += 1;
        self.push(Record::Step {
            step: self.steps,
            band: band.map(BandRecord::from),
        });
        self.hash.add(after);
        self.in_place.state = after.to_array();
        self.unchecked += 1;
    }

    /// Records the state after the latest step as a check, if one is due ([`Record::Check`]).
    pub fn push_check_if_due(&mut self, after: &BodyState) {
        if self.steps > 0 && (self.check_next || self.unchecked >= CHECK_EVERY) {
            self.push(Record::Check {
                step: self.steps,
                state: Box::new(after.to_array()),
            });
            self.unchecked = 0;
            self.check_next = false;
        }
    }

    /// Returns the state a replay has before the next step unless a record moves it.
    pub fn expected_state(&self) -> BodyState {
        BodyState::from_array(self.in_place.state)
    }
}
