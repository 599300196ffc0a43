//! The headline results of a run, one row per run: what `runs.csv` of a sweep holds and what Python's
//! `pounding.headline` puts in a DataFrame.

use crate::summary::RunSummary;

/// One value of a headline row.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Cell {
    /// A number in the unit its column names.
    Number(f64),
    /// A count.
    Count(usize),
}

impl Cell {
    /// As a number.
    pub fn as_f64(self) -> f64 {
        match self {
            Cell::Number(x) => x,
            Cell::Count(n) => n as f64,
        }
    }
}

/// `(column, value)` pairs of one run's summary, with units in the column names: the record's PGA, each
/// building's largest floor displacement and storey drift ratio (and its isolator's displacement), each
/// contact site's (contacts and walls alike) impacts, peak force and largest penetration, the energy balance
/// error and the integration steps.
pub fn headline(s: &RunSummary) -> Vec<(String, Cell)> {
    let max = |v: &[f64]| Cell::Number(v.iter().copied().fold(0.0, f64::max));
    let mut row = vec![("pga_m_per_s2".to_string(), Cell::Number(s.record.pga))];
    for b in &s.buildings {
        let name = &b.name;
        row.push((
            format!("{name}_peak_displacement_m"),
            max(&b.peak_displacement),
        ));
        row.push((format!("{name}_peak_drift_ratio"), max(&b.peak_drift_ratio)));
        if let Some(iso) = &b.isolator {
            row.push((
                format!("{name}_isolator_displacement_m"),
                Cell::Number(iso.peak_displacement),
            ));
        }
    }
    for site in &s.sites {
        let name = &site.name;
        row.push((format!("{name}_impacts"), Cell::Count(site.impacts)));
        row.push((
            format!("{name}_peak_force_N"),
            Cell::Number(site.peak_force),
        ));
        row.push((
            format!("{name}_max_penetration_m"),
            Cell::Number(site.max_penetration),
        ));
    }
    row.push((
        "energy_balance_error".to_string(),
        Cell::Number(s.energy_balance_error),
    ));
    row.push(("steps".to_string(), Cell::Count(s.statistics.steps)));
    row
}
