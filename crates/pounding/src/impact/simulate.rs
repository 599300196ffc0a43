//! One impact, integrated by the engine's driver: one degree of freedom (the relative motion, with the
//! effective mass) against a contact to the ground that starts engaged and stops the run when it ends.

use super::{History, ImpactOptions, ImpactResult, ImpactSetup};
use crate::contact::{ForceLaw, Tension};
use crate::element::{Contact, ContactPiece, Element, ElementLaw, End, Notice};
use crate::engine::{self, Dof, Ending, EventInfo, Ground, Observer, Segment, System};
use crate::integrate::PeakTracker;
use crate::Error;

/// Records the history (if asked), the force at given times (if asked), the largest force and the largest
/// penetration of the impact.
struct Recorder<'t> {
    history: Option<History>,
    /// Times since touch (s, increasing) at which to read the force on the interpolant, and the forces read.
    samples: (&'t [f64], Vec<f64>),
    peak: PeakTracker<ContactPiece>,
    max_penetration: f64,
}

impl Recorder<'_> {
    fn record(&mut self, t: f64, d: f64, v: f64, f: f64) {
        if let Some(h) = self.history.as_mut() {
            h.t.push(t);
            h.penetration.push(d);
            h.rate.push(v);
            h.force.push(f);
        }
    }
}

impl Observer for Recorder<'_> {
    fn segment(&mut self, seg: &Segment<'_, '_>) {
        let sys = seg.system;
        let Some(c) = sys.elements()[0].law.as_contact() else {
            return;
        };
        // The law's phase holds over the segment (events end segments): its force on the interpolant.
        let (times, forces) = &mut self.samples;
        while let Some(&t) = times.get(forces.len()).filter(|&&t| t <= seg.t1) {
            let (d, rate) = sys.deformation_at(0, seg.dense, t.max(seg.t0));
            forces.push(c.force(d, rate, &[]));
        }
        let (x, v) = sys.deformation_interpolants(0, seg.dense);
        if let Some(piece) = c.piece((seg.t0, seg.t1), x, v) {
            let (d, rate) = sys.deformation(0, seg.y1);
            let f = c.force(d, rate, &[]);
            self.peak.push(piece, f);
            self.record(seg.t1, d, rate, f);
        }
    }

    fn event(&mut self, ev: &EventInfo<'_, '_>) {
        if ev.notice == Some(Notice::ImpactTurned) {
            self.max_penetration = ev.system.deformation(0, ev.y).0;
        }
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
    integrate(law, tension, setup, opts, &[]).map(|r| r.0)
}

/// The contact force (N) of one impact (as [`simulate`]) at each of `times` (s since first touch, any
/// order): read on the integrator's interpolant, so as accurate as the motion; 0 before touch and after the
/// contact ends. For comparing the law with a measured force history.
pub fn force_at(
    law: &ForceLaw,
    tension: Tension,
    setup: &ImpactSetup,
    opts: &ImpactOptions,
    times: &[f64],
) -> Result<Vec<f64>, Error> {
    let mut order: Vec<usize> = (0..times.len()).collect();
    order.sort_by(|&a, &b| times[a].total_cmp(&times[b]));
    let first = order.partition_point(|&k| times[k] < 0.0);
    let sorted: Vec<f64> = order[first..].iter().map(|&k| times[k]).collect();
    let (_, read) = integrate(law, tension, setup, opts, &sorted)?;
    let mut out = vec![0.0; times.len()];
    for (&k, f) in order[first..].iter().zip(read) {
        out[k] = f;
    }
    Ok(out)
}

/// [`simulate`], and the force at `times` (s since touch, increasing, none negative) while in contact.
fn integrate(
    law: &ForceLaw,
    tension: Tension,
    setup: &ImpactSetup,
    opts: &ImpactOptions,
    times: &[f64],
) -> Result<(ImpactResult, Vec<f64>), Error> {
    let (m, v_i) = (setup.mass, setup.v_i);
    let len = law.length_scale(m, v_i);
    let tau = len / v_i;
    // The tightest relative tolerance used below is 1e-14: each scale, times or over it, must stay a normal
    // finite number.
    let (lo, hi) = super::SCALE_RANGE;
    if [len, tau, m * v_i, m * v_i * v_i]
        .iter()
        .any(|s| !(lo..=hi).contains(s))
    {
        let (k, n) = law.scale_stiffness();
        return Err(Error::ScaleOutOfRange { mass: m, v_i, k, n });
    }
    // A law that is not smooth at touch starts with a step so small that the singular start contributes
    // below 1e-14 of the velocity, and is integrated 100 times tighter: its error estimate is pessimistic
    // by a constant factor while steps are as long as the time since touch (measured: 2e-9 at 1e-11).
    let (rtol, h0) = if law.smooth_at_touch() {
        (opts.rtol, 1e-2 * tau)
    } else {
        ((opts.rtol * 1e-2).max(1e-14), 1e-12 * tau)
    };
    // Gravity pushes the body into the slab: a ground acceleration of -g.
    let mut sys = System::new(
        &[Dof::x(m, 0.0)],
        vec![Element::new(
            End::Dof(0),
            End::Ground,
            Contact::engaged(*law, tension, m),
        )],
        Ground::Constant(-setup.gravity),
    );
    let layout = sys.layout().clone();
    // The input and damping energies are not read: only the contact's works are controlled.
    let mut atol = vec![f64::INFINITY; layout.dim()];
    for k in layout.block(0) {
        atol[k] = rtol * m * v_i * v_i;
    }
    atol[layout.u(0)] = rtol * len;
    atol[layout.v(0)] = rtol * v_i;
    let mut y0 = vec![0.0; layout.dim()];
    y0[layout.v(0)] = v_i;

    let f0 = sys.elements()[0].force(0.0, v_i, &[0.0, 0.0]);
    let mut rec = Recorder {
        history: opts.history.then(History::default),
        samples: (times, Vec::with_capacity(times.len())),
        peak: PeakTracker::new(0.0, f0),
        max_penetration: 0.0,
    };
    rec.record(0.0, 0.0, v_i, f0);
    let settings = engine::Settings {
        t_end: 1e4 * tau,
        rtol,
        atol,
        h0,
        max_steps: 1_000_000,
        propagation: engine::Propagation::default(),
    };
    let out = engine::run(&mut sys, (0.0, &y0), &settings, &mut rec)?;
    if out.ending != Ending::Stopped {
        return Err(Error::ContactNeverEnds { t: out.t });
    }
    let (time_of_peak_force, peak_force) = rec.peak.finish();
    let mut history = rec.history;
    if let (Some(h), Some(piece)) = (history.as_mut(), rec.peak.best_piece()) {
        // The located peak joins the history, so that a plot of it shows the true peak force.
        let k = h.t.partition_point(|&t| t < time_of_peak_force);
        if h.t.get(k) != Some(&time_of_peak_force) {
            let (d, v, _) = piece.at(time_of_peak_force);
            h.t.insert(k, time_of_peak_force);
            h.penetration.insert(k, d);
            h.rate.insert(k, v);
            h.force.insert(k, peak_force);
        }
    }
    let v_out = out.y[layout.v(0)];
    let mut read = rec.samples.1;
    // Times after the contact ended read no force.
    read.resize(times.len(), 0.0);
    let result = ImpactResult {
        e_post: -v_out / v_i,
        peak_force,
        time_of_peak_force,
        max_penetration: rec.max_penetration,
        contact_duration: out.t,
        dissipated_energy: sys.elements()[0]
            .law
            .as_contact()
            .map_or(0.0, |c| c.dissipated(&out.y[layout.block(0)])),
        // m d'' = m g - F, so the impulse of F is m (v_i - v_out) + m g T.
        impulse: m * (v_i - v_out) + m * setup.gravity * out.t,
        v_out,
        steps: out.steps,
        history,
    };
    Ok((result, read))
}
