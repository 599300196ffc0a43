//! Validation of a [`ScenarioDoc`] into the library's types, once, with one-line messages that name the key.

use super::{
    AlphaDoc, BuildingDoc, ContactDoc, Contacts, DeviceDoc, EDoc, FloorRef, FormatName,
    GroundMotionDoc, IsolatorDoc, LawDoc, LawKeys, ScenarioDoc, SchemaError, WallDoc,
};
use crate::analysis::{Building, Bumper, DeviceSpec, Scenario, WallSpec};
use crate::contact::{
    AlphaRule, AlphaWord, ContactModel, ContactOptions, Restitution, RestitutionTable,
};
use crate::element::{StoreyLaw, StoreyModel};
use crate::ground_motion::{Builtin, Format, Record, Units};
use crate::names::Named;
use crate::structure::ShearBuilding;
use crate::structure::{isolation, Isolator, IsolatorKind, IsolatorModel};
use crate::Error;

/// The record a scenario needs, checked: a built-in (`file == None`) or a file, how to read it, and the scale.
#[derive(Clone, Debug, PartialEq)]
pub struct RecordSpec {
    /// The built-in record's name, or the file's path as given.
    pub source: String,
    /// Whether `source` is a file.
    pub is_file: bool,
    /// The file's format, if given; `Values` carries its `dt` (s).
    pub format: Option<Format>,
    /// Units of the file's accelerations, if given (`None`: the AT2 header's, else g; see
    /// [`Record::read`]).
    pub units: Option<Units>,
    /// Scale factor on the accelerations (dimensionless).
    pub scale: f64,
}

/// Checks the name of the entry at `at`: 1 to 64 bytes, no control characters (they would break a line
/// of a message or of a table), and nothing `refused` finds (`rule` says what is allowed).
fn check_name(
    at: &str,
    name: &str,
    rule: &str,
    refused: impl Fn(&str) -> bool,
) -> Result<(), SchemaError> {
    if name.is_empty() || name.len() > 64 || name.chars().any(char::is_control) || refused(name) {
        return Err(SchemaError::new(
            format!("{at}.name"),
            format!("name = {name:?} is not allowed: 1 to 64 bytes, {rule}"),
        ));
    }
    Ok(())
}

/// What a wall's or a device's name may hold: any letter, commas, quotes and `|` too (the tables quote them).
const FREE_NAME: &str = "without control characters";

/// A library error in a scenario's words, about the entry at `entry` (`what: ` before it if not empty).
fn lib(entry: &str, what: &str, e: Error) -> SchemaError {
    let key = match &e {
        Error::Parameter { name, .. } | Error::Length { name, .. } | Error::Choice { name, .. } => {
            format!("{entry}.{name}")
        }
        _ => entry.to_string(),
    };
    let msg = e.to_string();
    if what.is_empty() {
        SchemaError::new(key, msg)
    } else {
        SchemaError::new(key, format!("{what}: {msg}"))
    }
}

impl GroundMotionDoc {
    /// The record this ground motion names, checked: exactly one of `record` and `file`; `format` and `dt`
    /// only with a file; `units` one of [`Units::parse`]'s names.
    pub fn spec(&self) -> Result<RecordSpec, SchemaError> {
        self.spec_at("ground_motion")
    }

    /// The record along y (`[ground_motion.y]`), checked as [`GroundMotionDoc::spec`]; `None` without one.
    pub fn spec_y(&self) -> Result<Option<RecordSpec>, SchemaError> {
        let Some(y) = &self.y else { return Ok(None) };
        if y.y.is_some() || y.angle.is_some() {
            return Err(SchemaError::new(
                "ground_motion.y",
                "[ground_motion.y] is the record along y: its own y and angle are not allowed (turn the pair with angle in [ground_motion])",
            ));
        }
        y.spec_at("ground_motion.y").map(Some)
    }

    pub(super) fn spec_at(&self, at: &str) -> Result<RecordSpec, SchemaError> {
        let table = format!("[{at}]");
        let key = |k: &str| format!("{at}.{k}");
        let (source, is_file) = match (&self.record, &self.file) {
            (Some(r), None) => (r.clone(), false),
            (None, Some(f)) => (f.clone(), true),
            _ => {
                return Err(SchemaError::new(
                    at,
                    format!(
                    "{table} needs exactly one of record = \"el-centro-1940\" or file = \"path\""
                ),
                ))
            }
        };
        if !is_file {
            if self.format.is_some() || self.dt.is_some() {
                return Err(SchemaError::new(
                    at,
                    "format and dt apply to a record file (file = ...), not to a built-in record",
                ));
            }
            if let (Some(u), Some(b)) = (self.units, Builtin::from_name(&source)) {
                return Err(SchemaError::new(key("units"), b.units_refused(u)));
            }
            if Record::builtin(&source).is_none() {
                return Err(SchemaError::new(
                    key("record"),
                    format!("record = {source:?} is not a built-in record: {} (for a file, use file = \"path\")", Record::BUILTINS),
                ));
            }
        }
        let format = match self.format {
            None => None,
            Some(FormatName::At2) => Some(Format::At2),
            Some(FormatName::TimeAcc) => Some(Format::TimeAcc),
            Some(FormatName::Values) => match self.dt {
                Some(dt) => Some(Format::Values { dt }),
                None => {
                    return Err(SchemaError::new(
                        key("format"),
                        format!("{table} format = values needs dt (the time step, s)"),
                    ))
                }
            },
        };
        if self.dt.is_some() && !matches!(format, Some(Format::Values { .. })) {
            return Err(SchemaError::new(
                key("dt"),
                format!("{table} dt applies to format = values only (other formats carry their time step)"),
            ));
        }
        let units = self.units;
        Ok(RecordSpec {
            source,
            is_file,
            format,
            units,
            scale: self.scale,
        })
    }
}

impl ScenarioDoc {
    /// The scenario under `record` (the one [`GroundMotionDoc::spec`] names, loaded and scaled by the
    /// caller), validated: buildings, settings and contacts.
    pub fn build(&self, record: Record) -> Result<Scenario, SchemaError> {
        self.build_full(record, None, Vec::new())
    }

    /// The record of each `[[support]]` that has one of its own (`None` for a delayed copy of the scenario's),
    /// checked as [`GroundMotionDoc::spec`]: what a caller loads for [`ScenarioDoc::build_full`].
    pub fn support_specs(&self) -> Result<Vec<Option<RecordSpec>>, SchemaError> {
        self.support
            .iter()
            .enumerate()
            .map(|(i, sp)| {
                sp.own()
                    .map(|gm| gm.spec_at(&format!("support.{i}")))
                    .transpose()
            })
            .collect()
    }

    /// The scenario under `record` along x and `y` along y, its supports' own records `supports` (one per
    /// `[[support]]` with a record of its own, in order, loaded and scaled by the caller).
    pub fn build_full(
        &self,
        record: Record,
        y: Option<Record>,
        supports: Vec<Record>,
    ) -> Result<Scenario, SchemaError> {
        let own = self.support.iter().filter(|s| s.own().is_some()).count();
        if own != supports.len() {
            return Err(SchemaError::new(
                "support",
                format!("{own} supports have records of their own, and {} were given: load them (ScenarioDoc::support_specs)", supports.len()),
            ));
        }
        let mut s = self.build_base(record, y)?;
        let mut own = supports.into_iter();
        for (i, sp) in self.support.iter().enumerate() {
            let at = format!("support.{i}");
            check_name(&at, &sp.name, FREE_NAME, |_| false)?;
            let base = match sp.own() {
                Some(_) => own.next().expect("counted above"),
                None => s.record().clone(),
            };
            let delay = match (sp.delay, sp.distance, sp.apparent_velocity) {
                (Some(d), None, None) => d,
                (None, Some(d), Some(v)) => {
                    if !(d.is_finite() && d >= 0.0 && v.is_finite() && v > 0.0) {
                        return Err(SchemaError::new(
                            format!("{at}.apparent_velocity"),
                            format!("support {:?}: distance = {} and apparent_velocity = {} are not allowed: distance >= 0 (m), apparent_velocity > 0 (m/s)", sp.name, crate::words::number(d), crate::words::number(v)),
                        ));
                    }
                    d / v
                }
                (None, None, None) if sp.own().is_some() => 0.0,
                _ => {
                    return Err(SchemaError::new(
                        format!("{at}.delay"),
                        format!("support {:?}: give delay (s), or distance (m) with apparent_velocity (m/s), or a record of its own", sp.name),
                    ))
                }
            };
            let rec = base
                .delayed(delay)
                .map_err(|e| lib(&at, &format!("support {:?}", sp.name), e))?;
            s = s.with_support(&sp.name, rec).map_err(|e| lib(&at, "", e))?;
        }
        for (i, b) in self.building.iter().enumerate() {
            if let Some(name) = &b.support {
                s = s.with_building_on(&b.name, name).map_err(|e| {
                    lib(
                        &format!("building.{i}"),
                        &format!("building {:?}", b.name),
                        e,
                    )
                })?;
            }
        }
        for (i, w) in self.wall.iter().enumerate() {
            if let Some(name) = &w.support {
                s = s
                    .with_wall_on(&w.name, name)
                    .map_err(|e| lib(&format!("wall.{i}"), &format!("wall {:?}", w.name), e))?;
            }
        }
        Ok(s)
    }

    /// The scenario under `record` along x and `y` along y (the record [`GroundMotionDoc::spec_y`] names,
    /// loaded and scaled by the caller; required if the scenario has `[ground_motion.y]`), validated. The
    /// records are put on one time grid and turned by `angle`.
    pub fn build_with(&self, record: Record, y: Option<Record>) -> Result<Scenario, SchemaError> {
        self.build_full(record, y, Vec::new())
    }

    /// The scenario under its records, before its supports of their own.
    fn build_base(&self, record: Record, y: Option<Record>) -> Result<Scenario, SchemaError> {
        let gm = &self.ground_motion;
        if gm.y.is_some() != y.is_some() {
            return Err(SchemaError::new(
                "ground_motion.y",
                if y.is_some() {
                    "a record along y was given, but the scenario has no [ground_motion.y]"
                } else {
                    "[ground_motion.y] names a record along y: load it (GroundMotionDoc::spec_y) and pass it to ScenarioDoc::build_with"
                },
            ));
        }
        let angle = gm.angle.unwrap_or(0.0);
        if !angle.is_finite() || angle.abs() > 360.0 {
            return Err(SchemaError::new(
                "ground_motion.angle",
                format!("angle = {} is not allowed: -360 <= angle <= 360 (degrees from x, counterclockwise)", crate::words::number(angle)),
            ));
        }
        let in_plan = self.building.iter().any(|b| b.plan.is_some());
        if (y.is_some() || angle != 0.0) && !in_plan {
            return Err(SchemaError::new(
                if y.is_some() { "ground_motion.y" } else { "ground_motion.angle" },
                "a ground motion along y moves buildings in plan only, and no building has a [building.plan] (buildings in one line move along x)",
            ));
        }
        let (record, y) = match (y, angle) {
            (None, 0.0) => (record, None),
            (y, a) => {
                let (x, y) = crate::ground_motion::turned(&record, y.as_ref(), a)
                    .map_err(|e| lib("ground_motion.y", "", e))?;
                (x, Some(y))
            }
        };
        let scenario = self.build_x(record, y)?;
        self.settle(scenario)
    }

    /// The buildings under `record` (and `y` along y), with the analysis settings.
    fn build_x(&self, record: Record, y: Option<Record>) -> Result<Scenario, SchemaError> {
        if self.building.is_empty() {
            return Err(SchemaError::new(
                "",
                "no [[building]] entries: a scenario needs at least one building",
            ));
        }
        // The size of the row, before any building's modes are computed.
        let floors: Vec<usize> = self
            .building
            .iter()
            .map(|b| b.masses.len() * if b.plan.is_some() { 3 } else { 1 })
            .collect();
        crate::limits::check_row(&floors).map_err(|e| lib("building.0", "", e))?;
        let mut buildings = Vec::new();
        for (i, b) in self.building.iter().enumerate() {
            let at = format!("building.{i}");
            // A building's name is also a word of limit states ("drift_ratio.NAME > 0.02") and half of
            // a pair's ("left|right"), so it keeps to plain words.
            check_name(
                &at,
                &b.name,
                "without commas, quotes, | or control characters",
                |n| n.contains([',', '"', '|']),
            )?;
            let what = format!("building {:?}", b.name);
            if let Some(plan) = &b.plan {
                buildings.push(Building {
                    name: b.name.clone(),
                    structure: building_in_plan(&at, &what, b, plan)?,
                });
                continue;
            }
            if !b.line.is_empty() {
                return Err(SchemaError::new(
                    format!("{at}.line"),
                    format!("{what}: [[building.line]] applies to a building in plan: add [building.plan] (size, position), or give stiffnesses"),
                ));
            }
            if b.stiffness_matrix.is_some() || b.mass_matrix.is_some() || b.damping_matrix.is_some()
            {
                buildings.push(Building {
                    name: b.name.clone(),
                    structure: building_from_matrices(&at, &what, b)?,
                });
                continue;
            }
            if b.stiffnesses.is_empty() && b.isolator.is_none() {
                return Err(SchemaError::new(
                    format!("{at}.stiffnesses"),
                    format!("{what}: stiffnesses (N/m, one per storey) is required, or a [building.plan] with its lines"),
                ));
            }
            let laws = storey_laws(&at, &what, b)?;
            let structure = match &b.isolator {
                None => ShearBuilding::new(
                    b.masses.clone(),
                    b.stiffnesses.clone(),
                    b.heights.clone(),
                    b.damping_ratio,
                ),
                Some(iso) => {
                    if b.masses.is_empty() {
                        return Err(SchemaError::new(
                            format!("{at}.masses"),
                            format!("{what}: masses = [] is not allowed: with an isolator, the base slab (floor 1) first, then the floors above it; an isolator carries the weight of the masses above it (a friction pendulum's force is proportional to it)"),
                        ));
                    }
                    let above = b.masses.len() - 1;
                    for (key, len) in [("stiffnesses", b.stiffnesses.len()), ("heights", b.heights.len())] {
                        if b.masses.is_empty() || len != above {
                            return Err(SchemaError::new(
                                format!("{at}.{key}"),
                                format!("{what}: with an isolator, {key} lists the storeys above the base slab: {len} values for {} masses (the slab, floor 1, and {above} floors above it)", b.masses.len()),
                            ));
                        }
                    }
                    ShearBuilding::isolated(
                        b.masses[0],
                        isolator(&format!("{at}.isolator"), &what, iso)?,
                        b.masses[1..].to_vec(),
                        b.stiffnesses.clone(),
                        b.heights.clone(),
                        b.damping_ratio,
                    )
                }
            }
            .and_then(|s| s.with_storey_laws(laws))
            .map_err(|e| lib(&at, &what, e))?;
            let structure = match &b.foundation {
                None => structure,
                Some(f) => structure
                    .with_foundation(foundation(&at, &what, f)?)
                    .map_err(|e| lib(&at, &what, e))?,
            };
            buildings.push(Building {
                name: b.name.clone(),
                structure,
            });
        }
        let last = format!("building.{}", self.building.len() - 1);
        let mut scenario = Scenario::new(buildings, record).map_err(|e| lib(&last, "", e))?;
        if let Some(y) = y {
            scenario = scenario
                .with_ground_y(y)
                .map_err(|e| lib("ground_motion.y", "", e))?;
        }

        if let Some(a) = &self.analysis {
            let e = |e| lib("analysis", "", e);
            if let Some(d) = a.duration {
                scenario = scenario.with_duration(d).map_err(e)?;
            }
            if let Some(d) = a.output_dt {
                scenario = scenario.with_output_dt(d).map_err(e)?;
            }
            if let Some(t) = a.tolerance {
                scenario = scenario.with_tolerance(t).map_err(e)?;
            }
            if let Some(v) = a.min_impact_velocity {
                scenario = scenario.with_min_impact_velocity(v).map_err(e)?;
            }
            if let Some(p) = a.propagation {
                scenario = scenario.with_propagation(p);
            }
        }
        if scenario.output_samples() > crate::limits::MAX_OUTPUT_SAMPLES {
            return Err(SchemaError::new(
                "analysis.output_dt",
                format!(
                    "duration / output_dt = {:e} output samples; allowed: at most 1e7 (raise output_dt)",
                    scenario.duration() / scenario.output_dt()
                ),
            ));
        }

        Ok(scenario)
    }

    /// `scenario` with its contacts, walls and devices.
    fn settle(&self, mut scenario: Scenario) -> Result<Scenario, SchemaError> {
        let names = FloorNames::of(&self.building)?;
        for (i, c) in self.contact.iter().enumerate() {
            scenario = contact(scenario, &format!("contact.{i}"), c, &names)?;
        }
        for (i, w) in self.wall.iter().enumerate() {
            scenario = wall(scenario, &format!("wall.{i}"), w, &names)?;
        }
        for (i, c) in self.column_contact.iter().enumerate() {
            let at = format!("column_contact.{i}");
            let what = format!("column contact {:?} floor {}", c.slab.0, c.slab.1);
            let floor = names.number(&format!("{at}.slab"), &c.slab.0, &c.slab.1)?;
            let spec = crate::analysis::ColumnLinkSpec {
                slab: (c.slab.0.clone(), floor),
                column: c.column.clone(),
                gap: c.gap,
                contact: contact_law(&at, &what, &c.law())?,
                ei: c.ei,
                mass: c.column_mass,
                shear_capacity: c.shear_capacity,
                moment_capacity: c.moment_capacity,
            };
            scenario = scenario
                .with_column_contact(spec)
                .map_err(|e| lib(&at, &what, e))?;
        }
        for (i, d) in self.device.iter().enumerate() {
            scenario = device(scenario, &format!("device.{i}"), d, &names)?;
        }
        Ok(match self.contacts {
            Contacts::On => scenario,
            Contacts::Off => scenario.with_contacts_off(),
        })
    }
}

/// A building in plan: its plan entry and its lines, checked (`stiffnesses`, the storey keys and an isolator
/// belong to a building in one line).
fn building_in_plan(
    at: &str,
    what: &str,
    b: &BuildingDoc,
    plan: &super::PlanDoc,
) -> Result<ShearBuilding, SchemaError> {
    let err =
        |key: &str, msg: String| SchemaError::new(format!("{at}.{key}"), format!("{what}: {msg}"));
    if !b.stiffnesses.is_empty() {
        return Err(err("stiffnesses", "stiffnesses is not allowed beside [building.plan]: the storey stiffnesses of a building in plan are its lines' ([[building.line]] stiffnesses)".into()));
    }
    if StoreyKeys::of_building(b).any() {
        return Err(err("storey_model", "the storey keys (storey_model, yield_forces, post_yield_ratio, bouc_wen) of a building in plan go on its lines ([[building.line]])".into()));
    }
    if b.isolator.is_some() {
        return Err(err("isolator", "an isolator under a building in plan is not modelled yet: give the isolated building in one line".into()));
    }
    if b.foundation.is_some() {
        return Err(err("foundation", "a foundation under a building in plan is not modelled yet: give the building on soil in one line".into()));
    }
    if b.stiffness_matrix.is_some() || b.mass_matrix.is_some() || b.damping_matrix.is_some() {
        return Err(err("stiffness_matrix", "a building in plan takes its stiffness from its lines: a structure given by its matrices moves in one line".into()));
    }
    let n = b.masses.len();
    let per = |key: &str, len: usize| {
        err(
            key,
            format!("{key} has {len} values, but there are {n} floors: give one per floor, or one for all"),
        )
    };
    let centres = plan
        .mass_centre
        .as_ref()
        .map(|c| c.per_storey(n).map_err(|len| per("plan.mass_centre", len)))
        .transpose()?
        .map(|c| c.iter().map(|p| (p[0], p[1])).collect());
    let inertias = plan
        .inertia
        .as_ref()
        .map(|c| c.per_storey(n).map_err(|len| per("plan.inertia", len)))
        .transpose()?;
    let mut lines = Vec::new();
    for (i, l) in b.line.iter().enumerate() {
        let key = format!("{at}.line.{i}");
        let lw = format!("{what}, line {}", i + 1);
        let stiffnesses = l.stiffnesses.per_storey(n).map_err(|len| {
            SchemaError::new(
                format!("{key}.stiffnesses"),
                format!("{lw}: stiffnesses has {len} values, but there are {n} storeys: give one per storey, or one for all"),
            )
        })?;
        let laws = laws_of(&key, &lw, &StoreyKeys::of_line(l), n)?;
        lines.push(crate::structure::Line {
            direction: l.direction,
            at: l.at,
            stiffnesses,
            laws,
        });
    }
    let spec = crate::structure::PlanSpec {
        size: (plan.size[0], plan.size[1]),
        origin: plan.position.map_or((0.0, 0.0), |p| (p[0], p[1])),
        centres,
        inertias,
        lines,
        damping_modes: plan.damping_modes.map(|[i, j]| (i, j)),
    };
    ShearBuilding::in_plan(b.masses.clone(), b.heights.clone(), b.damping_ratio, spec).map_err(
        |e| {
            // A line's error names `line.at`: the entry's key holds the line's number in the message.
            lib(at, what, e)
        },
    )
}

/// A structure given by its matrices (`stiffness_matrix`, `masses` or `mass_matrix`, `damping_matrix`), its
/// storeys linear.
fn building_from_matrices(
    at: &str,
    what: &str,
    b: &BuildingDoc,
) -> Result<ShearBuilding, SchemaError> {
    let err =
        |key: &str, msg: String| SchemaError::new(format!("{at}.{key}"), format!("{what}: {msg}"));
    let Some(k) = &b.stiffness_matrix else {
        return Err(err("stiffness_matrix", "stiffness_matrix (N/m) is required beside mass_matrix or damping_matrix: a structure given by its matrices needs its stiffness".into()));
    };
    if !b.stiffnesses.is_empty() {
        return Err(err(
            "stiffnesses",
            "stiffnesses is not allowed beside stiffness_matrix: give one or the other".into(),
        ));
    }
    if b.isolator.is_some() {
        return Err(err("isolator", "an isolator under a structure given by its matrices is not modelled yet: put the isolator's spring in the matrix, or give a shear building".into()));
    }
    if StoreyKeys::of_building(b).any() {
        return Err(err("storey_model", "the storey keys (storey_model, yield_forces, post_yield_ratio, bouc_wen) are not allowed for a structure given by its matrices: its storeys are linear (the inelastic laws stay on the shear-building forms)".into()));
    }
    if b.foundation.is_some() {
        return Err(err("foundation", "a foundation under a structure given by its matrices is not modelled yet: add the foundation's degrees of freedom to the matrices, or give a shear building".into()));
    }
    let lib = |e| lib(at, what, e);
    let k = k.matrix("stiffness_matrix").map_err(lib)?;
    let mass = match (&b.mass_matrix, b.masses.is_empty()) {
        (Some(m), true) => m.matrix("mass_matrix").map_err(lib)?,
        (None, false) => crate::structure::Matrix::diagonal(&b.masses),
        (Some(_), false) => return Err(err("mass_matrix", "mass_matrix is not allowed beside masses: give one or the other (a lumped mass matrix's diagonal is the floors' masses)".into())),
        (None, true) => return Err(err("masses", "masses (kg, one per floor) or mass_matrix is required beside stiffness_matrix".into())),
    };
    let c = match &b.damping_matrix {
        Some(c) => Some(c.matrix("damping_matrix").map_err(lib)?),
        None => None,
    };
    let structure = crate::structure::MatrixStructure::new(&mass, k, c).map_err(lib)?;
    if b.heights.len() != structure.n() {
        return Err(err("heights", format!("heights has {} values, but the matrices have {} degrees of freedom (floors): give each storey's height, m", b.heights.len(), structure.n())));
    }
    ShearBuilding::from_matrices(structure, b.heights.clone(), b.damping_ratio).map_err(lib)
}

/// The foundation of a building entry at `at`: its springs given, or from the soil and its shape.
fn foundation(
    at: &str,
    what: &str,
    f: &super::FoundationDoc,
) -> Result<crate::structure::Foundation, SchemaError> {
    use crate::structure::{Foundation, Shape, Soil};
    let key = format!("{at}.foundation");
    let err =
        |k: &str, msg: String| SchemaError::new(format!("{key}.{k}"), format!("{what}: {msg}"));
    let given = [f.kx, f.ktheta, f.cx, f.ctheta].iter().any(Option::is_some);
    let soil_keys = [f.vs, f.density, f.poisson, f.radius]
        .iter()
        .any(Option::is_some)
        || f.size.is_some();
    let soil = match (given, soil_keys) {
        (true, true) => {
            return Err(err(
                "kx",
                "the springs given (kx, ktheta, cx, ctheta) or the soil (vs, density, poisson, radius or size), not both".into(),
            ))
        }
        (true, false) => {
            let need = |k: &str, v: Option<f64>, unit: &str| {
                v.ok_or_else(|| err(k, format!("{k} ({unit}) is required with the springs given")))
            };
            Soil::Given {
                kx: need("kx", f.kx, "N/m")?,
                ktheta: need("ktheta", f.ktheta, "N m/rad")?,
                cx: f.cx.unwrap_or(0.0),
                ctheta: f.ctheta.unwrap_or(0.0),
            }
        }
        (false, _) => {
            let vs = f.vs.ok_or_else(|| {
                err("vs", "vs (the soil's shear-wave velocity, m/s) is required, or the springs given (kx, ktheta, cx, ctheta)".into())
            })?;
            let shape = match (f.radius, f.size) {
                (Some(r), None) => Shape::Disk(r),
                (None, Some([a, b])) => Shape::Rectangle(a, b),
                _ => {
                    return Err(err(
                        "radius",
                        "the foundation's radius (m) or its size [a, b] (m), one of them".into(),
                    ))
                }
            };
            Soil::HalfSpace {
                vs,
                density: f.density.unwrap_or(1800.0),
                poisson: f.poisson.unwrap_or(0.33),
                shape,
            }
        }
    };
    Foundation::new(f.mass, f.inertia, soil).map_err(|e| lib(at, what, e))
}

/// The storey keys of a building entry or of one of its lines.
struct StoreyKeys<'a> {
    storey_model: &'a Option<super::OneOrMany<String>>,
    yield_forces: &'a Option<super::OneOrMany<f64>>,
    post_yield_ratio: &'a Option<super::OneOrMany<f64>>,
    bouc_wen: &'a Option<crate::element::BoucWenShape>,
}

impl<'a> StoreyKeys<'a> {
    fn of_building(b: &'a BuildingDoc) -> Self {
        Self {
            storey_model: &b.storey_model,
            yield_forces: &b.yield_forces,
            post_yield_ratio: &b.post_yield_ratio,
            bouc_wen: &b.bouc_wen,
        }
    }
    fn of_line(l: &'a super::LineDoc) -> Self {
        Self {
            storey_model: &l.storey_model,
            yield_forces: &l.yield_forces,
            post_yield_ratio: &l.post_yield_ratio,
            bouc_wen: &l.bouc_wen,
        }
    }
    /// Whether any key is given.
    fn any(&self) -> bool {
        self.storey_model.is_some()
            || self.yield_forces.is_some()
            || self.post_yield_ratio.is_some()
            || self.bouc_wen.is_some()
    }
}

/// The storey laws of a building entry: `storey_model` (default linear), `yield_forces`, `post_yield_ratio`
/// (default 0, elastic–perfectly-plastic) and `bouc_wen` (default n = 1, beta = gamma = 0.5).
fn storey_laws(at: &str, what: &str, b: &BuildingDoc) -> Result<Vec<StoreyLaw>, SchemaError> {
    // With an isolator, the storeys above the base slab.
    let storeys = b.masses.len() - usize::from(b.isolator.is_some() && !b.masses.is_empty());
    laws_of(at, what, &StoreyKeys::of_building(b), storeys)
}

/// The laws of `storeys` storeys from their keys `b` (of the entry at `at`, `what` in messages).
fn laws_of(
    at: &str,
    what: &str,
    b: &StoreyKeys,
    storeys: usize,
) -> Result<Vec<StoreyLaw>, SchemaError> {
    let err =
        |key: &str, msg: String| SchemaError::new(format!("{at}.{key}"), format!("{what}: {msg}"));
    let list = |key: &str, len: usize| {
        err(
            key,
            format!(
                "{key} has {len} values, but there {} {}: give one per storey, or one for all",
                if storeys == 1 { "is" } else { "are" },
                crate::words::count(storeys, "storey", None)
            ),
        )
    };
    let names = match b.storey_model {
        None => vec![StoreyModel::Linear.name().to_string(); storeys],
        Some(m) => m.per_storey(storeys).map_err(|n| list("storey_model", n))?,
    };
    let models = names
        .iter()
        .map(|m| StoreyModel::parse_name(m).map_err(|e| err("storey_model", e)))
        .collect::<Result<Vec<_>, _>>()?;
    let inelastic = models.iter().any(|m| *m != StoreyModel::Linear);
    let bouc_wen = models.contains(&StoreyModel::BoucWen);
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
    let fy = match b.yield_forces {
        None => {
            return Err(err(
                "storey_model",
                "yield_forces (N) is required for bilinear and bouc-wen storeys".into(),
            ))
        }
        Some(f) => f.per_storey(storeys).map_err(|n| list("yield_forces", n))?,
    };
    let ratio = match b.post_yield_ratio {
        None => vec![0.0; storeys],
        Some(r) => r
            .per_storey(storeys)
            .map_err(|n| list("post_yield_ratio", n))?,
    };
    let bw = b.bouc_wen.unwrap_or_default();
    models
        .iter()
        .enumerate()
        .map(|(j, m)| {
            match m {
                StoreyModel::Linear => Ok(StoreyLaw::Linear),
                StoreyModel::Bilinear => StoreyLaw::bilinear(fy[j], ratio[j]),
                StoreyModel::BoucWen => {
                    StoreyLaw::bouc_wen(fy[j], ratio[j], bw.n, bw.beta, bw.gamma)
                }
            }
            .map_err(|e| lib(at, &format!("{what}, storey {}", j + 1), e))
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

/// What the entry at `at` asks its contact to deliver: `e` (a number or a table) or `damping_constant`, one of
/// them; the default `e` without either.
fn restitution(at: &str, pair: &str, c: &LawDoc) -> Result<Restitution, SchemaError> {
    let err = |key: &str, e: Error| SchemaError::new(format!("{at}.{key}"), format!("{pair}: {e}"));
    match (c.e, c.damping_constant) {
        (Some(_), Some(d)) => Err(SchemaError::new(
            format!("{at}.damping_constant"),
            format!(
                "{pair}: damping_constant = {} is not allowed beside e: give e (the restitution to deliver) or damping_constant (the material's D/K, s/m), not both",
                crate::words::number(d)
            ),
        )),
        (None, Some(d)) => Restitution::damping_constant(d).map_err(|e| err("damping_constant", e)),
        (Some(EDoc::Number(e)), None) => Ok(Restitution::Constant(*e)),
        (Some(EDoc::Table { table }), None) => {
            RestitutionTable::new(table.iter().map(|r| (r[0], r[1])).collect())
                .map(Restitution::Table)
                .map_err(|e| err("e.table", e))
        }
        (None, None) => Ok(ContactOptions::default().e),
    }
}

/// The contact options of an entry, asked to deliver `e`.
fn options(c: &LawDoc, e: Restitution) -> ContactOptions {
    ContactOptions {
        model: c.model,
        e,
        exponent: c.exponent,
        damping: c.damping.unwrap_or(ContactOptions::default().damping),
        alpha: c.alpha.map(|a| match a {
            AlphaDoc::Number(x) => AlphaRule::Given(*x),
            AlphaDoc::Word(AlphaWord::Eq8) => AlphaRule::Eq8,
            AlphaDoc::Word(AlphaWord::Calibrate) => AlphaRule::Calibrate,
        }),
        reading: c.reading.unwrap_or(ContactOptions::default().reading),
        tension: c.tension,
        max_penetration: c.max_penetration,
        yield_ratio: c
            .yield_ratio
            .unwrap_or(ContactOptions::default().yield_ratio),
        radius: c.radius,
        yield_pressure: c.yield_pressure,
    }
}

/// The contact law of an entry at `at` (`pair` names it in messages): its options, and a stiffness that
/// states its unit.
fn contact_law(at: &str, pair: &str, c: &LawDoc) -> Result<ContactModel, SchemaError> {
    let key = |k: &str| format!("{at}.{k}");
    let opts = options(c, restitution(at, pair, c)?);
    // The stiffness states its unit, so that changing the model cannot silently change what it means.
    let n = opts.exponent();
    match c.stiffness_unit {
        None => {
            return Err(SchemaError::new(
                key("stiffness"),
                format!(
                    "{pair}: stiffness_unit is required with stiffness: \"{}\" for {} (exponent {n}), so that the stiffness keeps its meaning if the model changes",
                    crate::words::stiffness_unit(n),
                    opts.model.name(),
                ),
            ))
        }
        Some(u) => {
            let given = stiffness_exponent(u).ok_or_else(|| {
                SchemaError::new(
                    key("stiffness_unit"),
                    format!("{pair}: stiffness_unit = {u:?} is not allowed: \"N/m\" or \"N/m^n\" (for example \"N/m^1.5\")"),
                )
            })?;
            if (given - n).abs() > 1e-12 {
                return Err(SchemaError::new(
                    key("stiffness_unit"),
                    format!(
                        "{pair}: stiffness_unit = {u:?} does not match the exponent {n} of {}: its stiffness is in {} (convert it, or set exponent = {given})",
                        opts.model.name(),
                        crate::words::stiffness_unit(n),
                    ),
                ));
            }
        }
    }
    opts.build(c.stiffness).map_err(|e| {
        let m = e.message(|k| k.replace('-', "_"));
        let path = e
            .key()
            .map_or(at.to_string(), |k| key(&k.replace('-', "_")));
        SchemaError::new(path, format!("{pair}: {m}"))
    })
}

/// The bumper of an entry at `at`, if it has one.
fn bumper(
    at: &str,
    pair: &str,
    b: &Option<super::BumperDoc>,
) -> Result<Option<Bumper>, SchemaError> {
    let Some(b) = b else { return Ok(None) };
    let at = format!("{at}.bumper");
    let what = format!("{pair} bumper");
    let law = contact_law(&at, &what, &b.law())?;
    Bumper::new(b.thickness, b.max_strain, &law)
        .map(Some)
        .map_err(|e| lib(&at, &what, e))
}

/// The buildings' names of their degrees of freedom (`dof_names`), checked, by building: what a floor named
/// in a contact, a wall, a device or a column contact refers to.
struct FloorNames<'a>(Vec<(&'a str, &'a [String])>);

impl<'a> FloorNames<'a> {
    /// The names of every building entry, each list checked: one per floor, 1 to 64 bytes without control
    /// characters, unique in its building.
    fn of(buildings: &'a [BuildingDoc]) -> Result<Self, SchemaError> {
        let mut out = Vec::new();
        for (i, b) in buildings.iter().enumerate() {
            let Some(names) = &b.dof_names else {
                out.push((b.name.as_str(), &[][..]));
                continue;
            };
            let at = format!("building.{i}.dof_names");
            let floors = if b.masses.is_empty() {
                b.heights.len()
            } else {
                b.masses.len()
            };
            if names.len() != floors {
                return Err(SchemaError::new(at, format!("building {:?}: dof_names has {} names, but it has {floors} floors (degrees of freedom): give one name per floor, floor 1 first", b.name, names.len())));
            }
            for (k, n) in names.iter().enumerate() {
                if n.is_empty() || n.len() > 64 || n.chars().any(char::is_control) {
                    return Err(SchemaError::new(at, format!("building {:?}: dof name {n:?} is not allowed: 1 to 64 bytes without control characters", b.name)));
                }
                if names[..k].contains(n) {
                    return Err(SchemaError::new(at, format!("building {:?}: dof name {n:?} is given twice: each floor's name must be its own", b.name)));
                }
            }
            out.push((b.name.as_str(), names.as_slice()));
        }
        Ok(Self(out))
    }

    /// Whether `name` is a building's.
    fn is_building(&self, name: &str) -> bool {
        self.0.iter().any(|(b, _)| *b == name)
    }

    /// The number (from 1) of floor `f` of `building`, for the key `key`. A number is taken as it is (the
    /// library checks its range); a name must be one of the building's `dof_names`.
    fn number(&self, key: &str, building: &str, f: &FloorRef) -> Result<usize, SchemaError> {
        let name = match f {
            FloorRef::Number(n) => return Ok(*n),
            FloorRef::Name(name) => name,
        };
        let names = self
            .0
            .iter()
            .find(|(b, _)| *b == building)
            .map_or(&[][..], |(_, n)| *n);
        if let Some(k) = names.iter().position(|n| n == name) {
            return Ok(k + 1);
        }
        let allowed = if names.is_empty() {
            format!("building {building:?} has no dof_names: its floors by number, from 1")
        } else {
            let shown: Vec<String> = names.iter().take(8).map(|n| format!("{n:?}")).collect();
            let more = if names.len() > 8 { ", ..." } else { "" };
            format!(
                "one of building {building:?}'s dof_names ({}{more}), or a floor number from 1",
                shown.join(", ")
            )
        };
        Err(SchemaError::new(
            key,
            format!("floor {name:?} is not allowed: {allowed}"),
        ))
    }

    /// Floor pairs `[[i, j], ...]` at `at.floors` between `between` (a wall's side takes the building's
    /// floors), as numbers.
    fn pairs(
        &self,
        at: &str,
        between: &[String; 2],
        floors: &Option<Vec<Vec<FloorRef>>>,
    ) -> Result<Option<Vec<(usize, usize)>>, SchemaError> {
        let key = format!("{at}.floors");
        let side = |k: usize| {
            if self.is_building(&between[k]) {
                between[k].as_str()
            } else {
                between[1 - k].as_str()
            }
        };
        floors
            .as_ref()
            .map(|f| {
                f.iter()
                    .map(|p| match p.as_slice() {
                        [i, j] => Ok((
                            self.number(&key, side(0), i)?,
                            self.number(&key, side(1), j)?,
                        )),
                        _ => {
                            let shown: Vec<String> = p.iter().map(ToString::to_string).collect();
                            Err(SchemaError::new(
                                key.clone(),
                                format!("floors entry [{}] is not allowed: pairs [floor of left, floor of right], from 1 or by name", shown.join(", ")),
                            ))
                        }
                    })
                    .collect()
            })
            .transpose()
    }
}

/// Two names in `between`.
fn two(at: &str, between: &[String], what: &str) -> Result<[String; 2], SchemaError> {
    <[String; 2]>::try_from(between.to_vec()).map_err(|_| {
        SchemaError::new(
            format!("{at}.between"),
            format!("between = {between:?} is not allowed: two names, {what}"),
        )
    })
}

/// Adds the contact entry `c` (at `at`) to `scenario`.
fn contact(
    scenario: Scenario,
    at: &str,
    c: &ContactDoc,
    names: &FloorNames,
) -> Result<Scenario, SchemaError> {
    let between = two(at, &c.between, "[\"left\", \"right\"]")?;
    let pair = format!("contact {:?}-{:?}", between[0], between[1]);
    let spec = contact_law(at, &pair, &c.law())?;
    let floors = names.pairs(at, &between, &c.floors)?;
    let [a, b] = between;
    let bumper = bumper(at, &pair, &c.bumper)?;
    let in_plan = |n: &str| {
        scenario
            .building_index(n)
            .is_ok_and(|i| scenario.buildings()[i].structure.plan().is_some())
    };
    if in_plan(&a) || in_plan(&b) {
        if let Some(g) = c.gap {
            return Err(SchemaError::new(
                format!("{at}.gap"),
                format!("{pair}: gap = {} is not allowed between buildings in plan: their positions give it (plan.position); leave it out", crate::words::number(g)),
            ));
        }
        return scenario
            .with_plan_contact(crate::analysis::PlanLinkSpec {
                between: [a, b],
                floors,
                points: c.points.clone(),
                contact: spec,
                bumper,
                seat: c.seat,
            })
            .map_err(|e| lib(at, &pair, e));
    }
    if c.points.is_some() {
        return Err(SchemaError::new(
            format!("{at}.points"),
            format!(
                "{pair}: points along the façades apply to buildings in plan ([building.plan])"
            ),
        ));
    }
    let Some(gap) = c.gap else {
        return Err(SchemaError::new(
            format!("{at}.gap"),
            format!("{pair}: gap (m, the clear distance at rest) is required"),
        ));
    };
    let mut s = scenario
        .with_link(&a, &b, gap, &spec, floors)
        .map_err(|e| lib(at, "", e))?;
    if let Some(bm) = bumper {
        s = s
            .with_link_bumper(&a, &b, bm)
            .map_err(|e| lib(at, &pair, e))?;
    }
    if let Some(seat) = c.seat {
        s = s
            .with_link_seat(&a, &b, seat)
            .map_err(|e| lib(at, &pair, e))?;
    }
    Ok(s)
}

/// Adds the wall entry `w` (at `at`) to `scenario`.
fn wall(
    scenario: Scenario,
    at: &str,
    w: &WallDoc,
    names: &FloorNames,
) -> Result<Scenario, SchemaError> {
    check_name(at, &w.name, FREE_NAME, |_| false)?;
    let what = format!("wall {:?}", w.name);
    let side = w.side;
    let spec = WallSpec {
        name: w.name.clone(),
        facing: w.facing.clone(),
        side,
        gap: w.gap,
        floors: w
            .floors
            .as_ref()
            .map(|f| {
                f.iter()
                    .map(|x| names.number(&format!("{at}.floors"), &w.facing, x))
                    .collect::<Result<Vec<_>, _>>()
            })
            .transpose()?,
        points: w.points.clone(),
        contact: contact_law(at, &what, &w.law())?,
        bumper: bumper(at, &what, &w.bumper)?,
        seat: w.seat,
    };
    scenario.with_wall(spec).map_err(|e| lib(at, &what, e))
}

/// Adds the device entry `d` (at `at`) to `scenario`.
fn device(
    scenario: Scenario,
    at: &str,
    d: &DeviceDoc,
    names: &FloorNames,
) -> Result<Scenario, SchemaError> {
    let between = two(
        at,
        &d.between,
        "two neighbouring buildings, or a building and a wall",
    )?;
    if let Some(name) = &d.name {
        check_name(at, name, FREE_NAME, |_| false)?;
    }
    let what = format!(
        "device {:?}",
        d.name.clone().unwrap_or_else(|| d.law.name().to_string())
    );
    let floors = names.pairs(at, &between, &d.floors)?;
    let spec = DeviceSpec {
        name: d.name.clone(),
        between,
        floors,
        law: d.law.clone(),
    };
    scenario.with_device(spec).map_err(|e| lib(at, &what, e))
}

/// The isolator of a building entry at `at`.
fn isolator(at: &str, what: &str, d: &IsolatorDoc) -> Result<Isolator, SchemaError> {
    let model = d.model;
    let err =
        |key: &str, msg: String| SchemaError::new(format!("{at}.{key}"), format!("{what}: {msg}"));
    let fp = model == IsolatorKind::FrictionPendulum;
    let hysteretic = [IsolatorKind::Bilinear, IsolatorKind::BoucWen].contains(&model);
    for (key, given, applies) in [
        ("stiffness", d.stiffness.is_some(), !fp),
        ("yield_force", d.yield_force.is_some(), hysteretic),
        ("post_yield_ratio", d.post_yield_ratio.is_some(), hysteretic),
        (
            "bouc_wen",
            d.bouc_wen.is_some(),
            model == IsolatorKind::BoucWen,
        ),
        ("radius", d.radius.is_some(), fp),
        ("mu", d.mu.is_some(), fp),
        ("yield_displacement", d.yield_displacement.is_some(), fp),
    ] {
        if given && !applies {
            return Err(err(
                key,
                format!("{key} does not apply to a {model} isolator"),
            ));
        }
    }
    let needs = |key: &str, v: Option<f64>, unit: &str| {
        v.ok_or_else(|| err(key, format!("a {model} isolator needs {key} ({unit})")))
    };
    let k = || needs("stiffness", d.stiffness, "N/m");
    let fy = || needs("yield_force", d.yield_force, "N");
    let a = d.post_yield_ratio.unwrap_or(0.0);
    let m = match model {
        IsolatorKind::Linear => IsolatorModel::Linear { stiffness: k()? },
        IsolatorKind::Bilinear => IsolatorModel::Bilinear {
            stiffness: k()?,
            yield_force: fy()?,
            post_yield_ratio: a,
        },
        IsolatorKind::BoucWen => {
            let bw = d.bouc_wen.unwrap_or_default();
            IsolatorModel::BoucWen {
                stiffness: k()?,
                yield_force: fy()?,
                post_yield_ratio: a,
                n: bw.n,
                beta: bw.beta,
                gamma: bw.gamma,
            }
        }
        IsolatorKind::FrictionPendulum => IsolatorModel::FrictionPendulum {
            radius: needs("radius", d.radius, "m")?,
            mu: needs("mu", d.mu, "dimensionless")?,
            yield_displacement: d
                .yield_displacement
                .unwrap_or(isolation::FRICTION_YIELD_DISPLACEMENT),
        },
    };
    let mut iso = Isolator::new(m);
    if let Some(h) = d.height {
        iso.height = h;
    }
    if let Some(c) = d.damping_coefficient {
        iso.damping = c;
    }
    iso.clearance = d.clearance;
    Ok(iso)
}
