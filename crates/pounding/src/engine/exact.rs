//! Exact propagation between events while every law is affine ([`super::linear`]).
//!
//! A slow configuration met after the run's start (one series-length step per record interval, as the
//! Runge–Kutta stepper takes one or two) is left to the stepper, whose motion is cheaper for the recorders
//! to read, until one visit lasts [`BUILD_AFTER`] intervals; the configuration the run starts in is
//! propagated exactly from its first step.
//!
//! Each record interval (the ground's acceleration is linear on it) is split into equal steps short enough
//! for the truncated Taylor series of `exp(M h)` to be exact to rounding ([`crate::integrate::MAX_RHO`]);
//! the transition matrices of a configuration (keyed by its laws' stiffnesses and viscous coefficients) and
//! step length are built once and kept, a few configurations at a time. The energies and the laws' own
//! integrated states (a contact's work) are integrated along the exact motion by three-point
//! Gauss–Legendre quadrature, their rates at the nodes (and the state's at a step's end) read off the
//! configuration's matrix and forms ([`AffineRates`]) rather than the laws; over a built step length the same
//! quadrature is held as the forms' integrals ([`Length::integrals`]), and the nodes are read only when an
//! observer reads an integrated quantity inside the step. Events are located on the exact motion
//! ([`crate::integrate::Motion`]).
//!
//! A configuration whose fast modes (a foundation on soil) would split an interval into many such steps takes
//! each whole interval in one ([`Whole`]): its transitions by scaling and squaring, its energies as quadratic
//! forms of `w` integrated over it ([`super::forms`], [`crate::integrate::form_integrals`]), its motion read
//! inside on a chain of pieces. The rest of an interval after an event is taken in blocks of `2^i` pieces
//! (their transitions and forms are the doubling's intermediate results), after one series-length step to
//! the grid of pieces; so is an interval whose motion the cubic Hermite screens would misread
//! ([`HERMITE_MISS`]), in blocks half as long.

use super::forms::AffineRates;
use super::linear::{channel_at, forcing, full_w_at};
use super::System;
use crate::integrate::{
    halvings, live_of, mat_vec_on, quadrature, step_bound, transition, Dense, JerkRows, Motion,
    NodeSource, OdeSystem, Sparse, Tolerance, UnreadNodes, GAUSS_NODES, GAUSS_WEIGHTS, MAX_RHO,
    OFFSETS, QUADRATURE_NODES, QUADRATURE_WEIGHTS, TERMS, THREE_POINT_REACH,
};
use std::sync::Arc;

/// Configurations kept at a time.
const KEPT: usize = 16;
/// Step lengths kept per configuration.
const LENGTHS: usize = 3;
/// Largest work of a record interval propagated exactly, in multiply-adds of its transition matrices
/// (`mech x nw` per step, steps per interval): beyond it (more than a few degrees of freedom, a very stiff or
/// heavily damped contact) the Runge–Kutta stepper is cheaper, its implicit stretches handling stiffness.
/// Set from the examples' timings (`docs/performance.md`, "Exact propagation"): a two-SDOF pair (44) gains,
/// a 4-floor frame (about 500) and two buildings of 3 and 8 storeys (about 2,500) lost.
pub const MAX_INTERVAL_WORK: f64 = 512.0;
/// Steps of one configuration and length taken with the series before its transition matrices are built
/// (four matrix exponentials cost about as much as that many series): a closed contact lasts a few steps.
const BUILD_AFTER: usize = 24;
/// Largest number of components of `w` propagated exactly: beyond it a matrix–vector product costs more
/// than the Runge–Kutta stages it replaces.
pub const MAX_EXACT_DIM: usize = 64;

/// The transition matrices of one step length: to its end and to its three Gauss nodes; and, when the
/// configuration's rates are forms, the integrals of the forms over the step (three-point Gauss, as the
/// nodes' rates would give them): a step's integrated quantities grow by them without reading the nodes.
#[derive(Debug)]
struct Length {
    h: f64,
    phi: Arc<[Vec<f64>; 4]>,
    /// Each form's integral over the step, packed symmetric ([`pack_symmetric`]), in the order of the
    /// configuration's forms.
    integrals: Option<Vec<f64>>,
    /// Without them, the transitions to the step's [`QUADRATURE_NODES`], where the integrated quantities'
    /// rates are read for their growth.
    quadrature: Option<[Vec<f64>; 5]>,
}

/// A whole interval's rows at the three Gauss nodes of one of its blocks, `mech x nw` and `n x nw` each.
#[derive(Debug)]
struct NodeRows {
    /// Transition rows: the motion there.
    motion: [Vec<f64>; 3],
    /// The accelerations there ([`node_acceleration_rows`]).
    acc: [Vec<f64>; 3],
}

/// A whole record interval in one step ([`crate::integrate::exponential`]), for a configuration whose
/// fast modes would split it into many series-length steps: its transitions, the pieces its motion is read
/// on inside, and the integrals of the rates' forms over it; and the same over blocks of `1, 2, 4, ...` of
/// its pieces, which take the rest of an interval after an event, and an interval whose motion a whole step's
/// screens would misread ([`HERMITE_MISS`]), in a few exact steps.
#[derive(Debug)]
struct Whole {
    /// The interval, s.
    h: f64,
    /// The rows at the three Gauss nodes of each block (built when a block is first taken).
    nodes: Vec<Option<NodeRows>>,
    /// The transition rows of the blocks of `2^i` pieces, `i = 0 ..= log2(pieces)`, one after the other
    /// (`mech x nw` each; the last is the interval's): what the dense output's chain jumps with too
    /// ([`Motion::chained`]).
    jumps: Vec<f64>,
    /// Each block's form integrals, in the order of [`Self::quantities`], one after the other, each packed
    /// symmetric ([`pack_symmetric`]).
    integrals: Vec<Vec<f64>>,
    /// The integrated quantities whose rate is not 0, in the order of each block's form integrals.
    quantities: Vec<usize>,
    /// The elements with events watched, and the rows of their deformations and rates at the pieces'
    /// starts ([`Motion::probe`]): where the driver reads their event functions inside a step.
    probe_keys: Vec<usize>,
    probe_rows: Vec<f64>,
    /// The rows of each degree of freedom's jerk at the pieces' starts, built by the motion when the peaks
    /// recorder first asks for them ([`Motion::jerk_rows`]), and kept with the configuration.
    jerks: Arc<JerkRows>,
}

impl Whole {
    /// Blocks: `log2(pieces) + 1`.
    fn blocks(&self) -> usize {
        self.integrals.len()
    }

    /// The interval's series-length pieces (a power of 2).
    fn pieces(&self) -> usize {
        1 << (self.blocks() - 1)
    }

    /// Length of a piece, s.
    fn piece(&self) -> f64 {
        self.h / self.pieces() as f64
    }

    /// The transition rows of block `i` (`2^i` pieces).
    fn rows(&self, i: usize) -> &[f64] {
        let n = self.jumps.len() / self.blocks();
        &self.jumps[i * n..(i + 1) * n]
    }
}

/// How far the cubic Hermite of each displacement through the ends of a whole interval may miss the exact
/// motion at the interval's Gauss nodes, relative to what the displacement can reach: the screens of events
/// and peaks read the Hermite within 1 %; a step that misses by more is stepped instead (fast modes still
/// ringing in it).
const HERMITE_MISS: f64 = 1e-3;
/// Most pieces of a whole interval (a bound on the rows of its probes, `2 nw` per piece and watched element):
/// the chain of pieces is read by jumps over blocks and the events by probe rows, so the count matters
/// little below it. Measured (`docs/performance.md`): 256 pieces, the floor-to-column example 1.14 times
/// faster than stepped, a storey on V_s = 400 m/s soil 8 times; with 32 pieces at most and the chain walked
/// piece by piece, both ran slower whole.
const MAX_PIECES: usize = 1024;
/// Fewest pieces of a whole interval: with fewer, the Runge–Kutta stepper takes about as few steps as
/// that, each cheaper than a whole interval's. From 4 to [`FEW_PIECES`], a whole interval saves little
/// against the stepper's two or three steps, and pays for its building only over a long stretch
/// ([`FEW_PIECES_AFTER`]).
const MIN_PIECES: usize = 4;
/// Pieces per interval below which a configuration must be met in [`FEW_PIECES_AFTER`] whole intervals,
/// not [`WHOLE_AFTER`], before its transitions and forms are built.
const FEW_PIECES: usize = 8;
/// Whole intervals a configuration of fewer than [`FEW_PIECES`] pieces is met in before it is built: its
/// saving per interval is small, so only a configuration that lasts pays for the building (`nw^3` per
/// block and form). Measured (`docs/performance.md`, eighth session; instructions per run): built after 8,
/// the elastic 3-vs-8-storey pair and the condensed frame gain 27 and 31 %, but a pair of 3 and 8 bilinear
/// storeys, whose branches change configuration at every yield, costs 4 to 10 % more; after 64 (1.3 s of
/// a 0.02-s record), all gain: 27, 29 and 4 %, and three buildings in a row 9 %. A rule by law or by `w`
/// would step a bilinear storey that never yields unlike a linear one.
const FEW_PIECES_AFTER: usize = 64;
/// Largest `w` taken a whole interval at a time: its transitions and forms are built in `nw^3` (a plan of
/// four storeys, `nw` = 60, built them for each of its bilinear branches at a loss of 3 times).
const MAX_WHOLE_DIM: usize = 40;
/// Whole intervals a configuration is met in before its transitions and forms are built (they cost about
/// as much as that many intervals stepped): a bilinear branch that lasts a few intervals is stepped. The
/// configuration the run starts in is built at once (at rest, it is the one that lasts: a building on
/// soil on V_s = 400 m/s spent 11 % of its run stepping its first 8 intervals), unless it has fewer
/// than [`FEW_PIECES`] pieces.
const WHOLE_AFTER: usize = 8;

#[derive(Debug)]
struct Configuration {
    key: Vec<u64>,
    m: Vec<f64>,
    /// The nonzeros of `m` (for a configuration stepped exactly): a step's series built on them.
    sparse: Sparse,
    /// Bound on the rate of change of the motion, 1/s ([`crate::integrate::step_bound`]).
    r: f64,
    lengths: Vec<Length>,
    /// Steps taken in this configuration (the least used is forgotten first).
    uses: usize,
    /// A step length met, and how many times in a row: built into [`Self::lengths`] after
    /// [`BUILD_AFTER`].
    seen: (f64, usize),
    /// Transition rows at offsets into a step where observers ask for the whole state (at most
    /// [`OFFSETS`]): see [`Motion::motion_at`].
    offsets: Vec<(f64, Vec<f64>)>,
    /// Offsets asked without rows, with how many times: built into [`Self::offsets`] after [`BUILD_AFTER`].
    asked: Vec<(f64, usize)>,
    /// The rates of its integrated quantities as forms (`None`: a law cannot give them, or a contact is
    /// closed), integrated over a built step length ([`Length::integrals`]) or, for a configuration too
    /// costly in series-length steps, over the whole interval once built.
    forms: Option<RateForms>,
    /// The rates of the state at any `w` (`None`: a law cannot give its states' rates): at a step's Gauss
    /// nodes and end in place of the right-hand side.
    rates: Option<Arc<AffineRates>>,
    whole: Option<Whole>,
    /// Whole intervals taken, and left to the stepper for their Hermite misses ([`HERMITE_MISS`]): a
    /// configuration whose fast modes ring (lightly damped) misses nearly always, and stops trying.
    taken: usize,
    missed: usize,
    /// Whole intervals met before [`Self::whole`] was built ([`WHOLE_AFTER`]).
    met: usize,
    /// The run started in this configuration: stepped exactly from its first step.
    first: bool,
    /// Whole intervals in a row left to the stepper in this visit (see [`Exact::step_until`]).
    visit: usize,
}

/// Each integrated quantity's rate as a quadratic form of `w` ([`System::rate_forms`]).
type RateForms = Vec<(usize, Vec<f64>)>;

impl Configuration {
    /// A slow configuration ([`slow`]) met after the start, without transitions yet (record intervals of
    /// `interval` s): left to the stepper until a visit lasts [`BUILD_AFTER`] intervals.
    fn declined(&self, interval: f64) -> bool {
        !self.first && self.lengths.is_empty() && slow(self.r, interval)
    }
}

/// The series' reach at which this module's thresholds were measured (`r h <= 1/2`; steps reach
/// [`MAX_RHO`] since): the choices between exact and stepped, whole and series-length, are made on this
/// scale, so that each stays what it was measured to be, while steps and pieces are as long as the
/// series allows.
const CHOICE_RHO: f64 = 0.5;

/// The pieces of a record interval of `rho = r × interval` on the choices' scale ([`CHOICE_RHO`]): twice
/// the pieces a whole interval takes.
fn choice_pieces(rho: f64) -> usize {
    1usize << halvings(rho * MAX_RHO / CHOICE_RHO)
}

/// A configuration of step bound `r` (1/s) that takes a record interval of length `interval` (s) in one
/// short series-length step ([`CHOICE_RHO`]), as the Runge–Kutta stepper does in one or two.
fn slow(r: f64, interval: f64) -> bool {
    r * interval <= CHOICE_RHO
}

/// What stepping configuration `m` of `sys` exactly needs: the rates' forms (integrated over a whole
/// interval, or over a step length once built), the rates of the state off them, and the nonzeros of `m`.
fn exact_parts(
    sys: &System,
    m: &[f64],
    (nw, mech): (usize, usize),
) -> (Option<RateForms>, Option<Arc<AffineRates>>, Sparse) {
    let forms = sys.rate_forms();
    let sparse = Sparse::of(m, nw);
    let rates = forms
        .as_deref()
        .map(|f| Arc::new(AffineRates::new(sparse.clone(), nw, mech / 2, f)));
    (forms, rates, sparse)
}

/// The integrals over a step of length `h` (within the series' reach) of configuration `c`'s forms,
/// packed ([`Length::integrals`]); `None` without forms or rates.
fn length_integrals(c: &Configuration, (nw, mech): (usize, usize), h: f64) -> Option<Vec<f64>> {
    let forms = c.forms.as_deref().filter(|_| c.rates.is_some())?;
    let qs: Vec<&[f64]> = forms.iter().map(|(_, q)| q.as_slice()).collect();
    let blocks = crate::integrate::form_blocks(&c.m, nw, mech, (h, c.r), &qs);
    // The last block is the whole step (the only one within the series' reach).
    let step = blocks.last()?;
    Some(
        step.integrals
            .iter()
            .flat_map(|g| pack_symmetric(g, nw))
            .collect(),
    )
}

/// Each integrated quantity's growth over a step (a whole interval's block, or a built length) from `w`:
/// `w^T G w` by its form's integral `G` (`integrals`, packed symmetric, one after the other in the order of
/// `keys`, the quantities' indices) into `inc`, 0 for the quantities without a form; `pairs` is room for
/// `w`'s products ([`pair_products`]).
fn form_growth(
    w: &[f64],
    (keys, integrals): (impl Iterator<Item = usize>, &[f64]),
    pairs: &mut [f64],
    inc: &mut [f64],
) {
    inc.fill(0.0);
    pair_products(w, pairs);
    for (k, g) in keys.zip(integrals.chunks_exact(pairs.len())) {
        inc[k] = crate::integrate::dot(g, pairs);
    }
}

/// The whole interval of length `h` of configuration `c` (with its forms) of `sys`.
fn build_whole(sys: &System, c: &Configuration, (nw, mech): (usize, usize), h: f64) -> Whole {
    use crate::integrate::{form_blocks, functional_at_pieces};
    let forms = c.forms.as_deref().unwrap_or_default();
    let qs: Vec<&[f64]> = forms.iter().map(|(_, q)| q.as_slice()).collect();
    let blocks = form_blocks(&c.m, nw, mech, (h, c.r), &qs);
    let pieces = 1usize << (blocks.len() - 1);
    let (mut probe_keys, mut probe_rows) = (Vec::new(), Vec::new());
    for (e, el) in sys.elements().iter().enumerate() {
        if el.watched().is_empty() {
            continue;
        }
        probe_keys.push(e);
        let terms = super::linear::deformation_terms(el);
        for shift in [0, mech / 2] {
            let mut a = vec![0.0; nw];
            for &(i, k) in &terms {
                a[shift + i] += k;
            }
            let at = (h / pieces as f64, pieces);
            functional_at_pieces(&a, (&c.m, &blocks[0].rows), (nw, mech), at, &mut probe_rows);
        }
    }
    Whole {
        h,
        jerks: Arc::default(),
        nodes: (0..blocks.len()).map(|_| None).collect(),
        quantities: forms.iter().map(|(k, _)| *k).collect(),
        probe_keys,
        probe_rows,
        jumps: blocks.iter().flat_map(|b| b.rows.iter().copied()).collect(),
        integrals: blocks
            .into_iter()
            .map(|b| {
                b.integrals
                    .iter()
                    .flat_map(|g| pack_symmetric(g, nw))
                    .collect()
            })
            .collect(),
    }
}

/// [`crate::integrate::terms_for`] `rho`, through `last` (the last `rho` and its count): most steps repeat
/// the one before's length.
fn terms(last: &mut (f64, usize), rho: f64) -> usize {
    if last.0 != rho {
        *last = (rho, crate::integrate::terms_for(rho));
    }
    last.1
}

/// The upper triangle, row by row, of the symmetric part of the `nw x nw` matrix `g` (`g_ij + g_ji` off the
/// diagonal): `w^T g w` is then its dot product with the products `w_i w_j`, `i <= j`, in the same order
/// ([`pair_products`]), half the multiply-adds, and in partial sums ([`crate::integrate::dot`]).
fn pack_symmetric(g: &[f64], nw: usize) -> Vec<f64> {
    (0..nw)
        .flat_map(|i| {
            (i..nw).map(move |j| {
                if i == j {
                    g[i * nw + i]
                } else {
                    g[i * nw + j] + g[j * nw + i]
                }
            })
        })
        .collect()
}

/// The products `w_i w_j`, `i <= j`, in the order of [`pack_symmetric`].
fn pair_products(w: &[f64], out: &mut [f64]) {
    let mut rest = out;
    for (i, &wi) in w.iter().enumerate() {
        let (row, tail) = rest.split_at_mut(w.len() - i);
        for (o, &wj) in row.iter_mut().zip(&w[i..]) {
            *o = wi * wj;
        }
        rest = tail;
    }
}

/// The rows (`n x nw`) giving the accelerations (the velocities' rates) at `tau` into a step from `w` at its
/// start, `Φ(tau)`'s motion rows `rows` (`mech x nw`) given: `M`'s velocity rows applied to the motion there
/// and to the forcing, which moves on its lines (`w_f + tau M_f w`: a channel's value by its slope, the
/// constants not at all). One product with `w` where the motion's rows and then `M`'s would be two.
fn node_acceleration_rows(
    m: &[f64],
    rows: &[f64],
    tau: f64,
    (nw, mech): (usize, usize),
) -> Vec<f64> {
    let n = mech / 2;
    let mut out = vec![0.0; n * nw];
    for (r, acc) in out.chunks_exact_mut(nw).enumerate() {
        let row = &m[(n + r) * nw..(n + r + 1) * nw];
        for (k, &a) in row.iter().enumerate().filter(|(_, a)| **a != 0.0) {
            if k < mech {
                for (o, p) in acc.iter_mut().zip(&rows[k * nw..(k + 1) * nw]) {
                    *o += a * p;
                }
            } else {
                acc[k] += a;
                for (o, p) in acc.iter_mut().zip(&m[k * nw..(k + 1) * nw]) {
                    *o += a * tau * p;
                }
            }
        }
    }
    out
}

/// Transition rows (`mech x nw`) over `tau` s (at most the interval) of the configuration of matrix `m`
/// that takes whole intervals `whole`: a series-length step within the piece holding `tau`, carried on by the
/// blocks of the binary digits of the pieces before it ([`crate::integrate::times_transition`]), in a few
/// products where scaling and squaring would take a dozen.
fn rows_at(m: &[f64], whole: &Whole, tau: f64, (nw, mech): (usize, usize)) -> Vec<f64> {
    let piece = whole.piece();
    let before = ((tau / piece).floor() as usize).min(whole.pieces());
    let mut rows = transition(m, nw, mech, (tau - before as f64 * piece).max(0.0));
    let mut next = rows.clone();
    for b in 0..whole.blocks() {
        if before >> b & 1 == 1 {
            let t = (1usize << b) as f64 * piece;
            let block = whole.rows(b);
            crate::integrate::times_transition(&rows, (m, block), (nw, mech), t, &mut next);
            std::mem::swap(&mut rows, &mut next);
        }
    }
    rows
}

impl Configuration {
    /// Counts `n` more asks of the offset `tau` (within `slack`, s); the rows of an offset asked
    /// [`BUILD_AFTER`] times are built and returned. The least asked offset makes room for a new one.
    fn ask(&mut self, tau: f64, n: usize, slack: f64, nw: usize, mech: usize) -> Option<usize> {
        if self.offsets.len() >= OFFSETS {
            return None;
        }
        let i = match self
            .asked
            .iter()
            .position(|(t, _)| (t - tau).abs() <= slack)
        {
            Some(i) => {
                self.asked[i].1 += n;
                i
            }
            None if self.asked.len() < OFFSETS => {
                self.asked.push((tau, n));
                self.asked.len() - 1
            }
            None => {
                let i = (0..self.asked.len())
                    .min_by_key(|&i| self.asked[i].1)
                    .expect("offsets asked");
                self.asked[i] = (tau, n);
                i
            }
        };
        if self.asked[i].1 < BUILD_AFTER {
            return None;
        }
        let (tau, _) = self.asked.swap_remove(i);
        let rows = match &self.whole {
            Some(w) if tau <= w.h => rows_at(&self.m, w, tau, (nw, mech)),
            _ => crate::integrate::transition_rows(&self.m, nw, mech, tau, self.r),
        };
        self.offsets.push((tau, rows));
        Some(self.offsets.len() - 1)
    }
}

/// The mean rate of each integrated quantity over a one-piece step from `t0` of length `h` (s), by
/// five-point Gauss–Legendre ([`QUADRATURE_NODES`]) along the exact motion: `w` at the step's start (its
/// forcing carried along the lines of `fd` components), the motion at the nodes `wq`; the rates by the
/// configuration's forms, or by the system's right-hand side without them. Written to `inc` (times `h`,
/// the growth); `room` holds a whole `w`, a state and its rate.
fn five_point_growth(
    sys: &System,
    rates: Option<&AffineRates>,
    (w, wq, fd): (&[f64], &[Vec<f64>; 5], usize),
    (t0, h): (f64, f64),
    (wfull, ynode, dynode): (&mut [f64], &mut [f64], &mut [f64]),
    inc: &mut [f64],
) {
    let mech = 2 * sys.layout().dofs();
    inc.fill(0.0);
    for ((g, weight), at) in QUADRATURE_NODES.iter().zip(QUADRATURE_WEIGHTS).zip(wq) {
        rate_at(sys, rates, (w, at, fd), (t0, g * h), (wfull, ynode), dynode);
        for (inc, r) in inc.iter_mut().zip(&dynode[mech..]) {
            *inc += weight * r;
        }
    }
}

/// The rate of every layout component `tau` s into a step from `t0` (`out`, the layout's length), the
/// motion there `at` (`w` at the step's start, its forcing carried along the lines of `fd` components): by
/// the configuration's `rates`, or by the system's right-hand side without them (its integrated quantities
/// as `ynode` holds them). `wfull` is room for a whole `w`.
fn rate_at(
    sys: &System,
    rates: Option<&AffineRates>,
    (w, at, fd): (&[f64], &[f64], usize),
    (t0, tau): (f64, f64),
    (wfull, ynode): (&mut [f64], &mut [f64]),
    out: &mut [f64],
) {
    let mech = 2 * sys.layout().dofs();
    match rates {
        Some(rates) => {
            full_w_at(at, (w, mech, fd), tau, wfull);
            rates.write(wfull, out);
        }
        None => {
            ynode[..mech].copy_from_slice(&at[..mech]);
            sys.rhs_in(t0 + tau, forcing(w, mech, tau), ynode, out);
        }
    }
}

/// How a step's Gauss nodes are left unread, if they are: a built length with form integrals (its rows), a
/// step of one series whose rates are forms (`series_five`: its series), or a whole interval's block when no
/// observer read the last step's integrated quantities inside it (`integrals_read`: held, the motion's
/// rates read there as accelerations are sampled at them). `None`: read now.
fn unread_nodes(
    config: &Configuration,
    (block, built): (Option<usize>, Option<usize>),
    series_five: bool,
    integrals_read: bool,
) -> Option<UnreadNodes> {
    let source = match (block, built) {
        (None, Some(i)) => NodeSource::Rows(config.lengths.get(i)?.phi.clone()),
        (None, None) if series_five => NodeSource::Series,
        (Some(_), _) if !integrals_read => NodeSource::Held,
        _ => return None,
    };
    let rates = config.rates.clone()?;
    Some(UnreadNodes { source, rates })
}

/// The motion's rates at a block's Gauss nodes: the velocities of `wn[1..4]` and the accelerations `wacc`
/// ([`Exact::propagate_block`]); `n` degrees of freedom.
fn block_node_rates(motion: &mut Motion, wn: &[Vec<f64>; 4], wacc: &[Vec<f64>; 3], n: usize) {
    for (rates, (w, acc)) in motion.rates[1..4].iter_mut().zip(wn[1..].iter().zip(wacc)) {
        rates[..n].copy_from_slice(&w[n..2 * n]);
        rates[n..2 * n].copy_from_slice(acc);
    }
}

/// The exact stepper of a run (see the module). Working memory is allocated once per run.
#[derive(Debug)]
pub struct Exact {
    configs: Vec<Configuration>,
    current: usize,
    key: Vec<u64>,
    f0: Vec<f64>,
    nw: usize,
    mech: usize,
    t: f64,
    y: Vec<f64>,
    dydt: Vec<f64>,
    dense: Dense,
    w: Vec<f64>,
    wn: [Vec<f64>; 4],
    /// The accelerations at a whole interval's block's Gauss nodes ([`Self::propagate_block`]).
    wacc: [Vec<f64>; 3],
    /// The motion at the step's [`QUADRATURE_NODES`], where a step's integrated quantities are read for
    /// their growth when no form integrals give it (set by [`Self::propagate`] on one-piece steps).
    wq: [Vec<f64>; 5],
    scratch: Vec<f64>,
    series: Vec<f64>,
    /// The last step built [`Self::series`] (one piece): the dense output adopts it.
    series_built: bool,
    ynode: Vec<f64>,
    dynode: Vec<f64>,
    /// `w` at a Gauss node or a step's end, whole (the motion and the forcing there).
    wfull: Vec<f64>,
    /// Offsets the last step's observers asked of its motion (room for [`OFFSETS`]).
    asked: Vec<(f64, usize)>,
    /// The configuration whose matrix the dense output holds.
    dense_config: Option<usize>,
    /// The configuration whose whole interval's rows (jumps, probes) the dense output holds: a
    /// series-length step between two blocks of another configuration changes the matrix, not them.
    chain_config: Option<usize>,
    steps: usize,
    last: f64,
    /// The current configuration takes whole record intervals ([`Whole`]) and leaves the rest to the
    /// Runge–Kutta stepper.
    whole: bool,
    /// Each integrated quantity's growth over a block of a whole interval.
    inc: Vec<f64>,
    /// The products of the components of `w` for its form integrals ([`pair_products`]).
    pairs: Vec<f64>,
    /// The largest block of the current interval's pieces to try (`log2` of its pieces): lowered by a
    /// Hermite miss for the rest of the interval.
    cap: usize,
    /// What each degree of freedom's displacement can reach, m or rad (its absolute tolerance over the
    /// relative one): the size a Hermite miss is measured against.
    scale: Vec<f64>,
    /// The components of `w` that are not 0.
    live: Vec<usize>,
    /// The state and its rate before a whole interval, to return to if it is stepped instead.
    before: (Vec<f64>, Vec<f64>),
    /// The record's time step, s (the shortest of supports' records; infinite under a constant
    /// acceleration).
    interval: f64,
    /// The built length with form integrals of the current configuration the last step took: its
    /// integrated quantities grown by them, its Gauss nodes left unread.
    built: Option<usize>,
    /// Each ground channel's acceleration and slope on the current interval (`[g_0, s_0, g_1, s_1, ...]`).
    lines: Vec<f64>,
    /// The current configuration is slow, met after the start and without transitions yet: left to the
    /// stepper, its visit counted at each whole interval ([`Self::resume`]).
    waiting: bool,
    /// The last `r h` whose series terms were counted, and the count ([`terms`]).
    terms: (f64, usize),
}

impl Exact {
    /// A stepper for `sys`, or `None` when its `w` is too large to pay ([`MAX_EXACT_DIM`], or larger than
    /// whole intervals take, [`MAX_WHOLE_DIM`], with a series step's work above [`MAX_INTERVAL_WORK`]):
    /// then no configuration is tried at any event. `tol` is the run's (the sizes of its motion).
    pub fn new(sys: &System, tol: &Tolerance) -> Option<Self> {
        let nw = sys.linear_dim();
        let dim = sys.dim();
        let mech = 2 * sys.layout().dofs();
        // Too large to pay in any configuration: beyond whole intervals' size, and a single series step
        // per interval beyond the work they may cost (only a configuration without stiffness or damping,
        // bodies in free flight, would be cheaper, and the stepper takes those in long steps).
        let never = nw > MAX_WHOLE_DIM && (mech * nw) as f64 > MAX_INTERVAL_WORK;
        if nw > MAX_EXACT_DIM || never {
            return None;
        }
        let scale: Vec<f64> = (0..mech / 2)
            .map(|i| {
                tol.atol
                    .get(i)
                    .map_or(0.0, |a| a / tol.rtol.max(f64::MIN_POSITIVE))
            })
            .collect();
        Some(Self {
            configs: Vec::new(),
            current: 0,
            key: Vec::new(),
            f0: Vec::new(),
            nw,
            mech,
            t: 0.0,
            y: vec![0.0; dim],
            dydt: vec![0.0; dim],
            dense: Dense::exact(Motion::new(mech, nw, dim - mech)),
            w: vec![0.0; nw],
            wn: std::array::from_fn(|_| vec![0.0; nw]),
            wacc: std::array::from_fn(|_| vec![0.0; mech / 2]),
            wq: std::array::from_fn(|_| vec![0.0; nw]),
            scratch: vec![0.0; dim],
            series: vec![0.0; TERMS * nw],
            series_built: false,
            ynode: vec![0.0; dim],
            dynode: vec![0.0; dim],
            wfull: vec![0.0; nw],
            asked: Vec::with_capacity(OFFSETS),
            dense_config: None,
            chain_config: None,
            steps: 0,
            last: 0.0,
            interval: match sys.ground() {
                super::Ground::Record(r) | super::Ground::Plane { x: r, .. } => r.dt(),
                // The kinks of all the records: intervals no longer than the shortest step.
                super::Ground::Many(rs) => rs.iter().map(|r| r.dt()).fold(f64::INFINITY, f64::min),
                super::Ground::Constant(_) => f64::INFINITY,
            },
            lines: vec![0.0; sys.forcing_dim()],
            whole: false,
            inc: vec![0.0; dim - mech],
            pairs: vec![0.0; nw * (nw + 1) / 2],
            cap: usize::MAX,
            scale,
            live: Vec::with_capacity(nw),
            before: (vec![0.0; dim], vec![0.0; dim]),
            built: None,
            waiting: false,
            terms: (f64::NAN, 0),
        })
    }

    /// Starts at `(t0, y0)` if the system's laws are all affine now; `false` otherwise, or when the
    /// configuration is slow and met after the start without transitions yet ([`Self::waiting`]).
    pub fn reset(&mut self, sys: &System, t0: f64, y0: &[f64]) -> bool {
        self.waiting = false;
        if !sys.linear_now(&mut self.key, &mut self.f0) {
            return false;
        }
        self.current = match self.configs.iter().position(|c| c.key == self.key) {
            Some(i) => {
                if i != self.current {
                    self.configs[i].visit = 0;
                }
                i
            }
            None => {
                let m = sys.linear_matrix();
                let r = step_bound(&m, self.nw, sys.layout().dofs());
                // A closed contact's motion is read as one series per step by the impact recorders: no
                // whole intervals then.
                let closed = sys.elements().iter().any(|el| {
                    el.law.as_contact().is_some()
                        && el.affine().is_none_or(|a| a.k != 0.0 || a.c != 0.0)
                });
                let fine = self.fine_work(r) <= MAX_INTERVAL_WORK;
                let whole = !fine
                    && !closed
                    && self.nw <= MAX_WHOLE_DIM
                    && (MIN_PIECES..=MAX_PIECES).contains(&choice_pieces(r * self.interval));
                let mut config = Configuration {
                    key: self.key.clone(),
                    forms: None,
                    rates: None,
                    r,
                    sparse: Sparse::default(),
                    m,
                    lengths: Vec::new(),
                    seen: (f64::NAN, 0),
                    uses: 0,
                    offsets: Vec::new(),
                    asked: Vec::with_capacity(OFFSETS),
                    whole: None,
                    taken: 0,
                    missed: 0,
                    met: 0,
                    first: self.configs.is_empty(),
                    visit: 0,
                };
                // Forms only for a configuration that will be stepped exactly (many are met and refused,
                // or left to the stepper until they last: see `reset` below and `resume`).
                if whole || (fine && !config.declined(self.interval)) {
                    (config.forms, config.rates, config.sparse) =
                        exact_parts(sys, &config.m, (self.nw, self.mech));
                }
                if self.configs.len() < KEPT {
                    self.configs.push(config);
                    self.configs.len() - 1
                } else {
                    let i = (0..KEPT)
                        .min_by_key(|&i| self.configs[i].uses)
                        .expect("configurations kept");
                    if self.dense_config == Some(i) {
                        self.dense_config = None;
                    }
                    if self.chain_config == Some(i) {
                        self.chain_config = None;
                    }
                    self.configs[i] = config;
                    i
                }
            }
        };
        let c = &mut self.configs[self.current];
        if c.declined(self.interval) {
            // A slow configuration met after the start (a branch, a restrainer gone taut): the stepper
            // takes an interval in one step too, and its motion is cheaper to read, until a visit lasts
            // long enough to pay for the transitions. Counted as used, or it would be the first forgotten.
            c.uses += 1;
            self.waiting = true;
            return false;
        }
        self.start(sys, t0, y0)
    }

    /// Whether the current configuration is left to the stepper until a visit lasts [`BUILD_AFTER`] whole
    /// intervals ([`Self::resume`] counts them): no event has changed it since [`Self::reset`].
    pub fn waiting(&self) -> bool {
        self.waiting
    }

    /// At `(t0, y0)`, the start of a whole record interval the stepper is about to take: while
    /// [`Self::waiting`], counts the visit's interval and starts once the visit lasts [`BUILD_AFTER`] (the
    /// next step builds the configuration's transitions); else as [`Self::reset`].
    pub fn resume(&mut self, sys: &System, t0: f64, y0: &[f64]) -> bool {
        if !self.waiting {
            return self.reset(sys, t0, y0);
        }
        let c = &mut self.configs[self.current];
        c.uses += 1;
        c.visit += 1;
        if c.visit < BUILD_AFTER {
            return false;
        }
        self.waiting = false;
        if c.sparse.rows() == 0 {
            (c.forms, c.rates, c.sparse) = exact_parts(sys, &c.m, (self.nw, self.mech));
        }
        self.start(sys, t0, y0)
    }

    /// Starts the current configuration at `(t0, y0)`; `false` if it takes whole intervals and cannot
    /// (no forms) or misses its Hermite screens more often than not.
    fn start(&mut self, sys: &System, t0: f64, y0: &[f64]) -> bool {
        self.whole = self.fine_work(self.configs[self.current].r) > MAX_INTERVAL_WORK;
        let c = &self.configs[self.current];
        if self.whole && (c.forms.is_none() || (c.missed >= 8 && c.missed > c.taken)) {
            return false;
        }
        self.t = t0;
        self.y.copy_from_slice(y0);
        sys.rhs(t0, y0, &mut self.dydt);
        true
    }

    /// The work of a record interval in series-length steps (of the choices' reach, [`CHOICE_RHO`]) for a
    /// configuration of step bound `r` (1/s): see [`MAX_INTERVAL_WORK`].
    fn fine_work(&self, r: f64) -> f64 {
        (r * self.interval / CHOICE_RHO).ceil() * (self.mech * self.nw) as f64
    }

    /// Whether `[t, t_stop]` is a whole record interval.
    pub fn is_interval(&self, t: f64, t_stop: f64) -> bool {
        (t_stop - t - self.interval).abs() <= 1e-9 * self.interval
    }

    /// Current time, s.
    pub fn t(&self) -> f64 {
        self.t
    }
    /// Current state.
    pub fn y(&self) -> &[f64] {
        &self.y
    }
    /// `f(t, y)` of the current state.
    pub fn dydt(&self) -> &[f64] {
        &self.dydt
    }
    /// The exact motion of the last step.
    pub fn dense(&self) -> &Dense {
        &self.dense
    }
    /// Steps taken.
    pub fn steps(&self) -> usize {
        self.steps
    }
    /// Length of the last step, s.
    pub fn last_length(&self) -> f64 {
        self.last
    }

    /// The step length that splits `[t, t_stop]` into equal exact steps.
    fn length(&self, t_stop: f64) -> f64 {
        let span = t_stop - self.t;
        let r = self.configs[self.current].r;
        let count = (span * r / MAX_RHO).ceil().max(1.0);
        span / count
    }

    /// Takes one exact step towards `t_stop` (never past it). The ground's acceleration must be linear on
    /// `[t, t_stop]` (the driver stops at its kinks). `false`, with nothing done, when a configuration that
    /// takes whole record intervals ([`Whole`]) has not built them yet, or misses its Hermite screens more
    /// often than not ([`HERMITE_MISS`]): the Runge–Kutta stepper takes `[t, t_stop]` then. (A slow
    /// configuration met after the start is not started until it lasts: [`Self::reset`], [`Self::resume`].)
    pub fn step_until(&mut self, sys: &System, t_stop: f64) -> bool {
        if self.whole {
            return self.step_whole(sys, t_stop);
        }
        let (t0, h) = (self.t, self.length(t_stop));
        let c = &mut self.configs[self.current];
        if c.declined(self.interval) {
            // Resumed after a visit of BUILD_AFTER whole intervals (a declined configuration is not started
            // otherwise): its transitions are built now.
            c.seen = (h, BUILD_AFTER);
        }
        self.begin(sys, h);
        self.propagate(h);
        self.finish(sys, (t0, h, self.end_time(t0, h, t_stop)), None);
        self.steps += 1;
        true
    }

    /// A step of a configuration that takes whole record intervals: a whole interval in one; else, towards
    /// `t_stop`, a series-length step to the grid of pieces counted back from `t_stop` (after an event),
    /// then the largest blocks of pieces that fit. A block whose motion the Hermite screens would misread
    /// is taken again as blocks half as long, down to one piece (a series-length step, as exact as any).
    fn step_whole(&mut self, sys: &System, t_stop: f64) -> bool {
        let interval = self.is_interval(self.t, t_stop);
        let (nw, mech, length) = (self.nw, self.mech, self.interval);
        let c = &mut self.configs[self.current];
        if c.whole.is_none() {
            let after = if choice_pieces(c.r * length) < FEW_PIECES {
                FEW_PIECES_AFTER
            } else if c.first {
                0
            } else {
                WHOLE_AFTER
            };
            if !interval || c.met < after {
                c.met += usize::from(interval);
                return false;
            }
            c.whole = Some(build_whole(sys, c, (nw, mech), length));
        }
        if interval {
            self.cap = usize::MAX;
        }
        let whole = c.whole.as_ref().expect("built above");
        let (top, piece) = (whole.blocks() - 1, whole.piece());
        let (t0, span) = (self.t, t_stop - self.t);
        let count = (span / piece + 1e-9).floor();
        let rest = span - count * piece;
        if count < 1.0 || rest > 1e-9 * piece {
            let h = if count < 1.0 { span } else { rest };
            self.begin(sys, h);
            self.propagate(h);
            self.finish(sys, (t0, h, self.end_time(t0, h, t_stop)), None);
            self.steps += 1;
            return true;
        }
        let mut i = ((count as usize).ilog2() as usize).min(top).min(self.cap);
        self.begin(sys, span);
        self.before.0.copy_from_slice(&self.y);
        self.before.1.copy_from_slice(&self.dydt);
        loop {
            let h = (1usize << i) as f64 * piece;
            self.propagate_block(i);
            self.finish(sys, (t0, h, self.end_time(t0, h, t_stop)), Some(i));
            if i == 0 || self.hermite_holds(h) {
                self.configs[self.current].taken += usize::from(i == top);
                self.steps += 1;
                return true;
            }
            self.y.copy_from_slice(&self.before.0);
            self.dydt.copy_from_slice(&self.before.1);
            self.t = t0;
            let c = &mut self.configs[self.current];
            if i == top {
                c.missed += 1;
                if c.missed >= 8 && c.missed > c.taken {
                    // Fast modes that ring (lightly damped): the stepper is cheaper.
                    return false;
                }
            }
            i -= 1;
            self.cap = i;
        }
    }

    /// Readies a step of length `h` from the current state: counts a use of the configuration, reads each
    /// ground channel's line on the step and sets `w`.
    fn begin(&mut self, sys: &System, h: f64) {
        let t0 = self.t;
        self.configs[self.current].uses += 1;
        // Each ground channel's acceleration on the step, read inside it (a record's end is a jump).
        let ground = sys.ground();
        let (ta, tb) = (t0 + 0.25 * h, t0 + 0.75 * h);
        for (c, line) in self.lines.chunks_exact_mut(2).enumerate() {
            let (ga, gb) = (channel_at(ground, c, ta), channel_at(ground, c, tb));
            // A sliver of a step (an event a few roundings before a kink) reads no slope: its two
            // readings may straddle the kink, and over it the slope adds nothing.
            let slope = if tb - ta > 1e-9 * self.interval.min(1.0) {
                (gb - ga) / (tb - ta)
            } else {
                0.0
            };
            line.copy_from_slice(&[ga - slope * (ta - t0), slope]);
        }
        sys.linear_state(&self.y, &self.lines, &self.f0, &mut self.w);
    }

    /// The end of a step of length `h` from `t0` towards `t_stop`: `t_stop` itself when within rounding
    /// (of `h`, or of the time itself: blocks of one piece, tens of microseconds, summed to a time of seconds
    /// would otherwise leave a sliver of a few roundings before `t_stop`, too short to read the ground's
    /// slope on).
    fn end_time(&self, t0: f64, h: f64, t_stop: f64) -> f64 {
        if (t_stop - (t0 + h)).abs() <= 1e-12 * h + 8.0 * f64::EPSILON * t_stop.abs() {
            t_stop
        } else {
            t0 + h
        }
    }

    /// `wn` (as [`Self::propagate`]) and [`Self::inc`] over block `i` of the whole interval (`2^i` pieces).
    fn propagate_block(&mut self, i: usize) {
        let (nw, mech) = (self.nw, self.mech);
        self.built = None;
        let c = &mut self.configs[self.current];
        let whole = c.whole.as_mut().expect("built by step_whole");
        if whole.nodes[i].is_none() {
            let length = (1usize << i) as f64 * whole.piece();
            let motion = GAUSS_NODES.map(|g| rows_at(&c.m, whole, g * length, (nw, mech)));
            let acc = std::array::from_fn(|j| {
                node_acceleration_rows(&c.m, &motion[j], GAUSS_NODES[j] * length, (nw, mech))
            });
            whole.nodes[i] = Some(NodeRows { motion, acc });
        }
        // Over the components of w that are not 0 (constant forces of linear laws, a ground channel the
        // record does not have).
        live_of(&self.w, &mut self.live);
        let (w, live) = (&self.w, &self.live);
        mat_vec_on(whole.rows(i), w, live, &mut self.wn[0][..mech]);
        let nodes = whole.nodes[i].as_ref().expect("built above");
        for (p, out) in nodes.motion.iter().zip(self.wn[1..].iter_mut()) {
            mat_vec_on(p, w, live, &mut out[..mech]);
        }
        for (p, out) in nodes.acc.iter().zip(self.wacc.iter_mut()) {
            mat_vec_on(p, w, live, out);
        }
        let keys = whole.quantities.iter().copied();
        form_growth(
            w,
            (keys, &whole.integrals[i]),
            &mut self.pairs,
            &mut self.inc,
        );
    }

    /// Whether the cubic Hermite (values and rates at the ends) of each displacement meets the exact motion
    /// at the step's Gauss nodes within [`HERMITE_MISS`] of its size (what it can reach, [`Self::scale`], or
    /// more): what the screens of events and peaks read. An element's deformation, a combination of
    /// displacements, then misses by at most the same fraction of what it can reach. (Accelerations, where a
    /// foundation's fast modes ring after each kink of the record, are not checked: their peaks are
    /// screened on their own cubic through the jerks, and read at the Gauss nodes as well.)
    fn hermite_holds(&self, h: f64) -> bool {
        let Some(motion) = self.dense.motion() else {
            return true;
        };
        let holds = |value: &dyn Fn(&[f64]) -> (f64, f64), scale: f64| {
            let ((a, ra), (b, rb)) = (value(&motion.w0), value(&self.wn[0]));
            let p = crate::integrate::Hermite::new(a, b, ra, rb, h);
            let mut size = scale.max(a.abs()).max(b.abs());
            let mut worst = 0.0f64;
            for (j, node) in GAUSS_NODES.iter().enumerate() {
                let exact = value(&self.wn[j + 1]).0;
                size = size.max(exact.abs());
                worst = worst.max((p.at(*node) - exact).abs());
            }
            worst <= HERMITE_MISS * size
        };
        let n = self.mech / 2;
        let scale = &self.scale;
        (0..n).all(|i| holds(&|y| (y[i], y[n + i]), scale[i]))
    }

    /// `wn[0]` = `w` at the end of a step of length `h`, `wn[1..4]` at its Gauss nodes.
    fn propagate(&mut self, h: f64) {
        self.series_built = false;
        let (nw, mech) = (self.nw, self.mech);
        let c = &mut self.configs[self.current];
        let found = c.lengths.iter().position(|l| (l.h - h).abs() <= 1e-12 * h);
        let found = found.or_else(|| {
            // A length met again and again is a record interval's: worth its matrices.
            if (c.seen.0 - h).abs() <= 1e-12 * h {
                c.seen.1 += 1;
            } else {
                c.seen = (h, 1);
            }
            if c.seen.1 >= BUILD_AFTER {
                let phi = [
                    transition(&c.m, nw, mech, h),
                    transition(&c.m, nw, mech, GAUSS_NODES[0] * h),
                    transition(&c.m, nw, mech, GAUSS_NODES[1] * h),
                    transition(&c.m, nw, mech, GAUSS_NODES[2] * h),
                ];
                let integrals = length_integrals(c, (nw, mech), h);
                // Beyond three points' reach, the five points' rows for the integrated quantities.
                let quadrature = (integrals.is_none() && c.r * h > THREE_POINT_REACH)
                    .then(|| QUADRATURE_NODES.map(|g| transition(&c.m, nw, mech, g * h)));
                if c.lengths.len() >= LENGTHS {
                    c.lengths.remove(0);
                }
                c.lengths.push(Length {
                    h,
                    phi: Arc::new(phi),
                    integrals,
                    quadrature,
                });
                Some(c.lengths.len() - 1)
            } else {
                None
            }
        });
        self.built = None;
        match found {
            Some(i) => {
                live_of(&self.w, &mut self.live);
                // With the length's form integrals the quantities grow by them, and the nodes are read only
                // if an observer asks.
                let keys = c.forms.iter().flatten().map(|(k, _)| *k);
                let nodes = match &c.lengths[i].integrals {
                    Some(g) => {
                        form_growth(&self.w, (keys, g), &mut self.pairs, &mut self.inc);
                        self.built = Some(i);
                        1
                    }
                    None => 4,
                };
                for (p, out) in c.lengths[i].phi.iter().zip(self.wn.iter_mut()).take(nodes) {
                    mat_vec_on(p, &self.w, &self.live, &mut out[..mech]);
                }
                for (p, out) in c.lengths[i].quadrature.iter().flatten().zip(&mut self.wq) {
                    mat_vec_on(p, &self.w, &self.live, &mut out[..mech]);
                }
            }
            None => {
                let terms = terms(&mut self.terms, c.r * h);
                if c.sparse.rows() == nw {
                    c.sparse.series(&self.w, terms, &mut self.series);
                } else {
                    crate::integrate::series(&c.m, mech, &self.w, terms, &mut self.series);
                }
                self.series_built = true;
                let at = [
                    h,
                    GAUSS_NODES[0] * h,
                    GAUSS_NODES[1] * h,
                    GAUSS_NODES[2] * h,
                ];
                for (tau, out) in at.into_iter().zip(self.wn.iter_mut()) {
                    crate::integrate::series_into(&self.series, nw, tau, terms, &mut out[..mech]);
                }
                let five = (c.r * h > THREE_POINT_REACH).then_some(QUADRATURE_NODES);
                for (g, out) in five.iter().flatten().zip(&mut self.wq) {
                    crate::integrate::series_into(&self.series, nw, g * h, terms, &mut out[..mech]);
                }
            }
        }
    }

    /// Integrates the energies and states along the step from `wn` (by three-point Gauss, or on block `i` of
    /// the whole interval by its form integrals, [`Self::inc`]), sets the state at `t1` (`t0 + h` to rounding)
    /// and the dense output.
    fn finish(&mut self, sys: &System, (t0, h, t1): (f64, f64, f64), block: Option<usize>) {
        let mech = self.mech;
        let acc = self.y.len() - mech;
        self.last = h;
        let motion_config = self.current;
        let same_matrix = self.dense_config == Some(motion_config);
        let Some((dt0, dh, motion)) = self.dense.motion_mut() else {
            return;
        };
        // Where the last step's observers sampled its motion: offsets worth rows of their own.
        let slack = 16.0 * f64::EPSILON * (t0.abs() + h);
        motion.take_asked(&mut self.asked);
        if let Some(c) = self.dense_config.map(|p| &mut self.configs[p]) {
            for &(tau, n) in &self.asked {
                if let Some(k) = c.ask(tau, n, slack, self.nw, mech) {
                    if same_matrix {
                        motion.add_offset(c.offsets[k].0, &c.offsets[k].1);
                    }
                }
            }
        }
        *dt0 = t0;
        *dh = h;
        let config = &self.configs[motion_config];
        if !same_matrix {
            motion.set_matrix(&config.m);
            motion.clear_offsets();
            for (tau, phi) in &config.offsets {
                motion.add_offset(*tau, phi);
            }
        }
        motion.set_start(&self.w);
        motion.acc0.copy_from_slice(&self.y[mech..]);
        motion.rates[0].copy_from_slice(&self.dydt);
        let whole = block.and_then(|i| Some((i, config.whole.as_ref()?)));
        let piece = whole.map_or(h, |(_, w)| w.piece());
        motion.terms = terms(&mut self.terms, config.r * piece);
        // Observers that read the last step's integrated quantities inside it (histories) will read this
        // one's: its nodes are read now, where it costs least.
        let integrals_read = motion.integrals_read();
        motion.invalidate();
        let series = std::mem::take(&mut self.series_built) && block.is_none();
        if series {
            motion.adopt_series(&self.series);
        }
        self.dense_config = Some(motion_config);
        motion.w1.copy_from_slice(&self.wn[0][..mech]);
        self.ynode.copy_from_slice(&self.y);
        // A built length with form integrals, or a step of one series whose rates are forms: its nodes,
        // unread, are found only if an observer asks (the same numbers whatever the observers read).
        let grown = block.is_some() || self.built.is_some();
        // Beyond three points' reach, integrated by five ([`Self::wq`]) and the quartic bent to meet them.
        let bend = block.is_none() && config.r * h > THREE_POINT_REACH;
        let five = bend && !grown;
        let unread = unread_nodes(config, (block, self.built), series && five, integrals_read);
        if grown {
            // Grown by the form integrals over the block or the length ([`Self::propagate_block`],
            // [`Self::propagate`]).
            for (y, inc) in self.y[mech..].iter_mut().zip(&self.inc) {
                *y += inc;
            }
        }
        if let Some((i, w)) = whole {
            motion.chained(
                (1 << i, piece),
                &w.jumps,
                (&w.probe_keys, &w.probe_rows, Some(&w.jerks)),
                self.chain_config != Some(motion_config),
                &self.y[mech..],
            );
            self.chain_config = Some(motion_config);
        }
        let read = unread.is_none();
        let held = matches!(&unread, Some(u) if matches!(u.source, NodeSource::Held));
        motion.set_nodes_unread(unread);
        if held {
            motion.hold_nodes([&self.wn[1], &self.wn[2], &self.wn[3]]);
        }
        for (j, node) in GAUSS_NODES.iter().enumerate().filter(|_| read) {
            if let (Some(_), Some(rates)) = (block, config.rates.as_deref()) {
                // A block's motion rates come from its rows below: the integrated quantities' only.
                let w = (&self.w[..], mech, self.lines.len());
                full_w_at(&self.wn[j + 1], w, node * h, &mut self.wfull);
                rates.write_integrated(&self.wfull, &mut motion.rates[j + 1][mech..]);
                continue;
            }
            let at = (&self.w[..], &self.wn[j + 1][..], self.lines.len());
            let room = (&mut self.wfull[..], &mut self.ynode[..]);
            let rates = config.rates.as_deref();
            rate_at(
                sys,
                rates,
                at,
                (t0, node * h),
                room,
                &mut motion.rates[j + 1],
            );
        }
        if block.is_some() {
            // The accelerations by their rows, read or held alike (a history does not move a peak).
            block_node_rates(motion, &self.wn, &self.wacc, mech / 2);
        }
        if whole.is_none() {
            if !grown && !five {
                for k in 0..acc {
                    let inc: f64 = (0..3)
                        .map(|j| GAUSS_WEIGHTS[j] * motion.rates[j + 1][mech + k])
                        .sum();
                    self.y[mech + k] += h * inc;
                }
            }
            if five {
                // The three nodes' rates serve the quartic inside the step, bent to meet this at its end.
                let room = (
                    &mut self.wfull[..],
                    &mut self.ynode[..],
                    &mut self.dynode[..],
                );
                let motion_at = (&self.w[..], &self.wq, self.lines.len());
                let rates = config.rates.as_deref();
                five_point_growth(sys, rates, motion_at, (t0, h), room, &mut self.inc);
                for (y, inc) in self.y[mech..].iter_mut().zip(&self.inc) {
                    *y += h * inc;
                }
            }
            motion.single(bend.then_some(&self.y[mech..]));
        }
        self.y[..mech].copy_from_slice(&self.wn[0][..mech]);
        self.t = t1;
        match &config.rates {
            Some(rates) => {
                full_w_at(
                    &self.wn[0],
                    (&self.w, mech, self.lines.len()),
                    h,
                    &mut self.wfull,
                );
                rates.write(&self.wfull, &mut self.dydt);
            }
            None => sys.rhs_in(t1, forcing(&self.w, mech, h), &self.y, &mut self.dydt),
        }
        motion.rates[4].copy_from_slice(&self.dydt);
        motion.set_jerks(self.lines.len());
    }

    /// The state at `t` inside the last step, its integrated quantities by three-point Gauss–Legendre
    /// along the exact motion from the step's start, piece by piece on a whole interval taken at once
    /// (what an event carries on with).
    pub fn state_at(&mut self, sys: &System, t: f64, out: &mut [f64]) {
        let mech = self.mech;
        let Some(motion) = self.dense.motion() else {
            return;
        };
        let t0 = self.dense.t0();
        let tau = t - t0;
        let r = self
            .dense_config
            .map_or(f64::INFINITY, |c| self.configs[c].r);
        motion.on_series(tau, &mut out[..mech]);
        self.scratch.copy_from_slice(&self.y);
        let acc = out.len() - mech;
        out[mech..].copy_from_slice(&motion.acc0);
        let (pieces, piece) = match motion.pieces() {
            1 => (1, tau),
            _ => (
                (tau / motion.piece()).ceil().max(1.0) as usize,
                motion.piece(),
            ),
        };
        for p in 0..pieces {
            let a = p as f64 * piece;
            let len = (tau - a).min(piece);
            let (nodes, weights) = quadrature(r * len);
            for (node, weight) in nodes.iter().zip(weights) {
                let s = a + node * len;
                motion.on_series(s, &mut self.scratch[..mech]);
                sys.rhs_in(
                    t0 + s,
                    forcing(&motion.w0, mech, s),
                    &self.scratch,
                    &mut self.dynode,
                );
                for k in 0..acc {
                    out[mech + k] += len * weight * self.dynode[mech + k];
                }
            }
        }
    }
}
