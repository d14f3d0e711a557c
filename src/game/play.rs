//! Starting the game: the play command's options checked and put in place (the step rate and
//! integrator, a replay to play back, a file to record to, a link to open), then Bevy's plugins,
//! the window and the game's. [`prepare`] is the part a test can call: it needs no window.

#[cfg(not(target_arch = "wasm32"))]
use std::path::{Path, PathBuf};

use bevy::prelude::*;
use bevy_prototype_lyon::prelude::ShapePlugin;

use super::GamePlugin;
use super::layout::WINDOW_SIZE;
use super::replays::links::PendingLink;
use crate::physics::{Integrator, SceneParams};
use crate::replay::Link;

/// How to start the game: `play`'s options on the command line, the defaults on the web.
#[derive(Debug, Default, Clone)]
pub struct PlayOptions {
    pub integrator: Option<Integrator>,
    pub step_rate: Option<f64>,
    /// Save the game to this file when it ends.
    #[cfg(not(target_arch = "wasm32"))]
    pub record: Option<PathBuf>,
    /// Play this replay back; a press takes over.
    #[cfg(not(target_arch = "wasm32"))]
    pub replay: Option<PathBuf>,
    /// Open this link (docs/links.md): `play --link`, or the page's own address.
    pub link: Option<String>,
}

/// Inserts the game's starting resources from `options` into `app`, before its plugins.
///
/// They are the scene's parameters, the integrator, a replay to play back, a recorder and its
/// file, a link to open. Every option is checked first, against the game's ranges: a bad one is
/// refused with a message and `app` is left untouched. A link is taken in part: what it cannot set
/// is said on the status line (and natively on stderr) and the rest is opened.
pub fn prepare(app: &mut App, options: &PlayOptions) -> Result<(), String> {
    let mut params = SceneParams::tutorial();
    if let Some(rate) = options.step_rate {
        params.step_rate_hz = rate;
    }
    params.check_playable().map_err(|error| error.to_string())?;
    let link = options
        .link
        .as_deref()
        .map(Link::parse)
        .and_then(|(link, problems)| {
            let problems: Vec<String> = problems.iter().map(ToString::to_string).collect();
            #[cfg(not(target_arch = "wasm32"))]
            for problem in &problems {
                eprintln!("warning: link: {problem}");
            }
            (link != Link::default() || !problems.is_empty())
                .then_some(PendingLink { link, problems })
        });
    // A replay (native only) may start with others.
    #[cfg_attr(target_arch = "wasm32", allow(unused_mut))]
    let mut integrator = options.integrator.unwrap_or_default();
    #[cfg(not(target_arch = "wasm32"))]
    {
        use super::replays::{playback::Playback, recording::Recorder};
        use super::shared::SceneName;
        let playback = match &options.replay {
            Some(path) => {
                let replay = crate::replay::Replay::read_file(path)?;
                replay
                    .check_playable()
                    .map_err(|error| format!("{}: {error}", path.display()))?;
                Some(replay)
            }
            None => None,
        };
        if let Some(target) = &options.record {
            check_folder(target)?;
        }
        if let Some(replay) = playback {
            app.insert_resource(SceneName(replay.header.scene.clone()));
            let playback = Playback::of(replay);
            if let Some((start, recorded, auto)) = playback.start() {
                (params, integrator) = (start, recorded);
                app.insert_resource(auto);
            }
            app.insert_resource(playback);
        }
        if let Some(target) = &options.record {
            app.insert_resource(Recorder::to_file(target.clone()));
        }
    }
    app.insert_resource(params).insert_resource(integrator);
    if let Some(link) = link {
        app.insert_resource(link);
    }
    Ok(())
}

/// Checks for an X server, which the window needs natively on Linux and the BSDs.
///
/// The game is built for X11 only. Without a server it says so, and what runs instead, rather
/// than leave Bevy to panic.
#[cfg(all(unix, not(target_os = "macos"), not(target_arch = "wasm32")))]
fn check_display() -> Result<(), String> {
    match std::env::var_os("DISPLAY") {
        Some(display) if !display.is_empty() => Ok(()),
        _ => Err(
            "no display to open the game's window on (DISPLAY is not set): `simulate` \
                  runs the physics without one, and the web build plays in a browser \
                  (docs/web.md)"
                .to_owned(),
        ),
    }
}

#[cfg(not(all(unix, not(target_os = "macos"), not(target_arch = "wasm32"))))]
fn check_display() -> Result<(), String> {
    Ok(())
}

/// Checks that a file to record to is in a folder that exists.
///
/// A missing folder is said now, not when the game ends.
#[cfg(not(target_arch = "wasm32"))]
fn check_folder(target: &Path) -> Result<(), String> {
    let folder = match target.parent() {
        Some(folder) if !folder.as_os_str().is_empty() => folder,
        _ => Path::new("."),
    };
    if folder.is_dir() {
        Ok(())
    } else {
        Err(format!(
            "cannot record to {}: {} is not a folder",
            target.display(),
            folder.display()
        ))
    }
}

/// Returns the window the game opens.
fn window() -> Window {
    Window {
        title: "Rubber Band Box".into(),
        resolution: WINDOW_SIZE.into(),
        // On the web: draw into the page's canvas, fill its parent, keep the browser's own
        // gestures (scroll, zoom) off the canvas.
        canvas: Some("#bevy".into()),
        fit_canvas_to_parent: true,
        prevent_default_event_handling: true,
        ..default()
    }
}

/// Plays until the window closes; a bad option is refused before any window opens.
pub fn play(options: &PlayOptions) -> Result<(), String> {
    let mut app = App::new();
    prepare(&mut app, options)?;
    check_display()?;
    #[cfg(all(unix, not(target_arch = "wasm32")))]
    if options.record.is_some() {
        // A process-wide signal handler: installed by the game that plays, not by `prepare`.
        super::replays::recording::sigterm::exit_on_sigterm(&mut app);
    }
    // Before Bevy's window plugin, whose build opens the display.
    #[cfg(all(unix, not(target_os = "macos"), not(target_arch = "wasm32")))]
    say_an_unopenable_display();
    app.insert_resource(ClearColor(super::theme::colour::BACKGROUND))
        .add_plugins(DefaultPlugins.set(WindowPlugin {
            primary_window: Some(window()),
            ..default()
        }))
        .add_plugins((ShapePlugin, GamePlugin))
        .run();
    Ok(())
}

/// Ends the game with one line and status 2 where the display named cannot be opened.
///
/// A `DISPLAY` that names no running X server (a stale one in tmux or over ssh) fails only
/// when Bevy's window plugin builds its event loop, which panics; this turns that panic into
/// the line a missing `DISPLAY` gets, and leaves every other panic as it was.
#[cfg(all(unix, not(target_os = "macos"), not(target_arch = "wasm32")))]
fn say_an_unopenable_display() {
    let before = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        let said = info
            .payload()
            .downcast_ref::<String>()
            .map(String::as_str)
            .or_else(|| info.payload().downcast_ref::<&str>().copied())
            .unwrap_or_default();
        if said.contains("Failed to build event loop") {
            let display = std::env::var("DISPLAY").unwrap_or_default();
            eprintln!(
                "error: cannot open the display DISPLAY={display:?} (no X server answers \
                 there): start one, or unset DISPLAY; `simulate` runs the physics without a \
                 display, and the web build plays in a browser (docs/web.md)"
            );
            std::process::exit(2);
        }
        before(info);
    }));
}
