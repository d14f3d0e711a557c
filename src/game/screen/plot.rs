//! Speed against error, live (P): every ghost a point on the report's work-precision axes,
//! its distance from the reference (px) across, its cost per simulated second (ns) up, both
//! logarithmic, in the ghost's colour with its name, moving as the hand pulls. A diverged
//! ghost is a cross at the right edge, at the cost it had; a reference that had to fall back
//! (its budget) says so above the plot. Drawn with gizmos at the left of the tutorial's
//! screen; the points are [`plot_points`], which a test holds to the ghosts' own figures.

use bevy::prelude::*;
use bevy::window::PrimaryWindow;

use crate::game::ghosts::{GhostKind, Ghosts};
use crate::game::schedule::ScreenSystems;
use crate::game::screen::view::{view_area, world_per_pixel};
use crate::game::shared::Overlays;
use crate::physics::{Integrator, SCENE_SIZE, SceneParams};

pub struct WorkPrecisionPlotPlugin;

impl Plugin for WorkPrecisionPlotPlugin {
    fn build(&self, app: &mut App) {
        app.add_systems(Update, draw_plot.in_set(ScreenSystems::Plot));
    }
}

/// One ghost on the plot.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlotPoint {
    pub kind: GhostKind,
    /// Distance from the reference now (px); None once diverged.
    pub error: Option<f64>,
    /// Wall time per simulated second (ns): the ghost's time per step times the step rate.
    pub cost: f64,
    /// The ghost of the live box's own integrator: the live box itself.
    pub live: bool,
}

/// Every ghost but the reference, as the plot shows it.
pub fn plot_points(ghosts: &Ghosts, step_rate_hz: f64, live: Integrator) -> Vec<PlotPoint> {
    ghosts
        .ghosts
        .iter()
        .filter(|ghost| ghost.kind != GhostKind::Reference)
        .map(|ghost| PlotPoint {
            kind: ghost.kind,
            error: ghost
                .diverged_at
                .is_none()
                .then(|| ghosts.distance_from_reference(ghost))
                .flatten(),
            cost: ghost.ns_per_step * step_rate_hz,
            live: ghost.kind == GhostKind::Method(live),
        })
        .collect()
}

/// The axes' decades: the report's work-precision figure spans these.
pub const ERROR_DECADES: (f64, f64) = (-16.0, 3.0);
pub const COST_DECADES: (f64, f64) = (2.0, 8.0);

/// The plot's size in world units, and its distance from the tutorial screen's corner.
pub const PLOT_SIZE: Vec2 = Vec2::new(220.0, 130.0);
const PLOT_MARGIN: f32 = 8.0;
/// The plot's lower edge (world units, the scene's centre at 0).
const PLOT_BOTTOM: f32 = -105.0;
const FRAME_COLOUR: Color = Color::srgb(0.25, 0.25, 0.3);
const LABEL_SIZE: f32 = 10.0;

/// Where the plot lies: at the left of the tutorial's screen, between the HUD's column above
/// and the ghosts' list below, away from the top right where the tutorial's pull takes the box
/// and from the bottom right where the panel's button sits.
pub fn plot_frame() -> Rect {
    let left = -SCENE_SIZE.as_vec2().x / 2.0 + PLOT_MARGIN;
    let min = Vec2::new(left, PLOT_BOTTOM);
    Rect::from_corners(min, min + PLOT_SIZE)
}

/// What the plot takes of the world with its captions above and below and the names to the
/// right of its points: where the ghosts' names must not go.
pub fn plot_footprint() -> Rect {
    let frame = plot_frame();
    Rect::from_corners(
        frame.min - Vec2::new(0.0, 2.0 * LABEL_SIZE),
        frame.max + Vec2::new(9.0 * LABEL_SIZE, 3.0 * LABEL_SIZE),
    )
}

/// A point's place in `frame`: each axis's decade clamped into the frame; a diverged ghost at
/// the right edge.
pub fn place(point: &PlotPoint, frame: Rect) -> Vec2 {
    let across = |decades: (f64, f64), value: f64| {
        ((value.max(1e-300).log10() - decades.0) / (decades.1 - decades.0)).clamp(0.0, 1.0) as f32
    };
    let x = point
        .error
        .map_or(1.0, |error| across(ERROR_DECADES, error));
    let y = across(COST_DECADES, point.cost);
    frame.min + Vec2::new(x, y) * frame.size()
}

/// Where each point's name goes: to the right of it, moved up a line at a time while it
/// would lie on a name placed before it (ghosts often coincide).
fn label_places(points: &[PlotPoint], frame: Rect, font_size: f32) -> Vec<Vec2> {
    let mut placed: Vec<Vec2> = Vec::new();
    for point in points {
        let mut at = place(point, frame) + Vec2::new(7.0, 0.0);
        while placed.iter().any(|other| {
            (other.y - at.y).abs() < font_size && (other.x - at.x).abs() < 6.0 * font_size
        }) {
            at.y += font_size + 1.0;
        }
        placed.push(at);
    }
    placed
}

/// A ghost's label beside its point.
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
struct PlotLabel(GhostKind);

/// The axes' captions and the reference's note.
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
enum PlotCaption {
    /// Under the frame.
    Across,
    /// Over the frame.
    Up,
    /// Over that.
    Reference,
}

/// The names' size on screen, in window pixels, however small the view makes the scene.
pub const LABEL_PIXELS: f32 = 11.0;

#[allow(clippy::too_many_arguments)]
fn draw_plot(
    mut commands: Commands,
    mut gizmos: Gizmos,
    windows: Query<&Window, With<PrimaryWindow>>,
    cameras: Query<(&Projection, &GlobalTransform), With<Camera2d>>,
    overlays: Res<Overlays>,
    ghosts: Res<Ghosts>,
    params: Res<SceneParams>,
    integrator: Res<Integrator>,
    mut labels: Query<(
        Entity,
        &PlotLabel,
        &mut Text2d,
        &mut TextFont,
        &mut Transform,
        &mut Visibility,
    )>,
    mut captions: Query<
        (
            &PlotCaption,
            &mut Text2d,
            &mut TextFont,
            &mut Transform,
            &mut Visibility,
        ),
        Without<PlotLabel>,
    >,
) {
    // On a phone the scene is drawn small: the names keep their size on screen.
    let view = cameras
        .iter()
        .find_map(|(projection, transform)| view_area(projection, transform));
    let font_size = LABEL_SIZE.max(LABEL_PIXELS * world_per_pixel(windows.iter().next(), view));
    let shown = overlays.plot && !overlays.hud_hidden;
    if captions.is_empty() {
        for caption in [PlotCaption::Across, PlotCaption::Up, PlotCaption::Reference] {
            commands.spawn((
                Name::new("Plot caption"),
                caption,
                Text2d::default(),
                TextFont::from_font_size(LABEL_SIZE),
                TextColor(Color::srgb(0.7, 0.7, 0.75)),
                bevy::sprite::Anchor::CENTER_LEFT,
                Transform::default(),
                Visibility::Hidden,
            ));
        }
    }
    let frame = plot_frame();
    let points = if shown {
        plot_points(&ghosts, params.step_rate_hz, *integrator)
    } else {
        Vec::new()
    };
    for (caption, mut text, mut font, mut transform, mut visibility) in &mut captions {
        if font.font_size != FontSize::Px(font_size) {
            font.font_size = FontSize::Px(font_size);
        }
        visibility.set_if_neq(if shown {
            Visibility::Inherited
        } else {
            Visibility::Hidden
        });
        let y = match caption {
            PlotCaption::Across => frame.min.y - font_size * 0.8,
            PlotCaption::Up => frame.max.y + font_size * 0.8,
            PlotCaption::Reference => frame.max.y + font_size * 2.0,
        };
        transform.translation = Vec3::new(frame.min.x, y, 3.0);
        let said = match caption {
            PlotCaption::Across => "error from the reference, px: 1e-16 .. 1e3".to_owned(),
            PlotCaption::Up => "cost up, ns per simulated s: 1e2 .. 1e8".to_owned(),
            PlotCaption::Reference => {
                let capped = ghosts
                    .ghosts
                    .iter()
                    .find(|g| g.kind == GhostKind::Reference)
                    .map_or(0, |g| g.capped);
                if capped > 0 {
                    format!("reference capped at {capped} steps: errors there are implicit's")
                } else {
                    String::new()
                }
            }
        };
        if text.0 != said {
            text.0 = said;
        }
    }
    let mut unlabelled: Vec<GhostKind> = points.iter().map(|p| p.kind).collect();
    let label_places = label_places(&points, frame, font_size);
    for (entity, label, mut text, mut font, mut transform, mut visibility) in &mut labels {
        if font.font_size != FontSize::Px(font_size) {
            font.font_size = FontSize::Px(font_size);
        }
        let Some(point) = points.iter().find(|p| p.kind == label.0) else {
            if !shown {
                visibility.set_if_neq(Visibility::Hidden);
            } else {
                commands.entity(entity).despawn();
            }
            continue;
        };
        unlabelled.retain(|&kind| kind != label.0);
        visibility.set_if_neq(Visibility::Inherited);
        let mut name = match (point.error, point.live) {
            (None, _) => format!("{} diverged", point.kind.name()),
            (Some(_), true) => format!("{} (live)", point.kind.name()),
            (Some(_), false) => point.kind.name().to_owned(),
        };
        if point.cost == 0.0 {
            // A browser's clock can be coarser than a step.
            name += " (too fast to time)";
        }
        if text.0 != name {
            text.0 = name;
        }
        let index = points.iter().position(|p| p.kind == label.0).unwrap_or(0);
        transform.translation = label_places[index].extend(3.0);
    }
    for kind in unlabelled {
        commands.spawn((
            Name::new("Plot label"),
            PlotLabel(kind),
            Text2d::new(kind.name()),
            TextFont::from_font_size(LABEL_SIZE),
            TextColor(kind.colour()),
            bevy::sprite::Anchor::CENTER_LEFT,
            Transform::default(),
            Visibility::Hidden,
        ));
    }
    if !shown {
        return;
    }
    gizmos.rect_2d(
        Isometry2d::from_translation(frame.center()),
        frame.size(),
        FRAME_COLOUR,
    );
    // A tick at each decade, along the bottom and the left.
    let decades = |range: (f64, f64)| (range.0 as i32..=range.1 as i32).map(f64::from);
    for decade in decades(ERROR_DECADES) {
        let x = frame.min.x
            + ((decade - ERROR_DECADES.0) / (ERROR_DECADES.1 - ERROR_DECADES.0)) as f32
                * frame.width();
        gizmos.line_2d(
            Vec2::new(x, frame.min.y),
            Vec2::new(x, frame.min.y + 3.0),
            FRAME_COLOUR,
        );
    }
    for decade in decades(COST_DECADES) {
        let y = frame.min.y
            + ((decade - COST_DECADES.0) / (COST_DECADES.1 - COST_DECADES.0)) as f32
                * frame.height();
        gizmos.line_2d(
            Vec2::new(frame.min.x, y),
            Vec2::new(frame.min.x + 3.0, y),
            FRAME_COLOUR,
        );
    }
    for (point, label) in points.iter().zip(&label_places) {
        let at = place(point, frame);
        let colour = point.kind.colour();
        // A name moved off its point's line is tied to it.
        if (label.y - at.y).abs() > 1.0 {
            gizmos.line_2d(at, *label - Vec2::new(2.0, 0.0), colour.with_alpha(0.5));
        }
        match point.error {
            Some(_) => {
                gizmos.circle_2d(Isometry2d::from_translation(at), 3.0, colour);
                if point.live {
                    gizmos.circle_2d(Isometry2d::from_translation(at), 5.5, colour);
                }
            }
            None => {
                for (a, b) in [
                    (Vec2::new(-4.0, -4.0), Vec2::new(4.0, 4.0)),
                    (Vec2::new(-4.0, 4.0), Vec2::new(4.0, -4.0)),
                ] {
                    gizmos.line_2d(at + a, at + b, colour);
                }
            }
        }
    }
}
