//! A structure given by its matrices (`docs/structures.md`, "Structures from matrices"): what a shear building
//! cannot describe (a frame condensed to its floors by another program), as a lumped mass per degree of
//! freedom, a symmetric positive-definite stiffness matrix and, optionally, a damping matrix. Its degrees of
//! freedom are the floors' horizontal displacements, floor 1 (the lowest) first.
//!
//! The engine joins degrees of freedom two by two, so a matrix is written as springs: `K = sum_(i<j) k_ij
//! (e_i - e_j)(e_i - e_j)^T + sum_i s_i e_i e_i^T` with `k_ij = -K_ij` and `s_i = sum_j K_ij` (a row's sum: its
//! spring to the ground), exactly (a spring may be negative; their sum is the matrix). The storey shear below
//! floor `j` is the force of the springs across the cut between floors `j - 1` and `j` (the ground's below floor
//! 1): the storey's force of a shear building. Text formats: a dense CSV (or whitespace-separated) square
//! array, or Matrix Market (`%%MatrixMarket matrix coordinate|array real general|symmetric`, 1-based indices).

use crate::Error;

/// A square matrix, row-major, and its order.
#[derive(Clone, Debug, PartialEq)]
pub struct Matrix {
    /// Its order.
    pub n: usize,
    /// Its entries, row by row.
    pub values: Vec<f64>,
}

impl Matrix {
    /// Entry `(i, j)`.
    pub fn at(&self, i: usize, j: usize) -> f64 {
        self.values[i * self.n + j]
    }

    /// The matrix in `text` (named `name` in messages): a Matrix Market file if it starts with
    /// `%%MatrixMarket`, else a dense array of rows (commas, semicolons or white space; `#` comments).
    pub fn parse(name: &'static str, text: &str) -> Result<Self, Error> {
        let bad = |why: String| Error::Choice {
            name,
            value: "the matrix".into(),
            allowed: why,
        };
        let trimmed = text.trim_start();
        let m = if trimmed
            .get(..14)
            .is_some_and(|h| h.eq_ignore_ascii_case("%%MatrixMarket"))
        {
            market(trimmed)
        } else {
            dense(trimmed)
        };
        m.map_err(bad)?.checked(name)
    }

    /// The matrix of `rows` (named `name` in messages), each a row of numbers.
    pub fn from_rows(name: &'static str, rows: &[Vec<f64>]) -> Result<Self, Error> {
        square(rows.to_vec())
            .map_err(|why| Error::Choice {
                name,
                value: "the matrix".into(),
                allowed: why,
            })?
            .checked(name)
    }

    /// The matrix if its order is within the limits and its entries finite.
    fn checked(self, name: &'static str) -> Result<Self, Error> {
        let bad = |why: String| Error::Choice {
            name,
            value: "the matrix".into(),
            allowed: why,
        };
        let m = self;
        if m.n == 0 || m.n > crate::limits::MAX_STOREYS {
            return Err(bad(format!(
                "a square matrix of order 1 to {} (this one: {})",
                crate::limits::MAX_STOREYS,
                m.n
            )));
        }
        if let Some(x) = m.values.iter().find(|x| !x.is_finite()) {
            return Err(bad(format!("finite entries (found {x})")));
        }
        Ok(m)
    }

    /// The diagonal matrix of `d`.
    pub fn diagonal(d: &[f64]) -> Self {
        let n = d.len();
        let mut values = vec![0.0; n * n];
        d.iter()
            .enumerate()
            .for_each(|(i, x)| values[i * n + i] = *x);
        Matrix { n, values }
    }

    /// Whether the matrix is symmetric to `1e-9` of its largest entry.
    pub fn is_symmetric(&self) -> bool {
        let big = self.values.iter().fold(0.0f64, |a, x| a.max(x.abs()));
        (0..self.n).all(|i| (0..i).all(|j| (self.at(i, j) - self.at(j, i)).abs() <= 1e-9 * big))
    }
}

/// A dense square array, row by row.
fn dense(text: &str) -> Result<Matrix, String> {
    let rows: Vec<Vec<f64>> = text
        .lines()
        .map(|l| l.split('#').next().unwrap_or("").trim())
        .filter(|l| !l.is_empty())
        .map(|l| {
            l.split(|c: char| c == ',' || c == ';' || c.is_whitespace())
                .filter(|t| !t.is_empty())
                .map(|t| {
                    t.parse::<f64>()
                        .map_err(|_| format!("numbers (found {t:?})"))
                })
                .collect::<Result<Vec<f64>, String>>()
        })
        .collect::<Result<_, _>>()?;
    square(rows)
}

/// The square matrix of `rows`.
fn square(rows: Vec<Vec<f64>>) -> Result<Matrix, String> {
    let n = rows.len();
    if let Some(r) = rows.iter().find(|r| r.len() != n) {
        return Err(format!(
            "a square array: {n} rows of {n} numbers (a row has {})",
            r.len()
        ));
    }
    Ok(Matrix {
        n,
        values: rows.concat(),
    })
}

/// A Matrix Market file: real, coordinate or array, general or symmetric.
fn market(text: &str) -> Result<Matrix, String> {
    let mut lines = text.lines();
    let header = lines.next().unwrap_or("").to_ascii_lowercase();
    let words: Vec<&str> = header.split_whitespace().collect();
    let (coordinate, symmetric) = match words.as_slice() {
        [_, "matrix", format, "real" | "integer", symmetry] => {
            let c = match *format {
                "coordinate" => true,
                "array" => false,
                other => return Err(format!("a coordinate or array matrix (found {other:?})")),
            };
            let s = match *symmetry {
                "general" => false,
                "symmetric" => true,
                other => return Err(format!("a general or symmetric matrix (found {other:?})")),
            };
            (c, s)
        }
        _ => {
            return Err(
                "the header %%MatrixMarket matrix coordinate|array real general|symmetric".into(),
            )
        }
    };
    let mut data = lines
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with('%'));
    let size: Vec<usize> = data
        .next()
        .ok_or("a size line")?
        .split_whitespace()
        .map(|t| {
            t.parse()
                .map_err(|_| format!("a size line of whole numbers (found {t:?})"))
        })
        .collect::<Result<_, _>>()?;
    let (rows, cols) = match size.as_slice() {
        [r, c] | [r, c, _] => (*r, *c),
        _ => return Err("a size line `rows columns [entries]`".into()),
    };
    if rows != cols || rows > crate::limits::MAX_STOREYS {
        return Err(format!(
            "a square matrix of order at most {} (this one: {rows} x {cols})",
            crate::limits::MAX_STOREYS
        ));
    }
    let n = rows;
    let mut values = vec![0.0; n * n];
    let number = |t: &str| {
        t.parse::<f64>()
            .map_err(|_| format!("numbers (found {t:?})"))
    };
    if coordinate {
        for line in data {
            let t: Vec<&str> = line.split_whitespace().collect();
            let [i, j, x] = t.as_slice() else {
                return Err(format!("entries `row column value` (found {line:?})"));
            };
            let (i, j): (usize, usize) = (
                i.parse()
                    .map_err(|_| format!("a row index (found {i:?})"))?,
                j.parse()
                    .map_err(|_| format!("a column index (found {j:?})"))?,
            );
            if !(1..=n).contains(&i) || !(1..=n).contains(&j) {
                return Err(format!("indices from 1 to {n} (found {i} {j})"));
            }
            let x = number(x)?;
            values[(i - 1) * n + (j - 1)] = x;
            if symmetric {
                values[(j - 1) * n + (i - 1)] = x;
            }
        }
    } else {
        // Column by column; a symmetric array lists the lower triangle only.
        let xs: Vec<f64> = data.map(number).collect::<Result<_, _>>()?;
        let mut k = 0;
        for j in 0..n {
            for i in (if symmetric { j } else { 0 })..n {
                let x = *xs
                    .get(k)
                    .ok_or("as many values as the matrix has entries")?;
                values[i * n + j] = x;
                values[j * n + i] = if symmetric { x } else { values[j * n + i] };
                k += 1;
            }
        }
    }
    Ok(Matrix { n, values })
}

/// A structure given by its matrices: floor masses (the diagonal of a lumped mass matrix), its stiffness and
/// (optionally) its damping matrix, checked.
#[derive(Clone, Debug, PartialEq)]
pub struct MatrixStructure {
    /// Mass of each degree of freedom (floor), kg.
    pub masses: Vec<f64>,
    /// Stiffness matrix, N/m.
    pub stiffness: Matrix,
    /// Damping matrix, N s/m (`None`: Rayleigh damping of the building's damping ratio on modes 1 and 2).
    pub damping: Option<Matrix>,
}

impl MatrixStructure {
    /// The structure of a mass matrix (`mass`: diagonal, lumped), `stiffness` (symmetric, positive definite)
    /// and `damping` (symmetric, if given), all of one order. Errors name `mass_matrix`,
    /// `stiffness_matrix`, `damping_matrix`.
    pub fn new(mass: &Matrix, stiffness: Matrix, damping: Option<Matrix>) -> Result<Self, Error> {
        let n = stiffness.n;
        let refuse = |name: &'static str, why: String| Error::Choice {
            name,
            value: "the matrix".into(),
            allowed: why,
        };
        if mass.n != n || damping.as_ref().is_some_and(|c| c.n != n) {
            return Err(refuse(
                "mass_matrix",
                format!("matrices of one order (stiffness {n}, mass {})", mass.n),
            ));
        }
        let off_diagonal = (0..n).any(|i| (0..n).any(|j| i != j && mass.at(i, j) != 0.0));
        if off_diagonal || (0..n).any(|i| mass.at(i, i) <= 0.0) {
            return Err(refuse(
                "mass_matrix",
                "a lumped (diagonal) mass matrix with masses > 0 (kg)".into(),
            ));
        }
        if !stiffness.is_symmetric() {
            return Err(refuse("stiffness_matrix", "a symmetric matrix".into()));
        }
        if damping.as_ref().is_some_and(|c| !c.is_symmetric()) {
            return Err(refuse("damping_matrix", "a symmetric matrix".into()));
        }
        Ok(Self {
            masses: (0..n).map(|i| mass.at(i, i)).collect(),
            stiffness,
            damping,
        })
    }

    /// Order.
    pub fn n(&self) -> usize {
        self.masses.len()
    }

    /// `phi^T C phi`, N s/m: with the damping matrix, or Rayleigh's `C = a0 M + a1 K` (`rayleigh = (a0, a1)`).
    pub fn quadratic_damping(&self, phi: &[f64], (a0, a1): (f64, f64)) -> f64 {
        let form = |m: &Matrix| -> f64 {
            (0..m.n)
                .map(|i| phi[i] * (0..m.n).map(|j| m.at(i, j) * phi[j]).sum::<f64>())
                .sum()
        };
        match &self.damping {
            Some(c) => form(c),
            None => {
                let mass: f64 = self.masses.iter().zip(phi).map(|(m, p)| m * p * p).sum();
                a0 * mass + a1 * form(&self.stiffness)
            }
        }
    }

    /// The springs that make `m`: `(upper, lower, k)` with `lower` `None` for the ground, `upper > lower`,
    /// for every nonzero `k`. A row's sum within `1e-12` of its diagonal is the roundoff of a row that sums to
    /// zero (a floor held by its neighbours only), and makes no spring.
    pub fn springs(m: &Matrix) -> Vec<(usize, Option<usize>, f64)> {
        let n = m.n;
        let mut out = Vec::new();
        for i in 0..n {
            let s: f64 = (0..n).map(|j| m.at(i, j)).sum();
            if s.abs() > 1e-12 * m.at(i, i).abs() {
                out.push((i, None, s));
            }
            for j in 0..i {
                let k = -m.at(i, j);
                if k != 0.0 {
                    out.push((i, Some(j), k));
                }
            }
        }
        out
    }

    /// The stiffness across the cut under each floor (the springs joining a floor at or above it to one
    /// below it or to the ground), N/m: a shear building's storey stiffnesses.
    pub fn cut_stiffnesses(&self) -> Vec<f64> {
        let springs = Self::springs(&self.stiffness);
        (0..self.n())
            .map(|j| {
                springs
                    .iter()
                    .filter(|(hi, lo, _)| *hi >= j && lo.is_none_or(|lo| lo < j))
                    .map(|s| s.2)
                    .sum()
            })
            .collect()
    }
}

/// Circular frequencies and shapes.
pub type Omegas = (Vec<f64>, Vec<Vec<f64>>);

/// The modes of `K phi = w^2 M phi` for the lumped `masses` and `stiffness`: circular frequencies (rad/s,
/// lowest first) and mass-normalised shapes (the top floor's component positive); refused (naming
/// `stiffness_matrix`) unless `K` is positive definite.
pub fn modes_of(masses: &[f64], stiffness: &Matrix) -> Result<Omegas, Error> {
    let n = masses.len();
    let s: Vec<f64> = masses.iter().map(|m| 1.0 / m.sqrt()).collect();
    let mut a: Vec<f64> = (0..n * n)
        .map(|ij| stiffness.values[ij] * s[ij / n] * s[ij % n])
        .collect();
    let scale = (0..n).map(|i| a[i * n + i].abs()).fold(0.0f64, f64::max);
    let e = super::eigen::symmetric(&mut a, n);
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|&i, &j| e.values[i].total_cmp(&e.values[j]));
    if e.values[order[0]].is_nan() || e.values[order[0]] <= 1e-10 * scale {
        return Err(Error::Choice {
            name: "stiffness_matrix",
            value: "the matrix".into(),
            allowed: "a positive-definite stiffness matrix (this one has a mode without stiffness: the structure is not held)".into(),
        });
    }
    let omega = order.iter().map(|&r| e.values[r].sqrt()).collect();
    let shapes = order
        .iter()
        .map(|&r| {
            let mut phi: Vec<f64> = (0..n).map(|i| e.vectors[i * n + r] * s[i]).collect();
            if phi[n - 1] < 0.0 {
                phi.iter_mut().for_each(|x| *x = -*x);
            }
            phi
        })
        .collect();
    Ok((omega, shapes))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn matrices_are_read_from_csv_and_matrix_market() {
        let csv = Matrix::parse("stiffness_matrix", "# K\n 3e8, -1e8\n-1e8; 1e8\n").unwrap();
        let mm = Matrix::parse(
            "stiffness_matrix",
            "%%MatrixMarket matrix coordinate real symmetric\n% a comment\n2 2 3\n1 1 3e8\n2 1 -1e8\n2 2 1e8\n",
        )
        .unwrap();
        assert_eq!(csv, mm);
        let array = Matrix::parse(
            "stiffness_matrix",
            "%%MatrixMarket matrix array real symmetric\n2 2\n3e8\n-1e8\n1e8\n",
        )
        .unwrap();
        assert_eq!(csv, array);
        // The springs of a shear building's matrix are its storeys.
        let springs = MatrixStructure::springs(&csv);
        assert_eq!(springs, vec![(0, None, 2e8), (1, Some(0), 1e8)]);
        let e = Matrix::parse("stiffness_matrix", "1 2\n3\n")
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with("stiffness_matrix = the matrix is not allowed: a square array"),
            "{e}"
        );
    }
}
