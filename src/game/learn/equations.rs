//! The quantities a chapter's equations show, read from the body's components, the scene's
//! parameters and the band, and each equation written twice: in symbols, then with this
//! frame's numbers substituted, in the HUD's one number format.

use bevy::math::DVec2;

use super::chapters::Equation;
use super::twin::Twin;
use crate::game::shared::readable;
use crate::physics::forces::ForceModel;
use crate::physics::integrators::seed::{SeedStages, tutorial_stages};
use crate::physics::{BandEnds, BodyState, EnergyLedger, MassProperties, SceneParams};

/// Everything a chapter's equations read, for one frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Quantities {
    pub mass: f64,
    pub size: DVec2,
    pub inertia: f64,
    pub state: BodyState,
    pub stiffness: f64,
    pub linear_damping: f64,
    pub angular_damping: f64,
    /// The band's corner (world) and anchor, while a band acts.
    pub band: Option<(DVec2, DVec2)>,
    pub ledger: EnergyLedger,
    pub dt: f64,
    /// The centre twin's state, when a chapter shows one ([`super::twin`]).
    pub twin: Option<BodyState>,
    /// The moment of inertia the chapter started with, I₀.
    pub inertia_at_start: f64,
    /// The `seed` integrator's stages for the next step from this state, its own numbers.
    pub seed: SeedStages,
}

impl Quantities {
    pub fn of(
        state: BodyState,
        mass: &MassProperties,
        params: &SceneParams,
        band: Option<BandEnds>,
        ledger: EnergyLedger,
    ) -> Self {
        // The forces as the fixed step sums them, and the tutorial's update from them.
        let model = ForceModel {
            mass: *mass,
            band,
            stiffness: params.stiffness,
            linear_damping: params.linear_damping,
            angular_damping: params.angular_damping,
        };
        let seed = tutorial_stages(&state, &model, model.forces(&state), params.dt());
        Self {
            mass: mass.mass(),
            size: mass.size(),
            inertia: mass.inertia(),
            state,
            stiffness: params.stiffness,
            linear_damping: params.linear_damping,
            angular_damping: params.angular_damping,
            band: band.map(|band| (band.attachment(&state), band.anchor)),
            ledger,
            dt: params.dt(),
            twin: None,
            inertia_at_start: mass.inertia(),
            seed,
        }
    }

    /// Adds the centre twin's numbers, when a chapter shows one.
    pub fn with_twin(self, twin: Option<&Twin>) -> Self {
        Self {
            twin: twin.map(|twin| twin.beside(&self.state)),
            ..self
        }
    }

    /// Adds the moment of inertia the chapter started with.
    pub fn with_inertia_at_start(self, inertia_at_start: f64) -> Self {
        Self {
            inertia_at_start,
            ..self
        }
    }

    /// Returns the arm r from the centre to the band's corner (zero without a band).
    fn arm(&self) -> DVec2 {
        self.band.map_or(DVec2::ZERO, |(corner, _)| {
            corner - self.state.linear.position
        })
    }

    /// Returns the band's force F = −k (p − q) (zero without a band).
    fn band_force(&self) -> DVec2 {
        self.band.map_or(DVec2::ZERO, |(corner, anchor)| {
            -self.stiffness * (corner - anchor)
        })
    }

    /// Returns the band's torque τ = r × F.
    fn band_torque(&self) -> f64 {
        self.arm().perp_dot(self.band_force())
    }

    /// Returns the damping force −b v.
    fn damping_force(&self) -> DVec2 {
        -self.linear_damping * self.state.linear.velocity
    }

    /// Returns the damping torque −c I ω.
    fn damping_torque(&self) -> f64 {
        -self.angular_damping * self.inertia * self.state.angular.angular_velocity
    }

    fn force_sum(&self) -> DVec2 {
        self.band_force() + self.damping_force()
    }

    fn torque_sum(&self) -> f64 {
        self.band_torque() + self.damping_torque()
    }

    /// Returns the three terms of the energy ½ m v² + ½ I ω² + ½ k |p − q|².
    fn energy(&self) -> (f64, f64, f64) {
        let v = self.state.linear.velocity;
        let omega = self.state.angular.angular_velocity;
        let stretch = self
            .band
            .map_or(0.0, |(corner, anchor)| corner.distance_squared(anchor));
        (
            0.5 * self.mass * v.length_squared(),
            0.5 * self.inertia * omega * omega,
            0.5 * self.stiffness * stretch,
        )
    }
}

/// Formats a number as the HUD writes it.
fn n(value: f64) -> String {
    readable(value).replace('-', "−")
}

/// Formats a factor after an operator: a negative one in parentheses, `× (−0.6)`.
fn f(value: f64) -> String {
    if value.is_sign_negative() && value != 0.0 {
        format!("({})", n(value))
    } else {
        n(value)
    }
}

/// Formats a vector: (x, y).
fn v(value: DVec2) -> String {
    format!("({}, {})", n(value.x), n(value.y))
}

/// Returns the equation's lines: its symbols, then the same with this frame's numbers.
pub fn lines(equation: Equation, q: &Quantities) -> Vec<String> {
    let m = n(q.mass);
    let x = q.state.linear.position;
    let velocity = q.state.linear.velocity;
    let theta = q.state.angular.orientation;
    let omega = q.state.angular.angular_velocity;
    let sum = q.force_sum();
    let torque = q.torque_sum();
    match equation {
        Equation::ForceSum => vec![format!(
            "ΣF = F_band + F_damp = {} + {} = {}",
            v(q.band_force()),
            v(q.damping_force()),
            v(sum)
        )],
        Equation::Acceleration => vec![format!(
            "a = ΣF / m = {} / {m} = {}",
            v(sum),
            v(sum / q.mass)
        )],
        Equation::Motion => vec![format!("x = {}   v = dx/dt = {}", v(x), v(velocity))],
        Equation::Orientation => vec![format!(
            "θ = {} rad   ω = dθ/dt = {} rad/s",
            n(theta),
            n(omega)
        )],
        Equation::AngularDecay => vec![format!(
            "dω/dt = −c ω = −{} × {} = {} rad/s²",
            n(q.angular_damping),
            f(omega),
            n(-q.angular_damping * omega)
        )],
        Equation::Arm => match q.band {
            Some((corner, _)) => vec![format!(
                "r = p − x = {} − {} = {}",
                v(corner),
                v(x),
                v(q.arm())
            )],
            None => vec!["r = p − x: no band (press on the scene)".to_owned()],
        },
        Equation::Torque => {
            let (r, f) = (q.arm(), q.band_force());
            vec![format!(
                "τ = r × F = {} × {} = {}",
                v(r),
                v(f),
                n(q.band_torque())
            )]
        }
        Equation::CentrePull => match (q.twin, q.band) {
            (Some(twin), Some(_)) => vec![
                format!(
                    "twin: ΣF = F_band + F_damp = {} + {}, a = ΣF / m = {}",
                    v(q.band_force()),
                    // Its velocity is the box's, so its damping is too.
                    v(q.damping_force()),
                    v((q.band_force() + q.damping_force()) / q.mass)
                ),
                format!(
                    "twin: r = 0, τ = 0 × F = 0, θ = {} rad",
                    n(twin.angular.orientation)
                ),
            ],
            _ => vec!["twin (below): the box's band force at its centre, r = 0, τ = 0".to_owned()],
        },
        Equation::Inertia => vec![format!(
            "I = m (w² + h²) / 12 = {m} × ({}² + {}²) / 12 = {}",
            n(q.size.x),
            n(q.size.y),
            n(q.inertia)
        )],
        Equation::AngularAcceleration => vec![
            format!(
                "Στ = τ_band + τ_damp = {} + {} = {}",
                n(q.band_torque()),
                f(q.damping_torque()),
                n(torque)
            ),
            format!(
                "α = Στ / I = {} / {} = {} rad/s²",
                f(torque),
                n(q.inertia),
                n(torque / q.inertia)
            ),
        ],
        Equation::BandShareOfAlpha => {
            let share = q.band_torque() / q.inertia;
            vec![
                format!(
                    "τ_band / I = {} / {} = {} rad/s²",
                    f(q.band_torque()),
                    n(q.inertia),
                    n(share)
                ),
                format!(
                    "with I₀ = {}: τ_band / I₀ = {}, and I₀ / I = {}",
                    n(q.inertia_at_start),
                    n(q.band_torque() / q.inertia_at_start),
                    n(q.inertia_at_start / q.inertia)
                ),
            ]
        }
        Equation::Spring => match q.band {
            Some((corner, anchor)) => vec![format!(
                "F = −k (p − q) = −{} × ({} − {}) = {}",
                n(q.stiffness),
                v(corner),
                v(anchor),
                v(q.band_force())
            )],
            None => vec!["F = −k (p − q): no band (press on the scene)".to_owned()],
        },
        Equation::NearestCorner => match q.band {
            Some((corner, anchor)) => vec![format!(
                "p = the corner nearest q = {}: {}, {} away",
                v(anchor),
                v(corner),
                n(corner.distance(anchor))
            )],
            None => vec!["p = the corner nearest the pointer, when pressed".to_owned()],
        },
        Equation::LinearDamping => vec![format!(
            "F_damp = −b v = −{} × {} = {}",
            n(q.linear_damping),
            v(velocity),
            v(q.damping_force())
        )],
        Equation::AngularDamping => vec![format!(
            "τ_damp = −c I ω = −{} × {} × {} = {}",
            n(q.angular_damping),
            n(q.inertia),
            f(omega),
            n(q.damping_torque())
        )],
        Equation::Energy => {
            let (linear, turning, band) = q.energy();
            vec![format!(
                "E = ½mv² + ½Iω² + ½k|p − q|² = {} + {} + {} = {}",
                n(linear),
                n(turning),
                n(band),
                n(linear + turning + band)
            )]
        }
        Equation::Ledger => vec![format!(
            "E₀ + W_hand − W_damp = {} + {} − {} = {}",
            n(q.ledger.initial),
            f(q.ledger.work_in),
            f(q.ledger.dissipated),
            n(q.ledger.initial + q.ledger.work_in - q.ledger.dissipated)
        )],
        Equation::Update => {
            // The `seed` integrator's own stages for the next step, in its order.
            let s = &q.seed;
            let after = s.after;
            vec![
                format!(
                    "1  ω ← e^(−c dt) ω = {} × {} = {}   (c = {} /s)",
                    n(s.damping_factor),
                    f(omega),
                    n(s.damped_angular_velocity),
                    n(q.angular_damping)
                ),
                format!(
                    "2  a = (F_band + F_damp) / m = ({} + {}) / {m} = {}",
                    v(s.band_force),
                    v(s.damping_force),
                    v(s.acceleration)
                ),
                format!(
                    "3  α = τ_band / I = {} / {} = {}",
                    f(s.torque),
                    n(q.inertia),
                    n(s.angular_acceleration)
                ),
                format!(
                    "4  ω += α dt → {}   θ += ω dt → {}",
                    n(after.angular.angular_velocity),
                    n(after.angular.orientation)
                ),
                format!(
                    "5  v += a dt → {}   x += v dt → {}   (dt = {} s)",
                    v(after.linear.velocity),
                    v(after.linear.position),
                    n(q.dt)
                ),
            ]
        }
    }
}
