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
    COMPONENTS, Components, DISSIPATED, RELATIVE_TOLERANCE, error_weights, pack, unpack,
};
use crate::physics::body::BodyState;
use crate::physics::forces::ForceModel;
use crate::physics::maths;

/// The highest order the engine can be asked for.
pub const MAX_ORDER: usize = 24;

const N: usize = COMPONENTS;

/// The longest step, as rate times step, at which the fastest decay's truncations still shrink.
///
/// Every truncation from order 2 up of the fastest decay e^(−λh) still shrinks there (as RK4's
/// stability limit of 2.78 bounds its own).
const STABLE_RATE_TIMES_STEP: f64 = 1.5;

/// The lowest order at which a step may stop early.
const MIN_ORDER: usize = 4;

/// Slightly under the step the last two coefficients allow.
///
/// The terms past the truncation then shrink geometrically.
const SAFETY: f64 = 0.9;

/// What one fixed step of the engine did.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Integrated {
    pub state: BodyState,
    /// Taylor steps taken.
    pub steps: u32,
    /// The orders of the steps, summed: the work done.
    ///
    /// Each order is about one evaluation of the equations of motion.
    pub orders: u32,
    /// Energy damping took out, its Taylor series integrated with the motion's.
    pub dissipated: f64,
}

/// The rate times the step that a Taylor step covers on the stiff pulls at the default settings.
///
/// The band's oscillation sets the box spinning about three times faster than the band's own
/// rate, and a step covers about one radian of that (the report's engine table).
const RATE_TIMES_STEP: f64 = 0.3;

/// Returns the steps a fixed step `dt` is expected to need, from the motion at its start.
///
/// The estimate decides, before any work, whether the budget can afford the step.
pub fn steps_expected(state: &BodyState, model: &ForceModel, dt: f64) -> f64 {
    (model.fastest_rate(state) * dt / RATE_TIMES_STEP)
        .ceil()
        .max(1.0)
}

/// How the engine works: the order of its series, the error allowed and the step budget.
///
/// The error allowed is per step, in px of corner displacement; the budget is the most steps a
/// fixed step may take.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TaylorSettings {
    pub order: usize,
    pub tolerance: f64,
    pub max_steps: u32,
}

/// Advances `state` by `dt` with Taylor steps.
///
/// None when the step needs more than `settings.max_steps` (expected beforehand, or found on
/// the way): the caller falls back to a method that is stable at any step.
///
/// On an x86-64 with AVX the same code runs compiled for its four-lane registers: one vector
/// multiply or add where SSE2 takes two. Each lane rounds each operation as before (no fused
/// multiply-add), so the bits are the same on every machine and in the browser.
pub fn integrate(
    state: &BodyState,
    model: &ForceModel,
    dt: f64,
    settings: &TaylorSettings,
) -> Option<Integrated> {
    #[cfg(target_arch = "x86_64")]
    if std::is_x86_feature_detected!("avx") {
        // SAFETY: the processor has AVX, as just checked.
        return unsafe { integrate_on_avx(state, model, dt, settings) };
    }
    integrate_portable(state, model, dt, settings)
}

/// Runs [`integrate`] as compiled for any processor: what the browser runs.
///
/// The tests hold the two compilations to the same bits; the benchmarks time them side by side.
pub fn integrate_portable(
    state: &BodyState,
    model: &ForceModel,
    dt: f64,
    settings: &TaylorSettings,
) -> Option<Integrated> {
    integrate_here(state, model, dt, settings)
}

/// Runs [`integrate`] compiled for AVX's four-lane registers.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx")]
fn integrate_on_avx(
    state: &BodyState,
    model: &ForceModel,
    dt: f64,
    settings: &TaylorSettings,
) -> Option<Integrated> {
    integrate_here(state, model, dt, settings)
}

/// Holds [`integrate`]'s body, inlined into each of its compilations.
#[inline(always)]
fn integrate_here(
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
    // The series, an order a row: row n holds every component's n-th coefficient, so that
    // a row is written at once and the sums at the end run over all components together.
    let mut series: [Components; MAX_ORDER + 1] = [[0.0; N]; MAX_ORDER + 1];
    // Each order's operands of the products, in pairs so that one multiply-add serves two
    // sums (see [`Operands`]).
    let mut operands = [Operands::default(); MAX_ORDER + 1];
    // The anchor's share of the offset's series past order 0 (zero, of the anchor's sign).
    let anchor_past_start = [0.0 * anchor.y, 0.0 * anchor.x];
    let arm_of =
        |cos: f64, sin: f64| [cos * local.x - sin * local.y, sin * local.x + cos * local.y];
    let mut remaining = dt;
    let mut steps = 0u32;
    let mut orders = 0u32;
    loop {
        if steps >= budget {
            return None;
        }
        steps += 1;
        series[0] = y;
        // Order 0: the step's start. `newest` is the latest order's operands, carried in
        // registers from one order to the next rather than read back from memory.
        let first = {
            let [arm_x, arm_y] = arm_of(y[2], y[3]);
            Operands {
                left: [y[7], y[7], arm_x, arm_y],
                right: [y[3], y[2], anchor.y - y[1], anchor.x - y[0]],
                square: [y[5], y[6], y[7], 0.0],
            }
        };
        operands[0] = first;
        let mut newest = first;
        let size = weighted_max(&weights, &y);
        let tolerance = settings.tolerance + RELATIVE_TOLERANCE * size;
        // Jorba and Zou: the step at which each of the last two terms reaches the tolerance.
        // The smaller of the two roots is taken as logarithms, then one exponential: an `ln`
        // or two and an `exp` cost less than two `pow`.
        let step_allowed = |series: &[Components; MAX_ORDER + 1], top: usize| {
            let term = |n: usize| (weighted_max(&weights, &series[n]), n as f64);
            maths::exp(least_log_root(tolerance, [term(top - 1), term(top)])) * SAFETY
        };
        // (remaining / SAFETY)^top, the step that would end the fixed step, as a power.
        let reach_step = remaining / SAFETY;
        let mut reach_power = 1.0;
        // The series stops early where a lower order already reaches the end of the fixed
        // step (a soft band: a few orders instead of all of them).
        let mut used = order;
        for n in 0..order {
            let products = Products::at(n, &operands, &first, &newest);
            let over = 1.0 / (n + 1) as f64;
            let omega = newest.omega();
            let [_, _, arm_x, arm_y] = newest.left;
            let [_, _, to_anchor_y, to_anchor_x] = newest.right;
            let [velocity_x, velocity_y, ..] = newest.square;
            let position_x = velocity_x * over;
            let position_y = velocity_y * over;
            let cos = -products.omega_sin * over;
            let sin = products.omega_cos * over;
            let theta = omega * over;
            let force_x = k * (to_anchor_x - arm_x) - linear_damping * velocity_x;
            let force_y = k * (to_anchor_y - arm_y) - linear_damping * velocity_y;
            let vx = force_x * inverse_mass * over;
            let vy = force_y * inverse_mass * over;
            let om = (k * products.lever - angular_damping * omega) * inverse_inertia * over;
            let (speed_squared, spin_squared) = (products.speed_squared, products.spin_squared);
            let e = (linear_damping * speed_squared + angular_damping * spin_squared) * over;
            series[n + 1] = [position_x, position_y, cos, sin, theta, vx, vy, om, e];
            let [arm_x, arm_y] = arm_of(cos, sin);
            newest = Operands {
                left: [om, om, arm_x, arm_y],
                right: [
                    sin,
                    cos,
                    anchor_past_start[0] - position_y,
                    anchor_past_start[1] - position_x,
                ],
                square: [vx, vy, om, 0.0],
            };
            operands[n + 1] = newest;
            let top = n + 1;
            // Whether the last two terms are within the tolerance at the end of the fixed
            // step: Jorba and Zou's step reaches it (compared without roots). The terms are
            // weighed only where the step could end here: a stiff band's never does.
            reach_power *= reach_step;
            if (MIN_ORDER..order).contains(&top) && longest >= remaining {
                let term = |n: usize| weighted_max(&weights, &series[n]);
                if term(top) * reach_power <= tolerance
                    && term(top - 1) * reach_power <= tolerance * reach_step
                {
                    used = top;
                    break;
                }
            }
        }
        orders += used as u32;
        let early = used < order;
        let mut h = if early {
            remaining
        } else {
            step_allowed(&series, used).min(longest)
        };
        let last = early || h >= remaining;
        if last {
            h = remaining;
        }
        y = horner(&series[..=used], h);
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

/// The most [`rough_ln`] is off from the natural logarithm, with a margin for its rounding.
///
/// Its log2 of the mantissa m ∈ [1, 2) is m − 1 + 0.04305, and log2(m) − (m − 1) lies in
/// [0, 0.0861]: at most 0.04305 off in log2, 0.02984 in ln.
const ROUGH_LN_ERROR: f64 = 0.0305;

/// Returns ln x within [`ROUGH_LN_ERROR`], from x's exponent and mantissa.
///
/// None unless x is a positive normal number.
#[inline(always)]
fn rough_ln(x: f64) -> Option<f64> {
    if !(x.is_normal() && x > 0.0) {
        return None;
    }
    let bits = x.to_bits();
    let exponent = ((bits >> 52) & 0x7ff) as f64 - 1023.0;
    let mantissa = f64::from_bits((bits & 0x000f_ffff_ffff_ffff) | 0x3ff0_0000_0000_0000);
    Some((exponent + (mantissa - 1.0) + 0.04305) * std::f64::consts::LN_2)
}

/// Returns the least of ln(tolerance / term) / n over the (term, n) whose term is positive.
///
/// Infinity if neither is; bit for bit the two logarithms' minimum. Where the two roots' rough logarithms ([`rough_ln`]) lie further apart than their error,
/// only the smaller root's exact logarithm is taken: one `ln` instead of two, the same bits.
#[inline(always)]
fn least_log_root(tolerance: f64, terms: [(f64, f64); 2]) -> f64 {
    let exact = |(term, n): (f64, f64)| {
        if term > 0.0 {
            maths::ln(tolerance / term) / n
        } else {
            f64::INFINITY
        }
    };
    let [first, second] = terms;
    let rough = |(term, n): (f64, f64)| {
        let root = rough_ln(tolerance / term)?;
        (term > 0.0).then_some((root / n, ROUGH_LN_ERROR / n))
    };
    if let (Some((a, error_a)), Some((b, error_b))) = (rough(first), rough(second)) {
        if a + error_a < b - error_b {
            return f64::INFINITY.min(exact(first));
        }
        if b + error_b < a - error_a {
            return f64::INFINITY.min(exact(second));
        }
    }
    f64::INFINITY.min(exact(first)).min(exact(second))
}

type Quad = [f64; 4];

/// Returns acc + a·b, lane by lane.
///
/// It is written so that the compiler makes it vector multiplies and adds where the machine has
/// them (two SSE2 instructions each on any x86-64); the same operations, so the same bits, one
/// lane at a time where it has none (wasm).
#[inline(always)]
fn mul_add(acc: Quad, a: Quad, b: Quad) -> Quad {
    std::array::from_fn(|i| acc[i] + a[i] * b[i])
}

/// One order's operands of the Cauchy products, in lanes: one multiply-add serves four sums.
///
/// `left` × `right` is [ω·sin, ω·cos, arm x · (a − x) y, arm y · (a − x) x] (the torque's cross
/// product arm × (a − x) is then the difference of the last two lanes), and `square` × `square`
/// is [vx², vy², ω², 0], the damping power's.
#[derive(Clone, Copy, Default)]
struct Operands {
    /// [ω, ω, arm x, arm y], the corner's arm R(θ) r.
    left: Quad,
    /// [sin, cos, (a − x) y, (a − x) x], the offset to the anchor swapped.
    right: Quad,
    /// [vx, vy, ω, 0].
    square: Quad,
}

impl Operands {
    fn omega(&self) -> f64 {
        self.left[0]
    }
}

/// The Cauchy products the n-th coefficients need.
///
/// They are ω·sin, ω·cos, the torque's arm × (a − x), and the damping power's |v|² and ω².
struct Products {
    omega_sin: f64,
    omega_cos: f64,
    lever: f64,
    speed_squared: f64,
    spin_squared: f64,
}

impl Products {
    /// Computes the Cauchy products for the n-th coefficients, each sum from its middle out.
    ///
    /// Each sum Σ f[j] g[n − j] is taken from its middle term out to its ends, the terms
    /// (j, n − j) and (n − j, j) together: the ends hold the newest order, found only by the
    /// previous one, so the middle's additions run while that order is still being computed,
    /// and what waits on it is two multiply-adds, on operands kept in registers. The two ends
    /// of each pair go to separate sums, which halves the chain again.
    #[inline(always)]
    fn at(
        n: usize,
        operands: &[Operands; MAX_ORDER + 1],
        first: &Operands,
        newest: &Operands,
    ) -> Self {
        let n = n.min(MAX_ORDER);
        let zero = [0.0; 4];
        let (mut low_ends, mut high_ends, mut squares) = (zero, zero, zero);
        if n.is_multiple_of(2) {
            let middle = if n == 0 { first } else { &operands[n / 2] };
            low_ends = mul_add(zero, middle.left, middle.right);
            squares = mul_add(zero, middle.square, middle.square);
        }
        let mut add_pair = |low: &Operands, high: &Operands| {
            low_ends = mul_add(low_ends, low.left, high.right);
            high_ends = mul_add(high_ends, high.left, low.right);
            // The squares' pairs once, doubled (exactly).
            let double = low.square.map(|factor| 2.0 * factor);
            squares = mul_add(squares, double, high.square);
        };
        for low in (1..n.div_ceil(2)).rev() {
            add_pair(&operands[low], &operands[n - low]);
        }
        if n >= 1 {
            add_pair(first, newest);
        }
        let sums: Quad = std::array::from_fn(|i| low_ends[i] + high_ends[i]);
        Self {
            omega_sin: sums[0],
            omega_cos: sums[1],
            lever: sums[2] - sums[3],
            speed_squared: squares[0] + squares[1],
            spin_squared: squares[2],
        }
    }
}

/// Sums every component's series at `h`, each by Horner's rule.
#[inline(always)]
fn horner(rows: &[Components], h: f64) -> Components {
    rows.iter().rev().fold([0.0; N], |sums, row| {
        std::array::from_fn(|i| sums[i] * h + row[i])
    })
}

/// Returns the largest of weights[i]·|values[i]| over the motion's components.
///
/// The energy is not weighed. It is found by a tree of plain comparisons: every order of the
/// series takes one, and the NaN-aware `f64::max` costs five instructions a comparison. A NaN
/// here needs no care: it reaches the state, which the step then refuses.
#[inline(always)]
fn weighted_max(weights: &[f64; N], values: &[f64; N]) -> f64 {
    let w = |i: usize| weights[i] * values[i].abs();
    let larger = |a: f64, b: f64| if a > b { a } else { b };
    let pairs = [
        larger(w(0), w(1)),
        larger(w(2), w(3)),
        larger(w(4), w(5)),
        larger(w(6), w(7)),
    ];
    larger(larger(pairs[0], pairs[1]), larger(pairs[2], pairs[3]))
}

#[cfg(test)]
mod tests {
    use super::*;

    // The two logarithms' minimum, as the step size was taken before the rough shortcut.
    fn both_logarithms(tolerance: f64, terms: [(f64, f64); 2]) -> f64 {
        let mut log_h = f64::INFINITY;
        for (term, n) in terms {
            if term > 0.0 {
                log_h = log_h.min(maths::ln(tolerance / term) / n);
            }
        }
        log_h
    }

    // The rough logarithm stays within its stated error over every binade and mantissa.
    #[test]
    fn the_rough_logarithm_is_within_its_error() {
        let mut worst: f64 = 0.0;
        for exponent in -1020..=1020 {
            for step in 0..=64 {
                let x = (1.0 + f64::from(step) / 64.0) * 2f64.powi(exponent);
                let off = (rough_ln(x).unwrap() - x.ln()).abs();
                worst = worst.max(off);
            }
        }
        assert!(worst <= ROUGH_LN_ERROR, "{worst}");
        assert!(worst > 0.029, "the bound is tight: {worst}");
        for outside in [0.0, -1.0, f64::INFINITY, f64::NAN, f64::MIN_POSITIVE / 2.0] {
            assert_eq!(rough_ln(outside), None, "{outside}");
        }
    }

    // The least root is the two logarithms' minimum to the bit: on terms far apart (one `ln`),
    // on terms within the rough error of each other (both), on zero, tiny, huge and NaN terms.
    #[test]
    fn the_least_root_is_the_two_logarithms_minimum_to_the_bit() {
        let mut seed = 0x9e37_79b9_7f4a_7c15_u64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed
        };
        let mut terms = vec![0.0, f64::NAN, 1e-320, 1e300, f64::INFINITY, 1e-13, 2e-13];
        for _ in 0..20_000 {
            let exponent = (next() % 60) as i32 - 40;
            let mantissa = 1.0 + (next() % 1_000_000) as f64 / 1e6;
            terms.push(mantissa * 10f64.powi(exponent));
        }
        let mut shortcuts = 0;
        for (i, &a) in terms.iter().enumerate() {
            let b = terms[(i * 7 + 3) % terms.len()];
            // Nearby pairs too: the second term a hair from the first.
            for b in [b, a * (1.0 + 1e-3), a * (1.0 + 1e-9)] {
                for (tolerance, n) in [(1e-13, 20.0), (3.7e-11, 8.0), (1e-15, 24.0)] {
                    let pair = [(a, n - 1.0), (b, n)];
                    let fast = least_log_root(tolerance, pair);
                    let slow = both_logarithms(tolerance, pair);
                    assert_eq!(fast.to_bits(), slow.to_bits(), "{pair:?} at {tolerance}");
                    let (ra, rb) = (rough_ln(tolerance / a), rough_ln(tolerance / b));
                    if let (Some(ra), Some(rb)) = (ra, rb)
                        && ((ra / (n - 1.0)) - (rb / n)).abs() > ROUGH_LN_ERROR
                    {
                        shortcuts += 1;
                    }
                }
            }
        }
        assert!(shortcuts > 50_000, "the shortcut is taken: {shortcuts}");
    }
}
