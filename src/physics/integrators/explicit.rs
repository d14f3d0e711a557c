//! The explicit methods: forward Euler, the tutorial's symplectic Euler, velocity Verlet and
//! classical Runge-Kutta. Each takes the forces summed at the start of the step and evaluates
//! the force laws again where it needs them.

use bevy::math::DVec2;

use crate::physics::body::{AngularState, BodyState, LinearState, MassProperties};
use crate::physics::forces::{ForceModel, Forces, Wrench};

/// Returns the linear and angular accelerations: a = F/m, α = τ/I.
///
/// These are steps 2 and 4 of the total reaction.
fn accelerations(wrench: Wrench, mass: &MassProperties) -> (DVec2, f64) {
    (
        wrench.force * mass.inverse_mass(),
        wrench.torque * mass.inverse_inertia(),
    )
}

/// Advances `state` by `dt` with forward Euler: the position moves with the old velocity.
pub fn euler(state: &mut BodyState, mass: &MassProperties, total: Wrench, dt: f64) {
    let (acceleration, angular_acceleration) = accelerations(total, mass);
    state.linear.position += state.linear.velocity * dt;
    state.angular.orientation += state.angular.angular_velocity * dt;
    state.linear.velocity += acceleration * dt;
    state.angular.angular_velocity += angular_acceleration * dt;
}

/// Applies the tutorial's total reaction (section 4.4), steps 2 to 5: symplectic Euler.
///
/// From the summed force and torque of steps 1 and 3 it takes a = F/m and α = τ/I, then moves
/// the velocities first, then the position and orientation from the new velocities.
pub fn symplectic_euler(state: &mut BodyState, mass: &MassProperties, total: Wrench, dt: f64) {
    let (acceleration, angular_acceleration) = accelerations(total, mass);
    state.linear.velocity += acceleration * dt;
    state.angular.angular_velocity += angular_acceleration * dt;
    state.linear.position += state.linear.velocity * dt;
    state.angular.orientation += state.angular.angular_velocity * dt;
}

/// Advances `state` by `dt` with velocity Verlet.
///
/// The closing half-kick takes the damping at the new velocity, which is solvable in closed
/// form because damping is linear: over the step the damping term is the trapezoidal rule, so
/// the method stays second order and damping never limits the step.
pub fn velocity_verlet(state: &mut BodyState, model: &ForceModel, start: Forces, dt: f64) {
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

/// Advances `state` by `dt` with classical Runge-Kutta; returns the energy damping took out.
///
/// Damping is part of the force at every stage. The energy it took out is integrated with the
/// same stages (so to the same fourth order).
pub fn runge_kutta_4(state: &mut BodyState, model: &ForceModel, start: Forces, dt: f64) -> f64 {
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
