//! `pounding separation`: the separation each pair of neighbours needs, against the code rules; its
//! probability under a random motion or over a suite, its mean annual frequency with a hazard curve.

mod options;
mod print;

use crate::args::SeparationArgs;
use crate::error::{input, CliError};
use crate::files::{check_out, save_out};
use crate::plot::analyses;
use pounding_study::separation::SeparationReport;
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
            .map_err(|e| {
                input(e.named(&format!("--records {}", crate::error::as_typed_text(r))))
            })?,
        );
    }
    let options = options::of(a, records)?;
    let label = a.scenario.display().to_string();
    check_out(&a.out)?;
    let v = pounding_study::separation::report_with(
        &file.value,
        &label,
        &options,
        &mut crate::interrupt::go_on,
    )
    .map_err(|(k, m)| {
        if crate::interrupt::pressed() {
            CliError::Interrupted("the separation stopped; nothing was written".into())
        } else {
            input(options::flagged(k, m))
        }
    })?;
    let figs = figures(&v, &label, options.records.len());
    if a.json {
        println!("{}", serde_json::to_string_pretty(&v).expect("JSON"));
    } else {
        print::report(&v);
    }
    save_out(&a.out, ("separation", &v), Vec::new(), &figs, a.json)
}

/// The figures of a report: the rules against the runs' answers, and the probability or the annual
/// frequency against the gap.
fn figures(v: &SeparationReport, label: &str, records: usize) -> Vec<crate::plot::Figure> {
    let subtitle = format!("{label}; {} record(s)", records.max(1));
    match v {
        SeparationReport::One { .. } => vec![analyses::separation(v, &subtitle)],
        SeparationReport::Suite { .. } => vec![
            analyses::separation(v, &subtitle),
            analyses::separation_probability(v, &subtitle),
        ],
        SeparationReport::WhiteNoise(_) => {
            vec![analyses::separation_probability(v, label)]
        }
        SeparationReport::Risk(_) => vec![analyses::separation_risk(v, &subtitle)],
    }
}
