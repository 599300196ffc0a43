//! Devices between neighbours, or between a building and a wall beside it: a law of
//! [`crate::element::device`] at each of their floor pairs, for good.

use crate::element::DeviceLaw;

/// One end of a device besides a building: the neighbouring building, or a wall.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DeviceEnds {
    /// Between buildings `left` and `left + 1`; floor pairs `(floor of left, floor of right)`.
    Buildings {
        /// Index of the left building.
        left: usize,
        /// Index of the right building.
        right: usize,
    },
    /// Between a building's floors and the wall at site `site` ([`super::Scenario::sites`]), on the
    /// building's side; floor pairs `(floor, floor)`.
    Wall {
        /// Index of the wall's site.
        site: usize,
    },
}

/// A device between neighbours (or a building and a wall).
#[derive(Clone, Debug)]
pub struct Device {
    /// Name, unique among devices.
    pub name: String,
    /// What it joins.
    pub ends: DeviceEnds,
    /// Floor pairs (for a wall, the floor twice), from 1.
    pub floors: Vec<(usize, usize)>,
    /// Its model and parameters.
    pub law: DeviceLaw,
}

/// What a device is given: named fields, checked by [`super::Scenario::with_device`].
#[derive(Clone, Debug)]
pub struct DeviceSpec {
    /// Name (default: the model's name and its number, `restrainer1`).
    pub name: Option<String>,
    /// Two neighbouring buildings, or a building and a wall beside it.
    pub between: [String; 2],
    /// Floor pairs (for a wall, `(floor, floor)`; default: floors at the same height, or floor 1 for a wall).
    pub floors: Option<Vec<(usize, usize)>>,
    /// Its model and parameters.
    pub law: DeviceLaw,
}
