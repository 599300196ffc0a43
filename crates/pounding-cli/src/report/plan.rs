//! The report's tables of a building in plan: its modes in plan, and its response along y, in rotation and
//! at its corners.

use super::markup::{e, mm, n, table};
use pounding_study::summary::{BuildingSummary, PlanSummary};

/// The modes in plan of building `b` (the `k`-th structure).
pub fn modes(h: &mut String, k: usize, b: &BuildingSummary, p: &PlanSummary) {
    let rows: Vec<Vec<String>> = p
        .modes
        .iter()
        .enumerate()
        .map(|(r, m)| {
            vec![
                (r + 1).to_string(),
                format!("{:.4}", m.period),
                format!("{:.2}", 100.0 * m.damping_ratio),
                format!("{:.1}", 100.0 * m.mass_ratio_x),
                format!("{:.1}", 100.0 * m.mass_ratio_y),
                format!("{:.1}", 100.0 * m.mass_ratio_rotation),
            ]
        })
        .collect();
    table(
        h,
        &format!("modes-{k}"),
        &format!(
            "Building {} in plan: modes of its floors' x, y and rotation (damping fixed on modes {} and {})",
            b.name, p.damping_modes[0], p.damping_modes[1]
        ),
        &[
            "mode",
            "period (s)",
            "damping (%)",
            "effective mass along x (%)",
            "along y (%)",
            "rotation (% of the floors' inertia)",
        ],
        &rows,
    );
}

/// The response of building `b` (the `k`-th structure) in plan beyond its mass centres' along x.
pub fn response(h: &mut String, k: usize, b: &BuildingSummary, p: &PlanSummary) {
    let amp = |v: &Option<Vec<f64>>, f: usize| {
        v.as_ref()
            .map_or("–".to_string(), |v| format!("{:.3}", v[f]))
    };
    let rows: Vec<Vec<String>> = (0..b.storeys)
        .map(|f| {
            let top = |c: &[f64; 4]| c.iter().copied().fold(0.0f64, f64::max);
            vec![
                (f + 1).to_string(),
                mm(p.peak_displacement_y[f]),
                n(1e3 * p.peak_rotation[f]),
                mm(top(&p.peak_corner_x[f])),
                mm(top(&p.peak_corner_y[f])),
                amp(&p.torsional_amplification_x, f),
                amp(&p.torsional_amplification_y, f),
                n(1e3 * p.peak_twist[f]),
                n(1e-6 * p.peak_torque[f]),
            ]
        })
        .collect();
    table(
        h,
        &format!("plan-{k}"),
        &format!(
            "Building {} in plan: its mass centres along y, its rotations and its corners (the tables above hold its mass centres along x)",
            e(&b.name)
        ),
        &[
            "floor",
            "peak displacement along y (mm)",
            "peak rotation (mrad)",
            "largest corner peak along x (mm)",
            "along y (mm)",
            "torsional amplification along x",
            "along y",
            "peak twist of the storey below (mrad)",
            "peak torque of the storey below (MN m)",
        ],
        &rows,
    );
}
