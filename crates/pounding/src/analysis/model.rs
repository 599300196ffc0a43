//! The row of buildings as a system of the engine: one degree of freedom per floor, one storey element per
//! storey (and, for an isolated building, one dashpot per floor above the base slab for the
//! mass-proportional damping of its superstructure), one contact element per level of each contact site
//! (two with a bumper), and one device element per floor pair of each device.

use super::{ContactSite, DeviceEnds, Layer, Scenario, SiteKind, NO_CONTACT_GAP};
use crate::element::device::Dashpot;
use crate::element::{Contact, Element, ElementLaw, End, Point, Scales};
use crate::engine::{Axis, Dof, System};
use crate::structure::{MatrixStructure, Plan, PlanDof};

/// A contact element and where it stands.
#[derive(Clone, Copy, Debug)]
pub(super) struct ContactRef {
    /// Index of the element in the system.
    pub element: usize,
    /// Its site (index in [`Scenario::sites`]).
    pub site: usize,
    /// Its level (index in the site's levels).
    pub level: usize,
    /// Which law of the site.
    pub layer: Layer,
}

/// A struck column's point.
#[derive(Clone, Copy, Debug)]
pub(super) struct ColumnRef {
    /// Its site (index in [`Scenario::sites`]).
    pub site: usize,
    /// The degree of freedom of the point struck.
    pub dof: usize,
    /// The element of its spring to the floors (its force: the load on the column at the point, N).
    pub element: usize,
    /// The column's drift: its upper end's displacement less its lower end's and the foundation's rigid
    /// rotation over its length, m.
    pub drift: Point,
    /// The force at the point (N), then its lower and upper end shears (N) and moments (N m), each
    /// `alpha x + beta drift` with `x` the spring's deformation: the load at the point (`k x`), and its part
    /// (the shape functions) and the drift's (`12 EI / L^3`, `6 EI / L^2`; Roark, table 8.1, cases 1e and 2e)
    /// in the end forces.
    pub ends: [(f64, f64); 5],
}

/// A device element and where it stands.
#[derive(Clone, Copy, Debug)]
pub(super) struct DeviceRef {
    /// Index of the element in the system.
    pub element: usize,
    /// Index in [`Scenario::devices`].
    pub device: usize,
}

/// The storey under a degree of freedom: the degree of freedom below it (the ground under floor 1), and the
/// storey's elements that act on it, each with its coefficient there (1 for a storey in one line; for a floor
/// in plan, 1 for the lines along the degree of freedom's direction, a line's arm (m) for the rotation). The
/// storey's force on the degree of freedom is `sum c f`: its shear, or its torque (N m).
#[derive(Clone, Debug, Default)]
pub(super) struct StoreyRef {
    pub below: Option<usize>,
    /// On a foundation: its rocking and the storey's height, whose product the rigid rotation adds to the
    /// floors' difference (the drift leaves it out).
    pub tilt: Option<(usize, f64)>,
    pub elements: Vec<(usize, f64)>,
}

impl StoreyRef {
    /// The drift of the storey under degree of freedom `i` in `y` (displacements at `off`, or velocities).
    #[inline]
    pub fn drift(&self, i: usize, y: &[f64], off: usize) -> f64 {
        let d = y[off + i] - self.below.map_or(0.0, |b| y[off + b]);
        match self.tilt {
            None => d,
            Some((t, h)) => d - h * y[off + t],
        }
    }
}

/// The system and the map from buildings, storeys and contacts to its degrees of freedom and elements.
pub(super) struct Model<'a> {
    pub system: System<'a>,
    /// First degree of freedom of each building (floor 1; for a building in plan, its x block).
    pub offsets: Vec<usize>,
    /// The degrees of freedom reported as floors (each building's storeys from its offset; not a
    /// foundation's sway and rocking, a floor in plan's y and twist, a struck column's point): the floors
    /// whose absolute accelerations the results give.
    pub floors: Vec<usize>,
    /// Element index of the first element of storey 1 of each building.
    pub first_storey: Vec<usize>,
    /// Elements per storey of each building (1, or a plan's number of lines); storey `j`'s are
    /// `first_storey + j * per_storey ..` and the next `per_storey`.
    pub per_storey: Vec<usize>,
    /// The storey under each degree of freedom.
    pub storeys: Vec<StoreyRef>,
    /// The displacements of the corners of every floor in plan, building by building, floor by floor: along
    /// x those of the edges at `y_min` and `y_max`, along y those at `x_min` and `x_max` (the corners of an
    /// edge move alike along it).
    pub corners: Vec<Point>,
    /// The elements of the lines of every building in plan, building by building, storey by storey.
    pub lines: Vec<usize>,
    /// The struck columns: their site and their point's degree of freedom.
    pub columns: Vec<ColumnRef>,
    /// The contact elements, site by site, level by level; a bumper's layer comes before the hard law
    /// behind it.
    pub contacts: Vec<ContactRef>,
    /// The elements of the devices, device by device, floor pair by floor pair.
    pub devices: Vec<DeviceRef>,
}

/// Degrees of freedom and elements as they are assembled.
#[derive(Default)]
struct Parts {
    dofs: Vec<Dof>,
    elements: Vec<Element>,
    storeys: Vec<StoreyRef>,
    /// Dashpots of the mass-proportional damping of isolated superstructures (and of buildings on a
    /// foundation), relative to the base slab (the base's rigid motion).
    base_dashpots: Vec<(End, End, f64)>,
}

impl Parts {
    /// A building in one line: one degree of freedom per floor, one storey element per storey.
    fn in_line(&mut self, st: &crate::structure::ShearBuilding, axis: Axis) {
        let (c, a0, base) = st.damping_layout();
        let offset = self.dofs.len();
        for (j, (&k, law)) in st.stiffnesses().iter().zip(st.storey_laws()).enumerate() {
            let bottom = if j == 0 {
                End::Ground
            } else {
                End::Dof(offset + j - 1)
            };
            self.storeys.push(StoreyRef {
                below: j.checked_sub(1).map(|b| offset + b),
                tilt: None,
                elements: vec![(self.elements.len(), 1.0)],
            });
            // Rayleigh damping on the initial stiffness (OpenSees' betaKinit); an isolator's own.
            self.elements
                .push(Element::new(End::Dof(offset + j), bottom, law.law(k)).with_dashpot(c[j]));
        }
        let a0_dof = if base.is_some() { 0.0 } else { a0 };
        self.dofs.extend(st.masses().iter().map(|&mass| Dof {
            mass,
            a0: a0_dof,
            axis,
        }));
        if let (Some(base), true) = (base, a0 > 0.0) {
            for (i, &m) in st.masses().iter().enumerate().filter(|(i, _)| *i != base) {
                self.base_dashpots
                    .push((End::Dof(offset + i), End::Dof(offset + base), a0 * m));
            }
        }
    }

    /// A building on a foundation: its floors' displacements (relative to the free-field ground, rocking
    /// included), then the foundation's sway and rocking; each storey deforms by its floors' difference less
    /// its height times the rocking; the fixed-base Rayleigh damping, its mass-proportional part relative to
    /// the base's rigid motion; the soil's springs and dashpots under the foundation.
    fn on_foundation(
        &mut self,
        st: &crate::structure::ShearBuilding,
        f: &crate::structure::Foundation,
        axis: Axis,
    ) {
        let (a0, a1) = st.rayleigh();
        let offset = self.dofs.len();
        let n = st.storeys();
        let (uf, th) = (offset + n, offset + n + 1);
        let z = st.elevations();
        // A floor's point: its displacement less the rigid rotation's at its elevation.
        let point = |i: usize| End::Point(Point::new(&[(offset + i, 1.0), (th, -z[i])]));
        for (j, (&k, law)) in st.stiffnesses().iter().zip(st.storey_laws()).enumerate() {
            let bottom = if j == 0 { End::Dof(uf) } else { point(j - 1) };
            self.storeys.push(StoreyRef {
                below: Some(if j == 0 { uf } else { offset + j - 1 }),
                tilt: Some((th, st.heights()[j])),
                elements: vec![(self.elements.len(), 1.0)],
            });
            self.elements
                .push(Element::new(point(j), bottom, law.law(k)).with_dashpot(a1 * k));
        }
        self.dofs.extend(st.masses().iter().map(|&mass| Dof {
            mass,
            a0: 0.0,
            axis,
        }));
        self.dofs.push(Dof {
            mass: f.mass,
            a0: 0.0,
            axis,
        });
        self.dofs.push(Dof {
            mass: f.inertia,
            a0: 0.0,
            axis: Axis::Rotation,
        });
        if a0 > 0.0 {
            for (i, &m) in st.masses().iter().enumerate() {
                self.base_dashpots.push((point(i), End::Dof(uf), a0 * m));
            }
        }
        // The soil: sway and rocking, each "storey" of its own degree of freedom (its force, the base shear
        // and the overturning moment the soil takes).
        for (dof, k, c) in [(uf, f.kx, f.cx), (th, f.ktheta, f.ctheta)] {
            self.storeys.push(StoreyRef {
                below: None,
                tilt: None,
                elements: vec![(self.elements.len(), 1.0)],
            });
            self.elements.push(
                Element::new(
                    End::Dof(dof),
                    End::Ground,
                    crate::element::StoreyLaw::Linear.law(k),
                )
                .with_dashpot(c),
            );
        }
    }

    /// A structure given by its matrices: one degree of freedom per floor, and the springs that make its
    /// stiffness matrix (and the dashpots that make its damping matrix, or Rayleigh's `a0 M + a1 K`); the storey
    /// under each floor is the springs across the cut under it.
    fn by_matrices(
        &mut self,
        st: &crate::structure::ShearBuilding,
        ms: &MatrixStructure,
        axis: Axis,
    ) {
        let (a0, a1) = st.rayleigh();
        let offset = self.dofs.len();
        let n = ms.n();
        let rayleigh = ms.damping.is_none();
        self.dofs.extend(ms.masses.iter().map(|&mass| Dof {
            mass,
            a0: if rayleigh { a0 } else { 0.0 },
            axis,
        }));
        let first = self.storeys.len();
        self.storeys.extend((0..n).map(|j| StoreyRef {
            below: j.checked_sub(1).map(|b| offset + b),
            tilt: None,
            elements: Vec::new(),
        }));
        let ends = |hi: usize, lo: Option<usize>| {
            (
                End::Dof(offset + hi),
                lo.map_or(End::Ground, |lo| End::Dof(offset + lo)),
            )
        };
        for (hi, lo, k) in MatrixStructure::springs(&ms.stiffness) {
            let e = self.elements.len();
            // The storeys whose cut it crosses.
            for j in lo.map_or(0, |lo| lo + 1)..=hi {
                self.storeys[first + j].elements.push((e, 1.0));
            }
            let (a, b) = ends(hi, lo);
            let c = if rayleigh { a1 * k } else { 0.0 };
            self.elements
                .push(Element::new(a, b, crate::element::StoreyLaw::Linear.law(k)).with_dashpot(c));
        }
        if let Some(cm) = &ms.damping {
            for (hi, lo, c) in MatrixStructure::springs(cm) {
                let (a, b) = ends(hi, lo);
                self.elements.push(Element::new(a, b, Dashpot::new(c)));
            }
        }
    }

    /// The struck columns' points (after the buildings' degrees of freedom), each on its spring to its
    /// building's floors (their translations through the column's shape functions; the building's
    /// stiffness-proportional damping on it): the columns, and each site's point (`None` for others).
    fn columns(
        &mut self,
        s: &Scenario,
        offsets: &[usize],
        axis_of: &dyn Fn(usize) -> Axis,
    ) -> (Vec<ColumnRef>, Vec<Option<usize>>) {
        let mut refs = Vec::new();
        let mut dofs = vec![None; s.sites().len()];
        for (si, site) in s.sites().iter().enumerate() {
            let (Some(c), SiteKind::Between { left, right }) = (&site.column, site.kind) else {
                continue;
            };
            let Some(col) = c.struck else { continue };
            let b = if c.on_left { left } else { right };
            let o = offsets[b];
            let dof = self.dofs.len();
            self.dofs.push(Dof {
                mass: col.point_mass(),
                a0: 0.0,
                axis: axis_of(b),
            });
            let element = self.elements.len();
            self.storeys.push(StoreyRef {
                below: None,
                tilt: None,
                elements: vec![(element, 1.0)],
            });
            let (n1, n2) = col.shears();
            let j = c.storey;
            let st = &s.buildings()[b].structure;
            // The ends: the floor below (the ground, or a foundation's sway, under storey 1) and the floor
            // above; on a foundation both ends also turn with its rocking (slope theta), which the column's
            // shape carries to the point by L xi (1 - xi)(1 - 2 xi), xi = a / L.
            let n = st.storeys();
            let rocking = st.foundation().map(|_| (o + n, o + n + 1));
            let lower = match (j, rocking) {
                (1, None) => None,
                (1, Some((sway, _))) => Some(sway),
                _ => Some(o + j - 2),
            };
            let upper = o + j - 1;
            let (l, xi) = (col.length, col.a / col.length);
            let (mut terms, mut drift) = (Vec::new(), Vec::new());
            if let Some(lo) = lower {
                terms.push((lo, n1));
                drift.push((lo, -1.0));
            }
            terms.push((upper, n2));
            drift.push((upper, 1.0));
            if let Some((_, th)) = rocking {
                terms.push((th, l * xi * (1.0 - xi) * (1.0 - 2.0 * xi)));
                drift.push((th, -l));
            }
            let floors = Point::new(&terms);
            let k = col.stiffness();
            let a1 = s.buildings()[b].structure.rayleigh().1;
            self.elements.push(
                Element::new(
                    End::Dof(dof),
                    End::Point(floors),
                    crate::element::StoreyLaw::Linear.law(k),
                )
                .with_dashpot(a1 * k),
            );
            dofs[si] = Some(dof);
            let ((m1, m2), ei) = (col.moments(), col.ei);
            let (kv, km) = (12.0 * ei / l.powi(3), 6.0 * ei / (l * l));
            refs.push(ColumnRef {
                site: si,
                dof,
                element,
                drift: Point::new(&drift),
                // A load P along +x and a drift d > 0 bend the lower end alike and the upper end against
                // each other: V_lo = n1 P + kv d, V_hi = n2 P - kv d, M_lo = m1 P + km d, M_hi = m2 P - km d.
                ends: [
                    (k, 0.0),
                    (n1 * k, kv),
                    (n2 * k, -kv),
                    (m1 * k, km),
                    (m2 * k, -km),
                ],
            });
        }
        (refs, dofs)
    }

    /// A building in plan: x, y and rotation of every floor (x block, y block, rotation block), one element
    /// per line per storey (storey by storey), with Rayleigh damping `a0 M + a1 K_0` of the plan's modes.
    fn in_plan(&mut self, plan: &Plan) {
        let (a0, a1) = plan.rayleigh();
        let offset = self.dofs.len();
        let n = plan.floors();
        let masses = plan.dof_masses();
        for (i, &mass) in masses.iter().enumerate() {
            let axis = match i / n {
                0 => Axis::X,
                1 => Axis::Y,
                _ => Axis::Rotation,
            };
            self.dofs.push(Dof { mass, a0, axis });
            self.storeys.push(StoreyRef::default());
        }
        for storey in 1..=n {
            for (li, line) in plan.lines().iter().enumerate() {
                let k = line.stiffnesses[storey - 1];
                let (a, b) = plan.line_ends(li, storey, offset);
                let e = self.elements.len();
                for &(i, c) in a.terms().terms() {
                    if c != 0.0 {
                        self.storeys[i].elements.push((e, c));
                    }
                }
                self.elements
                    .push(Element::new(a, b, line.laws[storey - 1].law(k)).with_dashpot(a1 * k));
            }
        }
        for floor in 2..=n {
            for d in [PlanDof::X, PlanDof::Y, PlanDof::Rotation] {
                self.storeys[offset + plan.dof(floor, d)].below =
                    Some(offset + plan.dof(floor - 1, d));
            }
        }
    }
}

impl<'a> Model<'a> {
    pub fn new(s: &'a Scenario) -> Self {
        let mut parts = Parts::default();
        let mut offsets = Vec::new();
        let mut first_storey = Vec::new();
        let mut per_storey = Vec::new();
        let mut corners = Vec::new();
        let mut lines = Vec::new();
        // Multi-support excitation: each building shaken by its support's record, each support's
        // displacement a driven degree of freedom after the buildings' (for elements between supports).
        let multi = s.multi_support();
        for (bi, b) in s.buildings().iter().enumerate() {
            let st = &b.structure;
            let axis = if multi {
                Axis::On(s.building_supports()[bi])
            } else {
                Axis::X
            };
            let offset = parts.dofs.len();
            offsets.push(offset);
            first_storey.push(parts.elements.len());
            match st.plan() {
                Some(plan) => {
                    per_storey.push(plan.lines().len());
                    let first = parts.elements.len();
                    parts.in_plan(plan);
                    lines.extend(first..parts.elements.len());
                    // Two corners on an edge along x move alike along x (so do two on an edge along y,
                    // along y): the bottom and top edges along x, the left and right edges along y.
                    let [c0, _, c2, _] = plan.corners();
                    for floor in 1..=plan.floors() {
                        corners.push(plan.point(floor, offset, c0, (1.0, 0.0)));
                        corners.push(plan.point(floor, offset, c2, (1.0, 0.0)));
                        corners.push(plan.point(floor, offset, c0, (0.0, 1.0)));
                        corners.push(plan.point(floor, offset, c2, (0.0, 1.0)));
                    }
                }
                None => match (st.foundation(), st.matrices()) {
                    (Some(f), _) => {
                        per_storey.push(1);
                        parts.on_foundation(st, f, axis);
                    }
                    (None, Some(ms)) => {
                        // No element is one storey's: storey_elements is empty for it.
                        per_storey.push(0);
                        parts.by_matrices(st, ms, axis);
                    }
                    (None, None) => {
                        per_storey.push(1);
                        parts.in_line(st, axis);
                    }
                },
            }
        }
        let axis_of = |b: usize| {
            if multi {
                Axis::On(s.building_supports()[b])
            } else {
                Axis::X
            }
        };
        let (columns, column_dofs) = parts.columns(s, &offsets, &axis_of);
        let supports = Supports {
            base: multi.then_some(parts.dofs.len()),
            building: s.building_supports().to_vec(),
        };
        if multi {
            for k in 0..=s.supports().len() {
                parts.dofs.push(Dof {
                    mass: 1.0,
                    a0: 0.0,
                    axis: Axis::Driven(k),
                });
                parts.storeys.push(StoreyRef::default());
            }
        }
        let Parts {
            dofs,
            mut elements,
            storeys,
            base_dashpots,
        } = parts;
        for (a, b, c) in base_dashpots {
            elements.push(Element::new(a, b, Dashpot::new(c)));
        }
        let contacts = contact_elements(s, (&offsets, &column_dofs), &supports, &mut elements);
        let devices = device_elements(s, &offsets, &supports, &mut elements);
        let floors = s
            .buildings()
            .iter()
            .zip(&offsets)
            .flat_map(|(b, &o)| o..o + b.structure.storeys())
            .collect();
        Self {
            system: System::new(&dofs, elements, s.ground()),
            offsets,
            floors,
            first_storey,
            per_storey,
            storeys,
            corners,
            lines,
            columns,
            contacts,
            devices,
        }
    }

    /// The elements of storey `j` (from 0) of building `b`.
    pub fn storey_elements(&self, b: usize, j: usize) -> std::ops::Range<usize> {
        let (first, per) = (self.first_storey[b], self.per_storey[b]);
        first + j * per..first + (j + 1) * per
    }

    /// Absolute tolerances of every state component for the relative tolerance `rtol`, and a first trial
    /// step; sets each element's rate resolution from them ([`crate::element::RateGate`]). Scales per
    /// building: the static displacement of its fundamental mode under the peak ground acceleration within
    /// the analysis (or, for a building so flexible that it barely responds within the analysis, of a mode
    /// with the analysis duration as period), and the velocity that goes with it; energies from the modal
    /// effective masses and velocities. Gaps play no part: a floor reaches what its building can reach.
    pub fn tolerances(&mut self, s: &Scenario, rtol: f64) -> (Vec<f64>, f64) {
        let sys = &self.system;
        let l = sys.layout();
        let n = l.dofs();
        // The peak ground accelerations within the analysis (a short analysis of a long record sees only its
        // start).
        let (pga, pga_y) = s.pga_within();
        let w_floor = 2.0 * std::f64::consts::PI / s.duration();
        let mut atol = vec![0.0; l.dim()];
        let mut u_scale = vec![0.0; n];
        let mut v_scale = vec![0.0; n];
        let mut w_max: f64 = 0.0;
        let mut resolutions = Vec::new();
        // Energy a building can take in: each mode's effective mass times its velocity under the peak ground
        // acceleration (the modal masses sum to the building's mass; a stiff, heavy floor whose mode barely
        // responds used to count with the fundamental mode's velocity, which loosened the control of the
        // energy terms a hundredfold). A plan's modes take in energy along x and along y.
        let mut e_scale = 0.0;
        let velocity = |a: f64, w: f64| {
            let w = w.max(w_floor);
            (a / (w * w)).max(1e-30) * w
        };
        for b in s.buildings() {
            match b.structure.plan() {
                None => {
                    let modes = b.structure.modes();
                    let m = b.structure.masses();
                    for (w, phi) in modes.omega.iter().zip(&modes.shapes) {
                        let gamma: f64 = phi.iter().zip(m).map(|(p, m)| p * m).sum();
                        let v = velocity(pga, *w);
                        e_scale += gamma * gamma * v * v;
                    }
                }
                Some(p) => {
                    for (w, (gx, gy)) in p.modes().omega.iter().zip(p.gammas()) {
                        let (vx, vy) = (velocity(pga, *w), velocity(pga_y, *w));
                        e_scale += gx * gx * vx * vx + gy * gy * vy * vy;
                    }
                }
            }
        }
        for (b, &offset) in s.buildings().iter().zip(&self.offsets) {
            // What the building can reach, not a gap it may never close (a huge gap used to loosen the error
            // control of every floor); no floor of a nanometre either (a stiff floor that moves 1e-10 m had its
            // energies controlled to 1e-3 only).
            let reach = |a: f64, w: f64| {
                let w = w.max(w_floor);
                ((a / (w * w)).max(1e-30), w)
            };
            let mut scale = |i: usize, (u, w): (f64, f64)| {
                (u_scale[i], v_scale[i]) = (u, u * w);
                atol[l.u(i)] = rtol * u;
                atol[l.v(i)] = rtol * u * w;
            };
            match b.structure.plan() {
                None => {
                    let omega = &b.structure.modes().omega;
                    w_max = omega.iter().copied().fold(w_max, f64::max);
                    for i in offset..offset + omega.len() {
                        scale(i, reach(pga, omega[0]));
                    }
                    // On a foundation: its sway and rocking under the building's weight times the peak
                    // ground acceleration (the base shear and overturning moment the soil takes, statically),
                    // at most what moves a floor or the roof as much as the floors move: the soil's dashpots
                    // dissipate through these motions, so they are held as closely as the floors' (the
                    // energy balance of a pair on soft soil went from 2.5e-6 to 2.3e-7).
                    if let (Some(flex), Some(f)) =
                        (b.structure.flexible_modes(), b.structure.foundation())
                    {
                        w_max = flex.omega.iter().copied().fold(w_max, f64::max);
                        let n = omega.len();
                        let (u, _) = reach(pga, omega[0]);
                        let z = b.structure.elevations();
                        let m = b.structure.masses();
                        let shear: f64 = m.iter().sum::<f64>() * pga;
                        let moment: f64 = m.iter().zip(&z).map(|(m, z)| m * z).sum::<f64>() * pga;
                        let w1 = flex.omega[0].max(w_floor);
                        // Not below 1e-2 of the floors': on stiff soil the foundation barely moves, and
                        // holding its motion to the tolerance would only resolve a mode that carries nothing.
                        let (uz, top) = (1e-2 * u, z[n - 1]);
                        scale(offset + n, ((shear / f.kx).clamp(uz, u), w1));
                        scale(
                            offset + n + 1,
                            ((moment / f.ktheta).clamp(uz / top, u / top), w1),
                        );
                    }
                }
                Some(p) => {
                    let a = pga.max(pga_y);
                    let f = p.floors();
                    let first = p.first_modes();
                    w_max = p.excited_w_max(pga > 0.0, pga_y > 0.0).max(w_max);
                    let (x, y) = (reach(a, first.0), reach(a, first.1));
                    for k in 0..f {
                        scale(offset + k, x);
                        scale(offset + f + k, y);
                        // A rotation that moves the floor's edge by what its centre can reach.
                        let rg = (p.inertias()[k] / p.masses()[k]).sqrt();
                        scale(
                            offset + 2 * f + k,
                            (x.0.min(y.0) / rg, first.2.max(w_floor)),
                        );
                    }
                }
            }
        }
        self.point_and_support_scales(s, rtol, &mut atol, (&mut u_scale, &mut v_scale));
        atol[l.input()] = rtol * e_scale;
        atol[l.damping()] = rtol * e_scale;
        for (e, el) in sys.elements().iter().enumerate() {
            let r = l.block(e);
            // Each end's terms (a point of a floor in plan weighs its degrees of freedom; a plain degree of
            // freedom is one term of weight 1).
            let (ta, tb) = (el.a.terms(), el.b.terms());
            let terms = || {
                ta.terms()
                    .iter()
                    .chain(tb.terms())
                    .map(|&(i, c)| (i, c.abs()))
            };
            let v = terms().map(|(i, c)| c * v_scale[i]).fold(0.0, f64::max);
            // Ten times the local error allowed in each end's rate (atol + rtol |v|, up to 2 atol).
            let v_res: f64 = terms().map(|(i, c)| 20.0 * c * atol[l.v(i)]).sum();
            resolutions.push((e, v_res));
            let u = terms().map(|(i, c)| c * u_scale[i]).fold(0.0, f64::max);
            let scales = Scales {
                rtol,
                displacement: u,
                velocity: v,
                energy: e_scale,
            };
            el.law.state_tolerances(&scales, &mut atol[r]);
        }
        for (e, v_res) in resolutions {
            self.system.elements_mut()[e].set_rate_resolution(v_res);
        }
        (atol, 1e-3 * 2.0 * std::f64::consts::PI / w_max)
    }
}

impl Model<'_> {
    /// The scales of the struck columns' points (as their buildings' floors) and of the driven supports
    /// (their records' displacement and velocity, after a baseline correction: a scale, not a bound).
    fn point_and_support_scales(
        &self,
        s: &Scenario,
        rtol: f64,
        atol: &mut [f64],
        (u_scale, v_scale): (&mut [f64], &mut [f64]),
    ) {
        let sys = &self.system;
        let l = sys.layout();
        for c in &self.columns {
            let site = &s.sites()[c.site];
            if let (SiteKind::Between { left, right }, Some(col)) = (site.kind, &site.column) {
                let o = self.offsets[if col.on_left { left } else { right }];
                (u_scale[c.dof], v_scale[c.dof]) = (u_scale[o], v_scale[o]);
                atol[l.u(c.dof)] = atol[l.u(o)];
                atol[l.v(c.dof)] = atol[l.v(o)];
            }
        }
        if let crate::engine::Ground::Many(rs) = sys.ground() {
            for i in 0..l.dofs() {
                if let crate::engine::Axis::Driven(k) = sys.axis(i) {
                    let p = rs[k].peaks();
                    let (u, v) = (p.pgd.max(1e-6), p.pgv.max(1e-6));
                    (u_scale[i], v_scale[i]) = (u, v);
                    atol[l.u(i)] = rtol * u;
                    atol[l.v(i)] = rtol * v;
                }
            }
        }
    }
}

/// The contact elements of every site, level by level.
fn contact_elements(
    s: &Scenario,
    (offsets, columns): (&[usize], &[Option<usize>]),
    supports: &Supports,
    elements: &mut Vec<Element>,
) -> Vec<ContactRef> {
    let mut contacts = Vec::new();
    for (si, site) in s.sites().iter().enumerate() {
        for li in 0..site.levels.len() {
            let mut ends = site_ends(s, site, li, offsets);
            // A struck column's side is its point.
            if let (Some(dof), Some(c)) = (columns[si], &site.column) {
                if c.on_left {
                    ends.0 = End::Dof(dof);
                } else {
                    ends.1 = End::Dof(dof);
                }
            }
            let ends = supports.site(site, ends);
            let m_eff = s.effective_mass(site, li);
            let mut push = |layer, gap, contact: &crate::contact::PreparedContact| {
                contacts.push(ContactRef {
                    element: elements.len(),
                    site: si,
                    level: li,
                    layer,
                });
                let law = Contact::new(contact.clone(), gap, m_eff, s.min_impact_velocity());
                elements.push(Element::new(ends.0, ends.1, law));
            };
            match &site.bumper {
                _ if !site.active => push(Layer::Direct, NO_CONTACT_GAP, &site.contact),
                None => push(Layer::Direct, site.gap, &site.contact),
                Some(bm) => {
                    let (touch, consumed) = bm.gaps(site.gap);
                    push(Layer::Bumper, touch, &bm.contact);
                    push(Layer::Consumed, consumed, &site.contact);
                }
            }
        }
    }
    contacts
}

/// The elements of every device, floor pair by floor pair (devices join buildings in one line).
fn device_elements(
    s: &Scenario,
    offsets: &[usize],
    supports: &Supports,
    elements: &mut Vec<Element>,
) -> Vec<DeviceRef> {
    let mut devices = Vec::new();
    for (di, d) in s.devices().iter().enumerate() {
        for &(fa, fb) in &d.floors {
            let ends = match d.ends {
                DeviceEnds::Buildings { left, right } => supports.join(
                    (End::Dof(offsets[left] + fa - 1), supports.building[left]),
                    (End::Dof(offsets[right] + fb - 1), supports.building[right]),
                ),
                DeviceEnds::Wall { site } => supports.site(&s.sites()[site], {
                    let floor = |b: usize| End::Dof(offsets[b] + fa - 1);
                    match s.sites()[site].kind {
                        SiteKind::Wall { building, side } if side.negative() => {
                            (End::Ground, floor(building))
                        }
                        SiteKind::Wall { building, .. }
                        | SiteKind::Between { left: building, .. } => {
                            (floor(building), End::Ground)
                        }
                    }
                }),
            };
            devices.push(DeviceRef {
                element: elements.len(),
                device: di,
            });
            // Checked when the device was added.
            let law = d
                .law
                .law()
                .expect("a device law checked by Scenario::with_device");
            elements.push(Element::new(ends.0, ends.1, law));
        }
    }
    devices
}

/// The supports' displacements, for elements between structures on different supports: support `k`'s is
/// degree of freedom `base + k` (with supports that differ; `None` otherwise).
struct Supports {
    base: Option<usize>,
    building: Vec<usize>,
}

impl Supports {
    /// An end that moves with support `k` as well: a floor's displacement relative to its support plus the
    /// support's, the ground of support `k` its displacement.
    fn moved(&self, end: End, k: usize) -> End {
        let Some(base) = self.base else { return end };
        let g = base + k;
        match end {
            End::Ground => End::Dof(g),
            End::Dof(i) => End::Point(Point::new(&[(i, 1.0), (g, 1.0)])),
            End::Point(p) => {
                let mut t = p.terms().to_vec();
                t.push((g, 1.0));
                // Points of floors in plan (three terms) stand on the scenario's ground only.
                End::Point(Point::new(&t))
            }
        }
    }

    /// The ends `a` (on support `sa`) and `b` (on `sb`): as they are on one support, each with its support's
    /// displacement otherwise.
    fn join(&self, (a, sa): (End, usize), (b, sb): (End, usize)) -> (End, End) {
        if sa == sb {
            (a, b)
        } else {
            (self.moved(a, sa), self.moved(b, sb))
        }
    }

    /// The ends of an element of `site`: between two buildings on their supports, or a building and its wall
    /// on the wall's.
    fn site(&self, site: &ContactSite, (a, b): (End, End)) -> (End, End) {
        match site.kind {
            SiteKind::Between { left, right } => {
                self.join((a, self.building[left]), (b, self.building[right]))
            }
            SiteKind::Wall { building, side } if side.negative() => {
                self.join((a, site.support), (b, self.building[building]))
            }
            SiteKind::Wall { building, .. } => {
                self.join((a, self.building[building]), (b, site.support))
            }
        }
    }
}

/// The ends of a site's contact element at level `level` (an index in its levels): the left floor and the
/// right floor, or a floor and the ground (a wall on the positive side is end `b`; on the negative side, end
/// `a`). A floor in plan is its point of the façade, moving along the site's normal.
fn site_ends(s: &Scenario, site: &ContactSite, level: usize, offsets: &[usize]) -> (End, End) {
    let lv = site.levels[level];
    // A point across the gap has the same arm about the mass centre along the normal: the right
    // building's point is taken at the left façade's.
    let floor = |b: usize, f: Option<usize>| {
        let f = f.unwrap_or(1);
        match (s.buildings()[b].structure.plan(), &site.plan) {
            (Some(p), Some(sp)) => End::Point(p.point(f, offsets[b], sp.points[level], sp.normal)),
            _ => End::Dof(offsets[b] + f - 1),
        }
    };
    match site.kind {
        SiteKind::Between { left, right } => (floor(left, lv.left), floor(right, lv.right)),
        SiteKind::Wall { building, side } if side.negative() => {
            (End::Ground, floor(building, lv.right))
        }
        SiteKind::Wall { building, .. } => (floor(building, lv.left), End::Ground),
    }
}
