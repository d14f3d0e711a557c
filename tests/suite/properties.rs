//! Property tests: random scenes, states, pulls and input sequences. Nothing panics, nothing
//! non-finite reaches a component, there is never more than one band, and the default
//! integrator never diverges. About 1e5 generated cases in all; set RBB_LONG=1 for ten times
//! as many (`RBB_LONG=1 cargo test --release --test suite properties::`).

use crate::common;

use std::time::Duration;

use bevy::input::ButtonState;
use bevy::input::touch::TouchPhase;
use bevy::math::DVec2;
use bevy::prelude::*;
use bevy::window::WindowFocused;
use proptest::prelude::*;

use common::{Action, Game, Overlay, key};
use rubber_band_box::game::pointer::Grip;
use rubber_band_box::game::simulation::{ForceAccumulator, RigidBox, Tap};
use rubber_band_box::physics::{
    AngularState, BodyState, Integrator, LinearState, MIN_STEP, Pull, Run, SceneParams, Stepper,
    kinetic_energy,
};

fn cases(n: u32) -> ProptestConfig {
    let long = std::env::var("RBB_LONG").is_ok_and(|v| v == "1");
    ProptestConfig {
        cases: if long { n * 10 } else { n },
        failure_persistence: None,
        ..ProptestConfig::default()
    }
}

/// log-uniform in [low, high].
fn log_uniform(low: f64, high: f64) -> impl Strategy<Value = f64> {
    (low.log10()..=high.log10()).prop_map(|e| 10f64.powf(e))
}

fn scene() -> impl Strategy<Value = SceneParams> {
    (
        log_uniform(1e-3, 1e3),
        log_uniform(1.0, 500.0),
        log_uniform(1.0, 500.0),
        prop_oneof![Just(0.0), log_uniform(1e-2, 1e9)],
        prop_oneof![Just(0.0), log_uniform(1e-3, 1e2)],
        prop_oneof![Just(0.0), log_uniform(1e-3, 1e2)],
    )
        .prop_map(|(mass, w, h, k, b, c)| SceneParams {
            mass,
            size: DVec2::new(w, h),
            stiffness: k,
            linear_damping: b,
            angular_damping: c,
            step_rate_hz: 100.0,
        })
}

fn point(range: f64) -> impl Strategy<Value = DVec2> {
    (-range..=range, -range..=range).prop_map(|(x, y)| DVec2::new(x, y))
}

fn state() -> impl Strategy<Value = BodyState> {
    (point(500.0), point(1e3), -10.0..10.0, -100.0..100.0).prop_map(|(x, v, theta, omega)| {
        BodyState {
            linear: LinearState {
                position: x,
                velocity: v,
            },
            angular: AngularState {
                orientation: theta,
                angular_velocity: omega,
            },
        }
    })
}

fn pulls() -> impl Strategy<Value = Vec<Pull>> {
    prop::collection::vec(
        (0u64..100, 1u64..100, prop_oneof![point(500.0), point(1e6)]).prop_map(
            |(start, length, target)| Pull {
                start,
                end: start + length,
                target,
            },
        ),
        0..4,
    )
}

fn integrator() -> impl Strategy<Value = Integrator> {
    prop::sample::select(Integrator::ALL.to_vec())
}

proptest! {
    #![proptest_config(cases(20_000))]

    /// Any integrator on any scene: the run completes, or its divergence is reported at the
    /// first step whose state is not sane, and the run is left at the last sane state before
    /// it (the step refused, as the game refuses it). The default never diverges.
    #[test]
    fn a_divergence_is_the_first_bad_step_and_leaves_the_last_sane_state(
        params in scene(),
        initial in state(),
        pulls in pulls(),
        integrator in integrator(),
        dt in log_uniform(1e-4, 0.1),
    ) {
        let fresh = || Run::new(params, initial, pulls.clone(), integrator, dt).unwrap();
        let mut run = fresh();
        match run.advance_by(120) {
            Ok(()) => prop_assert_eq!(run.step, 120),
            Err(d) => {
                prop_assert!(integrator != Integrator::default(), "the default diverged: {}", d);
                prop_assert_eq!(run.step + 1, d.step);
                prop_assert_eq!(d.time, d.step as f64 * dt);
                prop_assert!(run.stepper.state.is_sane());
                // Stepped by hand, one step at a time, every step before the reported one
                // is sane and the run reaches the very state it was left at.
                // Alongside, the refusal bound recomputed from the run's inputs (see
                // `DIVERGENCE_FACTOR`, src/physics/scenes.rs): 1e3 times the reachable energy,
                // the initial kinetic energy plus the band's energy at each attachment, plus 1 J.
                let active = |step: u64| {
                    pulls.iter().rposition(|pull| pull.start <= step && step < pull.end)
                };
                let band_energy = |run: &Run| {
                    run.stepper.band.map_or(0.0, |band| {
                        band.potential_energy(&run.stepper.state, params.stiffness)
                    })
                };
                let mut by_hand = fresh();
                // A pull active at step 0 attached its band in `Run::new`.
                let mut reachable =
                    kinetic_energy(&initial, &by_hand.stepper.mass) + band_energy(&by_hand);
                for _ in 1..d.step {
                    let before = active(by_hand.step);
                    prop_assert!(by_hand.advance().is_ok());
                    prop_assert!(by_hand.stepper.state.is_sane());
                    let now = active(by_hand.step);
                    if now.is_some() && now != before {
                        reachable += band_energy(&by_hand);
                    }
                }
                prop_assert_eq!(by_hand.stepper.state, run.stepper.state);
                let bound = 1e3 * reachable + 1.0;
                // The reported step itself, taken by the stepper under the run, is not sane
                // or ends above that bound.
                let mut stepper = by_hand.stepper.clone();
                stepper.step(dt);
                let energy = stepper.energy();
                prop_assert!(
                    !stepper.state.is_sane()
                        || !energy.is_finite()
                        || energy > bound,
                    "step {} was refused but looks sane: energy {energy}, bound {bound}", d.step
                );
            }
        }
    }
}

proptest! {
    #![proptest_config(cases(40_000))]

    /// Validation accepts exactly the domain: mass, size, rate finite and positive, the rate
    /// at most a step a microsecond; k, b, c finite and not negative. Nothing panics either
    /// way.
    #[test]
    fn validation_accepts_exactly_the_domain(
        values in prop::collection::vec(
            prop_oneof![
                Just(f64::NAN), Just(f64::INFINITY), Just(f64::NEG_INFINITY),
                Just(0.0), Just(-0.0), -1e6..1e6, log_uniform(1e-300, 1e300),
            ],
            7,
        ),
    ) {
        let params = SceneParams {
            mass: values[0],
            size: DVec2::new(values[1], values[2]),
            stiffness: values[3],
            linear_damping: values[4],
            angular_damping: values[5],
            step_rate_hz: values[6],
        };
        let positive = |v: f64| v.is_finite() && v > 0.0;
        let non_negative = |v: f64| v.is_finite() && v >= 0.0;
        let inertia = params.mass * (params.size.x.powi(2) + params.size.y.powi(2)) / 12.0;
        let valid = positive(params.mass) && positive(params.size.x) && positive(params.size.y)
            && positive(inertia) && positive(params.step_rate_hz)
            && params.step_rate_hz <= 1.0 / MIN_STEP
            && non_negative(params.stiffness) && non_negative(params.linear_damping)
            && non_negative(params.angular_damping);
        prop_assert_eq!(params.validate().is_ok(), valid);
        prop_assert_eq!(Stepper::new(params).is_ok(), valid);
    }
}

proptest! {
    #![proptest_config(cases(40_000))]

    /// With damping and no band, the default integrator never adds energy.
    #[test]
    fn damped_motion_without_a_band_never_gains_energy(
        params in scene(),
        b in log_uniform(1e-3, 1e2),
        c in log_uniform(1e-3, 1e2),
        initial in state(),
        dt in log_uniform(1e-4, 0.1),
    ) {
        let params = SceneParams { linear_damping: b, angular_damping: c, ..params };
        let mut stepper = Stepper::new(params).unwrap();
        stepper.state = initial;
        let mut energy = kinetic_energy(&stepper.state, &stepper.mass);
        for _ in 0..20 {
            stepper.step(dt);
            let now = kinetic_energy(&stepper.state, &stepper.mass);
            prop_assert!(now <= energy * (1.0 + 1e-12), "{} -> {}", energy, now);
            energy = now;
        }
    }
}

proptest! {
    #![proptest_config(cases(4_000))]

    /// The Taylor engine as the machine runs it (on an x86-64 with AVX, compiled for its wide
    /// registers) and as compiled for any processor (what the browser runs) agree to the bit:
    /// the replays' hashes rest on it.
    #[test]
    fn the_engine_gives_the_same_bits_however_it_is_compiled(
        params in scene(),
        initial in state(),
        anchor in point(1e3),
        order in 2usize..=rubber_band_box::physics::integrators::taylor::MAX_ORDER,
        tolerance in log_uniform(1e-15, 1e-6),
    ) {
        use rubber_band_box::physics::integrators::taylor::{self, TaylorSettings};
        let mut stepper = Stepper::new(params).unwrap();
        stepper.state = initial;
        stepper.grab(anchor);
        let model = stepper.model();
        let settings = TaylorSettings { order, tolerance, max_steps: 200 };
        let bits = |done: Option<taylor::Integrated>| {
            done.map(|d| (d.state.to_array().map(f64::to_bits), d.steps, d.orders, d.dissipated.to_bits()))
        };
        let run = bits(taylor::integrate(&initial, &model, 0.01, &settings));
        let portable = bits(taylor::integrate_portable(&initial, &model, 0.01, &settings));
        prop_assert_eq!(run, portable);
    }
}

/// One thing a player, a window system or a clock can do between two frames.
#[derive(Clone, Debug)]
enum Input {
    Press(Vec2),
    Move(Option<Vec2>),
    Release,
    Tap(Vec2),
    FocusLost,
    Touch(u64, TouchPhase, Vec2),
    Frame(Duration),
    Key(KeyCode),
}

fn screen() -> impl Strategy<Value = Vec2> {
    // The window is 1280 x 720; some points fall outside it.
    (-100.0f32..1400.0, -100.0f32..850.0).prop_map(|(x, y)| Vec2::new(x, y))
}

fn input() -> impl Strategy<Value = Input> {
    prop_oneof![
        screen().prop_map(Input::Press),
        prop::option::of(screen()).prop_map(Input::Move),
        Just(Input::Release),
        screen().prop_map(Input::Tap),
        Just(Input::FocusLost),
        (
            0u64..3,
            prop::sample::select(vec![
                TouchPhase::Started,
                TouchPhase::Moved,
                TouchPhase::Ended,
                TouchPhase::Canceled
            ]),
            screen()
        )
            .prop_map(|(id, phase, at)| Input::Touch(id, phase, at)),
        prop_oneof![Just(0u64), 0u64..50_000_000, Just(10_000_000_000)]
            .prop_map(|ns| Input::Frame(Duration::from_nanos(ns))),
        prop::sample::select(vec![
            key(Action::TogglePause),
            key(Action::Step),
            key(Action::Reset),
            key(Action::NextIntegrator),
            key(Action::Softer),
            key(Action::Stiffer),
            key(Action::Slower),
            key(Action::Faster),
            key(Action::FewerSteps),
            key(Action::MoreSteps),
            key(Action::Toggle(Overlay::Vectors)),
            key(Action::Toggle(Overlay::Trail)),
        ])
        .prop_map(Input::Key),
    ]
}

proptest! {
    #![proptest_config(cases(300))]

    /// Random input into the headless game: no panic, finite components, at most one band,
    /// none once nothing holds it, accumulators empty after every step.
    #[test]
    fn the_game_survives_any_input(
        inputs in prop::collection::vec(input(), 1..40),
        integrator in integrator(),
        k in prop_oneof![Just(20.0), log_uniform(1.0, 1e9)],
    ) {
        let mut game = Game::stepping();
        game.world().insert_resource(integrator);
        game.world().resource_mut::<SceneParams>().stiffness = k;
        for input in inputs {
            match input {
                Input::Press(at) => {
                    game.cursor(Some(at));
                    game.mouse(ButtonState::Pressed);
                }
                Input::Move(at) => game.cursor(at),
                Input::Release => game.mouse(ButtonState::Released),
                Input::Tap(at) => {
                    game.cursor(Some(at));
                    game.mouse(ButtonState::Pressed);
                    game.mouse(ButtonState::Released);
                }
                Input::FocusLost => {
                    let window = game.window;
                    game.world().write_message(WindowFocused { window, focused: false });
                }
                Input::Touch(id, phase, at) => game.touch_screen(id, phase, at),
                Input::Key(key) => game.tap_key(key),
                Input::Frame(frame) => {
                    game.world()
                        .insert_resource(bevy::time::TimeUpdateStrategy::ManualDuration(frame));
                }
            }
            game.update(1);

            let bands = game.bands();
            prop_assert!(bands.len() <= 1, "{} bands", bands.len());
            if game.world().resource::<Grip>().0.is_none() {
                // A tap's band lives for exactly one fixed step; a frame may run none.
                let mut taps = game.world().query_filtered::<(), With<Tap>>();
                let tapping = taps.iter(game.world()).count();
                prop_assert!(bands.len() == tapping, "a band outlived its release");
            }
            let (linear, angular) = game.state();
            prop_assert!(linear.position.is_finite() && linear.velocity.is_finite());
            prop_assert!(angular.orientation.is_finite() && angular.angular_velocity.is_finite());
            // The books balance to `auto`'s error whenever it never fell back (a fall-back is
            // an `implicit` step, which damps; k may have been stiff before it was soft).
            let books = *game.world().resource::<rubber_band_box::game::simulation::EnergyBooks>();
            let stats = *game.world().resource::<rubber_band_box::game::simulation::StepStats>();
            let auto = *game.world().resource::<Integrator>() == Integrator::Auto;
            let soft = game.world().resource::<SceneParams>().stiffness <= 1e4;
            let never_fell_back = stats.fallbacks == 0;
            if auto && soft && never_fell_back && integrator == Integrator::Auto
                && books.ledger.throughput() > 0.0
            {
                let relative = books.residual().abs() / books.ledger.throughput();
                prop_assert!(relative < 1e-6, "books off by {}", relative);
            }
            let audit = game.world().resource::<common::AccumulatorAudit>();
            prop_assert_eq!(audit.largest, 0.0);
            prop_assert_eq!(audit.bands_left, 0);
            let mut accumulators = game.world().query_filtered::<&ForceAccumulator, With<RigidBox>>();
            for accumulator in accumulators.iter(game.world()) {
                prop_assert_eq!(*accumulator, ForceAccumulator::default());
            }
        }
    }
}
