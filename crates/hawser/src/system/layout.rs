//! Where each object's unknowns sit in the state vector.

/// Where each object's unknowns sit in the state vector.
#[derive(Clone, Debug, PartialEq)]
pub struct Layout {
    /// Offset of each line's block: 3·m coordinates then 3·m rates.
    pub line_offset: Vec<usize>,
    /// Interior vector count m of each line (`fe`: N − 1 nodes; `hermite`: 2N; `dg`: 0, its
    /// block is modal coefficients).
    pub line_interior: Vec<usize>,
    /// Length of each line's block (6m, or the `dg` line's state length).
    pub line_len: Vec<usize>,
    /// Offset of each free point's block (position then velocity), `None` otherwise.
    pub point_offset: Vec<Option<usize>>,
    /// Offset of each free body's block ([`crate::bodies::STATE_LEN`] entries: position,
    /// quaternion, velocity, angular velocity), `None` otherwise.
    pub body_offset: Vec<Option<usize>>,
    /// Total length.
    pub len: usize,
}

impl Layout {
    /// The entries of line `line`'s block.
    #[inline]
    pub fn line_range(&self, line: usize) -> std::ops::Range<usize> {
        self.line_offset[line]..self.line_offset[line] + self.line_len[line]
    }

    /// The entries of point `point`'s block (position then velocity), `None` unless it is
    /// free.
    #[inline]
    pub fn point_range(&self, point: usize) -> Option<std::ops::Range<usize>> {
        self.point_offset[point].map(|o| o..o + 6)
    }

    /// The entries of body `body`'s block, `None` unless it is free.
    #[inline]
    pub fn body_range(&self, body: usize) -> Option<std::ops::Range<usize>> {
        self.body_offset[body].map(|o| o..o + crate::bodies::STATE_LEN)
    }

    /// Every second-order block of the state as (offset, node count): each `fe` or `hermite`
    /// line's interior nodes, then each free point (one node). A block holds 3·count
    /// positions then 3·count velocities. `dg` blocks (first order) are not listed.
    pub fn blocks(&self) -> impl Iterator<Item = (usize, usize)> + '_ {
        self.line_offset
            .iter()
            .copied()
            .zip(self.line_interior.iter().copied())
            .chain(self.point_offset.iter().flatten().map(|&o| (o, 1)))
    }
}
