//! Floor-to-column contact sites: a slab of one building striking its neighbour's column between the
//! neighbour's floors, where their floor levels differ (`docs/structures.md`, "Floor-to-column impacts").

use super::{ColumnLinkSpec, ContactSite, Level, Scenario, SiteColumn, SiteKind};
use crate::error::check;
use crate::structure::StruckColumn;
use crate::Error;

/// Floors within this of a slab's elevation are met by it, m (as floors "at the same height").
const SAME_HEIGHT: f64 = 1e-3;

impl Scenario {
    /// Adds a slab striking its neighbour's column ([`ColumnLinkSpec`]): the slab's floor of one building
    /// against the neighbour (next in the row) at the slab's elevation. Between the neighbour's floors
    /// `j - 1` and `j`, the column (fixed–fixed, `EI`, the storey's height) is struck at the height `a` above
    /// floor `j - 1`: a point of the column, carrying its share of the column's mass, moves with the floors'
    /// translations through the column's shape functions and deflects under the contact by its point
    /// stiffness ([`StruckColumn`]). Where the slab meets one of the neighbour's floors (within 1 mm), the
    /// site is a floor contact, as a `[[contact]]` at that floor pair.
    pub fn with_column_contact(mut self, spec: ColumnLinkSpec) -> Result<Self, Error> {
        let (slab_name, floor) = &spec.slab;
        let (s, c) = (
            self.building_index(slab_name)?,
            self.building_index(&spec.column)?,
        );
        if s.abs_diff(c) != 1 {
            return Err(Error::Choice {
                name: "column",
                value: format!("{:?}", spec.column),
                allowed: format!(
                    "a neighbour of {slab_name:?} in the row (as listed, left to right)"
                ),
            });
        }
        let plan = |b: usize| self.buildings[b].structure.plan().is_some();
        if plan(s) || plan(c) {
            return Err(Error::Choice {
                name: "column",
                value: format!("{:?}", spec.column),
                allowed: "buildings in one line: floor-to-column contacts between buildings in plan are not modelled yet".into(),
            });
        }
        let zs = self.buildings[s].structure.elevations();
        check(
            "slab",
            *floor as f64,
            (1..=zs.len()).contains(floor),
            "a floor of the slab's building, from 1",
        )?;
        let z = zs[floor - 1];
        let column_building = &self.buildings[c].structure;
        let zc = column_building.elevations();
        let top = *zc.last().expect("a building has floors");
        if z > top + SAME_HEIGHT {
            return Err(Error::Choice {
                name: "slab",
                value: format!("floor {floor} of {slab_name:?}, at {} m", crate::words::number(z)),
                allowed: format!(
                    "a slab at most as high as {:?}'s roof ({} m): above it there is no column to strike",
                    spec.column,
                    crate::words::number(top)
                ),
            });
        }
        check(
            "gap",
            spec.gap,
            spec.gap >= 0.0 && spec.gap.is_finite(),
            "gap >= 0 (m)",
        )?;
        // The neighbour's floor the slab meets, or the storey it strikes.
        let met = zc.iter().position(|w| (w - z).abs() <= SAME_HEIGHT);
        let (storey, struck) = match met {
            Some(k) => (k + 1, None),
            None => {
                let j = zc.iter().position(|&w| w > z).expect("below the roof");
                let below = if j == 0 { 0.0 } else { zc[j - 1] };
                let mut col = StruckColumn::new(spec.ei, zc[j] - below, z - below, spec.mass)?;
                for (name, cap) in [
                    ("shear_capacity", spec.shear_capacity),
                    ("moment_capacity", spec.moment_capacity),
                ] {
                    if let Some(x) = cap {
                        check(name, x, x > 0.0 && x.is_finite(), "a capacity > 0")?;
                    }
                }
                col.shear_capacity = spec.shear_capacity;
                col.moment_capacity = spec.moment_capacity;
                (j + 1, Some(col))
            }
        };
        let (left, right) = (s.min(c), s.max(c));
        let on_left = c == left;
        let (slab_side, column_side) = (Some(*floor), Some(storey));
        let level = if on_left {
            Level {
                left: column_side,
                right: slab_side,
            }
        } else {
            Level {
                left: slab_side,
                right: column_side,
            }
        };
        let name = format!(
            "{}|{}:{}{}",
            self.buildings[left].name, self.buildings[right].name, slab_name, floor
        );
        if self.sites.iter().any(|x| x.name == name) {
            return Err(Error::Choice {
                name: "slab",
                value: format!("floor {floor} of {slab_name:?}"),
                allowed: "one column contact per slab".into(),
            });
        }
        let contact = spec.contact.prepare()?;
        self.insert_link(ContactSite {
            name,
            kind: SiteKind::Between { left, right },
            gap: spec.gap,
            levels: vec![level],
            contact,
            bumper: None,
            seat: None,
            active: true,
            plan: None,
            support: 0,
            column: Some(SiteColumn {
                on_left,
                struck,
                storey,
            }),
        });
        Ok(self)
    }
}
