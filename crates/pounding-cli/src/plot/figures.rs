//! The tool's figures: one impact (force against time and against penetration), several models on one
//! impact, the seed's Table 1 as curves, and the four figures of a pounding run.

use super::{Figure, Legend, Mark, Panel, Quantity, Series, Style};
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
        },
        Figure {
            id: format!("{prefix}-force-penetration"),
            title: format!("{title}: force against penetration"),
            subtitle: subtitle.into(),
            panels: vec![loop_],
            columns: 1,
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

/// The seed's Table 1 as curves, in two groups (the seed's models; the other damped models): delivered
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
        },
        Figure {
            id: "table1-error".into(),
            title: "Error in the coefficient of restitution (seed's Table 1)".into(),
            subtitle: format!(
                "{subtitle}; errors below 0.001 % (calibrated models: about 1e\u{2212}10 %) lie under the axis"
            ),
            panels: error,
            columns: 1,
        },
    ]
}

/// The four figures of a pounding run: floor displacements with impact instants, contact forces,
/// relative displacement against the gap, and the energy balance.
pub fn run(d: &RunData) -> Vec<Figure> {
    let time = || Quantity::new("time", "s");
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
    let mut displacement = vec![ground];
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
            .filter(|i| d.contacts[i.contact].left == b || d.contacts[i.contact].right == b)
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
        displacement.push(p);
    }

    let mut forces = Vec::new();
    let mut closing = Vec::new();
    for (c, cd) in d.contacts.iter().enumerate() {
        let mine: Vec<_> = d.impacts.iter().filter(|i| i.contact == c).collect();
        let mut p = Panel::new(
            format!("contact {}: {} impacts", cd.name, mine.len()),
            time(),
            force(),
        );
        p.x_tight = true;
        p.y_zero = true;
        let mut q = Panel::new(
            format!("contact {}: closing of the gap", cd.name),
            time(),
            Quantity::new("relative displacement u_left \u{2212} u_right", "m"),
        );
        q.x_tight = true;
        for (k, el) in cd.elements.iter().enumerate() {
            let label = format!("floors {}-{}", el.floors.0, el.floors.1);
            // The samples, with each impact's located peak inserted, so the curve reaches its true peak.
            let peaks: Vec<(f64, f64)> = mine
                .iter()
                .filter(|i| i.floors == el.floors)
                .map(|i| (i.time_of_peak_force, i.peak_force))
                .collect();
            let (t, f) = merge(&d.t, &el.force, &peaks);
            p.series.push(Series::line(&label, t, f, Style::nth(k)));
            let ul = &d.buildings[cd.left].floors[el.floors.0 - 1];
            let ur = &d.buildings[cd.right].floors[el.floors.1 - 1];
            let rel = ul.iter().zip(ur).map(|(a, b)| a - b).collect();
            q.series
                .push(Series::line(&label, d.t.clone(), rel, Style::nth(k)));
        }
        if !mine.is_empty() {
            p.series.push(Series::points(
                "peak of each impact",
                mine.iter().map(|i| i.time_of_peak_force).collect(),
                mine.iter().map(|i| i.peak_force).collect(),
                Style {
                    width: 1.4,
                    ..Style::nth(1)
                },
            ));
        }
        q.series.push(Series {
            label: format!("gap ({} mm): contact above", fmt_mm(cd.gap)),
            mark: Mark::HLine(cd.gap),
            style: Style::reference(),
        });
        forces.push(p);
        closing.push(q);
    }

    // Delivered e of each ended impact against its impact velocity, with the e each contact was given.
    let mut restitution = Panel::new(
        "",
        Quantity::new("relative velocity at touch v_i", "m/s"),
        Quantity::new("delivered e (e_post)", ""),
    );
    restitution.y_zero = true;
    for (c, cd) in d.contacts.iter().enumerate() {
        let ended: Vec<_> = d
            .impacts
            .iter()
            .filter(|i| i.contact == c && i.e_post.is_some())
            .collect();
        restitution.series.push(Series::points(
            format!("contact {}", cd.name),
            ended.iter().map(|i| i.v_i).collect(),
            ended.iter().filter_map(|i| i.e_post).collect(),
            Style {
                width: 1.6,
                ..Style::nth(c)
            },
        ));
        restitution.series.push(Series {
            label: format!("e given to {}: {}", cd.name, crate::output::fmt_num(cd.e)),
            mark: Mark::HLine(cd.e),
            style: Style {
                width: 1.2,
                dash: super::Dash::Dashed,
                ..Style::nth(c)
            },
        });
    }

    let mut energy = Panel::new("", time(), Quantity::new("energy", "J"));
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
        if name.contains("hysteresis") && e.iter().all(|x| *x == 0.0) {
            continue;
        }
        energy
            .series
            .push(Series::line(*name, d.t.clone(), e.clone(), st));
    }

    let mut figs = vec![Figure {
        id: "displacement".into(),
        title: "Floor displacements".into(),
        subtitle: d.subtitle.clone(),
        panels: displacement,
        columns: 1,
    }];
    if !d.contacts.is_empty() {
        figs.push(Figure {
            id: "contact-force".into(),
            title: "Contact forces".into(),
            subtitle: d.subtitle.clone(),
            panels: forces,
            columns: 1,
        });
        if d.impacts.iter().any(|i| i.e_post.is_some()) {
            figs.push(Figure {
                id: "impact-restitution".into(),
                title: "Delivered coefficient of restitution of each impact".into(),
                subtitle: d.subtitle.clone(),
                panels: vec![restitution],
                columns: 1,
            });
        }
        figs.push(Figure {
            id: "relative-displacement".into(),
            title: "Relative displacement of the contact floors against the gap".into(),
            subtitle: d.subtitle.clone(),
            panels: closing,
            columns: 1,
        });
    }
    figs.push(Figure {
        id: "energy".into(),
        title: "Energy balance: input = kinetic + strain + structural damping + contact".into(),
        subtitle: d.subtitle.clone(),
        panels: vec![energy],
        columns: 1,
    });
    figs
}

/// Floors from light to dark up the building, the roof in the darkest blue.
fn floor_style(f: usize, n: usize) -> Style {
    if n <= 3 {
        return Style::nth(f);
    }
    const RAMP: [&str; 8] = [
        "#9ecae1", "#6baed6", "#4292c6", "#2171b5", "#08519c", "#08306b", "#041f4a", "#000000",
    ];
    let k = ((f as f64 / (n - 1) as f64) * (RAMP.len() - 1) as f64).round() as usize;
    Style {
        color: RAMP[k.min(RAMP.len() - 1)],
        ..Style::nth(0)
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
