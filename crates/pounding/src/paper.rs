//! Reproduction of Table 1 of Papi & Toopchi-Nezhad (2022): the mean relative error
//! `|e_pre - e_post| / e_pre * 100` of each model over `0.1 <= e <= 1` and `0.5 <= e <= 0.8`.
//!
//! Protocol (the paper states none): an ideal single impact of each model with its damping from `e_pre`,
//! `e_post` by the exact relation of [`crate::impact::exact`] where one exists and by event-located
//! integration otherwise (Jankowski), on the grids `e = 0.1, 0.2, ..., 1.0` and `e = 0.10, 0.11, ..., 1.00`.
//! The result does not depend on stiffness, mass or impact velocity.

use crate::contact::{AlphaRule, ContactModel, Damping, Model, Reading, Tension};
use crate::impact::{delivered_e, ImpactSetup};
use crate::Error;

/// One model variant compared in Table 1.
#[derive(Clone, Debug)]
pub struct Variant {
    /// Label, as printed.
    pub label: &'static str,
    /// The model.
    pub model: Model,
    /// Tension rule.
    pub tension: Tension,
    /// Rule for `alpha` (papi only).
    pub alpha: AlphaRule,
    /// Reading (papi only).
    pub reading: Reading,
    /// The published errors (%) over 0.1..1 and 0.5..0.8, where it gives them.
    pub published: Option<(f64, f64)>,
}

/// One row of the reproduced table: mean errors in %, on the 0.1 grid and on the 0.01 grid, each over
/// 0.1..1 and over 0.5..0.8.
#[derive(Clone, Debug)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Row {
    /// Label.
    pub label: &'static str,
    /// Model name.
    pub model: &'static str,
    /// Mean error (%) over 0.1..1, grid step 0.1.
    pub coarse_all: f64,
    /// Mean error (%) over 0.5..0.8, grid step 0.1.
    pub coarse_mid: f64,
    /// Mean error (%) over 0.1..1, grid step 0.01.
    pub fine_all: f64,
    /// Mean error (%) over 0.5..0.8, grid step 0.01.
    pub fine_mid: f64,
    /// The paper's figures (%) over 0.1..1 and 0.5..0.8, if published.
    pub published: Option<(f64, f64)>,
}

fn variant(label: &'static str, model: Model) -> Variant {
    Variant {
        label,
        model,
        tension: model.info().tension,
        alpha: AlphaRule::Calibrate,
        reading: Reading::EnergySplit,
        published: None,
    }
}

/// The variants of Table 1: the paper's four models (Anagnostopoulos in both tension rules, the paper's own
/// model with eq (8) and calibrated, in both readings), then every other damped model of the library.
pub fn variants() -> Vec<Variant> {
    let ana = Some((28.76, 11.65));
    let papi = Some((3.68, 0.68));
    let mut v = vec![
        Variant {
            published: ana,
            ..variant(
                "Anagnostopoulos (kelvin-voigt, tension allowed)",
                Model::KelvinVoigt,
            )
        },
        Variant {
            tension: Tension::Clamp,
            published: ana,
            ..variant(
                "Anagnostopoulos (kelvin-voigt, clamped)",
                Model::KelvinVoigt,
            )
        },
        Variant {
            published: Some((9.41, 9.04)),
            ..variant("Mahmoud & Jankowski", Model::MahmoudJankowski)
        },
        Variant {
            published: Some((10.86, 4.60)),
            ..variant("Ye et al.", Model::Ye)
        },
        Variant {
            alpha: AlphaRule::Eq8,
            published: papi,
            ..variant("Papi, eq (8) alpha, energy-split", Model::Papi)
        },
        Variant {
            alpha: AlphaRule::Eq8,
            reading: Reading::SameDamping,
            published: papi,
            ..variant("Papi, eq (8) alpha, same-damping", Model::Papi)
        },
        Variant {
            published: papi,
            ..variant("Papi, calibrated alpha, energy-split", Model::Papi)
        },
        Variant {
            reading: Reading::SameDamping,
            published: papi,
            ..variant("Papi, calibrated alpha, same-damping", Model::Papi)
        },
    ];
    for (label, m) in [
        ("Hunt & Crossley", Model::HuntCrossley),
        ("Herbert & McWhannell", Model::HerbertMcWhannell),
        ("Lee & Wang", Model::LeeWang),
        ("Lankarani & Nikravesh", Model::LankaraniNikravesh),
        ("Gonthier et al.", Model::Gonthier),
        ("Zhiying & Qishao", Model::ZhiyingQishao),
        ("Flores et al.", Model::Flores),
        ("Hertzdamp (OpenSees)", Model::Hertzdamp),
        ("Jankowski", Model::Jankowski),
        ("Impact material (bilinear)", Model::ImpactMaterial),
    ] {
        v.push(variant(label, m));
    }
    v
}

/// The delivered `e_post` of `variant` for requested `e` (formula damping; `alpha` per the variant).
pub fn e_post(variant: &Variant, e: f64) -> Result<f64, Error> {
    let spec = ContactModel::new(variant.model, 1.0, e)?
        .with_damping(Damping::Formula)
        .with_tension(variant.tension)
        .with_reading(variant.reading)
        .with_alpha(variant.alpha)?;
    let (law, _) = spec.prepare()?.law(1.0, 1.0)?;
    delivered_e(&law, variant.tension, &ImpactSetup::relative(1.0, 1.0))
}

/// Relative errors (%) at `e = i / 100`, `i = 10..=100`; the 0.1 grid and both ranges are subsets of it
/// (`i / 10` and `10 i / 100` are the same double).
fn errors(variant: &Variant) -> Result<Vec<(u32, f64)>, Error> {
    (10..=100)
        .map(|i| {
            let e = f64::from(i) / 100.0;
            Ok((i, (e - e_post(variant, e)?).abs() / e * 100.0))
        })
        .collect()
}

fn mean(errors: &[(u32, f64)], keep: impl Fn(u32) -> bool) -> f64 {
    let (sum, count) = errors
        .iter()
        .filter(|(i, _)| keep(*i))
        .fold((0.0, 0u32), |(s, c), p| (s + p.1, c + 1));
    sum / f64::from(count)
}

/// Reproduces Table 1 for every variant of [`variants`].
pub fn table1() -> Result<Vec<Row>, Error> {
    variants()
        .iter()
        .map(|v| {
            let err = errors(v)?;
            let coarse = |i: u32| i.is_multiple_of(10);
            let mid = |i: u32| (50..=80).contains(&i);
            Ok(Row {
                label: v.label,
                model: v.model.name(),
                coarse_all: mean(&err, coarse),
                coarse_mid: mean(&err, |i| coarse(i) && mid(i)),
                fine_all: mean(&err, |_| true),
                fine_mid: mean(&err, mid),
                published: v.published,
            })
        })
        .collect()
}
