//! The window's regions, not overlays: the scene's viewport (the largest region at every size)
//! between a status line above and a one-line hint below, and the dock of instrument cards:
//! at the side of a wide window, as a bottom sheet of a tall one (a phone held upright).
//!
//! The cards (the panel's controls, the readouts, the energy, the ghosts' table, the plot,
//! the stability line) fold; on the side, any number is open and the dock is a strip of
//! titles when all are folded; on a tall window the titles are tabs and one card at a time is
//! open. Nothing here draws over the scene: the viewport is a node of the layout, and
//! [`SceneViewport`] says where Bevy's layout put it, for the camera to render the scene
//! into and the pointer to map through.
//!
//! The plugins that fill the regions find them by their `Slot`; this module spawns the
//! frame in `PreStartup`, they spawn their content in `Startup`. The cards' registry and which
//! are open are [`cards`], the window's shape [`shape`], the dock's scrolling [`scroll`], the
//! dock hidden on a small window [`small`], and what the window shows, for the checks and the
//! page, [`visible`].

pub mod cards;
pub mod scroll;
pub mod shape;
pub mod small;
pub mod visible;

use bevy::a11y::AccessibilityNode;
use bevy::ecs::system::SystemParam;
use bevy::picking::Pickable;
use bevy::prelude::*;
#[cfg(target_arch = "wasm32")]
use bevy::ui::CalculatedClip;
use bevy::ui::UiGlobalTransform;
use bevy::ui_widgets::{
    ActivateOnPress, Button, ControlOrientation, Scrollbar, ScrollbarPlugin, ScrollbarThumb,
};
use bevy::window::PrimaryWindow;

use crate::game::schedule::{AfterBevySystems, ScreenSystems};
use crate::game::shared::{DockHidden, Owns};
use crate::game::theme::{self, colour, size, space};
use cards::Offered;
pub use cards::{Card, CardButton, CardRegistry, CardSpec, Cards, RegisterCard};
pub use scroll::{DockCards, DockScrollbar};
use scroll::{scroll_the_dock, show_the_dock_scrollbar};
use shape::{SHEET_SHARE, dock_width};
pub use shape::{Shape, WINDOW_SIZE, ui_scale_for};
pub use visible::{shown_texts, visible_rect, window_rect};

pub struct LayoutPlugin;

impl Plugin for LayoutPlugin {
    fn build(&self, app: &mut App) {
        // `DefaultPlugins` bring it with the widgets feature; the headless game adds it.
        if !app.is_plugin_added::<ScrollbarPlugin>() {
            app.add_plugins(ScrollbarPlugin);
        }
        // The panel's sliders read it too (the UI plugin has it; the headless game does not).
        app.add_plugins(small::plugin)
            .init_resource::<UiScale>()
            .init_resource::<CardRegistry>()
            .init_resource::<Cards>()
            .owns::<Cards>()
            .add_observer(fold_card)
            .init_resource::<SceneViewport>()
            .add_systems(PreStartup, spawn_regions)
            .add_systems(
                Update,
                (
                    scale_ui_to_window,
                    open_cards_switched_on,
                    arrange,
                    scroll_the_dock,
                )
                    .chain()
                    .in_set(ScreenSystems::Arrange),
            )
            .add_systems(
                PostUpdate,
                (publish_viewport, show_the_dock_scrollbar).in_set(AfterBevySystems::AfterLayout),
            );
        #[cfg(target_arch = "wasm32")]
        app.add_systems(
            PostUpdate,
            // With the viewport this frame's layout gave, not the last frame's: a status line
            // that wraps moves the viewport down in the same frame.
            publish_texts
                .after(publish_viewport)
                .in_set(AfterBevySystems::AfterLayout),
        );
    }
}

/// Where the regions' content goes: the plugins that fill them find them by it.
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Slot {
    /// Over the scene, one line: what a player must always see.
    Status,
    /// At the status line's end: the switches that must stay in reach (the dock's own).
    StatusTools,
    /// Under the scene, one line: how to play.
    Hint,
    /// A card's body.
    Card(Card),
}

/// The regions' slots: where a plugin finds the place for its content.
#[derive(SystemParam)]
pub(crate) struct Slots<'w, 's> {
    slots: Query<'w, 's, (Entity, &'static Slot)>,
}

impl Slots<'_, '_> {
    /// Returns the slot's entity, if the layout has spawned it.
    pub fn find(&self, wanted: Slot) -> Option<Entity> {
        self.slots
            .iter()
            .find(|(_, slot)| **slot == wanted)
            .map(|(entity, _)| entity)
    }

    /// Returns the body of `card`, if the card registered and the layout spawned it.
    pub fn card_body(&self, card: Card) -> Option<Entity> {
        self.find(Slot::Card(card))
    }
}

/// Returns a line of text in a card's body: the cards' inset and background, taking no press.
///
/// The Readouts, Energy and Stability cards' lines and the panel's line of keys are all one.
pub(crate) fn card_line(text: impl Into<String>, font: TextFont, shade: Color) -> impl Bundle {
    (
        Text::new(text),
        font,
        TextColor(shade),
        Pickable::IGNORE,
        Node {
            padding: UiRect::axes(px(space::PAD + 2.0), px(1)),
            ..default()
        },
        BackgroundColor(colour::CARD),
    )
}

/// The node the scene is rendered into: the canvas a screen reader finds the scene by.
///
/// Not Bevy's `bevy::ui::widget::ViewportNode`, which renders a camera's image in a node: the
/// scene's camera renders into [`SceneViewport`]'s rectangle instead.
#[derive(Component, Debug)]
pub(crate) struct SceneCanvas;

/// The dock (the side column or the bottom sheet): its cards and their scrollbar.
#[derive(Component, Debug)]
pub struct Dock;

/// The root of every region.
#[derive(Component, Debug)]
struct Regions;

/// A card: its title and its body.
#[derive(Component, Debug, Clone, Copy)]
struct CardFrame(Card);

/// The row of tabs a tall window shows above the open card.
#[derive(Component, Debug)]
struct Tabs;

/// Where the scene is rendered, in logical window pixels (origin at the top left).
///
/// Bevy's layout last placed the viewport node there; it is `None` before the first layout (and in
/// the headless game, which has none: the scene then has the whole window).
#[derive(Resource, Debug, Default, Clone, Copy, PartialEq)]
pub struct SceneViewport(pub Option<Rect>);

/// Builds a card's title button: the same widget in the side column and as a tab.
fn title_button(card: Card, title: &'static str) -> impl Bundle {
    (
        Name::new(format!("Card title {title}")),
        Button,
        ActivateOnPress,
        CardButton(card),
        Node {
            min_height: px(28),
            padding: UiRect::axes(px(space::PAD + 2.0), px(4)),
            align_items: AlignItems::Center,
            ..default()
        },
        BackgroundColor(colour::CARD_TITLE),
        children![(
            Text::new(title),
            theme::text_font(size::TITLE),
            TextColor(colour::TEXT),
            Pickable::IGNORE,
        )],
    )
}

/// Returns the scene's node as a screen reader finds it: a canvas named for what it shows.
///
/// Its description (the scene in words, `access`) is a polite live region.
fn scene_node() -> AccessibilityNode {
    let mut node = accesskit::Node::new(accesskit::Role::Canvas);
    node.set_label("The scene: a box pulled by a rubber band");
    node.set_live(accesskit::Live::Polite);
    AccessibilityNode(node)
}

/// Returns the status line as a screen reader finds it: the window's status bar.
///
/// Its text (the HUD's) is read when the listener asks for the status bar; not a live region,
/// since its clock changes ten times a simulated second.
fn status_node() -> AccessibilityNode {
    let mut node = accesskit::Node::new(accesskit::Role::Status);
    node.set_label("Status");
    AccessibilityNode(node)
}

/// Returns the hint line as a screen reader finds it: a polite live region.
///
/// Its text (the HUD's: how to play, or the latest news) is said when it changes, as the page's
/// live region says it in the browser.
fn news_node() -> AccessibilityNode {
    let mut node = accesskit::Node::new(accesskit::Role::GenericContainer);
    node.set_live(accesskit::Live::Polite);
    AccessibilityNode(node)
}

/// Returns a card as a screen reader finds it: a group named by its title.
fn card_node(title: &str) -> AccessibilityNode {
    let mut node = accesskit::Node::new(accesskit::Role::Group);
    node.set_label(title);
    AccessibilityNode(node)
}

/// Spawns the window's regions: the scene's column (status bar, viewport, hint) and the dock.
///
/// The dock holds the tabs (a tall window's row of card titles) and each registered card's
/// frame, title and empty body, which its plugin fills in `Startup`.
fn spawn_regions(mut commands: Commands, registry: Res<CardRegistry>) {
    let root = commands.spawn(regions()).id();
    commands.spawn((scene_column(), ChildOf(root)));
    let holder = commands.spawn((dock_holder(), ChildOf(root))).id();
    let dock = commands.spawn((dock_cards(), ChildOf(holder))).id();
    commands.spawn((dock_scrollbar(dock), ChildOf(holder)));
    let tabs = commands.spawn((tabs(), ChildOf(dock))).id();
    for &CardSpec { card, title, .. } in &registry.0 {
        commands.spawn((title_button(card, title), ChildOf(tabs)));
        commands.spawn((card_frame(card, title), ChildOf(dock)));
    }
}

/// Returns the window's root: the scene's column and the dock side by side.
fn regions() -> impl Bundle {
    (
        Name::new("Regions"),
        Regions,
        Pickable::IGNORE,
        Node {
            width: percent(100),
            height: percent(100),
            flex_direction: FlexDirection::Row,
            ..default()
        },
    )
}

/// Returns the scene's column: the status bar, the scene's viewport and the hint under it.
fn scene_column() -> impl Bundle {
    (
        Name::new("Scene column"),
        Pickable::IGNORE,
        Node {
            flex_grow: 1.0,
            flex_shrink: 1.0,
            flex_basis: px(0),
            min_width: px(0),
            min_height: px(0),
            flex_direction: FlexDirection::Column,
            ..default()
        },
        children![
            status_bar(),
            scene_viewport(),
            (
                bar("Hint line", Slot::Hint, Overflow::clip_x()),
                news_node()
            ),
        ],
    )
}

/// Returns a line of text over or under the scene, for the plugin that fills `slot`.
fn bar(name: &'static str, slot: Slot, overflow: Overflow) -> impl Bundle {
    (
        Name::new(name),
        slot,
        Pickable::IGNORE,
        Node {
            padding: UiRect::axes(px(space::PAD + 2.0), px(3)),
            column_gap: px(space::PAD * 2.0),
            flex_wrap: FlexWrap::Wrap,
            align_items: AlignItems::Center,
            overflow,
            ..default()
        },
        BackgroundColor(colour::CARD),
    )
}

/// Returns the status bar: the status line, and the tools at its end.
fn status_bar() -> impl Bundle {
    (
        Name::new("Status bar"),
        Pickable::IGNORE,
        Node {
            justify_content: JustifyContent::SpaceBetween,
            align_items: AlignItems::Center,
            ..default()
        },
        BackgroundColor(colour::CARD),
        children![
            (
                bar("Status line", Slot::Status, Overflow::DEFAULT),
                status_node(),
            ),
            (
                Name::new("Status tools"),
                Slot::StatusTools,
                Node {
                    flex_shrink: 0.0,
                    ..default()
                },
            ),
        ],
    )
}

/// Returns the scene's viewport, where the scene's camera renders (so it has no background).
fn scene_viewport() -> impl Bundle {
    (
        Name::new("Scene viewport"),
        SceneCanvas,
        scene_node(),
        Pickable::IGNORE,
        Node {
            flex_grow: 1.0,
            flex_basis: px(0),
            min_height: px(0),
            ..default()
        },
    )
}

/// Returns the dock's holder: the cards' column and its scrollbar.
fn dock_holder() -> impl Bundle {
    (
        Name::new("Dock"),
        Dock,
        Node {
            flex_direction: FlexDirection::Row,
            flex_shrink: 0.0,
            ..default()
        },
    )
}

/// Returns the cards' column, which scrolls.
///
/// The scrollbar takes the cards' right padding: the cards keep the width they had.
fn dock_cards() -> impl Bundle {
    (
        Name::new("Dock cards"),
        DockCards,
        Node {
            flex_direction: FlexDirection::Column,
            flex_grow: 1.0,
            flex_shrink: 1.0,
            min_width: px(0),
            min_height: px(0),
            overflow: Overflow::scroll_y(),
            row_gap: px(space::GAP),
            padding: UiRect {
                right: px(0),
                ..UiRect::all(px(space::GAP))
            },
            ..default()
        },
    )
}

/// Returns the scrollbar of the cards' column `dock`.
fn dock_scrollbar(dock: Entity) -> impl Bundle {
    (
        Name::new("Dock scrollbar"),
        DockScrollbar,
        Scrollbar::new(dock, ControlOrientation::Vertical, 24.0),
        Node {
            width: px(space::GAP),
            flex_shrink: 0.0,
            ..default()
        },
        BackgroundColor(Color::NONE),
        children![(
            ScrollbarThumb {
                border_radius: BorderRadius::all(px(space::GAP / 2.0)),
                border: UiRect::DEFAULT,
            },
            BackgroundColor(Color::NONE),
        )],
    )
}

/// Returns the row of card titles a tall window shows above the open card (hidden at first).
fn tabs() -> impl Bundle {
    (
        Name::new("Tabs"),
        Tabs,
        Node {
            display: Display::None,
            flex_wrap: FlexWrap::Wrap,
            column_gap: px(2),
            row_gap: px(2),
            flex_shrink: 0.0,
            ..default()
        },
    )
}

/// Returns a card's frame: its title, a button that folds it, and its body, hidden until open.
///
/// The card has no background of its own: a chart in it is drawn under the UI, seen where no
/// node of the card paints.
fn card_frame(card: Card, title: &'static str) -> impl Bundle {
    (
        Name::new(format!("Card {title}")),
        CardFrame(card),
        card_node(title),
        Node {
            flex_direction: FlexDirection::Column,
            flex_shrink: 0.0,
            ..default()
        },
        children![
            title_button(card, title),
            (
                Name::new(format!("Card body {title}")),
                Slot::Card(card),
                Node {
                    display: Display::None,
                    flex_direction: FlexDirection::Column,
                    flex_shrink: 0.0,
                    ..default()
                },
            ),
        ],
    )
}

fn scale_ui_to_window(windows: Query<&Window, With<PrimaryWindow>>, mut scale: ResMut<UiScale>) {
    for window in &windows {
        let fit = ui_scale_for(window.size());
        if scale.0 != fit {
            scale.0 = fit;
        }
    }
}

/// Arranges the regions for the window's shape and shows the cards, folded or open.
///
/// Each card is folded or open as [`Cards`] and the overlays say. Writes only what changed.
#[allow(clippy::type_complexity)]
fn arrange(
    windows: Query<&Window, With<PrimaryWindow>>,
    cards: Res<Cards>,
    offered: Offered,
    dock_hidden: Res<DockHidden>,
    mut nodes: ParamSet<(
        Query<&mut Node, With<Regions>>,
        Query<&mut Node, With<Dock>>,
        Query<&mut Node, With<Tabs>>,
        Query<(&CardFrame, &mut Node)>,
        Query<(&Slot, &mut Node)>,
        Query<(&CardButton, &ChildOf, &mut BackgroundColor, &mut Node)>,
    )>,
    tabs: Query<(), With<Tabs>>,
) {
    let window = windows
        .iter()
        .next()
        .map_or(WINDOW_SIZE.as_vec2(), Window::size);
    let shape = Shape::of(window);
    let offers = offered.now();
    let scale = ui_scale_for(window);
    let dock_hidden = dock_hidden.0;
    let any_open = offers
        .registry
        .cards()
        .any(|card| cards.body_shows(card, shape, &offers));
    // Folded, a wide window's dock is a strip of titles; open, a share of the window.
    let open_width = if any_open {
        px(dock_width(window.x / scale))
    } else {
        Val::Auto
    };
    for mut node in &mut nodes.p0() {
        set(&mut node, |n| {
            n.flex_direction = match shape {
                Shape::Wide => FlexDirection::Row,
                Shape::Tall => FlexDirection::Column,
            };
        });
    }
    for mut node in &mut nodes.p1() {
        set(&mut node, |n| {
            size_the_dock(n, shape, dock_hidden, open_width)
        });
    }
    for mut node in &mut nodes.p2() {
        show_node(&mut node, shape == Shape::Tall);
    }
    for (CardFrame(card), mut node) in &mut nodes.p3() {
        let shown = offers.offers(*card)
            && (shape == Shape::Wide || cards.body_shows(*card, shape, &offers));
        show_node(&mut node, shown);
    }
    for (slot, mut node) in &mut nodes.p4() {
        if let Slot::Card(card) = slot {
            let shows = cards.body_shows(*card, shape, &offers);
            show_node(&mut node, shows);
        }
    }
    for (CardButton(card), parent, mut background, mut node) in &mut nodes.p5() {
        let in_tabs = tabs.contains(parent.parent());
        // A tall window's card shows under its tab, without its own title.
        let shown = offers.offers(*card) && (in_tabs || shape == Shape::Wide);
        show_node(&mut node, shown);
        let lit = cards.body_shows(*card, shape, &offers);
        background.set_if_neq(BackgroundColor(if lit {
            colour::LIT
        } else {
            colour::CARD_TITLE
        }));
    }
}

/// Changes a node as `wanted` does, writing it only if that changes it.
fn set(node: &mut Mut<Node>, wanted: impl Fn(&mut Node)) {
    let mut next = (**node).clone();
    wanted(&mut next);
    if **node != next {
        **node = next;
    }
}

/// Shows a node or takes it out of the layout, writing it only if that changes it.
pub(crate) fn show_node(node: &mut Mut<Node>, shown: bool) {
    let display = if shown { Display::Flex } else { Display::None };
    if node.display != display {
        node.display = display;
    }
}

/// Sizes the dock: beside the scene on a wide window, a sheet under it on a tall one.
fn size_the_dock(node: &mut Node, shape: Shape, hidden: bool, open_width: Val) {
    node.display = if hidden { Display::None } else { Display::Flex };
    match shape {
        Shape::Wide => {
            node.width = open_width;
            node.height = percent(100);
            node.max_height = Val::Auto;
        }
        Shape::Tall => {
            node.width = percent(100);
            node.height = Val::Auto;
            node.max_height = percent(SHEET_SHARE * 100.0);
        }
    }
}

/// Opens a card that comes into the dock.
///
/// The ghosts' table comes with G, the plot with P, learn mode's card with the mode. It opens
/// as a tall window shows it: alone. Before the first frame the dock offers what it offers in
/// play with no overlay on, so a game that starts with one on opens its card.
fn open_cards_switched_on(
    offered: Offered,
    windows: Query<&Window, With<PrimaryWindow>>,
    mut cards: ResMut<Cards>,
    mut before: Local<Option<Vec<Card>>>,
) {
    let now = offered.now().offered();
    let before = before.get_or_insert_with(|| offered.at_start());
    if now == *before {
        return;
    }
    let shape = windows
        .iter()
        .next()
        .map_or(Shape::Wide, |window| Shape::of(window.size()));
    for &card in &now {
        if !before.contains(&card) && !cards.is_open(card) {
            cards.toggle(card, shape);
        }
    }
    *before = now;
}

/// Fold a card, or open it (a click on its title).
///
/// On a tall window, where one card shows at a time, an open card folds and a folded one opens
/// alone.
#[derive(Event, Debug, Clone, Copy, PartialEq, Eq)]
pub struct FoldCard(pub Card);

/// Folds or opens the card asked, as the window's shape has it.
fn fold_card(
    fold: On<FoldCard>,
    windows: Query<&Window, With<PrimaryWindow>>,
    mut cards: ResMut<Cards>,
) {
    let shape = windows
        .iter()
        .next()
        .map_or(Shape::Wide, |window| Shape::of(window.size()));
    cards.toggle(fold.0, shape);
}

/// Publishes where Bevy's layout put the viewport node.
fn publish_viewport(
    nodes: Query<(&ComputedNode, &UiGlobalTransform), With<SceneCanvas>>,
    ui_scale: Res<UiScale>,
    mut viewport: ResMut<SceneViewport>,
) {
    let Some(rect) = nodes
        .iter()
        .map(|(node, transform)| window_rect(node, transform, &ui_scale))
        .next()
    else {
        return;
    };
    // No layout yet (or none at all, headless): nothing to say.
    let placed = (!rect.is_empty()).then_some(rect);
    if placed.is_some() && viewport.0 != placed {
        viewport.0 = placed;
    }
}

/// Publishes the viewport and every text shown, for the page (and the browser test).
///
/// In the browser only.
#[cfg(target_arch = "wasm32")]
fn publish_texts(
    texts: Query<(
        &Text,
        &ComputedNode,
        &UiGlobalTransform,
        Option<&CalculatedClip>,
    )>,
    ui_scale: Res<UiScale>,
    viewport: Res<SceneViewport>,
    mut published: Local<String>,
) {
    let shown: Vec<serde_json::Value> = shown_texts(&texts, &ui_scale)
        .into_iter()
        .map(|(text, rect)| {
            serde_json::json!({
                "text": text,
                "rect": [rect.min.x, rect.min.y, rect.width(), rect.height()],
            })
        })
        .collect();
    let json = serde_json::to_string(&shown).unwrap_or_default();
    if *published != json {
        crate::game::web::publish_texts(&json);
        *published = json;
    }
    if viewport.is_changed()
        && let Some(rect) = viewport.0
    {
        crate::game::web::publish_viewport(rect.min.x, rect.min.y, rect.width(), rect.height());
    }
}
