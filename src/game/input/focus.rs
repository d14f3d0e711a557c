//! Keyboard focus (docs/controls.md): Tab and Shift+Tab move it through every button and slider
//! shown (the status line's, the cards' titles, the panel's, learn mode's), in reading order,
//! with Bevy's own tab navigation (`bevy_input_focus`); a ring shows the focused control when
//! focus came by keyboard; Escape gives focus back to the scene. A focused control takes its
//! own keys (a button Space and Enter, a slider the arrows, Home, End and the Page keys), and
//! the game's global keys do not fire for them
//! ([`FocusedKeys`](crate::game::shared::FocusedKeys)). A click keeps no keyboard focus. In the
//! browser, Tab into the canvas from the page starts at the first control, Shift+Tab at the last.

use bevy::ecs::system::SystemParam;
use bevy::input::ButtonState;
use bevy::input::keyboard::KeyboardInput;
use bevy::input_focus::tab_navigation::{TabGroup, TabIndex, TabNavigationPlugin};
use bevy::input_focus::{
    FocusCause, InputDispatchPlugin, InputFocus, InputFocusPlugin, InputFocusVisible,
};
use bevy::prelude::*;
use bevy::ui_widgets::{Button, Slider};
use bevy::window::PrimaryWindow;

use crate::game::schedule::{GameSystems, ScreenSystems};
use crate::game::shared::focused_control;
use crate::game::theme::colour;

pub struct FocusPlugin;

impl Plugin for FocusPlugin {
    fn build(&self, app: &mut App) {
        // `DefaultPlugins` bring the first two; the headless game adds them.
        if !app.is_plugin_added::<InputFocusPlugin>() {
            app.add_plugins(InputFocusPlugin);
        }
        if !app.is_plugin_added::<InputDispatchPlugin>() {
            app.add_plugins(InputDispatchPlugin);
        }
        app.add_plugins(TabNavigationPlugin)
            .add_observer(focus_control)
            .add_systems(Startup, group_the_ui_roots)
            .add_systems(
                RunFixedMainLoop,
                return_focus_to_the_scene.in_set(GameSystems::Input),
            )
            .add_systems(
                Update,
                (offer_what_is_shown, ring_the_focused)
                    .chain()
                    .in_set(ScreenSystems::Offer),
            );
        #[cfg(target_arch = "wasm32")]
        app.add_systems(
            RunFixedMainLoop,
            enter_from_the_page
                .after(return_focus_to_the_scene)
                .in_set(GameSystems::Input),
        );
    }
}

/// Makes every UI root a tab group: the status line's, the dock's.
fn group_the_ui_roots(
    mut commands: Commands,
    roots: Query<Entity, (With<Node>, Without<ChildOf>)>,
) {
    for root in &roots {
        commands.entity(root).insert(TabGroup::new(0));
    }
}

/// The controls focus may land on: Bevy's buttons and sliders.
type Controls = Or<(With<Button>, With<Slider>)>;

/// Offers focus to each button and slider shown, and to none hidden.
///
/// A folded card's controls and an unused answer's button are hidden.
fn offer_what_is_shown(
    mut commands: Commands,
    controls: Query<(Entity, Option<&TabIndex>), Controls>,
    displayed: Displayed,
) {
    for (entity, index) in &controls {
        let wanted = TabIndex(if displayed.shown(entity) { 0 } else { -1 });
        if index != Some(&wanted) {
            commands.entity(entity).insert(wanted);
        }
    }
}

/// Marks the node the ring is drawn on.
#[derive(Component, Debug)]
struct Ringed;

/// Draws a ring around the focused control while focus came by keyboard.
fn ring_the_focused(
    mut commands: Commands,
    focus: Res<InputFocus>,
    visible: Res<InputFocusVisible>,
    nodes: Query<(), With<Node>>,
    ringed: Query<Entity, With<Ringed>>,
) {
    let wanted = focus
        .get()
        .filter(|&entity| visible.0 && nodes.contains(entity));
    for entity in &ringed {
        if Some(entity) != wanted {
            commands.entity(entity).remove::<(Outline, Ringed)>();
        }
    }
    if let Some(entity) = wanted
        && !ringed.contains(entity)
    {
        commands
            .entity(entity)
            .insert((Outline::new(px(2), px(1), colour::FOCUS), Ringed));
    }
}

/// Gives focus back to the scene on Escape, and after a click on a control.
///
/// The scene's focus is no entity, not the window, so that Bevy hands AccessKit its tree.
///
/// A control clicked or tapped takes focus (Bevy's picking does it) but shows no ring; the keys
/// then stay the game's, as before focus existed: Space after a click on `rk4` pauses.
fn return_focus_to_the_scene(
    mut keys: MessageReader<KeyboardInput>,
    mut focus: ResMut<InputFocus>,
    mut visible: ResMut<InputFocusVisible>,
    window: Query<Entity, With<PrimaryWindow>>,
) {
    let window = window.single().ok();
    // The scene's focus is none: Bevy puts it on the window at start, and while it rests on an
    // entity with no accessibility node Bevy hands AccessKit no tree at all.
    if window.is_some() && focus.get() == window {
        focus.clear();
    }
    let escaped = keys
        .read()
        .any(|key| key.key_code == KeyCode::Escape && key.state == ButtonState::Pressed);
    if focused_control(&focus, window).is_some() && (escaped || !visible.0) {
        focus.clear();
        visible.0 = false;
    }
}

/// Focus a control, its ring shown as Tab shows it (a screen reader's request).
#[derive(Event, Debug, Clone, Copy, PartialEq, Eq)]
pub struct FocusControl(pub Entity);

/// Focuses the control asked, as Tab would reach it.
fn focus_control(
    asked: On<FocusControl>,
    mut focus: ResMut<InputFocus>,
    mut visible: ResMut<InputFocusVisible>,
) {
    focus.set(asked.0, FocusCause::Navigated);
    visible.0 = true;
}

/// Whether a UI node is displayed: it and every node above it (a folded card's are not).
#[derive(SystemParam)]
pub struct Displayed<'w, 's> {
    nodes: Query<'w, 's, &'static Node>,
    parents: Query<'w, 's, &'static ChildOf>,
}

impl Displayed<'_, '_> {
    /// Tells whether `entity` and every node above it are displayed.
    pub fn shown(&self, entity: Entity) -> bool {
        std::iter::once(entity)
            .chain(self.parents.iter_ancestors(entity))
            .all(|node| {
                self.nodes
                    .get(node)
                    .is_ok_and(|node| node.display != Display::None)
            })
    }
}

/// Focuses the game's first control as Tab enters the canvas from the page; Shift+Tab its last.
///
/// As a page's own Tab order does. In the browser only: the canvas is one stop in the page's
/// order (index.html lets Tab leave it from the game's last control).
#[cfg(target_arch = "wasm32")]
fn enter_from_the_page(
    navigation: bevy::input_focus::tab_navigation::TabNavigation,
    mut commands: Commands,
) {
    use bevy::input_focus::tab_navigation::NavAction;
    let Some(end) = crate::game::web::take_entered() else {
        return;
    };
    let action = if end == "last" {
        NavAction::Last
    } else {
        NavAction::First
    };
    if let Ok(control) = navigation.navigate(&InputFocus::default(), action) {
        commands.trigger(FocusControl(control));
    }
}
