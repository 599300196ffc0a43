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
    match v {
        Value::Object(m) => m,
        _ => unreachable!("a JSON object"),
    }
}
