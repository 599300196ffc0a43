//! A separation's options as a JSON object (what Python passes).

use super::tables::Refusal;
use super::{codes, noise, risk};
use pounding::fragility::HazardCurve;
use pounding::ground_motion::synthetic::{Filter, SyntheticParams};
use pounding::separation::codes::{CodeRule, DesignSpectrum, GbSystem, GroundType};
use pounding::separation::random::Clumping;
use serde_json::Value;

/// What a separation is asked beyond the required gap under the scenario's record.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SeparationOptions {
    /// Records in place of the scenario's (sources: built-in names or file paths).
    pub records: Vec<String>,
    /// Factor on the ABS, SRSS and DDC rules at aligned floors (0 < f <= 1).
    pub aligned_factor: Option<f64>,
    /// The probability of pounding to find the gap for (0 < P < 1): within the duration of a random
    /// motion, or per record of a suite.
    pub target_probability: Option<f64>,
    /// A stationary random ground motion instead of records.
    pub white_noise: Option<noise::NoiseOptions>,
    /// A hazard curve and intensity levels: the mean annual frequency of pounding against the gap.
    pub risk: Option<risk::RiskOptions>,
    /// A design code's rule.
    pub code: Option<codes::CodeOptions>,
}

fn refuse(key: &str, msg: String) -> Refusal {
    (Some(key.into()), msg)
}

#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct Doc {
    target_probability: Option<f64>,
    white_noise: Option<NoiseDoc>,
    code: Option<CodeDoc>,
    hazard: Option<HazardDoc>,
}
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct NoiseDoc {
    s0: f64,
    duration: f64,
    filter: Option<FilterDoc>,
    clumping: Option<Clumping>,
}
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct FilterDoc {
    kind: pounding::ground_motion::synthetic::FilterKind,
    wg: Option<f64>,
    zg: Option<f64>,
    wf: Option<f64>,
    zf: Option<f64>,
}
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct CodeDoc {
    name: pounding::separation::codes::CodeName,
    cd: Option<f64>,
    ie: Option<f64>,
    q: Option<f64>,
    qd: Option<f64>,
    r: Option<f64>,
    intensity: Option<u8>,
    system: Option<GbSystem>,
    design_spectrum: Option<Vec<[f64; 2]>>,
    spectrum: Option<SpectrumDoc>,
}
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct SpectrumDoc {
    shape: String,
    sds: Option<f64>,
    sd1: Option<f64>,
    tl: Option<f64>,
    ag: Option<f64>,
    ground_type: Option<GroundType>,
    spectrum_type: Option<u8>,
}
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct HazardDoc {
    curve: Vec<[f64; 2]>,
    levels: Vec<f64>,
    measure: Option<String>,
    building: Option<String>,
    damping: Option<f64>,
    target_rate: Option<f64>,
    design_life: Option<f64>,
}

/// The options of a separation as a JSON object (what Python's `pounding.separation` passes): keys
/// `target_probability`, `white_noise` (`s0`, `duration`, `filter` with `kind` and `wg`, `zg`, `wf`, `zf`,
/// `clumping`), `code` (`name` and its parameters `cd`, `ie`, `q`, `qd`, `r`, `intensity`, `system`, with
/// `design_spectrum` rows `[T, Sa]` or `spectrum`: `shape` and its parameters), `hazard` (`curve` rows
/// `[IM, rate]`, `levels`, `measure`, `building`, `damping`, `target_rate`, `design_life`).
pub fn options_from_json(
    v: &Value,
    records: Vec<String>,
    aligned_factor: Option<f64>,
) -> Result<SeparationOptions, Refusal> {
    let doc: Doc = serde_json::from_value(v.clone()).map_err(|e| (None, e.to_string()))?;
    let d = SyntheticParams::default();
    let white_noise = doc.white_noise.map(|n| noise::NoiseOptions {
        s0: n.s0,
        duration: n.duration,
        filter: n.filter.map(|f| {
            let (wg, zg) = (f.wg.unwrap_or(d.wg), f.zg.unwrap_or(d.zg));
            match f.kind {
                pounding::ground_motion::synthetic::FilterKind::KanaiTajimi => {
                    Filter::KanaiTajimi { wg, zg }
                }
                pounding::ground_motion::synthetic::FilterKind::CloughPenzien => {
                    Filter::CloughPenzien {
                        wg,
                        zg,
                        wf: f.wf.unwrap_or(d.wf),
                        zf: f.zf.unwrap_or(d.zf),
                    }
                }
            }
        }),
        clumping: n.clumping.unwrap_or(Clumping::Poisson),
    });
    let code = doc.code.map(code_options).transpose()?;
    let risk = doc.hazard.map(risk_options).transpose()?;
    Ok(SeparationOptions {
        records,
        aligned_factor,
        target_probability: doc.target_probability,
        white_noise,
        risk,
        code,
    })
}

/// The code of a JSON document.
fn code_options(c: CodeDoc) -> Result<codes::CodeOptions, Refusal> {
    let need = |name: &str, x: Option<f64>, key: &str| {
        x.ok_or_else(|| refuse(key, format!("{key} is required by code {name}")))
    };
    let name = c.name.name();
    let rule = match c.name {
        pounding::separation::codes::CodeName::Asce7_22 => CodeRule::Asce7_22 {
            cd: need(name, c.cd, "cd")?,
            ie: c.ie.unwrap_or(1.0),
        },
        pounding::separation::codes::CodeName::En1998_1 => {
            let q = need(name, c.q, "q")?;
            CodeRule::En1998_1 {
                q,
                qd: c.qd.unwrap_or(q),
            }
        }
        pounding::separation::codes::CodeName::Is1893_2016 => CodeRule::Is1893_2016 {
            r: need(name, c.r, "r")?,
        },
        pounding::separation::codes::CodeName::Gb50011_2010 => CodeRule::Gb50011_2010 {
            intensity: c.intensity.ok_or_else(|| {
                refuse(
                    "intensity",
                    "intensity is required by code gb50011-2010: 6, 7, 8 or 9".into(),
                )
            })?,
            system: c.system.unwrap_or(GbSystem::Frame),
        },
    };
    let spectrum = match (c.design_spectrum, c.spectrum) {
        (Some(rows), _) => Some(DesignSpectrum::Table(
            rows.into_iter().map(|r| (r[0], r[1])).collect(),
        )),
        (None, Some(sp)) if sp.shape == "asce7-22" => Some(DesignSpectrum::Asce7 {
            sds: need("asce7-22", sp.sds, "sds")?,
            sd1: need("asce7-22", sp.sd1, "sd1")?,
            tl: need("asce7-22", sp.tl, "tl")?,
            reduction: need("asce7-22", c.r, "r")? / c.ie.unwrap_or(1.0),
        }),
        (None, Some(sp)) if sp.shape == "en1998-1" => Some(DesignSpectrum::En1998 {
            ag: need("en1998-1", sp.ag, "ag")?,
            ground: sp.ground_type.unwrap_or(GroundType::B),
            kind: sp.spectrum_type.unwrap_or(1),
            q: need("en1998-1", c.q, "q")?,
        }),
        (None, Some(sp)) => {
            return Err(refuse(
                "spectrum",
                format!(
                    "spectrum shape = {:?} is not allowed: \"asce7-22\" or \"en1998-1\"",
                    sp.shape
                ),
            ))
        }
        (None, None) => None,
    };
    let spectrum = spectrum
        .map(DesignSpectrum::checked)
        .transpose()
        .map_err(|e| (None, e.to_string()))?;
    Ok(codes::CodeOptions { rule, spectrum })
}

/// The hazard of a JSON document.
fn risk_options(h: HazardDoc) -> Result<risk::RiskOptions, Refusal> {
    Ok(risk::RiskOptions {
        hazard: HazardCurve::new(h.curve.into_iter().map(|r| (r[0], r[1])).collect())
            .map_err(|e| (None, e.to_string()))?,
        measure: match h.measure.as_deref() {
            Some("pga") => risk::MeasureOptions::Pga,
            None | Some("sa") => risk::MeasureOptions::Sa {
                building: h.building,
                damping: h.damping.unwrap_or(0.05),
            },
            Some(other) => {
                return Err(refuse(
                    "measure",
                    format!("measure = {other:?} is not allowed: \"sa\" or \"pga\""),
                ))
            }
        },
        levels: h.levels,
        target_rate: h.target_rate,
        design_life: h.design_life,
    })
}
