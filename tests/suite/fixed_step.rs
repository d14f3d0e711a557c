//! The fixed step as the schedule runs it: the physics independent of the frame rate and equal
//! to the core's, a long frame's bounded catch-up, refused steps and rates, the energy books,
//! the drawn state between steps, and the frame's order (every schedule checked for
//! ambiguities). Headless `App`s: `MinimalPlugins` plus the game without its screen, time
//! driven by `TimeUpdateStrategy`.

use crate::common;

use common::*;

#[test]
fn with_no_band_the_box_stays_exactly_at_rest_and_accumulators_are_zero_after_every_step() {
    let mut game = Game::stepping();
    let start = game.state();
    game.update(300);
    assert_eq!(game.steps(), 300);
    assert_eq!(game.state(), start);
    assert_eq!(start.0.position, DVec2::ZERO);

    game.press_at(DVec2::new(200.0, 150.0));
    game.update(100);
    assert_ne!(game.state(), start);
    let audit = game.world().resource::<AccumulatorAudit>();
    assert_eq!(audit.steps, 400);
    assert_eq!(audit.largest, 0.0);
    assert_eq!(audit.bands_left, 0);
}

#[test]
fn a_pull_turns_the_box_the_way_r_cross_f_says() {
    // Pulling the upper-right corner (r = (30, 30)) to the right: r x F < 0, clockwise.
    let mut game = Game::stepping();
    game.press_at(DVec2::new(200.0, 30.0));
    game.update(20);
    let (linear, angular) = game.state();
    assert!(linear.velocity.x > 0.0);
    assert!(angular.angular_velocity < 0.0 && angular.orientation < 0.0);

    // Pulling the same corner straight up: r x F > 0, counter-clockwise.
    let mut game = Game::stepping();
    game.press_at(DVec2::new(30.0, 200.0));
    game.update(20);
    let (linear, angular) = game.state();
    assert!(linear.velocity.y > 0.0);
    assert!(angular.angular_velocity > 0.0 && angular.orientation > 0.0);

    // Pulling along the diagonal through the centre: no torque (up to the f32 pixels the
    // pointer passes through; tests/core.rs checks the exact case).
    let mut game = Game::stepping();
    game.press_at(DVec2::new(150.0, 150.0));
    game.update(50);
    let (linear, angular) = game.state();
    assert!(linear.velocity.x > 10.0);
    assert!((linear.velocity.x - linear.velocity.y).abs() < 1e-4 * linear.velocity.x);
    assert!(angular.angular_velocity.abs() < 1e-6);
}

#[test]
fn after_release_the_velocities_decay_at_the_damping_rates() {
    let params = SceneParams::tutorial();
    let dt = params.dt();
    let linear_rate = params.linear_damping / params.mass;
    let angular_rate = params.angular_damping;
    for integrator in Integrator::ALL {
        let mut game = Game::stepping();
        game.world().insert_resource(integrator);
        game.press_at(DVec2::new(200.0, 30.0));
        game.update(30);
        game.mouse(ButtonState::Released);
        game.update(1);
        assert!(game.bands().is_empty());

        let (linear0, angular0) = game.state();
        assert!(angular0.angular_velocity.abs() > 0.01, "{integrator}");
        let frames = 100;
        let mut previous = (linear0, angular0);
        let mut first_ratios = None;
        for _ in 0..frames {
            game.update(1);
            let now = game.state();
            let linear_ratio = now.0.velocity / previous.0.velocity;
            let angular_ratio = now.1.angular_velocity / previous.1.angular_velocity;
            // Each step scales the velocities by the same factor, near exp(-rate dt); `auto`
            // may change its substeps as the motion slows, so it is held to exp itself.
            if integrator == Integrator::Auto {
                let exact = ((-linear_rate * dt).exp(), (-angular_rate * dt).exp());
                assert!((linear_ratio - DVec2::splat(exact.0)).abs().max_element() < 1e-9);
                assert!((angular_ratio - exact.1).abs() < 1e-9);
            } else {
                let ratios = *first_ratios.get_or_insert((linear_ratio, angular_ratio));
                assert!(
                    (linear_ratio - ratios.0).abs().max_element() < 1e-12,
                    "{integrator}"
                );
                assert!((angular_ratio - ratios.1).abs() < 1e-12, "{integrator}");
            }
            assert!(
                (linear_ratio.x - linear_ratio.y).abs() < 1e-12,
                "{integrator}"
            );
            previous = now;
        }
        // Over one second: each method's own decay factor per step, a hundred times over,
        // to round-off. A damping taken at another point of the step (its start instead of
        // the trapezoid, say) gives another factor and fails here.
        let (linear1, angular1) = previous;
        let angular_decay = angular1.angular_velocity / angular0.angular_velocity;
        let linear_decay = linear1.velocity.length() / linear0.velocity.length();
        let expected = |rate: f64, exact_for_seed: bool| {
            decay_factor(integrator, rate * dt, exact_for_seed).powi(frames)
        };
        let close = |a: f64, b: f64| (a / b - 1.0).abs() < 1e-9;
        assert!(
            close(angular_decay, expected(angular_rate, true)),
            "{integrator}: {angular_decay} {}",
            expected(angular_rate, true)
        );
        assert!(
            close(linear_decay, expected(linear_rate, false)),
            "{integrator}: {linear_decay} {}",
            expected(linear_rate, false)
        );
    }
}

/// What one step of `integrator` does to a velocity decaying at a rate with rate·dt = `x`
/// and no other force, from each method's formula: explicit Euler 1 − x, the trapezoid
/// (1 − x/2)/(1 + x/2), RK4 the exponential's series to x⁴, backward Euler 1/(1 + x), the
/// exponential itself for `auto` (and for `seed`'s angular damping, the tutorial's 0.98).
fn decay_factor(integrator: Integrator, x: f64, exact_for_seed: bool) -> f64 {
    match integrator {
        Integrator::Euler | Integrator::Symplectic => 1.0 - x,
        Integrator::Seed if !exact_for_seed => 1.0 - x,
        Integrator::Seed | Integrator::Auto => (-x).exp(),
        Integrator::Verlet => (1.0 - x / 2.0) / (1.0 + x / 2.0),
        Integrator::Rk4 => 1.0 - x + x * x / 2.0 - x.powi(3) / 6.0 + x.powi(4) / 24.0,
        Integrator::Implicit => 1.0 / (1.0 + x),
    }
}

/// The same two seconds of input at several frame rates. Input events happen at times every
/// frame rate reaches; each is delivered before the frame that starts at its time.
fn play_script(frames_per_second: u32) -> (LinearState, AngularState, u64) {
    let frame = Duration::from_nanos((1e9 / frames_per_second as f64).round() as u64);
    let mut game = Game::new(frame);
    let script: [(f64, Option<ButtonState>, DVec2); 6] = [
        (0.2, Some(ButtonState::Pressed), DVec2::new(200.0, 100.0)),
        (0.6, None, DVec2::new(-150.0, 180.0)),
        (1.0, None, DVec2::new(-220.0, -160.0)),
        (1.2, Some(ButtonState::Released), DVec2::new(-220.0, -160.0)),
        (1.4, Some(ButtonState::Pressed), DVec2::new(40.0, -200.0)),
        (1.8, Some(ButtonState::Released), DVec2::new(40.0, -200.0)),
    ];
    let total_frames = 2 * frames_per_second as usize;
    for n in 0..total_frames {
        let now = n as f64 / frames_per_second as f64;
        for (at, button, cursor) in script {
            if (at - now).abs() < 1e-9 {
                game.cursor(Some(world_to_screen(cursor)));
                if let Some(state) = button {
                    game.mouse(state);
                }
            }
        }
        game.update(1);
    }
    let (linear, angular) = game.state();
    (linear, angular, game.steps())
}

#[test]
fn the_physics_is_independent_of_the_frame_rate() {
    let reference = play_script(60);
    assert_eq!(reference.2, 200);
    assert!(reference.0.position.length() > 1.0);
    for fps in [25, 240] {
        assert_eq!(play_script(fps), reference, "{fps} frames per second");
    }
}

#[test]
fn the_schedule_steps_exactly_as_the_core_does() {
    let mut game = Game::stepping();
    let anchor = DVec2::new(-200.0, 120.0);
    game.press_at(anchor);
    game.update(150);
    game.mouse(ButtonState::Released);
    game.update(50);

    // The pointer's anchor went through f32 screen coordinates: use the one the game saw.
    let mut stepper = Stepper::new(SceneParams::tutorial()).unwrap();
    let seen_anchor = {
        let mut probe = Game::stepping();
        probe.press_at(anchor);
        probe.update(1);
        probe.the_band().ends.anchor
    };
    stepper.grab(seen_anchor);
    for _ in 0..150 {
        stepper.step(0.01);
    }
    stepper.release();
    for _ in 0..50 {
        stepper.step(0.01);
    }
    let (linear, angular) = game.state();
    assert_eq!(
        (linear, angular),
        (stepper.state.linear, stepper.state.angular)
    );
}

/// What makes the test above hold for every pair of systems: the headless game builds its
/// schedules with ambiguity detection as an error, so a system that writes what another reads,
/// with no order between them, stops the game before its first frame.
#[test]
#[should_panic(expected = "conflicting")]
fn an_unordered_pair_of_writers_fails_the_schedules_ambiguity_check() {
    fn grab_from_elsewhere(mut grip: ResMut<Grip>) {
        grip.0 = Some(PointerSource::Mouse);
    }
    let mut game = Game::with(Duration::from_millis(10), |app| {
        app.add_systems(
            RunFixedMainLoop,
            grab_from_elsewhere.in_set(RunFixedMainLoopSystems::BeforeFixedMainLoop),
        );
    });
    game.update(1);
}

#[test]
fn a_long_frame_catches_up_a_bounded_number_of_steps() {
    let mut game = Game::new(Duration::from_secs(10));
    game.press_at(DVec2::new(200.0, 100.0));
    game.update(1);
    // Bevy clamps a frame's virtual time to 250 ms: 25 steps, not 1000.
    assert_eq!(game.steps(), 25);
    let (linear, angular) = game.state();
    assert!(linear.position.is_finite() && angular.orientation.is_finite());
}

#[test]
fn the_integrator_key_switches_on_the_next_step_and_names_it_on_the_status_line() {
    let mut game = Game::stepping();
    assert_eq!(
        *game.world().resource::<Integrator>(),
        Integrator::default()
    );
    game.press_at(DVec2::new(200.0, 100.0));
    game.update(20);
    let expected_next = Integrator::default().next();

    // Replay the same 20 steps in the core, then one step of each integrator from there.
    let mut probe = Game::stepping();
    probe.press_at(DVec2::new(200.0, 100.0));
    probe.update(1);
    let mut stepper = Stepper::new(SceneParams::tutorial()).unwrap();
    stepper.grab(probe.the_band().ends.anchor);
    for _ in 0..20 {
        stepper.step(0.01);
    }
    stepper.integrator = expected_next;
    stepper.step(0.01);

    game.key(key(Action::NextIntegrator), ButtonState::Pressed);
    game.update(1);
    assert_eq!(*game.world().resource::<Integrator>(), expected_next);
    let (linear, angular) = game.state();
    assert_eq!(
        (linear, angular),
        (stepper.state.linear, stepper.state.angular)
    );
    let status = game.line("HUD Status");
    assert!(status.starts_with(expected_next.name()), "{status}");
}

#[test]
fn a_diverging_step_is_refused_and_the_state_stays_finite() {
    let mut game = Game::stepping();
    game.world().insert_resource(Integrator::Euler);
    game.world().resource_mut::<SceneParams>().stiffness = 1e9;
    game.press_at(DVec2::new(200.0, 100.0));
    game.update(30);
    let (linear, angular) = game.state();
    let finite = linear.position.is_finite()
        && linear.velocity.is_finite()
        && angular.orientation.is_finite()
        && angular.angular_velocity.is_finite();
    assert!(finite, "{linear:?} {angular:?}");
    let stats = *game.world().resource::<StepStats>();
    let (integrator, step) = stats.divergence.expect("the divergence is reported");
    assert_eq!(integrator, Integrator::Euler);
    assert!((1..=30).contains(&step), "{step}");
    let status = game.line("HUD Status");
    assert!(status.contains("euler DIVERGED at step"), "{status}");
}

#[test]
fn a_step_rate_the_clock_cannot_hold_is_refused_without_a_panic() {
    for rate in [1e300, f64::NAN, -5.0, 0.0] {
        let mut app = App::new();
        app.add_plugins((MinimalPlugins, SimulationPlugin))
            .insert_resource(SceneParams::tutorial());
        app.update();
        // A good rate first (100 Hz), so "kept" is a step Bevy's 64 Hz default could not fake.
        let step = app.world().resource::<Time<Fixed>>().timestep();
        assert_eq!(step, Duration::from_millis(10), "the good rate first");
        app.world_mut().resource_mut::<SceneParams>().step_rate_hz = rate;
        app.update();
        let step = app.world().resource::<Time<Fixed>>().timestep();
        assert_eq!(
            step,
            Duration::from_millis(10),
            "{rate} Hz must leave the step at 10 ms"
        );
    }
}

#[test]
fn the_games_energy_books_balance_to_the_integrators_error() {
    let residual_of = |integrator: Integrator| {
        let mut game = Game::stepping();
        game.world().insert_resource(integrator);
        game.press_at(DVec2::new(200.0, 100.0));
        game.update(40);
        // The hand moves the anchor: work the books must take in.
        for target in [DVec2::new(-150.0, 120.0), DVec2::new(50.0, -180.0)] {
            game.cursor(Some(world_to_screen(target)));
            game.update(40);
        }
        game.mouse(ButtonState::Released);
        game.update(80);
        let books = *game.world().resource::<EnergyBooks>();
        assert!(books.ledger.work_moved > 0.0 && books.ledger.dissipated > 0.0);
        books.residual().abs() / books.ledger.throughput()
    };
    let auto = residual_of(Integrator::Auto);
    assert!(auto < 1e-9, "auto: {auto}");
    let euler = residual_of(Integrator::Euler);
    assert!(euler > 1e-4, "euler's error shows in the books: {euler}");
}

/// The drawn state lies between the last two steps, as far along as the clock has run past
/// the last one: with frames shorter than a step and a steady pull, the drawn box moves
/// forward every frame. (Previous and current swapped, it would jump back within each step:
/// jitter no other test would see.)
#[test]
fn the_drawn_state_moves_forward_every_frame_between_steps() {
    use rubber_band_box::game::simulation::RenderSnapshots;
    use rubber_band_box::game::simulation::interpolated_state;
    let mut game = Game::new(Duration::from_millis(7));
    // Along the diagonal from rest: x grows for the first half period, about 1.5 s.
    game.press_at(DVec2::new(150.0, 150.0));
    let mut drawn = Vec::new();
    for _ in 0..80 {
        game.update(1);
        let world = game.world();
        let snapshots = *world
            .query::<&RenderSnapshots>()
            .single(world)
            .expect("one box");
        let fixed = world.resource::<Time<Fixed>>();
        let x = interpolated_state(&snapshots, fixed).linear.position.x;
        let (low, high) = (
            snapshots.previous.linear.position.x,
            snapshots.current.linear.position.x,
        );
        assert!(low <= x && x <= high, "{low} <= {x} <= {high}");
        drawn.push(x);
    }
    let moving = drawn.iter().position(|&x| x > 0.0).expect("the box moves");
    assert!(moving < 5, "{drawn:?}");
    for pair in drawn[moving..].windows(2) {
        assert!(pair[1] > pair[0], "the drawn box went back: {drawn:?}");
    }
}

/// The screen's plugins (the camera and interpolation, the drawing, the energy graph, the plot) join the
/// headless game's schedules without a window or a renderer: Bevy's gizmos and assets run
/// headless, so their systems are checked for ambiguities with the rest of the frame like
/// every other, and the frame runs with the box pulled, the vectors, the trail and the ghosts
/// drawn.
#[test]
fn the_screens_plugins_join_the_frame_without_an_ambiguity() {
    let mut game = Game::with(Duration::from_millis(10), add_the_screen);
    game.press_at(DVec2::new(200.0, 100.0));
    for key in [KeyCode::KeyV, KeyCode::KeyT, KeyCode::KeyG] {
        game.tap_key(key);
    }
    game.update(5);
    assert!(game.steps() >= 5, "the frame ran");
}

/// A step the integrator cannot take is refused and named by its number: explicit Euler on a
/// band of k = 1e12 diverges within a few steps; the step said is the one counted, the box
/// keeps its last sane state, and each later step refused is named in turn.
#[test]
fn a_divergence_names_the_step_it_refused() {
    let mut game = Game::stepping();
    *game.world().resource_mut::<Integrator>() = Integrator::Euler;
    game.world().resource_mut::<SceneParams>().stiffness = 1e12;
    game.press_at(DVec2::new(200.0, 100.0));
    let mut first = None;
    for _ in 0..50 {
        game.update(1);
        if let Some((integrator, step)) = game.world().resource::<StepStats>().divergence {
            assert_eq!(integrator, Integrator::Euler);
            assert_eq!(
                step,
                game.steps(),
                "the refused step is the one just counted"
            );
            first = Some(step);
            break;
        }
    }
    let first = first.expect("explicit Euler diverges at k = 1e12");
    assert!(first >= 1);
    let (linear, angular) = game.state();
    assert!(linear.position.is_finite() && angular.orientation.is_finite());
    game.update(3);
    let steps = game.steps();
    assert_eq!(
        game.world().resource::<StepStats>().divergence,
        Some((Integrator::Euler, steps)),
        "the latest refused step"
    );
}

/// A step that runs out of `auto`'s budget falls back to `implicit` and is counted: each such
/// step adds one to the fall-backs, a step that does not adds none.
#[test]
fn fall_backs_are_counted_a_step_each() {
    let mut game = Game::stepping();
    game.world().resource_mut::<SceneParams>().stiffness = 1e9;
    game.press_at(DVec2::new(200.0, 100.0));
    game.update(1);
    let mut last = game.world().resource::<StepStats>().fallbacks;
    for _ in 0..3 {
        game.update(1);
        let stats = game.world().resource::<StepStats>();
        assert!(stats.fell_back, "k = 1e9 is over auto's budget at 100 Hz");
        assert_eq!(stats.fallbacks, last + 1);
        last = stats.fallbacks;
    }
    game.world().resource_mut::<SceneParams>().stiffness = 20.0;
    game.update(2);
    let stats = game.world().resource::<StepStats>();
    assert!(!stats.fell_back);
    assert_eq!(stats.fallbacks, last);
}

/// The heaviest settings (4096 Hz, ×16, the ghosts and the plot on, k = 1e12) with frames of
/// a quarter second: a frame owes 16,384 steps, and with the game's wall budget each update
/// runs at most the budget's steps, the status line says the game falls behind, and a pause
/// sent in one frame holds from the next (issue 51).
#[test]
fn the_heaviest_settings_keep_each_frame_within_its_budget() {
    use rubber_band_box::game::input::controls::{Action, Parameter};
    use rubber_band_box::game::shared::Overlay;
    let mut game = Game::new(Duration::from_millis(250));
    game.world().insert_resource(FrameBudget::default());
    for action in [
        Action::Set(Parameter::Stiffness, 1e12),
        Action::Toggle(Overlay::Ghosts),
        Action::Toggle(Overlay::Plot),
    ]
    .into_iter()
    .chain([Action::MoreSteps; 6])
    .chain([Action::Faster; 4])
    {
        game.world().write_message(action);
    }
    game.update(1);
    assert_eq!(game.world().resource::<SceneParams>().step_rate_hz, 4096.0);
    game.press_at(DVec2::new(200.0, 100.0));
    for _ in 0..8 {
        let before = game.steps();
        game.update(1);
        let taken = game.steps() - before;
        assert!(
            (1..=u64::from(FrameBudget::MAX_STEPS)).contains(&taken),
            "{taken} steps in one update"
        );
        let budget = *game.world().resource::<FrameBudget>();
        assert!(
            budget.dropped > Duration::ZERO,
            "the time owed past the budget is dropped"
        );
    }
    assert!(game.line("HUD Status").contains("behind"));
    game.world().write_message(Action::TogglePause);
    game.update(1);
    let paused_at = game.steps();
    game.update(3);
    assert_eq!(game.steps(), paused_at, "a pause holds from the next frame");
}

/// Two presses of one key between two frames are two actions: the keys are read as
/// messages, not as "just pressed" (a slow frame never eats a press).
#[test]
fn every_key_press_counts_even_several_in_one_frame() {
    let mut game = Game::stepping();
    let k = game.world().resource::<SceneParams>().stiffness;
    for _ in 0..3 {
        game.tap_key(KeyCode::BracketRight);
    }
    game.update(1);
    let now = game.world().resource::<SceneParams>().stiffness;
    assert!(
        (now / k - 1e3).abs() < 1e-6,
        "k {k} to {now}: three presses, ×1000"
    );
}
