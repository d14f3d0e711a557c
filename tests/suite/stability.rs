//! The stability view's numbers (`physics::stability`) against closed forms: each method's
//! one-step amplification on the band's stiffest mode, x'' = −ω²x − γx'.

use rubber_band_box::physics::stability::{
    Limit, Mode, margins, omega_at, spectral_radius, stiffest_held,
};
use rubber_band_box::physics::{AutoSettings, Integrator, SceneParams};

fn undamped() -> SceneParams {
    SceneParams {
        linear_damping: 0.0,
        angular_damping: 0.0,
        ..SceneParams::tutorial()
    }
}

/// ω·dt at the stiffest k a method holds.
fn limit(integrator: Integrator, params: &SceneParams, dt: f64) -> Option<f64> {
    match stiffest_held(integrator, params, dt, &AutoSettings::default()) {
        Limit::UpTo(k) => Some(omega_at(k, params.mass) * dt),
        other => panic!("{integrator}: {other:?}"),
    }
}

#[test]
fn the_stiffest_mode_of_a_box_pulled_at_a_corner() {
    let tutorial = SceneParams::tutorial();
    let mode = Mode::of(&tutorial);
    // ω² = k(1/m + r²/I): 20 (1/5 + 1800/3000) = 16.
    assert!((mode.omega - 4.0).abs() < 1e-12);
    // The translation's rate b/m and the rotation's c, weighed 1 : 3 as in ω².
    let rate = tutorial.linear_damping / tutorial.mass;
    assert!((mode.damping - (rate + 3.0 * tutorial.angular_damping) / 4.0).abs() < 1e-12);
}

#[test]
fn undamped_limits_are_the_textbooks() {
    let params = undamped();
    let dt = 0.01;
    // Explicit Euler grows every undamped oscillation: |1 + iωh| > 1.
    assert_eq!(
        stiffest_held(Integrator::Euler, &params, dt, &AutoSettings::default()),
        Limit::Never
    );
    // Symplectic Euler, velocity Verlet and the tutorial's own step: ω·dt = 2.
    for integrator in [Integrator::Symplectic, Integrator::Verlet, Integrator::Seed] {
        let at = limit(integrator, &params, dt).unwrap();
        assert!((at - 2.0).abs() < 1e-3, "{integrator}: {at}");
    }
    // Classical RK4: 2√2 on the imaginary axis.
    let rk4 = limit(Integrator::Rk4, &params, dt).unwrap();
    assert!((rk4 - 2.0 * 2f64.sqrt()).abs() < 1e-3, "rk4: {rk4}");
    // Backward Euler holds every k; so does auto, which falls back to it.
    for integrator in [Integrator::Implicit, Integrator::Auto] {
        assert_eq!(
            stiffest_held(integrator, &params, dt, &AutoSettings::default()),
            Limit::Any,
            "{integrator}"
        );
    }
}

#[test]
fn damping_moves_the_limits_as_the_closed_forms_say() {
    let params = SceneParams::tutorial();
    let dt = 0.01;
    let gamma = Mode::of(&params).damping;
    // Semi-implicit Euler: ω²h² + 2γh < 4.
    let symplectic = limit(Integrator::Symplectic, &params, dt).unwrap();
    let expected = (4.0 - 2.0 * gamma * dt).sqrt();
    assert!(
        (symplectic - expected).abs() < 1e-3,
        "{symplectic} vs {expected}"
    );
    assert!(symplectic < 2.0 - 5e-3, "damping lowers it below 2");
    // Explicit Euler: stable while the damping outweighs its growth, ω² < γ/h.
    let Limit::UpTo(k) = stiffest_held(Integrator::Euler, &params, dt, &AutoSettings::default())
    else {
        panic!("damped explicit Euler holds a soft band");
    };
    let expected = params.mass * gamma / (4.0 * dt);
    assert!((k / expected - 1.0).abs() < 1e-3, "{k} vs {expected}");
}

#[test]
fn the_spectral_radius_is_the_closed_forms() {
    let params = undamped();
    let dt = 0.01;
    let wh = Mode::of(&params).omega * dt;
    let auto = AutoSettings::default();
    // Explicit Euler: sqrt(1 + (ωh)²).
    let euler = spectral_radius(Integrator::Euler, &params, dt, &auto);
    assert!((euler - (1.0 + wh * wh).sqrt()).abs() < 1e-12, "{euler}");
    // Backward Euler: 1 / sqrt(1 + (ωh)²).
    let implicit = spectral_radius(Integrator::Implicit, &params, dt, &auto);
    assert!(
        (implicit - 1.0 / (1.0 + wh * wh).sqrt()).abs() < 1e-9,
        "{implicit}"
    );
    // Symplectic Euler below its limit: exactly on the unit circle.
    let symplectic = spectral_radius(Integrator::Symplectic, &params, dt, &auto);
    assert!((symplectic - 1.0).abs() < 1e-12, "{symplectic}");
    // Past it (ωh = 4): the larger real root of λ² − (2 − ω²h²)λ + 1.
    let stiff = SceneParams {
        stiffness: params.stiffness * 4.0 / (wh * wh) * 4.0,
        ..params
    };
    let beyond = spectral_radius(Integrator::Symplectic, &stiff, dt, &auto);
    let t: f64 = 2.0 - 16.0;
    let expected = (-t / 2.0) + (t * t / 4.0 - 1.0).sqrt();
    assert!(
        (beyond / expected - 1.0).abs() < 1e-9,
        "{beyond} vs {expected}"
    );
}

#[test]
fn the_margins_say_which_methods_hold_the_present_band() {
    // k = 1e5 at 100 Hz: ω·dt = 2.83, past the symplectic methods' 2 and RK4's 2.83 (just).
    let params = SceneParams {
        stiffness: 1e5,
        ..SceneParams::tutorial()
    };
    let found = margins(&params, &AutoSettings::default());
    assert_eq!(found.len(), Integrator::ALL.len());
    let holds = |integrator: Integrator| {
        found
            .iter()
            .find(|m| m.integrator == integrator)
            .unwrap()
            .holds
    };
    for integrator in [
        Integrator::Euler,
        Integrator::Symplectic,
        Integrator::Verlet,
        Integrator::Seed,
    ] {
        assert!(!holds(integrator), "{integrator}");
    }
    for integrator in [Integrator::Implicit, Integrator::Auto] {
        assert!(holds(integrator), "{integrator}");
    }
    let omega_dt = found[0].omega_dt;
    assert!((omega_dt - 2.0 * (1e5f64 / 5.0).sqrt() * 0.01).abs() < 1e-12);
    // The tutorial's band at 100 Hz: every method holds (explicit Euler by its damping).
    let gentle = margins(&SceneParams::tutorial(), &AutoSettings::default());
    for margin in &gentle {
        assert!(margin.holds, "{:?}", margin.integrator);
    }
}

#[test]
fn an_overdamped_mode_decays_at_its_slower_rate() {
    // Heavy damping: both roots of s² + γs + ω² are real, and one step of a fourth-order method
    // scales the mode by about exp(s·dt) for the slower one, the larger in size.
    let params = SceneParams {
        linear_damping: 320.0,
        angular_damping: 0.0,
        ..SceneParams::tutorial()
    };
    let mode = Mode::of(&params);
    let half = mode.damping / 2.0;
    assert!(half > mode.omega, "{mode:?} is not overdamped");
    let slower = -half + (half * half - mode.omega * mode.omega).sqrt();
    let dt = 1e-3;
    let radius = spectral_radius(Integrator::Rk4, &params, dt, &AutoSettings::default());
    assert!(
        (radius - (slower * dt).exp()).abs() < 1e-9,
        "{radius} against {}",
        (slower * dt).exp()
    );
}

#[test]
fn undamped_margins_hold_on_the_nose_and_name_the_textbooks_limits() {
    // Undamped, a symplectic step keeps the mode's size exactly (|λ| = 1 up to round-off):
    // the margin holds it, and its limit is ω·dt = 2 at the game's step.
    let params = undamped();
    for margin in margins(&params, &AutoSettings::default()) {
        if matches!(
            margin.integrator,
            Integrator::Symplectic | Integrator::Verlet | Integrator::Seed
        ) {
            assert!((margin.spectral_radius - 1.0).abs() < 1e-12, "{margin:?}");
            assert!(margin.holds, "{margin:?}");
            let limit = margin.limit_omega_dt.expect("a limit");
            assert!((limit - 2.0).abs() < 1e-3, "{margin:?}");
        }
    }
}
