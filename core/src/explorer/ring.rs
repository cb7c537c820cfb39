//! The ring card (issue 24): what the scene's law does to a ring, built once for every surface.
//!
//! Given the scene, τ and Ω (or a planet and a distance), [`ring_card`] runs
//! [`crate::applications::ring::equilibrium`] and returns what a card draws: the ε_cr line for the ε_N chart (a
//! figure series, so every surface draws it alike), where the scene's ε_N(g) curve meets it, the
//! ring's mean impact speed as a chart marker, c and H in words and the plain verdict. The physics
//! and its limits are in docs/physics.md#ring.

use crate::applications::ring::{
    FLOOR_IN_R_OMEGA, RingInput, RingRecord, SLOW_REGIME_LIMIT, Verdict, equilibrium,
};
use crate::applications::ring_sizes::{
    self, DampingRule, SizeDistribution, SizeRingInput, SizeRingRecord, Viscosity,
};
use crate::error::{Error, Result};
use crate::explorer::format::{qty, sig};
use crate::explorer::palette;
use crate::figure::{Figure, Marker, Series, Stroke};
use crate::numerics::accuracy::Accuracy;
use crate::numerics::math::{exp, ln};
use crate::scene::Scene;
use crate::scene::contact::Contact;
use alloc::format;
use alloc::string::{String, ToString};
use alloc::vec;
use alloc::vec::Vec;

/// Log-spaced samples of ε_N(g) searched for the meeting with the ε_cr line.
const MEETING_SAMPLES: usize = 200;

/// One printed row of the card.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct RingRow {
    /// What the row is (`velocity dispersion c`, …).
    pub label: String,
    /// The printed value (4 significant digits, as [`qty`] prints).
    pub text: String,
}

/// Everything a ring card shows.
#[derive(Debug, Clone, PartialEq)]
pub struct RingCard {
    /// The prediction behind the card (`rime ring`'s record).
    pub record: RingRecord,
    /// The ε_cr line across the chart's speed range, dashed (the prediction's ε_cr, with the
    /// Enskog collision rate at the balance).
    pub eps_cr_line: Series,
    /// Where the scene's ε_N(g) curve meets the line `(g, ε_cr)`: the lowest crossing in the
    /// chart's range, `None` when the curve stays on one side there.
    pub meeting: Option<(f64, f64)>,
    /// The ring's mean impact speed √π c, a vertical marker on the chart.
    pub impact_marker: Marker,
    /// c, H, the impact speed, ε_cr, ε̄, the equilibration time (and the smooth-grain
    /// alternative when the scene has friction), printed.
    pub rows: Vec<RingRow>,
    /// The verdict word(s): [`Verdict::words`] of the ring of many sizes when the card has one, else
    /// of the scene's one size.
    pub verdict: &'static str,
    /// Whether the ring settles ([`Verdict::is_equilibrium`]).
    pub equilibrium: bool,
    /// The verdict in a plain sentence.
    pub sentence: String,
    /// The ring's kinematic viscosity (docs/physics.md#ring-sizes): of the scene's one size, or of
    /// the size distribution when the card has one.
    pub viscosity: Viscosity,
    /// The ring of many sizes the card describes besides the scene's one size (issue 38): its
    /// ring-wide c and H and its bins, smallest first; `None` for one size.
    pub sizes: Option<SizeRingRecord>,
}

/// The ring card's size choices, the same on every surface (issue 38): the scene's one size, or
/// `dN/dR ∝ R^−3` (Saturn's rings' q ≈ 2.75–3) from the scene's radius R to 5R or 10R in three
/// bins equal in log R, with A the same for every pair (a material constant). `rime ring
/// --radii … --q …` takes any other distribution.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum CardSizeChoice {
    /// The scene's grains only.
    #[default]
    #[cfg_attr(feature = "serde", serde(rename = "one"))]
    One,
    /// R to 5R, q = 3.
    #[cfg_attr(feature = "serde", serde(rename = "to_5r"))]
    ToFiveR,
    /// R to 10R, q = 3.
    #[cfg_attr(feature = "serde", serde(rename = "to_10r"))]
    ToTenR,
}

impl CardSizeChoice {
    /// Every choice, in the order a key cycles through them.
    pub const ALL: [CardSizeChoice; 3] = [Self::One, Self::ToFiveR, Self::ToTenR];

    /// The size exponent q of the distributions.
    pub const Q: f64 = 3.0;

    /// The number of bins of the distributions.
    pub const BINS: usize = 3;

    /// Its name in JSON and links (`one`, `to_5r`, `to_10r`).
    pub fn name(self) -> &'static str {
        match self {
            Self::One => "one",
            Self::ToFiveR => "to_5r",
            Self::ToTenR => "to_10r",
        }
    }

    /// What a person reads: `one size`, `R–5R, q = 3`.
    pub fn label(self) -> &'static str {
        match self {
            Self::One => "one size",
            Self::ToFiveR => "R–5R, q = 3",
            Self::ToTenR => "R–10R, q = 3",
        }
    }

    /// The next choice (after the last, the first).
    pub fn next(self) -> Self {
        match self {
            Self::One => Self::ToFiveR,
            Self::ToFiveR => Self::ToTenR,
            Self::ToTenR => Self::One,
        }
    }

    /// The distribution for grains of radius `radius` \[m\]; `None` for one size.
    pub fn sizes(self, radius: f64) -> Option<CardSizes> {
        let top = match self {
            Self::One => return None,
            Self::ToFiveR => 5.0,
            Self::ToTenR => 10.0,
        };
        Some(CardSizes {
            sizes: SizeDistribution::PowerLaw {
                q: Self::Q,
                radius_min: radius,
                radius_max: top * radius,
                bins: Self::BINS,
            },
            damping_rule: DampingRule::Same,
        })
    }
}

/// A size distribution for the ring card: the sizes and the rule for A across them.
#[derive(Debug, Clone, PartialEq)]
pub struct CardSizes {
    /// The sizes (a power law or a list).
    pub sizes: SizeDistribution,
    /// How A follows from the scene's for every pair.
    pub damping_rule: DampingRule,
}

impl RingCard {
    /// Adds the card to the ε_N chart's figure, the same on every surface: the dashed ε_cr line,
    /// the meeting point (a one-point series) and the mean-impact-speed marker.
    pub fn overlay(&self, fig: &mut Figure) {
        fig.series.push(self.eps_cr_line.clone());
        if let Some((g, e)) = self.meeting {
            fig.series.push(Series {
                name: format!("ε_N meets the ring's ε_cr at g = {}", qty(g, "m/s")),
                short: format!("meets ε_cr {}", qty(g, "m/s")),
                points: vec![(g, e)],
                color: palette::SERIES_RING,
                stroke: Stroke::Points,
            });
        }
        fig.markers.push(self.impact_marker.clone());
    }
}

fn row(label: &str, text: String) -> RingRow {
    RingRow {
        label: label.to_string(),
        text,
    }
}

/// The card for `scene` at `input`, drawn over the ε_N chart's speed range `chart` \[m/s\]
/// (`0 < from < to`, finite). Errors name the field (`tau`, `omega`, …, `chart`).
// Long by design: the card's rows in the order they are shown, each from the one equilibrium
// record.
pub fn ring_card(scene: &Scene, input: &RingInput, chart: (f64, f64)) -> Result<RingCard> {
    ring_card_with_sizes(scene, input, None, chart)
}

/// [`ring_card`] with a size distribution (issue 38): the card's chart parts and first rows stay
/// the ring of the scene's one size; rows for the ring of many sizes follow (ring-wide c and H,
/// the smallest and largest bins, ν). Errors name the field (`q`, `radius_min`, `bins`, …).
// Long by design: the card's rows in the order they are shown, each from the one equilibrium
// record.
pub fn ring_card_with_sizes(
    scene: &Scene,
    input: &RingInput,
    sizes: Option<&CardSizes>,
    chart: (f64, f64),
) -> Result<RingCard> {
    let (from, to) = chart;
    if !(from.is_finite() && to.is_finite() && from > 0.0 && to > from) {
        return Err(Error::InvalidValue {
            field: "chart",
            expected: "a speed range 0 < from < to (finite, m/s)",
        });
    }
    let record = equilibrium(scene, input)?;
    let p = *record.prediction();
    let eps_cr = p.eps_cr;
    let eps_cr_line = Series {
        name: format!(
            "ε_cr of the ring at τ = {} (docs/physics.md#ring)",
            sig(record.tau, 4)
        ),
        short: "ring ε_cr".to_string(),
        points: vec![(from, eps_cr), (to, eps_cr)],
        color: palette::SERIES_RING,
        stroke: Stroke::Dashed,
    };
    let contact = Contact::new(scene)?;
    let meeting = meeting(&contact, eps_cr, from, to)?;
    let v = p.mean_impact_speed;
    let impact_marker = Marker {
        x: v,
        label: format!("ring: mean impact speed √π c = {}", qty(v, "m/s")),
        short: format!("ring √πc {}", qty(v, "m/s")),
        color: palette::SERIES_RING,
    };
    let r_omega = record.radius * record.omega;
    let c = p.velocity_dispersion;
    let mut rows = vec![
        row(
            "velocity dispersion c",
            format!("{} ({} RΩ)", qty(c, "m/s"), sig(c / r_omega, 4)),
        ),
        row(
            "thickness H (rms z)",
            format!(
                "{} ({} grain radii)",
                qty(p.thickness, "m"),
                sig(p.thickness / record.radius, 4)
            ),
        ),
        row("mean impact speed √π c", qty(v, "m/s")),
        row("ε_cr at the balance", sig(eps_cr, 4)),
        row("ε̄ of the impacts", sig(p.eps_effective, 4)),
        row(
            "equilibration",
            if p.equilibration_orbits > 0.0 {
                format!("{} orbits from the floor", sig(p.equilibration_orbits, 4))
            } else {
                "none: the ring starts and stays at the floor".to_string()
            },
        ),
    ];
    let sizes = match sizes {
        Some(s) => Some(ring_sizes::equilibrium(
            scene,
            &SizeRingInput {
                tau: input.tau,
                orbit: input.orbit,
                sizes: s.sizes.clone(),
                damping_rule: s.damping_rule,
            },
        )?),
        None => None,
    };
    let viscosity = match &sizes {
        Some(rec) => rec.viscosity,
        None => ring_sizes::one_size_viscosity(scene, input)?,
    };
    // With sizes, what the user asked for comes first (a small terminal cuts the card from the
    // bottom); the one-size rows, which the chart's overlay belongs to, follow under their header.
    if let Some(rec) = &sizes {
        let one_size = core::mem::take(&mut rows);
        rows.extend(size_rows(rec));
        rows.push(row("viscosity ν (all sizes)", viscosity_text(&viscosity)));
        rows.push(row(
            "one size",
            format!(
                "R = {}, as on the chart (ε_cr line, meeting point, impact speed):",
                qty(record.radius, "m")
            ),
        ));
        rows.extend(one_size);
    }
    if sizes.is_none() {
        rows.push(row("viscosity ν", viscosity_text(&viscosity)));
    }
    if record.friction {
        let s = record.smooth;
        rows.push(row(
            "smooth grains (no friction)",
            format!(
                "{}: c = {}, H = {}",
                s.verdict.words(),
                qty(s.velocity_dispersion, "m/s"),
                qty(s.thickness, "m")
            ),
        ));
    }
    if let Some(a) = record.scaled_damping_time {
        rows.push(row(
            "A for this radius",
            format!(
                "A′ = {} keeps ε_N(g) of the grains A was set for: a different material",
                qty(a, "s")
            ),
        ));
    }
    // The verdict at the top is the ring the user asked for: of many sizes when given.
    let shown = sizes.as_ref().map_or(p.verdict, |s| s.verdict);
    let mut sentence = sentence(&record, r_omega);
    if sizes.is_some() {
        sentence = format!("For the scene's one size: {sentence}");
    }
    Ok(RingCard {
        record,
        eps_cr_line,
        meeting,
        impact_marker,
        rows,
        verdict: shown.words(),
        equilibrium: shown.is_equilibrium(),
        sentence,
        viscosity,
        sizes,
    })
}

/// ν with its two parts and d ln ν/d ln τ, as a row prints it.
fn viscosity_text(v: &Viscosity) -> String {
    let (scale, unit) = crate::format::area_per_time_unit(v.total);
    let q = |x: f64| format!("{} {unit}", sig(x / scale, 4));
    format!(
        "{} (translational {}, collisional {}); d ln ν/d ln τ = {}",
        q(v.total),
        q(v.translational),
        q(v.collisional),
        sig(v.dlnnu_dlntau, 3)
    )
}

/// The rows of a ring of many sizes: ring-wide c and H with the verdict, then the smallest and
/// largest bins (c and H each).
fn size_rows(rec: &SizeRingRecord) -> Vec<RingRow> {
    let range = match (rec.size_bins.first(), rec.size_bins.last()) {
        (Some(a), Some(b)) => format!("{}–{}", qty(a.radius_min, "m"), qty(b.radius_max, "m")),
        _ => "—".to_string(),
    };
    let mut rows = vec![row(
        &format!("sizes {range}, all grains"),
        format!(
            "c = {}, H = {}: {} (rms over the grains; A {})",
            qty(rec.velocity_dispersion, "m/s"),
            qty(rec.thickness, "m"),
            rec.verdict.words(),
            match rec.damping_rule {
                DampingRule::Same => "the same for all pairs",
                DampingRule::KeepEpsilon => "scaled so all pairs keep ε_N(g)",
            }
        ),
    )];
    let bin = |label: &str, b: &ring_sizes::BinPrediction| {
        row(
            label,
            format!(
                "{}–{}: c = {}, H = {}{}",
                qty(b.radius_min, "m"),
                qty(b.radius_max, "m"),
                qty(b.velocity_dispersion, "m/s"),
                qty(b.thickness, "m"),
                if b.at_floor { " (at its floor)" } else { "" }
            ),
        )
    };
    if let (Some(first), Some(last)) = (rec.size_bins.first(), rec.size_bins.last()) {
        rows.push(bin("smallest grains", first));
        if rec.size_bins.len() > 1 {
            rows.push(bin("largest grains", last));
        }
    }
    rows
}

fn sentence(record: &RingRecord, r_omega: f64) -> String {
    let p = record.prediction();
    let c = qty(p.velocity_dispersion, "m/s");
    let grains = if record.friction {
        "with the scene's friction"
    } else {
        "smooth grains"
    };
    match p.verdict {
        Verdict::Equilibrium => format!(
            "Equilibrium ({grains}): the ring settles at c = {c}, where the mean ε of its impacts \
             equals ε_cr = {}, about {} orbits after starting from the floor.",
            sig(p.eps_cr, 4),
            sig(p.equilibration_orbits, 3)
        ),
        Verdict::MonolayerFloor => format!(
            "Equilibrium at the monolayer floor ({grains}): even the slowest impacts lose more \
             than the shear's local gain, so the ring flattens to c ≈ {}RΩ = {c}, held there by \
             the finite-size gain.",
            sig(FLOOR_IN_R_OMEGA, 2)
        ),
        Verdict::Aggregates => format!(
            "Aggregates ({grains}): {} % of the impacts stick at c = {c}; the ring clumps.",
            sig(100.0 * p.sticking_fraction, 3)
        ),
        Verdict::Heats => format!(
            "Heats ({grains}): no balance in the slow-collision regime (mean impact speed {} \
             against the {} limit, c = {} RΩ); the ring disperses.",
            qty(p.mean_impact_speed, "m/s"),
            qty(SLOW_REGIME_LIMIT, "m/s"),
            sig(p.velocity_dispersion / r_omega, 3)
        ),
    }
}

/// The lowest g in `[from, to]` where ε_N(g) crosses `eps_cr` (log-spaced scan, then bisection).
fn meeting(contact: &Contact, eps_cr: f64, from: f64, to: f64) -> Result<Option<(f64, f64)>> {
    let f = |g: f64| -> Result<f64> { Ok(contact.eps_n(g, Accuracy::Fast)? - eps_cr) };
    let (a, b) = (ln(from), ln(to));
    let step = (b - a) / MEETING_SAMPLES as f64;
    let mut prev = (a, f(from)?);
    for k in 1..=MEETING_SAMPLES {
        let x = a + k as f64 * step;
        let y = f(exp(x))?;
        if prev.1 == 0.0 {
            return Ok(Some((exp(prev.0), eps_cr)));
        }
        if (prev.1 < 0.0) != (y < 0.0) {
            let (mut lo, mut hi, low_sign) = (prev.0, x, prev.1 < 0.0);
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                if (f(exp(mid))? < 0.0) == low_sign {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            return Ok(Some((exp(0.5 * (lo + hi)), eps_cr)));
        }
        prev = (x, y);
    }
    Ok(None)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::applications::ring::Orbit;
    use crate::scene::Preset;

    fn ice(radius: f64, friction: bool) -> Scene {
        let mut scene = Preset::Ice.scene();
        scene.grains.radius_1 = radius;
        scene.grains.radius_2 = radius;
        if !friction {
            scene.friction = None;
        }
        scene
    }

    fn a_ring() -> RingInput {
        RingInput {
            tau: 0.5,
            orbit: Orbit::Omega(1.3143527e-4),
            damping_set_for_radius: None,
        }
    }

    #[test]
    fn the_line_and_the_meeting_point_lie_on_the_curve_and_at_eps_cr() {
        let scene = ice(0.02, false);
        let card = ring_card(&scene, &a_ring(), (1e-7, 1.0)).unwrap();
        let p = card.record.smooth;
        assert_eq!(
            card.eps_cr_line.points,
            vec![(1e-7, p.eps_cr), (1.0, p.eps_cr)]
        );
        assert_eq!(card.eps_cr_line.stroke, Stroke::Dashed);
        // The meeting point is on the scene's curve (its own ε_N there equals ε_cr).
        let (g, e) = card.meeting.unwrap();
        let contact = Contact::new(&scene).unwrap();
        assert!((contact.eps_n(g, Accuracy::Fast).unwrap() - e).abs() < 1e-9);
        // ε_N falls with g and the balance averages it over Rayleigh impacts, so the single-impact
        // speed with ε_N = ε_cr lies within the spread of the ring's impact speeds.
        let v = p.mean_impact_speed;
        assert!(g > 0.2 * v && g < 3.0 * v, "{g} vs {v}");
        assert_eq!(card.impact_marker.x, v);
        // The overlay adds the line, the meeting point and the marker to a chart's figure.
        let mut fig = Figure::stick_map("f".into(), "t".into(), "c".into(), vec![], vec![], 1.0);
        card.overlay(&mut fig);
        assert_eq!(fig.series.len(), 2);
        assert_eq!(fig.series[1].points, vec![(g, e)]);
        assert_eq!(fig.series[1].stroke, Stroke::Points);
        assert_eq!(fig.markers, vec![card.impact_marker.clone()]);
        assert_eq!(card.verdict, "equilibrium");
        assert!(card.equilibrium);
        assert!(card.sentence.starts_with("Equilibrium (smooth grains)"));
    }

    #[test]
    fn issue_24_the_card_says_floor_heats_and_different_material() {
        let floor = ring_card(&ice(0.02, true), &a_ring(), (1e-7, 1.0)).unwrap();
        assert_eq!(floor.verdict, "equilibrium at the monolayer floor");
        assert!(floor.equilibrium);
        assert!(
            floor
                .rows
                .iter()
                .any(|r| r.label.starts_with("smooth grains"))
        );
        let mut input = a_ring();
        input.damping_set_for_radius = Some(0.02);
        let hot = ring_card(&ice(1.0, true), &input, (1e-7, 1.0)).unwrap();
        assert_eq!(hot.verdict, "heats");
        assert!(!hot.equilibrium);
        assert!(hot.sentence.starts_with("Heats"));
        assert!(
            hot.rows
                .iter()
                .any(|r| r.text.contains("a different material"))
        );
    }

    #[test]
    fn the_printed_rows_read_back_as_the_record() {
        use crate::explorer::format::agrees_to_printed;
        let card = ring_card(&ice(0.02, false), &a_ring(), (1e-7, 1.0)).unwrap();
        let p = card.record.smooth;
        // "34.16 mm" is compared as 34.16 against the value in mm (no float noise in its digits).
        let check = |label: &str, unit: &str, computed: f64| {
            let text = &card.rows.iter().find(|r| r.label == label).unwrap().text;
            let shown = text.split(" (").next().unwrap();
            let (number, scale) = match shown.split_once(' ') {
                Some((n, u)) => (
                    n,
                    crate::scene::units::parse_quantity("unit", &format!("1 {u}"), unit).unwrap(),
                ),
                None => (shown, 1.0),
            };
            let number: f64 = number.parse().unwrap();
            assert!(
                agrees_to_printed(computed / scale, number),
                "{text} vs {computed}"
            );
        };
        check("velocity dispersion c", "m/s", p.velocity_dispersion);
        check("thickness H (rms z)", "m", p.thickness);
        check("mean impact speed √π c", "m/s", p.mean_impact_speed);
        check("ε_cr at the balance", "1", p.eps_cr);
    }

    #[test]
    fn a_bad_chart_range_names_the_field() {
        for chart in [
            (0.0, 1.0),
            (1.0, 0.5),
            (f64::NAN, 1.0),
            (1e-6, f64::INFINITY),
        ] {
            assert!(matches!(
                ring_card(&ice(0.02, true), &a_ring(), chart),
                Err(Error::InvalidValue { field: "chart", .. })
            ));
        }
        let mut bad = a_ring();
        bad.tau = -1.0;
        assert!(matches!(
            ring_card(&ice(0.02, true), &bad, (1e-7, 1.0)),
            Err(Error::OutOfRange { field: "tau", .. })
        ));
    }

    fn power_law(q: f64, from: f64, to: f64, bins: usize) -> CardSizes {
        CardSizes {
            sizes: SizeDistribution::PowerLaw {
                q,
                radius_min: from,
                radius_max: to,
                bins,
            },
            damping_rule: DampingRule::Same,
        }
    }

    /// The card of one size shows ν of that ring: the one-bin ring of many sizes, which the
    /// card with a list of the scene's one radius must give too (two paths to the same ring).
    #[test]
    fn issue_38_the_card_shows_the_rings_viscosity() {
        let scene = ice(0.02, true);
        let card = ring_card(&scene, &a_ring(), (1e-7, 1.0)).unwrap();
        let one = CardSizes {
            sizes: SizeDistribution::List {
                radii: vec![0.02],
                fractions: vec![1.0],
            },
            damping_rule: DampingRule::Same,
        };
        let listed = ring_card_with_sizes(&scene, &a_ring(), Some(&one), (1e-7, 1.0)).unwrap();
        assert_eq!(card.viscosity, listed.viscosity);
        assert!(card.sizes.is_none());
        // ν = ν_trans + ν_coll > 0, and the row prints the total with its unit.
        let v = card.viscosity;
        assert!(v.translational > 0.0 && v.collisional > 0.0);
        assert_eq!(v.total, v.translational + v.collisional);
        let row = card.rows.iter().find(|r| r.label == "viscosity ν").unwrap();
        // 2 cm ice at τ = 0.5 has ν ~ 1e-7 m²/s: written in mm²/s, 4 significant digits.
        assert!((1e-8..1e-6).contains(&v.total), "{}", v.total);
        let printed = format!("{} mm²/s", sig(v.total * 1e6, 4));
        assert!(row.text.starts_with(&printed), "{} vs {printed}", row.text);
    }

    /// A distribution adds its rows after the one-size rows and leaves the chart's parts alone;
    /// the bins' edges are equal in log R (1–5 cm in three bins: 5^(1/3) and 5^(2/3) cm).
    #[test]
    fn issue_38_the_card_shows_the_smallest_and_largest_bins() {
        let scene = ice(0.02, true);
        let plain = ring_card(&scene, &a_ring(), (1e-7, 1.0)).unwrap();
        let sizes = power_law(3.0, 0.01, 0.05, 3);
        let card = ring_card_with_sizes(&scene, &a_ring(), Some(&sizes), (1e-7, 1.0)).unwrap();
        assert_eq!(card.eps_cr_line, plain.eps_cr_line);
        assert_eq!(card.meeting, plain.meeting);
        // The sizes' rows come first; the one-size rows follow their header, unchanged.
        let one = plain
            .rows
            .iter()
            .position(|r| r.label == "viscosity ν")
            .unwrap();
        let header = card
            .rows
            .iter()
            .position(|r| r.label == "one size")
            .unwrap();
        assert_eq!(card.rows[header + 1..header + 1 + one], plain.rows[..one]);
        assert_eq!(
            card.rows[0].label,
            format!("sizes {}–{}, all grains", qty(0.01, "m"), qty(0.05, "m"))
        );
        let rec = card.sizes.as_ref().unwrap();
        assert_eq!(rec.size_bins.len(), 3);
        assert_eq!(card.viscosity, rec.viscosity);
        let text = |label: &str| {
            card.rows
                .iter()
                .find(|r| r.label == label)
                .map(|r| r.text.clone())
                .unwrap()
        };
        let edge1 = 0.01 * 5f64.powf(1.0 / 3.0);
        let edge2 = 0.01 * 5f64.powf(2.0 / 3.0);
        let small = text("smallest grains");
        assert!(
            small.starts_with(&format!("{}–{}", qty(0.01, "m"), qty(edge1, "m"))),
            "{small}"
        );
        let large = text("largest grains");
        assert!(
            large.starts_with(&format!("{}–{}", qty(edge2, "m"), qty(0.05, "m"))),
            "{large}"
        );
        // Small grains move faster than large ones (partial equipartition, Salo 1992).
        let (s, l) = (rec.size_bins[0], rec.size_bins[2]);
        assert!(s.velocity_dispersion > l.velocity_dispersion);
        assert!(small.contains(&qty(s.velocity_dispersion, "m/s")));
        let nu = rec.viscosity.total;
        assert!((1e-8..1e-6).contains(&nu), "{nu}");
        assert!(
            text("viscosity ν (all sizes)").starts_with(&format!("{} mm²/s", sig(nu * 1e6, 4)))
        );
    }

    #[test]
    fn issue_38_a_bad_distribution_names_the_field() {
        let bad = power_law(3.0, 0.05, 0.01, 3);
        assert!(matches!(
            ring_card_with_sizes(&ice(0.02, true), &a_ring(), Some(&bad), (1e-7, 1.0)),
            Err(Error::OutOfRange {
                field: "radius_max",
                ..
            })
        ));
    }

    #[test]
    fn issue_38_the_size_choices_cycle_and_scale_with_the_grains() {
        let mut c = CardSizeChoice::default();
        let mut seen = vec![];
        for _ in 0..3 {
            seen.push(c);
            c = c.next();
        }
        assert_eq!(seen, CardSizeChoice::ALL);
        assert_eq!(c, CardSizeChoice::One);
        assert!(CardSizeChoice::One.sizes(0.02).is_none());
        match CardSizeChoice::ToTenR.sizes(0.02).map(|s| s.sizes) {
            Some(SizeDistribution::PowerLaw {
                q,
                radius_min,
                radius_max,
                bins,
            }) => assert_eq!((q, radius_min, radius_max, bins), (3.0, 0.02, 0.2, 3)),
            other => panic!("{other:?}"),
        }
    }
}
