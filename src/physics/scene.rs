//! The scene's parameters, their units, their defaults (the tutorial's Rubber Band Box) and
//! their validation. One source of truth: the game, the CLI and the tests read them from here.

use bevy::math::DVec2;
use bevy::prelude::Resource;

use super::body::MassProperties;
use super::forces::{BandEnds, ForceModel};
use super::maths;
use super::param_error::{ParamError, Range};

/// The tutorial's frame rate: it runs one update per frame at this rate.
///
/// Its per-frame constants convert to per-second ones through it.
pub const TUTORIAL_FRAME_RATE: f64 = 100.0;

/// The tutorial's screen, in world units. The camera keeps it in view at any window size.
pub const SCENE_SIZE: DVec2 = DVec2::new(640.0, 480.0);

/// The tutorial's angular damping: ω is multiplied by this every frame.
pub const TUTORIAL_ANGULAR_FACTOR: f64 = 0.98;

/// The ranges the game keeps: this one, the step rate's, and those that follow.
///
/// The game's controls stay inside them, and every other way into the game (`play`'s flags, a
/// replay opened, a link) is held to them ([`SceneParams::check_playable`]). The panel's sliders
/// span them; docs/links.md lists them.
pub const STEP_RATE_RANGE: Range = Range::new(8.0, 4096.0, "Hz");
pub const STIFFNESS_RANGE: Range = Range::new(1e-2, 1e12, "");
pub const MASS_RANGE: Range = Range::new(1e-3, 1e3, "");
/// The box's width and height: the size slider's range, which a replay may not exceed.
pub const SIZE_RANGE: Range = Range::new(1.0, 640.0, "px");
/// The coefficient b.
pub const LINEAR_DAMPING_RANGE: Range = Range::new(0.0, 50.0, "");
/// The rate c.
pub const ANGULAR_DAMPING_RANGE: Range = Range::new(0.0, 20.0, "/s");
/// How fast the game's clock runs against the wall's: slow motion to fast forward.
pub const TIME_SCALE_RANGE: Range = Range::new(1.0 / 16.0, 16.0, "");

/// The shortest step anything takes, the game or not.
///
/// `simulate` and `report` keep wider ranges than the game for convergence studies, but no
/// clock keeps a shorter step, and a replay or a command line asking for one is refused.
/// Bevy's fixed clock counts whole nanoseconds.
pub const MIN_STEP: f64 = 1e-6;

/// Physical parameters of the scene, in world units (logical pixels, seconds, mass units).
#[derive(Resource, Clone, Copy, Debug, PartialEq)]
pub struct SceneParams {
    /// Box mass.
    pub mass: f64,
    /// Box width and height.
    pub size: DVec2,
    /// Band stiffness k: force per unit of stretch.
    pub stiffness: f64,
    /// Linear damping b: force −b·v, so the velocity decays at the rate b/m.
    pub linear_damping: f64,
    /// Angular damping rate c: ω decays as exp(−c t).
    pub angular_damping: f64,
    /// Fixed physics steps per second.
    pub step_rate_hz: f64,
}

impl SceneParams {
    /// Returns the tutorial's scene, converted from its per-frame units at 100 frames per second.
    ///
    /// k = 0.002 /frame² → 20, b = 0.05 /frame → 5, ω·0.98 per frame → c = −ln(0.98)·100.
    pub fn tutorial() -> Self {
        let f = TUTORIAL_FRAME_RATE;
        Self {
            mass: 5.0,
            size: DVec2::new(60.0, 60.0),
            stiffness: 0.002 * f * f,
            linear_damping: 0.05 * f,
            angular_damping: -maths::ln(TUTORIAL_ANGULAR_FACTOR) * f,
            step_rate_hz: 100.0,
        }
    }

    /// Returns the fixed step in seconds.
    pub fn dt(&self) -> f64 {
        1.0 / self.step_rate_hz
    }

    /// Checks every field; the error names the first bad field and its value.
    ///
    /// Mass, size and step rate must be finite and positive, the step no shorter than
    /// [`MIN_STEP`]; k, b and c finite and not negative.
    pub fn validate(&self) -> Result<(), ParamError> {
        self.mass_properties()?;
        ParamError::check_positive("step rate", self.step_rate_hz)?;
        ParamError::check_within(
            "step rate",
            self.step_rate_hz,
            &Range::new(0.0, 1.0 / MIN_STEP, "Hz (a step of at least a microsecond)"),
        )?;
        ParamError::check_non_negative("stiffness k", self.stiffness)?;
        ParamError::check_non_negative("linear damping b", self.linear_damping)?;
        ParamError::check_non_negative("angular damping c", self.angular_damping)?;
        Ok(())
    }

    /// Checks every field as [`validate`](Self::validate) does, then against the game's ranges.
    ///
    /// The game's ranges are the controls' own. The error names the first field outside and the
    /// range it must lie in.
    pub fn check_playable(&self) -> Result<(), ParamError> {
        self.validate()?;
        ParamError::check_within("step rate", self.step_rate_hz, &STEP_RATE_RANGE)?;
        ParamError::check_within("stiffness k", self.stiffness, &STIFFNESS_RANGE)?;
        ParamError::check_within("mass", self.mass, &MASS_RANGE)?;
        ParamError::check_within("width", self.size.x, &SIZE_RANGE)?;
        ParamError::check_within("height", self.size.y, &SIZE_RANGE)?;
        ParamError::check_within(
            "linear damping b",
            self.linear_damping,
            &LINEAR_DAMPING_RANGE,
        )?;
        ParamError::check_within(
            "angular damping c",
            self.angular_damping,
            &ANGULAR_DAMPING_RANGE,
        )
    }

    /// Returns the force laws of this scene acting on a body, with or without a band.
    pub fn force_model(&self, mass: MassProperties, band: Option<BandEnds>) -> ForceModel {
        ForceModel {
            mass,
            band,
            stiffness: self.stiffness,
            linear_damping: self.linear_damping,
            angular_damping: self.angular_damping,
        }
    }

    /// Returns the box's mass properties; fails on a bad mass or size.
    pub fn mass_properties(&self) -> Result<MassProperties, ParamError> {
        MassProperties::rectangle(self.mass, self.size)
    }
}

impl Default for SceneParams {
    fn default() -> Self {
        Self::tutorial()
    }
}
