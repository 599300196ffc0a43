//! The study store keeps each run's summary without the units every run shares: the rows are a third of the
//! size, the study table holds the units once, and a summary read back is the whole summary of the run.

use pounding::analysis::RunOptions;
use pounding_study::store::Store;
use pounding_study::summary::RunSummary;
use pounding_study::sweep;
use serde_json::{json, Value};
use std::ops::ControlFlow;
use std::sync::atomic::AtomicBool;

/// Two one-storey buildings 10 mm apart for two seconds of El Centro, the gap of run `i`.
fn pair(i: usize) -> Value {
    json!({
        "ground_motion": {"record": "el-centro-1940"},
        "analysis": {"duration": 2.0},
        "building": [
            {"name": "a", "masses": [5.0e5], "stiffnesses": [7.8957e7], "heights": [3.0]},
            {"name": "b", "masses": [5.0e5], "stiffnesses": [1.9739e7], "heights": [3.0]},
        ],
        "contact": [{"between": ["a", "b"], "gap": 0.005 * i as f64, "model": "hooke",
                     "stiffness": 2.0e9, "stiffness_unit": "N/m"}],
    })
}

#[test]
fn a_stored_row_leaves_out_the_units_and_reads_back_whole() {
    let dir = std::env::temp_dir().join(format!("pounding-store-units-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("study.sqlite");
    let scenarios = |i: usize| (pair(i), format!("run {i}"));
    let mut store = Store::open(&path, "units-test", 2, &Vec::new).unwrap();
    let options = RunOptions::default();
    let swept = sweep::run(2, &scenarios, 1, &options, Some(&mut store), &mut |_| {
        ControlFlow::Continue(())
    })
    .unwrap();
    // Each run as a single run gives it: the whole summary, units included.
    let cancel = AtomicBool::new(false);
    let prepared = sweep::prepare((0..2).map(scenarios).collect(), 1);
    let conn = rusqlite::Connection::open(&path).unwrap();
    let units: String = conn
        .query_row("SELECT value FROM study WHERE name = 'units'", [], |r| {
            r.get(0)
        })
        .unwrap();
    for (i, p) in prepared.iter().enumerate() {
        let whole = sweep::run_one(p, &options, &cancel).unwrap();
        assert!(!whole.units.is_empty());
        let row: String = conn
            .query_row("SELECT summary FROM runs WHERE idx = ?1", [i as i64], |r| {
                r.get(0)
            })
            .unwrap();
        let row_value: Value = serde_json::from_str(&row).unwrap();
        assert!(row_value.get("units").is_none(), "{row}");
        let full = whole.to_value().to_string();
        assert!(
            row.len() * 2 < full.len(),
            "{} of {}",
            row.len(),
            full.len()
        );
        // The units once in the study table, equal to a run's.
        assert_eq!(
            serde_json::from_str::<Value>(&units).unwrap(),
            json!(whole.units)
        );
        // Read back (through the sweep's outcome, as runs.csv is written), the summary is the run's.
        let text = swept.outcome(i, Some(&store)).unwrap().unwrap();
        let back = RunSummary::from_json(&text).unwrap();
        assert_eq!(back, whole);
        assert_eq!(RunSummary::row_to_whole(&row), full);
        assert_eq!(RunSummary::whole_to_row(&full), row);
        // The row is the summary's value without `units`, written: cut out of the text for the shared
        // units, from the value for units of its own.
        let without_units = |s: &RunSummary| {
            let mut v = s.to_value();
            v.as_object_mut().unwrap().shift_remove("units");
            v.to_string()
        };
        assert_eq!(row, without_units(&whole));
        let mut own = whole.clone();
        own.units = serde_json::from_str(r#"{"duration": "s"}"#).unwrap();
        assert!(whole.units.is_shared() && !own.units.is_shared());
        assert_eq!(own.to_row(), without_units(&own));
    }
    drop(store);
    let _ = std::fs::remove_dir_all(&dir);
}

/// A summary names the first number of its results that is not finite, found past the text it is written
/// as; a name that says "null" is no such number.
#[test]
fn a_summary_refuses_a_result_that_is_not_finite_and_only_that() {
    let mut value = pair(1);
    value["building"][0]["name"] = json!("null");
    value["contact"][0]["between"] = json!(["null", "b"]);
    let loaded = pounding_study::input::from_value(&value, "null pair").unwrap();
    let mut results = loaded.scenario.run().unwrap();
    let summary = RunSummary::new(&loaded, &results).unwrap();
    assert_eq!(summary.buildings[0].name, "null");
    results.buildings[1].peak_displacement[0] = f64::NAN;
    let e = RunSummary::new(&loaded, &results).unwrap_err();
    assert!(
        e.starts_with(
            "the result summary.buildings[1].peak_displacement[0] is not a finite number"
        ),
        "{e}"
    );
}
