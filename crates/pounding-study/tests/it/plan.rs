//! Buildings in plan given as values (a scenario file, a Python dict): bad plans, lines, façades and points
//! get one line naming the key, the value and what is allowed.

use pounding_study::input::{dict_message, from_value};
use serde_json::{json, Value};

/// Two one-storey buildings in plan, their façades facing along x 20 mm apart, B shifted north by 4 m.
fn two_in_plan() -> Value {
    let lines = |a: f64, b: f64| {
        json!([
            {"direction": "x", "at": 0.0, "stiffnesses": 1e8},
            {"direction": "x", "at": b, "stiffnesses": 1e8},
            {"direction": "y", "at": 0.0, "stiffnesses": 1e8},
            {"direction": "y", "at": a, "stiffnesses": 1e8},
        ])
    };
    json!({
        "ground_motion": {"record": "el-centro-1940", "y": {"record": "synthetic-1"}},
        "analysis": {"duration": 2.0},
        "building": [
            {"name": "A", "masses": [5.0e5], "heights": [3.0],
             "plan": {"size": [20.0, 12.0]}, "line": lines(20.0, 12.0)},
            {"name": "B", "masses": [5.0e5], "heights": [3.0],
             "plan": {"size": [10.0, 10.0], "position": [20.02, 4.0]}, "line": lines(10.0, 10.0)},
        ],
        "contact": [{"between": ["A", "B"], "model": "papi", "stiffness": 2.0e9, "stiffness_unit": "N/m"}],
    })
}

/// The message a scenario with `change` made to it gets.
fn message(change: impl FnOnce(&mut Value)) -> String {
    let mut v = two_in_plan();
    change(&mut v);
    let (key, msg) = from_value(&v, "<dict>").map(|_| ()).unwrap_err();
    let line = pounding_study::one_line(&dict_message(key, msg), 299);
    assert!(!line.contains('\n') && line.chars().count() < 300, "{line}");
    line
}

#[test]
fn the_facades_give_the_gap_and_the_points() {
    let loaded = from_value(&two_in_plan(), "<dict>").unwrap();
    let site = &loaded.scenario.sites()[0];
    assert_eq!(site.gap, 0.02);
    let plan = site.plan.as_ref().unwrap();
    assert_eq!(plan.normal, (1.0, 0.0));
    assert_eq!(plan.points, vec![(20.0, 4.0), (20.0, 12.0)]);
    assert!(loaded.scenario.record_y().is_some());
}

#[test]
fn bad_plans_are_refused_naming_the_key() {
    // A point off the façades' overlap.
    let msg = message(|v| v["contact"][0]["points"] = json!([2.0]));
    assert!(
        msg.starts_with("contact.0.points: contact \"A\"-\"B\": points = 2 is not allowed: distinct points on the façade"),
        "{msg}"
    );
    // Façades that do not face each other: B moved north-east of A.
    let msg = message(|v| v["building"][1]["plan"]["position"] = json!([21.0, 13.0]));
    assert!(
        msg.starts_with("contact.0.position: contact \"A\"-\"B\": position = \"A\" and \"B\" is not allowed: plans whose façades face each other")
            && msg.contains("diagonally"),
        "{msg}"
    );
    // Overlapping plans.
    let msg = message(|v| v["building"][1]["plan"]["position"] = json!([19.0, 4.0]));
    assert!(msg.contains("plans that do not overlap"), "{msg}");
    // A line outside its plan.
    let msg = message(|v| v["building"][0]["line"][1]["at"] = json!(13.0));
    assert!(
        msg.starts_with("building.0.line.at: building \"A\": line.at = line 2: 13 is not allowed: inside the plan: 0 <= at <= 12 m"),
        "{msg}"
    );
    // Lines that cannot hold the floor: all through one point.
    let msg = message(|v| {
        v["building"][0]["line"] = json!([
            {"direction": "x", "at": 6.0, "stiffnesses": 1e8},
            {"direction": "y", "at": 10.0, "stiffnesses": 1e8},
        ])
    });
    assert!(
        msg.starts_with("building.0.line: building \"A\": line = these lines is not allowed")
            && msg.contains("singular"),
        "{msg}"
    );
    // A gap, which the positions give.
    let msg = message(|v| v["contact"][0]["gap"] = json!(0.05));
    assert!(
        msg.starts_with("contact.0.gap: contact \"A\"-\"B\": gap = 0.05 is not allowed between buildings in plan"),
        "{msg}"
    );
    // Stiffnesses beside a plan; a mass centre outside it; records on steps without a common divisor.
    let msg = message(|v| v["building"][0]["stiffnesses"] = json!([1e8]));
    assert!(msg.starts_with("building.0.stiffnesses: building \"A\": stiffnesses is not allowed beside [building.plan]"), "{msg}");
    let msg = message(|v| v["building"][0]["plan"]["mass_centre"] = json!([25.0, 6.0]));
    assert!(msg.starts_with("building.0.plan.mass_centres: building \"A\": plan.mass_centres = 25 is not allowed: inside the plan"), "{msg}");
    let msg = message(|v| v["ground_motion"]["angle"] = json!(400.0));
    assert!(
        msg.starts_with("ground_motion.angle: angle = 400 is not allowed"),
        "{msg}"
    );
    // A ground along y without a building in plan.
    let mut one_line = two_in_plan();
    for b in one_line["building"].as_array_mut().unwrap() {
        let o = b.as_object_mut().unwrap();
        o.remove("plan");
        o.remove("line");
        o.insert("stiffnesses".into(), json!([1e8]));
    }
    one_line["contact"][0]["gap"] = json!(0.02);
    let (key, msg) = from_value(&one_line, "<dict>").map(|_| ()).unwrap_err();
    assert_eq!(key.as_deref(), Some("ground_motion.y"));
    assert!(msg.contains("buildings in plan only"), "{msg}");
}
