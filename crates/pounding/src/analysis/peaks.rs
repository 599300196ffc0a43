//! Peaks a run keeps, as observers of the engine: of every floor and storey, of every device, and the worst
//! energy imbalance.

use super::model::{ColumnRef, DeviceRef, Model, StoreyRef};
use crate::element::{End, Point};
use crate::engine::{EventInfo, Observer, Segment, System};
use crate::integrate::{
    brent_root, derivative, golden_max, hermite_peak, horner, quadratic_roots, Hermite, OdeSystem,
    TERMS,
};

/// A largest value and its time, s.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Peak {
    pub value: f64,
    pub time: f64,
}

impl Peak {
    fn offer(&mut self, value: f64, time: f64) {
        if value > self.value {
            *self = Peak { value, time };
        }
    }
}

/// The largest `|q|` on a step of a quantity `q = value(y, 0)` whose rate is `value(y, n)` (a combination of
/// displacements; its rate the same of velocities), with its time: the cubic Hermite's estimate on the step's
/// ends; on a step propagated exactly whose estimate may beat `best`, the extremum on the exact motion (the
/// root of the rate, located by Brent's method). `ends` are `q` and its rate at the step's ends,
/// `(q0, q1, r0, r1)` ([`ends_on`], or read once for several uses); `motion` is room for the displacements
/// and velocities.
pub(super) fn step_peak(
    seg: &Segment<'_, '_>,
    motion: &mut [f64],
    best: f64,
    (qa, qb, va, vb): (f64, f64, f64, f64),
    value: impl Fn(&[f64], usize) -> f64,
) -> (f64, f64) {
    let h = seg.t1 - seg.t0;
    let (s, p) = hermite_peak(qa, qb, va, vb, h);
    // The Hermite estimate errs by less than 0.3 % on an exact step (r h <= 1; the module
    // crate::integrate::exact).
    if p < 0.99 * best {
        return (seg.t0 + s * h, p);
    }
    let curve = Hermite::new(qa, qb, va, vb, h);
    match exact_extremum(seg, motion, &curve, &value) {
        Some((tm, q)) if q.abs() > qb.abs() => (tm, q.abs()),
        Some(_) => (seg.t1, qb.abs()),
        None => (seg.t0 + s * h, p),
    }
}

/// A quantity `q = value(y, 0)` and its rate `value(y, n)` at the ends of a step, as [`step_peak`] takes
/// them; `n` degrees of freedom.
pub(super) fn ends_on(
    seg: &Segment<'_, '_>,
    n: usize,
    value: impl Fn(&[f64], usize) -> f64,
) -> (f64, f64, f64, f64) {
    let (y0, y1) = (seg.y0, seg.y1);
    (value(y0, 0), value(y1, 0), value(y0, n), value(y1, n))
}

/// A piece of a whole interval taken at once over which a rate (`va`, `vb` at the step's ends,
/// `rate(motion, k)` at the start of piece `k`) changes sign, with its rates at its ends: the step itself
/// for a step of one piece. First the piece where `guess` (a cubic Hermite on the segment whose slope is
/// that rate) puts the root, in two readings; else the first such piece along the chain. A search then
/// builds the series of one piece only.
fn bracket(
    seg: &Segment<'_, '_>,
    (va, vb): (f64, f64),
    guess: &Hermite,
    mut rate: impl FnMut(&crate::integrate::Motion, usize) -> f64,
) -> ((f64, f64), (f64, f64)) {
    let mut a = (seg.t0, va);
    if let Some(m) = seg.dense.motion().filter(|m| m.pieces() > 1) {
        let (n, p) = (m.pieces(), m.piece());
        if let Some(g) = guess
            .root_of_slope()
            .map(|s| seg.t0 + s * (seg.t1 - seg.t0))
        {
            // The cubic is within a per cent of the motion on an exact step: its root is most often in
            // the same piece, found in two readings instead of a walk from the start.
            let k = (((g - seg.t0) / p).floor().max(0.0) as usize).min(n - 1);
            let at =
                |k: usize, rate: &mut dyn FnMut(&crate::integrate::Motion, usize) -> f64| match k {
                    0 => (seg.t0, va),
                    k if k >= n => (seg.t1, vb),
                    k => (seg.t0 + k as f64 * p, rate(m, k)),
                };
            let (l, r) = (at(k, &mut rate), at(k + 1, &mut rate));
            if l.1 * r.1 <= 0.0 {
                return (l, r);
            }
        }
        for k in 1..n {
            let b = (seg.t0 + k as f64 * p, rate(m, k));
            if a.1 * b.1 <= 0.0 {
                return (a, b);
            }
            a = b;
        }
    }
    (a, (seg.t1, vb))
}

/// On a step propagated exactly, the interior extremum of `q = value(y, 0)` (rate `value(y, n)`), `curve`
/// its cubic Hermite on the segment (its rates `va`, `vb` at the ends): the root of its rate on the exact
/// motion (Brent's method) and `q` there; `None` on a stepped step or when the rate keeps its sign.
pub(super) fn exact_extremum(
    seg: &Segment<'_, '_>,
    motion: &mut [f64],
    curve: &Hermite,
    value: &impl Fn(&[f64], usize) -> f64,
) -> Option<(f64, f64)> {
    let (va, vb) = curve.end_slopes();
    if seg.dense.motion().is_none() || va * vb >= 0.0 {
        return None;
    }
    let n = motion.len() / 2;
    let ((ta, ra), (tb, rb)) = bracket(seg, (va, vb), curve, |m, k| {
        m.piece_start(k, motion);
        value(motion, n)
    });
    // The bracket lies in one piece: the quantity and its rate as polynomials there (one series built,
    // each of the search's readings a scalar Horner instead of the whole motion).
    let m = seg.dense.motion()?;
    let t0 = seg.dense.t0();
    let (mut q, mut r) = ([0.0; TERMS], [0.0; TERMS]);
    let mid = 0.5 * (ta + tb) - t0;
    let (start, terms) = m.functional_series(mid, |c| value(c, 0), &mut q);
    m.functional_series(mid, |c| value(c, n), &mut r);
    let at = |c: &[f64; TERMS], t: f64| horner(&c[..terms], t - t0 - start);
    let tol = 4.0 * f64::EPSILON * seg.t1.abs();
    let tm = brent_root(|t| at(&r, t), ta, tb, ra, rb, tol)?;
    Some((tm, at(&q, tm)))
}

/// On a step propagated exactly, where floor `i`'s absolute acceleration (`a0`, `a1` at the segment's ends,
/// its jerks `j0`, `j1` of opposite signs) turns: the root of the jerk on the exact motion (Brent's method),
/// s, and the acceleration there, m/s^2; `ground` is the ground's acceleration at an offset into the step
/// and its slope (m/s^2, m/s^3). Apart from the screens that call it: most steps never do.
#[cold]
fn jerk_root(
    seg: &Segment<'_, '_>,
    i: usize,
    (a0, a1, j0, j1): (f64, f64, f64, f64),
    (ground, slope): (impl Fn(f64) -> f64, f64),
) -> Option<(f64, f64)> {
    let motion = seg.dense.motion()?;
    let n = seg.system.layout().dofs();
    let (t0, t1) = (seg.t0, seg.t1);
    let tol = 4.0 * f64::EPSILON * t1.abs();
    // The jerks at the pieces' starts along the chain around the cubic's guess, then, for a walk, by rows
    // where the configuration has them (built at the first walk).
    let curve = Hermite::new(a0, a1, j0, j1, t1 - t0);
    let mut readings = 0;
    let ((ta, ja), (tb, jb)) = bracket(seg, (j0, j1), &curve, |m, k| {
        readings += 1;
        let rows = readings > 2 && m.jerk_rows(i);
        let jerk = rows.then(|| m.jerk_probe(i, k)).flatten();
        jerk.unwrap_or_else(|| m.second_rate_at(k, n + i)) + slope
    });
    // The bracket lies in one piece: the velocity's series there, differentiated once and twice (each of
    // the search's readings a scalar Horner instead of the motion's).
    let mut v = [0.0; TERMS];
    let (start, terms) = motion.functional_series(0.5 * (ta + tb) - t0, |c| c[n + i], &mut v);
    let acc = derivative(&v);
    let jerk = derivative(&acc);
    let at = |c: &[f64; TERMS], t: f64| horner(&c[..terms], t - t0 - start);
    let tm = brent_root(|t| at(&jerk, t) + slope, ta, tb, ja, jb, tol)?;
    Some((tm, at(&acc, tm) + ground(tm - t0)))
}

/// Room for the states of the element with the most.
fn room(m: &Model) -> Vec<f64> {
    let l = m.system.layout();
    let most = (0..m.system.elements().len())
        .map(|e| l.block(e).len())
        .max()
        .unwrap_or(0);
    vec![0.0; most]
}

/// Peaks of every floor (degree of freedom) and every storey (indexed by the degree of freedom of its top
/// floor: for a floor in plan, the storey's drift and shear along x and along y, its twist and torque), of
/// every element of a plan's lines, and of the corners of every floor in plan.
pub(super) struct Peaks {
    storeys: Vec<StoreyRef>,
    pub displacement: Vec<Peak>,
    /// The largest absolute acceleration of each floor ([`Model::floors`]; 0 for the other degrees of
    /// freedom, whose accelerations no result reports), m/s^2 or rad/s^2.
    pub acceleration: Vec<Peak>,
    floors: Vec<usize>,
    pub drift: Vec<f64>,
    pub shear: Vec<f64>,
    /// The elements of the lines of buildings in plan, and the largest |deformation| of each, m.
    lines: Vec<usize>,
    pub line_drift: Vec<f64>,
    /// The corners' displacements along x and along y ([`Model::corners`]), and their largest |value|, m.
    corners: Vec<Point>,
    pub corner: Vec<Peak>,
    /// The struck columns ([`Model::columns`]) and the largest |value| of each one's force at the point (N),
    /// lower and upper end shears (N) and moments (N m), load and drift together.
    columns: Vec<ColumnRef>,
    pub column: Vec<[f64; 5]>,
    /// A storey element's states between nodes.
    states: Vec<f64>,
    /// Room for the displacements and velocities between nodes.
    motion: Vec<f64>,
    /// Room for a state inside a Runge–Kutta step, and for an element's states' rates.
    at_y: Vec<f64>,
    at_f: Vec<f64>,
    /// Each storey element's deformation on the step (room for the storey with the most).
    curves: Vec<Hermite>,
    /// The elements of the storeys and lines, each once, and each element's deformation and rate at the
    /// step's two ends `[x0, v0, x1, v1]` (read once per step: a line of a plan serves two storeys).
    used: Vec<usize>,
    ends: Vec<[f64; 4]>,
    /// Each of those elements' force (of its law) at the step's end, N.
    forces: Vec<f64>,
}

impl Peaks {
    pub fn new(m: &Model) -> Self {
        let n = m.system.layout().dofs();
        let most = m
            .storeys
            .iter()
            .map(|s| s.elements.len())
            .max()
            .unwrap_or(0);
        Self {
            storeys: m.storeys.clone(),
            displacement: vec![Peak::default(); n],
            acceleration: vec![Peak::default(); n],
            floors: m.floors.clone(),
            drift: vec![0.0; n],
            shear: vec![0.0; n],
            lines: m.lines.clone(),
            line_drift: vec![0.0; m.lines.len()],
            corners: m.corners.clone(),
            corner: vec![Peak::default(); m.corners.len()],
            columns: m.columns.clone(),
            column: vec![[0.0; 5]; m.columns.len()],
            states: room(m),
            motion: vec![0.0; 2 * n],
            at_y: vec![0.0; m.system.dim()],
            at_f: vec![0.0; m.system.dim()],
            curves: vec![Hermite::new(0.0, 0.0, 0.0, 0.0, 1.0); most],
            used: {
                let mut u: Vec<usize> = m
                    .storeys
                    .iter()
                    .flat_map(|s| s.elements.iter().map(|&(e, _)| e))
                    .chain(m.lines.iter().copied())
                    .collect();
                u.sort_unstable();
                u.dedup();
                u
            },
            ends: vec![[0.0; 4]; m.system.elements().len()],
            forces: vec![0.0; m.system.elements().len()],
        }
    }

    fn accelerations(&mut self, sys: &System, t: f64, rate: &[f64]) {
        let l = sys.layout();
        let g = sys.ground().at_xy(t);
        for &i in &self.floors {
            let a = rate[l.v(i)] + sys.ground_from(i, t, g);
            self.acceleration[i].offer(a.abs(), t);
        }
    }

    /// On a step propagated exactly, the largest absolute acceleration of each floor inside it: where the
    /// jerk changes sign and the cubic Hermite of the acceleration (values and jerks at the ends) may beat the
    /// peak, the root of the jerk on the exact motion (Brent's method) and the acceleration there.
    fn accelerations_inside(&mut self, seg: &Segment<'_, '_>) {
        let Some(motion) = seg.dense.motion() else {
            return;
        };
        let sys = seg.system;
        let n = sys.layout().dofs();
        let (t0, t1) = (seg.t0, seg.t1);
        let h = t1 - t0;
        // A segment an event cut short ends inside the step: its end's rates are the segment's own, and
        // what the step holds past it (the motion as if no event) is not offered.
        let step = seg.dense.t1() - t0;
        let cut = h < step - 4.0 * f64::EPSILON * t1.abs();
        for k in 0..self.floors.len() {
            let i = self.floors[k];
            let line = sys.ground_in(i, &motion.w0, 2 * n);
            let ground = |tau: f64| line.at(tau);
            let slope = line.slope();
            let (a0, a1) = (
                motion.rates[0][n + i] + ground(0.0),
                if cut {
                    seg.rate1[n + i]
                } else {
                    motion.rates[4][n + i]
                } + ground(h),
            );
            let j1 = if cut {
                motion.w_at(h, n + i)[2]
            } else {
                motion.jerk[1][i]
            };
            let (j0, j1) = (motion.jerk[0][i] + slope, j1 + slope);
            if motion.pieces() > 1 {
                // A whole interval: its exact accelerations at the Gauss nodes too (a foundation's fast
                // modes ring inside it, which the cubic through the ends may not show).
                for (j, node) in crate::integrate::GAUSS_NODES.iter().enumerate() {
                    if node * step <= h {
                        let a = motion.rates[j + 1][n + i] + ground(node * step);
                        self.acceleration[i].offer(a.abs(), t0 + node * step);
                    }
                }
            }
            let (_, p) = hermite_peak(a0, a1, j0, j1, h);
            if j0 * j1 >= 0.0 || p < 0.99 * self.acceleration[i].value {
                continue;
            }
            if let Some((tm, a)) = jerk_root(seg, i, (a0, a1, j0, j1), (ground, slope)) {
                self.acceleration[i].offer(a.abs(), tm);
            }
        }
    }

    /// On a Runge–Kutta step, the largest absolute acceleration of each floor inside it (read at the steps'
    /// ends alone, impacts' peaks were 2e-3 to 7.5e-3 low at the default tolerance). The derivative of the
    /// velocity's interpolant, a cubic, shows where the acceleration turns; where it may beat the floor's
    /// peak there, the acceleration of the interpolated state (its entry of the right-hand side,
    /// [`System::acceleration`], as accurate as the state) is maximised around it by parabolic interpolation
    /// ([`parabolic_max`]).
    fn accelerations_stepped(&mut self, seg: &Segment<'_, '_>) {
        let dense = seg.dense;
        let (t0, h) = (dense.t0(), dense.t1() - dense.t0());
        if dense.motion().is_some() || h <= 0.0 {
            return;
        }
        let sys = seg.system;
        let l = sys.layout();
        // The part of the step this segment covers (an event may cut it short), as fractions of the step.
        let (lo, hi) = (((seg.t0 - t0) / h).max(0.0), ((seg.t1 - t0) / h).min(1.0));
        let (ga, gb) = (sys.ground().at_xy(t0), sys.ground().at_xy(t0 + h));
        for k in 0..self.floors.len() {
            let i = self.floors[k];
            let Some(c) = dense.quartic(l.v(i)) else {
                return;
            };
            // The ground's acceleration is linear on a step (steps end at the records' samples).
            let (g0, g1) = (sys.ground_from(i, t0, ga), sys.ground_from(i, t0 + h, gb));
            // The absolute acceleration's rate in theta: 2 c2 + 6 c3 th + 12 c4 th^2 (over h^2) plus the
            // ground's; its roots inside the segment are where the interpolant's acceleration turns.
            let (qa, qb, qc) = (12.0 * c[4], 6.0 * c[3], 2.0 * c[2] + (g1 - g0) * h);
            let acc = |th: f64| {
                (c[1] + th * (2.0 * c[2] + th * (3.0 * c[3] + th * 4.0 * c[4]))) / h
                    + g0
                    + th * (g1 - g0)
            };
            for th in quadratic_roots(qa, qb, qc) {
                if !(th > lo && th < hi) || acc(th).abs() < 0.99 * self.acceleration[i].value {
                    continue;
                }
                let Self { at_y, at_f, .. } = self;
                let true_acc = |t: f64| {
                    dense.eval(t, at_y);
                    (sys.acceleration(i, t, at_y, at_f) + sys.ground_at(i, t)).abs()
                };
                let (tm, am) = parabolic_max(true_acc, t0 + th * h, (t0 + lo * h, t0 + hi * h), h);
                self.acceleration[i].offer(am, tm);
            }
        }
    }

    fn storey(&mut self, seg: &Segment<'_, '_>, i: usize) {
        let sys = seg.system;
        let l = sys.layout();
        let (y0, y1) = (seg.y0, seg.y1);
        let h = seg.t1 - seg.t0;
        let Self {
            storeys,
            curves,
            states: room,
            ends,
            forces,
            motion,
            ..
        } = self;
        let st = &storeys[i];
        let drift = |y: &[f64], off: usize| st.drift(i, y, off);
        let n = l.dofs();
        let (xa, xb, va, vb) = (drift(y0, 0), drift(y1, 0), drift(y0, n), drift(y1, n));
        let curve = Hermite::new(xa, xb, va, vb, h);
        let end: f64 = st.elements.iter().map(|&(e, c)| c * forces[e]).sum();
        // Each element's deformation on its cubic Hermite, where a shear between the ends is read on them.
        let mut set_curves = || {
            for (k, &(e, _)) in st.elements.iter().enumerate() {
                let [pa, qa, pb, qb] = ends[e];
                curves[k] = Hermite::new(pa, pb, qa, qb, h);
            }
        };
        let mut shear = end.abs();
        if let Some(m) = seg.dense.motion() {
            let (tm, peak_drift) = step_peak(seg, motion, self.drift[i], (xa, xb, va, vb), drift);
            self.drift[i] = self.drift[i].max(peak_drift);
            // On the exact motion (every law affine there) the shear is affine in it. A storey of one spring
            // without a reported viscous part peaks where its drift does; any other (a storey of a building
            // given by its matrices, whose shear combines every floor's; one with a viscous device) at its
            // own extremum, located as such.
            let laws = || {
                st.elements
                    .iter()
                    .filter_map(|&(e, c)| Some((sys.elements()[e].affine()?, e, c)))
            };
            let spring = st.elements.len() == 1 && laws().all(|(a, _, _)| a.c == a.viscous);
            if !spring && laws().count() == st.elements.len() {
                let f0: f64 = laws().map(|(a, _, c)| c * a.f0).sum();
                let lin = |y: &[f64]| {
                    laws()
                        .map(|(a, e, c)| {
                            let (x, v) = sys.deformation(e, y);
                            // The shear as reported: without a law's viscous part.
                            c * (a.k * x + (a.c - a.viscous) * v)
                        })
                        .sum::<f64>()
                };
                let ends = (
                    (lin(y0) + f0, lin(&m.rates[0])),
                    (lin(y1) + f0, lin(seg.rate1)),
                );
                let p = affine_peak(seg, ends, (self.shear[i], motion), lin, f0);
                self.shear[i] = self.shear[i].max(shear).max(p);
                return;
            }
            // The shear at the drift's extremum inside the step on the Hermite curves (within 1 %) first:
            // only one that may beat the peak is read on the exact motion.
            if tm >= seg.t1 {
                self.shear[i] = self.shear[i].max(shear);
                return;
            }
            set_curves();
            let s = (tm - seg.t0) / h;
            let estimate: f64 = st
                .elements
                .iter()
                .enumerate()
                .map(|(k, &(e, c))| {
                    let p = &curves[k];
                    c * sys.elements()[e].force(p.at(s), p.slope(s), &room[..l.block(e).len()])
                })
                .sum();
            if estimate.abs() >= 0.99 * self.shear[i] {
                seg.dense.eval_prefix(tm, motion);
                let mut f = 0.0;
                for &(e, c) in &st.elements {
                    let (x, v) = sys.deformation(e, motion);
                    f += c * sys.elements()[e].force(x, v, &room[..l.block(e).len()]);
                }
                shear = shear.max(f.abs());
            }
            self.shear[i] = self.shear[i].max(shear);
            return;
        }
        let peak_drift = hermite_peak(xa, xb, va, vb, h).1;
        set_curves();
        for s in curve.extrema() {
            if s.is_nan() {
                continue;
            }
            let t = seg.t0 + s * h;
            let mut f = 0.0;
            for (k, &(e, c)) in st.elements.iter().enumerate() {
                let block = l.block(e);
                let states = &mut room[..block.len()];
                for (kk, z) in block.clone().zip(states.iter_mut()) {
                    *z = seg.dense.component(t, kk);
                }
                let p = &curves[k];
                f += c * sys.elements()[e].force(p.at(s), p.slope(s), states);
            }
            shear = shear.max(f.abs());
        }
        self.drift[i] = self.drift[i].max(peak_drift);
        self.shear[i] = self.shear[i].max(shear);
    }
}

impl Observer for Peaks {
    fn segment(&mut self, seg: &Segment<'_, '_>) {
        let sys = seg.system;
        let l = sys.layout();
        let (y0, y1) = (seg.y0, seg.y1);
        let n = l.dofs();
        for &e in &self.used {
            let ((xa, va), (xb, vb)) = (sys.deformation(e, y0), sys.deformation(e, y1));
            self.ends[e] = [xa, va, xb, vb];
            self.forces[e] = sys.elements()[e].force(xb, vb, &y1[l.block(e)]);
        }
        for i in 0..n {
            let best = self.displacement[i].value;
            let ends = (y0[i], y1[i], y0[n + i], y1[n + i]);
            let (t, u) = step_peak(seg, &mut self.motion, best, ends, |y, off| y[off + i]);
            self.displacement[i].offer(u, t);
            self.storey(seg, i);
        }
        for (k, &e) in self.lines.iter().enumerate() {
            let el = &sys.elements()[e];
            let x = |y: &[f64], off: usize| el.a.value(y, off) - el.b.value(y, off);
            // The line's deformation at the ends, read once above.
            let [xa, va, xb, vb] = self.ends[e];
            let (_, d) = step_peak(
                seg,
                &mut self.motion,
                self.line_drift[k],
                (xa, xb, va, vb),
                x,
            );
            self.line_drift[k] = self.line_drift[k].max(d);
        }
        for (p, peak) in self.corners.iter().zip(&mut self.corner) {
            let end = End::Point(*p);
            let value = |y: &[f64], off: usize| end.value(y, off);
            let ends = ends_on(seg, n, value);
            let (t, u) = step_peak(seg, &mut self.motion, peak.value, ends, value);
            peak.offer(u, t);
        }
        for (c, peak) in self.columns.iter().zip(&mut self.column) {
            // Each end force is a combination of the spring's deformation and the drift: cubic on the step
            // as they are, so its peak is located as a drift's.
            let [xa, va, xb, vb] = self.ends[c.element];
            let d = End::Point(c.drift);
            let (da, db, dva, dvb) = (
                d.value(y0, 0),
                d.value(y1, 0),
                d.value(y0, n),
                d.value(y1, n),
            );
            let el = &sys.elements()[c.element];
            for (p, &(alpha, beta)) in peak.iter_mut().zip(&c.ends) {
                let q = |y: &[f64], off: usize| {
                    alpha * (el.a.value(y, off) - el.b.value(y, off)) + beta * d.value(y, off)
                };
                let ends = (
                    alpha * xa + beta * da,
                    alpha * xb + beta * db,
                    alpha * va + beta * dva,
                    alpha * vb + beta * dvb,
                );
                *p = p.max(step_peak(seg, &mut self.motion, *p, ends, q).1);
            }
        }
        self.accelerations_inside(seg);
        self.accelerations_stepped(seg);
        self.accelerations(sys, seg.t1, seg.rate1);
    }

    fn event(&mut self, ev: &EventInfo<'_, '_>) {
        // The acceleration just after the event (a contact force may jump at touch).
        self.accelerations(ev.system, ev.t, ev.rate);
    }
}

/// The largest value of `f` near `t` within `span` (s), whose scale of time is `h` (s): `t` the estimate of
/// where a smooth peak is. Two rounds of the parabola through three values at `t +- d` (d = 0.1 h, then
/// 0.01 h) about the last vertex, and the final vertex: seven evaluations, the peak's time to well within
/// 1e-4 h, its value to its square. Every value read is a candidate.
fn parabolic_max(mut f: impl FnMut(f64) -> f64, t: f64, (a, b): (f64, f64), h: f64) -> (f64, f64) {
    let mut best = (t, f(t));
    let mut centre = best;
    for d in [0.1 * h, 0.01 * h] {
        let (tl, tr) = ((centre.0 - d).max(a), (centre.0 + d).min(b));
        let (fl, fr) = (f(tl), f(tr));
        for p in [(tl, fl), (tr, fr)] {
            if p.1 > best.1 {
                best = p;
            }
        }
        // The vertex of the parabola through the three points (unequal spacing at the span's ends).
        let (x0, x1, x2) = (tl - centre.0, 0.0, tr - centre.0);
        let (y0, y1, y2) = (fl, centre.1, fr);
        let den = (x0 - x1) * (x0 - x2) * (x1 - x2);
        let ca = (x2 * (y1 - y0) + x1 * (y0 - y2) + x0 * (y2 - y1)) / den;
        let cb = (x2 * x2 * (y0 - y1) + x1 * x1 * (y2 - y0) + x0 * x0 * (y1 - y2)) / den;
        if ca.is_nan() || ca >= 0.0 || !den.is_finite() || den == 0.0 {
            // Not a maximum inside: the best point read so far is the next centre.
            centre = best;
            continue;
        }
        let tv = (centre.0 - cb / (2.0 * ca)).clamp(a, b);
        centre = (tv, f(tv));
        if centre.1 > best.1 {
            best = centre;
        }
    }
    best
}

/// The force of element `e` in state `y`, elastic and viscous, N; `ds` is room for the rates of its states.
pub(super) fn total_force(sys: &System, e: usize, y: &[f64], ds: &mut [f64]) -> f64 {
    let (x, v) = sys.deformation(e, y);
    let r = sys.layout().block(e);
    let (f, fv) = sys.elements()[e].evaluate(x, v, &y[r.clone()], &mut ds[..r.len()]);
    f + fv
}

/// Peaks of every device element, located on the step's interpolant as the floors' and the contacts' are:
/// its deformation's extrema (a restrainer's largest opening and force, exactly as the joint beside it
/// records them), the extremum of its rate (a dashpot's force) and the step's end.
pub(super) struct DevicePeaks {
    devices: Vec<DeviceRef>,
    pub force: Vec<f64>,
    pub closing: Vec<f64>,
    pub opening: Vec<f64>,
    /// Room for the rates of a device's states.
    rates: Vec<f64>,
    /// Room for a device's states between nodes.
    states: Vec<f64>,
    /// Room for the displacements and velocities between nodes.
    motion: Vec<f64>,
}

impl DevicePeaks {
    pub fn new(m: &Model) -> Self {
        let n = m.devices.len();
        Self {
            devices: m.devices.clone(),
            force: vec![0.0; n],
            closing: vec![0.0; n],
            opening: vec![0.0; n],
            rates: room(m),
            states: room(m),
            motion: vec![0.0; 2 * m.system.layout().dofs()],
        }
    }
}

impl Observer for DevicePeaks {
    fn segment(&mut self, seg: &Segment<'_, '_>) {
        let sys = seg.system;
        let h = seg.t1 - seg.t0;
        for (k, d) in self.devices.iter().enumerate() {
            let e = d.element;
            let ((xa, va), (xb, vb)) = (sys.deformation(e, seg.y0), sys.deformation(e, seg.y1));
            let f = total_force(sys, e, seg.y1, &mut self.rates);
            let (mut force, mut hi, mut lo) = (f.abs(), xb, -xb);
            if seg.dense.motion().is_some() {
                // On the exact motion: the deformation's extremum, and the force's largest value where it
                // may beat the peak (golden section; an affine law's force needs no states).
                let el = &sys.elements()[e];
                let q = |y: &[f64], off: usize| el.a.value(y, off) - el.b.value(y, off);
                // Only where the Hermite's extremum (within 1 % on an exact step) may beat a peak.
                let p = Hermite::new(xa, xb, va, vb, h);
                let near = p.extremum_near((self.closing[k], self.opening[k]), 0.99);
                if let Some((_, x)) = near
                    .then(|| exact_extremum(seg, &mut self.motion, &p, &q))
                    .flatten()
                {
                    hi = hi.max(x);
                    lo = lo.max(-x);
                }
                let fa = total_force(sys, e, seg.y0, &mut self.rates).abs();
                if fa.max(force) >= 0.9 * self.force[k] {
                    // An affine law's force is a polynomial on a one-piece step: searched there.
                    let fm = affine_force_max(seg, e).unwrap_or_else(|| {
                        let (motion, rates) = (&mut self.motion, &mut self.rates);
                        let states = &self.states[..sys.layout().block(e).len()];
                        let mut at = |t: f64| {
                            seg.dense.eval_prefix(t, motion);
                            let (x, v) = sys.deformation(e, motion);
                            let (fe, fv) = el.evaluate(x, v, states, &mut rates[..states.len()]);
                            (fe + fv).abs()
                        };
                        golden_max(&mut at, seg.t0, seg.t1, 1e-12 * h).1
                    });
                    force = force.max(fm);
                }
                self.force[k] = self.force[k].max(force);
                self.closing[k] = self.closing[k].max(hi);
                self.opening[k] = self.opening[k].max(lo);
                continue;
            }
            let p = Hermite::new(xa, xb, va, vb, h);
            let [s1, s2] = p.extrema();
            for s in [s1, s2, p.inflection()] {
                if s.is_nan() {
                    continue;
                }
                let x = p.at(s);
                hi = hi.max(x);
                lo = lo.max(-x);
                // The force between nodes: deformation and rate on the interpolant the openings are read
                // on (so that a restrainer's peak force is its law at its largest opening), its own
                // states on the step's dense output.
                let t = seg.t0 + s * h;
                let block = sys.layout().block(e);
                let states = &mut self.states[..block.len()];
                for (kk, z) in block.clone().zip(states.iter_mut()) {
                    *z = seg.dense.component(t, kk);
                }
                let rates = &mut self.rates[..block.len()];
                let (fe, fv) = sys.elements()[e].evaluate(x, p.slope(s), states, rates);
                force = force.max((fe + fv).abs());
            }
            self.force[k] = self.force[k].max(force);
            self.closing[k] = self.closing[k].max(hi);
            self.opening[k] = self.opening[k].max(lo);
        }
    }
}

/// The largest `|q|` on a step propagated exactly of a quantity affine in the motion, `q = f(y) + f0` for a
/// linear `f` of the displacements and velocities (a storey's shear, N), its values `(qa, qb)` and rates
/// `(ra, rb)` (`f` of the state's rates) at the segment's ends: the cubic Hermite's estimate; where it may
/// beat `best`, the exact value. On one piece, the root of the rate on the polynomial `f` makes of the step's
/// series (`f` of a series coefficient is the polynomial's coefficient); on a whole interval of many pieces,
/// `q` at every piece's start (read on the chain) and the interior extremum of the two pieces beside the
/// largest. `motion` is room for the displacements and velocities.
fn affine_peak(
    seg: &Segment<'_, '_>,
    ((qa, ra), (qb, rb)): ((f64, f64), (f64, f64)),
    (best, motion): (f64, &mut [f64]),
    f: impl Fn(&[f64]) -> f64,
    f0: f64,
) -> f64 {
    let h = seg.t1 - seg.t0;
    let (_, p) = hermite_peak(qa, qb, ra, rb, h);
    let ends = qa.abs().max(qb.abs());
    let Some(m) = seg.dense.motion().filter(|_| p >= 0.99 * best) else {
        return p;
    };
    let t0 = seg.dense.t0();
    if m.pieces() == 1 {
        // One piece: the motion is smooth on it (r h <= 1), an interior extremum where the rate turns.
        if ra * rb >= 0.0 {
            return p.max(ends);
        }
        let q = piece_extremum(m, (t0, 0.0), (seg.t0, seg.t1), &f, f0);
        return q.map_or(p.max(ends), |q| q.max(ends));
    }
    let piece = m.piece();
    let (mut peak, mut at) = (qa.abs(), 0);
    for k in 1..m.pieces() {
        if t0 + k as f64 * piece >= seg.t1 {
            break;
        }
        m.piece_start(k, motion);
        let q = (f(motion) + f0).abs();
        if q > peak {
            (peak, at) = (q, k);
        }
    }
    if qb.abs() > peak {
        // The segment's end: the step's, or an event's inside the piece it cuts.
        let end = ((seg.t1 - t0) / piece).ceil() as usize;
        (peak, at) = (qb.abs(), end.min(m.pieces()));
    }
    for k in [at.wrapping_sub(1), at] {
        if k < m.pieces() {
            let span = (
                seg.t0.max(t0 + k as f64 * piece),
                seg.t1.min(t0 + (k + 1) as f64 * piece),
            );
            if let Some(q) = piece_extremum(m, (t0, k as f64 * piece), span, &f, f0) {
                peak = peak.max(q);
            }
        }
    }
    peak
}

/// `|q|` at the extremum inside `(ta, tb)` (s; within one piece, which starts `start` s into the step that
/// starts at `t0`) of `q = f(y) + f0` on the exact motion: the root of the rate of its polynomial on the
/// piece's series; `None` when the rate keeps its sign there.
fn piece_extremum(
    m: &crate::integrate::Motion,
    (t0, start): (f64, f64),
    (ta, tb): (f64, f64),
    f: &impl Fn(&[f64]) -> f64,
    f0: f64,
) -> Option<f64> {
    if ta >= tb {
        return None;
    }
    let mut poly = [0.0; TERMS];
    let (origin, terms) = m.functional_series(0.5 * (ta + tb) - t0, f, &mut poly);
    debug_assert!((origin - start).abs() <= 1e-9 * (1.0 + start.abs()));
    poly[0] += f0;
    let origin = t0 + origin;
    let slope = derivative(&poly);
    let value = |t: f64| horner(&poly[..terms], t - origin);
    let rate = |t: f64| horner(&slope[..terms - 1], t - origin);
    let tol = 4.0 * f64::EPSILON * tb.abs();
    let tm = brent_root(rate, ta, tb, rate(ta), rate(tb), tol)?;
    Some(value(tm).abs())
}

/// The largest `|force|` of element `e` on a step propagated exactly in one piece, its law affine
/// (`k x + c v + f0`), N: the force as a polynomial on the step's series
/// ([`crate::integrate::Motion::functional_series`]), searched by golden section, each reading a scalar
/// Horner instead of the whole motion and the law.
/// `None` for a whole interval taken at once (a polynomial per piece) or a law that is not affine.
fn affine_force_max(seg: &Segment<'_, '_>, e: usize) -> Option<f64> {
    let m = seg.dense.motion().filter(|m| m.pieces() == 1)?;
    let sys = seg.system;
    let a = sys.elements()[e].affine()?;
    if a.k == 0.0 && a.c == 0.0 {
        // A constant force (a slack restrainer's 0).
        return Some(a.f0.abs());
    }
    let force = |c: &[f64]| {
        let (x, v) = sys.deformation(e, c);
        a.k * x + a.c * v
    };
    let mut poly = [0.0; TERMS];
    let (start, terms) = m.functional_series(0.0, force, &mut poly);
    poly[0] += a.f0;
    let t0 = seg.dense.t0() + start;
    let at = |t: f64| horner(&poly[..terms], t - t0).abs();
    let h = seg.t1 - seg.t0;
    Some(golden_max(at, seg.t0, seg.t1, 1e-12 * h).1)
}

/// The worst energy imbalance over the run, at every node.
#[derive(Default)]
pub(super) struct Balance {
    pub worst: f64,
    pub scale: f64,
}

impl Observer for Balance {
    fn segment(&mut self, seg: &Segment<'_, '_>) {
        let e = seg.system.energies(seg.y1);
        self.worst = self.worst.max(e.imbalance().abs());
        self.scale = self.scale.max(e.scale());
    }
}
