//! Pounding time histories: the two-SDOF example of `bench/opensees/` (the OpenSeesPy peer measures the
//! same problems), a 20-storey pair, how cost grows with storeys and with record length, and inelastic
//! storeys against the same linear runs (`bench/opensees/scenarios-inelastic/`).

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use pounding::analysis::{Building, RunOptions, Scenario};
use pounding::contact::{ContactModel, Model};
use pounding::element::StoreyLaw;
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

/// The laws of `bench/opensees/scenarios-inelastic/`: yield forces per storey, a = 0.05.
fn laws(kind: &str, fy: &[f64]) -> Vec<StoreyLaw> {
    fy.iter()
        .map(|&f| match kind {
            "bilinear" => StoreyLaw::bilinear(f, 0.05).unwrap(),
            "bouc-wen" => StoreyLaw::bouc_wen(f, 0.05, 1.0, 0.5, 0.5).unwrap(),
            _ => StoreyLaw::Linear,
        })
        .collect()
}

/// `bilinear-sdof.toml` (and its linear and Bouc–Wen twins): the hertzdamp two-SDOF pair, F_y 2.5e6 and
/// 1.2e6 N.
fn sdof_pair(kind: &str) -> Scenario {
    let mut s = pair(1, Record::el_centro_1940(), Model::Hertzdamp, 2.0e10);
    let mut b = s.buildings().to_vec();
    b[0].structure = b[0]
        .structure
        .clone()
        .with_storey_laws(laws(kind, &[2.5e6]))
        .unwrap();
    b[1].structure = b[1]
        .structure
        .clone()
        .with_storey_laws(laws(kind, &[1.2e6]))
        .unwrap();
    s = Scenario::new(b, Record::el_centro_1940()).unwrap();
    s.with_link(
        "left",
        "right",
        0.02,
        &ContactModel::new(Model::Hertzdamp, 2.0e10, 0.65).unwrap(),
        None,
    )
    .unwrap()
}

/// `bilinear-mdof.toml`: the 3-storey and 8-storey buildings of the examples, hertzdamp contact at floors
/// 1-3, 40 mm, the whole record.
fn mdof_pair(kind: &str) -> Scenario {
    let with = |name: &str, m: Vec<f64>, k: Vec<f64>, fy: &[f64]| Building {
        name: name.into(),
        structure: ShearBuilding::new(m, k, vec![3.0; fy.len()], 0.05)
            .unwrap()
            .with_storey_laws(laws(kind, fy))
            .unwrap(),
    };
    Scenario::new(
        vec![
            with(
                "3",
                vec![4.0e5, 4.0e5, 3.5e5],
                vec![6.0e8, 5.0e8, 4.0e8],
                &[4.5e6, 4.0e6, 4.0e6],
            ),
            with(
                "8",
                vec![4.0e5, 4.0e5, 4.0e5, 4.0e5, 4.0e5, 4.0e5, 4.0e5, 3.0e5],
                vec![2.6e8, 2.4e8, 2.2e8, 2.0e8, 1.8e8, 1.6e8, 1.4e8, 1.2e8],
                &[2.5e6, 2.5e6, 2.5e6, 3.0e6, 3.5e6, 4.0e6, 4.0e6, 4.0e6],
            ),
        ],
        Record::el_centro_1940(),
    )
    .unwrap()
    .with_link(
        "3",
        "8",
        0.04,
        &ContactModel::new(Model::Hertzdamp, 2.0e10, 0.65).unwrap(),
        None,
    )
    .unwrap()
}

fn inelastic(c: &mut Criterion) {
    let mut g = c.benchmark_group("inelastic");
    g.sample_size(20);
    for kind in ["linear", "bilinear", "bouc-wen"] {
        let s = sdof_pair(kind);
        g.bench_function(format!("sdof_pair/{kind}"), |b| b.iter(|| s.run().unwrap()));
        let s = mdof_pair(kind);
        g.bench_function(format!("mdof_pair/{kind}"), |b| b.iter(|| s.run().unwrap()));
    }
    // A study keeps only the summary: no histories.
    let s = mdof_pair("bilinear");
    let summary_only = RunOptions::summary_only();
    g.bench_function("mdof_pair/bilinear/summary_only", |b| {
        b.iter(|| {
            s.run_with_options(&summary_only, &mut |_| std::ops::ControlFlow::Continue(()))
                .unwrap()
        })
    });
    g.finish();
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
    criterion_group!(pounding_benches, benches, inelastic);
}
criterion_main!(group::pounding_benches);
