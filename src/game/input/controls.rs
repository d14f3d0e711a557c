//! The controls: every action a player can take ([`Action`]), from the keys or from the
//! on-screen panel, applied in one place before the fixed loop ([`GameSystems::Controls`]) so
//! that it acts on the very next step. The keys are listed once, in [`CONTROLS`], with the
//! action each sends: the Controls card's help line and README's table are written from it (a
//! test holds README to it). A value that `SceneParams::validate` refuses
//! is not applied, and the HUD's status line says why.

use bevy::input::ButtonState;
use bevy::input::keyboard::KeyboardInput;
use bevy::prelude::*;

use crate::game::camera::{HomeView, ZOOM_IN, ZOOM_OUT};
use crate::game::pointer::BAND_KEY;
use crate::game::replays::links::ShareLink;
use crate::game::replays::recording::SaveReplay;
use crate::game::replays::scenes::{LoadScene, RestartScene};
use crate::game::schedule::GameSystems;
use crate::game::setup::CurrentSetup;
use crate::game::shared::FocusedKeys;
use crate::game::shared::Learn;
use crate::game::shared::{Overlay, Say};
use crate::game::simulation::StepOnce;
use crate::game::theme::readable;
use crate::physics::{
    Integrator, Range, STEP_RATE_RANGE, STIFFNESS_RANGE, Scene, SceneParams, TIME_SCALE_RANGE,
};

pub struct ControlsPlugin;

impl Plugin for ControlsPlugin {
    fn build(&self, app: &mut App) {
        app.add_message::<Action>().add_systems(
            RunFixedMainLoop,
            (keys_to_actions, apply_actions)
                .chain()
                .in_set(GameSystems::Controls),
        );
    }
}

const PAUSE: KeyCode = KeyCode::Space;
const SINGLE_STEP: KeyCode = KeyCode::KeyN;
const RESET: KeyCode = KeyCode::KeyR;
const CYCLE_INTEGRATOR: KeyCode = KeyCode::KeyI;
const SOFTER: KeyCode = KeyCode::BracketLeft;
const STIFFER: KeyCode = KeyCode::BracketRight;
const SLOWER: KeyCode = KeyCode::Minus;
const FASTER: KeyCode = KeyCode::Equal;
const FEWER_STEPS: KeyCode = KeyCode::PageDown;
const MORE_STEPS: KeyCode = KeyCode::PageUp;
const VECTORS: KeyCode = KeyCode::KeyV;
const TRAIL: KeyCode = KeyCode::KeyT;
const HUD: KeyCode = KeyCode::KeyH;
const SAVE: KeyCode = KeyCode::KeyS;
const OPEN: KeyCode = KeyCode::KeyO;
const GHOSTS: KeyCode = KeyCode::KeyG;
const PLOT: KeyCode = KeyCode::KeyP;
const HOME_VIEW: KeyCode = KeyCode::KeyF;
const LINK: KeyCode = KeyCode::KeyC;
const GAME_LINK: KeyCode = KeyCode::KeyU;
const LEARN: KeyCode = KeyCode::KeyL;
/// The named scenes, in the core's order ([`Scene::NAMES`]).
const SCENE_KEYS: [KeyCode; 10] = [
    KeyCode::Digit1,
    KeyCode::Digit2,
    KeyCode::Digit3,
    KeyCode::Digit4,
    KeyCode::Digit5,
    KeyCode::Digit6,
    KeyCode::Digit7,
    KeyCode::Digit8,
    KeyCode::Digit9,
    KeyCode::Digit0,
];

const SCENE_ACTIONS: [Action; 10] = [
    Action::Scene(0),
    Action::Scene(1),
    Action::Scene(2),
    Action::Scene(3),
    Action::Scene(4),
    Action::Scene(5),
    Action::Scene(6),
    Action::Scene(7),
    Action::Scene(8),
    Action::Scene(9),
];

/// Everything a player can do but drag: what a key and a panel button send.
#[derive(Message, Debug, Clone, Copy, PartialEq)]
pub enum Action {
    TogglePause,
    /// One fixed step, while paused.
    Step,
    Reset,
    NextIntegrator,
    Integrator(Integrator),
    Softer,
    Stiffer,
    Slower,
    Faster,
    FewerSteps,
    MoreSteps,
    /// A parameter set to a value (the panel's sliders), refused if not valid.
    Set(Parameter, f64),
    /// An overlay switched on or off.
    Toggle(Overlay),
    ToggleDock,
    /// The camera back to the tutorial's 640 x 480 frame at once.
    HomeView,
    Save,
    Open,
    /// The link of what is on screen written out ([`ShareLink`]).
    ShareLink,
    /// The same with the game so far in it.
    ShareGame,
    /// Into learn mode, or out of it ([`Learn`]).
    Learn,
    NextChapter,
    PreviousChapter,
    /// This answer to the chapter's prediction.
    Predict(usize),
    /// The chapter's scene back at its start, its answers kept.
    RestartChapter,
    /// More point masses across the box, or fewer.
    PointMasses(i32),
    /// The scene at this place in [`Scene::NAMES`].
    Scene(usize),
}

/// A scene parameter the panel sets directly.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Parameter {
    Stiffness,
    Mass,
    /// The side of the (square) box.
    Size,
    LinearDamping,
    AngularDamping,
}

impl Parameter {
    pub const ALL: [Self; 5] = [
        Self::Stiffness,
        Self::Mass,
        Self::Size,
        Self::LinearDamping,
        Self::AngularDamping,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Self::Stiffness => "k",
            Self::Mass => "mass",
            Self::Size => "size",
            Self::LinearDamping => "linear damping",
            Self::AngularDamping => "angular damping",
        }
    }

    /// Returns its name in full, as a screen reader says it.
    pub fn spoken(self) -> &'static str {
        match self {
            Self::Stiffness => "band stiffness k",
            Self::Mass => "box mass",
            Self::Size => "box size",
            Self::LinearDamping => "linear damping b",
            Self::AngularDamping => "angular damping c",
        }
    }

    pub fn get(self, params: &SceneParams) -> f64 {
        match self {
            Self::Stiffness => params.stiffness,
            Self::Mass => params.mass,
            Self::Size => params.size.x,
            Self::LinearDamping => params.linear_damping,
            Self::AngularDamping => params.angular_damping,
        }
    }

    /// Writes a value of the parameter with its unit: the panel's and the Readouts card's one form.
    ///
    /// The linear damping is its coefficient b and, given the mass, the rate b/m at which the
    /// velocity decays (`b 5 = 1 /s`); without it (a slider's end, where room is short) `b 5`.
    pub fn written(self, value: f64, mass: Option<f64>) -> String {
        let value_read = readable(value);
        match (self, mass) {
            (Self::Stiffness | Self::Mass, _) => value_read,
            (Self::Size, _) => format!("{value_read} px"),
            (Self::LinearDamping, Some(mass)) => {
                format!("b {value_read} = {} /s", readable(value / mass))
            }
            (Self::LinearDamping, None) => format!("b {value_read}"),
            (Self::AngularDamping, _) => format!("{value_read} /s"),
        }
    }

    fn set(self, params: &mut SceneParams, value: f64) {
        match self {
            Self::Stiffness => params.stiffness = value,
            Self::Mass => params.mass = value,
            Self::Size => params.size = bevy::math::DVec2::splat(value),
            Self::LinearDamping => params.linear_damping = value,
            Self::AngularDamping => params.angular_damping = value,
        }
    }
}

/// One control: its keys and the action each sends.
///
/// It also holds how the help line names the keys, and what the control does.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Control {
    pub keys: &'static [KeyCode],
    /// The action of each key, in the same order.
    pub actions: &'static [Action],
    /// The keys as the help line and README write them ("[ ]").
    pub label: &'static str,
    /// What it does, in a word (the help line).
    pub name: &'static str,
    /// What it does, in full (README's table).
    pub effect: &'static str,
}

/// Every key the game reads, in the order the help line lists them.
pub const CONTROLS: [Control; 22] = [
    Control {
        keys: &[PAUSE],
        actions: &[Action::TogglePause],
        label: "Space",
        name: "pause",
        effect: "pause / resume (from the next frame: Bevy advances its clocks before it reads input)",
    },
    Control {
        keys: &[SINGLE_STEP],
        actions: &[Action::Step],
        label: "N",
        name: "step",
        effect: "one fixed step while paused",
    },
    Control {
        keys: &[RESET],
        actions: &[Action::Reset],
        label: "R",
        name: "reset",
        effect: "reset: a scene loaded back at its start, its scripted pull with it, the sliders as they are (else the box at rest at the centre); the books, the graph and the trail started over",
    },
    Control {
        keys: &[CYCLE_INTEGRATOR],
        actions: &[Action::NextIntegrator],
        label: "I",
        name: "integrator",
        effect: "the next integrator",
    },
    Control {
        keys: &[SOFTER, STIFFER],
        actions: &[Action::Softer, Action::Stiffer],
        label: "[ ]",
        name: "k",
        effect: "band stiffness k ÷10 / ×10, from 1e-2 to 1e12 (the hard cases are a few presses away)",
    },
    Control {
        keys: &[SLOWER, FASTER],
        actions: &[Action::Slower, Action::Faster],
        label: "- =",
        name: "time",
        effect: "time scale ÷2 / ×2, from 1/16 to 16 (slow motion, fast forward)",
    },
    Control {
        keys: &[FEWER_STEPS, MORE_STEPS],
        actions: &[Action::FewerSteps, Action::MoreSteps],
        label: "PgDn PgUp",
        name: "rate",
        effect: "fixed step rate ÷2 / ×2, from 8 to 4096 Hz",
    },
    Control {
        keys: &[VECTORS],
        actions: &[Action::Toggle(Overlay::Vectors)],
        label: "V",
        name: "vectors",
        effect: "vectors: velocity at the centre (green, where it will be in 0.25 s), the band's force at its corner (orange, length growing with log force)",
    },
    Control {
        keys: &[TRAIL],
        actions: &[Action::Toggle(Overlay::Trail)],
        label: "T",
        name: "trail",
        effect: "a fading trail of the pulled corner",
    },
    Control {
        keys: &[GHOSTS],
        actions: &[Action::Toggle(Overlay::Ghosts)],
        label: "G",
        name: "ghosts",
        effect: "ghosts: every integrator and a reference (Taylor order 32 at 1e-13 px) beside the box under the same band, each outlined in its colour; their card lists their distance from the reference, energy residual and cost per step",
    },
    Control {
        keys: &[PLOT],
        actions: &[Action::Toggle(Overlay::Plot)],
        label: "P",
        name: "plot",
        effect: "speed against error, live: each ghost a point, its cost per simulated second against its distance from the reference on the report's log-log axes (turns the ghosts on)",
    },
    Control {
        keys: &SCENE_KEYS,
        actions: &SCENE_ACTIONS,
        label: "1-0",
        name: "scene",
        effect: "load the named scene at that place in the core's table (the order of `simulate --scene`'s list: 1 the first, 0 the tenth): its parameters and start, its scripted pull played until you press; the readouts name it and say what makes it hard",
    },
    Control {
        keys: &[HUD],
        actions: &[Action::ToggleDock],
        label: "H",
        name: "dock",
        effect: "hide / show the dock of instruments (the scene takes the window)",
    },
    Control {
        keys: &[HOME_VIEW],
        actions: &[Action::HomeView],
        label: "F",
        name: "frame",
        effect: "the camera back to the tutorial's 640 x 480 frame (the wheel or a pinch zooms, the right button or two fingers pan; the camera follows a box pulled out of view)",
    },
    Control {
        // The camera reads these itself, as it reads the wheel.
        keys: &[ZOOM_IN, ZOOM_OUT],
        actions: &[],
        label: "Z X",
        name: "zoom",
        effect: "zoom in / out about the scene's centre, as the wheel does about the pointer (F goes back to the frame)",
    },
    Control {
        keys: &[SAVE],
        actions: &[Action::Save],
        label: "S",
        name: "save",
        effect: "save the game so far as a replay (to `--record`'s file, else `replay-<time>.jsonl`; in the browser a download; the readouts show the name)",
    },
    Control {
        keys: &[OPEN],
        actions: &[Action::Open],
        label: "O",
        name: "open",
        effect: "play a replay file: in the browser a file chooser; on the desktop drop the file on the window (or `play --replay FILE`); dropping works in the browser too",
    },
    Control {
        keys: &[LINK],
        actions: &[Action::ShareLink],
        label: "C",
        name: "link",
        effect: "the link of what is on screen (scene, integrator, settings, overlays; docs/links.md; in learn mode the chapter's, `?learn=N`): in the browser it becomes the page's address and is copied, on the desktop it is printed to the terminal (open it with `play --link`)",
    },
    Control {
        keys: &[GAME_LINK],
        actions: &[Action::ShareGame],
        label: "U",
        name: "game link",
        effect: "the same with the game so far in it: whoever opens it sees your pull replayed to the bit",
    },
    Control {
        // Bevy's tab navigation and the focused controls answer these (`input::focus`).
        keys: &[KeyCode::Tab, KeyCode::Escape],
        actions: &[],
        label: "Tab Esc",
        name: "focus",
        effect: "keyboard focus: Tab moves it through the dock's buttons and sliders in reading order (Shift+Tab back), a ring shows it; a focused button takes Space and Enter, a focused slider ← → ↑ ↓ one step (with Shift a tenth), PgUp PgDn ten steps, Home End its ends, and the game's key of that name does not fire; Esc gives focus back to the scene (docs/controls.md)",
    },
    Control {
        // The pointer plugin reads these itself: they drive the band as the mouse does.
        keys: &[
            BAND_KEY,
            KeyCode::ArrowLeft,
            KeyCode::ArrowRight,
            KeyCode::ArrowUp,
            KeyCode::ArrowDown,
        ],
        actions: &[],
        label: "B ←→↑↓",
        name: "band",
        effect: "the band by keyboard: the arrows move a cursor on the scene (with Shift slowly), B grabs the corner nearest it and the arrows then pull; B again lets go. The same band as the mouse's, recorded and replayed the same way",
    },
    Control {
        keys: &[LEARN],
        actions: &[Action::Learn],
        label: "L",
        name: "learn",
        effect: "learn mode: the tutorial's chapters, each with its equations written with the numbers of the moment and a prediction the game checks by experiment (docs/learn.md; a link `?learn=N` opens chapter N); L again leaves it and puts the game back as it was",
    },
];

/// Returns the HUD's help line: "drag: pull  Space: pause  N: step ...".
///
/// Each item's spaces are non-breaking, so that a narrow window wraps the line between items,
/// never inside one.
pub fn help_line() -> String {
    let keys: Vec<String> = CONTROLS
        .iter()
        .map(|control| format!("{}: {}", control.label, control.name).replace(' ', "\u{a0}"))
        .collect();
    format!("drag:\u{a0}pull  {}", keys.join("  "))
}

/// Sends the action of every key press since the last frame, in the order pressed.
///
/// It reads the keyboard's messages rather than "just pressed": two presses of one key between
/// two frames (a slow frame, a fast typist) are two actions. A key held down and repeating
/// sends one.
///
/// A key a focused control takes for itself (Space on a button, an arrow on a slider) is the
/// control's, not the game's.
fn keys_to_actions(
    mut keys: MessageReader<KeyboardInput>,
    mut actions: MessageWriter<Action>,
    focused: FocusedKeys,
) {
    for press in keys.read().filter(|key| {
        key.state == ButtonState::Pressed && !key.repeat && !focused.takes(key.key_code)
    }) {
        for control in &CONTROLS {
            for (key, action) in control.keys.iter().zip(control.actions) {
                if *key == press.key_code {
                    actions.write(*action);
                }
            }
        }
    }
}

/// Applies every action of this frame, in the order sent.
///
/// The settings the actions change are changed on a copy, and each part changed is sent to its
/// owner once; the single steps, then the parts, then what the actions have to say, then the
/// actions' other messages (a reset, a scene, learn mode...) go out in that order, so that a
/// scene loaded or a reset in the same frame takes the settings sent before it. k, the time
/// scale and the step rate move by factors, so that a player reaches the hard cases in a few
/// presses; each stays inside its range, and a scene parameter changes only if the whole scene
/// stays valid.
fn apply_actions(mut actions: MessageReader<Action>, mut commands: Commands, setup: CurrentSetup) {
    let actions: Vec<Action> = actions.read().copied().collect();
    if actions.is_empty() {
        return;
    }
    let before = setup.get();
    let mut set = before.clone();
    let mut steps = 0;
    let mut said = Vec::new();
    let scaled = |value: f64, factor: f64, range: Range| range.clamp(value * factor);
    for &action in &actions {
        let mut next = set.params;
        match action {
            Action::TogglePause => set.clock.paused = !set.clock.paused,
            // While paused, the fixed clock is fed exactly one step of time.
            Action::Step if set.clock.paused => steps += 1,
            Action::NextIntegrator => set.integrator = set.integrator.next(),
            Action::Integrator(integrator) => set.integrator = integrator,
            Action::Softer => next.stiffness = scaled(next.stiffness, 0.1, STIFFNESS_RANGE),
            Action::Stiffer => {
                next.stiffness = scaled(
                    next.stiffness.max(STIFFNESS_RANGE.low),
                    10.0,
                    STIFFNESS_RANGE,
                )
            }
            Action::FewerSteps => {
                next.step_rate_hz = scaled(next.step_rate_hz, 0.5, STEP_RATE_RANGE)
            }
            Action::MoreSteps => {
                next.step_rate_hz = scaled(next.step_rate_hz, 2.0, STEP_RATE_RANGE)
            }
            Action::Set(parameter, value) => parameter.set(&mut next, value),
            Action::Slower | Action::Faster => {
                let factor = if action == Action::Slower { 0.5 } else { 2.0 };
                set.clock.speed = scaled(set.clock.speed, factor, TIME_SCALE_RANGE);
            }
            Action::Toggle(overlay) => set.overlays.toggle(overlay),
            Action::ToggleDock => set.dock_hidden.0 = !set.dock_hidden.0,
            Action::Open => said.extend(open_replay()),
            _ => {}
        }
        if next != set.params {
            match next.check_playable() {
                Ok(()) => set.params = next,
                Err(error) => said.push(format!("refused: {error}; kept the old value")),
            }
        }
    }
    // Fed at the step in force, before a new rate's step is.
    for _ in 0..steps {
        commands.trigger(StepOnce);
    }
    set.send_changed(&before, &mut commands);
    for said in said {
        commands.trigger(Say(said));
    }
    for action in actions {
        send_message(&mut commands, action);
    }
}

/// Sends what an action asks of another plugin, which acts on it.
fn send_message(commands: &mut Commands, action: Action) {
    match action {
        // The scene plays from its start, each plugin putting back what it owns.
        Action::Reset => commands.trigger(RestartScene),
        // The view puts its camera back ([`HomeView`]).
        Action::HomeView => commands.trigger(HomeView),
        // The recorder saves and says where ([`crate::game::replays::recording`]).
        Action::Save => commands.trigger(SaveReplay),
        Action::Learn => commands.trigger(Learn::Toggle),
        Action::NextChapter => commands.trigger(Learn::Next),
        Action::PreviousChapter => commands.trigger(Learn::Previous),
        Action::Predict(choice) => commands.trigger(Learn::Predict(choice)),
        Action::RestartChapter => commands.trigger(Learn::Restart),
        Action::PointMasses(by) => commands.trigger(Learn::PointMasses(by)),
        Action::ShareLink => commands.trigger(ShareLink { game: false }),
        Action::ShareGame => commands.trigger(ShareLink { game: true }),
        Action::Scene(index) => {
            if let Some(&name) = Scene::NAMES.get(index) {
                commands.trigger(LoadScene(name));
            }
        }
        _ => {}
    }
}

/// Opens the file chooser in the browser, or on the desktop returns how to open a replay.
///
/// In the browser the playback opens what is chosen; on the desktop dropping a file on the
/// window opens it, which the HUD says.
fn open_replay() -> Option<String> {
    #[cfg(target_arch = "wasm32")]
    {
        crate::game::web::choose_replay_file();
        None
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        Some("drop a replay file on the window to play it".to_owned())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    // One form for a parameter wherever it is written: the panel's readout and the Readouts
    // card with the mass, a slider's end without it (only the linear damping differs).
    #[test]
    fn a_parameter_is_written_with_its_unit() {
        let written =
            |parameter: Parameter, value: f64, mass: Option<f64>| parameter.written(value, mass);
        assert_eq!(written(Parameter::Stiffness, 1e5, Some(5.0)), "1.0e5");
        assert_eq!(written(Parameter::Mass, 5.0, None), "5");
        assert_eq!(written(Parameter::Size, 60.0, Some(5.0)), "60 px");
        assert_eq!(
            written(Parameter::LinearDamping, 5.0, Some(2.0)),
            "b 5 = 2.5 /s"
        );
        assert_eq!(written(Parameter::LinearDamping, 5.0, None), "b 5");
        assert_eq!(written(Parameter::AngularDamping, 2.0203, None), "2.02 /s");
    }
}
