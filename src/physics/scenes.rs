//! Scripted runs: a scene, an initial state, and pulls of the band, stepped by one integrator.
//! The `simulate` command, the report and the tests all run through [`Run`].

use std::fmt;

use bevy::math::DVec2;

use super::body::{BodyState, STATE_LIMIT};
use super::integrators::{Integrator, StepInfo};
use super::param_error::ParamError;
use super::scene::SceneParams;
use super::stepper::{Books, Bound, Stepper};

/// A pull of the band toward `target` during steps `start <= s < end`.
///
/// The band is attached at the step `start` to the corner nearest `target`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pull {
    pub start: u64,
    pub end: u64,
    pub target: DVec2,
}

impl Pull {
    /// Finds the pull acting during step `step` (the latest one started, if pulls overlap).
    pub fn active(pulls: &[Pull], step: u64) -> Option<usize> {
        pulls
            .iter()
            .rposition(|pull| pull.start <= step && step < pull.end)
    }
}

/// The pulls of a scripted run, in steps, and which one acts.
///
/// [`Run`] and the peers' runs follow the same schedule, so they attach and release at the same
/// steps.
#[derive(Clone, Debug, PartialEq)]
pub struct PullSchedule {
    pulls: Vec<Pull>,
    active: Option<usize>,
}

/// What the band does before a step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum BandChange {
    /// A new band, at the corner nearest this target, pulling toward it (any old band goes).
    Grab(DVec2),
    /// No band from now on.
    Release,
}

impl PullSchedule {
    pub fn new(pulls: Vec<Pull>) -> Self {
        Self {
            pulls,
            active: None,
        }
    }

    /// Returns what must change before step `step`; `None` while the same pull (or none) goes on.
    pub fn change_at(&mut self, step: u64) -> Option<BandChange> {
        let current = Pull::active(&self.pulls, step);
        if current == self.active {
            return None;
        }
        self.active = current;
        Some(current.map_or(BandChange::Release, |index| {
            BandChange::Grab(self.pulls[index].target)
        }))
    }
}

/// A named scene: parameters, initial state and pulls given in seconds.
///
/// The pulls are in seconds, not steps, so that the same scene can be run at any step.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    pub name: &'static str,
    pub summary: &'static str,
    pub params: SceneParams,
    pub initial: BodyState,
    /// (from, until, target) in seconds; `until` may be infinite.
    pub pulls: Vec<(f64, f64, DVec2)>,
}

/// Where the tutorial scene pulls: up and to the right of the box, off its diagonals.
pub const TUTORIAL_PULL_TARGET: DVec2 = DVec2::new(200.0, 120.0);

impl Scene {
    pub const NAMES: [&'static str; 10] = [
        "tutorial",
        "diagonal",
        "stiff",
        "light",
        "spin",
        "spin-band",
        "far",
        "undamped",
        "zero-length",
        "rest",
    ];

    pub fn named(name: &str) -> Result<Self, UnknownScene> {
        let name = Self::NAMES
            .into_iter()
            .find(|&known| known == name)
            .ok_or_else(|| UnknownScene(name.to_owned()))?;
        let tutorial = SceneParams::tutorial();
        let at_rest = BodyState::default();
        let spinning = {
            let mut state = at_rest;
            state.angular.angular_velocity = 100.0;
            state
        };
        let held = f64::INFINITY;
        let (summary, params, initial, pulls) = match name {
            "tutorial" => (
                "the tutorial's scene: pulled for 2 s, then released",
                tutorial,
                at_rest,
                vec![(0.0, 2.0, TUTORIAL_PULL_TARGET)],
            ),
            "diagonal" => (
                "pulled along the diagonal, through the centre",
                tutorial,
                at_rest,
                vec![(0.0, held, DVec2::new(150.0, 150.0))],
            ),
            "stiff" => (
                "a stiff band, k = 1e5 (omega dt = 2.83 at 100 Hz)",
                SceneParams {
                    stiffness: 1e5,
                    ..tutorial
                },
                at_rest,
                vec![(0.0, held, TUTORIAL_PULL_TARGET)],
            ),
            "light" => (
                "a light box, mass 1e-3, with the tutorial's band",
                SceneParams {
                    mass: 1e-3,
                    ..tutorial
                },
                at_rest,
                vec![(0.0, held, TUTORIAL_PULL_TARGET)],
            ),
            "spin" => ("spinning at 100 rad/s, no band", tutorial, spinning, vec![]),
            "spin-band" => (
                "spinning at 100 rad/s, with the band",
                tutorial,
                spinning,
                vec![(0.0, held, TUTORIAL_PULL_TARGET)],
            ),
            "far" => (
                "the anchor 1e6 units away",
                tutorial,
                at_rest,
                vec![(0.0, held, DVec2::new(1e6, 0.0))],
            ),
            "undamped" => (
                "no damping (b = c = 0), band held: E, and the angular momentum about the anchor, are invariants",
                SceneParams {
                    linear_damping: 0.0,
                    angular_damping: 0.0,
                    ..tutorial
                },
                at_rest,
                vec![(0.0, held, TUTORIAL_PULL_TARGET)],
            ),
            "zero-length" => (
                "the anchor exactly at the corner: no force at all",
                tutorial,
                at_rest,
                vec![(0.0, held, DVec2::new(30.0, 30.0))],
            ),
            _ => ("the box at rest, no band", tutorial, at_rest, vec![]),
        };
        Ok(Self {
            name,
            summary,
            params,
            initial,
            pulls,
        })
    }

    /// Converts the pulls into steps of `dt`.
    pub fn pulls_in_steps(&self, dt: f64) -> Vec<Pull> {
        let to_step = |t: f64| {
            if t.is_finite() {
                (t / dt).round() as u64
            } else {
                u64::MAX
            }
        };
        self.pulls
            .iter()
            .map(|&(from, until, target)| Pull {
                start: to_step(from),
                end: to_step(until),
                target,
            })
            .collect()
    }
}

#[derive(Clone, Debug, PartialEq, Eq)]
pub struct UnknownScene(pub String);

impl fmt::Display for UnknownScene {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "unknown scene '{}' (expected one of: {})",
            self.0,
            Scene::NAMES.join(", ")
        )
    }
}

impl std::error::Error for UnknownScene {}

/// How far above the physically reachable energy a run may go before it counts as diverged.
///
/// With damping b, c >= 0 and a fixed anchor the energy can only fall, so the reachable
/// energy is the initial energy plus the band's energy at each attachment.
pub const DIVERGENCE_FACTOR: f64 = 1e3;

/// A run that blew up: its state or its energy went out of bounds.
///
/// Its state left [`super::body::STATE_LIMIT`] (or became non-finite), or its energy left every
/// physical bound.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Diverged {
    pub integrator: Integrator,
    pub step: u64,
    pub time: f64,
}

impl fmt::Display for Diverged {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "integrator {} diverged at step {} (t = {} s)",
            self.integrator, self.step, self.time
        )
    }
}

impl std::error::Error for Diverged {}

/// One scripted run, stepped one fixed step at a time.
#[derive(Clone, Debug)]
pub struct Run {
    pub stepper: Stepper,
    pub dt: f64,
    /// Steps taken so far.
    pub step: u64,
    schedule: PullSchedule,
    energy_budget: f64,
    /// The latest step's substeps, and how many steps fell back to `implicit` so far.
    pub last_step: StepInfo,
    pub fallbacks: u64,
    /// Where the energy came from and went; its residual is the integrator's error.
    pub books: Books,
}

impl Run {
    pub fn new(
        params: SceneParams,
        initial: BodyState,
        pulls: Vec<Pull>,
        integrator: Integrator,
        dt: f64,
    ) -> Result<Self, ParamError> {
        ParamError::check_positive("dt", dt)?;
        // A sub-normal step has no finite rate: name the step, not the rate it implies.
        if !(1.0 / dt).is_finite() {
            return Err(ParamError {
                field: "dt",
                value: dt,
                requirement: "a step whose rate 1/dt is finite (not sub-normal)".to_owned(),
            });
        }
        let mut stepper = Stepper::new(params)?;
        if let Some(&bad) = initial
            .to_array()
            .iter()
            .find(|v| !(v.is_finite() && v.abs() <= STATE_LIMIT))
        {
            return Err(ParamError {
                field: "each component of the initial state",
                value: bad,
                requirement: "finite and within 1e12 of zero".to_owned(),
            });
        }
        stepper.state = initial;
        stepper.integrator = integrator;
        let energy_budget = stepper.energy();
        let mut run = Self {
            stepper,
            dt,
            step: 0,
            schedule: PullSchedule::new(pulls),
            energy_budget,
            last_step: StepInfo::SINGLE,
            fallbacks: 0,
            books: Books::starting_at(energy_budget),
        };
        run.apply_pulls();
        if !run.energy_budget.is_finite() {
            return Err(ParamError {
                field: "the initial energy",
                value: run.energy_budget,
                requirement: "finite (a state, band and k this large overflow it)".to_owned(),
            });
        }
        Ok(run)
    }

    pub fn of(scene: &Scene, integrator: Integrator, dt: f64) -> Result<Self, ParamError> {
        Self::new(
            scene.params,
            scene.initial,
            scene.pulls_in_steps(dt),
            integrator,
            dt,
        )
    }

    pub fn time(&self) -> f64 {
        self.step as f64 * self.dt
    }

    /// Attaches or releases the band as the pulls say for the coming step.
    ///
    /// The next step books the band's energy it puts in or takes away as the hand's work.
    fn apply_pulls(&mut self) {
        let Some(change) = self.schedule.change_at(self.step) else {
            return;
        };
        match change {
            BandChange::Grab(target) => {
                self.stepper.grab(target);
                if let Some(band) = self.stepper.band {
                    self.energy_budget +=
                        band.potential_energy(&self.stepper.state, self.stepper.params.stiffness);
                }
            }
            BandChange::Release => self.stepper.release(),
        }
    }

    /// Advances the run by one booked step, refusing a step that diverges.
    ///
    /// A step that leaves the state not sane or its energy beyond every physical bound is
    /// refused, as the game refuses it: `Err` names it (the first such step), and the run stays
    /// as it was before it (the last sane state, its books and counters).
    pub fn advance(&mut self) -> Result<(), Diverged> {
        let kept = (self.stepper.state, self.books);
        let booked = self.books.step(&mut self.stepper, self.dt, Bound::Sane);
        let energy = self.books.settled.unwrap_or(f64::NAN);
        if booked.refused
            || !energy.is_finite()
            || energy > DIVERGENCE_FACTOR * self.energy_budget + 1.0
        {
            (self.stepper.state, self.books) = kept;
            return Err(Diverged {
                integrator: self.stepper.integrator,
                step: self.step + 1,
                time: (self.step + 1) as f64 * self.dt,
            });
        }
        self.last_step = booked.info;
        self.fallbacks += u64::from(booked.info.fell_back);
        self.step += 1;
        self.apply_pulls();
        Ok(())
    }

    /// Advances the run by `steps` more steps, or returns the divergence that stopped them.
    pub fn advance_by(&mut self, steps: u64) -> Result<(), Diverged> {
        for _ in 0..steps {
            self.advance()?;
        }
        Ok(())
    }
}
