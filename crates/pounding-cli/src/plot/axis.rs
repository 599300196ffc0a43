//! Linear axes: range, "nice" ticks (1, 2, 2.5, 5 x 10^k) and tick labels in the display unit of the
//! quantity ([`display_prefix`]: lengths in mm, forces in MN, energies in kJ, times in s or ms), so that a
//! force axis reads "1.5" in MN rather than "1500000" in N.

/// What an axis shows: a quantity in an SI unit (prefixed on the axis as needed), or a plain number.
#[derive(Clone, Debug, PartialEq)]
pub struct Quantity {
    /// Name of the quantity, e.g. "contact force".
    pub name: String,
    /// Its SI unit ("N", "m", "s", "J", "m/s"), "%" or "" for a dimensionless number; never prefixed.
    pub unit: &'static str,
    /// The power of ten (a multiple of 3) of the displayed unit, if not the convention's
    /// ([`display_prefix`]): 0 for a height in m.
    pub prefix: Option<i32>,
}

impl Quantity {
    /// `name` in `unit` (SI, unprefixed; "%" or "" for numbers).
    pub fn new(name: impl Into<String>, unit: &'static str) -> Self {
        Self {
            name: name.into(),
            unit,
            prefix: None,
        }
    }

    /// The same quantity shown in `unit` times `10^e` (`e` a multiple of 3 from -9 to 9).
    pub fn shown_in(mut self, e: i32) -> Self {
        self.prefix = Some(e);
        self
    }
}

/// The display convention of figures and the report's tables, as the power of ten of the unit shown for a
/// value of SI `unit` whose largest magnitude is `biggest`: lengths (m) in mm, forces (N) in MN, energies
/// (J) in kJ; times (s) in s, or in ms (µs) when every value is below 1 s (the time of one impact);
/// accelerations (m/s^2), velocities (m/s), percentages and plain numbers as they are.
pub fn display_prefix(unit: &str, biggest: f64) -> i32 {
    match unit {
        "m" => -3,
        "N" => 6,
        "J" => 3,
        "s" if biggest > 0.0 && biggest < 1.0 => {
            (((biggest.log10() / 3.0).floor() as i32) * 3).clamp(-6, 0)
        }
        _ => 0,
    }
}

/// `unit` with the prefix of `10^e`: "mm", "MN", "kJ".
pub fn prefixed(unit: &str, e: i32) -> String {
    format!("{}{unit}", prefix_symbol(e))
}

/// A number for people, never in e-notation: `digits` significant digits (trailing zeros dropped), with a
/// typographic minus; a value of 1e9 or more, or below 1e-4, as "1.23 × 10^n" with a superscript n.
pub fn plain(v: f64, digits: i32) -> String {
    if !v.is_finite() {
        return "\u{2013}".into();
    }
    if v == 0.0 {
        return "0".into();
    }
    let a = v.abs();
    let e = a.log10().floor() as i32;
    let out = if (-4..9).contains(&e) {
        let decimals = (digits - 1 - e).max(0) as usize;
        let f = 10f64.powi(digits - 1 - e);
        let s = format!("{:.*}", decimals, (v * f).round() / f);
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        }
    } else {
        let m = v / 10f64.powi(e);
        let sup: String = e
            .to_string()
            .chars()
            .map(|c| match c {
                '-' => '\u{207b}',
                '0' => '\u{2070}',
                '1' => '\u{b9}',
                '2' => '\u{b2}',
                '3' => '\u{b3}',
                d => char::from_u32(0x2070 + d.to_digit(10).unwrap_or(0)).unwrap_or(d),
            })
            .collect();
        format!("{} \u{d7} 10{sup}", plain(m, digits))
    };
    out.replace('-', "\u{2212}")
}

/// A value in its display unit with that unit ([`display_prefix`]) and `digits` significant digits:
/// "27.3 MN", "12.5 mm", "186.6 kJ", "35.2 ms".
pub fn human(v: f64, unit: &str, digits: i32) -> String {
    let e = display_prefix(unit, v.abs());
    let u = prefixed(unit, e);
    let x = plain(v / 10f64.powi(e), digits);
    if u.is_empty() {
        x
    } else {
        format!("{x} {u}")
    }
}

/// A computed axis: data range, ticks, and the power of ten the labels are divided by.
#[derive(Clone, Debug, PartialEq)]
pub struct Axis {
    /// Data value at the start of the axis (SI).
    pub lo: f64,
    /// Data value at the end of the axis (SI).
    pub hi: f64,
    /// Tick positions (SI).
    pub ticks: Vec<f64>,
    /// Decimal places of the tick labels (after the prefix scaling).
    decimals: usize,
    /// Exponent of the SI prefix (multiple of 3), 0 for none.
    prefix: i32,
    /// Label of the axis, with the unit: "contact force (MN)".
    pub label: String,
    /// Logarithmic (decades) instead of linear.
    pub log: bool,
}

impl Axis {
    /// An axis over the data range `[lo, hi]`. `tight` keeps the ends at the data (time axes); otherwise
    /// the ends extend to the next ticks. A degenerate range is widened around its value.
    pub fn new(q: &Quantity, lo: f64, hi: f64, tight: bool) -> Self {
        let (mut lo, mut hi) = if lo.is_finite() && hi.is_finite() && lo <= hi {
            (lo, hi)
        } else {
            (0.0, 1.0)
        };
        if hi - lo <= 1e-12 * hi.abs().max(lo.abs()) {
            let pad = if lo == 0.0 { 1.0 } else { 0.1 * lo.abs() };
            (lo, hi) = (lo - pad, hi + pad);
        }
        let step = nice_step((hi - lo) / 5.0);
        if !tight {
            // Data a hair beyond a tick (a penetration of -1e-19 m at separation) does not add a tick.
            lo = (lo / step + 1e-6).floor() * step;
            hi = (hi / step - 1e-6).ceil() * step;
        }
        let first = (lo / step - 1e-9).ceil() as i64;
        let last = (hi / step + 1e-9).floor() as i64;
        // Ticks as multiples of the step, snapped so that 0 prints as 0 and not -1e-17.
        let ticks: Vec<f64> = (first..=last).map(|i| i as f64 * step).collect();
        let biggest = ticks.iter().fold(0.0f64, |m, t| m.max(t.abs()));
        let prefix = q
            .prefix
            .unwrap_or_else(|| display_prefix(q.unit, hi.abs().max(lo.abs()).max(biggest)));
        let scaled_step = step / 10f64.powi(prefix);
        // 2.5 and 0.25 need one more decimal than their power of ten; 25 and 250 do not.
        let decimals = (-(scaled_step.log10() - 1e-9).floor()).max(0.0) as usize
            + usize::from(is_quarter(scaled_step) && scaled_step < 10.0);
        let unit = format!("{}{}", prefix_symbol(prefix), q.unit);
        let label = if unit.is_empty() {
            q.name.clone()
        } else {
            format!("{} ({unit})", q.name)
        };
        Self {
            lo,
            hi,
            ticks,
            decimals,
            prefix,
            label,
            log: false,
        }
    }

    /// A logarithmic axis from `lo` to `hi` (both > 0, else 1e-3 and 1e3), ticks at the decades, no prefix.
    pub fn log(q: &Quantity, lo: f64, hi: f64) -> Self {
        let (lo, hi) = if lo > 0.0 && hi > lo && hi.is_finite() {
            (lo, hi)
        } else {
            (1e-3, 1e3)
        };
        // Ticks at the decades; over fewer than three, at 1, 2 and 5 times them too.
        let decades = (lo.log10().floor() as i32)..=(hi.log10().ceil() as i32);
        let few = (hi / lo).log10() < 3.0;
        let ticks = decades
            .flat_map(|k| {
                let d = 10f64.powi(k);
                let m: &[f64] = if few { &[1.0, 2.0, 5.0] } else { &[1.0] };
                m.iter().map(move |m| m * d)
            })
            .filter(|t| *t >= lo * (1.0 - 1e-9) && *t <= hi * (1.0 + 1e-9))
            .collect();
        let label = if q.unit.is_empty() {
            q.name.clone()
        } else {
            format!("{} ({})", q.name, q.unit)
        };
        Self {
            lo,
            hi,
            ticks,
            decimals: 0,
            prefix: 0,
            label,
            log: true,
        }
    }

    /// Position of `value` along the axis, 0 at `lo` and 1 at `hi` (a log axis puts values <= 0 at 0... and
    /// below, so that clipping hides them).
    pub fn fraction(&self, value: f64) -> f64 {
        if self.log {
            let v = value.max(self.lo * 1e-3);
            (v / self.lo).log10() / (self.hi / self.lo).log10()
        } else {
            (value - self.lo) / (self.hi - self.lo)
        }
    }

    /// The label of the tick at `value` (SI), in the axis's prefixed unit, with a typographic minus.
    pub fn tick_label(&self, value: f64) -> String {
        if self.log {
            // 1, 2 or 5 times a power of ten: as many decimals as its first digit needs.
            let k = (value.log10() + 1e-9).floor() as i32;
            let m = (value / 10f64.powi(k)).round();
            return if (-4..=5).contains(&k) {
                format!("{:.*}", (-k).max(0) as usize, value)
            } else if m == 1.0 {
                format!("1e{k}").replace('-', "\u{2212}")
            } else {
                format!("{m}e{k}").replace('-', "\u{2212}")
            };
        }
        let x = value / 10f64.powi(self.prefix);
        let s = format!("{:.*}", self.decimals, x);
        let s = if s
            .trim_start_matches('-')
            .chars()
            .all(|c| c == '0' || c == '.')
        {
            s.trim_start_matches('-').to_string()
        } else {
            s
        };
        s.replace('-', "\u{2212}")
    }
}

/// The nice step (1, 2, 2.5 or 5 times a power of ten) nearest above `raw`.
fn nice_step(raw: f64) -> f64 {
    let p = 10f64.powf(raw.log10().floor());
    let f = raw / p;
    let m = if f <= 1.0 {
        1.0
    } else if f <= 2.0 {
        2.0
    } else if f <= 2.5 {
        2.5
    } else if f <= 5.0 {
        5.0
    } else {
        10.0
    };
    m * p
}

/// True if `step` needs one more decimal than its power of ten (2.5, 0.25, ...).
fn is_quarter(step: f64) -> bool {
    let p = 10f64.powf(step.log10().floor());
    ((step / p) - 2.5).abs() < 1e-9
}

/// The SI prefix of the power of ten `e` (a multiple of 3 from -9 to 9).
pub(crate) fn prefix_symbol(e: i32) -> &'static str {
    match e {
        -9 => "n",
        -6 => "\u{b5}",
        -3 => "m",
        3 => "k",
        6 => "M",
        9 => "G",
        _ => "",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn force_axis_in_meganewtons() {
        let a = Axis::new(&Quantity::new("contact force", "N"), 0.0, 2.3e6, false);
        assert_eq!(a.label, "contact force (MN)");
        assert_eq!((a.lo, a.hi), (0.0, 2.5e6));
        let labels: Vec<String> = a.ticks.iter().map(|t| a.tick_label(*t)).collect();
        assert_eq!(labels, ["0.0", "0.5", "1.0", "1.5", "2.0", "2.5"]);
    }

    #[test]
    fn negative_millimetres_use_a_minus_sign() {
        let a = Axis::new(&Quantity::new("displacement", "m"), -0.093, 0.05, false);
        assert_eq!(a.label, "displacement (mm)");
        assert_eq!(a.tick_label(-0.05), "\u{2212}50");
        assert_eq!(a.tick_label(0.0), "0");
    }

    #[test]
    fn rounding_noise_beyond_a_tick_adds_no_tick() {
        let a = Axis::new(&Quantity::new("penetration", "m"), -1e-19, 7.9e-3, false);
        assert_eq!(a.lo, 0.0);
        assert_eq!(a.ticks[0], 0.0);
    }

    #[test]
    fn log_axis_has_decades() {
        let a = Axis::log(&Quantity::new("error", "%"), 1e-3, 1e3);
        let labels: Vec<String> = a.ticks.iter().map(|t| a.tick_label(*t)).collect();
        assert_eq!(labels, ["0.001", "0.01", "0.1", "1", "10", "100", "1000"]);
        assert!((a.fraction(1.0) - 0.5).abs() < 1e-12);
        assert!(a.fraction(0.0) < 0.0);
    }

    #[test]
    fn short_log_axis_has_1_2_5_ticks() {
        let a = Axis::log(&Quantity::new("period", "s"), 0.05, 10.0);
        let labels: Vec<String> = a.ticks.iter().map(|t| a.tick_label(*t)).collect();
        assert_eq!(labels, ["0.05", "0.1", "0.2", "0.5", "1", "2", "5", "10"]);
        assert!((a.fraction(0.05)).abs() < 1e-12 && (a.fraction(10.0) - 1.0).abs() < 1e-12);
        let b = Axis::log(&Quantity::new("x", ""), 2e-7, 6e-5);
        let labels: Vec<String> = b.ticks.iter().map(|t| b.tick_label(*t)).collect();
        assert_eq!(
            labels,
            [
                "2e\u{2212}7",
                "5e\u{2212}7",
                "1e\u{2212}6",
                "2e\u{2212}6",
                "5e\u{2212}6",
                "1e\u{2212}5",
                "2e\u{2212}5",
                "5e\u{2212}5"
            ]
        );
    }

    #[test]
    fn tight_time_axis_keeps_the_data_range() {
        let a = Axis::new(&Quantity::new("time", "s"), 0.0, 31.18, true);
        assert_eq!((a.lo, a.hi), (0.0, 31.18));
        assert_eq!(a.ticks.last(), Some(&30.0));
        assert_eq!(a.label, "time (s)");
    }

    #[test]
    fn quarter_steps_get_one_more_decimal() {
        let a = Axis::new(&Quantity::new("e", ""), 0.0, 1.2, false);
        assert_eq!(a.ticks.len(), 6);
        assert_eq!(a.tick_label(0.25), "0.25");
        let b = Axis::new(&Quantity::new("x", ""), 0.0, 12.0, false);
        assert_eq!(b.tick_label(2.5), "2.5");
        assert_eq!(b.tick_label(5.0), "5.0");
        let c = Axis::new(&Quantity::new("x", ""), 0.0, 120.0, false);
        assert_eq!(c.tick_label(25.0), "25");
    }
}
