//! What a screen reader finds (docs/accessibility.md), read from the AccessKit nodes the game
//! hands Bevy: every control Tab reaches has a name and a role, every slider its value and
//! range, every text is a label, the scene is described when it changes and only then, and
//! the screen reader's requests act as the keys do.

use crate::common;

use accesskit::{Action, Live, Role};
use bevy::a11y::{AccessibilityNode, ActionRequest};
use bevy::input::ButtonState;
use bevy::input_focus::InputFocus;
use bevy::prelude::*;

use common::{Game, keys_of};
use rubber_band_box::game::access::SceneDescription;
use rubber_band_box::game::input::controls::Action as GameAction;
use rubber_band_box::game::input::controls::Parameter;
use rubber_band_box::game::input::panel::PanelButton;
use rubber_band_box::physics::{Integrator, SceneParams};

fn node(game: &mut Game, entity: Entity) -> accesskit::Node {
    game.world()
        .get::<AccessibilityNode>(entity)
        .expect("an AccessKit node")
        .0
        .clone()
}

/// The scene's node, as AccessKit finds it: the one canvas of the tree.
fn the_scene(game: &mut Game) -> Entity {
    let world = game.world();
    let canvases: Vec<Entity> = world
        .query::<(Entity, &AccessibilityNode)>()
        .iter(world)
        .filter(|(_, node)| node.role() == Role::Canvas)
        .map(|(entity, _)| entity)
        .collect();
    assert_eq!(canvases.len(), 1, "one canvas, the scene's");
    canvases[0]
}

/// What Tab visits, in order, from the first control round to it again.
fn tab_round(game: &mut Game) -> Vec<Entity> {
    let mut visited: Vec<Entity> = Vec::new();
    loop {
        game.tap_key(KeyCode::Tab);
        game.update(1);
        let at = game.world().resource::<InputFocus>().get().expect("focus");
        if visited.first() == Some(&at) {
            return visited;
        }
        visited.push(at);
        assert!(visited.len() < 200, "Tab never came round");
    }
}

#[test]
fn every_control_tab_reaches_has_a_name_and_a_role_in_the_documented_order() {
    let mut game = Game::stepping();
    game.update(3);
    let visited = tab_round(&mut game);
    let mut said = Vec::new();
    for &entity in &visited {
        let node = node(&mut game, entity);
        let name = node.label().unwrap_or_default().to_owned();
        assert!(!name.is_empty(), "{entity} has no name: {node:?}");
        assert!(!node.is_hidden(), "{name}: hidden but reached");
        match node.role() {
            Role::Button => assert!(node.supports_action(Action::Click), "{name}"),
            Role::Slider => {
                assert!(node.numeric_value().is_some() && node.max_numeric_value().is_some());
                assert!(node.value().is_some_and(|v| !v.is_empty()), "{name}");
                assert!(node.supports_action(Action::Increment), "{name}");
            }
            role => panic!("{name}: role {role:?}"),
        }
        said.push(name);
    }
    println!("{said:#?}");
    // docs/accessibility.md's order: the status line's button, then each card's title.
    let documented = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/docs/accessibility.md"
    ))
    .expect("docs/accessibility.md");
    let order: Vec<&str> = documented
        .lines()
        .skip_while(|line| !line.starts_with("Tab order"))
        .skip(1)
        .skip_while(|line| line.trim().is_empty())
        .take_while(|line| line.starts_with(char::is_numeric))
        .map(|line| line.split_once(". ").map_or(line, |(_, name)| name))
        .collect();
    assert!(!order.is_empty(), "the page lists the Tab order");
    assert_eq!(said, order, "Tab's order is the page's");
    // Every card open: every control Tab reaches then has a name and a role too.
    for title in &visited[1..] {
        game.world()
            .resource_mut::<InputFocus>()
            .set(*title, bevy::input_focus::FocusCause::Navigated);
        game.tap_key(KeyCode::Enter);
        game.update(2);
    }
    game.world().resource_mut::<InputFocus>().clear();
    game.update(1);
    let all = tab_round(&mut game);
    assert!(
        all.len() > 40,
        "{} controls with every card open",
        all.len()
    );
    let mut sliders = 0;
    let mut names = std::collections::BTreeSet::new();
    for entity in all {
        let node = node(&mut game, entity);
        let name = node.label().unwrap_or_default().to_owned();
        assert!(!name.is_empty() && !node.is_hidden(), "{entity}: {node:?}");
        // Each says which it is: the rate's "÷2" is not the time's.
        assert!(names.insert(name.clone()), "two controls named {name}");
        match node.role() {
            Role::Button => {}
            Role::Slider => {
                sliders += 1;
                assert!(node.value().is_some_and(|v| !v.is_empty()), "{name}");
                assert!(node.supports_action(Action::Increment), "{name}");
            }
            role => panic!("{name}: role {role:?}"),
        }
    }
    assert_eq!(sliders, 5, "k, mass, size and the two dampings");
}

#[test]
fn every_text_shown_is_a_label_with_its_words_and_cards_and_the_scene_are_named() {
    let mut game = Game::stepping();
    game.update(3);
    let world = game.world();
    let mut texts =
        world.query_filtered::<(&Text, &AccessibilityNode), With<bevy::ui::widget::Label>>();
    let labels: Vec<(String, accesskit::Node)> = texts
        .iter(world)
        .map(|(text, node)| (text.0.clone(), node.0.clone()))
        .collect();
    assert!(labels.len() > 10, "{} labels", labels.len());
    for (text, node) in &labels {
        assert_eq!(node.role(), Role::Label);
        assert!(
            node.value().unwrap_or_default().starts_with(text.as_str()),
            "{text}"
        );
    }
    let mut groups = world.query::<&AccessibilityNode>();
    let names: Vec<String> = groups
        .iter(world)
        .filter(|node| node.role() == Role::Group)
        .filter_map(|node| node.label().map(str::to_owned))
        .collect();
    assert!(names.iter().any(|name| name == "Controls"), "{names:?}");
}

/// Read from the scene's node, as AccessKit reads it; when it changed, from the description's
/// resource.
#[test]
fn the_description_changes_when_the_box_moves_and_is_quiet_when_it_does_not() {
    let mut game = Game::stepping();
    game.update(5);
    let scene = the_scene(&mut game);
    let said = |game: &mut Game| {
        let found = node(game, scene);
        found.description().unwrap_or_default().to_owned()
    };
    let first = said(&mut game);
    let told = game.world().resource::<SceneDescription>().changes;
    assert!(first.contains("at the centre"), "{first}");
    // At rest for three seconds: nothing new to say.
    game.update(300);
    assert_eq!(said(&mut game), first);
    assert_eq!(game.world().resource::<SceneDescription>().changes, told);
    // A pull far to the right: it is said, and at most twice a second.
    game.press_at(bevy::math::DVec2::new(300.0, 0.0));
    game.update(1);
    let mut changes = Vec::new();
    for _ in 0..200 {
        game.update(1);
        let now = said(&mut game);
        let at = game.world().resource::<SceneDescription>().at;
        if changes
            .last()
            .is_none_or(|(said, _): &(String, f64)| *said != now)
        {
            changes.push((now, at));
        }
    }
    assert!(
        changes
            .iter()
            .any(|(said, _)| said.contains("A band pulls a corner to the right")),
        "{changes:#?}"
    );
    assert!(
        changes
            .iter()
            .any(|(said, _)| said.contains("moving to the right")),
        "{changes:#?}"
    );
    for pair in changes.windows(2) {
        assert!(pair[1].1 - pair[0].1 >= 0.5 - 1e-9, "{pair:?}");
    }
    assert!(changes.len() <= 5, "{changes:#?}");
}

/// The scene's own node, the one AccessKit hands the screen reader, says the scene: at rest, and
/// after a pull by keyboard with the band in it, as the description said to the page.
///
/// Issue 61: `access` looked for Bevy's `ViewportNode`, which the scene's node does not carry
/// (the layout's marker had the same name), so the words reached the page and no node.
#[test]
fn the_scenes_node_says_the_scene_after_a_pull_by_keyboard() {
    let mut game = Game::stepping();
    game.update(5);
    let scene = the_scene(&mut game);
    let at_rest = node(&mut game, scene);
    assert_eq!(
        at_rest.label(),
        Some("The scene: a box pulled by a rubber band")
    );
    assert_eq!(at_rest.live(), Some(Live::Polite));
    let said = at_rest.description().unwrap_or_default();
    assert!(said.contains("at the centre"), "{at_rest:?}");
    // The cursor to the right, B grabs the corner nearest it, and the arrow pulls on.
    game.key(KeyCode::ArrowRight, ButtonState::Pressed);
    game.update(30);
    game.tap_key(keys_of("band")[0]);
    game.update(60);
    game.key(KeyCode::ArrowRight, ButtonState::Released);
    game.update(60);
    let pulled = node(&mut game, scene);
    let said = pulled.description().unwrap_or_default();
    assert!(said.contains("A band pulls a corner"), "{pulled:?}");
    assert_eq!(said, game.world().resource::<SceneDescription>().said);
}

/// What changes is said where a listener looks for it, not in the window's name: the status
/// line is the window's status bar, and the hint (how to play, or the latest news) a polite
/// live region, as the page's is in the browser.
#[test]
fn the_status_line_is_the_status_bar_and_the_hint_a_live_region() {
    let mut game = Game::stepping();
    game.update(3);
    let status = region_of(&mut game, "HUD Status");
    assert_eq!(status.role(), Role::Status);
    assert_eq!(status.label(), Some("Status"));
    assert_eq!(status.live(), None, "its clock changes every tenth");
    assert_eq!(region_of(&mut game, "HUD Hint").live(), Some(Live::Polite));
}

/// The node of the region the HUD's line named `line` lies in.
fn region_of(game: &mut Game, line: &str) -> accesskit::Node {
    let world = game.world();
    let region = world
        .query::<(&Name, &ChildOf)>()
        .iter(world)
        .find(|(name, _)| name.as_str() == line)
        .map(|(_, child_of)| child_of.parent())
        .expect("the HUD's line");
    node(game, region)
}

fn request(game: &mut Game, entity: Entity, action: Action) {
    game.world()
        .write_message(ActionRequest(accesskit::ActionRequest {
            action,
            target_tree: accesskit::TreeId::ROOT,
            target_node: accesskit::NodeId(entity.to_bits()),
            data: None,
        }));
    game.update(2);
}

#[test]
fn the_screen_readers_requests_press_step_and_focus() {
    let mut game = Game::stepping();
    game.update(3);
    let rk4 = game.button(PanelButton::Send(GameAction::Integrator(Integrator::Rk4)));
    let mass = game.slider(Parameter::Mass);
    request(&mut game, rk4, Action::Click);
    assert_eq!(*game.world().resource::<Integrator>(), Integrator::Rk4);
    let before = game.world().resource::<SceneParams>().mass;
    request(&mut game, mass, Action::Increment);
    let after = game.world().resource::<SceneParams>().mass;
    assert!(after > before, "{before} -> {after}");
    request(&mut game, mass, Action::Decrement);
    request(&mut game, mass, Action::Decrement);
    assert!(game.world().resource::<SceneParams>().mass < before);
    request(&mut game, mass, Action::Focus);
    assert_eq!(game.world().resource::<InputFocus>().get(), Some(mass));
}

/// What the browser's page is told (docs/accessibility.md): the live region says the scene
/// and then the last action's result, the list names every control shown with a slider's
/// value, and the focus says when Tab is at the first or last control, where it leaves.
#[test]
fn the_page_is_told_the_scene_the_last_result_the_controls_and_the_focus() {
    use rubber_band_box::game::access::Page;
    let mut game = Game::stepping();
    game.update(3);
    let page = game.world().resource::<Page>().clone();
    assert!(page.said.starts_with("The box is"), "{}", page.said);
    assert!(page.focus.is_none(), "the scene has the focus");
    let names: Vec<&str> = page
        .controls
        .iter()
        .map(|(name, _)| name.as_str())
        .collect();
    assert_eq!(
        names,
        ["instruments", "Controls", "Readouts", "Energy", "Stability"]
    );
    game.tap_key(KeyCode::KeyO);
    game.update(2);
    assert_eq!(
        game.world().resource::<Page>().said,
        "drop a replay file on the window to play it"
    );
    // Tab to the first control, then round to the last (Shift+Tab).
    game.tap_key(KeyCode::Tab);
    game.update(2);
    let focus = game.world().resource::<Page>().focus.clone();
    assert_eq!(focus, Some(("instruments".to_owned(), true, false)));
    // Enter on Controls' title opens it: its sliders are listed with their values.
    game.tap_key(KeyCode::Tab);
    game.update(1);
    game.tap_key(KeyCode::Enter);
    game.update(3);
    let page = game.world().resource::<Page>().clone();
    let k = page
        .controls
        .iter()
        .find(|(name, _)| name == "band stiffness k")
        .expect("k's slider listed");
    assert_eq!(k.1, "20", "the tutorial's k, as the readout writes it");
    game.key(KeyCode::ShiftLeft, bevy::input::ButtonState::Pressed);
    game.update(1);
    game.tap_key(KeyCode::Tab);
    game.update(1);
    game.tap_key(KeyCode::Tab);
    game.update(1);
    game.key(KeyCode::ShiftLeft, bevy::input::ButtonState::Released);
    game.update(2);
    let focus = game
        .world()
        .resource::<Page>()
        .focus
        .clone()
        .expect("a focus");
    assert!(
        focus.2 && !focus.1,
        "Shift+Tab from the first goes to the last: {focus:?}"
    );
}

/// A lit button says so: a switch (ghosts, the dock) on or off, a choice (an integrator, a
/// scene) selected or not, as the panel lights it.
#[test]
fn a_screen_reader_hears_which_switches_are_on_and_which_choice_is_made() {
    let mut game = Game::stepping();
    game.update(3);
    let find = |game: &mut Game, does: GameAction| game.button(PanelButton::Send(does));
    let ghosts = find(
        &mut game,
        GameAction::Toggle(rubber_band_box::game::shared::Overlay::Ghosts),
    );
    let rk4 = find(&mut game, GameAction::Integrator(Integrator::Rk4));
    let auto = find(&mut game, GameAction::Integrator(Integrator::Auto));
    assert_eq!(
        node(&mut game, ghosts).toggled(),
        Some(accesskit::Toggled::False)
    );
    assert_eq!(node(&mut game, auto).is_selected(), Some(true));
    assert_eq!(node(&mut game, rk4).is_selected(), Some(false));
    game.tap_key(KeyCode::KeyG);
    game.tap_key(KeyCode::KeyI);
    game.update(3);
    assert_eq!(
        node(&mut game, ghosts).toggled(),
        Some(accesskit::Toggled::True)
    );
    let next = game.world().resource::<Integrator>().to_owned();
    let chosen = find(&mut game, GameAction::Integrator(next));
    assert_eq!(node(&mut game, chosen).is_selected(), Some(true));
    assert_eq!(node(&mut game, auto).is_selected(), Some(false));
}
