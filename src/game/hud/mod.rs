//! The heads-up display: what the simulation is doing (integrator, step, parameters, time),
//! where the energy is, how much of it the integrator got wrong (the ledger's residual), and
//! the keys; the energy graph ([`graph`]) and the window title ([`title`]) say the same for a
//! glance and for a hidden HUD.
//!
//! The numbers come from resources the physics keeps; this module only formats them, so its
//! text, history and title run headless too (the text is plain `Text` components). The graph
//! draws with gizmos and is added with the screen.

pub mod history;
pub mod title;

use bevy::diagnostic::{DiagnosticsStore, FrameTimeDiagnosticsPlugin};
use bevy::ecs::system::SystemParam;
use bevy::picking::Pickable;
use bevy::prelude::*;

use crate::game::ghosts::{GhostKind, Ghosts};
use crate::game::input::controls::help_line;
use crate::game::replays::playback::Playback;
use crate::game::replays::recording::Recorder;
use crate::game::schedule::{AfterBevySystems, ScreenSystems};
use crate::game::shared::{
    HudArea, Overlays, SceneName, StatusMessage, linear_damping_readout, readable, window_rect,
};
use crate::game::simulation::{Band, Bodies, EnergyBooks, StepStats, mechanical_energies};
use crate::game::stability::StabilityMargins;
use crate::physics::stability::{Limit, Margin};
use crate::physics::{Energies, EnergyLedger, Integrator, Scenario, SceneParams};
pub use history::EnergyHistory;

pub struct HudPlugin;

impl Plugin for HudPlugin {
    fn build(&self, app: &mut App) {
        if !app.is_plugin_added::<FrameTimeDiagnosticsPlugin>() {
            app.add_plugins(FrameTimeDiagnosticsPlugin::default());
        }
        app.add_plugins(history::EnergyHistoryPlugin)
            .add_systems(Startup, spawn_hud)
            .add_systems(
                Update,
                (show_hud, title::show_state_in_title).in_set(ScreenSystems::Hud),
            )
            .add_systems(
                PostUpdate,
                publish_area.in_set(AfterBevySystems::AfterLayout),
            );
    }
}

pub const KINETIC_COLOUR: Color = Color::srgb(0.35, 0.75, 1.0);
pub const BAND_ENERGY_COLOUR: Color = Color::srgb(1.0, 0.3, 0.8);
pub const TOTAL_COLOUR: Color = Color::srgb(1.0, 0.85, 0.2);
const TEXT_COLOUR: Color = Color::srgb(0.9, 0.9, 0.9);
const DIM_COLOUR: Color = Color::srgb(0.6, 0.6, 0.65);
const WARNING_COLOUR: Color = Color::srgb(1.0, 0.4, 0.3);
const BACKDROP_COLOUR: Color = Color::srgba(0.0, 0.0, 0.0, 0.55);
const FONT_SIZE: f32 = 13.0;
const HELP_FONT_SIZE: f32 = 12.0;

/// One line of the HUD. Each is a `Text` entity whose content [`HudLine::text`] writes.
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
pub enum HudLine {
    SceneName,
    Integrator,
    Clock,
    Parameters,
    Stability,
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
    /// The column's lines, top to bottom (the ghosts' list and the help line sit apart, at
    /// the bottom).
    pub const COLUMN: [HudLine; 13] = [
        HudLine::SceneName,
        HudLine::Integrator,
        HudLine::Clock,
        HudLine::Parameters,
        HudLine::Stability,
        HudLine::EnergyHeading,
        HudLine::KineticLinear,
        HudLine::KineticRotational,
        HudLine::BandPotential,
        HudLine::Total,
        HudLine::Ledger,
        HudLine::Residual,
        HudLine::Replay,
    ];

    /// The line's colour: the energy lines in their graph colours (the graph's legend).
    pub fn colour(self, readings: &HudReadings) -> Color {
        match self {
            HudLine::KineticLinear | HudLine::KineticRotational => KINETIC_COLOUR,
            HudLine::BandPotential => BAND_ENERGY_COLOUR,
            HudLine::Total => TOTAL_COLOUR,
            HudLine::Integrator if readings.divergence.is_some() => WARNING_COLOUR,
            HudLine::Stability if readings.live_margin().is_some_and(|m| !m.holds) => {
                WARNING_COLOUR
            }
            HudLine::EnergyHeading | HudLine::Help | HudLine::Replay | HudLine::Ghosts => {
                DIM_COLOUR
            }
            _ => TEXT_COLOUR,
        }
    }

    pub fn text(self, r: &HudReadings) -> String {
        let e = &r.energies;
        match self {
            HudLine::SceneName => {
                let summary = Scenario::named(&r.scene)
                    .map_or("a recorded game", |scenario| scenario.summary);
                format!("scene {}: {summary}", r.scene)
            }
            HudLine::Ghosts => ghost_lines(r),
            HudLine::Stability => match r.live_margin() {
                Some(margin) => format!("stability: {}", stability_text(margin)),
                None => String::new(),
            },
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
            HudLine::EnergyHeading => "energy (mass px^2/s^2)".to_owned(),
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

/// A line per ghost: its distance from the reference, its energy residual, its work and
/// time per step; empty while the ghosts are off.
fn ghost_lines(r: &HudReadings) -> String {
    if r.ghosts.is_empty() {
        return String::new();
    }
    let mut text =
        "ghosts: distance from the reference, energy residual, work and time per step, k held"
            .to_owned();
    for g in &r.ghosts {
        let live = if g.live { " (live)" } else { "" };
        let name = format!("{}{live}", g.name);
        text += &format!("\n  {name:<17}");
        let margin = r.margins.iter().find(|m| m.integrator.name() == g.name);
        let margin = margin.map_or(String::new(), |m| format!("  {}", stability_short(m)));
        if let Some(step) = g.diverged_at {
            text += &format!("DIVERGED at step {step} (frozen){margin}");
            continue;
        }
        let distance = g.distance.map_or("-".to_owned(), |d| format!("{d:.1e} px"));
        let work = if g.substeps > 1 {
            format!("{} substeps, {} evals", g.substeps, g.evaluations)
        } else {
            format!("{} evals", g.evaluations)
        };
        text += &format!(
            "{distance:>10}  {:>+9.1e}  {work:<22} {:>7.0} ns",
            g.residual, g.ns_per_step
        );
        if g.capped > 0 {
            text += &format!("  capped {} steps", g.capped);
        }
        text += &margin;
    }
    text
}

/// The live integrator's margin, said in full: ω·dt now against the method's limit at this
/// damping, and the stiffest band it holds.
fn stability_text(margin: &Margin) -> String {
    let now = format!("{} at omega*dt {:.2}", margin.integrator, margin.omega_dt);
    match margin.stiffest {
        Limit::Any => format!("{now}, stable at any k"),
        Limit::Never => format!("{now}: UNSTABLE at any k without more damping"),
        Limit::UpTo(k) => {
            let limit = margin.limit_omega_dt.unwrap_or(f64::NAN);
            if margin.holds {
                format!("{now} of {limit:.2}: holds k up to {}", number(k))
            } else {
                format!("{now}, past its {limit:.2}: UNSTABLE above k {}", number(k))
            }
        }
    }
}

/// A ghost's margin, short: whether it holds the band and up to which k.
fn stability_short(margin: &Margin) -> String {
    match (margin.stiffest, margin.holds) {
        (Limit::Any, _) => "any k".to_owned(),
        (Limit::Never, _) => "no k".to_owned(),
        (Limit::UpTo(k), true) => format!("k<{}", number(k)),
        (Limit::UpTo(k), false) => format!("UNSTABLE: k<{}", number(k)),
    }
}

/// A number as a person reads it: whole below 10⁴, two digits in powers of ten above.
fn number(value: f64) -> String {
    if value < 1e4 {
        format!("{value:.0}")
    } else {
        format!("{value:.1e}")
    }
}

/// Energies are shown fixed-point in the usual range, in scientific notation outside it.
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
    /// While a replay plays back: (steps played, steps in it).
    pub playback: Option<(u64, u64)>,
    /// The scene's name (the core's table's, or a recording's).
    pub scene: String,
    /// Every ghost, while they are on.
    pub ghosts: Vec<GhostReading>,
    /// Every integrator's distance from instability now.
    pub margins: Vec<Margin>,
}

impl HudReadings {
    /// The live integrator's margin.
    pub fn live_margin(&self) -> Option<&Margin> {
        self.margins
            .iter()
            .find(|m| m.integrator == self.integrator)
    }
}

/// What the HUD says about one ghost.
#[derive(Debug, Clone, PartialEq)]
pub struct GhostReading {
    pub name: &'static str,
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
            .map_or(params.mass, |(_, _, mass)| mass.mass());
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
            playback: self.playback.progress(),
            scene: self.scene.0.clone(),
            ghosts: self
                .ghosts
                .ghosts
                .iter()
                .map(|ghost| GhostReading {
                    name: ghost.kind.name(),
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

/// The HUD's root: hidden with the H key.
#[derive(Component, Debug)]
pub struct Hud;

fn spawn_hud(mut commands: Commands) {
    // The HUD only shows: a press where it lies over the panel (a long line on a small
    // screen) goes through to the panel's button.
    let text = |line: HudLine, size: f32| {
        (
            line,
            Text::default(),
            TextFont::from_font_size(size),
            TextColor(TEXT_COLOUR),
            Pickable::IGNORE,
        )
    };
    let column = commands
        .spawn((
            Name::new("HUD column"),
            Hud,
            Pickable::IGNORE,
            Node {
                position_type: PositionType::Absolute,
                top: px(6),
                left: px(6),
                flex_direction: FlexDirection::Column,
                padding: UiRect::all(px(6)),
                ..default()
            },
            BackgroundColor(BACKDROP_COLOUR),
        ))
        .id();
    for line in HudLine::COLUMN {
        commands.spawn((text(line, FONT_SIZE), ChildOf(column)));
    }
    // Bottom left, above the help line: on a short screen (a phone turned) the HUD's column
    // and this list together would reach down over the box's start.
    commands.spawn((
        Name::new("HUD ghosts"),
        Hud,
        text(HudLine::Ghosts, FONT_SIZE),
        Node {
            position_type: PositionType::Absolute,
            bottom: px(40),
            left: px(6),
            ..default()
        },
        BackgroundColor(BACKDROP_COLOUR),
    ));
    commands.spawn((
        Name::new("HUD help"),
        Hud,
        text(HudLine::Help, HELP_FONT_SIZE),
        Node {
            position_type: PositionType::Absolute,
            bottom: px(6),
            left: px(6),
            right: px(6),
            ..default()
        },
    ));
}

fn show_hud(
    sources: HudSources,
    overlays: Res<Overlays>,
    mut roots: Query<&mut Visibility, With<Hud>>,
    mut lines: Query<(&HudLine, &mut Text, &mut TextColor, &mut Node)>,
) {
    let visibility = if overlays.hud_hidden {
        Visibility::Hidden
    } else {
        Visibility::Inherited
    };
    for mut shown in &mut roots {
        shown.set_if_neq(visibility);
    }
    let readings = sources.readings();
    for (line, mut text, mut colour, mut node) in &mut lines {
        // Only write what changed, so change detection (and text layout) stays quiet.
        let content = line.text(&readings);
        // The ghosts' list has a box of its own: none while the ghosts are off.
        if *line == HudLine::Ghosts {
            let display = if content.is_empty() {
                Display::None
            } else {
                Display::Flex
            };
            if node.display != display {
                node.display = display;
            }
        }
        if text.0 != content {
            text.0 = content;
        }
        colour.set_if_neq(TextColor(line.colour(&readings)));
    }
}

/// Where the HUD's shown boxes lie on the window, for the view to fit the scene clear of them
/// (none while H hides the HUD; a box with nothing to show, the ghosts' list while they are
/// off, has no size).
fn publish_area(
    boxes: Query<(&ComputedNode, &UiGlobalTransform), With<Hud>>,
    overlays: Res<Overlays>,
    ui_scale: Res<UiScale>,
    mut area: ResMut<HudArea>,
) {
    let rects: Vec<Rect> = boxes
        .iter()
        .filter(|_| !overlays.hud_hidden)
        .map(|(node, transform)| window_rect(node, transform, &ui_scale))
        .filter(|rect| !rect.is_empty())
        .collect();
    if area.0 != rects {
        area.0 = rects;
    }
}
