//! Restitution that depends on the impact velocity (issue 24): a table e(v_i) calibrated per impact, and the
//! Hunt–Crossley law with a material damping constant. Expected values: next-physics.md section 1 (computed
//! there independently of this code) and linear interpolation of the table written out here.

use pounding::contact::{ContactModel, Model, Restitution, RestitutionTable};
use pounding::impact::{simulate, ImpactOptions, ImpactSetup};

/// The e delivered by one integrated impact of `spec` between free bodies of masses `m1`, `m2` at `v` (m/s).
fn delivered(spec: &ContactModel, m1: f64, m2: f64, v: f64) -> f64 {
    let m = if m2.is_finite() {
        m1 * m2 / (m1 + m2)
    } else {
        m1
    };
    let (law, _) = spec.prepare().unwrap().law(m, v).unwrap();
    let setup = ImpactSetup::relative(m, v);
    let opts = ImpactOptions {
        rtol: 1e-12,
        history: false,
    };
    simulate(&law, spec.tension(), &setup, &opts)
        .unwrap()
        .e_post
}

#[test]
fn a_damping_constant_delivers_the_published_e_for_any_exponent_and_masses() {
    let want = [
        (0.05, 0.990099),
        (0.1, 0.980391),
        (0.2, 0.961533),
        (0.5, 0.909016),
        (1.0, 0.832870),
        (2.0, 0.711950),
        (3.0, 0.619736),
    ];
    for n in [1.0, 1.5] {
        for (m1, m2) in [(1.0e5, 1.0e5), (7.0, 3.0), (2.0e6, 5.0e4)] {
            let spec = ContactModel::new(Model::HuntCrossley, 3.0e9, 0.5)
                .unwrap()
                .with_exponent(n)
                .unwrap()
                .with_restitution(Restitution::DampingConstant(0.3))
                .unwrap();
            for (v, e) in want {
                let got = delivered(&spec, m1, m2, v);
                assert!(
                    (got - e).abs() < 1e-6,
                    "n {n}, m {m1}/{m2}, v {v}: {got} vs {e}"
                );
            }
        }
    }
}

#[test]
fn a_table_calibrates_each_impact_to_its_own_e() {
    let rows = [(0.1, 0.8), (0.5, 0.65), (2.0, 0.5)];
    // Linear between rows, held beyond them.
    let interpolated = |v: f64| -> f64 {
        if v <= 0.1 {
            0.8
        } else if v <= 0.5 {
            0.8 + (0.65 - 0.8) * (v - 0.1) / 0.4
        } else if v <= 2.0 {
            0.65 + (0.5 - 0.65) * (v - 0.5) / 1.5
        } else {
            0.5
        }
    };
    let table = Restitution::Table(RestitutionTable::new(rows.to_vec()).unwrap());
    for model in [
        Model::Papi,
        Model::Hertzdamp,
        Model::KelvinVoigt,
        Model::Jankowski,
    ] {
        let spec = ContactModel::new(model, 2.0e9, 0.5)
            .unwrap()
            .with_restitution(table.clone())
            .unwrap();
        for v in [0.05, 0.1, 0.3, 0.5, 1.2, 2.0, 4.0] {
            let got = delivered(&spec, 1.0e5, 2.0e5, v);
            let want = interpolated(v);
            assert!(
                (got - want).abs() < 1e-8,
                "{model:?} at v {v}: {got} vs {want}"
            );
        }
    }
}

#[test]
fn what_cannot_be_asked_is_refused_naming_the_key() {
    let dk = Restitution::DampingConstant(0.3);
    // A damping constant belongs to the Hunt–Crossley family; a table to a damped model.
    let e = ContactModel::new(Model::Papi, 1e9, 0.5)
        .unwrap()
        .with_restitution(dk.clone());
    let e = e.unwrap_err().to_string();
    assert!(
        e.starts_with("damping_constant = 0.3 is not allowed") && e.ends_with("not papi"),
        "{e}"
    );
    let t = Restitution::Table(RestitutionTable::new(vec![(1.0, 0.6)]).unwrap());
    let e = ContactModel::new(Model::Hooke, 1e9, 1.0)
        .unwrap()
        .with_restitution(t);
    let e = e.unwrap_err().to_string();
    assert!(
        e.starts_with("e.table = 1 row is not allowed: only with a damped model, not hooke"),
        "{e}"
    );
    let e = Restitution::damping_constant(-0.1).unwrap_err().to_string();
    assert!(
        e.starts_with("damping_constant = -0.1 is not allowed"),
        "{e}"
    );
}

/// Thornton (1997) elastic–perfectly-plastic spheres: e = 1 up to the yield velocity, then the check values
/// of next-physics.md section 1 (Thornton's closed form, recomputed there), which the exact energy balance
/// of the law (`exact::e_post`) and the integrated impact both reproduce.
#[test]
fn thornton_spheres_deliver_the_closed_form_e() {
    use pounding::contact::exact;
    let (r, p_y, k) = (0.1, 1.0e8, 2.0e10);
    let spec = ContactModel::new(Model::Thornton, k, 1.0)
        .unwrap()
        .with_sphere(r, p_y)
        .unwrap();
    for m in [100.0, 3.0e4] {
        // v_y: the impact velocity whose Hertz energy reaches first yield, (2/5) F_y d_y = m v_y^2 / 2.
        let e_star = 0.75 * k / f64::sqrt(r);
        let d_y = r * (std::f64::consts::PI * p_y / (2.0 * e_star)).powi(2);
        let f_y = k * d_y.powf(1.5);
        let v_y = (2.0 * 0.4 * f_y * d_y / m).sqrt();
        for (ratio, e) in [
            (0.5, 1.0),
            (1.0, 1.0),
            (1.5, 0.971239),
            (2.0, 0.930626),
            (5.0, 0.773337),
            (10.0, 0.658558),
            (20.0, 0.557109),
            (50.0, 0.444606),
            (100.0, 0.374299),
        ] {
            let v = ratio * v_y;
            let (law, _) = spec.prepare().unwrap().law(m, v).unwrap();
            let closed = exact::e_post(&law, spec.tension(), m, v).unwrap();
            let integrated = delivered(&spec, m, f64::INFINITY, v);
            assert!(
                (closed - e).abs() < 1e-6,
                "m {m}, v/v_y {ratio}: {closed} vs {e}"
            );
            assert!(
                (integrated - closed).abs() < 1e-6,
                "m {m}, v/v_y {ratio}: {integrated} vs {closed}"
            );
            let d_max = exact::max_penetration(&law, m, v).unwrap();
            assert!(d_max > 0.0);
        }
    }
}
