//! Risk-targeted separation (docs/separation.md, "Mean annual frequency"): a suite of records scaled to
//! intensity levels as an IDA scales them, each run without contact giving every level's required gap;
//! for a gap `g`, the intensity at which each record first needs more than `g` (read between levels,
//! proportional beyond them) makes a lognormal fragility (Baker 2015's IDA fit) integrated over the hazard
//! curve:
//! `lambda(g) = int P(g_req > g | im) |d lambda_IM(im)|`. The gap for a target annual frequency (or a
//! probability over a design life, `1 - exp(-lambda T)`) is the root of `lambda(g)`.

use super::codes::CodeInfo;
use super::runs::run_all;
use super::tables::Refusal;
use crate::ida::{Ida, Measure};
use pounding::fragility::HazardCurve;
use serde::Serialize;
use serde_json::{json, Map, Value};
use std::ops::ControlFlow;

/// The intensity measure of a risk-targeted separation.
#[derive(Clone, Debug, PartialEq)]
pub enum MeasureOptions {
    /// Peak ground acceleration, m/s^2.
    Pga,
    /// Pseudo-spectral acceleration at the first period of `building` (the first building if `None`),
    /// damping ratio `damping`, m/s^2.
    Sa {
        /// The building whose first period.
        building: Option<String>,
        /// Damping ratio of the spectrum.
        damping: f64,
    },
}

/// What a risk-targeted separation is asked.
#[derive(Clone, Debug, PartialEq)]
pub struct RiskOptions {
    /// The hazard curve of the intensity measure.
    pub hazard: HazardCurve,
    /// The intensity measure.
    pub measure: MeasureOptions,
    /// Intensity levels the records are scaled to, m/s^2.
    pub levels: Vec<f64>,
    /// The target mean annual frequency of pounding, 1/yr.
    pub target_rate: Option<f64>,
    /// A design life, yr: with a target probability, the target rate `-ln(1 - P) / T`; and the probability
    /// of pounding over it at each gap.
    pub design_life: Option<f64>,
}

/// The curve of one level: gaps and their annual frequencies.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct FrequencyCurve {
    /// Gaps, m.
    pub gaps: Vec<f64>,
    /// Mean annual frequency of pounding at each, 1/yr.
    pub annual_frequency: Vec<f64>,
}

/// One contact level's risk.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct RiskLevel {
    /// Floors (of the left building, of the right), from 1.
    pub floors: (usize, usize),
    /// The contact's gap at rest, m.
    pub gap: f64,
    /// Mean annual frequency of pounding at the contact's gap, 1/yr.
    pub annual_frequency: f64,
    /// Probability of pounding over the design life at the contact's gap.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub probability_in_life: Option<f64>,
    /// The gap whose annual frequency is the target, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gap_for_target: Option<f64>,
    /// The gap the code asked for requires here, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub code_required_gap: Option<f64>,
    /// Mean annual frequency of pounding at the code's gap, 1/yr.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub annual_frequency_at_code_gap: Option<f64>,
    /// The frequency against the gap.
    pub curve: FrequencyCurve,
}

/// One pair's levels.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct RiskPair {
    /// The left and the right building.
    pub between: [String; 2],
    /// Its levels.
    pub levels: Vec<RiskLevel>,
}

/// The risk-targeted separation.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct RiskReport {
    /// The study: records, measure, levels, hazard, targets.
    pub risk: Map<String, Value>,
    /// Pair by pair.
    pub pairs: Vec<RiskPair>,
    /// The code asked for, with its parameters.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub code: Option<CodeInfo>,
    /// The unit of each quantity.
    pub units: Map<String, Value>,
}

/// The required gaps of one contact level, record by record, level by level (m).
struct LevelGaps {
    gaps: Vec<Vec<f64>>,
}

impl LevelGaps {
    /// The intensity (m/s^2) at which each record first needs more than `g` (m > 0): its required gap read
    /// log-log between the levels that bracket `g`, and proportional to the intensity beyond the levels
    /// (exact for linear structures, whose gap scales with the record); infinite for a record whose floors
    /// never approach.
    fn capacities(&self, g: f64, levels: &[f64]) -> Vec<f64> {
        self.gaps
            .iter()
            .map(|r| {
                let last = levels.len() - 1;
                match r.iter().position(|&x| x >= g) {
                    Some(0) => levels[0] * g / r[0],
                    Some(j) if r[j - 1] > 0.0 => {
                        let t = (g / r[j - 1]).ln() / (r[j] / r[j - 1]).ln();
                        levels[j - 1] * (levels[j] / levels[j - 1]).powf(t)
                    }
                    Some(j) => levels[j] * g / r[j],
                    None if r[last] > 0.0 => levels[last] * g / r[last],
                    None => f64::INFINITY,
                }
            })
            .collect()
    }

    /// The mean annual frequency (1/yr) of needing more than `g` (m): the records' intensities of first
    /// exceedance ([`LevelGaps::capacities`]) as a lognormal fragility (their log mean and standard
    /// deviation: Baker 2015's IDA fit), scaled by the share of records that approach at all, integrated
    /// over the hazard curve.
    fn frequency(&self, g: f64, levels: &[f64], hazard: &HazardCurve) -> f64 {
        if g <= 0.0 {
            return hazard.integrate(&|_| 1.0);
        }
        let caps: Vec<f64> = self
            .capacities(g, levels)
            .into_iter()
            .filter(|c| c.is_finite())
            .collect();
        let share = caps.len() as f64 / self.gaps.len() as f64;
        let n = caps.len();
        match n {
            0 => 0.0,
            1 => share * hazard.integrate(&|im: f64| f64::from(u8::from(im >= caps[0]))),
            _ => {
                let logs: Vec<f64> = caps.iter().map(|c| c.ln()).collect();
                let mean = logs.iter().sum::<f64>() / n as f64;
                let sd = (logs.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / n as f64).sqrt();
                if sd > 0.0 {
                    share
                        * hazard.mean_annual_frequency(&pounding::fragility::Fragility {
                            median: mean.exp(),
                            beta: sd,
                        })
                } else {
                    share * hazard.integrate(&|im: f64| f64::from(u8::from(im >= mean.exp())))
                }
            }
        }
    }
}

/// The risk-targeted separation of `scenario` under `options.records` scaled to `risk.levels`.
pub fn report(
    scenario: &Value,
    label: &str,
    records: &[String],
    (aligned_factor, target_probability): (Option<f64>, Option<f64>),
    risk: &RiskOptions,
    code: Option<CodeInfo>,
    go_on: &mut dyn FnMut() -> ControlFlow<()>,
) -> Result<RiskReport, Refusal> {
    let target = target_rate(risk, target_probability)?;
    let ida = study(scenario, label, records, risk)?;
    let ims = ida.intensities().map_err(|e| (None, e.0))?;
    let nl = ida.levels.len();
    let variants: Vec<(Option<String>, Value)> = (0..ida.records.len())
        .flat_map(|i| (0..nl).map(move |j| (i, j)))
        .map(|(i, j)| {
            let (_, v) = ida.scenario(i, j, &ims);
            (Some(ida.records[i].clone()), v)
        })
        .collect();
    let runs = run_all(&variants, label, aligned_factor, go_on)?;
    let first = &runs[0];
    let pairs = first
        .pairs
        .iter()
        .enumerate()
        .map(|(p, pair)| RiskPair {
            between: pair.between.clone(),
            levels: (0..pair.levels.len())
                .map(|l| {
                    let lg = LevelGaps {
                        gaps: (0..ida.records.len())
                            .map(|i| {
                                (0..nl)
                                    .map(|j| runs[i * nl + j].pairs[p].levels[l].level.required_gap)
                                    .collect()
                            })
                            .collect(),
                    };
                    let gap = pair.levels[l].level.gap;
                    let freq = |g: f64| lg.frequency(g, &ida.levels, &risk.hazard);
                    let top = lg.gaps.iter().flatten().fold(0.0f64, |a, &b| a.max(b));
                    let curve_gaps: Vec<f64> =
                        (1..=60).map(|k| 1.5 * top * f64::from(k) / 60.0).collect();
                    let code_gap = code.as_ref().and_then(|c| c.gap(p, l));
                    let lam = freq(gap);
                    RiskLevel {
                        floors: pair.levels[l].level.floors,
                        gap,
                        annual_frequency: lam,
                        probability_in_life: risk.design_life.map(|t| -(-lam * t).exp_m1()),
                        gap_for_target: target.map(|t| gap_for(&freq, t)),
                        code_required_gap: code_gap,
                        annual_frequency_at_code_gap: code_gap.map(freq),
                        curve: FrequencyCurve {
                            annual_frequency: curve_gaps.iter().map(|&g| freq(g)).collect(),
                            gaps: curve_gaps,
                        },
                    }
                })
                .collect(),
        })
        .collect();
    let info = json!({
        "records": ida.records, "measure": ida.measure_name(), "levels": ida.levels,
        "record_intensities": ims, "hazard_rows": risk.hazard.points().len(),
        "target_rate": target, "design_life": risk.design_life,
        "target_probability": target_probability,
    });
    let units = json!({
        "levels": "m/s^2", "record_intensities": "m/s^2 (at scale 1)", "gap": "m",
        "annual_frequency": "1/yr (mean annual frequency of pounding)", "target_rate": "1/yr",
        "design_life": "yr", "probability_in_life": "1 - exp(-annual_frequency x design_life)",
        "gap_for_target": "m", "gaps": "m", "code_required_gap": "m",
    });
    let (Value::Object(risk_map), Value::Object(units)) = (info, units) else {
        return Err((None, "risk report: not an object".into()));
    };
    Ok(RiskReport {
        risk: risk_map,
        pairs,
        code,
        units,
    })
}

/// The target annual frequency: given, or from a probability over the design life.
fn target_rate(risk: &RiskOptions, p: Option<f64>) -> Result<Option<f64>, Refusal> {
    match (risk.target_rate, risk.design_life, p) {
        (Some(_), _, Some(_)) => Err((
            Some("target_rate".into()),
            "target_rate is not allowed with target_probability: give a rate (1/yr), or a probability with design_life".into(),
        )),
        (Some(r), _, None) if !(r > 0.0 && r.is_finite()) => Err((
            Some("target_rate".into()),
            format!("target_rate = {} is not allowed: > 0 (1/yr)", pounding::words::number(r)),
        )),
        (Some(r), _, None) => Ok(Some(r)),
        (None, Some(t), Some(p)) if t > 0.0 && t.is_finite() => Ok(Some(-(-p).ln_1p() / t)),
        (None, Some(t), _) if !(t > 0.0 && t.is_finite()) => Err((
            Some("design_life".into()),
            format!("design_life = {} is not allowed: > 0 (yr)", pounding::words::number(t)),
        )),
        (None, None, Some(_)) => Err((
            Some("target_probability".into()),
            "target_probability with a hazard curve needs design_life (yr): the probability over it".into(),
        )),
        _ => Ok(None),
    }
}

/// The IDA-style study of the separation: the scenario, its records, the measure and levels.
fn study(
    scenario: &Value,
    label: &str,
    records: &[String],
    risk: &RiskOptions,
) -> Result<Ida, Refusal> {
    let loaded = crate::input::from_value(scenario, label)?;
    let buildings: Vec<String> = loaded
        .scenario
        .buildings()
        .iter()
        .map(|b| b.name.clone())
        .collect();
    let measure = match &risk.measure {
        MeasureOptions::Pga => Measure::Pga,
        MeasureOptions::Sa { building, damping } => {
            let name = building.clone().unwrap_or(buildings[0].clone());
            let Some(b) = loaded.scenario.buildings().iter().find(|b| b.name == name) else {
                return Err((
                    Some("building".into()),
                    format!(
                        "building = {name:?} names no building; the scenario's are {}",
                        buildings.join(", ")
                    ),
                ));
            };
            if !(0.0..1.0).contains(damping) {
                return Err((
                    Some("damping".into()),
                    format!(
                        "damping = {} is not allowed: 0 <= damping < 1",
                        pounding::words::number(*damping)
                    ),
                ));
            }
            Measure::Sa {
                period: b.structure.modes().periods()[0],
                building: name,
                damping: *damping,
            }
        }
    };
    let mut levels = risk.levels.clone();
    if levels.is_empty() || levels.iter().any(|x| !(x.is_finite() && *x > 0.0)) {
        return Err((
            Some("levels".into()),
            "levels are not allowed: at least one intensity, each > 0 (m/s^2)".into(),
        ));
    }
    levels.sort_by(f64::total_cmp);
    levels.dedup();
    let runs = records.len() * levels.len();
    if runs > super::runs::MAX_RECORDS {
        return Err((
            Some("levels".into()),
            format!(
                "{} records x {} levels = {runs} runs is not allowed: at most {} in one separation",
                records.len(),
                levels.len(),
                super::runs::MAX_RECORDS
            ),
        ));
    }
    Ok(Ida {
        path: std::path::PathBuf::from(label),
        base: scenario.clone(),
        records: records.to_vec(),
        measure,
        levels,
        limit_states: Vec::new(),
        buildings,
        inelastic: Vec::new(),
    })
}

/// The gap (m) whose annual frequency is `target`, by bisection on the falling `freq` (which vanishes
/// only for records that never approach: bracketed by doubling).
fn gap_for(freq: &dyn Fn(f64) -> f64, target: f64) -> f64 {
    let mut hi = 1e-3;
    while freq(hi) > target && hi < 1e3 {
        hi *= 2.0;
    }
    let mut lo = 0.0;
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if freq(mid) > target {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    hi
}
