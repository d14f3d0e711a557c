//! Playing a replay back in the game (`play --replay FILE`): before each fixed step the
//! recorded resets, settings and band are put in place, so that the box moves as it did, to
//! the bit. A press takes over: the playback ends and the pointer's band replaces the
//! recorded one. The recorder keeps recording, so a game taken over saves whole.
//!
//! A replay can also be opened while the game runs: dropped on the window, or in the browser
//! chosen with the open control or dropped on the page. The scene is reset to the replay's
//! start; the recorder goes on (it notes the box put there), and the playback hashes the
//! states the game has from there, so that at the replay's end the two hashes say whether the
//! game stepped to the recorded bits.

use bevy::prelude::*;

use crate::game::pointer::PointerAction;
use crate::game::replays::recording::Recorder;
use crate::game::schedule::{AfterStepsSystems, GameSystems, PhysicsSystems};
use crate::game::shared::{Apply, Say, SceneName};
use crate::game::simulation::{Band, Bodies, ResetScene, RigidBox, placed, rigid_box};
use crate::physics::{AutoSettings, BandEnds, BodyState, Integrator, SceneParams};
use crate::replay::play::{Player, Reader};
use crate::replay::{Replay, Settings, TrajectoryHash};

/// Plays a replay opened, step by step, until it ends or a press takes over.
pub(super) fn plugin(app: &mut App) {
    app.init_resource::<Playback>()
        .add_observer(open)
        .add_observer(play_scene)
        .add_observer(stop)
        .add_systems(
            RunFixedMainLoop,
            (
                take_over_on_press.in_set(GameSystems::Input),
                // What this frame's steps did, before the HUD shows it.
                report_the_end
                    .run_if(resource_changed::<Playback>)
                    .in_set(AfterStepsSystems::Conclude),
            ),
        )
        .add_systems(
            FixedUpdate,
            (
                play_step.in_set(PhysicsSystems::Playback),
                hash_the_played_state.in_set(PhysicsSystems::AfterStep),
            ),
        );
    // A replay file opened is input: it acts on the very next step.
    #[cfg(not(target_arch = "wasm32"))]
    app.add_systems(
        RunFixedMainLoop,
        open_dropped_files.in_set(GameSystems::Input),
    );
    #[cfg(target_arch = "wasm32")]
    app.add_systems(Startup, page::expose_replay_hash)
        .add_systems(
            RunFixedMainLoop,
            page::open_chosen_files.in_set(GameSystems::Input),
        );
}

/// How the latest playback ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PlaybackEnd {
    /// The player pressed at this step.
    TakenOver { step: u64 },
    /// Played to the end: the hash of the states the game had, and the recording's.
    Finished {
        steps: u64,
        hash: TrajectoryHash,
        recorded: TrajectoryHash,
    },
}

impl PlaybackEnd {
    /// Returns what the status line tells the player of a recorded game's end.
    ///
    /// What a person did or must know: no steps, no hashes (the log and the Readouts card
    /// have them, [`Self::describe`]).
    pub fn tell(&self) -> String {
        match *self {
            Self::TakenOver { .. } => "you took over the replay: the box is yours".to_owned(),
            Self::Finished { hash, recorded, .. } if hash == recorded => {
                "replay over: the game followed the recording exactly".to_owned()
            }
            Self::Finished { .. } => "replay over: the game did NOT follow the recording (the \
                                      Readouts card and the log say how)"
                .to_owned(),
        }
    }

    /// Returns the end in full, for the log and the Readouts card: its steps and hashes.
    pub fn describe(&self) -> String {
        match *self {
            Self::TakenOver { step } => format!("replay taken over at step {step}"),
            Self::Finished {
                steps,
                hash,
                recorded,
            } if hash == recorded => {
                format!("replay over: {steps} steps, the recorded states to the bit (hash {hash})")
            }
            Self::Finished {
                steps,
                hash,
                recorded,
            } => format!(
                "replay over: {steps} steps, the states DIFFER from the recording (hash {hash}, \
                 recorded {recorded})"
            ),
        }
    }
}

/// The replay being played back, if any, and how far it has got.
#[derive(Resource, Debug, Default)]
pub struct Playback {
    replay: Option<Replay>,
    /// It is a scene's scripted pull, not a recorded game: its end is no news to the player.
    scene: bool,
    /// How far its records are read.
    reader: Reader,
    /// Steps played so far.
    pub played: u64,
    /// The hash of the states the game had after each step played.
    hash: TrajectoryHash,
    hashed: u64,
    /// How the latest playback ended.
    pub ended: Option<PlaybackEnd>,
}

impl Playback {
    /// Plays `replay` from its start. Its `auto` settings are put in place with it.
    pub fn of(replay: Replay) -> Self {
        Self {
            replay: Some(replay),
            ..default()
        }
    }

    pub fn is_playing(&self) -> bool {
        self.replay.is_some()
    }

    /// Returns (steps played, steps in the replay) while playing.
    pub fn progress(&self) -> Option<(u64, u64)> {
        self.replay
            .as_ref()
            .map(|replay| (self.played, replay.steps))
    }

    /// Returns the replay's settings and auto settings, for the game to start with.
    pub fn start(&self) -> Option<(SceneParams, Integrator, AutoSettings)> {
        let header = &self.replay.as_ref()?.header;
        Some((
            header.settings.params(),
            header.settings.integrator,
            header.auto.into(),
        ))
    }
}

/// Ends the playback on a press: the pointer's band replaces the recorded one.
fn take_over_on_press(mut actions: MessageReader<PointerAction>, mut playback: ResMut<Playback>) {
    let pressed = actions
        .read()
        .any(|action| matches!(action, PointerAction::Press(_)));
    if pressed && playback.is_playing() {
        playback.replay = None;
        playback.ended = Some(PlaybackEnd::TakenOver {
            step: playback.played,
        });
        info!("playback ended: the player took over");
    }
}

/// The game as the one reader's [`Player`]: its box and settings.
///
/// It is told what the replay's records put in place before a step.
struct InTheGame<'a, 'c, 's> {
    commands: &'a mut Commands<'c, 's>,
    body: Entity,
    /// The scene's parameters in force, as the records have put them.
    params: SceneParams,
    /// A reset came before this step: its observers remove the old bands.
    reset: bool,
}

impl Player for InTheGame<'_, '_, '_> {
    fn reset(&mut self, start: BodyState, _step: u64) {
        // Its observers put the box, the books and the bands back before this step; the
        // replay's reset puts the box at the replay's start, not the game's.
        self.commands.trigger(ResetScene);
        self.commands.entity(self.body).insert(placed(start));
        self.reset = true;
    }

    fn settings(&mut self, recorded: &Settings, _step: u64) {
        let next = recorded.params();
        if next.mass != self.params.mass || next.size != self.params.size {
            // Checked when the file was read.
            if let Ok(mass) = next.mass_properties() {
                self.commands.entity(self.body).insert(mass);
            }
        }
        self.params = next;
        // Their owner puts them in place before this step, the fixed clock's step at their
        // rate with them (checked in the game's ranges when opened).
        self.commands.trigger(Apply(next));
        self.commands.trigger(Apply(recorded.integrator));
    }

    fn auto(&mut self, auto: AutoSettings, _step: u64) {
        self.commands.trigger(Apply(auto));
    }

    fn state(&mut self, state: BodyState, _step: u64) {
        self.commands.entity(self.body).insert(placed(state));
    }

    // A check is what the game had after a step: the playback's hash says it at the end.
}

/// Puts the recorded resets and settings up to the next step, and its band, in place.
///
/// This runs before the step's forces. At the replay's end the playback stops, leaving the box
/// as it is.
fn play_step(
    mut commands: Commands,
    mut playback: ResMut<Playback>,
    params: Res<SceneParams>,
    boxes: Query<Entity, With<RigidBox>>,
    mut bands: Query<(Entity, &mut Band)>,
) {
    let Ok(body) = boxes.single() else {
        return;
    };
    let playback = &mut *playback;
    let Some(replay) = playback.replay.as_ref() else {
        return;
    };
    if playback.reader.at_start()
        && let Ok(mass) = params.mass_properties()
    {
        // The recorded start (the game's is the box at rest at the centre).
        let start = BodyState::from_array(replay.header.initial);
        commands.entity(body).insert(rigid_box(mass, start));
    }
    let mut in_the_game = InTheGame {
        commands: &mut commands,
        body,
        params: *params,
        reset: false,
    };
    let band = playback.reader.next_step(replay, &mut in_the_game);
    let reset = in_the_game.reset;
    match band {
        Some(band) => {
            playback.played += 1;
            place_band(&mut commands, body, band, reset, &mut bands);
        }
        None => {
            if let Some(replay) = playback.replay.take() {
                playback.ended = Some(PlaybackEnd::Finished {
                    steps: playback.hashed,
                    hash: playback.hash,
                    recorded: replay.hash,
                });
            }
        }
    }
}

/// Adds the state a played step left to the playback's hash.
fn hash_the_played_state(mut playback: ResMut<Playback>, boxes: Bodies) {
    if playback.is_playing()
        && playback.hashed < playback.played
        && let Ok(body) = boxes.single()
    {
        playback.hashed = playback.played;
        playback.hash.add(&body.state());
    }
}

/// Places the step's band, and no other.
///
/// After a reset the old bands are the reset's to remove.
fn place_band(
    commands: &mut Commands,
    body: Entity,
    ends: Option<BandEnds>,
    reset: bool,
    bands: &mut Query<(Entity, &mut Band)>,
) {
    let mut kept = false;
    if !reset {
        for (entity, mut band) in bands.iter_mut() {
            match ends {
                Some(ends) if !kept => {
                    band.set_if_neq(Band { body, ends });
                    kept = true;
                }
                _ => commands.entity(entity).despawn(),
            }
        }
    }
    if let (Some(ends), false) = (ends, kept) {
        commands.spawn((Name::new("Band (replay)"), Band { body, ends }));
    }
}

/// Open a replay in the running game and play it from its first step.
///
/// The caller has held the replay to the game's ranges (`Replay::check_playable`; a scene's
/// script is made in them).
#[derive(Event, Debug, Clone)]
pub struct OpenReplay(pub Replay);

/// Play a scene's scripted pull (a scene or a chapter loaded), as [`OpenReplay`] plays a game.
#[derive(Event, Debug, Clone)]
pub struct PlayScene(pub Replay);

/// Stop the playback, leaving the box where it is (learn mode left).
#[derive(Event, Debug, Clone, Copy, Default)]
pub struct StopPlayback;

/// Opens a replay: the scene reset, its settings sent to their owners, its playback started.
///
/// The recorder goes on, and the log says so.
fn open(
    open: On<OpenReplay>,
    mut commands: Commands,
    mut playback: ResMut<Playback>,
    recorder: Res<Recorder>,
) {
    start(
        &mut commands,
        &mut playback,
        &recorder,
        open.0.clone(),
        false,
    );
}

/// Plays a scene's scripted pull, as a replay is opened.
fn play_scene(
    play: On<PlayScene>,
    mut commands: Commands,
    mut playback: ResMut<Playback>,
    recorder: Res<Recorder>,
) {
    start(
        &mut commands,
        &mut playback,
        &recorder,
        play.0.clone(),
        true,
    );
}

/// Resets the scene, sends the replay's settings to their owners and starts its playback.
///
/// The recorder goes on, and the log says so.
fn start(
    commands: &mut Commands,
    playback: &mut Playback,
    recorder: &Recorder,
    replay: Replay,
    scene: bool,
) {
    let header = &replay.header;
    commands.trigger(ResetScene);
    commands.trigger(Apply(header.settings.params()));
    commands.trigger(Apply(header.settings.integrator));
    commands.trigger(Apply(AutoSettings::from(header.auto)));
    commands.trigger(Apply(SceneName(header.scene.clone())));
    *playback = Playback {
        scene,
        ..Playback::of(replay)
    };
    if let Some(goes_on) = recorder.goes_on() {
        info!("{goes_on}");
    }
}

/// Stops the playback.
fn stop(_stop: On<StopPlayback>, mut playback: ResMut<Playback>) {
    *playback = Playback::default();
}

/// Plays a replay file's text the player opened, or says why it cannot be played.
fn open_or_refuse(commands: &mut Commands, name: &str, read: Result<Replay, String>) {
    let read = read.and_then(|replay| {
        replay.check_playable().map_err(|error| error.to_string())?;
        Ok(replay)
    });
    match read {
        Ok(replay) => {
            info!("playing {name} ({} steps)", replay.steps);
            commands.trigger(OpenReplay(replay));
            commands.trigger(Say(format!("playing {name}")));
        }
        Err(error) => commands.trigger(Say(format!("cannot play {name}: {error}"))),
    }
}

/// Says the end of a playback once: in the HUD's status and the log.
///
/// In the browser it is said to the page too.
fn report_the_end(
    playback: Res<Playback>,
    mut commands: Commands,
    mut said: Local<Option<PlaybackEnd>>,
) {
    let Some(end) = playback.ended else {
        return;
    };
    if *said == Some(end) {
        return;
    }
    *said = Some(end);
    info!("{}", end.describe());
    if !playback.scene {
        commands.trigger(Say(end.tell()));
    }
    #[cfg(target_arch = "wasm32")]
    if let PlaybackEnd::Finished {
        steps,
        hash,
        recorded,
    } = end
    {
        crate::game::web::publish_playback(
            steps as f64,
            &hash.to_string(),
            &recorded.to_string(),
            hash == recorded,
        );
    }
}

/// Plays a file dropped on the window as a replay.
#[cfg(not(target_arch = "wasm32"))]
fn open_dropped_files(
    mut commands: Commands,
    mut drops: MessageReader<bevy::window::FileDragAndDrop>,
) {
    for drop in drops.read() {
        if let bevy::window::FileDragAndDrop::DroppedFile { path_buf, .. } = drop {
            let name = path_buf.display().to_string();
            open_or_refuse(&mut commands, &name, Replay::read_file(path_buf));
        }
    }
}

/// The browser's side: files chosen or dropped on the page, and the hash the page can ask for.
#[cfg(target_arch = "wasm32")]
mod page {
    use bevy::prelude::*;
    use wasm_bindgen::closure::Closure;

    use crate::game::web;
    use crate::replay::Replay;
    use crate::replay::run::ReplayRun;

    pub fn open_chosen_files(mut commands: Commands) {
        let name = web::take_opened_name().unwrap_or_else(|| "the file".to_owned());
        if let Some(text) = web::take_opened_text() {
            let read = Replay::from_bytes(text.as_bytes()).map_err(|error| error.to_string());
            crate::game::replays::playback::open_or_refuse(&mut commands, &name, read);
        }
    }

    /// Exposes `window.rubberBandBox.replayHash(text)`, which steps a replay and hashes its states.
    ///
    /// The replay is stepped with its recorded integrators, as `simulate --replay FILE --hash`
    /// does natively.
    pub fn expose_replay_hash() {
        let hash = Closure::<dyn Fn(String) -> String>::new(|text: String| {
            Replay::from_bytes(text.as_bytes())
                .map_err(|error| error.to_string())
                .and_then(|replay| {
                    ReplayRun::new(&replay, None)
                        .map(|mut run| run.finish().to_string())
                        .map_err(|error| error.to_string())
                })
                .unwrap_or_else(|error| format!("error: {error}"))
        });
        web::expose_replay_hash(&hash);
        // The page keeps it for the life of the game.
        hash.forget();
        web::accept_dropped_files();
    }
}
