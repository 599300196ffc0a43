//! The report's tables: modal properties, peak response of floors and storeys, contacts, devices, energy.

use super::markup::{e, kj, mm, mn, n, secs, table};
use crate::plot::axis::plain;
use pounding::structure::Form;
use pounding_study::summary::inside::hysteresis_of;
use pounding_study::summary::{
    BuildingSummary, ContactLawSummary, DampingSummary, RunSummary, SitePlace, SiteSummary,
};

/// The modal properties of each building.
pub fn modes(h: &mut String, s: &RunSummary) {
    h.push_str("\n<h2 id=\"modes\">Modal properties</h2>");
    for (k, b) in s.buildings.iter().enumerate() {
        if let Some(p) = &b.plan {
            super::plan::modes(h, k, b, p);
            continue;
        }
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
                match b.form() {
                    Form::Deck => "shape (one mass)",
                    _ => "shape, floor 1 up (largest |component| = 1)",
                },
            ],
            &rows,
        );
    }
}

/// The peak response: floors (a bridge's decks), then the storeys of each building (a deck's bearings).
pub fn response(h: &mut String, s: &RunSummary) {
    h.push_str("\n<h2 id=\"response\">Peak response</h2>");
    let decks = s
        .buildings
        .iter()
        .filter(|b| b.form() == Form::Deck)
        .count();
    // The words of the structures and their masses: buildings' floors, decks, or both.
    let (who, each) = match decks {
        0 => ("building", "each floor"),
        d if d == s.buildings.len() => ("deck", "each deck"),
        _ => ("structure", "each floor and deck"),
    };
    let only_decks = who == "deck";
    let mut rows = Vec::new();
    for b in &s.buildings {
        let name = e(&b.name);
        for f in 0..b.storeys {
            let mut row = vec![name.clone()];
            if !only_decks {
                row.push(match b.form() {
                    Form::Deck => "deck".to_string(),
                    _ => (f + 1).to_string(),
                });
            }
            row.extend([
                mm(b.peak_displacement[f]),
                secs(b.time_of_peak_displacement[f]),
                n(b.peak_absolute_acceleration[f]),
                secs(b.time_of_peak_absolute_acceleration[f]),
                mm(b.residual_displacement[f]),
            ]);
            rows.push(row);
        }
    }
    let mut head = vec![who];
    if !only_decks {
        head.push("floor");
    }
    head.extend([
        "peak displacement (mm)",
        "at (s)",
        "peak absolute acceleration (m/s²)",
        "at (s)",
        "residual displacement (mm)",
    ]);
    table(
        h,
        "peaks",
        &format!(
            "Largest displacement (relative to the ground) and absolute acceleration of {each}"
        ),
        &head,
        &rows,
    );
    for (k, b) in s.buildings.iter().enumerate() {
        match b.form() {
            Form::Deck => bearings(h, k, b),
            _ => storeys(h, k, b),
        }
        if let Some(p) = &b.plan {
            super::plan::response(h, k, b, p);
        }
    }
}

/// The storeys of building `b` (the `k`-th structure), an isolator's among them.
fn storeys(h: &mut String, k: usize, b: &BuildingSummary) {
    let rows: Vec<Vec<String>> = (0..b.storeys)
        .map(|j| {
            // Ductility, yield force and hysteretic energy are listed for the inelastic storeys only.
            let at = b.inelastic_storeys.iter().position(|&i| i == j + 1);
            let only = |v: &[f64], f: fn(f64) -> String| at.map_or(String::new(), |i| f(v[i]));
            // An isolator is storey 1; its drift over its height is no drift ratio.
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
    let inelastic = if b.isolator.is_some() {
        "inelastic storeys and isolator only"
    } else {
        "inelastic storeys only"
    };
    table(
        h,
        &format!("storeys-{k}"),
        &format!(
            "Storeys of building {} (shear: the restoring force; ductility: peak drift / yield drift, {inelastic})",
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

/// The bearings of deck `b` (the `k`-th structure): one row, displacements and forces (no storey, no drift
/// ratio).
fn bearings(h: &mut String, k: usize, b: &BuildingSummary) {
    // Yield force, ductility and hysteretic energy for bearings that can yield only.
    let yields = b.inelastic_storeys.first() == Some(&1);
    let only = |v: &[f64], f: fn(f64) -> String| {
        v.first()
            .filter(|_| yields)
            .map_or(String::new(), |&x| f(x))
    };
    let row = vec![
        e(b.storey_models[0].name()),
        mm(b.peak_drift[0]),
        mn(b.peak_storey_shear[0]),
        mm(b.residual_drift[0]),
        only(&b.yield_forces, mn),
        only(&b.ductility, |mu| format!("{mu:.3}")),
        only(&b.hysteretic_energy, kj),
    ];
    table(
        h,
        &format!("storeys-{k}"),
        &format!(
            "Bearings of deck {} (displacement relative to the ground; force: the restoring force; ductility: \
             peak displacement / yield displacement, bearings that yield only)",
            b.name
        ),
        &[
            "model",
            "peak displacement (mm)",
            "peak force (MN)",
            "residual displacement (mm)",
            "yield force (MN)",
            "ductility",
            "hysteretic energy (kJ)",
        ],
        &[row],
    );
}

/// Whether every structure of the run is a deck (one mass each: tables drop their floor numbers).
fn decks_only(s: &RunSummary) -> bool {
    s.buildings.iter().all(|b| b.form() == Form::Deck)
}

/// One site's rows of the contacts table (without its floors when `decks`: every structure is a deck): the
/// site with its law, and a bumper's layer with its own.
fn site_rows(c: &SiteSummary, decks: bool) -> Vec<Vec<String>> {
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
    let seat = match (c.seat, c.unseated) {
        (Some(x), Some(true)) => format!("{}: UNSEATED", mm(x)),
        (Some(x), _) => format!("{}: seated", mm(x)),
        _ => "–".into(),
    };
    let impacts = match c.consumed {
        Some(k) => format!("{} (bumper consumed {k})", c.impacts),
        None => c.impacts.to_string(),
    };
    // With a bumper, the site's row gives the law behind it; the bumper's own row follows.
    let label = match c.bumper {
        Some(_) => format!("{label}, behind its bumper"),
        None => label,
    };
    let mut row = vec![e(&label), mm(c.gap)];
    if !decks {
        row.push(floors.join(", "));
    }
    row.extend(law_cells(&c.law));
    row.extend([
        impacts,
        mn(c.peak_force),
        mm(c.max_penetration),
        kj(c.dissipated_energy),
        plain(c.largest_opening() * 1e3, 4),
        seat,
    ]);
    let mut rows = vec![row];
    if let Some(b) = &c.bumper {
        // The layer: its thickness, where its face is, its law; the site's totals are on the row above.
        let mut row = vec![
            e(&format!(
                "bumper of {}: {} mm thick, consumed at strain {}",
                c.name,
                mm(b.thickness),
                n(b.max_strain)
            )),
            format!("{} (its face)", mm(c.gap - b.thickness)),
        ];
        if !decks {
            row.push(floors.join(", "));
        }
        row.extend(law_cells(&b.law));
        row.push(format!("{} on its face", c.impacts));
        row.extend(std::iter::repeat_n(String::new(), 5));
        rows.push(row);
    }
    rows
}

/// The model, e, stiffness and damping cells of a contact law.
fn law_cells(law: &ContactLawSummary) -> [String; 4] {
    let param = match law.damping_parameter {
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
    // A law asked no one e: a table of e against v_i, a damping constant, Thornton's plastic spheres.
    let e_cell = match (law.e, &law.e_table, law.damping_parameter) {
        (Some(e), _, _) => n(e),
        (None, Some(_), _) => "table e(v_i)".to_string(),
        (None, None, DampingSummary::DampingConstant { .. }) => "from D/K at v_i".to_string(),
        (None, None, DampingSummary::YieldPressure { .. }) => "plastic".to_string(),
        _ => "elastic".to_string(),
    };
    [
        e(law.model.name()),
        e_cell,
        format!("{} (n = {})", n(law.stiffness), n(law.exponent)),
        param,
    ]
}

/// The contacts, the devices and the energy at the end.
pub fn contacts(h: &mut String, s: &RunSummary) {
    h.push_str("\n<h2 id=\"contacts\">Contacts and energy</h2>");
    // Contacts between neighbours, then walls.
    let decks = decks_only(s);
    let rows: Vec<Vec<String>> = (s.sites.iter().filter(|c| !c.is_wall()))
        .chain(s.sites.iter().filter(|c| c.is_wall()))
        .flat_map(|c| site_rows(c, decks))
        .collect();
    let mut head = vec!["contact", "gap (mm)"];
    if !decks {
        head.push("floors");
    }
    head.extend([
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
    ]);
    let caption = if s.sites.iter().any(|c| c.bumper.is_some()) {
        "Contacts (a bumper on its own row under its site, with its own law; the site's row gives the law \
         behind the bumper and the site's totals)"
    } else {
        "Contacts"
    };
    table(h, "contacts", caption, &head, &rows);
    devices(h, s);
    let en = &s.energy;
    // What yields: storeys, isolators, a bridge's bearings.
    let hysteresis = format!("{} hysteresis", hysteresis_of(&s.buildings));
    table(
        h,
        "energy",
        &format!(
            "Energy at the end of the analysis (kJ): input = kinetic + strain + structural damping + {hysteresis} + contact"
        ),
        &[
            "input",
            "kinetic",
            "strain",
            "structural damping",
            &hysteresis,
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
    let decks = decks_only(s);
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
            let mut row = vec![e(&d.name), e(&d.between.join("|"))];
            if !decks {
                row.push(pairs.join(", "));
            }
            row.extend([
                e(&law.join(", ")),
                peaks(&d.peak_force, mn),
                peaks(&d.max_closing, mm),
                peaks(&d.max_opening, mm),
            ]);
            row
        })
        .collect();
    let mut head = vec!["device", "between"];
    if !decks {
        head.push("floors");
    }
    head.extend([
        "law",
        "peak force (MN)",
        "largest closing (mm)",
        "largest opening (mm)",
    ]);
    if !rows.is_empty() {
        table(
            h,
            "devices",
            "Devices (law, SI: stiffness N/m, damping_coefficient N s/m, slack m)",
            &head,
            &rows,
        );
    }
}
