//! The one range policy of the ε_N chart and the stick map.

use super::limits::SPEED_MAX;
use crate::numerics::math::log10;
use crate::scene::contact::Contact;

/// Multiple of the largest critical speed that the automatic stick-map range spans: the sticking
/// corner (below g_s) then takes a fifth of each axis, and the regimes above it stay visible.
pub const MAP_RANGE_FACTOR: f64 = 5.0;

/// Range of the stick map when no critical speed sets one \[m/s\].
pub const MAP_RANGE_DEFAULT: f64 = 1.0;

/// A range with the note a surface must show beside it (empty when nothing needs saying).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MapRange {
    /// Upper end of both stick-map axes \[m/s\].
    pub max: f64,
    /// True when the automatic range was cut to [`SPEED_MAX`].
    pub clamped: bool,
}

/// A map range crosses with its note: `{max, clamped, note}`.
#[cfg(feature = "serde")]
impl serde::Serialize for MapRange {
    fn serialize<S: serde::Serializer>(&self, s: S) -> core::result::Result<S::Ok, S::Error> {
        use serde::ser::SerializeStruct;
        let mut st = s.serialize_struct("MapRange", 3)?;
        st.serialize_field("max", &self.max)?;
        st.serialize_field("clamped", &self.clamped)?;
        st.serialize_field("note", &self.note())?;
        st.end()
    }
}

impl MapRange {
    /// The note to show beside the map, if any.
    pub fn note(&self) -> Option<&'static str> {
        self.clamped.then_some(
            "stick map range cut to the speed limit 1e6 m/s: the critical speed lies above it",
        )
    }
}

/// The critical speeds (layer, Eq. (10); adhesion, Eq. (15)) of a contact, where they exist.
pub fn critical_speeds(contact: &Contact) -> [Option<f64>; 2] {
    [
        contact.layer.map(|l| l.critical_velocity),
        contact.adhesion.map(|a| a.critical_velocity),
    ]
}

/// Rounds up to 1, 2 or 5 × 10^k (1 for values that are not finite and positive).
pub fn nice_ceil(v: f64) -> f64 {
    if !(v.is_finite() && v > 0.0) {
        return 1.0;
    }
    // The nearest double to the decade, so that 5 × 10^k is the double `5e{k}` a user would type.
    let base = crate::numerics::grid::exact_decade(libm::floor(log10(v)) as i32);
    for m in [1.0, 2.0, 5.0, 10.0] {
        if m * base >= v * (1.0 - 1e-12) {
            return m * base;
        }
    }
    10.0 * base
}

/// The automatic stick-map range: [`MAP_RANGE_FACTOR`] × the largest critical speed, rounded up to
/// 1, 2 or 5 × 10^k and cut to [`SPEED_MAX`] (with a note); [`MAP_RANGE_DEFAULT`] without one.
pub fn auto_map_range(contact: &Contact) -> MapRange {
    let g_s = critical_speeds(contact)
        .into_iter()
        .flatten()
        .filter(|g| g.is_finite() && *g > 0.0)
        .fold(0.0, f64::max);
    if !(g_s > 0.0) {
        return MapRange {
            max: MAP_RANGE_DEFAULT,
            clamped: false,
        };
    }
    let max = nice_ceil(MAP_RANGE_FACTOR * g_s);
    if max > SPEED_MAX {
        MapRange {
            max: SPEED_MAX,
            clamped: true,
        }
    } else {
        MapRange {
            max,
            clamped: false,
        }
    }
}

/// The decades `(lo, hi)` of the ε_N chart: 1e-7…10 m/s, extended down to a decade below any
/// critical speed (not below 1e-12 m/s) and up to a decade above it (not above the speed limit).
pub fn chart_decades(contact: Option<&Contact>) -> (i32, i32) {
    let (mut lo, mut hi) = (-7, 1);
    if let Some(c) = contact {
        for g_s in critical_speeds(c).into_iter().flatten() {
            if g_s > 0.0 && g_s.is_finite() {
                let e = libm::floor(log10(g_s)) as i32;
                lo = lo.min(e - 1);
                hi = hi.max(e + 2);
            }
        }
    }
    (lo.max(-12), hi.min(6))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Scene;

    fn contact_with_layer(radius: f64, thickness: f64) -> Contact {
        let mut scene = crate::Preset::IceFrost.scene();
        scene.grains.radius_1 = radius;
        scene.grains.radius_2 = radius;
        if let Some(l) = scene.layer.as_mut() {
            l.thickness = thickness;
        }
        Contact::new(&scene).unwrap()
    }

    #[test]
    fn auto_map_range_never_exceeds_the_speed_limit_issue_10() {
        // R₁ = R₂ = 2 µm, D = 10 µm: g_s ≈ 1.8e6 m/s (Eq. (10) grows as D^(3/2)/R^(5/2)).
        let c = contact_with_layer(2e-6, 1e-5);
        let g_s = c.layer.unwrap().critical_velocity;
        assert!(g_s * MAP_RANGE_FACTOR > SPEED_MAX, "{g_s}");
        let r = auto_map_range(&c);
        assert_eq!(r.max, SPEED_MAX);
        assert!(r.clamped && r.note().is_some());
        // The ordinary case: 5 g_s rounded up, no note.
        let c = contact_with_layer(0.02, 1e-6);
        let g_s = c.layer.unwrap().critical_velocity;
        let r = auto_map_range(&c);
        assert!(
            r.max >= 5.0 * g_s && r.max < 10.0 * g_s && !r.clamped,
            "{r:?} {g_s}"
        );
        assert_eq!(
            auto_map_range(&Contact::new(&Scene::default()).unwrap()).max,
            1.0
        );
    }

    #[test]
    fn nice_ceil_rounds_up_to_one_two_five() {
        assert_eq!(nice_ceil(3.3e-5), 5e-5);
        assert_eq!(nice_ceil(1e-3), 1e-3);
        assert_eq!(nice_ceil(1.01e-3), 2e-3);
        assert_eq!(nice_ceil(f64::NAN), 1.0);
    }
}
