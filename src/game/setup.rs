//! The game's setup: one value that says what the game is set to (the scene and its
//! parameters, the integrator and `auto`'s settings, the step rate and the clock's pace, the
//! overlays, the dock and its cards, the camera's stage) and, for learn mode to put back, the
//! box. It is read whole ([`CurrentSetup`]) and sent whole ([`Setup::send`]): each part goes to
//! the plugin that owns it as an [`Apply`], which alone writes it. Learn mode takes the setup as
//! it enters and sends it back as it leaves; everything else that opens a setting (a key, the
//! panel, a link, a scene, a replay, a chapter) sends only the parts it opens.

use bevy::ecs::system::SystemParam;
use bevy::prelude::*;

use crate::game::camera::{CameraFrame, Stage};
use crate::game::layout::Cards;
use crate::game::shared::{Apply, DockHidden, Overlays, SceneName};
use crate::game::simulation::{Bodies, Clock, PlacedBox};
use crate::physics::{AutoSettings, Integrator, SceneParams};

/// What the game is set to, and the box.
#[derive(Debug, Clone, PartialEq)]
pub struct Setup {
    pub scene: SceneName,
    /// The scene's parameters, the step rate among them (the fixed clock's step follows it).
    pub params: SceneParams,
    pub integrator: Integrator,
    pub auto: AutoSettings,
    pub clock: Clock,
    pub overlays: Overlays,
    pub dock_hidden: DockHidden,
    pub cards: Cards,
    pub stage: Stage,
    /// The box where it was and its mass (None without a box).
    pub body: Option<PlacedBox>,
}

impl Setup {
    /// Sends every part to its owner, in order, the box last.
    ///
    /// Last, so that a reset sent before it (which puts the box at rest) does not undo it.
    pub fn send(&self, commands: &mut Commands) {
        self.send_against(None, commands);
    }

    /// Sends each part that differs from `before` to its owner, in order, the box last.
    pub fn send_changed(&self, before: &Setup, commands: &mut Commands) {
        self.send_against(Some(before), commands);
    }

    /// Sends every part, or with `before` each part that differs from it.
    fn send_against(&self, before: Option<&Setup>, commands: &mut Commands) {
        let differs = |same: fn(&Setup, &Setup) -> bool| before.is_none_or(|b| !same(self, b));
        if differs(|a, b| a.scene == b.scene) {
            commands.trigger(Apply(self.scene.clone()));
        }
        if differs(|a, b| a.params == b.params) {
            commands.trigger(Apply(self.params));
        }
        if differs(|a, b| a.integrator == b.integrator) {
            commands.trigger(Apply(self.integrator));
        }
        if differs(|a, b| a.auto == b.auto) {
            commands.trigger(Apply(self.auto));
        }
        if differs(|a, b| a.clock == b.clock) {
            commands.trigger(Apply(self.clock));
        }
        if differs(|a, b| a.overlays == b.overlays) {
            commands.trigger(Apply(self.overlays));
        }
        if differs(|a, b| a.dock_hidden == b.dock_hidden) {
            commands.trigger(Apply(self.dock_hidden));
        }
        if differs(|a, b| a.cards == b.cards) {
            commands.trigger(Apply(self.cards.clone()));
        }
        if differs(|a, b| a.stage == b.stage) {
            commands.trigger(Apply(self.stage));
        }
        if let Some(body) = self.body
            && differs(|a, b| a.body == b.body)
        {
            commands.trigger(Apply(body));
        }
    }
}

/// The setup as the game has it now, read from its owners.
#[derive(SystemParam)]
pub struct CurrentSetup<'w, 's> {
    scene: Res<'w, SceneName>,
    params: Res<'w, SceneParams>,
    integrator: Res<'w, Integrator>,
    auto: Res<'w, AutoSettings>,
    virtual_time: Res<'w, Time<Virtual>>,
    overlays: Res<'w, Overlays>,
    dock_hidden: Res<'w, DockHidden>,
    cards: Res<'w, Cards>,
    camera: Res<'w, CameraFrame>,
    bodies: Bodies<'w, 's>,
}

impl CurrentSetup<'_, '_> {
    /// Returns the setup now.
    pub fn get(&self) -> Setup {
        Setup {
            scene: self.scene.clone(),
            params: *self.params,
            integrator: *self.integrator,
            auto: *self.auto,
            clock: Clock::of(&self.virtual_time),
            overlays: *self.overlays,
            dock_hidden: *self.dock_hidden,
            cards: self.cards.clone(),
            stage: self.camera.stage,
            body: self.bodies.iter().next().map(|body| PlacedBox {
                state: body.state(),
                mass: *body.mass,
            }),
        }
    }
}
