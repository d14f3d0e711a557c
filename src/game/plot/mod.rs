//! Speed against error, live (P): every ghost a point on the report's work-precision axes,
//! its distance from the reference (px) across, its cost per simulated second (ns) up, both
//! logarithmic with a tick at every decade, in the ghost's colour with its name, moving as
//! the hand pulls. A diverged ghost is a cross at the right edge, at the cost it had, and
//! says so. The chart fills the plot card's canvas (the chart camera draws it); its ticks'
//! values, its captions and the names are UI text in the canvas, the names put by
//! `axes::place_labels` where no other text, no point and no name lies, tied to their point by
//! a leader line when moved away from it. The points are [`plot_points`], which a test holds
//! to the ghosts' own figures; the axes' geometry is [`axes`], this module the card.

pub mod axes;

use bevy::ecs::system::SystemParam;
use bevy::picking::Pickable;
use bevy::prelude::*;
use bevy::ui::UiGlobalTransform;
use bevy::window::PrimaryWindow;

use crate::game::ghosts::{GhostKind, Ghosts};
use crate::game::layout::{Card, CardSpec, RegisterCard, Slots, show_node};
use crate::game::schedule::ScreenSystems;
use crate::game::screen::chart::{Canvas, ChartGizmos, text_box};
use crate::game::shared::{Overlay, Overlays, has_screen};
use crate::game::theme::{self, colour, size, space};
use crate::physics::{Integrator, SceneParams};
use axes::{COST_DECADES, ERROR_DECADES, MARK, along, decade_label, label_every, place_labels};
pub use axes::{PlotPoint, place, plot_frame, plot_points};

/// The Speed against error card, with a screen (its canvas is the screen's chart camera's).
pub struct PlotPlugin;

impl Card {
    /// Speed against error (with the plot on).
    pub const PLOT: Card = Card("plot");
}

impl Plugin for PlotPlugin {
    fn build(&self, _app: &mut App) {}

    fn finish(&self, app: &mut App) {
        if !has_screen(app) {
            return;
        }
        app.register_card(CardSpec {
            card: Card::PLOT,
            title: "Speed against error",
            place: 60,
            offered: |overlays, _| overlays.on(Overlay::Plot),
        })
        .add_systems(Startup, spawn_canvas)
        .add_systems(Update, draw_plot.in_set(ScreenSystems::Plot));
    }
}

/// The canvas's height in the UI's units (its width is the card's).
const PLOT_HEIGHT: f32 = 230.0;

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

impl PlotTexts<'_, '_> {
    /// Says under the plot when the reference was capped, and hides the note otherwise.
    fn note_the_reference(&mut self, capped: u64) {
        for (mut text, mut node) in &mut self.notes {
            let said = if capped > 0 {
                format!("The reference was capped at {capped} steps: errors there are implicit's.")
            } else {
                String::new()
            };
            show_node(&mut node, !said.is_empty());
            text.set_if_neq(Text(said));
        }
    }

    /// Places the ticks' values, spaced so that none meets the next, and the axes' captions.
    ///
    /// Returns where they lie, for the names to keep clear of.
    fn place_the_axes(&mut self, frame: Rect, size: Vec2, every: (i32, i32)) -> Vec<Rect> {
        let caption = size::CAPTION;
        let (across_every, up_every) = every;
        let mut obstacles = Vec::new();
        for (what, mut node) in &mut self.texts {
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
        obstacles
    }

    /// Names each point where its name fits clear of the axes' texts and of each other.
    ///
    /// Returns each point's place and its name's size, and where each name went.
    fn name_the_points(
        &mut self,
        points: &[PlotPoint],
        frame: Rect,
        obstacles: &[Rect],
    ) -> (Vec<(Vec2, Vec2)>, Vec<Rect>) {
        let wanted: Vec<(Vec2, Vec2)> = points
            .iter()
            .map(|point| {
                let size = text_box(Vec2::ZERO, &point.label(), size::CAPTION).size();
                (place(point, frame), size)
            })
            .collect();
        let places = place_labels(&wanted, frame.inflate(-1.0), obstacles);
        for (label, mut text, mut node) in &mut self.labels {
            let index = points.iter().position(|p| p.kind == label.0);
            let name = index.map(|i| points[i].label()).unwrap_or_default();
            text.set_if_neq(Text(name));
            put(&mut node, index.map(|i| places[i]));
        }
        (wanted, places)
    }
}

/// Draws the Speed against error card: its note, axes, ticks, names and points.
fn draw_plot(
    mut gizmos: Gizmos<ChartGizmos>,
    window: Option<Single<&Window, With<PrimaryWindow>>>,
    ui_scale: Res<UiScale>,
    plotted: Plotted,
    canvases: Query<(&ComputedNode, &UiGlobalTransform), With<PlotCanvas>>,
    mut plot_texts: PlotTexts,
) {
    let Plotted {
        overlays,
        ghosts,
        params,
        integrator,
    } = plotted;
    // A folded card's canvas has no size.
    let canvas = canvases
        .iter()
        .map(|(node, transform)| Canvas::of(node, transform, &ui_scale))
        .find(|canvas| overlays.on(Overlay::Plot) && !canvas.rect.is_empty());
    let capped = ghosts
        .ghosts
        .iter()
        .find(|g| g.kind == GhostKind::Reference)
        .map_or(0, |g| g.capped);
    plot_texts.note_the_reference(capped);
    let Some(canvas) = canvas else {
        return;
    };
    let size = canvas.size();
    let frame = plot_frame(size);
    let caption = size::CAPTION;
    let across_every = label_every(ERROR_DECADES, frame.width(), 6.0 * 0.602 * caption + 6.0);
    let up_every = label_every(COST_DECADES, frame.height(), 1.2 * caption + 2.0);
    let obstacles = plot_texts.place_the_axes(frame, size, (across_every, up_every));
    let points = plot_points(&ghosts, params.step_rate_hz, *integrator);
    let (wanted, places) = plot_texts.name_the_points(&points, frame, &obstacles);

    // In window pixels.
    let window = window.map_or(Vec2::ONE, |window| window.size());
    let at = |point: Vec2| canvas.to_chart(point, window);
    draw_the_frame(&mut gizmos, frame, across_every, &at);
    for ((point, (anchor, _)), label) in points.iter().zip(&wanted).zip(&places) {
        draw_a_point(&mut gizmos, point, (*anchor, *label), canvas.ui_scale, &at);
    }
}

/// Draws the plot's frame and the decades' ticks, the error's longer where a value is written.
fn draw_the_frame(
    gizmos: &mut Gizmos<ChartGizmos>,
    frame: Rect,
    across_every: i32,
    at: &impl Fn(Vec2) -> Vec2,
) {
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
}

/// Draws one ghost's point, tied to its name when the name moved off it.
///
/// A dot (ringed for the live integrator), or a cross where it has no error yet.
fn draw_a_point(
    gizmos: &mut Gizmos<ChartGizmos>,
    point: &PlotPoint,
    (anchor, label): (Vec2, Rect),
    scale: f32,
    at: &impl Fn(Vec2) -> Vec2,
) {
    let shade = point.kind.colour();
    let centre = at(anchor);
    let nearest = anchor.clamp(label.min, label.max);
    if nearest.distance(anchor) > 9.0 {
        let from = anchor + (nearest - anchor).normalize_or_zero() * (MARK + 1.0);
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
