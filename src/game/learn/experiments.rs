//! Each chapter's experiment: what a frame shows it, and when it concludes, which of the
//! chapter's choices happened and why, in numbers. The answer held when the experiment began
//! is judged by it (`check_task`), so a task passes only on a right prediction.

use bevy::math::DVec2;

use super::chapters::Task;
use crate::game::theme::readable;
use crate::physics::{BandEnds, BodyState, kinetic_energy};
use crate::physics::{Integrator, MassProperties, SceneParams};

/// How far ω must change from the press for a pull's turn to count (rad/s).
pub const TURN: f64 = 1.0;
/// How far the centre must travel in chapter 1's pull before it is judged (px), at most.
pub const JUDGED_TRAVEL: f64 = 40.0;
/// How long ω is watched with the angular damping at 0 (s).
pub const SPIN_WATCH: f64 = 0.5;

/// What an experiment found, against the answer the learner held when it began.
#[derive(Debug, Clone, PartialEq)]
pub struct Verdict {
    /// The answer held when the experiment began (none chosen yet: `None`).
    pub answer: Option<usize>,
    /// The choice that happened; `None` when what was done was not the experiment.
    pub outcome: Option<usize>,
    /// What happened, with its numbers, and why.
    pub why: String,
}

impl Verdict {
    pub fn right(&self) -> bool {
        self.answer.is_some() && self.answer == self.outcome
    }
}

/// What an experiment has seen since its chapter began.
#[derive(Debug, Default, Clone)]
pub(super) struct Progress {
    /// The answer held when the experiment under way began: the one it is judged by.
    pub(super) committed: Option<usize>,
    pub(super) verdict: Option<Verdict>,
    /// The experiment under way has been judged (a new press, release or setting starts one).
    pub(super) judged: bool,
    /// A pull under way: where it started, θ and ω then.
    pub(super) pull_start: Option<(DVec2, f64, f64)>,
    /// The band's point on the box, in its own coordinates, and its torque as the pull began.
    pub(super) pull_point: DVec2,
    pub(super) pull_torque: f64,
    /// The band's stretch as the pull began (px).
    pub(super) pull_stretch: f64,
    /// When the pull under way began (the fixed clock, s).
    pub(super) pull_clock: f64,
    /// The pull under way is, or was at some moment, the player's own.
    pub(super) players: bool,
    /// The farthest the band's line of action has passed from the centre in this pull (px).
    pub(super) worst_miss: f64,
    /// ω and the fixed clock when the angular damping was first seen at 0.
    pub(super) window: Option<(f64, f64)>,
    /// ω's change over the latest single step (rad/s), τ_band and I then.
    pub(super) before: Option<(f64, f64, f64)>,
    /// A pull let go: the most kinetic energy since, and when (the fixed clock, s).
    pub(super) released: Option<f64>,
    pub(super) released_at: f64,
    /// The band's own change of ω over the pull under way: ∫ τ_band dt / I.
    pub(super) band_turn: f64,
    pub(super) pulled: bool,
    /// The state at the end of the previous frame.
    pub(super) last_state: Option<BodyState>,
    /// The game was paused in the previous frame.
    ///
    /// A step now is a single step, not the remainder of the frame that paused it.
    pub(super) was_paused: bool,
    pub(super) steps_seen: u64,
    /// The answer whose try this experiment has counted (a try counts once an experiment).
    pub(super) tried: Option<usize>,
}

/// What a frame shows an experiment: the box, its player's band and any band, the settings.
pub(super) struct Look<'a> {
    pub(super) state: BodyState,
    pub(super) mass: &'a MassProperties,
    pub(super) params: &'a SceneParams,
    /// The player's own band (a scene's script is not the player's pull).
    pub(super) player_band: Option<BandEnds>,
    pub(super) any_band: Option<BandEnds>,
    /// The fixed clock (s), and the steps this frame took while paused (else 0).
    pub(super) clock: f64,
    /// The simulated time this frame's steps covered.
    pub(super) stepped_seconds: f64,
    pub(super) integrator: Integrator,
    /// The answer chosen now.
    pub(super) answer: Option<usize>,
    pub(super) single_step: bool,
}

/// What an experiment concluded: the choice that happened (`None`: not the experiment), and why.
pub type Found = Option<(Option<usize>, String)>;

/// Feeds this frame to the chapter's experiment and returns what it concluded, if it did.
pub(super) fn observe(task: Task, progress: &mut Progress, look: &Look) -> Found {
    let finite = look.state.to_array().iter().all(|x| x.is_finite());
    if !finite || !kinetic_energy(&look.state, look.mass).is_finite() {
        if progress.judged {
            return None;
        }
        return Some((
            None,
            "the step blew up: lower k or b, raise the mass, or take more steps a second (the \
             Stability card)"
                .to_owned(),
        ));
    }
    match task {
        Task::TurnThroughTheCentre => turn_through_the_centre(progress, look),
        Task::SpinWithoutDamping => spin_without_damping(progress, look),
        Task::SignOfTorque => sign_of_torque(progress, look),
        Task::DoubleTheInertia => double_the_inertia(progress, look),
        Task::HeldCorner => held_corner(progress, look),
        Task::ComeToRest => come_to_rest(progress, look),
        Task::StepOrder => step_order(progress, look),
        Task::MoreEnergy => more_energy(progress, look),
    }
}

/// Formats a number as the card does.
fn n(value: f64) -> String {
    readable(value).replace('-', "−")
}

fn v(value: DVec2) -> String {
    format!("({}, {})", n(value.x), n(value.y))
}

/// Returns the band's torque now (the core's own wrench).
fn band_torque(look: &Look, band: BandEnds) -> f64 {
    band.wrench(&look.state, look.params.stiffness).torque
}

/// Returns how far the band's line of action passes from the centre: |r × F| / |F|.
fn line_miss(look: &Look, band: BandEnds) -> f64 {
    let state = &look.state;
    let force = band.wrench(state, look.params.stiffness).force;
    let arm = band.attachment(state) - state.linear.position;
    if force.length() == 0.0 {
        0.0
    } else {
        arm.perp_dot(force).abs() / force.length()
    }
}

/// Starts a pull when a band appears, and forgets it when the band goes.
///
/// The band is the scene's or the player's.
/// Returns the band while the pull is on.
fn follow_pull(progress: &mut Progress, look: &Look) -> Option<BandEnds> {
    let Some(band) = look.any_band else {
        progress.pull_start = None;
        return None;
    };
    if progress.pull_start.is_none() {
        let angular = look.state.angular;
        progress.pull_start = Some((
            look.state.linear.position,
            angular.orientation,
            angular.angular_velocity,
        ));
        progress.pull_point = band.local_point;
        progress.pull_clock = look.clock;
        progress.pull_torque = band_torque(look, band);
        progress.pull_stretch = band.length(&look.state);
        progress.players = false;
        progress.worst_miss = 0.0;
        progress.band_turn = 0.0;
        progress.committed = look.answer;
        progress.judged = false;
    }
    progress.players |= look.player_band.is_some();
    Some(band)
}

/// Says what a chapter whose pull is the scene's makes of a pull of the player's own.
fn not_the_chapters_pull(what: &str) -> String {
    format!("that was your own pull, not the chapter's: {what}; ↺ restart plays the chapter's pull")
}

fn turn_through_the_centre(progress: &mut Progress, look: &Look) -> Found {
    let band = follow_pull(progress, look)?;
    progress.worst_miss = progress.worst_miss.max(line_miss(look, band));
    let (from, angle, spin) = progress.pull_start?;
    // 40 px, or half the band's stretch where the corner starts nearer its end than 80 px (a
    // box about as large as the scene's pull).
    let travel = JUDGED_TRAVEL.min(0.5 * progress.pull_stretch);
    if progress.judged {
        return None;
    }
    if travel < 1.0 {
        return Some((
            None,
            format!(
                "the corner starts {} px from the band's end, so the band hardly pulls: another \
                 size moves the box",
                n(progress.pull_stretch)
            ),
        ));
    }
    let moved = look.state.linear.position.distance(from);
    if moved < travel {
        return None;
    }
    let angular = look.state.angular;
    let (turned, spun) = (angular.orientation - angle, angular.angular_velocity - spin);
    if progress.players {
        let what = format!("it turned the box {} rad", n(turned));
        return Some((None, not_the_chapters_pull(&what)));
    }
    if spin != 0.0 {
        return Some((
            None,
            format!(
                "the box was already turning (ω = {} rad/s): ↺ restart starts it at rest",
                n(spin)
            ),
        ));
    }
    // A pull through the centre has no torque about it to the bit (the box's corner, its
    // centre and the pointer on one line); the band of a box that is not square misses it.
    let size = look.mass.size();
    let reach = size.length() / 2.0;
    let miss = progress.worst_miss;
    if miss > 1e-9 * reach {
        return Some((
            None,
            format!(
                "this box is {} × {} px, not square: its corner's diagonal misses the centre by \
                 up to {} px, so the pull does not pass through it",
                n(size.x),
                n(size.y),
                n(miss)
            ),
        ));
    }
    let outcome = usize::from(turned.abs() <= 1e-9 && spun.abs() <= 1e-9);
    let why = if outcome == 1 {
        format!(
            "over {} px θ changed by {} rad and ω by {} rad/s: the band's line passed through \
             the centre, so its torque about the centre, τ = r × F, was 0",
            n(travel),
            n(turned),
            n(spun)
        )
    } else {
        format!(
            "over {} px θ changed by {} rad and ω by {} rad/s: something gave a torque about \
             the centre",
            n(travel),
            n(turned),
            n(spun)
        )
    };
    Some((Some(outcome), why))
}

/// How long the outline's chapter watches the band pull (s).
pub const ENERGY_WATCH: f64 = 0.5;

fn more_energy(progress: &mut Progress, look: &Look) -> Found {
    follow_pull(progress, look)?;
    if progress.judged || look.clock - progress.pull_clock < ENERGY_WATCH {
        return None;
    }
    let state = &look.state;
    let boxed = kinetic_energy(state, look.mass);
    // The outline moves with the box's centre and never turns.
    let mut outline = *state;
    outline.angular.angular_velocity = 0.0;
    let centre = kinetic_energy(&outline, look.mass);
    if progress.players {
        let what = format!(
            "the box has {} mu·px²/s², the outline {} mu·px²/s²",
            n(boxed),
            n(centre)
        );
        return Some((None, not_the_chapters_pull(&what)));
    }
    let outcome = if boxed > centre * (1.0 + 1e-9) {
        0
    } else if boxed >= centre * (1.0 - 1e-9) {
        1
    } else {
        2
    };
    let turning = boxed - centre;
    Some((
        Some(outcome),
        format!(
            "both have ½ m v² = {}, and the box ½ I ω² = {} on top ({} in all, mu·px²/s²): \
             the band's point on the box moved further along F than its centre did, so F did \
             more work on the box",
            n(centre),
            n(turning),
            n(boxed)
        ),
    ))
}

fn spin_without_damping(progress: &mut Progress, look: &Look) -> Found {
    let omega = look.state.angular.angular_velocity;
    if look.params.angular_damping != 0.0 || look.any_band.is_some() {
        progress.window = None;
        progress.judged = false;
        return None;
    }
    if progress.judged {
        return None;
    }
    let Some((from, since)) = progress.window else {
        progress.window = Some((omega, look.clock));
        progress.committed = look.answer;
        return None;
    };
    if look.clock - since < SPIN_WATCH {
        return None;
    }
    if from.abs() < 1.0 {
        return Some((
            None,
            format!(
                "the spin had died down (ω = {} rad/s): ↺ restart spins it again",
                n(from)
            ),
        ));
    }
    let outcome = if (omega - from).abs() <= 1e-9 * from.abs() {
        1
    } else if omega.abs() < from.abs() {
        0
    } else {
        2
    };
    let why = if outcome == 1 {
        "with c = 0 and no band, no torque acts: dω/dt = −c ω = 0, and the box turns on at the \
         same rate"
    } else {
        "with c = 0 and no band, something still gave a torque"
    };
    Some((
        Some(outcome),
        format!(
            "ω went from {} to {} rad/s in {} s: {why}",
            n(from),
            n(omega),
            n(look.clock - since)
        ),
    ))
}

fn sign_of_torque(progress: &mut Progress, look: &Look) -> Found {
    if look.any_band.is_none() && progress.pull_start.is_some() && !progress.judged {
        // Let go before its torque turned the box enough to judge: said, not waited on.
        progress.pull_start = None;
        return Some((
            None,
            format!(
                "the pull ended with its torque having changed ω by {} rad/s, under the {} \
                 rad/s judged: a stiffer band or a lighter box turns it more (↺ restart)",
                n(progress.band_turn),
                n(TURN)
            ),
        ));
    }
    let band = follow_pull(progress, look)?;
    let torque = band_torque(look, band);
    let band_step = band_mode(look) * look.params.dt();
    if band_step > 2.0 && !progress.judged {
        return Some((
            None,
            format!(
                "with this band the step cannot follow ω (ω dt = {} > 2): lower k or raise the \
                 mass",
                n(band_step)
            ),
        ));
    }
    // The band's own part of ω's change: ∫ τ_band dt / I over the pull, not damping's, the
    // torque taken at the frame's two ends.
    let before = progress.last_state.map_or(torque, |state| {
        band.wrench(&state, look.params.stiffness).torque
    });
    progress.band_turn += 0.5 * (before + torque) / look.mass.inertia() * look.stepped_seconds;
    let turn = progress.band_turn;
    if progress.judged || turn.abs() < TURN {
        return None;
    }
    if progress.players {
        let what = format!("its torque changed ω by {} rad/s", n(turn));
        return Some((None, not_the_chapters_pull(&what)));
    }
    let outcome = usize::from(turn < 0.0);
    let sense = ["rose", "fell"][outcome];
    Some((
        Some(outcome),
        format!(
            "the band's torque alone changed ω by {} rad/s (∫ τ_band dt / I): ω {sense}, as the \
             sign of τ = r × F at the start ({} mu·px²/s²) says, whichever way the box was turning",
            n(turn),
            n(progress.pull_torque)
        ),
    ))
}

fn double_the_inertia(progress: &mut Progress, look: &Look) -> Found {
    let Some(band) = look.any_band else {
        progress.before = None;
        return None;
    };
    if !look.single_step {
        // While the box runs, τ_band moves with it: the steps compared are single steps.
        if look.stepped_seconds > 0.0 {
            progress.before = None;
        }
        return None;
    }
    let last = progress.last_state?;
    let change = look.state.angular.angular_velocity - last.angular.angular_velocity;
    let (torque, inertia) = (band_torque(look, band), look.mass.inertia());
    match progress.before {
        // I doubled since the step before: judge the answer held then.
        Some((change_then, torque_then, inertia_then))
            if inertia >= 2.0 * inertia_then * (1.0 - 1e-12) =>
        {
            progress.before = Some((change, torque, inertia));
            let grown = inertia / inertia_then;
            if grown > 2.04 {
                return Some((
                    None,
                    format!(
                        "I went × {}, not × 2: ↺ restart and double it (mass × 2 or size × 1.42)",
                        n(grown)
                    ),
                ));
            }
            let ratio = change / change_then;
            if change_then == 0.0 || !ratio.is_finite() {
                return Some((
                    None,
                    "ω did not change over the step before: the band had no torque".to_owned(),
                ));
            }
            let outcome = if ratio > 1.5 {
                0
            } else if ratio > 0.75 {
                1
            } else {
                2
            };
            Some((
                Some(outcome),
                format!(
                    "over one step ω changed by {} rad/s with I = {} mu·px², by {} with I = {} \
                     (× {}); the band's torque went {} → {} mu·px²/s²: α = τ / I",
                    n(change_then),
                    n(inertia_then),
                    n(change),
                    n(inertia),
                    n(ratio),
                    n(torque_then),
                    n(torque)
                ),
            ))
        }
        // I moved, but not to twice: keep the step from before it moved.
        Some((_, _, inertia_then)) if inertia != inertia_then => None,
        _ => {
            progress.before = Some((change, torque, inertia));
            progress.committed = look.answer;
            None
        }
    }
}

fn held_corner(progress: &mut Progress, look: &Look) -> Found {
    let band = follow_pull(progress, look)?;
    if progress.judged || !progress.players {
        return None;
    }
    let state = &look.state;
    let nearest = look.mass.corners().into_iter().min_by(|a, b| {
        let to = |corner: DVec2| state.local_to_world(corner).distance(band.anchor);
        to(*a).total_cmp(&to(*b))
    })?;
    let first = progress.pull_point;
    let to_first = state.local_to_world(first).distance(band.anchor);
    let nearer = to_first - state.local_to_world(nearest).distance(band.anchor);
    if nearer < 1.0 {
        return None;
    }
    // Judged from where the band holds now, in the box's own coordinates.
    let outcome = usize::from(band.local_point != first);
    let why = if outcome == 0 {
        format!(
            "the band held the corner {} px of the box, though the corner {} px is {} px nearer the \
             pointer: the corner is chosen once, at the press",
            v(first),
            v(nearest),
            n(nearer)
        )
    } else {
        format!(
            "the band moved from the corner {} px to {} px",
            v(first),
            v(band.local_point)
        )
    };
    Some((Some(outcome), why))
}

fn come_to_rest(progress: &mut Progress, look: &Look) -> Found {
    let state = &look.state;
    let energy = kinetic_energy(state, look.mass);
    if look.any_band.is_some() {
        progress.pulled = true;
        progress.released = None;
        return None;
    }
    if !progress.pulled {
        return None;
    }
    let most = match progress.released {
        None => {
            progress.committed = look.answer;
            progress.judged = false;
            progress.released_at = look.clock;
            energy
        }
        Some(most) => most.max(energy),
    };
    progress.released = Some(most);
    if progress.judged {
        return None;
    }
    let p = look.params;
    let inertia = look.mass.inertia();
    let (velocity, omega) = (state.linear.velocity, state.angular.angular_velocity);
    if most < 1e-6 {
        return Some((
            None,
            "the box was still when let go: pull it, then let go while it moves".to_owned(),
        ));
    }
    // With c = 0 nothing takes ω down, with b = 0 nothing takes v down: after a second
    // watched, a motion left undamped is judged to go on, however small it has become.
    let spin = 0.5 * inertia * omega * omega;
    let watched = look.clock - progress.released_at >= 1.0;
    if watched && p.angular_damping == 0.0 && omega != 0.0 {
        return Some((
            Some(1),
            format!(
                "it still turns at ω = {} rad/s: with c = 0 nothing takes ½ I ω² = {} mu·px²/s² out",
                n(omega),
                n(spin)
            ),
        ));
    }
    if watched && p.linear_damping == 0.0 && velocity != DVec2::ZERO {
        return Some((
            Some(1),
            format!(
                "it still drifts at v = {} px/s: with b = 0 nothing takes ½ m v² = {} mu·px²/s² out",
                v(velocity),
                n(energy - spin)
            ),
        ));
    }
    let damped = (p.angular_damping > 0.0 || omega == 0.0)
        && (p.linear_damping > 0.0 || velocity == DVec2::ZERO);
    if energy < 0.01 * most && damped {
        return Some((
            Some(0),
            format!(
                "its kinetic energy fell from {} to {} mu·px²/s²: b = {} mu/s takes it from v \
                 and c = {} /s from ω",
                n(most),
                n(energy),
                n(p.linear_damping),
                n(p.angular_damping)
            ),
        ));
    }
    None
}

fn step_order(progress: &mut Progress, look: &Look) -> Found {
    let held = progress.committed;
    // The answer held as this frame ends is the one the next single step is judged by.
    progress.committed = look.answer;
    if !look.single_step {
        return None;
    }
    let before: BodyState = progress.last_state?;
    let dt = look.params.dt();
    let (v0, v1) = (before.linear.velocity, look.state.linear.velocity);
    let (x0, x1) = (before.linear.position, look.state.linear.position);
    // What rounding alone can move x by: a few units in the last place of x.
    let rounding = 8.0 * f64::EPSILON * x0.length().max(x1.length()).max(1.0);
    if (v1 - v0).length() * dt <= 2.0 * rounding {
        return Some((
            None,
            "v hardly changed over that step, so both answers move x alike: resume a moment, \
             pause and step again"
                .to_owned(),
        ));
    }
    let moved = x1 - x0;
    progress.committed = held;
    let off = |v: DVec2| moved.distance(v * dt);
    if off(v0).min(off(v1)) > rounding + 1e-9 * moved.length() {
        return Some((
            None,
            format!(
                "x moved by {} px, neither v dt before ({}) nor after ({}): the integrator now \
                 stepping is not the tutorial's loop (I until seed)",
                v(moved),
                v(v0 * dt),
                v(v1 * dt)
            ),
        ));
    }
    let outcome = usize::from(off(v1) < off(v0));
    let which = ["before", "after"][outcome];
    let p = look.params;
    let moved_by = format!(
        "x moved by {} px = {} px/s · dt: the v {which} the step (before it was {}, after {})",
        v(moved),
        v(moved / dt),
        v(v0),
        v(v1)
    );
    // The limits are the tutorial's loop's: other integrators have their own (the Stability
    // card).
    let why = if look.integrator == Integrator::Seed {
        format!(
            "{moved_by}. This order follows the band only while ω dt < 2, ω = √(k (1/m + \
             |r|²/I)) its fastest mode (2 √(k/m) at a corner; more once the box shrinks under a \
             held band), here {}, and while b dt / m < 2, here {}: past either, its step gains \
             energy the physics does not have",
            n(band_mode(look) * dt),
            n(p.linear_damping * dt / look.mass.mass())
        )
    } else {
        format!("{moved_by}, with {}", look.integrator.name())
    };
    Some((Some(outcome), why))
}

/// Returns the band's fastest mode ω = √(k (1/m + |r|²/I)) (rad/s), r its point's arm.
///
/// Without a band, r is a corner's.
fn band_mode(look: &Look) -> f64 {
    let corner = BandEnds {
        local_point: look.mass.size() / 2.0,
        anchor: DVec2::ZERO,
    };
    let band = look.any_band.unwrap_or(corner);
    look.params.force_model(*look.mass, Some(band)).band_rate()
}
