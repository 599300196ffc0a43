//! What the run's figures share: quantities, number formats, the floors' colours.

use crate::plot::axis::human;
use crate::plot::{Quantity, Style};

pub fn force() -> Quantity {
    Quantity::new("contact force", "N")
}

pub fn time() -> Quantity {
    Quantity::new("time", "s")
}

/// Blues from light to dark (ColorBrewer's Blues, #9ecae1 to #08306b, in 16 steps).
const BLUES: [&str; 16] = [
    "#9ecae1", "#8dc1dd", "#7cb7da", "#6baed6", "#5da5d1", "#509bcb", "#4292c6", "#3787c0",
    "#2c7cbb", "#2171b5", "#1966ad", "#105ca4", "#08519c", "#08468c", "#083b7b", "#08306b",
];

/// Floor `f` (from 0) of `n`: blues from light (floor 1) to dark, the roof in the darkest blue and a little
/// wider, for every building height (up to 16 floors each has its own shade).
pub fn floor_style(f: usize, n: usize) -> Style {
    let k = if n <= 1 {
        BLUES.len() - 1
    } else {
        ((f as f64 / (n - 1) as f64) * (BLUES.len() - 1) as f64).round() as usize
    };
    Style {
        color: BLUES[k.min(BLUES.len() - 1)],
        width: if f + 1 == n { 2.0 } else { 1.5 },
        ..Style::nth(0)
    }
}

/// Gap in mm for a label, without trailing zeros.
pub fn fmt_mm(gap: f64) -> String {
    crate::output::fmt_num((gap * 1e3 * 1e6).round() / 1e6)
}

/// A value in its display unit, 4 significant digits: "2.5 MN", "186.6 kJ", "1.27 mm".
pub fn human_si(v: f64, unit: &str) -> String {
    human(v, unit, 4)
}
