//! A whole record interval in one exact step, for motions whose fast modes would split it into many
//! series-length steps (a foundation on soil, a stiff column): the transition by scaling and squaring
//! (Moler & Van Loan 2003, "Nineteen dubious ways", method 3, with the series of [`super::transition`] on
//! the scaled step), and integrals of quadratic forms along the motion by doubling.

use super::exact::{quadrature, transition, MAX_RHO};
use super::memo::{remembered, Key, Memo};
use std::cell::RefCell;

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

/// One block of a step's doubling ([`form_blocks`]): `2^i` of its pieces.
#[derive(Clone, Debug)]
pub struct Block {
    /// The first `mech` rows of `exp(M t)` over the block (row-major `mech x nw`).
    pub rows: Vec<f64>,
    /// `G = int_0^t exp(M s)^T Q exp(M s) ds` over the block for each form `Q` (`nw x nw`).
    pub integrals: Vec<Vec<f64>>,
}

/// For a step of length `h` split into `2^s` pieces ([`halvings`] of `r h`, `r` the step bound, 1/s): the
/// blocks of `1, 2, 4, ..., 2^s` pieces, each with its transition and, for each form `Q` (`nw x nw`,
/// symmetric), `G = int_0^t exp(M s)^T Q exp(M s) ds` over it, so that a quantity whose rate is `w^T Q w`
/// grows by `w0^T G w0` over a block from `w0`. Gauss–Legendre on each piece ([`quadrature`], the accuracy
/// of an exact step's energies), the pieces summed exactly by doubling: `G(2 t) = G(t) + exp(M t)^T G(t)
/// exp(M t)`, the transitions by squaring (as [`exponential`]).
pub fn form_blocks(
    m: &[f64],
    nw: usize,
    mech: usize,
    (h, r): (f64, f64),
    forms: &[&[f64]],
) -> Vec<Block> {
    thread_local! {
        static BUILT: RefCell<Memo<Vec<Block>>> = const { RefCell::new(Memo::new()) };
    }
    let key = Key::default().count(nw).count(mech).num(h).num(r).slice(m);
    let key = forms.iter().fold(key, |k, q| k.slice(q));
    let bytes = |blocks: &Vec<Block>| {
        let numbers = |b: &Block| b.rows.len() + b.integrals.iter().map(Vec::len).sum::<usize>();
        8 * blocks.iter().map(numbers).sum::<usize>()
    };
    remembered(&BUILT, key, bytes, || {
        build_form_blocks(m, nw, mech, (h, r), forms)
    })
}

/// [`form_blocks`], built.
fn build_form_blocks(
    m: &[f64],
    nw: usize,
    mech: usize,
    (h, r): (f64, f64),
    forms: &[&[f64]],
) -> Vec<Block> {
    let s = halvings(r * h);
    let piece = h / f64::powi(2.0, s as i32);
    let (at, weights) = quadrature(r * piece);
    let nodes: Vec<Vec<f64>> = at
        .iter()
        .map(|g| short_exponential(m, nw, mech, g * piece))
        .collect();
    let mut tmp = vec![0.0; nw * nw];
    let mut gs: Vec<Vec<f64>> = forms
        .iter()
        .map(|q| {
            let mut g = vec![0.0; nw * nw];
            for (node, w) in nodes.iter().zip(weights) {
                add_congruence(node, q, piece * w, nw, &mut g, &mut tmp);
            }
            g
        })
        .collect();
    let mut e = short_exponential(m, nw, mech, piece);
    let mut next = vec![0.0; nw * nw];
    let mut blocks = Vec::with_capacity(s as usize + 1);
    for i in 0..=s {
        blocks.push(Block {
            rows: e[..mech * nw].to_vec(),
            integrals: gs.clone(),
        });
        if i == s {
            break;
        }
        for g in &mut gs {
            next.copy_from_slice(g);
            add_congruence(&e, &next, 1.0, nw, g, &mut tmp);
        }
        mat_mul(&e, &e, nw, &mut next);
        std::mem::swap(&mut e, &mut next);
    }
    blocks
}

/// `out = A exp(M t)` for rows `A` (`nw` columns each), given the first `mech` rows of `exp(M t)` (`rows`);
/// its forcing block is `I + F t` (`F^2 = 0`, as [`transition`] takes it). Rows of `exp(M s)` give those of
/// `exp(M (s + t))`; a functional's row gives its value after `t` as a row product.
pub fn times_transition(
    a: &[f64],
    (m, rows): (&[f64], &[f64]),
    (nw, mech): (usize, usize),
    t: f64,
    out: &mut [f64],
) {
    for (o, r) in out.chunks_exact_mut(nw).zip(a.chunks_exact(nw)) {
        o.fill(0.0);
        for (l, &rl) in r.iter().enumerate().filter(|(_, x)| **x != 0.0) {
            if l < mech {
                o.iter_mut()
                    .zip(&rows[l * nw..(l + 1) * nw])
                    .for_each(|(o, p)| *o += rl * p);
            } else {
                o[l] += rl;
                for j in mech..nw {
                    o[j] += rl * t * m[l * nw + j];
                }
            }
        }
    }
}

/// The row `a^T exp(M k p)` for `k = 1 .. pieces - 1`, one after the other (`nw` each), appended to `out`:
/// what the linear functional `a . w` (an element's deformation) is at the start of each piece of a chained
/// step, as one product with `w0` instead of a walk along the chain. `rows` are the first `mech` rows of
/// `exp(M p)` ([`times_transition`]).
pub fn functional_at_pieces(
    a: &[f64],
    (m, rows): (&[f64], &[f64]),
    (nw, mech): (usize, usize),
    (piece, pieces): (f64, usize),
    out: &mut Vec<f64>,
) {
    thread_local! {
        static BUILT: RefCell<Memo<Vec<f64>>> = const { RefCell::new(Memo::new()) };
    }
    let key = Key::default()
        .count(nw)
        .count(mech)
        .num(piece)
        .count(pieces);
    let key = key.slice(a).slice(m).slice(rows);
    let built = remembered(
        &BUILT,
        key,
        |v| 8 * v.len(),
        || {
            let mut built = Vec::with_capacity(pieces.saturating_sub(1) * nw);
            let mut r = a.to_vec();
            let mut next = vec![0.0; nw];
            for _ in 1..pieces {
                times_transition(&r, (m, rows), (nw, mech), piece, &mut next);
                std::mem::swap(&mut r, &mut next);
                built.extend_from_slice(&r);
            }
            built
        },
    );
    out.extend_from_slice(&built);
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
    fn each_block_integrates_the_energy_dissipated_in_free_vibration() {
        // From u = 1, v = 0 the dashpot dissipates int 2 zeta w v^2 dt = (w^2 / 2)(1 - E(t)) over [0, t],
        // E(t) the energy left, in closed form (as in the test above), for the block of each length t.
        // Pieces of r h = 0.36 take three-point Gauss: its error, 2.6e-10 of the energy there was (the
        // bound rho^7 (3!)^4 / (7 (6!)^3) of a rate of scale w, 4e-10). Pieces of r h = 0.6 take five
        // points: within rounding (5e-15 measured; the bound, 1.4e-15). The doubling adds no error.
        let (w, zeta) = (150.0, 0.3);
        for (h, within) in [(0.0015, 1e-9), (0.02, 1e-13)] {
            let m = oscillator(w, zeta);
            let mut q = vec![0.0; 16];
            q[4 + 1] = 2.0 * zeta * w;
            let r = super::super::step_bound(&m, 4, 1);
            let blocks = form_blocks(&m, 4, 2, (h, r), &[&q]);
            let s = halvings(r * h);
            assert_eq!(blocks.len(), s as usize + 1);
            // The last block's transition is the exponential's (the same squarings).
            assert_eq!(blocks[s as usize].rows, exponential(&m, 4, 2, h, r)[..8]);
            let wd = w * (1.0 - zeta * zeta).sqrt();
            for (i, b) in blocks.iter().enumerate() {
                let t = h * f64::powi(2.0, i as i32 - s as i32);
                let decay = (-zeta * w * t).exp();
                let u = decay * ((wd * t).cos() + zeta * w / wd * (wd * t).sin());
                let v = -decay * w * w / wd * (wd * t).sin();
                assert!((b.rows[0] - u).abs() < 1e-13, "{i}: {} {u}", b.rows[0]);
                assert!((b.rows[4] - v).abs() < 1e-13 * w, "{i}: {} {v}", b.rows[4]);
                let dissipated = 0.5 * w * w * (1.0 - (u * u + v * v / (w * w)));
                let g = b.integrals[0][0];
                assert!(
                    (g - dissipated).abs() < within * 0.5 * w * w,
                    "{h} {i}: {g} {dissipated}"
                );
            }
        }
    }

    #[test]
    fn rows_times_a_transition_are_the_rows_of_the_longer_step() {
        // exp(M s) exp(M t) = exp(M (s + t)), the forcing block included (a ground line with a slope).
        let (w, zeta) = (150.0, 0.05);
        let m = oscillator(w, zeta);
        let r = super::super::step_bound(&m, 4, 1);
        let (s, t) = (0.0037, 0.011);
        let a = exponential(&m, 4, 2, s, r);
        let b = exponential(&m, 4, 2, t, r);
        let want = exponential(&m, 4, 2, s + t, r);
        let mut got = vec![0.0; 8];
        times_transition(&a[..8], (&m, &b[..8]), (4, 2), t, &mut got);
        for (k, (g, e)) in got.iter().zip(&want).enumerate() {
            let scale = if k < 4 { 1.0 } else { w };
            assert!((g - e).abs() < 1e-13 * scale, "{k}: {g} vs {e}");
        }
    }
}
