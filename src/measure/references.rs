//! The answers the report and the side-by-side with the peers measure against: the work
//! scenes with their converged solutions (a closed form where there is one, a fine RK4 run
//! where not), the stiff pulls with two tight, independent references each (Taylor series
//! and DOP853) and the horizon within which they can judge a state at all, and a recorded
//! game's reference (`report --replay`). A leaf over the
//! core: the report and the peers both use it, neither is used by it.

use bevy::math::DVec2;

use crate::physics::integrators::dop853;
use crate::physics::integrators::taylor::{self, TaylorSettings};
use crate::physics::{
    AutoSettings, BandEnds, BodyState, Integrator, MassProperties, Run, Scene, SceneParams,
};
use crate::replay::Replay;
use crate::replay::run::ReplayRun;

/// A scene of the work-precision sweep and how its reference is obtained.
pub struct WorkScene {
    pub scene: Scene,
    /// Simulated time; short for the chaotic stiff band.
    pub horizon: f64,
    /// Step of the fine RK4 reference (unused where the answer is exact).
    pub reference_step: f64,
    pub exact: Option<fn(f64) -> BodyState>,
    /// Report the energy drift (undamped scenes, where energy is an invariant).
    pub energy_invariant: bool,
}

/// Returns the converged answer of a work scene at time `t`.
pub fn work_reference(work: &WorkScene, t: f64) -> BodyState {
    match work.exact {
        Some(exact) => exact(t),
        None => reference_state(&work.scene, t, work.reference_step),
    }
}

pub fn work_scenes() -> Vec<WorkScene> {
    let named = |name: &str| Scene::named(name).expect("a built-in scene");
    vec![
        WorkScene {
            scene: named("diagonal"),
            horizon: 4.0,
            reference_step: 0.0,
            exact: Some(diagonal_exact),
            energy_invariant: false,
        },
        WorkScene {
            scene: named("tutorial"),
            horizon: 4.0,
            reference_step: 1e-5,
            exact: None,
            energy_invariant: false,
        },
        WorkScene {
            scene: named("stiff"),
            horizon: 0.1,
            reference_step: 1e-6,
            exact: None,
            energy_invariant: false,
        },
        WorkScene {
            scene: named("undamped"),
            horizon: 10.0,
            reference_step: 1e-5,
            exact: None,
            energy_invariant: true,
        },
    ]
}

/// Returns the diagonal pull's state at time `t`, in closed form.
///
/// The corner (30, 30) pulled toward (150, 150) moves the box along the diagonal as
/// m u'' + b u' + k u = 0 with u = x − 120, u(0) = −120, u'(0) = 0.
pub fn diagonal_exact(t: f64) -> BodyState {
    let p = SceneParams::tutorial();
    let equilibrium = 150.0 - 30.0;
    let u0 = -equilibrium;
    let gamma = p.linear_damping / (2.0 * p.mass);
    let omega_d = (p.stiffness / p.mass - gamma * gamma).sqrt();
    let (sin, cos) = (omega_d * t).sin_cos();
    let decay = (-gamma * t).exp();
    let u = decay * (u0 * cos + gamma * u0 / omega_d * sin);
    let du = decay * (-(gamma * gamma / omega_d + omega_d) * u0 * sin);
    let mut state = BodyState::at_rest(DVec2::splat(equilibrium + u));
    state.linear.velocity = DVec2::splat(du);
    state
}

/// Runs `scene` to time `t` with fine RK4 steps and returns the final state.
///
/// The number of steps is even, so that pulls at whole seconds fall on step boundaries.
pub fn reference_state(scene: &Scene, t: f64, step: f64) -> BodyState {
    let n = ((t / step).ceil() as u64).max(2).next_multiple_of(2);
    let mut run = Run::of(scene, Integrator::Rk4, t / n as f64).expect("valid scene");
    run.advance_by(n)
        .expect("the reference converges on every built-in scene");
    run.stepper.state
}

/// Returns how long after a stiff pull from rest two tight references still agree.
///
/// Until then they agree well enough to judge an integrator by its state: the stiffer the band,
/// the sooner its chaotic motion parts them (docs/report.md, "Horizons"; the report prints how far
/// its two references agree). None beyond k = 1e7, where no state can be compared and only
/// boundedness and energy can.
pub fn resolvable_horizon(k: f64) -> Option<f64> {
    if k <= 1e5 {
        Some(0.1)
    } else if k <= 1e6 {
        Some(0.05)
    } else if k <= 1e7 {
        Some(0.02)
    } else {
        None
    }
}

/// Simulated seconds of the undamped runs that judge a band too stiff for any horizon.
pub const UNRESOLVABLE_SECONDS: f64 = 10.0;

/// Two references for a resolvable case.
///
/// Where both agree, the report can judge errors down to their agreement.
#[derive(Clone, Copy, Debug)]
pub struct StiffReference {
    /// The tightest the core has: Taylor series of order 32 at a tolerance of 1e-15 px.
    pub state: BodyState,
    /// How far a second, independent method (DOP853 at 1e-13 px) ends from it.
    pub agreement: f64,
}

/// A candidate engine for `auto` with its setting, as the engine comparison runs it.
///
/// The comparison runs it inside each fixed step of a stiff pull, restarted at every fixed step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Engine {
    /// Classical RK4 with this many equal substeps per fixed step.
    Rk4(u32),
    /// DOP853 at this tolerance (px per substep).
    Dop853(f64),
    /// Taylor series of this order at this tolerance (px per step).
    Taylor(usize, f64),
}

impl Engine {
    pub const TIGHTEST_TAYLOR: Self = Self::Taylor(taylor::MAX_ORDER, 1e-15);
    pub const TIGHTEST_DOP853: Self = Self::Dop853(1e-13);

    pub fn name(&self) -> String {
        match *self {
            Self::Rk4(n) => format!("rk4 x{n}"),
            Self::Dop853(tolerance) => format!("dop853 {tolerance:.0e}"),
            Self::Taylor(order, tolerance) => format!("taylor {order} {tolerance:.0e}"),
        }
    }
}

/// Runs a stiff pull (one pull, held from the start) with `engine`.
///
/// Returns the final state and the force evaluations (Taylor: coefficient orders) per fixed
/// step; None if the engine gave up.
pub fn run_engine(
    scene: &Scene,
    rate: f64,
    ticks: u64,
    engine: Engine,
) -> Option<(BodyState, f64)> {
    let mass = scene.params.mass_properties().ok()?;
    let band = BandEnds::grabbing(&mass, &scene.initial, scene.pulls.first()?.2);
    let model = scene.params.force_model(mass, Some(band));
    let dt = 1.0 / rate;
    let mut state = scene.initial;
    let mut evaluations = 0.0;
    for _ in 0..ticks {
        match engine {
            Engine::Rk4(n) => {
                for _ in 0..n {
                    let start = model.forces(&state);
                    Integrator::Rk4.step(&mut state, &model, start, dt / f64::from(n));
                }
                evaluations += 4.0 * f64::from(n);
            }
            Engine::Dop853(tolerance) => {
                let done = dop853::integrate(
                    &state,
                    &model,
                    model.forces(&state),
                    dt,
                    tolerance,
                    u32::MAX,
                )?;
                state = done.state;
                evaluations += 1.0 + 12.0 * f64::from(done.attempts);
            }
            Engine::Taylor(order, tolerance) => {
                let settings = TaylorSettings {
                    order,
                    tolerance,
                    max_steps: u32::MAX,
                };
                let done = taylor::integrate(&state, &model, dt, &settings)?;
                state = done.state;
                evaluations += f64::from(done.orders);
            }
        }
    }
    state
        .is_finite()
        .then_some((state, evaluations / ticks as f64))
}

/// One point of the stiffness sweep: the stiff pull at band stiffness `k` and rate `rate`.
///
/// It is run to its resolvable horizon and compared there, or, beyond k = 1e7, run undamped
/// for [`UNRESOLVABLE_SECONDS`] and judged by boundedness and energy.
#[derive(Clone, Debug)]
pub struct StiffCase {
    pub k: f64,
    pub rate: f64,
    pub ticks: u64,
    pub scene: Scene,
    pub reference: Option<StiffReference>,
}

impl StiffCase {
    pub fn new(k: f64, rate: f64) -> Self {
        Self::moved(k, rate, DVec2::ZERO)
    }

    /// Returns the case with its pull's anchor moved by `offset` (px), its references its own.
    ///
    /// A stiff band's chaotic motion amplifies a change at the start many times by the horizon,
    /// so one anchor's error says little: the report judges `auto` over a few anchors a pixel
    /// apart. Beyond any horizon the anchor does not move.
    pub fn moved(k: f64, rate: f64, offset: DVec2) -> Self {
        let Some(horizon) = resolvable_horizon(k) else {
            let mut scene = Scene::named("undamped").expect("built-in");
            scene.params.stiffness = k;
            return Self {
                k,
                rate,
                ticks: (UNRESOLVABLE_SECONDS * rate).round() as u64,
                scene,
                reference: None,
            };
        };
        let mut scene = Scene::named("stiff").expect("built-in");
        scene.params.stiffness = k;
        for pull in &mut scene.pulls {
            pull.2 += offset;
        }
        let ticks = ((horizon * rate).round() as u64).max(1);
        let mass = scene.params.mass_properties().expect("valid");
        let taylor = run_engine(&scene, rate, ticks, Engine::TIGHTEST_TAYLOR)
            .expect("the tight reference converges");
        let dop853 = run_engine(&scene, rate, ticks, Engine::TIGHTEST_DOP853)
            .expect("the tight reference converges");
        Self {
            k,
            rate,
            ticks,
            reference: Some(StiffReference {
                state: taylor.0,
                agreement: taylor.0.pose_error(&dop853.0, &mass),
            }),
            scene,
        }
    }

    /// Returns the simulated seconds run.
    pub fn seconds(&self) -> f64 {
        self.ticks as f64 / self.rate
    }
}

/// Runs `replay` with `integrator` and returns the state after each recorded step.
///
/// `auto`'s settings are used if given, and each recorded step is split into `substeps` equal
/// steps with the same band. Returns every state and the seconds simulated, or the step where
/// the run left every bound.
pub fn replay_trajectory(
    replay: &Replay,
    integrator: Integrator,
    substeps: u32,
    auto: Option<AutoSettings>,
) -> Result<(Vec<BodyState>, f64), u64> {
    let mut run = ReplayRun::new(replay, Some(integrator))
        .expect("a replay read from a file is valid")
        .subdivided(substeps);
    if let Some(auto) = auto {
        run.stepper.auto = auto;
    }
    let mut states = Vec::with_capacity(replay.steps as usize);
    while run.advance().is_some() {
        if let Some(step) = run.refused {
            return Err(step);
        }
        states.push(run.stepper.state);
    }
    Ok((states, run.time))
}

/// A recorded game's converged answer.
///
/// It holds the state after each recorded step of the tightest Taylor series (order 32 at
/// 1e-15 px, no budget, so it never falls back) at the recorded rate, the seconds simulated,
/// and the box the corner distance is measured on.
pub struct ReplayReference {
    pub states: Vec<BodyState>,
    pub seconds: f64,
    pub mass: MassProperties,
}

impl ReplayReference {
    pub fn of(replay: &Replay) -> Self {
        let tightest = AutoSettings {
            tolerance: 1e-15,
            order: 24,
            max_substeps: u32::MAX,
        };
        let (states, seconds) = replay_trajectory(replay, Integrator::Auto, 1, Some(tightest))
            .expect("the tightest series never leaves the bounds");
        let mass = replay
            .header
            .settings
            .params()
            .mass_properties()
            .expect("a replay read from a file is valid");
        Self {
            states,
            seconds,
            mass,
        }
    }

    /// Returns the largest corner distance of `states` from the reference's over the game.
    ///
    /// `states` holds a state after each recorded step.
    pub fn largest_error(&self, states: &[BodyState]) -> f64 {
        states
            .iter()
            .zip(&self.states)
            .map(|(state, reference)| state.pose_error(reference, &self.mass))
            .fold(0.0, f64::max)
    }
}
