//! The on-screen panel: every control a key has, for a mouse or a finger, built from Bevy's
//! own widgets (`bevy_ui_widgets`: buttons and sliders, reached through picking). Each button
//! sends the same [`Action`] its key sends and each slider an [`Action::Set`], so the panel
//! holds no state of its own beyond whether it is open: what it shows is read back from the
//! resources every frame. It is the dock's first card ([`Card::CONTROLS`]); the cards' titles
//! are buttons too, and fold their cards. It lies outside the scene's viewport, so a press on
//! it never grabs the box.

use bevy::ecs::system::SystemParam;
use bevy::prelude::*;
use bevy::ui::UiGlobalTransform;
use bevy::ui_widgets::{
    Activate, ActivateOnPress, Button, ButtonPlugin, Slider, SliderPlugin, SliderRange, SliderStep,
    SliderThumb, SliderValue, TrackClick, ValueChange,
};

use crate::game::input::controls::{Action, Parameter, help_line};
use crate::game::layout::{
    Card, CardButton, CardSpec, Cards, RegisterCard, Shape, Slot, Slots, card_line,
};
use crate::game::learn::ChapterButtons;
#[cfg(target_arch = "wasm32")]
use crate::game::schedule::AfterBevySystems;
use crate::game::schedule::{GameSystems, ScreenSystems};
use crate::game::shared::{DockHidden, Mode, Overlays, SceneName, hertz, times, window_rect};
use crate::game::theme::{self, colour, size, space};
use crate::physics::{
    ANGULAR_DAMPING_RANGE, Integrator, LINEAR_DAMPING_RANGE, MASS_RANGE, SIZE_RANGE,
    STIFFNESS_RANGE, Scene, SceneParams,
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
            .add_systems(Startup, spawn_panel)
            .add_systems(PostStartup, spawn_chapter_buttons)
            .add_systems(RunFixedMainLoop, tap_buttons.in_set(GameSystems::Input))
            .add_systems(
                Update,
                (show_state, place_thumbs)
                    .chain()
                    .in_set(ScreenSystems::Panel),
            );
        #[cfg(target_arch = "wasm32")]
        app.add_systems(
            PostUpdate,
            publish_buttons.in_set(AfterBevySystems::AfterLayout),
        );
    }
}

/// What a panel button does.
#[derive(Component, Debug, Clone, Copy, PartialEq)]
pub enum PanelButton {
    /// Fold or unfold a card of the dock (its title).
    Fold(Card),
    Send(Action),
}

/// A slider setting a scene parameter.
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
pub struct PanelSlider(pub Parameter);

/// The value at one end of a parameter's slider.
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
pub struct SliderEnd(pub Parameter);

/// A text showing a value the panel controls.
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
enum ValueText {
    Parameter(Parameter),
    StepRate,
    TimeScale,
}

const TEXT: Color = colour::TEXT;
const BUTTON: Color = colour::CARD_TITLE;
const LIT: Color = colour::LIT;
const BORDER: Color = colour::BORDER;
const TRACK: Color = colour::TRACK;
const THUMB: Color = colour::THUMB;
const DIM: Color = colour::DIM;
/// Big enough for a fingertip.
const BUTTON_HEIGHT: f32 = 30.0;
const SLIDER_WIDTH: f32 = 150.0;
const THUMB_SIZE: f32 = 18.0;

impl Parameter {
    /// Returns the slider's range and step.
    ///
    /// k, the mass and the size are on a logarithmic scale (log10 of the value), the damping
    /// rates on a linear one. Each spans the game's range for its parameter (`physics::scene`).
    fn slider(self) -> (f32, f32, f32) {
        let (range, step) = match self {
            Self::Stiffness => (STIFFNESS_RANGE, 0.1),
            Self::Mass => (MASS_RANGE, 0.1),
            Self::Size => (SIZE_RANGE, 0.05),
            Self::LinearDamping => (LINEAR_DAMPING_RANGE, 0.5),
            Self::AngularDamping => (ANGULAR_DAMPING_RANGE, 0.1),
        };
        let end = |value: f64| self.slider_position(value);
        (end(range.low), end(range.high), step)
    }

    /// Labels a slider's end as the readout shows the value.
    ///
    /// The linear damping is shown by its coefficient, whose rate depends on the mass.
    fn end_label(self, position: f32) -> String {
        self.written(self.value_at(position), None)
    }

    fn logarithmic(self) -> bool {
        matches!(self, Self::Stiffness | Self::Mass | Self::Size)
    }

    fn slider_position(self, value: f64) -> f32 {
        if self.logarithmic() {
            value.log10() as f32
        } else {
            value as f32
        }
    }

    fn value_at(self, position: f32) -> f64 {
        let position = f64::from(position);
        if self.logarithmic() {
            // The slider's steps are tenths of a decade: 1e5, not 99999.99.
            let value = 10f64.powf(position);
            let digits = 10f64.powf(value.log10().floor() - 1.0);
            (value / digits).round() * digits
        } else {
            position
        }
    }
}

fn text(value: impl Into<String>) -> impl Bundle {
    coloured_text(value, TEXT)
}

fn coloured_text(value: impl Into<String>, shade: Color) -> impl Bundle {
    (
        Text::new(value),
        theme::text_font(size::BODY),
        TextColor(shade),
    )
}

fn spawn_button(commands: &mut Commands, parent: Entity, label: &str, does: PanelButton) {
    commands.spawn((
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
    ));
}

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
fn spawn_chapter_buttons(mut commands: Commands, rows: Query<Entity, With<ChapterButtons>>) {
    for row in &rows {
        for (label, action) in [
            ("◂ back", Action::PreviousChapter),
            ("next ▸", Action::NextChapter),
            ("leave", Action::Learn),
        ] {
            spawn_button(&mut commands, row, label, PanelButton::Send(action));
        }
    }
}

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
    let body = commands
        .spawn((
            Name::new("Panel"),
            Node {
                flex_direction: FlexDirection::Column,
                padding: UiRect::all(px(space::PAD)),
                ..default()
            },
            BackgroundColor(colour::CARD),
            ChildOf(card),
        ))
        .id();

    let row = spawn_row(&mut commands, body, "");
    for (label, action) in [
        ("pause", Action::TogglePause),
        ("step", Action::Step),
        ("reset", Action::Reset),
        ("save", Action::Save),
        ("open", Action::Open),
        ("frame", Action::HomeView),
        ("learn", Action::Learn),
    ] {
        spawn_button(&mut commands, row, label, PanelButton::Send(action));
    }
    let row = spawn_row(&mut commands, body, "method");
    for integrator in Integrator::ALL {
        let does = PanelButton::Send(Action::Integrator(integrator));
        spawn_button(&mut commands, row, integrator.name(), does);
    }
    let row = spawn_row(&mut commands, body, "scene");
    for (index, name) in Scene::NAMES.iter().enumerate() {
        spawn_button(
            &mut commands,
            row,
            name,
            PanelButton::Send(Action::Scene(index)),
        );
    }
    for parameter in Parameter::ALL {
        let row = spawn_row(&mut commands, body, parameter.name());
        spawn_slider(&mut commands, row, parameter);
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
    for (title, readout, slower, faster) in [
        (
            "rate",
            ValueText::StepRate,
            Action::FewerSteps,
            Action::MoreSteps,
        ),
        ("time", ValueText::TimeScale, Action::Slower, Action::Faster),
    ] {
        let row = spawn_row(&mut commands, body, title);
        spawn_button(&mut commands, row, "÷2", PanelButton::Send(slower));
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
        spawn_button(&mut commands, row, "×2", PanelButton::Send(faster));
    }
    let row = spawn_row(&mut commands, body, "share");
    for (label, action) in [
        ("link", Action::ShareLink),
        ("game link", Action::ShareGame),
    ] {
        spawn_button(&mut commands, row, label, PanelButton::Send(action));
    }
    let row = spawn_row(&mut commands, body, "show");
    for (label, action) in [
        ("ghosts", Action::ToggleGhosts),
        ("plot", Action::TogglePlot),
        ("vectors", Action::ToggleVectors),
        ("trail", Action::ToggleTrail),
    ] {
        spawn_button(&mut commands, row, label, PanelButton::Send(action));
    }
    // Under the buttons, every key: the card is the panel's, whole.
    commands.spawn((
        Name::new("Keys"),
        KeysLine,
        card_line(help_line(), theme::text_font(size::CAPTION), DIM),
        ChildOf(card),
    ));
}

/// The Controls card's line of every key and what it does (`controls::help_line`).
#[derive(Component, Debug)]
struct KeysLine;

fn spawn_slider(commands: &mut Commands, row: Entity, parameter: Parameter) {
    let (start, end, step) = parameter.slider();
    // The track with its ends' values under it, in the readout's units.
    let column = commands
        .spawn((
            Node {
                flex_direction: FlexDirection::Column,
                margin: UiRect::vertical(px(3)),
                ..default()
            },
            ChildOf(row),
        ))
        .id();
    commands.spawn((
        Name::new(format!("Slider {}", parameter.name())),
        Slider {
            track_click: TrackClick::Snap,
            ..default()
        },
        SliderRange::new(start, end),
        SliderStep(step),
        PanelSlider(parameter),
        Node {
            width: px(SLIDER_WIDTH),
            height: px(THUMB_SIZE),
            ..default()
        },
        BackgroundColor(TRACK),
        ChildOf(column),
        children![(
            SliderThumb,
            Node {
                position_type: PositionType::Absolute,
                width: px(THUMB_SIZE),
                height: px(THUMB_SIZE),
                ..default()
            },
            BackgroundColor(THUMB),
        )],
    ));
    let ends = commands
        .spawn((
            Node {
                width: px(SLIDER_WIDTH),
                justify_content: JustifyContent::SpaceBetween,
                ..default()
            },
            ChildOf(column),
        ))
        .id();
    for position in [start, end] {
        commands.spawn((
            SliderEnd(parameter),
            Text::new(parameter.end_label(position)),
            theme::figures_font(size::CAPTION),
            TextColor(DIM),
            ChildOf(ends),
        ));
    }
}

fn press(does: PanelButton, cards: &mut Cards, shape: Shape, actions: &mut MessageWriter<Action>) {
    match does {
        PanelButton::Fold(card) => cards.toggle(card, shape),
        PanelButton::Send(action) => {
            actions.write(action);
        }
    }
}

/// Returns the window's shape, for a card's title to fold as the dock is laid out.
fn shape(windows: &Query<&Window, With<bevy::window::PrimaryWindow>>) -> Shape {
    windows
        .iter()
        .next()
        .map_or(Shape::Wide, |window| Shape::of(window.size()))
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
fn press_button(
    activate: On<Activate>,
    buttons: Query<(Option<&PanelButton>, Option<&CardButton>)>,
    touches: Res<Touches>,
    windows: Query<&Window, With<bevy::window::PrimaryWindow>>,
    mut cards: ResMut<Cards>,
    mut actions: MessageWriter<Action>,
) {
    let fingers = touches.iter().next().is_some() || touches.any_just_released();
    if let Ok((panel, card)) = buttons.get(activate.entity)
        && let Some(what) = does(panel, card)
        && !fingers
    {
        press(what, &mut cards, shape(&windows), &mut actions);
    }
}

/// Presses the button a finger taps, read from the touches.
///
/// In the browser, picking misses a new finger's first press (its pointer has no hover yet when
/// the press is dispatched), so taps go through here.
fn tap_buttons(
    touches: Res<Touches>,
    ui_scale: Res<UiScale>,
    buttons: Query<(
        Option<&PanelButton>,
        Option<&CardButton>,
        &ComputedNode,
        &UiGlobalTransform,
    )>,
    windows: Query<&Window, With<bevy::window::PrimaryWindow>>,
    mut cards: ResMut<Cards>,
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
            press(what, &mut cards, shape(&windows), &mut actions);
        }
    }
}

/// Sends the new value of a moved slider's parameter.
///
/// The slider shows the value in force after the controls have applied (or refused) it.
fn move_slider(
    change: On<ValueChange<f32>>,
    sliders: Query<&PanelSlider>,
    mut actions: MessageWriter<Action>,
) {
    if let Ok(PanelSlider(parameter)) = sliders.get(change.source) {
        actions.write(Action::Set(*parameter, parameter.value_at(change.value)));
    }
}

/// What the panel shows: the settings, the overlays, the mode and the clocks.
#[derive(SystemParam)]
struct Shown<'w> {
    params: Res<'w, SceneParams>,
    integrator: Res<'w, Integrator>,
    scene: Res<'w, SceneName>,
    overlays: Res<'w, Overlays>,
    dock_hidden: Res<'w, DockHidden>,
    mode: Res<'w, State<Mode>>,
    virtual_time: Res<'w, Time<Virtual>>,
    fixed_time: Res<'w, Time<Fixed>>,
}

/// Shows what the resources say: the panel open or folded, which buttons are lit, the values.
fn show_state(
    mut commands: Commands,
    shown: Shown,
    mut buttons: Query<(&PanelButton, &mut BackgroundColor, &Children)>,
    mut texts: Query<&mut Text>,
    mut readouts: Query<(&ValueText, Entity)>,
    sliders: Query<(Entity, &PanelSlider, &SliderValue)>,
) {
    let Shown {
        params,
        integrator,
        scene,
        overlays,
        dock_hidden,
        mode,
        virtual_time,
        fixed_time,
    } = shown;
    let paused = virtual_time.is_paused();
    for (button, mut background, children) in &mut buttons {
        let (lit, label) = match *button {
            PanelButton::Fold(_) => (false, None),
            PanelButton::Send(Action::TogglePause) => {
                (paused, Some(if paused { "resume" } else { "pause" }))
            }
            PanelButton::Send(Action::Integrator(method)) => (method == *integrator, None),
            PanelButton::Send(Action::Scene(index)) => {
                (Scene::NAMES.get(index) == Some(&scene.0.as_str()), None)
            }
            PanelButton::Send(Action::ToggleGhosts) => (overlays.ghosts, None),
            PanelButton::Send(Action::TogglePlot) => (overlays.plot, None),
            PanelButton::Send(Action::ToggleVectors) => (overlays.vectors, None),
            PanelButton::Send(Action::ToggleTrail) => (overlays.trail, None),
            PanelButton::Send(Action::ToggleDock) => (!dock_hidden.0, None),
            PanelButton::Send(Action::Learn) => (*mode.get() == Mode::Learn, None),
            PanelButton::Send(_) => (false, None),
        };
        background.set_if_neq(BackgroundColor(if lit { LIT } else { BUTTON }));
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
            ValueText::StepRate => hertz(1.0 / fixed_time.timestep().as_secs_f64()),
            ValueText::TimeScale => times(virtual_time.relative_speed_f64()),
        };
        if let Ok(mut text) = texts.get_mut(entity)
            && text.0 != shown
        {
            text.0 = shown;
        }
    }
    for (entity, PanelSlider(parameter), value) in &sliders {
        let (start, end, _) = parameter.slider();
        let wanted = parameter
            .slider_position(parameter.get(&params))
            .clamp(start, end);
        if (value.0 - wanted).abs() > 1e-4 {
            commands.entity(entity).insert(SliderValue(wanted));
        }
    }
}

/// Places each slider's thumb where its value lies along the track.
fn place_thumbs(
    sliders: Query<(&SliderValue, &SliderRange, &Children), Changed<SliderValue>>,
    mut thumbs: Query<&mut Node, With<SliderThumb>>,
) {
    for (value, range, children) in &sliders {
        for &child in children {
            if let Ok(mut node) = thumbs.get_mut(child) {
                let fraction = (value.0 - range.start()) / range.span().max(f32::EPSILON);
                node.left = px(fraction.clamp(0.0, 1.0) * (SLIDER_WIDTH - THUMB_SIZE));
            }
        }
    }
}

/// Publishes where each button lies, for the page (and the browser test) to read.
///
/// In the browser only.
#[cfg(target_arch = "wasm32")]
fn publish_buttons(
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
