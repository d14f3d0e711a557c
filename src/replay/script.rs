//! A named scene as a replay: its parameters, its start and its scripted pulls written out
//! as the records a player's hand would have made, so that the game plays a scene with the
//! playback it plays a recording with (`playback::open`), and a press takes over.

use crate::physics::scenes::{BandChange, PullSchedule};
use crate::physics::{AutoSettings, BandEnds, Integrator, ParamError, Scene};

use super::run::ReplayRun;
use super::{Replay, Settings};

/// How long a scene's script runs after its last release, or in all when a pull is held.
///
/// The band then stays where the script left it, as a held pull would.
pub const SCRIPT_TAIL_SECONDS: f64 = 1.0;
pub const HELD_SECONDS: f64 = 5.0;

/// Builds the replay of `scene` at step `dt` with `integrator`.
///
/// The pulls are in steps, each band grabbing the corner nearest its target when it starts,
/// and the recorded hash is the core's own stepping of it (the game must step to it:
/// [`crate::game::replays::playback::PlaybackEnd`]).
pub fn scene_replay(
    scene: &Scene,
    dt: f64,
    integrator: Integrator,
    auto: AutoSettings,
) -> Result<Replay, ParamError> {
    let params = scene.params;
    let settings = Settings::new(&params, dt, integrator);
    settings.validate()?;
    let script_end = scene
        .pulls
        .iter()
        .map(|&(_, until, _)| until)
        .fold(0.0, f64::max);
    let seconds = if script_end.is_finite() {
        script_end + SCRIPT_TAIL_SECONDS
    } else {
        HELD_SECONDS
    };
    let steps = (seconds / dt).round().max(1.0) as u64;

    let mut replay = Replay::start(scene.name, settings, auto, scene.initial);
    let mut stepper = replay.stepper()?;
    let mass = params.mass_properties()?;
    let mut schedule = PullSchedule::new(scene.pulls_in_steps(dt));
    for step in 0..steps {
        match schedule.change_at(step) {
            Some(BandChange::Grab(target)) => {
                stepper.band = Some(BandEnds::grabbing(&mass, &stepper.state, target));
            }
            Some(BandChange::Release) => stepper.band = None,
            None => {}
        }
        stepper.step(dt);
        replay.push_step(stepper.band, &stepper.state);
    }
    // The game's own rules (a step that leaves the bounds is refused, the state kept).
    let hash = ReplayRun::new(&replay, None)?.finish();
    replay.hash = hash;
    Ok(replay)
}
