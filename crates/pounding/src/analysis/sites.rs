//! Walls beside buildings, bumpers on contacts, seats of joints, and devices between neighbours.
//!
//! - A **wall** is fixed to the ground beside a building, on its left or right, at a clear distance `gap`
//!   (m); the floors listed strike it through contact elements whose other end is the ground, with the floor's
//!   own mass as the effective mass of each impact (`docs/structures.md`). A moat wall around an isolated building and a bridge's abutment are walls.
//! - A **bumper** of finite thickness `t` (m) sits on the face of a contact or a wall: its soft law acts on
//!   the layer's compression from the moment the layer touches (at a closing of `gap - t`); once the
//!   compression reaches `max_strain t` the layer is consumed and the contact's own (hard) law acts as well,
//!   on the penetration beyond that point. The force is continuous, and a bumper whose layer is never
//!   consumed is exactly the soft law. The two laws are two contact elements on the same floor pair, each
//!   with its own impacts and calibration. This two-stage form is ours; Polycarpou, Komodromos & Polycarpou
//!   (2013) proposed the idea of a threshold at the layer's thickness in a nonlinear rubber-bumper model.
//! - A **seat** (m) on a contact or a wall is the length of the support that a deck's end rests on: the
//!   run reports the largest opening of the joint (moving apart, or away from the wall) and whether it
//!   exceeded the seat (unseating).
//! - A **device** joins floors of two neighbours, or a floor and a wall, for good: a spring, dashpot,
//!   Kelvin or Maxwell unit, or a restrainer with slack ([`crate::element::device`]).

use super::Scenario;
use crate::contact::{ContactModel, PreparedContact};
use crate::element::DeviceLaw;
use crate::error::check;
use crate::Error;

/// Which side of a building a wall stands on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    /// Towards negative displacements.
    Left,
    /// Towards positive displacements.
    Right,
}

impl Side {
    /// `left` or `right`.
    pub fn name(self) -> &'static str {
        match self {
            Side::Left => "left",
            Side::Right => "right",
        }
    }
}

/// A bumper: a soft layer of finite thickness on the face of a contact or wall.
#[derive(Clone, Debug)]
pub struct Bumper {
    /// Thickness of the layer, m (at most the gap it stands in).
    pub thickness: f64,
    /// Largest compressive strain of the layer, in (0, 1): the hard law joins in once the compression
    /// reaches `max_strain * thickness`.
    pub max_strain: f64,
    /// The layer's contact law.
    pub contact: PreparedContact,
}

impl Bumper {
    /// A bumper of `thickness` (m, > 0), `max_strain` in (0, 1) and the layer's law `contact`.
    pub fn new(thickness: f64, max_strain: f64, contact: &ContactModel) -> Result<Self, Error> {
        check(
            "bumper.thickness",
            thickness,
            thickness > 0.0 && thickness.is_finite(),
            "thickness > 0 (m)",
        )?;
        check(
            "bumper.max_strain",
            max_strain,
            max_strain > 0.0 && max_strain < 1.0,
            "0 < max_strain < 1",
        )?;
        Ok(Self {
            thickness,
            max_strain,
            contact: contact.prepare()?,
        })
    }

    /// The closing at which the layer touches, and the one at which it is consumed, for a clear `gap`, m.
    pub fn gaps(&self, gap: f64) -> (f64, f64) {
        let touch = gap - self.thickness;
        (touch, touch + self.max_strain * self.thickness)
    }
}

/// A wall fixed to the ground beside a building.
#[derive(Clone, Debug)]
pub struct Wall {
    /// Name, unique among walls and buildings.
    pub name: String,
    /// Index of the building it faces.
    pub building: usize,
    /// Which side of that building.
    pub side: Side,
    /// Clear distance at rest, m.
    pub gap: f64,
    /// Floors of the building that can strike it, from 1.
    pub floors: Vec<usize>,
    /// The contact law.
    pub contact: PreparedContact,
    /// A bumper on its face.
    pub bumper: Option<Bumper>,
    /// Seat length for the unseating check, m.
    pub seat: Option<f64>,
}

/// What a wall is given: named fields, checked by [`Scenario::with_wall`].
#[derive(Clone, Debug)]
pub struct WallSpec {
    /// Name, unique among walls and buildings.
    pub name: String,
    /// The building it faces.
    pub facing: String,
    /// Which side of that building.
    pub side: Side,
    /// Clear distance at rest, m (>= 0).
    pub gap: f64,
    /// Floors that can strike it, from 1 (default: floor 1).
    pub floors: Option<Vec<usize>>,
    /// The contact law.
    pub contact: ContactModel,
    /// A bumper on its face.
    pub bumper: Option<Bumper>,
    /// Seat length, m (> 0).
    pub seat: Option<f64>,
}

/// One end of a device besides a building: the neighbouring building, or a wall.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DeviceEnds {
    /// Between buildings `left` and `left + 1`; floor pairs `(floor of left, floor of right)`.
    Buildings {
        /// Index of the left building.
        left: usize,
        /// Index of the right building.
        right: usize,
    },
    /// Between a building's floors and wall `wall` (on the building's side); floor pairs `(floor, floor)`.
    Wall {
        /// Index of the wall.
        wall: usize,
    },
}

/// A device between neighbours (or a building and a wall).
#[derive(Clone, Debug)]
pub struct Device {
    /// Name, unique among devices.
    pub name: String,
    /// What it joins.
    pub ends: DeviceEnds,
    /// Floor pairs (for a wall, the floor twice), from 1.
    pub floors: Vec<(usize, usize)>,
    /// Its law.
    pub law: DeviceLaw,
}

/// What a device is given: named fields, checked by [`Scenario::with_device`].
#[derive(Clone, Debug)]
pub struct DeviceSpec {
    /// Name (default: the law's name and its number, `restrainer1`).
    pub name: Option<String>,
    /// Two neighbouring buildings, or a building and a wall beside it.
    pub between: [String; 2],
    /// Floor pairs (for a wall, `(floor, floor)`; default: floors at the same height, or floor 1 for a wall).
    pub floors: Option<Vec<(usize, usize)>>,
    /// Its law.
    pub law: DeviceLaw,
}

/// Where an impact happened.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Site {
    /// Between two buildings: link index and floor pair `(left, right)`, from 1.
    Link {
        /// Index in [`Scenario::links`].
        link: usize,
        /// Floor pair, from 1.
        floors: (usize, usize),
    },
    /// Against a wall: wall index and floor, from 1.
    Wall {
        /// Index in [`Scenario::walls`].
        wall: usize,
        /// Floor, from 1.
        floor: usize,
    },
}

/// Which law of a contact an impact is of.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Layer {
    /// The contact's law, without a bumper.
    Direct,
    /// A bumper's soft layer.
    Bumper,
    /// The hard law behind a bumper whose layer was consumed.
    Consumed,
}

impl Layer {
    /// `direct`, `bumper` or `consumed`.
    pub fn name(self) -> &'static str {
        match self {
            Layer::Direct => "direct",
            Layer::Bumper => "bumper",
            Layer::Consumed => "consumed",
        }
    }
}

fn choice(name: &'static str, value: String, allowed: String) -> Error {
    Error::Choice {
        name,
        value,
        allowed,
    }
}

impl Scenario {
    /// Adds a wall ([`WallSpec`]): it faces a building of the row on a side without a neighbour, at a gap
    /// >= 0 (m), struck by distinct floors of that building; a bumper must fit in the gap.
    pub fn with_wall(mut self, w: WallSpec) -> Result<Self, Error> {
        let b = self
            .building_index(&w.facing)
            .map_err(|_| choice("facing", format!("{:?}", w.facing), self.names()))?;
        if self.buildings.iter().any(|x| x.name == w.name)
            || self.walls.iter().any(|x| x.name == w.name)
        {
            return Err(choice(
                "name",
                format!("{:?}", w.name),
                "a name used by no building and no other wall".into(),
            ));
        }
        let neighbour = match w.side {
            Side::Left => b.checked_sub(1),
            Side::Right => (b + 1 < self.buildings.len()).then_some(b + 1),
        };
        if let Some(n) = neighbour {
            return Err(choice(
                "side",
                format!("{:?}", w.side.name()),
                format!(
                    "a side of {:?} without a neighbour: {:?} stands on its {} (pounding between buildings is a [[contact]])",
                    w.facing,
                    self.buildings[n].name,
                    w.side.name()
                ),
            ));
        }
        if self
            .walls
            .iter()
            .any(|x| x.building == b && x.side == w.side)
        {
            return Err(choice(
                "side",
                format!("{:?}", w.side.name()),
                format!("one wall per side of {:?}", w.facing),
            ));
        }
        check(
            "gap",
            w.gap,
            w.gap >= 0.0 && w.gap.is_finite(),
            "gap >= 0 (m)",
        )?;
        let storeys = self.buildings[b].structure.storeys();
        let floors = w.floors.unwrap_or_else(|| vec![1]);
        if floors.is_empty() {
            return Err(choice("floors", "[]".into(), "at least one floor".into()));
        }
        for (k, f) in floors.iter().enumerate() {
            if !(1..=storeys).contains(f) || floors[..k].contains(f) {
                return Err(choice(
                    "floors",
                    format!("{floors:?}"),
                    format!("distinct floors 1..={storeys} of {:?}", w.facing),
                ));
            }
        }
        check_bumper(&w.bumper, w.gap)?;
        check_seat(w.seat)?;
        let contact = w.contact.prepare()?;
        self.walls.push(Wall {
            name: w.name,
            building: b,
            side: w.side,
            gap: w.gap,
            floors,
            contact,
            bumper: w.bumper,
            seat: w.seat,
        });
        Ok(self)
    }

    /// Puts a bumper on the contact between `a` and `b` (added before with [`Scenario::with_link`]).
    pub fn with_link_bumper(mut self, a: &str, b: &str, bumper: Bumper) -> Result<Self, Error> {
        let l = self.link_index(a, b)?;
        check_bumper(&Some(bumper.clone()), self.links[l].gap)?;
        self.links[l].bumper = Some(bumper);
        Ok(self)
    }

    /// Sets the seat length (m, > 0) of the joint between `a` and `b` for the unseating check.
    pub fn with_link_seat(mut self, a: &str, b: &str, seat: f64) -> Result<Self, Error> {
        let l = self.link_index(a, b)?;
        check_seat(Some(seat))?;
        self.links[l].seat = Some(seat);
        Ok(self)
    }

    /// Adds a device ([`DeviceSpec`]) between two neighbouring buildings, or a building and a wall beside it.
    pub fn with_device(mut self, d: DeviceSpec) -> Result<Self, Error> {
        let law = d.law.checked()?;
        let [a, b] = &d.between;
        let wall_of = |n: &str| self.walls.iter().position(|w| w.name == n);
        let (ends, default_floors) = match (wall_of(a), wall_of(b)) {
            (None, None) => {
                let (ia, ib) = (self.building_index(a)?, self.building_index(b)?);
                let (left, right) = (ia.min(ib), ia.max(ib));
                if right != left + 1 {
                    return Err(choice(
                        "between",
                        format!("[{a:?}, {b:?}]"),
                        "two buildings next to each other in the row, or a building and a wall beside it".into(),
                    ));
                }
                (
                    DeviceEnds::Buildings { left, right },
                    self.aligned_floors(left),
                )
            }
            (Some(w), None) | (None, Some(w)) => {
                let other = if wall_of(a).is_some() { b } else { a };
                let ib = self.building_index(other)?;
                if self.walls[w].building != ib {
                    return Err(choice(
                        "between",
                        format!("[{a:?}, {b:?}]"),
                        format!(
                            "a wall and the building it faces ({:?} faces {:?})",
                            self.walls[w].name, self.buildings[self.walls[w].building].name
                        ),
                    ));
                }
                (DeviceEnds::Wall { wall: w }, vec![(1, 1)])
            }
            (Some(_), Some(_)) => {
                return Err(choice(
                    "between",
                    format!("[{a:?}, {b:?}]"),
                    "at most one wall: a device joins a building to a neighbour or to a wall"
                        .into(),
                ))
            }
        };
        let (n_left, n_right) = match ends {
            DeviceEnds::Buildings { left, right } => (
                self.buildings[left].structure.storeys(),
                self.buildings[right].structure.storeys(),
            ),
            DeviceEnds::Wall { wall } => {
                let n = self.buildings[self.walls[wall].building]
                    .structure
                    .storeys();
                (n, n)
            }
        };
        let floors = d.floors.unwrap_or(default_floors);
        if floors.is_empty() {
            return Err(choice(
                "floors",
                "(default)".into(),
                "at least one pair of floors (none are at the same height: list them)".into(),
            ));
        }
        for (k, &(i, j)) in floors.iter().enumerate() {
            let wall_pair = matches!(ends, DeviceEnds::Wall { .. }) && i != j;
            if !(1..=n_left).contains(&i)
                || !(1..=n_right).contains(&j)
                || floors[..k].contains(&(i, j))
                || wall_pair
            {
                return Err(choice(
                    "floors",
                    format!("[{i}, {j}]"),
                    format!("distinct pairs of floors 1..={n_left} and 1..={n_right} (to a wall, the same floor twice)"),
                ));
            }
        }
        let n = self.devices.len() + 1;
        let name = d.name.unwrap_or_else(|| format!("{}{n}", law.name()));
        if name.is_empty() || self.devices.iter().any(|x| x.name == name) {
            return Err(choice(
                "name",
                format!("{name:?}"),
                "a name used by one device only".into(),
            ));
        }
        self.devices.push(Device {
            name,
            ends,
            floors,
            law,
        });
        Ok(self)
    }

    /// The walls.
    pub fn walls(&self) -> &[Wall] {
        &self.walls
    }
    /// The devices.
    pub fn devices(&self) -> &[Device] {
        &self.devices
    }

    /// The name of a site: `left|right` for a link, the wall's name for a wall.
    pub fn site_name(&self, site: Site) -> String {
        match site {
            Site::Link { link, .. } => self.link_name(link),
            Site::Wall { wall, .. } => self.walls[wall].name.clone(),
        }
    }

    /// The floor on each side of a site, left then right, from 1: a link's pair, or a wall's floor with
    /// `None` on the wall's side.
    pub fn site_sides(&self, site: Site) -> (Option<usize>, Option<usize>) {
        match site {
            Site::Link { floors, .. } => (Some(floors.0), Some(floors.1)),
            Site::Wall { wall, floor } => match self.walls[wall].side {
                Side::Right => (Some(floor), None),
                Side::Left => (None, Some(floor)),
            },
        }
    }

    fn link_index(&self, a: &str, b: &str) -> Result<usize, Error> {
        let (ia, ib) = (self.building_index(a)?, self.building_index(b)?);
        let (left, right) = (ia.min(ib), ia.max(ib));
        self.links
            .iter()
            .position(|l| l.left == left && l.right == right)
            .ok_or_else(|| {
                choice(
                    "between",
                    format!("[{a:?}, {b:?}]"),
                    "two buildings with a contact between them".into(),
                )
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
}

fn check_bumper(bumper: &Option<Bumper>, gap: f64) -> Result<(), Error> {
    if let Some(bm) = bumper {
        check(
            "bumper.thickness",
            bm.thickness,
            bm.thickness <= gap,
            "a bumper no thicker than the gap it stands in (m)",
        )?;
    }
    Ok(())
}

fn check_seat(seat: Option<f64>) -> Result<(), Error> {
    if let Some(s) = seat {
        check("seat", s, s > 0.0 && s.is_finite(), "seat > 0 (m)")?;
    }
    Ok(())
}
