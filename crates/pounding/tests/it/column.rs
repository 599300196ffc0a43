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
    // Each end force is the load's part (the shape functions b^2 (3a + b) / L^3, a^2 (3b + a) / L^3 and the
    // moments a b^2 / L^2, a^2 b / L^2 times the force at the point) plus the drift's (12 EI / L^3 and
    // 6 EI / L^2 times the storey's drift, B's storey 1 here): so each peak is within the load part's peak of
    // the drift part's. Without contact the load part is the point's inertia only, and the drift's dominates.
    let (a, b, l, ei) = (3.0, 0.6, 3.6f64, 5.333e7);
    let load = [
        b * b * (3.0 * a + b) / l.powi(3),
        a * a * (3.0 * b + a) / l.powi(3),
        a * b * b / (l * l),
        a * a * b / (l * l),
    ];
    let bend = [
        12.0 * ei / l.powi(3),
        12.0 * ei / l.powi(3),
        6.0 * ei / (l * l),
        6.0 * ei / (l * l),
    ];
    let within = |r: &pounding::analysis::Results, what: &str| {
        let c = r.sites[0].column.as_ref().unwrap();
        let drift = r.buildings[1].peak_drift[0];
        let ends = [
            c.peak_shear.0,
            c.peak_shear.1,
            c.peak_moment.0,
            c.peak_moment.1,
        ];
        for k in 0..4 {
            let gap = (ends[k] - bend[k] * drift).abs();
            assert!(
                gap <= load[k] * c.peak_force * (1.0 + 1e-9),
                "{what}, end force {k}: {} vs drift part {} (load part at most {})",
                ends[k],
                bend[k] * drift,
                load[k] * c.peak_force
            );
        }
        c.clone()
    };
    let c = within(&r, "pounding");
    assert!(c.shear_exceeded.is_some() && c.moment_exceeded.is_none());
    let off = s.clone().with_contacts_off().run().unwrap();
    let c = within(&off, "without contact");
    assert!(load[0] * c.peak_force < 0.2 * bend[0] * off.buildings[1].peak_drift[0]);
    // The column's point meets the slab with the mass it carries (Rayleigh's equivalent mass of its static
    // deflection, normalised at the point: above the column's own this close to an end), in series with
    // the slab's floor.
    let (mp, ms) = (col.point_mass(), 4.0e5);
    assert!((s.effective_mass(site, 0) - mp * ms / (mp + ms)).abs() < 1e-9 * mp);
}

/// A column struck in a building on a foundation hangs from the foundation and turns with its rocking: with
/// rigid storeys the struck point moves as the rigid body, `u_f + z theta` at its elevation `z`, so each
/// contact's largest closing is the slab's floor less that (sampled every 1 ms: within 2e-3, where a point
/// hung from the free field missed by 1.6 % and 2.5 %).
#[test]
fn a_column_on_a_foundation_moves_with_it() {
    use pounding::structure::{Foundation, Shape, Soil};
    let soil = Soil::HalfSpace {
        vs: 100.0,
        density: 1800.0,
        poisson: 0.33,
        shape: Shape::Disk(6.0),
    };
    let tall = ShearBuilding::new(vec![5.0e5; 2], vec![1.0e12; 2], vec![3.6; 2], 0.05)
        .unwrap()
        .with_foundation(Foundation::new(4.0e5, None, soil).unwrap())
        .unwrap();
    let low = ShearBuilding::new(vec![4.0e5; 2], vec![4.0e8; 2], vec![3.0; 2], 0.05).unwrap();
    let mut s = Scenario::new(
        vec![
            Building {
                name: "A".into(),
                structure: low,
            },
            Building {
                name: "B".into(),
                structure: tall,
            },
        ],
        Record::el_centro_1940(),
    )
    .unwrap()
    .with_duration(4.0)
    .unwrap()
    .with_output_dt(0.001)
    .unwrap();
    for floor in [1, 2] {
        s = s
            .with_column_contact(ColumnLinkSpec {
                gap: 1.0,
                ..spec(floor)
            })
            .unwrap();
    }
    let r = s.run().unwrap();
    assert!(r.impacts.is_empty());
    let h = &r.histories;
    let (sway, rocking) = (&h.foundation[1][0], &h.foundation[1][1]);
    for (site, (floor, z)) in [(1usize, 3.0), (2, 6.0)].into_iter().enumerate() {
        let sampled = (0..h.t.len())
            .map(|k| h.displacement[0][floor - 1][k] - (sway[k] + z * rocking[k]))
            .fold(f64::MIN, f64::max);
        let got = r.sites[site].max_closing[0];
        assert!(
            (got / sampled - 1.0).abs() < 2e-3,
            "floor {floor}: closing {got} vs the rigid body's {sampled}"
        );
    }
}
