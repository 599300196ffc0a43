//! `pounding record info|spectrum|synth`: a record's peaks, its elastic response spectrum, and synthetic
//! records.

use crate::args::{CoherentArgs, RecordArgs, RecordCmd, SpectrumArgs, SynthArgs};
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
        RecordCmd::Coherent(a) => record_coherent(&a),
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
    let p = a.spectrum.params();
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
    push_rows(&mut text, &r);
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

/// The rows `time_s,acceleration_m_per_s2` of `r`, each acceleration in its shortest exact form.
fn push_rows(text: &mut String, r: &pounding::ground_motion::Record) {
    for (k, x) in r.accelerations().iter().enumerate() {
        text.push_str(&format!("{},{x:e}\n", fmt_num(r.t0() + k as f64 * r.dt())));
    }
}

/// `pounding record coherent`: one file per support and coherent.json, appearing together in `--out`.
fn record_coherent(a: &CoherentArgs) -> Result<(), CliError> {
    use pounding::ground_motion::coherency::{Coherency, CoherencyKind, Spatial};
    let coherency = match (a.model, a.alpha) {
        (CoherencyKind::LucoWong, Some(alpha)) => Coherency::LucoWong { alpha },
        (CoherencyKind::LucoWong, None) => {
            return Err(input(
                "--alpha is required with --model luco-wong: the incoherence, s/m (e.g. 2.5e-4)",
            ))
        }
        (CoherencyKind::HarichandranVanmarcke, None) => {
            Coherency::harichandran_vanmarcke(a.hv_a_big, a.hv_a, a.hv_k, a.hv_f0, a.hv_b)
        }
        (CoherencyKind::HarichandranVanmarcke, Some(_)) => {
            return Err(input("--alpha is Luco-Wong's: with --model harichandran-vanmarcke give --hv-A, --hv-a, --hv-k, --hv-f0, --hv-b (defaults: SMART-1 event 20)"))
        }
    };
    crate::output_set::OutputSet::check(&a.out)?;
    let p = a.spectrum.params();
    let source = match &a.record {
        Some(s) => Some(crate::records::load_record_from(
            s,
            None,
            None,
            a.record_units,
            1.0,
        )?),
        None => None,
    };
    let records = match &source {
        Some(r) => pounding::ground_motion::conditional::Conditioned {
            record: r.clone(),
            coherency,
            positions: a.positions.clone(),
            window: a.window,
            low_cut: a.low_cut,
        }
        .records("support", a.seed),
        None => Spatial {
            synthetic: p.synthetic(),
            coherency,
            positions: a.positions.clone(),
        }
        .records("support", a.seed),
    }
    .map_err(|e| {
        // The library names Harichandran-Vanmarcke's parameters as the paper does; the options add hv-.
        let msg = e.to_string();
        // The library's `low_cut` is the option --low-cut.
        let msg = match msg.strip_prefix("low_cut") {
            Some(rest) => format!("low-cut{rest}"),
            None => msg,
        };
        let hv = ["A ", "a ", "k ", "f0 ", "b "]
            .iter()
            .any(|p| msg.starts_with(p));
        input(format!("--{}{msg}", if hv { "hv-" } else { "" }))
    })?;
    let set = crate::output_set::OutputSet::begin(&a.out)?;
    let mut files = Vec::new();
    for (j, r) in records.iter().enumerate() {
        let mut text = format!(
            "# support {} of {} at {} m, pounding record coherent --seed {} --model {}{} (docs/structures.md)\n# read with units = \"m/s2\" (format time-acc)\ntime_s,acceleration_m_per_s2\n",
            j + 1,
            records.len(),
            fmt_num(a.positions[j]),
            a.seed,
            a.model,
            a.record
                .as_ref()
                .map_or(String::new(), |r| format!(
                    " --record {r} --window {} --low-cut {}",
                    fmt_num(a.window),
                    fmt_num(a.low_cut)
                ))
        );
        push_rows(&mut text, r);
        let name = format!("support-{}.csv", j + 1);
        set.write_data(&name, text.as_bytes())?;
        files.push(name);
    }
    let mut about = json!({
        "seed": a.seed,
        "model": a.model.to_string(),
        "coherency": match coherency {
            Coherency::LucoWong { alpha } => json!({ "alpha_s_per_m": alpha }),
            Coherency::HarichandranVanmarcke { a_big, a, k, f0, b } =>
                json!({ "A": a_big, "a": a, "k_m": k, "f0_hz": f0, "b": b }),
        },
        "positions_m": a.positions,

        "files": files,
        "pga_m_per_s2": records.iter().map(|r| r.peaks().pga).collect::<Vec<f64>>(),
    });
    // What the records came from: the spectrum, or the record they are conditioned on.
    match &source {
        Some(r) => {
            about["conditioned_on"] = json!({
                "record": a.record,
                "npts": r.npts(),
                "dt_s": r.dt(),
                "pga_m_per_s2": r.peaks().pga,
                "window_s": a.window,
                "low_cut_hz": a.low_cut,
            })
        }
        None => about["synthetic"] = json!(p),
    }
    set.write_data("coherent.json", format!("{about:#}\n").as_bytes())?;
    if a.figures.plots {
        let how = match &a.record {
            Some(r) => format!("conditioned on {r}, seed {}", a.seed),
            None => format!("generated from a spectrum, seed {}", a.seed),
        };
        let fig =
            crate::plot::analyses::supports(&records, &a.positions, &format!("{}, {how}", a.model));
        for (name, bytes) in crate::files::render_figures(&[fig], a.figures.png)? {
            set.write_data(&name, &bytes)?;
        }
    }
    set.commit()?;
    println!(
        "wrote {}: {} records of {} samples at {} s (seed {}); PGA {} m/s^2",
        a.out.display(),
        records.len(),
        records[0].npts(),
        fmt_num(records[0].dt()),
        a.seed,
        records
            .iter()
            .map(|r| fmt_sig(r.peaks().pga, 4))
            .collect::<Vec<_>>()
            .join(", ")
    );
    println!("use each as a support's record: [[support]] name = \"s2\", file = \"{}/support-2.csv\" (and delay = distance / apparent velocity for the wave's passage)", a.out.display());
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
