//! The heads-up display: the status line over the scene (the integrator, k, the rate, the
//! time scale, the clock, and whether the game is paused, diverged or falls behind), and the
//! hint under it (how to play, or the latest news). The dock's cards write their own lines
//! (`game::readouts`, `game::energy` and the rest). The window's title is the game's name
//! alone: a screen reader says it as the window's name, so what changes is said by the status
//! line (the window's status bar) and the hint (a live region); `layout` gives them those roles.
//!
//! The numbers come from resources the physics keeps; this module only formats them, so its
//! text runs headless too (the text is plain `Text` components).

pub mod pace;

use bevy::ecs::system::SystemParam;
use bevy::picking::Pickable;
use bevy::prelude::*;

use crate::game::layout::{Slot, Slots};
use crate::game::schedule::ScreenSystems;
use crate::game::shared::{Say, StatusMessage};
use crate::game::simulation::{Clocks, StepStats};
use crate::game::theme::{self, colour, size};
use crate::game::theme::{hertz, readable, times};
use crate::physics::{Integrator, SceneParams};
use pace::{Pace, behind, measure_pace};

pub struct HudPlugin;

impl Plugin for HudPlugin {
    fn build(&self, app: &mut App) {
        app.init_resource::<Pace>()
            .init_resource::<StatusMessage>()
            .add_observer(hear)
            .add_systems(Startup, spawn_hud)
            .add_systems(
                Update,
                (measure_pace, show_hud)
                    .chain()
                    .in_set(ScreenSystems::Write)
                    .ambiguous_with(ScreenSystems::Write),
            );
    }
}

/// Keeps what a plugin said as the status line's latest news: the one writer of [`StatusMessage`].
fn hear(say: On<Say>, mut status: ResMut<StatusMessage>) {
    status.0 = Some(say.0.clone());
}

/// One line of the HUD, a `Text` entity named "HUD" and the line.
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
enum HudLine {
    /// Over the scene: what a player must always see.
    Status,
    /// Under the scene: how to play, in one line, or the latest news.
    Hint,
}

impl HudLine {
    /// Returns where the line lies: the status over the scene, the hint under it.
    fn slot(self) -> Slot {
        match self {
            HudLine::Status => Slot::Status,
            HudLine::Hint => Slot::Hint,
        }
    }

    /// Returns the line's size and face.
    fn font(self) -> TextFont {
        match self {
            HudLine::Status => theme::text_font(size::TITLE),
            HudLine::Hint => theme::text_font(size::CAPTION),
        }
    }

    /// Returns the line's colour: the status warns once the live method diverged.
    ///
    /// The hint is dim but for news.
    fn colour(self, r: &Readings) -> Color {
        match self {
            HudLine::Status if r.divergence.is_some() => colour::WARNING,
            HudLine::Status => colour::TEXT,
            HudLine::Hint if r.news.is_some() => colour::TEXT,
            HudLine::Hint => colour::DIM,
        }
    }

    fn text(self, r: &Readings) -> String {
        match self {
            HudLine::Status => status_line(r),
            HudLine::Hint => r.news.clone().unwrap_or_else(|| HINT.to_owned()),
        }
    }
}

/// How long the hint line says the latest status, in seconds of the wall's clock.
///
/// The status may be a save, a value refused or a link left in part.
pub const NEWS_SECONDS: f64 = 10.0;

/// The latest status and when it came, by the wall's clock.
#[derive(Default)]
struct News {
    text: Option<String>,
    since: f64,
}

/// The hint under the scene: how to play, in a line a phone can hold.
pub const HINT: &str = "drag: pull the box · wheel or pinch: zoom · F: frame · H: instruments";

/// Writes the status over the scene: the integrator, k, the step rate, the time scale, the clock.
///
/// It says so when paused, diverged, or falling behind the wall clock ([`Pace`]).
fn status_line(r: &Readings) -> String {
    let mut line = format!(
        "{} · k {} · {} · time {} · t {:.1} s",
        r.integrator,
        readable(r.stiffness),
        hertz(r.step_rate_hz),
        times(r.time_scale),
        r.simulated_seconds
    );
    if r.paused {
        line += " · PAUSED";
    } else if let Some(behind) = behind(r.pace, r.time_scale, r.paused) {
        line += &format!(" · {behind}");
    }
    if let Some((diverged, step)) = r.divergence {
        line += &format!(" · {diverged} DIVERGED at step {step}");
    }
    line
}

/// Everything the HUD shows, gathered from the resources.
#[derive(Debug, Clone, PartialEq)]
struct Readings {
    integrator: Integrator,
    stiffness: f64,
    divergence: Option<(Integrator, u64)>,
    step_rate_hz: f64,
    time_scale: f64,
    paused: bool,
    simulated_seconds: f64,
    /// The share of the set pace the game's clock keeps ([`Pace`]).
    pace: f64,
    /// The latest status while it is news ([`NEWS_SECONDS`]).
    ///
    /// The hint line says it, so that a player sees it with the dock's cards folded.
    news: Option<String>,
}

fn spawn_hud(mut commands: Commands, slots: Slots) {
    for line in [HudLine::Status, HudLine::Hint] {
        let Some(parent) = slots.find(line.slot()) else {
            continue;
        };
        // The hint line holds one line whatever it says (a long status is cut at the window's
        // edge), so that nothing below it moves when a message comes and goes.
        let layout = if line == HudLine::Hint {
            TextLayout::no_wrap()
        } else {
            TextLayout::default()
        };
        commands.spawn((
            Name::new(format!("HUD {line:?}")),
            line,
            Text::default(),
            layout,
            line.font(),
            TextColor(colour::TEXT),
            Pickable::IGNORE,
            Node::default(),
            BackgroundColor(Color::NONE),
            ChildOf(parent),
        ));
    }
}

/// What the HUD reads.
#[derive(SystemParam)]
struct Sources<'w> {
    integrator: Res<'w, Integrator>,
    stats: Res<'w, StepStats>,
    params: Res<'w, SceneParams>,
    clocks: Clocks<'w>,
    pace: Res<'w, Pace>,
    status: Res<'w, StatusMessage>,
}

impl Sources<'_> {
    /// Returns the readings, with the news the hint says, if any.
    fn readings(&self, news: Option<String>) -> Readings {
        Readings {
            integrator: *self.integrator,
            stiffness: self.params.stiffness,
            divergence: self.stats.divergence,
            step_rate_hz: self.clocks.step_rate_hz(),
            time_scale: self.clocks.time_scale(),
            paused: self.clocks.paused(),
            simulated_seconds: self.clocks.since_reset(),
            pace: self.pace.0,
            news,
        }
    }
}

fn show_hud(
    sources: Sources,
    real_time: Res<Time<Real>>,
    mut news: Local<News>,
    mut lines: Query<(&HudLine, &mut Text, &mut TextColor)>,
) {
    let now = real_time.elapsed_secs_f64();
    if sources.status.is_changed() && sources.status.0.is_some() {
        *news = News {
            text: sources.status.0.clone(),
            since: now,
        };
    }
    let recent = now - news.since < NEWS_SECONDS;
    let readings = sources.readings(news.text.clone().filter(|_| recent));
    for (line, mut text, mut shade) in &mut lines {
        // Only what changed is written, so change detection (and text layout) stays quiet.
        text.set_if_neq(Text(line.text(&readings)));
        shade.set_if_neq(TextColor(line.colour(&readings)));
    }
}
