//! `pounding record info|spectrum|synth`: a record's peaks, its elastic response spectrum, and synthetic
//! records.

use crate::args::{RecordArgs, RecordCmd, SpectrumArgs, SynthArgs};
use crate::error::{input, CliError};
use crate::files::{check_out, save_out};
use crate::output::{fmt_num, fmt_sig, num, Report};
use crate::records::load_record;
use pounding_study::input::write_atomic;
use serde_json::json;

/// `pounding record COMMAND`.
pub fn run(cmd: RecordCmd) -> Result<(), CliError> {
    match cmd {
        RecordCmd::Info(a) => record_info(&a),
        RecordCmd::Spectrum(a) => record_spectrum(&a),
        RecordCmd::Synth(a) => record_synth(&a),
    }
}

fn record_synth(a: &SynthArgs) -> Result<(), CliError> {
    if let Ok(m) = std::fs::symlink_metadata(&a.out) {
        if !m.is_file() && !m.file_type().is_symlink() {
            return Err(crate::error::input(format!(
                "--out {} is not a regular file (a folder, a device or a FIFO); allowed: a new file, or a regular file to replace",
                a.out.display()
            )));
        }
    }
    let p = a.params();
    let name = a
        .out
        .file_stem()
        .and_then(|x| x.to_str())
        .unwrap_or("synthetic");
    let r = p.synthetic().record(name, a.seed)?;
    let mut text = format!(
        "# synthetic ground motion, pounding record synth --seed {} --filter {} --wg {} --zg {} --wf {} --zf {} --duration {} --dt {} --t1 {} --t2 {} --decay {} --pga {}\n# read with units = \"m/s2\" (format time-acc)\ntime_s,acceleration_m_per_s2\n",
        a.seed, p.filter, p.wg, p.zg, p.wf, p.zf, p.duration, p.dt, p.t1, p.t2, p.decay, p.pga
    );
    for (k, x) in r.accelerations().iter().enumerate() {
        text.push_str(&format!("{},{x:e}\n", fmt_num(r.t0() + k as f64 * r.dt())));
    }
    let limit = pounding_study::input::RECORD_FILE_LIMIT;
    if text.len() as u64 > limit {
        return Err(crate::error::input(format!(
            "--duration {} / --dt {} make {} samples, a file of {} MiB; allowed: at most {} MiB, what every record reader takes (a shorter duration or a larger dt)",
            p.duration,
            p.dt,
            r.npts(),
            text.len() >> 20,
            limit >> 20
        )));
    }
    // A suite goes into a folder of its own (docs/separation.md): made if missing, as --out folders are.
    if let Some(dir) = a.out.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir)
            .map_err(|e| CliError::Io(format!("cannot create {}: {e}", dir.display())))?;
    }
    write_atomic(&a.out, text.as_bytes())
        .map_err(|e| CliError::Io(format!("cannot write {}: {e}", a.out.display())))?;
    println!(
        "wrote {}: {} samples at {} s, PGA {} m/s^2 (seed {})",
        a.out.display(),
        r.npts(),
        fmt_num(r.dt()),
        fmt_sig(r.peaks().pga, 6),
        a.seed
    );
    Ok(())
}

/// The default periods of a spectrum: 100 from 0.02 to 10 s, evenly spaced in log, s.
fn default_periods() -> Vec<f64> {
    (0..100)
        .map(|i| 0.02 * (10.0f64 / 0.02).powf(i as f64 / 99.0))
        .collect()
}

fn record_spectrum(a: &SpectrumArgs) -> Result<(), CliError> {
    check_out(&a.out)?;
    let r = load_record(&a.record)?;
    let periods = a.periods.clone().unwrap_or_else(default_periods);
    let s = pounding::ground_motion::spectrum::spectrum_with(
        &r,
        a.damping,
        &periods,
        &mut crate::interrupt::go_on,
    )?;
    let figs = vec![
        crate::plot::analyses::record(
            &r,
            &format!(
                "{} samples at {} s, scale {}",
                r.npts(),
                fmt_num(r.dt()),
                fmt_num(a.record.scale)
            ),
        ),
        crate::plot::analyses::spectrum(&s, &format!("Record {}", r.name())),
    ];
    let result = json!({
        "record": r.name(),
        "damping": num(s.damping),
        "periods": s.periods.iter().map(|x| num(*x)).collect::<Vec<_>>(),
        "sd": s.sd.iter().map(|x| num(*x)).collect::<Vec<_>>(),
        "psv": s.psv.iter().map(|x| num(*x)).collect::<Vec<_>>(),
        "psa": s.psa.iter().map(|x| num(*x)).collect::<Vec<_>>(),
        "units": {"periods": "s", "sd": "m", "psv": "m/s", "psa": "m/s^2", "damping": "ratio"},
    });
    if a.record.json {
        println!("{}", serde_json::to_string_pretty(&result).expect("JSON"));
        return save_out(&a.out, ("spectrum", &result), Vec::new(), &figs, true);
    }
    println!(
        "elastic spectrum of {} ({} samples at {} s), damping {} %, exact piecewise-linear solution",
        r.name(),
        r.npts(),
        fmt_num(r.dt()),
        fmt_num(100.0 * s.damping)
    );
    println!("  period_s        sd_m   psv_m_per_s  psa_m_per_s2   psa_g");
    let g = pounding::units::STANDARD_GRAVITY;
    for i in 0..s.periods.len() {
        println!(
            "{:>10.4}  {:>10.5e}  {:>12.5e}  {:>12.5e}  {:>6.4}",
            s.periods[i],
            s.sd[i],
            s.psv[i],
            s.psa[i],
            s.psa[i] / g
        );
    }
    save_out(&a.out, ("spectrum", &result), Vec::new(), &figs, false)
}

fn record_info(a: &RecordArgs) -> Result<(), CliError> {
    let r = load_record(a)?;
    let p = r.peaks();
    if ![p.pga, p.pgv, p.pgd].iter().all(|x| x.is_finite()) {
        return Err(input(format!(
            "record {}: its peak velocity or displacement is not a finite number (accelerations and duration too large)",
            r.name()
        )));
    }
    let g = pounding::units::STANDARD_GRAVITY;
    let mut rep = Report::default();
    rep.add("record", r.name(), "")
        .add("npts", r.npts(), "")
        .add("dt", num(r.dt()), "s")
        .add("t0", num(r.t0()), "s")
        .add("duration", num(r.duration()), "s")
        .add("pga", num(p.pga), "m/s^2")
        .add("pga_g", num(p.pga / g), "g")
        .add("pga_signed", num(p.pga_signed), "m/s^2")
        .add("pga_time", num(p.pga_time), "s")
        .add("pgv", num(p.pgv), "m/s")
        .add("pgd", num(p.pgd), "m")
        .add(
            "baseline_correction",
            "least-squares line removed from the acceleration before integrating (PGV, PGD only)",
            "",
        );
    rep.print(a.json);
    Ok(())
}
