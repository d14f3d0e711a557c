//! Criterion benchmarks: one core step per integrator; `auto` on the stiff pulls the report
//! sets against the peers; the Taylor engine alone, as compiled for any processor and as run; one headless `App` fixed step with the
//! box and its band beside an empty `App` (the ECS floor); N boxes each with a band; and a
//! scene's step with the ghosts on and off.
//!
//! Run: `cargo bench --bench steps` (add `-- core` to run one group).

use std::hint::black_box;
use std::time::Duration;

use bevy::math::DVec2;
use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};

use rubber_band_box::game::ghosts::GhostsPlugin;
use rubber_band_box::game::schedule::PhysicsSystems;
use rubber_band_box::game::shared::SharedPlugin;
use rubber_band_box::game::shared::{Overlay, Overlays};
use rubber_band_box::game::simulation::{
    Band, RigidBox, SimulationPlugin, rigid_box, run_single_threaded,
};
use rubber_band_box::measure::references::StiffCase;
use rubber_band_box::physics::scenes::TUTORIAL_PULL_TARGET;
use rubber_band_box::physics::{BandEnds, BodyState, Integrator, Run, Scene, SceneParams, Stepper};

fn core_step(c: &mut Criterion) {
    let mut group = c.benchmark_group("core_step");
    for integrator in Integrator::ALL {
        let mut stepper = Stepper::new(SceneParams::tutorial()).unwrap();
        stepper.integrator = integrator;
        stepper.grab(TUTORIAL_PULL_TARGET);
        // Start from a moving state so that every method does its real work.
        for _ in 0..50 {
            stepper.step(0.01);
        }
        let start = stepper.state;
        let mut steps = 0;
        group.bench_function(integrator.name(), |b| {
            b.iter(|| {
                stepper.step(black_box(0.01));
                steps += 1;
                if steps == 10_000 {
                    stepper.state = start;
                    steps = 0;
                }
            })
        });
    }
    group.finish();
}

/// `auto` on the stiff pulls the side-by-side times against the peers (docs/peers.md): one
/// iteration is the case's whole run, its ticks from the scene's start.
fn stiff_auto(c: &mut Criterion) {
    let mut group = c.benchmark_group("stiff_auto");
    for (k, rate) in [
        (1e5, 100.0),
        (1e6, 100.0),
        (1e6, 64.0),
        (1e7, 100.0),
        (1e7, 64.0),
    ] {
        let case = StiffCase::new(k, rate);
        let dt = 1.0 / rate;
        group.bench_function(format!("k{k:e}/{rate}Hz/{}ticks", case.ticks), |b| {
            b.iter(|| {
                let mut run = Run::of(&case.scene, Integrator::Auto, dt).expect("valid");
                for _ in 0..case.ticks {
                    run.advance().expect("stable");
                }
                black_box(run.stepper.state)
            })
        });
    }
    group.finish();
}

/// The Taylor engine alone, one fixed step of `auto`'s settings from a state half way through
/// the stiff case's run (k = 20: the tutorial's pull), compiled for any processor and, on an
/// x86-64 with AVX, for its four-lane registers: the two side by side in one run.
fn taylor_lanes(c: &mut Criterion) {
    use rubber_band_box::physics::AutoSettings;
    use rubber_band_box::physics::integrators::taylor::{self, TaylorSettings};
    let mut group = c.benchmark_group("taylor_lanes");
    for (k, rate) in [
        (20.0, 100.0),
        (1e6, 100.0),
        (1e6, 64.0),
        (1e7, 100.0),
        (1e7, 64.0),
    ] {
        let case = StiffCase::new(k, rate);
        let dt = 1.0 / rate;
        let mut run = Run::of(&case.scene, Integrator::Auto, dt).expect("valid");
        run.advance_by(case.ticks / 2).expect("stable");
        let (state, model) = (run.stepper.state, run.stepper.model());
        let auto = AutoSettings::default();
        let settings = TaylorSettings {
            order: auto.order,
            tolerance: auto.tolerance,
            max_steps: auto.max_substeps,
        };
        let label = format!("k{k:e}/{rate}Hz");
        group.bench_function(format!("{label}/portable"), |b| {
            b.iter(|| taylor::integrate_portable(black_box(&state), &model, dt, &settings))
        });
        group.bench_function(format!("{label}/as_run"), |b| {
            b.iter(|| taylor::integrate(black_box(&state), &model, dt, &settings))
        });
    }
    group.finish();
}

/// A headless app whose every `update()` runs one 10 ms fixed step, every schedule on the
/// single-threaded executor (on two cores the multi-threaded one costs far more per update for
/// a scene this small: docs/benchmarks.md).
/// Returns a headless `App` whose clock takes one 10 ms fixed step (100 Hz) each update.
fn bare_app() -> App {
    let mut app = App::new();
    app.add_plugins(MinimalPlugins)
        .insert_resource(Time::<Fixed>::from_hz(100.0))
        .insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_millis(
            10,
        )));
    app
}

fn headless_app(physics: bool, boxes: usize, single_threaded: bool) -> App {
    let mut app = bare_app();
    if physics {
        app.add_plugins(SimulationPlugin);
    }
    app.finish();
    app.cleanup();
    app.update(); // starts the clock, runs Startup (spawns the box)
    if physics {
        let params = SceneParams::tutorial();
        let mass = params.mass_properties().unwrap();
        let world = app.world_mut();
        let mut existing = world.query_filtered::<Entity, With<RigidBox>>();
        let mut bodies: Vec<Entity> = existing.iter(world).collect();
        for i in bodies.len()..boxes {
            let state = BodyState::at_rest(DVec2::new(i as f64, 0.0));
            bodies.push(world.spawn(rigid_box(mass, state)).id());
        }
        for body in bodies {
            world.spawn(Band {
                body,
                ends: BandEnds {
                    local_point: DVec2::new(30.0, 30.0),
                    anchor: TUTORIAL_PULL_TARGET,
                },
            });
        }
    }
    if single_threaded {
        run_single_threaded(&mut app);
    }
    app.update();
    app
}

fn app_tick(c: &mut Criterion) {
    let mut group = c.benchmark_group("app_tick");
    for (executor, single) in [("single_threaded", true), ("multi_threaded", false)] {
        let mut empty = headless_app(false, 0, single);
        group.bench_function(format!("empty/{executor}"), |b| b.iter(|| empty.update()));
        let mut scene = headless_app(true, 1, single);
        group.bench_function(format!("box_and_band/{executor}"), |b| {
            b.iter(|| scene.update())
        });
    }
    // The plugin's machinery without its physics, a part at a time: what an empty `App` pays
    // for one system in the fixed schedule, and for the settings check before the fixed loop.
    for (name, part) in [
        ("one_empty_fixed_system", Machinery::FixedSystem),
        ("settings_check", Machinery::SettingsCheck),
    ] {
        let mut app = machinery_app(part);
        group.bench_function(format!("{name}/single_threaded"), |b| {
            b.iter(|| app.update())
        });
    }
    group.finish();
}

/// A part of the plugin's machinery, alone in an otherwise empty `App`.
#[derive(Clone, Copy)]
enum Machinery {
    /// A system in `FixedUpdate` that does nothing.
    FixedSystem,
    /// A system before the fixed loop that runs only when `SceneParams` changes (never here).
    SettingsCheck,
}

fn machinery_app(part: Machinery) -> App {
    fn nothing() {}
    let mut app = bare_app();
    app.init_resource::<SceneParams>();
    match part {
        Machinery::FixedSystem => app.add_systems(FixedUpdate, nothing),
        Machinery::SettingsCheck => app.add_systems(
            RunFixedMainLoop,
            nothing.run_if(resource_changed::<SceneParams>),
        ),
    };
    app.finish();
    app.cleanup();
    app.update();
    run_single_threaded(&mut app);
    app.update();
    app
}

fn many_boxes(c: &mut Criterion) {
    let mut group = c.benchmark_group("boxes_with_bands");
    group.sample_size(10);
    for boxes in [1, 100, 10_000, 100_000] {
        let mut app = headless_app(true, boxes, true);
        group.throughput(Throughput::Elements(boxes as u64));
        group.bench_with_input(BenchmarkId::from_parameter(boxes), &boxes, |b, _| {
            b.iter(|| app.update())
        });
    }
    group.finish();
}

/// One fixed step of a scene's box and band in a headless `App`, the anchor circling as a hand
/// would (so the band never settles), with every ghost stepping beside it and without: what
/// the ghosts cost a frame (docs/lab.md).
fn ghosts(c: &mut Criterion) {
    let mut group = c.benchmark_group("ghosts");
    // The tutorial's band, the stiff scene's (k = 1e5), and the stiffest the game allows,
    // where the reference runs out of its substep budget.
    for (scene, stiffness) in [("tutorial", None), ("stiff", None), ("stiff", Some(1e12))] {
        for on in [false, true] {
            let mut app = ghost_app(scene, stiffness, on);
            let k = stiffness.map_or(String::new(), |k| format!("-k{k:e}"));
            let label = format!("{scene}{k}/{}", if on { "on" } else { "off" });
            group.bench_function(label, |b| b.iter(|| app.update()));
        }
    }
    group.finish();
}

fn ghost_app(scene: &str, stiffness: Option<f64>, ghosts_on: bool) -> App {
    let mut scene = Scene::named(scene).unwrap();
    if let Some(k) = stiffness {
        scene.params.stiffness = k;
    }
    let mut overlays = Overlays::default();
    overlays.set(Overlay::Ghosts, ghosts_on);
    let mut app = bare_app();
    app.insert_resource(scene.params)
        .insert_resource(overlays)
        .add_plugins((SharedPlugin, SimulationPlugin, GhostsPlugin))
        .add_systems(FixedUpdate, circle_the_anchor.before(PhysicsSystems::Step));
    app.finish();
    app.cleanup();
    app.update();
    let mass = scene.params.mass_properties().unwrap();
    let world = app.world_mut();
    let body = world
        .query_filtered::<Entity, With<RigidBox>>()
        .single(world)
        .unwrap();
    world.spawn(Band {
        body,
        ends: BandEnds::grabbing(&mass, &BodyState::default(), TUTORIAL_PULL_TARGET),
    });
    run_single_threaded(&mut app);
    app.update();
    app
}

/// The anchor around a circle of 200 px, a turn every 2 s.
fn circle_the_anchor(mut bands: Query<&mut Band>, mut step: Local<u32>) {
    *step += 1;
    let angle = f64::from(*step) * std::f64::consts::PI / 100.0;
    for mut band in &mut bands {
        band.ends.anchor = 200.0 * DVec2::new(angle.cos(), angle.sin());
    }
}

criterion_group!(
    benches,
    core_step,
    stiff_auto,
    taylor_lanes,
    app_tick,
    many_boxes,
    ghosts
);
criterion_main!(benches);
