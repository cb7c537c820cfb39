//! Batch ε_N (`rime_core::batch`) against `Contact::normal` at Precise, and `rime eps --g-file`.

use rime_core::batch::BatchLaw;
use rime_core::{Accuracy, Adhesion, Contact, ContactEnd, Damping, Preset, Scene};
use rime_tests::rime_binary;
use std::process::Command;

/// Every preset, plus damping times that move the speeds across the whole table and a scene with
/// both a layer and adhesion, each with both contact-end rules.
fn scenes() -> Vec<(String, Scene)> {
    let mut base: Vec<(String, Scene)> = Preset::ALL
        .iter()
        .map(|p| (p.name().to_string(), p.scene()))
        .collect();
    for a in [1e-9, 1e-7, 1e-2, 1.0] {
        let mut s = Preset::Ice.scene();
        s.bulk.damping = Damping::Time(a);
        base.push((format!("ice, A = {a:e} s"), s));
    }
    let mut both = Preset::IceFrost.scene();
    both.adhesion = Some(Adhesion::default());
    base.push(("ice-frost + adhesion".into(), both));
    let mut out = Vec::new();
    for (name, s) in base {
        for end in [ContactEnd::ForceZero, ContactEnd::ZeroOverlap] {
            out.push((
                format!("{name}, {end:?}"),
                Scene {
                    contact_end: end,
                    ..s
                },
            ));
        }
    }
    out
}

/// Log-spaced speeds over [1e-12, 1e3] m/s with an irrational step, both ends included.
fn speeds() -> Vec<f64> {
    let mut g: Vec<f64> = (0..)
        .map(|k| 1e-12 * 10f64.powf(k as f64 * 0.0007 * std::f64::consts::SQRT_2))
        .take_while(|&g| g < 1e3)
        .collect();
    g.push(1e3);
    g
}

#[test]
fn batch_meets_the_fast_bound_against_precise_at_every_speed() {
    let g = speeds();
    let mut out = vec![0.0; g.len()];
    let mut worst = (0.0f64, String::new());
    for (name, scene) in scenes() {
        let contact = Contact::new(&scene).unwrap();
        let law = BatchLaw::new(&contact, Accuracy::Fast);
        assert!(law.uses_table(), "{name}");
        law.fill(&g, &mut out).unwrap();
        for (&gi, &e) in g.iter().zip(&out) {
            let want = contact.normal(gi, Accuracy::Precise).unwrap().eps;
            // Stuck (layer or adhesion) is exactly 0, as in `normal`.
            assert_eq!(e == 0.0, want == 0.0, "{name}: g = {gi:e}: {e} vs {want}");
            if want > 1e-6 {
                let err = ((e - want) / want).abs();
                assert!(
                    err <= 1e-6,
                    "{name}: g = {gi:e}: {e} vs {want} (rel {err:.2e})"
                );
                if err > worst.0 {
                    worst = (err, format!("{name}, g = {gi:e}"));
                }
            } else {
                assert!(
                    (e - want).abs() <= 1e-12,
                    "{name}: g = {gi:e}: {e} vs {want} (abs {:.2e})",
                    (e - want).abs()
                );
            }
        }
    }
    println!(
        "batch ε_N, worst relative error against normal(Precise): {:.2e} ({})",
        worst.0, worst.1
    );
}

#[test]
fn batch_takes_signed_speeds_nan_zero_and_refuses_the_rest() {
    for preset in Preset::ALL {
        let contact = Contact::new(&preset.scene()).unwrap();
        let g = [1e-3, -1e-3, f64::NAN, 0.0, -0.0, 0.2, -7e-5];
        let mut out = [0.0; 7];
        contact.eps_n_batch(&g, &mut out, Accuracy::Fast).unwrap();
        assert_eq!(out[0], out[1]);
        assert!(out[2].is_nan());
        let rest = contact.eps_n(0.0, Accuracy::Precise).unwrap();
        assert_eq!(out[3], rest);
        assert_eq!(out[4], rest);
        let mut pos = [0.0; 2];
        contact
            .eps_n_batch(&[0.2, 7e-5], &mut pos, Accuracy::Fast)
            .unwrap();
        assert_eq!([out[5], out[6]], pos);
        // Levels without batch cells are the scalar path value by value.
        for acc in [Accuracy::Balanced, Accuracy::Precise] {
            let mut o = [0.0; 2];
            contact.eps_n_batch(&[0.01, -0.01], &mut o, acc).unwrap();
            let want = contact.eps_n(0.01, acc).unwrap();
            assert_eq!(o, [want, want]);
        }
        for bad in [2e6, f64::INFINITY, -f64::INFINITY] {
            let mut o = [0.0; 3];
            assert!(
                contact
                    .eps_n_batch(&[0.1, bad, 0.1], &mut o, Accuracy::Fast)
                    .is_err()
            );
        }
        let mut short = [0.0; 1];
        assert!(
            contact
                .eps_n_batch(&[0.1, 0.2], &mut short, Accuracy::Fast)
                .is_err()
        );
    }
}
