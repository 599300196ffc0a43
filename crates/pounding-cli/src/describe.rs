//! Contact models in words: one line for a terminal or a figure, and the rows of a report.

use crate::args::{BodiesArgs, ModelArgs};
use crate::error::{flag, input, CliError};
use crate::output::{fmt_num, num, Report};
use pounding::contact::{AlphaRule, ContactModel, DampingParameter, Model};
use pounding::impact::ImpactResult;
use serde_json::Value;

/// The contact specification of `a` with stiffness `k` (N/m^n).
pub fn contact(a: &ModelArgs, k: f64) -> Result<ContactModel, CliError> {
    match (a.model.is_damped(), a.e) {
        (true, None) => {
            return Err(input(format!(
                "--e is required by model {}: the coefficient of restitution it is to deliver, 0 < e <= 1",
                a.model.name()
            )))
        }
        (false, Some(e)) if e != 1.0 => {
            return Err(input(format!(
                "--e {} is not allowed with model {}: it is elastic and delivers e = 1 (leave --e out, or choose a damped model, see pounding models)",
                fmt_num(e),
                a.model.name()
            )))
        }
        _ => {}
    }
    a.options().build(k).map_err(|e| match e {
        pounding::contact::OptionError::Value(v) => CliError::from(v),
        other => input(other.message(flag)),
    })
}

/// The unit of a contact stiffness of exponent `n`: `N/m`, `N/m^1.5`.
pub fn stiffness_unit(n: f64) -> String {
    if n == 1.0 {
        "N/m".into()
    } else {
        format!("N/m^{}", fmt_num(n))
    }
}

/// One line describing a contact model and its damping: `papi, k = 2e9 N/m, e = 0.65, ...`.
pub fn contact_label(s: &ContactModel, p: Option<DampingParameter>) -> String {
    let asked = s
        .asked_restitution()
        .map_or_else(|| "elastic".to_string(), |e| format!("e = {}", fmt_num(e)));
    let mut text = format!(
        "{}, k = {} {}, {asked}",
        s.model().name(),
        fmt_num(s.stiffness()),
        stiffness_unit(s.exponent()),
    );
    if s.model().is_damped() {
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
                rep.add(name, num(v), "");
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
pub fn results(rep: &mut Report, s: &ContactModel, r: &ImpactResult, exact_e: Option<f64>) {
    // An elastic model is asked for no e.
    if let Some(e) = s.asked_restitution() {
        rep.add("e_pre", num(e), "");
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
