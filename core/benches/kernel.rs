//! criterion benches of the sticking kernel (issue 39): a 120 × 120 table per temperature, the
//! cost a dust code pays once per distinct temperature.
#![allow(missing_docs)]

use criterion::{Criterion, criterion_group, criterion_main};
use rime_core::kernel::{self, ARule, KernelOptions};
use rime_core::{Accuracy, Scene};
use std::hint::black_box;

fn radii(n: usize) -> Vec<f64> {
    // 1 µm to 1 m, equal in log.
    (0..n)
        .map(|i| 1e-6 * 10f64.powf(6.0 * i as f64 / (n - 1) as f64))
        .collect()
}

fn tables(c: &mut Criterion) {
    let scene = Scene::default();
    let r = radii(120);
    let mut group = c.benchmark_group("kernel");
    group.sample_size(10);
    for (name, a_rule) in [
        ("given", ARule::Given),
        ("keep_epsilon", ARule::KeepEpsilon),
    ] {
        for (level, accuracy) in [("fast", Accuracy::Fast), ("precise", Accuracy::Precise)] {
            let options = KernelOptions {
                a_rule,
                accuracy,
                ..Default::default()
            };
            for temps in [vec![150.0], vec![150.0, 175.0, 187.5, 200.0]] {
                group.bench_function(format!("120x120x{}/{name}/{level}", temps.len()), |b| {
                    b.iter(|| kernel::table(&scene, black_box(&r), &temps, &options))
                });
            }
        }
    }
    // A dust code's first update: one table per distinct temperature of 100 radial cells.
    let temps: Vec<f64> = (0..100).map(|i| 40.0 + 2.1 * i as f64).collect();
    let options = KernelOptions::default();
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    for threads in [1, cores] {
        group.bench_function(format!("120x120x100/given/fast/{threads}threads"), |b| {
            b.iter(|| kernel::table_parallel(&scene, black_box(&r), &temps, &options, threads))
        });
    }
    group.finish();
}

criterion_group!(benches, tables);
criterion_main!(benches);
