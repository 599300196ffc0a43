//! Time stepping with event location.
//!
//! [`DormandPrince`] is the explicit Runge–Kutta pair of Dormand & Prince (1980), order 5 with an embedded
//! order-4 error estimate and the continuous extension of Hairer, Nørsett & Wanner (*Solving Ordinary
//! Differential Equations I*, 2nd ed., section II.6), so that events (touch, zero force, separation) are
//! located on the interpolant with [`brent_root`] instead of at a time step. The stepper only takes steps;
//! drivers (for example [`crate::impact`]) decide what happens at an event, in the spirit of a
//! stepper/driver split.
//!
//! Units follow the system being integrated; the stepper is unit-agnostic.

mod exact;
mod interval;
pub(crate) mod lu;
mod memo;
mod peaks;
mod roots;
mod rosenbrock;
mod switching;

pub use exact::{
    dot, live_of, mat_vec, mat_vec_on, quadrature, series, series_at, series_into, step_bound,
    terms_for, transition, IntegratedRates, JerkRows, Motion, NodeSource, Sparse, UnreadNodes,
    GAUSS_NODES, GAUSS_WEIGHTS, MAX_RHO, OFFSETS, QUADRATURE_NODES, QUADRATURE_WEIGHTS, TERMS,
    THREE_POINT_REACH,
};
pub use interval::{
    exponential, form_blocks, functional_at_pieces, halvings, mat_mul, times_transition,
    transition_rows, Block,
};
pub use peaks::{hermite_peak, Hermite, PeakTracker, Piece};
pub use roots::{brent_root, golden_max, quadratic_roots};
pub use rosenbrock::Rosenbrock;
pub use switching::Stepper;

use crate::Error;

/// A first-order system `y' = f(t, y)`.
pub trait OdeSystem {
    /// Number of state components.
    fn dim(&self) -> usize;
    /// Writes `f(t, y)` into `dydt`.
    fn rhs(&self, t: f64, y: &[f64], dydt: &mut [f64]);
}

// Dormand–Prince 5(4) tableau.
const C2: f64 = 1.0 / 5.0;
const C3: f64 = 3.0 / 10.0;
const C4: f64 = 4.0 / 5.0;
const C5: f64 = 8.0 / 9.0;
const A21: f64 = 1.0 / 5.0;
const A31: f64 = 3.0 / 40.0;
const A32: f64 = 9.0 / 40.0;
const A41: f64 = 44.0 / 45.0;
const A42: f64 = -56.0 / 15.0;
const A43: f64 = 32.0 / 9.0;
const A51: f64 = 19372.0 / 6561.0;
const A52: f64 = -25360.0 / 2187.0;
const A53: f64 = 64448.0 / 6561.0;
const A54: f64 = -212.0 / 729.0;
const A61: f64 = 9017.0 / 3168.0;
const A62: f64 = -355.0 / 33.0;
const A63: f64 = 46732.0 / 5247.0;
const A64: f64 = 49.0 / 176.0;
const A65: f64 = -5103.0 / 18656.0;
const A71: f64 = 35.0 / 384.0;
const A73: f64 = 500.0 / 1113.0;
const A74: f64 = 125.0 / 192.0;
const A75: f64 = -2187.0 / 6784.0;
const A76: f64 = 11.0 / 84.0;
// Difference between the order-5 and order-4 weights.
const E1: f64 = 71.0 / 57600.0;
const E3: f64 = -71.0 / 16695.0;
const E4: f64 = 71.0 / 1920.0;
const E5: f64 = -17253.0 / 339200.0;
const E6: f64 = 22.0 / 525.0;
const E7: f64 = -1.0 / 40.0;
// Continuous extension (Hairer's DOPRI5 dense output).
const D1: f64 = -12715105075.0 / 11282082432.0;
const D3: f64 = 87487479700.0 / 32700410799.0;
const D4: f64 = -10690763975.0 / 1880347072.0;
const D5: f64 = 701980252875.0 / 199316789632.0;
const D6: f64 = -1453857185.0 / 822651844.0;
const D7: f64 = 69997945.0 / 29380423.0;

/// The motion on one accepted step, valid on `[t0, t0 + h]`: the quartic interpolant of a Runge–Kutta step
/// (order 4, exact at both ends), or the exact motion of a step propagated exactly ([`Motion`]).
#[derive(Clone, Debug, Default)]
pub struct Dense {
    t0: f64,
    h: f64,
    r: [Vec<f64>; 5],
    exact: Option<Box<Motion>>,
}

impl Dense {
    /// An empty interpolant for `n` components (to copy steps into without allocating).
    pub fn zeros(n: usize) -> Self {
        Self {
            t0: 0.0,
            h: 0.0,
            r: std::array::from_fn(|_| vec![0.0; n]),
            exact: None,
        }
    }

    /// An exact motion (see [`Motion`]) on `[t0, t0 + h]`.
    pub fn exact(motion: Motion) -> Self {
        Self {
            t0: 0.0,
            h: 0.0,
            r: std::array::from_fn(|_| Vec::new()),
            exact: Some(Box::new(motion)),
        }
    }

    /// The exact motion and its span, to set for a new step.
    pub fn motion_mut(&mut self) -> Option<(&mut f64, &mut f64, &mut Motion)> {
        let Self { t0, h, exact, .. } = self;
        exact.as_deref_mut().map(|m| (t0, h, m))
    }

    /// The exact motion, if the step was propagated exactly.
    pub fn motion(&self) -> Option<&Motion> {
        self.exact.as_deref()
    }

    /// How far apart two offsets into the step may be and still name one time, s: a few roundings of the
    /// times involved.
    fn slack(&self) -> f64 {
        16.0 * f64::EPSILON * (self.t0.abs() + self.h)
    }

    /// Start time of the step.
    pub fn t0(&self) -> f64 {
        self.t0
    }

    /// End time of the step.
    pub fn t1(&self) -> f64 {
        self.t0 + self.h
    }

    /// Writes the interpolated state at time `t` (in the step) into `out`.
    pub fn eval(&self, t: f64, out: &mut [f64]) {
        if let Some(m) = &self.exact {
            let tau = t - self.t0;
            let mech = m.mech.min(out.len());
            m.motion_at(tau, self.h, self.slack(), &mut out[..mech], true);
            // Past the motion (not when only a prefix of it is asked): the integrated quantities.
            if mech == m.mech {
                m.integrated_into(tau, self.h, &mut out[mech..]);
            }
            return;
        }
        let th = if self.h == 0.0 {
            0.0
        } else {
            (t - self.t0) / self.h
        };
        let th1 = 1.0 - th;
        for (i, o) in out.iter_mut().enumerate() {
            *o = self.r[0][i]
                + th * (self.r[1][i]
                    + th1 * (self.r[2][i] + th * (self.r[3][i] + th1 * self.r[4][i])));
        }
    }

    /// On a step propagated exactly, the accelerations (m/s^2 or rad/s^2, relative to the ground) of the
    /// first `out.len()` degrees of freedom at `t`, given the displacements and velocities there (`motion`,
    /// as [`Self::eval`] wrote them): off the configuration's matrix ([`Motion::accelerations_at`]), not the
    /// laws. `false`, with nothing written, on a Runge–Kutta step.
    pub fn accelerations(&self, t: f64, motion: &[f64], out: &mut [f64]) -> bool {
        match &self.exact {
            Some(m) => {
                m.accelerations_at(t - self.t0, motion, out);
                true
            }
            None => false,
        }
    }

    /// The interpolant of component `i` of a Runge–Kutta step as a polynomial in `theta = (t - t0) / h`:
    /// its coefficients of `theta^0 .. theta^4`; `None` on a step propagated exactly.
    pub fn quartic(&self, i: usize) -> Option<[f64; 5]> {
        if self.exact.is_some() {
            return None;
        }
        // r0 + th r1 + th (1 - th) r2 + th^2 (1 - th) r3 + th^2 (1 - th)^2 r4, expanded.
        let r = |k: usize| self.r[k][i];
        Some([
            r(0),
            r(1) + r(2),
            r(3) + r(4) - r(2),
            -r(3) - 2.0 * r(4),
            r(4),
        ])
    }

    /// Interpolated component `i` at time `t` (in the step): the cheap form of [`Self::eval`] when only a
    /// few components are needed.
    #[inline]
    pub fn component(&self, t: f64, i: usize) -> f64 {
        if let Some(m) = &self.exact {
            return m.component(t - self.t0, self.h, i);
        }
        let th = if self.h == 0.0 {
            0.0
        } else {
            (t - self.t0) / self.h
        };
        let th1 = 1.0 - th;
        self.r[0][i]
            + th * (self.r[1][i] + th1 * (self.r[2][i] + th * (self.r[3][i] + th1 * self.r[4][i])))
    }

    /// Writes the first `out.len()` components at `t` (the motion only, for an exact step: cheaper than
    /// [`Self::eval`] when the integrated quantities are not needed).
    pub fn eval_prefix(&self, t: f64, out: &mut [f64]) {
        match &self.exact {
            Some(m) => m.motion_at(t - self.t0, self.h, self.slack(), out, false),
            None => self.eval(t, out),
        }
    }

    /// The interpolant of `u_a - u_b` (a missing index stands for 0), kept after the stepper has moved on.
    pub fn difference(&self, a: Option<usize>, b: Option<usize>) -> DenseComponent {
        let mut terms = [(0, 0.0); 2];
        let mut len = 0;
        for (i, c) in [(a, 1.0), (b, -1.0)] {
            if let Some(i) = i {
                terms[len] = (i, c);
                len += 1;
            }
        }
        self.combination(&terms[..len])
    }

    /// The interpolant of `sum c u_i` over `terms` `(i, c)` (an empty list: 0), kept after the stepper has
    /// moved on. Only components of the motion (displacements and velocities) for an exact step.
    pub fn combination(&self, terms: &[(usize, f64)]) -> DenseComponent {
        if let Some(m) = &self.exact {
            let nw = m.w0.len();
            return m.with_series(|c| DenseComponent::Series {
                t0: self.t0,
                c: std::array::from_fn(|k| terms.iter().map(|&(i, w)| w * c[k * nw + i]).sum()),
            });
        }
        DenseComponent::Quartic {
            t0: self.t0,
            h: self.h,
            r: std::array::from_fn(|k| terms.iter().map(|&(i, c)| c * self.r[k][i]).sum()),
        }
    }
}

/// One scalar of an interpolant (see [`Dense::difference`]), valid on the step it came from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum DenseComponent {
    /// A Runge–Kutta step's quartic.
    Quartic {
        /// Start of the step, s.
        t0: f64,
        /// Its length, s.
        h: f64,
        /// Coefficients in Hairer's form.
        r: [f64; 5],
    },
    /// An exact step's Taylor series in `t - t0`.
    Series {
        /// Start of the step, s.
        t0: f64,
        /// Coefficients of the powers 0 to `TERMS - 1`.
        c: [f64; TERMS],
    },
}

impl Default for DenseComponent {
    fn default() -> Self {
        DenseComponent::Quartic {
            t0: 0.0,
            h: 0.0,
            r: [0.0; 5],
        }
    }
}

impl std::ops::Sub for DenseComponent {
    type Output = DenseComponent;
    /// The difference of two scalars of one step's interpolant.
    fn sub(self, o: DenseComponent) -> DenseComponent {
        match (self, o) {
            (DenseComponent::Quartic { t0, h, r }, DenseComponent::Quartic { r: q, .. }) => {
                DenseComponent::Quartic {
                    t0,
                    h,
                    r: std::array::from_fn(|k| r[k] - q[k]),
                }
            }
            (DenseComponent::Series { t0, c }, DenseComponent::Series { c: q, .. }) => {
                DenseComponent::Series {
                    t0,
                    c: std::array::from_fn(|k| c[k] - q[k]),
                }
            }
            // Scalars of one step are of one kind.
            (a, _) => a,
        }
    }
}

impl DenseComponent {
    /// The value at `t`.
    #[inline]
    pub fn eval(&self, t: f64) -> f64 {
        match self {
            DenseComponent::Quartic { t0, h, r } => {
                let th = if *h == 0.0 { 0.0 } else { (t - t0) / h };
                let th1 = 1.0 - th;
                r[0] + th * (r[1] + th1 * (r[2] + th * (r[3] + th1 * r[4])))
            }
            DenseComponent::Series { t0, c } => horner(c, t - t0),
        }
    }
}

/// The seven stages' rates of a Dormand–Prince step, each as a slice of the state's length `n`: indexed
/// without bounds checks in the step's loops.
fn stages(k: &[Vec<f64>; 7], n: usize) -> [&[f64]; 7] {
    std::array::from_fn(|j| &k[j][..n])
}

/// `sum_k c[k] d^k` (`c` from the constant term up) by Horner's rule.
#[inline]
pub fn horner(c: &[f64], d: f64) -> f64 {
    c.iter().rev().fold(0.0, |acc, &x| acc * d + x)
}

/// The coefficients of the derivative of the polynomial `sum_k c[k] d^k` (a series' rate): `(k + 1)
/// c[k + 1]`, the last 0.
#[inline]
pub fn derivative(c: &[f64; TERMS]) -> [f64; TERMS] {
    std::array::from_fn(|k| c.get(k + 1).map_or(0.0, |x| (k + 1) as f64 * x))
}

/// Accuracy settings of [`DormandPrince`]: a step is accepted when the weighted RMS of the local error,
/// with weight `atol_i + rtol * |y_i|`, is at most 1.
#[derive(Clone, Debug)]
pub struct Tolerance {
    /// Relative tolerance (dimensionless).
    pub rtol: f64,
    /// Absolute tolerance of each component, in that component's unit; an infinite value leaves the
    /// component out of the error control (a bookkeeping integral nobody reads).
    pub atol: Vec<f64>,
    /// Components that count in the error norm only in a step where they are not identically zero (the
    /// translation across and the rotation of a symmetric plan shaken along its axis stay exactly 0;
    /// counting them would dilute the norm, and the same motion would take other steps than in one line).
    pub quiet: Vec<usize>,
    /// Components held to their absolute tolerance alone: works accumulated over a whole run (J), whose
    /// weight `rtol |y|` would loosen as the run goes on (a contact's work after 40 impacts was held to 40
    /// times what the first impact's was).
    pub absolute: Vec<usize>,
}

impl Tolerance {
    /// `rtol` and `atol`, with no quiet components.
    pub fn new(rtol: f64, atol: Vec<f64>) -> Self {
        Self {
            rtol,
            atol,
            quiet: Vec::new(),
            absolute: Vec::new(),
        }
    }

    /// The relative tolerance of each component: `rtol`, or 0 for the absolute ones.
    pub(crate) fn relative(&self) -> Vec<f64> {
        let mut rel = vec![self.rtol; self.atol.len()];
        for &i in &self.absolute {
            rel[i] = 0.0;
        }
        rel
    }

    /// The number of controlled components, less the quiet ones that are identically zero in a step that
    /// starts at `y` with stage derivatives `k` (each zero at a silent component).
    #[inline]
    pub(crate) fn counted(&self, controlled: usize, y: &[f64], k: &[&[f64]]) -> usize {
        let silent = self
            .quiet
            .iter()
            .filter(|&&i| self.atol[i].is_finite() && y[i] == 0.0 && k.iter().all(|k| k[i] == 0.0))
            .count();
        (controlled - silent).max(1)
    }
}

/// An adaptive Dormand–Prince 5(4) stepper with dense output. Working memory is allocated once, in
/// [`DormandPrince::new`]; stepping allocates nothing.
#[derive(Debug)]
pub struct DormandPrince {
    n: usize,
    /// Number of components under error control.
    controlled: usize,
    tol: Tolerance,
    /// Each component's relative tolerance ([`Tolerance::relative`]).
    rel: Vec<f64>,
    t: f64,
    h: f64,
    y: Vec<f64>,
    ynew: Vec<f64>,
    ytmp: Vec<f64>,
    k: [Vec<f64>; 7],
    dense: Dense,
    /// Largest step allowed (in the time unit of the system).
    pub h_max: f64,
    rejected: usize,
    accepted: usize,
    /// Accepted steps at the edge of stability since the last run of calm ones (Hairer's stiffness test).
    stiff_steps: usize,
    calm_steps: usize,
}

/// `h |lambda|` above which a Dormand–Prince step is at its stability limit (the boundary of its stability
/// region on the negative real axis is about 3.3): Hairer & Wanner, *Solving Ordinary Differential Equations
/// II*, section IV.2, and their DOPRI5 code.
const STIFF_H_LAMBDA: f64 = 3.25;
/// Steps at the stability limit that make a stretch stiff, and calm steps that clear the count (as DOPRI5).
const STIFF_STEPS: usize = 15;
const CALM_STEPS: usize = 6;

impl DormandPrince {
    /// A stepper for a system of `tol.atol.len()` components.
    pub fn new(tol: Tolerance) -> Self {
        let n = tol.atol.len();
        let controlled = tol.atol.iter().filter(|a| a.is_finite()).count().max(1);
        Self {
            n,
            controlled,
            rel: tol.relative(),
            tol,
            t: 0.0,
            h: 0.0,
            y: vec![0.0; n],
            ynew: vec![0.0; n],
            ytmp: vec![0.0; n],
            k: std::array::from_fn(|_| vec![0.0; n]),
            dense: Dense::zeros(n),
            h_max: f64::INFINITY,
            rejected: 0,
            accepted: 0,
            stiff_steps: 0,
            calm_steps: 0,
        }
    }

    /// Whether the last steps were held to their size by stability rather than accuracy: 15 accepted steps
    /// with `h |lambda|` above 3.25, `|lambda|` estimated from the last two stages of each step (both at the
    /// step's end), with no 6 calm steps between them.
    pub fn looks_stiff(&self) -> bool {
        self.stiff_steps >= STIFF_STEPS
    }

    /// Forgets the steps counted by [`Self::looks_stiff`].
    pub fn clear_stiffness(&mut self) {
        self.stiff_steps = 0;
        self.calm_steps = 0;
    }

    /// Counts the accepted step of size `h` for [`Self::looks_stiff`]: `k[5]` and `k[6]` are `f` at the step's
    /// end from the last stage's state (`ytmp`) and from the new state, so their difference over that of
    /// the states is `|lambda|` of the direction they differ in; norms weighted like the error.
    fn count_stiffness(&mut self, h: f64) {
        let (mut num, mut den) = (0.0, 0.0);
        for i in 0..self.n {
            let sc = self.tol.atol[i] + self.rel[i] * self.ynew[i].abs();
            if sc.is_finite() {
                num += ((self.k[6][i] - self.k[5][i]) / sc).powi(2);
                den += ((self.ynew[i] - self.ytmp[i]) / sc).powi(2);
            }
        }
        if den > 0.0 && h * (num / den).sqrt() > STIFF_H_LAMBDA {
            self.stiff_steps += 1;
            self.calm_steps = 0;
        } else {
            self.calm_steps += 1;
            if self.calm_steps >= CALM_STEPS {
                self.stiff_steps = 0;
            }
        }
    }

    /// (Re)starts integration at `(t0, y0)` with first trial step `h0`. Call after every event that
    /// changes the right-hand side, so that no step straddles a discontinuity.
    pub fn reset<S: OdeSystem>(&mut self, sys: &S, t0: f64, y0: &[f64], h0: f64) {
        self.t = t0;
        self.y.copy_from_slice(y0);
        self.h = h0.min(self.h_max);
        sys.rhs(t0, &self.y, &mut self.k[0]);
    }

    /// Restarts at the start `(t0, y0)` of the last accepted step with first trial step `h0`, as
    /// [`Self::reset`] would, but keeping the rate there that the step began with (first-same-as-last left
    /// it in the seventh stage): one evaluation of the right-hand side fewer when a step is taken again
    /// (an event's, [`crate::engine`]'s settling). `false`, with nothing done, when the last accepted step
    /// did not start at `(t0, y0)`.
    pub fn restart_last(&mut self, t0: f64, y0: &[f64], h0: f64) -> bool {
        if self.accepted == 0 || self.dense.t0 != t0 || self.dense.r[0] != y0 {
            return false;
        }
        self.k.swap(0, 6);
        self.t = t0;
        self.y.copy_from_slice(y0);
        self.h = h0.min(self.h_max);
        true
    }

    /// Current time.
    pub fn t(&self) -> f64 {
        self.t
    }

    /// Current state.
    pub fn y(&self) -> &[f64] {
        &self.y
    }

    /// Trial size of the next step.
    pub fn h(&self) -> f64 {
        self.h
    }

    /// Time derivative `f(t, y)` of the current state (after a reset, or at the end of the last step).
    pub fn dydt(&self) -> &[f64] {
        &self.k[0]
    }

    /// The interpolant of the last accepted step.
    pub fn dense(&self) -> &Dense {
        &self.dense
    }

    /// Number of accepted and rejected steps since construction.
    pub fn counts(&self) -> (usize, usize) {
        (self.accepted, self.rejected)
    }

    fn stage<S: OdeSystem>(&mut self, sys: &S, t: f64, h: f64, a: &[(usize, f64)], out: usize) {
        // `y + h sum_j a_j k_j`, summed stage by stage over whole vectors (no bounds checks inside; the same
        // additions in the same order as element by element).
        let n = self.n;
        let ytmp = &mut self.ytmp[..n];
        ytmp.fill(0.0);
        for &(j, aj) in a {
            for (s, &kj) in ytmp.iter_mut().zip(&self.k[j][..n]) {
                *s += aj * kj;
            }
        }
        for (s, &yi) in ytmp.iter_mut().zip(&self.y[..n]) {
            *s = yi + h * *s;
        }
        let (ytmp, k) = (&self.ytmp, &mut self.k);
        sys.rhs(t, ytmp, &mut k[out]);
    }

    /// Takes one accepted step (retrying with smaller steps as needed). Afterwards [`Self::t`],
    /// [`Self::y`] and [`Self::dense`] describe the end of the step.
    pub fn step<S: OdeSystem>(&mut self, sys: &S) -> Result<(), Error> {
        self.step_until(sys, f64::INFINITY)
    }

    /// Like [`Self::step`], but never steps past `t_stop`: a step that would reach it (or stop just short
    /// of it) ends exactly at `t_stop`. Used at breakpoints where the right-hand side has a kink, such as the
    /// samples of a piecewise-linear ground motion, so that no step straddles one. The step size proposed
    /// before the cut is kept for the next step.
    pub fn step_until<S: OdeSystem>(&mut self, sys: &S, t_stop: f64) -> Result<(), Error> {
        let (t, n) = (self.t, self.n);
        let h_wanted = self.h;
        loop {
            // Within 1 % of a step of the stop, take it in one go instead of leaving a sliver.
            let cut = t + 1.01 * self.h >= t_stop;
            let h = if cut { t_stop - t } else { self.h };
            if !(h.is_finite() && h > 0.0) || t + h == t {
                return Err(Error::StepSizeUnderflow { t });
            }
            self.stage(sys, t + C2 * h, h, &[(0, A21)], 1);
            self.stage(sys, t + C3 * h, h, &[(0, A31), (1, A32)], 2);
            self.stage(sys, t + C4 * h, h, &[(0, A41), (1, A42), (2, A43)], 3);
            self.stage(
                sys,
                t + C5 * h,
                h,
                &[(0, A51), (1, A52), (2, A53), (3, A54)],
                4,
            );
            self.stage(
                sys,
                t + h,
                h,
                &[(0, A61), (1, A62), (2, A63), (3, A64), (4, A65)],
                5,
            );
            {
                let [k0, _, k2, k3, k4, k5, _] = stages(&self.k, n);
                let (y, ynew) = (&self.y[..n], &mut self.ynew[..n]);
                for i in 0..n {
                    ynew[i] = y[i]
                        + h * (A71 * k0[i] + A73 * k2[i] + A74 * k3[i] + A75 * k4[i] + A76 * k5[i]);
                }
            }
            {
                let (ynew, k) = (&self.ynew, &mut self.k);
                sys.rhs(t + h, ynew, &mut k[6]);
            }
            let mut err = 0.0;
            {
                let [k0, _, k2, k3, k4, k5, k6] = stages(&self.k, n);
                let (y, ynew) = (&self.y[..n], &self.ynew[..n]);
                let (atol, rel) = (&self.tol.atol[..n], &self.rel[..n]);
                for i in 0..n {
                    let e = h
                        * (E1 * k0[i]
                            + E3 * k2[i]
                            + E4 * k3[i]
                            + E5 * k4[i]
                            + E6 * k5[i]
                            + E7 * k6[i]);
                    let sc = atol[i] + rel[i] * y[i].abs().max(ynew[i].abs());
                    err += (e / sc) * (e / sc);
                }
            }
            let counted = if self.tol.quiet.is_empty() {
                self.controlled
            } else {
                self.tol
                    .counted(self.controlled, &self.y, &stages(&self.k, self.n))
            };
            let err = (err / counted as f64).sqrt();
            if !err.is_finite() {
                self.rejected += 1;
                self.h = h * 0.2;
                continue;
            }
            // Classic controller: exponent 1/5 for an order-4 error estimate, safety 0.9.
            let fac = if err == 0.0 {
                5.0
            } else {
                (0.9 * err.powf(-0.2)).clamp(0.2, 5.0)
            };
            if err <= 1.0 {
                self.count_stiffness(h);
                let d = &mut self.dense;
                d.t0 = t;
                d.h = h;
                let [k0, _, k2, k3, k4, k5, k6] = stages(&self.k, n);
                let (y, ynew) = (&self.y[..n], &self.ynew[..n]);
                let [r0, r1, r2, r3, r4] = &mut d.r;
                let (r0, r1, r2, r3, r4) = (
                    &mut r0[..n],
                    &mut r1[..n],
                    &mut r2[..n],
                    &mut r3[..n],
                    &mut r4[..n],
                );
                for i in 0..n {
                    let dy = ynew[i] - y[i];
                    let bspl = h * k0[i] - dy;
                    r0[i] = y[i];
                    r1[i] = dy;
                    r2[i] = bspl;
                    r3[i] = dy - h * k6[i] - bspl;
                    r4[i] = h
                        * (D1 * k0[i]
                            + D3 * k2[i]
                            + D4 * k3[i]
                            + D5 * k4[i]
                            + D6 * k5[i]
                            + D7 * k6[i]);
                }
                self.t = if cut { t_stop } else { t + h };
                std::mem::swap(&mut self.y, &mut self.ynew);
                // First-same-as-last: the last stage is the first of the next step.
                self.k.swap(0, 6);
                self.h = (h * fac).min(self.h_max);
                if cut {
                    self.h = self.h.max(h_wanted.min(self.h_max));
                }
                self.accepted += 1;
                return Ok(());
            }
            self.rejected += 1;
            self.h = h * fac.min(1.0);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Harmonic oscillator y'' = -y, exact solution (sin t, cos t).
    struct Oscillator;
    impl OdeSystem for Oscillator {
        fn dim(&self) -> usize {
            2
        }
        fn rhs(&self, _t: f64, y: &[f64], dy: &mut [f64]) {
            dy[0] = y[1];
            dy[1] = -y[0];
        }
    }

    fn run(rtol: f64) -> (f64, f64) {
        let mut dp = DormandPrince::new(Tolerance::new(rtol, vec![rtol; 2]));
        dp.reset(&Oscillator, 0.0, &[0.0, 1.0], 1e-3);
        let mut max_dense_err: f64 = 0.0;
        let mut out = [0.0; 2];
        while dp.t() < 10.0 {
            dp.step(&Oscillator).unwrap();
            let d = dp.dense();
            for j in 1..10 {
                let t = d.t0() + (d.t1() - d.t0()) * j as f64 / 10.0;
                d.eval(t, &mut out);
                max_dense_err = max_dense_err.max((out[0] - t.sin()).abs());
            }
        }
        ((dp.y()[0] - dp.t().sin()).abs(), max_dense_err)
    }

    #[test]
    fn end_point_and_interpolant_track_the_exact_oscillator() {
        // Global error stays a modest multiple of the tolerance, and so does the interpolant between steps.
        for rtol in [1e-6, 1e-9, 1e-12] {
            let (end_err, dense_err) = run(rtol);
            assert!(end_err < 100.0 * rtol, "rtol {rtol}: end error {end_err}");
            assert!(
                dense_err < 100.0 * rtol,
                "rtol {rtol}: dense error {dense_err}"
            );
        }
    }

    #[test]
    fn interpolant_is_fourth_order() {
        // On one fixed step the interpolation error must fall like h^5: halving h divides it by about 32.
        let err = |h: f64| {
            let mut dp = DormandPrince::new(Tolerance::new(1.0, vec![1.0; 2]));
            dp.reset(&Oscillator, 0.0, &[0.0, 1.0], h);
            dp.step(&Oscillator).unwrap();
            let mut out = [0.0; 2];
            let t = 0.37 * h;
            dp.dense().eval(t, &mut out);
            (out[0] - t.sin()).abs()
        };
        let ratio = err(0.2) / err(0.1);
        assert!(ratio > 20.0 && ratio < 50.0, "ratio {ratio}");
    }
}
