//! The rates of a [`System`]'s integrated quantities (input and damping energy, the laws' states) while
//! every law is affine, as quadratic forms of the linear state `w` ([`super::linear`]): `q' = w^T Q w`.
//! Integrated along the exact motion over a whole record interval (`int_0^h Φ(t)^T Q Φ(t) dt`,
//! [`crate::integrate::form_integrals`]), they give the energies of an interval without stepping through it.

use super::linear::deformation_terms;
use super::System;
use crate::element::ElementLaw;
use crate::integrate::Sparse;

/// Adds `value w_a w_b` to the form `q` (`nw x nw`, row-major, kept symmetric).
fn add(q: &mut [f64], nw: usize, a: usize, b: usize, value: f64) {
    if a == b {
        q[a * nw + a] += value;
    } else {
        q[a * nw + b] += 0.5 * value;
        q[b * nw + a] += 0.5 * value;
    }
}

impl System<'_> {
    /// The rate of each integrated quantity of the layout (index past the motion, `k` for layout component
    /// `2 n + k`) that is not identically 0 in the current configuration, as a form on `w`; `None` when a
    /// law cannot give its states' rates ([`ElementLaw::affine_rates`]) or a law is not affine.
    pub(crate) fn rate_forms(&self) -> Option<Vec<(usize, Vec<f64>)>> {
        let n = self.layout.dofs();
        let nw = self.linear_dim();
        let acc = self.layout.dim() - 2 * n;
        let mut forms = vec![vec![0.0; nw * nw]; acc];
        let (input, damping) = (self.layout.input() - 2 * n, self.layout.damping() - 2 * n);
        // Input: the ground's inertia force on each mass, and the forces a driven support takes.
        for i in 0..n {
            let m = self.mass[i];
            for (c, p) in self.channels_of(i) {
                add(&mut forms[input], nw, n + i, 2 * n + 2 * c, -m * p);
            }
            add(&mut forms[damping], nw, n + i, n + i, self.a0[i] * m);
        }
        let mut rates = [[0.0; 3]; 8];
        for (e, el) in self.elements.iter().enumerate() {
            let a = el.affine()?;
            let x = deformation_terms(el);
            let f0 = self.constant_in(e);
            for &(i, ci) in &x {
                for &(j, cj) in &x {
                    add(&mut forms[damping], nw, n + i, n + j, a.viscous * ci * cj);
                }
            }
            // A driven support's share: the element's whole force times the support's velocity.
            for &d in &self.driven {
                for &(i, ci) in x.iter().filter(|(i, _)| *i == d) {
                    // x = ... + ci u_d: the force acts -ci F on d, and -(-ci F) v_d is the input.
                    for &(j, cj) in &x {
                        add(&mut forms[input], nw, n + i, j, ci * a.k * cj);
                        add(&mut forms[input], nw, n + i, n + j, ci * a.c * cj);
                    }
                    if let Some(f0) = f0 {
                        add(&mut forms[input], nw, n + i, f0, ci);
                    }
                }
            }
            let states = self.layout.block(e);
            if states.is_empty() {
                continue;
            }
            let law = el.law.affine()?;
            let out = rates.get_mut(..states.len())?;
            if !el.law.affine_rates(&law, out) {
                return None;
            }
            for (s, &[p, q, r]) in states.zip(out.iter()) {
                let form = &mut forms[s - 2 * n];
                for &(i, ci) in &x {
                    for &(j, cj) in &x {
                        add(form, nw, i, n + j, p * ci * cj);
                        add(form, nw, n + i, n + j, q * ci * cj);
                    }
                    if let Some(f0) = f0.filter(|_| r != 0.0) {
                        add(form, nw, f0, n + i, r * ci);
                    }
                }
            }
        }
        Some(
            forms
                .into_iter()
                .enumerate()
                .filter(|(_, q)| q.iter().any(|&x| x != 0.0))
                .collect(),
        )
    }
}

/// Nonzero entries `(a, b, value)` of a sparse matrix or form.
type Entries = Vec<(usize, usize, f64)>;

/// The rate of every layout component at any `w` of one configuration, without evaluating the laws: the
/// displacements' rates are the velocities, the velocities' the rows of `M` (m/s^2 or rad/s^2), and the
/// integrated quantities' their forms ([`System::rate_forms`]; 0 where a quantity has none). Sparse: a
/// configuration's `M` and forms have a few entries per row, so the rates at a step's Gauss nodes and end
/// cost a small part of the right-hand side they stand for.
#[derive(Debug)]
pub(crate) struct AffineRates {
    /// Degrees of freedom.
    n: usize,
    /// The nonzeros of `M`, row by row: the velocities' rows are read (each summed in a register).
    rows: Sparse,
    /// The velocities' rows of `M` whole (`n x nw`), where most of their entries are not 0 (a building on
    /// soil): a dense product costs less than walking the nonzeros.
    dense: Option<Vec<f64>>,
    /// For each integrated quantity with a form (layout component `2 n + k`): `k` and the form's entries
    /// `(a, b, c)` for `c w_a w_b`, each pair once (`a <= b`).
    forms: Vec<(usize, Entries)>,
}

impl AffineRates {
    /// The rates of the configuration of matrix `M` (its nonzeros `rows`, [`Sparse::of`]; `nw x nw`) with `n`
    /// degrees of freedom and the integrated quantities' `forms`.
    pub(crate) fn new(rows: Sparse, nw: usize, n: usize, forms: &[(usize, Vec<f64>)]) -> Self {
        let forms = forms
            .iter()
            .map(|(k, q)| {
                let entries = (0..nw)
                    .flat_map(|a| (a..nw).map(move |b| (a, b)))
                    .map(|(a, b)| {
                        let c = if a == b {
                            q[a * nw + a]
                        } else {
                            q[a * nw + b] + q[b * nw + a]
                        };
                        (a, b, c)
                    })
                    .filter(|&(_, _, c)| c != 0.0)
                    .collect();
                (*k, entries)
            })
            .collect();
        let nonzeros: usize = (n..2 * n).map(|i| rows.row(i).len()).sum();
        let dense = (n > 0 && 2 * nonzeros >= n * nw).then(|| {
            let mut d = vec![0.0; n * nw];
            for (i, row) in d.chunks_exact_mut(nw).enumerate() {
                for (j, v) in rows.row(n + i) {
                    row[j] = v;
                }
            }
            d
        });
        Self {
            n,
            rows,
            dense,
            forms,
        }
    }

    /// The integrated quantities' rates at `w`, one per quantity (as [`Self::write`] writes them past the
    /// motion).
    pub(crate) fn write_integrated(&self, w: &[f64], out: &mut [f64]) {
        out.fill(0.0);
        for (k, entries) in &self.forms {
            out[*k] = entries.iter().map(|&(a, b, c)| c * w[a] * w[b]).sum();
        }
    }

    /// Writes the rate of each layout component at `w` to `out` (the layout's length).
    pub(crate) fn write(&self, w: &[f64], out: &mut [f64]) {
        self.write_motion(w, out);
        self.write_integrated(w, &mut out[2 * self.n..]);
    }

    /// Writes the rates of the motion alone (the displacements' and velocities', `out[..2 n]`) at `w`.
    pub(crate) fn write_motion(&self, w: &[f64], out: &mut [f64]) {
        let n = self.n;
        out[..n].copy_from_slice(&w[n..2 * n]);
        if let Some(dense) = &self.dense {
            // The same sums as over the nonzeros, with zeros between (a zero's sign aside).
            let nw = dense.len() / n;
            for (o, row) in out[n..2 * n].iter_mut().zip(dense.chunks_exact(nw)) {
                *o = row.iter().zip(&w[..nw]).fold(0.0, |a, (v, x)| a + v * x);
            }
            return;
        }
        for (i, o) in out[n..2 * n].iter_mut().enumerate() {
            // From 0 in the row's order, as the entries were once added to it.
            *o = self.rows.row(n + i).fold(0.0, |a, (j, v)| a + v * w[j]);
        }
    }
}

impl crate::integrate::IntegratedRates for AffineRates {
    fn integrated_rates(&self, w: &[f64], out: &mut [f64]) {
        self.write_integrated(w, out);
    }
}
