//! The headline results of a run, one row per run: what `runs.csv` of a sweep holds and what Python's
//! `pounding.headline` puts in a DataFrame.

use serde_json::Value;

/// `(column, value)` pairs of one run's summary, with units in the column names: the record's PGA, each
/// building's largest floor displacement and storey drift ratio (and its isolator's displacement), each
/// contact's and wall's impacts, peak force and largest penetration, the energy balance error and the
/// integration steps.
pub fn headline(summary: &Value) -> Vec<(String, Value)> {
    let mut row = vec![("pga_m_per_s2".to_string(), summary["record"]["pga"].clone())];
    let max = |v: &Value| {
        v.as_array()
            .into_iter()
            .flatten()
            .filter_map(Value::as_f64)
            .fold(None, |m: Option<f64>, x| Some(m.map_or(x, |m| m.max(x))))
            .map_or(Value::Null, |x| serde_json::json!(x))
    };
    for b in summary["buildings"].as_array().into_iter().flatten() {
        let name = b["name"].as_str().unwrap_or("?");
        row.push((
            format!("{name}_peak_displacement_m"),
            max(&b["peak_displacement"]),
        ));
        row.push((
            format!("{name}_peak_drift_ratio"),
            max(&b["peak_drift_ratio"]),
        ));
        if b["isolator"].is_object() {
            row.push((
                format!("{name}_isolator_displacement_m"),
                b["isolator"]["peak_displacement"].clone(),
            ));
        }
    }
    let contacts = summary["contacts"].as_array().into_iter().flatten();
    let walls = summary["walls"].as_array().into_iter().flatten();
    for c in contacts.chain(walls) {
        let pair: Vec<&str> = c["between"]
            .as_array()
            .into_iter()
            .flatten()
            .filter_map(Value::as_str)
            .collect();
        // A wall by its name.
        let name = c["name"].as_str().map_or(pair.join("|"), String::from);
        row.push((format!("{name}_impacts"), c["impacts"].clone()));
        row.push((format!("{name}_peak_force_N"), c["peak_force"].clone()));
        row.push((
            format!("{name}_max_penetration_m"),
            c["max_penetration"].clone(),
        ));
    }
    row.push((
        "energy_balance_error".to_string(),
        summary["energy_balance_error"].clone(),
    ));
    row.push(("steps".to_string(), summary["statistics"]["steps"].clone()));
    row
}

/// One CSV field: quoted if it holds a comma, a quote or a line break.
pub fn csv_field(s: &str) -> String {
    if s.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

/// A JSON value as a CSV field: numbers and strings as they are, nothing for null.
pub fn csv_value(v: &Value) -> String {
    match v {
        Value::Null => String::new(),
        Value::String(s) => csv_field(s),
        other => csv_field(&other.to_string()),
    }
}
