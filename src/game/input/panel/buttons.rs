//! The panel's buttons: each sends the [`Action`] its key sends, or folds a card (a card's title
//! is a button too), pressed by a click, by Enter while focused, or by a finger's tap, which
//! is read from the touches here since picking misses a new finger's first press.

use bevy::prelude::*;
use bevy::ui::UiGlobalTransform;
use bevy::ui_widgets::{Activate, ActivateOnPress, Button};

use crate::game::input::controls::Action;
use crate::game::layout::window_rect;
use crate::game::layout::{Card, CardButton, FoldCard};
use crate::game::theme::{self, colour, size};

/// What a panel button does.
#[derive(Component, Debug, Clone, Copy, PartialEq)]
pub enum PanelButton {
    /// Fold or unfold a card of the dock (its title).
    Fold(Card),
    Send(Action),
}

pub(super) const TEXT: Color = colour::TEXT;

pub(super) const BUTTON: Color = colour::CARD_TITLE;

pub(super) const LIT: Color = colour::LIT;

pub(super) const BORDER: Color = colour::BORDER;

/// Big enough for a fingertip.
const BUTTON_HEIGHT: f32 = 30.0;

/// Returns a text in the panel's face and colour.
pub(super) fn text(value: impl Into<String>) -> impl Bundle {
    coloured_text(value, TEXT)
}

/// Returns a text in the panel's face, in `shade`.
pub(super) fn coloured_text(value: impl Into<String>, shade: Color) -> impl Bundle {
    (
        Text::new(value),
        theme::text_font(size::BODY),
        TextColor(shade),
    )
}

/// Spawns a button labelled `label` in `parent` that does `does` when pressed.
pub(super) fn spawn_button(
    commands: &mut Commands,
    parent: Entity,
    label: &str,
    does: PanelButton,
) -> Entity {
    commands
        .spawn((
            Name::new(format!("Panel button {label}")),
            Button,
            // On the press, not the release: a quick tap (down and up in one frame) still counts.
            ActivateOnPress,
            does,
            Node {
                min_height: px(BUTTON_HEIGHT),
                padding: UiRect::axes(px(8), px(4)),
                margin: UiRect::all(px(2)),
                border: UiRect::all(px(1)),
                justify_content: JustifyContent::Center,
                align_items: AlignItems::Center,
                ..default()
            },
            BackgroundColor(BUTTON),
            BorderColor::all(BORDER),
            ChildOf(parent),
            children![text(label)],
        ))
        .id()
}

fn press(does: PanelButton, commands: &mut Commands, actions: &mut MessageWriter<Action>) {
    match does {
        // The layout folds it, as the window's shape has it.
        PanelButton::Fold(card) => commands.trigger(FoldCard(card)),
        PanelButton::Send(action) => {
            actions.write(action);
        }
    }
}

/// Returns what a button does: a panel button's own, or a card title's fold.
fn does(panel: Option<&PanelButton>, card: Option<&CardButton>) -> Option<PanelButton> {
    panel
        .copied()
        .or(card.map(|&CardButton(card)| PanelButton::Fold(card)))
}

/// Sends a pressed button's action (a click, or Enter while focused).
///
/// While a finger is on the screen, touches are [`tap_buttons`]'s.
pub(super) fn press_button(
    activate: On<Activate>,
    buttons: Query<(Option<&PanelButton>, Option<&CardButton>)>,
    touches: Res<Touches>,
    mut commands: Commands,
    mut actions: MessageWriter<Action>,
) {
    let fingers = touches.iter().next().is_some() || touches.any_just_released();
    if let Ok((panel, card)) = buttons.get(activate.entity)
        && let Some(what) = does(panel, card)
        && !fingers
    {
        press(what, &mut commands, &mut actions);
    }
}

/// Presses the button a finger taps, read from the touches.
///
/// In the browser, picking misses a new finger's first press (its pointer has no hover yet when
/// the press is dispatched), so taps go through here.
pub(super) fn tap_buttons(
    touches: Res<Touches>,
    ui_scale: Res<UiScale>,
    buttons: Query<(
        Option<&PanelButton>,
        Option<&CardButton>,
        &ComputedNode,
        &UiGlobalTransform,
    )>,
    mut commands: Commands,
    mut actions: MessageWriter<Action>,
) {
    for touch in touches.iter_just_pressed() {
        // A button not displayed has no size.
        let tapped = buttons.iter().find(|(panel, card, node, transform)| {
            let rect = window_rect(node, transform, &ui_scale);
            (panel.is_some() || card.is_some())
                && !rect.is_empty()
                && rect.contains(touch.position())
        });
        if let Some((panel, card, ..)) = tapped
            && let Some(what) = does(panel, card)
        {
            press(what, &mut commands, &mut actions);
        }
    }
}

/// Publishes where each button lies, for the page (and the browser test) to read.
///
/// In the browser only.
#[cfg(target_arch = "wasm32")]
pub(super) fn publish_buttons(
    buttons: Query<
        (&ComputedNode, &UiGlobalTransform, &Children),
        Or<(With<PanelButton>, With<CardButton>)>,
    >,
    ui_scale: Res<UiScale>,
    texts: Query<&Text>,
    mut published: Local<String>,
) {
    let mut places = std::collections::BTreeMap::new();
    for (node, transform, children) in &buttons {
        let Some(label) = children.first().and_then(|&child| texts.get(child).ok()) else {
            continue;
        };
        let rect = window_rect(node, transform, &ui_scale);
        // A card's title stands twice (as a tab and over its card): the one shown.
        if rect.is_empty() {
            continue;
        }
        places.entry(label.0.clone()).or_insert([
            rect.min.x,
            rect.min.y,
            rect.width(),
            rect.height(),
        ]);
    }
    let json = serde_json::to_string(&places).unwrap_or_default();
    if *published != json {
        crate::game::web::publish_panel(&json);
        *published = json;
    }
}
