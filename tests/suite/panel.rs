//! The on-screen panel, driven headless through the picking events a click or a tap sends
//! (press, release, click on the widget's entity): each button sends its key's action, the
//! sliders set their parameter (refused values kept out), what it shows follows the game, and
//! a press on it never grabs the box.

use crate::common;

use bevy::picking::pointer::PointerId;
use bevy::ui_widgets::{SetSliderValue, SliderValue, SliderValueChange};

use common::*;
use rubber_band_box::game::input::controls::{Action, CONTROLS, Parameter};
use rubber_band_box::game::input::panel::{PanelButton, PanelSlider};
use rubber_band_box::game::layout::{Card, CardButton, Cards};
use rubber_band_box::game::shared::SceneName;
use rubber_band_box::game::shared::{Overlay, Overlays, StatusMessage};
use rubber_band_box::physics::Integrator;

/// A card's title (the one over the card; a tall window shows the other, its tab).
fn title(game: &mut Game, card: Card) -> Entity {
    let world = game.world();
    let mut titles = world.query::<(Entity, &CardButton)>();
    titles
        .iter(world)
        .filter(|(_, title)| title.0 == card)
        .map(|(entity, _)| entity)
        .last()
        .unwrap_or_else(|| panic!("no title for {card:?}"))
}

fn open(game: &mut Game, card: Card) -> bool {
    game.world().resource::<Cards>().is_open(card)
}

#[test]
fn a_click_or_a_tap_on_a_button_does_what_its_key_does() {
    let mut game = Game::stepping();
    let fold = title(&mut game, Card::CONTROLS);
    click(&mut game, fold, PointerId::Mouse);
    assert!(open(&mut game, Card::CONTROLS));

    let pause = game.button(PanelButton::Send(Action::TogglePause));
    click(&mut game, pause, PointerId::Mouse);
    game.update(1);
    assert!(game.world().resource::<Time<Virtual>>().is_paused());
    let steps = game.steps();
    let step = game.button(PanelButton::Send(Action::Step));
    click(&mut game, step, PointerId::Touch(7));
    game.update(2);
    assert_eq!(game.steps(), steps + 1);
    click(&mut game, pause, PointerId::Touch(7));
    game.update(1);
    assert!(!game.world().resource::<Time<Virtual>>().is_paused());

    let rk4 = game.button(PanelButton::Send(Action::Integrator(Integrator::Rk4)));
    click(&mut game, rk4, PointerId::Touch(7));
    assert_eq!(*game.world().resource::<Integrator>(), Integrator::Rk4);

    let stiff = game.button(PanelButton::Send(Action::Scene(2)));
    click(&mut game, stiff, PointerId::Mouse);
    game.update(1);
    assert_eq!(game.world().resource::<SceneName>().0, "stiff");
    assert_eq!(game.world().resource::<SceneParams>().stiffness, 1e5);

    let ghosts = game.button(PanelButton::Send(Action::Toggle(Overlay::Ghosts)));
    click(&mut game, ghosts, PointerId::Mouse);
    assert!(game.world().resource::<Overlays>().on(Overlay::Ghosts));
    let faster = game.button(PanelButton::Send(Action::MoreSteps));
    click(&mut game, faster, PointerId::Mouse);
    game.update(1);
    assert_eq!(game.world().resource::<SceneParams>().step_rate_hz, 200.0);

    click(&mut game, fold, PointerId::Mouse);
    assert!(!open(&mut game, Card::CONTROLS));
}

/// Learn mode by the panel: `learn` enters it and opens its card, `next ▸` and `◂ back` move
/// between chapters, `leave` ends it and folds the card away.
#[test]
fn the_learn_buttons_walk_the_chapters() {
    use rubber_band_box::game::learn::chapter_shown;
    use rubber_band_box::game::shared::Mode;
    let mut game = Game::stepping();
    let chapter = |game: &mut Game| chapter_shown(game.world());
    let mode = |game: &mut Game| *game.world().resource::<State<Mode>>().get();
    let learn = game.button(PanelButton::Send(Action::Learn));
    click(&mut game, learn, PointerId::Mouse);
    assert_eq!(chapter(&mut game), Some(0));
    assert!(open(&mut game, Card::LEARN));
    assert_eq!(mode(&mut game), Mode::Learn);
    let next = game.button(PanelButton::Send(Action::NextChapter));
    for wanted in [1, 2, 2] {
        if wanted == 2 && chapter(&mut game) == Some(2) {
            let back = game.button(PanelButton::Send(Action::PreviousChapter));
            click(&mut game, back, PointerId::Touch(3));
            assert_eq!(chapter(&mut game), Some(1));
        }
        click(&mut game, next, PointerId::Touch(3));
        assert_eq!(chapter(&mut game), Some(wanted));
    }
    click(&mut game, learn, PointerId::Mouse);
    assert_eq!(chapter(&mut game), None);
    assert_eq!(mode(&mut game), Mode::Play);
}

/// Every action a key sends has a button, but for the digits' scenes (each has one) and the
/// single-key cycles the panel shows as choices.
#[test]
fn the_panel_reaches_every_control() {
    let mut game = Game::stepping();
    let world = game.world();
    let sent: Vec<Action> = world
        .query::<&PanelButton>()
        .iter(world)
        .filter_map(|b| match b {
            PanelButton::Send(action) => Some(*action),
            PanelButton::Fold(_) => None,
        })
        .collect();
    // Focus's keys (Tab, Esc) send no action: Bevy's tab navigation answers them.
    for control in CONTROLS
        .iter()
        .filter(|control| !control.actions.is_empty())
    {
        assert_eq!(
            control.keys.len(),
            control.actions.len(),
            "{}",
            control.name
        );
        for action in control.actions {
            let reached = match action {
                // A choice of every integrator instead of "the next one".
                Action::NextIntegrator => Integrator::ALL
                    .iter()
                    .all(|&i| sent.contains(&Action::Integrator(i))),
                // k's slider instead of ÷10 and ×10.
                Action::Softer | Action::Stiffer => true,
                other => sent.contains(other),
            };
            assert!(
                reached,
                "no panel button for {action:?} ({})",
                control.label
            );
        }
    }
    let sliders: Vec<Parameter> = world
        .query::<&PanelSlider>()
        .iter(world)
        .map(|s| s.0)
        .collect();
    assert_eq!(sliders, Parameter::ALL);
}

/// The slider moved to `position` along its track as a drag moves it (`SetSliderValue` ends in
/// the slider's own `ValueChange`), and two frames for the controls to apply it.
fn move_slider_to(game: &mut Game, slider: Entity, position: f32) {
    game.world().trigger(SetSliderValue {
        entity: slider,
        change: SliderValueChange::Absolute(position),
    });
    game.update(2);
}

/// k's slider is logarithmic (1e-2 to 1e12); a value the scene refuses is kept out, with a
/// message, and the slider keeps showing the value in force.
#[test]
fn sliders_set_parameters_through_validation() {
    let mut game = Game::stepping();
    let k = game.slider(Parameter::Stiffness);
    move_slider_to(&mut game, k, 5.0);
    assert_eq!(game.world().resource::<SceneParams>().stiffness, 1e5);
    move_slider_to(&mut game, k, 40.0);
    assert_eq!(
        game.world().resource::<SceneParams>().stiffness,
        1e12,
        "clamped to the range"
    );
    // Three significant figures, as a person reads them and enough for a fine step (a
    // hundredth of a decade) to move: 10^2.5 is 316.2..., set as 316.
    move_slider_to(&mut game, k, 2.5);
    assert_eq!(game.world().resource::<SceneParams>().stiffness, 316.0);
    // A key moves the slider too: ten times stiffer, a decade along.
    game.tap_key(KeyCode::BracketRight);
    game.update(2);
    assert_eq!(game.world().resource::<SceneParams>().stiffness, 3160.0);
    let shown = game.world().get::<SliderValue>(k).unwrap().0;
    assert!((shown - 3160f32.log10()).abs() < 1e-4, "{shown}");

    // The mass slider itself moved: `SetSliderValue` ends in the same `ValueChange` from the
    // slider that a drag sends, which `move_slider` turns into `Action::Set`. A good value
    // first (10^2), so that "the old value" differs from the scene's start (5 kg).
    let mass_slider = game.slider(Parameter::Mass);
    move_slider_to(&mut game, mass_slider, 2.0);
    assert_eq!(game.world().resource::<SceneParams>().mass, 100.0);
    // NaN is the one position the slider's clamp lets through (every other in -3..3 is a
    // valid mass), and the scene refuses it.
    move_slider_to(&mut game, mass_slider, f32::NAN);
    assert_eq!(game.world().resource::<SceneParams>().mass, 100.0);
    let said = game.world().resource::<StatusMessage>().0.clone().unwrap();
    assert!(said.starts_with("refused: mass"), "{said}");
    let shown = game.world().get::<SliderValue>(mass_slider).unwrap().0;
    assert!((shown - 2.0).abs() < 1e-4, "{shown}");
}

/// A press off the scene's viewport (where the dock and its panel lie) is not the band's:
/// no band; on the viewport, the band.
#[test]
fn a_press_off_the_viewport_never_grabs_the_box() {
    let mut game = Game::stepping();
    game.world()
        .resource_mut::<rubber_band_box::game::layout::SceneViewport>()
        .0 = Some(Rect::new(0.0, 0.0, 1000.0, 720.0));
    let on_dock = Vec2::new(1200.0, 40.0);
    game.cursor(Some(on_dock));
    game.mouse(ButtonState::Pressed);
    game.update(2);
    assert!(game.bands().is_empty());
    game.touch_screen(3, TouchPhase::Started, on_dock);
    game.update(2);
    assert!(game.bands().is_empty());
    game.touch_screen(3, TouchPhase::Ended, on_dock);
    game.mouse(ButtonState::Released);
    game.update(1);
    game.cursor(Some(Vec2::new(500.0, 300.0)));
    game.mouse(ButtonState::Pressed);
    game.update(1);
    assert_eq!(game.bands().len(), 1);
}

/// The panel's values in the HUD's units and format: k and the mass as numbers, the linear
/// damping as its coefficient and its rate, the angular damping as a rate.
#[test]
fn the_panel_shows_values_in_the_huds_units() {
    let mut game = Game::stepping();
    game.update(2);
    let world = game.world();
    let shown: Vec<String> = world
        .query::<&Text>()
        .iter(world)
        .map(|text| text.0.clone())
        .collect();
    for value in ["20", "5", "b 5 = 1 /s", "2.02 /s"] {
        assert!(
            shown.iter().any(|text| text == value),
            "{value} in {shown:?}"
        );
    }
    // Not the engineering notation the panel once printed.
    for old in ["2.000e1", "5.000e0", "2.020e0"] {
        assert!(!shown.iter().any(|text| text == old), "{old} in {shown:?}");
    }
}

/// Each slider's ends read in the same units: k from 0.01 to 1e12, the mass from 1e-3 to
/// 1000 and the size from 1 to 640 px (logarithmic), the linear damping's coefficient from 0 to 50, the angular rate from 0
/// to 20 /s.
#[test]
fn the_sliders_ends_say_their_values_in_the_readouts_units() {
    use rubber_band_box::game::input::panel::SliderEnd;
    let mut game = Game::stepping();
    game.update(1);
    let world = game.world();
    let mut ends: Vec<(String, String)> = world
        .query::<(&SliderEnd, &Text)>()
        .iter(world)
        .map(|(end, text)| (end.0.name().to_owned(), text.0.clone()))
        .collect();
    ends.sort();
    let mut expected: Vec<(String, String)> = [
        ("k", "0.01"),
        ("k", "1.0e12"),
        ("mass", "1.0e-3"),
        ("mass", "1000"),
        ("size", "1 px"),
        ("size", "640 px"),
        ("linear damping", "b 0"),
        ("linear damping", "b 50"),
        ("angular damping", "0 /s"),
        ("angular damping", "20 /s"),
    ]
    .into_iter()
    .map(|(name, text)| (name.to_owned(), text.to_owned()))
    .collect();
    expected.sort();
    assert_eq!(ends, expected);
}

/// The panel's buttons where Bevy's own UI layout puts them (no renderer): what a window
/// shows, read back as the page and the pointer read it.
fn laid_out_game() -> Game {
    let mut game = Game::with(Duration::from_millis(10), add_the_layout);
    game.update(2);
    game
}

/// Where a laid-out node lies on the window.
fn rect_of(game: &mut Game, entity: Entity) -> Rect {
    let world = game.world();
    let scale = world.resource::<UiScale>().0;
    let node = world.get::<ComputedNode>(entity).unwrap();
    let transform = world.get::<UiGlobalTransform>(entity).unwrap();
    let s = node.inverse_scale_factor() * scale;
    Rect::from_center_size(transform.translation * s, node.size() * s)
}

/// Where the button that does `does` lies on the window, as laid out.
fn laid_out(game: &mut Game, does: PanelButton) -> Rect {
    let entity = game.button(does);
    rect_of(game, entity)
}

/// A phone's tap, the way the game takes it: a finger's `TouchInput` at the place Bevy's UI
/// layout gave the button (`tap_buttons` reads the touches; picking misses a new finger's
/// first press in the browser). The controls card's title, in the dock at the window's
/// right, unfolds it; the laid-out pause button pauses the game; neither tap grabs the box,
/// and a finger on the scene still pulls.
#[test]
fn a_finger_taps_a_laid_out_button_and_never_grabs_the_box() {
    let mut game = laid_out_game();
    let fold = title(&mut game, Card::CONTROLS);
    let fold = rect_of(&mut game, fold);
    assert!(
        fold.width() > 20.0 && fold.height() >= 28.0,
        "laid out: {fold:?}"
    );
    // The dock's first card, at the right of the 1280 x 720 window.
    assert!(fold.max.x <= 1280.0 && fold.min.x > 800.0 && fold.min.y < 60.0);

    let tap = |game: &mut Game, id: u64, at: Vec2| {
        game.touch_screen(id, TouchPhase::Started, at);
        game.update(1);
        let grabbed = !game.bands().is_empty();
        game.touch_screen(id, TouchPhase::Ended, at);
        game.update(2);
        grabbed
    };
    assert!(!open(&mut game, Card::CONTROLS));
    // Folded, the body's buttons have no size: a tap elsewhere reaches none of them.
    tap(&mut game, 5, Vec2::new(300.0, 300.0));
    assert!(!open(&mut game, Card::CONTROLS));
    assert!(!game.world().resource::<Time<Virtual>>().is_paused());
    assert_eq!(*game.world().resource::<Integrator>(), Integrator::Auto);
    assert_eq!(*game.world().resource::<Overlays>(), Overlays::default());
    assert!(!tap(&mut game, 1, fold.center()), "the tap grabbed the box");
    assert!(open(&mut game, Card::CONTROLS), "the tap unfolded it");

    let pause = laid_out(&mut game, PanelButton::Send(Action::TogglePause));
    assert!(pause.width() > 20.0, "unfolded, the pause button has room");
    let paused = |game: &mut Game| game.world().resource::<Time<Virtual>>().is_paused();
    assert!(!paused(&mut game));
    assert!(
        !tap(&mut game, 2, pause.center()),
        "the tap grabbed the box"
    );
    assert!(paused(&mut game), "the tap paused the game");

    // A finger on the scene pulls.
    game.touch(3, TouchPhase::Started, DVec2::new(-100.0, 50.0));
    game.update(1);
    assert_eq!(game.bands().len(), 1, "a finger on the scene pulls");
}

/// What the panel lights says what is on: the live integrator's button and the scene's, the
/// shown overlays' and the HUD's, the fold button while open; the pause button says "resume"
/// while paused.
#[test]
fn the_lit_buttons_say_what_is_on() {
    let mut game = Game::stepping();
    game.update(1);
    let lit = |game: &mut Game| -> Vec<PanelButton> {
        let world = game.world();
        // Reset is never lit: its colour is the unlit one.
        let unlit = world
            .query::<(&PanelButton, &BackgroundColor)>()
            .iter(world)
            .find(|(b, _)| **b == PanelButton::Send(Action::Reset))
            .map(|(_, c)| c.0)
            .unwrap();
        world
            .query::<(&PanelButton, &BackgroundColor)>()
            .iter(world)
            .filter(|(_, c)| c.0 != unlit)
            .map(|(b, _)| *b)
            .collect()
    };
    let mut on = lit(&mut game);
    on.sort_by_key(|b| format!("{b:?}"));
    let mut expected = vec![
        PanelButton::Send(Action::Integrator(Integrator::Auto)),
        PanelButton::Send(Action::Scene(0)),
        PanelButton::Send(Action::ToggleDock),
    ];
    expected.sort_by_key(|b| format!("{b:?}"));
    assert_eq!(on, expected, "auto, the tutorial and the HUD at the start");

    *game.world().resource_mut::<Integrator>() = Integrator::Rk4;
    game.world().resource_mut::<SceneName>().0 = "stiff".to_owned();
    game.world()
        .resource_mut::<rubber_band_box::game::shared::DockHidden>()
        .0 = true;
    game.world()
        .resource_mut::<Overlays>()
        .set(Overlay::Ghosts, true);
    game.update(1);
    let on = lit(&mut game);
    for button in [
        PanelButton::Send(Action::Integrator(Integrator::Rk4)),
        PanelButton::Send(Action::Scene(2)),
        PanelButton::Send(Action::Toggle(Overlay::Ghosts)),
    ] {
        assert!(on.contains(&button), "{button:?} lit: {on:?}");
    }
    for button in [
        PanelButton::Send(Action::Integrator(Integrator::Auto)),
        PanelButton::Send(Action::Scene(0)),
        PanelButton::Send(Action::ToggleDock),
    ] {
        assert!(!on.contains(&button), "{button:?} not lit: {on:?}");
    }

    let label = |game: &mut Game| -> String {
        let world = game.world();
        let children = world
            .query::<(&PanelButton, &Children)>()
            .iter(world)
            .find(|(b, _)| **b == PanelButton::Send(Action::TogglePause))
            .map(|(_, c)| c[0])
            .unwrap();
        world.get::<Text>(children).unwrap().0.clone()
    };
    assert_eq!(label(&mut game), "pause");
    game.world().resource_mut::<Time<Virtual>>().pause();
    game.update(1);
    assert_eq!(label(&mut game), "resume");
}

/// While a finger is on the screen its taps are `tap_buttons`' (read from the touches):
/// picking's own press of the same tap is ignored, so a tap never acts twice.
#[test]
fn a_picking_press_while_a_finger_is_down_is_ignored() {
    let mut game = Game::stepping();
    game.touch_screen(4, TouchPhase::Started, Vec2::new(20.0, 700.0));
    game.update(1);
    let pause = game.button(PanelButton::Send(Action::TogglePause));
    click(&mut game, pause, PointerId::Touch(4));
    game.update(1);
    assert!(!game.world().resource::<Time<Virtual>>().is_paused());
    game.touch_screen(4, TouchPhase::Ended, Vec2::new(20.0, 700.0));
    game.update(2);
    click(&mut game, pause, PointerId::Mouse);
    game.update(1);
    assert!(game.world().resource::<Time<Virtual>>().is_paused());
}

/// Each slider's thumb lies where its value does along the track (150 px less the 18 px
/// thumb): k = 1e5 halfway along 1e-2 .. 1e12, the mass of 5 kg at log10(5) along 1e-3 .. 1e3.
#[test]
fn each_thumb_lies_where_its_value_does() {
    use bevy::ui_widgets::SliderThumb;
    let mut game = Game::stepping();
    let k = game.slider(Parameter::Stiffness);
    move_slider_to(&mut game, k, 5.0);
    let thumb_left = |game: &mut Game, parameter: Parameter| -> f32 {
        let entity = game.slider(parameter);
        let world = game.world();
        let children: Vec<Entity> = world.get::<Children>(entity).unwrap().to_vec();
        let node = children
            .iter()
            .find(|&&child| world.get::<SliderThumb>(child).is_some())
            .and_then(|&child| world.get::<Node>(child))
            .expect("the slider's thumb");
        match node.left {
            Val::Px(left) => left,
            other => panic!("{other:?}"),
        }
    };
    let track = 150.0 - 18.0;
    let k_left = thumb_left(&mut game, Parameter::Stiffness);
    assert!((k_left - 0.5 * track).abs() < 1e-3, "{k_left}");
    let mass_left = thumb_left(&mut game, Parameter::Mass);
    let expected = (5f32.log10() + 3.0) / 6.0 * track;
    assert!(
        (mass_left - expected).abs() < 1e-3,
        "{mass_left} against {expected}"
    );
}

/// A slider follows its value however it changed: at k = 10 (1 along its logarithmic track)
/// and then k set to 0.1 elsewhere (a scene, a replay), it moves to -1.
#[test]
fn a_slider_follows_its_value_set_elsewhere() {
    let mut game = Game::stepping();
    let k = game.slider(Parameter::Stiffness);
    move_slider_to(&mut game, k, 1.0);
    assert_eq!(game.world().resource::<SceneParams>().stiffness, 10.0);
    game.world().resource_mut::<SceneParams>().stiffness = 0.1;
    game.update(2);
    let shown = game.world().get::<SliderValue>(k).unwrap().0;
    assert!((shown + 1.0).abs() < 1e-4, "{shown}");
}
