//! Learn mode's own state: the chapter shown, the answers, the point masses, what each chapter
//! taught, and the game's setup as the mode found it.

use bevy::prelude::*;

use super::chapters::CHAPTERS;
use super::experiments::{Progress, Verdict};
use crate::game::setup::Setup;

/// Learn mode's chapters: the one shown, its prediction and experiment, what each chapter taught.
///
/// Whether the mode is on is the state [`Mode`](crate::game::shared::Mode), asked nowhere else.
#[derive(Resource, Debug)]
pub struct Learning {
    /// The chapter shown in learn mode (the one it shows next when entered).
    pub chapter: usize,
    /// Each chapter's prediction found right by its experiment.
    pub done: [bool; CHAPTERS.len()],
    /// Each chapter's answer chosen now: kept across the chapters and their restarts.
    pub(super) chosen: [Option<usize>; CHAPTERS.len()],
    /// Each chapter's first answer judged, and whether it was right.
    pub(super) first: [Option<(usize, bool)>; CHAPTERS.len()],
    /// How many answers each chapter's experiments have judged.
    pub(super) tries: [u32; CHAPTERS.len()],
    /// The point masses across the box (the moment of inertia's sum is over n × n).
    pub point_masses: u32,
    pub(super) progress: Progress,
    /// The game's setup as learn mode found it, sent back as the mode is left.
    pub(super) kept: Option<Setup>,
    /// The chapter's scene, loaded on the frame after the chapter paused the clock.
    ///
    /// With it, whether that frame has come.
    pub(super) scene_to_load: Option<(&'static str, bool)>,
}

impl Default for Learning {
    fn default() -> Self {
        Self {
            chapter: 0,
            done: [false; CHAPTERS.len()],
            chosen: [None; CHAPTERS.len()],
            first: [None; CHAPTERS.len()],
            tries: [0; CHAPTERS.len()],
            point_masses: 4,
            progress: Progress::default(),
            kept: None,
            scene_to_load: None,
        }
    }
}

/// The most point masses across the box.
pub const MOST_POINT_MASSES: u32 = 64;

impl Learning {
    /// Returns the answer chosen for this chapter's prediction.
    pub fn predicted(&self) -> Option<usize> {
        self.chosen.get(self.chapter).copied().flatten()
    }

    /// Returns the first answer the chapter's experiments judged, and whether it was right.
    pub fn first_answer(&self) -> Option<(usize, bool)> {
        self.first.get(self.chapter).copied().flatten()
    }

    /// Returns what the chapter's experiment found last, against the answer held then.
    pub fn verdict(&self) -> Option<&Verdict> {
        self.progress.verdict.as_ref()
    }
}
