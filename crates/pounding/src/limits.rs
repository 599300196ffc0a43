//! Sizes the library accepts, checked before anything is allocated or solved, so that no input can make a
//! run abort on memory or crawl through an eigen-analysis (`docs/reliability.md`).

/// Largest number of storeys of one building. Modes take about 0.1 s at this size; taller shear-building
/// models are outside what the lumped shear model is used for.
pub const MAX_STOREYS: usize = 200;

/// Largest number of buildings in a row.
pub const MAX_BUILDINGS: usize = 50;

/// Largest number of floors in a row, all buildings together: 2,000 floors take about 1 s for their modes
/// and 0.55 ms per integration step.
pub const MAX_FLOORS: usize = 2000;

/// Largest number of supports of their own (multi-support excitation).
pub const MAX_SUPPORTS: usize = 16;

/// Largest number of load-resisting lines of a building in plan.
pub const MAX_LINES: usize = 100;

/// Largest number of samples of a ground-motion record (80 MB of accelerations).
pub const MAX_RECORD_SAMPLES: usize = 10_000_000;

/// Largest number of output samples of a run's histories.
pub const MAX_OUTPUT_SAMPLES: usize = 10_000_000;

/// Largest number of values in a run's histories: output samples times columns (time, ground acceleration,
/// three per floor, one per contact, six energies). 1e7 values are 80 MB in memory and about 210 MB of CSV;
/// ten buildings of 200 storeys under El Centro at 5 ms hold 3.7e7 and took 21 s and 1.2 GB.
pub const MAX_HISTORY_VALUES: usize = 10_000_000;

/// Largest work of one analysis, in integration steps (accepted and rejected) times (state components + 8):
/// about 5 s on one core of the machines we measured. A step costs 0.08 to 0.13 us per unit (1.2 us for 2
/// floors and a contact, 7 states; 3 us for 11 floors and 3 contacts, 27 states; 0.55 ms for 2,000 floors,
/// 4,030 states); the 8 is the cost of a step that does not grow with the states. The step budget of a run
/// is this divided by its units, checked before the run (from its highest natural frequency and the samples
/// of its record) and during the run step by step.
pub const MAX_WORK: f64 = 5e7;

/// Checks the size of a row from the number of floors of each building, before any building is analysed:
/// 1 to [`MAX_BUILDINGS`] buildings with at most [`MAX_FLOORS`] floors in all (the caller counts a floor in
/// plan three times: its x, y and rotation).
pub fn check_row(floors: &[usize]) -> Result<(), crate::Error> {
    let total: usize = floors.iter().sum();
    if floors.is_empty() || floors.len() > MAX_BUILDINGS {
        return Err(crate::Error::Choice {
            name: "building",
            value: format!("{} buildings", floors.len()),
            allowed: "1 to 50 buildings (limits::MAX_BUILDINGS)".into(),
        });
    }
    if total > MAX_FLOORS {
        return Err(crate::Error::Choice {
            name: "building",
            value: format!("{total} floors in {} buildings", floors.len()),
            allowed: "at most 2000 floors in a row, all buildings together, a floor in plan counting three (limits::MAX_FLOORS)"
                .into(),
        });
    }
    Ok(())
}

/// The step budget of a system of `dim` state components for the work `max_work` ([`MAX_WORK`] by default),
/// at least 1000 steps.
pub fn step_budget(dim: usize, max_work: f64) -> usize {
    (max_work / (dim + 8) as f64).max(1e3) as usize
}

/// Largest |ground acceleration|, m/s^2 (about 1e4 g): beyond any earthquake, and far from where the energies
/// of a run leave the range of `f64`.
pub const MAX_GROUND_ACCELERATION: f64 = 1e5;

/// Smallest nonzero magnitude of a number in a scenario, and of a ground acceleration (m/s^2, after scaling).
/// Smaller numbers are zero for any structure, and products of them fall below the smallest normal `f64`
/// (2.2e-308): arithmetic on such subnormal numbers is many times slower on common processors (an isolator
/// yield force of 1e-300 N took 22 s to reach the step budget of [`MAX_WORK`], 1e-160 N 3.5 s, against
/// under 1 s for ordinary numbers). Scenario numbers below it are refused; record accelerations below it are
/// read as 0.
pub const MIN_MAGNITUDE: f64 = 1e-30;

/// Whether `x` is 0 or at least [`MIN_MAGNITUDE`] in magnitude.
pub fn not_tiny(x: f64) -> bool {
    x == 0.0 || x.abs() >= MIN_MAGNITUDE || x.is_nan()
}

/// Smallest time step of a record, s.
pub const MIN_RECORD_DT: f64 = 1e-5;

/// Largest time step of a record, s.
pub const MAX_RECORD_DT: f64 = 10.0;
