//! The shape of a scenario value against the scenario's JSON Schema, checked before serde reads it: serde
//! reads a struct from a list by position (`analysis = [1.0, 0.01]` as duration and output step), which no
//! user means.

use pounding::scenario::ScenarioDoc;
use serde_json::Value;
use std::sync::OnceLock;

/// The scenario's JSON Schema as a value, generated once.
pub fn scenario_schema() -> &'static Value {
    static SCHEMA: OnceLock<Value> = OnceLock::new();
    SCHEMA.get_or_init(|| {
        serde_json::to_value(schemars::schema_for!(ScenarioDoc)).expect("a schema is JSON")
    })
}

/// The dotted path of the first list in the scenario `value` where its schema allows no list (a table, a
/// number, a name), if any. serde reads a struct from a list by position (`analysis = [1.0, 0.01]` as
/// duration and output step), which no user means: such a value is refused before it is read.
pub fn lists_where_tables_belong(value: &Value) -> Option<String> {
    let root = scenario_schema();
    let mut path = Vec::new();
    first_misplaced_list(value, root, root, &mut path).then(|| {
        path.reverse();
        path.join(".")
    })
}

/// Whether a misplaced list is at or below `value` (read against `schema`); `path` then holds its keys,
/// innermost first (pushed on the way out: nothing is built where none is found).
fn first_misplaced_list(
    value: &Value,
    schema: &Value,
    root: &Value,
    path: &mut Vec<String>,
) -> bool {
    // A number, a name: no list below, whatever the schema.
    if !(value.is_array() || value.is_object()) {
        return false;
    }
    let alternatives = resolve(schema, root);
    match value {
        Value::Array(items) => {
            if !alternatives.iter().any(|s| allows(s, "array")) {
                return true;
            }
            let Some(item) = alternatives.iter().find_map(|s| s.get("items")) else {
                return false;
            };
            items.iter().enumerate().any(|(i, v)| {
                let found = first_misplaced_list(v, item, root, path);
                if found {
                    path.push(i.to_string());
                }
                found
            })
        }
        Value::Object(map) => map.iter().any(|(k, v)| {
            let Some(sub) = alternatives
                .iter()
                .find_map(|s| s.get("properties").and_then(|p| p.get(k)))
            else {
                // A key the schema does not know: serde names it.
                return false;
            };
            let found = first_misplaced_list(v, sub, root, path);
            if found {
                path.push(k.clone());
            }
            found
        }),
        _ => false,
    }
}

/// The alternatives `schema` stands for: its `$ref` followed, its `anyOf` and `oneOf` expanded.
fn resolve<'a>(schema: &'a Value, root: &'a Value) -> Vec<&'a Value> {
    let mut out = Vec::new();
    let mut stack = vec![schema];
    while let Some(s) = stack.pop() {
        if let Some(r) = s.get("$ref").and_then(Value::as_str) {
            if let Some(target) = r.strip_prefix('#').and_then(|p| root.pointer(p)) {
                stack.push(target);
                continue;
            }
        }
        let mut split = false;
        for k in ["anyOf", "oneOf", "allOf"] {
            if let Some(Value::Array(alts)) = s.get(k) {
                stack.extend(alts.iter());
                split = true;
            }
        }
        if !split || s.get("type").is_some() || s.get("properties").is_some() {
            out.push(s);
        }
    }
    out
}

/// Whether `schema` (one alternative) allows the JSON type `ty`: a schema that names no type allows any.
fn allows(schema: &Value, ty: &str) -> bool {
    match schema.get("type") {
        Some(Value::String(t)) => t == ty,
        Some(Value::Array(ts)) => ts.iter().any(|t| t == ty),
        _ => schema.get("properties").is_none() && schema.get("enum").is_none(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn lists_are_refused_only_where_the_schema_has_no_list() {
        let base = json!({
            "ground_motion": {"record": "el-centro-1940"},
            "building": [{"name": "a", "masses": [1.0, 2.0], "stiffnesses": [3.0, 4.0]}],
            "contact": [{"between": ["a", "b"], "gap": 0.01}],
        });
        assert_eq!(lists_where_tables_belong(&base), None);
        let cases = [
            ("/analysis", json!([1.0, 0.01]), "analysis"),
            ("/ground_motion", json!(["el-centro-1940"]), "ground_motion"),
            ("/contact/0/gap", json!([0.01]), "contact.0.gap"),
            ("/building/0", json!(["a", [1.0], [3.0]]), "building.0"),
        ];
        for (pointer, list, key) in cases {
            let mut v = base.clone();
            match v.pointer_mut(pointer) {
                Some(slot) => *slot = list,
                None => {
                    v.as_object_mut()
                        .unwrap()
                        .insert(pointer[1..].to_string(), list);
                }
            }
            assert_eq!(
                lists_where_tables_belong(&v).as_deref(),
                Some(key),
                "{pointer}"
            );
        }
    }
}
