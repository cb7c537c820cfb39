//! Agreement with the independent high-precision reference (`tests/reference/generate.py`, mpmath):
//! the judged accuracy of issue 2 — ε_N to ≤ 1e-9 (Precise: our bound is 1e-10) wherever ε_N > 1e-6,
//! critical velocities to ≤ 1e-9.

use rime_core::master::{self, Resolution};
use rime_core::normal::viscoelastic::dimensionless;
use rime_core::{
    Accuracy, Adhesion, AdhesionModulus, Contact, ContactEnd, Damping, Layer, Preset, Scene,
};
use rime_tests::{read_csv, rel};

fn num(row: &std::collections::HashMap<String, String>, key: &str) -> f64 {
    row.get(key)
        .unwrap_or_else(|| panic!("column {key} missing"))
        .parse()
        .unwrap_or_else(|_| panic!("column {key} not a number: {:?}", row.get(key)))
}

fn rule(name: &str) -> ContactEnd {
    match name {
        "force_zero" => ContactEnd::ForceZero,
        "zero_overlap" => ContactEnd::ZeroOverlap,
        other => panic!("unknown rule {other}"),
    }
}

#[test]
fn master_curve_matches_the_mpmath_reference() {
    let rows = read_csv("viscoelastic.csv");
    assert!(rows.len() > 100, "reference table too short");
    let mut worst = [0.0f64; 4]; // precise table, live 1e-13, fast table, balanced
    let mut checked = 0;
    for row in &rows {
        let end = rule(&row["rule"]);
        let delta = num(row, "delta");
        let reference = num(row, "eps");
        let fine = master::lookup(delta, end, Resolution::Fine);
        let coarse = master::lookup(delta, end, Resolution::Coarse);
        let live = dimensionless(delta, end, 1e-13).unwrap();
        let balanced = dimensionless(delta, end, Accuracy::Balanced.integrator_rtol()).unwrap();
        if reference > 1e-6 {
            checked += 1;
            let errs = [
                rel(fine.eps, reference),
                rel(live.eps, reference),
                rel(coarse.eps, reference),
                rel(balanced.eps, reference),
            ];
            for (w, e) in worst.iter_mut().zip(errs) {
                *w = w.max(e);
            }
            assert!(errs[0] <= 1e-10, "{row:?}: precise table {}", fine.eps);
            assert!(errs[1] <= 1e-10, "{row:?}: live DP5 {}", live.eps);
            assert!(errs[2] <= 1e-6, "{row:?}: fast {}", coarse.eps);
            assert!(errs[3] <= 1e-6, "{row:?}: balanced {}", balanced.eps);
            assert!(
                rel(fine.s_c, num(row, "s_c")) <= 1e-8,
                "{row:?}: s_c {}",
                fine.s_c
            );
            assert!(
                rel(fine.x_max, num(row, "x_max")) <= 1e-8,
                "{row:?}: x_max {}",
                fine.x_max
            );
        } else {
            // Below 1e-6 only the magnitude is promised: the result must be tiny too.
            assert!(
                fine.eps <= 2e-6 && live.eps <= 2e-6,
                "{row:?}: {} {}",
                fine.eps,
                live.eps
            );
        }
    }
    assert!(checked > 80, "only {checked} rows with ε > 1e-6");
    eprintln!(
        "reference: {checked} rows; worst relative errors precise {:.1e}, live {:.1e}, fast {:.1e}, balanced {:.1e}",
        worst[0], worst[1], worst[2], worst[3]
    );
}

#[test]
fn critical_velocities_match_the_mpmath_reference() {
    for row in read_csv("critical_velocities.csv") {
        let mut scene = Scene::default();
        match row["kind"].as_str() {
            "layer" => {
                scene.layer = Some(Layer {
                    thickness: num(&row, "D"),
                    viscosity: num(&row, "eta"),
                    ..Layer::default()
                })
            }
            "adhesion" => {
                scene.adhesion = Some(Adhesion {
                    surface_energy: num(&row, "gamma"),
                    modulus: match row["option"].as_str() {
                        "consistent" => AdhesionModulus::Consistent,
                        _ => AdhesionModulus::AsPrinted,
                    },
                    jkr_end: Default::default(),
                })
            }
            other => panic!("unknown kind {other}"),
        }
        let c = Contact::new(&scene).unwrap();
        let ours = c
            .layer
            .map(|l| l.critical_velocity)
            .or(c.adhesion.map(|a| a.critical_velocity))
            .unwrap();
        assert!(rel(ours, num(&row, "g_s")) <= 1e-12, "{row:?}: {ours}");
    }
}

#[test]
fn scenes_match_the_mpmath_reference_at_precise() {
    let path = rime_tests::data("scenes.csv");
    if !path.exists() {
        // The physical-scene table is generated together with the others; its absence is a
        // failure, not a skip.
        panic!(
            "{} is missing: run tests/reference/generate.py",
            path.display()
        );
    }
    let mut checked = 0;
    for row in read_csv("scenes.csv") {
        let mut scene = Scene {
            contact_end: rule(&row["rule"]),
            ..Scene::default()
        };
        scene.bulk.damping = Damping::Time(num(&row, "A"));
        scene.grains.radius_1 = num(&row, "R");
        scene.grains.radius_2 = num(&row, "R");
        let option = row["option"].as_str();
        let model = row["model"].as_str();
        if model.contains("layer") {
            scene.layer = Some(Layer {
                thickness: num(&row, "D"),
                viscosity: num(&row, "eta"),
                reading: if option.contains("literal") {
                    rime_core::LayerReading::Literal
                } else {
                    rime_core::LayerReading::Offset
                },
            });
        }
        if model.contains("adhesion") {
            scene.adhesion = Some(Adhesion {
                surface_energy: num(&row, "gamma"),
                modulus: if option.contains("consistent") {
                    AdhesionModulus::Consistent
                } else {
                    AdhesionModulus::AsPrinted
                },
                jkr_end: Default::default(),
            });
        }
        let g = num(&row, "g");
        let reference = num(&row, "eps");
        let c = Contact::new(&scene).unwrap();
        if g > 1e6 {
            // Outside rime's domain (speeds up to 1e6 m/s): a clear error, not a number.
            let e = c.normal(g, Accuracy::Precise).unwrap_err();
            assert!(e.to_string().contains("g_n"), "{e}");
            continue;
        }
        for acc in [Accuracy::Precise, Accuracy::Fast, Accuracy::Balanced] {
            let n = c.normal(g, acc).unwrap();
            let ours = n.eps;
            let fast_path = c.eps_n(g, acc).unwrap();
            if reference > 1e-6 {
                // The level's bound, widened by the reported conditioning near the adhesion
                // threshold (never below the level's own bound).
                let bound = n.error_estimate;
                assert!(bound >= acc.error_bound());
                assert!(
                    rel(ours, reference) <= bound,
                    "{row:?} {acc:?}: {ours} vs {reference}"
                );
                assert!(
                    rel(fast_path, reference) <= bound,
                    "{row:?} {acc:?}: eps_n {fast_path}"
                );
            } else {
                assert!(ours <= 2e-6, "{row:?} {acc:?}: {ours}");
            }
        }
        checked += 1;
    }
    assert!(checked > 100, "only {checked} scene rows");
}

/// The force-zero contact duration of strong damping grows with ln δ (issue 22): checked against the
/// independent integration in scaled variables (`tests/reference/strong_damping.py`, RK4 with
/// Richardson extrapolation in mpmath, ≤ 6e-12) from δ = 1e3 to 1e12, at every level, and through a
/// scene at δ = 1e8 (the issue's `--set bulk.damping.time=13348 --g 0.01`: t_c ≈ 2.63e-8 s, not
/// the 2.300e-8 s of the pure δ^(−2/3) law).
#[test]
fn force_zero_duration_grows_with_ln_delta_up_to_1e12_issue_22() {
    let rows = read_csv("strong_damping.csv");
    assert!(rows.len() >= 10, "reference table too short");
    let mut beyond_table = 0;
    for row in &rows {
        let delta = num(row, "delta");
        let s_c = num(row, "s_c");
        let fine = master::lookup(delta, ContactEnd::ForceZero, Resolution::Fine);
        let coarse = master::lookup(delta, ContactEnd::ForceZero, Resolution::Coarse);
        // Inside the table an overdamped force-zero end is ill-conditioned (docs/physics.md#decision-2:
        // 1e-5); beyond it the closed form is exact to O(δ^(−5/3) ln² δ).
        let bound = if delta > 1e7 { 1e-9 } else { 1e-5 };
        assert!(
            rel(fine.s_c, s_c) <= bound,
            "δ = {delta}: fine s_c {} vs {s_c}",
            fine.s_c
        );
        assert!(
            rel(coarse.s_c, s_c) <= bound.max(1e-6),
            "δ = {delta}: coarse s_c {}",
            coarse.s_c
        );
        assert!(
            rel(fine.eps, num(row, "eps")) <= 1e-6,
            "δ = {delta}: ε {}",
            fine.eps
        );
        assert!(
            rel(fine.x_max, num(row, "x_max")) <= 1e-6,
            "δ = {delta}: x_max {}",
            fine.x_max
        );
        if delta <= 1e7 {
            let live = dimensionless(delta, ContactEnd::ForceZero, 1e-12).unwrap();
            assert!(
                rel(live.s_c, s_c) <= 1e-5,
                "δ = {delta}: live s_c {}",
                live.s_c
            );
        } else {
            beyond_table += 1;
        }
    }
    assert!(beyond_table >= 5, "only {beyond_table} rows past the table");

    // Through a scene, at every level: δ = 1e8 at 1 cm/s for A = 13348 s (default ice).
    let mut scene = Scene::default();
    scene.bulk.damping = Damping::Time(13348.0);
    let c = Contact::new(&scene).unwrap();
    let g = 0.01;
    let delta = c.delta(g);
    assert!(rel(delta, 1e8) < 1e-3, "δ = {delta}");
    // (20/9) ln δ + (2/3) ln(27/8) + ln 3 − π/(3√3): the asymptote of docs/physics.md#decision-2.
    let scaled = 20.0 / 9.0 * delta.ln() + 2.0 / 3.0 * (27.0f64 / 8.0).ln() + 3.0f64.ln()
        - std::f64::consts::PI / (3.0 * 3.0f64.sqrt());
    let expected = c.time_scale(g) * delta.powf(-2.0 / 3.0) * scaled;
    assert!(rel(expected, 2.63e-8) < 0.01, "t_c {expected}");
    for acc in [
        Accuracy::Fast,
        Accuracy::Precise,
        Accuracy::Balanced,
        Accuracy::Tolerance(1e-8),
    ] {
        let n = c.normal(g, acc).unwrap();
        assert!(
            rel(n.t_c, expected) < 1e-9,
            "{acc:?}: t_c {} vs {expected}",
            n.t_c
        );
    }
}

/// The integrated level where the paper's viscosities put every contact (issue 26): the force-zero
/// contact of strong damping, 1 < δ ≤ 1e12, integrated live at the level's rtol against the mpmath
/// reference (`viscoelastic.csv`, δ ≤ 1e4) and the independent scaled integration
/// (`strong_damping.csv`, 1e3 … 1e12, with quarter decades over the preset's 1e5 … 1e7). ε_N, s_c
/// and x_max meet the level's bound, 1e-6, even where ε_N < 1e-6 (where only the magnitude is
/// promised); so does the preset `ice-paper-viscosities` itself at speeds where its δ is a
/// reference row. Until issue 26 this regime cost 9 000 evaluations per contact at δ = 1e6 (rtol
/// 1e-11), s_c was off by 3.9e-6 at δ = 1e7, and from δ ≈ 1e9 on the integration ran out of steps.
#[test]
fn integrated_level_resolves_strong_damping_issue_26() {
    let rtol = Accuracy::Balanced.integrator_rtol();
    let bound = Accuracy::Balanced.error_bound();
    // (δ, ε_N, s_c, x_max where certified)
    let mut rows: Vec<(f64, f64, f64, Option<f64>)> = Vec::new();
    for row in read_csv("viscoelastic.csv") {
        let delta = num(&row, "delta");
        if row["rule"] == "force_zero" && delta > 1.0 {
            let x_max = num(&row, "x_max");
            rows.push((delta, num(&row, "eps"), num(&row, "s_c"), Some(x_max)));
        }
    }
    let strong = read_csv("strong_damping.csv");
    for row in &strong {
        rows.push((num(row, "delta"), num(row, "eps"), num(row, "s_c"), None));
    }
    assert!(rows.len() >= 35, "only {} rows", rows.len());
    let mut worst = [0.0f64; 3];
    for &(delta, eps, s_c, x_max) in &rows {
        let live = dimensionless(delta, ContactEnd::ForceZero, rtol).unwrap();
        let errs = [
            rel(live.eps, eps),
            rel(live.s_c, s_c),
            x_max.map_or(0.0, |x| rel(live.x_max, x)),
        ];
        assert!(
            errs.iter().all(|&e| e <= bound),
            "δ = {delta}: ε {} s_c {} x_max {} (relative errors {errs:?})",
            live.eps,
            live.s_c,
            live.x_max
        );
        for (w, e) in worst.iter_mut().zip(errs) {
            *w = w.max(e);
        }
    }
    eprintln!(
        "strong damping at integrated, {} rows: worst relative errors ε {:.1e}, s_c {:.1e}, x_max {:.1e}",
        rows.len(),
        worst[0],
        worst[1],
        worst[2]
    );

    // Through the preset, at speeds where its δ is a reference row inside the live domain (beyond
    // δ = 1e7 every level takes the asymptotes).
    let c = Contact::new(&Preset::IcePaperViscosities.scene()).unwrap();
    let mut through = 0;
    for row in &strong {
        let delta = num(row, "delta");
        // δ = A α^(2/5) g^(1/5).
        let g = (delta / c.delta(1.0)).powi(5);
        if delta > 1e7 || !(1e-12..=1e2).contains(&g) || rel(c.delta(g), delta) > 1e-14 {
            continue;
        }
        let n = c.normal(g, Accuracy::Balanced).unwrap();
        assert!(n.rhs_evaluations > 0, "δ = {delta}: not integrated");
        let t_c = num(row, "s_c") * c.time_scale(g);
        assert!(
            rel(n.eps, num(row, "eps")) <= bound && rel(n.t_c, t_c) <= bound,
            "δ = {delta} (g = {g:e} m/s): ε {} t_c {} vs {t_c}",
            n.eps,
            n.t_c
        );
        through += 1;
    }
    assert!(through >= 5, "only {through} preset speeds");
}
