//! The one error type of `rime-core`.

use core::fmt;

/// Everything that can go wrong in `rime-core`.
///
/// Every variant names the offending field (a dotted scene path such as `layer.viscosity`, or an
/// argument name such as `g_n`) so that front ends can report it verbatim.
#[non_exhaustive]
#[derive(Debug, Clone, PartialEq)]
pub enum Error {
    /// A number is outside the range the model accepts.
    OutOfRange {
        /// Dotted path or argument name.
        field: &'static str,
        /// The rejected value (may be NaN or infinite).
        value: f64,
        /// Human-readable statement of the accepted range, e.g. `"must be > 0"`.
        expected: &'static str,
    },
    /// A quantity derived from several fields is not representable (overflow, underflow).
    DerivedOutOfRange {
        /// Name of the derived quantity, e.g. `"m_eff"`.
        quantity: &'static str,
        /// The fields it is derived from.
        fields: &'static str,
    },
    /// A parameter path passed to [`crate::Scene::set`] does not exist.
    UnknownParameter,
    /// A value could not be parsed for the given field.
    InvalidValue {
        /// Dotted path of the field.
        field: &'static str,
        /// What was expected.
        expected: &'static str,
    },
    /// The integrator took more steps than its budget allows (a guard against hangs).
    StepBudgetExceeded {
        /// Which computation ran out of steps.
        what: &'static str,
        /// The step budget.
        steps: usize,
    },
    /// The integrator's step size underflowed.
    StepSizeUnderflow {
        /// Which computation failed.
        what: &'static str,
        /// Time at which it happened (dimensionless).
        t: f64,
    },
    /// Drawing a figure failed (feature `plot`).
    Plot {
        /// What went wrong.
        reason: &'static str,
    },
    /// A fit did not converge or its input was unusable.
    Fit {
        /// What went wrong.
        reason: &'static str,
    },
}

/// A number as messages print it: the shortest text that reads back as the same value, plain
/// between 1e-4 and 1e6 and with an exponent outside (`1e300`, not 301 digits).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Number(pub f64);

impl fmt::Display for Number {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let v = self.0;
        if v == 0.0 || !v.is_finite() || (1e-4..1e6).contains(&v.abs()) {
            write!(f, "{v}")
        } else {
            write!(f, "{v:e}")
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::OutOfRange {
                field,
                value,
                expected,
            } => write!(f, "{field}: {expected} (got {})", Number(*value)),
            Error::DerivedOutOfRange { quantity, fields } => write!(
                f,
                "{fields}: the derived quantity {quantity} is not a finite positive number"
            ),
            Error::UnknownParameter => write!(f, "unknown parameter"),
            Error::InvalidValue { field, expected } => write!(f, "{field}: expected {expected}"),
            Error::StepBudgetExceeded { what, steps } => {
                write!(
                    f,
                    "{what}: integration exceeded its budget of {steps} steps"
                )
            }
            Error::StepSizeUnderflow { what, t } => {
                write!(
                    f,
                    "{what}: integrator step size underflow at s = {}",
                    Number(*t)
                )
            }
            Error::Fit { reason } => write!(f, "fit: {reason}"),
            Error::Plot { reason } => write!(f, "figure: {reason}"),
        }
    }
}

/// `core::error::Error` (stable since Rust 1.81): the error works with `?` into `Box<dyn Error>`
/// and error-reporting crates with or without `std`.
impl core::error::Error for Error {}

/// Shorthand for `Result<T, rime_core::Error>`.
pub type Result<T> = core::result::Result<T, Error>;

/// Checks that `value` is finite and strictly positive.
pub(crate) fn positive(field: &'static str, value: f64) -> Result<f64> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(Error::OutOfRange {
            field,
            value,
            expected: "must be a finite number > 0",
        })
    }
}

/// Checks that `value` is finite and non-negative.
pub(crate) fn non_negative(field: &'static str, value: f64) -> Result<f64> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(Error::OutOfRange {
            field,
            value,
            expected: "must be a finite number >= 0",
        })
    }
}

/// Checks that `value` lies in `[lo, hi]`.
pub(crate) fn within(
    field: &'static str,
    value: f64,
    lo: f64,
    hi: f64,
    expected: &'static str,
) -> Result<f64> {
    if value.is_finite() && value >= lo && value <= hi {
        Ok(value)
    } else {
        Err(Error::OutOfRange {
            field,
            value,
            expected,
        })
    }
}
