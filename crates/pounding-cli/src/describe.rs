//! Contact models in words: one line for a terminal or a figure, and the rows of a report.

use crate::args::{BodiesArgs, ModelArgs};
use crate::error::{flag, input, CliError};
use crate::output::{fmt_num, num, Report};
use pounding::contact::{
    AlphaRule, ContactModel, DampingParameter, Model, Restitution, RestitutionTable,
};
use pounding::impact::ImpactResult;
use serde_json::Value;

/// The contact specification of `a` with stiffness `k` (N/m^n).
pub fn contact(a: &ModelArgs, k: f64, radius: Option<f64>) -> Result<ContactModel, CliError> {
    let e = crate::restitution::asked(a.model, a.e, a.e_table.as_deref(), a.damping_constant)?;
    a.options(e, radius).build(k).map_err(|e| match e {
        pounding::contact::OptionError::Value(v) => CliError::from(v),
        other => input(other.message(flag)),
    })
}

pub use pounding::words::stiffness_unit;

/// One line describing a contact model and its damping: `papi, k = 2e9 N/m, e = 0.65, ...`.
pub fn contact_label(s: &ContactModel, p: Option<DampingParameter>) -> String {
    let asked = match (s.asked(), s.sphere()) {
        (_, Some(sp)) => format!(
            "elastic-plastic, R = {} m, p_y = {} Pa",
            fmt_num(sp.radius),
            fmt_num(sp.yield_pressure)
        ),
        (None, None) => "elastic".to_string(),
        (Some(Restitution::Constant(e)), None) => format!("e = {}", fmt_num(*e)),
        (Some(Restitution::Table(t)), None) => table_label(t),
        (Some(Restitution::DampingConstant(c)), None) => {
            format!("damping constant D/K = {} s/m", fmt_num(*c))
        }
    };
    let mut text = format!(
        "{}, k = {} {}, {asked}",
        s.model().name(),
        fmt_num(s.stiffness()),
        stiffness_unit(s.exponent()),
    );
    // A damping constant is the damping itself: nothing calibrated, no formula.
    let material = matches!(s.asked(), Some(Restitution::DampingConstant(_)));
    if s.model().is_damped() && !material {
        text.push_str(&format!(", damping {}", s.damping()));
        if s.model() == Model::Papi {
            text.push_str(&format!(", {} reading", s.reading()));
        }
        match p {
            Some(DampingParameter::Papi { alpha, chi, chi_r }) => text.push_str(&format!(
                " (alpha = {}, chi = {}, chi_r = {})",
                fmt_num(alpha),
                fmt_num(chi),
                fmt_num(chi_r)
            )),
            Some(other) => {
                if let Some((name, v)) = other.named() {
                    text.push_str(&format!(" ({name} = {})", fmt_num(v)));
                }
            }
            None => text.push_str(" (set per impact)"),
        }
    }
    text.push_str(&format!(", tension {}", s.tension()));
    text
}

/// A table e(v_i) in a few words: "e from 3 rows, 0.8 at 0.1 m/s to 0.5 at 2 m/s".
pub fn table_label(t: &RestitutionTable) -> String {
    let p = t.points();
    let (first, last) = (p[0], p[p.len() - 1]);
    format!(
        "e from {} (held beyond: {} at {} m/s to {} at {} m/s)",
        pounding::words::count(p.len(), "row", None),
        fmt_num(first.1),
        fmt_num(first.0),
        fmt_num(last.1),
        fmt_num(last.0)
    )
}

/// Adds the damping parameter by its name (for papi: alpha and the factors chi, chi_r).
pub fn parameter(rep: &mut Report, p: DampingParameter) {
    match p {
        DampingParameter::Papi { alpha, chi, chi_r } => {
            rep.add("alpha", num(alpha), "")
                .add("chi", num(chi), "")
                .add("chi_r", num(chi_r), "");
        }
        other => {
            if let Some((name, v)) = other.named() {
                // The dimensional parameters: a material damping constant and a yield pressure.
                let unit = match other {
                    DampingParameter::DampingConstant(_) => "s/m",
                    DampingParameter::Yield(_) => "Pa",
                    _ => "",
                };
                rep.add(name, num(v), unit);
            }
        }
    }
}

/// Adds the model description and its damping parameter to a report.
pub fn describe(rep: &mut Report, s: &ContactModel, p: DampingParameter) {
    rep.add("model", s.model().name(), "")
        .add_shown(
            "k",
            num(s.stiffness()),
            format!(
                "{} {}",
                fmt_num(s.stiffness()),
                stiffness_unit(s.exponent())
            ),
            "",
        )
        .add("n", num(s.exponent()), "")
        .add("tension", s.tension().name(), "");
    if s.model().is_damped() {
        rep.add("damping", s.damping().name(), "");
    }
    if s.model() == Model::Papi {
        let rule = match s.alpha_rule() {
            AlphaRule::Given(_) => "given",
            AlphaRule::Eq8 => "eq8",
            AlphaRule::Calibrate => "calibrate",
        };
        rep.add("reading", s.reading().name(), "")
            .add("alpha_rule", rule, "");
    }
    parameter(rep, p);
}

/// Adds the results of one impact to a report.
pub fn results(
    rep: &mut Report,
    s: &ContactModel,
    (r, v_i): (&ImpactResult, f64),
    exact_e: Option<f64>,
) {
    // An elastic model is asked for no e; a table or a damping constant asks e(v_i) of this impact.
    if let Some(asked) = s.asked() {
        rep.add("e_pre", num(asked.at(v_i)), "");
    }
    rep.add("e_post", num(r.e_post), "")
        .add("e_post_exact", exact_e.map_or(Value::Null, num), "")
        .add("peak_force", num(r.peak_force), "N")
        .add("time_of_peak_force", num(r.time_of_peak_force), "s")
        .add("max_penetration", num(r.max_penetration), "m")
        .add("contact_duration", num(r.contact_duration), "s")
        .add("dissipated_energy", num(r.dissipated_energy), "J")
        .add("impulse", num(r.impulse), "N s")
        .add("steps", r.steps, "");
}

/// The two bodies in one line: `m1 = 100000 kg, m2 rigid, v = 1 m/s`.
pub fn bodies_text(b: &BodiesArgs) -> String {
    format!(
        "m1 = {} kg, {}, v = {} m/s",
        fmt_num(b.m1),
        m2_text(b.m2),
        fmt_num(b.v)
    )
}

/// `m2` as text: `m2 = 3e5 kg`, or `m2 rigid` for an infinite mass (JSON: null).
fn m2_text(m2: f64) -> String {
    if m2.is_infinite() {
        "m2 rigid".into()
    } else {
        format!("m2 = {} kg", fmt_num(m2))
    }
}
