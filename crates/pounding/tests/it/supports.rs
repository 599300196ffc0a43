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
