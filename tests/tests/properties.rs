//! scratch
use rime_core::*;
#[test]
fn scratch() {
    for r in [1e-6, 1e-5, 1e-3, 0.1, 1.0, 10.0] {
        for (r1, r2) in [(r, r), (r, 1e-6), (r, 10.0)] {
            let mut s = Scene::default();
            s.grains.radius_1 = r1;
            s.grains.radius_2 = r2;
            let c = Contact::new(&s).unwrap();
            for g in [1e-12, 1e-10, 1e-8] {
                let n = c.normal(g, Accuracy::Balanced).unwrap();
                if n.eps > 1.0 {
                    eprintln!(
                        "R {r1} {r2} g {g} delta {} eps {} -1 = {:e}",
                        c.delta(g),
                        n.eps,
                        n.eps - 1.0
                    );
                }
            }
        }
    }
    for d in [1e-6, 1e-4] {
        let mut s = Scene::default();
        s.bulk.damping = Damping::Time(0.0);
        s.layer = Some(Layer {
            thickness: d,
            viscosity: 0.0,
            reading: LayerReading::Literal,
        });
        let c = Contact::new(&s).unwrap();
        for g in [1e-9, 1e-6, 1e-3, 1.0] {
            for acc in [Accuracy::Balanced, Accuracy::Precise] {
                let t = std::time::Instant::now();
                let n = c.normal(g, acc);
                eprintln!(
                    "literal eta0 D {d} g {g} {acc:?} {:?} {:?}",
                    n.map(|n| 1.0 - n.eps),
                    t.elapsed()
                );
            }
        }
    }
}
