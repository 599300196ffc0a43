//! `pounding models`: every contact model with its force law, damping formula and source.

use crate::error::CliError;
use pounding::contact::MODELS;
use serde_json::{json, Value};

pub fn run(json: bool) -> Result<(), CliError> {
    if json {
        let list: Vec<Value> = MODELS
            .iter()
            .map(|i| {
                json!({
                    "name": i.name, "family": i.family, "default_n": i.default_n, "tension": i.tension,
                    "restitution_damped": i.restitution_damped, "force_law": i.force_law,
                    "damping_formula": i.damping_formula, "parameter": i.parameter, "source": i.source,
                })
            })
            .collect();
        println!("{}", json!({ "models": list }));
        return Ok(());
    }
    println!("Contact models (d penetration in m, v = d' in m/s, v_i impact velocity, k in N/m^n, m effective mass in kg)\n");
    for i in &MODELS {
        println!(
            "{}  (n = {}, tension: {}{})",
            i.name,
            i.default_n,
            i.tension,
            i.parameter.map_or(String::new(), |p| format!(
                ", exact calibration adjusts {p}"
            ))
        );
        println!("    force:   {}", i.force_law);
        println!("    damping: {}", i.damping_formula);
        println!("    source:  {}", i.source);
    }
    Ok(())
}
