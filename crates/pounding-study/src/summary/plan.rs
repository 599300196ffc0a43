//! The summary of a building in plan: its plan, lines and modes in plan, and its response beyond its mass
//! centres' along x (which [`super::BuildingSummary`] holds).

use pounding::analysis::PlanResponse;
use pounding::element::StoreyModel;
use pounding::structure::{LineDirection, Plan};
use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

/// A mode of a building in plan.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
pub struct PlanModeSummary {
    /// Natural period, s.
    pub period: f64,
    /// Damping ratio (dimensionless).
    pub damping_ratio: f64,
    /// Effective modal mass along x over the building's mass (dimensionless).
    pub mass_ratio_x: f64,
    /// Effective modal mass along y over the building's mass (dimensionless).
    pub mass_ratio_y: f64,
    /// Effective modal moment of inertia about the mass centres over the floors' sum (dimensionless).
    pub mass_ratio_rotation: f64,
}

/// A load-resisting line of a building in plan and its peaks, storey 1 upwards.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
pub struct LineSummary {
    /// The direction it resists along.
    pub direction: LineDirection,
    /// Where it stands in the plan's frame, m (y of a line along x, x of one along y).
    pub at: f64,
    /// Initial stiffness of each storey, N/m.
    pub stiffnesses: Vec<f64>,
    /// The law of each storey.
    pub storey_models: Vec<StoreyModel>,
    /// Largest |drift| of the line in each storey, m.
    pub peak_drift: Vec<f64>,
    /// Peak drift over yield drift of each storey (0 for a linear storey; dimensionless).
    pub ductility: Vec<f64>,
    /// Energy dissipated by the line's hysteresis in each storey, J.
    pub hysteretic_energy: Vec<f64>,
}

/// A building in plan: where it stands, its floors' mass centres and inertias, its lines, its modes in plan,
/// and its response along y, in rotation and at its corners. Lists run floor 1 (storey 1) upwards.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
pub struct PlanSummary {
    /// `[a, b]`: size along x and y, m.
    pub size: [f64; 2],
    /// `[x, y]`: the corner of smallest x and y in the site's frame, m.
    pub position: [f64; 2],
    /// `[x, y]` of each floor's mass centre in the plan's frame, m.
    pub mass_centres: Vec<[f64; 2]>,
    /// Each floor's moment of inertia about its mass centre, kg m^2.
    pub inertias: Vec<f64>,
    /// The two modes (from 1) its Rayleigh damping ratio is fixed on.
    pub damping_modes: [usize; 2],
    /// Its modes in plan, lowest first.
    pub modes: Vec<PlanModeSummary>,
    /// Its lines.
    pub lines: Vec<LineSummary>,
    /// Largest |displacement along y| of each floor's mass centre, m.
    pub peak_displacement_y: Vec<f64>,
    /// Largest |rotation| of each floor, rad.
    pub peak_rotation: Vec<f64>,
    /// Largest |drift along y| of each storey at the mass centres, m.
    pub peak_drift_y: Vec<f64>,
    /// Largest |twist| of each storey (rotation of its floor less the floor's below), rad.
    pub peak_twist: Vec<f64>,
    /// Largest |shear along y| of each storey (its lines' along y, without damping), N.
    pub peak_storey_shear_y: Vec<f64>,
    /// Largest |torque| of each storey's lines about its floor's mass centre, N m.
    pub peak_torque: Vec<f64>,
    /// Largest |displacement along x| of each floor's four corners, counterclockwise from the plan's
    /// corner of smallest x and y, m.
    pub peak_corner_x: Vec<[f64; 4]>,
    /// Largest |displacement along y| of each floor's four corners, m.
    pub peak_corner_y: Vec<[f64; 4]>,
    /// Torsional amplification along x of each floor: the largest corner peak over the mass centre's
    /// (dimensionless; absent if a floor's centre did not move along x).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub torsional_amplification_x: Option<Vec<f64>>,
    /// Torsional amplification along y of each floor (absent if a floor's centre did not move along y).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub torsional_amplification_y: Option<Vec<f64>>,
    /// Displacement along y of each floor's mass centre at the end of the analysis, m (signed).
    pub residual_displacement_y: Vec<f64>,
    /// Rotation of each floor at the end of the analysis, rad (signed, counterclockwise).
    pub residual_rotation: Vec<f64>,
}

impl PlanSummary {
    /// Plan `p` of a building with damping ratio `zeta`, and its response `r`.
    pub fn of(p: &Plan, r: &PlanResponse) -> Self {
        let (a0, a1) = p.rayleigh();
        let modes = p
            .modes()
            .omega
            .iter()
            .zip(p.participation())
            .map(|(&w, (x, y, t))| PlanModeSummary {
                period: 2.0 * std::f64::consts::PI / w,
                damping_ratio: a0 / (2.0 * w) + a1 * w / 2.0,
                mass_ratio_x: x,
                mass_ratio_y: y,
                mass_ratio_rotation: t,
            })
            .collect();
        let lines = p
            .lines()
            .iter()
            .zip(&r.lines)
            .map(|(l, lr)| LineSummary {
                direction: l.direction,
                at: l.at,
                stiffnesses: l.stiffnesses.clone(),
                storey_models: l.laws.iter().map(|law| law.model()).collect(),
                peak_drift: lr.peak_drift.clone(),
                ductility: lr.ductility.iter().map(|d| d.unwrap_or(0.0)).collect(),
                hysteretic_energy: lr.hysteretic_energy.clone(),
            })
            .collect();
        let all = |v: Vec<Option<f64>>| v.into_iter().collect::<Option<Vec<f64>>>();
        let (dm1, dm2) = p.damping_modes();
        Self {
            size: [p.size().0, p.size().1],
            position: [p.origin().0, p.origin().1],
            mass_centres: p.centres().iter().map(|c| [c.0, c.1]).collect(),
            inertias: p.inertias().to_vec(),
            damping_modes: [dm1, dm2],
            modes,
            lines,
            peak_displacement_y: r.peak_displacement_y.clone(),
            peak_rotation: r.peak_rotation.clone(),
            peak_drift_y: r.peak_drift_y.clone(),
            peak_twist: r.peak_twist.clone(),
            peak_storey_shear_y: r.peak_storey_shear_y.clone(),
            peak_torque: r.peak_torque.clone(),
            peak_corner_x: r.peak_corner.iter().map(|c| c.map(|p| p.0)).collect(),
            peak_corner_y: r.peak_corner.iter().map(|c| c.map(|p| p.1)).collect(),
            torsional_amplification_x: all(r.torsional_amplification.iter().map(|t| t.0).collect()),
            torsional_amplification_y: all(r.torsional_amplification.iter().map(|t| t.1).collect()),
            residual_displacement_y: r.residual_displacement_y.clone(),
            residual_rotation: r.residual_rotation.clone(),
        }
    }

    /// The largest torsional amplification of any floor along x and along y (1 where it is not defined).
    pub fn largest_amplification(&self) -> (f64, f64) {
        let top = |v: &Option<Vec<f64>>| {
            v.as_ref()
                .map_or(1.0, |v| v.iter().copied().fold(1.0, f64::max))
        };
        (
            top(&self.torsional_amplification_x),
            top(&self.torsional_amplification_y),
        )
    }
}
