//! The side-by-side (`report --peers`, compiled with the `peers` feature): our plugin, avian2d
//! and bevy_rapier2d, each in a headless `App`, on the work scenes and on the stiffness
//! sweep's cases. `run` makes its tables (`peers.csv`, `peers_stiffness.csv`) and draws its
//! contenders' lines in both plots. The measuring is `crate::measure::peers::measure`'s.

use plotters::prelude::*;

use crate::measure::peers::measure::{self, NAMES};
use crate::measure::references::{StiffCase, work_scenes};

use super::plots::{ExtraLines, Line};
use super::stiffness::{case_cells, horizon_cells};
use super::table::{Cell, Column, Table, or_empty};

/// Returns the targets of `auto` beside the peers at band stiffness k.
///
/// They are the largest error at the horizon (None beyond any horizon: bounded, and no energy
/// growth undamped instead) and the largest ratio of our tick to the fastest peer's. None below
/// k = 1e3 (the tutorial scene's own target is in the side-by-side table).
fn stiff_target(k: f64) -> Option<(Option<f64>, f64)> {
    if k < 1e3 {
        None
    } else if k <= 1e6 {
        Some((Some(1e-5), 1.0))
    } else if k <= 1e7 {
        Some((Some(1e-4), 2.0))
    } else {
        Some((None, 2.0))
    }
}

/// Returns a contender's colour in the plots.
///
/// The colours are dark, unlike the integrators' palette: black for ours, brown and grey for the
/// peers.
fn colour(name: &str) -> RGBAColor {
    let index = NAMES.iter().position(|&n| n == name).unwrap_or(0);
    [
        RGBColor(0, 0, 0),
        RGBColor(150, 80, 20),
        RGBColor(120, 120, 120),
    ][index]
        .to_rgba()
}

/// Builds a contender's line in a plot: triangles, its whole `App` tick.
fn line(name: &str, points: Vec<(f64, f64)>) -> Line {
    Line {
        label: format!("{name} (App tick)"),
        colour: colour(name),
        triangles: true,
        points,
    }
}

/// Builds the side-by-side's two tables, and the contenders' lines for the two plots.
pub(super) fn section(cases: &[StiffCase], quick: bool) -> (Vec<Table>, ExtraLines) {
    let (work_table, work) = work_scenes_side_by_side(quick);
    let (stiffness_table, stiffness) = stiffness_side_by_side(cases, quick);
    (
        vec![work_table, stiffness_table],
        ExtraLines { work, stiffness },
    )
}

/// Tabulates every contender on the work scenes at 64 and 100 Hz, a line each.
///
/// The table gives the ratios to ours, then notes how an empty `App` ticks.
fn work_scenes_side_by_side(quick: bool) -> (Table, Vec<(&'static str, Line)>) {
    let short = |value: Option<f64>| value.map_or("-".to_owned(), |v| format!("{v:.1e}"));
    let points = measure::side_by_side(quick);
    let mut table = Table::new(
        "Side by side with avian2d and bevy_rapier2d: a headless `App` per contender, one \
         fixed step per update, single-threaded executor (error in px; ratios to ours; the \
         contenders timed interleaved in rounds, the tick ratio the median of the rounds' \
         ratios with their interquartile range)",
        Some("peers.csv"),
        vec![
            Column::new("scene", "scene"),
            Column::new("rate", "rate_hz"),
            Column::new("contender", "contender"),
            Column::csv("steps"),
            Column::new("error", "error_px"),
            Column::new("energy drift", "energy_drift"),
            Column::new("ns per tick", "ns_per_tick"),
            Column::markdown("error / ours"),
            Column::new("tick / ours", "tick_over_ours"),
            Column::csv("tick_over_ours_q1"),
            Column::csv("tick_over_ours_q3"),
        ],
    );
    for chunk in points.chunk_by(|a, b| a.scene == b.scene && a.rate == b.rate) {
        let ours = &chunk[0];
        for p in chunk {
            let error_ratio = p.error.zip(ours.error).map(|(a, b)| a / b);
            table.row(vec![
                Cell::same(p.scene),
                Cell::new(format!("{} Hz", p.rate), p.rate.to_string()),
                Cell::same(p.contender),
                Cell::csv(p.steps),
                Cell::new(
                    p.error
                        .map_or("non-finite".to_owned(), |e| format!("{e:.1e}")),
                    or_empty(p.error),
                ),
                Cell::new(short(p.energy_drift), or_empty(p.energy_drift)),
                Cell::new(format!("{:.0}", p.ns_per_tick), p.ns_per_tick.to_string()),
                Cell::markdown(short(error_ratio)),
                Cell::new(
                    p.tick_over_ours.describe(),
                    p.tick_over_ours.median.to_string(),
                ),
                Cell::csv(p.tick_over_ours.q1),
                Cell::csv(p.tick_over_ours.q3),
            ]);
        }
    }
    for rate in measure::RATES {
        let (empty, ratio) = measure::tutorial_over_empty_app(rate, quick);
        table.note(format!(
            "At {rate} Hz an empty `App` (the same plugins and clock, no physics, driven \
             through the same calls as every contender) ticks in {empty:.0} ns: our \
             tutorial-scene tick is {} times that (median and interquartile range of the ratio \
             over rounds timed interleaved).",
            ratio.describe()
        ));
    }
    let mut lines = Vec::new();
    for work in work_scenes() {
        let scene = work.scene.name;
        for name in NAMES {
            let points = points
                .iter()
                .filter(|p| p.scene == scene && p.contender == name)
                .filter_map(|p| p.error.map(|e| (e.max(1e-16), p.ns_per_tick * p.rate)))
                .collect();
            lines.push((scene, line(name, points)));
        }
    }
    (table, lines)
}

/// Tabulates every contender on the stiffness sweep's cases, a line per case.
///
/// The table gives our tick over the fastest peer's and the targets; the CSV has a row per
/// case and contender.
fn stiffness_side_by_side(cases: &[StiffCase], quick: bool) -> (Table, [Vec<Line>; 2]) {
    let stiff = measure::stiffness(cases, quick);
    let mut table = Table::new(
        "Stiffness sweep, side by side: the cases of the stiffness sweep (error in px at \
         the horizon, or beyond k = 1e7 the largest energy growth undamped / ns per App tick), \
         our tick over the fastest peer's, and the targets (error at most 1e-5 px and a tick \
         at most the fastest peer's to k = 1e6; 1e-4 px and twice at 1e7; beyond, bounded, no \
         energy growth, and twice)",
        Some("peers_stiffness.csv"),
        vec![
            Column::new("k", "k"),
            Column::new("rate", "rate_hz"),
            Column::csv("contender"),
            Column::csv("ns_per_tick"),
            Column::csv("error_px"),
            Column::new("horizon (s)", "horizon_s"),
            Column::new("refs agree (px)", "references_agree_px"),
            Column::csv("energy_growth"),
            Column::csv("bounded"),
            Column::markdown("{}").each(),
            Column::new("tick / fastest peer", "ours_over_fastest_peer"),
            Column::csv("ours_over_fastest_peer_q1"),
            Column::csv("ours_over_fastest_peer_q3"),
            Column::markdown("target"),
        ],
    )
    .across(2);
    for (case, chunk) in cases
        .iter()
        .zip(stiff.chunk_by(|a, b| a.k == b.k && a.rate == b.rate))
    {
        let ours = &chunk[0];
        let spread = ours.ours_over_fastest_peer;
        let ratio = spread.median;
        let target = match stiff_target(case.k) {
            None => "-",
            Some((error, tick)) => {
                let accurate = match error {
                    Some(bound) => ours.error.is_some_and(|e| e <= bound),
                    None => ours.bounded && ours.energy_growth.is_some_and(|g| g <= 0.0),
                };
                match (accurate, ratio <= tick) {
                    (true, true) => "met",
                    (false, true) => "not met: error",
                    (true, false) => "not met: tick",
                    (false, false) => "not met: error and tick",
                }
            }
        };
        for p in chunk {
            let outcome = match (p.error, p.energy_growth) {
                _ if !p.bounded => "non-finite".to_owned(),
                (Some(e), _) => format!("{e:.1e}"),
                (None, Some(g)) => format!("dE {g:+.0e}"),
                _ => "?".to_owned(),
            };
            let [k, rate] = case_cells(p.k, p.rate);
            let [horizon, agreement] = horizon_cells(case);
            table.row(vec![
                k,
                rate,
                Cell::same(p.contender),
                Cell::csv(p.ns_per_tick),
                Cell::csv_option(p.error),
                horizon,
                agreement,
                Cell::csv_option(p.energy_growth),
                Cell::csv(p.bounded),
                Cell::markdown(format!("{outcome} / {:.0}", p.ns_per_tick)),
                Cell::new(spread.describe(), ratio.to_string()),
                Cell::csv(spread.q1),
                Cell::csv(spread.q3),
                Cell::markdown(target),
            ]);
        }
    }
    let stiff_line = |name: &str, value: fn(&measure::PeerStiffPoint) -> Option<f64>| {
        let points = stiff
            .iter()
            .filter(|p| p.contender == name && p.rate == 100.0)
            .filter_map(|p| value(p).map(|v| (p.k, v)))
            .collect();
        line(name, points)
    };
    let cost = NAMES
        .iter()
        .map(|name| stiff_line(name, |p| Some(p.ns_per_tick)))
        .collect();
    let error = NAMES
        .iter()
        .map(|name| stiff_line(name, |p| p.error.map(|e| e.max(1e-14))))
        .collect();
    (table, [cost, error])
}

/// Tabulates the contenders on the recorded hand, for `report --replay FILE --peers`.
///
/// They run at the recorded rate and finer, against the replay sweep's reference
/// (`peers_replay.csv`).
pub(super) fn replay_table(
    recorded: &crate::replay::Replay,
    reference: &crate::measure::references::ReplayReference,
    quick: bool,
) -> Table {
    let points = crate::measure::peers::replay::sweep(
        recorded,
        super::replay::subdivisions(quick),
        reference,
        quick,
    );
    let mut table = Table::new(
        "Replay side by side: each contender's whole App on the recorded hand (largest corner \
         error over the game in px, against the replay table's reference; ns per simulated \
         second, building the App again at each settings change included)",
        Some("peers_replay.csv"),
        vec![
            Column::new("steps per recorded step", "substeps"),
            Column::csv("contender"),
            Column::csv("error_px"),
            Column::csv("ns_per_simulated_second"),
            Column::markdown("{}").each(),
        ],
    )
    .across(1);
    for p in &points {
        let outcome = match p.error {
            Some(error) => format!("{error:.1e} / {:.0}", p.ns_per_simulated_second),
            None => "diverged".to_owned(),
        };
        table.row(vec![
            Cell::same(p.substeps),
            Cell::same(p.contender),
            Cell::csv_option(p.error),
            Cell::csv(p.ns_per_simulated_second),
            Cell::markdown(outcome),
        ]);
    }
    table
}
