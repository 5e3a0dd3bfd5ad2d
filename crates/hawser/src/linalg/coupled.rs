//! Lines (block-tridiagonal over their nodes) coupled through shared free points.
//!
//! One solver serves the consistent mass matrix of the dynamics (symmetric blocks) and the
//! stiffness Jacobian of Newton statics (non-symmetric blocks). Each line's interior is
//! eliminated by block Thomas; the free points are solved from their Schur complement, a small
//! dense system; then the interior is back-substituted. Cost O(nodes) + O(points³).

use super::{BlockTridiagonal, DenseLu};
use crate::math::{Mat3, Real, Vec3};

/// What an end node of a line is in the coupled system.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EndKind {
    /// Its unknown is known (fixed or prescribed end): the caller puts the value in `x`.
    Known,
    /// It is the free point with this index in [`CoupledSystem`].
    Free(usize),
}

/// The blocks of one line over its nodes 0..=N (N elements).
#[derive(Clone, Debug)]
pub struct LineBlocks {
    /// Diagonal blocks, one per node.
    pub diag: Vec<Mat3>,
    /// Block (row i+1, column i), one per element.
    pub lower: Vec<Mat3>,
    /// Block (row i, column i+1), one per element.
    pub upper: Vec<Mat3>,
    /// Right-hand side per node on input (known ends: their value); solution on output.
    pub x: Vec<Vec3>,
    /// End A kind.
    pub end_a: EndKind,
    /// End B kind.
    pub end_b: EndKind,
    /// Whether `lower`/`upper` hold non-zero blocks (false for a lumped mass matrix).
    pub coupled: bool,
    factor: BlockTridiagonal,
    response_a: Vec<Mat3>,
    response_b: Vec<Mat3>,
}

/// A singular block met while solving.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Singular {
    /// In a line's interior, at this node.
    Line {
        /// Line index.
        line: usize,
        /// Node index.
        node: usize,
    },
    /// In the shared-point system, at this point.
    Point(usize),
}

impl LineBlocks {
    /// Storage for a line of `elements` elements.
    pub fn new(elements: usize, end_a: EndKind, end_b: EndKind, coupled: bool) -> Self {
        let n = elements + 1;
        let interior = elements.saturating_sub(1);
        Self {
            diag: vec![Mat3::zeros(); n],
            lower: vec![Mat3::zeros(); elements],
            upper: vec![Mat3::zeros(); elements],
            x: vec![Vec3::zeros(); n],
            end_a,
            end_b,
            coupled,
            factor: BlockTridiagonal::with_capacity(interior.max(1)),
            response_a: vec![Mat3::zeros(); interior],
            response_b: vec![Mat3::zeros(); interior],
        }
    }

    /// Number of nodes N + 1.
    pub fn nodes(&self) -> usize {
        self.diag.len()
    }

    /// Zeroes the blocks (not the ends' kinds).
    pub fn clear(&mut self) {
        self.diag.iter_mut().for_each(|m| *m = Mat3::zeros());
        if self.coupled {
            self.lower.iter_mut().for_each(|m| *m = Mat3::zeros());
            self.upper.iter_mut().for_each(|m| *m = Mat3::zeros());
        }
    }
}

/// The shared-point part: per free point a diagonal block and right-hand side, and the dense
/// Schur-complement system.
#[derive(Clone, Debug)]
pub struct CoupledSystem {
    /// The points' own diagonal blocks (point mass, or the point's own stiffness).
    pub point_diag: Vec<Mat3>,
    /// The points' own right-hand sides on input; their solution on output.
    pub point_x: Vec<Vec3>,
    lu: DenseLu,
    b: Vec<Real>,
    tmp: Vec<Real>,
}

impl CoupledSystem {
    /// Storage for `points` free points.
    pub fn new(points: usize) -> Self {
        Self {
            point_diag: vec![Mat3::zeros(); points],
            point_x: vec![Vec3::zeros(); points],
            lu: DenseLu::new(3 * points),
            b: vec![0.0; 3 * points],
            tmp: vec![0.0; 3 * points],
        }
    }

    fn add_block(&mut self, p: usize, q: usize, m: &Mat3, sign: Real) {
        for r in 0..3 {
            for c in 0..3 {
                self.lu.add(3 * p + r, 3 * q + c, sign * m[(r, c)]);
            }
        }
    }

    /// Solves the whole system in place: every line's `x` and `point_x` become the solution.
    pub fn solve(&mut self, lines: &mut [LineBlocks]) -> Result<(), Singular> {
        let np = self.point_diag.len();
        self.lu.clear();
        for p in 0..np {
            let d = self.point_diag[p];
            self.add_block(p, p, &d, 1.0);
            for k in 0..3 {
                self.b[3 * p + k] = self.point_x[p][k];
            }
        }
        // 1. Eliminate each line's interior.
        for (li, line) in lines.iter_mut().enumerate() {
            let n = line.nodes() - 1; // elements
            let interior = n - 1;
            if interior > 0 {
                // Known ends move to the right-hand side.
                if line.end_a == EndKind::Known {
                    let xa = line.x[0];
                    line.x[1] -= line.lower[0] * xa;
                }
                if line.end_b == EndKind::Known {
                    let xb = line.x[n];
                    line.x[n - 1] -= line.upper[n - 1] * xb;
                }
                if line.coupled {
                    line.factor
                        .factor(
                            &line.diag[1..n],
                            &line.lower[1..n - 1],
                            &line.upper[1..n - 1],
                        )
                        .map_err(|k| Singular::Line {
                            line: li,
                            node: k + 1,
                        })?;
                    line.factor.solve(interior, &mut line.x[1..n]);
                    if let EndKind::Free(_) = line.end_a {
                        line.response_a.iter_mut().for_each(|m| *m = Mat3::zeros());
                        line.response_a[0] = line.lower[0];
                        line.factor.solve_blocks(interior, &mut line.response_a);
                    }
                    if let EndKind::Free(_) = line.end_b {
                        line.response_b.iter_mut().for_each(|m| *m = Mat3::zeros());
                        line.response_b[interior - 1] = line.upper[n - 1];
                        line.factor.solve_blocks(interior, &mut line.response_b);
                    }
                } else {
                    for i in 1..n {
                        line.x[i] = crate::math::solve3(&line.diag[i], &line.x[i])
                            .ok_or(Singular::Line { line: li, node: i })?;
                    }
                }
            }
            // 2. Contributions of this line to the point system.
            for (end, node, next) in [(line.end_a, 0usize, 1usize), (line.end_b, n, n - 1)] {
                let EndKind::Free(p) = end else { continue };
                let d = line.diag[node];
                self.add_block(p, p, &d, 1.0);
                for k in 0..3 {
                    self.b[3 * p + k] += line.x[node][k];
                }
                // Coupling block from the neighbouring node into this end's row.
                let c = if node == 0 {
                    line.upper[0]
                } else {
                    line.lower[n - 1]
                };
                if !line.coupled {
                    continue;
                }
                if interior == 0 {
                    // One element: the two ends couple directly.
                    let other = if node == 0 { line.end_b } else { line.end_a };
                    match other {
                        EndKind::Free(q) => self.add_block(p, q, &c, 1.0),
                        EndKind::Known => {
                            let xo = c * line.x[next];
                            for k in 0..3 {
                                self.b[3 * p + k] -= xo[k];
                            }
                        }
                    }
                    continue;
                }
                let j = next - 1; // interior index of the neighbour
                let g = c * line.x[next];
                for k in 0..3 {
                    self.b[3 * p + k] -= g[k];
                }
                if let EndKind::Free(q) = line.end_a {
                    let m = c * line.response_a[j];
                    self.add_block(p, q, &m, -1.0);
                }
                if let EndKind::Free(q) = line.end_b {
                    let m = c * line.response_b[j];
                    self.add_block(p, q, &m, -1.0);
                }
            }
        }
        // 3. Solve the points.
        if np > 0 {
            self.lu.factor().map_err(|k| Singular::Point(k / 3))?;
            self.lu.solve(&mut self.b, &mut self.tmp);
            for p in 0..np {
                self.point_x[p] = Vec3::new(self.b[3 * p], self.b[3 * p + 1], self.b[3 * p + 2]);
            }
        }
        // 4. Back-substitute the interiors and set the free ends.
        for line in lines.iter_mut() {
            let n = line.nodes() - 1;
            let interior = n - 1;
            let xa = match line.end_a {
                EndKind::Free(p) => Some(self.point_x[p]),
                EndKind::Known => None,
            };
            let xb = match line.end_b {
                EndKind::Free(p) => Some(self.point_x[p]),
                EndKind::Known => None,
            };
            if line.coupled && interior > 0 {
                for j in 0..interior {
                    let mut v = line.x[j + 1];
                    if let Some(xa) = xa {
                        v -= line.response_a[j] * xa;
                    }
                    if let Some(xb) = xb {
                        v -= line.response_b[j] * xb;
                    }
                    line.x[j + 1] = v;
                }
            }
            if let Some(xa) = xa {
                line.x[0] = xa;
            }
            if let Some(xb) = xb {
                line.x[n] = xb;
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{DMatrix, DVector};

    /// Two lines sharing a free point, one end fixed each, compared with a dense solve.
    #[test]
    fn matches_dense_assembly() {
        let f = |i: usize, r: usize, c: usize| ((i * 13 + r * 5 + c * 7) % 17) as f64 / 17.0 - 0.5;
        let mut lines = vec![
            LineBlocks::new(4, EndKind::Known, EndKind::Free(0), true),
            LineBlocks::new(3, EndKind::Free(0), EndKind::Free(1), true),
            LineBlocks::new(1, EndKind::Free(1), EndKind::Known, true),
        ];
        let mut seed = 0;
        for l in lines.iter_mut() {
            for m in l.diag.iter_mut() {
                seed += 1;
                *m = Mat3::from_fn(|r, c| f(seed, r, c)) + Mat3::identity() * 5.0;
            }
            for (lo, up) in l.lower.iter_mut().zip(l.upper.iter_mut()) {
                seed += 1;
                *lo = Mat3::from_fn(|r, c| f(seed, r, c));
                *up = Mat3::from_fn(|r, c| f(seed + 50, r, c));
            }
            for (i, x) in l.x.iter_mut().enumerate() {
                *x = Vec3::new(i as f64, 1.0 + seed as f64 * 0.1, -0.3);
            }
        }
        let mut sys = CoupledSystem::new(2);
        sys.point_diag = vec![Mat3::identity() * 2.0, Mat3::identity() * 3.0];
        sys.point_x = vec![Vec3::new(1.0, 2.0, 3.0), Vec3::new(-1.0, 0.5, 0.0)];
        // Dense reference: unknowns are interior nodes of each line then the two points.
        let mut index = vec![];
        let mut count = 0;
        for l in &lines {
            let n = l.nodes() - 1;
            let mut idx = vec![None; n + 1];
            for slot in idx.iter_mut().take(n).skip(1) {
                *slot = Some(count);
                count += 1;
            }
            index.push(idx);
        }
        let p0 = count;
        let dim = 3 * (count + 2);
        for (l, idx) in lines.iter().zip(index.iter_mut()) {
            let n = l.nodes() - 1;
            if let EndKind::Free(p) = l.end_a {
                idx[0] = Some(p0 + p);
            }
            if let EndKind::Free(p) = l.end_b {
                idx[n] = Some(p0 + p);
            }
        }
        let mut a = DMatrix::<f64>::zeros(dim, dim);
        let mut b = DVector::<f64>::zeros(dim);
        for p in 0..2 {
            a.view_mut((3 * (p0 + p), 3 * (p0 + p)), (3, 3))
                .copy_from(&sys.point_diag[p]);
            for k in 0..3 {
                b[3 * (p0 + p) + k] = sys.point_x[p][k];
            }
        }
        for (l, idx) in lines.iter().zip(index.iter()) {
            let n = l.nodes() - 1;
            for i in 0..=n {
                let Some(ri) = idx[i] else { continue };
                let mut blk = a.view_mut((3 * ri, 3 * ri), (3, 3)).clone_owned();
                blk += l.diag[i];
                a.view_mut((3 * ri, 3 * ri), (3, 3)).copy_from(&blk);
                for k in 0..3 {
                    b[3 * ri + k] += l.x[i][k];
                }
                for (j, m) in [
                    (i.wrapping_sub(1), i.checked_sub(1).map(|e| l.lower[e])),
                    (i + 1, (i < n).then(|| l.upper[i])),
                ] {
                    let Some(m) = m else { continue };
                    match idx.get(j).copied().flatten() {
                        Some(cj) => {
                            let mut blk = a.view_mut((3 * ri, 3 * cj), (3, 3)).clone_owned();
                            blk += m;
                            a.view_mut((3 * ri, 3 * cj), (3, 3)).copy_from(&blk);
                        }
                        None => {
                            let v = m * l.x[j];
                            for k in 0..3 {
                                b[3 * ri + k] -= v[k];
                            }
                        }
                    }
                }
            }
        }
        let xd = a.lu().solve(&b).unwrap();
        sys.solve(&mut lines).unwrap();
        for (l, idx) in lines.iter().zip(index.iter()) {
            for (i, slot) in idx.iter().enumerate() {
                if let Some(r) = slot {
                    for k in 0..3 {
                        assert!(
                            (l.x[i][k] - xd[3 * r + k]).abs() < 1e-11,
                            "{} vs {}",
                            l.x[i][k],
                            xd[3 * r + k]
                        );
                    }
                }
            }
        }
    }
}
