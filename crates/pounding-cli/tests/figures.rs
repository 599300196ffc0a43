//! Figures and the HTML report, read back as a user's script would: every SVG is parsed, its pixels are
//! turned back into data with the axis ranges the figure carries, and the data are compared with the
//! command's own results. Tolerances are the figure's resolution: coordinates are written to 0.01 px, so a
//! value is known to 0.005 px of its axis.

use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// The figures' font metrics (DejaVu Sans and its bold face), the ones the layout uses.
#[path = "../src/plot/font.rs"]
mod font;

fn pounding(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_pounding"))
        .args(args)
        .output()
        .expect("runs")
}

fn ok_json(args: &[&str]) -> Value {
    let o = pounding(args);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    serde_json::from_slice(&o.stdout).expect("one JSON object on stdout")
}

fn tmp(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("pounding-fig-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

fn example(name: &str) -> String {
    format!("{}/../../examples/{name}", env!("CARGO_MANIFEST_DIR"))
}

/// A panel read back from an SVG: its axes, and every series in data units.
#[derive(Debug, Default)]
struct Panel {
    title: String,
    log_y: bool,
    log_x: bool,
    x: (f64, f64),
    y: (f64, f64),
    /// Data per 0.005 px, along x and y.
    res: (f64, f64),
    lines: Vec<(String, Vec<(f64, f64)>)>,
    points: Vec<(String, Vec<(f64, f64)>)>,
    hlines: Vec<(String, f64)>,
    rugs: Vec<(String, usize)>,
    /// For each line, the label of the earlier line it coincides with (`data-same-as`).
    same_as: Vec<Option<String>>,
    /// For each points series, its colour and marker shape ("circle", or a path's commands: "MhvhZ").
    point_styles: Vec<(String, String)>,
    /// The legend's texts.
    legend: Vec<String>,
}

fn attr(n: roxmltree::Node, name: &str) -> f64 {
    n.attribute(name)
        .unwrap_or_else(|| panic!("{name} missing"))
        .parse()
        .unwrap()
}

/// Every panel of the SVG document `text`, in data units.
fn panels(text: &str) -> Vec<Panel> {
    let doc = roxmltree::Document::parse(text).expect("well-formed SVG");
    let root = doc.root_element();
    assert_eq!(root.tag_name().name(), "svg");
    root.descendants()
        .filter(|n| n.attribute("class") == Some("panel"))
        .map(|g| {
            let mut p = Panel {
                title: g.attribute("data-title").unwrap_or("").into(),
                log_y: g.attribute("data-y-scale") == Some("log"),
                log_x: g.attribute("data-x-scale") == Some("log"),
                x: (attr(g, "data-x-lo"), attr(g, "data-x-hi")),
                y: (attr(g, "data-y-lo"), attr(g, "data-y-hi")),
                ..Panel::default()
            };
            let (l, r, t, b) = (
                attr(g, "data-left"),
                attr(g, "data-right"),
                attr(g, "data-top"),
                attr(g, "data-bottom"),
            );
            p.res = (
                0.0051 / (r - l) * (p.x.1 - p.x.0),
                0.0051 / (b - t) * (p.y.1 - p.y.0),
            );
            let (x, y, log, log_x) = (p.x, p.y, p.log_y, p.log_x);
            let data = |px: f64, py: f64| {
                let fx = (px - l) / (r - l);
                let fy = (b - py) / (b - t);
                let yv = if log {
                    y.0 * (y.1 / y.0).powf(fy)
                } else {
                    y.0 + fy * (y.1 - y.0)
                };
                let xv = if log_x {
                    x.0 * (x.1 / x.0).powf(fx)
                } else {
                    x.0 + fx * (x.1 - x.0)
                };
                (xv, yv)
            };
            for n in g.descendants() {
                let label = n.attribute("data-label").unwrap_or("").to_string();
                match n.attribute("class") {
                    Some("line") => {
                        let pts = n
                            .attribute("points")
                            .unwrap()
                            .split(' ')
                            .map(|xy| {
                                let (a, b) = xy.split_once(',').unwrap();
                                data(a.parse().unwrap(), b.parse().unwrap())
                            })
                            .collect();
                        p.same_as
                            .push(n.attribute("data-same-as").map(String::from));
                        p.lines.push((label, pts));
                    }
                    Some("points") => {
                        // A marker is a circle, or a path (square, triangle, ...) carrying its centre.
                        let pts = n
                            .children()
                            .filter_map(|c| {
                                if c.has_tag_name("circle") {
                                    Some(data(attr(c, "cx"), attr(c, "cy")))
                                } else if c.has_tag_name("path") {
                                    Some(data(attr(c, "data-cx"), attr(c, "data-cy")))
                                } else {
                                    None
                                }
                            })
                            .collect();
                        p.points.push((label, pts));
                        p.point_styles.push((
                            n.attribute("fill").unwrap_or("").to_string(),
                            n.children()
                                .find(|c| c.is_element())
                                .map_or(String::new(), |c| {
                                    // The shape: a circle, or the path's commands.
                                    if c.has_tag_name("circle") {
                                        "circle".into()
                                    } else {
                                        c.attribute("d")
                                            .unwrap_or("")
                                            .chars()
                                            .filter(|ch| ch.is_ascii_alphabetic())
                                            .collect()
                                    }
                                }),
                        ));
                    }
                    Some("hline") => p.hlines.push((label, attr(n, "data-value"))),
                    Some("rug") => p.rugs.push((label, attr(n, "data-count") as usize)),
                    Some("legend") => p.legend.extend(
                        n.children()
                            .filter(|c| c.has_tag_name("text"))
                            .map(|c| c.text().unwrap_or("").to_string()),
                    ),
                    _ => {}
                }
            }
            p
        })
        .collect()
}

fn read_panels(path: &Path) -> Vec<Panel> {
    panels(&std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display())))
}

/// Every panel title of an SVG (the document's element `svg`) whose text is cut (the panel's `data-title`
/// is the whole title).
fn cut_titles(svg: roxmltree::Node) -> Vec<String> {
    svg.descendants()
        .filter(|n| n.attribute("class") == Some("panel"))
        .filter_map(|g| {
            let whole = g.attribute("data-title").unwrap_or("");
            let shown = g
                .descendants()
                .find(|t| t.attribute("class") == Some("ptitle"))
                .and_then(|t| t.text())
                .unwrap_or("");
            (shown != whole).then(|| whole.to_string())
        })
        .collect()
}

/// Parses every SVG in `dir`: each is well-formed, has at least one panel, no panel title cut, and every
/// plotted value is finite.
fn every_svg_reads_back(dir: &Path) -> usize {
    let mut n = 0;
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|x| x == "svg") {
            let text = std::fs::read_to_string(&path).unwrap();
            let doc = roxmltree::Document::parse(&text).expect("well-formed SVG");
            let bad = text_fits(doc.root_element(), "");
            assert!(bad.is_empty(), "{}: {bad:#?}", path.display());
            let ps = read_panels(&path);
            assert!(!ps.is_empty(), "{}: no panel", path.display());
            for p in &ps {
                let all = p.lines.iter().chain(&p.points).flat_map(|s| &s.1);
                assert!(
                    all.clone().all(|(x, y)| x.is_finite() && y.is_finite()),
                    "{}",
                    path.display()
                );
            }
            n += 1;
        }
    }
    n
}

/// The texts of the elements of class `class` among the children of `svg` (titles, subtitles and notes
/// are the SVG's own children; a report's figure is an `<svg>` inside the page).
fn texts_of<'a>(
    svg: roxmltree::Node<'a, 'a>,
    class: &str,
) -> Vec<(roxmltree::Node<'a, 'a>, String)> {
    svg.children()
        .filter(|n| n.attribute("class") == Some(class))
        .map(|n| (n, n.text().unwrap_or("").to_string()))
        .collect()
}

/// Checks that the figure `svg` shows its whole title and subtitle inside its width: every line of the title
/// (in the bold face it is set in) and of the subtitle fits, centred, with 10 px (title) and 20 px
/// (subtitle) to spare at each side; the title's lines hold the `<title>` word for word; no subtitle line
/// is cut with an ellipsis; every note fits from x = 20 to 20 px short of the right edge; and no panel
/// title is cut. `subtitle_starts` is the text the subtitle begins with (the scenario's file name).
/// Returns what is wrong, one line per defect.
fn text_fits(svg: roxmltree::Node, subtitle_starts: &str) -> Vec<String> {
    let id = svg.attribute("data-figure").unwrap_or("?").to_string();
    let width = attr(svg, "width");
    let mut bad = Vec::new();
    let whole = svg
        .children()
        .find(|n| n.has_tag_name("title"))
        .and_then(|t| t.text())
        .unwrap_or("")
        .to_string();
    let title = texts_of(svg, "title");
    let shown: String = title
        .iter()
        .map(|(_, t)| t.as_str())
        .collect::<Vec<_>>()
        .join(" ");
    if title.is_empty() || shown.replace(' ', "") != whole.replace(' ', "") {
        bad.push(format!("{id}: title {whole:?} shown as {shown:?}"));
    }
    let centred = |n: roxmltree::Node| {
        n.attribute("text-anchor") == Some("middle") && (attr(n, "x") - width / 2.0).abs() < 0.01
    };
    for (n, t) in &title {
        let w = font::bold_text_width(t, attr(*n, "font-size"));
        if !centred(*n) || w > width - 20.0 + 1e-9 {
            bad.push(format!(
                "{id}: title line {t:?} is {w:.1} px in a figure {width} px wide"
            ));
        }
    }
    let sub = texts_of(svg, "subtitle");
    let joined: String = sub
        .iter()
        .map(|(_, t)| t.as_str())
        .collect::<Vec<_>>()
        .join(" ");
    if !joined.starts_with(subtitle_starts) {
        bad.push(format!(
            "{id}: subtitle {joined:?} does not start with {subtitle_starts:?}"
        ));
    }
    for (n, t) in &sub {
        let w = font::text_width(t, attr(*n, "font-size"));
        if !centred(*n) || w > width - 40.0 + 1e-9 || t.ends_with('\u{2026}') {
            bad.push(format!(
                "{id}: subtitle line {t:?} is {w:.1} px (or cut) in {width} px"
            ));
        }
    }
    for (n, t) in texts_of(svg, "note") {
        let w = font::text_width(&t, attr(n, "font-size"));
        if attr(n, "x") + w > width - 20.0 + 1e-9 {
            bad.push(format!("{id}: note line {t:?} runs past the right edge"));
        }
    }
    let cut = cut_titles(svg);
    if !cut.is_empty() {
        bad.push(format!("{id}: panel titles cut: {cut:?}"));
    }
    bad
}

fn max_y(pts: &[(f64, f64)]) -> f64 {
    pts.iter().map(|p| p.1).fold(f64::NEG_INFINITY, f64::max)
}

/// `--png` in a build that has it, so that the figures are tested either way.
const PNG: &[&str] = if cfg!(feature = "png") {
    &["--png"]
} else {
    &[]
};

/// Width and height of a PNG file, from its IHDR chunk.
fn png_size(path: &Path) -> (u32, u32) {
    let b = std::fs::read(path).unwrap();
    assert_eq!(
        &b[..8],
        b"\x89PNG\r\n\x1a\n",
        "{} is not a PNG",
        path.display()
    );
    let be = |i: usize| u32::from_be_bytes([b[i], b[i + 1], b[i + 2], b[i + 3]]);
    (be(16), be(20))
}

fn svg_size(path: &Path) -> (f64, f64) {
    let text = std::fs::read_to_string(path).unwrap();
    let doc = roxmltree::Document::parse(&text).unwrap();
    let r = doc.root_element();
    (attr(r, "width"), attr(r, "height"))
}

/// The contact sites of a summary of one kind (`contact` or `wall`), in order.
fn sites<'a>(summary: &'a Value, kind: &str) -> Vec<&'a Value> {
    summary["sites"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|s| s["kind"] == kind)
        .collect()
}

#[test]
fn impact_figures_show_the_located_peak_and_the_whole_contact() {
    let dir = tmp("impact");
    let r = ok_json(
        &[
            &[
                "impact",
                "--model",
                "papi",
                "--e",
                "0.65",
                "--json",
                "--out",
                dir.to_str().unwrap(),
                "--plots",
            ],
            PNG,
        ]
        .concat(),
    );
    let peak = r["peak_force"].as_f64().unwrap();
    let p = &read_panels(&dir.join("impact-force-time.svg"))[0];
    let curve = &p.lines[0].1;
    assert!(
        (max_y(curve) - peak).abs() <= p.res.1,
        "{} vs {peak}",
        max_y(curve)
    );
    // The time axis runs from touch to the end of contact.
    assert_eq!(p.x, (0.0, r["contact_duration"].as_f64().unwrap()));
    assert_eq!(p.points[0].1.len(), 1);
    assert!((p.points[0].1[0].1 - peak).abs() <= p.res.1);
    assert!((p.points[0].1[0].0 - r["time_of_peak_force"].as_f64().unwrap()).abs() <= p.res.0);
    // The loop reaches the largest penetration and closes at zero force.
    let q = &read_panels(&dir.join("impact-force-penetration.svg"))[0];
    let d_max = q.lines[0].1.iter().map(|p| p.0).fold(0.0, f64::max);
    assert!((d_max - r["max_penetration"].as_f64().unwrap()).abs() <= q.res.0);
    assert!(q.lines[0].1.last().unwrap().1.abs() <= q.res.1);
    assert_eq!(every_svg_reads_back(&dir), 2);
    // The history and the result beside the figures.
    let (hh, hrows) = csv(&dir.join("history.csv"));
    assert_eq!(hh[0], "t_s");
    assert!(hrows.len() > 10);
    let saved: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("impact.json")).unwrap()).unwrap();
    assert_eq!(saved, r);
    // PNGs at twice the SVG size.
    for name in ["impact-force-time", "impact-force-penetration"] {
        if !cfg!(feature = "png") {
            break;
        }
        let (w, h) = svg_size(&dir.join(format!("{name}.svg")));
        assert_eq!(
            png_size(&dir.join(format!("{name}.png"))),
            ((2.0 * w) as u32, (2.0 * h) as u32)
        );
    }
}

#[test]
fn drop_figures_show_the_located_peak() {
    let dir = tmp("drop");
    let r = ok_json(&[
        "drop",
        "--model",
        "hertzdamp",
        "--e",
        "0.65",
        "--radius",
        "0.1",
        "--youngs-modulus",
        "30e9",
        "--poisson",
        "0.2",
        "--height",
        "0.5",
        "--json",
        "--out",
        dir.to_str().unwrap(),
        "--plots",
    ]);
    let p = &read_panels(&dir.join("drop-force-time.svg"))[0];
    assert!((max_y(&p.lines[0].1) - r["peak_force"].as_f64().unwrap()).abs() <= p.res.1);
    assert_eq!(every_svg_reads_back(&dir), 2);
}

#[test]
fn compare_overlays_each_model_with_its_own_peak() {
    let dir = tmp("compare");
    let r = ok_json(&[
        "compare",
        "--models",
        "papi,hertzdamp,jankowski",
        "--e",
        "0.5",
        "--json",
        "--out",
        dir.to_str().unwrap(),
        "--plots",
    ]);
    let p = &read_panels(&dir.join("compare-force-time.svg"))[0];
    let models = r["models"].as_array().unwrap();
    assert_eq!(p.lines.len(), models.len());
    for (m, (label, curve)) in models.iter().zip(&p.lines) {
        assert!(label.starts_with(m["model"].as_str().unwrap()), "{label}");
        let peak = m["peak_force"].as_f64().unwrap();
        assert!(
            (max_y(curve) - peak).abs() <= p.res.1,
            "{label}: {} vs {peak}",
            max_y(curve)
        );
    }
}

#[test]
fn table1_figures_give_back_the_table() {
    let dir = tmp("table1");
    let t = ok_json(&[
        "paper",
        "table1",
        "--json",
        "--out",
        dir.to_str().unwrap(),
        "--plots",
    ]);
    let panels = read_panels(&dir.join("table1-e-post.svg"));
    let mut checked = 0;
    for row in t["rows"].as_array().unwrap() {
        let label = row["label"].as_str().unwrap();
        let (p, pts) = panels
            .iter()
            .find_map(|p| p.lines.iter().find(|l| l.0 == label).map(|l| (p, &l.1)))
            .unwrap_or_else(|| panic!("no curve {label}"));
        assert_eq!(pts.len(), 91, "{label}: e = 0.10 to 1.00");
        // The mean relative error of the plotted curve is the table's, to the figure's resolution
        // (e is the grid value, e_post is read to res.1, and e >= 0.1).
        let mean = pts
            .iter()
            .map(|&(x, y)| {
                let e = (x * 100.0).round() / 100.0;
                (e - y).abs() / e * 100.0
            })
            .sum::<f64>()
            / pts.len() as f64;
        let want = row["grid_0.01"]["all"].as_f64().unwrap();
        assert!(
            (mean - want).abs() <= p.res.1 / 0.1 * 100.0,
            "{label}: {mean} vs {want}"
        );
        checked += 1;
    }
    assert_eq!(checked, t["rows"].as_array().unwrap().len());
    assert_eq!(every_svg_reads_back(&dir), 2);
    // The error figure is on decades.
    assert!(read_panels(&dir.join("table1-error.svg"))
        .iter()
        .all(|p| p.log_y));
}

fn csv(path: &Path) -> (Vec<String>, Vec<Vec<String>>) {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    let header = lines.next().unwrap().split(',').map(String::from).collect();
    let rows = lines
        .map(|l| l.split(',').map(String::from).collect())
        .collect();
    (header, rows)
}

fn col(h: &[String], rows: &[Vec<String>], name: &str) -> Vec<f64> {
    let k = h
        .iter()
        .position(|c| c == name)
        .unwrap_or_else(|| panic!("{name}"));
    rows.iter().map(|r| r[k].parse().unwrap()).collect()
}

#[test]
fn run_figures_and_report_match_the_results() {
    let dir = tmp("run");
    let s = ok_json(
        &[
            &[
                "run",
                &example("two-sdof.toml"),
                "--out",
                dir.to_str().unwrap(),
                "--json",
                "--plots",
                "--report",
            ],
            PNG,
        ]
        .concat(),
    );
    let contact = sites(&s, "contact")[0];
    let (ih, irows) = csv(&dir.join("impacts.csv"));
    let n_impacts = irows.len();
    assert_eq!(n_impacts as u64, contact["impacts"].as_u64().unwrap());

    // Contact force: the curve reaches the contact's peak force; one marker per impact, at its peak.
    let p = &read_panels(&dir.join("contact-force.svg"))[0];
    let peak = contact["peak_force"].as_f64().unwrap();
    assert!((max_y(&p.lines[0].1) - peak).abs() <= p.res.1);
    let marks = &p.points[0].1;
    assert_eq!(marks.len(), n_impacts);
    for ((x, y), (t, f)) in marks.iter().zip(
        col(&ih, &irows, "time_of_peak_force_s")
            .into_iter()
            .zip(col(&ih, &irows, "peak_force_N")),
    ) {
        assert!(
            (x - t).abs() <= p.res.0 && (y - f).abs() <= p.res.1,
            "({x}, {y}) vs ({t}, {f}), {:?}",
            p.res
        );
    }

    // Displacements: the ground motion, then one panel per building; each building's curve is the
    // response.csv column, and its impact instants are all the impacts.
    let (rh, rrows) = csv(&dir.join("response.csv"));
    let d = read_panels(&dir.join("displacement.svg"));
    assert_eq!(d.len(), 3);
    let ground = col(&rh, &rrows, "ground_acceleration_m_per_s2");
    let top = ground.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
    assert!((max_y(&d[0].lines[0].1) - top).abs() <= d[0].res.1);
    for (b, name) in [(1, "left"), (2, "right")] {
        let u = col(&rh, &rrows, &format!("{name}_floor1_displacement_m"));
        let (lo, hi) = u
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, c), v| {
                (a.min(*v), c.max(*v))
            });
        assert!(
            d[b].title.contains(&format!("building {name}")),
            "{}",
            d[b].title
        );
        let curve = &d[b].lines[0].1;
        let clo = curve.iter().map(|p| p.1).fold(f64::INFINITY, f64::min);
        assert!((max_y(curve) - hi).abs() <= d[b].res.1 && (clo - lo).abs() <= d[b].res.1);
        // Located peaks lie between samples, never below them.
        let located = s["buildings"][b - 1]["peak_displacement"][0]
            .as_f64()
            .unwrap();
        assert!(located >= hi.max(-lo) - d[b].res.1);
        assert_eq!(d[b].rugs[0].1, n_impacts);
    }

    // Relative displacement: the gap line at the scenario's gap; the curve crosses it at every impact.
    let q = &read_panels(&dir.join("relative-displacement.svg"))[0];
    assert_eq!(q.hlines[0].1, contact["gap"].as_f64().unwrap());
    assert!(max_y(&q.lines[0].1) > q.hlines[0].1);

    // Energy: the input curve ends at the summary's input energy.
    let e = &read_panels(&dir.join("energy.svg"))[0];
    let input = e.lines.iter().find(|l| l.0.starts_with("input")).unwrap();
    let (eh, erows) = csv(&dir.join("energy.csv"));
    let last = *col(&eh, &erows, "input_J").last().unwrap();
    assert!((input.1.last().unwrap().1 - last).abs() <= e.res.1);

    // Delivered e of every ended impact against its v_i.
    let r = &read_panels(&dir.join("impact-restitution.svg"))[0];
    assert_eq!(r.points[0].1.len(), n_impacts);
    assert_eq!(r.hlines[0].1, contact["e"].as_f64().unwrap());

    // Linear storeys: the loop is of the storey with the largest peak drift ratio, with no yield lines.
    let ratio = |b: usize| s["buildings"][b]["peak_drift_ratio"][0].as_f64().unwrap();
    let most = if ratio(1) > ratio(0) { "right" } else { "left" };
    assert!(
        figure_title(&dir.join("hysteresis.svg")).contains(&format!("building {most}, storey 1")),
        "{}",
        figure_title(&dir.join("hysteresis.svg"))
    );
    let h = &read_panels(&dir.join("hysteresis.svg"))[0];
    assert!(h.hlines.is_empty());
    assert!(!dir.join("hysteresis-storeys.svg").exists());
    // One storey: each envelope is one segment (floor values) or one step (storey values).
    let env = read_panels(&dir.join("envelopes.svg"));
    assert_eq!(env.len(), 4);
    assert!(env
        .iter()
        .all(|p| p.lines.len() == 2 && p.lines[0].1.len() == 2));

    for name in [
        "displacement",
        "envelopes",
        "hysteresis",
        "contact-force",
        "relative-displacement",
        "energy",
        "impact-restitution",
    ] {
        if !cfg!(feature = "png") {
            break;
        }
        let (w, h) = svg_size(&dir.join(format!("{name}.svg")));
        assert_eq!(
            png_size(&dir.join(format!("{name}.png"))),
            ((2.0 * w) as u32, (2.0 * h) as u32)
        );
    }

    // The report: well-formed, every figure and table, every impact, and nothing fetched from anywhere.
    let html = std::fs::read_to_string(dir.join("report.html")).unwrap();
    let doc = report(&html);
    let figures = figure_ids(&doc);
    assert_eq!(
        figures,
        [
            "record",
            "displacement",
            "envelopes",
            "hysteresis",
            "contact-force",
            "impact-loops",
            "impact-restitution",
            "relative-displacement",
            "energy"
        ]
    );
    let table = |id: &str| {
        doc.descendants()
            .find(|n| n.has_tag_name("table") && n.attribute("id") == Some(id))
            .unwrap_or_else(|| panic!("table {id}"))
    };
    for id in [
        "modes-0",
        "modes-1",
        "peaks",
        "storeys-0",
        "storeys-1",
        "contacts",
        "energy",
        "impact-list",
    ] {
        table(id);
    }
    let rows = |id: &str| {
        table(id)
            .descendants()
            .filter(|n| n.has_tag_name("tr"))
            .count()
            - 1
    };
    assert_eq!(rows("impact-list"), n_impacts);
    assert_eq!(rows("peaks"), 2);
    assert_eq!(rows("storeys-0"), 1);
    // Linear storeys have no ductility, yield force or hysteretic energy: blank cells.
    let cells = |id: &str| -> Vec<String> {
        table(id)
            .descendants()
            .filter(|n| n.has_tag_name("td"))
            .map(|n| n.text().unwrap_or("").to_string())
            .collect()
    };
    assert_eq!(cells("storeys-0")[1], "linear");
    assert_eq!(&cells("storeys-0")[6..], ["", "", ""]);
    assert!(html.contains("gap = 0.02"), "the scenario file is shown");
    for n in doc.descendants() {
        assert!(
            !["script", "link", "img", "iframe", "object", "embed"].contains(&n.tag_name().name()),
            "{:?} in the report",
            n.tag_name()
        );
        for a in n.attributes() {
            if ["src", "href"].contains(&a.name()) {
                assert!(
                    a.value().starts_with('#'),
                    "{}={} reaches outside",
                    a.name(),
                    a.value()
                );
            }
        }
    }
    assert!(html.contains("Content-Security-Policy\" content=\"default-src 'none'"));

    // `pounding report DIR` makes the same report from the files alone.
    let again = dir.join("again.html");
    let o = pounding(&[
        "report",
        dir.to_str().unwrap(),
        "--out",
        again.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(std::fs::read_to_string(&again).unwrap(), html);
}

/// The text of the `<title>` of an SVG figure.
fn figure_title(path: &Path) -> String {
    let text = std::fs::read_to_string(path).unwrap();
    let doc = roxmltree::Document::parse(&text).unwrap();
    let t = doc
        .root_element()
        .children()
        .find(|n| n.has_tag_name("title"))
        .expect("a title");
    t.text().unwrap_or("").to_string()
}

/// The words of an SVG figure under its title: its subtitle and its notes, lines joined by spaces.
fn figure_words(path: &Path) -> String {
    let text = std::fs::read_to_string(path).unwrap();
    let doc = roxmltree::Document::parse(&text).unwrap();
    doc.root_element()
        .children()
        .filter(|n| matches!(n.attribute("class"), Some("subtitle" | "note")))
        .filter_map(|n| n.text())
        .collect::<Vec<_>>()
        .join(" ")
}

fn numbers(v: &Value) -> Vec<f64> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect()
}

fn extremes(v: impl IntoIterator<Item = f64>) -> (f64, f64) {
    v.into_iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
            (a.min(x), b.max(x))
        })
}

#[test]
fn inelastic_run_envelopes_and_loops_match_the_results() {
    let dir = tmp("inelastic");
    let s = ok_json(&[
        "run",
        &example("three-vs-eight-inelastic.toml"),
        "--out",
        dir.to_str().unwrap(),
        "--json",
        "--plots",
        "--report",
    ]);
    let buildings = s["buildings"].as_array().unwrap();
    // Floor elevations from the scenario's storey heights, ground first.
    let scenario: toml::Table = std::fs::read_to_string(dir.join("scenario.toml"))
        .unwrap()
        .parse()
        .unwrap();
    let levels: Vec<Vec<f64>> = scenario["building"]
        .as_array()
        .unwrap()
        .iter()
        .map(|b| {
            let mut z = vec![0.0];
            for h in b["heights"].as_array().unwrap() {
                z.push(z.last().unwrap() + h.as_float().unwrap());
            }
            z
        })
        .collect();

    // Envelopes: displacement, drift ratio (%), absolute acceleration, storey shear; one line per building,
    // through the summary's peaks at the floors (0 and the PGA at the ground), or as steps over the storeys.
    let env = read_panels(&dir.join("envelopes.svg"));
    assert_eq!(env.len(), 4);
    let pga = s["record"]["pga"].as_f64().unwrap();
    for (b, bs) in buildings.iter().enumerate() {
        let name = bs["name"].as_str().unwrap();
        let z = &levels[b];
        let n = z.len() - 1;
        let curve = |p: usize| {
            let found = env[p].lines.iter().find(|l| l.0 == name);
            (&env[p], &found.unwrap_or_else(|| panic!("{name}")).1)
        };
        let close = |p: &Panel, (x, y): (f64, f64), (wx, wy): (f64, f64)| {
            assert!(
                (x - wx).abs() <= p.res.0 && (y - wy).abs() <= p.res.1,
                "{}: ({x}, {y}) vs ({wx}, {wy})",
                p.title
            );
        };
        for (k, (key, ground, scale)) in [
            ("peak_displacement", 0.0, 1.0),
            ("peak_absolute_acceleration", pga, 1.0),
        ]
        .into_iter()
        .enumerate()
        {
            let (p, pts) = curve(2 * k);
            let want = numbers(&bs[key]);
            assert_eq!(pts.len(), n + 1, "{key}");
            close(p, pts[0], (ground, 0.0));
            for f in 1..=n {
                close(p, pts[f], (scale * want[f - 1], z[f]));
            }
        }
        for (k, (key, scale)) in [("peak_drift_ratio", 100.0), ("peak_storey_shear", 1.0)]
            .into_iter()
            .enumerate()
        {
            let (p, pts) = curve(2 * k + 1);
            let want = numbers(&bs[key]);
            assert_eq!(pts.len(), 2 * n, "{key}");
            for j in 0..n {
                close(p, pts[2 * j], (scale * want[j], z[j]));
                close(p, pts[2 * j + 1], (scale * want[j], z[j + 1]));
            }
        }
    }

    // The loop: the storey of the largest ductility; its drift u_j - u_(j-1) and shear are the columns of
    // response.csv (extremes and last point), its yield lines at +-F_y.
    let (rh, rrows) = csv(&dir.join("response.csv"));
    let loop_of = |b: usize, j: usize| {
        let name = buildings[b]["name"].as_str().unwrap();
        let u = |f: usize| col(&rh, &rrows, &format!("{name}_floor{f}_displacement_m"));
        let drift: Vec<f64> = if j == 1 {
            u(1)
        } else {
            u(j).iter().zip(u(j - 1)).map(|(a, c)| a - c).collect()
        };
        (
            drift,
            col(&rh, &rrows, &format!("{name}_storey{j}_shear_N")),
        )
    };
    let check_loop = |p: &Panel, (drift, shear): &(Vec<f64>, Vec<f64>), fy: f64| {
        let pts = &p.lines[0].1;
        assert_eq!(pts.len(), drift.len(), "every sample, not thinned");
        let (x, y) = (
            extremes(pts.iter().map(|p| p.0)),
            extremes(pts.iter().map(|p| p.1)),
        );
        let (wx, wy) = (
            extremes(drift.iter().copied()),
            extremes(shear.iter().copied()),
        );
        assert!(
            (x.0 - wx.0).abs() <= p.res.0 && (x.1 - wx.1).abs() <= p.res.0,
            "{}: drift {x:?} vs {wx:?}",
            p.title
        );
        assert!(
            (y.0 - wy.0).abs() <= p.res.1 && (y.1 - wy.1).abs() <= p.res.1,
            "{}: shear {y:?} vs {wy:?}",
            p.title
        );
        let mut lines: Vec<f64> = p.hlines.iter().map(|h| h.1).collect();
        lines.sort_by(f64::total_cmp);
        assert_eq!(lines, [-fy, fy], "{}", p.title);
    };
    let (mut best, mut at) = (0.0, (0, 0, 0));
    for (b, bs) in buildings.iter().enumerate() {
        for (k, (mu, j)) in numbers(&bs["ductility"])
            .into_iter()
            .zip(numbers(&bs["inelastic_storeys"]))
            .enumerate()
        {
            if mu > best {
                (best, at) = (mu, (b, j as usize, k));
            }
        }
    }
    let (b, j, k) = at;
    let name = buildings[b]["name"].as_str().unwrap();
    let title = figure_title(&dir.join("hysteresis.svg"));
    assert!(
        title.contains(&format!("building {name}, storey {j}")),
        "{title}"
    );
    let p = &read_panels(&dir.join("hysteresis.svg"))[0];
    let data = loop_of(b, j);
    check_loop(p, &data, numbers(&buildings[b]["yield_forces"])[k]);
    // The end of the analysis is marked, at the residual drift.
    let end = p.points[0].1[0];
    assert!((end.0 - data.0.last().unwrap()).abs() <= p.res.0);
    assert!((end.1 - data.1.last().unwrap()).abs() <= p.res.1);
    let residual = buildings[b]["residual_drift"][j - 1].as_f64().unwrap();
    assert!((end.0 - residual).abs() <= p.res.0, "{end:?} vs {residual}");

    // Every inelastic storey of every building (issue 23: the other building's were nowhere), building by
    // building, on axes common to the building's storeys.
    let all = read_panels(&dir.join("hysteresis-storeys.svg"));
    let mut at = 0;
    for (b, bs) in buildings.iter().enumerate() {
        let name = bs["name"].as_str().unwrap();
        let storeys = numbers(&bs["inelastic_storeys"]);
        let mine = &all[at..at + storeys.len()];
        at += storeys.len();
        let model = scenario["building"][b]["storey_model"].as_str().unwrap();
        for (k, (p, j)) in mine.iter().zip(storeys).enumerate() {
            let head = format!("{name}, storey {j}: {model}, \u{3bc} ");
            assert!(p.title.starts_with(&head), "{}", p.title);
            // The ductility to 3 significant digits.
            let mu: f64 = p.title[head.len()..].parse().unwrap();
            let want = numbers(&bs["ductility"])[k];
            assert!((mu - want).abs() <= 5e-3 * want, "{}: {want}", p.title);
            check_loop(p, &loop_of(b, j as usize), numbers(&bs["yield_forces"])[k]);
            assert_eq!((p.x, p.y), (mine[0].x, mine[0].y));
        }
    }
    assert_eq!(at, all.len());
    assert!(buildings.len() == 2 && all[0].x != all[all.len() - 1].x);

    // The report has both figures and a row per storey with its ductility.
    let html = std::fs::read_to_string(dir.join("report.html")).unwrap();
    let doc = report(&html);
    let figures = figure_ids(&doc);
    for id in ["envelopes", "hysteresis", "hysteresis-storeys"] {
        assert!(figures.contains(&id), "{id} in {figures:?}");
    }
    for (b, bs) in buildings.iter().enumerate() {
        let t = doc
            .descendants()
            .find(|n| n.attribute("id") == Some(&format!("storeys-{b}")))
            .unwrap();
        let rows: Vec<Vec<String>> = t
            .descendants()
            .filter(|n| n.has_tag_name("tr"))
            .skip(1)
            .map(|r| {
                r.children()
                    .filter(|c| c.has_tag_name("td"))
                    .map(|c| c.text().unwrap_or("").to_string())
                    .collect()
            })
            .collect();
        let mu = numbers(&bs["ductility"]);
        assert_eq!(rows.len(), mu.len());
        for (r, mu) in rows.iter().zip(mu) {
            assert_eq!(r[7], format!("{mu:.3}"));
        }
    }
    assert_eq!(every_svg_reads_back(&dir), 10);
}

#[test]
fn figure_options_fail_cleanly() {
    let dir = tmp("bad");
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("a-file");
    std::fs::write(&file, "x").unwrap();
    let missing = dir.join("missing");
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (
            vec!["impact", "--model", "papi", "--e", "0.5", "--png"],
            "--plots",
        ),
        (
            vec!["impact", "--model", "papi", "--e", "0.5", "--plots"],
            "--out",
        ),
        (
            vec![
                "impact",
                "--model",
                "papi",
                "--e",
                "0.5",
                "--out",
                file.to_str().unwrap(),
            ],
            "is a file",
        ),
        (vec!["report", missing.to_str().unwrap()], "not a folder"),
        // A folder no run wrote (no marker): refused before anything is read.
        (
            vec!["report", dir.to_str().unwrap()],
            "not an output folder of `pounding run`",
        ),
        (
            vec!["compare", "--models", "papi,nope", "--e", "0.5"],
            "nope",
        ),
        (
            vec!["compare", "--models", "papi", "--e", "0.5", "--k", "-1"],
            "--k",
        ),
    ];
    for (args, says) in cases {
        let o = pounding(&args);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(says), "{args:?}: {err}");
    }
    let left: Vec<_> = std::fs::read_dir(&dir).unwrap().collect();
    assert_eq!(left.len(), 1, "only the file the test made");
}

/// A report parsed as XML (it must be well-formed).
fn report(html: &str) -> roxmltree::Document<'_> {
    let opts = roxmltree::ParsingOptions {
        allow_dtd: true,
        ..roxmltree::ParsingOptions::default()
    };
    roxmltree::Document::parse_with_options(html, opts).expect("report is well-formed")
}

/// The figures of a report, by their `data-figure` ids, in order.
fn figure_ids<'a>(doc: &'a roxmltree::Document) -> Vec<&'a str> {
    doc.descendants()
        .filter_map(|n| n.attribute("data-figure"))
        .collect()
}

#[test]
fn every_figure_of_every_example_shows_its_whole_title_and_subtitle() {
    // Each example scenario with --plots and --report: every figure file, and every figure inlined in the
    // report, keeps its title, subtitle, notes and panel titles whole and inside its width.
    let mut examples: Vec<PathBuf> = std::fs::read_dir(example(""))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    examples.sort();
    assert!(examples.len() >= 7, "{examples:?}");
    let mut figures = 0;
    for scenario in &examples {
        let name = scenario.file_name().unwrap().to_str().unwrap().to_string();
        let out = tmp(&format!("fit-{name}"));
        ok_json(&[
            "run",
            scenario.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
            "--plots",
            "--report",
            "--json",
        ]);
        let starts = format!("{name}:");
        let mut bad = Vec::new();
        for entry in std::fs::read_dir(&out).unwrap() {
            let path = entry.unwrap().path();
            if path.extension().is_some_and(|x| x == "svg") {
                let text = std::fs::read_to_string(&path).unwrap();
                let doc = roxmltree::Document::parse(&text).expect("well-formed SVG");
                bad.extend(text_fits(doc.root_element(), &starts));
                figures += 1;
            }
        }
        let html = std::fs::read_to_string(out.join("report.html")).unwrap();
        let doc = report(&html);
        let inline: Vec<_> = doc
            .descendants()
            .filter(|n| n.has_tag_name("svg") && n.attribute("data-figure").is_some())
            .collect();
        assert!(!inline.is_empty(), "{name}: the report has no figure");
        for svg in inline {
            bad.extend(text_fits(svg, &starts));
        }
        assert!(bad.is_empty(), "{name}: {bad:#?}");
        let _ = std::fs::remove_dir_all(&out);
    }
    assert!(figures >= 60, "{figures} figures");
}

/// The text of the `<dd>` after the `<dt>` `key` in a report, if there is one.
fn report_entry(html: &str, key: &str) -> Option<String> {
    let doc = report(html);
    let dt = doc
        .descendants()
        .find(|n| n.has_tag_name("dt") && n.text() == Some(key))?;
    let dd = dt.next_siblings().find(|n| n.has_tag_name("dd"))?;
    Some(
        dd.descendants()
            .filter_map(|n| n.text())
            .collect::<String>(),
    )
}

#[test]
fn why_delivered_e_differs_is_said_in_the_words_of_what_met() {
    // Buildings meet buildings (storeys, floors), an isolated building meets its moat walls (the isolator and
    // the storeys, floors driven off a wall), decks meet decks and abutments (bearings, decks): the figure's
    // note, the report's summary, the terminal and summary.json say it in those words.
    // (example, what the run's words say, what its first site's note in summary.json says, words never used)
    let cases: [(&str, &str, &str, &[&str]); 3] = [
        (
            "two-sdof.toml",
            "between buildings, the storeys",
            "between buildings, the storeys",
            &["bearings", "isolator", "deck", "wall"],
        ),
        (
            "isolated-moat.toml",
            "against a wall, the isolator and the storeys",
            "against a wall, the isolator and the storeys",
            &["bearings", "deck", "between buildings"],
        ),
        (
            "bridge-three-span.toml",
            "between decks or against a wall, the bearings",
            "between decks, the bearings",
            &["storey", "floor", "isolator", "between buildings"],
        ),
    ];
    for (ex, says, site_says, never) in cases {
        let out = tmp(&format!("why-{ex}"));
        let o = pounding(&[
            "run",
            &example(ex),
            "--out",
            out.to_str().unwrap(),
            "--plots",
            "--report",
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let stdout = String::from_utf8_lossy(&o.stdout);
        let flat = |t: &str| t.split_whitespace().collect::<Vec<_>>().join(" ");
        let terminal = flat(&stdout[stdout.find("e_delivered (separation").expect(ex)..]);
        let terminal = &terminal[..terminal.find("Impacts inside a run").unwrap()];
        let note = figure_words(&out.join("impact-restitution.svg"));
        let html = std::fs::read_to_string(out.join("report.html")).unwrap();
        let row = report_entry(&html, "why delivered e differs from e asked").expect(ex);
        let summary: Value =
            serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap())
                .unwrap();
        let json = summary["sites"][0]["e_delivered"]["note"]
            .as_str()
            .unwrap()
            .to_string();
        for (place, text, says) in [
            ("terminal", terminal.to_string(), says),
            ("figure", note, says),
            ("report", row, says),
            ("summary.json", json, site_says),
        ] {
            assert!(
                text.contains(says),
                "{ex}, {place}: {says:?} not in {text:?}"
            );
            for word in never {
                assert!(!text.contains(word), "{ex}, {place}: {word:?} in {text:?}");
            }
        }
        let _ = std::fs::remove_dir_all(&out);
    }
}

/// Every text a reader sees in a report (a document's text nodes, the scenario file as run and the style
/// sheet left out) or in an SVG figure (its texts, `<title>` and the titles and labels of its panels and
/// series), lower case, one piece a line.
fn seen_words(doc: &roxmltree::Document) -> String {
    let mut out = String::new();
    for n in doc.descendants() {
        let hidden = n
            .ancestors()
            .any(|a| a.has_tag_name("pre") || a.has_tag_name("style"));
        if n.is_text() && !hidden {
            out.push_str(&n.text().unwrap_or("").to_lowercase());
            out.push('\n');
        }
        for key in ["data-title", "data-label"] {
            if let Some(v) = n.attribute(key) {
                out.push_str(&v.to_lowercase());
                out.push('\n');
            }
        }
    }
    out
}

#[test]
fn a_bridge_is_told_in_deck_and_bearing_words() {
    // examples/bridge-three-span.toml: three decks on their bearings, joints, abutments and restrainers. No
    // storey, floor or building anywhere a reader looks: the terminal, the report, the figures.
    let out = tmp("bridge-words");
    let o = pounding(&[
        "run",
        &example("bridge-three-span.toml"),
        "--out",
        out.to_str().unwrap(),
        "--plots",
        "--report",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let terminal = String::from_utf8_lossy(&o.stdout).to_lowercase();
    let html = std::fs::read_to_string(out.join("report.html")).unwrap();
    let doc = report(&html);
    let mut places = vec![
        ("terminal".to_string(), terminal.clone()),
        ("report".to_string(), seen_words(&doc)),
    ];
    for entry in std::fs::read_dir(&out).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|x| x == "svg") {
            let text = std::fs::read_to_string(&path).unwrap();
            let svg = roxmltree::Document::parse(&text).unwrap();
            places.push((path.display().to_string(), seen_words(&svg)));
        }
    }
    for (place, text) in &places {
        for word in ["storey", "floor", "building"] {
            let at: Vec<&str> = text.lines().filter(|l| l.contains(word)).collect();
            assert!(at.is_empty(), "{place}: {word:?} in {at:#?}");
        }
    }
    // What they say instead.
    let header = |id: &str| -> Vec<String> {
        let t = doc
            .descendants()
            .find(|n| n.attribute("id") == Some(id))
            .unwrap_or_else(|| panic!("table {id}"));
        t.descendants()
            .filter(|n| n.has_tag_name("th"))
            .map(|n| n.text().unwrap_or("").to_string())
            .collect()
    };
    assert_eq!(header("peaks")[0], "deck");
    assert_eq!(
        header("storeys-0")[..3],
        ["model", "peak displacement (mm)", "peak force (MN)"]
    );
    assert!(header("energy").contains(&"bearing hysteresis".to_string()));
    assert!(
        terminal.contains("deck        displacement_mm"),
        "{terminal}"
    );
    assert!(
        terminal.contains("deck        bearings  ductility"),
        "{terminal}"
    );
    assert!(terminal.contains("bearing yield"), "{terminal}");
    assert!(figure_title(&out.join("energy.svg")).contains("bearing hysteresis"));
    let words = figure_words(&out.join("relative-displacement.svg"));
    assert!(
        words.contains(
            "each pair of contact decks (for a wall, the deck's displacement towards it)"
        ),
        "{words}"
    );
    let _ = std::fs::remove_dir_all(&out);

    // An isolated building: its hysteresis is the isolator's.
    let out = tmp("moat-words");
    ok_json(&[
        "run",
        &example("isolated-moat.toml"),
        "--out",
        out.to_str().unwrap(),
        "--plots",
        "--report",
        "--json",
    ]);
    assert!(figure_title(&out.join("energy.svg")).contains("+ isolator hysteresis +"));
    let html = std::fs::read_to_string(out.join("report.html")).unwrap();
    assert!(html.contains("<th>isolator hysteresis</th>"));
    let _ = std::fs::remove_dir_all(&out);
}

/// The rows of the report's table `id`, each its cells' texts (header row left out).
fn table_rows(doc: &roxmltree::Document, id: &str) -> Vec<Vec<String>> {
    let t = doc
        .descendants()
        .find(|n| n.has_tag_name("table") && n.attribute("id") == Some(id))
        .unwrap_or_else(|| panic!("table {id}"));
    t.descendants()
        .filter(|n| n.has_tag_name("tr"))
        .map(|tr| {
            tr.children()
                .filter(|n| n.has_tag_name("td"))
                .map(|n| {
                    n.descendants()
                        .filter(|t| t.is_text())
                        .filter_map(|t| t.text())
                        .collect::<String>()
                })
                .collect::<Vec<_>>()
        })
        .filter(|r| !r.is_empty())
        .collect()
}

#[test]
fn a_bumper_is_in_the_report_with_its_law_and_each_impact_with_its_layer() {
    // examples/isolated-moat.toml: a rubber bumper on the east moat wall, consumed twice.
    let out = tmp("moat-bumper");
    let s = ok_json(&[
        "run",
        &example("isolated-moat.toml"),
        "--out",
        out.to_str().unwrap(),
        "--report",
        "--json",
    ]);
    let html = std::fs::read_to_string(out.join("report.html")).unwrap();
    let doc = report(&html);
    let site = sites(&s, "wall")
        .into_iter()
        .find(|w| w["bumper"].is_object())
        .expect("a wall with a bumper");
    let b = &site["bumper"];
    let name = site["name"].as_str().unwrap();
    // The contacts table: the site's row (the law behind the bumper), then the bumper's own row.
    let rows = table_rows(&doc, "contacts");
    let k = rows
        .iter()
        .position(|r| r[0].starts_with(&format!("wall {name} ")))
        .expect("the site's row");
    assert!(rows[k][0].ends_with("behind its bumper"), "{:?}", rows[k]);
    let bumper = &rows[k + 1];
    let mm = |x: f64| format!("{}", (x * 1e3 * 1e6).round() / 1e6);
    assert_eq!(
        bumper[0],
        format!(
            "bumper of {name}: {} mm thick, consumed at strain {}",
            mm(b["thickness"].as_f64().unwrap()),
            b["max_strain"]
        )
    );
    let face = site["gap"].as_f64().unwrap() - b["thickness"].as_f64().unwrap();
    assert_eq!(bumper[1], format!("{} (its face)", mm(face)));
    assert_eq!(bumper[3], b["model"].as_str().unwrap());
    let f = |v: &Value| v.as_f64().unwrap();
    assert_eq!(bumper[4], format!("{}", f(&b["e"])));
    assert_eq!(
        bumper[5],
        format!("{} (n = {})", f(&b["stiffness"]), f(&b["exponent"]))
    );
    let chi = b["damping_parameter"]["value"].as_f64().unwrap();
    assert_eq!(bumper[6], format!("chi = {}", (chi * 1e4).round() / 1e4));
    assert_ne!(
        rows[k][4], bumper[4],
        "the two laws' e differ in this example"
    );
    // The impacts table: a layer column equal to impacts.csv's, and a caption that says what a consumed
    // row is.
    let (ih, irows) = csv(&out.join("impacts.csv"));
    let c = |name: &str| ih.iter().position(|h| h == name).unwrap();
    let list = table_rows(&doc, "impact-list");
    assert_eq!(list.len(), irows.len());
    let layer_col = 3;
    for (shown, row) in list.iter().zip(&irows) {
        assert_eq!(shown[layer_col], row[c("layer")]);
    }
    let caption = doc
        .descendants()
        .find(|n| n.has_tag_name("table") && n.attribute("id") == Some("impact-list"))
        .and_then(|t| t.children().find(|n| n.has_tag_name("caption")))
        .and_then(|n| n.text())
        .unwrap();
    assert!(
        caption.contains("A consumed row is no impact of its own"),
        "{caption}"
    );
    // What the caption says holds: each consumed row lies within the last bumper row of its level before it.
    let num = |r: &Vec<String>, name: &str| -> f64 { r[c(name)].parse().unwrap() };
    let mut consumed = 0;
    for (i, r) in irows.iter().enumerate() {
        if r[c("layer")] != "consumed" {
            continue;
        }
        consumed += 1;
        let level = |q: &Vec<String>| {
            (
                q[c("contact")].clone(),
                q[c("floor_left")].clone(),
                q[c("floor_right")].clone(),
            )
        };
        let host = irows[..i]
            .iter()
            .rev()
            .find(|q| q[c("layer")] == "bumper" && level(q) == level(r))
            .expect("a bumper row before it");
        let (t0, t1) = (
            num(host, "time_s"),
            num(host, "time_s") + num(host, "duration_s"),
        );
        assert!(
            t0 <= num(r, "time_s") && num(r, "time_s") + num(r, "duration_s") <= t1,
            "{r:?} within {host:?}"
        );
    }
    assert_eq!(consumed, site["consumed"].as_u64().unwrap());
    assert!(consumed > 0);
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn impacts_released_at_one_over_chi_are_counted_and_explained() {
    // A clamped Hunt-Crossley-type force k d^n (1 + chi d'/v_i) vanishes when the parting speed reaches
    // v_i/chi; an impact whose floors part that fast with penetration left ends there, at e = 1/chi exactly.
    // isolated-moat: four impacts on the bumper (chi 1.4328, 1/chi 0.698, e asked 0.5) and one on the west
    // wall (1/chi 1.026, its release once missed: no_clamped_hunt_crossley_impact_delivers_more_than_one_over_chi
    // in cli.rs); three-in-a-row: three between middle and east (1/chi 1.026). Found from the files alone,
    // then looked for in the note.
    for (ex, expect, says) in [
        ("isolated-moat.toml", 5, "a bumper still compressed"),
        ("three-in-a-row.toml", 3, "with penetration left"),
    ] {
        let out = tmp(&format!("released-{ex}"));
        let s = ok_json(&[
            "run",
            &example(ex),
            "--out",
            out.to_str().unwrap(),
            "--plots",
            "--json",
        ]);
        // Each site's chi, and its bumper's, by (site, layer).
        let mut chi = std::collections::HashMap::new();
        for site in s["sites"].as_array().unwrap() {
            let name = site["name"].as_str().unwrap().to_string();
            for (layer, law) in [
                ("direct", &site["damping_parameter"]),
                ("bumper", &site["bumper"]["damping_parameter"]),
            ] {
                if law["name"] == "chi" {
                    chi.insert((name.clone(), layer), law["value"].as_f64().unwrap());
                }
            }
        }
        let (ih, irows) = csv(&out.join("impacts.csv"));
        let c = |name: &str| ih.iter().position(|h| h == name).unwrap();
        let (lh, lrows) = csv(&out.join("impact-loops.csv"));
        let l = |name: &str| lh.iter().position(|h| h == name).unwrap();
        let mut at = Vec::new();
        for (k, r) in irows.iter().enumerate() {
            let layer = r[c("layer")].as_str();
            let Some(&x) = chi.get(&(r[c("contact")].clone(), layer)) else {
                continue;
            };
            let Ok(e) = r[c("e_post")].parse::<f64>() else {
                continue;
            };
            if (e * x - 1.0).abs() <= 1e-9 {
                at.push((k + 1, 1.0 / x));
            }
        }
        assert_eq!(at.len(), expect, "{ex}: {at:?}");
        // Each ended with penetration left and no force: its loop's last point.
        for &(k, _) in &at {
            let last = lrows
                .iter()
                .rfind(|r| r[l("impact")] == k.to_string())
                .unwrap();
            let pen: f64 = last[l("penetration_m")].parse().unwrap();
            let force: f64 = last[l("force_N")].parse().unwrap();
            assert!(
                pen > 1e-4 && force == 0.0,
                "{ex}: impact {k} ends at {pen} m, {force} N"
            );
        }
        let words = figure_words(&out.join("impact-restitution.svg"));
        for part in [
            format!(
                "Of these, {expect} deliver exactly 1/chi of their law, 1/chi = {:.3}",
                at[0].1
            ),
            "vanishes when the parting speed d' reaches v_i/chi".to_string(),
            says.to_string(),
        ] {
            assert!(words.contains(&part), "{ex}: {part:?} not in {words:?}");
        }
        let _ = std::fs::remove_dir_all(&out);
    }
}

/// Two 6-storey buildings side by side, in contact at every floor (six contact levels), under the built-in
/// synthetic record of seed 7: every level pounds.
const SIX_LEVELS: &str = r#"
[ground_motion]
record = "synthetic-7"
scale = 1.3

[analysis]
duration = 12.0
output_dt = 0.005

[[building]]
name = "west"
masses = [4.0e5, 4.0e5, 4.0e5, 4.0e5, 4.0e5, 3.0e5]
stiffnesses = [6.0e8, 5.5e8, 5.0e8, 4.5e8, 4.0e8, 3.5e8]
heights = [3.0, 3.0, 3.0, 3.0, 3.0, 3.0]
damping_ratio = 0.05

[[building]]
name = "east"
masses = [4.0e5, 4.0e5, 4.0e5, 4.0e5, 4.0e5, 3.0e5]
stiffnesses = [2.2e8, 2.0e8, 1.8e8, 1.6e8, 1.4e8, 1.2e8]
heights = [3.0, 3.0, 3.0, 3.0, 3.0, 3.0]
damping_ratio = 0.05

[[contact]]
between = ["west", "east"]
gap = 0.01
model = "hertzdamp"
e = 0.6
stiffness = 2.0e10
stiffness_unit = "N/m^1.5"
"#;

#[test]
fn six_contact_levels_give_six_panels_each_with_its_own_impacts_and_loops() {
    let dir = tmp("six");
    std::fs::create_dir_all(&dir).unwrap();
    let scenario = dir.join("six.toml");
    std::fs::write(&scenario, SIX_LEVELS).unwrap();
    let out = dir.join("out");
    ok_json(&[
        "run",
        scenario.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--json",
        "--plots",
        "--report",
    ]);
    let (ih, irows) = csv(&out.join("impacts.csv"));
    let level = col(&ih, &irows, "floor_left");
    let (t_peak, peak) = (
        col(&ih, &irows, "time_of_peak_force_s"),
        col(&ih, &irows, "peak_force_N"),
    );
    let at =
        |f: usize| -> Vec<usize> { (0..irows.len()).filter(|&i| level[i] == f as f64).collect() };
    for f in 1..=6 {
        assert!(!at(f).is_empty(), "floor {f} pounds");
    }

    // Contact force: one panel per level, one time axis; each panel's markers are its level's impacts.
    let p = read_panels(&out.join("contact-force.svg"));
    assert_eq!(p.len(), 6);
    for (k, q) in p.iter().enumerate() {
        let f = k + 1;
        assert!(q.title.contains(&format!("floors {f}-{f}")), "{}", q.title);
        assert_eq!(q.x, p[0].x);
        assert_eq!(q.lines.len(), 1);
        let mine = at(f);
        let marks = &q.points[0].1;
        assert_eq!(marks.len(), mine.len(), "floor {f}");
        for (m, &i) in marks.iter().zip(&mine) {
            assert!((m.0 - t_peak[i]).abs() <= q.res.0 && (m.1 - peak[i]).abs() <= q.res.1);
        }
        let top = mine.iter().map(|&i| peak[i]).fold(0.0, f64::max);
        assert!((max_y(&q.lines[0].1) - top).abs() <= q.res.1);
    }
    // Each level keeps one colour and one marker shape, different from every other level's.
    let styles: Vec<&(String, String)> = p.iter().map(|q| &q.point_styles[0]).collect();
    for a in 0..6 {
        for b in 0..a {
            assert_ne!(styles[a], styles[b], "levels {} and {}", a + 1, b + 1);
        }
    }

    // Delivered e: the same colour and shape per level, each level's ended impacts, the requested e, and a
    // note when impacts deliver more than requested.
    let r = &read_panels(&out.join("impact-restitution.svg"))[0];
    assert_eq!(r.points.len(), 6);
    for (k, style) in styles.iter().enumerate() {
        assert_eq!(&&r.point_styles[k], style);
        assert_eq!(r.points[k].1.len(), at(k + 1).len());
    }
    assert_eq!(r.hlines[0].1, 0.6);
    let e_post = col(&ih, &irows, "e_post");
    let above = e_post.iter().filter(|e| **e > 0.6).count();
    assert!(above > 0);
    let text = std::fs::read_to_string(out.join("impact-restitution.svg")).unwrap();
    assert!(
        text.contains(&format!(
            "{above} of {} impacts lie above the requested e",
            e_post.len()
        )),
        "the note counts the impacts above the line"
    );

    // Relative displacement: one panel per level on one axis, each with the gap.
    let q = read_panels(&out.join("relative-displacement.svg"));
    assert_eq!(q.len(), 6);
    assert!(q.iter().all(|x| x.y == q[0].y && x.hlines[0].1 == 0.01));

    // impact-loops.csv: one block per impact, in the order of impacts.csv, from the touch; the largest force
    // is the located peak, at its time.
    let (lh, lrows) = csv(&out.join("impact-loops.csv"));
    assert_eq!(
        lh,
        [
            "impact",
            "contact",
            "floor_left",
            "floor_right",
            "stride",
            "t_s",
            "penetration_m",
            "force_N"
        ]
    );
    let (li, lt, ld, lf) = (
        col(&lh, &lrows, "impact"),
        col(&lh, &lrows, "t_s"),
        col(&lh, &lrows, "penetration_m"),
        col(&lh, &lrows, "force_N"),
    );
    let touch = col(&ih, &irows, "time_s");
    let duration = col(&ih, &irows, "duration_s");
    let dissipated = col(&ih, &irows, "dissipated_energy_J");
    let mut start = 0;
    let (mut area_sum, mut energy_sum) = (0.0, 0.0);
    for i in 0..irows.len() {
        let mut end = start;
        while end < li.len() && li[end] == (i + 1) as f64 {
            end += 1;
        }
        assert!(end - start >= 3, "impact {} has a block", i + 1);
        let (t, d, f) = (&lt[start..end], &ld[start..end], &lf[start..end]);
        assert!(t.windows(2).all(|w| w[0] < w[1]));
        assert_eq!(t[0], touch[i]);
        assert!((t[t.len() - 1] - (touch[i] + duration[i])).abs() <= 1e-9);
        let k = (0..f.len()).max_by(|&a, &b| f[a].total_cmp(&f[b])).unwrap();
        assert_eq!(f[k], peak[i]);
        assert_eq!(t[k], t_peak[i]);
        // The area inside the loop, by trapezoids over the steps, is the energy the impact dissipated.
        area_sum += (1..d.len())
            .map(|j| (f[j] + f[j - 1]) / 2.0 * (d[j] - d[j - 1]))
            .sum::<f64>();
        energy_sum += dissipated[i];
        start = end;
    }
    assert_eq!(start, li.len(), "no rows after the last impact");
    assert!(
        (area_sum - energy_sum).abs() <= 0.05 * energy_sum,
        "{area_sum} vs {energy_sum}"
    );

    // impact-loops.svg: one panel per level, its three strongest impacts, each reaching its peak.
    let l = read_panels(&out.join("impact-loops.svg"));
    assert_eq!(l.len(), 6);
    for (k, q) in l.iter().enumerate() {
        let mut mine = at(k + 1);
        mine.sort_by(|&a, &b| peak[b].total_cmp(&peak[a]));
        assert_eq!(q.lines.len(), 3.min(mine.len()));
        for (line, &i) in q.lines.iter().zip(&mine) {
            assert!(line.0.starts_with(&format!("#{} ", i + 1)), "{}", line.0);
            assert!((max_y(&line.1) - peak[i]).abs() <= q.res.1);
        }
    }

    // A folder written before impact-loops.csv existed still makes its report, without that figure.
    std::fs::remove_file(out.join("impact-loops.csv")).unwrap();
    let marker = out.join(".pounding-run");
    let kept: String = std::fs::read_to_string(&marker)
        .unwrap()
        .lines()
        .filter(|l| !l.starts_with("impact-loops.csv "))
        .map(|l| format!("{l}\n"))
        .collect();
    std::fs::write(&marker, kept).unwrap();
    let o = pounding(&["report", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let html = std::fs::read_to_string(out.join("report.html")).unwrap();
    let doc = report(&html);
    let ids = figure_ids(&doc);
    assert!(!ids.contains(&"impact-loops") && ids.contains(&"contact-force"));
}

#[test]
fn coinciding_curves_say_so_and_stay_visible() {
    // Table 1: Flores et al. and Hertzdamp (OpenSees) deliver the same e (the same damping law).
    let dir = tmp("same");
    ok_json(&[
        "paper",
        "table1",
        "--json",
        "--out",
        dir.to_str().unwrap(),
        "--plots",
    ]);
    let panels = read_panels(&dir.join("table1-e-post.svg"));
    let (p, k) = panels
        .iter()
        .find_map(|p| {
            p.lines
                .iter()
                .position(|l| l.0.starts_with("Hertzdamp"))
                .map(|k| (p, k))
        })
        .expect("a Hertzdamp curve");
    assert_eq!(p.same_as[k].as_deref(), Some("Flores et al."));
    assert!(p
        .legend
        .iter()
        .any(|t| t.starts_with("Hertzdamp") && t.ends_with("(same as Flores et al.)")));
    // Every line said to coincide does, within 0.5 % of the axis (read back, independently of the
    // figure's own test), and lines that differ visibly are not said to.
    for p in &panels {
        let range = p.y.1 - p.y.0;
        for (k, (label, pts)) in p.lines.iter().enumerate() {
            let Some(of) = &p.same_as[k] else { continue };
            let root = &p.lines.iter().find(|l| &l.0 == of).unwrap().1;
            assert_eq!(pts.len(), root.len(), "{label}");
            let gap = pts
                .iter()
                .zip(root)
                .map(|(a, b)| (a.1 - b.1).abs())
                .fold(0.0, f64::max);
            assert!(gap <= 0.005 * range + p.res.1, "{label}: {gap}");
        }
        let papi = p
            .lines
            .iter()
            .position(|l| l.0 == "Papi, eq (8) alpha, same-damping");
        if let Some(k) = papi {
            assert_eq!(p.same_as[k], None);
        }
    }

    // compare with the exact damping: hunt-crossley, flores and hertzdamp give one force history.
    let dir = tmp("same-compare");
    ok_json(&[
        "compare",
        "--models",
        "papi,hunt-crossley,flores,hertzdamp",
        "--e",
        "0.65",
        "--damping",
        "exact",
        "--json",
        "--out",
        dir.to_str().unwrap(),
        "--plots",
    ]);
    for name in ["compare-force-time", "compare-force-penetration"] {
        let p = &read_panels(&dir.join(format!("{name}.svg")))[0];
        let same: Vec<Option<&str>> = p.same_as.iter().map(|s| s.as_deref()).collect();
        assert_eq!(same[0], None, "{name}: papi differs");
        assert_eq!(
            same[1], None,
            "{name}: the first of the three is drawn whole"
        );
        assert!(
            same[1..]
                .iter()
                .skip(1)
                .all(|s| s.is_some_and(|s| s.starts_with("hunt-crossley"))),
            "{name}: {same:?}"
        );
        assert!(p
            .legend
            .iter()
            .any(|t| t.contains("(same as hunt-crossley)")));
    }
}

#[test]
fn the_report_shows_mode_shapes_with_a_largest_component_of_one() {
    // The 8-storey building's high modes: normalised to the roof, some components would be far above 1.
    let dir = tmp("modes");
    ok_json(&[
        "run",
        &example("three-vs-eight-storey.toml"),
        "--out",
        dir.to_str().unwrap(),
        "--json",
        "--report",
    ]);
    let html = std::fs::read_to_string(dir.join("report.html")).unwrap();
    let doc = report(&html);
    let mut rows = 0;
    for t in doc.descendants().filter(|n| {
        n.has_tag_name("table") && n.attribute("id").is_some_and(|i| i.starts_with("modes-"))
    }) {
        for tr in t.descendants().filter(|n| n.has_tag_name("tr")).skip(1) {
            let cells: Vec<String> = tr
                .children()
                .filter(|c| c.has_tag_name("td"))
                .map(|c| c.text().unwrap_or("").to_string())
                .collect();
            let shape: Vec<f64> = cells[4]
                .split(' ')
                .map(|x| x.replace('\u{2212}', "-").parse().unwrap())
                .collect();
            let big = shape.iter().fold(0.0f64, |a, x| a.max(x.abs()));
            assert_eq!(big, 1.0, "{shape:?}");
            rows += 1;
        }
    }
    assert_eq!(rows, 3 + 8);
    // No e-notation in the report's tables.
    for td in doc.descendants().filter(|n| n.has_tag_name("td")) {
        let t = td.text().unwrap_or("");
        let looks_like_e = t.split(['e', 'E']).count() == 2
            && t.split(['e', 'E'])
                .all(|p| !p.is_empty() && p.trim_start_matches(['-', '+']).parse::<f64>().is_ok());
        assert!(!looks_like_e, "{t:?} in e-notation");
    }
}

/// The figures follow what was hit and what the structure is (issue 23): contact-force draws the levels that
/// were hit and names the others; a bridge's decks have bearings, no storeys and no height envelope; an
/// isolator's drift is no drift ratio; log-spaced periods on a log axis; the separation rules' points all
/// visible where they coincide.
#[test]
fn figures_follow_what_was_hit_and_what_the_structure_is() {
    // Three in a row: impacts.csv says which levels pounded; the figure has exactly those panels.
    let dir = tmp("follow-row");
    let s = ok_json(&[
        "run",
        &example("three-in-a-row.toml"),
        "--out",
        dir.to_str().unwrap(),
        "--json",
        "--plots",
    ]);
    let (ih, irows) = csv(&dir.join("impacts.csv"));
    let left = col(&ih, &irows, "floor_left");
    let sites = s["sites"].as_array().unwrap();
    let mut hit = Vec::new();
    let mut silent = Vec::new();
    for site in sites {
        let name = site["name"].as_str().unwrap();
        let site_col = ih.iter().position(|h| h == "contact").unwrap();
        for level in site["levels"].as_array().unwrap() {
            let f = level["left"].as_f64().unwrap();
            let n = irows
                .iter()
                .zip(&left)
                .filter(|(r, l)| r[site_col] == name && **l == f)
                .count();
            let label = format!("contact {name}, floors {f}-{}", level["right"]);
            if n > 0 {
                hit.push((label, n));
            } else {
                silent.push(format!("{f}-{}", level["right"]));
            }
        }
    }
    assert!(
        !silent.is_empty() && !hit.is_empty(),
        "the example has both"
    );
    let p = read_panels(&dir.join("contact-force.svg"));
    assert_eq!(p.len(), hit.len());
    for (q, (label, n)) in p.iter().zip(&hit) {
        assert!(
            q.title.starts_with(&format!("{label}: {n} impact")),
            "{} vs {label}",
            q.title
        );
    }
    let text = std::fs::read_to_string(dir.join("contact-force.svg")).unwrap();
    let total = hit.len() + silent.len();
    assert!(text.contains(&format!("levels that were hit ({} of {total})", hit.len())));
    assert!(text.contains("Not hit"), "the silent levels are named");
    for f in &silent {
        assert!(text.contains(f.as_str()), "{f} named");
    }
    // Relative displacement keeps every level: how near the silent ones came.
    assert_eq!(
        read_panels(&dir.join("relative-displacement.svg")).len(),
        total
    );
    assert!(every_svg_reads_back(&dir) >= 8);

    // A bridge: decks on bearings.
    let dir = tmp("follow-bridge");
    ok_json(&[
        "run",
        &example("bridge-three-span.toml"),
        "--out",
        dir.to_str().unwrap(),
        "--json",
        "--plots",
    ]);
    for absent in ["envelopes.svg", "hysteresis.svg", "hysteresis-storeys.svg"] {
        assert!(
            !dir.join(absent).exists(),
            "{absent}: a deck has no storeys"
        );
    }
    assert_eq!(
        figure_title(&dir.join("isolators.svg")),
        "Bearing force against displacement"
    );
    for q in read_panels(&dir.join("isolators.svg")) {
        assert!(
            q.title.starts_with("deck span") && q.title.contains("bilinear bearings"),
            "{}",
            q.title
        );
    }
    let d = read_panels(&dir.join("displacement.svg"));
    assert!(
        d[1..].iter().all(|q| q.title.starts_with("deck span")),
        "{:?}",
        d[1].title
    );
    for q in read_panels(&dir.join("contact-force.svg")) {
        assert!(!q.title.contains("floor"), "{}", q.title);
    }
    assert!(every_svg_reads_back(&dir) >= 8);
    assert!(every_svg_reads_back(&dir) >= 8);

    // An isolated building: drift ratios of the storeys above the isolator only.
    let dir = tmp("follow-moat");
    let s = ok_json(&[
        "run",
        &example("isolated-moat.toml"),
        "--out",
        dir.to_str().unwrap(),
        "--json",
        "--plots",
    ]);
    let ratios = numbers(&s["buildings"][0]["peak_drift_ratio"]);
    let drift = &read_panels(&dir.join("envelopes.svg"))[1];
    let pts = &drift.lines[0].1;
    assert_eq!(
        pts.len(),
        2 * (ratios.len() - 1),
        "no step for the isolator"
    );
    let top = ratios[1..].iter().fold(0.0f64, |a, r| a.max(*r));
    assert!(
        (max_x(pts) - 100.0 * top).abs() <= drift.res.0,
        "{} vs {top}",
        max_x(pts)
    );
    assert!(
        100.0 * ratios[0] > 10.0 * max_x(pts),
        "the isolator's would have dwarfed them"
    );
    // Its storeys stay linear but its Bouc-Wen isolator yields: the storey loop's note sends the reader to
    // the isolator's figure, and does not call the building elastic.
    let words = figure_words(&dir.join("hysteresis.svg"));
    let mu = numbers(&s["buildings"][0]["ductility"])[0];
    assert!(mu > 2.0, "the isolator yields: {mu}");
    for says in [
        "every storey above the isolator is linear",
        &format!("the isolator of building isolated (bouc-wen, ductility {mu:.2})"),
        "has its loop in its own figure, isolators.svg",
    ] {
        assert!(words.contains(says), "{says:?} not in {words:?}");
    }
    assert!(!words.contains("no inelastic storey"), "{words}");

    // The spectrum's periods on a log axis: the SD curve reads back exactly through it.
    let dir = tmp("follow-spectrum");
    let v = ok_json(&[
        "record",
        "spectrum",
        "el-centro-1940",
        "--out",
        dir.to_str().unwrap(),
        "--plots",
        "--json",
    ]);
    let sd = &read_panels(&dir.join("spectrum.svg"))[0];
    assert!(sd.log_x);
    let (periods, want) = (numbers(&v["periods"]), numbers(&v["sd"]));
    let line = &sd.lines[0].1;
    assert_eq!(line.len(), periods.len());
    for ((t, y), (tw, yw)) in line.iter().zip(periods.iter().zip(&want)) {
        assert!((t / tw - 1.0).abs() < 1e-4, "{t} vs {tw}");
        assert!((y - yw).abs() <= sd.res.1, "{y} vs {yw}");
    }

    // Separation: each rule its own marker shape (SRSS and DDC coincide here to 0.1 mm).
    let dir = tmp("follow-separation");
    ok_json(&[
        "separation",
        &example("three-vs-eight-storey.toml"),
        "--out",
        dir.to_str().unwrap(),
        "--plots",
        "--json",
    ]);
    let p = &read_panels(&dir.join("separation.svg"))[0];
    let labels: Vec<&str> = p.points.iter().map(|x| x.0.as_str()).collect();
    assert_eq!(labels, ["ABS", "SRSS", "DDC"]);
    let shapes: Vec<&String> = p.point_styles.iter().map(|x| &x.1).collect();
    assert!(
        shapes[0] != shapes[1] && shapes[1] != shapes[2] && shapes[0] != shapes[2],
        "{shapes:?}"
    );
}

fn max_x(pts: &[(f64, f64)]) -> f64 {
    pts.iter().fold(f64::NEG_INFINITY, |a, p| a.max(p.0))
}
