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

/// 10⁶ log-uniform pseudo-random speeds in [1e-6, 1] m/s (a population, not a sorted curve).
fn population() -> Vec<f64> {
    let mut state = 0x9e37_79b9_7f4a_7c15u64;
    (0..1_000_000)
        .map(|_| {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            let x = (state >> 11) as f64 / (1u64 << 53) as f64;
            10f64.powf(-6.0 + 6.0 * x)
        })
        .collect()
}

/// Batch ε_N against the scalar fast path on the same 10⁶ speeds (ns per value = time / 10⁶).
fn batch(c: &mut Criterion) {
    let g = population();
    let mut out = vec![0.0; g.len()];
    let mut group = c.benchmark_group("batch1e6");
    group.sample_size(10);
    group.throughput(criterion::Throughput::Elements(g.len() as u64));
    for (model, scene) in scenes() {
        let Ok(contact) = Contact::new(&scene) else {
            continue;
        };
        if model == "layer_literal" {
            continue;
        }
        let law = rime_core::batch::BatchLaw::new(&contact, Accuracy::Fast);
        group.bench_function(format!("{model}/batch"), |b| {
            b.iter(|| law.fill(black_box(&g), &mut out))
        });
        group.bench_function(format!("{model}/scalar"), |b| {
            b.iter(|| {
                for (o, &x) in out.iter_mut().zip(black_box(&g)) {
                    *o = contact.eps_n(x, Accuracy::Fast).unwrap_or(f64::NAN);
                }
            })
        });
    }
    group.finish();
}

criterion_group!(benches, single_eps, curves_and_maps, batch);
criterion_main!(benches);
