//! The separation's options from the command line, checked against each other.

use crate::args::SeparationArgs;
use crate::error::{input, CliError};
use pounding::fragility::HazardCurve;
use pounding::ground_motion::synthetic::{Filter, FilterKind};
use pounding::separation::codes::{CodeName, CodeRule, DesignSpectrum};
use pounding_study::separation::codes::CodeOptions;
use pounding_study::separation::noise::NoiseOptions;
use pounding_study::separation::risk::{MeasureOptions, RiskOptions};
use pounding_study::separation::SeparationOptions;
use std::path::Path;

/// The options of `a`, with `records` (its `--records` resolved).
pub fn of(a: &SeparationArgs, records: Vec<String>) -> Result<SeparationOptions, CliError> {
    Ok(SeparationOptions {
        records,
        aligned_factor: a.aligned_factor,
        target_probability: a.target_probability,
        white_noise: noise(a)?,
        risk: risk(a)?,
        code: code(a)?,
    })
}

/// A library or study message naming key `k` (`target_probability = 2 is not allowed: ...`) as the
/// command line names it (`--target-probability 2 is not allowed: ...`).
pub fn flagged(k: Option<String>, m: String) -> String {
    // A library message names its parameter first (`aligned_factor = 2 is not allowed`).
    const OPTIONS: [&str; 7] = [
        "aligned_factor",
        "target_probability",
        "duration",
        "target_rate",
        "design_life",
        "levels",
        "s0",
    ];
    let k = k.or_else(|| {
        OPTIONS
            .iter()
            .find(|o| m.starts_with(&format!("{o} = ")))
            .map(|o| o.to_string())
    });
    let Some(k) = k else { return m };
    let flag = match k.as_str() {
        "s0" => "white-noise".to_string(),
        "damping" => "im-damping".to_string(),
        other => other.replace('_', "-"),
    };
    if let Some(rest) = m.strip_prefix(&format!("{k} = ")) {
        format!("--{flag} {rest}")
    } else if let Some(rest) = m.strip_prefix(&format!("{k} ")) {
        format!("--{flag} {rest}")
    } else {
        m
    }
}

fn noise(a: &SeparationArgs) -> Result<Option<NoiseOptions>, CliError> {
    let n = &a.noise;
    let Some(s0) = n.white_noise else {
        return Ok(None);
    };
    let duration = n.duration.ok_or_else(|| {
        input("--duration is required with --white-noise: how long the stationary motion lasts, s")
    })?;
    let filter = n.filter.map(|k| match k {
        FilterKind::KanaiTajimi => Filter::KanaiTajimi { wg: n.wg, zg: n.zg },
        FilterKind::CloughPenzien => Filter::CloughPenzien {
            wg: n.wg,
            zg: n.zg,
            wf: n.wf,
            zf: n.zf,
        },
    });
    if let Some(f) = filter {
        let (wg, zg) = match f {
            Filter::KanaiTajimi { wg, zg } | Filter::CloughPenzien { wg, zg, .. } => (wg, zg),
        };
        for (flag, x) in [("wg", wg), ("zg", zg), ("wf", n.wf), ("zf", n.zf)] {
            if !(x.is_finite() && x > 0.0) {
                return Err(input(format!(
                    "--{flag} {} is not allowed: > 0",
                    crate::output::fmt_num(x)
                )));
            }
        }
    }
    Ok(Some(NoiseOptions {
        s0,
        filter,
        duration,
        clumping: n.clumping,
    }))
}

/// The rows of a two-column file given as `flag`, for `what`.
fn pairs(path: &Path, flag: &str, what: &str) -> Result<Vec<(f64, f64)>, CliError> {
    let shown = path.display();
    // An input file that cannot be read is bad input (exit 2), read with the limits of every data file.
    let text = pounding_study::input::read_text_file(
        path,
        &format!("--{flag} file"),
        pounding_study::input::DATA_FILE_LIMIT,
    )
    .map_err(input)?;
    pounding_study::fit::pairs(&text).map_err(|e| input(format!("--{flag} {shown}: {e} ({what})")))
}

fn risk(a: &SeparationArgs) -> Result<Option<RiskOptions>, CliError> {
    let r = &a.risk;
    let Some(path) = &r.hazard else {
        return Ok(None);
    };
    let rows = pairs(
        path,
        "hazard",
        "intensity in m/s^2, then annual exceedance rate in 1/yr",
    )?;
    let hazard =
        HazardCurve::new(rows).map_err(|e| input(format!("--hazard {}: {e}", path.display())))?;
    let measure = match r.measure.as_str() {
        "pga" => MeasureOptions::Pga,
        _ => MeasureOptions::Sa {
            building: r.building.clone(),
            damping: r.im_damping,
        },
    };
    Ok(Some(RiskOptions {
        hazard,
        measure,
        levels: r.levels.clone(),
        target_rate: r.target_rate,
        design_life: r.design_life,
    }))
}

fn code(a: &SeparationArgs) -> Result<Option<CodeOptions>, CliError> {
    let c = &a.code;
    let Some(name) = c.code else {
        if c.design_spectrum.is_some() || c.spectrum.is_some() {
            return Err(input(
                "--design-spectrum and --spectrum are not allowed without --code: they are its elastic analysis's",
            ));
        }
        return Ok(None);
    };
    let need = |flag: &str, x: Option<f64>, what: &str| {
        x.ok_or_else(|| input(format!("--{flag} is required by --code {name}: {what}")))
    };
    let rule = match name {
        CodeName::Asce7_22 => CodeRule::Asce7_22 {
            cd: need("cd", c.cd, "the deflection amplification factor C_d")?,
            ie: c.ie,
        },
        CodeName::En1998_1 => {
            let q = need("q", c.q, "the behaviour factor q")?;
            CodeRule::En1998_1 {
                q,
                qd: c.qd.unwrap_or(q),
            }
        }
        CodeName::Is1893_2016 => CodeRule::Is1893_2016 {
            r: need("r", c.r, "the response reduction factor R")?,
        },
        CodeName::Gb50011_2010 => CodeRule::Gb50011_2010 {
            intensity: c.intensity.ok_or_else(|| {
                input("--intensity is required by --code gb50011-2010: 6, 7, 8 or 9")
            })?,
            system: c.system,
        },
    };
    let spectrum = match (&c.design_spectrum, c.spectrum.as_deref()) {
        (Some(path), _) => Some(DesignSpectrum::Table(pairs(
            path,
            "design-spectrum",
            "period in s, then Sa in m/s^2",
        )?)),
        (None, Some("asce7-22")) => Some(DesignSpectrum::Asce7 {
            sds: need("sds", c.sds, "S_DS (g) of the asce7-22 spectrum")?,
            sd1: need("sd1", c.sd1, "S_D1 (g) of the asce7-22 spectrum")?,
            tl: need("tl", c.tl, "T_L (s) of the asce7-22 spectrum")?,
            reduction: need("r", c.r, "R, the asce7-22 spectrum is divided by R / I_e")? / c.ie,
        }),
        (None, Some(_)) => Some(DesignSpectrum::En1998 {
            ag: need("ag", c.ag, "a_g (m/s^2) of the en1998-1 spectrum")?,
            ground: c.ground_type,
            kind: c.spectrum_type,
            q: need(
                "q",
                c.q,
                "the behaviour factor of the en1998-1 design spectrum",
            )?,
        }),
        (None, None) => None,
    };
    let spectrum = spectrum
        .map(DesignSpectrum::checked)
        .transpose()
        .map_err(|e| input(flagged_error(e)))?;
    Ok(Some(CodeOptions { rule, spectrum }))
}

/// A library error as the command line names its key.
fn flagged_error(e: pounding::Error) -> String {
    let key = match &e {
        pounding::Error::Parameter { name, .. } | pounding::Error::Choice { name, .. } => {
            Some(name.to_string())
        }
        _ => None,
    };
    flagged(key, e.to_string())
}
