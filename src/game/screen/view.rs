//! The cameras, and the interpolation that draws the box between fixed steps so that motion
//! is smooth at any display rate (as Bevy's `physics_in_fixed_timestep` example does).
//!
//! The scene's camera renders into the layout's viewport ([`SceneViewport`]) only, so nothing
//! of the world is ever drawn under the dock, and shows the view that `game::camera` chose
//! this frame (home, following the box, the player's zoom and pan).
//!
//! A second camera draws the dock's charts (gizmos on their own render layer, in window
//! pixels) and the UI over the whole window.

use bevy::camera::visibility::RenderLayers;
use bevy::camera::{ClearColorConfig, ScalingMode, Viewport};
use bevy::prelude::*;
use bevy::ui::IsDefaultUiCamera;
use bevy::window::PrimaryWindow;

use crate::game::camera::{CameraFrame, SceneCamera, viewport_rect};
use crate::game::layout::SceneViewport;
use crate::game::schedule::{AfterBevySystems, AfterStepsSystems};
use crate::game::simulation::{Band, RenderSnapshots, interpolated_state};
#[cfg(target_arch = "wasm32")]
use crate::physics::{MassProperties, SCENE_SIZE};

pub struct ViewPlugin;

impl Plugin for ViewPlugin {
    fn build(&self, app: &mut App) {
        app.add_systems(Startup, spawn_cameras)
            .add_systems(
                RunFixedMainLoop,
                (interpolate_body_transforms, place_band_pins).in_set(AfterStepsSystems::Conclude),
            )
            .add_systems(PostUpdate, place_cameras.in_set(AfterBevySystems::Camera));
        #[cfg(target_arch = "wasm32")]
        app.add_systems(
            PostUpdate,
            publish_view
                .in_set(AfterBevySystems::Camera)
                .after(place_cameras),
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
pub(crate) const CHART_LAYER: usize = 1;

/// The camera that draws the dock's charts and the UI, over the whole window.
#[derive(Component, Debug)]
struct ChartCamera;

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
