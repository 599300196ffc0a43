//! `pounding run`: a scenario file in; modal properties and a summary on the terminal; summary.json,
//! response.csv, impacts.csv and energy.csv in the output folder.

use crate::args::RunArgs;
use crate::commands::{contact_label, input};
use crate::output::{fmt_num, fmt_sig, fmt_table, render_figures};
use crate::run_data::RunData;
use crate::scenario::load;
use crate::CliError;
use pounding::analysis::{Bumper, Device, DeviceEnds, Results, Scenario, SiteKind};
use pounding::element::StoreyLaw;
use std::fmt::Write as _;
use std::io::IsTerminal;
use std::path::Path;

pub fn run(a: &RunArgs) -> Result<(), CliError> {
    let (mut loaded, text) = load(&a.scenario)?;
    if let Some(t) = a.tolerance {
        loaded.scenario = loaded.scenario.with_tolerance(t).map_err(CliError::from)?;
    }
    let scenario = &loaded.scenario;
    // The output folder must be new, empty or an earlier run's, checked before any work.
    crate::output_set::OutputSet::check(&a.out)?;
    crate::commands::check_figures(&a.figures)?;
    if !a.json {
        print_setup(
            scenario,
            &a.scenario,
            &loaded.record_source,
            loaded.doc.ground_motion.scale,
        );
    }

    let bar = (!a.quiet && std::io::stderr().is_terminal()).then(|| {
        let b = indicatif::ProgressBar::new(1000);
        b.set_style(
            indicatif::ProgressStyle::with_template(
                "{spinner} [{bar:40}] t = {msg} ({elapsed} of about {duration})",
            )
            .expect("a valid template")
            .progress_chars("=> "),
        );
        b
    });
    let record_end = scenario.record().t0() + scenario.record().duration();
    let results = scenario.run_with(&mut |p| {
        if let Some(b) = &bar {
            let work = expected_work(p.t, record_end) / expected_work(p.duration, record_end);
            b.set_position((1000.0 * work) as u64);
            b.set_message(format!(
                "{:.2} s, {}",
                p.t,
                pounding::words::count(p.impacts, "impact", None)
            ));
        }
        std::ops::ControlFlow::Continue(())
    });
    if let Some(b) = &bar {
        b.finish_and_clear();
    }
    let results = results.map_err(|e| CliError::Input(format!("analysis failed: {e}")))?;

    let summary = pounding_study::summary::summary(&loaded, &results).map_err(input)?;
    // Accuracy that holds itself to account: the summary's warnings are said on stderr too.
    for w in summary["warnings"].as_array().into_iter().flatten() {
        eprintln!("warning: {}", w.as_str().unwrap_or_default());
    }
    // The scenario as run travels with the results (the report shows it).

    // Everything is formatted before the first file is written.
    let files = [
        ("scenario.toml", text),
        (
            "summary.json",
            serde_json::to_string_pretty(&summary).expect("JSON") + "\n",
        ),
        ("response.csv", response_csv(scenario, &results)),
        ("impacts.csv", impacts_csv(scenario, &results)),
        (
            crate::run_data::LOOPS_FILE,
            crate::run_data::impact_loops_csv(scenario, &results),
        ),
        ("energy.csv", energy_csv(&results)),
    ];
    // The whole set is written into a folder beside --out and appears there in one rename.
    let mut set = crate::output_set::OutputSet::begin(&a.out)?;
    for (name, text) in &files {
        set.write_data(name, text.as_bytes())?;
    }
    let mut written: Vec<String> = files.iter().map(|f| f.0.to_string()).collect();
    if a.figures.plots || a.report {
        // Figures and report are made from the files just written, exactly as `pounding report` makes them.
        let data = RunData::load(set.dir())?;
        let figs = crate::plot::figures::run(&data);
        if a.figures.plots {
            for (name, bytes) in render_figures(&figs, a.figures.png)? {
                set.write(&name, &bytes)?;
                written.push(name);
            }
        }
        if a.report {
            written.push(crate::report::write(
                &data,
                &figs,
                &set.dir().join("report.html"),
            )?);
        }
    }
    set.commit()?;
    if a.json {
        println!("{}", serde_json::to_string_pretty(&summary).expect("JSON"));
    } else {
        print_results(scenario, &results);
        println!("\nwrote {}: {}", a.out.display(), written.join(", "));
    }
    Ok(())
}

/// How much of a run's cost lies before time `t` (s), in record-seconds: a second of free vibration after
/// the record ends costs about a third of a second under it (fewer steps, fewer impacts; measured 0.2 to
/// 0.4 on the examples run three times longer than their record), so the progress bar's estimate of the
/// time left does not count it in full.
fn expected_work(t: f64, record_end: f64) -> f64 {
    t.min(record_end) + 0.3 * (t - record_end).max(0.0)
}

fn print_setup(s: &Scenario, file: &Path, source: &str, scale: f64) {
    let rec = s.record();
    let p = rec.peaks();
    println!("scenario  {}", file.display());
    println!(
        "record    {source} x {scale}: {} samples at {} s, PGA {} m/s^2 ({} g) at {} s",
        rec.npts(),
        fmt_num(rec.dt()),
        fmt_sig(p.pga, 4),
        fmt_sig(p.pga / pounding::units::STANDARD_GRAVITY, 4),
        fmt_num(p.pga_time)
    );
    println!(
        "analysis  {} s, output every {} s, tolerance {:e}",
        fmt_num(s.duration()),
        fmt_num(s.output_dt()),
        s.tolerance()
    );
    for b in s.buildings() {
        let st = &b.structure;
        let modes = st.modes();
        let part = modes.participation(st.masses());
        let m_tot = st.total_mass();
        let damping = match st.isolator() {
            None => format!(
                "damping {} % (Rayleigh, modes 1 and 2)",
                fmt_num(100.0 * st.damping_ratio())
            ),
            Some(iso) => format!(
                "isolated: {} isolator (storey 1) under the base slab (floor 1){}; {}isolator damped by its hysteresis{}",
                iso.model.name(),
                iso.clearance
                    .map_or(String::new(), |c| format!(", clearance {} m", fmt_num(c))),
                if st.storeys() > 1 {
                    format!(
                        "superstructure damped {} % on its fixed-base modes 1 and 2, ",
                        fmt_num(100.0 * st.damping_ratio())
                    )
                } else {
                    String::new()
                },
                if iso.damping > 0.0 {
                    format!(" and {} N s/m", fmt_sig(iso.damping, 4))
                } else {
                    String::new()
                }
            ),
        };
        println!(
            "\nbuilding {:?}: {}, {} kg, height {} m, {damping}",
            b.name,
            pounding::words::count(st.storeys(), "storey", None),
            fmt_num(m_tot),
            fmt_num(st.elevations().last().copied().unwrap_or(0.0)),
        );
        let laws = st.storey_laws();
        if laws.iter().any(|l| l.is_inelastic()) {
            let desc: Vec<String> = laws
                .iter()
                .enumerate()
                .map(|(j, l)| match *l {
                    StoreyLaw::Linear => format!("{}: linear", j + 1),
                    StoreyLaw::Bilinear {
                        yield_force,
                        post_yield_ratio,
                    } => format!(
                        "{}: bilinear F_y {} N, a {}",
                        j + 1,
                        fmt_sig(yield_force, 4),
                        fmt_num(post_yield_ratio)
                    ),
                    StoreyLaw::BoucWen {
                        yield_force,
                        post_yield_ratio,
                        n,
                        beta,
                        gamma,
                    } => format!(
                        "{}: bouc-wen F_y {} N, a {}, n {}, beta {}, gamma {}",
                        j + 1,
                        fmt_sig(yield_force, 4),
                        fmt_num(post_yield_ratio),
                        fmt_num(n),
                        fmt_num(beta),
                        fmt_num(gamma)
                    ),
                })
                .collect();
            println!("  storeys: {}", desc.join("; "));
            if st.isolator().is_some() {
                println!("  (modes of the initial stiffness; damping_% is phi^T C phi / 2w, the isolator's hysteresis not counted)");
            } else {
                println!("  (modes and Rayleigh damping of the initial stiffness)");
            }
        }
        println!("  mode  period_s  damping_%  mass_%  shape (floor 1 up, largest = 1)");
        let shapes = modes.shapes_normalised();
        for (r, t) in modes.periods().iter().enumerate().take(6) {
            let shape: Vec<String> = shapes[r].iter().map(|x| format!("{x:.3}")).collect();
            println!(
                "  {:>4}  {:>8.4}  {:>9.2}  {:>6.1}  {}",
                r + 1,
                t,
                100.0 * st.damping_of_mode(r),
                100.0 * part[r].1 / m_tot,
                shape.join(" ")
            );
        }
        if st.storeys() > 6 {
            println!("  (modes 7 to {} in summary.json)", st.storeys());
        }
    }
    for site in s.sites() {
        match site.kind {
            SiteKind::Between { .. } => {
                let floors: Vec<String> = site
                    .levels
                    .iter()
                    .map(|l| format!("{}-{}", l.left.unwrap_or(0), l.right.unwrap_or(0)))
                    .collect();
                println!(
                    "\ncontact {}: gap {} m at floors {}, {}",
                    site.name,
                    fmt_num(site.gap),
                    floors.join(", "),
                    contact_label(site.contact.spec(), site.contact.parameter())
                );
            }
            SiteKind::Wall { building, side } => {
                let floors: Vec<String> =
                    site.levels.iter().map(|l| l.floor().to_string()).collect();
                println!(
                    "\nwall {}: {} of {}, gap {} m, floors {}, {}",
                    site.name,
                    side.name(),
                    s.buildings()[building].name,
                    fmt_num(site.gap),
                    floors.join(", "),
                    contact_label(site.contact.spec(), site.contact.parameter())
                );
            }
        }
        describe_extras(&site.bumper, site.seat);
    }
    for d in s.devices() {
        let (a, b) = device_ends(s, d);
        let floors: Vec<String> = d.floors.iter().map(|(i, j)| format!("{i}-{j}")).collect();
        println!(
            "\ndevice {}: {} between {a} and {b} at floors {}",
            d.name,
            device_label(&d.law),
            floors.join(", ")
        );
    }
    println!();
}

/// The names of a device's two ends.
pub(crate) fn device_ends(s: &Scenario, d: &Device) -> (String, String) {
    match d.ends {
        DeviceEnds::Buildings { left, right } => (
            s.buildings()[left].name.clone(),
            s.buildings()[right].name.clone(),
        ),
        DeviceEnds::Wall { site } => {
            let w = &s.sites()[site];
            let b = match w.kind {
                SiteKind::Wall { building, .. } | SiteKind::Between { left: building, .. } => {
                    building
                }
            };
            (s.buildings()[b].name.clone(), w.name.clone())
        }
    }
}

/// A device's law in words, with units.
fn device_label(law: &pounding::element::DeviceLaw) -> String {
    let params: Vec<String> = law
        .parameters()
        .iter()
        .map(|p| format!("{} {} {}", p.key, fmt_sig(p.value, 4), p.unit))
        .collect();
    format!("{} {}", law.name(), params.join(", "))
}

/// A bumper and a seat, if given.
fn describe_extras(bumper: &Option<Bumper>, seat: Option<f64>) {
    if let Some(b) = bumper {
        println!(
            "  bumper {} m thick, consumed at strain {}: {}",
            fmt_num(b.thickness),
            fmt_num(b.max_strain),
            contact_label(b.contact.spec(), b.contact.parameter())
        );
    }
    if let Some(seat) = seat {
        println!("  seat {} m (unseating check)", fmt_num(seat));
    }
}

/// Metres as millimetres, N as MN, J as kJ: the units of the terminal tables, the figures and the report.
fn mm(x: f64) -> String {
    fmt_table(1e3 * x, 4)
}
fn mn(x: f64) -> String {
    fmt_table(1e-6 * x, 4)
}
fn kj(x: f64) -> String {
    fmt_table(1e-3 * x, 4)
}

fn print_results(s: &Scenario, r: &Results) {
    println!(
        "peak responses (lengths in mm, forces in MN, energies in kJ; the files hold m, N and J)\n"
    );
    println!(
        "building    floor  displacement_mm    at_s  abs_acceleration_m_per_s2  storey  drift_mm  drift_ratio_%  shear_MN"
    );
    for (b, resp) in s.buildings().iter().zip(&r.buildings) {
        let h = b.structure.heights();
        for (f, h_f) in h.iter().enumerate() {
            println!(
                "{:<10}  {:>5}  {:>15}  {:>6.2}  {:>25}  {:>6}  {:>8}  {:>13.3}  {:>8}",
                b.name,
                f + 1,
                mm(resp.peak_displacement[f]),
                resp.time_of_peak_displacement[f],
                fmt_table(resp.peak_absolute_acceleration[f], 4),
                f + 1,
                mm(resp.peak_drift[f]),
                100.0 * resp.peak_drift[f] / h_f,
                mn(resp.peak_storey_shear[f])
            );
        }
    }
    let inelastic = s
        .buildings()
        .iter()
        .any(|b| b.structure.storey_laws().iter().any(|l| l.is_inelastic()));
    if inelastic {
        println!(
            "\nbuilding    storey  model     ductility  residual_drift_mm  hysteretic_energy_kJ"
        );
        for (b, resp) in s.buildings().iter().zip(&r.buildings) {
            for (j, law) in b.structure.storey_laws().iter().enumerate() {
                if let Some(mu) = resp.ductility[j] {
                    println!(
                        "{:<10}  {:>6}  {:<8}  {:>9.3}  {:>17}  {:>20}",
                        b.name,
                        j + 1,
                        law.name(),
                        mu,
                        mm(resp.residual_drift[j]),
                        kj(resp.hysteretic_energy[j])
                    );
                }
            }
        }
    }
    let isolated: Vec<usize> = (0..s.buildings().len())
        .filter(|&b| s.buildings()[b].structure.isolator().is_some())
        .collect();
    if !isolated.is_empty() {
        println!(
            "\nbuilding    isolator           peak_displacement_mm  clearance_mm  residual_mm"
        );
        for b in isolated {
            let (st, resp) = (&s.buildings()[b].structure, &r.buildings[b]);
            let iso = st.isolator().expect("isolated");
            let clearance = iso.clearance.map_or("-".to_string(), mm);
            let over = match iso.clearance {
                Some(c) if resp.peak_drift[0] > c => "  EXCEEDED",
                _ => "",
            };
            println!(
                "{:<10}  {:<17}  {:>20}  {:>12}  {:>11}{over}",
                s.buildings()[b].name,
                iso.model.name(),
                mm(resp.peak_drift[0]),
                clearance,
                mm(resp.residual_drift[0])
            );
        }
    }
    if !s.sites().is_empty() {
        println!(
            "\ncontact              impacts  e_asked  e_delivered    peak_force_MN  max_penetration_mm  dissipated_kJ  max_opening_mm"
        );
        let rows = s
            .sites()
            .iter()
            .zip(&r.sites)
            .enumerate()
            .map(|(i, (site, lr))| {
                let name = if site.is_wall() {
                    format!("wall {}", site.name)
                } else {
                    site.name.clone()
                };
                (
                    name,
                    lr,
                    site.contact.spec().restitution(),
                    site.seat,
                    site.bumper.is_some(),
                    r.delivered_e(i),
                )
            });
        let mut spread = false;
        for (name, lr, e_asked, seat, bumper, delivered) in rows {
            if let Some((lo, hi)) = delivered {
                spread |= (lo - e_asked).abs() > 0.01 || (hi - e_asked).abs() > 0.01;
            }
            let range = match delivered {
                Some((lo, hi)) if hi - lo < 5e-4 => format!("{lo:.3}"),
                Some((lo, hi)) => format!("{lo:.3}-{hi:.3}"),
                None => "-".into(),
            };
            let opening = lr.max_opening.iter().fold(0.0, |a: f64, b| a.max(*b));
            let unseat = match (seat, lr.unseated) {
                (Some(seat), Some(true)) => format!("  UNSEATED (seat {} mm)", mm(seat)),
                (Some(seat), _) => format!("  (seat {} mm)", mm(seat)),
                _ => String::new(),
            };
            let consumed = if bumper {
                format!(
                    "  bumper consumed {}",
                    pounding::words::count(lr.consumed, "time", None)
                )
            } else {
                String::new()
            };
            println!(
                "{:<20} {:>7}  {:>7}  {:>11}  {:>15}  {:>18}  {:>13}  {:>14}{unseat}{consumed}",
                name,
                lr.impacts,
                fmt_num(e_asked),
                range,
                mn(lr.peak_force),
                mm(lr.max_penetration),
                kj(lr.dissipated_energy),
                mm(opening)
            );
        }
        if spread {
            println!(
                "e_delivered (separation over approach velocity of each impact, in impacts.csv) differs from e_asked:\n\
                 the calibration is exact for two free bodies, but here the storeys, the damping and every other force\n\
                 on the two floors act during each contact, and can even part the floors faster than they met (e > 1).\n\
                 Nothing is lost: the energy balance below holds. See docs/verification.md, \"Impacts inside a run\"."
            );
        }
    }
    if !s.devices().is_empty() {
        println!("\ndevice               floors  peak_force_MN  max_closing_mm  max_opening_mm");
        for (d, dr) in s.devices().iter().zip(&r.devices) {
            for (k, (i, j)) in d.floors.iter().enumerate() {
                println!(
                    "{:<20} {:>6}  {:>13}  {:>14}  {:>14}",
                    d.name,
                    format!("{i}-{j}"),
                    mn(dr.peak_force[k]),
                    mm(dr.max_closing[k]),
                    mm(dr.max_opening[k])
                );
            }
        }
    }
    let e = &r.energy.end;
    println!(
        "\nenergy at the end, kJ: input {} = kinetic {} + strain {} + damping {} + hysteretic {} + contact {}",
        kj(e.input),
        kj(e.kinetic),
        kj(e.strain),
        kj(e.damping),
        kj(e.hysteretic),
        kj(e.contact)
    );
    println!(
        "energy balance error: {:.2e} (largest over the run, relative to the largest energy)",
        r.energy.relative_error
    );
    println!(
        "integration: {} steps ({} rejected), {} events (contact touch, turn, separation; storey yield, reversal)",
        r.statistics.steps, r.statistics.rejected, r.statistics.events
    );
}

fn response_csv(s: &Scenario, r: &Results) -> String {
    let h = &r.histories;
    let mut out = String::from("time_s,ground_acceleration_m_per_s2");
    for b in s.buildings() {
        for f in 1..=b.structure.storeys() {
            let _ = write!(out, ",{}_floor{f}_displacement_m", b.name);
        }
    }
    for site in s.sites() {
        for l in &site.levels {
            let _ = match site.kind {
                SiteKind::Between { .. } => write!(
                    out,
                    ",{}_floors{}-{}_force_N",
                    site.name,
                    l.left.unwrap_or(0),
                    l.right.unwrap_or(0)
                ),
                SiteKind::Wall { .. } => write!(out, ",{}_floor{}_force_N", site.name, l.floor()),
            };
        }
    }
    for d in s.devices() {
        for (i, j) in &d.floors {
            let _ = write!(out, ",{}_floors{i}-{j}_force_N", d.name);
        }
    }
    for b in s.buildings() {
        for f in 1..=b.structure.storeys() {
            let _ = write!(out, ",{}_floor{f}_absolute_acceleration_m_per_s2", b.name);
        }
    }
    for b in s.buildings() {
        for j in 1..=b.structure.storeys() {
            let _ = write!(out, ",{}_storey{j}_shear_N", b.name);
        }
    }
    out.push('\n');
    for k in 0..h.t.len() {
        let _ = write!(out, "{},{:e}", fmt_num(h.t[k]), h.ground_acceleration[k]);
        for b in &h.displacement {
            for col in b {
                let _ = write!(out, ",{:e}", col[k]);
            }
        }
        for group in [
            &h.site_force,
            &h.device_force,
            &h.absolute_acceleration,
            &h.storey_shear,
        ] {
            for cols in group {
                for col in cols {
                    let _ = write!(out, ",{:e}", col[k]);
                }
            }
        }
        out.push('\n');
    }
    out
}

fn impacts_csv(s: &Scenario, r: &Results) -> String {
    let mut out = String::from(
        "time_s,contact,floor_left,floor_right,layer,v_i_m_per_s,e_post,peak_force_N,time_of_peak_force_s,duration_s,dissipated_energy_J,max_penetration_m,ended,resting\n",
    );
    for i in &r.impacts {
        // Blank on a wall's side.
        let floor = |f: Option<usize>| f.map_or(String::new(), |f| f.to_string());
        let lv = s.sites()[i.site].levels[i.level];
        let (fl, fr) = (floor(lv.left), floor(lv.right));
        let _ = writeln!(
            out,
            "{:e},{},{},{},{},{:e},{},{:e},{:e},{:e},{:e},{:e},{},{}",
            i.time,
            s.sites()[i.site].name,
            fl,
            fr,
            i.layer.name(),
            i.v_i,
            i.e_post.map_or(String::new(), |e| format!("{e:e}")),
            i.peak_force,
            i.time_of_peak_force,
            i.duration,
            i.dissipated_energy,
            i.max_penetration,
            i.ended,
            i.resting
        );
    }
    out
}

fn energy_csv(r: &Results) -> String {
    let h = &r.histories;
    let mut out = String::from(
        "time_s,input_J,kinetic_J,strain_J,structural_damping_J,hysteretic_J,contact_J,balance_error_J\n",
    );
    for k in 0..h.t.len() {
        let e: [f64; 6] = std::array::from_fn(|c| h.energy[c][k]);
        let _ = write!(out, "{}", fmt_num(h.t[k]));
        for x in e {
            let _ = write!(out, ",{x:e}");
        }
        let _ = writeln!(out, ",{:e}", e[0] - e[1..].iter().sum::<f64>());
    }
    out
}
