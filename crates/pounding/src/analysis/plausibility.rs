//! The common unit slips a scenario may hide, said as warnings: a gap or a device's opening larger than the
//! buildings are tall (millimetres written as metres), a first period under 0.05 s or above 20 s (masses in
//! tonnes, stiffnesses in kN/m), a peak ground acceleration above 5 g (a record in m/s^2 or cm/s^2 read as g).
//! None of them is an error: such structures and records exist, rarely.

use super::{DeviceEnds, Scenario, SiteKind};
use crate::units::STANDARD_GRAVITY as G;

/// First periods outside this range, s, are said.
pub const PLAUSIBLE_PERIOD: (f64, f64) = (0.05, 20.0);

/// Peak ground accelerations above this many g are said.
pub const PLAUSIBLE_PGA_G: f64 = 5.0;

/// `x` with four significant digits, in its shortest form (`0.007071`, `1e300`).
fn sig(x: f64) -> String {
    crate::words::number(format!("{x:.3e}").parse().unwrap_or(x))
}

impl Scenario {
    /// The unit slips this scenario may hide, each a sentence naming the value, the likely slip and the unit
    /// expected (empty for an ordinary scenario).
    pub fn implausible(&self) -> Vec<String> {
        let mut said = Vec::new();
        let height = |b: usize| self.buildings[b].structure.heights().iter().sum::<f64>();
        for b in &self.buildings {
            let t1 = b
                .structure
                .modes()
                .periods()
                .first()
                .copied()
                .unwrap_or(1.0);
            let (lo, hi) = PLAUSIBLE_PERIOD;
            if t1 < lo {
                said.push(format!("building {:?}: first period {} s is under {lo} s: masses in tonnes? masses are in kg, stiffnesses in N/m", b.name, sig(t1)));
            } else if t1 > hi {
                said.push(format!("building {:?}: first period {} s is over {hi} s: stiffnesses in kN/m? stiffnesses are in N/m, masses in kg", b.name, sig(t1)));
            }
        }
        for site in &self.sites {
            let tall = match site.kind {
                SiteKind::Between { left, right } => height(left).max(height(right)),
                SiteKind::Wall { building, .. } => height(building),
            };
            if site.gap > tall {
                said.push(format!("{} {}: gap {} m is larger than the buildings are tall ({} m): a gap in mm? gaps are in m", if site.is_wall() { "wall" } else { "contact" }, site.name, sig(site.gap), sig(tall)));
            }
        }
        for d in &self.devices {
            let tall = match d.ends {
                DeviceEnds::Buildings { left, right } => height(left).max(height(right)),
                DeviceEnds::Wall { site } => height(self.site_building(&self.sites[site])),
            };
            for p in d.law.parameters().iter().filter(|p| p.unit == "m") {
                if p.value > tall {
                    said.push(format!("device {}: {} {} m is larger than the buildings are tall ({} m): in mm? lengths are in m", d.name, p.key, sig(p.value), sig(tall)));
                }
            }
        }
        let pga = self.record.pga();
        if pga > PLAUSIBLE_PGA_G * G {
            said.push(format!("record: PGA {} m/s^2 ({} g) is above {PLAUSIBLE_PGA_G} g: a record in m/s^2 or cm/s^2 read as g? state units in [ground_motion]", sig(pga), sig(pga / G)));
        }
        said
    }
}
