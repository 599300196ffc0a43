//! Contact sites of buildings in plan: between two buildings whose façades face each other (found from the
//! plans' positions), and walls beside a façade; each level a floor pair at a point of the façade.

use super::facades::{facing, Facing};
use super::{ContactSite, Level, PlanLinkSpec, Scenario, Side, SiteKind, SitePlan};
use crate::contact::{ContactModel, Model, PreparedContact};
use crate::error::check;
use crate::structure::Plan;
use crate::Error;

fn choice(name: &'static str, value: String, allowed: String) -> Error {
    Error::Choice {
        name,
        value,
        allowed,
    }
}

/// The points along a façade spanning `(lo, hi)` (m, site frame): those given, each on it, or both ends.
fn points_on(given: Option<Vec<f64>>, (lo, hi): (f64, f64)) -> Result<Vec<f64>, Error> {
    let Some(p) = given else {
        return Ok(vec![lo, hi]);
    };
    if p.is_empty() {
        return Err(choice("points", "[]".into(), "at least one point".into()));
    }
    // A millimetre's grace: a point given at a corner to the digits a user types.
    let grace = 1e-3;
    for (k, &x) in p.iter().enumerate() {
        if !(x.is_finite() && x >= lo - grace && x <= hi + grace) || p[..k].contains(&x) {
            return Err(choice(
                "points",
                crate::words::number(x),
                format!(
                    "distinct points on the façade (on both façades between buildings): {} <= point <= {} (m, along the façade in the site's frame)",
                    crate::words::number(lo),
                    crate::words::number(hi)
                ),
            ));
        }
    }
    Ok(p.iter().map(|x| x.clamp(lo, hi)).collect())
}

impl Scenario {
    /// The plan of building `b`, or an error naming `key` if it has none.
    fn plan_of(&self, b: usize, key: &'static str) -> Result<&Plan, Error> {
        self.buildings[b].structure.plan().ok_or_else(|| {
            choice(
                key,
                format!("{:?}", self.buildings[b].name),
                "buildings in plan on both sides (a [building.plan] each): a building in one line meets its neighbours in the row".into(),
            )
        })
    }

    /// How buildings `a` and `b` (indices) face each other.
    pub(super) fn facing_of(&self, a: usize, b: usize) -> Result<Facing, Error> {
        let (pa, pb) = (self.plan_of(a, "between")?, self.plan_of(b, "between")?);
        facing(pa, pb, (&self.buildings[a].name, &self.buildings[b].name))
    }

    /// Adds a contact between two buildings in plan ([`PlanLinkSpec`]): their façades that face each other
    /// (from the plans' positions) give the direction and the gap; contact elements act along the façades'
    /// normal at each point and floor pair.
    pub fn with_plan_contact(mut self, spec: PlanLinkSpec) -> Result<Self, Error> {
        let [a, b] = &spec.between;
        let (ia, ib) = (self.building_index(a)?, self.building_index(b)?);
        if ia == ib {
            return Err(choice(
                "between",
                format!("[{a:?}, {b:?}]"),
                "two different buildings".into(),
            ));
        }
        let f = self.facing_of(ia, ib)?;
        let (left, right) = if f.first_is_left { (ia, ib) } else { (ib, ia) };
        if self
            .sites
            .iter()
            .any(|s| s.kind == SiteKind::Between { left, right })
        {
            return Err(choice(
                "between",
                format!("[{a:?}, {b:?}]"),
                "one contact entry per pair of buildings".into(),
            ));
        }
        // Floor pairs in the order of `between`, as the levels want them: (left, right).
        let floors = spec.floors.map(|f| {
            f.into_iter()
                .map(|(i, j)| if ia == left { (i, j) } else { (j, i) })
                .collect()
        });
        let floors = self.link_floors(left, right, floors)?;
        let along = points_on(spec.points, f.overlap)?;
        let mut site = self.plan_site(
            left,
            right,
            &f,
            &floors,
            along,
            spec.contact.prepare()?,
            true,
        );
        if let Some(bm) = spec.bumper {
            check(
                "bumper.thickness",
                bm.thickness,
                bm.thickness <= site.gap,
                "a bumper no thicker than the gap it stands in (m)",
            )?;
            site.bumper = Some(bm);
        }
        if let Some(seat) = spec.seat {
            check("seat", seat, seat > 0.0 && seat.is_finite(), "seat > 0 (m)")?;
            site.seat = Some(seat);
        }
        self.insert_link(site);
        Ok(self)
    }

    /// The site of a contact between buildings in plan `left` and `right` facing as `f`, at floor pairs
    /// `floors` and points `along` the façades.
    #[allow(clippy::too_many_arguments)]
    fn plan_site(
        &self,
        left: usize,
        right: usize,
        f: &Facing,
        floors: &[(usize, usize)],
        along: Vec<f64>,
        contact: PreparedContact,
        active: bool,
    ) -> ContactSite {
        let mut levels = Vec::new();
        let mut points = Vec::new();
        for &(l, r) in floors {
            for &t in &along {
                levels.push(Level {
                    left: Some(l),
                    right: Some(r),
                });
                points.push(f.point(t));
            }
        }
        ContactSite {
            name: format!(
                "{}|{}",
                self.buildings[left].name, self.buildings[right].name
            ),
            kind: SiteKind::Between { left, right },
            gap: if active { f.gap } else { super::NO_CONTACT_GAP },
            levels,
            contact,
            bumper: None,
            seat: None,
            active,
            support: 0,
            column: None,
            plan: Some(SitePlan {
                normal: f.normal,
                points,
                along,
            }),
        }
    }

    /// The levels and plan of a wall on `side` of building in plan `b` at `floors`, at `points` along the
    /// façade (default its corners).
    pub(super) fn plan_wall_levels(
        &self,
        b: usize,
        side: Side,
        floors: &[usize],
        points: Option<Vec<f64>>,
    ) -> Result<(Vec<Level>, SitePlan), Error> {
        let p = self.plan_of(b, "side")?;
        let (o, s) = (p.origin(), p.size());
        // The façade: its coordinate across, and its extent along.
        let (plane, extent) = match side {
            Side::Left => (o.0, (o.1, o.1 + s.1)),
            Side::Right => (o.0 + s.0, (o.1, o.1 + s.1)),
            Side::South => (o.1, (o.0, o.0 + s.0)),
            Side::North => (o.1 + s.1, (o.0, o.0 + s.0)),
        };
        let along = points_on(points, extent)?;
        let outward = side.outward();
        let mut levels = Vec::new();
        let mut at = Vec::new();
        for &fl in floors {
            for &t in &along {
                levels.push(if side.negative() {
                    Level {
                        left: None,
                        right: Some(fl),
                    }
                } else {
                    Level {
                        left: Some(fl),
                        right: None,
                    }
                });
                at.push(if outward.0 != 0.0 {
                    (plane, t)
                } else {
                    (t, plane)
                });
            }
        }
        // The normal points along the positive axis, as between neighbours: a wall on the negative side is
        // the left end of its elements.
        let normal = (outward.0.abs(), outward.1.abs());
        Ok((
            levels,
            SitePlan {
                normal,
                points: at,
                along,
            },
        ))
    }

    /// Inactive sites between every pair of buildings in plan whose façades face each other and that have
    /// no contact entry, at their floors at the same height and the ends of the façades' overlap (for a run
    /// without contact, [`Scenario::without_contact`]).
    pub(super) fn plan_pairs_without_contact(&self, s: &mut Scenario) {
        let n = self.buildings.len();
        for a in 0..n {
            for b in a + 1..n {
                let Ok(f) = self.facing_of(a, b) else {
                    continue;
                };
                let (left, right) = if f.first_is_left { (a, b) } else { (b, a) };
                if s.sites
                    .iter()
                    .any(|l| l.kind == SiteKind::Between { left, right })
                {
                    continue;
                }
                let floors = self.aligned_floor_pairs(left, right);
                // Any contact model: it never acts. Hooke's needs no calibration.
                let prepared = ContactModel::new(Model::Hooke, 1.0, 1.0).and_then(|c| c.prepare());
                if let (false, Ok(contact)) = (floors.is_empty(), prepared) {
                    let along = vec![f.overlap.0, f.overlap.1];
                    let site = self.plan_site(left, right, &f, &floors, along, contact, false);
                    s.insert_link(site);
                }
            }
        }
    }
}
