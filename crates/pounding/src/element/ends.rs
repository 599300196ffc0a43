//! An element: a law between two ends, each a degree of freedom or the ground.

use super::{ElementEnergy, ElementLaw, Event, Law, Transition, Watch};
use crate::Error;

/// One end of an element: a degree of freedom (its index in the structure), a point of a rigid floor, or
/// the ground.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum End {
    /// The (moving) ground: displacement 0 relative to itself.
    Ground,
    /// Degree of freedom `i`.
    Dof(usize),
    /// A point of a floor that moves in plan: its displacement along a direction is a weighted sum of the
    /// floor's degrees of freedom ([`Point`]).
    Point(Point),
}

/// The displacement of a point of a rigid floor along a direction `n`: `sum c_k u_k` over at most three of
/// the floor's degrees of freedom (for a point `r` from the floor's mass centre, `n_x u_x + n_y u_y +
/// (r x n) theta`: coefficients dimensionless for the translations, m for the rotation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Point {
    terms: [(usize, f64); 3],
    len: usize,
}

impl Point {
    /// The point of `terms` `(degree of freedom, coefficient)`, at most three (the rest are dropped).
    pub fn new(terms: &[(usize, f64)]) -> Self {
        // Unused slots repeat the first degree of freedom with weight 0, so that a value reads all three
        // without a branch.
        let first = terms.first().map_or(0, |t| t.0);
        let mut t = [(first, 0.0); 3];
        let len = terms.len().min(3);
        t[..len].copy_from_slice(&terms[..len]);
        Self { terms: t, len }
    }

    /// `sum c_k y[offset + i_k]`: the point's displacement (or velocity) in `y`, all three slots read (a
    /// point of no terms reads 0).
    #[inline(always)]
    pub fn value(&self, y: &[f64], offset: usize) -> f64 {
        if self.len == 0 {
            return 0.0;
        }
        let [(i0, c0), (i1, c1), (i2, c2)] = self.terms;
        c0 * y[offset + i0] + c1 * y[offset + i1] + c2 * y[offset + i2]
    }

    /// Its terms.
    #[inline]
    pub fn terms(&self) -> &[(usize, f64)] {
        &self.terms[..self.len]
    }
}

impl End {
    /// The degree of freedom, if the end is one (not the ground, nor a point of a floor).
    pub fn dof(self) -> Option<usize> {
        match self {
            End::Dof(i) => Some(i),
            End::Ground | End::Point(_) => None,
        }
    }

    /// The end's displacement as `(degree of freedom, coefficient)` terms: none for the ground, `(i, 1)` for a
    /// degree of freedom.
    #[inline]
    pub fn terms(&self) -> Point {
        match *self {
            End::Ground => Point::new(&[]),
            End::Dof(i) => Point::new(&[(i, 1.0)]),
            End::Point(p) => p,
        }
    }

    /// The end's value in the vector `y` whose degrees of freedom start at `offset` (its displacement for
    /// the displacements' offset, its velocity for the velocities').
    #[inline]
    pub fn value(&self, y: &[f64], offset: usize) -> f64 {
        match self {
            End::Ground => 0.0,
            End::Dof(i) => y[offset + i],
            End::Point(p) => p.value(y, offset),
        }
    }
}

/// An element: two ends, a law, and a linear dashpot in parallel with it. Its deformation is
/// `x = u_a - u_b` (m); its force resists a growing `x`: it acts as `-f` on end `a` and `+f` on end `b`.
#[derive(Clone, Debug)]
pub struct Element {
    /// End `a` (deformation `x = u_a - u_b`).
    pub a: End,
    /// End `b`.
    pub b: End,
    /// The element's law, with its phase.
    pub law: Law,
    /// Coefficient of a linear dashpot in parallel with the law, N s/m: a storey's Rayleigh damping on its
    /// initial stiffness (`a1 k`), an isolator's own damping; 0 for most elements.
    pub c: f64,
}

impl Element {
    /// An element of `law` between `a` and `b`, without a parallel dashpot.
    pub fn new(a: End, b: End, law: impl Into<Law>) -> Self {
        Self {
            a,
            b,
            law: law.into(),
            c: 0.0,
        }
    }

    /// The same element with a linear dashpot of `c` (N s/m) in parallel.
    pub fn with_dashpot(mut self, c: f64) -> Self {
        self.c = c;
        self
    }

    /// Number of extra ODE states the element carries.
    pub fn states(&self) -> usize {
        self.law.states()
    }

    /// The element's forces at deformation `x` (m), rate `v` (m/s) and states `s`: `(f, f_viscous)`, N, the
    /// force of its law and the viscous force of the law and the parallel dashpot; the rates of its states
    /// go to `ds`.
    #[inline]
    pub fn evaluate(&self, x: f64, v: f64, s: &[f64], ds: &mut [f64]) -> (f64, f64) {
        let (f, fv) = self.law.evaluate(x, v, s, ds);
        (f, fv + self.c * v)
    }

    /// The force of the element's law as reported (without viscous forces), N.
    #[inline]
    pub fn force(&self, x: f64, v: f64, s: &[f64]) -> f64 {
        self.law.force(x, v, s)
    }

    /// Energy held or dissipated by the element's law, J (the viscous forces' is integrated by the engine).
    #[inline]
    pub fn energy(&self, x: f64, s: &[f64]) -> ElementEnergy {
        self.law.energy(x, s)
    }

    /// The element's force (law and parallel dashpot) in its law's current phase as an affine function of
    /// deformation and rate, if it is one.
    #[inline]
    pub fn affine(&self) -> Option<super::Affine> {
        self.law.affine().map(|a| super::Affine {
            c: a.c + self.c,
            viscous: a.viscous + self.c,
            ..a
        })
    }

    /// The events watched in the current phase.
    pub fn watched(&self) -> &'static [Watch] {
        self.law.watched()
    }

    /// Event function of `ev`: positive before the event, <= 0 at and after it.
    #[inline]
    pub fn event_value(&self, ev: Event, x: f64, v: f64, s: &[f64]) -> f64 {
        self.law.event_value(ev, x, v, s)
    }

    /// Applies `ev` at deformation `x`, rate `v` and states `s`; `h` is the integrator's next step, s.
    pub fn apply(
        &mut self,
        ev: Event,
        x: f64,
        v: f64,
        s: &[f64],
        h: f64,
    ) -> Result<Transition, Error> {
        self.law.apply(ev, x, v, s, h)
    }

    /// Sets the resolution of the deformation rate, m/s ([`super::RateGate`]).
    pub fn set_rate_resolution(&mut self, v_res: f64) {
        if let Some(g) = self.law.gate_mut() {
            g.set_resolution(v_res);
        }
    }

    /// Arms the next change of direction once its rate is clear of 0, at deformation `x` (m), rate `v`
    /// (m/s) and states `s` (called after every step while disarmed); returns whether it is still disarmed.
    #[inline]
    pub fn rearm(&mut self, x: f64, v: f64, s: &[f64]) -> bool {
        let g = self.law.rate_event(x, v, s);
        match self.law.gate_mut() {
            Some(gate) => {
                gate.rearm(g);
                !gate.armed()
            }
            None => false,
        }
    }

    /// Whether the next change of direction is located at a rate of exactly 0 ([`super::RateGate`]).
    pub fn armed(&self) -> bool {
        self.law.gate().is_none_or(|g| g.armed())
    }
}
