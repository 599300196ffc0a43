//! `pounding report DIR`: one self-contained HTML file from the output folder of a run: the scenario, modal
//! properties, summary tables, every impact and the figures as inline SVG. No script, no external file, and a
//! Content-Security-Policy that forbids any network access; it opens offline and can be mailed.
//!
//! The document is well-formed XML as well as HTML5 (void elements closed, only XML's five entities), so
//! that tests and scripts can parse it with any XML reader.

use crate::args::ReportArgs;
use crate::output::{fmt_sig, write_atomic};
use crate::plot::axis::plain;
use crate::plot::{svg, Figure};
use crate::run_data::RunData;
use crate::CliError;
use serde_json::Value;
use std::fmt::Write as _;
use std::path::Path;

/// Impacts listed in the report's table at most (all are in impacts.csv).
const MAX_IMPACT_ROWS: usize = 1000;

/// `pounding report DIR [--out FILE]`.
pub fn command(a: &ReportArgs) -> Result<(), CliError> {
    if !a.dir.is_dir() {
        return Err(CliError::Input(format!(
            "{} is not a folder (give the --out folder of `pounding run`)",
            a.dir.display()
        )));
    }
    let out = a.out.clone().unwrap_or_else(|| a.dir.join("report.html"));
    if out.is_dir() {
        return Err(CliError::Input(format!(
            "--out {} is a folder; give a file name such as report.html",
            out.display()
        )));
    }
    crate::output_set::verify(&a.dir)
        .map_err(|m| CliError::Input(format!("{}: {m}", a.dir.display())))?;
    let data = RunData::load(&a.dir)?;
    let figs = crate::plot::figures::run(&data);
    let name = write(&data, &figs, &out)?;
    println!("wrote {}", out.with_file_name(name).display());
    Ok(())
}

/// Writes the report of `data` with `figs` to `path` (atomically); returns its file name.
pub fn write(data: &RunData, figs: &[Figure], path: &Path) -> Result<String, CliError> {
    let html = html(data, figs);
    write_atomic(path, html.as_bytes())
        .map_err(|e| CliError::Io(format!("cannot write {}: {e}", path.display())))?;
    Ok(path
        .file_name()
        .map_or("report.html".into(), |n| n.to_string_lossy().into_owned()))
}

fn e(s: &str) -> String {
    svg::esc(s)
}

/// A number for people: 5 significant digits, never in e-notation.
fn n(v: &Value) -> String {
    v.as_f64().map_or("–".into(), |x| plain(x, 5))
}

/// A length (m in the files) in mm, 4 significant digits.
fn mm(v: &Value) -> String {
    v.as_f64().map_or("–".into(), |x| plain(x * 1e3, 4))
}

/// A force (N in the files) in MN, 4 significant digits.
fn mn(v: &Value) -> String {
    v.as_f64().map_or("–".into(), |x| plain(x * 1e-6, 4))
}

/// An energy (J in the files) in kJ, 4 significant digits.
fn kj(v: &Value) -> String {
    v.as_f64().map_or("–".into(), |x| plain(x * 1e-3, 4))
}

/// A time in s, to the ms (times of events within a run).
fn secs(x: f64) -> String {
    format!("{x:.3}")
}

/// A table: id, caption, header cells (with units) and rows of cells (already escaped).
fn table(out: &mut String, id: &str, caption: &str, head: &[&str], rows: &[Vec<String>]) {
    let _ = write!(
        out,
        "\n<table id=\"{id}\"><caption>{}</caption>\n<thead><tr>",
        e(caption)
    );
    for h in head {
        let _ = write!(out, "<th>{}</th>", e(h));
    }
    out.push_str("</tr></thead>\n<tbody>");
    for r in rows {
        out.push_str("\n<tr>");
        for c in r {
            let _ = write!(out, "<td>{c}</td>");
        }
        out.push_str("</tr>");
    }
    out.push_str("\n</tbody></table>");
}

/// The display units of the report's tables and figures (the files keep base SI units).
pub const UNITS: &str = "lengths in mm, forces in MN, energies in kJ, accelerations in m/s², velocities in \
                         m/s, times in s (one impact's duration in ms); the files keep base SI units";

const STYLE: &str = "
body { font-family: 'DejaVu Sans', Verdana, Arial, Helvetica, sans-serif; color: #1a1a1a; margin: 2em auto;
       max-width: 1180px; padding: 0 1.5em; line-height: 1.45; }
h1 { font-size: 1.6em; margin-bottom: 0.2em; }
h2 { font-size: 1.25em; border-bottom: 1px solid #ccc; padding-bottom: 0.2em; margin-top: 2em; }
p.meta { color: #555; margin-top: 0; overflow-wrap: anywhere; }
dd { overflow-wrap: anywhere; }
nav a { margin-right: 1em; }
table { border-collapse: collapse; margin: 1em 0; font-size: 0.9em; }
caption { text-align: left; font-weight: bold; padding-bottom: 0.3em; }
th, td { border: 1px solid #d0d0d0; padding: 0.2em 0.6em; }
th { background: #f2f2f2; font-weight: normal; text-align: center; }
td { text-align: right; font-variant-numeric: tabular-nums; }
td:first-child { text-align: left; }
table[id^='storeys'] td:nth-child(2) { text-align: left; }
pre { background: #f6f6f6; border: 1px solid #ddd; padding: 0.8em; overflow-x: auto; font-size: 0.85em; }
figure { margin: 1.5em 0; }
figure svg { max-width: 100%; height: auto; border: 1px solid #eee; }
figcaption { color: #444; font-size: 0.9em; }
dl.summary { display: grid; grid-template-columns: max-content auto; gap: 0.2em 1.2em; }
dl.summary dt { color: #555; }
dl.summary dd { margin: 0; }
@media print { figure { break-inside: avoid; } }
";

/// The report as an HTML document.
pub fn html(d: &RunData, figs: &[Figure]) -> String {
    let s = &d.summary;
    let scenario = s["scenario"].as_str().unwrap_or("scenario");
    let title = format!(
        "Pounding analysis: {}",
        Path::new(scenario)
            .file_name()
            .map_or(scenario.into(), |n| n.to_string_lossy())
    );
    let mut h = String::new();
    h.push_str("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\"/>\n");
    // No network: everything is inline; images only as data: URLs (none are used).
    h.push_str("<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; style-src 'unsafe-inline'; img-src data:\"/>\n");
    h.push_str("<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\"/>\n");
    let _ = write!(
        h,
        "<title>{}</title>\n<style>{STYLE}</style>\n</head>\n<body>",
        e(&title)
    );
    let _ = write!(h, "\n<h1>{}</h1>", e(&title));
    let _ = write!(
        h,
        "\n<p class=\"meta\">{} · written by pounding {} from the files of its output folder · {}</p>",
        e(&d.subtitle),
        env!("CARGO_PKG_VERSION"),
        UNITS
    );
    h.push_str("\n<nav><a href=\"#summary\">Summary</a><a href=\"#scenario\">Scenario</a><a href=\"#modes\">Modal properties</a><a href=\"#response\">Peak response</a><a href=\"#contacts\">Contacts</a><a href=\"#figures\">Figures</a><a href=\"#impacts\">Impacts</a></nav>");

    // Summary.
    h.push_str("\n<h2 id=\"summary\">Summary</h2>\n<dl class=\"summary\">");
    let rec = &s["record"];
    let dl = |h: &mut String, k: &str, v: String| {
        let _ = write!(h, "\n<dt>{}</dt><dd>{}</dd>", e(k), v);
    };
    dl(
        &mut h,
        "ground motion",
        format!(
            "{} × {} ({} samples at {} s, PGA {} m/s²)",
            e(rec["source"].as_str().unwrap_or("")),
            n(&rec["scale"]),
            rec["npts"],
            n(&rec["dt"]),
            n(&rec["pga"])
        ),
    );
    dl(
        &mut h,
        "analysis",
        format!(
            "{} s, output every {} s, tolerance {}",
            n(&s["duration"]),
            n(&s["output_dt"]),
            n(&s["tolerance"])
        ),
    );
    for b in s["buildings"].as_array().into_iter().flatten() {
        let peak = b["peak_displacement"]
            .as_array()
            .and_then(|a| a.last())
            .cloned()
            .unwrap_or(Value::Null);
        // The storey with the largest ductility, if any storey is inelastic.
        let most = b["ductility"]
            .as_array()
            .into_iter()
            .flatten()
            .zip(b["inelastic_storeys"].as_array().into_iter().flatten())
            .filter_map(|(mu, j)| Some((mu.as_f64()?, j)))
            .max_by(|a, c| a.0.total_cmp(&c.0))
            .map(|(mu, j)| format!(", largest ductility {} (storey {j})", fmt_sig(mu, 3)))
            .unwrap_or_default();
        dl(
            &mut h,
            &format!("building {}", b["name"].as_str().unwrap_or("")),
            format!(
                "{} storey{} ({}), T1 = {} s, roof peak displacement {} mm{most}",
                b["storeys"],
                if b["storeys"].as_u64() == Some(1) {
                    ""
                } else {
                    "s"
                },
                e(&models(b)),
                n(&b["periods"][0]),
                mm(&peak)
            ),
        );
    }
    for b in s["buildings"].as_array().into_iter().flatten() {
        let iso = &b["isolator"];
        if let Some(model) = iso["model"].as_str() {
            let clearance = match (&iso["clearance"], &iso["exceeds_clearance"]) {
                (c @ Value::Number(_), Value::Bool(true)) => {
                    format!(" against a clearance of {} mm: EXCEEDED", mm(c))
                }
                (c @ Value::Number(_), _) => format!(" against a clearance of {} mm", mm(c)),
                _ => String::new(),
            };
            dl(
                &mut h,
                &format!("isolator of {}", b["name"].as_str().unwrap_or("")),
                format!(
                    "{}, peak displacement {} mm{clearance}",
                    e(model),
                    mm(&iso["peak_displacement"])
                ),
            );
        }
    }
    for w in s["walls"].as_array().into_iter().flatten() {
        dl(
            &mut h,
            &format!("wall {}", w["name"].as_str().unwrap_or("")),
            format!(
                "{} impacts, peak force {} MN, dissipated {} kJ",
                w["impacts"],
                mn(&w["peak_force"]),
                kj(&w["dissipated_energy"])
            ),
        );
    }
    // Each contact's impacts, with the e asked of it and the range its impacts delivered.
    let mut differs = false;
    for c in s["contacts"].as_array().into_iter().flatten() {
        let delivered = match (
            c["e_delivered"]["min"].as_f64(),
            c["e_delivered"]["max"].as_f64(),
        ) {
            (Some(lo), Some(hi)) => {
                let asked = c["e"].as_f64().unwrap_or(f64::NAN);
                differs |= (lo - asked).abs() > 0.01 || (hi - asked).abs() > 0.01;
                format!(", delivered {} to {}", plain(lo, 3), plain(hi, 3))
            }
            _ => String::new(),
        };
        dl(
            &mut h,
            &format!("contact {}", between(c)),
            format!(
                "{}, e asked {}{delivered}, peak force {} MN, dissipated {} kJ",
                pounding::words::count(c["impacts"].as_u64().unwrap_or(0) as usize, "impact", None),
                n(&c["e"]),
                mn(&c["peak_force"]),
                kj(&c["dissipated_energy"])
            ),
        );
    }
    if differs {
        dl(
            &mut h,
            "why delivered e differs from e asked",
            "delivered e is the separation over the approach velocity of each impact. The calibration is exact \
             for two free bodies; between floors, the storeys, the damping and every other force on the two floors \
             act during each contact, and can even part the floors faster than they met (e above 1). The energy \
             balance still holds (docs/verification.md, \"Impacts inside a run\")."
                .to_string(),
        );
    }
    dl(
        &mut h,
        "energy balance error",
        format!(
            "{} (largest over the run, relative to the largest energy)",
            n(&s["energy_balance_error"])
        ),
    );
    h.push_str("\n</dl>");

    // Scenario.
    h.push_str("\n<h2 id=\"scenario\">Scenario</h2>");
    match &d.scenario_text {
        Some(t) => {
            let _ = write!(h, "\n<pre>{}</pre>", e(t));
        }
        None => h.push_str("\n<p>The output folder holds no scenario.toml.</p>"),
    }

    // Modal properties.
    h.push_str("\n<h2 id=\"modes\">Modal properties</h2>");
    for (k, b) in s["buildings"].as_array().into_iter().flatten().enumerate() {
        let name = b["name"].as_str().unwrap_or("");
        let arr = |key: &str| b[key].as_array().cloned().unwrap_or_default();
        let (periods, zeta, mass, shapes) = (
            arr("periods"),
            arr("modal_damping_ratios"),
            arr("effective_modal_mass_ratios"),
            arr("mode_shapes"),
        );
        let rows: Vec<Vec<String>> = periods
            .iter()
            .enumerate()
            .map(|(r, t)| {
                let shape: Vec<String> = shapes[r]
                    .as_array()
                    .into_iter()
                    .flatten()
                    .map(|x| format!("{:.3}", x.as_f64().unwrap_or(0.0)))
                    .collect();
                vec![
                    (r + 1).to_string(),
                    format!("{:.4}", t.as_f64().unwrap_or(0.0)),
                    format!("{:.2}", 100.0 * zeta[r].as_f64().unwrap_or(0.0)),
                    format!("{:.1}", 100.0 * mass[r].as_f64().unwrap_or(0.0)),
                    shape.join(" "),
                ]
            })
            .collect();
        table(
            &mut h,
            &format!("modes-{k}"),
            &format!("Building {name}"),
            &[
                "mode",
                "period (s)",
                "damping (%)",
                "effective mass (%)",
                "shape, floor 1 up (largest |component| = 1)",
            ],
            &rows,
        );
    }

    // Peak response: floors, then the storeys of each building.
    h.push_str("\n<h2 id=\"response\">Peak response</h2>");
    let mut rows = Vec::new();
    for b in s["buildings"].as_array().into_iter().flatten() {
        let name = e(b["name"].as_str().unwrap_or(""));
        let storeys = b["storeys"].as_u64().unwrap_or(0) as usize;
        for f in 0..storeys {
            rows.push(vec![
                name.clone(),
                (f + 1).to_string(),
                mm(&b["peak_displacement"][f]),
                b["time_of_peak_displacement"][f]
                    .as_f64()
                    .map_or("–".into(), secs),
                n(&b["peak_absolute_acceleration"][f]),
                b["time_of_peak_absolute_acceleration"][f]
                    .as_f64()
                    .map_or("–".into(), secs),
                mm(&b["residual_displacement"][f]),
            ]);
        }
    }
    table(
        &mut h,
        "peaks",
        "Largest displacement (relative to the ground) and absolute acceleration of each floor",
        &[
            "building",
            "floor",
            "peak displacement (mm)",
            "at (s)",
            "peak absolute acceleration (m/s²)",
            "at (s)",
            "residual displacement (mm)",
        ],
        &rows,
    );
    for (k, b) in s["buildings"].as_array().into_iter().flatten().enumerate() {
        let storeys = b["storeys"].as_u64().unwrap_or(0) as usize;
        let inelastic: Vec<u64> = b["inelastic_storeys"]
            .as_array()
            .into_iter()
            .flatten()
            .filter_map(Value::as_u64)
            .collect();
        let rows: Vec<Vec<String>> = (0..storeys)
            .map(|j| {
                // Ductility, yield force and hysteretic energy are listed for the inelastic storeys only.
                let at = inelastic.iter().position(|&i| i == j as u64 + 1);
                let only = |key: &str, f: fn(&Value) -> String| {
                    at.map_or(String::new(), |i| f(&b[key][i]))
                };
                vec![
                    (j + 1).to_string(),
                    e(b["storey_models"][j].as_str().unwrap_or("linear")),
                    mm(&b["peak_drift"][j]),
                    b["peak_drift_ratio"][j]
                        .as_f64()
                        .map_or("–".into(), |r| format!("{:.3}", 100.0 * r)),
                    mn(&b["peak_storey_shear"][j]),
                    mm(&b["residual_drift"][j]),
                    only("yield_forces", mn),
                    at.map_or(String::new(), |i| {
                        b["ductility"][i]
                            .as_f64()
                            .map_or("–".into(), |mu| format!("{mu:.3}"))
                    }),
                    only("hysteretic_energy", kj),
                ]
            })
            .collect();
        table(
            &mut h,
            &format!("storeys-{k}"),
            &format!(
                "Storeys of building {} (shear: the restoring force; ductility: peak drift / yield drift, inelastic storeys only)",
                b["name"].as_str().unwrap_or("")
            ),
            &[
                "storey",
                "model",
                "peak drift (mm)",
                "drift ratio (%)",
                "peak shear (MN)",
                "residual drift (mm)",
                "yield force (MN)",
                "ductility",
                "hysteretic energy (kJ)",
            ],
            &rows,
        );
    }

    // Contacts and energy.
    h.push_str("\n<h2 id=\"contacts\">Contacts and energy</h2>");
    let list = |key: &str| s[key].as_array().cloned().unwrap_or_default();
    let rows: Vec<Vec<String>> = list("contacts")
        .iter()
        .map(|c| (between(c), c))
        .chain(list("walls").iter().map(|w| {
            (
                format!(
                    "wall {} ({} of {})",
                    w["name"].as_str().unwrap_or(""),
                    w["side"].as_str().unwrap_or(""),
                    w["facing"].as_str().unwrap_or("")
                ),
                w,
            )
        }))
        .collect::<Vec<_>>()
        .into_iter()
        .map(|(label, c)| {
            let floors: Vec<String> = c["floors"]
                .as_array()
                .into_iter()
                .flatten()
                .map(|p| match p.as_array() {
                    Some(p) => format!("{}-{}", p[0], p[1]),
                    None => p.to_string(),
                })
                .collect();
            let param = match &c["damping_parameter"] {
                Value::Object(p) if p.contains_key("value") => format!(
                    "{} = {}",
                    e(p.get("name").and_then(Value::as_str).unwrap_or("")),
                    p.get("value").map_or("–".into(), n)
                ),
                Value::Object(p) if p.get("name").and_then(Value::as_str) == Some("none") => {
                    "none (elastic)".into()
                }
                _ => "set per impact".into(),
            };
            let opening = c["max_opening"]
                .as_array()
                .into_iter()
                .flatten()
                .filter_map(Value::as_f64)
                .fold(0.0, f64::max);
            let seat = match (&c["seat"], &c["unseated"]) {
                (x @ Value::Number(_), Value::Bool(true)) => format!("{}: UNSEATED", mm(x)),
                (x @ Value::Number(_), _) => format!("{}: seated", mm(x)),
                _ => "–".into(),
            };
            let impacts = match c["consumed"].as_u64() {
                Some(k) => format!("{} (bumper consumed {k})", c["impacts"]),
                None => c["impacts"].to_string(),
            };
            vec![
                e(&label),
                mm(&c["gap"]),
                floors.join(", "),
                e(c["model"].as_str().unwrap_or("")),
                n(&c["e"]),
                format!("{} (n = {})", n(&c["stiffness"]), n(&c["exponent"])),
                param,
                impacts,
                mn(&c["peak_force"]),
                mm(&c["max_penetration"]),
                kj(&c["dissipated_energy"]),
                plain(opening * 1e3, 4),
                seat,
            ]
        })
        .collect();
    table(
        &mut h,
        "contacts",
        "Contacts",
        &[
            "contact",
            "gap (mm)",
            "floors",
            "model",
            "e",
            "k (N/m^n, SI)",
            "damping",
            "impacts",
            "peak force (MN)",
            "max penetration (mm)",
            "dissipated (kJ)",
            "largest opening (mm)",
            "seat (mm)",
        ],
        &rows,
    );
    let devices: Vec<Vec<String>> = list("devices")
        .iter()
        .map(|d| {
            let pairs: Vec<String> = d["floors"]
                .as_array()
                .into_iter()
                .flatten()
                .map(|p| format!("{}-{}", p[0], p[1]))
                .collect();
            let peaks = |key: &str, f: fn(&Value) -> String| {
                d[key]
                    .as_array()
                    .into_iter()
                    .flatten()
                    .map(f)
                    .collect::<Vec<_>>()
                    .join(", ")
            };
            vec![
                e(d["name"].as_str().unwrap_or("")),
                e(&between(d)),
                pairs.join(", "),
                e(&d["law"]
                    .as_object()
                    .into_iter()
                    .flatten()
                    .map(|(k, v)| match v {
                        Value::String(x) => x.clone(),
                        _ => format!("{k} {}", n(v)),
                    })
                    .collect::<Vec<_>>()
                    .join(", ")),
                peaks("peak_force", mn),
                peaks("max_closing", mm),
                peaks("max_opening", mm),
            ]
        })
        .collect();
    if !devices.is_empty() {
        table(
            &mut h,
            "devices",
            "Devices (law, SI: stiffness N/m, damping N s/m, slack m)",
            &[
                "device",
                "between",
                "floors",
                "law",
                "peak force (MN)",
                "largest closing (mm)",
                "largest opening (mm)",
            ],
            &devices,
        );
    }
    let en = &s["energy"];
    table(
        &mut h,
        "energy",
        "Energy at the end of the analysis (kJ): input = kinetic + strain + structural damping + storey hysteresis + contact",
        &[
            "input",
            "kinetic",
            "strain",
            "structural damping",
            "storey hysteresis",
            "contact",
            "balance error (relative)",
        ],
        &[vec![
            kj(&en["input"]),
            kj(&en["kinetic"]),
            kj(&en["strain"]),
            kj(&en["structural_damping"]),
            kj(&en["hysteretic"]),
            kj(&en["contact"]),
            n(&s["energy_balance_error"]),
        ]],
    );

    // Figures.
    h.push_str("\n<h2 id=\"figures\">Figures</h2>");
    for (k, f) in figs.iter().enumerate() {
        let _ = write!(
            h,
            "\n<figure id=\"fig-{}\">\n{}<figcaption>Figure {}: {} ({}.svg with <code>--plots</code>)</figcaption>\n</figure>",
            e(&f.id),
            svg::render(f),
            k + 1,
            e(&f.title),
            e(&f.id)
        );
    }

    // Impacts.
    h.push_str("\n<h2 id=\"impacts\">Impacts</h2>");
    if d.contacts.is_empty() {
        h.push_str("\n<p>The scenario has no contacts.</p>");
    } else if d.impacts.is_empty() {
        h.push_str("\n<p>No impacts: the gaps never closed.</p>");
    }
    let shown = d.impacts.len().min(MAX_IMPACT_ROWS);
    if shown < d.impacts.len() {
        let _ = write!(
            h,
            "\n<p>The first {shown} of {} impacts; all are in impacts.csv.</p>",
            d.impacts.len()
        );
    }
    let rows: Vec<Vec<String>> = d.impacts[..shown]
        .iter()
        .enumerate()
        .map(|(k, i)| {
            vec![
                (k + 1).to_string(),
                e(&d.contacts[i.contact].name),
                match i.floors {
                    // A wall's side has no floor.
                    (f, 0) | (0, f) => f.to_string(),
                    (l, r) => format!("{l}-{r}"),
                },
                format!("{:.4}", i.time),
                plain(i.v_i, 4),
                i.e_post.map_or("(not ended)".into(), |x| plain(x, 4)),
                plain(i.peak_force * 1e-6, 4),
                format!("{:.4}", i.time_of_peak_force),
                plain(i.duration * 1e3, 4),
                plain(i.max_penetration * 1e3, 4),
                plain(i.dissipated_energy * 1e-3, 4),
            ]
        })
        .collect();
    table(
        &mut h,
        "impact-list",
        "Every impact (time of touch, relative velocity at touch, delivered e = −v_out / v_i)",
        &[
            "#",
            "contact",
            "floors",
            "touch (s)",
            "v_i (m/s)",
            "e_post",
            "peak force (MN)",
            "peak at (s)",
            "duration (ms)",
            "max penetration (mm)",
            "dissipated (kJ)",
        ],
        &rows,
    );
    h.push_str("\n<footer><p class=\"meta\">Files: summary.json, response.csv, impacts.csv, impact-loops.csv, energy.csv, scenario.toml (base SI units, named in every column header).</p></footer>");
    h.push_str("\n</body>\n</html>\n");
    h
}

/// A building's storey models in a few words: "linear", "bilinear", or "1-2 bilinear, 3 linear".
fn models(b: &Value) -> String {
    let names: Vec<&str> = b["storey_models"]
        .as_array()
        .into_iter()
        .flatten()
        .map(|m| m.as_str().unwrap_or("linear"))
        .collect();
    if names.windows(2).all(|w| w[0] == w[1]) {
        return names.first().copied().unwrap_or("linear").to_string();
    }
    // Runs of storeys with the same model.
    let mut runs: Vec<(usize, usize, &str)> = Vec::new();
    for (j, m) in names.iter().enumerate() {
        match runs.last_mut() {
            Some(r) if r.2 == *m => r.1 = j + 1,
            _ => runs.push((j + 1, j + 1, m)),
        }
    }
    let runs: Vec<String> = runs
        .iter()
        .map(|(a, z, m)| {
            if a == z {
                format!("{a} {m}")
            } else {
                format!("{a}-{z} {m}")
            }
        })
        .collect();
    runs.join(", ")
}

fn between(c: &Value) -> String {
    let names: Vec<&str> = c["between"]
        .as_array()
        .into_iter()
        .flatten()
        .filter_map(Value::as_str)
        .collect();
    names.join("|")
}
