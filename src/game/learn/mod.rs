//! Learn mode (`L`, the panel's `learn`): the tutorial's chapters ([`chapters::CHAPTERS`]),
//! each on a scene of the core's table, its equations written with this frame's numbers
//! ([`equations`]) in the dock's *Learn* card, and a task the game checks. The mode is the
//! state [`Mode::Learn`]: entering saves the game (`save_the_game`, on `OnEnter`), leaving
//! puts it back as it was (`restore_the_game`, on `OnExit`): the scene, the settings, the
//! overlays, the clock and the box.

pub mod chapters;
pub mod equations;
pub mod twin;

use bevy::prelude::*;

use self::chapters::{CHAPTERS, Equation, Task};
use self::equations::Quantities;
use self::twin::{CentreTwin, TWIN_OFFSET};
use crate::game::camera::{CameraFrame, Stage};
use crate::game::layout::{Card, CardSpec, Cards, RegisterCard, Slots};
use crate::game::pointer::Grip;
use crate::game::replays::playback::Playback;
use crate::game::replays::recording::say_it_goes_on;
use crate::game::replays::scenes::load_scene;
use crate::game::schedule::{AfterStepsSystems, PhysicsSystems, ScreenSystems};
use crate::game::shared::{DockHidden, Mode, Overlays, SceneName};
use crate::game::simulation::{
    Band, Bodies, EnergyBooks, ResetScene, RigidBodyQueryReadOnly, RigidBox, StepCount,
    acting_band, rigid_box, set_fixed_step,
};
use crate::game::theme::{self, colour, size, space};
use crate::physics::{
    AutoSettings, BodyState, Integrator, MassProperties, SceneParams, kinetic_energy,
};

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
        .add_observer(twin::restart_on_reset)
        .add_systems(Startup, spawn_card)
        .add_systems(OnEnter(Mode::Learn), save_the_game)
        .add_systems(OnExit(Mode::Learn), restore_the_game)
        .add_systems(FixedUpdate, keep_the_twin.in_set(PhysicsSystems::Observe))
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
                .in_set(ScreenSystems::Learn),
        );
    }
}

impl Card {
    /// Learn mode's chapter (while in learn mode).
    pub const LEARN: Card = Card("learn");
}

/// What the learn controls ask.
#[derive(Event, Debug, Clone, Copy, PartialEq, Eq)]
pub enum Learn {
    /// Into learn mode at its first chapter, or out of it.
    Toggle,
    Next,
    Previous,
    /// This chapter (entering the mode if need be).
    Chapter(usize),
}

/// Learn mode's chapters: the one shown, what each task has seen, and the game to go back to.
///
/// Whether the mode is on is the state [`Mode`], asked nowhere else.
#[derive(Resource, Debug, Default)]
pub struct Learning {
    /// The chapter shown in learn mode (the one it shows next when entered).
    pub chapter: usize,
    /// Each chapter's task done.
    pub done: [bool; CHAPTERS.len()],
    progress: Progress,
    saved: Option<Box<Saved>>,
}

/// What a task has seen since its chapter began.
#[derive(Debug, Default, Clone)]
struct Progress {
    inertia_at_start: f64,
    /// The player's band: where its pull started (position, orientation).
    ///
    /// `turned` says whether the box turned too much since.
    pull_start: Option<(Vec2, f64)>,
    turned: bool,
    corners: Vec<[i64; 2]>,
    pulled: bool,
    most_energy: f64,
    steps_seen: u64,
    single_steps: u32,
}

/// The game as it was when learn mode was entered.
#[derive(Debug, Clone)]
struct Saved {
    params: SceneParams,
    integrator: Integrator,
    auto: AutoSettings,
    scene: SceneName,
    overlays: Overlays,
    dock_hidden: DockHidden,
    cards: Cards,
    speed: f64,
    paused: bool,
    body: Option<(BodyState, MassProperties)>,
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
    let learning = *world.resource::<State<Mode>>().get() == Mode::Learn;
    learning.then(|| world.resource::<Learning>().chapter)
}

/// Acts on a learn control at once, within the frame that sent it.
///
/// Entering and leaving change [`Mode`] and run the state's transition there and then, so the
/// chapter is in place before the frame's steps, as every other control is.
fn learn(learn: On<Learn>, mut commands: Commands) {
    let asked = *learn;
    commands.queue(move |world: &mut World| {
        let last = CHAPTERS.len() - 1;
        match (asked, chapter_shown(world)) {
            (Learn::Toggle, Some(_)) => switch_to(world, Mode::Play),
            (Learn::Toggle, None) => enter_at(world, 0),
            (Learn::Next, Some(index)) => go_to(world, (index + 1).min(last)),
            (Learn::Previous, Some(index)) => go_to(world, index.saturating_sub(1)),
            (Learn::Chapter(index), Some(_)) if index <= last => go_to(world, index),
            (Learn::Chapter(index), None) if index <= last => enter_at(world, index),
            _ => {}
        }
    });
}

/// Enters learn mode at chapter `index`.
fn enter_at(world: &mut World, index: usize) {
    world.resource_mut::<Learning>().chapter = index;
    switch_to(world, Mode::Learn);
}

/// Sets the mode and runs the state's transition now, `OnExit` and `OnEnter` included.
fn switch_to(world: &mut World, mode: Mode) {
    world.resource_mut::<NextState<Mode>>().set(mode);
    world.run_schedule(StateTransition);
}

/// Returns the box's state and mass, if there is one.
fn the_body(world: &mut World) -> Option<(BodyState, MassProperties)> {
    let mut boxes = world.query_filtered::<RigidBodyQueryReadOnly, With<RigidBox>>();
    boxes
        .iter(world)
        .next()
        .map(|body| (body.state(), *body.mass))
}

/// Saves the game as learn mode is entered, then shows the chapter asked.
fn save_the_game(world: &mut World) {
    let time = world.resource::<Time<Virtual>>();
    let saved = Saved {
        params: *world.resource::<SceneParams>(),
        integrator: *world.resource::<Integrator>(),
        auto: *world.resource::<AutoSettings>(),
        scene: world.resource::<SceneName>().clone(),
        overlays: *world.resource::<Overlays>(),
        dock_hidden: *world.resource::<DockHidden>(),
        cards: world.resource::<Cards>().clone(),
        speed: time.relative_speed_f64(),
        paused: time.is_paused(),
        body: the_body(world),
    };
    world.resource_mut::<Learning>().saved = Some(Box::new(saved));
    let index = world.resource::<Learning>().chapter;
    go_to(world, index);
}

/// Shows chapter `index` in learn mode.
///
/// The chapter's scene is loaded (its scripted pull plays until the player presses), its
/// integrator put in place, its task started over, the *Learn* card open.
fn go_to(world: &mut World, index: usize) {
    let Some(chapter) = CHAPTERS.get(index) else {
        return;
    };
    if let Some(integrator) = chapter.integrator.and_then(|name| name.parse().ok()) {
        world.insert_resource::<Integrator>(integrator);
    }
    load_scene(world, chapter.scene);
    let mut overlays = world.resource_mut::<Overlays>();
    // The arrows of force and velocity are the chapters' pictures.
    overlays.vectors = true;
    // The chapter is in the dock: it shows.
    world.resource_mut::<DockHidden>().0 = false;
    world.resource_mut::<Cards>().set(Card::LEARN, true);
    let [left, bottom, right, top] = chapter.frame;
    world.resource_mut::<CameraFrame>().stage = Stage {
        close: Some(Rect::new(left, bottom, right, top)),
        copy_at: chapter.centre_twin.then_some(TWIN_OFFSET.as_vec2()),
    };
    let inertia = world
        .resource::<SceneParams>()
        .mass_properties()
        .map_or(0.0, |mass| mass.inertia());
    let mut learning = world.resource_mut::<Learning>();
    learning.chapter = index;
    learning.progress = Progress {
        inertia_at_start: inertia,
        ..default()
    };
}

/// Puts the game back as learn mode was entered, as the mode is left.
fn restore_the_game(world: &mut World) {
    let saved = world.resource_mut::<Learning>().saved.take();
    world.resource_mut::<CameraFrame>().stage = Stage::default();
    let Some(saved) = saved else {
        return;
    };
    // The chapter's script stops, its bands go, the books start over (as a reset does).
    world.insert_resource(Playback::default());
    world.trigger(ResetScene);
    world.flush();
    let bands: Vec<Entity> = world
        .query_filtered::<Entity, With<Band>>()
        .iter(world)
        .collect();
    for band in bands {
        world.despawn(band);
    }
    world.insert_resource(saved.params);
    world.insert_resource(saved.integrator);
    world.insert_resource(saved.auto);
    world.insert_resource(saved.scene);
    world.insert_resource(saved.overlays);
    world.insert_resource(saved.dock_hidden);
    world.insert_resource(saved.cards);
    set_fixed_step(&mut world.resource_mut::<Time<Fixed>>(), saved.params.dt());
    let mut time = world.resource_mut::<Time<Virtual>>();
    time.set_relative_speed_f64(saved.speed);
    if saved.paused {
        time.pause();
    } else {
        time.unpause();
    }
    if let Some((state, mass)) = saved.body {
        let boxes: Vec<Entity> = world
            .query_filtered::<Entity, With<RigidBox>>()
            .iter(world)
            .collect();
        for body in boxes {
            world.entity_mut(body).insert(rigid_box(mass, state));
        }
    }
    // The recorder notes the box put back as it notes any other change, and goes on.
    say_it_goes_on(world);
}

/// Checks the chapter's task, after the frame's steps, against what the steps did.
fn check_task(
    mut learning: ResMut<Learning>,
    params: Res<SceneParams>,
    grip: Res<Grip>,
    steps: Res<StepCount>,
    time: Res<Time<Virtual>>,
    boxes: Bodies,
    bands: Query<&Band>,
) {
    let index = learning.chapter;
    let Ok(body) = boxes.single() else {
        return;
    };
    let mass = body.mass;
    // Only the player's own band counts, not a scene's script.
    let band = acting_band(body.entity, &bands).filter(|_| grip.0.is_some());
    let state = body.state();
    let progress = &mut learning.progress;
    let stepped = steps.0.saturating_sub(progress.steps_seen);
    let first_look = progress.steps_seen == 0;
    progress.steps_seen = steps.0;
    let done = match CHAPTERS[index].task {
        Task::MoveWithoutTurning => {
            let here = (state.linear.position.as_vec2(), state.angular.orientation);
            match (band, progress.pull_start) {
                (Some(_), None) => {
                    progress.pull_start = Some(here);
                    progress.turned = false;
                    false
                }
                (Some(_), Some((from, angle))) => {
                    progress.turned |= (here.1 - angle).abs() >= 0.05;
                    !progress.turned && here.0.distance(from) >= 40.0
                }
                (None, _) => {
                    progress.pull_start = None;
                    false
                }
            }
        }
        Task::SpinWithoutDamping => {
            params.angular_damping == 0.0 && state.angular.angular_velocity.abs() > 1.0
        }
        Task::SpinClockwise => band.is_some() && state.angular.angular_velocity < -1.0,
        Task::DoubleTheInertia => {
            // A side times √2 doubles I up to the last bit.
            let twice = 2.0 * progress.inertia_at_start * (1.0 - 1e-12);
            progress.inertia_at_start > 0.0 && mass.inertia() >= twice
        }
        Task::ThreeCorners => {
            if let Some(band) = band {
                let corner = [
                    band.local_point.x.signum() as i64,
                    band.local_point.y.signum() as i64,
                ];
                if !progress.corners.contains(&corner) {
                    progress.corners.push(corner);
                }
            }
            progress.corners.len() >= 3
        }
        Task::ComeToRest => {
            let energy = kinetic_energy(&state, mass);
            progress.pulled |= band.is_some();
            if progress.pulled {
                progress.most_energy = progress.most_energy.max(energy);
            }
            progress.pulled
                && band.is_none()
                && progress.most_energy > 1.0
                && energy < 0.01 * progress.most_energy
        }
        Task::StepFiveTimes => {
            if time.is_paused() && !first_look && stepped == 1 {
                progress.single_steps += 1;
            }
            progress.single_steps >= 5
        }
    };
    if done && !learning.done[index] {
        learning.done[index] = true;
    }
}

/// The *Learn* card's texts.
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
pub enum LearnText {
    Title,
    Body,
    /// A line of the chapter's equations, in the colour of what it is about.
    Line(usize),
    Task,
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
        | Equation::BandShareOfAlpha
        | Equation::AngularDamping => colour::TORQUE,
        _ => colour::TEXT,
    }
}

/// Where the panel puts the chapter's buttons: under the title.
///
/// There the equations' changing lengths never move them.
#[derive(Component, Debug)]
pub(crate) struct ChapterButtons;

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
}

/// Writes the chapter's texts from the game's state this frame, each with its colour.
fn chapter_texts(
    learning: &Learning,
    quantities: Option<&Quantities>,
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
    let lines: Vec<(String, Color)> = quantities.map_or_else(Vec::new, |q| {
        chapter
            .equations
            .iter()
            .flat_map(|&equation| {
                let colour = equation_colour(equation);
                equations::lines(equation, q)
                    .into_iter()
                    .map(move |line| (line, colour))
            })
            .collect()
    });
    for line in 0..LINES {
        let (text, colour) = lines.get(line).cloned().unwrap_or_default();
        texts.push((LearnText::Line(line), text, colour));
    }
    let task = if learning.done[index] {
        (format!("✓ {}: done", chapter.ask), colour::VELOCITY)
    } else {
        (format!("▸ {}", chapter.ask), colour::TEXT)
    };
    texts.push((LearnText::Task, task.0, task.1));
    Some(texts)
}

/// Writes the card from this frame's components.
fn show_chapter(
    learning: Res<Learning>,
    params: Res<SceneParams>,
    books: Res<EnergyBooks>,
    twin: Res<CentreTwin>,
    boxes: Bodies,
    bands: Query<&Band>,
    mut texts: Query<(&LearnText, &mut Text, &mut TextColor)>,
) {
    let quantities = boxes.single().ok().map(|body| {
        Quantities::of(
            body.state(),
            body.mass,
            &params,
            acting_band(body.entity, &bands),
            books.ledger,
        )
        .with_twin(twin.body.as_ref())
        .with_inertia_at_start(learning.progress.inertia_at_start)
    });
    let Some(shown) = chapter_texts(&learning, quantities.as_ref()) else {
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
}
