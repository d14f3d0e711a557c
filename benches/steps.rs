//! Criterion benchmarks: one core step per integrator; one headless `App` fixed step with the
//! box and its band beside an empty `App` (the ECS floor); and N boxes each with a band.
//!
//! Run: `cargo bench --bench steps` (add `-- core` to run one group).

use std::hint::black_box;
use std::time::Duration;

use bevy::math::DVec2;
use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};

use rubber_band_box::physics::scenario::TUTORIAL_PULL_TARGET;
use rubber_band_box::physics::{BandEnds, BodyState, Integrator, SceneParams, Stepper};
use rubber_band_box::simulation::{
    Band, RigidBox, SimulationPlugin, rigid_box, run_single_threaded,
};

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

/// A headless app whose every `update()` runs one 10 ms fixed step, every schedule on the
/// single-threaded executor (on two cores the multi-threaded one costs far more per update for
/// a scene this small: README, "Benchmarks").
fn headless_app(physics: bool, boxes: usize, single_threaded: bool) -> App {
    let mut app = App::new();
    app.add_plugins(MinimalPlugins)
        .insert_resource(Time::<Fixed>::from_hz(100.0))
        .insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_millis(
            10,
        )));
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
    group.finish();
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

criterion_group!(benches, core_step, app_tick, many_boxes);
criterion_main!(benches);
