//! The heads-up display: what the simulation is doing (integrator, step, parameters, time),
//! where the energy is, how much of it the integrator got wrong (the ledger's residual), and
//! the keys; the energy graph (`screen::graph`) and the window title ([`title`]) say the same
//! for a glance and for a hidden HUD.
//!
//! The numbers come from resources the physics keeps; this module only formats them, so its
//! text, history and title run headless too (the text is plain `Text` components). The graph
//! draws with gizmos and is added with the screen.

pub mod history;
pub mod pace;
pub mod title;

use bevy::diagnostic::{DiagnosticsStore, FrameTimeDiagnosticsPlugin};
use bevy::ecs::system::SystemParam;
use bevy::picking::Pickable;
use bevy::prelude::*;

use crate::game::layout::{Card, CardSpec, RegisterCard, Slot, Slots, card_line};
use crate::game::replays::playback::Playback;
use crate::game::replays::recording::Recorder;
use crate::game::schedule::ScreenSystems;
use crate::game::shared::{
    SceneName, StatusMessage, hertz, linear_damping_readout, readable, times,
};
use crate::game::simulation::{Band, Bodies, EnergyBooks, StepStats, mechanical_energies};
use crate::game::theme::{self, colour, size};
use crate::physics::{Energies, EnergyLedger, Integrator, Scene, SceneParams};
pub use history::EnergyHistory;
use pace::{Pace, behind, measure_pace};

pub struct HudPlugin;

impl Plugin for HudPlugin {
    fn build(&self, app: &mut App) {
        if !app.is_plugin_added::<FrameTimeDiagnosticsPlugin>() {
            app.add_plugins(FrameTimeDiagnosticsPlugin::default());
        }
        app.register_card(CardSpec::always(Card::READOUTS, "Readouts", 30))
            .register_card(CardSpec::always(Card::ENERGY, "Energy", 40))
            .add_plugins(history::EnergyHistoryPlugin)
            .init_resource::<Pace>()
            .add_systems(Startup, spawn_hud)
            .add_systems(
                Update,
                (measure_pace, (show_hud, title::show_state_in_title))
                    .chain()
                    .in_set(ScreenSystems::Hud),
            );
    }
}

impl Card {
    /// The scene, the integrator, the clock, the parameters, the replay.
    pub const READOUTS: Card = Card("readouts");
    /// The energies, the ledger and the energy graph.
    pub const ENERGY: Card = Card("energy");
}

pub const KINETIC_COLOUR: Color = colour::KINETIC;
pub const BAND_ENERGY_COLOUR: Color = colour::BAND_ENERGY;
pub const TOTAL_COLOUR: Color = colour::TOTAL;
const TEXT_COLOUR: Color = colour::TEXT;
const DIM_COLOUR: Color = colour::DIM;
const WARNING_COLOUR: Color = colour::WARNING;

/// One line of the HUD.
///
/// Each is a `Text` entity whose content [`HudLine::text`] writes, in the region `HudLine::slot`
/// names. The Stability and Ghosts cards write their own (`game::stability`, `game::ghosts`).
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
pub enum HudLine {
    /// Over the scene: what a player must always see.
    Status,
    /// Under the scene: how to play, in one line.
    Hint,
    SceneName,
    Integrator,
    Clock,
    Parameters,
    EnergyHeading,
    KineticLinear,
    KineticRotational,
    BandPotential,
    Total,
    Ledger,
    Residual,
    Replay,
}

impl HudLine {
    /// Every line with an entity of its own, in the order they are spawned.
    pub const SPAWNED: [HudLine; 14] = [
        HudLine::Status,
        HudLine::Hint,
        HudLine::SceneName,
        HudLine::Integrator,
        HudLine::Clock,
        HudLine::Parameters,
        HudLine::EnergyHeading,
        HudLine::KineticLinear,
        HudLine::KineticRotational,
        HudLine::BandPotential,
        HudLine::Total,
        HudLine::Ledger,
        HudLine::Residual,
        HudLine::Replay,
    ];

    /// Returns where the line lies.
    ///
    /// The status lies over the scene, the hint under it, the rest in the dock's cards.
    fn slot(self) -> Slot {
        match self {
            HudLine::Status => Slot::Status,
            HudLine::Hint => Slot::Hint,
            HudLine::SceneName
            | HudLine::Integrator
            | HudLine::Clock
            | HudLine::Parameters
            | HudLine::Replay => Slot::Card(Card::READOUTS),
            HudLine::EnergyHeading
            | HudLine::KineticLinear
            | HudLine::KineticRotational
            | HudLine::BandPotential
            | HudLine::Total
            | HudLine::Ledger
            | HudLine::Residual => Slot::Card(Card::ENERGY),
        }
    }

    /// Returns the line's size and face: figures of one width where numbers stand in columns.
    fn font(self) -> TextFont {
        match self {
            HudLine::Status => theme::text_font(size::TITLE),
            HudLine::Hint => theme::text_font(size::CAPTION),
            HudLine::KineticLinear
            | HudLine::KineticRotational
            | HudLine::BandPotential
            | HudLine::Total => theme::figures_font(size::READOUT),
            _ => theme::text_font(size::BODY),
        }
    }

    /// Returns the line's colour: the energy lines in their graph colours (the graph's legend).
    pub fn colour(self, readings: &HudReadings) -> Color {
        match self {
            HudLine::KineticLinear | HudLine::KineticRotational => KINETIC_COLOUR,
            HudLine::BandPotential => BAND_ENERGY_COLOUR,
            HudLine::Total => TOTAL_COLOUR,
            HudLine::Integrator if readings.divergence.is_some() => WARNING_COLOUR,
            HudLine::Status if readings.divergence.is_some() => WARNING_COLOUR,
            HudLine::Hint if readings.news.is_some() => TEXT_COLOUR,
            HudLine::EnergyHeading | HudLine::Hint | HudLine::Replay => DIM_COLOUR,
            _ => TEXT_COLOUR,
        }
    }

    pub fn text(self, r: &HudReadings) -> String {
        let e = &r.energies;
        match self {
            HudLine::Status => status_line(r),
            HudLine::Hint => r.news.clone().unwrap_or_else(|| HINT.to_owned()),
            HudLine::SceneName => {
                let summary =
                    Scene::named(&r.scene).map_or("a recorded game", |scene| scene.summary);
                format!("scene {}: {summary}", r.scene)
            }
            HudLine::Integrator => {
                let mut line = format!("integrator {}", r.integrator);
                if r.integrator == Integrator::Auto {
                    let latest = if r.fell_back {
                        "fell back to implicit (over budget)".to_owned()
                    } else {
                        format!(
                            "{} taylor step{}/step",
                            r.substeps,
                            if r.substeps == 1 { "" } else { "s" }
                        )
                    };
                    line += &format!(": {latest}, {} fall-backs to implicit", r.fallbacks);
                }
                if let Some((diverged, step)) = r.divergence {
                    line += &format!("  {diverged} DIVERGED at step {step}: steps refused");
                }
                line
            }
            HudLine::Clock => {
                let mut line = format!(
                    "step {:.2} ms ({})  time {}  t {:.2} s  {:.0} fps",
                    1e3 / r.step_rate_hz,
                    // The clock counts whole nanoseconds: 240 Hz steps at 239.99998 Hz, which
                    // three digits write as 240.
                    hertz(r.step_rate_hz),
                    times(r.time_scale),
                    r.simulated_seconds,
                    r.frames_per_second
                );
                if r.paused {
                    line += "  PAUSED (N: one step)";
                }
                line
            }
            HudLine::Parameters => format!(
                "m {}  k {}  damping: linear {}, angular {} /s",
                readable(r.mass),
                readable(r.stiffness),
                linear_damping_readout(r.linear_rate * r.mass, r.mass),
                readable(r.angular_rate)
            ),
            HudLine::EnergyHeading => "energy (mass · px²/s²)".to_owned(),
            HudLine::KineticLinear => format!("  kinetic, linear   {}", energy(e.linear)),
            HudLine::KineticRotational => format!("  kinetic, rotation {}", energy(e.rotational)),
            HudLine::BandPotential => format!("  band potential    {}", energy(e.band)),
            HudLine::Total => format!("  total             {}", energy(e.total())),
            HudLine::Ledger => format!(
                "  hand's work in {}  damping out {}",
                energy(r.ledger.work_in).trim_start(),
                energy(r.ledger.dissipated).trim_start()
            ),
            HudLine::Residual => {
                let throughput = r.ledger.throughput();
                let relative = if throughput > 0.0 {
                    format!("{:.1e}", r.residual.abs() / throughput)
                } else {
                    "-".to_owned()
                };
                format!(
                    "  integrator's error {:+.2e} ({relative} of energy through)",
                    r.residual
                )
            }
            HudLine::Replay => {
                let mut line = format!("recorded {} steps", r.recorded_steps);
                if let Some((played, steps)) = r.playback {
                    line = format!("replay: step {played} of {steps} (press to take over)  {line}");
                }
                if let Some(status) = &r.status {
                    line += &format!("  {status}");
                }
                line
            }
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
fn status_line(r: &HudReadings) -> String {
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

/// Writes an energy fixed-point in the usual range, in scientific notation outside it.
fn energy(value: f64) -> String {
    // An empty sum is −0.0 in Rust: show it as 0.
    let value = value + 0.0;
    if value == 0.0 || (1e-2..1e7).contains(&value.abs()) {
        format!("{value:>12.2}")
    } else {
        format!("{value:>12.3e}")
    }
}

/// Everything the HUD shows, gathered from the resources.
#[derive(Debug, Clone, PartialEq)]
pub struct HudReadings {
    pub integrator: Integrator,
    pub substeps: u32,
    /// The latest step fell back: `auto` was over its budget and took one `implicit` step.
    pub fell_back: bool,
    pub fallbacks: u64,
    pub divergence: Option<(Integrator, u64)>,
    pub step_rate_hz: f64,
    pub time_scale: f64,
    pub paused: bool,
    pub simulated_seconds: f64,
    /// The share of the set pace the game's clock keeps ([`Pace`]).
    pub pace: f64,
    pub frames_per_second: f64,
    pub mass: f64,
    pub stiffness: f64,
    /// Velocity decay rates, per second.
    pub linear_rate: f64,
    pub angular_rate: f64,
    pub energies: Energies,
    pub ledger: EnergyLedger,
    pub residual: f64,
    /// Steps in the recording so far, and what the latest save said.
    pub recorded_steps: u64,
    pub status: Option<String>,
    /// The latest status while it is news ([`NEWS_SECONDS`]).
    ///
    /// The hint line says it, so that a player sees it with the dock's cards folded.
    pub news: Option<String>,
    /// While a replay plays back: (steps played, steps in it).
    pub playback: Option<(u64, u64)>,
    /// The scene's name (the core's table's, or a recording's).
    pub scene: String,
}

#[derive(SystemParam)]
pub struct HudSources<'w, 's> {
    integrator: Res<'w, Integrator>,
    stats: Res<'w, StepStats>,
    params: Res<'w, SceneParams>,
    books: Res<'w, EnergyBooks>,
    virtual_time: Res<'w, Time<Virtual>>,
    pace: Res<'w, Pace>,
    fixed_time: Res<'w, Time<Fixed>>,
    diagnostics: Res<'w, DiagnosticsStore>,
    history: Res<'w, EnergyHistory>,
    recorder: Res<'w, Recorder>,
    status: Res<'w, StatusMessage>,
    playback: Res<'w, Playback>,
    scene: Res<'w, SceneName>,
    boxes: Bodies<'w, 's>,
    bands: Query<'w, 's, &'static Band>,
}

impl HudSources<'_, '_> {
    pub fn readings(&self) -> HudReadings {
        let params = &*self.params;
        let mass = self
            .boxes
            .iter()
            .next()
            .map_or(params.mass, |body| body.mass.mass());
        let step = self.fixed_time.timestep().as_secs_f64();
        HudReadings {
            integrator: *self.integrator,
            substeps: self.stats.substeps,
            fell_back: self.stats.fell_back,
            fallbacks: self.stats.fallbacks,
            divergence: self.stats.divergence,
            // The clock's step, which a refused rate leaves as it was.
            step_rate_hz: 1.0 / step,
            time_scale: self.virtual_time.relative_speed_f64(),
            paused: self.virtual_time.is_paused(),
            simulated_seconds: self.fixed_time.elapsed_secs_f64() - self.history.since,
            pace: self.pace.0,
            frames_per_second: self
                .diagnostics
                .get(&FrameTimeDiagnosticsPlugin::FPS)
                .and_then(|fps| fps.smoothed())
                .unwrap_or(0.0),
            mass,
            stiffness: params.stiffness,
            linear_rate: params.linear_damping / mass,
            angular_rate: params.angular_damping,
            // Now, not at the last step: the band moves while paused too.
            energies: mechanical_energies(params, &self.boxes, &self.bands),
            ledger: self.books.ledger,
            residual: self.books.residual,
            recorded_steps: self.recorder.steps(),
            status: self.status.0.clone(),
            news: None,
            playback: self.playback.progress(),
            scene: self.scene.0.clone(),
        }
    }
}

/// A text of the HUD (its lines).
#[derive(Component, Debug)]
pub struct Hud;

fn spawn_hud(mut commands: Commands, slots: Slots) {
    for line in HudLine::SPAWNED {
        let Some(parent) = slots.find(line.slot()) else {
            continue;
        };
        let mut spawned = commands.spawn((
            Name::new(format!("HUD {line:?}")),
            Hud,
            line,
            ChildOf(parent),
        ));
        if let Slot::Card(_) = line.slot() {
            spawned.insert(card_line("", line.font(), TEXT_COLOUR));
            continue;
        }
        // The hint line holds one line whatever it says (a long status is cut at the window's
        // edge), so that nothing below it moves when a message comes and goes.
        let layout = if line == HudLine::Hint {
            TextLayout::no_wrap()
        } else {
            TextLayout::default()
        };
        spawned.insert((
            Text::default(),
            layout,
            line.font(),
            TextColor(TEXT_COLOUR),
            Pickable::IGNORE,
            Node::default(),
            BackgroundColor(Color::NONE),
        ));
    }
}

fn show_hud(
    sources: HudSources,
    real_time: Res<Time<Real>>,
    mut news: Local<News>,
    mut lines: Query<(&HudLine, &mut Text, &mut TextColor)>,
) {
    let mut readings = sources.readings();
    let now = real_time.elapsed_secs_f64();
    if sources.status.is_changed() && sources.status.0.is_some() {
        *news = News {
            text: sources.status.0.clone(),
            since: now,
        };
    }
    if now - news.since < NEWS_SECONDS {
        readings.news.clone_from(&news.text);
    }
    for (line, mut text, mut colour) in &mut lines {
        // Only write what changed, so change detection (and text layout) stays quiet.
        let content = line.text(&readings);
        if text.0 != content {
            text.0 = content;
        }
        colour.set_if_neq(TextColor(line.colour(&readings)));
    }
}
