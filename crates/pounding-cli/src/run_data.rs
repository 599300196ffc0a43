//! The output folder of `pounding run`, read back: what the figures and the report are made from, so that
//! `pounding report DIR` gives the same figures as `run --plots` did, from the files alone. Reading it back
//! is deserialisation: `summary.json` is a [`RunSummary`], the tables are the study crate's typed rows, and
//! `response.csv`'s columns are those the summary describes (pounding_study::tables).

use crate::error::CliError;
use crate::output::fmt_num;
use pounding_study::summary::{RunSummary, SitePlace};
use pounding_study::tables::{read_response, read_rows, EnergyRow, ImpactRow, LoopRow, Table};
use std::path::Path;

/// The file of every impact's force–penetration path, in a run's output folder.
pub const LOOPS_FILE: &str = <LoopRow as Table>::FILE;

/// The last component of a path (a record file's name), or the whole text if it has none: subtitles show
/// the file, not its folders.
pub fn file_name(path: &str) -> String {
    Path::new(path)
        .file_name()
        .map_or_else(|| path.to_string(), |n| n.to_string_lossy().into_owned())
}

/// One impact's force–penetration path, from impact-loops.csv.
pub struct LoopData {
    /// Index of the impact in [`RunData::impacts`].
    pub impact: usize,
    /// Penetration, m.
    pub penetration: Vec<f64>,
    /// Contact force, N.
    pub force: Vec<f64>,
}

/// One building's histories, and its floor elevations.
pub struct BuildingData {
    /// Name.
    pub name: String,
    /// Displacement relative to the ground of each floor (floor 1 first), m, at [`RunData::t`].
    pub floors: Vec<Vec<f64>>,
    /// Restoring force of each storey (storey 1 first), N, at [`RunData::t`].
    pub storey_shear: Vec<Vec<f64>>,
    /// Elevation of each floor above the ground (floor 1 first), m.
    pub elevations: Option<Vec<f64>>,
    /// A building in plan: each floor's mass centre along y, m, at [`RunData::t`] (empty in one line).
    pub floors_y: Vec<Vec<f64>>,
    /// A building in plan: each floor's rotation, rad, at [`RunData::t`] (empty in one line).
    pub rotation: Vec<Vec<f64>>,
}

/// One contact element (a level) of a site.
pub struct ElementData {
    /// Floors (left, right), counted from 1; 0 on a wall's side.
    pub floors: (usize, usize),
    /// Contact force, N, at [`RunData::t`].
    pub force: Vec<f64>,
}

/// One contact site: a contact between neighbouring buildings, or a wall beside a building.
pub struct ContactData {
    /// `left|right`, or the wall's name.
    pub name: String,
    /// Index of the left building (`None`: a wall on the left of the right one).
    pub left: Option<usize>,
    /// Index of the right building (`None`: a wall on the right of the left one).
    pub right: Option<usize>,
    /// Whether it is a wall.
    pub wall: bool,
    /// Gap at rest, m.
    pub gap: f64,
    /// Coefficient of restitution the contact model is built to deliver (`None`: an elastic model).
    pub e: Option<f64>,
    /// Its levels.
    pub elements: Vec<ElementData>,
}

/// One device, with the force of each floor pair.
pub struct DeviceData {
    /// Its name.
    pub name: String,
    /// Its model's name.
    pub model: String,
    /// The force of each floor pair (N, positive pushing apart), at [`RunData::t`].
    pub elements: Vec<ElementData>,
}

/// One impact (a row of impacts.csv), placed at its site.
pub struct ImpactData {
    /// Index of the site ([`RunData::contacts`], [`RunSummary::sites`]).
    pub contact: usize,
    /// Floors (left, right); 0 on a wall's side.
    pub floors: (usize, usize),
    /// Time of touch, s.
    pub time: f64,
    /// Relative velocity at touch, m/s.
    pub v_i: f64,
    /// The e its law was built to deliver between free bodies (`None`: an elastic law, or an older folder).
    pub e_asked: Option<f64>,
    /// Delivered e, if the impact ended.
    pub e_post: Option<f64>,
    /// Largest force, N.
    pub peak_force: f64,
    /// Time of the largest force, s.
    pub time_of_peak_force: f64,
    /// Duration, s.
    pub duration: f64,
    /// Energy dissipated, J.
    pub dissipated_energy: f64,
    /// Largest penetration, m.
    pub max_penetration: f64,
    /// An impact of the hard law behind a consumed bumper (layer `consumed`).
    pub consumed: bool,
    /// Which law of its site it is of: `direct`, a bumper's layer, or the hard law behind a consumed one.
    pub layer: pounding::analysis::Layer,
    /// Its level in the site ([`ContactData::elements`]).
    pub level: usize,
}

/// Everything a run wrote, read back.
pub struct RunData {
    /// summary.json.
    pub summary: RunSummary,
    /// The scenario file as run (scenario.toml), if present.
    pub scenario_text: Option<String>,
    /// One line: scenario, record, duration, impacts.
    pub subtitle: String,
    /// Output times, s.
    pub t: Vec<f64>,
    /// Ground acceleration, m/s^2, at `t`.
    pub ground_acceleration: Vec<f64>,
    /// Buildings, left to right.
    pub buildings: Vec<BuildingData>,
    /// Contact sites: contacts left to right, then walls.
    pub contacts: Vec<ContactData>,
    /// Devices.
    pub devices: Vec<DeviceData>,
    /// Every impact, in time order.
    pub impacts: Vec<ImpactData>,
    /// The force–penetration path of each impact that has one in impact-loops.csv.
    pub loops: Vec<LoopData>,
    /// Input, kinetic, strain, structural damping, hysteretic, contact energy, J, at `t`.
    pub energy: Vec<Vec<f64>>,
}

fn bad(dir: &Path, what: impl std::fmt::Display) -> CliError {
    CliError::Input(format!(
        "{}: {what} (give the --out folder of `pounding run`)",
        dir.display()
    ))
}

fn open(dir: &Path, name: &str) -> Result<std::io::BufReader<std::fs::File>, CliError> {
    std::fs::File::open(dir.join(name))
        .map(std::io::BufReader::new)
        .map_err(|e| bad(dir, format!("cannot read {name}: {e}")))
}

/// The rows of table `T` in `dir`.
fn rows<T: Table>(dir: &Path) -> Result<Vec<T>, CliError> {
    read_rows(open(dir, T::FILE)?).map_err(|e| bad(dir, e))
}

impl RunData {
    /// Reads the files `pounding run` wrote into `dir`.
    pub fn load(dir: &Path) -> Result<Self, CliError> {
        let text = std::fs::read_to_string(dir.join("summary.json"))
            .map_err(|e| bad(dir, format!("cannot read summary.json: {e}")))?;
        let summary =
            RunSummary::from_json(&text).map_err(|e| bad(dir, format!("summary.json: {e}")))?;
        let scenario_text = std::fs::read_to_string(dir.join("scenario.toml")).ok();
        let h = read_response(open(dir, "response.csv")?, &summary).map_err(|e| bad(dir, e))?;
        let impact_rows: Vec<ImpactRow> = rows(dir)?;
        let impacts = impact_rows
            .iter()
            .map(|r| {
                let (contact, level) = r.place(&summary).ok_or_else(|| {
                    bad(
                        dir,
                        format!(
                            "impacts.csv: no site {:?} with floors {:?}, {:?} in summary.json",
                            r.contact, r.floor_left, r.floor_right
                        ),
                    )
                })?;
                Ok(ImpactData {
                    contact,
                    floors: (r.floor_left.unwrap_or(0), r.floor_right.unwrap_or(0)),
                    time: r.time_s,
                    v_i: r.v_i_m_per_s,
                    e_asked: r.e_asked,
                    e_post: r.e_post,
                    peak_force: r.peak_force_n,
                    time_of_peak_force: r.time_of_peak_force_s,
                    duration: r.duration_s,
                    dissipated_energy: r.dissipated_energy_j,
                    max_penetration: r.max_penetration_m,
                    consumed: r.layer == pounding::analysis::Layer::Consumed,
                    layer: r.layer,
                    level,
                })
            })
            .collect::<Result<Vec<_>, CliError>>()?;
        let loops = if dir.join(LOOPS_FILE).is_file() {
            let rows: Vec<LoopRow> = rows(dir)?;
            let paths = LoopRow::paths(&rows);
            if let Some((k, _)) = paths.iter().find(|(k, _)| *k >= impacts.len()) {
                return Err(bad(
                    dir,
                    format!("{LOOPS_FILE}: impact {} is not a row of impacts.csv", k + 1),
                ));
            }
            paths
                .into_iter()
                .map(|(impact, l)| LoopData {
                    impact,
                    penetration: l.penetration,
                    force: l.force,
                })
                .collect()
        } else {
            Vec::new()
        };
        let energy_rows: Vec<EnergyRow> = rows(dir)?;
        let energy = (0..6)
            .map(|c| energy_rows.iter().map(|r| r.terms()[c]).collect())
            .collect();
        Ok(Self::assemble(
            summary,
            scenario_text,
            h,
            impacts,
            loops,
            energy,
        ))
    }

    /// The folder's contents grouped for the figures and the report.
    fn assemble(
        summary: RunSummary,
        scenario_text: Option<String>,
        h: pounding::analysis::Histories,
        impacts: Vec<ImpactData>,
        loops: Vec<LoopData>,
        energy: Vec<Vec<f64>>,
    ) -> Self {
        let buildings = summary
            .buildings
            .iter()
            .zip(h.displacement)
            .zip(h.storey_shear)
            .zip(h.displacement_y.into_iter().zip(h.rotation))
            .map(
                |(((b, floors), storey_shear), (floors_y, rotation))| BuildingData {
                    name: b.name.clone(),
                    floors,
                    storey_shear,
                    elevations: Some(b.elevations()),
                    floors_y,
                    rotation,
                },
            )
            .collect();
        let index = |name: &str| summary.buildings.iter().position(|b| b.name == name);
        let contacts = summary
            .sites
            .iter()
            .zip(h.site_force)
            .map(|(s, forces)| {
                let (left, right) = match &s.place {
                    SitePlace::Contact { between } => (index(&between[0]), index(&between[1])),
                    SitePlace::Wall { facing, side } if side.negative() => (None, index(facing)),
                    SitePlace::Wall { facing, .. } => (index(facing), None),
                };
                ContactData {
                    name: s.name.clone(),
                    left,
                    right,
                    wall: s.is_wall(),
                    gap: s.gap,
                    e: s.law.e,
                    elements: s
                        .levels
                        .iter()
                        .zip(forces)
                        .map(|(l, force)| ElementData {
                            floors: (l.left.unwrap_or(0), l.right.unwrap_or(0)),
                            force,
                        })
                        .collect(),
                }
            })
            .collect();
        let devices = summary
            .devices
            .iter()
            .zip(h.device_force)
            .map(|(d, forces)| DeviceData {
                name: d.name.clone(),
                model: d.law.name().to_string(),
                elements: d
                    .floors
                    .iter()
                    .zip(forces)
                    .map(|(&[a, b], force)| ElementData {
                        floors: (a, b),
                        force,
                    })
                    .collect(),
            })
            .collect();
        let scenario = &summary.scenario;
        let subtitle = format!(
            "{}: {} \u{d7} {}, {} s, {} impacts",
            Path::new(scenario)
                .file_name()
                .map_or(scenario.into(), |n| n.to_string_lossy()),
            file_name(&summary.record.source),
            fmt_num(summary.record.scale),
            fmt_num(summary.duration),
            impacts.iter().filter(|i| !i.consumed).count()
        );
        Self {
            summary,
            scenario_text,
            subtitle,
            t: h.t,
            ground_acceleration: h.ground_acceleration,
            buildings,
            contacts,
            devices,
            impacts,
            loops,
            energy,
        }
    }
}
