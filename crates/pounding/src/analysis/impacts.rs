//! The impacts of a run, as an observer of the engine: each contact element's notices (an impact started,
//! turned, was released, resumed, ended) open and close its record; its force is followed between nodes to
//! locate its peak, and its path kept if asked.

use super::model::{ContactRef, Model};
use super::peaks::{ends_on, exact_extremum, step_peak};
use super::{Impact, ImpactLoop, Layer, MAX_LOOP_POINTS};
use crate::element::{ContactPiece, ElementLaw, End, Engagement, Notice};
use crate::engine::{EventInfo, Observer, Segment, System};
use crate::integrate::{Hermite, PeakTracker};

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
    /// The largest total force on the site's face during the impact, at the integration nodes `(t, N)`:
    /// a bumper's impact pushes on the wall with the bumper and, once it is consumed, the hard contact
    /// behind it.
    face: (f64, f64),
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
        self.tentative = !self.steps.is_multiple_of(p.stride);
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
    /// Largest |displacement| of each contact element's two ends along it so far, m, for an end at a point of a
    /// floor in plan (along the normal); 0 for an end at a floor or the ground ([`Impacts::end_peaks_of`]).
    pub end_peaks: Vec<[f64; 2]>,
    /// The site (floor pair or wall floor) of each contact element, numbered in order: a bumper's layer and
    /// the hard law behind it share one.
    pub pair: Vec<usize>,
    /// Largest total force of each site at the integration nodes, N.
    pub pair_peak: Vec<f64>,
    pair_sum: Vec<f64>,
    /// Room for the displacements and velocities between nodes.
    motion: Vec<f64>,
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
            let same =
                k > 0 && (m.contacts[k - 1].site, m.contacts[k - 1].level) == (c.site, c.level);
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
            end_peaks: vec![[0.0; 2]; m.contacts.len()],
            pair,
            pair_peak: vec![0.0; pairs],
            pair_sum: vec![0.0; pairs],
            motion: vec![0.0; 2 * m.system.layout().dofs()],
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
        let mut i = Self::impact(c, tr, t, v_out, work);
        // The path is the layer's own force against its own penetration, with its own located peak.
        if let Some(path) = &tr.path {
            let d = tr
                .peak
                .best_piece()
                .map_or(path.points.penetration[0], |p| p.at(i.time_of_peak_force).0);
            self.loops
                .push(path.with_peak((i.time_of_peak_force, d, i.peak_force)));
        }
        // A bumper's impact: the whole force on the face, the site's force (one peak per site).
        if c.layer == Layer::Bumper && tr.face.1 > i.peak_force {
            (i.time_of_peak_force, i.peak_force) = tr.face;
        }
        self.impacts.push(i);
    }

    fn impact(c: &ContactRef, tr: &mut Tracker, t: f64, v_out: Option<f64>, work: f64) -> Impact {
        let (time_of_peak_force, peak_force) = tr.peak.finish();
        Impact {
            site: c.site,
            level: c.level,
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
            let engaged = sys.elements()[c.element]
                .law
                .as_contact()
                .is_some_and(|ct| {
                    matches!(
                        ct.state(),
                        Engagement::Contact { .. } | Engagement::Held { .. }
                    )
                });
            if self.trackers[k].is_some() && engaged {
                let work = dissipated(sys, c.element, y);
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
            let el = &sys.elements()[c.element];
            for (peak, end) in self.end_peaks[k].iter_mut().zip([el.a, el.b]) {
                // A floor's is its peak displacement, which the floors' peaks locate the same way
                // ([`super::peaks::Peaks::displacement`]); the ground's is 0.
                if !matches!(end, End::Point(_)) {
                    continue;
                }
                let q = |y: &[f64], off: usize| end.value(y, off);
                let ends = ends_on(seg, self.motion.len() / 2, q);
                *peak = peak.max(step_peak(seg, &mut self.motion, *peak, ends, q).1);
            }
            let (hi, lo) = (&mut self.max_closing[k], &mut self.max_opening[k]);
            *hi = hi.max(xb);
            *lo = lo.max(-xb);
            // On an exact step, an extremum that may beat a peak (the Hermite's is within 1 %) is located on
            // the exact motion.
            let near = p.extremum_near((*hi, *lo), 0.99);
            let x = |y: &[f64], off: usize| el.a.value(y, off) - el.b.value(y, off);
            match near.then(|| exact_extremum(seg, &mut self.motion, &p, &x)) {
                Some(Some((_, x))) => {
                    *hi = hi.max(x);
                    *lo = lo.max(-x);
                }
                _ => {
                    for s in p.extrema() {
                        if !s.is_nan() {
                            let x = p.at(s);
                            *hi = hi.max(x);
                            *lo = lo.max(-x);
                        }
                    }
                }
            }
            if let Some(ct) = sys.elements()[c.element].law.as_contact() {
                self.pair_sum[self.pair[k]] += ct.force(xb, vb, &[]);
            }
        }
        for (peak, f) in self.pair_peak.iter_mut().zip(&self.pair_sum) {
            *peak = peak.max(*f);
        }
        for (k, tr) in self.trackers.iter_mut().enumerate() {
            if let Some(tr) = tr.as_mut() {
                let f = self.pair_sum[self.pair[k]];
                if f > tr.face.1 {
                    tr.face = (seg.t1, f);
                }
            }
        }
        for (c, tr) in self.contacts.iter().zip(self.trackers.iter_mut()) {
            let (Some(tr), Some(ct)) = (tr.as_mut(), sys.elements()[c.element].law.as_contact())
            else {
                continue;
            };
            let (x, v) = sys.deformation_interpolants(c.element, seg.dense);
            if let Some(piece) = ct.piece((seg.t0, seg.t1), x, v) {
                let (x1, v1) = sys.deformation(c.element, seg.y1);
                let f1 = ct.force(x1, v1, &[]);
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
        let Some(notice) = ev.notice.filter(|_| k != usize::MAX) else {
            return;
        };
        let sys = ev.system;
        let c = self.contacts[k];
        let Some(ct) = sys.elements()[c.element].law.as_contact() else {
            return;
        };
        let (x, v) = sys.deformation(c.element, ev.y);
        let work = ct.dissipated(&ev.y[sys.layout().block(c.element)]);
        let keep = self.keep_loops;
        let start = |resting| Tracker {
            time: ev.t,
            v_i: v,
            work0: work,
            peak: PeakTracker::new(ev.t, ct.force(x, v, &[])),
            max_penetration: 0.0,
            resting,
            recorded: None,
            path: keep.then(|| Path::new(ev.t, x - ct.gap(), ct.force(x, v, &[]))),
            face: (ev.t, 0.0),
        };
        match notice {
            Notice::ImpactStarted { resting } => self.trackers[k] = Some(start(resting)),
            Notice::ImpactTurned => {
                if let Some(tr) = self.trackers[k].as_mut() {
                    tr.max_penetration = tr.max_penetration.max(x - ct.gap());
                }
            }
            Notice::ImpactReleased if self.trackers[k].is_some() => {
                self.record(k, ev.t, Some(v), work);
                let n = self.impacts.len();
                if let Some(tr) = self.trackers[k].as_mut() {
                    tr.recorded = Some(n - 1);
                }
            }
            Notice::ImpactEnded if self.trackers[k].is_some() => {
                self.record(k, ev.t, Some(v), work);
                self.trackers[k] = None;
            }
            Notice::ContactCleared => self.trackers[k] = None,
            Notice::ImpactResumed => self.withdraw(k),
            _ => {}
        }
    }
}

impl Impacts {
    /// The largest |displacement| over the run of contact element `k`'s two ends along it, m: a floor's peak
    /// displacement (`displacement`, the floors' peaks), a point's tracked here, 0 for the ground.
    pub fn end_peaks_of(
        &self,
        sys: &System,
        displacement: &[super::peaks::Peak],
        k: usize,
    ) -> [f64; 2] {
        let el = &sys.elements()[self.contacts[k].element];
        let tracked = self.end_peaks[k];
        [(el.a, tracked[0]), (el.b, tracked[1])].map(|(end, tracked)| match end {
            End::Dof(i) => displacement[i].value,
            End::Point(_) => tracked,
            End::Ground => 0.0,
        })
    }

    /// The impact of contact `k` goes on after a release: its record is withdrawn.
    fn withdraw(&mut self, k: usize) {
        let Some(i) = self.trackers[k].as_mut().and_then(|tr| tr.recorded.take()) else {
            return;
        };
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

/// The energy contact element `element` has dissipated in the state `y`, J ([`Contact::dissipated`]).
pub(crate) fn dissipated(sys: &System, element: usize, y: &[f64]) -> f64 {
    sys.elements()[element]
        .law
        .as_contact()
        .map_or(0.0, |ct| ct.dissipated(&y[sys.layout().block(element)]))
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
