//! The recorder: what reached the physics at each fixed step (the band the integrator used,
//! the settings in force, the resets), kept as a [`Replay`] from the first step on, so that a
//! game can be saved at any moment and stepped again to the bit (`simulate --replay`).
//!
//! It reads the step's inputs as the step will take them (the band that acts, the settings and
//! `auto`'s settings in force, the state the step starts from) and the state after it, so it
//! sees exactly what the integrator saw, whatever put it there: a key, the panel, a link, a
//! scene, learn mode or a replay opened. It never writes anything the physics reads, and it
//! never starts over: one recording holds the whole session. Saving writes a new file beside the target and renames it into
//! place ([`crate::replay::save`]). `play --record FILE` saves to FILE when the game ends (the
//! window closed, Ctrl-C, or SIGTERM); the save control saves the game so far at any time.

#[cfg(not(target_arch = "wasm32"))]
use std::path::{Path, PathBuf};

use bevy::prelude::*;

use crate::game::schedule::PhysicsSystems;
use crate::game::shared::{Say, SceneName};
use crate::game::simulation::{Band, Bodies, ResetScene, StepSettings, acting_band};
use crate::physics::BandEnds;
use crate::replay::{Replay, Settings};

/// Keeps the recording: the step's inputs before it, its state after, a save asked or due.
pub(super) fn plugin(app: &mut App) {
    app.init_resource::<Recorder>()
        .add_observer(note_reset)
        .add_observer(save_on_request)
        .add_systems(
            FixedUpdate,
            (
                note_step_inputs.in_set(PhysicsSystems::Observe),
                note_step_result.in_set(PhysicsSystems::AfterStep),
            ),
        );
    // After the window plugin's exit systems: closing the last window asks to exit there.
    #[cfg(not(target_arch = "wasm32"))]
    app.add_systems(
        Last,
        save_on_exit.in_set(crate::game::schedule::AfterBevySystems::AfterExit),
    );
}

/// The game so far, and where `play --record` saves it.
#[derive(Resource, Debug, Default)]
pub struct Recorder {
    /// None until the first step.
    pub replay: Option<Replay>,
    /// `play --record FILE`: saved there when the game ends.
    #[cfg(not(target_arch = "wasm32"))]
    pub target: Option<PathBuf>,
    /// A reset happened since the latest step.
    reset_pending: bool,
    /// The band of the step being taken, between its two systems.
    band: Option<BandEnds>,
    step_noted: bool,
    #[cfg(not(target_arch = "wasm32"))]
    saved_at_exit: bool,
}

impl Recorder {
    /// Records to `target` (saved when the game ends).
    #[cfg(not(target_arch = "wasm32"))]
    pub fn to_file(target: PathBuf) -> Self {
        Self {
            target: Some(target),
            ..default()
        }
    }

    pub fn steps(&self) -> u64 {
        self.replay.as_ref().map_or(0, |replay| replay.steps)
    }

    /// Returns what to tell the player when the game changes under the recording.
    ///
    /// A replay, a scene or a link opened, learn mode left: the recording goes on, and this
    /// says where it goes.
    pub fn goes_on(&self) -> Option<String> {
        let steps = self.steps();
        if steps == 0 {
            return None;
        }
        #[cfg(not(target_arch = "wasm32"))]
        let place = match &self.target {
            Some(target) => format!("saved to {} when the game ends", target.display()),
            None => "S saves it".to_owned(),
        };
        #[cfg(target_arch = "wasm32")]
        let place = "S downloads it".to_owned();
        Some(format!(
            "the recording goes on: its {steps} steps so far are kept ({place})"
        ))
    }
}

/// Save the game so far (the save control).
#[derive(Event, Debug, Clone, Copy, Default)]
pub struct SaveReplay;

fn note_reset(_reset: On<ResetScene>, mut recorder: ResMut<Recorder>) {
    recorder.reset_pending = true;
}

/// Notes what the step will take, before it: settings, start state and band.
///
/// Each is recorded only when it is not what the replay would have there anyway.
fn note_step_inputs(
    mut recorder: ResMut<Recorder>,
    step: StepSettings,
    scene: Res<SceneName>,
    boxes: Bodies,
    bands: Query<&Band>,
) {
    let Ok(body) = boxes.single() else {
        return;
    };
    let settings = Settings::new(
        &step.params,
        step.time.timestep().as_secs_f64(),
        *step.integrator,
    );
    let recorder = &mut *recorder;
    let replay = recorder
        .replay
        .get_or_insert_with(|| Replay::start(&scene.0, settings, *step.auto, body.state()));
    if replay.is_full() {
        warn_once!("the recording is full: later steps are not recorded");
        return;
    }
    if std::mem::take(&mut recorder.reset_pending) {
        replay.push_reset();
    }
    replay.push_settings(settings);
    replay.push_auto(*step.auto);
    replay.push_state(&body.state());
    recorder.band = acting_band(body.entity, &bands);
    recorder.step_noted = true;
}

/// Notes the state the step left once it has run (refused steps included, as the game kept it).
fn note_step_result(mut recorder: ResMut<Recorder>, boxes: Bodies) {
    let recorder = &mut *recorder;
    if !std::mem::take(&mut recorder.step_noted) {
        return;
    }
    let band = recorder.band.take();
    if let (Some(replay), Ok(body)) = (recorder.replay.as_mut(), boxes.single()) {
        let after = body.state();
        replay.push_step(band, &after);
        replay.push_check_if_due(&after);
    }
}

/// Saves the game for the save control, to `--record`'s file if there is one.
///
/// Otherwise it saves to a new file named by the time, in the working folder.
fn save_on_request(_save: On<SaveReplay>, recorder: Res<Recorder>, mut commands: Commands) {
    #[cfg(not(target_arch = "wasm32"))]
    {
        let path = recorder.target.clone().unwrap_or_else(timestamped_name);
        commands.trigger(Say(save(&recorder, &path).unwrap_or_else(|message| message)));
    }
    // In the browser: offered as a download.
    #[cfg(target_arch = "wasm32")]
    {
        commands.trigger(Say(match recorder.replay.as_ref() {
            None => "nothing to save yet: no step has run".to_owned(),
            Some(replay) => {
                let text = String::from_utf8_lossy(&replay.to_bytes()).into_owned();
                let name = crate::game::web::download_replay(&text);
                info!("saved {} steps as the download {name}", replay.steps);
                format!("saved the game as the download {name}")
            }
        }));
    }
}

/// Returns the name `replay-<seconds since 1970>.jsonl`.
#[cfg(not(target_arch = "wasm32"))]
fn timestamped_name() -> PathBuf {
    let seconds = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |since| since.as_secs());
    PathBuf::from(format!("replay-{seconds}.jsonl"))
}

/// Saves the game so far to `path` and returns what to tell the player either way.
#[cfg(not(target_arch = "wasm32"))]
fn save(recorder: &Recorder, path: &Path) -> Result<String, String> {
    let Some(replay) = recorder.replay.as_ref() else {
        return Err("nothing to save yet: no step has run".to_owned());
    };
    crate::replay::save::write_atomically(path, |file| replay.write(file))
        .map(|()| {
            info!("saved {} steps to {}", replay.steps, path.display());
            format!("saved the game to {}", path.display())
        })
        .map_err(|error| error.to_string())
}

/// Saves `--record`'s file when the game ends (the window closed, Ctrl-C, SIGTERM).
#[cfg(not(target_arch = "wasm32"))]
fn save_on_exit(mut exits: MessageReader<AppExit>, mut recorder: ResMut<Recorder>) {
    if exits.read().last().is_none() || recorder.saved_at_exit {
        return;
    }
    recorder.saved_at_exit = true;
    let Some(target) = recorder.target.clone() else {
        return;
    };
    match save(&recorder, &target) {
        Ok(message) => info!("{message}"),
        Err(message) => error!("{message}"),
    }
}

/// SIGTERM ends the game as Ctrl-C does (Bevy handles SIGINT).
///
/// It sends an [`AppExit`], so that the recording is saved.
#[cfg(all(unix, not(target_arch = "wasm32")))]
pub mod sigterm {
    use std::sync::atomic::{AtomicBool, Ordering};

    use bevy::prelude::*;

    static RECEIVED: AtomicBool = AtomicBool::new(false);

    extern "C" fn on_sigterm(_signal: libc::c_int) {
        // Only an atomic store: all a signal handler may safely do.
        RECEIVED.store(true, Ordering::SeqCst);
    }

    /// Installs the handler and the system that turns it into an [`AppExit`].
    pub fn exit_on_sigterm(app: &mut App) {
        let handler = on_sigterm as extern "C" fn(libc::c_int);
        // SAFETY: the handler only stores to an atomic, which is async-signal-safe.
        let previous = unsafe { libc::signal(libc::SIGTERM, handler as libc::sighandler_t) };
        if previous == libc::SIG_ERR {
            warn!("cannot handle SIGTERM: the recording is saved on Ctrl-C or closing only");
            return;
        }
        // Both only ask to exit: in either order the game ends the same way.
        app.add_systems(
            Update,
            write_exit.ambiguous_with(bevy::app::TerminalCtrlCHandlerPlugin::exit_on_flag),
        );
    }

    fn write_exit(mut exits: MessageWriter<AppExit>) {
        if RECEIVED.load(Ordering::SeqCst) {
            exits.write(AppExit::from_code(143));
        }
    }
}
