//! Buildings in plan: the site's plan with each building's rectangle, mass centres, lines and contact points
//! (with their impacts), and the orbit of the corner that moved most of each building's top floor.

use crate::output::fmt_num;
use crate::plot::{Dash, Figure, Legend, Panel, Quantity, Series, Shape, Style};
use crate::run_data::RunData;
use pounding::structure::LineDirection;
use pounding_study::summary::{BuildingSummary, PlanSummary, SitePlace};

/// Ranges of `x` and `y` data that keep one metre the same length along both axes of a `plot` (px), with a
/// margin of a tenth around the data.
fn to_scale(
    (x0, x1): (f64, f64),
    (y0, y1): (f64, f64),
    plot: (f64, f64),
) -> ((f64, f64), (f64, f64)) {
    let (dx, dy) = ((x1 - x0).max(1e-9), (y1 - y0).max(1e-9));
    let per_px = (1.2 * dx / plot.0).max(1.2 * dy / plot.1);
    let (cx, cy) = ((x0 + x1) / 2.0, (y0 + y1) / 2.0);
    let (hx, hy) = (per_px * plot.0 / 2.0, per_px * plot.1 / 2.0);
    ((cx - hx, cx + hx), (cy - hy, cy + hy))
}

/// The buildings in plan, with their summaries.
fn planned(d: &RunData) -> Vec<(usize, &BuildingSummary, &PlanSummary)> {
    d.summary
        .buildings
        .iter()
        .enumerate()
        .filter_map(|(b, s)| s.plan.as_ref().map(|p| (b, s, p)))
        .collect()
}

/// The plan of the site: every building in plan, its mass centres, its lines, and each contact point with the
/// impacts it took; `None` without a building in plan.
pub fn plan_view(d: &RunData) -> Option<Figure> {
    let plans = planned(d);
    if plans.is_empty() {
        return None;
    }
    let plot = (620.0, 420.0);
    let mut p = Panel::new(
        "plan at rest: outlines, mass centres, load-resisting lines (dashed), contact points",
        Quantity::new("x", "m").shown_in(0),
        Quantity::new("y", "m").shown_in(0),
    );
    p.legend = Legend::Right;
    let (mut xs, mut ys) = (Vec::new(), Vec::new());
    for (k, (_, bs, ps)) in plans.iter().enumerate() {
        let ([x0, y0], [a, b]) = (ps.position, ps.size);
        let st = Style {
            width: 2.0,
            ..Style::nth(k)
        };
        p.series.push(Series::line(
            bs.name.clone(),
            vec![x0, x0 + a, x0 + a, x0, x0],
            vec![y0, y0, y0 + b, y0 + b, y0],
            st,
        ));
        xs.extend([x0, x0 + a]);
        ys.extend([y0, y0 + b]);
        let (cx, cy): (Vec<f64>, Vec<f64>) = ps
            .mass_centres
            .iter()
            .map(|c| (x0 + c[0], y0 + c[1]))
            .unzip();
        p.series.push(Series::points(
            format!("{}: mass centre", bs.name),
            cx,
            cy,
            Style {
                width: 4.0,
                shape: Shape::Diamond,
                ..Style::nth(k)
            },
        ));
        for l in &ps.lines {
            let (x, y) = match l.direction {
                LineDirection::X => (vec![x0, x0 + a], vec![y0 + l.at; 2]),
                LineDirection::Y => (vec![x0 + l.at; 2], vec![y0, y0 + b]),
            };
            p.series.push(Series::line(
                "",
                x,
                y,
                Style {
                    width: 1.0,
                    dash: Dash::Dashed,
                    ..Style::nth(k)
                },
            ));
        }
    }
    for (si, site) in d.summary.sites.iter().enumerate() {
        let Some(points) = &site.points else { continue };
        // Each point once (the floor pairs share it), with the impacts it took over every floor.
        let mut seen: Vec<[f64; 2]> = Vec::new();
        for (level, pt) in points.iter().enumerate() {
            if seen.contains(pt) {
                continue;
            }
            seen.push(*pt);
            let impacts = d
                .impacts
                .iter()
                .filter(|i| i.contact == si && points[i.level] == *pt)
                .count();
            let what = match &site.place {
                SitePlace::Contact { .. } => format!("contact {}", site.name),
                SitePlace::Wall { .. } => format!("wall {}", site.name),
            };
            p.series.push(Series::points(
                format!(
                    "{what} at ({}, {}): {} impacts",
                    fmt_num(pt[0]),
                    fmt_num(pt[1]),
                    impacts
                ),
                vec![pt[0]],
                vec![pt[1]],
                // Dark, in the level's shape: not mistaken for a building's colour.
                Style {
                    width: 5.0,
                    color: crate::plot::PALETTE[6],
                    shape: Style::level(seen.len() - 1).shape,
                    ..Style::level(level)
                },
            ));
        }
    }
    let range = |v: &[f64]| {
        v.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |r, &x| {
            (r.0.min(x), r.1.max(x))
        })
    };
    let (xr, yr) = to_scale(range(&xs), range(&ys), plot);
    p.x_range = Some(xr);
    p.y_range = Some(yr);
    Some(Figure {
        id: "plan".into(),
        title: "The buildings in plan".into(),
        subtitle: d.subtitle.clone(),
        panels: vec![p],
        columns: 1,
        plot,
        notes: vec![
            "Drawn to scale. Gaps between façades are too small to see: their values are in the terminal and in summary.json. Each contact point acts at every floor pair of its contact; its impacts are counted over them.".into(),
        ],
        ..Figure::default()
    })
}

/// The orbit in plan of the corner of each building's top floor that moved most, with its mass centre's;
/// `None` without a building in plan.
pub fn corner_orbit(d: &RunData) -> Option<Figure> {
    let plans = planned(d);
    if plans.is_empty() {
        return None;
    }
    let plot = (360.0, 360.0);
    let mut panels = Vec::new();
    for (b, bs, ps) in plans {
        let bd = &d.buildings[b];
        let top = bs.storeys - 1;
        let (Some(ux), Some(uy), Some(th)) = (
            bd.floors.get(top),
            bd.floors_y.get(top),
            bd.rotation.get(top),
        ) else {
            continue;
        };
        let ([x0, y0], [a, bb]) = (ps.position, ps.size);
        let c = ps.mass_centres[top];
        let corners = [(0.0, 0.0), (a, 0.0), (a, bb), (0.0, bb)];
        // The corner whose larger peak (along x or y) is the largest.
        let k = (0..4)
            .max_by(|&i, &j| {
                let m = |k: usize| ps.peak_corner_x[top][k].max(ps.peak_corner_y[top][k]);
                m(i).total_cmp(&m(j))
            })
            .unwrap_or(0);
        let (rx, ry) = (corners[k].0 - c[0], corners[k].1 - c[1]);
        let cx: Vec<f64> = ux.iter().zip(th).map(|(u, t)| u - ry * t).collect();
        let cy: Vec<f64> = uy.iter().zip(th).map(|(u, t)| u + rx * t).collect();
        let mut p = Panel::new(
            format!(
                "{}, floor {} (roof): corner ({}, {})",
                bs.name,
                top + 1,
                fmt_num(x0 + corners[k].0),
                fmt_num(y0 + corners[k].1)
            ),
            Quantity::new("displacement along x", "m"),
            Quantity::new("displacement along y", "m"),
        );
        let range = |v: &[f64]| {
            v.iter()
                .fold((0.0f64, 0.0f64), |r, &x| (r.0.min(x), r.1.max(x)))
        };
        let (xr, yr) = to_scale(range(&cx), range(&cy), plot);
        p.series.push(Series::line(
            "corner",
            cx,
            cy,
            Style {
                width: 1.2,
                ..Style::nth(1)
            },
        ));
        p.series.push(Series::line(
            "mass centre",
            ux.clone(),
            uy.clone(),
            Style {
                width: 1.2,
                ..Style::nth(0)
            },
        ));
        p.x_range = Some(xr);
        p.y_range = Some(yr);
        panels.push(p);
    }
    if panels.is_empty() {
        return None;
    }
    Some(Figure {
        id: "corner-orbit".into(),
        title: "Orbit of the corner that moved most, top floor".into(),
        subtitle: d.subtitle.clone(),
        columns: panels.len().min(2),
        panels,
        plot,
        notes: vec![
            "Displacements relative to the ground, to scale, sampled at the output interval. A corner moves with its floor's mass centre and its rotation (small rotations): the gap between the two orbits is the twist times the arm.".into(),
        ],
        ..Figure::default()
    })
}
