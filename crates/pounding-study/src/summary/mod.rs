//! The summary of a run ([`RunSummary`]): what `summary.json`, Python's `result.summary` and a sweep's
//! store hold, built once from the library's results. `summary.json` is its serde form, and reading one
//! back is deserialisation: a field that is renamed is a compile error, not a silent default. Its JSON
//! Schema ([`RunSummary::json_schema`]) is `docs/summary.schema.json`.

mod building;
mod device;
pub mod inside;
mod plan;
mod site;
mod units;
pub use units::Units;

pub use building::{BuildingSummary, FoundationSummary, IsolatorSummary, MatricesSummary};
pub use device::DeviceSummary;
pub use plan::{LineSummary, PlanModeSummary, PlanSummary};
pub use site::{
    BumperSummary, ColumnSummary, ContactLawSummary, DampingSummary, DeliveredE, LevelSummary,
    SitePlace, SiteSummary,
};

use crate::input::Loaded;
use pounding::analysis::Results;
use pounding::scenario::Contacts;
use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

/// Largest energy balance error accepted without a warning.
pub const BALANCE_WARNING: f64 = 1e-4;

/// The record a run was under.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
pub struct RecordSummary {
    /// A built-in record's name, or the file's path as given.
    pub source: String,
    /// The scale factor applied to it (dimensionless).
    pub scale: f64,
    /// Number of samples.
    pub npts: usize,
    /// Time step, s.
    pub dt: f64,
    /// Peak ground acceleration after scaling, m/s^2.
    pub pga: f64,
}

/// A support of its own and what stands on it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
pub struct SupportSummary {
    /// Its name.
    pub name: String,
    /// How much later than the scenario's record its motion arrives, s (with a record of its own: that
    /// record's delay).
    pub delay: f64,
    /// Whether it has a record of its own (else the scenario's, delayed).
    pub own_record: bool,
    /// Its peak ground acceleration, m/s^2.
    pub pga: f64,
    /// The buildings and walls on it.
    pub structures: Vec<String>,
}

/// The energies at the end of the analysis, J.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
pub struct EnergySummary {
    /// Input energy `-int a_g 1^T M u' dt`, J.
    pub input: f64,
    /// Kinetic energy of the relative motion, J.
    pub kinetic: f64,
    /// Recoverable strain energy, J.
    pub strain: f64,
    /// Energy dissipated by viscous damping (structure and devices), J.
    pub structural_damping: f64,
    /// Energy dissipated by the storeys' hysteresis, J.
    pub hysteretic: f64,
    /// Work of the contact forces, J.
    pub contact: f64,
}

/// The counts of the integration.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
pub struct StatisticsSummary {
    /// Accepted steps.
    pub steps: usize,
    /// Rejected steps.
    pub rejected_steps: usize,
    /// Events located and applied.
    pub events: usize,
}

/// The summary of one run: the record, the settings, each building's modes and peak response, each contact
/// site (contacts between neighbours and walls, in one list with their kind) with its law and totals, each
/// device, the energy at the end and its balance error, the integration counts, and what the run says
/// about its own accuracy. SI units throughout (`units` names them).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
pub struct RunSummary {
    /// Where the scenario came from (its file, or a study's run).
    pub scenario: String,
    /// The record (along x).
    pub record: RecordSummary,
    /// The record along y, when the ground shakes in two directions (`[ground_motion.y]`, or one record
    /// along an angle: then the same source); the records as the analysis used them, on one time grid
    /// and turned by the angle.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub record_y: Option<RecordSummary>,
    /// Supports of their own (multi-support excitation), with the structures on them.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub supports: Vec<SupportSummary>,
    /// Analysed duration, s.
    pub duration: f64,
    /// Output interval of the histories, s.
    pub output_dt: f64,
    /// Relative tolerance of the integration.
    pub tolerance: f64,
    /// `off` for a run without contact (`contacts = "off"`): its sites record closings and openings only;
    /// absent when contacts act.
    #[serde(default, skip_serializing_if = "Contacts::is_on")]
    pub contacts: Contacts,
    /// The buildings, left to right.
    pub buildings: Vec<BuildingSummary>,
    /// The contact sites: contacts between neighbours, left to right, then walls.
    pub sites: Vec<SiteSummary>,
    /// The devices.
    pub devices: Vec<DeviceSummary>,
    /// Energies at the end of the analysis.
    pub energy: EnergySummary,
    /// Largest `|input - kinetic - strain - damping - hysteretic - contact|` over the run, over the largest
    /// energy (dimensionless).
    pub energy_balance_error: f64,
    /// The counts of the integration.
    pub statistics: StatisticsSummary,
    /// The unit of every number, by key. The same for every run: a study store's rows leave them out
    /// ([`crate::store`]), and a summary read without them gets them back.
    #[serde(default = "units::Units::shared")]
    pub units: units::Units,
    /// What the run says about its input (the common unit slips: a gap or opening larger than the buildings
    /// are tall, a first period under 0.05 s or over 20 s, a PGA above 5 g) and its own accuracy.
    pub warnings: Vec<String>,
}

impl RunSummary {
    /// The summary of a run of `loaded` that gave `r`. An error names the first number that is not finite
    /// (a result file holds no NaN, infinity or null).
    pub fn new(loaded: &Loaded, r: &Results) -> Result<RunSummary, String> {
        let s = &loaded.scenario;
        let rec = s.record();
        let e = &r.energy.end;
        // The common unit slips first: they explain everything else that looks odd.
        let mut warnings = s.implausible();
        // Accuracy that holds itself to account: a balance error above 1e-4 is said in the summary.
        if r.energy.relative_error > BALANCE_WARNING {
            warnings.push(format!(
                "energy balance error {:.2e} is above 1e-4: the integration is not as accurate as the tolerance asks; rerun with a smaller tolerance",
                r.energy.relative_error
            ));
        }
        let summary = RunSummary {
            scenario: loaded.label.clone(),
            record: RecordSummary {
                source: loaded.record_source.clone(),
                scale: loaded.doc.ground_motion.scale,
                npts: rec.npts(),
                dt: rec.dt(),
                pga: rec.pga(),
            },
            record_y: s.record_y().map(|r| {
                let gm = &loaded.doc.ground_motion;
                let (source, scale) = match &gm.y {
                    Some(y) => (
                        y.record.clone().or(y.file.clone()).unwrap_or_default(),
                        y.scale,
                    ),
                    None => (loaded.record_source.clone(), gm.scale),
                };
                RecordSummary {
                    source,
                    scale,
                    npts: r.npts(),
                    dt: r.dt(),
                    pga: r.pga(),
                }
            }),
            supports: s
                .supports()
                .iter()
                .enumerate()
                .map(|(k, (name, r))| SupportSummary {
                    name: name.clone(),
                    delay: r.delay(),
                    own_record: loaded.doc.support.get(k).is_some_and(|d| d.own().is_some()),
                    pga: r.pga(),
                    structures: s
                        .buildings()
                        .iter()
                        .zip(s.building_supports())
                        .filter(|(_, &b)| b == k + 1)
                        .map(|(b, _)| b.name.clone())
                        .chain(
                            s.sites()
                                .iter()
                                .filter(|w| w.is_wall() && w.support == k + 1)
                                .map(|w| w.name.clone()),
                        )
                        .collect(),
                })
                .collect(),
            duration: s.duration(),
            output_dt: s.output_dt(),
            tolerance: s.tolerance(),
            contacts: loaded.doc.contacts,
            buildings: s
                .buildings()
                .iter()
                .zip(&r.buildings)
                .map(|(b, resp)| BuildingSummary::of(b, resp))
                .collect(),
            sites: (0..s.sites().len())
                .map(|i| SiteSummary::of(s, r, i))
                .collect(),
            devices: r
                .devices
                .iter()
                .enumerate()
                .map(|(i, d)| DeviceSummary::of(s, i, d))
                .collect(),
            energy: EnergySummary {
                input: e.input,
                kinetic: e.kinetic,
                strain: e.strain,
                structural_damping: e.damping,
                hysteretic: e.hysteretic,
                contact: e.contact,
            },
            energy_balance_error: r.energy.relative_error,
            statistics: StatisticsSummary {
                steps: r.statistics.steps,
                rejected_steps: r.statistics.rejected,
                events: r.statistics.events,
            },
            units: units::Units::shared(),
            warnings,
        };
        // Read as text first (no tree built): a summary holds a null only where a number is not finite,
        // or a name or a warning says "null"; the tree then finds which.
        let text = serde_json::to_string(&summary).expect("a summary is JSON");
        if !text.contains("null") {
            return Ok(summary);
        }
        match first_null(&summary.to_value(), "summary") {
            Some(path) => Err(format!(
                "the result {path} is not a finite number: the scenario's scales leave the range of floating-point numbers"
            )),
            None => Ok(summary),
        }
    }

    /// As a JSON value (serde writes NaN and infinities as null).
    pub fn to_value(&self) -> serde_json::Value {
        serde_json::to_value(self).expect("a summary is JSON")
    }

    /// The row a study store keeps of this summary ([`crate::store`]): compact JSON without `units`, which
    /// are the same for every run (2.2 KB instead of 6.2 KB for a pair of buildings and a contact).
    /// [`RunSummary::from_json`] gives them back.
    pub fn to_row(&self) -> String {
        // Written once, the shared units cut out of the text: the bytes of the value without them, with no
        // tree built. (The first `,"units":{` of compact JSON is the field's: a string escapes its quotes.)
        let mut text = serde_json::to_string(self).expect("a summary is JSON");
        let field = units::shared_field_text();
        if let Some(at) = self.units.is_shared().then(|| text.find(field)).flatten() {
            text.replace_range(at..at + field.len(), "");
            return text;
        }
        let mut v = self.to_value();
        if let Some(o) = v.as_object_mut() {
            o.shift_remove("units");
        }
        v.to_string()
    }

    /// A store's row ([`RunSummary::to_row`]) as a whole summary's compact JSON, `units` included; text that
    /// does not read as a summary is given back as it is.
    pub fn row_to_whole(row: &str) -> String {
        RunSummary::from_json(row).map_or_else(|_| row.to_string(), |s| s.to_value().to_string())
    }

    /// A whole summary's JSON as a store's row ([`RunSummary::to_row`]); text that does not read as a
    /// summary is given back as it is.
    pub fn whole_to_row(text: &str) -> String {
        RunSummary::from_json(text).map_or_else(|_| text.to_string(), |s| s.to_row())
    }

    /// `summary.json`'s text: pretty-printed, with a final newline.
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).expect("a summary is JSON") + "\n"
    }

    /// A summary read back from its JSON text; the error says what does not fit.
    pub fn from_json(text: &str) -> Result<RunSummary, String> {
        // Read plainly first (a study reads every run's summary, twice for runs.csv); only a summary that
        // fails is read again with its path tracked, for the message.
        if let Ok(s) = serde_json::from_str(text) {
            return Ok(s);
        }
        let de = &mut serde_json::Deserializer::from_str(text);
        serde_path_to_error::deserialize(de).map_err(|e| {
            let path = e.path().to_string();
            format!("{path}: {}", e.into_inner())
        })
    }

    /// The JSON Schema of a summary (`docs/summary.schema.json`), pretty-printed with a final newline.
    pub fn json_schema() -> String {
        let schema = schemars::schema_for!(RunSummary);
        serde_json::to_string_pretty(&schema).expect("a schema is JSON") + "\n"
    }

    /// The index of the building called `name`.
    pub fn building(&self, name: &str) -> Option<usize> {
        self.buildings.iter().position(|b| b.name == name)
    }

    /// The total number of impacts of every site.
    pub fn impacts(&self) -> usize {
        self.sites.iter().map(|s| s.impacts).sum()
    }
}

/// The unit of every number of a summary (its `units`), as compact JSON.
pub fn units_text() -> String {
    serde_json::Value::Object(units::units()).to_string()
}

/// The path of the first `null` in `v` (JSON has no NaN or infinity: serde writes them as null). The path
/// is written only for the null found (this runs on every run's summary).
fn first_null(v: &serde_json::Value, path: &str) -> Option<String> {
    use serde_json::Value;
    match v {
        Value::Null => Some(path.to_string()),
        Value::Array(a) => a
            .iter()
            .position(has_null)
            .and_then(|i| first_null(&a[i], &format!("{path}[{i}]"))),
        Value::Object(o) => o
            .iter()
            .find(|(_, x)| has_null(x))
            .and_then(|(k, x)| first_null(x, &format!("{path}.{k}"))),
        _ => None,
    }
}

/// Whether `v` holds a `null` anywhere.
fn has_null(v: &serde_json::Value) -> bool {
    use serde_json::Value;
    match v {
        Value::Null => true,
        Value::Array(a) => a.iter().any(has_null),
        Value::Object(o) => o.values().any(has_null),
        _ => false,
    }
}
