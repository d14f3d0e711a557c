//! The engine of `auto`: Taylor series of high order, their coefficients from the equations of
//! motion by recurrence, each step as long as the series' last terms allow (Jorba and Zou's
//! rule), run inside one fixed step.
//!
//! Why it fits this scene: with the orientation carried as a unit vector u = (cos θ, sin θ)
//! (u' = ω u⊥) the equations of motion are polynomials of degree two: the band's force is
//! linear in the corner's position, its torque k·(R r) × (a − x) bilinear, the damping linear.
//! So every Taylor coefficient costs a handful of running products, and a high order lets a
//! step cover a large share of the band's oscillation and the spin. The report's comparison of
//! engines (docs/integrators.md) measured it against classical RK4 substeps
//! and Dormand and Prince's 8(5,3) pair at the same error on the stiff pulls.
//!
//! Everything is counted, nothing timed: the steps taken depend only on the state, the model,
//! the step and the settings, so a run is bit-identical on every machine.

use bevy::math::DVec2;

use super::engine_state::{
    COMPONENTS, DISSIPATED, RELATIVE_TOLERANCE, error_weights, pack, unpack,
};
use crate::physics::body::BodyState;
use crate::physics::forces::ForceModel;
use crate::physics::maths;

/// The highest order the engine can be asked for.
pub const MAX_ORDER: usize = 24;

const N: usize = COMPONENTS;
type Series = [f64; MAX_ORDER + 1];

/// The longest step, as rate times step, at which every truncation from order 2 up of the
/// fastest decay e^(−λh) still shrinks (as RK4's stability limit of 2.78 bounds its own).
const STABLE_RATE_TIMES_STEP: f64 = 1.5;

/// The lowest order at which a step may stop early.
const MIN_ORDER: usize = 4;

/// Slightly under the step the last two coefficients allow: the terms past the truncation
/// then shrink geometrically.
const SAFETY: f64 = 0.9;

/// What one fixed step of the engine did.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Integrated {
    pub state: BodyState,
    /// Taylor steps taken.
    pub steps: u32,
    /// The orders of the steps, summed: the work done, each order about one evaluation of
    /// the equations of motion.
    pub orders: u32,
    /// Energy damping took out, its Taylor series integrated with the motion's.
    pub dissipated: f64,
}

/// The rate times the step that a Taylor step covers on the stiff pulls at the default
/// settings: the band's oscillation sets the box spinning about three times faster than the
/// band's own rate, and a step covers about one radian of that (the report's engine table).
const RATE_TIMES_STEP: f64 = 0.3;

/// The steps a fixed step `dt` is expected to need, from the motion at its start: what
/// decides, before any work, whether the budget can afford it.
pub fn steps_expected(state: &BodyState, model: &ForceModel, dt: f64) -> f64 {
    (model.fastest_rate(state) * dt / RATE_TIMES_STEP)
        .ceil()
        .max(1.0)
}

/// How the engine works: the order of its series, the error allowed per step (px of corner
/// displacement) and the most steps a fixed step may take.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TaylorSettings {
    pub order: usize,
    pub tolerance: f64,
    pub max_steps: u32,
}

/// Advances `state` by `dt` with Taylor steps. None when the step needs more than
/// `settings.max_steps` (expected beforehand, or found on the way): the caller falls back to a
/// method that is stable at any step.
pub fn integrate(
    state: &BodyState,
    model: &ForceModel,
    dt: f64,
    settings: &TaylorSettings,
) -> Option<Integrated> {
    let budget = settings.max_steps;
    let expected = steps_expected(state, model, dt);
    if expected.is_nan() || expected > f64::from(budget) {
        return None;
    }
    let order = settings.order.clamp(2, MAX_ORDER);
    let (local, anchor, k) = match model.band {
        Some(band) => (band.local_point, band.anchor, model.stiffness),
        None => (DVec2::ZERO, DVec2::ZERO, 0.0),
    };
    let inverse_mass = model.mass.inverse_mass();
    let inverse_inertia = model.mass.inverse_inertia();
    let linear_damping = model.linear_damping;
    // c·I: the angular damping torque per unit ω.
    let angular_damping = model.angular_damping * model.mass.inertia();

    let weights = error_weights(state, model, dt);

    // Never a step past where a truncated series of the fastest decay or oscillation could
    // grow: tiny states pass any absolute tolerance, and must still decay.
    let longest = STABLE_RATE_TIMES_STEP / model.fastest_rate(state).max(f64::MIN_POSITIVE);

    let mut y = pack(state);
    let mut series: [Series; N] = [[0.0; MAX_ORDER + 1]; N];
    let mut arm_x: Series = [0.0; MAX_ORDER + 1];
    let mut arm_y: Series = [0.0; MAX_ORDER + 1];
    let mut to_anchor_x: Series = [0.0; MAX_ORDER + 1];
    let mut to_anchor_y: Series = [0.0; MAX_ORDER + 1];
    let mut remaining = dt;
    let mut steps = 0u32;
    let mut orders = 0u32;
    loop {
        if steps >= budget {
            return None;
        }
        steps += 1;
        for (s, &value) in series.iter_mut().zip(&y) {
            s[0] = value;
        }
        let size = weighted_max(&weights, |i| y[i].abs());
        let tolerance = settings.tolerance + RELATIVE_TOLERANCE * size;
        // Jorba and Zou: the step at which each of the last two terms reaches the tolerance.
        let step_allowed = |terms: &Series, top: usize| {
            let mut h = f64::INFINITY;
            for n in [top - 1, top] {
                if terms[n] > 0.0 {
                    h = h.min(maths::powf(tolerance / terms[n], 1.0 / n as f64));
                }
            }
            h * SAFETY
        };
        let mut terms: Series = [0.0; MAX_ORDER + 1];
        // (remaining / SAFETY)^top, the step that would end the fixed step, as a power.
        let reach_step = remaining / SAFETY;
        let mut reach_power = 1.0;
        // The series stops early where a lower order already reaches the end of the fixed
        // step (a soft band: a few orders instead of all of them).
        let mut used = order;
        let [x, yy, c, s, theta, vx, vy, om, e] = &mut series;
        for n in 0..order {
            // The corner's arm R(θ) r and the anchor's offset a − x, at order n.
            arm_x[n] = c[n] * local.x - s[n] * local.y;
            arm_y[n] = s[n] * local.x + c[n] * local.y;
            let origin = if n == 0 { 1.0 } else { 0.0 };
            to_anchor_x[n] = origin * anchor.x - x[n];
            to_anchor_y[n] = origin * anchor.y - yy[n];
            // The products at order n: ω·sin, ω·cos, the torque's arm × (a − x), and the
            // damping power's |v|² and ω².
            let (mut omega_sin, mut omega_cos, mut lever) = (0.0, 0.0, 0.0);
            {
                // Slices of length n + 1, so that no index below is checked.
                let (o, sn, cs) = (&om[..=n], &s[..=n], &c[..=n]);
                let (ax, ay) = (&arm_x[..=n], &arm_y[..=n]);
                let (tx, ty) = (&to_anchor_x[..=n], &to_anchor_y[..=n]);
                for j in 0..=n {
                    let m = n - j;
                    omega_sin += o[j] * sn[m];
                    omega_cos += o[j] * cs[m];
                    lever += ax[j] * ty[m] - ay[j] * tx[m];
                }
            }
            let speed_squared = square(vx, n) + square(vy, n);
            let spin_squared = square(om, n);
            let over = 1.0 / (n + 1) as f64;
            x[n + 1] = vx[n] * over;
            yy[n + 1] = vy[n] * over;
            c[n + 1] = -omega_sin * over;
            s[n + 1] = omega_cos * over;
            theta[n + 1] = om[n] * over;
            let force_x = k * (to_anchor_x[n] - arm_x[n]) - linear_damping * vx[n];
            let force_y = k * (to_anchor_y[n] - arm_y[n]) - linear_damping * vy[n];
            vx[n + 1] = force_x * inverse_mass * over;
            vy[n + 1] = force_y * inverse_mass * over;
            om[n + 1] = (k * lever - angular_damping * om[n]) * inverse_inertia * over;
            e[n + 1] = (linear_damping * speed_squared + angular_damping * spin_squared) * over;
            let top = n + 1;
            let coefficients = [
                x[top], yy[top], c[top], s[top], theta[top], vx[top], vy[top], om[top], 0.0,
            ];
            terms[top] = weighted_max(&weights, |i| coefficients[i].abs());
            // Whether the last two terms are within the tolerance at the end of the fixed
            // step: Jorba and Zou's step reaches it (compared without roots).
            reach_power *= reach_step;
            if (MIN_ORDER..order).contains(&top)
                && longest >= remaining
                && terms[top] * reach_power <= tolerance
                && terms[top - 1] * reach_power <= tolerance * reach_step
            {
                used = top;
                break;
            }
        }
        orders += used as u32;
        let early = used < order;
        let mut h = if early {
            remaining
        } else {
            step_allowed(&terms, used).min(longest)
        };
        let last = early || h >= remaining;
        if last {
            h = remaining;
        }
        for (value, s) in y.iter_mut().zip(&series) {
            *value = horner(&s[..=used], h);
        }
        if !y.iter().all(|v| v.is_finite()) {
            return None;
        }
        if last {
            break;
        }
        remaining -= h;
    }
    Some(Integrated {
        state: unpack(&y),
        steps,
        orders,
        dissipated: y[DISSIPATED],
    })
}

/// The n-th Taylor coefficient of a square: Σ a[j] a[n − j], each pair once.
fn square(a: &Series, n: usize) -> f64 {
    let mut twice = 0.0;
    for j in 0..n.div_ceil(2) {
        twice += a[j] * a[n - j];
    }
    let middle = if n.is_multiple_of(2) {
        a[n / 2] * a[n / 2]
    } else {
        0.0
    };
    2.0 * twice + middle
}

fn horner(coefficients: &[f64], h: f64) -> f64 {
    coefficients.iter().rev().fold(0.0, |sum, &c| sum * h + c)
}

fn weighted_max(weights: &[f64; N], value: impl Fn(usize) -> f64) -> f64 {
    (0..N).map(|i| weights[i] * value(i)).fold(0.0, f64::max)
}
