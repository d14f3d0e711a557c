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
//! frame in `PreStartup`, they spawn their content in `Startup`.

use bevy::ecs::system::ScheduleSystem;
use bevy::ecs::system::SystemParam;
use bevy::picking::Pickable;
use bevy::prelude::*;
use bevy::ui::{CalculatedClip, UiGlobalTransform};
use bevy::ui_widgets::{
    ActivateOnPress, Button, ControlOrientation, Scrollbar, ScrollbarPlugin, ScrollbarThumb,
};
use bevy::window::PrimaryWindow;

use crate::game::schedule::{AfterBevySystems, ScreenSystems};
use crate::game::shared::{DockHidden, Mode, Overlays, window_rect};
use crate::game::theme::{self, colour, size, space};

pub struct LayoutPlugin;

impl Plugin for LayoutPlugin {
    fn build(&self, app: &mut App) {
        // `DefaultPlugins` bring it with the widgets feature; the headless game adds it.
        if !app.is_plugin_added::<ScrollbarPlugin>() {
            app.add_plugins(ScrollbarPlugin);
        }
        // The panel's sliders read it too (the UI plugin has it; the headless game does not).
        app.init_resource::<UiScale>()
            .init_resource::<CardRegistry>()
            .init_resource::<Cards>()
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
                    .in_set(ScreenSystems::Scale),
            )
            .add_systems(
                PostUpdate,
                (publish_viewport, show_the_dock_scrollbar).in_set(AfterBevySystems::AfterLayout),
            );
        #[cfg(target_arch = "wasm32")]
        app.add_systems(
            PostUpdate,
            publish_texts.in_set(AfterBevySystems::AfterLayout),
        );
    }
}

/// Returns the part of a node the window shows: its rectangle, in logical pixels, cut to its clip.
///
/// The clip is that of a node above, such as the scrolled dock. `None` when the node has no
/// size (it, or a node above it, is not displayed) or is cut away.
pub fn visible_rect(
    node: &ComputedNode,
    transform: &UiGlobalTransform,
    clip: Option<&CalculatedClip>,
    ui_scale: &UiScale,
) -> Option<Rect> {
    clipped(window_rect(node, transform, ui_scale), node, clip, ui_scale)
}

/// Cuts `rect`, in logical pixels, to the node's clip; `None` if nothing is left.
fn clipped(
    mut rect: Rect,
    node: &ComputedNode,
    clip: Option<&CalculatedClip>,
    ui_scale: &UiScale,
) -> Option<Rect> {
    let scale = node.inverse_scale_factor() * ui_scale.0;
    if let Some(clip) = clip {
        let cut = Rect::from_corners(clip.clip.min * scale, clip.clip.max * scale);
        rect = rect.intersect(cut);
    }
    (rect.width() > 0.0 && rect.height() > 0.0).then_some(rect)
}

/// Returns where a text's glyphs may lie, in logical pixels.
///
/// They lie in its node's content box (inside its padding), cut to its clip.
fn visible_text_rect(
    node: &ComputedNode,
    transform: &UiGlobalTransform,
    clip: Option<&CalculatedClip>,
    ui_scale: &UiScale,
) -> Option<Rect> {
    let scale = node.inverse_scale_factor() * ui_scale.0;
    let content = node.content_box();
    let rect = Rect::from_corners(
        (transform.translation + content.min) * scale,
        (transform.translation + content.max) * scale,
    );
    clipped(rect, node, clip, ui_scale)
}

/// Lists every text the window shows and where, in logical pixels.
///
/// The layout's checks read it (no two meet, none on the scene, all in the window).
pub fn shown_texts(
    texts: &Query<(
        &Text,
        &ComputedNode,
        &UiGlobalTransform,
        Option<&CalculatedClip>,
    )>,
    ui_scale: &UiScale,
) -> Vec<(String, Rect)> {
    texts
        .iter()
        .filter(|(text, ..)| !text.0.trim().is_empty())
        .filter_map(|(text, node, transform, clip)| {
            visible_text_rect(node, transform, clip, ui_scale).map(|rect| (text.0.clone(), rect))
        })
        .collect()
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

/// The game's window when it opens, in logical pixels.
pub const WINDOW_SIZE: UVec2 = UVec2::new(960, 720);

/// An instrument card of the dock, named by the plugin that fills it.
///
/// Each card's own module names it (`Card::STABILITY` in `stability/`) and registers it with
/// the dock ([`RegisterCard::register_card`]); the dock keeps no list of its own.
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Card(pub &'static str);

/// A card as its plugin registers it: its name, its title, its place and when it is offered.
#[derive(Debug, Clone, Copy)]
pub struct CardSpec {
    pub card: Card,
    /// The title on its fold button and its tab.
    pub title: &'static str,
    /// Its place in the dock, top to bottom (a tall window's tabs, left to right).
    pub place: u8,
    /// Tells whether the card is in the dock now (the ghosts' table only with the ghosts on).
    pub offered: fn(&Overlays, Mode) -> bool,
}

impl CardSpec {
    /// Returns a card that is always in the dock.
    pub const fn always(card: Card, title: &'static str, place: u8) -> Self {
        Self {
            card,
            title,
            place,
            offered: |_, _| true,
        }
    }
}

/// Every card of the dock in its order: what the plugins registered.
///
/// The dock spawns a frame, a title and a body (`Slot::Card`) for each at start-up.
#[derive(Resource, Debug, Default)]
pub struct CardRegistry(Vec<CardSpec>);

impl CardRegistry {
    /// Returns the cards in the dock's order.
    pub fn cards(&self) -> impl Iterator<Item = Card> + '_ {
        self.0.iter().map(|spec| spec.card)
    }

    /// Tells whether `card` is in the dock now; an unregistered card never is.
    pub fn offers(&self, card: Card, overlays: &Overlays, mode: Mode) -> bool {
        self.0
            .iter()
            .any(|spec| spec.card == card && (spec.offered)(overlays, mode))
    }
}

/// Registers cards with the dock.
pub trait RegisterCard {
    /// Registers a card, in the place it asks; a second registration of a name is ignored.
    fn register_card(&mut self, spec: CardSpec) -> &mut Self;

    /// Registers a card that writes its own text, and its two systems.
    ///
    /// `spawn` fills its body at start-up, `write` writes it every frame, in
    /// `ScreenSystems::Cards`. The cards' writers run in any order among themselves: each writes only its own texts.
    fn add_text_card<S, W>(
        &mut self,
        spec: CardSpec,
        spawn: impl IntoScheduleConfigs<ScheduleSystem, S>,
        write: impl IntoScheduleConfigs<ScheduleSystem, W>,
    ) -> &mut Self;
}

impl RegisterCard for App {
    fn register_card(&mut self, spec: CardSpec) -> &mut Self {
        let mut registry = self.world_mut().get_resource_or_init::<CardRegistry>();
        if registry.0.iter().any(|known| known.card == spec.card) {
            warn!(
                "the card {:?} is registered twice: the second ignored",
                spec.card
            );
        } else {
            registry.0.push(spec);
            registry.0.sort_by_key(|known| known.place);
        }
        self
    }

    fn add_text_card<S, W>(
        &mut self,
        spec: CardSpec,
        spawn: impl IntoScheduleConfigs<ScheduleSystem, S>,
        write: impl IntoScheduleConfigs<ScheduleSystem, W>,
    ) -> &mut Self {
        self.register_card(spec)
            .add_systems(Startup, spawn)
            .add_systems(
                Update,
                write
                    .in_set(ScreenSystems::Cards)
                    .ambiguous_with(ScreenSystems::Cards),
            )
    }
}

/// What decides which cards the dock offers now, as a system reads it.
#[derive(SystemParam)]
struct Offered<'w> {
    registry: Res<'w, CardRegistry>,
    overlays: Res<'w, Overlays>,
    mode: Res<'w, State<Mode>>,
}

impl Offered<'_> {
    fn now(&self) -> Offers<'_> {
        Offers {
            registry: &self.registry,
            overlays: &self.overlays,
            mode: *self.mode.get(),
        }
    }
}

/// What decides which cards the dock offers now: the cards, the overlays and the mode.
#[derive(Clone, Copy)]
struct Offers<'a> {
    registry: &'a CardRegistry,
    overlays: &'a Overlays,
    mode: Mode,
}

impl Offers<'_> {
    fn offers(&self, card: Card) -> bool {
        self.registry.offers(card, self.overlays, self.mode)
    }

    /// Returns every card offered, in the dock's order.
    fn offered(&self) -> Vec<Card> {
        self.registry
            .cards()
            .filter(|&card| self.offers(card))
            .collect()
    }
}

/// Which cards are open, kept as the player left them while the game runs.
///
/// A tall window shows one at a time (the first open one).
#[derive(Resource, Debug, Clone, PartialEq, Eq, Default)]
pub struct Cards {
    open: std::collections::BTreeSet<Card>,
}

impl Cards {
    pub fn is_open(&self, card: Card) -> bool {
        self.open.contains(&card)
    }

    pub fn set(&mut self, card: Card, open: bool) {
        if open {
            self.open.insert(card);
        } else {
            self.open.remove(&card);
        }
    }

    /// Folds or unfolds `card`, as a press on its title does.
    ///
    /// On the side it folds or unfolds; on a tall window, where one card shows at a time, an open
    /// card folds and a folded one opens alone.
    pub fn toggle(&mut self, card: Card, shape: Shape) {
        let open = !self.is_open(card);
        if shape == Shape::Tall && open {
            self.open.clear();
        }
        self.set(card, open);
    }

    /// Returns the card a tall window shows: the first open one the dock offers.
    fn shown_alone(&self, offers: &Offers) -> Option<Card> {
        offers
            .registry
            .cards()
            .find(|&card| self.is_open(card) && offers.offers(card))
    }

    /// Tells whether the card's body shows.
    fn body_shows(&self, card: Card, shape: Shape, offers: &Offers) -> bool {
        match shape {
            Shape::Wide => self.is_open(card) && offers.offers(card),
            Shape::Tall => self.shown_alone(offers) == Some(card),
        }
    }
}

/// The window's shape: the dock at the side of a wide window, below the scene on a tall one.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shape {
    Wide,
    Tall,
}

impl Shape {
    pub fn of(window: Vec2) -> Self {
        if window.x >= window.y {
            Shape::Wide
        } else {
            Shape::Tall
        }
    }
}

/// Returns the dock's width at the side of a wide window, in logical pixels before the UI scale.
///
/// It takes a share of the window, with a floor (the plot's 300 px and the ghosts' table) and a
/// ceiling.
fn dock_width(window_width: f32) -> f32 {
    (window_width * 0.34).clamp(350.0, 460.0)
}

/// A tall window's sheet keeps the scene at least this share of the height.
const SHEET_SHARE: f32 = 0.45;

/// Returns the UI's scale for a window: 1 at the game's own size and above.
///
/// On a phone it is a little smaller, never so small that text cannot be read.
pub fn ui_scale_for(size: Vec2) -> f32 {
    (size.min_element() / WINDOW_SIZE.y as f32).clamp(0.85, 1.0)
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

/// A card's title: a button that folds it (the panel presses it, as its other buttons).
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
pub struct CardButton(pub Card);

/// The node the scene is rendered into.
#[derive(Component, Debug)]
struct ViewportNode;

/// The dock (the side column or the bottom sheet): its cards and their scrollbar.
#[derive(Component, Debug)]
pub struct Dock;

/// The dock's cards, in a column that scrolls when they are taller than the dock.
#[derive(Component, Debug)]
pub struct DockCards;

/// The dock's scrollbar: seen only while the cards overflow, a sign that there is more.
#[derive(Component, Debug)]
pub struct DockScrollbar;

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

fn spawn_regions(mut commands: Commands, registry: Res<CardRegistry>) {
    let root = commands
        .spawn((
            Name::new("Regions"),
            Regions,
            Pickable::IGNORE,
            Node {
                width: percent(100),
                height: percent(100),
                flex_direction: FlexDirection::Row,
                ..default()
            },
        ))
        .id();
    let scene = commands
        .spawn((
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
            ChildOf(root),
        ))
        .id();
    let bar = |name: &'static str, slot: Slot| {
        (
            Name::new(name),
            slot,
            Pickable::IGNORE,
            Node {
                padding: UiRect::axes(px(space::PAD + 2.0), px(3)),
                column_gap: px(space::PAD * 2.0),
                flex_wrap: FlexWrap::Wrap,
                align_items: AlignItems::Center,
                ..default()
            },
            BackgroundColor(colour::CARD),
        )
    };
    let status = commands
        .spawn((
            Name::new("Status bar"),
            Pickable::IGNORE,
            Node {
                justify_content: JustifyContent::SpaceBetween,
                align_items: AlignItems::Center,
                ..default()
            },
            BackgroundColor(colour::CARD),
            ChildOf(scene),
        ))
        .id();
    commands.spawn((bar("Status line", Slot::Status), ChildOf(status)));
    commands.spawn((
        Name::new("Status tools"),
        Slot::StatusTools,
        Node {
            flex_shrink: 0.0,
            ..default()
        },
        ChildOf(status),
    ));
    // No background: the scene's camera renders under it.
    commands.spawn((
        Name::new("Scene viewport"),
        ViewportNode,
        Pickable::IGNORE,
        Node {
            flex_grow: 1.0,
            flex_basis: px(0),
            min_height: px(0),
            ..default()
        },
        ChildOf(scene),
    ));
    let mut hint = bar("Hint line", Slot::Hint);
    hint.3.overflow = Overflow::clip_x();
    commands.spawn((hint, ChildOf(scene)));

    let holder = commands
        .spawn((
            Name::new("Dock"),
            Dock,
            Node {
                flex_direction: FlexDirection::Row,
                flex_shrink: 0.0,
                ..default()
            },
            ChildOf(root),
        ))
        .id();
    // The scrollbar takes the cards' right padding: the cards keep the width they had.
    let dock = commands
        .spawn((
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
            ChildOf(holder),
        ))
        .id();
    commands.spawn((
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
        ChildOf(holder),
    ));
    let tabs = commands
        .spawn((
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
            ChildOf(dock),
        ))
        .id();
    for &CardSpec { card, title, .. } in &registry.0 {
        commands.spawn((title_button(card, title), ChildOf(tabs)));
        // The card has no background of its own: a chart in it is drawn under the UI, seen
        // where no node of the card paints.
        let frame = commands
            .spawn((
                Name::new(format!("Card {title}")),
                CardFrame(card),
                Node {
                    flex_direction: FlexDirection::Column,
                    flex_shrink: 0.0,
                    ..default()
                },
                ChildOf(dock),
            ))
            .id();
        commands.spawn((title_button(card, title), ChildOf(frame)));
        commands.spawn((
            Name::new(format!("Card body {title}")),
            Slot::Card(card),
            Node {
                display: Display::None,
                flex_direction: FlexDirection::Column,
                flex_shrink: 0.0,
                ..default()
            },
            ChildOf(frame),
        ));
    }
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
    let set = |node: &mut Mut<Node>, wanted: &dyn Fn(&mut Node)| {
        let mut next = (**node).clone();
        wanted(&mut next);
        if **node != next {
            **node = next;
        }
    };
    for mut node in &mut nodes.p0() {
        set(&mut node, &|n| {
            n.flex_direction = match shape {
                Shape::Wide => FlexDirection::Row,
                Shape::Tall => FlexDirection::Column,
            };
        });
    }
    for mut node in &mut nodes.p1() {
        set(&mut node, &|n| {
            n.display = if dock_hidden {
                Display::None
            } else {
                Display::Flex
            };
            match shape {
                Shape::Wide => {
                    // Folded, a strip of titles; open, a share of the window.
                    n.width = if any_open {
                        px(dock_width(window.x / scale))
                    } else {
                        Val::Auto
                    };
                    n.height = percent(100);
                    n.max_height = Val::Auto;
                }
                Shape::Tall => {
                    n.width = percent(100);
                    n.height = Val::Auto;
                    n.max_height = percent(SHEET_SHARE * 100.0);
                }
            }
        });
    }
    for mut node in &mut nodes.p2() {
        set(&mut node, &|n| {
            n.display = match shape {
                Shape::Wide => Display::None,
                Shape::Tall => Display::Flex,
            };
        });
    }
    for (CardFrame(card), mut node) in &mut nodes.p3() {
        let shown = offers.offers(*card)
            && (shape == Shape::Wide || cards.body_shows(*card, shape, &offers));
        set(&mut node, &|n| {
            n.display = if shown { Display::Flex } else { Display::None };
        });
    }
    for (slot, mut node) in &mut nodes.p4() {
        if let Slot::Card(card) = slot {
            let shows = cards.body_shows(*card, shape, &offers);
            set(&mut node, &|n| {
                n.display = if shows { Display::Flex } else { Display::None };
            });
        }
    }
    for (CardButton(card), parent, mut background, mut node) in &mut nodes.p5() {
        let in_tabs = tabs.contains(parent.parent());
        // A tall window's card shows under its tab, without its own title.
        let shown = offers.offers(*card) && (in_tabs || shape == Shape::Wide);
        set(&mut node, &|n| {
            n.display = if shown { Display::Flex } else { Display::None };
        });
        let lit = cards.body_shows(*card, shape, &offers);
        background.set_if_neq(BackgroundColor(if lit {
            colour::LIT
        } else {
            colour::CARD_TITLE
        }));
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
    let before = before.get_or_insert_with(|| {
        Offers {
            registry: &offered.registry,
            overlays: &Overlays::default(),
            mode: Mode::Play,
        }
        .offered()
    });
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

/// Scrolls the dock with the wheel over it or a finger's drag that starts on it.
///
/// Over the scene the wheel zooms the view instead.
fn scroll_the_dock(
    mut wheel: MessageReader<bevy::input::mouse::MouseWheel>,
    touches: Res<Touches>,
    windows: Query<&Window, With<PrimaryWindow>>,
    ui_scale: Res<UiScale>,
    mut docks: Query<(&ComputedNode, &UiGlobalTransform, &mut ScrollPosition), With<DockCards>>,
) {
    let cursor = windows.iter().next().and_then(Window::cursor_position);
    for event in wheel.read() {
        let lines = match event.unit {
            bevy::input::mouse::MouseScrollUnit::Line => event.y * 24.0,
            bevy::input::mouse::MouseScrollUnit::Pixel => event.y,
        };
        for (node, transform, mut scroll) in &mut docks {
            let rect = window_rect(node, transform, &ui_scale);
            if cursor.is_some_and(|at| rect.contains(at)) {
                scroll.0.y = (scroll.0.y - lines).max(0.0);
            }
        }
    }
    for touch in touches.iter() {
        let moved = touch.delta().y;
        for (node, transform, mut scroll) in &mut docks {
            let rect = window_rect(node, transform, &ui_scale);
            if moved != 0.0 && rect.contains(touch.start_position()) {
                scroll.0.y = (scroll.0.y - moved / ui_scale.0).max(0.0);
            }
        }
    }
}

/// Shows the dock's scrollbar while its cards are taller than the dock, and hides it when not.
///
/// Only colours change: the bar keeps its width either way, so the layout never moves.
fn show_the_dock_scrollbar(
    cards: Query<&ComputedNode, With<DockCards>>,
    bars: Query<(&Children, Entity), With<DockScrollbar>>,
    mut colours: Query<&mut BackgroundColor>,
) {
    let Some(node) = cards.iter().next() else {
        return;
    };
    let (track, thumb) = if tells_overflow(node) {
        (colour::CARD, colour::DIM)
    } else {
        (Color::NONE, Color::NONE)
    };
    for (thumbs, bar) in &bars {
        if let Ok(mut background) = colours.get_mut(bar) {
            background.set_if_neq(BackgroundColor(track));
        }
        for thumb_entity in thumbs {
            if let Ok(mut background) = colours.get_mut(*thumb_entity) {
                background.set_if_neq(BackgroundColor(thumb));
            }
        }
    }
}

/// Tells whether a scrolled node's content is taller than the node (by more than a pixel).
fn tells_overflow(node: &ComputedNode) -> bool {
    let scale = node.inverse_scale_factor();
    (node.content_size().y - node.size().y) * scale > 1.0
}

/// Publishes where Bevy's layout put the viewport node.
fn publish_viewport(
    nodes: Query<(&ComputedNode, &UiGlobalTransform), With<ViewportNode>>,
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
