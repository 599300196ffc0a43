//! Sizes the library accepts, checked before anything is allocated or solved, so that no input can make a
//! run abort on memory or crawl through an eigen-analysis (`docs/reliability.md`).

/// Largest number of storeys of one building. Modes take about 0.1 s at this size; taller shear-building
/// models are outside what the lumped shear model is used for.
pub const MAX_STOREYS: usize = 200;

/// Largest number of buildings in a row.
pub const MAX_BUILDINGS: usize = 50;

/// Largest number of samples of a ground-motion record (80 MB of accelerations).
pub const MAX_RECORD_SAMPLES: usize = 10_000_000;

/// Largest number of output samples of a run's histories.
pub const MAX_OUTPUT_SAMPLES: usize = 10_000_000;

/// Largest work of one analysis, in integration steps times (state components + 8): about 8 s on one core of
/// the machines we measured (a step costs about 0.09 us per unit: 1.2 us for 2 floors and one contact, 3 us for
/// 11 floors and 3 contacts; the 8 is the cost of a step that does not grow with the states). The step
/// budget of a run is this divided by its units, checked before the run (from its highest natural frequency
/// and the samples of its record) and during the run step by step.
pub const MAX_WORK: f64 = 1e8;

/// The step budget of a system of `dim` state components (at least 1000 steps).
pub fn step_budget(dim: usize) -> usize {
    (MAX_WORK / (dim + 8) as f64).max(1e3) as usize
}

/// Largest |ground acceleration|, m/s^2 (about 1e4 g): beyond any earthquake, and far from where the energies
/// of a run leave the range of `f64`.
pub const MAX_GROUND_ACCELERATION: f64 = 1e5;

/// Smallest time step of a record, s.
pub const MIN_RECORD_DT: f64 = 1e-5;

/// Largest time step of a record, s.
pub const MAX_RECORD_DT: f64 = 10.0;
