//! `pounding compare`: several contact models on one impact, a table and their force histories.

use crate::args::CompareArgs;
use crate::describe::bodies_text;
use crate::error::{flag, impact_scales, input, CliError};
use crate::files::{check_out, save_out};
use crate::output::{fmt_num, fmt_sig, num};
use crate::plot::figures::{self, ForceHistory};
use pounding::contact::{ContactOptions, Model, OptionError};
use pounding::impact::{simulate, ImpactOptions, TwoBodies};
use serde_json::{json, Value};

pub fn run(a: &CompareArgs) -> Result<(), CliError> {
    check_out(&a.out)?;
    let bodies = TwoBodies::new(a.bodies.m1, a.bodies.m2, a.bodies.v)?;
    if !(a.k.is_finite() && a.k > 0.0) {
        return Err(input(format!(
            "--k {} is not allowed: k > 0 (N/m^1.5)",
            a.k
        )));
    }
    let setup = bodies.setup();
    // The e of this impact: the one given, or the table read at its velocity.
    let e = match (&a.e_table, a.e) {
        (Some(path), _) => crate::restitution::read_e_table(path)?.at(setup.v_i),
        (None, Some(e)) => e,
        (None, None) => return Err(input("--e or --e-table is required")),
    };
    let opts = ImpactOptions {
        history: true,
        ..ImpactOptions::default()
    };
    if (a.radius.is_some() || a.yield_pressure.is_some()) && !a.models.contains(&Model::Thornton) {
        return Err(input(
            "--radius and --yield-pressure are not allowed without thornton in --models: they are its spheres'",
        ));
    }
    let b = a.bodies;
    let given = [("m1", b.m1), ("m2", b.m2), ("v", b.v), ("k", a.k)];
    let scales = impact_scales(&given, super::impact::TWO_BODIES);
    let mut runs = Vec::new();
    for &model in &a.models {
        let n = model.info().default_n;
        let k = pounding::impact::equivalent_stiffness(a.k, setup.mass, setup.v_i, n);
        // The stiffness of the model's exponent that matches --k at this impact: beyond f64, so are the
        // impact's scales (it is not --k that is wrong).
        if !(k.is_finite() && k > 0.0) {
            return Err(scales(pounding::Error::ScaleOutOfRange {
                mass: setup.mass,
                v_i: setup.v_i,
                k,
                n,
            }));
        }
        // Thornton's spheres take the radius and yield pressure; the other models are asked e.
        let thornton = model == Model::Thornton;
        let options = ContactOptions {
            damping: a.damping,
            radius: a.radius.filter(|_| thornton),
            yield_pressure: a.yield_pressure.filter(|_| thornton),
            ..ContactOptions::new(model, e)
        };
        let s = options.build(k).map_err(|e| match e {
            OptionError::Value(v) => CliError::from(v),
            other => input(other.message(flag)),
        })?;
        let (law, _) = s.prepare()?.law(setup.mass, setup.v_i).map_err(&scales)?;
        let r = simulate(&law, s.tension(), &setup, &opts).map_err(&scales)?;
        runs.push((s, r));
    }
    let damping = a.damping.name();
    let rows: Vec<Value> = runs
        .iter()
        .map(|(s, r)| {
            json!({
                "model": s.model().name(), "n": num(s.exponent()), "k": num(s.stiffness()),
                "e_post": num(r.e_post), "peak_force": num(r.peak_force),
                "time_of_peak_force": num(r.time_of_peak_force), "max_penetration": num(r.max_penetration),
                "contact_duration": num(r.contact_duration), "dissipated_energy": num(r.dissipated_energy),
            })
        })
        .collect();
    let result = json!({
        "e_pre": num(e), "damping": damping, "k_hertz": num(a.k), "m1": num(a.bodies.m1),
        "m2": if a.bodies.m2.is_finite() { num(a.bodies.m2) } else { Value::Null }, "v": num(a.bodies.v),
        "effective_mass": num(setup.mass),
        "units": {"k": "N/m^n", "k_hertz": "N/m^1.5", "peak_force": "N", "time_of_peak_force": "s",
                  "max_penetration": "m", "contact_duration": "s", "dissipated_energy": "J",
                  "m1": "kg", "m2": "kg (null: rigid)", "v": "m/s", "effective_mass": "kg"},
        "models": rows,
    });
    if a.json {
        println!("{result}");
    } else {
        println!(
            "One impact: {}, e_pre = {}, damping {damping}; k_h = {} N/m^1.5",
            bodies_text(&a.bodies),
            fmt_num(e),
            fmt_num(a.k)
        );
        println!(
            "(models with n != 1.5 use k_h d_h^(1.5 - n), d_h the elastic Hertz penetration)\n"
        );
        println!(
            "{:<22} {:>4} {:>13} {:>10} {:>13} {:>12} {:>17} {:>19}",
            "model",
            "n",
            "k_N_per_m^n",
            "e_post",
            "peak_force_N",
            "duration_s",
            "max_penetration_m",
            "dissipated_energy_J"
        );
        for (s, r) in &runs {
            println!(
                "{:<22} {:>4} {:>13.5e} {:>10.6} {:>13.6e} {:>12.6e} {:>17.6e} {:>19.6e}",
                s.model().name(),
                s.exponent(),
                s.stiffness(),
                r.e_post,
                r.peak_force,
                r.contact_duration,
                r.max_penetration,
                r.dissipated_energy
            );
        }
    }
    let mut figs = Vec::new();
    if a.out.figures.plots {
        let histories: Vec<ForceHistory> = runs
            .iter()
            .filter_map(|(s, r)| {
                r.history.as_ref().map(|h| ForceHistory {
                    label: format!("{} (e_post {})", s.model().name(), fmt_sig(r.e_post, 4)),
                    t: &h.t,
                    penetration: &h.penetration,
                    force: &h.force,
                })
            })
            .collect();
        let subtitle = format!(
            "e_pre = {1}, {damping} damping; {0}; k_h = {2} N/m^1.5 (models of n \u{2260} 1.5: the equivalent k)",
            bodies_text(&a.bodies),
            fmt_num(e),
            fmt_num(a.k)
        );
        figs = figures::impact(
            "compare",
            "Contact models on one impact",
            &subtitle,
            &histories,
        );
    }
    save_out(&a.out, ("compare", &result), Vec::new(), &figs, a.json)
}
