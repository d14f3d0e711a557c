//! Playing a replay back in the game (`play --replay FILE`): before each fixed step the
//! recorded resets, settings and band are put in place, so that the box moves as it did, to
//! the bit. A press takes over: the playback ends and the pointer's band replaces the
//! recorded one. The recorder keeps recording, so a game taken over saves whole.

use std::time::Duration;

use bevy::prelude::*;

use crate::physics::{AutoSettings, BandEnds, BodyState, Integrator, SceneParams};
use crate::pointer::{PointerAction, read_pointer};
use crate::replay::{Record, Replay};
use crate::schedule::GameSystems;
use crate::simulation::{Band, PhysicsSystems, ResetScene, RigidBox, rigid_box};

pub struct PlaybackPlugin;

impl Plugin for PlaybackPlugin {
    fn build(&self, app: &mut App) {
        app.init_resource::<Playback>()
            .add_systems(
                RunFixedMainLoop,
                take_over_on_press
                    .after(read_pointer)
                    .in_set(GameSystems::Input),
            )
            .add_systems(FixedUpdate, play_step.before(PhysicsSystems::Accumulate));
    }
}

/// The replay being played back, if any, and how far it has got.
#[derive(Resource, Debug, Default)]
pub struct Playback {
    replay: Option<Replay>,
    next: usize,
    /// Steps played so far.
    pub played: u64,
}

impl Playback {
    /// Plays `replay` from its start. Its `auto` settings are put in place with it.
    pub fn of(replay: Replay) -> Self {
        Self {
            replay: Some(replay),
            next: 0,
            played: 0,
        }
    }

    pub fn is_playing(&self) -> bool {
        self.replay.is_some()
    }

    /// (steps played, steps in the replay) while playing.
    pub fn progress(&self) -> Option<(u64, u64)> {
        self.replay
            .as_ref()
            .map(|replay| (self.played, replay.steps))
    }

    /// The replay's settings and auto settings, for the game to start with.
    pub fn start(&self) -> Option<(SceneParams, Integrator, AutoSettings)> {
        let header = &self.replay.as_ref()?.header;
        Some((
            header.settings.params(),
            header.settings.integrator,
            header.auto.into(),
        ))
    }
}

/// A press ends the playback: the pointer's band replaces the recorded one.
fn take_over_on_press(mut actions: MessageReader<PointerAction>, mut playback: ResMut<Playback>) {
    let pressed = actions
        .read()
        .any(|action| matches!(action, PointerAction::Press(_)));
    if pressed && playback.is_playing() {
        playback.replay = None;
        info!("playback ended: the player took over");
    }
}

/// Before the step's forces: the recorded resets and settings up to the next step, and its
/// band. At the replay's end the playback stops, leaving the box as it is.
fn play_step(
    mut commands: Commands,
    mut playback: ResMut<Playback>,
    mut params: ResMut<SceneParams>,
    mut integrator: ResMut<Integrator>,
    mut time: ResMut<Time<Fixed>>,
    boxes: Query<Entity, With<RigidBox>>,
    mut bands: Query<(Entity, &mut Band)>,
) {
    let Ok(body) = boxes.single() else {
        return;
    };
    if playback.next == 0
        && let Some(replay) = playback.replay.as_ref()
        && let Ok(mass) = params.mass_properties()
    {
        // The recorded start (the game's is the box at rest at the centre).
        let start = BodyState::from_array(replay.header.initial);
        commands.entity(body).insert(rigid_box(mass, start));
    }
    let mut reset = false;
    while playback.is_playing() {
        let next = playback.next;
        let Some(record) = playback
            .replay
            .as_ref()
            .and_then(|replay| replay.records.get(next))
            .cloned()
        else {
            playback.replay = None;
            info!("playback ended: the replay is over");
            return;
        };
        playback.next += 1;
        match record {
            Record::Reset { .. } => {
                // Its observers put the box, the books and the bands back before this step.
                commands.trigger(ResetScene);
                reset = true;
            }
            Record::Settings { settings, .. } => {
                let next = settings.params();
                if next.mass != params.mass || next.size != params.size {
                    // Checked when the file was read.
                    if let Ok(mass) = next.mass_properties() {
                        commands.entity(body).insert(mass);
                    }
                }
                *params = next;
                *integrator = settings.integrator;
                if let Ok(step) = Duration::try_from_secs_f64(settings.dt) {
                    time.set_timestep(step);
                }
            }
            Record::Step { band, .. } => {
                playback.played += 1;
                place_band(
                    &mut commands,
                    body,
                    band.map(BandEnds::from),
                    reset,
                    &mut bands,
                );
                return;
            }
            Record::End { .. } => {}
        }
    }
}

/// The step's band, and no other. After a reset the old bands are the reset's to remove.
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
