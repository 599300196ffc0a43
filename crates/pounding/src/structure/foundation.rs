//! Soil–structure interaction: a building's rigid foundation (its mass and rotational inertia) on sway and
//! rocking springs and dashpots to the free-field ground (`docs/structures.md`, "Soil and foundation").
//!
//! The springs are given, or come from the soil and the foundation: a rigid circular foundation of radius `r`
//! on a homogeneous elastic half-space of shear-wave velocity `V_s`, density `rho` and Poisson's ratio `nu`,
//! `G = rho V_s^2`, with the static stiffnesses (Gazetas 1991, "Formulas and charts for impedances of surface
//! and embedded foundations", J. Geotech. Eng. 117(9), Table 1; Wolf 1994, *Foundation Vibration Analysis
//! Using Simple Physical Models*)
//!
//! `K_x = 8 G r / (2 - nu)`, `K_theta = 8 G r^3 / (3 (1 - nu))`,
//!
//! and the dashpots of Wolf's cones (Wolf 1994, Table 2-3A; Wolf & Deeks 2004, Table 2.3): sway
//! `C_x = rho V_s pi r^2`, rocking `C_theta = rho V_p pi r^4 / 4` with `V_p` the dilatational velocity, capped at
//! `2 V_s` for `nu > 1/3`, where a trapped mass moment of inertia `1.2 (nu - 1/3) rho (pi r^4 / 4) r` joins the
//! foundation's. A rectangular foundation `a x b` (`a` along the motion) takes the radius of the disk of the
//! same area for sway, `sqrt(a b / pi)`, and of the same moment of area for rocking, `(b a^3 / (3 pi))^(1/4)`.
//! The springs and dashpots do not depend on frequency: the simplest of Wolf's physical models.

use crate::error::check;
use crate::Error;

/// What a foundation's springs and dashpots come from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Soil {
    /// Given directly.
    Given {
        /// Sway stiffness, N/m.
        kx: f64,
        /// Rocking stiffness, N m/rad.
        ktheta: f64,
        /// Sway dashpot, N s/m.
        cx: f64,
        /// Rocking dashpot, N m s/rad.
        ctheta: f64,
    },
    /// A homogeneous half-space under a rigid foundation.
    HalfSpace {
        /// Shear-wave velocity, m/s.
        vs: f64,
        /// Density, kg/m^3.
        density: f64,
        /// Poisson's ratio (dimensionless).
        poisson: f64,
        /// The foundation's shape.
        shape: Shape,
    },
}

/// A rigid foundation's shape in plan.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Shape {
    /// A disk of radius `r`, m.
    Disk(f64),
    /// A rectangle `a x b`, m, `a` along the motion.
    Rectangle(f64, f64),
}

impl Shape {
    /// The radii of the equivalent disks for sway and for rocking, m.
    pub fn radii(self) -> (f64, f64) {
        match self {
            Shape::Disk(r) => (r, r),
            Shape::Rectangle(a, b) => (
                (a * b / std::f64::consts::PI).sqrt(),
                (b * a.powi(3) / (3.0 * std::f64::consts::PI)).powf(0.25),
            ),
        }
    }
}

/// A building's foundation on the soil: its mass and moment of inertia about the horizontal axis normal to the
/// motion (a trapped soil mass included), and the springs and dashpots of sway and rocking.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Foundation {
    /// Mass, kg (> 0).
    pub mass: f64,
    /// Moment of inertia about the rocking axis through the foundation's centre, kg m^2 (> 0), with the
    /// trapped soil's.
    pub inertia: f64,
    /// Sway stiffness, N/m.
    pub kx: f64,
    /// Rocking stiffness, N m/rad.
    pub ktheta: f64,
    /// Sway dashpot, N s/m.
    pub cx: f64,
    /// Rocking dashpot, N m s/rad.
    pub ctheta: f64,
    /// What the springs and dashpots came from.
    pub soil: Soil,
}

impl Foundation {
    /// A foundation of `mass` (kg, >= 0; a run needs it > 0, [`crate::structure::ShearBuilding::with_foundation`])
    /// and moment of inertia `inertia` (kg m^2, >= 0; `None`: a disk's or a rectangle's, uniform, `m r^2 / 4` or
    /// `m a^2 / 12`, from the soil's shape; required with given springs) on `soil`. Errors name the key
    /// (`foundation.vs`).
    pub fn new(mass: f64, inertia: Option<f64>, soil: Soil) -> Result<Self, Error> {
        let positive = |name: &'static str, x: f64, unit: &'static str| {
            check(name, x, x > 0.0 && x.is_finite(), unit)
        };
        check(
            "foundation.mass",
            mass,
            mass >= 0.0 && mass.is_finite(),
            "finite mass >= 0 (kg)",
        )?;
        let (kx, ktheta, cx, ctheta, trapped, own) = match soil {
            Soil::Given {
                kx,
                ktheta,
                cx,
                ctheta,
            } => {
                positive("foundation.kx", kx, "finite kx > 0 (N/m)")?;
                positive("foundation.ktheta", ktheta, "finite ktheta > 0 (N m/rad)")?;
                for (name, c) in [("foundation.cx", cx), ("foundation.ctheta", ctheta)] {
                    check(name, c, c >= 0.0 && c.is_finite(), "finite dashpot >= 0")?;
                }
                (kx, ktheta, cx, ctheta, 0.0, None)
            }
            Soil::HalfSpace {
                vs,
                density,
                poisson,
                shape,
            } => {
                positive("foundation.vs", vs, "finite V_s > 0 (m/s)")?;
                positive("foundation.density", density, "finite density > 0 (kg/m^3)")?;
                check(
                    "foundation.poisson",
                    poisson,
                    (0.0..0.5).contains(&poisson),
                    "0 <= poisson < 0.5",
                )?;
                let (r_x, r_t) = match shape {
                    Shape::Disk(r) => {
                        positive("foundation.radius", r, "finite radius > 0 (m)")?;
                        (r, r)
                    }
                    Shape::Rectangle(a, b) => {
                        positive("foundation.size", a, "finite sides > 0 (m)")?;
                        positive("foundation.size", b, "finite sides > 0 (m)")?;
                        shape.radii()
                    }
                };
                let h = HalfSpace::new(vs, density, poisson);
                let own = match shape {
                    Shape::Disk(r) => mass * r * r / 4.0,
                    Shape::Rectangle(a, _) => mass * a * a / 12.0,
                };
                let (kx, cx) = h.sway(r_x);
                let (kt, ct, trapped) = h.rocking(r_t);
                (kx, kt, cx, ct, trapped, Some(own))
            }
        };
        let inertia = match (inertia, own) {
            (Some(j), _) => check(
                "foundation.inertia",
                j,
                j >= 0.0 && j.is_finite(),
                "finite moment of inertia >= 0 (kg m^2)",
            )?,
            (None, Some(j)) => j,
            (None, None) => {
                return Err(Error::Choice {
                    name: "foundation.inertia",
                    value: "(none)".into(),
                    allowed: "a moment of inertia (kg m^2) with springs given directly (or radius/size with the soil's velocity)".into(),
                })
            }
        };
        Ok(Self {
            mass,
            inertia: inertia + trapped,
            kx,
            ktheta,
            cx,
            ctheta,
            soil,
        })
    }
}

/// A homogeneous elastic half-space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HalfSpace {
    /// Shear-wave velocity, m/s.
    pub vs: f64,
    /// Density, kg/m^3.
    pub density: f64,
    /// Poisson's ratio.
    pub poisson: f64,
}

impl HalfSpace {
    /// The half-space of shear-wave velocity `vs` (m/s), `density` (kg/m^3) and Poisson's ratio `poisson`.
    pub fn new(vs: f64, density: f64, poisson: f64) -> Self {
        Self {
            vs,
            density,
            poisson,
        }
    }

    /// Shear modulus `G = rho V_s^2`, Pa.
    pub fn shear_modulus(&self) -> f64 {
        self.density * self.vs * self.vs
    }

    /// Dilatational velocity `V_p = V_s sqrt(2 (1 - nu) / (1 - 2 nu))`, m/s.
    pub fn vp(&self) -> f64 {
        let nu = self.poisson;
        self.vs * (2.0 * (1.0 - nu) / (1.0 - 2.0 * nu)).sqrt()
    }

    /// Sway of a rigid disk of radius `r` (m): `(K_x, C_x)`, N/m and N s/m.
    pub fn sway(&self, r: f64) -> (f64, f64) {
        let (g, nu) = (self.shear_modulus(), self.poisson);
        (
            8.0 * g * r / (2.0 - nu),
            self.density * self.vs * std::f64::consts::PI * r * r,
        )
    }

    /// Rocking of a rigid disk of radius `r` (m): `(K_theta, C_theta, trapped moment of inertia)`, N m/rad,
    /// N m s/rad and kg m^2 (Wolf's cone: `V_p` capped at `2 V_s` and a trapped mass for `nu > 1/3`).
    pub fn rocking(&self, r: f64) -> (f64, f64, f64) {
        let (g, nu, rho) = (self.shear_modulus(), self.poisson, self.density);
        let i0 = std::f64::consts::PI * r.powi(4) / 4.0;
        let k = 8.0 * g * r.powi(3) / (3.0 * (1.0 - nu));
        let (c, trapped) = if nu > 1.0 / 3.0 {
            (
                rho * 2.0 * self.vs * i0,
                1.2 * (nu - 1.0 / 3.0) * rho * i0 * r,
            )
        } else {
            (rho * self.vp() * i0, 0.0)
        };
        (k, c, trapped)
    }
}

/// The modes of a shear building (floor `masses` kg, storey `stiffnesses` N/m and `heights` m, storey 1
/// first) on `foundation`: circular frequencies (rad/s, lowest first) and mass-normalised shapes over the floors'
/// displacements (with the rocking's share), the foundation's sway and its rocking, in that order. A massless
/// foundation (or one without inertia) is condensed out statically: its modes are the building's, and its
/// shapes' foundation components are those its springs take under the floors' forces.
pub fn flexible_modes(
    masses: &[f64],
    stiffnesses: &[f64],
    heights: &[f64],
    foundation: &Foundation,
) -> (Vec<f64>, Vec<Vec<f64>>) {
    let n = masses.len();
    let d = n + 2;
    let (uf, th) = (n, n + 1);
    let mut k = vec![0.0; d * d];
    let mut add = |terms: &[(usize, f64)], kk: f64| {
        for &(i, ci) in terms {
            for &(j, cj) in terms {
                k[i * d + j] += kk * ci * cj;
            }
        }
    };
    for j in 0..n {
        let below = if j == 0 { uf } else { j - 1 };
        add(
            &[(j, 1.0), (below, -1.0), (th, -heights[j])],
            stiffnesses[j],
        );
    }
    add(&[(uf, 1.0)], foundation.kx);
    add(&[(th, 1.0)], foundation.ktheta);
    let mut m: Vec<f64> = masses.to_vec();
    m.extend([foundation.mass, foundation.inertia]);
    // Static condensation of the massless degrees of freedom: K* = K_aa - K_ab K_bb^-1 K_ba.
    let kept: Vec<usize> = (0..d).filter(|&i| m[i] > 0.0).collect();
    let gone: Vec<usize> = (0..d).filter(|&i| m[i] <= 0.0).collect();
    let (a, b) = (kept.len(), gone.len());
    let kbb: Vec<f64> = gone
        .iter()
        .flat_map(|&i| gone.iter().map(move |&j| (i, j)))
        .map(|(i, j)| k[i * d + j])
        .collect();
    let inv = invert(&kbb, b);
    let mut ks = vec![0.0; a * a];
    for (p, &i) in kept.iter().enumerate() {
        for (q, &j) in kept.iter().enumerate() {
            let mut v = k[i * d + j];
            for (r, &g) in gone.iter().enumerate() {
                for (t, &h) in gone.iter().enumerate() {
                    v -= k[i * d + g] * inv[r * b + t] * k[h * d + j];
                }
            }
            ks[p * a + q] = v;
        }
    }
    let s: Vec<f64> = kept.iter().map(|&i| 1.0 / m[i].sqrt()).collect();
    let mut sym: Vec<f64> = (0..a * a)
        .map(|pq| ks[pq] * s[pq / a] * s[pq % a])
        .collect();
    let e = super::eigen::symmetric(&mut sym, a);
    let mut order: Vec<usize> = (0..a).collect();
    order.sort_by(|&x, &y| e.values[x].total_cmp(&e.values[y]));
    let omega = order.iter().map(|&r| e.values[r].max(0.0).sqrt()).collect();
    let shapes = order
        .iter()
        .map(|&r| {
            let mut phi = vec![0.0; d];
            for (p, &i) in kept.iter().enumerate() {
                phi[i] = e.vectors[p * a + r] * s[p];
            }
            // The condensed degrees of freedom follow: u_b = -K_bb^-1 K_ba u_a.
            for (r2, &g) in gone.iter().enumerate() {
                let mut v = 0.0;
                for (t, &h) in gone.iter().enumerate() {
                    let kba: f64 = kept.iter().map(|&i| k[h * d + i] * phi[i]).sum();
                    v -= inv[r2 * b + t] * kba;
                }
                phi[g] = v;
            }
            if phi[n - 1] < 0.0 {
                phi.iter_mut().for_each(|x| *x = -*x);
            }
            phi
        })
        .collect();
    (omega, shapes)
}

/// The inverse of a small symmetric positive-definite matrix (`n` at most 2 here), row-major.
fn invert(a: &[f64], n: usize) -> Vec<f64> {
    match n {
        0 => Vec::new(),
        1 => vec![1.0 / a[0]],
        _ => {
            let det = a[0] * a[3] - a[1] * a[2];
            vec![a[3] / det, -a[1] / det, -a[2] / det, a[0] / det]
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The same through the building's modes on a massless foundation (statically condensed): the period
    /// ratio equals the closed form to 1e-12, and the check values to their 7 digits.
    #[test]
    fn the_modes_on_a_massless_foundation_are_the_closed_form() {
        let (m, t, h, r, rho, nu) = (5.0e5, 0.5, 10.0, 8.0, 1800.0, 0.33);
        let w0 = 2.0 * std::f64::consts::PI / t;
        let k = m * w0 * w0;
        for (vs, want) in [(400.0, 1.010251), (200.0, 1.040398), (100.0, 1.153133)] {
            let soil = Soil::HalfSpace {
                vs,
                density: rho,
                poisson: nu,
                shape: Shape::Disk(r),
            };
            let f = Foundation::new(0.0, Some(0.0), soil).unwrap();
            let (w, shapes) = flexible_modes(&[m], &[k], &[h], &f);
            assert_eq!(w.len(), 1);
            let closed = (1.0 + k / f.kx + k * h * h / f.ktheta).sqrt();
            assert!((w0 / w[0] / closed - 1.0).abs() < 1e-12, "V_s {vs}");
            assert!(
                (w0 / w[0] - want).abs() < 5e-7,
                "V_s {vs}: {} vs {want}",
                w0 / w[0]
            );
            // The foundation takes the floor's force through its springs: sway F / K_x, rocking F h / K_theta.
            let phi = &shapes[0];
            let force = k * (phi[0] - phi[1] - h * phi[2]);
            assert!((phi[1] - force / f.kx).abs() < 1e-12 * phi[0].abs());
            assert!((phi[2] - force * h / f.ktheta).abs() < 1e-12 * phi[0].abs() / h);
        }
    }

    /// An SDOF (k, h) on a massless foundation over the half-space: `T~ / T = sqrt(1 + k / K_x + k h^2 /
    /// K_theta)` (Veletsos & Meek 1974), the check values of next-physics.md section 4 to 1e-6 (they are given
    /// to 7 digits).
    #[test]
    fn the_flexible_base_period_of_next_physics() {
        let (m, t, h, r, rho, nu) = (5.0e5, 0.5, 10.0, 8.0, 1800.0, 0.33);
        let k = m * (2.0 * std::f64::consts::PI / t).powi(2);
        for (vs, want) in [(400.0, 1.010251), (200.0, 1.040398), (100.0, 1.153133)] {
            let hs = HalfSpace::new(vs, rho, nu);
            let (kx, _) = hs.sway(r);
            let (kt, _, trapped) = hs.rocking(r);
            assert_eq!(trapped, 0.0, "nu = 0.33 <= 1/3: no trapped mass");
            let ratio = (1.0 + k / kx + k * h * h / kt).sqrt();
            assert!((ratio - want).abs() < 5e-7, "V_s {vs}: {ratio} vs {want}");
        }
    }
}
