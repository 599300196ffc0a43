//! Buildings that move in plan (docs/structures.md, "Buildings in plan"): each floor a rigid diaphragm with
//! translations `u_x`, `u_y` of its mass centre and a rotation `theta` about the vertical axis
//! (counterclockwise), its mass `m` and moment of inertia `J` (by default the uniform rectangle's,
//! `m (a^2 + b^2) / 12`), resisting through lateral load-resisting lines (frames or walls), each along x or
//! along y at a position in plan, with a stiffness and a law per storey.
//!
//! A point `r` from a floor's mass centre moves by `(u_x - r_y theta, u_y + r_x theta)`; a line along x at
//! ordinate `y` deforms in storey `s` by that x-displacement of floor `s` less that of floor `s - 1` (the
//! ground below floor 1). The building's degrees of freedom are its floors' `u_x` (floor 1 upwards), then
//! their `u_y`, then their `theta`: a plan's x-translations sit where a building in one line keeps its
//! floors.

use super::{eigen, Modes};
use crate::element::{Point, StoreyLaw};
use crate::error::check;
use crate::Error;

crate::named! {
    /// The direction a load-resisting line resists along.
    pub enum LineDirection: "direction" {
        /// Along x: the line lies at an ordinate `y`.
        X = "x",
        /// Along y: the line lies at an abscissa `x`.
        Y = "y",
    }
}

/// A lateral load-resisting line (a frame or a wall): its direction, where it lies in the plan, and each
/// storey's initial stiffness and law.
#[derive(Clone, Debug, PartialEq)]
pub struct Line {
    /// The direction it resists along.
    pub direction: LineDirection,
    /// Its position across that direction in the plan's frame, m: the ordinate `y` of a line along x, the
    /// abscissa `x` of one along y.
    pub at: f64,
    /// Initial stiffness of each storey, N/m, storey 1 upwards.
    pub stiffnesses: Vec<f64>,
    /// Law of each storey (linear, bilinear, Bouc–Wen) along the line.
    pub laws: Vec<StoreyLaw>,
}

/// What makes a building's plan besides its floor masses: size `(a, b)` (m), the corner `origin` in the site's
/// frame (m), mass centres and moments of inertia (default the rectangle's middle and `m (a^2 + b^2) / 12`),
/// the load-resisting lines, and the two modes its Rayleigh damping is fixed on (default: the two lowest
/// that move mostly along x, [`Plan::new`]).
#[derive(Clone, Debug, PartialEq)]
pub struct PlanSpec {
    /// Size along x and y, m.
    pub size: (f64, f64),
    /// The plan's corner `(x_min, y_min)` in the site's frame, m.
    pub origin: (f64, f64),
    /// Mass centres in the plan's frame, m, one per floor.
    pub centres: Option<Vec<(f64, f64)>>,
    /// Moments of inertia, kg m^2, one per floor.
    pub inertias: Option<Vec<f64>>,
    /// Lateral load-resisting lines.
    pub lines: Vec<Line>,
    /// Modes (from 1) of the Rayleigh damping.
    pub damping_modes: Option<(usize, usize)>,
}

/// The plan of a building: a rectangle placed in the site's frame, each floor's mass centre and moment of
/// inertia, and the load-resisting lines.
#[derive(Clone, Debug, PartialEq)]
pub struct Plan {
    size: (f64, f64),
    origin: (f64, f64),
    centres: Vec<(f64, f64)>,
    inertias: Vec<f64>,
    lines: Vec<Line>,
    masses: Vec<f64>,
    modes: Modes,
    rayleigh: (f64, f64),
    damping_modes: (usize, usize),
}

/// Which of a plan's degrees of freedom of a floor: the building's degrees of freedom are laid out x block,
/// y block, rotation block.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PlanDof {
    /// `u_x` of the mass centre, m.
    X,
    /// `u_y` of the mass centre, m.
    Y,
    /// The rotation, rad.
    Rotation,
}

impl Plan {
    /// The plan `spec` for floors of `masses` (kg): size `a` x `b` (m, along x and y), its corner `(x_min,
    /// y_min)` at `origin` (m) in the site's frame, the mass centres `centres` (m, in the plan's frame;
    /// default its middle), moments of inertia `inertias` (kg m^2; default `m (a^2 + b^2) / 12`), the lines,
    /// and Rayleigh damping `damping_ratio` on modes `damping_modes` (from 1) of the building's own modes in
    /// plan; by default the two lowest modes that move mostly along x (those a building in one line fixes it
    /// on; the lowest one alone if only one does). Errors name the key: `plan.size`, `line.2.at`, ...
    pub fn new(masses: &[f64], spec: PlanSpec, damping_ratio: f64) -> Result<Self, Error> {
        let PlanSpec {
            size,
            origin,
            centres,
            inertias,
            lines,
            damping_modes,
        } = spec;
        let n = masses.len();
        let (a, b) = size;
        for side in [a, b] {
            check(
                "plan.size",
                side,
                side > 0.0 && side.is_finite(),
                "a plan a x b with finite a, b > 0 (m)",
            )?;
        }
        check(
            "plan.position",
            origin.0,
            origin.0.is_finite(),
            "finite (m)",
        )?;
        check(
            "plan.position",
            origin.1,
            origin.1.is_finite(),
            "finite (m)",
        )?;
        let centres = centres.unwrap_or_else(|| vec![(a / 2.0, b / 2.0); n]);
        if centres.len() != n {
            return Err(Error::Length {
                name: "plan.mass_centres",
                len: centres.len(),
                expected: n,
            });
        }
        for &(x, y) in &centres {
            check(
                "plan.mass_centres",
                x,
                (0.0..=a).contains(&x),
                "inside the plan: 0 <= x <= a (m)",
            )?;
            check(
                "plan.mass_centres",
                y,
                (0.0..=b).contains(&y),
                "inside the plan: 0 <= y <= b (m)",
            )?;
        }
        let inertias =
            inertias.unwrap_or_else(|| masses.iter().map(|m| m * (a * a + b * b) / 12.0).collect());
        if inertias.len() != n {
            return Err(Error::Length {
                name: "plan.inertias",
                len: inertias.len(),
                expected: n,
            });
        }
        for &j in &inertias {
            check(
                "plan.inertias",
                j,
                j > 0.0,
                "moments of inertia > 0 (kg m^2)",
            )?;
        }
        check_lines(&lines, n, size)?;
        let mut plan = Self {
            size,
            origin,
            centres,
            inertias,
            lines,
            masses: masses.to_vec(),
            modes: Modes {
                omega: Vec::new(),
                shapes: Vec::new(),
            },
            rayleigh: (0.0, 0.0),
            damping_modes: (1, 1),
        };
        plan.modes = plan.solve_modes()?;
        plan.damping_modes = damping_modes.unwrap_or_else(|| plan.x_modes());
        let (i, j) = plan.damping_modes;
        let m = plan.modes.omega.len();
        for (k, name) in [(i, "first"), (j, "second")] {
            if k == 0 || k > m {
                return Err(Error::Choice {
                    name: "plan.damping_modes",
                    value: format!("{k} ({name})"),
                    allowed: format!("modes from 1 to {m} (the building's modes in plan)"),
                });
            }
        }
        let (w1, w2) = (plan.modes.omega[i - 1], plan.modes.omega[j - 1]);
        plan.rayleigh = if w1 == w2 {
            // One mode: mass- and stiffness-proportional halves give zeta there.
            (damping_ratio * w1, damping_ratio / w1)
        } else {
            let s = w1 + w2;
            (2.0 * damping_ratio * w1 * w2 / s, 2.0 * damping_ratio / s)
        };
        Ok(plan)
    }

    /// Size `(a, b)` along x and y, m.
    pub fn size(&self) -> (f64, f64) {
        self.size
    }
    /// The plan's corner `(x_min, y_min)` in the site's frame, m.
    pub fn origin(&self) -> (f64, f64) {
        self.origin
    }
    /// Each floor's mass centre in the plan's frame, m.
    pub fn centres(&self) -> &[(f64, f64)] {
        &self.centres
    }
    /// Each floor's moment of inertia about its mass centre, kg m^2.
    pub fn inertias(&self) -> &[f64] {
        &self.inertias
    }
    /// The load-resisting lines.
    pub fn lines(&self) -> &[Line] {
        &self.lines
    }
    /// The modes in plan: circular frequencies (rad/s) and mass-normalised shapes over the `3 n` degrees of
    /// freedom (x block, y block, rotation block).
    pub fn modes(&self) -> &Modes {
        &self.modes
    }
    /// Rayleigh coefficients `(a0` 1/s, `a1` s) of `C = a0 M + a1 K_0`.
    pub fn rayleigh(&self) -> (f64, f64) {
        self.rayleigh
    }
    /// The two modes (from 1) the Rayleigh damping is fixed on.
    pub fn damping_modes(&self) -> (usize, usize) {
        self.damping_modes
    }

    /// Floors.
    pub fn floors(&self) -> usize {
        self.masses.len()
    }

    /// The index, within the building's degrees of freedom, of `dof` of floor `floor` (from 1).
    pub fn dof(&self, floor: usize, dof: PlanDof) -> usize {
        let n = self.floors();
        let k = floor - 1;
        match dof {
            PlanDof::X => k,
            PlanDof::Y => n + k,
            PlanDof::Rotation => 2 * n + k,
        }
    }

    /// The site-frame position of floor `floor`'s mass centre, m.
    pub fn centre_in_site(&self, floor: usize) -> (f64, f64) {
        let (cx, cy) = self.centres[floor - 1];
        (self.origin.0 + cx, self.origin.1 + cy)
    }

    /// The corners of the plan in the site's frame, m, counterclockwise from `(x_min, y_min)`.
    pub fn corners(&self) -> [(f64, f64); 4] {
        let ((x0, y0), (a, b)) = (self.origin, self.size);
        [(x0, y0), (x0 + a, y0), (x0 + a, y0 + b), (x0, y0 + b)]
    }

    /// The displacement of the point `p` (m, site frame) of floor `floor` along the unit direction `n`, as
    /// terms over the building's degrees of freedom shifted by `offset`: `n_x u_x + n_y u_y + (r x n) theta`
    /// with `r` from the floor's mass centre.
    pub fn point(&self, floor: usize, offset: usize, p: (f64, f64), n: (f64, f64)) -> Point {
        let c = self.centre_in_site(floor);
        let r = (p.0 - c.0, p.1 - c.1);
        let mut terms = Vec::with_capacity(3);
        if n.0 != 0.0 {
            terms.push((offset + self.dof(floor, PlanDof::X), n.0));
        }
        if n.1 != 0.0 {
            terms.push((offset + self.dof(floor, PlanDof::Y), n.1));
        }
        let arm = r.0 * n.1 - r.1 * n.0;
        terms.push((offset + self.dof(floor, PlanDof::Rotation), arm));
        Point::new(&terms)
    }

    /// The mass of floor `floor` that a force along `n` at `p` (site frame) meets: `1 / (n^2 / m + (r x n)^2 /
    /// J)`, kg (the effective mass of an impact there on a floor free to translate and turn).
    pub fn point_mass(&self, floor: usize, p: (f64, f64), n: (f64, f64)) -> f64 {
        let c = self.centre_in_site(floor);
        let r = (p.0 - c.0, p.1 - c.1);
        let arm = r.0 * n.1 - r.1 * n.0;
        let (m, j) = (self.masses[floor - 1], self.inertias[floor - 1]);
        if arm == 0.0 {
            // On the line of action through the mass centre: the floor's mass, to the last digit (a
            // symmetric plan then calibrates its contacts exactly as a building in one line).
            return m / (n.0 * n.0 + n.1 * n.1);
        }
        1.0 / ((n.0 * n.0 + n.1 * n.1) / m + arm * arm / j)
    }

    /// The deformation of storey `storey` (from 1) of line `line`: the displacement of the line's point on
    /// floor `storey` less that on the floor below (the ground under floor 1), as two ends over the
    /// building's degrees of freedom shifted by `offset`.
    pub fn line_ends(
        &self,
        line: usize,
        storey: usize,
        offset: usize,
    ) -> (crate::element::End, crate::element::End) {
        use crate::element::End;
        let l = &self.lines[line];
        let end = |floor: usize| {
            let (cx, cy) = self.centres[floor - 1];
            let (dof, arm) = match l.direction {
                LineDirection::X => (PlanDof::X, -(l.at - cy)),
                LineDirection::Y => (PlanDof::Y, l.at - cx),
            };
            End::Point(Point::new(&[
                (offset + self.dof(floor, dof), 1.0),
                (offset + self.dof(floor, PlanDof::Rotation), arm),
            ]))
        };
        let below = if storey == 1 {
            End::Ground
        } else {
            end(storey - 1)
        };
        (end(storey), below)
    }

    /// The masses of the building's degrees of freedom: each floor's mass (x, y) and moment of inertia.
    pub fn dof_masses(&self) -> Vec<f64> {
        let mut m = self.masses.clone();
        m.extend_from_slice(&self.masses);
        m.extend_from_slice(&self.inertias);
        m
    }

    /// The initial stiffness matrix over the `3 n` degrees of freedom, row-major.
    pub fn stiffness_matrix(&self) -> Vec<f64> {
        let d = 3 * self.floors();
        let mut k = vec![0.0; d * d];
        for (li, line) in self.lines.iter().enumerate() {
            for (s, &ks) in line.stiffnesses.iter().enumerate() {
                let (a, b) = self.line_ends(li, s + 1, 0);
                let mut g: Vec<(usize, f64)> = a.terms().terms().to_vec();
                g.extend(b.terms().terms().iter().map(|&(i, c)| (i, -c)));
                for &(i, ci) in &g {
                    for &(j, cj) in &g {
                        k[i * d + j] += ks * ci * cj;
                    }
                }
            }
        }
        k
    }

    /// The modes of `K phi = w^2 M phi` over the `3 n` degrees of freedom, lowest first; refused if a mode has
    /// no stiffness (lines that cannot hold the floors in plan). A plan whose motion along x is uncoupled
    /// from its rotation (lines along x balanced about every mass centre) has the modes along x of the
    /// building in one line with its lines' stiffnesses summed, computed the same way to the last digit; the
    /// rest by Jacobi on `M^-1/2 K M^-1/2`.
    fn solve_modes(&self) -> Result<Modes, Error> {
        let n = self.floors();
        let d = 3 * n;
        let m = self.dof_masses();
        let k = self.stiffness_matrix();
        let scale = (0..d).map(|i| k[i * d + i] / m[i]).fold(0.0f64, f64::max);
        let uncoupled = (0..n).all(|i| (2 * n..d).all(|j| k[i * d + j] == 0.0));
        let mut modes: Vec<(f64, Vec<f64>)> = Vec::with_capacity(d);
        if uncoupled {
            let sums: Vec<f64> = (0..n)
                .map(|s| {
                    self.lines
                        .iter()
                        .filter(|l| l.direction == LineDirection::X)
                        .map(|l| l.stiffnesses[s])
                        .sum()
                })
                .collect();
            let (x, _) = super::solve_modes(&self.masses, &sums);
            for (w, phi) in x.omega.into_iter().zip(x.shapes) {
                let mut full = vec![0.0; d];
                full[..n].copy_from_slice(&phi);
                modes.push((w, full));
            }
            modes.extend(block_modes(&k, &m, &(n..d).collect::<Vec<_>>()));
        } else {
            modes.extend(block_modes(&k, &m, &(0..d).collect::<Vec<_>>()));
        }
        // A stable sort: modes of equal frequency keep x before the rest.
        modes.sort_by(|a, b| a.0.total_cmp(&b.0));
        if modes[0].0 * modes[0].0 <= 1e-10 * scale {
            return Err(Error::Choice {
                name: "line",
                value: "these lines".into(),
                allowed: "lines along x and along y, not all through one point, that hold every floor in x, y and rotation (the stiffness in plan is singular)".into(),
            });
        }
        let (omega, shapes) = modes.into_iter().unzip();
        Ok(Modes { omega, shapes })
    }

    /// The two modes (from 1) that Rayleigh damping is fixed on by default: the two lowest whose largest
    /// effective mass ratio is along x (the modes of the building in one line, for a plan whose x motion
    /// stands apart), the lowest one twice if only one is; the two lowest modes if none is.
    fn x_modes(&self) -> (usize, usize) {
        let along_x: Vec<usize> = self
            .participation()
            .iter()
            .enumerate()
            .filter(|(_, p)| p.0 > PARTICIPATES && p.0 >= p.1 && p.0 >= p.2)
            .map(|(k, _)| k + 1)
            .take(2)
            .collect();
        match along_x[..] {
            [a, b] => (a, b),
            [a] => (a, a),
            _ => (1, 2.min(self.modes.omega.len())),
        }
    }

    /// The circular frequency (rad/s) of the lowest mode that moves mostly along x (the lowest mode if none
    /// does): the fundamental of the building along x.
    pub fn fundamental_x(&self) -> f64 {
        self.modes.omega[self.x_modes().0 - 1]
    }

    /// The floor masses, kg.
    pub fn masses(&self) -> &[f64] {
        &self.masses
    }

    /// Each mode's participation factors along x and along y, `sum m_i phi_i` over the floors' translations
    /// (kg, the shapes being mass-normalised).
    pub fn gammas(&self) -> Vec<(f64, f64)> {
        let n = self.floors();
        self.modes
            .shapes
            .iter()
            .map(|phi| {
                let gx: f64 = (0..n).map(|i| phi[i] * self.masses[i]).sum();
                let gy: f64 = (0..n).map(|i| phi[n + i] * self.masses[i]).sum();
                (gx, gy)
            })
            .collect()
    }

    /// The circular frequencies (rad/s) of the lowest modes that move the floors along x, along y, and in
    /// rotation (the lowest mode if none does, which a plan's modes cannot all avoid).
    pub fn first_modes(&self) -> (f64, f64, f64) {
        let part = self.participation();
        let w = &self.modes.omega;
        let first = |pick: &dyn Fn(&(f64, f64, f64)) -> f64| {
            part.iter()
                .position(|p| pick(p) > PARTICIPATES)
                .map_or(w[0], |k| w[k])
        };
        (first(&|p| p.0), first(&|p| p.1), first(&|p| p.2))
    }

    /// The highest circular frequency (rad/s) of the modes that a ground shaking along x (`x`) and along y
    /// (`y`) excites (of all modes if neither excites any).
    pub fn excited_w_max(&self, x: bool, y: bool) -> f64 {
        let w = &self.modes.omega;
        self.participation()
            .iter()
            .zip(w)
            .filter(|(p, _)| (x && p.0 > PARTICIPATES) || (y && p.1 > PARTICIPATES))
            .map(|(_, w)| *w)
            .reduce(f64::max)
            .unwrap_or_else(|| w.iter().copied().fold(0.0, f64::max))
    }

    /// Each mode's effective mass ratios along x, along y (dimensionless, of the building's mass) and in
    /// rotation (of its polar inertia about the floors' mass centres).
    pub fn participation(&self) -> Vec<(f64, f64, f64)> {
        let n = self.floors();
        let total: f64 = self.masses.iter().sum();
        let polar: f64 = self.inertias.iter().sum();
        self.modes
            .shapes
            .iter()
            .map(|phi| {
                let gx: f64 = (0..n).map(|i| self.masses[i] * phi[i]).sum();
                let gy: f64 = (0..n).map(|i| self.masses[i] * phi[n + i]).sum();
                let gt: f64 = (0..n).map(|i| self.inertias[i] * phi[2 * n + i]).sum();
                (gx * gx / total, gy * gy / total, gt * gt / polar)
            })
            .collect()
    }
}

/// The modes of `K phi = w^2 M phi` restricted to the degrees of freedom `idx` (of the full `K`, row-major,
/// and masses `m`): circular frequencies (rad/s, unsorted) and mass-normalised shapes over all degrees of
/// freedom (zero outside `idx`), each with its component of largest magnitude positive.
fn block_modes(k: &[f64], m: &[f64], idx: &[usize]) -> Vec<(f64, Vec<f64>)> {
    let d = m.len();
    let b = idx.len();
    let s: Vec<f64> = idx.iter().map(|&i| 1.0 / m[i].sqrt()).collect();
    let mut a: Vec<f64> = (0..b * b)
        .map(|ij| {
            let (p, q) = (ij / b, ij % b);
            k[idx[p] * d + idx[q]] * s[p] * s[q]
        })
        .collect();
    let e = eigen::symmetric(&mut a, b);
    (0..b)
        .map(|r| {
            let mut phi = vec![0.0; d];
            for (p, &i) in idx.iter().enumerate() {
                phi[i] = e.vectors[p * b + r] * s[p];
            }
            let big = phi
                .iter()
                .fold(0.0f64, |acc, x| if x.abs() > acc.abs() { *x } else { acc });
            if big < 0.0 {
                phi.iter_mut().for_each(|x| *x = -*x);
            }
            (e.values[r].max(0.0).sqrt(), phi)
        })
        .collect()
}

/// An effective mass ratio above which a mode takes part in a direction (a symmetric plan's modes have
/// exactly 0 in the directions they do not move along).
const PARTICIPATES: f64 = 1e-9;

/// The lines checked: at least one, each inside the plan, one stiffness and law per storey, stiffnesses > 0.
fn check_lines(lines: &[Line], storeys: usize, (a, b): (f64, f64)) -> Result<(), Error> {
    if lines.len() > crate::limits::MAX_LINES {
        return Err(Error::Choice {
            name: "line",
            value: format!("{} lines", lines.len()),
            allowed: "at most 100 load-resisting lines per building (limits::MAX_LINES)".into(),
        });
    }
    if lines.is_empty() {
        return Err(Error::Choice {
            name: "line",
            value: "none".into(),
            allowed: "lateral load-resisting lines ([[building.line]]) along x and along y".into(),
        });
    }
    for (i, l) in lines.iter().enumerate() {
        let span = match l.direction {
            LineDirection::X => b,
            LineDirection::Y => a,
        };
        if !(l.at.is_finite() && (0.0..=span).contains(&l.at)) {
            return Err(Error::Choice {
                name: "line.at",
                value: format!("line {}: {}", i + 1, crate::words::number(l.at)),
                allowed: format!(
                    "inside the plan: 0 <= at <= {} m (the plan's {} for a line along {})",
                    crate::words::number(span),
                    if l.direction == LineDirection::X {
                        "depth b"
                    } else {
                        "width a"
                    },
                    l.direction.name()
                ),
            });
        }
        for (name, len) in [
            ("line.stiffnesses", l.stiffnesses.len()),
            ("line.laws", l.laws.len()),
        ] {
            if len != storeys {
                return Err(Error::Length {
                    name,
                    len,
                    expected: storeys,
                });
            }
        }
        for &k in &l.stiffnesses {
            check(
                "line.stiffnesses",
                k,
                k > 0.0,
                "storey stiffnesses > 0 (N/m)",
            )?;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A one-storey floor (m, J, mass centre (xc, yc)) on four lines: along x at y = 0 and y = b, along y at
    /// x = 0 and x = a. Its stiffness about the mass centre, written out by hand:
    /// `K = [[kx, 0, -sum k_i (y_i - yc)], [0, ky, sum k_j (x_j - xc)], [.., .., sum k_i (y_i - yc)^2 + sum
    /// k_j (x_j - xc)^2]]`; `det(K - lambda M) = 0` is a cubic in `lambda`, solved by Vieta's trigonometric
    /// form (three real roots). The Jacobi modes equal them to 1e-10.
    #[test]
    fn a_one_storey_eccentric_floor_has_the_closed_form_modes() {
        let (m, a, b) = (4.0e5, 20.0, 12.0);
        let j = m * (a * a + b * b) / 12.0;
        let (xc, yc) = (8.0, 5.0);
        let lines = vec![
            (LineDirection::X, 0.0, 3.0e8),
            (LineDirection::X, b, 1.0e8),
            (LineDirection::Y, 0.0, 2.0e8),
            (LineDirection::Y, a, 2.5e8),
        ];
        let spec = PlanSpec {
            size: (a, b),
            origin: (0.0, 0.0),
            centres: Some(vec![(xc, yc)]),
            inertias: None,
            lines: lines
                .iter()
                .map(|&(direction, at, k)| Line {
                    direction,
                    at,
                    stiffnesses: vec![k],
                    laws: vec![StoreyLaw::Linear],
                })
                .collect(),
            damping_modes: None,
        };
        let plan = Plan::new(&[m], spec, 0.05).unwrap();
        let (mut kx, mut ky, mut kxt, mut kyt, mut ktt) = (0.0, 0.0, 0.0, 0.0, 0.0);
        for &(d, at, k) in &lines {
            match d {
                LineDirection::X => {
                    kx += k;
                    kxt -= k * (at - yc);
                    ktt += k * (at - yc).powi(2);
                }
                LineDirection::Y => {
                    ky += k;
                    kyt += k * (at - xc);
                    ktt += k * (at - xc).powi(2);
                }
            }
        }
        // Symmetric A = M^-1/2 K M^-1/2 and its characteristic cubic l^3 + p2 l^2 + p1 l + p0 = 0.
        let (sm, sj) = (1.0 / m.sqrt(), 1.0 / j.sqrt());
        let a11 = kx * sm * sm;
        let a22 = ky * sm * sm;
        let a33 = ktt * sj * sj;
        let a13 = kxt * sm * sj;
        let a23 = kyt * sm * sj;
        let p2 = -(a11 + a22 + a33);
        let p1 = a11 * a22 + a11 * a33 + a22 * a33 - a13 * a13 - a23 * a23;
        let p0 = -(a11 * a22 * a33 - a11 * a23 * a23 - a22 * a13 * a13);
        // Depressed cubic t^3 + p t + q with l = t - p2/3; three real roots.
        let p = p1 - p2 * p2 / 3.0;
        let q = 2.0 * p2.powi(3) / 27.0 - p2 * p1 / 3.0 + p0;
        let r = 2.0 * (-p / 3.0).sqrt();
        let phi = (3.0 * q / (p * r)).acos() / 3.0;
        let mut roots: Vec<f64> = (0..3)
            .map(|k| r * (phi - 2.0 * std::f64::consts::PI * k as f64 / 3.0).cos() - p2 / 3.0)
            .collect();
        roots.sort_by(f64::total_cmp);
        for (w, l) in plan.modes().omega.iter().zip(&roots) {
            assert!((w * w / l - 1.0).abs() < 1e-10, "{} vs {l}", w * w);
        }
        // Each mode: K phi = w^2 M phi, and the effective mass ratios of x, y sum to 1.
        let part = plan.participation();
        let (sx, sy): (f64, f64) = part.iter().fold((0.0, 0.0), |s, p| (s.0 + p.0, s.1 + p.1));
        assert!((sx - 1.0).abs() < 1e-12 && (sy - 1.0).abs() < 1e-12);
    }

    #[test]
    fn bad_plans_name_their_key() {
        let line = |direction, at| Line {
            direction,
            at,
            stiffnesses: vec![1e8],
            laws: vec![StoreyLaw::Linear],
        };
        let make = |lines: Vec<Line>| {
            let spec = PlanSpec {
                size: (10.0, 8.0),
                origin: (0.0, 0.0),
                centres: None,
                inertias: None,
                lines,
                damping_modes: None,
            };
            Plan::new(&[1e5], spec, 0.05)
        };
        let e = make(vec![line(LineDirection::X, 9.0)])
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with("line.at = line 1: 9 is not allowed: inside the plan"),
            "{e}"
        );
        // All lines along x: nothing holds the floor along y.
        let e = make(vec![
            line(LineDirection::X, 0.0),
            line(LineDirection::X, 8.0),
        ])
        .unwrap_err()
        .to_string();
        assert!(e.contains("singular"), "{e}");
        // Infinite stiffnesses, and more lines than a plan may have.
        let mut stiff = line(LineDirection::X, 0.0);
        stiff.stiffnesses = vec![f64::INFINITY];
        let e = make(vec![stiff]).unwrap_err().to_string();
        assert!(
            e.starts_with("line.stiffnesses = inf is not allowed"),
            "{e}"
        );
        let many = (0..=crate::limits::MAX_LINES)
            .map(|k| line(LineDirection::X, k as f64 * 0.05))
            .collect();
        let e = make(many).unwrap_err().to_string();
        assert!(e.starts_with("line = 101 lines is not allowed"), "{e}");
        // Lines through one point cannot hold the rotation.
        let e = make(vec![
            line(LineDirection::X, 4.0),
            line(LineDirection::Y, 5.0),
        ])
        .unwrap_err()
        .to_string();
        assert!(e.contains("singular"), "{e}");
    }
}
