//! Messages about scenarios given as values (Python dicts, a study's variants): each names its key, the
//! value and what is allowed, on a line that stays short whatever the value echoes.

use pounding_study::input::{dict_message, from_value};
use serde_json::{json, Value};

fn two_buildings() -> Value {
    json!({
        "ground_motion": {"record": "el-centro-1940"},
        "building": [
            {"name": "A", "masses": [5.0e5], "stiffnesses": [7.9e7], "heights": [3.0]},
            {"name": "B", "masses": [5.0e5], "stiffnesses": [2.0e7], "heights": [3.0]},
        ],
        "contact": [{"between": ["A", "B"], "gap": 0.02, "model": "papi", "e": 0.65,
                     "stiffness": 2.0e9, "stiffness_unit": "N/m"}],
    })
}

/// The message a dict with `change` made to it gets, as Python shows it.
fn message(change: impl FnOnce(&mut Value)) -> String {
    let mut v = two_buildings();
    change(&mut v);
    let (key, msg) = from_value(&v, "<dict>").map(|_| ()).unwrap_err();
    pounding_study::one_line(&dict_message(key, msg), 299)
}

#[test]
fn a_long_unknown_key_is_named_once_cut_with_its_length() {
    let key = "k".repeat(5000);
    let msg = message(|v| v["contact"][0][&key] = json!(1.0));
    assert!(
        msg.starts_with(&format!(
            "contact.0: unknown field `{}...` (5000 characters), expected one of `between`, ",
            "k".repeat(56)
        )),
        "{msg}"
    );
    assert!(
        msg.ends_with(" in all)") && msg.chars().count() < 300,
        "{msg}"
    );
    // Under a key of its own, the part of the path is cut too.
    let msg = message(|v| v["ground_motion"][&key] = json!([1e-40]));
    assert_eq!(
        msg,
        format!(
            "ground_motion.{}... (5000 characters).0 = 1e-40 is not allowed: 0, or at least 1e-30 in magnitude (limits::MIN_MAGNITUDE: smaller numbers are zero for any structure and slow the analysis)",
            "k".repeat(16)
        )
    );
}

#[test]
fn a_misspelt_key_gets_the_first_allowed_keys_and_their_count() {
    let msg = message(|v| {
        let c = v["contact"][0].as_object_mut().unwrap();
        c.remove("e");
        c.insert("yeld_ratio".into(), json!(0.5));
    });
    assert!(
        msg.starts_with("contact.0.yeld_ratio: unknown field `yeld_ratio` (did you mean `yield_ratio`?), expected one of `between`, `gap`, "),
        "{msg}"
    );
    let count = msg.rsplit_once(", ... (").map(|t| t.1);
    assert!(
        count.is_some_and(|c| c.ends_with(" in all)")
            && c.trim_end_matches(" in all)").parse::<usize>().unwrap() > 10),
        "{msg}"
    );
    // A short list is left whole.
    let msg = message(|v| v["ground_motion"]["scael"] = json!(1.0));
    assert_eq!(
        msg,
        "ground_motion.scael: unknown field `scael` (did you mean `scale`?), expected one of `record`, `file`, `format`, `dt`, `units`, `scale`, `y`, `angle`"
    );
}

#[test]
fn a_long_model_name_is_cut_with_its_length() {
    let msg = message(|v| v["contact"][0]["model"] = json!("m".repeat(500)));
    assert!(
        msg.contains(&format!(
            "model = \"{}...\" (500 characters) is not allowed: one of hooke, hertz, ",
            "m".repeat(56)
        )) && msg.ends_with(" (17 in all)"),
        "{msg}"
    );
}
