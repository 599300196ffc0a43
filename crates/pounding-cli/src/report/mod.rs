//! The HTML report of a run: one self-contained file from the output folder of a run: the scenario, modal
//! properties, summary tables, every impact and the figures as inline SVG. No script, no external file, and a
//! Content-Security-Policy that forbids any network access; it opens offline and can be mailed.
//!
//! The document is well-formed XML as well as HTML5 (void elements closed, only XML's five entities), so
//! that tests and scripts can parse it with any XML reader. It is written section by section: the summary
//! ([`summary`]), the tables ([`tables`]), the figures and the impacts.

mod markup;
mod plan;
mod summary;
mod tables;

use crate::error::CliError;
use crate::plot::axis::plain;
use crate::plot::{svg, Figure};
use crate::run_data::RunData;
use markup::{e, table, STYLE, UNITS};
use pounding::structure::Form;
use pounding_study::input::write_atomic;
use std::fmt::Write as _;
use std::path::Path;

/// Impacts listed in the report's table at most (all are in impacts.csv).
const MAX_IMPACT_ROWS: usize = 1000;

/// Writes the report of `data` with `figs` to `path` (atomically); returns its file name.
pub fn write(data: &RunData, figs: &[Figure], path: &Path) -> Result<String, CliError> {
    let html = html(data, figs);
    write_atomic(path, html.as_bytes())
        .map_err(|e| CliError::Io(format!("cannot write {}: {e}", path.display())))?;
    Ok(path
        .file_name()
        .map_or("report.html".into(), |n| n.to_string_lossy().into_owned()))
}

/// The report as an HTML document.
pub fn html(d: &RunData, figs: &[Figure]) -> String {
    let s = &d.summary;
    let scenario = &s.scenario;
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
    summary::section(&mut h, s);
    h.push_str("\n<h2 id=\"scenario\">Scenario</h2>");
    match &d.scenario_text {
        Some(t) => {
            let _ = write!(h, "\n<pre>{}</pre>", e(t));
        }
        None => h.push_str("\n<p>The output folder holds no scenario.toml.</p>"),
    }
    tables::modes(&mut h, s);
    tables::response(&mut h, s);
    tables::contacts(&mut h, s);
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
    impacts(&mut h, d);
    h.push_str("\n<footer><p class=\"meta\">Files: summary.json, response.csv, impacts.csv, impact-loops.csv, energy.csv, scenario.toml (base SI units, named in every column header).</p></footer>");
    h.push_str("\n</body>\n</html>\n");
    h
}

/// The impacts section: every impact (up to [`MAX_IMPACT_ROWS`]).
fn impacts(h: &mut String, d: &RunData) {
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
    // Decks are one mass each: no floor numbers when every structure is one.
    let decks = d.summary.buildings.iter().all(|b| b.form() == Form::Deck);
    // With a bumper, which law each row is of.
    let layers = d.summary.sites.iter().any(|c| c.bumper.is_some());
    let rows: Vec<Vec<String>> = d.impacts[..shown]
        .iter()
        .enumerate()
        .map(|(k, i)| {
            let mut row = vec![(k + 1).to_string(), e(&d.contacts[i.contact].name)];
            if !decks {
                row.push(match i.floors {
                    // A wall's side has no floor.
                    (f, 0) | (0, f) => f.to_string(),
                    (l, r) => format!("{l}-{r}"),
                });
            }
            if layers {
                row.push(i.layer.name().to_string());
            }
            row.extend([
                format!("{:.4}", i.time),
                plain(i.v_i, 4),
                i.e_post.map_or("(not ended)".into(), |x| plain(x, 4)),
                plain(i.peak_force * 1e-6, 4),
                format!("{:.4}", i.time_of_peak_force),
                plain(i.duration * 1e3, 4),
                plain(i.max_penetration * 1e3, 4),
                plain(i.dissipated_energy * 1e-3, 4),
            ]);
            row
        })
        .collect();
    let mut head = vec!["#", "contact"];
    if !decks {
        head.push("floors");
    }
    if layers {
        head.push("layer");
    }
    head.extend([
        "touch (s)",
        "v_i (m/s)",
        "e_post",
        "peak force (MN)",
        "peak at (s)",
        "duration (ms)",
        "max penetration (mm)",
        "dissipated (kJ)",
    ]);
    let caption = if layers {
        "Every impact (time of touch, relative velocity at touch, delivered e = −v_out / v_i), as the rows of \
         impacts.csv (#). Layer: direct, the site's own law; bumper, a bumper's layer; consumed, the hard law \
         behind a bumper compressed to its limit (max_strain × thickness). A consumed row is no impact of its \
         own: it lies within the last bumper row of its level above it, from the instant the layer \
         was used up (its touch, its v_i the closing speed then) to the instant the hard law let go."
    } else {
        "Every impact (time of touch, relative velocity at touch, delivered e = −v_out / v_i)"
    };
    table(h, "impact-list", caption, &head, &rows);
}
