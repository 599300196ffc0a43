//! `pounding impact`, `pounding drop` and `pounding calibrate`: one impact of two bodies, a ball dropped on
//! a slab, and the damping parameter that delivers e exactly.

use crate::args::{CalibrateArgs, DropArgs, ImpactArgs};
use crate::describe::{bodies_text, contact, contact_label, describe, parameter, results};
use crate::error::{impact_scales, input, CliError};
use crate::files::{check_out, history_csv, save_out};
use crate::output::{fmt_num, fmt_sig, num, Report};
use crate::plot::figures::{self, ForceHistory};
use pounding::contact::{ContactModel, Damping, Model};
use pounding::impact::{
    delivered_e, exact, simulate, BallDrop, ImpactOptions, ImpactResult, ImpactSetup, TwoBodies,
};

/// How the options of two bodies make an impact's mass and velocity (for messages).
pub const TWO_BODIES: &str = "with m = m1 m2 / (m1 + m2)";

/// The figures of one integrated impact, if `--plots` asks for them.
fn impact_figures(
    plots: bool,
    (prefix, title): (&str, &str),
    s: &ContactModel,
    r: &ImpactResult,
    inputs: &str,
) -> Vec<crate::plot::Figure> {
    let (true, Some(h)) = (plots, r.history.as_ref()) else {
        return Vec::new();
    };
    let subtitle = format!(
        "{}; {inputs}: e_post = {}, peak force {}",
        contact_label(s, None).replace(" (set per impact)", ""),
        fmt_sig(r.e_post, 6),
        crate::plot::axis::human(r.peak_force, "N", 4)
    );
    figures::impact(
        prefix,
        title,
        &subtitle,
        &[ForceHistory {
            label: s.model().name().into(),
            t: &h.t,
            penetration: &h.penetration,
            force: &h.force,
        }],
    )
}

/// The impact's time history as the file `history.csv`, if it was kept.
fn history_file(r: &ImpactResult) -> Vec<(String, Vec<u8>)> {
    r.history
        .as_ref()
        .map(|h| ("history.csv".to_string(), history_csv(h).into_bytes()))
        .into_iter()
        .collect()
}

pub fn impact(a: &ImpactArgs) -> Result<(), CliError> {
    check_out(&a.out)?;
    let bodies = TwoBodies::new(a.bodies.m1, a.bodies.m2, a.bodies.v)?;
    let s = contact(&a.model, a.k, a.radius)?;
    let setup = bodies.setup();
    let b = a.bodies;
    let options = [("m1", b.m1), ("m2", b.m2), ("v", b.v), ("k", a.k)];
    let scales = impact_scales(&options, TWO_BODIES);
    let (law, p) = s.prepare()?.law(setup.mass, setup.v_i).map_err(&scales)?;
    let opts = ImpactOptions {
        history: a.out.out.is_some(),
        ..ImpactOptions::default()
    };
    let r = simulate(&law, s.tension(), &setup, &opts).map_err(&scales)?;
    let exact_e = exact::e_post(&law, s.tension(), setup.mass, setup.v_i);
    let (v1, v2) = bodies.velocities_after(r.impulse);
    let mut rep = Report::default();
    describe(&mut rep, &s, p);
    rep.add("m1", num(b.m1), "kg")
        .add_shown(
            "m2",
            num(b.m2),
            if b.m2.is_infinite() {
                "rigid (infinite mass)".into()
            } else {
                fmt_num(b.m2)
            },
            if b.m2.is_infinite() { "" } else { "kg" },
        )
        .add("v", num(b.v), "m/s")
        .add("effective_mass", num(setup.mass), "kg");
    if let (Some(sp), Some(v_y)) = (s.sphere(), exact::thornton_yield_velocity(&law, setup.mass)) {
        rep.add("radius", num(sp.radius), "m")
            .add("yield_velocity", num(v_y), "m/s");
    }
    results(&mut rep, &s, (&r, setup.v_i), exact_e);
    rep.add("velocity_1_after", num(v1), "m/s")
        .add("velocity_2_after", num(v2), "m/s");
    let inputs = bodies_text(&a.bodies);
    let title = format!("Impact ({})", s.model().name());
    let figs = impact_figures(a.out.figures.plots, ("impact", &title), &s, &r, &inputs);
    rep.print(a.json);
    save_out(
        &a.out,
        ("impact", &rep.json()),
        history_file(&r),
        &figs,
        a.json,
    )?;
    Ok(())
}

pub fn calibrate(a: &CalibrateArgs) -> Result<(), CliError> {
    if let Some(why) = a.model.asks_no_e() {
        return Err(input(format!(
            "model {} has no damping to calibrate ({why}); choose a damped model",
            a.model
        )));
    }
    let mut s = ContactModel::new(a.model, 1.0, a.e)?
        .with_damping(Damping::Exact)
        .with_reading(a.reading);
    if let Some(n) = a.n {
        s = s.with_exponent(n)?;
    }
    if let Some(t) = a.tension {
        s = s.with_tension(t);
    }
    // The parameter is dimensionless: any k, m and v give it; unit values are used.
    let (law, p) = s.prepare()?.law(1.0, 1.0)?;
    let setup = ImpactSetup::relative(1.0, 1.0);
    let e_post = delivered_e(&law, s.tension(), &setup)?;
    let integrated = simulate(&law, s.tension(), &setup, &ImpactOptions::default())?.e_post;
    let mut rep = Report::default();
    rep.add("model", s.model().name(), "")
        .add("e_pre", num(a.e), "")
        .add("n", num(s.exponent()), "")
        .add("tension", s.tension().name(), "");
    if s.model() == Model::Papi {
        rep.add("reading", s.reading().name(), "");
    }
    parameter(&mut rep, p);
    rep.add("e_post", num(e_post), "")
        .add("e_post_integrated", num(integrated), "");
    rep.print(a.json);
    Ok(())
}

pub fn drop(a: &DropArgs) -> Result<(), CliError> {
    check_out(&a.out)?;
    let drop = BallDrop::new(a.radius, a.youngs_modulus, a.poisson, a.density, a.height)?;
    let n = a.model.n.unwrap_or(a.model.model.info().default_n);
    let s = contact(
        &a.model,
        drop.equivalent_stiffness(n.max(f64::MIN_POSITIVE)),
        // The ball's radius is thornton's sphere radius too.
        Some(a.radius).filter(|_| a.model.model == pounding::contact::Model::Thornton),
    )?;
    let setup = drop.setup();
    let options = [
        ("radius", a.radius),
        ("density", a.density),
        ("height", a.height),
        ("youngs-modulus", a.youngs_modulus),
    ];
    let scales = impact_scales(
        &options,
        "with m the ball's mass, v = sqrt(2 g height) and k its Hertz stiffness",
    );
    let (law, p) = s.prepare()?.law(setup.mass, setup.v_i).map_err(&scales)?;
    let opts = ImpactOptions {
        history: a.out.out.is_some(),
        ..ImpactOptions::default()
    };
    let r = simulate(&law, s.tension(), &setup, &opts).map_err(&scales)?;
    let mut rep = Report::default();
    describe(&mut rep, &s, p);
    rep.add("radius", num(a.radius), "m")
        .add("youngs_modulus", num(a.youngs_modulus), "Pa")
        .add("poisson", num(a.poisson), "")
        .add("density", num(a.density), "kg/m^3")
        .add("height", num(a.height), "m")
        .add("mass", num(setup.mass), "kg")
        .add("hertz_stiffness", num(drop.hertz_stiffness()), "N/m^1.5")
        .add("v_i", num(setup.v_i), "m/s");
    results(&mut rep, &s, (&r, setup.v_i), None);
    let inputs = format!(
        "ball R = {} m, E = {} Pa, h = {} m, v_i = {} m/s",
        fmt_num(a.radius),
        fmt_num(a.youngs_modulus),
        fmt_num(a.height),
        fmt_sig(setup.v_i, 6)
    );
    let title = format!("Ball drop ({})", s.model().name());
    let figs = impact_figures(a.out.figures.plots, ("drop", &title), &s, &r, &inputs);
    rep.print(a.json);
    save_out(
        &a.out,
        ("drop", &rep.json()),
        history_file(&r),
        &figs,
        a.json,
    )?;
    Ok(())
}
