//! "Model only what a scene requires": effects that are off cost nothing, counted in right-hand-side
//! evaluations of the integrator (issue 3).

use rime_core::sweep::StickMap;
use rime_core::{Accuracy, Adhesion, Contact, Friction, Layer, LayerReading, Scene};

fn evals(scene: &Scene, g: f64, acc: Accuracy) -> usize {
    Contact::new(scene)
        .unwrap()
        .normal(g, acc)
        .unwrap()
        .rhs_evaluations
}

#[test]
fn table_levels_integrate_nothing_for_tabulated_models() {
    let mut s = Scene::default();
    for acc in [Accuracy::Fast, Accuracy::Precise] {
        assert_eq!(evals(&s, 0.01, acc), 0);
        s.layer = Some(Layer::default());
        assert_eq!(
            evals(&s, 0.01, acc),
            0,
            "offset layer is assembled from the table"
        );
        s.adhesion = Some(Adhesion::default());
        assert_eq!(evals(&s, 0.01, acc), 0, "adhesion is algebraic on top");
        s.layer = Some(Layer {
            reading: LayerReading::Literal,
            ..Layer::default()
        });
        assert!(evals(&s, 0.01, acc) > 0, "the literal reading has no table");
        s = Scene::default();
    }
}

#[test]
fn effects_that_are_off_or_algebraic_cost_no_extra_integration() {
    let clean = Scene::default();
    let base = evals(&clean, 0.01, Accuracy::Balanced);
    assert!(base > 0);
    let no_friction = Scene {
        friction: None,
        ..clean
    };
    assert_eq!(evals(&no_friction, 0.01, Accuracy::Balanced), base);
    let sticky = Scene {
        adhesion: Some(Adhesion::default()),
        friction: Some(Friction::default()),
        ..clean
    };
    assert_eq!(evals(&sticky, 0.01, Accuracy::Balanced), base);
    // The offset layer integrates one bulk collision, at the bulk-entry speed.
    let frost = Scene {
        layer: Some(Layer::default()),
        ..clean
    };
    let g_s = Contact::new(&frost)
        .unwrap()
        .layer
        .unwrap()
        .critical_velocity;
    assert_eq!(
        evals(&frost, 0.01, Accuracy::Balanced),
        evals(&clean, 0.01 - g_s, Accuracy::Balanced)
    );
    // Stuck in the layer: closed form, no integration at all.
    assert_eq!(evals(&frost, g_s * 0.5, Accuracy::Balanced), 0);
}

#[test]
fn a_stick_map_evaluates_the_normal_law_once_per_grid_speed() {
    let scene = Scene::default();
    let contact = Contact::new(&scene).unwrap();
    let n = 40;
    let map = StickMap::new(&contact, 0.05, n, Accuracy::Balanced).unwrap();
    // Grid speeds 1..n-1 are integrated once each (g = 0 is the elastic limit, free).
    let per_speed: usize = map.g[1..]
        .iter()
        .map(|&g| {
            contact
                .normal(g, Accuracy::Balanced)
                .unwrap()
                .rhs_evaluations
        })
        .sum();
    assert_eq!(map.rhs_evaluations, per_speed);
    assert_eq!(map.class.len(), n * n);
}

/// The integrated level on strongly damped contacts (issue 26): the force falls through
/// ~(10/3) ln δ e-foldings before it vanishes, and measuring its error against the accuracy the
/// end of contact needs (not relative to itself all the way down) keeps a contact to a few
/// thousand evaluations up to δ = 1e12 (it was 9 067 at δ = 1e6 and 10 063 at 1e7, at rtol 1e-11,
/// and from δ ≈ 1e9 on no budget sufficed). Counted, not timed; the accuracy is checked against
/// the references by `integrated_level_resolves_strong_damping_issue_26`.
#[test]
fn overdamped_contacts_cost_a_few_thousand_evaluations_issue_26() {
    let rtol = Accuracy::Balanced.integrator_rtol();
    for k in 3..=12 {
        let delta = 10f64.powi(k);
        let r = rime_core::normal::viscoelastic::dimensionless(
            delta,
            rime_core::ContactEnd::ForceZero,
            rtol,
        )
        .unwrap();
        assert!(
            r.rhs_evaluations <= 4_000,
            "δ = {delta:e}: {} evaluations",
            r.rhs_evaluations
        );
    }
}
