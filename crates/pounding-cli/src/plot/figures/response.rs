//! The structures' response: the record as applied, floor displacements, peak response over height, device
//! forces, the energy balance.

use super::common::{floor_style, time};
use crate::output::{fmt_num, fmt_sig};
use crate::plot::axis::human;
use crate::plot::{Figure, Legend, Mark, Panel, Quantity, Series, Style, PLOT};
use crate::run_data::RunData;
use pounding::structure::Form;
use pounding_study::summary::inside::hysteresis_of;

/// The ground motion, and each building's floor displacements with the instants of its impacts.
pub fn displacement(d: &RunData) -> Figure {
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
        let form = d.summary.buildings[b].form();
        let mut p = Panel::new(
            match form {
                Form::Deck => format!("deck {}: displacement relative to the ground", bd.name),
                _ => format!(
                    "building {}: floor displacements relative to the ground",
                    bd.name
                ),
            },
            time(),
            Quantity::new("displacement", "m"),
        );
        p.x_tight = true;
        let n = bd.floors.len();
        for (f, u) in bd.floors.iter().enumerate() {
            let label = match (form, f) {
                (Form::Deck, _) => "deck".to_string(),
                _ if f + 1 == n && n > 1 => format!("floor {} (roof)", f + 1),
                (Form::IsolatedBuilding, 0) => "floor 1 (base slab)".to_string(),
                _ => format!("floor {}", f + 1),
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
        title: {
            let decks = d
                .summary
                .buildings
                .iter()
                .filter(|b| b.form() == Form::Deck);
            match (decks.count(), d.buildings.len()) {
                (0, _) => "Floor displacements",
                (k, n) if k == n => "Deck displacements",
                _ => "Floor and deck displacements",
            }
        }
        .into(),
        subtitle: d.subtitle.clone(),
        panels,
        columns: 1,
        plot: PLOT,
        ..Figure::default()
    }
}

/// The forces of the devices, if there are any.
pub fn devices(d: &RunData) -> Option<Figure> {
    if d.devices.is_empty() {
        return None;
    }
    let panels = d
        .devices
        .iter()
        .zip(&d.summary.devices)
        .map(|(dd, ds)| {
            // One floor pair needs no legend: the title says what it joins.
            let one = dd.elements.len() == 1;
            // A side's floor, where it has more than one (a wall or a deck has not).
            let side = |name: &str, floor: usize| {
                let many = d
                    .buildings
                    .iter()
                    .any(|b| b.name == name && b.floors.len() > 1);
                match (one && many, floor) {
                    (true, f) => format!("{name} floor {f}"),
                    _ => name.to_string(),
                }
            };
            let el = dd.elements.first().map_or((0, 0), |e| e.floors);
            let joins = format!(
                ", {} to {}",
                side(&ds.between[0], el.0),
                side(&ds.between[1], el.1)
            );
            let mut p = Panel::new(
                format!("device {} ({}{joins})", dd.name, dd.model),
                time(),
                Quantity::new("force, positive pushing apart", "N"),
            );
            p.x_tight = true;
            for (k, el) in dd.elements.iter().enumerate() {
                p.series.push(Series::line(
                    if one {
                        String::new()
                    } else {
                        format!("floors {}-{}", el.floors.0, el.floors.1)
                    },
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
pub fn energy(d: &RunData) -> Figure {
    let mut energy = Panel::new("", time(), Quantity::new("energy", "J"));
    let mut hysteretic = false;
    energy.x_tight = true;
    energy.y_zero = true;
    energy.legend = Legend::Right;
    // What yields: storeys, isolators, a bridge's bearings.
    let what = hysteresis_of(&d.summary.buildings);
    let by_hysteresis = format!("dissipated by {what} hysteresis");
    let names = [
        "input (ground motion)",
        "kinetic",
        "strain",
        "dissipated by structural damping",
        &by_hysteresis,
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
        if *name == by_hysteresis {
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
            format!(
                "Energy balance: input = kinetic + strain + structural damping + {what} hysteresis + contact"
            )
        } else {
            "Energy balance: input = kinetic + strain + structural damping + contact".into()
        },
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

/// Peak response over height, one line per building (decks have no height: none for them), four panels side
/// by side: floor displacement and absolute acceleration at the floors (0 and the record's PGA at the
/// ground), storey drift ratio (storeys above any isolator) and storey shear as steps over each storey's
/// height.
pub fn envelopes(d: &RunData) -> Option<Figure> {
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
    let mut isolated = false;
    for (b, bd) in d.buildings.iter().enumerate() {
        let s = &d.summary.buildings[b];
        match s.form() {
            Form::Deck => continue,
            Form::IsolatedBuilding => isolated = true,
            Form::Building => {}
        }
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
        // An isolator's drift over its height is no drift ratio: the storeys above it only.
        let ratio: Vec<f64> = s
            .structural_drift_ratios()
            .iter()
            .map(|r| 100.0 * r)
            .collect();
        let (x, y) = steps(&ratio, &z[z.len() - 1 - ratio.len()..]);
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
    if disp.series.is_empty() {
        return None;
    }
    disp.legend = Legend::Inside;
    Some(Figure {
        id: "envelopes".into(),
        title: "Peak response over height".into(),
        subtitle: format!(
            "{}; floor values as dots at the floors (at the ground: 0 and the record's PGA), storey values as steps over each storey{}",
            d.subtitle,
            if isolated {
                "; drift ratio above the isolator (its displacement: isolators.svg), shear of the isolator included"
            } else {
                ""
            }
        ),
        panels: vec![disp, drift, acc, shear],
        columns: 4,
        plot: (240.0, 360.0),
        ..Figure::default()
    })
}

/// The record as the run applied it: ground acceleration at the output samples, and the velocity and
/// displacement integrated from them (from rest, exact for a piecewise-linear acceleration between samples).
pub fn record(d: &RunData) -> Figure {
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
