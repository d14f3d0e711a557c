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
    /// τ = r × F.
    Torque,
    /// The centre twin: the box's band force at its centre, r = 0, so it never turns.
    CentrePull,
    /// I = m (w² + h²) / 12.
    Inertia,
    /// α = Στ / I.
    AngularAcceleration,
    /// The band's part of α, τ_band / I, against what it was with the chapter's first I.
    BandShareOfAlpha,
    /// F = −k (p − q).
    Spring,
    /// The corner nearest the pointer.
    NearestCorner,
    /// F_damp = −b v.
    LinearDamping,
    /// τ_damp = −c I ω.
    AngularDamping,
    /// E = ½ m v² + ½ I ω² + ½ k |p − q|².
    Energy,
    /// Where the energy went: in by the hand, out by damping.
    Ledger,
    /// The update loop, one line a stage.
    Update,
}

/// What a chapter asks the player to do; learn mode checks it (`check_task`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Task {
    /// Move the box 40 px with a band while it turns less than 0.05 rad.
    MoveWithoutTurning,
    /// Angular damping c set to 0 while the box still spins (|ω| above 1 rad/s).
    SpinWithoutDamping,
    /// A band turning the box clockwise, faster than 1 rad/s.
    SpinClockwise,
    /// The moment of inertia at least twice what the chapter started with.
    DoubleTheInertia,
    /// The band grabbed at three different corners.
    ThreeCorners,
    /// After a pull, the box back to rest, with no band.
    ///
    /// At rest means its kinetic energy is under 1% of the most it had.
    ComeToRest,
    /// Five single steps taken while paused.
    StepFiveTimes,
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
    pub task: Task,
    /// The task, as the player reads it.
    pub ask: &'static str,
}

/// The chapters, in the tutorial's order.
pub const CHAPTERS: [Chapter; 7] = [
    Chapter {
        title: "Linear motion",
        sections: "§3.2, §4.2",
        scene: "diagonal",
        integrator: None,
        text: "A force whose line passes through the centre of mass moves the box as if all \
               its mass sat there: F\u{a0}=\u{a0}m\u{a0}a, and the box does not turn. Here the band pulls \
               along the diagonal, through the centre.",
        equations: &[Equation::ForceSum, Equation::Acceleration, Equation::Motion],
        frame: [-70.0, -70.0, 230.0, 230.0],
        centre_twin: false,
        task: Task::MoveWithoutTurning,
        ask: "pull along a diagonal so that the box moves 40 px without turning",
    },
    Chapter {
        title: "Orientation and angular velocity",
        sections: "§3.3",
        scene: "spin",
        integrator: None,
        text: "A rigid body also has an orientation θ, one number in 2D, and an angular \
               velocity ω = dθ/dt. Nothing pulls this box: it only spins, and angular damping \
               takes ω down at the rate c.",
        equations: &[
            Equation::Orientation,
            Equation::AngularDecay,
            Equation::Inertia,
        ],
        frame: [-130.0, -100.0, 130.0, 100.0],
        centre_twin: false,
        task: Task::SpinWithoutDamping,
        ask: "set the angular damping to 0 while it spins: ω stops falling",
    },
    Chapter {
        title: "A force at a point",
        sections: "§4.2, §4.3",
        scene: "tutorial",
        integrator: None,
        text: "A force applied away from the centre still accelerates the centre by F\u{a0}/\u{a0}m, \
               and also turns the box: the torque is the perpendicular dot product of the arm \
               r, from the centre to the point, with the force. The outline below is a twin \
               that the box's own band force pushes at its centre, with the same damping: its \
               centre moves exactly as the box's does, and with r\u{a0}=\u{a0}0 it never turns.",
        equations: &[
            Equation::Arm,
            Equation::Torque,
            Equation::Acceleration,
            Equation::AngularAcceleration,
            Equation::CentrePull,
        ],
        frame: [-70.0, -180.0, 270.0, 190.0],
        centre_twin: true,
        task: Task::SpinClockwise,
        ask: "pull so that the box spins clockwise",
    },
    Chapter {
        title: "The moment of inertia",
        sections: "§4.3.4, §4.3.6",
        scene: "tutorial",
        integrator: None,
        text: "The moment of inertia is to turning what mass is to moving: the same torque \
               gives a box with twice the inertia half the angular acceleration. For a box it \
               grows with the mass and the square of its size (the Controls card's mass and \
               size sliders). Change either while the band pulls: the band holds the same point, \
               so the torque is the same and its part of α halves (damping's −c\u{a0}ω does not \
               depend on I). A larger box grabbed afresh at its corner is held further from its \
               centre, so the same stretch gives it more torque.",
        equations: &[
            Equation::Inertia,
            Equation::Torque,
            Equation::AngularAcceleration,
            Equation::BandShareOfAlpha,
        ],
        frame: [-70.0, -100.0, 270.0, 190.0],
        centre_twin: false,
        task: Task::DoubleTheInertia,
        ask: "double I while the band pulls (mass ×2 or size ×1.41): τ_band / I halves",
    },
    Chapter {
        title: "The rubber band",
        sections: "§5.2.3",
        scene: "rest",
        integrator: None,
        text: "The band is a spring of zero rest length between the pointer and the corner \
               nearest it when pressed: its force is k times the stretch, toward the pointer.",
        equations: &[Equation::NearestCorner, Equation::Spring, Equation::Torque],
        frame: [-130.0, -100.0, 130.0, 100.0],
        centre_twin: false,
        task: Task::ThreeCorners,
        ask: "press near three different corners: the band takes the nearest each time",
    },
    Chapter {
        title: "Damping",
        sections: "§5.2.4",
        scene: "tutorial",
        integrator: None,
        text: "Damping forces oppose the motion: −b v on the centre and −c I ω on the turn. \
               They turn the band's work into heat, so the box always comes to rest: the ledger \
               adds what the hand put in to the energy at the start and takes away what damping \
               took out, which leaves E.",
        equations: &[
            Equation::LinearDamping,
            Equation::AngularDamping,
            Equation::Energy,
            Equation::Ledger,
        ],
        frame: [-70.0, -100.0, 270.0, 190.0],
        centre_twin: false,
        task: Task::ComeToRest,
        ask: "pull, let go, and watch the energy leave until the box rests",
    },
    Chapter {
        title: "The update loop",
        sections: "§5.2.4; appendix §8.1: RigidBody.update, AngularDamping",
        scene: "tutorial",
        integrator: Some("seed"),
        text: "The tutorial's own loop, run here by the seed integrator, its lines the \
               seed's numbers for the next step: the angular damping first scales ω by \
               e^(−c\u{a0}dt), 0.98 a step at 100\u{a0}Hz; the band's force and the damping force \
               give a, the band's torque α; then ω and θ, then v and x, each from the one just \
               updated. Other integrators take the same forces at other points of the step: G \
               shows them all beside the box and P plots their error against their cost, the \
               way into the lab.",
        equations: &[Equation::Update],
        frame: [-70.0, -100.0, 270.0, 190.0],
        centre_twin: false,
        task: Task::StepFiveTimes,
        ask: "pause (Space) and step (N) five times, reading each line",
    },
];
