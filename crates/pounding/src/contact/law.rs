//! Force laws resolved for one impact (effective mass and impact velocity known). Forces in N, penetration
//! `d` in m, rate `v = d'` in m/s.

/// Phase of an impact: approach (`v > 0`, compression) or restitution (`v <= 0`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Phase {
    /// Compression, until the rate `v` first reaches 0.
    Approach,
    /// Restitution, from the turning point until the contact ends.
    Restitution,
}

/// What a law remembers of the current impact: the turning point (maximum penetration in m and the force
/// there in N), used by hysteretic laws on unloading.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Turn {
    /// Penetration at the turning point, m.
    pub d: f64,
    /// Force at the turning point, N.
    pub force: f64,
}

/// A contact force law with every parameter fixed for one impact. The force is the smooth continuation of
/// the law for any `d` (signed powers for `d < 0`), so that an integrator may step past the end of contact
/// and locate it as an event; whether the contact has ended is decided by the caller.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ForceLaw {
    /// `F = k d^n`; `k` in N/m^n.
    Elastic {
        /// Stiffness, N/m^n.
        k: f64,
        /// Exponent.
        n: f64,
    },
    /// `F = k d + c v` in approach, `k d + c_r v` in restitution; `k` in N/m, `c`, `c_r` in N s/m.
    LinearViscous {
        /// Stiffness, N/m.
        k: f64,
        /// Approach damping coefficient, N s/m.
        c: f64,
        /// Restitution damping coefficient, N s/m.
        c_r: f64,
    },
    /// `F = k d^n (1 + chi v / v_i)` in approach, `chi_r` in place of `chi` in restitution.
    HuntCrossley {
        /// Stiffness, N/m^n.
        k: f64,
        /// Exponent.
        n: f64,
        /// Approach damping factor (dimensionless).
        chi: f64,
        /// Restitution damping factor (dimensionless).
        chi_r: f64,
        /// Impact velocity, m/s.
        v_i: f64,
    },
    /// `F = k d^n + c0 d^((n-1)/2) v` in approach, `k d^n` in restitution, `c0 = 2 xi sqrt(k m)`.
    Jankowski {
        /// Stiffness, N/m^n.
        k: f64,
        /// Exponent.
        n: f64,
        /// `2 xi sqrt(k m)`, in N s / m^((n+1)/2).
        c0: f64,
    },
    /// Bilinear loop: loading `K1` up to `d_y`, then `K2`; unloading with `K1` down to the line `F = K2 d`.
    Bilinear {
        /// Initial (and unloading) stiffness, N/m.
        k1: f64,
        /// Post-yield stiffness, N/m.
        k2: f64,
        /// Yield penetration, m.
        d_y: f64,
    },
    /// Thornton (1997) elastic–perfectly-plastic spheres: Hertz `k d^(3/2)` up to `d_y`, where the contact
    /// pressure reaches the yield pressure `p_y`, then `f_y + k_p (d - d_y)` with `k_p = pi p_y R` (the same
    /// slope as Hertz there); unloading Hertzian about a permanent set with the larger radius
    /// `R_p = 4 E* a_p^3 / (3 F_p)`, `a_p^2 = (2 F_p + f_y) / (2 pi p_y)` ([`thornton_unloading`]).
    Thornton {
        /// Hertz stiffness `(4/3) E* sqrt(R)`, N/m^1.5.
        k: f64,
        /// Effective modulus `E*`, Pa.
        e_star: f64,
        /// Yield pressure (the largest contact pressure), Pa.
        p_y: f64,
        /// Penetration at first yield, m.
        d_y: f64,
        /// Force at first yield, N.
        f_y: f64,
        /// Slope of plastic loading `pi p_y R`, N/m.
        k_p: f64,
    },
}

/// The unloading curve of a Thornton contact from the turning point `(d_p, F_p)` (m, N) past first yield:
/// `F = (4/3) E* sqrt(R_p) (d - d_f)^(3/2)`; returns `((4/3) E* sqrt(R_p), d_f)` (N/m^1.5, m). It passes
/// through the turning point: `(4/3) E* sqrt(R_p) (a_p^2 / R_p)^(3/2) = (4/3) E* a_p^3 / R_p = F_p`.
pub fn thornton_unloading(e_star: f64, p_y: f64, f_y: f64, d_p: f64, f_p: f64) -> (f64, f64) {
    let a_p2 = (2.0 * f_p + f_y) / (2.0 * std::f64::consts::PI * p_y);
    let r_p = 4.0 * e_star * a_p2 * a_p2.sqrt() / (3.0 * f_p);
    (4.0 / 3.0 * e_star * r_p.sqrt(), d_p - a_p2 / r_p)
}

/// `sign(d) |d|^n`, with the common exponents computed without `powf`.
#[inline]
pub(crate) fn spow(d: f64, n: f64) -> f64 {
    let a = d.abs();
    let p = if n == 1.0 {
        a
    } else if n == 1.5 {
        a * a.sqrt()
    } else {
        a.powf(n)
    };
    p.copysign(d)
}

impl ForceLaw {
    /// Contact force in N (positive pushes the bodies apart) at penetration `d` (m) and rate `v` (m/s).
    #[inline]
    pub fn force(&self, d: f64, v: f64, phase: Phase, turn: &Turn) -> f64 {
        match *self {
            ForceLaw::Elastic { k, n } => k * spow(d, n),
            ForceLaw::LinearViscous { k, c, c_r } => {
                k * d
                    + v * match phase {
                        Phase::Approach => c,
                        Phase::Restitution => c_r,
                    }
            }
            ForceLaw::HuntCrossley {
                k,
                n,
                chi,
                chi_r,
                v_i,
            } => {
                let x = match phase {
                    Phase::Approach => chi,
                    Phase::Restitution => chi_r,
                };
                k * spow(d, n) * (1.0 + x * v / v_i)
            }
            ForceLaw::Jankowski { k, n, c0 } => {
                let el = k * spow(d, n);
                match phase {
                    Phase::Approach => el + c0 * spow(d, 0.5 * (n - 1.0)).abs() * v,
                    Phase::Restitution => el,
                }
            }
            ForceLaw::Bilinear { k1, k2, d_y } => match phase {
                Phase::Approach => {
                    if d <= d_y {
                        k1 * d
                    } else {
                        k1 * d_y + k2 * (d - d_y)
                    }
                }
                Phase::Restitution => (turn.force - k1 * (turn.d - d)).max(k2 * d),
            },
            ForceLaw::Thornton {
                k,
                e_star,
                p_y,
                d_y,
                f_y,
                k_p,
            } => match phase {
                Phase::Approach if d <= d_y => k * spow(d, 1.5),
                Phase::Approach => f_y + k_p * (d - d_y),
                // An impact that never yielded unloads along its loading curve.
                Phase::Restitution if turn.d <= d_y => k * spow(d, 1.5),
                Phase::Restitution => {
                    let (k_u, d_f) = thornton_unloading(e_star, p_y, f_y, turn.d, turn.force);
                    k_u * spow(d - d_f, 1.5)
                }
            },
        }
    }

    /// The elastic part of the law at penetration `d` (m): its force (N) and the energy it stores (J), `k d^n`
    /// and `k |d|^(n+1) / (n+1)`; the rest of the force is viscous and dissipates, `(F - k d^n) v >= 0`.
    /// `None` for the bilinear loop, whose force has no potential (its work is counted whole).
    #[inline]
    pub fn elastic(&self, d: f64) -> Option<(f64, f64)> {
        let (k, n) = match *self {
            ForceLaw::Elastic { k, n }
            | ForceLaw::HuntCrossley { k, n, .. }
            | ForceLaw::Jankowski { k, n, .. } => (k, n),
            ForceLaw::LinearViscous { k, .. } => (k, 1.0),
            ForceLaw::Bilinear { .. } | ForceLaw::Thornton { .. } => return None,
        };
        let f = k * spow(d, n);
        Some((f, f * d / (n + 1.0)))
    }

    /// `(k, c)` (N/m, N s/m) when the law is `F = k d + c v` in `phase` (Hooke, Kelvin–Voigt, a linear
    /// Jankowski law); `None` for a nonlinear law.
    pub fn linear(&self, phase: Phase) -> Option<(f64, f64)> {
        match (*self, phase) {
            (ForceLaw::Elastic { k, n }, _) => (n == 1.0).then_some((k, 0.0)),
            (ForceLaw::LinearViscous { k, c, .. }, Phase::Approach) => Some((k, c)),
            (ForceLaw::LinearViscous { k, c_r, .. }, Phase::Restitution) => Some((k, c_r)),
            (ForceLaw::Jankowski { k, n, c0 }, Phase::Approach) => (n == 1.0).then_some((k, c0)),
            (ForceLaw::Jankowski { k, n, .. }, Phase::Restitution) => {
                (n == 1.0).then_some((k, 0.0))
            }
            (
                ForceLaw::HuntCrossley { .. }
                | ForceLaw::Bilinear { .. }
                | ForceLaw::Thornton { .. },
                _,
            ) => None,
        }
    }

    /// A function that is positive while the law pushes and whose first sign change in restitution marks
    /// the force reaching 0 before the penetration does (the release of a clamped law): the force itself,
    /// except for a Hunt–Crossley law, whose force `k d^n (1 + chi_r v / v_i)` changes sign twice when the
    /// factor and the penetration both do within one step (and so seems not to change at all): its factor
    /// alone, `1 + chi_r v / v_i`.
    #[inline]
    pub fn release_value(&self, d: f64, v: f64, phase: Phase, turn: &Turn) -> f64 {
        match (*self, phase) {
            (ForceLaw::HuntCrossley { chi_r, v_i, .. }, Phase::Restitution) => {
                1.0 + chi_r * v / v_i
            }
            _ => self.force(d, v, phase, turn),
        }
    }

    /// A function whose sign change marks a kink of the law (where the force is continuous but its slope
    /// is not), so that integration can restart there; `None` for smooth laws.
    pub fn kink(&self, d: f64, phase: Phase, turn: &Turn) -> Option<f64> {
        match *self {
            ForceLaw::Bilinear { k1, k2, d_y } => Some(match phase {
                Phase::Approach => d_y - d,
                Phase::Restitution => (turn.force - k1 * (turn.d - d)) - k2 * d,
            }),
            // Hertz meets the plastic line with the same slope, pi p_y R: no kink.
            ForceLaw::Elastic { .. }
            | ForceLaw::LinearViscous { .. }
            | ForceLaw::HuntCrossley { .. }
            | ForceLaw::Jankowski { .. }
            | ForceLaw::Thornton { .. } => None,
        }
    }

    /// The penetration (m) up to which the law, approaching again during restitution, reloads along its
    /// unloading line: the last turning point of a bilinear loop; `None` for laws whose force depends on
    /// the current penetration and rate only.
    pub fn reload_limit(&self, turn: &Turn) -> Option<f64> {
        match *self {
            ForceLaw::Bilinear { .. } | ForceLaw::Thornton { .. } => Some(turn.d),
            ForceLaw::Elastic { .. }
            | ForceLaw::LinearViscous { .. }
            | ForceLaw::HuntCrossley { .. }
            | ForceLaw::Jankowski { .. } => None,
        }
    }

    /// Whether the force is a smooth function of time at first touch. Jankowski's damping grows like
    /// `d^((n-1)/2)`, so the solution behaves like `t^((n+1)/2)` near touch, where an integrator's error
    /// estimate underestimates its error by a constant factor.
    pub fn smooth_at_touch(&self) -> bool {
        match *self {
            ForceLaw::Jankowski { n, .. } => n == 1.0,
            // d^n with n not a whole number: the motion goes like t^(n+2) from touch, whose higher derivatives
            // (those a fifth-order error estimate relies on) are unbounded there.
            ForceLaw::Elastic { n, .. } | ForceLaw::HuntCrossley { n, .. } => n.fract() == 0.0,
            ForceLaw::Thornton { .. } => false,
            ForceLaw::LinearViscous { .. } | ForceLaw::Bilinear { .. } => true,
        }
    }

    /// Scale of penetration for this law, m: the penetration at which the elastic part of the force has
    /// stored the kinetic energy `m v^2` (up to a factor of order one). Used to set tolerances.
    pub fn length_scale(&self, m: f64, v: f64) -> f64 {
        let (k, n) = self.scale_stiffness();
        (m * v * v / k).powf(1.0 / (n + 1.0))
    }

    /// The stiffness and exponent `(k, n)` that set [`Self::length_scale`]: the law's loading stiffness
    /// (`k1` of the bilinear law, the Hertz stiffness of Thornton's).
    pub fn scale_stiffness(&self) -> (f64, f64) {
        match *self {
            ForceLaw::Elastic { k, n }
            | ForceLaw::HuntCrossley { k, n, .. }
            | ForceLaw::Jankowski { k, n, .. } => (k, n),
            ForceLaw::LinearViscous { k, .. } => (k, 1.0),
            ForceLaw::Bilinear { k1, .. } => (k1, 1.0),
            ForceLaw::Thornton { k, .. } => (k, 1.5),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn signed_power_matches_powf() {
        for n in [1.0, 1.5, 2.0, 0.25] {
            for d in [-0.3f64, 0.0, 1e-9, 0.7] {
                let expect = if d < 0.0 { -(-d).powf(n) } else { d.powf(n) };
                assert!((spow(d, n) - expect).abs() <= 1e-15 * expect.abs().max(1e-300));
            }
        }
    }

    #[test]
    fn bilinear_loop_follows_opensees_impact_material() {
        // Load past yield, unload: the unloading branch has slope K1 and meets F = K2 d.
        let law = ForceLaw::Bilinear {
            k1: 10.0,
            k2: 2.0,
            d_y: 1.0,
        };
        let t0 = Turn::default();
        assert_eq!(law.force(0.5, 1.0, Phase::Approach, &t0), 5.0);
        assert_eq!(law.force(3.0, 1.0, Phase::Approach, &t0), 14.0);
        let turn = Turn {
            d: 3.0,
            force: 14.0,
        };
        assert_eq!(law.force(2.5, -1.0, Phase::Restitution, &turn), 9.0);
        // Unloading line 14 - 10 (3 - d) meets 2 d at d = 2, F = 4; below that F = 2 d.
        assert_eq!(law.force(1.0, -1.0, Phase::Restitution, &turn), 2.0);
    }
}
