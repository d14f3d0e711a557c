//! Learn mode (docs/learn.md): every chapter's live values equal the quantities recomputed
//! here from the body's components and the scene's parameters (by the tutorial's formulas,
//! not through the code that writes them), to the last printed digit; each chapter's task
//! passes under the action it asks for and not without it; leaving puts the game back.

use crate::common;

use bevy::input::ButtonState;
use bevy::math::DVec2;
use bevy::prelude::*;

use common::{Action, Game, Overlay, key, world_to_screen};
use rubber_band_box::game::input::controls::Parameter;

use rubber_band_box::game::learn::chapters::{CHAPTERS, Task};
use rubber_band_box::game::learn::twin::{CentreTwin, TWIN_OFFSET};
use rubber_band_box::game::learn::{LINES, Learn, LearnText, Learning, Verdict, chapter_shown};
use rubber_band_box::game::shared::{Mode, Overlays, SceneName};
use rubber_band_box::game::simulation::{Band, EnergyBooks, RigidBox};
use rubber_band_box::game::theme::{precise, readable};
use rubber_band_box::physics::{
    AngularState, BandEnds, BodyState, Integrator, LinearState, MassProperties, SceneParams,
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
    // The chapter pauses the clock, then loads its scene on the next frame.
    game.update(2);
    assert_eq!(chapter_shown(game.world()), Some(index));
}

/// Opens a chapter, answers its question (the chapter waits paused until then) and resumes.
fn run_chapter(game: &mut Game, index: usize) {
    chapter(game, index);
    game.world().trigger(Learn::Predict(RIGHT[index]));
    game.world().write_message(Action::TogglePause);
    game.update(1);
    assert!(!game.world().resource::<Time<Virtual>>().is_paused());
}

/// A number as the card prints it (the HUD's format, a true minus sign).
fn n(value: f64) -> String {
    precise(value).replace('-', "−")
}

fn v(value: DVec2) -> String {
    format!("({}, {})", n(value.x), n(value.y))
}

/// The box's state, its mass properties and the band on it, read from the components.
fn the_box(game: &mut Game) -> (BodyState, MassProperties, Option<BandEnds>) {
    let world = game.world();
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
    (BodyState { linear, angular }, mass, band)
}

/// What the card must show now, recomputed from the components: each chapter's quantities.
fn expected(game: &mut Game, index: usize) -> Vec<String> {
    let (BodyState { linear, angular }, mass, band) = the_box(game);
    let world = game.world();
    let params = *world.resource::<SceneParams>();
    let ledger = world.resource::<EnergyBooks>().ledger;
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
    let f = |x: f64| if x < 0.0 { format!("({})", n(x)) } else { n(x) };
    let torque_parts = format!(
        "Στ = τ_band + τ_damp = {} + {} = {}",
        n(torque),
        f(damp_torque),
        n(torques)
    );
    let perp_dot = format!(
        "τ = r × F = r_x·F_y − r_y·F_x = {}·{} − {}·{} = {}",
        n(arm.x),
        f(force.y),
        f(arm.y),
        f(force.x),
        n(torque)
    );
    let mut wanted = Vec::new();
    match CHAPTERS[index].task {
        Task::TurnThroughTheCentre => {
            wanted.push(v(sum));
            wanted.push(v(sum / m));
            wanted.push(v(x));
            wanted.push(v(vel));
        }
        Task::SpinWithoutDamping => {
            wanted.push(format!("θ = {} rad", n(theta)));
            wanted.push(format!("ω = dθ/dt = {} rad/s", n(omega)));
            wanted.push(n(-params.angular_damping * omega));
        }
        Task::SignOfTorque => {
            wanted.push(perp_dot);
            wanted.push(v(sum / m));
            wanted.push(format!("ω = dθ/dt = {} rad/s", n(omega)));
            // The velocity of the band's corner, ω r⊥ with r⊥ = (−r_y, r_x).
            if band.is_some() {
                wanted.push(v(vel + omega * DVec2::new(-arm.y, arm.x)));
            }
            // The centre twin: the box's own band force at its centre, and its own damping.
            let twin = world.resource::<CentreTwin>().body.expect("a twin");
            if band.is_some() {
                let drag = -params.linear_damping * vel;
                wanted.push(format!(
                    "outline: the box's ΣF = {} + {} as if at its centre, a = ΣF / m = {}",
                    v(force),
                    v(drag),
                    v((force + drag) / m)
                ));
                wanted.push(format!(
                    "outline: r = 0, no torque about its centre, θ = {} rad",
                    n(twin.orientation)
                ));
            }
        }
        Task::DoubleTheInertia => {
            // Σ mᵢ |rᵢ|² over the card's n × n masses at the cells' centres, summed here.
            let count = world.resource::<Learning>().point_masses;
            let cells = f64::from(count);
            let mut sum = 0.0;
            for i in 0..count {
                for j in 0..count {
                    let rx = (f64::from(i) + 0.5) * w / cells - w / 2.0;
                    let ry = (f64::from(j) + 0.5) * h / cells - h / 2.0;
                    sum += m / (cells * cells) * (rx * rx + ry * ry);
                }
            }
            wanted.push(format!("over {count} by {count} masses"));
            // Their centre of mass, x + Σ mₖ R(θ) rₖ / m: the box's centre.
            wanted.push(format!("Σ mₖ xₖ / m = {} = x", v(x)));
            wanted.push(format!("= {} mu·px² (", n(sum)));
            wanted.push(format!("= {}", n(inertia)));
            wanted.push(format!(
                "L = I ω about the centre = {}·{} = {} mu·px²/s",
                n(inertia),
                f(omega),
                n(inertia * omega)
            ));
            wanted.push(torque_parts);
            wanted.push(format!("= {} rad/s²", n(torques / inertia)));
        }
        Task::HeldCorner => {
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
            let books = ledger.initial + ledger.work_in - ledger.dissipated;
            wanted.push(format!(
                "books: E₀ + W_hand − W_damp = {} + {} − {} = {}",
                n(ledger.initial),
                f(ledger.work_in),
                f(ledger.dissipated),
                n(books)
            ));
            let e = world.resource::<EnergyBooks>().energies;
            let integrator = *world.resource::<Integrator>();
            wanted.push(format!(
                "E after the step − books = {}: the error of {}",
                n(e.linear + e.rotational + e.band - books),
                integrator.name()
            ));
        }
        Task::MoreEnergy => {
            let moving = 0.5 * m * vel.length_squared();
            let turning = 0.5 * inertia * omega * omega;
            wanted.push(format!(
                "box: ½mv² + ½Iω² = {} + {} = {} mu·px²/s²",
                n(moving),
                n(turning),
                n(moving + turning)
            ));
            wanted.push(format!("outline: ½mv² = {} mu·px²/s²", n(moving)));
        }
        Task::StepOrder => {
            // The tutorial's update (its appendix's RigidBody.update after AngularDamping),
            // redone here: ω scaled first, a and α from the forces at the start, then ω, θ,
            // v, x, each from the one just updated.
            let dt = params.dt();
            let factor = (-params.angular_damping * dt).exp();
            let damped = omega * factor;
            let a = force / m + damp / m;
            let alpha = torque / inertia;
            let omega_after = damped + alpha * dt;
            let theta_after = theta + omega_after * dt;
            let v_after = vel + a * dt;
            let x_after = x + v_after * dt;
            wanted.push(format!("= {}", n(damped)));
            wanted.push(format!("= {}", v(a)));
            wanted.push(format!("= {}", n(alpha)));
            wanted.push(format!(
                "ω += α_band dt → {}   θ += ω dt → {}",
                n(omega_after),
                n(theta_after)
            ));
            wanted.push(format!(
                "v += a dt → {}   x += v dt → {}",
                v(v_after),
                v(x_after)
            ));
        }
    }
    wanted
}

/// Every chapter's numbers, at several frames of a pull toward the upper right and a release.
#[test]
fn every_chapters_values_are_the_components_recomputed() {
    let mut game = Game::stepping();
    game.update(2);
    game.tap_key(key(Action::Learn));
    game.update(1);
    assert_eq!(chapter_shown(game.world()), Some(0));
    for (index, shown) in CHAPTERS.iter().enumerate() {
        run_chapter(&mut game, index);
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

/// Each chapter's right answer to its prediction, under the action [`task_done`] takes.
const RIGHT: [usize; 8] = [1, 1, 1, 2, 0, 0, 1, 0];

/// Opens a chapter, chooses `answer` (if any), does the chapter's experiment (if `act`), and
/// returns whether the prediction was judged right, and the verdict's text as the card shows it.
fn task_done(index: usize, answer: Option<usize>, act: bool) -> (bool, String) {
    use rubber_band_box::game::input::controls::Action;
    let mut game = Game::stepping();
    game.update(2);
    chapter(&mut game, index);
    // The chapter waits, paused: a scene's script does not run before the answer.
    game.update(30);
    if let Some(answer) = answer {
        game.world().trigger(Learn::Predict(answer));
        game.update(1);
        assert_eq!(
            game.world().resource::<Learning>().predicted(),
            Some(answer)
        );
    }
    let resume = |game: &mut Game| {
        game.world().write_message(Action::TogglePause);
        game.update(1);
    };
    let step = |game: &mut Game| {
        game.world().write_message(Action::Step);
        game.update(2);
    };
    if act {
        match CHAPTERS[index].task {
            // The scene's own pulls: along the diagonal; toward (200, 120); 2 s, then let go.
            Task::TurnThroughTheCentre
            | Task::SignOfTorque
            | Task::ComeToRest
            | Task::MoreEnergy => resume(&mut game),
            Task::SpinWithoutDamping => {
                game.world()
                    .write_message(Action::Set(Parameter::AngularDamping, 0.0));
                game.update(1);
                resume(&mut game);
            }
            Task::DoubleTheInertia => {
                // Paused: a single step, the mass doubled, a single step.
                step(&mut game);
                let mass = game.world().resource::<SceneParams>().mass;
                game.world()
                    .write_message(Action::Set(Parameter::Mass, 2.0 * mass));
                game.update(2);
                step(&mut game);
            }
            Task::HeldCorner => {
                // By the upper-right corner, then round to the lower left.
                game.press_at(DVec2::new(50.0, 40.0));
                game.update(1);
                game.cursor(Some(world_to_screen(DVec2::new(-90.0, -70.0))));
                game.update(3);
            }
            Task::StepOrder => {
                resume(&mut game);
                game.update(30);
                resume(&mut game);
                game.update(2);
                step(&mut game);
            }
        }
    }
    game.update(600);
    let verdict = card(&mut game, LearnText::Verdict);
    let learning = game.world().resource::<Learning>();
    let why = learning
        .verdict()
        .map(|verdict| format!("{verdict:?}"))
        .unwrap_or_default();
    (learning.done[index], format!("{why} / card: {verdict}"))
}

/// Every chapter's task is a prediction: the right answer passes under the experiment, a wrong
/// answer fails it and the card says what happened, and without the experiment nothing passes.
#[test]
fn each_chapters_prediction_passes_when_right_and_fails_when_wrong() {
    for (index, chapter) in CHAPTERS.iter().enumerate() {
        let right = RIGHT[index];
        let (done, why) = task_done(index, Some(right), false);
        assert!(
            !done,
            "chapter {}: done without the experiment: {why}",
            index + 1
        );
        let (done, why) = task_done(index, Some(right), true);
        assert!(
            done,
            "chapter {}: the right answer not judged right: {why}",
            index + 1
        );
        for wrong in (0..chapter.prediction.choices.len()).filter(|&c| c != right) {
            let (done, why) = task_done(index, Some(wrong), true);
            assert!(!done, "chapter {}: answer {wrong} judged right", index + 1);
            assert!(
                why.contains("outcome: Some"),
                "chapter {}: {why}",
                index + 1
            );
        }
        // With no answer, nothing of the result shows: no choice is named on the card.
        let (done, why) = task_done(index, None, true);
        assert!(!done, "chapter {}: done with no answer chosen", index + 1);
        let shown = why.split(" / card: ").nth(1).unwrap_or_default();
        for choice in chapter.prediction.choices {
            assert!(
                !shown.contains(choice),
                "chapter {}: '{choice}' shown before an answer: {shown}",
                index + 1
            );
        }
    }
}

/// Chapter 6 with either rate at 0: the box released with a spin (c = 0) or a drift (b = 0)
/// keeps moving, however small the motion has become when its energy is a hundredth of its
/// peak; "it keeps moving" is right, "it comes to rest" wrong, and the verdict names the rate.
#[test]
fn damping_with_a_rate_at_zero_keeps_the_box_moving_and_says_which() {
    use rubber_band_box::game::input::controls::Action;
    let index = 5;
    for (parameter, named) in [
        (Parameter::AngularDamping, "with c = 0"),
        (Parameter::LinearDamping, "with b = 0"),
    ] {
        for (answer, right) in [(1, true), (0, false)] {
            let mut game = Game::stepping();
            game.update(2);
            chapter(&mut game, index);
            game.update(250);
            game.world().write_message(Action::Set(parameter, 0.0));
            game.world().trigger(Learn::Predict(answer));
            game.update(1);
            game.world().write_message(Action::TogglePause);
            game.update(1);
            game.press_at(DVec2::new(200.0, 120.0));
            game.update(50);
            game.mouse(ButtonState::Released);
            game.update(600);
            let learning = game.world().resource::<Learning>();
            let verdict = learning.verdict().expect("a verdict");
            assert_eq!(verdict.outcome, Some(1), "{named}: {verdict:?}");
            assert!(verdict.why.contains(named), "{verdict:?}");
            assert_eq!(learning.done[index], right, "{named}, answer {answer}");
        }
    }
}

/// The moment of inertia's chapter takes the size as well as the mass, moved in two goes: a
/// side √2 times as long doubles I, the box drawn and stepped at its new size, and τ_band / I
/// is judged against its value before the first move.
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
    game.update(20);
    game.world().trigger(Learn::Predict(RIGHT[index]));
    game.update(1);
    let step = |game: &mut Game| {
        game.world().write_message(Action::Step);
        game.update(2);
    };
    step(&mut game);
    let side = game.world().resource::<SceneParams>().size.x;
    game.world()
        .write_message(Action::Set(Parameter::Size, 1.2 * side));
    game.update(3);
    step(&mut game);
    assert!(!game.world().resource::<Learning>().done[index]);
    // The band holds its point of the box through the resize: no longer a corner.
    let held = game.bands()[0].ends.local_point;
    assert_eq!(held, DVec2::splat(side / 2.0));
    game.world().write_message(Action::Set(
        Parameter::Size,
        std::f64::consts::SQRT_2 * side,
    ));
    game.update(3);
    step(&mut game);
    assert_eq!(game.bands()[0].ends.local_point, held);
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

/// Leaving learn mode puts back what each plugin kept beside the scene: the dock, the cards,
/// `auto`'s settings, the clock's pace and pause, and the fixed clock's step.
#[test]
fn leaving_learn_mode_puts_back_the_dock_the_cards_and_the_clocks() {
    use rubber_band_box::game::layout::Cards;
    use rubber_band_box::game::shared::DockHidden;
    use rubber_band_box::physics::AutoSettings;
    let mut game = Game::stepping();
    game.update(2);
    game.tap_key(key(Action::ToggleDock));
    game.tap_key(key(Action::Slower));
    game.tap_key(key(Action::FewerSteps));
    game.update(2);
    game.tap_key(key(Action::TogglePause));
    game.update(2);
    game.world().insert_resource(AutoSettings {
        tolerance: 1e-9,
        ..AutoSettings::default()
    });
    let kept = |game: &mut Game| {
        let world = game.world();
        let clock = world.resource::<Time<Virtual>>();
        (
            world.resource::<DockHidden>().0,
            world.resource::<Cards>().clone(),
            *world.resource::<AutoSettings>(),
            (clock.relative_speed_f64(), clock.is_paused()),
            world.resource::<Time<Fixed>>().timestep(),
        )
    };
    let before = kept(&mut game);
    game.tap_key(key(Action::Learn));
    game.update(2);
    game.world().trigger(Learn::Next);
    game.update(5);
    assert_ne!(kept(&mut game), before, "the chapter shows its own");
    game.tap_key(key(Action::Learn));
    game.update(1);
    assert_eq!(chapter_shown(game.world()), None);
    assert_eq!(kept(&mut game), before);
}

#[test]
fn leaving_learn_mode_puts_the_game_back_as_it_was() {
    let mut game = Game::stepping();
    game.update(2);
    // A game of the player's own: other settings, overlays, a pull under way, then let go.
    game.tap_key(key(Action::Stiffer));
    game.tap_key(key(Action::NextIntegrator));
    game.tap_key(key(Action::Toggle(Overlay::Ghosts)));
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
    game.tap_key(key(Action::Learn));
    game.update(2);
    for _ in 0..CHAPTERS.len() {
        game.world().trigger(Learn::Next);
        game.update(20);
    }
    assert_eq!(*game.world().resource::<State<Mode>>().get(), Mode::Learn);
    game.tap_key(key(Action::Learn));
    game.update(1);
    let world = game.world();
    assert_eq!(chapter_shown(world), None);
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

/// Learn mode is the state `Mode::Learn`: whatever sets it (here the state itself, as a plugin
/// of the game might) enters at the chapter asked and saves the game, and whatever leaves it
/// puts the game back. Save and restore live on the state's transitions (each owner's, into and
/// out of learn mode), not in the control.
#[test]
fn the_mode_state_saves_on_enter_and_restores_on_exit_whoever_sets_it() {
    let mut game = Game::stepping();
    game.update(2);
    game.tap_key(key(Action::Stiffer));
    game.tap_key(KeyCode::KeyP);
    game.update(2);
    let settings = |game: &mut Game| {
        let world = game.world();
        (
            *world.resource::<SceneParams>(),
            *world.resource::<Integrator>(),
            *world.resource::<Overlays>(),
            world.resource::<SceneName>().clone(),
        )
    };
    let before = settings(&mut game);
    game.world().resource_mut::<Learning>().chapter = 2;
    game.world()
        .resource_mut::<NextState<Mode>>()
        .set(Mode::Learn);
    game.update(2);
    assert_eq!(chapter_shown(game.world()), Some(2));
    assert_eq!(game.world().resource::<SceneName>().0, CHAPTERS[2].scene);
    assert_ne!(
        settings(&mut game),
        before,
        "the chapter's scene is in place"
    );
    game.world()
        .resource_mut::<NextState<Mode>>()
        .set(Mode::Play);
    game.update(1);
    assert_eq!(chapter_shown(game.world()), None);
    assert_eq!(settings(&mut game), before);
    // The control enters at the first chapter and leaves the same way.
    game.tap_key(key(Action::Learn));
    game.update(1);
    assert_eq!(chapter_shown(game.world()), Some(0));
    game.tap_key(key(Action::Learn));
    game.update(1);
    assert_eq!(settings(&mut game), before);
}

// --- Each chapter's claims, as physics: one test a claim, on the chapter's own scene. ---

/// The body's state now.
fn body_state(game: &mut Game) -> BodyState {
    the_box(game).0
}

/// Chapter 1: "A force whose line passes through the centre of mass moves the box as if all
/// its mass sat there: F = m a, and the box does not turn." The diagonal scene's band pulls
/// through the centre: the box moves, and its orientation and spin stay exactly zero.
#[test]
fn claim_1_a_force_through_the_centre_moves_the_box_without_turning_it() {
    let mut game = Game::stepping();
    run_chapter(&mut game, 0);
    let start = body_state(&mut game);
    for _ in 0..150 {
        game.update(1);
        let now = body_state(&mut game);
        assert_eq!(now.angular.orientation, 0.0);
        assert_eq!(now.angular.angular_velocity, 0.0);
    }
    let moved = body_state(&mut game).linear.position - start.linear.position;
    assert!(moved.length() > 40.0, "moved {moved}");
    // Along the line of the force: the diagonal.
    assert!((moved.x - moved.y).abs() < 1e-9 * moved.length(), "{moved}");
}

/// Chapter 2: "Nothing pulls this box: it only spins, and angular damping takes ω down at
/// the rate c." On the spin scene the centre stays put and ω falls as ω₀ e^(−c t).
#[test]
fn claim_2_an_unpulled_box_only_spins_and_omega_falls_at_the_rate_c() {
    let mut game = Game::stepping();
    run_chapter(&mut game, 1);
    let c = game.world().resource::<SceneParams>().angular_damping;
    let start = body_state(&mut game);
    let t0 = game.world().resource::<Time<Fixed>>().elapsed_secs_f64();
    game.update(100);
    let now = body_state(&mut game);
    let t = game.world().resource::<Time<Fixed>>().elapsed_secs_f64() - t0;
    assert!(game.bands().is_empty());
    assert_eq!(now.linear.position, start.linear.position);
    let expected = start.angular.angular_velocity * (-c * t).exp();
    let omega = now.angular.angular_velocity;
    assert!(
        (omega - expected).abs() < 1e-9 * expected.abs(),
        "ω {omega}, ω₀ e^(−c t) {expected} after {t} s"
    );
    assert!(omega.abs() < start.angular.angular_velocity.abs());
}

/// Chapter 3: "τ = r × F = r_x F_y − r_y F_x ... it sets how ω changes" and "a point of the
/// box moves at v + ω r⊥". Stepped by every integrator, not read from the card: boxes that
/// are not square, turned (θ ≠ 0) and moving, pulled at points off their corners, change ω
/// over a short step by τ dt / I, τ written out here from the components (so a torque with
/// its components swapped, a rotation the wrong way or I of a square fails), and the band's
/// point moves at v + ω r⊥.
#[test]
fn claim_3_a_force_at_a_point_changes_omega_by_r_cross_f_over_i() {
    use rubber_band_box::physics::Stepper;
    let cases = [
        (
            DVec2::new(80.0, 30.0),
            0.7,
            DVec2::new(40.0, -15.0),
            DVec2::new(200.0, 90.0),
        ),
        (
            DVec2::new(20.0, 90.0),
            -2.1,
            DVec2::new(-10.0, 45.0),
            DVec2::new(-150.0, 60.0),
        ),
        (
            DVec2::new(50.0, 120.0),
            2.9,
            DVec2::new(25.0, 10.0),
            DVec2::new(30.0, -200.0),
        ),
    ];
    let dt = 1e-6;
    for integrator in Integrator::ALL {
        for (size, theta, local, anchor) in cases {
            let params = SceneParams {
                size,
                linear_damping: 0.0,
                angular_damping: 0.0,
                ..SceneParams::tutorial()
            };
            let state = BodyState {
                linear: LinearState {
                    position: DVec2::new(5.0, -3.0),
                    velocity: DVec2::new(12.0, 7.0),
                },
                angular: AngularState {
                    orientation: theta,
                    angular_velocity: 0.8,
                },
            };
            // Written out: r turned by θ counter-clockwise, F = −k (p − q), τ = r_x F_y − r_y F_x.
            let (sin, cos) = theta.sin_cos();
            let r = DVec2::new(cos * local.x - sin * local.y, sin * local.x + cos * local.y);
            let p = state.linear.position + r;
            let force = -params.stiffness * (p - anchor);
            let torque = r.x * force.y - r.y * force.x;
            let inertia = params.mass * (size.x * size.x + size.y * size.y) / 12.0;
            let band = BandEnds {
                local_point: local,
                anchor,
            };
            let mut stepper = Stepper {
                state,
                band: Some(band),
                integrator,
                ..Stepper::new(params).expect("a valid box")
            };
            stepper.step(dt);
            let after = stepper.state;
            let alpha = (after.angular.angular_velocity - 0.8) / dt;
            assert!(
                (alpha - torque / inertia).abs() < 1e-3 * (torque / inertia).abs(),
                "{integrator} {size}: α {alpha}, τ / I {}",
                torque / inertia
            );
            // v + ω r⊥, r⊥ = (−r_y, r_x): the point's move over the step.
            let moved = (band.attachment(&after) - p) / dt;
            let expected = state.linear.velocity + 0.8 * DVec2::new(-r.y, r.x);
            assert!(
                moved.distance(expected) < 1e-3 * expected.length(),
                "{integrator} {size}: the point moved at {moved}, v + ω r⊥ {expected}"
            );
        }
    }
}

/// Chapter 3: "the same force at its centre, with the same damping, moves the twin's centre
/// as the box's": the tutorial's "the linear response is the same as if the force acted on
/// the centre of mass". On the chapter's scene and pull, a twin stepped on its own, pushed at
/// its centre by the box's band force of each step, stays on the box's path to 1e-9 px and
/// never turns, with each integrator that takes the forces once a step. A twin held by the
/// same band at its centre (what the chapter once said) leaves the path by pixels.
#[test]
fn claim_3_the_box_force_at_the_centre_moves_the_twin_as_the_box() {
    use rubber_band_box::physics::{Forces, Wrench};
    use rubber_band_box::physics::{Run, Scene};
    let scene = Scene::named(CHAPTERS[2].scene).unwrap();
    let dt = scene.params.dt();
    for integrator in [Integrator::Seed, Integrator::Symplectic, Integrator::Euler] {
        let mut run = Run::of(&scene, integrator, dt).unwrap();
        let mut twin = run.stepper.state;
        twin.linear.position += TWIN_OFFSET;
        let unbanded = scene.params.force_model(run.stepper.mass, None);
        let mut same_band = twin;
        let mut strayed = 0.0f64;
        let mut turned = 0.0f64;
        for _ in 0..(4.0 / dt) as usize {
            let model = run.stepper.model();
            let pull = model.applied(&run.stepper.state).force;
            let push = Forces {
                applied: Wrench::at_arm(pull, DVec2::ZERO),
                damping: unbanded.damping(&twin),
            };
            integrator.step(&mut twin, &unbanded, push, dt);
            // The old twin: a band from its centre to the box's anchor moved by the offset.
            let held = run.stepper.band.map(|band| BandEnds {
                local_point: DVec2::ZERO,
                anchor: band.anchor + TWIN_OFFSET,
            });
            let held = scene.params.force_model(run.stepper.mass, held);
            let start = held.forces(&same_band);
            integrator.step(&mut same_band, &held, start, dt);
            run.advance().unwrap();
            let path = run.stepper.state.linear.position + TWIN_OFFSET;
            assert!(
                twin.linear.position.distance(path) < 1e-9,
                "{integrator} at {} s: twin {} from the box's centre by the offset {}",
                run.time(),
                twin.linear.position,
                path
            );
            assert_eq!(twin.angular, scene.initial.angular, "the twin turned");
            turned = turned.max(run.stepper.state.angular.orientation.abs());
            strayed = strayed.max(same_band.linear.position.distance(path));
        }
        assert!(
            turned > 0.5,
            "{integrator}: the box turned {turned} rad at most"
        );
        assert!(
            strayed > 5.0,
            "{integrator}: the same band's twin strayed {strayed} px"
        );
    }
}

/// Chapter 3's twin, for every integrator, `auto` included: a body of its own, stepped by the
/// same integrator, pushed at its centre by the box's band force (held over each step: a band
/// at its centre so soft, k = 1e-6, and so long that it pulls F the whole step), with the same
/// damping. Its centre follows the box's by the offset, more closely as the step shrinks: at
/// 1 ms at least five times closer than at 10 ms, or within 1e-9 px at both (the integrators
/// that take the forces once a step), and it never turns.
#[test]
fn claim_3_the_twin_stepped_on_its_own_follows_the_box_for_every_integrator() {
    use rubber_band_box::physics::ForceModel;
    use rubber_band_box::physics::{Run, Scene};
    let scene = Scene::named(CHAPTERS[2].scene).unwrap();
    const SOFT: f64 = 1e-6;
    let strayed = |integrator: Integrator, dt: f64| {
        let mut run = Run::of(&scene, integrator, dt).unwrap();
        let mut twin = run.stepper.state;
        twin.linear.position += TWIN_OFFSET;
        let mut strayed = 0.0f64;
        for _ in 0..(4.0 / dt).round() as usize {
            let box_model = run.stepper.model();
            let pull = box_model.applied(&run.stepper.state).force;
            let model = ForceModel {
                band: Some(BandEnds {
                    local_point: DVec2::ZERO,
                    anchor: twin.linear.position + pull / SOFT,
                }),
                stiffness: SOFT,
                ..scene.params.force_model(run.stepper.mass, None)
            };
            let start = model.forces(&twin);
            integrator.step(&mut twin, &model, start, dt);
            run.advance().unwrap();
            let path = run.stepper.state.linear.position + TWIN_OFFSET;
            strayed = strayed.max(twin.linear.position.distance(path));
            assert_eq!(
                twin.angular, scene.initial.angular,
                "{integrator}: the twin turned"
            );
        }
        strayed
    };
    for integrator in Integrator::ALL {
        let coarse = strayed(integrator, 0.01);
        let fine = strayed(integrator, 0.001);
        assert!(
            (coarse < 1e-9 && fine < 1e-9) || fine < coarse / 5.0,
            "{integrator}: the twin strayed {coarse} px at 10 ms, {fine} px at 1 ms"
        );
        eprintln!("{integrator}: {coarse:e} px at 10 ms, {fine:e} px at 1 ms");
    }
}

/// Chapter 4: "α = Στ / I ... the band holds the same point of the box when the mass or the
/// size changes". Stepped, not computed: the same band on a box at rest, undamped, for ten
/// steps of 0.1 ms, changes ω at half the rate when I is doubled by the mass and, in another
/// run, by the size, every integrator; the band's torque at the start is the same to the bit.
#[test]
fn claim_4_twice_the_inertia_halves_the_change_of_omega_for_the_same_torque() {
    use rubber_band_box::physics::{AutoSettings, Stepper};
    let base = SceneParams {
        linear_damping: 0.0,
        angular_damping: 0.0,
        ..SceneParams::tutorial()
    };
    let band = BandEnds {
        local_point: DVec2::new(30.0, 30.0),
        anchor: DVec2::new(200.0, -100.0),
    };
    let dt = 1e-4;
    for integrator in Integrator::ALL {
        let rate = |params: SceneParams| {
            let mass = params.mass_properties().unwrap();
            let state = BodyState::default();
            let mut stepper = Stepper {
                params,
                mass,
                state,
                band: Some(band),
                integrator,
                auto: AutoSettings::default(),
            };
            for _ in 0..10 {
                stepper.step(dt);
            }
            let torque = band.wrench(&state, params.stiffness).torque;
            (
                torque,
                mass.inertia(),
                stepper.state.angular.angular_velocity / (10.0 * dt),
            )
        };
        let (torque, inertia, alpha) = rate(base);
        assert!(torque.abs() > 1000.0, "the band's torque {torque}");
        for doubled in [
            SceneParams {
                mass: 2.0 * base.mass,
                ..base
            },
            SceneParams {
                size: std::f64::consts::SQRT_2 * base.size,
                ..base
            },
        ] {
            let (same, twice, half) = rate(doubled);
            assert_eq!(same, torque, "{integrator}: the band's torque is the same");
            assert!(
                (twice / inertia - 2.0).abs() < 1e-12,
                "{integrator}: I {twice}"
            );
            let ratio = half / alpha;
            assert!(
                (ratio - 0.5).abs() < 1e-3,
                "{integrator}: Δω / Δt × {ratio} with I doubled"
            );
        }
    }
}

/// Chapter 4: "A larger box grabbed afresh at its corner is held further from its centre, so
/// the same stretch gives it more torque". The same press on a box √2 times as large takes a
/// corner √2 times as far: more than 1.3 times the torque, so α is more than half.
#[test]
fn claim_4_a_larger_box_grabbed_at_its_corner_gets_more_torque() {
    let params = SceneParams::tutorial();
    let state = BodyState::default();
    let torque = |params: &SceneParams| {
        let mass = params.mass_properties().unwrap();
        let band = BandEnds::grabbing(&mass, &state, DVec2::new(300.0, -100.0));
        (band.wrench(&state, params.stiffness).torque, mass.inertia())
    };
    let (base, inertia) = torque(&params);
    let (large, larger) = torque(&SceneParams {
        size: params.size * std::f64::consts::SQRT_2,
        ..params
    });
    assert!(large > 1.3 * base, "{large} against {base}");
    assert!((larger / inertia - 2.0).abs() < 1e-12);
    assert!(
        (large / larger) / (base / inertia) > 0.6,
        "more than half the α"
    );
}

/// Chapter 4: "While I stays, the angular momentum L = I ω changes at the rate of the torque,
/// τ = dL/dt". On the undamped scene's held pull, stepped by `auto` at the chapter's 100 Hz:
/// over each step of the first 3 s, ΔL / dt equals the mean of Στ at the step's two ends to
/// within 1e-3 of the torque's scale (the trapezoid's error over a step), and the card's line
/// shows both.
#[test]
fn claim_4_the_torque_is_the_rate_of_change_of_the_angular_momentum() {
    use rubber_band_box::physics::{Run, Scene};
    let scene = Scene::named(CHAPTERS[3].scene).unwrap();
    let dt = scene.params.dt();
    let mut run = Run::of(&scene, Integrator::Auto, dt).unwrap();
    let inertia = run.stepper.mass.inertia();
    let torque = |run: &Run| {
        run.stepper
            .model()
            .forces(&run.stepper.state)
            .total()
            .torque
    };
    let mut scale = 0.0f64;
    let mut worst = 0.0f64;
    for _ in 0..(3.0 / dt) as usize {
        let (before, omega) = (torque(&run), run.stepper.state.angular.angular_velocity);
        run.advance().unwrap();
        let after = torque(&run);
        let rate = inertia * (run.stepper.state.angular.angular_velocity - omega) / dt;
        scale = scale.max(before.abs());
        worst = worst.max((rate - 0.5 * (before + after)).abs());
    }
    assert!(scale > 1e4, "the pull's torque {scale}");
    assert!(
        worst < 1e-3 * scale,
        "ΔL / dt off the mean Στ by {worst} of {scale}"
    );
    let mut game = Game::stepping();
    chapter(&mut game, 3);
    game.update(20);
    let shown = equations(&mut game);
    assert!(shown.contains("over the next step ΔL / dt = "), "{shown}");
}

/// Chapter 5: "a spring of zero rest length from the pointer q to a corner p: its force is
/// F = −k (p − q) ... The corner is the one nearest the pointer when pressed". A press by each
/// of the four corners takes that corner, each a different one.
#[test]
fn claim_5_the_band_takes_the_nearest_corner_and_pulls_k_times_the_stretch_toward_the_pointer() {
    let mut corners_taken = Vec::new();
    // A press by each of the four corners, each a fresh chapter.
    for pointer in [
        DVec2::new(-150.0, 80.0),
        DVec2::new(150.0, 80.0),
        DVec2::new(150.0, -80.0),
        DVec2::new(-150.0, -80.0),
    ] {
        let mut game = Game::stepping();
        chapter(&mut game, 4);
        let k = game.world().resource::<SceneParams>().stiffness;
        game.press_at(pointer);
        game.update(1);
        let (state, mass, band) = the_box(&mut game);
        let band = band.expect("the press holds a band");
        let corner = band.attachment(&state);
        for other in mass.corners() {
            assert!(
                corner.distance(band.anchor)
                    <= state.local_to_world(other).distance(band.anchor) + 1e-9,
                "pressed at {pointer}: {corner} is not the nearest corner"
            );
        }
        corners_taken.push(band.local_point);
        let force = band.wrench(&state, k).force;
        let stretch = band.anchor - corner;
        assert!((force - k * stretch).length() < 1e-9 * force.length());
        // Zero rest length: no stretch, no force.
        let mut slack = band;
        slack.anchor = corner;
        assert_eq!(slack.wrench(&state, k).force, DVec2::ZERO);
    }
    corners_taken.dedup();
    assert_eq!(corners_taken.len(), 4, "{corners_taken:?}");
}

/// Chapter 6: "With b > 0, c > 0 and no band the box comes to rest; with c = 0 a spin never
/// stops, with b = 0 a drift never does." Stepped with every integrator from a box moving
/// and turning, no band: over a sweep of b > 0 and c > 0 the kinetic energy never rises and
/// falls under a millionth (in 1.2 times the time the slower rate takes); with c = 0, ω keeps its value; with b = 0, v keeps its.
#[test]
fn claim_6_damping_brings_the_box_to_rest_only_when_both_rates_are_positive() {
    use rubber_band_box::physics::{AutoSettings, Stepper, kinetic_energy};
    let start = BodyState {
        linear: LinearState {
            position: DVec2::ZERO,
            velocity: DVec2::new(120.0, -45.0),
        },
        angular: AngularState {
            orientation: 0.3,
            angular_velocity: 4.0,
        },
    };
    let tutorial = SceneParams::tutorial();
    let run = |integrator: Integrator, b: f64, c: f64, seconds: f64| {
        let params = SceneParams {
            linear_damping: b,
            angular_damping: c,
            ..tutorial
        };
        let mass = params.mass_properties().unwrap();
        let mut stepper = Stepper {
            params,
            mass,
            state: start,
            band: None,
            integrator,
            auto: AutoSettings::default(),
        };
        let mut energies = vec![kinetic_energy(&start, &mass)];
        for _ in 0..(seconds / params.dt()) as usize {
            stepper.step(params.dt());
            energies.push(kinetic_energy(&stepper.state, &mass));
        }
        (stepper.state, energies)
    };
    for integrator in Integrator::ALL {
        for b in [0.5, 5.0, 20.0] {
            for c in [0.5, tutorial.angular_damping, 10.0] {
                // Long enough for the slower rate, 2b / m or 2c, to take it down 1e6 times.
                let rate = (2.0 * b / tutorial.mass).min(2.0 * c);
                let (_, energies) = run(integrator, b, c, 1.2 * 1e6f64.ln() / rate);
                let first = energies[0];
                assert!(
                    energies.windows(2).all(|w| w[1] <= w[0] * (1.0 + 1e-12)),
                    "{integrator} b {b} c {c}: the energy rose"
                );
                let last = *energies.last().unwrap();
                assert!(
                    last < 1e-6 * first,
                    "{integrator} b {b} c {c}: {last} of {first}"
                );
            }
        }
        let (state, _) = run(integrator, 5.0, 0.0, 10.0);
        let omega = state.angular.angular_velocity;
        let kept = start.angular.angular_velocity;
        assert!(
            (omega - kept).abs() < 1e-9 * kept,
            "{integrator}: with c = 0 the spin goes on: {omega}"
        );
        let (state, _) = run(integrator, 0.0, 2.0, 10.0);
        let velocity = state.linear.velocity;
        let kept = start.linear.velocity;
        assert!(
            velocity.distance(kept) < 1e-9 * kept.length(),
            "{integrator}: with b = 0 the drift goes on: {velocity}"
        );
    }
}

/// Chapter 6: "E differs from [the books] only by the integrator's error, the last line." For
/// every integrator, the chapter's pull and release in a game: the card's last line is E after
/// the step minus the books, named for the integrator, and for the default (`auto`) it is
/// under a millionth of the energy that passed through.
#[test]
fn claim_6_the_books_leave_e_up_to_the_error_the_card_shows() {
    use rubber_band_box::game::input::controls::Action;
    for integrator in Integrator::ALL {
        let mut game = Game::stepping();
        run_chapter(&mut game, 5);
        game.world().write_message(Action::Integrator(integrator));
        game.update(1);
        game.press_at(DVec2::new(220.0, 160.0));
        game.update(80);
        game.mouse(ButtonState::Released);
        game.update(120);
        let books = *game.world().resource::<EnergyBooks>();
        // E from the box itself, written out (the band let go): ½ m |v|² + ½ I ω².
        let (state, mass, band) = the_box(&mut game);
        assert!(band.is_none());
        let size = mass.size();
        let inertia = mass.mass() * (size.x * size.x + size.y * size.y) / 12.0;
        let omega = state.angular.angular_velocity;
        let e = 0.5 * mass.mass() * state.linear.velocity.length_squared()
            + 0.5 * inertia * omega * omega;
        let residual = e - books.ledger.expected();
        let shown = equations(&mut game);
        let line = format!(
            "E after the step − books = {}: the error of {}",
            n(residual),
            integrator.name()
        );
        assert!(shown.contains(&line), "{line} not in\n{shown}");
        if integrator == Integrator::Auto {
            let scale = books.ledger.throughput();
            assert!(
                residual.abs() < 1e-6 * scale,
                "auto: {residual} against {scale}"
            );
        }
    }
}

/// Chapter 7: "That order (semi-implicit Euler) keeps the energy's error bounded; explicit
/// Euler ... gains energy step after step." On the undamped scene (band held, b = c = 0, so
/// E is constant), 60 s at the tutorial's 100 Hz: the seed's books stay within 3 % of the
/// energy that passed through and no further off in the last 30 s than in the first, explicit
/// Euler's error grows every second and ends above the seed's worst.
#[test]
fn claim_7_the_tutorials_order_keeps_the_energy_bounded_and_explicit_euler_gains_it() {
    use rubber_band_box::physics::{Run, Scene};
    let scene = Scene::named("undamped").unwrap();
    let dt = scene.params.dt();
    let errors = |integrator: Integrator| {
        let mut run = Run::of(&scene, integrator, dt).unwrap();
        let mut errors = Vec::new();
        for _ in 0..(60.0 / dt) as usize {
            run.advance().unwrap();
            errors.push(run.books.residual() / run.books.ledger.throughput());
        }
        errors
    };
    let seed = errors(Integrator::Seed);
    let worst = |errors: &[f64]| errors.iter().fold(0.0f64, |worst, e| worst.max(e.abs()));
    let (early, late) = seed.split_at(seed.len() / 2);
    assert!(
        worst(&seed) < 0.03,
        "the seed's error reached {}",
        worst(&seed)
    );
    assert!(
        worst(late) <= 1.05 * worst(early),
        "the seed's error grew: {} in the first 30 s, {} in the last",
        worst(early),
        worst(late)
    );
    let euler = errors(Integrator::Euler);
    let second = (1.0 / dt) as usize;
    let by_second: Vec<f64> = euler.iter().step_by(second).copied().collect();
    assert!(
        by_second.windows(2).all(|w| w[1] > w[0]),
        "explicit Euler's error, second by second: {by_second:?}"
    );
    assert!(*euler.last().unwrap() > worst(&seed), "{:?}", euler.last());
}

/// Chapter 7: "The tutorial's own loop, run here by the seed integrator, its lines the seed's
/// numbers for the next step: the angular damping first scales ω by e^(−c dt), 0.98 a step
/// at 100 Hz ...". The card's lines are written from the seed's stages for the next step, and
/// the step the game then takes with the seed ends, to the bit, where the card's last two lines
/// say.
#[test]
fn claim_7_the_update_loops_lines_are_the_seed_integrators_next_step_to_the_bit() {
    use rubber_band_box::game::learn::equations::Quantities;
    let mut game = Game::stepping();
    run_chapter(&mut game, 6);
    assert_eq!(*game.world().resource::<Integrator>(), Integrator::Seed);
    game.press_at(DVec2::new(200.0, 120.0));
    game.update(30);
    for _ in 0..5 {
        let (state, mass, band) = the_box(&mut game);
        let params = *game.world().resource::<SceneParams>();
        let ledger = game.world().resource::<EnergyBooks>().ledger;
        let q = Quantities::of(state, &mass, &params, band, ledger);
        assert!((q.seed.damping_factor - 0.98).abs() < 1e-15);
        let lines = equations(&mut game);
        let after = q.seed.after;
        for shown in [
            n(q.seed.damped_angular_velocity),
            v(q.seed.acceleration),
            n(q.seed.angular_acceleration),
            n(after.angular.angular_velocity),
            n(after.angular.orientation),
            v(after.linear.velocity),
            v(after.linear.position),
        ] {
            assert!(lines.contains(&shown), "{shown} not in\n{lines}");
        }
        game.update(1);
        let stepped = body_state(&mut game);
        assert_eq!(
            stepped.to_array().map(f64::to_bits),
            after.to_array().map(f64::to_bits)
        );
        // The tutorial's loop written out here, in its order: damping scales ω; a and α from
        // the forces; ω, then θ with the new ω; v, then x with the new v.
        let band = band.expect("the band holds");
        let dt = params.dt();
        let (x, vel) = (state.linear.position, state.linear.velocity);
        let (theta, omega) = (state.angular.orientation, state.angular.angular_velocity);
        let (sin, cos) = theta.sin_cos();
        let local = band.local_point;
        let r = DVec2::new(cos * local.x - sin * local.y, sin * local.x + cos * local.y);
        let force = -params.stiffness * (x + r - band.anchor);
        let a = (force - params.linear_damping * vel) / params.mass;
        let size = mass.size();
        let inertia = params.mass * (size.x * size.x + size.y * size.y) / 12.0;
        let alpha = (r.x * force.y - r.y * force.x) / inertia;
        let omega = (-params.angular_damping * dt).exp() * omega + alpha * dt;
        let vel = vel + a * dt;
        let by_hand = [
            x.x + vel.x * dt,
            x.y + vel.y * dt,
            vel.x,
            vel.y,
            theta + omega * dt,
            omega,
        ];
        let stepped = [
            stepped.linear.position.x,
            stepped.linear.position.y,
            stepped.linear.velocity.x,
            stepped.linear.velocity.y,
            stepped.angular.orientation,
            stepped.angular.angular_velocity,
        ];
        for (got, want) in stepped.into_iter().zip(by_hand) {
            assert!(
                (got - want).abs() <= 1e-9 * want.abs().max(1.0),
                "{stepped:?} {by_hand:?}"
            );
        }
    }
}

/// Learn mode's numbers keep three significant digits in powers of ten (τ and L reach 1e4 and
/// more), so that ΔL/dt = Στ can be checked from the card to a part in a thousand, not ten.
#[test]
fn learn_numbers_keep_three_digits_beyond_the_usual_range() {
    assert_eq!(precise(12_345.0), "1.23e4");
    assert_eq!(readable(12_345.0), "1.2e4");
    assert_eq!(precise(-0.001_234), "-1.23e-3");
    // In the usual range both write the same.
    for value in [0.0, 20.0, 2.0203, -0.05, 9999.0] {
        assert_eq!(precise(value), readable(value), "{value}");
    }
    assert_eq!(n(-12_345.0), "−1.23e4");
}

/// A retry is allowed and says it is one; the first answer is kept beside it, across a restart.
#[test]
fn a_retry_keeps_the_first_answer_beside_it() {
    let mut game = Game::stepping();
    game.update(2);
    chapter(&mut game, 0);
    game.world().trigger(Learn::Predict(0));
    game.world().write_message(Action::TogglePause);
    game.update(120);
    let verdict = card(&mut game, LearnText::Verdict);
    assert!(verdict.starts_with("✕"), "{verdict}");
    game.world().trigger(Learn::Predict(1));
    game.world().write_message(Action::RestartChapter);
    game.update(2);
    assert!(game.world().resource::<Time<Virtual>>().is_paused());
    assert_eq!(game.world().resource::<Learning>().predicted(), Some(1));
    game.world().write_message(Action::TogglePause);
    game.update(120);
    let verdict = card(&mut game, LearnText::Verdict);
    assert!(
        verdict.contains("● Right (a retry: your first answer, it turns, was wrong)"),
        "{verdict}"
    );
    assert_eq!(
        game.world().resource::<Learning>().first_answer(),
        Some((0, false))
    );
}

/// While a chapter's question has no answer, nothing moves: a resume is taken back before any
/// step, and the status line says why.
#[test]
fn a_chapter_waits_paused_for_its_answer() {
    use rubber_band_box::game::simulation::StepCount;
    let mut game = Game::stepping();
    game.update(2);
    chapter(&mut game, 2);
    let steps = game.world().resource::<StepCount>().0;
    let start = body_state(&mut game);
    game.world().write_message(Action::TogglePause);
    game.update(60);
    assert_eq!(game.world().resource::<StepCount>().0, steps);
    assert_eq!(body_state(&mut game), start);
    let status = game.status();
    assert!(status.contains("choose an answer first"), "{status}");
}

/// Chapter 7's verdict: "This order follows the band only while ω dt < 2, ω = √(k (1/m +
/// |r|²/I)) ... and while b dt / m < 2: past either, its step gains energy the physics does not
/// have." The seed on the chapter's pull, at each end of the mass, size, damping and k sliders
/// (one at a time), and a box shrunk from 60 to 1 px under a held band: where both numbers are
/// well under 2 the energy never passes twice its start in 20 s; where one is well over, it
/// passes a hundred times its start, which damping and a still pointer never allow.
#[test]
fn claim_7_the_seed_blows_up_where_the_verdicts_limits_say() {
    use rubber_band_box::physics::Stepper;
    use rubber_band_box::physics::scene::{
        ANGULAR_DAMPING_RANGE, LINEAR_DAMPING_RANGE, MASS_RANGE, SIZE_RANGE, STIFFNESS_RANGE,
    };
    let base = SceneParams::tutorial();
    let corner = |params: &SceneParams| params.size / 2.0;
    let mut cases: Vec<(SceneParams, DVec2)> = Vec::new();
    for (low, high, set) in [
        (MASS_RANGE.low, MASS_RANGE.high, 0),
        (SIZE_RANGE.low, SIZE_RANGE.high, 1),
        (LINEAR_DAMPING_RANGE.low, LINEAR_DAMPING_RANGE.high, 2),
        (ANGULAR_DAMPING_RANGE.low, ANGULAR_DAMPING_RANGE.high, 3),
        (STIFFNESS_RANGE.low, STIFFNESS_RANGE.high, 4),
    ] {
        for value in [low, high] {
            let mut params = base;
            match set {
                0 => params.mass = value,
                1 => params.size = DVec2::splat(value),
                2 => params.linear_damping = value,
                3 => params.angular_damping = value,
                _ => params.stiffness = value,
            }
            cases.push((params, corner(&params)));
        }
    }
    // Shrunk from 60 px to 1 px under a held band at k = 40: the band's point stays 42 px out.
    for side in [60.0, 1.0] {
        let params = SceneParams {
            stiffness: 40.0,
            size: DVec2::splat(side),
            ..base
        };
        cases.push((params, DVec2::splat(30.0)));
    }
    let (mut stable, mut unstable) = (0, 0);
    for (params, local) in cases {
        let mass = params.mass_properties().unwrap();
        let band = BandEnds {
            local_point: local,
            anchor: DVec2::new(200.0, 120.0),
        };
        let dt = params.dt();
        let omega_dt = params.force_model(mass, Some(band)).band_rate() * dt;
        let decay = params.linear_damping * dt / params.mass;
        let mut stepper = Stepper {
            band: Some(band),
            integrator: Integrator::Seed,
            ..Stepper::new(params).expect("a valid box")
        };
        // With b, c ≥ 0 and the pointer still, E can only fall from the band's energy at the
        // start: the seed's error aside, a run that goes far above it has blown up.
        let start = stepper.energy();
        let mut most = start;
        for _ in 0..2000 {
            stepper.step(dt);
            let energy = stepper.energy();
            most = if energy.is_finite() {
                most.max(energy)
            } else {
                f64::INFINITY
            };
            if most > 1e2 * start {
                break;
            }
        }
        let left = most > 1e2 * start;
        let size = params.size;
        if omega_dt < 1.5 && decay < 1.5 {
            assert!(
                most <= 2.0 * start,
                "{size} m {} k {}: ω dt {omega_dt}, b dt / m {decay}",
                params.mass,
                params.stiffness
            );
            stable += 1;
        } else if omega_dt > 2.5 || decay > 2.5 {
            assert!(
                left,
                "{size} m {} k {}: ω dt {omega_dt}, b dt / m {decay}",
                params.mass, params.stiffness
            );
            unstable += 1;
        }
    }
    assert!(
        stable >= 6 && unstable >= 3,
        "{stable} stable, {unstable} unstable"
    );
}

/// Each chapter's text on screen is short: at most about 60 words (the derivations are
/// docs/learn.md's).
#[test]
fn every_chapters_text_is_at_most_about_sixty_words() {
    for (index, chapter) in CHAPTERS.iter().enumerate() {
        let words = chapter.text.split_whitespace().count();
        assert!(words <= 65, "chapter {}: {words} words", index + 1);
    }
}

/// The slider ends, one slider at a time, as the panel sets them.
fn slider_ends() -> Vec<(Parameter, f64)> {
    use rubber_band_box::physics::scene::{
        ANGULAR_DAMPING_RANGE, LINEAR_DAMPING_RANGE, MASS_RANGE, SIZE_RANGE, STIFFNESS_RANGE,
    };
    [
        (Parameter::Mass, MASS_RANGE),
        (Parameter::Size, SIZE_RANGE),
        (Parameter::LinearDamping, LINEAR_DAMPING_RANGE),
        (Parameter::AngularDamping, ANGULAR_DAMPING_RANGE),
        (Parameter::Stiffness, STIFFNESS_RANGE),
    ]
    .into_iter()
    .flat_map(|(parameter, range)| [(parameter, range.low), (parameter, range.high)])
    .collect()
}

/// Chapter 1's verdict at every slider's ends and with every integrator: where it says what
/// happened, it says the box did not turn (the scene's pull passes through the centre to the
/// bit), and a box that is not square is told its pull misses the centre.
#[test]
fn chapter_1s_verdict_holds_at_every_sliders_ends_with_every_integrator() {
    for integrator in Integrator::ALL {
        for (parameter, value) in slider_ends() {
            let mut game = Game::stepping();
            game.update(2);
            chapter(&mut game, 0);
            game.world().write_message(Action::Integrator(integrator));
            game.world().write_message(Action::Set(parameter, value));
            game.update(1);
            game.world().trigger(Learn::Predict(RIGHT[0]));
            game.world().write_message(Action::TogglePause);
            game.update(200);
            let learning = game.world().resource::<Learning>();
            if let Some(verdict) = learning.verdict() {
                assert_ne!(
                    verdict.outcome,
                    Some(0),
                    "{integrator}, {parameter:?} = {value}: {verdict:?}"
                );
                if verdict.outcome == Some(1) {
                    assert!(verdict.why.contains("θ changed by 0 rad"), "{verdict:?}");
                }
            }
        }
    }
}

/// Chapter 7's verdict with every integrator, at the chapter's settings and at every slider's
/// ends: x moves with the v after the step for the tutorial's order (seed, symplectic) and for
/// implicit Euler, with the v before it for explicit Euler, and by neither for the others,
/// which the card names rather than judges; never the wrong one. Only the seed's verdict gives
/// the seed's stability limits.
#[test]
fn chapter_7s_verdict_names_each_integrators_own_order() {
    let order = |integrator: Integrator| match integrator {
        // Backward Euler too: v from the forces at the step's end, then x with it.
        Integrator::Seed | Integrator::Symplectic | Integrator::Implicit => Some(1),
        Integrator::Euler => Some(0),
        _ => None,
    };
    let mut ends: Vec<Option<(Parameter, f64)>> = vec![None];
    ends.extend(slider_ends().into_iter().map(Some));
    for integrator in Integrator::ALL {
        for end in &ends {
            let mut game = Game::stepping();
            game.update(2);
            chapter(&mut game, 6);
            game.world().write_message(Action::Integrator(integrator));
            if let Some((parameter, value)) = end {
                game.world().write_message(Action::Set(*parameter, *value));
            }
            game.update(1);
            game.world().trigger(Learn::Predict(1));
            game.world().write_message(Action::TogglePause);
            game.update(20);
            game.world().write_message(Action::TogglePause);
            game.update(2);
            game.world().write_message(Action::Step);
            game.update(2);
            let learning = game.world().resource::<Learning>();
            let Some(verdict) = learning.verdict() else {
                continue;
            };
            // `auto` past its substeps' budget falls back to implicit Euler for the step.
            let fallen_back = integrator == Integrator::Auto && verdict.outcome == Some(1);
            if let Some(outcome) = verdict.outcome
                && !fallen_back
            {
                assert_eq!(
                    Some(outcome),
                    order(integrator),
                    "{integrator}, {end:?}: {verdict:?}"
                );
            }
            if end.is_none() {
                assert_eq!(
                    verdict.outcome,
                    order(integrator),
                    "{integrator}: {verdict:?}"
                );
            }
        }
    }
}

/// Single steps taken before the answer play the experiment, but it is judged by no answer:
/// an answer chosen after seeing it is not marked right, the card names no choice, and the
/// status line asks for a restart.
#[test]
fn an_experiment_seen_before_the_answer_is_not_judged_by_it() {
    let mut game = Game::stepping();
    game.update(2);
    chapter(&mut game, 0);
    for _ in 0..40 {
        game.world().write_message(Action::Step);
        game.update(1);
    }
    game.world().trigger(Learn::Predict(RIGHT[0]));
    game.world().write_message(Action::TogglePause);
    game.update(200);
    assert!(!game.world().resource::<Learning>().done[0]);
    // Judged before the answer, by none; the answer given after it asks for a restart.
    let status = game.status();
    assert!(status.contains("↺ restart"), "{status}");
    let verdict = card(&mut game, LearnText::Verdict);
    for choice in CHAPTERS[0].prediction.choices {
        assert!(!verdict.contains(choice), "{verdict}");
    }
}

/// Chapter 4 asks about I doubled: a mass made 200 times larger is said, not judged.
#[test]
fn the_inertias_task_wants_i_doubled_not_any_larger() {
    let index = 3;
    let mut game = Game::stepping();
    game.update(2);
    chapter(&mut game, index);
    game.world().trigger(Learn::Predict(RIGHT[index]));
    game.update(1);
    game.world().write_message(Action::Step);
    game.update(2);
    game.world()
        .write_message(Action::Set(Parameter::Mass, 1000.0));
    game.update(2);
    game.world().write_message(Action::Step);
    game.update(2);
    let learning = game.world().resource::<Learning>();
    assert!(!learning.done[index]);
    let verdict = learning.verdict().expect("a verdict");
    assert_eq!(verdict.outcome, None, "{verdict:?}");
    assert!(verdict.why.contains("not × 2"), "{verdict:?}");
}

/// `R` after learn mode: the game put back is a fresh game's tutorial, so `R` puts the box at
/// rest, not the chapter's scripted pull.
#[test]
fn r_after_learn_mode_puts_a_fresh_game_at_rest() {
    let mut game = Game::stepping();
    game.update(2);
    run_chapter(&mut game, 2);
    game.update(10);
    game.world().write_message(Action::Learn);
    game.update(2);
    game.world().write_message(Action::Reset);
    game.update(20);
    assert!(game.bands().is_empty());
    assert_eq!(body_state(&mut game), BodyState::default());
}

/// Runs a chapter's scene from its start with one setting changed, and returns its verdict.
fn verdict_with(index: usize, parameter: Parameter, value: f64, frames: usize) -> Option<Verdict> {
    let mut game = Game::stepping();
    game.update(2);
    chapter(&mut game, index);
    game.world().write_message(Action::Set(parameter, value));
    game.update(1);
    // R: the chapter's scene from its start with the sliders as they are, its band on the
    // nearest corner of the box as it is now.
    game.world().write_message(Action::Reset);
    game.update(2);
    game.world().trigger(Learn::Predict(RIGHT[index]));
    game.world().write_message(Action::TogglePause);
    game.update(frames);
    game.world().resource::<Learning>().verdict().cloned()
}

/// Chapter 1 with a box about as large as its pull: the corner starts near the band's end, so
/// the centre never travels 40 px; the verdict comes over half the band's stretch instead, and
/// a corner that starts on the band's end is told the band hardly pulls.
#[test]
fn chapter_1_judges_a_box_about_as_large_as_its_pull() {
    for side in [260.0, 340.0] {
        let verdict = verdict_with(0, Parameter::Size, side, 300).expect("a verdict");
        assert_eq!(verdict.outcome, Some(1), "{side}: {verdict:?}");
        // The corner (±130 or ±170 px) starts 28.3 px from (150, 150): judged over 14.1 px.
        assert!(
            verdict.why.starts_with("over 14.1 px"),
            "{side}: {verdict:?}"
        );
    }
    let verdict = verdict_with(0, Parameter::Size, 300.0, 300).expect("a verdict");
    assert_eq!(verdict.outcome, None, "{verdict:?}");
    assert!(verdict.why.contains("hardly pulls"), "{verdict:?}");
}

/// Chapter 3 with a box too heavy for its 2 s pull to change ω by 1 rad/s: the end of the
/// pull is said, with how far ω changed, not waited on in silence.
#[test]
fn chapter_3_says_when_its_pull_ends_too_weak_to_judge() {
    let verdict = verdict_with(2, Parameter::Mass, 1000.0, 400).expect("a verdict");
    assert_eq!(verdict.outcome, None, "{verdict:?}");
    assert!(verdict.why.starts_with("the pull ended"), "{verdict:?}");
    // The tutorial's box turns well past 1 rad/s under the same pull.
    let verdict = verdict_with(2, Parameter::Mass, 5.0, 400).expect("a verdict");
    assert!(verdict.outcome.is_some(), "{verdict:?}");
}
