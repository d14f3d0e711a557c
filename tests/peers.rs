//! The peers' harness (`cargo test --features peers --test peers`): each engine holds the
//! scene as we set it up, and our own contender is the core, step for step. CI runs these.

#[path = "suite/common.rs"]
mod common;

use rubber_band_box::measure::peers::avian::Avian;
use rubber_band_box::measure::peers::empty::Empty;
use rubber_band_box::measure::peers::ours::Ours;
use rubber_band_box::measure::peers::rapier::Rapier;
use rubber_band_box::measure::peers::{Contender, PeerRun, unwrap_angle};
use rubber_band_box::measure::references::reference_state;
use rubber_band_box::physics::{BodyState, Integrator, Run, Scene};

#[test]
fn our_contender_steps_exactly_as_the_core() {
    let scene = Scene::named("tutorial").unwrap();
    let mut app = PeerRun::<Ours>::of(&scene, 100.0);
    let mut core = Run::of(&scene, Integrator::Auto, 0.01).unwrap();
    for _ in 0..300 {
        app.advance();
        core.advance().unwrap();
    }
    assert_eq!(app.state(), core.stepper.state);
}

/// The floor the plugin's cost is measured against goes through the same calls as ours: the
/// scene's pulls put and take its band entity, and with no physics its box never moves.
#[test]
fn the_empty_app_holds_the_band_and_never_moves_the_box() {
    use rubber_band_box::game::simulation::Band;
    let scene = Scene::named("tutorial").unwrap();
    let mut run = PeerRun::<Empty>::of(&scene, 100.0);
    let bands = |run: &mut PeerRun<Empty>| {
        let world = run.contender.app().world_mut();
        world.query::<&Band>().iter(world).count()
    };
    assert_eq!(bands(&mut run), 1, "the tutorial pulls from its first step");
    run.advance_by(250);
    assert_eq!(bands(&mut run), 0, "released after 2 s");
    assert_eq!(run.state(), scene.initial);
}

/// A box at rest with no band stays at rest, and a pulled one moves toward the anchor and
/// ends near the reference: the set-up (mass, damping, spring, no gravity) is the scene's.
fn holds_the_scene<C: Contender>(tolerance: f64) {
    let rest = Scene::named("rest").unwrap();
    let mut run = PeerRun::<C>::of(&rest, 100.0);
    run.advance_by(50);
    assert_eq!(run.state(), BodyState::default(), "{}", C::NAME);

    let tutorial = Scene::named("tutorial").unwrap();
    let mut run = PeerRun::<C>::of(&tutorial, 100.0);
    run.advance_by(400);
    let reference = reference_state(&tutorial, 4.0, 1e-4);
    let error = run.state().pose_error(&reference, &run.mass);
    assert!(error < tolerance, "{}: {error} px after 4 s", C::NAME);
}

#[test]
fn avian_holds_the_scene() {
    holds_the_scene::<Avian>(5.0);
}

#[test]
fn rapier_holds_the_scene() {
    holds_the_scene::<Rapier>(5.0);
}

#[test]
fn a_released_band_stops_pulling() {
    // Pulled for 2 s then released: afterwards only damping acts, so the speed only falls.
    fn speeds<C: Contender>() -> Vec<f64> {
        let tutorial = Scene::named("tutorial").unwrap();
        let mut run = PeerRun::<C>::of(&tutorial, 100.0);
        run.advance_by(201);
        (0..100)
            .map(|_| {
                run.advance();
                run.state().linear.velocity.length()
            })
            .collect()
    }
    for (name, speeds) in [
        (Avian::NAME, speeds::<Avian>()),
        (Rapier::NAME, speeds::<Rapier>()),
    ] {
        assert!(speeds.windows(2).all(|w| w[1] <= w[0]), "{name}");
        assert!(speeds[0] > 1.0, "{name}: the band had moved the box");
    }
}

#[test]
fn angles_unwrap_to_the_nearest_turn() {
    let turn = std::f64::consts::TAU;
    assert_eq!(unwrap_angle(0.0, 0.5), 0.5);
    assert!((unwrap_angle(3.0 * turn + 3.1, -3.1) - (3.0 * turn + turn - 3.1)).abs() < 1e-12);
}

/// The band pulls from the very first step: after one step from rest the box moves, in every
/// contender, by about the same amount.
#[test]
fn the_band_acts_from_the_first_step() {
    fn first_step<C: Contender>() -> BodyState {
        let tutorial = Scene::named("tutorial").unwrap();
        let mut run = PeerRun::<C>::of(&tutorial, 100.0);
        run.advance();
        run.state()
    }
    let ours = first_step::<Ours>();
    for (name, state) in [
        (Avian::NAME, first_step::<Avian>()),
        (Rapier::NAME, first_step::<Rapier>()),
    ] {
        let ratio = state.linear.velocity.length() / ours.linear.velocity.length();
        assert!(
            (ratio - 1.0).abs() < 0.05,
            "{name}: {state:?} against {ours:?}"
        );
    }
}

/// What the harness must switch off for the peers to hold our scene, checked by what it does:
/// sleeping (a damped box slowing below the crates' sleep thresholds keeps decaying at its
/// rate instead of stopping dead), rapier's speed cap (400 units per second by default: the
/// far anchor's pull is far faster), and avian's f32 transform sync (an f64 position that f32
/// cannot hold stays exact).
fn never_sleeps_and_is_not_speed_capped<C: Contender>() {
    // Released at 2 s, then damped at b/m = 1 /s: by 10 s a few hundredths of a px/s.
    let tutorial = Scene::named("tutorial").unwrap();
    let mut run = PeerRun::<C>::of(&tutorial, 100.0);
    run.advance_by(900);
    let at_9_s = run.state().linear.velocity.length();
    run.advance_by(100);
    let at_10_s = run.state().linear.velocity.length();
    assert!(
        at_10_s > 0.0 && at_10_s < 1.0,
        "{}: {at_9_s} -> {at_10_s}",
        C::NAME
    );
    let rate = (at_9_s / at_10_s).ln();
    assert!(
        (rate - 1.0).abs() < 0.05,
        "{}: decay rate {rate} /s",
        C::NAME
    );

    let far = Scene::named("far").unwrap();
    let mut run = PeerRun::<C>::of(&far, 100.0);
    run.advance_by(10);
    let speed = run.state().linear.velocity.length();
    assert!(speed > 1e4, "{}: {speed} px/s after 0.1 s", C::NAME);
}

#[test]
fn avian2d_never_sleeps_and_is_not_speed_capped() {
    never_sleeps_and_is_not_speed_capped::<Avian>();
}

#[test]
fn bevy_rapier2d_never_sleeps_and_is_not_speed_capped() {
    never_sleeps_and_is_not_speed_capped::<Rapier>();
}

#[test]
fn avian2d_keeps_f64_positions_with_no_transform_round_trip() {
    let mut scene = Scene::named("rest").unwrap();
    scene.initial.linear.position.x = 1000.1;
    assert_ne!(f64::from(1000.1_f32), 1000.1);
    let mut run = PeerRun::<Avian>::of(&scene, 100.0);
    run.advance_by(10);
    assert_eq!(run.state().linear.position.x, 1000.1);
}

/// `report --replay --peers`: a recorded hand (a reset, a settings change) drives each
/// contender; ours, rebuilt at the settings change, steps exactly as the core's replay run,
/// at the recorded rate and at twice it; the peers follow the same band.
#[test]
fn a_replay_drives_every_contender_with_the_recorded_hand() {
    use rubber_band_box::measure::peers::replay::PeerReplay;
    use rubber_band_box::replay::run::ReplayRun;

    let replay = common::small_replay();
    for substeps in [1, 2] {
        let mut ours = PeerReplay::<Ours>::new(&replay, substeps);
        let mut core = ReplayRun::new(&replay, Some(Integrator::Auto))
            .unwrap()
            .subdivided(substeps);
        let mut steps = 0;
        while core.advance().is_some() {
            assert!(ours.advance().is_some());
            assert_eq!(
                ours.state(),
                core.stepper.state,
                "step {steps}, x{substeps}"
            );
            steps += 1;
        }
        assert!(ours.advance().is_none());
        assert_eq!(steps, replay.steps);
    }
    fn follows<C: Contender>(replay: &rubber_band_box::replay::Replay) {
        let mut run = PeerReplay::<C>::new(replay, 1);
        while run.advance().is_some() {
            assert!(run.state().is_finite(), "{}", C::NAME);
        }
        // The last steps pull toward (200, 120) from the centre.
        let position = run.state().linear.position;
        assert!(
            position.x > 0.0 && position.y > 0.0,
            "{}: {position}",
            C::NAME
        );
    }
    follows::<Avian>(&replay);
    follows::<Rapier>(&replay);
}
