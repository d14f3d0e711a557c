//! The camera plugin: what part of the world the scene shows, and the one map between the
//! window and the world that the pointer, the camera and the drawing share.
//!
//! [`CameraFrame`] holds the player's frame (home: the tutorial's 640 x 480 screen fitted to
//! the scene's viewport, then the player's zoom and pan) and the view shown this frame. The
//! view follows the box only: it stays home while the box lies in the home frame, and when the
//! box leaves it the view widens (by at most [`MAX_WIDEN`] times) to hold it in its inner 80%,
//! then eases home when the box returns.
//!
//! A held band's anchor never makes the view move. The pointer is clamped to the viewport
//! (over the dock, the status line or off the window it stops at the viewport's edge, as a
//! slider's thumb stops at its track's end) and its world point to [`CameraFrame::reach`]: the
//! home frame less the box's diagonal, so that a box held still lies in the home frame. A
//! camera that kept the anchor in sight while the anchor was the pointer mapped through that
//! camera widened without end in a few frames (issue 40): here the anchor's bound does not
//! depend on the view shown, so nothing feeds back.
//!
//! A mode may ask for a closer home ([`Stage`]): learn mode frames its chapter's picture. The
//! reach stays the tutorial's screen.
//!
//! It runs headless too (the game without its screen): `screen::view` places the camera
//! entity from the frame.

use bevy::ecs::system::SystemParam;
use bevy::input::ButtonState;
use bevy::input::keyboard::KeyboardInput;
use bevy::input::mouse::{MouseScrollUnit, MouseWheel};
use bevy::math::DVec2;
use bevy::prelude::*;
use bevy::window::PrimaryWindow;

use crate::game::layout::SceneViewport;
use crate::game::schedule::AfterBevySystems;
use crate::game::shared::Apply;
use crate::game::simulation::{Band, RenderSnapshots, ResetScene, interpolated_state};
use crate::physics::{MassProperties, SCENE_SIZE};

pub struct CameraPlugin;

impl Plugin for CameraPlugin {
    fn build(&self, app: &mut App) {
        app.init_resource::<CameraFrame>()
            .add_observer(go_home)
            .add_observer(go_home_on_reset)
            .add_observer(set_stage)
            .add_systems(
                PostUpdate,
                (zoom_and_pan, follow_the_box)
                    .chain()
                    .in_set(AfterBevySystems::View),
            );
    }
}

/// The camera that renders the scene into its viewport.
#[derive(Component, Debug, Default)]
pub struct SceneCamera;

/// The camera back to its home frame at once: triggered by the controls.
#[derive(Event, Debug, Clone, Copy)]
pub struct HomeView;

/// What the scene's camera shows: a centre and a zoom, in world units per logical pixel.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct View {
    pub centre: Vec2,
    pub world_per_pixel: f32,
}

impl View {
    /// Returns the part of the world the view shows in a viewport of `size` logical pixels.
    pub fn area(&self, size: Vec2) -> Rect {
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

    /// Returns the world point at a place on the window, in logical pixels.
    ///
    /// The viewport lies at `viewport`; the inverse of [`View::to_window`].
    pub fn to_world(&self, window: Vec2, viewport: Rect) -> Vec2 {
        let offset = window - viewport.center();
        self.centre + Vec2::new(offset.x, -offset.y) * self.world_per_pixel
    }
}

/// The scene camera's frame: where the player put it and what it shows now.
///
/// Where the player put it is the home: the tutorial's screen, or as zoomed and panned.
#[derive(Resource, Debug, Clone, Copy, PartialEq)]
pub struct CameraFrame {
    /// The player's zoom about the home frame (1: the stage fitted) and pan.
    pub zoom: f32,
    pub pan: Vec2,
    /// What the camera shows this frame (`None` until the first).
    pub shown: Option<View>,
    /// What home frames: the tutorial's screen, or a closer area a mode asks for.
    pub stage: Stage,
}

impl Default for CameraFrame {
    fn default() -> Self {
        Self {
            zoom: 1.0,
            pan: Vec2::ZERO,
            shown: None,
            stage: Stage::default(),
        }
    }
}

/// What the home view frames, as a mode sets it (learn mode: its chapter's picture).
///
/// A reset and `F` keep it; the band's reach stays the tutorial's screen either way.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Stage {
    /// The world area home fits instead of the tutorial's screen.
    pub close: Option<Rect>,
    /// A copy of the box drawn this far from it (learn mode's centre twin), kept in view too.
    pub copy_at: Option<Vec2>,
}

/// The tutorial's screen: the world the band reaches, and home unless a stage is closer.
const SCREEN: Rect = Rect {
    min: Vec2::new(-0.5 * SCENE_SIZE.x as f32, -0.5 * SCENE_SIZE.y as f32),
    max: Vec2::new(0.5 * SCENE_SIZE.x as f32, 0.5 * SCENE_SIZE.y as f32),
};
/// The room left around the stage in the home frame, as a share of it.
const HOME_MARGIN: f32 = 1.04;
/// The share of the view a box that left home is brought back into.
const INNER: f32 = 0.8;
/// How fast the view eases toward where it should be, per second.
const EASE_RATE: f32 = 6.0;
/// The player's zoom's range.
const ZOOM_RANGE: (f32, f32) = (0.05, 20.0);
/// The most the view widens to follow the box, as a multiple of home's world per pixel.
///
/// Past it the view pans with the box instead. A box let go from rest anywhere the band can
/// hold it never needs it (tests/camera.rs); a box flung on an undamped scene may.
pub const MAX_WIDEN: f32 = 4.0;

impl CameraFrame {
    /// Returns the home view in a viewport of `size`.
    ///
    /// It fits the stage (the tutorial's screen unless a mode set a closer one), then applies
    /// the player's zoom and pan.
    pub fn home(&self, size: Vec2) -> View {
        self.fitted(self.stage.close.unwrap_or(SCREEN), size)
    }

    /// Returns `area`, with its margin, fitted to a viewport of `size`, then zoomed and panned.
    fn fitted(&self, area: Rect, size: Vec2) -> View {
        let fitted = View::fitting(
            Rect::from_center_size(area.center(), area.size() * HOME_MARGIN),
            size,
        );
        View {
            centre: area.center() + self.pan,
            world_per_pixel: fitted.world_per_pixel * self.zoom,
        }
    }

    /// Returns the view shown, or home before the first frame has placed one.
    pub fn view(&self, size: Vec2) -> View {
        self.shown.unwrap_or_else(|| self.home(size))
    }

    /// Returns where a held band's anchor may lie in a viewport of `size`.
    ///
    /// It is the home frame less `span` (the box's diagonal) on every side: a box held still
    /// there by a corner lies in the home frame, so the view comes home. A frame narrower than
    /// two spans leaves its centre line.
    pub fn reach(&self, size: Vec2, span: f32) -> Rect {
        let home = self.fitted(SCREEN, size).area(size);
        let half = (home.half_size() - Vec2::splat(span)).max(Vec2::ZERO);
        Rect::from_center_half_size(home.center(), half)
    }

    /// Returns the world point where a pointer at `cursor` holds the band's anchor.
    ///
    /// The pointer is clamped to `viewport`, mapped through the view shown, then clamped to
    /// [`CameraFrame::reach`] for a box whose diagonal is `span`.
    pub fn anchor_at(&self, viewport: Rect, span: f32, cursor: Vec2) -> DVec2 {
        let on_scene = cursor.clamp(viewport.min, viewport.max);
        let world = self.view(viewport.size()).to_world(on_scene, viewport);
        let reach = self.reach(viewport.size(), span);
        world.clamp(reach.min, reach.max).as_dvec2()
    }
}

/// Returns where the view should be to keep `keep` (the box's corners) in sight.
///
/// It is the home view while they lie in its frame; else the least view, centred between,
/// that holds the home frame and them in its inner 80%, widened at most [`MAX_WIDEN`] times.
fn wanted_view(home: View, size: Vec2, keep: Rect) -> View {
    let frame = home.area(size);
    if keep.is_empty() || frame.union(keep) == frame {
        return home;
    }
    let view = View::fitting(frame.union(keep), size * INNER);
    bounded(
        View {
            world_per_pixel: view.world_per_pixel.max(home.world_per_pixel),
            ..view
        },
        home,
        size,
        keep,
    )
}

/// Returns `view` widened at most [`MAX_WIDEN`] times `home`.
///
/// A view narrowed to the bound moves the least that puts `keep` back in it (centred on `keep`
/// when it is larger).
fn bounded(view: View, home: View, size: Vec2, keep: Rect) -> View {
    let most = home.world_per_pixel * MAX_WIDEN;
    if view.world_per_pixel <= most {
        return view;
    }
    let mut view = View {
        world_per_pixel: most,
        ..view
    };
    let half = size * most / 2.0;
    if !keep.is_empty() {
        let (low, high) = (keep.max - half, keep.min + half);
        view.centre = Vec2::select(
            low.cmple(high),
            view.centre.clamp(low.min(high), high.max(low)),
            keep.center(),
        );
    }
    view
}

/// Eases `shown` toward `wanted` by the share `ease` (0 to 1).
///
/// Each edge of the area moves the same share, so a view between two that hold the home frame
/// holds it too. Then, if `keep` is not whole in it, widens it at once until it is (up to the
/// bound): the box is never lost.
fn eased_view(shown: View, wanted: View, ease: f32, home: View, size: Vec2, keep: Rect) -> View {
    let view = View {
        centre: shown.centre.lerp(wanted.centre, ease),
        world_per_pixel: shown.world_per_pixel
            + (wanted.world_per_pixel - shown.world_per_pixel) * ease,
    };
    let area = view.area(size);
    if keep.is_empty() || area.union(keep) == area {
        return view;
    }
    // The least view holding both what it showed and what must be seen.
    let grown = area.union(keep.inflate(keep.size().max_element() * 0.05));
    bounded(View::fitting(grown, size), home, size, keep)
}

/// How the scene shows the world on the window, which the pointer and the drawing map through.
///
/// It is the window, the viewport the layout gave the scene, and the camera's frame.
#[derive(SystemParam)]
pub struct SceneView<'w, 's> {
    pub window: Option<Single<'w, 's, &'static Window, With<PrimaryWindow>>>,
    pub viewport: Res<'w, SceneViewport>,
    pub frame: Res<'w, CameraFrame>,
}

/// Zooms the view in, about the viewport's centre: the wheel's zoom for the keyboard.
pub(crate) const ZOOM_IN: KeyCode = KeyCode::KeyZ;

/// Zooms the view out, about the viewport's centre.
pub(crate) const ZOOM_OUT: KeyCode = KeyCode::KeyX;

/// What one press of a zoom key zooms by (held, the key repeats).
const KEY_ZOOM: f32 = 1.25;

/// What moves the view by hand: the wheel, the buttons, the fingers and the zoom keys.
#[derive(SystemParam)]
struct ViewControls<'w, 's> {
    wheel: MessageReader<'w, 's, MouseWheel>,
    keys: MessageReader<'w, 's, KeyboardInput>,
    buttons: Res<'w, ButtonInput<MouseButton>>,
    touches: Res<'w, Touches>,
}

/// Returns the viewport's rectangle now, in logical pixels: the layout's, or the whole window.
pub(crate) fn viewport_rect(viewport: &SceneViewport, window: &Window) -> Rect {
    viewport
        .0
        .unwrap_or(Rect::from_corners(Vec2::ZERO, window.size()))
}

/// Returns the world units a logical pixel spans now (1 before the first view).
pub fn world_per_pixel(frame: &CameraFrame) -> f32 {
    frame.shown.map_or(1.0, |view| view.world_per_pixel)
}

/// Returns the part of the world the scene's camera shows now, if it has shown any.
pub(crate) fn shown_area(
    frame: &CameraFrame,
    viewport: &SceneViewport,
    window: &Window,
) -> Option<Rect> {
    let size = viewport_rect(viewport, window).size();
    frame.shown.map(|view| view.area(size))
}

fn go_home(_home: On<HomeView>, mut frame: ResMut<CameraFrame>) {
    frame.zoom = 1.0;
    frame.pan = Vec2::ZERO;
    // At once, not eased.
    frame.shown = None;
}

/// Frames the stage sent (learn mode's chapter, or the tutorial's screen back).
fn set_stage(apply: On<Apply<Stage>>, mut frame: ResMut<CameraFrame>) {
    frame.stage = apply.0;
}

/// Starts the view over on a reset too.
fn go_home_on_reset(_reset: On<ResetScene>, mut frame: ResMut<CameraFrame>) {
    *frame = CameraFrame {
        stage: frame.stage,
        ..default()
    };
}

/// Zooms and pans the view with the wheel, the right button, two fingers and the zoom keys.
///
/// The zoom keys zoom about the viewport's centre, the wheel about the pointer, the right button drags the view, two fingers pinch and
/// pan: all on the scene's viewport only (the wheel over the dock scrolls it). While a band is
/// held two fingers do not pinch: a second finger beside the one that holds does nothing.
fn zoom_and_pan(
    controls: ViewControls,
    bands: Query<(), With<Band>>,
    window: Option<Single<&Window, With<PrimaryWindow>>>,
    viewport: Res<SceneViewport>,
    mut frame: ResMut<CameraFrame>,
    mut last_cursor: Local<Option<Vec2>>,
    mut last_pinch: Local<Option<(f32, Vec2)>>,
) {
    let ViewControls {
        mut wheel,
        mut keys,
        buttons,
        touches,
    } = controls;
    let Some(window) = window else {
        wheel.clear();
        keys.clear();
        return;
    };
    let area = viewport_rect(&viewport, &window);
    let Some(shown) = frame.shown else {
        wheel.clear();
        keys.clear();
        return;
    };
    let home = frame.home(area.size());
    let cursor = window.cursor_position();
    // A change of zoom about a window point: the world point under it stays under it.
    let zoom_about = |frame: &mut CameraFrame, factor: f32, at: Vec2| {
        let zoom = (frame.zoom * factor).clamp(ZOOM_RANGE.0, ZOOM_RANGE.1);
        let applied = zoom / frame.zoom;
        let world_at = shown.to_world(at, area);
        let centre = frame.home(area.size()).centre;
        frame.pan += world_at + (centre - world_at) * applied - centre;
        frame.zoom = zoom;
    };
    for key in keys.read().filter(|key| key.state == ButtonState::Pressed) {
        match key.key_code {
            // The zoom scales the world a pixel spans: less is closer.
            ZOOM_IN => zoom_about(&mut frame, 1.0 / KEY_ZOOM, area.center()),
            ZOOM_OUT => zoom_about(&mut frame, KEY_ZOOM, area.center()),
            _ => {}
        }
    }
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
    let holding = !bands.is_empty();
    let fingers: Vec<Vec2> = touches
        .iter()
        .map(|touch| touch.position())
        .take(2)
        .collect();
    if let ([a, b], false) = (&fingers[..], holding) {
        let (spread, middle) = (a.distance(*b).max(1.0), (*a + *b) / 2.0);
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

/// Eases the view toward where it should be this frame; the box always in it.
///
/// When the viewport changes size (a card opens, the window resizes) the view is where it
/// should be at once: easing from a view made for another size would crop the scene.
fn follow_the_box(
    time: Res<Time<Real>>,
    fixed_time: Res<Time<Fixed>>,
    window: Option<Single<&Window, With<PrimaryWindow>>>,
    viewport: Res<SceneViewport>,
    boxes: Query<(&RenderSnapshots, &MassProperties)>,
    mut frame: ResMut<CameraFrame>,
    mut last_size: Local<Vec2>,
) {
    let Some(window) = window else {
        return;
    };
    let size = viewport_rect(&viewport, &window).size();
    if size.min_element() <= 0.0 {
        return;
    }
    let resized = std::mem::replace(&mut *last_size, size) != size;
    // Every box's corners as drawn; never the band's anchor (the module's doc says why).
    let mut keep = Rect::EMPTY;
    let copy = frame.stage.copy_at;
    for (snapshots, mass) in &boxes {
        let state = interpolated_state(snapshots, &fixed_time);
        for corner in mass.corners() {
            let corner = state.local_to_world(corner).as_vec2();
            keep = keep.union_point(corner);
            if let Some(offset) = copy {
                keep = keep.union_point(corner + offset);
            }
        }
    }
    let home = frame.home(size);
    let wanted = wanted_view(home, size, keep);
    let shown = frame.shown.filter(|_| !resized).unwrap_or(wanted);
    let ease = 1.0 - (-EASE_RATE * time.delta_secs()).exp();
    let view = eased_view(shown, wanted, ease, home, size, keep);
    if frame.shown != Some(view) {
        frame.shown = Some(view);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Checks that the camera keeps the box in view and comes home.
    ///
    /// While the box lies in the home frame it stays home; pulled out, it widens so that the
    /// box lies inside at every frame, however fast, and never past the bound; and it comes
    /// home when the box does.
    #[test]
    fn the_view_keeps_the_box_and_comes_home() {
        let size = Vec2::new(600.0, 500.0);
        let home = CameraFrame::default().home(size);
        let screen = home.area(size);
        assert!(
            screen.width() >= 640.0 && screen.height() >= 480.0,
            "{screen:?}"
        );
        let near = Rect::from_center_size(Vec2::new(250.0, 180.0), Vec2::splat(60.0));
        assert_eq!(wanted_view(home, size, near), home);
        let mut shown = home;
        // A box flung far right and up, then back.
        for step in 0..400 {
            let t = step as f32 / 100.0;
            let reach = if t < 2.0 { t } else { 4.0 - t };
            let keep = Rect::from_center_size(Vec2::new(900.0, 500.0) * reach, Vec2::splat(85.0));
            let wanted = wanted_view(home, size, keep);
            shown = eased_view(shown, wanted, 0.1, home, size, keep);
            let area = shown.area(size);
            assert!(
                area.union(keep) == area,
                "step {step}: {keep:?} out of {area:?}"
            );
            assert!(shown.world_per_pixel <= home.world_per_pixel * MAX_WIDEN);
            if shown.world_per_pixel < home.world_per_pixel * MAX_WIDEN {
                assert!(area.union(screen) == area, "step {step}: home lost");
            }
        }
        for _ in 0..100 {
            shown = eased_view(shown, wanted_view(home, size, near), 0.1, home, size, near);
        }
        assert!(shown.centre.distance(home.centre) < 1.0, "{shown:?}");
        assert!((shown.world_per_pixel / home.world_per_pixel - 1.0).abs() < 0.01);
    }

    /// Checks that the pointer maps onto the world through the view and stops at the reach.
    #[test]
    fn the_anchor_follows_the_pointer_and_stops_at_the_reach() {
        let viewport = Rect::new(0.0, 40.0, 640.0, 700.0);
        let frame = CameraFrame::default();
        let view = frame.home(viewport.size());
        let span = 60.0 * std::f32::consts::SQRT_2;
        let reach = frame.reach(viewport.size(), span);
        let inside = Vec2::new(300.0, 400.0);
        let world = view.to_world(inside, viewport);
        assert!(view.to_window(world, viewport).distance(inside) < 1e-3);
        assert!(
            frame
                .anchor_at(viewport, span, inside)
                .as_vec2()
                .distance(world)
                < 1e-4
        );
        // Far over the dock and off every edge: the reach's edge, whatever the view shows.
        for far in [Vec2::new(5000.0, 400.0), Vec2::new(-90.0, -800.0)] {
            let widened = CameraFrame {
                shown: Some(View {
                    world_per_pixel: view.world_per_pixel * 3.0,
                    ..view
                }),
                ..frame
            };
            for frame in [frame, widened] {
                let anchor = frame.anchor_at(viewport, span, far).as_vec2();
                assert!(
                    reach.inflate(1e-3).contains(anchor),
                    "{anchor} out of {reach:?}"
                );
                let on_edge = (anchor.x - reach.min.x)
                    .abs()
                    .min((anchor.x - reach.max.x).abs())
                    < 1e-3
                    || (anchor.y - reach.min.y)
                        .abs()
                        .min((anchor.y - reach.max.y).abs())
                        < 1e-3;
                assert!(on_edge, "{anchor} within {reach:?}");
            }
        }
        // Zoomed in past two spans: the reach is the centre, not a panic.
        let close = CameraFrame {
            zoom: ZOOM_RANGE.0,
            ..frame
        };
        assert_eq!(close.reach(viewport.size(), span).size(), Vec2::ZERO);
        assert!(close.anchor_at(viewport, span, Vec2::ZERO).is_finite());
    }
}
