//! The headless game shared by the schedule and property tests: `MinimalPlugins`, input and
//! window messages, the game without its screen (`GameLogicPlugin`: physics, pointer, controls
//! and HUD, in the frame's order), and a camera set up as the game's. Every schedule is built
//! with Bevy's ambiguity detection as an error: two systems that touch the same data with no
//! order between them fail every test.
#![allow(dead_code, unused_imports)]

pub use std::time::Duration;

pub use bevy::camera::RenderTargetInfo;
pub use bevy::ecs::schedule::{LogLevel, ScheduleBuildSettings};
pub use bevy::input::ButtonState;
pub use bevy::input::InputPlugin;
pub use bevy::input::keyboard::{Key, KeyboardInput};
pub use bevy::input::mouse::MouseButtonInput;
pub use bevy::input::touch::{TouchInput, TouchPhase};
pub use bevy::math::DVec2;
pub use bevy::prelude::*;
pub use bevy::time::TimeUpdateStrategy;
pub use bevy::window::{
    ExitCondition, PrimaryWindow, WindowFocused, WindowPlugin, WindowResolution,
};

pub use rubber_band_box::game::GameLogicPlugin;
pub use rubber_band_box::game::budget::FrameBudget;
pub use rubber_band_box::game::camera::SceneCamera;
pub use rubber_band_box::game::energy::EnergyHistory;
pub use rubber_band_box::game::input::controls::Action;
use rubber_band_box::game::input::controls::CONTROLS;
pub use rubber_band_box::game::pointer::{Grip, PointerPlugin, PointerSource};
pub use rubber_band_box::game::schedule::PhysicsSystems;
pub use rubber_band_box::game::shared::Overlay;
pub use rubber_band_box::game::simulation::{
    Band, EnergyBooks, ForceAccumulator, RigidBox, SimulationPlugin, StepCount, StepStats,
};
pub use rubber_band_box::physics::{
    AngularState, Integrator, LinearState, SceneParams, Stepper, Wrench,
};

use rubber_band_box::physics::{AutoSettings, BandEnds, BodyState};
use rubber_band_box::replay::{Replay, Settings};

/// A 1280 x 720 window: the 640 x 480 scene with its 4% margin (499.2 high) fits its height,
/// so one pixel is 499.2 / 720 of a world unit and the screen centre (640, 360) is the world
/// origin.
pub const WINDOW: UVec2 = UVec2::new(1280, 720);

/// World units a pixel at home in [`WINDOW`].
pub const HOME_SCALE: f64 = 480.0 * 1.04 / 720.0;

/// Returns the key that sends `action`, as the controls table (`CONTROLS`) binds it.
pub fn key(action: Action) -> KeyCode {
    CONTROLS
        .iter()
        .find_map(|control| {
            let at = control.actions.iter().position(|sent| *sent == action)?;
            control.keys.get(at).copied()
        })
        .unwrap_or_else(|| panic!("no key sends {action:?}"))
}

/// Returns the keys of the control the table names `name` (one with no action of its own).
pub fn keys_of(name: &str) -> &'static [KeyCode] {
    CONTROLS
        .iter()
        .find(|control| control.name == name)
        .unwrap_or_else(|| panic!("no control named {name}"))
        .keys
}

/// Returns the scenes' keys, in the core's order of scenes.
pub fn scene_keys() -> Vec<KeyCode> {
    (0..rubber_band_box::physics::Scene::NAMES.len())
        .map(|index| key(Action::Scene(index)))
        .collect()
}

pub fn screen_to_world(screen: Vec2) -> DVec2 {
    let scale = HOME_SCALE;
    DVec2::new(
        (screen.x as f64 - 640.0) * scale,
        (360.0 - screen.y as f64) * scale,
    )
}

pub fn world_to_screen(world: DVec2) -> Vec2 {
    let scale = 1.0 / HOME_SCALE;
    Vec2::new(
        (640.0 + world.x * scale) as f32,
        (360.0 - world.y * scale) as f32,
    )
}

pub struct Game {
    pub app: App,
    pub window: Entity,
}

/// An app with no window and no renderer: `MinimalPlugins`, input, and window messages (a test
/// spawns its own window), its clock advanced by `frame` each update.
pub fn headless_app(frame: Duration) -> App {
    let mut app = App::new();
    app.add_plugins((
        MinimalPlugins,
        InputPlugin,
        WindowPlugin {
            primary_window: None,
            exit_condition: ExitCondition::DontExit,
            close_when_requested: false,
            ..default()
        },
    ))
    .insert_resource(TimeUpdateStrategy::ManualDuration(frame));
    app
}

/// Sets `camera`'s computed values and `projection` for a window of `size`, as bevy_render's
/// camera system would (the headless tests have no renderer to do it).
pub fn compute_camera(camera: &mut Camera, projection: &mut Projection, size: UVec2) {
    projection.update(size.x as f32, size.y as f32);
    camera.computed.clip_from_view = projection.get_clip_from_view();
    camera.computed.target_info = Some(RenderTargetInfo {
        physical_size: size,
        scale_factor: 1.0,
    });
}

impl Game {
    /// A headless game whose every `update()` advances the clock by `frame`.
    pub fn new(frame: Duration) -> Self {
        Self::with(frame, |_| {})
    }

    /// [`Game::new`] with `extra` applied to the app after the game's plugins (a test's own
    /// systems), before its schedules are built.
    pub fn with(frame: Duration, extra: impl FnOnce(&mut App)) -> Self {
        let mut app = headless_app(frame);
        app.add_plugins(GameLogicPlugin)
            // The manual clock's frames keep every step they owe, however long the steps take on
            // a loaded machine: the step counts a test asserts never vary (a test of the budget
            // puts the wall back).
            .insert_resource(FrameBudget::steps_only())
            .init_resource::<AccumulatorAudit>()
            .add_systems(FixedUpdate, audit_accumulators.after(PhysicsSystems::Step));

        let window = app
            .world_mut()
            .spawn((
                Window {
                    resolution: WindowResolution::new(WINDOW.x, WINDOW.y),
                    ..default()
                },
                PrimaryWindow,
            ))
            .id();
        // A scene camera as bevy_render's camera system would compute it for this window, for
        // the screen's plugins to place (the pointer maps through the camera's frame, not it).
        let mut projection = Projection::Orthographic(OrthographicProjection {
            scaling_mode: bevy::camera::ScalingMode::AutoMin {
                min_width: 640.0,
                min_height: 480.0,
            },
            ..OrthographicProjection::default_2d()
        });
        let mut camera = Camera::default();
        compute_camera(&mut camera, &mut projection, WINDOW);
        app.world_mut().spawn((
            Camera2d,
            SceneCamera,
            camera,
            projection,
            GlobalTransform::IDENTITY,
        ));

        extra(&mut app);
        // After every plugin, so that it applies to every schedule they made.
        app.configure_schedules(ScheduleBuildSettings {
            ambiguity_detection: LogLevel::Error,
            hierarchy_detection: LogLevel::Error,
            ..default()
        });
        // Bevy's UI plugin (a test that lays the panel out) leaves two of its own systems in
        // `First` unordered (its viewport picking and the message update): Bevy's, not ours,
        // and none of ours runs in `First`.
        if app.is_plugin_added::<bevy::ui::UiPlugin>() {
            app.edit_schedule(First, |schedule| {
                schedule.set_build_settings(ScheduleBuildSettings {
                    hierarchy_detection: LogLevel::Error,
                    ..default()
                });
            });
        }
        // Bevy's state transitions run each state's exclusive enter and exit systems unordered
        // among themselves (`StateTransition`: Bevy's, and only learn mode's `Mode` is ours).
        app.edit_schedule(StateTransition, |schedule| {
            schedule.set_build_settings(ScheduleBuildSettings {
                hierarchy_detection: LogLevel::Error,
                ..default()
            });
        });
        // Each test's app on its own thread: the test threads already keep every core busy,
        // and the ambiguity check above holds all a multi-threaded executor could reorder.
        rubber_band_box::game::simulation::run_single_threaded(&mut app);
        app.finish();
        app.cleanup();
        // The first update only starts the clock: it runs Startup and no fixed step.
        app.update();
        Self { app, window }
    }

    /// One fixed step (10 ms at the seed's 100 Hz) per update.
    pub fn stepping() -> Self {
        Self::new(Duration::from_millis(10))
    }

    pub fn world(&mut self) -> &mut World {
        self.app.world_mut()
    }

    pub fn update(&mut self, frames: usize) {
        for _ in 0..frames {
            self.app.update();
        }
    }

    pub fn cursor(&mut self, screen: Option<Vec2>) {
        let window = self.window;
        self.world()
            .get_mut::<Window>(window)
            .unwrap()
            .set_cursor_position(screen);
    }

    pub fn mouse(&mut self, state: ButtonState) {
        let window = self.window;
        self.world().write_message(MouseButtonInput {
            button: MouseButton::Left,
            state,
            window,
        });
    }

    /// Presses the mouse where the scene shows the world point `world` now.
    ///
    /// At home in [`WINDOW`] that is [`world_to_screen`]; learn mode frames closer.
    pub fn press_at(&mut self, world: DVec2) {
        let at = self.window_point(world);
        self.cursor(Some(at));
        self.mouse(ButtonState::Pressed);
    }

    /// Returns the scene's viewport on the window: the layout's, or without it the whole window.
    pub fn viewport(&mut self) -> Rect {
        let window = self.window;
        let world = self.world();
        let whole = Rect::from_corners(Vec2::ZERO, world.get::<Window>(window).unwrap().size());
        world
            .resource::<rubber_band_box::game::layout::SceneViewport>()
            .0
            .unwrap_or(whole)
    }

    /// Returns where the camera's frame shows a world point on the window, as the pointer maps.
    pub fn window_point(&mut self, world: DVec2) -> Vec2 {
        use rubber_band_box::game::camera::CameraFrame;
        let viewport = self.viewport();
        let frame = self.world().resource::<CameraFrame>();
        frame
            .view(viewport.size())
            .to_window(world.as_vec2(), viewport)
    }

    pub fn key(&mut self, key_code: KeyCode, state: ButtonState) {
        let window = self.window;
        self.world().write_message(KeyboardInput {
            key_code,
            logical_key: Key::Character("i".into()),
            state,
            text: None,
            repeat: false,
            window,
        });
    }

    /// A key pressed and released before the next frame: `just_pressed` in it.
    pub fn tap_key(&mut self, key_code: KeyCode) {
        self.key(key_code, ButtonState::Pressed);
        self.key(key_code, ButtonState::Released);
    }

    /// A touch at a screen position (the property tests' fingers may land outside the window).
    pub fn touch_screen(&mut self, id: u64, phase: TouchPhase, position: Vec2) {
        let window = self.window;
        self.world().write_message(TouchInput {
            phase,
            position,
            window,
            force: None,
            id,
        });
    }

    pub fn touch(&mut self, id: u64, phase: TouchPhase, world: DVec2) {
        let window = self.window;
        self.world().write_message(TouchInput {
            phase,
            position: world_to_screen(world),
            window,
            force: None,
            id,
        });
    }

    /// Returns the panel's button that does `does` (the first, where two do).
    pub fn button(&mut self, does: rubber_band_box::game::input::panel::PanelButton) -> Entity {
        use rubber_band_box::game::input::panel::PanelButton;
        let world = self.world();
        let mut buttons = world.query::<(Entity, &PanelButton)>();
        buttons
            .iter(world)
            .find(|(_, button)| **button == does)
            .map(|(entity, _)| entity)
            .unwrap_or_else(|| panic!("no button for {does:?}"))
    }

    /// Returns the panel's slider of `parameter`.
    pub fn slider(
        &mut self,
        parameter: rubber_band_box::game::input::controls::Parameter,
    ) -> Entity {
        use rubber_band_box::game::input::panel::PanelSlider;
        let world = self.world();
        let mut sliders = world.query::<(Entity, &PanelSlider)>();
        sliders
            .iter(world)
            .find(|(_, slider)| slider.0 == parameter)
            .map(|(entity, _)| entity)
            .unwrap_or_else(|| panic!("no slider for {parameter:?}"))
    }

    pub fn bands(&mut self) -> Vec<Band> {
        let mut query = self.world().query::<&Band>();
        query.iter(self.world()).copied().collect()
    }

    pub fn the_band(&mut self) -> Band {
        let bands = self.bands();
        assert_eq!(bands.len(), 1, "expected exactly one band");
        bands[0]
    }

    pub fn state(&mut self) -> (LinearState, AngularState) {
        let mut query = self
            .world()
            .query_filtered::<(&LinearState, &AngularState), With<RigidBox>>();
        let (linear, angular) = query.single(self.world()).unwrap();
        (*linear, *angular)
    }

    /// The window resized to `size`, and the camera's values recomputed as bevy_render would.
    pub fn resize(&mut self, size: UVec2) {
        let window = self.window;
        self.world()
            .get_mut::<Window>(window)
            .unwrap()
            .resolution
            .set(size.x as f32, size.y as f32);
        let mut cameras = self.world().query::<(&mut Camera, &mut Projection)>();
        for (mut camera, mut projection) in cameras.iter_mut(self.app.world_mut()) {
            compute_camera(&mut camera, &mut projection, size);
        }
    }

    /// Returns what the line of text named `name` says now: "HUD Status", "Energy Total".
    ///
    /// Each line of the HUD and of the Readouts and Energy cards is named by its place and its
    /// reading.
    pub fn line(&mut self, name: &str) -> String {
        let mut lines = self.world().query::<(&Name, &Text)>();
        let found: Vec<String> = lines
            .iter(self.world())
            .filter(|(named, _)| named.as_str() == name)
            .map(|(_, text)| text.0.clone())
            .collect();
        match found.as_slice() {
            [text] => text.clone(),
            _ => panic!("{} lines named {name:?}", found.len()),
        }
    }

    /// The ghosts' table as its grid shows it: a row a line, the cells two spaces apart.
    pub fn ghost_table(&mut self) -> String {
        use rubber_band_box::game::ghosts::table::GhostCell;
        let mut cells: Vec<(GhostCell, String)> = self
            .world()
            .query::<(&GhostCell, &Text)>()
            .iter(self.world())
            .map(|(cell, text)| (*cell, text.0.clone()))
            .collect();
        cells.sort_by_key(|(cell, _)| (cell.row, cell.column));
        let mut rows: Vec<Vec<String>> = Vec::new();
        for (cell, text) in cells {
            if rows.len() <= cell.row {
                rows.resize(cell.row + 1, Vec::new());
            }
            if !text.is_empty() {
                rows[cell.row].push(text);
            }
        }
        rows.iter()
            .filter(|row| !row.is_empty())
            .map(|row| row.join("  "))
            .collect::<Vec<_>>()
            .join("\n")
    }

    pub fn steps(&mut self) -> u64 {
        self.world().resource::<StepCount>().0
    }

    /// Returns what the status line says now ("" when it says nothing).
    pub fn status(&mut self) -> String {
        self.world()
            .resource::<rubber_band_box::game::shared::StatusMessage>()
            .0
            .clone()
            .unwrap_or_default()
    }
}

/// The largest accumulator seen right after an integration step.
#[derive(Resource, Default)]
pub struct AccumulatorAudit {
    pub steps: u64,
    pub largest: f64,
    pub bands_left: usize,
}

pub fn audit_accumulators(bodies: Query<&ForceAccumulator>, mut audit: ResMut<AccumulatorAudit>) {
    for accumulator in &bodies {
        let Wrench { force, torque } = accumulator.forces.total();
        audit.steps += 1;
        audit.largest = audit.largest.max(force.length()).max(torque.abs());
        audit.bands_left += usize::from(accumulator.band.is_some());
    }
}

/// Opens `replay` in the running game, as a file dropped on it opens it.
pub fn open_replay(world: &mut World, replay: Replay) {
    world.trigger(rubber_band_box::game::replays::playback::OpenReplay(replay));
    world.flush();
}

/// A small valid replay: a pull, a release, a reset, a change of settings.
pub fn small_replay() -> Replay {
    let params = SceneParams::tutorial();
    let settings = Settings::new(&params, 0.01, Integrator::Auto);
    let mut replay = Replay::start(
        "tutorial",
        settings,
        AutoSettings::default(),
        BodyState::default(),
    );
    let mut stepper = replay.stepper().unwrap();
    let band = BandEnds {
        local_point: DVec2::new(30.0, 30.0),
        anchor: DVec2::new(200.0, 120.0),
    };
    for step in 0..12 {
        if step == 4 {
            replay.push_reset();
            stepper.state = BodyState::default();
        }
        if step == 8 {
            let stiffer = Settings {
                stiffness: 2000.0,
                integrator: Integrator::Rk4,
                ..settings
            };
            replay.push_settings(stiffer);
            stepper.params.stiffness = 2000.0;
            stepper.integrator = Integrator::Rk4;
        }
        stepper.band = (step % 3 != 2).then_some(band);
        stepper.step(0.01);
        replay.push_step(stepper.band, &stepper.state);
    }
    replay
}

/// Every state the game's box had after each fixed step, as the physics left it (a test adds
/// it with [`Game::keeping_trajectory`]).
#[derive(Resource, Default)]
pub struct Trajectory(pub Vec<BodyState>);

fn keep_trajectory(
    mut trajectory: ResMut<Trajectory>,
    boxes: Query<(&LinearState, &AngularState), With<RigidBox>>,
) {
    for (linear, angular) in &boxes {
        trajectory.0.push(BodyState {
            linear: *linear,
            angular: *angular,
        });
    }
}

impl Game {
    /// A headless game at `frame` per update that keeps its [`Trajectory`], with `extra`
    /// applied as [`Game::with`] does.
    pub fn keeping_trajectory(frame: Duration, extra: impl FnOnce(&mut App)) -> Self {
        Self::with(frame, |app| {
            keep_the_trajectory(app);
            extra(app);
        })
    }
}

/// Keeps the [`Trajectory`] of the app's box.
pub fn keep_the_trajectory(app: &mut App) {
    app.init_resource::<Trajectory>()
        .add_systems(FixedUpdate, keep_trajectory.after(PhysicsSystems::Step));
}

impl Game {}

/// States as their bits, for comparing trajectories exactly.
pub fn bits(states: &[BodyState]) -> Vec<[u64; 6]> {
    states
        .iter()
        .map(|state| state.to_array().map(f64::to_bits))
        .collect()
}

impl Game {
    /// The game with its screen and Bevy's UI layout (see [`Game::with_screen`]).
    pub fn laid_out() -> Self {
        Self::with_screen(|app| {
            add_the_layout(app);
            add_the_screen(app);
        })
    }

    /// The game with what `plugins` adds, the screen's among them, one fixed step a frame.
    ///
    /// The view's own camera has no renderer to compute its projection, so it goes: the
    /// test's camera (as bevy_render would compute it) is placed by the view as its own.
    pub fn with_screen(plugins: impl FnOnce(&mut App)) -> Self {
        let mut game = Game::with(Duration::from_millis(10), plugins);
        let world = game.world();
        let views: Vec<Entity> = world
            .query::<(Entity, &Name)>()
            .iter(world)
            .filter(|(_, name)| name.as_str() == "Camera")
            .map(|(entity, _)| entity)
            .collect();
        assert_eq!(views.len(), 1, "the view's camera");
        world.despawn(views[0]);
        game
    }

    /// Returns where the scene camera puts a world point on the window: its transform and its
    /// projection's scale, in the viewport Bevy's layout gave it.
    pub fn on_window(&mut self, world_point: Vec2) -> Vec2 {
        let viewport = self.viewport();
        let world = self.world();
        let mut cameras = world.query_filtered::<(&Transform, &Projection), With<SceneCamera>>();
        let (transform, projection) = cameras.single(world).unwrap();
        let Projection::Orthographic(orthographic) = projection else {
            panic!("the scene camera is orthographic");
        };
        let offset = (world_point - transform.translation.truncate()) / orthographic.scale;
        viewport.center() + Vec2::new(offset.x, -offset.y)
    }

    /// Returns the box's corners as drawn this frame, in the world.
    pub fn drawn_corners(&mut self) -> Vec<Vec2> {
        use rubber_band_box::game::simulation::{RenderSnapshots, interpolated_state};
        use rubber_band_box::physics::MassProperties;
        let world = self.world();
        let fixed = *world.resource::<Time<bevy::time::Fixed>>();
        let mut boxes = world.query::<(&RenderSnapshots, &MassProperties)>();
        let (snapshots, mass) = boxes.single(world).unwrap();
        let state = interpolated_state(snapshots, &fixed);
        mass.corners()
            .iter()
            .map(|&corner| state.local_to_world(corner).as_vec2())
            .collect()
    }
}

/// The screen's plugins (view, drawing, energy graph, plot) added to a headless game, with
/// what the renderer would bring for them: assets, and the ones the gizmos' mesh bounds read.
pub fn add_the_screen(app: &mut App) {
    use rubber_band_box::game::GameScreenPlugin;
    if !app.is_plugin_added::<bevy::asset::AssetPlugin>() {
        app.add_plugins(bevy::asset::AssetPlugin::default());
    }
    app.init_asset::<Mesh>()
        .init_asset::<bevy::mesh::skinning::SkinnedMeshInverseBindposes>();
    app.add_plugins((bevy::gizmos::GizmoPlugin, GameScreenPlugin));
}

/// Bevy's own UI layout, with no renderer: the panel's and the HUD's nodes get their
/// `ComputedNode` and place as in a window (text measured with Bevy's default font), and
/// picking, focus and accessibility as the UI plugin needs them.
pub fn add_the_layout(app: &mut App) {
    if !app.is_plugin_added::<bevy::asset::AssetPlugin>() {
        app.add_plugins(bevy::asset::AssetPlugin::default());
    }
    app.add_plugins((
        bevy::image::ImagePlugin::default(),
        bevy::image::TextureAtlasPlugin,
        bevy::text::TextPlugin,
        bevy::a11y::AccessibilityPlugin,
        bevy::picking::input::PointerInputPlugin,
        bevy::picking::PickingPlugin,
        bevy::picking::InteractionPlugin,
        bevy::ui::UiPlugin,
    ));
    // The game's focus plugin adds these when it comes first.
    if !app.is_plugin_added::<bevy::input_focus::InputFocusPlugin>() {
        app.add_plugins((
            bevy::input_focus::InputFocusPlugin,
            bevy::input_focus::InputDispatchPlugin,
        ));
    }
}

/// A path in this test binary's own scratch folder (under the system's temporary folder, named
/// by the binary and its process), with nothing at it yet.
pub fn scratch(name: &str) -> std::path::PathBuf {
    let binary = std::env::current_exe()
        .ok()
        .and_then(|path| path.file_stem().map(|s| s.to_string_lossy().into_owned()))
        .unwrap_or_default();
    let folder = std::env::temp_dir().join(format!("rbb-{binary}-{}", std::process::id()));
    std::fs::create_dir_all(&folder).expect("a scratch folder");
    let path = folder.join(name);
    let _ = std::fs::remove_dir_all(&path);
    let _ = std::fs::remove_file(&path);
    path
}

/// The game's binary with its subcommand, as a user runs it.
pub fn binary(subcommand: &str) -> std::process::Command {
    let mut command = std::process::Command::new(env!("CARGO_BIN_EXE_rubber_band_box"));
    command.arg(subcommand);
    command
}

/// What a mouse click (or a finger's tap, `PointerId::Touch`) on `entity` sends through picking.
pub fn click(game: &mut Game, entity: Entity, pointer: bevy::picking::pointer::PointerId) {
    use bevy::camera::{ManualTextureViewHandle, NormalizedRenderTarget};
    use bevy::picking::backend::HitData;
    use bevy::picking::events::{Click, Pointer, Press, Release};
    use bevy::picking::pointer::{Location, PointerButton};
    let location = Location {
        target: NormalizedRenderTarget::TextureView(ManualTextureViewHandle(0)),
        position: Vec2::new(900.0, 40.0),
    };
    let hit = HitData::new(Entity::PLACEHOLDER, 0.0, None, None);
    let button = PointerButton::Primary;
    let world = game.world();
    world.trigger(Pointer::new(
        pointer,
        location.clone(),
        Press {
            button,
            hit: hit.clone(),
            count: 1,
        },
        entity,
    ));
    world.flush();
    world.trigger(Pointer::new(
        pointer,
        location.clone(),
        Click {
            button,
            hit: hit.clone(),
            duration: Duration::from_millis(80),
            count: 1,
        },
        entity,
    ));
    world.trigger(Pointer::new(
        pointer,
        location,
        Release { button, hit },
        entity,
    ));
    world.flush();
    game.update(1);
}

/// The hash of every state the game's steps left ([`Trajectory`]), kept apart from the
/// recorder, and the number of steps.
pub fn own_hash(game: &mut Game) -> (u64, rubber_band_box::replay::TrajectoryHash) {
    let trajectory = &game.world().resource::<Trajectory>().0;
    let mut hash = rubber_band_box::replay::TrajectoryHash::default();
    for state in trajectory {
        hash.add(state);
    }
    (trajectory.len() as u64, hash)
}

/// Checks that the game's recording, written and read back, steps to the game's own hash.
///
/// The game keeps its [`Trajectory`]; `what` names the case in a failure.
pub fn assert_replays(game: &mut Game, what: &str) {
    use rubber_band_box::game::replays::recording::Recorder;
    use rubber_band_box::replay::Integrity;
    use rubber_band_box::replay::run::ReplayRun;
    let (steps, hash) = own_hash(game);
    let recorded = game
        .world()
        .resource::<Recorder>()
        .replay
        .clone()
        .expect("a recording");
    assert_eq!(recorded.steps, steps, "{what}: every step recorded");
    assert_eq!(recorded.hash, hash, "{what}: the recorder's hash");
    let read = Replay::from_bytes(&recorded.to_bytes()).expect("the recording reads back");
    assert_eq!(read.integrity, Integrity::Intact);
    let mut run = ReplayRun::new(&read, None).unwrap();
    let replayed = run.finish();
    assert!(
        replayed == hash,
        "{what}: the recording replays to another game: {}",
        run.explain_mismatch()
    );
}
