//! The error every validation in the core returns: a parameter outside its domain, named with
//! its value. A leaf, so that the body, the scene and the runs can all refuse bad input.

use std::fmt;

/// A parameter outside its domain: names the field and the value it was given.
#[derive(Clone, Debug, PartialEq)]
pub struct ParamError {
    pub field: &'static str,
    pub value: f64,
    pub requirement: &'static str,
}

impl ParamError {
    pub fn check_positive(field: &'static str, value: f64) -> Result<(), Self> {
        if value.is_finite() && value > 0.0 {
            Ok(())
        } else {
            Err(Self {
                field,
                value,
                requirement: "a finite number greater than zero",
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
                requirement: "a finite number, zero or more",
            })
        }
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
