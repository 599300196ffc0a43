//! Pounding time histories: the two-SDOF example of `bench/opensees/` (the OpenSeesPy peer measures the
//! same problems), a 20-storey pair, and how cost grows with storeys and with record length.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use pounding::analysis::{Building, Scenario};
use pounding::contact::{ContactModel, Model};
use pounding::ground_motion::Record;
use pounding::structure::ShearBuilding;

fn building(name: &str, n: usize, m: f64, k: f64) -> Building {
    Building {
        name: name.into(),
        structure: ShearBuilding::new(vec![m; n], vec![k; n], vec![3.0; n], 0.05).unwrap(),
    }
}

/// Two buildings of `n` storeys side by side, the left one stiffer, papi contacts at every floor.
fn pair(n: usize, record: Record, model: Model, k_c: f64) -> Scenario {
    // Storey stiffness chosen so that the fundamental periods are about 0.1 n s and 0.15 n s.
    let m = 5.0e5;
    let k_for = |t1: f64| {
        let w = 2.0 * std::f64::consts::PI / t1;
        // Uniform chain: w1 = 2 sqrt(k/m) sin(pi / (2 (2n + 1))).
        let s = (std::f64::consts::PI / (2.0 * (2 * n + 1) as f64)).sin();
        m * (w / (2.0 * s)).powi(2)
    };
    let (t_l, t_r) = if n == 1 {
        (0.5, 1.0)
    } else {
        (0.1 * n as f64, 0.15 * n as f64)
    };
    let (k_l, k_r) = if n == 1 {
        (7.8957e7, 1.9739e7)
    } else {
        (k_for(t_l), k_for(t_r))
    };
    Scenario::new(
        vec![building("left", n, m, k_l), building("right", n, m, k_r)],
        record,
    )
    .unwrap()
    .with_link(
        "left",
        "right",
        0.02,
        &ContactModel::new(model, k_c, 0.65).unwrap(),
        None,
    )
    .unwrap()
}

/// El Centro repeated `times` times end to end.
fn repeated(times: usize) -> Record {
    let r = Record::el_centro_1940();
    let mut acc = Vec::new();
    for _ in 0..times {
        acc.extend_from_slice(r.accelerations());
    }
    Record::new("el-centro-repeated", r.dt(), r.t0(), acc).unwrap()
}

fn benches(c: &mut Criterion) {
    let mut g = c.benchmark_group("two_sdof_el_centro");
    g.sample_size(20);
    for (model, k) in [
        (Model::Hooke, 2.0e9),
        (Model::KelvinVoigt, 2.0e9),
        (Model::Jankowski, 2.0e10),
        (Model::Hertzdamp, 2.0e10),
        (Model::Papi, 2.0e9),
    ] {
        let s = pair(1, Record::el_centro_1940(), model, k);
        g.bench_function(model.name(), |b| b.iter(|| s.run().unwrap()));
    }
    g.finish();

    let mut g = c.benchmark_group("storeys");
    g.sample_size(10);
    for n in [1, 2, 5, 10, 20, 40] {
        let s = pair(n, Record::el_centro_1940(), Model::Papi, 2.0e9);
        g.bench_with_input(BenchmarkId::from_parameter(n), &s, |b, s| {
            b.iter(|| s.run().unwrap())
        });
    }
    g.finish();

    let mut g = c.benchmark_group("record_length");
    g.sample_size(10);
    for times in [1, 2, 4] {
        let s = pair(1, repeated(times), Model::Papi, 2.0e9);
        g.bench_with_input(BenchmarkId::from_parameter(times), &s, |b, s| {
            b.iter(|| s.run().unwrap())
        });
    }
    g.finish();
}

#[allow(missing_docs)]
mod group {
    use super::*;
    criterion_group!(pounding_benches, benches);
}
criterion_main!(group::pounding_benches);
