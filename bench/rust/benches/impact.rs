//! Criterion benchmarks of single impacts (exact path and integrated, every model) and of the paper's
//! Table 1 sweep. Results and the machine are in `docs/performance.md`.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use pounding::contact::{ContactModel, Model};
use pounding::impact::{exact, simulate, ImpactOptions, ImpactSetup};

fn single_impacts(c: &mut Criterion) {
    let setup = ImpactSetup::relative(1.0e5, 1.0);
    for model in Model::all() {
        let spec = ContactModel::new(model, 1.0e9, 0.65).unwrap();
        let prepared = spec.prepare().unwrap();
        let (law, _) = prepared.law(setup.mass, setup.v_i).unwrap();
        if exact::e_post(&law, spec.tension(), setup.mass, setup.v_i).is_some() {
            c.bench_function(&format!("exact/{model}"), |b| {
                b.iter(|| {
                    let (l, _) = prepared
                        .law(black_box(setup.mass), black_box(setup.v_i))
                        .unwrap();
                    exact::e_post(&l, spec.tension(), setup.mass, setup.v_i)
                })
            });
        }
        c.bench_function(&format!("integrated/{model}"), |b| {
            b.iter(|| {
                simulate(
                    black_box(&law),
                    spec.tension(),
                    &setup,
                    &ImpactOptions::default(),
                )
                .unwrap()
            })
        });
    }
}

fn table1(c: &mut Criterion) {
    let mut g = c.benchmark_group("paper");
    g.sample_size(10);
    g.bench_function("table1", |b| b.iter(|| pounding::paper::table1().unwrap()));
    g.finish();
}

// The macro generates an undocumented function.
#[allow(missing_docs)]
mod group {
    use super::*;
    criterion_group!(benches, single_impacts, table1);
}
criterion_main!(group::benches);
