//! What a run prints of buildings in plan: before, each one's plan, lines and modes in plan, the ground along
//! y and each contact's façades and points; after, each floor's response along y, in rotation and at its
//! corners, and the lines that yield.

use crate::output::{fmt_num, fmt_sig, fmt_table};
use pounding::analysis::{Building, ContactSite, Results, Scenario, SiteKind};
use pounding::structure::{LineDirection, Plan};

/// The record along y, if the ground shakes in two directions.
pub fn record_y(s: &Scenario, angle: Option<f64>) {
    if let Some(y) = s.record_y() {
        let p = y.peaks();
        let turned = angle
            .filter(|a| *a != 0.0)
            .map_or(String::new(), |a| format!(", turned {} deg", fmt_num(a)));
        println!(
            "along y   {} samples at {} s, PGA {} m/s^2 ({} g) at {} s{turned}",
            y.npts(),
            fmt_num(y.dt()),
            fmt_sig(p.pga, 4),
            fmt_sig(p.pga / pounding::units::STANDARD_GRAVITY, 4),
            fmt_num(p.pga_time)
        );
    }
}

/// `(x, y)` in metres.
fn xy(p: (f64, f64)) -> String {
    format!("({}, {})", fmt_num(p.0), fmt_num(p.1))
}

/// A building in plan: its plan, lines and modes in plan.
pub fn building(b: &Building, p: &Plan) {
    let st = &b.structure;
    let centres = p.centres();
    let centre = if centres.iter().all(|c| *c == centres[0]) {
        format!("mass centre {}", xy(centres[0]))
    } else {
        "mass centres per floor (summary.json)".to_string()
    };
    let (dm1, dm2) = p.damping_modes();
    println!(
        "\nbuilding {:?}: {} in plan, {} kg, height {} m; plan {} x {} m at {}, {centre}; damping {} % (Rayleigh on modes {dm1} and {dm2} in plan)",
        b.name,
        pounding::words::count(st.storeys(), "storey", None),
        fmt_num(st.total_mass()),
        fmt_num(st.elevations().last().copied().unwrap_or(0.0)),
        fmt_num(p.size().0),
        fmt_num(p.size().1),
        xy(p.origin()),
        fmt_num(100.0 * st.damping_ratio()),
    );
    for (i, l) in p.lines().iter().enumerate() {
        let across = match l.direction {
            LineDirection::X => "y",
            LineDirection::Y => "x",
        };
        let k: Vec<String> = l.stiffnesses.iter().map(|k| fmt_sig(*k, 4)).collect();
        let laws: Vec<&str> = l.laws.iter().map(|law| law.model().name()).collect();
        let laws = if laws.iter().all(|m| *m == "linear") {
            String::new()
        } else {
            format!(", {}", laws.join(" "))
        };
        println!(
            "  line {}: along {} at {across} = {} m, k {} N/m{laws}",
            i + 1,
            l.direction.name(),
            fmt_num(l.at),
            k.join(" ")
        );
    }
    println!("  mode  period_s  damping_%  mass_x_%  mass_y_%  rotation_%");
    let (a0, a1) = p.rayleigh();
    let part = p.participation();
    for (r, (w, (x, y, t))) in p.modes().omega.iter().zip(part).enumerate().take(9) {
        println!(
            "  {:>4}  {:>8.4}  {:>9.2}  {:>8.1}  {:>8.1}  {:>10.1}",
            r + 1,
            2.0 * std::f64::consts::PI / w,
            100.0 * (a0 / (2.0 * w) + a1 * w / 2.0),
            100.0 * x,
            100.0 * y,
            100.0 * t
        );
    }
    if p.modes().omega.len() > 9 {
        println!("  (modes 10 to {} in summary.json)", p.modes().omega.len());
    }
}

/// A contact site between buildings in plan, or a wall beside one.
pub fn site(s: &Scenario, site: &ContactSite, law: &str) {
    let Some(sp) = &site.plan else { return };
    let (axis, along) = if sp.normal.0 != 0.0 {
        ("x", "y")
    } else {
        ("y", "x")
    };
    let floors: Vec<String> = site
        .levels
        .iter()
        .step_by(sp.along.len().max(1))
        .map(|l| match site.kind {
            SiteKind::Between { .. } => {
                format!("{}-{}", l.left.unwrap_or(0), l.right.unwrap_or(0))
            }
            SiteKind::Wall { .. } => l.floor().to_string(),
        })
        .collect();
    let points: Vec<String> = sp.along.iter().map(|t| fmt_num(*t)).collect();
    match site.kind {
        SiteKind::Between { left, right } => println!(
            "\ncontact {}: {}'s {} façade and {}'s {}, along {axis}, gap {} m from the plans' positions, at floors {} and {along} = {} m, {law}",
            site.name,
            s.buildings()[left].name,
            if axis == "x" { "east" } else { "north" },
            s.buildings()[right].name,
            if axis == "x" { "west" } else { "south" },
            fmt_num(site.gap),
            floors.join(", "),
            points.join(", ")
        ),
        SiteKind::Wall { building, side } => println!(
            "\nwall {}: {} of {}, gap {} m, floors {} at {along} = {} m, {law}",
            site.name,
            side.name(),
            s.buildings()[building].name,
            fmt_num(site.gap),
            floors.join(", "),
            points.join(", ")
        ),
    }
}

/// Each building in plan's response along y, in rotation and at its corners, and its lines' yielding.
pub fn peaks(s: &Scenario, r: &Results) {
    let plans: Vec<_> = s
        .buildings()
        .iter()
        .zip(&r.buildings)
        .filter_map(|(b, resp)| resp.plan.as_ref().map(|p| (b, p)))
        .collect();
    if plans.is_empty() {
        return;
    }
    println!("\nbuildings in plan (the table above holds their mass centres along x; rotations in mrad)\n");
    println!("building    floor  disp_y_mm  rotation_mrad  twist_mrad  torque_MNm  corner_x_mm  corner_y_mm  amplification_x  amplification_y");
    let ratio = |v: Option<f64>| v.map_or("-".to_string(), |x| format!("{x:.3}"));
    for (b, p) in &plans {
        for f in 0..b.structure.storeys() {
            let (cx, cy) = p.peak_corner[f]
                .iter()
                .fold((0.0f64, 0.0f64), |a, c| (a.0.max(c.0), a.1.max(c.1)));
            let (ax, ay) = p.torsional_amplification[f];
            println!(
                "{:<10}  {:>5}  {:>9}  {:>13}  {:>10}  {:>10}  {:>11}  {:>11}  {:>15}  {:>15}",
                b.name,
                f + 1,
                fmt_table(1e3 * p.peak_displacement_y[f], 4),
                fmt_table(1e3 * p.peak_rotation[f], 4),
                fmt_table(1e3 * p.peak_twist[f], 4),
                fmt_table(1e-6 * p.peak_torque[f], 4),
                fmt_table(1e3 * cx, 4),
                fmt_table(1e3 * cy, 4),
                ratio(ax),
                ratio(ay)
            );
        }
    }
    println!("(corner: the largest of the four corners' peaks; amplification: that over the mass centre's, - where the centre did not move)");
    let yielding: Vec<String> = plans
        .iter()
        .flat_map(|(b, p)| {
            p.lines.iter().enumerate().flat_map(move |(i, l)| {
                l.ductility.iter().enumerate().filter_map(move |(j, d)| {
                    d.filter(|d| *d > 1.0)
                        .map(|d| format!("{} line {} storey {}: {:.2}", b.name, i + 1, j + 1, d))
                })
            })
        })
        .collect();
    if !yielding.is_empty() {
        println!(
            "lines that yield (ductility, peak drift over yield drift): {}",
            yielding.join("; ")
        );
    }
}

/// A building's foundation on the soil: its springs and dashpots, and the periods on it.
pub fn foundation(b: &Building) {
    let st = &b.structure;
    let (Some(f), Some(modes)) = (st.foundation(), st.flexible_modes()) else {
        return;
    };
    let source = match f.soil {
        pounding::structure::Soil::Given { .. } => "springs given".to_string(),
        pounding::structure::Soil::HalfSpace {
            vs,
            density,
            poisson,
            ..
        } => format!(
            "half-space V_s {} m/s, rho {} kg/m^3, nu {} (Gazetas; Wolf's cones)",
            fmt_num(vs),
            fmt_num(density),
            fmt_num(poisson)
        ),
    };
    println!(
        "  on a foundation of {} kg, J {} kg m^2; {source}: K_x {} N/m, K_theta {} N m/rad, C_x {} N s/m, C_theta {} N m s/rad",
        fmt_num(f.mass),
        fmt_sig(f.inertia, 4),
        fmt_sig(f.kx, 4),
        fmt_sig(f.ktheta, 4),
        fmt_sig(f.cx, 4),
        fmt_sig(f.ctheta, 4)
    );
    let periods: Vec<String> = modes
        .periods()
        .iter()
        .take(4)
        .map(|t| format!("{t:.4}"))
        .collect();
    println!(
        "  periods on the foundation (s): {} (fixed base: {:.4})",
        periods.join(", "),
        st.modes().periods()[0]
    );
}

/// Each foundation's sway and rocking.
pub fn foundations(s: &Scenario, r: &Results) {
    let rows: Vec<_> = s
        .buildings()
        .iter()
        .zip(&r.buildings)
        .filter_map(|(b, resp)| resp.foundation.as_ref().map(|f| (b, f)))
        .collect();
    if rows.is_empty() {
        return;
    }
    println!("\nfoundations (floors above move with their rocking; drifts leave it out)\n");
    println!("building    sway_mm  rocking_mrad  soil_force_MN  soil_moment_MNm  residual_sway_mm");
    for (b, f) in rows {
        println!(
            "{:<10}  {:>7}  {:>12}  {:>13}  {:>15}  {:>16}",
            b.name,
            fmt_table(1e3 * f.peak_sway, 4),
            fmt_table(1e3 * f.peak_rocking, 4),
            fmt_table(1e-6 * f.peak_soil_force, 4),
            fmt_table(1e-6 * f.peak_soil_moment, 4),
            fmt_table(1e3 * f.residual_sway, 4)
        );
    }
}

/// Each struck column's demand.
pub fn columns(s: &Scenario, r: &Results) {
    let rows: Vec<_> = s
        .sites()
        .iter()
        .zip(&r.sites)
        .filter_map(|(site, resp)| resp.column.as_ref().map(|c| (site, c)))
        .collect();
    if rows.is_empty() {
        return;
    }
    println!("\nstruck columns (demand at the column's ends, the load at the point and the storey's drift together; MN, MNm)\n");
    println!("contact                 force_MN  shear_lower  shear_upper  moment_lower  moment_upper  capacity");
    for (site, c) in rows {
        let exceeded = match (c.shear_exceeded, c.moment_exceeded) {
            (None, None) => "-".to_string(),
            (s, m) => {
                let word = |x: Option<bool>, what: &str| match x {
                    Some(true) => format!("{what} exceeded"),
                    Some(false) => format!("{what} ok"),
                    None => String::new(),
                };
                [word(s, "shear"), word(m, "moment")]
                    .into_iter()
                    .filter(|w| !w.is_empty())
                    .collect::<Vec<_>>()
                    .join(", ")
            }
        };
        println!(
            "{:<22}  {:>8}  {:>11}  {:>11}  {:>12}  {:>12}  {exceeded}",
            site.name,
            fmt_table(1e-6 * c.peak_force, 4),
            fmt_table(1e-6 * c.peak_shear.0, 4),
            fmt_table(1e-6 * c.peak_shear.1, 4),
            fmt_table(1e-6 * c.peak_moment.0, 4),
            fmt_table(1e-6 * c.peak_moment.1, 4)
        );
    }
}
