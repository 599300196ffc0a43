//! The summary of a run: what `summary.json`, Python's `result.summary` and a sweep's store hold, built once.

use crate::input::Loaded;
use pounding::analysis::{Results, Scenario};
use serde_json::{json, Value};

/// A finite number as JSON, or null (JSON has no infinity or NaN).
pub fn num(x: f64) -> Value {
    serde_json::Number::from_f64(x).map_or(Value::Null, Value::Number)
}

/// The summary of a run of `loaded` (what `summary.json` holds): the record, the settings, each building's
/// modes and peak responses, each contact's impacts and peaks, the energy at the end and its balance error,
/// the integration statistics, `warnings` (what the run says about its own accuracy) and the units of every
/// number. An error names the first number that is not finite (JSON has no NaN or infinity).
pub fn summary(loaded: &Loaded, r: &Results) -> Result<Value, String> {
    let s = &loaded.scenario;
    let mut v = summary_value(
        s,
        r,
        &loaded.label,
        &loaded.record_source,
        loaded.doc.ground_motion.scale,
    );
    // Accuracy that holds itself to account: a balance error above 1e-4 is said in the summary.
    let mut warnings = Vec::new();
    if r.energy.relative_error > BALANCE_WARNING {
        warnings.push(format!(
            "energy balance error {:.2e} is above 1e-4: the integration is not as accurate as the tolerance asks; rerun with a smaller tolerance",
            r.energy.relative_error
        ));
    }
    v["warnings"] = json!(warnings);
    if let Some(path) = first_null(&v, "summary") {
        return Err(format!(
            "the result {path} is not a finite number: the scenario's scales leave the range of floating-point numbers"
        ));
    }
    Ok(v)
}

fn summary_value(s: &Scenario, r: &Results, file: &str, source: &str, scale: f64) -> Value {
    let rec = s.record();
    let pk = rec.peaks();
    let buildings: Vec<Value> = s
        .buildings()
        .iter()
        .zip(&r.buildings)
        .map(|(b, resp)| {
            let st = &b.structure;
            let modes = st.modes();
            let part = modes.participation(st.masses());
            let mut out = json!({
                "name": b.name,
                "storeys": st.storeys(),
                "periods": modes.periods().into_iter().map(num).collect::<Vec<_>>(),
                "modal_damping_ratios": modes.omega.iter().map(|w| num(st.modal_damping(*w))).collect::<Vec<_>>(),
                "mode_shapes": modes.shapes_normalised().into_iter().map(|s| s.into_iter().map(num).collect::<Vec<_>>()).collect::<Vec<_>>(),
                "effective_modal_mass_ratios": part.iter().map(|p| num(p.1 / st.total_mass())).collect::<Vec<_>>(),
                "peak_displacement": resp.peak_displacement.iter().copied().map(num).collect::<Vec<_>>(),
                "time_of_peak_displacement": resp.time_of_peak_displacement.iter().copied().map(num).collect::<Vec<_>>(),
                "peak_drift": resp.peak_drift.iter().copied().map(num).collect::<Vec<_>>(),
                "peak_drift_ratio": resp.peak_drift.iter().zip(st.heights()).map(|(d, h)| num(d / h)).collect::<Vec<_>>(),
                "storey_models": st.storey_laws().iter().map(|l| l.name()).collect::<Vec<_>>(),
                "peak_absolute_acceleration": nums(&resp.peak_absolute_acceleration),
                "time_of_peak_absolute_acceleration": nums(&resp.time_of_peak_absolute_acceleration),
                "peak_storey_shear": nums(&resp.peak_storey_shear),
                "residual_displacement": nums(&resp.residual_displacement),
                "residual_drift": nums(&resp.residual_drift),
            });
            // Ductility and hysteretic energy exist for inelastic storeys only: listed with their numbers.
            let inelastic: Vec<usize> = (0..st.storeys()).filter(|&j| st.storey_laws()[j].is_inelastic()).collect();
            if !inelastic.is_empty() {
                out["inelastic_storeys"] = json!(inelastic.iter().map(|j| j + 1).collect::<Vec<_>>());
                out["yield_forces"] = json!(inelastic.iter().map(|&j| num(st.storey_laws()[j].yield_force().unwrap_or(0.0))).collect::<Vec<_>>());
                out["ductility"] = json!(inelastic.iter().map(|&j| num(resp.ductility[j].unwrap_or(0.0))).collect::<Vec<_>>());
                out["hysteretic_energy"] = json!(inelastic.iter().map(|&j| num(resp.hysteretic_energy[j])).collect::<Vec<_>>());
            }
            out
        })
        .collect();
    let contacts: Vec<Value> = s
        .links()
        .iter()
        .zip(&r.links)
        .map(|(link, lr)| {
            let spec = link.contact.spec();
            let param = link.contact.parameter().and_then(|p| p.named());
            json!({
                "between": [s.buildings()[link.left].name, s.buildings()[link.right].name],
                "gap": num(link.gap),
                "floors": link.floors.iter().map(|(i, j)| json!([i, j])).collect::<Vec<_>>(),
                "model": spec.model().name(),
                "e": num(spec.restitution()),
                "stiffness": num(spec.stiffness()),
                "exponent": num(spec.exponent()),
                "damping_parameter": match (link.contact.parameter(), param) {
                    (None, _) => json!({ "name": "per-impact" }),
                    (Some(_), None) => json!({ "name": "none" }),
                    (Some(_), Some((n, v))) => json!({ "name": n, "value": num(v) }),
                },
                "impacts": lr.impacts,
                "peak_force": num(lr.peak_force),
                "max_penetration": num(lr.max_penetration),
                "dissipated_energy": num(lr.dissipated_energy),
            })
        })
        .collect();
    let e = &r.energy.end;
    json!({
        "scenario": file,
        "record": {
            "source": source,
            "scale": num(scale),
            "npts": rec.npts(),
            "dt": num(rec.dt()),
            "pga": num(pk.pga),
        },
        "duration": num(s.duration()),
        "output_dt": num(s.output_dt()),
        "tolerance": num(s.tolerance()),
        "buildings": buildings,
        "contacts": contacts,
        "energy": {
            "input": num(e.input),
            "kinetic": num(e.kinetic),
            "strain": num(e.strain),
            "structural_damping": num(e.damping),
            "hysteretic": num(e.hysteretic),
            "contact": num(e.contact),
        },
        "energy_balance_error": num(r.energy.relative_error),
        "statistics": {
            "steps": r.statistics.steps,
            "rejected_steps": r.statistics.rejected,
            "events": r.statistics.events,
        },
        "units": {
            "periods": "s", "mode_shapes": "largest component = 1, top floor positive", "peak_displacement": "m", "time_of_peak_displacement": "s",
            "peak_drift": "m", "peak_drift_ratio": "drift / storey height",
            "peak_absolute_acceleration": "m/s^2", "time_of_peak_absolute_acceleration": "s",
            "peak_storey_shear": "N (restoring force of the storey, without Rayleigh damping)",
            "residual_displacement": "m (signed, at the end of the analysis)", "residual_drift": "m (signed, at the end of the analysis)",
            "inelastic_storeys": "storey numbers, from 1", "yield_forces": "N", "ductility": "peak drift / yield drift",
            "hysteretic_energy": "J", "gap": "m", "stiffness": "N/m^exponent",
            "peak_force": "N", "max_penetration": "m", "dissipated_energy": "J", "energy": "J",
            "energy_balance_error": "max |input - kinetic - strain - damping - hysteretic - contact| / max energy",
            "warnings": "what the run says about its own accuracy (an energy balance error above 1e-4)",
            "duration": "s", "output_dt": "s", "record.dt": "s", "record.pga": "m/s^2",
        },
    })
}

/// Largest energy balance error accepted without a warning.
pub const BALANCE_WARNING: f64 = 1e-4;

/// The path of the first `null` in `v` (JSON has no NaN or infinity: `num` writes them as null).
fn first_null(v: &Value, path: &str) -> Option<String> {
    match v {
        Value::Null => Some(path.to_string()),
        Value::Array(a) => a
            .iter()
            .enumerate()
            .find_map(|(i, x)| first_null(x, &format!("{path}[{i}]"))),
        Value::Object(o) => o
            .iter()
            .find_map(|(k, x)| first_null(x, &format!("{path}.{k}"))),
        _ => None,
    }
}

fn nums(xs: &[f64]) -> Vec<Value> {
    xs.iter().copied().map(num).collect()
}
