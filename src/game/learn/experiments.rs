//! Each chapter's experiment: what a frame shows it, and when it concludes, which of the
//! chapter's choices happened and why, in numbers. The answer held when the experiment began
//! is judged by it (`check_task`), so a task passes only on a right prediction.

use bevy::math::DVec2;

use super::chapters::Task;
use crate::game::theme::readable;
use crate::physics::{BandEnds, BodyState, kinetic_energy};
use crate::physics::{MassProperties, SceneParams};

/// How far the box may turn over a 40 px pull and count as not turning (rad).
pub const NOT_TURNING: f64 = 0.05;
/// How far a pull's line of action may pass from the centre and count as through it (px).
pub const THROUGH_THE_CENTRE: f64 = 3.0;
/// How long ω is watched with the angular damping at 0 (s).
pub const SPIN_WATCH: f64 = 0.5;
/// How far ω must change from the press for a pull's turn to count (rad/s).
pub const TURN: f64 = 1.0;

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
    /// The answer chosen now.
    pub(super) predicted: Option<usize>,
    /// The answer held when the experiment under way began: the one it is judged by.
    pub(super) committed: Option<usize>,
    pub(super) verdict: Option<Verdict>,
    /// The experiment under way has been judged (a new press, release or setting starts one).
    pub(super) judged: bool,
    /// A pull of the player's under way: where it started, θ and ω then.
    pub(super) pull_start: Option<(DVec2, f64, f64)>,
    /// The farthest the band's line of action has passed from the centre in this pull (px).
    pub(super) worst_miss: f64,
    /// ω and the fixed clock when the angular damping was first seen at 0.
    pub(super) window: Option<(f64, f64)>,
    /// τ_band / I, τ_band and I while the band held with I unchanged.
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
    pub(super) paused: bool,
    pub(super) single_step: bool,
}

/// What an experiment concluded: the choice that happened (`None`: not the experiment), and why.
pub type Found = Option<(Option<usize>, String)>;

/// Feeds this frame to the chapter's experiment and returns what it concluded, if it did.
pub(super) fn observe(task: Task, progress: &mut Progress, look: &Look) -> Found {
    match task {
        Task::TurnThroughTheCentre => turn_through_the_centre(progress, look),
        Task::SpinWithoutDamping => spin_without_damping(progress, look),
        Task::SignOfTorque => sign_of_torque(progress, look),
        Task::DoubleTheInertia => double_the_inertia(progress, look),
        Task::HeldCorner => held_corner(progress, look),
        Task::ComeToRest => come_to_rest(progress, look),
        Task::StepOrder => step_order(progress, look),
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

/// Starts a pull of the player's when the band appears, and forgets it when the band goes.
///
/// Returns the band while the pull is on.
fn follow_pull(progress: &mut Progress, look: &Look) -> Option<BandEnds> {
    let Some(band) = look.player_band else {
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
        progress.worst_miss = 0.0;
        progress.committed = progress.predicted;
        progress.judged = false;
    }
    Some(band)
}

fn turn_through_the_centre(progress: &mut Progress, look: &Look) -> Found {
    let band = follow_pull(progress, look)?;
    progress.worst_miss = progress.worst_miss.max(line_miss(look, band));
    let (from, angle, _) = progress.pull_start?;
    let moved = look.state.linear.position.distance(from);
    if progress.judged || moved < 40.0 {
        return None;
    }
    let turned = (look.state.angular.orientation - angle).abs();
    let miss = progress.worst_miss;
    if miss > THROUGH_THE_CENTRE {
        return Some((
            None,
            format!(
                "that pull's line passed up to {} px from the centre, so τ = r × F was not 0 \
                 and the box turned {} rad: pull along the diagonal to test the answer",
                n(miss),
                n(turned)
            ),
        ));
    }
    // A line `miss` px off the centre turns the box by about 40 m miss / I over the 40 px
    // (the torque F miss over the same ∫∫F dt² = 40 m that moved the centre).
    let explained = 40.0 * look.mass.mass() * miss / look.mass.inertia();
    let outcome = usize::from(turned < NOT_TURNING + explained);
    let why = if outcome == 1 {
        format!(
            "over 40 px it turned {} rad, no more than a line {} px off the centre explains: \
             through the centre, τ = r × F = 0 and ω stays 0",
            n(turned),
            n(miss)
        )
    } else {
        format!(
            "it turned {} rad over 40 px, more than its line {} px off the centre explains: \
             something else turned it (was it turning before the press?)",
            n(turned),
            n(miss)
        )
    };
    Some((Some(outcome), why))
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
        progress.committed = progress.predicted;
        return None;
    };
    if look.clock - since < SPIN_WATCH {
        return None;
    }
    if from.abs() < 1.0 {
        return Some((
            None,
            format!(
                "the spin had died down (ω = {} rad/s): ◂ back and next ▸ spin it again",
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
    Some((
        Some(outcome),
        format!(
            "ω went from {} to {} rad/s in {} s: with c = 0, dω/dt = −c ω = 0, and nothing \
             else turns it",
            n(from),
            n(omega),
            n(look.clock - since)
        ),
    ))
}

fn sign_of_torque(progress: &mut Progress, look: &Look) -> Found {
    let Some(band) = follow_pull(progress, look) else {
        progress.band_turn = 0.0;
        return None;
    };
    let torque = band_torque(look, band);
    // The band's own part of ω's change: ∫ τ_band dt / I over the pull, not damping's.
    progress.band_turn += torque / look.mass.inertia() * look.stepped_seconds;
    let turn = progress.band_turn;
    if progress.judged || turn.abs() < TURN {
        return None;
    }
    let outcome = usize::from(turn < 0.0);
    let sense = ["counter-clockwise", "clockwise"][outcome];
    Some((
        Some(outcome),
        format!(
            "the band's torque alone changed ω by {} rad/s (∫ τ_band dt / I), {sense}: the sign \
             of τ = r × F ({} now) is the sense",
            n(turn),
            n(torque)
        ),
    ))
}

fn double_the_inertia(progress: &mut Progress, look: &Look) -> Found {
    let Some(band) = look.any_band else {
        progress.before = None;
        return None;
    };
    let (torque, inertia) = (band_torque(look, band), look.mass.inertia());
    let share = torque / inertia;
    match progress.before {
        // I doubled since: judge the answer held before the change.
        Some((share_then, torque_then, inertia_then))
            if inertia >= 2.0 * inertia_then * (1.0 - 1e-12) =>
        {
            progress.before = Some((share, torque, inertia));
            if !look.paused {
                return Some((
                    None,
                    "the box moved while I changed, so τ_band changed too: pause (Space) first, \
                     then change I"
                        .to_owned(),
                ));
            }
            let ratio = share / share_then;
            if share_then == 0.0 || !ratio.is_finite() {
                return Some((
                    None,
                    "the band had no torque before: wait for it to pull off the centre".to_owned(),
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
                    "τ_band / I went {} → {} rad/s² (× {}): τ_band {} → {} (the band held \
                     its point), I {} → {}",
                    n(share_then),
                    n(share),
                    n(ratio),
                    n(torque_then),
                    n(torque),
                    n(inertia_then),
                    n(inertia)
                ),
            ))
        }
        // I grows (a slider dragged over several frames): keep the sample before it moved.
        Some((_, _, inertia_then)) if inertia > inertia_then => None,
        _ => {
            progress.before = Some((share, torque, inertia));
            progress.committed = progress.predicted;
            None
        }
    }
}

fn held_corner(progress: &mut Progress, look: &Look) -> Found {
    let band = follow_pull(progress, look)?;
    if progress.judged {
        return None;
    }
    let state = &look.state;
    let held = band.attachment(state);
    let to_held = held.distance(band.anchor);
    let nearest = look
        .mass
        .corners()
        .map(|corner| state.local_to_world(corner))
        .into_iter()
        .min_by(|a, b| a.distance(band.anchor).total_cmp(&b.distance(band.anchor)))?;
    let nearer = to_held - nearest.distance(band.anchor);
    if nearer < 1.0 {
        return None;
    }
    Some((
        Some(0),
        format!(
            "the band held {}, though the corner at {} is {} px nearer the pointer: the corner \
             is chosen once, at the press",
            v(held),
            v(nearest),
            n(nearer)
        ),
    ))
}

fn come_to_rest(progress: &mut Progress, look: &Look) -> Found {
    let state = &look.state;
    let energy = kinetic_energy(state, look.mass);
    if look.player_band.is_some() {
        progress.pulled = true;
        progress.released = None;
        return None;
    }
    if !progress.pulled {
        return None;
    }
    let most = match progress.released {
        None => {
            progress.committed = progress.predicted;
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
                "it still turns at ω = {} rad/s: with c = 0 nothing takes ½ I ω² = {} out",
                n(omega),
                n(spin)
            ),
        ));
    }
    if watched && p.linear_damping == 0.0 && velocity != DVec2::ZERO {
        return Some((
            Some(1),
            format!(
                "it still drifts at v = {}: with b = 0 nothing takes ½ m v² = {} out",
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
                "its kinetic energy fell from {} to {}: b = {} takes it from v and c = {} \
                 from ω",
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
    progress.committed = progress.predicted;
    if !look.single_step {
        return None;
    }
    let before: BodyState = progress.last_state?;
    let dt = look.params.dt();
    let (v0, v1) = (before.linear.velocity, look.state.linear.velocity);
    if (v1 - v0).length() * dt < 1e-9 {
        return Some((
            None,
            "v did not change over that step, so both answers move x alike: pull the box first"
                .to_owned(),
        ));
    }
    let moved = look.state.linear.position - before.linear.position;
    progress.committed = held;
    let off = |v: DVec2| moved.distance(v * dt) / moved.length().max(1e-300);
    if off(v0).min(off(v1)) > 1e-9 {
        return Some((
            None,
            format!(
                "x moved by {}, neither v dt before nor after: this integrator takes the forces \
                 at several points of the step; the question is the seed's (I until seed)",
                v(moved)
            ),
        ));
    }
    let outcome = usize::from(off(v1) < off(v0));
    let which = ["before", "after"][outcome];
    Some((
        Some(outcome),
        format!(
            "x moved by {} = {} × dt: the v {which} the step (before it was {}, after {})",
            v(moved),
            v(moved / dt),
            v(v0),
            v(v1)
        ),
    ))
}
