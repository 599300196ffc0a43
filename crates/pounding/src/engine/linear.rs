//! The motion of a [`System`] while every law is affine, as one linear system `w' = M w`.
//!
//! `w = [u (n), v (n), (g_c, s_c) per ground channel, f0 (one per element whose law may have one)]`: displacements and velocities of
//! the degrees of freedom, each ground channel's acceleration (m/s^2) and its slope (m/s^3) on the current
//! interval between the ground's kinks (so `g' = s`, `s' = 0`), and each element's constant force `f0` (N,
//! `f0' = 0`). The channels are x and y for one record or two on one grid ([`Ground::Record`],
//! [`Ground::Plane`]), and each support's record for supports of their own ([`Ground::Many`]: record 0, the
//! scenario's, is channel 0). The equations of motion are those of [`System`]'s right-hand side with each law
//! replaced by its [`crate::element::Affine`] form; `M` depends only on the laws' stiffnesses and viscous
//! coefficients, so a bilinear storey that yields keeps its matrix family and only its `f0` changes.

use super::{Ground, System};

/// The ground channels of `ground`: at least two (x and y), or one per record of supports of their own.
pub(crate) fn channels(ground: Ground<'_>) -> usize {
    match ground {
        Ground::Many(rs) => rs.len().max(2),
        _ => 2,
    }
}

/// Ground channel `c`'s acceleration at `t`, m/s^2 (0 for a channel the ground does not have).
pub(crate) fn channel_at(ground: Ground<'_>, c: usize, t: f64) -> f64 {
    match (ground, c) {
        (Ground::Many(rs), c) => rs.get(c).map_or(0.0, |r| r.at(t)),
        (Ground::Plane { y, .. }, 1) => y.at(t),
        (g, 0) => g.at(t),
        _ => 0.0,
    }
}

/// The ground's accelerations `(g_x, g_y)` (m/s^2) of channels 0 and 1 at `tau` (s) into a step whose `w` at
/// its start is `w` (what [`System::rhs_in`] takes); `mech` is the number of displacements and velocities in
/// `w`.
#[inline]
pub(crate) fn forcing(w: &[f64], mech: usize, tau: f64) -> (f64, f64) {
    let f = &w[mech..mech + 4];
    (f[0] + f[1] * tau, f[2] + f[3] * tau)
}

/// `w` at `tau` into a step that started at `w0`, its motion `motion` (`mech` components, the rest unread)
/// there: the ground channels carried along their lines, the constant forces as they were.
/// `fd` components after the motion carry the channels (`[g_0, s_0, g_1, s_1, ...]`).
pub(super) fn full_w_at(
    motion: &[f64],
    (w0, mech, fd): (&[f64], usize, usize),
    tau: f64,
    out: &mut [f64],
) {
    out.copy_from_slice(w0);
    out[..mech].copy_from_slice(&motion[..mech]);
    for c in (mech..mech + fd).step_by(2) {
        out[c] += w0[c + 1] * tau;
    }
}

/// The degrees of freedom and weights of element `el`'s deformation `x = sum over a's terms - sum over b's
/// terms`.
pub(super) fn deformation_terms(el: &crate::element::Element) -> Vec<(usize, f64)> {
    let (ta, tb) = (el.a.terms(), el.b.terms());
    let a = ta.terms().iter().copied();
    let b = tb.terms().iter().map(|&(i, c)| (i, -c));
    a.chain(b).collect()
}

impl System<'_> {
    /// Whether the motion can be written as `w' = M w` now: every law affine. Writes the configuration's key (the laws' stiffnesses
    /// and viscous coefficients, bit for bit) to `key` and each element's `f0` to `f0`.
    pub(crate) fn linear_now(&self, key: &mut Vec<u64>, f0: &mut Vec<f64>) -> bool {
        key.clear();
        f0.clear();
        for (el, constant) in self.elements.iter().zip(&self.constants) {
            let Some(a) = el.affine() else {
                return false;
            };
            key.push(a.k.to_bits());
            key.push(a.c.to_bits());
            match constant {
                Some(_) => f0.push(a.f0),
                // A law that said it has no constant force, and has one: not propagated exactly.
                None if a.f0 != 0.0 => return false,
                None => {}
            }
        }
        true
    }

    /// The number of components of `w`.
    pub(crate) fn linear_dim(&self) -> usize {
        2 * self.layout.dofs() + self.forcing_dim() + self.constants.iter().flatten().count()
    }

    /// The component of `w` that holds element `e`'s constant force, if it has one.
    pub(crate) fn constant_in(&self, e: usize) -> Option<usize> {
        self.constants[e].map(|c| 2 * self.layout.dofs() + self.forcing_dim() + c)
    }

    /// The components of `w` that carry the ground channels (two per channel).
    pub(crate) fn forcing_dim(&self) -> usize {
        2 * channels(self.ground)
    }

    /// The ground channels that shake degree of freedom `i`, with their coefficients: its own support's
    /// record, or the pull of x and y.
    pub(crate) fn channels_of(&self, i: usize) -> [(usize, f64); 2] {
        match (self.source[i], self.ground) {
            (Some((k, _)), Ground::Many(_)) => [(k, 1.0), (0, 0.0)],
            _ => [(0, self.pull[i].0), (1, self.pull[i].1)],
        }
    }

    /// The ground's acceleration that shakes degree of freedom `i` in a step whose `w` at its start is `w`
    /// (`mech` displacements and velocities), as a line in the offset into the step: read off `w` once
    /// for the many offsets a search reads.
    pub(crate) fn ground_in(&self, i: usize, w: &[f64], mech: usize) -> GroundLine {
        GroundLine(
            self.channels_of(i)
                .map(|(c, p)| (p, w[mech + 2 * c], w[mech + 2 * c + 1])),
        )
    }

    /// `M` (row-major, [`Self::linear_dim`] squared) of the current configuration ([`Self::linear_now`]).
    pub(crate) fn linear_matrix(&self) -> Vec<f64> {
        let n = self.layout.dofs();
        let nw = self.linear_dim();
        let g = 2 * n;
        let mut m = vec![0.0; nw * nw];
        let fd = self.forcing_dim();
        for i in 0..n {
            m[i * nw + n + i] = 1.0;
            let row = (n + i) * nw;
            // A driven support moves with its record's acceleration, whatever the forces on it.
            let sign = if self.driven.contains(&i) { 1.0 } else { -1.0 };
            for (c, p) in self.channels_of(i) {
                m[row + g + 2 * c] += sign * p;
            }
            m[row + n + i] = -self.a0[i];
        }
        for c in (0..fd).step_by(2) {
            m[(g + c) * nw + g + c + 1] = 1.0;
        }
        for (e, el) in self.elements.iter().enumerate() {
            let a = el.affine().expect("an affine configuration");
            // The force acts -F on a's terms, +F on b's.
            let x = deformation_terms(el);
            for &(i, ci) in x.iter().filter(|(i, _)| !self.driven.contains(i)) {
                let row = (n + i) * nw;
                let inv = self.inv_mass[i];
                for &(j, cj) in &x {
                    m[row + j] -= ci * cj * a.k * inv;
                    m[row + n + j] -= ci * cj * a.c * inv;
                }
                if let Some(c) = self.constant_in(e) {
                    m[row + c] -= ci * inv;
                }
            }
        }
        m
    }

    /// `w` at `(t, y)` for an interval on which ground channel `c`'s acceleration is
    /// `g_c + s_c (t' - t)` (`forcing = [g_0, s_0, g_1, s_1, ...]`, [`Self::forcing_dim`] of them).
    pub(crate) fn linear_state(&self, y: &[f64], forcing: &[f64], f0: &[f64], w: &mut [f64]) {
        let n2 = 2 * self.layout.dofs();
        let fd = forcing.len();
        w[..n2].copy_from_slice(&y[..n2]);
        w[n2..n2 + fd].copy_from_slice(forcing);
        w[n2 + fd..].copy_from_slice(f0);
    }
}

/// The ground's acceleration shaking one degree of freedom inside a step: per channel, its weight, the
/// channel's acceleration at the step's start (m/s^2) and its slope (m/s^3) ([`System::ground_in`]).
#[derive(Clone, Copy, Debug)]
pub(crate) struct GroundLine([(f64, f64, f64); 2]);

impl GroundLine {
    /// The acceleration at `tau` s into the step, m/s^2.
    #[inline]
    pub(crate) fn at(&self, tau: f64) -> f64 {
        self.0
            .iter()
            .fold(0.0, |a, &(p, g, sl)| a + p * (g + sl * tau))
    }

    /// Its slope, m/s^3.
    #[inline]
    pub(crate) fn slope(&self) -> f64 {
        self.0.iter().fold(0.0, |s, &(p, _, sl)| s + p * sl)
    }
}
