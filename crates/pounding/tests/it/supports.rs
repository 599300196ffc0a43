//! Multi-support excitation: identical supports are the uniform excitation, a pure delay shifts a
//! free-standing building's response, and a pair on supports a wave reaches at different times balances its
//! energy with the supports' work.

use pounding::analysis::{Building, Results, Scenario};
use pounding::contact::{ContactModel, Model};
use pounding::ground_motion::Record;
use pounding::structure::ShearBuilding;

fn building(name: &str, t: f64) -> Building {
    let m = 4.0e5;
    let k = m * (2.0 * std::f64::consts::PI / t).powi(2);
    Building {
        name: name.into(),
        structure: ShearBuilding::new(vec![m, m], vec![k, 0.8 * k], vec![3.0, 3.0], 0.05).unwrap(),
    }
}

fn pair(gap: f64) -> Scenario {
    Scenario::new(
        vec![building("A", 0.4), building("B", 0.7)],
        Record::el_centro_1940(),
    )
    .unwrap()
    .with_duration(8.0)
    .unwrap()
    .with_link(
        "A",
        "B",
        gap,
        &ContactModel::new(Model::Hertzdamp, 2.0e10, 0.65).unwrap(),
        None,
    )
    .unwrap()
}

#[test]
fn identical_supports_are_the_uniform_excitation() {
    let uniform = pair(0.01).run().unwrap();
    let same = pair(0.01)
        .with_support("east", Record::el_centro_1940())
        .unwrap()
        .with_building_on("B", "east")
        .unwrap();
    assert!(!same.multi_support());
    assert_eq!(same.run().unwrap(), uniform);
}

#[test]
fn a_delay_shifts_a_free_standing_building() {
    let tau = 0.25;
    let dt = 0.005;
    let alone = |delayed: bool| {
        let mut s = Scenario::new(vec![building("A", 0.4)], Record::el_centro_1940())
            .unwrap()
            .with_duration(6.0)
            .unwrap()
            .with_output_dt(dt)
            .unwrap()
            .with_tolerance(1e-10)
            .unwrap();
        if delayed {
            let late = Record::el_centro_1940().delayed(tau).unwrap();
            s = s
                .with_support("late", late)
                .unwrap()
                .with_building_on("A", "late")
                .unwrap();
        }
        s.run().unwrap()
    };
    let (now, late) = (alone(false), alone(true));
    let shift = (tau / dt).round() as usize;
    let (u, v) = (
        &now.histories.displacement[0][1],
        &late.histories.displacement[0][1],
    );
    let peak = u.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    assert!(
        v[..shift].iter().all(|x| *x == 0.0),
        "at rest before the wave arrives"
    );
    for k in 0..u.len() - shift {
        assert!((v[k + shift] - u[k]).abs() < 1e-8 * peak, "sample {k}");
    }
}

/// A wave reaching B's support 0.05 s after A's: the pair pounds otherwise than under uniform input, and the
/// energy balances, the supports' work on the contact counted as input.
#[test]
fn a_pair_under_wave_passage_balances_its_energy() {
    let run = |tau: Option<f64>| -> Results {
        let mut s = pair(0.02);
        if let Some(tau) = tau {
            s = s
                .with_support("far", Record::el_centro_1940().delayed(tau).unwrap())
                .unwrap()
                .with_building_on("B", "far")
                .unwrap();
        }
        s.run().unwrap()
    };
    let (uniform, passage) = (run(None), run(Some(0.05)));
    assert!(!passage.impacts.is_empty());
    assert!(
        passage.energy.relative_error < 1e-6,
        "{}",
        passage.energy.relative_error
    );
    assert_ne!(uniform.impacts.len(), 0);
    assert!((uniform.sites[0].max_closing[1] - passage.sites[0].max_closing[1]).abs() > 1e-4);
}

/// Records generated with a coherency model reproduce it over an ensemble: per band of ten frequencies, the
/// ensemble coherency `|sum X1 X2*| / sqrt(sum |X1|^2 sum |X2|^2)` of 100 seeds (the samples' DFT at the
/// generated frequencies, exact for a stationary record of one period) is the target's (`sum S gamma / sum S`
/// over the band) within four standard errors `sqrt((1 - gamma^2) / 2M)` of its M = 1000 terms, for Luco–Wong
/// and Harichandran–Vanmarcke; supports at one point get one record.
#[test]
fn generated_records_reproduce_their_coherency_over_an_ensemble() {
    use pounding::ground_motion::coherency::{Coherency, Spatial};
    use pounding::ground_motion::synthetic::{Filter, Synthetic};
    let filter = Filter::KanaiTajimi { wg: 15.6, zg: 0.6 };
    let synthetic = Synthetic {
        filter,
        duration: 20.0,
        dt: 0.02,
        t1: 1.0,
        t2: 10.0,
        decay: 0.3,
        pga: None,
        envelope: false,
    };
    let n = 1000;
    let dw = 2.0 * std::f64::consts::PI / 20.0;
    for (coherency, d) in [
        (Coherency::LucoWong { alpha: 2.5e-4 }, 200.0),
        (Coherency::SMART1_EVENT20, 300.0),
    ] {
        let sp = Spatial {
            synthetic,
            coherency,
            positions: vec![0.0, d],
        };
        let bands = 12;
        let (mut cross, mut p1, mut p2) =
            (vec![(0.0, 0.0); bands], vec![0.0; bands], vec![0.0; bands]);
        for seed in 0..100 {
            let r = sp.records("c", seed).unwrap();
            let (a1, a2) = (r[0].accelerations(), r[1].accelerations());
            assert_eq!(a1.len(), n);
            for (b, ((c, q1), q2)) in cross.iter_mut().zip(&mut p1).zip(&mut p2).enumerate() {
                for l in (10 * b + 1)..=(10 * b + 10) {
                    let w = l as f64 * dw;
                    let dft = |a: &[f64]| {
                        a.iter().enumerate().fold((0.0, 0.0), |(re, im), (k, x)| {
                            let (s, c) = (w * 0.02 * (k + 1) as f64).sin_cos();
                            (re + x * c, im - x * s)
                        })
                    };
                    let (x1, x2) = (dft(a1), dft(a2));
                    c.0 += x1.0 * x2.0 + x1.1 * x2.1;
                    c.1 += x1.1 * x2.0 - x1.0 * x2.1;
                    *q1 += x1.0 * x1.0 + x1.1 * x1.1;
                    *q2 += x2.0 * x2.0 + x2.1 * x2.1;
                }
            }
        }
        for b in 0..bands {
            let ls = (10 * b + 1)..=(10 * b + 10);
            let s: f64 = ls.clone().map(|l| filter.density(l as f64 * dw)).sum();
            let target: f64 = ls
                .map(|l| filter.density(l as f64 * dw) * coherency.gamma(l as f64 * dw, d))
                .sum::<f64>()
                / s;
            let got = cross[b].0.hypot(cross[b].1) / (p1[b] * p2[b]).sqrt();
            let se = ((1.0 - target * target) / 2000.0).sqrt();
            assert!(
                (got - target).abs() < 4.0 * se + 1e-3,
                "{:?}, band {b}: coherency {got} vs {target} (standard error {se})",
                coherency.kind()
            );
        }
    }
    // Two supports at one point move alike.
    let sp = Spatial {
        synthetic,
        coherency: Coherency::LucoWong { alpha: 2.5e-4 },
        positions: vec![50.0, 50.0],
    };
    let r = sp.records("c", 3).unwrap();
    assert_eq!(r[0].accelerations(), r[1].accelerations());
}
