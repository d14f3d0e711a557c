//! The dock's Readouts card: the scene, the integrator and its substeps, the clock, the
//! parameters and the replay, each a line it formats from the resources the physics and the
//! replays keep. Registered with the dock here; nothing outside this folder names it but the
//! game's wiring.

use bevy::diagnostic::{DiagnosticsStore, FrameTimeDiagnosticsPlugin};
use bevy::ecs::system::SystemParam;
use bevy::prelude::*;

use crate::game::input::controls::Parameter;
use crate::game::layout::{Card, CardSpec, RegisterCard, Slots, card_line};
use crate::game::replays::playback::Playback;
use crate::game::replays::recording::Recorder;
use crate::game::shared::{SceneName, StatusMessage};
use crate::game::simulation::{Bodies, Clocks, StepStats};
use crate::game::theme::{self, colour, size};
use crate::game::theme::{hertz, times};
use crate::physics::{Integrator, Scene, SceneParams};

impl Card {
    /// The scene, the integrator, the clock, the parameters, the replay.
    pub const READOUTS: Card = Card("readouts");
}

/// The Readouts card: registered with the dock and filled each frame.
pub struct ReadoutsPlugin;

impl Plugin for ReadoutsPlugin {
    fn build(&self, app: &mut App) {
        if !app.is_plugin_added::<FrameTimeDiagnosticsPlugin>() {
            app.add_plugins(FrameTimeDiagnosticsPlugin::default());
        }
        app.add_text_card(
            CardSpec::always(Card::READOUTS, "Readouts", 30),
            spawn_lines,
            show_lines,
        );
    }
}

/// One line of the card, a `Text` entity named "Readouts" and the line.
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
enum ReadoutLine {
    Scene,
    Integrator,
    Clock,
    Parameters,
    Replay,
}

impl ReadoutLine {
    /// Every line, in the card's order.
    const ALL: [ReadoutLine; 5] = [
        ReadoutLine::Scene,
        ReadoutLine::Integrator,
        ReadoutLine::Clock,
        ReadoutLine::Parameters,
        ReadoutLine::Replay,
    ];

    /// Returns the line's colour: the integrator's in the warning colour once it diverged.
    fn colour(self, r: &Readings) -> Color {
        match self {
            ReadoutLine::Integrator if r.divergence.is_some() => colour::WARNING,
            ReadoutLine::Replay => colour::DIM,
            _ => colour::TEXT,
        }
    }

    /// Returns what the line says of the readings.
    fn text(self, r: &Readings) -> String {
        match self {
            ReadoutLine::Scene => {
                let summary =
                    Scene::named(&r.scene).map_or("a recorded game", |scene| scene.summary);
                format!("scene {}: {summary}", r.scene)
            }
            ReadoutLine::Integrator => {
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
            ReadoutLine::Clock => {
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
            ReadoutLine::Parameters => format!(
                "m {}  k {}  damping: linear {}, angular {}",
                Parameter::Mass.written(r.mass, None),
                Parameter::Stiffness.written(r.stiffness, None),
                Parameter::LinearDamping.written(r.linear_rate * r.mass, Some(r.mass)),
                Parameter::AngularDamping.written(r.angular_rate, None)
            ),
            ReadoutLine::Replay => {
                let mut line = format!("recorded {} steps", r.recorded_steps);
                match (r.playback, &r.ended) {
                    (Some((played, steps)), _) => {
                        line = format!(
                            "replay: step {played} of {steps} (press to take over)  {line}"
                        );
                    }
                    (None, Some(ended)) => line += &format!("  {ended}"),
                    (None, None) => {}
                }
                if let Some(status) = &r.status {
                    line += &format!("  {status}");
                }
                line
            }
        }
    }
}

/// Everything the card shows, gathered from the resources.
#[derive(Debug, Clone, PartialEq)]
struct Readings {
    integrator: Integrator,
    substeps: u32,
    /// The latest step fell back: `auto` was over its budget and took one `implicit` step.
    fell_back: bool,
    fallbacks: u64,
    divergence: Option<(Integrator, u64)>,
    step_rate_hz: f64,
    time_scale: f64,
    paused: bool,
    simulated_seconds: f64,
    frames_per_second: f64,
    mass: f64,
    stiffness: f64,
    /// Velocity decay rates, per second.
    linear_rate: f64,
    angular_rate: f64,
    /// Steps in the recording so far, and what the latest save said.
    recorded_steps: u64,
    status: Option<String>,
    /// While a replay plays back: (steps played, steps in it).
    playback: Option<(u64, u64)>,
    /// How the latest playback ended, in full (its steps and hashes), once it has.
    ended: Option<String>,
    /// The scene's name (the core's table's, or a recording's).
    scene: String,
}

/// The resources the card reads.
#[derive(SystemParam)]
struct Sources<'w, 's> {
    integrator: Res<'w, Integrator>,
    stats: Res<'w, StepStats>,
    params: Res<'w, SceneParams>,
    clocks: Clocks<'w>,
    diagnostics: Res<'w, DiagnosticsStore>,
    recorder: Res<'w, Recorder>,
    status: Res<'w, StatusMessage>,
    playback: Res<'w, Playback>,
    scene: Res<'w, SceneName>,
    boxes: Bodies<'w, 's>,
}

impl Sources<'_, '_> {
    fn readings(&self) -> Readings {
        let params = &*self.params;
        let mass = self
            .boxes
            .iter()
            .next()
            .map_or(params.mass, |body| body.mass.mass());
        Readings {
            integrator: *self.integrator,
            substeps: self.stats.substeps,
            fell_back: self.stats.fell_back,
            fallbacks: self.stats.fallbacks,
            divergence: self.stats.divergence,
            step_rate_hz: self.clocks.step_rate_hz(),
            time_scale: self.clocks.time_scale(),
            paused: self.clocks.paused(),
            simulated_seconds: self.clocks.since_reset(),
            frames_per_second: self
                .diagnostics
                .get(&FrameTimeDiagnosticsPlugin::FPS)
                .and_then(|fps| fps.smoothed())
                .unwrap_or(0.0),
            mass,
            stiffness: params.stiffness,
            linear_rate: params.linear_damping / mass,
            angular_rate: params.angular_damping,
            recorded_steps: self.recorder.steps(),
            status: self.status.0.clone(),
            playback: self.playback.progress(),
            ended: self.playback.ended.map(|end| end.describe()),
            scene: self.scene.0.clone(),
        }
    }
}

fn spawn_lines(mut commands: Commands, slots: Slots) {
    let Some(card) = slots.card_body(Card::READOUTS) else {
        return;
    };
    for line in ReadoutLine::ALL {
        commands.spawn((
            Name::new(format!("Readouts {line:?}")),
            line,
            card_line("", theme::text_font(size::BODY), colour::TEXT),
            ChildOf(card),
        ));
    }
}

fn show_lines(sources: Sources, mut lines: Query<(&ReadoutLine, &mut Text, &mut TextColor)>) {
    let readings = sources.readings();
    for (line, mut text, mut shade) in &mut lines {
        // Only what changed is written, so change detection (and text layout) stays quiet.
        text.set_if_neq(Text(line.text(&readings)));
        shade.set_if_neq(TextColor(line.colour(&readings)));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn readings() -> Readings {
        Readings {
            integrator: Integrator::Auto,
            substeps: 3,
            fell_back: false,
            fallbacks: 0,
            divergence: None,
            step_rate_hz: 100.0,
            time_scale: 1.0,
            paused: false,
            simulated_seconds: 1.5,
            frames_per_second: 60.0,
            mass: 5.0,
            stiffness: 20.0,
            linear_rate: 1.0,
            angular_rate: 2.0203,
            recorded_steps: 150,
            status: None,
            playback: None,
            ended: None,
            scene: "tutorial".to_owned(),
        }
    }

    #[test]
    fn lines_say_what_the_readings_hold() {
        let r = readings();
        assert_eq!(
            ReadoutLine::Integrator.text(&r),
            "integrator auto: 3 taylor steps/step, 0 fall-backs to implicit"
        );
        assert!(
            ReadoutLine::Clock
                .text(&r)
                .starts_with("step 10.00 ms (100 Hz)")
        );
        assert!(!ReadoutLine::Clock.text(&r).contains("PAUSED"));
        assert!(ReadoutLine::Parameters.text(&r).contains("k 20"));
        assert_eq!(ReadoutLine::Replay.text(&r), "recorded 150 steps");
        let playing = Readings {
            playback: Some((40, 1125)),
            status: Some("saved the game to a.jsonl".to_owned()),
            ..r.clone()
        };
        assert_eq!(
            ReadoutLine::Replay.text(&playing),
            "replay: step 40 of 1125 (press to take over)  recorded 150 steps  saved the game to a.jsonl"
        );
        let over = Readings {
            ended: Some(
                "replay over: 1125 steps, the recorded states to the bit (hash 0123)".into(),
            ),
            ..r.clone()
        };
        assert_eq!(
            ReadoutLine::Replay.text(&over),
            "recorded 150 steps  replay over: 1125 steps, the recorded states to the bit (hash 0123)"
        );

        let fell_back = Readings {
            fell_back: true,
            fallbacks: 4,
            ..readings()
        };
        assert_eq!(
            ReadoutLine::Integrator.text(&fell_back),
            "integrator auto: fell back to implicit (over budget), 4 fall-backs to implicit"
        );

        let paused = Readings {
            paused: true,
            integrator: Integrator::Rk4,
            divergence: Some((Integrator::Euler, 7)),
            ..readings()
        };
        assert!(ReadoutLine::Clock.text(&paused).contains("PAUSED"));
        let solver = ReadoutLine::Integrator.text(&paused);
        assert!(solver.starts_with("integrator rk4") && !solver.contains("steps/step"));
        assert!(solver.contains("euler DIVERGED at step 7"));
    }

    // The replay line dim, the integrator line in the warning colour exactly when the live
    // method diverged, the rest plain text.
    #[test]
    fn each_line_has_its_colour() {
        let calm = readings();
        let text = ReadoutLine::Scene.colour(&calm);
        assert_eq!(text, colour::TEXT);
        assert_eq!(ReadoutLine::Replay.colour(&calm), colour::DIM);
        assert_ne!(colour::TEXT, colour::DIM);
        for line in [
            ReadoutLine::Integrator,
            ReadoutLine::Clock,
            ReadoutLine::Parameters,
        ] {
            assert_eq!(line.colour(&calm), text, "{line:?}");
        }
        let diverged = Readings {
            divergence: Some((Integrator::Euler, 12)),
            ..readings()
        };
        let warning = ReadoutLine::Integrator.colour(&diverged);
        for other in [
            text,
            colour::DIM,
            colour::KINETIC,
            colour::BAND_ENERGY,
            colour::TOTAL,
        ] {
            assert_ne!(warning, other);
        }
    }
}
