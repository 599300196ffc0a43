//! The separation the design codes require between neighbours (docs/separation.md, "The codes' rules"),
//! from a modal response-spectrum analysis of each building under a design spectrum: the elastic
//! displacement `d_e` of each floor combines the modes by CQC (Der Kiureghian 1981), each mode's
//! displacement `Gamma phi Sa(T) / w^2`.
//!
//! - ASCE 7-22 §12.12.2: `delta_M = C_d delta_max / I_e` per building; neighbours on one property
//!   `sqrt(delta_M1^2 + delta_M2^2)`; a building to its property line (a wall here) `delta_M`.
//! - EN 1998-1 §4.4.2.7 with §4.3.4: `d_s = q_d d_e` (`q_d = q` unless given); neighbours the SRSS of
//!   their `d_s`, times 0.7 where the floor levels coincide; to a boundary line `d_s`.
//! - IS 1893 (Part 1):2016 §7.11.3: `R` times the sum of the two buildings' displacements at the level,
//!   `R/2` where the floor levels coincide.
//! - GB 50011-2010 §6.1.4: a width from the lower building's height alone: 100 mm up to 15 m, then 20 mm
//!   more per 5, 4, 3 or 2 m for intensity 6, 7, 8 or 9 (frames); 70 % of it for frame–shear-wall and 50 %
//!   for shear-wall structures, never below 100 mm.

use super::cqc_correlation;
use crate::analysis::{Scenario, SiteKind};
use crate::error::check;
use crate::structure::ShearBuilding;
use crate::units::STANDARD_GRAVITY as G;
use crate::Error;

crate::named! {
    /// The design codes whose separation rule is implemented.
    pub enum CodeName: "code" {
        /// ASCE/SEI 7-22, §12.12.2.
        Asce7_22 = "asce7-22",
        /// EN 1998-1:2004 (Eurocode 8), §4.4.2.7.
        En1998_1 = "en1998-1",
        /// IS 1893 (Part 1):2016, §7.11.3.
        Is1893_2016 = "is1893-2016",
        /// GB 50011-2010, §6.1.4.
        Gb50011_2010 = "gb50011-2010",
    }
}

crate::named! {
    /// GB 50011's structural systems, for its joint width.
    pub enum GbSystem: "system" {
        /// Frame.
        Frame = "frame",
        /// Frame–shear-wall (70 % of the frame's width).
        FrameShearWall = "frame-shear-wall",
        /// Shear-wall (50 % of the frame's width).
        ShearWall = "shear-wall",
    }
}

crate::named! {
    /// EN 1998-1's ground types (Table 3.1).
    pub enum GroundType: "ground_type" {
        /// Rock.
        A = "A",
        /// Very dense sand, gravel or very stiff clay.
        B = "B",
        /// Dense or medium-dense sand, gravel or stiff clay.
        C = "C",
        /// Loose-to-medium cohesionless soil or soft-to-firm cohesive soil.
        D = "D",
        /// A surface alluvium layer over stiffer material.
        E = "E",
    }
}

/// A code's rule with its parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum CodeRule {
    /// ASCE 7-22: deflection amplification `C_d` and importance factor `I_e`.
    Asce7_22 {
        /// `C_d` (dimensionless).
        cd: f64,
        /// `I_e` (dimensionless).
        ie: f64,
    },
    /// EN 1998-1: behaviour factor `q` and displacement behaviour factor `q_d` (default `q`).
    En1998_1 {
        /// `q` (dimensionless).
        q: f64,
        /// `q_d` (dimensionless).
        qd: f64,
    },
    /// IS 1893: response reduction factor `R`.
    Is1893_2016 {
        /// `R` (dimensionless).
        r: f64,
    },
    /// GB 50011: seismic intensity (6 to 9) and structural system.
    Gb50011_2010 {
        /// Intensity, 6 to 9.
        intensity: u8,
        /// System.
        system: GbSystem,
    },
}

impl CodeRule {
    /// The rule checked: factors > 0 (`C_d`, `I_e`, `q`, `q_d`, `R`), intensity 6 to 9.
    pub fn checked(self) -> Result<Self, Error> {
        let pos = |name, x: f64| check(name, x, x > 0.0, "> 0");
        match self {
            CodeRule::Asce7_22 { cd, ie } => {
                pos("cd", cd)?;
                pos("ie", ie)?;
            }
            CodeRule::En1998_1 { q, qd } => {
                check("q", q, q >= 1.0, "q >= 1")?;
                check("qd", qd, qd >= 1.0, "qd >= 1")?;
            }
            CodeRule::Is1893_2016 { r } => {
                check("r", r, r >= 1.0, "r >= 1")?;
            }
            CodeRule::Gb50011_2010 { intensity, .. } => {
                if !(6..=9).contains(&intensity) {
                    return Err(Error::Choice {
                        name: "intensity",
                        value: intensity.to_string(),
                        allowed: "6, 7, 8 or 9".into(),
                    });
                }
            }
        }
        Ok(self)
    }

    /// Its name.
    pub fn name(&self) -> CodeName {
        match self {
            CodeRule::Asce7_22 { .. } => CodeName::Asce7_22,
            CodeRule::En1998_1 { .. } => CodeName::En1998_1,
            CodeRule::Is1893_2016 { .. } => CodeName::Is1893_2016,
            CodeRule::Gb50011_2010 { .. } => CodeName::Gb50011_2010,
        }
    }

    /// Whether the rule needs a response-spectrum analysis (GB 50011's does not).
    pub fn needs_spectrum(&self) -> bool {
        !matches!(self, CodeRule::Gb50011_2010 { .. })
    }
}

/// The design spectrum of the elastic analysis whose displacements a code amplifies: pseudo-acceleration
/// against period, 5 % damping.
#[derive(Clone, Debug, PartialEq)]
pub enum DesignSpectrum {
    /// Points `(T` s, `Sa` m/s^2), periods increasing: linear between them, held beyond the ends.
    Table(Vec<(f64, f64)>),
    /// ASCE 7-22 §11.4.6 two-period shape from `S_DS`, `S_D1` (g) and `T_L` (s), reduced by `I_e / R` (the
    /// analysis whose displacements `C_d / I_e` amplifies).
    Asce7 {
        /// `S_DS`, g.
        sds: f64,
        /// `S_D1`, g.
        sd1: f64,
        /// Long-period transition `T_L`, s.
        tl: f64,
        /// `R / I_e`, the reduction of the elastic spectrum (dimensionless).
        reduction: f64,
    },
    /// EN 1998-1 §3.2.2.5 design spectrum `S_d(T)` for ground acceleration `a_g` (m/s^2), ground type,
    /// spectrum type 1 or 2 and behaviour factor `q` (lower bound `0.2 a_g`).
    En1998 {
        /// Design ground acceleration on type A ground, m/s^2.
        ag: f64,
        /// Ground type.
        ground: GroundType,
        /// Type 1 (larger earthquakes) or 2.
        kind: u8,
        /// Behaviour factor `q`.
        q: f64,
    },
}

impl DesignSpectrum {
    /// The spectrum checked: a table of at least one row, periods increasing and >= 0, `Sa >= 0`; the
    /// shapes' parameters > 0, `S_D1 <= ... `, type 1 or 2.
    pub fn checked(self) -> Result<Self, Error> {
        match &self {
            DesignSpectrum::Table(rows) => {
                if rows.is_empty() {
                    return Err(Error::Choice {
                        name: "design_spectrum",
                        value: "no rows".into(),
                        allowed: "rows of period (s) and Sa (m/s^2)".into(),
                    });
                }
                for (k, &(t, sa)) in rows.iter().enumerate() {
                    let bad = !(t.is_finite() && t >= 0.0 && sa.is_finite() && sa >= 0.0)
                        || (k > 0 && t <= rows[k - 1].0);
                    if bad {
                        return Err(Error::Choice {
                            name: "design_spectrum",
                            value: format!(
                                "row {} [{}, {}]",
                                k + 1,
                                crate::words::number(t),
                                crate::words::number(sa)
                            ),
                            allowed: "periods >= 0 (s) increasing, Sa >= 0 (m/s^2)".into(),
                        });
                    }
                }
            }
            DesignSpectrum::Asce7 {
                sds,
                sd1,
                tl,
                reduction,
            } => {
                check("sds", *sds, *sds > 0.0, "sds > 0 (g)")?;
                check("sd1", *sd1, *sd1 > 0.0, "sd1 > 0 (g)")?;
                check("tl", *tl, *tl > 0.0, "tl > 0 (s)")?;
                check("r", *reduction, *reduction > 0.0, "r / ie > 0")?;
            }
            DesignSpectrum::En1998 { ag, kind, q, .. } => {
                check("ag", *ag, *ag > 0.0, "ag > 0 (m/s^2)")?;
                check("q", *q, *q >= 1.0, "q >= 1")?;
                if !matches!(kind, 1 | 2) {
                    return Err(Error::Choice {
                        name: "spectrum_type",
                        value: kind.to_string(),
                        allowed: "1 or 2 (EN 1998-1 §3.2.2.2)".into(),
                    });
                }
            }
        }
        Ok(self)
    }

    /// Pseudo-acceleration at period `t` (s), m/s^2.
    pub fn sa(&self, t: f64) -> f64 {
        match self {
            DesignSpectrum::Table(rows) => {
                let k = rows.partition_point(|r| r.0 <= t);
                match k {
                    0 => rows[0].1,
                    _ if k == rows.len() => rows[k - 1].1,
                    _ => {
                        let ((t0, a0), (t1, a1)) = (rows[k - 1], rows[k]);
                        a0 + (a1 - a0) * (t - t0) / (t1 - t0)
                    }
                }
            }
            DesignSpectrum::Asce7 {
                sds,
                sd1,
                tl,
                reduction,
            } => {
                let (t0, ts) = (0.2 * sd1 / sds, sd1 / sds);
                let sa = if t < t0 {
                    sds * (0.4 + 0.6 * t / t0)
                } else if t <= ts {
                    *sds
                } else if t <= *tl {
                    sd1 / t
                } else {
                    sd1 * tl / (t * t)
                };
                sa * G / reduction
            }
            DesignSpectrum::En1998 {
                ag,
                ground,
                kind,
                q,
            } => {
                let (s, tb, tc, td) = en1998_parameters(*ground, *kind);
                let base = ag * s;
                let sd = if t <= tb {
                    base * (2.0 / 3.0 + t / tb * (2.5 / q - 2.0 / 3.0))
                } else if t <= tc {
                    base * 2.5 / q
                } else if t <= td {
                    base * 2.5 / q * tc / t
                } else {
                    base * 2.5 / q * tc * td / (t * t)
                };
                // The lower bound beta a_g (beta = 0.2) beyond T_C.
                if t > tc {
                    sd.max(0.2 * ag)
                } else {
                    sd
                }
            }
        }
    }
}

/// EN 1998-1 Tables 3.2 (type 1) and 3.3 (type 2): `S`, `T_B`, `T_C`, `T_D` (s) of a ground type.
pub fn en1998_parameters(ground: GroundType, kind: u8) -> (f64, f64, f64, f64) {
    use GroundType::*;
    match (kind, ground) {
        (1, A) => (1.0, 0.15, 0.4, 2.0),
        (1, B) => (1.2, 0.15, 0.5, 2.0),
        (1, C) => (1.15, 0.20, 0.6, 2.0),
        (1, D) => (1.35, 0.20, 0.8, 2.0),
        (1, E) => (1.4, 0.15, 0.5, 2.0),
        (_, A) => (1.0, 0.05, 0.25, 1.2),
        (_, B) => (1.35, 0.05, 0.25, 1.2),
        (_, C) => (1.5, 0.10, 0.25, 1.2),
        (_, D) => (1.8, 0.10, 0.30, 1.2),
        (_, E) => (1.6, 0.05, 0.25, 1.2),
    }
}

/// The elastic displacement of each floor of `b` under `spectrum` (m): modal response-spectrum analysis,
/// every mode, combined by CQC with each mode's damping ratio.
pub fn elastic_displacements(b: &ShearBuilding, spectrum: &DesignSpectrum) -> Vec<f64> {
    let modes = b.modes();
    let part = modes.participation(b.masses());
    let n = b.storeys();
    let d: Vec<Vec<f64>> = (0..n)
        .map(|r| {
            let w = modes.omega[r];
            let sd = spectrum.sa(2.0 * std::f64::consts::PI / w) / (w * w);
            modes.shapes[r].iter().map(|p| part[r].0 * p * sd).collect()
        })
        .collect();
    let z: Vec<f64> = (0..n).map(|r| b.damping_of_mode(r)).collect();
    (0..n)
        .map(|i| {
            let mut s = 0.0;
            for r in 0..n {
                for q in 0..n {
                    let rho = cqc_correlation(modes.omega[r], z[r], modes.omega[q], z[q]);
                    s += rho * d[r][i] * d[q][i];
                }
            }
            s.max(0.0).sqrt()
        })
        .collect()
}

/// GB 50011-2010 §6.1.4's joint width (m) for the lower building's height `h` (m).
pub fn gb50011_width(h: f64, intensity: u8, system: GbSystem) -> f64 {
    let per = match intensity {
        6 => 5.0,
        7 => 4.0,
        8 => 3.0,
        _ => 2.0,
    };
    let frame = 0.1 + 0.02 * ((h - 15.0).max(0.0) / per);
    let w = match system {
        GbSystem::Frame => frame,
        GbSystem::FrameShearWall => 0.7 * frame,
        GbSystem::ShearWall => 0.5 * frame,
    };
    w.max(0.1)
}

/// One contact level of a pair under a code's rule.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct CodeLevel {
    /// Floors (of the left building, of the right), from 1.
    pub floors: (usize, usize),
    /// The elastic displacement of each floor under the design spectrum, m (none for GB 50011).
    pub elastic: Option<(f64, f64)>,
    /// Whether the floors are at the same height (within 1 mm).
    pub aligned: bool,
    /// The gap the code requires here, m.
    pub code_required_gap: f64,
}

/// The gap `rule` requires at each contact level of each pair of neighbours of `s`: `(left, right,
/// levels)` per pair. `spectrum` is needed by every rule but GB 50011's.
pub fn code_gaps(
    s: &Scenario,
    rule: CodeRule,
    spectrum: Option<&DesignSpectrum>,
) -> Result<Vec<(usize, usize, Vec<CodeLevel>)>, Error> {
    let rule = rule.checked()?;
    let spectrum = match (rule.needs_spectrum(), spectrum) {
        (true, None) => {
            return Err(Error::Choice {
                name: "design_spectrum",
                value: "missing".into(),
                allowed: format!(
                    "a design spectrum (a file of period s and Sa m/s^2, or the asce7-22 or en1998-1 shape) for code {}",
                    rule.name()
                ),
            })
        }
        (_, sp) => sp,
    };
    let b = s.buildings();
    let elastic: Vec<Vec<f64>> = match spectrum {
        Some(sp) => b
            .iter()
            .map(|x| elastic_displacements(&x.structure, sp))
            .collect(),
        None => Vec::new(),
    };
    let mut out = Vec::new();
    for site in s.sites() {
        let SiteKind::Between { left, right } = site.kind else {
            continue;
        };
        let aligned_floors = s.aligned_floors(left);
        let levels = site
            .levels
            .iter()
            .map(|level| {
                let (i, j) = (level.left.unwrap_or(1), level.right.unwrap_or(1));
                let aligned = aligned_floors.contains(&(i, j));
                let de =
                    (!elastic.is_empty()).then(|| (elastic[left][i - 1], elastic[right][j - 1]));
                let (dl, dr) = de.unwrap_or((0.0, 0.0));
                let gap = match rule {
                    CodeRule::Asce7_22 { cd, ie } => (cd * dl / ie).hypot(cd * dr / ie),
                    CodeRule::En1998_1 { qd, .. } => {
                        let f = if aligned { 0.7 } else { 1.0 };
                        f * (qd * dl).hypot(qd * dr)
                    }
                    CodeRule::Is1893_2016 { r } => {
                        let f = if aligned { 0.5 } else { 1.0 };
                        f * r * (dl + dr)
                    }
                    CodeRule::Gb50011_2010 { intensity, system } => {
                        let h =
                            |k: usize| b[k].structure.elevations().last().copied().unwrap_or(0.0);
                        gb50011_width(h(left).min(h(right)), intensity, system)
                    }
                };
                CodeLevel {
                    floors: (i, j),
                    elastic: de,
                    aligned,
                    code_required_gap: gap,
                }
            })
            .collect();
        out.push((left, right, levels));
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_spectrum_shapes_follow_their_clauses() {
        // ASCE 7-22 11.4.6: S_DS = 1 g, S_D1 = 0.6 g, T_L = 8 s: T0 = 0.12 s, T_S = 0.6 s.
        let asce = DesignSpectrum::Asce7 {
            sds: 1.0,
            sd1: 0.6,
            tl: 8.0,
            reduction: 1.0,
        };
        for (t, sa_g) in [
            (0.0, 0.4),
            (0.06, 0.7),
            (0.3, 1.0),
            (1.2, 0.5),
            (10.0, 0.048),
        ] {
            assert!(
                (asce.sa(t) / G - sa_g).abs() < 1e-12,
                "T {t}: {}",
                asce.sa(t) / G
            );
        }
        // EN 1998-1 3.2.2.5, type 1, ground B (S 1.2, T_B 0.15, T_C 0.5, T_D 2), a_g 2.5 m/s^2.
        let ec8 = |q| DesignSpectrum::En1998 {
            ag: 2.5,
            ground: GroundType::B,
            kind: 1,
            q,
        };
        for (q, t, sd) in [
            (1.0, 0.0, 2.0),
            (1.0, 0.3, 7.5),
            (1.0, 1.0, 3.75),
            (1.0, 3.0, 7.5 * 0.5 * 2.0 / 9.0),
            (4.0, 3.0, 0.5),
        ] {
            assert!(
                (ec8(q).sa(t) - sd).abs() < 1e-12,
                "q {q} T {t}: {}",
                ec8(q).sa(t)
            );
        }
    }

    #[test]
    fn the_gb50011_width_grows_with_height_by_intensity() {
        for (h, i, sys, w) in [
            (12.0, 9, GbSystem::Frame, 0.1),
            (30.0, 8, GbSystem::Frame, 0.2),
            (30.0, 8, GbSystem::FrameShearWall, 0.14),
            (30.0, 8, GbSystem::ShearWall, 0.1),
            (40.0, 7, GbSystem::Frame, 0.225),
            (40.0, 6, GbSystem::ShearWall, 0.1),
            (45.0, 9, GbSystem::ShearWall, 0.5 * 0.4),
        ] {
            assert!(
                (gb50011_width(h, i, sys) - w).abs() < 1e-12,
                "{h} {i} {sys:?}"
            );
        }
    }
}
