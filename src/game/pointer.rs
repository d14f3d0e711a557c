//! The pointer plugin: the left mouse button, one finger, or the keyboard holds the band.
//!
//! Three systems run before the fixed loop each frame, in [`GameSystems::Input`], so that a
//! press is felt by the very next fixed step: `read_pointer` turns mouse, touch and focus
//! input into [`PointerAction`]s in world coordinates (through the camera's frame,
//! [`CameraFrame::anchor_at`]), `read_keyboard` does the same for the keyboard's cursor
//! ([`KeyCursor`]: the arrows move it, `BAND_KEY` grabs and lets go), and `drive_band`
//! spawns, moves and despawns the band entity from them. Tests can drive either end. The
//! plugin owns the grip (which device holds the band) and lets go on a reset.
//!
//! What happens at the edges:
//! - press and release within one frame (a quick click or tap): the band acts for exactly one
//!   fixed step, then is removed (by `remove_taps`), so no click is lost;
//! - the pointer leaves the scene while held (over the dock, the status line, the bottom
//!   sheet): the anchor stops at the viewport's edge, and never goes past the camera's reach,
//!   so the box held still stays in the home frame;
//! - the cursor leaves the window while held: the anchor stays where the cursor was last seen
//!   and follows again when it comes back;
//! - the window loses focus: the band is released (the button's release may never arrive);
//! - a second press while a band exists (a missed release, or the mouse taking over from a
//!   finger): the old band goes and a new one attaches at the corner nearest the new press;
//!   a second finger while the first holds the band is ignored. There is never more than one band;
//! - the keyboard's cursor stays on the scene's viewport, and its anchor keeps the camera's reach
//!   as the mouse's does; a focused slider takes the arrows for itself, so they move the cursor
//!   only while the scene (or a button) has the focus.
//!
//! [`CameraFrame::anchor_at`]: crate::game::camera::CameraFrame::anchor_at

use bevy::ecs::system::SystemParam;
use bevy::input::ButtonState;
use bevy::input::keyboard::KeyboardInput;
use bevy::math::DVec2;
use bevy::prelude::*;
use bevy::window::WindowFocused;

use crate::game::camera::{CameraFrame, SceneView, viewport_rect, world_per_pixel};
use crate::game::schedule::{GameSystems, PhysicsSystems};
use crate::game::shared::FocusedKeys;
use crate::game::simulation::{Band, Bodies, ResetScene, Tap};
use crate::physics::BandEnds;

pub struct PointerPlugin;

impl Plugin for PointerPlugin {
    fn build(&self, app: &mut App) {
        app.init_resource::<Grip>()
            .init_resource::<KeyCursor>()
            .add_message::<PointerAction>()
            .add_observer(let_go_on_reset)
            .add_systems(
                RunFixedMainLoop,
                (
                    (read_pointer, read_keyboard)
                        .chain()
                        .in_set(GameSystems::ReadPointer),
                    drive_band.in_set(GameSystems::Input),
                ),
            )
            .add_systems(FixedUpdate, remove_taps.in_set(PhysicsSystems::AfterStep));
    }
}

/// Removes a tap's band after the one step it acts for.
///
/// The removal is applied when the fixed step's schedule ends, before the next step.
fn remove_taps(mut commands: Commands, taps: Query<Entity, (With<Band>, With<Tap>)>) {
    for band in &taps {
        commands.entity(band).despawn();
    }
}

/// What the pointer did this frame, in world coordinates.
#[derive(Message, Debug, Clone, Copy, PartialEq)]
pub enum PointerAction {
    /// Grab the box's nearest corner with a band anchored here.
    Press(DVec2),
    /// Move the held band's anchor here.
    Move(DVec2),
    /// Let go of the band.
    Release,
}

/// Which device holds the band, if any.
#[derive(Resource, Debug, Default, Clone, Copy, PartialEq, Eq)]
pub struct Grip(pub Option<PointerSource>);

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PointerSource {
    Mouse,
    Touch(u64),
    /// The keyboard's cursor ([`KeyCursor`]).
    Keyboard,
}

/// The key that grabs the corner nearest the keyboard's cursor, and lets go.
pub(crate) const BAND_KEY: KeyCode = KeyCode::KeyB;

/// The keys that move the keyboard's cursor, and the way each moves it (y up).
const CURSOR_KEYS: [(KeyCode, Vec2); 4] = [
    (KeyCode::ArrowLeft, Vec2::NEG_X),
    (KeyCode::ArrowRight, Vec2::X),
    (KeyCode::ArrowUp, Vec2::Y),
    (KeyCode::ArrowDown, Vec2::NEG_Y),
];

/// How fast an arrow moves the keyboard's cursor, in logical pixels a second of real time.
const CURSOR_SPEED: f32 = 240.0;

/// The part of that speed with Shift held: a fine pull.
const CURSOR_SLOW: f32 = 0.2;

/// The keyboard's cursor on the scene: where the band key grabs and what the arrows move.
///
/// It lives in the window's logical pixels, as the mouse's cursor does, so that the anchor it
/// gives goes through the same frame, clamps and reach ([`CameraFrame::anchor_at`]).
#[derive(Resource, Debug, Default, Clone, Copy, PartialEq)]
pub struct KeyCursor {
    /// On the window; none until an arrow or the band key is first pressed.
    pub screen: Option<Vec2>,
    /// Where that lies in the world this frame, and how many world units a pixel spans there.
    pub world: Option<(DVec2, f32)>,
    /// Drawn: since the keyboard last moved it, until the mouse or a finger holds the band.
    pub shown: bool,
}

/// Reads mouse, touch and focus input into [`PointerAction`]s.
///
/// A press grabs only on the scene's viewport (the dock and its controls lie outside it); a
/// held band follows anywhere, its anchor clamped to the viewport and the camera's reach.
fn read_pointer(
    buttons: Res<ButtonInput<MouseButton>>,
    touches: Res<Touches>,
    view: SceneView,
    mut focus: MessageReader<WindowFocused>,
    boxes: Bodies,
    mut grip: ResMut<Grip>,
    mut actions: MessageWriter<PointerAction>,
) {
    let SceneView {
        window,
        viewport,
        frame,
    } = view;
    let span = span(&boxes);
    let area = window
        .as_deref()
        .map(|window| viewport_rect(&viewport, window));
    let to_world = |screen: Vec2| anchor_at(&frame, area, span, screen);
    // Before any layout (and in the headless game) the scene has the whole window.
    let on_scene = |screen: Vec2| viewport.0.is_none_or(|viewport| viewport.contains(screen));
    if focus.read().any(|event| !event.focused) && grip.0.is_some() {
        grip.0 = None;
        actions.write(PointerAction::Release);
    }

    // The mouse. A press and a release seen in the same frame happened in the order that
    // leaves the button in its current state.
    let on_screen = window
        .as_deref()
        .and_then(|window| window.cursor_position());
    let cursor = on_screen.and_then(to_world);
    // A press off the scene (on the dock's controls) is not the band's.
    let off_scene = !on_screen.is_some_and(on_scene);
    let (pressed, released, held) = (
        buttons.just_pressed(MouseButton::Left),
        buttons.just_released(MouseButton::Left),
        buttons.pressed(MouseButton::Left),
    );
    if released && held {
        release(&mut grip, &mut actions, PointerSource::Mouse);
    }
    if pressed
        && !off_scene
        && let Some(at) = cursor
    {
        grip.0 = Some(PointerSource::Mouse);
        actions.write(PointerAction::Press(at));
    }
    if grip.0 == Some(PointerSource::Mouse)
        && !pressed
        && let Some(at) = cursor
    {
        actions.write(PointerAction::Move(at));
    }
    if released && !held {
        release(&mut grip, &mut actions, PointerSource::Mouse);
    }

    // One finger: the first to touch holds the band until it lifts.
    for touch in touches.iter_just_pressed() {
        if grip.0.is_none()
            && on_scene(touch.position())
            && let Some(at) = to_world(touch.position())
        {
            grip.0 = Some(PointerSource::Touch(touch.id()));
            actions.write(PointerAction::Press(at));
        }
    }
    if let Some(PointerSource::Touch(id)) = grip.0
        && let Some(touch) = touches.get_pressed(id)
        && !touches.just_pressed(id)
        && let Some(at) = to_world(touch.position())
    {
        actions.write(PointerAction::Move(at));
    }
    for touch in touches
        .iter_just_released()
        .chain(touches.iter_just_canceled())
    {
        release(&mut grip, &mut actions, PointerSource::Touch(touch.id()));
    }
}

/// Returns the box's diagonal: how far past its corner a box held still may lie.
fn span(boxes: &Bodies) -> f32 {
    boxes
        .iter()
        .map(|body| body.mass.size().length() as f32)
        .fold(0.0, f32::max)
}

/// Returns the anchor a point of the window gives: on the scene's viewport, in the camera's reach.
fn anchor_at(frame: &CameraFrame, area: Option<Rect>, span: f32, screen: Vec2) -> Option<DVec2> {
    let area = area.filter(|area| area.size().min_element() > 0.0)?;
    let world = frame.anchor_at(area, span, screen);
    world.is_finite().then_some(world)
}

/// The arrows held for the keyboard's cursor, and the frame's time they move it for.
#[derive(SystemParam)]
struct Arrows<'w, 's> {
    held: Res<'w, ButtonInput<KeyCode>>,
    time: Res<'w, Time<Real>>,
    focused: FocusedKeys<'w, 's>,
}

impl Arrows<'_, '_> {
    /// Returns the way the arrows point (y up) and the move they make on the window this frame.
    ///
    /// An arrow a focused slider takes moves the slider, not the cursor.
    fn step(&self) -> (Vec2, Vec2) {
        let direction: Vec2 = CURSOR_KEYS
            .iter()
            .filter(|(key, _)| self.held.pressed(*key) && !self.focused.takes(*key))
            .map(|(_, way)| *way)
            .sum();
        let slow = self
            .held
            .any_pressed([KeyCode::ShiftLeft, KeyCode::ShiftRight]);
        let speed = CURSOR_SPEED * if slow { CURSOR_SLOW } else { 1.0 };
        // Window pixels run down the screen; the arrows say up.
        let step = direction * Vec2::new(1.0, -1.0) * speed * self.time.delta_secs();
        (direction, step)
    }
}

/// Reads the keyboard's band: the arrows move [`KeyCursor`], `BAND_KEY` grabs and lets go.
///
/// The cursor moves first, then each press of the band key acts where it has got to; a held
/// band follows the cursor every frame, as the mouse's follows the mouse. The band key takes
/// over a band the mouse or a finger holds.
fn read_keyboard(
    mut keys: MessageReader<KeyboardInput>,
    arrows: Arrows,
    view: SceneView,
    boxes: Bodies,
    mut cursor: ResMut<KeyCursor>,
    mut grip: ResMut<Grip>,
    mut actions: MessageWriter<PointerAction>,
) {
    let Some(window) = view.window.as_deref() else {
        return;
    };
    let area = viewport_rect(&view.viewport, window);
    let presses = keys
        .read()
        .filter(|key| key.state == ButtonState::Pressed && !key.repeat)
        .filter(|key| key.key_code == BAND_KEY)
        .count();
    // The mouse or a finger took the band: the cursor is put away until the keys move it.
    if grip
        .0
        .is_some_and(|source| source != PointerSource::Keyboard)
    {
        cursor.shown = false;
    }
    let (direction, step) = arrows.step();
    if direction == Vec2::ZERO && presses == 0 && cursor.screen.is_none() {
        return;
    }
    let screen = (cursor.screen.unwrap_or(area.center()) + step).clamp(area.min, area.max);
    cursor.screen = Some(screen);
    cursor.shown |= direction != Vec2::ZERO || presses > 0;
    let at = anchor_at(&view.frame, Some(area), span(&boxes), screen);
    cursor.world = at.map(|at| (at, world_per_pixel(&view.frame)));
    let Some(at) = at else {
        return;
    };
    for _ in 0..presses {
        if grip.0 == Some(PointerSource::Keyboard) {
            grip.0 = None;
            actions.write(PointerAction::Release);
        } else {
            grip.0 = Some(PointerSource::Keyboard);
            actions.write(PointerAction::Press(at));
        }
    }
    if grip.0 == Some(PointerSource::Keyboard) && presses == 0 {
        actions.write(PointerAction::Move(at));
    }
}

/// Lets go of the band if `source` holds it.
fn release(grip: &mut Grip, actions: &mut MessageWriter<PointerAction>, source: PointerSource) {
    if grip.0 == Some(source) {
        grip.0 = None;
        actions.write(PointerAction::Release);
    }
}

/// Lets go on a reset: no band, and no device holds one.
///
/// A button still down grabs again only with a new press.
fn let_go_on_reset(
    _reset: On<ResetScene>,
    mut commands: Commands,
    bands: Query<Entity, With<Band>>,
    mut grip: ResMut<Grip>,
) {
    for band in &bands {
        commands.entity(band).despawn();
    }
    grip.0 = None;
}

/// Drives the band entity from [`PointerAction`]s, spawning, moving and despawning it.
///
/// At most one band exists after this system.
fn drive_band(
    mut commands: Commands,
    mut actions: MessageReader<PointerAction>,
    boxes: Bodies,
    mut existing: Query<(Entity, &mut Band)>,
) {
    // Play this frame's actions on a small model first, then touch the world once, so that
    // several actions in one frame never leave two bands behind.
    // The band kept: taken away by a press (a new band replaces it) or a release.
    let mut existing_band = existing.iter().next().map(|(entity, band)| (entity, *band));
    let mut fresh: Option<Band> = None;
    let mut tap: Option<Band> = None;

    for action in actions.read() {
        match *action {
            PointerAction::Press(at) => {
                existing_band = None;
                let Ok(body) = boxes.single() else {
                    continue;
                };
                fresh = Some(Band {
                    body: body.entity,
                    ends: BandEnds::grabbing(body.mass, &body.state(), at),
                });
            }
            PointerAction::Move(to) => {
                if let Some(band) = fresh.as_mut() {
                    band.ends.anchor = to;
                } else if let Some((_, band)) = existing_band.as_mut() {
                    band.ends.anchor = to;
                }
            }
            PointerAction::Release => {
                if let Some(band) = fresh.take() {
                    tap = Some(band);
                } else {
                    existing_band = None;
                }
            }
        }
    }

    for (entity, mut band) in &mut existing {
        match existing_band {
            Some((kept, updated)) if kept == entity => {
                band.set_if_neq(updated);
            }
            _ => commands.entity(entity).despawn(),
        }
    }
    if let Some(band) = fresh {
        commands.spawn((Name::new("Band"), band));
    } else if let Some(band) = tap {
        commands.spawn((Name::new("Band (tap)"), band, Tap));
    }
}
