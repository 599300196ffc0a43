//! Storey and isolator loops: shear against drift.

use super::common::human_si;
use crate::output::fmt_sig;
use crate::plot::{Figure, Legend, Mark, Panel, Quantity, Series, Style};
use crate::run_data::RunData;
use pounding::structure::Form;

/// One storey's identity and numbers from summary.json: building, storey (from 0), model, yield force
/// (inelastic storeys), ductility and hysteretic energy. An isolator (storey 1 of an isolated building) has
/// its own figure and is not among them.
struct StoreyInfo {
    building: usize,
    storey: usize,
    model: String,
    yield_force: Option<f64>,
    ductility: Option<f64>,
    hysteretic_energy: Option<f64>,
}

/// The storeys of building `b` above any isolator, from summary.json.
fn storey_info(d: &RunData, b: usize) -> Vec<StoreyInfo> {
    let s = &d.summary.buildings[b];
    let n = d.buildings[b].storey_shear.len();
    let inelastic = &s.inelastic_storeys;
    let (fy, mu, eh) = (&s.yield_forces, &s.ductility, &s.hysteretic_energy);
    (usize::from(s.isolator.is_some())..n)
        .map(|j| {
            let k = inelastic.iter().position(|&i| i == j + 1);
            let pick = |v: &[f64]| k.and_then(|k| v.get(k).copied()).filter(|x| x.is_finite());
            StoreyInfo {
                building: b,
                storey: j,
                model: s.storey_models[j].name().to_string(),
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

/// The loop of every isolator (a deck's bearings): its force against its displacement (storey 1 of the
/// files), with its clearance.
pub fn isolators(d: &RunData) -> Option<Figure> {
    let forms: Vec<Form> = d
        .summary
        .buildings
        .iter()
        .filter(|b| b.isolator.is_some())
        .map(|b| b.form())
        .collect();
    let decks = forms.iter().filter(|f| **f == Form::Deck).count();
    // The words of what is drawn: isolators, bearings, or both.
    let (what, thing, under) = match (decks, forms.len() - decks) {
        (0, _) => ("Isolator", "isolator", "the base slab"),
        (_, 0) => ("Bearing", "bearing", "the deck"),
        _ => ("Isolator and bearing", "isolator", "the base slab or deck"),
    };
    let panels: Vec<Panel> = (0..d.buildings.len())
        .filter_map(|b| isolator_panel(d, b, thing))
        .collect();
    (!panels.is_empty()).then(|| Figure {
        id: "isolators".into(),
        title: format!("{what} force against displacement"),
        subtitle: format!(
            "{}; displacement of {under} relative to the ground; force: the {thing}'s restoring force",
            d.subtitle
        ),
        panels,
        columns: 1,
        plot: (620.0, 380.0),
        ..Figure::default()
    })
}

/// The loop of building `b`'s isolator, if it has one, on axes named after `thing`.
fn isolator_panel(d: &RunData, b: usize, thing: &str) -> Option<Panel> {
    let s = &d.summary.buildings[b];
    let iso = s.isolator.as_ref()?;
    let u = drift(d, b, 0);
    let f = d.buildings[b].storey_shear[0].clone();
    let mut p = Panel::new(
        format!(
            "{} {}: {} {}, peak displacement {}",
            s.form().noun(),
            s.name,
            iso.model.name(),
            s.form().isolator_noun(),
            human_si(iso.peak_displacement, "m")
        ),
        Quantity::new(format!("{thing} displacement"), "m"),
        Quantity::new(format!("{thing} force"), "N"),
    );
    p.x_zero = true;
    p.y_zero = true;
    let top = f.iter().fold(0.0f64, |a, x| a.max(x.abs()));
    p.series.push(Series::line("", u, f, loop_style()));
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
}

fn drift_q() -> Quantity {
    Quantity::new("storey drift", "m")
}

fn shear_q() -> Quantity {
    Quantity::new("storey shear", "N")
}

/// The style of a storey's loop.
fn loop_style() -> Style {
    Style {
        width: 1.2,
        ..Style::nth(0)
    }
}

/// The force-drift loop of the most strained storey (the largest ductility over every building, or, with
/// no inelastic storey, the largest peak drift ratio), and, when more than one storey yields, the loops of
/// every inelastic storey of every building. Isolators are in [`isolators`]; a run of decks has no storeys.
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
    let mut figs = vec![most_strained(d, most)];
    let yielding: Vec<&StoreyInfo> = all.iter().filter(|i| i.ductility.is_some()).collect();
    if yielding.len() >= 2 {
        figs.push(every_yielding(d, &yielding));
    }
    figs
}

/// Where the isolators' (and bearings') loops are, for the storey loop's note: "the isolator of building
/// isolated (bouc-wen, ductility 7.46) has its loop in isolators.svg"; `None` without isolators.
fn isolator_loops(d: &RunData) -> Option<String> {
    let isolators: Vec<String> = d
        .summary
        .buildings
        .iter()
        .filter_map(|b| {
            let iso = b.isolator.as_ref()?;
            let form = b.form();
            // An inelastic isolator is storey 1 of the inelastic storeys, its ductility the first.
            let mu = (b.inelastic_storeys.first() == Some(&1))
                .then(|| b.ductility.first().copied())
                .flatten()
                .map_or(String::new(), |mu| {
                    format!(", ductility {}", fmt_sig(mu, 3))
                });
            Some(format!(
                "the {} of {} {} ({}{mu})",
                form.isolator_noun(),
                form.noun(),
                b.name,
                iso.model.name()
            ))
        })
        .collect();
    match isolators.len() {
        0 => None,
        1 => Some(format!(
            "{} has its loop in its own figure, isolators.svg",
            isolators[0]
        )),
        _ => Some(format!(
            "{} have their loops in their own figure, isolators.svg",
            isolators.join(", ")
        )),
    }
}

/// The loop of storey `most`, with its yield lines and the end of the analysis marked.
fn most_strained(d: &RunData, most: &StoreyInfo) -> Figure {
    let name = &d.buildings[most.building].name;
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
            .push(Series::line("", u.clone(), v.clone(), loop_style()));
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
    let isolated = d
        .summary
        .buildings
        .iter()
        .filter(|b| b.isolator.is_some())
        .count();
    let mut why = match (most.ductility.is_some(), isolated) {
        (true, _) => "the largest ductility of the run".to_string(),
        (false, 0) => "no inelastic storey; the largest peak drift ratio of the run".to_string(),
        (false, n) => format!(
            "every storey above the {} is linear: the storey of the largest peak drift ratio",
            if n == 1 { "isolator" } else { "isolators" }
        ),
    };
    if let Some(elsewhere) = isolator_loops(d) {
        why = format!("{why}; {elsewhere}");
    }
    Figure {
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
    }
}

/// The loop of every inelastic storey, one row per building, on axes common to the building's storeys so
/// that its loops compare (buildings differ too much for one range).
fn every_yielding(d: &RunData, yielding: &[&StoreyInfo]) -> Figure {
    let buildings: Vec<usize> = {
        let mut b: Vec<usize> = yielding.iter().map(|i| i.building).collect();
        b.dedup();
        b
    };
    let one = buildings.len() == 1;
    let mut panels = Vec::new();
    for &b in &buildings {
        let mine: Vec<&&StoreyInfo> = yielding.iter().filter(|i| i.building == b).collect();
        let curves: Vec<(Vec<f64>, &Vec<f64>)> = mine
            .iter()
            .map(|i| {
                (
                    drift(d, b, i.storey),
                    &d.buildings[b].storey_shear[i.storey],
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
        for (k, (i, (u, v))) in mine.iter().zip(curves).enumerate() {
            // Small panels: the ductility as μ, the building's name when there are several.
            let short = format!(
                "storey {}: {}, \u{3bc} {}",
                i.storey + 1,
                i.model,
                fmt_sig(i.ductility.unwrap_or(0.0), 3)
            );
            let title = if one {
                short
            } else {
                format!("{}, {short}", d.buildings[b].name)
            };
            let mut p = Panel::new(title, drift_q(), shear_q());
            p.x_range = Some(xr);
            p.y_range = Some(yr);
            p.legend = Legend::None;
            p.new_row = k == 0;
            p.series.push(Series::line("", u, v.clone(), loop_style()));
            if let Some(fy) = i.yield_force {
                yield_lines(&mut p, fy, false);
            }
            panels.push(p);
        }
    }
    let widest = buildings
        .iter()
        .map(|&b| yielding.iter().filter(|i| i.building == b).count())
        .max()
        .unwrap_or(1);
    Figure {
        id: "hysteresis-storeys".into(),
        title: if one {
            format!(
                "Storey shear against drift: every inelastic storey of building {}",
                d.buildings[buildings[0]].name
            )
        } else {
            "Storey shear against drift: every inelastic storey, one row per building".into()
        },
        subtitle: format!(
            "{}; \u{3bc}: ductility; axes common to a building's storeys; dashed: \u{b1}F_y of the storey",
            d.subtitle
        ),
        panels,
        columns: widest.min(4),
        plot: (260.0, 190.0),
        ..Figure::default()
    }
}
