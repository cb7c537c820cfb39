//! Issue 10: every sticking threshold of every model and option, walked to one ulp on both sides at
//! every level. Near a threshold the result must be a number (finite ε_N in [0, 1], a status, a
//! duration that is finite or unresolved), never an error, continuous and monotone across it.
//!
//! The property tests sample scenes uniformly and never landed in the windows of a few ulps to a few
//! 1e-4 relative above a threshold where the literal reading used to fail; this family *seeks* each
//! threshold by bisection on the bit pattern of g (positive doubles order like their bits), so it ends
//! on two adjacent doubles, one stuck and one not, and then probes outwards from there.

use rime_core::{
    Accuracy, AdhesionModulus, Contact, ContactEnd, Damping, DampingFormula, LayerReading, Normal,
    Preset, Scene, Status, Viscosities,
};

const LEVELS: [Accuracy; 3] = [Accuracy::Fast, Accuracy::Balanced, Accuracy::Precise];

fn stuck(n: &Normal) -> bool {
    matches!(n.status, Status::StuckInLayer | Status::StuckByAdhesion)
}

/// Checks one result and returns it: a number, never an error.
fn evaluate(c: &Contact, g: f64, acc: Accuracy, what: &str) -> Normal {
    let n = c
        .normal(g, acc)
        .unwrap_or_else(|e| panic!("{what}: g = {g:e} at {acc:?}: error {e}"));
    assert!(
        n.eps.is_finite() && (0.0..=1.0).contains(&n.eps),
        "{what}: g = {g:e} at {acc:?}: ε = {}",
        n.eps
    );
    assert!(
        n.t_c > 0.0 && !n.t_c.is_nan(),
        "{what}: g = {g:e} at {acc:?}: t_c = {}",
        n.t_c
    );
    assert!(
        n.xi_max.is_finite() && n.xi_max >= 0.0,
        "{what}: g = {g:e} at {acc:?}: ξ_max = {}",
        n.xi_max
    );
    if stuck(&n) {
        assert_eq!(n.eps, 0.0, "{what}: stuck with ε = {}", n.eps);
    }
    n
}

/// The largest speed in `[lo, hi]` at which the grains stick, to one ulp (None when the status does not
/// change across the interval).
fn threshold(c: &Contact, acc: Accuracy, what: &str) -> Option<f64> {
    let (mut lo, mut hi) = (1e-12f64, 1e5f64);
    if !stuck(&evaluate(c, lo, acc, what)) || stuck(&evaluate(c, hi, acc, what)) {
        return None;
    }
    // Bisection on the bits: both ends stay valid doubles, and it stops at adjacent ones.
    let (mut a, mut b) = (lo.to_bits(), hi.to_bits());
    while b - a > 1 {
        let m = a + (b - a) / 2;
        if stuck(&evaluate(c, f64::from_bits(m), acc, what)) {
            a = m;
        } else {
            b = m;
        }
    }
    lo = f64::from_bits(a);
    hi = f64::from_bits(b);
    assert_eq!(hi, lo.next_up());
    Some(lo)
}

/// Walks outwards from a threshold: ulps and then relative steps, on both sides.
///
/// ε_N must be continuous (tiny one ulp above) and, under the force-zero rule, monotone. Under the
/// zero-overlap rule it is not: once the bulk contact creeps (δ ≳ 30), ε_ve ≈ K δ⁻⁵ ∝ 1/g_bulk, so
/// ε_N = ε_ve g_bulk/g ≈ const/g falls again, by the exact physics of that rule (K of
/// docs/physics.md#decision-2), not by a numerical error.
fn walk(c: &Contact, acc: Accuracy, g_stick: f64, what: &str) {
    let mut above = Vec::new();
    for k in 0..=24u32 {
        // 1, 2, 4, … 2^24 ulps above the last sticking speed, then relative steps to 10 %.
        let g = f64::from_bits(g_stick.to_bits() + (1u64 << k));
        above.push(g);
        let below = f64::from_bits(g_stick.to_bits() - ((1u64 << k) - 1));
        let n = evaluate(c, below, acc, what);
        // An integrated threshold (literal reading) is known to the tolerance only: within it the
        // status may flip, but a rebound there must be tiny (continuity).
        assert!(
            stuck(&n) || n.eps < 1e-4,
            "{what} at {acc:?}: g = {below:e} below the threshold rebounds with ε = {:e}",
            n.eps
        );
    }
    for e in [1e-8, 1e-6, 1e-4, 1e-3, 1e-2, 3e-2, 1e-1] {
        above.push(g_stick * (1.0 + e));
    }
    let mut previous = 0.0f64;
    let first = evaluate(c, above[0], acc, what);
    assert!(
        first.eps < 1e-6,
        "{what} at {acc:?}: ε_N jumps to {:e} one ulp above the threshold",
        first.eps
    );
    for g in above {
        let n = evaluate(c, g, acc, what);
        let near = g / g_stick - 1.0 < 1e-6;
        assert!(
            !stuck(&n) || near,
            "{what} at {acc:?}: g = {g:e} above the threshold sticks"
        );
        if c.contact_end == ContactEnd::ZeroOverlap || (near && stuck(&n)) {
            continue;
        }
        // Monotone across the threshold, up to the level's error bound.
        // The literal reading's ε is a difference v_exit − g_s/g of two numbers near g_s/g, each
        // known to the level's tolerance: its noise is absolute, ~ bound × g_s/g.
        let literal = c
            .layer
            .is_some_and(|l| l.reading == LayerReading::Literal && l.thickness > 0.0);
        let absolute = if literal {
            4.0 * acc.error_bound()
        } else {
            1e-15
        };
        let slack = n.error_estimate.max(1e-12) * 4.0 * n.eps + absolute;
        assert!(
            n.eps + slack >= previous,
            "{what} at {acc:?}: ε_N falls from {previous:e} to {:e} at g = {g:e}",
            n.eps
        );
        previous = previous.max(n.eps);
    }
}

/// The scenes: every model and option, with one parameter moved over decades at a time.
fn scenes() -> Vec<(String, Scene)> {
    let mut out = Vec::new();
    let bases: Vec<(&str, Scene)> = {
        let frost = Preset::IceFrost.scene();
        let sticky = Preset::IceSticky.scene();
        let mut literal = frost;
        if let Some(l) = literal.layer.as_mut() {
            l.reading = LayerReading::Literal;
        }
        let mut consistent = sticky;
        if let Some(a) = consistent.adhesion.as_mut() {
            a.modulus = AdhesionModulus::Consistent;
        }
        let both = Scene {
            adhesion: sticky.adhesion,
            ..frost
        };
        let both_literal = Scene {
            adhesion: sticky.adhesion,
            ..literal
        };
        vec![
            ("layer offset", frost),
            ("layer literal", literal),
            ("adhesion as printed", sticky),
            ("adhesion consistent", consistent),
            ("layer + adhesion", both),
            ("literal layer + adhesion", both_literal),
        ]
    };
    for (name, base) in bases {
        for end in [ContactEnd::ForceZero, ContactEnd::ZeroOverlap] {
            for viscosities in [false, true] {
                let mut s = base;
                s.contact_end = end;
                if viscosities {
                    s.bulk.damping = Damping::Viscosities(Viscosities {
                        shear: 1e6,
                        bulk: 1e12,
                        formula: DampingFormula::Brilliantov,
                    });
                }
                let label = format!(
                    "{name}, {end:?}, {}",
                    if viscosities {
                        "A from viscosities"
                    } else {
                        "A given"
                    }
                );
                out.push((label.clone(), s));
                let mut vary = |field: &str, values: &[f64]| {
                    for &v in values {
                        let mut t = s;
                        let ok = match field {
                            "radius" => t
                                .set_number("grains.radius_1", v)
                                .and_then(|_| t.set_number("grains.radius_2", v)),
                            f => t.set_number(f, v),
                        };
                        if ok.is_ok() {
                            out.push((format!("{label}, {field} = {v:e}"), t));
                        }
                    }
                };
                if s.layer.is_some() {
                    vary("layer.thickness", &[1e-8, 1e-7, 1e-5, 1e-4]);
                    vary("layer.viscosity", &[10.0, 100.0, 1e4, 1e5]);
                }
                if s.adhesion.is_some() {
                    vary("adhesion.surface_energy", &[1e-3, 1e-2, 1.0, 10.0]);
                }
                vary("radius", &[1e-6, 1e-4, 1.0]);
                if !viscosities {
                    vary("bulk.damping.time", &[0.0, 1e-6, 1e-2, 100.0]);
                }
            }
        }
    }
    out
}

#[test]
fn every_threshold_walked_to_one_ulp_at_every_level_issue_10() {
    let mut walked = std::collections::BTreeMap::<String, usize>::new();
    for (what, scene) in scenes() {
        let c = Contact::new(&scene).unwrap_or_else(|e| panic!("{what}: {e}"));
        let model = what.split(',').next().unwrap_or_default().to_string();
        for acc in LEVELS {
            // None: stuck at every speed up to 1e5 m/s (µm grains, thick layers, or an overdamped
            // rebound that adhesion always holds) or never stuck; both are checked by `threshold`.
            if let Some(g) = threshold(&c, acc, &what) {
                walk(&c, acc, g, &what);
                *walked.entry(model.clone()).or_default() += 1;
            }
        }
    }
    // Every model and option had its threshold walked many times over.
    assert_eq!(walked.len(), 6, "{walked:?}");
    for (model, n) in &walked {
        assert!(*n >= 40, "{model}: only {n} thresholds walked ({walked:?})");
    }
}

#[test]
fn literal_reading_just_above_its_threshold_is_a_number_issue_10() {
    // The reported case: ice-frost, literal reading, 1.3267312500000002e-5 m/s at fast exited 1 with
    // "no separation before the time limit".
    let mut s = Preset::IceFrost.scene();
    s.set("layer.reading", "literal").unwrap();
    let c = Contact::new(&s).unwrap();
    for acc in LEVELS {
        let n = evaluate(&c, 1.3267312500000002e-05, acc, "reported case");
        let stuck_below = evaluate(&c, 1.3266e-5, acc, "reported case");
        assert!(stuck(&stuck_below));
        assert!(!stuck(&n) && n.eps > 0.0 && n.t_c.is_finite(), "{n:?}");
        // 1.3268e-5 rebounds with ε_N ≈ 5.2e-5 (the issue's report, from the old integrator).
        let r = evaluate(&c, 1.3268e-5, acc, "reported case");
        assert!((r.eps / 5.2e-5 - 1.0).abs() < 0.05, "{}", r.eps);
    }
}

#[test]
fn literal_reading_with_the_papers_viscosities_sticks_in_the_layer_issue_10() {
    // A ≈ 404 s: the bulk stops the grains almost at once and lets them creep back at speed
    // ξ/(1.5 A)·…, far below what the layer takes off on the way out: stuck in the layer.
    for end in [ContactEnd::ForceZero, ContactEnd::ZeroOverlap] {
        let mut s = Preset::IcePaperViscosities.scene();
        s.layer = Preset::IceFrost.scene().layer;
        s.set("layer.reading", "literal").unwrap();
        s.contact_end = end;
        let c = Contact::new(&s).unwrap();
        for acc in LEVELS {
            for g in [1e-5, 1e-3, 0.1, 10.0] {
                let n = evaluate(&c, g, acc, "paper's viscosities, literal");
                assert_eq!(
                    n.status,
                    Status::StuckInLayer,
                    "{end:?} {acc:?} g = {g}: {n:?}"
                );
            }
        }
    }
}
