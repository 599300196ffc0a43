//! Lumped-mass shear buildings: assembly, natural modes and Rayleigh damping.
//!
//! A building of `n` storeys has one horizontal degree of freedom per floor (floor 1 is the lowest, the
//! ground does not move relative to itself). Storey `j` joins floor `j - 1` (the ground for `j = 1`) and floor
//! `j` with a spring of stiffness `k_j` (N/m), so the stiffness matrix is tridiagonal:
//! `(K u)_i = k_i (u_i - u_{i-1}) - k_{i+1} (u_{i+1} - u_i)` (Chopra, *Dynamics of Structures*, section 9.2).
//! Damping is classical: `C = a0 M + a1 K` with the ratio `zeta` on modes 1 and 2,
//! `a0 = 2 zeta w1 w2 / (w1 + w2)`, `a1 = 2 zeta / (w1 + w2)` (Chopra, eq 11.4.9); a single storey gets
//! `c = 2 zeta sqrt(k m)`, which is the same formula with `w2 = w1`.

pub mod column;
mod eigen;
mod form;
pub mod foundation;
pub mod isolation;
pub mod matrix;
pub mod plan;

pub use column::StruckColumn;
pub use form::Form;
pub use foundation::{Foundation, HalfSpace, Shape, Soil};
pub use isolation::{Isolator, IsolatorKind, IsolatorModel};
pub use matrix::{Matrix, MatrixStructure};
pub use plan::{Line, LineDirection, Plan, PlanDof, PlanSpec};

use crate::element::StoreyLaw;
use crate::error::check;
use crate::Error;

/// A lumped-mass shear building.
///
/// Built with named values by [`ShearBuilding::builder`] (or positionally by [`ShearBuilding::new`]):
///
/// ```
/// use pounding::structure::ShearBuilding;
/// let b = ShearBuilding::builder()
///     .masses([4.0e5, 4.0e5, 3.5e5]) // kg, floor 1 upwards
///     .stiffnesses([6.0e8, 5.0e8, 4.0e8]) // N/m, storey 1 upwards
///     .heights([3.0; 3]) // m
///     .damping_ratio(0.05) // on modes 1 and 2
///     .build()?;
/// let t1 = b.modes().periods()[0]; // s
/// assert!(t1 > 0.2 && t1 < 0.5, "{t1}");
/// assert_eq!(b.elevations(), [3.0, 6.0, 9.0]); // m
/// // A missing list is named in the error.
/// let e = ShearBuilding::builder().masses([4.0e5]).heights([3.0]).build().unwrap_err();
/// assert_eq!(e.to_string(), "stiffnesses has 0 values, but there is 1 floor: give one per floor");
/// # Ok::<(), pounding::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct ShearBuilding {
    masses: Vec<f64>,
    stiffnesses: Vec<f64>,
    heights: Vec<f64>,
    damping_ratio: f64,
    /// Rayleigh coefficients `(a0, a1)`, fixed by the modes at construction.
    rayleigh: (f64, f64),
    /// The law of each storey (linear unless set by [`ShearBuilding::with_storey_laws`]).
    storey_laws: Vec<StoreyLaw>,
    /// The isolator under floor 1 (the base slab), if the building is isolated at its base.
    isolator: Option<Isolator>,
    /// Natural modes, computed once at construction.
    modes: Modes,
    /// The plan of a building whose floors move in plan ([`ShearBuilding::in_plan`]).
    plan: Option<Box<Plan>>,
    /// The foundation on the soil, and the modes on it ([`ShearBuilding::with_foundation`]).
    foundation: Option<Box<(Foundation, Modes)>>,
    /// The matrices of a structure given by them ([`ShearBuilding::from_matrices`]).
    matrix: Option<Box<MatrixStructure>>,
}

/// Natural modes of a [`ShearBuilding`], lowest first.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Modes {
    /// Circular frequencies, rad/s.
    pub omega: Vec<f64>,
    /// Mass-normalised mode shapes (`phi^T M phi = 1`, in 1/sqrt(kg)); `shapes[r][i]` is floor `i + 1` of
    /// mode `r + 1`, with the top floor's component positive.
    pub shapes: Vec<Vec<f64>>,
}

impl Modes {
    /// Natural periods, s.
    pub fn periods(&self) -> Vec<f64> {
        self.omega
            .iter()
            .map(|w| 2.0 * std::f64::consts::PI / w)
            .collect()
    }

    /// Mode shapes scaled so that their largest component is 1 in magnitude, the top floor's component
    /// positive (dimensionless). For the fundamental mode of a regular building, whose roof moves most, that is
    /// the roof = 1 convention; unlike it, a mode in which the roof barely moves (a stiff, light floor low in
    /// the building) stays finite.
    pub fn shapes_normalised(&self) -> Vec<Vec<f64>> {
        self.shapes
            .iter()
            .map(|s| {
                let big = s.iter().fold(0.0f64, |a, x| a.max(x.abs()));
                s.iter().map(|x| x / big).collect()
            })
            .collect()
    }

    /// Participation factor of each mode for a uniform base excitation, `Gamma = phi^T M 1` (sqrt(kg), with
    /// the mass-normalised shapes), and the effective modal mass `Gamma^2` (kg).
    pub fn participation(&self, masses: &[f64]) -> Vec<(f64, f64)> {
        self.shapes
            .iter()
            .map(|s| {
                let g: f64 = s.iter().zip(masses).map(|(p, m)| p * m).sum();
                (g, g * g)
            })
            .collect()
    }
}

/// Named values of a [`ShearBuilding`], from [`ShearBuilding::builder`]: the floor masses, storey
/// stiffnesses and storey heights (required, one per storey) and the damping ratio (0.05 unless set).
/// [`ShearBuildingBuilder::build`] checks them as [`ShearBuilding::new`] does; a list left out is an
/// [`Error::Length`] naming it.
#[derive(Clone, Debug, PartialEq)]
#[must_use = "a builder does nothing until `build` is called"]
pub struct ShearBuildingBuilder {
    masses: Vec<f64>,
    stiffnesses: Vec<f64>,
    heights: Vec<f64>,
    damping_ratio: f64,
    /// Base slab mass (kg) and its isolator, for a base-isolated building.
    base: Option<(f64, Isolator)>,
}

/// Default damping ratio of a building's modes 1 and 2 (Rayleigh), dimensionless: 5 %, the ratio design
/// spectra assume.
pub const DEFAULT_DAMPING_RATIO: f64 = 0.05;

impl Default for ShearBuildingBuilder {
    fn default() -> Self {
        Self {
            masses: Vec::new(),
            stiffnesses: Vec::new(),
            heights: Vec::new(),
            damping_ratio: DEFAULT_DAMPING_RATIO,
            base: None,
        }
    }
}

impl ShearBuildingBuilder {
    /// Floor masses, kg (> 0), floor 1 (the lowest) upwards: one per storey.
    pub fn masses(mut self, masses: impl Into<Vec<f64>>) -> Self {
        self.masses = masses.into();
        self
    }
    /// Storey stiffnesses, N/m (> 0), storey 1 (ground to floor 1) upwards.
    pub fn stiffnesses(mut self, stiffnesses: impl Into<Vec<f64>>) -> Self {
        self.stiffnesses = stiffnesses.into();
        self
    }
    /// Storey heights, m (1e-3 to 1e4), storey 1 upwards.
    pub fn heights(mut self, heights: impl Into<Vec<f64>>) -> Self {
        self.heights = heights.into();
        self
    }
    /// Rayleigh damping ratio of modes 1 and 2, in `[0, 1)` (dimensionless; 0.05 unless set).
    pub fn damping_ratio(mut self, zeta: f64) -> Self {
        self.damping_ratio = zeta;
        self
    }
    /// Base isolation: a base slab of `base_mass` kg (floor 1) on `isolator` (storey 1). The masses,
    /// stiffnesses and heights given are then those of the superstructure above the slab (all three may be
    /// empty, for a deck on its bearings), as in [`ShearBuilding::isolated`].
    pub fn isolated_on(mut self, base_mass: f64, isolator: Isolator) -> Self {
        self.base = Some((base_mass, isolator));
        self
    }
    /// The building, checked: [`ShearBuilding::new`] with these values, or [`ShearBuilding::isolated`]
    /// after [`ShearBuildingBuilder::isolated_on`].
    pub fn build(self) -> Result<ShearBuilding, Error> {
        match self.base {
            None => ShearBuilding::new(
                self.masses,
                self.stiffnesses,
                self.heights,
                self.damping_ratio,
            ),
            Some((base_mass, isolator)) => ShearBuilding::isolated(
                base_mass,
                isolator,
                self.masses,
                self.stiffnesses,
                self.heights,
                self.damping_ratio,
            ),
        }
    }
}

/// One stiffness and one height per floor mass: an [`Error::Length`] naming the list that differs.
fn same_lengths(masses: &[f64], stiffnesses: &[f64], heights: &[f64]) -> Result<(), Error> {
    for (name, list) in [("stiffnesses", stiffnesses), ("heights", heights)] {
        if list.len() != masses.len() {
            return Err(Error::Length {
                name,
                len: list.len(),
                expected: masses.len(),
            });
        }
    }
    Ok(())
}

impl ShearBuilding {
    /// A builder with named values: `ShearBuilding::builder().masses(..).stiffnesses(..).heights(..)
    /// .damping_ratio(..).build()` (see [`ShearBuilding`]). Prefer it to [`ShearBuilding::new`], whose three
    /// lists of numbers are easy to pass in the wrong order.
    pub fn builder() -> ShearBuildingBuilder {
        ShearBuildingBuilder::default()
    }

    /// A building with floor masses (kg, floor 1 upwards), storey stiffnesses (N/m, storey 1 upwards), storey
    /// heights (m) and a damping ratio `zeta` in `[0, 1)` on modes 1 and 2. All three lists must have the same
    /// length, at least 1, with positive finite values. This is the positional, low-level form; the same
    /// with named values is [`ShearBuilding::builder`].
    pub fn new(
        masses: Vec<f64>,
        stiffnesses: Vec<f64>,
        heights: Vec<f64>,
        damping_ratio: f64,
    ) -> Result<Self, Error> {
        if masses.is_empty() || masses.len() > crate::limits::MAX_STOREYS {
            return Err(Error::Parameter {
                name: "masses",
                value: masses.len() as f64,
                allowed: "1 to 200 floor masses (kg), one per storey (limits::MAX_STOREYS)",
            });
        }
        same_lengths(&masses, &stiffnesses, &heights)?;
        for &m in &masses {
            check("mass", m, m > 0.0, "floor masses > 0 (kg)")?;
        }
        for &k in &stiffnesses {
            check("stiffness", k, k > 0.0, "storey stiffnesses > 0 (N/m)")?;
        }
        for &h in &heights {
            check(
                "height",
                h,
                (1e-3..=1e4).contains(&h),
                "storey heights from 1e-3 to 1e4 m",
            )?;
        }
        check(
            "damping_ratio",
            damping_ratio,
            (0.0..1.0).contains(&damping_ratio),
            "0 <= damping_ratio < 1",
        )?;
        let (modes, _sweeps) = solve_modes(&masses, &stiffnesses);
        let n_storeys = masses.len();
        let w = &modes.omega;
        let rayleigh = rayleigh_of(w, damping_ratio);
        // Masses and stiffnesses whose ratios leave the range of f64 give modes that are not numbers.
        let finite = |x: &f64| x.is_finite();
        if !(w.iter().all(|w| w.is_finite() && *w > 0.0)
            && modes.shapes.iter().flatten().all(finite)
            && modes.shapes_normalised().iter().flatten().all(finite)
            && finite(&rayleigh.0)
            && finite(&rayleigh.1))
        {
            return Err(Error::Parameter {
                name: "stiffnesses",
                value: stiffnesses.iter().fold(f64::INFINITY, |a, k| a.min(*k)),
                allowed: "stiffnesses and masses whose natural frequencies and mode shapes are finite numbers (k / m from about 1e-250 to 1e250 1/s^2)",
            });
        }
        Ok(Self {
            masses,
            stiffnesses,
            heights,
            damping_ratio,
            rayleigh,
            storey_laws: vec![StoreyLaw::Linear; n_storeys],
            isolator: None,
            modes,
            plan: None,
            foundation: None,
            matrix: None,
        })
    }

    /// A building whose floors move in plan ([`plan`]): floor masses (kg), storey heights (m), the damping
    /// ratio of its Rayleigh damping, and its plan's lines and geometry (`spec`). Its stiffnesses, storey laws
    /// and modes in one line are those of the lines along x summed per storey (a view for what treats the
    /// building along x); the motion uses the plan ([`ShearBuilding::plan`]).
    pub fn in_plan(
        masses: Vec<f64>,
        heights: Vec<f64>,
        damping_ratio: f64,
        spec: PlanSpec,
    ) -> Result<Self, Error> {
        let plan = Plan::new(&masses, spec, damping_ratio)?;
        let n = masses.len();
        let along_x: Vec<f64> = (0..n)
            .map(|s| {
                plan.lines()
                    .iter()
                    .filter(|l| l.direction == LineDirection::X)
                    .map(|l| l.stiffnesses[s])
                    .sum()
            })
            .collect();
        // A plan with no line along x is refused by its modes (singular); the sums are then > 0.
        let mut b = Self::new(masses, along_x, heights, damping_ratio)?;
        b.plan = Some(Box::new(plan));
        Ok(b)
    }

    /// The plan of a building whose floors move in plan.
    pub fn plan(&self) -> Option<&Plan> {
        self.plan.as_deref()
    }

    /// Degrees of freedom: one per floor, three (x, y, rotation) for a building in plan; two more (the
    /// foundation's sway and rocking) on a foundation.
    pub fn dofs(&self) -> usize {
        if self.plan.is_some() {
            3 * self.storeys()
        } else {
            self.storeys() + 2 * usize::from(self.foundation.is_some())
        }
    }

    /// The same building on `foundation` (soil–structure interaction, [`foundation`]): its floors then move
    /// with the foundation's sway and rocking (a floor at elevation `z` by `z theta`) besides their storeys'
    /// drifts; Rayleigh damping stays that of the fixed-base building, its mass-proportional part acting
    /// relative to the rigid motion of the base (as over an isolator), and the soil's dashpots damp the
    /// foundation. Refused for a building in plan or on an isolator, and for a foundation without mass or
    /// moment of inertia (a run needs both).
    pub fn with_foundation(mut self, foundation: Foundation) -> Result<Self, Error> {
        let refuse = |why: &str| Error::Choice {
            name: "foundation",
            value: "[building.foundation]".into(),
            allowed: why.into(),
        };
        if self.plan.is_some() {
            return Err(refuse(
                "a building in one line: a foundation under a building in plan is not modelled yet",
            ));
        }
        if self.isolator.is_some() {
            return Err(refuse("a building without an isolator: an isolated building on soil springs is not modelled yet"));
        }
        if self.matrix.is_some() {
            return Err(refuse("a shear building: a structure given by its matrices on soil springs is not modelled yet"));
        }
        check(
            "foundation.mass",
            foundation.mass,
            foundation.mass > 0.0,
            "mass > 0 (kg) for a time history (a massless foundation has no equation of motion: give the mat's mass)",
        )?;
        check(
            "foundation.inertia",
            foundation.inertia,
            foundation.inertia > 0.0,
            "moment of inertia > 0 (kg m^2) for a time history",
        )?;
        let (omega, shapes) =
            foundation::flexible_modes(&self.masses, &self.stiffnesses, &self.heights, &foundation);
        self.foundation = Some(Box::new((foundation, Modes { omega, shapes })));
        Ok(self)
    }

    /// A structure given by its matrices (`structure`: lumped masses, stiffness, optional damping) with
    /// storey `heights` (m, the floors' elevations): its modes are the matrices', its Rayleigh damping
    /// (without a damping matrix) the ratio `damping_ratio` on their modes 1 and 2, and its storey
    /// stiffnesses in one line the stiffness across each cut under a floor ([`MatrixStructure::cut_stiffnesses`]).
    /// Its storeys are linear.
    pub fn from_matrices(
        structure: MatrixStructure,
        heights: Vec<f64>,
        damping_ratio: f64,
    ) -> Result<Self, Error> {
        let (omega, shapes) = matrix::modes_of(&structure.masses, &structure.stiffness)?;
        let modes = Modes { omega, shapes };
        let cuts = structure.cut_stiffnesses();
        if let Some((j, k)) = cuts.iter().enumerate().find(|(_, k)| **k <= 0.0) {
            return Err(Error::Choice {
                name: "stiffness_matrix",
                value: format!("the matrix (stiffness across the cut under floor {}: {})", j + 1, crate::words::number(*k)),
                allowed: "a structure whose every floor is held from below: a positive stiffness across the cut under each floor".into(),
            });
        }
        let mut b = Self::new(structure.masses.clone(), cuts, heights, damping_ratio)?;
        b.rayleigh = rayleigh_of(&modes.omega, damping_ratio);
        b.modes = modes;
        b.matrix = Some(Box::new(structure));
        Ok(b)
    }

    /// The matrices of a structure given by them.
    pub fn matrices(&self) -> Option<&MatrixStructure> {
        self.matrix.as_deref()
    }

    /// The foundation a building stands on, if it is not fixed at its base.
    pub fn foundation(&self) -> Option<&Foundation> {
        self.foundation.as_deref().map(|f| &f.0)
    }

    /// The modes on the foundation (floors, then the foundation's sway and rocking; [`foundation::flexible_modes`]),
    /// if there is one.
    pub fn flexible_modes(&self) -> Option<&Modes> {
        self.foundation.as_deref().map(|f| &f.1)
    }

    /// A building isolated at its base: the base slab (floor 1, `base_mass` kg) on `isolator` (storey 1),
    /// with the superstructure's floors above it (`masses` kg, `stiffnesses` N/m of the storeys from the
    /// slab up, `heights` m; all three may be empty, for a deck on its bearings). The superstructure is
    /// damped with the ratio `damping_ratio` on modes 1 and 2 of its fixed-base modes (the slab held still);
    /// see [`isolation`]. A friction pendulum carries the weight of every mass, slab included.
    pub fn isolated(
        base_mass: f64,
        isolator: Isolator,
        masses: Vec<f64>,
        stiffnesses: Vec<f64>,
        heights: Vec<f64>,
        damping_ratio: f64,
    ) -> Result<Self, Error> {
        isolator.check()?;
        same_lengths(&masses, &stiffnesses, &heights)?;
        check("mass", base_mass, base_mass > 0.0, "floor masses > 0 (kg)")?;
        let weight = crate::units::STANDARD_GRAVITY * (base_mass + masses.iter().sum::<f64>());
        let (k0, law) = isolator.model.storey(weight)?;
        let above = (masses.clone(), stiffnesses.clone());
        let all = |first: f64, rest: Vec<f64>| std::iter::once(first).chain(rest).collect();
        let mut b = Self::new(
            all(base_mass, masses),
            all(k0, stiffnesses),
            all(isolator.height, heights),
            damping_ratio,
        )?;
        b.storey_laws[0] = law;
        b.rayleigh = if above.0.is_empty() {
            (0.0, 0.0)
        } else {
            rayleigh_of(&solve_modes(&above.0, &above.1).0.omega, damping_ratio)
        };
        b.isolator = Some(isolator);
        Ok(b)
    }

    /// What the structure is: a building, an isolated building, or a deck on its bearings.
    pub fn form(&self) -> Form {
        Form::of(self.isolator.is_some(), self.storeys())
    }

    /// The isolator under the base slab, if the building is isolated ([`ShearBuilding::isolated`]).
    pub fn isolator(&self) -> Option<&Isolator> {
        self.isolator.as_ref()
    }

    /// The viscous coefficient of each storey's dashpot, N s/m (storey 1 upwards), and the
    /// mass-proportional coefficient `a0` (1/s) with the floor it is relative to: the ground (`None`) for a
    /// fixed-base building, the base slab (floor 1, index 0) for an isolated one.
    pub fn damping_layout(&self) -> (Vec<f64>, f64, Option<usize>) {
        let (a0, a1) = self.rayleigh;
        let mut c: Vec<f64> = self.stiffnesses.iter().map(|k| a1 * k).collect();
        match &self.isolator {
            Some(iso) => {
                c[0] = iso.damping;
                (c, a0, Some(0))
            }
            None => (c, a0, None),
        }
    }

    /// Damping ratio of mode `r` (from 0): `phi^T C phi / (2 w)` with the building's damping matrix (the
    /// diagonal term; for a fixed-base building with Rayleigh damping this is exactly the modal ratio, for an
    /// isolated one the modes are not classically damped and the isolator's hysteresis is not counted).
    pub fn damping_of_mode(&self, r: usize) -> f64 {
        let (w, phi) = (self.modes.omega[r], &self.modes.shapes[r]);
        if let Some(ms) = &self.matrix {
            return ms.quadratic_damping(phi, self.rayleigh) / (2.0 * w);
        }
        let (c, a0, base) = self.damping_layout();
        let mut sum = 0.0;
        for (j, cj) in c.iter().enumerate() {
            let d = phi[j] - if j == 0 { 0.0 } else { phi[j - 1] };
            sum += cj * d * d;
        }
        let p0 = base.map_or(0.0, |b| phi[b]);
        for (i, m) in self.masses.iter().enumerate() {
            if base != Some(i) {
                sum += a0 * m * (phi[i] - p0) * (phi[i] - p0);
            }
        }
        sum / (2.0 * w)
    }

    /// Sets the law of each storey (one per storey; for an isolated building, one per storey above the
    /// isolator, whose law stays its own). The stiffnesses stay the initial stiffnesses: modes and Rayleigh
    /// damping (`C = a0 M + a1 K_0`, OpenSees' `betaKinit`) are those of the initial, elastic building.
    pub fn with_storey_laws(mut self, laws: Vec<StoreyLaw>) -> Result<Self, Error> {
        let first = usize::from(self.isolator.is_some());
        if laws.len() != self.storeys() - first {
            return Err(Error::Length {
                name: "storey_model",
                len: laws.len(),
                expected: self.storeys() - first,
            });
        }
        if self.matrix.is_some() && laws.iter().any(|l| l.is_inelastic()) {
            return Err(Error::Choice {
                name: "storey_model",
                value: "an inelastic storey".into(),
                allowed: "linear storeys for a structure given by its matrices (the inelastic laws stay on the shear-building forms)".into(),
            });
        }
        self.storey_laws.truncate(first);
        self.storey_laws.extend(laws);
        Ok(self)
    }

    /// The law of each storey, storey 1 upwards.
    pub fn storey_laws(&self) -> &[StoreyLaw] {
        &self.storey_laws
    }

    /// Number of storeys (= floors).
    pub fn storeys(&self) -> usize {
        self.masses.len()
    }
    /// Floor masses, kg, floor 1 upwards.
    pub fn masses(&self) -> &[f64] {
        &self.masses
    }
    /// Storey stiffnesses, N/m, storey 1 upwards.
    pub fn stiffnesses(&self) -> &[f64] {
        &self.stiffnesses
    }
    /// Storey heights, m.
    pub fn heights(&self) -> &[f64] {
        &self.heights
    }
    /// Damping ratio of modes 1 and 2 (dimensionless).
    pub fn damping_ratio(&self) -> f64 {
        self.damping_ratio
    }
    /// Total mass, kg.
    pub fn total_mass(&self) -> f64 {
        self.masses.iter().sum()
    }

    /// Elevation of each floor above the ground, m.
    pub fn elevations(&self) -> Vec<f64> {
        self.heights
            .iter()
            .scan(0.0, |z, h| {
                *z += h;
                Some(*z)
            })
            .collect()
    }

    /// Natural modes: `K phi = w^2 M phi`, solved as the symmetric problem
    /// `M^(-1/2) K M^(-1/2) x = w^2 x` by cyclic Jacobi rotations (accurate to rounding for the small
    /// matrices of shear buildings). Computed once, at construction.
    pub fn modes(&self) -> &Modes {
        &self.modes
    }

    /// Rayleigh coefficients `(a0, a1)` of `C = a0 M + a1 K` (a0 in 1/s, a1 in s) giving the damping ratio
    /// on modes 1 and 2 (mode 1 alone for a single storey); for an isolated building, those of its
    /// superstructure on a fixed base ((0, 0) without one), see [`ShearBuilding::damping_layout`].
    pub fn rayleigh(&self) -> (f64, f64) {
        self.rayleigh
    }

    /// Damping ratio of a mode of circular frequency `w` (rad/s) under Rayleigh damping with this building's
    /// coefficients: `a0 / (2 w) + a1 w / 2` (for an isolated building, of a fixed-base superstructure mode;
    /// use [`ShearBuilding::damping_of_mode`] for the building's own modes).
    pub fn modal_damping(&self, w: f64) -> f64 {
        let (a0, a1) = self.rayleigh();
        a0 / (2.0 * w) + a1 * w / 2.0
    }
}

/// Rayleigh coefficients `(a0, a1)` giving `zeta` on the first two of the circular frequencies `w` (rad/s,
/// lowest first; the first alone if there is one): Chopra, eq 11.4.9.
fn rayleigh_of(w: &[f64], zeta: f64) -> (f64, f64) {
    let (w1, w2) = (w[0], *w.get(1).unwrap_or(&w[0]));
    (2.0 * zeta * w1 * w2 / (w1 + w2), 2.0 * zeta / (w1 + w2))
}

/// Natural modes of the shear building with these floor masses and storey stiffnesses (same length, at
/// least 1, positive), and the number of Jacobi sweeps it took.
pub(super) fn solve_modes(masses: &[f64], stiffnesses: &[f64]) -> (Modes, usize) {
    let n = masses.len();
    let s: Vec<f64> = masses.iter().map(|m| 1.0 / m.sqrt()).collect();
    let mut a = vec![0.0; n * n];
    for i in 0..n {
        let k_below = stiffnesses[i];
        let k_above = stiffnesses.get(i + 1).copied().unwrap_or(0.0);
        a[i * n + i] = (k_below + k_above) * s[i] * s[i];
        if i + 1 < n {
            let off = -k_above * s[i] * s[i + 1];
            a[i * n + i + 1] = off;
            a[(i + 1) * n + i] = off;
        }
    }
    let eigen::Eigen {
        values,
        vectors,
        sweeps,
    } = eigen::symmetric(&mut a, n);
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|&i, &j| values[i].total_cmp(&values[j]));
    let omega = order.iter().map(|&r| values[r].max(0.0).sqrt()).collect();
    let shapes = order
        .iter()
        .map(|&r| {
            let mut phi: Vec<f64> = (0..n).map(|i| vectors[i * n + r] * s[i]).collect();
            if phi[n - 1] < 0.0 {
                phi.iter_mut().for_each(|x| *x = -*x);
            }
            phi
        })
        .collect();
    (Modes { omega, shapes }, sweeps)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn single_storey_period_and_damping() {
        let b = ShearBuilding::new(vec![5.0e5], vec![7.8957e7], vec![3.0], 0.05).unwrap();
        let t = b.modes().periods()[0];
        assert!((t - 2.0 * PI * (5.0e5f64 / 7.8957e7).sqrt()).abs() < 1e-14);
        let (a0, a1) = b.rayleigh();
        let c = a0 * 5.0e5 + a1 * 7.8957e7;
        assert!((c / (2.0 * 0.05 * (7.8957e7f64 * 5.0e5).sqrt()) - 1.0).abs() < 1e-14);
    }

    #[test]
    fn uniform_building_matches_closed_form() {
        // Equal masses m and stiffnesses k, free top: w_r = 2 sqrt(k/m) sin((2r - 1) pi / (2 (2n + 1)))
        // (the fixed-free chain; Chopra, Dynamics of Structures, problem 10.x).
        let (n, m, k) = (12, 3.0e5, 2.0e8);
        let b = ShearBuilding::new(vec![m; n], vec![k; n], vec![3.0; n], 0.05).unwrap();
        let modes = b.modes();
        for (r, w) in modes.omega.iter().enumerate() {
            let exact =
                2.0 * (k / m).sqrt() * ((2 * r + 1) as f64 * PI / (2.0 * (2 * n + 1) as f64)).sin();
            assert!(
                (w / exact - 1.0).abs() < 1e-12,
                "mode {}: {w} vs {exact}",
                r + 1
            );
        }
        // Shapes: phi_i ∝ sin(i (2r - 1) pi / (2n + 1)), mass-normalised.
        for (r, phi) in modes.shapes.iter().enumerate() {
            let g = |i: usize| ((i as f64) * (2 * r + 1) as f64 * PI / (2 * n + 1) as f64).sin();
            let norm: f64 = (1..=n).map(|i| m * g(i) * g(i)).sum::<f64>().sqrt();
            let sign = g(n).signum();
            for (i, p) in phi.iter().enumerate() {
                assert!((p - sign * g(i + 1) / norm).abs() < 1e-12 / m.sqrt());
            }
        }
        // Rayleigh damping: exactly zeta on modes 1 and 2.
        for w in &modes.omega[..2] {
            assert!((b.modal_damping(*w) - 0.05).abs() < 1e-14);
        }
        // Effective modal masses sum to the total mass.
        let sum: f64 = modes.participation(b.masses()).iter().map(|p| p.1).sum();
        assert!((sum / b.total_mass() - 1.0).abs() < 1e-12);
    }

    #[test]
    fn two_storey_closed_form() {
        // m1 = 2m, m2 = m, k1 = 2k, k2 = k: w^2 = k/(2m) and 2k/m (Chopra, example 10.4).
        let (m, k) = (1.0e5, 5.0e7);
        let b =
            ShearBuilding::new(vec![2.0 * m, m], vec![2.0 * k, k], vec![3.0, 3.0], 0.0).unwrap();
        let w = &b.modes().omega;
        assert!((w[0] * w[0] / (k / (2.0 * m)) - 1.0).abs() < 1e-13);
        assert!((w[1] * w[1] / (2.0 * k / m) - 1.0).abs() < 1e-13);
        let shapes = b.modes().shapes_normalised();
        assert!((shapes[0][0] - 0.5).abs() < 1e-13 && (shapes[1][0] + 1.0).abs() < 1e-13);
    }

    /// `w_r = 2 sqrt(k/m) sin((2r - 1) pi / (2 (2n + 1)))`, r = 1..=n: the uniform fixed-free chain.
    fn uniform_chain_omega(n: usize, m: f64, k: f64) -> Vec<f64> {
        (1..=n)
            .map(|r| {
                let x = (2 * r - 1) as f64 * PI / (2 * (2 * n + 1)) as f64;
                2.0 * (k / m).sqrt() * x.sin()
            })
            .collect()
    }

    #[test]
    fn tall_uniform_building_matches_closed_form() {
        let (n, m, k) = (80, 3.0e5, 2.0e8);
        let b = ShearBuilding::new(vec![m; n], vec![k; n], vec![3.0; n], 0.05).unwrap();
        let modes = b.modes();
        assert_eq!(modes.omega.len(), n);
        for (r, (w, exact)) in modes
            .omega
            .iter()
            .zip(uniform_chain_omega(n, m, k))
            .enumerate()
        {
            assert!(
                (w / exact - 1.0).abs() < 1e-10,
                "mode {}: {w} vs {exact}",
                r + 1
            );
        }
        // Mass-orthonormal shapes.
        for (r, pr) in modes.shapes.iter().enumerate() {
            for (q, pq) in modes.shapes.iter().enumerate() {
                let dot: f64 = pr.iter().zip(pq).map(|(a, b)| a * m * b).sum();
                let want = if r == q { 1.0 } else { 0.0 };
                assert!((dot - want).abs() < 1e-12, "modes {r}, {q}: {dot}");
            }
        }
        let sum: f64 = modes.participation(b.masses()).iter().map(|p| p.1).sum();
        assert!((sum / b.total_mass() - 1.0).abs() < 1e-12);
    }

    #[test]
    fn jacobi_converges_in_a_few_sweeps() {
        // Quadratic convergence: a handful of sweeps, growing slowly with the size (the stopping test used
        // to be below rounding, so every building of 2 storeys or more ran all 100). Counts include the
        // last sweep, which finds nothing to rotate: 1, 2, 5, 8 and 11 today.
        let (m, k) = (3.0e5, 2.0e8);
        for (n, max_sweeps) in [(1, 1), (2, 2), (3, 5), (12, 8), (80, 12)] {
            let (modes, sweeps) = solve_modes(&vec![m; n], &vec![k; n]);
            assert!(sweeps <= max_sweeps, "{n} storeys: {sweeps} sweeps");
            let exact = uniform_chain_omega(n, m, k);
            for (w, e) in modes.omega.iter().zip(&exact) {
                assert!((w / e - 1.0).abs() < 1e-10, "{n} storeys: {w} vs {e}");
            }
        }
        // A tapered 80-storey building (mass and stiffness falling with height, soft top storeys).
        let n = 80;
        let masses: Vec<f64> = (0..n).map(|i| 4.0e5 * (1.0 - 0.006 * i as f64)).collect();
        let stiff: Vec<f64> = (0..n)
            .map(|i| 6.0e8 * (1.0 - 0.01 * i as f64) * if i >= 75 { 0.3 } else { 1.0 })
            .collect();
        let (modes, sweeps) = solve_modes(&masses, &stiff);
        assert!(sweeps <= 12, "tapered: {sweeps} sweeps");
        // Each mode satisfies K phi = w^2 M phi to rounding.
        for (w, phi) in modes.omega.iter().zip(&modes.shapes) {
            for i in 0..n {
                let below = phi[i] - if i > 0 { phi[i - 1] } else { 0.0 };
                let above = if i + 1 < n { phi[i + 1] - phi[i] } else { 0.0 };
                let k_above = stiff.get(i + 1).copied().unwrap_or(0.0);
                let kphi = stiff[i] * below - k_above * above;
                let scale = (stiff[i] + k_above) * phi.iter().fold(0.0f64, |a, x| a.max(x.abs()));
                assert!((kphi - w * w * masses[i] * phi[i]).abs() < 1e-12 * scale);
            }
        }
    }

    #[test]
    fn modes_are_stored_at_construction() {
        let (masses, stiff) = (vec![4.0e5, 3.5e5, 3.0e5], vec![6.0e8, 5.0e8, 3.0e8]);
        let b = ShearBuilding::new(masses.clone(), stiff.clone(), vec![3.0; 3], 0.05).unwrap();
        assert_eq!(*b.modes(), solve_modes(&masses, &stiff).0);
        assert!(std::ptr::eq(b.modes(), b.modes()));
        assert_eq!(b.clone(), b);
    }

    #[test]
    fn invalid_buildings_are_refused() {
        let ok = |m: Vec<f64>, k: Vec<f64>, h: Vec<f64>, z: f64| ShearBuilding::new(m, k, h, z);
        assert!(matches!(
            ok(vec![1.0, 1.0], vec![1.0], vec![3.0, 3.0], 0.05),
            Err(Error::Length {
                name: "stiffnesses",
                len: 1,
                expected: 2
            })
        ));
        assert!(ok(vec![0.0], vec![1.0], vec![3.0], 0.05).is_err());
        assert!(ok(vec![1.0], vec![-1.0], vec![3.0], 0.05).is_err());
        assert!(ok(vec![1.0], vec![1.0], vec![f64::NAN], 0.05).is_err());
        assert!(ok(vec![1.0], vec![1.0], vec![3.0], 1.0).is_err());
        assert!(ok(vec![], vec![], vec![], 0.05).is_err());
    }
}
