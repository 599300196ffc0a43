//! The summary of a contact site: a contact between neighbours or a wall, its law, and its totals.

use pounding::analysis::{
    Bumper, ContactSite, Level, Results, Scenario, Side, SiteKind, SiteResponse,
};
use pounding::contact::{DampingParameter, Model, PreparedContact, Restitution};
use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

/// Where a site is: between two neighbouring buildings, or a wall beside one (`kind`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum SitePlace {
    /// A contact between two neighbouring buildings.
    Contact {
        /// The left and the right building.
        between: [String; 2],
    },
    /// A wall fixed to the ground beside a building.
    Wall {
        /// The building it faces.
        facing: String,
        /// Which side of that building.
        side: Side,
    },
}

/// One level of a site: the floor on each side of the joint, from 1 (absent on a wall's side).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
pub struct LevelSummary {
    /// The floor of the left building, from 1 (absent: a wall on the left).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub left: Option<usize>,
    /// The floor of the right building, from 1 (absent: a wall on the right).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub right: Option<usize>,
}

impl From<Level> for LevelSummary {
    fn from(l: Level) -> Self {
        Self {
            left: l.left,
            right: l.right,
        }
    }
}

/// The damping parameter a contact law was given (`name`, and its `value`, dimensionless).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(tag = "name", rename_all = "kebab-case")]
pub enum DampingSummary {
    /// An elastic law: no damping.
    None,
    /// Calibrated anew at every impact (`impact-material` with a given `max_penetration`, a table `e(v_i)`).
    PerImpact,
    /// Damping ratio of a linear dashpot, `c = 2 zeta sqrt(k m)`.
    Zeta {
        /// Its value.
        value: f64,
    },
    /// Hunt–Crossley factor.
    Chi {
        /// Its value.
        value: f64,
    },
    /// `alpha` of Papi & Toopchi-Nezhad (2022).
    Alpha {
        /// Its value.
        value: f64,
    },
    /// Jankowski's damping ratio.
    Xi {
        /// Its value.
        value: f64,
    },
    /// The design `e` of the bilinear loop.
    #[serde(rename = "e_design")]
    EDesign {
        /// Its value.
        value: f64,
    },
    /// A material damping constant D/K of the Hunt–Crossley law, s/m (the one value not dimensionless).
    #[serde(rename = "damping_constant")]
    DampingConstant {
        /// Its value, s/m.
        value: f64,
    },
    /// Thornton's spheres: no damping, plastic flow at this yield pressure, Pa.
    #[serde(rename = "yield_pressure")]
    YieldPressure {
        /// Yield pressure, Pa.
        value: f64,
        /// The spheres' radius, m.
        radius: f64,
    },
}

impl DampingSummary {
    /// The parameter fixed for a prepared contact (`None`: per impact).
    pub fn of(p: Option<DampingParameter>) -> Self {
        match p {
            None => DampingSummary::PerImpact,
            Some(DampingParameter::None) => DampingSummary::None,
            Some(DampingParameter::Zeta(value)) => DampingSummary::Zeta { value },
            Some(DampingParameter::Chi(value)) => DampingSummary::Chi { value },
            Some(DampingParameter::Papi { alpha, .. }) => DampingSummary::Alpha { value: alpha },
            Some(DampingParameter::Xi(value)) => DampingSummary::Xi { value },
            Some(DampingParameter::EDesign(value)) => DampingSummary::EDesign { value },
            Some(DampingParameter::DampingConstant(value)) => {
                DampingSummary::DampingConstant { value }
            }
            Some(DampingParameter::Yield(s)) => DampingSummary::YieldPressure {
                value: s.yield_pressure,
                radius: s.radius,
            },
        }
    }
}

/// A contact law as it was run.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
pub struct ContactLawSummary {
    /// The contact model.
    pub model: Model,
    /// The coefficient of restitution asked of it (dimensionless); absent for an elastic model (hooke,
    /// hertz), which delivers 1.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub e: Option<f64>,
    /// The table `e(v_i)` asked of it instead, rows `[v_i (m/s), e]`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub e_table: Option<Vec<[f64; 2]>>,
    /// Stiffness, N/m^exponent.
    pub stiffness: f64,
    /// Exponent of the force law (dimensionless).
    pub exponent: f64,
    /// Its damping parameter.
    pub damping_parameter: DampingSummary,
}

impl ContactLawSummary {
    /// The law of `contact`.
    pub fn of(contact: &PreparedContact) -> Self {
        let spec = contact.spec();
        Self {
            model: spec.model(),
            e: spec.asked_restitution(),
            e_table: match spec.asked() {
                Some(Restitution::Table(t)) => {
                    Some(t.points().iter().map(|p| [p.0, p.1]).collect())
                }
                _ => None,
            },
            stiffness: spec.stiffness(),
            exponent: spec.exponent(),
            damping_parameter: DampingSummary::of(contact.parameter()),
        }
    }
}

/// A bumper on a site's face.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
pub struct BumperSummary {
    /// Thickness of the layer, m.
    pub thickness: f64,
    /// Compressive strain at which the layer is consumed (dimensionless).
    pub max_strain: f64,
    /// The layer's law.
    #[serde(flatten)]
    pub law: ContactLawSummary,
}

impl BumperSummary {
    fn of(b: &Bumper) -> Self {
        Self {
            thickness: b.thickness,
            max_strain: b.max_strain,
            law: ContactLawSummary::of(&b.contact),
        }
    }
}

/// The range of the coefficient of restitution that a site's ended impacts delivered.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
pub struct DeliveredE {
    /// Smallest, dimensionless.
    pub min: f64,
    /// Largest, dimensionless.
    pub max: f64,
    /// Why it differs from the e asked.
    pub note: String,
}

/// A contact site as it was run, and its totals.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
pub struct SiteSummary {
    /// Between neighbours, or a wall.
    #[serde(flatten)]
    pub place: SitePlace,
    /// Its name: `left|right` between neighbours, the wall's name for a wall.
    pub name: String,
    /// Gap at rest, m.
    pub gap: f64,
    /// Its levels, each a contact element.
    pub levels: Vec<LevelSummary>,
    /// Between buildings in plan: the unit normal of the façades (from the left building, or from the
    /// building to the wall, along a positive axis), `[x, y]`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub normal: Option<[f64; 2]>,
    /// Between buildings in plan: each level's point on the left building's façade (the wall's building's)
    /// at rest, `[x, y]` in the site's frame, m.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub points: Option<Vec<[f64; 2]>>,
    /// Its law (behind the bumper, if there is one).
    #[serde(flatten)]
    pub law: ContactLawSummary,
    /// The bumper on its face.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bumper: Option<BumperSummary>,
    /// Impacts of the hard law behind a consumed bumper (with a bumper only).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub consumed: Option<usize>,
    /// Number of impacts (on the bumper's face, if there is one).
    pub impacts: usize,
    /// Largest contact force of a level, N.
    pub peak_force: f64,
    /// Largest penetration of any impact, m.
    pub max_penetration: f64,
    /// Energy dissipated by the site's contacts, J.
    pub dissipated_energy: f64,
    /// Largest closing of each level, m (`u_left - u_right`; for a wall, a floor's displacement towards it).
    pub max_closing: Vec<f64>,
    /// Largest opening of each level, m (`u_right - u_left`; for a wall, away from it).
    pub max_opening: Vec<f64>,
    /// Seat length of the joint, m.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub seat: Option<f64>,
    /// Whether the largest opening exceeded the seat.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub unseated: Option<bool>,
    /// The delivered e of its ended impacts (absent without one).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub e_delivered: Option<DeliveredE>,
    /// A slab striking a column between its floors: the column and its demand.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub column: Option<ColumnSummary>,
}

/// A column struck between its floors, and its demand.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
pub struct ColumnSummary {
    /// The building whose column is struck.
    pub building: String,
    /// The storey struck, from 1.
    pub storey: usize,
    /// Height of the strike above the storey's lower floor, m.
    pub height: f64,
    /// The column's length (the storey's height), m.
    pub length: f64,
    /// Its flexural rigidity, N m^2.
    #[serde(rename = "EI")]
    pub ei: f64,
    /// Its stiffness at the point, `3 EI L^3 / (a^3 b^3)`, N/m.
    pub stiffness: f64,
    /// The mass its point carries, kg.
    pub point_mass: f64,
    /// Largest |force| on it at the point, N.
    pub peak_force: f64,
    /// Largest |shear| at its lower and upper ends, N: the load at the point's part and its storey drift's.
    pub peak_shear: [f64; 2],
    /// Largest |moment| at its lower and upper ends, N m: the load's part and the drift's.
    pub peak_moment: [f64; 2],
    /// Shear capacity, N.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub shear_capacity: Option<f64>,
    /// Moment capacity, N m.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub moment_capacity: Option<f64>,
    /// Whether a shear exceeded the shear capacity.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub shear_exceeded: Option<bool>,
    /// Whether a moment exceeded the moment capacity.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub moment_exceeded: Option<bool>,
}

impl SiteSummary {
    /// Site `i` of `s` and its totals in `r`.
    pub fn of(s: &Scenario, r: &Results, i: usize) -> Self {
        let (site, lr): (&ContactSite, &SiteResponse) = (&s.sites()[i], &r.sites[i]);
        let names = |b: usize| s.buildings()[b].name.clone();
        let place = match site.kind {
            SiteKind::Between { left, right } => SitePlace::Contact {
                between: [names(left), names(right)],
            },
            SiteKind::Wall { building, side } => SitePlace::Wall {
                facing: names(building),
                side,
            },
        };
        Self {
            place,
            name: site.name.clone(),
            gap: site.gap,
            levels: site.levels.iter().map(|&l| l.into()).collect(),
            normal: site.plan.as_ref().map(|p| [p.normal.0, p.normal.1]),
            points: site
                .plan
                .as_ref()
                .map(|p| p.points.iter().map(|q| [q.0, q.1]).collect()),
            law: ContactLawSummary::of(&site.contact),
            bumper: site.bumper.as_ref().map(BumperSummary::of),
            consumed: site.bumper.as_ref().map(|_| lr.consumed),
            impacts: lr.impacts,
            peak_force: lr.peak_force,
            max_penetration: lr.max_penetration,
            dissipated_energy: lr.dissipated_energy,
            max_closing: lr.max_closing.clone(),
            max_opening: lr.max_opening.clone(),
            seat: site.seat,
            unseated: site.seat.and(lr.unseated),
            column: site.column.as_ref().and_then(|c| {
                let (col, resp) = (c.struck?, lr.column.as_ref()?);
                let SiteKind::Between { left, right } = site.kind else {
                    return None;
                };
                Some(ColumnSummary {
                    building: names(if c.on_left { left } else { right }),
                    storey: c.storey,
                    height: col.a,
                    length: col.length,
                    ei: col.ei,
                    stiffness: col.stiffness(),
                    point_mass: col.point_mass(),
                    peak_force: resp.peak_force,
                    peak_shear: [resp.peak_shear.0, resp.peak_shear.1],
                    peak_moment: [resp.peak_moment.0, resp.peak_moment.1],
                    shear_capacity: col.shear_capacity,
                    moment_capacity: col.moment_capacity,
                    shear_exceeded: resp.shear_exceeded,
                    moment_exceeded: resp.moment_exceeded,
                })
            }),
            e_delivered: r.delivered_e(i).map(|(min, max)| DeliveredE {
                min,
                max,
                note: super::inside::delivered_e_note(super::inside::Meeting::of_site(s, site)),
            }),
        }
    }

    /// Whether it is a wall.
    pub fn is_wall(&self) -> bool {
        matches!(self.place, SitePlace::Wall { .. })
    }

    /// The largest opening of any level, m.
    pub fn largest_opening(&self) -> f64 {
        self.max_opening.iter().fold(0.0, |a, &b| a.max(b))
    }
}
