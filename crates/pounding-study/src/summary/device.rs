//! The summary of a device: its law and its peaks.

use pounding::analysis::{DeviceResponse, Scenario};
use pounding::element::DeviceLaw;
use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

/// A device as it was run, and its peaks per floor pair.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
pub struct DeviceSummary {
    /// Its name.
    pub name: String,
    /// What it joins: two buildings, or a building and a wall.
    pub between: [String; 2],
    /// Its floor pairs, from 1 (to a wall, the floor twice).
    pub floors: Vec<[usize; 2]>,
    /// Its model and parameters (stiffness N/m, damping_coefficient N s/m, slack m, ...).
    pub law: DeviceLaw,
    /// Largest |force| of each floor pair (elastic and viscous), N.
    pub peak_force: Vec<f64>,
    /// Largest closing of each floor pair, m.
    pub max_closing: Vec<f64>,
    /// Largest opening of each floor pair, m.
    pub max_opening: Vec<f64>,
}

impl DeviceSummary {
    /// Device `i` of `s` and its peaks `r`.
    pub fn of(s: &Scenario, i: usize, r: &DeviceResponse) -> Self {
        let d = &s.devices()[i];
        Self {
            name: d.name.clone(),
            between: s.device_between(d),
            floors: d.floors.iter().map(|&(a, b)| [a, b]).collect(),
            law: d.law.clone(),
            peak_force: r.peak_force.clone(),
            max_closing: r.max_closing.clone(),
            max_opening: r.max_opening.clone(),
        }
    }
}
