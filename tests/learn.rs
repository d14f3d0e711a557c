//! Learn mode (docs/learn.md): every chapter's live values equal the quantities recomputed
//! here from the body's components and the scene's parameters (by the tutorial's formulas,
//! not through the code that writes them), to the last printed digit; each chapter's task
//! passes under the action it asks for and not without it; leaving puts the game back.

mod common;

use bevy::input::ButtonState;
use bevy::math::DVec2;
use bevy::prelude::*;

use common::{Game, world_to_screen};
use rubber_band_box::game::input::controls::Parameter;
use rubber_band_box::game::input::controls::{LEARN, PAUSE, SINGLE_STEP};
use rubber_band_box::game::learn::chapters::{CHAPTERS, Task};
use rubber_band_box::game::learn::twin::{CentreTwin, TWIN_OFFSET};
use rubber_band_box::game::learn::{LINES, Learn, LearnText, Learning};
use rubber_band_box::game::shared::{Overlays, SceneName, readable};
use rubber_band_box::game::simulation::{Band, EnergyBooks, RigidBox};
use rubber_band_box::physics::{
    AngularState, Integrator, LinearState, MassProperties, SceneParams,
};

/// The chapter's equations, a line each, as the card shows them.
fn equations(game: &mut Game) -> String {
    (0..LINES)
        .map(|line| card(game, LearnText::Line(line)))
        .filter(|line| !line.is_empty())
        .collect::<Vec<_>>()
        .join("\n")
}

fn card(game: &mut Game, which: LearnText) -> String {
    let mut texts = game.world().query::<(&LearnText, &Text)>();
    texts
        .iter(game.world())
        .find(|(kind, _)| **kind == which)
        .map(|(_, text)| text.0.clone())
        .expect("the Learn card's texts are spawned")
}

fn chapter(game: &mut Game, index: usize) {
    game.world().trigger(Learn::Chapter(index));
    game.update(1);
    assert_eq!(game.world().resource::<Learning>().chapter, Some(index));
}

/// A number as the card prints it (the HUD's format, a true minus sign).
fn n(value: f64) -> String {
    readable(value).replace('-', "−")
}

fn v(value: DVec2) -> String {
    format!("({}, {})", n(value.x), n(value.y))
}

/// What the card must show now, recomputed from the components: each chapter's quantities.
fn expected(game: &mut Game, index: usize) -> Vec<String> {
    let world = game.world();
    let params = *world.resource::<SceneParams>();
    let ledger = world.resource::<EnergyBooks>().ledger;
    let (body, linear, angular, mass) = world
        .query_filtered::<(Entity, &LinearState, &AngularState, &MassProperties), With<RigidBox>>()
        .single(world)
        .map(|(e, l, a, m)| (e, *l, *a, *m))
        .unwrap();
    let band = world
        .query::<&Band>()
        .iter(world)
        .find(|band| band.body == body)
        .map(|band| band.ends);
    let m = params.mass;
    let (w, h) = (params.size.x, params.size.y);
    // The tutorial's moment of inertia of a box, from the parameters (§4.3.4).
    let inertia = m * (w * w + h * h) / 12.0;
    assert!((inertia - mass.inertia()).abs() <= 1e-12 * inertia);
    let (x, vel) = (linear.position, linear.velocity);
    let (theta, omega) = (angular.orientation, angular.angular_velocity);
    let (corner, anchor) = match band {
        Some(ends) => {
            let (sin, cos) = theta.sin_cos();
            let p = ends.local_point;
            (
                Some(x + DVec2::new(cos * p.x - sin * p.y, sin * p.x + cos * p.y)),
                Some(ends.anchor),
            )
        }
        None => (None, None),
    };
    let force = match (corner, anchor) {
        (Some(p), Some(q)) => -params.stiffness * (p - q),
        _ => DVec2::ZERO,
    };
    let arm = corner.map_or(DVec2::ZERO, |p| p - x);
    let torque = arm.x * force.y - arm.y * force.x;
    let damp = -params.linear_damping * vel;
    let damp_torque = -params.angular_damping * inertia * omega;
    let sum = force + damp;
    let torques = torque + damp_torque;
    let mut wanted = Vec::new();
    match CHAPTERS[index].task {
        Task::MoveWithoutTurning => {
            wanted.push(v(sum));
            wanted.push(v(sum / m));
            wanted.push(v(x));
            wanted.push(v(vel));
        }
        Task::SpinWithoutDamping => {
            wanted.push(format!("θ = {} rad", n(theta)));
            wanted.push(format!("ω = dθ/dt = {} rad/s", n(omega)));
            wanted.push(n(-params.angular_damping * omega));
            wanted.push(n(inertia));
        }
        Task::SpinClockwise => {
            wanted.push(format!(
                "τ = r × F = {} × {} = {}",
                v(arm),
                v(force),
                n(torque)
            ));
            wanted.push(v(sum / m));
            wanted.push(n(torques / inertia));
            // The centre twin: the same band's anchor moved by the offset, held at its centre.
            let twin = world.resource::<CentreTwin>().body.clone().expect("a twin");
            let state = twin.stepper.state;
            let pulled = band.map(|ends| ends.anchor + TWIN_OFFSET);
            assert_eq!(twin.anchor(), pulled);
            if let Some(q) = pulled {
                let f = -params.stiffness * (state.linear.position - q);
                wanted.push(format!(
                    "twin: F = −k (x − q) = {}, a = F / m = {}",
                    v(f),
                    v(f / m)
                ));
                // Pulled through its centre, it never turns.
                assert_eq!(state.angular.orientation, 0.0);
                wanted.push("twin: r = 0, τ = 0 × F = 0, θ = 0 rad".to_owned());
            }
        }
        Task::DoubleTheInertia => {
            wanted.push(format!("= {}", n(inertia)));
            wanted.push(n(torques / inertia));
        }
        Task::ThreeCorners => {
            if let (Some(p), Some(q)) = (corner, anchor) {
                wanted.push(v(p));
                wanted.push(v(q));
                wanted.push(v(force));
                wanted.push(n(p.distance(q)));
            }
        }
        Task::ComeToRest => {
            let stretch = match (corner, anchor) {
                (Some(p), Some(q)) => p.distance_squared(q),
                _ => 0.0,
            };
            let kinetic = 0.5 * m * vel.length_squared();
            let turning = 0.5 * inertia * omega * omega;
            let elastic = 0.5 * params.stiffness * stretch;
            wanted.push(v(damp));
            wanted.push(n(damp_torque));
            wanted.push(n(kinetic + turning + elastic));
            let f = |x: f64| if x < 0.0 { format!("({})", n(x)) } else { n(x) };
            wanted.push(format!(
                "E₀ + W_hand − W_damp = {} + {} − {} = {}",
                n(ledger.initial),
                f(ledger.work_in),
                f(ledger.dissipated),
                n(ledger.initial + ledger.work_in - ledger.dissipated)
            ));
        }
        Task::StepFiveTimes => {
            wanted.push(format!("ΣF = {}", v(sum)));
            wanted.push(format!("a = ΣF / m = {}", v(sum / m)));
            wanted.push(format!("Στ = Σ r × F = {}", n(torques)));
            wanted.push(format!("α = Στ / I = {}", n(torques / inertia)));
        }
    }
    wanted
}

/// Every chapter's numbers, at several frames of a pull toward the upper right and a release.
#[test]
fn every_chapters_values_are_the_components_recomputed() {
    let mut game = Game::stepping();
    game.update(2);
    game.tap_key(LEARN);
    game.update(1);
    assert_eq!(game.world().resource::<Learning>().chapter, Some(0));
    for (index, shown) in CHAPTERS.iter().enumerate() {
        chapter(&mut game, index);
        let title = card(&mut game, LearnText::Title);
        assert!(title.contains(shown.title), "{title}");
        game.press_at(DVec2::new(160.0, 110.0));
        for frame in 0..40 {
            if frame < 25 {
                let at = DVec2::new(160.0 + 2.0 * f64::from(frame), 110.0 - f64::from(frame));
                game.cursor(Some(world_to_screen(at)));
            } else if frame == 25 {
                game.mouse(ButtonState::Released);
            }
            game.update(1);
            if frame % 6 == 5 {
                let shown = equations(&mut game);
                for wanted in expected(&mut game, index) {
                    assert!(
                        shown.contains(&wanted),
                        "chapter {} frame {frame}: '{wanted}' not in\n{shown}",
                        index + 1
                    );
                }
            }
        }
    }
}

/// Plays a chapter's scripted action (or none) and says whether its task was judged done.
fn task_done(index: usize, act: bool) -> bool {
    let mut game = Game::stepping();
    game.update(2);
    chapter(&mut game, index);
    // Let a scene's script run a moment first: it is not the player's pull.
    game.update(30);
    if act {
        match CHAPTERS[index].task {
            Task::MoveWithoutTurning => {
                // Along the diagonal through the centre: no torque.
                let x = game.state().0.position;
                game.press_at(x + DVec2::new(150.0, 150.0));
                game.update(60);
                game.mouse(ButtonState::Released);
            }
            Task::SpinWithoutDamping => {
                game.world()
                    .write_message(rubber_band_box::game::input::controls::Action::Set(
                        Parameter::AngularDamping,
                        0.0,
                    ));
            }
            Task::SpinClockwise => {
                // Below and right of the box: the lower-right corner pulled down turns it
                // clockwise.
                let x = game.state().0.position;
                game.press_at(x + DVec2::new(120.0, -200.0));
                game.update(30);
            }
            Task::DoubleTheInertia => {
                let mass = game.world().resource::<SceneParams>().mass;
                game.world()
                    .write_message(rubber_band_box::game::input::controls::Action::Set(
                        Parameter::Mass,
                        2.0 * mass,
                    ));
            }
            Task::ThreeCorners => {
                for at in [
                    DVec2::new(200.0, 200.0),
                    DVec2::new(-200.0, 200.0),
                    DVec2::new(-200.0, -200.0),
                ] {
                    game.press_at(at);
                    game.update(2);
                    game.mouse(ButtonState::Released);
                    game.update(2);
                }
            }
            Task::ComeToRest => {
                game.press_at(DVec2::new(200.0, 120.0));
                game.update(50);
                game.mouse(ButtonState::Released);
            }
            Task::StepFiveTimes => {
                game.tap_key(PAUSE);
                game.update(2);
                for _ in 0..5 {
                    game.tap_key(SINGLE_STEP);
                    game.update(2);
                }
            }
        }
    } else if CHAPTERS[index].task == Task::StepFiveTimes {
        // Paused, without stepping.
        game.tap_key(PAUSE);
        game.update(12);
    }
    game.update(600);
    game.world().resource::<Learning>().done[index]
}

#[test]
fn each_chapters_task_passes_under_its_action_and_not_without() {
    for index in 0..CHAPTERS.len() {
        assert!(
            !task_done(index, false),
            "chapter {}: done without the action",
            index + 1
        );
        assert!(task_done(index, true), "chapter {}: not done", index + 1);
    }
}

/// The moment of inertia's chapter takes the size as well as the mass: a side √2 times as
/// long doubles I, the box drawn and stepped at its new size.
#[test]
fn a_side_root_two_times_as_long_does_the_inertias_task() {
    use rubber_band_box::game::input::controls::Action;
    let index = CHAPTERS
        .iter()
        .position(|chapter| chapter.task == Task::DoubleTheInertia)
        .unwrap();
    let mut game = Game::stepping();
    game.update(2);
    chapter(&mut game, index);
    let side = game.world().resource::<SceneParams>().size.x;
    game.world()
        .write_message(Action::Set(Parameter::Size, 1.2 * side));
    game.update(3);
    assert!(!game.world().resource::<Learning>().done[index]);
    game.world().write_message(Action::Set(
        Parameter::Size,
        std::f64::consts::SQRT_2 * side,
    ));
    game.update(3);
    let mut boxes = game
        .world()
        .query_filtered::<&MassProperties, With<RigidBox>>();
    let size = boxes.single(game.world()).unwrap().size();
    assert_eq!(size, DVec2::splat(std::f64::consts::SQRT_2 * side));
    assert!(game.world().resource::<Learning>().done[index]);
    let shown = equations(&mut game);
    assert!(
        shown.contains(&format!("({}² + {}²)", n(size.x), n(size.y))),
        "{shown}"
    );
}

#[test]
fn leaving_learn_mode_puts_the_game_back_as_it_was() {
    let mut game = Game::stepping();
    game.update(2);
    // A game of the player's own: other settings, overlays, a pull under way, then let go.
    game.tap_key(rubber_band_box::game::input::controls::STIFFER);
    game.tap_key(rubber_band_box::game::input::controls::CYCLE_INTEGRATOR);
    game.tap_key(rubber_band_box::game::input::controls::GHOSTS);
    game.update(2);
    game.press_at(DVec2::new(150.0, 80.0));
    game.update(20);
    game.mouse(ButtonState::Released);
    game.update(3);
    let world = game.world();
    let before = (
        *world.resource::<SceneParams>(),
        *world.resource::<Integrator>(),
        *world.resource::<Overlays>(),
        world.resource::<SceneName>().clone(),
    );
    let state = game.state();
    game.tap_key(LEARN);
    game.update(2);
    for _ in 0..CHAPTERS.len() {
        game.world().trigger(Learn::Next);
        game.update(20);
    }
    assert!(game.world().resource::<Overlays>().learn);
    game.tap_key(LEARN);
    game.update(1);
    let world = game.world();
    assert_eq!(world.resource::<Learning>().chapter, None);
    let after = (
        *world.resource::<SceneParams>(),
        *world.resource::<Integrator>(),
        *world.resource::<Overlays>(),
        world.resource::<SceneName>().clone(),
    );
    assert_eq!(after, before);
    let bands = world.query::<&Band>().iter(world).count();
    assert_eq!(bands, 0);
    // The box where it was, moving as it was (one step on, as the frame steps it).
    let (linear, _) = game.state();
    assert!(linear.position.distance(state.0.position) < 1.0 + 0.01 * state.0.velocity.length());
}
