//! The models' own domain, written once (the explorer's request limits build on it).

/// Largest impact speed any model accepts \[m/s\]: far above the slow-collision regime (the
/// models' validity ends near 1 m/s for ice), kept only so that no input reaches infinity.
pub const SPEED_MAX: f64 = 1e6;

/// Whether `g` is an impact speed the models accept: finite, positive and at most [`SPEED_MAX`].
pub fn speed_is_valid(g: f64) -> bool {
    g.is_finite() && g > 0.0 && g <= SPEED_MAX
}

/// The domain of [`speed_is_valid`] as messages write it (`(0, 1e6]`, unit m/s apart).
pub const SPEED_DOMAIN: &str = "(0, 1e6]";

/// The domain of [`speed_or_zero_is_valid`] as messages write it.
pub const SPEED_OR_ZERO_DOMAIN: &str = "[0, 1e6]";

/// Whether `g` is a speed or zero (a stick map's tangential axis may start at rest).
pub fn speed_or_zero_is_valid(g: f64) -> bool {
    g == 0.0 || speed_is_valid(g)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The written domains say what the checks do: their upper end is [`SPEED_MAX`], and the
    /// checks accept it and refuse the next float above it.
    #[test]
    fn issue_36_the_written_domains_are_the_checked_ones() {
        for text in [SPEED_DOMAIN, SPEED_OR_ZERO_DOMAIN] {
            let upper = text.trim_end_matches(']').rsplit(", ").next().unwrap();
            assert_eq!(upper.parse::<f64>().unwrap(), SPEED_MAX, "{text}");
        }
        let above = f64::from_bits(SPEED_MAX.to_bits() + 1);
        assert!(speed_is_valid(SPEED_MAX) && !speed_is_valid(above) && !speed_is_valid(0.0));
        assert!(speed_or_zero_is_valid(0.0) && !speed_or_zero_is_valid(-0.1));
        assert!(SPEED_DOMAIN.starts_with('(') && SPEED_OR_ZERO_DOMAIN.starts_with("[0,"));
    }
}
