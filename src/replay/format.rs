//! The replay file's contents: the header, the records after it, the hash of a trajectory,
//! and a whole replay as the recorder keeps and writes it (JSON Lines, one value a line).

use std::fmt;
use std::io::{self, Write};

use bevy::math::DVec2;
use serde::{Deserialize, Serialize};

use crate::physics::{
    AutoSettings, BandEnds, BodyState, Integrator, MIN_STEP, ParamError, Range, STEP_RATE_RANGE,
    SceneParams, Stepper,
};

/// The header's `format` field: what the file is.
pub const FORMAT: &str = "rubber-band-box replay";
/// The format version this build writes; it reads this one and every earlier one.
///
/// Version 2 added the `state`, `auto` and `check` records, the header's `made_by` and the end
/// record's `lines`.
pub const VERSION: u32 = 2;
/// A check record follows at most this many steps after the previous one.
pub const CHECK_EVERY: u64 = 1000;
/// The most steps a replay holds; a recording stops there.
///
/// 3 million is 8 hours at 100 Hz, 12 minutes at 4096 Hz, under 150 MB in memory (a record is
/// 48 bytes).
pub const MAX_STEPS: u64 = 3_000_000;
/// The longest line a reader accepts (a header is about 400 bytes, a step at most about 120).
pub const MAX_LINE_BYTES: usize = 4096;
/// The range of `auto`'s series order a replay may ask for (as `simulate --auto-order`): the engine's.
pub const AUTO_ORDERS: (usize, usize) = (2, crate::physics::integrators::taylor::MAX_ORDER);

/// The first line: what the recording started with.
#[derive(Serialize, Deserialize, Clone, Debug, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Header {
    pub format: String,
    pub version: u32,
    /// The version of the crate that recorded it (for a reader's information only).
    pub crate_version: String,
    /// The scene played.
    pub scene: String,
    pub settings: Settings,
    pub auto: AutoRecord,
    /// The box at the scene's start, and after each reset: x, y, θ, vx, vy, ω.
    pub initial: [f64; 6],
    /// What wrote the file: the crate's version and the platform ([`made_by`]).
    ///
    /// None before version 2.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub made_by: Option<String>,
}

/// Returns what this build writes in a header's `made_by`: "0.1.0 x86_64-linux".
///
/// Two builds that say the same compute every step to the same bits.
pub fn made_by() -> String {
    format!(
        "{} {}-{}",
        env!("CARGO_PKG_VERSION"),
        std::env::consts::ARCH,
        std::env::consts::OS
    )
}

/// Everything a step is taken with, as the physics saw it.
#[derive(Serialize, Deserialize, Clone, Copy, Debug, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Settings {
    pub mass: f64,
    pub width: f64,
    pub height: f64,
    pub stiffness: f64,
    pub linear_damping: f64,
    pub angular_damping: f64,
    /// The step rate the player chose.
    pub step_rate_hz: f64,
    /// The step the fixed clock took for it, in seconds.
    ///
    /// The clock counts whole nanoseconds, so 60 Hz steps 0.016666667 s.
    pub dt: f64,
    #[serde(with = "integrator_name")]
    pub integrator: Integrator,
}

impl Settings {
    pub fn new(params: &SceneParams, dt: f64, integrator: Integrator) -> Self {
        Self {
            mass: params.mass,
            width: params.size.x,
            height: params.size.y,
            stiffness: params.stiffness,
            linear_damping: params.linear_damping,
            angular_damping: params.angular_damping,
            step_rate_hz: params.step_rate_hz,
            dt,
            integrator,
        }
    }

    pub fn params(&self) -> SceneParams {
        SceneParams {
            mass: self.mass,
            size: DVec2::new(self.width, self.height),
            stiffness: self.stiffness,
            linear_damping: self.linear_damping,
            angular_damping: self.angular_damping,
            step_rate_hz: self.step_rate_hz,
        }
    }

    /// Checks that every field is in its domain, and the step no shorter than [`MIN_STEP`].
    ///
    /// The domains are `SceneParams::validate`'s; `simulate --replay` accepts what passes.
    pub fn validate(&self) -> Result<(), ParamError> {
        self.params().validate()?;
        ParamError::check_positive("dt", self.dt)?;
        ParamError::check_within(
            "dt",
            self.dt,
            &Range::new(MIN_STEP, f64::MAX, "s (no clock keeps a shorter step)"),
        )
    }

    /// Checks that the settings are ones the game plays.
    ///
    /// Every field must be in the game's ranges (`SceneParams::check_playable`), and the step one
    /// the game's clock takes at a rate in its range.
    pub fn check_playable(&self) -> Result<(), ParamError> {
        self.validate()?;
        self.params().check_playable()?;
        // The clock rounds the step to the nanosecond.
        let steps = Range::new(
            1.0 / STEP_RATE_RANGE.high - 1e-9,
            1.0 / STEP_RATE_RANGE.low + 1e-9,
            "s (a step of the game's clock at 8 to 4096 Hz)",
        );
        ParamError::check_within("dt", self.dt, &steps)
    }
}

/// `auto`'s settings (the game never changes them, a replay may ask for others).
#[derive(Serialize, Deserialize, Clone, Copy, Debug, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct AutoRecord {
    pub tolerance: f64,
    pub order: usize,
    pub max_substeps: u32,
}

impl From<AutoSettings> for AutoRecord {
    fn from(auto: AutoSettings) -> Self {
        Self {
            tolerance: auto.tolerance,
            order: auto.order,
            max_substeps: auto.max_substeps,
        }
    }
}

impl From<AutoRecord> for AutoSettings {
    fn from(auto: AutoRecord) -> Self {
        Self {
            tolerance: auto.tolerance,
            order: auto.order,
            max_substeps: auto.max_substeps,
        }
    }
}

/// One line after the header.
#[derive(Serialize, Deserialize, Clone, Debug, PartialEq)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum Record {
    /// Before step `step`: the scene back at its start, no band (the reset control).
    Reset { step: u64 },
    /// From step `step` on, these settings (a control changed one of them).
    ///
    /// Boxed: rare, and larger than a step, which would otherwise pay for it in memory.
    Settings { step: u64, settings: Box<Settings> },
    /// Before step `step`: the box put in this state (x, y, θ, vx, vy, ω), not by a step.
    ///
    /// The recorder writes one whenever the state a step starts from is not the one the
    /// previous step left (or a reset's start): a scene loaded, a replay or a link opened,
    /// learn mode left. Boxed, as settings are.
    State { step: u64, state: Box<[f64; 6]> },
    /// From step `step` on, `auto` takes these settings (a replay or a link opened with others).
    Auto { step: u64, auto: AutoRecord },
    /// The state the game had after step `step`.
    ///
    /// It says where a replay that does not reach the recorded hash first went its own way.
    ///
    /// The recorder writes one after the first step that follows a reset, a state or a
    /// settings record, and at least every [`CHECK_EVERY`] steps.
    Check { step: u64, state: Box<[f64; 6]> },
    /// Step `step` (counted from 1) ran with this band, or none.
    Step {
        step: u64,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        band: Option<BandRecord>,
    },
    /// The last line: how many steps the file holds, and the hash of the states.
    ///
    /// The hash is of the states the game had after each step ([`TrajectoryHash`], 16 hex
    /// digits). `lines` (from version 2) is the FNV-1a hash of every line before it, so that a
    /// reader can tell a file changed after it was written.
    End {
        steps: u64,
        hash: String,
        /// Boxed: a record stays small in memory.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        lines: Option<Box<String>>,
    },
}

/// The band during a step: the body point (body coordinates) pulled toward the anchor (world).
#[derive(Serialize, Deserialize, Clone, Copy, Debug, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct BandRecord {
    pub point: [f64; 2],
    pub anchor: [f64; 2],
}

impl From<BandEnds> for BandRecord {
    fn from(band: BandEnds) -> Self {
        Self {
            point: band.local_point.to_array(),
            anchor: band.anchor.to_array(),
        }
    }
}

impl From<BandRecord> for BandEnds {
    fn from(band: BandRecord) -> Self {
        Self {
            local_point: DVec2::from_array(band.point),
            anchor: DVec2::from_array(band.anchor),
        }
    }
}

/// FNV-1a over the bits of every step's state, in order.
///
/// Equal hashes mean, but for a collision, equal trajectories to the last bit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TrajectoryHash(pub u64);

impl Default for TrajectoryHash {
    fn default() -> Self {
        Self(0xcbf2_9ce4_8422_2325)
    }
}

impl TrajectoryHash {
    pub fn add(&mut self, state: &BodyState) {
        for value in state.to_array() {
            self.add_bytes(&value.to_bits().to_le_bytes());
        }
    }

    /// Adds bytes to the hash (the end record's `lines` hashes each line and a newline).
    pub fn add_bytes(&mut self, bytes: &[u8]) {
        for &byte in bytes {
            self.0 = (self.0 ^ u64::from(byte)).wrapping_mul(0x0000_0100_0000_01b3);
        }
    }

    /// Adds one line of a file and its newline.
    pub fn add_line(&mut self, line: &[u8]) {
        self.add_bytes(line);
        self.add_bytes(b"\n");
    }
}

/// Whether a file's lines are the ones written (its end record's `lines`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Integrity {
    /// Made in memory, or read from a file whose lines hash to its end record's `lines`.
    #[default]
    Intact,
    /// Read from a file whose lines do not: it was changed after it was written.
    Changed,
    /// Read from a file with no `lines` (format version 1).
    Unknown,
}

impl fmt::Display for TrajectoryHash {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{:016x}", self.0)
    }
}

/// A whole recording: the header, the records (no end record), the steps and their hash.
///
/// Two replays are equal when their files would say the same: the recorder's bookkeeping and
/// the integrity of the file read are not compared.
#[derive(Clone, Debug)]
pub struct Replay {
    pub header: Header,
    pub records: Vec<Record>,
    pub steps: u64,
    /// The hash of the states after each step, as the recorder saw them.
    pub hash: TrajectoryHash,
    /// What a reader has in place after every record so far (the one reader's model).
    ///
    /// It is kept, not searched for, because the recorder asks at every step.
    pub(super) in_place: InPlace,
    /// Steps since the latest check record, and whether the next step must be checked.
    ///
    /// A step is checked after a reset, a state or a settings record.
    pub(super) unchecked: u64,
    pub(super) check_next: bool,
    /// Whether the file read is the one written.
    pub integrity: Integrity,
}

/// What a reader has in place between records: the settings, `auto`'s, and the box's state.
///
/// The writer keeps one, so that it records only what a reader would not have there anyway;
/// the one reader ([`super::play`]) tells it each record.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct InPlace {
    pub settings: Settings,
    pub auto: AutoRecord,
    /// The state the next step starts from unless something puts the box elsewhere.
    ///
    /// The start, a state record's or (told by the writer) the latest step's.
    pub state: [f64; 6],
}

impl PartialEq for Replay {
    fn eq(&self, other: &Self) -> bool {
        (&self.header, &self.records, self.steps, self.hash)
            == (&other.header, &other.records, other.steps, other.hash)
    }
}

impl Replay {
    /// Returns an empty recording of a game starting with these settings.
    pub fn start(scene: &str, settings: Settings, auto: AutoSettings, initial: BodyState) -> Self {
        Self::with_header(Header {
            format: FORMAT.to_owned(),
            version: VERSION,
            crate_version: env!("CARGO_PKG_VERSION").to_owned(),
            scene: scene.to_owned(),
            settings,
            auto: auto.into(),
            initial: initial.to_array(),
            made_by: Some(made_by()),
        })
    }

    /// Returns a replay with this header and no records yet.
    pub(super) fn with_header(header: Header) -> Self {
        Self {
            in_place: InPlace {
                settings: header.settings,
                auto: header.auto,
                state: header.initial,
            },
            unchecked: 0,
            check_next: false,
            integrity: Integrity::Intact,
            header,
            records: Vec::new(),
            steps: 0,
            hash: TrajectoryHash::default(),
        }
    }

    /// Tells whether the replay is full, so that no other step fits ([`MAX_STEPS`]).
    pub fn is_full(&self) -> bool {
        self.steps >= MAX_STEPS
    }

    /// Writes the file: the header, the records, the end record.
    pub fn write(&self, out: impl Write) -> io::Result<()> {
        let mut out = io::BufWriter::new(out);
        let mut lines = TrajectoryHash::default();
        let mut line = |out: &mut io::BufWriter<_>, text: String| {
            lines.add_line(text.as_bytes());
            writeln!(out, "{text}")
        };
        line(&mut out, json_line(&self.header))?;
        for record in &self.records {
            line(&mut out, json_line(record))?;
        }
        let end = Record::End {
            steps: self.steps,
            hash: self.hash.to_string(),
            lines: Some(Box::new(lines.to_string())),
        };
        writeln!(out, "{}", json_line(&end))?;
        out.flush()
    }

    /// Returns the file as bytes.
    pub fn to_bytes(&self) -> Vec<u8> {
        let mut bytes = Vec::new();
        // Writing to memory cannot fail.
        let _ = self.write(&mut bytes);
        bytes
    }

    /// Returns a stepper at the start of the replay: its settings, its initial state, no band.
    pub fn stepper(&self) -> Result<Stepper, ParamError> {
        let settings = self.header.settings;
        let mut stepper = Stepper::new(settings.params())?;
        stepper.state = BodyState::from_array(self.header.initial);
        stepper.integrator = settings.integrator;
        stepper.auto = self.header.auto.into();
        Ok(stepper)
    }
}

/// Returns one record as a line of JSON: serialising these plain structs cannot fail.
pub(super) fn json_line(value: &impl Serialize) -> String {
    serde_json::to_string(value).unwrap_or_default()
}

/// The integrator by its name, as the command line spells it.
mod integrator_name {
    use serde::{Deserialize, Deserializer, Serializer, de};

    use crate::physics::Integrator;

    pub fn serialize<S: Serializer>(integrator: &Integrator, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(integrator.name())
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Integrator, D::Error> {
        let name = String::deserialize(d)?;
        name.parse().map_err(de::Error::custom)
    }
}
