//! The appendix of the paper: tidal force, adhesion and self-gravity of two touching grains in orbit
//! (Eq. (A.1)–(A.7)), with docs/physics.md#decision-8.
//!
//! Two identical spheres of radius `r` and density `ρ` touch; the line of centres is radial and the
//! contact point is at distance `d` from a planet of mass `M`.
//!
//! **Deviations from the printed numbers (not fudged, shown).**
//! * `G` is printed as `6.672 N m²/kg²` (the exponent is missing); we use `6.672e-11`.
//! * Eq. (A.2) is `F_s = πγR_eff` with `R_eff = r/2` (3.14e-3 N in the example), but the paper's quoted
//!   `6.28e-3 N` is `πγr`. Both are reported ([`Tidal::surface_force`], [`Tidal::surface_force_paper`]).
//! * The paper's `d_min ≈ 5.43e4 m` is not what its own Eq. (A.6) gives: A.6 (both printed forms)
//!   gives `3.08e5 m`, still far inside the planet.
//! * Eq. (A.5) gives `r_max = 37.72 m`, not quite the printed `37.6 m` (0.3 % apart). `r_max` is very
//!   sensitive to its inputs: `4M/d³ − πρ/3 = 954.11 − 942.48` keeps 1.2 % of either term, so
//!   `r_max ∝ (4M/d³ − πρ/3)^(−1/3)` moves by −27 × any relative change of `4M/d³`; the printed value
//!   corresponds to `4M/d³` larger by only 0.012 % (a rounded intermediate would do it).
//!
//! `ΔF` and `d_Roche` reproduce the printed values to all printed digits.

use crate::error::{Error, Result, non_negative, positive};
use crate::numerics::math::cbrt;
use core::f64::consts::PI;

/// The gravitational constant \[N m²/kg²\] as the paper uses it: `6.672e-11` (printed as `6.672`
/// without the exponent; the CODATA value 6.674e-11 would change the third digit of nothing quoted).
pub const G: f64 = 6.672e-11;

/// Inputs of the appendix. `Default` is the paper's example (Saturn, Encke division, 2 cm ice grains).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
pub struct TidalInput {
    /// Planet mass `M` \[kg\]. Default 5.688e26 kg (Saturn).
    pub planet_mass: f64,
    /// Distance `d` of the contact point from the planet's centre \[m\]. Default 1.336e8 m (Encke
    /// division).
    pub distance: f64,
    /// Grain radius `r` \[m\] (both grains; `R_eff = r/2`). Default 0.02 m.
    pub radius: f64,
    /// Grain density `ρ` \[kg/m³\]. Default 900 kg/m³.
    pub density: f64,
    /// Surface energy `γ` \[J/m²\] (0 allowed: no adhesion). Default 0.1 J/m².
    pub surface_energy: f64,
}

impl Default for TidalInput {
    fn default() -> Self {
        TidalInput {
            planet_mass: 5.688e26,
            distance: 1.336e8,
            radius: 0.02,
            density: 900.0,
            surface_energy: 0.1,
        }
    }
}

/// The appendix's quantities for one [`TidalInput`].
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Tidal {
    /// Mass of one grain `m = (4/3)πρr³` \[kg\].
    pub mass: f64,
    /// Tidal force difference, Eq. (A.1) exact: `GMm (1/(d−r)² − 1/(d+r)²)`, evaluated without
    /// cancellation as `GMm·4dr/((d−r)²(d+r)²)` \[N\].
    pub delta_f: f64,
    /// Eq. (A.1) approximation for `r ≪ d`: `4GMmr/d³` \[N\].
    pub delta_f_approx: f64,
    /// JKR pull-off estimate, Eq. (A.2): `πγR_eff` with `R_eff = r/2` \[N\].
    pub surface_force: f64,
    /// `πγr` \[N\]: what the paper's quoted 6.28e-3 N actually is.
    pub surface_force_paper: f64,
    /// Mutual gravity of the grains, Eq. (A.3): `Gm²/(4r²)` \[N\].
    pub gravity: f64,
    /// Classical Roche distance without adhesion, Eq. (A.7): `(12M/(πρ))^(1/3)` \[m\].
    pub d_roche: f64,
    /// Minimum distance at which grains of radius `r` stay in contact, Eq. (A.6) \[m\].
    #[doc(alias = "Eq. (A.6)")]
    pub d_min: f64,
    /// Maximum radius of grains that stay in contact at distance `d`, Eq. (A.5) \[m\]; `None` where
    /// `4M/d³ ≤ πρ/3` (at or outside the Roche distance, self-gravity alone holds any size).
    #[doc(alias = "Eq. (A.5)")]
    pub r_max: Option<f64>,
}

/// The numbers the paper prints for its example (appendix), for comparison with [`tidal`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TidalQuoted {
    /// ΔF ≈ 3.84e-11 N (reproduced).
    pub delta_f: f64,
    /// F_s ≈ 6.28e-3 N (that is πγr, not Eq. (A.2)'s πγR_eff).
    pub surface_force: f64,
    /// d_Roche ≈ 1.341e8 m (reproduced).
    pub d_roche: f64,
    /// d_min ≈ 5.43e4 m (not reproduced: Eq. (A.6) gives 3.08e5 m).
    pub d_min: f64,
    /// r_max ≈ 37.6 m (Eq. (A.5) gives 37.72 m, 0.3 % larger; see the module docs).
    pub r_max: f64,
}

/// The paper's printed values for the default [`TidalInput`].
pub const PAPER_QUOTED: TidalQuoted = TidalQuoted {
    delta_f: 3.84e-11,
    surface_force: 6.28e-3,
    d_roche: 1.341e8,
    d_min: 5.43e4,
    r_max: 37.6,
};

fn finite(quantity: &'static str, value: f64) -> Result<f64> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::DerivedOutOfRange {
            quantity,
            fields: "planet_mass, distance, radius, density, surface_energy",
        })
    }
}

impl Tidal {
    /// The one verdict of every surface: the pair stays in contact when the tidal pull ΔF of
    /// Eq. (A.1) (exact) is below what holds it, adhesion plus self-gravity F_s + F_g of
    /// Eq. (A.2) and (A.3) — the balance of Eq. (A.4).
    #[doc(alias = "Eq. (A.4)")]
    pub fn holds(&self) -> bool {
        self.delta_f < self.hold()
    }

    /// What holds the pair, F_s + F_g \[N\].
    pub fn hold(&self) -> f64 {
        self.surface_force + self.gravity
    }

    /// (F_s + F_g)/ΔF: above 1 the pair stays in contact.
    pub fn margin(&self) -> f64 {
        self.hold() / self.delta_f
    }

    /// The verdict in words (`ΔF < F_s + F_g (×1.6e8): the pair stays in contact`).
    #[cfg(feature = "alloc")]
    pub fn verdict(&self) -> alloc::string::String {
        if self.holds() {
            alloc::format!(
                "ΔF < F_s + F_g (×{}): the pair stays in contact",
                crate::format::sig(self.margin(), 2)
            )
        } else {
            alloc::string::String::from("ΔF ≥ F_s + F_g: the tide pulls the pair apart")
        }
    }
}

/// Evaluates Eq. (A.1)–(A.7). Inputs must be finite and positive (`surface_energy` may be 0) with
/// `radius < distance`; the error names the offending field.
#[doc(alias = "Eq. (A.1)")]
pub fn tidal(input: &TidalInput) -> Result<Tidal> {
    let big_m = positive("planet_mass", input.planet_mass)?;
    let d = positive("distance", input.distance)?;
    let r = positive("radius", input.radius)?;
    let rho = positive("density", input.density)?;
    let gamma = non_negative("surface_energy", input.surface_energy)?;
    if r >= d {
        return Err(Error::OutOfRange {
            field: "radius",
            value: r,
            expected: "must be smaller than distance",
        });
    }
    let r3 = r * r * r;
    let mass = finite("m", 4.0 / 3.0 * PI * rho * r3)?;
    let gmm = G * big_m * mass;
    // Eq. (A.1), exact: 1/(d−r)² − 1/(d+r)² = 4dr/((d−r)(d+r))²; d − r and d + r are single roundings.
    let p = (d - r) * (d + r);
    let delta_f = finite("delta_f", gmm * (4.0 * d * r / p) / p)?;
    // Eq. (A.1), r ≪ d.
    let delta_f_approx = finite("delta_f_approx", 4.0 * gmm * (r / d) / (d * d))?;
    // Eq. (A.2) with R_eff = r/2, and the paper's number πγr.
    let surface_force = PI * gamma * 0.5 * r;
    let surface_force_paper = PI * gamma * r;
    // Eq. (A.3).
    let gravity = finite("gravity", G * mass * mass / (4.0 * r * r))?;
    // Eq. (A.7).
    let d_roche = finite("d_roche", cbrt(12.0 / PI * big_m / rho))?;
    // Eq. (A.6), first form: ((32/3) G M ρ r³ / (γ + (8/9)π G ρ² r³))^(1/3).
    let d_min = finite(
        "d_min",
        cbrt(32.0 / 3.0 * G * big_m * rho * r3 / (gamma + 8.0 / 9.0 * PI * G * rho * rho * r3)),
    )?;
    // Eq. (A.5): r_max = (3γ / (8Gρ(4M/d³ − πρ/3)))^(1/3).
    let excess = 4.0 * (big_m / d) / (d * d) - PI / 3.0 * rho;
    let r_max = if excess > 0.0 {
        Some(finite(
            "r_max",
            cbrt(3.0 * gamma / (8.0 * G * rho * excess)),
        )?)
    } else {
        None
    };
    Ok(Tidal {
        mass,
        delta_f,
        delta_f_approx,
        surface_force,
        surface_force_paper,
        gravity,
        d_roche,
        d_min,
        r_max,
    })
}

#[cfg(test)]
mod tests {
    #[test]
    fn one_verdict_flips_at_d_min_issue_21() {
        // d_min (Eq. (A.6)) is where F_s + F_g balance the tidal pull: the verdict must flip
        // there (to the approximation A.4 makes, ΔF ≈ 4GMmr/d³, which is tiny for r ≪ d).
        let paper = super::TidalInput::default();
        let t = super::tidal(&paper).expect("paper");
        assert!(t.holds() && t.margin() > 1.0, "{t:?}");
        for (factor, holds) in [(1.01, true), (0.99, false)] {
            let input = super::TidalInput {
                distance: t.d_min * factor,
                ..paper
            };
            let at = super::tidal(&input).expect("near d_min");
            assert_eq!(at.holds(), holds, "{factor}: {at:?}");
            assert_eq!(at.holds(), at.margin() > 1.0);
        }
    }

    use super::*;

    fn rel(a: f64, b: f64) -> f64 {
        (a - b).abs() / b.abs()
    }

    /// True when `x` rounds to `quoted` at `digits` significant digits, as printed.
    fn prints_as(x: f64, digits: i32, quoted: f64) -> bool {
        let e = libm::floor(libm::log10(x.abs())) as i32;
        let scale = libm::pow(10.0, (digits - 1 - e) as f64);
        let rounded = libm::round(x * scale) / scale;
        (rounded - quoted).abs() <= 1e-12 * quoted.abs()
    }

    #[test]
    fn reproduces_the_printed_delta_f_and_roche_distance() {
        let t = tidal(&TidalInput::default()).unwrap();
        assert!(
            prints_as(t.delta_f, 3, PAPER_QUOTED.delta_f),
            "{}",
            t.delta_f
        );
        assert!(
            prints_as(t.d_roche, 4, PAPER_QUOTED.d_roche),
            "{}",
            t.d_roche
        );
        // Eq. (A.5) by hand: 4M/d³ = 954.114, πρ/3 = 942.478, difference 11.636;
        // (0.3/(8 · 6.672e-11 · 900 · 11.636))^(1/3) = 37.72 m. The paper prints 37.6 m (0.3 % off).
        let r_max = t.r_max.unwrap();
        assert!(prints_as(r_max, 4, 37.72), "{r_max}");
        assert!(rel(r_max, PAPER_QUOTED.r_max) < 4e-3);
        // m ≈ 30 g.
        assert!(prints_as(t.mass, 1, 0.03), "{}", t.mass);
    }

    #[test]
    fn surface_force_of_the_paper_is_pi_gamma_r() {
        let t = tidal(&TidalInput::default()).unwrap();
        assert!(prints_as(
            t.surface_force_paper,
            3,
            PAPER_QUOTED.surface_force
        ));
        // Eq. (A.2) with R_eff = r/2 is half of it: 3.14e-3 N.
        assert!(
            prints_as(t.surface_force, 3, 3.14e-3),
            "{}",
            t.surface_force
        );
        assert!(t.surface_force > 1e7 * t.delta_f);
    }

    #[test]
    fn d_min_is_3_08e5_not_the_printed_5_43e4() {
        let t = tidal(&TidalInput::default()).unwrap();
        assert!(prints_as(t.d_min, 3, 3.08e5), "{}", t.d_min);
        assert!(t.d_min / PAPER_QUOTED.d_min > 5.0);
        assert!(t.d_min < t.d_roche);
    }

    #[test]
    fn a1_exact_form_keeps_the_digits_the_naive_difference_loses() {
        let inp = TidalInput::default();
        let t = tidal(&inp).unwrap();
        let (d, r) = (inp.distance, inp.radius);
        let gmm = G * inp.planet_mass * t.mass;
        // Reference by the exact identity 1/(d−r)² − 1/(d+r)² = (4r/d³)(1 − ε²)^(−2), ε = r/d,
        // expanded: (1 − ε²)^(−2) = 1 + 2ε² + 3ε⁴ + …; here 2ε² ≈ 4.5e-20 is below double precision,
        // so the exact value equals the r ≪ d form to rounding.
        let eps = r / d;
        let reference = 4.0 * gmm * (r / d) / (d * d) * (1.0 + 2.0 * eps * eps);
        assert!(rel(t.delta_f, reference) < 1e-15);
        assert!(rel(t.delta_f_approx, reference) < 1e-15);
        let naive = gmm * (1.0 / ((d - r) * (d - r)) - 1.0 / ((d + r) * (d + r)));
        let naive_error = rel(naive, reference);
        // Each term has a rounding error ≈ 1e-16 relative; their difference is 6e-10 of them, so
        // about 2e-7 relative error: ~7 digits lost.
        assert!(naive_error > 1e-11 && naive_error < 1e-5, "{naive_error}");
    }

    #[test]
    fn a1_exact_form_on_a_case_with_an_exact_answer() {
        // d = 3, r = 1: 1/4 − 1/16 = 3/16; approximation 4/27.
        let inp = TidalInput {
            planet_mass: 1.0 / G,
            distance: 3.0,
            radius: 1.0,
            density: 3.0 / (4.0 * PI),
            surface_energy: 0.0,
        };
        let t = tidal(&inp).unwrap();
        assert!(rel(t.mass, 1.0) < 1e-15);
        assert!(rel(t.delta_f, 3.0 / 16.0) < 1e-15);
        assert!(rel(t.delta_f_approx, 4.0 / 27.0) < 1e-15);
    }

    #[test]
    fn both_forms_of_a6_agree() {
        for &r in &[1e-4, 0.02, 1.0, 37.6, 1e3] {
            for &gamma in &[0.0, 0.1, 10.0] {
                let inp = TidalInput {
                    radius: r,
                    surface_energy: gamma,
                    ..TidalInput::default()
                };
                let t = tidal(&inp).unwrap();
                let (m, rho) = (inp.planet_mass, inp.density);
                let second = libm::pow(
                    PI / 12.0 * rho / m + 3.0 / 32.0 * gamma / (G * m * rho * r * r * r),
                    -1.0 / 3.0,
                );
                assert!(rel(t.d_min, second) < 1e-14, "r = {r}, γ = {gamma}");
                // A.7 is A.6 without adhesion; adhesion moves d_min inside.
                if gamma == 0.0 {
                    assert!(rel(t.d_min, t.d_roche) < 1e-14);
                } else {
                    assert!(t.d_min < t.d_roche);
                }
            }
        }
    }

    #[test]
    fn a5_a6_a7_are_one_balance() {
        for &r in &[0.01, 0.02, 0.5, 10.0] {
            let at_r = tidal(&TidalInput {
                radius: r,
                ..TidalInput::default()
            })
            .unwrap();
            // At d = d_min(r) the balance F_g + F_s − ΔF = 0 holds (with ΔF ≈ 4GMmr/d³, as in A.4),
            // and r_max(d) = r.
            let inp = TidalInput {
                radius: r,
                distance: at_r.d_min,
                ..TidalInput::default()
            };
            let t = tidal(&inp).unwrap();
            let balance = t.gravity + t.surface_force - t.delta_f_approx;
            assert!(balance.abs() < 1e-12 * t.delta_f_approx, "r = {r}");
            assert!(rel(t.r_max.unwrap(), r) < 1e-12);
        }
        // At the Roche distance F_g = ΔF (approx) whatever r; outside it r_max is unbounded.
        let roche = tidal(&TidalInput::default()).unwrap().d_roche;
        for &r in &[0.02, 3.0] {
            let t = tidal(&TidalInput {
                radius: r,
                distance: roche,
                ..TidalInput::default()
            })
            .unwrap();
            assert!(rel(t.gravity, t.delta_f_approx) < 1e-12);
        }
        let outside = tidal(&TidalInput {
            distance: 1.01 * roche,
            ..TidalInput::default()
        })
        .unwrap();
        assert_eq!(outside.r_max, None);
    }

    #[test]
    fn bad_input_names_the_field() {
        let field = |inp: TidalInput| match tidal(&inp) {
            Err(Error::OutOfRange { field, .. }) => field,
            other => panic!("unexpected {other:?}"),
        };
        let base = TidalInput::default();
        let cases = [
            (
                TidalInput {
                    planet_mass: 0.0,
                    ..base
                },
                "planet_mass",
            ),
            (
                TidalInput {
                    distance: f64::NAN,
                    ..base
                },
                "distance",
            ),
            (
                TidalInput {
                    radius: -1.0,
                    ..base
                },
                "radius",
            ),
            (
                TidalInput {
                    radius: 2e8,
                    ..base
                },
                "radius",
            ),
            (
                TidalInput {
                    density: f64::INFINITY,
                    ..base
                },
                "density",
            ),
            (
                TidalInput {
                    surface_energy: -0.1,
                    ..base
                },
                "surface_energy",
            ),
        ];
        for (inp, name) in cases {
            assert_eq!(field(inp), name);
        }
    }
}
