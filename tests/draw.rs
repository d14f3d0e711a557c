//! The drawing, headless: the screen's plugins run without a window (Bevy's gizmos and assets
//! need none), and after each frame the test reads what the gizmos drew from the frame's gizmo
//! asset: the box's outline where the box is, the band from the pointer to the pulled corner
//! in the colour its stretch gives, the ghosts' outlines in their colours, the vectors and the
//! trail only when they are on.

mod common;

use std::any::TypeId;
use std::time::Duration;

use bevy::color::LinearRgba;
use bevy::gizmos::config::DefaultGizmoConfigGroup;
use bevy::gizmos::{GizmoAsset, GizmoHandles};
use common::*;
use rubber_band_box::game::ghosts::GhostKind;
use rubber_band_box::game::screen::draw::{BOX_OUTLINE, PIN_FILL};
use rubber_band_box::physics::SCENE_SIZE;

/// The headless game with the screen's plugins. The view's own camera has no renderer to
/// compute its projection, so it goes: the test's camera (as bevy_render would compute it)
/// maps the pointer.
fn screen_game() -> Game {
    screen_game_with(add_the_screen)
}

/// [`screen_game`], with what `plugins` adds.
fn screen_game_with(plugins: impl FnOnce(&mut App)) -> Game {
    let mut game = Game::with(Duration::from_millis(10), plugins);
    let world = game.world();
    let views: Vec<Entity> = world
        .query::<(Entity, &Name)>()
        .iter(world)
        .filter(|(_, name)| name.as_str() == "Camera")
        .map(|(entity, _)| entity)
        .collect();
    assert_eq!(views.len(), 1, "the view's camera");
    world.despawn(views[0]);
    game
}

/// One thing drawn: a segment, or a strip (a loop repeats its first two points at its end,
/// for the joints), with its first point's colour.
#[derive(Debug, Clone)]
struct Drawn {
    points: Vec<Vec2>,
    colour: LinearRgba,
    closed: bool,
}

/// What the gizmos drew in the last frame.
fn drawn(game: &mut Game) -> Vec<Drawn> {
    let world = game.world();
    let handle = world.resource::<GizmoHandles>().handles()
        [&TypeId::of::<DefaultGizmoConfigGroup>()]
        .clone();
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
    use rubber_band_box::game::screen::draw::GhostLabel;
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

/// On a phone the HUD and the panel shrink with the window, to 0.6 at the least; at the
/// game's own size and above they are at 1.
#[test]
fn the_ui_scales_down_with_a_small_window_to_no_less_than_0_6() {
    use rubber_band_box::game::screen::view::ui_scale_for;
    assert_eq!(ui_scale_for(Vec2::new(960.0, 720.0)), 1.0);
    assert_eq!(ui_scale_for(Vec2::new(1920.0, 1080.0)), 1.0);
    assert_eq!(ui_scale_for(Vec2::new(720.0, 720.0)), 0.75);
    assert_eq!(ui_scale_for(Vec2::new(390.0, 844.0)), 0.6);
    let mut game = screen_game();
    game.update(1);
    assert_eq!(game.world().resource::<UiScale>().0, 1.0);
    game.resize(UVec2::new(390, 844));
    game.update(1);
    assert_eq!(game.world().resource::<UiScale>().0, 0.6);
    game.resize(UVec2::new(720, 540));
    game.update(1);
    assert_eq!(game.world().resource::<UiScale>().0, 0.75);
}

/// The plot (P): each ghost's point is its own figures, as the HUD lists them (distance from
/// the reference, and time per step times the step rate), drawn in its colour where the
/// report's axes put it; a diverged ghost is a cross at the right edge.
#[test]
fn the_plot_puts_each_ghost_where_its_own_figures_say() {
    use bevy::ecs::system::RunSystemOnce;
    use rubber_band_box::game::ghosts::Ghosts;
    use rubber_band_box::game::hud::HudSources;
    use rubber_band_box::game::screen::plot::{place, plot_frame, plot_points};

    let mut game = screen_game();
    game.update(1);
    game.tap_key(KeyCode::KeyP);
    game.press_at(DVec2::new(200.0, 120.0));
    game.update(30);
    let readings = game
        .world()
        .run_system_once(|sources: HudSources| sources.readings())
        .unwrap();
    let world = game.world();
    let live = *world.resource::<Integrator>();
    let points = plot_points(world.resource::<Ghosts>(), 100.0, live);
    assert_eq!(
        points.len(),
        Integrator::ALL.len(),
        "every method, not the reference"
    );
    for point in &points {
        let listed = readings
            .ghosts
            .iter()
            .find(|g| g.name == point.kind.name())
            .expect("listed in the HUD");
        assert_eq!(point.error, listed.distance, "{}", listed.name);
        assert_eq!(point.cost, listed.ns_per_step * 100.0, "{}", listed.name);
        assert!(point.cost > 0.0, "{} was timed", listed.name);
        assert_eq!(point.live, point.kind == GhostKind::Method(live));
    }
    // Drawn: a circle in each ghost's colour around its place.
    let drawn_now = drawn(&mut game);
    let frame = plot_frame();
    for point in &points {
        let at = place(point, frame);
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
        assert!(frame.contains(at));
    }
}

fn close_to(a: Vec2, b: Vec2) -> bool {
    a.distance(b) < 0.5
}

#[test]
fn a_diverged_ghost_is_a_cross_at_the_plots_right_edge() {
    use rubber_band_box::game::ghosts::Ghosts;
    use rubber_band_box::game::screen::plot::{place, plot_frame, plot_points};

    let mut game = screen_game();
    game.update(1);
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
    let at = place(euler, plot_frame());
    assert_eq!(at.x, plot_frame().max.x);
    let colour = GhostKind::Method(Integrator::Euler).colour();
    let strokes = drawn(&mut game)
        .into_iter()
        .filter(|d| {
            !d.closed
                && d.points.len() == 2
                && same_colour(d.colour, colour)
                && close_to((d.points[0] + d.points[1]) / 2.0, at)
        })
        .count();
    assert_eq!(strokes, 2, "a cross");
    // Off again: nothing of the plot drawn.
    game.tap_key(KeyCode::KeyP);
    game.update(1);
    let frame_drawn = drawn(&mut game).into_iter().any(|d| {
        d.closed && d.points.len() == 4 && close_to(d.points[0], plot_frame().min)
            || d.points.iter().any(|p| close_to(*p, plot_frame().min))
    });
    assert!(!frame_drawn, "the plot's frame is gone");
}

/// The scene is fitted to the part of the window the panel and the HUD leave free: at a
/// desktop's size and both phones', with the panel folded (its one button) or open and the
/// HUD's column, ghosts' list and help line where the game lays them out, the scene's
/// rectangle lies inside the window and clear of every one of them; with room to spare, or
/// nothing laid out, it fills the window as before.
#[test]
fn the_scene_is_fitted_where_no_control_lies() {
    use rubber_band_box::game::screen::view::{fitted_scene, free_area, scene_scale};
    let rect = |x0: f32, y0: f32, x1: f32, y1: f32| Rect::new(x0, y0, x1, y1);
    // Laid out as the game's and the browser test's screenshots show them (logical window
    // pixels): the panel, then the HUD's column, ghosts' list and help line.
    let desktop_hud = [
        rect(6.0, 6.0, 540.0, 224.0),
        rect(6.0, 538.0, 662.0, 680.0),
        rect(6.0, 684.0, 954.0, 714.0),
    ];
    let portrait_hud = [
        rect(4.0, 4.0, 386.0, 146.0),
        rect(4.0, 684.0, 386.0, 800.0),
        rect(4.0, 804.0, 386.0, 842.0),
    ];
    let landscape_hud = [rect(4.0, 4.0, 480.0, 146.0), rect(4.0, 360.0, 840.0, 388.0)];
    let cases = [
        (
            "desktop, folded",
            Vec2::new(960.0, 720.0),
            vec![rect(871.0, 648.0, 952.0, 678.0)],
            &desktop_hud[..],
        ),
        (
            "desktop, open",
            Vec2::new(960.0, 720.0),
            vec![
                rect(604.0, 150.0, 952.0, 640.0),
                rect(871.0, 648.0, 952.0, 678.0),
            ],
            &desktop_hud[..],
        ),
        (
            "portrait, folded",
            Vec2::new(390.0, 844.0),
            vec![rect(335.0, 798.0, 385.0, 818.0)],
            &portrait_hud[..],
        ),
        (
            "portrait, open",
            Vec2::new(390.0, 844.0),
            vec![
                rect(178.0, 500.0, 386.0, 795.0),
                rect(335.0, 798.0, 385.0, 818.0),
            ],
            &portrait_hud[..],
        ),
        (
            "landscape, open",
            Vec2::new(844.0, 390.0),
            vec![
                rect(560.0, 4.0, 840.0, 350.0),
                rect(790.0, 355.0, 840.0, 375.0),
            ],
            &landscape_hud[..],
        ),
    ];
    for (name, window, controls, hud) in cases {
        let covered: Vec<Rect> = controls.iter().chain(hud).copied().collect();
        let free = free_area(window, &covered);
        let scene = fitted_scene(free);
        let inside = Rect::from_corners(Vec2::ZERO, window);
        assert!(
            scene.width() > 150.0,
            "{name}: the scene is drawn ({scene:?})"
        );
        assert_eq!(inside.union(scene), inside, "{name}: inside the window");
        for covering in &covered {
            assert!(
                scene.intersect(*covering).is_empty(),
                "{name}: {scene:?} lies under {covering:?}"
            );
        }
        // And no larger scene would have fitted: one 5% larger, centred anywhere on a grid,
        // meets something or leaves the window.
        let larger = scene.size() * 1.05;
        for x in (0..=window.x as usize).step_by(4) {
            for y in (0..=window.y as usize).step_by(4) {
                let bigger = Rect::from_center_size(Vec2::new(x as f32, y as f32), larger);
                let fits = inside.union(bigger) == inside
                    && covered.iter().all(|c| c.intersect(bigger).is_empty());
                assert!(!fits, "{name}: {bigger:?} would have fitted too");
            }
        }
    }
    // Nothing laid out, or a panel that a wide window keeps clear of: the whole window.
    let window = Vec2::new(960.0, 720.0);
    assert_eq!(
        free_area(window, &[]),
        Rect::from_corners(Vec2::ZERO, window)
    );
    let wide = Vec2::new(1280.0, 720.0);
    let corner = [rect(1191.0, 648.0, 1272.0, 678.0)];
    assert_eq!(
        free_area(wide, &corner),
        Rect::from_corners(Vec2::ZERO, wide)
    );
    assert_eq!(scene_scale(free_area(wide, &corner)), 1.5);
}

/// The scene keeps its place while the HUD's lines change width with their digits: the area
/// it has is kept while its scene stays clear and nothing fits one more than 5% larger; it
/// moves as soon as something covers it, and grows when the room is worth it.
#[test]
fn the_scene_does_not_follow_each_digit() {
    use rubber_band_box::game::screen::view::{area_to_fit, fitted_scene, free_area};
    let window = Vec2::new(960.0, 720.0);
    let column = |right: f32| Rect::new(6.0, 6.0, right, 224.0);
    let list = Rect::new(6.0, 538.0, 662.0, 680.0);
    let first = free_area(window, &[column(540.0), list]);
    // A digit more or less: kept.
    for right in [532.0, 548.0] {
        let covered = [column(right), list];
        if fitted_scene(first).intersect(covered[0]).is_empty() {
            assert_eq!(area_to_fit(window, &covered, Some(first)), first);
        }
    }
    // A line that reaches over the scene: it moves clear.
    let long = [column(800.0), list];
    assert!(!fitted_scene(first).intersect(long[0]).is_empty());
    let moved = area_to_fit(window, &long, Some(first));
    assert!(fitted_scene(moved).intersect(long[0]).is_empty());
    // The ghosts' list gone: the room below is worth growing into.
    let grown = area_to_fit(window, &[column(800.0)], Some(moved));
    assert!(fitted_scene(grown).width() > 1.05 * fitted_scene(moved).width());
}

/// The ghosts' names go above the box, or where that would lie over the energy graph or the
/// plot or leave the tutorial's screen, below it, right or left of it.
#[test]
fn the_ghosts_names_keep_off_the_graph_and_the_plot() {
    use rubber_band_box::game::screen::draw::label_column;
    use rubber_band_box::game::screen::graph::graph_frame;
    use rubber_band_box::game::screen::plot::plot_footprint;
    let scene = Rect::from_center_size(Vec2::ZERO, SCENE_SIZE.as_vec2());
    let graph = graph_frame(scene);
    let avoid = [graph, plot_footprint()];
    let (line, width, lines, reach) = (13.0, 80.0, 7, 46.0);
    // Each name's box, where the column puts it.
    let names = |centre: Vec2, (first, step): (Vec2, Vec2)| -> Vec<Rect> {
        (0..lines)
            .map(|i| {
                let at = centre + first + step * i as f32;
                Rect::from_center_size(at, Vec2::new(width, line))
            })
            .collect()
    };
    let clear = |boxes: &[Rect]| {
        boxes
            .iter()
            .all(|b| scene.union(*b) == scene && avoid.iter().all(|a| a.intersect(*b).is_empty()))
    };
    // In the middle, the plot off: above, one line over the other.
    let (first, step) = label_column(Vec2::ZERO, reach, lines, line, width, &[graph]);
    assert!(first.x == 0.0 && first.y > reach && step == Vec2::new(0.0, line));
    // Anywhere the box goes in the scene, the names lie in the scene, off the graph and the
    // plot, but where no side has room (then above).
    let mut crowded = 0;
    let mut moved = 0;
    for x in (-280..=280).step_by(20) {
        for y in (-200..=200).step_by(20) {
            let centre = Vec2::new(x as f32, y as f32);
            let place = label_column(centre, reach, lines, line, width, &avoid);
            let above = label_column(centre, reach, lines, line, width, &[]) == place;
            if clear(&names(centre, place)) {
                moved += usize::from(!above);
            } else {
                assert_eq!(
                    place.0, first,
                    "at {centre}: names on the graph or the plot"
                );
                crowded += 1;
            }
        }
    }
    assert!(moved > 50, "{moved} places moved the names off");
    assert!(crowded < 120, "{crowded} of 609 places found no room");
    // Just under the graph (where the tutorial's pull takes the box): not above.
    let under_graph = Vec2::new(graph.center().x, graph.min.y - 50.0);
    let place = label_column(under_graph, reach, lines, line, width, &avoid);
    assert!(clear(&names(under_graph, place)), "on the graph");
}

/// The same, from Bevy's own layout of the panel and the HUD (no renderer): at a desktop's
/// and both phones' sizes, the ghosts' list on, the panel folded and open, the scene the
/// camera shows lies inside the window and clear of every rectangle the panel and the HUD
/// published, and those are the real ones (the fold button, the HUD's column).
#[test]
fn the_laid_out_panel_and_hud_leave_the_scene_clear() {
    use rubber_band_box::game::input::panel::PanelOpen;
    use rubber_band_box::game::shared::{ControlsArea, HudArea};
    let mut game = screen_game_with(|app| {
        add_the_layout(app);
        add_the_screen(app);
    });
    game.tap_key(KeyCode::KeyG);
    for size in [
        UVec2::new(960, 720),
        UVec2::new(390, 844),
        UVec2::new(844, 390),
    ] {
        for open in [false, true] {
            game.resize(size);
            game.world().resource_mut::<PanelOpen>().0 = open;
            // Laid out, published, fitted: a frame each.
            game.update(4);
            let name = format!("{size}, panel open: {open}");
            let world = game.world();
            let controls = world.resource::<ControlsArea>().0.clone();
            let hud = world.resource::<HudArea>().0.clone();
            assert!(
                !controls.is_empty() && hud.len() >= 3,
                "{name}: laid out: {controls:?} {hud:?}"
            );
            // The HUD's column starts at its top left corner, below it the ghosts' list.
            assert!(
                hud.iter()
                    .any(|r| r.min.x < 10.0 && r.min.y < 10.0 && r.height() > 50.0)
            );
            let window = size.as_vec2();
            let mut cameras = world.query_filtered::<(&Projection, &Transform), With<Camera2d>>();
            let (projection, transform) = cameras.single(world).unwrap();
            let Projection::Orthographic(orthographic) = projection else {
                panic!("{name}: the camera is orthographic");
            };
            // World to window: a world unit is 1 / scale pixels, the camera at the centre.
            let pixels = 1.0 / orthographic.scale;
            let centre = window / 2.0
                + Vec2::new(-transform.translation.x, transform.translation.y) * pixels;
            let scene = Rect::from_center_size(centre, SCENE_SIZE.as_vec2() * pixels);
            let inside = Rect::from_corners(Vec2::ZERO, window);
            assert!(
                scene.width() > 150.0,
                "{name}: the scene is drawn ({scene:?})"
            );
            assert!(
                inside.union(scene).size().distance(inside.size()) < 0.01,
                "{name}: {scene:?} leaves the window"
            );
            for covering in controls.iter().chain(&hud) {
                let overlap = scene.intersect(*covering);
                assert!(
                    overlap.is_empty() || overlap.width().min(overlap.height()) < 0.01,
                    "{name}: {scene:?} lies under {covering:?}"
                );
            }
        }
    }
}
