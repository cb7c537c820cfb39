use super::*;
use crate::scene::Layer;

fn rel(a: f64, b: f64) -> f64 {
    (a / b - 1.0).abs()
}

const RADII: [f64; 6] = [1e-6, 1e-5, 1e-4, 3e-4, 1e-3, 1e-2];
const TEMPERATURES: [f64; 4] = [150.0, 180.0, 187.5, 200.0];

/// Both `None`, or both finite and within `tol` relative.
fn agree(fast: Option<f64>, direct: Option<f64>, tol: f64, what: &str) {
    match (fast, direct) {
        (None, None) => {}
        (Some(a), Some(b)) => assert!(rel(a, b) < tol, "{what}: {a} vs {b}"),
        _ => panic!("{what}: {fast:?} vs {direct:?}"),
    }
}

#[test]
fn issue_39_equal_radii_equal_the_stick_threshold() {
    for accuracy in [Accuracy::Fast, Accuracy::Precise] {
        let options = KernelOptions {
            accuracy,
            ..Default::default()
        };
        let scene = Scene::default();
        let k = table(&scene, &RADII, &TEMPERATURES, &options).unwrap();
        assert_eq!(k.method, Method::ScalingLaw);
        let mut both = [0, 0];
        for (t, &temp) in TEMPERATURES.iter().enumerate() {
            for (i, &r) in RADII.iter().enumerate() {
                let s =
                    stick::threshold(&scene, r, temp, Convention::SurfaceEnergy, accuracy).unwrap();
                // The bisection stops within 1e-10 in ln g, on the rebounding side.
                agree(k.get(t, i, i), s.v_stick, 2e-10, "diagonal");
                both[usize::from(s.v_stick.is_some())] += 1;
            }
        }
        // Both outcomes occur (µm grains stick at every speed, mm grains have a threshold).
        assert!(both[0] > 0 && both[1] > 0, "{both:?}");
    }
}

#[test]
fn issue_39_unequal_pairs_match_bisection_and_are_symmetric() {
    let layered = Scene {
        layer: Some(Layer {
            thickness: 1e-7,
            viscosity: 1e4,
            reading: LayerReading::Offset,
        }),
        ..Scene::default()
    };
    for (scene, rule) in [
        (Scene::default(), ARule::Given),
        (Scene::default(), ARule::KeepEpsilon),
        (layered, ARule::Given),
        (
            Scene {
                contact_end: ContactEnd::ZeroOverlap,
                ..Scene::default()
            },
            ARule::Given,
        ),
    ] {
        let options = KernelOptions {
            a_rule: rule,
            ..Default::default()
        };
        let k = table(&scene, &RADII, &TEMPERATURES, &options).unwrap();
        assert_eq!(k.method, Method::ScalingLaw);
        for t in 0..TEMPERATURES.len() {
            for i in 0..RADII.len() {
                for j in 0..RADII.len() {
                    assert_eq!(
                        k.v_stick[k.index(t, i, j)].to_bits(),
                        k.v_stick[k.index(t, j, i)].to_bits()
                    );
                    assert_eq!(k.status[k.index(t, i, j)], k.status[k.index(t, j, i)]);
                    if j < i {
                        continue;
                    }
                    let d = pair(&scene, RADII[i], RADII[j], TEMPERATURES[t], &options).unwrap();
                    agree(k.get(t, i, j), d.v_stick, 2e-10, "pair");
                    assert_eq!(
                        k.status[k.index(t, i, j)] == StickStatus::AlwaysSticks,
                        d.v_stick.is_none()
                    );
                }
            }
        }
    }
}

#[test]
fn issue_39_literal_layer_falls_back_to_bisection() {
    let scene = Scene {
        layer: Some(Layer {
            thickness: 1e-7,
            viscosity: 1e4,
            reading: LayerReading::Literal,
        }),
        ..Scene::default()
    };
    let radii = [1e-4, 1e-3];
    let k = table(&scene, &radii, &[200.0], &KernelOptions::default()).unwrap();
    assert_eq!(k.method, Method::Bisection);
    let d = pair(&scene, 1e-4, 1e-3, 200.0, &KernelOptions::default()).unwrap();
    assert_eq!(k.get(0, 0, 1), d.v_stick);
}

/// Eq. (15) evaluated from its ingredients, independently of `Contact`.
fn eq15(r1: f64, r2: f64, gamma_w: f64) -> f64 {
    let (rho, y, nu) = (900.0, 1e10, 0.3);
    let mass = |r: f64| rho * 4.0 / 3.0 * core::f64::consts::PI * r * r * r;
    let r_eff = r1 * r2 / (r1 + r2);
    let m_eff = mass(r1) * mass(r2) / (mass(r1) + mass(r2));
    let e = y / (1.0 - nu * nu);
    libm::sqrt(14.18 / m_eff)
        * libm::pow(
            libm::pow(gamma_w, 5.0) * libm::pow(r_eff, 4.0) / (e * e),
            1.0 / 6.0,
        )
}

#[test]
fn issue_39_without_dissipation_the_threshold_is_eq15_of_the_pair() {
    // python3: r = 1 µm and 3 µm, ρ = 900, Y = 10 GPa, ν = 0.3, w = 2 × 0.19 J/m²:
    // g_s = 1.0354059583845912 m/s.
    assert!(rel(eq15(1e-6, 3e-6, 0.38), 1.035_405_958_384_591_2) < 1e-13);
    let radii = [1e-6, 3e-6, 1e-4, 2e-2];
    for a in [0.0, 1e-16] {
        let mut scene = Scene::default();
        scene.bulk.damping = Damping::Time(a);
        let k = table(&scene, &radii, &[200.0, 150.0], &KernelOptions::default()).unwrap();
        for i in 0..radii.len() {
            for j in 0..radii.len() {
                for (t, w) in [(0, 0.38), (1, 2.0 * 0.0029)] {
                    let gs = eq15(radii[i], radii[j], w);
                    // A = 1e-16 s: ε = 1 − 1.73 δ with δ ≤ 1e-16 α^(2/5) g^(1/5) < 1e-7 here.
                    let tol = if a == 0.0 { 1e-13 } else { 1e-6 };
                    let v = k.get(t, i, j).unwrap();
                    assert!(rel(v, gs) < tol, "{i} {j} {t}: {v} vs {gs}");
                    assert!(v >= gs * (1.0 - 1e-13));
                }
            }
        }
    }
}

#[test]
fn issue_39_the_full_model_depends_on_damping_at_g_s_alone() {
    // Claim of the scaling law: v_stick/g_s is a function of β g_s^(1/5), β = A α^(2/5). Two
    // different pairs with β₂ = 2β₁ and g_s,₂ = g_s,₁/2⁵ (γ chosen for it) have the same
    // β g_s^(1/5), so v₂ = v₁ g_s,₂/g_s,₁ = v₁/32 — checked by bisection on the full model.
    let with = |r1: f64, r2: f64, a: f64, gamma: f64| {
        Contact::new(&pair_scene(&Scene::default(), r1, r2, gamma, Some(a)).unwrap()).unwrap()
    };
    let c1 = with(1e-4, 3e-4, 1e-4, 0.38);
    let probe = with(2e-3, 5e-4, 1e-4, 0.38);
    let beta1 = c1.damping_time * libm::pow(c1.alpha, 0.4);
    let a2 = 2.0 * beta1 / libm::pow(probe.alpha, 0.4);
    let gs1 = c1.adhesion.unwrap().critical_velocity;
    let gs_probe = probe.adhesion.unwrap().critical_velocity;
    let gamma2 = 0.38 * libm::pow(gs1 / 32.0 / gs_probe, 1.2);
    let c2 = with(2e-3, 5e-4, a2, gamma2);
    assert!(rel(c2.adhesion.unwrap().critical_velocity, gs1 / 32.0) < 1e-12);
    let v1 = stick::first_rebound_speed(&c1, Accuracy::Precise)
        .unwrap()
        .unwrap();
    let v2 = stick::first_rebound_speed(&c2, Accuracy::Precise)
        .unwrap()
        .unwrap();
    assert!(v1 > 2.0 * gs1, "damping must matter here: {v1} vs {gs1}");
    assert!(rel(v2, v1 / 32.0) < 3e-10, "{v2} vs {}", v1 / 32.0);
}

#[test]
fn issue_39_keep_epsilon_scales_a_as_the_formula() {
    let scene = Scene::default(); // reference pair: 2 cm + 2 cm, A = 1e-4 s
    let options = KernelOptions {
        a_rule: ARule::KeepEpsilon,
        ..Default::default()
    };
    let r_ref = 0.02;
    for (r1, r2) in [(1e-6, 1e-6), (1e-5, 3e-3), (0.02, 0.02), (0.5, 0.1)] {
        let p = pair(&scene, r1, r2, 190.0, &options).unwrap();
        // R_eff = r1 r2/(r1 + r2); m_eff ∝ r1³ r2³/(r1³ + r2³) (one density).
        let r_ratio = (r1 * r2 / (r1 + r2)) / (r_ref / 2.0);
        let (c1, c2) = (r1 * r1 * r1, r2 * r2 * r2);
        let m_ratio = (c1 * c2 / (c1 + c2)) / (r_ref * r_ref * r_ref / 2.0);
        let expected = 1e-4 * libm::pow(r_ratio, -0.2) * libm::pow(m_ratio, 0.4);
        assert!(rel(p.damping_time, expected) < 1e-13, "{r1} {r2}");
        // Hence every pair's ε_N(g) without adhesion is the reference pair's.
        let mut bare = pair_scene(&scene, r1, r2, 0.1, Some(p.damping_time)).unwrap();
        bare.adhesion = None;
        let e = Contact::new(&bare)
            .unwrap()
            .eps_n(0.01, Accuracy::Fast)
            .unwrap();
        let e_ref = Contact::new(&Scene::default())
            .unwrap()
            .eps_n(0.01, Accuracy::Fast)
            .unwrap();
        assert!(rel(e, e_ref) < 1e-12);
    }
    // Given keeps the scene's A.
    let given = pair(&scene, 1e-5, 3e-3, 190.0, &KernelOptions::default()).unwrap();
    assert_eq!(given.damping_time, 1e-4);
}

#[test]
fn issue_39_fit_measured_reproduces_the_measured_speed() {
    let m = MeasuredSpeed::GUNDLACH_2015;
    let options = KernelOptions {
        a_rule: ARule::FitMeasured(m),
        ..Default::default()
    };
    let scene = Scene::default();
    let fit = fit_measured(&scene, &m, &options).unwrap();
    // The bisection on the full model with the fitted A sticks up to 9.6 m/s.
    assert!(rel(fit.achieved, 9.6) < 1e-6, "{fit:?}");
    // Eq. (15) of two 1.5 µm grains at w = 0.38 J/m² lies below: damping closes the gap.
    assert!(rel(fit.v_elastic, eq15(1.5e-6, 1.5e-6, 0.38)) < 1e-12);
    assert!(fit.v_elastic < 1.0);
    let k = table(&scene, &[1e-6, 1.5e-6, 1e-3], &[200.0, 150.0], &options).unwrap();
    assert!(rel(k.get(0, 1, 1).unwrap(), 9.6) < 1e-6);
    assert_eq!(k.damping_time, fit.damping_time);
    let d = pair(&scene, 1e-6, 1e-3, 150.0, &options).unwrap();
    assert_eq!(d.damping_time, fit.damping_time);
    agree(k.get(1, 0, 2), d.v_stick, 2e-10, "fitted pair");
    // Below g_s no A can reach the speed.
    let slow = MeasuredSpeed { speed: 0.1, ..m };
    assert!(matches!(
        fit_measured(&scene, &slow, &options),
        Err(Error::OutOfRange { field: "fit", .. })
    ));
}

#[test]
fn issue_39_temperatures_outside_the_measured_range_are_held_or_refused() {
    let hold = KernelOptions::default();
    let cold = gamma(150.0, &hold).unwrap();
    assert_eq!(
        (cold.range, cold.gamma_source, cold.gamma),
        (GammaRange::HeldCold, 0.0029, 0.0058)
    );
    let warm = gamma(250.0, &hold).unwrap();
    assert_eq!(
        (warm.range, warm.gamma_source),
        (GammaRange::HeldWarm, 0.19)
    );
    for t in [175.0, 187.5, 200.0] {
        assert_eq!(gamma(t, &hold).unwrap().range, GammaRange::Measured);
    }
    let refuse = KernelOptions {
        temperature_rule: TemperatureRule::Refuse,
        ..Default::default()
    };
    assert!(gamma(187.5, &refuse).is_ok());
    for t in [150.0, 250.0] {
        assert!(matches!(
            table(&Scene::default(), &[1e-3], &[180.0, t], &refuse),
            Err(Error::OutOfRange {
                field: "temperatures",
                ..
            })
        ));
    }
    let k = table(&Scene::default(), &[1e-3], &[150.0, 180.0, 250.0], &hold).unwrap();
    let ranges: Vec<GammaRange> = k.gammas.iter().map(|g| g.range).collect();
    assert_eq!(
        ranges,
        [
            GammaRange::HeldCold,
            GammaRange::Measured,
            GammaRange::HeldWarm
        ]
    );
}

#[test]
fn issue_39_bad_grids_are_refused_naming_the_field() {
    let s = Scene::default();
    let o = KernelOptions::default();
    let field = |r: Result<Kernel>| match r {
        Err(Error::OutOfRange { field, .. }) | Err(Error::InvalidValue { field, .. }) => field,
        other => panic!("{other:?}"),
    };
    assert_eq!(field(table(&s, &[], &[150.0], &o)), "radii");
    assert_eq!(field(table(&s, &[1e-3, -1.0], &[150.0], &o)), "radii");
    assert_eq!(field(table(&s, &[f64::NAN], &[150.0], &o)), "radii");
    assert_eq!(field(table(&s, &[1e-3], &[], &o)), "temperatures");
    assert_eq!(field(table(&s, &[1e-3], &[f64::NAN], &o)), "temperatures");
    assert_eq!(field(table(&s, &[1e-3], &[0.0], &o)), "temperatures");
}

#[test]
fn issue_39_the_rebound_speed_grows_with_the_impact_speed_under_force_zero() {
    // g ε(δ(g)) increasing in g is what makes "sticks below v_stick" one threshold; Ψ's grid is
    // kept only where it holds. Force zero: ε ~ (2/3) δ^(−5/3) for strong damping, Ψ' → 10/3.
    for resolution in [Resolution::Coarse, Resolution::Fine] {
        let grid = PsiGrid::new(ContactEnd::ForceZero, resolution).unwrap();
        let n = grid.psi.len();
        let slope = (grid.psi[n - 1] - grid.psi[n - 2]) / grid.step / LN10;
        assert!((slope - 10.0 / 3.0).abs() < 1e-6, "{slope}");
        // Weak damping: ε → 1, Ψ' → 5.
        let slope0 = (grid.psi[1] - grid.psi[0]) / grid.step / LN10;
        assert!((slope0 - 5.0).abs() < 1e-6, "{slope0}");
    }
}

#[test]
fn issue_39_threads_give_the_same_table_bit_for_bit() {
    let temps = [140.0, 176.0, 181.0, 190.0, 199.0, 230.0, 187.5];
    let options = KernelOptions::default();
    let one = table(&Scene::default(), &RADII, &temps, &options).unwrap();
    for threads in [2, 3, 7, 16] {
        let many = table_parallel(&Scene::default(), &RADII, &temps, &options, threads).unwrap();
        assert_eq!(many.status, one.status);
        let bits = |k: &Kernel| k.v_stick.iter().map(|v| v.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&many), bits(&one), "{threads} threads");
    }
    // Each temperature's block is that temperature's own table.
    let single = table(&Scene::default(), &RADII, &[190.0], &options).unwrap();
    let nn = RADII.len() * RADII.len();
    assert_eq!(one.v_stick[3 * nn..4 * nn], single.v_stick[..]);
}

#[test]
fn issue_39_scaling_law_agrees_with_the_live_integrated_model() {
    // The integrated level bisects contacts integrated step by step (no table): an independent
    // numerical path. Its ε_N bound 1e-6 moves v_stick by about 1e-6/(d ln(g ε)/d ln g) ≲ 2e-6.
    let radii = [1e-4, 3e-4, 1e-3, 1e-2];
    let temps = [180.0, 200.0];
    let live = KernelOptions {
        accuracy: Accuracy::Balanced,
        ..Default::default()
    };
    let precise = KernelOptions {
        accuracy: Accuracy::Precise,
        ..Default::default()
    };
    let a = table(&Scene::default(), &radii, &temps, &live).unwrap();
    let b = table(&Scene::default(), &radii, &temps, &precise).unwrap();
    assert_eq!(
        (a.method, b.method),
        (Method::Bisection, Method::ScalingLaw)
    );
    let mut compared = 0;
    for t in 0..temps.len() {
        for i in 0..radii.len() {
            for j in 0..radii.len() {
                agree(
                    a.get(t, i, j),
                    b.get(t, i, j),
                    1e-5,
                    "integrated vs scaling law",
                );
                compared += usize::from(a.get(t, i, j).is_some());
            }
        }
    }
    assert!(compared >= 20, "{compared}");
    assert_eq!(a.get(2, 0, 0), None, "out of range");
}
