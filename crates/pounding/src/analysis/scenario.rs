//! A pounding analysis: buildings in a row, the contact sites between them and beside them, devices, the
//! ground motion and the settings ([`Scenario`]).

use super::{ContactSite, Device, DeviceEnds, SiteKind};
use crate::error::check;
use crate::ground_motion::Record;
use crate::structure::ShearBuilding;
use crate::Error;

/// A building of the row, with its name.
#[derive(Clone, Debug, PartialEq)]
pub struct Building {
    /// Name, unique in the scenario.
    pub name: String,
    /// The structure.
    pub structure: ShearBuilding,
}

/// A pounding analysis: buildings, contact sites, devices, ground motion and settings.
///
/// Buildings are listed left to right; contacts between neighbours ([`Scenario::with_contact`]) and walls
/// beside them ([`Scenario::with_wall`]) are its contact sites ([`Scenario::sites`]), devices join floors for
/// good ([`Scenario::with_device`]); [`Scenario::run`] integrates the motion and returns the
/// [`super::Results`]. A comparison run without contact ([`Scenario::without_contact`]) gives the gap each
/// floor pair needed.
///
/// ```
/// use pounding::analysis::{Building, LinkSpec, Scenario};
/// use pounding::contact::{ContactModel, Model};
/// use pounding::ground_motion::Record;
/// use pounding::structure::ShearBuilding;
///
/// // Two one-storey buildings, T = 0.5 s and 1.0 s (k = 4 pi^2 m / T^2), 10 mm apart.
/// let storey = |k: f64| ShearBuilding::builder().masses([5.0e5]).stiffnesses([k]).heights([3.0]).build();
/// let buildings = vec![
///     Building { name: "stiff".into(), structure: storey(7.8957e7)? },
///     Building { name: "flexible".into(), structure: storey(1.9739e7)? },
/// ];
/// let scenario = Scenario::new(buildings, Record::el_centro_1940())?
///     .with_duration(4.0)? // s: the strong motion's first seconds
///     .with_contact(LinkSpec {
///         between: ["stiff".into(), "flexible".into()],
///         gap: 0.01, // m
///         floors: None, // the floors at the same height: (1, 1)
///         contact: ContactModel::new(Model::Papi, 2.0e9, 0.65)?, // k in N/m, e
///         bumper: None,
///         seat: None,
///     })?;
/// let results = scenario.run()?;
/// let site = &results.sites[0];
/// assert!(site.impacts > 0 && site.peak_force > 0.0); // N
/// // Without contact, the floors close by more than the gap: that is why they pound.
/// let free = scenario.without_contact().run()?;
/// assert!(free.sites[0].max_closing[0] > 0.01); // m
/// # Ok::<(), pounding::Error>(())
/// ```
#[derive(Clone, Debug)]
pub struct Scenario {
    pub(super) buildings: Vec<Building>,
    /// Contacts between neighbours (left to right), then walls (in the order added).
    pub(super) sites: Vec<ContactSite>,
    pub(super) devices: Vec<Device>,
    pub(super) record: Record,
    /// The record along y, on the x record's time grid ([`Scenario::with_ground_y`]).
    pub(super) record_y: Option<Record>,
    /// Supports of their own (multi-support excitation, [`Scenario::with_support`]): name and record; support
    /// 0 is the scenario's record, unnamed.
    pub(super) supports: Vec<(String, Record)>,
    /// The support of each building (0: the scenario's record).
    pub(super) building_support: Vec<usize>,
    /// The scenario's record, then each support's: what the engine's ground is given for multi-support
    /// excitation (empty without supports).
    pub(super) many: Vec<Record>,
    pub(super) duration: f64,
    pub(super) output_dt: f64,
    pub(super) tolerance: f64,
    pub(super) min_impact_velocity: f64,
    pub(super) propagation: crate::engine::Propagation,
}

/// Default floor of the impact velocity used to build a contact law, m/s (see
/// [`Scenario::with_min_impact_velocity`]).
pub const DEFAULT_MIN_IMPACT_VELOCITY: f64 = 1e-3;

/// Default relative tolerance of the integration (see `docs/verification.md` for the convergence study).
pub const DEFAULT_TOLERANCE: f64 = 1e-7;

/// Default interval of the output histories, s.
pub const DEFAULT_OUTPUT_DT: f64 = 0.005;

impl Scenario {
    /// A scenario with the buildings (left to right; at least one, unique names) under `record`, for the
    /// record's duration, output every [`DEFAULT_OUTPUT_DT`], at [`DEFAULT_TOLERANCE`].
    pub fn new(buildings: Vec<Building>, record: Record) -> Result<Self, Error> {
        let floors: Vec<usize> = buildings.iter().map(|b| b.structure.dofs()).collect();
        crate::limits::check_row(&floors)?;
        for (i, b) in buildings.iter().enumerate() {
            if buildings[..i].iter().any(|o| o.name == b.name) {
                return Err(Error::Choice {
                    name: "name",
                    value: format!("{:?}", b.name),
                    allowed: "a name used by one building only".into(),
                });
            }
        }
        let duration = record.duration();
        let n = buildings.len();
        Ok(Self {
            buildings,
            sites: Vec::new(),
            devices: Vec::new(),
            building_support: vec![0; n],
            record,
            record_y: None,
            supports: Vec::new(),
            many: Vec::new(),
            duration,
            output_dt: DEFAULT_OUTPUT_DT,
            tolerance: DEFAULT_TOLERANCE,
            min_impact_velocity: DEFAULT_MIN_IMPACT_VELOCITY,
            propagation: crate::engine::Propagation::default(),
        })
    }

    /// Index of the building called `name`.
    pub fn building_index(&self, name: &str) -> Result<usize, Error> {
        self.buildings
            .iter()
            .position(|b| b.name == name)
            .ok_or_else(|| Error::Choice {
                name: "between",
                value: format!("{name:?}"),
                allowed: self.names(),
            })
    }

    /// "one of the buildings: ..." for messages.
    pub(super) fn names(&self) -> String {
        format!(
            "one of the buildings: {}",
            self.buildings
                .iter()
                .map(|b| format!("{:?}", b.name))
                .collect::<Vec<_>>()
                .join(", ")
        )
    }

    /// The floor pairs of buildings `left` and `left + 1` at the same height (within 1 mm), from 1.
    pub fn aligned_floors(&self, left: usize) -> Vec<(usize, usize)> {
        self.aligned_floor_pairs(left, left + 1)
    }

    /// The floor pairs of buildings `a` and `b` at the same height (within 1 mm), from 1.
    pub fn aligned_floor_pairs(&self, a: usize, b: usize) -> Vec<(usize, usize)> {
        let zl = self.buildings[a].structure.elevations();
        let zr = self.buildings[b].structure.elevations();
        zl.iter()
            .enumerate()
            .filter_map(|(i, z)| {
                zr.iter()
                    .position(|w| (w - z).abs() <= 1e-3)
                    .map(|j| (i + 1, j + 1))
            })
            .collect()
    }

    /// Sets the analysed duration, s (> 0; may exceed the record, which is followed by free vibration).
    pub fn with_duration(mut self, duration: f64) -> Result<Self, Error> {
        self.duration = check("duration", duration, duration > 0.0, "duration > 0 (s)")?;
        Ok(self)
    }

    /// Sets the interval of the output histories, s (> 0).
    pub fn with_output_dt(mut self, dt: f64) -> Result<Self, Error> {
        self.output_dt = check("output_dt", dt, dt > 0.0, "output_dt > 0 (s)")?;
        Ok(self)
    }

    /// Sets the relative tolerance of the integration, in `[1e-12, 1e-3]`.
    pub fn with_tolerance(mut self, rtol: f64) -> Result<Self, Error> {
        self.tolerance = check(
            "tolerance",
            rtol,
            (1e-12..=1e-3).contains(&rtol),
            "1e-12 <= tolerance <= 1e-3",
        )?;
        Ok(self)
    }

    /// Sets the smallest impact velocity used to build a contact law, m/s (> 0). Slower impacts (a touch at
    /// a turning point of the relative motion, or the last bounces before floors come to rest against each
    /// other) build their law with this velocity. Hunt–Crossley-type laws divide their damping by `v_i`, so
    /// without a floor a touch at `v_i -> 0` makes the damping unbounded and the equations infinitely
    /// stiff. Impacts below 1 mm/s carry a millionth of the energy of a 1 m/s impact. The reported `v_i`
    /// and `e_post` are always the measured ones.
    pub fn with_min_impact_velocity(mut self, v: f64) -> Result<Self, Error> {
        self.min_impact_velocity = check(
            "min_impact_velocity",
            v,
            v > 0.0,
            "min_impact_velocity > 0 (m/s)",
        )?;
        Ok(self)
    }

    /// Smallest impact velocity used to build a contact law, m/s.
    pub fn min_impact_velocity(&self) -> f64 {
        self.min_impact_velocity
    }

    /// The same scenario advanced between events as `how` says (default: exactly while every law is affine,
    /// `docs/performance.md`; `Stepping` takes every stretch with the adaptive Runge–Kutta stepper, to check
    /// one against the other).
    pub fn with_propagation(mut self, how: crate::engine::Propagation) -> Self {
        self.propagation = how;
        self
    }

    /// How the scenario advances between events.
    pub fn propagation(&self) -> crate::engine::Propagation {
        self.propagation
    }
    /// The buildings, left to right.
    pub fn buildings(&self) -> &[Building] {
        &self.buildings
    }
    /// The contact sites: contacts between neighbours, left to right, then walls, in the order added. The
    /// results of a run list theirs in the same order ([`super::Results::sites`]).
    pub fn sites(&self) -> &[ContactSite] {
        &self.sites
    }
    /// The devices.
    pub fn devices(&self) -> &[Device] {
        &self.devices
    }
    /// The building a site stands beside or begins at: a wall's building, the left of two neighbours.
    pub fn site_building(&self, site: &ContactSite) -> usize {
        match site.kind {
            SiteKind::Wall { building, .. } => building,
            SiteKind::Between { left, .. } => left,
        }
    }
    /// The effective mass (kg) of the contact element at level `level` (an index in the site's levels) of
    /// `site`: `m_L m_R / (m_L + m_R)` of the masses its two ends meet, or the one end's against a rigid wall.
    /// A floor in one line meets its own mass; a floor in plan, at a point `r` from its mass centre along the
    /// normal `n`, meets `1 / (1 / m + (r x n)^2 / J)` ([`crate::structure::Plan::point_mass`]).
    pub fn effective_mass(&self, site: &ContactSite, level: usize) -> f64 {
        let lv = site.levels[level];
        // A point across the gap has the same arm along the normal: the left façade's point serves both.
        let mass = |b: usize, f: Option<usize>| {
            let floor = f.unwrap_or(1);
            let st = &self.buildings[b].structure;
            match (st.plan(), &site.plan) {
                (Some(p), Some(sp)) => p.point_mass(floor, sp.points[level], sp.normal),
                _ => st.masses()[floor - 1],
            }
        };
        // A struck column's side meets the mass its point carries.
        let column = site
            .column
            .as_ref()
            .and_then(|c| c.struck.map(|col| (c.on_left, col.point_mass())));
        match site.kind {
            SiteKind::Between { left, right } => {
                let (ml, mr) = match column {
                    Some((true, m)) => (m, mass(right, lv.right)),
                    Some((false, m)) => (mass(left, lv.left), m),
                    None => (mass(left, lv.left), mass(right, lv.right)),
                };
                ml * mr / (ml + mr)
            }
            SiteKind::Wall { building, side } => {
                mass(building, if side.negative() { lv.right } else { lv.left })
            }
        }
    }
    /// The names of what device `d` joins: two buildings, or a building and a wall.
    pub fn device_between(&self, d: &Device) -> [String; 2] {
        let name = |b: usize| self.buildings[b].name.clone();
        match d.ends {
            DeviceEnds::Buildings { left, right } => [name(left), name(right)],
            DeviceEnds::Wall { site } => {
                let w = &self.sites[site];
                [name(self.site_building(w)), w.name.clone()]
            }
        }
    }
    /// The ground motion (along x).
    pub fn record(&self) -> &Record {
        &self.record
    }
    /// The ground motion along y, if the ground shakes in two directions.
    pub fn record_y(&self) -> Option<&Record> {
        self.record_y.as_ref()
    }
    /// The peak ground accelerations along x and along y within the analysis, m/s^2 (a short analysis of a
    /// long record sees only its start).
    pub fn pga_within(&self) -> (f64, f64) {
        let peak = |r: &Record| {
            let within = ((self.duration - r.t0()) / r.dt()).floor().max(0.0) as usize + 1;
            r.accelerations()[..within.min(r.npts())]
                .iter()
                .fold(0.0f64, |a, x| a.max(x.abs()))
        };
        (peak(&self.record), self.record_y.as_ref().map_or(0.0, peak))
    }
    /// The ground as the engine moves it: the record along x, or both records.
    pub fn ground(&self) -> crate::engine::Ground<'_> {
        if self.multi_support() {
            return crate::engine::Ground::Many(&self.many);
        }
        match &self.record_y {
            Some(y) => crate::engine::Ground::Plane { x: &self.record, y },
            None => crate::engine::Ground::Record(&self.record),
        }
    }

    /// Adds a support of its own called `name` (multi-support excitation), shaken by `record` (its own, or the
    /// scenario's delayed, [`Record::delayed`]): structures put on it ([`Scenario::with_building_on`]) are shaken by
    /// it, and a contact or wall between structures on different supports closes by their displacements'
    /// difference as well (each support's displacement integrated from rest). Buildings in one line only.
    pub fn with_support(mut self, name: &str, record: Record) -> Result<Self, Error> {
        if self.supports.iter().any(|(n, _)| n == name) || name.is_empty() {
            return Err(Error::Choice {
                name: "support",
                value: format!("{name:?}"),
                allowed: "a name used by one support only".into(),
            });
        }
        if self.supports.len() >= crate::limits::MAX_SUPPORTS {
            return Err(Error::Choice {
                name: "support",
                value: format!("{} supports", self.supports.len() + 1),
                allowed: "at most 16 supports of their own (limits::MAX_SUPPORTS)".into(),
            });
        }
        if self.record_y.is_some() {
            return Err(Error::Choice {
                name: "support",
                value: format!("{name:?}"),
                allowed: "one ground component: supports of their own shake along x, and this scenario has a record along y".into(),
            });
        }
        self.supports.push((name.to_string(), record));
        self.many = self.support_records();
        Ok(self)
    }

    /// Puts building `building` (by name) on the support called `support`.
    pub fn with_building_on(mut self, building: &str, support: &str) -> Result<Self, Error> {
        let b = self.building_index(building)?;
        if self.buildings[b].structure.plan().is_some() {
            return Err(Error::Choice {
                name: "support",
                value: format!("{support:?}"),
                allowed: "the scenario's ground under a building in plan: supports of their own are for buildings in one line".into(),
            });
        }
        self.building_support[b] = self.support_index(support)?;
        Ok(self)
    }

    /// Puts the wall called `wall` on the support called `support` (it moves with that support's ground).
    pub fn with_wall_on(mut self, wall: &str, support: &str) -> Result<Self, Error> {
        let k = self.support_index(support)?;
        let site = self
            .sites
            .iter_mut()
            .find(|s| s.is_wall() && s.name == wall)
            .ok_or_else(|| Error::Choice {
                name: "wall",
                value: format!("{wall:?}"),
                allowed: "the name of a wall".into(),
            })?;
        site.support = k;
        Ok(self)
    }

    /// The index of the support called `name` (from 1; 0 is the scenario's record).
    pub(super) fn support_index(&self, name: &str) -> Result<usize, Error> {
        self.supports
            .iter()
            .position(|(n, _)| n == name)
            .map(|k| k + 1)
            .ok_or_else(|| Error::Choice {
                name: "support",
                value: format!("{name:?}"),
                allowed: if self.supports.is_empty() {
                    "the name of a [[support]] (there are none)".into()
                } else {
                    format!(
                        "one of the supports: {}",
                        self.supports
                            .iter()
                            .map(|(n, _)| format!("{n:?}"))
                            .collect::<Vec<_>>()
                            .join(", ")
                    )
                },
            })
    }

    /// The supports of their own, name and record, in order (support `k + 1`).
    pub fn supports(&self) -> &[(String, Record)] {
        &self.supports
    }
    /// The support of each building: 0 for the scenario's record, `k + 1` for [`Scenario::supports`]`[k]`.
    pub fn building_supports(&self) -> &[usize] {
        &self.building_support
    }
    /// Every record that shakes a support, the scenario's first (index 0): what [`crate::engine::Ground::Many`]
    /// is given.
    pub fn support_records(&self) -> Vec<Record> {
        std::iter::once(self.record.clone())
            .chain(self.supports.iter().map(|(_, r)| r.clone()))
            .collect()
    }
    /// Whether supports differ: a structure stands on a support whose record is not the scenario's (a run of
    /// identical supports is the uniform excitation exactly).
    pub fn multi_support(&self) -> bool {
        let on = |k: usize| k > 0 && self.supports[k - 1].1 != self.record;
        self.building_support.iter().any(|&k| on(k)) || self.sites.iter().any(|s| on(s.support))
    }

    /// Shakes the ground along y as well, with `y` (the record along x stays [`Scenario::record`]). The two
    /// records are put on one time grid: a step that holds every sample of both (their steps' common
    /// divisor), where each is the same piecewise-linear acceleration as before; each keeps its length (its
    /// acceleration is 0 after its last sample). Refused if the steps have no common divisor of at least a
    /// hundredth of the smaller step, or if the first samples are not a whole number of common steps apart.
    pub fn with_ground_y(mut self, y: Record) -> Result<Self, Error> {
        if !self.supports.is_empty() {
            return Err(Error::Choice {
                name: "y",
                value: "a record along y".into(),
                allowed: "a scenario without supports of their own (they shake along x)".into(),
            });
        }
        let (x, y) = crate::ground_motion::on_one_grid(&self.record, &y)?;
        // A duration left at the record's follows the longer of the two.
        if self.duration == self.record.duration() {
            self.duration = x.duration().max(y.duration());
        }
        self.record = x;
        self.record_y = Some(y);
        Ok(self)
    }
    /// Analysed duration, s.
    pub fn duration(&self) -> f64 {
        self.duration
    }
    /// Output interval, s.
    pub fn output_dt(&self) -> f64 {
        self.output_dt
    }
    /// Relative tolerance of the integration.
    pub fn tolerance(&self) -> f64 {
        self.tolerance
    }
    /// Number of output samples in the histories.
    /// (Saturates at `usize::MAX` instead of wrapping: compare with [`crate::limits::MAX_OUTPUT_SAMPLES`].)
    pub fn output_samples(&self) -> usize {
        let n = (self.duration / self.output_dt * (1.0 + 1e-12)).floor() + 1.0;
        if n < 1e15 {
            n as usize
        } else {
            usize::MAX
        }
    }
}
