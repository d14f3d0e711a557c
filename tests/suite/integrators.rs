//! The integrators against closed forms, invariants, the tutorial and the hard cases.

use bevy::math::DVec2;
use rubber_band_box::measure::references::diagonal_exact;
use rubber_band_box::measure::report::hard_cases;
use rubber_band_box::physics::scenes::TUTORIAL_PULL_TARGET;
use rubber_band_box::physics::{
    AutoSettings, BodyState, Integrator, Pull, Run, Scene, SceneParams, Stepper,
    angular_momentum_about,
};

/// The largest pose error against the closed form over 2 s of the diagonal pull.
fn diagonal_error(integrator: Integrator, dt: f64) -> f64 {
    let scene = Scene::named("diagonal").unwrap();
    let mass = scene.params.mass_properties().unwrap();
    let mut run = Run::of(&scene, integrator, dt).unwrap();
    let steps = (2.0 / dt).round() as u64;
    let mut worst: f64 = 0.0;
    for _ in 0..steps {
        run.advance().unwrap();
        let exact = diagonal_exact(run.time());
        worst = worst.max(run.stepper.state.pose_error(&exact, &mass));
    }
    worst
}

#[test]
fn each_integrator_converges_on_the_diagonal_pull_at_its_order() {
    // `auto` picks its substeps for a target error, so it has no fixed order in dt: see below.
    for integrator in Integrator::ALL
        .into_iter()
        .filter(|&i| i != Integrator::Auto)
    {
        let errors: Vec<f64> = [0.02, 0.01, 0.005]
            .iter()
            .map(|&dt| diagonal_error(integrator, dt))
            .collect();
        let expected = integrator.order() as f64;
        for pair in errors.windows(2) {
            let observed = (pair[0] / pair[1]).log2();
            assert!(
                (observed - expected).abs() < 0.3,
                "{integrator}: errors {errors:?}, observed order {observed}"
            );
        }
        // And the error is small where it should be: the higher the order, the smaller.
        let bound = match integrator.order() {
            1 => 3.0,
            2 => 0.05,
            _ => 1e-4,
        };
        assert!(
            errors[1] < bound,
            "{integrator}: error {} at 100 Hz",
            errors[1]
        );
    }
}

#[test]
fn no_integrator_turns_the_box_on_the_diagonal_pull() {
    for integrator in Integrator::ALL {
        let mut run = Run::of(&Scene::named("diagonal").unwrap(), integrator, 0.01).unwrap();
        for _ in 0..500 {
            run.advance().unwrap();
            let s = run.stepper.state;
            assert_eq!(s.angular.angular_velocity, 0.0, "{integrator}");
            assert_eq!(s.angular.orientation, 0.0, "{integrator}");
            assert_eq!(s.linear.position.x, s.linear.position.y, "{integrator}");
        }
    }
}

/// Energy and angular momentum about the anchor over `steps` of the undamped scene.
struct InvariantDrift {
    energy_start: f64,
    energy_end: f64,
    /// Largest |E − E0| / E0 over the first and the last tenth of the run.
    energy_error_early: f64,
    energy_error_late: f64,
    momentum_error: f64,
}

fn undamped_drift(integrator: Integrator, steps: u64) -> Result<InvariantDrift, u64> {
    let scene = Scene::named("undamped").unwrap();
    let mut run = Run::of(&scene, integrator, 0.01).unwrap();
    let mass = run.stepper.mass;
    let anchor = TUTORIAL_PULL_TARGET;
    let e0 = run.stepper.energy();
    let l0 = angular_momentum_about(&run.stepper.state, &mass, anchor);
    let tenth = steps / 10;
    let mut drift = InvariantDrift {
        energy_start: e0,
        energy_end: e0,
        energy_error_early: 0.0,
        energy_error_late: 0.0,
        momentum_error: 0.0,
    };
    for step in 1..=steps {
        run.advance().map_err(|d| d.step)?;
        let e = run.stepper.energy();
        let error = (e - e0).abs() / e0;
        if step <= tenth {
            drift.energy_error_early = drift.energy_error_early.max(error);
        } else if step > steps - tenth {
            drift.energy_error_late = drift.energy_error_late.max(error);
        }
        let l = angular_momentum_about(&run.stepper.state, &mass, anchor);
        drift.momentum_error = drift.momentum_error.max((l - l0).abs());
        drift.energy_end = e;
    }
    Ok(drift)
}

#[test]
fn symplectic_methods_keep_the_invariants_over_a_million_steps() {
    for integrator in [Integrator::Symplectic, Integrator::Verlet] {
        let drift = undamped_drift(integrator, 1_000_000).unwrap();
        // Angular momentum about the anchor: kept to round-off (it starts at zero).
        assert!(
            drift.momentum_error < 1e-6,
            "{integrator}: {}",
            drift.momentum_error
        );
        // Energy: bounded, and no drift: the late error is no larger than the early one.
        assert!(drift.energy_error_early < 0.05, "{integrator}");
        assert!(
            drift.energy_error_late < 1.5 * drift.energy_error_early,
            "{integrator}: early {} late {}",
            drift.energy_error_early,
            drift.energy_error_late
        );
    }
}

#[test]
fn explicit_euler_gains_energy_rk4_and_implicit_lose_it() {
    // Forward Euler's energy grows every step until it diverges.
    let euler = undamped_drift(Integrator::Euler, 1_000_000);
    assert!(euler.is_err(), "explicit Euler should blow up undamped");
    let early = undamped_drift(Integrator::Euler, 10_000).unwrap();
    assert!(early.energy_end > 2.0 * early.energy_start);

    // RK4 loses a little energy, slowly; backward Euler damps it away.
    let rk4 = undamped_drift(Integrator::Rk4, 100_000).unwrap();
    assert!(rk4.energy_end < rk4.energy_start);
    assert!(rk4.energy_end > 0.99 * rk4.energy_start);
    let implicit = undamped_drift(Integrator::Implicit, 100_000).unwrap();
    assert!(implicit.energy_end < 0.01 * implicit.energy_start);
    // Neither is symplectic: the angular momentum about the anchor (zero at the start, kept
    // to round-off by the symplectic methods above) wanders, RK4's by a hair of its scale
    // m·|x − a|·|v| ~ 1e6, backward Euler's more as it damps the swing. Bounded, both, well
    // under that scale (docs/integrators.md has the figures).
    assert!(rk4.momentum_error < 1e-2, "rk4: {}", rk4.momentum_error);
    assert!(
        implicit.momentum_error < 1e4,
        "implicit: {}",
        implicit.momentum_error
    );
}

/// The tutorial's own update (tests/fixtures/tutorial_reference.py), in its per-frame units
/// on its y-down screen: frame, then position, orientation, velocity, angular velocity.
const TUTORIAL_FRAMES: [(u64, [f64; 6]); 6] = [
    (
        1,
        [
            320.068,
            239.964,
            0.0016000000000000005,
            0.068,
            -0.036,
            0.0016000000000000005,
        ],
    ),
    (
        2,
        [
            320.2032736153682,
            239.89235518464818,
            0.004757121285187285,
            0.13527361536818874,
            -0.07164481535180472,
            0.003157121285187284,
        ],
    ),
    (
        10,
        [
            323.60829768994404,
            238.0761454777484,
            0.07799525872265455,
            0.6430798911444234,
            -0.34489016744326745,
            0.01303283590573738,
        ],
    ),
    (
        30,
        [
            347.47630753624463,
            224.71482786848014,
            0.36735881415071736,
            1.62143836543809,
            -0.9386651459010016,
            0.009906700928932134,
        ],
    ),
    (
        31,
        [
            349.0815315180283,
            223.78554937403814,
            0.37706738106107085,
            1.605223981783709,
            -0.9292784944419916,
            0.00970856691035349,
        ],
    ),
    (
        50,
        [
            376.70632260478084,
            207.79331118068248,
            0.528711326484906,
            1.3261856879781275,
            -0.7677407349131463,
            0.006613792513948689,
        ],
    ),
];

/// The same transliteration with a frame of 1/64 s (its per-frame constants scaled from the
/// per-second ones: k by the frame squared, the drag by the frame, 0.98 to the power of the
/// frame in hundredths): `python3 tests/fixtures/tutorial_reference.py` prints both tables.
const TUTORIAL_FRAMES_64_HZ: [(u64, [f64; 6]); 6] = [
    (
        1,
        [
            320.166015625,
            239.912109375,
            0.00390625,
            0.166015625,
            -0.087890625,
            0.00390625,
        ],
    ),
    (
        2,
        [
            320.4951765391158,
            239.73767258256004,
            0.011532537307435082,
            0.32916091411578896,
            -0.1744367924399628,
            0.0076262873074350816,
        ],
    ),
    (
        20,
        [
            350.09617754481184,
            223.18877430922205,
            0.3819390710625411,
            2.611851369107679,
            -1.5205479837854052,
            0.013581943811300639,
        ],
    ),
    (
        40,
        [
            415.2415146378746,
            183.3344080533488,
            0.2604327630007317,
            3.596388040216323,
            -2.2437179204533337,
            -0.014330469787122766,
        ],
    ),
    (
        41,
        [
            418.78170911496255,
            181.12574822540253,
            0.24654759396607098,
            3.540194477087943,
            -2.2086598279462506,
            -0.01388516903466073,
        ],
    ),
    (
        60,
        [
            476.45847687803524,
            145.14231262926825,
            0.05125573084904511,
            2.624690226880439,
            -1.637494183563167,
            -0.007622111424152535,
        ],
    ),
];

/// `seed` at a step other than the tutorial's 0.01 s is still the tutorial's update, run with
/// that frame: the per-second constants convert exactly, at any step.
#[test]
fn seed_at_64_hz_reproduces_the_tutorials_update_run_at_that_frame() {
    let dt = 1.0 / 64.0;
    let pulls = vec![Pull {
        start: 0,
        end: 40,
        target: DVec2::new(200.0, 120.0),
    }];
    let mut run = Run::new(
        SceneParams::tutorial(),
        BodyState::default(),
        pulls,
        Integrator::Seed,
        dt,
    )
    .unwrap();
    for (frame, [x, y, theta, vx, vy, omega]) in TUTORIAL_FRAMES_64_HZ {
        run.advance_by(frame - run.step).unwrap();
        // y down to y up, per frame to per second.
        let expected = [x - 320.0, 240.0 - y, -theta, vx / dt, -vy / dt, -omega / dt];
        for (got, want) in run.stepper.state.to_array().iter().zip(expected) {
            assert!(
                (got - want).abs() <= 1e-12 * want.abs().max(1.0),
                "frame {frame}: {got} != {want}"
            );
        }
    }
}

#[test]
fn seed_reproduces_the_tutorials_trajectory_to_round_off() {
    // Screen (520, 120) is world (200, 120); pressed for 30 frames.
    let pulls = vec![Pull {
        start: 0,
        end: 30,
        target: DVec2::new(200.0, 120.0),
    }];
    let mut run = Run::new(
        SceneParams::tutorial(),
        BodyState::default(),
        pulls,
        Integrator::Seed,
        0.01,
    )
    .unwrap();
    for (frame, [x, y, theta, vx, vy, omega]) in TUTORIAL_FRAMES {
        run.advance_by(frame - run.step).unwrap();
        let s = run.stepper.state;
        // y down to y up, per frame to per second.
        let expected = [
            x - 320.0,
            240.0 - y,
            -theta,
            vx * 100.0,
            -vy * 100.0,
            -omega * 100.0,
        ];
        let got = [
            s.linear.position.x,
            s.linear.position.y,
            s.angular.orientation,
            s.linear.velocity.x,
            s.linear.velocity.y,
            s.angular.angular_velocity,
        ];
        for (g, e) in got.iter().zip(expected) {
            assert!(
                (g - e).abs() <= 1e-12 * e.abs().max(1.0),
                "frame {frame}: got {got:?}, tutorial {expected:?}"
            );
        }
    }
}

#[test]
fn the_default_integrator_never_diverges_on_a_hard_case() {
    let default = Integrator::default();
    for case in hard_cases(true) {
        let mut run = Run::of(&case.scene, default, 1.0 / case.rate).unwrap();
        // `Ok` is the check: every step taken, every state sane and within the energy bound.
        run.advance_by(case.steps)
            .unwrap_or_else(|d| panic!("{}: {d}", case.name));
    }
}

#[test]
fn every_integrator_stays_bounded_or_reports_its_divergence() {
    let mut diverged = Vec::new();
    for case in hard_cases(true) {
        for integrator in Integrator::ALL {
            let mut run = Run::of(&case.scene, integrator, 1.0 / case.rate).unwrap();
            // `Ok` needs no check: it already means every step was taken, every state sane.
            if let Err(d) = run.advance_by(case.steps) {
                // Reported at the step refused; the run stays at the last sane state.
                assert_eq!((d.integrator, d.step), (integrator, run.step + 1));
                assert!(run.stepper.state.is_sane(), "{} {integrator}", case.name);
                diverged.push((case.name.clone(), integrator));
            }
        }
    }
    // The explicit methods cannot hold a band this stiff; divergence is detected, not missed.
    for integrator in [Integrator::Euler, Integrator::Symplectic, Integrator::Rk4] {
        let case = "stiff band k = 1e9 at 100 Hz".to_owned();
        assert!(diverged.contains(&(case, integrator)), "{integrator}");
    }
}

/// A run refuses the first step that takes the state out of bounds, even with little energy:
/// the box near the limit, moving outward at 1000 px/s, leaves it at step 3 of 0.01 s.
#[test]
fn a_run_refuses_the_first_step_that_leaves_the_state_limit() {
    let undamped = Scene::named("undamped").unwrap().params;
    let near_limit = BodyState::from_array([1e12 - 25.0, 0.0, 0.0, 1000.0, 0.0, 0.0]);
    let mut run = Run::new(undamped, near_limit, vec![], Integrator::Rk4, 0.01).unwrap();
    run.advance_by(2).unwrap();
    let last_sane = run.stepper.state;
    assert_eq!(last_sane.linear.position.x, 1e12 - 5.0);
    let diverged = run.advance().unwrap_err();
    assert_eq!((diverged.step, diverged.time), (3, 3.0 * 0.01));
    assert_eq!((run.step, run.stepper.state), (2, last_sane));
}

/// A run refuses the first step whose energy exceeds 1000 times all it was given plus 1 J,
/// while the state is still within bounds: found here by stepping a copy by hand. The band
/// is stretched 1e-6 px (5e-8 J), so the 1 J term decides the step (1000 times the energy
/// alone would fire steps earlier).
#[test]
fn a_run_refuses_the_first_step_whose_energy_leaves_every_physical_bound() {
    let stiff = Scene::named("stiff").unwrap().params;
    let corner = DVec2::new(30.0, 30.0);
    let pull = Pull {
        start: 0,
        end: u64::MAX,
        target: corner + DVec2::new(1e-6, 0.0),
    };
    let mut run = Run::new(
        stiff,
        BodyState::default(),
        vec![pull],
        Integrator::Euler,
        0.01,
    )
    .unwrap();
    let mut by_hand = run.stepper.clone();
    let given = by_hand.energy();
    assert!(given > 0.0 && given < 1e-7, "{given}");
    let first_above = |bound: f64| {
        let mut stepper = by_hand.clone();
        (1..=1000u64).find(|_| {
            stepper.step(0.01);
            stepper.energy() > bound
        })
    };
    let expected = first_above(1e3 * given + 1.0).expect("euler diverges on this band");
    assert!(first_above(1e3 * given).unwrap() < expected);
    for _ in 1..expected {
        by_hand.step(0.01);
    }
    let last_sane = by_hand.state;
    by_hand.step(0.01);
    assert!(
        by_hand.state.is_sane(),
        "the energy must fire before the state limit"
    );

    let diverged = run.advance_by(1000).unwrap_err();
    assert_eq!(diverged.step, expected);
    assert_eq!(diverged.time, expected as f64 * 0.01);
    assert_eq!((run.step, run.stepper.state), (expected - 1, last_sane));
}

#[test]
fn a_zero_length_band_exerts_nothing() {
    for integrator in Integrator::ALL {
        let mut run = Run::of(&Scene::named("zero-length").unwrap(), integrator, 0.01).unwrap();
        run.advance_by(100).unwrap();
        assert_eq!(run.stepper.state, BodyState::default(), "{integrator}");
    }
}

#[test]
fn the_implicit_step_holds_a_very_stiff_band_at_its_corner() {
    let mut scene = Scene::named("stiff").unwrap();
    scene.params.stiffness = 1e9;
    let mut run = Run::of(&scene, Integrator::Implicit, 1.0 / 64.0).unwrap();
    run.advance_by(640).unwrap();
    let band = run.stepper.band.unwrap();
    assert!(band.length(&run.stepper.state) < 1e-3);
    // The box hangs from the corner, its centre on the line through the anchor.
    assert!(run.stepper.state.linear.velocity.length() < 1.0);
}

#[test]
fn integrator_names_round_trip_and_unknown_names_are_refused() {
    for integrator in Integrator::ALL {
        assert_eq!(integrator.name().parse::<Integrator>(), Ok(integrator));
    }
    let error = "rk5".parse::<Integrator>().unwrap_err().to_string();
    assert!(error.contains("rk5") && error.contains("verlet"), "{error}");
    let mut seen = Integrator::default();
    for _ in 0..Integrator::ALL.len() {
        seen = seen.next();
    }
    assert_eq!(seen, Integrator::default());
}

#[test]
fn auto_meets_its_tolerance_at_any_step() {
    // On the diagonal pull, whatever the fixed step, the error stays near the tolerance per
    // step times the number of steps, far below plain RK4 at the coarse steps.
    for dt in [1.0 / 30.0, 0.01, 0.001] {
        let auto = diagonal_error(Integrator::Auto, dt);
        assert!(auto < 1e-5, "dt {dt}: auto error {auto}");
        if dt > 0.02 {
            assert!(auto < diagonal_error(Integrator::Rk4, dt) / 10.0);
        }
    }
}

#[test]
fn auto_takes_more_substeps_for_a_stiffer_band_and_falls_back_beyond_its_budget() {
    let settings = AutoSettings::default();
    let substeps_at = |k: f64| {
        let mut scene = Scene::named("stiff").unwrap();
        scene.params.stiffness = k;
        let mut run = Run::of(&scene, Integrator::Auto, 0.01).unwrap();
        run.advance().unwrap();
        run.last_step
    };
    let soft = substeps_at(20.0);
    let stiff = substeps_at(1e5);
    let stiffest = substeps_at(1e9);
    assert!(
        soft.substeps >= 1 && soft.substeps <= 4 && !soft.fell_back,
        "{soft:?}"
    );
    assert!(
        stiff.substeps > soft.substeps && !stiff.fell_back,
        "{stiff:?}"
    );
    assert!(stiff.substeps <= settings.max_substeps);
    assert!(stiffest.fell_back, "{stiffest:?}");

    // Fall-backs are counted, and the run stays bounded.
    let mut scene = Scene::named("stiff").unwrap();
    scene.params.stiffness = 1e9;
    let mut run = Run::of(&scene, Integrator::Auto, 1.0 / 64.0).unwrap();
    run.advance_by(640).unwrap();
    // Every step: the band is held throughout and its rate, 2 sqrt(k/m) = 28284/s, needs
    // about 28284 / 64 / 0.3 = 1474 Taylor steps a fixed step, past the budget of 200.
    assert_eq!(run.fallbacks, 640);
}

/// `auto`'s engine with one Taylor step of order `order` per fixed step: a tolerance nothing
/// exceeds.
fn one_step_per_fixed_step(order: usize) -> AutoSettings {
    AutoSettings {
        tolerance: f64::MAX,
        order,
        max_substeps: u32::MAX,
    }
}

#[test]
fn autos_engine_converges_at_the_order_of_its_series_on_the_diagonal_pull() {
    // From order 4 up a step may stop early (see `taylor`), which a tolerance nothing exceeds
    // would always allow; the stiff fixtures hold the higher orders.
    for order in [2, 3, 4] {
        let errors: Vec<f64> = [0.2, 0.1, 0.05]
            .iter()
            .map(|&dt| {
                let scene = Scene::named("diagonal").unwrap();
                let mass = scene.params.mass_properties().unwrap();
                let mut run = Run::of(&scene, Integrator::Auto, dt).unwrap();
                run.stepper.auto = one_step_per_fixed_step(order);
                let mut worst: f64 = 0.0;
                for _ in 0..(2.0 / dt).round() as u64 {
                    run.advance().unwrap();
                    assert_eq!(run.last_step.substeps, 1);
                    let exact = diagonal_exact(run.time());
                    worst = worst.max(run.stepper.state.pose_error(&exact, &mass));
                }
                worst
            })
            .collect();
        for pair in errors.windows(2) {
            let observed = (pair[0] / pair[1]).log2();
            assert!(
                (observed - order as f64).abs() < 0.5,
                "order {order}: errors {errors:?}, observed order {observed}"
            );
        }
    }
}

/// The stiff pulls' reference states, from tests/fixtures/stiff_references.py (SciPy's DOP853
/// at a tolerance of 1e-13, checked against 3e-14): (k, rate, ticks, state, agreement).
fn stiff_references() -> Vec<(f64, f64, u64, BodyState, f64)> {
    include_str!("../fixtures/stiff_references.csv")
        .lines()
        .skip(1)
        .map(|line| {
            let v: Vec<f64> = line.split(',').map(|f| f.parse().unwrap()).collect();
            let mut state = BodyState::at_rest(DVec2::new(v[4], v[5]));
            state.angular.orientation = v[6];
            state.linear.velocity = DVec2::new(v[7], v[8]);
            state.angular.angular_velocity = v[9];
            (v[0], v[1], v[2] as u64, state, v[10])
        })
        .collect()
}

#[test]
fn auto_meets_the_stiff_targets_at_each_horizon_without_falling_back() {
    let references = stiff_references();
    assert_eq!(references.len(), 10);
    for (k, rate, ticks, reference, agreement) in references {
        let mut scene = Scene::named("stiff").unwrap();
        scene.params.stiffness = k;
        let mass = scene.params.mass_properties().unwrap();
        let mut run = Run::of(&scene, Integrator::Auto, 1.0 / rate).unwrap();
        run.advance_by(ticks).unwrap();
        let error = run.stepper.state.pose_error(&reference, &mass);
        // The targets of the stiffness table (docs/report.md); the fixture's two solutions agree to well
        // within them.
        let target = if k <= 1e6 { 1e-5 } else { 1e-4 };
        assert!(agreement < target / 2.0, "k {k:e}: references {agreement}");
        assert!(
            error <= target,
            "k {k:e} at {rate} Hz: {error} px after {ticks} steps"
        );
        assert_eq!(run.fallbacks, 0, "k {k:e} at {rate} Hz");
    }
}

// The engine as the browser compiles it (no vector lanes) steps the stiff pulls to the bits of
// the one that runs here, and so to the same targets: a replay hashes alike in both.
#[test]
fn the_browsers_engine_meets_the_stiff_targets_to_the_same_bits() {
    use rubber_band_box::physics::BandEnds;
    use rubber_band_box::physics::integrators::taylor::{self, TaylorSettings};
    let auto = AutoSettings::default();
    let settings = TaylorSettings {
        order: auto.order,
        tolerance: auto.tolerance,
        max_steps: auto.max_substeps,
    };
    for (k, rate, ticks, reference, _) in stiff_references() {
        let mut scene = Scene::named("stiff").unwrap();
        scene.params.stiffness = k;
        let mass = scene.params.mass_properties().unwrap();
        // The stiff pull holds the band from the start (as the references' runs do).
        let band = BandEnds::grabbing(&mass, &scene.initial, scene.pulls[0].2);
        let model = scene.params.force_model(mass, Some(band));
        let mut state = scene.initial;
        for tick in 0..ticks {
            let here = taylor::integrate(&state, &model, 1.0 / rate, &settings).unwrap();
            let browser = taylor::integrate_portable(&state, &model, 1.0 / rate, &settings);
            let browser = browser.unwrap();
            let bits = |state: BodyState| state.to_array().map(f64::to_bits);
            assert_eq!(
                bits(here.state),
                bits(browser.state),
                "k {k:e}, tick {tick}"
            );
            assert_eq!((here.steps, here.orders), (browser.steps, browser.orders));
            assert_eq!(here.dissipated.to_bits(), browser.dissipated.to_bits());
            state = browser.state;
        }
        let target = if k <= 1e6 { 1e-5 } else { 1e-4 };
        let error = state.pose_error(&reference, &mass);
        assert!(error <= target, "k {k:e} at {rate} Hz: {error} px");
    }
}

#[test]
fn beyond_every_horizon_auto_falls_back_counts_it_and_never_gains_energy() {
    for k in [1e8, 1e9, 1e12] {
        for rate in [100.0, 64.0] {
            let mut scene = Scene::named("undamped").unwrap();
            scene.params.stiffness = k;
            let mut run = Run::of(&scene, Integrator::Auto, 1.0 / rate).unwrap();
            let e0 = run.stepper.energy();
            let mut previous = e0;
            let steps = (10.0 * rate) as u64;
            for _ in 0..steps {
                run.advance().unwrap();
                let e = run.stepper.energy();
                assert!(
                    e <= previous,
                    "k {k:e} at {rate} Hz, step {}: {e} > {previous}",
                    run.step
                );
                previous = e;
                assert!(run.stepper.state.is_sane());
            }
            // Every step fell back (the budget cannot afford any), and each was counted.
            assert_eq!(run.fallbacks, steps, "k {k:e} at {rate} Hz");
        }
    }
}

#[test]
fn the_ledger_balances_on_stiff_pulls_where_auto_did_not_fall_back() {
    for (k, rate, ticks, _, _) in stiff_references() {
        let mut scene = Scene::named("stiff").unwrap();
        scene.params.stiffness = k;
        let mut run = Run::of(&scene, Integrator::Auto, 1.0 / rate).unwrap();
        for _ in 0..ticks {
            run.advance().unwrap();
            let residual = run.books.residual().abs();
            assert!(
                residual <= 1e-6 * run.books.ledger.throughput(),
                "k {k:e} step {}: residual {residual} of {}",
                run.step,
                run.books.ledger.throughput()
            );
        }
        assert_eq!(run.fallbacks, 0);
    }
}

#[test]
fn a_tighter_budget_makes_auto_fall_back_sooner() {
    let mut scene = Scene::named("stiff").unwrap();
    scene.params.stiffness = 1e5;
    let mut run = Run::of(&scene, Integrator::Auto, 0.01).unwrap();
    // k = 1e5 at 100 Hz needs about ten Taylor steps a fixed step.
    run.stepper.auto = AutoSettings {
        max_substeps: 2,
        ..AutoSettings::default()
    };
    run.advance_by(10).unwrap();
    assert_eq!(run.fallbacks, 10);
}

/// The soak: 1e7 steps (28 simulated hours) of the default integrator on the undamped
/// tutorial scene with the band held, part of `cargo test` (a few seconds). Its figures:
/// `cargo test --test suite integrators::soak -- --nocapture`. The bounds leave a wide margin over
/// the figures measured (docs/testing.md, "Robustness"), far below what a slow drift would reach;
/// `auto` must never fall back here.
#[test]
fn soak_ten_million_undamped_steps() {
    let steps = 10_000_000;
    let scene = Scene::named("undamped").unwrap();
    let mut run = Run::of(&scene, Integrator::default(), 0.01).unwrap();
    let mass = run.stepper.mass;
    let e0 = run.stepper.energy();
    let l0 = angular_momentum_about(&run.stepper.state, &mass, TUTORIAL_PULL_TARGET);
    let (mut energy, mut momentum) = (0.0_f64, 0.0_f64);
    let started = std::time::Instant::now();
    for _ in 0..steps {
        run.advance().unwrap();
        energy = energy.max((run.stepper.energy() - e0).abs() / e0);
        let l = angular_momentum_about(&run.stepper.state, &mass, TUTORIAL_PULL_TARGET);
        momentum = momentum.max((l - l0).abs());
    }
    let final_energy = (run.stepper.energy() - e0) / e0;
    println!(
        "soak: {steps} steps of {} in {:.1} s; energy: largest relative error {energy:.2e}, \
         final {final_energy:.2e}; angular momentum about the anchor: largest change \
         {momentum:.2e} (from {l0}); fall-backs {}",
        Integrator::default(),
        started.elapsed().as_secs_f64(),
        run.fallbacks
    );
    assert_eq!(run.fallbacks, 0);
    assert!(energy < 1e-9, "energy error {energy:e}");
    assert!(momentum < 1e-5, "angular momentum change {momentum:e}");
}

/// The largest ledger residual over a run of the seed scene (pulled 2 s, released, 4 s),
/// relative to the energy that passed through.
fn ledger_residual(integrator: Integrator, dt: f64) -> f64 {
    let scene = Scene::named("tutorial").unwrap();
    let mut run = Run::of(&scene, integrator, dt).unwrap();
    let mut worst: f64 = 0.0;
    for _ in 0..(4.0 / dt).round() as u64 {
        run.advance().unwrap();
        worst = worst.max(run.books.residual().abs());
    }
    worst / run.books.ledger.throughput()
}

#[test]
fn the_ledger_balances_exactly_where_nothing_acts() {
    // Free flight and spin, no band, no damping: every integrator keeps the energy.
    let mut params = SceneParams::tutorial();
    params.linear_damping = 0.0;
    params.angular_damping = 0.0;
    let mut initial = BodyState::default();
    initial.linear.velocity = DVec2::new(30.0, -40.0);
    initial.angular.angular_velocity = 2.0;
    for integrator in Integrator::ALL {
        let mut run = Run::new(params, initial, vec![], integrator, 0.01).unwrap();
        run.advance_by(500).unwrap();
        // Zero to round-off (`implicit` recovers the velocity from two positions).
        let residual = run.books.residual();
        assert!(
            residual.abs() <= 1e-13 * run.books.ledger.initial,
            "{integrator}: {residual}"
        );
    }
}

#[test]
fn the_ledger_residual_shrinks_with_dt_at_the_integrators_order() {
    for (integrator, order) in [
        (Integrator::Euler, 1.0),
        (Integrator::Symplectic, 1.0),
        (Integrator::Verlet, 2.0),
        (Integrator::Rk4, 4.0),
    ] {
        let residuals: Vec<f64> = [0.01, 0.005, 0.0025]
            .iter()
            .map(|&dt| ledger_residual(integrator, dt))
            .collect();
        for pair in residuals.windows(2) {
            let observed = (pair[0] / pair[1]).log2();
            assert!(
                (observed - order).abs() < 0.5,
                "{integrator}: residuals {residuals:?}, observed order {observed}"
            );
        }
    }
    // The default's residual is far below a millionth of the energy that passed through.
    let auto = ledger_residual(Integrator::Auto, 0.01);
    assert!(auto < 1e-8, "auto: {auto}");
}

/// The references with spin (tests/fixtures/spin_references.py): (case, release time, end
/// time, state, how far its two solutions agree).
fn spin_references() -> Vec<(String, f64, f64, BodyState, f64)> {
    include_str!("../fixtures/spin_references.csv")
        .lines()
        .skip(1)
        .map(|line| {
            let fields: Vec<&str> = line.split(',').collect();
            let v: Vec<f64> = fields[1..].iter().map(|f| f.parse().unwrap()).collect();
            let state = BodyState::from_array([v[2], v[3], v[4], v[5], v[6], v[7]]);
            (fields[0].to_owned(), v[0], v[1], state, v[8])
        })
        .collect()
}

/// Every integrator on the two cases that turn the box (a corner pull and release; a box
/// spinning at 100 rad/s pulled, then released), against SciPy's DOP853: each converges at its
/// order, and `auto` is within 1e-9 px at every step tried. Orientation errors count through
/// the corners (30·θ), so a method that lost the rotation's accuracy fails here even where the
/// diagonal pull, which never turns, would not see it.
#[test]
fn every_integrator_converges_at_its_order_on_the_cases_with_spin() {
    let references = spin_references();
    assert_eq!(references.len(), 2);
    for (case, release, end, reference, agreement) in references {
        assert!(agreement < 1e-10, "{case}: references agree to {agreement}");
        let dts: [f64; 3] = if case == "corner" {
            [0.01, 0.005, 0.0025]
        } else {
            [1e-3, 5e-4, 2.5e-4]
        };
        let mass = SceneParams::tutorial().mass_properties().unwrap();
        let error = |integrator: Integrator, dt: f64| -> f64 {
            let mut initial = BodyState::default();
            if case == "spinning-release" {
                initial.angular.angular_velocity = 100.0;
            }
            let pulls = vec![Pull {
                start: 0,
                end: (release / dt).round() as u64,
                target: TUTORIAL_PULL_TARGET,
            }];
            let mut run =
                Run::new(SceneParams::tutorial(), initial, pulls, integrator, dt).unwrap();
            run.advance_by((end / dt).round() as u64).unwrap();
            run.stepper.state.pose_error(&reference, &mass)
        };
        for integrator in Integrator::ALL {
            let errors = dts.map(|dt| error(integrator, dt));
            println!("{case} {integrator}: {errors:?}");
            if integrator == Integrator::Auto {
                assert!(errors.iter().all(|&e| e < 1e-9), "{case} auto: {errors:?}");
                continue;
            }
            for pair in errors.windows(2) {
                let observed = (pair[0] / pair[1]).log2();
                let expected = f64::from(integrator.order());
                assert!(
                    (observed - expected).abs() < 0.35,
                    "{case} {integrator}: order {observed:.2}, not {expected} ({errors:?})"
                );
            }
        }
    }
}

#[test]
fn the_switch_cycles_the_table_in_order_and_autos_order_is_its_series() {
    // The order written out (docs/integrators.md's table), not recomputed from `ALL`: a
    // reordered table, a skipped entry or a wrong wrap from the last to the first fails.
    let mut integrator = Integrator::Euler;
    let mut names = Vec::new();
    for _ in 0..8 {
        integrator = integrator.next();
        names.push(integrator.name());
    }
    assert_eq!(
        names,
        [
            "symplectic",
            "verlet",
            "rk4",
            "implicit",
            "seed",
            "auto",
            "euler",
            "symplectic"
        ]
    );
    assert_eq!(
        Integrator::Auto.order() as usize,
        AutoSettings::default().order
    );
}

/// Each fixed-step method counts the force evaluations of its step (the work the report
/// compares), and every method moves the pulled box.
#[test]
fn each_step_counts_its_force_evaluations_and_moves_the_box() {
    let mut stepper = Stepper::new(SceneParams::tutorial()).unwrap();
    stepper.grab(TUTORIAL_PULL_TARGET);
    let model = stepper.model();
    let start = model.forces(&stepper.state);
    let counted = [
        (Integrator::Euler, 1),
        (Integrator::Symplectic, 1),
        (Integrator::Verlet, 2),
        (Integrator::Rk4, 4),
        (Integrator::Seed, 1),
    ];
    for (integrator, evaluations) in counted {
        let mut state = stepper.state;
        let info = integrator.step(&mut state, &model, start, 0.01);
        assert_eq!(
            (info.substeps, info.evaluations),
            (1, evaluations),
            "{integrator}"
        );
    }
    // (No check that `step` equals `step_with` under the defaults: it is that very call.)
    for integrator in Integrator::ALL {
        let mut stepped = stepper.state;
        integrator.step(&mut stepped, &model, start, 0.01);
        assert_ne!(stepped, stepper.state, "{integrator} moved the box");
    }
}

/// A rooted tree (Butcher's): its children, in canonical order.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
struct Tree(Vec<Tree>);

impl Tree {
    fn order(&self) -> usize {
        1 + self.0.iter().map(Tree::order).sum::<usize>()
    }

    /// γ(t): the order times the children's densities.
    fn density(&self) -> f64 {
        self.order() as f64 * self.0.iter().map(Tree::density).product::<f64>()
    }

    /// The elementary weight's stage vector: for stage i, the product over the children of
    /// Σ_j a_ij (their vector)_j.
    fn stage_vector(&self, a: &[Vec<f64>]) -> Vec<f64> {
        let mut vector = vec![1.0; a.len()];
        for child in &self.0 {
            let inner = child.stage_vector(a);
            for (i, value) in vector.iter_mut().enumerate() {
                *value *= (0..a.len()).map(|j| a[i][j] * inner[j]).sum::<f64>();
            }
        }
        vector
    }
}

/// Every rooted tree up to `max_order`: the trees of order n are the multisets of smaller
/// trees whose orders sum to n − 1.
fn rooted_trees(max_order: usize) -> Vec<Tree> {
    fn multisets(
        smaller: &[Tree],
        from: usize,
        left: usize,
        chosen: &mut Vec<Tree>,
        out: &mut Vec<Tree>,
    ) {
        if left == 0 {
            out.push(Tree(chosen.clone()));
            return;
        }
        for (index, tree) in smaller.iter().enumerate().skip(from) {
            if tree.order() <= left {
                chosen.push(tree.clone());
                multisets(smaller, index, left - tree.order(), chosen, out);
                chosen.pop();
            }
        }
    }
    let mut trees = vec![Tree(vec![])];
    for order in 2..=max_order {
        let smaller = trees.clone();
        let mut new = Vec::new();
        multisets(&smaller, 0, order - 1, &mut Vec::new(), &mut new);
        trees.extend(new);
    }
    trees
}

/// DOP853's tableau against Runge-Kutta theory: the eighth-order weights meet all 200 order
/// conditions up to order 8, the fifth-order error estimator is blind to every tree up to
/// order 5 (it is the difference of two methods of at least that order), and the third-order
/// one is the weights less Hairer's three published coefficients. A changed coefficient breaks
/// one of them.
#[test]
fn dop853s_tableau_meets_the_order_conditions() {
    use rubber_band_box::physics::integrators::dop853::{A, B, E3, E5};
    let trees = rooted_trees(8);
    // The number of rooted trees of each order (OEIS A000081): 1, 1, 2, 4, 9, 20, 48, 115.
    let counts: Vec<usize> = (1..=8)
        .map(|n| trees.iter().filter(|t| t.order() == n).count())
        .collect();
    assert_eq!(counts, [1, 1, 2, 4, 9, 20, 48, 115]);

    let a: Vec<Vec<f64>> = A.iter().map(|row| row.to_vec()).collect();
    for tree in &trees {
        let phi: f64 = B
            .iter()
            .zip(tree.stage_vector(&a))
            .map(|(b, g)| b * g)
            .sum();
        let expected = 1.0 / tree.density();
        assert!(
            (phi - expected).abs() <= 1e-12 * expected.max(1e-3),
            "order {}: {phi} against 1/γ = {expected}",
            tree.order()
        );
    }

    // The estimators see the 12 stages and the derivative at the step's end, whose row is B.
    let mut extended = a.clone();
    for row in &mut extended {
        row.push(0.0);
    }
    extended.push(B.iter().copied().chain([0.0]).collect());
    for tree in trees.iter().filter(|t| t.order() <= 5) {
        let seen: f64 = E5
            .iter()
            .zip(tree.stage_vector(&extended))
            .map(|(e, g)| e * g)
            .sum();
        assert!(
            seen.abs() < 1e-12,
            "E5 sees a tree of order {}: {seen}",
            tree.order()
        );
    }
    // Hairer's bhh1, bhh2, bhh3 (DOP853's Fortran source: 0.244094488188976377952755905512,
    // 0.733846688281611857341361741547, 0.220588235294117647058823529412D-01) at stages 1, 9
    // and 12, to f64.
    let bhh = [
        (0, 0.244_094_488_188_976_4),
        (8, 0.733_846_688_281_611_9),
        (11, 0.022_058_823_529_411_765),
    ];
    for (j, e3) in E3.iter().enumerate() {
        let weight = B.get(j).copied().unwrap_or(0.0);
        let less = bhh.iter().find(|(at, _)| *at == j).map_or(0.0, |(_, b)| *b);
        assert!(
            (e3 - (weight - less)).abs() < 1e-15,
            "E3[{j}] = {e3}, not {}",
            weight - less
        );
    }
}

/// DOP853 on the stiff pulls, against the SciPy fixtures: within 1e-8 px at a tight
/// tolerance; looser, it takes fewer evaluations and lands farther off, but within its
/// tolerance's reach.
#[test]
fn dop853_meets_the_stiff_references_and_trades_accuracy_for_work_by_its_tolerance() {
    use rubber_band_box::physics::integrators::dop853;
    for (k, rate, ticks, reference, _) in stiff_references().into_iter().filter(|&(k, ..)| k <= 1e5)
    {
        let mut scene = Scene::named("stiff").unwrap();
        scene.params.stiffness = k;
        let mass = scene.params.mass_properties().unwrap();
        // The stiff pull, each fixed step one DOP853 integration; a budget, so that a broken
        // controller fails here rather than loops.
        let run = |tolerance: f64| -> (BodyState, u32) {
            let mut stepper = Stepper::new(scene.params).unwrap();
            stepper.grab(TUTORIAL_PULL_TARGET);
            let model = stepper.model();
            let (mut state, mut attempts) = (stepper.state, 0);
            for _ in 0..ticks {
                let start = model.forces(&state);
                let done = dop853::integrate(&state, &model, start, 1.0 / rate, tolerance, 10_000)
                    .expect("within 10000 substeps a fixed step");
                (state, attempts) = (done.state, attempts + done.attempts);
            }
            (state, attempts)
        };
        let (tight, tight_work) = run(1e-12);
        let (loose, loose_work) = run(1e-5);
        let (tight_error, loose_error) = (
            tight.pose_error(&reference, &mass),
            loose.pose_error(&reference, &mass),
        );
        assert!(tight_error < 1e-8, "k {k:e} at {rate} Hz: {tight_error}");
        assert!(
            loose_error > tight_error && loose_error < 1e-2,
            "k {k:e} at {rate} Hz: {loose_error}"
        );
        assert!(
            loose_work < tight_work,
            "k {k:e}: {loose_work} / {tight_work}"
        );
    }
}

/// One DOP853 step of damped free motion (no band) against the closed form: the state, and
/// the energy damping took out, which its extra component integrates.
#[test]
fn dop853_follows_damped_free_motion_and_integrates_what_damping_takes() {
    use rubber_band_box::physics::integrators::dop853;
    let params = SceneParams::tutorial();
    let mass = params.mass_properties().unwrap();
    let model = params.force_model(mass, None);
    let mut initial = BodyState::default();
    initial.linear.velocity = DVec2::new(30.0, -40.0);
    initial.angular.angular_velocity = 2.0;
    let dt = 0.05;
    let done =
        dop853::integrate(&initial, &model, model.forces(&initial), dt, 1e-12, 10_000).unwrap();
    let (rate, spin_rate) = (params.linear_damping / params.mass, params.angular_damping);
    let (decay, spin_decay) = ((-rate * dt).exp(), (-spin_rate * dt).exp());
    let mut exact = initial;
    exact.linear.velocity = initial.linear.velocity * decay;
    exact.linear.position = initial.linear.velocity * (1.0 - decay) / rate;
    exact.angular.angular_velocity = 2.0 * spin_decay;
    exact.angular.orientation = 2.0 * (1.0 - spin_decay) / spin_rate;
    assert!(
        done.state.pose_error(&exact, &mass) < 1e-10,
        "{:?} against {exact:?}",
        done.state
    );
    let velocity_error = (done.state.linear.velocity - exact.linear.velocity).length()
        + (done.state.angular.angular_velocity - exact.angular.angular_velocity).abs();
    assert!(velocity_error < 1e-10, "{velocity_error}");
    let energy = |s: &BodyState| {
        0.5 * params.mass * s.linear.velocity.length_squared()
            + 0.5 * mass.inertia() * s.angular.angular_velocity.powi(2)
    };
    let taken = energy(&initial) - energy(&exact);
    assert!(
        (done.dissipated - taken).abs() < 1e-10 * taken,
        "{} against {taken}",
        done.dissipated
    );
    assert!(done.attempts >= 1);
}

/// A step DOP853 cannot afford within its budget is given up (None), before or during it.
#[test]
fn dop853_gives_up_a_step_beyond_its_budget() {
    use rubber_band_box::physics::integrators::dop853;
    let mut stepper = Stepper::new(Scene::named("stiff").unwrap().params).unwrap();
    stepper.params.stiffness = 1e6;
    stepper.grab(TUTORIAL_PULL_TARGET);
    let model = stepper.model();
    let start = model.forces(&stepper.state);
    let state = stepper.state;
    let done = dop853::integrate(&state, &model, start, 0.01, 1e-9, 100_000).unwrap();
    assert!(done.attempts > 2, "{}", done.attempts);
    assert!(dop853::integrate(&state, &model, start, 0.01, 1e-9, 1).is_none());
    // One attempt short of what it needs: given up.
    assert!(dop853::integrate(&state, &model, start, 0.01, 1e-9, done.attempts - 1).is_none());
    let exact_budget = dop853::integrate(&state, &model, start, 0.01, 1e-9, done.attempts);
    assert_eq!(exact_budget.map(|d| d.state), Some(done.state));
}

/// One `implicit` step of the diagonal pull with damping, against backward Euler solved by
/// hand: along the diagonal the band is a linear spring through the centre, so
/// v₁ = (m v₀ − h k (x₀ + c − a)) / (m + h b + h² k) and x₁ = x₀ + h v₁, with no turn. Newton's
/// method solves this quadratic problem in one iteration, and one more sees it is done.
#[test]
fn an_implicit_step_is_backward_euler_solved_by_hand() {
    let params = SceneParams::tutorial();
    let mass = params.mass_properties().unwrap();
    let corner = DVec2::new(30.0, 30.0);
    let anchor = DVec2::new(150.0, 150.0);
    let band = rubber_band_box::physics::BandEnds {
        local_point: corner,
        anchor,
    };
    let model = params.force_model(mass, Some(band));
    let mut state = BodyState::default();
    state.linear.position = DVec2::new(10.0, 10.0);
    state.linear.velocity = DVec2::new(20.0, 20.0);
    let (m, k, b, h) = (params.mass, params.stiffness, params.linear_damping, 0.01);
    let start = state;
    let evaluations = Integrator::Implicit
        .step(&mut state, &model, model.forces(&start), h)
        .evaluations;
    let stretch = start.linear.position + corner - anchor;
    let v1 = (m * start.linear.velocity - h * k * stretch) / (m + h * b + h * h * k);
    let x1 = start.linear.position + h * v1;
    assert!(
        (state.linear.velocity - v1).length() < 1e-12 * v1.length(),
        "{:?} against {v1:?}",
        state.linear.velocity
    );
    assert!((state.linear.position - x1).length() < 1e-12 * x1.length());
    assert_eq!(
        (state.angular.orientation, state.angular.angular_velocity),
        (0.0, 0.0)
    );
    // The work, counted: the start; Newton's first iteration (its linearisation, and the
    // energy of its full step, accepted); the second, which finds a step of round-off and
    // stops: 1 + 2 + 2.
    assert_eq!(evaluations, 5);
}

/// A budget of exactly the steps a soft fixed step is expected to need is enough: the
/// engines give up beforehand only when the expectation exceeds the budget.
#[test]
fn a_budget_equal_to_the_expected_steps_is_enough() {
    use rubber_band_box::physics::integrators::dop853;
    use rubber_band_box::physics::integrators::taylor::{self, TaylorSettings};
    let mut stepper = Stepper::new(SceneParams::tutorial()).unwrap();
    stepper.grab(TUTORIAL_PULL_TARGET);
    let model = stepper.model();
    let state = stepper.state;
    let expected = taylor::steps_expected(&state, &model, 0.01);
    assert_eq!(expected, 1.0);
    let settings = TaylorSettings {
        order: 20,
        tolerance: 1e-10,
        max_steps: 1,
    };
    assert_eq!(
        taylor::integrate(&state, &model, 0.01, &settings)
            .unwrap()
            .steps,
        1
    );
    let done = dop853::integrate(&state, &model, model.forces(&state), 0.01, 1e-6, 1).unwrap();
    assert_eq!(done.attempts, 1);
}

/// A fast decay in one long fixed step (c·dt = 6.2 and b/m·dt = 5.5, a light box of side 1):
/// the series' own error estimate would allow a step longer than a truncated series of the
/// decay can hold (a small box passes an absolute tolerance easily), so only the engine's
/// stability cap keeps the energy from growing. The case the property test "damped motion
/// never gains energy" found (tests/properties.rs).
#[test]
fn autos_engine_never_lets_a_fast_decay_grow() {
    let params = SceneParams {
        mass: 0.018_123_685_883_822_16,
        size: DVec2::ONE,
        stiffness: 0.0,
        linear_damping: 1.0,
        angular_damping: 62.347_552_097_715_44,
        step_rate_hz: 10.0,
    };
    let mut stepper = Stepper::new(params).unwrap();
    stepper.state.angular.angular_velocity = 17.292_839_282_923_35;
    let mut energy = stepper.energy();
    for step in 1..=20 {
        let info = stepper.step(0.1);
        assert!(!info.fell_back);
        let now = stepper.energy();
        assert!(now <= energy, "step {step}: {energy} -> {now}");
        energy = now;
    }
}

/// The far anchor (1e6 px away) at `auto`'s default tolerance: the tolerance is relative to
/// the state's size as well, so round-off a million px out is never chased, and no step falls
/// back.
#[test]
fn auto_pulls_the_far_anchor_without_falling_back() {
    let far = Scene::named("far").unwrap();
    let mut run = Run::of(&far, Integrator::Auto, 0.01).unwrap();
    run.advance_by(200).unwrap();
    assert_eq!(run.fallbacks, 0);
}

/// The engines' error follows their tolerance: on the stiff pull at k = 1e4 (10 fixed steps
/// at 100 Hz, the fixture's two solutions agreeing to 1e-11 px), every hundredfold tightening
/// buys at least tenfold less error, and the error stays within 50 tolerances (a
/// tolerance bounds each substep's error, and there are tens of substeps). An error estimate
/// or weight that is off shows here, where the accuracy tests alone, far below their targets,
/// would not see it.
#[test]
fn the_engines_error_follows_their_tolerance() {
    use rubber_band_box::physics::integrators::dop853;
    let (k, rate, ticks, reference, _) = stiff_references()
        .into_iter()
        .find(|&(k, rate, ..)| k == 1e4 && rate == 100.0)
        .unwrap();
    let mut scene = Scene::named("stiff").unwrap();
    scene.params.stiffness = k;
    let mass = scene.params.mass_properties().unwrap();
    let tolerances = [1e-3, 1e-5, 1e-7];
    let dop853_error = |tolerance: f64| {
        let mut stepper = Stepper::new(scene.params).unwrap();
        stepper.grab(TUTORIAL_PULL_TARGET);
        let model = stepper.model();
        let mut state = stepper.state;
        for _ in 0..ticks {
            let start = model.forces(&state);
            state = dop853::integrate(&state, &model, start, 1.0 / rate, tolerance, 10_000)
                .unwrap()
                .state;
        }
        state.pose_error(&reference, &mass)
    };
    let auto_error = |tolerance: f64| {
        let mut run = Run::of(&scene, Integrator::Auto, 1.0 / rate).unwrap();
        run.stepper.auto.tolerance = tolerance;
        run.advance_by(ticks).unwrap();
        assert_eq!(run.fallbacks, 0);
        run.stepper.state.pose_error(&reference, &mass)
    };
    for (name, errors) in [
        ("dop853", tolerances.map(dop853_error)),
        ("auto", tolerances.map(auto_error)),
    ] {
        println!("{name}: {errors:?} at tolerances {tolerances:?}");
        for (error, tolerance) in errors.iter().zip(tolerances) {
            assert!(*error < 50.0 * tolerance, "{name}: {errors:?}");
        }
        for pair in errors.windows(2) {
            assert!(pair[1] < pair[0] / 10.0, "{name}: {errors:?}");
        }
    }
}

/// On the tutorial's soft band (the band's rate times the step about 0.02) the series' terms
/// fall about fiftyfold an order, so `auto` reaches its tolerance in a handful of orders and
/// stops there, in one Taylor step, instead of computing all twenty.
#[test]
fn autos_series_stops_early_on_a_soft_band() {
    let tutorial = Scene::named("tutorial").unwrap();
    let mut run = Run::of(&tutorial, Integrator::Auto, 0.01).unwrap();
    let mut orders = Vec::new();
    for _ in 0..300 {
        run.advance().unwrap();
        orders.push(run.last_step.evaluations);
        assert_eq!(run.last_step.substeps, 1);
    }
    assert!(orders.iter().all(|n| (4..=12).contains(n)), "{orders:?}");
}
