//! Links in the game (docs/links.md): a link opened puts its scene, settings, overlays and
//! recorded game in place (`open_link`), and the share controls write the link of what is
//! on screen ([`ShareLink`]): natively to the terminal and the status line, in the browser to
//! the address bar, the clipboard and the status line. A link the game cannot take whole is
//! taken in part, and what was left is named on the status line.

use bevy::math::DVec2;
use bevy::prelude::*;

use crate::game::layout::small::SmallWindow;
use crate::game::replays::playback::OpenReplay;
use crate::game::replays::recording::Recorder;
use crate::game::replays::scenes::LoadScene;
use crate::game::schedule::GameSystems;
use crate::game::setup::{CurrentSetup, Setup};
use crate::game::shared::{Apply, DockHidden, Learn, Mode, Overlay, Say};
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

/// Opens the link `play --link` or the page's address gave, before the first step.
fn open_pending_link(mut commands: Commands, pending: Res<PendingLink>, setup: CurrentSetup) {
    commands.remove_resource::<PendingLink>();
    let PendingLink { link, mut problems } = pending.clone();
    problems.extend(open_link(&mut commands, link, &setup.get()));
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
fn open_link(commands: &mut Commands, link: Link, now: &Setup) -> Vec<String> {
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
        let mut next = now.clone();
        if let Some(integrator) = link.integrator {
            next.integrator = integrator;
        }
        if let Some(rate) = link.step_rate_hz {
            // The scene below is loaded at this step (in range: the clock can keep it).
            next.params.step_rate_hz = rate;
        }
        next.send_changed(now, commands);
        let mut params = next.params;
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
    let mut shown = now.clone();
    if let Some(speed) = link.time_scale {
        shown.clock.speed = speed;
    }
    for overlay in Overlay::ALL {
        if let Some(on) = link.overlays.get(overlay) {
            shown.overlays.set(overlay, on);
        }
    }
    // Only the time scale and the overlays differ from `now` here.
    shown.send_changed(now, commands);
    // Sent even as it is: a link that names the dock has set it (a small window's rule yields).
    if let Some(on) = link.overlays.dock {
        commands.trigger(Apply(DockHidden(!on)));
    }
    problems
}

/// Returns the link of the game set as `now`, and with `game` its `recording`.
///
/// The link has the keys that differ from what a fresh game starts with, so it holds only what
/// the player changed.
pub fn link_of(now: &Setup, recording: Option<&Replay>, game: bool) -> Result<Link, String> {
    let params = now.params;
    // The tutorial's is the scene a fresh game shows (without its scripted pull).
    let named = Scene::named(&now.scene.0)
        .ok()
        .filter(|s| s.name != "tutorial");
    let base = named.as_ref().map_or(SceneParams::tutorial(), |s| s.params);
    let differs = |value: f64, base: f64| (value != base).then_some(value);
    let overlays = now.overlays;
    let on = |on: bool| on.then_some(true);
    let mut link = Link {
        time_scale: differs(now.clock.speed, 1.0),
        overlays: LinkOverlays {
            // The ghosts are left out where the plot turns them on.
            shown: Overlay::ALL.map(|overlay| {
                let implied = overlay == Overlay::Ghosts && overlays.on(Overlay::Plot);
                on(overlays.on(overlay) && !implied)
            }),
            dock: now.dock_hidden.0.then_some(false),
        },
        ..default()
    };
    if game {
        let replay = recording.cloned();
        link.replay = Some(replay.ok_or("nothing recorded yet: pull the box first")?);
    } else {
        link.scene = named.map(|s| s.name.to_owned());
        let integrator = now.integrator;
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

/// Answers the share controls, writing the link where the player can take it.
fn share(
    share: On<ShareLink>,
    mode: Res<State<Mode>>,
    (setup, recorder): (CurrentSetup, Res<Recorder>),
    small: Option<Res<SmallWindow>>,
    mut commands: Commands,
) {
    // In learn mode the link is the chapter's, which learn mode writes.
    if !share.game && *mode.get() == Mode::Learn {
        return;
    }
    let mut now = setup.get();
    // A dock a small window hid is the window's: a desktop opening the link shows it.
    if small.is_some_and(|small| small.hid_the_dock()) {
        now.dock_hidden = DockHidden(false);
    }
    let link = link_of(&now, recorder.replay.as_ref(), share.game);
    let said = match link.and_then(|link| link.to_query()) {
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
