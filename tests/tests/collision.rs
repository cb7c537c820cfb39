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
    assert!((tr.t_c / (3.21806545971904 * tau) - 1.0).abs() < 1e-10, "{}", tr.t_c / tau);
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
    assert!(area.abs() < 1e-6 * peak, "loop area {area:e} vs peak work {peak:e}");
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
            let bound = if accuracy == Accuracy::Precise { 1e-9 } else { 1e-5 };
            if tr.resolved {
                assert!(l.closure.abs() <= bound, "{name} {accuracy:?}: {}", l.closure);
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
        assert!((got / expected - 1.0).abs() < 1e-12, "g = {g}: {got:e} vs {expected:e}");
    }
}

#[test]
fn adhesion_takes_w_s_off_the_rebound_energy_of_the_model_without_it() {
    for preset in [Preset::IceSticky, Preset::IceFrost] {
        let with = scene(preset, &[("adhesion", "on")]);
        let mut without = with.clone();
        without.set("adhesion", "off").unwrap();
        let (cw, co) = (Contact::new(&with).unwrap(), Contact::new(&without).unwrap());
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
    assert!((rebound / many.eps_n - 1.0).abs() < 1e-9, "{rebound} vs {}", many.eps_n);
    let names: Vec<&str> = many.phases.iter().map(|p| p.name).collect();
    assert_eq!(
        names,
        ["bulk_loading", "maximum_compression", "unloading", "end_of_contact"]
    );
}
