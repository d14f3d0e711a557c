//! The energy graph: kinetic, band and total energy over the last seconds of simulated time,
//! in the Energy card under its lines (whose colours are its legend), scaled so that the
//! largest total in view reaches the top. Drawn by the chart camera in its canvas.

use bevy::prelude::*;
use bevy::ui::UiGlobalTransform;
use bevy::window::PrimaryWindow;

use super::history::EnergyHistory;
use super::lines::spawn_lines;
use crate::game::layout::{Card, Slots};
use crate::game::schedule::ScreenSystems;
use crate::game::screen::chart::{Canvas, ChartGizmos};
use crate::game::theme::readable;
use crate::game::theme::{self, colour, size, space};
use crate::physics::Energies;

/// Draws the graph (with the screen: it needs the chart camera's gizmos).
pub(super) fn plugin(app: &mut App) {
    app.add_systems(Startup, spawn_canvas.after(spawn_lines))
        .add_systems(Update, draw_energy_graph.in_set(ScreenSystems::Draw));
}

/// The graph's canvas.
#[derive(Component, Debug)]
struct EnergyCanvas;

/// The caption under it: the span and the peak.
#[derive(Component, Debug)]
struct EnergyCaption;

/// The canvas's height in the UI's units.
const GRAPH_HEIGHT: f32 = 90.0;

fn spawn_canvas(mut commands: Commands, slots: Slots) {
    let Some(card) = slots.card_body(Card::ENERGY) else {
        return;
    };
    commands.spawn((
        Name::new("Energy graph"),
        EnergyCanvas,
        Node {
            height: px(GRAPH_HEIGHT),
            margin: UiRect::axes(px(space::PAD), px(space::GAP)),
            flex_shrink: 0.0,
            ..default()
        },
        ChildOf(card),
    ));
    commands.spawn((
        Name::new("Energy caption"),
        EnergyCaption,
        Text::default(),
        theme::text_font(size::CAPTION),
        TextColor(colour::DIM),
        Node {
            padding: UiRect::new(px(space::PAD + 2.0), px(space::PAD), px(0), px(space::PAD)),
            ..default()
        },
        BackgroundColor(colour::CARD),
        ChildOf(card),
    ));
}

/// Returns the graph's place in its canvas, in the UI's units: the whole canvas but a pixel.
fn graph_frame(canvas: Vec2) -> Rect {
    Rect::from_corners(Vec2::ONE, canvas - Vec2::ONE)
}

fn draw_energy_graph(
    mut gizmos: Gizmos<ChartGizmos>,
    history: Res<EnergyHistory>,
    ui_scale: Res<UiScale>,
    window: Option<Single<&Window, With<PrimaryWindow>>>,
    canvases: Query<(&ComputedNode, &UiGlobalTransform), With<EnergyCanvas>>,
    mut captions: Query<&mut Text, With<EnergyCaption>>,
) {
    let highest = history
        .samples
        .iter()
        .map(|(_, e)| e.total())
        .fold(0.0, f64::max);
    let said = format!(
        "the last {} s of simulated time; the top is {}",
        EnergyHistory::SPAN,
        readable(highest)
    );
    for mut caption in &mut captions {
        if caption.0 != said {
            caption.0.clone_from(&said);
        }
    }
    let Some(window) = window else {
        return;
    };
    let size = window.size();
    for (node, transform) in &canvases {
        let canvas = Canvas::of(node, transform, &ui_scale);
        // A folded card's canvas has no size.
        if canvas.rect.is_empty() {
            continue;
        }
        let frame = graph_frame(canvas.size());
        let corner = |x: f32, y: f32| canvas.to_chart(Vec2::new(x, y), size);
        gizmos.linestrip_2d(
            [
                corner(frame.min.x, frame.min.y),
                corner(frame.max.x, frame.min.y),
                corner(frame.max.x, frame.max.y),
                corner(frame.min.x, frame.max.y),
                corner(frame.min.x, frame.min.y),
            ],
            colour::FRAME,
        );
        let Some(&(now, _)) = history.samples.back() else {
            continue;
        };
        let point = |t: f64, energy: f64| {
            let x = 1.0 - ((now - t) / EnergyHistory::SPAN) as f32;
            let y = if highest > 0.0 {
                (energy / highest) as f32
            } else {
                0.0
            };
            corner(
                frame.min.x + x * frame.width(),
                frame.max.y - y * frame.height(),
            )
        };
        let mut line = |energy: fn(&Energies) -> f64, shade: Color| {
            gizmos.linestrip_2d(
                history.samples.iter().map(|(t, e)| point(*t, energy(e))),
                shade,
            );
        };
        line(|e| e.kinetic(), colour::KINETIC);
        line(|e| e.band, colour::BAND_ENERGY);
        line(|e| e.total(), colour::TOTAL);
    }
}
