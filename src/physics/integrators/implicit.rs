//! Backward Euler, stable at any stiffness and step: `implicit`, and `auto`'s fall-back.

use bevy::math::{DMat3, DVec3};

use crate::physics::body::{BodyState, rotate};
use crate::physics::forces::ForceModel;

/// Advances `state` by `dt` with backward Euler; returns the force-law evaluations it made.
///
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
pub fn backward_euler(state: &mut BodyState, model: &ForceModel, dt: f64) -> u32 {
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
                let arm = rotate(band.local_point, q.z);
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
