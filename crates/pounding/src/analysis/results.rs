//! What a run produces ([`Results`]): peaks of buildings, totals of contact sites and devices, every impact,
//! the energy balance, histories and integration counts.

use super::Layer;

/// One impact of one contact element.
#[derive(Clone, Debug, PartialEq)]
pub struct Impact {
    /// Its site: an index in [`super::Scenario::sites`] (and [`Results::sites`]).
    pub site: usize,
    /// Its level: an index in the site's [`super::ContactSite::levels`].
    pub level: usize,
    /// Which law: the contact's own, a bumper's layer, or the hard law behind a consumed bumper.
    pub layer: Layer,
    /// Time of touch, s.
    pub time: f64,
    /// Relative velocity at touch, m/s.
    pub v_i: f64,
    /// Relative velocity when the impact ended, m/s (negative: separating); `None` if it had not ended.
    pub v_out: Option<f64>,
    /// Delivered coefficient of restitution `-v_out / v_i`; `None` if the impact had not ended, or for a resting
    /// contact (where `v_i` is too small for the ratio to mean anything).
    pub e_post: Option<f64>,
    /// Whether the impact had ended before the analysis stopped.
    pub ended: bool,
    /// A resting contact: the ends closed from rest, at a relative velocity below the smallest impact
    /// velocity used to build a law ([`crate::analysis::Scenario::with_min_impact_velocity`]); its law was built with that
    /// velocity, and it has no meaningful `e_post`.
    pub resting: bool,
    /// Largest contact force, N, located between steps; for an impact on a bumper's layer, the larger of
    /// that and the whole force on the face at the integration nodes (the bumper and the hard law behind it
    /// once consumed: the site's force).
    pub peak_force: f64,
    /// Time of the largest force, s.
    pub time_of_peak_force: f64,
    /// Largest penetration, m.
    pub max_penetration: f64,
    /// Duration of contact, s (to the end of the analysis if it had not ended).
    pub duration: f64,
    /// Work of the contact force on the relative motion over the impact, J (the energy dissipated).
    pub dissipated_energy: f64,
}

/// Peak response of one building.
#[derive(Clone, Debug, PartialEq)]
pub struct BuildingResponse {
    /// Largest |displacement| of each floor relative to the ground, m.
    pub peak_displacement: Vec<f64>,
    /// Time of each, s.
    pub time_of_peak_displacement: Vec<f64>,
    /// Largest |inter-storey drift| of each storey, m.
    pub peak_drift: Vec<f64>,
    /// Largest |absolute acceleration| `|u'' + a_g|` of each floor, m/s^2, over every integration node (step
    /// ends and events, just before and just after each event).
    pub peak_absolute_acceleration: Vec<f64>,
    /// Time of each, s.
    pub time_of_peak_absolute_acceleration: Vec<f64>,
    /// Largest |restoring force| of each storey (its law's force, without the Rayleigh damping force), N.
    pub peak_storey_shear: Vec<f64>,
    /// Displacement of each floor at the end of the analysis, m (signed).
    pub residual_displacement: Vec<f64>,
    /// Drift of each storey at the end of the analysis, m (signed).
    pub residual_drift: Vec<f64>,
    /// Ductility demand of each storey, peak drift / yield drift (`None` for a linear storey).
    pub ductility: Vec<Option<f64>>,
    /// Energy dissipated by the hysteresis of each storey, J (0 for a linear storey).
    pub hysteretic_energy: Vec<f64>,
    /// For a building in plan, the rest of its response: the fields above are then those of its floors' mass
    /// centres along x (the drift and shear along x: the sum of its lines' along x), with each storey's
    /// largest ductility of any line and the hysteretic energy of all its lines.
    pub plan: Option<PlanResponse>,
    /// For a building on a foundation, its sway and rocking (the floors' displacements above include the
    /// rocking's `z theta`; the drifts leave it out).
    pub foundation: Option<FoundationResponse>,
}

/// The response of a building's foundation on the soil.
#[derive(Clone, Debug, PartialEq)]
pub struct FoundationResponse {
    /// Largest |sway| of the foundation relative to the free-field ground, m.
    pub peak_sway: f64,
    /// Largest |rocking| of the foundation, rad.
    pub peak_rocking: f64,
    /// Largest |force| of the sway spring (the soil's share of the base shear, without its dashpot), N.
    pub peak_soil_force: f64,
    /// Largest |moment| of the rocking spring (without its dashpot), N m.
    pub peak_soil_moment: f64,
    /// Sway at the end of the analysis, m (signed).
    pub residual_sway: f64,
    /// Rocking at the end of the analysis, rad (signed).
    pub residual_rocking: f64,
}

/// The response of a building in plan beyond its mass centres' along x ([`BuildingResponse`]).
#[derive(Clone, Debug, PartialEq)]
pub struct PlanResponse {
    /// Largest |displacement along y| of each floor's mass centre, m.
    pub peak_displacement_y: Vec<f64>,
    /// Largest |rotation| of each floor about the vertical axis, rad.
    pub peak_rotation: Vec<f64>,
    /// Largest |drift along y| of each storey at the mass centres, m.
    pub peak_drift_y: Vec<f64>,
    /// Largest |twist| of each storey (the rotation of its floor less that of the floor below), rad.
    pub peak_twist: Vec<f64>,
    /// Largest |shear along y| of each storey (the sum of its lines' along y, without damping), N.
    pub peak_storey_shear_y: Vec<f64>,
    /// Largest |torque| of each storey's lines about the mass centre of its floor, N m.
    pub peak_torque: Vec<f64>,
    /// Largest |displacement| of each floor's corners along x and along y, m: `peak_corner[floor][corner] =
    /// (along x, along y)`, the corners counterclockwise from the plan's `(x_min, y_min)`.
    pub peak_corner: Vec<[(f64, f64); 4]>,
    /// Torsional amplification of each floor along x and along y: the largest corner peak over the mass
    /// centre's peak (dimensionless: 1 for a floor that does not turn; `None` where the centre did not
    /// move).
    pub torsional_amplification: Vec<(Option<f64>, Option<f64>)>,
    /// Displacement along y of each floor's mass centre at the end of the analysis, m (signed).
    pub residual_displacement_y: Vec<f64>,
    /// Rotation of each floor at the end of the analysis, rad (signed, counterclockwise).
    pub residual_rotation: Vec<f64>,
    /// Each load-resisting line, in the plan's order.
    pub lines: Vec<LineResponse>,
}

/// Peaks of one load-resisting line of a building in plan, storey by storey.
#[derive(Clone, Debug, PartialEq)]
pub struct LineResponse {
    /// Largest |drift| of the line in each storey (along its direction, where it stands), m.
    pub peak_drift: Vec<f64>,
    /// Ductility demand of each storey, peak drift / yield drift (`None` for a linear storey).
    pub ductility: Vec<Option<f64>>,
    /// Energy dissipated by the line's hysteresis in each storey, J.
    pub hysteretic_energy: Vec<f64>,
}

/// Totals of one contact site (all its elements): a contact between neighbours or a wall.
#[derive(Clone, Debug, PartialEq)]
pub struct SiteResponse {
    /// Number of impacts (on the bumper's face, if there is one).
    pub impacts: usize,
    /// Impacts of the hard law behind a consumed bumper (0 without a bumper).
    pub consumed: usize,
    /// Largest contact force of a level, N: of any impact, located between steps, or (with a bumper) of the
    /// layer and the hard law together, at the integration nodes.
    pub peak_force: f64,
    /// Energy dissipated by the site's contacts, J.
    pub dissipated_energy: f64,
    /// Largest penetration of any element, m.
    pub max_penetration: f64,
    /// Largest closing of each level (in [`super::ContactSite::levels`] order) over the run, m, located
    /// between steps; 0 if the floors never approached: `u_left - u_right` between neighbours, a floor's
    /// displacement towards a wall. Without contact (a run of [`super::Scenario::without_contact`]) it is
    /// the gap each level needed to never touch.
    pub max_closing: Vec<f64>,
    /// Largest opening of each level, m (0 if they never moved apart): `u_right - u_left`, or a floor's
    /// displacement away from a wall.
    pub max_opening: Vec<f64>,
    /// Whether the largest opening exceeded the seat ([`super::ContactSite::seat`]; `None` without one).
    pub unseated: Option<bool>,
    /// Largest |displacement| of each level's two ends along the contact, m: `[left, right]` (a floor's;
    /// a point's along the normal for a floor in plan; 0 on a wall's side).
    pub peak_ends: Vec<[f64; 2]>,
    /// A slab striking a column: the column's demand.
    pub column: Option<ColumnResponse>,
}

/// The demand on a column struck between its floors ([`crate::structure::StruckColumn`]): the force its
/// point's spring carries (the column's own, between the contact and the floors), and its end shears and
/// moments under that load and its storey's drift together, peaks over the run.
#[derive(Clone, Debug, PartialEq)]
pub struct ColumnResponse {
    /// Largest |force| on the column at the point, N.
    pub peak_force: f64,
    /// Largest |shear| at its lower and upper ends, N: the load at the point's part (the shape functions)
    /// and its drift's (`12 EI / L^3` times it), located between the integration nodes.
    pub peak_shear: (f64, f64),
    /// Largest |moment| at its lower and upper ends, N m: the load's part and the drift's (`6 EI / L^2`).
    pub peak_moment: (f64, f64),
    /// Whether a shear exceeded the shear capacity (`None` without one).
    pub shear_exceeded: Option<bool>,
    /// Whether a moment exceeded the moment capacity (`None` without one).
    pub moment_exceeded: Option<bool>,
}

/// Peaks of one device, per floor pair ([`super::Device::floors`] order).
#[derive(Clone, Debug, PartialEq)]
pub struct DeviceResponse {
    /// Largest |force| (elastic and viscous), N, over the integration nodes.
    pub peak_force: Vec<f64>,
    /// Largest closing `x` (m; for a restrainer, negative values are openings).
    pub max_closing: Vec<f64>,
    /// Largest opening `-x`, m.
    pub max_opening: Vec<f64>,
}

/// Energies at the end of the analysis, J, and the worst relative error of the balance.
#[derive(Clone, Debug, PartialEq)]
pub struct EnergyBalance {
    /// The six energy terms at the end of the analysis, J (the contact term is the dissipated energy plus
    /// what the contacts hold at the end).
    pub end: crate::engine::Energies,
    /// Largest `|input - kinetic - strain - damping - hysteretic - contact|` over the run (at every node),
    /// divided by the largest of `kinetic + strain + damping + hysteretic + |contact|` (dimensionless).
    pub relative_error: f64,
}

/// Time histories at the output interval.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Histories {
    /// Times, s.
    pub t: Vec<f64>,
    /// Ground acceleration (along x), m/s^2.
    pub ground_acceleration: Vec<f64>,
    /// Ground acceleration along y, m/s^2 (empty unless the ground shakes in two directions).
    pub ground_acceleration_y: Vec<f64>,
    /// `displacement[building][floor][sample]`, m, relative to the ground (of a floor in plan, its mass
    /// centre's along x).
    pub displacement: Vec<Vec<Vec<f64>>>,
    /// `displacement_y[building][floor][sample]`: a floor in plan's mass centre along y, m (no floors for a
    /// building in one line).
    pub displacement_y: Vec<Vec<Vec<f64>>>,
    /// `rotation[building][floor][sample]`: a floor in plan's rotation about the vertical axis,
    /// counterclockwise, rad (no floors for a building in one line).
    pub rotation: Vec<Vec<Vec<f64>>>,
    /// `foundation[building]`: a building on a foundation's sway (m) and rocking (rad) at each sample,
    /// `[sway, rocking]` (empty for a building fixed at its base).
    pub foundation: Vec<Vec<Vec<f64>>>,
    /// `absolute_acceleration[building][floor][sample]`, `u'' + a_g`, m/s^2 (of a floor in plan, its mass
    /// centre's along x).
    pub absolute_acceleration: Vec<Vec<Vec<f64>>>,
    /// `storey_shear[building][storey][sample]`: the restoring force of each storey, N (of a building in
    /// plan, the sum of its lines' along x).
    pub storey_shear: Vec<Vec<Vec<f64>>>,
    /// `site_force[site][level][sample]`, N (sites in [`super::Scenario::sites`] order, levels in
    /// [`super::ContactSite::levels`] order; with a bumper, the layer's and the hard law's force together).
    pub site_force: Vec<Vec<Vec<f64>>>,
    /// `device_force[device][pair][sample]`, N, positive pushing apart (pairs in [`super::Device::floors`]
    /// order).
    pub device_force: Vec<Vec<Vec<f64>>>,
    /// Energies, J: input, kinetic, recoverable strain, viscous damping, hysteretic, contact work
    /// (`energy[0..6][sample]`).
    pub energy: [Vec<f64>; 6],
    /// The force–penetration path of every impact, `impact_loops[i]` of [`Results::impacts`]`[i]`: points at
    /// every accepted integration step in contact, with the located peak (histories sample every
    /// `output_dt`, too coarse for impacts of a few ms).
    pub impact_loops: Vec<ImpactLoop>,
}

/// Largest number of points an [`ImpactLoop`] keeps; past it, every other point is dropped and only every
/// `stride`-th step is kept from then on ([`ImpactLoop::stride`]).
pub const MAX_LOOP_POINTS: usize = 2000;

/// The path of one impact: its touch, the end of every accepted integration step while in contact, and its
/// located peak force, in time order.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ImpactLoop {
    /// Times, s.
    pub t: Vec<f64>,
    /// Penetration `u_left - u_right - gap` (for a wall, towards it), m.
    pub penetration: Vec<f64>,
    /// Contact force (as reported: the located peak is [`Impact::peak_force`]), N.
    pub force: Vec<f64>,
    /// 1 if every step is kept; `2^k` once the impact outgrew [`MAX_LOOP_POINTS`] `k` times (then one step
    /// in `stride` is kept, and always the touch, the last step and the peak).
    pub stride: usize,
}

/// Counts of the integration.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Statistics {
    /// Accepted steps.
    pub steps: usize,
    /// Rejected steps.
    pub rejected: usize,
    /// Events located and applied: contact touch, turn, kink, zero force, separation, resume; storey yield
    /// and reversal.
    pub events: usize,
}

impl Results {
    /// The smallest and largest delivered coefficient of restitution (`-v_out / v_i`, dimensionless) of the
    /// ended impacts at site `site`, `None` if there are none. Between floors of buildings these differ from
    /// the `e` a contact was calibrated for: the calibration holds for two free bodies, and the other forces
    /// on the floors act during a contact (`docs/verification.md`, "Impacts inside a run").
    pub fn delivered_e(&self, site: usize) -> Option<(f64, f64)> {
        self.impacts
            .iter()
            .filter(|i| i.site == site)
            .filter_map(|i| i.e_post)
            .fold(None, |range, e| {
                Some(range.map_or((e, e), |(lo, hi): (f64, f64)| (lo.min(e), hi.max(e))))
            })
    }

    /// The first quantity that is not a finite number (its name), if any: a run returns
    /// [`crate::Error::NotFinite`] rather than such a result.
    pub fn first_non_finite(&self) -> Option<String> {
        // A branch-free fold, which the compiler vectorises: a short-circuiting `any` took 0.8 % of the
        // instructions of a run, this takes 0.5 %.
        let bad = |xs: &[f64]| !xs.iter().fold(true, |ok, x| ok & x.is_finite());
        for (b, r) in self.buildings.iter().enumerate() {
            for (name, xs) in [
                ("peak_displacement", &r.peak_displacement),
                ("peak_drift", &r.peak_drift),
                ("peak_absolute_acceleration", &r.peak_absolute_acceleration),
                ("peak_storey_shear", &r.peak_storey_shear),
                ("residual_drift", &r.residual_drift),
                ("hysteretic_energy", &r.hysteretic_energy),
            ] {
                if bad(xs) {
                    return Some(format!("{name} of building {}", b + 1));
                }
            }
        }
        if bad(&self.energy.end.terms()) {
            return Some("energy".into());
        }
        if self.impacts.iter().any(|i| {
            bad(&[
                i.v_i,
                i.peak_force,
                i.max_penetration,
                i.duration,
                i.dissipated_energy,
            ]) || i.e_post.is_some_and(|x| !x.is_finite())
        }) {
            return Some("impacts".into());
        }
        let h = &self.histories;
        let groups = [
            &h.displacement,
            &h.displacement_y,
            &h.rotation,
            &h.foundation,
            &h.absolute_acceleration,
            &h.storey_shear,
            &h.site_force,
            &h.device_force,
        ];
        if self
            .devices
            .iter()
            .any(|d| bad(&d.peak_force) || bad(&d.max_closing) || bad(&d.max_opening))
        {
            return Some("devices".into());
        }
        if groups.iter().any(|g| g.iter().flatten().any(|c| bad(c)))
            || h.energy.iter().any(|c| bad(c))
        {
            return Some("histories".into());
        }
        None
    }
}

/// Everything a run produces.
#[derive(Clone, Debug, PartialEq)]
pub struct Results {
    /// Peak response of each building.
    pub buildings: Vec<BuildingResponse>,
    /// Totals of each contact site, in [`super::Scenario::sites`] order.
    pub sites: Vec<SiteResponse>,
    /// Peaks of each device.
    pub devices: Vec<DeviceResponse>,
    /// Every impact, in order of touch.
    pub impacts: Vec<Impact>,
    /// Energy balance.
    pub energy: EnergyBalance,
    /// Time histories (empty when the run kept none, see [`crate::analysis::RunOptions`]).
    pub histories: Histories,
    /// Integration counts.
    pub statistics: Statistics,
}
