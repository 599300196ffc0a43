//! `pounding separation`: the separation each pair of neighbours needs, against the code rules.

use crate::args::SeparationArgs;
use crate::error::{input, CliError};
use crate::files::{check_out, save_out};
use pounding_study::separation::{PairReport, SeparationReport, Stats};
use std::path::Path;

/// `pounding separation`.
pub fn run(a: &SeparationArgs) -> Result<(), CliError> {
    let file = pounding_study::input::ScenarioFile::read(&a.scenario).map_err(|e| input(e.0))?;
    // The scenario itself is checked with file and line first, and its likely unit slips said.
    for w in file.load().map_err(|e| input(e.0))?.scenario.implausible() {
        eprintln!("warning: {w}");
    }
    let mut records = Vec::new();
    for r in &a.records {
        records.extend(
            pounding_study::study::record_sources(
                Path::new("."),
                &serde_json::Value::String(r.clone()),
            )
            .map_err(|m| input(format!("--{m}")))?,
        );
    }
    let label = a.scenario.display().to_string();
    check_out(&a.out)?;
    let v = pounding_study::separation::report_with(
        &file.value,
        &label,
        &records,
        a.aligned_factor,
        &mut crate::interrupt::go_on,
    )
    .map_err(|(k, m)| {
        if crate::interrupt::pressed() {
            CliError::Interrupted("the separation stopped; nothing was written".into())
        } else {
            let m = pounding_study::input::dict_message(k, m);
            input(m.replace("aligned_factor = ", "--aligned-factor "))
        }
    })?;
    let fig = crate::plot::analyses::separation(
        &v,
        &format!("{label}; {} record(s)", records.len().max(1)),
    );
    if a.json {
        println!("{}", serde_json::to_string_pretty(&v).expect("JSON"));
        return save_out(&a.out, ("separation", &v), Vec::new(), &[fig], true);
    }
    print(&v);
    save_out(&a.out, ("separation", &v), Vec::new(), &[fig], false)
}

/// Millimetres per metre, for the terminal.
const MM: f64 = 1e3;

/// The report as tables on the terminal, lengths in mm (separation.json holds m).
fn print(v: &SeparationReport) {
    let table = |pairs: &[PairReport]| {
        for p in pairs {
            for l in &p.levels {
                println!(
                    "{:<20} {:>3}-{:<3} {:>12.2}  {:>13.2}  {:>15.2}  {:>8.2}  {:>8.2}  {:>8.2}  {:.4}",
                    p.between.join("|"),
                    l.floors.0,
                    l.floors.1,
                    MM * l.peak_left,
                    MM * l.peak_right,
                    MM * l.required_gap,
                    MM * l.abs,
                    MM * l.srss,
                    MM * l.ddc,
                    l.rho
                );
            }
        }
    };
    println!("required separation (a run without contact) and the rules' estimates, mm (separation.json holds m)");
    println!("pair                 floors  peak_left_mm  peak_right_mm  required_gap_mm    abs_mm   srss_mm    ddc_mm  rho");
    let (records, statistics) = match v {
        SeparationReport::One { pairs, .. } => return table(pairs),
        SeparationReport::Suite {
            records,
            statistics,
            ..
        } => (records, statistics),
    };
    for r in records {
        println!("\nrecord {}", r.record);
        table(&r.pairs);
    }
    type Pick = fn(&Stats) -> f64;
    let stats: [(&str, Pick); 3] = [
        ("mean", |s| s.mean),
        ("median", |s| s.median),
        ("p84", |s| s.p84),
    ];
    for (stat, pick) in stats {
        println!("\n{stat} over {} records", records.len());
        for p in &statistics.pairs {
            for l in &p.levels {
                println!(
                    "{:<20} {:>3}-{:<3} {:>12.2}  {:>13.2}  {:>15.2}  {:>8.2}  {:>8.2}  {:>8.2}",
                    p.between.join("|"),
                    l.floors.0,
                    l.floors.1,
                    MM * pick(&l.peak_left),
                    MM * pick(&l.peak_right),
                    MM * pick(&l.required_gap),
                    MM * pick(&l.abs),
                    MM * pick(&l.srss),
                    MM * pick(&l.ddc)
                );
            }
        }
    }
}
