//! Façades of buildings in plan that face each other: two rectangles apart along x with overlapping
//! extents along y face each other through their east and west façades (apart along y, through their north
//! and south ones). The gap is the distance between the façades at rest; contact points lie on the
//! overlap of the two façades (`docs/structures.md`, "Buildings in plan").
//!
//! Floors are rigid and turn by small angles, so the closing of two façades along their normal is linear
//! along the façade: its largest value over the overlap is at one of the overlap's ends. The ends are
//! therefore the default points (each is a corner of one of the two plans).

use crate::structure::Plan;
use crate::Error;

/// Two façades that face each other.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Facing {
    /// Whether the first plan (as asked) is on the negative side of the normal: the "left" building.
    pub first_is_left: bool,
    /// The unit normal from the left building to the right one: `(1, 0)` or `(0, 1)`.
    pub normal: (f64, f64),
    /// The distance between the façades at rest, m.
    pub gap: f64,
    /// The left building's façade: its coordinate along the normal, m (site frame).
    pub plane: f64,
    /// The overlap of the two façades along the tangent, `(lo, hi)`, m (site frame).
    pub overlap: (f64, f64),
}

impl Facing {
    /// The point at `along` (m, the site-frame coordinate along the façade) on the left building's
    /// façade, site frame.
    pub fn point(&self, along: f64) -> (f64, f64) {
        if self.normal.0 != 0.0 {
            (self.plane, along)
        } else {
            (along, self.plane)
        }
    }
}

/// `[lo, hi]` of a rectangle along x (`axis` 0) or y (1), site frame.
fn extent(p: &Plan, axis: usize) -> (f64, f64) {
    let (o, s) = (p.origin(), p.size());
    if axis == 0 {
        (o.0, o.0 + s.0)
    } else {
        (o.1, o.1 + s.1)
    }
}

/// How plans `a` and `b` face each other, or why they do not (named `position`, the key that places a
/// plan).
pub(super) fn facing(a: &Plan, b: &Plan, names: (&str, &str)) -> Result<Facing, Error> {
    let refuse = |why: String| Error::Choice {
        name: "position",
        value: format!("{:?} and {:?}", names.0, names.1),
        allowed: why,
    };
    // Per axis: the clear distance between the rectangles (negative if they overlap along it), and the
    // overlap of their extents (negative if apart).
    let along = |axis: usize| {
        let ((a0, a1), (b0, b1)) = (extent(a, axis), extent(b, axis));
        // To the picometre: positions a user types (20.02 beside 20) give the gap they mean (0.02, not
        // 0.019999999999999574), as a contact in one line is given it.
        let gap = ((b0 - a1).max(a0 - b1) * 1e12).round() / 1e12;
        let overlap = a1.min(b1) - a0.max(b0);
        (gap, overlap, a1 <= b0, (a0.max(b0), a1.min(b1)))
    };
    let (gx, ox, ax_first, rx) = along(0);
    let (gy, oy, ay_first, ry) = along(1);
    let facing_on = |axis: usize, gap: f64, first: bool, overlap: (f64, f64)| {
        let left = if first { a } else { b };
        let (_, hi) = extent(left, axis);
        let normal = if axis == 0 { (1.0, 0.0) } else { (0.0, 1.0) };
        Facing {
            first_is_left: first,
            normal,
            gap,
            plane: hi,
            overlap,
        }
    };
    let scale = a.size().0.max(a.size().1).max(b.size().0).max(b.size().1);
    // Façades must share a length, not a corner.
    let shared = 1e-9 * scale;
    if gx >= 0.0 && oy > shared {
        Ok(facing_on(0, gx, ax_first, ry))
    } else if gy >= 0.0 && ox > shared {
        Ok(facing_on(1, gy, ay_first, rx))
    } else if gx < 0.0 && gy < 0.0 {
        Err(refuse(
            "plans that do not overlap (these do: move one with plan.position)".into(),
        ))
    } else {
        Err(refuse(
            "plans whose façades face each other: apart along x with overlapping extents along y, or apart along y with overlapping extents along x (these are apart diagonally)".into(),
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::element::StoreyLaw;
    use crate::structure::{Line, LineDirection};

    fn plan(origin: (f64, f64), size: (f64, f64)) -> Plan {
        let line = |direction, at| Line {
            direction,
            at,
            stiffnesses: vec![1e8],
            laws: vec![StoreyLaw::Linear],
        };
        let lines = vec![
            line(LineDirection::X, 0.0),
            line(LineDirection::X, size.1),
            line(LineDirection::Y, 0.0),
            line(LineDirection::Y, size.0),
        ];
        let spec = crate::structure::PlanSpec {
            size,
            origin,
            centres: None,
            inertias: None,
            lines,
            damping_modes: None,
        };
        Plan::new(&[1e5], spec, 0.05).unwrap()
    }

    #[test]
    fn facades_are_found_from_the_positions() {
        let a = plan((0.0, 0.0), (20.0, 15.0));
        // East of a, 0.1 m away, shifted north by 5 m: overlap y in [5, 15].
        let b = plan((20.1, 5.0), (10.0, 30.0));
        let f = facing(&a, &b, ("a", "b")).unwrap();
        assert!(f.first_is_left && f.normal == (1.0, 0.0));
        assert!((f.gap - 0.1).abs() < 1e-12 && f.plane == 20.0 && f.overlap == (5.0, 15.0));
        let g = facing(&b, &a, ("b", "a")).unwrap();
        assert!(!g.first_is_left && g.plane == 20.0 && (g.gap - 0.1).abs() < 1e-12);
        // North of a.
        let c = plan((-4.0, 15.05), (10.0, 10.0));
        let f = facing(&c, &a, ("c", "a")).unwrap();
        assert!(!f.first_is_left && f.normal == (0.0, 1.0) && f.overlap == (0.0, 6.0));
        assert_eq!(f.point(2.0), (2.0, 15.0));
        // Diagonal and overlapping plans are refused, naming the key.
        let d = plan((21.0, 16.0), (5.0, 5.0));
        let e = facing(&a, &d, ("a", "d")).unwrap_err().to_string();
        assert!(
            e.starts_with("position = ") && e.contains("diagonally"),
            "{e}"
        );
        let o = plan((19.0, 1.0), (5.0, 5.0));
        let e = facing(&a, &o, ("a", "o")).unwrap_err().to_string();
        assert!(e.contains("do not overlap"), "{e}");
    }
}
