//! The buildings of a scenario as one linear system, `x' = A x + b w(t)`, driven by a white noise `w` through
//! an optional ground filter (Kanai–Tajimi or Clough–Penzien, as [`crate::ground_motion::synthetic`] defines
//! them), and its stationary covariance: the solution `P` of the Lyapunov equation `A P + P A^T + Q = 0`.
//!
//! The state holds the floors' displacements relative to the ground (m), then their velocities (m/s), then
//! the filter's states. Storeys enter with their initial stiffness (an inelastic storey as its elastic
//! branch) and their viscous damping as the time-history analysis has it (Rayleigh on the initial
//! stiffness; an isolated superstructure's mass-proportional part relative to its base slab).

use crate::analysis::Scenario;
use crate::error::check;
use crate::ground_motion::synthetic::Filter;
use crate::integrate::{lu, mat_mul};
use crate::Error;

/// A linear time-invariant system `x' = A x + b w`, `A` row-major `n` x `n`.
#[derive(Clone, Debug, PartialEq)]
pub struct StateSpace {
    /// States.
    pub n: usize,
    /// `A`, row-major.
    pub a: Vec<f64>,
    /// `b`: how the white noise enters.
    pub b: Vec<f64>,
    /// Degrees of freedom (floors of every building, in order): the displacement of floor `i` of the whole
    /// row is state `i`, its velocity state `dofs + i`.
    pub dofs: usize,
    /// The first degree of freedom of each building.
    pub offsets: Vec<usize>,
    /// A scale of the system's circular frequencies, rad/s: the geometric mean of the slowest and the
    /// fastest (for the solver's shift).
    pub frequency: f64,
}

/// The buildings of `s` (without contacts, devices left out) under a white-noise ground acceleration, or
/// its filtered version.
pub fn state_space(s: &Scenario, filter: Option<Filter>) -> StateSpace {
    let buildings = s.buildings();
    let mut offsets = Vec::new();
    let mut dofs = 0;
    for b in buildings {
        offsets.push(dofs);
        dofs += b.structure.storeys();
    }
    let nf = match filter {
        None => 0,
        Some(Filter::KanaiTajimi { .. }) => 2,
        Some(Filter::CloughPenzien { .. }) => 4,
    };
    let n = 2 * dofs + nf;
    let mut a = vec![0.0; n * n];
    let mut b = vec![0.0; n];
    let (mut w_lo, mut w_hi) = (f64::INFINITY, 0.0f64);
    for (bi, building) in buildings.iter().enumerate() {
        let st = &building.structure;
        let o = offsets[bi];
        let m = st.masses();
        let (c, a0, base) = st.damping_layout();
        // Storey j joins floor j to floor j - 1 (the ground below floor 1) with k_j and c_j.
        let mut add = |i: usize, j: Option<usize>, k: f64, c: f64| {
            let (vi, ui) = (dofs + o + i, o + i);
            a[vi * n + ui] -= k / m[i];
            a[vi * n + dofs + ui] -= c / m[i];
            if let Some(j) = j {
                let (vj, uj) = (dofs + o + j, o + j);
                a[vi * n + uj] += k / m[i];
                a[vi * n + dofs + uj] += c / m[i];
                a[vj * n + uj] -= k / m[j];
                a[vj * n + dofs + uj] -= c / m[j];
                a[vj * n + ui] += k / m[j];
                a[vj * n + dofs + ui] += c / m[j];
            }
        };
        if let Some(ms) = st.matrices() {
            // A structure given by its matrices: the springs and dashpots that make them.
            let (a0, a1) = st.rayleigh();
            for (hi, lo, k) in crate::structure::MatrixStructure::springs(&ms.stiffness) {
                add(hi, lo, k, if ms.damping.is_none() { a1 * k } else { 0.0 });
            }
            match &ms.damping {
                Some(cm) => crate::structure::MatrixStructure::springs(cm)
                    .into_iter()
                    .for_each(|(hi, lo, c)| add(hi, lo, 0.0, c)),
                None => m
                    .iter()
                    .enumerate()
                    .for_each(|(i, &mi)| add(i, None, 0.0, a0 * mi)),
            }
            let w = &st.modes().omega;
            w_lo = w_lo.min(w[0]);
            w_hi = w_hi.max(w[w.len() - 1]);
            continue;
        }
        for (j, (&k, &cj)) in st.stiffnesses().iter().zip(&c).enumerate() {
            if j == 0 {
                add(0, None, k, cj);
            } else {
                add(j, Some(j - 1), k, cj);
            }
        }
        // Mass-proportional damping: to the ground, or to the base slab of an isolated building.
        for (i, &mi) in m.iter().enumerate() {
            match base {
                None => add(i, None, 0.0, a0 * mi),
                Some(bs) if bs != i => add(i, Some(bs), 0.0, a0 * mi),
                Some(_) => {}
            }
        }
        let w = &st.modes().omega;
        w_lo = w_lo.min(w[0]);
        w_hi = w_hi.max(w[w.len() - 1]);
    }
    for i in 0..dofs {
        a[i * n + dofs + i] = 1.0;
    }
    // The ground acceleration a_g pushes every floor by -a_g (relative coordinates). Without a filter a_g
    // is the noise; with one, a_g is the filter's output and the noise drives the filter.
    let f0 = 2 * dofs;
    match filter {
        None => (dofs..2 * dofs).for_each(|i| b[i] = -1.0),
        Some(f) => {
            let (wg, zg) = match f {
                Filter::KanaiTajimi { wg, zg } | Filter::CloughPenzien { wg, zg, .. } => (wg, zg),
            };
            // Soil: x'' = -2 zg wg x' - wg^2 x - w; a_kt = -(2 zg wg x' + wg^2 x).
            a[f0 * n + f0 + 1] = 1.0;
            a[(f0 + 1) * n + f0] = -wg * wg;
            a[(f0 + 1) * n + f0 + 1] = -2.0 * zg * wg;
            b[f0 + 1] = -1.0;
            // a_g as a row over the states.
            let mut ag = vec![0.0; n];
            ag[f0] = -wg * wg;
            ag[f0 + 1] = -2.0 * zg * wg;
            w_lo = w_lo.min(wg);
            w_hi = w_hi.max(wg);
            if let Filter::CloughPenzien { wf, zf, .. } = f {
                // High-pass: y'' = -2 zf wf y' - wf^2 y + a_kt; a_g = a_kt - 2 zf wf y' - wf^2 y.
                let y = f0 + 2;
                a[y * n + y + 1] = 1.0;
                for (k, &g) in ag.clone().iter().enumerate() {
                    a[(y + 1) * n + k] += g;
                }
                a[(y + 1) * n + y] -= wf * wf;
                a[(y + 1) * n + y + 1] -= 2.0 * zf * wf;
                ag[y] = -wf * wf;
                ag[y + 1] = -2.0 * zf * wf;
                w_lo = w_lo.min(wf);
                w_hi = w_hi.max(wf);
            }
            for i in dofs..2 * dofs {
                for (k, &g) in ag.iter().enumerate() {
                    a[i * n + k] -= g;
                }
            }
        }
    }
    StateSpace {
        n,
        a,
        b,
        dofs,
        offsets,
        frequency: (w_lo * w_hi).sqrt(),
    }
}

/// The stationary covariance `P` (row-major, symmetric) of `x' = A x + b w` under a white noise of
/// two-sided spectral density `s0` (`E[w(t) w(t + tau)] = 2 pi s0 delta(tau)`): the solution of
/// `A P + P A^T + 2 pi s0 b b^T = 0`.
///
/// Solved exactly (to rounding) by the Cayley transform with shift `p` (the system's frequency scale):
/// `P = A_d P A_d^T + Q_d`, `A_d = (A - p I)^-1 (A + p I)`, `Q_d = 2 p (A - p I)^-1 Q (A - p I)^-T`, whose
/// series `sum A_d^k Q_d (A_d^k)^T` Smith's doubling sums in `log2` of its length (Smith 1968, SIAM J. Appl.
/// Math. 16(1): 198-201). Refused for a system that is not asymptotically stable (an undamped mode): its
/// response has no stationary variance.
pub fn stationary_covariance(sys: &StateSpace, s0: f64) -> Result<Vec<f64>, Error> {
    check("s0", s0, s0 > 0.0, "s0 > 0 (m^2/s^3)")?;
    let n = sys.n;
    let p = sys.frequency;
    // (A - p I)^-1 by LU.
    let mut lu_m = sys.a.clone();
    for i in 0..n {
        lu_m[i * n + i] -= p;
    }
    let mut piv = vec![0; n];
    if !lu::factor(&mut lu_m, &mut piv, n) {
        return Err(unstable());
    }
    let solve_cols = |rhs: &[f64]| -> Vec<f64> {
        // (A - p I)^-1 rhs, column by column.
        let mut out = vec![0.0; n * n];
        let mut col = vec![0.0; n];
        for j in 0..n {
            for i in 0..n {
                col[i] = rhs[i * n + j];
            }
            lu::solve(&lu_m, &piv, &mut col);
            for i in 0..n {
                out[i * n + j] = col[i];
            }
        }
        out
    };
    let mut plus = sys.a.clone();
    for i in 0..n {
        plus[i * n + i] += p;
    }
    let mut ad = solve_cols(&plus);
    // Q_d = 2 p u u^T with u = (A - p I)^-1 b sqrt(2 pi s0).
    let mut u = sys.b.clone();
    lu::solve(&lu_m, &piv, &mut u);
    let scale = (2.0 * std::f64::consts::PI * s0).sqrt();
    let mut pm = vec![0.0; n * n];
    for i in 0..n {
        for j in 0..n {
            pm[i * n + j] = 2.0 * p * u[i] * u[j] * scale * scale;
        }
    }
    let mut tmp = vec![0.0; n * n];
    let mut tmp2 = vec![0.0; n * n];
    let mut adt = vec![0.0; n * n];
    for _ in 0..200 {
        // P += A_d P A_d^T; A_d = A_d^2.
        mat_mul(&ad, &pm, n, &mut tmp);
        for i in 0..n {
            for j in 0..n {
                adt[i * n + j] = ad[j * n + i];
            }
        }
        mat_mul(&tmp, &adt, n, &mut tmp2);
        let mut grow = 0.0f64;
        let mut size = 0.0f64;
        for (x, d) in pm.iter_mut().zip(&tmp2) {
            *x += d;
            grow = grow.max(d.abs());
            size = size.max(x.abs());
        }
        mat_mul(&ad, &ad, n, &mut tmp);
        std::mem::swap(&mut ad, &mut tmp);
        let norm = ad.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        if !norm.is_finite() || !size.is_finite() {
            return Err(unstable());
        }
        if grow <= 1e-17 * size && norm < 1e-8 {
            // Symmetric to rounding; made exactly so.
            for i in 0..n {
                for j in 0..i {
                    let m = 0.5 * (pm[i * n + j] + pm[j * n + i]);
                    pm[i * n + j] = m;
                    pm[j * n + i] = m;
                }
            }
            return Ok(pm);
        }
    }
    Err(unstable())
}

fn unstable() -> Error {
    Error::Choice {
        name: "damping_ratio",
        value: "0 (or a mode without damping)".into(),
        allowed: "damped structures: an undamped mode has no stationary response to white noise"
            .into(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One oscillator `u'' + 2 z w u' + w^2 u = -w(t)`: `sigma_u^2 = pi s0 / (2 z w^3)` and
    /// `sigma_v^2 = pi s0 / (2 z w)` (Crandall & Mark 1963), zero covariance of u and u'.
    #[test]
    fn an_oscillator_has_the_textbook_variances() {
        let (w, z, s0) = (7.0, 0.03, 0.2);
        let sys = StateSpace {
            n: 2,
            a: vec![0.0, 1.0, -w * w, -2.0 * z * w],
            b: vec![0.0, -1.0],
            dofs: 1,
            offsets: vec![0],
            frequency: w,
        };
        let p = stationary_covariance(&sys, s0).unwrap();
        let pi = std::f64::consts::PI;
        assert!(
            (p[0] / (pi * s0 / (2.0 * z * w.powi(3))) - 1.0).abs() < 1e-12,
            "{p:?}"
        );
        assert!(
            (p[3] / (pi * s0 / (2.0 * z * w)) - 1.0).abs() < 1e-12,
            "{p:?}"
        );
        assert!(p[1].abs() < 1e-12 * (p[0] * p[3]).sqrt());
    }

    /// A 3-storey and a 2-storey building (one isolated) under Clough–Penzien noise: Smith's doubling
    /// equals the direct solution of the Lyapunov equation as the linear system
    /// `(I (x) A + A (x) I) vec(P) = -vec(Q)`, solved by LU.
    #[test]
    fn doubling_equals_the_direct_solution() {
        use crate::analysis::{Building, Scenario};
        use crate::ground_motion::Record;
        use crate::structure::{Isolator, IsolatorModel, ShearBuilding};
        let three = ShearBuilding::new(
            vec![3e5, 3e5, 2.5e5],
            vec![2e8, 1.6e8, 1.2e8],
            vec![3.0; 3],
            0.05,
        )
        .unwrap();
        // Isolated on a linear bearing with a dashpot: the superstructure's damping is not classical.
        let mut iso = Isolator::new(IsolatorModel::Linear { stiffness: 6e6 });
        iso.damping = 2.0e5;
        let two = ShearBuilding::isolated(
            2.5e5,
            iso,
            vec![2e5, 2e5],
            vec![9e7, 9e7],
            vec![3.0, 3.0],
            0.05,
        )
        .unwrap();
        let s = Scenario::new(
            vec![
                Building {
                    name: "a".into(),
                    structure: three,
                },
                Building {
                    name: "b".into(),
                    structure: two,
                },
            ],
            Record::el_centro_1940(),
        )
        .unwrap();
        let filter = Filter::CloughPenzien {
            wg: 15.6,
            zg: 0.6,
            wf: 1.56,
            zf: 0.6,
        };
        let sys = state_space(&s, Some(filter));
        let p = stationary_covariance(&sys, 0.02).unwrap();
        let n = sys.n;
        let m = n * n;
        let mut big = vec![0.0; m * m];
        // Row (i, j) of A P + P A^T: sum_k A_ik P_kj + P_ik A_jk.
        for i in 0..n {
            for j in 0..n {
                let row = i * n + j;
                for k in 0..n {
                    big[row * m + k * n + j] += sys.a[i * n + k];
                    big[row * m + i * n + k] += sys.a[j * n + k];
                }
            }
        }
        let q = 2.0 * std::f64::consts::PI * 0.02;
        let mut rhs: Vec<f64> = (0..m).map(|r| -q * sys.b[r / n] * sys.b[r % n]).collect();
        let mut piv = vec![0; m];
        assert!(lu::factor(&mut big, &mut piv, m));
        lu::solve(&big, &piv, &mut rhs);
        let scale = p.iter().fold(0.0f64, |a, x| a.max(x.abs()));
        for (x, y) in p.iter().zip(&rhs) {
            assert!((x - y).abs() < 1e-9 * scale, "{x} vs {y}");
        }
    }
}
