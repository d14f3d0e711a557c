//! The plot's axes: each ghost a point ([`plot_points`]), the decades across (error, px) and
//! up (cost, ns per simulated second) and a point's place in the frame, the ticks' values, and
//! where the ghosts' names go so that none covers a point, a text or another name.

use bevy::prelude::*;

use crate::game::ghosts::{GhostKind, Ghosts};
use crate::physics::Integrator;

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
    pub(super) fn label(&self) -> String {
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
pub(super) const ERROR_DECADES: (i32, i32) = (-16, 3);
pub(super) const COST_DECADES: (i32, i32) = (2, 8);

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
pub(super) fn along(decades: (i32, i32), value: f64, length: f32) -> f32 {
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
pub(super) fn decade_label(decade: i32) -> String {
    match decade {
        0 => "1".to_owned(),
        1 => "10".to_owned(),
        _ => format!("1e{decade}"),
    }
}

/// Returns every how many decades an axis of `length` writes a value, so that no two meet.
///
/// `room` is what one value needs.
pub(super) fn label_every(decades: (i32, i32), length: f32, room: f32) -> i32 {
    let per_decade = length / (decades.1 - decades.0) as f32;
    (1..=6)
        .find(|&every| every as f32 * per_decade >= room)
        .unwrap_or(6)
}

/// The half-size of a point's mark, which no name may cover.
pub(super) const MARK: f32 = 7.0;

/// Returns where each name goes: near its point if there is room, else the first free place.
///
/// A name goes beside its point (right, left, above, below, then the diagonals), further out ring
/// by ring, at the first place inside `bounds` that meets no mark of any point, no text of
/// `obstacles` and no name placed before; where no such place is near, at the first free place in
/// `bounds`, top to bottom. `labels` are each point and its name's size.
pub(super) fn place_labels(labels: &[(Vec2, Vec2)], bounds: Rect, obstacles: &[Rect]) -> Vec<Rect> {
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
                    .all(|other| other.inflate(3.0).intersect(rect).is_empty())
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
