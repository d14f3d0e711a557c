//! What plugins at several levels of the game share, so that none imports another for it: the
//! settings several read (the scene's name, what shows, the dock hidden, the game's [`Mode`]),
//! initialised once here ([`SharedPlugin`], added first by the game), which own them; the
//! messages several send ([`Apply`], a part of the setup to its owner; [`Say`], news for the
//! status line the HUD owns; [`Learn`], a learn control); and which keys a focused control
//! takes ([`FocusedKeys`]). It imports no plugin.

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

/// The game has a screen: `GameScreenPlugin` puts it in.
///
/// Each feature that draws adds its drawing in its plugin's `finish` when it finds it, so that
/// the headless game runs without.
#[derive(Resource, Debug, Default)]
pub struct Screen;

/// Tells whether the app has a screen to draw on.
pub fn has_screen(app: &App) -> bool {
    app.world().contains_resource::<Screen>()
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
    /// The chapter's scene back at its start, paused, its answers kept.
    Restart,
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
