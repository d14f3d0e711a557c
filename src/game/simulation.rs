//! The physics plugin: the box's state as components, the band as an entity, and the fixed
//! step as one system in the frame's `schedule::PhysicsSystems::Step`: forces and torques
//! accumulated, then the core's booked step (the hand's work and damping's share booked, a
//! state the game cannot play refused, the render snapshots and the energies settled), then
//! the step counted. A tap's band is the pointer's to remove after its step. It owns
//! the body, the energy books and the step statistics, and puts them back on [`ResetScene`].
//!
//! Headless, and usable alone (the benchmarks and the side-by-side with the peers run it
//! without the rest of the game). Every system is a thin loop over the numerical core in
//! [`crate::physics`].

use std::time::Duration;

use bevy::ecs::query::QueryData;
use bevy::ecs::schedule::{Schedules, SingleThreadedExecutor};
use bevy::ecs::system::SystemParam;
use bevy::math::DVec2;
use bevy::prelude::*;

use crate::game::schedule::{self, PhysicsSystems};
use crate::game::shared::{Apply, Owns};
use crate::physics::{
    AngularState, AutoSettings, BandEnds, BodyState, Books, Bound, Energies, Forces, Integrator,
    LinearState, MassProperties, SceneParams, Stepper, damping_wrench,
};

pub struct SimulationPlugin;

impl Plugin for SimulationPlugin {
    fn build(&self, app: &mut App) {
        // Ordered here as well as by the game: the plugin also runs alone (the benchmarks,
        // the side-by-side with the peers).
        schedule::order_the_physics(app);
        app.init_resource::<SceneParams>()
            .init_resource::<Integrator>()
            .init_resource::<AutoSettings>()
            .owns::<Integrator>()
            .owns::<AutoSettings>()
            .add_observer(set_params)
            .add_observer(set_clock)
            .add_observer(step_once)
            .add_observer(place_the_box)
            .init_resource::<StepStats>()
            .init_resource::<ResetAt>()
            .init_resource::<StepCount>()
            .init_resource::<EnergyBooks>()
            // The clock at the scene's rate before the first frame: a link or a replay opened
            // then builds its steps on it.
            .add_systems(Startup, (spawn_box, apply_step_rate))
            .add_observer(reset_bodies_and_books)
            .add_systems(FixedUpdate, step.in_set(PhysicsSystems::Step));
    }
}

/// The scene put back at its start, triggered by the reset control.
///
/// The box at rest at the centre, no band, the books, the statistics, the graph and the trail
/// started over. Each plugin observes it for the state it owns.
#[derive(Event, Debug, Clone, Copy, Default)]
pub struct ResetScene;

/// The simulated time of the latest reset (0 before any).
///
/// The clocks the HUD and the Readouts card show start there.
#[derive(Resource, Debug, Default, Clone, Copy, PartialEq)]
pub struct ResetAt(pub f64);

/// The game's clocks as its texts read them: the HUD, the Readouts card and the panel.
#[derive(SystemParam)]
pub(crate) struct Clocks<'w> {
    virtual_time: Res<'w, Time<Virtual>>,
    fixed_time: Res<'w, Time<Fixed>>,
    reset_at: Res<'w, ResetAt>,
}

impl Clocks<'_> {
    /// Returns the fixed clock's step rate in Hz: the step in force, which a refused rate leaves.
    pub(crate) fn step_rate_hz(&self) -> f64 {
        1.0 / self.fixed_time.timestep().as_secs_f64()
    }

    /// Returns the time scale: simulated seconds per second of the wall's clock.
    pub(crate) fn time_scale(&self) -> f64 {
        self.virtual_time.relative_speed_f64()
    }

    /// Tells whether the game is paused.
    pub(crate) fn paused(&self) -> bool {
        self.virtual_time.is_paused()
    }

    /// Returns the simulated seconds since the latest reset.
    pub(crate) fn since_reset(&self) -> f64 {
        self.fixed_time.elapsed_secs_f64() - self.reset_at.0
    }
}

/// Marks the pulled box.
#[derive(Component, Debug, Default)]
#[require(LinearState, AngularState, ForceAccumulator, RenderSnapshots)]
pub struct RigidBox;

/// What acts on a body during the current step.
///
/// The summed forces and torques, and the band whose force the integrator evaluates again at its
/// intermediate states. Filled and emptied within the step: empty between steps.
#[derive(Component, Debug, Default, Clone, Copy, PartialEq)]
pub struct ForceAccumulator {
    pub forces: Forces,
    pub band: Option<BandEnds>,
}

/// The band: pulls `ends.local_point` on `body` toward the world point `ends.anchor`.
#[derive(Component, Debug, Clone, Copy, PartialEq)]
pub struct Band {
    pub body: Entity,
    pub ends: BandEnds,
}

/// A band that was pressed and released within one frame.
///
/// It acts for exactly one fixed step, so that a quick click is never lost, and is then removed
/// (by the pointer, which makes it: the step itself has no deferred work).
#[derive(Component, Debug, Default)]
pub struct Tap;

/// Returns the state to draw this frame, between the last two fixed steps.
///
/// It lies as far between them as the clock has run past the last one.
pub fn interpolated_state(snapshots: &RenderSnapshots, fixed_time: &Time<Fixed>) -> BodyState {
    snapshots.interpolate(fixed_time.overstep_fraction_f64().clamp(0.0, 1.0))
}

/// The state before and after the latest fixed step, for drawing in between.
#[derive(Component, Debug, Default, Clone, Copy)]
pub struct RenderSnapshots {
    pub previous: BodyState,
    pub current: BodyState,
}

impl RenderSnapshots {
    fn at_rest(state: BodyState) -> Self {
        Self {
            previous: state,
            current: state,
        }
    }

    /// Returns the state a fraction `alpha` of the way from the previous step to the current.
    ///
    /// `alpha` runs from 0 (the previous step) to 1 (the current).
    pub fn interpolate(&self, alpha: f64) -> BodyState {
        let (a, b) = (self.previous.to_array(), self.current.to_array());
        BodyState::from_array(std::array::from_fn(|i| a[i] + (b[i] - a[i]) * alpha))
    }
}

/// What the integrator did: its substeps, its fall-backs and the latest step it refused.
///
/// The latest step's substeps (most over the bodies) and whether it fell back (`auto`, over its
/// budget, took one `implicit` step), the fall-backs since start-up, and the latest step refused
/// because it would have left the state non-finite (which integrator, which step).
#[derive(Resource, Debug, Default, Clone, Copy, PartialEq, Eq)]
pub struct StepStats {
    pub substeps: u32,
    pub fell_back: bool,
    pub fallbacks: u64,
    pub divergence: Option<(Integrator, u64)>,
}

/// The box's energy books, kept by the core's booked step ([`Books::step`]), and its energies.
///
/// Between two steps only the player changes the energy (attaching, moving or releasing the band,
/// changing k, resetting), so whatever the energy did between the end of one step and the start of
/// the next is booked as the hand's work; damping's share comes from the integrator. The residual
/// after each step ([`Books::residual`]) is the integrator's error.
#[derive(Resource, Debug, Default, Clone, Copy, PartialEq, Deref, DerefMut)]
pub struct EnergyBooks {
    #[deref]
    pub books: Books,
    /// The energies by kind right after the latest step.
    pub energies: Energies,
}

/// Sums the kinetic and band energy of every body, with the bands as they are now.
///
/// The Energy card reads it between steps; the step keeps the energies its booked step settled
/// at ([`EnergyBooks::energies`]).
pub(crate) fn mechanical_energies(
    params: &SceneParams,
    bodies: &Query<RigidBodyQueryReadOnly, With<RigidBox>>,
    bands: &Query<&Band>,
) -> Energies {
    let kinetic: Energies = bodies
        .iter()
        .map(|body| Energies::of(&body.state(), body.mass, None, params.stiffness))
        .sum();
    let band = bands
        .iter()
        .filter_map(|band| {
            let body = bodies.get(band.body).ok()?;
            Some(band.ends.potential_energy(&body.state(), params.stiffness))
        })
        .sum();
    Energies { band, ..kinetic }
}

/// Returns the band that acts on `body` in the next step: the first on it.
///
/// The scene has one band a body; the pointer never makes a second, and the step ignores one. The
/// step's observers (`PhysicsSystems::Observe`: the recorder, the ghosts) read it as the step's
/// input.
pub(crate) fn acting_band(body: Entity, bands: &Query<&Band>) -> Option<BandEnds> {
    bands
        .iter()
        .find(|band| band.body == body)
        .map(|band| band.ends)
}

/// A rigid body as the step moves it (avian's `RigidBodyQuery` is the model).
///
/// Its state, its mass, what acts on it and what is drawn of it. Read-only ([`Bodies`]), it is what
/// the rest of the game reads of the box.
#[derive(QueryData)]
#[query_data(mutable)]
pub struct RigidBodyQuery {
    pub entity: Entity,
    pub linear: &'static mut LinearState,
    pub angular: &'static mut AngularState,
    pub mass: &'static MassProperties,
    pub accumulator: &'static mut ForceAccumulator,
    pub snapshots: &'static mut RenderSnapshots,
}

impl RigidBodyQueryItem<'_, '_> {
    /// Returns the core's state, joined from the two components.
    pub fn state(&self) -> BodyState {
        body_state(&self.linear, &self.angular)
    }

    fn set_state(&mut self, state: BodyState) {
        *self.linear = state.linear;
        *self.angular = state.angular;
    }
}

impl RigidBodyQueryReadOnlyItem<'_, '_> {
    /// Returns the core's state, joined from the two components.
    pub fn state(&self) -> BodyState {
        body_state(self.linear, self.angular)
    }
}

/// The boxes, read.
pub type Bodies<'w, 's> = Query<'w, 's, RigidBodyQueryReadOnly, With<RigidBox>>;

/// The boxes, as the step moves them.
type Moving<'w, 's> = Query<'w, 's, RigidBodyQuery, With<RigidBox>>;

/// Puts every schedule the app has now on the single-threaded executor.
///
/// For one box the multi-threaded one costs many times more per tick (docs/benchmarks.md). The
/// benchmarks and the side-by-side with the peers measure with it.
pub fn run_single_threaded(app: &mut App) {
    let mut schedules = app.world_mut().resource_mut::<Schedules>();
    for (_, schedule) in schedules.iter_mut() {
        schedule.set_executor(SingleThreadedExecutor::new());
    }
}

/// Fixed steps run since start-up.
#[derive(Resource, Debug, Default, Clone, Copy, PartialEq, Eq)]
pub struct StepCount(pub u64);

/// Joins a body's two state components into the core's state.
pub fn body_state(linear: &LinearState, angular: &AngularState) -> BodyState {
    BodyState {
        linear: *linear,
        angular: *angular,
    }
}

/// Applies the scene's step rate to the fixed clock, or refuses it with a message.
///
/// Bevy's fixed clock counts whole nanoseconds and panics on a zero step: a rate it cannot
/// represent is refused with a message, and the clock keeps its step.
fn apply_step_rate(params: Res<SceneParams>, mut time: ResMut<Time<Fixed>>) {
    set_step_rate(&params, &mut time);
}

/// Sets the fixed clock's step to the rate of `params`: the one place the step is written.
///
/// A rate the clock cannot keep is refused with a message, and the clock keeps its step.
fn set_step_rate(params: &SceneParams, time: &mut Time<Fixed>) {
    let step = params
        .validate()
        .map_err(|error| error.to_string())
        .and_then(|()| Duration::try_from_secs_f64(params.dt()).map_err(|e| e.to_string()))
        .and_then(|step| {
            (!step.is_zero())
                .then_some(step)
                .ok_or_else(|| "the step is shorter than a nanosecond".to_owned())
        });
    match step {
        Ok(step) => time.set_timestep(step),
        Err(error) => error!(
            "refusing the step rate {} Hz ({error}); keeping {:?}",
            params.step_rate_hz,
            time.timestep()
        ),
    }
}

/// The game clock's pace: the time scale and whether it is paused (`Time<Virtual>`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Clock {
    pub speed: f64,
    pub paused: bool,
}

impl Clock {
    /// Returns the pace of `time`.
    pub fn of(time: &Time<Virtual>) -> Self {
        Self {
            speed: time.relative_speed_f64(),
            paused: time.is_paused(),
        }
    }
}

/// The box put at a state with a mass, as learn mode found it (sent back as it leaves).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlacedBox {
    pub state: BodyState,
    pub mass: MassProperties,
}

/// Feed the fixed clock exactly one step of time (the single step, while paused).
#[derive(Event, Debug, Clone, Copy, Default)]
pub struct StepOnce;

/// Takes the scene's parameters, with the fixed clock's step and the box's mass and size, at once.
///
/// At once, so that the steps still to come in this frame (a replay's settings record) take
/// them; and here, the parameters' one writer, so that no system asks every frame whether they
/// changed. The box keeps its state. Only a valid scene reaches here (the controls refuse the
/// rest).
fn set_params(
    apply: On<Apply<SceneParams>>,
    mut params: ResMut<SceneParams>,
    mut time: ResMut<Time<Fixed>>,
    mut boxes: Query<&mut MassProperties, With<RigidBox>>,
) {
    *params = apply.0;
    set_step_rate(&params, &mut time);
    if let Ok(wanted) = params.mass_properties() {
        for mut mass in &mut boxes {
            mass.set_if_neq(wanted);
        }
    }
}

/// Sets the clock's pace.
fn set_clock(apply: On<Apply<Clock>>, mut time: ResMut<Time<Virtual>>) {
    let Clock { speed, paused } = apply.0;
    time.set_relative_speed_f64(speed);
    if paused {
        time.pause();
    } else {
        time.unpause();
    }
}

/// Feeds the fixed clock one step of time, so that one step runs while paused.
fn step_once(_step: On<StepOnce>, mut time: ResMut<Time<Fixed>>) {
    let step = time.timestep();
    time.accumulate_overstep(step);
}

/// Puts every box at the state and mass sent.
fn place_the_box(
    apply: On<Apply<PlacedBox>>,
    mut commands: Commands,
    boxes: Query<Entity, With<RigidBox>>,
) {
    let PlacedBox { state, mass } = apply.0;
    for body in &boxes {
        commands.entity(body).insert(rigid_box(mass, state));
    }
}

/// Returns the box as components, in `state`, with nothing acting on it yet.
///
/// Every box is made or put back this way (the game, reset, the benchmarks, the side-by-side).
/// Its render snapshots both hold `state`, so the first frame drawn never jumps.
pub fn rigid_box(mass: MassProperties, state: BodyState) -> impl Bundle {
    (RigidBox, mass, placed(state))
}

/// Returns a box's state as components, put there rather than stepped.
///
/// Nothing acts on it yet, and both render snapshots hold `state`, so the frame drawn never
/// slides.
pub fn placed(state: BodyState) -> impl Bundle {
    (
        state.linear,
        state.angular,
        ForceAccumulator::default(),
        RenderSnapshots::at_rest(state),
    )
}

/// Spawns the box at rest at the centre of the scene.
fn spawn_box(mut commands: Commands, params: Res<SceneParams>) {
    match params.mass_properties() {
        Ok(mass) => {
            let rest = BodyState::at_rest(DVec2::ZERO);
            commands.spawn((Name::new("Box"), rigid_box(mass, rest)));
        }
        Err(error) => error!("cannot spawn the box: {error}"),
    }
}

/// Puts every box back at rest at the centre and starts the run's books, statistics and clock over.
///
/// Each box keeps its mass.
fn reset_bodies_and_books(
    _reset: On<ResetScene>,
    mut commands: Commands,
    boxes: Query<(Entity, &MassProperties), With<RigidBox>>,
    (mut stats, mut books): (ResMut<StepStats>, ResMut<EnergyBooks>),
    (mut reset_at, time): (ResMut<ResetAt>, Res<Time<Fixed>>),
) {
    reset_at.0 = time.elapsed_secs_f64();
    for (entity, mass) in &boxes {
        let rest = BodyState::at_rest(DVec2::ZERO);
        commands.entity(entity).insert(rigid_box(*mass, rest));
    }
    *stats = StepStats::default();
    *books = EnergyBooks::default();
}

/// Everything that says how to take a step (the step reads it, and so does the recorder).
#[derive(SystemParam)]
pub(crate) struct StepSettings<'w> {
    pub time: Res<'w, Time<Fixed>>,
    pub params: Res<'w, SceneParams>,
    pub integrator: Res<'w, Integrator>,
    pub auto: Res<'w, AutoSettings>,
}

/// What the step keeps account of: the energy books, the integrator's statistics, the count.
#[derive(SystemParam)]
struct StepRecords<'w> {
    books: ResMut<'w, EnergyBooks>,
    stats: ResMut<'w, StepStats>,
    count: ResMut<'w, StepCount>,
}

/// Takes the fixed step: [`accumulate`], [`integrate`], and the step counted.
///
/// It is one system because each system a step costs Bevy about as much again as the box's physics
/// (docs/peers.md).
fn step(settings: StepSettings, bands: Query<&Band>, mut bodies: Moving, mut records: StepRecords) {
    accumulate(&settings.params, &bands, &mut bodies);
    integrate(&settings, &mut bodies, &mut records);
    records.count.0 += 1;
}

/// Puts the band's force on each body (one band a body).
///
/// The force k·(anchor − corner) acts at its corner, with its torque r × F.
fn accumulate(params: &SceneParams, bands: &Query<&Band>, bodies: &mut Moving) {
    for band in bands {
        let Ok(mut body) = bodies.get_mut(band.body) else {
            continue;
        };
        if body.accumulator.band.is_some() {
            // The scene has one band per body; the pointer never makes a second.
            warn_once!("a second band on one body is ignored");
            continue;
        }
        let wrench = band.ends.wrench(&body.state(), params.stiffness);
        body.accumulator.forces.applied += wrench;
        body.accumulator.band = Some(band.ends);
    }
}

/// Advances each body by the core's booked step under what was accumulated and damping.
///
/// Damping adds −b·v and −c·I·ω. The step books the hand's work since the last one and damping's
/// share, and refuses a state the game cannot play. Either way the accumulator is emptied, the
/// render snapshots move on, and the energies the books settled at are kept by kind, summed
/// over the bodies. The scene has one box, whose books the game keeps; the benchmarks' extra
/// boxes share them.
fn integrate(settings: &StepSettings, bodies: &mut Moving, records: &mut StepRecords) {
    let StepSettings {
        time,
        params,
        integrator,
        auto,
    } = settings;
    let dt = time.timestep().as_secs_f64();
    let stats = &mut *records.stats;
    stats.substeps = 0;
    stats.fell_back = false;
    let step = records.count.0 + 1;
    let mut energies = Energies::default();
    for mut body in bodies.iter_mut() {
        let mut stepper = Stepper {
            params: **params,
            mass: *body.mass,
            state: body.state(),
            band: body.accumulator.band,
            integrator: **integrator,
            auto: **auto,
        };
        let mut forces = body.accumulator.forces;
        forces.damping += damping_wrench(
            &stepper.state,
            body.mass,
            params.linear_damping,
            params.angular_damping,
        );
        *body.accumulator = ForceAccumulator::default();
        let booked = records
            .books
            .step_accumulated(&mut stepper, forces, dt, Bound::Playable);
        stats.substeps = stats.substeps.max(booked.info.substeps);
        stats.fell_back |= booked.info.fell_back;
        stats.fallbacks += u64::from(booked.info.fell_back);
        // A divergent explicit method (a stiff band) must not put NaN, infinity or an absurd
        // value into a component, nor fling the box past where it can be drawn: the step is
        // refused, the last playable state kept, and the game says so.
        if booked.refused {
            if stats.divergence.is_none() {
                warn!(
                    "integrator {} diverged at step {step}: step refused",
                    **integrator
                );
            }
            stats.divergence = Some((**integrator, step));
        }
        energies = energies + booked.energies;
        body.set_state(stepper.state);
        body.snapshots.previous = body.snapshots.current;
        body.snapshots.current = stepper.state;
    }
    records.books.energies = energies;
}
