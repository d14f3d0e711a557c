//! The numerical core on its own: no `App`, no `World`.

use bevy::math::DVec2;
use rubber_band_box::physics::{
    BandEnds, BodyState, Energies, EnergyLedger, Integrator, MASS_RANGE, MassProperties,
    ParamError, Range, STIFFNESS_RANGE, SceneParams, Stepper, TIME_SCALE_RANGE, Wrench,
    angular_momentum_about, damping_wrench, kinetic_energy, param_error::exact, rotate,
    symplectic_euler,
};

#[test]
fn seed_scene_converts_the_tutorials_per_frame_units() {
    let p = SceneParams::tutorial();
    assert_eq!(p.mass, 5.0);
    assert_eq!(p.size, DVec2::new(60.0, 60.0));
    assert!((p.stiffness - 20.0).abs() < 1e-12);
    assert!((p.linear_damping - 5.0).abs() < 1e-12);
    assert!((p.angular_damping - 2.020_270_731_751_944).abs() < 1e-12);
    assert!(((-p.angular_damping * 0.01).exp() - 0.98).abs() < 1e-15);
    assert_eq!(p.dt(), 0.01);
    let mass = p.mass_properties().unwrap();
    assert_eq!(mass.inertia(), 3000.0);
    assert_eq!(mass.inverse_inertia(), 1.0 / 3000.0);
    assert_eq!(mass.inverse_mass(), 0.2);
}

#[test]
fn bad_parameters_are_refused_with_the_field_and_value() {
    type Spoil = fn(&mut SceneParams);
    let cases: [(Spoil, &str); 6] = [
        (|p| p.mass = 0.0, "mass"),
        (|p| p.mass = f64::NAN, "mass"),
        (|p| p.size.y = -1.0, "height"),
        (|p| p.stiffness = -2.0, "stiffness k"),
        (|p| p.angular_damping = f64::INFINITY, "angular damping c"),
        (|p| p.step_rate_hz = 0.0, "step rate"),
    ];
    for (spoil, field) in cases {
        let mut params = SceneParams::tutorial();
        spoil(&mut params);
        let error: ParamError = params.validate().unwrap_err();
        assert_eq!(error.field, field);
        assert!(error.to_string().starts_with(field), "{error}");
        assert!(Stepper::new(params).is_err());
    }
    assert!(SceneParams::tutorial().validate().is_ok());
}

#[test]
fn rotation_is_counter_clockwise() {
    let v = rotate(DVec2::X, std::f64::consts::FRAC_PI_2);
    assert!((v - DVec2::Y).length() < 1e-15);
}

#[test]
fn nearest_corner_follows_the_orientation_and_breaks_ties_in_tutorial_order() {
    let mass = SceneParams::tutorial().mass_properties().unwrap();
    let mut state = BodyState::at_rest(DVec2::new(100.0, 0.0));
    assert_eq!(
        mass.nearest_corner(&state, DVec2::new(200.0, 100.0)),
        DVec2::new(30.0, 30.0)
    );
    assert_eq!(
        mass.nearest_corner(&state, DVec2::new(0.0, -100.0)),
        DVec2::new(-30.0, -30.0)
    );
    // Turned a quarter counter-clockwise, the body's upper-left corner is at the lower left.
    state.angular.orientation = std::f64::consts::FRAC_PI_2;
    assert_eq!(
        mass.nearest_corner(&state, DVec2::new(0.0, -100.0)),
        DVec2::new(-30.0, 30.0)
    );
    // From the centre all four are equally near: the first (upper-left) wins.
    assert_eq!(
        mass.nearest_corner(&BodyState::default(), DVec2::ZERO),
        DVec2::new(-30.0, 30.0)
    );
}

/// The tutorial's five steps by hand, for one state and band, against one core step.
#[test]
fn one_step_equals_the_five_step_total_reaction_by_hand() {
    let params = SceneParams::tutorial();
    let (m, inertia, k, b, c, dt) = (5.0, 3000.0, 20.0, 5.0, params.angular_damping, 0.01);
    let (x, y, vx, vy, theta, omega) = (10.0, -5.0, 3.0, 4.0, 0.3_f64, 0.5);
    let (local_x, local_y, anchor_x, anchor_y) = (30.0, 30.0, 100.0, 50.0);

    // The corner in world coordinates, and the arm from the centre of mass.
    let (s, co) = theta.sin_cos();
    let (rx, ry) = (co * local_x - s * local_y, s * local_x + co * local_y);
    let (band_x, band_y) = (k * (anchor_x - (x + rx)), k * (anchor_y - (y + ry)));
    // 1. Sum all forces: band and pull.
    let (fx, fy) = (band_x - b * vx, band_y - b * vy);
    // 2. Linear acceleration.
    let (ax, ay) = (fx / m, fy / m);
    // 3. Total torque: r x F of the band, plus the pull torque.
    let torque = rx * band_y - ry * band_x - c * inertia * omega;
    // 4. Angular acceleration.
    let alpha = torque / inertia;
    // 5. Integrate: velocities first, then position and orientation.
    let (vx1, vy1, omega1) = (vx + ax * dt, vy + ay * dt, omega + alpha * dt);
    let (x1, y1, theta1) = (x + vx1 * dt, y + vy1 * dt, theta + omega1 * dt);

    let mut stepper = Stepper::new(params).unwrap();
    stepper.integrator = Integrator::Symplectic;
    stepper.state.linear.position = DVec2::new(x, y);
    stepper.state.linear.velocity = DVec2::new(vx, vy);
    stepper.state.angular.orientation = theta;
    stepper.state.angular.angular_velocity = omega;
    stepper.band = Some(BandEnds {
        local_point: DVec2::new(local_x, local_y),
        anchor: DVec2::new(anchor_x, anchor_y),
    });
    stepper.step(dt);

    let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * b.abs().max(1.0);
    let s1 = stepper.state;
    assert!(close(s1.linear.velocity.x, vx1) && close(s1.linear.velocity.y, vy1));
    assert!(close(s1.angular.angular_velocity, omega1));
    assert!(close(s1.linear.position.x, x1) && close(s1.linear.position.y, y1));
    assert!(close(s1.angular.orientation, theta1));
}

#[test]
fn a_force_at_the_centre_makes_no_torque_and_an_off_centre_one_does() {
    assert_eq!(
        Wrench::at_arm(DVec2::new(3.0, 4.0), DVec2::ZERO).torque,
        0.0
    );
    // Pushing +x on a point above the centre turns clockwise (negative).
    assert_eq!(Wrench::at_arm(DVec2::X, DVec2::Y).torque, -1.0);
}

#[test]
fn a_pull_along_the_diagonal_through_the_centre_never_turns_the_box() {
    let mut stepper = Stepper::new(SceneParams::tutorial()).unwrap();
    stepper.grab(DVec2::new(150.0, 150.0));
    assert_eq!(stepper.band.unwrap().local_point, DVec2::new(30.0, 30.0));
    for _ in 0..500 {
        stepper.step(0.01);
        assert_eq!(stepper.state.angular.angular_velocity, 0.0);
        assert_eq!(
            stepper.state.linear.position.x,
            stepper.state.linear.position.y
        );
    }
    assert!(stepper.state.linear.position.x > 50.0);
}

#[test]
fn damping_alone_decays_each_step_by_one_minus_rate_times_dt() {
    let params = SceneParams::tutorial();
    let mass = params.mass_properties().unwrap();
    let dt = params.dt();
    let mut state = BodyState::at_rest(DVec2::ZERO);
    state.linear.velocity = DVec2::new(120.0, -80.0);
    state.angular.angular_velocity = 3.0;
    for _ in 0..100 {
        let before = state;
        let wrench = damping_wrench(&state, &mass, params.linear_damping, params.angular_damping);
        symplectic_euler(&mut state, &mass, wrench, dt);
        let linear_ratio = state.linear.velocity / before.linear.velocity;
        let angular_ratio = state.angular.angular_velocity / before.angular.angular_velocity;
        let expected_linear = 1.0 - params.linear_damping / params.mass * dt;
        assert!(
            (linear_ratio - DVec2::splat(expected_linear))
                .abs()
                .max_element()
                < 1e-13
        );
        assert!((angular_ratio - (1.0 - params.angular_damping * dt)).abs() < 1e-13);
    }
    // After 1 s: the explicit factor a hundred times over, which is first-order close to
    // exp(-rate t) and no closer (a decay taken anywhere else would not be this number).
    let omega_ratio = state.angular.angular_velocity / 3.0;
    let explicit = (1.0 - params.angular_damping * dt).powi(100);
    assert!(
        (omega_ratio / explicit - 1.0).abs() < 1e-12,
        "{omega_ratio} {explicit}"
    );
    let exact = (-params.angular_damping).exp();
    assert!((omega_ratio / exact - 1.0).abs() > 1e-3);
}

#[test]
fn without_a_band_a_box_at_rest_stays_exactly_at_rest() {
    let mut stepper = Stepper::new(SceneParams::tutorial()).unwrap();
    let start = stepper.state;
    for _ in 0..1000 {
        stepper.step(0.01);
    }
    assert_eq!(stepper.state, start);
}

#[test]
fn undamped_band_energy_stays_bounded_under_symplectic_euler() {
    let params = SceneParams {
        linear_damping: 0.0,
        angular_damping: 0.0,
        ..SceneParams::tutorial()
    };
    let mut stepper = Stepper::new(params).unwrap();
    stepper.integrator = Integrator::Symplectic;
    stepper.grab(DVec2::new(150.0, 100.0));
    let e0 = stepper.energy();
    let mut worst: f64 = 0.0;
    for _ in 0..10_000 {
        stepper.step(0.01);
        worst = worst.max((stepper.energy() - e0).abs() / e0);
    }
    // Symplectic: the energy error oscillates at O(omega dt) and does not grow.
    assert!(worst < 0.05, "relative energy error {worst}");
}

#[test]
fn mass_properties_refuse_a_degenerate_box() {
    assert!(MassProperties::rectangle(1.0, DVec2::new(0.0, 1.0)).is_err());
    assert!(MassProperties::rectangle(-1.0, DVec2::ONE).is_err());
    assert!(MassProperties::rectangle(1e-300, DVec2::splat(1e-200)).is_err());
}

#[test]
fn energies_by_kind_are_the_textbook_formulas_computed_by_hand() {
    let params = SceneParams::tutorial();
    let mass = params.mass_properties().unwrap();
    let band = BandEnds {
        anchor: DVec2::new(100.0, -40.0),
        local_point: DVec2::new(30.0, 30.0),
    };
    let mut state = BodyState::at_rest(DVec2::new(5.0, 7.0));
    state.linear.velocity = DVec2::new(3.0, -4.0);
    // A quarter turn: the corner (30, 30) is at (-30, 30) from the centre, so at (-25, 37),
    // 125 px left of the anchor and 77 px above it.
    state.angular.orientation = std::f64::consts::FRAC_PI_2;
    state.angular.angular_velocity = 0.5;
    let energies = Energies::of(&state, &mass, Some(&band), params.stiffness);
    // m = 5, |v|² = 25; I = 5 (60² + 60²) / 12 = 3000, ω² = 0.25; k = 20, |d|² = 125² + 77².
    let (linear, rotational, stretched) = (62.5, 375.0, 0.5 * 20.0 * 21554.0);
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * b;
    assert!(close(energies.linear, linear), "{energies:?}");
    assert!(close(energies.rotational, rotational), "{energies:?}");
    assert!(close(energies.band, stretched), "{energies:?}");
    let total = linear + rotational + stretched;
    assert!(close(energies.total(), total));
    let model = params.force_model(mass, Some(band));
    assert!(close(model.energy(&state), total));
    assert_eq!(
        Energies::of(&state, &mass, None, params.stiffness).band,
        0.0
    );
}

/// What the game and the runs accept from a step: every component finite and within 1e12.
/// Each component, each way out (NaN, infinite, just beyond the limit), is refused alone.
#[test]
fn a_state_is_sane_only_with_every_component_finite_and_within_the_limit() {
    let inside = [1.0, -2.0, 3.0, -4.0, 5.0, -6.0];
    assert!(BodyState::from_array(inside).is_sane());
    assert!(BodyState::from_array(inside).is_finite());
    assert!(BodyState::from_array([1e12, -1e12, 1e12, -1e12, 1e12, -1e12]).is_sane());
    for component in 0..6 {
        for (bad, finite) in [
            (f64::NAN, false),
            (f64::INFINITY, false),
            (f64::NEG_INFINITY, false),
            (1.000_001e12, true),
            (-1.000_001e12, true),
        ] {
            let mut values = inside;
            values[component] = bad;
            let state = BodyState::from_array(values);
            assert!(!state.is_sane(), "component {component} = {bad}");
            assert_eq!(state.is_finite(), finite, "component {component} = {bad}");
        }
    }
}

#[test]
fn the_corners_are_the_boxs_four_in_the_tutorials_order() {
    let mass = MassProperties::rectangle(2.0, DVec2::new(60.0, 40.0)).unwrap();
    assert_eq!(
        mass.corners(),
        [
            DVec2::new(-30.0, 20.0),
            DVec2::new(30.0, 20.0),
            DVec2::new(30.0, -20.0),
            DVec2::new(-30.0, -20.0),
        ]
    );
    // Each is the nearest to a target just beyond it.
    for corner in mass.corners() {
        assert_eq!(
            mass.nearest_corner(&BodyState::default(), corner * 3.0),
            corner
        );
    }
}

#[test]
fn energies_add_by_kind_and_kinetic_energy_is_the_two_kinetic_parts() {
    let a = Energies {
        linear: 1.0,
        rotational: 2.0,
        band: 3.0,
    };
    let b = Energies {
        linear: 10.0,
        rotational: 20.0,
        band: 30.0,
    };
    let sum = Energies {
        linear: 11.0,
        rotational: 22.0,
        band: 33.0,
    };
    assert_eq!(a + b, sum);
    assert_eq!([a, b].into_iter().sum::<Energies>(), sum);
    assert_eq!(
        std::iter::empty::<Energies>().sum::<Energies>(),
        Energies::default()
    );

    // m = 5, |v|² = 25; I = 3000, ω² = 0.25.
    let mass = SceneParams::tutorial().mass_properties().unwrap();
    let mut state = BodyState::at_rest(DVec2::new(7.0, 8.0));
    state.linear.velocity = DVec2::new(3.0, -4.0);
    state.angular.angular_velocity = -0.5;
    assert_eq!(kinetic_energy(&state, &mass), 62.5 + 375.0);
}

#[test]
fn the_ledger_books_by_hand() {
    let mut ledger = EnergyLedger::starting_at(10.0);
    ledger.hand(5.0);
    ledger.hand(-2.0);
    ledger.dissipated = 4.0;
    assert_eq!(ledger.work_in, 3.0);
    assert_eq!(ledger.work_moved, 7.0);
    assert_eq!(ledger.expected(), 10.0 + 3.0 - 4.0);
    assert_eq!(ledger.residual(9.5), 0.5);
    assert_eq!(ledger.throughput(), 10.0 + 7.0 + 4.0);
}

#[test]
fn a_step_opens_with_the_hands_work_since_the_last_or_a_fresh_ledger() {
    let mut ledger = EnergyLedger::starting_at(10.0);
    // The band moved between two steps: its energy went from 10 to 12.5, then 12 to 11.
    ledger.open_step(Some(10.0), 12.5);
    assert_eq!((ledger.work_in, ledger.work_moved), (2.5, 2.5));
    ledger.open_step(Some(12.0), 11.0);
    assert_eq!((ledger.work_in, ledger.work_moved), (1.5, 3.5));
    assert_eq!(ledger.initial, 10.0);
    // No previous step (the start, a reset): the books start again at the energy now.
    ledger.dissipated = 1.0;
    ledger.open_step(None, 7.0);
    assert_eq!(ledger, EnergyLedger::starting_at(7.0));
}

#[test]
fn the_games_ranges_include_their_ends_and_refuse_what_lies_outside() {
    let range = Range::new(1.0, 2.0, "px");
    for (value, inside) in [
        (1.0, true),
        (2.0, true),
        (1.5, true),
        (0.5, false),
        (2.5, false),
    ] {
        assert_eq!(range.contains(value), inside, "{value}");
    }
    assert!(!range.contains(f64::NAN));
    assert_eq!(ParamError::check_within("width", 1.0, &range), Ok(()));
    let refused = ParamError::check_within("width", 3.0, &range).unwrap_err();
    assert_eq!((refused.field, refused.value), ("width", 3.0));
    assert_eq!(refused.requirement, "from 1 to 2 px");

    let mut params = SceneParams::default();
    assert_eq!(params.check_playable(), Ok(()));
    params.stiffness = STIFFNESS_RANGE.high;
    assert_eq!(params.check_playable(), Ok(()));
    // A valid scene (any positive mass) that the game's controls cannot reach.
    params.mass = MASS_RANGE.high * 2.0;
    assert_eq!(params.validate(), Ok(()));
    let refused = params.check_playable().unwrap_err();
    assert_eq!(refused.field, "mass");
    assert_eq!(refused.requirement, MASS_RANGE.to_string());
}

#[test]
fn a_range_clamps_into_itself_and_names_its_ends_exactly() {
    let range = Range::new(0.5, 4.0, "Hz");
    let clamped: Vec<f64> = [0.1, 0.5, 2.0, 4.0, 9.0, f64::NAN, f64::INFINITY]
        .iter()
        .map(|&v| range.clamp(v))
        .collect();
    assert_eq!(clamped, [0.5, 0.5, 2.0, 4.0, 4.0, 0.5, 4.0]);
    assert_eq!(range.to_string(), "from 0.5 to 4 Hz");
    assert_eq!(Range::new(1e-3, 1e12, "").to_string(), "from 1e-3 to 1e12");
    // Slow motion to fast forward, through real time.
    assert!(TIME_SCALE_RANGE.contains(1.0) && TIME_SCALE_RANGE.clamp(0.0) < 1.0);
    assert_eq!(TIME_SCALE_RANGE.low * TIME_SCALE_RANGE.high, 1.0);
}

#[test]
fn a_number_is_written_plainly_in_the_usual_range_and_reads_back_the_same() {
    for (value, written) in [
        (0.0, "0"),
        (20.0, "20"),
        (0.05, "0.05"),
        (-4096.0, "-4096"),
        (1e5, "1e5"),
        (1e-3, "1e-3"),
        (-2.5e-7, "-2.5e-7"),
    ] {
        assert_eq!(exact(value), written);
    }
    for value in [0.1 + 0.2, 1.0 / 3.0, 6.02e23, -1e-300, f64::MIN_POSITIVE] {
        assert_eq!(exact(value).parse::<f64>(), Ok(value), "{value}");
    }
}

#[test]
fn each_integrator_has_a_colour_of_its_own() {
    let colours: Vec<[u8; 3]> = Integrator::ALL.iter().map(|i| i.colour()).collect();
    for (at, colour) in colours.iter().enumerate() {
        assert!(
            !colours[..at].contains(colour),
            "{colour:?} is used twice: {colours:?}"
        );
        // Drawn on the game's dark background and the report's white one.
        assert!(colour.iter().any(|&c| c > 64), "{colour:?} is too dark");
        assert!(colour.iter().any(|&c| c < 192), "{colour:?} is too light");
    }
}

#[test]
fn wrenches_accumulate_and_a_bands_length_is_its_stretch() {
    let mut wrench = Wrench {
        force: DVec2::new(1.0, 2.0),
        torque: 3.0,
    };
    wrench += Wrench {
        force: DVec2::new(10.0, 20.0),
        torque: 30.0,
    };
    assert_eq!(
        wrench,
        Wrench {
            force: DVec2::new(11.0, 22.0),
            torque: 33.0
        }
    );
    // The corner (30, 30) of a box at (10, -10), turned by nothing, is at (40, 20): 3-4-5.
    let band = BandEnds {
        local_point: DVec2::new(30.0, 30.0),
        anchor: DVec2::new(43.0, 24.0),
    };
    assert_eq!(
        band.length(&BodyState::at_rest(DVec2::new(10.0, -10.0))),
        5.0
    );
}

#[test]
fn angular_momentum_and_the_bands_rate_by_hand() {
    let params = SceneParams::tutorial();
    let mass = params.mass_properties().unwrap();
    let mut state = BodyState::at_rest(DVec2::new(10.0, 20.0));
    state.linear.velocity = DVec2::new(3.0, -4.0);
    state.angular.angular_velocity = 0.5;
    // About (0, 0): m (x × v) + I ω = 5 (10·−4 − 20·3) + 3000 · 0.5.
    assert_eq!(
        angular_momentum_about(&state, &mass, DVec2::ZERO),
        5.0 * (-40.0 - 60.0) + 1500.0
    );
    // About (10, 20), the centre itself: only the spin.
    assert_eq!(
        angular_momentum_about(&state, &mass, DVec2::new(10.0, 20.0)),
        1500.0
    );
    // A square pulled at a corner: sqrt(k (1/m + r²/I)) = sqrt(20 (0.2 + 1800/3000)) = 4.
    let band = BandEnds {
        local_point: DVec2::new(30.0, 30.0),
        anchor: DVec2::ZERO,
    };
    assert!((params.force_model(mass, Some(band)).band_rate() - 4.0).abs() < 1e-15);
    assert_eq!(params.force_model(mass, None).band_rate(), 0.0);
}

/// Each named scene is what its name and summary say (the CLI, the report and the tests pick
/// them by name).
#[test]
fn each_named_scene_is_what_it_says() {
    use rubber_band_box::physics::Scene;
    use rubber_band_box::physics::scenes::TUTORIAL_PULL_TARGET;
    let tutorial = SceneParams::tutorial();
    let held = f64::INFINITY;
    for name in Scene::NAMES {
        let s = Scene::named(name).unwrap();
        assert_eq!(s.name, name);
        let spin = s.initial.angular.angular_velocity;
        let targets: Vec<DVec2> = s.pulls.iter().map(|p| p.2).collect();
        match name {
            "tutorial" => {
                assert_eq!(s.pulls, [(0.0, 2.0, TUTORIAL_PULL_TARGET)]);
                assert_eq!(s.params, tutorial);
            }
            "diagonal" => assert_eq!(s.pulls, [(0.0, held, DVec2::new(150.0, 150.0))]),
            "stiff" => assert_eq!(s.params.stiffness, 1e5),
            "light" => assert_eq!(s.params.mass, 1e-3),
            "spin" => assert!(spin == 100.0 && s.pulls.is_empty()),
            "spin-band" => assert!(spin == 100.0 && targets == [TUTORIAL_PULL_TARGET]),
            "far" => assert_eq!(targets, [DVec2::new(1e6, 0.0)]),
            "undamped" => {
                assert_eq!(
                    (s.params.linear_damping, s.params.angular_damping),
                    (0.0, 0.0)
                )
            }
            "zero-length" => assert_eq!(targets, [DVec2::new(30.0, 30.0)]),
            "rest" => {
                assert!(s.pulls.is_empty() && s.params == tutorial);
                assert_eq!(s.initial, BodyState::default());
            }
            other => panic!("a scene this test does not know: {other}"),
        }
    }
    assert!(Scene::named("moon").is_err());
}
