//! Keyboard controls: `I` cycles the integrator. The window title names the one in use.

use bevy::prelude::*;
use bevy::window::PrimaryWindow;

use crate::physics::Integrator;
use crate::simulation::StepStats;

pub struct ControlsPlugin;

impl Plugin for ControlsPlugin {
    fn build(&self, app: &mut App) {
        // Before the fixed loop, like the pointer, so a key acts on the very next step.
        app.add_systems(
            RunFixedMainLoop,
            cycle_integrator.in_set(RunFixedMainLoopSystems::BeforeFixedMainLoop),
        )
        .add_systems(Update, show_integrator_in_title);
    }
}

pub const CYCLE_INTEGRATOR: KeyCode = KeyCode::KeyI;

/// The switch takes effect on the next fixed step.
pub fn cycle_integrator(keys: Res<ButtonInput<KeyCode>>, mut integrator: ResMut<Integrator>) {
    if keys.just_pressed(CYCLE_INTEGRATOR) {
        *integrator = integrator.next();
        info!("integrator: {}", *integrator);
    }
}

/// "Rubber Band Box (integrator: auto, 2 substeps, 0 fall-backs; I to change)".
fn show_integrator_in_title(
    integrator: Res<Integrator>,
    stats: Res<StepStats>,
    mut window: Option<Single<&mut Window, With<PrimaryWindow>>>,
) {
    let Some(window) = window.as_deref_mut() else {
        return;
    };
    let mut detail = match *integrator {
        Integrator::Auto => format!(
            ", {} substeps, {} fall-backs",
            stats.substeps, stats.fallbacks
        ),
        _ => String::new(),
    };
    if let Some((diverged, step)) = stats.divergence {
        detail += &format!(", {diverged} diverged at step {step}: steps refused");
    }
    let title = format!(
        "Rubber Band Box (integrator: {}{detail}; I to change)",
        *integrator
    );
    if window.title != title {
        window.title = title;
    }
}
