//! The camera that keeps the tutorial's 640 x 480 scene in view at any window size, in the
//! part of the window the on-screen panel and the HUD leave free, and the interpolation that draws the
//! box between fixed steps so that motion is smooth at any display rate (as Bevy's
//! `physics_in_fixed_timestep` example does).

use bevy::camera::ScalingMode;
use bevy::prelude::*;

use crate::game::schedule::{AfterStepsSystems, ScreenSystems};
use crate::game::shared::{ControlsArea, HudArea};
use crate::game::simulation::{Band, RenderSnapshots};
use crate::physics::{BodyState, SCENE_SIZE};

pub struct ViewPlugin;

impl Plugin for ViewPlugin {
    fn build(&self, app: &mut App) {
        app.add_systems(Startup, spawn_camera)
            .add_systems(
                RunFixedMainLoop,
                (interpolate_body_transforms, place_band_pins).in_set(AfterStepsSystems::Conclude),
            )
            .add_systems(
                Update,
                (scale_ui_to_window, fit_scene_to_free_area).in_set(ScreenSystems::Scale),
            );
    }
}

/// An orthographic projection that always shows the whole scene, centred, aspect kept: the
/// window's extra width or height shows more of the world around it.
pub fn scene_projection() -> Projection {
    Projection::Orthographic(OrthographicProjection {
        scaling_mode: ScalingMode::AutoMin {
            min_width: SCENE_SIZE.x as f32,
            min_height: SCENE_SIZE.y as f32,
        },
        ..OrthographicProjection::default_2d()
    })
}

/// The window's size when the game opens, in logical pixels: the tutorial's 640 x 480 scene
/// with room around it for the HUD and the panel.
pub const WINDOW_SIZE: UVec2 = UVec2::new(960, 720);

/// In a window smaller than [`WINDOW_SIZE`] (a phone) the HUD and the panel shrink with it, to
/// no less than 0.6, so that they leave the scene readable.
pub fn ui_scale_for(size: Vec2) -> f32 {
    let full = WINDOW_SIZE.as_vec2();
    (size.x / full.x).min(size.y / full.y).clamp(0.6, 1.0)
}

fn scale_ui_to_window(
    windows: Query<&Window, With<bevy::window::PrimaryWindow>>,
    mut scale: ResMut<UiScale>,
) {
    for window in &windows {
        let fit = ui_scale_for(window.size());
        if scale.0 != fit {
            scale.0 = fit;
        }
    }
}

/// The part of the window the scene is fitted to, in logical window pixels (origin at the top
/// left): of the rectangles bounded by the window's and the covered rectangles' edges, the one
/// whose fitted scene is the largest and lies clear of every covered rectangle (the panel's,
/// the HUD's); among equals, the largest (the whole window when nothing is in the way). With
/// no such rectangle, the whole window.
pub fn free_area(window: Vec2, covered: &[Rect]) -> Rect {
    let whole = Rect::from_corners(Vec2::ZERO, window);
    let covered: Vec<Rect> = covered
        .iter()
        .map(|rect| rect.intersect(whole))
        .filter(|rect| !rect.is_empty())
        .collect();
    let edges = |along: fn(Vec2) -> f32| {
        let mut edges: Vec<f32> = covered
            .iter()
            .flat_map(|rect| [along(rect.min), along(rect.max)])
            .chain([0.0, along(window)])
            .collect();
        edges.sort_by(f32::total_cmp);
        edges.dedup();
        edges
    };
    let (xs, ys) = (edges(|v| v.x), edges(|v| v.y));
    let mut best: Option<(f32, f32, Rect)> = None;
    for (i, &left) in xs.iter().enumerate() {
        for &right in &xs[i + 1..] {
            for (j, &top) in ys.iter().enumerate() {
                for &bottom in &ys[j + 1..] {
                    let area = Rect::new(left, top, right, bottom);
                    if !clear_of(fitted_scene(area), &covered) {
                        continue;
                    }
                    let key = (scene_scale(area), area.width() * area.height());
                    if best.is_none_or(|(scale, size, _)| key > (scale, size)) {
                        best = Some((key.0, key.1, area));
                    }
                }
            }
        }
    }
    best.map_or(whole, |(_, _, area)| area)
}

/// Whether `scene` lies clear of every rectangle of `covered` (touching is clear).
pub fn clear_of(scene: Rect, covered: &[Rect]) -> bool {
    covered.iter().all(|rect| rect.intersect(scene).is_empty())
}

/// The area to fit the scene to this frame: the present one while its scene stays in the
/// window and clear of what covers it, and nothing else fits the scene more than 5% larger
/// (the HUD's lines change width with their numbers: the scene does not follow each digit);
/// else the free area.
pub fn area_to_fit(window: Vec2, covered: &[Rect], present: Option<Rect>) -> Rect {
    let free = free_area(window, covered);
    let whole = Rect::from_corners(Vec2::ZERO, window);
    match present {
        Some(present)
            if whole.union(present) == whole
                && clear_of(fitted_scene(present), covered)
                && scene_scale(free) <= scene_scale(present) * 1.05 =>
        {
            present
        }
        _ => free,
    }
}

/// Window pixels a world unit spans when the scene fits `area`, aspect kept.
pub fn scene_scale(area: Rect) -> f32 {
    let scene = SCENE_SIZE.as_vec2();
    (area.width() / scene.x)
        .min(area.height() / scene.y)
        .max(0.0)
}

/// Where the tutorial's scene lies on the window when fitted to `area`: centred in it.
pub fn fitted_scene(area: Rect) -> Rect {
    Rect::from_center_size(area.center(), SCENE_SIZE.as_vec2() * scene_scale(area))
}

/// The camera shows the scene in the free area: its projection's scale and its position such
/// that the world's origin lies at the area's centre. Only once the panel has been laid out
/// (headless there is no layout, and the camera keeps fitting the whole window).
fn fit_scene_to_free_area(
    window: Single<&Window, With<bevy::window::PrimaryWindow>>,
    controls: Res<ControlsArea>,
    hud: Res<HudArea>,
    mut present: Local<Option<Rect>>,
    mut fitted_to: Local<Option<(Vec2, Vec<Rect>)>>,
    camera: Single<(&mut Projection, &mut Transform), With<Camera2d>>,
) {
    if controls.0.is_empty() {
        return;
    }
    let size = window.size();
    let covered: Vec<Rect> = controls.0.iter().chain(&hud.0).copied().collect();
    // The search is for a frame whose window or boxes moved, not for every frame.
    if fitted_to
        .as_ref()
        .is_some_and(|(fitted, boxes)| *fitted == size && *boxes == covered)
    {
        return;
    }
    let free = area_to_fit(size, &covered, *present);
    let scale = scene_scale(free);
    // A window with no room (minimised) leaves the camera as it is.
    if scale.is_nan() || scale <= 0.0 {
        return;
    }
    if *present != Some(free) {
        #[cfg(target_arch = "wasm32")]
        {
            let scene = fitted_scene(free);
            crate::game::web::publish_scene(
                scene.min.x,
                scene.min.y,
                scene.width(),
                scene.height(),
            );
        }
        *present = Some(free);
    }
    *fitted_to = Some((size, covered));
    let (mut projection, mut transform) = camera.into_inner();
    let offset = free.center() - size / 2.0;
    let position = Vec3::new(-offset.x / scale, offset.y / scale, transform.translation.z);
    if transform.translation != position {
        transform.translation = position;
    }
    if let Projection::Orthographic(orthographic) = &mut *projection
        && (!matches!(orthographic.scaling_mode, ScalingMode::WindowSize)
            || orthographic.scale != 1.0 / scale)
    {
        orthographic.scaling_mode = ScalingMode::WindowSize;
        orthographic.scale = 1.0 / scale;
    }
}

/// The part of the world the camera shows: it may sit off the origin (the scene fitted to the
/// part of the window the panel and the HUD leave free).
pub fn view_area(projection: &Projection, transform: &GlobalTransform) -> Option<Rect> {
    let Projection::Orthographic(projection) = projection else {
        return None;
    };
    let centre = transform.translation().truncate();
    Some(Rect::from_corners(
        projection.area.min + centre,
        projection.area.max + centre,
    ))
}

/// World units a window pixel spans now: the view's width in the world over the window's.
pub fn world_per_pixel(window: Option<&Window>, view: Option<Rect>) -> f32 {
    match (window.map(Window::width), view.map(|view| view.width())) {
        (Some(width), Some(area)) if width > 0.0 && area > 0.0 => area / width,
        _ => 1.0,
    }
}

fn spawn_camera(mut commands: Commands) {
    commands.spawn((Name::new("Camera"), Camera2d, scene_projection()));
}

/// The state to draw this frame: between the last two fixed steps, by how far the clock has
/// run past the last one.
pub fn interpolated_state(snapshots: &RenderSnapshots, fixed_time: &Time<Fixed>) -> BodyState {
    snapshots.interpolate(fixed_time.overstep_fraction_f64().clamp(0.0, 1.0))
}

/// `Transform` is written from the physics state for rendering only; physics never reads it.
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

/// Bands and bodies are never the same entity: said, so the two writers of `Transform` need
/// no order between them.
fn place_band_pins(mut bands: Query<(&Band, &mut Transform), Without<RenderSnapshots>>) {
    for (band, mut transform) in &mut bands {
        transform.translation = band.ends.anchor.as_vec2().extend(transform.translation.z);
    }
}
