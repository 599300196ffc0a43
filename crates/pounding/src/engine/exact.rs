//! Exact propagation between events while every law is affine ([`super::linear`]).
//!
//! Each record interval (the ground's acceleration is linear on it) is split into equal steps short enough
//! for the truncated Taylor series of `exp(M h)` to be exact to rounding ([`crate::integrate::MAX_RHO`]);
//! the transition matrices of a configuration (keyed by its laws' stiffnesses and viscous coefficients) and
//! step length are built once and kept, a few configurations at a time. The energies and the laws' own
//! integrated states (a contact's work) are integrated along the exact motion by three-point
//! Gauss–Legendre quadrature. Events are located on the exact motion ([`crate::integrate::Motion`]).

use super::linear::{channel_at, forcing};
use super::System;
use crate::integrate::{
    mat_vec, step_bound, transition, Dense, Motion, OdeSystem, GAUSS_NODES, GAUSS_WEIGHTS, MAX_RHO,
    OFFSETS, TERMS,
};

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

/// The transition matrices of one step length: to its end and to its three Gauss nodes.
#[derive(Debug)]
struct Length {
    h: f64,
    phi: [Vec<f64>; 4],
}

#[derive(Debug)]
struct Configuration {
    key: Vec<u64>,
    m: Vec<f64>,
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
        self.offsets.push((tau, transition(&self.m, nw, mech, tau)));
        Some(self.offsets.len() - 1)
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
    scratch: Vec<f64>,
    series: Vec<f64>,
    ynode: Vec<f64>,
    dynode: Vec<f64>,
    /// Offsets the last step's observers asked of its motion (room for [`OFFSETS`]).
    asked: Vec<(f64, usize)>,
    /// The configuration whose matrix the dense output holds.
    dense_config: Option<usize>,
    steps: usize,
    last: f64,
    /// The record's time step, s (the shortest of supports' records; infinite under a constant
    /// acceleration).
    interval: f64,
    /// Each ground channel's acceleration and slope on the current interval (`[g_0, s_0, g_1, s_1, ...]`).
    lines: Vec<f64>,
}

impl Exact {
    /// A stepper for `sys`, or `None` when its `w` is too large to pay ([`MAX_EXACT_DIM`]).
    pub fn new(sys: &System) -> Option<Self> {
        let nw = sys.linear_dim();
        if nw > MAX_EXACT_DIM {
            return None;
        }
        let dim = sys.dim();
        let mech = 2 * sys.layout().dofs();
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
            scratch: vec![0.0; dim],
            series: vec![0.0; TERMS * nw],
            ynode: vec![0.0; dim],
            dynode: vec![0.0; dim],
            asked: Vec::with_capacity(OFFSETS),
            dense_config: None,
            steps: 0,
            last: 0.0,
            interval: match sys.ground() {
                super::Ground::Record(r) | super::Ground::Plane { x: r, .. } => r.dt(),
                // The kinks of all the records: intervals no longer than the shortest step.
                super::Ground::Many(rs) => rs.iter().map(|r| r.dt()).fold(f64::INFINITY, f64::min),
                super::Ground::Constant(_) => f64::INFINITY,
            },
            lines: vec![0.0; sys.forcing_dim()],
        })
    }

    /// Starts at `(t0, y0)` if the system's laws are all affine now; `false` otherwise.
    pub fn reset(&mut self, sys: &System, t0: f64, y0: &[f64]) -> bool {
        if !sys.linear_now(&mut self.key, &mut self.f0) {
            return false;
        }
        self.current = match self.configs.iter().position(|c| c.key == self.key) {
            Some(i) => i,
            None => {
                let m = sys.linear_matrix();
                let config = Configuration {
                    key: self.key.clone(),
                    r: step_bound(&m, self.nw, sys.layout().dofs()),
                    m,
                    lengths: Vec::new(),
                    seen: (f64::NAN, 0),
                    uses: 0,
                    offsets: Vec::new(),
                    asked: Vec::with_capacity(OFFSETS),
                };
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
                    self.configs[i] = config;
                    i
                }
            }
        };
        let steps = (self.configs[self.current].r * self.interval / MAX_RHO).ceil();
        if steps * (self.mech * self.nw) as f64 > MAX_INTERVAL_WORK {
            return false;
        }
        self.t = t0;
        self.y.copy_from_slice(y0);
        sys.rhs(t0, y0, &mut self.dydt);
        true
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
    /// `[t, t_stop]` (the driver stops at its kinks).
    pub fn step_until(&mut self, sys: &System, t_stop: f64) {
        let h = self.length(t_stop);
        let t0 = self.t;
        self.configs[self.current].uses += 1;
        // Each ground channel's acceleration on the interval, read inside it (a record's end is a jump).
        let ground = sys.ground();
        let (ta, tb) = (t0 + 0.25 * h, t0 + 0.75 * h);
        for (c, line) in self.lines.chunks_exact_mut(2).enumerate() {
            let (ga, gb) = (channel_at(ground, c, ta), channel_at(ground, c, tb));
            let slope = (gb - ga) / (tb - ta);
            line.copy_from_slice(&[ga - slope * (ta - t0), slope]);
        }
        sys.linear_state(&self.y, &self.lines, &self.f0, &mut self.w);
        self.propagate(h);
        self.last = h;
        let t1 = if (t_stop - (t0 + h)).abs() <= 1e-12 * h {
            t_stop
        } else {
            t0 + h
        };
        self.finish(sys, t0, h, t1);
        self.steps += 1;
    }

    /// `wn[0]` = `w` at the end of a step of length `h`, `wn[1..4]` at its Gauss nodes.
    fn propagate(&mut self, h: f64) {
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
                if c.lengths.len() >= LENGTHS {
                    c.lengths.remove(0);
                }
                c.lengths.push(Length { h, phi });
                Some(c.lengths.len() - 1)
            } else {
                None
            }
        });
        match found {
            Some(i) => {
                for (p, out) in c.lengths[i].phi.iter().zip(self.wn.iter_mut()) {
                    mat_vec(p, &self.w, &mut out[..mech]);
                }
            }
            None => {
                let terms = crate::integrate::terms_for(c.r * h);
                crate::integrate::series(&c.m, mech, &self.w, terms, &mut self.series);
                let at = [
                    h,
                    GAUSS_NODES[0] * h,
                    GAUSS_NODES[1] * h,
                    GAUSS_NODES[2] * h,
                ];
                for (tau, out) in at.into_iter().zip(self.wn.iter_mut()) {
                    for (i, o) in out[..mech].iter_mut().enumerate() {
                        *o = crate::integrate::series_at(&self.series, nw, i, tau, terms);
                    }
                }
            }
        }
    }

    /// Integrates the energies and states along the step from `wn`, sets the state at `t1 = t0 + h` and
    /// the dense output.
    fn finish(&mut self, sys: &System, t0: f64, h: f64, t1: f64) {
        let mech = self.mech;
        let acc = self.y.len() - mech;
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
        if !same_matrix {
            motion.m.copy_from_slice(&self.configs[motion_config].m);
            motion.clear_offsets();
            for (tau, phi) in &self.configs[motion_config].offsets {
                motion.add_offset(*tau, phi);
            }
        }
        motion.w0.copy_from_slice(&self.w);
        motion.acc0.copy_from_slice(&self.y[mech..]);
        motion.rates[0].copy_from_slice(&self.dydt);
        motion.terms = crate::integrate::terms_for(self.configs[motion_config].r * h);
        motion.invalidate();
        self.dense_config = Some(motion_config);
        motion.w1.copy_from_slice(&self.wn[0][..mech]);
        self.ynode.copy_from_slice(&self.y);
        for (j, node) in GAUSS_NODES.iter().enumerate() {
            self.ynode[..mech].copy_from_slice(&self.wn[j + 1][..mech]);
            let tau = node * h;
            sys.rhs_in(
                t0 + tau,
                forcing(&self.w, mech, tau),
                &self.ynode,
                &mut self.dynode,
            );
            motion.rates[j + 1].copy_from_slice(&self.dynode);
        }
        for k in 0..acc {
            let inc: f64 = (0..3)
                .map(|j| GAUSS_WEIGHTS[j] * motion.rates[j + 1][mech + k])
                .sum();
            self.y[mech + k] += h * inc;
        }
        self.y[..mech].copy_from_slice(&self.wn[0][..mech]);
        self.t = t1;
        sys.rhs_in(t1, forcing(&self.w, mech, h), &self.y, &mut self.dydt);
        motion.rates[4].copy_from_slice(&self.dydt);
        // The jerks: the velocities' rows of M on the rates (the forcing's rates are its slopes).
        let (nw, n, fd) = (self.nw, mech / 2, self.lines.len());
        let m = &motion.m;
        for (end, rates) in [0, 4].into_iter().enumerate() {
            for i in 0..n {
                let row = &m[(n + i) * nw..(n + i + 1) * nw];
                let mut j: f64 = (0..mech).map(|l| row[l] * motion.rates[rates][l]).sum();
                j += (0..fd)
                    .step_by(2)
                    .map(|c| row[mech + c] * motion.w0[mech + c + 1])
                    .sum::<f64>();
                motion.jerk[end][i] = j;
            }
        }
    }

    /// The state at `t` inside the last step, its integrated quantities by three-point Gauss–Legendre
    /// along the exact motion from the step's start (what an event carries on with).
    pub fn state_at(&mut self, sys: &System, t: f64, out: &mut [f64]) {
        let mech = self.mech;
        let Some(motion) = self.dense.motion() else {
            return;
        };
        let t0 = self.dense.t0();
        let tau = t - t0;
        let nw = self.nw;
        motion.with_series(|c| {
            self.scratch.copy_from_slice(&self.y);
            for (i, o) in out[..mech].iter_mut().enumerate() {
                *o = crate::integrate::series_at(c, nw, i, tau, motion.terms);
            }
            let acc = out.len() - mech;
            out[mech..].copy_from_slice(&motion.acc0);
            for (j, node) in GAUSS_NODES.iter().enumerate() {
                let s = node * tau;
                for (i, x) in self.scratch[..mech].iter_mut().enumerate() {
                    *x = crate::integrate::series_at(c, nw, i, s, motion.terms);
                }
                sys.rhs_in(
                    t0 + s,
                    forcing(&motion.w0, mech, s),
                    &self.scratch,
                    &mut self.dynode,
                );
                for k in 0..acc {
                    out[mech + k] += tau * GAUSS_WEIGHTS[j] * self.dynode[mech + k];
                }
            }
        });
    }
}
