//! The report's summary: the ground motion, the analysis, each building, isolator, wall and contact in a
//! line, and the energy balance.

use super::markup::{dl, e, kj, mm, mn, n};
use crate::output::fmt_sig;
use crate::plot::axis::plain;
use pounding::structure::Form;
use pounding_study::summary::{BuildingSummary, RunSummary, SitePlace, SiteSummary};

/// A building's storey models in a few words: "linear", "bilinear", or "1-2 bilinear, 3 linear".
pub fn models(b: &BuildingSummary) -> String {
    let names: Vec<&str> = b.storey_models.iter().map(|m| m.name()).collect();
    if names.windows(2).all(|w| w[0] == w[1]) {
        return names.first().copied().unwrap_or("linear").to_string();
    }
    // Runs of storeys with the same model.
    let mut runs: Vec<(usize, usize, &str)> = Vec::new();
    for (j, m) in names.iter().enumerate() {
        match runs.last_mut() {
            Some(r) if r.2 == *m => r.1 = j + 1,
            _ => runs.push((j + 1, j + 1, m)),
        }
    }
    let runs: Vec<String> = runs
        .iter()
        .map(|(a, z, m)| {
            if a == z {
                format!("{a} {m}")
            } else {
                format!("{a}-{z} {m}")
            }
        })
        .collect();
    runs.join(", ")
}

/// A building in a line: storeys, models, T1, roof displacement, largest ductility of its storeys (an
/// isolator's is in its own line); a deck: its period and displacement.
fn building(b: &BuildingSummary) -> String {
    let peak = b.peak_displacement.last().copied().unwrap_or(0.0);
    if b.form() == Form::Deck {
        return format!(
            "T1 = {} s on its bearings, peak displacement {} mm",
            n(b.periods[0]),
            mm(peak)
        );
    }
    // The storey with the largest ductility, if any storey above any isolator is inelastic.
    let skip = b.ductility.len() - b.structural_ductility().len();
    let most = b
        .structural_ductility()
        .iter()
        .zip(&b.inelastic_storeys[skip..])
        .max_by(|a, c| a.0.total_cmp(c.0))
        .map(|(mu, j)| format!(", largest ductility {} (storey {j})", fmt_sig(*mu, 3)))
        .unwrap_or_default();
    format!(
        "{} storey{} ({}), T1 = {} s, roof peak displacement {} mm{most}",
        b.storeys,
        if b.storeys == 1 { "" } else { "s" },
        e(&models(b)),
        n(b.periods[0]),
        mm(peak)
    )
}

/// A contact in a line, and whether the e it delivered differs from the e asked.
fn contact(c: &SiteSummary) -> (String, bool) {
    let (delivered, differs) = match &c.e_delivered {
        Some(d) => (
            format!(", delivered {} to {}", plain(d.min, 3), plain(d.max, 3)),
            c.law
                .e
                .is_some_and(|e| (d.min - e).abs() > 0.01 || (d.max - e).abs() > 0.01),
        ),
        None => (String::new(), false),
    };
    let asked = match c.law.e {
        Some(e) => format!("e asked {}", n(e)),
        None => "elastic".to_string(),
    };
    let line = format!(
        "{}, {asked}{delivered}, peak force {} MN, dissipated {} kJ",
        pounding::words::count(c.impacts, "impact", None),
        mn(c.peak_force),
        kj(c.dissipated_energy)
    );
    (line, differs)
}

/// The summary section.
pub fn section(h: &mut String, s: &RunSummary) {
    h.push_str("\n<h2 id=\"summary\">Summary</h2>\n<dl class=\"summary\">");
    let rec = &s.record;
    dl(
        h,
        "ground motion",
        format!(
            "{} × {} ({} samples at {} s, PGA {} m/s²)",
            e(&rec.source),
            n(rec.scale),
            rec.npts,
            n(rec.dt),
            n(rec.pga)
        ),
    );
    dl(
        h,
        "analysis",
        format!(
            "{} s, output every {} s, tolerance {}",
            n(s.duration),
            n(s.output_dt),
            n(s.tolerance)
        ),
    );
    for b in &s.buildings {
        dl(h, &format!("{} {}", b.form().noun(), b.name), building(b));
    }
    for b in &s.buildings {
        if let Some(iso) = &b.isolator {
            let clearance = match (iso.clearance, iso.exceeds_clearance) {
                (Some(c), Some(true)) => format!(" against a clearance of {} mm: EXCEEDED", mm(c)),
                (Some(c), _) => format!(" against a clearance of {} mm", mm(c)),
                _ => String::new(),
            };
            // A bearing or isolator that yields: its ductility (storey 1 of the lists).
            let mu = match (b.inelastic_storeys.first(), b.ductility.first()) {
                (Some(1), Some(mu)) => format!(", ductility {}", fmt_sig(*mu, 3)),
                _ => String::new(),
            };
            dl(
                h,
                &format!("{} of {}", b.form().isolator_noun(), b.name),
                format!(
                    "{}, peak displacement {} mm{mu}{clearance}",
                    e(iso.model.name()),
                    mm(iso.peak_displacement)
                ),
            );
        }
    }
    for w in s.sites.iter().filter(|w| w.is_wall()) {
        dl(
            h,
            &format!("wall {}", w.name),
            format!(
                "{} impacts, peak force {} MN, dissipated {} kJ",
                w.impacts,
                mn(w.peak_force),
                kj(w.dissipated_energy)
            ),
        );
    }
    // Each contact's impacts, with the e asked of it and the range its impacts delivered.
    let mut differs = false;
    for c in &s.sites {
        if let SitePlace::Contact { between } = &c.place {
            let (line, d) = contact(c);
            differs |= d;
            dl(h, &format!("contact {}", between.join("|")), line);
        }
    }
    if differs {
        dl(
            h,
            "why delivered e differs from e asked",
            "delivered e is the separation over the approach velocity of each impact. The calibration is exact \
             for two free bodies; between floors, the storeys, the damping and every other force on the two floors \
             act during each contact, and can even part the floors faster than they met (e above 1). The energy \
             balance still holds (docs/verification.md, \"Impacts inside a run\")."
                .to_string(),
        );
    }
    dl(
        h,
        "energy balance error",
        format!(
            "{} (largest over the run, relative to the largest energy)",
            n(s.energy_balance_error)
        ),
    );
    h.push_str("\n</dl>");
}
