//! The report's markup: escaping, numbers for people in display units, tables and the style sheet.

use crate::plot::axis::plain;
use crate::plot::svg;
use std::fmt::Write as _;

/// `s` escaped for HTML text and attributes.
pub fn e(s: &str) -> String {
    svg::esc(s)
}

/// A number for people: 5 significant digits, never in e-notation.
pub fn n(x: f64) -> String {
    plain(x, 5)
}

/// A length (m in the files) in mm, 4 significant digits.
pub fn mm(x: f64) -> String {
    plain(x * 1e3, 4)
}

/// A force (N in the files) in MN, 4 significant digits.
pub fn mn(x: f64) -> String {
    plain(x * 1e-6, 4)
}

/// An energy (J in the files) in kJ, 4 significant digits.
pub fn kj(x: f64) -> String {
    plain(x * 1e-3, 4)
}

/// A time in s, to the ms (times of events within a run).
pub fn secs(x: f64) -> String {
    format!("{x:.3}")
}

/// A table: id, caption, header cells (with units) and rows of cells (already escaped).
pub fn table(out: &mut String, id: &str, caption: &str, head: &[&str], rows: &[Vec<String>]) {
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

/// One `<dt>`/`<dd>` pair of a definition list (`v` already escaped).
pub fn dl(out: &mut String, k: &str, v: String) {
    let _ = write!(out, "\n<dt>{}</dt><dd>{}</dd>", e(k), v);
}

/// The display units of the report's tables and figures (the files keep base SI units).
pub const UNITS: &str = "lengths in mm, forces in MN, energies in kJ, accelerations in m/s², velocities in \
                         m/s, times in s (one impact's duration in ms); the files keep base SI units";

/// The style sheet.
pub const STYLE: &str = "
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
