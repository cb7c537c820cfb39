//! Accuracy levels: the user's trade between speed and accuracy.

use crate::error::{Error, Result};

/// How accurately restitution coefficients are computed.
///
/// Each level carries a documented bound on the relative error of ε_N (where ε_N > 1e-6), checked by
/// the test suite against an independent high-precision reference. The default, `precise`, is the
/// best choice: the fine table is both the tightest named bound and, after `fast`, the cheapest
/// (issue 12: the old default integrated every contact, 100× slower at a 1e4 times looser bound).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum Accuracy {
    /// `fast`: the coarse table of the master curve ([`crate::normal::viscoelastic::master`]; brilliantov2007: of its own
    /// master surface, [`crate::models::brilliantov2007_master`]): relative error ≤ 1e-6.
    Fast,
    /// `integrated` (formerly `balanced`, still accepted): integrates every contact with adaptive
    /// Dormand–Prince at a moderate tolerance, relative error ≤ 1e-6. The slowest level; it checks
    /// the tables and serves contacts they do not cover.
    Balanced,
    /// `precise`: the fine table of the master curve (brilliantov2007: of its own master surface),
    /// relative error ≤ 1e-10 (the default).
    #[default]
    Precise,
    /// Adaptive Dormand–Prince with this relative tolerance (parsed from `[1e-11, 1e-2]`: tighter
    /// bounds than 1e-11 are not met by a double-precision integration of the contact).
    Tolerance(f64),
}

/// ε_N below which no accuracy level bounds the relative error (the tables and the integrator are
/// verified against the independent reference where ε_N > 1e-6; below, to its magnitude).
pub const ERROR_BOUND_DOMAIN: f64 = 1e-6;

/// The tightest tolerance a user may ask for: at rtol 1e-14, the integrator's floor, the measured error
/// against the independent reference stays below it.
pub const TIGHTEST_TOLERANCE: f64 = 1e-11;

impl Accuracy {
    /// The three named levels, in cycling order (cheapest first).
    pub const LEVELS: [Accuracy; 3] = [Accuracy::Fast, Accuracy::Precise, Accuracy::Balanced];

    /// Name used on the command line: `fast`, `precise`, `integrated`, or `tolerance`.
    pub fn name(self) -> &'static str {
        match self {
            Accuracy::Fast => "fast",
            Accuracy::Balanced => "integrated",
            Accuracy::Precise => "precise",
            Accuracy::Tolerance(_) => "tolerance",
        }
    }

    /// What the level trades, in a few words for a screen: how ε_N is obtained, its bound and its
    /// cost (`coarse table · error ≤ 1e-6 · ~0.05 µs per speed`). The costs are orders of magnitude
    /// measured by `rime bench` (one ε_N on the ice scenes); the surfaces show the measured frame time
    /// beside it.
    pub fn trade(self) -> &'static str {
        match self {
            Accuracy::Fast => "coarse table · error ≤ 1e-6 · ~0.05 µs per speed",
            Accuracy::Precise => {
                "fine table (literal layer: integrates) · error ≤ 1e-10 · ~0.06 µs per speed"
            }
            Accuracy::Balanced => "integrates each contact · error ≤ 1e-6 · ~10 µs per speed",
            Accuracy::Tolerance(_) => "integrates each contact at your tolerance · slowest",
        }
    }

    /// Parses `fast`, `precise`, `integrated` (or its former name `balanced`) or a relative
    /// tolerance such as `1e-8`.
    pub fn parse(text: &str) -> Result<Accuracy> {
        match text.trim() {
            "fast" => Ok(Accuracy::Fast),
            "integrated" | "balanced" => Ok(Accuracy::Balanced),
            "precise" => Ok(Accuracy::Precise),
            other => match other.parse::<f64>() {
                Ok(t) if t.is_finite() && (TIGHTEST_TOLERANCE..=1e-2).contains(&t) => {
                    Ok(Accuracy::Tolerance(t))
                }
                Ok(t) => Err(Error::OutOfRange {
                    field: "accuracy",
                    value: t,
                    expected: "a tolerance must lie in [1e-11, 1e-2]",
                }),
                Err(_) => Err(Error::InvalidValue {
                    field: "accuracy",
                    expected: "fast, precise, integrated, or a relative tolerance like 1e-8",
                }),
            },
        }
    }

    /// The next named level (for the explorer's `a` key): fast → precise → integrated → fast.
    pub fn next(self) -> Accuracy {
        match self {
            Accuracy::Fast => Accuracy::Precise,
            Accuracy::Precise => Accuracy::Balanced,
            Accuracy::Balanced | Accuracy::Tolerance(_) => Accuracy::Fast,
        }
    }

    /// The documented (and tested) bound on the relative error of ε_N.
    ///
    /// The bound holds where ε_N ≥ [`ERROR_BOUND_DOMAIN`]; below it only the order of magnitude of
    /// ε_N is promised and [`crate::Normal::error_estimate`] is infinite (no bound).
    pub fn error_bound(self) -> f64 {
        match self {
            Accuracy::Fast => 1e-6,
            Accuracy::Balanced => 1e-6,
            Accuracy::Precise => 1e-10,
            Accuracy::Tolerance(t) => t,
        }
    }

    /// Relative tolerance handed to the integrator so that the result meets [`Self::error_bound`].
    pub fn integrator_rtol(self) -> f64 {
        match self {
            // Fast falls back to the integrator only where no table applies. At 1e-8 zero-overlap
            // contacts near δ ~ 1 missed the 1e-6 bound (1.1e-6, found by the property tests).
            Accuracy::Fast => 1e-9,
            Accuracy::Balanced => 1e-9,
            Accuracy::Precise => 1e-13,
            // Global error is a multiple of the local tolerance: the safety factor of 1000 that
            // balanced uses (at 100, a zero-overlap contact near δ ~ 1 missed 1e-6 by 1.15×).
            Accuracy::Tolerance(t) => (t * 1e-3).max(1e-14),
        }
    }
}
