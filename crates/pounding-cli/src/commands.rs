//! The commands: validated inputs in, library calls, reports out.

use crate::args::{
    CalibrateArgs, Command, CompareArgs, DropArgs, FormatArg, ImpactArgs, ModelArgs, OutArgs,
    PaperTable, RecordArgs, RecordCmd,
};
use crate::output::{
    fmt_num, fmt_sig, history_csv, num, render_figures, write_atomic, write_files, Report,
};
use crate::plot::figures::{self, Curve, ForceHistory};
use crate::CliError;
use pounding::contact::{
    AlphaRule, ContactModel, Damping, DampingParameter, Model, Reading, Tension, MODELS,
};
use pounding::ground_motion::{Format, Record, Units};
use pounding::impact::{
    delivered_e, exact, simulate, BallDrop, ImpactOptions, ImpactResult, ImpactSetup, TwoBodies,
};
use serde_json::{json, Value};
use std::path::Path;

/// Runs one command.
pub fn run(cmd: Command) -> Result<(), CliError> {
    match cmd {
        Command::Models { json } => models(json),
        Command::Impact(a) => impact(&a),
        Command::Calibrate(a) => calibrate(&a),
        Command::Drop(a) => drop(&a),
        Command::Compare(a) => compare(&a),
        Command::Run(a) => crate::run::run(&a),
        Command::Sweep(a) => crate::sweep::command(&a),
        Command::Ida(a) => crate::sweep::ida(&a),
        Command::Separation(a) => separation(&a),
        Command::Report(a) => crate::report::command(&a),
        Command::Record {
            cmd: RecordCmd::Info(a),
        } => record_info(&a),
        Command::Record {
            cmd: RecordCmd::Spectrum(a),
        } => record_spectrum(&a),
        Command::Record {
            cmd: RecordCmd::Synth(a),
        } => record_synth(&a),
        Command::Paper { table } => match table {
            PaperTable::Table1 { json, out } => table1(json, &out),
            PaperTable::Table2 { json } => table2(json),
        },
    }
}

pub fn input(msg: impl Into<String>) -> CliError {
    CliError::Input(msg.into())
}

/// An option as the command line spells it in messages: `--max-penetration`.
pub fn flag(key: &str) -> String {
    format!("--{key}")
}

/// The contact specification of `a` with stiffness `k` (N/m^n).
pub fn contact(a: &ModelArgs, k: f64) -> Result<ContactModel, CliError> {
    a.options().build(k).map_err(|e| match e {
        pounding::contact::OptionError::Value(v) => CliError::from(v),
        other => input(other.message(flag)),
    })
}

/// One line describing a contact model and its damping: `papi, k = 2e9 N/m^1, e = 0.65, ...`.
/// The unit of a contact stiffness of exponent `n`: `N/m`, `N/m^1.5`.
pub fn stiffness_unit(n: f64) -> String {
    if n == 1.0 {
        "N/m".into()
    } else {
        format!("N/m^{}", fmt_num(n))
    }
}

pub fn contact_label(s: &ContactModel, p: Option<DampingParameter>) -> String {
    let mut text = format!(
        "{}, k = {} {}, e = {}",
        s.model().name(),
        fmt_num(s.stiffness()),
        stiffness_unit(s.exponent()),
        fmt_num(s.restitution())
    );
    if s.model().is_damped() {
        text.push_str(&format!(", damping {}", damping_name(s.damping())));
        if s.model() == Model::Papi {
            text.push_str(&format!(", {} reading", reading_name(s.reading())));
        }
        match p {
            Some(DampingParameter::Papi { alpha, chi, chi_r }) => text.push_str(&format!(
                " (alpha = {}, chi = {}, chi_r = {})",
                fmt_num(alpha),
                fmt_num(chi),
                fmt_num(chi_r)
            )),
            Some(other) => {
                if let Some((name, v)) = other.named() {
                    text.push_str(&format!(" ({name} = {})", fmt_num(v)));
                }
            }
            None => text.push_str(" (set per impact)"),
        }
    }
    text.push_str(&format!(", tension {}", tension_name(s.tension())));
    text
}

fn tension_name(t: Tension) -> &'static str {
    match t {
        Tension::Allow => "allow",
        Tension::Clamp => "clamp",
    }
}

fn damping_name(d: Damping) -> &'static str {
    match d {
        Damping::Formula => "formula",
        Damping::Exact => "exact",
    }
}

fn reading_name(r: Reading) -> &'static str {
    match r {
        Reading::EnergySplit => "energy-split",
        Reading::SameDamping => "same-damping",
    }
}

/// Adds the damping parameter by its name (for papi: alpha and the factors chi, chi_r).
fn parameter(rep: &mut Report, p: DampingParameter) {
    match p {
        DampingParameter::Papi { alpha, chi, chi_r } => {
            rep.add("alpha", num(alpha), "")
                .add("chi", num(chi), "")
                .add("chi_r", num(chi_r), "");
        }
        other => {
            if let Some((name, v)) = other.named() {
                rep.add(name, num(v), "");
            }
        }
    }
}

/// Adds the model description and its damping parameter to a report.
fn describe(rep: &mut Report, s: &ContactModel, p: DampingParameter) {
    rep.add("model", s.model().name(), "")
        .add_shown(
            "k",
            num(s.stiffness()),
            format!(
                "{} {}",
                fmt_num(s.stiffness()),
                stiffness_unit(s.exponent())
            ),
            "",
        )
        .add("n", num(s.exponent()), "")
        .add("tension", tension_name(s.tension()), "")
        .add("damping", damping_name(s.damping()), "");
    if s.model() == Model::Papi {
        let rule = match s.alpha_rule() {
            AlphaRule::Given(_) => "given",
            AlphaRule::Eq8 => "eq8",
            AlphaRule::Calibrate => "calibrate",
        };
        rep.add("reading", reading_name(s.reading()), "")
            .add("alpha_rule", rule, "");
    }
    parameter(rep, p);
}

/// Adds the results of one impact to a report.
fn results(rep: &mut Report, s: &ContactModel, r: &ImpactResult, exact_e: Option<f64>) {
    rep.add("e_pre", num(s.restitution()), "")
        .add("e_post", num(r.e_post), "")
        .add("e_post_exact", exact_e.map_or(Value::Null, num), "")
        .add("peak_force", num(r.peak_force), "N")
        .add("time_of_peak_force", num(r.time_of_peak_force), "s")
        .add("max_penetration", num(r.max_penetration), "m")
        .add("contact_duration", num(r.contact_duration), "s")
        .add("dissipated_energy", num(r.dissipated_energy), "J")
        .add("impulse", num(r.impulse), "N s")
        .add("steps", r.steps, "");
}

/// Fails early (before any work or output) if `--out` names a file or `--png` cannot be honoured.
pub fn check_out(o: &OutArgs) -> Result<(), CliError> {
    match &o.out {
        Some(dir) if dir.is_file() => Err(input(format!(
            "--out {} is a file; give a folder (it is created if missing)",
            dir.display()
        ))),
        _ => check_figures(&o.figures),
    }
}

/// Fails early if `--png` is asked of a build without PNG support.
pub fn check_figures(f: &crate::args::FigureArgs) -> Result<(), CliError> {
    if f.png && !cfg!(feature = "png") {
        return Err(input(crate::output::NO_PNG));
    }
    Ok(())
}

/// Writes a command's files into `--out`, if given: `name.json` holding `json`, the `extra` files, and the
/// figures with --plots, each file atomically, all rendered before the first is written. Prints the folder
/// and the files unless `quiet`.
pub fn save_out(
    o: &OutArgs,
    (name, json): (&str, &Value),
    extra: Vec<(String, Vec<u8>)>,
    figs: &[crate::plot::Figure],
    quiet: bool,
) -> Result<(), CliError> {
    let Some(dir) = &o.out else {
        return Ok(());
    };
    let mut files = vec![(
        format!("{name}.json"),
        (serde_json::to_string_pretty(json).expect("JSON") + "\n").into_bytes(),
    )];
    files.extend(extra);
    if o.figures.plots {
        files.extend(render_figures(figs, o.figures.png)?);
    }
    let names = write_files(dir, files)?;
    if !quiet {
        println!("\nwrote {}: {}", dir.display(), names.join(", "));
    }
    Ok(())
}

/// The figures of one integrated impact, if `--plots` asks for them.
fn impact_figures(
    plots: bool,
    (prefix, title): (&str, &str),
    s: &ContactModel,
    r: &ImpactResult,
    inputs: &str,
) -> Vec<crate::plot::Figure> {
    let (true, Some(h)) = (plots, r.history.as_ref()) else {
        return Vec::new();
    };
    let subtitle = format!(
        "{}; {inputs}: e_post = {}, peak force {}",
        contact_label(s, None).replace(" (set per impact)", ""),
        fmt_sig(r.e_post, 6),
        crate::plot::axis::human(r.peak_force, "N", 4)
    );
    figures::impact(
        prefix,
        title,
        &subtitle,
        &[ForceHistory {
            label: s.model().name().into(),
            t: &h.t,
            penetration: &h.penetration,
            force: &h.force,
        }],
    )
}

/// The impact's time history as the file `history.csv`, if it was kept.
fn history_file(r: &ImpactResult) -> Vec<(String, Vec<u8>)> {
    r.history
        .as_ref()
        .map(|h| ("history.csv".to_string(), history_csv(h).into_bytes()))
        .into_iter()
        .collect()
}

/// The two bodies in one line: `m1 = 100000 kg, m2 rigid, v = 1 m/s`.
fn bodies_text(b: &crate::args::BodiesArgs) -> String {
    format!(
        "m1 = {} kg, {}, v = {} m/s",
        fmt_num(b.m1),
        m2_text(b.m2),
        fmt_num(b.v)
    )
}

/// `m2` as text: `m2 = 3e5 kg`, or `m2 rigid` for an infinite mass (JSON: null).
fn m2_text(m2: f64) -> String {
    if m2.is_infinite() {
        "m2 rigid".into()
    } else {
        format!("m2 = {} kg", fmt_num(m2))
    }
}

fn impact(a: &ImpactArgs) -> Result<(), CliError> {
    check_out(&a.out)?;
    let bodies = TwoBodies::new(a.bodies.m1, a.bodies.m2, a.bodies.v)?;
    let s = contact(&a.model, a.k)?;
    let setup = bodies.setup();
    let (law, p) = s.prepare()?.law(setup.mass, setup.v_i)?;
    let opts = ImpactOptions {
        history: a.out.out.is_some(),
        ..ImpactOptions::default()
    };
    let r = simulate(&law, s.tension(), &setup, &opts)?;
    let exact_e = exact::e_post(&law, s.tension(), setup.mass, setup.v_i);
    let (v1, v2) = bodies.velocities_after(r.impulse);
    let mut rep = Report::default();
    describe(&mut rep, &s, p);
    let b = a.bodies;
    rep.add("m1", num(b.m1), "kg")
        .add_shown(
            "m2",
            num(b.m2),
            if b.m2.is_infinite() {
                "rigid (infinite mass)".into()
            } else {
                fmt_num(b.m2)
            },
            if b.m2.is_infinite() { "" } else { "kg" },
        )
        .add("v", num(b.v), "m/s")
        .add("effective_mass", num(setup.mass), "kg");
    results(&mut rep, &s, &r, exact_e);
    rep.add("velocity_1_after", num(v1), "m/s")
        .add("velocity_2_after", num(v2), "m/s");
    let inputs = bodies_text(&a.bodies);
    let title = format!("Impact ({})", s.model().name());
    let figs = impact_figures(a.out.figures.plots, ("impact", &title), &s, &r, &inputs);
    rep.print(a.json);
    save_out(
        &a.out,
        ("impact", &rep.json()),
        history_file(&r),
        &figs,
        a.json,
    )?;
    Ok(())
}

fn calibrate(a: &CalibrateArgs) -> Result<(), CliError> {
    if !a.model.is_damped() {
        return Err(input(format!(
            "model {} has no damping to calibrate (elastic: e = 1); choose a damped model",
            a.model
        )));
    }
    let mut s = ContactModel::new(a.model, 1.0, a.e)?
        .with_damping(Damping::Exact)
        .with_reading(a.reading.into());
    if let Some(n) = a.n {
        s = s.with_exponent(n)?;
    }
    if let Some(t) = a.tension {
        s = s.with_tension(t.into());
    }
    // The parameter is dimensionless: any k, m and v give it; unit values are used.
    let (law, p) = s.prepare()?.law(1.0, 1.0)?;
    let setup = ImpactSetup::relative(1.0, 1.0);
    let e_post = delivered_e(&law, s.tension(), &setup)?;
    let integrated = simulate(&law, s.tension(), &setup, &ImpactOptions::default())?.e_post;
    let mut rep = Report::default();
    rep.add("model", s.model().name(), "")
        .add("e_pre", num(a.e), "")
        .add("n", num(s.exponent()), "")
        .add("tension", tension_name(s.tension()), "");
    if s.model() == Model::Papi {
        rep.add("reading", reading_name(s.reading()), "");
    }
    parameter(&mut rep, p);
    rep.add("e_post", num(e_post), "")
        .add("e_post_integrated", num(integrated), "");
    rep.print(a.json);
    Ok(())
}

fn drop(a: &DropArgs) -> Result<(), CliError> {
    check_out(&a.out)?;
    let drop = BallDrop::new(a.radius, a.youngs_modulus, a.poisson, a.density, a.height)?;
    let n = a.model.n.unwrap_or(a.model.model.info().default_n);
    let s = contact(
        &a.model,
        drop.equivalent_stiffness(n.max(f64::MIN_POSITIVE)),
    )?;
    let setup = drop.setup();
    let (law, p) = s.prepare()?.law(setup.mass, setup.v_i)?;
    let opts = ImpactOptions {
        history: a.out.out.is_some(),
        ..ImpactOptions::default()
    };
    let r = simulate(&law, s.tension(), &setup, &opts)?;
    let mut rep = Report::default();
    describe(&mut rep, &s, p);
    rep.add("radius", num(a.radius), "m")
        .add("youngs_modulus", num(a.youngs_modulus), "Pa")
        .add("poisson", num(a.poisson), "")
        .add("density", num(a.density), "kg/m^3")
        .add("height", num(a.height), "m")
        .add("mass", num(setup.mass), "kg")
        .add("hertz_stiffness", num(drop.hertz_stiffness()), "N/m^1.5")
        .add("v_i", num(setup.v_i), "m/s");
    results(&mut rep, &s, &r, None);
    let inputs = format!(
        "ball R = {} m, E = {} Pa, h = {} m, v_i = {} m/s",
        fmt_num(a.radius),
        fmt_num(a.youngs_modulus),
        fmt_num(a.height),
        fmt_sig(setup.v_i, 6)
    );
    let title = format!("Ball drop ({})", s.model().name());
    let figs = impact_figures(a.out.figures.plots, ("drop", &title), &s, &r, &inputs);
    rep.print(a.json);
    save_out(
        &a.out,
        ("drop", &rep.json()),
        history_file(&r),
        &figs,
        a.json,
    )?;
    Ok(())
}

fn compare(a: &CompareArgs) -> Result<(), CliError> {
    check_out(&a.out)?;
    let bodies = TwoBodies::new(a.bodies.m1, a.bodies.m2, a.bodies.v)?;
    if !(a.k.is_finite() && a.k > 0.0) {
        return Err(input(format!(
            "--k {} is not allowed: k > 0 (N/m^1.5)",
            a.k
        )));
    }
    let setup = bodies.setup();
    let opts = ImpactOptions {
        history: true,
        ..ImpactOptions::default()
    };
    let mut runs = Vec::new();
    for &model in &a.models {
        let n = model.info().default_n;
        let k = pounding::impact::equivalent_stiffness(a.k, setup.mass, setup.v_i, n);
        let s = ContactModel::new(model, k, a.e)?.with_damping(a.damping.into());
        let (law, _) = s.prepare()?.law(setup.mass, setup.v_i)?;
        let r = simulate(&law, s.tension(), &setup, &opts)?;
        runs.push((s, r));
    }
    let damping = damping_name(a.damping.into());
    let rows: Vec<Value> = runs
        .iter()
        .map(|(s, r)| {
            json!({
                "model": s.model().name(), "n": num(s.exponent()), "k": num(s.stiffness()),
                "e_post": num(r.e_post), "peak_force": num(r.peak_force),
                "time_of_peak_force": num(r.time_of_peak_force), "max_penetration": num(r.max_penetration),
                "contact_duration": num(r.contact_duration), "dissipated_energy": num(r.dissipated_energy),
            })
        })
        .collect();
    let result = json!({
        "e_pre": num(a.e), "damping": damping, "k_hertz": num(a.k), "m1": num(a.bodies.m1),
        "m2": if a.bodies.m2.is_finite() { num(a.bodies.m2) } else { Value::Null }, "v": num(a.bodies.v),
        "effective_mass": num(setup.mass),
        "units": {"k": "N/m^n", "k_hertz": "N/m^1.5", "peak_force": "N", "time_of_peak_force": "s",
                  "max_penetration": "m", "contact_duration": "s", "dissipated_energy": "J",
                  "m1": "kg", "m2": "kg (null: rigid)", "v": "m/s", "effective_mass": "kg"},
        "models": rows,
    });
    if a.json {
        println!("{result}");
    } else {
        println!(
            "One impact: {}, e_pre = {}, damping {damping}; k_h = {} N/m^1.5",
            bodies_text(&a.bodies),
            fmt_num(a.e),
            fmt_num(a.k)
        );
        println!(
            "(models with n != 1.5 use k_h d_h^(1.5 - n), d_h the elastic Hertz penetration)\n"
        );
        println!(
            "{:<22} {:>4} {:>13} {:>10} {:>13} {:>12} {:>17} {:>19}",
            "model",
            "n",
            "k_N_per_m^n",
            "e_post",
            "peak_force_N",
            "duration_s",
            "max_penetration_m",
            "dissipated_energy_J"
        );
        for (s, r) in &runs {
            println!(
                "{:<22} {:>4} {:>13.5e} {:>10.6} {:>13.6e} {:>12.6e} {:>17.6e} {:>19.6e}",
                s.model().name(),
                s.exponent(),
                s.stiffness(),
                r.e_post,
                r.peak_force,
                r.contact_duration,
                r.max_penetration,
                r.dissipated_energy
            );
        }
    }
    let mut figs = Vec::new();
    if a.out.figures.plots {
        let histories: Vec<ForceHistory> = runs
            .iter()
            .filter_map(|(s, r)| {
                r.history.as_ref().map(|h| ForceHistory {
                    label: format!("{} (e_post {})", s.model().name(), fmt_sig(r.e_post, 4)),
                    t: &h.t,
                    penetration: &h.penetration,
                    force: &h.force,
                })
            })
            .collect();
        let subtitle = format!(
            "e_pre = {1}, {damping} damping; {0}; k_h = {2} N/m^1.5 (models of n \u{2260} 1.5: the equivalent k)",
            bodies_text(&a.bodies),
            fmt_num(a.e),
            fmt_num(a.k)
        );
        figs = figures::impact(
            "compare",
            "Contact models on one impact",
            &subtitle,
            &histories,
        );
    }
    save_out(&a.out, ("compare", &result), Vec::new(), &figs, a.json)
}

fn models(json: bool) -> Result<(), CliError> {
    if json {
        let list: Vec<Value> = MODELS
            .iter()
            .map(|i| {
                json!({
                    "name": i.name, "family": i.family, "default_n": i.default_n, "tension": i.tension,
                    "restitution_damped": i.restitution_damped, "force_law": i.force_law,
                    "damping_formula": i.damping_formula, "parameter": i.parameter, "source": i.source,
                })
            })
            .collect();
        println!("{}", json!({ "models": list }));
        return Ok(());
    }
    println!("Contact models (d penetration in m, v = d' in m/s, v_i impact velocity, k in N/m^n, m effective mass in kg)\n");
    for i in &MODELS {
        println!(
            "{}  (n = {}, tension: {}{})",
            i.name,
            i.default_n,
            tension_name(i.tension),
            i.parameter.map_or(String::new(), |p| format!(
                ", exact calibration adjusts {p}"
            ))
        );
        println!("    force:   {}", i.force_law);
        println!("    damping: {}", i.damping_formula);
        println!("    source:  {}", i.source);
    }
    Ok(())
}

/// Delivered e of every Table 1 variant on the grid e = 0.10, 0.11, ..., 1.00, in two groups: the paper's
/// models (those with published figures) and the other damped models.
fn table1_curves() -> Result<Vec<(&'static str, Vec<Curve>)>, CliError> {
    let mut seed = Vec::new();
    let mut others = Vec::new();
    for v in pounding::paper::variants() {
        let e_pre: Vec<f64> = (10..=100).map(|i| f64::from(i) / 100.0).collect();
        let e_post = e_pre
            .iter()
            .map(|&e| pounding::paper::e_post(&v, e))
            .collect::<Result<Vec<_>, _>>()?;
        let c = Curve {
            label: v.label.into(),
            e_pre,
            e_post,
        };
        if v.published.is_some() {
            seed.push(c);
        } else {
            others.push(c);
        }
    }
    Ok(vec![
        ("Models of Papi & Toopchi-Nezhad (2022)", seed),
        ("Other damped models of the library", others),
    ])
}

fn table1(json: bool, out: &OutArgs) -> Result<(), CliError> {
    check_out(out)?;
    let rows = pounding::paper::table1()?;
    let figs = if out.figures.plots {
        figures::table1(&table1_curves()?)
    } else {
        Vec::new()
    };
    let result = json!({
        "quantity": "mean |e_pre - e_post| / e_pre * 100, percent",
        "protocol": "ideal single impacts, formula damping from e_pre; e_post by the exact relations \
                     (event-located integration for jankowski); grids e = 0.1..1.0 step 0.1 and 0.10..1.00 step 0.01",
        "rows": rows.iter().map(|r| json!({
            "label": r.label, "model": r.model,
            "grid_0.1": {"all": num(r.coarse_all), "mid": num(r.coarse_mid)},
            "grid_0.01": {"all": num(r.fine_all), "mid": num(r.fine_mid)},
            "published": r.published.map(|(a, m)| json!({"all": a, "mid": m})),
        })).collect::<Vec<_>>(),
    });
    if json {
        println!("{result}");
        return save_out(out, ("table1", &result), Vec::new(), &figs, true);
    }
    println!("Papi & Toopchi-Nezhad (2022), Table 1: mean |e_pre - e_post| / e_pre * 100 (%) over 0.1 <= e <= 1 (all) and 0.5 <= e <= 0.8 (mid)");
    println!("Ideal single impacts with each model's published damping; e_post exact (integrated for Jankowski).\n");
    println!(
        "{:<48} {:>16} {:>16} {:>16}",
        "model", "grid 0.1", "grid 0.01", "published"
    );
    println!(
        "{:<48} {:>8}{:>8} {:>8}{:>8} {:>8}{:>8}",
        "", "all", "mid", "all", "mid", "all", "mid"
    );
    let f = |x: f64| format!("{x:.2}");
    for r in &rows {
        let (pa, pm) = r
            .published
            .map_or(("".into(), "".into()), |(a, m)| (f(a), f(m)));
        println!(
            "{:<48} {:>8}{:>8} {:>8}{:>8} {:>8}{:>8}",
            r.label,
            f(r.coarse_all),
            f(r.coarse_mid),
            f(r.fine_all),
            f(r.fine_mid),
            pa,
            pm
        );
    }
    println!("\nThe paper's figures for Papi (3.68 / 0.68) are shown beside each of its variants.");
    println!("See docs/paper-reproduction.md for the protocol and the differences.");
    save_out(out, ("table1", &result), Vec::new(), &figs, false)
}

/// The documented concrete ball-drop example of `docs/paper-reproduction.md`.
struct DropExample {
    radius_m: f64,
    youngs_modulus_pa: f64,
    poisson: f64,
    density_kg_per_m3: f64,
    height_m: f64,
    e: f64,
}

const TABLE2_EXAMPLE: DropExample = DropExample {
    radius_m: 0.1,
    youngs_modulus_pa: 30.0e9,
    poisson: 0.2,
    density_kg_per_m3: 2400.0,
    height_m: 0.5,
    e: 0.65,
};

fn table2(json: bool) -> Result<(), CliError> {
    let DropExample {
        radius_m: radius,
        youngs_modulus_pa: youngs,
        poisson: nu,
        density_kg_per_m3: rho,
        height_m: height,
        e,
    } = TABLE2_EXAMPLE;
    let drop = BallDrop::new(radius, youngs, nu, rho, height)?;
    let setup = drop.setup();
    let mut rows = Vec::new();
    let mut variants: Vec<(Model, Tension)> = Model::all().map(|m| (m, m.info().tension)).collect();
    variants.insert(3, (Model::KelvinVoigt, Tension::Clamp));
    for (model, tension) in variants {
        let n = model.info().default_n;
        let k = drop.equivalent_stiffness(n);
        let run = |damping: Damping| -> Result<Option<ImpactResult>, CliError> {
            if damping == Damping::Exact && !model.is_damped() {
                return Ok(None);
            }
            let s = ContactModel::new(model, k, e)?
                .with_damping(damping)
                .with_tension(tension);
            let (law, _) = s.prepare()?.law(setup.mass, setup.v_i)?;
            Ok(Some(simulate(
                &law,
                tension,
                &setup,
                &ImpactOptions::default(),
            )?))
        };
        let formula = run(Damping::Formula)?.expect("formula damping always runs");
        let exact = run(Damping::Exact)?;
        rows.push((model, tension, n, k, formula, exact));
    }
    let hertz_peak = rows
        .iter()
        .find(|r| r.0 == Model::Hertz)
        .map(|r| r.4.peak_force)
        .unwrap_or(f64::NAN);
    if json {
        println!(
            "{}",
            json!({
                "example": {"radius_m": radius, "youngs_modulus_Pa": youngs, "poisson": nu, "density_kg_per_m3": rho,
                            "height_m": height, "e": e, "mass_kg": num(setup.mass), "v_i_m_per_s": num(setup.v_i),
                            "hertz_stiffness_N_per_m1.5": num(drop.hertz_stiffness())},
                "rows": rows.iter().map(|(m, t, n, k, f, x)| json!({
                    "model": m.name(), "tension": tension_name(*t), "n": n, "k": num(*k),
                    "peak_force_N": num(f.peak_force), "e_post": num(f.e_post),
                    "peak_force_exact_damping_N": x.as_ref().map_or(Value::Null, |r| num(r.peak_force)),
                })).collect::<Vec<_>>(),
            })
        );
        return Ok(());
    }
    println!(
        "Concrete ball on a concrete slab: R = {radius} m, E = {youngs:e} Pa, nu = {nu}, rho = {rho} kg/m^3, h = {height} m, e = {e}"
    );
    println!(
        "mass {} kg, v_i {} m/s, k_h {} N/m^1.5; linear models use k_h d_h^(1/2) with d_h the elastic Hertz penetration\n",
        fmt_num(setup.mass),
        fmt_num(setup.v_i),
        fmt_num(drop.hertz_stiffness())
    );
    println!(
        "{:<22} {:>7} {:>4} {:>14} {:>10} {:>14} {:>10}",
        "model", "tension", "n", "peak_force_N", "e_post", "exact_damp_N", "vs_hertz_%"
    );
    for (m, t, n, _, f, x) in &rows {
        println!(
            "{:<22} {:>7} {:>4} {:>14.6e} {:>10.6} {:>14} {:>10.2}",
            m.name(),
            tension_name(*t),
            n,
            f.peak_force,
            f.e_post,
            x.as_ref()
                .map_or("-".to_string(), |r| format!("{:.6e}", r.peak_force)),
            (f.peak_force / hertz_peak - 1.0) * 100.0
        );
    }
    println!("\nThe paper's Table 2 compares against an experiment whose inputs it does not give; see docs/paper-reproduction.md.");
    Ok(())
}

/// Loads the ground motion `a` describes: a built-in record by name, or a file in the given format.
pub fn load_record(a: &RecordArgs) -> Result<Record, CliError> {
    load_record_from(&a.file, a.format, a.dt, a.units, a.scale)
}

/// Loads a built-in record called `source`, or the file at `source` in `format` (default: detected, AT2 by
/// its header or a `*.at2` name, time-acc otherwise), with values in `units` (default: an AT2 header's,
/// else g) multiplied by `scale`.
pub fn load_record_from(
    source: &str,
    format: Option<FormatArg>,
    dt: Option<f64>,
    units: Option<Units>,
    scale: f64,
) -> Result<Record, CliError> {
    let name = flag;
    let is_file = Record::builtin(source).is_none();
    // The options are checked here, in the command line's words; reading is the scenarios' own.
    let format = match (format, dt) {
        // A built-in record carries its own format.
        _ if !is_file => None,
        (Some(FormatArg::Values), Some(dt)) => Some(Format::Values { dt }),
        (Some(FormatArg::Values), None) => {
            return Err(input(format!(
                "{} values needs {} (the time step, s)",
                name("format"),
                name("dt")
            )))
        }
        (Some(FormatArg::At2), _) => Some(Format::At2),
        (Some(FormatArg::TimeAcc), _) => Some(Format::TimeAcc),
        (None, _) => None,
    };
    if is_file && dt.is_some() && !matches!(format, Some(Format::Values { .. })) {
        return Err(input(format!(
            "{} applies to {} values only (other formats carry their time step)",
            name("dt"),
            name("format")
        )));
    }
    let spec = pounding::scenario::RecordSpec {
        source: source.to_string(),
        is_file,
        format,
        units,
        scale,
    };
    let record = pounding_study::input::read_record(&spec).map_err(|e| match e {
        pounding::ground_motion::RecordError::Value(v) => CliError::from(v),
        parse => input(pounding_study::input::record_message(&spec, parse)),
    })?;
    record.scaled(scale).map_err(CliError::from)
}

fn separation(a: &crate::args::SeparationArgs) -> Result<(), CliError> {
    let file = pounding_study::input::ScenarioFile::read(&a.scenario).map_err(|e| input(e.0))?;
    // The scenario itself is checked with file and line first.
    file.load().map_err(|e| input(e.0))?;
    let mut records = Vec::new();
    for r in &a.records {
        records.extend(
            pounding_study::study::record_sources(Path::new("."), &Value::String(r.clone()))
                .map_err(|m| input(format!("--{m}")))?,
        );
    }
    let label = a.scenario.display().to_string();
    check_out(&a.out)?;
    let v =
        pounding_study::separation::report_message(&file.value, &label, &records, a.aligned_factor)
            .map_err(|m| input(m.replace("aligned_factor = ", "--aligned-factor ")))?;
    let fig = crate::plot::analyses::separation(
        &v,
        &format!("{label}; {} record(s)", records.len().max(1)),
    );
    if a.json {
        println!("{}", serde_json::to_string_pretty(&v).expect("JSON"));
        return save_out(&a.out, ("separation", &v), Vec::new(), &[fig], true);
    }
    let table = |pairs: &Value, pick: &dyn Fn(&Value) -> String| {
        for p in pairs.as_array().into_iter().flatten() {
            let between: Vec<&str> = p["between"]
                .as_array()
                .into_iter()
                .flatten()
                .filter_map(Value::as_str)
                .collect();
            for l in p["levels"].as_array().into_iter().flatten() {
                println!(
                    "{:<20} {:>3}-{:<3} {}",
                    between.join("|"),
                    l["floors"][0],
                    l["floors"][1],
                    pick(l)
                );
            }
        }
    };
    let m = |x: &Value| x.as_f64().map_or("-".into(), |x| format!("{x:>10.5}"));
    println!("required separation (a run without contact) and the rules' estimates, m");
    println!("pair                 floors   peak_left  peak_right  required_gap         abs        srss         ddc    rho");
    let row = |l: &Value| {
        format!(
            "{}  {}  {}    {}  {}  {}  {:.4}",
            m(&l["peak_left"]),
            m(&l["peak_right"]),
            m(&l["required_gap"]),
            m(&l["abs"]),
            m(&l["srss"]),
            m(&l["ddc"]),
            l["rho"].as_f64().unwrap_or(f64::NAN)
        )
    };
    match v.get("records") {
        None => table(&v["pairs"], &row),
        Some(runs) => {
            for r in runs.as_array().into_iter().flatten() {
                println!("\nrecord {}", r["record"].as_str().unwrap_or(""));
                table(&r["pairs"], &row);
            }
            for stat in ["mean", "median", "p84"] {
                println!(
                    "\n{stat} over {} records",
                    runs.as_array().map_or(0, Vec::len)
                );
                table(&v["statistics"]["pairs"], &|l: &Value| {
                    let q = |k: &str| m(&l[k][stat]);
                    format!(
                        "{}  {}  {}    {}  {}  {}",
                        q("peak_left"),
                        q("peak_right"),
                        q("required_gap"),
                        q("abs"),
                        q("srss"),
                        q("ddc")
                    )
                });
            }
        }
    }
    save_out(&a.out, ("separation", &v), Vec::new(), &[fig], false)
}

fn record_synth(a: &crate::args::SynthArgs) -> Result<(), CliError> {
    use pounding::ground_motion::synthetic::{Filter, Synthetic};
    let filter = match a.filter {
        crate::args::FilterArg::KanaiTajimi => Filter::KanaiTajimi { wg: a.wg, zg: a.zg },
        crate::args::FilterArg::CloughPenzien => Filter::CloughPenzien {
            wg: a.wg,
            zg: a.zg,
            wf: a.wf,
            zf: a.zf,
        },
    };
    let s = Synthetic {
        filter,
        duration: a.duration,
        dt: a.dt,
        t1: a.t1,
        t2: a.t2,
        decay: a.decay,
        pga: Some(a.pga),
        envelope: true,
    };
    let name = a
        .out
        .file_stem()
        .and_then(|x| x.to_str())
        .unwrap_or("synthetic");
    let r = s.record(name, a.seed)?;
    let mut text = format!(
        "# synthetic ground motion, pounding record synth --seed {} --filter {} --wg {} --zg {} --wf {} --zf {} --duration {} --dt {} --t1 {} --t2 {} --decay {} --pga {}\n# read with units = \"m/s2\" (format time-acc)\ntime_s,acceleration_m_per_s2\n",
        a.seed,
        match a.filter {
            crate::args::FilterArg::KanaiTajimi => "kanai-tajimi",
            crate::args::FilterArg::CloughPenzien => "clough-penzien",
        },
        a.wg,
        a.zg, a.wf, a.zf, a.duration, a.dt, a.t1, a.t2, a.decay, a.pga
    );
    for (k, x) in r.accelerations().iter().enumerate() {
        text.push_str(&format!("{},{x:e}\n", fmt_num(r.t0() + k as f64 * r.dt())));
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

fn record_spectrum(a: &crate::args::SpectrumArgs) -> Result<(), CliError> {
    check_out(&a.out)?;
    let r = load_record(&a.record)?;
    let periods = a.periods.clone().unwrap_or_else(default_periods);
    let s = pounding::ground_motion::spectrum::spectrum(&r, a.damping, &periods)?;
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
