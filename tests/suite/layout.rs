//! The screen's regions, laid out by Bevy's own UI layout (no renderer) at six window sizes,
//! from a phone held upright to a desktop: with every instrument open and with every one
//! folded, no two texts meet, no text or control lies on the scene's viewport, everything
//! lies in the window, and the viewport is the largest region. (The box in the viewport under
//! a player's hand: tests/camera.rs.)

use crate::common;

use bevy::ecs::system::RunSystemOnce;
use bevy::ui::{CalculatedClip, UiGlobalTransform};
use common::*;
use rubber_band_box::game::layout::{
    Card, CardRegistry, Cards, SceneViewport, Shape, shown_texts, visible_rect,
};
use rubber_band_box::game::pointer::PointerAction;
use rubber_band_box::game::shared::DockHidden;

const SIZES: [UVec2; 6] = [
    UVec2::new(360, 740),
    UVec2::new(390, 844),
    UVec2::new(844, 390),
    UVec2::new(960, 720),
    UVec2::new(1280, 800),
    UVec2::new(1920, 1080),
];

/// Every text shown and every button shown, as the window shows them.
fn shown(game: &mut Game) -> (Vec<(String, Rect)>, Vec<Rect>) {
    let world = game.world();
    let scale = UiScale(world.resource::<UiScale>().0);
    let texts = world
        .run_system_once(
            |scale: Res<UiScale>,
             texts: Query<(
                &Text,
                &ComputedNode,
                &UiGlobalTransform,
                Option<&CalculatedClip>,
            )>| { shown_texts(&texts, &scale) },
        )
        .unwrap();
    let mut buttons = world.query_filtered::<
        (&ComputedNode, &UiGlobalTransform, Option<&CalculatedClip>),
        With<bevy::ui_widgets::Button>,
    >();
    let buttons = buttons
        .iter(world)
        .filter_map(|(node, transform, clip)| visible_rect(node, transform, clip, &scale))
        .collect();
    (texts, buttons)
}

/// Two rectangles share more than an edge.
fn overlap(a: Rect, b: Rect) -> bool {
    let cut = a.intersect(b);
    cut.width() > 0.5 && cut.height() > 0.5
}

/// Every check of the layout at one size and state; the viewport's share of the window.
fn check(game: &mut Game, size: UVec2, name: &str) -> f32 {
    game.update(4);
    let window = Rect::from_corners(Vec2::ZERO, size.as_vec2());
    let viewport = game
        .world()
        .resource::<SceneViewport>()
        .0
        .unwrap_or_else(|| panic!("{name}: the viewport laid out"));
    let (texts, buttons) = shown(game);
    assert!(texts.len() >= 3, "{name}: texts shown: {texts:?}");
    for (i, (text, rect)) in texts.iter().enumerate() {
        assert!(
            window.union(rect.inflate(-0.5)) == window,
            "{name}: {text:?} at {rect:?} leaves the window"
        );
        assert!(
            !overlap(*rect, viewport),
            "{name}: {text:?} at {rect:?} lies on the scene {viewport:?}"
        );
        for (other, other_rect) in &texts[i + 1..] {
            assert!(
                !overlap(*rect, *other_rect),
                "{name}: {text:?} at {rect:?} meets {other:?} at {other_rect:?}"
            );
        }
    }
    for rect in &buttons {
        assert!(
            window.union(rect.inflate(-0.5)) == window,
            "{name}: a button at {rect:?} leaves the window"
        );
        assert!(
            !overlap(*rect, viewport),
            "{name}: a button at {rect:?} lies on the scene {viewport:?}"
        );
    }
    viewport.width() * viewport.height() / (window.width() * window.height())
}

#[test]
fn at_six_sizes_nothing_meets_and_the_scene_is_the_largest_region() {
    let mut game = Game::laid_out();
    // Every instrument on: the ghosts, the plot, the vectors and the trail, a pull going on.
    game.tap_key(KeyCode::KeyP);
    game.tap_key(KeyCode::KeyV);
    game.tap_key(KeyCode::KeyT);
    game.update(1);
    game.world()
        .write_message(PointerAction::Press(DVec2::new(200.0, 120.0)));
    game.update(30);
    for size in SIZES {
        game.resize(size);
        let shape = Shape::of(size.as_vec2());
        // Folded: every card closed.
        *game.world().resource_mut::<Cards>() = Cards::default();
        let folded = check(&mut game, size, &format!("{size} folded"));
        // Open: on the side every card at once; on a tall window each in turn.
        let all: Vec<Card> = game.world().resource::<CardRegistry>().cards().collect();
        let opened: Vec<Vec<Card>> = match shape {
            Shape::Wide => vec![all],
            Shape::Tall => all.into_iter().map(|card| vec![card]).collect(),
        };
        for cards in opened {
            let mut state = Cards::default();
            for card in &cards {
                state.set(*card, true);
            }
            *game.world().resource_mut::<Cards>() = state;
            let name = format!("{size}, {cards:?} open");
            let share = check(&mut game, size, &name);
            let least = match (shape, size.x >= 960) {
                (Shape::Wide, true) => 0.5,
                _ => 0.4,
            };
            assert!(
                share >= least,
                "{name}: the scene has {share:.2} of the window"
            );
            assert!(
                share <= folded + 1e-3,
                "{name}: folding gives the scene room"
            );
        }
        // Hidden (H): the scene takes the whole window but its two lines.
        game.world().resource_mut::<DockHidden>().0 = true;
        let hidden = check(&mut game, size, &format!("{size}, the dock hidden"));
        assert!(hidden > 0.85, "{size}: hidden, the scene has {hidden:.2}");
        game.world().resource_mut::<DockHidden>().0 = false;
    }
}

/// A message under the scene (the hint line says the latest status for a while) moves
/// nothing: the line holds one line whatever it says, so a button below it stays where a
/// finger is about to land.
#[test]
fn a_message_under_the_scene_moves_nothing() {
    let mut game = Game::laid_out();
    for size in SIZES {
        game.resize(size);
        game.update(4);
        let before = game.world().resource::<SceneViewport>().0;
        game.world().trigger(rubber_band_box::game::shared::Say(
            "replay over: 1234 steps, the recorded states to the bit (hash 0123456789abcdef), and \
             more words to wrap"
                .to_owned(),
        ));
        game.update(4);
        assert_eq!(game.world().resource::<SceneViewport>().0, before, "{size}");
        let (texts, _) = shown(&mut game);
        assert!(
            texts
                .iter()
                .any(|(text, _)| text.starts_with("replay over")),
            "{size}"
        );
    }
}

/// Learn mode's card, on every chapter (the longest equations: the energy's, the update
/// loop's), at every size: open beside every other card on a wide window, alone on a tall one.
#[test]
fn learn_modes_card_lays_out_at_six_sizes() {
    use rubber_band_box::game::learn::Learn;
    use rubber_band_box::game::learn::chapters::CHAPTERS;
    let mut game = Game::laid_out();
    game.world()
        .write_message(PointerAction::Press(DVec2::new(200.0, 120.0)));
    for chapter in 0..CHAPTERS.len() {
        game.world().trigger(Learn::Chapter(chapter));
        game.update(10);
        for size in SIZES {
            game.resize(size);
            let mut state = Cards::default();
            match Shape::of(size.as_vec2()) {
                Shape::Wide => {
                    let registry = game.world().resource::<CardRegistry>();
                    registry.cards().for_each(|card| state.set(card, true));
                }
                Shape::Tall => state.set(Card::LEARN, true),
            }
            *game.world().resource_mut::<Cards>() = state;
            let name = format!("{size}, chapter {}", chapter + 1);
            let share = check(&mut game, size, &name);
            assert!(
                share >= 0.4,
                "{name}: the scene has {share:.2} of the window"
            );
            let title = format!("{} of {}", chapter + 1, CHAPTERS.len());
            let (texts, _) = shown(&mut game);
            assert!(
                texts.iter().any(|(text, _)| text.starts_with(&title)),
                "{name}: the chapter's title is not shown"
            );
        }
    }
}

/// The dock's track and thumb on the window, and whether each is painted.
fn dock_scrollbar(game: &mut Game) -> ((Rect, bool), (Rect, bool)) {
    use bevy::ui_widgets::ScrollbarThumb;
    use rubber_band_box::game::layout::DockScrollbar;
    use rubber_band_box::game::layout::window_rect;
    let world = game.world();
    let scale = UiScale(world.resource::<UiScale>().0);
    let track = world
        .query_filtered::<Entity, With<DockScrollbar>>()
        .single(world)
        .unwrap();
    let thumb = world
        .query_filtered::<Entity, With<ScrollbarThumb>>()
        .single(world)
        .unwrap();
    let read = |entity: Entity| {
        let node = world.get::<ComputedNode>(entity).unwrap();
        let transform = world.get::<UiGlobalTransform>(entity).unwrap();
        let painted = world.get::<BackgroundColor>(entity).unwrap().0.alpha() > 0.5;
        (window_rect(node, transform, &scale), painted)
    };
    (read(track), read(thumb))
}

/// At 960 x 720 with the energy, ghosts and plot cards open the dock's cards run past the
/// window's bottom: a scrollbar beside them says so (its thumb shorter than its track, at the
/// top), and it reaches the track's end when the cards are scrolled to theirs. With the cards
/// folded, or on a phone with one short card open, no scrollbar is painted.
#[test]
fn a_dock_that_overflows_shows_its_scrollbar() {
    use rubber_band_box::game::layout::DockCards;
    let mut game = Game::laid_out();
    game.resize(UVec2::new(960, 720));
    game.tap_key(KeyCode::KeyG);
    game.tap_key(KeyCode::KeyP);
    let mut open = Cards::default();
    for card in [Card::ENERGY, Card::GHOSTS, Card::PLOT] {
        open.set(card, true);
    }
    *game.world().resource_mut::<Cards>() = open;
    game.update(4);
    let ((track, painted), (thumb, shown)) = dock_scrollbar(&mut game);
    assert!(
        painted && shown,
        "the scrollbar is seen: {track:?} {thumb:?}"
    );
    assert!(
        thumb.height() < track.height() - 10.0 && (thumb.min.y - track.min.y).abs() < 1.0,
        "a short thumb at the top: {thumb:?} in {track:?}"
    );
    assert!(track.width() >= 3.0 && track.max.x <= 960.5, "{track:?}");
    // Scrolled to the end: the thumb at the track's end.
    let world = game.world();
    let mut scrolled = world.query_filtered::<&mut ScrollPosition, With<DockCards>>();
    scrolled.single_mut(world).unwrap().0.y = 1e6;
    game.update(3);
    let ((track, _), (thumb, _)) = dock_scrollbar(&mut game);
    assert!(
        (thumb.max.y - track.max.y).abs() < 1.0,
        "scrolled to the end, the thumb at the track's end: {thumb:?} in {track:?}"
    );
    // Folded: nothing to scroll, nothing painted.
    *game.world().resource_mut::<Cards>() = Cards::default();
    game.update(4);
    let ((_, painted), (_, shown)) = dock_scrollbar(&mut game);
    assert!(!painted && !shown, "folded cards need no scrollbar");
    game.resize(UVec2::new(390, 844));
    let mut readouts = Cards::default();
    readouts.set(Card::READOUTS, true);
    *game.world().resource_mut::<Cards>() = readouts;
    game.update(4);
    let ((track, painted), (_, shown)) = dock_scrollbar(&mut game);
    assert!(!painted && !shown, "a short card on a phone: {track:?}");
}

/// A small window starts with the dock hidden and says how to show it: where a card open would
/// leave the scene less than half the window (320 x 240, 480 x 320, 240 x 480); a desktop and a
/// phone held upright keep it. A window grown large shows it again; once the player (or a
/// link) sets the dock, the window's size no longer does.
#[test]
fn a_small_window_starts_with_the_dock_hidden() {
    use rubber_band_box::game::layout::small::scene_share_with_a_card_open;
    // The rule: the scene kept at least half the window.
    const LEAST_SCENE_SHARE: f32 = 0.5;
    use rubber_band_box::game::shared::StatusMessage;
    for (size, hidden) in [
        (UVec2::new(320, 240), true),
        (UVec2::new(480, 320), true),
        (UVec2::new(240, 480), true),
        (UVec2::new(960, 720), false),
        (UVec2::new(1280, 800), false),
        (UVec2::new(844, 390), false),
    ] {
        let share = scene_share_with_a_card_open(size.as_vec2());
        println!("{size}: {share:.3}");
        assert_eq!(share < LEAST_SCENE_SHARE, hidden, "{size}: {share}");
        let mut game = Game::laid_out();
        game.resize(size);
        game.update(3);
        assert_eq!(game.world().resource::<DockHidden>().0, hidden, "{size}");
        if hidden {
            // Measured, with a card open and the dock shown: less than half.
            let said = game.world().resource::<StatusMessage>().0.clone();
            assert!(
                said.is_some_and(|said| said.contains("instruments")),
                "{size}"
            );
            game.world()
                .trigger(rubber_band_box::game::shared::Apply(DockHidden(false)));
            let mut cards = Cards::default();
            cards.set(Card::CONTROLS, true);
            *game.world().resource_mut::<Cards>() = cards;
            game.update(4);
            let viewport = game.world().resource::<SceneViewport>().0.unwrap();
            let measured = viewport.width() * viewport.height() / size.as_vec2().element_product();
            assert!(measured < LEAST_SCENE_SHARE, "{size}: {measured}");
            // The player's dock stays through a resize.
            game.resize(UVec2::new(300, 200));
            game.update(3);
            assert!(!game.world().resource::<DockHidden>().0, "{size}");
        }
    }
    for size in SIZES {
        println!(
            "{size}: {:.3}",
            scene_share_with_a_card_open(size.as_vec2())
        );
    }
    // Grown large, the dock the rule hid comes back.
    let mut game = Game::laid_out();
    game.resize(UVec2::new(320, 240));
    game.update(3);
    assert!(game.world().resource::<DockHidden>().0);
    game.resize(UVec2::new(1280, 800));
    game.update(3);
    assert!(!game.world().resource::<DockHidden>().0);
}

/// A link shared from a small window leaves out the dock the window's size hid: a desktop that
/// opens it shows its dock. The dock the player hid stays in it.
#[test]
fn a_link_from_a_small_window_leaves_its_hidden_dock_out() {
    use rubber_band_box::game::replays::links::ShareLink;
    use rubber_band_box::game::shared::StatusMessage;
    let said = |game: &mut Game| {
        game.world()
            .resource::<StatusMessage>()
            .0
            .clone()
            .unwrap_or_default()
    };
    let mut game = Game::laid_out();
    game.resize(UVec2::new(480, 320));
    game.update(3);
    assert!(game.world().resource::<DockHidden>().0);
    game.world().trigger(ShareLink { game: false });
    game.update(1);
    assert!(!said(&mut game).contains("dock=off"), "{}", said(&mut game));
    // H twice, a frame apart: shown, then hidden, by the player now.
    game.tap_key(KeyCode::KeyH);
    game.update(1);
    game.tap_key(KeyCode::KeyH);
    game.update(2);
    assert!(game.world().resource::<DockHidden>().0);
    game.world().trigger(ShareLink { game: false });
    game.update(1);
    assert!(said(&mut game).contains("dock=off"), "{}", said(&mut game));
}
