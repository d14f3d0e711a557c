//! The keyboard controls, each applied before the fixed loop ([`GameSystems::Controls`]) so
//! that it acts on the very next step. The keys are listed once, in [`CONTROLS`]: the HUD's
//! help line, the window title's hint and README's table are written from it (a test holds
//! README to it).

use bevy::input::common_conditions::input_just_pressed;
use bevy::prelude::*;

use crate::overlays::Overlays;
use crate::physics::{Integrator, Scenario, SceneParams};
#[cfg(not(target_arch = "wasm32"))]
use crate::recording::ReplayStatus;
use crate::recording::SaveReplay;
use crate::scenes::LoadScene;
use crate::schedule::GameSystems;
use crate::simulation::ResetScene;

pub struct ControlsPlugin;

impl Plugin for ControlsPlugin {
    fn build(&self, app: &mut App) {
        app.init_resource::<Overlays>().add_systems(
            RunFixedMainLoop,
            (
                cycle_integrator.run_if(input_just_pressed(CYCLE_INTEGRATOR)),
                toggle_pause.run_if(input_just_pressed(PAUSE)),
                single_step.run_if(input_just_pressed(SINGLE_STEP)),
                reset_scene.run_if(input_just_pressed(RESET)),
                save_replay.run_if(input_just_pressed(SAVE)),
                open_replay.run_if(input_just_pressed(OPEN)),
                load_scene,
                tune_parameters,
                toggle_overlays,
            )
                // One order within the set too: pausing and the time scale both write the
                // virtual clock.
                .chain()
                .in_set(GameSystems::Controls),
        );
    }
}

pub const PAUSE: KeyCode = KeyCode::Space;
pub const SINGLE_STEP: KeyCode = KeyCode::KeyN;
pub const RESET: KeyCode = KeyCode::KeyR;
pub const CYCLE_INTEGRATOR: KeyCode = KeyCode::KeyI;
pub const SOFTER: KeyCode = KeyCode::BracketLeft;
pub const STIFFER: KeyCode = KeyCode::BracketRight;
pub const SLOWER: KeyCode = KeyCode::Minus;
pub const FASTER: KeyCode = KeyCode::Equal;
pub const FEWER_STEPS: KeyCode = KeyCode::PageDown;
pub const MORE_STEPS: KeyCode = KeyCode::PageUp;
pub const VECTORS: KeyCode = KeyCode::KeyV;
pub const TRAIL: KeyCode = KeyCode::KeyT;
pub const HUD: KeyCode = KeyCode::KeyH;
pub const SAVE: KeyCode = KeyCode::KeyS;
pub const OPEN: KeyCode = KeyCode::KeyO;
pub const GHOSTS: KeyCode = KeyCode::KeyG;
/// The named scenes, in the core's order ([`Scenario::NAMES`]).
pub const SCENE_KEYS: [KeyCode; 10] = [
    KeyCode::Digit1,
    KeyCode::Digit2,
    KeyCode::Digit3,
    KeyCode::Digit4,
    KeyCode::Digit5,
    KeyCode::Digit6,
    KeyCode::Digit7,
    KeyCode::Digit8,
    KeyCode::Digit9,
    KeyCode::Digit0,
];

pub const STIFFNESS_RANGE: (f64, f64) = (1e-2, 1e12);
pub const TIME_SCALE_RANGE: (f64, f64) = (1.0 / 16.0, 16.0);
pub const STEP_RATE_RANGE: (f64, f64) = (8.0, 4096.0);

/// One control: its keys, how the help line names them, and what it does.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Control {
    pub keys: &'static [KeyCode],
    /// The keys as the help line, the title and README write them ("[ ]").
    pub label: &'static str,
    /// What it does, in a word (the help line).
    pub name: &'static str,
    /// What it does, in full (README's table).
    pub effect: &'static str,
}

/// Every key the game reads, in the order the help line lists them.
pub const CONTROLS: [Control; 14] = [
    Control {
        keys: &[PAUSE],
        label: "Space",
        name: "pause",
        effect: "pause / resume (from the next frame: Bevy advances its clocks before it reads input)",
    },
    Control {
        keys: &[SINGLE_STEP],
        label: "N",
        name: "step",
        effect: "one fixed step while paused",
    },
    Control {
        keys: &[RESET],
        label: "R",
        name: "reset",
        effect: "reset: the box at rest at the centre, no band, the books, the graph and the trail started over",
    },
    Control {
        keys: &[CYCLE_INTEGRATOR],
        label: "I",
        name: "integrator",
        effect: "the next integrator",
    },
    Control {
        keys: &[SOFTER, STIFFER],
        label: "[ ]",
        name: "k",
        effect: "band stiffness k ÷10 / ×10, from 1e-2 to 1e12 (the hard cases are a few presses away)",
    },
    Control {
        keys: &[SLOWER, FASTER],
        label: "- =",
        name: "time",
        effect: "time scale ÷2 / ×2, from 1/16 to 16 (slow motion, fast forward)",
    },
    Control {
        keys: &[FEWER_STEPS, MORE_STEPS],
        label: "PgDn PgUp",
        name: "rate",
        effect: "fixed step rate ÷2 / ×2, from 8 to 4096 Hz",
    },
    Control {
        keys: &[VECTORS],
        label: "V",
        name: "vectors",
        effect: "vectors: velocity at the centre (green, where it will be in 0.25 s), the band's force at its corner (orange, length growing with log force)",
    },
    Control {
        keys: &[TRAIL],
        label: "T",
        name: "trail",
        effect: "a fading trail of the pulled corner",
    },
    Control {
        keys: &[GHOSTS],
        label: "G",
        name: "ghosts",
        effect: "ghosts: every integrator and a reference (Taylor order 24 at 1e-13 px) beside the box under the same band, each outlined in its colour; the HUD lists their distance from the reference, energy residual and cost per step",
    },
    Control {
        keys: &SCENE_KEYS,
        label: "1-0",
        name: "scene",
        effect: "load the named scene at that place in the core's table (the order of `simulate --scene`'s list: 1 the first, 0 the tenth): its parameters and start, its scripted pull played until you press; the HUD names it and says what makes it hard",
    },
    Control {
        keys: &[HUD],
        label: "H",
        name: "HUD",
        effect: "hide / show the HUD and the energy graph",
    },
    Control {
        keys: &[SAVE],
        label: "S",
        name: "save",
        effect: "save the game so far as a replay (to `--record`'s file, else `replay-<time>.jsonl`; in the browser a download; the HUD shows the name)",
    },
    Control {
        keys: &[OPEN],
        label: "O",
        name: "open",
        effect: "play a replay file: in the browser a file chooser; on the desktop drop the file on the window (or `play --replay FILE`); dropping works in the browser too",
    },
];

/// The HUD's help line: "drag: pull  Space: pause  N: step ...".
/// Each item's spaces are non-breaking, so that a narrow window wraps the line between items,
/// never inside one.
pub fn help_line() -> String {
    let keys: Vec<String> = CONTROLS
        .iter()
        .map(|control| format!("{}: {}", control.label, control.name).replace(' ', "\u{a0}"))
        .collect();
    format!("drag:\u{a0}pull  {}", keys.join("  "))
}

/// The window title's reminder of the keys: "Space N R I [ ] ...".
pub fn key_hint() -> String {
    let labels: Vec<&str> = CONTROLS.iter().map(|control| control.label).collect();
    labels.join(" ")
}

/// The switch takes effect on the next fixed step.
pub fn cycle_integrator(mut integrator: ResMut<Integrator>) {
    *integrator = integrator.next();
    info!("integrator: {}", *integrator);
}

/// Pausing stops the virtual clock, so no fixed step runs.
fn toggle_pause(mut virtual_time: ResMut<Time<Virtual>>) {
    if virtual_time.is_paused() {
        virtual_time.unpause();
    } else {
        virtual_time.pause();
    }
}

/// While paused, feeds the fixed clock exactly one step of time (running, it does nothing).
fn single_step(virtual_time: Res<Time<Virtual>>, mut fixed_time: ResMut<Time<Fixed>>) {
    if virtual_time.is_paused() {
        let step = fixed_time.timestep();
        fixed_time.accumulate_overstep(step);
    }
}

/// Each plugin puts back what it owns (see [`ResetScene`]).
fn reset_scene(mut commands: Commands) {
    commands.trigger(ResetScene);
}

/// The recorder saves and says where ([`crate::recording`]).
fn save_replay(mut commands: Commands) {
    commands.trigger(SaveReplay);
}

/// In the browser, the file chooser (the playback opens what is chosen); on the desktop,
/// where dropping a file on the window opens it, the HUD says so.
#[cfg(target_arch = "wasm32")]
fn open_replay() {
    crate::web::choose_replay_file();
}

#[cfg(not(target_arch = "wasm32"))]
fn open_replay(mut status: ResMut<ReplayStatus>) {
    status.0 = Some("drop a replay file on the window to play it".to_owned());
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
    if keys.just_pressed(GHOSTS) {
        overlays.ghosts = !overlays.ghosts;
    }
}

/// A digit loads the scene at its place in the core's table ([`SCENE_KEYS`]).
fn load_scene(keys: Res<ButtonInput<KeyCode>>, mut commands: Commands) {
    for (key, name) in SCENE_KEYS.iter().zip(Scenario::NAMES) {
        if keys.just_pressed(*key) {
            commands.trigger(LoadScene(name));
        }
    }
}
