//! Dormand and Prince's 8(5,3) embedded Runge-Kutta pair (DOP853, as in Hairer, Nørsett and
//! Wanner's "Solving Ordinary Differential Equations I", and SciPy), with its step-size
//! control, run inside one fixed step: the best explicit Runge-Kutta candidate for `auto`'s
//! engine on the stiff pulls, kept for the report's comparison of engines and as a second,
//! independent reference (docs/integrators.md).
//!
//! The orientation is carried as a unit vector (cos θ, sin θ), whose rate of change is ω times
//! its perpendicular, so no stage calls `sin` or `cos`; θ is integrated beside it, so turns are
//! never lost.
//!
//! Everything is counted, nothing timed: the substeps taken depend only on the state, the
//! model, the step and the settings, so a run is bit-identical on every machine.

use bevy::math::DVec2;

use super::engine_state::{
    COMPONENTS, Components, DISSIPATED, RELATIVE_TOLERANCE, error_weights, pack, unpack,
};
use crate::physics::body::BodyState;
use crate::physics::forces::{ForceModel, Forces};
use crate::physics::maths;

pub const STAGES: usize = 12;

const N: usize = COMPONENTS;
type Vector = Components;

// The tableau, as SciPy's `dop853_coefficients.py` gives it (printed to f64 by a script);
// the nodes c are not needed: the scene's forces do not depend on time within a step.
/// Row i: the coefficients of stages 0..i in stage i (explicit: zero on and above the diagonal).
///
/// The tableau is public so that a test can check its order conditions.
#[rustfmt::skip]
pub const A: [[f64; STAGES]; STAGES] = [
    [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [0.05260015195876773, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [0.0197250569845379, 0.0591751709536137, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [0.02958758547680685, 0.0, 0.08876275643042054, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [0.2413651341592667, 0.0, -0.8845494793282861, 0.924834003261792, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [0.037037037037037035, 0.0, 0.0, 0.17082860872947386, 0.12546768756682242, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [0.037109375, 0.0, 0.0, 0.17025221101954405, 0.06021653898045596, -0.017578125, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [0.03709200011850479, 0.0, 0.0, 0.17038392571223998, 0.10726203044637328, -0.015319437748624402, 0.008273789163814023, 0.0, 0.0, 0.0, 0.0, 0.0],
    [0.6241109587160757, 0.0, 0.0, -3.3608926294469414, -0.868219346841726, 27.59209969944671, 20.154067550477894, -43.48988418106996, 0.0, 0.0, 0.0, 0.0],
    [0.47766253643826434, 0.0, 0.0, -2.4881146199716677, -0.590290826836843, 21.230051448181193, 15.279233632882423, -33.28821096898486, -0.020331201708508627, 0.0, 0.0, 0.0],
    [-0.9371424300859873, 0.0, 0.0, 5.186372428844064, 1.0914373489967295, -8.149787010746927, -18.52006565999696, 22.739487099350505, 2.4936055526796523, -3.0467644718982196, 0.0, 0.0],
    [2.273310147516538, 0.0, 0.0, -10.53449546673725, -2.0008720582248625, -17.9589318631188, 27.94888452941996, -2.8589982771350235, -8.87285693353063, 12.360567175794303, 0.6433927460157636, 0.0],
];
/// The eighth-order weights (row 12 of the extended tableau).
pub const B: [f64; STAGES] = [
    0.054293734116568765,
    0.0,
    0.0,
    0.0,
    0.0,
    4.450312892752409,
    1.8915178993145003,
    -5.801203960010585,
    0.3111643669578199,
    -0.1521609496625161,
    0.20136540080403034,
    0.04471061572777259,
];
/// The fifth- and third-order error estimators, over the 12 stages and the derivative at the end.
pub const E5: [f64; STAGES + 1] = [
    0.01312004499419488,
    0.0,
    0.0,
    0.0,
    0.0,
    -1.2251564463762044,
    -0.4957589496572502,
    1.6643771824549864,
    -0.35032884874997366,
    0.3341791187130175,
    0.08192320648511571,
    -0.022355307863886294,
    0.0,
];
pub const E3: [f64; STAGES + 1] = [
    -0.18980075407240762,
    0.0,
    0.0,
    0.0,
    0.0,
    4.450312892752409,
    1.8915178993145003,
    -5.801203960010585,
    -0.4226823213237919,
    -0.1521609496625161,
    0.20136540080403034,
    0.02265179219836082,
    0.0,
];

/// Step-size control as in Hairer's and SciPy's DOP853.
const SAFETY: f64 = 0.9;
const MIN_FACTOR: f64 = 0.2;
const MAX_FACTOR: f64 = 10.0;
const ERROR_EXPONENT: f64 = -1.0 / 8.0;

/// The right-hand side, with every constant of the force model unpacked once per fixed step.
struct Rhs {
    band: Option<(DVec2, DVec2)>,
    stiffness: f64,
    inverse_mass: f64,
    inverse_inertia: f64,
    linear_damping: f64,
    /// c·I: the angular damping torque per unit ω.
    angular_damping_torque: f64,
}

impl Rhs {
    fn of(model: &ForceModel) -> Self {
        Self {
            band: model.band.map(|band| (band.local_point, band.anchor)),
            stiffness: model.stiffness,
            inverse_mass: model.mass.inverse_mass(),
            inverse_inertia: model.mass.inverse_inertia(),
            linear_damping: model.linear_damping,
            angular_damping_torque: model.angular_damping * model.mass.inertia(),
        }
    }

    /// Returns the time derivative of `y`, given the band's force and torque at `y`.
    fn rate_with(&self, y: &Vector, force: DVec2, torque: f64) -> Vector {
        let (vx, vy, omega) = (y[5], y[6], y[7]);
        let damping_force = -self.linear_damping * DVec2::new(vx, vy);
        let damping_torque = -self.angular_damping_torque * omega;
        let acceleration = (force + damping_force) * self.inverse_mass;
        [
            vx,
            vy,
            -omega * y[3],
            omega * y[2],
            omega,
            acceleration.x,
            acceleration.y,
            (torque + damping_torque) * self.inverse_inertia,
            self.linear_damping * (vx * vx + vy * vy) + self.angular_damping_torque * omega * omega,
        ]
    }

    /// Returns the time derivative of `y` at the cost of one force evaluation.
    ///
    /// The band's force is as `BandEnds::wrench` computes it, with the rotation read from
    /// (cos θ, sin θ) instead of computed from θ.
    fn rate(&self, y: &Vector) -> Vector {
        let (force, torque) = match self.band {
            None => (DVec2::ZERO, 0.0),
            Some((local, anchor)) => {
                let (cos, sin) = (y[2], y[3]);
                let arm = DVec2::new(cos * local.x - sin * local.y, sin * local.x + cos * local.y);
                let point = DVec2::new(y[0], y[1]) + arm;
                let force = self.stiffness * (anchor - point);
                (force, arm.perp_dot(force))
            }
        };
        self.rate_with(y, force, torque)
    }
}

/// What one fixed step of the engine did.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Integrated {
    pub state: BodyState,
    /// Substeps tried, accepted or rejected: the work done is 12 force evaluations each.
    pub attempts: u32,
    /// Energy damping took out, integrated with the same stages (eighth order).
    pub dissipated: f64,
}

/// λh of the first substep of a fixed step, where λ is the fastest rate of the motion.
///
/// It matches roughly what the controller settles on at tolerances near 1e-9, so that few first
/// substeps are rejected.
const FIRST_SUBSTEP_LAMBDA_H: f64 = 0.3;

/// Advances `state` by `dt` with error-controlled DOP853 substeps, each within `tolerance` (px).
///
/// `start` holds the forces at `state`. None when the step needs more than `budget` substeps
/// (expected beforehand, or found on the way).
pub fn integrate(
    state: &BodyState,
    model: &ForceModel,
    start: Forces,
    dt: f64,
    tolerance: f64,
    budget: u32,
) -> Option<Integrated> {
    let expected = (model.fastest_rate(state) * dt / FIRST_SUBSTEP_LAMBDA_H)
        .ceil()
        .max(1.0);
    if expected.is_nan() || expected > f64::from(budget) {
        return None;
    }
    let rhs = Rhs::of(model);
    let mut y = pack(state);
    let mut f = rhs.rate_with(&y, start.applied.force, start.applied.torque);

    let weights = error_weights(state, model, dt);

    let mut remaining = dt;
    let mut h = dt / expected;
    let mut attempts = 0u32;
    let mut rejected = false;
    let mut k = [[0.0; N]; STAGES + 1];
    loop {
        // Split what is left into equal substeps no longer than h, so that no sliver is left
        // at the end.
        let last;
        {
            let pieces = (remaining / h).ceil().max(1.0);
            last = pieces <= 1.0;
            h = if last { remaining } else { remaining / pieces };
        }
        if attempts >= budget {
            return None;
        }
        attempts += 1;

        k[0] = f;
        for s in 1..STAGES {
            let mut stage = y;
            for (j, kj) in k.iter().enumerate().take(s) {
                let a = A[s][j];
                if a != 0.0 {
                    for i in 0..N {
                        stage[i] += h * a * kj[i];
                    }
                }
            }
            k[s] = rhs.rate(&stage);
        }
        let mut next = y;
        for (j, kj) in k.iter().enumerate().take(STAGES) {
            for i in 0..N {
                next[i] += h * B[j] * kj[i];
            }
        }
        if !next.iter().all(|v| v.is_finite()) {
            // Far past stability: shrink hard and try again.
            h *= MIN_FACTOR;
            rejected = true;
            continue;
        }
        let f_next = rhs.rate(&next);
        k[STAGES] = f_next;

        // DOP853's error norm: the fifth-order estimate, damped by the third-order one where
        // the two disagree (a step far too long for either).
        let (mut e5, mut e3) = (0.0, 0.0);
        for i in 0..N {
            let (mut d5, mut d3) = (0.0, 0.0);
            for (j, kj) in k.iter().enumerate() {
                d5 += E5[j] * kj[i];
                d3 += E3[j] * kj[i];
            }
            // Relative to the size of the component too, so that round-off far from the
            // origin (the anchor a million px away) is never asked to beat the tolerance.
            let size = y[i].abs().max(next[i].abs());
            let scale = weights[i] / (tolerance + RELATIVE_TOLERANCE * weights[i] * size);
            e5 += (d5 * scale) * (d5 * scale);
            e3 += (d3 * scale) * (d3 * scale);
        }
        let error = if e5 == 0.0 && e3 == 0.0 {
            0.0
        } else {
            h * e5 / ((e5 + 0.01 * e3) * N as f64).sqrt()
        };

        if error <= 1.0 {
            y = next;
            f = f_next;
            remaining -= h;
            if last {
                break;
            }
            let mut factor = if error == 0.0 {
                MAX_FACTOR
            } else {
                (SAFETY * maths::powf(error, ERROR_EXPONENT)).min(MAX_FACTOR)
            };
            if rejected {
                factor = factor.min(1.0);
            }
            rejected = false;
            h *= factor;
        } else {
            h *= (SAFETY * maths::powf(error, ERROR_EXPONENT)).max(MIN_FACTOR);
            rejected = true;
        }
    }
    Some(Integrated {
        state: unpack(&y),
        attempts,
        dissipated: y[DISSIPATED],
    })
}
