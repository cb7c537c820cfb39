//! Limits every surface enforces on what a user may ask for.

pub use crate::scene::limits::{SPEED_DOMAIN, SPEED_MAX, speed_is_valid};
/// Smallest (positive) speed a chart or a speed list may start at \[m/s\].
pub const SPEED_MIN: f64 = 1e-12;
/// The domain of [`chart_speed_is_valid`] as messages write it (unit m/s apart).
pub const CHART_SPEED_DOMAIN: &str = "[1e-12, 1e6]";
/// Largest number of points on one curve.
pub const MAX_CURVE_POINTS: usize = 20_000;
/// Largest stick-map side (the map has `n²` cells).
pub const MAX_MAP_SIDE: usize = 1_000;
/// Largest number of curves in one family.
pub const MAX_FAMILY: usize = 32;
/// Largest accepted scene JSON text \[bytes\] (a scene is a few hundred bytes).
pub const MAX_SCENE_BYTES: usize = 1 << 20;

/// Whether `g` may be an end of a chart's speed range: in [[`SPEED_MIN`], [`SPEED_MAX`]] (a chart
/// from 1e-300 m/s would span 300 decades; single speeds keep the models' own domain).
pub fn chart_speed_is_valid(g: f64) -> bool {
    speed_is_valid(g) && g >= SPEED_MIN
}

#[cfg(test)]
mod tests {
    use super::*;
    use alloc::format;

    #[test]
    fn issue_36_the_chart_domain_as_written_is_the_checked_one() {
        let inner = CHART_SPEED_DOMAIN
            .trim_start_matches('[')
            .trim_end_matches(']');
        let (lo, hi) = inner.split_once(", ").unwrap();
        assert_eq!(lo.parse::<f64>().unwrap(), SPEED_MIN);
        assert_eq!(hi.parse::<f64>().unwrap(), SPEED_MAX);
        let note = crate::explorer::range::MapRange {
            max: SPEED_MAX,
            clamped: true,
        };
        assert!(note.note().unwrap().contains(&format!("{hi} m/s")));
        assert_eq!(
            crate::explorer::request::CHART_SPEED_EXPECTED,
            format!("a speed in {CHART_SPEED_DOMAIN} m/s")
        );
    }

    #[test]
    fn the_chart_range_has_a_floor_that_single_speeds_do_not_issue_22() {
        // A link with view.from = 1e-300 drew a 301-decade chart; a single speed may be that slow.
        assert!(speed_is_valid(1e-300) && !chart_speed_is_valid(1e-300));
        assert!(chart_speed_is_valid(SPEED_MIN) && !chart_speed_is_valid(SPEED_MIN / 2.0));
        assert!(chart_speed_is_valid(SPEED_MAX) && !chart_speed_is_valid(SPEED_MAX * 2.0));
        assert!(!chart_speed_is_valid(f64::NAN) && !chart_speed_is_valid(0.0));
    }
}
