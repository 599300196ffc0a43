//! Contact sites: where floors can strike something. A site is a contact between two neighbouring
//! buildings or a wall beside a building; both are listed together ([`ContactSite`]), each with its kind.
//!
//! - A **contact** between neighbours joins floors of the left building to floors of the right one, with a
//!   gap at rest (m); the effective mass of an impact is `m_L m_R / (m_L + m_R)`.
//! - A **wall** is fixed to the ground beside a building, on its left or right, at a clear distance `gap`
//!   (m); the floors listed strike it through contact elements whose other end is the ground, with the floor's
//!   own mass as the effective mass of each impact (`docs/structures.md`). A moat wall around an isolated
//!   building and a bridge's abutment are walls.
//! - A **bumper** of finite thickness `t` (m) sits on the face of a site: its soft law acts on the layer's
//!   compression from the moment the layer touches (at a closing of `gap - t`); once the compression reaches
//!   `max_strain t` the layer is consumed and the site's own (hard) law acts as well, on the penetration
//!   beyond that point. The force is continuous, and a bumper whose layer is never consumed is exactly the
//!   soft law. The two laws are two contact elements on the same floor pair, each with its own impacts and
//!   calibration. This two-stage form is ours; Polycarpou, Komodromos & Polycarpou (2013) proposed the idea
//!   of a threshold at the layer's thickness in a nonlinear rubber-bumper model.
//! - A **seat** (m) on a site is the length of the support that a deck's end rests on: the run reports the
//!   largest opening of the joint (moving apart, or away from the wall) and whether it exceeded the seat
//!   (unseating).

use crate::contact::{ContactModel, PreparedContact};
use crate::error::check;
use crate::Error;

crate::named! {
    /// Which side of a building a wall stands on.
    pub enum Side: "side" {
        /// Towards negative displacements (for a building in plan: its façade at the smallest x, west).
        Left = "left",
        /// Towards positive displacements (for a building in plan: its façade at the largest x, east).
        Right = "right",
        /// For a building in plan only: its façade at the smallest y.
        South = "south",
        /// For a building in plan only: its façade at the largest y.
        North = "north",
    }
}

impl Side {
    /// The direction from the building to a wall on this side, a unit vector in plan (x, y).
    pub fn outward(self) -> (f64, f64) {
        match self {
            Side::Left => (-1.0, 0.0),
            Side::Right => (1.0, 0.0),
            Side::South => (0.0, -1.0),
            Side::North => (0.0, 1.0),
        }
    }

    /// Whether a wall on this side stands towards negative coordinates (left, south): the building is then
    /// the right-hand end of the wall's contact elements, as in a row.
    pub fn negative(self) -> bool {
        matches!(self, Side::Left | Side::South)
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

/// What a site is: a contact between two neighbours, or a wall beside a building.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SiteKind {
    /// Between buildings `left` and `right = left + 1` (indices in [`super::Scenario::buildings`]).
    Between {
        /// Index of the left building.
        left: usize,
        /// Index of the right building.
        right: usize,
    },
    /// A wall fixed to the ground beside building `building`, on its `side`.
    Wall {
        /// Index of the building it faces.
        building: usize,
        /// Which side of that building.
        side: Side,
    },
}

/// One level of a site: the floor on each side of the joint, from 1 (`None` on a wall's side).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Level {
    /// The floor of the left building (`None`: a wall on the left of the right building).
    pub left: Option<usize>,
    /// The floor of the right building (`None`: a wall on the right of the left building).
    pub right: Option<usize>,
}

impl Level {
    /// The floor of a building that strikes at this level (the left one's, if both do), from 1.
    pub fn floor(&self) -> usize {
        self.left.or(self.right).unwrap_or(0)
    }
}

/// A contact site: contact elements at each of its levels, with one law, a gap, and optionally a bumper
/// and a seat.
#[derive(Clone, Debug)]
pub struct ContactSite {
    /// Its name: `left|right` (the names of the two buildings) for a contact between neighbours, the
    /// wall's own name for a wall.
    pub name: String,
    /// Between neighbours, or a wall.
    pub kind: SiteKind,
    /// Gap at rest, m.
    pub gap: f64,
    /// Its levels, each a contact element (with a bumper, two on the same floors).
    pub levels: Vec<Level>,
    /// The contact law of every element (behind the bumper, if there is one).
    pub contact: PreparedContact,
    /// A bumper on its face.
    pub bumper: Option<Bumper>,
    /// Seat length of the joint for the unseating check, m.
    pub seat: Option<f64>,
    /// Whether its contacts act: a site of a run without contact ([`super::Scenario::with_contacts_off`])
    /// only records the largest closing and opening of each level.
    pub active: bool,
    /// For buildings in plan: the direction the contact elements act along and the point of each level.
    pub plan: Option<SitePlan>,
    /// A wall's support (0: the scenario's record; `k + 1`: [`super::Scenario::supports`]`[k]`); 0 between
    /// buildings (each moves with its own).
    pub support: usize,
    /// A slab striking a neighbour's column ([`super::Scenario::with_column_contact`]).
    pub column: Option<SiteColumn>,
}

/// A site where a slab strikes a neighbour: between its floors (a column struck at a height), or at one of
/// them (`struck` `None`: a floor contact, made by a column entry).
#[derive(Clone, Debug, PartialEq)]
pub struct SiteColumn {
    /// Whether the struck building is the left one.
    pub on_left: bool,
    /// The column struck, between floors `storey - 1` and `storey` of its building (`None`: the slab meets a
    /// floor, and the level's floors say which).
    pub struck: Option<crate::structure::StruckColumn>,
    /// The storey struck, from 1 (its building's), or the floor met.
    pub storey: usize,
}

/// What a slab striking a neighbour's column is given: checked by [`super::Scenario::with_column_contact`]
/// (a scenario file's `[[column_contact]]`).
#[derive(Clone, Debug)]
pub struct ColumnLinkSpec {
    /// The building whose slab strikes, and the slab's floor, from 1.
    pub slab: (String, usize),
    /// The neighbour whose column is struck (at the slab's elevation).
    pub column: String,
    /// Gap at rest between the slab's edge and the column, m (>= 0).
    pub gap: f64,
    /// The contact law.
    pub contact: ContactModel,
    /// Flexural rigidity of the column (or of the line of columns struck together), N m^2.
    pub ei: f64,
    /// Its mass, kg.
    pub mass: f64,
    /// Shear capacity at its ends, N.
    pub shear_capacity: Option<f64>,
    /// Moment capacity at its ends, N m.
    pub moment_capacity: Option<f64>,
}

/// Where the contact elements of a site between buildings in plan act: along the normal of the facing
/// façades, at a point of the façade per level.
#[derive(Clone, Debug, PartialEq)]
pub struct SitePlan {
    /// The unit normal of the façades, from the left building (or from the building to a wall) towards the
    /// right building (or the wall): `(±1, 0)` or `(0, ±1)`.
    pub normal: (f64, f64),
    /// The point of each level on the façade of the left building (a wall's building) at rest, in the site's
    /// frame, m; `points[k]` is that of `levels[k]`.
    pub points: Vec<(f64, f64)>,
    /// The points given along the façade (m, the site-frame coordinate along the façade), per floor pair.
    pub along: Vec<f64>,
}

impl ContactSite {
    /// Whether the site is a wall.
    pub fn is_wall(&self) -> bool {
        matches!(self.kind, SiteKind::Wall { .. })
    }

    /// The closing at which its face is first touched, m: the gap, less a bumper's thickness.
    pub fn touch_gap(&self) -> f64 {
        self.bumper
            .as_ref()
            .map_or(self.gap, |b| b.gaps(self.gap).0)
    }
}

crate::named! {
    /// Which law of a site an impact is of.
    pub enum Layer: "layer" {
        /// The site's law, without a bumper.
        Direct = "direct",
        /// A bumper's soft layer.
        Bumper = "bumper",
        /// The hard law behind a bumper whose layer was consumed.
        Consumed = "consumed",
    }
}

/// What a contact between two neighbouring buildings is given: named fields, checked by
/// [`super::Scenario::with_contact`] (a scenario file's `[[contact]]`).
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

/// What a contact between two buildings in plan is given: named fields, checked by
/// [`super::Scenario::with_plan_contact`] (a scenario file's `[[contact]]` between buildings with a
/// `[building.plan]`). The gap and the direction come from the plans' positions: the façades that face each
/// other.
#[derive(Clone, Debug)]
pub struct PlanLinkSpec {
    /// The two buildings, by name.
    pub between: [String; 2],
    /// Floor pairs `(floor of the first building of between, floor of the second)`, from 1 (`None`: every
    /// pair of floors at the same height, within 1 mm).
    pub floors: Option<Vec<(usize, usize)>>,
    /// Where along the façades the contact elements act, m: the site-frame coordinate along the façade (y
    /// for façades facing along x, x for façades facing along y), each on both façades (`None`: both ends
    /// of the façades' overlap, each a corner of one of the plans).
    pub points: Option<Vec<f64>>,
    /// The contact law of every element (one per point and floor pair; its stiffness is that of one point).
    pub contact: ContactModel,
    /// A bumper on the façades.
    pub bumper: Option<Bumper>,
    /// Seat length for the unseating check, m (> 0).
    pub seat: Option<f64>,
}

/// What a wall is given: named fields, checked by [`super::Scenario::with_wall`].
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
    /// For a building in plan: where along its façade the contact elements act, m (the site-frame
    /// coordinate along the façade; default its two corners). `None` for a building in one line.
    pub points: Option<Vec<f64>>,
    /// The contact law.
    pub contact: ContactModel,
    /// A bumper on its face.
    pub bumper: Option<Bumper>,
    /// Seat length, m (> 0).
    pub seat: Option<f64>,
}
