//! The drawing, headless: the screen's plugins run without a window (Bevy's gizmos and assets
//! need none), and after each frame the test reads what the gizmos drew from the frame's gizmo
//! asset: the box's outline where the box is, the band from the pointer to the pulled corner
//! in the colour its stretch gives, the ghosts' outlines in their colours, the vectors and the
//! trail only when they are on.

use crate::common;

use std::any::TypeId;

use bevy::color::LinearRgba;
use bevy::gizmos::config::DefaultGizmoConfigGroup;
use bevy::gizmos::{GizmoAsset, GizmoHandles};
use common::*;
use rubber_band_box::game::ghosts::GhostKind;
use rubber_band_box::game::theme::colour::{BOX_OUTLINE, PIN_FILL};

/// The headless game with the screen's plugins ([`Game::with_screen`]).
fn screen_game() -> Game {
    Game::with_screen(add_the_screen)
}

/// One thing drawn: a segment, or a strip (a loop repeats its first two points at its end,
/// for the joints), with its first point's colour.
#[derive(Debug, Clone)]
struct Drawn {
    points: Vec<Vec2>,
    colour: LinearRgba,
    closed: bool,
}

/// What the scene's gizmos drew in the last frame.
fn drawn(game: &mut Game) -> Vec<Drawn> {
    drawn_in::<DefaultGizmoConfigGroup>(game)
}

/// What the gizmos of group `G` drew in the last frame (the charts': `ChartGizmos`).
fn drawn_in<G: 'static>(game: &mut Game) -> Vec<Drawn> {
    let world = game.world();
    let handle = world.resource::<GizmoHandles>().handles()[&TypeId::of::<G>()].clone();
    let Some(handle) = handle else {
        return Vec::new();
    };
    let buffer = world
        .resource::<Assets<GizmoAsset>>()
        .get(&handle)
        .expect("the frame's gizmos")
        .buffer();
    let mut found: Vec<Drawn> = buffer
        .list_positions
        .chunks(2)
        .zip(buffer.list_colors.chunks(2))
        .map(|(ends, colours)| Drawn {
            points: ends.iter().map(|p| p.truncate()).collect(),
            colour: colours[0],
            closed: false,
        })
        .collect();
    let mut strip: Vec<(Vec2, LinearRgba)> = Vec::new();
    for (position, colour) in buffer.strip_positions.iter().zip(&buffer.strip_colors) {
        if position.is_nan() {
            if let Some(&(first, colour)) = strip.first() {
                let mut points: Vec<Vec2> = strip.iter().map(|(p, _)| *p).collect();
                let n = points.len();
                let closed = n > 4 && points[n - 2] == first && points[n - 1] == points[1];
                if closed {
                    points.truncate(n - 2);
                }
                found.push(Drawn {
                    points,
                    colour,
                    closed,
                });
            }
            strip.clear();
        } else {
            strip.push((position.truncate(), *colour));
        }
    }
    found
}

fn close(a: Vec2, b: Vec2) -> bool {
    a.distance(b) < 1e-3
}

fn same_colour(a: LinearRgba, b: impl Into<LinearRgba>) -> bool {
    let b = b.into();
    (a.red - b.red).abs() < 1e-4
        && (a.green - b.green).abs() < 1e-4
        && (a.blue - b.blue).abs() < 1e-4
}

/// The outlines (closed loops of four corners) drawn in `colour`.
fn outlines(drawn: &[Drawn], colour: impl Into<LinearRgba> + Copy) -> Vec<Vec<Vec2>> {
    drawn
        .iter()
        .filter(|d| d.closed && d.points.len() == 4 && same_colour(d.colour, colour))
        .map(|d| d.points.clone())
        .collect()
}

/// A square's centre and side from its four corners, in order around it.
fn square(corners: &[Vec2]) -> (Vec2, [f32; 4]) {
    let centre = corners.iter().copied().sum::<Vec2>() / 4.0;
    let sides = [0, 1, 2, 3].map(|i| corners[i].distance(corners[(i + 1) % 4]));
    (centre, sides)
}

#[test]
fn the_box_is_outlined_where_it_is_and_the_band_runs_from_the_pointer_to_its_corner() {
    let mut game = screen_game();
    game.update(1);
    // At rest: one white square of 60 px around the origin (the scene's border is grey).
    let box_outlines = outlines(&drawn(&mut game), BOX_OUTLINE);
    assert_eq!(box_outlines.len(), 1, "{box_outlines:?}");
    let (centre, sides) = square(&box_outlines[0]);
    assert!(close(centre, Vec2::ZERO), "{centre}");
    assert!(sides.iter().all(|s| (s - 60.0).abs() < 1e-3), "{sides:?}");

    // Pulled: the outline follows the box, the band joins the anchor to a corner of it.
    let anchor = DVec2::new(200.0, 120.0);
    game.press_at(anchor);
    game.update(20);
    let (linear, _) = game.state();
    let drawn_now = drawn(&mut game);
    let box_outlines = outlines(&drawn_now, BOX_OUTLINE);
    assert_eq!(box_outlines.len(), 1);
    let (centre, _) = square(&box_outlines[0]);
    assert!(centre.x > 1.0, "the box moved toward the anchor: {centre}");
    // Drawn between the last two steps: within one step's travel of the box.
    let travel = (linear.velocity.length() * 0.01) as f32 + 1e-3;
    assert!(
        centre.distance(linear.position.as_vec2()) <= travel,
        "{centre} {linear:?}"
    );
    let bands: Vec<&Drawn> = drawn_now
        .iter()
        .filter(|d| {
            !d.closed && d.points.len() == 2 && d.colour.red == 1.0 && d.colour.green == 0.0
        })
        .collect();
    assert_eq!(bands.len(), 1, "one band: {bands:?}");
    let band = bands[0];
    let (corner, pointer) = (band.points[0], band.points[1]);
    assert!(close(pointer, anchor.as_vec2()), "{pointer}");
    assert!(
        box_outlines[0].iter().any(|&c| close(c, corner)),
        "the band ends at a corner of the outline: {corner} {:?}",
        box_outlines[0]
    );
    // Red when slack, toward magenta as it stretches (in sRGB): fully magenta at 510 px.
    let stretch = corner.distance(pointer);
    let blue = Srgba::from(band.colour).blue;
    assert!(
        (blue - (stretch / 510.0).min(1.0)).abs() < 1e-3,
        "blue {blue} at a stretch of {stretch} px"
    );
}

#[test]
fn a_band_stretched_past_510_px_is_fully_magenta() {
    let mut game = screen_game();
    // A wide window shows the world far beyond the scene: room for a long band.
    game.resize(UVec2::new(2400, 720));
    game.update(1);
    // 1.5 window px a world px (the scene's 480 in 720), the origin at the window's centre:
    // world (-700, 0), 670 px from the nearest corner.
    game.cursor(Some(Vec2::new(1200.0 - 700.0 * 1.5, 360.0)));
    game.mouse(ButtonState::Pressed);
    game.update(1);
    let bands: Vec<Drawn> = drawn(&mut game)
        .into_iter()
        .filter(|d| {
            !d.closed && d.points.len() == 2 && d.colour.red == 1.0 && d.colour.green == 0.0
        })
        .collect();
    assert_eq!(bands.len(), 1);
    assert_eq!(bands[0].colour.blue, 1.0);
    // Released: no band drawn.
    game.mouse(ButtonState::Released);
    game.update(2);
    let left = drawn(&mut game)
        .into_iter()
        .filter(|d| {
            !d.closed && d.points.len() == 2 && d.colour.red == 1.0 && d.colour.green == 0.0
        })
        .count();
    assert_eq!(left, 0);
}

#[test]
fn the_ghosts_are_outlined_in_their_colours_but_the_live_integrators() {
    let mut game = screen_game();
    game.update(1);
    game.tap_key(KeyCode::KeyG);
    game.press_at(DVec2::new(200.0, 120.0));
    game.update(10);
    let drawn_now = drawn(&mut game);
    let live = *game.world().resource::<Integrator>();
    for integrator in Integrator::ALL {
        let colour = GhostKind::Method(integrator).colour();
        let count = outlines(&drawn_now, colour).len();
        let expected = usize::from(integrator != live);
        assert_eq!(count, expected, "{integrator}'s ghost (live: {live})");
    }
    // The reference is white, as the box: the box and the reference's ghost.
    assert_eq!(outlines(&drawn_now, BOX_OUTLINE).len(), 2);
    // Off again: only the box.
    game.tap_key(KeyCode::KeyG);
    game.update(1);
    assert_eq!(outlines(&drawn(&mut game), BOX_OUTLINE).len(), 1);
}

/// The ghosts' names stand in one column, a line apart, however far the ghosts drift from one
/// another: a column beside each ghost's own outline put names over each other (seen in the
/// browser, where rk4's name vanished under implicit's on the stiff scene).
#[test]
fn the_ghosts_names_stand_in_one_column_a_line_apart() {
    use rubber_band_box::game::ghosts::draw::GhostLabel;
    let mut game = screen_game();
    game.update(1);
    game.tap_key(KeyCode::Digit3);
    game.tap_key(KeyCode::KeyG);
    game.update(150);
    let world = game.world();
    let mut shown: Vec<(GhostKind, Vec3)> = world
        .query::<(&GhostLabel, &Transform, &Visibility)>()
        .iter(world)
        .filter(|(_, _, visibility)| **visibility != Visibility::Hidden)
        .map(|(label, transform, _)| (label.0, transform.translation))
        .collect();
    assert_eq!(
        shown.len(),
        Integrator::ALL.len(),
        "every ghost's but the live one's"
    );
    let ghosts = world.resource::<rubber_band_box::game::ghosts::Ghosts>();
    let apart = ghosts
        .ghosts
        .iter()
        .map(|ghost| ghost.stepper.state.linear.position)
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(low, high), p| {
            (low.min(p.x), high.max(p.x))
        });
    assert!(
        apart.1 - apart.0 > 1.0,
        "the ghosts have drifted apart: {apart:?}"
    );
    shown.sort_by(|a, b| a.1.y.total_cmp(&b.1.y));
    for pair in shown.windows(2) {
        assert!(
            (pair[0].1.x - pair[1].1.x).abs() < 1e-3,
            "one column: {shown:?}"
        );
        let gap = pair[1].1.y - pair[0].1.y;
        let first_gap = shown[1].1.y - shown[0].1.y;
        assert!(
            gap > 1.0 && (gap - first_gap).abs() < 1e-3,
            "a line apart: {shown:?}"
        );
    }
}

#[test]
fn the_vectors_and_the_trail_are_drawn_only_when_on() {
    let velocity = LinearRgba::from(Color::srgb(0.3, 0.9, 0.4));
    let force = LinearRgba::from(Color::srgb(1.0, 0.55, 0.1));
    let count = |drawn: &[Drawn], colour: LinearRgba| {
        drawn
            .iter()
            .filter(|d| same_colour(d.colour, colour))
            .count()
    };
    // The trail fades in from transparent (the energy graph's total is the same yellow,
    // opaque).
    let pin = LinearRgba::from(PIN_FILL);
    let trails = |drawn: &[Drawn]| -> Vec<Drawn> {
        drawn
            .iter()
            .filter(|d| !d.closed && same_colour(d.colour, pin) && d.colour.alpha == 0.0)
            .cloned()
            .collect()
    };
    let mut game = screen_game();
    game.update(1);
    game.press_at(DVec2::new(200.0, 120.0));
    game.update(5);
    let before = drawn(&mut game);
    assert_eq!(count(&before, velocity) + count(&before, force), 0);
    assert!(trails(&before).is_empty());

    game.tap_key(KeyCode::KeyV);
    game.tap_key(KeyCode::KeyT);
    game.update(10);
    let after = drawn(&mut game);
    // An arrow is a shaft and two head lines.
    assert!(count(&after, velocity) >= 3, "the velocity arrow");
    assert!(count(&after, force) >= 3, "the force arrow");
    // The trail: a point a frame since it was switched on.
    let trail = trails(&after);
    assert_eq!(trail.len(), 1, "{trail:?}");
    assert!(trail[0].points.len() >= 9, "{}", trail[0].points.len());
}

/// Learn mode draws its equations' pictures in their colours: the arm r from the centre to
/// the band's corner, and the torque as an arc about the centre, sweeping in its sense (a
/// pull from the lower right turns the box clockwise); none outside learn mode.
#[test]
fn learn_mode_draws_the_arm_and_the_torques_arc_in_their_colours() {
    use rubber_band_box::game::learn::Learn;
    use rubber_band_box::game::theme::colour;
    let arm = LinearRgba::from(colour::ARM);
    let torque = LinearRgba::from(colour::TORQUE);
    let mut game = screen_game();
    game.update(1);
    game.press_at(DVec2::new(150.0, -200.0));
    game.update(3);
    let outside = drawn(&mut game);
    assert!(
        !outside
            .iter()
            .any(|d| same_colour(d.colour, arm) || same_colour(d.colour, torque))
    );
    game.mouse(ButtonState::Released);
    // The chapter on a force at a point; the player's pull.
    game.world().trigger(Learn::Chapter(2));
    // The chapter pauses, loads its scene on the next frame, and frames it on the one after.
    game.update(3);
    // Learn mode frames the chapter closer (down to y = −180): the press goes where the camera
    // shows the point.
    let below_right = game.on_window(Vec2::new(100.0, -150.0));
    game.cursor(Some(below_right));
    game.mouse(ButtonState::Pressed);
    game.update(3);
    let (linear, angular) = game.state();
    let band = game.the_band();
    let state = rubber_band_box::physics::BodyState { linear, angular };
    let corner = band.ends.attachment(&state).as_vec2();
    let centre = linear.position.as_vec2();
    let inside = drawn(&mut game);
    // The shaft (the interpolated state lies within a step of the body's).
    let shaft = inside
        .iter()
        .find(|d| {
            same_colour(d.colour, arm)
                && d.points.len() == 2
                && d.points[1].distance(d.points[0]) > 20.0
        })
        .expect("the arm's shaft");
    assert!(
        shaft.points[0].distance(centre) < 5.0 && shaft.points[1].distance(corner) < 5.0,
        "{shaft:?}"
    );
    let arc = inside
        .iter()
        .find(|d| same_colour(d.colour, torque) && d.points.len() > 10)
        .expect("the torque's arc");
    // Clockwise: each point turns the negative way about the centre.
    let turn = arc
        .points
        .windows(2)
        .map(|w| (w[0] - centre).perp_dot(w[1] - centre))
        .sum::<f32>();
    assert!(turn < 0.0, "the arc turns {turn}");
}

/// On a phone the text shrinks a little with the window, to 0.85 at the least (text a
/// person can still read); at the game's own size and above it is at 1.
#[test]
fn the_ui_scales_down_with_a_small_window_to_no_less_than_0_85() {
    use rubber_band_box::game::layout::ui_scale_for;
    assert_eq!(ui_scale_for(Vec2::new(960.0, 720.0)), 1.0);
    assert_eq!(ui_scale_for(Vec2::new(1920.0, 1080.0)), 1.0);
    assert_eq!(ui_scale_for(Vec2::new(648.0, 648.0)), 0.9);
    assert_eq!(ui_scale_for(Vec2::new(390.0, 844.0)), 0.85);
    let mut game = screen_game();
    game.update(1);
    assert_eq!(game.world().resource::<UiScale>().0, 1.0);
    game.resize(UVec2::new(390, 844));
    game.update(1);
    assert_eq!(game.world().resource::<UiScale>().0, 0.85);
    game.resize(UVec2::new(648, 648));
    game.update(1);
    assert_eq!(game.world().resource::<UiScale>().0, 0.9);
}

/// The headless game with the screen and Bevy's UI layout: the dock laid out, its charts'
/// canvases placed (every camera told the window's size, as the renderer would).
fn laid_out_screen_game(size: UVec2) -> Game {
    let mut game = Game::with_screen(|app| {
        add_the_layout(app);
        add_the_screen(app);
    });
    game.resize(size);
    game.update(3);
    game
}

/// The plot's canvas and its plotting frame, on the window (the UI's units scaled).
fn plot_canvas(game: &mut Game) -> (rubber_band_box::game::screen::chart::Canvas, Rect) {
    use rubber_band_box::game::plot::{PlotCanvas, plot_frame};
    use rubber_band_box::game::screen::chart::Canvas;
    let world = game.world();
    let scale = UiScale(world.resource::<UiScale>().0);
    let mut canvases =
        world.query_filtered::<(&ComputedNode, &bevy::ui::UiGlobalTransform), With<PlotCanvas>>();
    let (node, transform) = canvases.single(world).unwrap();
    let canvas = Canvas::of(node, transform, &scale);
    (canvas, plot_frame(canvas.size()))
}

/// The plot (P): each ghost's point is its own figures, as the ghosts' table lists them (distance from
/// the reference, and time per step times the step rate), drawn in its colour where the
/// report's axes put it in the plot card's canvas; a diverged ghost is a cross at the right
/// edge.
#[test]
fn the_plot_puts_each_ghost_where_its_own_figures_say() {
    use rubber_band_box::game::ghosts::Ghosts;
    use rubber_band_box::game::ghosts::table::readings as table_readings;
    use rubber_band_box::game::plot::{place, plot_points};
    use rubber_band_box::game::screen::chart::ChartGizmos;

    let mut game = laid_out_screen_game(UVec2::new(1280, 800));
    game.tap_key(KeyCode::KeyP);
    game.press_at(DVec2::new(200.0, 120.0));
    game.update(30);
    let world = game.world();
    let live = *world.resource::<Integrator>();
    let readings = table_readings(world.resource::<Ghosts>(), live);
    let points = plot_points(world.resource::<Ghosts>(), 100.0, live);
    assert_eq!(
        points.len(),
        Integrator::ALL.len(),
        "every method, not the reference"
    );
    for point in &points {
        let listed = readings
            .iter()
            .find(|g| g.name == point.kind.name())
            .expect("listed in the ghosts' table");
        assert_eq!(point.error, listed.distance, "{}", listed.name);
        assert_eq!(point.cost, listed.ns_per_step * 100.0, "{}", listed.name);
        assert!(point.cost > 0.0, "{} was timed", listed.name);
        assert_eq!(point.live, point.kind == GhostKind::Method(live));
    }
    // Drawn: a circle in each ghost's colour around its place in the canvas.
    let (canvas, frame) = plot_canvas(&mut game);
    assert!(
        canvas.rect.width() >= 300.0 && canvas.rect.height() >= 200.0,
        "a chart a person reads on a desktop: {:?}",
        canvas.rect
    );
    let window = Vec2::new(1280.0, 800.0);
    let drawn_now = drawn_in::<ChartGizmos>(&mut game);
    for point in &points {
        let at = canvas.to_chart(place(point, frame), window);
        let colour = point.kind.colour();
        // A circle is a strip of many points around its centre.
        let circle = drawn_now.iter().any(|d| {
            d.points.len() > 8
                && same_colour(d.colour, colour)
                && close_to(
                    d.points.iter().copied().sum::<Vec2>() / d.points.len() as f32,
                    at,
                )
        });
        assert!(circle, "{} at {at}", point.kind.name());
        assert!(frame.contains(place(point, frame)));
    }
}

fn close_to(a: Vec2, b: Vec2) -> bool {
    a.distance(b) < 0.5
}

#[test]
fn a_diverged_ghost_is_a_cross_at_the_plots_right_edge() {
    use rubber_band_box::game::ghosts::Ghosts;
    use rubber_band_box::game::plot::{PlotLabel, place, plot_points};
    use rubber_band_box::game::screen::chart::ChartGizmos;

    let mut game = laid_out_screen_game(UVec2::new(1280, 800));
    // k = 2e5 at 100 Hz: explicit Euler cannot hold it.
    game.world().resource_mut::<SceneParams>().stiffness = 2e5;
    game.tap_key(KeyCode::KeyP);
    game.press_at(DVec2::new(200.0, 120.0));
    game.update(40);
    let world = game.world();
    let points = plot_points(world.resource::<Ghosts>(), 100.0, Integrator::Auto);
    let euler = points
        .iter()
        .find(|p| p.kind == GhostKind::Method(Integrator::Euler))
        .unwrap();
    assert_eq!(euler.error, None, "euler diverged");
    let (canvas, frame) = plot_canvas(&mut game);
    let placed = place(euler, frame);
    assert_eq!(placed.x, frame.max.x);
    let at = canvas.to_chart(placed, Vec2::new(1280.0, 800.0));
    let colour = GhostKind::Method(Integrator::Euler).colour();
    let strokes = drawn_in::<ChartGizmos>(&mut game)
        .into_iter()
        .filter(|d| {
            !d.closed
                && d.points.len() == 2
                && same_colour(d.colour, colour)
                && close_to((d.points[0] + d.points[1]) / 2.0, at)
        })
        .count();
    assert_eq!(strokes, 2, "a cross");
    // Its name says so.
    let world = game.world();
    let name = world
        .query::<(&PlotLabel, &Text)>()
        .iter(world)
        .find(|(label, _)| label.0 == GhostKind::Method(Integrator::Euler))
        .map(|(_, text)| text.0.clone())
        .unwrap();
    assert_eq!(name, "euler diverged");
    // Off again: nothing of the plot drawn.
    game.tap_key(KeyCode::KeyP);
    game.update(2);
    assert!(
        drawn_in::<ChartGizmos>(&mut game)
            .iter()
            .all(|d| !same_colour(d.colour, colour))
    );
}
