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
