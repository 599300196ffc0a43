//! Histories at the output interval, as an observer of the engine: the state is interpolated at every
//! output time that a step passes.

use super::model::{ContactRef, DeviceRef, Model, StoreyRef};
use super::peaks::total_force;
use super::Histories;
use crate::engine::{Observer, Segment};
use crate::integrate::OdeSystem;

/// How many columns of each kind, per building, site or device: storeys (floors), floors in plan (0 in one
/// line), foundation columns (2 on a foundation, else 0), levels per site, pairs per device.
#[derive(Clone, Copy)]
pub(super) struct Counts<'a> {
    pub storeys: &'a [usize],
    pub plans: &'a [usize],
    pub grounded: &'a [usize],
    pub sites: &'a [usize],
    pub devices: &'a [usize],
}

/// Histories at the output interval.
pub(super) struct HistoryRecorder {
    pub hist: Histories,
    times: Vec<f64>,
    next: usize,
    offsets: Vec<usize>,
    /// Floors of each building in plan (`None` in one line).
    plans: Vec<Option<usize>>,
    storeys: Vec<StoreyRef>,
    contacts: Vec<ContactRef>,
    devices: Vec<DeviceRef>,
    ys: Vec<f64>,
    rate: Vec<f64>,
    ds: Vec<f64>,
}

impl HistoryRecorder {
    /// Samples at `k dt` (the last one at `t_end`), `n_out` of them, with the columns `counts` says.
    pub fn new(m: &Model, counts: &Counts<'_>, n_out: usize, dt: f64, t_end: f64) -> Self {
        let dim = m.system.layout().dim();
        let Counts {
            storeys,
            plans,
            grounded,
            sites,
            devices,
        } = *counts;
        let per = |counts: &[usize]| -> Vec<Vec<Vec<f64>>> {
            counts
                .iter()
                // Each column its own capacity: `vec![v; c]` would clone `v` without it.
                .map(|&c| (0..c).map(|_| Vec::with_capacity(n_out)).collect())
                .collect()
        };
        Self {
            hist: Histories {
                t: Vec::with_capacity(n_out),
                ground_acceleration: Vec::with_capacity(n_out),
                ground_acceleration_y: Vec::new(),
                displacement: per(storeys),
                displacement_y: per(plans),
                rotation: per(plans),
                foundation: per(grounded),
                absolute_acceleration: per(storeys),
                storey_shear: per(storeys),
                site_force: per(sites),
                device_force: per(devices),
                energy: std::array::from_fn(|_| Vec::with_capacity(n_out)),
                impact_loops: Vec::new(),
            },
            times: (0..n_out).map(|k| (k as f64 * dt).min(t_end)).collect(),
            next: 0,
            offsets: m.offsets.clone(),
            plans: storeys
                .iter()
                .zip(plans)
                .map(|(&n, &p)| (p > 0).then_some(n))
                .collect(),
            storeys: m.storeys.clone(),
            contacts: m.contacts.clone(),
            devices: m.devices.clone(),
            ys: vec![0.0; dim],
            rate: vec![0.0; dim],
            ds: vec![0.0; dim],
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
            seg.dense.eval(t.max(seg.t0), &mut self.ys);
            // The floors' accelerations: on an exact step off its configuration's matrix (a few sparse rows),
            // else the right-hand side.
            let n = l.dofs();
            let (motion, acc) = (&self.ys[..2 * n], &mut self.rate[n..2 * n]);
            if !seg.dense.accelerations(t.max(seg.t0), motion, acc) {
                sys.rhs(t, &self.ys, &mut self.rate);
            }
            let ag = sys.ground().at(t);
            let h = &mut self.hist;
            h.t.push(t);
            h.ground_acceleration.push(ag);
            if let crate::engine::Ground::Plane { y, .. } = sys.ground() {
                h.ground_acceleration_y.push(y.at(t));
            }
            for (b, (&o, plan)) in self.offsets.iter().zip(&self.plans).enumerate() {
                for (f, col) in h.displacement[b].iter_mut().enumerate() {
                    col.push(self.ys[l.u(o + f)]);
                }
                for (f, col) in h.absolute_acceleration[b].iter_mut().enumerate() {
                    // A building on a support of its own is shaken by that support's record.
                    let a = if sys.sourced(o + f) {
                        sys.ground_at(o + f, t)
                    } else {
                        ag
                    };
                    col.push(self.rate[l.v(o + f)] + a);
                }
                for (j, col) in h.storey_shear[b].iter_mut().enumerate() {
                    let st = &self.storeys[o + j];
                    col.push(
                        st.elements
                            .iter()
                            .map(|&(e, c)| c * sys.element_force(e, &self.ys))
                            .sum(),
                    );
                }
                // A foundation's sway and rocking follow its building's floors.
                if let [sway, rocking] = &mut h.foundation[b][..] {
                    let n = h.displacement[b].len();
                    sway.push(self.ys[l.u(o + n)]);
                    rocking.push(self.ys[l.u(o + n + 1)]);
                }
                if let Some(n) = *plan {
                    for (f, col) in h.displacement_y[b].iter_mut().enumerate() {
                        col.push(self.ys[l.u(o + n + f)]);
                    }
                    for (f, col) in h.rotation[b].iter_mut().enumerate() {
                        col.push(self.ys[l.u(o + 2 * n + f)]);
                    }
                }
            }
            for col in h.site_force.iter_mut().flatten() {
                col.push(0.0);
            }
            // A bumper's layer and the hard law behind it add up on their level.
            for c in &self.contacts {
                let f = sys.element_force(c.element, &self.ys);
                *h.site_force[c.site][c.level].last_mut().expect("a sample") += f;
            }
            let mut prev = usize::MAX;
            let mut j = 0;
            for d in &self.devices {
                j = if d.device == prev { j + 1 } else { 0 };
                prev = d.device;
                let f = total_force(sys, d.element, &self.ys, &mut self.ds);
                h.device_force[d.device][j].push(f);
            }
            let e = sys.energies(&self.ys);
            for (col, x) in h.energy.iter_mut().zip(e.terms()) {
                col.push(x);
            }
            self.next += 1;
        }
    }
}
