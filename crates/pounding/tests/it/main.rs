//! Integration tests of the `pounding` library: one test binary (less linking), one module per subject.
//! Expected values come from the exact relations and reference tables of
//! `docs/contact-models.md` or from closed forms stated beside each test.

mod allocations;
mod api;
mod buildings;
mod calibration;
mod column;
mod engine;
mod exact;
mod exact_relations;
mod fit;
mod fluid_viscous;
mod ground_motion;
mod inelastic;
mod integrated;
mod isolation;
mod matrices;
mod paper;
mod plan;
mod reliability;
mod restitution;
mod separation;
mod soil;
mod supports;

use pounding::contact::{ContactModel, Damping, ForceLaw, Model, Tension};
use pounding::impact::{simulate, ImpactOptions, ImpactResult, ImpactSetup};

/// The force law of `spec` for effective mass `m` and impact velocity `v`.
pub fn law(spec: &ContactModel, m: f64, v: f64) -> ForceLaw {
    spec.prepare().unwrap().law(m, v).unwrap().0
}

/// An integrated impact of `spec`, with history.
pub fn run(spec: &ContactModel, m: f64, v: f64) -> ImpactResult {
    let opts = ImpactOptions {
        history: true,
        ..ImpactOptions::default()
    };
    simulate(
        &law(spec, m, v),
        spec.tension(),
        &ImpactSetup::relative(m, v),
        &opts,
    )
    .unwrap()
}

/// `spec` for `model` with formula damping.
pub fn formula(model: Model, k: f64, e: f64) -> ContactModel {
    ContactModel::new(model, k, e)
        .unwrap()
        .with_damping(Damping::Formula)
}

/// Every damped model, in each tension rule that changes what it delivers.
pub fn damped_variants() -> Vec<(Model, Tension)> {
    let mut v: Vec<_> = Model::all()
        .filter(|m| m.is_damped())
        .map(|m| (m, m.info().tension))
        .collect();
    v.push((Model::KelvinVoigt, Tension::Clamp));
    v
}
