//! A column struck between its floors (floor-to-column pounding, `docs/structures.md`, "Floor-to-column
//! impacts"): a fixed–fixed Euler–Bernoulli column of flexural rigidity `EI` (N m^2) and length `L` (m), its
//! ends moving with the floors below and above without rotating (rigid floors), struck by a point force at
//! height `a` from its lower end (`b = L - a`).
//!
//! Statics of the fixed–fixed beam (Roark's *Formulas for Stress and Strain*, table 8.1, case 1e; Gere &
//! Timoshenko): under a force `P` at `a`, the point deflects by `P / k` with `k = 3 EI L^3 / (a^3 b^3)`; the
//! end reactions are `P b^2 (3a + b) / L^3` (lower) and `P a^2 (3b + a) / L^3` (upper), the end moments
//! `P a b^2 / L^2` and `P a^2 b / L^2`. The reactions per unit force are the cubic Hermite shape functions
//! `1 - 3 xi^2 + 2 xi^3` and `3 xi^2 - 2 xi^3` (`xi = a / L`), which also carry the floors' translations to
//! the point (Maxwell–Betti): the point moves by `N1 u_below + N2 u_above + P / k`.

use crate::error::check;
use crate::Error;

/// A struck column: its stiffness, length, the height it is struck at, its mass, and its capacities.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StruckColumn {
    /// Flexural rigidity `EI`, N m^2 (of the line of columns struck: their sum).
    pub ei: f64,
    /// Length (the storey's height), m.
    pub length: f64,
    /// Height of the strike above the column's lower end, m (`0 < a < L`).
    pub a: f64,
    /// The column's mass, kg (its mass per length times `L`).
    pub mass: f64,
    /// Shear capacity at its ends, N, if given.
    pub shear_capacity: Option<f64>,
    /// Moment capacity at its ends, N m, if given.
    pub moment_capacity: Option<f64>,
}

impl StruckColumn {
    /// The column of `ei` (N m^2, > 0) and `length` (m, > 0) struck at `a` (m, `0 < a < L`), of `mass` (kg,
    /// > 0). Errors name the key (`EI`, `column_mass`).
    pub fn new(ei: f64, length: f64, a: f64, mass: f64) -> Result<Self, Error> {
        check(
            "column.ei",
            ei,
            ei > 0.0 && ei.is_finite(),
            "finite EI > 0 (N m^2)",
        )?;
        check(
            "length",
            length,
            length > 0.0 && length.is_finite(),
            "finite length > 0 (m)",
        )?;
        check(
            "height",
            a,
            a > 0.0 && a < length,
            "a height strictly inside the storey: 0 < a < L (m); at a floor, the contact is a floor contact",
        )?;
        check(
            "column_mass",
            mass,
            mass > 0.0 && mass.is_finite(),
            "finite mass > 0 (kg)",
        )?;
        Ok(Self {
            ei,
            length,
            a,
            mass,
            shear_capacity: None,
            moment_capacity: None,
        })
    }

    /// `b = L - a`, m.
    pub fn b(&self) -> f64 {
        self.length - self.a
    }

    /// The point's stiffness against a force there, the floors held: `3 EI L^3 / (a^3 b^3)`, N/m.
    pub fn stiffness(&self) -> f64 {
        let (a, b, l) = (self.a, self.b(), self.length);
        3.0 * self.ei * l.powi(3) / (a.powi(3) * b.powi(3))
    }

    /// The end shears per unit force at the point, `(lower, upper)`: `b^2 (3a + b) / L^3` and
    /// `a^2 (3b + a) / L^3` (dimensionless; they sum to 1). The same weights carry the floors' translations to
    /// the point.
    pub fn shears(&self) -> (f64, f64) {
        let (a, b, l) = (self.a, self.b(), self.length);
        let lower = b * b * (3.0 * a + b) / l.powi(3);
        (lower, 1.0 - lower)
    }

    /// The end moments per unit force at the point, `(lower, upper)`: `a b^2 / L^2` and `a^2 b / L^2`, m.
    pub fn moments(&self) -> (f64, f64) {
        let (a, b, l) = (self.a, self.b(), self.length);
        (a * b * b / (l * l), a * a * b / (l * l))
    }

    /// The mass the point carries, kg: the column's mass times `(1/L) int (y / y(a))^2 dx` over its static
    /// deflection `y` under a force at the point (Rayleigh's equivalent mass; 13/35 at mid-height).
    pub fn point_mass(&self) -> f64 {
        let (a, b, l) = (self.a, self.b(), self.length);
        // The deflection under a unit force at a, up to a constant factor (Roark): for x <= a,
        // b^2 x^2 (3 a L - 3 a x - b x); for x >= a the same with a and b exchanged and x measured from the top.
        let y = |x: f64| {
            if x <= a {
                b * b * x * x * (3.0 * a * l - 3.0 * a * x - b * x)
            } else {
                let xr = l - x;
                a * a * xr * xr * (3.0 * b * l - 3.0 * b * xr - a * xr)
            }
        };
        let ya = y(a);
        // Four-point Gauss–Legendre on each side of the point: (y / ya)^2 is a polynomial of degree 6 on
        // each, which it integrates exactly.
        const NODES: [(f64, f64); 4] = [
            (-0.861_136_311_594_052_6, 0.347_854_845_137_453_85),
            (-0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
            (0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
            (0.861_136_311_594_052_6, 0.347_854_845_137_453_85),
        ];
        let side = |x0: f64, x1: f64| {
            let (m, h) = (0.5 * (x0 + x1), 0.5 * (x1 - x0));
            NODES
                .iter()
                .map(|&(t, w)| w * (y(m + h * t) / ya).powi(2))
                .sum::<f64>()
                * h
        };
        self.mass * (side(0.0, a) + side(a, l)) / l
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The check values of next-physics.md section 4: L = 3 m, EI = 5.333e7 N m^2.
    #[test]
    fn the_check_values_of_a_struck_column() {
        for (a, k, shear) in [
            (0.75, 8.989287e8, 0.84375),
            (1.0, 5.399662e8, 0.740741),
            (1.5, 3.792356e8, 0.5),
        ] {
            let c = StruckColumn::new(5.333e7, 3.0, a, 1000.0).unwrap();
            assert!(
                (c.stiffness() / k - 1.0).abs() < 5e-7,
                "a {a}: {}",
                c.stiffness()
            );
            assert!(
                (c.shears().0 - shear).abs() < 5e-7,
                "a {a}: {}",
                c.shears().0
            );
        }
        // Mid-height: the classic equivalent mass 13/35 of the column's, and end moments P L / 8.
        let c = StruckColumn::new(5.333e7, 3.0, 1.5, 1000.0).unwrap();
        assert!(
            (c.point_mass() - 1000.0 * 13.0 / 35.0).abs() < 1e-9,
            "{}",
            c.point_mass()
        );
        assert!((c.moments().0 - 3.0 / 8.0).abs() < 1e-15);
        // The point stiffness of a column struck at mid-height is 192 EI / L^3 (fixed-fixed, central load).
        assert!((c.stiffness() / (192.0 * 5.333e7 / 27.0) - 1.0).abs() < 1e-14);
        // At a floor it is no column contact.
        let e = StruckColumn::new(5.333e7, 3.0, 0.0, 1.0)
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("height = 0 is not allowed"), "{e}");
    }
}
