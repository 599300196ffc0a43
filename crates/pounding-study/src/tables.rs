//! The tables of a run's output folder, one row type each, written and read by the `csv` crate (fields with
//! commas, quotes or line breaks are quoted; numbers are written in their shortest round-trip form):
//!
//! - `impacts.csv`: one [`ImpactRow`] per impact;
//! - `impact-loops.csv`: one [`LoopRow`] per point of each impact's force–penetration path;
//! - `energy.csv`: one [`EnergyRow`] per output time;
//! - `response.csv`: the histories, one column per [`Column`] (their names come from the summary, so a
//!   table is read back against the summary it belongs to, never by guessing names).
//!
//! Writers take any [`std::io::Write`] and readers any [`std::io::Read`]: opening files is the caller's.

use crate::format::{push_time, Shortest};
use crate::summary::{RunSummary, SitePlace};
use pounding::analysis::{Histories, ImpactLoop, Layer, Results, Scenario};
use pounding::contact::exact;
use serde::{Deserialize, Serialize};
use std::io::{Read, Write};

/// A table that could not be written (the writer's I/O error) or read (what does not fit, one line).
#[derive(Debug)]
pub enum TableError {
    /// Writing failed.
    Io(std::io::Error),
    /// The table does not read as it should.
    Invalid(String),
}

impl std::fmt::Display for TableError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            TableError::Io(e) => e.fmt(f),
            TableError::Invalid(m) => f.write_str(m),
        }
    }
}

impl From<csv::Error> for TableError {
    fn from(e: csv::Error) -> Self {
        if e.is_io_error() {
            if let csv::ErrorKind::Io(io) = e.into_kind() {
                return TableError::Io(io);
            }
            unreachable!("an I/O error's kind is Io");
        }
        TableError::Invalid(e.to_string())
    }
}

impl From<std::io::Error> for TableError {
    fn from(e: std::io::Error) -> Self {
        TableError::Io(e)
    }
}

/// One impact (a row of `impacts.csv`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ImpactRow {
    /// Time of touch, s.
    pub time_s: f64,
    /// The site's name (`left|right`, or a wall's name).
    pub contact: String,
    /// Floor of the left building, from 1 (blank on a wall's side).
    pub floor_left: Option<usize>,
    /// Floor of the right building, from 1 (blank on a wall's side).
    pub floor_right: Option<usize>,
    /// Which law: `direct`, `bumper` or `consumed`.
    pub layer: Layer,
    /// Relative velocity at touch, m/s.
    pub v_i_m_per_s: f64,
    /// The coefficient of restitution its law was built to deliver between two free bodies: the contact's
    /// `e`, its table read at `v_i`, its damping constant's `e` at `v_i`, or Thornton's spheres' `e` at `v_i`
    /// and the level's effective mass (`v_i` floored at the smallest impact velocity, as the law was); blank
    /// for an elastic law (and in folders written before it).
    #[serde(default)]
    pub e_asked: Option<f64>,
    /// Delivered coefficient of restitution `-v_out / v_i` (blank if the impact had not ended, or rested).
    pub e_post: Option<f64>,
    /// Largest contact force, N: on a bumper's layer the whole force on the face (the bumper and, once it is
    /// consumed, the hard law behind it), so that the largest over a site's rows is its peak; on a consumed
    /// row the hard law's own.
    #[serde(rename = "peak_force_N")]
    pub peak_force_n: f64,
    /// Time of the largest force, s.
    pub time_of_peak_force_s: f64,
    /// Duration of contact, s.
    pub duration_s: f64,
    /// Work of the contact force over the impact, J.
    #[serde(rename = "dissipated_energy_J")]
    pub dissipated_energy_j: f64,
    /// Largest penetration, m.
    pub max_penetration_m: f64,
    /// Whether the impact had ended before the analysis stopped.
    pub ended: bool,
    /// A resting contact (closing slower than the smallest impact velocity).
    pub resting: bool,
    /// Between buildings in plan: the x of the impact's point at rest, m (blank in one line).
    #[serde(default)]
    pub point_x_m: Option<f64>,
    /// Between buildings in plan: the y of the impact's point at rest, m (blank in one line).
    #[serde(default)]
    pub point_y_m: Option<f64>,
}

impl ImpactRow {
    /// The rows of every impact of `r`, in time order.
    pub fn all(s: &Scenario, r: &Results) -> Vec<ImpactRow> {
        r.impacts
            .iter()
            .map(|i| {
                let site = &s.sites()[i.site];
                let level = site.levels[i.level];
                // The law of this impact: the bumper's layer, or the site's own (behind a consumed bumper too).
                let law = match (i.layer, &site.bumper) {
                    (Layer::Bumper, Some(b)) => &b.contact,
                    _ => &site.contact,
                };
                let v_law = i.v_i.max(s.min_impact_velocity());
                // A law asked no e but not elastic (Thornton's spheres): the e it delivers at this v_i.
                let own = || {
                    let m = s.effective_mass(site, i.level);
                    let (l, _) = law.law(m, v_law).ok()?;
                    exact::e_post(&l, law.spec().tension(), m, v_law)
                        .filter(|_| law.spec().sphere().is_some())
                };
                ImpactRow {
                    time_s: i.time,
                    contact: site.name.clone(),
                    floor_left: level.left,
                    floor_right: level.right,
                    layer: i.layer,
                    v_i_m_per_s: i.v_i,
                    e_asked: law.spec().asked().map(|r| r.at(v_law)).or_else(own),
                    e_post: i.e_post,
                    peak_force_n: i.peak_force,
                    time_of_peak_force_s: i.time_of_peak_force,
                    duration_s: i.duration,
                    dissipated_energy_j: i.dissipated_energy,
                    max_penetration_m: i.max_penetration,
                    ended: i.ended,
                    resting: i.resting,
                    point_x_m: site.plan.as_ref().map(|p| p.points[i.level].0),
                    point_y_m: site.plan.as_ref().map(|p| p.points[i.level].1),
                }
            })
            .collect()
    }

    /// The index of its site in `summary.sites`, and of its level.
    pub fn place(&self, summary: &RunSummary) -> Option<(usize, usize)> {
        let site = summary.sites.iter().position(|s| s.name == self.contact)?;
        let st = &summary.sites[site];
        // In plan, a floor pair has a level per point.
        let point = |k: usize| match (&st.points, self.point_x_m, self.point_y_m) {
            (Some(p), Some(x), Some(y)) => p[k] == [x, y],
            _ => true,
        };
        let level = (0..st.levels.len()).position(|k| {
            let l = st.levels[k];
            l.left == self.floor_left && l.right == self.floor_right && point(k)
        })?;
        Some((site, level))
    }
}

/// One point of an impact's force–penetration path (a row of `impact-loops.csv`): its touch, the end of
/// every accepted integration step in contact and its located peak, in time order.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct LoopRow {
    /// The impact: its row in `impacts.csv`, from 1.
    pub impact: usize,
    /// The site's name.
    pub contact: String,
    /// Floor of the left building (blank on a wall's side).
    pub floor_left: Option<usize>,
    /// Floor of the right building (blank on a wall's side).
    pub floor_right: Option<usize>,
    /// 1 when every step is kept; `2^k` for an impact that outgrew the cap on points.
    pub stride: usize,
    /// Time, s.
    pub t_s: f64,
    /// Penetration, m.
    pub penetration_m: f64,
    /// Contact force, N.
    #[serde(rename = "force_N")]
    pub force_n: f64,
}

impl LoopRow {
    /// The rows of every impact's path of `r` (in the order of its impacts).
    pub fn all(s: &Scenario, r: &Results) -> Vec<LoopRow> {
        let mut out = Vec::new();
        for (k, (i, l)) in r.impacts.iter().zip(&r.histories.impact_loops).enumerate() {
            let site = &s.sites()[i.site];
            let level = site.levels[i.level];
            for ((&t, &d), &f) in l.t.iter().zip(&l.penetration).zip(&l.force) {
                out.push(LoopRow {
                    impact: k + 1,
                    contact: site.name.clone(),
                    floor_left: level.left,
                    floor_right: level.right,
                    stride: l.stride,
                    t_s: t,
                    penetration_m: d,
                    force_n: f,
                });
            }
        }
        out
    }

    /// The paths of `rows`, impact by impact: `(impact index from 0, its path)`.
    pub fn paths(rows: &[LoopRow]) -> Vec<(usize, ImpactLoop)> {
        let mut out: Vec<(usize, ImpactLoop)> = Vec::new();
        for r in rows {
            let k = r.impact.saturating_sub(1);
            if out.last().is_none_or(|(i, _)| *i != k) {
                out.push((
                    k,
                    ImpactLoop {
                        stride: r.stride,
                        ..ImpactLoop::default()
                    },
                ));
            }
            let l = &mut out.last_mut().expect("a path").1;
            l.t.push(r.t_s);
            l.penetration.push(r.penetration_m);
            l.force.push(r.force_n);
        }
        out
    }
}

/// The energies at one output time (a row of `energy.csv`), J.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[allow(non_snake_case)]
pub struct EnergyRow {
    /// Time, s (an output time `k dt`, written to 12 significant digits).
    #[serde(serialize_with = "output_time")]
    pub time_s: f64,
    /// Input energy, J.
    pub input_J: f64,
    /// Kinetic energy, J.
    pub kinetic_J: f64,
    /// Recoverable strain energy, J.
    pub strain_J: f64,
    /// Viscous damping, J.
    pub structural_damping_J: f64,
    /// Hysteretic dissipation, J.
    pub hysteretic_J: f64,
    /// Contact work, J.
    pub contact_J: f64,
    /// `input - kinetic - strain - damping - hysteretic - contact`, J.
    pub balance_error_J: f64,
}

impl EnergyRow {
    /// The rows of the histories `h`.
    pub fn all(h: &Histories) -> Vec<EnergyRow> {
        (0..h.t.len())
            .map(|k| {
                let e: [f64; 6] = std::array::from_fn(|c| h.energy[c][k]);
                EnergyRow {
                    time_s: h.t[k],
                    input_J: e[0],
                    kinetic_J: e[1],
                    strain_J: e[2],
                    structural_damping_J: e[3],
                    hysteretic_J: e[4],
                    contact_J: e[5],
                    balance_error_J: e[0] - e[1..].iter().sum::<f64>(),
                }
            })
            .collect()
    }

    /// The six energies, J: input, kinetic, strain, damping, hysteretic, contact.
    pub fn terms(&self) -> [f64; 6] {
        [
            self.input_J,
            self.kinetic_J,
            self.strain_J,
            self.structural_damping_J,
            self.hysteretic_J,
            self.contact_J,
        ]
    }
}

/// A row type of a table, with its header (the names of its fields, with their units).
pub trait Table: Serialize + for<'de> Deserialize<'de> {
    /// The file the table is (`impacts.csv`).
    const FILE: &'static str;
    /// Its header, column by column.
    const HEADER: &'static [&'static str];
}

impl Table for ImpactRow {
    const FILE: &'static str = "impacts.csv";
    const HEADER: &'static [&'static str] = &[
        "time_s",
        "contact",
        "floor_left",
        "floor_right",
        "layer",
        "v_i_m_per_s",
        "e_asked",
        "e_post",
        "peak_force_N",
        "time_of_peak_force_s",
        "duration_s",
        "dissipated_energy_J",
        "max_penetration_m",
        "ended",
        "resting",
        "point_x_m",
        "point_y_m",
    ];
}

impl Table for LoopRow {
    const FILE: &'static str = "impact-loops.csv";
    const HEADER: &'static [&'static str] = &[
        "impact",
        "contact",
        "floor_left",
        "floor_right",
        "stride",
        "t_s",
        "penetration_m",
        "force_N",
    ];
}

impl Table for EnergyRow {
    const FILE: &'static str = "energy.csv";
    const HEADER: &'static [&'static str] = &[
        "time_s",
        "input_J",
        "kinetic_J",
        "strain_J",
        "structural_damping_J",
        "hysteretic_J",
        "contact_J",
        "balance_error_J",
    ];
}

/// An output time `k dt` to 12 significant digits, as `energy.csv` and `response.csv` write it.
fn output_time<S: serde::Serializer>(t: &f64, s: S) -> Result<S::Ok, S::Error> {
    let mut text = Vec::with_capacity(24);
    push_time(&mut text, *t);
    // push_time writes ASCII only.
    s.serialize_str(&String::from_utf8_lossy(&text))
}

/// Writes `rows` as a CSV table under its header.
pub fn write_rows<T: Table>(w: impl Write, rows: &[T]) -> Result<(), TableError> {
    let mut wtr = csv::WriterBuilder::new().has_headers(false).from_writer(w);
    wtr.write_record(T::HEADER)?;
    for r in rows {
        wtr.serialize(r)?;
    }
    wtr.flush()?;
    Ok(())
}

/// Reads a CSV table of rows of `T`, under its header.
pub fn read_rows<T: Table>(r: impl Read) -> Result<Vec<T>, TableError> {
    let mut rdr = csv::ReaderBuilder::new().has_headers(true).from_reader(r);
    let header = rdr.headers()?.clone();
    // A folder written before the last columns were added reads with them blank.
    let older = header.len() < T::HEADER.len() && header.len() >= 2;
    if header
        .iter()
        .ne(T::HEADER.iter().copied().take(header.len()))
        || (!older && header.len() != T::HEADER.len())
    {
        return Err(TableError::Invalid(format!(
            "{}: the header is not {}",
            T::FILE,
            T::HEADER.join(",")
        )));
    }
    let mut out = Vec::new();
    for (k, row) in rdr.deserialize().enumerate() {
        out.push(row.map_err(|e| TableError::Invalid(format!("{}: row {}: {e}", T::FILE, k + 1)))?);
    }
    Ok(out)
}

/// A column of `response.csv`: floors, storeys, levels and pairs counted from 0 here, from 1 in its name.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Column {
    /// Time, s.
    Time,
    /// Ground acceleration, m/s^2.
    GroundAcceleration,
    /// A floor's displacement relative to the ground, m.
    Displacement {
        /// Index of the building.
        building: usize,
        /// Index of the floor.
        floor: usize,
    },
    /// The contact force of a site's level, N.
    SiteForce {
        /// Index of the site.
        site: usize,
        /// Index of the level.
        level: usize,
    },
    /// The force of a device's floor pair (elastic and viscous), N.
    DeviceForce {
        /// Index of the device.
        device: usize,
        /// Index of the floor pair.
        pair: usize,
    },
    /// A floor's absolute acceleration, m/s^2.
    AbsoluteAcceleration {
        /// Index of the building.
        building: usize,
        /// Index of the floor.
        floor: usize,
    },
    /// A storey's restoring force, N.
    StoreyShear {
        /// Index of the building.
        building: usize,
        /// Index of the storey.
        storey: usize,
    },
    /// Ground acceleration along y, m/s^2.
    GroundAccelerationY,
    /// A floor in plan's mass centre along y, m.
    DisplacementY {
        /// Index of the building.
        building: usize,
        /// Index of the floor.
        floor: usize,
    },
    /// A floor in plan's rotation, rad.
    Rotation {
        /// Index of the building.
        building: usize,
        /// Index of the floor.
        floor: usize,
    },
    /// A foundation's sway (`part` 0, m) or rocking (`part` 1, rad).
    Foundation {
        /// Index of the building.
        building: usize,
        /// 0: sway, 1: rocking.
        part: usize,
    },
}

impl Column {
    /// The columns of `response.csv` of a run summarised by `s`, in order: time, ground acceleration,
    /// displacements, site forces, device forces, absolute accelerations, storey shears.
    pub fn all(s: &RunSummary) -> Vec<Column> {
        let mut out = vec![Column::Time, Column::GroundAcceleration];
        let floors = |b: &crate::summary::BuildingSummary| 0..b.storeys;
        for (building, b) in s.buildings.iter().enumerate() {
            out.extend(floors(b).map(|floor| Column::Displacement { building, floor }));
        }
        for (site, st) in s.sites.iter().enumerate() {
            out.extend((0..st.levels.len()).map(|level| Column::SiteForce { site, level }));
        }
        for (device, d) in s.devices.iter().enumerate() {
            out.extend((0..d.floors.len()).map(|pair| Column::DeviceForce { device, pair }));
        }
        for (building, b) in s.buildings.iter().enumerate() {
            out.extend(floors(b).map(|floor| Column::AbsoluteAcceleration { building, floor }));
        }
        for (building, b) in s.buildings.iter().enumerate() {
            out.extend(floors(b).map(|storey| Column::StoreyShear { building, storey }));
        }
        // Buildings in plan and a ground along y: after the columns of a row in one line.
        if s.record_y.is_some() {
            out.push(Column::GroundAccelerationY);
        }
        for (building, b) in s.buildings.iter().enumerate() {
            if b.plan.is_some() {
                out.extend(floors(b).map(|floor| Column::DisplacementY { building, floor }));
                out.extend(floors(b).map(|floor| Column::Rotation { building, floor }));
            }
        }
        for (building, b) in s.buildings.iter().enumerate() {
            if b.foundation.is_some() {
                out.extend((0..2).map(|part| Column::Foundation { building, part }));
            }
        }
        out
    }

    /// Its name in the header, with its unit.
    pub fn header(&self, s: &RunSummary) -> String {
        match *self {
            Column::Time => "time_s".into(),
            Column::GroundAcceleration => "ground_acceleration_m_per_s2".into(),
            Column::Displacement { building, floor } => format!(
                "{}_floor{}_displacement_m",
                s.buildings[building].name,
                floor + 1
            ),
            Column::SiteForce { site, level } => {
                let st = &s.sites[site];
                let l = st.levels[level];
                // In plan, the point along the façades too: `_y10` for y = 10 m.
                let at = match (&st.normal, &st.points) {
                    (Some(n), Some(p)) if n[0] != 0.0 => format!("_y{}", p[level][1]),
                    (Some(_), Some(p)) => format!("_x{}", p[level][0]),
                    _ => String::new(),
                };
                match st.place {
                    SitePlace::Contact { .. } => format!(
                        "{}_floors{}-{}{at}_force_N",
                        st.name,
                        l.left.unwrap_or(0),
                        l.right.unwrap_or(0)
                    ),
                    SitePlace::Wall { .. } => format!(
                        "{}_floor{}{at}_force_N",
                        st.name,
                        l.left.or(l.right).unwrap_or(0)
                    ),
                }
            }
            Column::DeviceForce { device, pair } => {
                let d = &s.devices[device];
                let [i, j] = d.floors[pair];
                format!("{}_floors{i}-{j}_force_N", d.name)
            }
            Column::AbsoluteAcceleration { building, floor } => format!(
                "{}_floor{}_absolute_acceleration_m_per_s2",
                s.buildings[building].name,
                floor + 1
            ),
            Column::StoreyShear { building, storey } => format!(
                "{}_storey{}_shear_N",
                s.buildings[building].name,
                storey + 1
            ),
            Column::GroundAccelerationY => "ground_acceleration_y_m_per_s2".into(),
            Column::DisplacementY { building, floor } => format!(
                "{}_floor{}_displacement_y_m",
                s.buildings[building].name,
                floor + 1
            ),
            Column::Rotation { building, floor } => format!(
                "{}_floor{}_rotation_rad",
                s.buildings[building].name,
                floor + 1
            ),
            Column::Foundation { building, part } => format!(
                "{}_foundation_{}",
                s.buildings[building].name,
                ["sway_m", "rocking_rad"][part]
            ),
        }
    }

    /// Its values in `h`.
    fn values<'h>(&self, h: &'h Histories) -> &'h [f64] {
        match *self {
            Column::Time => &h.t,
            Column::GroundAcceleration => &h.ground_acceleration,
            Column::Displacement { building, floor } => &h.displacement[building][floor],
            Column::SiteForce { site, level } => &h.site_force[site][level],
            Column::DeviceForce { device, pair } => &h.device_force[device][pair],
            Column::AbsoluteAcceleration { building, floor } => {
                &h.absolute_acceleration[building][floor]
            }
            Column::StoreyShear { building, storey } => &h.storey_shear[building][storey],
            Column::GroundAccelerationY => &h.ground_acceleration_y,
            Column::DisplacementY { building, floor } => &h.displacement_y[building][floor],
            Column::Rotation { building, floor } => &h.rotation[building][floor],
            Column::Foundation { building, part } => &h.foundation[building][part],
        }
    }

    /// Its values in `h`, to fill.
    fn values_mut<'h>(&self, h: &'h mut Histories) -> &'h mut Vec<f64> {
        match *self {
            Column::Time => &mut h.t,
            Column::GroundAcceleration => &mut h.ground_acceleration,
            Column::Displacement { building, floor } => &mut h.displacement[building][floor],
            Column::SiteForce { site, level } => &mut h.site_force[site][level],
            Column::DeviceForce { device, pair } => &mut h.device_force[device][pair],
            Column::AbsoluteAcceleration { building, floor } => {
                &mut h.absolute_acceleration[building][floor]
            }
            Column::StoreyShear { building, storey } => &mut h.storey_shear[building][storey],
            Column::GroundAccelerationY => &mut h.ground_acceleration_y,
            Column::DisplacementY { building, floor } => &mut h.displacement_y[building][floor],
            Column::Rotation { building, floor } => &mut h.rotation[building][floor],
            Column::Foundation { building, part } => &mut h.foundation[building][part],
        }
    }
}

/// Writes `response.csv` of the histories `h` of a run summarised by `s`.
pub fn write_response(w: impl Write, s: &RunSummary, h: &Histories) -> Result<(), TableError> {
    let columns = Column::all(s);
    let header: Vec<String> = columns.iter().map(|c| c.header(s)).collect();
    let values: Vec<&[f64]> = columns[1..].iter().map(|c| c.values(h)).collect();
    write_numbers(w, &header, &h.t, &values)
}

/// Writes `energy.csv` of the histories `h`: the rows of [`EnergyRow::all`], without building them.
pub fn write_energy(w: impl Write, h: &Histories) -> Result<(), TableError> {
    let balance: Vec<f64> = (0..h.t.len())
        .map(|k| h.energy[0][k] - h.energy[1..].iter().map(|e| e[k]).sum::<f64>())
        .collect();
    let mut values: Vec<&[f64]> = h.energy.iter().map(|e| e.as_slice()).collect();
    values.push(&balance);
    write_numbers(w, EnergyRow::HEADER, &h.t, &values)
}

/// Writes a table of numbers: the header (quoted where a name needs it), then one row per output time `t[k]`
/// (12 significant digits, as [`output_time`]) followed by `columns[c][k]` in shortest round-trip form. The
/// rows are written without a CSV writer: digits, signs, points and exponents never need quoting, and this is
/// most of the time a run spends on its files.
fn write_numbers(
    mut w: impl Write,
    header: &[impl AsRef<[u8]>],
    t: &[f64],
    columns: &[&[f64]],
) -> Result<(), TableError> {
    let mut head = csv::WriterBuilder::new()
        .has_headers(false)
        .from_writer(Vec::new());
    head.write_record(header)?;
    let mut out = head
        .into_inner()
        .map_err(|e| TableError::Io(e.into_error()))?;
    // Written on in pieces of about 64 kB: small enough to stay in cache, large enough for few system calls.
    const CHUNK: usize = 1 << 16;
    out.reserve(CHUNK + 32 * (columns.len() + 1));
    let mut num = Shortest::new();
    for (k, &tk) in t.iter().enumerate() {
        push_time(&mut out, tk);
        for c in columns {
            out.push(b',');
            num.push(&mut out, c[k]);
        }
        out.push(b'\n');
        if out.len() >= CHUNK {
            w.write_all(&out)?;
            out.clear();
        }
    }
    w.write_all(&out)?;
    w.flush()?;
    Ok(())
}

/// Reads `response.csv` of a run summarised by `s` back into histories (without energies and paths): its
/// header must be the one `s` gives, column for column.
pub fn read_response(r: impl Read, s: &RunSummary) -> Result<Histories, TableError> {
    let columns = Column::all(s);
    let mut rdr = csv::ReaderBuilder::new().has_headers(true).from_reader(r);
    let header = rdr.headers()?.clone();
    let bad = |m: String| TableError::Invalid(format!("response.csv: {m}"));
    if header.len() != columns.len() {
        return Err(bad(format!(
            "{} columns, where summary.json describes {}",
            header.len(),
            columns.len()
        )));
    }
    for (k, (got, c)) in header.iter().zip(&columns).enumerate() {
        let want = c.header(s);
        if got != want {
            return Err(bad(format!(
                "column {} is {got:?}, where summary.json gives {want:?}",
                k + 1
            )));
        }
    }
    let per = |n: &dyn Fn(usize) -> usize, count: usize| -> Vec<Vec<Vec<f64>>> {
        (0..count).map(|i| vec![Vec::new(); n(i)]).collect()
    };
    let floors = |b: usize| s.buildings[b].storeys;
    let plan_floors = |b: usize| {
        if s.buildings[b].plan.is_some() {
            s.buildings[b].storeys
        } else {
            0
        }
    };
    let mut h = Histories {
        displacement: per(&floors, s.buildings.len()),
        absolute_acceleration: per(&floors, s.buildings.len()),
        storey_shear: per(&floors, s.buildings.len()),
        site_force: per(&|i| s.sites[i].levels.len(), s.sites.len()),
        device_force: per(&|i| s.devices[i].floors.len(), s.devices.len()),
        displacement_y: per(&plan_floors, s.buildings.len()),
        rotation: per(&plan_floors, s.buildings.len()),
        foundation: per(
            &|b| 2 * usize::from(s.buildings[b].foundation.is_some()),
            s.buildings.len(),
        ),
        ..Histories::default()
    };
    let mut record = csv::StringRecord::new();
    let mut row = 0;
    while rdr.read_record(&mut record)? {
        row += 1;
        for (field, c) in record.iter().zip(&columns) {
            let x: f64 = field
                .parse()
                .ok()
                .filter(|x: &f64| x.is_finite())
                .ok_or_else(|| bad(format!("row {row}: {field:?} is not a finite number")))?;
            c.values_mut(&mut h).push(x);
        }
    }
    Ok(h)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn energy_rows_written_fast_are_the_serde_rows_and_read_back() {
        // Energies of every size and sign, times k dt with rounding noise.
        let n = 2000;
        let mut h = Histories {
            t: (0..n).map(|k| k as f64 * 0.005).collect(),
            ..Histories::default()
        };
        for (c, e) in h.energy.iter_mut().enumerate() {
            *e = (0..n)
                .map(|k| ((k * (c + 3)) as f64).sin() * 10f64.powi((k % 40) as i32 - 20))
                .collect();
        }
        let mut fast = Vec::new();
        write_energy(&mut fast, &h).unwrap();
        let mut serde = Vec::new();
        write_rows(&mut serde, &EnergyRow::all(&h)).unwrap();
        assert_eq!(
            String::from_utf8(fast.clone()).unwrap(),
            String::from_utf8(serde).unwrap()
        );
        // The energies come back bit for bit, the times to their 12 digits.
        let back: Vec<EnergyRow> = read_rows(fast.as_slice()).unwrap();
        for (b, a) in back.iter().zip(EnergyRow::all(&h)) {
            assert!((b.time_s - a.time_s).abs() <= 1e-12 * a.time_s, "{b:?}");
            assert_eq!(
                EnergyRow {
                    time_s: a.time_s,
                    ..*b
                },
                a
            );
        }
        assert_eq!(back.len(), n);
    }
}
