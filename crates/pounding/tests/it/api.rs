//! The named forms of the library's entry points: `ShearBuilding::builder` and `Scenario::with_contact`
//! build what their positional forms build, and their errors name the parameter.

use pounding::analysis::{Building, Bumper, Level, LinkSpec, Scenario, SiteKind};
use pounding::contact::{ContactModel, Model};
use pounding::ground_motion::Record;
use pounding::structure::{Isolator, IsolatorModel, ShearBuilding};
use pounding::Error;

#[test]
fn the_builder_builds_what_new_builds_and_names_what_is_wrong() {
    let (m, k, h) = (vec![4.0e5, 3.5e5], vec![6.0e8, 4.0e8], vec![4.0, 3.0]);
    let named = ShearBuilding::builder()
        .heights(h.clone())
        .damping_ratio(0.03)
        .stiffnesses(k.clone())
        .masses(m.clone())
        .build()
        .unwrap();
    assert_eq!(
        named,
        ShearBuilding::new(m.clone(), k.clone(), h.clone(), 0.03).unwrap()
    );
    // The damping ratio is 0.05 unless set.
    let default = ShearBuilding::builder()
        .masses(&m[..])
        .stiffnesses(&k[..])
        .heights(&h[..])
        .build()
        .unwrap();
    assert_eq!(default.damping_ratio(), 0.05);
    // One storey: T = 2 pi sqrt(m / k) = 0.5 s for m = 5e5 kg, k = 7.8957e7 N/m.
    let one = ShearBuilding::builder()
        .masses([5.0e5])
        .stiffnesses([7.8957e7])
        .heights([3.0])
        .build()
        .unwrap();
    assert!((one.modes().periods()[0] - 0.5).abs() < 1e-4);
    let base = || {
        ShearBuilding::builder()
            .masses([1e5, 1e5])
            .stiffnesses([1e8, 1e8])
            .heights([3.0, 3.0])
    };
    let err = |b: pounding::structure::ShearBuildingBuilder| b.build().unwrap_err();
    assert!(matches!(
        err(ShearBuilding::builder().stiffnesses([1e8]).heights([3.0])),
        Error::Parameter { name: "masses", .. }
    ));
    assert!(matches!(
        err(ShearBuilding::builder().masses([1e5]).heights([3.0])),
        Error::Length {
            name: "stiffnesses",
            len: 0,
            expected: 1
        }
    ));
    assert!(matches!(
        err(ShearBuilding::builder().masses([1e5]).stiffnesses([1e8])),
        Error::Length {
            name: "heights",
            len: 0,
            expected: 1
        }
    ));
    assert!(matches!(
        err(base().damping_ratio(1.0)),
        Error::Parameter { name: "damping_ratio", value, .. } if value == 1.0
    ));
    assert!(matches!(
        err(base().stiffnesses([1e8, -1e8])),
        Error::Parameter { name: "stiffness", value, .. } if value == -1e8
    ));
}

fn row(names: &[&str]) -> Scenario {
    let buildings = names
        .iter()
        .zip([7.8957e7, 1.9739e7, 4.0e7])
        .map(|(n, k)| Building {
            name: n.to_string(),
            structure: ShearBuilding::builder()
                .masses([5.0e5])
                .stiffnesses([k])
                .heights([3.0])
                .build()
                .unwrap(),
        })
        .collect();
    Scenario::new(buildings, Record::el_centro_1940())
        .unwrap()
        .with_duration(3.0)
        .unwrap()
}

fn spec(between: [&str; 2], gap: f64, contact: &ContactModel) -> LinkSpec {
    LinkSpec {
        between: between.map(String::from),
        gap,
        floors: None,
        contact: contact.clone(),
        bumper: None,
        seat: None,
    }
}

#[test]
fn with_contact_is_with_link_with_names() {
    let papi = ContactModel::new(Model::Papi, 2.0e9, 0.65).unwrap();
    let rubber = ContactModel::new(Model::Hertz, 1.0e8, 1.0).unwrap();
    let bumper = Bumper::new(0.005, 0.5, &rubber).unwrap();
    let named = row(&["a", "b"])
        .with_contact(LinkSpec {
            // Either order, as with_link.
            between: ["b".into(), "a".into()],
            gap: 0.01,
            floors: Some(vec![(1, 1)]),
            contact: papi.clone(),
            bumper: Some(bumper.clone()),
            seat: Some(0.3),
        })
        .unwrap();
    let positional = row(&["a", "b"])
        .with_link("a", "b", 0.01, &papi, Some(vec![(1, 1)]))
        .unwrap()
        .with_link_bumper("a", "b", bumper)
        .unwrap()
        .with_link_seat("a", "b", 0.3)
        .unwrap();
    let (l, p) = (&named.sites()[0], &positional.sites()[0]);
    let level = Level {
        left: Some(1),
        right: Some(1),
    };
    let kind = SiteKind::Between { left: 0, right: 1 };
    assert_eq!(
        (l.kind, l.gap, &l.levels, l.seat, l.name.as_str()),
        (kind, 0.01, &vec![level], Some(0.3), "a|b")
    );
    assert_eq!(
        (p.kind, p.gap, &p.levels, p.seat, p.name.as_str()),
        (kind, 0.01, &vec![level], Some(0.3), "a|b")
    );
    assert!(l.bumper.is_some() && p.bumper.is_some());
    // The same scenario: the same run, impact for impact.
    let (rn, rp) = (named.run().unwrap(), positional.run().unwrap());
    assert!(!rn.impacts.is_empty());
    assert_eq!(rn, rp);
}

#[test]
fn with_contact_names_what_is_wrong() {
    let papi = ContactModel::new(Model::Papi, 2.0e9, 0.65).unwrap();
    let three = || row(&["a", "b", "c"]);
    let name_of = |e: Error| match e {
        Error::Parameter { name, .. } | Error::Choice { name, .. } => name,
        other => panic!("{other:?}"),
    };
    // Not neighbours; a building that does not exist; a negative gap; a seat of 0; a bumper thicker
    // than the gap.
    let cases = [
        (spec(["a", "c"], 0.01, &papi), "between"),
        (spec(["a", "x"], 0.01, &papi), "between"),
        (spec(["a", "b"], -0.01, &papi), "gap"),
        (
            LinkSpec {
                seat: Some(0.0),
                ..spec(["a", "b"], 0.01, &papi)
            },
            "seat",
        ),
        (
            LinkSpec {
                bumper: Some(Bumper::new(0.02, 0.5, &papi).unwrap()),
                ..spec(["a", "b"], 0.01, &papi)
            },
            "bumper.thickness",
        ),
        (
            LinkSpec {
                floors: Some(vec![(1, 2)]),
                ..spec(["a", "b"], 0.01, &papi)
            },
            "floors",
        ),
    ];
    for (s, name) in cases {
        let e = three().with_contact(s).unwrap_err();
        assert_eq!(name_of(e.clone()), name, "{e}");
    }
}

#[test]
fn the_builder_builds_isolated_buildings_as_isolated_does() {
    let iso = Isolator::new(IsolatorModel::Bilinear {
        stiffness: 1.5e8,
        yield_force: 2.2e6,
        post_yield_ratio: 0.1,
    });
    let (m, k, h) = (vec![6.0e5, 5.0e5], vec![8.0e8, 7.0e8], vec![3.0, 3.0]);
    let positional =
        ShearBuilding::isolated(8.0e5, iso, m.clone(), k.clone(), h.clone(), 0.04).unwrap();
    let named = ShearBuilding::builder()
        .isolated_on(8.0e5, iso)
        .masses(m)
        .stiffnesses(k)
        .heights(h)
        .damping_ratio(0.04)
        .build()
        .unwrap();
    assert_eq!(named, positional);
    // Slab, then two floors above it: three floors in all, the isolator the first storey.
    assert_eq!(named.storeys(), 3);
    assert!(named.isolator().is_some());
    // A deck on its bearings: no superstructure at all.
    let deck = ShearBuilding::builder()
        .isolated_on(2.0e6, iso)
        .build()
        .unwrap();
    assert_eq!(deck.storeys(), 1);
    // A bad isolator is named as the positional form names it.
    let bad = Isolator::new(IsolatorModel::Linear { stiffness: -1.0 });
    let e = ShearBuilding::builder()
        .isolated_on(8.0e5, bad)
        .build()
        .unwrap_err();
    assert!(e.to_string().contains("stiffness"), "{e}");
}
