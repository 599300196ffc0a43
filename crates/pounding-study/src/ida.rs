//! Incremental dynamic analysis and fragility: a base scenario under each record of a suite, scaled to each of
//! a list of intensity levels (Sa(T1, zeta) of a named building, or PGA), run as one resumable sweep; the
//! engineering demand parameters of each run; and, for each limit state, lognormal fragility functions fitted
//! by maximum likelihood from the stripes and from each record's first exceedance.
//!
//! ```toml
//! scenario = "../three-vs-eight-inelastic.toml"
//! records = ["el-centro-1940", "suite/"]           # built-ins, files, folders, globs
//! limit_states = ["drift_ratio > 0.015", "pounding", "peak_force > 2e7"]
//!
//! [intensity]
//! measure = "sa"          # "sa": pseudo-spectral acceleration at the building's T1 (m/s^2); "pga" (m/s^2)
//! building = "3-storey"   # whose first period (for "sa")
//! damping = 0.05          # of the spectrum (for "sa")
//! levels = [0.5, 1.0, 2.0, 3.0, 4.0]   # m/s^2
//! ```

use crate::input::{read_record, read_text_file, ScenarioFile, SCENARIO_FILE_LIMIT};
use crate::study::{record_sources, set_record};
use crate::summary::{BuildingSummary, RunSummary, SiteSummary};
use crate::InputError;
use pounding::fragility::{fit_ida, fit_stripes, Fragility};
use serde::Serialize;
use serde_json::{json, Value};
use std::path::{Path, PathBuf};

/// An engineering demand parameter of a run, read from its summary.
#[derive(Clone, Debug, PartialEq)]
pub enum Edp {
    /// Largest storey drift ratio (drift / storey height) of a building, or of all.
    DriftRatio(Option<String>),
    /// Largest absolute floor acceleration, m/s^2, of a building, or of all.
    Acceleration(Option<String>),
    /// Largest floor displacement, m, of a building, or of all.
    Displacement(Option<String>),
    /// Largest storey shear (restoring force, an isolator's included), N, of a building, or of all.
    StoreyShear(Option<String>),
    /// Largest ductility (peak drift over yield drift) of an inelastic storey above any isolator, of a
    /// building or of all (0 where no such storey can yield).
    Ductility(Option<String>),
    /// Largest contact force of any contact, N.
    PeakForce,
    /// Largest penetration of any contact, m.
    Penetration,
    /// Whether any impact occurred (1) or not (0).
    Pounding,
}

impl Edp {
    /// The EDP's value in a run's summary. Forces, penetrations and impacts count every contact site,
    /// contacts between neighbours and walls alike.
    pub fn value(&self, s: &RunSummary) -> f64 {
        let of = |name: &Option<String>, key: fn(&BuildingSummary) -> &[f64]| {
            s.buildings
                .iter()
                .filter(|b| name.as_ref().is_none_or(|n| b.name == *n))
                .flat_map(key)
                .fold(0.0f64, |a, &x| a.max(x))
        };
        let sites = |key: fn(&SiteSummary) -> f64| s.sites.iter().map(key).fold(0.0f64, f64::max);
        match self {
            Edp::DriftRatio(b) => of(b, BuildingSummary::structural_drift_ratios),
            Edp::StoreyShear(b) => of(b, |b| &b.peak_storey_shear),
            Edp::Ductility(b) => of(b, BuildingSummary::structural_ductility),
            Edp::Acceleration(b) => of(b, |b| &b.peak_absolute_acceleration),
            Edp::Displacement(b) => of(b, |b| &b.peak_displacement),
            Edp::PeakForce => sites(|c| c.peak_force),
            Edp::Penetration => sites(|c| c.max_penetration),
            Edp::Pounding => f64::from(u8::from(s.impacts() > 0)),
        }
    }
}

/// A limit state: an EDP above a threshold (or, for `pounding`, any impact).
#[derive(Clone, Debug, PartialEq)]
pub struct LimitState {
    /// As written in the study file.
    pub name: String,
    /// The EDP.
    pub edp: Edp,
    /// Exceeded when the EDP is above this.
    pub threshold: f64,
}

const EDPS: &str = "drift_ratio, acceleration, displacement, storey_shear, ductility (each optionally .BUILDING), peak_force, penetration, pounding";

fn parse_limit(text: &str, buildings: &[String]) -> Result<LimitState, String> {
    let (lhs, threshold) = match text.split_once('>') {
        Some((l, r)) => {
            let t: f64 = r
                .trim()
                .parse()
                .map_err(|_| format!("limit state {text:?}: {:?} is not a number", r.trim()))?;
            if !t.is_finite() {
                return Err(format!(
                    "limit state {text:?}: the threshold must be finite"
                ));
            }
            (l.trim(), Some(t))
        }
        None => (text.trim(), None),
    };
    let (name, building) = match lhs.split_once('.') {
        Some((n, b)) => (n, Some(b.to_string())),
        None => (lhs, None),
    };
    if let Some(b) = &building {
        if !buildings.contains(b) {
            return Err(format!(
                "limit state {text:?} names no building: {b:?}; the scenario's are {}",
                buildings
                    .iter()
                    .map(|b| format!("{b:?}"))
                    .collect::<Vec<_>>()
                    .join(", ")
            ));
        }
    }
    let edp = match (name, building) {
        ("drift_ratio", b) => Edp::DriftRatio(b),
        ("acceleration", b) => Edp::Acceleration(b),
        ("displacement", b) => Edp::Displacement(b),
        ("storey_shear", b) => Edp::StoreyShear(b),
        ("ductility", b) => Edp::Ductility(b),
        ("peak_force", None) => Edp::PeakForce,
        ("penetration", None) => Edp::Penetration,
        ("pounding", None) => Edp::Pounding,
        _ => {
            return Err(format!(
                "limit state {text:?}: unknown quantity {lhs:?}; allowed: {EDPS}"
            ))
        }
    };
    let threshold = match (&edp, threshold) {
        (Edp::Pounding, None) => 0.5,
        (Edp::Pounding, Some(_)) => {
            return Err(format!(
                "limit state {text:?}: pounding takes no threshold (write \"pounding\")"
            ))
        }
        (_, Some(t)) => t,
        (_, None) => {
            return Err(format!(
                "limit state {text:?} needs a threshold: \"{lhs} > value\" (SI units)"
            ))
        }
    };
    Ok(LimitState {
        name: text.trim().to_string(),
        edp,
        threshold,
    })
}

/// The intensity measure.
#[derive(Clone, Debug, PartialEq)]
pub enum Measure {
    /// Pseudo-spectral acceleration at period `period` (s) and damping ratio `damping`, m/s^2.
    Sa {
        /// The building it is named after.
        building: String,
        /// Its first period, s.
        period: f64,
        /// Damping ratio of the spectrum.
        damping: f64,
    },
    /// Peak ground acceleration, m/s^2.
    Pga,
}

/// An IDA study, read and checked.
pub struct Ida {
    /// The study file.
    pub path: PathBuf,
    /// The base scenario as JSON.
    pub base: Value,
    /// Record sources.
    pub records: Vec<String>,
    /// The intensity measure.
    pub measure: Measure,
    /// Intensity levels, m/s^2, ascending.
    pub levels: Vec<f64>,
    /// The limit states.
    pub limit_states: Vec<LimitState>,
    /// The base scenario's buildings, left to right.
    pub buildings: Vec<String>,
    /// Those with storeys that can yield.
    pub inelastic: Vec<String>,
}

/// The buildings of `s` with storeys that can yield (above any isolator: its ductility is the isolator's).
fn inelastic(s: &pounding::analysis::Scenario) -> Vec<String> {
    s.buildings()
        .iter()
        .filter(|b| {
            let skip = usize::from(b.structure.isolator().is_some());
            b.structure.storey_laws()[skip..]
                .iter()
                .any(|l| l.is_inelastic())
        })
        .map(|b| b.name.clone())
        .collect()
}

/// A base scenario of one ground component (or one along an angle): an IDA scales each record of its suite
/// alone.
fn one_component(path: &Path, base: &crate::input::Loaded) -> Result<(), InputError> {
    if base.doc.support.iter().any(|s| s.own().is_some()) {
        return Err(err(
            path,
            "the base scenario has a [[support]] with a record of its own: an IDA scales each record of its suite, and would leave that one as it is; give the support a delay (wave passage) instead",
        ));
    }
    if base.doc.ground_motion.y.is_some() {
        return Err(err(
            path,
            "the base scenario has [ground_motion.y]: an IDA scales each record of its suite alone, which would pair every one with that same record along y; remove it (a record along an angle, ground_motion.angle, is scaled as one)",
        ));
    }
    Ok(())
}

fn err(path: &Path, msg: impl std::fmt::Display) -> InputError {
    InputError::new(format!("{}: {msg}", path.display()))
}

impl Ida {
    /// Reads and checks the study at `path`: one line naming the file for bad input.
    pub fn read(path: &Path) -> Result<Ida, InputError> {
        let text =
            read_text_file(path, "study file", SCENARIO_FILE_LIMIT).map_err(InputError::new)?;
        let top = crate::input::study_json(path, &text)?;
        for k in top.as_object().into_iter().flat_map(|o| o.keys()) {
            if !["scenario", "records", "limit_states", "intensity"].contains(&k.as_str()) {
                return Err(err(
                    path,
                    format!(
                        "unknown key {k:?}; allowed: scenario, records, limit_states, [intensity]"
                    ),
                ));
            }
        }
        let dir = path.parent().unwrap_or(Path::new(".")).to_path_buf();
        let base_path = match top.get("scenario") {
            Some(Value::String(s)) => dir.join(s),
            _ => return Err(err(path, "scenario = \"base.toml\" is required: the base scenario, relative to the study file")),
        };
        let base_file = ScenarioFile::read(&base_path)?;
        let base_loaded = base_file.load()?;
        one_component(path, &base_loaded)?;
        let names: Vec<String> = base_loaded
            .scenario
            .buildings()
            .iter()
            .map(|b| b.name.clone())
            .collect();
        let mut records = Vec::new();
        match top.get("records") {
            Some(Value::Array(a)) if !a.is_empty() => {
                for v in a {
                    records.extend(record_sources(&dir, v).map_err(|m| err(path, format!("records: {m}")))?);
                }
            }
            _ => return Err(err(path, "records = [...] is required: built-in names, files, folders or globs, at least one")),
        }
        let limit_states = match top.get("limit_states") {
            Some(Value::Array(a)) if !a.is_empty() => a
                .iter()
                .map(|v| match v {
                    Value::String(s) => parse_limit(s, &names),
                    other => Err(format!("limit state {other} is not a string like \"drift_ratio > 0.015\"")),
                })
                .collect::<Result<Vec<_>, _>>()
                .map_err(|m| err(path, m))?,
            _ => {
                return Err(err(
                    path,
                    format!("limit_states = [...] is required, at least one (for example \"drift_ratio > 0.015\", \"pounding\"); quantities: {EDPS}"),
                ))
            }
        };
        let Some(Value::Object(int)) = top.get("intensity") else {
            return Err(err(
                path,
                "[intensity] is required: measure, levels (and building, damping for sa)",
            ));
        };
        for k in int.keys() {
            if !["measure", "building", "damping", "levels"].contains(&k.as_str()) {
                return Err(err(path, format!("[intensity] unknown key {k:?}; allowed: measure, building, damping, levels")));
            }
        }
        let measure_name = match int.get("measure") {
            None => "sa",
            Some(Value::String(m)) => m.as_str(),
            Some(other) => {
                return Err(err(
                    path,
                    format!("[intensity] measure = {other} is not allowed: one of \"sa\", \"pga\""),
                ))
            }
        };
        let measure = match measure_name {
            "pga" => Measure::Pga,
            "sa" => {
                let building = match int.get("building") {
                    Some(Value::String(b)) => b.clone(),
                    _ => return Err(err(path, "[intensity] building = \"name\" is required for measure = \"sa\" (whose first period)")),
                };
                let Some(b) = base_loaded
                    .scenario
                    .buildings()
                    .iter()
                    .find(|x| x.name == building)
                else {
                    return Err(err(path, format!(
                        "[intensity] building = {building:?} names no building; the scenario's are {}",
                        names.iter().map(|b| format!("{b:?}")).collect::<Vec<_>>().join(", ")
                    )));
                };
                let damping = match int.get("damping") {
                    None => 0.05,
                    Some(v) => v
                        .as_f64()
                        .ok_or_else(|| err(path, "[intensity] damping is not a number"))?,
                };
                if !(0.0..1.0).contains(&damping) {
                    return Err(err(
                        path,
                        format!("[intensity] damping = {damping} is not allowed: 0 <= damping < 1"),
                    ));
                }
                // A building in plan: its fundamental along x, the record's direction (an IDA's suite is
                // along x, or along an angle from it).
                let period = match b.structure.plan() {
                    Some(p) => 2.0 * std::f64::consts::PI / p.fundamental_x(),
                    None => b.structure.modes().periods()[0],
                };
                Measure::Sa {
                    period,
                    building,
                    damping,
                }
            }
            other => {
                return Err(err(
                    path,
                    format!("[intensity] measure = {other:?} is not allowed: one of sa, pga"),
                ))
            }
        };
        let levels: Vec<f64> = match int.get("levels") {
            Some(Value::Array(a)) if !a.is_empty() => a
                .iter()
                .map(|v| v.as_f64().filter(|x| x.is_finite() && *x > 0.0))
                .collect::<Option<Vec<_>>>()
                .ok_or_else(|| err(path, "[intensity] levels must be numbers > 0 (m/s^2)"))?,
            _ => {
                return Err(err(
                    path,
                    "[intensity] levels = [...] is required: at least one intensity, m/s^2",
                ))
            }
        };
        let mut sorted = levels.clone();
        sorted.sort_by(f64::total_cmp);
        sorted.dedup();
        Ok(Ida {
            path: path.to_path_buf(),
            base: base_file.value,
            records,
            measure,
            levels: sorted,
            limit_states,
            buildings: names,
            inelastic: inelastic(&base_loaded.scenario),
        })
    }

    /// The intensity of each record at scale 1 (m/s^2): one line on error.
    pub fn intensities(&self) -> Result<Vec<f64>, InputError> {
        self.records
            .iter()
            .map(|r| {
                let mut v = self.base.clone();
                set_record(&mut v, r);
                let mut doc: pounding::scenario::GroundMotionDoc =
                    serde_json::from_value(v["ground_motion"].clone())
                        .map_err(|e| err(&self.path, format!("ground_motion: {e}")))?;
                doc.scale = 1.0;
                let spec = doc
                    .spec()
                    .map_err(|e| err(&self.path, format!("record {r}: {}", e.message)))?;
                let rec = read_record(&spec).map_err(|e| {
                    err(
                        &self.path,
                        format!("record {r}: {}", crate::input::record_message(&spec, e)),
                    )
                })?;
                let im = match &self.measure {
                    Measure::Pga => rec.pga(),
                    Measure::Sa {
                        period, damping, ..
                    } => {
                        pounding::ground_motion::spectrum::spectrum(&rec, *damping, &[*period])
                            .map_err(|e| err(&self.path, e))?
                            .psa[0]
                    }
                };
                if im > 0.0 && im.is_finite() {
                    Ok(im)
                } else {
                    Err(err(
                        &self.path,
                        format!("record {r} has intensity {im}: it cannot be scaled"),
                    ))
                }
            })
            .collect()
    }

    /// The run of record `i` at level `j` (the records' intensities at scale 1 are `ims`): its scale and
    /// scenario.
    pub fn scenario(&self, i: usize, j: usize, ims: &[f64]) -> (f64, Value) {
        let mut v = self.base.clone();
        set_record(&mut v, &self.records[i]);
        let scale = self.levels[j] / ims[i];
        v["ground_motion"]["scale"] = json!(scale);
        (scale, v)
    }

    /// The unit of the intensity measure.
    pub fn measure_name(&self) -> String {
        match &self.measure {
            Measure::Pga => "pga (m/s^2)".into(),
            Measure::Sa {
                building,
                period,
                damping,
            } => format!("sa (m/s^2) at T1 = {period:.4} s of {building:?}, damping {damping}"),
        }
    }

    /// Each limit state's EDP of a run's summary, in [`Ida::limit_states`] order.
    pub fn edps(&self, summary: &RunSummary) -> Vec<f64> {
        self.limit_states
            .iter()
            .map(|ls| ls.edp.value(summary))
            .collect()
    }

    /// Fits every limit state from the runs' EDPs ([`Ida::edps`]; `None` for a failed run), laid out record
    /// by record, level by level.
    pub fn fit(&self, edps: &[Option<Vec<f64>>]) -> Vec<Fit> {
        let nl = self.levels.len();
        self.limit_states
            .iter()
            .enumerate()
            .map(|(k, ls)| {
                let exceeded =
                    |i: usize, j: usize| edps[i * nl + j].as_ref().map(|e| e[k] > ls.threshold);
                let counts: Vec<(usize, usize)> = (0..nl)
                    .map(|j| {
                        let runs: Vec<bool> = (0..self.records.len())
                            .filter_map(|i| exceeded(i, j))
                            .collect();
                        (runs.len(), runs.iter().filter(|x| **x).count())
                    })
                    .collect();
                let n: Vec<usize> = counts.iter().map(|c| c.0).collect();
                let z: Vec<usize> = counts.iter().map(|c| c.1).collect();
                let stripes = fit_stripes(&self.levels, &n, &z).map_err(|e| e.to_string());
                let first: Vec<Option<f64>> = (0..self.records.len())
                    .map(|i| {
                        (0..nl)
                            .find(|&j| exceeded(i, j) == Some(true))
                            .map(|j| self.levels[j])
                    })
                    .collect();
                let ida = fit_ida(&first, self.levels[nl - 1]).map_err(|e| e.to_string());
                Fit {
                    limit_state: ls.name.clone(),
                    stripes,
                    ida,
                    exceedances: counts,
                }
            })
            .collect()
    }
}

/// The fragility fits of one limit state.
pub struct Fit {
    /// The limit state, as written.
    pub limit_state: String,
    /// From the stripes (binomial likelihood), or why not.
    pub stripes: Result<Fragility, String>,
    /// From each record's first exceedance, or why not.
    pub ida: Result<Fragility, String>,
    /// `(runs, exceeding)` at each level.
    pub exceedances: Vec<(usize, usize)>,
}

/// The EDP columns of runs.csv for buildings `names` (those in `inelastic` with their ductility): column name
/// (with its unit) and how to read it.
pub fn edp_columns(names: &[String], inelastic: &[String]) -> Vec<(String, Edp)> {
    let mut cols = Vec::new();
    for n in names {
        let b = Some(n.clone());
        cols.push((format!("{n}_peak_drift_ratio"), Edp::DriftRatio(b.clone())));
        cols.push((
            format!("{n}_peak_acceleration_m_per_s2"),
            Edp::Acceleration(b.clone()),
        ));
        cols.push((
            format!("{n}_peak_displacement_m"),
            Edp::Displacement(b.clone()),
        ));
        cols.push((
            format!("{n}_peak_storey_shear_N"),
            Edp::StoreyShear(b.clone()),
        ));
        if inelastic.contains(n) {
            cols.push((format!("{n}_peak_ductility"), Edp::Ductility(b)));
        }
    }
    cols.push(("peak_force_N".into(), Edp::PeakForce));
    cols.push(("max_penetration_m".into(), Edp::Penetration));
    cols.push(("pounding".into(), Edp::Pounding));
    cols
}

/// One fit of a limit state, as the JSON result gives it.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(untagged)]
pub enum FitJson {
    /// The fitted curve: median (m/s^2 of the measure) and logarithmic standard deviation.
    Fitted {
        /// Median, m/s^2.
        median: f64,
        /// Dispersion (dimensionless).
        beta: f64,
    },
    /// Why there is none.
    Failed {
        /// The reason.
        error: String,
    },
}

impl FitJson {
    fn of(r: &Result<Fragility, String>) -> Self {
        match r {
            Ok(f) => FitJson::Fitted {
                median: f.median,
                beta: f.beta,
            },
            Err(m) => FitJson::Failed { error: m.clone() },
        }
    }
}

/// The fits of one limit state, as the JSON result gives them.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct FragilityJson {
    /// The limit state, as written.
    pub limit_state: String,
    /// From the stripes.
    pub stripes: FitJson,
    /// From each record's first exceedance.
    pub ida: FitJson,
    /// `[exceeding, runs]` at each level.
    pub exceedances: Vec<[usize; 2]>,
}

/// The fragility fits as JSON rows.
pub fn fragility_json(fits: &[Fit]) -> Vec<FragilityJson> {
    fits.iter()
        .map(|f| FragilityJson {
            limit_state: f.limit_state.clone(),
            stripes: FitJson::of(&f.stripes),
            ida: FitJson::of(&f.ida),
            exceedances: f.exceedances.iter().map(|&(n, z)| [z, n]).collect(),
        })
        .collect()
}

/// A record of the suite and its intensity at scale 1.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct RecordIntensity {
    /// The record's source.
    pub record: String,
    /// Its intensity measure at scale 1, m/s^2.
    pub intensity: f64,
}

/// What `pounding ida --json` prints.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct IdaReport {
    /// The intensity measure, in words.
    pub measure: String,
    /// Its levels, m/s^2.
    pub levels: Vec<f64>,
    /// The records and their intensities.
    pub records: Vec<RecordIntensity>,
    /// Number of runs.
    pub runs: usize,
    /// Runs that failed.
    pub failed: usize,
    /// The fits of every limit state.
    pub fragility: Vec<FragilityJson>,
    /// The unit of each quantity.
    pub units: serde_json::Map<String, Value>,
}

/// What an IDA wrote and found.
pub struct IdaOutput {
    /// runs.csv, as written.
    pub runs_csv: String,
    /// fragility.csv, as written.
    pub fragility_csv: String,
    /// The whole result: measure, levels, records, the fits.
    pub json: IdaReport,
    /// Each run's EDPs ([`Ida::edps`]; `None` for a failed run), record by record, level by level.
    pub edps: Vec<Option<Vec<f64>>>,
}

/// How an IDA ended early.
#[derive(Debug)]
pub enum IdaError {
    /// Bad input (the study, its records, another study's store): exit code 2.
    Input(InputError),
    /// The store or the files could not be written.
    Io(String),
    /// The progress callback asked to stop; every finished run is in the store.
    Cancelled,
}

/// Runs the IDA `ida` into `out` (created if missing): `out/study.sqlite` (resumable), `out/runs.csv` and
/// `out/fragility.csv`, written atomically at the end. `progress` as for [`crate::sweep::run`].
pub fn run(
    ida: &Ida,
    out: &Path,
    workers: usize,
    progress: &mut dyn FnMut(crate::sweep::Progress) -> std::ops::ControlFlow<()>,
) -> Result<IdaOutput, IdaError> {
    use crate::store::{Store, StoreError};
    let nl = ida.levels.len();
    let len = ida.records.len().saturating_mul(nl);
    if len > crate::study::MAX_RUNS {
        return Err(IdaError::Input(err(
            &ida.path,
            format!(
                "{} records x {nl} levels make {len} runs; allowed: at most 1e7",
                ida.records.len()
            ),
        )));
    }
    let ims = ida.intensities().map_err(IdaError::Input)?;
    let label = ida.path.display().to_string();
    let scenario = |n: usize| (ida.scenario(n / nl, n % nl, &ims).1, format!("{label}#{n}"));
    let id = crate::key::definition_id(
        &json!({"base": ida.base, "records": ida.records, "levels": ida.levels, "intensities": ims}),
        ida.path.parent(),
    );
    // Every run's key: what a store of the first layout knew this IDA by, and what an earlier IDA's store
    // must hold no more than to grow into this one's (new records or levels).
    // Made at most once, for the check and the opening alike.
    let made = std::cell::OnceCell::new();
    let keys = || {
        made.get_or_init(|| crate::sweep::run_keys(len, &scenario, workers))
            .clone()
    };
    let db = out.join("study.sqlite");
    let store_err = |e: StoreError| match e {
        StoreError::Mismatch(m) => IdaError::Input(InputError::new(m)),
        StoreError::Io(m) => IdaError::Io(m),
    };
    Store::check(&db, &id, len, &keys).map_err(store_err)?;
    std::fs::create_dir_all(out)
        .map_err(|e| IdaError::Io(format!("cannot create {}: {e}", out.display())))?;
    let mut store = Store::open(&db, &id, len, &keys).map_err(store_err)?;
    let swept = crate::sweep::run(
        len,
        &scenario,
        workers,
        &pounding::analysis::RunOptions::summary_only(),
        Some(&mut store),
        progress,
    )
    .map_err(|e| match e {
        crate::sweep::SweepError::Cancelled => IdaError::Cancelled,
        e => IdaError::Io(e.to_string()),
    })?;
    // Each run's outcome read back from the store, one at a time: its EDPs kept, its runs.csv row written.
    let mut edps: Vec<Option<Vec<f64>>> = Vec::with_capacity(len);
    let mut rows = RunsCsv::new(ida).map_err(IdaError::Io)?;
    let mut failed = 0;
    for n in 0..len {
        let outcome = swept
            .outcome(n, Some(&store))
            .map_err(|e| IdaError::Io(e.to_string()))?
            .and_then(|text| RunSummary::from_json(&text));
        failed += usize::from(outcome.is_err());
        let (i, j) = (n / nl, n % nl);
        rows.row(ida, i, j, &ims, &outcome).map_err(IdaError::Io)?;
        edps.push(outcome.ok().map(|s| ida.edps(&s)));
    }
    let runs = rows.finish().map_err(IdaError::Io)?;
    let fits = ida.fit(&edps);
    let frag = fragility_csv(&fits).map_err(IdaError::Io)?;
    for (name, text) in [("runs.csv", &runs), ("fragility.csv", &frag)] {
        crate::input::write_atomic(&out.join(name), text.as_bytes())
            .map_err(|e| IdaError::Io(format!("cannot write {}: {e}", out.join(name).display())))?;
    }
    let units = serde_json::json!({"levels": "m/s^2", "intensity": "m/s^2 at scale 1", "median": "m/s^2 (of the measure)", "beta": "logarithmic standard deviation", "exceedances": "[exceeding, runs] per level"});
    let json = IdaReport {
        measure: ida.measure_name(),
        levels: ida.levels.clone(),
        records: ida
            .records
            .iter()
            .zip(&ims)
            .map(|(r, &intensity)| RecordIntensity {
                record: r.clone(),
                intensity,
            })
            .collect(),
        runs: len,
        failed,
        fragility: fragility_json(&fits),
        units: match units {
            Value::Object(m) => m,
            _ => unreachable!("a JSON object"),
        },
    };
    Ok(IdaOutput {
        runs_csv: runs,
        fragility_csv: frag,
        json,
        edps,
    })
}

/// `runs.csv` of an IDA, row by row: each run's record, intensity and scale, its status, its EDPs, its
/// impacts and its error.
struct RunsCsv {
    cols: Vec<(String, Edp)>,
    wtr: csv::Writer<Vec<u8>>,
    buf: crate::format::Shortest,
}

fn csv_fail(e: csv::Error) -> String {
    format!("cannot write runs.csv: {e}")
}

impl RunsCsv {
    fn new(ida: &Ida) -> Result<RunsCsv, String> {
        let cols = edp_columns(&ida.buildings, &ida.inelastic);
        let mut wtr = csv::Writer::from_writer(Vec::new());
        let mut header = vec![
            "record",
            "intensity_m_per_s2",
            "record_intensity_m_per_s2",
            "scale",
            "status",
        ];
        header.extend(cols.iter().map(|(c, _)| c.as_str()));
        header.extend(["impacts", "error"]);
        wtr.write_record(&header).map_err(csv_fail)?;
        Ok(RunsCsv {
            cols,
            wtr,
            buf: crate::format::Shortest::new(),
        })
    }

    /// The row of record `i` at level `j`.
    fn row(
        &mut self,
        ida: &Ida,
        i: usize,
        j: usize,
        ims: &[f64],
        o: &Result<RunSummary, String>,
    ) -> Result<(), String> {
        let buf = &mut self.buf;
        let mut row: Vec<String> = vec![
            ida.records[i].clone(),
            buf.format(ida.levels[j]).to_string(),
            buf.format(ims[i]).to_string(),
            buf.format(ida.levels[j] / ims[i]).to_string(),
            if o.is_ok() { "ok" } else { "error" }.to_string(),
        ];
        match o {
            Ok(s) => {
                row.extend(
                    self.cols
                        .iter()
                        .map(|(_, e)| buf.format(e.value(s)).to_string()),
                );
                row.push(s.impacts().to_string());
                row.push(String::new());
            }
            Err(e) => {
                row.extend(self.cols.iter().map(|_| String::new()));
                row.push(String::new());
                row.push(e.clone());
            }
        }
        self.wtr.write_record(&row).map_err(csv_fail)
    }

    fn finish(self) -> Result<String, String> {
        let bytes = self.wtr.into_inner().map_err(|e| e.to_string())?;
        String::from_utf8(bytes).map_err(|e| e.to_string())
    }
}

/// `fragility.csv`: for each limit state and method, the fitted median and dispersion, or why there is none.
fn fragility_csv(fits: &[Fit]) -> Result<String, String> {
    let mut wtr = csv::Writer::from_writer(Vec::new());
    let fail = |e: csv::Error| format!("cannot write fragility.csv: {e}");
    wtr.write_record(["limit_state", "method", "median_m_per_s2", "beta", "note"])
        .map_err(fail)?;
    let mut buf = crate::format::Shortest::new();
    for f in fits {
        for (method, r) in [("stripes", &f.stripes), ("ida", &f.ida)] {
            let (m, b, note) = match r {
                Ok(f) => (
                    buf.format(f.median).to_string(),
                    buf.format(f.beta).to_string(),
                    String::new(),
                ),
                Err(e) => (String::new(), String::new(), e.clone()),
            };
            wtr.write_record([f.limit_state.as_str(), method, &m, &b, &note])
                .map_err(fail)?;
        }
    }
    let bytes = wtr.into_inner().map_err(|e| e.to_string())?;
    String::from_utf8(bytes).map_err(|e| e.to_string())
}
