//! Inelastic storeys through the engine: the force–drift loops against their analytic forms (bilinear
//! kinematic hardening by an independent return map; Bouc–Wen with n = 1 by its closed form on each monotone
//! branch), the energy balance with hysteresis, and the relations the new responses must satisfy.

use crate::buildings::building;
use pounding::analysis::Scenario;
use pounding::contact::{ContactModel, Damping, Model};
use pounding::element::{Element, End, StoreyLaw};
use pounding::engine::{self, Dof, Ground, Observer, Segment, Settings, System};
use pounding::ground_motion::Record;

/// A slow cyclic ground acceleration of growing amplitude: `a_g = a (t / 20) sin(2 pi t / 2)`, m/s^2, for
/// 20 s (a period four times the oscillator's).
fn slow_cycles(a: f64) -> Record {
    let dt = 0.01;
    let acc = (0..=2000)
        .map(|i| {
            let t = i as f64 * dt;
            a * (t / 20.0) * (std::f64::consts::PI * t).sin()
        })
        .collect();
    Record::new("slow cycles", dt, 0.0, acc).unwrap()
}

/// Every node of a run (step ends and events): drift, its rate, the storey force and the storey's states.
#[derive(Default)]
struct Nodes(Vec<(f64, f64, f64, Vec<f64>)>);

impl Observer for Nodes {
    fn segment(&mut self, seg: &Segment<'_, '_>) {
        let sys = seg.system;
        let (x, v) = sys.deformation(0, seg.y1);
        let s = seg.y1[sys.layout().block(0)].to_vec();
        self.0.push((x, v, sys.element_force(0, seg.y1), s));
    }
}

/// A 0.5 s oscillator (m = 5e5 kg, k = 7.8957e7 N/m, 2 % viscous damping on the drift rate) on a storey of
/// `law`, run through the engine at relative tolerance 1e-10; its nodes.
fn oscillator(law: StoreyLaw, record: &Record) -> Vec<(f64, f64, f64, Vec<f64>)> {
    let (m, k): (f64, f64) = (5.0e5, 7.8957e7);
    let c = 2.0 * 0.02 * (k * m).sqrt();
    let mut sys = System::new(
        &[Dof::x(m, 0.0)],
        vec![Element::new(End::Dof(0), End::Ground, law.law(k)).with_dashpot(c)],
        Ground::Record(record),
    );
    let l = sys.layout().clone();
    let rtol = 1e-10;
    let mut atol = vec![rtol * 1e6; l.dim()];
    atol[l.u(0)] = rtol * 0.01;
    atol[l.v(0)] = rtol * 0.1;
    if let Some(z) = l.block(0).next() {
        atol[z] = rtol;
    }
    let settings = Settings {
        t_end: record.duration(),
        rtol,
        atol,
        h0: 1e-4,
        max_steps: 10_000_000,
        propagation: pounding::engine::Propagation::default(),
    };
    let mut nodes = Nodes::default();
    engine::run(&mut sys, (0.0, &vec![0.0; l.dim()]), &settings, &mut nodes).unwrap();
    nodes.0
}

#[test]
fn bilinear_loop_through_the_engine_is_the_kinematic_hardening_loop() {
    // F_y = 1e6 N (d_y = 12.7 mm) and a = 0.1: the growing cycles yield in both directions many times.
    let (k, fy, a) = (7.8957e7, 1.0e6, 0.1);
    let nodes = oscillator(StoreyLaw::bilinear(fy, a).unwrap(), &slow_cycles(8.0));
    // Independent return map (Simo & Hughes, Computational Inelasticity, section 1.3): back-force q with
    // hardening modulus H = a k / (1 - a). It is exact between nodes on which the drift is monotone while
    // yielding, which the located reversals guarantee.
    let h = a * k / (1.0 - a);
    let (mut f, mut q, mut x_prev) = (0.0f64, 0.0f64, 0.0);
    let (mut yielded, mut reversals, mut worst) = (0, 0, 0.0f64);
    let mut was_plastic = false;
    for (x, _, f_engine, _) in &nodes {
        let trial = f + k * (x - x_prev);
        let over = (trial - q).abs() - fy;
        let plastic = over > 0.0;
        if plastic {
            let dl = over / (k + h);
            let sgn = (trial - q).signum();
            f = trial - k * dl * sgn;
            q += h * dl * sgn;
            yielded += 1;
        } else {
            f = trial;
            if was_plastic {
                reversals += 1;
            }
        }
        was_plastic = plastic;
        x_prev = *x;
        worst = worst.max((f - f_engine).abs());
    }
    assert!(yielded > 100 && reversals > 10, "{yielded} {reversals}");
    assert!(worst < 1e-8 * fy, "largest difference {worst} N");
}

/// Bouc–Wen z after a monotone drift increment `dx` from `z0` (n = 1, A = 1): on each branch
/// `dz/dx = (1 - c z) / d_y` with `c = beta + gamma` while `z` has the sign of the increment and
/// `c = beta - gamma` before, so `z = (1 - (1 - c z0) exp(-c dx / d_y)) / c`.
fn bouc_wen_n1(z0: f64, dx: f64, dy: f64, beta: f64, gamma: f64) -> f64 {
    if dx < 0.0 {
        return -bouc_wen_n1(-z0, -dx, dy, beta, gamma);
    }
    let branch = |z0: f64, dx: f64, c: f64| {
        if c == 0.0 {
            z0 + dx / dy
        } else {
            (1.0 - (1.0 - c * z0) * (-c * dx / dy).exp()) / c
        }
    };
    if z0 >= 0.0 {
        return branch(z0, dx, beta + gamma);
    }
    let c = beta - gamma;
    // The increment that brings z to 0 on the first branch.
    let to_zero = if c == 0.0 {
        -z0 * dy
    } else {
        dy * (1.0 - c * z0).ln() / c
    };
    if dx <= to_zero {
        branch(z0, dx, c)
    } else {
        branch(0.0, dx - to_zero, beta + gamma)
    }
}

#[test]
fn bouc_wen_loop_through_the_engine_is_its_closed_form() {
    let (k, fy, a) = (7.8957e7, 1.0e6, 0.1);
    for (beta, gamma) in [(0.5, 0.5), (0.75, 0.25), (0.9, -0.1)] {
        let law = StoreyLaw::bouc_wen(fy, a, 1.0, beta, gamma).unwrap();
        let nodes = oscillator(law, &slow_cycles(8.0));
        let dy = fy / k;
        let (mut z, mut x_prev) = (0.0, 0.0);
        let (mut worst_z, mut worst_f, mut z_max) = (0.0f64, 0.0f64, 0.0f64);
        for (x, _, f_engine, s) in &nodes {
            z = bouc_wen_n1(z, x - x_prev, dy, beta, gamma);
            x_prev = *x;
            worst_z = worst_z.max((z - s[0]).abs());
            worst_f = worst_f.max((a * k * x + (1.0 - a) * fy * z - f_engine).abs());
            z_max = z_max.max(z.abs());
        }
        // The cycles reach well into the hysteretic range, and z never exceeds its bound.
        let bound = 1.0 / (beta + gamma);
        assert!(
            z_max > 0.9 * bound && z_max <= bound * (1.0 + 1e-9),
            "{z_max}"
        );
        assert!(
            worst_z < 1e-7,
            "beta {beta} gamma {gamma}: z off by {worst_z}"
        );
        assert!(worst_f < 1e-7 * fy, "force off by {worst_f} N");
    }
}

/// The three-storey building beside the eight-storey one of `examples/three-vs-eight-storey.toml`, with
/// the storeys of `laws` (one for each building) and hertzdamp contact at 40 mm.
fn three_vs_eight(laws: [&dyn Fn(usize) -> StoreyLaw; 2]) -> Scenario {
    let mut b3 = building("3", &[4.0e5, 4.0e5, 3.5e5], &[6.0e8, 5.0e8, 4.0e8], 0.05);
    let mut b8 = building(
        "8",
        &[4.0e5, 4.0e5, 4.0e5, 4.0e5, 4.0e5, 4.0e5, 4.0e5, 3.0e5],
        &[2.6e8, 2.4e8, 2.2e8, 2.0e8, 1.8e8, 1.6e8, 1.4e8, 1.2e8],
        0.05,
    );
    b3.structure = b3
        .structure
        .with_storey_laws((0..3).map(laws[0]).collect())
        .unwrap();
    b8.structure = b8
        .structure
        .with_storey_laws((0..8).map(laws[1]).collect())
        .unwrap();
    // The published damping formula, as the OpenSees model of the comparison has it.
    let contact = ContactModel::new(Model::Hertzdamp, 2.0e10, 0.65)
        .unwrap()
        .with_damping(Damping::Formula);
    Scenario::new(vec![b3, b8], Record::el_centro_1940())
        .unwrap()
        .with_link("3", "8", 0.04, &contact, None)
        .unwrap()
        .with_duration(20.0)
        .unwrap()
}

#[test]
fn inelastic_pounding_closes_its_energy_balance() {
    let fy3 = [4.5e6, 4.0e6, 4.0e6];
    let fy8 = [2.5e6, 2.5e6, 2.5e6, 3.0e6, 3.5e6, 4.0e6, 4.0e6, 4.0e6];
    let bilinear = three_vs_eight([&|j| StoreyLaw::bilinear(fy3[j], 0.05).unwrap(), &|j| {
        StoreyLaw::bilinear(fy8[j], 0.05).unwrap()
    }]);
    let bouc_wen = three_vs_eight([
        &|j| StoreyLaw::bouc_wen(fy3[j], 0.05, 1.0, 0.5, 0.5).unwrap(),
        &|j| StoreyLaw::bouc_wen(fy8[j], 0.05, 2.0, 0.5, 0.5).unwrap(),
    ]);
    for s in [bilinear, bouc_wen] {
        let r = s.run().unwrap();
        let e = &r.energy;
        assert!(
            e.relative_error < 1e-6,
            "balance error {}",
            e.relative_error
        );
        assert!(!r.impacts.is_empty());
        // Storeys yield: hysteresis dissipates a real share of the input, and it is the sum of the storeys'.
        assert!(e.end.hysteretic > 0.05 * e.end.input, "{e:?}");
        let sum: f64 = r
            .buildings
            .iter()
            .flat_map(|b| b.hysteretic_energy.iter())
            .sum();
        assert!((sum - e.end.hysteretic).abs() <= 1e-9 * e.end.hysteretic);
        let yielded = r
            .buildings
            .iter()
            .flat_map(|b| b.ductility.iter().flatten());
        assert!(yielded.clone().any(|mu| *mu > 1.0));
        // The energy history ends where the balance does.
        let h = &r.histories;
        assert!((h.energy[4].last().unwrap() - e.end.hysteretic).abs() <= 1e-9 * e.end.hysteretic);
    }
}

#[test]
fn bilinear_storeys_that_never_yield_are_linear() {
    let linear = three_vs_eight([&|_| StoreyLaw::Linear, &|_| StoreyLaw::Linear]);
    let never = three_vs_eight([&|_| StoreyLaw::bilinear(1e20, 0.05).unwrap(), &|_| {
        StoreyLaw::bilinear(1e20, 0.05).unwrap()
    }]);
    let (a, b) = (linear.run().unwrap(), never.run().unwrap());
    for (ba, bb) in a.buildings.iter().zip(&b.buildings) {
        for (x, y) in ba.peak_displacement.iter().zip(&bb.peak_displacement) {
            assert!((x - y).abs() <= 1e-12 * x, "{x} vs {y}");
        }
        assert!(bb.hysteretic_energy.iter().all(|h| *h == 0.0));
        assert!(bb.ductility.iter().flatten().all(|mu| *mu < 1e-10));
    }
    assert_eq!(a.impacts.len(), b.impacts.len());
}

#[test]
fn linear_storey_shear_is_stiffness_times_drift_and_acceleration_is_absolute() {
    let s = three_vs_eight([&|_| StoreyLaw::Linear, &|_| StoreyLaw::Linear]);
    let r = s.run().unwrap();
    for (b, resp) in s.buildings().iter().zip(&r.buildings) {
        for (k, (v, d)) in b
            .structure
            .stiffnesses()
            .iter()
            .zip(resp.peak_storey_shear.iter().zip(&resp.peak_drift))
        {
            assert!((v - k * d).abs() <= 1e-12 * v, "{v} vs {}", k * d);
        }
        assert!(resp.ductility.iter().all(Option::is_none));
        // Residual drift is the difference of residual displacements.
        let u = &resp.residual_displacement;
        assert!((resp.residual_drift[1] - (u[1] - u[0])).abs() < 1e-15);
    }
    // An undamped SDOF without contact: u'' + a_g = -w^2 u, so the peak absolute acceleration is w^2 times
    // the peak displacement (to the spacing of the integration nodes, where accelerations are read).
    let (m, k): (f64, f64) = (5.0e5, 7.8957e7);
    let s = Scenario::new(
        vec![building("sdof", &[m], &[k], 0.0)],
        Record::el_centro_1940(),
    )
    .unwrap();
    let r = s.run().unwrap();
    let b = &r.buildings[0];
    let ratio = b.peak_absolute_acceleration[0] / (k / m * b.peak_displacement[0]);
    assert!((ratio - 1.0).abs() < 1e-3, "{ratio}");
    // The history agrees at every sample.
    let h = &r.histories;
    for (a, u) in h.absolute_acceleration[0][0]
        .iter()
        .zip(&h.displacement[0][0])
    {
        assert!((a + k / m * u).abs() <= 1e-9 * b.peak_absolute_acceleration[0]);
    }
}

/// `bench/opensees/scenarios-inelastic/{bilinear,bouc-wen}-sdof.toml`: the hertzdamp two-SDOF pair with
/// inelastic storeys (F_y 2.5e6 and 1.2e6 N, a = 0.05).
fn inelastic_sdof_pair(law: &dyn Fn(f64) -> StoreyLaw) -> Scenario {
    let mut l = building("left", &[5.0e5], &[7.8957e7], 0.05);
    let mut r = building("right", &[5.0e5], &[1.9739e7], 0.05);
    l.structure = l.structure.with_storey_laws(vec![law(2.5e6)]).unwrap();
    r.structure = r.structure.with_storey_laws(vec![law(1.2e6)]).unwrap();
    Scenario::new(vec![l, r], Record::el_centro_1940())
        .unwrap()
        .with_link(
            "left",
            "right",
            0.02,
            // The published damping formula, as the OpenSees model of the comparison has it.
            &ContactModel::new(Model::Hertzdamp, 2.0e10, 0.65)
                .unwrap()
                .with_damping(Damping::Formula),
            None,
        )
        .unwrap()
}

#[test]
fn inelastic_pounding_agrees_with_converged_opensees() {
    // OpenSeesPy 3.7.1 (bench/opensees/inelastic.py, results-inelastic.json): Steel01 at dt = 5e-6 s, which
    // agrees with dt = 1e-5 to 3e-6; BoucWen (first order in dt) extrapolated as 2 q(5e-6) - q(1e-5), which
    // agrees with the extrapolation from 1e-4 and 1e-5 to 7e-7. Per building: peak |u|, u at 31.18 s (m),
    // peak storey force (N); impacts. Our default tolerance is within 2e-5 of these (compare_inelastic.py);
    // the issue asks for 0.5 % on peaks, 2 % of the peak on residuals and impact counts within one.
    // (law, per building (peak |u|, u at the end, peak force), impacts).
    type Expected = [(f64, f64, f64); 2];
    let cases: [(StoreyLaw, Expected, usize); 2] = [
        (
            StoreyLaw::bilinear(1.0, 0.05).unwrap(),
            [
                (
                    0.03958015552793759,
                    -0.00788574245680818,
                    2531256.5170009686,
                ),
                (0.11100661472952635, 0.0481941705410907, 1249557.9784073061),
            ],
            5,
        ),
        (
            StoreyLaw::bouc_wen(1.0, 0.05, 1.0, 0.5, 0.5).unwrap(),
            [
                (
                    0.045938661961900155,
                    -0.007904546605386859,
                    1915914.6955817393,
                ),
                (0.07969536686438425, 0.012457197025175715, 910071.8940138625),
            ],
            4,
        ),
    ];
    for (kind, expected, impacts) in cases {
        let law = |fy: f64| match kind {
            StoreyLaw::Bilinear { .. } => StoreyLaw::bilinear(fy, 0.05).unwrap(),
            _ => StoreyLaw::bouc_wen(fy, 0.05, 1.0, 0.5, 0.5).unwrap(),
        };
        let r = inelastic_sdof_pair(&law).run().unwrap();
        for (b, (peak, end, force)) in r.buildings.iter().zip(expected) {
            assert!(
                (b.peak_displacement[0] - peak).abs() <= 1e-4 * peak,
                "{} vs {peak}",
                b.peak_displacement[0]
            );
            assert!(
                (b.residual_displacement[0] - end).abs() <= 1e-4 * peak,
                "{} vs {end}",
                b.residual_displacement[0]
            );
            assert!((b.peak_storey_shear[0] - force).abs() <= 1e-4 * force);
        }
        assert_eq!(r.impacts.len(), impacts);
    }
}
