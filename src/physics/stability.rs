//! How close a band is to blowing an integrator up, before it does: each method's one-step
//! amplification on the band's linearisation, and the stiffest band it holds at the present
//! mass, damping and step.
//!
//! The band's stiffest mode: a rectangle pulled at a corner by a band of stiffness k moves the
//! corner with ω² = k(1/m + r²/I), r the half-diagonal; for any rectangle r²/I = 3/m, so
//! ω = 2·sqrt(k/m) (the report's stability table uses the same ω). Its damping mixes the two
//! rates by the same weights: γ = (b/m + 3c)/4. Each integrator is then stepped, as the game
//! steps it, on that mode alone: a probe box of the same mass and size with a band at its
//! centre of stiffness m·ω² and linear damping m·γ, so that it only translates and its
//! x obeys x'' = −ω²x − γx' exactly. Two steps, from a unit displacement and a unit velocity,
//! give the step's 2×2 amplification matrix; its spectral radius above 1 means the method
//! grows this mode at every step, which is how a ghost blows up.
//!
//! The real box is not this linear mode, and the report's scan of the full nonlinear scene
//! finds other limits (docs/integrators.md compares them): the swing lowers the symplectic
//! methods' limit below ω·dt = 2, and once the box hangs from the band its centre lies on the
//! band's line, where the stiffest mode is sqrt(k/m), half as fast, so RK4 holds to nearly
//! twice its linear limit. This view is the band's own, at any pose; the scan is the tutorial's
//! pull.

use bevy::math::DVec2;

use super::body::BodyState;
use super::forces::BandEnds;
use super::integrators::{AutoSettings, Integrator};
use super::scene::SceneParams;
use super::stepper::Stepper;

/// The band's stiffest mode at these parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mode {
    /// Angular frequency ω (rad/s).
    pub omega: f64,
    /// Damping rate γ (/s): the mode's velocity decays as exp(−γt) without the band.
    pub damping: f64,
}

/// Returns ω of the band's stiffest mode for a band of stiffness `k` on a box of mass `m`.
pub fn omega_at(k: f64, m: f64) -> f64 {
    2.0 * (k / m).sqrt()
}

impl Mode {
    pub fn of(params: &SceneParams) -> Self {
        let m = params.mass;
        Self {
            omega: omega_at(params.stiffness, m),
            damping: (params.linear_damping / m + 3.0 * params.angular_damping) / 4.0,
        }
    }
}

/// A spectral radius up to this far above 1 is rounding, not growth.
///
/// A symplectic method's is 1 on the nose in exact arithmetic.
const GROWTH: f64 = 1e-9;

/// Computes the spectral radius of one step of `integrator` on the band's stiffest mode.
///
/// The mode is the one at `params`, the step is `dt` (NaN if a step leaves the numbers).
pub fn spectral_radius(
    integrator: Integrator,
    params: &SceneParams,
    dt: f64,
    auto: &AutoSettings,
) -> f64 {
    let mode = Mode::of(params);
    let probe_params = SceneParams {
        stiffness: params.mass * mode.omega * mode.omega,
        linear_damping: params.mass * mode.damping,
        angular_damping: 0.0,
        ..*params
    };
    let Ok(mut probe) = Stepper::new(probe_params) else {
        return f64::NAN;
    };
    probe.integrator = integrator;
    probe.auto = *auto;
    probe.band = Some(BandEnds {
        local_point: DVec2::ZERO,
        anchor: DVec2::ZERO,
    });
    let mut column = |position: f64, velocity: f64| {
        let mut start = BodyState::at_rest(DVec2::new(position, 0.0));
        start.linear.velocity.x = velocity;
        probe.state = start;
        probe.step(dt);
        (probe.state.linear.position.x, probe.state.linear.velocity.x)
    };
    // The step is linear: the columns of its matrix are the steps from a unit displacement
    // and from a velocity in the mode's own scale (so that both move the box alike), divided
    // by it.
    let (a, c) = column(1.0, 0.0);
    let scale = mode.omega.max(1.0 / dt);
    let (b, d) = column(0.0, scale);
    let (b, d) = (b / scale, d / scale);
    let trace = a + d;
    let determinant = a * d - b * c;
    let discriminant = trace * trace / 4.0 - determinant;
    if discriminant >= 0.0 {
        let root = discriminant.sqrt();
        (trace / 2.0 + root).abs().max((trace / 2.0 - root).abs())
    } else {
        // A complex pair: |λ|² is the determinant.
        determinant.abs().sqrt()
    }
}

/// Tells whether `integrator` holds the band's stiffest mode at `params` and `dt`.
pub fn holds(integrator: Integrator, params: &SceneParams, dt: f64, auto: &AutoSettings) -> bool {
    spectral_radius(integrator, params, dt, auto) <= 1.0 + GROWTH
}

/// The stiffest band an integrator holds at the present mass, damping and step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Limit {
    /// Not even the softest band tried ([`SOFTEST`]): explicit Euler without damping.
    Never,
    /// Every k up to this one.
    UpTo(f64),
    /// Every k tried, up to [`STIFFEST`]: an implicit method.
    Any,
}

/// The range of k searched.
pub const SOFTEST: f64 = 1e-2;
pub const STIFFEST: f64 = 1e12;

/// Finds the stiffest k that `integrator` holds at `params`' mass and damping and step `dt`.
///
/// It scans up by quarter decades to the first k that fails, then bisects between it and the
/// last that held (on this linear mode the stable ks form one interval from zero).
pub fn stiffest_held(
    integrator: Integrator,
    params: &SceneParams,
    dt: f64,
    auto: &AutoSettings,
) -> Limit {
    let at = |k: f64| {
        let params = SceneParams {
            stiffness: k,
            ..*params
        };
        holds(integrator, &params, dt, auto)
    };
    if !at(SOFTEST) {
        return Limit::Never;
    }
    let mut held = SOFTEST.log10();
    let top = STIFFEST.log10();
    let failed = loop {
        let next = (held + 0.25).min(top);
        if !at(10f64.powf(next)) {
            break next;
        }
        if next >= top {
            return Limit::Any;
        }
        held = next;
    };
    let (mut low, mut high) = (held, failed);
    while high - low > 1e-4 {
        let middle = (low + high) / 2.0;
        if at(10f64.powf(middle)) {
            low = middle;
        } else {
            high = middle;
        }
    }
    Limit::UpTo(10f64.powf(low))
}

/// One integrator's distance from instability at the present settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Margin {
    pub integrator: Integrator,
    /// ω·dt of the band's stiffest mode now.
    pub omega_dt: f64,
    /// The spectral radius of a step now: above 1 (and `holds` false) it blows up.
    pub spectral_radius: f64,
    pub holds: bool,
    /// The stiffest band it holds at this mass, damping and step.
    pub stiffest: Limit,
    /// ω·dt at that band: the method's limit at this damping (None for `Never` and `Any`).
    pub limit_omega_dt: Option<f64>,
}

/// Returns every integrator's margin at `params` (its step rate gives the step).
pub fn margins(params: &SceneParams, auto: &AutoSettings) -> Vec<Margin> {
    let dt = 1.0 / params.step_rate_hz;
    let omega_dt = Mode::of(params).omega * dt;
    Integrator::ALL
        .into_iter()
        .map(|integrator| {
            let spectral_radius = spectral_radius(integrator, params, dt, auto);
            let stiffest = stiffest_held(integrator, params, dt, auto);
            Margin {
                integrator,
                omega_dt,
                spectral_radius,
                holds: spectral_radius <= 1.0 + GROWTH,
                stiffest,
                limit_omega_dt: match stiffest {
                    Limit::UpTo(k) => Some(omega_at(k, params.mass) * dt),
                    Limit::Never | Limit::Any => None,
                },
            }
        })
        .collect()
}
