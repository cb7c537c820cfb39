//! Inside one collision (`Contact::collision`, `rime collision`): checks from theory
//! (docs/physics.md#collision).

use rime_core::{Accuracy, Contact, Preset, Scene, Status};

fn scene(preset: Preset, sets: &[(&str, &str)]) -> Scene {
    let mut s = preset.scene();
    for (path, value) in sets {
        s.set(path, value).unwrap();
    }
    s
}

/// Every model the issue names, both end rules and both layer readings, at speeds where each
/// rebounds, with adhesion, and where each sticks.
fn models() -> Vec<(&'static str, Scene, f64)> {
    let mut v = Vec::new();
    for end in ["force_zero", "zero_overlap"] {
        let e = ("contact_end", end);
        v.push(("viscoelastic", scene(Preset::Ice, &[e]), 0.01));
        v.push(("viscoelastic slow", scene(Preset::Ice, &[e]), 1e-5));
        for reading in ["offset", "literal"] {
            let r = ("layer.reading", reading);
            v.push(("layer", scene(Preset::IceFrost, &[e, r]), 0.01));
            v.push(("layer near g_s", scene(Preset::IceFrost, &[e, r]), 2e-5));
            v.push(("layer stuck", scene(Preset::IceFrost, &[e, r]), 3e-6));
            v.push((
                "layer + adhesion",
                scene(Preset::IceFrost, &[e, r, ("adhesion", "on")]),
                0.01,
            ));
        }
        v.push(("adhesion", scene(Preset::IceSticky, &[e]), 0.01));
        v.push(("adhesion stuck", scene(Preset::IceSticky, &[e]), 1e-4));
    }
    v
}

#[test]
fn elastic_collision_has_hertz_duration_compression_and_a_loop_of_zero_area() {
    let s = scene(Preset::Ice, &[("bulk.damping.time", "0")]);
    let c = Contact::new(&s).unwrap();
    let g = 0.01;
    let tr = c.collision(g, 20_001, Accuracy::Precise).unwrap();
    let (xi_star, tau) = (c.length_scale(g), c.time_scale(g));
    // Hertz: t_c = 3.21806545971904 τ, ξ_max = (5/4)^(2/5) ξ*.
    assert!(
        (tr.t_c / (3.21806545971904 * tau) - 1.0).abs() < 1e-10,
        "{}",
        tr.t_c / tau
    );
    let hertz_xi_max = 1.25f64.powf(0.4) * xi_star;
    assert!((tr.xi_max / hertz_xi_max - 1.0).abs() < 1e-10);
    // The sampled maximum (the phase instant is a sample) agrees too.
    let sampled = tr.xi.iter().cloned().fold(0.0, f64::max);
    assert!((sampled / hertz_xi_max - 1.0).abs() < 1e-9, "{sampled}");
    // ∮ F dξ by the trapezoid rule over the samples, against the peak work ∫₀^ξmax F dξ =
    // (2/5) ρ_H ξ_max^(5/2).
    let area: f64 = (1..tr.t.len())
        .map(|i| 0.5 * (tr.force[i] + tr.force[i - 1]) * (tr.xi[i] - tr.xi[i - 1]))
        .sum();
    let peak = 0.4 * c.rho_h * hertz_xi_max.powf(2.5);
    assert!(
        area.abs() < 1e-6 * peak,
        "loop area {area:e} vs peak work {peak:e}"
    );
    assert!((tr.eps_n - 1.0).abs() < 1e-12);
    assert!(tr.ledger.closure.abs() < 1e-12 && tr.ledger.dissipated_bulk.abs() < 1e-20);
}

#[test]
fn ledger_closes_at_precise_for_every_model() {
    let mut worst: f64 = 0.0;
    for (name, s, g) in models() {
        let c = Contact::new(&s).unwrap();
        for accuracy in [Accuracy::Precise, Accuracy::Fast] {
            let tr = c.collision(g, 200, accuracy).unwrap();
            let n = c.normal(g, accuracy).unwrap();
            // Same t_c, ε_N, status as Contact::normal.
            assert_eq!(tr.eps_n, n.eps, "{name}");
            assert_eq!(tr.status, n.status, "{name}");
            assert!(tr.t_c == n.t_c, "{name}");
            let l = tr.ledger;
            eprintln!(
                "{name:20} {:22} g = {g:e} {:?}: closure {:+.2e} ({:?}) bulk {:.3e} layer {:.3e} retained {:.3e} adhesion {:.3e}",
                format!("{:?}", c.contact_end),
                accuracy,
                l.closure,
                tr.status,
                l.dissipated_bulk / l.kinetic_in,
                l.dissipated_layer / l.kinetic_in,
                l.elastic_retained / l.kinetic_in,
                l.adhesion / l.kinetic_in
            );
            let bound = if accuracy == Accuracy::Precise {
                1e-9
            } else {
                1e-5
            };
            if tr.resolved {
                assert!(
                    l.closure.abs() <= bound,
                    "{name} {accuracy:?}: {}",
                    l.closure
                );
                if accuracy == Accuracy::Precise {
                    worst = worst.max(l.closure.abs());
                }
            }
        }
    }
    eprintln!("worst closure at precise: {worst:e}");
}

#[test]
fn offset_layer_dissipates_what_eq_9_takes_off_the_impact_speed() {
    // Eq. (9): the layer slows the grains from g to g − g_s, so in the offset reading it
    // dissipates ½ m_eff (g² − (g − g_s)²); below g_s, all of ½ m_eff g².
    let c = Contact::new(&Preset::IceFrost.scene()).unwrap();
    let g_s = c.layer.unwrap().critical_velocity;
    for g in [1e-2, 1e-4, 2.0 * g_s, 1.001 * g_s, 0.5 * g_s] {
        let tr = c.collision(g, 50, Accuracy::Precise).unwrap();
        let expected = if g > g_s {
            0.5 * c.m_eff * (g * g - (g - g_s) * (g - g_s))
        } else {
            0.5 * c.m_eff * g * g
        };
        let got = tr.ledger.dissipated_layer;
        assert!(
            (got / expected - 1.0).abs() < 1e-12,
            "g = {g}: {got:e} vs {expected:e}"
        );
    }
}

#[test]
fn adhesion_takes_w_s_off_the_rebound_energy_of_the_model_without_it() {
    for preset in [Preset::IceSticky, Preset::IceFrost] {
        let with = scene(preset, &[("adhesion", "on")]);
        let mut without = with;
        without.set("adhesion", "off").unwrap();
        let (cw, co) = (
            Contact::new(&with).unwrap(),
            Contact::new(&without).unwrap(),
        );
        let w_s = cw.adhesion.unwrap().separation_energy;
        for g in [0.003, 0.01, 0.05] {
            let a = cw.collision(g, 50, Accuracy::Precise).unwrap();
            let b = co.collision(g, 50, Accuracy::Precise).unwrap();
            assert_eq!(a.status, Status::Rebound);
            // The rebound energy without adhesion, from that trajectory's own last sample.
            let v_end = *b.xi_dot.last().unwrap();
            let e_without = 0.5 * co.m_eff * v_end * v_end;
            let rel = (a.ledger.kinetic_out - (e_without - w_s)) / e_without;
            assert!(rel.abs() < 1e-9, "{preset:?} g = {g}: {rel:e}");
            assert_eq!(a.ledger.adhesion, w_s);
            // The trajectory is the non-adhesive one.
            assert_eq!(a.xi, b.xi);
        }
    }
}

#[test]
fn trajectory_ends_where_the_table_says_and_samples_scale_with_points() {
    let c = Contact::new(&Preset::Ice.scene()).unwrap();
    let g = 0.01;
    let few = c.collision(g, 10, Accuracy::Precise).unwrap();
    let many = c.collision(g, 1000, Accuracy::Precise).unwrap();
    assert!(few.t.len() >= 10 && few.t.len() <= 10 + few.phases.len());
    assert!(many.t.len() >= 1000 && many.t.len() <= 1000 + many.phases.len());
    assert_eq!(few.rhs_evaluations, many.rhs_evaluations);
    // The force-zero rule: the force at the end vanishes; the live integration meets the table.
    let f_peak = many.force.iter().cloned().fold(0.0, f64::max);
    assert!(many.force.last().unwrap().abs() < 1e-8 * f_peak);
    let rebound = -many.xi_dot.last().unwrap() / g;
    assert!(
        (rebound / many.eps_n - 1.0).abs() < 1e-9,
        "{rebound} vs {}",
        many.eps_n
    );
    let names: Vec<&str> = many.phases.iter().map(|p| p.name).collect();
    assert_eq!(
        names,
        [
            "bulk_loading",
            "maximum_compression",
            "unloading",
            "end_of_contact"
        ]
    );
}

#[test]
fn oblique_impact_conserves_momentum_and_the_energy_identity_with_kappa_holds() {
    // Eq. (22): the tangential mass is κ m_eff, κ = 2/7 for two solid spheres, so the kinetic
    // energy falls by ½ m_eff (1 − ε_N²) g_N² + ½ κ m_eff (1 − ε_T²) g_T².
    let s = Preset::Ice.scene();
    let c = Contact::new(&s).unwrap();
    let (r1, r2) = (s.grains.radius_1, s.grains.radius_2);
    for (g_n, g_t) in [(0.01, 0.001), (0.01, 0.005), (0.01, 0.05), (0.001, 0.0)] {
        let o = c.oblique(r1, r2, g_n, g_t, Accuracy::Precise).unwrap();
        let eps_n = c.normal(g_n, Accuracy::Precise).unwrap().eps;
        let kappa = 2.0 / 7.0;
        let expected_loss = 0.5 * c.m_eff * (1.0 - eps_n * eps_n) * g_n * g_n
            + 0.5 * kappa * c.m_eff * (1.0 - o.eps_t * o.eps_t) * g_t * g_t;
        let loss = o.kinetic_before - o.kinetic_after;
        assert!(
            (loss - expected_loss).abs() < 1e-12 * o.kinetic_before,
            "{g_n} {g_t}"
        );
        let p_scale = c.mass_1 * (g_n + g_t);
        assert!(o.momentum_change < 1e-14 * p_scale);
        assert!(
            (o.energy_before - 0.5 * kappa * c.m_eff * g_t * g_t).abs() < 1e-14 * o.kinetic_before
        );
        // The friction impulse's work is the change of the tangential energy.
        assert!(
            (o.friction_work - (o.energy_after - o.energy_before)).abs() < 1e-12 * o.kinetic_before
        );
        // The spin change follows from the tangential impulse: Δω = a J_T/I for each grain,
        // J_T = m_t (ε_T − 1) g_T; opposite torques on the two grains.
        let m_t = kappa * c.m_eff;
        let j_t = m_t * (o.eps_t - 1.0) * g_t;
        let i1 = 0.4 * c.mass_1 * r1 * r1;
        assert!(
            (o.spin_change[0].abs() - r1 * j_t.abs() / i1).abs()
                <= 1e-12 * (1.0 + o.spin_change[0].abs())
        );
    }
}

mod cli {
    use crate::bin::rime_binary;
    use std::process::Command;

    fn rime(args: &[&str]) -> (i32, String, String) {
        let out = Command::new(rime_binary()).args(args).output().unwrap();
        (
            out.status.code().unwrap_or(-1),
            String::from_utf8_lossy(&out.stdout).to_string(),
            String::from_utf8_lossy(&out.stderr).to_string(),
        )
    }

    #[test]
    fn collision_json_follows_the_contract_and_agrees_with_rime_eps() {
        for (preset, level) in [
            ("ice", "precise"),
            ("ice-frost", "fast"),
            ("ice-sticky", "balanced"),
        ] {
            let (code, out, e) = rime(&[
                "collision",
                "--g",
                "0.01",
                "--gt",
                "0.005",
                "--points",
                "50",
                "--preset",
                preset,
                "--accuracy",
                level,
                "--format",
                "json",
            ]);
            assert_eq!(code, 0, "{e}");
            let v: serde_json::Value = serde_json::from_str(&out).unwrap();
            for key in ["t", "xi", "xi_dot", "force"] {
                assert!(v[key].as_array().unwrap().len() >= 50, "{key}");
            }
            for key in [
                "t_c",
                "xi_max",
                "eps_n",
                "status",
                "phases",
                "ledger",
                "tangential",
            ] {
                assert!(v.get(key).is_some(), "missing {key}");
            }
            for key in [
                "kinetic_in",
                "kinetic_out",
                "dissipated_bulk",
                "dissipated_layer",
                "adhesion",
                "closure",
            ] {
                assert!(v["ledger"][key].is_number(), "ledger.{key}");
            }
            for key in [
                "eps_t",
                "class",
                "energy_before",
                "energy_after",
                "friction_work",
                "spin_change",
            ] {
                assert!(v["tangential"].get(key).is_some(), "tangential.{key}");
            }
            assert!(v["phases"][0]["name"].is_string() && v["phases"][0]["t"].is_number());
            let (code, eps, _) = rime(&[
                "eps",
                "--g",
                "0.01",
                "--preset",
                preset,
                "--accuracy",
                level,
                "--format",
                "json",
            ]);
            assert_eq!(code, 0);
            let eps: serde_json::Value = serde_json::from_str(&eps).unwrap();
            assert_eq!(v["eps_n"], eps[0]["eps_n"], "{preset}");
            assert_eq!(v["t_c"], eps[0]["t_c"], "{preset}");
        }
    }

    #[test]
    fn collision_csv_has_units_and_the_ledger_as_comments_and_bad_input_names_the_flag() {
        let (code, out, _) = rime(&[
            "collision",
            "--g",
            "0.01",
            "--points",
            "5",
            "--format",
            "csv",
        ]);
        assert_eq!(code, 0);
        let mut lines = out.lines();
        assert_eq!(lines.next(), Some("t [s],xi [m],xi_dot [m/s],force [N]"));
        assert!(out.lines().any(|l| l.starts_with("# ledger.closure,")));
        for (args, flag) in [
            (vec!["collision"], "--g"),
            (vec!["collision", "--g", "-1"], "--g"),
            (
                vec!["collision", "--g", "0.01", "--points", "1"],
                "--points",
            ),
            (vec!["collision", "--g", "0.01", "--gt", "x"], "--gt"),
        ] {
            let (code, _, e) = rime(&args);
            assert_eq!(code, 2, "{args:?}");
            assert_eq!(e.trim().lines().count(), 1, "{e}");
            assert!(e.contains(flag), "{e}");
        }
    }
}

/// Issue 36: the CSV (and the table) are the core's, beside its JSON record: the CSV's header names
/// the record's arrays with their units, its rows are their samples to the digit, and each
/// `# key,value,unit` line is the record's field at that key.
#[test]
fn issue_36_the_collision_csv_is_the_json_records_fields() {
    let args = [
        "collision",
        "--g",
        "0.02",
        "--set",
        "friction=on",
        "--gt",
        "0.01",
    ];
    let with = |format: &str| {
        let mut a = args.to_vec();
        a.extend(["--points", "25", "--format", format]);
        let (code, out, err) = crate::bin::rime(&a);
        assert_eq!(code, 0, "{err}");
        out
    };
    let json: serde_json::Value = serde_json::from_str(&with("json")).unwrap();
    let csv = with("csv");
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(header, ["t [s]", "xi [m]", "xi_dot [m/s]", "force [N]"]);
    let row: Vec<f64> = lines
        .next()
        .unwrap()
        .split(',')
        .map(|c| c.parse().unwrap())
        .collect();
    for (h, v) in header.iter().zip(&row) {
        let key = h.split(' ').next().unwrap();
        assert_eq!(json[key][0].as_f64(), Some(*v), "{key}");
    }
    let comment = |key: &str| {
        csv.lines()
            .find_map(|l| l.strip_prefix(&format!("# {key},")))
            .unwrap_or_else(|| panic!("# {key} in the CSV"))
            .to_string()
    };
    assert_eq!(
        comment("status"),
        format!("{},", json["status"].as_str().unwrap())
    );
    let closure = comment("ledger.closure");
    assert_eq!(
        closure.split(',').next().unwrap().parse::<f64>().ok(),
        json["ledger"]["closure"].as_f64()
    );
    assert_eq!(
        comment("tangential.class"),
        format!("{},", json["tangential"]["class"].as_str().unwrap())
    );
    assert!(comment("tangential.spin_change_1").ends_with(",rad/s"));
}
