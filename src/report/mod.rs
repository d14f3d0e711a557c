//! The speed-against-error report: a work-precision sweep, a stability table and the hard
//! cases, for every integrator, measured in one process.
//!
//! Errors are final-pose errors: the largest distance between where a corner of the box is
//! and where the reference says it should be (px). Costs are nanoseconds of this machine per
//! simulated second (the median of repeated runs of the core alone, no `App`).

use std::error::Error;
use std::fmt::Write as _;
use std::fs;
use std::path::PathBuf;
use std::time::Instant;

use clap::Args;

use crate::physics::scenario::TUTORIAL_PULL_TARGET;
use crate::physics::{Integrator, Run, Scenario, angular_momentum_about};
use crate::references::{Engine, StiffCase, UNRESOLVABLE_SECONDS, run_engine};
use crate::timing::median_ns;

mod hard_cases;
mod plots;
mod stability;
mod table;
mod work_precision;

pub use hard_cases::{HardCase, hard_cases};
pub use plots::{ExtraLines, Line};
use plots::{plot_stiffness, plot_work_precision};
pub use stability::{STIFFEST_TRIED, StabilityRow};
pub use work_precision::WorkPoint;

#[derive(Args, Debug)]
pub struct ReportArgs {
    /// Where to write the CSV files and the plot.
    #[arg(long, default_value = "target/report")]
    pub out: PathBuf,
    /// A reduced sweep that runs in well under a minute (CI's smoke test).
    #[arg(long)]
    pub quick: bool,
    /// Also run avian2d and bevy_rapier2d side by side with our plugin (needs a build with
    /// `--features peers`).
    #[arg(long)]
    pub peers: bool,
}

/// What `report --peers` says in a build without the peers compiled in.
pub const NO_PEERS: &str = "this build has no peers: run it as \
`cargo run --release --features peers -- report --peers`";

/// The engine comparison: each candidate at several settings on the stiff pulls at 100 Hz,
/// error at the horizon against the reference, cost per fixed step of the core alone.
pub struct EnginePoint {
    pub k: f64,
    pub engine: Engine,
    pub error: Option<f64>,
    pub ns_per_tick: f64,
    pub evaluations_per_tick: f64,
}

fn engines_compared(cases: &[StiffCase], quick: bool) -> Vec<EnginePoint> {
    let engines: Vec<Engine> = if quick {
        vec![
            Engine::Rk4(100),
            Engine::Dop853(1e-9),
            Engine::Taylor(20, 1e-9),
        ]
    } else {
        let mut all: Vec<Engine> = [25, 100, 400, 1600].map(Engine::Rk4).to_vec();
        all.extend([1e-8, 1e-9, 1e-10, 1e-11].map(Engine::Dop853));
        for order in [12, 16, 20, 24] {
            all.extend([1e-8, 1e-9, 3e-10, 1e-10].map(|t| Engine::Taylor(order, t)));
        }
        all
    };
    let mut points = Vec::new();
    for case in cases.iter().filter(|c| c.rate == 100.0 && c.k >= 1e3) {
        let Some(reference) = case.reference else {
            continue;
        };
        let mass = case.scenario.params.mass_properties().expect("valid");
        for &engine in &engines {
            let outcome = run_engine(&case.scenario, case.rate, case.ticks, engine);
            let ns = median_ns(if quick { 1 } else { 5 }, || {
                std::hint::black_box(run_engine(&case.scenario, case.rate, case.ticks, engine));
            });
            points.push(EnginePoint {
                k: case.k,
                engine,
                error: outcome.map(|(state, _)| state.pose_error(&reference.state, &mass)),
                ns_per_tick: ns / case.ticks as f64,
                evaluations_per_tick: outcome.map_or(0.0, |o| o.1),
            });
        }
    }
    points
}

/// One integrator on one [`StiffCase`].
#[derive(Clone, Debug)]
pub struct StiffPoint {
    pub k: f64,
    pub rate: f64,
    pub integrator: Integrator,
    pub ns_per_tick: f64,
    /// Pose error at the horizon against the RK4 reference; None if diverged or beyond any
    /// horizon.
    pub error: Option<f64>,
    /// Beyond any horizon: the largest (E − E0) / E0 of the undamped run (positive: it grew).
    pub energy_growth: Option<f64>,
    pub diverged_at: Option<u64>,
    pub mean_substeps: f64,
    pub mean_evaluations: f64,
    pub fallbacks: u64,
}

/// The k swept, 20 to 1e12.
pub fn ks_swept(quick: bool) -> &'static [f64] {
    if quick {
        &[20.0, 1e5, 1e9]
    } else {
        &[20.0, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e12]
    }
}

/// The rates of the stiffness sweep.
pub const SWEEP_RATES: [f64; 2] = [100.0, 64.0];

/// Every case of the stiffness sweep, references computed once.
pub fn stiff_cases(quick: bool) -> Vec<StiffCase> {
    SWEEP_RATES
        .iter()
        .flat_map(|&rate| {
            ks_swept(quick)
                .iter()
                .map(move |&k| StiffCase::new(k, rate))
        })
        .collect()
}

fn stiffness_sweep(cases: &[StiffCase], quick: bool) -> Vec<StiffPoint> {
    let mut points = Vec::new();
    for case in cases {
        let scenario = &case.scenario;
        let mass = scenario.params.mass_properties().expect("valid");
        let dt = 1.0 / case.rate;
        for integrator in Integrator::ALL {
            let fresh = || Run::of(scenario, integrator, dt).expect("valid");
            let mut run = fresh();
            let e0 = run.stepper.energy();
            let (mut substeps, mut evaluations) = (0u64, 0u64);
            let mut growth = f64::NEG_INFINITY;
            let mut outcome = Ok(());
            for _ in 0..case.ticks {
                outcome = run.advance();
                if outcome.is_err() {
                    break;
                }
                substeps += u64::from(run.last_step.substeps);
                evaluations += u64::from(run.last_step.evaluations);
                growth = growth.max((run.stepper.energy() - e0) / e0);
            }
            let diverged_at = outcome.err().map(|d| d.step);
            let ns = median_ns(if quick { 3 } else { 15 }, || {
                let mut run = fresh();
                let _ = std::hint::black_box(run.advance_by(case.ticks));
            });
            let steps = run.step.max(1) as f64;
            points.push(StiffPoint {
                k: case.k,
                rate: case.rate,
                integrator,
                ns_per_tick: ns / case.ticks as f64,
                error: case
                    .reference
                    .filter(|_| diverged_at.is_none())
                    .map(|r| run.stepper.state.pose_error(&r.state, &mass)),
                energy_growth: (case.reference.is_none() && diverged_at.is_none())
                    .then_some(growth),
                diverged_at,
                mean_substeps: substeps as f64 / steps,
                mean_evaluations: evaluations as f64 / steps,
                fallbacks: run.fallbacks,
            });
        }
    }
    points
}

/// The undamped stiff band (k = 1e5, 100 Hz, 10 s): the largest energy error relative to the
/// energy the band put in, and the largest change of the angular momentum about the anchor.
/// Largest energy error and angular momentum change, or the step where the run diverged.
type InvariantDrift = Result<(f64, f64), u64>;

fn stiff_invariants(quick: bool) -> Vec<(Integrator, InvariantDrift)> {
    let mut scenario = Scenario::named("undamped").expect("built-in");
    scenario.params.stiffness = 1e5;
    let steps = if quick { 100 } else { 1000 };
    Integrator::ALL
        .iter()
        .map(|&integrator| {
            let mut run = Run::of(&scenario, integrator, 0.01).expect("valid");
            let mass = run.stepper.mass;
            let e0 = run.stepper.energy();
            let l0 = angular_momentum_about(&run.stepper.state, &mass, TUTORIAL_PULL_TARGET);
            let (mut energy, mut momentum) = (0.0_f64, 0.0_f64);
            for _ in 0..steps {
                if let Err(d) = run.advance() {
                    return (integrator, Err(d.step));
                }
                energy = energy.max((run.stepper.energy() - e0).abs() / e0);
                let l = angular_momentum_about(&run.stepper.state, &mass, TUTORIAL_PULL_TARGET);
                momentum = momentum.max((l - l0).abs());
            }
            (integrator, Ok((energy, momentum)))
        })
        .collect()
}

/// An optional CSV field: empty when absent.
fn optional(value: Option<impl ToString>) -> String {
    value.map_or(String::new(), |v| v.to_string())
}

/// The largest |ledger residual| over a run, relative to the energy that passed through, or
/// the step where the run diverged.
fn ledger_residual(scenario: &Scenario, integrator: Integrator, steps: u64) -> Result<f64, u64> {
    let mut run = Run::of(scenario, integrator, 0.01).expect("valid");
    let mut worst: f64 = 0.0;
    for _ in 0..steps {
        run.advance().map_err(|d| d.step)?;
        worst = worst.max(run.ledger.residual(run.stepper.energy()).abs());
    }
    Ok(worst / run.ledger.throughput())
}

/// A markdown table's head: two leading columns, then one per integrator.
fn table_head(table: &mut String, first: [&str; 2], names: &[&str]) -> std::fmt::Result {
    writeln!(
        table,
        "| {} | {} | {} |",
        first[0],
        first[1],
        names.join(" | ")
    )?;
    writeln!(table, "|---|---|{}", "---|".repeat(names.len()))
}

/// The heads of a stiffness table after k and the rate: the horizon, the references'
/// agreement, then the integrators or engines.
fn stiff_head<'a>(names: &[&'a str]) -> Vec<&'a str> {
    let mut head = vec!["horizon (s)", "refs agree (px)"];
    head.extend_from_slice(names);
    head
}

/// The horizon and reference cells of a stiffness row.
fn horizon_cells(case: &StiffCase) -> Vec<String> {
    match case.reference {
        Some(r) => vec![
            format!("{}", case.seconds()),
            format!("{:.0e}", r.agreement),
        ],
        None => vec![format!("{} undamped", case.seconds()), "-".to_owned()],
    }
}

/// A row of a stiffness table: k, the rate, a cell per integrator or engine.
fn stiffness_row(table: &mut String, k: f64, rate: f64, cells: &[String]) -> std::fmt::Result {
    writeln!(table, "| {k:e} | {rate} Hz | {} |", cells.join(" | "))
}

pub fn run(args: &ReportArgs) -> Result<(), Box<dyn Error>> {
    if args.peers && !cfg!(feature = "peers") {
        return Err(NO_PEERS.into());
    }
    fs::create_dir_all(&args.out)?;
    let started = Instant::now();
    let names: Vec<&str> = Integrator::ALL.iter().map(|i| i.name()).collect();

    let points = work_precision::sweep(args.quick);
    let mut table = String::new();
    for section in [
        work_precision::table(&points),
        stability::table(),
        hard_cases::table(args.quick),
    ] {
        if !table.is_empty() {
            table.push('\n');
        }
        table += &section.markdown();
        if let Some(file) = section.file() {
            fs::write(args.out.join(file), section.csv())?;
        }
    }

    let cases = stiff_cases(args.quick);
    let sweep = stiffness_sweep(&cases, args.quick);
    writeln!(
        table,
        "\n## Stiffness sweep: stiff pulls from rest, each k judged at the horizon its \
         references resolve (error in px against the RK4 reference / ns per step; auto: mean \
         substeps and force evaluations per step, fall-backs). Beyond k = 1e7 no horizon \
         resolves a state: undamped for {UNRESOLVABLE_SECONDS} s, bounded or not, and the \
         largest energy growth (E - E0) / E0\n"
    )?;
    table_head(&mut table, ["k", "rate"], &stiff_head(&names))?;
    let mut csv = String::from(
        "k,rate_hz,horizon_s,references_agree_px,integrator,ns_per_tick,error_px,energy_growth,\
         diverged_at_step,mean_substeps,mean_evaluations,fallbacks\n",
    );
    for (case, chunk) in cases
        .iter()
        .zip(sweep.chunk_by(|a, b| a.k == b.k && a.rate == b.rate))
    {
        let mut cells = horizon_cells(case);
        cells.extend(chunk.iter().map(|p| {
            let auto = if p.integrator == Integrator::Auto {
                format!(
                    " ({:.0}, {:.0}, {})",
                    p.mean_substeps, p.mean_evaluations, p.fallbacks
                )
            } else {
                String::new()
            };
            match (p.error, p.energy_growth, p.diverged_at) {
                (Some(e), _, _) => format!("{e:.1e} / {:.0}{auto}", p.ns_per_tick),
                (None, Some(g), _) => format!("dE {g:+.0e} / {:.0}{auto}", p.ns_per_tick),
                (_, _, Some(s)) => format!("diverged @{s}"),
                _ => "?".to_owned(),
            }
        }));
        stiffness_row(&mut table, case.k, case.rate, &cells)?;
        for p in chunk {
            writeln!(
                csv,
                "{},{},{},{},{},{},{},{},{},{},{},{}",
                p.k,
                p.rate,
                case.seconds(),
                optional(case.reference.map(|r| r.agreement)),
                p.integrator,
                p.ns_per_tick,
                optional(p.error),
                optional(p.energy_growth),
                optional(p.diverged_at),
                p.mean_substeps,
                p.mean_evaluations,
                p.fallbacks
            )?;
        }
    }
    fs::write(args.out.join("stiffness.csv"), csv)?;

    writeln!(
        table,
        "\n## Engines for auto: candidates on the stiff pulls at 100 Hz, restarted every fixed \
         step (error in px at the horizon against the reference; ns per fixed step of the core \
         alone; force evaluations per fixed step, for Taylor series coefficient orders)\n"
    )?;
    writeln!(table, "| k | engine | error | ns per step | evaluations |")?;
    writeln!(table, "|---|---|---|---|---|")?;
    let mut csv = String::from("k,engine,error_px,ns_per_tick,evaluations_per_tick\n");
    for p in engines_compared(&cases, args.quick) {
        let error = p.error.map_or("gave up".to_owned(), |e| format!("{e:.1e}"));
        writeln!(
            table,
            "| {:e} | {} | {error} | {:.0} | {:.0} |",
            p.k,
            p.engine.name(),
            p.ns_per_tick,
            p.evaluations_per_tick
        )?;
        writeln!(
            csv,
            "{},{},{},{},{}",
            p.k,
            p.engine.name(),
            optional(p.error),
            p.ns_per_tick,
            p.evaluations_per_tick
        )?;
    }
    fs::write(args.out.join("engines.csv"), csv)?;

    writeln!(
        table,
        "\n## Undamped stiff band (k = 1e5, 100 Hz, 10 s): largest energy error relative to \
         the energy put in, and largest change of angular momentum about the anchor\n"
    )?;
    writeln!(table, "| integrator | energy | angular momentum |")?;
    writeln!(table, "|---|---|---|")?;
    for (integrator, outcome) in stiff_invariants(args.quick) {
        match outcome {
            Ok((energy, momentum)) => {
                writeln!(table, "| {integrator} | {energy:.1e} | {momentum:.1e} |")?
            }
            Err(step) => writeln!(table, "| {integrator} | diverged @{step} | |")?,
        }
    }

    writeln!(
        table,
        "\n## Energy ledger at 100 Hz: largest |residual| relative to the energy that passed \
         through (seed: 4 s; stiff, k = 1e5 with damping: 10 s)\n"
    )?;
    writeln!(table, "| integrator | seed | stiff |")?;
    writeln!(table, "|---|---|---|")?;
    let seed = Scenario::named("tutorial").expect("built-in");
    let stiff = Scenario::named("stiff").expect("built-in");
    let steps = if args.quick { 100 } else { 1000 };
    for integrator in Integrator::ALL {
        let cell = |outcome: Result<f64, u64>| match outcome {
            Ok(residual) => format!("{residual:.1e}"),
            Err(step) => format!("diverged @{step}"),
        };
        writeln!(
            table,
            "| {integrator} | {} | {} |",
            cell(ledger_residual(&seed, integrator, 400)),
            cell(ledger_residual(&stiff, integrator, steps))
        )?;
    }

    #[cfg(feature = "peers")]
    let extra = if args.peers {
        peers_section(&mut table, args, &cases)?
    } else {
        ExtraLines::default()
    };
    #[cfg(not(feature = "peers"))]
    let extra = ExtraLines::default();
    plot_work_precision(&points, extra.work, &args.out.join("work_precision.svg"))?;
    plot_stiffness(&sweep, extra.stiffness, &args.out.join("stiffness.svg"))?;
    writeln!(
        table,
        "\nWritten to {} in {:.1} s.",
        args.out.display(),
        started.elapsed().as_secs_f64()
    )?;
    fs::write(args.out.join("report.md"), &table)?;
    print!("{table}");
    Ok(())
}

/// The targets of `auto` beside the peers at band stiffness k: the largest error at the
/// horizon (None beyond any horizon: bounded, and no energy growth undamped instead) and the
/// largest ratio of our tick to the fastest peer's. None below k = 1e3 (the seed scene's
/// own target is in the side-by-side table).
#[cfg(feature = "peers")]
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

/// The peers beside our own plugin, each in a headless `App`: the tables, `peers.csv` and
/// `peers_stiffness.csv`, and the peers' lines for the two plots.
#[cfg(feature = "peers")]
fn peers_section(
    table: &mut String,
    args: &ReportArgs,
    cases: &[StiffCase],
) -> Result<ExtraLines, Box<dyn Error>> {
    use crate::peers::measure::{self, NAMES};
    use plotters::prelude::*;
    // Dark, unlike the integrators' palette: black for ours, brown and grey for the peers.
    let colour = |name: &str| {
        let index = NAMES.iter().position(|&n| n == name).unwrap_or(0);
        [
            RGBColor(0, 0, 0),
            RGBColor(150, 80, 20),
            RGBColor(120, 120, 120),
        ][index]
            .to_rgba()
    };
    let label = |name: &str| format!("{name} (App tick)");
    let short = |value: Option<f64>| value.map_or("-".to_owned(), |v| format!("{v:.1e}"));

    let points = measure::side_by_side(args.quick);
    writeln!(
        table,
        "\n## Side by side with avian2d and bevy_rapier2d: a headless `App` per engine, one \
         fixed step per update, single-threaded executor (error in px; ratios to ours)\n"
    )?;
    writeln!(
        table,
        "| scene | rate | engine | error | energy drift | ns per tick | error / ours | tick / ours |"
    )?;
    writeln!(table, "|---|---|---|---|---|---|---|---|")?;
    let mut csv = String::from("scene,rate_hz,engine,steps,error_px,energy_drift,ns_per_tick\n");
    for chunk in points.chunk_by(|a, b| a.scene == b.scene && a.rate == b.rate) {
        let ours = &chunk[0];
        for p in chunk {
            let error_ratio = p.error.zip(ours.error).map(|(a, b)| a / b);
            writeln!(
                table,
                "| {} | {} Hz | {} | {} | {} | {:.0} | {} | {:.2} |",
                p.scene,
                p.rate,
                p.contender,
                p.error
                    .map_or("non-finite".to_owned(), |e| format!("{e:.1e}")),
                short(p.energy_drift),
                p.ns_per_tick,
                short(error_ratio),
                p.ns_per_tick / ours.ns_per_tick
            )?;
            writeln!(
                csv,
                "{},{},{},{},{},{},{}",
                p.scene,
                p.rate,
                p.contender,
                p.steps,
                optional(p.error),
                optional(p.energy_drift),
                p.ns_per_tick
            )?;
        }
    }
    fs::write(args.out.join("peers.csv"), csv)?;
    writeln!(table)?;
    for rate in measure::RATES {
        let empty = measure::empty_app_ns_per_tick(rate, args.quick);
        let seed = points
            .iter()
            .find(|p| p.scene == "tutorial" && p.rate == rate && p.contender == NAMES[0]);
        if let Some(seed) = seed {
            writeln!(
                table,
                "At {rate} Hz an empty `App` (the same plugins and clock, no physics) ticks in \
                 {empty:.0} ns: our seed-scene tick is {:.2} times that.",
                seed.ns_per_tick / empty
            )?;
        }
    }
    let mut work_lines = Vec::new();
    for scene in work_scenes() {
        let scene = scene.scenario.name;
        for name in NAMES {
            let line = points
                .iter()
                .filter(|p| p.scene == scene && p.contender == name)
                .filter_map(|p| p.error.map(|e| (e.max(1e-16), p.ns_per_tick * p.rate)))
                .collect();
            work_lines.push((
                scene,
                Line {
                    label: label(name),
                    colour: colour(name),
                    triangles: true,
                    points: line,
                },
            ));
        }
    }

    let stiff = measure::stiffness(cases, args.quick);
    writeln!(
        table,
        "\n## Stiffness sweep, side by side: the cases of the stiffness sweep (error in px at \
         the horizon, or beyond k = 1e7 the largest energy growth undamped / ns per App tick), \
         our tick over the fastest peer's, and the targets (error at most 1e-5 px and a tick \
         at most the fastest peer's to k = 1e6; 1e-4 px and twice at 1e7; beyond, bounded, no \
         energy growth, and twice)\n"
    )?;
    let mut head = stiff_head(&NAMES);
    head.extend(["tick / fastest peer", "target"]);
    table_head(table, ["k", "rate"], &head)?;
    let mut csv = String::from(
        "k,rate_hz,engine,ns_per_tick,error_px,horizon_s,references_agree_px,energy_growth,bounded\n",
    );
    for (case, chunk) in cases
        .iter()
        .zip(stiff.chunk_by(|a, b| a.k == b.k && a.rate == b.rate))
    {
        let mut cells = horizon_cells(case);
        cells.extend(chunk.iter().map(|p| {
            let outcome = match (p.error, p.energy_growth) {
                _ if !p.bounded => "non-finite".to_owned(),
                (Some(e), _) => format!("{e:.1e}"),
                (None, Some(g)) => format!("dE {g:+.0e}"),
                _ => "?".to_owned(),
            };
            format!("{outcome} / {:.0}", p.ns_per_tick)
        }));
        let ours = &chunk[0];
        let fastest_peer = chunk[1..]
            .iter()
            .map(|p| p.ns_per_tick)
            .fold(f64::INFINITY, f64::min);
        let ratio = ours.ns_per_tick / fastest_peer;
        cells.push(format!("{ratio:.2}"));
        cells.push(match stiff_target(case.k) {
            None => "-".to_owned(),
            Some((error, tick)) => {
                let accurate = match error {
                    Some(bound) => ours.error.is_some_and(|e| e <= bound),
                    None => ours.bounded && ours.energy_growth.is_some_and(|g| g <= 0.0),
                };
                match (accurate, ratio <= tick) {
                    (true, true) => "met".to_owned(),
                    (false, true) => "not met: error".to_owned(),
                    (true, false) => "not met: tick".to_owned(),
                    (false, false) => "not met: error and tick".to_owned(),
                }
            }
        });
        stiffness_row(table, case.k, case.rate, &cells)?;
        for p in chunk {
            writeln!(
                csv,
                "{},{},{},{},{},{},{},{},{}",
                p.k,
                p.rate,
                p.contender,
                p.ns_per_tick,
                optional(p.error),
                case.seconds(),
                optional(case.reference.map(|r| r.agreement)),
                optional(p.energy_growth),
                p.bounded
            )?;
        }
    }
    fs::write(args.out.join("peers_stiffness.csv"), csv)?;
    let stiff_line = |name: &str, value: fn(&measure::PeerStiffPoint) -> Option<f64>| Line {
        label: label(name),
        colour: colour(name),
        triangles: true,
        points: stiff
            .iter()
            .filter(|p| p.contender == name && p.rate == 100.0)
            .filter_map(|p| value(p).map(|v| (p.k, v)))
            .collect(),
    };
    let cost = NAMES
        .iter()
        .map(|name| stiff_line(name, |p| Some(p.ns_per_tick)))
        .collect();
    let error = NAMES
        .iter()
        .map(|name| stiff_line(name, |p| p.error.map(|e| e.max(1e-14))))
        .collect();
    Ok(ExtraLines {
        work: work_lines,
        stiffness: [cost, error],
    })
}
