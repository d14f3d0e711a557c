//! The order of the game's frame, in code, in one place: every system set of the game is
//! declared here and ordered here. A plugin only says which set each of its systems belongs
//! to; none orders itself against another module's system.
//!
//! A frame, in order:
//! 1. `RunFixedMainLoop`, before the fixed loop, [`GameSystems`] in this order, so that all
//!    of it acts on the very next step: the pointer read, the input acted on, the controls
//!    applied, the game's mode changed (Bevy's `StateTransition` run again here, so learn
//!    mode's `OnEnter` and `OnExit` act before the steps), the settings' consequences derived;
//! 2. `FixedUpdate`, zero or more times, [`PhysicsSystems`]: a playback's recorded inputs,
//!    the observers of the step's inputs (the recorder, the ghosts, learn mode's twin), the
//!    step (accumulate, then integrate with the energies settled), then the readers of the step's results (the recorder, the HUD's
//!    history);
//! 3. `RunFixedMainLoop`, after the fixed loop, [`AfterStepsSystems`]: the drawn state
//!    interpolated between the last two steps, the end of a playback said, learn mode's task
//!    checked;
//! 4. `Update`, [`ScreenSystems`]: the regions arranged for the window, every text written
//!    (the status line and the hint, the cards' lines, learn mode's card, the panel's values),
//!    what Tab offers, the drawing and the energy graph, then the plot, then what a screen
//!    reader hears;
//! 5. `PostUpdate` and `Last`, [`AfterBevySystems`]: after Bevy's UI layout the layout says
//!    where the scene's viewport lies, then the view is chosen for it and the scene camera
//!    placed (before transforms propagate, so the frame drawn is the frame laid out); after
//!    Bevy's window exit systems the recorder saves a game that ends.
//!
//! [`order_the_physics`] chains the fixed step's sets, and the physics plugin calls it itself
//! because it also runs without the game (the benchmarks, the side-by-side with the peers);
//! [`order_the_frame`] chains the rest, for the game.

use bevy::prelude::*;

/// Before the fixed loop, in this order each frame.
#[derive(SystemSet, Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum GameSystems {
    /// Mouse, touch and focus read into pointer actions (in world coordinates).
    ReadPointer,
    /// What acts on this frame's input.
    ///
    /// The band driven, a playback taken over by a press, the panel's taps, replay files opened.
    Input,
    /// The controls: each action writes the resource it controls, or triggers a reset.
    Controls,
    /// Bevy's `StateTransition` run again, so a mode a control set is in place for the next step.
    ///
    /// Bevy runs it once a frame after `PreUpdate`, before the controls; here it runs a second
    /// time, as Bevy's docs allow, so that learn mode's chapter (its `OnEnter`) and the game put
    /// back (`OnExit`) act on this frame's steps. With no mode asked it does nothing.
    ModeChange,
    /// What derives from the settings the controls wrote (the stability view's margins).
    ApplySettings,
    /// The frame's budget for fixed steps opened, just before the loop (`budget`).
    Budget,
}

/// The fixed step, in this order.
#[derive(SystemSet, Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum PhysicsSystems {
    /// A playback puts the step's recorded resets, settings and band in place.
    Playback,
    /// Read the step's inputs as the step will take them; write nothing the physics reads.
    ///
    /// The recorder and the ghosts read here; the band they read is the one that acts
    /// (`simulation::acting_band`).
    Observe,
    /// The step, one system.
    ///
    /// Book the hand's work since the last step in the energy ledger, sum every force and
    /// torque on each body into its `ForceAccumulator`, advance each body with the `Integrator`
    /// resource, then hand the new state to the rest of the app (the render snapshots, the
    /// energy books settled, taps' bands removed after their one step, the step counted).
    Step,
    /// Read the step's results; write nothing the physics reads.
    ///
    /// The readers are the recorder (its state after the step) and the Energy card's history.
    AfterStep,
    /// The frame's budget: the loop stopped once the frame's steps have taken it (`budget`).
    Budget,
}

/// After the fixed loop, each frame.
#[derive(SystemSet, Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum AfterStepsSystems {
    /// What this frame's steps did, made ready for the screen.
    ///
    /// The drawn state interpolated between the last two steps, the end of a playback said
    /// before the HUD shows it.
    Conclude,
}

/// The screen's work in `Update`: its phases, in this order.
///
/// Two features have a set of their own, because another must follow them: the plot (its
/// chart's gizmos after the energy graph's) and the screen reader (after every text written).
#[derive(SystemSet, Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ScreenSystems {
    /// The regions arranged for the window's shape and the cards open, the UI's scale.
    Arrange,
    /// Every text the screen shows written from this frame's state.
    ///
    /// The status line and the hint, the cards' lines, learn mode's card, the panel's values
    /// and thumbs. Each writer writes only its own texts, so they run in any order.
    Write,
    /// What Tab offers and the focus ring, for the nodes as this frame shows them.
    Offer,
    /// The box, the band and the overlays drawn, and the energy graph.
    Draw,
    /// The ghosts' speed against error, in its card, over the energy graph's gizmos.
    Plot,
    /// What a screen reader hears: the names, the labels, the scene described (`access`).
    Access,
}

/// Work that waits for Bevy's own systems.
#[derive(SystemSet, Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum AfterBevySystems {
    /// In `PostUpdate`, after the UI's layout: where the scene's viewport lies.
    AfterLayout,
    /// In `PostUpdate`, then: what the scene shows chosen, for the viewport laid out.
    ///
    /// The player's zoom and pan, the view following the box.
    View,
    /// In `PostUpdate`, then, before transforms propagate: the scene camera placed.
    ///
    /// It renders into the viewport, showing the view.
    Camera,
    /// In `Last`, after the window's exit systems asked to exit: a game that ends saved.
    AfterExit,
}

/// Orders the fixed step's chain.
///
/// The physics plugin needs no more to run alone: it takes the settings it owns as they are
/// sent, with no system before the loop.
pub fn order_the_physics(app: &mut App) {
    app.configure_sets(
        FixedUpdate,
        (
            PhysicsSystems::Playback,
            PhysicsSystems::Observe,
            PhysicsSystems::Step,
            PhysicsSystems::AfterStep,
            PhysicsSystems::Budget,
        )
            .chain(),
    );
}

/// Runs Bevy's state transition at this point of the frame ([`GameSystems::ModeChange`]).
fn change_the_mode(world: &mut World) {
    // Without Bevy's states (a physics-only app) there is no transition to run.
    let _ = world.try_run_schedule(StateTransition);
}

/// Orders the rest of the frame, for the game.
///
/// The fixed step's chain is the physics plugin's own call of [`order_the_physics`]. A press
/// and a key in one frame always act in the same order: the press first, so a reset in that
/// frame also lets go.
pub fn order_the_frame(app: &mut App) {
    app.configure_sets(
        RunFixedMainLoop,
        (
            (
                GameSystems::ReadPointer,
                GameSystems::Input,
                GameSystems::Controls,
                GameSystems::ModeChange,
                GameSystems::ApplySettings,
                GameSystems::Budget,
            )
                .chain()
                .in_set(RunFixedMainLoopSystems::BeforeFixedMainLoop),
            AfterStepsSystems::Conclude.in_set(RunFixedMainLoopSystems::AfterFixedMainLoop),
        ),
    )
    .add_systems(
        RunFixedMainLoop,
        change_the_mode.in_set(GameSystems::ModeChange),
    )
    .configure_sets(
        Update,
        (
            ScreenSystems::Arrange,
            ScreenSystems::Write,
            ScreenSystems::Offer,
            ScreenSystems::Draw,
            ScreenSystems::Plot,
            ScreenSystems::Access,
        )
            .chain(),
    )
    .configure_sets(
        PostUpdate,
        (
            AfterBevySystems::AfterLayout,
            AfterBevySystems::View,
            AfterBevySystems::Camera,
        )
            .chain()
            .after(bevy::ui::UiSystems::Layout)
            .before(bevy::transform::TransformSystems::Propagate),
    )
    .configure_sets(
        Last,
        AfterBevySystems::AfterExit.after(bevy::window::ExitSystems),
    );
}
