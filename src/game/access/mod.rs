//! Described to a screen reader (docs/accessibility.md): every control has a name and a role,
//! every slider its value and range, every text the player reads is a label, the scene is
//! described in words at a calm rate, and the screen reader's requests (press, focus, a
//! slider's step up or down) act as the keys do.
//!
//! Bevy keeps the tree in its `AccessibilityNode` components and hands it to AccessKit, which
//! speaks to the platform (Windows, macOS; Linux with `accesskit_unix`). In the browser, which
//! AccessKit cannot reach, the page reads the description from a live region (`web`).

pub mod describe;

use accesskit::{Action, Node as AccessNode, Role};
use bevy::a11y::{AccessibilityNode, ActionRequest};
use bevy::ecs::system::SystemParam;
use bevy::input_focus::InputFocus;
use bevy::input_focus::tab_navigation::{NavAction, TabNavigation};
use bevy::prelude::*;
use bevy::ui_widgets::{Activate, Button, SetSliderValue, Slider, SliderValueChange};

use crate::game::input::focus::Displayed;
use crate::game::input::focus::FocusControl;
use crate::game::layout::{CardButton, Cards, SceneCanvas};
use crate::game::schedule::ScreenSystems;
use crate::game::shared::StatusMessage;
use crate::game::simulation::{Band, Bodies};
use describe::{Seen, describe};

pub struct AccessPlugin;

impl Plugin for AccessPlugin {
    fn build(&self, app: &mut App) {
        app.add_message::<ActionRequest>()
            .init_resource::<SceneDescription>()
            .init_resource::<Page>()
            .add_systems(
                Update,
                (
                    answer_requests,
                    describe_the_scene,
                    contain_the_tree,
                    name_the_controls,
                    label_the_texts,
                    tell_the_page,
                )
                    .chain()
                    .in_set(ScreenSystems::Access),
            );
    }
}

/// The least real time between two descriptions, in seconds: a listener hears each out.
const CALM: f64 = 0.5;

/// The scene in words, as a screen reader hears it.
#[derive(Resource, Debug, Default, Clone, PartialEq)]
pub struct SceneDescription {
    pub said: String,
    /// When it last changed, in seconds of real time.
    pub at: f64,
    /// How many times it has changed.
    pub changes: u64,
}

/// Describes the scene when what a listener would hear has changed, at most every [`CALM`].
///
/// The description is the scene's node's (a live region), and in the browser the page's.
fn describe_the_scene(
    boxes: Bodies,
    bands: Query<&Band>,
    virtual_time: Res<Time<Virtual>>,
    real: Res<Time<Real>>,
    mut description: ResMut<SceneDescription>,
    mut scene: Query<&mut AccessibilityNode, With<SceneCanvas>>,
) {
    let Ok(body) = boxes.single() else {
        return;
    };
    let state = body.state();
    let band = bands
        .iter()
        .find(|band| band.body == body.entity)
        .map(|band| (band.ends.anchor, band.ends.attachment(&state)));
    let said = describe(&Seen {
        state,
        band,
        paused: virtual_time.is_paused(),
    });
    let now = real.elapsed_secs_f64();
    let first = description.changes == 0;
    if said == description.said || (!first && now - description.at < CALM) {
        return;
    }
    *description = SceneDescription {
        said,
        at: now,
        changes: description.changes + 1,
    };
    for mut node in &mut scene {
        node.set_description(description.said.clone());
    }
}

/// Leaves out of a name the glyphs a screen reader would spell: fold markers, bullets.
fn spoken(text: &str) -> String {
    text.chars()
        .filter(|c| !('\u{25a0}'..='\u{25ff}').contains(c))
        .collect::<String>()
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ")
}

/// The UI's tree as the names read it: texts under a node, and whether it shows.
#[derive(SystemParam)]
struct UiTree<'w, 's> {
    children: Query<'w, 's, &'static Children>,
    texts: Query<'w, 's, &'static Text>,
    spans: Query<'w, 's, &'static TextSpan>,
    parents: Query<'w, 's, &'static ChildOf>,
    displayed: Displayed<'w, 's>,
}

impl UiTree<'_, '_> {
    /// Returns the text of a node and its descendants, in order.
    fn text_under(&self, entity: Entity) -> String {
        let mut found = Vec::new();
        for node in std::iter::once(entity).chain(self.children.iter_descendants(entity)) {
            if let Ok(text) = self.texts.get(node) {
                found.push(text.0.clone());
            } else if let Ok(span) = self.spans.get(node) {
                found.push(span.0.clone());
            }
        }
        found.join(" ")
    }

    /// Returns a button's name: its text, with its row's title before a text of no word.
    ///
    /// The rate's "÷2" is said "rate ÷2", not as the time's is.
    fn button_name(&self, button: Entity) -> String {
        let own = spoken(&self.text_under(button));
        if own.chars().any(char::is_alphabetic) {
            return own;
        }
        let title = self
            .parents
            .get(button)
            .ok()
            .and_then(|row| self.children.get(row.parent()).ok())
            .and_then(|siblings| siblings.iter().find_map(|s| self.texts.get(s).ok()));
        match title {
            Some(title) => format!("{} {own}", spoken(&title.0)),
            None => own,
        }
    }

    /// Tells whether a node and every node above it are displayed.
    fn shown(&self, entity: Entity) -> bool {
        self.displayed.shown(entity)
    }

    /// Tells whether any node above `entity` is one of `among`.
    fn under<F: bevy::ecs::query::QueryFilter>(
        &self,
        entity: Entity,
        among: &Query<(), F>,
    ) -> bool {
        self.parents
            .iter_ancestors(entity)
            .any(|above| among.contains(above))
    }
}

/// Puts `wanted` in the node only if it differs.
///
/// So the tree handed to the screen reader changes only when what it says does.
fn set_if_changed(node: &mut Mut<AccessibilityNode>, wanted: &AccessNode) {
    if node.as_ref().0 != *wanted {
        node.0 = wanted.clone();
    }
}

/// The UI nodes holding others that have no node of the tree yet.
type Unnamed = (With<Node>, With<Children>, Without<AccessibilityNode>);

/// Gives every UI node that holds others a node of the tree, a container of no role.
///
/// Bevy hangs a node under its parent's node only if the parent has one, else under the
/// window: without these, a card's controls would be the window's, not the card's.
fn contain_the_tree(mut commands: Commands, containers: Query<Entity, Unnamed>) {
    for entity in &containers {
        commands
            .entity(entity)
            .insert(AccessibilityNode(AccessNode::new(Role::GenericContainer)));
    }
}

/// Names every button by its text, and hides every control and card not shown.
///
/// A card's title says whether the card is open; each control offers the screen reader's
/// actions it answers. A button given a name of its own (`AccessibleLabel`, a slider's) keeps it.
fn name_the_controls(
    mut buttons: Query<(Entity, &mut AccessibilityNode, Option<&CardButton>), With<Button>>,
    mut others: Query<(Entity, &mut AccessibilityNode, Has<Slider>), Without<Button>>,
    labels: Query<(), With<AccessibleLabel>>,
    cards: Res<Cards>,
    tree: UiTree,
) {
    for (entity, mut node, card) in &mut buttons {
        let mut wanted = node.as_ref().0.clone();
        wanted.set_role(Role::Button);
        if !labels.contains(entity) {
            wanted.set_label(tree.button_name(entity));
        }
        if let Some(CardButton(card)) = card {
            wanted.set_expanded(cards.is_open(*card));
        }
        hide_unless(&mut wanted, tree.shown(entity));
        wanted.add_action(Action::Click);
        wanted.add_action(Action::Focus);
        set_if_changed(&mut node, &wanted);
    }
    // The sliders, and the regions: a card the dock does not offer is hidden.
    for (entity, mut node, slider) in &mut others {
        let mut wanted = node.as_ref().0.clone();
        // A slider's own name (`AccessibleLabel`) brings a node of no role with it.
        if slider {
            wanted.set_role(Role::Slider);
        }
        match wanted.role() {
            Role::Slider => {
                for action in [Action::Increment, Action::Decrement, Action::Focus] {
                    wanted.add_action(action);
                }
            }
            Role::Group | Role::Canvas => {}
            _ => continue,
        }
        hide_unless(&mut wanted, tree.shown(entity));
        set_if_changed(&mut node, &wanted);
    }
}

fn hide_unless(node: &mut AccessNode, shown: bool) {
    if shown {
        node.clear_hidden();
    } else {
        node.set_hidden();
    }
}

/// The UI's texts.
type UiTexts = (With<Text>, With<Node>);

/// What [`label_the_texts`] leaves to a control: its text is the control's name.
type InControl = Or<(With<Button>, With<Slider>)>;

/// Marks every text the player reads as a label whose value is the text, hidden when it is.
fn label_the_texts(
    mut commands: Commands,
    mut texts: Query<(Entity, Option<&mut AccessibilityNode>), UiTexts>,
    controls: Query<(), InControl>,
    tree: UiTree,
) {
    for (entity, node) in &mut texts {
        if tree.under(entity, &controls) {
            continue;
        }
        let mut wanted = AccessNode::new(Role::Label);
        wanted.set_value(tree.text_under(entity));
        hide_unless(&mut wanted, tree.shown(entity));
        match node {
            Some(mut node) => set_if_changed(&mut node, &wanted),
            None => {
                commands
                    .entity(entity)
                    .insert((bevy::ui::widget::Label, AccessibilityNode(wanted)));
            }
        }
    }
}

/// Answers the screen reader's requests as the keys do.
///
/// It presses a button, focuses a control (its ring shown, as by Tab), steps a slider up or
/// down. What they send acts from the next frame.
fn answer_requests(
    mut requests: MessageReader<ActionRequest>,
    mut commands: Commands,
    buttons: Query<(), With<Button>>,
    sliders: Query<(), With<Slider>>,
) {
    for ActionRequest(request) in requests.read() {
        let Some(entity) = Entity::try_from_bits(request.target_node.0) else {
            continue;
        };
        match request.action {
            Action::Click if buttons.contains(entity) => {
                commands.trigger(Activate { entity });
            }
            Action::Increment | Action::Decrement if sliders.contains(entity) => {
                let steps = if request.action == Action::Increment {
                    1.0
                } else {
                    -1.0
                };
                commands.trigger(SetSliderValue {
                    entity,
                    change: SliderValueChange::RelativeStep(steps),
                });
            }
            Action::Focus if buttons.contains(entity) || sliders.contains(entity) => {
                commands.trigger(FocusControl(entity));
            }
            _ => {}
        }
    }
}

/// What the page around the web build is told, for a screen reader in the browser.
///
/// AccessKit cannot reach the browser (docs/accessibility.md). Kept natively too, where tests
/// read it.
#[derive(Resource, Debug, Default, Clone, PartialEq)]
pub struct Page {
    /// The live region's text: the scene's description, or the last action's result if newer.
    pub said: String,
    /// Every control shown, in reading order: its name and, for a slider, its value.
    pub controls: Vec<(String, String)>,
    /// The focused control's name, and whether Tab reaches it first or last.
    pub focus: Option<(String, bool, bool)>,
}

/// Tells the page what changed: the live region, the controls' list, the focus.
#[allow(clippy::too_many_arguments)]
fn tell_the_page(
    description: Res<SceneDescription>,
    status: Res<StatusMessage>,
    roots: Query<Entity, (With<Node>, Without<ChildOf>)>,
    children: Query<&Children>,
    controls: Query<&AccessibilityNode, InControl>,
    focus: Res<InputFocus>,
    navigation: TabNavigation,
    mut page: ResMut<Page>,
) {
    // The newer of the two is said: a change of the status line, or of the scene.
    if status.is_changed()
        && let Some(message) = &status.0
    {
        page.said = message.clone();
    } else if description.is_changed() {
        page.said = description.said.clone();
    }
    let mut shown = Vec::new();
    for root in &roots {
        for node in std::iter::once(root).chain(children.iter_descendants(root)) {
            if let Ok(control) = controls.get(node)
                && !control.is_hidden()
            {
                let name = control.label().unwrap_or_default().to_owned();
                shown.push((name, control.value().unwrap_or_default().to_owned()));
            }
        }
    }
    if page.controls != shown {
        page.controls = shown;
    }
    let focused = focus.get().and_then(|entity| {
        let name = controls.get(entity).ok()?.label()?.to_owned();
        let at = |end| navigation.navigate(&InputFocus::default(), end).ok() == Some(entity);
        Some((name, at(NavAction::First), at(NavAction::Last)))
    });
    if page.focus != focused {
        page.focus = focused;
    }
    #[cfg(target_arch = "wasm32")]
    if page.is_changed() {
        publish(&page);
    }
}

/// Hands the page what [`tell_the_page`] gathered.
#[cfg(target_arch = "wasm32")]
fn publish(page: &Page) {
    use crate::game::web;
    web::announce(&page.said);
    let controls: Vec<serde_json::Value> = page
        .controls
        .iter()
        .map(|(name, value)| serde_json::json!({ "name": name, "value": value }))
        .collect();
    web::publish_controls(&serde_json::Value::from(controls).to_string());
    let focus = page.focus.as_ref().map(
        |(name, first, last)| serde_json::json!({ "name": name, "first": first, "last": last }),
    );
    web::publish_focus(&serde_json::to_string(&focus).unwrap_or_default());
}
