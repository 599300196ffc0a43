//! The summary of a run: what `summary.json`, Python's `result.summary` and a sweep's store hold, built once.

use crate::input::Loaded;
use pounding::analysis::{Bumper, DeviceEnds, Results, Scenario, SiteKind, SiteResponse};
use pounding::contact::PreparedContact;
use pounding::element::DeviceLaw;
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
                "modal_damping_ratios": (0..modes.omega.len()).map(|r| num(st.damping_of_mode(r))).collect::<Vec<_>>(),
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
            if let Some(iso) = st.isolator() {
                out["isolator"] = json!({
                    "model": iso.model.name(),
                    "law": flat_law(iso.model.name(), serde_json::to_value(iso.model).unwrap_or(Value::Null)),
                    "height": num(iso.height),
                    "damping_coefficient": num(iso.damping),
                    "clearance": iso.clearance.map_or(Value::Null, num),
                    "peak_displacement": num(resp.peak_drift[0]),
                    "exceeds_clearance": iso.clearance.map_or(Value::Null, |c| Value::Bool(resp.peak_drift[0] > c)),
                    "residual_displacement": num(resp.residual_drift[0]),
                });
                if iso.clearance.is_none() {
                    // No clearance given: nothing to compare the demand with (null is kept for JSON readers).
                    out["isolator"].as_object_mut().expect("object").retain(|k, _| k != "clearance" && k != "exceeds_clearance");
                }
            }
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
        .sites()
        .iter()
        .zip(&r.sites)
        .enumerate()
        .filter_map(|(l, (link, lr))| {
            let SiteKind::Between { left, right } = link.kind else {
                return None;
            };
            let mut v = json!({
                "between": [s.buildings()[left].name, s.buildings()[right].name],
                "gap": num(link.gap),
                "floors": link.levels.iter().map(|lv| json!([lv.left, lv.right])).collect::<Vec<_>>(),
            });
            site_totals(&mut v, &link.contact, &link.bumper, link.seat, lr);
            if let Some(e) = delivered(r, l) {
                v["e_delivered"] = e;
            }
            Some(v)
        })
        .collect();
    let walls: Vec<Value> = s
        .sites()
        .iter()
        .zip(&r.sites)
        .enumerate()
        .filter_map(|(k, (w, wr))| {
            let SiteKind::Wall { building, side } = w.kind else {
                return None;
            };
            let mut v = json!({
                "name": w.name,
                "facing": s.buildings()[building].name,
                "side": side.name(),
                "gap": num(w.gap),
                "floors": w.levels.iter().map(|l| l.floor()).collect::<Vec<_>>(),
            });
            site_totals(&mut v, &w.contact, &w.bumper, w.seat, wr);
            if let Some(e) = delivered(r, k) {
                v["e_delivered"] = e;
            }
            Some(v)
        })
        .collect();
    let devices: Vec<Value> = s
        .devices()
        .iter()
        .zip(&r.devices)
        .map(|(d, dr)| {
            let between = match d.ends {
                DeviceEnds::Buildings { left, right } => [
                    s.buildings()[left].name.clone(),
                    s.buildings()[right].name.clone(),
                ],
                DeviceEnds::Wall { site } => {
                    let w = &s.sites()[site];
                    let b = match w.kind {
                        SiteKind::Wall { building, .. }
                        | SiteKind::Between { left: building, .. } => building,
                    };
                    [s.buildings()[b].name.clone(), w.name.clone()]
                }
            };
            let mut v = json!({
                "name": d.name,
                "between": between,
                "floors": d.floors.iter().map(|(i, j)| json!([i, j])).collect::<Vec<_>>(),
                "law": serde_json::to_value(&d.law).unwrap_or(Value::Null),
                "peak_force": nums(&dr.peak_force),
                "max_closing": nums(&dr.max_closing),
                "max_opening": nums(&dr.max_opening),
            });
            if let DeviceLaw::Restrainer(p) = &d.law {
                v["slack"] = num(p.slack);
            }
            v
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
        "walls": walls,
        "devices": devices,
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
        "units": units(),
    })
}

/// The unit of every number of a summary.
fn units() -> Value {
    json!({
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
        "max_closing": "m (largest u_left - u_right of each floor pair; for a wall, towards it)",
        "max_opening": "m (largest u_right - u_left of each floor pair; for a wall, away from it)",
        "seat": "m", "unseated": "largest opening > seat", "consumed": "impacts of the hard law behind a consumed bumper",
        "bumper.thickness": "m", "isolator.peak_displacement": "m (peak |drift| of storey 1)", "isolator.clearance": "m",
        "devices.law": "stiffness N/m, damping N s/m, slack m", "devices.peak_force": "N (elastic and viscous)",

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

/// A law serialised as `{"Variant": {fields}}`, flattened into `{"model": name, fields}`.
fn flat_law(name: &str, v: Value) -> Value {
    let mut out = serde_json::Map::new();
    out.insert("model".into(), json!(name));
    if let Value::Object(o) = v {
        for (_, inner) in o {
            if let Value::Object(fields) = inner {
                out.extend(fields);
            }
        }
    }
    Value::Object(out)
}

/// The contact law, bumper, seat and totals of a link or a wall, into `v`.
/// The smallest and largest delivered e of a contact's or wall's ended impacts ([`Results::delivered_e`]),
/// with a word on why they differ from the e asked of it; `None` without such impacts (the key is left out:
/// a result file holds no null).
fn delivered(r: &Results, site: usize) -> Option<Value> {
    let (lo, hi) = r.delivered_e(site)?;
    Some(json!({
        "min": num(lo),
        "max": num(hi),
        "note": "separation over approach velocity; the calibration is exact for two free bodies, and the storey, \
                 damping and other forces on the floors act during each contact (docs/verification.md, \
                 \"Impacts inside a run\")",
    }))
}

fn site_totals(
    v: &mut Value,
    contact: &PreparedContact,
    bumper: &Option<Bumper>,
    seat: Option<f64>,
    r: &SiteResponse,
) {
    law(v, contact);
    if let Some(b) = bumper {
        let mut bv = json!({ "thickness": num(b.thickness), "max_strain": num(b.max_strain) });
        law(&mut bv, &b.contact);
        v["bumper"] = bv;
        v["consumed"] = json!(r.consumed);
    }
    v["impacts"] = json!(r.impacts);
    v["peak_force"] = num(r.peak_force);
    v["max_penetration"] = num(r.max_penetration);
    v["dissipated_energy"] = num(r.dissipated_energy);
    v["max_closing"] = json!(nums(&r.max_closing));
    v["max_opening"] = json!(nums(&r.max_opening));
    if let (Some(seat), Some(u)) = (seat, r.unseated) {
        v["seat"] = num(seat);
        v["unseated"] = json!(u);
    }
}

/// A contact law's model, e, stiffness, exponent and damping parameter, into `v`.
fn law(v: &mut Value, contact: &PreparedContact) {
    let spec = contact.spec();
    let param = contact.parameter().and_then(|p| p.named());
    v["model"] = json!(spec.model().name());
    v["e"] = num(spec.restitution());
    v["stiffness"] = num(spec.stiffness());
    v["exponent"] = num(spec.exponent());
    v["damping_parameter"] = match (contact.parameter(), param) {
        (None, _) => json!({ "name": "per-impact" }),
        (Some(_), None) => json!({ "name": "none" }),
        (Some(_), Some((n, x))) => json!({ "name": n, "value": num(x) }),
    };
}

fn nums(xs: &[f64]) -> Vec<Value> {
    xs.iter().copied().map(num).collect()
}
