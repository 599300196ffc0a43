//! Required separation: the located largest closing of a run without contact, checked against that run's
//! sampled histories and against the contact run it predicts; the rules at their exact limits.

use pounding::analysis::{Building, RunOptions, Scenario};
use pounding::contact::{ContactModel, Model};
use pounding::ground_motion::Record;
use pounding::separation::separation;
use pounding::structure::ShearBuilding;

fn building(name: &str, m: f64, k: f64) -> Building {
    Building {
        name: name.into(),
        structure: ShearBuilding::new(vec![m, m], vec![k, k], vec![3.0, 3.0], 0.05).unwrap(),
    }
}

/// Two 2-storey buildings (periods about 0.8 and 1.3 s) under El Centro, a papi contact at both levels.
fn pair(k_right: f64, gap: f64) -> Scenario {
    Scenario::new(
        vec![building("L", 4e5, 1.0e8), building("R", 4e5, k_right)],
        Record::el_centro_1940(),
    )
    .unwrap()
    .with_link(
        "L",
        "R",
        gap,
        &ContactModel::new(Model::Papi, 2e9, 0.65).unwrap(),
        None,
    )
    .unwrap()
}

#[test]
fn the_required_gap_is_the_largest_closing_of_the_run_without_contact() {
    let s = pair(3.7e7, 0.02);
    let pairs = separation(&s, None, &RunOptions::default()).unwrap();
    assert_eq!(pairs.len(), 1);
    let levels = &pairs[0].levels;
    assert_eq!(levels.len(), 2);
    // The same run without contact, sampled every 1e-4 s (the step's quartic dense output): the largest
    // sample agrees with the closing located on each step's cubic Hermite interpolant within the
    // integration's accuracy (rtol 1e-7; the sampling error (w dt)^2 / 8 is about 1e-7 too).
    let free = s
        .without_contact()
        .with_output_dt(1e-4)
        .unwrap()
        .run()
        .unwrap();
    let h = &free.histories;
    for (f, level) in levels.iter().enumerate() {
        let sampled = (0..h.t.len())
            .map(|k| h.displacement[0][f][k] - h.displacement[1][f][k])
            .fold(0.0f64, f64::max);
        assert!(level.required_gap > 0.01, "{level:?}");
        assert!(
            (sampled - level.required_gap).abs() <= 1e-6 * level.required_gap,
            "{sampled} against {level:?}"
        );
        // No contact acted in that run.
        assert!(free.impacts.is_empty());
        // The rules bound each other as they must: DDC <= SRSS <= ABS (rho >= 0); and ABS bounds the
        // required gap exactly (u_L - u_R <= |u_L| + |u_R| at every instant).
        assert!(level.ddc <= level.srss && level.srss <= level.abs);
        assert!(level.required_gap <= level.abs);
    }
    // The peaks are those of the free run.
    assert_eq!(levels[1].peak_left, free.buildings[0].peak_displacement[1]);
}

#[test]
fn a_gap_just_above_the_required_one_never_closes_and_one_just_below_does() {
    let required = separation(&pair(3.7e7, 0.02), None, &RunOptions::default()).unwrap()[0]
        .levels
        .iter()
        .map(|l| l.required_gap)
        .fold(0.0, f64::max);
    let above = pair(3.7e7, required * 1.001).run().unwrap();
    assert_eq!(above.sites[0].impacts, 0);
    let below = pair(3.7e7, required * 0.999).run().unwrap();
    assert!(below.sites[0].impacts >= 1);
}

#[test]
fn identical_neighbours_move_together_and_the_ddc_says_so() {
    let s = pair(1.0e8, 0.0);
    let pairs = separation(&s, Some(0.7), &RunOptions::default()).unwrap();
    for level in &pairs[0].levels {
        // Same equations, same numbers: the floors never approach; rho = 1, so DDC = |pl - pr| = 0.
        assert_eq!(level.required_gap, 0.0);
        assert!((level.rho - 1.0).abs() < 1e-12);
        assert_eq!(level.peak_left, level.peak_right);
        assert!(level.ddc.abs() < 1e-9 * level.peak_left);
        // Floors at the same height: Eurocode 8's factor applies.
        assert_eq!(level.factor, 0.7);
        assert!((level.srss - 0.7 * level.peak_left * 2f64.sqrt()).abs() < 1e-12 * level.srss);
    }
    assert!(separation(&s, Some(1.5), &RunOptions::default()).is_err());
}
