//! Floor-to-column contacts: a slab meeting a neighbour's floor is the floor contact, a slab striking a
//! column between floors loads the column by its shape functions, and the energy balances.

use pounding::analysis::{Building, ColumnLinkSpec, Scenario};
use pounding::contact::{ContactModel, Model};
use pounding::ground_motion::Record;
use pounding::structure::ShearBuilding;

/// A 3-storey building with storeys of 3 m beside a 2-storey one with storeys of `h2` m.
fn row(h2: f64) -> Scenario {
    let b = |name: &str, n: usize, k: f64, h: f64| Building {
        name: name.into(),
        structure: ShearBuilding::new(vec![4.0e5; n], vec![k; n], vec![h; n], 0.05).unwrap(),
    };
    Scenario::new(
        vec![b("A", 3, 4.0e8, 3.0), b("B", 2, 1.0e8, h2)],
        Record::el_centro_1940(),
    )
    .unwrap()
    .with_duration(6.0)
    .unwrap()
}

fn spec(floor: usize) -> ColumnLinkSpec {
    ColumnLinkSpec {
        slab: ("A".into(), floor),
        column: "B".into(),
        gap: 0.01,
        contact: ContactModel::new(Model::Papi, 2.0e9, 0.65).unwrap(),
        ei: 5.333e7,
        mass: 1500.0,
        shear_capacity: Some(2.0e6),
        moment_capacity: None,
    }
}

#[test]
fn a_slab_meeting_a_floor_is_the_floor_contact() {
    let floor = row(3.0)
        .with_link(
            "A",
            "B",
            0.01,
            &ContactModel::new(Model::Papi, 2.0e9, 0.65).unwrap(),
            Some(vec![(2, 2)]),
        )
        .unwrap()
        .run()
        .unwrap();
    let column = row(3.0).with_column_contact(spec(2)).unwrap();
    assert!(column.sites()[0].column.as_ref().unwrap().struck.is_none());
    let column = column.run().unwrap();
    assert_eq!(floor.buildings, column.buildings);
    assert_eq!(floor.impacts.len(), column.impacts.len());
    for (a, b) in floor.impacts.iter().zip(&column.impacts) {
        assert_eq!((a.time, a.v_i, a.peak_force), (b.time, b.v_i, b.peak_force));
    }
}

#[test]
fn a_slab_striking_a_column_loads_it_by_its_shape_functions() {
    // B's storeys are 3.6 m: A's floor 1 (3 m) strikes B's first-storey column at a = 3.0 m of 3.6.
    let s = row(3.6).with_column_contact(spec(1)).unwrap();
    let site = &s.sites()[0];
    let col = site.column.as_ref().unwrap().struck.unwrap();
    assert!((col.a - 3.0).abs() < 1e-12 && (col.length - 3.6).abs() < 1e-12);
    assert_eq!(site.levels[0].left, Some(1));
    let r = s.run().unwrap();
    assert!(!r.impacts.is_empty(), "the slab strikes the column");
    assert!(
        r.energy.relative_error < 1e-6,
        "{}",
        r.energy.relative_error
    );
    let c = r.sites[0].column.as_ref().unwrap();
    // End shears in the ratio of the shape functions b^2 (3a + b) : a^2 (3b + a), summing to the force.
    let (a, b, l) = (3.0, 0.6, 3.6f64);
    let lower = b * b * (3.0 * a + b) / l.powi(3);
    assert!((c.peak_shear.0 / c.peak_force - lower).abs() < 1e-12);
    assert!(((c.peak_shear.0 + c.peak_shear.1) / c.peak_force - 1.0).abs() < 1e-12);
    assert!((c.peak_moment.1 / c.peak_force - a * a * b / (l * l)).abs() < 1e-12);
    assert!(c.shear_exceeded.is_some() && c.moment_exceeded.is_none());
    // The column's point meets the slab with the mass it carries (Rayleigh's equivalent mass of its static
    // deflection, normalised at the point: above the column's own this close to an end), in series with
    // the slab's floor.
    let (mp, ms) = (col.point_mass(), 4.0e5);
    assert!((s.effective_mass(site, 0) - mp * ms / (mp + ms)).abs() < 1e-9 * mp);
}
