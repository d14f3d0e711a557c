//! The physics plugin: the box's state as components, the band as an entity, and the fixed
//! step as one system in the frame's `schedule::PhysicsSystems::Step`: the hand's work booked,
//! forces and torques accumulated, the integration (and what damping took out booked), then
//! the results published (render snapshots, the energy books settled, taps ended, the step
//! counted). It owns the body, the energy books and the step statistics, and puts them back on
//! [`ResetScene`].
//!
//! Headless, and usable alone (the benchmarks and the side-by-side with the peers run it
//! without the rest of the game). Every system is a thin loop over the numerical core in
//! [`crate::physics`].

use std::time::Duration;

use bevy::ecs::schedule::{Schedules, SingleThreadedExecutor};
use bevy::ecs::system::SystemParam;
use bevy::math::DVec2;
use bevy::prelude::*;

use crate::game::schedule::{self, GameSystems, PhysicsSystems};
use crate::physics::{
    AngularState, AutoSettings, BandEnds, BodyState, Energies, EnergyLedger, Forces, Integrator,
    LinearState, MassProperties, SceneParams, damping_wrench,
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
            .init_resource::<StepStats>()
            .init_resource::<StepCount>()
            .init_resource::<EnergyBooks>()
            .add_systems(Startup, spawn_box)
            .add_observer(reset_bodies_and_books)
            // The step rate can change during play (a control): applied before the loop.
            .add_systems(
                RunFixedMainLoop,
                (apply_step_rate, apply_mass)
                    .run_if(resource_changed::<SceneParams>)
                    .in_set(GameSystems::ApplySettings),
            )
            .add_systems(FixedUpdate, step.in_set(PhysicsSystems::Step));
    }
}

/// The scene back at its start: the box at rest at the centre, no band, the books, the
/// statistics, the graph and the trail started over. Triggered by the reset control; each
/// plugin observes it for the state it owns.
#[derive(Event, Debug, Clone, Copy, Default)]
pub struct ResetScene;

/// Marks the pulled box.
#[derive(Component, Debug, Default)]
#[require(LinearState, AngularState, ForceAccumulator, RenderSnapshots)]
pub struct RigidBox;

/// What acts on a body during the current step: the summed forces and torques, and the band
/// whose force the integrator evaluates again at its intermediate states. Filled and emptied
/// within the step: empty between steps.
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

/// A band that was pressed and released within one frame: it acts for exactly one fixed step,
/// so that a quick click is never lost, and is then removed.
#[derive(Component, Debug, Default)]
pub struct Tap;

/// The state before and after the latest fixed step, for drawing in between.
#[derive(Component, Debug, Default, Clone, Copy)]
pub struct RenderSnapshots {
    pub previous: BodyState,
    pub current: BodyState,
}

impl RenderSnapshots {
    pub fn at_rest(state: BodyState) -> Self {
        Self {
            previous: state,
            current: state,
        }
    }

    /// The state a fraction `alpha` (0 to 1) of the way from the previous step to the current.
    pub fn interpolate(&self, alpha: f64) -> BodyState {
        let (a, b) = (self.previous.to_array(), self.current.to_array());
        BodyState::from_array(std::array::from_fn(|i| a[i] + (b[i] - a[i]) * alpha))
    }
}

/// What the integrator did: the latest step's substeps (most over the bodies) and whether it
/// fell back (`auto`, over its budget, took one `implicit` step), the fall-backs since
/// start-up, and the latest step refused because it would have left the state non-finite
/// (which integrator, which step).
#[derive(Resource, Debug, Default, Clone, Copy, PartialEq, Eq)]
pub struct StepStats {
    pub substeps: u32,
    pub fell_back: bool,
    pub fallbacks: u64,
    pub divergence: Option<(Integrator, u64)>,
}

/// The energy ledger of the game. Between two steps only the player changes the energy
/// (attaching, moving or releasing the band, changing k, resetting), so whatever the energy
/// did between the end of one step and the start of the next is booked as the hand's work;
/// damping's share comes from the integrator. The residual after each step is the
/// integrator's error.
#[derive(Resource, Debug, Default, Clone, Copy, PartialEq)]
pub struct EnergyBooks {
    pub ledger: EnergyLedger,
    /// Mechanical energy right after the latest step; None before the first.
    pub settled: Option<f64>,
    /// The ledger's residual after the latest step.
    pub residual: f64,
    /// The energies by kind right after the latest step.
    pub energies: Energies,
}

/// Kinetic and band energy of every body, with the bands as they are now.
pub fn mechanical_energies(
    params: &SceneParams,
    bodies: &Bodies,
    bands: &Query<&Band>,
) -> Energies {
    energies_of(
        params,
        bodies
            .iter()
            .map(|(linear, angular, mass)| (body_state(linear, angular), mass)),
        bands.iter().filter_map(|band| {
            let (linear, angular, _) = bodies.get(band.body).ok()?;
            Some((band.ends, body_state(linear, angular)))
        }),
    )
}

/// Kinetic energy of the bodies given, and band energy of the bands given with their body's
/// state.
fn energies_of<'m>(
    params: &SceneParams,
    bodies: impl Iterator<Item = (BodyState, &'m MassProperties)>,
    bands: impl Iterator<Item = (BandEnds, BodyState)>,
) -> Energies {
    let kinetic: Energies = bodies
        .map(|(state, mass)| Energies::of(&state, mass, None, params.stiffness))
        .sum();
    let band = bands
        .map(|(ends, state)| ends.potential_energy(&state, params.stiffness))
        .sum();
    Energies { band, ..kinetic }
}

/// The band that acts on `body` in the next step: the first on it (the scene has one band a
/// body; the pointer never makes a second, and the step ignores one). What the step's
/// observers (`PhysicsSystems::Observe`: the recorder, the ghosts) read as its input.
pub fn acting_band(body: Entity, bands: &Query<&Band>) -> Option<BandEnds> {
    bands
        .iter()
        .find(|band| band.body == body)
        .map(|band| band.ends)
}

/// The bodies the energy books count: their state and mass.
pub type Bodies<'w, 's> = Query<
    'w,
    's,
    (
        &'static LinearState,
        &'static AngularState,
        &'static MassProperties,
    ),
    With<RigidBox>,
>;

/// Puts every schedule the app has now on the single-threaded executor: for one box the
/// multi-threaded one costs many times more per tick (docs/benchmarks.md). The benchmarks
/// and the side-by-side with the peers measure with it.
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

/// The fixed clock's step set to `seconds`, if the clock can keep it (it counts whole
/// nanoseconds and panics on a zero step); whether it was set.
pub fn set_fixed_step(time: &mut Time<Fixed>, seconds: f64) -> bool {
    match Duration::try_from_secs_f64(seconds) {
        Ok(step) if !step.is_zero() => {
            time.set_timestep(step);
            true
        }
        _ => false,
    }
}

/// Bevy's fixed clock counts whole nanoseconds and panics on a zero step: a rate it cannot
/// represent is refused with a message, and the clock keeps its step.
pub fn apply_step_rate(params: Res<SceneParams>, mut time: ResMut<Time<Fixed>>) {
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

/// The box's mass and size as the scene's parameters say (the mass slider, a link): its
/// state kept. A valid scene only reaches here (the controls refuse the rest).
pub fn apply_mass(params: Res<SceneParams>, mut boxes: Query<&mut MassProperties, With<RigidBox>>) {
    if let Ok(wanted) = params.mass_properties() {
        for mut mass in &mut boxes {
            mass.set_if_neq(wanted);
        }
    }
}

/// The box as components, in `state`, with nothing acting on it yet: the one way every box
/// is made or put back (the game, reset, the benchmarks, the side-by-side). Its render
/// snapshots both hold `state`, so the first frame drawn never jumps.
pub fn rigid_box(mass: MassProperties, state: BodyState) -> impl Bundle {
    (
        RigidBox,
        mass,
        state.linear,
        state.angular,
        ForceAccumulator::default(),
        RenderSnapshots::at_rest(state),
    )
}

/// Spawns the box at rest at the centre of the scene.
pub fn spawn_box(mut commands: Commands, params: Res<SceneParams>) {
    match params.mass_properties() {
        Ok(mass) => {
            let rest = BodyState::at_rest(DVec2::ZERO);
            commands.spawn((Name::new("Box"), rigid_box(mass, rest)));
        }
        Err(error) => error!("cannot spawn the box: {error}"),
    }
}

/// Every box back at rest at the centre (its mass kept), and the books and statistics of the
/// run started over.
fn reset_bodies_and_books(
    _reset: On<ResetScene>,
    mut commands: Commands,
    boxes: Query<(Entity, &MassProperties), With<RigidBox>>,
    mut stats: ResMut<StepStats>,
    mut books: ResMut<EnergyBooks>,
) {
    for (entity, mass) in &boxes {
        let rest = BodyState::at_rest(DVec2::ZERO);
        commands.entity(entity).insert(rigid_box(*mass, rest));
    }
    *stats = StepStats::default();
    *books = EnergyBooks::default();
}

/// Everything that says how to take a step (the step reads it, and so does the recorder).
#[derive(SystemParam)]
pub struct StepSettings<'w> {
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

/// The bodies the step moves.
type Moving<'w, 's> = Query<
    'w,
    's,
    (
        &'static mut LinearState,
        &'static mut AngularState,
        &'static MassProperties,
        &'static mut ForceAccumulator,
        &'static mut RenderSnapshots,
    ),
    With<RigidBox>,
>;

/// The fixed step, in one system (each system a step costs Bevy about as much again as the
/// box's physics: docs/peers.md), in three phases:
/// - accumulate: the hand's work since the last step booked, then on each body the band's
///   force k·(anchor − corner) at its corner with its torque r × F, and damping's force −b·v
///   and torque −c·I·ω;
/// - integrate with the `Integrator` resource (a step that would leave the state non-finite
///   is refused; damping's share booked; the accumulator emptied);
/// - publish: the render snapshots moved on, the energy books settled (the energies now, the
///   residual), a tap's band removed after its one step, the step counted.
fn step(
    mut commands: Commands,
    settings: StepSettings,
    bands: Query<&Band>,
    taps: Query<Entity, (With<Band>, With<Tap>)>,
    mut bodies: Moving,
    mut records: StepRecords,
) {
    let StepSettings {
        time,
        params,
        integrator,
        auto,
    } = settings;
    let books = &mut *records.books;
    let stats = &mut *records.stats;
    let energies_now = |bodies: &Moving| {
        energies_of(
            &params,
            bodies
                .iter()
                .map(|(linear, angular, mass, ..)| (body_state(linear, angular), mass)),
            bands.iter().filter_map(|band| {
                let (linear, angular, ..) = bodies.get(band.body).ok()?;
                Some((band.ends, body_state(linear, angular)))
            }),
        )
    };

    // Accumulate.
    books
        .ledger
        .open_step(books.settled, energies_now(&bodies).total());
    for band in &bands {
        let Ok((linear, angular, _, mut accumulator, _)) = bodies.get_mut(band.body) else {
            continue;
        };
        if accumulator.band.is_some() {
            // The scene has one band per body; the pointer never makes a second.
            warn_once!("a second band on one body is ignored");
            continue;
        }
        accumulator.forces.applied += band
            .ends
            .wrench(&body_state(&linear, &angular), params.stiffness);
        accumulator.band = Some(band.ends);
    }

    // Integrate.
    let dt = time.timestep().as_secs_f64();
    stats.substeps = 0;
    stats.fell_back = false;
    let step = records.count.0 + 1;
    for (mut linear, mut angular, mass, mut accumulator, mut snapshots) in &mut bodies {
        let mut state = body_state(&linear, &angular);
        let mut forces = accumulator.forces;
        forces.damping +=
            damping_wrench(&state, mass, params.linear_damping, params.angular_damping);
        let model = params.force_model(*mass, accumulator.band);
        *accumulator = ForceAccumulator::default();
        let info = integrator.step_with(&mut state, &model, forces, dt, &auto);
        stats.substeps = stats.substeps.max(info.substeps);
        stats.fell_back |= info.fell_back;
        stats.fallbacks += u64::from(info.fell_back);
        // A divergent explicit method (a stiff band) must not put NaN, infinity or an absurd
        // value into a component: refuse the step, keep the last sane state, and say so.
        if state.is_sane() {
            books.ledger.dissipated += info.dissipated;
            *linear = state.linear;
            *angular = state.angular;
        } else {
            if stats.divergence.is_none() {
                warn!(
                    "integrator {} diverged at step {step}: step refused",
                    *integrator
                );
            }
            stats.divergence = Some((*integrator, step));
        }
        // Publish, for this body.
        snapshots.previous = snapshots.current;
        snapshots.current = body_state(&linear, &angular);
    }

    // Publish.
    let energies = energies_now(&bodies);
    books.energies = energies;
    books.settled = Some(energies.total());
    books.residual = books.ledger.residual(energies.total());
    for band in &taps {
        commands.entity(band).despawn();
    }
    records.count.0 = step;
}
