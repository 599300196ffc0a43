//! The event-located integration against the exact relations, closed forms and conservation laws.

use crate::{damped_variants, formula, law, run};
use pounding::contact::{ContactModel, Damping, ForceLaw, Model, Phase, Tension, Turn};
use pounding::impact::{exact, simulate, BallDrop, ImpactOptions, ImpactSetup, TwoBodies};
use proptest::prelude::*;
use std::f64::consts::PI;

/// Hertz (n = 3/2) contact duration factor: `t_c = C d_max / v_i` with
/// `C = 2 sqrt(pi) Gamma(7/5) / Gamma(9/10)` (from `int_0^1 (1 - x^(5/2))^(-1/2) dx`); docs/contact-models.md
/// rounds it to 2.9433. Value from Python's `math.gamma`.
const HERTZ_DURATION: f64 = 2.943275184324706;

fn spec(model: Model, tension: Tension, k: f64, e: f64, n: Option<f64>) -> ContactModel {
    let s = formula(model, k, e).with_tension(tension);
    match n {
        Some(n) if !model.info().n_fixed => s.with_exponent(n).unwrap(),
        _ => s,
    }
}

proptest! {
    // 48 cases in CI; PROPTEST_CASES=N for a longer search.
    #![proptest_config(ProptestConfig::with_cases(
        std::env::var("PROPTEST_CASES").ok().and_then(|c| c.parse().ok()).unwrap_or(48)
    ))]

    /// e_post of the integrator equals the exact relation to 1e-8 for every model that has one, over random
    /// e, k, m, v and n; the exact relation itself does not depend on k, m, v or n.
    #[test]
    fn integrator_matches_exact_relations(
        e in 0.05f64..1.0, k in 1e6f64..1e11, m in 1.0f64..1e6, v in 0.01f64..10.0,
        n in 1.0f64..2.5, which in 0usize..16,
    ) {
        let variants = damped_variants();
        let (model, tension) = variants[which % variants.len()];
        prop_assume!(model != Model::Jankowski);
        let s = spec(model, tension, k, e, Some(n));
        let l = law(&s, m, v);
        let exact_e = exact::e_post(&l, tension, m, v).unwrap();
        // Hunt-Crossley results do not depend on n either; the bilinear loop's design does.
        let n_unit = (model == Model::ImpactMaterial).then_some(n);
        let unit = exact::e_post(&law(&spec(model, tension, 1.0, e, n_unit), 1.0, 1.0), tension, 1.0, 1.0).unwrap();
        prop_assert!((exact_e - unit).abs() <= 1e-12, "{} depends on k, m, v or n: {} vs {}", model, exact_e, unit);
        let r = run(&s, m, v);
        prop_assert!((r.e_post - exact_e).abs() <= 1e-8 * exact_e, "{} {:?}: integrated {} exact {}", model, tension, r.e_post, exact_e);
        if let Some(dm) = exact::max_penetration(&l, m, v) {
            prop_assert!((r.max_penetration - dm).abs() <= 1e-8 * dm);
        }
    }

    /// Energy: the work of the contact force equals the kinetic energy lost, m v^2 (1 - e^2) / 2; for two
    /// finite masses the impulse gives body velocities whose difference is the relative exit velocity and
    /// whose momentum is the initial one.
    #[test]
    fn energy_and_momentum(e in 0.1f64..1.0, m1 in 1.0f64..1e5, m2 in 1.0f64..1e5, v in 0.1f64..5.0, which in 0usize..16) {
        let variants = damped_variants();
        let (model, tension) = variants[which % variants.len()];
        let bodies = TwoBodies::new(m1, m2, v).unwrap();
        let m = bodies.effective_mass();
        let r = run(&spec(model, tension, 1e8, e, None), m, v);
        let lost = 0.5 * m * v * v * (1.0 - r.e_post * r.e_post);
        prop_assert!((r.dissipated_energy - lost).abs() <= 1e-8 * 0.5 * m * v * v);
        let (v1, v2) = bodies.velocities_after(r.impulse);
        prop_assert!(((v1 - v2) - r.v_out).abs() <= 1e-8 * v);
        prop_assert!((m1 * v1 + m2 * v2 - m1 * v).abs() <= 1e-12 * m1 * v);
    }
}

#[test]
fn elastic_linear_peak_force_and_duration() {
    // F_max = v sqrt(k m), t_c = pi sqrt(m / k).
    for (k, m, v) in [(1e9, 1e5, 1.0), (3.3e7, 12.0, 0.07)] {
        let r = run(&formula(Model::Hooke, k, 1.0), m, v);
        assert!((r.peak_force - v * (k * m).sqrt()).abs() < 1e-6 * r.peak_force);
        assert!((r.contact_duration - PI * (m / k).sqrt()).abs() < 1e-6 * r.contact_duration);
        assert!((r.e_post - 1.0).abs() < 1e-9);
    }
}

#[test]
fn elastic_hertz_peak_force_and_duration() {
    // d_max = (5 m v^2 / (4 k))^(2/5), F_max = k d_max^(3/2), t_c = 2.943275 d_max / v.
    for (k, m, v) in [(6.6e9, 10.0, 3.1), (1e9, 1e5, 0.5)] {
        let r = run(&formula(Model::Hertz, k, 1.0), m, v);
        let d = (5.0 * m * v * v / (4.0 * k)).powf(0.4);
        assert!((r.max_penetration - d).abs() < 1e-6 * d);
        assert!((r.peak_force - k * d.powf(1.5)).abs() < 1e-6 * r.peak_force);
        assert!((r.contact_duration - HERTZ_DURATION * d / v).abs() < 1e-6 * r.contact_duration);
    }
}

#[test]
fn tension_free_models_never_pull() {
    for (model, tension) in damped_variants() {
        if tension == Tension::Allow {
            continue;
        }
        for e in [0.05, 0.3, 0.65, 0.95] {
            let r = run(&formula(model, 1e9, e).with_tension(tension), 1e4, 1.0);
            let h = r.history.unwrap();
            assert!(
                h.force.iter().all(|&f| f >= 0.0),
                "{model} e={e} reports a tensile force"
            );
        }
    }
}

#[test]
fn kelvin_voigt_with_tension_pulls_before_separating() {
    // The classic model does pull late in restitution: its history must show it, not hide it.
    let r = run(&formula(Model::KelvinVoigt, 1e9, 0.5), 1e4, 1.0);
    assert!(r.history.unwrap().force.iter().any(|&f| f < 0.0));
}

#[test]
fn jankowski_exact_damping_by_integration() {
    for e in [0.2, 0.65, 0.9] {
        let s = ContactModel::new(Model::Jankowski, 1e9, e)
            .unwrap()
            .with_damping(Damping::Exact);
        let r = run(&s, 1e4, 1.0);
        assert!((r.e_post - e).abs() < 1e-9, "e={e}: {}", r.e_post);
    }
}

#[test]
fn ball_drop_with_gravity_conserves_energy_and_tends_to_the_no_gravity_result() {
    // A 0.1 m concrete ball from 0.5 m: gravity during contact changes e by a tiny amount, and the work of the
    // contact force equals the kinetic energy lost (the contact ends at d = 0, where gravity's work is zero).
    let drop = BallDrop::new(0.1, 30e9, 0.2, 2400.0, 0.5).unwrap();
    let (m, v) = (drop.mass(), drop.impact_velocity());
    let s = formula(Model::Hertzdamp, drop.hertz_stiffness(), 0.65);
    let l = law(&s, m, v);
    let opts = ImpactOptions::default();
    let with_g = simulate(&l, Tension::Clamp, &drop.setup(), &opts).unwrap();
    let without = simulate(&l, Tension::Clamp, &ImpactSetup::relative(m, v), &opts).unwrap();
    assert!((with_g.e_post - without.e_post).abs() < 1e-3);
    assert!(with_g.e_post != without.e_post);
    let lost = 0.5 * m * v * v * (1.0 - with_g.e_post.powi(2));
    assert!((with_g.dissipated_energy - lost).abs() < 1e-8 * 0.5 * m * v * v);
}

#[test]
fn bilinear_matches_its_parallelogram_closed_form() {
    let l = ForceLaw::Bilinear {
        k1: 5e8,
        k2: 1e8,
        d_y: 1e-3,
    };
    let r = simulate(
        &l,
        Tension::Clamp,
        &ImpactSetup::relative(1e3, 2.0),
        &ImpactOptions::default(),
    )
    .unwrap();
    let e = exact::bilinear_e_post(5e8, 1e8, 1e-3, 0.5 * 1e3 * 4.0);
    assert!((r.e_post - e).abs() < 1e-9 * e);
}

#[test]
fn history_holds_the_located_peak_force() {
    // A plot of the history must show the true peak: the largest force in it is `peak_force` itself, at
    // `time_of_peak_force`, with the state there (the force law evaluated on it gives the same force).
    for (model, tension) in damped_variants() {
        let spec = formula(model, 1e9, 0.65).with_tension(tension);
        let r = run(&spec, 1e4, 1.0);
        let h = r.history.as_ref().unwrap();
        assert!(
            h.t.windows(2).all(|w| w[0] < w[1]),
            "{model}: times not increasing"
        );
        let k = h.t.iter().position(|&t| t == r.time_of_peak_force).unwrap();
        assert_eq!(h.force[k], r.peak_force, "{model}");
        assert!(h.force.iter().all(|&f| f <= r.peak_force), "{model}");
        // The state stored at a peak in approach gives the same force through the force law.
        if h.rate[k] >= 0.0 {
            let f = law(&spec, 1e4, 1.0).force(
                h.penetration[k],
                h.rate[k],
                Phase::Approach,
                &Turn::default(),
            );
            assert!(
                (f - r.peak_force).abs() <= 1e-9 * r.peak_force,
                "{model}: {f} vs {}",
                r.peak_force
            );
        }
    }
}
