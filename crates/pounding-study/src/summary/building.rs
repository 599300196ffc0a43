//! The summary of a building: its modes and its peak response.

use pounding::analysis::{Building, BuildingResponse};
use pounding::element::StoreyModel;
use pounding::structure::{Form, IsolatorKind, IsolatorModel};
use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

/// The isolator under a base-isolated building's slab, and its demand.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
pub struct IsolatorSummary {
    /// Its model.
    pub model: IsolatorKind,
    /// Its law and parameters (stiffness N/m, yield force N, radius m, ...).
    pub law: IsolatorModel,
    /// Height of the isolation storey, m.
    pub height: f64,
    /// Its own viscous coefficient, N s/m.
    pub damping_coefficient: f64,
    /// Its displacement capacity, m.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub clearance: Option<f64>,
    /// Peak displacement of the isolator (|drift| of storey 1), m.
    pub peak_displacement: f64,
    /// Whether the peak displacement exceeded the clearance.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub exceeds_clearance: Option<bool>,
    /// Displacement of the isolator at the end of the analysis, m (signed).
    pub residual_displacement: f64,
}

/// A building: its modes and peak response. Lists run floor 1 (or storey 1) upwards.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
pub struct BuildingSummary {
    /// Its name.
    pub name: String,
    /// Number of storeys (floors).
    pub storeys: usize,
    /// Height of each storey, m (with an isolator, storey 1 is the isolation storey).
    pub heights: Vec<f64>,
    /// Natural periods, s.
    pub periods: Vec<f64>,
    /// Damping ratio of each mode, `phi^T C phi / 2w` (dimensionless).
    pub modal_damping_ratios: Vec<f64>,
    /// Mode shapes, largest component 1, top floor positive (dimensionless).
    pub mode_shapes: Vec<Vec<f64>>,
    /// Effective modal mass of each mode over the building's mass (dimensionless).
    pub effective_modal_mass_ratios: Vec<f64>,
    /// Largest |displacement| of each floor relative to the ground, m.
    pub peak_displacement: Vec<f64>,
    /// Time of each, s.
    pub time_of_peak_displacement: Vec<f64>,
    /// Largest |drift| of each storey, m.
    pub peak_drift: Vec<f64>,
    /// Largest |drift| over the storey's height (dimensionless).
    pub peak_drift_ratio: Vec<f64>,
    /// The law of each storey.
    pub storey_models: Vec<StoreyModel>,
    /// Largest |absolute acceleration| of each floor, m/s^2.
    pub peak_absolute_acceleration: Vec<f64>,
    /// Time of each, s.
    pub time_of_peak_absolute_acceleration: Vec<f64>,
    /// Largest |restoring force| of each storey (without Rayleigh damping), N.
    pub peak_storey_shear: Vec<f64>,
    /// Displacement of each floor at the end of the analysis, m (signed).
    pub residual_displacement: Vec<f64>,
    /// Drift of each storey at the end of the analysis, m (signed).
    pub residual_drift: Vec<f64>,
    /// The isolator, if the building is isolated at its base.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub isolator: Option<IsolatorSummary>,
    /// The inelastic storeys, numbered from 1 (the lists below follow them).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub inelastic_storeys: Vec<usize>,
    /// Yield force of each inelastic storey, N.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub yield_forces: Vec<f64>,
    /// Peak drift over yield drift of each inelastic storey (dimensionless).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub ductility: Vec<f64>,
    /// Energy dissipated by the hysteresis of each inelastic storey, J.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub hysteretic_energy: Vec<f64>,
    /// For a building in plan: its plan, lines and modes in plan, and its response along y, in rotation and
    /// at its corners. The fields above then hold its mass centres' response along x; its periods, damping
    /// ratios and mass ratios (along x) are its modes' in plan, its mode shapes their x components; a storey
    /// is inelastic if one of its lines is, with the yield force of its lines along x summed, the largest
    /// ductility of its lines and their hysteretic energy summed.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub plan: Option<super::PlanSummary>,
    /// For a building on a foundation over soil springs: the foundation, the modes on it and its response
    /// (the fields above are then its floors' displacements relative to the free field, rocking included, and
    /// its storeys' drifts without it; its periods are the fixed-base ones its damping is fixed on).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub foundation: Option<FoundationSummary>,
    /// For a structure given by its matrices: what the run took from them (its periods and modes above are
    /// the matrices'; its storey shears the springs' forces across each cut under a floor).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub matrices: Option<MatricesSummary>,
}

/// A structure given by its matrices.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
pub struct MatricesSummary {
    /// Degrees of freedom (floors).
    pub dofs: usize,
    /// The stiffness across the cut under each floor (the springs joining a floor at or above it to one
    /// below it or to the ground), N/m: the storey stiffness a shear building would have.
    pub cut_stiffnesses: Vec<f64>,
    /// `matrix` (the damping matrix given) or `rayleigh` (`damping_ratio` on the matrices' modes 1 and 2).
    pub damping: String,
}

/// A building's foundation on the soil, the modes on it and its response.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
pub struct FoundationSummary {
    /// Mass, kg.
    pub mass: f64,
    /// Moment of inertia about the rocking axis (a trapped soil mass included), kg m^2.
    pub inertia: f64,
    /// Sway stiffness, N/m.
    pub kx: f64,
    /// Rocking stiffness, N m/rad.
    pub ktheta: f64,
    /// Sway dashpot, N s/m.
    pub cx: f64,
    /// Rocking dashpot, N m s/rad.
    pub ctheta: f64,
    /// The periods on the foundation (floors, sway and rocking together), s, lowest mode first.
    pub flexible_periods: Vec<f64>,
    /// Each of those modes' damping ratio `phi^T C phi / 2 w` (the soil's dashpots and the building's
    /// Rayleigh damping; the damping is not classical, so this is an estimate), dimensionless.
    pub flexible_damping_ratios: Vec<f64>,
    /// Largest |sway| of the foundation relative to the free-field ground, m.
    pub peak_sway: f64,
    /// Largest |rocking|, rad.
    pub peak_rocking: f64,
    /// Largest |force| of the sway spring, N.
    pub peak_soil_force: f64,
    /// Largest |moment| of the rocking spring, N m.
    pub peak_soil_moment: f64,
    /// Sway at the end of the analysis, m (signed).
    pub residual_sway: f64,
    /// Rocking at the end of the analysis, rad (signed).
    pub residual_rocking: f64,
}

impl FoundationSummary {
    fn of(
        st: &pounding::structure::ShearBuilding,
        r: &pounding::analysis::FoundationResponse,
    ) -> Option<Self> {
        let (f, modes) = (st.foundation()?, st.flexible_modes()?);
        let (a0, a1) = st.rayleigh();
        let n = st.storeys();
        let z = st.elevations();
        // phi^T C phi: the storeys' a1 k and the floors' a0 m on the drift (rocking left out), the soil's dashpots.
        let damping = |phi: &[f64], w: f64| {
            let mut c = f.cx * phi[n] * phi[n] + f.ctheta * phi[n + 1] * phi[n + 1];
            for j in 0..n {
                let below = if j == 0 { phi[n] } else { phi[j - 1] };
                let d = phi[j] - below - st.heights()[j] * phi[n + 1];
                c += a1 * st.stiffnesses()[j] * d * d;
                let rel = phi[j] - z[j] * phi[n + 1] - phi[n];
                c += a0 * st.masses()[j] * rel * rel;
            }
            c / (2.0 * w)
        };
        Some(Self {
            mass: f.mass,
            inertia: f.inertia,
            kx: f.kx,
            ktheta: f.ktheta,
            cx: f.cx,
            ctheta: f.ctheta,
            flexible_periods: modes.periods(),
            flexible_damping_ratios: modes
                .shapes
                .iter()
                .zip(&modes.omega)
                .map(|(phi, &w)| damping(phi, w))
                .collect(),
            peak_sway: r.peak_sway,
            peak_rocking: r.peak_rocking,
            peak_soil_force: r.peak_soil_force,
            peak_soil_moment: r.peak_soil_moment,
            residual_sway: r.residual_sway,
            residual_rocking: r.residual_rocking,
        })
    }
}

/// A storey law per storey of a building in plan, for its summary along x: the first inelastic law of its
/// lines, with the yield forces of its lines along x summed (the storey's along x; those of its lines along
/// y if none along x yields).
fn plan_storey_laws(p: &pounding::structure::Plan) -> Vec<pounding::element::StoreyLaw> {
    use pounding::element::StoreyLaw;
    use pounding::structure::LineDirection;
    (0..p.floors())
        .map(|j| {
            let inelastic = |d: Option<LineDirection>| {
                p.lines()
                    .iter()
                    .filter(move |l| d.is_none_or(|d| l.direction == d))
                    .map(move |l| l.laws[j])
                    .filter(|law| law.is_inelastic())
            };
            let Some(first) = inelastic(None).next() else {
                return StoreyLaw::Linear;
            };
            let along_x: f64 = inelastic(Some(LineDirection::X))
                .filter_map(|l| l.yield_force())
                .sum();
            first.with_yield_force(if along_x > 0.0 {
                along_x
            } else {
                first.yield_force().unwrap_or(0.0)
            })
        })
        .collect()
}

/// The x components of each mode of plan `p`, over the largest translation or edge motion of the mode (its
/// rotation times the floor's radius of gyration), so that a mode along y or in rotation has small x
/// components, not a scale of its own.
fn plan_shapes(p: &pounding::structure::Plan) -> Vec<Vec<f64>> {
    let n = p.floors();
    p.modes()
        .shapes
        .iter()
        .map(|phi| {
            let big = (0..n)
                .map(|i| {
                    let rg = (p.inertias()[i] / p.masses()[i]).sqrt();
                    phi[i]
                        .abs()
                        .max(phi[n + i].abs())
                        .max(rg * phi[2 * n + i].abs())
                })
                .fold(0.0f64, f64::max);
            phi[..n].iter().map(|x| x / big).collect()
        })
        .collect()
}

impl BuildingSummary {
    /// Building `b` and its response `resp`.
    pub fn of(b: &Building, resp: &BuildingResponse) -> Self {
        let st = &b.structure;
        let modes = st.modes();
        let part = modes.participation(st.masses());
        let plan = st
            .plan()
            .zip(resp.plan.as_ref())
            .map(|(p, r)| super::PlanSummary::of(p, r));
        let laws = match st.plan() {
            None => st.storey_laws().to_vec(),
            Some(p) => plan_storey_laws(p),
        };
        let isolator = st.isolator().map(|iso| IsolatorSummary {
            model: iso.model.kind(),
            law: iso.model,
            height: iso.height,
            damping_coefficient: iso.damping,
            clearance: iso.clearance,
            peak_displacement: resp.peak_drift[0],
            exceeds_clearance: iso.clearance.map(|c| resp.peak_drift[0] > c),
            residual_displacement: resp.residual_drift[0],
        });
        // Ductility and hysteretic energy exist for inelastic storeys only: listed with their numbers.
        let inelastic: Vec<usize> = (0..st.storeys())
            .filter(|&j| laws[j].is_inelastic())
            .collect();
        let (periods, modal_damping_ratios, mode_shapes, effective_modal_mass_ratios) =
            match (st.plan(), &plan) {
                (Some(p), Some(ps)) => (
                    ps.modes.iter().map(|m| m.period).collect(),
                    ps.modes.iter().map(|m| m.damping_ratio).collect(),
                    plan_shapes(p),
                    ps.modes.iter().map(|m| m.mass_ratio_x).collect(),
                ),
                _ => (
                    modes.periods(),
                    (0..modes.omega.len())
                        .map(|r| st.damping_of_mode(r))
                        .collect(),
                    modes.shapes_normalised(),
                    part.iter().map(|p| p.1 / st.total_mass()).collect(),
                ),
            };
        Self {
            name: b.name.clone(),
            storeys: st.storeys(),
            heights: st.heights().to_vec(),
            periods,
            modal_damping_ratios,
            mode_shapes,
            effective_modal_mass_ratios,
            peak_displacement: resp.peak_displacement.clone(),
            time_of_peak_displacement: resp.time_of_peak_displacement.clone(),
            peak_drift: resp.peak_drift.clone(),
            peak_drift_ratio: resp
                .peak_drift
                .iter()
                .zip(st.heights())
                .map(|(d, h)| d / h)
                .collect(),
            storey_models: laws.iter().map(|l| l.model()).collect(),
            peak_absolute_acceleration: resp.peak_absolute_acceleration.clone(),
            time_of_peak_absolute_acceleration: resp.time_of_peak_absolute_acceleration.clone(),
            peak_storey_shear: resp.peak_storey_shear.clone(),
            residual_displacement: resp.residual_displacement.clone(),
            residual_drift: resp.residual_drift.clone(),
            isolator,
            yield_forces: inelastic
                .iter()
                .map(|&j| laws[j].yield_force().unwrap_or(0.0))
                .collect(),
            ductility: inelastic
                .iter()
                .map(|&j| resp.ductility[j].unwrap_or(0.0))
                .collect(),
            hysteretic_energy: inelastic
                .iter()
                .map(|&j| resp.hysteretic_energy[j])
                .collect(),
            inelastic_storeys: inelastic.iter().map(|j| j + 1).collect(),
            plan,
            foundation: resp
                .foundation
                .as_ref()
                .and_then(|r| FoundationSummary::of(st, r)),
            matrices: st.matrices().map(|ms| MatricesSummary {
                dofs: ms.n(),
                cut_stiffnesses: ms.cut_stiffnesses(),
                damping: if ms.damping.is_some() {
                    "matrix"
                } else {
                    "rayleigh"
                }
                .into(),
            }),
        }
    }

    /// Elevation of each floor above the ground, m.
    pub fn elevations(&self) -> Vec<f64> {
        self.heights
            .iter()
            .scan(0.0, |z, h| {
                *z += h;
                Some(*z)
            })
            .collect()
    }

    /// The drift ratio of each storey of the structure (above an isolator, whose drift over its height is no
    /// drift ratio: its displacement is the isolator's own), dimensionless.
    pub fn structural_drift_ratios(&self) -> &[f64] {
        &self.peak_drift_ratio[usize::from(self.isolator.is_some())..]
    }

    /// The ductility of each inelastic storey of the structure (above an isolator, whose ductility is the
    /// isolator's own), dimensionless; empty if none can yield.
    pub fn structural_ductility(&self) -> &[f64] {
        let isolator = self.isolator.is_some() && self.inelastic_storeys.first() == Some(&1);
        &self.ductility[usize::from(isolator)..]
    }

    /// Whether any storey yields (bilinear or Bouc–Wen).
    pub fn is_inelastic(&self) -> bool {
        !self.inelastic_storeys.is_empty()
    }

    /// What the structure is, for the words that name it and its parts.
    pub fn form(&self) -> Form {
        Form::of(self.isolator.is_some(), self.storeys)
    }
}
