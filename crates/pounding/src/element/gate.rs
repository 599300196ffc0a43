//! The resolution of an element's deformation rate, and whether its next change of direction is armed.

/// The resolution of an element's deformation rate, and whether its next change of direction (a contact's
/// turn or new approach, a storey's reversal) is armed. A phase entered at a rate within the resolution of 0
/// (every turning point; a touch, release or reversal at a vanishing rate) arms its next change only once the
/// rate is clear of 0 by the resolution; until then that change needs the rate to pass 0 by the resolution.
/// Floors pressed together at rest, or a stiff storey between floors that move together, have a rate at the
/// integrator's noise, whose sign flipped the phase back and forth at one instant. Changes after a real swing
/// are located exactly at a rate of 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RateGate {
    v_res: f64,
    armed: bool,
}

impl Default for RateGate {
    fn default() -> Self {
        Self {
            v_res: 0.0,
            armed: true,
        }
    }
}

impl RateGate {
    /// Sets the resolution, m/s.
    pub fn set_resolution(&mut self, v_res: f64) {
        self.v_res = v_res;
    }
    /// Whether the next change of direction is located at a rate of exactly 0.
    pub fn armed(&self) -> bool {
        self.armed
    }
    /// What a change-of-direction event function adds while disarmed, m/s.
    #[inline]
    pub fn slack(&self) -> f64 {
        if self.armed {
            0.0
        } else {
            self.v_res
        }
    }
    /// After a change of phase: armed if the new phase's change-of-direction function `g` (m/s; `None` if
    /// it has none) is already clear of 0.
    pub fn enter(&mut self, g: Option<f64>) {
        self.armed = g.is_none_or(|g| g > self.v_res);
    }
    /// After a step: arms once `g` is clear of 0.
    pub fn rearm(&mut self, g: Option<f64>) {
        if !self.armed {
            self.enter(g);
        }
    }
}
