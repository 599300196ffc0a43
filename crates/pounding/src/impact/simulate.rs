//! Event-located integration of one impact.

use super::{History, ImpactOptions, ImpactResult, ImpactSetup};
use crate::contact::{ForceLaw, Phase, Tension, Turn};
use crate::integrate::{brent_root, golden_max, Dense, DormandPrince, OdeSystem, Tolerance};
use crate::Error;

/// State: penetration (m), rate (m/s), impulse `int F dt` (N s), work `int F v dt` (J).
const DIM: usize = 4;

struct Ode<'a> {
    law: &'a ForceLaw,
    phase: Phase,
    turn: Turn,
    m: f64,
    g: f64,
}

impl Ode<'_> {
    #[inline]
    fn force(&self, y: &[f64]) -> f64 {
        self.law.force(y[0], y[1], self.phase, &self.turn)
    }
}

impl OdeSystem for Ode<'_> {
    fn dim(&self) -> usize {
        DIM
    }
    fn rhs(&self, _t: f64, y: &[f64], dy: &mut [f64]) {
        // During contact the law is continued smoothly past its end; the end is an event (see `simulate`).
        let f = self.force(y);
        dy[0] = y[1];
        dy[1] = self.g - f / self.m;
        dy[2] = f;
        dy[3] = f * y[1];
    }
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Event {
    Turn,
    Kink,
    Separation,
    ZeroForce,
}

/// One piece of the solution between two nodes, with what is needed to evaluate the force on it.
struct Segment {
    dense: Dense,
    ta: f64,
    tb: f64,
    phase: Phase,
    turn: Turn,
}

impl Segment {
    /// The largest force on the segment, `(t, F)`, with the state at `t` left in `buf`.
    fn peak(&self, law: &ForceLaw, buf: &mut [f64; DIM]) -> (f64, f64) {
        let tol = 1e-12 * (self.tb - self.ta).max(f64::MIN_POSITIVE);
        let p = golden_max(
            |t| {
                self.dense.eval(t, buf);
                law.force(buf[0], buf[1], self.phase, &self.turn)
            },
            self.ta,
            self.tb,
            tol,
        );
        self.dense.eval(p.0, buf);
        p
    }
}

/// Local maxima of the force are refined on the two segments around a node that is higher than both of its
/// neighbours, so the ring buffer below keeps only the last two segments (no allocation per step).
struct PeakTracker {
    segs: [Segment; 2],
    cur: usize,
    count: usize,
    f_prev: f64,
    f_node: f64,
    best: (f64, f64),
    /// The state at the best time (for the history).
    best_y: [f64; DIM],
    buf: [f64; DIM],
}

impl PeakTracker {
    fn new(f0: f64, y0: [f64; DIM]) -> Self {
        let seg = || Segment {
            dense: Dense::zeros(DIM),
            ta: 0.0,
            tb: 0.0,
            phase: Phase::Approach,
            turn: Turn::default(),
        };
        Self {
            segs: [seg(), seg()],
            cur: 0,
            count: 0,
            f_prev: f64::NEG_INFINITY,
            f_node: f0,
            best: (0.0, f0),
            best_y: y0,
            buf: [0.0; DIM],
        }
    }

    fn consider(&mut self, p: (f64, f64), y: [f64; DIM]) {
        if p.1 > self.best.1 {
            self.best = p;
            self.best_y = y;
        }
    }

    fn push(
        &mut self,
        law: &ForceLaw,
        dense: &Dense,
        (ta, tb): (f64, f64),
        phase: Phase,
        turn: Turn,
        (f_end, y_end): (f64, [f64; DIM]),
    ) {
        let s = &mut self.segs[self.cur];
        s.dense.copy_from(dense);
        (s.ta, s.tb, s.phase, s.turn) = (ta, tb, phase, turn);
        if self.f_node >= f_end && self.f_node >= self.f_prev {
            let p = self.segs[self.cur].peak(law, &mut self.buf);
            self.consider(p, self.buf);
            if self.count > 0 {
                let p = self.segs[1 - self.cur].peak(law, &mut self.buf);
                self.consider(p, self.buf);
            }
        }
        self.consider((tb, f_end), y_end);
        self.f_prev = self.f_node;
        self.f_node = f_end;
        self.cur = 1 - self.cur;
        self.count += 1;
    }

    fn finish(&mut self, law: &ForceLaw) -> (f64, f64) {
        if self.count > 0 && self.f_node >= self.f_prev {
            let p = self.segs[1 - self.cur].peak(law, &mut self.buf);
            self.consider(p, self.buf);
        }
        self.best
    }
}

/// Integrates one impact of `law` for the relative motion `setup` from first touch to the end of contact.
///
/// The contact ends when the penetration returns to 0, or, if `tension` is [`Tension::Clamp`], when the
/// force first reaches 0 in restitution (after which the bodies fly apart). Forces in the reported history
/// of a clamped contact are never negative.
///
/// ```
/// use pounding::contact::{ForceLaw, Tension};
/// use pounding::impact::{simulate, ImpactOptions, ImpactSetup};
/// // An elastic linear spring: the bodies leave at the speed they came, after half a period.
/// let law = ForceLaw::Elastic { k: 1.0e8, n: 1.0 };
/// let r = simulate(&law, Tension::Clamp, &ImpactSetup::relative(1.0e3, 0.5), &ImpactOptions::default())?;
/// assert!((r.e_post - 1.0).abs() < 1e-9);
/// assert!((r.contact_duration - std::f64::consts::PI * (1.0e3f64 / 1.0e8).sqrt()).abs() < 1e-12);
/// # Ok::<(), pounding::Error>(())
/// ```
pub fn simulate(
    law: &ForceLaw,
    tension: Tension,
    setup: &ImpactSetup,
    opts: &ImpactOptions,
) -> Result<ImpactResult, Error> {
    let (m, v_i) = (setup.mass, setup.v_i);
    let len = law.length_scale(m, v_i);
    let tau = len / v_i;
    let rtol_floor = 1e-14; // the tightest relative tolerance used below
    if [len, tau, m * v_i, m * v_i * v_i]
        .iter()
        .any(|s| !(s * rtol_floor).is_normal() || !(s / rtol_floor).is_finite())
    {
        return Err(Error::ScaleOutOfRange { mass: m, v_i });
    }
    // A law that is not smooth at touch starts with a step so small that the singular start contributes
    // below 1e-14 of the velocity, and is integrated 100 times tighter: its error estimate is pessimistic
    // by a constant factor while steps are as long as the time since touch (measured: 2e-9 at 1e-11).
    let (rtol, h0) = if law.smooth_at_touch() {
        (opts.rtol, 1e-2 * tau)
    } else {
        ((opts.rtol * 1e-2).max(1e-14), 1e-12 * tau)
    };
    let mut dp = DormandPrince::new(Tolerance {
        rtol,
        atol: vec![rtol * len, rtol * v_i, rtol * m * v_i, rtol * m * v_i * v_i],
    });
    let mut ode = Ode {
        law,
        phase: Phase::Approach,
        turn: Turn::default(),
        m,
        g: setup.gravity,
    };
    let clamp = |f: f64| match tension {
        Tension::Clamp => f.max(0.0),
        Tension::Allow => f,
    };
    let mut y0 = [0.0, v_i, 0.0, 0.0];
    let f0 = ode.force(&y0);
    let mut history = opts.history.then(History::default);
    let record = |h: &mut Option<History>, t: f64, y: &[f64], f: f64| {
        if let Some(h) = h {
            h.t.push(t);
            h.penetration.push(y[0]);
            h.rate.push(y[1]);
            h.force.push(f);
        }
    };
    record(&mut history, 0.0, &y0, clamp(f0));
    let mut peak = PeakTracker::new(clamp(f0), y0);
    let mut max_penetration = 0.0;
    dp.reset(&ode, 0.0, &y0, h0);
    let t_limit = 1e4 * tau;
    let mut ye = [0.0; DIM];
    loop {
        let t0 = dp.t();
        dp.step(&ode)?;
        let t1 = dp.t();
        let y1 = dp.y();
        if t1 > t_limit || dp.counts().0 > 1_000_000 {
            return Err(Error::ContactNeverEnds { t: t1 });
        }
        // Earliest event in this step, located on the interpolant.
        let mut first: Option<(f64, Event)> = None;
        let dense = dp.dense();
        // Every event function is positive before its event and <= 0 after it; the located time is nudged
        // to the far side so that a restarted step never finds the same event again.
        let mut locate = |ev: Event, g: &dyn Fn(&[f64]) -> f64| {
            let (g0, g1) = (g(&y0), g(y1));
            if g1 > 0.0 {
                return;
            }
            let mut buf = [0.0; DIM];
            let mut at = |t: f64| {
                dense.eval(t, &mut buf);
                g(&buf)
            };
            let xtol = 4.0 * f64::EPSILON * t1 + 1e-300;
            let mut te = brent_root(&mut at, t0, t1, g0.max(0.0), g1, xtol).unwrap_or(t1);
            let mut nudge = xtol;
            while te < t1 && at(te) > 0.0 {
                te = (te + nudge).min(t1);
                nudge *= 2.0;
            }
            if first.is_none_or(|(tf, _)| te < tf) {
                first = Some((te, ev));
            }
        };
        let (phase, turn) = (ode.phase, ode.turn);
        match phase {
            Phase::Approach => locate(Event::Turn, &|y: &[f64]| y[1]),
            Phase::Restitution => {
                locate(Event::Separation, &|y: &[f64]| y[0]);
                if tension == Tension::Clamp {
                    locate(Event::ZeroForce, &|y: &[f64]| {
                        law.force(y[0], y[1], phase, &turn)
                    });
                }
            }
        }
        if law.kink(0.0, phase, &turn).is_some() {
            let kink = |y: &[f64]| law.kink(y[0], phase, &turn).unwrap_or(1.0);
            if kink(&y0) > 0.0 {
                locate(Event::Kink, &kink);
            }
        }
        let (te, event) = match first {
            Some((te, ev)) => {
                dense.eval(te, &mut ye);
                (te, Some(ev))
            }
            None => {
                ye.copy_from_slice(y1);
                (t1, None)
            }
        };
        let fe = ode.force(&ye);
        peak.push(law, dense, (t0, te), phase, turn, (clamp(fe), ye));
        record(&mut history, te, &ye, clamp(fe));
        match event {
            None => {}
            Some(Event::Turn) => {
                max_penetration = ye[0];
                ode.phase = Phase::Restitution;
                ode.turn = Turn {
                    d: ye[0],
                    force: fe,
                };
                let h = dp.h();
                dp.reset(&ode, te, &ye, h);
            }
            Some(Event::Kink) => {
                let h = dp.h();
                dp.reset(&ode, te, &ye, h);
            }
            Some(Event::Separation | Event::ZeroForce) => {
                let (time_of_peak_force, peak_force) = peak.finish(law);
                if let Some(h) = history.as_mut() {
                    // The located peak joins the history, so that a plot of it shows the true peak force.
                    let k = h.t.partition_point(|&t| t < time_of_peak_force);
                    if h.t.get(k) != Some(&time_of_peak_force) {
                        let y = peak.best_y;
                        h.t.insert(k, time_of_peak_force);
                        h.penetration.insert(k, y[0]);
                        h.rate.insert(k, y[1]);
                        h.force.insert(k, peak_force);
                    }
                }
                return Ok(ImpactResult {
                    e_post: -ye[1] / v_i,
                    peak_force,
                    time_of_peak_force,
                    max_penetration,
                    contact_duration: te,
                    dissipated_energy: ye[3],
                    impulse: ye[2],
                    v_out: ye[1],
                    steps: dp.counts().0,
                    history,
                });
            }
        }
        y0 = ye;
    }
}
