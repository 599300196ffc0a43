//! Buildings in plan: a symmetric plan shaken along its axis is the building in one line, an eccentric
//! impact between two free slabs delivers the rigid-body impulse, a pair of ground components is what
//! linearity says, the energy balances, and bad plans are refused naming the key.

use pounding::analysis::{Building, PlanLinkSpec, Results, Scenario};
use pounding::contact::{ContactModel, ContactOptions, Model, Restitution};
use pounding::element::{Contact, Element, End, Notice, StoreyLaw};
use pounding::engine::{self, Axis, Dof, EventInfo, Ground, Observer, Segment, Settings, System};
use pounding::ground_motion::Record;
use pounding::structure::{Line, LineDirection, Plan, PlanSpec, ShearBuilding};

/// Every model with a stiffness of its exponent's unit and the keys it needs; models asked no `e` are
/// elastic.
fn contact(model: Model) -> ContactModel {
    let mut o = ContactOptions {
        model,
        ..ContactOptions::default()
    };
    if model.asks_no_e().is_some() {
        o.e = Restitution::Constant(1.0);
    }
    if model == Model::ImpactMaterial {
        o.max_penetration = Some(0.005);
        o.e = Restitution::Constant(0.97);
    }
    if model == Model::Thornton {
        o.radius = Some(2.0);
        o.yield_pressure = Some(2.0e8);
    }
    // About 2e9 N/m at a penetration of 1 cm whatever the exponent.
    let k = 2.0e9 * 0.01f64.powf(1.0 - o.exponent());
    o.build(k).unwrap()
}

const MASSES_A: [f64; 3] = [4.0e5, 4.0e5, 3.0e5];
const K_A: [f64; 3] = [3.2e8, 2.8e8, 2.0e8];
const MASSES_B: [f64; 2] = [6.0e5, 5.0e5];
const K_B: [f64; 2] = [1.2e8, 1.0e8];

/// Lines of a symmetric `a` x `b` plan: along x at both edges, halves of `kx` (or, `split` false, one line
/// along x through the middle); along y at both edges, halves of `ky`.
fn symmetric_lines((a, b): (f64, f64), kx: &[f64], ky: &[f64], split: bool) -> Vec<Line> {
    let line = |direction, at, k: &[f64], part: f64| Line {
        direction,
        at,
        stiffnesses: k.iter().map(|k| k * part).collect(),
        laws: vec![StoreyLaw::Linear; k.len()],
    };
    let mut lines = if split {
        vec![
            line(LineDirection::X, 0.0, kx, 0.5),
            line(LineDirection::X, b, kx, 0.5),
        ]
    } else {
        vec![line(LineDirection::X, b / 2.0, kx, 1.0)]
    };
    lines.push(line(LineDirection::Y, 0.0, ky, 0.5));
    lines.push(line(LineDirection::Y, a, ky, 0.5));
    lines
}

fn in_plan(
    masses: &[f64],
    (kx, ky): (&[f64], &[f64]),
    size: (f64, f64),
    origin: (f64, f64),
    split: bool,
) -> ShearBuilding {
    let spec = PlanSpec {
        size,
        origin,
        centres: None,
        inertias: None,
        lines: symmetric_lines(size, kx, ky, split),
        damping_modes: None,
    };
    ShearBuilding::in_plan(masses.to_vec(), vec![3.0; masses.len()], 0.05, spec).unwrap()
}

/// Two neighbours 20 mm apart in one line, and the same in plan: A 20 m x 12 m, B 16 m x 16 m east of it,
/// both mass centres on y = 6 m, contact elements at y = 6 m only (on the line of the mass centres). Both
/// are stepped (`propagation = "stepping"`): the plan's motion is too large to pay being propagated exactly,
/// and the two take the same steps only with the same stepper.
fn pair(model: Model, split: bool) -> (Scenario, Scenario) {
    let gap = 0.02;
    let record = Record::el_centro_1940();
    let line = |m: &[f64], k: &[f64]| {
        ShearBuilding::new(m.to_vec(), k.to_vec(), vec![3.0; m.len()], 0.05).unwrap()
    };
    let one = Scenario::new(
        vec![
            Building {
                name: "A".into(),
                structure: line(&MASSES_A, &K_A),
            },
            Building {
                name: "B".into(),
                structure: line(&MASSES_B, &K_B),
            },
        ],
        record.clone(),
    )
    .unwrap()
    .with_duration(4.0)
    .unwrap()
    .with_link("A", "B", gap, &contact(model), None)
    .unwrap();
    let ky_a: Vec<f64> = K_A.iter().map(|k| 1.7 * k).collect();
    let ky_b: Vec<f64> = K_B.iter().map(|k| 0.8 * k).collect();
    let plan = Scenario::new(
        vec![
            Building {
                name: "A".into(),
                structure: in_plan(&MASSES_A, (&K_A, &ky_a), (20.0, 12.0), (0.0, 0.0), split),
            },
            Building {
                name: "B".into(),
                structure: in_plan(
                    &MASSES_B,
                    (&K_B, &ky_b),
                    (16.0, 16.0),
                    (20.0 + gap, -2.0),
                    split,
                ),
            },
        ],
        record,
    )
    .unwrap()
    .with_duration(4.0)
    .unwrap()
    .with_plan_contact(PlanLinkSpec {
        between: ["A".into(), "B".into()],
        floors: None,
        points: Some(vec![6.0]),
        contact: contact(model),
        bumper: None,
        seat: None,
    })
    .unwrap();
    let stepped = pounding::engine::Propagation::Stepping;
    (
        one.with_propagation(stepped),
        plan.with_propagation(stepped),
    )
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * a.abs().max(b.abs()).max(1e-30)
}

/// The peaks and impacts of `one` and `plan` agree to `tol` (relative), and nothing turns or moves along y.
fn same(one: &Results, plan: &Results, tol: f64, what: &str) {
    for (b, (x, p)) in one.buildings.iter().zip(&plan.buildings).enumerate() {
        for (name, u, v) in [
            ("displacement", &x.peak_displacement, &p.peak_displacement),
            ("drift", &x.peak_drift, &p.peak_drift),
            ("shear", &x.peak_storey_shear, &p.peak_storey_shear),
            (
                "acceleration",
                &x.peak_absolute_acceleration,
                &p.peak_absolute_acceleration,
            ),
        ] {
            for (f, (a, c)) in u.iter().zip(v).enumerate() {
                assert!(
                    close(*a, *c, tol),
                    "{what}: {name} of building {b} floor {f}: {a} vs {c}"
                );
            }
        }
        let pr = p.plan.as_ref().unwrap();
        assert!(pr
            .peak_rotation
            .iter()
            .chain(&pr.peak_displacement_y)
            .all(|&x| x == 0.0));
    }
    assert_eq!(one.impacts.len(), plan.impacts.len(), "{what}: impacts");
    assert!(!one.impacts.is_empty(), "{what}: they pound");
    for (a, c) in one.impacts.iter().zip(&plan.impacts) {
        assert!(
            (a.time - c.time).abs() < tol,
            "{what}: touch at {} vs {}",
            a.time,
            c.time
        );
        assert!(
            close(a.v_i, c.v_i, tol),
            "{what}: v_i {} vs {}",
            a.v_i,
            c.v_i
        );
        assert!(
            close(a.peak_force, c.peak_force, tol),
            "{what}: force {} vs {}",
            a.peak_force,
            c.peak_force
        );
        if let (Some(e1), Some(e2)) = (a.e_post, c.e_post) {
            assert!((e1 - e2).abs() < tol, "{what}: e {e1} vs {e2}");
        }
    }
}

/// A symmetric plan shaken along x by one record, struck on the line of the mass centres, is the building in
/// one line: the same steps to the last digit when its lines along x carry the storeys' stiffnesses whole
/// (one through the mass centres; its Rayleigh damping fixed on the same modes, its gap from the positions
/// the same); with the stiffness split in halves between two lines, the same to rounding, which may decide
/// a step differently and move the results by up to the tolerance (1e-7; 1.5e-8 here).
#[test]
fn a_symmetric_plan_shaken_along_its_axis_is_the_building_in_one_line_for_every_model() {
    for (split, tol) in [(false, 1e-12), (true, 1e-7)] {
        for model in Model::all() {
            let (one, plan) = pair(model, split);
            let (r1, r2) = (one.run().unwrap(), plan.run().unwrap());
            same(&r1, &r2, tol, &format!("{} (split {split})", model.name()));
            // The damping of the plan is fixed on its modes along x: those of the building in one line.
            let p = plan.buildings()[0].structure.plan().unwrap();
            let (a0, a1) = one.buildings()[0].structure.rayleigh();
            assert!(close(p.rayleigh().0, a0, 1e-14) && close(p.rayleigh().1, a1, 1e-14));
        }
    }
}

/// The velocities of the degrees of freedom at each event, m/s (rad/s for rotations).
#[derive(Default)]
struct AtEvents(Vec<(Option<Notice>, Vec<f64>)>);

impl Observer for AtEvents {
    fn segment(&mut self, _seg: &Segment<'_, '_>) {}
    fn event(&mut self, ev: &EventInfo<'_, '_>) {
        let v = ev.y[ev.system.layout().velocities()].to_vec();
        self.0.push((ev.notice, v));
    }
}

#[test]
fn an_eccentric_impact_between_two_slabs_delivers_the_rigid_body_impulse() {
    // Two free 1e6 kg, 20 m x 20 m slabs; slab 1 strikes slab 2 at 1 m/s along x, at a point whose lever arm
    // about each mass centre is r. P = (1 + e) v_n / (1/m1 + r^2/J1 + 1/m2 + r^2/J2), spin P r / J
    // (next-physics.md section 4): 8.25e5, 6.0e5, 3.3e5 N s and 0, 0.045, 0.0495 rad/s.
    let (m, e) = (1.0e6, 0.65);
    for (r, p_want, spin_want) in [
        (0.0, 8.25e5, 0.0),
        (5.0, 6.0e5, 0.045),
        (10.0, 3.3e5, 0.0495),
    ] {
        let slab = |origin: (f64, f64)| {
            let spec = PlanSpec {
                size: (20.0, 20.0),
                origin,
                centres: None,
                inertias: None,
                lines: symmetric_lines((20.0, 20.0), &[1e8], &[1e8], true),
                damping_modes: None,
            };
            Plan::new(&[m], spec, 0.05).unwrap()
        };
        // Slab 1 centred at (10, 10); slab 2 east of it, its centre 2 r higher, so that the point (20, 10 + r)
        // is r from both centres across x.
        let (s1, s2) = (slab((0.0, 0.0)), slab((20.0, 2.0 * r)));
        let point = (20.0, 10.0 + r);
        let n = (1.0, 0.0);
        let m_eff = {
            let (a, b) = (s1.point_mass(1, point, n), s2.point_mass(1, point, n));
            a * b / (a + b)
        };
        let spec = ContactModel::new(Model::Papi, 2.0e9, e).unwrap();
        let c = Contact::new(spec.prepare().unwrap(), 0.0, m_eff, 1e-3);
        let el = Element::new(
            End::Point(s1.point(1, 0, point, n)),
            End::Point(s2.point(1, 3, point, n)),
            c,
        );
        let dofs: Vec<Dof> = [s1.dof_masses(), s2.dof_masses()]
            .concat()
            .iter()
            .zip([Axis::X, Axis::Y, Axis::Rotation].iter().cycle())
            .map(|(&mass, &axis)| Dof {
                mass,
                a0: 0.0,
                axis,
            })
            .collect();
        let mut sys = System::new(&dofs, vec![el], Ground::Constant(0.0));
        let l = sys.layout().clone();
        let mut y0 = vec![0.0; l.dim()];
        y0[l.v(0)] = 1.0;
        let rtol = 1e-11;
        let mut atol = vec![rtol * 1e5; l.dim()];
        for i in 0..6 {
            atol[l.u(i)] = rtol * 1e-3;
            atol[l.v(i)] = rtol * 1e-1;
        }
        let settings = Settings {
            t_end: 0.5,
            rtol,
            atol,
            h0: 1e-5,
            max_steps: 1_000_000,
            propagation: pounding::engine::Propagation::default(),
        };
        let mut obs = AtEvents::default();
        engine::run(&mut sys, (0.0, &y0), &settings, &mut obs).unwrap();
        let end = obs
            .0
            .iter()
            .find(|e| matches!(e.0, Some(Notice::ImpactEnded | Notice::ImpactReleased)))
            .expect("the impact ends")
            .1
            .clone();
        let p = m * (1.0 - end[0]);
        assert!(close(p, p_want, 1e-9), "r = {r}: P = {p} vs {p_want}");
        // Slab 2 gains what slab 1 lost, and both turn by P r / J (in opposite senses).
        assert!(
            close(m * end[3], p_want, 1e-9),
            "r = {r}: slab 2 {}",
            m * end[3]
        );
        for (w, slab) in [(end[2], 1), (end[5], 2)] {
            assert!(
                (w.abs() - spin_want).abs() < 1e-11,
                "r = {r}: slab {slab} spins {w}"
            );
        }
        assert!(end[1] == 0.0 && end[4] == 0.0, "no motion along y");
    }
}

/// An eccentric three-storey building in plan: its mass centres 3 m east of the middle of a 20 m x 12 m
/// plan, a stiff line along y on its west side, lines along x unequal (it twists under either component).
fn eccentric(laws: StoreyLaw, origin: (f64, f64)) -> ShearBuilding {
    let line = |direction, at, k: f64| Line {
        direction,
        at,
        stiffnesses: vec![k, 0.9 * k, 0.7 * k],
        laws: vec![laws; 3],
    };
    let spec = PlanSpec {
        size: (20.0, 12.0),
        origin,
        centres: Some(vec![(13.0, 6.0), (13.0, 6.5), (12.0, 6.0)]),
        inertias: None,
        lines: vec![
            line(LineDirection::X, 0.0, 2.0e8),
            line(LineDirection::X, 12.0, 1.2e8),
            line(LineDirection::Y, 1.0, 4.0e8),
            line(LineDirection::Y, 20.0, 1.0e8),
        ],
        damping_modes: None,
    };
    ShearBuilding::in_plan(vec![4.0e5, 4.0e5, 3.0e5], vec![3.0; 3], 0.05, spec).unwrap()
}

/// A linear building is linear in its ground: one record along 30 degrees is `cos 30` of it along x plus
/// `sin 30` of it along y, sample by sample, in x, y and rotation (each run converged to 1e-10).
#[test]
fn one_record_along_an_angle_is_the_sum_of_its_components() {
    let rec = Record::el_centro_1940();
    let zero = Record::new("zero", rec.dt(), rec.t0(), vec![0.0; rec.npts()]).unwrap();
    let run = |x: &Record, y: &Record| {
        let b = Building {
            name: "A".into(),
            structure: eccentric(StoreyLaw::Linear, (0.0, 0.0)),
        };
        Scenario::new(vec![b], x.clone())
            .unwrap()
            .with_duration(6.0)
            .unwrap()
            .with_tolerance(1e-10)
            .unwrap()
            .with_ground_y(y.clone())
            .unwrap()
            .run()
            .unwrap()
    };
    let a = 30f64.to_radians();
    let (along_x, along_y) = (run(&rec, &zero), run(&zero, &rec));
    let (turned_x, turned_y) = pounding::ground_motion::turned(&rec, None, 30.0).unwrap();
    let both = run(&turned_x, &turned_y);
    let h = |r: &Results| {
        let h = &r.histories;
        [
            h.displacement[0].clone(),
            h.displacement_y[0].clone(),
            h.rotation[0].clone(),
        ]
    };
    let (hx, hy, hb) = (h(&along_x), h(&along_y), h(&both));
    for q in 0..3 {
        let scale = hb[q].iter().flatten().fold(0.0f64, |m, v| m.max(v.abs()));
        assert!(scale > 0.0, "quantity {q} moves");
        for f in 0..3 {
            for k in 0..hb[q][f].len() {
                let sum = a.cos() * hx[q][f][k] + a.sin() * hy[q][f][k];
                assert!(
                    (hb[q][f][k] - sum).abs() < 1e-7 * scale,
                    "quantity {q}, floor {f}, sample {k}: {} vs {sum}",
                    hb[q][f][k]
                );
            }
        }
    }
}

/// Two eccentric buildings with yielding lines, pounding at their façades' corners under two components:
/// the energy balances to 1e-6 at the default tolerance, and each contact point's effective mass is less
/// than the floors' in series (they turn as they are struck).
#[test]
fn two_eccentric_buildings_pounding_in_plan_balance_their_energy() {
    let bilinear = StoreyLaw::bilinear(6.0e5, 0.05).unwrap();
    let buildings = vec![
        Building {
            name: "A".into(),
            structure: eccentric(bilinear, (0.0, 0.0)),
        },
        Building {
            name: "B".into(),
            structure: eccentric(StoreyLaw::Linear, (20.03, 4.0)),
        },
    ];
    let rec = Record::el_centro_1940();
    let y = Record::el_centro_1940().scaled(0.7).unwrap();
    let s = Scenario::new(buildings, rec)
        .unwrap()
        .with_duration(8.0)
        .unwrap()
        .with_ground_y(y)
        .unwrap()
        .with_plan_contact(PlanLinkSpec {
            between: ["B".into(), "A".into()],
            floors: None,
            points: None,
            contact: contact(Model::Hertzdamp),
            bumper: None,
            seat: None,
        })
        .unwrap();
    let site = &s.sites()[0];
    assert_eq!(site.levels.len(), 6, "three floor pairs, two points");
    let r = s.run().unwrap();
    assert!(r.impacts.len() > 2, "{} impacts", r.impacts.len());
    assert!(
        r.energy.relative_error < 1e-6,
        "{}",
        r.energy.relative_error
    );
    assert!(r.energy.end.hysteretic > 0.0);
    let series = 1.0 / (1.0 / 4.0e5 + 1.0 / 4.0e5);
    for k in 0..site.levels.len() {
        let m = s.effective_mass(site, k);
        assert!(m > 0.0 && m < series, "level {k}: {m}");
    }
    // Both ends of the overlap are corners: (20, 4) of B, (20, 12) of A; the buildings twist.
    let along: Vec<f64> = site.plan.as_ref().unwrap().along.clone();
    assert_eq!(along, vec![4.0, 12.0]);
    assert!(r.buildings[0].plan.as_ref().unwrap().peak_rotation[2] > 0.0);
}

/// A wall beside a building in plan, struck on the line of its mass centre, is the wall beside the building
/// in one line: on the east and west (shaken along x: to the last digit) and on the north and south (the same
/// building turned a quarter, shaken along y: to the tolerance, since its x components then count in the
/// error norm).
#[test]
fn walls_beside_a_building_in_plan_are_the_walls_of_the_building_in_one_line() {
    use pounding::analysis::{Side, WallSpec};
    let rec = Record::el_centro_1940();
    let zero = Record::new("zero", rec.dt(), rec.t0(), vec![0.0; rec.npts()]).unwrap();
    let wall = |side: Side, points: Option<Vec<f64>>| WallSpec {
        name: format!("wall-{}", side.name()),
        facing: "A".into(),
        side,
        gap: 0.015625,
        floors: Some(vec![2]),
        points,
        contact: contact(Model::Papi),
        bumper: None,
        seat: None,
    };
    let k = [3.0e8, 2.0e8];
    let line_building =
        ShearBuilding::new(vec![4.0e5, 3.0e5], k.to_vec(), vec![3.0; 2], 0.05).unwrap();
    // Along x: one line along x through the middle; along y (turned): one line along y through it.
    let planned = |along_y: bool| {
        let l = |direction, at, part: f64| Line {
            direction,
            at,
            stiffnesses: k.iter().map(|k| k * part).collect(),
            laws: vec![StoreyLaw::Linear; 2],
        };
        let (main, other) = if along_y {
            (LineDirection::Y, LineDirection::X)
        } else {
            (LineDirection::X, LineDirection::Y)
        };
        let mut spec = PlanSpec {
            size: (10.0, 10.0),
            origin: (0.0, 0.0),
            centres: None,
            inertias: None,
            lines: vec![l(main, 5.0, 1.0), l(other, 0.0, 0.7), l(other, 10.0, 0.7)],
            damping_modes: None,
        };
        if along_y {
            // Damped on its two modes along y, as the building in one line on its two.
            let p = Plan::new(&[4.0e5, 3.0e5], spec.clone(), 0.05).unwrap();
            let y: Vec<usize> = (0..6).filter(|&r| p.participation()[r].1 > 1e-9).collect();
            spec.damping_modes = Some((y[0] + 1, y[1] + 1));
        }
        ShearBuilding::in_plan(vec![4.0e5, 3.0e5], vec![3.0; 2], 0.05, spec).unwrap()
    };
    let one = |st: ShearBuilding| {
        vec![Building {
            name: "A".into(),
            structure: st,
        }]
    };
    for (line_side, plan_side, along_y) in [
        (Side::Right, Side::Right, false),
        (Side::Left, Side::Left, false),
        (Side::Right, Side::North, true),
        (Side::Left, Side::South, true),
    ] {
        // Both stepped, so that they take the same steps (the plan is too large to be propagated exactly).
        let stepped = pounding::engine::Propagation::Stepping;
        let r1 = Scenario::new(one(line_building.clone()), rec.clone())
            .unwrap()
            .with_duration(5.0)
            .unwrap()
            .with_wall(wall(line_side, None))
            .unwrap()
            .with_propagation(stepped)
            .run()
            .unwrap();
        let (x, y) = if along_y {
            (&zero, &rec)
        } else {
            (&rec, &zero)
        };
        let mut s = Scenario::new(one(planned(along_y)), x.clone())
            .unwrap()
            .with_duration(5.0)
            .unwrap()
            .with_propagation(stepped);
        if along_y {
            s = s.with_ground_y(y.clone()).unwrap();
        }
        let r2 = s
            .with_wall(wall(plan_side, Some(vec![5.0])))
            .unwrap()
            .run()
            .unwrap();
        let what = format!("{} wall", plan_side.name());
        assert!(!r1.impacts.is_empty(), "{what}: the floor strikes it");
        assert_eq!(r1.impacts.len(), r2.impacts.len(), "{what}: impacts");
        let tol = if along_y { 1e-6 } else { 1e-12 };
        let turned = |r: &Results| match along_y {
            false => r.buildings[0].peak_displacement.clone(),
            true => r.buildings[0]
                .plan
                .as_ref()
                .unwrap()
                .peak_displacement_y
                .clone(),
        };
        for (a, b) in r1.buildings[0].peak_displacement.iter().zip(turned(&r2)) {
            assert!(close(*a, b, tol), "{what}: {a} vs {b}");
        }
        for (a, b) in r1.impacts.iter().zip(&r2.impacts) {
            assert!(
                close(a.v_i, b.v_i, tol) && close(a.peak_force, b.peak_force, tol),
                "{what}"
            );
        }
    }
}

/// The separation of a symmetric pair in plan, at a point on the line of the mass centres, is that of the
/// pair in one line: the same peaks, required gap and rules.
#[test]
fn the_separation_of_a_symmetric_pair_in_plan_is_that_of_the_pair_in_one_line() {
    use pounding::analysis::RunOptions;
    let (one, plan) = pair(Model::Papi, false);
    let opts = RunOptions::summary_only();
    let (a, b) = (
        pounding::separation::separation(&one, None, &opts).unwrap(),
        pounding::separation::separation(&plan, None, &opts).unwrap(),
    );
    let (la, lb) = (&a[0].levels, &b[0].levels);
    assert_eq!(la.len(), lb.len());
    for (x, y) in la.iter().zip(lb) {
        assert_eq!(y.point, Some((20.0, 6.0)));
        for (p, q) in [
            (x.peak_left, y.peak_left),
            (x.peak_right, y.peak_right),
            (x.required_gap, y.required_gap),
            (x.srss, y.srss),
            (x.ddc, y.ddc),
            (x.rho, y.rho),
        ] {
            assert!(close(p, q, 1e-12), "{p} vs {q}");
        }
        assert!(x.required_gap > 0.0 && y.required_gap <= y.peak_left + y.peak_right);
    }
}
