//! The integrators: one table of methods over the same f64 state and force laws.
//!
//! Every method takes the forces already summed at the start of the step (the ECS
//! accumulator, or [`ForceModel::forces`]) and evaluates the [`ForceModel`] again where it
//! needs forces at other states. Damping never limits the step or lowers the order: the
//! explicit methods fold it into the force (it is far from stiff at any step the game uses),
//! `verlet` treats it with the trapezoidal rule, `implicit` takes it implicitly (a first-order
//! decay, v₁ = v₀ − h·r·v₁), `auto` integrates it in its series, and `seed` does what the
//! tutorial does.

use std::fmt;
use std::str::FromStr;

use bevy::prelude::Resource;

pub mod auto;
pub mod dop853;
pub mod engine_state;
pub mod explicit;
pub mod implicit;
mod lanes;
pub mod seed;
pub mod step_info;
pub mod taylor;

pub use auto::AutoSettings;
pub use explicit::symplectic_euler;
pub use step_info::StepInfo;

use super::body::BodyState;
use super::forces::{ForceModel, Forces};
use auto::auto_step;
use explicit::{euler, runge_kutta_4, velocity_verlet};
use implicit::backward_euler;
use seed::tutorial_update;

#[derive(Resource, Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Integrator {
    /// Explicit (forward) Euler: the textbook baseline; gains energy at every step.
    Euler,
    /// Semi-implicit (symplectic) Euler: velocities first, then positions from them.
    Symplectic,
    /// Velocity Verlet: second order, symplectic; damping by the trapezoidal rule.
    Verlet,
    /// Classical fourth-order Runge-Kutta.
    Rk4,
    /// Backward Euler, solved by minimising the step's incremental potential with Newton's method.
    ///
    /// It is stable for any stiffness and step, and it damps the stiff band's ringing.
    Implicit,
    /// Exactly the tutorial's per-frame update, in its order, in per-second units.
    Seed,
    /// Error-controlled Taylor-series steps within each step, within a budget.
    ///
    /// It falls back to `implicit` where the budget binds (see [`mod@auto`]). The game's
    /// default.
    #[default]
    Auto,
}

impl Integrator {
    pub const ALL: [Self; 7] = [
        Self::Euler,
        Self::Symplectic,
        Self::Verlet,
        Self::Rk4,
        Self::Implicit,
        Self::Seed,
        Self::Auto,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Self::Euler => "euler",
            Self::Symplectic => "symplectic",
            Self::Verlet => "verlet",
            Self::Rk4 => "rk4",
            Self::Implicit => "implicit",
            Self::Seed => "seed",
            Self::Auto => "auto",
        }
    }

    /// Returns the integrator's colour (sRGB), from one table for every figure.
    ///
    /// The table serves the game's ghosts, table and plot, and the report's charts. Its colours
    /// read on the game's dark background and the report's white one.
    pub fn colour(self) -> [u8; 3] {
        match self {
            Self::Euler => [225, 87, 89],
            Self::Symplectic => [242, 142, 43],
            Self::Verlet => [222, 186, 40],
            Self::Rk4 => [89, 161, 79],
            Self::Implicit => [78, 159, 214],
            Self::Seed => [176, 122, 161],
            Self::Auto => [255, 111, 176],
        }
    }

    /// Returns the order of accuracy of the global error.
    pub fn order(self) -> u32 {
        match self {
            Self::Verlet => 2,
            Self::Rk4 => 4,
            Self::Auto => auto::DEFAULT_ORDER as u32,
            _ => 1,
        }
    }

    /// Returns the next integrator in [`Self::ALL`], wrapping round (the game's switch).
    pub fn next(self) -> Self {
        let index = Self::ALL.iter().position(|&i| i == self).unwrap_or(0);
        Self::ALL[(index + 1) % Self::ALL.len()]
    }

    /// Advances `state` by `dt`; `start` holds the forces summed at `state`.
    pub fn step(
        self,
        state: &mut BodyState,
        model: &ForceModel,
        start: Forces,
        dt: f64,
    ) -> StepInfo {
        self.step_with(state, model, start, dt, &AutoSettings::default())
    }

    /// Advances `state` as [`Self::step`] does, with `auto`'s settings given.
    pub fn step_with(
        self,
        state: &mut BodyState,
        model: &ForceModel,
        start: Forces,
        dt: f64,
        auto: &AutoSettings,
    ) -> StepInfo {
        let before = *state;
        let evaluations = match self {
            Self::Euler => {
                euler(state, &model.mass, start.total(), dt);
                1
            }
            Self::Symplectic => {
                symplectic_euler(state, &model.mass, start.total(), dt);
                1
            }
            Self::Verlet => {
                velocity_verlet(state, model, start, dt);
                2
            }
            Self::Rk4 => {
                let dissipated = runge_kutta_4(state, model, start, dt);
                return StepInfo {
                    dissipated,
                    evaluations: 4,
                    ..StepInfo::SINGLE
                };
            }
            Self::Implicit => backward_euler(state, model, dt),
            Self::Seed => {
                tutorial_update(state, model, start, dt);
                1
            }
            Self::Auto => {
                return auto_step(state, model, dt, auto);
            }
        };
        StepInfo {
            dissipated: model.dissipated_by_trapezoid(&before, state, dt),
            evaluations,
            ..StepInfo::SINGLE
        }
    }
}

impl fmt::Display for Integrator {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Integrator {
    type Err = UnknownIntegrator;
    fn from_str(name: &str) -> Result<Self, Self::Err> {
        Self::ALL
            .into_iter()
            .find(|i| i.name() == name)
            .ok_or_else(|| UnknownIntegrator(name.to_owned()))
    }
}

#[derive(Clone, Debug, PartialEq, Eq)]
pub struct UnknownIntegrator(pub String);

impl fmt::Display for UnknownIntegrator {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let names: Vec<_> = Integrator::ALL.iter().map(|i| i.name()).collect();
        write!(
            f,
            "unknown integrator '{}' (expected one of: {})",
            self.0,
            names.join(", ")
        )
    }
}

impl std::error::Error for UnknownIntegrator {}
