//! The ghosts' steppers: every integrator, and a reference, stepping the live box's scene
//! beside it under the live band (the same anchor path, the same attach and release steps), so
//! that a player sees each method's distance from the converged answer follow their own hand.
//! Each ghost is the core's [`Stepper`] with its own [`Books`], stepped by the core's booked
//! step; the live box never reads them.
//!
//! A ghost whose step leaves the bounds freezes there, with the step. The reference is a
//! Taylor series of order 32 at 1e-13 px a step, with a budget of substeps so that a stiff
//! band cannot stall the frame; a step that exhausts it falls back to `implicit` and is
//! counted as capped. Ghosts restart from the live box at a reset (and so at a scene or
//! replay opened) and when they are switched on.

use bevy::platform::time::Instant;
use bevy::prelude::*;

use crate::game::schedule::PhysicsSystems;
use crate::game::shared::{Overlay, Overlays};
use crate::game::simulation::{Band, Bodies, ResetScene, acting_band};
use crate::physics::integrators::taylor::MAX_ORDER;
use crate::physics::{
    AutoSettings, BandEnds, BodyState, Books, Bound, Integrator, MassProperties, SceneParams,
    StepInfo, Stepper,
};

/// Steps the ghosts beside the box and restarts them at a reset.
pub(super) fn plugin(app: &mut App) {
    app.init_resource::<Ghosts>()
        .add_observer(restart_on_reset)
        .add_systems(FixedUpdate, step_ghosts.in_set(PhysicsSystems::Observe));
}

/// The reference: Taylor series of order 32 at 1e-13 px per step.
///
/// It takes at most `max_substeps` substeps a fixed step. The highest order, as the report's
/// references (order 24 ended 5 to 10 times further off than its neighbours: docs/integrators.md).
const REFERENCE: AutoSettings = AutoSettings {
    tolerance: 1e-13,
    order: MAX_ORDER,
    max_substeps: 2000,
};

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GhostKind {
    Method(Integrator),
    Reference,
}

impl GhostKind {
    pub fn name(self) -> &'static str {
        match self {
            Self::Method(integrator) => integrator.name(),
            Self::Reference => "reference",
        }
    }

    /// Returns the ghost's colour, the same in its outline, its table row and its plot point.
    ///
    /// A method's ghost takes the core's [`Integrator::colour`], as the report's figures do; the
    /// reference is white.
    pub fn colour(self) -> Color {
        match self {
            Self::Method(integrator) => crate::game::theme::method_colour(integrator),
            Self::Reference => Color::WHITE,
        }
    }
}

/// One ghost: a stepper following the live band.
#[derive(Clone, Debug)]
pub struct Ghost {
    pub kind: GhostKind,
    pub stepper: Stepper,
    /// The state before the latest step, for drawing between the two.
    pub previous: BodyState,
    /// The step at which it left the bounds (frozen since).
    pub diverged_at: Option<u64>,
    pub books: Books,
    pub last: StepInfo,
    /// Steps taken since the (re)start.
    pub steps: u64,
    /// Steps that ran out of the substep budget (the reference only: see `REFERENCE`).
    pub capped: u64,
    /// Wall time of a step, averaged over the latest few dozen (ns).
    pub ns_per_step: f64,
}

impl Ghost {
    fn new(kind: GhostKind, params: SceneParams, mass: MassProperties, state: BodyState) -> Self {
        let (integrator, auto) = match kind {
            GhostKind::Method(integrator) => (integrator, AutoSettings::default()),
            GhostKind::Reference => (Integrator::Auto, REFERENCE),
        };
        Self {
            kind,
            stepper: Stepper {
                params,
                mass,
                state,
                band: None,
                integrator,
                auto,
            },
            previous: state,
            diverged_at: None,
            books: Books::default(),
            last: StepInfo::SINGLE,
            steps: 0,
            capped: 0,
            ns_per_step: 0.0,
        }
    }

    /// Takes the core's booked step of `dt` under `band`, as the game's fixed step takes one.
    ///
    /// A step that leaves the bounds is refused and the ghost frozen.
    fn step(&mut self, band: Option<BandEnds>, dt: f64) {
        if self.diverged_at.is_some() {
            return;
        }
        self.stepper.band = band;
        let before = self.stepper.state;
        let started = Instant::now();
        let booked = self.books.step(&mut self.stepper, dt, Bound::Sane);
        let ns = started.elapsed().as_nanos() as f64;
        self.ns_per_step = if self.steps == 0 {
            ns
        } else {
            0.95 * self.ns_per_step + 0.05 * ns
        };
        self.steps += 1;
        self.last = booked.info;
        self.capped += u64::from(booked.info.fell_back && self.kind == GhostKind::Reference);
        self.previous = before;
        if booked.refused {
            self.diverged_at = Some(self.steps);
        }
    }

    /// Returns the books' residual now: the integrator's energy error since the (re)start.
    pub fn residual(&self) -> f64 {
        self.books.residual()
    }
}

/// The ghosts, every integrator then the reference; empty while they are off.
#[derive(Resource, Debug, Default)]
pub struct Ghosts {
    pub ghosts: Vec<Ghost>,
    restart: bool,
}

impl Ghosts {
    pub fn reference(&self) -> Option<&Ghost> {
        self.ghosts.iter().find(|g| g.kind == GhostKind::Reference)
    }

    /// Returns how far `ghost` is from the reference now (px).
    ///
    /// The distance is the largest corner distance, so the orientation counts as the corner's
    /// 30√2·θ.
    pub fn distance_from_reference(&self, ghost: &Ghost) -> Option<f64> {
        let reference = self.reference()?;
        Some(
            ghost
                .stepper
                .state
                .pose_error(&reference.stepper.state, &ghost.stepper.mass),
        )
    }
}

fn restart_on_reset(_reset: On<ResetScene>, mut ghosts: ResMut<Ghosts>) {
    ghosts.restart = true;
}

/// Steps every ghost before the live box's step: the same step under the same band.
///
/// They step with the settings in force. Switched off, they are dropped, to start again from the
/// live box when switched on.
fn step_ghosts(
    overlays: Res<Overlays>,
    mut ghosts: ResMut<Ghosts>,
    time: Res<Time<Fixed>>,
    params: Res<SceneParams>,
    boxes: Bodies,
    bands: Query<&Band>,
) {
    if !overlays.on(Overlay::Ghosts) {
        if !ghosts.ghosts.is_empty() {
            ghosts.ghosts.clear();
        }
        return;
    }
    let Ok(body) = boxes.single() else {
        return;
    };
    let mass = body.mass;
    // Taken at every step, so that a restart asked while the ghosts were off is not done
    // again a step after they start.
    let restart = std::mem::take(&mut ghosts.restart);
    if ghosts.ghosts.is_empty() || restart {
        let start = body.state();
        ghosts.ghosts = Integrator::ALL
            .map(GhostKind::Method)
            .into_iter()
            .chain([GhostKind::Reference])
            .map(|kind| Ghost::new(kind, *params, *mass, start))
            .collect();
    }
    let dt = time.timestep().as_secs_f64();
    let band = acting_band(body.entity, &bands);
    for ghost in &mut ghosts.ghosts {
        ghost.stepper.params = *params;
        ghost.stepper.mass = *mass;
        ghost.step(band, dt);
    }
}
