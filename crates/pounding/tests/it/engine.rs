//! The engine's element interface beyond floors side by side: a contact from a floor to the ground (a rigid
//! wall) delivers the single-impact restitution with the floor's own mass.

use pounding::contact::{ContactModel, Model};
use pounding::element::{Contact, Element, End, Notice};
use pounding::engine::{self, Dof, EventInfo, Ground, Observer, Segment, Settings, System};
use pounding::impact::exact;

/// What each event said, and the velocity of the floor there, m/s.
#[derive(Default)]
struct Velocities(Vec<(Option<Notice>, f64)>);

impl Observer for Velocities {
    fn segment(&mut self, _seg: &Segment<'_, '_>) {}
    fn event(&mut self, ev: &EventInfo<'_, '_>) {
        self.0.push((ev.notice, ev.y[ev.system.layout().v(0)]));
    }
}

#[test]
fn a_floor_against_a_rigid_wall_delivers_the_single_impact_e() {
    // A free floor of 2e5 kg moving right at 0.3 m/s strikes a wall 10 mm to its right (a contact from the
    // floor, end a, to the ground, end b: penetration u - gap), and on the left of a second floor moving left
    // (end a the ground: penetration -u - gap).
    let m = 2.0e5;
    for (side, v0) in [("right", 0.3), ("left", -0.3)] {
        for model in [Model::Papi, Model::Hertzdamp, Model::KelvinVoigt] {
            let k = if model == Model::Hertzdamp {
                2.0e10
            } else {
                2.0e9
            };
            let spec = ContactModel::new(model, k, 0.65).unwrap();
            let contact = Contact::new(spec.prepare().unwrap(), 0.01, m, 1e-3);
            let (a, b) = if side == "right" {
                (End::Dof(0), End::Ground)
            } else {
                (End::Ground, End::Dof(0))
            };
            let mut sys = System::new(
                &[Dof::x(m, 0.0)],
                vec![Element::new(a, b, contact)],
                Ground::Constant(0.0),
            );
            let l = sys.layout().clone();
            let mut y0 = vec![0.0; l.dim()];
            y0[l.v(0)] = v0;
            let rtol = 1e-11;
            let mut atol = vec![rtol * m * 0.09; l.dim()];
            atol[l.u(0)] = rtol * 0.01;
            atol[l.v(0)] = rtol * 0.3;
            let settings = Settings {
                t_end: 0.2,
                rtol,
                atol,
                h0: 1e-4,
                max_steps: 1_000_000,
                propagation: pounding::engine::Propagation::default(),
            };
            let mut obs = Velocities::default();
            engine::run(&mut sys, (0.0, &y0), &settings, &mut obs).unwrap();
            let touch = obs
                .0
                .iter()
                .find(|e| matches!(e.0, Some(Notice::ImpactStarted { .. })))
                .unwrap()
                .1;
            let end = obs
                .0
                .iter()
                .find(|e| matches!(e.0, Some(Notice::ImpactEnded | Notice::ImpactReleased)))
                .unwrap()
                .1;
            let law = spec.prepare().unwrap().law(m, v0.abs()).unwrap().0;
            let e_exact = exact::e_post(&law, spec.tension(), m, v0.abs()).unwrap();
            assert!(
                (touch - v0).abs() < 1e-12,
                "{side} {model}: touch at {touch}"
            );
            assert!(
                (-end / touch - e_exact).abs() < 1e-8,
                "{side} {model}: e = {} vs {e_exact}",
                -end / touch
            );
        }
    }
}

#[test]
fn a_floor_s_acceleration_alone_is_its_entry_of_the_right_hand_side() {
    // A floor in plan (x, y, rotation) on Bouc–Wen and linear lines from its points to the ground (its
    // points on either end), a contact from it to a second floor on a support of its own, and that support
    // driven by a record of its own, tied to the first floor too: System::acceleration, which sums the
    // elements acting on one degree of freedom, against the same entry of the whole right-hand side, bit for
    // bit, at states spread over a few magnitudes.
    use pounding::element::{Point, StoreyLaw};
    use pounding::engine::Axis;
    use pounding::ground_motion::Record;
    use pounding::integrate::OdeSystem;
    let records = [
        Record::new("a", 0.01, 0.0, vec![0.0, 1.2, -0.7, 2.1, 0.4]).unwrap(),
        Record::new("b", 0.01, 0.0, vec![0.0, -0.5, 1.9, -1.1, 0.8]).unwrap(),
    ];
    let dof = |mass: f64, a0: f64, axis: Axis| Dof { mass, a0, axis };
    let dofs = [
        dof(3.0e5, 0.1, Axis::X),
        dof(3.0e5, 0.1, Axis::Y),
        dof(4.0e6, 0.1, Axis::Rotation),
        dof(2.0e5, 0.2, Axis::On(1)),
        dof(1.0, 0.0, Axis::Driven(1)),
    ];
    let corner = |rx: f64, ry: f64, along_x: bool| {
        // A point at (rx, ry) from the mass centre, along x or y: n_x u_x + n_y u_y + (r x n) theta.
        if along_x {
            Point::new(&[(0, 1.0), (2, -ry)])
        } else {
            Point::new(&[(1, 1.0), (2, rx)])
        }
    };
    let bouc_wen = StoreyLaw::bouc_wen(4.0e5, 0.1, 2.0, 0.5, 0.5).unwrap();
    let spec = ContactModel::new(Model::KelvinVoigt, 2.0e9, 0.65).unwrap();
    let elements = vec![
        Element::new(
            End::Point(corner(4.0, 3.0, true)),
            End::Ground,
            bouc_wen.law(6.0e7),
        )
        .with_dashpot(2.0e5),
        Element::new(
            End::Point(corner(-4.0, 3.0, false)),
            End::Ground,
            StoreyLaw::Linear.law(5.0e7),
        ),
        Element::new(
            End::Point(corner(-4.0, -3.0, true)),
            End::Ground,
            StoreyLaw::Linear.law(4.0e7),
        ),
        Element::new(
            End::Dof(3),
            End::Point(corner(4.0, 0.0, true)),
            Contact::new(spec.prepare().unwrap(), 0.0, 3.0e5, 1e-3),
        ),
        Element::new(End::Dof(3), End::Dof(4), StoreyLaw::Linear.law(3.0e7)).with_dashpot(1.0e5),
        // Points on end b: the force acts +f there.
        Element::new(
            End::Ground,
            End::Point(corner(-4.0, -3.0, false)),
            StoreyLaw::Linear.law(2.0e7),
        ),
        Element::new(
            End::Dof(4),
            End::Point(corner(4.0, -3.0, true)),
            StoreyLaw::Linear.law(1.0e7),
        )
        .with_dashpot(5.0e4),
    ];
    let sys = System::new(&dofs, elements, Ground::Many(&records));
    let l = sys.layout().clone();
    let mut dy = vec![0.0; l.dim()];
    let mut ds = vec![0.0; l.dim()];
    let mut checked = 0;
    for k in 0..40 {
        let t = 0.001 * k as f64;
        // Deterministic states of mixed signs and sizes (|y| up to 5e-3, 5e-2 or 0.5 in SI units), Bouc–Wen's
        // z inside its bound of 1.
        let y: Vec<f64> = (0..l.dim())
            .map(|j| {
                let s = ((j * 7 + k * 13) % 17) as f64 / 17.0 - 0.5;
                s * 10f64.powi(-(((j + k) % 3) as i32))
            })
            .collect();
        sys.rhs(t, &y, &mut dy);
        for i in 0..l.dofs() {
            let a = sys.acceleration(i, t, &y, &mut ds);
            assert_eq!(
                a.to_bits(),
                dy[l.v(i)].to_bits(),
                "dof {i} at t = {t}: {a} vs {}",
                dy[l.v(i)]
            );
            checked += 1;
        }
    }
    assert_eq!(checked, 40 * dofs.len());
}
