//! The output folder of `pounding run`, read back: what the figures and the report are made from, so that
//! `pounding report DIR` gives the same figures as `run --plots` did, from the files alone.

use crate::CliError;
use pounding::analysis::{Results, Scenario};
use serde_json::Value;
use std::fmt::Write as _;
use std::path::Path;

/// The file of every impact's force–penetration path, in a run's output folder.
pub const LOOPS_FILE: &str = "impact-loops.csv";

/// `impact-loops.csv`: one block of rows per impact, in the order of impacts.csv (`impact` is its row,
/// from 1), each row a point of the impact's path: its touch, the end of every accepted integration step in
/// contact and its located peak, in time order (t_s, s; penetration_m, m; force_N, N). `stride` is 1 when
/// every step is kept, `2^k` for an impact that outgrew [`pounding::analysis::MAX_LOOP_POINTS`] points.
pub fn impact_loops_csv(s: &Scenario, r: &Results) -> String {
    let mut out =
        String::from("impact,contact,floor_left,floor_right,stride,t_s,penetration_m,force_N\n");
    for (k, (i, l)) in r.impacts.iter().zip(&r.histories.impact_loops).enumerate() {
        let floor = |f: Option<usize>| f.map_or(String::new(), |f| f.to_string());
        let lv = s.sites()[i.site].levels[i.level];
        let (fl, fr) = (lv.left, lv.right);
        let head = format!(
            "{},{},{},{},{}",
            k + 1,
            s.sites()[i.site].name,
            floor(fl),
            floor(fr),
            l.stride
        );
        for ((t, d), f) in l.t.iter().zip(&l.penetration).zip(&l.force) {
            let _ = writeln!(out, "{head},{t:e},{d:e},{f:e}");
        }
    }
    out
}

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
    /// Times, s.
    pub t: Vec<f64>,
    /// Penetration, m.
    pub penetration: Vec<f64>,
    /// Contact force, N.
    pub force: Vec<f64>,
}

/// One building's histories, and its floor elevations if the scenario file gives them.
pub struct BuildingData {
    /// Name.
    pub name: String,
    /// Displacement relative to the ground of each floor (floor 1 first), m, at [`RunData::t`].
    pub floors: Vec<Vec<f64>>,
    /// Absolute acceleration of each floor (floor 1 first), m/s^2, at [`RunData::t`]. Read and checked
    /// with the other columns; no figure draws it yet (the envelopes use summary.json's located peaks).
    #[allow(dead_code)]
    pub absolute_acceleration: Vec<Vec<f64>>,
    /// Restoring force of each storey (storey 1 first), N, at [`RunData::t`].
    pub storey_shear: Vec<Vec<f64>>,
    /// Elevation of each floor above the ground (floor 1 first), m: the sums of the storey heights of
    /// scenario.toml; `None` if the folder has no readable scenario file naming this building.
    pub elevations: Option<Vec<f64>>,
}

/// One contact element (a pair of floors) of a contact.
pub struct ElementData {
    /// Floors (left, right), counted from 1.
    pub floors: (usize, usize),
    /// Contact force, N, at [`RunData::t`].
    pub force: Vec<f64>,
}

/// One contact between neighbouring buildings, or a wall beside a building.
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
    /// Coefficient of restitution the contact model was given.
    pub e: f64,
    /// Its elements (for a wall, floor pairs `(f, 0)` or `(0, f)`, the wall's side being 0).
    pub elements: Vec<ElementData>,
}

/// A contact or wall as summary.json gives it: name, left and right building, gap (m), e, floor pairs.
type ContactSpec = (
    String,
    Option<usize>,
    Option<usize>,
    f64,
    f64,
    Vec<(usize, usize)>,
);

/// One device, with the force of each floor pair.
pub struct DeviceData {
    /// Its name.
    pub name: String,
    /// `spring`, `dashpot`, `kelvin`, `maxwell` or `restrainer`.
    pub model: String,
    /// The force of each floor pair (N, positive pushing apart), at [`RunData::t`].
    pub elements: Vec<ElementData>,
}

/// One row of impacts.csv.
pub struct ImpactRow {
    /// Index of the contact.
    pub contact: usize,
    /// Floors (left, right).
    pub floors: (usize, usize),
    /// Time of touch, s.
    pub time: f64,
    /// Relative velocity at touch, m/s.
    pub v_i: f64,
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
}

/// Everything a run wrote, parsed.
pub struct RunData {
    /// summary.json.
    pub summary: Value,
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
    /// Contacts, left to right, then walls.
    pub contacts: Vec<ContactData>,
    /// Devices.
    pub devices: Vec<DeviceData>,
    /// Every impact, in time order.
    pub impacts: Vec<ImpactRow>,
    /// The force–penetration path of each impact that has one in impact-loops.csv (none for a folder
    /// written before that file existed).
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

fn read(dir: &Path, name: &str) -> Result<String, CliError> {
    std::fs::read_to_string(dir.join(name))
        .map_err(|e| bad(dir, format!("cannot read {name}: {e}")))
}

/// A CSV table of numbers (empty cells and `true`/`false` kept as text): header and rows of cells.
fn csv(dir: &Path, name: &str) -> Result<(Vec<String>, Vec<Vec<String>>), CliError> {
    let text = read(dir, name)?;
    let mut lines = text.lines();
    let header: Vec<String> = lines
        .next()
        .ok_or_else(|| bad(dir, format!("{name} is empty")))?
        .split(',')
        .map(String::from)
        .collect();
    let rows: Vec<Vec<String>> = lines
        .filter(|l| !l.is_empty())
        .map(|l| l.split(',').map(String::from).collect())
        .collect();
    if let Some((k, _)) = rows
        .iter()
        .enumerate()
        .find(|(_, r)| r.len() != header.len())
    {
        return Err(bad(
            dir,
            format!("{name} line {}: wrong number of columns", k + 2),
        ));
    }
    Ok((header, rows))
}

fn number(dir: &Path, name: &str, cell: &str) -> Result<f64, CliError> {
    cell.parse::<f64>()
        .ok()
        .filter(|x| x.is_finite())
        .ok_or_else(|| bad(dir, format!("{name}: {cell:?} is not a number")))
}

/// Column `k` of `rows` as numbers.
fn column(dir: &Path, name: &str, rows: &[Vec<String>], k: usize) -> Result<Vec<f64>, CliError> {
    rows.iter().map(|r| number(dir, name, &r[k])).collect()
}

/// The storey heights (m) of every `[[building]]` of a scenario file that has a name and positive heights;
/// nothing for a file that does not parse (the figures then count floors instead).
fn storey_heights(text: &str) -> Vec<(String, Vec<f64>)> {
    let Ok(file) = text.parse::<toml::Table>() else {
        return Vec::new();
    };
    let buildings = file.get("building").and_then(toml::Value::as_array);
    buildings
        .into_iter()
        .flatten()
        .filter_map(|b| {
            let name = b.get("name")?.as_str()?.to_string();
            let heights = b
                .get("heights")?
                .as_array()?
                .iter()
                .map(|h| {
                    h.as_float()
                        .or_else(|| h.as_integer().map(|i| i as f64))
                        .filter(|h| h.is_finite() && *h > 0.0)
                })
                .collect::<Option<Vec<f64>>>()?;
            Some((name, heights))
        })
        .collect()
}

/// The paths of impact-loops.csv, checked against the number of impacts.
fn read_loops(dir: &Path, impacts: usize) -> Result<Vec<LoopData>, CliError> {
    let (header, rows) = csv(dir, LOOPS_FILE)?;
    let col = |name: &str| {
        header
            .iter()
            .position(|h| h == name)
            .ok_or_else(|| bad(dir, format!("{LOOPS_FILE} has no column {name}")))
    };
    let [ki, kt, kd, kf] = [
        col("impact")?,
        col("t_s")?,
        col("penetration_m")?,
        col("force_N")?,
    ];
    let mut loops: Vec<LoopData> = Vec::new();
    for r in &rows {
        let x = |k: usize| number(dir, LOOPS_FILE, &r[k]);
        let i = x(ki)? as usize;
        if i == 0 || i > impacts {
            return Err(bad(
                dir,
                format!("{LOOPS_FILE}: impact {i} is not a row of impacts.csv"),
            ));
        }
        if loops.last().is_none_or(|l| l.impact != i - 1) {
            loops.push(LoopData {
                impact: i - 1,
                t: Vec::new(),
                penetration: Vec::new(),
                force: Vec::new(),
            });
        }
        let l = loops.last_mut().expect("a block");
        l.t.push(x(kt)?);
        l.penetration.push(x(kd)?);
        l.force.push(x(kf)?);
    }
    Ok(loops)
}

impl RunData {
    /// Reads the files `pounding run` wrote into `dir`.
    pub fn load(dir: &Path) -> Result<Self, CliError> {
        let summary: Value = serde_json::from_str(&read(dir, "summary.json")?)
            .map_err(|e| bad(dir, format!("summary.json: {e}")))?;
        let scenario_text = std::fs::read_to_string(dir.join("scenario.toml")).ok();
        let list = |key: &str| summary[key].as_array().cloned().unwrap_or_default();

        let (header, rows) = csv(dir, "response.csv")?;
        let t = column(dir, "response.csv", &rows, 0)?;
        let ground_acceleration = column(dir, "response.csv", &rows, 1)?;
        let mut k = 2;
        let mut expect = |col: &str| -> Result<usize, CliError> {
            match header.get(k) {
                Some(h) if h == col => {
                    k += 1;
                    Ok(k - 1)
                }
                other => Err(bad(
                    dir,
                    format!(
                        "response.csv: column {} is {other:?}, expected {col:?}",
                        k + 1
                    ),
                )),
            }
        };
        let mut names = Vec::new();
        let mut storeys = Vec::new();
        let mut columns = Vec::new();
        for b in list("buildings") {
            let name = b["name"].as_str().unwrap_or_default().to_string();
            let n = b["storeys"].as_u64().unwrap_or(0) as usize;
            let mut cols = Vec::new();
            for f in 1..=n {
                cols.push(expect(&format!("{name}_floor{f}_displacement_m"))?);
            }
            names.push(name);
            storeys.push(n);
            columns.push(cols);
        }
        let mut contacts = Vec::new();
        let mut contact_columns = Vec::new();
        for c in list("contacts") {
            let between: Vec<String> = c["between"]
                .as_array()
                .map(|a| {
                    a.iter()
                        .filter_map(|v| v.as_str().map(String::from))
                        .collect()
                })
                .unwrap_or_default();
            let (Some(left), Some(right)) = (
                between
                    .first()
                    .and_then(|n| names.iter().position(|x| x == n)),
                between
                    .get(1)
                    .and_then(|n| names.iter().position(|x| x == n)),
            ) else {
                return Err(bad(
                    dir,
                    "summary.json: a contact names an unknown building",
                ));
            };
            let name = format!("{}|{}", names[left], names[right]);
            let (left, right) = (Some(left), Some(right));
            let mut elements = Vec::new();
            for pair in c["floors"].as_array().cloned().unwrap_or_default() {
                let f = |i: usize| pair[i].as_u64().unwrap_or(0) as usize;
                let floors = (f(0), f(1));
                contact_columns.push(expect(&format!(
                    "{name}_floors{}-{}_force_N",
                    floors.0, floors.1
                ))?);
                elements.push(floors);
            }
            let (gap, e) = (
                c["gap"].as_f64().unwrap_or(0.0),
                c["e"].as_f64().unwrap_or(1.0),
            );
            contacts.push((name, left, right, gap, e, elements));
        }
        for w in list("walls") {
            let name = w["name"].as_str().unwrap_or_default().to_string();
            let Some(b) = w["facing"]
                .as_str()
                .and_then(|n| names.iter().position(|x| x == n))
            else {
                return Err(bad(dir, "summary.json: a wall faces an unknown building"));
            };
            let right_side = w["side"].as_str() == Some("right");
            let (left, right) = if right_side {
                (Some(b), None)
            } else {
                (None, Some(b))
            };
            let mut elements = Vec::new();
            for f in w["floors"].as_array().cloned().unwrap_or_default() {
                let f = f.as_u64().unwrap_or(0) as usize;
                contact_columns.push(expect(&format!("{name}_floor{f}_force_N"))?);
                elements.push(if right_side { (f, 0) } else { (0, f) });
            }
            let (gap, e) = (
                w["gap"].as_f64().unwrap_or(0.0),
                w["e"].as_f64().unwrap_or(1.0),
            );
            contacts.push((name, left, right, gap, e, elements));
        }
        let mut device_specs = Vec::new();
        let mut device_columns = Vec::new();
        for d in list("devices") {
            let name = d["name"].as_str().unwrap_or_default().to_string();
            let model = d["law"]["model"].as_str().unwrap_or_default().to_string();
            let mut pairs = Vec::new();
            for pair in d["floors"].as_array().cloned().unwrap_or_default() {
                let f = |i: usize| pair[i].as_u64().unwrap_or(0) as usize;
                device_columns.push(expect(&format!("{name}_floors{}-{}_force_N", f(0), f(1)))?);
                pairs.push((f(0), f(1)));
            }
            device_specs.push((name, model, pairs));
        }
        // Then every building's floor accelerations, then every building's storey shears.
        let mut acceleration_columns = Vec::new();
        for (name, &n) in names.iter().zip(&storeys) {
            let cols = (1..=n)
                .map(|f| expect(&format!("{name}_floor{f}_absolute_acceleration_m_per_s2")))
                .collect::<Result<Vec<_>, CliError>>()?;
            acceleration_columns.push(cols);
        }
        let mut shear_columns = Vec::new();
        for (name, &n) in names.iter().zip(&storeys) {
            let cols = (1..=n)
                .map(|j| expect(&format!("{name}_storey{j}_shear_N")))
                .collect::<Result<Vec<_>, CliError>>()?;
            shear_columns.push(cols);
        }
        let heights = scenario_text.as_deref().map(storey_heights);
        let columns_of = |cols: &[usize]| {
            cols.iter()
                .map(|&k| column(dir, "response.csv", &rows, k))
                .collect::<Result<Vec<_>, CliError>>()
        };
        let mut buildings = Vec::new();
        for (b, name) in names.iter().enumerate() {
            let elevations = heights
                .as_ref()
                .and_then(|h| h.iter().find(|(n, _)| n == name))
                .map(|(_, h)| h)
                .filter(|h| h.len() == storeys[b])
                .map(|h| {
                    h.iter()
                        .scan(0.0, |z, dz| {
                            *z += dz;
                            Some(*z)
                        })
                        .collect()
                });
            buildings.push(BuildingData {
                name: name.clone(),
                floors: columns_of(&columns[b])?,
                absolute_acceleration: columns_of(&acceleration_columns[b])?,
                storey_shear: columns_of(&shear_columns[b])?,
                elevations,
            });
        }
        let mut cc = contact_columns.into_iter();
        let contacts = contacts
            .into_iter()
            .map(|(name, left, right, gap, e, els): ContactSpec| {
                let elements = els
                    .into_iter()
                    .map(|floors| {
                        let k = cc.next().expect("one column per element");
                        Ok(ElementData {
                            floors,
                            force: column(dir, "response.csv", &rows, k)?,
                        })
                    })
                    .collect::<Result<_, CliError>>()?;
                Ok(ContactData {
                    wall: left.is_none() || right.is_none(),
                    name,
                    left,
                    right,
                    gap,
                    e,
                    elements,
                })
            })
            .collect::<Result<Vec<_>, CliError>>()?;
        let mut dc = device_columns.into_iter();
        let devices = device_specs
            .into_iter()
            .map(|(name, model, pairs)| {
                let elements = pairs
                    .into_iter()
                    .map(|floors| {
                        let k = dc.next().expect("one column per pair");
                        Ok(ElementData {
                            floors,
                            force: column(dir, "response.csv", &rows, k)?,
                        })
                    })
                    .collect::<Result<_, CliError>>()?;
                Ok(DeviceData {
                    name,
                    model,
                    elements,
                })
            })
            .collect::<Result<Vec<_>, CliError>>()?;

        let (header, rows) = csv(dir, "impacts.csv")?;
        let col = |name: &str| {
            header
                .iter()
                .position(|h| h == name)
                .ok_or_else(|| bad(dir, format!("impacts.csv has no column {name}")))
        };
        let [time, v_i, peak, t_peak, dur, diss, pen, fl, fr, contact_col, e_col] = [
            col("time_s")?,
            col("v_i_m_per_s")?,
            col("peak_force_N")?,
            col("time_of_peak_force_s")?,
            col("duration_s")?,
            col("dissipated_energy_J")?,
            col("max_penetration_m")?,
            col("floor_left")?,
            col("floor_right")?,
            col("contact")?,
            col("e_post")?,
        ];
        let layer = header.iter().position(|h| h == "layer");
        let mut impacts = Vec::new();
        for r in &rows {
            let x = |k: usize| number(dir, "impacts.csv", &r[k]);
            // A wall's side has no floor: blank in impacts.csv, 0 here.
            let floor = |k: usize| {
                if r[k].is_empty() {
                    Ok(0)
                } else {
                    x(k).map(|v| v as usize)
                }
            };
            let contact = contacts
                .iter()
                .position(|c| c.name == r[contact_col])
                .ok_or_else(|| {
                    bad(
                        dir,
                        format!("impacts.csv: unknown contact {:?}", r[contact_col]),
                    )
                })?;
            impacts.push(ImpactRow {
                contact,
                floors: (floor(fl)?, floor(fr)?),
                time: x(time)?,
                v_i: x(v_i)?,
                e_post: if r[e_col].is_empty() {
                    None
                } else {
                    Some(x(e_col)?)
                },
                peak_force: x(peak)?,
                time_of_peak_force: x(t_peak)?,
                duration: x(dur)?,
                dissipated_energy: x(diss)?,
                max_penetration: x(pen)?,
                consumed: layer.is_some_and(|k| r[k] == "consumed"),
            });
        }

        let loops = if dir.join(LOOPS_FILE).is_file() {
            read_loops(dir, impacts.len())?
        } else {
            Vec::new()
        };

        let (_, rows) = csv(dir, "energy.csv")?;
        let energy = (1..=6)
            .map(|k| column(dir, "energy.csv", &rows, k))
            .collect::<Result<Vec<_>, CliError>>()?;

        let scenario = summary["scenario"].as_str().unwrap_or("scenario");
        let rec = &summary["record"];
        let subtitle = format!(
            "{}: {} \u{d7} {}, {} s, {} impacts",
            Path::new(scenario)
                .file_name()
                .map_or(scenario.into(), |n| n.to_string_lossy()),
            file_name(rec["source"].as_str().unwrap_or("record")),
            crate::output::fmt_num(rec["scale"].as_f64().unwrap_or(1.0)),
            crate::output::fmt_num(summary["duration"].as_f64().unwrap_or(0.0)),
            impacts.iter().filter(|i| !i.consumed).count()
        );
        Ok(Self {
            summary,
            scenario_text,
            subtitle,
            t,
            ground_acceleration,
            buildings,
            contacts,
            devices,
            impacts,
            loops,
            energy,
        })
    }
}
