//! Keyboard controls, each applied before the fixed loop so it acts on the very next step.
//! The window title shows the state they set.
//!
//! | key | effect |
//! |---|---|
//! | Space | pause / resume |
//! | N | one fixed step while paused |
//! | R | reset: the box at rest at the centre, no band |
//! | I | next integrator |
//! | `[` / `]` | band stiffness k ÷10 / ×10 (1e-2 to 1e12) |
//! | `-` / `=` | time scale ÷2 / ×2 (1/16 to 16) |
//! | PageDown / PageUp | fixed step rate ÷2 / ×2 (8 to 4096 Hz) |
//! | V | force and velocity vectors |
//! | T | trail of the pulled corner |
//! | H | hide / show the HUD |

use bevy::ecs::system::SystemParam;
use bevy::prelude::*;
use bevy::window::PrimaryWindow;

use crate::hud::EnergyHistory;
use crate::physics::{AngularState, BodyState, Integrator, LinearState, SceneParams};
use crate::pointer::Grip;
use crate::simulation::{
    Band, EnergyBooks, ForceAccumulator, RenderSnapshots, RigidBox, StepStats, apply_step_rate,
};

pub struct ControlsPlugin;

impl Plugin for ControlsPlugin {
    fn build(&self, app: &mut App) {
        app.init_resource::<Overlays>()
            .add_systems(
                RunFixedMainLoop,
                (
                    cycle_integrator,
                    pause_and_step,
                    reset_scene,
                    tune_parameters,
                    toggle_overlays,
                )
                    .before(apply_step_rate)
                    .in_set(RunFixedMainLoopSystems::BeforeFixedMainLoop),
            )
            .add_systems(Update, show_state_in_title);
    }
}

pub const CYCLE_INTEGRATOR: KeyCode = KeyCode::KeyI;
pub const PAUSE: KeyCode = KeyCode::Space;
pub const SINGLE_STEP: KeyCode = KeyCode::KeyN;
pub const RESET: KeyCode = KeyCode::KeyR;
pub const SOFTER: KeyCode = KeyCode::BracketLeft;
pub const STIFFER: KeyCode = KeyCode::BracketRight;
pub const SLOWER: KeyCode = KeyCode::Minus;
pub const FASTER: KeyCode = KeyCode::Equal;
pub const FEWER_STEPS: KeyCode = KeyCode::PageDown;
pub const MORE_STEPS: KeyCode = KeyCode::PageUp;
pub const VECTORS: KeyCode = KeyCode::KeyV;
pub const TRAIL: KeyCode = KeyCode::KeyT;
pub const HUD: KeyCode = KeyCode::KeyH;

pub const STIFFNESS_RANGE: (f64, f64) = (1e-2, 1e12);
pub const TIME_SCALE_RANGE: (f64, f64) = (1.0 / 16.0, 16.0);
pub const STEP_RATE_RANGE: (f64, f64) = (8.0, 4096.0);

/// What the drawing shows besides the box and the band.
#[derive(Resource, Debug, Default, Clone, Copy, PartialEq, Eq)]
pub struct Overlays {
    pub vectors: bool,
    pub trail: bool,
    /// The HUD (text and energy graph) shows unless hidden.
    pub hud_hidden: bool,
}

/// The switch takes effect on the next fixed step.
pub fn cycle_integrator(keys: Res<ButtonInput<KeyCode>>, mut integrator: ResMut<Integrator>) {
    if keys.just_pressed(CYCLE_INTEGRATOR) {
        *integrator = integrator.next();
        info!("integrator: {}", *integrator);
    }
}

/// Pausing stops the virtual clock, so no fixed step runs; a single step feeds the fixed clock
/// exactly one step of time.
fn pause_and_step(
    keys: Res<ButtonInput<KeyCode>>,
    mut virtual_time: ResMut<Time<Virtual>>,
    mut fixed_time: ResMut<Time<Fixed>>,
) {
    if keys.just_pressed(PAUSE) {
        if virtual_time.is_paused() {
            virtual_time.unpause();
        } else {
            virtual_time.pause();
        }
    }
    if keys.just_pressed(SINGLE_STEP) && virtual_time.is_paused() {
        let step = fixed_time.timestep();
        fixed_time.accumulate_overstep(step);
    }
}

/// Everything a reset puts back: the run's books and counters, the grip, the graph and clock.
#[derive(SystemParam)]
struct RunRecords<'w> {
    grip: ResMut<'w, Grip>,
    stats: ResMut<'w, StepStats>,
    books: ResMut<'w, EnergyBooks>,
    fixed_time: Res<'w, Time<Fixed>>,
    history: Option<ResMut<'w, EnergyHistory>>,
}

fn reset_scene(
    keys: Res<ButtonInput<KeyCode>>,
    mut commands: Commands,
    bands: Query<Entity, With<Band>>,
    mut boxes: Query<
        (
            &mut LinearState,
            &mut AngularState,
            &mut ForceAccumulator,
            &mut RenderSnapshots,
        ),
        With<RigidBox>,
    >,
    mut records: RunRecords,
) {
    if !keys.just_pressed(RESET) {
        return;
    }
    for band in &bands {
        commands.entity(band).despawn();
    }
    let rest = BodyState::default();
    for (mut linear, mut angular, mut accumulator, mut snapshots) in &mut boxes {
        *linear = rest.linear;
        *angular = rest.angular;
        *accumulator = ForceAccumulator::default();
        *snapshots = RenderSnapshots::at_rest(rest);
    }
    records.grip.0 = None;
    *records.stats = StepStats::default();
    *records.books = EnergyBooks::default();
    let now = records.fixed_time.elapsed_secs_f64();
    if let Some(history) = records.history.as_mut() {
        history.restart(now);
    }
}

/// k, the time scale and the step rate move by factors, so that a player reaches the hard
/// cases in a few presses; each stays inside its range and valid.
fn tune_parameters(
    keys: Res<ButtonInput<KeyCode>>,
    mut params: ResMut<SceneParams>,
    mut virtual_time: ResMut<Time<Virtual>>,
) {
    let scaled =
        |value: f64, factor: f64, (low, high): (f64, f64)| (value * factor).clamp(low, high);
    let mut next = *params;
    if keys.just_pressed(SOFTER) {
        next.stiffness = scaled(next.stiffness, 0.1, STIFFNESS_RANGE);
    }
    if keys.just_pressed(STIFFER) {
        next.stiffness = scaled(next.stiffness.max(STIFFNESS_RANGE.0), 10.0, STIFFNESS_RANGE);
    }
    if keys.just_pressed(FEWER_STEPS) {
        next.step_rate_hz = scaled(next.step_rate_hz, 0.5, STEP_RATE_RANGE);
    }
    if keys.just_pressed(MORE_STEPS) {
        next.step_rate_hz = scaled(next.step_rate_hz, 2.0, STEP_RATE_RANGE);
    }
    if next != *params {
        match next.validate() {
            Ok(()) => *params = next,
            Err(error) => warn!("refused: {error}"),
        }
    }
    let speed = virtual_time.relative_speed_f64();
    if keys.just_pressed(SLOWER) {
        virtual_time.set_relative_speed_f64(scaled(speed, 0.5, TIME_SCALE_RANGE));
    }
    if keys.just_pressed(FASTER) {
        virtual_time.set_relative_speed_f64(scaled(speed, 2.0, TIME_SCALE_RANGE));
    }
}

fn toggle_overlays(keys: Res<ButtonInput<KeyCode>>, mut overlays: ResMut<Overlays>) {
    if keys.just_pressed(VECTORS) {
        overlays.vectors = !overlays.vectors;
    }
    if keys.just_pressed(TRAIL) {
        overlays.trail = !overlays.trail;
    }
    if keys.just_pressed(HUD) {
        overlays.hud_hidden = !overlays.hud_hidden;
    }
}

/// "Rubber Band Box: auto (2 substeps, 0 fall-backs), k 20, 100 Hz, time ×1, paused".
fn show_state_in_title(
    integrator: Res<Integrator>,
    stats: Res<StepStats>,
    params: Res<SceneParams>,
    books: Res<EnergyBooks>,
    virtual_time: Res<Time<Virtual>>,
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
        ", k {}, {} Hz, time ×{}",
        params.stiffness,
        params.step_rate_hz,
        virtual_time.relative_speed_f64()
    );
    title += &format!(", energy error {:.1e}", books.residual);
    if virtual_time.is_paused() {
        title += ", paused (N steps)";
    }
    if let Some((diverged, step)) = stats.divergence {
        title += &format!(", {diverged} diverged at step {step}: steps refused");
    }
    title += "; Space I R [ ] - = V T H";
    if window.title != title {
        window.title = title;
    }
}
