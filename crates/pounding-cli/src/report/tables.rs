//! The report's tables: modal properties, peak response of floors and storeys, contacts, devices, energy.

use super::markup::{e, kj, mm, mn, n, secs, table};
use crate::plot::axis::plain;
use pounding::structure::Form;
use pounding_study::summary::{DampingSummary, RunSummary, SitePlace, SiteSummary};

/// The modal properties of each building.
pub fn modes(h: &mut String, s: &RunSummary) {
    h.push_str("\n<h2 id=\"modes\">Modal properties</h2>");
    for (k, b) in s.buildings.iter().enumerate() {
        let rows: Vec<Vec<String>> = b
            .periods
            .iter()
            .enumerate()
            .map(|(r, t)| {
                let shape: Vec<String> =
                    b.mode_shapes[r].iter().map(|x| format!("{x:.3}")).collect();
                vec![
                    (r + 1).to_string(),
                    format!("{t:.4}"),
                    format!("{:.2}", 100.0 * b.modal_damping_ratios[r]),
                    format!("{:.1}", 100.0 * b.effective_modal_mass_ratios[r]),
                    shape.join(" "),
                ]
            })
            .collect();
        table(
            h,
            &format!("modes-{k}"),
            &match b.form() {
                Form::Deck => format!("Deck {} on its bearings", b.name),
                _ => format!("Building {}", b.name),
            },
            &[
                "mode",
                "period (s)",
                "damping (%)",
                "effective mass (%)",
                "shape, floor 1 up (largest |component| = 1)",
            ],
            &rows,
        );
    }
}

/// The peak response: floors, then the storeys of each building.
pub fn response(h: &mut String, s: &RunSummary) {
    h.push_str("\n<h2 id=\"response\">Peak response</h2>");
    let mut rows = Vec::new();
    for b in &s.buildings {
        let name = e(&b.name);
        for f in 0..b.storeys {
            rows.push(vec![
                name.clone(),
                (f + 1).to_string(),
                mm(b.peak_displacement[f]),
                secs(b.time_of_peak_displacement[f]),
                n(b.peak_absolute_acceleration[f]),
                secs(b.time_of_peak_absolute_acceleration[f]),
                mm(b.residual_displacement[f]),
            ]);
        }
    }
    table(
        h,
        "peaks",
        "Largest displacement (relative to the ground) and absolute acceleration of each floor",
        &[
            "building",
            "floor",
            "peak displacement (mm)",
            "at (s)",
            "peak absolute acceleration (m/s²)",
            "at (s)",
            "residual displacement (mm)",
        ],
        &rows,
    );
    for (k, b) in s.buildings.iter().enumerate() {
        let rows: Vec<Vec<String>> = (0..b.storeys)
            .map(|j| {
                // Ductility, yield force and hysteretic energy are listed for the inelastic storeys only.
                let at = b.inelastic_storeys.iter().position(|&i| i == j + 1);
                let only = |v: &[f64], f: fn(f64) -> String| at.map_or(String::new(), |i| f(v[i]));
                // An isolator (a deck's bearings) is storey 1; its drift over its height is no drift ratio.
                let iso = j == 0 && b.isolator.is_some();
                vec![
                    if iso {
                        format!("1 ({})", b.form().isolator_noun())
                    } else {
                        (j + 1).to_string()
                    },
                    e(b.storey_models[j].name()),
                    mm(b.peak_drift[j]),
                    if iso {
                        "\u{2013}".to_string()
                    } else {
                        format!("{:.3}", 100.0 * b.peak_drift_ratio[j])
                    },
                    mn(b.peak_storey_shear[j]),
                    mm(b.residual_drift[j]),
                    only(&b.yield_forces, mn),
                    only(&b.ductility, |mu| format!("{mu:.3}")),
                    only(&b.hysteretic_energy, kj),
                ]
            })
            .collect();
        table(
            h,
            &format!("storeys-{k}"),
            &format!(
                "{} of {} {} (shear: the restoring force; ductility: peak drift / yield drift, inelastic storeys only)",
                match b.form() {
                    Form::Deck => "Bearings",
                    _ => "Storeys",
                },
                b.form().noun(),
                b.name
            ),
            &[
                "storey",
                "model",
                "peak drift (mm)",
                "drift ratio (%)",
                "peak shear (MN)",
                "residual drift (mm)",
                "yield force (MN)",
                "ductility",
                "hysteretic energy (kJ)",
            ],
            &rows,
        );
    }
}

/// One site's row of the contacts table.
fn site_row(c: &SiteSummary) -> Vec<String> {
    let label = match &c.place {
        SitePlace::Contact { between } => between.join("|"),
        SitePlace::Wall { facing, side } => {
            format!("wall {} ({} of {facing})", c.name, side.name())
        }
    };
    let floors: Vec<String> = c
        .levels
        .iter()
        .map(|l| match (l.left, l.right) {
            (Some(a), Some(b)) => format!("{a}-{b}"),
            (Some(f), None) | (None, Some(f)) => f.to_string(),
            (None, None) => String::new(),
        })
        .collect();
    let param = match c.law.damping_parameter {
        DampingSummary::None => "none (elastic)".into(),
        DampingSummary::PerImpact => "set per impact".into(),
        DampingSummary::Zeta { value } => format!("zeta = {}", n(value)),
        DampingSummary::Chi { value } => format!("chi = {}", n(value)),
        DampingSummary::Alpha { value } => format!("alpha = {}", n(value)),
        DampingSummary::Xi { value } => format!("xi = {}", n(value)),
        DampingSummary::EDesign { value } => format!("e_design = {}", n(value)),
        DampingSummary::DampingConstant { value } => format!("D/K = {} s/m", n(value)),
        DampingSummary::YieldPressure { value, radius } => {
            format!("p_y = {} Pa, R = {} m", n(value), n(radius))
        }
    };
    let seat = match (c.seat, c.unseated) {
        (Some(x), Some(true)) => format!("{}: UNSEATED", mm(x)),
        (Some(x), _) => format!("{}: seated", mm(x)),
        _ => "–".into(),
    };
    let impacts = match c.consumed {
        Some(k) => format!("{} (bumper consumed {k})", c.impacts),
        None => c.impacts.to_string(),
    };
    vec![
        e(&label),
        mm(c.gap),
        floors.join(", "),
        e(c.law.model.name()),
        c.law.e.map_or_else(|| "elastic".to_string(), n),
        format!("{} (n = {})", n(c.law.stiffness), n(c.law.exponent)),
        param,
        impacts,
        mn(c.peak_force),
        mm(c.max_penetration),
        kj(c.dissipated_energy),
        plain(c.largest_opening() * 1e3, 4),
        seat,
    ]
}

/// The contacts, the devices and the energy at the end.
pub fn contacts(h: &mut String, s: &RunSummary) {
    h.push_str("\n<h2 id=\"contacts\">Contacts and energy</h2>");
    // Contacts between neighbours, then walls.
    let rows: Vec<Vec<String>> = (s.sites.iter().filter(|c| !c.is_wall()))
        .chain(s.sites.iter().filter(|c| c.is_wall()))
        .map(site_row)
        .collect();
    table(
        h,
        "contacts",
        "Contacts",
        &[
            "contact",
            "gap (mm)",
            "floors",
            "model",
            "e",
            "k (N/m^n, SI)",
            "damping",
            "impacts",
            "peak force (MN)",
            "max penetration (mm)",
            "dissipated (kJ)",
            "largest opening (mm)",
            "seat (mm)",
        ],
        &rows,
    );
    devices(h, s);
    let en = &s.energy;
    table(
        h,
        "energy",
        "Energy at the end of the analysis (kJ): input = kinetic + strain + structural damping + storey hysteresis + contact",
        &[
            "input",
            "kinetic",
            "strain",
            "structural damping",
            "storey hysteresis",
            "contact",
            "balance error (relative)",
        ],
        &[vec![
            kj(en.input),
            kj(en.kinetic),
            kj(en.strain),
            kj(en.structural_damping),
            kj(en.hysteretic),
            kj(en.contact),
            n(s.energy_balance_error),
        ]],
    );
}

/// The devices table, if there are devices.
fn devices(h: &mut String, s: &RunSummary) {
    let rows: Vec<Vec<String>> = s
        .devices
        .iter()
        .map(|d| {
            let pairs: Vec<String> = d.floors.iter().map(|[a, b]| format!("{a}-{b}")).collect();
            let peaks = |v: &[f64], f: fn(f64) -> String| {
                v.iter().map(|&x| f(x)).collect::<Vec<_>>().join(", ")
            };
            let mut law = vec![d.law.name().to_string()];
            law.extend(
                d.law
                    .parameters()
                    .iter()
                    .map(|p| format!("{} {}", p.key, n(p.value))),
            );
            vec![
                e(&d.name),
                e(&d.between.join("|")),
                pairs.join(", "),
                e(&law.join(", ")),
                peaks(&d.peak_force, mn),
                peaks(&d.max_closing, mm),
                peaks(&d.max_opening, mm),
            ]
        })
        .collect();
    if !rows.is_empty() {
        table(
            h,
            "devices",
            "Devices (law, SI: stiffness N/m, damping_coefficient N s/m, slack m)",
            &[
                "device",
                "between",
                "floors",
                "law",
                "peak force (MN)",
                "largest closing (mm)",
                "largest opening (mm)",
            ],
            &rows,
        );
    }
}
