//! `pounding fit restitution|force-history`: contact laws fitted to tests (the fits are the library's,
//! the report `pounding_study::fit`'s, shared with Python).

use crate::args::{FitCmd, FitHistoryArgs, FitRestitutionArgs, OutArgs};
use crate::error::{input, CliError};
use crate::files::{check_out, save_out};
use crate::output::{fmt_num, fmt_sig};
use crate::plot::analyses;
use pounding_study::fit::{FitReport, HistoryRequest, RestitutionRequest};
use std::path::Path;

/// `pounding fit COMMAND`.
pub fn run(cmd: FitCmd) -> Result<(), CliError> {
    match cmd {
        FitCmd::Restitution(a) => restitution(&a),
        FitCmd::ForceHistory(a) => force_history(&a),
    }
}

/// The pairs of the data file `path`; `what` says what its columns are, for messages.
fn read(path: &Path, what: &str) -> Result<Vec<(f64, f64)>, CliError> {
    let shown = path.display();
    // An input file that cannot be read is bad input, as a scenario or record file is (exit 2).
    let text = pounding_study::input::read_text_file(
        path,
        "data file",
        pounding_study::input::DATA_FILE_LIMIT,
    )
    .map_err(input)?;
    pounding_study::fit::pairs(&text).map_err(|e| input(format!("{shown}: {e} ({what})")))
}

/// A refused fit: about the data, naming the file; about an option, naming its flag.
fn refused(path: &Path, e: pounding::Error) -> CliError {
    match e {
        e @ pounding::Error::Choice { name: "data", .. } => {
            input(format!("{}: {e}", path.display()))
        }
        pounding::Error::Choice {
            name,
            value,
            allowed,
        } if value == "missing" => input(format!(
            "--{} is required: {allowed}",
            name.replace('_', "-")
        )),
        pounding::Error::Choice {
            name,
            value,
            allowed,
        } if value == "true" => input(format!(
            "--{} is not allowed: {allowed}",
            name.replace('_', "-")
        )),
        pounding::Error::Choice {
            name,
            value,
            allowed,
        } => input(format!(
            "--{} {value} is not allowed: {allowed}",
            name.replace('_', "-")
        )),
        other => CliError::from(other),
    }
}

fn restitution(a: &FitRestitutionArgs) -> Result<(), CliError> {
    check_out(&a.out)?;
    let req = RestitutionRequest {
        law: a.model,
        rows: a.rows,
        monotone: a.monotone,
        radius: a.radius,
        k: a.k,
        m1: a.m1,
        m2: a.m2,
    };
    let points = read(&a.data, "v_i in m/s, then e")?;
    let r = pounding_study::fit::restitution(&points, &req).map_err(|e| refused(&a.data, e))?;
    let (v_lo, v_hi) = points.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), p| {
        (lo.min(p.0), hi.max(p.0))
    });
    let what = format!(
        "{}: {} points, v_i {} to {} m/s",
        a.data.display(),
        r.points,
        fmt_sig(v_lo, 3),
        fmt_sig(v_hi, 3)
    );
    let figs = if a.out.figures.plots {
        vec![analyses::fit_restitution(&points, &r, &what)]
    } else {
        Vec::new()
    };
    finish(&r, &what, ("v_i_m_per_s", "e"), &a.out, a.json, &figs)
}

fn force_history(a: &FitHistoryArgs) -> Result<(), CliError> {
    check_out(&a.out)?;
    let data = read(&a.data, "time in s, then force in N")?;
    let req = HistoryRequest {
        model: a.model,
        m1: a.m1,
        m2: a.m2,
        v: a.v,
        exponent: a.n,
        damping_constant: a.damping_constant,
        radius: a.radius,
    };
    let r = pounding_study::fit::force_history(&data, &req).map_err(|e| refused(&a.data, e))?;
    let what = format!(
        "{}: {} samples; m1 = {} kg, m2 = {}, v = {} m/s",
        a.data.display(),
        r.points,
        fmt_num(a.m1),
        if a.m2.is_finite() {
            format!("{} kg", fmt_num(a.m2))
        } else {
            "rigid".into()
        },
        fmt_num(a.v)
    );
    let figs = if a.out.figures.plots {
        vec![analyses::fit_force_history(&data, &r, &what)]
    } else {
        Vec::new()
    };
    finish(&r, &what, ("time_s", "force_N"), &a.out, a.json, &figs)
}

/// Prints the report (or its JSON) and writes the output folder.
fn finish(
    r: &FitReport,
    what: &str,
    columns: (&str, &str),
    out: &OutArgs,
    json: bool,
    figs: &[crate::plot::Figure],
) -> Result<(), CliError> {
    if json {
        println!("{}", serde_json::to_string(r).expect("JSON"));
    } else {
        print_report(r, what);
    }
    let mut csv = format!("{},{}\n", columns.0, columns.1);
    for (x, y) in r.curve.0.iter().zip(&r.curve.1) {
        csv.push_str(&format!("{x},{y}\n"));
    }
    save_out(
        out,
        ("fit", r),
        vec![("fit-curve.csv".into(), csv.into_bytes())],
        figs,
        json,
    )
}

fn print_report(r: &FitReport, what: &str) {
    let kind = if r.kind == "restitution" {
        "e against v_i"
    } else {
        "the force history"
    };
    println!("{} fitted to {kind} of {what}", r.model);
    let width = r
        .parameters
        .keys()
        .chain(r.also.keys())
        .map(String::len)
        .max()
        .unwrap_or(8)
        .max(8);
    for (key, value) in &r.parameters {
        let unit = r.units[key].as_str().unwrap_or("");
        match (value.as_f64(), r.std_errors[key].as_f64()) {
            (Some(v), Some(se)) => {
                println!(
                    "  {key:width$}  {} +- {} {unit}",
                    fmt_sig(v, 6),
                    fmt_sig(se, 2)
                )
            }
            (Some(v), None) => println!(
                "  {key:width$}  {} {unit} (no standard error: too few points)",
                fmt_sig(v, 6)
            ),
            _ => println!(
                "  {key:width$}  a table of {} rows, below",
                table_rows(value)
            ),
        }
    }
    for (key, v) in &r.also {
        let (value, se, unit) = (
            v["value"].as_f64(),
            v["std_error"].as_f64(),
            v["unit"].as_str(),
        );
        if let Some(value) = value {
            println!(
                "  {key:width$}  {} +- {} {}",
                fmt_sig(value, 6),
                se.map_or("-".into(), |s| fmt_sig(s, 2)),
                unit.unwrap_or("")
            );
        }
    }
    let unit = if r.residual_unit.is_empty() {
        "in e".to_string()
    } else {
        r.residual_unit.to_string()
    };
    println!(
        "  residual: rms {} {unit}, normalised {} % (sqrt of sum r^2 over sum of squared data); +- are standard errors",
        fmt_sig(r.rms_residual, 3),
        fmt_sig(100.0 * r.normalised_residual, 3)
    );
    println!("\npaste into a scenario's [[contact]] (or [[wall]]):");
    for line in &r.scenario {
        for l in line.lines() {
            println!("  {l}");
        }
    }
}

/// The number of rows of a fitted table parameter.
fn table_rows(v: &serde_json::Value) -> usize {
    v["table"].as_array().map_or(0, Vec::len)
}
