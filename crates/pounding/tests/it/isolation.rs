//! Walls, bumpers, devices and isolators: exact checks (`docs/structures.md`; issue 13). A block striking a rigid wall is a single impact with the block's own mass; a
//! bumper whose layer is never consumed is its soft law alone, and a consumed one stores energy in both laws;
//! a restrainer that never goes slack is a spring; an isolated building on a rigid isolator is its
//! superstructure on a fixed base; every element keeps the energy balance.

use super::buildings::{building, pulse};
use pounding::analysis::{Building, Bumper, DeviceSpec, Layer, Results, Scenario, Side, WallSpec};
use pounding::contact::{ContactModel, Model, Tension};
use pounding::element::device::{
    DashpotParams, KelvinParams, MaxwellParams, RestrainerParams, SpringParams,
};
use pounding::element::DeviceLaw;
use pounding::ground_motion::Record;
use pounding::impact::{simulate, ImpactOptions, ImpactSetup};
use pounding::structure::{Isolator, IsolatorModel, ShearBuilding};

/// A wall beside `facing` on `side`, at `gap`, with `contact`.
fn wall(facing: &str, side: Side, gap: f64, contact: &ContactModel) -> WallSpec {
    WallSpec {
        name: format!("wall-{}", side.name()),
        facing: facing.into(),
        side,
        gap,
        floors: None,
        points: None,
        contact: contact.clone(),
        bumper: None,
        seat: None,
    }
}

const M: f64 = 1.0e5;

/// A block of mass `M` on an almost free spring, driven towards a wall on `side` by a ground pulse (0.2 m/s
/// relative after 0.1 s); the storey spring's impulse over a contact bounds the disturbance of the impact
/// (`eps`, as in the isolated two-body impact of `buildings.rs`).
fn block_against(w: WallSpec) -> (Results, f64) {
    let k = M * 1e-6;
    let a = if w.side == Side::Right { -2.0 } else { 2.0 };
    let s = Scenario::new(vec![building("block", &[M], &[k], 0.0)], pulse(a, 0.1))
        .unwrap()
        .with_wall(w)
        .unwrap()
        .with_duration(1.0)
        .unwrap()
        .with_tolerance(1e-10)
        .unwrap();
    let r = s.run().unwrap();
    let eps = k * r.buildings[0].peak_displacement[0] / M * 1.0 / 0.2;
    (r, eps)
}

#[test]
fn a_block_striking_a_rigid_wall_delivers_the_single_impact_e_with_its_own_mass() {
    for side in [Side::Left, Side::Right] {
        for (model, k) in [
            (Model::Papi, 5.0e13),
            (Model::Hertzdamp, 2.0e16),
            (Model::Jankowski, 2.0e16),
            (Model::KelvinVoigt, 5.0e13),
            (Model::ImpactMaterial, 2.0e16),
        ] {
            let spec = ContactModel::new(model, k, 0.65).unwrap();
            let (r, eps) = block_against(wall("block", side, 0.05, &spec));
            assert_eq!(r.sites[0].impacts, r.impacts.len());
            let imp = &r.impacts[0];
            assert_eq!((imp.site, imp.level), (0, 0));
            assert_eq!(imp.layer, Layer::Direct);
            // The effective mass of an impact on a rigid wall is the block's mass.
            let law = spec.prepare().unwrap().law(M, imp.v_i).unwrap().0;
            let single = simulate(
                &law,
                spec.tension(),
                &ImpactSetup::relative(M, imp.v_i),
                &ImpactOptions::default(),
            )
            .unwrap();
            // Touch after the pulse: 0.2 m/s, less what the almost free spring took.
            assert!(
                (imp.v_i / 0.2 - 1.0).abs() < 1e-4,
                "{model}: v_i {}",
                imp.v_i
            );
            let e = imp.e_post.unwrap();
            assert!(
                (e - single.e_post).abs() <= 2.0 * eps + 1e-8,
                "{side:?} {model}: e_post {e} vs single impact {} (eps {eps:e})",
                single.e_post
            );
            assert!(
                (imp.peak_force / single.peak_force - 1.0).abs() <= 2.0 * eps + 1e-8,
                "{side:?} {model}: peak force {} vs {}",
                imp.peak_force,
                single.peak_force
            );
            // The block rebounds at e v_i, away from the wall.
            let toward = if side == Side::Right { 1.0 } else { -1.0 };
            assert!((r.sites[0].max_closing[0] - 0.05 - imp.max_penetration).abs() < 1e-9);
            assert!(toward * r.buildings[0].residual_displacement[0] < 0.05);
            if spec.tension() == Tension::Clamp {
                assert!(r.histories.site_force[0][0].iter().all(|f| *f >= 0.0));
            }
        }
    }
}

#[test]
fn a_bumper_never_consumed_is_its_soft_law_alone() {
    let hard = ContactModel::new(Model::Hertzdamp, 2.0e16, 0.65).unwrap();
    let soft = ContactModel::new(Model::Hertzdamp, 1.0e9, 0.4).unwrap();
    let (t, gap) = (0.02, 0.07);
    let mut with = wall("block", Side::Right, gap, &hard);
    // The layer would be consumed at 0.019 m of compression: far beyond what 0.2 m/s reaches.
    with.bumper = Some(Bumper::new(t, 0.95, &soft).unwrap());
    let (rb, _) = block_against(with);
    let (rs, _) = block_against(wall("block", Side::Right, gap - t, &soft));
    assert_eq!(rb.sites[0].consumed, 0);
    assert_eq!(rb.impacts.len(), rs.impacts.len());
    for (a, b) in rb.impacts.iter().zip(&rs.impacts) {
        assert_eq!(a.layer, Layer::Bumper);
        assert!(a.max_penetration < 0.5 * 0.95 * t);
        for (x, y, what) in [
            (a.time, b.time, "time"),
            (a.e_post.unwrap(), b.e_post.unwrap(), "e_post"),
            (a.peak_force, b.peak_force, "peak force"),
            (a.max_penetration, b.max_penetration, "penetration"),
        ] {
            // Both runs at 1e-10: the same motion to the integration's accuracy.
            assert!((x / y - 1.0).abs() < 1e-7, "{what}: {x} vs {y}");
        }
    }
}

/// The state at an event is the steps' solution, not an interpolant's: the rebound of a block on a
/// Hertz-damped bumper at tolerance 1e-10 is that of a 1e-12 run to 1e-9 (it was 3e-8 off, and 1e-7 once
/// the contact's work was held more closely: the interpolant of the step that crossed the separation gave
/// its velocity). So is the peak force.
#[test]
fn an_impact_rebounds_as_the_tolerance_says() {
    let soft = ContactModel::new(Model::Hertzdamp, 1.0e9, 0.4).unwrap();
    let run = |tol: f64| {
        let s = Scenario::new(
            vec![building("block", &[M], &[M * 1e-6], 0.0)],
            pulse(-2.0, 0.1),
        )
        .unwrap()
        .with_wall(wall("block", Side::Right, 0.05, &soft))
        .unwrap()
        .with_duration(1.0)
        .unwrap()
        .with_tolerance(tol)
        .unwrap();
        let r = s.run().unwrap();
        assert_eq!(r.impacts.len(), 1);
        (r.impacts[0].e_post.unwrap(), r.impacts[0].peak_force)
    };
    let ((e, f), (e_ref, f_ref)) = (run(1e-10), run(1e-12));
    assert!((e / e_ref - 1.0).abs() < 1e-9, "e_post {e} vs {e_ref}");
    assert!((f / f_ref - 1.0).abs() < 1e-8, "peak force {f} vs {f_ref}");
}

#[test]
fn a_consumed_bumper_of_two_springs_stores_the_impact_energy_in_both() {
    // Elastic layer k1 and elastic hard law k2 (Hooke, e = 1): at the largest penetration d the block's
    // kinetic energy is all in the springs, M v^2 / 2 = k1 d^2 / 2 + k2 (d - L)^2 / 2 with L = max_strain t,
    // and it leaves at the speed it came (e = 1, within the storey spring's disturbance).
    let (k1, k2) = (2.0e7, 2.0e9);
    // The layer touches at 0.05 m, after the pulse.
    let (t, strain, gap) = (0.02, 0.5, 0.07);
    let mut w = wall(
        "block",
        Side::Right,
        gap,
        &ContactModel::new(Model::Hooke, k2, 1.0).unwrap(),
    );
    w.bumper = Some(
        Bumper::new(
            t,
            strain,
            &ContactModel::new(Model::Hooke, k1, 1.0).unwrap(),
        )
        .unwrap(),
    );
    let (r, eps) = block_against(w);
    let layer = r.impacts.iter().find(|i| i.layer == Layer::Bumper).unwrap();
    let hard = r
        .impacts
        .iter()
        .find(|i| i.layer == Layer::Consumed)
        .unwrap();
    assert_eq!(r.sites[0].consumed, 1);
    let v = layer.v_i;
    let l = strain * t;
    // k1 d^2 + k2 (d - l)^2 = M v^2, the root beyond l.
    let (a, b, c) = (k1 + k2, -2.0 * k2 * l, k2 * l * l - M * v * v);
    let d = (-b + (b * b - 4.0 * a * c).sqrt()) / (2.0 * a);
    assert!(d > l);
    assert!(
        (layer.max_penetration / d - 1.0).abs() < 1e-7,
        "{} vs {d}",
        layer.max_penetration
    );
    assert!((hard.max_penetration / (d - l) - 1.0).abs() < 1e-6);
    // The force on the wall at that instant: k1 d + k2 (d - l), the sum of both elements.
    let f = k1 * d + k2 * (d - l);
    assert!(
        (r.sites[0].peak_force / f - 1.0).abs() < 1e-6,
        "{} vs {f}",
        r.sites[0].peak_force
    );
    assert!((layer.e_post.unwrap() - 1.0).abs() <= 2.0 * eps + 1e-8);
}

/// A block on a storey, a dashpot that makes it overdamped, and `law` to a wall on its left that no motion
/// reaches, under a constant ground push to the right (after the record's 0.01-s ramp).
fn restrained(law: DeviceLaw) -> Results {
    let (m, k) = (1.0e5, 4.0e6);
    let far = ContactModel::new(Model::Hooke, 1e9, 1.0).unwrap();
    let device = |law| DeviceSpec {
        name: None,
        between: ["block".into(), "wall-left".into()],
        floors: None,
        law,
    };
    Scenario::new(vec![building("block", &[m], &[k], 0.5)], pulse(-1.0, 20.0))
        .unwrap()
        .with_wall(wall("block", Side::Left, 10.0, &far))
        .unwrap()
        .with_device(device(law))
        .unwrap()
        .with_device(device(DeviceLaw::Dashpot(DashpotParams {
            damping_coefficient: 4.0e6,
        })))
        .unwrap()
        .with_duration(18.0)
        .unwrap()
        .with_tolerance(1e-10)
        .unwrap()
        .run()
        .unwrap()
}

#[test]
fn a_restrainer_never_slack_is_a_spring() {
    // The block moves right, away from the wall, without overshoot (damping ratio (c_s + 4e6) /
    // (2 sqrt((k + k_r) m)) = 2.6): a restrainer without slack is taut all along and pulls as a spring.
    let k_r = 2.0e6;
    let r = restrained(DeviceLaw::Restrainer(RestrainerParams {
        stiffness: k_r,
        slack: 0.0,
    }));
    let s = restrained(DeviceLaw::Spring(SpringParams { stiffness: k_r }));
    // Static answer: u = M a / (k + k_r) = 1e5 / 6e6.
    let u_static = 1.0e5 / 6.0e6;
    assert!(
        (s.buildings[0].residual_displacement[0] / u_static - 1.0).abs() < 1e-6,
        "{} vs {u_static}",
        s.buildings[0].residual_displacement[0]
    );
    for (a, b) in [
        (
            r.buildings[0].peak_displacement[0],
            s.buildings[0].peak_displacement[0],
        ),
        (
            r.buildings[0].residual_displacement[0],
            s.buildings[0].residual_displacement[0],
        ),
        (r.devices[0].peak_force[0], s.devices[0].peak_force[0]),
        (r.devices[0].max_opening[0], s.devices[0].max_opening[0]),
    ] {
        assert!((a / b - 1.0).abs() < 1e-8, "{a} vs {b}");
    }
    // Its force is the spring's pull, k_r times the opening (the device's deformation is -u).
    let h = &r.histories;
    let u = &h.displacement[0][0];
    for (k, f) in h.device_force[0][0].iter().enumerate().skip(1) {
        assert!(
            (f + k_r * u[k]).abs() <= 1e-9 * k_r * u_static,
            "{f} vs {}",
            -k_r * u[k]
        );
    }
    // With slack beyond the motion the restrainer never pulls: the block on its storey alone.
    let slack = restrained(DeviceLaw::Restrainer(RestrainerParams {
        stiffness: k_r,
        slack: 0.1,
    }));
    assert_eq!(slack.devices[0].peak_force[0], 0.0);
    assert!((slack.buildings[0].residual_displacement[0] / (1.0e5 / 4.0e6) - 1.0).abs() < 1e-6);
}

/// The fixed-base building and the same superstructure on an isolator.
fn superstructure() -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    (
        vec![5.0e5, 5.0e5, 4.0e5],
        vec![8.0e8, 7.0e8, 5.0e8],
        vec![3.5, 3.5, 3.5],
    )
}

#[test]
fn a_superstructure_on_a_rigid_isolator_is_the_fixed_base_building() {
    // The superstructure is damped on its fixed-base modes, relative to the base slab. On an isolator
    // 2e4 times stiffer than its storeys the slab barely moves, and the floors' motion relative to it is
    // the fixed-base building's, to about (w_s / w_iso)^2 = 1e-4.
    let (m, k, h) = superstructure();
    let fixed = Building {
        name: "fixed".into(),
        structure: ShearBuilding::new(m.clone(), k.clone(), h.clone(), 0.05).unwrap(),
    };
    let mut iso = Isolator::new(IsolatorModel::Linear { stiffness: 2.0e13 });
    iso.damping = 0.0;
    let isolated = Building {
        name: "isolated".into(),
        structure: ShearBuilding::isolated(6.0e5, iso, m, k, h, 0.05).unwrap(),
    };
    assert_eq!(isolated.structure.rayleigh(), fixed.structure.rayleigh());
    let run = |b: Building| {
        Scenario::new(vec![b], Record::el_centro_1940())
            .unwrap()
            .with_duration(10.0)
            .unwrap()
            .with_tolerance(1e-9)
            .unwrap()
            .run()
            .unwrap()
    };
    let (rf, ri) = (run(fixed), run(isolated));
    for f in 0..3 {
        let rel: f64 = ri.histories.displacement[0][f + 1]
            .iter()
            .zip(&ri.histories.displacement[0][0])
            .map(|(u, b)| (u - b).abs())
            .fold(0.0, f64::max);
        let fixed = rf.buildings[0].peak_displacement[f];
        assert!(
            (rel / fixed - 1.0).abs() < 1e-3,
            "floor {}: {rel} vs {fixed}",
            f + 1
        );
    }
}

#[test]
fn every_element_keeps_the_energy_balance_at_the_default_tolerance() {
    let (m, k, h) = superstructure();
    let isolated = |name: &str, model: IsolatorModel| {
        let mut iso = Isolator::new(model);
        iso.damping = 1.0e5;
        Building {
            name: name.into(),
            structure: ShearBuilding::isolated(6.0e5, iso, m.clone(), k.clone(), h.clone(), 0.05)
                .unwrap(),
        }
    };
    let hertz = ContactModel::new(Model::Hertzdamp, 2.0e10, 0.7).unwrap();
    let papi = ContactModel::new(Model::Papi, 1.0e9, 0.6).unwrap();
    let rubber = ContactModel::new(Model::Hertzdamp, 2.0e8, 0.5).unwrap();
    let devices = [
        DeviceLaw::Spring(SpringParams { stiffness: 1.0e6 }),
        DeviceLaw::Dashpot(DashpotParams {
            damping_coefficient: 2.0e5,
        }),
        DeviceLaw::Kelvin(KelvinParams {
            stiffness: 1.0e6,
            damping_coefficient: 1.0e5,
        }),
        DeviceLaw::Maxwell(MaxwellParams {
            stiffness: 5.0e6,
            damping_coefficient: 5.0e5,
        }),
        DeviceLaw::Restrainer(RestrainerParams {
            stiffness: 2.0e7,
            slack: 0.01,
        }),
    ];
    let mut s = Scenario::new(
        vec![
            isolated(
                "lrb",
                IsolatorModel::BoucWen {
                    stiffness: 8.0e7,
                    yield_force: 1.5e6,
                    post_yield_ratio: 0.1,
                    n: 1.0,
                    beta: 0.5,
                    gamma: 0.5,
                },
            ),
            isolated(
                "fps",
                IsolatorModel::FrictionPendulum {
                    radius: 2.0,
                    mu: 0.05,
                    yield_displacement: 2.5e-4,
                },
            ),
            isolated(
                "bilinear",
                IsolatorModel::Bilinear {
                    stiffness: 8.0e7,
                    yield_force: 1.5e6,
                    post_yield_ratio: 0.08,
                },
            ),
        ],
        Record::el_centro_1940().scaled(2.0).unwrap(),
    )
    .unwrap()
    .with_link("lrb", "fps", 0.04, &papi, None)
    .unwrap()
    .with_link("fps", "bilinear", 0.05, &hertz, None)
    .unwrap()
    .with_link_bumper("fps", "bilinear", Bumper::new(0.02, 0.6, &rubber).unwrap())
    .unwrap()
    .with_link_seat("fps", "bilinear", 0.1)
    .unwrap();
    let mut w = wall("lrb", Side::Left, 0.08, &hertz);
    w.bumper = Some(Bumper::new(0.03, 0.5, &rubber).unwrap());
    s = s.with_wall(w).unwrap();
    s = s
        .with_wall(wall("bilinear", Side::Right, 0.1, &hertz))
        .unwrap();
    for (i, law) in devices.into_iter().enumerate() {
        let between = if i % 2 == 0 {
            ["lrb", "fps"]
        } else {
            ["fps", "bilinear"]
        };
        s = s
            .with_device(DeviceSpec {
                name: None,
                between: between.map(String::from),
                floors: Some(vec![(4, 4)]),
                law,
            })
            .unwrap();
    }
    let r = s.with_duration(20.0).unwrap().run().unwrap();
    assert!(r.impacts.len() > 5, "{} impacts", r.impacts.len());
    assert!(
        r.energy.relative_error < 1e-6,
        "balance error {:e}",
        r.energy.relative_error
    );
    assert!(r.energy.end.hysteretic > 0.0 && r.energy.end.contact > 0.0);
    eprintln!(
        "impacts {} (sites {:?}), balance {:e}, steps {}",
        r.impacts.len(),
        r.sites
            .iter()
            .map(|l| (l.impacts, l.consumed))
            .collect::<Vec<_>>(),
        r.energy.relative_error,
        r.statistics.steps
    );
}
