//! The equations of motion of the row of buildings, as a first-order system for the stepper.
//!
//! State: floor displacements `u` (m, all buildings, left to right, floor 1 upwards), velocities `u'` (m/s),
//! then the integrated energies, J: input, structural damping, and the work of each contact element.

use super::Scenario;
use crate::contact::{ForceLaw, Phase, Tension, Turn};
use crate::ground_motion::Record;
use crate::integrate::OdeSystem;

/// One building's storeys in the global numbering.
pub(super) struct Storeys {
    pub offset: usize,
    pub k: Vec<f64>,
    pub a0: f64,
    pub a1: f64,
}

/// What a contact element is doing.
#[derive(Clone, Copy, Debug)]
pub(super) enum Engagement {
    /// Apart (or touching without force): waiting for `d` to exceed 0.
    Open,
    /// In contact with the law of the current impact.
    Contact {
        law: ForceLaw,
        phase: Phase,
        turn: Turn,
    },
    /// A clamped force reached zero while `d > 0`: no force until `d <= 0` (or the floors approach again).
    Released { law: ForceLaw, turn: Turn },
}

/// A contact element between floor `left` of one building and floor `right` of its right neighbour
/// (global degree-of-freedom indices).
pub(super) struct Element {
    pub link: usize,
    pub floors: (usize, usize),
    pub left: usize,
    pub right: usize,
    pub gap: f64,
    /// Effective mass of the two floors, kg.
    pub m_eff: f64,
    pub tension: Tension,
    pub state: Engagement,
}

pub(super) struct Dynamics<'a> {
    pub n: usize,
    pub mass: Vec<f64>,
    pub buildings: Vec<Storeys>,
    pub elements: Vec<Element>,
    pub record: &'a Record,
}

/// Index of the input energy in the state; structural damping follows, then the contact works.
pub(super) fn energy_index(n: usize) -> usize {
    2 * n
}

impl<'a> Dynamics<'a> {
    pub fn new(s: &'a Scenario) -> Self {
        let mut offset = 0;
        let mut mass = Vec::new();
        let mut offsets = Vec::new();
        let buildings = s
            .buildings()
            .iter()
            .map(|b| {
                let st = &b.structure;
                let (a0, a1) = st.rayleigh();
                offsets.push(offset);
                let out = Storeys {
                    offset,
                    k: st.stiffnesses().to_vec(),
                    a0,
                    a1,
                };
                mass.extend_from_slice(st.masses());
                offset += st.storeys();
                out
            })
            .collect();
        let mut elements = Vec::new();
        for (li, link) in s.links().iter().enumerate() {
            for &(fl, fr) in &link.floors {
                let (left, right) = (offsets[link.left] + fl - 1, offsets[link.right] + fr - 1);
                let (ml, mr) = (mass[left], mass[right]);
                elements.push(Element {
                    link: li,
                    floors: (fl, fr),
                    left,
                    right,
                    gap: link.gap,
                    m_eff: ml * mr / (ml + mr),
                    tension: link.contact.spec().tension(),
                    state: Engagement::Open,
                });
            }
        }
        Self {
            n: offset,
            mass,
            buildings,
            elements,
            record: s.record(),
        }
    }

    pub fn dim(&self) -> usize {
        2 * self.n + 2 + self.elements.len()
    }

    /// Penetration (m) and its rate (m/s) of element `e` in state `y`.
    #[inline]
    pub fn penetration(&self, e: usize, y: &[f64]) -> (f64, f64) {
        let el = &self.elements[e];
        (
            y[el.left] - y[el.right] - el.gap,
            y[self.n + el.left] - y[self.n + el.right],
        )
    }

    /// Contact force of element `e`, N (positive pushes the floors apart).
    #[inline]
    pub fn force(&self, e: usize, y: &[f64]) -> f64 {
        match self.elements[e].state {
            Engagement::Contact { law, phase, turn } => {
                let (d, v) = self.penetration(e, y);
                law.force(d, v, phase, &turn)
            }
            _ => 0.0,
        }
    }

    /// Kinetic and strain energy, J.
    pub fn mechanical_energy(&self, y: &[f64]) -> (f64, f64) {
        let n = self.n;
        let kinetic = 0.5
            * (0..n)
                .map(|i| self.mass[i] * y[n + i] * y[n + i])
                .sum::<f64>();
        let mut strain = 0.0;
        for b in &self.buildings {
            let mut below = 0.0;
            for (j, k) in b.k.iter().enumerate() {
                let u = y[b.offset + j];
                strain += 0.5 * k * (u - below) * (u - below);
                below = u;
            }
        }
        (kinetic, strain)
    }
}

impl OdeSystem for Dynamics<'_> {
    fn dim(&self) -> usize {
        Dynamics::dim(self)
    }

    fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64]) {
        let n = self.n;
        let ag = self.record.at(t);
        let (u, v) = (&y[..n], &y[n..2 * n]);
        dy[..n].copy_from_slice(v);
        let (mut e_in, mut e_damp) = (0.0, 0.0);
        for b in &self.buildings {
            let o = b.offset;
            let s = b.k.len();
            // Storey j joins floor j - 1 (ground for j = 0) and floor j.
            let (mut drift_below, mut rate_below) = (u[o], v[o]);
            for i in 0..s {
                let (drift_above, rate_above) = if i + 1 < s {
                    (u[o + i + 1] - u[o + i], v[o + i + 1] - v[o + i])
                } else {
                    (0.0, 0.0)
                };
                let k_above = if i + 1 < s { b.k[i + 1] } else { 0.0 };
                let ku = b.k[i] * drift_below - k_above * drift_above;
                let kv = b.k[i] * rate_below - k_above * rate_above;
                let m = self.mass[o + i];
                let vi = v[o + i];
                dy[n + o + i] = -(ku + b.a1 * kv) / m - b.a0 * vi - ag;
                e_in -= ag * m * vi;
                e_damp += b.a0 * m * vi * vi + b.a1 * b.k[i] * rate_below * rate_below;
                (drift_below, rate_below) = (drift_above, rate_above);
            }
        }
        let ei = energy_index(n);
        dy[ei] = e_in;
        dy[ei + 1] = e_damp;
        for (e, el) in self.elements.iter().enumerate() {
            let f = self.force(e, y);
            dy[n + el.left] -= f / self.mass[el.left];
            dy[n + el.right] += f / self.mass[el.right];
            dy[ei + 2 + e] = f * (v[el.left] - v[el.right]);
        }
    }
}
