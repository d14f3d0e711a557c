//! The pace: the share of the set pace the game's clock keeps, for the status line to say when
//! the game falls behind the wall clock.

use bevy::prelude::*;

use crate::game::budget::FrameBudget;

/// The share of the set pace below which the status line says the game falls behind.
const BEHIND: f64 = 0.95;

/// The share of the set pace the game's clock has kept over about the last second.
///
/// The set pace is the wall clock times the time scale. 1 while every frame's time reaches the
/// simulation. Bevy's virtual clock takes at most 250 ms from a frame (`Time<Virtual>`'s
/// `max_delta`), and a frame's fixed steps stop at its budget (`budget`), dropping the time
/// still owed: when frames (their fixed steps, their drawing) take longer, the simulated time
/// falls behind the wall clock, and this says by how much.
#[derive(Resource, Debug, Clone, Copy, PartialEq)]
pub struct Pace(pub f64);

impl Default for Pace {
    fn default() -> Self {
        Self(1.0)
    }
}

/// Returns what the status line says of the pace, if anything.
///
/// "behind: runs ×0.42" while the clock falls behind: the rate it really runs at, beside the
/// one set (`time_scale`). Nothing while it keeps the pace or the game is paused.
pub fn behind(pace: f64, time_scale: f64, paused: bool) -> Option<String> {
    (!paused && pace < BEHIND).then(|| format!("behind: runs ×{:.2}", pace * time_scale))
}

/// Updates [`Pace`] from this frame's real and virtual time, with a memory of about a second.
pub(super) fn measure_pace(
    real: Res<Time<Real>>,
    virtual_time: Res<Time<Virtual>>,
    budget: Res<FrameBudget>,
    mut pace: ResMut<Pace>,
) {
    let wall = real.delta_secs_f64();
    let set = wall * virtual_time.relative_speed_f64();
    if virtual_time.is_paused() || set <= 0.0 {
        return;
    }
    let stepped = virtual_time.delta_secs_f64() - budget.dropped.as_secs_f64();
    let kept = (stepped / set).clamp(0.0, 1.0);
    let weight = 1.0 - (-wall).exp();
    let next = pace.0 + (kept - pace.0) * weight;
    if pace.0 != next {
        pace.0 = next;
    }
}
