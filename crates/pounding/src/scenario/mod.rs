//! The one scenario schema (behind the `serde` feature): a scenario file (TOML), a Python dict and a study's
//! generated variants all deserialize into [`ScenarioDoc`], and [`ScenarioDoc::build`] validates it once into
//! an [`analysis::Scenario`](crate::analysis::Scenario), with the same one-line messages whatever the source.
//!
//! The library reads no files: [`GroundMotionDoc::spec`] says which record the scenario needs, and the
//! caller passes the loaded [`Record`] to [`ScenarioDoc::build`]. Every error names the key it concerns as a
//! dotted path (`contact.0.stiffness_unit`), which a caller maps to a line of its file or shows as it is.
//!
//! ```
//! use pounding::ground_motion::Record;
//! use pounding::scenario::ScenarioDoc;
//! let doc: ScenarioDoc = serde_json::from_str(r#"{
//!   "ground_motion": {"record": "el-centro-1940"},
//!   "building": [
//!     {"name": "A", "masses": [1e5], "stiffnesses": [4e7], "heights": [3.0]},
//!     {"name": "B", "masses": [2e5], "stiffnesses": [2e7], "heights": [3.0]}],
//!   "contact": [{"between": ["A", "B"], "gap": 0.01, "stiffness": 1e9, "stiffness_unit": "N/m"}]
//! }"#).unwrap();
//! let scenario = doc.build(Record::el_centro_1940()).unwrap();
//! assert_eq!(scenario.sites()[0].gap, 0.01);
//! ```

mod build;

pub use build::RecordSpec;

use crate::analysis::Side;
use crate::contact::{AlphaWord, ContactOptions, Damping, Model, Reading, Tension};
use crate::element::{BoucWenShape, DeviceLaw};
use crate::ground_motion::Units;
use crate::structure::IsolatorKind;
use serde::{Deserialize, Serialize};

/// A scenario: the ground motion, the analysis settings, the buildings left to right and the contacts
/// between neighbours (keys as in `docs/scenarios.md`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct ScenarioDoc {
    /// The ground motion.
    pub ground_motion: GroundMotionDoc,
    /// Analysis settings; defaults if absent.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub analysis: Option<AnalysisDoc>,
    /// The buildings, left to right.
    #[serde(default)]
    pub building: Vec<BuildingDoc>,
    /// Contacts between neighbouring buildings.
    #[serde(default)]
    pub contact: Vec<ContactDoc>,
    /// Walls beside buildings.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub wall: Vec<WallDoc>,
    /// Devices between neighbours.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub device: Vec<DeviceDoc>,
    /// Slabs striking a neighbour's column between its floors (floor-to-column contacts).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub column_contact: Vec<ColumnContactDoc>,
    /// Supports of their own (multi-support excitation): buildings and walls on them (`support = "name"`)
    /// are shaken by their record.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub support: Vec<SupportDoc>,
    /// `"on"` (default) or `"off"`: the same structures with every contact and wall inactive (they record
    /// closings only; devices stay), the response that pounding amplifies.
    #[serde(default, skip_serializing_if = "Contacts::is_on")]
    pub contacts: Contacts,
}

crate::named! {
    /// Whether a scenario's contacts and walls act (`contacts = "on"`, the default) or not (`"off"`).
    #[derive(Default)]
    pub enum Contacts: "contacts" {
        /// Every contact and wall acts.
        #[default]
        On = "on",
        /// None acts: they record the largest closing and opening of each level only.
        Off = "off",
    }
}

impl Contacts {
    /// Whether contacts act (the default, left out of a written scenario).
    pub fn is_on(&self) -> bool {
        *self == Contacts::On
    }
}

/// `[ground_motion]`: a built-in record or a record file.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct GroundMotionDoc {
    /// A built-in record: `el-centro-1940` or `synthetic-SEED`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub record: Option<String>,
    /// A record file (relative paths are the caller's to resolve).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub file: Option<String>,
    /// `at2`, `time-acc` or `values` (default: detected, [`Format::detect`](crate::ground_motion::Format::detect):
    /// `at2` for a text with the PEER AT2 header, a line holding NPTS and DT, whatever the file's name, or
    /// for a `*.at2` file; `time-acc` otherwise).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub format: Option<FormatName>,
    /// Time step of a `values` file, s.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub dt: Option<f64>,
    /// Units of the file's accelerations: `g`, `m/s2` (or `m/s^2`), `cm/s2` (or `cm/s^2`, `gal`), `mm/s2`
    /// (or `mm/s^2`), read by [`Units::parse`](crate::ground_motion::Units::parse). Default: the units an
    /// AT2 header states (`... IN UNITS OF G`), else g. Units given that contradict an AT2 header are an
    /// error.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub units: Option<Units>,
    /// Scale factor on the accelerations (dimensionless).
    #[serde(default = "one")]
    pub scale: f64,
    /// `[ground_motion.y]`: the record along y (the keys above, for it; the one above is then along x), for
    /// buildings in plan. Put on one time grid with the record along x
    /// ([`crate::ground_motion::on_one_grid`]).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub y: Option<Box<GroundMotionDoc>>,
    /// The direction of the record above from the x axis, degrees counterclockwise (default 0): one record
    /// along an angle shakes x with `cos` and y with `sin` of it; with a record along y too, the pair is
    /// turned by the angle.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub angle: Option<f64>,
}

/// `[analysis]`: settings; each absent one keeps the library's default.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct AnalysisDoc {
    /// Analysed duration, s (default: the record's).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub duration: Option<f64>,
    /// Output interval, s (default 0.005).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub output_dt: Option<f64>,
    /// Relative tolerance of the integration (default 1e-7).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tolerance: Option<f64>,
    /// Floor of the impact velocity used to build a contact law, m/s (default 1e-3).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub min_impact_velocity: Option<f64>,
    /// `exact` (default: linear stretches propagated exactly, `docs/performance.md`) or `stepping` (the
    /// adaptive Runge–Kutta stepper throughout).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub propagation: Option<crate::engine::Propagation>,
}

/// `[[building]]`: a shear building, floor 1 (the lowest) first. With an `isolator`, floor 1 is the base
/// slab on it, and `stiffnesses`, `heights` and the storey keys list the storeys above the slab.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct BuildingDoc {
    /// Name, unique in the scenario: 1 to 64 bytes without commas, quotes, `|` or control characters.
    pub name: String,
    /// Floor masses, kg.
    pub masses: Vec<f64>,
    /// Storey stiffnesses (initial), N/m; for a building in plan, its lines carry them instead.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub stiffnesses: Vec<f64>,
    /// Storey heights, m.
    pub heights: Vec<f64>,
    /// Rayleigh damping ratio of modes 1 and 2 (dimensionless, default 0.05).
    #[serde(default = "default_damping_ratio")]
    pub damping_ratio: f64,
    /// `linear`, `bilinear` or `bouc-wen`: one for every storey or one per storey (default linear).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub storey_model: Option<OneOrMany<String>>,
    /// Yield force of each inelastic storey, N.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub yield_forces: Option<OneOrMany<f64>>,
    /// Post-yield stiffness ratio (dimensionless, default 0).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub post_yield_ratio: Option<OneOrMany<f64>>,
    /// Bouc–Wen shape parameters.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bouc_wen: Option<BoucWenShape>,
    /// The isolator under the base slab, for a building isolated at its base.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub isolator: Option<IsolatorDoc>,
    /// `[building.plan]`: floors that move in plan (x, y and rotation), placed in the site's frame.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub plan: Option<PlanDoc>,
    /// `[[building.line]]`: the lateral load-resisting lines of a building in plan.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub line: Vec<LineDoc>,
    /// `[building.foundation]`: the building stands on a foundation over soil springs and dashpots
    /// (soil–structure interaction) instead of a fixed base.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub foundation: Option<FoundationDoc>,
    /// The `[[support]]` it stands on (default: the scenario's ground).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub support: Option<String>,
    /// A structure given by its matrices (`docs/structures.md`, "Structures from matrices"): the stiffness
    /// matrix, N/m, over the floors' displacements (floor 1, the lowest, first), in place of `stiffnesses`.
    /// Rows inline, or a file (dense CSV or Matrix Market) relative to the scenario's folder.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stiffness_matrix: Option<MatrixDoc>,
    /// The damping matrix, N s/m, of a structure given by its matrices (default: Rayleigh damping of
    /// `damping_ratio` on the matrices' modes 1 and 2). Rows or a file, as `stiffness_matrix`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub damping_matrix: Option<MatrixDoc>,
    /// The lumped (diagonal) mass matrix, kg, of a structure given by its matrices, in place of `masses`.
    /// Rows or a file, as `stiffness_matrix`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mass_matrix: Option<MatrixDoc>,
    /// Names of the degrees of freedom (the floors), floor 1 first, one per floor: contacts, walls, devices
    /// and column contacts may then name a floor by its name as well as by its number (for a structure given
    /// by its matrices, the names of the program that condensed it). 1 to 64 bytes each, unique, without
    /// control characters.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub dof_names: Option<Vec<String>>,
}

/// A floor named in a contact, a wall, a device or a column contact: its number, from 1, or its name in the
/// building's `dof_names`.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(untagged)]
pub enum FloorRef {
    /// The floor's number, from 1.
    Number(usize),
    /// The floor's name in its building's `dof_names`.
    Name(String),
}

impl<'de> Deserialize<'de> for FloorRef {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct Visitor;
        impl serde::de::Visitor<'_> for Visitor {
            type Value = FloorRef;
            fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.write_str("a floor: its number from 1, or its name in the building's dof_names")
            }
            fn visit_u64<E: serde::de::Error>(self, v: u64) -> Result<FloorRef, E> {
                usize::try_from(v)
                    .map(FloorRef::Number)
                    .map_err(|_| E::custom(format!("floor {v} is not allowed: a floor number from 1, or a name in the building's dof_names")))
            }
            fn visit_i64<E: serde::de::Error>(self, v: i64) -> Result<FloorRef, E> {
                u64::try_from(v)
                    .map_err(|_| E::custom(format!("floor {v} is not allowed: a floor number from 1, or a name in the building's dof_names")))
                    .and_then(|v| self.visit_u64(v))
            }
            fn visit_str<E: serde::de::Error>(self, v: &str) -> Result<FloorRef, E> {
                Ok(FloorRef::Name(v.to_string()))
            }
        }
        d.deserialize_any(Visitor)
    }
}

impl std::fmt::Display for FloorRef {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            FloorRef::Number(n) => write!(f, "{n}"),
            FloorRef::Name(s) => write!(f, "{s:?}"),
        }
    }
}

/// A matrix in a scenario: its rows, or the name of a file that holds it (read by the program that loads the
/// scenario, relative to the scenario's folder, and put in as rows).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(
    untagged,
    expecting = "expected a matrix: a list of rows of numbers, or a file name (CSV or Matrix Market)"
)]
pub enum MatrixDoc {
    /// Its rows, each a list of numbers.
    Rows(Vec<Vec<f64>>),
    /// A file holding it: a dense array (CSV or white space) or Matrix Market.
    File(String),
}

impl MatrixDoc {
    /// The matrix, named `name` in errors; a file name not yet read is refused.
    pub fn matrix(&self, name: &'static str) -> Result<crate::structure::Matrix, crate::Error> {
        match self {
            MatrixDoc::Rows(rows) => crate::structure::Matrix::from_rows(name, rows),
            MatrixDoc::File(f) => Err(crate::Error::Choice {
                name,
                value: format!("{f:?}"),
                allowed: "rows of numbers here (a file name is read by the program that loads the scenario)".into(),
            }),
        }
    }
}

/// `[building.foundation]`: a rigid foundation (its mass and moment of inertia) on sway and rocking springs
/// and dashpots, given directly (`kx`, `ktheta`, `cx`, `ctheta`) or from the soil (`vs`, `density`, `poisson`)
/// and the foundation's shape (`radius`, or `size`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct FoundationDoc {
    /// The foundation's mass, kg (> 0).
    pub mass: f64,
    /// Its moment of inertia about the rocking axis, kg m^2 (default from its shape: `m r^2 / 4`, `m a^2 / 12`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub inertia: Option<f64>,
    /// Sway stiffness, N/m (with the other three: the springs given directly).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub kx: Option<f64>,
    /// Rocking stiffness, N m/rad.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ktheta: Option<f64>,
    /// Sway dashpot, N s/m (default 0 with the springs given).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cx: Option<f64>,
    /// Rocking dashpot, N m s/rad (default 0 with the springs given).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ctheta: Option<f64>,
    /// The soil's shear-wave velocity, m/s (the springs and dashpots of a half-space).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub vs: Option<f64>,
    /// The soil's density, kg/m^3 (default 1800).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub density: Option<f64>,
    /// The soil's Poisson's ratio (default 0.33).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub poisson: Option<f64>,
    /// A circular foundation's radius, m.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub radius: Option<f64>,
    /// `[a, b]`: a rectangular foundation's sides, m, `a` along the motion.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub size: Option<[f64; 2]>,
}

/// `[[support]]`: a support with its own ground motion: the scenario's record arriving later (`delay`, or
/// `distance` over `apparent_velocity`: wave passage), or a record of its own (the keys of
/// `[ground_motion]`), itself delayed if asked.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct SupportDoc {
    /// Name, unique among supports: 1 to 64 bytes without control characters.
    pub name: String,
    /// How much later the motion arrives, s (>= 0).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub delay: Option<f64>,
    /// Distance from the scenario's ground to this support along the wave's path, m (with
    /// `apparent_velocity`: the delay `distance / apparent_velocity`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub distance: Option<f64>,
    /// The wave's apparent velocity along the ground, m/s.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub apparent_velocity: Option<f64>,
    /// A built-in record of its own (instead of the scenario's).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub record: Option<String>,
    /// A record file of its own (relative to the scenario's folder).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub file: Option<String>,
    /// The file's format (as `[ground_motion]`'s).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub format: Option<FormatName>,
    /// Time step of a `values` file, s.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub dt: Option<f64>,
    /// Units of the file's accelerations (as `[ground_motion]`'s).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub units: Option<Units>,
    /// Scale factor on its own record (dimensionless, default 1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub scale: Option<f64>,
}

impl SupportDoc {
    /// Its own record as a `[ground_motion]` entry, if it has one.
    pub fn own(&self) -> Option<GroundMotionDoc> {
        (self.record.is_some() || self.file.is_some()).then(|| GroundMotionDoc {
            record: self.record.clone(),
            file: self.file.clone(),
            format: self.format,
            dt: self.dt,
            units: self.units,
            scale: self.scale.unwrap_or(1.0),
            y: None,
            angle: None,
        })
    }
}

/// `[building.plan]`: a rectangular plan, its place in the site's frame, its floors' mass centres and
/// moments of inertia, and the modes its Rayleigh damping is fixed on.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct PlanDoc {
    /// `[a, b]`: the plan's size along x and along y, m.
    pub size: [f64; 2],
    /// `[x, y]`: its corner of smallest x and y in the site's frame, m (default `[0, 0]`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub position: Option<[f64; 2]>,
    /// `[x, y]` of the mass centre in the plan's frame (from its corner), m: one for every floor or one per
    /// floor (default the plan's middle).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mass_centre: Option<OneOrMany<[f64; 2]>>,
    /// Moment of inertia of each floor about its mass centre, kg m^2: one for every floor or one per floor
    /// (default the uniform rectangle's, `m (a^2 + b^2) / 12`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub inertia: Option<OneOrMany<f64>>,
    /// The two modes (from 1) the Rayleigh damping ratio is fixed on (default: the two lowest that move
    /// mostly along x).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub damping_modes: Option<[usize; 2]>,
}

/// `[[building.line]]`: a lateral load-resisting line (a frame or a wall) of a building in plan: its
/// direction, where it stands, and its storeys (with the storey keys of a building in one line).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct LineDoc {
    /// `x` or `y`: the direction it resists along.
    pub direction: crate::structure::LineDirection,
    /// Where it stands in the plan's frame, m: the ordinate y of a line along x, the abscissa x of one along
    /// y.
    pub at: f64,
    /// Storey stiffnesses (initial) of the line, N/m: one for every storey or one per storey.
    pub stiffnesses: OneOrMany<f64>,
    /// `linear`, `bilinear` or `bouc-wen`: one for every storey or one per storey (default linear).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub storey_model: Option<OneOrMany<String>>,
    /// Yield force of each inelastic storey of the line, N.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub yield_forces: Option<OneOrMany<f64>>,
    /// Post-yield stiffness ratio (dimensionless, default 0).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub post_yield_ratio: Option<OneOrMany<f64>>,
    /// Bouc–Wen shape parameters.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bouc_wen: Option<BoucWenShape>,
}

/// One value for every storey, or a list with one per storey.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(
    untagged,
    expecting = "expected one value for every storey, or a list with one per storey"
)]
pub enum OneOrMany<T> {
    /// The same value for every storey.
    One(T),
    /// One value per storey.
    Many(Vec<T>),
}

impl<T: Clone> OneOrMany<T> {
    /// One value per storey; `Err(len)` for a list of the wrong length.
    pub fn per_storey(&self, storeys: usize) -> Result<Vec<T>, usize> {
        match self {
            OneOrMany::One(x) => Ok(vec![x.clone(); storeys]),
            OneOrMany::Many(v) if v.len() == storeys => Ok(v.clone()),
            OneOrMany::Many(v) => Err(v.len()),
        }
    }
}

/// A contact's `e`: one number, or a table of `[v_i (m/s), e]` rows (`e = { table = [[0.1, 0.8], [2.0, 0.5]] }`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(
    untagged,
    expecting = "expected a number in (0, 1] or { table = [[v_i (m/s), e], ...] }"
)]
pub enum EDoc {
    /// One coefficient of restitution (dimensionless).
    Number(f64),
    /// `e` against the impact velocity: rows `[v_i (m/s), e]`, velocities increasing.
    Table {
        /// The rows.
        table: Vec<[f64; 2]>,
    },
}

/// `alpha` of `papi`: a number, or `eq8` / `calibrate`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(
    untagged,
    expecting = "expected a number >= 0, \"eq8\" or \"calibrate\""
)]
pub enum AlphaDoc {
    /// A given value (dimensionless).
    Number(f64),
    /// `eq8` or `calibrate`.
    Word(AlphaWord),
}

/// Declares a schema entry that carries a contact law: its own fields, then the law's keys (the same on a
/// `[[contact]]`, a `[[wall]]` and a bumper), and [`LawKeys`] to read them.
macro_rules! with_contact_law {
    ($(#[$meta:meta])* pub struct $name:ident { $($(#[$fm:meta])* pub $field:ident : $ty:ty,)* }) => {
        $(#[$meta])*
        #[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
        #[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
        #[serde(deny_unknown_fields)]
        pub struct $name {
            $($(#[$fm])* pub $field: $ty,)*
            /// Contact model (default `papi`, [`ContactOptions::default`]).
            #[serde(default = "default_model")]
            pub model: Model,
            /// Requested coefficient of restitution (dimensionless, default 0.65, [`ContactOptions::default`]),
            /// or a table of it against the impact velocity.
            #[serde(default, skip_serializing_if = "Option::is_none")]
            pub e: Option<EDoc>,
            /// Hunt–Crossley family: a material damping constant D/K (s/m) instead of `e`, with the law
            /// `F = K d^n (1 + (D/K) d')`.
            #[serde(default, skip_serializing_if = "Option::is_none")]
            pub damping_constant: Option<f64>,
            /// Stiffness, in `stiffness_unit`.
            pub stiffness: f64,
            /// `N/m` or `N/m^n`, matching the model's exponent (required).
            #[serde(default, skip_serializing_if = "Option::is_none")]
            pub stiffness_unit: Option<String>,
            /// Exponent of the force law (dimensionless; default the model's).
            #[serde(default, skip_serializing_if = "Option::is_none")]
            pub exponent: Option<f64>,
            /// `exact` (default: each impact of two free bodies delivers `e`) or `formula` (the published one).
            #[serde(default, skip_serializing_if = "Option::is_none")]
            pub damping: Option<Damping>,
            /// `alpha` of `papi`.
            #[serde(default, skip_serializing_if = "Option::is_none")]
            pub alpha: Option<AlphaDoc>,
            /// `energy-split` (default) or `same-damping`.
            #[serde(default, skip_serializing_if = "Option::is_none")]
            pub reading: Option<Reading>,
            /// `allow` or `clamp` (default: the model's).
            #[serde(default, skip_serializing_if = "Option::is_none")]
            pub tension: Option<Tension>,
            /// `impact-material`: expected maximum penetration, m.
            #[serde(default, skip_serializing_if = "Option::is_none")]
            pub max_penetration: Option<f64>,
            /// `impact-material`: yield ratio (dimensionless, default 0.1).
            #[serde(default, skip_serializing_if = "Option::is_none")]
            pub yield_ratio: Option<f64>,
            /// `thornton`: radius of the spheres, m (`stiffness` is their Hertz stiffness).
            #[serde(default, skip_serializing_if = "Option::is_none")]
            pub radius: Option<f64>,
            /// `thornton`: yield pressure, Pa.
            #[serde(default, skip_serializing_if = "Option::is_none")]
            pub yield_pressure: Option<f64>,
        }

        impl LawKeys for $name {
            fn law(&self) -> LawDoc<'_> {
                LawDoc {
                    model: self.model,
                    e: self.e.as_ref(),
                    damping_constant: self.damping_constant,
                    stiffness: self.stiffness,
                    stiffness_unit: self.stiffness_unit.as_deref(),
                    exponent: self.exponent,
                    damping: self.damping,
                    alpha: self.alpha.as_ref(),
                    reading: self.reading,
                    tension: self.tension,
                    max_penetration: self.max_penetration,
                    yield_ratio: self.yield_ratio,
                    radius: self.radius,
                    yield_pressure: self.yield_pressure,
                }
            }
        }
    };
}

/// The contact-law keys of an entry, borrowed.
#[derive(Clone, Copy, Debug)]
pub struct LawDoc<'a> {
    /// The model.
    pub model: Model,
    /// Requested coefficient of restitution, or its table.
    pub e: Option<&'a EDoc>,
    /// Material damping constant, s/m.
    pub damping_constant: Option<f64>,
    /// Stiffness, in `stiffness_unit`.
    pub stiffness: f64,
    /// Its unit.
    pub stiffness_unit: Option<&'a str>,
    /// Exponent.
    pub exponent: Option<f64>,
    /// `formula` or `exact`.
    pub damping: Option<Damping>,
    /// `alpha` of `papi`.
    pub alpha: Option<&'a AlphaDoc>,
    /// Reading of `papi`.
    pub reading: Option<Reading>,
    /// Tension rule.
    pub tension: Option<Tension>,
    /// `impact-material`: expected maximum penetration, m.
    pub max_penetration: Option<f64>,
    /// `impact-material`: yield ratio.
    pub yield_ratio: Option<f64>,
    /// `thornton`: radius, m.
    pub radius: Option<f64>,
    /// `thornton`: yield pressure, Pa.
    pub yield_pressure: Option<f64>,
}

/// An entry that carries a contact law.
pub trait LawKeys {
    /// Its law's keys.
    fn law(&self) -> LawDoc<'_>;
}

with_contact_law! {
    /// `[[contact]]`: contact elements between two neighbouring buildings.
    pub struct ContactDoc {
        /// The two buildings' names.
        pub between: Vec<String>,
        /// Gap at rest, m (for buildings in plan, their positions give it: leave it out).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        pub gap: Option<f64>,
        /// Floor pairs `[floor of left, floor of right]`, from 1 (default: floors at the same height); for
        /// buildings in plan, `[floor of the first of between, floor of the second]`.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        pub floors: Option<Vec<Vec<FloorRef>>>,
        /// Buildings in plan: where along the façades the contact elements act, m (the site-frame
        /// coordinate along them; default both ends of their overlap).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        pub points: Option<Vec<f64>>,
        /// A bumper on the joint's face.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        pub bumper: Option<BumperDoc>,
        /// Seat length of the joint for the unseating check, m.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        pub seat: Option<f64>,
    }
}

with_contact_law! {
    /// `[[wall]]`: a wall fixed to the ground beside a building.
    pub struct WallDoc {
        /// Name, unique among buildings and walls: 1 to 64 bytes without control characters (commas,
        /// quotes, `|` and any letter are fine).
        pub name: String,
        /// The building it stands beside.
        pub facing: String,
        /// `left` or `right` of that building (of a building in plan: its west or east façade; `south` and
        /// `north` its façades of smallest and largest y).
        pub side: Side,
        /// Clear distance at rest, m.
        pub gap: f64,
        /// Floors that can strike it, from 1 or by name (default `[1]`).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        pub floors: Option<Vec<FloorRef>>,
        /// For a building in plan: where along its façade the contact elements act, m (the site-frame
        /// coordinate along it; default its two corners).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        pub points: Option<Vec<f64>>,
        /// A bumper on its face.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        pub bumper: Option<BumperDoc>,
        /// Seat length for the unseating check (an abutment's seat), m.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        pub seat: Option<f64>,
        /// The `[[support]]` it stands on (default: the scenario's ground).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        pub support: Option<String>,
    }
}

with_contact_law! {
    /// `[[column_contact]]`: a slab striking its neighbour's column at the slab's elevation (between the
    /// neighbour's floors; at one of them, a floor contact).
    pub struct ColumnContactDoc {
        /// `[building, floor]`: the building whose slab strikes, and the floor (from 1, or by name).
        pub slab: (String, FloorRef),
        /// The neighbour whose column is struck.
        pub column: String,
        /// Gap at rest between the slab's edge and the column, m.
        pub gap: f64,
        /// Flexural rigidity of the column (or the line of columns struck together), N m^2.
        #[serde(rename = "EI")]
        pub ei: f64,
        /// The column's mass, kg.
        pub column_mass: f64,
        /// Shear capacity at the column's ends, N (its demand is reported against it).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        pub shear_capacity: Option<f64>,
        /// Moment capacity at the column's ends, N m.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        pub moment_capacity: Option<f64>,
    }
}

with_contact_law! {
    /// `bumper`: a soft layer of finite thickness on a contact's or a wall's face, with its own law.
    pub struct BumperDoc {
        /// Thickness, m (at most the gap).
        pub thickness: f64,
        /// Largest compressive strain of the layer, in (0, 1).
        pub max_strain: f64,
    }
}

/// `[building.isolator]`: the isolator under the base slab (floor 1); the building's `stiffnesses`,
/// `heights` and storey keys then describe the storeys above it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct IsolatorDoc {
    /// `linear`, `bilinear`, `bouc-wen` or `friction-pendulum`.
    pub model: IsolatorKind,
    /// Initial stiffness, N/m (linear, bilinear, bouc-wen).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stiffness: Option<f64>,
    /// Yield force, N (bilinear, bouc-wen).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub yield_force: Option<f64>,
    /// Post-yield stiffness ratio (bilinear, bouc-wen; default 0).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub post_yield_ratio: Option<f64>,
    /// Bouc–Wen shape parameters (bouc-wen).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bouc_wen: Option<BoucWenShape>,
    /// Radius of curvature, m (friction-pendulum).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub radius: Option<f64>,
    /// Coefficient of friction (friction-pendulum).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mu: Option<f64>,
    /// Yield displacement of the friction variable, m (friction-pendulum; default 2.5e-4).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub yield_displacement: Option<f64>,
    /// Height of the isolation storey, m (default 0.5).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub height: Option<f64>,
    /// Viscous coefficient of the isolator, N s/m (default 0: hysteresis only).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub damping_coefficient: Option<f64>,
    /// Displacement capacity, m, reported against the demand.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub clearance: Option<f64>,
}

/// `[[device]]`: a permanent device between floors of two neighbours, or of a building and a wall: its name,
/// ends and floors, and its `model` with that model's keys ([`DeviceLaw`], one per model of
/// `element/registry.rs`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct DeviceDoc {
    /// Name, unique among devices: 1 to 64 bytes without control characters (default: the model and its
    /// number, `restrainer1`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
    /// Two neighbouring buildings, or a building and a wall beside it.
    pub between: Vec<String>,
    /// Floor pairs (to a wall: `[floor, floor]`), from 1 (default: floors at the same height; floor 1 to a
    /// wall), numbers or names.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub floors: Option<Vec<Vec<FloorRef>>>,
    /// `model = "..."` and its keys (SI units): `spring` (stiffness), `dashpot` (damping_coefficient),
    /// `kelvin` and `maxwell` (both), `restrainer` (stiffness, slack).
    #[serde(flatten)]
    pub law: DeviceLaw,
}

fn one() -> f64 {
    1.0
}
fn default_damping_ratio() -> f64 {
    crate::structure::DEFAULT_DAMPING_RATIO
}
fn default_model() -> Model {
    ContactOptions::default().model
}
crate::named! {
    /// The formats of a record file, by name.
    pub enum FormatName: "format" {
        /// PEER AT2.
        At2 = "at2",
        /// Two columns: time (s) and acceleration.
        TimeAcc = "time-acc",
        /// One acceleration per line, with `dt` given.
        Values = "values",
    }
}

/// A scenario that does not validate: the key it concerns and a one-line message.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("{message}")]
pub struct SchemaError {
    /// Dotted path of the key (`contact.0.gap`), or of the entry (`building.1`, `ground_motion`); empty for
    /// the whole scenario.
    pub key: String,
    /// What is wrong and what is allowed.
    pub message: String,
}

impl SchemaError {
    fn new(key: impl Into<String>, message: impl Into<String>) -> Self {
        SchemaError {
            key: key.into(),
            message: message.into(),
        }
    }
}
