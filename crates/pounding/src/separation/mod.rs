//! Required separation between neighbours, and the code rules that estimate it.
//!
//! From a run without contact ([`Scenario::without_contact`]), at each contact level (a floor pair of
//! neighbours `L` and `R`): the peak displacements `pl`, `pr` (m) of the two floors, and the **required gap**
//! `max_t (u_L - u_R)` (m, 0 if the floors never approach), the smallest gap at which they never touch under
//! this record, located between steps. Against it, the rules that estimate it from the peaks alone:
//!
//! - ABS, the absolute sum `pl + pr`;
//! - SRSS, `sqrt(pl^2 + pr^2)`;
//! - DDC, the double-difference combination `sqrt(pl^2 + pr^2 - 2 rho pl pr)` with `rho` the CQC correlation
//!   of the two buildings' fundamental modes ([`cqc_correlation`]; Der Kiureghian 1981; Jeng et al. 1992).
//!
//! Eurocode 8 (EN 1998-1, 4.4.2.7) allows a factor of 0.7 where the floors are at the same height; with
//! `aligned_factor`, each rule's estimate at such a level is multiplied by it.

pub mod codes;
pub mod linear;
pub mod random;
pub mod suite;

use crate::analysis::{RunOptions, Scenario, SiteKind};
use crate::Error;
use std::ops::ControlFlow;

/// The CQC correlation coefficient of two modes of circular frequencies `w_l`, `w_r` (rad/s) and damping
/// ratios `z_l`, `z_r`, with `r = w_r / w_l`:
/// `rho = 8 sqrt(z_l z_r) (z_l + r z_r) r^1.5 / ((1 - r^2)^2 + 4 z_l z_r r (1 + r^2) + 4 (z_l^2 + z_r^2) r^2)`
/// (Der Kiureghian 1981). 1 for equal frequencies and damping; 0 if either damping is 0 and the
/// frequencies differ.
pub fn cqc_correlation(w_l: f64, z_l: f64, w_r: f64, z_r: f64) -> f64 {
    let r = w_r / w_l;
    let num = 8.0 * (z_l * z_r).sqrt() * (z_l + r * z_r) * r.powf(1.5);
    let den = (1.0 - r * r).powi(2)
        + 4.0 * z_l * z_r * r * (1.0 + r * r)
        + 4.0 * (z_l * z_l + z_r * z_r) * r * r;
    if den == 0.0 {
        // Equal frequencies without damping: fully correlated.
        1.0
    } else {
        num / den
    }
}

/// One contact level of a pair of neighbours.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Level {
    /// Floors (of the left building, of the right), from 1.
    pub floors: (usize, usize),
    /// Between buildings in plan: the level's point on the façade at rest, `(x, y)` in the site's frame, m
    /// (its peaks are those of the point along the façades' normal).
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub point: Option<(f64, f64)>,
    /// The contact's gap at rest, m (what the scenario gives the site).
    pub gap: f64,
    /// Peak displacement of the left building's floor, m.
    pub peak_left: f64,
    /// Peak displacement of the right building's floor, m.
    pub peak_right: f64,
    /// `max_t (u_L - u_R)`, m (0 if never positive; at most `pl + pr`, its exact bound): the gap at which the
    /// floors never touch.
    pub required_gap: f64,
    /// `pl + pr` (times the aligned factor where it applies), m.
    pub abs: f64,
    /// `sqrt(pl^2 + pr^2)` (times the aligned factor where it applies), m.
    pub srss: f64,
    /// `sqrt(pl^2 + pr^2 - 2 rho pl pr)` (times the aligned factor where it applies), m.
    pub ddc: f64,
    /// CQC correlation of the two buildings' fundamental modes (dimensionless).
    pub rho: f64,
    /// The factor applied to the rules here: the aligned factor if the floors are at the same height (within
    /// 1 mm) and one was given, else 1.
    pub factor: f64,
}

/// The contact levels of a pair of neighbours.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Pair {
    /// Index of the left building.
    pub left: usize,
    /// Index of the right building.
    pub right: usize,
    /// Its levels.
    pub levels: Vec<Level>,
}

/// The required separation of every pair of neighbours of `scenario`, and the rules' estimates, from a run
/// without contact (summary only, within `max_work`, see [`RunOptions`]). `aligned_factor` (0 < f <= 1, for
/// example Eurocode 8's 0.7) multiplies the rules at levels whose floors are at the same height.
pub fn separation(
    scenario: &Scenario,
    aligned_factor: Option<f64>,
    options: &RunOptions,
) -> Result<Vec<Pair>, Error> {
    separation_with(scenario, aligned_factor, options, &mut |_| {
        ControlFlow::Continue(())
    })
}

/// [`separation`], with the run without contact reporting to `progress` as
/// [`Scenario::run_with_options`] does (`Break` cancels it: [`Error::Cancelled`]).
pub fn separation_with(
    scenario: &Scenario,
    aligned_factor: Option<f64>,
    options: &RunOptions,
    progress: &mut dyn FnMut(crate::analysis::Progress) -> ControlFlow<()>,
) -> Result<Vec<Pair>, Error> {
    if let Some(f) = aligned_factor {
        crate::error::check(
            "aligned_factor",
            f,
            f > 0.0 && f <= 1.0,
            "0 < aligned_factor <= 1",
        )?;
    }
    let free = scenario.without_contact();
    let options = RunOptions {
        histories: false,
        ..options.clone()
    };
    let r = free.run_with_options(&options, progress)?;
    let b = free.buildings();
    let pairs = free.sites().iter().zip(&r.sites).filter_map(|(site, lr)| {
        let SiteKind::Between { left, right } = site.kind else {
            return None;
        };
        let (sl, sr) = (&b[left].structure, &b[right].structure);
        // Buildings in plan: their first modes along the façades' normal, the peaks of the contact's points.
        let first = |st: &crate::structure::ShearBuilding| match (st.plan(), &site.plan) {
            (Some(p), Some(sp)) => {
                let (wx, wy, _) = p.first_modes();
                let w = if sp.normal.0 != 0.0 { wx } else { wy };
                let (a0, a1) = p.rayleigh();
                (w, a0 / (2.0 * w) + a1 * w / 2.0)
            }
            _ => (st.modes().omega[0], st.damping_of_mode(0)),
        };
        let ((wl, zl), (wr, zr)) = (first(sl), first(sr));
        let rho = cqc_correlation(wl, zl, wr, zr);
        let aligned = free.aligned_floor_pairs(left, right);
        let levels = site
            .levels
            .iter()
            .zip(&lr.max_closing)
            .enumerate()
            .map(|(k, (level, &closing))| {
                let (i, j) = (level.left.unwrap_or(1), level.right.unwrap_or(1));
                let (pl, pr) = match site.plan {
                    Some(_) => (lr.peak_ends[k][0], lr.peak_ends[k][1]),
                    None => (
                        r.buildings[left].peak_displacement[i - 1],
                        r.buildings[right].peak_displacement[j - 1],
                    ),
                };
                let factor = match aligned_factor {
                    Some(f) if aligned.contains(&(i, j)) => f,
                    _ => 1.0,
                };
                Level {
                    floors: (i, j),
                    point: site.plan.as_ref().map(|p| p.points[k]),
                    gap: site.gap,
                    peak_left: pl,
                    peak_right: pr,
                    // max(u_l - u_r) <= max|u_l| + max|u_r| exactly; the two sides are located peaks
                    // of the same interpolant, and may differ by rounding: held to the bound.
                    required_gap: closing.max(0.0).min(pl + pr),
                    abs: factor * (pl + pr),
                    srss: factor * pl.hypot(pr),
                    ddc: factor * (pl * pl + pr * pr - 2.0 * rho * pl * pr).max(0.0).sqrt(),
                    rho,
                    factor,
                }
            })
            .collect();
        Some(Pair {
            left,
            right,
            levels,
        })
    });
    Ok(pairs.collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_cqc_correlation_reproduces_published_values() {
        // Periods 0.5 and 0.6 s at 5 % damping each: 0.2298 (the value issue 12 quotes; either order).
        let w = |t: f64| 2.0 * std::f64::consts::PI / t;
        let rho = cqc_correlation(w(0.5), 0.05, w(0.6), 0.05);
        assert!((rho - 0.2298).abs() < 5e-5, "{rho}");
        assert!((cqc_correlation(w(0.6), 0.05, w(0.5), 0.05) - rho).abs() < 1e-12);
        // Equal modes are fully correlated; undamped distinct modes not at all.
        assert!((cqc_correlation(7.0, 0.03, 7.0, 0.03) - 1.0).abs() < 1e-12);
        assert_eq!(cqc_correlation(5.0, 0.0, 7.0, 0.0), 0.0);
    }
}
