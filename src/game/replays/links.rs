//! Links in the game (docs/links.md): a link opened puts its scene, settings, overlays and
//! recorded game in place (`open_link`), and the share controls write the link of what is
//! on screen ([`ShareLink`]): natively to the terminal and the status line, in the browser to
//! the address bar, the clipboard and the status line. A link the game cannot take whole is
//! taken in part, and what was left is named on the status line.

use bevy::math::DVec2;
use bevy::prelude::*;

use crate::game::replays::playback;
use crate::game::replays::recording::Recorder;
use crate::game::replays::scenes::load_scene;
use crate::game::schedule::GameSystems;
use crate::game::shared::{DockHidden, Learn, Mode, Overlay, Overlays, Say, SceneName};
use crate::game::simulation::set_fixed_step;
use crate::physics::{Integrator, Scene, SceneParams};
use crate::replay::link::{Link, LinkOverlays};

pub struct LinksPlugin;

impl Plugin for LinksPlugin {
    fn build(&self, app: &mut App) {
        app.add_observer(share).add_systems(
            RunFixedMainLoop,
            open_pending_link
                .run_if(resource_exists::<PendingLink>)
                .in_set(GameSystems::Input),
        );
    }
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

fn open_pending_link(mut commands: Commands) {
    commands.queue(|world: &mut World| {
        if let Some(PendingLink { link, mut problems }) = world.remove_resource::<PendingLink>() {
            problems.extend(open_link(world, link));
            if !problems.is_empty() {
                let said = format!("link: not taken: {}", problems.join("; "));
                warn!("{said}");
                world.trigger(Say(said));
            }
        }
    });
}

/// Puts `link` in place and returns what was not taken, and why.
///
/// With a replay, the replay is played from its start (its scene and settings are the
/// replay's, so the link's own settings keys are left, and named); else the integrator and the
/// step rate, then the scene (loaded with them, as its number key does), then the scene's
/// parameters the link overrides. Then the time scale and the overlays.
fn open_link(world: &mut World, link: Link) -> Vec<String> {
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
        world.trigger(Learn::Chapter(chapter.saturating_sub(1) as usize));
        world.flush();
    } else if let Some(replay) = link.replay {
        if !settings_keys.is_empty() {
            problems.push(format!(
                "{}: left: the link's replay sets the scene and its settings",
                settings_keys.join(", ")
            ));
        }
        playback::open(world, replay);
    } else {
        if let Some(integrator) = link.integrator {
            world.insert_resource(integrator);
        }
        if let Some(rate) = link.step_rate_hz {
            world.resource_mut::<SceneParams>().step_rate_hz = rate;
            // The scene below is loaded at this step (in range: the clock can keep it).
            set_fixed_step(&mut world.resource_mut::<Time<Fixed>>(), 1.0 / rate);
        }
        if let Some(scene) = &link.scene {
            load_scene(world, scene);
        }
        let mut params = *world.resource::<SceneParams>();
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
            Ok(()) => world.insert_resource(params),
            Err(error) => problems.push(format!("{error}")),
        }
    }
    if let Some(scale) = link.time_scale {
        world
            .resource_mut::<Time<Virtual>>()
            .set_relative_speed_f64(scale);
    }
    let shown = link.overlays;
    let mut overlays = world.resource_mut::<Overlays>();
    for overlay in Overlay::ALL {
        if let Some(on) = shown.get(overlay) {
            overlays.set(overlay, on);
        }
    }
    if let Some(on) = shown.dock {
        world.resource_mut::<DockHidden>().0 = !on;
    }
    problems
}

/// Returns the link of what is on screen, and with `game` the recording so far.
///
/// The link has the keys that differ from what a fresh game starts with, so it holds only what
/// the player changed.
pub fn current_link(world: &World, game: bool) -> Result<Link, String> {
    let params = *world.resource::<SceneParams>();
    let scene = &world.resource::<SceneName>().0;
    // The tutorial's is the scene a fresh game shows (without its scripted pull).
    let named = Scene::named(scene).ok().filter(|s| s.name != "tutorial");
    let base = named.as_ref().map_or(SceneParams::tutorial(), |s| s.params);
    let differs = |value: f64, base: f64| (value != base).then_some(value);
    let overlays = *world.resource::<Overlays>();
    let on = |on: bool| on.then_some(true);
    let speed = world.resource::<Time<Virtual>>().relative_speed_f64();
    let integrator = *world.resource::<Integrator>();
    let mut link = Link {
        time_scale: differs(speed, 1.0),
        overlays: LinkOverlays {
            // The ghosts are left out where the plot turns them on.
            shown: Overlay::ALL.map(|overlay| {
                let implied = overlay == Overlay::Ghosts && overlays.on(Overlay::Plot);
                on(overlays.on(overlay) && !implied)
            }),
            dock: world.resource::<DockHidden>().0.then_some(false),
        },
        ..default()
    };
    if game {
        let replay = world.resource::<Recorder>().replay.clone();
        link.replay = Some(replay.ok_or("nothing recorded yet: pull the box first")?);
    } else {
        link.scene = named.map(|s| s.name.to_owned());
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
fn share(share: On<ShareLink>, mut commands: Commands) {
    let game = share.game;
    commands.queue(move |world: &mut World| {
        // In learn mode the link is the chapter's, which learn mode writes.
        if !game && *world.resource::<State<Mode>>().get() == Mode::Learn {
            return;
        }
        let said = match current_link(world, game).and_then(|link| link.to_query()) {
            Ok(query) => publish(&query, game),
            Err(error) => format!("no link: {error}"),
        };
        world.trigger(Say(said));
    });
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
