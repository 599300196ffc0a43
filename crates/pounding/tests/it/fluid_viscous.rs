//! The fluid viscous damper `F = c |v|^alpha sgn(v)`: the energy it dissipates in a cycle of harmonic motion
//! (closed form), the linear dashpot it is at `alpha = 1`, and the energy balance of a run with dampers.

use pounding::analysis::{Building, DeviceSpec, Scenario};
use pounding::contact::{ContactModel, Model};
use pounding::element::device::{DashpotParams, FluidViscousParams};
use pounding::element::{DeviceLaw, Element, ElementLaw, End};
use pounding::engine::{self, Dof, Ground, Settings, System};
use pounding::ground_motion::Record;
use pounding::structure::ShearBuilding;

/// `4 u0^(1+alpha) omega^alpha 2^alpha Gamma^2(1 + alpha/2) / Gamma(2 + alpha)` per unit `c`: the energy a
/// damper dissipates in one cycle of `u = u0 sin(omega t)` (Symans & Constantinou 1998; Soong & Dargush
/// 1997, eq 6.5). The factor `4 2^alpha Gamma^2(1 + alpha/2) / Gamma(2 + alpha)` is computed with Python's
/// `math.gamma` (double precision): pi for alpha = 1.
fn cycle_energy(c: f64, u0: f64, omega: f64, alpha: f64) -> f64 {
    let factors = [
        (0.3, 3.674571925364583),
        (0.5, 3.4960767390561607),
        (0.75, 3.3049770793727222),
        (1.0, std::f64::consts::PI),
    ];
    let (_, factor) = factors
        .iter()
        .find(|(a, _)| *a == alpha)
        .unwrap_or_else(|| panic!("no tabulated factor for alpha = {alpha}"));
    factor * c * u0.powf(1.0 + alpha) * omega.powf(alpha)
}

/// The energy `law` dissipates over one cycle of harmonic motion of amplitude `u0` (m) and circular
/// frequency `omega` (rad/s): its end is a mass so large that the law cannot move it, started at the
/// velocity that keeps it still in space while the ground accelerates as `a_g = -u0 omega^2 sin(omega t)`
/// (sampled finely: 20 000 samples a cycle, which leaves the motion within 1e-8 of the sine), so that its
/// relative displacement, the law's deformation, is `-u0 sin(omega t)`.
fn dissipated_per_cycle(law: &DeviceLaw, u0: f64, omega: f64) -> f64 {
    let period = 2.0 * std::f64::consts::PI / omega;
    let dt = period / 20_000.0;
    let acc: Vec<f64> = (1..=20_400)
        .map(|k| -u0 * omega * omega * (omega * k as f64 * dt).sin())
        .collect();
    let record = Record::new("harmonic", dt, dt, acc).unwrap();
    let m = 1.0e20;
    let mut sys = System::new(
        &[Dof::x(m, 0.0)],
        vec![Element::new(End::Dof(0), End::Ground, law.law().unwrap())],
        Ground::Record(&record),
    );
    let l = sys.layout().clone();
    let rtol = 1e-11;
    // The input energy is of the order of the huge mass's: not controlled (its error is irrelevant here).
    let mut atol = vec![f64::INFINITY; l.dim()];
    atol[l.u(0)] = rtol * u0;
    atol[l.v(0)] = rtol * u0 * omega;
    atol[l.damping()] = rtol * cycle_energy(1.0, u0, omega, 1.0) * 1e6;
    for k in l.block(0) {
        atol[k] = rtol * u0;
    }
    // The ground's velocity is u0 omega (cos(omega t) - 1): the mass, still in space at -u0 omega, moves
    // relative to the ground at -u0 omega cos(omega t).
    let mut y0 = vec![0.0; l.dim()];
    y0[l.v(0)] = -u0 * omega;
    let settings = Settings {
        t_end: period,
        rtol,
        atol,
        h0: dt / 10.0,
        max_steps: 10_000_000,
        // One stepper for every damper, so that a damper of exponent one and the linear dashpot (which
        // alone would be propagated exactly) take the same steps.
        propagation: pounding::engine::Propagation::Stepping,
    };
    let out = engine::run(&mut sys, (0.0, &y0), &settings, &mut ()).unwrap();
    assert!((out.t - period).abs() < 1e-12, "{out:?}");
    // The viscous work (of a damper alone, or of the damper in series with a spring, a state of its own).
    sys.energies(&out.y).damping
}

#[test]
fn a_damper_in_harmonic_motion_dissipates_the_closed_form_energy_per_cycle() {
    let (u0, omega) = (0.05, 2.0 * std::f64::consts::PI / 0.8); // m, rad/s (T = 0.8 s)
    for alpha in [0.3, 0.5, 0.75, 1.0] {
        let c = 1.0e6; // N (s/m)^alpha
        let law = DeviceLaw::FluidViscous(FluidViscousParams {
            damping_coefficient: c,
            velocity_exponent: alpha,
            stiffness: None,
        });
        let got = dissipated_per_cycle(&law, u0, omega);
        let want = cycle_energy(c, u0, omega, alpha);
        assert!(
            (got / want - 1.0).abs() < 1e-6,
            "alpha {alpha}: {got} J against {want} J"
        );
    }
}

#[test]
fn a_damper_in_series_with_a_very_stiff_spring_is_the_damper_alone() {
    // k = 1e13 N/m against c = 1e6 N (s/m)^0.5 at 0.4 m/s: the spring stretches by F / k = 6e-8 m, a
    // millionth of the motion; the energy per cycle agrees to about that.
    let (u0, omega) = (0.05, 2.0 * std::f64::consts::PI / 0.8);
    let law = DeviceLaw::FluidViscous(FluidViscousParams {
        damping_coefficient: 1.0e6,
        velocity_exponent: 0.5,
        stiffness: Some(1.0e13),
    });
    let got = dissipated_per_cycle(&law, u0, omega);
    let want = cycle_energy(1.0e6, u0, omega, 0.5);
    assert!((got / want - 1.0).abs() < 1e-5, "{got} J against {want} J");
}

/// Two one-storey buildings (0.5 s and 1 s, 5e5 kg, undamped) joined by `device`, set moving by a short
/// pulse and then free: the first floor's displacement history, m (the energy balance checked too).
fn free_decay(device: DeviceLaw) -> Vec<f64> {
    let storey = |k: f64| {
        ShearBuilding::builder()
            .masses([5.0e5])
            .stiffnesses([k])
            .heights([3.0])
            .damping_ratio(0.0)
            .build()
            .unwrap()
    };
    let row = vec![
        Building {
            name: "a".into(),
            structure: storey(7.8957e7),
        },
        Building {
            name: "b".into(),
            structure: storey(1.9739e7),
        },
    ];
    // Half a second of 2 m/s^2, then nothing: a push, then free decay.
    let mut push = vec![2.0; 50];
    push.push(0.0);
    let pulse = Record::new("push", 0.01, 0.01, push).unwrap();
    let s = Scenario::new(row, pulse)
        .unwrap()
        .with_duration(6.0)
        .unwrap()
        .with_device(DeviceSpec {
            name: Some("damper, \"one\"".into()),
            between: ["a".into(), "b".into()],
            floors: None,
            law: device,
        })
        .unwrap();
    let r = s.run().unwrap();
    assert!(
        r.energy.relative_error < 1e-6,
        "{}",
        r.energy.relative_error
    );
    r.histories.displacement[0][0].clone()
}

#[test]
fn a_damper_of_exponent_one_is_the_linear_dashpot() {
    let c = 4.0e6; // N s/m
    let fluid = free_decay(DeviceLaw::FluidViscous(FluidViscousParams {
        damping_coefficient: c,
        velocity_exponent: 1.0,
        stiffness: None,
    }));
    let dashpot = free_decay(DeviceLaw::Dashpot(DashpotParams {
        damping_coefficient: c,
    }));
    assert!(fluid.iter().any(|u| u.abs() > 1e-3));
    assert_eq!(fluid, dashpot);
}

#[test]
fn dampers_of_every_form_keep_the_energy_balance_of_a_pounding_run() {
    let papi = ContactModel::new(Model::Papi, 2.0e9, 0.65).unwrap();
    for (alpha, k) in [(0.35, None), (0.35, Some(2.0e8)), (1.0, Some(2.0e8))] {
        let b = |masses: &[f64], ks: &[f64]| {
            ShearBuilding::builder()
                .masses(masses.to_vec())
                .stiffnesses(ks.to_vec())
                .heights(vec![3.0; masses.len()])
                .build()
                .unwrap()
        };
        let row = vec![
            Building {
                name: "low".into(),
                structure: b(&[4.0e5, 3.5e5], &[6.0e8, 4.0e8]),
            },
            Building {
                name: "tall".into(),
                structure: b(&[3.0e5; 4], &[2.0e8, 1.8e8, 1.6e8, 1.4e8]),
            },
        ];
        let law = DeviceLaw::FluidViscous(FluidViscousParams {
            damping_coefficient: 3.0e6,
            velocity_exponent: alpha,
            stiffness: k,
        });
        let s = Scenario::new(row, Record::el_centro_1940())
            .unwrap()
            .with_duration(8.0)
            .unwrap()
            .with_device(DeviceSpec {
                name: None,
                between: ["low".into(), "tall".into()],
                floors: Some(vec![(2, 2)]),
                law: law.clone(),
            })
            .unwrap()
            .with_link("low", "tall", 0.005, &papi, Some(vec![(1, 1), (2, 2)]))
            .unwrap();
        let r = s.run().unwrap();
        assert!(r.sites[0].impacts > 0, "alpha {alpha}, k {k:?}: no impact");
        assert!(
            r.energy.relative_error < 1e-6,
            "alpha {alpha}, k {k:?}: {}",
            r.energy.relative_error
        );
        // The damper takes energy out: its viscous work is part of the damping term.
        assert!(r.devices[0].peak_force[0] > 0.0);
        assert!(law.law().unwrap().name() == "fluid-viscous");
    }
}
