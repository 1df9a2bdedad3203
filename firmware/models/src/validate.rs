//! Parameter validation shared by every model: one error type naming the
//! field and the reason, and the checks the `validate()` methods use.
use core::fmt;

/// A parameter that failed validation: which field and why.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ParamError {
    /// Field name as written in the struct / TOML file.
    pub field: &'static str,
    /// Human-readable reason (e.g. "must be finite and > 0").
    pub reason: &'static str,
}

impl fmt::Display for ParamError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "invalid parameter `{}`: {}", self.field, self.reason)
    }
}

#[cfg(feature = "std")]
impl std::error::Error for ParamError {}

/// Finite and strictly positive.
pub fn check_pos(field: &'static str, v: f64) -> Result<(), ParamError> {
    if v.is_finite() && v > 0.0 {
        Ok(())
    } else {
        Err(ParamError {
            field,
            reason: "must be finite and > 0",
        })
    }
}

/// Finite and not negative.
pub fn check_nonneg(field: &'static str, v: f64) -> Result<(), ParamError> {
    if v.is_finite() && v >= 0.0 {
        Ok(())
    } else {
        Err(ParamError {
            field,
            reason: "must be finite and >= 0",
        })
    }
}

/// Finite (not NaN, not infinite).
pub fn check_finite(field: &'static str, v: f64) -> Result<(), ParamError> {
    if v.is_finite() {
        Ok(())
    } else {
        Err(ParamError {
            field,
            reason: "must be finite",
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn checks_name_the_field_and_refuse_nan() {
        assert_eq!(check_pos("r", 1.0), Ok(()));
        for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            assert_eq!(check_pos("r", bad).unwrap_err().field, "r");
        }
        assert_eq!(check_nonneg("j", 0.0), Ok(()));
        assert!(check_nonneg("j", -1e-9).is_err());
        assert!(check_nonneg("j", f64::NAN).is_err());
        assert_eq!(check_finite("x", -3.0), Ok(()));
        assert!(check_finite("x", f64::NEG_INFINITY).is_err());
    }
}
