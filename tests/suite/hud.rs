//! The key(Action::ToggleDock), headless: its lines follow the simulation and the controls, and its energy lines
//! and history agree with the physics.

use crate::common;

use common::*;
use rubber_band_box::game::ghosts::table::GhostCell;

use rubber_band_box::game::stability::card::{StabilityLine, line as stability_line};
use rubber_band_box::physics::Energies;

#[test]
fn the_hud_follows_the_game() {
    let mut game = Game::stepping();
    game.update(1);
    assert!(
        game.line("Readouts Integrator")
            .starts_with("integrator auto")
    );
    game.tap_key(key(Action::NextIntegrator));
    game.update(1);
    assert!(
        game.line("Readouts Integrator")
            .starts_with(&format!("integrator {}", Integrator::Auto.next()))
    );

    // Pulling puts energy into the band; the panel shows ½m|v|² + ½Iω² + ½k|d|² of the
    // state now, computed here by hand from the box and the band (m 5, I 3000, k 20).
    game.press_at(DVec2::new(200.0, 100.0));
    game.update(20);
    let (linear, angular) = game.state();
    let band = game.the_band().ends;
    let (sin, cos) = angular.orientation.sin_cos();
    let p = band.local_point;
    let corner = linear.position + DVec2::new(cos * p.x - sin * p.y, sin * p.x + cos * p.y);
    let kinetic = 0.5 * 5.0 * linear.velocity.length_squared()
        + 0.5 * 3000.0 * angular.angular_velocity.powi(2);
    let stretched = 0.5 * 20.0 * corner.distance_squared(band.anchor);
    assert!(kinetic > 1.0 && stretched > 1.0, "{kinetic} {stretched}");
    let value = |line: &str, game: &mut Game| -> f64 {
        let text = game.line(line);
        text.split_whitespace().last().unwrap().parse().unwrap()
    };
    assert!((value("Energy BandPotential", &mut game) - stretched).abs() < 0.01);
    assert!((value("Energy Total", &mut game) - (kinetic + stretched)).abs() < 0.01);

    game.tap_key(key(Action::TogglePause));
    game.update(2);
    assert!(game.line("Readouts Clock").contains("PAUSED"));
}

/// H hides the dock of instruments (the scene takes the window) and shows it again.
#[test]
fn h_hides_and_shows_the_dock() {
    use rubber_band_box::game::layout::Dock;
    let mut game = Game::stepping();
    let display = |game: &mut Game| {
        let mut docks = game.world().query_filtered::<&Node, With<Dock>>();
        docks.single(game.world()).unwrap().display
    };
    game.update(1);
    assert_eq!(display(&mut game), Display::Flex);
    game.tap_key(key(Action::ToggleDock));
    game.update(1);
    assert_eq!(display(&mut game), Display::None);
    game.tap_key(key(Action::ToggleDock));
    game.update(1);
    assert_eq!(display(&mut game), Display::Flex);
}

#[test]
fn the_energy_history_keeps_a_bounded_recent_window() {
    let mut game = Game::new(Duration::from_millis(100));
    game.press_at(DVec2::new(200.0, 0.0));
    game.update(200); // 20 s of play at 100 Hz
    let history = game.world().resource::<EnergyHistory>().clone();
    let (first, _) = *history.samples.front().unwrap();
    let (last, latest) = *history.samples.back().unwrap();
    assert!(history.samples.len() <= EnergyHistory::SAMPLES + 1);
    assert!(history.samples.len() > EnergyHistory::SAMPLES / 2);
    assert!(last - first <= EnergyHistory::SPAN && last - first > 0.9 * EnergyHistory::SPAN);
    // Samples are at most one spacing apart, the latest within one spacing of now.
    let now = game.world().resource::<Time<Fixed>>().elapsed_secs_f64();
    assert!(now - last < EnergyHistory::SPAN / EnergyHistory::SAMPLES as f64);
    assert!(latest.total() > 0.0);
}

#[test]
fn the_history_starts_over_if_time_goes_back() {
    let mut history = EnergyHistory::default();
    history.record(5.0, Energies::default());
    history.record(6.0, Energies::default());
    history.record(1.0, Energies::default());
    assert_eq!(history.samples.len(), 1);
}

#[test]
fn a_step_that_fell_back_is_shown_as_such() {
    let mut game = Game::stepping();
    game.world().resource_mut::<SceneParams>().stiffness = 1e9;
    game.press_at(DVec2::new(200.0, 100.0));
    game.update(3);
    assert!(game.world().resource::<StepStats>().fell_back);
    let line = game.line("Readouts Integrator");
    assert!(
        line.contains("fell back to implicit (over budget)"),
        "{line}"
    );
    // Back to a soft band: the next steps are substeps again.
    game.world().resource_mut::<SceneParams>().stiffness = 20.0;
    game.update(2);
    assert!(!game.world().resource::<StepStats>().fell_back);
}

#[test]
fn reset_restarts_the_graph_and_the_clock() {
    let mut game = Game::stepping();
    game.press_at(DVec2::new(200.0, 100.0));
    game.update(100);
    assert!(game.world().resource::<EnergyHistory>().samples.len() > 10);
    assert!(
        game.line("Readouts Clock").contains("t 1.00 s"),
        "{}",
        game.line("Readouts Clock")
    );
    game.tap_key(key(Action::Reset));
    game.update(1);
    let history = game.world().resource::<EnergyHistory>().clone();
    assert!(history.samples.len() <= 1, "{:?}", history.samples);
    let clock = game.line("Readouts Clock");
    assert!(clock.contains("t 0.0"), "{clock}");
}

#[test]
fn the_energy_panel_is_live_while_paused() {
    let mut game = Game::stepping();
    game.press_at(DVec2::new(200.0, 100.0));
    game.update(5);
    game.tap_key(key(Action::TogglePause));
    game.update(2);
    let before = game.line("Energy BandPotential");
    // Pull the anchor further while paused: no step runs, the band stretches.
    game.cursor(Some(world_to_screen(DVec2::new(300.0, 200.0))));
    game.update(2);
    let after = game.line("Energy BandPotential");
    let value = |line: &str| {
        line.split_whitespace()
            .last()
            .unwrap()
            .parse::<f64>()
            .unwrap()
    };
    assert!(value(&after) > value(&before), "{before} -> {after}");
}

/// The Stability card's line as the game shows it.
fn shown_stability(game: &mut Game) -> String {
    let world = game.world();
    let mut lines = world.query_filtered::<&Text, With<StabilityLine>>();
    lines
        .single(world)
        .expect("the Stability card has its line")
        .0
        .clone()
}

/// The stability line: the live integrator's ω·dt against its limit at this damping, and the
/// stiffest band it holds, following the integrator and k; the ghosts' list says it for each.
#[test]
fn the_stability_line_says_how_close_the_band_is_to_blowing_the_integrator_up() {
    let mut game = Game::stepping();
    game.update(1);
    // ω = 2 sqrt(k/m) = 4 /s, a step of 10 ms.
    assert_eq!(
        shown_stability(&mut game),
        "stability: auto at ω·dt 0.04, stable at any k"
    );
    *game.world().resource_mut::<Integrator>() = Integrator::Symplectic;
    game.update(1);
    // Semi-implicit Euler at the tutorial's damping: ω²h² + 2γh < 4, so ω·h < 1.99.
    assert_eq!(
        shown_stability(&mut game),
        "stability: symplectic at ω·dt 0.04 of 1.99: holds k up to 5.0e4"
    );
    for _ in 0..4 {
        game.tap_key(key(Action::Stiffer));
        game.update(1);
    }
    assert_eq!(game.world().resource::<SceneParams>().stiffness, 2e5);
    let line = shown_stability(&mut game);
    assert_eq!(
        line,
        "stability: symplectic at ω·dt 4.00, past its 1.99: UNSTABLE above k 5.0e4"
    );
    game.tap_key(KeyCode::KeyG);
    game.update(2);
    let ghosts = game.ghost_table();
    let row = |name: &str| {
        ghosts
            .lines()
            .find(|line| line.trim_start().starts_with(name))
            .unwrap_or_else(|| panic!("{name} in\n{ghosts}"))
            .to_owned()
    };
    assert!(row("rk4").ends_with("✗ k<1.0e5"), "{ghosts}");
    // A limit under 1e4 reads whole: explicit Euler's at the tutorial's damping and 100 Hz.
    assert!(row("euler").ends_with("✗ k<221"), "{ghosts}");
    assert!(row("implicit").ends_with("any k"), "{ghosts}");
}

/// One format for the key(Action::ToggleDock) and the panel: numbers as a person reads them.
#[test]
fn numbers_are_shown_as_a_person_reads_them() {
    use rubber_band_box::game::theme::readable;
    for (value, shown) in [
        (20.0, "20"),
        (5.0, "5"),
        (1.0, "1"),
        (2.0203, "2.02"),
        (0.05, "0.05"),
        (123.4, "123"),
        (1e5, "1.0e5"),
        (3.2e-9, "3.2e-9"),
        (0.0, "0"),
        (-2.5, "-2.5"),
    ] {
        assert_eq!(readable(value), shown, "{value}");
    }
    // The parameters line: the linear damping as its coefficient and as its rate.
    let mut game = Game::stepping();
    game.update(1);
    assert_eq!(
        game.line("Readouts Parameters"),
        "m 5  k 20  damping: linear b 5 = 1 /s, angular 2.02 /s"
    );
}

/// The key(Action::ToggleDock) and the cards' texts only show: none of their nodes takes a press, so a long line lying over the panel
/// on a small screen never keeps a click from the panel's button under it.
#[test]
fn the_hud_takes_no_press() {
    use bevy::picking::Pickable;
    let mut game = Game::stepping();
    game.update(1);
    let world = game.world();
    // The key(Action::ToggleDock)'s lines and the Readouts and Energy cards' are named by their place.
    let texts = ["HUD ", "Readouts ", "Energy "];
    let mut nodes: Vec<Option<Pickable>> = world
        .query_filtered::<(&Name, Option<&Pickable>), With<Text>>()
        .iter(world)
        .filter(|(name, _)| texts.iter().any(|text| name.starts_with(text)))
        .map(|(_, pickable)| pickable.cloned())
        .collect();
    assert_eq!(
        nodes.len(),
        14,
        "the key(Action::ToggleDock)'s 2 lines, the Readouts' 5, the Energy's 7"
    );
    nodes.extend(
        world
            .query_filtered::<Option<&Pickable>, Or<(With<GhostCell>, With<StabilityLine>)>>()
            .iter(world)
            .map(|pickable| pickable.cloned()),
    );
    assert!(nodes.len() > 14, "{}", nodes.len());
    for pickable in nodes {
        let pickable = pickable.expect("every key(Action::ToggleDock) node says how it is picked");
        assert!(!pickable.should_block_lower && !pickable.is_hoverable);
    }
}

/// The Stability card's line, in its own folder, colours itself as the Readouts card's
/// integrator line does once the live method diverged: in the warning colour exactly when the
/// live method is past its limit, in the text's colour with no margin known or within it.
#[test]
fn the_stability_line_warns_only_past_the_live_methods_limit() {
    use rubber_band_box::game::theme::colour;
    use rubber_band_box::physics::stability::{Limit, Margin};
    let (text, warning) = (colour::TEXT, colour::WARNING);
    let stability = |margins: &[Margin], live: Integrator| stability_line(margins, live).1;
    assert_eq!(stability(&[], Integrator::Auto), text);
    assert_eq!(stability(&[], Integrator::Euler), text);
    // Past the live method's limit: the stability line warns; within it, it does not.
    let margin = |integrator: Integrator, holds: bool| Margin {
        integrator,
        omega_dt: 0.5,
        spectral_radius: if holds { 0.9 } else { 1.1 },
        holds,
        stiffest: Limit::UpTo(100.0),
        limit_omega_dt: Some(0.3),
    };
    let past_margins = [margin(Integrator::Euler, false)];
    assert_eq!(stability(&past_margins, Integrator::Euler), warning);
    // Another method past its limit is the ghosts' list's business, not the live line's.
    let other = [
        margin(Integrator::Euler, true),
        margin(Integrator::Rk4, false),
    ];
    assert_eq!(stability(&other, Integrator::Euler), text);
}

/// A ghost's work: its substeps times its evaluations when it took more than one substep,
/// its evaluations alone when it took one; the steps its budget capped, if any, where a
/// method says the stiffest band it holds.
#[test]
fn a_ghosts_work_says_its_substeps_when_there_are_several() {
    use rubber_band_box::game::ghosts::table::{GhostReading, lines};
    let ghost = |name: &'static str, substeps: u32, evaluations: u32, capped: u64| GhostReading {
        name,
        colour: Color::WHITE,
        live: false,
        distance: Some(1e-3),
        residual: 0.0,
        substeps,
        evaluations,
        ns_per_step: 100.0,
        diverged_at: None,
        capped,
    };
    use rubber_band_box::physics::stability::{Limit, Margin};
    // A limit of exactly 1e4 is the first in powers of ten.
    let rk4_margin = Margin {
        integrator: Integrator::Rk4,
        omega_dt: 0.1,
        spectral_radius: 0.9,
        holds: true,
        stiffest: Limit::UpTo(1e4),
        limit_omega_dt: Some(2.8),
    };
    let ghosts = [ghost("rk4", 1, 4, 0), ghost("reference", 3, 72, 5)];
    let list = lines(&ghosts, &[rk4_margin]);
    let row = |name: &str| {
        list.lines()
            .find(|line| line.trim_start().starts_with(name))
            .unwrap_or_else(|| panic!("{name} in\n{list}"))
            .to_owned()
    };
    assert!(row("rk4").contains("  100  4  "), "{list}");
    assert!(!row("rk4").contains('×'), "{list}");
    assert!(row("reference").contains("  100  3×72  "), "{list}");
    assert!(row("reference").ends_with("capped 5"), "{list}");
    assert!(!row("rk4").contains("capped"), "{list}");
    assert!(row("rk4").ends_with("k<1.0e4"), "{list}");
}

/// Read from the game: the step and its rate from the fixed clock, and the ghosts' list marks
/// the live box's own integrator, and only it, as live.
#[test]
fn the_clock_and_the_live_ghost_come_from_the_game() {
    let mut game = Game::stepping();
    game.update(1);
    let clock = game.line("Readouts Clock");
    assert!(clock.starts_with("step 10.00 ms (100 Hz)"), "{clock}");
    // The ghosts' card is in the dock only while they are on, and opens when they come on.
    use rubber_band_box::game::layout::{Card, CardRegistry, Cards};
    let offered = |game: &mut Game| {
        let world = game.world();
        let overlays = *world.resource::<rubber_band_box::game::shared::Overlays>();
        let mode = *world
            .resource::<State<rubber_band_box::game::shared::Mode>>()
            .get();
        (
            world
                .resource::<CardRegistry>()
                .offers(Card::GHOSTS, &overlays, mode),
            world.resource::<Cards>().is_open(Card::GHOSTS),
        )
    };
    assert_eq!(offered(&mut game), (false, false));
    game.tap_key(KeyCode::KeyG);
    game.update(2);
    assert_eq!(offered(&mut game), (true, true));
    let list = game.ghost_table();
    let live: Vec<&str> = list.lines().filter(|l| l.contains("(live)")).collect();
    assert_eq!(live.len(), 1, "{list}");
    assert!(live[0].trim_start().starts_with("auto (live)"), "{list}");
}

/// The history's edges: a sample at the latest one's time is not a clock going back; a sample
/// one spacing after the latest is kept, as is the oldest while it is no more than a span old.
#[test]
fn the_history_keeps_its_edges() {
    let spacing = EnergyHistory::SPAN / EnergyHistory::SAMPLES as f64;
    let mut history = EnergyHistory::default();
    history.record(5.0, Energies::default());
    history.record(6.0, Energies::default());
    history.record(6.0, Energies::default());
    assert_eq!(
        history.samples.len(),
        2,
        "the same time again is not time going back"
    );

    let mut history = EnergyHistory::default();
    history.record(0.0, Energies::default());
    history.record(spacing, Energies::default());
    assert_eq!(history.samples.len(), 2, "one spacing apart is kept");

    let mut history = EnergyHistory::default();
    history.record(0.0, Energies::default());
    history.record(EnergyHistory::SPAN, Energies::default());
    assert_eq!(
        history.samples.front().map(|s| s.0),
        Some(0.0),
        "a span old is kept"
    );
}

/// The window keeps the title it opened with, whatever the game does: Bevy hands AccessKit the
/// title as the window's name, so a screen reader would say every change of it as the window's
/// name (issue 61). What changes is the status line's and the hint's.
#[test]
fn nothing_writes_the_window_title() {
    let mut game = Game::stepping();
    let window = game.window;
    let title = |game: &mut Game| game.world().get::<Window>(window).unwrap().title.clone();
    let opened = title(&mut game);
    game.update(2);
    game.tap_key(key(Action::NextIntegrator));
    game.tap_key(key(Action::TogglePause));
    game.update(2);
    game.tap_key(key(Action::TogglePause));
    game.press_at(DVec2::new(200.0, 100.0));
    game.update(20);
    assert_eq!(title(&mut game), opened);
}

/// A game whose frames give the simulation less time than the wall clock (Bevy's virtual clock
/// caps each frame's time, as it does when a frame takes over 250 ms) says so on the status
/// line, with the rate it runs at; one that keeps up says nothing.
#[test]
fn the_status_line_says_when_the_game_falls_behind_the_wall_clock() {
    let mut game = Game::stepping();
    game.update(200);
    assert!(!game.line("HUD Status").contains("behind"));
    // Each 10 ms frame gives the simulation 4 ms.
    game.world()
        .resource_mut::<Time<Virtual>>()
        .set_max_delta(Duration::from_millis(4));
    game.update(500);
    let status = game.line("HUD Status");
    assert!(status.contains("behind: runs ×0.40"), "{status}");
    // Back to the wall clock's pace: it stops saying so within a few seconds.
    game.world()
        .resource_mut::<Time<Virtual>>()
        .set_max_delta(Duration::from_millis(250));
    game.update(500);
    let status = game.line("HUD Status");
    assert!(!status.contains("behind"), "{status}");
}

/// The step rate and the time scale read the same wherever they are written: the key(Action::ToggleDock)'s clock,
/// the status line and the panel's values (one formatter, `theme::hertz`
/// and `theme::times`; the panel once wrote 12.5 Hz as "12 Hz" and the clock "time x0.25").
#[test]
fn the_rate_and_the_time_scale_read_the_same_everywhere() {
    let mut game = Game::stepping();
    game.update(1);
    for key in [
        key(Action::FewerSteps),
        key(Action::FewerSteps),
        key(Action::FewerSteps),
        key(Action::Slower),
        key(Action::Slower),
    ] {
        game.tap_key(key);
        game.update(1);
    }
    game.update(2);
    for shown in [game.line("Readouts Clock"), game.line("HUD Status")] {
        assert!(
            shown.contains("12.5 Hz") && shown.contains("time ×0.25"),
            "{shown}"
        );
    }
    let world = game.world();
    let texts: Vec<String> = world
        .query::<&Text>()
        .iter(world)
        .map(|text| text.0.clone())
        .collect();
    assert!(texts.iter().any(|text| text == "12.5 Hz"), "{texts:?}");
    assert!(texts.iter().any(|text| text == "×0.25"), "{texts:?}");
}
