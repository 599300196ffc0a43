//! Storey and isolator loops: shear against drift.

use super::common::human_si;
use crate::output::fmt_sig;
use crate::plot::{Figure, Legend, Mark, Panel, Quantity, Series, Style};
use crate::run_data::RunData;

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
pub fn isolators(d: &RunData) -> Option<Figure> {
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
pub fn hysteresis(d: &RunData) -> Vec<Figure> {
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
