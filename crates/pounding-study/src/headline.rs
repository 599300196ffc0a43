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

/// `(column, value)` pairs of one run's summary, with units in the column names: the record's PGA; for each
/// building its largest floor displacement, storey drift ratio (storeys above an isolator; none for a deck),
/// absolute floor acceleration and storey shear (restoring force, the isolator's included), its largest
/// ductility where storeys above any isolator can yield, and its isolator's displacement; each contact site's (contacts and walls alike)
/// impacts, peak force and largest penetration; the energy balance error and the integration steps.
pub fn headline(s: &RunSummary) -> Vec<(String, Cell)> {
    let max = |v: &[f64]| Cell::Number(v.iter().copied().fold(0.0, f64::max));
    let mut row = vec![("pga_m_per_s2".to_string(), Cell::Number(s.record.pga))];
    for b in &s.buildings {
        let name = &b.name;
        row.push((
            format!("{name}_peak_displacement_m"),
            max(&b.peak_displacement),
        ));
        // A deck has no storey above its bearings: no drift ratio.
        if !b.structural_drift_ratios().is_empty() {
            row.push((
                format!("{name}_peak_drift_ratio"),
                max(b.structural_drift_ratios()),
            ));
        }
        row.push((
            format!("{name}_peak_floor_acceleration_m_per_s2"),
            max(&b.peak_absolute_acceleration),
        ));
        row.push((
            format!("{name}_peak_storey_shear_N"),
            max(&b.peak_storey_shear),
        ));
        if !b.structural_ductility().is_empty() {
            row.push((
                format!("{name}_peak_ductility"),
                max(b.structural_ductility()),
            ));
        }
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

/// The building columns whose ratio to the run without contact is the amplification pounding causes: the
/// headline column's suffix and its amplification column's.
pub const AMPLIFIED: [(&str, &str); 4] = [
    ("peak_displacement_m", "displacement_amplification"),
    ("peak_drift_ratio", "drift_ratio_amplification"),
    (
        "peak_floor_acceleration_m_per_s2",
        "floor_acceleration_amplification",
    ),
    ("peak_storey_shear_N", "storey_shear_amplification"),
];

/// The amplification column of the headline column `column`, if it has one (`A_peak_storey_shear_N` gives
/// `A_storey_shear_amplification`).
pub fn amplification_column(column: &str) -> Option<String> {
    AMPLIFIED.iter().find_map(|(peak, amp)| {
        column
            .strip_suffix(peak)
            .and_then(|b| b.strip_suffix('_'))
            .map(|b| format!("{b}_{amp}"))
    })
}

/// The amplification of the run with contact `on` over the same run without contact `off` (both headline
/// rows): each peak of [`AMPLIFIED`] over its value without contact (dimensionless), left out where that is
/// zero.
pub fn amplification(on: &[(String, Cell)], off: &[(String, Cell)]) -> Vec<(String, Cell)> {
    on.iter()
        .filter_map(|(c, v)| {
            let amp = amplification_column(c)?;
            let base = off.iter().find(|(k, _)| k == c)?.1.as_f64();
            (base > 0.0).then(|| (amp, Cell::Number(v.as_f64() / base)))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn amplification_is_the_ratio_of_each_peak_to_its_value_without_contact() {
        let row = |a: f64, v: f64| {
            vec![
                ("pga_m_per_s2".to_string(), Cell::Number(3.0)),
                ("A_peak_storey_shear_N".to_string(), Cell::Number(a)),
                (
                    "A_peak_floor_acceleration_m_per_s2".to_string(),
                    Cell::Number(v),
                ),
            ]
        };
        let amp = amplification(&row(6e6, 9.0), &row(2e6, 0.0));
        // The acceleration without contact is zero: no ratio, rather than an infinity in runs.csv.
        assert_eq!(
            amp,
            vec![(
                "A_storey_shear_amplification".to_string(),
                Cell::Number(3.0)
            )]
        );
        assert_eq!(amplification_column("pga_m_per_s2"), None);
    }
}
