//! The frame's budget for fixed steps: however much simulated time a frame owes (a slow frame
//! at ×16 and 4096 Hz owes 16,384 steps), its fixed loop stops once its steps have taken a
//! third of the previous frame's wall time (at least [`FrameBudget::WALL`]) or
//! [`FrameBudget::max_steps`] steps, and the time still owed is dropped. A frame then takes at
//! most about one and a half times what its drawing takes, however heavy the steps: the
//! simulation falls behind the wall clock instead of every frame taking longer than the last,
//! the status line says so (`hud::pace`), and the frame comes back to the input at once, so a
//! pause or a key acts within a frame at any setting. A slow renderer (the browser's software
//! WebGL, a quarter of a second a frame) keeps room for the steps of an ordinary game.
//!
//! The steps dropped are never taken, so nothing is recorded for them: a replay holds the
//! steps the game took.

use std::time::Duration;

use bevy::platform::time::Instant;
use bevy::prelude::*;

use crate::game::schedule::{GameSystems, PhysicsSystems};

pub struct BudgetPlugin;

impl Plugin for BudgetPlugin {
    fn build(&self, app: &mut App) {
        app.init_resource::<FrameBudget>()
            .add_systems(RunFixedMainLoop, open_the_frame.in_set(GameSystems::Budget))
            .add_systems(FixedUpdate, stop_when_spent.in_set(PhysicsSystems::Budget));
    }
}

/// What one frame's fixed steps may take, and what this frame's took.
#[derive(Resource, Debug, Clone, Copy)]
pub struct FrameBudget {
    /// The wall time a frame's steps may take at least.
    ///
    /// None: no limit but the count, as the headless tests' manual clock has it.
    pub wall: Option<Duration>,
    /// The share of the previous frame's wall time the steps may take, when it is more.
    pub share: f64,
    /// The most steps a frame takes, however cheap.
    pub max_steps: u32,
    /// This frame's steps so far.
    pub steps: u32,
    /// The wall time this frame's steps may take (None: no limit but the count).
    pub allowed: Option<Duration>,
    /// The simulated time this frame dropped, unstepped.
    pub dropped: Duration,
    started: Option<Instant>,
}

impl FrameBudget {
    /// The least wall time a frame's steps may take: a third of a 30 Hz frame.
    pub const WALL: Duration = Duration::from_millis(10);
    /// The share of the previous frame the steps may take.
    ///
    /// A frame is then at most one and a half times its drawing.
    pub const SHARE: f64 = 1.0 / 3.0;
    /// 4096 Hz at ×16 and 16 frames a second.
    pub const MAX_STEPS: u32 = 4096;

    /// Returns a budget that counts steps only, not the wall's time.
    ///
    /// Every frame of a manual clock (the headless tests) then takes the same steps however
    /// loaded the machine.
    pub fn steps_only() -> Self {
        Self {
            wall: None,
            ..default()
        }
    }
}

impl Default for FrameBudget {
    fn default() -> Self {
        Self {
            wall: Some(Self::WALL),
            share: Self::SHARE,
            max_steps: Self::MAX_STEPS,
            steps: 0,
            allowed: None,
            dropped: Duration::ZERO,
            started: None,
        }
    }
}

/// Starts the frame's budget, just before its fixed loop.
fn open_the_frame(mut budget: ResMut<FrameBudget>, real: Res<Time<Real>>) {
    budget.steps = 0;
    budget.dropped = Duration::ZERO;
    budget.started = Some(Instant::now());
    let share = real.delta().mul_f64(budget.share.clamp(0.0, 1.0));
    budget.allowed = budget.wall.map(|wall| wall.max(share));
}

/// Ends the frame's fixed loop once its budget is spent.
///
/// The whole steps still owed are dropped; what is left of a step stays, for drawing between
/// the last two.
fn stop_when_spent(mut budget: ResMut<FrameBudget>, mut time: ResMut<Time<Fixed>>) {
    budget.steps += 1;
    let out_of_time = matches!(
        (budget.allowed, budget.started),
        (Some(allowed), Some(started)) if started.elapsed() >= allowed
    );
    if budget.steps < budget.max_steps && !out_of_time {
        return;
    }
    let (owed, step) = (time.overstep(), time.timestep());
    let whole = owed.as_nanos() / step.as_nanos().max(1);
    if whole > 0 {
        let dropped = step.saturating_mul(u32::try_from(whole).unwrap_or(u32::MAX));
        time.discard_overstep(dropped);
        budget.dropped += dropped;
    }
}
