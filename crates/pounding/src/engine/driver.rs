//! The driver: step, locate the earliest event of any element, apply it, restart.

use super::propagator::{Propagation, Propagator};
use super::{EventInfo, Ground, Observer, Segment, System};
use crate::element::{ElementLaw, Event};
use crate::ground_motion::Record;
use crate::integrate::{brent_root, golden_max, Dense, OdeSystem, Tolerance};
use crate::Error;

/// Accuracy and extent of a run.
#[derive(Clone, Debug)]
pub struct Settings {
    /// End time, s.
    pub t_end: f64,
    /// Relative tolerance (dimensionless).
    pub rtol: f64,
    /// Absolute tolerance of each state component, in its unit (see [`super::Layout`]).
    pub atol: Vec<f64>,
    /// First trial step, s.
    pub h0: f64,
    /// Largest number of steps, accepted and rejected, in explicit steps (an implicit step of a stiff stretch
    /// counts as the explicit steps its work would buy: [`crate::integrate::Stepper::work`]).
    pub max_steps: usize,
    /// How the run advances between events.
    pub propagation: Propagation,
}

/// Why a run ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Ending {
    /// It reached the end time.
    Time,
    /// An element asked to stop (a single impact's contact ended).
    Stopped,
    /// It took the largest number of steps allowed.
    StepBudget,
    /// An observer asked to stop.
    Cancelled,
}

/// The end of a run.
#[derive(Clone, Debug, PartialEq)]
pub struct Outcome {
    /// Why it ended.
    pub ending: Ending,
    /// Time reached, s.
    pub t: f64,
    /// State there.
    pub y: Vec<f64>,
    /// Accepted steps.
    pub steps: usize,
    /// Rejected steps.
    pub rejected: usize,
    /// Events applied.
    pub events: usize,
}

/// The earliest event of any element in the step `[t0, t1]` (states `y0`, `y1`): `(time, element, event)`.
/// Every event function is positive before its event and <= 0 after it; the located time is nudged to the far
/// side, so that a restarted step never finds the same event again. `states` is room for one element's
/// states on the interpolant, `motion` for the displacements and velocities.
fn earliest_event(
    sys: &System,
    (t0, y0): (f64, &[f64]),
    (t1, y1, dense): (f64, &[f64], &Dense),
    (states, motion): (&mut [f64], &mut [f64]),
) -> Option<(f64, usize, Event)> {
    let mut first: Option<(f64, usize, Event)> = None;
    for (e, el) in sys.elements().iter().enumerate() {
        let watched = el.watched();
        if watched.is_empty() {
            continue;
        }
        let block = sys.layout().block(e);
        let (xa, va) = sys.deformation(e, y0);
        let (xb, vb) = sys.deformation(e, y1);
        for w in watched {
            let ev = w.event;
            let ga = el.event_value(ev, xa, va, &y0[block.clone()]);
            if ga <= 0.0 && w.keeps_phase {
                continue;
            }
            let gb = el.event_value(ev, xb, vb, &y1[block.clone()]);
            let s = &mut states[..block.len()];
            // The states along the step only for a law whose event functions read them.
            let reads = el.law.events_read_states();
            // On an exact step of one piece, the deformation and its rate as two polynomials, read off
            // the step's series at the first evaluation, not from the motion's components at each.
            let single = dense.motion().is_some_and(|m| m.pieces() == 1);
            let mut series = None;
            let mut g = |t: f64| {
                let (x, v) = if single {
                    let (x, v) =
                        series.get_or_insert_with(|| sys.deformation_interpolants(e, dense));
                    (x.eval(t), v.eval(t))
                } else {
                    sys.deformation_at(e, dense, t)
                };
                for (k, z) in block.clone().zip(s.iter_mut()).filter(|_| reads) {
                    *z = dense.component(t, k);
                }
                el.event_value(ev, x, v, s)
            };
            // The far end of the bracket: the step end, or, for a touch that comes and goes within one step
            // (the ends turn back inside it), the largest penetration.
            // An event is a crossing from positive to <= 0, or a function found negative at the step end; a
            // function that stays at exactly 0 (a storey at rest: its drift rate is identically 0) is no event.
            // A whole interval taken at once: an event function may dip below 0 and back inside it, which
            // its ends do not show; its pieces' starts do, as a series-length step's ends would.
            let crossed = piece_crossing(sys, (e, ev), (dense, y0), motion);
            let far = if let Some((_, crossed)) = crossed {
                Some(crossed)
            } else if gb < 0.0 || (gb == 0.0 && ga > 0.0) {
                Some((t1, gb))
            } else if w.graze.is_some_and(|g| g.turns(va, vb))
                && grazes(el, ev, &y1[block.clone()], (xa, va), (xb, vb), t1 - t0)
            {
                let (tm, gm) = golden_max(|t| -g(t), t0, t1, 1e-12 * (t1 - t0));
                (-gm <= 0.0).then_some((tm, -gm))
            } else {
                None
            };
            let Some((tb, gb)) = far else { continue };
            // Inside a whole interval, the crossing is bracketed by the pieces' starts on either side of it:
            // the function may cross and come back between the step's start and there. A function that
            // starts at 0 (a touch watched from the separation that just ended an impact) may rise and come
            // back within one step (the ends part and close again): its crossing is searched from its largest
            // value.
            let near = crossed.and_then(|(near, _)| near);
            let (ta, ga) = if let Some(near) = near {
                near
            } else if ga <= 0.0 {
                let (tm, gm) = golden_max(&mut g, t0, tb, 1e-12 * (tb - t0));
                if gm > 0.0 {
                    (tm, gm)
                } else {
                    (t0, 0.0)
                }
            } else {
                (t0, ga)
            };
            let xtol = 4.0 * f64::EPSILON * tb.abs() + 1e-300;
            let mut te = brent_root(&mut g, ta, tb, ga, gb, xtol).unwrap_or(tb);
            let mut nudge = xtol;
            while te < tb && g(te) > 0.0 {
                te = (te + nudge).min(tb);
                nudge *= 2.0;
            }
            if first.is_none_or(|(tf, _, _)| te < tf) {
                first = Some((te, e, ev));
            }
        }
    }
    first
}

/// Puts the event `ev` of element `e`, located at `te` on the interpolant of the step from `(t0, y0)`, on
/// the solution as the steps hold it. The step is taken again to end at `te` ([`Propagator::settle_at`]):
/// the interpolant's error, which nothing controls, was 1e-7 of an impact's rebound velocity at tolerance
/// 1e-10, and entered the run at every event. Where the event function is not 0 there, the state is moved
/// to its root by Newton steps in time along the state's rate, carried by Heun's rule (each move at most
/// 1e-3 of the step: its error is far below the step's), until the function is <= 0, as every event
/// leaves it. The state at the event goes to `ye`, its time is returned; `None` when the step to `te` was
/// refused and a shorter one taken (the event lies beyond it). `scratch`: room for the element's states, a
/// state and two rates.
fn settle_event(
    dp: &mut Propagator,
    sys: &System,
    (t0, y0): (f64, &[f64]),
    (te, e, ev): (f64, usize, Event),
    ye: &mut [f64],
    scratch: Scratch<'_>,
) -> Result<Option<f64>, Error> {
    // The step as first taken ends here, never past a kink of the ground motion.
    let t1 = dp.t();
    if !dp.settle_at(sys, (t0, y0), te, ye)? {
        return Ok(None);
    }
    // An event at the step's end, or on an exact solution, is where it was located.
    if te >= t1 || dp.is_exact() {
        return Ok(Some(te));
    }
    let (states, y_mid, f_mid, f_now) = scratch;
    f_now.copy_from_slice(dp.dydt());
    let el = &sys.elements()[e];
    let block = sys.layout().block(e);
    let states = &mut states[..block.len()];
    let value = |y: &[f64]| {
        let (x, v) = sys.deformation(e, y);
        el.event_value(ev, x, v, &y[block.clone()])
    };
    let mut g = value(ye);
    if g == 0.0 {
        return Ok(Some(te));
    }
    // The function's rate along the motion, by a difference over a small fraction of the step.
    let h = te - t0;
    let eps = 1e-4 * h;
    let (x, v) = sys.deformation(e, ye);
    let (dx, dv) = sys.deformation(e, f_now);
    for (k, z) in block.clone().zip(states.iter_mut()) {
        *z = ye[k] + eps * f_now[k];
    }
    let slope = (el.event_value(ev, x + eps * dx, v + eps * dv, states) - g) / eps;
    let mut t = te;
    // The first move aims at the root; a further one, needed only if that left the function above 0, past it.
    for aim in [1.0, 2.0, 4.0, 8.0] {
        let dt = -aim * g / slope;
        let tn = t + dt;
        // Only moves far smaller than the step, inside it: Heun's error over `dt` is about `(dt w)^3 / 12` of
        // the motion, below 1e-10 for `dt <= 1e-3 h` where the step resolves `w` (`h w <= 1`). A function with
        // a kink (a held contact's `max(d, v)`) or a flat slope stays where it was located.
        if !dt.is_finite() || tn <= t0 || tn > t1 || (tn - te).abs() > 1e-3 * h {
            break;
        }
        for ((m, y), f) in y_mid.iter_mut().zip(ye.iter()).zip(f_now.iter()) {
            *m = y + dt * f;
        }
        sys.rhs(tn, y_mid, f_mid);
        for ((y, f0), f1) in ye.iter_mut().zip(f_now.iter()).zip(f_mid.iter()) {
            *y += 0.5 * dt * (f0 + f1);
        }
        t = tn;
        g = value(ye);
        if g <= 0.0 {
            break;
        }
        sys.rhs(t, ye, f_now);
    }
    Ok(Some(t))
}

/// Room for [`settle_event`]: an element's states, a state and two rates.
type Scratch<'s> = (&'s mut [f64], &'s mut [f64], &'s mut [f64], &'s mut [f64]);

/// A time and an event function's value there, s and the function's unit.
type Sample = (f64, f64);

/// On a whole interval taken at once (more than one piece), the first start of a piece where the event
/// function of `ev` of element `e` is <= 0, with its value there, and the start of the piece before it when
/// that is inside the step and the function positive there (the element's deformation from its probe rows,
/// [`crate::integrate::Motion::probe`], else from the chain of pieces; `y0` the state at the step's start).
fn piece_crossing(
    sys: &System,
    (e, ev): (usize, Event),
    (dense, y0): (&Dense, &[f64]),
    motion: &mut [f64],
) -> Option<(Option<Sample>, Sample)> {
    let m = dense.motion().filter(|m| m.pieces() > 1)?;
    let el = &sys.elements()[e];
    // Whole intervals are taken while every law is affine, whose own states (a work) do not enter its
    // force or its events: the states at the step's start stand for them.
    let states = &y0[sys.layout().block(e)];
    let mut before = None;
    for k in 1..m.pieces() {
        let (x, v) = m.probe(e, k).unwrap_or_else(|| {
            m.piece_start(k, motion);
            sys.deformation(e, motion)
        });
        let g = el.event_value(ev, x, v, states);
        let here = (dense.t0() + k as f64 * m.piece(), g);
        if g <= 0.0 {
            return Some((before, here));
        }
        before = Some(here);
    }
    None
}

/// Whether a touch or a separation may come and go inside a step whose deformation turns inside it: the
/// distance at the turn, on the cubic Hermite of the deformation (within a few thousandths of the step's
/// motion of the true one on the steps the engine takes), is not clearly positive.
fn grazes(
    el: &crate::element::Element,
    ev: Event,
    states: &[f64],
    (xa, va): (f64, f64),
    (xb, vb): (f64, f64),
    h: f64,
) -> bool {
    let p = crate::integrate::Hermite::new(xa, xb, va, vb, h);
    let scale = xa.abs().max(xb.abs()) + h * (va.abs() + vb.abs());
    p.extrema()
        .into_iter()
        .any(|s| !s.is_nan() && el.event_value(ev, p.at(s), 0.0, states) <= 1e-2 * scale)
}

/// The kinks of the ground motion: every sample of its records, where a record arrives late the start of its
/// ramp, and the end of each record (its acceleration jumps to 0 there).
enum Kinks<'a> {
    /// One time grid (one record, or two on one grid): the next sample is `first + k dt`.
    Grid {
        first: f64,
        dt: f64,
        count: usize,
        k: usize,
        ends: [Option<f64>; 2],
    },
    /// Records on grids of their own (supports): the earliest next kink of any.
    Many(&'a [Record]),
    /// No record.
    None,
}

impl<'a> Kinks<'a> {
    fn of(ground: Ground<'a>) -> Self {
        match ground {
            Ground::Record(r) => Kinks::Grid {
                first: r.t0(),
                dt: r.dt(),
                count: r.npts(),
                k: 0,
                ends: [Some(r.duration()), None],
            },
            // Two components share one grid (their own lengths): both samples and both ends are kinks.
            Ground::Plane { x, y } => Kinks::Grid {
                first: x.t0(),
                dt: x.dt(),
                count: x.npts().max(y.npts()),
                k: 0,
                ends: [Some(x.duration()), Some(y.duration())],
            },
            Ground::Many(rs) => Kinks::Many(rs),
            Ground::Constant(_) => Kinks::None,
        }
    }

    /// The first kink after `t`, if any.
    fn next_after(&mut self, t: f64) -> Option<f64> {
        match self {
            Kinks::Grid {
                first,
                dt,
                count,
                k,
                ..
            } => {
                let at = |k: usize| *first + k as f64 * *dt;
                while *k < *count && at(*k) <= t {
                    *k += 1;
                }
                (*k < *count).then(|| at(*k))
            }
            // Two records' kinks a rounding apart (grids offset by a delay that is not a whole number of
            // steps in binary) are one kink: the step between them would be shorter than any stepper takes.
            Kinks::Many(rs) => rs
                .iter()
                .filter_map(|r| {
                    let t = t + Self::slack(t, r.dt());
                    if r.delay() > t {
                        return Some(r.delay());
                    }
                    let (first, dt) = (r.t0(), r.dt());
                    let mut k = ((t - first) / dt).floor().max(-1.0) as i64 + 1;
                    while k >= 0 && first + k as f64 * dt <= t {
                        k += 1;
                    }
                    let k = k.max(0) as usize;
                    (k < r.npts()).then_some(first + k as f64 * dt)
                })
                .reduce(f64::min),
            Kinks::None => None,
        }
    }

    /// How close two kinks near `t` on grids of step `dt` (s) may be and still be one: a few roundings of
    /// the times, s.
    fn slack(t: f64, dt: f64) -> f64 {
        16.0 * f64::EPSILON * (t.abs() + dt)
    }

    /// Whether a record ends at `t` (its acceleration jumps to 0).
    fn ends_at(&self, t: f64) -> bool {
        match self {
            Kinks::Grid { ends, .. } => ends.contains(&Some(t)),
            Kinks::Many(rs) => rs
                .iter()
                .any(|r| (r.duration() - t).abs() <= Self::slack(t, r.dt())),
            Kinks::None => false,
        }
    }
}

/// Runs `sys` from `(t0, y0)` to `settings.t_end`, or until an element stops it, telling `observer` every
/// segment and event. Steps end at every sample of a record (its acceleration has a kink there) and restart
/// where the record ends (its acceleration jumps to 0) and at every event.
pub fn run(
    sys: &mut System,
    (t_start, y_start): (f64, &[f64]),
    settings: &Settings,
    observer: &mut dyn Observer,
) -> Result<Outcome, Error> {
    let dim = sys.dim();
    let mut dp = Propagator::new(
        sys,
        Tolerance {
            rtol: settings.rtol,
            atol: settings.atol.clone(),
            quiet: sys.quiet_components(),
            absolute: sys.work_components(),
        },
        settings.propagation,
    );
    let mut y0 = y_start.to_vec();
    let mut ye = vec![0.0; dim];
    let mut rate = vec![0.0; dim];
    let (mut y_mid, mut f_mid, mut f_now) = (vec![0.0; dim], vec![0.0; dim], vec![0.0; dim]);
    dp.reset(sys, t_start, &y0, settings.h0);
    let t_end = settings.t_end;
    // Kinks of the ground motion: the samples of a record, and its end.
    let mut kinks = Kinks::of(sys.ground());
    let mut t0 = t_start;
    let mut events = 0usize;
    // Events applied in a row without time advancing: a state that keeps firing is a bug or a model that
    // chatters, reported instead of looping.
    let mut stalled = 0usize;
    let mut disarmed: Vec<usize> = Vec::new();
    // Room for the states of the element with the most (event functions may read them between nodes).
    let most = (0..sys.elements().len())
        .map(|e| sys.layout().block(e).len())
        .max()
        .unwrap_or(0);
    let mut states = vec![0.0; most];
    let mut motion = vec![0.0; 2 * sys.layout().dofs()];
    let mut ending = Ending::Time;
    while t0 < t_end {
        let t_stop = kinks.next_after(t0).map_or(t_end, |t| t.min(t_end));
        dp.step_until(&*sys, t_stop)?;
        let mut first = earliest_event(
            sys,
            (t0, &y0),
            (dp.t(), dp.y(), dp.dense()),
            (&mut states, &mut motion),
        );
        // The trial step that follows the step as first taken.
        let h = dp.h();
        if let Some((te, e, ev)) = first {
            // None when a step to the event was refused: the shorter one taken ends before it.
            let scratch = (
                &mut states[..],
                &mut y_mid[..],
                &mut f_mid[..],
                &mut f_now[..],
            );
            first = settle_event(&mut dp, sys, (t0, &y0), (te, e, ev), &mut ye, scratch)?
                .map(|te| (te, e, ev));
        }
        let t1 = dp.t();
        let te = match first {
            Some((te, _, _)) => {
                sys.rhs(te, &ye, &mut rate);
                te
            }
            None => {
                ye.copy_from_slice(dp.y());
                rate.copy_from_slice(dp.dydt());
                t1
            }
        };
        observer.segment(&Segment {
            system: sys,
            t0,
            t1: te,
            y0: &y0,
            y1: &ye,
            rate1: &rate,
            dense: dp.dense(),
        });
        if let Some((te, e, ev)) = first {
            events += 1;
            stalled = if te > t0 { 0 } else { stalled + 1 };
            if stalled > 1000 {
                return Err(Error::EventChatter { t: te });
            }
            let (x, v) = sys.deformation(e, &ye);
            let block = sys.layout().block(e);
            let tr = sys.elements_mut()[e].apply(ev, x, v, &ye[block], h)?;
            if !sys.elements()[e].armed() && !disarmed.contains(&e) {
                disarmed.push(e);
            }
            dp.reset(&*sys, te, &ye, tr.h_max.unwrap_or(h));
            observer.event(&EventInfo {
                system: sys,
                t: te,
                element: e,
                event: ev,
                notice: tr.notice,
                y: &ye,
                rate: dp.dydt(),
            });
            if tr.stop {
                ending = Ending::Stopped;
                y0.copy_from_slice(&ye);
                t0 = te;
                break;
            }
        } else if kinks.ends_at(t1) && t1 < t_end {
            let h = dp.h();
            dp.reset(&*sys, t1, &ye, h);
        }
        // Elements whose next change of direction waits for their rate to clear its resolution.
        if !disarmed.is_empty() {
            disarmed.retain(|&e| {
                let (x, v) = sys.deformation(e, &ye);
                let block = sys.layout().block(e);
                sys.elements_mut()[e].rearm(x, v, &ye[block])
            });
        }
        y0.copy_from_slice(&ye);
        t0 = te;
        // Rejected steps cost as much as accepted ones.
        if dp.work() >= settings.max_steps as f64 {
            ending = Ending::StepBudget;
            break;
        }
        if observer.cancelled() {
            ending = Ending::Cancelled;
            break;
        }
    }
    let (steps, rejected) = dp.counts();
    Ok(Outcome {
        ending,
        t: t0,
        y: y0,
        steps,
        rejected,
        events,
    })
}
