//! Figures of the analyses beyond one run: a record and its response spectra, the required separation against
//! the code rules, and an IDA's curves and fragility functions.

use super::{Dash, Figure, Legend, Mark, Panel, Quantity, Series, Shape, Style, PLOT};
use pounding::ground_motion::spectrum::Spectrum;
use pounding::ground_motion::Record;
use pounding::separation::random::Clumping;
use pounding::separation::Level;
use pounding_study::ida::{FitJson, FragilityJson};
use pounding_study::separation::SeparationReport;

fn time() -> Quantity {
    Quantity::new("time", "s")
}

/// The record as analysed, from rest at t = 0 (the ramp to the first sample, then the samples): times (s),
/// accelerations (m/s^2), and the velocity (m/s) and displacement (m) integrated exactly for the
/// piecewise-linear acceleration, without baseline correction.
fn from_rest(r: &Record) -> [Vec<f64>; 4] {
    let (dt, a) = (r.dt(), r.accelerations());
    let mut t = vec![0.0];
    let mut acc = vec![0.0];
    let (mut vel, mut dis) = (vec![0.0], vec![0.0]);
    let mut step = |a0: f64, a1: f64, h: f64, t1: f64| {
        let (v0, d0) = (*vel.last().unwrap_or(&0.0), *dis.last().unwrap_or(&0.0));
        vel.push(v0 + (a0 + a1) / 2.0 * h);
        dis.push(d0 + v0 * h + (2.0 * a0 + a1) * h * h / 6.0);
        t.push(t1);
        acc.push(a1);
    };
    if r.t0() > 0.0 {
        step(0.0, a[0], r.t0(), r.t0());
    }
    for k in 1..a.len() {
        step(a[k - 1], a[k], dt, r.t0() + k as f64 * dt);
    }
    [t, acc, vel, dis]
}

/// Ground acceleration, velocity and displacement panels of `records`, one series per record (`labels`).
fn ground_panels(records: &[&Record], labels: &[String]) -> Vec<Panel> {
    let motions: Vec<[Vec<f64>; 4]> = records.iter().map(|r| from_rest(r)).collect();
    let panel = |name: &str, unit: &'static str, which: usize| {
        let mut p = Panel::new("", time(), Quantity::new(name, unit));
        for (i, (m, label)) in motions.iter().zip(labels).enumerate() {
            p.series.push(Series::line(
                label,
                m[0].clone(),
                m[which].clone(),
                Style::nth(i),
            ));
        }
        p.x_tight = true;
        p.legend = if records.len() > 1 {
            Legend::Inside
        } else {
            Legend::None
        };
        p
    };
    vec![
        panel("ground acceleration", "m/s\u{b2}", 1),
        panel("ground velocity", "m/s", 2),
        panel("ground displacement", "m", 3),
    ]
}

/// The record as analysed (from rest, no baseline correction): acceleration, and the velocity and
/// displacement integrated exactly for the piecewise-linear acceleration.
pub fn record(r: &Record, subtitle: &str) -> Figure {
    Figure {
        id: "record".into(),
        title: format!(
            "Record {}: ground acceleration, velocity and displacement",
            r.name()
        ),
        subtitle: format!(
            "{subtitle}; velocity and displacement from rest, without baseline correction"
        ),
        panels: ground_panels(&[r], &[String::new()]),
        columns: 1,
        plot: (PLOT.0, 170.0),
        ..Figure::default()
    }
}

/// The records of supports along a line (`pounding record coherent`): each support's acceleration, and the
/// velocity and displacement it is driven by in a run (from rest, without baseline correction).
pub fn supports(records: &[Record], positions: &[f64], subtitle: &str) -> Figure {
    let labels: Vec<String> = positions
        .iter()
        .enumerate()
        .map(|(j, x)| format!("support {} at {} m", j + 1, crate::output::fmt_num(*x)))
        .collect();
    let refs: Vec<&Record> = records.iter().collect();
    Figure {
        id: "supports".into(),
        title: "Supports' ground motions: acceleration, velocity and displacement".into(),
        subtitle: format!(
            "{subtitle}; velocity and displacement from rest, without baseline correction, as a run drives each support"
        ),
        panels: ground_panels(&refs, &labels),
        columns: 1,
        plot: (PLOT.0, 170.0),
        ..Figure::default()
    }
}

/// SD, PSV and PSA against period.
pub fn spectrum(s: &Spectrum, title: &str) -> Figure {
    let period = || Quantity::new("period", "s");
    let panel = |name: &str, unit: &'static str, y: &[f64]| {
        let mut p = Panel::new("", period(), Quantity::new(name, unit));
        p.series.push(Series::line(
            "",
            s.periods.clone(),
            y.to_vec(),
            Style::nth(0),
        ));
        // The periods are log-spaced: a log axis gives every decade the same room.
        p.x_log = true;
        p.y_zero = true;
        p.legend = Legend::None;
        p
    };
    Figure {
        id: "spectrum".into(),
        title: format!("{title}: elastic response spectra"),
        subtitle: format!(
            "damping {} %, exact piecewise-linear solution, peaks located between samples",
            100.0 * s.damping
        ),
        panels: vec![
            panel("spectral displacement SD", "m", &s.sd),
            panel("pseudo-velocity PSV", "m/s", &s.psv),
            panel("pseudo-acceleration PSA", "m/s\u{b2}", &s.psa),
        ],
        columns: 1,
        plot: (PLOT.0, 170.0),
        ..Figure::default()
    }
}

/// Each rule's estimate against the required gap, every level (and every record of a suite), with the line
/// where the estimate equals the requirement: points below it are unconservative.
pub fn separation(report: &SeparationReport, subtitle: &str) -> Figure {
    let runs = report.runs();
    let mut p = Panel::new(
        "",
        Quantity::new("required gap (run without contact)", "m"),
        Quantity::new("rule's estimate", "m"),
    );
    let mut hi = 0.0f64;
    type Estimate = fn(&Level) -> f64;
    let rules: [(&str, Estimate); 3] =
        [("abs", |l| l.abs), ("srss", |l| l.srss), ("ddc", |l| l.ddc)];
    for (i, (rule, estimate)) in rules.iter().enumerate() {
        let (mut x, mut y) = (Vec::new(), Vec::new());
        for pairs in &runs {
            for l in pairs.iter().flat_map(|p| &p.levels).map(|l| &l.level) {
                let (g, e) = (l.required_gap, estimate(l));
                x.push(g);
                y.push(e);
                hi = hi.max(g).max(e);
            }
        }
        // Where rules agree their points coincide (SRSS and DDC for well-separated periods): each rule
        // its own shape, drawn largest first, so that every one stays visible on the one before.
        let style = Style {
            width: [4.2, 2.8, 1.5][i],
            shape: [Shape::Circle, Shape::Square, Shape::Diamond][i],
            ..Style::nth(i)
        };
        p.series
            .push(Series::points(rule.to_uppercase(), x, y, style));
    }
    p.series.insert(
        0,
        Series::line(
            "estimate = required",
            vec![0.0, hi],
            vec![0.0, hi],
            Style::reference(),
        ),
    );
    p.x_zero = true;
    p.y_zero = true;
    Figure {
        id: "separation".into(),
        title: "Required separation: the code rules against the gap each level needed".into(),
        subtitle: subtitle.into(),
        panels: vec![p],
        columns: 1,
        plot: (PLOT.0, 320.0),
        ..Figure::default()
    }
}

/// The probability of pounding against the gap, one curve per contact level (a colour each): under a
/// random motion the Rice–Poisson curve; over a suite the fitted lognormal (line) and the records'
/// fraction (steps); the contact's gap (dotted), the target probability (dashed) and a code's gap marked.
pub fn separation_probability(report: &SeparationReport, subtitle: &str) -> Figure {
    let mut p = Panel::new(
        "",
        Quantity::new("gap", "m"),
        Quantity::new("probability of pounding", ""),
    );
    p.x_zero = true;
    p.y_range = Some((0.0, 1.0));
    p.legend = Legend::Right;
    let mut k = 0;
    let mut codes = Vec::new();
    let mut target = None;
    match report {
        SeparationReport::WhiteNoise(n) => {
            target = n.target_probability;
            let duration = n.white_noise["duration"].as_f64().unwrap_or(1.0);
            let clumping = match n.white_noise["clumping"].as_str() {
                Some("vanmarcke") => Clumping::Vanmarcke,
                _ => Clumping::Poisson,
            };
            for pair in &n.pairs {
                for l in &pair.levels {
                    let top = 5.0 * l.crossing.sigma;
                    let g: Vec<f64> = (0..=120).map(|j| top * f64::from(j) / 120.0).collect();
                    let pr = g
                        .iter()
                        .map(|&x| l.crossing.probability(x, duration, clumping))
                        .collect();
                    let name = format!("{} {}-{}", pair.between.join("|"), l.floors.0, l.floors.1);
                    p.series.push(Series::line(name, g, pr, Style::level(k)));
                    codes.extend(
                        l.code_required_gap
                            .zip(l.probability_at_code_gap)
                            .map(|(c, pc)| (c, pc, k, format!("{}-{}", l.floors.0, l.floors.1))),
                    );
                    k += 1;
                }
            }
        }
        SeparationReport::Suite {
            records,
            statistics,
            target_probability,
            ..
        } => {
            target = *target_probability;
            for (pi, pair) in statistics.pairs.iter().enumerate() {
                for (li, l) in pair.levels.iter().enumerate() {
                    let mut gaps: Vec<f64> = records
                        .iter()
                        .map(|r| r.pairs[pi].levels[li].level.required_gap)
                        .collect();
                    gaps.sort_by(f64::total_cmp);
                    let top = 1.3 * gaps.last().copied().unwrap_or(0.0);
                    let name = format!("{} {}-{}", pair.between.join("|"), l.floors.0, l.floors.1);
                    // The records' fraction above each gap: a step down at each record's gap.
                    let n = gaps.len() as f64;
                    let (mut x, mut y) = (
                        vec![0.0],
                        vec![gaps.iter().filter(|g| **g > 0.0).count() as f64 / n],
                    );
                    for (i, g) in gaps.iter().enumerate().filter(|(_, g)| **g > 0.0) {
                        x.extend([*g, *g]);
                        y.extend([*y.last().unwrap_or(&0.0), (n - i as f64 - 1.0) / n]);
                    }
                    x.push(top);
                    y.push(0.0);
                    let step = Style {
                        width: 1.0,
                        dash: Dash::Dotted,
                        ..Style::level(k)
                    };
                    p.series
                        .push(Series::line(format!("{name}, records"), x, y, step));
                    if let Some(f) = l.fit {
                        let g: Vec<f64> = (0..=120).map(|j| top * f64::from(j) / 120.0).collect();
                        let pr = g.iter().map(|&x| f.probability(x)).collect();
                        p.series.push(Series::line(
                            format!("{name}, lognormal fit"),
                            g,
                            pr,
                            Style::level(k),
                        ));
                    }
                    codes.extend(
                        l.code_required_gap
                            .zip(l.probability_at_code_gap)
                            .map(|(c, pc)| (c, pc, k, format!("{}-{}", l.floors.0, l.floors.1))),
                    );
                    k += 1;
                }
            }
        }
        SeparationReport::One { .. } | SeparationReport::Risk(_) => {}
    }
    if let Some(t) = target {
        p.series.push(Series {
            label: format!("target P = {t}"),
            mark: Mark::HLine(t),
            style: Style::reference(),
        });
    }
    for (c, pc, k, floors) in codes {
        p.series.push(Series::points(
            format!(
                "code's gap, {floors}: P = {}",
                crate::output::fmt_sig(pc, 3)
            ),
            vec![c],
            vec![pc],
            Style {
                width: 4.0,
                shape: Shape::Triangle,
                ..Style::level(k)
            },
        ));
    }
    Figure {
        id: "separation-probability".into(),
        title: "Probability of pounding against the gap, by contact level".into(),
        subtitle: subtitle.into(),
        panels: vec![p],
        columns: 1,
        plot: (PLOT.0, 320.0),
        ..Figure::default()
    }
}

/// The mean annual frequency of pounding against the gap, per contact level (log axis), with the target.
pub fn separation_risk(report: &SeparationReport, subtitle: &str) -> Figure {
    let mut p = Panel::new(
        "",
        Quantity::new("gap", "m"),
        Quantity::new("mean annual frequency of pounding", "1/yr"),
    );
    p.x_zero = true;
    p.y_log = true;
    p.legend = Legend::Right;
    let mut lo = f64::INFINITY;
    let mut hi = 0.0f64;
    let mut notes = Vec::new();
    if let SeparationReport::Risk(r) = report {
        let mut k = 0;
        for pair in &r.pairs {
            for l in &pair.levels {
                let (g, f): (Vec<f64>, Vec<f64>) = l
                    .curve
                    .gaps
                    .iter()
                    .zip(&l.curve.annual_frequency)
                    .filter(|(_, f)| **f > 0.0)
                    .map(|(g, f)| (*g, *f))
                    .unzip();
                for &x in &f {
                    lo = lo.min(x);
                    hi = hi.max(x);
                }
                let name = format!("{} {}-{}", pair.between.join("|"), l.floors.0, l.floors.1);
                p.series.push(Series::line(name, g, f, Style::level(k)));
                k += 1;
            }
        }
        if let Some(t) = r.risk["target_rate"].as_f64() {
            lo = lo.min(t);
            hi = hi.max(t);
            p.series.push(Series {
                label: format!("target {} /yr", crate::output::fmt_sig(t, 3)),
                mark: Mark::HLine(t),
                style: Style::reference(),
            });
        }
        notes.push(format!(
            "For each gap, the intensity ({}) at which each record first needs more (runs without contact at each level, read between levels and in proportion beyond) makes a lognormal fragility, integrated over the hazard curve.",
            r.risk["measure"].as_str().unwrap_or("")
        ));
    }
    if hi > 0.0 {
        p.y_range = Some((lo / 2.0, hi * 2.0));
    }
    let mut panels = vec![p];
    if let SeparationReport::Risk(r) = report {
        if let Some(life) = r.risk["design_life"].as_f64() {
            let mut q = Panel::new(
                format!(
                    "over a design life of {} years",
                    crate::output::fmt_sig(life, 4)
                ),
                Quantity::new("gap", "m"),
                Quantity::new("probability of pounding", ""),
            );
            q.x_zero = true;
            q.y_range = Some((0.0, 1.0));
            q.legend = Legend::None;
            let mut k = 0;
            for pair in &r.pairs {
                for l in &pair.levels {
                    let pr = l
                        .curve
                        .annual_frequency
                        .iter()
                        .map(|f| -(-f * life).exp_m1())
                        .collect();
                    q.series
                        .push(Series::line("", l.curve.gaps.clone(), pr, Style::level(k)));
                    k += 1;
                }
            }
            if let Some(p) = r.risk["target_probability"].as_f64() {
                q.series.push(Series {
                    label: String::new(),
                    mark: Mark::HLine(p),
                    style: Style::reference(),
                });
            }
            panels.push(q);
        }
    }
    Figure {
        id: "separation-risk".into(),
        title: "Mean annual frequency of pounding against the gap".into(),
        subtitle: subtitle.into(),
        panels,
        columns: 1,
        plot: (PLOT.0, 320.0),
        notes,
        ..Figure::default()
    }
}

/// The IDA curves (each record's EDP against intensity, one panel per limit state with a threshold) and the
/// fragility functions (the two fits with the observed fraction at each level, one panel per limit state).
/// `runs` are `(record, level, edp values by limit state)`; `fits` the study's fragility JSON.
/// A limit state for the figures: its name, threshold, the unit of its demand, and whether it is `pounding`.
pub struct StateAxis {
    /// As written.
    pub name: String,
    /// Threshold, in `unit`.
    pub threshold: f64,
    /// SI unit of the demand ("" for a ratio).
    pub unit: &'static str,
    /// `pounding` (a yes/no demand: no IDA curve).
    pub boolean: bool,
}

pub fn ida(
    levels: &[f64],
    records: &[String],
    edps: &[Vec<Vec<Option<f64>>>],
    limit_states: &[StateAxis],
    fits: &[FragilityJson],
    measure: (&str, &str),
) -> Vec<Figure> {
    let im = || Quantity::new(measure.0, "m/s\u{b2}");
    let mut curves = Vec::new();
    for (l, ls) in limit_states.iter().enumerate() {
        let (name, threshold) = (&ls.name, &ls.threshold);
        if ls.boolean {
            continue;
        }
        let demand = name
            .split(['>', ' '])
            .next()
            .unwrap_or("demand")
            .to_string();
        let mut p = Panel::new(name.clone(), Quantity::new(demand, ls.unit), im());
        for (i, _) in records.iter().enumerate() {
            let (x, y): (Vec<f64>, Vec<f64>) = levels
                .iter()
                .enumerate()
                .filter_map(|(j, lv)| edps[l][i][j].map(|e| (e, *lv)))
                .unzip();
            let st = Style {
                width: 1.0,
                ..Style::nth(0)
            };
            p.series.push(Series::line("", x, y, st));
        }
        p.series.push(Series::line(
            "threshold",
            vec![*threshold, *threshold],
            vec![0.0, levels.last().copied().unwrap_or(1.0)],
            Style::reference(),
        ));
        p.x_zero = true;
        p.y_zero = true;
        curves.push(p);
    }
    let mut frag = Vec::new();
    for f in fits {
        let name = f.limit_state.clone();
        let mut p = Panel::new(name, im(), Quantity::new("probability of exceedance", ""));
        let top = levels.last().copied().unwrap_or(1.0) * 1.1;
        let xs: Vec<f64> = (1..=200).map(|k| top * k as f64 / 200.0).collect();
        for (i, (method, fit)) in [("stripes", &f.stripes), ("ida", &f.ida)]
            .into_iter()
            .enumerate()
        {
            if let FitJson::Fitted { median: m, beta: b } = *fit {
                let fr = pounding::fragility::Fragility { median: m, beta: b };
                let label = format!(
                    "{} fit: median {}, beta {:.3}",
                    if method == "stripes" {
                        "stripes"
                    } else {
                        "IDA"
                    },
                    crate::output::fmt_sig(m, 4),
                    b
                );
                p.series.push(Series::line(
                    label,
                    xs.clone(),
                    xs.iter().map(|x| fr.probability(*x)).collect(),
                    Style::nth(i),
                ));
            }
        }
        let (x, y): (Vec<f64>, Vec<f64>) = f
            .exceedances
            .iter()
            .zip(levels)
            .filter(|([_, n], _)| *n > 0)
            .map(|([z, n], lv)| (*lv, *z as f64 / *n as f64))
            .unzip();
        p.series.push(Series::points(
            "observed fraction",
            x,
            y,
            Style {
                width: 3.0,
                ..Style::nth(6)
            },
        ));
        p.y_range = Some((0.0, 1.0));
        p.x_zero = true;
        frag.push(p);
    }
    let mut out = Vec::new();
    if !curves.is_empty() {
        let n = curves.len();
        out.push(Figure {
            id: "ida-curves".into(),
            title: "IDA curves: each record's demand against intensity".into(),
            subtitle: format!(
                "{} records, {} levels; {}",
                records.len(),
                levels.len(),
                measure.1
            ),
            panels: curves,
            columns: n.min(2),
            plot: (420.0, 260.0),
            ..Figure::default()
        });
    }
    let n = frag.len();
    out.push(Figure {
        id: "fragility".into(),
        title: "Fragility: lognormal fits (maximum likelihood) and observed fractions".into(),
        subtitle: format!(
            "{} records, {} levels; {}",
            records.len(),
            levels.len(),
            measure.1
        ),
        panels: frag,
        columns: n.clamp(1, 2),
        plot: (420.0, 260.0),
        ..Figure::default()
    });
    out
}

/// A restitution fit: the measured points and the fitted `e(v_i)` (a table: its rows joined, held beyond).
pub fn fit_restitution(
    points: &[(f64, f64)],
    r: &pounding_study::fit::FitReport,
    what: &str,
) -> Figure {
    let mut p = Panel::new(
        "",
        Quantity::new("impact velocity v_i", "m/s"),
        Quantity::new("coefficient of restitution e", ""),
    );
    p.x_zero = true;
    p.series.push(Series::points(
        "measured",
        points.iter().map(|q| q.0).collect(),
        points.iter().map(|q| q.1).collect(),
        Style {
            width: 2.2,
            ..Style::nth(0)
        },
    ));
    let label = match r.parameters.iter().next() {
        Some((key, v)) if v.is_number() => format!(
            "fit: {key} = {} {}",
            crate::output::fmt_sig(v.as_f64().unwrap_or(0.0), 4),
            r.units.get(key).and_then(|u| u.as_str()).unwrap_or("")
        )
        .trim_end()
        .to_string(),
        _ => format!("fit: {}", r.model),
    };
    p.series.push(Series::line(
        label,
        r.curve.0.clone(),
        r.curve.1.clone(),
        Style::nth(1),
    ));
    Figure {
        id: "fit-restitution".into(),
        title: format!("Restitution against impact velocity, fitted ({})", r.model),
        subtitle: what.into(),
        panels: vec![p],
        notes: vec![residual_note(r)],
        ..Figure::default()
    }
}

/// A force-history fit: the measured samples and the fitted force against time, and the residual.
pub fn fit_force_history(
    data: &[(f64, f64)],
    r: &pounding_study::fit::FitReport,
    what: &str,
) -> Figure {
    let force = || Quantity::new("contact force", "N");
    let mut p = Panel::new("", time(), force());
    p.x_tight = true;
    p.series.push(Series::points(
        "measured",
        data.iter().map(|q| q.0).collect(),
        data.iter().map(|q| q.1).collect(),
        Style {
            width: 2.0,
            ..Style::nth(0)
        },
    ));
    p.series.push(Series::line(
        format!("fit: {}", r.model),
        r.curve.0.clone(),
        r.curve.1.clone(),
        Style::nth(1),
    ));
    // The residual at each sample: the fitted force there (the curve's grid holds the samples' span) less
    // the measurement, read on the fine curve by linear interpolation.
    let at = |t: f64| {
        let (x, y) = &r.curve;
        let k = x.partition_point(|&v| v < t).clamp(1, x.len().max(2) - 1);
        let (x0, x1, y0, y1) = (x[k - 1], x[k], y[k - 1], y[k]);
        if x1 > x0 {
            y0 + (y1 - y0) * (t - x0) / (x1 - x0)
        } else {
            y0
        }
    };
    let mut q = Panel::new("residual (fit - measured)", time(), force());
    q.x_tight = true;
    q.legend = Legend::None;
    q.series.push(Series::points(
        "",
        data.iter().map(|d| d.0).collect(),
        data.iter().map(|d| at(d.0) - d.1).collect(),
        Style {
            width: 1.6,
            shape: Shape::Square,
            ..Style::nth(2)
        },
    ));
    q.series.push(Series {
        label: String::new(),
        mark: super::Mark::HLine(0.0),
        style: Style::reference(),
    });
    Figure {
        id: "fit-force-history".into(),
        title: format!("Force history of an impact, fitted ({})", r.model),
        subtitle: what.into(),
        panels: vec![p, q],
        columns: 1,
        share_x: true,
        notes: vec![residual_note(r)],
        ..Figure::default()
    }
}

/// The residual of a fit, in words.
fn residual_note(r: &pounding_study::fit::FitReport) -> String {
    let unit = if r.residual_unit.is_empty() {
        String::new()
    } else {
        format!(" {}", r.residual_unit)
    };
    format!(
        "{} points; residual rms {}{unit}, normalised {} % (the square root of the sum of squared residuals over the sum of squared data).",
        r.points,
        crate::output::fmt_sig(r.rms_residual, 3),
        crate::output::fmt_sig(100.0 * r.normalised_residual, 3)
    )
}
