//! The window title: the essentials of the HUD for when it is hidden, and the keys.

use bevy::prelude::*;
use bevy::window::PrimaryWindow;

use crate::game::hud::pace::{Pace, behind};
use crate::game::input::controls::key_hint;
use crate::game::shared::{hertz, readable, times};
use crate::game::simulation::{EnergyBooks, StepStats};
use crate::physics::{Integrator, SceneParams};

/// Writes the state and the keys into the window title.
///
/// "Rubber Band Box: auto (2 substeps, 0 fall-backs), k 20, 100 Hz, time ×1, paused; keys";
/// "behind: runs ×0.42" after the time scale while the clock falls behind ([`Pace`]).
pub(super) fn show_state_in_title(
    integrator: Res<Integrator>,
    stats: Res<StepStats>,
    params: Res<SceneParams>,
    books: Res<EnergyBooks>,
    (virtual_time, pace): (Res<Time<Virtual>>, Res<Pace>),
    mut window: Option<Single<&mut Window, With<PrimaryWindow>>>,
) {
    let Some(window) = window.as_deref_mut() else {
        return;
    };
    let mut title = format!("Rubber Band Box: {}", *integrator);
    if *integrator == Integrator::Auto {
        let plural = |n: u64, word: &str| format!("{n} {word}{}", if n == 1 { "" } else { "s" });
        title += &format!(
            " ({}, {})",
            plural(u64::from(stats.substeps), "substep"),
            plural(stats.fallbacks, "fall-back")
        );
    }
    title += &format!(
        ", k {}, {}, time {}",
        readable(params.stiffness),
        hertz(params.step_rate_hz),
        times(virtual_time.relative_speed_f64())
    );
    if let Some(behind) = behind(
        pace.0,
        virtual_time.relative_speed_f64(),
        virtual_time.is_paused(),
    ) {
        title += &format!(", {behind}");
    }
    title += &format!(", energy error {:.1e}", books.residual());
    if virtual_time.is_paused() {
        title += ", paused (N steps)";
    }
    if let Some((diverged, step)) = stats.divergence {
        title += &format!(", {diverged} diverged at step {step}: steps refused");
    }
    title += "; ";
    title += &key_hint();
    if window.title != title {
        window.title = title;
    }
}
