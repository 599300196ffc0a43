//! A whole record interval in one exact step, for motions whose fast modes would split it into many
//! series-length steps (a foundation on soil, a stiff column): the transition by scaling and squaring
//! (Moler & Van Loan 2003, "Nineteen dubious ways", method 3, with the series of [`super::transition`] on
//! the scaled step), and integrals of quadratic forms along the motion by doubling.

use super::exact::{transition, GAUSS_NODES, GAUSS_WEIGHTS, MAX_RHO};

/// The halvings `s` that bring a step of `rho = r h` within the series' reach: the least with
/// `rho / 2^s <= MAX_RHO`.
pub fn halvings(rho: f64) -> u32 {
    let mut s = 0;
    let mut x = rho;
    while x > MAX_RHO && s < 60 {
        x *= 0.5;
        s += 1;
    }
    s
}

/// `out = a b` for square row-major `nw x nw` matrices (each entry summed over `k` in order).
pub fn mat_mul(a: &[f64], b: &[f64], nw: usize, out: &mut [f64]) {
    for (row, arow) in out.chunks_exact_mut(nw).zip(a.chunks_exact(nw)) {
        row.fill(0.0);
        for (&aik, brow) in arow.iter().zip(b.chunks_exact(nw)) {
            if aik != 0.0 {
                row.iter_mut().zip(brow).for_each(|(o, b)| *o += aik * b);
            }
        }
    }
}

/// All of `exp(M h)` (`nw x nw`) for a step within the series' reach: the rows of [`transition`] and the
/// forcing block `I + F h` (`F^2 = 0`).
fn short_exponential(m: &[f64], nw: usize, mech: usize, h: f64) -> Vec<f64> {
    let mut e = vec![0.0; nw * nw];
    e[..mech * nw].copy_from_slice(&transition(m, nw, mech, h));
    for i in mech..nw {
        for j in mech..nw {
            e[i * nw + j] = h * m[i * nw + j];
        }
        e[i * nw + i] += 1.0;
    }
    e
}

/// `exp(M h)` (`nw x nw`, row-major) for `w' = M w` as [`transition`] takes it, at any `h` (s): the series
/// on `h / 2^s` ([`halvings`] of `r h`, `r` the step bound, 1/s), squared `s` times. Each squaring adds
/// about one rounding of the norm; `s` stays below 12 for the structures of this library.
pub fn exponential(m: &[f64], nw: usize, mech: usize, h: f64, r: f64) -> Vec<f64> {
    let s = halvings(r * h);
    let mut e = short_exponential(m, nw, mech, h / f64::powi(2.0, s as i32));
    let mut t = vec![0.0; nw * nw];
    for _ in 0..s {
        mat_mul(&e, &e, nw, &mut t);
        std::mem::swap(&mut e, &mut t);
    }
    e
}

/// The first `mech` rows of `exp(M h)` at any `h` (see [`exponential`]; [`transition`] itself within the
/// series' reach).
pub fn transition_rows(m: &[f64], nw: usize, mech: usize, h: f64, r: f64) -> Vec<f64> {
    if halvings(r * h) == 0 {
        transition(m, nw, mech, h)
    } else {
        exponential(m, nw, mech, h, r)[..mech * nw].to_vec()
    }
}

/// `out += weight P^T Q P` (all `nw x nw`), with `tmp` for `Q P`.
fn add_congruence(p: &[f64], q: &[f64], weight: f64, nw: usize, out: &mut [f64], tmp: &mut [f64]) {
    mat_mul(q, p, nw, tmp);
    for k in 0..nw {
        let prow = &p[k * nw..(k + 1) * nw];
        let trow = &tmp[k * nw..(k + 1) * nw];
        for (i, &pki) in prow.iter().enumerate() {
            if pki != 0.0 {
                let w = weight * pki;
                out[i * nw..(i + 1) * nw]
                    .iter_mut()
                    .zip(trow)
                    .for_each(|(o, t)| *o += w * t);
            }
        }
    }
}

/// `G = int_0^h exp(M t)^T Q exp(M t) dt` for each form `Q` (`nw x nw`, symmetric): so that a quantity whose
/// rate is `w^T Q w` grows by `w0^T G w0` over a step of length `h` from `w0`. Three-point Gauss–Legendre
/// on each of the `2^s` pieces of the step ([`halvings`], the accuracy of an exact step's energies), the
/// pieces summed exactly by doubling: `G(2 t) = G(t) + exp(M t)^T G(t) exp(M t)`.
pub fn form_integrals(
    m: &[f64],
    nw: usize,
    mech: usize,
    (h, r): (f64, f64),
    forms: &[&[f64]],
) -> Vec<Vec<f64>> {
    let s = halvings(r * h);
    let piece = h / f64::powi(2.0, s as i32);
    let nodes: Vec<Vec<f64>> = GAUSS_NODES
        .iter()
        .map(|g| short_exponential(m, nw, mech, g * piece))
        .collect();
    let mut tmp = vec![0.0; nw * nw];
    let mut gs: Vec<Vec<f64>> = forms
        .iter()
        .map(|q| {
            let mut g = vec![0.0; nw * nw];
            for (node, w) in nodes.iter().zip(GAUSS_WEIGHTS) {
                add_congruence(node, q, piece * w, nw, &mut g, &mut tmp);
            }
            g
        })
        .collect();
    let mut e = short_exponential(m, nw, mech, piece);
    let mut next = vec![0.0; nw * nw];
    for _ in 0..s {
        for g in &mut gs {
            next.copy_from_slice(g);
            add_congruence(&e, &next, 1.0, nw, g, &mut tmp);
        }
        mat_mul(&e, &e, nw, &mut next);
        std::mem::swap(&mut e, &mut next);
    }
    gs
}

#[cfg(test)]
mod tests {
    use super::super::exact::tests::oscillator;
    use super::*;

    #[test]
    fn the_exponential_of_a_long_step_is_the_closed_form() {
        // Free vibration: u = e^(-zeta w t) (cos wd t + zeta w / wd sin wd t) from u = 1, v = 0.
        let (w, zeta, h) = (150.0, 0.05, 0.02);
        let m = oscillator(w, zeta);
        let e = exponential(&m, 4, 2, h, super::super::step_bound(&m, 4, 1));
        let wd = w * (1.0 - zeta * zeta).sqrt();
        let decay = (-zeta * w * h).exp();
        let u = decay * ((wd * h).cos() + zeta * w / wd * (wd * h).sin());
        let v = -decay * w * w / wd * (wd * h).sin();
        assert!((e[0] - u).abs() < 1e-13, "{} {u}", e[0]);
        assert!((e[4] - v).abs() < 1e-13 * w, "{} {v}", e[4]);
        // The forcing block: g(h) = g + s h.
        assert_eq!(e[2 * 4 + 3], h);
    }

    #[test]
    fn a_form_integral_is_the_energy_dissipated_in_free_vibration() {
        // From u = 1, v = 0 the dashpot dissipates int 2 zeta w v^2 dt = (u0^2 w^2 / 2)(1 - E(h)) where E is
        // the energy left, in closed form at t = h.
        let (w, zeta, h) = (150.0, 0.3, 0.02);
        let m = oscillator(w, zeta);
        let mut q = vec![0.0; 16];
        q[4 + 1] = 2.0 * zeta * w;
        let r = super::super::step_bound(&m, 4, 1);
        let g = form_integrals(&m, 4, 2, (h, r), &[&q]);
        let e = exponential(&m, 4, 2, h, r);
        let (u, v) = (e[0], e[4]);
        let dissipated = 0.5 * w * w - (0.5 * w * w * u * u + 0.5 * v * v);
        // To the accuracy of three-point Gauss on pieces of r h <= 1/2 (what a fine exact step's energies
        // have): 4.6e-10 here, the quadrature's error (the doubling itself is exact).
        assert!(
            (g[0][0] - dissipated).abs() < 2e-9 * dissipated,
            "{} {dissipated}",
            g[0][0]
        );
    }
}
