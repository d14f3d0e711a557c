//! The chapters of learn mode: the tutorial's ideas in its order, each on a scene of the core's
//! table, with its equations and something to do. Data only: a chapter is added or moved here
//! without touching a system.

/// An equation a chapter shows, written as symbols and again with this frame's numbers.
///
/// [`super::equations`] writes it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Equation {
    /// ΣF = F_band + F_damp.
    ForceSum,
    /// a = ΣF / m.
    Acceleration,
    /// The centre's position and velocity.
    Motion,
    /// θ and ω.
    Orientation,
    /// ω decays: dω/dt = −c ω.
    AngularDecay,
    /// r = p − x: from the centre to the band's corner.
    Arm,
    /// τ = r × F = r_x F_y − r_y F_x.
    Torque,
    /// The velocity of the band's corner: v_p = v + ω r⊥.
    PointVelocity,
    /// The centre twin: the box's band force at its centre, r = 0, so it never turns.
    CentrePull,
    /// I = Σ mₖ |rₖ|² over n × n point masses, against the box's closed form.
    PointMasses,
    /// I = m (w² + h²) / 12.
    Inertia,
    /// L = I ω, and τ = dL / dt against the change of L over the next step.
    AngularMomentum,
    /// α = Στ / I.
    AngularAcceleration,
    /// F = −k (p − q).
    Spring,
    /// The corner the band holds: the one nearest the pointer when pressed.
    NearestCorner,
    /// F_damp = −b v.
    LinearDamping,
    /// τ_damp = −c I ω.
    AngularDamping,
    /// E = ½ m v² + ½ I ω² + ½ k |p − q|².
    Energy,
    /// Where the energy went: in by the hand, out by damping; and E's distance from that.
    Ledger,
    /// The update loop, one line a stage.
    Update,
    /// The energy books of the seed's and explicit Euler's ghosts, stepped from the same start.
    UpdateOrder,
    /// The kinetic energy of the box and of the centre outline: ½ m v² + ½ I ω² against ½ m v².
    OutlineEnergy,
}

/// The experiment a chapter's prediction is checked against; learn mode runs it (`check_task`).
///
/// Each yields one of the chapter's choices as what happened.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Task {
    /// The scene's pull through the centre, over 40 px: did the box turn (0) or not (1)?
    TurnThroughTheCentre,
    /// Angular damping c at 0 while the box spins: did ω fall (0), stay (1) or grow (2)?
    SpinWithoutDamping,
    /// The scene's pull: did the band's torque make ω rise (0) or fall (1) by 1 rad/s?
    SignOfTorque,
    /// I doubled under a band: did ω change twice as fast (0), as fast (1) or half (2)?
    ///
    /// Judged over single steps.
    DoubleTheInertia,
    /// The pointer dragged nearer another corner: did the band hold its point (0) or move (1)?
    HeldCorner,
    /// A band let go: did the box come to rest (0) or keep moving (1)?
    ComeToRest,
    /// A single step while paused: did x move with the v before the step (0) or after it (1)?
    StepOrder,
    /// The scene's pull: did the box gain more kinetic energy than the outline (0, 1, 2)?
    ///
    /// More (0), as much (1) or less (2), judged after half a second.
    MoreEnergy,
}

/// What the learner commits to before the experiment: a question and its answers.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Prediction {
    pub question: &'static str,
    pub choices: &'static [&'static str],
    /// What to do once an answer is chosen.
    pub then: &'static str,
}

/// One chapter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Chapter {
    pub title: &'static str,
    /// The tutorial's sections it follows.
    pub sections: &'static str,
    /// A scene of the core's table (`Scene::NAMES`).
    pub scene: &'static str,
    /// The integrator the chapter runs with (the tutorial's own for its update loop).
    pub integrator: Option<&'static str>,
    /// A few sentences in the project's own words, at most about 60.
    ///
    /// The derivations are docs/learn.md's.
    pub text: &'static str,
    pub equations: &'static [Equation],
    /// The world area the camera frames, in px (left, bottom, right, top).
    ///
    /// It is what the chapter is about (its box, its pull, its twin), so that the box and its
    /// arrows read large; the band still reaches the whole tutorial screen.
    pub frame: [f32; 4],
    /// A twin of the box beside it, pushed at its centre by the box's band force ([`super::twin`]).
    pub centre_twin: bool,
    /// The ghosts of every integrator beside the box (the update loop's seed and Euler).
    pub ghosts: bool,
    /// How fast the game's clock runs in the chapter: slow motion where the eye needs it.
    pub pace: f64,
    pub task: Task,
    pub prediction: Prediction,
}

/// The chapters, in the tutorial's order.
///
/// Each starts paused at its scene's start; nothing moves until its question has an answer.
pub const CHAPTERS: [Chapter; 8] = [
    Chapter {
        title: "Linear motion",
        sections: "§3.2, §4.2",
        scene: "diagonal",
        integrator: None,
        text: "No gravity: the box floats in a plane, seen from above. Right and up are \
               positive; x is the centre's position, in px. Any force moves the centre as if all \
               the mass sat there: ΣF\u{a0}=\u{a0}m\u{a0}a, with damping's −b\u{a0}v in ΣF. \
               Time in s, mass in mass units (mu), force in mu·px/s². The band pulls along the \
               diagonal.",
        equations: &[Equation::ForceSum, Equation::Acceleration, Equation::Motion],
        frame: [-70.0, -70.0, 230.0, 230.0],
        centre_twin: false,
        ghosts: false,
        pace: 1.0,
        task: Task::TurnThroughTheCentre,
        prediction: Prediction {
            question: "the band will pull along the diagonal, through the centre: will the box turn?",
            choices: &["it turns", "it does not turn"],
            then: "then resume (Space) and watch the pull",
        },
    },
    Chapter {
        title: "Orientation and angular velocity",
        sections: "§3.3",
        scene: "spin",
        integrator: None,
        text: "A rigid body also has an orientation θ, in rad, and an angular velocity \
               ω\u{a0}=\u{a0}dθ/dt, in rad/s, counter-clockwise positive (the arc in the scene's \
               corner). No band pulls this box: only angular damping changes ω, \
               dω/dt\u{a0}=\u{a0}−c\u{a0}ω, c in /s. Slow motion: an eighth of real time, so the \
               spin is seen as it is.",
        equations: &[Equation::Orientation, Equation::AngularDecay],
        frame: [-130.0, -100.0, 130.0, 100.0],
        centre_twin: false,
        ghosts: false,
        pace: 0.125,
        task: Task::SpinWithoutDamping,
        prediction: Prediction {
            question: "with the angular damping c at 0, what will ω do?",
            choices: &["fall to 0", "stay as it is", "grow"],
            then: "then set angular damping to 0 (Controls card), resume (Space) and watch ω",
        },
    },
    Chapter {
        title: "Torque: a force at a point",
        sections: "§4.2, §4.3.1-4.3.3",
        scene: "tutorial",
        integrator: None,
        text: "The arm r runs from the centre to the band's point p. The band's torque about the \
               centre is τ\u{a0}=\u{a0}r\u{a0}×\u{a0}F\u{a0}=\u{a0}r_x\u{a0}F_y\u{a0}−\u{a0}r_y\u{a0}F_x \
               (eq.\u{a0}12), in mu·px²/s², counter-clockwise positive. It sets how ω changes, \
               not which way the box turns. The outline below only follows the centre: the centre \
               moves as if F acted there.",
        equations: &[
            Equation::Arm,
            Equation::Torque,
            Equation::PointVelocity,
            Equation::Acceleration,
            Equation::Orientation,
            Equation::CentrePull,
        ],
        frame: [-70.0, -180.0, 270.0, 190.0],
        centre_twin: true,
        ghosts: false,
        pace: 1.0,
        task: Task::SignOfTorque,
        prediction: Prediction {
            question: "the band will pull the upper-right corner toward (200, 120) px: what will \
                       its torque do to ω?",
            choices: &["ω rises (τ > 0)", "ω falls (τ < 0)"],
            then: "then resume (Space) and watch the band's pull",
        },
    },
    Chapter {
        title: "The moment of inertia",
        sections: "§4.3.4-4.3.6",
        scene: "undamped",
        integrator: None,
        text: "The moment of inertia I is to turning what mass is to moving: \
               I\u{a0}=\u{a0}Σ\u{a0}mₖ\u{a0}|rₖ|² over the dots (n\u{a0}±), \
               m\u{a0}(w²\u{a0}+\u{a0}h²)\u{a0}/\u{a0}12 for the box, in mu·px². About the \
               centre, L\u{a0}=\u{a0}I\u{a0}ω changes at the rate Στ. Undamped at the start; the \
               band keeps its point of the box through a new mass or size.",
        equations: &[
            Equation::PointMasses,
            Equation::Inertia,
            Equation::AngularMomentum,
            Equation::AngularAcceleration,
        ],
        frame: [-70.0, -100.0, 270.0, 190.0],
        centre_twin: false,
        ghosts: false,
        pace: 1.0,
        task: Task::DoubleTheInertia,
        prediction: Prediction {
            question: "I doubled, the band where it is: how fast will ω change?",
            choices: &["twice as fast", "as fast", "half as fast"],
            then: "then step (N) and note ω's change; double I (mass 5 → 10, or size 60 → 85 \
                   px, Controls card); step again",
        },
    },
    Chapter {
        title: "The rubber band",
        sections: "§5.2.3",
        scene: "rest",
        integrator: None,
        text: "The band is a spring of zero rest length from the pointer q to its point p on the \
               box: F\u{a0}=\u{a0}−k\u{a0}(p\u{a0}−\u{a0}q), k times the stretch, toward the \
               pointer. At the press it takes the corner nearest the pointer.",
        equations: &[Equation::NearestCorner, Equation::Spring, Equation::Torque],
        frame: [-130.0, -100.0, 130.0, 100.0],
        centre_twin: false,
        ghosts: false,
        pace: 1.0,
        task: Task::HeldCorner,
        prediction: Prediction {
            question: "press by one corner, then drag until another is nearer: which does the \
                       band hold?",
            choices: &["the one it took", "the one now nearest"],
            then: "then press by a corner and drag the pointer round to another",
        },
    },
    Chapter {
        title: "Damping",
        sections: "§5.2.4",
        scene: "tutorial",
        integrator: None,
        text: "Damping slows the box: F_damp\u{a0}=\u{a0}−b\u{a0}v on the centre, \
               τ_damp\u{a0}=\u{a0}−c\u{a0}I\u{a0}ω on the turn (the tutorial adds it for looks, \
               §5.2.4). It takes energy E out at b\u{a0}|v|²\u{a0}+\u{a0}c\u{a0}I\u{a0}ω². The \
               books, E₀\u{a0}+\u{a0}W_hand\u{a0}−\u{a0}W_damp, differ from E by the \
               integrator's error: the last line. The band pulls for 2\u{a0}s, then lets go.",
        equations: &[
            Equation::LinearDamping,
            Equation::AngularDamping,
            Equation::Energy,
            Equation::Ledger,
        ],
        frame: [-70.0, -100.0, 270.0, 190.0],
        centre_twin: false,
        ghosts: false,
        pace: 1.0,
        task: Task::ComeToRest,
        prediction: Prediction {
            question: "once the band lets go, will the box come to rest?",
            choices: &["it comes to rest", "it keeps moving"],
            then: "then resume (Space) and watch (set b or c to 0 first, if you like)",
        },
    },
    Chapter {
        title: "The update loop",
        sections: "appendix §8.1: RigidBody.update, AngularDamping",
        scene: "tutorial",
        integrator: Some("seed"),
        text: "The tutorial's own loop, run by the seed integrator; each line is its number for \
               the next step. Damping scales ω first, then the forces give a and α_band. The \
               ghosts step seed and explicit Euler from the same start, their books' errors the \
               last lines; P plots every integrator's error against its cost.",
        equations: &[Equation::Update, Equation::UpdateOrder],
        frame: [-70.0, -100.0, 270.0, 190.0],
        centre_twin: false,
        ghosts: true,
        pace: 1.0,
        task: Task::StepOrder,
        prediction: Prediction {
            question: "one step (N): x moves by v dt with which v?",
            choices: &["the v before the step", "the v after it"],
            then: "then resume a moment (Space), pause (Space) and step (N)",
        },
    },
    Chapter {
        title: "Work: one force at a corner, the same at the centre",
        sections: "§4.2, §4.3.4",
        scene: "tutorial",
        integrator: None,
        text: "The outline below takes the box's band force as if at its centre, so both centres \
               move alike. A force does work W\u{a0}=\u{a0}∫\u{a0}F\u{a0}·\u{a0}dp along the path \
               of the point p it acts at; kinetic energy is \
               ½\u{a0}m\u{a0}|v|²\u{a0}+\u{a0}½\u{a0}I\u{a0}ω², in mu·px²/s².",
        equations: &[Equation::OutlineEnergy, Equation::Arm, Equation::CentrePull],
        frame: [-70.0, -180.0, 270.0, 190.0],
        centre_twin: true,
        ghosts: false,
        pace: 1.0,
        task: Task::MoreEnergy,
        prediction: Prediction {
            question: "the same force on both: which will gain more kinetic energy?",
            choices: &["the box", "both the same", "the outline"],
            then: "then resume (Space) and watch the band's pull",
        },
    },
];
