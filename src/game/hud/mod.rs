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

use crate::game::ghosts::{GhostKind, Ghosts};
use crate::game::input::controls::help_line;
use crate::game::layout::{Card, CardSpec, RegisterCard, Slot};
use crate::game::replays::playback::Playback;
use crate::game::replays::recording::Recorder;
use crate::game::schedule::ScreenSystems;
use crate::game::shared::{SceneName, StatusMessage, linear_damping_readout, readable};
use crate::game::simulation::{Band, Bodies, EnergyBooks, StepStats, mechanical_energies};
use crate::game::stability::StabilityMargins;
use crate::game::theme::{self, colour, size, space};
use crate::physics::stability::{Limit, Margin};
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
            .register_card(CardSpec {
                card: Card::GHOSTS,
                title: "Ghosts",
                place: 50,
                offered: |overlays, _| overlays.ghosts,
            })
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
    /// The ghosts' table (with the ghosts on).
    pub const GHOSTS: Card = Card("ghosts");
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
/// names; the ghosts' table is a grid of cells of its own (`ghost_table`), its text the same
/// cells a row a line.
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
    Ghosts,
    Help,
}

impl HudLine {
    /// Every line with an entity of its own, in the order they are spawned.
    pub const SPAWNED: [HudLine; 15] = [
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
        HudLine::Help,
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
            HudLine::Ghosts => Slot::Card(Card::GHOSTS),
            HudLine::Help => Slot::Card(Card::CONTROLS),
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
            HudLine::Hint | HudLine::Help => theme::text_font(size::CAPTION),
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
            HudLine::EnergyHeading
            | HudLine::Help
            | HudLine::Hint
            | HudLine::Replay
            | HudLine::Ghosts => DIM_COLOUR,
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
            HudLine::Ghosts => ghost_lines(r),
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
                    "step {:.2} ms ({} Hz)  time x{}  t {:.2} s  {:.0} fps",
                    1e3 / r.step_rate_hz,
                    // The clock counts whole nanoseconds: 240 Hz steps at 239.99998 Hz.
                    format!("{:.2}", r.step_rate_hz)
                        .trim_end_matches('0')
                        .trim_end_matches('.'),
                    r.time_scale,
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
            HudLine::Help => help_line(),
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
        "{} · k {} · {} Hz · time ×{} · t {:.1} s",
        r.integrator,
        readable(r.stiffness),
        readable(r.step_rate_hz),
        readable(r.time_scale),
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

/// The ghosts' table's columns.
const GHOST_COLUMNS: [&str; 6] = [
    "method", "error px", "energy", "ns/step", "evals", "holds k",
];

/// Returns the ghosts' table: a header and a row per ghost, each cell its text.
///
/// A row's cells read left to right: the ghost's distance from the reference, its energy residual,
/// its time and work per step, and the stiffest band its method holds at this step. Empty while the
/// ghosts are off.
fn ghost_table(r: &HudReadings) -> Vec<[String; 6]> {
    if r.ghosts.is_empty() {
        return Vec::new();
    }
    let mut rows = vec![GHOST_COLUMNS.map(str::to_owned)];
    for g in &r.ghosts {
        let name = if g.live {
            format!("{} (live)", g.name)
        } else {
            g.name.to_owned()
        };
        let margin = r.margins.iter().find(|m| m.integrator.name() == g.name);
        let holds = match (margin, g.capped) {
            (Some(margin), _) => stability_short(margin),
            (None, 0) => String::new(),
            (None, capped) => format!("capped {capped}"),
        };
        let work = if g.substeps > 1 {
            format!("{}×{}", g.substeps, g.evaluations)
        } else {
            g.evaluations.to_string()
        };
        let row = match g.diverged_at {
            Some(step) => [
                name,
                "DIVERGED".to_owned(),
                format!("@{step}"),
                String::new(),
                String::new(),
                holds,
            ],
            None => [
                name,
                g.distance.map_or("-".to_owned(), |d| format!("{d:.1e}")),
                format!("{:+.1e}", g.residual),
                format!("{:.0}", g.ns_per_step),
                work,
                holds,
            ],
        };
        rows.push(row);
    }
    rows
}

/// Writes the table as text, a row a line, its cells two spaces apart.
///
/// A test or a terminal reads it.
fn ghost_lines(r: &HudReadings) -> String {
    ghost_table(r)
        .iter()
        .map(|row| {
            row.iter()
                .filter(|cell| !cell.is_empty())
                .cloned()
                .collect::<Vec<_>>()
                .join("  ")
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// Writes a ghost's margin, short: whether it holds the band and up to which k.
fn stability_short(margin: &Margin) -> String {
    match (margin.stiffest, margin.holds) {
        (Limit::Any, _) => "any k".to_owned(),
        (Limit::Never, _) => "✗ no k".to_owned(),
        (Limit::UpTo(k), true) => format!("k<{}", number(k)),
        (Limit::UpTo(k), false) => format!("✗ k<{}", number(k)),
    }
}

/// Writes a number as a person reads it: whole below 10⁴, two digits in powers of ten above.
fn number(value: f64) -> String {
    if value < 1e4 {
        format!("{value:.0}")
    } else {
        format!("{value:.1e}")
    }
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
    /// Every ghost, while they are on.
    pub ghosts: Vec<GhostReading>,
    /// Every integrator's distance from instability now.
    pub margins: Vec<Margin>,
}

/// What the HUD says about one ghost.
#[derive(Debug, Clone, PartialEq)]
pub struct GhostReading {
    pub name: &'static str,
    /// Its colour, in its outline, its row and its point.
    pub colour: Color,
    /// The live box's integrator.
    pub live: bool,
    pub distance: Option<f64>,
    pub residual: f64,
    pub substeps: u32,
    pub evaluations: u32,
    pub ns_per_step: f64,
    pub diverged_at: Option<u64>,
    pub capped: u64,
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
    ghosts: Res<'w, Ghosts>,
    margins: Res<'w, StabilityMargins>,
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
            ghosts: self
                .ghosts
                .ghosts
                .iter()
                .map(|ghost| GhostReading {
                    name: ghost.kind.name(),
                    colour: ghost.kind.colour(),
                    live: ghost.kind == GhostKind::Method(*self.integrator),
                    distance: self.ghosts.distance_from_reference(ghost),
                    residual: ghost.residual(),
                    substeps: ghost.last.substeps,
                    evaluations: ghost.last.evaluations,
                    ns_per_step: ghost.ns_per_step,
                    diverged_at: ghost.diverged_at,
                    capped: ghost.capped,
                })
                .collect(),
            margins: self.margins.0.clone(),
        }
    }
}

/// A text of the HUD (its lines and its table).
#[derive(Component, Debug)]
pub struct Hud;

/// A cell of the ghosts' table: its row (0 the header) and column.
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
pub struct GhostCell {
    pub row: usize,
    pub column: usize,
}

/// Rows the table has room for: the header, every integrator and the reference.
const GHOST_ROWS: usize = Integrator::ALL.len() + 2;

fn spawn_hud(mut commands: Commands, slots: Query<(Entity, &Slot)>) {
    let slot = |wanted: Slot| {
        slots
            .iter()
            .find(|(_, slot)| **slot == wanted)
            .map(|(entity, _)| entity)
    };
    for line in HudLine::SPAWNED {
        let Some(parent) = slot(line.slot()) else {
            continue;
        };
        let padding = match line.slot() {
            Slot::Card(_) => UiRect::axes(px(space::PAD + 2.0), px(1)),
            _ => UiRect::ZERO,
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
            Hud,
            line,
            Text::default(),
            layout,
            line.font(),
            TextColor(TEXT_COLOUR),
            Pickable::IGNORE,
            Node {
                padding,
                ..default()
            },
            BackgroundColor(match line.slot() {
                Slot::Card(_) => colour::CARD,
                _ => Color::NONE,
            }),
            ChildOf(parent),
        ));
    }
    // The ghosts' table: a grid, so that its columns line up in any face.
    let Some(card) = slot(Slot::Card(Card::GHOSTS)) else {
        return;
    };
    let grid = commands
        .spawn((
            Name::new("Ghosts' table"),
            Hud,
            Pickable::IGNORE,
            Node {
                display: Display::Grid,
                grid_template_columns: vec![RepeatedGridTrack::auto(GHOST_COLUMNS.len() as u16)],
                column_gap: px(space::GAP),
                padding: UiRect::all(px(space::GAP)),
                ..default()
            },
            BackgroundColor(colour::CARD),
            ChildOf(card),
        ))
        .id();
    for row in 0..GHOST_ROWS {
        for column in 0..GHOST_COLUMNS.len() {
            let font = if column == 0 || row == 0 {
                theme::text_font(size::CAPTION)
            } else {
                theme::figures_font(size::CAPTION)
            };
            commands.spawn((
                GhostCell { row, column },
                Text::default(),
                font,
                TextColor(if row == 0 { DIM_COLOUR } else { TEXT_COLOUR }),
                Pickable::IGNORE,
                Node {
                    justify_self: if column == 0 {
                        JustifySelf::Start
                    } else {
                        JustifySelf::End
                    },
                    ..default()
                },
                ChildOf(grid),
            ));
        }
    }
}

fn show_hud(
    sources: HudSources,
    real_time: Res<Time<Real>>,
    mut news: Local<News>,
    mut lines: Query<(&HudLine, &mut Text, &mut TextColor), Without<GhostCell>>,
    mut cells: Query<(&GhostCell, &mut Text, &mut TextColor, &mut Node), Without<HudLine>>,
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
    let table = ghost_table(&readings);
    for (cell, mut text, mut colour, mut node) in &mut cells {
        let content = table
            .get(cell.row)
            .map_or("", |row| row[cell.column].as_str());
        if text.0 != content {
            text.0 = content.to_owned();
        }
        // A row with nothing in it takes no room.
        let display = if cell.row < table.len() {
            Display::Flex
        } else {
            Display::None
        };
        if node.display != display {
            node.display = display;
        }
        let ghost = cell
            .row
            .checked_sub(1)
            .and_then(|index| readings.ghosts.get(index));
        let wanted = match ghost {
            None => DIM_COLOUR,
            Some(g) if g.diverged_at.is_some() && cell.column > 0 => WARNING_COLOUR,
            Some(g) if cell.column == 0 => g.colour,
            Some(_) if cell.column == 5 && content.starts_with('✗') => WARNING_COLOUR,
            Some(_) => TEXT_COLOUR,
        };
        colour.set_if_neq(TextColor(wanted));
    }
}
