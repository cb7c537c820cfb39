//! criterion benches of the speed/accuracy trade (the same cases as `rime bench`).
#![allow(missing_docs)]

use criterion::{Criterion, criterion_group, criterion_main};
use rime_core::sweep::{self, StickMap};
use rime_core::{Accuracy, Contact, Layer, LayerReading, Preset, Scene};
use std::hint::black_box;

fn scenes() -> Vec<(&'static str, Scene)> {
    let frost = Preset::IceFrost.scene();
    vec![
        ("viscoelastic", Preset::Ice.scene()),
        ("layer_offset", frost),
        (
            "layer_literal",
            Scene {
                layer: Some(Layer {
                    reading: LayerReading::Literal,
                    ..Layer::default()
                }),
                ..frost
            },
        ),
        ("adhesion", Preset::IceSticky.scene()),
    ]
}

fn levels() -> [(&'static str, Accuracy); 3] {
    [
        ("fast", Accuracy::Fast),
        ("balanced", Accuracy::Balanced),
        ("precise", Accuracy::Precise),
    ]
}

fn single_eps(c: &mut Criterion) {
    for (model, scene) in scenes() {
        let Ok(contact) = Contact::new(&scene) else {
            continue;
        };
        for (level, acc) in levels() {
            c.bench_function(&format!("eps/{model}/{level}"), |b| {
                b.iter(|| contact.eps_n(black_box(0.01), acc))
            });
        }
    }
}

fn curves_and_maps(c: &mut Criterion) {
    let Ok(contact) = Contact::new(&Preset::IceFrost.scene()) else {
        return;
    };
    let mut group = c.benchmark_group("sweeps");
    group.sample_size(20);
    for (level, acc) in levels() {
        group.bench_function(format!("curve400/{level}"), |b| {
            b.iter(|| sweep::curve(&contact, 1e-8, 10.0, 400, acc))
        });
        group.bench_function(format!("map200/{level}"), |b| {
            b.iter(|| StickMap::new(&contact, 0.05, 200, acc))
        });
    }
    group.finish();
}

criterion_group!(benches, single_eps, curves_and_maps);
criterion_main!(benches);
