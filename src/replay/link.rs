//! A game in a link. What a player set up rides in the query as plain keys and values
//! (`?v=1&scene=stiff&integrator=rk4&k=1e5&rate=64&ghosts=on`); a whole recorded game rides in
//! the fragment (`#replay=...`: the replay file, deflated, in base64url). docs/links.md is the
//! format. Reading a link never fails as a whole: each key it cannot take is named in a
//! problem, and the rest is kept.

use std::fmt;

use data_encoding::BASE64URL_NOPAD;

use super::format::Replay;
use crate::physics::param_error::exact;
use crate::physics::{
    ANGULAR_DAMPING_RANGE, Integrator, LINEAR_DAMPING_RANGE, MASS_RANGE, Range, SIZE_RANGE,
    STEP_RATE_RANGE, STIFFNESS_RANGE, Scene, SceneParams, TIME_SCALE_RANGE,
};

/// The link format's version, written as `v=1`. A link without `v` is read as version 1.
pub const LINK_VERSION: u32 = 1;
/// The longest fragment read or written: about what a browser keeps in its address bar.
///
/// Chromium's limit is 2 MB.
pub const MAX_FRAGMENT_BYTES: usize = 2 << 20;
/// The most bytes a fragment may inflate to: a compressed fragment cannot ask for more memory.
pub const MAX_INFLATED_BYTES: usize = 64 << 20;

/// A key of the query: its name, what it sets, the values it takes and its default.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Key {
    Version,
    Scene,
    Integrator,
    Stiffness,
    Mass,
    Size,
    LinearDamping,
    AngularDamping,
    StepRate,
    TimeScale,
    /// An overlay switched on or off: one key an overlay, named as the overlay.
    Overlay(Overlay),
    Dock,
    Learn,
}

impl Key {
    /// In the order a link writes them: the overlays' keys are [`Overlay::ALL`]'s.
    pub const ALL: [Self; 12 + Overlay::ALL.len()] = {
        const SETTINGS: [Key; 10] = [
            Key::Version,
            Key::Scene,
            Key::Integrator,
            Key::Stiffness,
            Key::Mass,
            Key::Size,
            Key::LinearDamping,
            Key::AngularDamping,
            Key::StepRate,
            Key::TimeScale,
        ];
        let mut all = [Key::Learn; 12 + Overlay::ALL.len()];
        let mut at = 0;
        while at < SETTINGS.len() {
            all[at] = SETTINGS[at];
            at += 1;
        }
        while at < SETTINGS.len() + Overlay::ALL.len() {
            all[at] = Key::Overlay(Overlay::ALL[at - SETTINGS.len()]);
            at += 1;
        }
        all[at] = Key::Dock;
        all
    };

    pub fn name(self) -> &'static str {
        match self {
            Self::Version => "v",
            Self::Scene => "scene",
            Self::Integrator => "integrator",
            Self::Stiffness => "k",
            Self::Mass => "mass",
            Self::Size => "size",
            Self::LinearDamping => "linear-damping",
            Self::AngularDamping => "angular-damping",
            Self::StepRate => "rate",
            Self::TimeScale => "time",
            Self::Overlay(overlay) => overlay.name(),
            Self::Dock => "dock",
            Self::Learn => "learn",
        }
    }

    /// Returns what the key sets (docs/links.md's table).
    pub fn meaning(self) -> &'static str {
        match self {
            Self::Version => "the link format's version",
            Self::Scene => "a named scene, loaded with its scripted pull",
            Self::Integrator => "the integrator",
            Self::Stiffness => "band stiffness k",
            Self::Mass => "box mass",
            Self::Size => "the box's side (width and height)",
            Self::LinearDamping => "linear damping coefficient b (force −b·v)",
            Self::AngularDamping => "angular damping rate c",
            Self::StepRate => "fixed steps per second",
            Self::TimeScale => "time scale (slow motion below 1)",
            Self::Overlay(overlay) => overlay.meaning(),
            Self::Dock => "the dock of instruments",
            Self::Learn => "learn mode at this chapter (its scene and settings are the chapter's)",
        }
    }

    /// Returns the values the key takes (docs/links.md's table).
    ///
    /// They come from the core's own lists and ranges.
    pub fn values(self) -> String {
        match self {
            Self::Version => LINK_VERSION.to_string(),
            Self::Scene => Scene::NAMES.join(", "),
            Self::Integrator => {
                let names: Vec<&str> = Integrator::ALL.iter().map(|i| i.name()).collect();
                names.join(", ")
            }
            Self::Overlay(_) | Self::Dock => "on, off".to_owned(),
            Self::Learn => "a chapter's number, 1 to the last".to_owned(),
            _ => self.range().map(|r| r.to_string()).unwrap_or_default(),
        }
    }

    /// Returns the key's default: what the game starts with when the key is absent.
    pub fn default_value(self) -> String {
        let tutorial = SceneParams::tutorial();
        match self {
            Self::Version => LINK_VERSION.to_string(),
            Self::Scene => "none (the box at rest, no pull)".to_owned(),
            Self::Integrator => Integrator::default().name().to_owned(),
            Self::Stiffness
            | Self::Mass
            | Self::Size
            | Self::LinearDamping
            | Self::AngularDamping => "the scene's".to_owned(),
            Self::StepRate => exact(tutorial.step_rate_hz),
            Self::TimeScale => "1".to_owned(),
            Self::Dock => "on".to_owned(),
            Self::Learn => "none (play)".to_owned(),
            Self::Overlay(_) => "off".to_owned(),
        }
    }

    /// Returns the range a number must lie in: the game's own (`physics::scene`).
    pub fn range(self) -> Option<Range> {
        match self {
            Self::Stiffness => Some(STIFFNESS_RANGE),
            Self::Mass => Some(MASS_RANGE),
            Self::Size => Some(SIZE_RANGE),
            Self::LinearDamping => Some(LINEAR_DAMPING_RANGE),
            Self::AngularDamping => Some(ANGULAR_DAMPING_RANGE),
            Self::StepRate => Some(STEP_RATE_RANGE),
            Self::TimeScale => Some(TIME_SCALE_RANGE),
            _ => None,
        }
    }

    fn named(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|key| key.name() == name)
    }
}

/// A picture over the scene or beside it that the player switches on and off.
///
/// One list for the game's switches (`game::shared::Overlays`), their key actions, the panel's
/// buttons and a link's keys, which are the overlays' names in this order.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Overlay {
    /// Every integrator and a reference beside the live box.
    Ghosts,
    /// The ghosts' speed against their error, live.
    Plot,
    /// Force and velocity arrows.
    Vectors,
    /// The pulled corner's trail.
    Trail,
}

impl Overlay {
    /// Every overlay, in the order the panel shows them and a link writes them.
    pub const ALL: [Self; 4] = [Self::Ghosts, Self::Plot, Self::Vectors, Self::Trail];

    /// Returns the overlay's name: its button's label and its key in a link.
    pub fn name(self) -> &'static str {
        match self {
            Self::Ghosts => "ghosts",
            Self::Plot => "plot",
            Self::Vectors => "vectors",
            Self::Trail => "trail",
        }
    }

    /// Returns what the overlay shows (docs/links.md's table).
    pub fn meaning(self) -> &'static str {
        match self {
            Self::Ghosts => "every integrator and a reference beside the box",
            Self::Plot => "the plot of speed against error (turns the ghosts on)",
            Self::Vectors => "velocity and force arrows",
            Self::Trail => "the pulled corner's trail",
        }
    }

    /// Returns the overlay's place in [`Overlay::ALL`].
    pub fn index(self) -> usize {
        self as usize
    }
}

/// The overlays a link turns on or off; `None` leaves one as the game has it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct LinkOverlays {
    /// Each overlay's switch, in [`Overlay::ALL`]'s order.
    pub shown: [Option<bool>; Overlay::ALL.len()],
    pub dock: Option<bool>,
}

impl LinkOverlays {
    /// Returns what the link says of an overlay.
    pub fn get(&self, overlay: Overlay) -> Option<bool> {
        self.shown[overlay.index()]
    }

    /// Sets what the link says of an overlay.
    pub fn set(&mut self, overlay: Overlay, on: Option<bool>) {
        self.shown[overlay.index()] = on;
    }
}

/// What a link sets: each field `None` when the link leaves it as the game starts.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Link {
    /// One of [`Scene::NAMES`].
    pub scene: Option<String>,
    pub integrator: Option<Integrator>,
    pub stiffness: Option<f64>,
    pub mass: Option<f64>,
    /// The box's side: its width and height.
    pub size: Option<f64>,
    pub linear_damping: Option<f64>,
    pub angular_damping: Option<f64>,
    pub step_rate_hz: Option<f64>,
    pub time_scale: Option<f64>,
    pub overlays: LinkOverlays,
    /// A whole game, played from its start (its scene and settings are the replay's).
    pub replay: Option<Replay>,
    /// Learn mode's chapter, counted from 1.
    pub learn: Option<u32>,
}

/// A part of a link that was not taken, and why.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LinkProblem {
    /// The key as the link spells it (`replay` for the fragment).
    pub key: String,
    pub message: String,
}

impl fmt::Display for LinkProblem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.key, self.message)
    }
}

impl Link {
    /// Reads a link, naming every key it cannot take as a problem and keeping the rest.
    ///
    /// A link is a whole address (`https://.../?k=1e5#replay=...`), its query and fragment
    /// (`?k=1e5#replay=...`), or a bare query (`k=1e5&rate=64`).
    pub fn parse(address: &str) -> (Self, Vec<LinkProblem>) {
        let mut link = Self::default();
        let mut problems = Vec::new();
        let (rest, fragment) = match address.split_once('#') {
            Some((rest, fragment)) => (rest, Some(fragment)),
            None => (address, None),
        };
        let query = match rest.split_once('?') {
            Some((_, query)) => query,
            // An address with no query, or a bare query.
            None if rest.contains("://") || !rest.contains('=') => "",
            None => rest,
        };
        for pair in query.split('&').filter(|pair| !pair.is_empty()) {
            let (name, value) = pair.split_once('=').unwrap_or((pair, ""));
            let (name, value) = (decode(name), decode(value));
            if let Err(message) = link.take(&name, &value) {
                problems.push(LinkProblem { key: name, message });
            }
        }
        if let Some(fragment) = fragment.filter(|fragment| !fragment.is_empty()) {
            match fragment.split_once('=') {
                Some(("replay", data)) => match decode_replay(data) {
                    Ok(replay) => link.replay = Some(replay),
                    Err(message) => problems.push(LinkProblem {
                        key: "replay".to_owned(),
                        message,
                    }),
                },
                _ => problems.push(LinkProblem {
                    key: "#".to_owned(),
                    message: "the fragment is not '#replay=...': ignored".to_owned(),
                }),
            }
        }
        (link, problems)
    }

    /// Puts one key and its value in place, or says why not.
    fn take(&mut self, name: &str, value: &str) -> Result<(), String> {
        let Some(key) = Key::named(name) else {
            return Err("not a key this build knows: ignored".to_owned());
        };
        let number = || -> Result<f64, String> {
            let parsed: f64 = value
                .trim()
                .parse()
                .map_err(|_| format!("'{value}' is not a number"))?;
            let range = key.range().unwrap_or(Range::new(f64::MIN, f64::MAX, ""));
            if range.contains(parsed) {
                Ok(parsed)
            } else {
                Err(format!("must be {range}, got {value}"))
            }
        };
        let switch = || match value {
            "on" | "1" | "true" => Ok(true),
            "off" | "0" | "false" => Ok(false),
            _ => Err(format!("'{value}' is not on or off")),
        };
        match key {
            Key::Version => match value.parse::<u32>() {
                Ok(LINK_VERSION) => {}
                _ => {
                    return Err(format!(
                        "version '{value}'; this build reads version {LINK_VERSION} (the keys it \
                         knows were applied)"
                    ));
                }
            },
            Key::Scene => {
                let name = Scene::named(value).map_err(|error| error.to_string())?.name;
                self.scene = Some(name.to_owned());
            }
            Key::Integrator => {
                self.integrator = Some(value.parse().map_err(|e| format!("{e}"))?);
            }
            Key::Stiffness => self.stiffness = Some(number()?),
            Key::Mass => self.mass = Some(number()?),
            Key::Size => self.size = Some(number()?),
            Key::LinearDamping => self.linear_damping = Some(number()?),
            Key::AngularDamping => self.angular_damping = Some(number()?),
            Key::StepRate => self.step_rate_hz = Some(number()?),
            Key::TimeScale => self.time_scale = Some(number()?),
            Key::Overlay(overlay) => self.overlays.set(overlay, Some(switch()?)),
            Key::Dock => self.overlays.dock = Some(switch()?),
            Key::Learn => match value.trim().parse::<u32>() {
                Ok(chapter) if chapter >= 1 => self.learn = Some(chapter),
                _ => return Err(format!("'{value}' is not a chapter's number (1, 2, ...)")),
            },
        }
        Ok(())
    }

    /// Returns the keys a link with a replay ignores: the replay sets the scene and its settings.
    pub fn settings_keys(&self) -> Vec<&'static str> {
        [
            (self.scene.is_some(), Key::Scene),
            (self.integrator.is_some(), Key::Integrator),
            (self.stiffness.is_some(), Key::Stiffness),
            (self.mass.is_some(), Key::Mass),
            (self.size.is_some(), Key::Size),
            (self.linear_damping.is_some(), Key::LinearDamping),
            (self.angular_damping.is_some(), Key::AngularDamping),
            (self.step_rate_hz.is_some(), Key::StepRate),
        ]
        .into_iter()
        .filter(|(set, _)| *set)
        .map(|(_, key)| key.name())
        .collect()
    }

    /// Writes the link's query and fragment (`?v=1&...#replay=...`).
    ///
    /// Each key the link sets comes in [`Key::ALL`]'s order; [`Link::parse`] reads it back to the
    /// same link. A replay too long for a link ([`MAX_FRAGMENT_BYTES`]) is refused.
    pub fn to_query(&self) -> Result<String, String> {
        let mut pairs = vec![format!("v={LINK_VERSION}")];
        let mut put = |key: Key, value: Option<String>| {
            if let Some(value) = value {
                pairs.push(format!("{}={value}", key.name()));
            }
        };
        let switch = |on: Option<bool>| on.map(|on| if on { "on" } else { "off" }.to_owned());
        put(Key::Scene, self.scene.clone());
        put(
            Key::Integrator,
            self.integrator.map(|i| i.name().to_owned()),
        );
        put(Key::Stiffness, self.stiffness.map(exact));
        put(Key::Mass, self.mass.map(exact));
        put(Key::Size, self.size.map(exact));
        put(Key::LinearDamping, self.linear_damping.map(exact));
        put(Key::AngularDamping, self.angular_damping.map(exact));
        put(Key::StepRate, self.step_rate_hz.map(exact));
        put(Key::TimeScale, self.time_scale.map(exact));
        for overlay in Overlay::ALL {
            put(Key::Overlay(overlay), switch(self.overlays.get(overlay)));
        }
        put(Key::Dock, switch(self.overlays.dock));
        put(Key::Learn, self.learn.map(|chapter| chapter.to_string()));
        let mut text = format!("?{}", pairs.join("&"));
        if let Some(replay) = &self.replay {
            let data = encode_replay(replay);
            if data.len() > MAX_FRAGMENT_BYTES {
                return Err(format!(
                    "the game is too long for a link ({} KB, at most {} KB): save it as a file",
                    data.len() / 1024,
                    MAX_FRAGMENT_BYTES / 1024
                ));
            }
            text.push_str("#replay=");
            text.push_str(&data);
        }
        Ok(text)
    }
}

/// Encodes a replay as a fragment's data: its file deflated (level 9), in unpadded base64url.
pub fn encode_replay(replay: &Replay) -> String {
    let deflated = miniz_oxide::deflate::compress_to_vec(&replay.to_bytes(), 9);
    BASE64URL_NOPAD.encode(&deflated)
}

/// Decodes a fragment's data back to a replay, read and checked as a file is.
///
/// The replay is then held to the game's ranges (`Replay::check_playable`).
pub fn decode_replay(data: &str) -> Result<Replay, String> {
    if data.len() > MAX_FRAGMENT_BYTES {
        return Err(format!(
            "longer than {} KB: not a link's replay",
            MAX_FRAGMENT_BYTES / 1024
        ));
    }
    let deflated = BASE64URL_NOPAD
        .decode(data.trim_end_matches('=').as_bytes())
        .map_err(|error| format!("not base64url: {error}"))?;
    let bytes = miniz_oxide::inflate::decompress_to_vec_with_limit(&deflated, MAX_INFLATED_BYTES)
        .map_err(|error| format!("not a deflated replay: {error}"))?;
    let replay = Replay::from_bytes(&bytes).map_err(|error| error.to_string())?;
    replay.check_playable().map_err(|error| error.to_string())?;
    Ok(replay)
}

/// Decodes `%41` and `+` as a browser writes them (a bad escape is kept as written).
fn decode(text: &str) -> String {
    let bytes = text.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        match bytes[i] {
            b'+' => out.push(b' '),
            b'%' if i + 2 < bytes.len() => {
                let hex = std::str::from_utf8(&bytes[i + 1..i + 3]).ok();
                match hex.and_then(|hex| u8::from_str_radix(hex, 16).ok()) {
                    Some(byte) => {
                        out.push(byte);
                        i += 2;
                    }
                    None => out.push(b'%'),
                }
            }
            byte => out.push(byte),
        }
        i += 1;
    }
    String::from_utf8_lossy(&out).into_owned()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Checks that an overlay's index is its place in `Overlay::ALL`.
    ///
    /// `ALL` lists the variants in the order they are declared; the ghosts come before the
    /// plot, which turns them on.
    #[test]
    fn overlays_are_listed_in_their_order_the_ghosts_before_the_plot() {
        for (at, overlay) in Overlay::ALL.into_iter().enumerate() {
            assert_eq!(overlay.index(), at, "{overlay:?}");
        }
        assert!(Overlay::Ghosts.index() < Overlay::Plot.index());
    }
}
