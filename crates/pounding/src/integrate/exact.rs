//! Exact propagation of a linear system `w' = M w` over a short step, and its motion between the ends.
//!
//! Over a step of length `h` with `rho = r h <= 1`, where `r` bounds `|M|` in a norm that weights each
//! displacement by the system's largest frequency ([`step_bound`]), the Taylor series of `exp(M tau)`
//! truncated after [`TERMS`] terms has a remainder below `rho^TERMS / TERMS! e^rho < 2e-18` of `|w|`: the
//! transition matrix and the motion inside the step are exact to rounding. No scaling and squaring is
//! needed: the caller splits a record interval into steps that short (Moler & Van Loan, *Nineteen dubious
//! ways to compute the exponential of a matrix*, 2003, method 1, with the truncation bound of their
//! section 3). On such a step the cubic Hermite of a displacement through its values and rates at the ends
//! misses the motion by at most `rho^4 / 384 < 0.3 %` of its size (the interpolation remainder
//! `h^4 / 384 |u^(4)|`, and `|u^(4)| <= r^4 |u|`): what the recorders' screens (a peak read on the exact
//! motion only where the cubic comes within 1 % of it) rely on.
//!
//! The quantities integrated along the motion (energies) are not part of `w`: their rates are quadratic in
//! it. The caller gives their rates at the step's ends and at the three Gauss–Legendre nodes of the step
//! ([`GAUSS_NODES`]), through which a quartic gives them inside the step. Their growth over a step of
//! `rho <= 1/2` is those three nodes' Gauss–Legendre sum, exact for a rate of degree 5 in time, within
//! `1e-8` of the increment (the remainder `h^7 (3!)^4 / (7 (6!)^3) f^(6)`); over a longer step, five
//! points' ([`QUADRATURE_NODES`]), exact to degree 9, within `4e-13` at `rho <= 1`
//! (`h^11 (5!)^4 / (11 (10!)^3) f^(10)`), and the quartic is bent to meet it at the step's end
//! ([`quadrature`]).

use super::memo::{remembered, Key, Memo};
use std::cell::{Cell, RefCell};
use std::sync::{Arc, OnceLock};

/// Most terms of the Taylor series kept (powers 0 to `TERMS - 1`): enough for `rho = 1`.
pub const TERMS: usize = 20;

/// The terms of the series that a step of `rho = r h` needs: the fewest `K` with `rho^K / K! < 1e-18` (at
/// most [`TERMS`]).
pub fn terms_for(rho: f64) -> usize {
    let mut term = 1.0;
    for k in 1..TERMS {
        term *= rho / k as f64;
        if term < 1e-18 {
            return k + 1;
        }
    }
    TERMS
}
/// Largest `r h` of a step (see the module).
pub const MAX_RHO: f64 = 1.0;
/// Offsets into a step with transition rows of their own ([`Motion::motion_at`]): a recorder sampling a few
/// times per record interval.
pub const OFFSETS: usize = 8;
/// The three Gauss–Legendre nodes on a step, as fractions of it.
pub const GAUSS_NODES: [f64; 3] = [
    0.5 - 0.387_298_334_620_741_7,
    0.5,
    0.5 + 0.387_298_334_620_741_7,
];
/// Their weights (summing to 1).
pub const GAUSS_WEIGHTS: [f64; 3] = [5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0];
/// The five Gauss–Legendre nodes on a step, as fractions of it: the quadrature of the integrated
/// quantities (energies) along a step, exact for a rate of degree 9 in time; its error over a step of
/// `rho = r h <= 1` is below `(5!)^4 / (11 (10!)^3) rho^11 < 4e-13` of the rate's scale times the step
/// (Abramowitz & Stegun 25.4.30).
pub const QUADRATURE_NODES: [f64; 5] = [
    0.5 - 0.453_089_922_969_332,
    0.5 - 0.269_234_655_052_841_55,
    0.5,
    0.5 + 0.269_234_655_052_841_55,
    0.5 + 0.453_089_922_969_332,
];
/// Their weights (summing to 1): `(322 -+ 13 sqrt(70)) / 1800` and `64 / 225`.
pub const QUADRATURE_WEIGHTS: [f64; 5] = [
    0.118_463_442_528_094_54,
    0.239_314_335_249_683_24,
    64.0 / 225.0,
    0.239_314_335_249_683_24,
    0.118_463_442_528_094_54,
];
/// Largest `r h` over which three-point Gauss–Legendre integrates a step's quantities within `1e-8` of
/// their increment (its remainder `h^7 (3!)^4 / (7 (6!)^3) f^(6)`; the steps' reach before [`MAX_RHO`]
/// grew): beyond it, five points ([`QUADRATURE_NODES`]).
pub const THREE_POINT_REACH: f64 = 0.5;

/// The Gauss–Legendre nodes and weights (fractions of the step, summing to 1) that integrate along a
/// step of `rho = r h`: three within [`THREE_POINT_REACH`], else five.
pub fn quadrature(rho: f64) -> (&'static [f64], &'static [f64]) {
    if rho <= THREE_POINT_REACH {
        (&GAUSS_NODES, &GAUSS_WEIGHTS)
    } else {
        (&QUADRATURE_NODES, &QUADRATURE_WEIGHTS)
    }
}

/// `a . b` over the shorter length, in four interleaved partial sums: rows of a transition are short
/// (tens of entries), and one running sum would wait on each addition in turn.
#[inline]
pub fn dot(a: &[f64], b: &[f64]) -> f64 {
    let n = a.len().min(b.len());
    let (a, b) = (&a[..n], &b[..n]);
    let mut s = [0.0; 4];
    let (ca, cb) = (a.chunks_exact(4), b.chunks_exact(4));
    let tail: f64 = ca
        .remainder()
        .iter()
        .zip(cb.remainder())
        .map(|(p, q)| p * q)
        .sum();
    for (p, q) in ca.zip(cb) {
        for k in 0..4 {
            s[k] += p[k] * q[k];
        }
    }
    (s[0] + s[2]) + (s[1] + s[3]) + tail
}

/// `y = A x` for a row-major `A` of `x.len()` columns.
#[inline]
pub fn mat_vec(a: &[f64], x: &[f64], y: &mut [f64]) {
    let n = x.len();
    for (row, yi) in a.chunks_exact(n).zip(y.iter_mut()) {
        *yi = dot(row, x);
    }
}

/// `y = A x` for a row-major `A` of `x.len()` columns, over the columns in `live` only (the others' `x`
/// being 0) when they are fewer than half.
#[inline]
pub fn mat_vec_on(a: &[f64], x: &[f64], live: &[usize], y: &mut [f64]) {
    let n = x.len();
    // A gathered product costs about three times a whole row's per column (the indices, and no paired
    // loads): from half the columns live, the whole rows are cheaper (measured: a pair of 3 and 8 bilinear
    // storeys, w of 40, -9 % instructions per run).
    if 2 * live.len() >= n {
        return mat_vec(a, x, y);
    }
    if live.len() < 8 {
        for (row, yi) in a.chunks_exact(n).zip(y.iter_mut()) {
            *yi = live.iter().map(|&j| row[j] * x[j]).sum();
        }
        return;
    }
    for (row, yi) in a.chunks_exact(n).zip(y.iter_mut()) {
        // Four partial sums, as in `dot`: one running sum waits on each addition before the next.
        let mut s = [0.0; 4];
        let chunks = live.chunks_exact(4);
        let tail: f64 = chunks.remainder().iter().map(|&j| row[j] * x[j]).sum();
        for c in chunks {
            for k in 0..4 {
                s[k] += row[c[k]] * x[c[k]];
            }
        }
        *yi = (s[0] + s[2]) + (s[1] + s[3]) + tail;
    }
}

/// The components of `x` that are not 0, written to `live`.
pub fn live_of(x: &[f64], live: &mut Vec<usize>) {
    live.clear();
    live.extend((0..x.len()).filter(|&j| x[j] != 0.0));
}

/// A bound `r` (1/s) on the rate at which the motion of `w' = M w` changes, for a state laid out as
/// `[u (n), v (n), forcing...]`: `sqrt(max_i sum_j |M[v_i][u_j]|) + max_i sum_j |M[v_i][v_j]|`, the
/// infinity norm of `M` once each displacement is weighted by the first term (the largest frequency by
/// Gershgorin's bound on `M^-1 K`).
pub fn step_bound(m: &[f64], nw: usize, dofs: usize) -> f64 {
    let (mut kk, mut cc) = (0.0f64, 0.0f64);
    for i in 0..dofs {
        let row = &m[(dofs + i) * nw..(dofs + i + 1) * nw];
        kk = kk.max(row[..dofs].iter().map(|x| x.abs()).sum());
        cc = cc.max(row[dofs..2 * dofs].iter().map(|x| x.abs()).sum());
    }
    kk.sqrt() + cc
}

/// The first `mech` rows of `exp(M h)` (row-major `mech x nw`) for `M = [[A, B], [0, F]]` with `F^2 = 0` (the
/// motion `x = w[..mech]` driven by forcing components that are constant or linear in time), for `h` within
/// [`MAX_RHO`] of the step bound: the Taylor series by Horner's rule (the terms of [`terms_for`]),
/// `P <- I + (M h / k) P` from the last term down, on the blocks (the forcing block of `P` is
/// `I + F h / (k + 1)` at every stage, as `F^2 = 0`).
pub fn transition(m: &[f64], nw: usize, mech: usize, h: f64) -> Vec<f64> {
    thread_local! {
        static BUILT: RefCell<Memo<Vec<f64>>> = const { RefCell::new(Memo::new()) };
    }
    let key = Key::default().count(nw).count(mech).num(h).slice(m);
    remembered(
        &BUILT,
        key,
        |p| 8 * p.len(),
        || build_transition(m, nw, mech, h),
    )
}

/// [`transition`], built.
fn build_transition(m: &[f64], nw: usize, mech: usize, h: f64) -> Vec<f64> {
    let q = nw - mech;
    // B F (mech x q).
    let mut bf = vec![0.0; mech * q];
    for i in 0..mech {
        for j in 0..q {
            bf[i * q + j] = (0..q)
                .map(|l| m[i * nw + mech + l] * m[(mech + l) * nw + mech + j])
                .sum();
        }
    }
    let mut p = vec![0.0; mech * nw];
    (0..mech).for_each(|i| p[i * nw + i] = 1.0);
    let mut next = vec![0.0; mech * nw];
    // The terms the step needs ([`terms_for`], as the series): fewer for a Gauss node's short step.
    let terms = terms_for(step_bound(m, nw, mech / 2) * h);
    for k in (1..terms).rev() {
        let f = h / k as f64;
        // The forcing block of the previous stage: I + F h / (k + 1), or I at the first.
        let c = if k + 1 == terms {
            0.0
        } else {
            h / (k + 1) as f64
        };
        for i in 0..mech {
            let a = &m[i * nw..(i + 1) * nw];
            let out = &mut next[i * nw..(i + 1) * nw];
            out.fill(0.0);
            // Row i of A P, row by row of P (most of A is 0: a displacement's row holds one 1).
            for (l, &al) in a[..mech].iter().enumerate() {
                if al != 0.0 {
                    for (o, q) in out.iter_mut().zip(&p[l * nw..(l + 1) * nw]) {
                        *o += al * q;
                    }
                }
            }
            for (j, o) in out.iter_mut().enumerate() {
                *o = if j < mech {
                    f * *o + if i == j { 1.0 } else { 0.0 }
                } else {
                    f * (*o + a[j] + c * bf[i * q + j - mech])
                };
            }
        }
        std::mem::swap(&mut p, &mut next);
    }
    p
}

/// The coefficients `c_k` of `w(t0 + tau) = sum_k c_k tau^k` from `w0`: `c_(k+1) = M c_k / (k + 1)`,
/// written row after row into `out` (`TERMS x nw`); `M`'s rows past `mech` act on the forcing only.
pub fn series(m: &[f64], mech: usize, w0: &[f64], terms: usize, out: &mut [f64]) {
    let nw = w0.len();
    out[..nw].copy_from_slice(w0);
    for k in 1..terms {
        let (done, rest) = out.split_at_mut(k * nw);
        let prev = &done[(k - 1) * nw..];
        let next = &mut rest[..nw];
        let f = 1.0 / k as f64;
        for (i, x) in next.iter_mut().enumerate() {
            let row = &m[i * nw..(i + 1) * nw];
            let from = if i < mech { 0 } else { mech };
            *x = f * row[from..]
                .iter()
                .zip(&prev[from..])
                .map(|(p, q)| p * q)
                .sum::<f64>();
        }
    }
}

/// Component `i` at `tau` of the series `c` (its first `terms` rows of `nw`), by Horner's rule.
#[inline]
pub fn series_at(c: &[f64], nw: usize, i: usize, tau: f64, terms: usize) -> f64 {
    (0..terms)
        .rev()
        .fold(0.0, |acc, k| acc * tau + c[k * nw + i])
}

/// Components `0 .. out.len()` at `tau` of the series `c` (its first `terms` rows of `nw`), by Horner's rule
/// on whole rows: each component's arithmetic is [`series_at`]'s.
#[inline]
pub fn series_into(c: &[f64], nw: usize, tau: f64, terms: usize, out: &mut [f64]) {
    let rows = &c[..terms * nw];
    // Four components at a time, each summed in a register over the rows (a motion has a few).
    let mut at = 0;
    let mut blocks = out.chunks_exact_mut(4);
    for block in &mut blocks {
        let mut acc = [0.0; 4];
        for row in rows.chunks_exact(nw).rev() {
            let x = &row[at..at + 4];
            for q in 0..4 {
                acc[q] = acc[q] * tau + x[q];
            }
        }
        block.copy_from_slice(&acc);
        at += 4;
    }
    for (k, o) in blocks.into_remainder().iter_mut().enumerate() {
        *o = rows
            .chunks_exact(nw)
            .rev()
            .fold(0.0, |acc, row| acc * tau + row[at + k]);
    }
}

/// A square row-major matrix by its nonzero entries, row by row `(row, column, value)`, and where each row
/// ends: a product in `nnz` multiply-adds instead of `n^2` (`M` of a configuration: a displacement's row holds
/// one 1, a storey's a few stiffnesses). Held flat, so that a whole product is one loop (most rows hold one to
/// four entries, where a loop per row costs more than its multiply-adds).
#[derive(Clone, Debug, Default)]
pub struct Sparse {
    entries: Vec<(u32, u32, f64)>,
    row_ends: Vec<usize>,
}

impl Sparse {
    /// The nonzeros of `m` (`n x n`, row-major).
    pub fn of(m: &[f64], n: usize) -> Self {
        let mut s = Self::default();
        s.set(m, n);
        s
    }

    /// Becomes the nonzeros of `m` (`n x n`, row-major), reusing its room.
    pub fn set(&mut self, m: &[f64], n: usize) {
        self.entries.clear();
        self.row_ends.clear();
        for (i, row) in m.chunks_exact(n).enumerate() {
            let nonzeros = row.iter().enumerate().filter(|(_, x)| **x != 0.0);
            self.entries
                .extend(nonzeros.map(|(j, &x)| (i as u32, j as u32, x)));
            self.row_ends.push(self.entries.len());
        }
    }

    /// Rows held (0 before [`Self::set`]).
    pub fn rows(&self) -> usize {
        self.row_ends.len()
    }

    /// The nonzeros of row `i`, `(column, value)` in the order of their columns.
    pub fn row(&self, i: usize) -> impl ExactSizeIterator<Item = (usize, f64)> + '_ {
        let start = if i == 0 { 0 } else { self.row_ends[i - 1] };
        let entries = &self.entries[start..self.row_ends[i]];
        entries.iter().map(|&(_, j, a)| (j as usize, a))
    }

    /// The first `terms` Taylor coefficients of `exp(M t) w0` (`terms x nw` to `out`, as [`series`]):
    /// `c_(k+1) = M c_k / (k + 1)` on the nonzeros.
    pub fn series(&self, w0: &[f64], terms: usize, out: &mut [f64]) {
        let nw = w0.len();
        out[..nw].copy_from_slice(w0);
        for k in 1..terms {
            let (done, rest) = out.split_at_mut(k * nw);
            let (prev, next) = (&done[(k - 1) * nw..], &mut rest[..nw]);
            // Each row's sum in the order of its nonzeros, from -0 as a sum of f64 starts.
            next.fill(-0.0);
            for &(i, j, a) in &self.entries {
                next[i as usize] += a * prev[j as usize];
            }
            let f = 1.0 / k as f64;
            next.iter_mut().for_each(|x| *x *= f);
        }
    }
}

/// The rates of the integrated quantities (energies, the laws' own states) at a whole state `w` of one
/// configuration: what a step whose Gauss nodes the stepper did not read asks when its integrated
/// quantities are read inside it ([`Motion::set_nodes_unread`]).
pub trait IntegratedRates: std::fmt::Debug + Send + Sync {
    /// Writes the rate of each integrated quantity at `w` (all `nw` components) to `out` (one per
    /// quantity, in the layout's order past the motion).
    fn integrated_rates(&self, w: &[f64], out: &mut [f64]);
}

/// Most numbers in a configuration's jerk rows ([`JerkRows`]): 512 KiB.
const MAX_JERK_ROWS: usize = 1 << 16;
/// Fewest pieces of a configuration's whole intervals for its jerk rows to be built ([`JerkRows`]).
/// Measured (instructions per run): from 32 pieces (buildings on soil, the floor-to-column example) they
/// save 2 to 6 %; with 4 to 8 (the 3-vs-8-storey pair) they cost 0.2 % more than they save.
const JERK_PIECES: usize = 16;

/// The rows `a_i^T exp(M k p)`, `k = 1 .. pieces - 1`, of a degree of freedom `i`'s jerk `a_i^T w` (`a_i`
/// the velocity's row of `M^2`, m/s^3 or rad/s^3, relative to the ground as the rates are) at the starts of
/// the pieces `p` of a configuration's whole intervals, one after the other (`nw` each): the jerk there is
/// one dot product with `w` at a step's start, where the chain of pieces would be walked. Built degree of
/// freedom by degree of freedom, by the motion when first asked for it ([`Motion::jerk_rows`]: the peaks
/// recorder asks for the floors' only), and shared by the configuration's steps; empty when all of them
/// would hold more than [`MAX_JERK_ROWS`] numbers.
#[derive(Debug, Default)]
pub struct JerkRows {
    rows: OnceLock<Vec<OnceLock<Vec<f64>>>>,
}

/// Where the motion at a step's Gauss nodes is found when their integrated quantities are read.
#[derive(Clone, Debug)]
pub enum NodeSource {
    /// The transition rows to the step's end and its three nodes (`[end, node 0, node 1, node 2]`, the
    /// first `mech` rows of each, [`transition`]), applied to `w` at the step's start.
    Rows(Arc<[Vec<f64>; 4]>),
    /// The step's series, which the motion holds ([`Motion::adopt_series`]).
    Series,
    /// The motion there as the stepper found it ([`Motion::hold_nodes`]): a whole interval's block.
    Held,
}

/// A step's Gauss nodes as the stepper left them unread (their integrated quantities' rates): where the
/// motion there is found, and the rates of the integrated quantities.
#[derive(Clone, Debug)]
pub struct UnreadNodes {
    /// Where the motion at the nodes is found.
    pub source: NodeSource,
    /// The configuration's rates.
    pub rates: Arc<dyn IntegratedRates>,
}

/// The exact motion on one step: the series of the linear state `w` (built on first use), and the
/// quantities integrated along it from their rates at five points of the step.
#[derive(Clone, Debug, Default)]
pub struct Motion {
    /// Components of the layout state that are the first components of `w` (displacements, velocities).
    pub mech: usize,
    /// The system matrix, row-major `nw x nw`.
    pub m: Vec<f64>,
    /// `w` at the step's start.
    pub w0: Vec<f64>,
    /// The integrated quantities at the step's start (layout components `mech..`).
    pub acc0: Vec<f64>,
    /// The rates of every layout component at the step's start, three Gauss nodes and end: `rates[j][i]`
    /// (at the nodes, not set when the stepper left them unread: [`Self::set_nodes_unread`]).
    pub rates: [Vec<f64>; 5],
    /// A step whose Gauss nodes the stepper did not read (its integrated quantities' growth found
    /// otherwise): how to read them when a reader asks for an integrated quantity inside the step.
    unread: Option<UnreadNodes>,
    /// The integrated quantities' rates at the three nodes, found from [`Self::unread`].
    node_rates: RefCell<[Vec<f64>; 3]>,
    /// The motion (`mech`) at the three nodes, when the stepper holds it here ([`NodeSource::Held`]).
    node_w: [Vec<f64>; 3],
    /// Terms of the series the step needs ([`terms_for`]).
    pub terms: usize,
    /// The second rates of the velocities (the jerks, m/s^3) at the step's start and end.
    pub jerk: [Vec<f64>; 2],
    /// The motion (`w[..mech]`) at the step's end.
    pub w1: Vec<f64>,
    /// Transition rows `Φ(τ)` (`mech x nw`, row-major) at offsets `τ` into the step where the whole state
    /// is often asked (a recorder's sampling grid), for the motion's configuration: the first
    /// [`Self::offset_count`] of [`OFFSETS`] slots, set by the stepper.
    offsets: Vec<(f64, Vec<f64>)>,
    offset_count: usize,
    /// Offsets into this step at which the whole state was asked between the ends without a slot, with
    /// how many times: what the stepper may build slots for.
    asked: RefCell<Vec<(f64, usize)>>,
    series: RefCell<Vec<f64>>,
    /// The piece whose series [`Self::series`] holds (`usize::MAX`: none).
    series_of: Cell<usize>,
    /// Per integrated quantity, the coefficients of its quartic rate's integral over `theta` (monomial
    /// `m` divided by `m + 1`), then that integral at `theta = 1` (built once per step, [`rate_quartic`]).
    acc_poly: RefCell<Vec<[f64; 6]>>,
    acc_built: Cell<bool>,
    /// Pieces of the step: 1, or more for a whole record interval taken at once ([`Self::chain`]).
    pieces: usize,
    /// Length of a piece, s.
    piece: f64,
    /// The motion at the start of pieces 1, 2, ... (`mech` each), found on demand from the one before.
    chain: RefCell<Vec<f64>>,
    /// Pieces whose start is known (piece 0's is `w0`).
    chained: Cell<usize>,
    /// `w` at the start of the piece being read.
    piece_w: RefCell<Vec<f64>>,
    /// The rates of `w` past the motion (the forcing's slopes; 0 for constant forces), once known this step.
    forcing_rate: RefCell<Vec<f64>>,
    forcing_known: Cell<bool>,
    /// The integrated quantities at the step's end (by five-point Gauss or the forms' integrals along the
    /// exact motion), when the quartics through the rates are bent to meet them ([`Self::bent`]).
    acc1: Vec<f64>,
    bent: bool,
    /// The nonzero entries of `m` (set by [`Self::set_matrix`]; empty, `m` is read).
    sparse: Sparse,
    /// The components of `w0` that are not 0 ([`Self::set_start`]).
    live: Vec<usize>,
    /// Probes of a chained step: for each key (an element), the rows of its two functionals (deformation
    /// and rate) at the start of pieces 1, 2, ... ([`super::functional_at_pieces`]): the first's rows,
    /// then the second's, `nw` each.
    probe_keys: Vec<usize>,
    probe_rows: Vec<f64>,
    /// The jerk rows of the motion's configuration ([`Self::jerk_probe`]).
    jerks: Option<Arc<JerkRows>>,
    /// Transition rows over `1, 2, 4, ...` pieces (`mech x nw` each): the chain's links (one piece), and a
    /// piece's start far along the chain in a few products ([`Self::ensure_chain`]).
    jump_rows: Vec<f64>,
    /// Room for one jump's product (`mech`).
    jumped: RefCell<Vec<f64>>,
    /// Room for `w` at an offset (`nw`): see [`Self::accelerations_at`].
    w_at_offset: RefCell<Vec<f64>>,
}

impl Motion {
    /// A motion of `w` of `nw` components whose first `mech` are layout components, with `acc` integrated
    /// quantities.
    pub fn new(mech: usize, nw: usize, acc: usize) -> Self {
        Self {
            mech,
            m: vec![0.0; nw * nw],
            w0: vec![0.0; nw],
            acc0: vec![0.0; acc],
            rates: std::array::from_fn(|_| vec![0.0; mech + acc]),
            unread: None,
            node_rates: RefCell::new(std::array::from_fn(|_| vec![0.0; acc])),
            node_w: std::array::from_fn(|_| vec![0.0; mech]),
            terms: TERMS,
            jerk: std::array::from_fn(|_| vec![0.0; mech / 2]),
            w1: vec![0.0; mech],
            offsets: (0..OFFSETS).map(|_| (0.0, vec![0.0; mech * nw])).collect(),
            offset_count: 0,
            asked: RefCell::new(Vec::with_capacity(OFFSETS)),
            series: RefCell::new(vec![0.0; TERMS * nw]),
            series_of: Cell::new(usize::MAX),
            acc_poly: RefCell::new(vec![[0.0; 6]; acc]),
            acc_built: Cell::new(false),
            pieces: 1,
            piece: 0.0,
            chain: RefCell::new(Vec::new()),
            chained: Cell::new(1),
            piece_w: RefCell::new(vec![0.0; nw]),
            forcing_rate: RefCell::new(vec![0.0; nw - mech]),
            forcing_known: Cell::new(false),
            acc1: vec![0.0; acc],
            bent: false,
            sparse: Sparse::default(),
            live: (0..nw).collect(),
            probe_keys: Vec::new(),
            probe_rows: Vec::new(),
            jerks: None,
            jump_rows: Vec::new(),
            jumped: RefCell::new(vec![0.0; mech]),
            w_at_offset: RefCell::new(vec![0.0; nw]),
        }
    }

    /// Sets `w` at the step's start.
    pub fn set_start(&mut self, w0: &[f64]) {
        self.w0.copy_from_slice(w0);
        live_of(&self.w0, &mut self.live);
    }

    /// Sets the system matrix (row-major `nw x nw`), keeping its nonzero entries for the series.
    pub fn set_matrix(&mut self, m: &[f64]) {
        self.m.copy_from_slice(m);
        self.sparse.set(m, self.w0.len());
    }

    /// Takes `s` (the series of `w0` on the step's one piece, as [`Sparse::series`] builds it, its first
    /// [`Self::terms`] rows) as its own: a step that built it to propagate spares the readers a second.
    pub fn adopt_series(&mut self, s: &[f64]) {
        let n = self.terms * self.w0.len();
        let mine = self.series.get_mut();
        mine[..n].copy_from_slice(&s[..n]);
        mine[n..].iter_mut().for_each(|x| *x = 0.0);
        self.series_of.set(0);
    }

    /// Whether a reader asked for the integrated quantities inside the step (since [`Self::invalidate`]).
    pub fn integrals_read(&self) -> bool {
        self.acc_built.get()
    }

    /// Forgets the series (after `w0` or `m` changed).
    pub fn invalidate(&self) {
        self.series_of.set(usize::MAX);
        self.chained.set(1);
        self.acc_built.set(false);
        self.forcing_known.set(false);
    }

    /// Makes the step one piece (an exact step within the series' reach), with the integrated quantities
    /// at its end `acc1` where the quartics through the rates are to be bent to meet them (a step beyond
    /// [`THREE_POINT_REACH`]).
    pub fn single(&mut self, acc1: Option<&[f64]>) {
        self.pieces = 1;
        self.bent = acc1.is_some();
        if let Some(a) = acc1 {
            self.acc1.copy_from_slice(a);
        }
    }

    /// The stepper did not read the step's Gauss nodes (`Some`: [`Self::rates`] at them is not set) or did.
    /// Unread, they are found when an integrated quantity is read inside the step, from `w` at the step's
    /// start by the rows to them.
    pub fn set_nodes_unread(&mut self, unread: Option<UnreadNodes>) {
        self.unread = unread;
    }

    /// Holds the motion at the step's three Gauss nodes (`mech` components of each), for a reader of the
    /// integrated quantities inside a step whose nodes are [`NodeSource::Held`].
    pub fn hold_nodes(&mut self, nodes: [&[f64]; 3]) {
        for (held, node) in self.node_w.iter_mut().zip(nodes) {
            held.copy_from_slice(&node[..self.mech]);
        }
    }

    /// The jerks at the step's ends ([`Self::jerk`]) from the rates there: the velocities' rows of `M` on
    /// them, the forcing's rates being its slopes (`fd` forcing components, a channel's acceleration and
    /// slope each).
    pub fn set_jerks(&mut self, fd: usize) {
        let (nw, mech) = (self.w0.len(), self.mech);
        let n = mech / 2;
        let slopes = &self.w0[mech..mech + fd];
        let (start, end) = (&self.rates[0][..mech], &self.rates[4][..mech]);
        let [j0, j1] = &mut self.jerk;
        for (i, (j0, j1)) in j0[..n].iter_mut().zip(&mut j1[..n]).enumerate() {
            let (motion, forcing) = self.m[(n + i) * nw..(n + i + 1) * nw].split_at(mech);
            // The forcing's rates are its channels' slopes (the second of each pair), the same at both
            // ends: its part is summed once.
            let mut f = 0.0;
            for (a, s) in forcing[..fd].chunks_exact(2).zip(slopes.chunks_exact(2)) {
                f += a[0] * s[1];
            }
            let (mut a, mut b) = (0.0, 0.0);
            for ((m, x), y) in motion.iter().zip(start).zip(end) {
                a += m * x;
                b += m * y;
            }
            *j0 = a + f;
            *j1 = b + f;
        }
    }

    /// Makes the step `pieces` pieces of `piece` s each, the motion carried across each by `rows` (the
    /// first `mech` rows of its transition; copied only when `fresh`, the matrix having changed), and the
    /// integrated quantities at its end `acc1` (the quartics through the rates are bent to meet them).
    /// `jumps` are the rows over `1, 2, 4, ...` pieces one after the other (`rows` first), and `probes` keys
    /// (elements) and the rows of their two functionals at the pieces' starts ([`Self::probe`]), for as many
    /// pieces as any step of this matrix and piece length has, both copied when `fresh` too; and the
    /// configuration's jerk rows, shared ([`Self::jerk_probe`]).
    pub fn chained(
        &mut self,
        (pieces, piece): (usize, f64),
        jumps: &[f64],
        probes: (&[usize], &[f64], Option<&Arc<JerkRows>>),
        fresh: bool,
        acc1: &[f64],
    ) {
        let fresh = fresh || self.piece != piece;
        self.pieces = pieces;
        self.piece = piece;
        if fresh || self.jump_rows.len() != jumps.len() {
            self.jump_rows.clear();
            self.jump_rows.extend_from_slice(jumps);
            self.probe_keys.clear();
            self.probe_keys.extend_from_slice(probes.0);
            self.probe_rows.clear();
            self.probe_rows.extend_from_slice(probes.1);
            self.jerks = probes.2.cloned();
        }
        let need = pieces.saturating_sub(1) * self.mech;
        let mut chain = self.chain.borrow_mut();
        if chain.len() < need {
            chain.resize(need, 0.0);
        }
        drop(chain);
        self.acc1.copy_from_slice(acc1);
        self.bent = true;
    }

    /// Pieces of the step (1 but for a whole interval taken at once).
    pub fn pieces(&self) -> usize {
        self.pieces
    }

    /// The piece holding `tau` and the offset into it, s.
    #[inline]
    fn locate(&self, tau: f64) -> (usize, f64) {
        if self.pieces == 1 {
            return (0, tau);
        }
        let k = ((tau / self.piece).max(0.0) as usize).min(self.pieces - 1);
        (k, tau - k as f64 * self.piece)
    }

    /// `w` at `tau` into the step for its components past the motion (the forcing is linear in time, the
    /// constant forces constant: `w_i + tau (M w)_i`, the rate `(M w)_i` kept in `rate`), written into
    /// `out[mech..]`.
    fn forcing_at(&self, tau: f64, rate: &[f64], out: &mut [f64]) {
        let mech = self.mech;
        for ((o, w), r) in out[mech..].iter_mut().zip(&self.w0[mech..]).zip(rate) {
            *o = w + tau * r;
        }
    }

    /// Forgets the offset slots (after `m` changed).
    pub fn clear_offsets(&mut self) {
        self.offset_count = 0;
    }

    /// Adds a slot: `phi` = the first `mech` rows of `Φ(tau)` of the motion's matrix (see
    /// [`transition`]). Ignored when all [`OFFSETS`] are taken.
    pub fn add_offset(&mut self, tau: f64, phi: &[f64]) {
        if let Some(slot) = self.offsets.get_mut(self.offset_count) {
            slot.0 = tau;
            slot.1.copy_from_slice(phi);
            self.offset_count += 1;
        }
    }

    /// Moves the offsets asked this step without a slot (see [`Self::motion_at`]), each with its count,
    /// into `into` (cleared first; at most [`OFFSETS`]).
    pub fn take_asked(&self, into: &mut Vec<(f64, usize)>) {
        into.clear();
        into.extend(self.asked.borrow_mut().drain(..));
    }

    /// Writes the motion `w[..out.len()]` (at most `mech` components) at `tau` into a step of length `h`:
    /// the ends as the step left them, an offset with a slot by one row product each (exact to rounding
    /// when `tau` is within `slack` of it, s), else from the series. With `log`, an interior offset
    /// without a slot is counted for the stepper ([`Self::take_asked`]).
    pub fn motion_at(&self, tau: f64, h: f64, slack: f64, out: &mut [f64], log: bool) {
        let nw = self.w0.len();
        if tau <= 0.0 {
            out.copy_from_slice(&self.w0[..out.len()]);
        } else if (tau - h).abs() <= slack {
            out.copy_from_slice(&self.w1[..out.len()]);
        } else if let Some((_, phi)) = self.offsets[..self.offset_count]
            .iter()
            .find(|(t, _)| (t - tau).abs() <= slack)
        {
            mat_vec_on(&phi[..out.len() * nw], &self.w0, &self.live, out);
        } else {
            if log {
                let mut asked = self.asked.borrow_mut();
                if let Some(e) = asked.iter_mut().find(|(t, _)| (t - tau).abs() <= slack) {
                    e.1 += 1;
                } else if asked.len() < OFFSETS {
                    asked.push((tau, 1));
                }
            }
            self.with_piece(tau, |c, d| series_into(c, nw, d, self.terms, out));
        }
    }

    /// The forcing's rates ([`Self::forcing_rate`]), constant over the step: found at the first ask.
    fn forcing_rates(&self) -> std::cell::Ref<'_, Vec<f64>> {
        if !self.forcing_known.get() {
            let (nw, mech) = (self.w0.len(), self.mech);
            let mut rate = self.forcing_rate.borrow_mut();
            rate.resize(nw - mech, 0.0);
            for (i, r) in rate.iter_mut().enumerate() {
                let row = &self.m[(mech + i) * nw + mech..(mech + i + 1) * nw];
                *r = row.iter().zip(&self.w0[mech..]).map(|(a, b)| a * b).sum();
            }
            self.forcing_known.set(true);
        }
        self.forcing_rate.borrow()
    }

    /// The accelerations (the velocities' rates, m/s^2 or rad/s^2, relative to the ground as the right-hand
    /// side gives them) at `tau` into the step, `out.len()` of them from the first, given the motion there
    /// (`motion`: `w[..mech]`, as [`Self::motion_at`] wrote it): the velocities' rows of `M` on `w`, whose
    /// components past the motion (the forcing) are linear in time, `w_i(tau) = w_i + tau (M w)_i`. The
    /// laws are not evaluated: in one configuration the rates are `M w`.
    pub fn accelerations_at(&self, tau: f64, motion: &[f64], out: &mut [f64]) {
        let (nw, n) = (self.w0.len(), self.mech / 2);
        let mut w = self.w_at_offset.borrow_mut();
        w[..2 * n].copy_from_slice(&motion[..2 * n]);
        self.forcing_at(tau, &self.forcing_rates(), &mut w);
        let w: &[f64] = &w;
        if self.sparse.rows() == nw {
            for (i, o) in out.iter_mut().enumerate() {
                *o = self.sparse.row(n + i).map(|(j, a)| a * w[j]).sum();
            }
        } else {
            mat_vec(&self.m[n * nw..(n + out.len()) * nw], w, out);
        }
    }

    /// `w[..out.len()]` at the start of piece `k`, along the chain (cheaper than a series: what a search
    /// inside a whole interval narrows itself with first).
    pub fn piece_start(&self, k: usize, out: &mut [f64]) {
        let mech = self.mech;
        if k > 0 && k < self.chained.get() && out.len() <= mech {
            // Known: the motion is read off the chain as it stands.
            out.copy_from_slice(&self.chain.borrow()[(k - 1) * mech..(k - 1) * mech + out.len()]);
            return;
        }
        self.ensure_chain(k);
        out.copy_from_slice(&self.piece_w.borrow()[..out.len()]);
    }

    /// The two functionals of probe `key` (an element's deformation and its rate) at the start of piece `k`
    /// of a chained step, one row product each; `None` without such a probe or piece.
    pub fn probe(&self, key: usize, k: usize) -> Option<(f64, f64)> {
        if k == 0 || k >= self.pieces {
            return None;
        }
        let nw = self.w0.len();
        let i = self.probe_keys.iter().position(|&p| p == key)?;
        // Each key's rows: the deformation's at every piece's start, then its rate's.
        let half = self.probe_rows.len() / self.probe_keys.len() / 2;
        let rows = &self.probe_rows[2 * i * half..2 * (i + 1) * half];
        let (x, v) = rows.split_at(half);
        let at = (k - 1) * nw..k * nw;
        Some((dot(x.get(at.clone())?, &self.w0), dot(&v[at], &self.w0)))
    }

    /// Whether [`Self::jerk_probe`] can read degree of freedom `i`'s jerk rows on this chained step: built
    /// at the first asking, once, for a configuration whose whole intervals have [`JERK_PIECES`] pieces or
    /// more (with fewer, a search walks a short chain and may not repay them).
    pub fn jerk_rows(&self, i: usize) -> bool {
        let Some(jerks) = self.jerks.as_ref().filter(|_| self.pieces > 1) else {
            return false;
        };
        let (nw, mech) = (self.w0.len(), self.mech);
        let n = mech / 2;
        let levels = self.jump_rows.len() / (mech * nw);
        let whole = 1usize << levels.saturating_sub(1);
        if whole < JERK_PIECES {
            return false;
        }
        let each = jerks
            .rows
            .get_or_init(|| (0..n).map(|_| OnceLock::new()).collect());
        let Some(cell) = each.get(i) else {
            return false;
        };
        let rows = cell.get_or_init(|| {
            let mut out = Vec::new();
            if n * whole * nw > MAX_JERK_ROWS {
                return out;
            }
            let m = &self.m;
            let one = &self.jump_rows[..mech * nw];
            let a: Vec<f64> = (0..nw)
                .map(|j| (0..nw).map(|k| m[(n + i) * nw + k] * m[k * nw + j]).sum())
                .collect();
            let at = (self.piece, whole);
            super::functional_at_pieces(&a, (m, one), (nw, mech), at, &mut out);
            out
        });
        !rows.is_empty()
    }

    /// Degree of freedom `i`'s jerk (its velocity's second rate, `(M^2 w)_(n + i)`) at the start of piece
    /// `k` of a chained step, one row product; `None` without the rows or the piece (read it by
    /// [`Self::second_rate_at`] then).
    pub fn jerk_probe(&self, i: usize, k: usize) -> Option<f64> {
        let nw = self.w0.len();
        if k == 0 || k >= self.pieces {
            return None;
        }
        let rows = self.jerks.as_ref()?.rows.get()?.get(i)?.get()?;
        let per = rows.len() / nw;
        let at = (k - 1) * nw;
        (k <= per).then(|| dot(&rows[at..at + nw], &self.w0))
    }

    /// The second rate of component `j` of `w` at the start of piece `k`.
    pub fn second_rate_at(&self, k: usize, j: usize) -> f64 {
        self.ensure_chain(k);
        self.second_rate(&self.piece_w.borrow(), j)
    }

    /// The second rate of component `j` of `w` at `w` (`(M M w)_j`, on the nonzeros of `M`).
    fn second_rate(&self, w: &[f64], j: usize) -> f64 {
        let row = |i: usize| self.sparse.row(i);
        if self.sparse.rows() != w.len() {
            let nw = w.len();
            let rate = |c: usize| (0..nw).map(|d| self.m[c * nw + d] * w[d]).sum::<f64>();
            return (0..nw).map(|c| self.m[j * nw + c] * rate(c)).sum();
        }
        row(j)
            .map(|(c, a)| a * row(c).map(|(d, b)| b * w[d]).sum::<f64>())
            .sum()
    }

    /// Sets [`Self::piece_w`] to `w` at the start of piece `k`, walking the chain as far as needed.
    fn ensure_chain(&self, k: usize) {
        let (nw, mech) = (self.w0.len(), self.mech);
        let mut w = self.piece_w.borrow_mut();
        w.copy_from_slice(&self.w0);
        if k > 0 {
            let rate = self.forcing_rates();
            let mut known = self.chained.get();
            let levels = self.jump_rows.len() / (mech * nw);
            if k + 1 - known.min(k + 1) > k.count_ones() as usize && k >> levels == 0 {
                // Far along: from the start by the blocks of the binary digits of k (the chain as it was).
                let mut at = 0;
                let mut next = self.jumped.borrow_mut();
                for b in (0..levels).filter(|b| k >> b & 1 == 1) {
                    self.forcing_at(at as f64 * self.piece, &rate, &mut w);
                    let rows = &self.jump_rows[b * mech * nw..(b + 1) * mech * nw];
                    mat_vec(rows, &w, &mut next);
                    w[..mech].copy_from_slice(&next);
                    at += 1 << b;
                }
                self.forcing_at(k as f64 * self.piece, &rate, &mut w);
                return;
            }
            let mut chain = self.chain.borrow_mut();
            while known <= k {
                // The start of piece `known` from that of the one before.
                let j = known - 1;
                if j > 0 {
                    w[..mech].copy_from_slice(&chain[(j - 1) * mech..j * mech]);
                }
                self.forcing_at(j as f64 * self.piece, &rate, &mut w);
                mat_vec(
                    &self.jump_rows[..mech * nw],
                    &w,
                    &mut chain[(known - 1) * mech..known * mech],
                );
                known += 1;
            }
            self.chained.set(known);
            w[..mech].copy_from_slice(&chain[(k - 1) * mech..k * mech]);
            self.forcing_at(k as f64 * self.piece, &rate, &mut w);
        }
    }

    /// Builds the series of piece `k` (from its start, found along the chain).
    fn ensure(&self, k: usize) {
        if self.series_of.get() == k {
            return;
        }
        let (nw, mech) = (self.w0.len(), self.mech);
        self.ensure_chain(k);
        let w = self.piece_w.borrow();
        let mut s = self.series.borrow_mut();
        if self.sparse.rows() == nw {
            self.sparse.series(&w, self.terms, &mut s);
        } else {
            series(&self.m, mech, &w, self.terms, &mut s);
        }
        // Rows past the step's terms stay 0 for readers of all of them.
        s[self.terms * nw..].iter_mut().for_each(|x| *x = 0.0);
        self.series_of.set(k);
    }

    /// The series coefficients of `w` (`TERMS x nw`) on the step's first piece (the whole step but for a
    /// whole interval taken at once, which is never taken while a contact is closed, where this is read).
    pub fn with_series<R>(&self, f: impl FnOnce(&[f64]) -> R) -> R {
        self.ensure(0);
        f(&self.series.borrow())
    }

    /// A linear functional `f` of the motion (read on a vector's first `mech` components: a displacement, a
    /// drift) as a polynomial in the offset into the piece holding `tau`: its coefficients, `f` of each of the
    /// piece's series coefficients, to `out` (room for [`TERMS`]). Returns the piece's start (s into the step)
    /// and the terms written. A search inside one piece then reads a scalar polynomial, not the whole motion.
    pub fn functional_series(
        &self,
        tau: f64,
        f: impl Fn(&[f64]) -> f64,
        out: &mut [f64],
    ) -> (f64, usize) {
        let (nw, mech, terms) = (self.w0.len(), self.mech, self.terms);
        let (k, _) = self.locate(tau);
        self.ensure(k);
        let c = self.series.borrow();
        for (j, o) in out[..terms].iter_mut().enumerate() {
            *o = f(&c[j * nw..j * nw + mech]);
        }
        (k as f64 * self.piece, terms)
    }

    /// The series coefficients of the piece holding `tau`, and the offset into it.
    fn with_piece<R>(&self, tau: f64, f: impl FnOnce(&[f64], f64) -> R) -> R {
        let (k, d) = self.locate(tau);
        self.ensure(k);
        f(&self.series.borrow(), d)
    }

    /// The motion `w[..out.len()]` at `tau` on the series of its piece (no slot, no end taken as left).
    pub fn on_series(&self, tau: f64, out: &mut [f64]) {
        let nw = self.w0.len();
        self.with_piece(tau, |c, d| series_into(c, nw, d, self.terms, out));
    }

    /// Length of a piece of the step, s (meaningful when [`Self::pieces`] is above 1).
    pub fn piece(&self) -> f64 {
        self.piece
    }

    /// Component `j` of `w` and its first and second rates at `tau`.
    pub fn w_at(&self, tau: f64, j: usize) -> [f64; 3] {
        let nw = self.w0.len();
        self.with_piece(tau, |c, tau| {
            let (mut p, mut d, mut dd) = (0.0, 0.0, 0.0);
            for k in (0..self.terms).rev() {
                dd = dd * tau + 2.0 * d;
                d = d * tau + p;
                p = p * tau + c[k * nw + j];
            }
            [p, d, dd]
        })
    }

    /// Layout component `i` at `tau` into a step of length `h`.
    pub fn component(&self, tau: f64, h: f64, i: usize) -> f64 {
        if i < self.mech {
            let nw = self.w0.len();
            self.with_piece(tau, |c, d| series_at(c, nw, i, d, self.terms))
        } else {
            self.integrated(tau, h, i - self.mech)
        }
    }

    /// Integrated quantity `k` at `tau`: its start value plus the integral of the quartic through its rates
    /// at the step's start, three Gauss nodes and end (built once per step, [`rate_quartic`]).
    fn integrated(&self, tau: f64, h: f64, k: usize) -> f64 {
        if h <= 0.0 || tau <= 0.0 {
            return self.acc0[k];
        }
        self.build_integrals(h);
        self.integrated_on(&self.acc_poly.borrow()[k], tau, h, k)
    }

    /// The integrated quantities `0 .. out.len()` at `tau` into `out` ([`Self::integrated`] each, the
    /// polynomials borrowed once: a history sample reads them all).
    pub fn integrated_into(&self, tau: f64, h: f64, out: &mut [f64]) {
        if h <= 0.0 || tau <= 0.0 {
            out.copy_from_slice(&self.acc0[..out.len()]);
            return;
        }
        self.build_integrals(h);
        let poly = self.acc_poly.borrow();
        for (k, (o, q)) in out.iter_mut().zip(poly.iter()).enumerate() {
            *o = self.integrated_on(q, tau, h, k);
        }
    }

    /// [`Self::acc_poly`] for this step of length `h` (s), if not built yet.
    fn build_integrals(&self, h: f64) {
        if self.acc_built.get() {
            return;
        }
        if let Some(unread) = &self.unread {
            self.read_nodes(unread, h);
        }
        let nodes = self.node_rates.borrow();
        let rate = |q: usize, j: usize| match (&self.unread, q) {
            (Some(_), 1..=3) => nodes[q - 1][j],
            _ => self.rates[q][self.mech + j],
        };
        let mut poly = self.acc_poly.borrow_mut();
        for (j, p) in poly.iter_mut().enumerate() {
            let r: [f64; 5] = std::array::from_fn(|q| rate(q, j));
            let c = rate_quartic(&r);
            for m in 0..5 {
                p[m] = c[m] / (m + 1) as f64;
            }
            p[5] = super::horner(&p[..5], 1.0);
        }
        self.acc_built.set(true);
    }

    /// The integrated quantities' rates at the Gauss nodes of a step of length `h` the stepper left unread
    /// ([`Self::node_rates`]): `w` there from its [`NodeSource`], the forcing linear in time; its rates by
    /// the configuration's.
    fn read_nodes(&self, unread: &UnreadNodes, h: f64) {
        let (nw, mech) = (self.w0.len(), self.mech);
        if matches!(unread.source, NodeSource::Series) {
            self.ensure(0);
        }
        let rate = self.forcing_rates();
        let series = self.series.borrow();
        let mut w = self.w_at_offset.borrow_mut();
        let mut nodes = self.node_rates.borrow_mut();
        for (j, (node, out)) in GAUSS_NODES.iter().zip(nodes.iter_mut()).enumerate() {
            match &unread.source {
                NodeSource::Rows(rows) => {
                    mat_vec_on(&rows[j + 1], &self.w0, &self.live, &mut w[..mech])
                }
                NodeSource::Series => {
                    series_into(&series, nw, node * h, self.terms, &mut w[..mech])
                }
                NodeSource::Held => w[..mech].copy_from_slice(&self.node_w[j]),
            }
            self.forcing_at(node * h, &rate, &mut w);
            unread.rates.integrated_rates(&w, out);
        }
    }

    /// Integrated quantity `k` at `tau` from its integral's coefficients `q` ([`Self::acc_poly`]).
    fn integrated_on(&self, q: &[f64; 6], tau: f64, h: f64, k: usize) -> f64 {
        let theta = tau / h;
        let integral = super::horner(&q[..5], theta);
        let value = self.acc0[k] + tau * integral;
        if self.bent {
            // The quartic misses the fast modes of a whole interval, or of a step of rho near 1, by a
            // little: its error at the end, known, is spread along the step so that the value meets the
            // exact one there.
            value + theta * (self.acc1[k] - self.acc0[k] - h * q[5])
        } else {
            value
        }
    }
}

/// The monomial coefficients (in the fraction `theta` of the step) of the quartic through `rates` at
/// `theta = 0`, the three Gauss nodes and 1: the inverse of their Vandermonde matrix, found once by
/// solving for its columns ([`super::lu`]), applied to `rates`.
fn rate_quartic(rates: &[f64; 5]) -> [f64; 5] {
    static INVERSE: std::sync::OnceLock<[[f64; 5]; 5]> = std::sync::OnceLock::new();
    let inv = INVERSE.get_or_init(|| {
        let nodes = [0.0, GAUSS_NODES[0], GAUSS_NODES[1], GAUSS_NODES[2], 1.0];
        // V[i][m] = nodes[i]^m, row-major, by repeated multiplication: `powi` of these constants is folded
        // by the compiler to the correctly rounded power in some builds and squared and multiplied at run
        // time in others (the fourth powers differ in their last bit), which moved the last digits of every
        // energy read inside a step from one build of the same code to the next.
        let mut v = [0.0; 25];
        for (row, &x) in v.chunks_exact_mut(5).zip(&nodes) {
            let mut p = 1.0;
            for vm in row {
                *vm = p;
                p *= x;
            }
        }
        let mut piv = [0; 5];
        assert!(super::lu::factor(&mut v, &mut piv, 5), "distinct nodes");
        // Column j of the inverse solves V x = e_j; kept row-major.
        let mut inv = [[0.0; 5]; 5];
        for j in 0..5 {
            let mut e = [0.0; 5];
            e[j] = 1.0;
            super::lu::solve(&v, &piv, &mut e);
            (0..5).for_each(|i| inv[i][j] = e[i]);
        }
        inv
    });
    std::array::from_fn(|i| (0..5).map(|j| inv[i][j] * rates[j]).sum())
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;

    /// `u'' + 2 zeta w u' + w^2 u = -g`, `g' = s`: `M` for `w = [u, v, g, s]`.
    pub(in crate::integrate) fn oscillator(w: f64, zeta: f64) -> Vec<f64> {
        #[rustfmt::skip]
        let m = vec![
            0.0, 1.0, 0.0, 0.0,
            -w * w, -2.0 * zeta * w, -1.0, 0.0,
            0.0, 0.0, 0.0, 1.0,
            0.0, 0.0, 0.0, 0.0,
        ];
        m
    }

    /// `u'' + 2 zeta w u' + w^2 u = -g(t)`, `g = g0 + s t`: the transition over `h` against the closed form of
    /// the free and forced motion.
    #[test]
    fn transition_and_series_equal_the_closed_form() {
        let (w, zeta) = (12.0f64, 0.05f64);
        // w = [u, v, g, s]
        let m = vec![
            0.0,
            1.0,
            0.0,
            0.0, //
            -w * w,
            -2.0 * zeta * w,
            -1.0,
            0.0, //
            0.0,
            0.0,
            0.0,
            1.0, //
            0.0,
            0.0,
            0.0,
            0.0,
        ];
        let r = step_bound(&m, 4, 1);
        let h = MAX_RHO / r;
        let w0 = [0.01, -0.2, 1.5, -30.0];
        let phi = transition(&m, 4, 2, h);
        let mut w1 = [0.0; 2];
        mat_vec(&phi, &w0, &mut w1);
        // Closed form: particular solution for a linear load, u_p = -(g0 + s t)/w^2 + 2 zeta s / w^3.
        let wd = w * (1.0 - zeta * zeta).sqrt();
        let (g0, s) = (w0[2], w0[3]);
        let up = |t: f64| -(g0 + s * t) / (w * w) + 2.0 * zeta * s / (w * w * w);
        let vp = -s / (w * w);
        let (a, b) = (w0[0] - up(0.0), w0[1] - vp);
        let exact = |t: f64| {
            let e = (-zeta * w * t).exp();
            let c2 = (b + zeta * w * a) / wd;
            let u = e * (a * (wd * t).cos() + c2 * (wd * t).sin()) + up(t);
            let v = e
                * ((-zeta * w) * (a * (wd * t).cos() + c2 * (wd * t).sin())
                    + wd * (-a * (wd * t).sin() + c2 * (wd * t).cos()))
                + vp;
            (u, v)
        };
        let (u, v) = exact(h);
        assert!((w1[0] - u).abs() < 1e-15 * 0.01 + 1e-16, "{} vs {u}", w1[0]);
        assert!((w1[1] - v).abs() < 1e-14 * 0.2, "{} vs {v}", w1[1]);
        let mut c = vec![0.0; TERMS * 4];
        series(&m, 2, &w0, TERMS, &mut c);
        for f in [0.1, 0.37, 0.8] {
            let (u, v) = exact(f * h);
            assert!((series_at(&c, 4, 0, f * h, TERMS) - u).abs() < 1e-16);
            assert!((series_at(&c, 4, 1, f * h, TERMS) - v).abs() < 3e-15);
            // All components at once on whole rows: each one's arithmetic, bit for bit.
            let mut all = [f64::NAN; 3];
            series_into(&c, 4, f * h, TERMS - 1, &mut all);
            for (i, x) in all.into_iter().enumerate() {
                assert_eq!(x, series_at(&c, 4, i, f * h, TERMS - 1), "{i}");
            }
        }
    }

    /// The accelerations read off the matrix at an offset equal the rate of the velocity's series there and
    /// the oscillator's own equation, with the matrix by its nonzeros and whole.
    #[test]
    fn accelerations_off_the_matrix_are_the_velocity_s_rate() {
        let (w, zeta) = (12.0f64, 0.05f64);
        let m = oscillator(w, zeta);
        let h = MAX_RHO / step_bound(&m, 4, 1);
        for sparse in [false, true] {
            let mut motion = Motion::new(2, 4, 0);
            if sparse {
                motion.set_matrix(&m);
            } else {
                motion.m.copy_from_slice(&m);
            }
            motion.set_start(&[0.01, -0.2, 1.5, -30.0]);
            motion.invalidate();
            motion.terms = TERMS;
            for tau in [0.0, 0.37 * h, h] {
                let mut at = [0.0; 2];
                motion.on_series(tau, &mut at);
                let mut acc = [0.0];
                motion.accelerations_at(tau, &at, &mut acc);
                // The rate of the velocity on the series, and the oscillator's equation at tau.
                let series = motion.w_at(tau, 1)[1];
                let equation = -w * w * at[0] - 2.0 * zeta * w * at[1] - (1.5 - 30.0 * tau);
                for expected in [series, equation] {
                    assert!(
                        (acc[0] - expected).abs() <= 1e-13 * expected.abs(),
                        "{acc:?} vs {expected}"
                    );
                }
            }
        }
    }

    /// The motion at an offset with transition rows of its own equals the series there (both exact to
    /// rounding); the ends are the states the step left; an interior offset without rows is counted once per
    /// ask, and only when asked with `log`.
    #[test]
    fn offset_rows_give_the_motion_of_the_series() {
        let (w, zeta) = (12.0f64, 0.05f64);
        let m = oscillator(w, zeta);
        let h = MAX_RHO / step_bound(&m, 4, 1);
        let mut motion = Motion::new(2, 4, 0);
        motion.m.copy_from_slice(&m);
        motion.w0.copy_from_slice(&[0.01, -0.2, 1.5, -30.0]);
        motion.w1.copy_from_slice(&[7.0, 8.0]);
        motion.terms = TERMS;
        let tau = 0.37 * h;
        let (mut by_series, mut by_rows) = ([0.0; 2], [0.0; 2]);
        motion.motion_at(tau, h, 1e-15, &mut by_series, true);
        motion.motion_at(tau, h, 1e-15, &mut by_series, false);
        let mut asked = Vec::new();
        motion.take_asked(&mut asked);
        assert_eq!(asked, vec![(tau, 1)]);
        motion.add_offset(tau, &transition(&m, 4, 2, tau));
        motion.motion_at(tau + 1e-16, h, 1e-15, &mut by_rows, true);
        for (a, b) in by_rows.iter().zip(&by_series) {
            assert!((a - b).abs() <= 1e-15 * b.abs(), "{a} vs {b}");
        }
        motion.take_asked(&mut asked);
        assert!(asked.is_empty());
        motion.motion_at(h, h, 1e-15, &mut by_rows, true);
        assert_eq!(by_rows, [7.0, 8.0]);
        motion.motion_at(0.0, h, 1e-15, &mut by_rows, true);
        assert_eq!(by_rows, [0.01, -0.2]);
        motion.clear_offsets();
        motion.motion_at(tau, h, 1e-15, &mut by_rows, true);
        motion.take_asked(&mut asked);
        assert_eq!(asked.len(), 1);
    }

    /// Integrated quantities read inside a step whose Gauss nodes the stepper left unread equal, bit for bit,
    /// those of the same step with its nodes read.
    #[test]
    fn nodes_left_unread_are_read_as_the_stepper_would_have() {
        // The oscillator's damping energy, rate 2 zeta w v^2, read inside a step whose nodes the stepper
        // read (rates set) and inside one whose nodes it left unread (rows and rates given).
        #[derive(Debug)]
        struct Damping(f64);
        impl IntegratedRates for Damping {
            fn integrated_rates(&self, w: &[f64], out: &mut [f64]) {
                out[0] = self.0 * w[1] * w[1];
            }
        }
        let (w, zeta) = (12.0f64, 0.05f64);
        let m = oscillator(w, zeta);
        let h = MAX_RHO / step_bound(&m, 4, 1);
        let c = 2.0 * zeta * w;
        let w0 = [0.01, -0.2, 1.5, -30.0];
        let rows = [
            h,
            GAUSS_NODES[0] * h,
            GAUSS_NODES[1] * h,
            GAUSS_NODES[2] * h,
        ]
        .map(|t| transition(&m, 4, 2, t));
        let step = |unread: bool| {
            let mut motion = Motion::new(2, 4, 1);
            motion.set_matrix(&m);
            motion.set_start(&w0);
            motion.invalidate();
            motion.acc0[0] = 3.0;
            for (j, p) in rows.iter().enumerate() {
                let mut at = [0.0; 2];
                mat_vec(p, &w0, &mut at);
                // Rows 0 and 4: the step's ends; 1 to 3: its nodes, set only when read by the stepper.
                let q = if j == 0 { 4 } else { j };
                if q == 4 || !unread {
                    motion.rates[q][2] = c * at[1] * at[1];
                }
            }
            motion.rates[0][2] = c * w0[1] * w0[1];
            if unread {
                let rates: Arc<dyn IntegratedRates> = Arc::new(Damping(c));
                motion.set_nodes_unread(Some(UnreadNodes {
                    source: NodeSource::Rows(Arc::new(rows.clone())),
                    rates,
                }));
            }
            [0.3, 0.8].map(|th| motion.component(th * h, h, 2))
        };
        let (read, unread) = (step(false), step(true));
        assert_eq!(read, unread);
        assert!(read[1] > read[0] && read[0] > 3.0);
    }

    /// The integrated quantities equal the integral of a quartic rate given at the five points, exactly.
    #[test]
    fn integrated_quantities_are_the_integral_of_the_quartic_rate() {
        let rate = |th: f64| 1.0f64 + 2.0 * th + 3.0 * th * th - th.powi(3) + 0.5 * th.powi(4);
        let nodes = [0.0, GAUSS_NODES[0], GAUSS_NODES[1], GAUSS_NODES[2], 1.0];
        let mut m = Motion::new(2, 4, 1);
        for (j, th) in nodes.iter().enumerate() {
            m.rates[j][2] = rate(*th);
        }
        m.acc0[0] = 5.0;
        let h = 2.0;
        for th in [0.3f64, 0.7, 1.0] {
            let exact = 5.0 + h * (th + th * th + th.powi(3) - th.powi(4) / 4.0 + 0.1 * th.powi(5));
            let got = m.component(th * h, h, 2);
            assert!((got - exact).abs() < 1e-13 * exact, "{got} vs {exact}");
        }
    }

    /// A whole interval read piece by piece: the motion anywhere inside it, from the chain of pieces and
    /// each piece's series, is `exp(M tau) w0` (scaling and squaring) to rounding; the pieces' starts and
    /// the second rate there agree with it too.
    #[test]
    fn a_chained_step_is_the_exponential_anywhere_inside() {
        let (w, zeta, h) = (300.0f64, 0.4f64, 0.02f64);
        let m = oscillator(w, zeta);
        let r = step_bound(&m, 4, 1);
        let pieces = 1usize << super::super::halvings(r * h);
        assert!(pieces >= 16);
        let piece = h / pieces as f64;
        let w0 = [0.01, -0.2, 1.5, -30.0];
        let mut motion = Motion::new(2, 4, 0);
        motion.set_matrix(&m);
        motion.set_start(&w0);
        motion.terms = terms_for(r * piece);
        // Rows over 1, 2, 4, ... pieces: a start far along is found by a few jumps, the next by one link.
        let jumps: Vec<f64> = super::super::form_blocks(&m, 4, 2, (h, r), &[])
            .iter()
            .flat_map(|b| b.rows.clone())
            .collect();
        motion.chained((pieces, piece), &jumps, (&[], &[], None), true, &[]);
        motion.invalidate();
        let scale = 0.01 + 0.2 * h;
        for tau in [0.3 * piece, 3.7 * piece, 0.55 * h, 0.999 * h] {
            let e = super::super::exponential(&m, 4, 2, tau, r);
            let mut want = [0.0; 2];
            mat_vec(&e[..8], &w0, &mut want);
            let mut got = [0.0; 2];
            motion.on_series(tau, &mut got);
            assert!(
                (got[0] - want[0]).abs() < 1e-13 * scale,
                "{tau}: {got:?} vs {want:?}"
            );
            assert!(
                (got[1] - want[1]).abs() < 1e-13 * scale * w,
                "{tau}: {got:?} vs {want:?}"
            );
            // The acceleration's rate: d/dt of (M w)_1 through the series, against the second rate there.
            let [_, a, _] = motion.w_at(tau, 0);
            assert!((a - got[1]).abs() < 1e-12 * scale * w);
        }
        let k = pieces / 2 + 1;
        let mut start = [0.0; 2];
        motion.piece_start(k, &mut start);
        let e = super::super::exponential(&m, 4, 2, k as f64 * piece, r);
        let mut want = [0.0; 2];
        mat_vec(&e[..8], &w0, &mut want);
        assert!((start[0] - want[0]).abs() < 1e-13 * scale);
        let jerk = motion.w_at(k as f64 * piece, 1)[2];
        assert!((motion.second_rate_at(k, 1) - jerk).abs() < 1e-9 * jerk.abs().max(1.0));
        // A probe of `u - 0.01 v` and of `v`, keyed 7: its rows give the chain's values at every piece's
        // start (the driver reads events there); no rows, no value.
        let mut rows = Vec::new();
        let one = transition(&m, 4, 2, piece);
        for a in [[1.0, -0.01, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0]] {
            super::super::functional_at_pieces(&a, (&m, &one), (4, 2), (piece, pieces), &mut rows);
        }
        assert_eq!(rows.len(), 2 * (pieces - 1) * 4);
        motion.chained((pieces, piece), &jumps, (&[7], &rows, None), true, &[]);
        motion.invalidate();
        for k in (1..pieces).rev() {
            motion.piece_start(k, &mut start);
            let e = super::super::exponential(&m, 4, 2, k as f64 * piece, r);
            mat_vec(&e[..8], &w0, &mut want);
            assert!((start[0] - want[0]).abs() < 1e-13 * scale, "{k}");
            assert!((start[1] - want[1]).abs() < 1e-13 * scale * w, "{k}");
            let (x, v) = motion.probe(7, k).expect("a probe");
            assert!(
                (x - (start[0] - 0.01 * start[1])).abs() < 1e-13 * scale,
                "{k}"
            );
            assert!((v - start[1]).abs() < 1e-13 * scale * w, "{k}");
        }
        assert_eq!(motion.probe(7, pieces), None);
        assert_eq!(motion.probe(6, 1), None);
        // The jerk's rows (the velocity's row of M^2): at every piece's start the jerk of the exact
        // motion there (w by the exponential, the forcing along its line), as the chain's second rate.
        let a: Vec<f64> = (0..4)
            .map(|j| (0..4).map(|c| m[4 + c] * m[c * 4 + j]).sum())
            .collect();
        assert!(!motion.jerk_rows(0));
        let jerks = Arc::new(JerkRows::default());
        motion.chained(
            (pieces, piece),
            &jumps,
            (&[7], &rows, Some(&jerks)),
            true,
            &[],
        );
        motion.invalidate();
        // Not built until asked for; then kept.
        assert_eq!(motion.jerk_probe(0, 1), None);
        assert!(motion.jerk_rows(0) && motion.jerk_rows(0));
        for k in 1..pieces {
            let tau = k as f64 * piece;
            let e = super::super::exponential(&m, 4, 2, tau, r);
            let mut wk = [0.0, 0.0, w0[2] + tau * w0[3], w0[3]];
            mat_vec(&e[..8], &w0, &mut wk[..2]);
            let want: f64 = a.iter().zip(&wk).map(|(x, y)| x * y).sum();
            let got = motion.jerk_probe(0, k).expect("jerk rows");
            let size = w * w * w * scale;
            assert!((got - want).abs() < 1e-12 * size, "{k}: {got} vs {want}");
            assert!(
                (got - motion.second_rate_at(k, 1)).abs() < 1e-12 * size,
                "{k}"
            );
        }
        assert_eq!(motion.jerk_probe(0, pieces), None);
        assert_eq!(motion.jerk_probe(0, 0), None);
    }
}
