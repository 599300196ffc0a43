//! The tool's figures: one impact (force against time and against penetration), several models on one
//! impact, Table 1 of Papi & Toopchi-Nezhad (2022) as curves, and the figures of a pounding run.

use super::axis::human;
use super::{Dash, Figure, Legend, Mark, Panel, Quantity, Series, Style, PLOT};
use crate::output::{fmt_num, fmt_sig};
use crate::run_data::RunData;

/// A force history to plot: label, time since touch (s), penetration (m), force (N).
pub struct ForceHistory<'a> {
    /// Legend text.
    pub label: String,
    /// Time since touch, s.
    pub t: &'a [f64],
    /// Penetration, m.
    pub penetration: &'a [f64],
    /// Contact force, N.
    pub force: &'a [f64],
}

fn force() -> Quantity {
    Quantity::new("contact force", "N")
}

/// Force against time and force against penetration (the hysteresis loop) of one or more impacts, as
/// figures `<prefix>-force-time` and `<prefix>-force-penetration`. A single impact has its peak marked.
pub fn impact(prefix: &str, title: &str, subtitle: &str, runs: &[ForceHistory]) -> Vec<Figure> {
    let one = runs.len() == 1;
    let mut time = Panel::new("", Quantity::new("time since touch", "s"), force());
    let mut loop_ = Panel::new("", Quantity::new("penetration", "m"), force());
    for (i, r) in runs.iter().enumerate() {
        let st = Style::nth(i);
        time.series
            .push(Series::line(&r.label, r.t.to_vec(), r.force.to_vec(), st));
        loop_.series.push(Series::line(
            &r.label,
            r.penetration.to_vec(),
            r.force.to_vec(),
            st,
        ));
    }
    if one {
        // The located peak is a point of the history (see `pounding::impact::History`).
        let r = &runs[0];
        let k = (0..r.force.len())
            .max_by(|&a, &b| r.force[a].total_cmp(&r.force[b]))
            .unwrap_or(0);
        let peak = Style {
            width: 2.0,
            ..Style::nth(1)
        };
        if let (Some(&t), Some(&d), Some(&f)) = (r.t.get(k), r.penetration.get(k), r.force.get(k)) {
            time.series
                .push(Series::points("peak force", vec![t], vec![f], peak));
            loop_
                .series
                .push(Series::points("peak force", vec![d], vec![f], peak));
        }
    }
    // Time runs from touch to the end of contact; penetration to the next tick past the largest.
    time.x_tight = true;
    for p in [&mut time, &mut loop_] {
        p.y_zero = true;
        if one {
            // The single curve needs no legend entry; the peak marker does.
            p.series[0].label.clear();
        }
    }
    vec![
        Figure {
            id: format!("{prefix}-force-time"),
            title: format!("{title}: contact force against time"),
            subtitle: subtitle.into(),
            panels: vec![time],
            columns: 1,
            plot: PLOT,
            ..Figure::default()
        },
        Figure {
            id: format!("{prefix}-force-penetration"),
            title: format!("{title}: force against penetration"),
            subtitle: subtitle.into(),
            panels: vec![loop_],
            columns: 1,
            plot: PLOT,
            ..Figure::default()
        },
    ]
}

/// One model variant of Table 1: its label and `(e_pre, e_post)` on a grid.
pub struct Curve {
    /// Legend text.
    pub label: String,
    /// Requested e.
    pub e_pre: Vec<f64>,
    /// Delivered e.
    pub e_post: Vec<f64>,
}

/// Table 1 of Papi & Toopchi-Nezhad (2022) as curves, in two groups (the paper's models; the other damped models): delivered
/// against requested e with the ideal line, and the relative error against e.
pub fn table1(groups: &[(&str, Vec<Curve>)]) -> Vec<Figure> {
    let e_pre = || Quantity::new("requested e (e_pre)", "");
    let mut delivered = Vec::new();
    let mut error = Vec::new();
    for (title, curves) in groups {
        let mut a = Panel::new(*title, e_pre(), Quantity::new("delivered e (e_post)", ""));
        a.x_range = Some((0.0, 1.0));
        a.y_range = Some((0.0, 1.05));
        a.legend = Legend::Right;
        a.series.push(Series::line(
            "ideal: e_post = e_pre",
            vec![0.0, 1.0],
            vec![0.0, 1.0],
            Style::reference(),
        ));
        let mut b = Panel::new(
            *title,
            e_pre(),
            Quantity::new("error |e_pre \u{2212} e_post| / e_pre", "%"),
        );
        b.x_range = Some((0.0, 1.0));
        // Errors span from 0 (calibrated) to hundreds of per cent: decades show both.
        b.y_range = Some((1e-3, 1e3));
        b.y_log = true;
        b.legend = Legend::Right;
        for (i, c) in curves.iter().enumerate() {
            let st = Style::nth(i);
            a.series.push(Series::line(
                &c.label,
                c.e_pre.clone(),
                c.e_post.clone(),
                st,
            ));
            let err = c
                .e_pre
                .iter()
                .zip(&c.e_post)
                .map(|(e, p)| (e - p).abs() / e * 100.0)
                .collect();
            b.series
                .push(Series::line(&c.label, c.e_pre.clone(), err, st));
        }
        delivered.push(a);
        error.push(b);
    }
    let subtitle = "ideal single impacts, each model's published damping formula; exact relations \
                    (Jankowski integrated); e = 0.10 to 1.00 in steps of 0.01";
    vec![
        Figure {
            id: "table1-e-post".into(),
            title: "Delivered against requested coefficient of restitution".into(),
            subtitle: subtitle.into(),
            panels: delivered,
            columns: 1,
            plot: PLOT,
            ..Figure::default()
        },
        Figure {
            id: "table1-error".into(),
            title: "Error in the coefficient of restitution (Table 1 of Papi & Toopchi-Nezhad 2022)".into(),
            subtitle: format!(
                "{subtitle}; errors below 0.001 % (calibrated models: about 1e\u{2212}10 %) lie under the axis"
            ),
            panels: error,
            columns: 1,
            plot: PLOT,
            ..Figure::default()
        },
    ]
}

fn time() -> Quantity {
    Quantity::new("time", "s")
}

/// The figures of a pounding run: floor displacements with impact instants, peak response over height,
/// the force-drift loop of the most strained storey (and of every inelastic storey of its building),
/// contact forces, delivered e, relative displacement against the gap, and the energy balance.
pub fn run(d: &RunData) -> Vec<Figure> {
    let (forces, closing, restitution) = contact_figures(d);
    let mut figs = vec![record(d), displacement(d)];
    if !d.buildings.is_empty() {
        figs.push(envelopes(d));
        figs.extend(hysteresis(d));
        figs.extend(isolators(d));
    }
    figs.extend(forces);
    figs.extend(impact_loops(d));
    figs.extend(restitution);
    figs.extend(closing);
    figs.extend(devices(d));
    figs.push(energy(d));
    figs
}

/// The ground motion, and each building's floor displacements with the instants of its impacts.
fn displacement(d: &RunData) -> Figure {
    let impact_style = Style {
        width: 1.0,
        ..Style::nth(1)
    };
    let mut ground = Panel::new(
        "ground motion",
        time(),
        Quantity::new("ground acceleration", "m/s\u{b2}"),
    );
    ground.x_tight = true;
    ground.legend = Legend::None;
    ground.series.push(Series::line(
        "",
        d.t.clone(),
        d.ground_acceleration.clone(),
        Style {
            width: 1.0,
            ..Style::nth(6)
        },
    ));
    let mut panels = vec![ground];
    for (b, bd) in d.buildings.iter().enumerate() {
        let mut p = Panel::new(
            format!(
                "building {}: floor displacements relative to the ground",
                bd.name
            ),
            time(),
            Quantity::new("displacement", "m"),
        );
        p.x_tight = true;
        let n = bd.floors.len();
        for (f, u) in bd.floors.iter().enumerate() {
            let label = if f + 1 == n && n > 1 {
                format!("floor {} (roof)", f + 1)
            } else {
                format!("floor {}", f + 1)
            };
            p.series.push(Series::line(
                label,
                d.t.clone(),
                u.clone(),
                floor_style(f, n),
            ));
        }
        let instants: Vec<f64> = d
            .impacts
            .iter()
            .filter(|i| {
                d.contacts[i.contact].left == Some(b) || d.contacts[i.contact].right == Some(b)
            })
            .map(|i| i.time)
            .collect();
        if !instants.is_empty() {
            p.series.push(Series {
                label: "impact (touch)".into(),
                mark: Mark::Rug(instants),
                style: impact_style,
            });
        }
        p.legend = if n > 4 { Legend::Right } else { Legend::Inside };
        panels.push(p);
    }
    Figure {
        id: "displacement".into(),
        title: "Floor displacements".into(),
        subtitle: d.subtitle.clone(),
        panels,
        columns: 1,
        plot: PLOT,
        ..Figure::default()
    }
}

/// The forces of the devices, if there are any.
fn devices(d: &RunData) -> Option<Figure> {
    if d.devices.is_empty() {
        return None;
    }
    let panels = d
        .devices
        .iter()
        .map(|dd| {
            let mut p = Panel::new(
                format!("device {} ({})", dd.name, dd.model),
                time(),
                Quantity::new("force, positive pushing apart", "N"),
            );
            p.x_tight = true;
            for (k, el) in dd.elements.iter().enumerate() {
                p.series.push(Series::line(
                    format!("floors {}-{}", el.floors.0, el.floors.1),
                    d.t.clone(),
                    el.force.clone(),
                    Style::nth(k),
                ));
            }
            p
        })
        .collect();
    Some(Figure {
        id: "device-force".into(),
        title: "Forces of the devices between neighbours".into(),
        subtitle: d.subtitle.clone(),
        panels,
        columns: 1,
        plot: PLOT,
        ..Figure::default()
    })
}

/// The energy balance over time.
fn energy(d: &RunData) -> Figure {
    let mut energy = Panel::new("", time(), Quantity::new("energy", "J"));
    let mut hysteretic = false;
    energy.x_tight = true;
    energy.y_zero = true;
    energy.legend = Legend::Right;
    let names = [
        "input (ground motion)",
        "kinetic",
        "strain",
        "dissipated by structural damping",
        "dissipated by storey hysteresis",
        "contact (dissipated and stored)",
    ];
    let styles = [
        Style {
            width: 2.2,
            ..Style::nth(6)
        },
        Style::nth(5),
        Style::nth(2),
        Style::nth(0),
        Style::nth(3),
        Style::nth(1),
    ];
    for ((name, e), st) in names.iter().zip(&d.energy).zip(styles) {
        // Linear storeys dissipate nothing by hysteresis: no line for them.
        if name.contains("hysteresis") {
            if e.iter().all(|x| *x == 0.0) {
                continue;
            }
            hysteretic = true;
        }
        energy
            .series
            .push(Series::line(*name, d.t.clone(), e.clone(), st));
    }
    Figure {
        id: "energy".into(),
        title: if hysteretic {
            "Energy balance: input = kinetic + strain + structural damping + storey hysteresis + contact"
        } else {
            "Energy balance: input = kinetic + strain + structural damping + contact"
        }
        .into(),
        subtitle: d.subtitle.clone(),
        panels: vec![energy],
        columns: 1,
        plot: PLOT,
        ..Figure::default()
    }
}

/// Each building's levels from the ground up (ground = 0, then every floor) and the quantity of the height
/// axis: elevations in m from the scenario file, or floor numbers if the folder has none for some building.
fn levels(d: &RunData) -> (Vec<Vec<f64>>, Quantity) {
    let with_ground = |z: &[f64]| std::iter::once(0.0).chain(z.iter().copied()).collect();
    if d.buildings.iter().all(|b| b.elevations.is_some()) {
        let z = d
            .buildings
            .iter()
            .map(|b| with_ground(b.elevations.as_deref().unwrap_or_default()))
            .collect();
        (z, Quantity::new("height above ground", "m").shown_in(0))
    } else {
        let z = d
            .buildings
            .iter()
            .map(|b| (0..=b.floors.len()).map(|f| f as f64).collect())
            .collect();
        (z, Quantity::new("floor (0 = ground)", ""))
    }
}

/// A storey quantity as steps over height: `v[j]` from level `z[j]` to level `z[j + 1]`.
fn steps(v: &[f64], z: &[f64]) -> (Vec<f64>, Vec<f64>) {
    let mut x = Vec::with_capacity(2 * v.len());
    let mut y = Vec::with_capacity(2 * v.len());
    for (j, &vj) in v.iter().enumerate() {
        x.extend([vj, vj]);
        y.extend([z[j], z[j + 1]]);
    }
    (x, y)
}

/// Peak response over height, one line per building, four panels side by side: floor displacement and
/// absolute acceleration at the floors (0 and the record's PGA at the ground), storey drift ratio and storey
/// shear as steps over each storey's height.
fn envelopes(d: &RunData) -> Figure {
    let (z, height) = levels(d);
    let panel = |title: &str, q: Quantity| {
        let mut p = Panel::new(title, q, height.clone());
        p.x_zero = true;
        p.y_zero = true;
        p.legend = Legend::None;
        p
    };
    let mut disp = panel(
        "floor displacement",
        Quantity::new("peak displacement", "m"),
    );
    let mut drift = panel(
        "storey drift (steps)",
        Quantity::new("peak drift ratio", "%"),
    );
    let mut acc = panel(
        "floor acceleration",
        Quantity::new("peak absolute acceleration", "m/s\u{b2}"),
    );
    let mut shear = panel(
        "storey shear (steps)",
        Quantity::new("peak storey shear", "N"),
    );
    let pga = d.summary.record.pga;
    for (b, bd) in d.buildings.iter().enumerate() {
        let s = &d.summary.buildings[b];
        let z = &z[b];
        let line = Style {
            width: 1.8,
            ..Style::nth(b)
        };
        let dotted = Style {
            marker: true,
            ..line
        };
        let at_floors = |ground: f64, v: Vec<f64>| std::iter::once(ground).chain(v).collect();
        disp.series.push(Series::line(
            &bd.name,
            at_floors(0.0, s.peak_displacement.clone()),
            z.clone(),
            dotted,
        ));
        let ratio: Vec<f64> = s.peak_drift_ratio.iter().map(|r| 100.0 * r).collect();
        let (x, y) = steps(&ratio, z);
        drift.series.push(Series::line(&bd.name, x, y, line));
        acc.series.push(Series::line(
            &bd.name,
            at_floors(pga, s.peak_absolute_acceleration.clone()),
            z.clone(),
            dotted,
        ));
        let (x, y) = steps(&s.peak_storey_shear, z);
        shear.series.push(Series::line(&bd.name, x, y, line));
    }
    disp.legend = Legend::Inside;
    Figure {
        id: "envelopes".into(),
        title: "Peak response over height".into(),
        subtitle: format!(
            "{}; floor values as dots at the floors (at the ground: 0 and the record's PGA), storey values as steps over each storey",
            d.subtitle
        ),
        panels: vec![disp, drift, acc, shear],
        columns: 4,
        plot: (240.0, 360.0),
        ..Figure::default()
    }
}

/// One storey's identity and numbers from summary.json: building, storey (from 0), model, yield force
/// (inelastic storeys), ductility and hysteretic energy.
struct StoreyInfo {
    building: usize,
    storey: usize,
    model: String,
    yield_force: Option<f64>,
    ductility: Option<f64>,
    hysteretic_energy: Option<f64>,
}

/// The storeys of building `b`, from summary.json.
fn storey_info(d: &RunData, b: usize) -> Vec<StoreyInfo> {
    let s = &d.summary.buildings[b];
    let n = d.buildings[b].storey_shear.len();
    let inelastic = &s.inelastic_storeys;
    let (fy, mu, eh) = (&s.yield_forces, &s.ductility, &s.hysteretic_energy);
    (0..n)
        .map(|j| {
            let k = inelastic.iter().position(|&i| i == j + 1);
            let pick = |v: &[f64]| k.and_then(|k| v.get(k).copied()).filter(|x| x.is_finite());
            StoreyInfo {
                building: b,
                storey: j,
                model: match (j, &s.isolator) {
                    (0, Some(iso)) => format!("isolator, {}", iso.model),
                    _ => s.storey_models[j].name().to_string(),
                },
                yield_force: pick(fy),
                ductility: pick(mu),
                hysteretic_energy: pick(eh),
            }
        })
        .collect()
}

/// The drift history of storey `j` of building `b`: u_j - u_(j-1), the ground not moving (m).
fn drift(d: &RunData, b: usize, j: usize) -> Vec<f64> {
    let floors = &d.buildings[b].floors;
    match j {
        0 => floors[0].clone(),
        _ => floors[j]
            .iter()
            .zip(&floors[j - 1])
            .map(|(a, c)| a - c)
            .collect(),
    }
}

/// The ±F_y lines of an inelastic storey (the upper one labelled if `label`).
fn yield_lines(p: &mut Panel, fy: f64, label: bool) {
    let st = Style::reference();
    p.series.push(Series {
        label: if label {
            format!("yield force \u{b1}F_y = \u{b1}{}", human_si(fy, "N"))
        } else {
            String::new()
        },
        mark: Mark::HLine(fy),
        style: st,
    });
    p.series.push(Series {
        label: String::new(),
        mark: Mark::HLine(-fy),
        style: st,
    });
}

/// A storey's name with its numbers, for titles: "storey 1 (bouc-wen, ductility 3.02)".
fn storey_title(i: &StoreyInfo) -> String {
    match i.ductility {
        Some(mu) => format!(
            "storey {} ({}, ductility {})",
            i.storey + 1,
            i.model,
            fmt_sig(mu, 3)
        ),
        None => format!("storey {} ({})", i.storey + 1, i.model),
    }
}

/// The loop of every isolator: its force against its displacement (storey 1), with its clearance.
fn isolators(d: &RunData) -> Option<Figure> {
    let panels: Vec<Panel> = (0..d.buildings.len())
        .filter_map(|b| {
            let iso = d.summary.buildings[b].isolator.as_ref()?;
            let model = iso.model.name();
            let u = drift(d, b, 0);
            let f = d.buildings[b].storey_shear[0].clone();
            let mut p = Panel::new(
                format!(
                    "{}: {model} isolator, peak displacement {}",
                    d.buildings[b].name,
                    human_si(iso.peak_displacement, "m")
                ),
                Quantity::new("isolator displacement", "m"),
                Quantity::new("isolator force", "N"),
            );
            p.x_zero = true;
            p.y_zero = true;
            let top = f.iter().fold(0.0f64, |a, x| a.max(x.abs()));
            p.series.push(Series::line(
                "",
                u,
                f,
                Style {
                    width: 1.2,
                    ..Style::nth(0)
                },
            ));
            if let Some(c) = iso.clearance {
                for (k, x) in [c, -c].into_iter().enumerate() {
                    let label = if k == 0 {
                        format!("clearance \u{b1}{}", human_si(c, "m"))
                    } else {
                        String::new()
                    };
                    p.series.push(Series::line(
                        label,
                        vec![x, x],
                        vec![-top, top],
                        Style::reference(),
                    ));
                }
            }
            Some(p)
        })
        .collect();
    (!panels.is_empty()).then(|| Figure {
        id: "isolators".into(),
        title: "Isolator force against displacement".into(),
        subtitle: format!(
            "{}; displacement of the base slab relative to the ground; force: the isolator's restoring force",
            d.subtitle
        ),
        panels,
        columns: 1,
        plot: (620.0, 380.0),
        ..Figure::default()
    })
}

/// The force-drift loop of the most strained storey: the largest ductility over every building, or, with
/// no inelastic storey, the largest peak drift ratio. With two or more inelastic storeys in its building, a
/// second figure has the loop of each of them on common axes.
fn hysteresis(d: &RunData) -> Vec<Figure> {
    let all: Vec<StoreyInfo> = (0..d.buildings.len())
        .flat_map(|b| storey_info(d, b))
        .collect();
    let ratio = |i: &StoreyInfo| d.summary.buildings[i.building].peak_drift_ratio[i.storey];
    let most = all
        .iter()
        .filter(|i| i.ductility.is_some())
        .max_by(|a, b| {
            a.ductility
                .unwrap_or(0.0)
                .total_cmp(&b.ductility.unwrap_or(0.0))
        })
        .or_else(|| all.iter().max_by(|a, b| ratio(a).total_cmp(&ratio(b))));
    let Some(most) = most else {
        return Vec::new();
    };
    let name = &d.buildings[most.building].name;
    let drift_q = || Quantity::new("storey drift", "m");
    let shear_q = || Quantity::new("storey shear", "N");
    let loop_style = Style {
        width: 1.2,
        ..Style::nth(0)
    };
    let end_style = Style {
        width: 2.0,
        ..Style::nth(1)
    };
    let j = most.storey;
    let u = drift(d, most.building, j);
    let v = d.buildings[most.building].storey_shear[j].clone();
    let mut p = Panel::new(
        match most.hysteretic_energy {
            Some(e) => format!(
                "{}, hysteretic energy {}",
                storey_title(most),
                human_si(e, "J")
            ),
            None => storey_title(most),
        },
        drift_q(),
        shear_q(),
    );
    p.x_zero = true;
    p.y_zero = true;
    if let (Some(&ue), Some(&ve)) = (u.last(), v.last()) {
        p.series
            .push(Series::line("", u.clone(), v.clone(), loop_style));
        p.series.push(Series::points(
            format!("end of the analysis: drift {}", human_si(ue, "m")),
            vec![ue],
            vec![ve],
            end_style,
        ));
    }
    if let Some(fy) = most.yield_force {
        yield_lines(&mut p, fy, true);
    }
    let why = if most.ductility.is_some() {
        "the largest ductility of the run"
    } else {
        "no inelastic storey; the largest peak drift ratio of the run"
    };
    let mut figs = vec![Figure {
        id: "hysteresis".into(),
        title: format!(
            "Storey shear against drift: building {name}, storey {}",
            j + 1
        ),
        subtitle: format!(
            "{}; {why}; drift u_j\u{2212}u_(j\u{2212}1) (u_0=0), shear: the storey's restoring force (no damping force)",
            d.subtitle
        ),
        panels: vec![p],
        columns: 1,
        plot: (620.0, 380.0),
        ..Figure::default()
    }];

    // Every inelastic storey of that building, on common axes so that the loops compare.
    let mine: Vec<&StoreyInfo> = all
        .iter()
        .filter(|i| i.building == most.building && i.ductility.is_some())
        .collect();
    if mine.len() >= 2 {
        let curves: Vec<(Vec<f64>, &Vec<f64>)> = mine
            .iter()
            .map(|i| {
                (
                    drift(d, i.building, i.storey),
                    &d.buildings[i.building].storey_shear[i.storey],
                )
            })
            .collect();
        // The range of every loop (shears with the yield forces) and a little more, so that neither a loop
        // nor a yield line lies on the frame.
        let range = |vs: &mut dyn Iterator<Item = f64>, pad: f64| {
            let (lo, hi) = vs.fold((0.0f64, 0.0f64), |(a, b), x| (a.min(x), b.max(x)));
            let pad = pad * (hi - lo);
            (lo - pad, hi + pad)
        };
        let xr = range(&mut curves.iter().flat_map(|c| c.0.iter().copied()), 0.03);
        let yr = range(
            &mut curves.iter().flat_map(|c| c.1.iter().copied()).chain(
                mine.iter()
                    .filter_map(|i| i.yield_force)
                    .flat_map(|f| [f, -f]),
            ),
            0.06,
        );
        let panels = mine
            .iter()
            .zip(curves)
            .map(|(i, (u, v))| {
                let mut p = Panel::new(storey_title(i), drift_q(), shear_q());
                p.x_range = Some(xr);
                p.y_range = Some(yr);
                p.legend = Legend::None;
                p.series.push(Series::line("", u, v.clone(), loop_style));
                if let Some(fy) = i.yield_force {
                    yield_lines(&mut p, fy, false);
                }
                p
            })
            .collect();
        figs.push(Figure {
            id: "hysteresis-storeys".into(),
            title: format!("Storey shear against drift: every inelastic storey of building {name}"),
            subtitle: format!(
                "{}; common axes; dashed: \u{b1}F_y of the storey",
                d.subtitle
            ),
            panels,
            columns: mine.len().min(4),
            plot: (260.0, 190.0),
            ..Figure::default()
        });
    }
    figs
}

/// Blues from light to dark (ColorBrewer's Blues, #9ecae1 to #08306b, in 16 steps).
const BLUES: [&str; 16] = [
    "#9ecae1", "#8dc1dd", "#7cb7da", "#6baed6", "#5da5d1", "#509bcb", "#4292c6", "#3787c0",
    "#2c7cbb", "#2171b5", "#1966ad", "#105ca4", "#08519c", "#08468c", "#083b7b", "#08306b",
];

/// Floor `f` (from 0) of `n`: blues from light (floor 1) to dark, the roof in the darkest blue and a little
/// wider, for every building height (up to 16 floors each has its own shade).
pub fn floor_style(f: usize, n: usize) -> Style {
    let k = if n <= 1 {
        BLUES.len() - 1
    } else {
        ((f as f64 / (n - 1) as f64) * (BLUES.len() - 1) as f64).round() as usize
    };
    Style {
        color: BLUES[k.min(BLUES.len() - 1)],
        width: if f + 1 == n { 2.0 } else { 1.5 },
        ..Style::nth(0)
    }
}

/// A contact level of a run: one contact element (a floor pair of a contact, or a wall's floor).
struct Level {
    /// Index of the contact in [`RunData::contacts`].
    contact: usize,
    /// Index of the element in the contact.
    element: usize,
    /// "contact west|east, floors 2-2" or "wall moat, floor 1".
    label: String,
    /// Its colour and marker shape, the same in every figure of the run.
    style: Style,
}

impl Level {
    /// Whether impact `i` happened at this level.
    fn holds(&self, d: &RunData, i: &crate::run_data::ImpactData) -> bool {
        i.contact == self.contact
            && i.floors == d.contacts[self.contact].elements[self.element].floors
    }
}

/// Every contact level of the run, contacts left to right, then walls; floor pairs in order.
fn contact_levels(d: &RunData) -> Vec<Level> {
    let mut out = Vec::new();
    for (c, cd) in d.contacts.iter().enumerate() {
        for (e, el) in cd.elements.iter().enumerate() {
            let short = if cd.wall {
                format!("floor {}", el.floors.0.max(el.floors.1))
            } else {
                format!("floors {}-{}", el.floors.0, el.floors.1)
            };
            let what = if cd.wall { "wall" } else { "contact" };
            out.push(Level {
                contact: c,
                element: e,
                label: format!("{what} {}, {short}", cd.name),
                style: Style::level(out.len()),
            });
        }
    }
    out
}

/// The plot height of one of `n` small multiples, px: the usual 250 for one, less for many.
fn multiple_height(n: usize) -> f64 {
    match n {
        0 | 1 => PLOT.1,
        2 | 3 => 170.0,
        _ => 120.0,
    }
}

/// Contact forces and relative displacements, one panel per contact level (small multiples sharing the
/// time axis), and the delivered e of every ended impact against its velocity at touch.
fn contact_figures(d: &RunData) -> (Option<Figure>, Option<Figure>, Option<Figure>) {
    let levels = contact_levels(d);
    if levels.is_empty() {
        return (None, None, None);
    }
    let (forces, closing) = level_panels(d, &levels);
    let n = levels.len();
    let force_fig = Figure {
        id: "contact-force".into(),
        title: format!(
            "Contact force at each contact level ({n} level{})",
            if n == 1 { "" } else { "s" }
        ),
        subtitle: d.subtitle.clone(),
        panels: forces,
        plot: (PLOT.0, multiple_height(n)),
        share_x: true,
        notes: vec![
            "Line: the force at the output samples with each impact's located peak inserted; markers: the \
             located peak of each impact (peak_force_N of impacts.csv). Each panel has its own force axis."
                .into(),
        ]
        .into_iter()
        .chain(
            d.impacts
                .iter()
                .any(|i| i.consumed)
                .then(|| "With a bumper, the line is the layer's and the hard law's force together and the panel's largest is their sum, as summary.json gives it; markers are each law's impacts.".to_string()),
        )
        .collect(),
        ..Figure::default()
    };
    let closing_fig = Figure {
        id: "relative-displacement".into(),
        title: "Relative displacement of the contact floors against the gap".into(),
        subtitle: d.subtitle.clone(),
        panels: closing,
        plot: (PLOT.0, multiple_height(n)),
        share_x: true,
        notes: vec![format!(
            "u_left \u{2212} u_right of each pair of contact floors (for a wall, the floor's displacement towards \
             it); dashed: the gap, contact above it{}. One axis for every level.",
            if d.summary.sites.iter().any(|s| s.bumper.is_some()) {
                "; dotted: a bumper's face, touched first"
            } else {
                ""
            }
        )],
        ..Figure::default()
    };

    (Some(force_fig), Some(closing_fig), restitution(d, &levels))
}

/// For each contact level: its force over time, and its closing against its gap (on one range for every
/// level).
fn level_panels(d: &RunData, levels: &[Level]) -> (Vec<Panel>, Vec<Panel>) {
    let t_range = (
        d.t.first().copied().unwrap_or(0.0),
        d.t.last().copied().unwrap_or(1.0),
    );
    let mut forces = Vec::new();
    let mut closing = Vec::new();
    let (mut lo, mut hi) = (0.0f64, 0.0f64);
    for lv in levels {
        let cd = &d.contacts[lv.contact];
        let el = &cd.elements[lv.element];
        let mine: Vec<_> = d.impacts.iter().filter(|i| lv.holds(d, i)).collect();
        let consumed = mine.iter().filter(|i| i.consumed).count();
        // One peak per site, as the terminal and summary.json give it (a bumper's layer and the hard law
        // behind it push together); a site of several levels: this level's own.
        let site = &d.summary.sites[lv.contact];
        let peak = if cd.elements.len() == 1 {
            site.peak_force
        } else {
            mine.iter()
                .map(|i| i.peak_force)
                .chain(el.force.iter().copied())
                .fold(0.0, f64::max)
        };
        let mut title = format!(
            "{}: {} impact{}",
            lv.label,
            mine.len() - consumed,
            if mine.len() - consumed == 1 { "" } else { "s" }
        );
        if consumed > 0 {
            title += &format!(", bumper consumed in {consumed}");
        }
        if !mine.is_empty() {
            title += &format!(", largest {}", human(peak, "N", 3));
        }
        let mut p = Panel::new(title, time(), force());
        p.x_range = Some(t_range);
        p.y_zero = true;
        p.legend = Legend::None;
        if mine.is_empty() && el.force.iter().all(|f| *f == 0.0) {
            // A level that never touched: a plain 0 to 1 MN axis, not one scaled to nothing.
            p.y_range = Some((0.0, 1.0e6));
        }
        // The samples, with each impact's located peak inserted, so the curve reaches its true peak.
        let peaks: Vec<(f64, f64)> = mine
            .iter()
            .map(|i| (i.time_of_peak_force, i.peak_force))
            .collect();
        let (t, f) = merge(&d.t, &el.force, &peaks);
        p.series.push(Series::line(&lv.label, t, f, lv.style));
        if !mine.is_empty() {
            p.series.push(Series::points(
                format!("{}: peak of each impact", lv.label),
                mine.iter().map(|i| i.time_of_peak_force).collect(),
                mine.iter().map(|i| i.peak_force).collect(),
                Style {
                    width: 1.6,
                    ..lv.style
                },
            ));
        }
        forces.push(p);

        // A wall's side does not move relative to the ground.
        let u = |b: Option<usize>, f: usize, k: usize| {
            b.map_or(0.0, |b| d.buildings[b].floors[f - 1][k])
        };
        let rel: Vec<f64> = (0..d.t.len())
            .map(|k| u(cd.left, el.floors.0, k) - u(cd.right, el.floors.1, k))
            .collect();
        for &v in rel.iter().chain([&cd.gap]) {
            (lo, hi) = (lo.min(v), hi.max(v));
        }
        // A bumper is touched before the gap closes: at the gap less its thickness.
        let face = site.bumper.as_ref().map(|b| cd.gap - b.thickness);
        let mut q = Panel::new(
            match face {
                Some(f) => format!(
                    "{}: bumper face at {} mm, gap {} mm",
                    lv.label,
                    fmt_mm(f),
                    fmt_mm(cd.gap)
                ),
                None => format!("{}: gap {} mm", lv.label, fmt_mm(cd.gap)),
            },
            time(),
            Quantity::new("u_left \u{2212} u_right", "m"),
        );
        if let Some(f) = face {
            q.series.push(Series {
                label: format!("bumper face ({} mm): contact above", fmt_mm(f)),
                mark: Mark::HLine(f),
                style: Style {
                    dash: Dash::Dotted,
                    ..Style::reference()
                },
            });
        }
        q.x_range = Some(t_range);
        q.legend = Legend::None;
        q.series
            .push(Series::line(&lv.label, d.t.clone(), rel, lv.style));
        q.series.push(Series {
            label: format!("gap ({} mm): contact above", fmt_mm(cd.gap)),
            mark: Mark::HLine(cd.gap),
            style: Style::reference(),
        });
        closing.push(q);
    }
    // One range for every level: the gap line at one height, and the levels compare at a glance.
    let pad = 0.04 * (hi - lo);
    for q in &mut closing {
        q.y_range = Some((lo - pad, hi + pad));
    }
    (forces, closing)
}

/// The delivered e of each ended impact against its impact velocity, one colour and shape per level, with
/// the e each contact was asked for.
fn restitution(d: &RunData, levels: &[Level]) -> Option<Figure> {
    let mut r = Panel::new(
        "",
        Quantity::new("relative velocity at touch v_i", "m/s"),
        Quantity::new("delivered e (e_post)", ""),
    );
    r.y_zero = true;
    r.x_zero = true;
    r.legend = Legend::Right;
    let (mut above, mut ended, mut top) = (0, 0, f64::NEG_INFINITY);
    for lv in levels {
        let cd = &d.contacts[lv.contact];
        // Impacts on the site's face (a bumper's layer, or the law itself); the hard law behind a consumed
        // bumper acts within such an impact and is not one.
        let mine: Vec<_> = d
            .impacts
            .iter()
            .filter(|i| lv.holds(d, i) && i.e_post.is_some() && !i.consumed)
            .collect();
        if mine.is_empty() {
            continue;
        }
        // The face's law asks its own e: a bumper's, else the site's.
        let asked = match &d.summary.sites[lv.contact].bumper {
            Some(b) => b.law.e,
            None => cd.e,
        };
        for e in mine.iter().filter_map(|i| i.e_post) {
            ended += 1;
            above += usize::from(e > asked.unwrap_or(1.0) * (1.0 + 1e-9));
            top = top.max(e);
        }
        r.series.push(Series::points(
            &lv.label,
            mine.iter().map(|i| i.v_i).collect(),
            mine.iter().filter_map(|i| i.e_post).collect(),
            Style {
                width: 1.8,
                ..lv.style
            },
        ));
    }
    // The requested e of each contact (one line for contacts given the same e).
    let mut given: Vec<(f64, Vec<String>)> = Vec::new();
    // An elastic contact asks none (it delivers 1); a bumper asks its own.
    for (cd, site) in d.contacts.iter().zip(&d.summary.sites) {
        let asked = match &site.bumper {
            Some(b) => (b.law.e, format!("{} bumper", cd.name)),
            None => (cd.e, cd.name.clone()),
        };
        let (Some(e), name) = asked else { continue };
        match given.iter_mut().find(|g| g.0 == e) {
            Some(g) => g.1.push(name),
            None => given.push((e, vec![name])),
        }
    }
    let several = given.len() > 1;
    for (k, (e, names)) in given.iter().enumerate() {
        r.series.push(Series {
            label: if several {
                format!("requested e = {} ({})", fmt_num(*e), names.join(", "))
            } else {
                format!("requested e = {}", fmt_num(*e))
            },
            mark: Mark::HLine(*e),
            // Two contacts given different e: dashes, then dots.
            style: Style {
                width: 1.4,
                dash: [Dash::Dashed, Dash::Dotted][k % 2],
                ..Style::reference()
            },
        });
    }
    (ended > 0).then(|| {
        let mut notes = Vec::new();
        if above > 0 {
            notes.push(format!(
                "{above} of {ended} impacts lie above the requested e{}: each contact law is calibrated to \
                 deliver e between two free bodies, but the storey forces act on the floors during a contact \
                 between buildings (docs/verification.md, \"Impacts inside a run\").{}",
                if top > 1.0 {
                    format!(" (up to {})", fmt_sig(top, 4))
                } else {
                    String::new()
                },
                if top > 1.0 {
                    " Above 1, the storeys pushed the floors apart during the contact."
                } else {
                    ""
                }
            ));
        }
        Figure {
            id: "impact-restitution".into(),
            title: "Delivered coefficient of restitution of each impact, by contact level".into(),
            subtitle: d.subtitle.clone(),
            panels: vec![r],
            notes,
            ..Figure::default()
        }
    })
}

/// The force–penetration loops of the strongest impacts (at most [`LOOPS_PER_LEVEL`]) of each contact level,
/// from impact-loops.csv (none for a folder without it).
fn impact_loops(d: &RunData) -> Option<Figure> {
    let levels = contact_levels(d);
    let mut panels = Vec::new();
    for lv in &levels {
        let mut mine: Vec<_> = d
            .loops
            .iter()
            .filter(|l| lv.holds(d, &d.impacts[l.impact]))
            .collect();
        if mine.is_empty() {
            continue;
        }
        let total = mine.len();
        let hard = mine.iter().filter(|l| d.impacts[l.impact].consumed).count();
        mine.sort_by(|a, b| {
            d.impacts[b.impact]
                .peak_force
                .total_cmp(&d.impacts[a.impact].peak_force)
        });
        mine.truncate(LOOPS_PER_LEVEL);
        let mut p = Panel::new(
            if hard > 0 {
                // Loops of the impacts on the bumper and of the hard law behind it when it was consumed.
                format!(
                    "{}: top {} of {total} ({hard} consumed)",
                    lv.label,
                    mine.len()
                )
            } else if total > mine.len() {
                format!("{}: strongest {} of {total} impacts", lv.label, mine.len())
            } else {
                format!(
                    "{}: {total} impact{}",
                    lv.label,
                    if total == 1 { "" } else { "s" }
                )
            },
            Quantity::new("penetration", "m"),
            force(),
        );
        p.x_zero = true;
        p.y_zero = true;
        for (rank, l) in mine.iter().enumerate() {
            let i = &d.impacts[l.impact];
            let dash = [Dash::Solid, Dash::Dashed, Dash::Dotted][rank % 3];
            let st = Style {
                dash,
                width: 1.5,
                ..lv.style
            };
            p.series.push(Series::line(
                format!(
                    "#{} at {} s: {}",
                    l.impact + 1,
                    fmt_sig(i.time, 4),
                    human(i.peak_force, "N", 3)
                ),
                l.penetration.clone(),
                l.force.clone(),
                st,
            ));
        }
        // The located peaks.
        let peak_of = |l: &&crate::run_data::LoopData| {
            let k = (0..l.force.len())
                .max_by(|&a, &b| l.force[a].total_cmp(&l.force[b]))
                .unwrap_or(0);
            (l.penetration[k], l.force[k])
        };
        let pk: Vec<(f64, f64)> = mine.iter().map(peak_of).collect();
        p.series.push(Series::points(
            "",
            pk.iter().map(|p| p.0).collect(),
            pk.iter().map(|p| p.1).collect(),
            Style {
                width: 1.6,
                ..lv.style
            },
        ));
        panels.push(p);
    }
    if panels.is_empty() {
        return None;
    }
    let columns = panels.len().min(2);
    Some(Figure {
        id: "impact-loops".into(),
        title: "Force against penetration of the strongest impacts, by contact level".into(),
        subtitle: d.subtitle.clone(),
        columns,
        plot: (340.0, 220.0),
        panels,
        notes: std::iter::once(
            "Every accepted integration step of each impact and its located peak (marker), from \
             impact-loops.csv; the area inside a loop is the energy the impact dissipated. Legend: impact \
             number in impacts.csv, time of touch, peak force."
                .to_string(),
        )
        .chain(d.impacts.iter().any(|i| i.consumed).then(|| {
            "With a bumper, \"consumed\" counts the loops of the hard law behind it once the layer was \
             consumed: each within an impact on the bumper, not an impact of its own."
                .to_string()
        }))
        .collect(),
        ..Figure::default()
    })
}

/// Impacts drawn per contact level in `impact-loops.svg`.
pub const LOOPS_PER_LEVEL: usize = 3;

/// The record as the run applied it: ground acceleration at the output samples, and the velocity and
/// displacement integrated from them (from rest, exact for a piecewise-linear acceleration between samples).
fn record(d: &RunData) -> Figure {
    let (t, a) = (&d.t, &d.ground_acceleration);
    let mut v = vec![0.0; t.len()];
    let mut u = vec![0.0; t.len()];
    for k in 1..t.len() {
        let h = t[k] - t[k - 1];
        v[k] = v[k - 1] + (a[k - 1] + a[k]) / 2.0 * h;
        u[k] = u[k - 1] + v[k - 1] * h + (2.0 * a[k - 1] + a[k]) * h * h / 6.0;
    }
    let t_range = (
        t.first().copied().unwrap_or(0.0),
        t.last().copied().unwrap_or(1.0),
    );
    let peak = |y: &[f64]| {
        (0..y.len())
            .max_by(|&i, &j| y[i].abs().total_cmp(&y[j].abs()))
            .map_or((0.0, 0.0), |k| (t[k], y[k]))
    };
    // One panel per quantity, titled with its largest |value| and when.
    let panel = |what: &'static str, unit: &'static str, y: Vec<f64>| {
        let (tp, yp) = peak(&y);
        let title = format!(
            "ground {what}: largest {} at {} s",
            human(yp.abs(), unit, 3),
            fmt_sig(tp, 4)
        );
        let mut p = Panel::new(title, Quantity::new("time", "s"), Quantity::new(what, unit));
        p.x_range = Some(t_range);
        p.legend = Legend::None;
        p.series.push(Series::line(
            "",
            t.clone(),
            y,
            Style {
                width: 1.0,
                ..Style::nth(6)
            },
        ));
        p.series.push(Series::points(
            "largest |value|",
            vec![tp],
            vec![yp],
            Style {
                width: 1.8,
                ..Style::nth(1)
            },
        ));
        p
    };
    Figure {
        id: "record".into(),
        title: "Ground motion as the run applied it: acceleration, velocity, displacement".into(),
        subtitle: d.subtitle.clone(),
        panels: vec![
            panel("acceleration", "m/s\u{b2}", a.clone()),
            panel("velocity", "m/s", v),
            panel("displacement", "m", u),
        ],
        plot: (PLOT.0, 140.0),
        share_x: true,
        notes: vec![format!(
            "The acceleration at the output samples (every {} s); velocity and displacement integrated from \
             them from rest, without baseline correction: the ground motion the analysis applied. Dots: largest \
             |value|.",
            fmt_num(d.summary.output_dt)
        )],
        ..Figure::default()
    }
}

/// Gap in mm for a label, without trailing zeros.
fn fmt_mm(gap: f64) -> String {
    crate::output::fmt_num((gap * 1e3 * 1e6).round() / 1e6)
}

/// `(t, f)` with the points `extra` inserted in time order.
fn merge(t: &[f64], f: &[f64], extra: &[(f64, f64)]) -> (Vec<f64>, Vec<f64>) {
    let mut extra = extra.to_vec();
    extra.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut out_t = Vec::with_capacity(t.len() + extra.len());
    let mut out_f = Vec::with_capacity(t.len() + extra.len());
    let mut k = 0;
    for (&ti, &fi) in t.iter().zip(f) {
        while k < extra.len() && extra[k].0 < ti {
            out_t.push(extra[k].0);
            out_f.push(extra[k].1);
            k += 1;
        }
        out_t.push(ti);
        out_f.push(fi);
    }
    for &(te, fe) in &extra[k..] {
        out_t.push(te);
        out_f.push(fe);
    }
    (out_t, out_f)
}

/// A value in its display unit, 4 significant digits: "2.5 MN", "186.6 kJ", "1.27 mm".
fn human_si(v: f64, unit: &str) -> String {
    human(v, unit, 4)
}

#[cfg(test)]
mod tests {
    #[test]
    fn merged_points_keep_time_order() {
        let (t, f) = super::merge(
            &[0.0, 1.0, 2.0],
            &[0.0, 0.0, 0.0],
            &[(1.5, 9.0), (0.5, 7.0)],
        );
        assert_eq!(t, [0.0, 0.5, 1.0, 1.5, 2.0]);
        assert_eq!(f, [0.0, 7.0, 0.0, 9.0, 0.0]);
    }
}
