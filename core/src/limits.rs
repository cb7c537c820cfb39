//! The models' own domain, written once (the explorer's request limits build on it).

/// Largest impact speed any model accepts \[m/s\]: far above the slow-collision regime (the
/// models' validity ends near 1 m/s for ice), kept only so that no input reaches infinity.
pub const SPEED_MAX: f64 = 1e6;

/// Whether `g` is an impact speed the models accept: finite, positive and at most [`SPEED_MAX`].
pub fn speed_is_valid(g: f64) -> bool {
    g.is_finite() && g > 0.0 && g <= SPEED_MAX
}
