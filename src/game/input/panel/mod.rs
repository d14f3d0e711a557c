//! The on-screen panel: every control a key has, for a mouse or a finger, built from Bevy's
//! own widgets (`bevy_ui_widgets`: buttons and sliders, reached through picking). Each button
//! sends the same [`Action`] its key sends and each slider an [`Action::Set`], so the panel
//! holds no state of its own beyond whether it is open: what it shows is read back from the
//! resources every frame. It is the dock's first card ([`Card::CONTROLS`]); the cards' titles
//! are buttons too, and fold their cards. It lies outside the scene's viewport, so a press on
//! it never grabs the box.
//!
//! Here the card and what it shows; its buttons and their touch dispatch in [`buttons`], its
//! sliders and their scales in [`slider`].

pub mod buttons;
pub mod slider;

use bevy::a11y::AccessibilityNode;
use bevy::ecs::system::SystemParam;
use bevy::prelude::*;
use bevy::ui_widgets::{ButtonPlugin, SliderPlugin};

use crate::game::input::controls::{Action, Parameter, help_line};
use crate::game::layout::{Card, CardSpec, RegisterCard, Slot, Slots, card_line};
use crate::game::learn::{
    CHOICES, ChapterButtons, ChoiceButton, ChoiceButtons, Learning, PointMassButton,
};
#[cfg(target_arch = "wasm32")]
use crate::game::schedule::AfterBevySystems;
use crate::game::schedule::{GameSystems, ScreenSystems};
use crate::game::shared::{DockHidden, Mode, Overlay, Overlays, SceneName};
use crate::game::simulation::Clocks;
use crate::game::theme::{self, colour, size, space};
use crate::game::theme::{hertz, times};
use crate::physics::{Integrator, Scene, SceneParams};
pub use buttons::PanelButton;
#[cfg(target_arch = "wasm32")]
use buttons::publish_buttons;
use buttons::{BUTTON, LIT, coloured_text, press_button, spawn_button, tap_buttons, text};
pub use slider::{PanelSlider, SliderEnd};
use slider::{
    fine_steps_with_shift, more_slider_keys, move_slider, place_thumbs, show_values, spawn_slider,
};

pub struct PanelPlugin;

impl Card {
    /// The panel: every control a key has.
    pub const CONTROLS: Card = Card("controls");
}

impl Plugin for PanelPlugin {
    fn build(&self, app: &mut App) {
        // `DefaultPlugins` bring them with the widgets feature; the headless game adds them.
        if !app.is_plugin_added::<ButtonPlugin>() {
            app.add_plugins(ButtonPlugin);
        }
        if !app.is_plugin_added::<SliderPlugin>() {
            app.add_plugins(SliderPlugin);
        }
        app.register_card(CardSpec::always(Card::CONTROLS, "Controls", 20))
            .add_observer(press_button)
            .add_observer(move_slider)
            .add_observer(more_slider_keys)
            .add_systems(
                PreUpdate,
                fine_steps_with_shift
                    .after(bevy::input::InputSystems)
                    .before(bevy::input_focus::InputFocusSystems::Dispatch),
            )
            .add_systems(Startup, spawn_panel)
            .add_systems(PostStartup, spawn_chapter_buttons)
            .add_systems(RunFixedMainLoop, tap_buttons.in_set(GameSystems::Input))
            .add_systems(
                Update,
                (show_state, show_values, place_thumbs)
                    .chain()
                    .in_set(ScreenSystems::Write)
                    .ambiguous_with(ScreenSystems::Write),
            );
        #[cfg(target_arch = "wasm32")]
        app.add_systems(
            PostUpdate,
            publish_buttons.in_set(AfterBevySystems::AfterLayout),
        );
    }
}

/// A text showing a value the panel controls.
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
enum ValueText {
    Parameter(Parameter),
    StepRate,
    TimeScale,
}

const DIM: Color = colour::DIM;

/// Spawns a titled row of widgets that wraps on a narrow screen.
fn spawn_row(commands: &mut Commands, parent: Entity, title: &str) -> Entity {
    let row = commands
        .spawn((
            Node {
                flex_direction: FlexDirection::Row,
                flex_wrap: FlexWrap::Wrap,
                align_items: AlignItems::Center,
                ..default()
            },
            ChildOf(parent),
        ))
        .id();
    if !title.is_empty() {
        commands.spawn((
            coloured_text(title, DIM),
            Node {
                width: px(64),
                ..default()
            },
            ChildOf(row),
        ));
    }
    row
}

/// Spawns learn mode's buttons where its card keeps them.
///
/// The card is spawned in `Startup`, so this runs in `PostStartup` to find it.
///
/// The answers' labels are the chapter's, written by learn mode, which also hides the unused.
fn spawn_chapter_buttons(
    mut commands: Commands,
    rows: Query<Entity, With<ChapterButtons>>,
    answers: Query<Entity, With<ChoiceButtons>>,
) {
    for row in &rows {
        for (label, action) in [
            ("◂ back", Action::PreviousChapter),
            ("↺ restart", Action::RestartChapter),
            ("next ▸", Action::NextChapter),
            ("leave", Action::Learn),
        ] {
            spawn_button(&mut commands, row, label, PanelButton::Send(action));
        }
        for (label, by) in [("n −", -1), ("n +", 1)] {
            let button = spawn_button(
                &mut commands,
                row,
                label,
                PanelButton::Send(Action::PointMasses(by)),
            );
            commands.entity(button).insert(PointMassButton);
        }
    }
    for row in &answers {
        for choice in 0..CHOICES {
            let does = PanelButton::Send(Action::Predict(choice));
            let button = spawn_button(&mut commands, row, "", does);
            commands.entity(button).insert(ChoiceButton(choice));
        }
    }
}

/// Spawns the Controls card's panel, row by row, and the dock's switch on the status line.
fn spawn_panel(mut commands: Commands, slots: Slots) {
    // The dock's own switch stands on the status line, where a finger finds it with the dock
    // hidden.
    if let Some(status) = slots.find(Slot::StatusTools) {
        spawn_button(
            &mut commands,
            status,
            "instruments",
            PanelButton::Send(Action::ToggleDock),
        );
    }
    let Some(card) = slots.card_body(Card::CONTROLS) else {
        return;
    };
    let body = commands.spawn((panel_body(), ChildOf(card))).id();
    let commands = &mut commands;
    spawn_buttons(
        commands,
        (body, ""),
        [
            ("pause", Action::TogglePause),
            ("step", Action::Step),
            ("reset", Action::Reset),
            ("save", Action::Save),
            ("open", Action::Open),
            ("frame", Action::HomeView),
            ("learn", Action::Learn),
        ],
    );
    let methods = Integrator::ALL.map(|method| (method.name(), Action::Integrator(method)));
    spawn_buttons(commands, (body, "method"), methods);
    let scenes = (0..Scene::NAMES.len()).map(|index| (Scene::NAMES[index], Action::Scene(index)));
    spawn_buttons(commands, (body, "scene"), scenes);
    for parameter in Parameter::ALL {
        spawn_slider_row(commands, body, parameter);
    }
    spawn_halve_and_double(
        commands,
        (body, "rate"),
        ValueText::StepRate,
        [Action::FewerSteps, Action::MoreSteps],
    );
    spawn_halve_and_double(
        commands,
        (body, "time"),
        ValueText::TimeScale,
        [Action::Slower, Action::Faster],
    );
    let share = [
        ("link", Action::ShareLink),
        ("game link", Action::ShareGame),
    ];
    spawn_buttons(commands, (body, "share"), share);
    let overlays = Overlay::ALL.map(|overlay| (overlay.name(), Action::Toggle(overlay)));
    spawn_buttons(commands, (body, "show"), overlays);
    // Under the buttons, every key: the card is the panel's, whole.
    commands.spawn((
        Name::new("Keys"),
        KeysLine,
        card_line(help_line(), theme::text_font(size::CAPTION), DIM),
        ChildOf(card),
    ));
}

/// Returns the panel's column of rows.
fn panel_body() -> impl Bundle {
    (
        Name::new("Panel"),
        Node {
            flex_direction: FlexDirection::Column,
            padding: UiRect::all(px(space::PAD)),
            ..default()
        },
        BackgroundColor(colour::CARD),
    )
}

/// Spawns a row of the panel, titled, with a button for each (label, action).
fn spawn_buttons<'a>(
    commands: &mut Commands,
    (body, title): (Entity, &str),
    buttons: impl IntoIterator<Item = (&'a str, Action)>,
) {
    let row = spawn_row(commands, body, title);
    for (label, action) in buttons {
        spawn_button(commands, row, label, PanelButton::Send(action));
    }
}

/// Spawns a parameter's row: its slider and the value it holds.
fn spawn_slider_row(commands: &mut Commands, body: Entity, parameter: Parameter) {
    let row = spawn_row(commands, body, parameter.name());
    spawn_slider(commands, row, parameter);
    commands.spawn((
        text(""),
        ValueText::Parameter(parameter),
        Node {
            margin: UiRect::left(px(8)),
            ..default()
        },
        ChildOf(row),
    ));
}

/// Spawns a row that halves and doubles a value, shown between its two buttons.
fn spawn_halve_and_double(
    commands: &mut Commands,
    (body, title): (Entity, &str),
    readout: ValueText,
    [halve, double]: [Action; 2],
) {
    let row = spawn_row(commands, body, title);
    spawn_button(commands, row, "÷2", PanelButton::Send(halve));
    commands.spawn((
        text(""),
        readout,
        Node {
            min_width: px(80),
            justify_content: JustifyContent::Center,
            ..default()
        },
        ChildOf(row),
    ));
    spawn_button(commands, row, "×2", PanelButton::Send(double));
}

/// The Controls card's line of every key and what it does (`controls::help_line`).
#[derive(Component, Debug)]
struct KeysLine;

/// What the panel shows: the settings, the overlays, the mode and the clocks.
#[derive(SystemParam)]
struct Shown<'w> {
    params: Res<'w, SceneParams>,
    integrator: Res<'w, Integrator>,
    scene: Res<'w, SceneName>,
    overlays: Res<'w, Overlays>,
    dock_hidden: Res<'w, DockHidden>,
    mode: Res<'w, State<Mode>>,
    clocks: Clocks<'w>,
    learning: Res<'w, Learning>,
}

/// What a lit button says: a switch is on, or a choice is the one chosen.
enum Lit {
    Switch,
    Choice,
}

impl PanelButton {
    /// Returns what this button's light means, if it has one.
    fn lit_is(&self) -> Option<Lit> {
        match self {
            Self::Send(Action::Toggle(_) | Action::ToggleDock | Action::Learn) => Some(Lit::Switch),
            Self::Send(Action::Integrator(_) | Action::Scene(_) | Action::Predict(_)) => {
                Some(Lit::Choice)
            }
            _ => None,
        }
    }
}

/// Shows what the resources say: the panel open or folded, which buttons are lit, the values.
fn show_state(
    shown: Shown,
    mut buttons: Query<(
        &PanelButton,
        &mut BackgroundColor,
        &Children,
        &mut AccessibilityNode,
    )>,
    mut texts: Query<&mut Text>,
    mut readouts: Query<(&ValueText, Entity)>,
) {
    let Shown {
        params,
        integrator,
        scene,
        overlays,
        dock_hidden,
        mode,
        clocks,
        learning,
    } = shown;
    let paused = clocks.paused();
    for (button, mut background, children, mut node) in &mut buttons {
        let (lit, label) = match *button {
            PanelButton::Fold(_) => (false, None),
            PanelButton::Send(Action::TogglePause) => {
                (paused, Some(if paused { "resume" } else { "pause" }))
            }
            PanelButton::Send(Action::Integrator(method)) => (method == *integrator, None),
            PanelButton::Send(Action::Scene(index)) => {
                (Scene::NAMES.get(index) == Some(&scene.0.as_str()), None)
            }
            PanelButton::Send(Action::Toggle(overlay)) => (overlays.on(overlay), None),
            PanelButton::Send(Action::ToggleDock) => (!dock_hidden.0, None),
            PanelButton::Send(Action::Learn) => (*mode.get() == Mode::Learn, None),
            PanelButton::Send(Action::Predict(choice)) => {
                (learning.predicted() == Some(choice), None)
            }
            PanelButton::Send(_) => (false, None),
        };
        background.set_if_neq(BackgroundColor(if lit { LIT } else { BUTTON }));
        // A screen reader hears the lit state: a switch on or off, a choice selected or not.
        match button.lit_is() {
            Some(Lit::Switch) if node.toggled() != Some(lit.into()) => {
                node.set_toggled(lit.into());
            }
            Some(Lit::Choice) if node.is_selected() != Some(lit) => node.set_selected(lit),
            _ => {}
        }
        if let Some(label) = label
            && let Some(&child) = children.first()
            && let Ok(mut text) = texts.get_mut(child)
            && text.0 != label
        {
            text.0 = label.to_owned();
        }
    }
    for (readout, entity) in &mut readouts {
        let shown = match readout {
            ValueText::Parameter(parameter) => {
                parameter.written(parameter.get(&params), Some(params.mass))
            }
            ValueText::StepRate => hertz(clocks.step_rate_hz()),
            ValueText::TimeScale => times(clocks.time_scale()),
        };
        if let Ok(mut text) = texts.get_mut(entity)
            && text.0 != shown
        {
            text.0 = shown;
        }
    }
}
