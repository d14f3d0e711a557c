//! The side-by-side measurement: every contender on the same scripted drags, in one process,
//! each tick a full headless `App` update on the single-threaded executor.

use std::time::Instant;

use super::avian::Avian;
use super::ours::Ours;
use super::rapier::Rapier;
use super::{Contender, PeerRun};
use crate::physics::{BodyState, Scenario};
use crate::report::{WorkScene, pose_error, stiff_scenario, work_reference, work_scenes};

/// The contenders' names, ours first (the ratios are to ours).
pub const NAMES: [&str; 3] = [Ours::NAME, Avian::NAME, Rapier::NAME];

/// The rates of the comparison: the tutorial's and a common display-locked one.
pub const RATES: [f64; 2] = [64.0, 100.0];

/// One contender on one scene at one rate.
#[derive(Clone, Debug)]
pub struct PeerPoint {
    pub contender: &'static str,
    pub scene: &'static str,
    pub rate: f64,
    pub steps: u64,
    /// Final pose error against the report's reference (px); None if the state went
    /// non-finite.
    pub error: Option<f64>,
    /// Largest |E − E0| / E0 over the run, on scenes where energy is an invariant.
    pub energy_drift: Option<f64>,
    /// Median wall time of one `App` update (one fixed step), in ns.
    pub ns_per_tick: f64,
}

/// A scripted run's accuracy: final state and, if asked, the largest relative energy drift.
fn accuracy<C: Contender>(scenario: &Scenario, rate: f64, steps: u64) -> (BodyState, f64) {
    let mut run = PeerRun::<C>::of(scenario, rate);
    let energy = |run: &mut PeerRun<C>| {
        let state = run.state();
        scenario
            .params
            .force_model(run.mass, run.band)
            .energy(&state)
    };
    let e0 = energy(&mut run);
    let mut drift: f64 = 0.0;
    for _ in 0..steps {
        run.advance();
        drift = drift.max((energy(&mut run) - e0).abs() / e0);
    }
    (run.state(), drift)
}

/// Ticks run before timing: the engines build their own structures on the first ones.
const WARM_UP_TICKS: u64 = 2;
/// Ticks timed at least, so that a short scene still gives a stable figure.
const TIMED_TICKS: u64 = 100;

/// Median over `reps` fresh runs of the time per tick (after a warm-up; building the `App`
/// is not timed). The run goes on past the scene's horizon if it is shorter than
/// [`TIMED_TICKS`].
fn ns_per_tick<C: Contender>(scenario: &Scenario, rate: f64, steps: u64, reps: usize) -> f64 {
    let ticks = steps.max(TIMED_TICKS);
    let mut times: Vec<f64> = (0..reps)
        .map(|_| {
            let mut run = PeerRun::<C>::of(scenario, rate);
            run.advance_by(WARM_UP_TICKS);
            let start = Instant::now();
            run.advance_by(ticks);
            std::hint::black_box(run.state());
            start.elapsed().as_nanos() as f64 / ticks as f64
        })
        .collect();
    times.sort_by(f64::total_cmp);
    times[times.len() / 2]
}

fn point<C: Contender>(
    scene: &WorkScene,
    rate: f64,
    reference: &BodyState,
    reps: usize,
) -> PeerPoint {
    let scenario = &scene.scenario;
    let steps = (scene.horizon * rate).round() as u64;
    let (state, drift) = accuracy::<C>(scenario, rate, steps);
    let mass = scenario.params.mass_properties().expect("valid");
    PeerPoint {
        contender: C::NAME,
        scene: scenario.name,
        rate,
        steps,
        error: state
            .is_finite()
            .then(|| pose_error(&state, reference, &mass)),
        energy_drift: scene.energy_invariant.then_some(drift),
        ns_per_tick: ns_per_tick::<C>(scenario, rate, steps, reps),
    }
}

/// Every contender on every scene of the work-precision sweep, at 64 and 100 Hz.
pub fn side_by_side(quick: bool) -> Vec<PeerPoint> {
    let reps = if quick { 1 } else { 5 };
    let mut points = Vec::new();
    for scene in work_scenes() {
        for rate in RATES {
            let steps = (scene.horizon * rate).round() as u64;
            let reference = work_reference(&scene, steps as f64 / rate);
            points.push(point::<Ours>(&scene, rate, &reference, reps));
            points.push(point::<Avian>(&scene, rate, &reference, reps));
            points.push(point::<Rapier>(&scene, rate, &reference, reps));
        }
    }
    points
}

/// One contender at one band stiffness: ten ticks of the stiff scene.
#[derive(Clone, Debug)]
pub struct PeerStiffPoint {
    pub contender: &'static str,
    pub k: f64,
    pub rate: f64,
    pub ns_per_tick: f64,
    pub error: Option<f64>,
}

fn stiff_point<C: Contender>(k: f64, rate: f64, ticks: u64, reps: usize) -> PeerStiffPoint {
    let (scenario, reference) = stiff_scenario(k, rate, ticks);
    let (state, _) = accuracy::<C>(&scenario, rate, ticks);
    let mass = scenario.params.mass_properties().expect("valid");
    PeerStiffPoint {
        contender: C::NAME,
        k,
        rate,
        ns_per_tick: ns_per_tick::<C>(&scenario, rate, ticks, reps),
        error: state
            .is_finite()
            .then(|| pose_error(&state, &reference, &mass)),
    }
}

/// The contenders across the stiffness sweep, at the sweep's `ks` and rates.
pub fn stiffness(ks: &[f64], rates: &[f64], ticks: u64, quick: bool) -> Vec<PeerStiffPoint> {
    let reps = if quick { 1 } else { 5 };
    let mut points = Vec::new();
    for &rate in rates {
        for &k in ks {
            points.push(stiff_point::<Ours>(k, rate, ticks, reps));
            points.push(stiff_point::<Avian>(k, rate, ticks, reps));
            points.push(stiff_point::<Rapier>(k, rate, ticks, reps));
        }
    }
    points
}
