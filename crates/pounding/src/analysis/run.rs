//! The driver: steps the equations of motion, locates contact events, and records what is asked for.

use super::dynamics::{energy_index, Dynamics, Engagement};
use super::{
    BuildingResponse, EnergyBalance, Histories, Impact, LinkResponse, Results, Scenario, Statistics,
};
use crate::contact::{ForceLaw, Phase, Tension, Turn};
use crate::integrate::{brent_root, golden_max, Dense, DormandPrince, Tolerance};
use crate::Error;

/// How far a run has got, for progress reports.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Progress {
    /// Time reached, s.
    pub t: f64,
    /// Duration of the analysis, s.
    pub duration: f64,
    /// Impacts so far.
    pub impacts: usize,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Event {
    /// Open: `d` reaches 0 from below.
    Touch,
    /// Approach: the rate reaches 0 (maximum penetration).
    Turn,
    /// A kink of the law (bilinear yield or unloading corner).
    Kink,
    /// Restitution, clamped law: the force reaches 0.
    ZeroForce,
    /// Restitution: `d` returns to 0.
    Separation,
    /// Restitution: the floors approach again (a bilinear law once back at its turning point).
    Reapproach,
    /// Released: `d` returns to 0.
    Rearm,
    /// Released: the floors approach again before `d` returned to 0.
    Resume,
}

/// Event function of `ev` for an element in `state`: positive before the event, <= 0 at and after it.
fn event_value(ev: Event, state: &Engagement, d: f64, v: f64) -> f64 {
    let (law, phase, turn) = match *state {
        Engagement::Contact { law, phase, turn } => (Some(law), phase, turn),
        Engagement::Released { law, turn } => (Some(law), Phase::Restitution, turn),
        Engagement::Open => (None, Phase::Approach, Turn::default()),
    };
    match ev {
        Event::Touch => -d,
        Event::Turn => v,
        Event::Kink => law.and_then(|l| l.kink(d, phase, &turn)).unwrap_or(1.0),
        Event::ZeroForce => law.map_or(1.0, |l| l.force(d, v, phase, &turn)),
        Event::Separation | Event::Rearm => d,
        Event::Reapproach => match law {
            Some(ForceLaw::Bilinear { .. }) => turn.d - d,
            _ => -v,
        },
        Event::Resume => -v,
    }
}

/// The events to watch for an element in `state`.
fn watched(state: &Engagement, tension: Tension) -> &'static [Event] {
    let kinked = |law: &ForceLaw| law.kink(0.0, Phase::Approach, &Turn::default()).is_some();
    match *state {
        Engagement::Open => &[Event::Touch],
        Engagement::Contact {
            law,
            phase: Phase::Approach,
            ..
        } => {
            if kinked(&law) {
                &[Event::Turn, Event::Kink]
            } else {
                &[Event::Turn]
            }
        }
        Engagement::Contact {
            law,
            phase: Phase::Restitution,
            ..
        } => match (tension, kinked(&law)) {
            (Tension::Clamp, true) => &[
                Event::Separation,
                Event::ZeroForce,
                Event::Reapproach,
                Event::Kink,
            ],
            (Tension::Clamp, false) => &[Event::Separation, Event::ZeroForce, Event::Reapproach],
            (Tension::Allow, true) => &[Event::Separation, Event::Reapproach, Event::Kink],
            (Tension::Allow, false) => &[Event::Separation, Event::Reapproach],
        },
        Engagement::Released { .. } => &[Event::Rearm, Event::Resume],
    }
}

/// The impact an element is in (or has just been released from).
#[derive(Clone, Copy, Debug)]
struct Tracker {
    time: f64,
    v_i: f64,
    work0: f64,
    peak_force: f64,
    time_of_peak_force: f64,
    max_penetration: f64,
    /// Index in the impact list once recorded (released, not yet re-armed).
    recorded: Option<usize>,
}

/// Penetration and rate of element `e` on the interpolant at `t`.
#[inline]
fn dv_at(sys: &Dynamics, e: usize, dense: &Dense, t: f64) -> (f64, f64) {
    let el = &sys.elements[e];
    let n = sys.n;
    (
        dense.component(t, el.left) - dense.component(t, el.right) - el.gap,
        dense.component(t, n + el.left) - dense.component(t, n + el.right),
    )
}

/// Largest `|p|` of the cubic Hermite interpolant of `p` (values `pa`, `pb`, slopes `va`, `vb`) on a step of
/// length `h`, over its interior extremum (if any) and its end: `(fraction of the step, |p|)`.
fn hermite_peak(pa: f64, pb: f64, va: f64, vb: f64, h: f64) -> (f64, f64) {
    let mut best = (1.0, pb.abs());
    if va * vb <= 0.0 && h > 0.0 {
        let dlt = pb - pa;
        let b = 3.0 * dlt - h * (2.0 * va + vb);
        let c = -2.0 * dlt + h * (va + vb);
        let p = |s: f64| pa + s * (h * va + s * (b + s * c));
        // p'(s) = h va + 2 b s + 3 c s^2.
        let (qa, qb, qc) = (3.0 * c, 2.0 * b, h * va);
        let mut roots = [f64::NAN; 2];
        if qa.abs() <= 1e-14 * (qb.abs() + qc.abs()) {
            if qb != 0.0 {
                roots[0] = -qc / qb;
            }
        } else {
            let disc = qb * qb - 4.0 * qa * qc;
            if disc >= 0.0 {
                let q = -0.5 * (qb + disc.sqrt().copysign(qb));
                roots = [q / qa, if q != 0.0 { qc / q } else { f64::NAN }];
            }
        }
        for s in roots {
            if (0.0..=1.0).contains(&s) && p(s).abs() > best.1 {
                best = (s, p(s).abs());
            }
        }
    }
    best
}

struct Peak {
    value: f64,
    time: f64,
}

pub(super) fn run(s: &Scenario, progress: &mut dyn FnMut(Progress)) -> Result<Results, Error> {
    let mut sys = Dynamics::new(s);
    let (n, dim, ne) = (sys.n, sys.dim(), sys.elements.len());
    let ei = energy_index(n);
    let rec = s.record();
    let t_end = s.duration();

    // Scales of the state for the absolute tolerances, per building: the static displacement of its
    // fundamental mode under the peak ground acceleration (or, for a building so flexible that it barely
    // responds within the analysis, of a mode with the analysis duration as period), and the velocity
    // that goes with it.
    let modes: Vec<_> = s.buildings().iter().map(|b| b.structure.modes()).collect();
    let w_max = modes
        .iter()
        .flat_map(|m| m.omega.iter().copied())
        .fold(0.0, f64::max);
    let pga = rec
        .accelerations()
        .iter()
        .fold(0.0f64, |a, x| a.max(x.abs()));
    let max_gap = s.links().iter().map(|l| l.gap).fold(0.0, f64::max);
    let w_floor = 2.0 * std::f64::consts::PI / t_end;
    let rtol = s.tolerance();
    let mut atol = vec![0.0; dim];
    let mut v_scale = vec![0.0; n];
    for (b, m) in sys.buildings.iter().zip(&modes) {
        let w = m.omega[0].max(w_floor);
        let u = (pga / (w * w)).max(1e-3 * max_gap).max(1e-9);
        for i in b.offset..b.offset + m.omega.len() {
            atol[i] = rtol * u;
            atol[n + i] = rtol * u * w;
            v_scale[i] = u * w;
        }
    }
    let e_scale: f64 = (0..n).map(|i| sys.mass[i] * v_scale[i] * v_scale[i]).sum();
    atol[ei] = rtol * e_scale;
    atol[ei + 1] = rtol * e_scale;
    for (e, el) in sys.elements.iter().enumerate() {
        let v = v_scale[el.left].max(v_scale[el.right]);
        atol[ei + 2 + e] = rtol * el.m_eff * v * v;
    }
    let mut dp = DormandPrince::new(Tolerance { rtol, atol });

    let mut y0 = vec![0.0; dim];
    let mut ye = vec![0.0; dim];
    let mut ys = vec![0.0; dim];
    dp.reset(&sys, 0.0, &y0, 1e-3 * 2.0 * std::f64::consts::PI / w_max);

    // Outputs.
    let n_out = s.output_samples();
    let mut hist = Histories {
        t: Vec::with_capacity(n_out),
        ground_acceleration: Vec::with_capacity(n_out),
        displacement: s
            .buildings()
            .iter()
            .map(|b| vec![Vec::with_capacity(n_out); b.structure.storeys()])
            .collect(),
        force: s
            .links()
            .iter()
            .map(|l| vec![Vec::with_capacity(n_out); l.floors.len()])
            .collect(),
        energy: std::array::from_fn(|_| Vec::with_capacity(n_out)),
    };
    let mut next_out = 0usize;
    let mut peak_u: Vec<Peak> = (0..n)
        .map(|_| Peak {
            value: 0.0,
            time: 0.0,
        })
        .collect();
    let mut peak_drift = vec![0.0; n];
    let first_floor: Vec<bool> = {
        let mut f = vec![false; n];
        for b in &sys.buildings {
            f[b.offset] = true;
        }
        f
    };
    let mut trackers: Vec<Option<Tracker>> = vec![None; ne];
    let mut impacts: Vec<Impact> = Vec::new();
    let mut stats = Statistics::default();
    let (mut worst_balance, mut energy_norm) = (0.0f64, 0.0f64);
    let mut last_report = f64::NEG_INFINITY;

    let breakpoint = |k: usize| rec.t0() + k as f64 * rec.dt();
    let mut k_bp = 0usize;
    let mut t0 = 0.0;

    while t0 < t_end {
        while k_bp < rec.npts() && breakpoint(k_bp) <= t0 {
            k_bp += 1;
        }
        let t_stop = if k_bp < rec.npts() {
            breakpoint(k_bp).min(t_end)
        } else {
            t_end
        };
        dp.step_until(&sys, t_stop)?;
        let t1 = dp.t();
        let dense = dp.dense();

        // The earliest event of any element in this step.
        let mut first: Option<(f64, usize, Event)> = None;
        for e in 0..ne {
            let state = sys.elements[e].state;
            let (da, va) = sys.penetration(e, &y0);
            let (db, vb) = sys.penetration(e, dp.y());
            for &ev in watched(&state, sys.elements[e].tension) {
                let ga = event_value(ev, &state, da, va);
                let gb = event_value(ev, &state, db, vb);
                let g = |t: f64| {
                    let (d, v) = dv_at(&sys, e, dense, t);
                    event_value(ev, &state, d, v)
                };
                // The far end of the bracket: the step end, or for a touch that comes and goes within one
                // step (the floors turn back inside it), the largest penetration.
                let far = if gb <= 0.0 {
                    Some((t1, gb))
                } else if ev == Event::Touch && va > 0.0 && vb < 0.0 {
                    let (tm, gm) = golden_max(|t| -g(t), t0, t1, 1e-12 * (t1 - t0));
                    (-gm <= 0.0).then_some((tm, -gm))
                } else {
                    None
                };
                let Some((tb, gb)) = far else { continue };
                if ev == Event::Kink && ga <= 0.0 {
                    continue;
                }
                let xtol = 4.0 * f64::EPSILON * tb.abs() + 1e-300;
                let mut te = brent_root(&g, t0, tb, ga.max(0.0), gb, xtol).unwrap_or(tb);
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
        let te = match first {
            Some((te, _, _)) => {
                dense.eval(te, &mut ye);
                te
            }
            None => {
                ye.copy_from_slice(dp.y());
                t1
            }
        };

        // Record the segment [t0, te], whose element states are those before the event.
        let h = te - t0;
        for i in 0..n {
            let (s_pk, u_pk) = hermite_peak(y0[i], ye[i], y0[n + i], ye[n + i], h);
            if u_pk > peak_u[i].value {
                peak_u[i] = Peak {
                    value: u_pk,
                    time: t0 + s_pk * h,
                };
            }
            let (ua, ub, va, vb) = if first_floor[i] {
                (y0[i], ye[i], y0[n + i], ye[n + i])
            } else {
                (
                    y0[i] - y0[i - 1],
                    ye[i] - ye[i - 1],
                    y0[n + i] - y0[n + i - 1],
                    ye[n + i] - ye[n + i - 1],
                )
            };
            peak_drift[i] = f64::max(peak_drift[i], hermite_peak(ua, ub, va, vb, h).1);
        }
        for (e, tr) in trackers.iter_mut().enumerate() {
            if let (Some(tr), Engagement::Contact { law, phase, turn }) =
                (tr.as_mut(), sys.elements[e].state)
            {
                let (t_max, fmax) = golden_max(
                    |t| {
                        let (d, v) = dv_at(&sys, e, dense, t);
                        law.force(d, v, phase, &turn)
                    },
                    t0,
                    te,
                    1e-12 * h.max(f64::MIN_POSITIVE),
                );
                if fmax > tr.peak_force {
                    (tr.peak_force, tr.time_of_peak_force) = (fmax, t_max);
                }
                tr.max_penetration = tr.max_penetration.max(sys.penetration(e, &ye).0);
            }
        }
        while next_out < n_out {
            let t_out = (next_out as f64 * s.output_dt()).min(t_end);
            if t_out > te {
                break;
            }
            dense.eval(t_out.max(t0), &mut ys);
            hist.t.push(t_out);
            hist.ground_acceleration.push(rec.at(t_out));
            for (b, bs) in sys.buildings.iter().enumerate() {
                for (f, col) in hist.displacement[b].iter_mut().enumerate() {
                    col.push(ys[bs.offset + f]);
                }
            }
            let mut e = 0;
            for link in hist.force.iter_mut() {
                for col in link.iter_mut() {
                    let f = sys.force(e, &ys);
                    col.push(match sys.elements[e].tension {
                        Tension::Clamp => f.max(0.0),
                        Tension::Allow => f,
                    });
                    e += 1;
                }
            }
            let (kin, strain) = sys.mechanical_energy(&ys);
            let work: f64 = ys[ei + 2..].iter().sum();
            for (col, x) in hist
                .energy
                .iter_mut()
                .zip([ys[ei], kin, strain, ys[ei + 1], work])
            {
                col.push(x);
            }
            next_out += 1;
        }
        {
            let (kin, strain) = sys.mechanical_energy(&ye);
            let work: f64 = ye[ei + 2..].iter().sum();
            let balance = ye[ei] - kin - strain - ye[ei + 1] - work;
            worst_balance = worst_balance.max(balance.abs());
            energy_norm = energy_norm.max(kin + strain + ye[ei + 1] + work.abs());
        }

        // Apply the event and restart the stepper there.
        if let Some((te, e, ev)) = first {
            stats.events += 1;
            let el = &sys.elements[e];
            let (d, v) = sys.penetration(e, &ye);
            let work = ye[ei + 2 + e];
            let link = &s.links()[el.link];
            let mut h_next = dp.h();
            let finish = |tr: &Tracker, impacts: &mut Vec<Impact>| {
                impacts.push(Impact {
                    link: el.link,
                    floors: el.floors,
                    time: tr.time,
                    v_i: tr.v_i,
                    v_out: Some(v),
                    e_post: (tr.v_i > 0.0).then(|| -v / tr.v_i),
                    peak_force: tr.peak_force,
                    time_of_peak_force: tr.time_of_peak_force,
                    max_penetration: tr.max_penetration,
                    duration: te - tr.time,
                    dissipated_energy: work - tr.work0,
                });
                impacts.len() - 1
            };
            let new_state = match (sys.elements[e].state, ev) {
                (Engagement::Open, Event::Touch) => {
                    let v_law = v.max(s.min_impact_velocity());
                    let (law, _) = link.contact.law(el.m_eff, v_law)?;
                    trackers[e] = Some(Tracker {
                        time: te,
                        v_i: v,
                        work0: work,
                        peak_force: 0.0,
                        time_of_peak_force: te,
                        max_penetration: 0.0,
                        recorded: None,
                    });
                    // Start each impact with a step well inside its time scale (far inside for a law that
                    // is not smooth at touch, see `impact::simulate`).
                    let tau = law.length_scale(el.m_eff, v_law) / v_law;
                    let f = if law.smooth_at_touch() { 1e-2 } else { 1e-8 };
                    h_next = h_next.min(f * tau);
                    Engagement::Contact {
                        law,
                        phase: Phase::Approach,
                        turn: Turn::default(),
                    }
                }
                (Engagement::Contact { law, .. }, Event::Turn) => {
                    let force = law.force(d, v, Phase::Approach, &Turn::default());
                    let turn = Turn { d, force };
                    if let Some(tr) = trackers[e].as_mut() {
                        tr.max_penetration = tr.max_penetration.max(d);
                    }
                    Engagement::Contact {
                        law,
                        phase: Phase::Restitution,
                        turn,
                    }
                }
                (state @ Engagement::Contact { .. }, Event::Kink) => state,
                (Engagement::Contact { law, turn, .. }, Event::Reapproach) => Engagement::Contact {
                    law,
                    phase: Phase::Approach,
                    turn,
                },
                (Engagement::Contact { law, turn, .. }, Event::ZeroForce) => {
                    if let Some(tr) = trackers[e].as_mut() {
                        tr.recorded = Some(finish(tr, &mut impacts));
                    }
                    Engagement::Released { law, turn }
                }
                (Engagement::Contact { .. }, Event::Separation) => {
                    if let Some(tr) = trackers[e].take() {
                        finish(&tr, &mut impacts);
                    }
                    Engagement::Open
                }
                (Engagement::Released { .. }, Event::Rearm) => {
                    trackers[e] = None;
                    Engagement::Open
                }
                (Engagement::Released { law, turn }, Event::Resume) => {
                    // The same impact goes on: withdraw its record.
                    if let Some(tr) = trackers[e].as_mut() {
                        if let Some(i) = tr.recorded.take() {
                            impacts.remove(i);
                            for t in trackers.iter_mut().flatten() {
                                if let Some(j) = t.recorded.as_mut() {
                                    if *j > i {
                                        *j -= 1;
                                    }
                                }
                            }
                        }
                    }
                    Engagement::Contact {
                        law,
                        phase: Phase::Approach,
                        turn,
                    }
                }
                (state, _) => state,
            };
            sys.elements[e].state = new_state;
            dp.reset(&sys, te, &ye, h_next);
        } else if t1 == rec.duration() && t1 < t_end {
            // The record stops: the ground acceleration jumps to 0.
            let h = dp.h();
            dp.reset(&sys, t1, &ye, h);
        }
        y0.copy_from_slice(&ye);
        t0 = te;
        if t0 - last_report >= 0.005 * t_end || t0 >= t_end {
            last_report = t0;
            progress(super::Progress {
                t: t0,
                duration: t_end,
                impacts: impacts.len() + trackers.iter().flatten().count(),
            });
        }
    }

    // Impacts still going on at the end of the analysis.
    for (e, tr) in trackers.iter().enumerate() {
        if let (Some(tr), Engagement::Contact { .. }) = (tr, sys.elements[e].state) {
            let el = &sys.elements[e];
            impacts.push(Impact {
                link: el.link,
                floors: el.floors,
                time: tr.time,
                v_i: tr.v_i,
                v_out: None,
                e_post: None,
                peak_force: tr.peak_force,
                time_of_peak_force: tr.time_of_peak_force,
                max_penetration: tr.max_penetration,
                duration: t_end - tr.time,
                dissipated_energy: y0[ei + 2 + e] - tr.work0,
            });
        }
    }
    impacts.sort_by(|a, b| a.time.total_cmp(&b.time));
    let (steps, rejected) = dp.counts();
    stats.steps = steps;
    stats.rejected = rejected;

    let buildings = sys
        .buildings
        .iter()
        .zip(s.buildings())
        .map(|(bs, b)| {
            let r = bs.offset..bs.offset + b.structure.storeys();
            BuildingResponse {
                peak_displacement: peak_u[r.clone()].iter().map(|p| p.value).collect(),
                time_of_peak_displacement: peak_u[r.clone()].iter().map(|p| p.time).collect(),
                peak_drift: peak_drift[r].to_vec(),
            }
        })
        .collect();
    let links = (0..s.links().len())
        .map(|l| {
            let mine = impacts.iter().filter(|i| i.link == l);
            LinkResponse {
                impacts: mine.clone().count(),
                peak_force: mine.clone().map(|i| i.peak_force).fold(0.0, f64::max),
                dissipated_energy: sys
                    .elements
                    .iter()
                    .enumerate()
                    .filter(|(_, el)| el.link == l)
                    .map(|(e, _)| y0[ei + 2 + e])
                    .sum(),
                max_penetration: mine.map(|i| i.max_penetration).fold(0.0, f64::max),
            }
        })
        .collect();
    let (kinetic, strain) = sys.mechanical_energy(&y0);
    let energy = EnergyBalance {
        input: y0[ei],
        kinetic,
        strain,
        damping: y0[ei + 1],
        contact: y0[ei + 2..].iter().sum(),
        relative_error: if energy_norm > 0.0 {
            worst_balance / energy_norm
        } else {
            0.0
        },
    };
    Ok(Results {
        buildings,
        links,
        impacts,
        energy,
        histories: hist,
        statistics: stats,
    })
}

#[cfg(test)]
mod tests {
    use super::hermite_peak;

    #[test]
    fn hermite_peak_of_a_cubic_is_exact() {
        // p(t) = sin-like cubic on [0, 2]: p = t (2 - t)^2 has its maximum 32/27 at t = 2/3.
        let p = |t: f64| t * (2.0 - t) * (2.0 - t);
        let dp = |t: f64| (2.0 - t) * (2.0 - t) - 2.0 * t * (2.0 - t);
        let (s, v) = hermite_peak(p(0.0), p(1.5), dp(0.0), dp(1.5), 1.5);
        assert!((v - 32.0 / 27.0).abs() < 1e-14);
        assert!((s * 1.5 - 2.0 / 3.0).abs() < 1e-12);
    }
}
