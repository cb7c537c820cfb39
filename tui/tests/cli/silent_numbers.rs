//! Numbers that were silently wrong, through the command line (issue 22): each test runs the
//! `rime` binary and checks it against the core or an independent limit.

use crate::bin::{rime, rime_json};
use rime_core::{Accuracy, Contact, Preset, Scene};
use rime_tests::rel;

/// Issue 22: past δ = 1e7 `rime collision` answers where `rime eps` answers (it ran out of steps
/// at δ ≈ 1.9e10); its t_c is the strong-damping asymptote and its energy ledger closes.
#[test]
fn collision_answers_past_the_tables_end_like_eps_issue_22() {
    let args = ["--g", "1", "--set", "bulk.damping.time=1e6"];
    let eps = rime_json(&[&["eps", "--format", "json"][..], &args[..]].concat());
    let col = rime_json(
        &[
            &["collision", "--points", "20", "--format", "json"][..],
            &args[..],
        ]
        .concat(),
    );
    let c = rime_core::Contact::new(&{
        let mut s = rime_core::Scene::default();
        s.bulk.damping = rime_core::Damping::Time(1e6);
        s
    })
    .unwrap();
    let delta = c.delta(1.0);
    assert!(delta > 1e10, "δ = {delta}");
    // docs/physics.md#decision-2: t_c = τ δ^(−2/3) ((20/9) ln δ + (2/3) ln(27/8) + ln 3 − π/(3√3)).
    let scaled = 20.0 / 9.0 * delta.ln() + 2.0 / 3.0 * (27.0f64 / 8.0).ln() + 3.0f64.ln()
        - std::f64::consts::PI / (3.0 * 3.0f64.sqrt());
    let t_c = c.time_scale(1.0) * delta.powf(-2.0 / 3.0) * scaled;
    assert!(rel(eps[0]["t_c"].as_f64().unwrap(), t_c) < 1e-9, "{eps}");
    assert!(rel(col["t_c"].as_f64().unwrap(), t_c) < 1e-9, "{col}");
    assert_eq!(col["eps_n"], eps[0]["eps_n"]);
    // ε_N → (2/3) δ^(−5/3); the grains hold at ξ_max ≈ δ^(−2/3) ξ* until the force vanishes.
    let e = col["eps_n"].as_f64().unwrap();
    assert!(rel(e, 2.0 / 3.0 * delta.powf(-5.0 / 3.0)) < 1e-6, "ε {e}");
    let xi: Vec<f64> = col["xi"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect();
    let xi_max = c.length_scale(1.0) * delta.powf(-2.0 / 3.0);
    assert!(
        rel(*xi.last().unwrap(), xi_max) < 1e-6,
        "{xi:?} vs {xi_max}"
    );
    assert!(
        col["ledger"]["closure"].as_f64().unwrap().abs() < 1e-9,
        "{col}"
    );
}

/// Issue 22: at 1e-200 m/s the default scene is elastic (δ ∝ g^(1/5) → 0), so brilliantov2007
/// answers ε = 1 (it divided two underflowed numbers and blamed bulk.damping).
#[test]
fn brilliantov2007_at_1e_minus_200_m_per_s_is_elastic_issue_22() {
    let v = rime_json(&[
        "compare",
        "--g",
        "1e-200",
        "--models",
        "brilliantov2007",
        "--format",
        "json",
    ]);
    assert_eq!(v["records"][0]["eps_n"], 1.0, "{v}");
    assert_eq!(v["records"][0]["status"], "rebound", "{v}");
}

/// Issue 22: error messages print 1e300 as `1e300`, not 301 digits.
#[test]
fn error_messages_print_huge_numbers_compactly_issue_22() {
    for args in [
        &["eps", "--g", "1e300"][..],
        &["eps", "--set", "grains.radius_1=1e300"][..],
    ] {
        let (code, _, err) = rime(args);
        assert_eq!(code, 2, "{args:?}");
        assert!(err.contains("1e300"), "{args:?}: {err}");
        assert!(!err.contains("000000000"), "{args:?}: {err}");
    }
    let (code, _, err) = rime(&["curve", "--from", "1e-300", "--to", "1e-301"]);
    assert_eq!(code, 2);
    assert!(err.contains("--to: 1e-301 is below --from 1e-300"), "{err}");
    let file = std::env::temp_dir().join(format!("rime-huge-{}.csv", std::process::id()));
    std::fs::write(&file, "g,eps\n0.01,1e300\n0.02,0.3\n").unwrap();
    let (code, _, err) = rime(&["fit", "--data", file.to_str().unwrap()]);
    std::fs::remove_file(&file).unwrap();
    assert_eq!(code, 2);
    assert!(err.contains("eps = 1e300 must lie in [0, 1]"), "{err}");
}

/// Issue 22: where ε_N < 1e-6 `error_estimate` no longer claims the level's bound (outside its
/// domain): it is infinite in the core, `null` in JSON, empty in CSV, explained below a table; and
/// a tolerance outside the allowed range prints as 1e-12, not 0.000000000001.
#[test]
fn error_estimate_says_when_eps_is_outside_the_bounds_domain_issue_22() {
    let c = Contact::new(&Preset::IcePaperViscosities.scene()).unwrap();
    for acc in [Accuracy::Fast, Accuracy::Precise, Accuracy::Balanced] {
        let n = c.normal(0.01, acc).unwrap();
        assert!(n.eps < 1e-6, "{n:?}");
        assert_eq!(n.error_estimate, f64::INFINITY, "{acc:?}");
    }
    let n = Contact::new(&Scene::default())
        .unwrap()
        .normal(0.01, Accuracy::Fast)
        .unwrap();
    assert_eq!(n.error_estimate, 1e-6);
    let v = rime_json(&[
        "eps",
        "--preset",
        "ice-paper-viscosities",
        "--g",
        "0.01",
        "--format",
        "json",
    ]);
    assert!(v[0]["error_estimate"].is_null(), "{v}");
    let (code, out, _) = rime(&[
        "eps",
        "--preset",
        "ice-paper-viscosities",
        "--g",
        "0.01",
        "--format",
        "table",
    ]);
    assert_eq!(code, 0);
    assert!(out.contains("outside the error bound's domain"), "{out}");
    let (code, _, err) = rime(&["eps", "--g", "0.01", "--accuracy", "1e-12"]);
    assert_eq!(code, 2);
    assert!(err.contains("(got 1e-12)"), "{err}");
}
