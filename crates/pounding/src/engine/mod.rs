//! The hybrid engine: degrees of freedom with masses, elements acting on them, one driver.
//!
//! A [`System`] is a set of degrees of freedom (horizontal displacements relative to the moving ground, m)
//! with their masses (kg) and mass-proportional damping (`a0`, 1/s), and [`Element`]s that join them to each
//! other or to the ground. Its equations of motion are
//! `m_i u_i'' = -m_i (a_g(t) + a0_i u_i') + sum of element forces`, a first-order system whose state is laid
//! out by [`Layout`]: displacements, velocities, input energy `-int a_g sum m_i u_i' dt`, viscous
//! damping energy, then each element's own states (Bouc–Wen's `z`, a contact's work).
//!
//! [`run`] steps it with the adaptive Dormand–Prince pair, ends steps at the kinks of the ground motion,
//! locates the earliest event of any element on the interpolant, applies it and restarts there. What a run
//! keeps is up to its [`Observer`]s. Single impacts ([`crate::impact::simulate`]) and pounding analyses
//! ([`crate::analysis`]) both run on it.

mod driver;
mod exact;
mod forms;
mod layout;
mod linear;
mod observe;
mod propagator;

pub use driver::{run, Ending, Outcome, Settings};
pub use layout::Layout;
pub use observe::{EventInfo, Observer, Segment};
pub use propagator::Propagation;

use crate::element::{Element, ElementLaw, End};
use crate::ground_motion::Record;
use crate::integrate::{Dense, DenseComponent, OdeSystem};

/// The ground's acceleration, m/s^2.
#[derive(Clone, Copy, Debug)]
pub enum Ground<'a> {
    /// A record along x, linear between samples (kinks at the samples) and 0 after its end.
    Record(&'a Record),
    /// Two records, along x and along y, on one time grid (the same first sample time and step; lengths
    /// their own, [`crate::ground_motion::on_one_grid`]).
    Plane {
        /// Along x.
        x: &'a Record,
        /// Along y.
        y: &'a Record,
    },
    /// Supports shaken each by its own record along x (multi-support excitation): record 0 is the
    /// scenario's; a degree of freedom of [`Axis::On`] `k` is shaken by record `k`, one of [`Axis::Driven`] `k`
    /// moves with it.
    Many(&'a [Record]),
    /// A constant acceleration along x (gravity pushing a body into a slab is `-g`).
    Constant(f64),
}

impl Ground<'_> {
    /// Ground acceleration along x at `t`, m/s^2.
    #[inline]
    pub fn at(&self, t: f64) -> f64 {
        match self {
            Ground::Record(r) | Ground::Plane { x: r, .. } => r.at(t),
            Ground::Many(rs) => rs[0].at(t),
            Ground::Constant(a) => *a,
        }
    }

    /// The records that shake the ground (none for a constant acceleration).
    pub fn records(&self) -> Vec<&Record> {
        match self {
            Ground::Record(r) => vec![r],
            Ground::Plane { x, y } => vec![x, y],
            Ground::Many(rs) => rs.iter().collect(),
            Ground::Constant(_) => Vec::new(),
        }
    }

    /// Ground acceleration along x and along y at `t`, m/s^2.
    #[inline]
    pub fn at_xy(&self, t: f64) -> (f64, f64) {
        match self {
            Ground::Plane { x, y } => (x.at(t), y.at(t)),
            other => (other.at(t), 0.0),
        }
    }
}

/// How a degree of freedom moves: along x, along y (the ground's two components push it), or a rotation about
/// the vertical axis (which the ground does not push).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Axis {
    /// A translation along x (every degree of freedom of a structure in one line).
    #[default]
    X,
    /// A translation along y.
    Y,
    /// A rotation about the vertical axis through the mass centre (its "mass" is a moment of inertia).
    Rotation,
    /// A translation along x shaken by record `k` of [`Ground::Many`] (a structure on support `k`).
    On(usize),
    /// A support's displacement along x: it moves as record `k` of [`Ground::Many`] from rest (its
    /// acceleration is prescribed; the elements' forces do not move it, and their power on it is input).
    Driven(usize),
}

/// A degree of freedom: its mass (kg; for a rotation its moment of inertia, kg m^2), mass-proportional
/// damping coefficient `a0` (1/s) and axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dof {
    /// Mass, kg (a rotation's moment of inertia, kg m^2).
    pub mass: f64,
    /// Mass-proportional damping `a0`: the force `-a0 m u'` acts between the degree of freedom and the
    /// ground, 1/s.
    pub a0: f64,
    /// Its axis.
    pub axis: Axis,
}

impl Dof {
    /// A translation along x of mass `mass` (kg) with mass-proportional damping `a0` (1/s).
    pub fn x(mass: f64, a0: f64) -> Self {
        Self {
            mass,
            a0,
            axis: Axis::X,
        }
    }
}

/// Energies of a state, J.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Energies {
    /// Input energy `-int a_g sum m u' dt`, J.
    pub input: f64,
    /// Kinetic energy of the relative motion, J.
    pub kinetic: f64,
    /// Recoverable strain energy of the storeys, J.
    pub strain: f64,
    /// Energy dissipated by viscous damping, J.
    pub damping: f64,
    /// Energy dissipated by the storeys' hysteresis, J.
    pub hysteretic: f64,
    /// Work of the contact forces, J.
    pub contact: f64,
}

impl Energies {
    /// `input - kinetic - strain - damping - hysteretic - contact`, J.
    pub fn imbalance(&self) -> f64 {
        self.input - self.kinetic - self.strain - self.damping - self.hysteretic - self.contact
    }
    /// The six terms in the order input, kinetic, strain, damping, hysteretic, contact, J.
    pub fn terms(&self) -> [f64; 6] {
        [
            self.input,
            self.kinetic,
            self.strain,
            self.damping,
            self.hysteretic,
            self.contact,
        ]
    }

    /// `kinetic + strain + damping + hysteretic + |contact|`, J: the scale of the balance.
    pub fn scale(&self) -> f64 {
        self.kinetic + self.strain + self.damping + self.hysteretic + self.contact.abs()
    }
}

/// Degrees of freedom, elements and the ground motion: the equations of motion.
#[derive(Clone, Debug)]
pub struct System<'a> {
    mass: Vec<f64>,
    inv_mass: Vec<f64>,
    a0: Vec<f64>,
    /// The ground's pull on each degree of freedom per unit mass: `(1, 0)` along x, `(0, 1)` along y,
    /// `(0, 0)` for a rotation (and for degrees of freedom of other supports, [`System::source`]).
    pull: Vec<(f64, f64)>,
    /// The record of [`Ground::Many`] that shakes (or drives) each degree of freedom, where it is not
    /// record 0 along x: `(k, driven)`.
    source: Vec<Option<(usize, bool)>>,
    axes: Vec<Axis>,
    /// The driven degrees of freedom.
    driven: Vec<usize>,
    elements: Vec<Element>,
    /// The elements acting on each degree of freedom (an end's term on it), in order.
    incident: Vec<Vec<usize>>,
    /// Each element's constant force's place among the constant forces of `w` ([`linear`]), if its law
    /// has one ([`crate::element::ElementLaw::constant_force`]).
    constants: Vec<Option<usize>>,
    layout: Layout,
    ground: Ground<'a>,
}

impl<'a> System<'a> {
    /// The system of `dofs` and `elements` under `ground`.
    pub fn new(dofs: &[Dof], elements: Vec<Element>, ground: Ground<'a>) -> Self {
        let layout = Layout::new(dofs.len(), elements.iter().map(Element::states));
        let driven = |d: &Dof| matches!(d.axis, Axis::Driven(_));
        Self {
            // A driven degree of freedom has no mass (no kinetic energy) and ignores forces.
            mass: dofs
                .iter()
                .map(|d| if driven(d) { 0.0 } else { d.mass })
                .collect(),
            inv_mass: dofs
                .iter()
                .map(|d| if driven(d) { 0.0 } else { 1.0 / d.mass })
                .collect(),
            a0: dofs.iter().map(|d| d.a0).collect(),
            pull: dofs
                .iter()
                .map(|d| match d.axis {
                    Axis::X => (1.0, 0.0),
                    Axis::Y => (0.0, 1.0),
                    Axis::Rotation | Axis::On(_) | Axis::Driven(_) => (0.0, 0.0),
                })
                .collect(),
            source: dofs
                .iter()
                .map(|d| match d.axis {
                    Axis::On(k) => Some((k, false)),
                    Axis::Driven(k) => Some((k, true)),
                    Axis::X | Axis::Y | Axis::Rotation => None,
                })
                .collect(),
            axes: dofs.iter().map(|d| d.axis).collect(),
            incident: (0..dofs.len())
                .map(|i| {
                    let on = |el: &Element| {
                        let (a, b) = (el.a.terms(), el.b.terms());
                        a.terms().iter().chain(b.terms()).any(|&(j, _)| j == i)
                    };
                    (0..elements.len()).filter(|&e| on(&elements[e])).collect()
                })
                .collect(),
            driven: (0..dofs.len()).filter(|&i| driven(&dofs[i])).collect(),
            constants: elements
                .iter()
                .scan(0, |count, el| {
                    Some(
                        crate::element::ElementLaw::constant_force(&el.law).then(|| {
                            *count += 1;
                            *count - 1
                        }),
                    )
                })
                .collect(),
            elements,
            layout,
            ground,
        }
    }

    /// The state layout.
    pub fn layout(&self) -> &Layout {
        &self.layout
    }
    /// Masses of the degrees of freedom, kg.
    pub fn masses(&self) -> &[f64] {
        &self.mass
    }
    /// The elements.
    pub fn elements(&self) -> &[Element] {
        &self.elements
    }
    /// The elements, to change their phase (the driver does this at events).
    pub fn elements_mut(&mut self) -> &mut [Element] {
        &mut self.elements
    }
    /// The ground's pull on degree of freedom `i` per unit mass: `(1, 0)` along x, `(0, 1)` along y, `(0, 0)`
    /// for a rotation.
    #[inline]
    pub fn pull(&self, i: usize) -> (f64, f64) {
        self.pull[i]
    }
    /// The axis of degree of freedom `i`.
    #[inline]
    pub fn axis(&self, i: usize) -> Axis {
        self.axes[i]
    }

    /// Whether degree of freedom `i` is shaken (or driven) by a record of [`Ground::Many`] other than the
    /// pull of [`System::pull`].
    #[inline]
    pub fn sourced(&self, i: usize) -> bool {
        self.source[i].is_some()
    }

    /// The ground's acceleration that shakes degree of freedom `i` at `t`, m/s^2 (0 for a rotation; a driven
    /// support's own acceleration).
    pub fn ground_at(&self, i: usize, t: f64) -> f64 {
        self.ground_from(i, t, self.ground.at_xy(t))
    }

    /// [`Self::ground_at`] with the record's accelerations `(g_x, g_y)` at `t` already read (m/s^2): a support
    /// of its own reads its record, any other degree of freedom takes them along its pull, written so that a
    /// floor in one line adds exactly `g_x`.
    #[inline]
    pub fn ground_from(&self, i: usize, t: f64, (gx, gy): (f64, f64)) -> f64 {
        match (self.source[i], self.ground) {
            (Some((k, _)), Ground::Many(rs)) => rs[k].at(t),
            _ => {
                let (px, py) = self.pull[i];
                if py == 0.0 {
                    px * gx
                } else {
                    px * gx + py * gy
                }
            }
        }
    }

    /// The ground motion.
    pub fn ground(&self) -> Ground<'a> {
        self.ground
    }

    /// The state components that may stay identically zero through a run and then count in no error norm
    /// ([`crate::integrate::Tolerance::quiet`]): the displacements and velocities of the degrees of freedom
    /// along y and in rotation, and the states of the elements acting on those alone (a symmetric plan
    /// shaken along x keeps them all at 0). None for structures in one line.
    pub fn quiet_components(&self) -> Vec<usize> {
        let l = &self.layout;
        let across = |i: usize| matches!(self.axes[i], Axis::Y | Axis::Rotation);
        let mut quiet: Vec<usize> = (0..l.dofs())
            .filter(|&i| across(i))
            .flat_map(|i| [l.u(i), l.v(i)])
            .collect();
        for (e, el) in self.elements.iter().enumerate() {
            let (ta, tb) = (el.a.terms(), el.b.terms());
            let mut terms = ta.terms().iter().chain(tb.terms());
            if terms.all(|&(i, _)| across(i)) && !(ta.terms().is_empty() && tb.terms().is_empty()) {
                quiet.extend(l.block(e));
            }
        }
        quiet.sort_unstable();
        quiet
    }

    /// The state components that accumulate a work over the whole run
    /// ([`crate::integrate::Tolerance::absolute`]): the elements' work states.
    pub fn work_components(&self) -> Vec<usize> {
        let l = &self.layout;
        self.elements
            .iter()
            .enumerate()
            .flat_map(|(e, el)| el.law.work_states().map(move |k| l.block(e).start + k))
            .collect()
    }

    /// Deformation `x = u_a - u_b` (m) and its rate (m/s) of element `e` in state `y`.
    #[inline(always)]
    pub fn deformation(&self, e: usize, y: &[f64]) -> (f64, f64) {
        let el = &self.elements[e];
        let n = self.layout.dofs();
        (
            el.a.value(y, 0) - el.b.value(y, 0),
            el.a.value(y, n) - el.b.value(y, n),
        )
    }

    /// The interpolants of the deformation and rate of element `e`, kept after the stepper moved on.
    pub fn deformation_interpolants(
        &self,
        e: usize,
        dense: &Dense,
    ) -> (DenseComponent, DenseComponent) {
        let el = &self.elements[e];
        let n = self.layout.dofs();
        match (el.a, el.b) {
            (End::Point(_), _) | (_, End::Point(_)) => {
                // The velocities' terms: the same weights, shifted past the displacements (no allocation).
                let shift = |p: crate::element::Point| {
                    let mut t = [(0, 0.0); 3];
                    for (s, &(i, c)) in t.iter_mut().zip(p.terms()) {
                        *s = (n + i, c);
                    }
                    crate::element::Point::new(&t[..p.terms().len()])
                };
                let (ta, tb) = (el.a.terms(), el.b.terms());
                (
                    dense.combination(ta.terms()) - dense.combination(tb.terms()),
                    dense.combination(shift(ta).terms()) - dense.combination(shift(tb).terms()),
                )
            }
            _ => {
                let (a, b) = (el.a.dof(), el.b.dof());
                (
                    dense.difference(a, b),
                    dense.difference(a.map(|i| n + i), b.map(|i| n + i)),
                )
            }
        }
    }

    /// Deformation and rate of element `e` on the interpolant at `t`.
    #[inline]
    pub fn deformation_at(&self, e: usize, dense: &Dense, t: f64) -> (f64, f64) {
        let el = &self.elements[e];
        let n = self.layout.dofs();
        let at = |end: End, off: usize| -> f64 {
            end.terms()
                .terms()
                .iter()
                .map(|&(i, c)| c * dense.component(t, off + i))
                .sum()
        };
        (at(el.a, 0) - at(el.b, 0), at(el.a, n) - at(el.b, n))
    }

    /// The force of element `e`'s law in state `y`, N.
    #[inline]
    pub fn element_force(&self, e: usize, y: &[f64]) -> f64 {
        let (x, v) = self.deformation(e, y);
        self.elements[e].force(x, v, &y[self.layout.block(e)])
    }

    /// Every energy of state `y`, J.
    pub fn energies(&self, y: &[f64]) -> Energies {
        let l = &self.layout;
        let mut out = Energies {
            input: y[l.input()],
            damping: y[l.damping()],
            ..Energies::default()
        };
        out.kinetic = 0.5
            * (0..l.dofs())
                .map(|i| self.mass[i] * y[l.v(i)] * y[l.v(i)])
                .sum::<f64>();
        for (e, el) in self.elements.iter().enumerate() {
            let (x, _) = self.deformation(e, y);
            let en = el.energy(x, &y[l.block(e)]);
            out.strain += en.strain;
            out.hysteretic += en.hysteretic;
            out.contact += en.contact;
            out.damping += en.damping;
        }
        out
    }
}

impl OdeSystem for System<'_> {
    fn dim(&self) -> usize {
        self.layout.dim()
    }

    fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64]) {
        self.rhs_in(t, self.ground.at_xy(t), y, dy);
    }
}

impl System<'_> {
    /// The right-hand side at `t` with the ground's accelerations along x and y given (m/s^2; supports of
    /// their own read their records at `t`).
    pub(crate) fn rhs_in(&self, t: f64, (agx, agy): (f64, f64), y: &[f64], dy: &mut [f64]) {
        let n = self.layout.dofs();
        dy[..n].copy_from_slice(&y[n..2 * n]);
        let (mut e_in, mut e_damp) = (0.0, 0.0);
        // Forces first (N), divided by the masses at the end.
        let (v, acc) = (&y[n..2 * n], &mut dy[n..2 * n]);
        let floors = self
            .mass
            .iter()
            .zip(&self.a0)
            .zip(&self.pull)
            .zip(v)
            .zip(acc);
        for (i, ((((&m, &a0), &pull), &vi), acc)) in floors.enumerate() {
            let ag = self.shaking(i, t, pull, (agx, agy));
            *acc = -m * (ag + a0 * vi);
            e_in -= ag * m * vi;
            e_damp += a0 * m * vi * vi;
        }
        for (e, el) in self.elements.iter().enumerate() {
            let (x, v) = self.deformation(e, y);
            let r = self.layout.block(e);
            let (f, fv) = el.evaluate(x, v, &y[r.clone()], &mut dy[r]);
            let total = f + fv;
            match el.a {
                End::Dof(a) => dy[n + a] -= total,
                End::Point(p) => p.terms().iter().for_each(|&(i, c)| dy[n + i] -= c * total),
                End::Ground => {}
            }
            match el.b {
                End::Dof(b) => dy[n + b] += total,
                End::Point(p) => p.terms().iter().for_each(|&(i, c)| dy[n + i] += c * total),
                End::Ground => {}
            }
            e_damp += fv * v;
        }
        // A driven support takes the elements' forces without moving for them: their power on it is work
        // the support does on the structure.
        for &i in &self.driven {
            e_in -= dy[n + i] * y[n + i];
        }
        for (a, &w) in dy[n..2 * n].iter_mut().zip(&self.inv_mass) {
            *a *= w;
        }
        if let Ground::Many(rs) = self.ground {
            for &i in &self.driven {
                if let Some((k, _)) = self.source[i] {
                    dy[n + i] = rs[k].at(t);
                }
            }
        }
        dy[self.layout.input()] = e_in;
        dy[self.layout.damping()] = e_damp;
    }

    /// The ground's acceleration on degree of freedom `i` of pull `(px, py)` at `t` in the right-hand side,
    /// m/s^2: its support's record, or the records' `(agx, agy)` along its pull.
    #[inline(always)]
    fn shaking(&self, i: usize, t: f64, (px, py): (f64, f64), (agx, agy): (f64, f64)) -> f64 {
        match (self.source[i], self.ground) {
            (Some((k, _)), Ground::Many(rs)) => rs[k].at(t),
            _ => px * agx + py * agy,
        }
    }

    /// The acceleration of degree of freedom `i` relative to the ground at `t` in state `y`, m/s^2 (rad/s^2
    /// for a rotation): its entry of the right-hand side, by the same arithmetic from the elements acting on
    /// it alone. `ds` is room for the states of the element with the most.
    pub fn acceleration(&self, i: usize, t: f64, y: &[f64], ds: &mut [f64]) -> f64 {
        let n = self.layout.dofs();
        if let (Some((k, true)), Ground::Many(rs)) = (self.source[i], self.ground) {
            return rs[k].at(t);
        }
        let (m, vi) = (self.mass[i], y[n + i]);
        let ag = self.shaking(i, t, self.pull[i], self.ground.at_xy(t));
        let mut acc = -m * (ag + self.a0[i] * vi);
        for &e in &self.incident[i] {
            let el = &self.elements[e];
            let (x, v) = self.deformation(e, y);
            let r = self.layout.block(e);
            let (f, fv) = el.evaluate(x, v, &y[r.clone()], &mut ds[..r.len()]);
            let total = f + fv;
            // As the right-hand side applies it, end a's terms first.
            for &(j, c) in el.a.terms().terms() {
                if j == i {
                    acc -= c * total;
                }
            }
            for &(j, c) in el.b.terms().terms() {
                if j == i {
                    acc += c * total;
                }
            }
        }
        acc * self.inv_mass[i]
    }
}
