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
mod layout;
mod observe;

pub use driver::{run, Ending, Outcome, Settings};
pub use layout::Layout;
pub use observe::{EventInfo, Observer, Segment};

use crate::element::{Element, End};
use crate::ground_motion::Record;
use crate::integrate::{Dense, DenseComponent, OdeSystem};

/// The ground's acceleration, m/s^2.
#[derive(Clone, Copy, Debug)]
pub enum Ground<'a> {
    /// A record, linear between samples (kinks at the samples) and 0 after its end.
    Record(&'a Record),
    /// A constant acceleration (gravity pushing a body into a slab is `-g`).
    Constant(f64),
}

impl Ground<'_> {
    /// Ground acceleration at `t`, m/s^2.
    #[inline]
    pub fn at(&self, t: f64) -> f64 {
        match self {
            Ground::Record(r) => r.at(t),
            Ground::Constant(a) => *a,
        }
    }
}

/// A degree of freedom: its mass (kg) and mass-proportional damping coefficient `a0` (1/s).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dof {
    /// Mass, kg.
    pub mass: f64,
    /// Mass-proportional damping `a0`: the force `-a0 m u'` acts between the degree of freedom and the
    /// ground, 1/s.
    pub a0: f64,
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
    elements: Vec<Element>,
    layout: Layout,
    ground: Ground<'a>,
}

impl<'a> System<'a> {
    /// The system of `dofs` and `elements` under `ground`.
    pub fn new(dofs: &[Dof], elements: Vec<Element>, ground: Ground<'a>) -> Self {
        let layout = Layout::new(dofs.len(), elements.iter().map(Element::states));
        Self {
            mass: dofs.iter().map(|d| d.mass).collect(),
            inv_mass: dofs.iter().map(|d| 1.0 / d.mass).collect(),
            a0: dofs.iter().map(|d| d.a0).collect(),
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
    /// The ground motion.
    pub fn ground(&self) -> Ground<'a> {
        self.ground
    }

    /// Deformation `x = u_a - u_b` (m) and its rate (m/s) of element `e` in state `y`.
    #[inline]
    pub fn deformation(&self, e: usize, y: &[f64]) -> (f64, f64) {
        let el = &self.elements[e];
        let n = self.layout.dofs();
        let at = |end: End, off: usize| end.dof().map_or(0.0, |i| y[off + i]);
        (at(el.a, 0) - at(el.b, 0), at(el.a, n) - at(el.b, n))
    }

    /// The interpolants of the deformation and rate of element `e`, kept after the stepper moved on.
    pub fn deformation_interpolants(
        &self,
        e: usize,
        dense: &Dense,
    ) -> (DenseComponent, DenseComponent) {
        let el = &self.elements[e];
        let n = self.layout.dofs();
        let (a, b) = (el.a.dof(), el.b.dof());
        (
            dense.difference(a, b),
            dense.difference(a.map(|i| n + i), b.map(|i| n + i)),
        )
    }

    /// Deformation and rate of element `e` on the interpolant at `t`.
    #[inline]
    pub fn deformation_at(&self, e: usize, dense: &Dense, t: f64) -> (f64, f64) {
        let el = &self.elements[e];
        let n = self.layout.dofs();
        let at = |end: End, off: usize| end.dof().map_or(0.0, |i| dense.component(t, off + i));
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
        let n = self.layout.dofs();
        let ag = self.ground.at(t);
        dy[..n].copy_from_slice(&y[n..2 * n]);
        let (mut e_in, mut e_damp) = (0.0, 0.0);
        // Forces first (N), divided by the masses at the end.
        for i in 0..n {
            let (m, vi) = (self.mass[i], y[n + i]);
            dy[n + i] = -m * (ag + self.a0[i] * vi);
            e_in -= ag * m * vi;
            e_damp += self.a0[i] * m * vi * vi;
        }
        for (e, el) in self.elements.iter().enumerate() {
            let (x, v) = self.deformation(e, y);
            let r = self.layout.block(e);
            let (f, fv) = el.evaluate(x, v, &y[r.clone()], &mut dy[r]);
            let total = f + fv;
            if let End::Dof(a) = el.a {
                dy[n + a] -= total;
            }
            if let End::Dof(b) = el.b {
                dy[n + b] += total;
            }
            e_damp += fv * v;
        }
        for i in 0..n {
            dy[n + i] *= self.inv_mass[i];
        }
        dy[self.layout.input()] = e_in;
        dy[self.layout.damping()] = e_damp;
    }
}
