//! The report's summary: the ground motion, the analysis, each building, isolator, wall and contact in a
//! line, and the energy balance.

use super::markup::{dl, e, kj, mm, mn, n};
use crate::output::fmt_sig;
use crate::plot::axis::plain;
use pounding::structure::Form;
use pounding_study::summary::inside::{inside, Meeting};
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
    let given = match &b.matrices {
        Some(m) => format!(", given by its matrices ({} damping)", m.damping),
        None => String::new(),
    };
    format!(
        "{} storey{} ({}{given}), T1 = {} s, roof peak displacement {} mm{most}",
        b.storeys,
        if b.storeys == 1 { "" } else { "s" },
        e(&models(b)),
        n(b.periods[0]),
        mm(peak)
    )
}

/// A contact or wall in a line, and whether the e it delivered differs from the e asked (with a bumper, the
/// bumper's and the law's behind it).
fn contact(c: &SiteSummary) -> (String, bool) {
    let asked: Vec<f64> = c
        .bumper
        .iter()
        .filter_map(|b| b.law.e)
        .chain(c.law.e)
        .collect();
    let (delivered, differs) = match &c.e_delivered {
        Some(d) => (
            format!(", delivered {} to {}", plain(d.min, 3), plain(d.max, 3)),
            !asked.is_empty()
                && [d.min, d.max]
                    .iter()
                    .any(|x| asked.iter().all(|e| (x - e).abs() > 0.01)),
        ),
        None => (String::new(), false),
    };
    let asked = match (c.bumper.as_ref().map(|b| b.law.e), c.law.e) {
        (None, Some(e)) => format!("e asked {}", n(e)),
        (None, None) => "elastic".to_string(),
        (Some(Some(b)), Some(e)) => {
            format!("e asked {} of the bumper and {} behind it", n(b), n(e))
        }
        (Some(Some(b)), None) => format!("e asked {} of the bumper, elastic behind it", n(b)),
        (Some(None), Some(e)) => format!("an elastic bumper, e asked {} behind it", n(e)),
        (Some(None), None) => "an elastic bumper, elastic behind it".to_string(),
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
    // Each wall and contact: its impacts, with the e asked of it and the range its impacts delivered.
    let mut differ = Vec::new();
    for c in &s.sites {
        let (line, d) = contact(c);
        if d {
            differ.push(Meeting::of_summary(s, c));
        }
        match &c.place {
            SitePlace::Wall { .. } => dl(h, &format!("wall {}", c.name), line),
            SitePlace::Contact { between } => {
                dl(h, &format!("contact {}", between.join("|")), line)
            }
        }
    }
    if !differ.is_empty() {
        let w = inside(&differ);
        dl(
            h,
            "why delivered e differs from e asked",
            format!(
                "delivered e is the separation over the approach velocity of each impact. The calibration is \
                 exact for two free bodies; in a contact {}, {}, the damping and every other force on the {} \
                 act during each contact, and can even {} (e above 1). The energy balance still holds \
                 (docs/verification.md, \"Impacts inside a run\").",
                w.contact, w.forces, w.masses, w.part
            ),
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
