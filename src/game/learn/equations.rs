//! The quantities a chapter's equations show, read from the body's components, the scene's
//! parameters and the band, and each equation written twice: in symbols, then with this
//! frame's numbers substituted, in the HUD's one number format.

use bevy::math::DVec2;

use super::chapters::Equation;
use super::twin::Twin;
use crate::game::theme::precise;
use crate::physics::forces::ForceModel;
use crate::physics::integrators::seed::{SeedStages, tutorial_stages};
use crate::physics::{
    AutoSettings, BandEnds, BodyState, EnergyLedger, Integrator, MassProperties, SceneParams,
    Stepper, rotate,
};

/// A ghost's energy and its books' error (E minus what the books say), for the update loop.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GhostBooks {
    pub energy: f64,
    pub residual: f64,
}

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
    /// The energy right after the latest step, which the books are kept against.
    pub settled_energy: f64,
    /// The integrator the game steps with.
    pub integrator: Integrator,
    /// The state after the next step, with the game's integrator, and Στ there.
    pub next: Option<(BodyState, f64)>,
    /// The point masses across the box, n (I = Σ mₖ |rₖ|² over n × n of them).
    pub point_masses: u32,
    /// The seed's and explicit Euler's ghosts, stepped from the same start.
    pub update_order: Option<[GhostBooks; 2]>,
    pub dt: f64,
    /// The centre twin's state, when a chapter shows one ([`super::twin`]).
    pub twin: Option<BodyState>,
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
            settled_energy: ledger.expected(),
            integrator: Integrator::default(),
            next: None,
            point_masses: 1,
            update_order: None,
            dt: params.dt(),
            twin: None,
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

    /// Adds the energy right after the latest step and the integrator that took it.
    pub fn with_books(self, settled_energy: f64, integrator: Integrator) -> Self {
        Self {
            settled_energy,
            integrator,
            ..self
        }
    }

    /// Adds the next step, taken on a copy with the game's integrator, and Στ after it.
    pub fn with_next_step(
        self,
        mass: &MassProperties,
        params: &SceneParams,
        band: Option<BandEnds>,
        auto: AutoSettings,
    ) -> Self {
        let mut stepper = Stepper {
            params: *params,
            mass: *mass,
            state: self.state,
            band,
            integrator: self.integrator,
            auto,
        };
        stepper.step(params.dt());
        let after = Self {
            state: stepper.state,
            band: band.map(|band| (band.attachment(&stepper.state), band.anchor)),
            ..self
        };
        Self {
            next: Some((stepper.state, after.torque_sum())),
            ..self
        }
    }

    /// Adds the number of point masses across the box.
    pub fn with_point_masses(self, point_masses: u32) -> Self {
        Self {
            point_masses,
            ..self
        }
    }

    /// Adds the seed's and explicit Euler's ghosts' books.
    pub fn with_update_order(self, update_order: Option<[GhostBooks; 2]>) -> Self {
        Self {
            update_order,
            ..self
        }
    }

    /// Returns Σ mₖ |rₖ|² over n × n equal masses at the centres of the box's n × n cells.
    pub fn point_mass_inertia(&self) -> f64 {
        let n = self.point_masses.max(1);
        let share = self.mass / f64::from(n * n);
        point_mass_arms(self.size, n)
            .map(|r| share * r.length_squared())
            .sum()
    }

    /// Returns where the point masses' centre of mass lies from the box's centre, in the world.
    pub fn point_mass_centre(&self) -> DVec2 {
        let n = self.point_masses.max(1);
        let share = self.mass / f64::from(n * n);
        let turned = |r: DVec2| rotate(r, self.state.angular.orientation);
        point_mass_arms(self.size, n)
            .map(|r| share * turned(r))
            .sum::<DVec2>()
            / self.mass
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

/// Returns the arms rₖ of n × n equal masses at the centres of a box's n × n cells.
///
/// The moment of inertia's chapter sums over them and draws them.
pub fn point_mass_arms(size: DVec2, n: u32) -> impl Iterator<Item = DVec2> {
    let n = n.max(1);
    let cell = size / f64::from(n);
    (0..n).flat_map(move |i| {
        (0..n).map(move |j| {
            DVec2::new(
                (f64::from(i) + 0.5) * cell.x - 0.5 * size.x,
                (f64::from(j) + 0.5) * cell.y - 0.5 * size.y,
            )
        })
    })
}

/// Formats a number as the HUD writes it.
fn n(value: f64) -> String {
    precise(value).replace('-', "−")
}

/// Formats a factor after an operator: a negative one in parentheses, `× (−0.6)`.
fn f_(value: f64) -> String {
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
    match equation {
        Equation::ForceSum => force_sum(q),
        Equation::Acceleration => acceleration(q),
        Equation::Motion => motion(q),
        Equation::Orientation => orientation(q),
        Equation::AngularDecay => angular_decay(q),
        Equation::Arm => arm(q),
        Equation::Torque => torque(q),
        Equation::PointVelocity => point_velocity(q),
        Equation::CentrePull => centre_pull(q),
        Equation::PointMasses => point_masses(q),
        Equation::Inertia => inertia(q),
        Equation::AngularMomentum => angular_momentum(q),
        Equation::AngularAcceleration => angular_acceleration(q),
        Equation::Spring => spring(q),
        Equation::NearestCorner => nearest_corner(q),
        Equation::LinearDamping => linear_damping(q),
        Equation::AngularDamping => angular_damping(q),
        Equation::Energy => energy(q),
        Equation::Ledger => ledger(q),
        Equation::Update => update(q),
        Equation::UpdateOrder => update_order(q),
        Equation::OutlineEnergy => outline_energy(q),
    }
}

/// Hides what an equation's lines would tell of the chapter's answer before it is given.
///
/// The update loop's lines 4 and 5 say which v moves x.
pub fn hide_the_answer(equation: Equation, lines: &mut Vec<String>) {
    match equation {
        Equation::Update => {
            lines.truncate(3);
            lines.push("4, 5  ω, θ, v and x: shown once you have answered".to_owned());
        }
        // Which corner the band keeps is chapter 5's question.
        Equation::NearestCorner => {
            *lines = vec!["p: the band's point on the box; q: the pointer".to_owned()];
        }
        // Which gains more energy is chapter 8's.
        Equation::OutlineEnergy => lines.truncate(1),
        _ => {}
    }
}

/// Returns the lines of ΣF, the band's and damping's forces summed.
fn force_sum(q: &Quantities) -> Vec<String> {
    let sum = q.force_sum();
    vec![format!(
        "ΣF = F_band + F_damp = {} + {} = {} mu·px/s²",
        v(q.band_force()),
        v(q.damping_force()),
        v(sum)
    )]
}

/// Returns the lines of a = ΣF / m.
fn acceleration(q: &Quantities) -> Vec<String> {
    let m = n(q.mass);
    let sum = q.force_sum();
    vec![format!(
        "a = ΣF / m = {} / {m} = {} px/s²",
        v(sum),
        v(sum / q.mass)
    )]
}

/// Returns the lines of the position and its velocity.
fn motion(q: &Quantities) -> Vec<String> {
    let x = q.state.linear.position;
    let velocity = q.state.linear.velocity;
    vec![format!(
        "x = {} px   v = dx/dt = {} px/s   momentum m v = {} mu·px/s",
        v(x),
        v(velocity),
        v(q.mass * velocity)
    )]
}

/// Returns the lines of the angle and its rate.
fn orientation(q: &Quantities) -> Vec<String> {
    let theta = q.state.angular.orientation;
    let omega = q.state.angular.angular_velocity;
    vec![format!(
        "θ = {} rad   ω = dθ/dt = {} rad/s",
        n(theta),
        n(omega)
    )]
}

/// Returns the lines of damping's share of dω/dt.
fn angular_decay(q: &Quantities) -> Vec<String> {
    let omega = q.state.angular.angular_velocity;
    vec![format!(
        "damping's part of dω/dt = −c ω = −{}·{} = {} rad/s²",
        n(q.angular_damping),
        f_(omega),
        n(-q.angular_damping * omega)
    )]
}

/// Returns the lines of the arm r from the centre to the band's corner.
fn arm(q: &Quantities) -> Vec<String> {
    let x = q.state.linear.position;
    match q.band {
        Some((corner, _)) => vec![format!(
            "r = p − x = {} − {} = {} px",
            v(corner),
            v(x),
            v(q.arm())
        )],
        None => vec!["r = p − x: no band yet".to_owned()],
    }
}

/// Returns the lines of τ = r × F of the band.
fn torque(q: &Quantities) -> Vec<String> {
    let (r, f) = (q.arm(), q.band_force());
    vec![format!(
        "τ = r × F = r_x·F_y − r_y·F_x = {}·{} − {}·{} = {} mu·px²/s²",
        n(r.x),
        f_(f.y),
        f_(r.y),
        f_(f.x),
        n(q.band_torque())
    )]
}

/// Returns the lines of the band's corner's velocity, v + ω r⊥.
fn point_velocity(q: &Quantities) -> Vec<String> {
    let velocity = q.state.linear.velocity;
    let omega = q.state.angular.angular_velocity;
    match q.band {
        Some(_) => {
            let r = q.arm();
            let perp = DVec2::new(-r.y, r.x);
            vec![format!(
                "v_p = v + ω r⊥ = {} + {}·{} = {} px/s",
                v(velocity),
                n(omega),
                v(perp),
                v(velocity + omega * perp)
            )]
        }
        None => vec!["v_p = v + ω r⊥, r⊥ = (−r_y, r_x): at the band's corner".to_owned()],
    }
}

/// Returns the lines of the twin's sum and its zero torque.
fn centre_pull(q: &Quantities) -> Vec<String> {
    match (q.twin, q.band) {
        (Some(twin), Some(_)) => vec![
            format!(
                "outline: the box's ΣF = {} + {} as if at its centre, a = ΣF / m = {}",
                v(q.band_force()),
                // Its velocity is the box's, so its damping is too.
                v(q.damping_force()),
                v((q.band_force() + q.damping_force()) / q.mass)
            ),
            format!(
                "outline: r = 0, no torque about its centre, θ = {} rad",
                n(twin.angular.orientation)
            ),
        ],
        _ => vec![
            "outline (below): the centre alone, as if F acted there: it never turns".to_owned(),
        ],
    }
}

/// Returns the lines of I summed over point masses across the box.
fn point_masses(q: &Quantities) -> Vec<String> {
    let count = q.point_masses.max(1);
    let sum = q.point_mass_inertia();
    let x = q.state.linear.position;
    vec![
        format!(
            "I ≈ Σ mₖ |rₖ|² over {count} by {count} masses of m / {} = {} mu·px² ({}% of the \
             box's)",
            count * count,
            n(sum),
            n(100.0 * sum / q.inertia)
        ),
        format!(
            "their centre of mass Σ mₖ xₖ / m = {} = x: forces move it as if all m sat there",
            v(x + q.point_mass_centre())
        ),
    ]
}

/// Returns the lines of I of the box in closed form.
fn inertia(q: &Quantities) -> Vec<String> {
    let m = n(q.mass);
    vec![format!(
        "I = m (w² + h²) / 12 = {m}·({}² + {}²) / 12 = {} mu·px²",
        n(q.size.x),
        n(q.size.y),
        n(q.inertia)
    )]
}

/// Returns the lines of L = I ω, and its change over the next step.
fn angular_momentum(q: &Quantities) -> Vec<String> {
    let omega = q.state.angular.angular_velocity;
    let torque = q.torque_sum();
    let momentum = q.inertia * omega;
    let mut lines = vec![format!(
        "L = I ω about the centre = {}·{} = {} mu·px²/s",
        n(q.inertia),
        f_(omega),
        n(momentum)
    )];
    if let Some((after, torque_after)) = q.next {
        let change = (q.inertia * after.angular.angular_velocity - momentum) / q.dt;
        lines.push(format!(
            "over the next step ΔL / dt = {}; Στ goes {} → {}, mean {} mu·px²/s²",
            n(change),
            n(torque),
            n(torque_after),
            n(0.5 * (torque + torque_after))
        ));
    }
    lines
}

/// Returns the lines of Στ and α = Στ / I.
fn angular_acceleration(q: &Quantities) -> Vec<String> {
    let torque = q.torque_sum();
    vec![
        format!(
            "Στ = τ_band + τ_damp = {} + {} = {} mu·px²/s²",
            n(q.band_torque()),
            f_(q.damping_torque()),
            n(torque)
        ),
        format!(
            "α = Στ / I = {} / {} = {} rad/s²",
            f_(torque),
            n(q.inertia),
            n(torque / q.inertia)
        ),
    ]
}

/// Returns the lines of the band's force F = −k (p − q).
fn spring(q: &Quantities) -> Vec<String> {
    match q.band {
        Some((corner, anchor)) => vec![format!(
            "F = −k (p − q) = −{}·({} − {}) = {} mu·px/s²",
            n(q.stiffness),
            v(corner),
            v(anchor),
            v(q.band_force())
        )],
        None => vec!["F = −k (p − q): no band yet".to_owned()],
    }
}

/// Returns the lines of the corner the band holds and the anchor.
fn nearest_corner(q: &Quantities) -> Vec<String> {
    match q.band {
        Some((corner, anchor)) => vec![format!(
            "p = the corner nearest q at the press, held since: p = {}; q = {}; |p − q| = {} px",
            v(corner),
            v(anchor),
            n(corner.distance(anchor))
        )],
        None => vec!["p = the corner nearest the pointer q, taken when pressed".to_owned()],
    }
}

/// Returns the lines of F_damp = −b v.
fn linear_damping(q: &Quantities) -> Vec<String> {
    let velocity = q.state.linear.velocity;
    vec![format!(
        "F_damp = −b v = −{}·{} = {} mu·px/s²",
        n(q.linear_damping),
        v(velocity),
        v(q.damping_force())
    )]
}

/// Returns the lines of τ_damp = −c I ω.
fn angular_damping(q: &Quantities) -> Vec<String> {
    let omega = q.state.angular.angular_velocity;
    vec![format!(
        "τ_damp = −c I ω = −{}·{}·{} = {} mu·px²/s²",
        n(q.angular_damping),
        n(q.inertia),
        f_(omega),
        n(q.damping_torque())
    )]
}

/// Returns the lines of E, its three terms summed.
fn energy(q: &Quantities) -> Vec<String> {
    let (linear, turning, band) = q.energy();
    vec![format!(
        "E = ½mv² + ½Iω² + ½k|p − q|² = {} + {} + {} = {} mu·px²/s²",
        n(linear),
        n(turning),
        n(band),
        n(linear + turning + band)
    )]
}

/// Returns the lines of the books and the energy's error against them.
fn ledger(q: &Quantities) -> Vec<String> {
    let books = q.ledger.expected();
    vec![
        format!(
            "books: E₀ + W_hand − W_damp = {} + {} − {} = {}",
            n(q.ledger.initial),
            f_(q.ledger.work_in),
            f_(q.ledger.dissipated),
            n(books)
        ),
        format!(
            "E after the step − books = {}: the error of {}",
            n(q.settled_energy - books),
            q.integrator.name()
        ),
    ]
}

/// Returns the lines of the `seed` integrator's five stages for the next step.
fn update(q: &Quantities) -> Vec<String> {
    let m = n(q.mass);
    let omega = q.state.angular.angular_velocity;
    // The `seed` integrator's own stages for the next step, in its order.
    let s = &q.seed;
    let after = s.after;
    vec![
        format!(
            "1  ω ← e^(−c dt) ω = {}·{} = {}   (c = {} /s)",
            n(s.damping_factor),
            f_(omega),
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
            "3  α_band = τ_band / I = {} / {} = {}   (damping acted in line 1)",
            f_(s.torque),
            n(q.inertia),
            n(s.angular_acceleration)
        ),
        format!(
            "4  ω += α_band dt → {}   θ += ω dt → {}",
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

/// Returns the lines of the box's kinetic energy and the centre outline's.
fn outline_energy(q: &Quantities) -> Vec<String> {
    let (linear, turning, _) = q.energy();
    let mut lines = vec![format!(
        "box: ½mv² + ½Iω² = {} + {} = {} mu·px²/s²",
        n(linear),
        n(turning),
        n(linear + turning)
    )];
    if let Some(outline) = q.twin {
        let moving = 0.5 * q.mass * outline.linear.velocity.length_squared();
        lines.push(format!(
            "outline: ½mv² = {} mu·px²/s², and no ½Iω²: it never turns",
            n(moving)
        ));
    }
    lines
}

/// Returns the lines of the seed's and explicit Euler's ghosts' energy and residual.
fn update_order(q: &Quantities) -> Vec<String> {
    match q.update_order {
        Some([seed, euler]) => vec![
            format!(
                "seed's ghost: E = {}, E − books = {}",
                n(seed.energy),
                n(seed.residual)
            ),
            format!(
                "explicit Euler's ghost: E = {}, E − books = {}",
                n(euler.energy),
                n(euler.residual)
            ),
        ],
        None => {
            vec!["the ghosts (G) step seed and explicit Euler from the same start".to_owned()]
        }
    }
}
