//! A design code's separation beside the analyses' answers: the library's rule
//! ([`pounding::separation::codes`]) at every contact level, with what the report says of it.

use super::tables::{PairReport, RecordReport, Refusal, SuiteStats};
use pounding::analysis::Scenario;
use pounding::separation::codes::{code_gaps, CodeLevel, CodeRule, DesignSpectrum};
use pounding::separation::suite::{empirical_probability, GapFit};
use serde::Serialize;
use serde_json::{json, Map, Value};

/// A code's rule and the design spectrum of its elastic analysis.
#[derive(Clone, Debug, PartialEq)]
pub struct CodeOptions {
    /// The rule with its parameters.
    pub rule: CodeRule,
    /// The design spectrum (every rule but GB 50011's needs one).
    pub spectrum: Option<DesignSpectrum>,
}

/// One contact level under the code.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CodeLevelReport {
    /// The left and the right building.
    pub between: [String; 2],
    /// The library's answer: floors, elastic displacements (m), aligned floors, the code's gap (m).
    #[serde(flatten)]
    pub level: CodeLevel,
}

/// The code asked for, its parameters, and its gap at every level of every pair.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CodeInfo {
    /// `asce7-22`, `en1998-1`, `is1893-2016` or `gb50011-2010`.
    pub name: &'static str,
    /// The clause applied, and how far it was checked against the standard's text
    /// (docs/separation.md, "The codes' rules").
    pub clause: &'static str,
    /// Its parameters by name.
    pub parameters: Map<String, Value>,
    /// The design spectrum of the elastic analysis, in words.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub spectrum: Option<String>,
    /// Every level of every pair of neighbours, in the order of the report's pairs.
    pub levels: Vec<CodeLevelReport>,
    /// The same, pair by pair (for filling the report's levels).
    #[serde(skip)]
    pub pairs: Vec<Vec<CodeLevel>>,
}

impl CodeInfo {
    /// The code's gaps on `s`, if a code was asked for.
    pub fn of(s: &Scenario, options: Option<&CodeOptions>) -> Result<Option<Self>, Refusal> {
        let Some(o) = options else {
            return Ok(None);
        };
        let gaps = code_gaps(s, o.rule, o.spectrum.as_ref()).map_err(refusal)?;
        let names = |i: usize| s.buildings()[i].name.clone();
        let levels = gaps
            .iter()
            .flat_map(|(l, r, levels)| {
                levels.iter().map(|level| CodeLevelReport {
                    between: [names(*l), names(*r)],
                    level: level.clone(),
                })
            })
            .collect();
        let (clause, parameters) = describe(&o.rule);
        Ok(Some(Self {
            name: o.rule.name().name(),
            clause,
            parameters,
            spectrum: o.spectrum.as_ref().map(spectrum_words),
            levels,
            pairs: gaps.into_iter().map(|g| g.2).collect(),
        }))
    }

    /// The code's gap at level `l` of pair `p`, m.
    pub fn gap(&self, p: usize, l: usize) -> Option<f64> {
        self.pairs
            .get(p)
            .and_then(|levels| levels.get(l))
            .map(|c| c.code_required_gap)
    }

    /// Writes the code's gap beside each level of `pairs` (one record's).
    pub fn fill(&self, pairs: &mut [PairReport]) {
        for (p, pair) in pairs.iter_mut().enumerate() {
            for (l, level) in pair.levels.iter_mut().enumerate() {
                level.code_required_gap = self.gap(p, l);
            }
        }
    }

    /// Writes the code's gap beside each level of a suite's statistics, with the probability that a record
    /// pounds at it (from the fit, and the records' fraction).
    pub fn fill_stats(&self, stats: &mut SuiteStats, runs: &[RecordReport]) {
        for (p, pair) in stats.pairs.iter_mut().enumerate() {
            for (l, level) in pair.levels.iter_mut().enumerate() {
                let Some(g) = self.gap(p, l) else { continue };
                let gaps: Vec<f64> = runs
                    .iter()
                    .map(|r| r.pairs[p].levels[l].level.required_gap)
                    .collect();
                level.code_required_gap = Some(g);
                level.probability_at_code_gap = level.fit.map(|f: GapFit| f.probability(g));
                level.probability_at_code_gap_empirical = Some(empirical_probability(&gaps, g));
            }
        }
    }
}

fn refusal(e: pounding::Error) -> Refusal {
    let key = match &e {
        pounding::Error::Parameter { name, .. } | pounding::Error::Choice { name, .. } => {
            Some(name.to_string())
        }
        _ => None,
    };
    (key, e.to_string())
}

/// The clause of `rule` with what was checked of it, and its parameters.
fn describe(rule: &CodeRule) -> (&'static str, Map<String, Value>) {
    let (clause, params) = match *rule {
        CodeRule::Asce7_22 { cd, ie } => (
            "ASCE 7 structural separation (7-10/7-16 12.12.3): delta_M = C_d delta_max / I_e, SRSS of the two on one property; text checked in the 7-10/7-16 wording, the 7-22 numbering not",
            json!({"cd": cd, "ie": ie}),
        ),
        CodeRule::En1998_1 { q, qd } => (
            "EN 1998-1:2004 4.4.2.7 with 4.3.4: d_s = q_d d_e, SRSS of the two units, x 0.7 where floor levels coincide; as secondary sources and next-physics.md state it, the standard's text not at hand",
            json!({"q": q, "qd": qd}),
        ),
        CodeRule::Is1893_2016 { r } => (
            "IS 1893 (Part 1):2016 7.11.3: R times the sum of the two buildings' displacements, R/2 where floor levels coincide; as a secondary source paraphrases it, the standard's text not at hand",
            json!({"r": r}),
        ),
        CodeRule::Gb50011_2010 { intensity, system } => (
            "GB 50011-2010 6.1.4: 100 mm up to 15 m, +20 mm per 5, 4, 3, 2 m above for intensity 6 to 9 (frames), 70 % / 50 % for frame-shear-wall / shear-wall, at least 100 mm, from the lower building's height; checked against the clause's text",
            json!({"intensity": intensity, "system": system.name()}),
        ),
    };
    match params {
        Value::Object(m) => (clause, m),
        _ => (clause, Map::new()),
    }
}

/// A design spectrum in words.
fn spectrum_words(s: &DesignSpectrum) -> String {
    use pounding::words::number as n;
    match s {
        DesignSpectrum::Table(rows) => format!("a table of {} rows (period s, Sa m/s^2)", rows.len()),
        DesignSpectrum::Asce7 {
            sds,
            sd1,
            tl,
            reduction,
        } => format!(
            "ASCE 7 two-period shape, S_DS = {} g, S_D1 = {} g, T_L = {} s, divided by R / I_e = {}",
            n(*sds),
            n(*sd1),
            n(*tl),
            n(*reduction)
        ),
        DesignSpectrum::En1998 { ag, ground, kind, q } => format!(
            "EN 1998-1 design spectrum type {kind}, ground {}, a_g = {} m/s^2, q = {}",
            ground.name(),
            n(*ag),
            n(*q)
        ),
    }
}
