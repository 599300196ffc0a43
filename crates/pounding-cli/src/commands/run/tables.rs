//! What a run prints at its end: peak responses, the yielding storeys, the isolators, contact sites and
//! devices, and the energy balance (lengths in mm, forces in MN, energies in kJ).

use crate::output::{fmt_num, fmt_table};
use pounding::analysis::{Results, Scenario};
use pounding::contact::Restitution;
use pounding::structure::Form;
use pounding_study::summary::inside::{inside, Meeting};

/// Prints the results `r` of a run of `s`.
pub fn print(s: &Scenario, r: &Results) {
    floors(s, r);
    super::plan::peaks(s, r);
    super::plan::foundations(s, r);
    super::plan::columns(s, r);
    inelastic(s, r);
    isolators(s, r);
    sites(s, r);
    devices(s, r);
    energy(s, r);
}

/// Metres as millimetres, N as MN, J as kJ: the units of the terminal tables, the figures and the report.
fn mm(x: f64) -> String {
    fmt_table(1e3 * x, 4)
}
fn mn(x: f64) -> String {
    fmt_table(1e-6 * x, 4)
}
fn kj(x: f64) -> String {
    fmt_table(1e-3 * x, 4)
}

/// The word of the structures' column: "building", or "deck" when every structure is one, else "structure".
pub(super) fn who(s: &Scenario) -> &'static str {
    let decks = s
        .buildings()
        .iter()
        .filter(|b| b.structure.form() == Form::Deck)
        .count();
    match decks {
        0 => "building",
        d if d == s.buildings().len() => "deck",
        _ => "structure",
    }
}

/// The peak response of every floor and storey (of a bridge's decks: each deck and its bearings).
fn floors(s: &Scenario, r: &Results) {
    println!(
        "peak responses (lengths in mm, forces in MN, energies in kJ; the files hold m, N and J)\n"
    );
    let who = who(s);
    if who == "deck" {
        // One mass on its bearings: the bearings' displacement is the deck's.
        println!(
            "deck        displacement_mm    at_s  abs_acceleration_m_per_s2  bearing_force_MN"
        );
        for (b, resp) in s.buildings().iter().zip(&r.buildings) {
            println!(
                "{:<10}  {:>15}  {:>6.2}  {:>25}  {:>16}",
                b.name,
                mm(resp.peak_displacement[0]),
                resp.time_of_peak_displacement[0],
                fmt_table(resp.peak_absolute_acceleration[0], 4),
                mn(resp.peak_storey_shear[0])
            );
        }
        return;
    }
    println!(
        "{who:<10}  floor  displacement_mm    at_s  abs_acceleration_m_per_s2  storey  drift_mm  drift_ratio_%  shear_MN"
    );
    let mut isolated = false;
    for (b, resp) in s.buildings().iter().zip(&r.buildings) {
        let h = b.structure.heights();
        let form = b.structure.form();
        for (f, h_f) in h.iter().enumerate() {
            // An isolator's drift over its height is no drift ratio.
            let iso = f == 0 && form != Form::Building;
            isolated |= iso;
            println!(
                "{:<10}  {:>5}  {:>15}  {:>6.2}  {:>25}  {:>6}  {:>8}  {:>13}  {:>8}",
                b.name,
                if form == Form::Deck {
                    "deck".to_string()
                } else {
                    (f + 1).to_string()
                },
                mm(resp.peak_displacement[f]),
                resp.time_of_peak_displacement[f],
                fmt_table(resp.peak_absolute_acceleration[f], 4),
                storey_name(form, f),
                mm(resp.peak_drift[f]),
                if iso {
                    "-".to_string()
                } else {
                    format!("{:.3}", 100.0 * resp.peak_drift[f] / h_f)
                },
                mn(resp.peak_storey_shear[f])
            );
        }
    }
    if isolated {
        println!("(iso: the isolator, a deck's bearings; its drift is its displacement, see the isolator table)");
    }
}

/// Storey `j` (from 0) in a table's storey column: its number, or `iso` for an isolator (a deck's bearings).
fn storey_name(form: Form, j: usize) -> String {
    if j == 0 && form != Form::Building {
        "iso".to_string()
    } else {
        (j + 1).to_string()
    }
}

/// The storeys that yield (a bridge's: the bearings): ductility, residual drift, hysteretic energy.
fn inelastic(s: &Scenario, r: &Results) {
    let inelastic = s
        .buildings()
        .iter()
        .any(|b| b.structure.storey_laws().iter().any(|l| l.is_inelastic()));
    if !inelastic {
        return;
    }
    let who = who(s);
    if who == "deck" {
        println!(
            "\ndeck        bearings  ductility  residual_displacement_mm  hysteretic_energy_kJ"
        );
    } else {
        println!(
            "\n{who:<10}  storey  model     ductility  residual_drift_mm  hysteretic_energy_kJ"
        );
    }
    for (b, resp) in s.buildings().iter().zip(&r.buildings) {
        for (j, law) in b.structure.storey_laws().iter().enumerate() {
            let Some(mu) = resp.ductility[j] else {
                continue;
            };
            if who == "deck" {
                println!(
                    "{:<10}  {:<8}  {:>9.3}  {:>24}  {:>20}",
                    b.name,
                    law.name(),
                    mu,
                    mm(resp.residual_drift[j]),
                    kj(resp.hysteretic_energy[j])
                );
            } else {
                println!(
                    "{:<10}  {:>6}  {:<8}  {:>9.3}  {:>17}  {:>20}",
                    b.name,
                    storey_name(b.structure.form(), j),
                    law.name(),
                    mu,
                    mm(resp.residual_drift[j]),
                    kj(resp.hysteretic_energy[j])
                );
            }
        }
    }
}

/// The isolators (a bridge's bearings): their displacement against their clearance.
fn isolators(s: &Scenario, r: &Results) {
    let isolated: Vec<usize> = (0..s.buildings().len())
        .filter(|&b| s.buildings()[b].structure.isolator().is_some())
        .collect();
    if isolated.is_empty() {
        return;
    }
    let who = who(s);
    let what = if who == "deck" {
        "bearings"
    } else {
        "isolator"
    };
    println!("\n{who:<10}  {what:<17}  peak_displacement_mm  clearance_mm  residual_mm");
    for b in isolated {
        let (st, resp) = (&s.buildings()[b].structure, &r.buildings[b]);
        let iso = st.isolator().expect("isolated");
        let clearance = iso.clearance.map_or("-".to_string(), mm);
        let over = match iso.clearance {
            Some(c) if resp.peak_drift[0] > c => "  EXCEEDED",
            _ => "",
        };
        // Among isolated buildings, a deck's isolator is said to be its bearings.
        let model = match st.form() {
            Form::Deck if who != "deck" => format!("{} bearings", iso.model.name()),
            _ => iso.model.name().to_string(),
        };
        println!(
            "{:<10}  {:<17}  {:>20}  {:>12}  {:>11}{over}",
            s.buildings()[b].name,
            model,
            mm(resp.peak_drift[0]),
            clearance,
            mm(resp.residual_drift[0])
        );
    }
}

/// What a contact asks, for the e_asked column, and its one e if it has one: a table or a damping constant
/// asks each impact its own e (impacts.csv has each impact's), Thornton's spheres none (their loss is
/// plastic), an elastic law none.
fn asked_label(spec: &pounding::contact::ContactModel) -> (String, Option<f64>) {
    match (spec.asked(), spec.sphere()) {
        (_, Some(_)) => ("plastic".into(), None),
        (None, None) => ("elastic".into(), None),
        (Some(Restitution::Constant(e)), None) => (fmt_num(*e), Some(*e)),
        (Some(Restitution::Table(_)), None) => ("table".into(), None),
        (Some(Restitution::DampingConstant(_)), None) => ("D/K".into(), None),
    }
}

/// Every site of a run without contact: its gap and each level's largest closing against it.
fn inactive_sites(s: &Scenario, r: &Results) {
    println!("\nwithout contact      gap_mm  max_closing_mm  would_touch  max_opening_mm (gap: to a bumper's face)");
    for (site, lr) in s.sites().iter().zip(&r.sites) {
        let name = if site.is_wall() {
            format!("wall {}", site.name)
        } else {
            site.name.clone()
        };
        let most = |v: &[f64]| v.iter().fold(0.0, |a: f64, b| a.max(*b));
        let closing = most(&lr.max_closing);
        println!(
            "{:<20} {:>6}  {:>14}  {:>11}  {:>14}",
            name,
            mm(site.touch_gap()),
            mm(closing),
            if closing > site.touch_gap() {
                "yes"
            } else {
                "no"
            },
            mm(most(&lr.max_opening))
        );
    }
}

/// Every contact site: impacts, e asked and delivered, peaks.
fn sites(s: &Scenario, r: &Results) {
    if s.sites().iter().any(|site| !site.active) {
        return inactive_sites(s, r);
    }
    if !s.sites().is_empty() {
        println!(
            "\ncontact              impacts  e_asked  e_delivered    peak_force_MN  max_penetration_mm  dissipated_kJ  max_opening_mm"
        );
        let rows = s
            .sites()
            .iter()
            .zip(&r.sites)
            .enumerate()
            .map(|(i, (site, lr))| {
                let name = if site.is_wall() {
                    format!("wall {}", site.name)
                } else {
                    site.name.clone()
                };
                (
                    (name, Meeting::of_site(s, site)),
                    lr,
                    asked_label(site.contact.spec()),
                    site.seat,
                    site.bumper.is_some(),
                    r.delivered_e(i),
                )
            });
        // What met at the sites whose impacts delivered another e than asked.
        let mut spread = Vec::new();
        for ((name, meeting), lr, e_asked, seat, bumper, delivered) in rows {
            if let (Some((lo, hi)), (_, Some(e))) = (delivered, &e_asked) {
                if (lo - e).abs() > 0.01 || (hi - e).abs() > 0.01 {
                    spread.push(meeting);
                }
            }
            let asked = &e_asked.0;
            let range = match delivered {
                Some((lo, hi)) if hi - lo < 5e-4 => format!("{lo:.3}"),
                Some((lo, hi)) => format!("{lo:.3}-{hi:.3}"),
                None => "-".into(),
            };
            let opening = lr.max_opening.iter().fold(0.0, |a: f64, b| a.max(*b));
            let unseat = match (seat, lr.unseated) {
                (Some(seat), Some(true)) => format!("  UNSEATED (seat {} mm)", mm(seat)),
                (Some(seat), _) => format!("  (seat {} mm)", mm(seat)),
                _ => String::new(),
            };
            let consumed = if bumper {
                format!(
                    "  bumper consumed {}",
                    pounding::words::count(lr.consumed, "time", None)
                )
            } else {
                String::new()
            };
            println!(
                "{:<20} {:>7}  {:>7}  {:>11}  {:>15}  {:>18}  {:>13}  {:>14}{unseat}{consumed}",
                name,
                lr.impacts,
                asked,
                range,
                mn(lr.peak_force),
                mm(lr.max_penetration),
                kj(lr.dissipated_energy),
                mm(opening)
            );
        }
        if !spread.is_empty() {
            let w = inside(&spread);
            let note = format!(
                "e_delivered (separation over approach velocity of each impact, in impacts.csv) differs from \
                 e_asked: the calibration is exact for two free bodies, but here, in a contact {}, {}, the damping \
                 and every other force on the {} act during each contact, and can even {} (e > 1). Nothing is \
                 lost: the energy balance below holds. See docs/verification.md, \"Impacts inside a run\".",
                w.contact, w.forces, w.masses, w.part
            );
            println!("{}", lines(&note, 104).join("\n"));
        }
    }
}

/// `text` broken at spaces into lines of at most `width` characters (a longer word keeps its own line).
fn lines(text: &str, width: usize) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    for word in text.split_whitespace() {
        match out.last_mut() {
            Some(line) if line.chars().count() + 1 + word.chars().count() <= width => {
                line.push(' ');
                line.push_str(word);
            }
            _ => out.push(word.to_string()),
        }
    }
    out
}

/// Every device: its peaks per floor pair.
fn devices(s: &Scenario, r: &Results) {
    if !s.devices().is_empty() {
        // Decks are one mass each: no floor numbers when every structure is one.
        let floors = |text: String| {
            if who(s) == "deck" {
                String::new()
            } else {
                text
            }
        };
        println!(
            "\ndevice               {}peak_force_MN  max_closing_mm  max_opening_mm",
            floors("floors  ".into())
        );
        for (d, dr) in s.devices().iter().zip(&r.devices) {
            for (k, (i, j)) in d.floors.iter().enumerate() {
                println!(
                    "{:<20} {}{:>13}  {:>14}  {:>14}",
                    d.name,
                    floors(format!("{:>6}  ", format!("{i}-{j}"))),
                    mn(dr.peak_force[k]),
                    mm(dr.max_closing[k]),
                    mm(dr.max_opening[k])
                );
            }
        }
    }
}

/// What can yield, for the events' words: "storey", "isolator and storey", "bearing", ...
fn yielding(s: &Scenario) -> String {
    let has = |f: Form| s.buildings().iter().any(|b| b.structure.form() == f);
    let mut words = Vec::new();
    if has(Form::Deck) {
        words.push("bearing");
    }
    if has(Form::IsolatedBuilding) {
        words.push("isolator");
    }
    if has(Form::Building) || has(Form::IsolatedBuilding) {
        words.push("storey");
    }
    match words.as_slice() {
        [a, b, c] => format!("{a}, {b} and {c}"),
        [a, b] => format!("{a} and {b}"),
        _ => words.concat(),
    }
}

/// The energy at the end, its balance and the integration counts.
fn energy(s: &Scenario, r: &Results) {
    let e = &r.energy.end;
    println!(
        "\nenergy at the end, kJ: input {} = kinetic {} + strain {} + damping {} + hysteretic {} + contact {}",
        kj(e.input),
        kj(e.kinetic),
        kj(e.strain),
        kj(e.damping),
        kj(e.hysteretic),
        kj(e.contact)
    );
    println!(
        "energy balance error: {:.2e} (largest over the run, relative to the largest energy)",
        r.energy.relative_error
    );
    println!(
        "integration: {} steps ({} rejected), {} events (contact touch, turn, separation; {} yield, reversal; device taut, slack, reversal)",
        r.statistics.steps,
        r.statistics.rejected,
        r.statistics.events,
        yielding(s)
    );
}
