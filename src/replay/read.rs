//! Reading a replay file: line by line, each checked against what came before, the first
//! bad line named with what is wrong in it. Nothing in a file can make it panic.

use std::fmt;
use std::io::{BufRead, Read};

use super::format::{
    AUTO_ORDERS, AutoRecord, BandRecord, FORMAT, Header, Integrity, MAX_LINE_BYTES, MAX_STEPS,
    Record, Replay, TrajectoryHash, VERSION,
};
use crate::physics::ParamError;
use crate::physics::body::STATE_LIMIT;

impl Replay {
    /// Reads and checks a whole file: the first bad line is named, with what is wrong in it.
    pub fn read(input: impl BufRead) -> Result<Self, ReplayError> {
        let mut reader = Reader::default();
        let mut input = input;
        let mut buffer = Vec::new();
        let mut number = 0usize;
        loop {
            buffer.clear();
            let read = (&mut input)
                .take(MAX_LINE_BYTES as u64 + 1)
                .read_until(b'\n', &mut buffer)
                .map_err(|error| ReplayError::at(number + 1, format!("cannot read: {error}")))?;
            if read == 0 {
                break;
            }
            number += 1;
            if buffer.last() == Some(&b'\n') {
                buffer.pop();
            } else if buffer.len() > MAX_LINE_BYTES {
                return Err(ReplayError::at(
                    number,
                    format!("longer than {MAX_LINE_BYTES} bytes: not a replay line"),
                ));
            }
            if buffer.last() == Some(&b'\r') {
                buffer.pop();
            }
            reader.line(number, &buffer)?;
        }
        reader.finish(number)
    }

    pub fn from_bytes(bytes: &[u8]) -> Result<Self, ReplayError> {
        Self::read(bytes)
    }

    /// Checks whether the game can play the replay.
    ///
    /// The header's settings and every settings record must be in the game's ranges
    /// (`Settings::check_playable`). The message names the line and the field.
    pub fn check_playable(&self) -> Result<(), ReplayError> {
        let at = |line: usize, error: crate::physics::ParamError| {
            ReplayError::at(line, format!("settings: {error} (the game's range)"))
        };
        self.header
            .settings
            .check_playable()
            .map_err(|e| at(1, e))?;
        for (index, record) in self.records.iter().enumerate() {
            if let Record::Settings { settings, .. } = record {
                // The header is line 1, the records follow it.
                settings.check_playable().map_err(|e| at(index + 2, e))?;
            }
        }
        Ok(())
    }

    /// Reads and checks a replay file: the message names the file, and the line if it is bad.
    #[cfg(not(target_arch = "wasm32"))]
    pub fn read_file(path: &std::path::Path) -> Result<Self, String> {
        let in_file = |message: String| format!("{}: {message}", path.display());
        let file =
            std::fs::File::open(path).map_err(|error| in_file(format!("cannot open: {error}")))?;
        Self::read(std::io::BufReader::new(file)).map_err(|error| in_file(error.to_string()))
    }
}

/// What is wrong with a replay file, and on which line (counted from 1).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ReplayError {
    pub line: Option<usize>,
    pub message: String,
}

impl ReplayError {
    fn at(line: usize, message: impl Into<String>) -> Self {
        Self {
            line: Some(line),
            message: message.into(),
        }
    }
}

impl fmt::Display for ReplayError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.line {
            Some(line) => write!(f, "line {line}: {}", self.message),
            None => f.write_str(&self.message),
        }
    }
}

impl std::error::Error for ReplayError {}

/// Reads a file line by line, checking each against what came before.
#[derive(Default)]
struct Reader {
    replay: Option<Replay>,
    end: Option<(u64, String)>,
    /// Whether the next step already has its reset (and, in `settings_noted`, its settings).
    ///
    /// The recorder writes at most one of each before a step, so a file cannot grow without
    /// steps.
    reset_noted: bool,
    settings_noted: bool,
    state_noted: bool,
    auto_noted: bool,
    /// The step the latest check record was for.
    checked: Option<u64>,
    /// The hash of the lines so far, for the end record's `lines`.
    lines: TrajectoryHash,
}

impl Reader {
    fn line(&mut self, number: usize, bytes: &[u8]) -> Result<(), ReplayError> {
        let at = |message: String| ReplayError::at(number, message);
        let text = std::str::from_utf8(bytes)
            .map_err(|_| at("not UTF-8 text: this is not a replay file".to_owned()))?;
        if self.end.is_some() {
            return Err(at("a line after the end record".to_owned()));
        }
        let Some(replay) = self.replay.as_mut() else {
            let header: Header = serde_json::from_str(text)
                .map_err(|error| at(format!("not a replay header: {error}")))?;
            check_header(&header).map_err(at)?;
            self.replay = Some(Replay::with_header(header));
            self.lines.add_line(bytes);
            return Ok(());
        };
        let record: Record = serde_json::from_str(text).map_err(|error| at(error.to_string()))?;
        if !matches!(record, Record::End { .. }) {
            self.lines.add_line(bytes);
        }
        let next = replay.steps + 1;
        let in_order = |step: u64, what: &str| {
            if step == next {
                Ok(())
            } else {
                Err(at(format!(
                    "{what} for step {step} out of order: the next step is {next}"
                )))
            }
        };
        match record {
            Record::Reset { step } => {
                in_order(step, "a reset")?;
                if std::mem::replace(&mut self.reset_noted, true) {
                    return Err(at(format!("a second reset before step {step}")));
                }
            }
            Record::Settings { step, ref settings } => {
                in_order(step, "settings")?;
                if std::mem::replace(&mut self.settings_noted, true) {
                    return Err(at(format!("a second settings record before step {step}")));
                }
                settings
                    .validate()
                    .map_err(|error| at(format!("settings: {error}")))?;
            }
            Record::State { step, ref state } => {
                in_order(step, "a state")?;
                if std::mem::replace(&mut self.state_noted, true) {
                    return Err(at(format!("a second state record before step {step}")));
                }
                check_state("state", state).map_err(at)?;
            }
            Record::Auto { step, auto } => {
                in_order(step, "auto's settings")?;
                if std::mem::replace(&mut self.auto_noted, true) {
                    return Err(at(format!("a second auto record before step {step}")));
                }
                check_auto(&auto).map_err(at)?;
            }
            Record::Check { step, ref state } => {
                if step != replay.steps || step == 0 {
                    return Err(at(format!(
                        "a check of step {step} out of order: the latest step is {}",
                        replay.steps
                    )));
                }
                if self.checked.replace(step) == Some(step) {
                    return Err(at(format!("a second check of step {step}")));
                }
                check_state("check", state).map_err(at)?;
            }
            Record::Step { step, band } => {
                in_order(step, "a step")?;
                if replay.is_full() {
                    return Err(at(format!("more than {MAX_STEPS} steps")));
                }
                if let Some(band) = band {
                    check_band(&band).map_err(at)?;
                }
                replay.steps = step;
                self.reset_noted = false;
                self.settings_noted = false;
                self.state_noted = false;
                self.auto_noted = false;
            }
            Record::End { steps, hash, lines } => {
                if steps != replay.steps {
                    return Err(at(format!(
                        "the end record counts {steps} steps, the file holds {}",
                        replay.steps
                    )));
                }
                let value = (hash.len() == 16)
                    .then(|| u64::from_str_radix(&hash, 16).ok())
                    .flatten()
                    .ok_or_else(|| at(format!("hash '{hash}' is not 16 hex digits")))?;
                replay.hash = TrajectoryHash(value);
                replay.integrity = match lines {
                    None => Integrity::Unknown,
                    Some(lines) if *lines == self.lines.to_string() => Integrity::Intact,
                    Some(_) => Integrity::Changed,
                };
                self.end = Some((steps, hash));
                return Ok(());
            }
        }
        replay.push(record);
        Ok(())
    }

    fn finish(self, lines: usize) -> Result<Replay, ReplayError> {
        let Some(replay) = self.replay else {
            return Err(ReplayError {
                line: None,
                message: "empty: no replay header".to_owned(),
            });
        };
        if self.end.is_none() {
            return Err(ReplayError::at(
                lines,
                "truncated: the file ends without its end record (the recording was cut off)",
            ));
        }
        Ok(replay)
    }
}

fn check_header(header: &Header) -> Result<(), String> {
    if header.format != FORMAT {
        return Err(format!(
            "format '{}' is not '{FORMAT}': not a replay file",
            header.format
        ));
    }
    if !(1..=VERSION).contains(&header.version) {
        return Err(format!(
            "replay format version {}; this build reads versions 1 to {VERSION}",
            header.version
        ));
    }
    header
        .settings
        .validate()
        .map_err(|error| format!("settings: {error}"))?;
    check_auto(&header.auto)?;
    check_state("initial", &header.initial)
}

fn check_auto(auto: &AutoRecord) -> Result<(), String> {
    ParamError::check_positive("auto.tolerance", auto.tolerance)
        .map_err(|error| error.to_string())?;
    if !(AUTO_ORDERS.0..=AUTO_ORDERS.1).contains(&auto.order) {
        return Err(format!(
            "auto.order must be from {} to {}, got {}",
            AUTO_ORDERS.0, AUTO_ORDERS.1, auto.order
        ));
    }
    if auto.max_substeps == 0 {
        return Err("auto.max_substeps must be at least 1, got 0".to_owned());
    }
    Ok(())
}

fn check_state(name: &str, state: &[f64; 6]) -> Result<(), String> {
    match state
        .iter()
        .find(|v| !(v.is_finite() && v.abs() <= STATE_LIMIT))
    {
        Some(bad) => Err(format!(
            "{name}: each component must be finite and within {STATE_LIMIT:e} of zero, got {bad:e}"
        )),
        None => Ok(()),
    }
}

fn check_band(band: &BandRecord) -> Result<(), String> {
    for (name, values) in [("band.point", band.point), ("band.anchor", band.anchor)] {
        if let Some(bad) = values
            .iter()
            .find(|v| !(v.is_finite() && v.abs() <= STATE_LIMIT))
        {
            return Err(format!(
                "{name}: each coordinate must be finite and within {STATE_LIMIT:e} of zero, got {bad:e}"
            ));
        }
    }
    Ok(())
}
