//! The error every validation in the core returns: a parameter outside its domain, named with
//! its value. A leaf, so that the body, the scene and the runs can all refuse bad input.

use std::fmt;

/// A parameter outside its domain: names the field and the value it was given.
#[derive(Clone, Debug, PartialEq)]
pub struct ParamError {
    pub field: &'static str,
    pub value: f64,
    pub requirement: String,
}

impl ParamError {
    pub fn check_positive(field: &'static str, value: f64) -> Result<(), Self> {
        if value.is_finite() && value > 0.0 {
            Ok(())
        } else {
            Err(Self {
                field,
                value,
                requirement: "a finite number greater than zero".to_owned(),
            })
        }
    }

    pub fn check_non_negative(field: &'static str, value: f64) -> Result<(), Self> {
        if value.is_finite() && value >= 0.0 {
            Ok(())
        } else {
            Err(Self {
                field,
                value,
                requirement: "a finite number, zero or more".to_owned(),
            })
        }
    }
    /// Checks that `value` lies within `range` (a finite number, ends included).
    ///
    /// The error's requirement names the ends.
    pub fn check_within(field: &'static str, value: f64, range: &Range) -> Result<(), Self> {
        if range.contains(value) {
            Ok(())
        } else {
            Err(Self {
                field,
                value,
                requirement: range.to_string(),
            })
        }
    }
}

/// A closed range a value must lie in, with its unit (empty for none).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Range {
    pub low: f64,
    pub high: f64,
    pub unit: &'static str,
}

impl Range {
    pub const fn new(low: f64, high: f64, unit: &'static str) -> Self {
        Self { low, high, unit }
    }

    /// Tells whether `value` lies in the range (never for NaN).
    pub fn contains(&self, value: f64) -> bool {
        self.low <= value && value <= self.high
    }

    /// Brings `value` inside the range (NaN to the low end).
    pub fn clamp(&self, value: f64) -> f64 {
        if value.is_nan() {
            self.low
        } else {
            value.clamp(self.low, self.high)
        }
    }
}

/// Writes a number whole: every bit of it, so that it reads back the same.
///
/// It is plain in the usual range (20, 0.05, 4096), in powers of ten beyond it (1e5, 1e-3).
/// A range's ends and a link's values are written so.
pub fn exact(value: f64) -> String {
    if value == 0.0 || (1e-2..1e5).contains(&value.abs()) {
        format!("{value}")
    } else {
        format!("{value:e}")
    }
}

/// "from 8 to 4096 Hz".
impl fmt::Display for Range {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "from {} to {}", exact(self.low), exact(self.high))?;
        if !self.unit.is_empty() {
            write!(f, " {}", self.unit)?;
        }
        Ok(())
    }
}

impl fmt::Display for ParamError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} must be {}, got {}",
            self.field, self.requirement, self.value
        )
    }
}

impl std::error::Error for ParamError {}
