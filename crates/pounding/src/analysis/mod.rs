//! Time-history analysis of pounding between adjacent buildings under a uniform base excitation.
//!
//! Buildings stand in a row, listed left to right; positive displacement points right. Displacements are
//! relative to the moving ground, so each floor obeys `m_i u_i'' = -m_i (a_g(t) + a0 u_i') + storey and
//! contact forces`. The row is built as a system of the engine ([`crate::engine`]): one degree of freedom per
//! floor, one storey element per storey (linear, bilinear or Bouc–Wen, [`crate::element::storey`], with the
//! stiffness-proportional Rayleigh damping `a1 k_j` of its initial stiffness), one contact element
//! ([`crate::element::Contact`]) per level of each contact site ([`ContactSite`]: a contact between
//! neighbours, or a wall): between neighbours it closes when `u_L - u_R` exceeds the gap, so its penetration
//! is `d = u_L - u_R - gap` and its rate `v = d'`; and one element per floor pair of each device.
//!
//! Each impact is one touch of one element. Its onset is located as an event on the integrator's
//! interpolant, so `v_i` is the relative velocity at the moment of touch, and the element's law is built
//! afresh for it with [`crate::contact::PreparedContact::law`] (effective mass `m_L m_R / (m_L + m_R)` of the two floors).
//! Storeys' yield and reversal are events too, so force–drift loops are exact, not smeared over a step.
//! Integration is adaptive Dormand–Prince 5(4) with steps that end at every sample of the record (the ground
//! acceleration has a kink there) and restart at every event. One relative tolerance sets the accuracy of
//! everything.
//!
//! The energy balance is integrated with the motion: input `E_I = -int a_g 1^T M u' dt` = kinetic
//! `u'^T M u' / 2` + recoverable strain of the storeys + viscous damping `int u'^T C u' dt` + hysteretic
//! dissipation of the storeys + contact work `int F d' dt` (equal to the energy dissipated by the contacts
//! once every impact has ended). What a run keeps (peaks, impacts, energies, and optionally histories) is
//! recorded by observers of the engine ([`RunOptions`]).

mod assemble;
mod column_sites;
mod devices;
mod facades;
mod histories;
mod impacts;
mod model;
mod peaks;
mod plan_sites;
mod plausibility;
mod recorders;
mod results;
mod run;
mod scenario;
mod sites;

pub use assemble::NO_CONTACT_GAP;
pub use devices::{Device, DeviceEnds, DeviceSpec};
pub use plausibility::{PLAUSIBLE_PERIOD, PLAUSIBLE_PGA_G};
pub use results::{
    BuildingResponse, ColumnResponse, DeviceResponse, EnergyBalance, FoundationResponse, Histories,
    Impact, ImpactLoop, LineResponse, PlanResponse, Results, SiteResponse, Statistics,
    MAX_LOOP_POINTS,
};
pub use run::{Progress, RunOptions};
pub use scenario::{
    Building, Scenario, DEFAULT_MIN_IMPACT_VELOCITY, DEFAULT_OUTPUT_DT, DEFAULT_TOLERANCE,
};
pub use sites::{
    Bumper, ColumnLinkSpec, ContactSite, Layer, Level, LinkSpec, PlanLinkSpec, Side, SiteColumn,
    SiteKind, SitePlan, WallSpec,
};
