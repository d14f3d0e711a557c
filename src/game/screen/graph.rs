//! The energy graph: kinetic, band and total energy over the last seconds of simulated time,
//! drawn with gizmos in the view's top-right corner. Part of the HUD (its text lines are the
//! legend, H hides both), added with the screen because gizmos need rendering.

use bevy::prelude::*;

use crate::game::hud::history::EnergyHistory;
use crate::game::hud::{BAND_ENERGY_COLOUR, KINETIC_COLOUR, TOTAL_COLOUR};
use crate::game::schedule::ScreenSystems;
use crate::game::screen::view::view_area;
use crate::game::shared::Overlays;
use crate::physics::{Energies, SCENE_SIZE};

pub struct EnergyGraphPlugin;

impl Plugin for EnergyGraphPlugin {
    fn build(&self, app: &mut App) {
        app.add_systems(
            Update,
            draw_energy_graph
                .run_if(hud_shown)
                .in_set(ScreenSystems::Draw),
        );
    }
}

/// The graph's frame: the scene border's grey.
const FRAME_COLOUR: Color = Color::srgb(0.25, 0.25, 0.3);

fn hud_shown(overlays: Res<Overlays>) -> bool {
    !overlays.hud_hidden
}

/// The graph's size in world units, and its distance from the top-right corner.
const GRAPH_SIZE: Vec2 = Vec2::new(200.0, 80.0);
const GRAPH_MARGIN: f32 = 8.0;

/// The graph's frame in the world: the top-right corner of the tutorial's screen or of the
/// view, whichever is lower.
pub fn graph_frame(view: Rect) -> Rect {
    let top_right = view.max.min(SCENE_SIZE.as_vec2() / 2.0) - Vec2::splat(GRAPH_MARGIN);
    Rect::from_corners(top_right - GRAPH_SIZE, top_right)
}

/// Kinetic, band and total energy over the last seconds, in the top-right corner of the
/// tutorial's screen or of the view, whichever is lower (on a tall phone the view reaches far
/// above the scene, where the HUD is), scaled so that the largest total in view reaches the top.
fn draw_energy_graph(
    mut gizmos: Gizmos,
    history: Res<EnergyHistory>,
    camera: Single<(&Projection, &GlobalTransform), With<Camera2d>>,
) {
    let Some(view) = view_area(camera.0, camera.1) else {
        return;
    };
    let frame = graph_frame(view);
    gizmos.rect_2d(
        Isometry2d::from_translation(frame.center()),
        GRAPH_SIZE,
        FRAME_COLOUR,
    );
    let Some(&(now, _)) = history.samples.back() else {
        return;
    };
    let highest = history
        .samples
        .iter()
        .map(|(_, e)| e.total())
        .fold(0.0, f64::max);
    let point = |t: f64, energy: f64| {
        let x = 1.0 - ((now - t) / EnergyHistory::SPAN) as f32;
        let y = if highest > 0.0 {
            (energy / highest) as f32
        } else {
            0.0
        };
        frame.min + Vec2::new(x, y) * GRAPH_SIZE
    };
    let mut line = |energy: fn(&Energies) -> f64, colour: Color| {
        gizmos.linestrip_2d(
            history.samples.iter().map(|(t, e)| point(*t, energy(e))),
            colour,
        );
    };
    line(|e| e.kinetic(), KINETIC_COLOUR);
    line(|e| e.band, BAND_ENERGY_COLOUR);
    line(|e| e.total(), TOTAL_COLOUR);
}
