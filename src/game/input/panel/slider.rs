//! The panel's sliders: one a scene parameter, on a logarithmic scale where the parameter
//! spans decades, its ends' values written under its track as the readout writes them, its
//! value sent as an [`Action::Set`] and moved back to the value in force.
//!
//! By keys, as on the web and in PhET's sims: Bevy's slider takes ← →, Home and End while
//! focused; this module adds ↑ ↓ (one step), PageUp and PageDown (ten steps), and Shift with any
//! of them for a tenth of a step. Its accessible value is the value as the readout writes it,
//! with its unit; its name is the parameter's.

use bevy::a11y::AccessibilityNode;
use bevy::input::ButtonState;
use bevy::input::keyboard::KeyboardInput;
use bevy::input_focus::FocusedInput;
use bevy::prelude::*;
use bevy::ui_widgets::{
    SetSliderValue, Slider, SliderRange, SliderStep, SliderThumb, SliderValue, SliderValueChange,
    TrackClick, ValueChange,
};

use crate::game::input::controls::{Action, Parameter};
use crate::game::theme::{self, colour, size};
use crate::physics::{
    ANGULAR_DAMPING_RANGE, LINEAR_DAMPING_RANGE, MASS_RANGE, SIZE_RANGE, STIFFNESS_RANGE,
    SceneParams,
};

/// A slider setting a scene parameter.
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
pub struct PanelSlider(pub Parameter);

/// The value at one end of a parameter's slider.
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
pub struct SliderEnd(pub Parameter);

const SLIDER_WIDTH: f32 = 150.0;

const THUMB_SIZE: f32 = 18.0;

/// The steps PageUp and PageDown move a slider by.
const COARSE_STEPS: f32 = 10.0;

/// The part of a step Shift moves a slider by.
const FINE_STEP: f32 = 0.1;

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
            // The slider's steps are tenths of a decade, a fine step a hundredth: 1e5, not
            // 99999.99, and three figures keep every fine step apart.
            let value = 10f64.powf(position);
            let digits = 10f64.powf(value.log10().floor() - 2.0);
            (value / digits).round() * digits
        } else {
            position
        }
    }
}

/// Spawns a parameter's slider in `row`, with its ends' values under its track.
pub(super) fn spawn_slider(commands: &mut Commands, row: Entity, parameter: Parameter) {
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
        AccessibleLabel::new(parameter.spoken()),
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
        BackgroundColor(colour::TRACK),
        ChildOf(column),
        children![(
            SliderThumb,
            Node {
                position_type: PositionType::Absolute,
                width: px(THUMB_SIZE),
                height: px(THUMB_SIZE),
                ..default()
            },
            BackgroundColor(colour::THUMB),
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
            TextColor(colour::DIM),
            ChildOf(ends),
        ));
    }
}

/// Sends the new value of a moved slider's parameter.
///
/// The slider shows the value in force after the controls have applied (or refused) it.
///
/// The slider takes the new position at once, so that a second key pressed in the same frame
/// steps on from it rather than from where the slider stood (two presses, two steps).
pub(super) fn move_slider(
    change: On<ValueChange<f32>>,
    sliders: Query<&PanelSlider>,
    mut actions: MessageWriter<Action>,
    mut commands: Commands,
) {
    if let Ok(PanelSlider(parameter)) = sliders.get(change.source) {
        actions.write(Action::Set(*parameter, parameter.value_at(change.value)));
        if change.value.is_finite() {
            commands
                .entity(change.source)
                .insert(SliderValue(change.value));
        }
    }
}

/// Places each slider's thumb where its value lies along the track.
pub(super) fn place_thumbs(
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

/// Moves each slider to the value in force (set by a key, a link or a refusal, not only by it).
pub(super) fn show_values(
    mut commands: Commands,
    params: Res<SceneParams>,
    mut sliders: Query<(Entity, &PanelSlider, &SliderValue, &mut AccessibilityNode)>,
) {
    for (entity, PanelSlider(parameter), value, mut node) in &mut sliders {
        // A screen reader says the value as the readout writes it, with its unit.
        let said = parameter.written(parameter.get(&params), Some(params.mass));
        if node.value() != Some(said.as_str()) {
            node.set_value(said);
        }
        let (start, end, _) = parameter.slider();
        let wanted = parameter
            .slider_position(parameter.get(&params))
            .clamp(start, end);
        // A NaN position is put back too.
        if value.0.is_nan() || (value.0 - wanted).abs() > 1e-4 {
            commands.entity(entity).insert(SliderValue(wanted));
        }
    }
}

/// Moves a focused slider by the keys Bevy's slider leaves: ↑ ↓, PageUp and PageDown.
pub(super) fn more_slider_keys(
    mut input: On<FocusedInput<KeyboardInput>>,
    sliders: Query<(), With<PanelSlider>>,
    mut commands: Commands,
) {
    let key = &input.input;
    if key.state != ButtonState::Pressed || !sliders.contains(input.focused_entity) {
        return;
    }
    let steps = match key.key_code {
        KeyCode::ArrowUp => 1.0,
        KeyCode::ArrowDown => -1.0,
        KeyCode::PageUp => COARSE_STEPS,
        KeyCode::PageDown => -COARSE_STEPS,
        _ => return,
    };
    input.propagate(false);
    commands.trigger(SetSliderValue {
        entity: input.focused_entity,
        change: SliderValueChange::RelativeStep(steps),
    });
}

/// Gives every slider its fine step while Shift is held, so that each key moves it a tenth.
///
/// It runs before Bevy hands the frame's keys to the focused control.
pub(super) fn fine_steps_with_shift(
    keys: Res<ButtonInput<KeyCode>>,
    mut commands: Commands,
    sliders: Query<(Entity, &PanelSlider, &SliderStep)>,
) {
    let fine = keys.any_pressed([KeyCode::ShiftLeft, KeyCode::ShiftRight]);
    for (entity, PanelSlider(parameter), step) in &sliders {
        let (_, _, whole) = parameter.slider();
        let wanted = if fine { whole * FINE_STEP } else { whole };
        if step.0 != wanted {
            commands.entity(entity).insert(SliderStep(wanted));
        }
    }
}
