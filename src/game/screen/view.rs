//! The cameras, and the interpolation that draws the box between fixed steps so that motion
//! is smooth at any display rate (as Bevy's `physics_in_fixed_timestep` example does).
//!
//! The scene's camera renders into the layout's viewport ([`SceneViewport`]) only, so nothing
//! of the world is ever drawn under the dock. It frames the tutorial's 640 x 480 screen by
//! default ([`CameraFrame::home`]); when a pull takes the box or the band's anchor out of the
//! frame's inner 80%, it widens smoothly to keep them in, and eases back when they return.
//! The wheel and a pinch zoom, the right button and two fingers pan, F (or the panel's
//! "frame") returns at once. The pointer maps through the same camera.
//!
//! A second camera draws the dock's charts (gizmos on their own render layer, in window
//! pixels) and the UI over the whole window.

use bevy::camera::visibility::RenderLayers;
use bevy::camera::{ClearColorConfig, ScalingMode, Viewport};
use bevy::input::mouse::{MouseScrollUnit, MouseWheel};
use bevy::prelude::*;
use bevy::ui::IsDefaultUiCamera;
use bevy::window::PrimaryWindow;

use crate::game::input::controls::HomeView;
use crate::game::layout::SceneViewport;
use crate::game::pointer::SceneCamera;
use crate::game::schedule::{AfterStepsSystems, ScreenSystems};
use crate::game::simulation::{Band, RenderSnapshots, ResetScene};
use crate::physics::{BodyState, MassProperties, SCENE_SIZE};

pub struct ViewPlugin;

impl Plugin for ViewPlugin {
    fn build(&self, app: &mut App) {
        app.init_resource::<CameraFrame>()
            .add_systems(Startup, spawn_cameras)
            .add_observer(go_home)
            .add_observer(go_home_on_reset)
            .add_systems(
                RunFixedMainLoop,
                (interpolate_body_transforms, place_band_pins).in_set(AfterStepsSystems::Conclude),
            )
            .add_systems(
                Update,
                (zoom_and_pan, follow_the_box, place_cameras)
                    .chain()
                    .in_set(ScreenSystems::Camera),
            );
        #[cfg(target_arch = "wasm32")]
        app.add_systems(
            Update,
            publish_view
                .after(place_cameras)
                .in_set(ScreenSystems::Camera),
        );
    }
}

/// Publishes where the tutorial's screen and the box's corners are on the page.
///
/// In the browser only.
#[cfg(target_arch = "wasm32")]
fn publish_view(
    fixed_time: Res<Time<Fixed>>,
    window: Option<Single<&Window, With<PrimaryWindow>>>,
    viewport: Res<SceneViewport>,
    frame: Res<CameraFrame>,
    boxes: Query<(&RenderSnapshots, &MassProperties)>,
    mut published: Local<(Option<Rect>, String)>,
) {
    let (Some(window), Some(view)) = (window, frame.shown) else {
        return;
    };
    let area = viewport_rect(&viewport, &window);
    let half = SCENE_SIZE.as_vec2() / 2.0;
    let scene = Rect::from_corners(view.to_window(-half, area), view.to_window(half, area));
    if published.0 != Some(scene) {
        crate::game::web::publish_scene(scene.min.x, scene.min.y, scene.width(), scene.height());
        published.0 = Some(scene);
    }
    let corners: Vec<[f32; 2]> = boxes
        .iter()
        .flat_map(|(snapshots, mass)| {
            let state = interpolated_state(snapshots, &fixed_time);
            mass.corners().map(|corner| {
                view.to_window(state.local_to_world(corner).as_vec2(), area)
                    .to_array()
            })
        })
        .collect();
    let json = serde_json::to_string(&corners).unwrap_or_default();
    if published.1 != json {
        crate::game::web::publish_box(&json);
        published.1 = json;
    }
}

/// The render layer of the dock's charts: only the chart camera draws it.
pub const CHART_LAYER: usize = 1;

/// The camera that draws the dock's charts and the UI, over the whole window.
#[derive(Component, Debug)]
struct ChartCamera;

/// What the scene's camera shows: a centre and a zoom, in world units per logical pixel.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct View {
    pub centre: Vec2,
    pub world_per_pixel: f32,
}

impl View {
    /// Returns the part of the world the view shows in a viewport of `size` logical pixels.
    fn area(&self, size: Vec2) -> Rect {
        Rect::from_center_size(self.centre, size * self.world_per_pixel)
    }

    /// Returns the view, centred on `area`, that shows it whole in a viewport of `size`.
    ///
    /// The aspect is kept.
    fn fitting(area: Rect, size: Vec2) -> Self {
        let ratio = area.size() / size.max(Vec2::ONE);
        Self {
            centre: area.center(),
            world_per_pixel: ratio.max_element().max(f32::MIN_POSITIVE),
        }
    }

    /// Returns a world point's place on the window, in logical pixels.
    ///
    /// The viewport lies at `viewport`.
    pub fn to_window(&self, world: Vec2, viewport: Rect) -> Vec2 {
        let offset = (world - self.centre) / self.world_per_pixel;
        viewport.center() + Vec2::new(offset.x, -offset.y)
    }
}

/// The scene camera's frame: where the player put it and what it shows now.
///
/// Where the player put it is the home: the tutorial's screen, or as zoomed and panned.
#[derive(Resource, Debug, Clone, Copy, PartialEq)]
pub struct CameraFrame {
    /// The player's zoom about the home frame (1: the tutorial's screen fitted) and pan.
    pub zoom: f32,
    pub pan: Vec2,
    /// What the camera shows this frame (`None` until the first).
    pub shown: Option<View>,
}

impl Default for CameraFrame {
    fn default() -> Self {
        Self {
            zoom: 1.0,
            pan: Vec2::ZERO,
            shown: None,
        }
    }
}

/// The room left around the tutorial's screen in the home frame, as a share of it.
const HOME_MARGIN: f32 = 1.04;
/// The share of the view that counts as well inside: out of it, the camera widens.
const INNER: f32 = 0.8;
/// How fast the view eases toward where it should be, per second.
const EASE_RATE: f32 = 6.0;
/// The player's zoom's range.
const ZOOM_RANGE: (f32, f32) = (0.05, 20.0);

impl CameraFrame {
    /// Returns the home view in a viewport of `size`.
    ///
    /// It fits the tutorial's screen, then applies the player's zoom and pan.
    fn home(&self, size: Vec2) -> View {
        let screen = Rect::from_center_size(Vec2::ZERO, SCENE_SIZE.as_vec2() * HOME_MARGIN);
        let fitted = View::fitting(screen, size);
        View {
            centre: self.pan,
            world_per_pixel: fitted.world_per_pixel * self.zoom,
        }
    }
}

/// Returns where the view should be to keep `keep` (the box's corners, the anchor) in sight.
///
/// It is the home view while they lie in its inner 80%; else the least view, centred between, that
/// holds the home frame's centre and them in its inner 80%.
fn wanted_view(home: View, size: Vec2, keep: Rect) -> View {
    let inner = Rect::from_center_size(home.centre, size * home.world_per_pixel * INNER);
    if keep.is_empty() || inner.union(keep) == inner {
        return home;
    }
    let area = home.area(size).union(keep);
    let mut view = View::fitting(area, size * INNER);
    view.world_per_pixel = view.world_per_pixel.max(home.world_per_pixel);
    view
}

/// Eases `shown` toward `wanted` by the share `ease` (0 to 1), the zoom on a log scale.
///
/// Then, if `keep` is not whole in it, widens it at once until it is (the box is never lost).
fn eased_view(shown: View, wanted: View, ease: f32, size: Vec2, keep: Rect) -> View {
    let mut view = View {
        centre: shown.centre.lerp(wanted.centre, ease),
        world_per_pixel: (shown.world_per_pixel.ln()
            + (wanted.world_per_pixel.ln() - shown.world_per_pixel.ln()) * ease)
            .exp(),
    };
    let area = view.area(size);
    if !keep.is_empty() && area.union(keep) != area {
        // The least view holding both what it showed and what must be seen.
        let grown = area.union(keep.inflate(keep.size().max_element() * 0.05));
        view = View::fitting(grown, size);
    }
    view
}

/// Returns what must stay in sight: every box's corners (as drawn) and the band's anchor.
fn kept_in_sight(
    fixed_time: &Time<Fixed>,
    boxes: &Query<(&RenderSnapshots, &MassProperties)>,
    bands: &Query<&Band>,
) -> Rect {
    let mut keep = Rect::EMPTY;
    for (snapshots, mass) in boxes {
        let state = interpolated_state(snapshots, fixed_time);
        for corner in mass.corners() {
            keep = keep.union_point(state.local_to_world(corner).as_vec2());
        }
    }
    for band in bands {
        keep = keep.union_point(band.ends.anchor.as_vec2());
    }
    keep
}

/// Returns the viewport's rectangle now, in logical pixels: the layout's, or the whole window.
fn viewport_rect(viewport: &SceneViewport, window: &Window) -> Rect {
    viewport
        .0
        .unwrap_or(Rect::from_corners(Vec2::ZERO, window.size()))
}

fn spawn_cameras(mut commands: Commands) {
    commands.spawn((
        Name::new("Camera"),
        Camera2d,
        SceneCamera,
        scene_projection(),
    ));
    commands.spawn((
        Name::new("Chart camera"),
        Camera2d,
        ChartCamera,
        IsDefaultUiCamera,
        Camera {
            order: 1,
            clear_color: ClearColorConfig::None,
            ..default()
        },
        RenderLayers::layer(CHART_LAYER),
        // One world unit a logical pixel, the origin at the window's centre.
        Projection::Orthographic(OrthographicProjection {
            scaling_mode: ScalingMode::WindowSize,
            ..OrthographicProjection::default_2d()
        }),
    ));
}

/// Returns an orthographic projection whose scale the view sets.
fn scene_projection() -> Projection {
    Projection::Orthographic(OrthographicProjection {
        scaling_mode: ScalingMode::WindowSize,
        ..OrthographicProjection::default_2d()
    })
}

fn go_home(_home: On<HomeView>, mut frame: ResMut<CameraFrame>) {
    frame.zoom = 1.0;
    frame.pan = Vec2::ZERO;
    // At once, not eased.
    frame.shown = None;
}

/// Starts the view over on a reset too.
fn go_home_on_reset(_reset: On<ResetScene>, mut frame: ResMut<CameraFrame>) {
    *frame = CameraFrame::default();
}

/// Zooms and pans the view with the wheel, the right button and two fingers.
///
/// The wheel zooms about the pointer, the right button drags the view, two fingers pinch and pan:
/// all on the scene's viewport only (the wheel over the dock scrolls it).
#[allow(clippy::too_many_arguments)]
fn zoom_and_pan(
    mut wheel: MessageReader<MouseWheel>,
    buttons: Res<ButtonInput<MouseButton>>,
    touches: Res<Touches>,
    window: Option<Single<&Window, With<PrimaryWindow>>>,
    viewport: Res<SceneViewport>,
    mut frame: ResMut<CameraFrame>,
    mut last_cursor: Local<Option<Vec2>>,
    mut last_pinch: Local<Option<(f32, Vec2)>>,
) {
    let Some(window) = window else {
        wheel.clear();
        return;
    };
    let area = viewport_rect(&viewport, &window);
    let Some(shown) = frame.shown else {
        wheel.clear();
        return;
    };
    let home = frame.home(area.size());
    let cursor = window.cursor_position();
    // A change of zoom about a window point: the world point under it stays under it.
    let zoom_about = |frame: &mut CameraFrame, factor: f32, at: Vec2| {
        let zoom = (frame.zoom * factor).clamp(ZOOM_RANGE.0, ZOOM_RANGE.1);
        let applied = zoom / frame.zoom;
        let offset = at - area.center();
        let world_at = shown.centre + Vec2::new(offset.x, -offset.y) * shown.world_per_pixel;
        frame.pan = world_at + (frame.pan - world_at) * applied;
        frame.zoom = zoom;
    };
    for event in wheel.read() {
        let Some(at) = cursor.filter(|at| area.contains(*at)) else {
            continue;
        };
        let lines = match event.unit {
            MouseScrollUnit::Line => event.y,
            MouseScrollUnit::Pixel => event.y / 40.0,
        };
        zoom_about(&mut frame, 1.1f32.powf(-lines), at);
    }
    // The right button drags the world with it.
    if buttons.pressed(MouseButton::Right)
        && let (Some(now), Some(before)) = (cursor, *last_cursor)
        && area.contains(before)
    {
        let moved = now - before;
        frame.pan -= Vec2::new(moved.x, -moved.y) * home.world_per_pixel;
    }
    *last_cursor = cursor;
    // Two fingers: their spread zooms, their middle pans.
    let fingers: Vec<Vec2> = touches
        .iter()
        .map(|touch| touch.position())
        .take(2)
        .collect();
    if let [a, b] = fingers[..] {
        let (spread, middle) = (a.distance(b).max(1.0), (a + b) / 2.0);
        if let Some((before_spread, before_middle)) = *last_pinch {
            zoom_about(&mut frame, before_spread / spread, middle);
            let moved = middle - before_middle;
            frame.pan -= Vec2::new(moved.x, -moved.y) * home.world_per_pixel;
        }
        *last_pinch = Some((spread, middle));
    } else {
        *last_pinch = None;
    }
}

/// Eases the view toward where it should be this frame; the box and the anchor always in it.
fn follow_the_box(
    time: Res<Time<Real>>,
    fixed_time: Res<Time<Fixed>>,
    window: Option<Single<&Window, With<PrimaryWindow>>>,
    viewport: Res<SceneViewport>,
    boxes: Query<(&RenderSnapshots, &MassProperties)>,
    bands: Query<&Band>,
    mut frame: ResMut<CameraFrame>,
) {
    let Some(window) = window else {
        return;
    };
    let size = viewport_rect(&viewport, &window).size();
    if size.min_element() <= 0.0 {
        return;
    }
    let keep = kept_in_sight(&fixed_time, &boxes, &bands);
    let home = frame.home(size);
    let wanted = wanted_view(home, size, keep);
    let shown = frame.shown.unwrap_or(wanted);
    let ease = 1.0 - (-EASE_RATE * time.delta_secs()).exp();
    let view = eased_view(shown, wanted, ease, size, keep);
    if frame.shown != Some(view) {
        frame.shown = Some(view);
    }
}

/// Places the cameras: the scene's renders into the viewport, showing the frame's view.
///
/// The chart camera covers the window.
fn place_cameras(
    window: Option<Single<&Window, With<PrimaryWindow>>>,
    viewport: Res<SceneViewport>,
    frame: Res<CameraFrame>,
    mut cameras: Query<(&mut Camera, &mut Projection, &mut Transform), With<SceneCamera>>,
) {
    let (Some(window), Some(view)) = (window, frame.shown) else {
        return;
    };
    let area = viewport_rect(&viewport, &window);
    let scale = window.scale_factor();
    let physical = Viewport {
        physical_position: (area.min * scale).round().as_uvec2(),
        physical_size: (area.size() * scale).round().as_uvec2().max(UVec2::ONE),
        ..default()
    };
    for (mut camera, mut projection, mut transform) in &mut cameras {
        // Without a layout (the headless game) the camera keeps the whole window.
        if viewport.0.is_some()
            && camera.viewport.as_ref().is_none_or(|now| {
                now.physical_position != physical.physical_position
                    || now.physical_size != physical.physical_size
            })
        {
            camera.viewport = Some(physical.clone());
        }
        let position = view.centre.extend(transform.translation.z);
        if transform.translation != position {
            transform.translation = position;
        }
        if let Projection::Orthographic(orthographic) = &mut *projection
            && (!matches!(orthographic.scaling_mode, ScalingMode::WindowSize)
                || orthographic.scale != view.world_per_pixel)
        {
            orthographic.scaling_mode = ScalingMode::WindowSize;
            orthographic.scale = view.world_per_pixel;
        }
    }
}

/// Returns the world units a logical pixel spans now (1 before the first view).
pub fn world_per_pixel(frame: &CameraFrame) -> f32 {
    frame.shown.map_or(1.0, |view| view.world_per_pixel)
}

/// Returns the part of the world the scene's camera shows now, if it has shown any.
pub fn shown_area(frame: &CameraFrame, viewport: &SceneViewport, window: &Window) -> Option<Rect> {
    let size = viewport_rect(viewport, window).size();
    frame.shown.map(|view| view.area(size))
}

/// Returns the state to draw this frame, between the last two fixed steps.
///
/// It lies as far between them as the clock has run past the last one.
pub fn interpolated_state(snapshots: &RenderSnapshots, fixed_time: &Time<Fixed>) -> BodyState {
    snapshots.interpolate(fixed_time.overstep_fraction_f64().clamp(0.0, 1.0))
}

/// Writes each body's `Transform` from the physics state, for rendering only.
///
/// Physics never reads it.
fn interpolate_body_transforms(
    fixed_time: Res<Time<Fixed>>,
    mut bodies: Query<(&RenderSnapshots, &mut Transform)>,
) {
    for (snapshots, mut transform) in &mut bodies {
        let state = interpolated_state(snapshots, &fixed_time);
        transform.translation = state
            .linear
            .position
            .as_vec2()
            .extend(transform.translation.z);
        transform.rotation = Quat::from_rotation_z(state.angular.orientation as f32);
    }
}

/// Places each band's pin at its anchor.
///
/// Bands and bodies are never the same entity: said, so the two writers of `Transform` need no
/// order between them.
fn place_band_pins(mut bands: Query<(&Band, &mut Transform), Without<RenderSnapshots>>) {
    for (band, mut transform) in &mut bands {
        transform.translation = band.ends.anchor.as_vec2().extend(transform.translation.z);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Checks that the camera keeps the box in view and comes home.
    ///
    /// While the box and the anchor lie well inside the home frame it stays home; pulled out, it
    /// widens so that both lie inside, at every frame, however fast, and comes home when they do.
    #[test]
    fn the_view_keeps_the_box_and_comes_home() {
        let size = Vec2::new(600.0, 500.0);
        let frame = CameraFrame::default();
        let home = frame.home(size);
        let screen = home.area(size);
        assert!(
            screen.width() >= 640.0 && screen.height() >= 480.0,
            "{screen:?}"
        );
        let near = Rect::from_center_size(Vec2::new(50.0, 20.0), Vec2::splat(60.0));
        assert_eq!(wanted_view(home, size, near), home);
        let mut shown = home;
        // A box flung far right and up, then back.
        for step in 0..200 {
            let t = step as f32 / 100.0;
            let centre = if t < 1.0 {
                Vec2::new(900.0 * t, 500.0 * t)
            } else {
                Vec2::new(900.0 * (2.0 - t), 500.0 * (2.0 - t))
            };
            let keep = Rect::from_center_size(centre, Vec2::splat(85.0));
            let wanted = wanted_view(home, size, keep);
            shown = eased_view(shown, wanted, 0.1, size, keep);
            let area = shown.area(size);
            assert!(
                area.union(keep) == area,
                "step {step}: {keep:?} out of {area:?}"
            );
        }
        for _ in 0..100 {
            shown = eased_view(shown, wanted_view(home, size, near), 0.1, size, near);
        }
        assert!(shown.centre.distance(home.centre) < 1.0, "{shown:?}");
        assert!((shown.world_per_pixel / home.world_per_pixel - 1.0).abs() < 0.01);
    }
}
