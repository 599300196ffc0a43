//! The separation under a stationary random ground motion: the library's random vibration
//! ([`pounding::separation::random`]) at every contact level, with a code's gap beside it.

use super::codes::CodeInfo;
use super::tables::Refusal;
use pounding::analysis::Scenario;
use pounding::ground_motion::synthetic::Filter;
use pounding::separation::random::{pounding_probability, Clumping, Crossing, WhiteNoise};
use serde::Serialize;
use serde_json::{json, Map, Value};

/// The random motion and how long it lasts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NoiseOptions {
    /// Two-sided spectral density of the white noise, m^2/s^3.
    pub s0: f64,
    /// The filter that shapes it, if any.
    pub filter: Option<Filter>,
    /// Duration of the strong motion, s.
    pub duration: f64,
    /// How crossings are counted.
    pub clumping: Clumping,
}

/// One contact level under the random motion.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct NoiseLevel {
    /// Floors (of the left building, of the right), from 1.
    pub floors: (usize, usize),
    /// The contact's gap at rest, m.
    pub gap: f64,
    /// The closing's statistics: `sigma` (m), `sigma_rate` (m/s), `nu0` (1/s), `delta` (with clumps).
    #[serde(flatten)]
    pub crossing: Crossing,
    /// Probability of pounding within the duration at the contact's gap.
    pub probability: f64,
    /// The gap for the target probability, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gap_for_target: Option<f64>,
    /// The gap the code asked for requires here, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub code_required_gap: Option<f64>,
    /// Probability of pounding within the duration at the code's gap.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub probability_at_code_gap: Option<f64>,
}

/// One pair of neighbours under the random motion.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct NoisePair {
    /// The left and the right building.
    pub between: [String; 2],
    /// Its levels.
    pub levels: Vec<NoiseLevel>,
}

/// The separation under a random motion.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct NoiseReport {
    /// The motion: `s0` (m^2/s^3), `filter`, `duration` (s), `clumping`, and what the structures were taken as.
    pub white_noise: Map<String, Value>,
    /// The target probability within the duration, if one was given.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub target_probability: Option<f64>,
    /// Pair by pair.
    pub pairs: Vec<NoisePair>,
    /// The code asked for, with its parameters.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub code: Option<CodeInfo>,
    /// The unit of each quantity.
    pub units: Map<String, Value>,
}

/// The report of `s` under the random motion `o`.
pub fn report(
    s: &Scenario,
    o: &NoiseOptions,
    target: Option<f64>,
    code: Option<CodeInfo>,
) -> Result<NoiseReport, Refusal> {
    let noise = WhiteNoise {
        s0: o.s0,
        filter: o.filter,
    };
    let pairs = pounding_probability(s, &noise, o.duration, target, o.clumping).map_err(|e| {
        let key = match &e {
            pounding::Error::Parameter { name, .. } | pounding::Error::Choice { name, .. } => {
                Some(name.to_string())
            }
            _ => None,
        };
        (key, e.to_string())
    })?;
    let names = |i: usize| s.buildings()[i].name.clone();
    let pairs = pairs
        .into_iter()
        .enumerate()
        .map(|(p, pair)| NoisePair {
            between: [names(pair.left), names(pair.right)],
            levels: pair
                .levels
                .into_iter()
                .enumerate()
                .map(|(l, lc)| {
                    let code_gap = code.as_ref().and_then(|c| c.gap(p, l));
                    NoiseLevel {
                        floors: lc.floors,
                        gap: lc.gap,
                        crossing: lc.crossing,
                        probability: lc.probability,
                        gap_for_target: lc.gap_for_target,
                        code_required_gap: code_gap,
                        probability_at_code_gap: code_gap
                            .map(|g| lc.crossing.probability(g, o.duration, o.clumping)),
                    }
                })
                .collect(),
        })
        .collect();
    let inelastic = s
        .buildings()
        .iter()
        .any(|b| b.structure.storey_laws().iter().any(|l| l.is_inelastic()));
    let filter = o.filter.map(|f| match f {
        Filter::KanaiTajimi { wg, zg } => json!({"kind": "kanai-tajimi", "wg": wg, "zg": zg}),
        Filter::CloughPenzien { wg, zg, wf, zf } => {
            json!({"kind": "clough-penzien", "wg": wg, "zg": zg, "wf": wf, "zf": zf})
        }
    });
    let structures = if inelastic {
        "linear: inelastic storeys at their initial stiffness"
    } else {
        "linear"
    };
    let white_noise = match json!({
        "s0": o.s0, "filter": filter, "duration": o.duration, "clumping": o.clumping.name(),
        "structures": structures,
    }) {
        Value::Object(m) => m,
        _ => Map::new(),
    };
    let units = match json!({
        "s0": "m^2/s^3, two-sided: E[a(t) a(t + tau)] = 2 pi s0 delta(tau)", "duration": "s",
        "wg": "rad/s", "wf": "rad/s", "gap": "m (the contact's at rest)",
        "sigma": "m (standard deviation of the closing u_left - u_right)",
        "sigma_rate": "m/s", "nu0": "1/s (mean rate of zero up-crossings)",
        "delta": "Vanmarcke's bandwidth (dimensionless)",
        "probability": "of pounding within the duration", "gap_for_target": "m",
        "code_required_gap": "m",
    }) {
        Value::Object(m) => m,
        _ => Map::new(),
    };
    Ok(NoiseReport {
        white_noise,
        target_probability: target,
        pairs,
        code,
        units,
    })
}
