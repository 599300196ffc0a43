//! Scenario files (TOML): parsed with serde, then validated once into the library's types. Every error is
//! one line that names the file, the line of the entry and the key.

use crate::args::{parse_alpha, parse_model, DampingArg, FormatArg, ModelArgs, ReadingArg};
use crate::args::{TensionArg, UnitsArg};
use crate::commands::{contact, key_message, load_record_from, Style};
use crate::CliError;
use clap::ValueEnum;
use pounding::analysis::{Building, Scenario};
use pounding::element::StoreyLaw;
use pounding::structure::ShearBuilding;
use serde::Deserialize;
use std::path::Path;
use toml::Spanned;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct File {
    ground_motion: Spanned<GroundMotion>,
    #[serde(default)]
    analysis: Option<Spanned<Analysis>>,
    #[serde(default)]
    building: Vec<Spanned<BuildingEntry>>,
    #[serde(default)]
    contact: Vec<Spanned<ContactEntry>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct GroundMotion {
    record: Option<String>,
    file: Option<String>,
    format: Option<String>,
    dt: Option<f64>,
    #[serde(default = "default_units")]
    units: String,
    #[serde(default = "one")]
    scale: f64,
}

fn default_units() -> String {
    "g".into()
}
fn one() -> f64 {
    1.0
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct Analysis {
    duration: Option<f64>,
    output_dt: Option<f64>,
    tolerance: Option<f64>,
    min_impact_velocity: Option<f64>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct BuildingEntry {
    name: String,
    masses: Vec<f64>,
    stiffnesses: Vec<f64>,
    heights: Vec<f64>,
    #[serde(default = "five_percent")]
    damping_ratio: f64,
    storey_model: Option<OneOrMany<String>>,
    yield_forces: Option<OneOrMany<f64>>,
    post_yield_ratio: Option<OneOrMany<f64>>,
    bouc_wen: Option<BoucWenEntry>,
}

/// One value for every storey, or a list with one per storey.
#[derive(Deserialize, Clone)]
#[serde(untagged)]
enum OneOrMany<T> {
    One(T),
    Many(Vec<T>),
}

impl<T: Clone> OneOrMany<T> {
    /// One value per storey; `Err(len)` for a list of the wrong length.
    fn per_storey(&self, storeys: usize) -> Result<Vec<T>, usize> {
        match self {
            OneOrMany::One(x) => Ok(vec![x.clone(); storeys]),
            OneOrMany::Many(v) if v.len() == storeys => Ok(v.clone()),
            OneOrMany::Many(v) => Err(v.len()),
        }
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct BoucWenEntry {
    #[serde(default = "one")]
    n: f64,
    #[serde(default = "half")]
    beta: f64,
    #[serde(default = "half")]
    gamma: f64,
}

fn half() -> f64 {
    0.5
}

fn five_percent() -> f64 {
    0.05
}

/// Alpha is a number or a word.
#[derive(Deserialize)]
#[serde(untagged)]
enum Alpha {
    Number(f64),
    Word(String),
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ContactEntry {
    between: Vec<String>,
    gap: f64,
    #[serde(default = "papi")]
    model: String,
    #[serde(default = "concrete_e")]
    e: f64,
    stiffness: f64,
    stiffness_unit: Option<String>,
    exponent: Option<f64>,
    damping: Option<String>,
    alpha: Option<Alpha>,
    reading: Option<String>,
    tension: Option<String>,
    floors: Option<Vec<Vec<usize>>>,
    max_penetration: Option<f64>,
    yield_ratio: Option<f64>,
}

fn papi() -> String {
    "papi".into()
}
fn concrete_e() -> f64 {
    0.65
}

/// A loaded scenario, with what the report needs to say where it came from.
pub struct Loaded {
    pub scenario: Scenario,
    /// The scenario file's text, as read.
    pub text: String,
    /// The ground-motion source as given (built-in name or path).
    pub record_source: String,
    pub scale: f64,
}

/// Where in the file: `path:line`.
struct At<'a> {
    path: &'a Path,
    text: &'a str,
}

impl At<'_> {
    fn line(&self, span: std::ops::Range<usize>) -> usize {
        self.text[..span.start.min(self.text.len())]
            .bytes()
            .filter(|b| *b == b'\n')
            .count()
            + 1
    }
    /// The line of `key` (or its plural, the list it belongs to) inside the entry at `span`, else the
    /// entry's own line.
    fn key_span(&self, span: std::ops::Range<usize>, key: &str) -> std::ops::Range<usize> {
        // A sub-key (`bouc_wen.beta`) is on the line of its table.
        let key = key.split('.').next().unwrap_or(key);
        let body = &self.text[span.start.min(self.text.len())..span.end.min(self.text.len())];
        let mut offset = span.start;
        for line in body.split_inclusive('\n') {
            let t = line.trim_start();
            let k = t.split(['=', ' ']).next().unwrap_or("");
            if k == key || k == format!("{key}s") || k == format!("{key}es") {
                return offset..offset;
            }
            offset += line.len();
        }
        span
    }
    fn err(&self, span: std::ops::Range<usize>, msg: impl std::fmt::Display) -> CliError {
        CliError::Input(format!(
            "{}:{}: {msg}",
            self.path.display(),
            self.line(span)
        ))
    }
    /// A library error about the entry at `span`, in the file's words (`key = value`).
    fn lib(&self, span: std::ops::Range<usize>, e: pounding::Error) -> CliError {
        self.lib_in(span, "", e)
    }
    /// The same, naming the entry (`what: ...`).
    fn lib_in(&self, span: std::ops::Range<usize>, what: &str, e: pounding::Error) -> CliError {
        let key = match &e {
            pounding::Error::Parameter { name, .. } | pounding::Error::Length { name, .. } => {
                Some(*name)
            }
            pounding::Error::Choice { name, .. } => Some(*name),
            _ => None,
        };
        let span = key.map_or(span.clone(), |k| self.key_span(span, k));
        let msg = match e {
            pounding::Error::Parameter {
                name,
                value,
                allowed,
            } => key_message(name, value, allowed),
            other => other.to_string(),
        };
        if what.is_empty() {
            self.err(span, msg)
        } else {
            self.err(span, format!("{what}: {msg}"))
        }
    }
}

fn word<T: ValueEnum>(
    at: &At,
    span: std::ops::Range<usize>,
    key: &str,
    v: &str,
) -> Result<T, CliError> {
    T::from_str(v, false).map_err(|_| {
        let allowed: Vec<String> = T::value_variants()
            .iter()
            .filter_map(|x| x.to_possible_value().map(|p| p.get_name().to_string()))
            .collect();
        at.err(
            span,
            format!(
                "{key} = {v:?} is not allowed: one of {}",
                allowed.join(", ")
            ),
        )
    })
}

/// The storey laws of a building entry: `storey_model` (default linear), `yield_forces`, `post_yield_ratio`
/// (default 0, elastic–perfectly-plastic) and `bouc_wen` (default n = 1, beta = gamma = 0.5).
fn storey_laws(
    at: &At,
    span: std::ops::Range<usize>,
    what: &str,
    b: &BuildingEntry,
) -> Result<Vec<StoreyLaw>, CliError> {
    let storeys = b.masses.len();
    let err =
        |key: &str, msg: String| at.err(at.key_span(span.clone(), key), format!("{what}: {msg}"));
    let list = |key: &str, len: usize| {
        err(
            key,
            format!("{key} has {len} values, but there are {storeys} storeys: give one per storey, or one for all"),
        )
    };
    let models = match &b.storey_model {
        None => vec!["linear".to_string(); storeys],
        Some(m) => m.per_storey(storeys).map_err(|n| list("storey_model", n))?,
    };
    for m in &models {
        if !["linear", "bilinear", "bouc-wen"].contains(&m.as_str()) {
            return Err(err(
                "storey_model",
                format!("storey_model = {m:?} is not allowed: one of linear, bilinear, bouc-wen"),
            ));
        }
    }
    let inelastic = models.iter().any(|m| m != "linear");
    let bouc_wen = models.iter().any(|m| m == "bouc-wen");
    for (key, given) in [
        ("yield_forces", b.yield_forces.is_some()),
        ("post_yield_ratio", b.post_yield_ratio.is_some()),
    ] {
        if given && !inelastic {
            return Err(err(
                key,
                format!("{key} applies to bilinear and bouc-wen storeys, and every storey is linear (set storey_model)"),
            ));
        }
    }
    if b.bouc_wen.is_some() && !bouc_wen {
        return Err(err(
            "bouc_wen",
            "bouc_wen applies to bouc-wen storeys, and there are none (set storey_model = \"bouc-wen\")".into(),
        ));
    }
    if !inelastic {
        return Ok(vec![StoreyLaw::Linear; storeys]);
    }
    let fy = match &b.yield_forces {
        None => {
            return Err(err(
                "storey_model",
                "yield_forces (N) is required for bilinear and bouc-wen storeys".into(),
            ))
        }
        Some(f) => f.per_storey(storeys).map_err(|n| list("yield_forces", n))?,
    };
    let ratio = match &b.post_yield_ratio {
        None => vec![0.0; storeys],
        Some(r) => r
            .per_storey(storeys)
            .map_err(|n| list("post_yield_ratio", n))?,
    };
    let bw = b
        .bouc_wen
        .as_ref()
        .map_or((1.0, 0.5, 0.5), |p| (p.n, p.beta, p.gamma));
    models
        .iter()
        .enumerate()
        .map(|(j, m)| {
            match m.as_str() {
                "bilinear" => StoreyLaw::bilinear(fy[j], ratio[j]),
                "bouc-wen" => StoreyLaw::bouc_wen(fy[j], ratio[j], bw.0, bw.1, bw.2),
                _ => Ok(StoreyLaw::Linear),
            }
            .map_err(|e| at.lib_in(span.clone(), &format!("{what}, storey {}", j + 1), e))
        })
        .collect()
}

/// The exponent `n` of a stiffness unit `N/m` (1) or `N/m^n`.
fn stiffness_exponent(unit: &str) -> Option<f64> {
    let u: String = unit.chars().filter(|c| !c.is_whitespace()).collect();
    match u.strip_prefix("N/m") {
        Some("") => Some(1.0),
        Some(rest) => rest
            .strip_prefix('^')
            .and_then(|x| x.trim_matches(['(', ')']).parse::<f64>().ok())
            .filter(|n| n.is_finite() && *n > 0.0),
        None => None,
    }
}

/// Reads and validates the scenario file at `path`.
pub fn load(path: &Path) -> Result<Loaded, CliError> {
    let text = crate::commands::read_text_file(
        path,
        "scenario file",
        crate::commands::SCENARIO_FILE_LIMIT,
    )
    .map_err(CliError::Input)?;
    let at = At { path, text: &text };
    let file: File = toml::from_str(&text).map_err(|e| {
        let msg = e.message().trim().replace('\n', " ");
        match e.span() {
            Some(span) => at.err(span, msg),
            None => CliError::Input(format!("{}: {msg}", path.display())),
        }
    })?;

    // Ground motion; a file is relative to the scenario's folder.
    let gm_span = file.ground_motion.span();
    let gm = file.ground_motion.into_inner();
    let source = match (&gm.record, &gm.file) {
        (Some(r), None) => r.clone(),
        (None, Some(f)) => {
            let p = Path::new(f);
            if p.is_relative() {
                path.parent()
                    .unwrap_or(Path::new("."))
                    .join(p)
                    .to_string_lossy()
                    .into_owned()
            } else {
                f.clone()
            }
        }
        _ => return Err(at.err(
            gm_span,
            "[ground_motion] needs exactly one of record = \"el-centro-1940\" or file = \"path\"",
        )),
    };
    if gm.record.is_some() && (gm.format.is_some() || gm.dt.is_some()) {
        return Err(at.err(
            gm_span,
            "format and dt apply to a record file (file = ...), not to a built-in record",
        ));
    }
    let format: Option<FormatArg> = gm
        .format
        .as_deref()
        .map(|f| word(&at, gm_span.clone(), "format", f))
        .transpose()?;
    let units: UnitsArg = word(&at, gm_span.clone(), "units", &gm.units)?;
    let record = load_record_from(&source, format, gm.dt, units, gm.scale, Style::Key)
        .map_err(|e| match e {
            CliError::Input(m) => {
                if gm.record.is_some() && pounding::ground_motion::Record::builtin(&source).is_none()
                {
                    at.err(
                        gm_span.clone(),
                        format!("record = {source:?} is not a built-in record: el-centro-1940 (for a file, use file = \"path\")"),
                    )
                } else {
                    at.err(gm_span.clone(), format!("[ground_motion] {m}"))
                }
            }
            other => other,
        })?;

    // Buildings.
    if file.building.is_empty() {
        return Err(CliError::Input(format!(
            "{}: no [[building]] entries: a scenario needs at least one building",
            path.display()
        )));
    }
    // The size of the row, before any building's modes are computed.
    let floors: Vec<usize> = file
        .building
        .iter()
        .map(|b| b.get_ref().masses.len())
        .collect();
    pounding::limits::check_row(&floors).map_err(|e| at.lib(file.building[0].span(), e))?;
    let mut buildings = Vec::new();
    let mut spans = Vec::new();
    for b in file.building {
        let span = b.span();
        let b = b.into_inner();
        if b.name.is_empty()
            || b.name.len() > 64
            || b.name.contains([',', '"', '|'])
            || b.name.chars().any(char::is_control)
        {
            return Err(at.err(
                span,
                format!(
                    "name = {:?} is not allowed: 1 to 64 bytes, without commas, quotes, | or control characters",
                    b.name
                ),
            ));
        }
        let what = format!("building {:?}", b.name);
        let laws = storey_laws(&at, span.clone(), &what, &b)?;
        let structure = ShearBuilding::new(b.masses, b.stiffnesses, b.heights, b.damping_ratio)
            .and_then(|s| s.with_storey_laws(laws))
            .map_err(|e| at.lib_in(span.clone(), &what, e))?;
        spans.push(span);
        buildings.push(Building {
            name: b.name,
            structure,
        });
    }
    let mut scenario = Scenario::new(buildings, record).map_err(|e| {
        let span = spans.last().cloned().unwrap_or(0..0);
        at.lib(span, e)
    })?;

    // Settings.
    if let Some(a) = file.analysis {
        let span = a.span();
        let a = a.into_inner();
        let lib = |e| at.lib(span.clone(), e);
        if let Some(d) = a.duration {
            scenario = scenario.with_duration(d).map_err(lib)?;
        }
        if let Some(d) = a.output_dt {
            scenario = scenario.with_output_dt(d).map_err(lib)?;
        }
        if let Some(t) = a.tolerance {
            scenario = scenario.with_tolerance(t).map_err(lib)?;
        }
        if let Some(v) = a.min_impact_velocity {
            scenario = scenario.with_min_impact_velocity(v).map_err(lib)?;
        }
    }
    if scenario.output_samples() > pounding::limits::MAX_OUTPUT_SAMPLES {
        return Err(CliError::Input(format!(
            "{}: duration / output_dt = {:e} output samples; allowed: at most 1e7 (raise output_dt)",
            path.display(),
            scenario.duration() / scenario.output_dt()
        )));
    }

    // Contacts.
    for c in file.contact {
        let span = c.span();
        let c = c.into_inner();
        let lib = |e| at.lib(span.clone(), e);
        let e_at = |m: String| at.err(span.clone(), m);
        let [a, b] = <[String; 2]>::try_from(c.between.clone()).map_err(|_| {
            e_at(format!(
                "between = {:?} is not allowed: two building names, [\"left\", \"right\"]",
                c.between
            ))
        })?;
        let model =
            parse_model(&c.model).map_err(|m| e_at(format!("model = {:?}: {m}", c.model)))?;
        let alpha = match &c.alpha {
            None => None,
            Some(Alpha::Number(x)) => Some(pounding::contact::AlphaRule::Given(*x)),
            Some(Alpha::Word(w)) => {
                Some(parse_alpha(w).map_err(|m| e_at(format!("alpha = {w:?}: {m}")))?)
            }
        };
        let args = ModelArgs {
            model,
            e: c.e,
            n: c.exponent,
            damping: c
                .damping
                .as_deref()
                .map(|d| word::<DampingArg>(&at, span.clone(), "damping", d))
                .transpose()?
                .unwrap_or(DampingArg::Formula),
            alpha,
            reading: c
                .reading
                .as_deref()
                .map(|r| word::<ReadingArg>(&at, span.clone(), "reading", r))
                .transpose()?
                .unwrap_or(ReadingArg::EnergySplit),
            tension: c
                .tension
                .as_deref()
                .map(|t| word::<TensionArg>(&at, span.clone(), "tension", t))
                .transpose()?,
            max_penetration: c.max_penetration,
            yield_ratio: c.yield_ratio.unwrap_or(0.1),
        };
        // The stiffness states its unit, so that changing the model cannot silently change what it means.
        let n = c.exponent.unwrap_or(model.info().default_n);
        let unit_for = |n: f64| {
            if n == 1.0 {
                "N/m".to_string()
            } else {
                format!("N/m^{}", crate::output::fmt_num(n))
            }
        };
        match c.stiffness_unit.as_deref() {
            None => {
                return Err(at.err(
                    at.key_span(span.clone(), "stiffness"),
                    format!(
                        "contact {a:?}-{b:?}: stiffness_unit is required with stiffness: \"{}\" for {} (exponent {}), so that the stiffness keeps its meaning if the model changes",
                        unit_for(n),
                        model.name(),
                        crate::output::fmt_num(n)
                    ),
                ))
            }
            Some(u) => {
                let given = stiffness_exponent(u).ok_or_else(|| {
                    at.err(
                        at.key_span(span.clone(), "stiffness_unit"),
                        format!("contact {a:?}-{b:?}: stiffness_unit = {u:?} is not allowed: \"N/m\" or \"N/m^n\" (for example \"N/m^1.5\")"),
                    )
                })?;
                if (given - n).abs() > 1e-12 {
                    return Err(at.err(
                        at.key_span(span.clone(), "stiffness_unit"),
                        format!(
                            "contact {a:?}-{b:?}: stiffness_unit = {u:?} does not match the exponent {} of {}: its stiffness is in {} (convert it, or set exponent = {})",
                            crate::output::fmt_num(n),
                            model.name(),
                            unit_for(n),
                            crate::output::fmt_num(given)
                        ),
                    ));
                }
            }
        }
        let spec = contact(&args, c.stiffness, Style::Key).map_err(|e| match e {
            CliError::Input(m) => {
                // Messages start with the key (`e = 1.5 is not allowed ...`): point at its line.
                let key = m.split([' ', '=']).next().unwrap_or("");
                at.err(
                    at.key_span(span.clone(), key),
                    format!("contact {a:?}-{b:?}: {m}"),
                )
            }
            other => other,
        })?;
        let floors = match c.floors {
            None => None,
            Some(f) => Some(
                f.iter()
                    .map(|p| match p.as_slice() {
                        [i, j] => Ok((*i, *j)),
                        _ => Err(e_at(format!(
                            "floors entry {p:?} is not allowed: pairs [floor of left, floor of right], from 1"
                        ))),
                    })
                    .collect::<Result<Vec<_>, _>>()?,
            ),
        };
        scenario = scenario
            .with_link(&a, &b, c.gap, &spec, floors)
            .map_err(lib)?;
    }
    Ok(Loaded {
        text,
        record_source: source,
        scale: gm.scale,
        scenario,
    })
}
