//! The resources several plugins of the game read, each initialised once, here
//! ([`SharedPlugin`], added first by the game): the scene's name, the status line, what
//! shows, the game's [`Mode`], and which keys a focused control takes ([`FocusedKeys`]). A leaf: it imports no plugin, so none of its readers
//! imports another for them.

use bevy::ecs::component::Mutable;
use bevy::ecs::system::SystemParam;
use bevy::input_focus::InputFocus;
use bevy::prelude::*;
use bevy::state::app::StatesPlugin;
use bevy::ui_widgets::Slider;
use bevy::window::PrimaryWindow;

/// Initialises the shared resources and the game's mode.
///
/// A replay given to `play` may have put `SceneName` in place already: it is kept.
pub struct SharedPlugin;

impl Plugin for SharedPlugin {
    fn build(&self, app: &mut App) {
        // `DefaultPlugins` bring it with the state feature; the headless game adds it.
        if !app.is_plugin_added::<StatesPlugin>() {
            app.add_plugins(StatesPlugin);
        }
        app.init_resource::<SceneName>()
            .init_resource::<Overlays>()
            .init_resource::<DockHidden>()
            .init_state::<Mode>()
            .owns::<SceneName>()
            .owns::<Overlays>()
            .owns::<DockHidden>();
    }
}

/// A part of the game's setup, sent to the plugin that owns it, which alone writes it.
///
/// A key, the panel, a link, a scene, a replay, a chapter and leaving learn mode all send the
/// settings they open this way; each owner applies its parts in its own observer (for a
/// resource held whole, [`Owns::owns`]). Triggered from a system's commands, it is applied at
/// that system's sync point, in the order sent.
#[derive(Event, Debug, Clone)]
pub struct Apply<P: Clone + Send + Sync + 'static>(pub P);

/// Makes a plugin the owner of a resource: the one writer, from the [`Apply`] sent for it.
pub trait Owns {
    /// Applies each `Apply<R>` sent by putting its value in the resource `R`.
    fn owns<R: Resource + Component<Mutability = Mutable> + Clone>(&mut self) -> &mut Self;
}

impl Owns for App {
    fn owns<R: Resource + Component<Mutability = Mutable> + Clone>(&mut self) -> &mut Self {
        self.add_observer(replace::<R>)
    }
}

/// Puts the value sent in the resource (marked changed, as an insert marks it).
fn replace<R: Resource + Component<Mutability = Mutable> + Clone>(
    apply: On<Apply<R>>,
    mut held: ResMut<R>,
) {
    *held = apply.0.clone();
}

/// What the game is doing: played freely, or walking the tutorial's chapters.
///
/// Learn mode keeps the game's setup as it enters and sends it back as it leaves; a system that
/// runs in one mode asks `in_state(Mode::Learn)`.
#[derive(States, Debug, Default, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Mode {
    #[default]
    Play,
    /// The tutorial's chapters, one at a time, in the dock's *Learn* card.
    Learn,
}

/// What the learn controls and links ask of learn mode (`game::learn` answers).
///
/// Shared, so that a link (under learn mode) can open a chapter.
#[derive(Event, Debug, Clone, Copy, PartialEq, Eq)]
pub enum Learn {
    /// Into learn mode at its first chapter, or out of it.
    Toggle,
    Next,
    Previous,
    /// This chapter (entering the mode if need be).
    Chapter(usize),
    /// This answer to the chapter's prediction.
    Predict(usize),
    /// More point masses across the box, or fewer (the moment of inertia's sum).
    PointMasses(i32),
}

/// The scene the game plays, which a recording's header names.
///
/// The tutorial's, a named scene loaded, or the one a replay opened was recorded in.
#[derive(Resource, Debug, Clone, PartialEq, Eq)]
pub struct SceneName(pub String);

impl Default for SceneName {
    fn default() -> Self {
        Self("tutorial".to_owned())
    }
}

pub use crate::replay::link::Overlay;

/// Which overlays show: the set of those switched on.
#[derive(Resource, Debug, Default, Clone, Copy, PartialEq, Eq)]
pub struct Overlays([bool; Overlay::ALL.len()]);

impl Overlays {
    /// Tells whether an overlay shows.
    pub fn on(&self, overlay: Overlay) -> bool {
        self.0[overlay.index()]
    }

    /// Switches an overlay on or off; the plot turns the ghosts on, its points being theirs.
    pub fn set(&mut self, overlay: Overlay, on: bool) {
        self.0[overlay.index()] = on;
        if overlay == Overlay::Plot && on {
            self.0[Overlay::Ghosts.index()] = true;
        }
    }

    /// Switches an overlay the other way.
    pub fn toggle(&mut self, overlay: Overlay) {
        self.set(overlay, !self.on(overlay));
    }
}

/// Whether the dock of cards is hidden (H; `dock=off` in a link): not an overlay, a region.
#[derive(Resource, Debug, Default, Clone, Copy, PartialEq, Eq)]
pub struct DockHidden(pub bool);

/// The latest thing the game has to tell the player: the HUD's, written only from [`Say`].
///
/// It may be a save, a replay opened or refused, or a value refused; the HUD's replay line shows it
/// until the next.
#[derive(Resource, Debug, Default, Clone, PartialEq)]
pub struct StatusMessage(pub Option<String>);

/// Something to tell the player on the status line, sent by whichever plugin has news.
///
/// The HUD owns what the status line says ([`StatusMessage`]); the latest said wins.
#[derive(Event, Debug, Clone, PartialEq)]
pub struct Say(pub String);

/// Returns where a UI node lies in the window, in logical pixels.
///
/// Logical pixels are what the pointer and the page use. It is the node's physical rectangle over
/// the window's scale factor; `ComputedNode`'s inverse scale factor also divides by the UI scale,
/// which is put back.
pub fn window_rect(node: &ComputedNode, transform: &UiGlobalTransform, ui_scale: &UiScale) -> Rect {
    let scale = node.inverse_scale_factor() * ui_scale.0;
    Rect::from_center_size(transform.translation * scale, node.size() * scale)
}

/// Writes a value as a person reads it, the one format the HUD and the panel share.
///
/// The value is written whole or to three significant digits in the usual range (20, 5, 2.02,
/// 0.05), in powers of ten beyond it (1.0e5, 3.2e-9).
pub fn readable(value: f64) -> String {
    let magnitude = value.abs();
    if value == 0.0 {
        "0".to_owned()
    } else if !value.is_finite() || !(1e-2..1e4).contains(&magnitude) {
        format!("{value:.1e}")
    } else {
        let decimals = (2 - magnitude.log10().floor() as i32).max(0) as usize;
        let text = format!("{value:.decimals$}");
        if text.contains('.') {
            text.trim_end_matches('0').trim_end_matches('.').to_owned()
        } else {
            text
        }
    }
}

/// Writes a rate in hertz as every readout shows it: `100 Hz`, `62.5 Hz`.
///
/// The HUD's clock, the status line and the panel all write it so.
pub fn hertz(rate: f64) -> String {
    format!("{} Hz", readable(rate))
}

/// Writes the time scale as every readout shows it: `×1`, `×0.25`.
pub fn times(scale: f64) -> String {
    format!("×{}", readable(scale))
}

/// The keys every focused control takes: they move the focus.
const FOCUS_KEYS: [KeyCode; 2] = [KeyCode::Tab, KeyCode::Escape];

/// The keys a focused button takes for itself: it is pressed.
const BUTTON_KEYS: [KeyCode; 3] = [KeyCode::Space, KeyCode::Enter, KeyCode::NumpadEnter];

/// The keys a focused slider takes for itself: they move it (`input::panel::slider`).
const SLIDER_KEYS: [KeyCode; 8] = [
    KeyCode::ArrowLeft,
    KeyCode::ArrowRight,
    KeyCode::ArrowUp,
    KeyCode::ArrowDown,
    KeyCode::Home,
    KeyCode::End,
    KeyCode::PageUp,
    KeyCode::PageDown,
];

/// Which keys the focused control takes for itself, rather than the game.
#[derive(SystemParam)]
pub struct FocusedKeys<'w, 's> {
    focus: Res<'w, InputFocus>,
    window: Query<'w, 's, Entity, With<PrimaryWindow>>,
    sliders: Query<'w, 's, (), With<Slider>>,
}

/// Returns the control that has the keyboard's focus, if one has (the window's is the scene's).
pub fn focused_control(focus: &InputFocus, window: Option<Entity>) -> Option<Entity> {
    focus.get().filter(|&entity| Some(entity) != window)
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

impl FocusedKeys<'_, '_> {
    /// Tells whether `key` goes to the focused control rather than the game.
    ///
    /// A button takes Space and Enter, a slider the arrows, Home, End and the Page keys; with
    /// the scene focused every key is the game's.
    pub fn takes(&self, key: KeyCode) -> bool {
        let Some(control) = focused_control(&self.focus, self.window.single().ok()) else {
            return false;
        };
        let own: &[KeyCode] = if self.sliders.contains(control) {
            &SLIDER_KEYS
        } else {
            &BUTTON_KEYS
        };
        FOCUS_KEYS.contains(&key) || own.contains(&key)
    }
}
