//! Adding contact sites and devices to a scenario, each checked once, and the same scenario without
//! contact.

use super::{
    Bumper, ContactSite, Device, DeviceEnds, DeviceSpec, Level, LinkSpec, Scenario, Side, SiteKind,
    WallSpec,
};
use crate::contact::{ContactModel, Model};
use crate::error::check;
use crate::Error;

/// The gap the contact elements of an inactive site act at ([`ContactSite::active`]), m: beyond any motion,
/// yet finite, so that penetrations `u_L - u_R - gap` stay ordinary numbers.
pub const NO_CONTACT_GAP: f64 = 1e100;

fn choice(name: &'static str, value: String, allowed: String) -> Error {
    Error::Choice {
        name,
        value,
        allowed,
    }
}

/// The levels of a contact between neighbours at floor pairs `floors`.
fn pair_levels(floors: &[(usize, usize)]) -> Vec<Level> {
    floors
        .iter()
        .map(|&(l, r)| Level {
            left: Some(l),
            right: Some(r),
        })
        .collect()
}

impl Scenario {
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

    /// The left and right building of the neighbours `a` and `b` (in either order).
    fn neighbours(&self, a: &str, b: &str) -> Result<(usize, usize), Error> {
        let (ia, ib) = (self.building_index(a)?, self.building_index(b)?);
        let (left, right) = (ia.min(ib), ia.max(ib));
        if right != left + 1 {
            return Err(choice(
                "between",
                format!("[{a:?}, {b:?}]"),
                "two buildings next to each other in the row (as listed, left to right)".into(),
            ));
        }
        Ok((left, right))
    }

    /// Floor pairs given for a contact between `left` and `right`, checked; by default the floors at the
    /// same height.
    pub(super) fn link_floors(
        &self,
        left: usize,
        right: usize,
        floors: Option<Vec<(usize, usize)>>,
    ) -> Result<Vec<(usize, usize)>, Error> {
        let (bl, br) = (&self.buildings[left], &self.buildings[right]);
        let (nl, nr) = (bl.structure.storeys(), br.structure.storeys());
        let Some(f) = floors else {
            let pairs = self.aligned_floor_pairs(left, right);
            if pairs.is_empty() {
                return Err(choice(
                    "floors",
                    "(default)".into(),
                    format!(
                        "no floors of {:?} and {:?} are at the same height; list them, as floors = [[1, 1]]",
                        bl.name, br.name
                    ),
                ));
            }
            return Ok(pairs);
        };
        if f.is_empty() {
            return Err(choice(
                "floors",
                "[]".into(),
                "at least one pair [floor of left, floor of right]".into(),
            ));
        }
        for (k, &(i, j)) in f.iter().enumerate() {
            if f[..k].contains(&(i, j)) {
                return Err(choice(
                    "floors",
                    format!("[{i}, {j}] twice"),
                    "each pair of floors once (two elements on one pair would double its contact)"
                        .into(),
                ));
            }
            if !(1..=nl).contains(&i) || !(1..=nr).contains(&j) {
                return Err(choice(
                    "floors",
                    format!("[{i}, {j}]"),
                    format!(
                        "floors 1..={nl} of {:?} and 1..={nr} of {:?}",
                        bl.name, br.name
                    ),
                ));
            }
        }
        Ok(f)
    }

    /// Puts `site` among the sites: contacts between neighbours left to right, before the walls.
    pub(super) fn insert_link(&mut self, site: ContactSite) {
        let left_of = |s: &ContactSite| match s.kind {
            SiteKind::Between { left, .. } => Some(left),
            SiteKind::Wall { .. } => None,
        };
        let new = left_of(&site);
        let at = self
            .sites
            .iter()
            .position(|s| left_of(s).is_none_or(|l| Some(l) > new))
            .unwrap_or(self.sites.len());
        self.sites.insert(at, site);
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
        let (left, right) = self.neighbours(a, b)?;
        if self.link_index(a, b).is_ok() {
            return Err(choice(
                "between",
                format!("[{a:?}, {b:?}]"),
                "one contact entry per pair of buildings".into(),
            ));
        }
        check("gap", gap, gap >= 0.0, "gap >= 0 (m)")?;
        let floors = self.link_floors(left, right, floors)?;
        let contact = contact.prepare()?;
        let name = format!(
            "{}|{}",
            self.buildings[left].name, self.buildings[right].name
        );
        self.insert_link(ContactSite {
            name,
            kind: SiteKind::Between { left, right },
            gap,
            levels: pair_levels(&floors),
            contact,
            bumper: None,
            seat: None,
            active: true,
            plan: None,
            support: 0,
            column: None,
        });
        Ok(self)
    }

    /// The site of the contact between the neighbours `a` and `b`.
    fn link_index(&self, a: &str, b: &str) -> Result<usize, Error> {
        let (ia, ib) = (self.building_index(a)?, self.building_index(b)?);
        // Buildings in plan are left and right as their façades face, not as listed.
        let pairs = [
            SiteKind::Between {
                left: ia,
                right: ib,
            },
            SiteKind::Between {
                left: ib,
                right: ia,
            },
        ];
        self.sites
            .iter()
            // A column contact is an entry of its own.
            .position(|s| pairs.contains(&s.kind) && s.column.is_none())
            .ok_or_else(|| {
                choice(
                    "between",
                    format!("[{a:?}, {b:?}]"),
                    "two buildings with a contact between them".into(),
                )
            })
    }

    /// Puts a bumper on the contact between `a` and `b` (added before with [`Scenario::with_link`]).
    pub fn with_link_bumper(mut self, a: &str, b: &str, bumper: Bumper) -> Result<Self, Error> {
        let l = self.link_index(a, b)?;
        check_bumper(&Some(bumper.clone()), self.sites[l].gap)?;
        self.sites[l].bumper = Some(bumper);
        Ok(self)
    }

    /// Sets the seat length (m, > 0) of the joint between `a` and `b` for the unseating check.
    pub fn with_link_seat(mut self, a: &str, b: &str, seat: f64) -> Result<Self, Error> {
        let l = self.link_index(a, b)?;
        check_seat(Some(seat))?;
        self.sites[l].seat = Some(seat);
        Ok(self)
    }

    /// Adds a wall ([`WallSpec`]): it faces a building of the row on a side without a neighbour, at a gap
    /// >= 0 (m), struck by distinct floors of that building; a bumper must fit in the gap.
    pub fn with_wall(mut self, w: WallSpec) -> Result<Self, Error> {
        let b = self
            .building_index(&w.facing)
            .map_err(|_| choice("facing", format!("{:?}", w.facing), self.names()))?;
        let taken = |n: &str| {
            self.buildings.iter().any(|x| x.name == n) || self.sites.iter().any(|s| s.name == n)
        };
        if taken(&w.name) {
            return Err(choice(
                "name",
                format!("{:?}", w.name),
                "a name used by no building and no other wall".into(),
            ));
        }
        let in_plan = self.buildings[b].structure.plan().is_some();
        let neighbour = match w.side {
            _ if in_plan => None,
            Side::Left => b.checked_sub(1),
            Side::Right => (b + 1 < self.buildings.len()).then_some(b + 1),
            Side::South | Side::North => {
                return Err(choice(
                    "side",
                    format!("{:?}", w.side.name()),
                    format!(
                        "left or right of {:?}: south and north are sides of a building in plan",
                        w.facing
                    ),
                ))
            }
        };
        if w.points.is_some() && !in_plan {
            return Err(choice(
                "points",
                format!("{:?}", w.points.as_deref().unwrap_or_default()),
                format!(
                    "points along a façade apply to a building in plan; {:?} stands in one line",
                    w.facing
                ),
            ));
        }
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
        let kind = SiteKind::Wall {
            building: b,
            side: w.side,
        };
        if self.sites.iter().any(|s| s.kind == kind) {
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
        let (levels, plan) = if in_plan {
            let (levels, plan) = self.plan_wall_levels(b, w.side, &floors, w.points)?;
            (levels, Some(plan))
        } else {
            let level = |f: usize| match w.side.negative() {
                false => Level {
                    left: Some(f),
                    right: None,
                },
                true => Level {
                    left: None,
                    right: Some(f),
                },
            };
            (floors.iter().map(|&f| level(f)).collect(), None)
        };
        self.sites.push(ContactSite {
            name: w.name,
            kind,
            gap: w.gap,
            levels,
            contact,
            bumper: w.bumper,
            seat: w.seat,
            active: true,
            plan,
            support: 0,
            column: None,
        });
        Ok(self)
    }

    /// The site of the wall called `name`.
    fn wall(&self, name: &str) -> Option<usize> {
        self.sites
            .iter()
            .position(|s| s.is_wall() && s.name == name)
    }

    /// What a device's `between` joins, and its default floor pairs.
    fn device_ends(
        &self,
        [a, b]: &[String; 2],
    ) -> Result<(DeviceEnds, Vec<(usize, usize)>), Error> {
        match (self.wall(a), self.wall(b)) {
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
                Ok((
                    DeviceEnds::Buildings { left, right },
                    self.aligned_floors(left),
                ))
            }
            (Some(w), None) | (None, Some(w)) => {
                let other = if self.wall(a).is_some() { b } else { a };
                let ib = self.building_index(other)?;
                let faced = self.site_building(&self.sites[w]);
                if faced != ib {
                    return Err(choice(
                        "between",
                        format!("[{a:?}, {b:?}]"),
                        format!(
                            "a wall and the building it faces ({:?} faces {:?})",
                            self.sites[w].name, self.buildings[faced].name
                        ),
                    ));
                }
                Ok((DeviceEnds::Wall { site: w }, vec![(1, 1)]))
            }
            (Some(_), Some(_)) => Err(choice(
                "between",
                format!("[{a:?}, {b:?}]"),
                "at most one wall: a device joins a building to a neighbour or to a wall".into(),
            )),
        }
    }

    /// Adds a device ([`DeviceSpec`]) between two neighbouring buildings, or a building and a wall beside it.
    pub fn with_device(mut self, d: DeviceSpec) -> Result<Self, Error> {
        d.law.law()?;
        let (ends, default_floors) = self.device_ends(&d.between)?;
        let planned = |b: usize| self.buildings[b].structure.plan().is_some();
        let in_plan = match ends {
            DeviceEnds::Buildings { left, right } => planned(left) || planned(right),
            DeviceEnds::Wall { site } => planned(self.site_building(&self.sites[site])),
        };
        if in_plan {
            return Err(choice(
                "between",
                format!("[{:?}, {:?}]", d.between[0], d.between[1]),
                "buildings in one line: devices on buildings in plan are not modelled yet".into(),
            ));
        }
        let storeys = |b: usize| self.buildings[b].structure.storeys();
        let (n_left, n_right) = match ends {
            DeviceEnds::Buildings { left, right } => (storeys(left), storeys(right)),
            DeviceEnds::Wall { site } => {
                let n = storeys(self.site_building(&self.sites[site]));
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
        let name = d.name.unwrap_or_else(|| format!("{}{n}", d.law.name()));
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
            law: d.law,
        });
        Ok(self)
    }

    /// The same scenario with every site inactive ([`ContactSite::active`]): contacts and walls (with
    /// their bumpers) stay in the scenario, with their gaps, and record each level's largest closing and
    /// opening, but never act; devices stay (they are part of the structure). The run a scenario's
    /// `contacts = "off"` asks for: the response that pounding amplifies.
    pub fn with_contacts_off(mut self) -> Scenario {
        for site in &mut self.sites {
            site.active = false;
        }
        self
    }

    /// The same scenario without contact ([`Scenario::with_contacts_off`]), every pair of neighbours
    /// linked: one without a contact entry gets an inactive site at its floors at the same height, so that
    /// a run records each floor pair's largest closing ([`super::SiteResponse::max_closing`]); walls record
    /// the largest approach to each. Neighbours without a contact entry and without floors at the same
    /// height stay unlinked.
    pub fn without_contact(&self) -> Scenario {
        let mut s = self.clone().with_contacts_off();
        self.plan_pairs_without_contact(&mut s);
        for left in 0..self.buildings.len().saturating_sub(1) {
            let in_plan = |b: usize| self.buildings[b].structure.plan().is_some();
            if in_plan(left) || in_plan(left + 1) {
                continue;
            }
            let pair = SiteKind::Between {
                left,
                right: left + 1,
            };
            if s.sites.iter().any(|l| l.kind == pair && l.column.is_none()) {
                continue;
            }
            let floors = self.aligned_floors(left);
            // Any contact model: it never acts. Hooke's needs no calibration.
            let prepared = ContactModel::new(Model::Hooke, 1.0, 1.0).and_then(|c| c.prepare());
            if let (false, Ok(contact)) = (floors.is_empty(), prepared) {
                let name = format!(
                    "{}|{}",
                    self.buildings[left].name,
                    self.buildings[left + 1].name
                );
                s.insert_link(ContactSite {
                    name,
                    kind: pair,
                    gap: NO_CONTACT_GAP,
                    levels: pair_levels(&floors),
                    contact,
                    bumper: None,
                    seat: None,
                    active: false,
                    plan: None,
                    support: 0,
                    column: None,
                });
            }
        }
        s
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
