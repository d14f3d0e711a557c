//! The integrators: one table of methods over the same f64 state and force laws.
//!
//! Every method takes the forces already summed at the start of the step (the ECS
//! accumulator, or [`ForceModel::forces`]) and evaluates the [`ForceModel`] again where it
//! needs forces at other states. Damping never limits the step or lowers the order: the
//! explicit methods fold it into the force (it is far from stiff at any step the game uses),
//! `verlet` treats it with the trapezoidal rule, `implicit` solves for it exactly, and `seed`
//! does what the tutorial does.

use std::fmt;
use std::str::FromStr;

use bevy::math::{DMat3, DVec2, DVec3};
use bevy::prelude::Resource;

use super::auto::{AutoSettings, StepInfo, auto_step};
use super::body::{AngularState, BodyState, LinearState, MassProperties};
use super::forces::{ForceModel, Forces, Wrench};

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
    /// Backward Euler, solved by minimising the step's incremental potential with Newton's
    /// method: stable for any stiffness and step, and it damps the stiff band's ringing.
    Implicit,
    /// Exactly the tutorial's per-frame update, in its order, in per-second units.
    Seed,
    /// Error-controlled Taylor-series steps within each step, within a budget; `implicit`
    /// where the budget binds (see [`super::auto`]). The game's default.
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

    /// Order of accuracy of the global error.
    pub fn order(self) -> u32 {
        match self {
            Self::Verlet => 2,
            Self::Rk4 => 4,
            Self::Auto => 20,
            _ => 1,
        }
    }

    /// The next integrator in [`Self::ALL`], wrapping round (the game's switch).
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

    /// [`Self::step`] with `auto`'s settings given.
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
                return auto_step(state, model, dt, auto, backward_euler);
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

/// Linear and angular acceleration: a = F/m, α = τ/I (steps 2 and 4 of the total reaction).
fn accelerations(wrench: Wrench, mass: &MassProperties) -> (DVec2, f64) {
    (
        wrench.force * mass.inverse_mass(),
        wrench.torque * mass.inverse_inertia(),
    )
}

/// Forward Euler: the position moves with the old velocity.
pub fn euler(state: &mut BodyState, mass: &MassProperties, total: Wrench, dt: f64) {
    let (acceleration, angular_acceleration) = accelerations(total, mass);
    state.linear.position += state.linear.velocity * dt;
    state.angular.orientation += state.angular.angular_velocity * dt;
    state.linear.velocity += acceleration * dt;
    state.angular.angular_velocity += angular_acceleration * dt;
}

/// The tutorial's total reaction (section 4.4), steps 2 to 5, given the summed force and
/// torque of steps 1 and 3: a = F/m, α = τ/I, then semi-implicit (symplectic) Euler: the
/// velocities first, then the position and orientation from the new velocities.
pub fn symplectic_euler(state: &mut BodyState, mass: &MassProperties, total: Wrench, dt: f64) {
    let (acceleration, angular_acceleration) = accelerations(total, mass);
    state.linear.velocity += acceleration * dt;
    state.angular.angular_velocity += angular_acceleration * dt;
    state.linear.position += state.linear.velocity * dt;
    state.angular.orientation += state.angular.angular_velocity * dt;
}

/// Velocity Verlet. The closing half-kick takes the damping at the new velocity, which is
/// solvable in closed form because damping is linear: over the step the damping term is the
/// trapezoidal rule, so the method stays second order and damping never limits the step.
fn velocity_verlet(state: &mut BodyState, model: &ForceModel, start: Forces, dt: f64) {
    let half = 0.5 * dt;
    let (linear_rate, angular_rate) = model.damping_rates();
    let (a0, alpha0) = accelerations(start.total(), &model.mass);
    let v_half = state.linear.velocity + a0 * half;
    let omega_half = state.angular.angular_velocity + alpha0 * half;
    state.linear.position += v_half * dt;
    state.angular.orientation += omega_half * dt;
    let (a1, alpha1) = accelerations(model.applied(state), &model.mass);
    state.linear.velocity = (v_half + a1 * half) / (1.0 + half * linear_rate);
    state.angular.angular_velocity = (omega_half + alpha1 * half) / (1.0 + half * angular_rate);
}

/// The time derivative of the state.
#[derive(Clone, Copy)]
struct Rate {
    velocity: DVec2,
    angular_velocity: f64,
    acceleration: DVec2,
    angular_acceleration: f64,
}

impl Rate {
    fn of(state: &BodyState, total: Wrench, mass: &MassProperties) -> Self {
        let (acceleration, angular_acceleration) = accelerations(total, mass);
        Self {
            velocity: state.linear.velocity,
            angular_velocity: state.angular.angular_velocity,
            acceleration,
            angular_acceleration,
        }
    }
}

fn advanced(state: &BodyState, rate: &Rate, dt: f64) -> BodyState {
    BodyState {
        linear: LinearState {
            position: state.linear.position + rate.velocity * dt,
            velocity: state.linear.velocity + rate.acceleration * dt,
        },
        angular: AngularState {
            orientation: state.angular.orientation + rate.angular_velocity * dt,
            angular_velocity: state.angular.angular_velocity + rate.angular_acceleration * dt,
        },
    }
}

/// Classical Runge-Kutta; damping is part of the force at every stage. Returns the energy
/// damping took out, integrated with the same stages (so to the same fourth order).
fn runge_kutta_4(state: &mut BodyState, model: &ForceModel, start: Forces, dt: f64) -> f64 {
    let rate_at = |s: &BodyState| Rate::of(s, model.forces(s).total(), &model.mass);
    let k1 = Rate::of(state, start.total(), &model.mass);
    let k2 = rate_at(&advanced(state, &k1, 0.5 * dt));
    let k3 = rate_at(&advanced(state, &k2, 0.5 * dt));
    let k4 = rate_at(&advanced(state, &k3, dt));
    let sixth = dt / 6.0;
    let combine = |a: f64, b: f64, c: f64, d: f64| (a + 2.0 * b + 2.0 * c + d) * sixth;
    let combine2 = |a: DVec2, b: DVec2, c: DVec2, d: DVec2| (a + 2.0 * b + 2.0 * c + d) * sixth;
    state.linear.position += combine2(k1.velocity, k2.velocity, k3.velocity, k4.velocity);
    state.linear.velocity += combine2(
        k1.acceleration,
        k2.acceleration,
        k3.acceleration,
        k4.acceleration,
    );
    state.angular.orientation += combine(
        k1.angular_velocity,
        k2.angular_velocity,
        k3.angular_velocity,
        k4.angular_velocity,
    );
    state.angular.angular_velocity += combine(
        k1.angular_acceleration,
        k2.angular_acceleration,
        k3.angular_acceleration,
        k4.angular_acceleration,
    );
    let power = |k: &Rate| model.damping_power(k.velocity, k.angular_velocity);
    combine(power(&k1), power(&k2), power(&k3), power(&k4))
}

/// Backward Euler: q₁ = q₀ + h v₁, v₁ = v₀ + h (F(q₁)/M − r v₁), for the configuration
/// q = (x, y, θ), mass matrix M = diag(m, m, I) and damping rates r = (b/m, b/m, c).
///
/// Eliminating v₁ leaves the stationarity condition of the incremental potential
/// E(q) = ½ (q − q̃)ᵀ W (q − q̃) + h² V(q), with q̃ = q₀ + h v₀ / (1 + h r), W = M (1 + h r),
/// and V the band's potential. E is bounded below and grows quadratically, so Newton's method
/// with a positive definite (Gauss-Newton) Hessian and a backtracking line search always
/// reaches a finite minimiser: the step is stable whatever k and h are. Being L-stable, it
/// damps the stiff band's oscillation instead of leaving it ringing (as the implicit midpoint
/// rule would); the price is first order. Returns the force-law evaluations it made (one per
/// Newton iteration and one per energy the line search tried).
fn backward_euler(state: &mut BodyState, model: &ForceModel, dt: f64) -> u32 {
    let (linear_rate, angular_rate) = model.damping_rates();
    let mass = &model.mass;
    let decay = DVec3::new(
        1.0 + dt * linear_rate,
        1.0 + dt * linear_rate,
        1.0 + dt * angular_rate,
    );
    let weight = DVec3::new(mass.mass(), mass.mass(), mass.inertia()) * decay;
    let q0 = configuration(state);
    let v0 = generalized_velocity(state);
    let predicted = q0 + v0 * dt / decay;
    let h2 = dt * dt;
    let mut evaluations = 1;

    let solved = match model.band {
        None => predicted,
        Some(band) => {
            let k = model.stiffness;
            // corner − anchor, and ∂corner/∂θ, at configuration q.
            let stretch_at = |q: DVec3| {
                let arm = super::body::rotate(band.local_point, q.z);
                (q.truncate() + arm - band.anchor, arm)
            };
            let energy = |q: DVec3| {
                let d = q - predicted;
                let (stretch, _) = stretch_at(q);
                0.5 * (d * weight).dot(d) + h2 * 0.5 * k * stretch.length_squared()
            };
            let mut q = predicted;
            let mut e = energy(q);
            for _ in 0..MAX_NEWTON_ITERATIONS {
                evaluations += 1;
                let (stretch, arm) = stretch_at(q);
                let lever = arm.perp();
                let jacobian_t_stretch = DVec3::new(stretch.x, stretch.y, lever.dot(stretch));
                let gradient = weight * (q - predicted) + h2 * k * jacobian_t_stretch;
                // Gauss-Newton Hessian W + h² k JᵀJ, plus the curvature of the corner's arc
                // where that keeps it positive definite.
                let curvature = (-stretch.dot(arm)).max(0.0);
                let hessian = DMat3::from_diagonal(weight)
                    + h2 * k
                        * DMat3::from_cols(
                            DVec3::new(1.0, 0.0, lever.x),
                            DVec3::new(0.0, 1.0, lever.y),
                            DVec3::new(lever.x, lever.y, lever.length_squared() + curvature),
                        );
                let direction = -(hessian.inverse() * gradient);
                let slope = gradient.dot(direction);
                if slope.is_nan() || slope >= 0.0 {
                    break; // at the minimiser to round-off
                }
                let mut length = 1.0;
                let mut accepted = false;
                for _ in 0..MAX_LINE_SEARCH_HALVINGS {
                    let candidate = q + direction * length;
                    evaluations += 1;
                    let candidate_energy = energy(candidate);
                    if candidate_energy <= e + 1e-4 * length * slope {
                        q = candidate;
                        e = candidate_energy;
                        accepted = true;
                        break;
                    }
                    length *= 0.5;
                }
                let converged = (direction * length).abs().max_element()
                    <= NEWTON_TOLERANCE * (1.0 + q.abs().max_element());
                if !accepted || converged {
                    break;
                }
            }
            q
        }
    };

    let v1 = (solved - q0) / dt;
    state.linear.position = solved.truncate();
    state.angular.orientation = solved.z;
    state.linear.velocity = v1.truncate();
    state.angular.angular_velocity = v1.z;
    evaluations
}

const MAX_NEWTON_ITERATIONS: usize = 50;
const MAX_LINE_SEARCH_HALVINGS: usize = 60;
const NEWTON_TOLERANCE: f64 = 1e-15;

fn configuration(state: &BodyState) -> DVec3 {
    state.linear.position.extend(state.angular.orientation)
}

fn generalized_velocity(state: &BodyState) -> DVec3 {
    state.linear.velocity.extend(state.angular.angular_velocity)
}

/// The tutorial's update (its section 5 and appendix), in its order, at a step of `dt`
/// instead of one frame: the angular damping scales ω by exp(−c·dt) (0.98 at 0.01 s); the
/// drag from the current velocity and the band's force and torque from the current position
/// and orientation are summed (`start`); then ω, θ, v, x in that order, each from the one
/// just updated. Its acceleration is the sum of each force divided by m, as the tutorial's
/// `addForce` scales each force before summing.
fn tutorial_update(state: &mut BodyState, model: &ForceModel, start: Forces, dt: f64) {
    let mass = &model.mass;
    state.angular.angular_velocity *= (-model.angular_damping * dt).exp();
    let acceleration =
        start.applied.force * mass.inverse_mass() + start.damping.force * mass.inverse_mass();
    let angular_acceleration = start.applied.torque / mass.inertia();
    state.angular.angular_velocity += angular_acceleration * dt;
    state.angular.orientation += state.angular.angular_velocity * dt;
    state.linear.velocity += acceleration * dt;
    state.linear.position += state.linear.velocity * dt;
}
