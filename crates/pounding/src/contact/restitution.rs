//! What a contact is asked to deliver: one coefficient of restitution, `e` as a function of the impact
//! velocity (a table, from drop tests such as Jankowski 2010), or a material damping constant of the
//! Hunt–Crossley law (`docs/contact-models.md`, section 2.6; `next-physics.md` section 1).
//!
//! Calibration is per impact: at each located touch the law is built for the impact's own `v_i`, so a table
//! is read at `v_i` and that impact's damping calibrated to the value read.

use super::exact::hc_e_post;
use crate::error::check;
use crate::Error;

/// `e` against the impact velocity: points `(v_i` in m/s, `e)`, velocities increasing, read linearly between
/// points and held constant beyond the first and the last.
#[derive(Clone, Debug, PartialEq)]
pub struct RestitutionTable {
    points: Vec<(f64, f64)>,
}

impl RestitutionTable {
    /// The table of `points` (`(v_i` m/s, `e)`): at least one, velocities finite, >= 0 and strictly
    /// increasing, every `e` in (0, 1]. The error names the first row that is not.
    pub fn new(points: Vec<(f64, f64)>) -> Result<Self, Error> {
        let bad = |k: usize, allowed: &str| {
            let (v, e) = points[k];
            Err(Error::Choice {
                name: "e.table",
                value: format!(
                    "row {} [{}, {}]",
                    k + 1,
                    crate::words::number(v),
                    crate::words::number(e)
                ),
                allowed: allowed.to_string(),
            })
        };
        if points.is_empty() {
            return Err(Error::Choice {
                name: "e.table",
                value: "[]".into(),
                allowed: "at least one row [v_i (m/s), e]".into(),
            });
        }
        for (k, &(v, e)) in points.iter().enumerate() {
            if !(v.is_finite() && v >= 0.0) {
                return bad(
                    k,
                    "an impact velocity v_i >= 0 (m/s) in each row's first column",
                );
            }
            if !(e > 0.0 && e <= 1.0) {
                return bad(k, "0 < e <= 1 in each row's second column");
            }
            if k > 0 && v <= points[k - 1].0 {
                return bad(
                    k,
                    "rows sorted by impact velocity, each faster than the one before",
                );
            }
        }
        Ok(Self { points })
    }

    /// The rows, `(v_i` m/s, `e)`.
    pub fn points(&self) -> &[(f64, f64)] {
        &self.points
    }

    /// `e` at impact velocity `v_i` (m/s): linear between rows, the end rows' values beyond them.
    pub fn at(&self, v_i: f64) -> f64 {
        let p = &self.points;
        let k = p.partition_point(|q| q.0 <= v_i);
        match k {
            0 => p[0].1,
            _ if k == p.len() => p[k - 1].1,
            _ => {
                let ((v0, e0), (v1, e1)) = (p[k - 1], p[k]);
                e0 + (e1 - e0) * (v_i - v0) / (v1 - v0)
            }
        }
    }
}

/// What a contact is asked to deliver.
#[derive(Clone, Debug, PartialEq)]
pub enum Restitution {
    /// One coefficient of restitution for every impact (dimensionless, 0 < e <= 1).
    Constant(f64),
    /// `e` as a function of the impact velocity.
    Table(RestitutionTable),
    /// A material damping constant `c = D/K` (s/m) of the Hunt–Crossley law `F = K d^n (1 + c d')`, not
    /// divided by the impact velocity: an impact of two free bodies delivers [`material_e`]`(c v_i)`.
    DampingConstant(f64),
}

impl Restitution {
    /// A material damping constant `c` (s/m, >= 0).
    pub fn damping_constant(c: f64) -> Result<Self, Error> {
        check(
            "damping_constant",
            c,
            c >= 0.0,
            "damping_constant >= 0 (s/m: D/K of F = K d^n (1 + (D/K) d'))",
        )
        .map(Restitution::DampingConstant)
    }

    /// The `e` an impact at `v_i` (m/s) is to deliver between two free bodies.
    pub fn at(&self, v_i: f64) -> f64 {
        match self {
            Restitution::Constant(e) => *e,
            Restitution::Table(t) => t.at(v_i),
            Restitution::DampingConstant(c) => material_e(c * v_i),
        }
    }

    /// The one `e` of every impact, if it is one.
    pub fn constant(&self) -> Option<f64> {
        match self {
            Restitution::Constant(e) => Some(*e),
            Restitution::Table(_) | Restitution::DampingConstant(_) => None,
        }
    }
}

/// The coefficient of restitution delivered between two free bodies by the Hunt–Crossley law with material
/// damping, `F = K d^n (1 + c d')`, at `chi = c v_i`: the root `e` of
/// `chi - ln(1 + chi) = -chi e - ln(1 - chi e)`, which depends on `chi` alone (not on `n`, `K` or the
/// masses). It is the law `F = K d^n (1 + chi d' / v_i)` of [`super::ForceLaw::HuntCrossley`] with
/// `chi = chi_r = c v_i`, whose exact relation is [`hc_e_post`].
pub fn material_e(chi: f64) -> f64 {
    hc_e_post(chi, chi)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_table_reads_linearly_and_holds_its_ends() {
        let t = RestitutionTable::new(vec![(0.1, 0.8), (0.5, 0.65), (2.0, 0.5)]).unwrap();
        assert_eq!(t.at(0.0), 0.8);
        assert_eq!(t.at(0.1), 0.8);
        assert!((t.at(0.3) - 0.725).abs() < 1e-15);
        assert_eq!(t.at(0.5), 0.65);
        assert!((t.at(1.25) - 0.575).abs() < 1e-15);
        assert_eq!(t.at(9.0), 0.5);
        let one = RestitutionTable::new(vec![(1.0, 0.6)]).unwrap();
        assert_eq!((one.at(0.01), one.at(100.0)), (0.6, 0.6));
    }

    #[test]
    fn bad_tables_name_their_row() {
        for (rows, row, says) in [
            (vec![(0.5, 0.6), (0.2, 0.7)], "row 2 [0.2, 0.7]", "sorted"),
            (vec![(0.5, 0.6), (0.5, 0.7)], "row 2", "sorted"),
            (vec![(0.1, 1.2)], "row 1 [0.1, 1.2]", "0 < e <= 1"),
            (vec![(-0.1, 0.5)], "row 1", "v_i >= 0"),
            (vec![(f64::NAN, 0.5)], "row 1", "v_i >= 0"),
        ] {
            let msg = RestitutionTable::new(rows).unwrap_err().to_string();
            assert!(
                msg.starts_with("e.table = ") && msg.contains(row) && msg.contains(says),
                "{msg}"
            );
        }
        assert!(RestitutionTable::new(Vec::new()).is_err());
        assert!(Restitution::damping_constant(-0.1).is_err());
    }

    /// next-physics.md section 1: c = 0.3 s/m at v_i = 0.05 ... 3 m/s (recomputed there independently).
    #[test]
    fn material_damping_delivers_the_published_check_values() {
        let want = [
            (0.05, 0.990099),
            (0.1, 0.980391),
            (0.2, 0.961533),
            (0.5, 0.909016),
            (1.0, 0.832870),
            (2.0, 0.711950),
            (3.0, 0.619736),
        ];
        for (v, e) in want {
            let got = Restitution::DampingConstant(0.3).at(v);
            assert!((got - e).abs() < 1e-6, "v_i = {v}: {got} vs {e}");
            // The relation itself: chi - ln(1 + chi) = -chi e - ln(1 - chi e).
            let chi = 0.3 * v;
            let lhs = chi - (1.0 + chi).ln();
            let rhs = -chi * got - (1.0 - chi * got).ln();
            assert!(
                (lhs - rhs).abs() < 1e-12 * lhs.max(1e-300),
                "{lhs} vs {rhs}"
            );
        }
    }
}
