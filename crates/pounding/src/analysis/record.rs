//! What a pounding run keeps, as observers of the engine: peaks of floors and storeys, impacts, the energy
//! balance, and (optionally) histories at the output interval.

use super::model::{ContactRef, DeviceRef, Model};
use super::{Histories, Impact, ImpactLoop, Progress, Site, MAX_LOOP_POINTS};
use crate::element::{ContactPiece, Engagement, Event, Kind};
use crate::engine::{hermite_peak, EventInfo, Hermite, Observer, PeakTracker, Segment, System};
use std::ops::ControlFlow;

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

/// Peaks of every floor (degree of freedom) and every storey (indexed by the degree of freedom of its top
/// floor).
pub(super) struct Peaks {
    /// Element index of the storey under each floor.
    storey: Vec<usize>,
    pub displacement: Vec<Peak>,
    pub acceleration: Vec<Peak>,
    pub drift: Vec<f64>,
    pub shear: Vec<f64>,
}

impl Peaks {
    pub fn new(m: &Model) -> Self {
        let n = m.system.layout().dofs();
        Self {
            storey: m.storey_under.clone(),
            displacement: vec![Peak::default(); n],
            acceleration: vec![Peak::default(); n],
            drift: vec![0.0; n],
            shear: vec![0.0; n],
        }
    }

    fn accelerations(&mut self, sys: &System, t: f64, rate: &[f64]) {
        let ag = sys.ground().at(t);
        let l = sys.layout();
        for (i, p) in self.acceleration.iter_mut().enumerate() {
            p.offer((rate[l.v(i)] + ag).abs(), t);
        }
    }
}

impl Observer for Peaks {
    fn segment(&mut self, seg: &Segment<'_, '_>) {
        let sys = seg.system;
        let l = sys.layout();
        let (y0, y1) = (seg.y0, seg.y1);
        let h = seg.t1 - seg.t0;
        for i in 0..l.dofs() {
            let (s, u) = hermite_peak(y0[l.u(i)], y1[l.u(i)], y0[l.v(i)], y1[l.v(i)], h);
            self.displacement[i].offer(u, seg.t0 + s * h);
            // The storey under floor i: its drift, and its force at the drift's extrema and at the end.
            let e = self.storey[i];
            let el = &sys.elements()[e];
            let ((xa, va), (xb, vb)) = (sys.deformation(e, y0), sys.deformation(e, y1));
            let drift = Hermite::new(xa, xb, va, vb, h);
            self.drift[i] = self.drift[i].max(hermite_peak(xa, xb, va, vb, h).1);
            let block = l.block(e);
            let mut shear = el.force(xb, vb, &y1[block.clone()]).abs();
            for s in drift.extrema() {
                if s.is_nan() {
                    continue;
                }
                let t = seg.t0 + s * h;
                let mut states = [0.0; 2];
                for (k, z) in block.clone().zip(states.iter_mut()) {
                    *z = seg.dense.component(t, k);
                }
                shear = shear.max(el.force(drift.at(s), 0.0, &states[..block.len()]).abs());
            }
            self.shear[i] = self.shear[i].max(shear);
        }
        self.accelerations(sys, seg.t1, seg.rate1);
    }

    fn event(&mut self, ev: &EventInfo<'_, '_>) {
        // The acceleration just after the event (a contact force may jump at touch).
        self.accelerations(ev.system, ev.t, ev.rate);
    }
}

/// The impact a contact element is in (or has just been released from).
struct Tracker {
    time: f64,
    v_i: f64,
    work0: f64,
    peak: PeakTracker<ContactPiece>,
    max_penetration: f64,
    /// A resting contact (closing at less than the smallest impact velocity).
    resting: bool,
    /// Index in the impact list once recorded (released, not yet re-armed).
    recorded: Option<usize>,
    /// Its force–penetration path, if the run keeps them.
    path: Option<Path>,
}

/// The points of an impact's path so far. The last point is always the latest step; it stays only if it
/// falls on the stride (`tentative` otherwise, and the next step replaces it).
struct Path {
    points: ImpactLoop,
    steps: usize,
    tentative: bool,
}

impl Path {
    fn new(t: f64, d: f64, f: f64) -> Self {
        Self {
            points: ImpactLoop {
                t: vec![t],
                penetration: vec![d],
                force: vec![f],
                stride: 1,
            },
            steps: 0,
            tentative: false,
        }
    }

    fn push(&mut self, t: f64, d: f64, f: f64) {
        let p = &mut self.points;
        // A step of zero length (an event at the instant of the last one) adds no point.
        if p.t.last() == Some(&t) {
            let k = p.t.len() - 1;
            p.penetration[k] = d;
            p.force[k] = f;
            return;
        }
        if self.tentative {
            p.t.pop();
            p.penetration.pop();
            p.force.pop();
        }
        p.t.push(t);
        p.penetration.push(d);
        p.force.push(f);
        self.steps += 1;
        self.tentative = self.steps % p.stride != 0;
        if p.t.len() > MAX_LOOP_POINTS {
            // Every other point goes (the touch and the latest step stay), and one step in twice as many is
            // kept from now on.
            let n = p.t.len();
            let keep = |v: &mut Vec<f64>| {
                let mut k = 0;
                v.retain(|_| {
                    k += 1;
                    (k - 1) % 2 == 0 || k == n
                });
            };
            keep(&mut p.t);
            keep(&mut p.penetration);
            keep(&mut p.force);
            p.stride *= 2;
            self.tentative = false;
        }
    }

    /// The path with the located peak `(t, d, f)` inserted in time order.
    fn with_peak(&self, (t, d, f): (f64, f64, f64)) -> ImpactLoop {
        let mut out = self.points.clone();
        let k = out.t.partition_point(|&x| x <= t);
        // A peak at a node is that node: replace it rather than add a twin.
        if k > 0 && out.t[k - 1] == t {
            out.penetration[k - 1] = d;
            out.force[k - 1] = f;
        } else {
            out.t.insert(k, t);
            out.penetration.insert(k, d);
            out.force.insert(k, f);
        }
        out
    }
}

/// Every impact of every contact element.
pub(super) struct Impacts {
    contacts: Vec<ContactRef>,
    /// Position in `contacts` of each element (`usize::MAX` for storeys).
    slot: Vec<usize>,
    trackers: Vec<Option<Tracker>>,
    pub impacts: Vec<Impact>,
    /// Keep each impact's force–penetration path.
    keep_loops: bool,
    /// The path of each of `impacts` (if kept).
    loops: Vec<ImpactLoop>,
    /// Largest closing `u_left - u_right` of each contact element so far, m (0 at rest).
    pub max_closing: Vec<f64>,
    /// Largest opening (the closing's opposite) of each contact element so far, m (0 at rest).
    pub max_opening: Vec<f64>,
    /// The site (floor pair or wall floor) of each contact element, numbered in order: a bumper's layer and
    /// the hard law behind it share one.
    pub pair: Vec<usize>,
    /// Largest total force of each site at the integration nodes, N.
    pub pair_peak: Vec<f64>,
    pair_sum: Vec<f64>,
}

impl Impacts {
    /// The recorder of `m`'s impacts; `keep_loops`: keep each impact's force–penetration path too.
    pub fn new(m: &Model, keep_loops: bool) -> Self {
        let mut slot = vec![usize::MAX; m.system.elements().len()];
        for (k, c) in m.contacts.iter().enumerate() {
            slot[c.element] = k;
        }
        let mut pair = Vec::with_capacity(m.contacts.len());
        for (k, c) in m.contacts.iter().enumerate() {
            let same = k > 0 && m.contacts[k - 1].site == c.site;
            let last = pair.last().copied();
            pair.push(match (same, last) {
                (true, Some(p)) => p,
                (_, Some(p)) => p + 1,
                (_, None) => 0,
            });
        }
        let pairs = pair.last().map_or(0, |p| p + 1);
        Self {
            contacts: m.contacts.clone(),
            slot,
            trackers: m.contacts.iter().map(|_| None).collect(),
            impacts: Vec::new(),
            keep_loops,
            loops: Vec::new(),
            max_closing: vec![0.0; m.contacts.len()],
            max_opening: vec![0.0; m.contacts.len()],
            pair,
            pair_peak: vec![0.0; pairs],
            pair_sum: vec![0.0; pairs],
        }
    }

    /// Impacts started so far (ended or not).
    pub fn count(&self) -> usize {
        self.impacts.len() + self.trackers.iter().flatten().count()
    }

    /// Records the impact `tr` of `c`, ended at `t` (or still going on, `v_out = None`).
    fn record(&mut self, k: usize, t: f64, v_out: Option<f64>, work: f64) {
        let c = &self.contacts[k];
        let tr = self.trackers[k].as_mut().expect("an impact under way");
        let i = Self::impact(c, tr, t, v_out, work);
        if let Some(path) = &tr.path {
            let d = tr
                .peak
                .best_piece()
                .map_or(path.points.penetration[0], |p| p.at(i.time_of_peak_force).0);
            self.loops
                .push(path.with_peak((i.time_of_peak_force, d, i.peak_force)));
        }
        self.impacts.push(i);
    }

    fn impact(c: &ContactRef, tr: &mut Tracker, t: f64, v_out: Option<f64>, work: f64) -> Impact {
        let (time_of_peak_force, peak_force) = tr.peak.finish();
        Impact {
            site: c.site,
            layer: c.layer,
            time: tr.time,
            v_i: tr.v_i,
            v_out,
            e_post: v_out.and_then(|v| (!tr.resting).then(|| -v / tr.v_i)),
            ended: v_out.is_some(),
            resting: tr.resting,
            peak_force,
            time_of_peak_force,
            max_penetration: tr.max_penetration,
            duration: t - tr.time,
            dissipated_energy: work - tr.work0,
        }
    }

    /// Ends the record: impacts still going on at `t`, and every impact in order of touch, with their paths
    /// in the same order (empty if not kept).
    pub fn finish(&mut self, sys: &System, t: f64, y: &[f64]) -> (Vec<Impact>, Vec<ImpactLoop>) {
        for k in 0..self.contacts.len() {
            let c = self.contacts[k];
            let engaged = matches!(
                &sys.elements()[c.element].kind,
                Kind::Contact(ct) if matches!(ct.state(), Engagement::Contact { .. })
            );
            if self.trackers[k].is_some() && engaged {
                let work = y[sys.layout().block(c.element).start];
                self.record(k, t, None, work);
            }
        }
        let impacts = std::mem::take(&mut self.impacts);
        let mut loops = std::mem::take(&mut self.loops);
        let mut order: Vec<usize> = (0..impacts.len()).collect();
        // Stable: impacts that touch at one instant keep the order they were recorded in.
        order.sort_by(|&a, &b| impacts[a].time.total_cmp(&impacts[b].time));
        let sorted = order.iter().map(|&i| impacts[i].clone()).collect();
        let loops = if loops.is_empty() {
            loops
        } else {
            order
                .iter()
                .map(|&i| std::mem::take(&mut loops[i]))
                .collect()
        };
        (sorted, loops)
    }
}

impl Observer for Impacts {
    fn segment(&mut self, seg: &Segment<'_, '_>) {
        let sys = seg.system;
        let h = seg.t1 - seg.t0;
        self.pair_sum.iter_mut().for_each(|f| *f = 0.0);
        for (k, c) in self.contacts.iter().enumerate() {
            // The closing's largest and smallest values on the step: at its end or at an interior extremum
            // of its Hermite interpolant (located, as the floors' peaks are).
            let ((xa, va), (xb, vb)) = (
                sys.deformation(c.element, seg.y0),
                sys.deformation(c.element, seg.y1),
            );
            let p = Hermite::new(xa, xb, va, vb, h);
            let (hi, lo) = (&mut self.max_closing[k], &mut self.max_opening[k]);
            *hi = hi.max(xb);
            *lo = lo.max(-xb);
            for s in p.extrema() {
                if !s.is_nan() {
                    let x = p.at(s);
                    *hi = hi.max(x);
                    *lo = lo.max(-x);
                }
            }
            if let Kind::Contact(ct) = &sys.elements()[c.element].kind {
                self.pair_sum[self.pair[k]] += ct.reported_force(xb, vb);
            }
        }
        for (peak, f) in self.pair_peak.iter_mut().zip(&self.pair_sum) {
            *peak = peak.max(*f);
        }
        for (c, tr) in self.contacts.iter().zip(self.trackers.iter_mut()) {
            let (Some(tr), Kind::Contact(ct)) = (tr.as_mut(), &sys.elements()[c.element].kind)
            else {
                continue;
            };
            let (x, v) = sys.deformation_interpolants(c.element, seg.dense);
            if let Some(piece) = ct.piece((seg.t0, seg.t1), x, v) {
                let (x1, v1) = sys.deformation(c.element, seg.y1);
                let f1 = ct.reported_force(x1, v1);
                tr.peak.push(piece, f1);
                tr.max_penetration = tr.max_penetration.max(x1 - ct.gap());
                if let Some(path) = tr.path.as_mut() {
                    path.push(seg.t1, x1 - ct.gap(), f1);
                }
            }
        }
    }

    fn event(&mut self, ev: &EventInfo<'_, '_>) {
        let k = self.slot[ev.element];
        if k == usize::MAX {
            return;
        }
        let sys = ev.system;
        let c = self.contacts[k];
        let Kind::Contact(ct) = &sys.elements()[c.element].kind else {
            return;
        };
        let (x, v) = sys.deformation(c.element, ev.y);
        let work = ev.y[sys.layout().block(c.element).start];
        let keep = self.keep_loops;
        let start = || Tracker {
            time: ev.t,
            v_i: v,
            work0: work,
            peak: PeakTracker::new(ev.t, ct.reported_force(x, v)),
            max_penetration: 0.0,
            resting: v < ct.min_impact_velocity(),
            recorded: None,
            path: keep.then(|| Path::new(ev.t, x - ct.gap(), ct.reported_force(x, v))),
        };
        let engaged = matches!(ct.state(), Engagement::Contact { .. });
        match ev.event {
            // A touch while the ends part (grazing) starts no impact: the contact rests without force.
            Event::Touch if engaged => self.trackers[k] = Some(start()),
            // Closing again from rest starts an impact.
            Event::Resume if self.trackers[k].is_none() => self.trackers[k] = Some(start()),
            Event::Turn => {
                if let Some(tr) = self.trackers[k].as_mut() {
                    tr.max_penetration = tr.max_penetration.max(x - ct.gap());
                }
            }
            Event::ZeroForce if self.trackers[k].is_some() => {
                self.record(k, ev.t, Some(v), work);
                let n = self.impacts.len();
                if let Some(tr) = self.trackers[k].as_mut() {
                    tr.recorded = Some(n - 1);
                }
            }
            Event::Separation if self.trackers[k].is_some() => {
                self.record(k, ev.t, Some(v), work);
                self.trackers[k] = None;
            }
            Event::Rearm => self.trackers[k] = None,
            Event::Resume => {
                // The same impact goes on: withdraw its record.
                if let Some(i) = self.trackers[k].as_mut().and_then(|tr| tr.recorded.take()) {
                    self.impacts.remove(i);
                    if self.keep_loops {
                        self.loops.remove(i);
                    }
                    for j in self
                        .trackers
                        .iter_mut()
                        .flatten()
                        .filter_map(|t| t.recorded.as_mut())
                    {
                        if *j > i {
                            *j -= 1;
                        }
                    }
                }
            }
            _ => {}
        }
    }
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

/// Histories at the output interval.
pub(super) struct HistoryRecorder {
    pub hist: Histories,
    times: Vec<f64>,
    next: usize,
    offsets: Vec<usize>,
    first_storey: Vec<usize>,
    contacts: Vec<ContactRef>,
    /// Index of each contact's column within its link or wall.
    column: Vec<usize>,
    devices: Vec<DeviceRef>,
    ys: Vec<f64>,
    rate: Vec<f64>,
}

impl HistoryRecorder {
    /// Samples at `k dt` (the last one at `t_end`), `n_out` of them.
    /// `storeys` per building, floor pairs per link, `walls` floors per wall, `devices` pairs per device.
    pub fn new(
        m: &Model,
        (storeys, links, walls, devices): (&[usize], &[usize], &[usize], &[usize]),
        n_out: usize,
        dt: f64,
        t_end: f64,
    ) -> Self {
        let dim = m.system.layout().dim();
        let per = |counts: &[usize]| -> Vec<Vec<Vec<f64>>> {
            counts
                .iter()
                .map(|&c| vec![Vec::with_capacity(n_out); c])
                .collect()
        };
        Self {
            hist: Histories {
                t: Vec::with_capacity(n_out),
                ground_acceleration: Vec::with_capacity(n_out),
                displacement: per(storeys),
                absolute_acceleration: per(storeys),
                storey_shear: per(storeys),
                force: per(links),
                wall_force: per(walls),
                device_force: per(devices),
                energy: std::array::from_fn(|_| Vec::with_capacity(n_out)),
                impact_loops: Vec::new(),
            },
            times: (0..n_out).map(|k| (k as f64 * dt).min(t_end)).collect(),
            next: 0,
            offsets: m.offsets.clone(),
            first_storey: m.first_storey.clone(),
            contacts: m.contacts.clone(),
            column: {
                // Columns follow the sites in order; a bumper's two elements share one.
                let mut col = Vec::with_capacity(m.contacts.len());
                let mut prev: Option<Site> = None;
                let mut n = 0;
                for c in &m.contacts {
                    let same_owner = match (prev, c.site) {
                        (Some(Site::Link { link: a, .. }), Site::Link { link: b, .. }) => a == b,
                        (Some(Site::Wall { wall: a, .. }), Site::Wall { wall: b, .. }) => a == b,
                        _ => false,
                    };
                    if !same_owner {
                        n = 0;
                    } else if prev != Some(c.site) {
                        n += 1;
                    }
                    col.push(n);
                    prev = Some(c.site);
                }
                col
            },
            devices: m.devices.clone(),
            ys: vec![0.0; dim],
            rate: vec![0.0; dim],
        }
    }
}

impl Observer for HistoryRecorder {
    fn segment(&mut self, seg: &Segment<'_, '_>) {
        let sys = seg.system;
        let l = sys.layout();
        while let Some(&t) = self.times.get(self.next) {
            if t > seg.t1 {
                break;
            }
            use crate::integrate::OdeSystem;
            seg.dense.eval(t.max(seg.t0), &mut self.ys);
            sys.rhs(t, &self.ys, &mut self.rate);
            let ag = sys.ground().at(t);
            let h = &mut self.hist;
            h.t.push(t);
            h.ground_acceleration.push(ag);
            for (b, (&o, &s0)) in self.offsets.iter().zip(&self.first_storey).enumerate() {
                for (f, col) in h.displacement[b].iter_mut().enumerate() {
                    col.push(self.ys[l.u(o + f)]);
                }
                for (f, col) in h.absolute_acceleration[b].iter_mut().enumerate() {
                    col.push(self.rate[l.v(o + f)] + ag);
                }
                for (j, col) in h.storey_shear[b].iter_mut().enumerate() {
                    col.push(sys.element_force(s0 + j, &self.ys));
                }
            }
            for col in h.force.iter_mut().chain(h.wall_force.iter_mut()).flatten() {
                col.push(0.0);
            }
            for (c, &j) in self.contacts.iter().zip(&self.column) {
                let (x, v) = sys.deformation(c.element, &self.ys);
                let f = match &sys.elements()[c.element].kind {
                    Kind::Contact(ct) => ct.reported_force(x, v),
                    _ => 0.0,
                };
                let col = match c.site {
                    Site::Link { link, .. } => &mut h.force[link][j],
                    Site::Wall { wall, .. } => &mut h.wall_force[wall][j],
                };
                *col.last_mut().expect("a sample") += f;
            }
            let mut prev = usize::MAX;
            let mut j = 0;
            for d in &self.devices {
                j = if d.device == prev { j + 1 } else { 0 };
                prev = d.device;
                h.device_force[d.device][j].push(device_force(sys, d.element, &self.ys));
            }
            let e = sys.energies(&self.ys);
            for (col, x) in h.energy.iter_mut().zip(e.terms()) {
                col.push(x);
            }
            self.next += 1;
        }
    }
}

/// The force of device element `e` in state `y` (elastic and viscous), N.
fn device_force(sys: &System, e: usize, y: &[f64]) -> f64 {
    let (x, v) = sys.deformation(e, y);
    let r = sys.layout().block(e);
    let mut ds = [0.0; 2];
    let (f, fv) = sys.elements()[e].evaluate(x, v, &y[r.clone()], &mut ds[..r.len()]);
    f + fv
}

/// Peaks of every device element.
pub(super) struct DevicePeaks {
    devices: Vec<DeviceRef>,
    pub force: Vec<f64>,
    pub closing: Vec<f64>,
    pub opening: Vec<f64>,
}

impl DevicePeaks {
    pub fn new(m: &Model) -> Self {
        let n = m.devices.len();
        Self {
            devices: m.devices.clone(),
            force: vec![0.0; n],
            closing: vec![0.0; n],
            opening: vec![0.0; n],
        }
    }
}

impl Observer for DevicePeaks {
    fn segment(&mut self, seg: &Segment<'_, '_>) {
        for (k, d) in self.devices.iter().enumerate() {
            let (x, _) = seg.system.deformation(d.element, seg.y1);
            self.force[k] = self.force[k].max(device_force(seg.system, d.element, seg.y1).abs());
            self.closing[k] = self.closing[k].max(x);
            self.opening[k] = self.opening[k].max(-x);
        }
    }
}

/// Everything a run keeps, and its progress reports.
pub(super) struct Recorders<'p> {
    pub peaks: Peaks,
    pub impacts: Impacts,
    pub devices: DevicePeaks,
    pub balance: Balance,
    pub histories: Option<HistoryRecorder>,
    pub progress: &'p mut dyn FnMut(Progress) -> ControlFlow<()>,
    cancelled: bool,
    pub t_end: f64,
    last_report: f64,
}

impl<'p> Recorders<'p> {
    pub fn new(
        peaks: Peaks,
        impacts: Impacts,
        devices: DevicePeaks,
        histories: Option<HistoryRecorder>,
        progress: &'p mut dyn FnMut(Progress) -> ControlFlow<()>,
        t_end: f64,
    ) -> Self {
        Self {
            devices,
            peaks,
            impacts,
            balance: Balance::default(),
            histories,
            progress,
            cancelled: false,
            t_end,
            last_report: f64::NEG_INFINITY,
        }
    }
}

impl Observer for Recorders<'_> {
    fn segment(&mut self, seg: &Segment<'_, '_>) {
        self.peaks.segment(seg);
        self.impacts.segment(seg);
        self.devices.segment(seg);
        self.balance.segment(seg);
        if let Some(h) = self.histories.as_mut() {
            h.segment(seg);
        }
        if seg.t1 - self.last_report >= 0.005 * self.t_end || seg.t1 >= self.t_end {
            self.last_report = seg.t1;
            let flow = (self.progress)(Progress {
                t: seg.t1,
                duration: self.t_end,
                impacts: self.impacts.count(),
            });
            self.cancelled = flow.is_break();
        }
    }

    fn event(&mut self, ev: &EventInfo<'_, '_>) {
        self.peaks.event(ev);
        self.impacts.event(ev);
    }

    fn cancelled(&self) -> bool {
        self.cancelled
    }
}

#[cfg(test)]
mod tests {
    use super::{Path, MAX_LOOP_POINTS};

    #[test]
    fn a_long_path_keeps_its_ends_and_its_peak_within_the_cap() {
        // A triangle of 10 001 steps: force i at step i up to 5000, then down; penetration = force / 1e3.
        let n = 10_000;
        let f = |i: usize| (i.min(n - i)) as f64;
        let mut p = Path::new(0.0, 0.0, 0.0);
        for i in 1..=n {
            p.push(i as f64, f(i) / 1e3, f(i));
        }
        let l = &p.points;
        assert!(l.t.len() <= MAX_LOOP_POINTS);
        assert!(l.t.windows(2).all(|w| w[0] < w[1]));
        assert_eq!((l.t[0], *l.t.last().unwrap()), (0.0, n as f64));
        // 10 000 steps in at most 2000 points: one in 8 kept.
        assert_eq!(l.stride, 8);
        // The located peak goes in at its time, between kept points.
        let with = p.with_peak((5000.5, 5.0005, 5000.5));
        let k = with.force.iter().position(|&x| x == 5000.5).unwrap();
        assert!(with.t[k - 1] < 5000.5 && with.t[k + 1] > 5000.5);
        assert_eq!(with.t.len(), l.t.len() + 1);
        // A peak at a kept node replaces it.
        assert_eq!(p.with_peak((0.0, 0.0, 1.0)).t.len(), l.t.len());
    }

    #[test]
    fn a_short_path_keeps_every_step() {
        let mut p = Path::new(0.0, 0.0, 0.0);
        for i in 1..=100 {
            p.push(i as f64, 0.0, 1.0);
        }
        assert_eq!((p.points.t.len(), p.points.stride), (101, 1));
    }
}
