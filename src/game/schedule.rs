//! The order of the game's frame, written once: the sets the game's plugins put their
//! pre-physics systems in. [`crate::game::GameLogicPlugin`] chains them; a plugin only says which
//! set a system belongs to.
//!
//! A frame, in order:
//! 1. `RunFixedMainLoop`, before the fixed loop: [`GameSystems::Input`] (mouse, touch and
//!    focus to the band entity; a replay file opened), then [`GameSystems::Controls`] (keys: pause, step, reset,
//!    integrator, parameters, overlays), then [`GameSystems::ApplySettings`] (the fixed
//!    clock's step from the scene's step rate), so that all of it acts on the very next step;
//! 2. `FixedUpdate`, zero or more times: the physics' own chain, accumulate, integrate,
//!    publish (`simulation::PhysicsSystems`), then the HUD's energy history;
//! 3. `RunFixedMainLoop`, after the fixed loop: the drawn state interpolated between the last
//!    two steps (`view`), and the end of a playback said (`playback`);
//! 4. `Update`: the HUD's text and the window title, then the panel ([`ScreenSystems`]),
//!    and the drawing.

use bevy::prelude::*;

/// The game's work before the fixed loop, in this order each frame.
#[derive(SystemSet, Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum GameSystems {
    /// The pointer: mouse, touch and focus input to the band entity; replay files opened.
    Input,
    /// The keys: each writes the resource it controls, or triggers a reset.
    Controls,
    /// What derives from the settings the controls wrote (the fixed clock's step).
    ApplySettings,
}

/// The text on screen, each frame in this order (both write `Text`).
#[derive(SystemSet, Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ScreenSystems {
    Hud,
    Panel,
}

/// Chains [`GameSystems`] inside `BeforeFixedMainLoop`: a press and a key in one frame always
/// act in the same order (the press first, so a reset in that frame also lets go).
pub fn order_the_frame(app: &mut App) {
    app.configure_sets(
        RunFixedMainLoop,
        (
            GameSystems::Input,
            GameSystems::Controls,
            GameSystems::ApplySettings,
        )
            .chain()
            .in_set(RunFixedMainLoopSystems::BeforeFixedMainLoop),
    )
    .configure_sets(Update, (ScreenSystems::Hud, ScreenSystems::Panel).chain());
}
