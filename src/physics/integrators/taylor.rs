//! The engine of `auto`: Taylor series of high order, their coefficients from the equations of
//! motion by recurrence, each step as long as the series' last terms allow (Jorba and Zou's
//! rule), run inside one fixed step.
//!
//! Why it fits this scene: in the frame that turns with the box, with D = Rᵀ(x − a) the centre
//! seen from the anchor and V = Rᵀv, the equations of motion are polynomials of degree two: the
//! band's force −k R(D + r) and torque −k r × D are linear in D, the damping linear, and the
//! turning adds −ω J D and −ω J V (J a quarter turn), the only products. So every Taylor
//! coefficient costs four running products, and a high order lets a step cover a large share
//! of the band's oscillation and the spin. The report's comparison of engines
//! (docs/integrators.md) measures it against classical RK4 substeps and Dormand and Prince's
//! 8(5,3) pair at the same error on the stiff pulls.
//!
//! Everything is counted, nothing timed: the steps taken depend only on the state, the model,
//! the step and the settings, so a run is bit-identical on every machine.

use bevy::math::DVec2;

use super::engine_state::RELATIVE_TOLERANCE;
#[cfg(target_arch = "x86_64")]
use super::lanes::Avx;
use super::lanes::{Lanes, Portable, Quad};
use crate::physics::body::{AngularState, BodyState, LinearState};
use crate::physics::forces::ForceModel;
use crate::physics::maths;

/// The highest order the engine can be asked for.
pub const MAX_ORDER: usize = 32;

/// The longest step, as rate times step, at which the fastest decay's truncations still shrink.
///
/// Every truncation from order 2 up of the fastest decay e^(−λh) still shrinks there (as RK4's
/// stability limit of 2.78 bounds its own).
const STABLE_RATE_TIMES_STEP: f64 = 1.5;

/// The lowest order at which a step may stop early.
const MIN_ORDER: usize = 4;

/// How far under the tolerance a series that ends the fixed step early must be.
///
/// Only a soft band's fixed step ends early, in a few orders: one order more costs little
/// there and keeps its error as low as the world frame's series had it.
const EARLY_MARGIN: f64 = 1e-2;

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
    /// Energy damping took out: the mechanical energy at the start less that at the end.
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
/// On an x86-64 with AVX the same code runs compiled for its four-lane registers, the
/// recurrence's lanes written as AVX's instructions (the module `lanes`). Each lane rounds each
/// operation as the arrays do (no fused multiply-add), so the bits are the same on every
/// machine and in the browser. (Compiled for AVX-512's eight lanes it ran slower on a machine
/// that has them: docs/benchmarks.md.)
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
    integrate_here::<Portable>(state, model, dt, settings)
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
    integrate_here::<Avx>(state, model, dt, settings)
}

/// The motion in the frame that turns with the box, as the engine's series carry it.
///
/// D = Rᵀ(x − a) the centre seen from the anchor and V = Rᵀv the velocity, both in the box's
/// axes, y before x (as the turning's products pair them with ω: see [`Recurrence`]), then
/// θ, ω, and two lanes of padding: two four-lane rows.
type Row = [f64; LANES];
const LANES: usize = 8;
const THETA: usize = 4;
const OMEGA: usize = 5;

/// Returns the state seen from the turning frame, from the state, the anchor and (sin θ, cos θ).
#[inline(always)]
fn turned(state: &BodyState, anchor: DVec2, (sin, cos): (f64, f64)) -> Row {
    let to_box = |v: DVec2| [cos * v.x + sin * v.y, cos * v.y - sin * v.x];
    let [dx, dy] = to_box(state.linear.position - anchor);
    let [vx, vy] = to_box(state.linear.velocity);
    let (theta, omega) = (state.angular.orientation, state.angular.angular_velocity);
    [dy, dx, vy, vx, theta, omega, 0.0, 0.0]
}

/// Returns the state after `moved` (every component's change since `start`), in the world's axes.
///
/// (sin θ, cos θ) are the start's.
///
/// The change is turned back by the start's rotation and the turn since, and added to the
/// state it started from: turning the whole of D and V back would round each in proportion to
/// its size, the anchor's distance, where this rounds the change (in D and V, and in the turn
/// times the start's D and V) and the start's position and velocity once each.
#[inline(always)]
fn moved_from(state: &BodyState, (sin, cos): (f64, f64), start: &Row, moved: &Row) -> BodyState {
    let (turn_sin, turn_cos) = maths::sin_cos(moved[THETA]);
    // R(θ₀)·((R(Δθ) − 1)·p + R(Δθ)·Δp): the change of the world's R(θ)·p.
    let change = |p: [f64; 2], change: [f64; 2]| {
        let [px, py] = p;
        let [cx, cy] = change;
        let x = (turn_cos - 1.0) * px - turn_sin * py + (turn_cos * cx - turn_sin * cy);
        let y = turn_sin * px + (turn_cos - 1.0) * py + (turn_sin * cx + turn_cos * cy);
        DVec2::new(cos * x - sin * y, sin * x + cos * y)
    };
    BodyState {
        linear: LinearState {
            position: state.linear.position + change([start[1], start[0]], [moved[1], moved[0]]),
            velocity: state.linear.velocity + change([start[3], start[2]], [moved[3], moved[2]]),
        },
        angular: AngularState {
            orientation: state.angular.orientation + moved[THETA],
            angular_velocity: state.angular.angular_velocity + moved[OMEGA],
        },
    }
}

/// Holds [`integrate`]'s body, inlined into each of its compilations.
///
/// In the frame that turns with the box the band's force −k R(D + r) and its torque −k r × D
/// are linear in D, and what the turning adds, −ω J D and −ω J V (J a quarter turn), is the
/// only product: four of them an order.
///
/// The energy damping took out is booked from the energy at the fixed step's ends: the anchor
/// stays put within it, so no other force works on the box.
#[inline(always)]
fn integrate_here<L: Lanes>(
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
    let stiffness_per_mass = k * model.mass.inverse_mass();
    let damping_per_mass = model.linear_damping * model.mass.inverse_mass();
    let spin = Spin {
        stiffness_per_inertia: k * model.mass.inverse_inertia(),
        damping: model.angular_damping,
    };

    let facing = maths::sin_cos(state.angular.orientation);
    let start = turned(state, anchor, facing);
    let weights = error_weights(state, model, dt, &start);
    // The sizes the round-off is relative to: θ's own, as the corner's displacement (the turn
    // of D weighs in the tolerance, not in how much round-off the series allow).
    let sizes = {
        let mut sizes = weights;
        sizes[THETA] = 0.5 * model.mass.size().length();
        sizes
    };
    // Every component's change since the start, summed step by step: the world's state is
    // found from it at the end (see [`moved_from`]).
    let mut moved: Row = [0.0; LANES];
    let mut y = start;

    // Never a step past where a truncated series of the fastest decay or oscillation could
    // grow: tiny states pass any absolute tolerance, and must still decay.
    let longest = STABLE_RATE_TIMES_STEP / model.fastest_rate(state).max(f64::MIN_POSITIVE);

    // The series, an order a row: row n holds every component's n-th coefficient, so that
    // a row is written at once and the sums at the end run over all components together.
    let mut aligned = Series([[0.0; LANES]; MAX_ORDER + 1]);
    let series = &mut aligned.0;
    let mut remaining = dt;
    let mut steps = 0u32;
    let mut orders = 0u32;
    loop {
        if steps >= budget {
            return None;
        }
        steps += 1;
        series[0] = y;
        // Order 0: the step's start.
        let first = y;
        let size = weighted_max(&sizes, &y);
        let tolerance = settings.tolerance + RELATIVE_TOLERANCE * size;
        // Jorba and Zou: the step at which each of the last two terms reaches the tolerance,
        // the smaller of the two, in logarithms.
        let log2_tolerance = rough_log2(tolerance);
        // Whether the series may end the fixed step early: the stability cap lets it.
        let may_end = longest >= remaining;
        // (remaining / SAFETY)^top, the step that would end the fixed step, as a power.
        let reach_step = if may_end { remaining / SAFETY } else { 0.0 };
        let mut reach_power = 1.0;
        // The series stops early where a lower order already reaches the end of the fixed
        // step (a soft band: a few orders instead of all of them).
        let mut used = order;
        let recurrence =
            Recurrence::<L>::of(&first, local, stiffness_per_mass, damping_per_mass, spin);
        let mut newest = recurrence.first_order(&first);
        let mut middle = Middle::<L>::from(newest);
        for n in 0..order {
            if n > 0 {
                let sums = middle.at(n, order, series, newest);
                newest = recurrence.next(&newest, sums, RECIPROCALS[n + 1]);
            }
            series[n + 1] = newest.row();
            let top = n + 1;
            // Whether the last two terms are within the tolerance at the end of the fixed
            // step: Jorba and Zou's step reaches it (compared without roots). Only where the
            // step could end here (a stiff band's never does): elsewhere the chain of powers
            // would hold up the orders after it, waiting on the size of the step before.
            if !may_end {
                continue;
            }
            reach_power *= reach_step;
            if (MIN_ORDER..order).contains(&top) {
                let term = |n: usize| weighted_max(&weights, &series[n]);
                let tolerance = tolerance * EARLY_MARGIN;
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
            // The last row from the registers it was found in, not read back.
            let last = (weighted_max(&weights, &newest.row()), RECIPROCALS[used]);
            let before = (
                weighted_max(&weights, &series[used - 1]),
                RECIPROCALS[used - 1],
            );
            let log2_step = least_root(log2_tolerance, [before, last]);
            (rough_exp2(log2_step) * SAFETY).min(longest)
        };
        let last = early || h >= remaining;
        if last {
            h = remaining;
        }
        let rows = &series[1..=used];
        let change = match rows.first_chunk::<28>() {
            Some(rows) if used == 28 => polynomial_28(rows, h),
            _ => polynomial(rows, h),
        }
        .map(|sum| sum * h);
        moved = std::array::from_fn(|i| moved[i] + change[i]);
        y = std::array::from_fn(|i| start[i] + moved[i]);
        if !y.iter().all(|v| v.is_finite()) {
            return None;
        }
        if last {
            break;
        }
        remaining -= h;
    }
    Some(Integrated {
        state: moved_from(state, facing, &start, &moved),
        steps,
        orders,
        dissipated: if model.linear_damping == 0.0 && model.angular_damping == 0.0 {
            0.0
        } else {
            mechanical_energy(model, local, k, &start) - mechanical_energy(model, local, k, &y)
        },
    })
}

/// The series, an order a row, every row on a cache line of its own.
///
/// Then a row's two four-lane halves never straddle two lines. Left where the stack put it, the
/// process's start decided how long a fixed step took (docs/benchmarks.md#the-recurrence-in-lanes).
#[repr(align(64))]
struct Series([Row; MAX_ORDER + 1]);

/// Returns the box's kinetic energy and the band's, from the turned state `row`.
///
/// The band's is ½k|D + r|², its stretch seen from the box. It is [`ForceModel::energy`] in
/// the box's axes (a test holds the two together): that one turns the corner into the world's
/// axes, a `sin_cos` at each end of every fixed step, which a soft band's step feels
/// (docs/benchmarks.md#the-turning-frame).
fn mechanical_energy(model: &ForceModel, local: DVec2, k: f64, row: &Row) -> f64 {
    let [dy, dx, vy, vx, _, omega, ..] = *row;
    let (stretch_x, stretch_y) = (dx + local.x, dy + local.y);
    0.5 * (model.mass.mass() * (vx * vx + vy * vy)
        + model.mass.inertia() * omega * omega
        + k * (stretch_x * stretch_x + stretch_y * stretch_y))
}

/// Returns the error weights for a fixed step `dt` from `state`, turned as `start`.
///
/// Positions count in px; the orientation as the displacement it makes of the farthest corner
/// and of the centre seen from the anchor, and of the velocity over the time the motion takes
/// to move that far (the faster of the motion's rate and the fixed step); velocities over that
/// time too; the padding has no weight.
fn error_weights(state: &BodyState, model: &ForceModel, dt: f64, start: &Row) -> Row {
    let reach = 0.5 * model.mass.size().length();
    let [dy, dx, vy, vx, ..] = *start;
    let rate = model.fastest_rate(state).max(1.0 / dt);
    let turn = reach + dx.hypot(dy) + vx.hypot(vy) / rate;
    [
        1.0,
        1.0,
        1.0 / rate,
        1.0 / rate,
        turn,
        reach / rate,
        0.0,
        0.0,
    ]
}

/// 1/n for every n up to one past the highest order: no division in the loop.
const RECIPROCALS: [f64; MAX_ORDER + 2] = {
    let mut table = [0.0; MAX_ORDER + 2];
    let mut n = 1;
    while n < MAX_ORDER + 2 {
        table[n] = 1.0 / n as f64;
        n += 1;
    }
    table
};

/// Returns log2 x within 0.0077, from x's exponent and a quadratic of its mantissa.
///
/// A step size needs its logarithm to a few parts in a thousand, not to the last bit: this
/// costs a few operations that round alike everywhere, where `ln` costs a library call.
/// Infinite or NaN where `log2` is (−∞ at zero, NaN below).
#[inline(always)]
fn rough_log2(x: f64) -> f64 {
    if x == 0.0 {
        return f64::NEG_INFINITY;
    }
    if !(x > 0.0 && x < f64::INFINITY) {
        // Infinity stays; below zero and NaN are NaN.
        return if x > 0.0 { x } else { f64::NAN };
    }
    // A subnormal is scaled into the normal range first, by 2^64.
    let (x, shift) = if x.is_normal() {
        (x, 0.0)
    } else {
        (x * 18_446_744_073_709_551_616.0, 64.0)
    };
    let bits = x.to_bits();
    let exponent = ((bits >> 52) & 0x7ff) as f64 - 1023.0;
    let t = f64::from_bits((bits & 0x000f_ffff_ffff_ffff) | 0x3ff0_0000_0000_0000) - 1.0;
    // log2(1 + t) for t in [0, 1), exact at both ends.
    exponent - shift + t * (1.34655 - 0.34655 * t)
}

/// Returns 2^x within 0.27%, from x's whole part as the exponent and a quadratic of its fraction.
///
/// 0 below 2^−1022, infinite from 2^1024, NaN at NaN.
#[inline(always)]
fn rough_exp2(x: f64) -> f64 {
    if x.is_nan() {
        return x;
    }
    if x < -1022.0 {
        return 0.0;
    }
    if x >= 1024.0 {
        return f64::INFINITY;
    }
    // The fraction from x's floor, which the processor finds in its floating-point lanes:
    // what waits on x is then a subtraction and the quadratic, not two conversions.
    let whole = x.floor();
    let fraction = x - whole;
    let scale = f64::from_bits(((whole as i64 + 1023) as u64) << 52);
    // 2^f for f in [0, 1), exact at both ends.
    scale * (1.0 + fraction * (0.6602 + 0.3398 * fraction))
}

/// Returns log2 of the step at which the first of the positive terms reaches the tolerance.
///
/// That is the least of (log2 tolerance − log2 term) / n over the (term, 1/n) whose term is
/// positive; infinity if none is.
#[inline(always)]
fn least_root(log2_tolerance: f64, terms: [(f64, f64); 2]) -> f64 {
    let root = |(term, reciprocal): (f64, f64)| {
        if term > 0.0 {
            (log2_tolerance - rough_log2(term)) * reciprocal
        } else {
            f64::INFINITY
        }
    };
    let [first, second] = terms.map(root);
    if first < second { first } else { second }
}

/// Returns [D y, D x, V y, V x]: what ω multiplies in the turning's products.
#[inline(always)]
fn turned_parts(row: &Row) -> &Quad {
    row.first_chunk().expect("a row has eight lanes")
}

/// What turns the box: its band's stiffness over its inertia, and its angular damping.
#[derive(Clone, Copy)]
struct Spin {
    stiffness_per_inertia: f64,
    damping: f64,
}

/// One order's coefficients as the recurrence carries them to the next, in registers.
///
/// The parts [D y, D x, V y, V x], θ, and ω in every lane.
struct Coefficients<L: Lanes> {
    parts: L::Four,
    theta: f64,
    omega: L::Four,
}

impl<L: Lanes> Clone for Coefficients<L> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<L: Lanes> Copy for Coefficients<L> {}

impl<L: Lanes> Coefficients<L> {
    /// Returns the coefficients as a row of the series.
    #[inline(always)]
    fn row(&self) -> Row {
        let [dy, dx, vy, vx] = L::store(self.parts);
        [dy, dx, vy, vx, self.theta, L::first(self.omega), 0.0, 0.0]
    }
}

/// The recurrence of one Taylor step: the (n + 1)-th coefficients from the n-th, linear in them.
///
/// The turning's product ω·J·(D, V) at order n is Σ ω_j (D, V)_(n−j): its two ends, ω₀ times
/// the newest parts and the newest ω times the start's, are linear in the newest coefficients
/// with the start's values as factors, and its middle ([`Middle`]) holds only older orders,
/// found while the newest still is. Every factor is scaled by 1/(n + 1) before the newest
/// order arrives: what waits on it is a multiply a term and a short tree of additions, the
/// middle sums' the last of them.
struct Recurrence<L: Lanes> {
    /// Times the parts with each pair swapped, [D x, D y, V x, V y]: ω₀ J.
    across: L::Four,
    /// Times the parts with the halves swapped, [V y, V x, D y, D x]: D' = V, the band's pull.
    halves: L::Four,
    /// The band's pull on the corner's offset r, which only the first order has.
    corner: L::Four,
    /// Times the parts themselves: the linear damping.
    itself: L::Four,
    /// Times the newest ω: J times the start's parts.
    spin: L::Four,
    /// Turns the middle sums [D y, D x, V y, V x] swapped pairwise into J's: signs.
    signs: L::Four,
    /// ω's, times the parts: the band's torque from D y and D x.
    torque: L::Four,
    /// ω's, times ω: the angular damping.
    spin_damping: L::Four,
}

impl<L: Lanes> Recurrence<L> {
    /// Returns the recurrence of the Taylor step that starts at `first`.
    #[inline(always)]
    fn of(first: &Row, local: DVec2, stiffness: f64, damping: f64, spin: Spin) -> Self {
        let omega = first[OMEGA];
        let [dy, dx, vy, vx] = *turned_parts(first);
        let torque = spin.stiffness_per_inertia;
        Self {
            across: L::load(&[-omega, omega, -omega, omega]),
            halves: L::load(&[1.0, 1.0, -stiffness, -stiffness]),
            corner: L::load(&[0.0, 0.0, -stiffness * local.y, -stiffness * local.x]),
            itself: L::load(&[0.0, 0.0, -damping, -damping]),
            spin: L::load(&[-dx, dy, -vx, vy]),
            signs: L::load(&[-1.0, 1.0, -1.0, 1.0]),
            torque: L::load(&[-torque * local.x, torque * local.y, 0.0, 0.0]),
            spin_damping: L::splat(-spin.damping),
        }
    }

    /// Returns the first-order coefficients from the start `first`.
    ///
    /// There the band pulls the corner D + r and the turning's product is the single ω₀·(D, V)₀.
    #[inline(always)]
    fn first_order(&self, first: &Row) -> Coefficients<L> {
        let parts = L::load(turned_parts(first));
        let omega = L::splat(first[OMEGA]);
        Coefficients {
            parts: self.linear(parts, self.corner),
            theta: first[OMEGA],
            omega: self.angular(parts, omega),
        }
    }

    /// Returns the (n + 1)-th coefficients from the n-th, `newest`, and the `middle` sums.
    ///
    /// `over` is 1/(n + 1).
    #[inline(always)]
    fn next(&self, newest: &Coefficients<L>, middle: L::Four, over: f64) -> Coefficients<L> {
        let scaled = |factor: L::Four| L::mul(factor, L::splat(over));
        let parts = newest.parts;
        let across = L::mul(scaled(self.across), L::swap_pairs(parts));
        let halves = L::mul(scaled(self.halves), L::swap_halves(parts));
        let itself = L::mul(scaled(self.itself), parts);
        let spun = L::mul(scaled(self.spin), newest.omega);
        let turned = L::mul(scaled(self.signs), L::swap_pairs(middle));
        let torques = L::mul(scaled(self.torque), parts);
        // Lanes 0 and 1 each hold the two torques' sum (in either order: the same bits).
        let torque = L::low_half_twice(L::add(torques, L::swap_pairs(torques)));
        Coefficients {
            parts: L::add(L::add(across, halves), L::add(L::add(itself, spun), turned)),
            theta: L::first(newest.omega) * over,
            omega: L::add(torque, L::mul(scaled(self.spin_damping), newest.omega)),
        }
    }

    /// Returns the parts' next coefficients before 1/(n + 1): `parts`' linear terms plus `rest`.
    #[inline(always)]
    fn linear(&self, parts: L::Four, rest: L::Four) -> L::Four {
        let across = L::mul(self.across, L::swap_pairs(parts));
        let halves = L::mul(self.halves, L::swap_halves(parts));
        let itself = L::mul(self.itself, parts);
        L::add(L::add(across, halves), L::add(itself, rest))
    }

    /// Returns ω's next coefficient before 1/(n + 1), in every lane.
    ///
    /// It is the torque of `parts` and the damping of `omega`.
    #[inline(always)]
    fn angular(&self, parts: L::Four, omega: L::Four) -> L::Four {
        let torques = L::mul(self.torque, parts);
        // Lanes 0 and 1 each hold the two torques' sum (in either order: the same bits).
        let torque = L::low_half_twice(L::add(torques, L::swap_pairs(torques)));
        L::add(torque, L::mul(self.spin_damping, omega))
    }
}

/// The middle of the turning's products, Σ ω_j (D, V)_(n−j) for j from 1 to n − 1.
///
/// Its two ends, ω₁ (D, V)_(n−1) and ω_(n−1) (D, V)₁, come from registers: order n − 1 was the
/// newest just before, and order 1 is kept. Its inner terms read only rows from 2 to n − 2,
/// found orders before, and two orders' inner terms are summed in one pass ([`inner_sums`]).
/// What waits on the newest orders is then a multiply and two additions, not a row written and
/// read back.
struct Middle<L: Lanes> {
    /// Order 1's coefficients, a factor of each end.
    order_one: Coefficients<L>,
    /// The order before the newest, the other factor of each end.
    previous: Coefficients<L>,
    /// The next order's inner sums, found with this order's.
    pending: L::Four,
}

impl<L: Lanes> Middle<L> {
    /// Returns the middle sums of a Taylor step whose first order is `order_one`.
    #[inline(always)]
    fn from(order_one: Coefficients<L>) -> Self {
        Self {
            order_one,
            previous: order_one,
            pending: L::splat(0.0),
        }
    }

    /// Returns the middle sums at order n (from 1) of a series up to `order`.
    ///
    /// `newest` is order n, and `series` holds the rows up to n.
    #[inline(always)]
    fn at(
        &mut self,
        n: usize,
        order: usize,
        series: &[Row; MAX_ORDER + 1],
        newest: Coefficients<L>,
    ) -> L::Four {
        let one = self.order_one;
        let sums = match n {
            1 => L::splat(0.0),
            // The middle term alone: ω₁ (D, V)₁.
            2 => L::mul(one.omega, one.parts),
            _ => {
                let inner = if n.is_multiple_of(2) {
                    self.pending
                } else if n + 1 < order {
                    let (inner, next) = inner_sums::<L, true>(n, series);
                    self.pending = next;
                    inner
                } else {
                    inner_sums::<L, false>(n, series).0
                };
                let ends = L::add(
                    L::mul(one.omega, self.previous.parts),
                    L::mul(self.previous.omega, one.parts),
                );
                L::add(inner, ends)
            }
        };
        self.previous = newest;
        sums
    }
}

/// Returns the middle sums but their ends at odd order n (from 3), and at n + 1 if `NEXT`.
///
/// Those are Σ ω_j (D, V)_(n−j) over 2 ≤ j ≤ n − 2, and order n + 1's over 2 ≤ j ≤ n − 1
/// (zero unless `NEXT`).
///
/// Each sum runs from its middle term out, pairing j with n − j, in two chains: every other
/// pair into each. The two orders' pairs share their low rows, and each high row of order
/// n + 1 is the next pair's high row of order n, so each row is read once for both.
#[inline(always)]
fn inner_sums<L: Lanes, const NEXT: bool>(
    n: usize,
    series: &[Row; MAX_ORDER + 1],
) -> (L::Four, L::Four) {
    let n = n.min(MAX_ORDER - 1);
    let operands = |row: &Row| (L::splat(row[OMEGA]), L::load(turned_parts(row)));
    let pair = |(low_omega, low_parts): (L::Four, L::Four),
                (high_omega, high_parts): (L::Four, L::Four)| {
        L::add(L::mul(low_omega, high_parts), L::mul(high_omega, low_parts))
    };
    // Order n's pairs are (half − i, half + 1 + i); order n + 1's are (half − i, half + 2 + i)
    // around its middle term, half + 1.
    let half = (n - 1) / 2;
    let zero = L::splat(0.0);
    let middle = operands(&series[half + 1]);
    let (mut this, mut this_other) = (zero, zero);
    let (mut next, mut next_other) = (
        if NEXT {
            L::mul(middle.0, middle.1)
        } else {
            zero
        },
        zero,
    );
    let mut high = middle;
    let mut low_row = half;
    while low_row >= 2 {
        let low = operands(&series[low_row]);
        let above = operands(&series[n + 1 - low_row]);
        this = L::add(this, pair(low, high));
        if NEXT {
            next = L::add(next, pair(low, above));
        }
        high = above;
        low_row -= 1;
        if low_row < 2 {
            break;
        }
        let low = operands(&series[low_row]);
        let above = operands(&series[n + 1 - low_row]);
        this_other = L::add(this_other, pair(low, high));
        if NEXT {
            next_other = L::add(next_other, pair(low, above));
        }
        high = above;
        low_row -= 1;
    }
    (L::add(this, this_other), L::add(next, next_other))
}

/// Sums a whole step's series at the default order (rows 1 to 28) at `h`, as [`polynomial`].
///
/// It runs in blocks of eight rows, each by Estrin's scheme (paired in h, the pairs in h², the
/// fours in h⁴), the blocks by Horner's rule in h⁸ from the top.
///
/// What waits on the step's size is then six multiply-adds, where Horner's rule alone waits on
/// fourteen: a stiff band's step spends most of its end waiting on its size.
#[inline(always)]
fn polynomial_28(rows: &[Row; 28], h: f64) -> Row {
    let h2 = h * h;
    let h4 = h2 * h2;
    let h8 = h4 * h4;
    let lanes = |f: &dyn Fn(usize) -> f64| -> Row { std::array::from_fn(f) };
    let two = |k: usize, i: usize| rows[k][i] + rows[k + 1][i] * h;
    let four = |k: usize, i: usize| two(k, i) + two(k + 2, i) * h2;
    let eight = |k: usize, i: usize| four(k, i) + four(k + 4, i) * h4;
    let blocks = [
        lanes(&|i| eight(0, i)),
        lanes(&|i| eight(8, i)),
        lanes(&|i| eight(16, i)),
        lanes(&|i| four(24, i)),
    ];
    let mut sum = blocks[3];
    for block in blocks[..3].iter().rev() {
        sum = std::array::from_fn(|i| block[i] + sum[i] * h8);
    }
    sum
}

/// Sums every component's series at `h`: Σ rows[n] hⁿ.
///
/// Two of Horner's chains in h², the even terms' and the odd terms', run side by side: each
/// waits on a multiply and an add per two orders instead of per order.
#[inline(always)]
fn polynomial(rows: &[Row], h: f64) -> Row {
    let h_squared = h * h;
    let pairs = rows.chunks_exact(2);
    // An odd count of rows leaves the highest, an even power: the even chain starts from it.
    let mut even = match pairs.remainder() {
        [highest] => *highest,
        _ => [0.0; LANES],
    };
    let mut odd = [0.0; LANES];
    for pair in pairs.rev() {
        even = std::array::from_fn(|i| even[i] * h_squared + pair[0][i]);
        odd = std::array::from_fn(|i| odd[i] * h_squared + pair[1][i]);
    }
    std::array::from_fn(|i| even[i] + h * odd[i])
}

/// Returns the largest of weights[i]·|values[i]| over the motion's components.
///
/// The energy is not weighed. It is found by a tree of plain comparisons: every order of the
/// series takes one, and the NaN-aware `f64::max` costs five instructions a comparison. A NaN
/// here needs no care: it reaches the state, which the step then refuses.
#[inline(always)]
fn weighted_max(weights: &Row, values: &Row) -> f64 {
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

    /// The most [`rough_log2`] is off from log2, over every positive number.
    const ROUGH_LOG2_ERROR: f64 = 0.0077;

    /// The most [`rough_exp2`] is off from 2^x, relatively.
    const ROUGH_EXP2_ERROR: f64 = 0.0027;
    use crate::physics::forces::BandEnds;
    use crate::physics::integrators::dop853;
    use crate::physics::scene::SceneParams;

    // Every binade's mantissas, the subnormals' among them.
    fn positives() -> impl Iterator<Item = f64> {
        (-1074..=1023).flat_map(|exponent| {
            (0..64).map(move |step| (1.0 + f64::from(step) / 64.0) * 2f64.powi(exponent))
        })
    }

    // The rough log2 stays within its stated error everywhere, and the bound is tight.
    #[test]
    fn the_rough_logarithm_is_within_its_error() {
        let worst = positives()
            .filter(|x| *x > 0.0 && x.is_finite())
            .map(|x| (rough_log2(x) - x.log2()).abs())
            .fold(0.0, f64::max);
        assert!(worst <= ROUGH_LOG2_ERROR, "{worst}");
        assert!(
            worst > 0.9 * ROUGH_LOG2_ERROR,
            "the bound is tight: {worst}"
        );
        assert_eq!(rough_log2(1.0), 0.0);
        assert_eq!(rough_log2(0.0), f64::NEG_INFINITY);
        assert_eq!(rough_log2(f64::INFINITY), f64::INFINITY);
        assert!(rough_log2(-1.0).is_nan() && rough_log2(f64::NAN).is_nan());
    }

    // The rough 2^x stays within its stated relative error, exact at whole numbers.
    #[test]
    fn the_rough_power_of_two_is_within_its_error() {
        let mut worst: f64 = 0.0;
        for step in -1022 * 64..1023 * 64 {
            let x = f64::from(step) / 64.0 + 1.0 / 128.0;
            worst = worst.max((rough_exp2(x) / x.exp2() - 1.0).abs());
        }
        assert!(worst <= ROUGH_EXP2_ERROR, "{worst}");
        assert!(
            worst > 0.9 * ROUGH_EXP2_ERROR,
            "the bound is tight: {worst}"
        );
        for whole in [-1022, -3, -1, 0, 1, 7, 1023] {
            assert_eq!(rough_exp2(f64::from(whole)), f64::from(whole).exp2());
        }
        assert_eq!(rough_exp2(-0.3).to_bits(), rough_exp2(-0.3).to_bits());
        assert_eq!(rough_exp2(-2000.0), 0.0);
        assert_eq!(rough_exp2(f64::INFINITY), f64::INFINITY);
        assert!(rough_exp2(f64::NAN).is_nan());
    }

    // The step's root is the least of the positive terms' and ignores the others.
    #[test]
    fn the_least_root_takes_the_smaller_step() {
        let log2_tolerance = rough_log2(1e-10);
        let step = |terms| rough_exp2(least_root(log2_tolerance, terms));
        // 1e-10 / 1e10 over 20 orders: 10^(-1); 1e-10 / 1e-6 over 19: 10^(-4/19).
        let h = step([(1e-6, RECIPROCALS[19]), (1e10, RECIPROCALS[20])]);
        assert!((h / 0.1 - 1.0).abs() < 0.01, "{h}");
        let h = step([(1e-6, RECIPROCALS[19]), (0.0, RECIPROCALS[20])]);
        assert!((h / 10f64.powf(-4.0 / 19.0) - 1.0).abs() < 0.01, "{h}");
        assert_eq!(step([(0.0, 1.0), (f64::NAN, 0.5)]), f64::INFINITY);
    }

    // The two chains sum the series as one Horner chain does, to rounding, at every length.
    #[test]
    fn the_polynomial_is_the_series_summed() {
        let rows: Vec<Row> = (0..=MAX_ORDER)
            .map(|n| std::array::from_fn(|i| ((n * 7 + i * 3) % 11) as f64 - 5.0 + 0.1 * n as f64))
            .collect();
        for h in [0.0, 0.3, -0.7, 1.3] {
            for length in 1..=rows.len() {
                let horner = rows[..length].iter().rev().fold([0.0; LANES], |sums, row| {
                    std::array::from_fn(|i| sums[i] * h + row[i])
                });
                let two_chains = polynomial(&rows[..length], h);
                // The default order's blocks, where there are its 28 rows.
                let blocks = rows[..length]
                    .first_chunk::<28>()
                    .filter(|_| length == 28)
                    .map(|rows| polynomial_28(rows, h));
                for i in 0..LANES {
                    let scale = rows[..length]
                        .iter()
                        .enumerate()
                        .map(|(n, row)| (row[i] * h.powi(n as i32)).abs())
                        .sum::<f64>();
                    for sum in std::iter::once(two_chains).chain(blocks) {
                        assert!(
                            (sum[i] - horner[i]).abs() <= 1e-14 * scale.max(1.0),
                            "length {length}, h {h}, lane {i}"
                        );
                    }
                }
                assert_eq!(blocks.is_some(), length == 28);
            }
        }
    }

    fn pulled(state: BodyState, anchor: DVec2, stiffness: f64) -> ForceModel {
        let params = SceneParams {
            stiffness,
            ..SceneParams::tutorial()
        };
        let mass = params.mass_properties().unwrap();
        params.force_model(mass, Some(BandEnds::grabbing(&mass, &state, anchor)))
    }

    // One fixed step in the turning frame lands where DOP853, in the world's, does: spinning,
    // moving, damped, on soft and stiff bands, near the anchor and a million px from it.
    #[test]
    fn a_fixed_step_agrees_with_an_independent_method() {
        // Odd and even orders (the middle sums pair them), and the default's blocked sum.
        for order in [12, 19, 26, 28, 31] {
            agrees_with_an_independent_method(TaylorSettings {
                order,
                tolerance: 1e-12,
                max_steps: 10_000,
            });
        }
    }

    fn agrees_with_an_independent_method(settings: TaylorSettings) {
        for (i, anchor) in [
            DVec2::new(200.0, 120.0),
            DVec2::new(-30.0, 80.0),
            DVec2::new(1e6, -2e5),
        ]
        .into_iter()
        .enumerate()
        {
            for stiffness in [20.0, 1e4, 1e6] {
                let state = BodyState {
                    linear: LinearState {
                        position: DVec2::new(10.0 * i as f64, -20.0),
                        velocity: DVec2::new(40.0, -15.0),
                    },
                    angular: AngularState {
                        orientation: 0.4 + i as f64,
                        angular_velocity: 3.0 - 2.0 * i as f64,
                    },
                };
                let model = pulled(state, anchor, stiffness);
                let dt = 0.01;
                let ours = integrate(&state, &model, dt, &settings).expect("within budget");
                let theirs =
                    dop853::integrate(&state, &model, model.forces(&state), dt, 1e-13, 100_000)
                        .expect("within budget");
                let error = ours.state.pose_error(&theirs.state, &model.mass);
                let size = state.linear.position.distance(anchor).max(1.0);
                assert!(
                    error < 1e-9 + RELATIVE_TOLERANCE * size,
                    "order {}, anchor {anchor}, k {stiffness}: {error}",
                    settings.order
                );
                let speed = (ours.state.linear.velocity - theirs.state.linear.velocity).length();
                let fast = theirs.state.linear.velocity.length();
                assert!(
                    speed < 1e-7 + RELATIVE_TOLERANCE * fast,
                    "anchor {anchor}, k {stiffness}: {speed}"
                );
                let heat = (ours.dissipated - theirs.dissipated).abs();
                assert!(heat <= 1e-9 * theirs.dissipated.abs().max(1.0), "{heat}");
            }
        }
    }

    // The turned state's energy is the world state's, as `ForceModel::energy` finds it.
    #[test]
    fn the_turned_energy_is_the_models() {
        for (anchor, stiffness) in [
            (DVec2::new(200.0, 120.0), 20.0),
            (DVec2::new(-3e4, 5.0), 1e7),
        ] {
            let state = BodyState {
                linear: LinearState {
                    position: DVec2::new(12.0, -40.0),
                    velocity: DVec2::new(-300.0, 75.0),
                },
                angular: AngularState {
                    orientation: 2.3,
                    angular_velocity: -6.0,
                },
            };
            let model = pulled(state, anchor, stiffness);
            let band = model.band.unwrap();
            let facing = maths::sin_cos(state.angular.orientation);
            let row = turned(&state, band.anchor, facing);
            let turned_energy = mechanical_energy(&model, band.local_point, stiffness, &row);
            let energy = model.energy(&state);
            assert!(
                (turned_energy - energy).abs() <= 1e-12 * energy,
                "{turned_energy} {energy}"
            );
        }
    }

    // With no band and no damping the box coasts: a far box moves by v·dt, rounded about once.
    #[test]
    fn a_coasting_box_far_away_moves_by_its_velocity() {
        let state = BodyState {
            linear: LinearState {
                position: DVec2::new(3e6, -1e6),
                velocity: DVec2::new(12.5, -7.25),
            },
            angular: AngularState {
                orientation: 0.7,
                angular_velocity: 2.0,
            },
        };
        let params = SceneParams {
            linear_damping: 0.0,
            angular_damping: 0.0,
            ..SceneParams::tutorial()
        };
        let model = params.force_model(params.mass_properties().unwrap(), None);
        let settings = TaylorSettings {
            order: 20,
            tolerance: 1e-10,
            max_steps: 100,
        };
        let done = integrate(&state, &model, 0.01, &settings).unwrap();
        let expected = state.linear.position + 0.01 * state.linear.velocity;
        let ulp = 3e6 * f64::EPSILON;
        assert!((done.state.linear.position - expected).length() <= 4.0 * ulp);
        assert!((done.state.linear.velocity - state.linear.velocity).length() <= 1e-12);
        assert_eq!(done.state.angular.angular_velocity, 2.0);
        assert!((done.state.angular.orientation - 0.72).abs() <= 1e-15);
    }
}
