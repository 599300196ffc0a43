//! Buildings on soil springs (soil–structure interaction): a storey on a foundation over the half-space against
//! an independent integration of its three equations, stiff soil against the fixed base, and the energy of a
//! pounding pair on soil.

use pounding::analysis::{Building, Scenario};
use pounding::contact::{ContactModel, Model};
use pounding::ground_motion::Record;
use pounding::structure::{Foundation, Shape, ShearBuilding, Soil};

const M: f64 = 5.0e5;
const H: f64 = 10.0;

fn storey(t: f64) -> ShearBuilding {
    let k = M * (2.0 * std::f64::consts::PI / t).powi(2);
    ShearBuilding::new(vec![M], vec![k], vec![H], 0.05).unwrap()
}

fn on_soil(vs: f64, m_f: f64) -> ShearBuilding {
    let soil = Soil::HalfSpace {
        vs,
        density: 1800.0,
        poisson: 0.33,
        shape: Shape::Disk(8.0),
    };
    storey(0.5)
        .with_foundation(Foundation::new(m_f, None, soil).unwrap())
        .unwrap()
}

/// Peaks of |w| (floor, relative to the free field) and |d| (the storey's drift, rocking left out) of the
/// storey on its foundation, by classical RK4 at a fixed step of 2e-6 s: the equations written out,
/// `m w'' = -m a_g - F`, `m_f u'' = -m_f a_g + F - K_x u - C_x u'`, `J theta'' = h F - K_t theta - C_t theta'`,
/// `F = k d + (a1 k + a0 m) d'`, `d = w - u - h theta` (Rayleigh of the fixed base, its mass part on the drift).
fn reference(b: &ShearBuilding, rec: &Record, t_end: f64) -> (f64, f64) {
    let f = b.foundation().unwrap();
    let k = b.stiffnesses()[0];
    let (a0, a1) = b.rayleigh();
    let c = a1 * k + a0 * M;
    let rhs = |t: f64, y: &[f64; 6]| -> [f64; 6] {
        let ag = rec.at(t);
        let [w, u, th, wv, uv, tv] = *y;
        let (d, dv) = (w - u - H * th, wv - uv - H * tv);
        let force = k * d + c * dv;
        [
            wv,
            uv,
            tv,
            -ag - force / M,
            -ag + (force - f.kx * u - f.cx * uv) / f.mass,
            (H * force - f.ktheta * th - f.ctheta * tv) / f.inertia,
        ]
    };
    let h = 2e-6;
    let mut y = [0.0; 6];
    let (mut pw, mut pd) = (0.0f64, 0.0f64);
    let steps = (t_end / h).round() as usize;
    for s in 0..steps {
        let t = s as f64 * h;
        let k1 = rhs(t, &y);
        let add = |y: &[f64; 6], k: &[f64; 6], a: f64| -> [f64; 6] {
            std::array::from_fn(|i| y[i] + a * k[i])
        };
        let k2 = rhs(t + h / 2.0, &add(&y, &k1, h / 2.0));
        let k3 = rhs(t + h / 2.0, &add(&y, &k2, h / 2.0));
        let k4 = rhs(t + h, &add(&y, &k3, h));
        y = std::array::from_fn(|i| y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]));
        pw = pw.max(y[0].abs());
        pd = pd.max((y[0] - y[1] - H * y[2]).abs());
    }
    (pw, pd)
}

#[test]
fn a_storey_on_soil_is_its_three_equations() {
    let rec = Record::el_centro_1940();
    let t_end = 4.0;
    for vs in [100.0, 250.0] {
        let b = on_soil(vs, 2.0e5);
        let (pw, pd) = reference(&b, &rec, t_end);
        for (tol, within) in [(1e-7, 2e-5), (1e-10, 1e-7)] {
            let s = Scenario::new(
                vec![Building {
                    name: "A".into(),
                    structure: b.clone(),
                }],
                rec.clone(),
            )
            .unwrap()
            .with_duration(t_end)
            .unwrap()
            .with_tolerance(tol)
            .unwrap();
            let r = s.run().unwrap();
            let resp = &r.buildings[0];
            let (w, d) = (resp.peak_displacement[0], resp.peak_drift[0]);
            assert!(
                (w / pw - 1.0).abs() < within,
                "V_s {vs}, tol {tol}: w {w} vs {pw}"
            );
            assert!(
                (d / pd - 1.0).abs() < within,
                "V_s {vs}, tol {tol}: d {d} vs {pd}"
            );
            let f = resp.foundation.as_ref().unwrap();
            assert!(f.peak_sway > 0.0 && f.peak_rocking > 0.0);
            if vs == 100.0 {
                // Its foundation's fast modes would split each interval into many series-length steps; each
                // of the 200 is one step (`engine/exact.rs`, `Whole`: the configuration the run starts in is
                // built at its first interval), its peaks located inside on the chain of pieces, and still
                // within 1e-7 of the reference at 1e-10.
                assert_eq!(
                    r.statistics.steps, 200,
                    "V_s {vs}, tol {tol}: one step per record interval"
                );
            }
            assert!(
                r.energy.relative_error < 1e-6,
                "{}",
                r.energy.relative_error
            );
        }
    }
}

/// On stiff soil (V_s = 3e4 m/s: a period 1.00005 times the fixed base's) the storey is the fixed-base one:
/// peaks within 1e-5 at the default tolerance, and within the physical difference at 1e-10.
#[test]
fn stiff_soil_is_the_fixed_base() {
    let rec = Record::el_centro_1940();
    let run = |b: ShearBuilding, tol: f64| {
        Scenario::new(
            vec![Building {
                name: "A".into(),
                structure: b,
            }],
            rec.clone(),
        )
        .unwrap()
        .with_duration(4.0)
        .unwrap()
        .with_tolerance(tol)
        .unwrap()
        .run()
        .unwrap()
    };
    let soil = on_soil(3.0e4, 5.0e5);
    let flex = soil.flexible_modes().unwrap().omega[0];
    let fixed = storey(0.5).modes().omega[0];
    assert!((fixed / flex - 1.0).abs() < 1e-4, "{}", fixed / flex);
    for tol in [1e-7, 1e-10] {
        let (a, b) = (run(storey(0.5), tol), run(soil.clone(), tol));
        let (x, y) = (a.buildings[0].peak_drift[0], b.buildings[0].peak_drift[0]);
        assert!((x / y - 1.0).abs() < 1e-5, "tol {tol}: {x} vs {y}");
    }
}

/// Two buildings on soft soil (periods 0.4 and 0.8 s fixed; V_s 150 and 250 m/s) 10 mm apart, Hertz-damped,
/// under El Centro for 8 s.
fn soil_pair() -> Scenario {
    let b = |name: &str, t: f64, vs: f64| {
        let soil = Soil::HalfSpace {
            vs,
            density: 1800.0,
            poisson: 0.4,
            shape: Shape::Rectangle(12.0, 10.0),
        };
        let k = M * (2.0 * std::f64::consts::PI / t).powi(2);
        let st = ShearBuilding::new(vec![M, M], vec![k, 0.8 * k], vec![3.5, 3.0], 0.05)
            .unwrap()
            .with_foundation(Foundation::new(4.0e5, None, soil).unwrap())
            .unwrap();
        Building {
            name: name.into(),
            structure: st,
        }
    };
    Scenario::new(
        vec![b("A", 0.4, 150.0), b("B", 0.8, 250.0)],
        Record::el_centro_1940(),
    )
    .unwrap()
    .with_duration(8.0)
    .unwrap()
    .with_link(
        "A",
        "B",
        0.01,
        &ContactModel::new(Model::Hertzdamp, 2.0e10, 0.65).unwrap(),
        None,
    )
    .unwrap()
}

/// `s` run as it is (its foundations' fast modes would split each record interval into 16 series-length
/// steps: the open stretches go a whole interval at a time, `engine/exact.rs`, `Whole`; the rest of an
/// interval after an impact in blocks of pieces; the impacts stepped) against `s` stepped throughout: the
/// energy balances to 1e-6; the same impacts, peaks and forces within the tolerance's reach (1e-5), and
/// fewer than half the steps.
fn whole_intervals_are_the_stepped_run(s: &Scenario) {
    let r = s.run().unwrap();
    assert!(!r.impacts.is_empty());
    assert!(
        r.energy.relative_error < 1e-6,
        "{}",
        r.energy.relative_error
    );
    let stepped = s
        .clone()
        .with_propagation(pounding::engine::Propagation::Stepping)
        .run()
        .unwrap();
    assert_eq!(r.impacts.len(), stepped.impacts.len());
    for (a, b) in r.buildings.iter().zip(&stepped.buildings) {
        let pairs = a
            .peak_displacement
            .iter()
            .zip(&b.peak_displacement)
            .chain(a.peak_drift.iter().zip(&b.peak_drift))
            .chain(
                a.peak_absolute_acceleration
                    .iter()
                    .zip(&b.peak_absolute_acceleration),
            );
        for (x, y) in pairs {
            assert!((x - y).abs() <= 1e-5 * y, "{} vs {}", x, y);
        }
        let (fa, fb) = (
            a.foundation.as_ref().unwrap(),
            b.foundation.as_ref().unwrap(),
        );
        for (x, y) in [
            (fa.peak_sway, fb.peak_sway),
            (fa.peak_rocking, fb.peak_rocking),
        ] {
            assert!((x - y).abs() <= 1e-5 * y, "{} vs {}", x, y);
        }
    }
    for (a, b) in r.impacts.iter().zip(&stepped.impacts) {
        assert!((a.peak_force - b.peak_force).abs() <= 1e-5 * b.peak_force);
        assert!((a.time - b.time).abs() < 1e-5);
    }
    assert!(
        2 * r.statistics.steps < stepped.statistics.steps,
        "{} vs {}",
        r.statistics.steps,
        stepped.statistics.steps
    );
}

/// Two buildings on soft soil pounding: the energy balances to 1e-6, the soil's dashpots dissipating; whole
/// intervals give the stepped run.
#[test]
fn a_pair_on_soil_pounding_balances_its_energy() {
    let s = soil_pair();
    whole_intervals_are_the_stepped_run(&s);
    // nu = 0.4 > 1/3: the rocking dashpot uses 2 V_s and a trapped inertia joins the foundation's.
    let f = s.buildings()[0].structure.foundation().unwrap();
    assert!(f.inertia > 4.0e5 * 12.0 * 12.0 / 12.0);
}

/// The same pair with B on a support the wave reaches 0.2 s later (ten record steps: its intervals stay whole):
/// whole intervals carry the work the supports do through the contact (the forms of `engine/forms.rs`), and
/// still give the stepped run.
#[test]
fn a_pair_on_soil_under_wave_passage_is_the_stepped_run() {
    let s = soil_pair()
        .with_support("far", Record::el_centro_1940().delayed(0.2).unwrap())
        .unwrap()
        .with_building_on("B", "far")
        .unwrap();
    whole_intervals_are_the_stepped_run(&s);
}

/// The energies a history reads inside a whole interval are the same whether the stepper read the
/// interval's Gauss nodes as it went (every interval sampled, output every 0.01 s) or left them for the
/// reader (one interval in two or three sampled, every 0.05 s: the nodes of an interval after an unsampled
/// one are found when the sample asks). At the common times, within rounding of the largest energy.
#[test]
fn energies_inside_whole_intervals_do_not_depend_on_which_were_sampled() {
    let run = |dt: f64| soil_pair().with_output_dt(dt).unwrap().run().unwrap();
    let (every, some) = (run(0.01), run(0.05));
    let largest = every.histories.energy[0]
        .iter()
        .fold(0.0f64, |a, &e| a.max(e.abs()));
    let mut compared = 0;
    for (k, (a, b)) in every
        .histories
        .energy
        .iter()
        .zip(&some.histories.energy)
        .enumerate()
    {
        for (j, y) in b.iter().enumerate() {
            let x = a[5 * j];
            assert!(
                (x - y).abs() <= 1e-12 * largest,
                "energy {k} at {} s: {x} vs {y}",
                0.05 * j as f64
            );
            compared += 1;
        }
    }
    assert!(compared > 6 * 150, "{compared}");
}
