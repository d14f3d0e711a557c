//! The peers (issue #5): the report's scenes in the Bevy physics crates avian2d and bevy_rapier2d,
//! each in a headless `App` beside our own plugin, driven by the same scripted pulls so that the
//! report can measure error, energy drift and the cost of a tick side by side.
//!
//! Compiled only with the `peers` feature: the game, the tests and CI never build these crates.

pub mod avian;
pub mod empty;
pub mod measure;
pub mod ours;
pub mod rapier;
pub mod replay;

use std::time::Duration;

use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;

use crate::game::simulation::{Band, body_state, run_single_threaded};
use crate::physics::scenes::{BandChange, PullSchedule};
use crate::physics::{BandEnds, BodyState, MassProperties, Scene, SceneParams};

/// A contender (our plugin or a peer) holding the scene in a headless `App`.
///
/// The `App` takes exactly one fixed step per `update()`.
pub trait Contender {
    /// Short name for tables and plots.
    const NAME: &'static str;

    /// Builds the contender with the box of `params` at `initial`, no band, stepping at `rate_hz`.
    fn new(params: &SceneParams, initial: BodyState, rate_hz: f64) -> Self;

    /// Attaches the band (or moves it), or removes it with `None`.
    fn set_band(&mut self, band: Option<BandEnds>);

    /// Returns the box's state as the contender holds it now, in f64.
    fn state(&mut self) -> BodyState;

    fn app(&mut self) -> &mut App;
}

/// Builds a headless `App`: `MinimalPlugins` on a manual clock.
///
/// The clock advances exactly one fixed step per update.
pub fn headless_app(rate_hz: f64) -> App {
    let step = Duration::from_secs_f64(1.0 / rate_hz);
    let mut app = App::new();
    app.add_plugins(MinimalPlugins)
        .insert_resource(Time::<Fixed>::from_duration(step))
        .insert_resource(TimeUpdateStrategy::ManualDuration(step));
    app
}

/// Finishes the app, runs its first update and puts every schedule on the single-threaded executor.
///
/// The first update only starts the clock and runs `Startup`. The single-threaded executor
/// makes all contenders pay the same, smallest, scheduling cost (on two cores the
/// multi-threaded one costs far more for a scene this small: docs/benchmarks.md).
pub fn start(app: &mut App) {
    app.finish();
    app.cleanup();
    app.update();
    run_single_threaded(app);
}

/// A headless `App` holding the box and its band as our plugin does.
///
/// The box is its two state components, the band one entity: what ours and the empty `App`
/// share.
struct HeldBox {
    app: App,
    body: Entity,
    band: Option<Entity>,
}

impl HeldBox {
    fn new(app: App, body: Entity) -> Self {
        Self {
            app,
            body,
            band: None,
        }
    }

    /// Puts the band `ends` on the box (or takes it off), keeping one band entity.
    fn set_band(&mut self, ends: Option<BandEnds>) {
        let (world, body) = (self.app.world_mut(), self.body);
        match (self.band, ends) {
            (Some(entity), Some(ends)) => {
                world.entity_mut(entity).insert(Band { body, ends });
            }
            (None, Some(ends)) => self.band = Some(world.spawn(Band { body, ends }).id()),
            (Some(entity), None) => {
                world.despawn(entity);
                self.band = None;
            }
            (None, None) => {}
        }
    }

    /// Returns the box's state: its two state components.
    fn state(&self) -> BodyState {
        let entity = self.app.world().entity(self.body);
        body_state(
            entity.get().expect("a body has a linear state"),
            entity.get().expect("a body has an angular state"),
        )
    }
}

/// A scripted run of a scene on a contender.
///
/// It has the same pulls, at the same steps, attached to the corner nearest the target at the
/// pull's first step, as [`crate::physics::Run`].
pub struct PeerRun<C: Contender> {
    pub contender: C,
    pub mass: MassProperties,
    pub step: u64,
    schedule: PullSchedule,
    pub band: Option<BandEnds>,
}

impl<C: Contender> PeerRun<C> {
    pub fn of(scene: &Scene, rate_hz: f64) -> Self {
        let mass = scene
            .params
            .mass_properties()
            .expect("built-in scenes are valid");
        let mut run = Self {
            contender: C::new(&scene.params, scene.initial, rate_hz),
            mass,
            step: 0,
            schedule: PullSchedule::new(scene.pulls_in_steps(1.0 / rate_hz)),
            band: None,
        };
        run.apply_pulls();
        run
    }

    fn apply_pulls(&mut self) {
        let Some(change) = self.schedule.change_at(self.step) else {
            return;
        };
        let state = self.contender.state();
        self.band = match change {
            BandChange::Grab(target) => Some(BandEnds::grabbing(&self.mass, &state, target)),
            BandChange::Release => None,
        };
        self.contender.set_band(self.band);
    }

    /// Takes one fixed step (one `App` update), then applies the pulls for the next.
    ///
    /// The state is read after every step, so that peers that keep the rotation as (cos, sin)
    /// count whole turns (see [`unwrap_angle`]); every contender pays the same small read.
    pub fn advance(&mut self) {
        self.contender.app().update();
        self.step += 1;
        self.contender.state();
        self.apply_pulls();
    }

    pub fn advance_by(&mut self, steps: u64) {
        for _ in 0..steps {
            self.advance();
        }
    }

    pub fn state(&mut self) -> BodyState {
        self.contender.state()
    }
}

/// Returns the angle equal to `wrapped` modulo 2π that is nearest `previous`.
///
/// Peers that keep a rotation as (cos, sin) give it back in (−π, π]; our orientation counts
/// whole turns.
pub fn unwrap_angle(previous: f64, wrapped: f64) -> f64 {
    let turn = std::f64::consts::TAU;
    wrapped + ((previous - wrapped) / turn).round() * turn
}
