//! `pounding ida STUDY.toml --out DIR`: incremental dynamic analysis: the runs of an IDA study as a
//! resumable sweep, runs.csv and fragility.csv, and the fitted fragility curves.

use crate::args::IdaArgs;
use crate::error::{input, CliError};
use crate::files::{check_figures, render_figures, write_files};
use crate::progress::{progress, workers};
use pounding_study::ida::{self, Edp, FitJson, Ida, IdaError};

/// `pounding ida`.
pub fn run(args: &IdaArgs) -> Result<(), CliError> {
    let a = args;
    check_figures(&args.figures)?;
    let workers = workers(a.runs.workers)?;
    crate::files::check_out_dir(&a.out, false)?;
    let mut study = Ida::read(&a.study).map_err(|e| input(e.0))?;
    if a.runs.no_contact {
        study.base["contacts"] = "off".into();
    }
    let (bar, mut report) = progress(a.runs.quiet);
    let out = ida::run(&study, &a.out, workers, &mut report).map_err(|e| match e {
        IdaError::Input(e) => input(e.0),
        IdaError::Io(m) => CliError::Io(m),
        IdaError::Cancelled => crate::progress::ended_early(
            pounding_study::sweep::SweepError::Cancelled,
            &a.out.join("study.sqlite"),
            &bar.borrow(),
        ),
    })?;
    drop(report);
    bar.borrow().finish();
    let v = &out.json;
    println!(
        "{} records x {} levels of {}: {} runs, {} failed",
        study.records.len(),
        study.levels.len(),
        study.measure_name(),
        v.runs,
        v.failed
    );
    println!("\nlimit state                    stripes: median_m_per_s2  beta    ida: median_m_per_s2  beta");
    let cell = |f: &FitJson| match *f {
        FitJson::Fitted { median, beta } => format!("{median:>16.4}  {beta:>6.3}"),
        FitJson::Failed { .. } => format!("{:>24}", "(no fit)"),
    };
    for f in &v.fragility {
        println!(
            "{:<30} {}    {}",
            f.limit_state,
            cell(&f.stripes),
            cell(&f.ida)
        );
    }
    println!(
        "\nwrote {}: study.sqlite, runs.csv, fragility.csv",
        a.out.display()
    );
    // Figures: each limit state's EDP per record and level.
    let nl = study.levels.len();
    let edps: Vec<Vec<Vec<Option<f64>>>> = study
        .limit_states
        .iter()
        .enumerate()
        .map(|(k, _)| {
            (0..study.records.len())
                .map(|i| {
                    (0..nl)
                        .map(|j| out.edps[i * nl + j].as_ref().map(|e| e[k]))
                        .collect()
                })
                .collect()
        })
        .collect();
    let states: Vec<crate::plot::analyses::StateAxis> = study
        .limit_states
        .iter()
        .map(|l| crate::plot::analyses::StateAxis {
            name: l.name.clone(),
            threshold: l.threshold,
            unit: match l.edp {
                Edp::DriftRatio(_) | Edp::Ductility(_) | Edp::Pounding => "",
                Edp::StoreyShear(_) => "N",
                Edp::Acceleration(_) => "m/s^2",
                Edp::Displacement(_) | Edp::Penetration => "m",
                Edp::PeakForce => "N",
            },
            boolean: l.edp == Edp::Pounding,
        })
        .collect();
    let short = match study.measure {
        pounding_study::ida::Measure::Pga => "PGA",
        pounding_study::ida::Measure::Sa { .. } => "Sa(T1)",
    };
    let figs = crate::plot::analyses::ida(
        &study.levels,
        &study.records,
        &edps,
        &states,
        &v.fragility,
        (short, &study.measure_name()),
    );
    if args.figures.plots {
        let names = write_files(&a.out, render_figures(&figs, args.figures.png)?)?;
        println!("wrote {}: {}", a.out.display(), names.join(", "));
    }
    if v.failed > 0 {
        return Err(CliError::Failed(format!(
            "{} of {} runs failed; why: the error column of {} (the fits use the others)",
            v.failed,
            v.runs,
            a.out.join("runs.csv").display()
        )));
    }
    Ok(())
}
