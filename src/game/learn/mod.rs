//! Learn mode (`L`, the panel's `learn`): the tutorial's chapters ([`chapters::CHAPTERS`]),
//! each on a scene of the core's table, its equations written with this frame's numbers
//! ([`equations`]) in the dock's *Learn* card, and a task the game checks. The mode is the
//! state [`Mode::Learn`]: on `OnEnter` learn mode keeps the game's setup
//! (`crate::game::setup::Setup`: the scene, the settings, the overlays, the dock, the cards, the
//! frame, the clock and the box) and shows its chapter; on `OnExit` it stops the chapter and
//! sends the setup back. It writes nothing of another plugin's: each chapter's settings go to
//! their owners as `shared::Apply`.

pub mod chapters;
pub mod draw;
pub mod equations;
mod experiments;
mod learning;

pub use self::experiments::Verdict;
use self::experiments::{Look, Progress};
pub use self::learning::{Learning, MOST_POINT_MASSES};
pub mod twin;

use bevy::ecs::system::SystemParam;
use bevy::prelude::*;

use self::chapters::{CHAPTERS, Equation};
use self::equations::{GhostBooks, Quantities};
use self::twin::{CentreTwin, TWIN_OFFSET};
use crate::game::camera::Stage;
use crate::game::ghosts::{GhostKind, Ghosts};
use crate::game::layout::{Card, CardSpec, RegisterCard, Slots, show_node};
use crate::game::pointer::Grip;
use crate::game::replays::links::{ShareLink, publish};
use crate::game::replays::playback::StopPlayback;
use crate::game::replays::recording::Recorder;
use crate::game::replays::scenes::LoadScene;
use crate::game::schedule::{AfterStepsSystems, ScreenSystems};
use crate::game::setup::{CurrentSetup, Setup};
pub use crate::game::shared::Learn;
use crate::game::shared::{Apply, DockHidden, Mode, Overlay, Say, SceneName, has_screen};
use crate::game::simulation::{
    Band, Bodies, Clock, EnergyBooks, PlacedBox, ResetScene, StepCount, acting_band,
};
use crate::game::theme::{self, colour, size, space};
use crate::physics::{AutoSettings, Integrator, Scene, SceneParams};
use crate::replay::link::Link;

pub struct LearnPlugin;

impl Plugin for LearnPlugin {
    fn build(&self, app: &mut App) {
        app.register_card(CardSpec {
            card: Card::LEARN,
            title: "Learn",
            // First, so that a tall window shows it.
            place: 10,
            offered: |_, mode| mode == Mode::Learn,
        })
        .init_resource::<Learning>()
        .init_resource::<CentreTwin>()
        .add_observer(learn)
        .add_observer(share_the_chapter)
        .add_observer(twin::restart_on_reset)
        .add_observer(start_over_on_reset)
        .add_systems(Startup, spawn_card)
        .add_systems(OnEnter(Mode::Learn), show_the_chapter)
        .add_systems(OnExit(Mode::Learn), stop_the_chapter)
        // Every frame, not every step: a chapter starts paused, its outline already beside it.
        .add_systems(
            Update,
            keep_the_twin
                .after(hold_until_answered)
                .before(ScreenSystems::Write),
        )
        .add_systems(
            Update,
            // In `Update`, after the frame's steps: a resume asked before an answer is taken back
            // before the next frame's clock advances.
            (load_the_chapters_scene, hold_until_answered)
                .chain()
                .run_if(in_state(Mode::Learn)),
        )
        .add_systems(
            RunFixedMainLoop,
            check_task
                .run_if(in_state(Mode::Learn))
                .in_set(AfterStepsSystems::Conclude),
        )
        .add_systems(
            Update,
            show_chapter
                .run_if(in_state(Mode::Learn))
                .in_set(ScreenSystems::Write)
                .ambiguous_with(ScreenSystems::Write),
        );
    }

    fn finish(&self, app: &mut App) {
        if has_screen(app) {
            draw::plugin(app);
        }
    }
}

impl Card {
    /// Learn mode's chapter (while in learn mode).
    pub const LEARN: Card = Card("learn");
}

/// Places the twin while learn mode shows a chapter that has one, and drops it otherwise.
fn keep_the_twin(
    mode: Res<State<Mode>>,
    learning: Res<Learning>,
    mut twin: ResMut<CentreTwin>,
    boxes: Bodies,
) {
    let wanted = *mode.get() == Mode::Learn
        && CHAPTERS
            .get(learning.chapter)
            .is_some_and(|chapter| chapter.centre_twin);
    twin::place_twin(&mut twin, wanted, &boxes);
}

/// Returns the chapter learn mode shows, or None out of learn mode.
pub fn chapter_shown(world: &World) -> Option<usize> {
    shown(
        world.resource::<State<Mode>>(),
        world.resource::<Learning>(),
    )
}

/// Returns the chapter shown in `mode`, or None out of learn mode.
fn shown(mode: &State<Mode>, learning: &Learning) -> Option<usize> {
    (*mode.get() == Mode::Learn).then_some(learning.chapter)
}

/// What a learn control reads and writes: learn mode's own state, and the setup it changes.
#[derive(SystemParam)]
struct Teaching<'w, 's> {
    mode: Res<'w, State<Mode>>,
    next_mode: ResMut<'w, NextState<Mode>>,
    learning: ResMut<'w, Learning>,
    setup: CurrentSetup<'w, 's>,
}

/// Acts on a learn control at once, within the frame that sent it.
///
/// Entering and leaving ask for a [`Mode`]; the frame's `GameSystems::ModeChange`, after the
/// controls, runs Bevy's transition, so the chapter is in place before the frame's steps, as
/// every other control is.
fn learn(learn: On<Learn>, mut teaching: Teaching, mut commands: Commands) {
    let last = CHAPTERS.len() - 1;
    let learning = &mut *teaching.learning;
    match (*learn, shown(&teaching.mode, learning)) {
        (Learn::Toggle, Some(_)) => teaching.next_mode.set(Mode::Play),
        (Learn::Toggle, None) => enter_at(&mut teaching, 0),
        (Learn::Next, Some(index)) => {
            go_to(
                &mut commands,
                &teaching.setup.get(),
                learning,
                (index + 1).min(last),
            );
        }
        (Learn::Previous, Some(index)) => {
            go_to(
                &mut commands,
                &teaching.setup.get(),
                learning,
                index.saturating_sub(1),
            );
        }
        (Learn::Chapter(index), Some(_)) if index <= last => {
            go_to(&mut commands, &teaching.setup.get(), learning, index);
        }
        (Learn::Chapter(index), None) if index <= last => enter_at(&mut teaching, index),
        (Learn::Chapter(index), _) => {
            commands.trigger(Say(format!(
                "learn: no chapter {} (there are {})",
                index + 1,
                CHAPTERS.len()
            )));
        }
        (Learn::Predict(choice), Some(index))
            if choice < CHAPTERS[index].prediction.choices.len() =>
        {
            learning.chosen[index] = Some(choice);
            if learning.progress.judged {
                commands.trigger(Say(
                    "↺ restart plays the experiment again for this answer".to_owned()
                ));
            }
            learning.progress.verdict = None;
        }
        (Learn::Restart, Some(index)) => {
            go_to(&mut commands, &teaching.setup.get(), learning, index);
        }
        (Learn::PointMasses(by), Some(_)) => {
            let n = learning.point_masses.saturating_add_signed(by);
            learning.point_masses = n.clamp(1, MOST_POINT_MASSES);
        }
        _ => {}
    }
}

/// Writes the link of the chapter shown (`?v=1&learn=N`), as the share control asks in learn mode.
///
/// Everything else of the game is the chapter's own, so the link needs nothing more.
fn share_the_chapter(
    share: On<ShareLink>,
    mode: Res<State<Mode>>,
    learning: Res<Learning>,
    mut commands: Commands,
) {
    if share.game {
        return;
    }
    let Some(index) = shown(&mode, &learning) else {
        return;
    };
    let link = Link {
        learn: Some(index as u32 + 1),
        ..default()
    };
    let said = match link.to_query() {
        Ok(query) => publish(&query, false),
        Err(error) => format!("no link: {error}"),
    };
    commands.trigger(Say(said));
}

/// Enters learn mode at chapter `index`.
///
/// Bevy's transition puts the mode in place, `OnExit` and `OnEnter` included; the frame runs it
/// after the controls (`GameSystems::ModeChange`), so the chapter is in place for this frame's
/// steps.
fn enter_at(teaching: &mut Teaching, index: usize) {
    teaching.learning.chapter = index;
    teaching.next_mode.set(Mode::Learn);
}

/// Keeps the game's setup as learn mode is entered, then shows the chapter asked.
fn show_the_chapter(mut learning: ResMut<Learning>, setup: CurrentSetup, mut commands: Commands) {
    let now = setup.get();
    let index = learning.chapter;
    go_to(&mut commands, &now, &mut learning, index);
    learning.kept = Some(now);
}

/// Shows chapter `index` in learn mode, the game being set as `now` says.
///
/// Its integrator, overlays, dock, card and frame are sent, then its scene loaded with them
/// (its scripted pull plays until the player presses); its prediction and experiment start
/// over.
fn go_to(commands: &mut Commands, now: &Setup, learning: &mut Learning, index: usize) {
    let Some(chapter) = CHAPTERS.get(index) else {
        return;
    };
    let mut next = now.clone();
    if let Some(integrator) = chapter.integrator.and_then(|name| name.parse().ok()) {
        next.integrator = integrator;
    }
    // The arrows of force and velocity are the chapters' pictures.
    next.overlays.set(Overlay::Vectors, true);
    // The update loop's seed and explicit Euler step beside the box as ghosts.
    if chapter.ghosts {
        next.overlays.set(Overlay::Ghosts, true);
    }
    // Paused at its start: nothing moves before the question has an answer.
    next.clock = Clock {
        speed: chapter.pace,
        paused: true,
    };
    // The chapter is in the dock: it shows.
    next.dock_hidden = DockHidden(false);
    next.cards.set(Card::LEARN, true);
    let [left, bottom, right, top] = chapter.frame;
    next.stage = Stage {
        close: Some(Rect::new(left, bottom, right, top)),
        copy_at: chapter.centre_twin.then_some(TWIN_OFFSET.as_vec2()),
    };
    next.send_changed(now, commands);
    // Loaded once the pause is in force: Bevy's clocks advance before the input is read, so a
    // scene loaded now would take this frame's steps before the question has its answer.
    learning.scene_to_load = Some((chapter.scene, false));
    learning.chapter = index;
    learning.progress = Progress::default();
}

/// Starts the chapter's experiment over when the scene starts over (the answer is kept apart).
///
/// A restart, `R` and a scene loaded all start it over.
fn start_over_on_reset(_reset: On<ResetScene>, mut learning: ResMut<Learning>) {
    learning.progress = Progress::default();
}

/// Loads the chapter's scene, on the frame after the chapter paused the clock.
///
/// The box is put at the scene's start at once (its playback would at its first step), so a
/// chapter waiting for its answer shows the box as the scene starts it: spinning in chapter 2.
fn load_the_chapters_scene(mut learning: ResMut<Learning>, mut commands: Commands) {
    let Some((name, due)) = learning.scene_to_load else {
        return;
    };
    // The pause sent this frame holds from the next: Bevy's clocks have advanced already.
    if !due {
        learning.scene_to_load = Some((name, true));
        return;
    }
    learning.scene_to_load = None;
    commands.trigger(LoadScene(name));
    if let Ok(scene) = Scene::named(name)
        && let Ok(mass) = scene.params.mass_properties()
    {
        commands.trigger(Apply(PlacedBox {
            state: scene.initial,
            mass,
        }));
    }
}

/// Holds the clock paused while the chapter's question has no answer.
///
/// So nothing, a scene's scripted pull least of all, shows the answer before it is given.
/// It runs after the frame's steps, which a resume asked in this frame does not reach (the
/// clock advanced before the input was read): the next frame starts paused again.
fn hold_until_answered(
    learning: Res<Learning>,
    time: Res<Time<Virtual>>,
    shown: Res<SceneName>,
    mut commands: Commands,
) {
    let waiting = learning.predicted().is_none()
        && CHAPTERS
            .get(learning.chapter)
            .is_some_and(|chapter| chapter.scene == shown.0);
    if waiting && !time.is_paused() {
        commands.trigger(Apply(Clock {
            speed: time.relative_speed_f64(),
            paused: true,
        }));
        commands.trigger(Say(
            "choose an answer first: the chapter runs once you have".to_owned(),
        ));
    }
}

/// Stops the chapter as learn mode is left, and sends back the setup kept as it was entered.
///
/// The chapter's script stops, its bands go and the books start over (as a reset does); then
/// the scene, the settings, the overlays, the dock, the cards, the frame, the clock and the box
/// go back to their owners. The recorder notes the box put back as it notes any other change,
/// and the log says the recording goes on.
fn stop_the_chapter(
    mut learning: ResMut<Learning>,
    recorder: Res<Recorder>,
    mut commands: Commands,
) {
    learning.scene_to_load = None;
    commands.trigger(Apply(Stage::default()));
    commands.trigger(StopPlayback);
    commands.trigger(ResetScene);
    if let Some(goes_on) = recorder.goes_on() {
        info!("{goes_on}");
    }
    if let Some(kept) = learning.kept.take() {
        kept.send(&mut commands);
    }
}

/// How the steps an experiment reads were taken: their count, the clocks and the integrator.
#[derive(SystemParam)]
struct Stepping<'w> {
    steps: Res<'w, StepCount>,
    time: Res<'w, Time<Virtual>>,
    fixed: Res<'w, Time<Fixed>>,
    integrator: Res<'w, Integrator>,
}

/// Checks the chapter's experiment, after the frame's steps, against what the steps did.
///
/// When it concludes, the answer held at its start is judged by what happened.
fn check_task(
    mut learning: ResMut<Learning>,
    params: Res<SceneParams>,
    grip: Res<Grip>,
    stepping: Stepping,
    boxes: Bodies,
    bands: Query<&Band>,
    shown: Res<SceneName>,
) {
    let Stepping {
        steps,
        time,
        fixed,
        integrator,
    } = stepping;
    let index = learning.chapter;
    let Ok(body) = boxes.single() else {
        return;
    };
    // Another scene is no experiment of the chapter's (the card says so).
    if CHAPTERS[index].scene != shown.0 {
        return;
    }
    let any_band = acting_band(body.entity, &bands);
    let answer = learning.predicted();
    let progress = &mut learning.progress;
    let stepped = steps.0.saturating_sub(progress.steps_seen);
    let first_look = progress.steps_seen == 0;
    progress.steps_seen = steps.0;
    let single_step = time.is_paused() && progress.was_paused && !first_look && stepped == 1;
    progress.was_paused = time.is_paused();
    let look = Look {
        state: body.state(),
        mass: body.mass,
        params: &params,
        player_band: any_band.filter(|_| grip.0.is_some()),
        any_band,
        clock: fixed.elapsed_secs_f64(),
        stepped_seconds: stepped as f64 * fixed.timestep().as_secs_f64(),
        single_step,
        integrator: *integrator,
        answer,
    };
    // An experiment begun before the answer (a single step, a press) is judged by no answer:
    // the card says so and shows nothing of its result.
    let found = experiments::observe(CHAPTERS[index].task, progress, &look);
    progress.last_state = Some(look.state);
    if let Some((outcome, why)) = found {
        let verdict = Verdict {
            answer: progress.committed,
            outcome,
            why,
        };
        progress.judged = true;
        let right = verdict.right();
        if let (Some(answer), Some(_)) = (verdict.answer, verdict.outcome)
            && progress.tried != Some(answer)
        {
            progress.tried = Some(answer);
            learning.tries[index] += 1;
            learning.first[index].get_or_insert((answer, right));
        }
        learning.progress.verdict = Some(verdict);
        if right {
            learning.done[index] = true;
        }
    }
}

/// The *Learn* card's texts.
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
pub enum LearnText {
    Title,
    Body,
    /// A line of the chapter's equations, in the colour of what it is about.
    Line(usize),
    /// The prediction asked, or the answer chosen, and what to do.
    Task,
    /// What the experiment found, against the answer.
    Verdict,
}

/// The most equation lines a chapter writes (a force at a point's seven).
pub const LINES: usize = 7;

/// Returns an equation's colour: that of its arrow on the box, else the text's.
fn equation_colour(equation: Equation) -> Color {
    match equation {
        Equation::ForceSum
        | Equation::Acceleration
        | Equation::Spring
        | Equation::NearestCorner
        | Equation::LinearDamping => colour::FORCE,
        Equation::CentrePull => colour::TWIN,
        Equation::Motion => colour::VELOCITY,
        Equation::Arm => colour::ARM,
        Equation::Torque
        | Equation::AngularAcceleration
        | Equation::AngularMomentum
        | Equation::AngularDamping => colour::TORQUE,
        Equation::PointVelocity => colour::VELOCITY,
        _ => colour::TEXT,
    }
}

/// Where the panel puts the chapter's buttons: under the title.
///
/// There the equations' changing lengths never move them.
#[derive(Component, Debug)]
pub(crate) struct ChapterButtons;

/// Where the panel puts the prediction's answers: under the question.
#[derive(Component, Debug)]
pub(crate) struct ChoiceButtons;

/// The button of the prediction's answer at this place.
///
/// Learn mode writes its label and hides it where the chapter has fewer answers.
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
pub struct ChoiceButton(pub usize);

/// The most answers a prediction offers.
pub const CHOICES: usize = 3;

/// The buttons for more or fewer point masses, shown where the chapter sums them.
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
pub struct PointMassButton;

fn spawn_card(mut commands: Commands, slots: Slots) {
    let Some(card) = slots.card_body(Card::LEARN) else {
        return;
    };
    let text = |commands: &mut Commands, which: LearnText, font: f32, gap: f32| {
        commands.spawn((
            Name::new(format!("Learn {which:?}")),
            which,
            Text::default(),
            theme::text_font(font),
            TextColor(colour::TEXT),
            Node {
                margin: UiRect::axes(px(space::PAD + 2.0), px(gap)),
                ..default()
            },
            ChildOf(card),
        ));
    };
    text(&mut commands, LearnText::Title, size::TITLE, 3.0);
    commands.spawn((
        Name::new("Learn buttons"),
        ChapterButtons,
        Node {
            flex_direction: FlexDirection::Row,
            flex_wrap: FlexWrap::Wrap,
            ..default()
        },
        ChildOf(card),
    ));
    text(&mut commands, LearnText::Body, size::BODY, 3.0);
    for line in 0..LINES {
        text(&mut commands, LearnText::Line(line), size::BODY, 1.0);
    }
    text(&mut commands, LearnText::Task, size::BODY, 3.0);
    commands.spawn((
        Name::new("Learn answers"),
        ChoiceButtons,
        Node {
            flex_direction: FlexDirection::Row,
            flex_wrap: FlexWrap::Wrap,
            ..default()
        },
        ChildOf(card),
    ));
    text(&mut commands, LearnText::Verdict, size::BODY, 3.0);
}

/// Writes the chapter's texts from the game's state this frame, each with its colour.
///
/// `scene` is the scene shown: another than the chapter's is said, and nothing judged on it.
fn chapter_texts(
    learning: &Learning,
    quantities: Option<&Quantities>,
    scene: &str,
) -> Option<Vec<(LearnText, String, Color)>> {
    let index = learning.chapter;
    let chapter = CHAPTERS.get(index)?;
    let title = format!(
        "{} of {}  {}  ({})",
        index + 1,
        CHAPTERS.len(),
        chapter.title,
        chapter.sections
    );
    let mut texts = vec![
        (LearnText::Title, title, colour::TEXT),
        (LearnText::Body, chapter.text.to_owned(), colour::DIM),
    ];
    let prediction = &chapter.prediction;
    let answered = learning.predicted().is_some();
    let lines: Vec<(String, Color)> = quantities.map_or_else(Vec::new, |q| {
        chapter
            .equations
            .iter()
            .flat_map(|&equation| {
                let colour = equation_colour(equation);
                let mut lines = equations::lines(equation, q);
                if !answered {
                    equations::hide_the_answer(equation, &mut lines);
                }
                lines.into_iter().map(move |line| (line, colour))
            })
            .collect()
    });
    for line in 0..LINES {
        let (text, colour) = lines.get(line).cloned().unwrap_or_default();
        texts.push((LearnText::Line(line), text, colour));
    }
    let done = if learning.done[index] {
        "● done. "
    } else {
        ""
    };
    let said = |choice: Option<usize>| {
        choice
            .and_then(|i| prediction.choices.get(i))
            .copied()
            .unwrap_or("nothing")
    };
    let task = match learning.predicted() {
        Some(answer) => format!(
            "{done}▸ {} You say: {}; {}",
            prediction.question,
            said(Some(answer)),
            prediction.then
        ),
        None => format!(
            "{done}▸ Predict: {} Choose an answer below; nothing moves until you do.",
            prediction.question
        ),
    };
    let task = (task, colour::TEXT);
    let retry = match (learning.first_answer(), learning.tries[index]) {
        (Some((first, right)), tries) if tries > 1 => format!(
            " (a retry: your first answer, {}, was {})",
            said(Some(first)),
            if right { "right" } else { "wrong" }
        ),
        _ => String::new(),
    };
    let verdict = if chapter.scene != scene {
        (
            format!(
                "This is the {scene} scene, not the chapter's ({}): ↺ restart brings it back.",
                chapter.scene
            ),
            colour::DIM,
        )
    } else {
        match learning.verdict() {
            None => (String::new(), colour::DIM),
            Some(verdict) => match (verdict.answer, verdict.outcome) {
                (_, None) => (format!("… {}", verdict.why), colour::DIM),
                // Nothing of the result is shown before an answer.
                (None, Some(_)) => (
                    "That experiment began before you answered: choose an answer, then \
                     ↺ restart and watch again."
                        .to_owned(),
                    colour::DIM,
                ),
                (Some(_), Some(_)) if verdict.right() => (
                    format!("● Right{retry}: {}. {}", said(verdict.outcome), verdict.why),
                    colour::VELOCITY,
                ),
                (answer, outcome) => (
                    format!(
                        "✕ You said {}; it was {}{retry}: {}. A retry is welcome: ↺ restart.",
                        said(answer),
                        said(outcome),
                        verdict.why
                    ),
                    colour::FORCE,
                ),
            },
        }
    };
    texts.push((LearnText::Task, task.0, task.1));
    texts.push((LearnText::Verdict, verdict.0, verdict.1));
    Some(texts)
}

/// The answers' buttons and the point masses' buttons, with their labels.
type ChoiceButtonsQuery<'w, 's> = Query<
    'w,
    's,
    (
        &'static mut Node,
        &'static Children,
        Option<&'static ChoiceButton>,
    ),
    Or<(With<ChoiceButton>, With<PointMassButton>)>,
>;

/// What the card's numbers are read from.
///
/// The settings, the books, the twin, the ghosts and the scene shown.
#[derive(SystemParam)]
struct CardSources<'w> {
    params: Res<'w, SceneParams>,
    integrator: Res<'w, Integrator>,
    auto: Res<'w, AutoSettings>,
    books: Res<'w, EnergyBooks>,
    twin: Res<'w, CentreTwin>,
    ghosts: Res<'w, Ghosts>,
    scene: Res<'w, SceneName>,
}

/// Writes the card from this frame's components.
fn show_chapter(
    learning: Res<Learning>,
    sources: CardSources,
    boxes: Bodies,
    bands: Query<&Band>,
    mut texts: Query<(&LearnText, &mut Text, &mut TextColor)>,
    mut buttons: ChoiceButtonsQuery,
    mut labels: Query<&mut Text, Without<LearnText>>,
) {
    let CardSources {
        params,
        integrator,
        auto,
        books,
        twin,
        ghosts,
        scene,
    } = sources;
    let Some(chapter) = CHAPTERS.get(learning.chapter) else {
        return;
    };
    let quantities = boxes.single().ok().map(|body| {
        let band = acting_band(body.entity, &bands);
        let energies = books.energies;
        let q = Quantities::of(body.state(), body.mass, &params, band, books.ledger)
            .with_books(
                energies.linear + energies.rotational + energies.band,
                *integrator,
            )
            .with_twin(twin.body.as_ref())
            .with_point_masses(learning.point_masses)
            .with_update_order(update_order(&ghosts));
        if chapter.equations.contains(&Equation::AngularMomentum) {
            q.with_next_step(body.mass, &params, band, *auto)
        } else {
            q
        }
    });
    let Some(shown) = chapter_texts(&learning, quantities.as_ref(), &scene.0) else {
        return;
    };
    for (which, mut text, mut colour) in &mut texts {
        if let Some((_, content, wanted)) = shown.iter().find(|(kind, ..)| kind == which) {
            if text.0 != *content {
                text.0.clone_from(content);
            }
            colour.set_if_neq(TextColor(*wanted));
        }
    }
    let choices = chapter.prediction.choices;
    let sums = chapter.equations.contains(&Equation::PointMasses);
    for (mut node, children, choice) in &mut buttons {
        let label = match choice {
            Some(ChoiceButton(i)) => choices.get(*i).copied(),
            None => sums.then_some(""),
        };
        show_node(&mut node, label.is_some());
        if let Some(label) = label.filter(|label| !label.is_empty())
            && let Some(mut text) = children
                .first()
                .and_then(|child| labels.get_mut(*child).ok())
            && text.0 != label
        {
            text.0 = label.to_owned();
        }
    }
}

/// Returns the books of the seed's and explicit Euler's ghosts, while the ghosts step.
fn update_order(ghosts: &Ghosts) -> Option<[GhostBooks; 2]> {
    let books = |integrator: Integrator| {
        ghosts
            .ghosts
            .iter()
            .find(|ghost| ghost.kind == GhostKind::Method(integrator))
            .map(|ghost| GhostBooks {
                energy: ghost.stepper.energy(),
                residual: ghost.residual(),
            })
    };
    Some([books(Integrator::Seed)?, books(Integrator::Euler)?])
}
