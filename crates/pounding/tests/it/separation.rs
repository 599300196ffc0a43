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

/// Two SDOFs (T = 0.5 and 1.0 s, 5 %) under white noise S0 = 0.01 m^2/s^3 for 20 s: the check values of
/// next-physics.md section 2 (recomputed there from the closed forms: each oscillator's variance
/// pi S0 / (2 z w^3), their correlation the CQC rho, Rice and Poisson).
fn two_sdofs(gap: f64) -> Scenario {
    let m = 1.0e5;
    let k = |t: f64| m * (2.0 * std::f64::consts::PI / t).powi(2);
    let one = |name: &str, t: f64| Building {
        name: name.into(),
        structure: ShearBuilding::new(vec![m], vec![k(t)], vec![3.0], 0.05).unwrap(),
    };
    Scenario::new(vec![one("A", 0.5), one("B", 1.0)], Record::el_centro_1940())
        .unwrap()
        .with_link(
            "A",
            "B",
            gap,
            &ContactModel::new(Model::Papi, 2e9, 0.65).unwrap(),
            None,
        )
        .unwrap()
}

#[test]
fn white_noise_gives_the_closed_form_closing_and_probabilities() {
    use pounding::separation::random::{pounding_probability, Clumping, WhiteNoise};
    let noise = WhiteNoise {
        s0: 0.01,
        filter: None,
    };
    let rel = |a: f64, b: f64| (a - b).abs() / b.abs();
    for (gap, p) in [(0.06, 0.998361), (0.08, 0.906840), (0.10, 0.483727)] {
        let pairs =
            pounding_probability(&two_sdofs(gap), &noise, 20.0, None, Clumping::Poisson).unwrap();
        let l = &pairs[0].levels[0];
        assert!(rel(l.crossing.sigma, 3.752697e-2) < 1e-6, "{l:?}");
        assert!(rel(l.crossing.sigma_rate, 0.2714642) < 1e-6, "{l:?}");
        assert!(rel(l.crossing.nu0, 1.151302) < 1e-6, "{l:?}");
        assert!(
            rel(l.probability, p) < 1e-5,
            "gap {gap}: {} vs {p}",
            l.probability
        );
    }
    for (p, gap) in [(0.5, 0.099332), (0.1, 0.123178), (0.01, 0.147618)] {
        let pairs =
            pounding_probability(&two_sdofs(0.05), &noise, 20.0, Some(p), Clumping::Poisson)
                .unwrap();
        let g = pairs[0].levels[0].gap_for_target.unwrap();
        assert!(rel(g, gap) < 1e-5, "P {p}: {g} vs {gap}");
        // Clumped crossings are fewer: the same target needs less gap, and the gap's probability is lower.
        let v = pounding_probability(&two_sdofs(gap), &noise, 20.0, Some(p), Clumping::Vanmarcke)
            .unwrap();
        let l = &v[0].levels[0];
        let delta = l.crossing.delta.unwrap();
        assert!(delta > 0.0 && delta < 1.0, "{delta}");
        assert!(l.gap_for_target.unwrap() < g && l.probability < p, "{l:?}");
    }
}

/// The codes on the two SDOFs under a flat design spectrum Sa = 2 m/s^2 (floors at one height): elastic
/// displacements Sa / w^2 = 0.0126651 and 0.0506606 m; next-physics.md section 3's check values.
#[test]
fn the_codes_rules_on_two_sdofs_under_a_flat_spectrum() {
    use pounding::separation::codes::{code_gaps, CodeRule, DesignSpectrum, GbSystem};
    let s = two_sdofs(0.05);
    let flat = DesignSpectrum::Table(vec![(0.0, 2.0), (10.0, 2.0)]);
    let gap = |rule| code_gaps(&s, rule, Some(&flat)).unwrap()[0].2[0].clone();
    let l = gap(CodeRule::Asce7_22 { cd: 5.5, ie: 1.0 });
    let (dl, dr) = l.elastic.unwrap();
    assert!(
        (dl - 0.0126651).abs() < 1e-7 && (dr - 0.0506606).abs() < 1e-7,
        "{l:?}"
    );
    assert!(l.aligned);
    for (rule, want) in [
        (CodeRule::Asce7_22 { cd: 5.5, ie: 1.0 }, 0.287209),
        (CodeRule::En1998_1 { q: 3.9, qd: 3.9 }, 0.142560),
        (CodeRule::Is1893_2016 { r: 5.0 }, 0.158314),
    ] {
        let g = gap(rule).code_required_gap;
        assert!((g / want - 1.0).abs() < 1e-5, "{rule:?}: {g} vs {want}");
    }
    // GB 50011: the lower building is 3 m tall: 100 mm whatever the intensity and system.
    let g = gap(CodeRule::Gb50011_2010 {
        intensity: 9,
        system: GbSystem::Frame,
    });
    assert_eq!(g.code_required_gap, 0.1);
}
