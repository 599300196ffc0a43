//! The JSON Schemas of the files users write and read: a scenario (`docs/scenario.schema.json`, what a
//! scenario file or a Python dict holds) and a run's summary (`docs/summary.schema.json`), generated from
//! their types, so that a renamed key changes the schema and a test notices. The scenario's schema also
//! refuses lists where tables belong ([`crate::shape`]).

use crate::summary::RunSummary;

/// The JSON Schema of a scenario, pretty-printed with a final newline.
pub fn scenario() -> String {
    serde_json::to_string_pretty(crate::shape::scenario_schema()).expect("a schema is JSON") + "\n"
}

/// The JSON Schema of a run's summary, pretty-printed with a final newline.
pub fn summary() -> String {
    RunSummary::json_schema()
}
