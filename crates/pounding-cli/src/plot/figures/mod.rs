//! The tool's figures: one impact (force against time and against penetration), several models on one
//! impact, Table 1 of Papi & Toopchi-Nezhad (2022) as curves, and the figures of a pounding run.

mod common;
mod contacts;
mod impact;
mod plan;
mod response;
mod storeys;

pub use impact::{impact, table1, Curve, ForceHistory};

use super::Figure;
use crate::run_data::RunData;
use contacts::{contact_figures, impact_loops};
use response::{devices, displacement, energy, envelopes, record};
use storeys::{hysteresis, isolators};

/// The figures of a pounding run: floor displacements with impact instants, peak response over height,
/// the force-drift loop of the most strained storey (and of every inelastic storey of its building),
/// contact forces, delivered e, relative displacement against the gap, and the energy balance.
pub fn run(d: &RunData) -> Vec<Figure> {
    let (forces, closing, restitution) = contact_figures(d);
    let mut figs = vec![record(d), displacement(d)];
    if !d.buildings.is_empty() {
        figs.extend(envelopes(d));
        figs.extend(hysteresis(d));
        figs.extend(isolators(d));
    }
    figs.extend(forces);
    figs.extend(impact_loops(d));
    figs.extend(restitution);
    figs.extend(closing);
    figs.extend(devices(d));
    figs.extend(plan::plan_view(d));
    figs.extend(plan::corner_orbit(d));
    figs.push(energy(d));
    figs
}
