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
    /// The band's part of α, τ_band / I.
    BandShareOfAlpha,
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
}

/// The experiment a chapter's prediction is checked against; learn mode runs it (`check_task`).
///
/// Each yields one of the chapter's choices as what happened.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Task {
    /// A pull of 40 px along a line through the centre: did the box turn (0) or not (1)?
    TurnThroughTheCentre,
    /// Angular damping c at 0 while the box spins: did ω fall (0), stay (1) or grow (2)?
    SpinWithoutDamping,
    /// A pull of the player's: did ω pass 1 rad/s counter-clockwise (0) or clockwise (1)?
    SignOfTorque,
    /// I doubled while a band holds: did τ_band / I double (0), stay (1) or halve (2)?
    DoubleTheInertia,
    /// The pointer dragged nearer another corner: did the band hold the first (0) or move (1)?
    HeldCorner,
    /// A pull let go: did the box come to rest (0) or keep moving (1)?
    ComeToRest,
    /// A single step while paused: did x move with the v before the step (0) or after it (1)?
    StepOrder,
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
    /// A few sentences in the project's own words.
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
    pub task: Task,
    pub prediction: Prediction,
}

/// The chapters, in the tutorial's order.
pub const CHAPTERS: [Chapter; 7] = [
    Chapter {
        title: "Linear motion",
        sections: "§3.2, §4.2",
        scene: "diagonal",
        integrator: None,
        text: "Axes: x to the right, y up (the tutorial's screen counts y down); the centre's \
               position is x (the tutorial's s). Every force moves the centre as if all the mass sat \
               there, wherever it acts: ΣF\u{a0}=\u{a0}m\u{a0}a (§4.2), where ΣF is the band's pull \
               F_band plus the damping F_damp\u{a0}=\u{a0}−b\u{a0}v (chapter 6). Does a force whose \
               line of action passes through the centre also turn the box? Predict below. Time is in \
               seconds: the tutorial's k\u{a0}=\u{a0}0.002\u{a0}/frame² and \
               b\u{a0}=\u{a0}0.05\u{a0}/frame are k\u{a0}=\u{a0}0.002\u{a0}×\u{a0}100²\u{a0}=\u{a0}20 \
               and b\u{a0}=\u{a0}0.05\u{a0}×\u{a0}100\u{a0}=\u{a0}5 at its 100 frames a second.",
        equations: &[Equation::ForceSum, Equation::Acceleration, Equation::Motion],
        frame: [-70.0, -70.0, 230.0, 230.0],
        centre_twin: false,
        ghosts: false,
        task: Task::TurnThroughTheCentre,
        prediction: Prediction {
            question: "pulled along its diagonal, through the centre: will the box turn?",
            choices: &["it turns", "it does not turn"],
            then: "then pull the box 40 px along the diagonal, from a corner away from the centre",
        },
    },
    Chapter {
        title: "Orientation and angular velocity",
        sections: "§3.3",
        scene: "spin",
        integrator: None,
        text: "A rigid body also has an orientation θ (the tutorial's Ω): one number, because a plane \
               has one way to turn (§3.3.1). Its angular velocity is ω\u{a0}=\u{a0}dθ/dt, its angular \
               acceleration α\u{a0}=\u{a0}dω/dt. θ, ω and torques count counter-clockwise as \
               positive, as the arc between the axes in the scene's corner shows (on the tutorial's \
               y-down screen its positive angle looks clockwise). No band pulls this box until you \
               press: it spins, and angular damping takes ω down at the rate c, \
               dω/dt\u{a0}=\u{a0}−c\u{a0}ω; the tutorial's ω\u{a0}×\u{a0}0.98 a frame is \
               c\u{a0}=\u{a0}−ln\u{a0}0.98\u{a0}×\u{a0}100\u{a0}=\u{a0}2.02\u{a0}/s.",
        equations: &[Equation::Orientation, Equation::AngularDecay],
        frame: [-130.0, -100.0, 130.0, 100.0],
        centre_twin: false,
        ghosts: false,
        task: Task::SpinWithoutDamping,
        prediction: Prediction {
            question: "with the angular damping c at 0, what will ω do?",
            choices: &["fall to 0", "stay as it is", "grow"],
            then: "then pause (Space), set angular damping to 0 (Controls card), resume and watch ω for half a second",
        },
    },
    Chapter {
        title: "Torque: a force at a point",
        sections: "§4.2, §4.3.1-4.3.3",
        scene: "tutorial",
        integrator: None,
        text: "The arm r runs from the centre to the point p where the force acts. The torque is \
               τ\u{a0}=\u{a0}r\u{a0}×\u{a0}F\u{a0}=\u{a0}r_x·F_y\u{a0}−\u{a0}r_y·F_x (the tutorial's \
               eq.\u{a0}12; its perp dot product r⊥\u{a0}·\u{a0}F is the same number): zero when the \
               force's line of action passes through the centre, positive when it turns the box \
               counter-clockwise. A point of the box moves at v\u{a0}+\u{a0}ω\u{a0}r⊥, with \
               r⊥\u{a0}=\u{a0}(−r_y,\u{a0}r_x) (§4.3.2): the green arrow at the corner, beside the \
               grey one of its move over the last step. The centre still accelerates by \
               ΣF\u{a0}/\u{a0}m. The outline below is a twin that the box's own band force pushes at \
               its centre, with the same damping: its centre moves as the box's, and with \
               r\u{a0}=\u{a0}0 it never turns. How much a torque changes ω takes the moment of \
               inertia: chapter 4.",
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
        task: Task::SignOfTorque,
        prediction: Prediction {
            question: "which way will your pull turn the box?",
            choices: &["counter-clockwise (τ > 0)", "clockwise (τ < 0)"],
            then: "then press and pull until the band has changed ω by 1 rad/s",
        },
    },
    Chapter {
        title: "The moment of inertia",
        sections: "§4.3.4-4.3.6",
        scene: "undamped",
        integrator: None,
        text: "The moment of inertia is to turning what mass is to moving. Cut the box into \
               n\u{a0}×\u{a0}n small masses mₖ at arms rₖ: its kinetic energy of turning is \
               ½\u{a0}Σ\u{a0}mₖ\u{a0}|ω\u{a0}rₖ|²\u{a0}=\u{a0}½\u{a0}I\u{a0}ω², so \
               I\u{a0}=\u{a0}Σ\u{a0}mₖ\u{a0}|rₖ|², which tends to the box's \
               m\u{a0}(w²\u{a0}+\u{a0}h²)\u{a0}/\u{a0}12 as n grows (the dots; n\u{a0}−, n\u{a0}+). \
               While I stays, the angular momentum L\u{a0}=\u{a0}I\u{a0}ω changes at the rate of the \
               torque, τ\u{a0}=\u{a0}dL/dt, so α\u{a0}=\u{a0}Στ\u{a0}/\u{a0}I \
               (τ_damp\u{a0}=\u{a0}−c\u{a0}I\u{a0}ω is chapter 6's; 0 here). This scene has no \
               damping and its band stays unless you press (◂\u{a0}back and next\u{a0}▸ bring it \
               back), so your hand is free for the sliders: the band holds the same point in the \
               box's own coordinates when the mass or the size changes (after a resize, no longer a \
               corner).",
        equations: &[
            Equation::PointMasses,
            Equation::Inertia,
            Equation::AngularMomentum,
            Equation::AngularAcceleration,
            Equation::BandShareOfAlpha,
        ],
        frame: [-70.0, -100.0, 270.0, 190.0],
        centre_twin: false,
        ghosts: false,
        task: Task::DoubleTheInertia,
        prediction: Prediction {
            question: "I doubled, the band where it is: what will τ_band / I do?",
            choices: &["double", "stay the same", "halve"],
            then: "then pause (Space) and at least double I: mass 5 → 10, or size 60 → 89 px (Controls card)",
        },
    },
    Chapter {
        title: "The rubber band",
        sections: "§5.2.3",
        scene: "rest",
        integrator: None,
        text: "The band is a spring of zero rest length from the pointer q to a corner p of the box: \
               its force is F\u{a0}=\u{a0}−k\u{a0}(p\u{a0}−\u{a0}q), k times the stretch, toward the \
               pointer (the tutorial's x is the stretch p\u{a0}−\u{a0}q; its p is the momentum). The \
               corner is the one nearest the pointer at the press. Does the band keep that corner \
               when another comes nearer? Predict below.",
        equations: &[Equation::NearestCorner, Equation::Spring, Equation::Torque],
        frame: [-130.0, -100.0, 130.0, 100.0],
        centre_twin: false,
        ghosts: false,
        task: Task::HeldCorner,
        prediction: Prediction {
            question: "press by one corner, then drag until another is nearer: which does the band hold?",
            choices: &["the one it took", "the one now nearest"],
            then: "then press by a corner and drag the pointer round to another",
        },
    },
    Chapter {
        title: "Damping",
        sections: "§5.2.4",
        scene: "tutorial",
        integrator: None,
        text: "Damping opposes the motion: F_damp\u{a0}=\u{a0}−b\u{a0}v on the centre and \
               τ_damp\u{a0}=\u{a0}−c\u{a0}I\u{a0}ω on the turn. It turns kinetic energy into heat at \
               the rate b\u{a0}|v|²\u{a0}+\u{a0}c\u{a0}I\u{a0}ω². The hand puts \
               ½\u{a0}k\u{a0}|p\u{a0}−\u{a0}q|² into the band at the press, and more in or out as it \
               moves the pointer; at release the band's energy leaves with the hand. A slider (k, \
               mass, size) changes E too, and the books count it with the hand. The books: \
               E₀\u{a0}+\u{a0}W_hand\u{a0}−\u{a0}W_damp; E differs from them by the integrator's \
               error (its own reckoning of W_damp included), the last line. Does the box always come \
               to rest? Set b or c to 0 if you like, and predict below.",
        equations: &[
            Equation::LinearDamping,
            Equation::AngularDamping,
            Equation::Energy,
            Equation::Ledger,
        ],
        frame: [-70.0, -100.0, 270.0, 190.0],
        centre_twin: false,
        ghosts: false,
        task: Task::ComeToRest,
        prediction: Prediction {
            question: "once you let go, will the box come to rest?",
            choices: &["it comes to rest", "it keeps moving"],
            then: "then pull and let go (set b or c to 0 first, if you like)",
        },
    },
    Chapter {
        title: "The update loop",
        sections: "§5.2.4; appendix §8.1: RigidBody.update, AngularDamping",
        scene: "tutorial",
        integrator: Some("seed"),
        text: "The tutorial's own loop, run here by the seed integrator; the lines are its numbers \
               for the next step. Angular damping first scales ω by e^(−c\u{a0}dt), 0.98 a step at \
               100\u{a0}Hz; the forces give a, and the band's torque \
               α_band\u{a0}=\u{a0}τ_band\u{a0}/\u{a0}I (damping acted in line 1); then ω and θ, then \
               v and x. Which v moves x? Predict below. This order (semi-implicit Euler) keeps the \
               energy's error bounded while the step resolves the band (2\u{a0}√(k/m)\u{a0}dt below \
               2: at 100\u{a0}Hz, k/m under 10⁴); explicit Euler, which moves x with the old v, runs \
               further from its books step after step. The ghosts step both from the same start, \
               their books' errors the last lines; the other ghosts are the other integrators, and P \
               plots each one's distance from the reference against its cost.",
        equations: &[Equation::Update, Equation::UpdateOrder],
        frame: [-70.0, -100.0, 270.0, 190.0],
        centre_twin: false,
        ghosts: true,
        task: Task::StepOrder,
        prediction: Prediction {
            question: "paused, one step (N): x moves by v dt with which v?",
            choices: &["the v before the step", "the v after it"],
            then: "then pause (Space) and step (N) while the box moves",
        },
    },
];
