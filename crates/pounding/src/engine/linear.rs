//! The motion of a [`System`] while every law is affine, as one linear system `w' = M w`.
//!
//! `w = [u (n), v (n), g_x, s_x, g_y, s_y, f0 (one per element)]`: displacements and velocities of the
//! degrees of freedom, the ground's acceleration along x and y (m/s^2) and their slopes (m/s^3) on the current
//! record interval (so `g' = s`, `s' = 0`), and each element's constant force `f0` (N, `f0' = 0`). The equations of motion are those of
//! [`System`]'s right-hand side with each law replaced by its [`crate::element::Affine`] form; `M` depends only
//! on the laws' stiffnesses and viscous coefficients, so a bilinear storey that yields keeps its matrix
//! family and only its `f0` changes.

use super::{Ground, System};

/// Components of `w` after the motion that carry the ground's accelerations and slopes.
pub(crate) const FORCING: usize = 4;

/// The ground's accelerations `(g_x, g_y)` (m/s^2) at `tau` (s) into a step whose `w` at its start is `w`,
/// and their slopes `(s_x, s_y)` (m/s^3); `mech` is the number of displacements and velocities in `w`.
#[inline]
pub(crate) fn forcing(w: &[f64], mech: usize, tau: f64) -> ((f64, f64), (f64, f64)) {
    let f = &w[mech..mech + FORCING];
    ((f[0] + f[1] * tau, f[2] + f[3] * tau), (f[1], f[3]))
}

impl System<'_> {
    /// Whether the motion can be written as `w' = M w` now: one record along x, two on one grid, or a constant
    /// acceleration (not supports of their own), every law affine. Writes the configuration's key (the laws' stiffnesses
    /// and viscous coefficients, bit for bit) to `key` and each element's `f0` to `f0`.
    pub(crate) fn linear_now(&self, key: &mut Vec<u64>, f0: &mut Vec<f64>) -> bool {
        if matches!(self.ground, Ground::Many(_)) || !self.driven.is_empty() {
            return false;
        }
        key.clear();
        f0.clear();
        for el in &self.elements {
            let Some(a) = el.affine() else {
                return false;
            };
            key.push(a.k.to_bits());
            key.push(a.c.to_bits());
            f0.push(a.f0);
        }
        true
    }

    /// The number of components of `w`.
    pub(crate) fn linear_dim(&self) -> usize {
        2 * self.layout.dofs() + FORCING + self.elements.len()
    }

    /// `M` (row-major, [`Self::linear_dim`] squared) of the current configuration ([`Self::linear_now`]).
    pub(crate) fn linear_matrix(&self) -> Vec<f64> {
        let n = self.layout.dofs();
        let nw = self.linear_dim();
        let g = 2 * n;
        let mut m = vec![0.0; nw * nw];
        for i in 0..n {
            m[i * nw + n + i] = 1.0;
            let row = (n + i) * nw;
            m[row + g] = -self.pull[i].0;
            m[row + g + 2] = -self.pull[i].1;
            m[row + n + i] = -self.a0[i];
        }
        m[g * nw + g + 1] = 1.0;
        m[(g + 2) * nw + g + 3] = 1.0;
        for (e, el) in self.elements.iter().enumerate() {
            let a = el.affine().expect("an affine configuration");
            // x = sum over a's terms - sum over b's terms; the force acts -F on a's, +F on b's.
            let ta = el.a.terms();
            let tb = el.b.terms();
            let signed = |side: usize| -> Vec<(usize, f64)> {
                let (t, sign) = if side == 0 { (&ta, 1.0) } else { (&tb, -1.0) };
                t.terms().iter().map(|&(i, c)| (i, sign * c)).collect()
            };
            let x: Vec<(usize, f64)> = signed(0).into_iter().chain(signed(1)).collect();
            for &(i, ci) in &x {
                let row = (n + i) * nw;
                let inv = self.inv_mass[i];
                for &(j, cj) in &x {
                    m[row + j] -= ci * cj * a.k * inv;
                    m[row + n + j] -= ci * cj * a.c * inv;
                }
                m[row + 2 * n + FORCING + e] -= ci * inv;
            }
        }
        m
    }

    /// `w` at `(t, y)` for a record interval on which the ground's accelerations are `g + s (t' - t)` along x
    /// and along y (`forcing = [g_x, s_x, g_y, s_y]`).
    pub(crate) fn linear_state(
        &self,
        y: &[f64],
        forcing: [f64; FORCING],
        f0: &[f64],
        w: &mut [f64],
    ) {
        let n2 = 2 * self.layout.dofs();
        w[..n2].copy_from_slice(&y[..n2]);
        w[n2..n2 + FORCING].copy_from_slice(&forcing);
        w[n2 + FORCING..].copy_from_slice(f0);
    }
}
