//! Observers of a run (recorders) and the tools they share.

use super::System;
use crate::element::{Event, Notice};
use crate::integrate::Dense;

/// One accepted piece of the solution, `[t0, t1]`, on which every element kept its phase.
pub struct Segment<'s, 'a> {
    /// The system, with the phases that held on the segment.
    pub system: &'s System<'a>,
    /// Start, s.
    pub t0: f64,
    /// End, s (a step end, or the located time of the next event).
    pub t1: f64,
    /// State at `t0`.
    pub y0: &'s [f64],
    /// State at `t1`.
    pub y1: &'s [f64],
    /// Time derivative of the state at `t1`, before any event there (accelerations in m/s^2 at the
    /// velocities' places).
    pub rate1: &'s [f64],
    /// The interpolant, valid on `[t0, t1]`.
    pub dense: &'s Dense,
}

/// An event that was applied.
pub struct EventInfo<'s, 'a> {
    /// The system, with the new phase.
    pub system: &'s System<'a>,
    /// Time, s.
    pub t: f64,
    /// Index of the element.
    pub element: usize,
    /// What fired (the element law's own number).
    pub event: Event,
    /// What the element said happened.
    pub notice: Option<Notice>,
    /// State at `t`.
    pub y: &'s [f64],
    /// Time derivative of the state at `t`, after the event.
    pub rate: &'s [f64],
}

/// Watches a run: every accepted segment, then every event applied at its end.
pub trait Observer {
    /// An accepted segment.
    fn segment(&mut self, seg: &Segment<'_, '_>);
    /// An event, applied at the end of the segment just observed.
    fn event(&mut self, _ev: &EventInfo<'_, '_>) {}
    /// Whether the run should stop here (asked after every segment; a cancelled run).
    fn cancelled(&self) -> bool {
        false
    }
}

impl Observer for () {
    fn segment(&mut self, _seg: &Segment<'_, '_>) {}
}
