//! Where each quantity lives in the state vector.

use std::ops::Range;

/// The layout of the state vector of a [`super::System`]: displacements of the degrees of freedom (m),
/// their velocities (m/s), the input energy and the energy dissipated by viscous damping (J), then each
/// element's own states, element by element.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Layout {
    dofs: usize,
    /// Start of each element's block, and the end of the last.
    blocks: Vec<usize>,
}

impl Layout {
    /// The layout of `dofs` degrees of freedom and elements carrying `states[e]` states each.
    pub fn new(dofs: usize, states: impl IntoIterator<Item = usize>) -> Self {
        let mut blocks = vec![2 * dofs + 2];
        for s in states {
            let last = *blocks.last().expect("a start");
            blocks.push(last + s);
        }
        Self { dofs, blocks }
    }

    /// Number of degrees of freedom.
    pub fn dofs(&self) -> usize {
        self.dofs
    }
    /// Number of state components.
    pub fn dim(&self) -> usize {
        *self.blocks.last().expect("a start")
    }
    /// Index of the displacement of degree of freedom `i`.
    #[inline]
    pub fn u(&self, i: usize) -> usize {
        i
    }
    /// Index of the velocity of degree of freedom `i`.
    #[inline]
    pub fn v(&self, i: usize) -> usize {
        self.dofs + i
    }
    /// The velocities.
    #[inline]
    pub fn velocities(&self) -> Range<usize> {
        self.dofs..2 * self.dofs
    }
    /// Index of the input energy, J.
    #[inline]
    pub fn input(&self) -> usize {
        2 * self.dofs
    }
    /// Index of the energy dissipated by viscous damping, J.
    #[inline]
    pub fn damping(&self) -> usize {
        2 * self.dofs + 1
    }
    /// The states of element `e`.
    #[inline]
    pub fn block(&self, e: usize) -> Range<usize> {
        self.blocks[e]..self.blocks[e + 1]
    }
}
