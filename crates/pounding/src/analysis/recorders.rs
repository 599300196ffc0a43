//! Everything a pounding run keeps, as one observer of the engine: peaks, impacts, device peaks, the energy
//! balance, histories if asked, and the progress reports.

use super::histories::HistoryRecorder;
use super::impacts::Impacts;
use super::peaks::{Balance, DevicePeaks, Peaks};
use super::Progress;
use crate::engine::{EventInfo, Observer, Segment};
use std::ops::ControlFlow;

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
    /// Segments since the last report: a run that crawls (tiny steps) still reports, so that it can be
    /// cancelled promptly.
    unreported: u32,
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
            unreported: 0,
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
        self.unreported += 1;
        if seg.t1 - self.last_report >= 0.005 * self.t_end
            || seg.t1 >= self.t_end
            || self.unreported >= 256
        {
            self.last_report = seg.t1;
            self.unreported = 0;
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
