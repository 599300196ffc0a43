//! Time-history analysis of pounding between adjacent buildings under a uniform base excitation.
//!
//! Buildings stand in a row, listed left to right; positive displacement points right. Displacements are
//! relative to the moving ground, so each floor obeys `m_i u_i'' = -m_i (a_g(t) + a0 u_i') + storey and
//! contact forces`. The row is built as a system of the engine ([`crate::engine`]): one degree of freedom per
//! floor, one storey element per storey (linear, bilinear or Bouc–Wen, [`crate::element::storey`], with the
//! stiffness-proportional Rayleigh damping `a1 k_j` of its initial stiffness), and one contact element per
//! floor pair of each [`Link`] ([`crate::element::contact`]): it closes when `u_L - u_R` exceeds the gap, so
//! its penetration is `d = u_L - u_R - gap` and its rate `v = d'`.
//!
//! Each impact is one touch of one element. Its onset is located as an event on the integrator's
//! interpolant, so `v_i` is the relative velocity at the moment of touch, and the element's law is built
//! afresh for it with [`PreparedContact::law`] (effective mass `m_L m_R / (m_L + m_R)` of the two floors).
//! Storeys' yield and reversal are events too, so force–drift loops are exact, not smeared over a step.
//! Integration is adaptive Dormand–Prince 5(4) with steps that end at every sample of the record (the ground
//! acceleration has a kink there) and restart at every event. One relative tolerance sets the accuracy of
//! everything.
//!
//! The energy balance is integrated with the motion: input `E_I = -int a_g 1^T M u' dt` = kinetic
//! `u'^T M u' / 2` + recoverable strain of the storeys + viscous damping `int u'^T C u' dt` + hysteretic
//! dissipation of the storeys + contact work `int F d' dt` (equal to the energy dissipated by the contacts
//! once every impact has ended). What a run keeps (peaks, impacts, energies, and optionally histories) is
//! recorded by observers of the engine ([`RunOptions`]).

mod model;
mod record;
mod run;
mod sites;

use crate::contact::{ContactModel, PreparedContact};
use crate::error::check;
use crate::ground_motion::Record;
use crate::structure::ShearBuilding;
use crate::Error;
use std::ops::ControlFlow;

pub use run::Progress;
pub use sites::{Bumper, Device, DeviceEnds, DeviceSpec, Layer, Side, Site, Wall, WallSpec};

/// A building of the row, with its name.
#[derive(Clone, Debug, PartialEq)]
pub struct Building {
    /// Name, unique in the scenario.
    pub name: String,
    /// The structure.
    pub structure: ShearBuilding,
}

/// Contact elements between two adjacent buildings (`left` is the one listed first).
#[derive(Clone, Debug)]
pub struct Link {
    /// Index of the left building.
    pub left: usize,
    /// Index of the right building (`left + 1`).
    pub right: usize,
    /// Gap at rest, m.
    pub gap: f64,
    /// Floor pairs `(floor of left, floor of right)`, numbered from 1 at the lowest floor.
    pub floors: Vec<(usize, usize)>,
    /// The contact model of every element of the link (behind the bumper, if there is one).
    pub contact: PreparedContact,
    /// A bumper on the joint's face ([`Scenario::with_link_bumper`]).
    pub bumper: Option<Bumper>,
    /// Seat length of the joint for the unseating check, m ([`Scenario::with_link_seat`]).
    pub seat: Option<f64>,
}

/// What a contact between two neighbouring buildings is given: named fields, checked by
/// [`Scenario::with_contact`] (a scenario file's `[[contact]]`).
#[derive(Clone, Debug)]
pub struct LinkSpec {
    /// The two buildings, by name, in either order; they must be neighbours in the row.
    pub between: [String; 2],
    /// Gap at rest, m (>= 0).
    pub gap: f64,
    /// Floor pairs `(floor of the left building, floor of the right)`, from 1 (`None`: every pair of floors
    /// at the same height, within 1 mm).
    pub floors: Option<Vec<(usize, usize)>>,
    /// The contact law of every element (see `docs/contact-models.md#5-choosing-the-contact-stiffness` for its
    /// stiffness).
    pub contact: ContactModel,
    /// A bumper on the joint's face (it must fit in the gap).
    pub bumper: Option<Bumper>,
    /// Seat length of the joint for the unseating check, m (> 0).
    pub seat: Option<f64>,
}

/// A pounding analysis: buildings, links, ground motion and settings.
///
/// Buildings are listed left to right; contacts ([`Scenario::with_contact`]), walls and devices are added
/// by name; [`Scenario::run`] integrates the motion and returns the [`Results`]. A comparison run without
/// contact ([`Scenario::without_contact`]) gives the gap each floor pair needed.
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
/// let link = &results.links[0];
/// assert!(link.impacts > 0 && link.peak_force > 0.0); // N
/// // Without contact, the floors close by more than the gap: that is why they pound.
/// let free = scenario.without_contact().run()?;
/// assert!(free.links[0].max_closing[0] > 0.01); // m
/// # Ok::<(), pounding::Error>(())
/// ```
#[derive(Clone, Debug)]
pub struct Scenario {
    buildings: Vec<Building>,
    links: Vec<Link>,
    walls: Vec<Wall>,
    devices: Vec<Device>,
    record: Record,
    duration: f64,
    output_dt: f64,
    tolerance: f64,
    min_impact_velocity: f64,
}

/// Default floor of the impact velocity used to build a contact law, m/s (see
/// [`Scenario::with_min_impact_velocity`]).
pub const DEFAULT_MIN_IMPACT_VELOCITY: f64 = 1e-3;

/// The gap of [`Scenario::without_contact`]'s links, m: beyond any motion, yet finite, so that penetrations
/// `u_L - u_R - gap` stay ordinary numbers.
pub const NO_CONTACT_GAP: f64 = 1e100;

/// Default relative tolerance of the integration (see `docs/verification.md` for the convergence study).
pub const DEFAULT_TOLERANCE: f64 = 1e-7;

impl Scenario {
    /// A scenario with the buildings (left to right; at least one, unique names) under `record`, for the
    /// record's duration, output every 0.005 s, at [`DEFAULT_TOLERANCE`].
    pub fn new(buildings: Vec<Building>, record: Record) -> Result<Self, Error> {
        let floors: Vec<usize> = buildings.iter().map(|b| b.structure.storeys()).collect();
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
        Ok(Self {
            buildings,
            links: Vec::new(),
            walls: Vec::new(),
            devices: Vec::new(),
            record,
            duration,
            output_dt: 0.005,
            tolerance: DEFAULT_TOLERANCE,
            min_impact_velocity: DEFAULT_MIN_IMPACT_VELOCITY,
        })
    }

    /// The name of link `l`: `left|right`, the names of its two buildings (as output columns show it).
    pub fn link_name(&self, l: usize) -> String {
        let link = &self.links[l];
        format!(
            "{}|{}",
            self.buildings[link.left].name, self.buildings[link.right].name
        )
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

    /// Adds a contact between two neighbouring buildings, given by named fields ([`LinkSpec`]): contact
    /// elements at its floor pairs, with its bumper and seat. The same as [`Scenario::with_link`] followed
    /// by [`Scenario::with_link_bumper`] and [`Scenario::with_link_seat`], with the same checks.
    pub fn with_contact(self, spec: LinkSpec) -> Result<Self, Error> {
        let [a, b] = &spec.between;
        let mut s = self.with_link(a, b, spec.gap, &spec.contact, spec.floors.clone())?;
        if let Some(bumper) = spec.bumper {
            s = s.with_link_bumper(a, b, bumper)?;
        }
        if let Some(seat) = spec.seat {
            s = s.with_link_seat(a, b, seat)?;
        }
        Ok(s)
    }

    /// Adds contact elements between the adjacent buildings `a` and `b` (in either order), with gap `gap`
    /// (m, >= 0) at rest and `contact` at every floor pair of `floors` (`(floor of the left building, floor
    /// of the right)`, from 1), or by default at every pair of floors at the same height (within 1 mm).
    /// This is the positional, low-level form; [`Scenario::with_contact`] takes the same with named fields.
    pub fn with_link(
        mut self,
        a: &str,
        b: &str,
        gap: f64,
        contact: &ContactModel,
        floors: Option<Vec<(usize, usize)>>,
    ) -> Result<Self, Error> {
        let (ia, ib) = (self.building_index(a)?, self.building_index(b)?);
        let (left, right) = (ia.min(ib), ia.max(ib));
        if right != left + 1 {
            return Err(Error::Choice {
                name: "between",
                value: format!("[{a:?}, {b:?}]"),
                allowed: "two buildings next to each other in the row (as listed, left to right)"
                    .into(),
            });
        }
        if self
            .links
            .iter()
            .any(|l| l.left == left && l.right == right)
        {
            return Err(Error::Choice {
                name: "between",
                value: format!("[{a:?}, {b:?}]"),
                allowed: "one contact entry per pair of buildings".into(),
            });
        }
        check("gap", gap, gap >= 0.0, "gap >= 0 (m)")?;
        let (sl, sr) = (
            &self.buildings[left].structure,
            &self.buildings[right].structure,
        );
        let floors = match floors {
            Some(f) => {
                if f.is_empty() {
                    return Err(Error::Choice {
                        name: "floors",
                        value: "[]".into(),
                        allowed: "at least one pair [floor of left, floor of right]".into(),
                    });
                }
                for (k, &(i, j)) in f.iter().enumerate() {
                    if f[..k].contains(&(i, j)) {
                        return Err(Error::Choice {
                            name: "floors",
                            value: format!("[{i}, {j}] twice"),
                            allowed: "each pair of floors once (two elements on one pair would double its contact)".into(),
                        });
                    }
                    if !(1..=sl.storeys()).contains(&i) || !(1..=sr.storeys()).contains(&j) {
                        return Err(Error::Choice {
                            name: "floors",
                            value: format!("[{i}, {j}]"),
                            allowed: format!(
                                "floors 1..={} of {:?} and 1..={} of {:?}",
                                sl.storeys(),
                                self.buildings[left].name,
                                sr.storeys(),
                                self.buildings[right].name
                            ),
                        });
                    }
                }
                f
            }
            None => {
                let pairs = self.aligned_floors(left);
                if pairs.is_empty() {
                    return Err(Error::Choice {
                        name: "floors",
                        value: "(default)".into(),
                        allowed: format!(
                            "no floors of {:?} and {:?} are at the same height; list them, as floors = [[1, 1]]",
                            self.buildings[left].name, self.buildings[right].name
                        ),
                    });
                }
                pairs
            }
        };
        let contact = contact.prepare()?;
        self.links.push(Link {
            left,
            right,
            gap,
            floors,
            contact,
            bumper: None,
            seat: None,
        });
        self.links.sort_by_key(|l| l.left);
        Ok(self)
    }

    /// The floor pairs of buildings `left` and `left + 1` at the same height (within 1 mm), from 1.
    pub fn aligned_floors(&self, left: usize) -> Vec<(usize, usize)> {
        let zl = self.buildings[left].structure.elevations();
        let zr = self.buildings[left + 1].structure.elevations();
        zl.iter()
            .enumerate()
            .filter_map(|(i, z)| {
                zr.iter()
                    .position(|w| (w - z).abs() <= 1e-3)
                    .map(|j| (i + 1, j + 1))
            })
            .collect()
    }

    /// The same scenario without contact: every pair of neighbours is linked at the floors of its contact
    /// entry (or, without one, at the floors at the same height) by contact elements whose gap no motion
    /// closes ([`NO_CONTACT_GAP`]), so that a run records each floor pair's largest closing
    /// ([`LinkResponse::max_closing`]) and nothing else changes; walls stay, out of reach, to record the
    /// largest approach to each ([`WallResponse::max_closing`]); bumpers go; devices stay (they are part of
    /// the structure). Neighbours without a contact entry and without floors at the same height stay
    /// unlinked.
    pub fn without_contact(&self) -> Scenario {
        let mut s = self.clone();
        for link in &mut s.links {
            link.gap = NO_CONTACT_GAP;
            link.bumper = None;
        }
        for wall in &mut s.walls {
            wall.gap = NO_CONTACT_GAP;
            wall.bumper = None;
        }
        for left in 0..self.buildings.len().saturating_sub(1) {
            if s.links.iter().any(|l| l.left == left) {
                continue;
            }
            let floors = self.aligned_floors(left);
            // Any contact model: it never acts. Hooke's needs no calibration.
            let prepared =
                ContactModel::new(crate::contact::Model::Hooke, 1.0, 1.0).and_then(|c| c.prepare());
            if let (false, Ok(contact)) = (floors.is_empty(), prepared) {
                s.links.push(Link {
                    left,
                    right: left + 1,
                    gap: NO_CONTACT_GAP,
                    floors,
                    contact,
                    bumper: None,
                    seat: None,
                });
            }
        }
        s.links.sort_by_key(|l| l.left);
        s
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

    /// The buildings, left to right.
    pub fn buildings(&self) -> &[Building] {
        &self.buildings
    }
    /// The links, ordered left to right.
    pub fn links(&self) -> &[Link] {
        &self.links
    }
    /// The ground motion.
    pub fn record(&self) -> &Record {
        &self.record
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

    /// Runs the analysis, keeping the histories.
    pub fn run(&self) -> Result<Results, Error> {
        run::run(self, &RunOptions::default(), &mut |_| {
            ControlFlow::Continue(())
        })
    }

    /// Runs the analysis, telling `progress` how far it has got (for progress bars); `progress` returns
    /// `ControlFlow::Break(())` to cancel the run ([`Error::Cancelled`]).
    pub fn run_with(
        &self,
        progress: &mut dyn FnMut(Progress) -> ControlFlow<()>,
    ) -> Result<Results, Error> {
        run::run(self, &RunOptions::default(), progress)
    }

    /// Runs the analysis with `options` (for example without histories, for studies of many runs). Every run
    /// has a step budget ([`crate::limits::step_budget`]): a run that would exceed it is refused before it
    /// starts, or stopped, with [`Error::StepBudget`].
    pub fn run_with_options(
        &self,
        options: &RunOptions,
        progress: &mut dyn FnMut(Progress) -> ControlFlow<()>,
    ) -> Result<Results, Error> {
        run::run(self, options, progress)
    }
}

/// What a run keeps, and how much work it may do.
#[derive(Clone, Debug, PartialEq)]
pub struct RunOptions {
    /// Keep the time histories at the output interval (otherwise [`Results::histories`] is empty and a run
    /// keeps only its peaks, impacts and energies).
    pub histories: bool,
    /// Largest work of the run, in integration steps times (states + 8) ([`crate::limits::step_budget`]);
    /// [`crate::limits::MAX_WORK`] (about 5 s) by default. A study may lower it to skip runs that would
    /// crawl, or raise it for a run it knows to be long.
    pub max_work: f64,
}

impl Default for RunOptions {
    fn default() -> Self {
        Self {
            histories: true,
            max_work: crate::limits::MAX_WORK,
        }
    }
}

impl RunOptions {
    /// Only peaks, impacts and energies, with the default work budget.
    pub fn summary_only() -> Self {
        Self {
            histories: false,
            ..Self::default()
        }
    }
}

/// One impact of one contact element.
#[derive(Clone, Debug, PartialEq)]
pub struct Impact {
    /// Where: a link's floor pair, or a wall's floor.
    pub site: Site,
    /// Which law: the contact's own, a bumper's layer, or the hard law behind a consumed bumper.
    pub layer: Layer,
    /// Time of touch, s.
    pub time: f64,
    /// Relative velocity at touch, m/s.
    pub v_i: f64,
    /// Relative velocity when the impact ended, m/s (negative: separating); `None` if it had not ended.
    pub v_out: Option<f64>,
    /// Delivered coefficient of restitution `-v_out / v_i`; `None` if the impact had not ended, or for a resting
    /// contact (where `v_i` is too small for the ratio to mean anything).
    pub e_post: Option<f64>,
    /// Whether the impact had ended before the analysis stopped.
    pub ended: bool,
    /// A resting contact: the ends closed from rest, at a relative velocity below the smallest impact
    /// velocity used to build a law ([`Scenario::with_min_impact_velocity`]); its law was built with that
    /// velocity, and it has no meaningful `e_post`.
    pub resting: bool,
    /// Largest contact force, N.
    pub peak_force: f64,
    /// Time of the largest force, s.
    pub time_of_peak_force: f64,
    /// Largest penetration, m.
    pub max_penetration: f64,
    /// Duration of contact, s (to the end of the analysis if it had not ended).
    pub duration: f64,
    /// Work of the contact force on the relative motion over the impact, J (the energy dissipated).
    pub dissipated_energy: f64,
}

/// Peak response of one building.
#[derive(Clone, Debug, PartialEq)]
pub struct BuildingResponse {
    /// Largest |displacement| of each floor relative to the ground, m.
    pub peak_displacement: Vec<f64>,
    /// Time of each, s.
    pub time_of_peak_displacement: Vec<f64>,
    /// Largest |inter-storey drift| of each storey, m.
    pub peak_drift: Vec<f64>,
    /// Largest |absolute acceleration| `|u'' + a_g|` of each floor, m/s^2, over every integration node (step
    /// ends and events, just before and just after each event).
    pub peak_absolute_acceleration: Vec<f64>,
    /// Time of each, s.
    pub time_of_peak_absolute_acceleration: Vec<f64>,
    /// Largest |restoring force| of each storey (its law's force, without the Rayleigh damping force), N.
    pub peak_storey_shear: Vec<f64>,
    /// Displacement of each floor at the end of the analysis, m (signed).
    pub residual_displacement: Vec<f64>,
    /// Drift of each storey at the end of the analysis, m (signed).
    pub residual_drift: Vec<f64>,
    /// Ductility demand of each storey, peak drift / yield drift (`None` for a linear storey).
    pub ductility: Vec<Option<f64>>,
    /// Energy dissipated by the hysteresis of each storey, J (0 for a linear storey).
    pub hysteretic_energy: Vec<f64>,
}

/// Totals of one link (all its elements), or of one wall ([`WallResponse`]).
#[derive(Clone, Debug, PartialEq)]
pub struct LinkResponse {
    /// Number of impacts (on the bumper's face, if there is one).
    pub impacts: usize,
    /// Impacts of the hard law behind a consumed bumper (0 without a bumper).
    pub consumed: usize,
    /// Largest contact force of a floor pair, N: of any impact, located between steps, or (with a bumper)
    /// of the layer and the hard law together, at the integration nodes.
    pub peak_force: f64,
    /// Energy dissipated by the link's contacts, J.
    pub dissipated_energy: f64,
    /// Largest penetration of any element, m.
    pub max_penetration: f64,
    /// Largest closing `u_left - u_right` of each floor pair (in [`Link::floors`] order) over the run, m,
    /// located between steps; 0 if the floors never approached. Without contact (a run of
    /// [`Scenario::without_contact`]) it is the gap each pair needed to never touch.
    pub max_closing: Vec<f64>,
    /// Largest opening `u_right - u_left` of each floor pair, m (0 if they never moved apart).
    pub max_opening: Vec<f64>,
    /// Whether the largest opening exceeded the seat ([`Link::seat`]; `None` without one).
    pub unseated: Option<bool>,
}

/// Totals of one wall (all its floors): a [`LinkResponse`] whose floor pairs are the wall's floors
/// ([`Wall::floors`] order), whose closing is a floor's displacement towards the wall and whose opening is
/// its displacement away from it.
pub type WallResponse = LinkResponse;

/// Peaks of one device, per floor pair ([`Device::floors`] order).
#[derive(Clone, Debug, PartialEq)]
pub struct DeviceResponse {
    /// Largest |force| (elastic and viscous), N, over the integration nodes.
    pub peak_force: Vec<f64>,
    /// Largest closing `x` (m; for a restrainer, negative values are openings).
    pub max_closing: Vec<f64>,
    /// Largest opening `-x`, m.
    pub max_opening: Vec<f64>,
}

/// Energies at the end of the analysis, J, and the worst relative error of the balance.
#[derive(Clone, Debug, PartialEq)]
pub struct EnergyBalance {
    /// The six energy terms at the end of the analysis, J (the contact term is the dissipated energy plus
    /// what the contacts hold at the end).
    pub end: crate::engine::Energies,
    /// Largest `|input - kinetic - strain - damping - hysteretic - contact|` over the run (at every node),
    /// divided by the largest of `kinetic + strain + damping + hysteretic + |contact|` (dimensionless).
    pub relative_error: f64,
}

/// Time histories at the output interval.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Histories {
    /// Times, s.
    pub t: Vec<f64>,
    /// Ground acceleration, m/s^2.
    pub ground_acceleration: Vec<f64>,
    /// `displacement[building][floor][sample]`, m, relative to the ground.
    pub displacement: Vec<Vec<Vec<f64>>>,
    /// `absolute_acceleration[building][floor][sample]`, `u'' + a_g`, m/s^2.
    pub absolute_acceleration: Vec<Vec<Vec<f64>>>,
    /// `storey_shear[building][storey][sample]`: the restoring force of each storey, N.
    pub storey_shear: Vec<Vec<Vec<f64>>>,
    /// `force[link][pair][sample]`, N (pairs in the order of [`Link::floors`]; with a bumper, the layer's and
    /// the hard law's force together).
    pub force: Vec<Vec<Vec<f64>>>,
    /// `wall_force[wall][floor][sample]`, N (floors in the order of [`Wall::floors`]).
    pub wall_force: Vec<Vec<Vec<f64>>>,
    /// `device_force[device][pair][sample]`, N, positive pushing apart (pairs in [`Device::floors`] order).
    pub device_force: Vec<Vec<Vec<f64>>>,
    /// Energies, J: input, kinetic, recoverable strain, viscous damping, hysteretic, contact work
    /// (`energy[0..6][sample]`).
    pub energy: [Vec<f64>; 6],
    /// The force–penetration path of every impact, `impact_loops[i]` of [`Results::impacts`]`[i]`: points at
    /// every accepted integration step in contact, with the located peak (histories sample every
    /// `output_dt`, too coarse for impacts of a few ms).
    pub impact_loops: Vec<ImpactLoop>,
}

/// Largest number of points an [`ImpactLoop`] keeps; past it, every other point is dropped and only every
/// `stride`-th step is kept from then on ([`ImpactLoop::stride`]).
pub const MAX_LOOP_POINTS: usize = 2000;

/// The path of one impact: its touch, the end of every accepted integration step while in contact, and its
/// located peak force, in time order.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ImpactLoop {
    /// Times, s.
    pub t: Vec<f64>,
    /// Penetration `u_left - u_right - gap` (for a wall, towards it), m.
    pub penetration: Vec<f64>,
    /// Contact force (as reported: the located peak is [`Impact::peak_force`]), N.
    pub force: Vec<f64>,
    /// 1 if every step is kept; `2^k` once the impact outgrew [`MAX_LOOP_POINTS`] `k` times (then one step
    /// in `stride` is kept, and always the touch, the last step and the peak).
    pub stride: usize,
}

/// Counts of the integration.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Statistics {
    /// Accepted steps.
    pub steps: usize,
    /// Rejected steps.
    pub rejected: usize,
    /// Events located and applied: contact touch, turn, kink, zero force, separation, resume; storey yield
    /// and reversal.
    pub events: usize,
}

impl Results {
    /// The smallest and largest delivered coefficient of restitution (`-v_out / v_i`, dimensionless) of the
    /// ended impacts at the sites `at` accepts, `None` if there are none. Between floors of buildings these
    /// differ from the `e` a contact was calibrated for: the calibration holds for two free bodies, and the
    /// other forces on the floors act during a contact (`docs/verification.md`, "Impacts inside a run").
    pub fn delivered_e(&self, at: impl Fn(Site) -> bool) -> Option<(f64, f64)> {
        self.impacts
            .iter()
            .filter(|i| at(i.site))
            .filter_map(|i| i.e_post)
            .fold(None, |range, e| {
                Some(range.map_or((e, e), |(lo, hi): (f64, f64)| (lo.min(e), hi.max(e))))
            })
    }

    /// Whether a site is link `link`, any floor pair: for [`Results::delivered_e`].
    pub fn at_link(link: usize) -> impl Fn(Site) -> bool {
        move |s| matches!(s, Site::Link { link: l, .. } if l == link)
    }

    /// Whether a site is wall `wall`, any floor: for [`Results::delivered_e`].
    pub fn at_wall(wall: usize) -> impl Fn(Site) -> bool {
        move |s| matches!(s, Site::Wall { wall: w, .. } if w == wall)
    }

    /// The first quantity that is not a finite number (its name), if any: a run returns
    /// [`Error::NotFinite`] rather than such a result.
    pub fn first_non_finite(&self) -> Option<String> {
        // A branch-free fold, which the compiler vectorises: a short-circuiting `any` took 0.8 % of the
        // instructions of a run, this takes 0.5 %.
        let bad = |xs: &[f64]| !xs.iter().fold(true, |ok, x| ok & x.is_finite());
        for (b, r) in self.buildings.iter().enumerate() {
            for (name, xs) in [
                ("peak_displacement", &r.peak_displacement),
                ("peak_drift", &r.peak_drift),
                ("peak_absolute_acceleration", &r.peak_absolute_acceleration),
                ("peak_storey_shear", &r.peak_storey_shear),
                ("residual_drift", &r.residual_drift),
                ("hysteretic_energy", &r.hysteretic_energy),
            ] {
                if bad(xs) {
                    return Some(format!("{name} of building {}", b + 1));
                }
            }
        }
        if bad(&self.energy.end.terms()) {
            return Some("energy".into());
        }
        if self.impacts.iter().any(|i| {
            bad(&[
                i.v_i,
                i.peak_force,
                i.max_penetration,
                i.duration,
                i.dissipated_energy,
            ]) || i.e_post.is_some_and(|x| !x.is_finite())
        }) {
            return Some("impacts".into());
        }
        let h = &self.histories;
        let groups = [
            &h.displacement,
            &h.absolute_acceleration,
            &h.storey_shear,
            &h.force,
            &h.wall_force,
            &h.device_force,
        ];
        if self
            .devices
            .iter()
            .any(|d| bad(&d.peak_force) || bad(&d.max_closing) || bad(&d.max_opening))
        {
            return Some("devices".into());
        }
        if groups.iter().any(|g| g.iter().flatten().any(|c| bad(c)))
            || h.energy.iter().any(|c| bad(c))
        {
            return Some("histories".into());
        }
        None
    }
}

/// Everything a run produces.
#[derive(Clone, Debug, PartialEq)]
pub struct Results {
    /// Peak response of each building.
    pub buildings: Vec<BuildingResponse>,
    /// Totals of each link.
    pub links: Vec<LinkResponse>,
    /// Totals of each wall.
    pub walls: Vec<WallResponse>,
    /// Peaks of each device.
    pub devices: Vec<DeviceResponse>,
    /// Every impact, in order of touch.
    pub impacts: Vec<Impact>,
    /// Energy balance.
    pub energy: EnergyBalance,
    /// Time histories (empty when the run kept none, see [`RunOptions`]).
    pub histories: Histories,
    /// Integration counts.
    pub statistics: Statistics,
}
