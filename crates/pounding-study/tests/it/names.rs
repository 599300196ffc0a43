//! Degrees of freedom by name (`dof_names`, issue 27): a structure given by its matrices, its floors named as
//! the program that condensed it named them; contacts, walls, devices and column contacts name them. A name
//! is its floor's number exactly; a name that is not there gets one line naming the key, the value and the
//! names allowed.

use pounding_study::input::{dict_message, from_value};
use serde_json::{json, Value};

/// A 3-floor frame given by its matrices (floors named L1, L2, roof) beside a 2-storey shear building, a
/// wall on the frame's left; contact, wall, device and column contact name floors by `f(building, number)`.
fn pair(f: impl Fn(&str, usize) -> Value) -> Value {
    json!({
        "ground_motion": {"record": "el-centro-1940"},
        "analysis": {"duration": 3.0},
        "building": [
            {"name": "frame", "masses": [4.0e5, 4.0e5, 3.0e5], "heights": [3.0, 3.0, 3.0],
             "stiffness_matrix": [[9.0e8, -4.5e8, 5.0e7], [-4.5e8, 7.5e8, -3.0e8], [5.0e7, -3.0e8, 2.6e8]],
             "dof_names": ["L1", "L2", "roof"]},
            {"name": "shear", "masses": [5.0e5, 5.0e5], "stiffnesses": [2.0e8, 1.5e8], "heights": [3.0, 4.5],
             "dof_names": ["ground floor", "top"]},
        ],
        "contact": [{"between": ["frame", "shear"], "gap": 0.002, "floors": [[f("frame", 1), f("shear", 1)]],
                     "model": "hooke", "stiffness": 1.0e9, "stiffness_unit": "N/m"}],
        "wall": [{"name": "W", "facing": "frame", "side": "left", "gap": 0.004, "floors": [f("frame", 3)],
                  "model": "hooke", "stiffness": 1.0e9, "stiffness_unit": "N/m"}],
        "device": [{"between": ["frame", "shear"], "floors": [[f("frame", 1), f("shear", 1)]],
                    "model": "spring", "stiffness": 1.0e6}],
        "column_contact": [{"slab": ["frame", f("frame", 2)], "column": "shear", "gap": 0.003, "EI": 5.333e7,
                            "column_mass": 2.0e3, "model": "hooke", "stiffness": 1.0e9,
                            "stiffness_unit": "N/m"}],
    })
}

fn name(building: &str, number: usize) -> Value {
    let names: &[&str] = match building {
        "frame" => &["L1", "L2", "roof"],
        _ => &["ground floor", "top"],
    };
    json!(names[number - 1])
}

#[test]
fn a_floor_by_name_is_its_number() {
    let by_number = from_value(&pair(|_, n| json!(n)), "<dict>").unwrap();
    let by_name = from_value(&pair(name), "<dict>").unwrap();
    let (a, b) = (
        by_number.scenario.run().unwrap(),
        by_name.scenario.run().unwrap(),
    );
    // Something happened at every named floor: impacts at the contact, the wall and the column.
    for (k, site) in a.sites.iter().enumerate() {
        assert!(site.impacts > 0, "site {k}: no impact");
    }
    assert_eq!(a.sites.len(), b.sites.len());
    for (x, y) in a.sites.iter().zip(&b.sites) {
        assert_eq!((x.impacts, x.peak_force), (y.impacts, y.peak_force));
    }
    for (x, y) in a.buildings.iter().zip(&b.buildings) {
        assert_eq!(x.peak_displacement, y.peak_displacement);
    }
    assert_eq!(a.devices[0].peak_force, b.devices[0].peak_force);
    // A floor by number beside one by name: the same again.
    let mixed = from_value(
        &pair(|b, n| if b == "frame" { json!(n) } else { name(b, n) }),
        "<dict>",
    )
    .unwrap();
    let c = mixed.scenario.run().unwrap();
    assert_eq!(c.sites[0].peak_force, a.sites[0].peak_force);
}

/// The one-line message of `v`.
fn message(v: &Value) -> String {
    let (key, msg) = from_value(v, "<dict>").map(|_| ()).unwrap_err();
    let line = pounding_study::one_line(&dict_message(key, msg), 299);
    assert!(!line.contains('\n') && line.chars().count() < 300, "{line}");
    line
}

#[test]
fn a_name_that_is_not_there_is_refused_with_the_names_allowed() {
    let mut v = pair(name);
    v["contact"][0]["floors"][0][0] = json!("attic");
    let m = message(&v);
    assert!(
        m.contains("contact.0.floors") && m.contains("\"attic\""),
        "{m}"
    );
    assert!(m.contains("\"L1\", \"L2\", \"roof\""), "{m}");
    // On the shear building's side, its own names.
    let mut v = pair(name);
    v["contact"][0]["floors"][0][1] = json!("roof");
    let m = message(&v);
    assert!(m.contains("\"ground floor\", \"top\""), "{m}");
    // A building without names: floors by number.
    let mut v = pair(name);
    v["building"][1]
        .as_object_mut()
        .unwrap()
        .remove("dof_names");
    let m = message(&v);
    assert!(
        m.contains("has no dof_names") && m.contains("\"ground floor\""),
        "{m}"
    );
    // The wall's, the device's and the column contact's keys.
    for (path, key) in [
        (&["wall", "0", "floors", "0"][..], "wall.0.floors"),
        (&["device", "0", "floors", "0", "1"][..], "device.0.floors"),
        (
            &["column_contact", "0", "slab", "1"][..],
            "column_contact.0.slab",
        ),
    ] {
        let mut v = pair(name);
        let mut at = &mut v;
        for p in path {
            at = match p.parse::<usize>() {
                Ok(i) => &mut at[i],
                Err(_) => &mut at[*p],
            };
        }
        *at = json!("cellar");
        let m = message(&v);
        assert!(m.contains(key) && m.contains("\"cellar\""), "{key}: {m}");
    }
}

#[test]
fn dof_names_are_one_per_floor_each_its_own() {
    let mut v = pair(name);
    v["building"][0]["dof_names"] = json!(["L1", "roof"]);
    let m = message(&v);
    assert!(
        m.contains("building.0.dof_names") && m.contains("2 names") && m.contains("3 floors"),
        "{m}"
    );
    v["building"][0]["dof_names"] = json!(["L1", "L1", "roof"]);
    let m = message(&v);
    assert!(m.contains("\"L1\" is given twice"), "{m}");
    v["building"][0]["dof_names"] = json!(["L1", "", "roof"]);
    let m = message(&v);
    assert!(m.contains("dof name \"\" is not allowed"), "{m}");
    // A floor is a whole number from 1 or a name: a negative number says so.
    let mut v = pair(name);
    v["contact"][0]["floors"][0][0] = json!(-2);
    let m = message(&v);
    assert!(
        m.contains("floor -2 is not allowed: a floor number from 1, or a name"),
        "{m}"
    );
}
