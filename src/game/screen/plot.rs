//! Speed against error, live (P): every ghost a point on the report's work-precision axes,
//! its distance from the reference (px) across, its cost per simulated second (ns) up, both
//! logarithmic with a tick at every decade, in the ghost's colour with its name, moving as
//! the hand pulls. A diverged ghost is a cross at the right edge, at the cost it had, and
//! says so. The chart fills the plot card's canvas (the chart camera draws it); its ticks'
//! values, its captions and the names are UI text in the canvas, the names put by
//! `place_labels` where no other text, no point and no name lies, tied to their point by a
//! leader line when moved away from it. The points are [`plot_points`], which a test holds
//! to the ghosts' own figures.

use bevy::ecs::system::SystemParam;
use bevy::picking::Pickable;
use bevy::prelude::*;
use bevy::ui::UiGlobalTransform;
use bevy::window::PrimaryWindow;

use crate::game::ghosts::{GhostKind, Ghosts};
use crate::game::layout::{Card, CardSpec, RegisterCard, Slots};
use crate::game::schedule::ScreenSystems;
use crate::game::screen::chart::{Canvas, ChartGizmos, text_box};
use crate::game::shared::Overlays;
use crate::game::theme::{self, colour, size, space};
use crate::physics::{Integrator, SceneParams};

pub struct WorkPrecisionPlotPlugin;

impl Card {
    /// Speed against error (with the plot on).
    pub const PLOT: Card = Card("plot");
}

impl Plugin for WorkPrecisionPlotPlugin {
    fn build(&self, app: &mut App) {
        app.register_card(CardSpec {
            card: Card::PLOT,
            title: "Speed against error",
            place: 60,
            offered: |overlays, _| overlays.plot,
        })
        .add_systems(Startup, spawn_canvas)
        .add_systems(Update, draw_plot.in_set(ScreenSystems::Plot));
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

impl PlotPoint {
    /// Returns the point's name on the plot.
    fn label(&self) -> String {
        let mut name = match (self.error, self.live) {
            (None, _) => format!("{} diverged", self.kind.name()),
            (Some(_), true) => format!("{} (live)", self.kind.name()),
            (Some(_), false) => self.kind.name().to_owned(),
        };
        if self.cost == 0.0 {
            // A browser's clock can be coarser than a step.
            name += " (untimed)";
        }
        name
    }
}

/// Returns every ghost but the reference, as the plot shows it.
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
const ERROR_DECADES: (i32, i32) = (-16, 3);
const COST_DECADES: (i32, i32) = (2, 8);

/// The canvas's height in the UI's units (its width is the card's).
const PLOT_HEIGHT: f32 = 230.0;
/// The room around the plotting frame for the ticks' values and the captions.
const LEFT: f32 = 34.0;
const RIGHT: f32 = 8.0;
const TOP: f32 = 26.0;
const BOTTOM: f32 = 38.0;

/// Returns the plotting frame in a canvas of `canvas` size.
///
/// The frame is in the UI's units from the canvas's top left (y down).
pub fn plot_frame(canvas: Vec2) -> Rect {
    Rect::from_corners(
        Vec2::new(LEFT, TOP),
        Vec2::new(canvas.x - RIGHT, canvas.y - BOTTOM).max(Vec2::new(LEFT + 1.0, TOP + 1.0)),
    )
}

/// Returns where a decade lies along an axis of `length` spanning `decades`.
fn along(decades: (i32, i32), value: f64, length: f32) -> f32 {
    let share =
        (value.max(1e-300).log10() - f64::from(decades.0)) / f64::from(decades.1 - decades.0);
    share.clamp(0.0, 1.0) as f32 * length
}

/// Returns a point's place in `frame` (y down), each axis's decade clamped into the frame.
///
/// A diverged ghost is at the right edge.
pub fn place(point: &PlotPoint, frame: Rect) -> Vec2 {
    let x = point.error.map_or(frame.width(), |error| {
        along(ERROR_DECADES, error, frame.width())
    });
    let y = along(COST_DECADES, point.cost, frame.height());
    Vec2::new(frame.min.x + x, frame.max.y - y)
}

/// Returns a tick's value as the axis writes it.
fn decade_label(decade: i32) -> String {
    match decade {
        0 => "1".to_owned(),
        1 => "10".to_owned(),
        _ => format!("1e{decade}"),
    }
}

/// Returns every how many decades an axis of `length` writes a value, so that no two meet.
///
/// `room` is what one value needs.
fn label_every(decades: (i32, i32), length: f32, room: f32) -> i32 {
    let per_decade = length / (decades.1 - decades.0) as f32;
    (1..=6)
        .find(|&every| every as f32 * per_decade >= room)
        .unwrap_or(6)
}

/// The half-size of a point's mark, which no name may cover.
const MARK: f32 = 7.0;

/// Returns where each name goes: near its point if there is room, else the first free place.
///
/// A name goes beside its point (right, left, above, below, then the diagonals), further out ring
/// by ring, at the first place inside `bounds` that meets no mark of any point, no text of
/// `obstacles` and no name placed before; where no such place is near, at the first free place in
/// `bounds`, top to bottom. `labels` are each point and its name's size.
fn place_labels(labels: &[(Vec2, Vec2)], bounds: Rect, obstacles: &[Rect]) -> Vec<Rect> {
    let marks: Vec<Rect> = labels
        .iter()
        .map(|(point, _)| Rect::from_center_half_size(*point, Vec2::splat(MARK)))
        .collect();
    let mut placed: Vec<Rect> = Vec::new();
    for &(point, size) in labels {
        let free = |rect: Rect| {
            bounds.union(rect) == bounds
                && marks
                    .iter()
                    .chain(obstacles)
                    .chain(&placed)
                    .all(|other| other.inflate(1.0).intersect(rect).is_empty())
        };
        let half = size / 2.0;
        let near = [6.0, 12.0, 20.0, 30.0, 42.0, 56.0, 72.0]
            .into_iter()
            .flat_map(|r: f32| {
                [
                    Vec2::new(r + half.x, 0.0),
                    Vec2::new(-r - half.x, 0.0),
                    Vec2::new(0.0, -r - half.y),
                    Vec2::new(0.0, r + half.y),
                    Vec2::new(r + half.x, -r - half.y) * 0.75,
                    Vec2::new(r + half.x, r + half.y) * 0.75,
                    Vec2::new(-r - half.x, -r - half.y) * 0.75,
                    Vec2::new(-r - half.x, r + half.y) * 0.75,
                ]
            });
        let scan = (0..)
            .map(|row| bounds.min.y + half.y + row as f32 * 3.0)
            .take_while(|y| *y + half.y <= bounds.max.y)
            .flat_map(|y| {
                (0..)
                    .map(move |column| bounds.max.x - half.x - column as f32 * 6.0)
                    .take_while(|x| *x - half.x >= bounds.min.x)
                    .map(move |x| Vec2::new(x, y))
            });
        let rect = near
            .map(|offset| Rect::from_center_size(point + offset, size))
            .chain(scan.map(|centre| Rect::from_center_size(centre, size)))
            .find(|rect| free(*rect))
            .unwrap_or(Rect::from_center_size(
                point + Vec2::new(6.0 + half.x, 0.0),
                size,
            ));
        placed.push(rect);
    }
    placed
}

/// The plot's canvas.
#[derive(Component, Debug)]
pub struct PlotCanvas;

/// A ghost's name beside its point.
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
pub struct PlotLabel(pub GhostKind);

/// The plot's other texts.
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
enum PlotText {
    /// A decade's value under the error axis.
    Across(i32),
    /// A decade's value beside the cost axis.
    Up(i32),
    AcrossCaption,
    UpCaption,
}

/// The note under the canvas that the reference fell back.
#[derive(Component, Debug)]
struct ReferenceNote;

fn absolute_text(text: String, shade: Color) -> impl Bundle {
    (
        Text::new(text),
        theme::figures_font(size::CAPTION),
        TextColor(shade),
        Pickable::IGNORE,
        Node {
            position_type: PositionType::Absolute,
            display: Display::None,
            ..default()
        },
    )
}

fn spawn_canvas(mut commands: Commands, slots: Slots) {
    let Some(card) = slots.card_body(Card::PLOT) else {
        return;
    };
    let canvas = commands
        .spawn((
            Name::new("Plot"),
            PlotCanvas,
            Pickable::IGNORE,
            Node {
                height: px(PLOT_HEIGHT),
                margin: UiRect::axes(px(space::PAD), px(space::GAP)),
                flex_shrink: 0.0,
                ..default()
            },
            ChildOf(card),
        ))
        .id();
    let texts = (ERROR_DECADES.0..=ERROR_DECADES.1)
        .map(|decade| (PlotText::Across(decade), decade_label(decade)))
        .chain(
            (COST_DECADES.0..=COST_DECADES.1)
                .map(|decade| (PlotText::Up(decade), decade_label(decade))),
        )
        .chain([
            (
                PlotText::AcrossCaption,
                "error from the reference, px →".to_owned(),
            ),
            (
                PlotText::UpCaption,
                "↑ cost, ns per simulated second".to_owned(),
            ),
        ]);
    for (what, text) in texts {
        commands.spawn((what, absolute_text(text, colour::DIM), ChildOf(canvas)));
    }
    for kind in Integrator::ALL.map(GhostKind::Method) {
        commands.spawn((
            Name::new("Plot label"),
            PlotLabel(kind),
            absolute_text(kind.name().to_owned(), kind.colour()),
            ChildOf(canvas),
        ));
    }
    commands.spawn((
        Name::new("Plot note"),
        ReferenceNote,
        Text::default(),
        theme::text_font(size::CAPTION),
        TextColor(colour::WARNING),
        Node {
            display: Display::None,
            padding: UiRect::new(px(space::PAD + 2.0), px(space::PAD), px(0), px(space::PAD)),
            ..default()
        },
        BackgroundColor(colour::CARD),
        ChildOf(card),
    ));
}

/// Places a text node at `rect` (the UI's units, in its canvas), or hides it.
fn put(node: &mut Node, rect: Option<Rect>) {
    let (display, left, top) = match rect {
        Some(rect) => (Display::Flex, px(rect.min.x), px(rect.min.y)),
        None => (Display::None, node.left, node.top),
    };
    if node.display != display || node.left != left || node.top != top {
        node.display = display;
        node.left = left;
        node.top = top;
    }
}

/// What the plot plots: the ghosts' figures, the scene's step, the live integrator.
#[derive(SystemParam)]
struct Plotted<'w> {
    overlays: Res<'w, Overlays>,
    ghosts: Res<'w, Ghosts>,
    params: Res<'w, SceneParams>,
    integrator: Res<'w, Integrator>,
}

/// The plot's text nodes: the axes' texts, the ghosts' labels and the reference's note.
#[derive(SystemParam)]
#[allow(clippy::type_complexity)]
struct PlotTexts<'w, 's> {
    texts: Query<'w, 's, (&'static PlotText, &'static mut Node), Without<PlotLabel>>,
    labels: Query<
        'w,
        's,
        (&'static PlotLabel, &'static mut Text, &'static mut Node),
        Without<PlotText>,
    >,
    notes: Query<
        'w,
        's,
        (&'static mut Text, &'static mut Node),
        (With<ReferenceNote>, Without<PlotLabel>, Without<PlotText>),
    >,
}

fn draw_plot(
    mut gizmos: Gizmos<ChartGizmos>,
    window: Option<Single<&Window, With<PrimaryWindow>>>,
    ui_scale: Res<UiScale>,
    plotted: Plotted,
    canvases: Query<(&ComputedNode, &UiGlobalTransform), With<PlotCanvas>>,
    plot_texts: PlotTexts,
) {
    let Plotted {
        overlays,
        ghosts,
        params,
        integrator,
    } = plotted;
    let PlotTexts {
        mut texts,
        mut labels,
        mut notes,
    } = plot_texts;
    // A folded card's canvas has no size.
    let canvas = canvases
        .iter()
        .map(|(node, transform)| Canvas::of(node, transform, &ui_scale))
        .find(|canvas| overlays.plot && !canvas.rect.is_empty());
    let capped = ghosts
        .ghosts
        .iter()
        .find(|g| g.kind == GhostKind::Reference)
        .map_or(0, |g| g.capped);
    for (mut text, mut node) in &mut notes {
        let said = if capped > 0 {
            format!("The reference was capped at {capped} steps: errors there are implicit's.")
        } else {
            String::new()
        };
        let display = if said.is_empty() {
            Display::None
        } else {
            Display::Flex
        };
        if node.display != display {
            node.display = display;
        }
        if text.0 != said {
            text.0 = said;
        }
    }
    let Some(canvas) = canvas else {
        return;
    };
    let size = canvas.size();
    let frame = plot_frame(size);
    let caption = size::CAPTION;

    // The ticks' values, spaced so that none meets the next; the captions at the corners.
    let across_every = label_every(ERROR_DECADES, frame.width(), 6.0 * 0.602 * caption + 6.0);
    let up_every = label_every(COST_DECADES, frame.height(), 1.2 * caption + 2.0);
    let mut obstacles = Vec::new();
    for (what, mut node) in &mut texts {
        let rect = match *what {
            PlotText::Across(decade) if (decade - ERROR_DECADES.0) % across_every == 0 => {
                let x = frame.min.x + along(ERROR_DECADES, 10f64.powi(decade), frame.width());
                let text = text_box(Vec2::ZERO, &decade_label(decade), caption);
                let left = (x - text.width() / 2.0).clamp(0.0, size.x - text.width());
                Some(text_box(
                    Vec2::new(left, frame.max.y + 8.0),
                    &decade_label(decade),
                    caption,
                ))
            }
            PlotText::Up(decade) if (decade - COST_DECADES.0) % up_every == 0 => {
                let y = frame.max.y - along(COST_DECADES, 10f64.powi(decade), frame.height());
                let text = text_box(Vec2::ZERO, &decade_label(decade), caption);
                Some(text_box(
                    Vec2::new(frame.min.x - 3.0 - text.width(), y - text.height() / 2.0),
                    &decade_label(decade),
                    caption,
                ))
            }
            PlotText::AcrossCaption => Some(text_box(
                Vec2::new(frame.min.x, size.y - 1.2 * caption - 1.0),
                "error from the reference, px →",
                caption,
            )),
            PlotText::UpCaption => Some(text_box(
                Vec2::new(2.0, 1.0),
                "↑ cost, ns per simulated second",
                caption,
            )),
            _ => None,
        };
        if let Some(rect) = rect {
            obstacles.push(rect);
        }
        put(&mut node, rect);
    }

    // The names.
    let points = plot_points(&ghosts, params.step_rate_hz, *integrator);
    let wanted: Vec<(Vec2, Vec2)> = points
        .iter()
        .map(|point| {
            let size = text_box(Vec2::ZERO, &point.label(), caption).size();
            (place(point, frame), size)
        })
        .collect();
    let places = place_labels(&wanted, frame.inflate(-1.0), &obstacles);
    for (label, mut text, mut node) in &mut labels {
        let index = points.iter().position(|p| p.kind == label.0);
        let name = index.map(|i| points[i].label()).unwrap_or_default();
        if text.0 != name {
            text.0 = name;
        }
        put(&mut node, index.map(|i| places[i]));
    }

    // The frame, the decades' ticks and the points, in window pixels.
    let window = window.map_or(Vec2::ONE, |window| window.size());
    let at = |point: Vec2| canvas.to_chart(point, window);
    gizmos.linestrip_2d(
        [
            Vec2::new(frame.min.x, frame.min.y),
            Vec2::new(frame.max.x, frame.min.y),
            frame.max,
            Vec2::new(frame.min.x, frame.max.y),
            frame.min,
        ]
        .map(at),
        colour::FRAME,
    );
    for decade in ERROR_DECADES.0..=ERROR_DECADES.1 {
        let x = frame.min.x + along(ERROR_DECADES, 10f64.powi(decade), frame.width());
        let long = if (decade - ERROR_DECADES.0) % across_every == 0 {
            5.0
        } else {
            3.0
        };
        gizmos.line_2d(
            at(Vec2::new(x, frame.max.y)),
            at(Vec2::new(x, frame.max.y - long)),
            colour::FRAME,
        );
    }
    for decade in COST_DECADES.0..=COST_DECADES.1 {
        let y = frame.max.y - along(COST_DECADES, 10f64.powi(decade), frame.height());
        gizmos.line_2d(
            at(Vec2::new(frame.min.x, y)),
            at(Vec2::new(frame.min.x + 5.0, y)),
            colour::FRAME,
        );
    }
    let scale = canvas.ui_scale;
    for ((point, (anchor, _)), label) in points.iter().zip(&wanted).zip(&places) {
        let shade = point.kind.colour();
        let centre = at(*anchor);
        // A name moved off its point is tied to it, from its nearest edge.
        let nearest = anchor.clamp(label.min, label.max);
        if nearest.distance(*anchor) > 9.0 {
            let from = *anchor + (nearest - *anchor).normalize_or_zero() * (MARK + 1.0);
            gizmos.line_2d(at(from), at(nearest), shade.with_alpha(0.6));
        }
        match point.error {
            Some(_) => {
                gizmos.circle_2d(Isometry2d::from_translation(centre), 3.0 * scale, shade);
                if point.live {
                    gizmos.circle_2d(Isometry2d::from_translation(centre), 5.5 * scale, shade);
                }
            }
            None => {
                let arm = 4.0 * scale;
                for (a, b) in [
                    (Vec2::new(-arm, -arm), Vec2::new(arm, arm)),
                    (Vec2::new(-arm, arm), Vec2::new(arm, -arm)),
                ] {
                    gizmos.line_2d(centre + a, centre + b, shade);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Checks that the plot's names never meet.
    ///
    /// Each lies beside its point or is tied to it, none on another name, on a point's mark or on
    /// the axes' text, all inside the frame, however the points crowd.
    #[test]
    fn the_plots_names_never_meet() {
        let bounds = Rect::new(34.0, 18.0, 320.0, 200.0);
        let obstacles = [
            Rect::new(0.0, 0.0, 200.0, 14.0),
            Rect::new(34.0, 202.0, 60.0, 214.0),
        ];
        // Seven names on two points (most ghosts agree on a soft band), then spread out.
        for spread in [0.0, 3.0, 20.0] {
            let labels: Vec<(Vec2, Vec2)> = (0..7)
                .map(|i| {
                    let point = Vec2::new(200.0 + spread * i as f32, 100.0 + (i % 2) as f32);
                    (point, Vec2::new(40.0 + 5.0 * i as f32, 13.0))
                })
                .collect();
            let placed = place_labels(&labels, bounds, &obstacles);
            for (i, rect) in placed.iter().enumerate() {
                assert!(bounds.union(*rect) == bounds, "{i} in the frame: {rect:?}");
                for other in placed.iter().skip(i + 1).chain(&obstacles) {
                    assert!(rect.intersect(*other).is_empty(), "{rect:?} on {other:?}");
                }
                for (point, _) in &labels {
                    let mark = Rect::from_center_half_size(*point, Vec2::splat(MARK));
                    assert!(rect.intersect(mark).is_empty(), "{rect:?} on a point");
                }
            }
        }
    }
}
