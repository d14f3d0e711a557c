//! Links in the game (docs/links.md): a link opened puts its scene, settings, overlays and
//! recorded game in place (`open_link`), and the share controls write the link of what is
//! on screen ([`ShareLink`]): natively to the terminal and the status line, in the browser to
//! the address bar, the clipboard and the status line. A link the game cannot take whole is
//! taken in part, and what was left is named on the status line.

use bevy::ecs::system::SystemParam;
use bevy::math::DVec2;
use bevy::prelude::*;

use crate::game::replays::playback::OpenReplay;
use crate::game::replays::recording::Recorder;
use crate::game::replays::scenes::LoadScene;
use crate::game::schedule::GameSystems;
use crate::game::shared::{Apply, DockHidden, Learn, Mode, Overlay, Overlays, Say, SceneName};
use crate::game::simulation::Clock;
use crate::physics::{Integrator, Scene, SceneParams};
use crate::replay::Replay;
use crate::replay::link::{Link, LinkOverlays};

/// Opens the link the game started with, and answers the share controls.
pub(super) fn plugin(app: &mut App) {
    app.add_observer(share).add_systems(
        RunFixedMainLoop,
        open_pending_link
            .run_if(resource_exists::<PendingLink>)
            .in_set(GameSystems::Input),
    );
}

/// A link to open before the first step, and what was wrong with it.
///
/// The link is `play --link`'s or the page's own address; what was wrong with it is said once
/// the game runs.
#[derive(Resource, Debug, Clone, Default)]
pub(crate) struct PendingLink {
    pub link: Link,
    pub problems: Vec<String>,
}

/// Write the link of what is on screen; with `game`, the game so far in its fragment.
#[derive(Event, Debug, Clone, Copy, PartialEq, Eq)]
pub struct ShareLink {
    pub game: bool,
}

/// What is on screen, as the link of it says it.
#[derive(SystemParam)]
pub(crate) struct OnScreen<'w> {
    params: Res<'w, SceneParams>,
    scene: Res<'w, SceneName>,
    overlays: Res<'w, Overlays>,
    dock_hidden: Res<'w, DockHidden>,
    virtual_time: Res<'w, Time<Virtual>>,
    integrator: Res<'w, Integrator>,
    recorder: Res<'w, Recorder>,
}

impl OnScreen<'_> {
    fn shown(&self) -> Shown<'_> {
        Shown {
            params: *self.params,
            scene: &self.scene.0,
            overlays: *self.overlays,
            dock_hidden: self.dock_hidden.0,
            speed: self.virtual_time.relative_speed_f64(),
            integrator: *self.integrator,
            recording: self.recorder.replay.as_ref(),
        }
    }
}

/// What a link writes of the game on screen.
struct Shown<'a> {
    params: SceneParams,
    scene: &'a str,
    overlays: Overlays,
    dock_hidden: bool,
    speed: f64,
    integrator: Integrator,
    recording: Option<&'a Replay>,
}

/// Opens the link `play --link` or the page's address gave, before the first step.
fn open_pending_link(mut commands: Commands, pending: Res<PendingLink>, on_screen: OnScreen) {
    commands.remove_resource::<PendingLink>();
    let PendingLink { link, mut problems } = pending.clone();
    problems.extend(open_link(&mut commands, link, &on_screen));
    if !problems.is_empty() {
        let said = format!("link: not taken: {}", problems.join("; "));
        warn!("{said}");
        commands.trigger(Say(said));
    }
}

/// Puts `link` in place and returns what was not taken, and why.
///
/// With a replay, the replay is played from its start (its scene and settings are the
/// replay's, so the link's own settings keys are left, and named); else the integrator and the
/// step rate, then the scene (loaded with them, as its number key does), then the scene's
/// parameters the link overrides. Then the time scale and the overlays. Each is sent to its
/// owner, in that order.
fn open_link(commands: &mut Commands, link: Link, now: &OnScreen) -> Vec<String> {
    let mut problems = Vec::new();
    let settings_keys = link.settings_keys();
    if let Some(chapter) = link.learn {
        // The chapter sets its own scene and settings, as its buttons do.
        let mut left = settings_keys.clone();
        if link.replay.is_some() {
            left.push("replay");
        }
        if !left.is_empty() {
            problems.push(format!(
                "{}: left: the link's chapter sets the scene and its settings",
                left.join(", ")
            ));
        }
        commands.trigger(Learn::Chapter(chapter.saturating_sub(1) as usize));
    } else if let Some(replay) = link.replay {
        if !settings_keys.is_empty() {
            problems.push(format!(
                "{}: left: the link's replay sets the scene and its settings",
                settings_keys.join(", ")
            ));
        }
        commands.trigger(OpenReplay(replay));
    } else {
        if let Some(integrator) = link.integrator {
            commands.trigger(Apply(integrator));
        }
        let mut params = *now.params;
        if let Some(rate) = link.step_rate_hz {
            // The scene below is loaded at this step (in range: the clock can keep it).
            params.step_rate_hz = rate;
            commands.trigger(Apply(params));
        }
        if let Some(name) = &link.scene {
            match Scene::named(name) {
                Ok(scene) => {
                    // Loaded as its key loads it: its parameters at the rate in force.
                    commands.trigger(LoadScene(scene.name));
                    params = SceneParams {
                        step_rate_hz: params.step_rate_hz,
                        ..scene.params
                    };
                }
                Err(error) => commands.trigger(Say(format!("cannot load {name}: {error}"))),
            }
        }
        let overrides = [
            (link.stiffness, &mut params.stiffness),
            (link.mass, &mut params.mass),
            (link.linear_damping, &mut params.linear_damping),
            (link.angular_damping, &mut params.angular_damping),
        ];
        for (value, field) in overrides {
            if let Some(value) = value {
                *field = value;
            }
        }
        if let Some(side) = link.size {
            params.size = DVec2::splat(side);
        }
        match params.check_playable() {
            Ok(()) => commands.trigger(Apply(params)),
            Err(error) => problems.push(format!("{error}")),
        }
    }
    if let Some(speed) = link.time_scale {
        let paused = now.virtual_time.is_paused();
        commands.trigger(Apply(Clock { speed, paused }));
    }
    let shown = link.overlays;
    let mut overlays = *now.overlays;
    for overlay in Overlay::ALL {
        if let Some(on) = shown.get(overlay) {
            overlays.set(overlay, on);
        }
    }
    if overlays != *now.overlays {
        commands.trigger(Apply(overlays));
    }
    if let Some(on) = shown.dock {
        commands.trigger(Apply(DockHidden(!on)));
    }
    problems
}

/// Returns the link of what is on screen, and with `game` the recording so far.
///
/// The link has the keys that differ from what a fresh game starts with, so it holds only what
/// the player changed.
pub fn current_link(world: &World, game: bool) -> Result<Link, String> {
    Shown {
        params: *world.resource::<SceneParams>(),
        scene: &world.resource::<SceneName>().0,
        overlays: *world.resource::<Overlays>(),
        dock_hidden: world.resource::<DockHidden>().0,
        speed: world.resource::<Time<Virtual>>().relative_speed_f64(),
        integrator: *world.resource::<Integrator>(),
        recording: world.resource::<Recorder>().replay.as_ref(),
    }
    .link(game)
}

impl Shown<'_> {
    /// Returns the link of what is shown, and with `game` the recording so far.
    fn link(&self, game: bool) -> Result<Link, String> {
        let params = self.params;
        // The tutorial's is the scene a fresh game shows (without its scripted pull).
        let named = Scene::named(self.scene)
            .ok()
            .filter(|s| s.name != "tutorial");
        let base = named.as_ref().map_or(SceneParams::tutorial(), |s| s.params);
        let differs = |value: f64, base: f64| (value != base).then_some(value);
        let overlays = self.overlays;
        let on = |on: bool| on.then_some(true);
        let mut link = Link {
            time_scale: differs(self.speed, 1.0),
            overlays: LinkOverlays {
                // The ghosts are left out where the plot turns them on.
                shown: Overlay::ALL.map(|overlay| {
                    let implied = overlay == Overlay::Ghosts && overlays.on(Overlay::Plot);
                    on(overlays.on(overlay) && !implied)
                }),
                dock: self.dock_hidden.then_some(false),
            },
            ..default()
        };
        if game {
            let replay = self.recording.cloned();
            link.replay = Some(replay.ok_or("nothing recorded yet: pull the box first")?);
        } else {
            link.scene = named.map(|s| s.name.to_owned());
            let integrator = self.integrator;
            link.integrator = (integrator != Integrator::default()).then_some(integrator);
            link.stiffness = differs(params.stiffness, base.stiffness);
            link.mass = differs(params.mass, base.mass);
            // A square box's side (every scene's box is square).
            link.size = (params.size != base.size).then_some(params.size.x);
            link.linear_damping = differs(params.linear_damping, base.linear_damping);
            link.angular_damping = differs(params.angular_damping, base.angular_damping);
            link.step_rate_hz = differs(params.step_rate_hz, base.step_rate_hz);
        }
        Ok(link)
    }
}

/// Answers the share controls, writing the link where the player can take it.
fn share(
    share: On<ShareLink>,
    mode: Res<State<Mode>>,
    on_screen: OnScreen,
    mut commands: Commands,
) {
    // In learn mode the link is the chapter's, which learn mode writes.
    if !share.game && *mode.get() == Mode::Learn {
        return;
    }
    let said = match on_screen
        .shown()
        .link(share.game)
        .and_then(|link| link.to_query())
    {
        Ok(query) => publish(&query, share.game),
        Err(error) => format!("no link: {error}"),
    };
    commands.trigger(Say(said));
}

/// Publishes the link and returns what the status line says.
///
/// Natively the link is printed (the terminal is where a long one can be copied from); in the
/// browser it becomes the page's address and is copied.
pub(crate) fn publish(query: &str, game: bool) -> String {
    #[cfg(not(target_arch = "wasm32"))]
    let (address, place) = {
        println!("{query}");
        (query.to_owned(), "printed to the terminal")
    };
    #[cfg(target_arch = "wasm32")]
    let (address, place) = (
        crate::game::web::share_link(query),
        "in the address bar, copied",
    );
    info!("link: {address}");
    if game {
        format!("game link ({} KB) {place}", address.len().div_ceil(1024))
    } else if cfg!(target_arch = "wasm32") {
        // The address bar shows it.
        format!("link {place}")
    } else {
        format!("link {place}: {address}")
    }
}
