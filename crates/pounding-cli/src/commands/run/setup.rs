//! What a run prints before it starts: the record, the settings, each building with its modes, each contact
//! site and device.

use super::tables::who;
use crate::describe::contact_label;
use crate::output::{fmt_num, fmt_sig};
use pounding::analysis::{Building, Bumper, Scenario, SiteKind};
use pounding::element::StoreyLaw;
use pounding::structure::{Form, IsolatorModel};
use pounding_study::input::Loaded;
use std::path::Path;

/// Prints the setup of `loaded` (read from `file`).
pub fn print(loaded: &Loaded, file: &Path) {
    let s = &loaded.scenario;
    let rec = s.record();
    let p = rec.peaks();
    println!("scenario  {}", file.display());
    println!(
        "record    {} x {}: {} samples at {} s, PGA {} m/s^2 ({} g) at {} s",
        loaded.record_source,
        loaded.doc.ground_motion.scale,
        rec.npts(),
        fmt_num(rec.dt()),
        fmt_sig(p.pga, 4),
        fmt_sig(p.pga / pounding::units::STANDARD_GRAVITY, 4),
        fmt_num(p.pga_time)
    );
    super::plan::record_y(s, loaded.doc.ground_motion.angle);
    println!(
        "analysis  {} s, output every {} s, tolerance {:e}",
        fmt_num(s.duration()),
        fmt_num(s.output_dt()),
        s.tolerance()
    );
    for (k, (name, r)) in s.supports().iter().enumerate() {
        let on: Vec<&str> = s
            .buildings()
            .iter()
            .zip(s.building_supports())
            .filter(|(_, &b)| b == k + 1)
            .map(|(b, _)| b.name.as_str())
            .chain(
                s.sites()
                    .iter()
                    .filter(|w| w.is_wall() && w.support == k + 1)
                    .map(|w| w.name.as_str()),
            )
            .collect();
        let own = loaded.doc.support.get(k).is_some_and(|d| d.own().is_some());
        println!(
            "support   {name}: {}, arriving {} s later, PGA {} m/s^2; under {}",
            if own {
                "a record of its own"
            } else {
                "the record above"
            },
            fmt_num(r.delay()),
            fmt_sig(r.peaks().pga, 4),
            if on.is_empty() {
                "nothing".to_string()
            } else {
                on.join(", ")
            }
        );
    }
    for b in s.buildings() {
        building(b);
    }
    sites(s);
    // Decks are one mass each: no floor numbers when every structure is one.
    let decks = who(s) == "deck";
    for d in s.devices() {
        let [a, b] = s.device_between(d);
        let floors: Vec<String> = d.floors.iter().map(|(i, j)| format!("{i}-{j}")).collect();
        let at = if decks {
            String::new()
        } else {
            format!(" at floors {}", floors.join(", "))
        };
        let params: Vec<String> = d
            .law
            .parameters()
            .iter()
            .map(|p| {
                let text = format!("{} {} {}", p.key, fmt_sig(p.value, 4), p.unit);
                text.trim_end().to_string()
            })
            .collect();
        println!(
            "\ndevice {}: {} {} between {a} and {b}{at}",
            d.name,
            d.law.name(),
            params.join(", "),
        );
    }
    println!();
}

/// How a building is damped, in words.
fn damping(b: &Building) -> String {
    let st = &b.structure;
    if let Some(ms) = st.matrices() {
        let form = format!(
            "given by its matrices ({} degrees of freedom, linear)",
            ms.n()
        );
        return match ms.damping {
            Some(_) => format!("{form}, its damping matrix"),
            None => format!(
                "{form}, damping {} % (Rayleigh on its modes 1 and 2)",
                fmt_num(100.0 * st.damping_ratio())
            ),
        };
    }
    let Some(iso) = st.isolator() else {
        return format!(
            "damping {} % (Rayleigh, modes 1 and 2)",
            fmt_num(100.0 * st.damping_ratio())
        );
    };
    format!(
        "isolated: {} isolator (storey 1) under the base slab (floor 1){}; {}isolator damped by its hysteresis{}",
        iso.model.name(),
        iso.clearance
            .map_or(String::new(), |c| format!(", clearance {} m", fmt_num(c))),
        if st.storeys() > 1 {
            format!(
                "superstructure damped {} % on its fixed-base modes 1 and 2, ",
                fmt_num(100.0 * st.damping_ratio())
            )
        } else {
            String::new()
        },
        if iso.damping > 0.0 {
            format!(" and {} N s/m", fmt_sig(iso.damping, 4))
        } else {
            String::new()
        }
    )
}

/// A storey's law in words, with units: "bilinear F_y 1.4e6 N, a 0.12".
fn storey_law(l: &StoreyLaw) -> String {
    match *l {
        StoreyLaw::Linear => "linear".to_string(),
        StoreyLaw::Bilinear {
            yield_force,
            post_yield_ratio,
        } => format!(
            "bilinear F_y {} N, a {}",
            fmt_sig(yield_force, 4),
            fmt_num(post_yield_ratio)
        ),
        StoreyLaw::BoucWen {
            yield_force,
            post_yield_ratio,
            n,
            beta,
            gamma,
        } => format!(
            "bouc-wen F_y {} N, a {}, n {}, beta {}, gamma {}",
            fmt_sig(yield_force, 4),
            fmt_num(post_yield_ratio),
            fmt_num(n),
            fmt_num(beta),
            fmt_num(gamma)
        ),
    }
}

/// A deck on its bearings: its mass, the bearings' law, its period.
fn deck(b: &Building) {
    let st = &b.structure;
    let Some(iso) = st.isolator() else { return };
    // The bearings' own parameters (a friction pendulum's radius and friction, else the storey law's).
    let law = match iso.model {
        IsolatorModel::FrictionPendulum {
            radius,
            mu,
            yield_displacement,
        } => format!(
            "R {} m, mu {}, d_y {} m",
            fmt_num(radius),
            fmt_num(mu),
            fmt_num(yield_displacement)
        ),
        _ => {
            let words = storey_law(&st.storey_laws()[0]);
            let rest = words
                .split_once(' ')
                .map_or(String::new(), |x| format!(", {}", x.1));
            format!("k {} N/m{rest}", fmt_sig(st.stiffnesses()[0], 4))
        }
    };
    let viscous = format!("{} N s/m", fmt_sig(iso.damping, 4));
    let damped = match (st.storey_laws()[0].is_inelastic(), iso.damping > 0.0) {
        (true, false) => "damped by their hysteresis".to_string(),
        (true, true) => format!("damped by their hysteresis and {viscous}"),
        (false, true) => format!("damped by {viscous}"),
        (false, false) => "undamped".to_string(),
    };
    println!(
        "\ndeck {:?}: {} kg on {} bearings, {law}; {damped}",
        b.name,
        fmt_num(st.total_mass()),
        iso.model.name(),
    );
    println!(
        "  period {} s (initial stiffness of the bearings)",
        fmt_sig(st.modes().periods()[0], 4)
    );
}

/// A building, its storey laws and its modes (a deck: [`deck`]; a building in plan: [`super::plan::building`]).
fn building(b: &Building) {
    let st = &b.structure;
    if let Some(p) = st.plan() {
        return super::plan::building(b, p);
    }
    if st.foundation().is_some() {
        // The fixed-base modes below fix the damping; the foundation line gives the periods on the soil.
        building_modes(b);
        return super::plan::foundation(b);
    }
    if st.form() == Form::Deck {
        return deck(b);
    }
    building_modes(b);
}

/// A building in one line: its storey laws and its (fixed-base) modes.
fn building_modes(b: &Building) {
    let st = &b.structure;
    let modes = st.modes();
    let part = modes.participation(st.masses());
    let m_tot = st.total_mass();
    println!(
        "\nbuilding {:?}: {}, {} kg, height {} m, {}",
        b.name,
        pounding::words::count(st.storeys(), "storey", None),
        fmt_num(m_tot),
        fmt_num(st.elevations().last().copied().unwrap_or(0.0)),
        damping(b)
    );
    let laws = st.storey_laws();
    if laws.iter().any(|l| l.is_inelastic()) {
        let desc: Vec<String> = laws
            .iter()
            .enumerate()
            .map(|(j, l)| format!("{}: {}", j + 1, storey_law(l)))
            .collect();
        println!("  storeys: {}", desc.join("; "));
        if st.isolator().is_some() {
            println!("  (modes of the initial stiffness; damping_% is phi^T C phi / 2w, the isolator's hysteresis not counted)");
        } else {
            println!("  (modes and Rayleigh damping of the initial stiffness)");
        }
    }
    println!("  mode  period_s  damping_%  mass_%  shape (floor 1 up, largest = 1)");
    let shapes = modes.shapes_normalised();
    for (r, t) in modes.periods().iter().enumerate().take(6) {
        let shape: Vec<String> = shapes[r].iter().map(|x| format!("{x:.3}")).collect();
        println!(
            "  {:>4}  {:>8.4}  {:>9.2}  {:>6.1}  {}",
            r + 1,
            t,
            100.0 * st.damping_of_mode(r),
            100.0 * part[r].1 / m_tot,
            shape.join(" ")
        );
    }
    if st.storeys() > 6 {
        println!("  (modes 7 to {} in summary.json)", st.storeys());
    }
}

/// Every contact site: where it is, its gap and levels, its law, bumper and seat.
fn sites(s: &Scenario) {
    if s.sites().iter().any(|site| !site.active) {
        println!("\ncontacts off: the contacts and walls below record closings only, their laws never act");
    }
    // Decks are one mass each: no floor numbers when every structure is one.
    let decks = who(s) == "deck";
    for site in s.sites() {
        let law = contact_label(site.contact.spec(), site.contact.parameter());
        if site.plan.is_some() {
            super::plan::site(s, site, &law);
            extras(&site.bumper, site.seat);
            continue;
        }
        if let (Some(c), SiteKind::Between { left, right }) = (&site.column, site.kind) {
            let (slab, col) = if c.on_left {
                (right, left)
            } else {
                (left, right)
            };
            let (lv, b) = (site.levels[0], &s.buildings()[col].name);
            let floor = if c.on_left { lv.right } else { lv.left }.unwrap_or(0);
            let what = match c.struck {
                Some(k) => format!(
                    "strikes {b:?}'s column in storey {} at {} m of {} m (EI {} N m^2: {} N/m at the point, which carries {} kg)",
                    c.storey,
                    fmt_num(k.a),
                    fmt_num(k.length),
                    fmt_sig(k.ei, 4),
                    fmt_sig(k.stiffness(), 4),
                    fmt_sig(k.point_mass(), 4)
                ),
                None => format!("meets {b:?}'s floor {} (a floor contact)", c.storey),
            };
            println!(
                "\ncolumn contact {}: floor {floor} of {:?} {what}, gap {} m, {law}",
                site.name,
                s.buildings()[slab].name,
                fmt_num(site.gap)
            );
            continue;
        }
        match site.kind {
            SiteKind::Between { .. } => {
                let floors: Vec<String> = site
                    .levels
                    .iter()
                    .map(|l| format!("{}-{}", l.left.unwrap_or(0), l.right.unwrap_or(0)))
                    .collect();
                let at = if decks {
                    String::new()
                } else {
                    format!(" at floors {}", floors.join(", "))
                };
                println!(
                    "\ncontact {}: gap {} m{at}, {law}",
                    site.name,
                    fmt_num(site.gap)
                );
            }
            SiteKind::Wall { building, side } => {
                let floors: Vec<String> =
                    site.levels.iter().map(|l| l.floor().to_string()).collect();
                let at = if decks {
                    String::new()
                } else {
                    format!(", floors {}", floors.join(", "))
                };
                println!(
                    "\nwall {}: {} of {}, gap {} m{at}, {law}",
                    site.name,
                    side.name(),
                    s.buildings()[building].name,
                    fmt_num(site.gap)
                );
            }
        }
        extras(&site.bumper, site.seat);
    }
}

/// A bumper and a seat, if given.
fn extras(bumper: &Option<Bumper>, seat: Option<f64>) {
    if let Some(b) = bumper {
        println!(
            "  bumper {} m thick, consumed at strain {}: {}",
            fmt_num(b.thickness),
            fmt_num(b.max_strain),
            contact_label(b.contact.spec(), b.contact.parameter())
        );
    }
    if let Some(seat) = seat {
        println!("  seat {} m (unseating check)", fmt_num(seat));
    }
}
