//! Figures of single impacts: force against time and against penetration of one or more impacts, and
//! Table 1 of Papi & Toopchi-Nezhad (2022) as curves.

use super::common::force;
use crate::plot::{Figure, Legend, Panel, Quantity, Series, Style, PLOT};

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
