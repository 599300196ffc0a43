//! The unit of every number of a summary, by key (`summary.json`'s `units`).

use serde_json::{json, Map, Value};

/// The unit of every number of a summary.
pub fn units() -> Map<String, Value> {
    let v = json!({
        "periods": "s", "heights": "m", "mode_shapes": "largest component = 1, top floor positive",
        "peak_displacement": "m", "time_of_peak_displacement": "s",
        "peak_drift": "m", "peak_drift_ratio": "drift / storey height",
        "peak_absolute_acceleration": "m/s^2", "time_of_peak_absolute_acceleration": "s",
        "peak_storey_shear": "N (restoring force of the storey, without Rayleigh damping)",
        "residual_displacement": "m (signed, at the end of the analysis)", "residual_drift": "m (signed, at the end of the analysis)",
        "inelastic_storeys": "storey numbers, from 1", "yield_forces": "N", "ductility": "peak drift / yield drift",
        "hysteretic_energy": "J", "gap": "m", "stiffness": "N/m^exponent",
        "peak_force": "N", "max_penetration": "m", "dissipated_energy": "J", "energy": "J",
        "energy_balance_error": "max |input - kinetic - strain - damping - hysteretic - contact| / max energy",
        "warnings": "what the run says about its input (likely unit slips) and its own accuracy (an energy balance error above 1e-4)",
        "duration": "s", "output_dt": "s", "record.dt": "s", "record.pga": "m/s^2",
        "sites.levels": "the floor on each side of the joint, from 1 (absent on a wall's side)",
        "max_closing": "m (largest u_left - u_right of each level; for a wall, towards it)",
        "max_opening": "m (largest u_right - u_left of each level; for a wall, away from it)",
        "seat": "m", "unseated": "largest opening > seat", "consumed": "impacts of the hard law behind a consumed bumper",
        "bumper.thickness": "m", "isolator.peak_displacement": "m (peak |drift| of storey 1)", "isolator.clearance": "m",
        "devices.law": "stiffness N/m, damping_coefficient N s/m (N (s/m)^velocity_exponent for fluid-viscous), slack m",
        "devices.peak_force": "N (elastic and viscous)",
    });
    // Buildings in plan and two ground components (a second object: one json! of all keys overflows the
    // macro's recursion limit).
    let plan = json!({
        "record_y.dt": "s", "record_y.pga": "m/s^2",
        "plan.size": "m (along x, along y)", "plan.position": "m (the corner of smallest x and y, in the site's frame)",
        "plan.mass_centres": "m (in the plan's frame)", "plan.inertias": "kg m^2",
        "plan.modes.period": "s", "plan.modes.mass_ratio_x": "effective modal mass along x / building mass",
        "plan.modes.mass_ratio_rotation": "effective modal moment of inertia / sum of the floors'",
        "plan.lines.at": "m (y of a line along x, x of a line along y, in the plan's frame)", "plan.lines.stiffnesses": "N/m",
        "plan.lines.peak_drift": "m", "plan.lines.ductility": "peak drift / yield drift (0 for linear)", "plan.lines.hysteretic_energy": "J",
        "plan.peak_displacement_y": "m", "plan.peak_rotation": "rad", "plan.peak_drift_y": "m", "plan.peak_twist": "rad",
        "plan.peak_storey_shear_y": "N", "plan.peak_torque": "N m", "plan.peak_corner_x": "m (corners counterclockwise from the plan's corner of smallest x and y)",
        "plan.peak_corner_y": "m", "plan.torsional_amplification_x": "largest corner peak / mass centre peak, along x",
        "plan.residual_displacement_y": "m (signed)", "plan.residual_rotation": "rad (signed, counterclockwise)",
        "sites.points": "m (each level's point on the left building's façade, in the site's frame)",
    });
    // Soil and supports (issue 27).
    let ground = json!({
        "foundation.mass": "kg", "foundation.inertia": "kg m^2", "foundation.kx": "N/m", "foundation.ktheta": "N m/rad",
        "foundation.cx": "N s/m", "foundation.ctheta": "N m s/rad", "foundation.flexible_periods": "s (on the foundation)",
        "foundation.flexible_damping_ratios": "phi^T C phi / 2w (an estimate: the damping is not classical)",
        "foundation.peak_sway": "m", "foundation.peak_rocking": "rad", "foundation.peak_soil_force": "N",
        "foundation.peak_soil_moment": "N m", "foundation.residual_sway": "m (signed)", "foundation.residual_rocking": "rad (signed)",
        "column.height": "m (above the storey's lower floor)", "column.length": "m", "column.EI": "N m^2",
        "column.stiffness": "N/m (at the point)", "column.point_mass": "kg", "column.peak_force": "N",
        "column.peak_shear": "N [lower end, upper end]", "column.peak_moment": "N m [lower end, upper end]",
        "supports.delay": "s (after the scenario's record)", "supports.pga": "m/s^2",
    });
    match (v, plan, ground) {
        (Value::Object(mut m), Value::Object(p), Value::Object(g)) => {
            m.extend(p);
            m.extend(g);
            m
        }
        _ => unreachable!("JSON objects"),
    }
}

/// A summary's units: [`units`], built once and shared by every summary that did not read units of its own
/// (a clone counts a reference), or the map a summary read.
#[derive(Clone, Debug, PartialEq)]
pub struct Units(std::sync::Arc<Map<String, Value>>);

impl Units {
    /// The units of [`units`], shared.
    pub fn shared() -> Self {
        static SHARED: std::sync::OnceLock<std::sync::Arc<Map<String, Value>>> =
            std::sync::OnceLock::new();
        Units(SHARED.get_or_init(|| std::sync::Arc::new(units())).clone())
    }

    /// Whether these are the shared units ([`Self::shared`]), not a map a summary read.
    pub fn is_shared(&self) -> bool {
        std::sync::Arc::ptr_eq(&self.0, &Self::shared().0)
    }
}

/// What a summary's compact JSON holds of the shared units: `,"units":` and their map.
pub(super) fn shared_field_text() -> &'static str {
    static TEXT: std::sync::OnceLock<String> = std::sync::OnceLock::new();
    TEXT.get_or_init(|| {
        let map = serde_json::to_string(&Units::shared()).expect("units are JSON");
        format!(",\"units\":{map}")
    })
}

impl Default for Units {
    fn default() -> Self {
        Self::shared()
    }
}

impl std::ops::Deref for Units {
    type Target = Map<String, Value>;
    fn deref(&self) -> &Self::Target {
        &self.0
    }
}

impl serde::Serialize for Units {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        self.0.serialize(s)
    }
}

impl<'de> serde::Deserialize<'de> for Units {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        Map::deserialize(d).map(|m| Units(std::sync::Arc::new(m)))
    }
}

/// The schema of the map it holds.
impl schemars::JsonSchema for Units {
    fn inline_schema() -> bool {
        true
    }
    fn schema_name() -> std::borrow::Cow<'static, str> {
        "Units".into()
    }
    fn json_schema(generator: &mut schemars::SchemaGenerator) -> schemars::Schema {
        <Map<String, Value>>::json_schema(generator)
    }
}
