//! The JSON Schemas in `docs/` are the ones the types give (run with `POUNDING_UPDATE_SCHEMAS=1` to write
//! them anew after a change of the schema), and `docs/scenarios.md` documents every key a scenario takes.

use std::path::PathBuf;

fn docs(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../docs")
        .join(name)
}

/// `generated` is the file `name` of docs/ (or becomes it, with POUNDING_UPDATE_SCHEMAS set).
fn current(name: &str, generated: &str) {
    let path = docs(name);
    if std::env::var_os("POUNDING_UPDATE_SCHEMAS").is_some() {
        std::fs::write(&path, generated).unwrap();
    }
    let on_disk = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        on_disk == generated,
        "docs/{name} is not the schema the types give: run `POUNDING_UPDATE_SCHEMAS=1 cargo test -p pounding-study` and commit it"
    );
}

#[test]
fn the_summary_schema_in_docs_is_current() {
    current("summary.schema.json", &pounding_study::schema::summary());
}

#[test]
fn the_scenario_schema_in_docs_is_current() {
    current("scenario.schema.json", &pounding_study::schema::scenario());
}

/// Every property name of a JSON Schema, however deep.
fn keys(v: &serde_json::Value, out: &mut Vec<String>) {
    match v {
        serde_json::Value::Object(m) => {
            if let Some(serde_json::Value::Object(props)) = m.get("properties") {
                out.extend(props.keys().cloned());
            }
            for x in m.values() {
                keys(x, out);
            }
        }
        serde_json::Value::Array(a) => a.iter().for_each(|x| keys(x, out)),
        _ => {}
    }
}

#[test]
fn scenarios_md_names_every_key_of_the_schema() {
    let schema: serde_json::Value =
        serde_json::from_str(&pounding_study::schema::scenario()).unwrap();
    let mut all = Vec::new();
    keys(&schema, &mut all);
    all.sort();
    all.dedup();
    // A schema too small to mean anything would pass trivially.
    assert!(all.len() > 40, "{all:?}");
    for must in [
        "gap",
        "velocity_exponent",
        "stiffness_unit",
        "yield_displacement",
    ] {
        assert!(all.iter().any(|k| k == must), "{must} in {all:?}");
    }
    let text = std::fs::read_to_string(docs("scenarios.md")).unwrap();
    // A key as `key` (or `key = ...`), or a table as [key], [[key]] or [parent.key].
    let named = |k: &str| {
        [
            format!("`{k}`"),
            format!("`{k} "),
            format!("[{k}]"),
            format!("[[{k}]]"),
            format!(".{k}]"),
        ]
        .iter()
        .any(|form| text.contains(form))
    };
    let missing: Vec<&String> = all.iter().filter(|k| !named(k)).collect();
    assert!(
        missing.is_empty(),
        "docs/scenarios.md does not name these scenario keys (as `key`): {missing:?}"
    );
}
