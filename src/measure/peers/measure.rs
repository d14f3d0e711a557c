//! The side-by-side measurement: every contender on the same scripted pulls, in one process,
//! each tick a full headless `App` update on the single-threaded executor.
//!
//! The contenders are timed interleaved, in rounds (ours, avian2d, bevy_rapier2d, then ours
//! again...), each round on fresh state, and a ratio is taken within each round: whatever
//! slows the machine for a while slows every contender of a round alike, so the median of the
//! rounds' ratios holds still where the ratio of separately timed medians moved by up to 2x
//! from one run to the next (docs/peers.md).

use std::time::{Duration, Instant};

use super::avian::Avian;
use super::empty::Empty;
use super::ours::Ours;
use super::rapier::Rapier;
use super::{Contender, PeerRun};
use crate::measure::references::{StiffCase, WorkScene, work_reference, work_scenes};
use crate::measure::timing::{Spread, median};
use crate::physics::{BodyState, Scene};

/// The contenders' names, ours first (the ratios are to ours).
pub const NAMES: [&str; 3] = [Ours::NAME, Avian::NAME, Rapier::NAME];

/// The rates of the comparison: Bevy's default fixed rate and the tutorial's.
pub const RATES: [f64; 2] = [64.0, 100.0];

/// Returns how many interleaved rounds to time.
///
/// The medians and the spread of the ratios are over these rounds.
fn rounds(quick: bool) -> usize {
    if quick { 1 } else { 21 }
}

/// One contender on one scene at one rate.
#[derive(Clone, Debug)]
pub struct PeerPoint {
    pub contender: &'static str,
    pub scene: &'static str,
    pub rate: f64,
    pub steps: u64,
    /// Final pose error against the report's reference (px); None if the state went non-finite.
    pub error: Option<f64>,
    /// Largest |E − E0| / E0 over the run, on scenes where energy is an invariant.
    pub energy_drift: Option<f64>,
    /// Wall time of one `App` update (one fixed step), in ns.
    ///
    /// The median over rounds of the mean over the scored ticks but the first.
    pub ns_per_tick: f64,
    /// This contender's tick over ours, round by round (1 for ours).
    pub tick_over_ours: Spread,
}

/// How a scripted run ended.
///
/// Its final state, the largest relative change of the energy, and its largest relative
/// growth (both None when the run starts with no energy to compare with).
struct Accuracy {
    state: BodyState,
    drift: Option<f64>,
    growth: Option<f64>,
}

fn accuracy<C: Contender>(scene: &Scene, rate: f64, steps: u64) -> Accuracy {
    let mut run = PeerRun::<C>::of(scene, rate);
    let energy = |run: &mut PeerRun<C>| {
        let state = run.state();
        scene.params.force_model(run.mass, run.band).energy(&state)
    };
    let e0 = energy(&mut run);
    let mut drift: f64 = 0.0;
    let mut growth = f64::NEG_INFINITY;
    for _ in 0..steps {
        run.advance();
        let change = energy(&mut run) - e0;
        drift = drift.max(change.abs());
        growth = growth.max(change);
    }
    let relative = |v: f64| (e0 > 0.0).then_some(v / e0);
    Accuracy {
        state: run.state(),
        drift: relative(drift),
        growth: relative(growth),
    }
}

/// Ticks timed at least per repetition.
///
/// A short scene is run again from the start until this many of its ticks have been timed.
const TIMED_TICKS: u64 = 100;

/// Times one round of contender `C` and returns its time per tick.
///
/// The time is over `timed` ticks of fresh runs after each run's first tick, where every
/// contender builds its own structures (how long: docs/peers.md): a game pays that once, not
/// every tick. The `App`'s construction is untimed.
fn round_ns<C: Contender>(scene: &Scene, rate: f64, timed: u64) -> f64 {
    let runs = TIMED_TICKS.div_ceil(timed);
    let mut total = Duration::ZERO;
    for _ in 0..runs {
        let mut run = PeerRun::<C>::of(scene, rate);
        run.advance();
        let start = Instant::now();
        run.advance_by(timed);
        total += start.elapsed();
        std::hint::black_box(run.state());
    }
    total.as_nanos() as f64 / (runs * timed) as f64
}

/// Returns each contender's time per tick in each of `rounds` interleaved rounds, ours first.
///
/// Before the rounds, one untimed run of each contender warms caches and allocators.
fn interleaved(scene: &Scene, rate: f64, timed: u64, rounds: usize) -> Vec<[f64; 3]> {
    let timed = timed.max(1);
    let timers: [fn(&Scene, f64, u64) -> f64; 3] =
        [round_ns::<Ours>, round_ns::<Avian>, round_ns::<Rapier>];
    for timer in timers {
        timer(scene, rate, timed);
    }
    (0..rounds)
        .map(|_| timers.map(|timer| timer(scene, rate, timed)))
        .collect()
}

/// Returns the median time per tick of contender `index` over the rounds.
fn median_of(rounds: &[[f64; 3]], index: usize) -> f64 {
    median(rounds.iter().map(|round| round[index]).collect())
}

/// Returns `scene` with every pull one fixed step later.
///
/// The box rests through the first tick (the contenders' set-up, untimed), so that the ticks
/// timed are exactly those of the original run.
fn one_tick_later(scene: &Scene, rate: f64) -> Scene {
    let mut later = scene.clone();
    for pull in &mut later.pulls {
        pull.0 += 1.0 / rate;
        pull.1 += 1.0 / rate;
    }
    later
}

fn point<C: Contender>(
    work: &WorkScene,
    rate: f64,
    reference: &BodyState,
    rounds: &[[f64; 3]],
    index: usize,
) -> PeerPoint {
    let scene = &work.scene;
    let steps = (work.horizon * rate).round() as u64;
    let Accuracy { state, drift, .. } = accuracy::<C>(scene, rate, steps);
    let mass = scene.params.mass_properties().expect("valid");
    PeerPoint {
        contender: C::NAME,
        scene: scene.name,
        rate,
        steps,
        error: state
            .is_finite()
            .then(|| state.pose_error(reference, &mass)),
        energy_drift: drift.filter(|_| work.energy_invariant),
        ns_per_tick: median_of(rounds, index),
        tick_over_ours: Spread::of(rounds.iter().map(|r| r[index] / r[0]).collect()),
    }
}

/// Measures every contender on every scene of the work-precision sweep, at 64 and 100 Hz.
pub fn side_by_side(quick: bool) -> Vec<PeerPoint> {
    let rounds = rounds(quick);
    let mut points = Vec::new();
    for work in work_scenes() {
        for rate in RATES {
            let steps = (work.horizon * rate).round() as u64;
            let reference = work_reference(&work, steps as f64 / rate);
            let times = interleaved(&work.scene, rate, steps.saturating_sub(1), rounds);
            points.push(point::<Ours>(&work, rate, &reference, &times, 0));
            points.push(point::<Avian>(&work, rate, &reference, &times, 1));
            points.push(point::<Rapier>(&work, rate, &reference, &times, 2));
        }
    }
    points
}

/// One contender on one case of the stiffness sweep.
#[derive(Clone, Debug)]
pub struct PeerStiffPoint {
    pub contender: &'static str,
    pub k: f64,
    pub rate: f64,
    pub ns_per_tick: f64,
    /// At the case's horizon, against its reference; None if non-finite or beyond any horizon.
    pub error: Option<f64>,
    /// Beyond any horizon: the largest (E − E0) / E0 of the undamped run; None if non-finite.
    pub energy_growth: Option<f64>,
    /// Whether every state of the run stayed finite.
    pub bounded: bool,
    /// Our tick over the faster peer's in the same round, round by round.
    ///
    /// The same for every contender of a case.
    pub ours_over_fastest_peer: Spread,
}

fn stiff_point<C: Contender>(
    case: &StiffCase,
    rounds: &[[f64; 3]],
    index: usize,
    ours_over_fastest_peer: Spread,
) -> PeerStiffPoint {
    let Accuracy { state, growth, .. } = accuracy::<C>(&case.scene, case.rate, case.ticks);
    let mass = case.scene.params.mass_properties().expect("valid");
    let bounded = state.is_finite() && growth.is_none_or(f64::is_finite);
    PeerStiffPoint {
        contender: C::NAME,
        k: case.k,
        rate: case.rate,
        ns_per_tick: median_of(rounds, index),
        error: case
            .reference
            .filter(|_| bounded)
            .map(|r| state.pose_error(&r.state, &mass)),
        energy_growth: growth.filter(|_| case.reference.is_none() && bounded),
        bounded,
        ours_over_fastest_peer,
    }
}

/// Measures the contenders across the stiffness sweep's cases.
pub fn stiffness(cases: &[StiffCase], quick: bool) -> Vec<PeerStiffPoint> {
    let rounds = rounds(quick);
    cases
        .iter()
        .flat_map(|case| {
            // Short horizons (one or two ticks at k = 1e7) leave no tick to time after the
            // first: time the case's own ticks one tick later instead.
            let later = one_tick_later(&case.scene, case.rate);
            let times = interleaved(&later, case.rate, case.ticks, rounds);
            let ratio = Spread::of(times.iter().map(|r| r[0] / r[1].min(r[2])).collect());
            [
                stiff_point::<Ours>(case, &times, 0, ratio),
                stiff_point::<Avian>(case, &times, 1, ratio),
                stiff_point::<Rapier>(case, &times, 2, ratio),
            ]
        })
        .collect()
}

/// Measures our plugin's own cost: the tutorial scene's tick against an empty `App`'s.
///
/// The two are timed interleaved, in rounds. Returns the empty `App`'s median tick and the
/// ratio's spread.
pub fn tutorial_over_empty_app(rate: f64, quick: bool) -> (f64, Spread) {
    // The work scene's tutorial: its pull and release, ticks timed as in the side-by-side.
    let work = work_scenes()
        .into_iter()
        .find(|work| work.scene.name == "tutorial")
        .expect("the tutorial is a work scene");
    let timed = ((work.horizon * rate).round() as u64)
        .saturating_sub(1)
        .max(1);
    // Both through the same call: a scripted run's step, state read and pull check.
    let tick = || round_ns::<Ours>(&work.scene, rate, timed);
    let empty = || round_ns::<Empty>(&work.scene, rate, timed);
    tick();
    empty();
    let rounds: Vec<[f64; 2]> = (0..rounds(quick)).map(|_| [empty(), tick()]).collect();
    (
        median(rounds.iter().map(|r| r[0]).collect()),
        Spread::of(rounds.iter().map(|r| r[1] / r[0]).collect()),
    )
}
