//! The explicit three-time-level scheme of the elastic-link paper (eqs. 35–47) with variable
//! steps, a two-stage predictor and corrector.
//!
//! The equations of motion of every unknown node i (interior line nodes and free points) are
//! M₁ ë_{i−1} + M₂ ë_i + M₃ ë_{i+1} = F_i(e, ė, t) (eq. 34, with the elastic and external forces
//! in F), M₂ the node's diagonal mass block and M₁, M₃ the blocks that couple it to its
//! neighbours (zero for lumped mass). The second derivative at level n is the three-level
//! difference with unequal steps Δt_n = t_n − t_{n−1}, Δt_{n+1} = t_{n+1} − t_n (eqs. 35–42):
//!
//!   ë^n ≈ C_t2 e^{n+1} − C_t1 e^n + C_t0 e^{n−1},
//!   C_t0 = 2 / ((Δt_n + Δt_{n+1}) Δt_n), C_t1 = 2 / (Δt_{n+1} Δt_n),
//!   C_t2 = 2 / ((Δt_n + Δt_{n+1}) Δt_{n+1}).
//!
//! **Predictor** (eqs. 44–45): ã_i = M̄_i⁻¹ F_i(e^n), and
//! ẽ^{n+1} = (ã + C_t1 e^n − C_t0 e^{n−1}) / C_t2, with M̄_i = M₁ + M₂ + M₃ the row sum of the
//! node's mass blocks. The paper drops M₁ and M₃ here (M̄ = M₂). With a lumped mass the two
//! are the same. With a consistent mass the paper's choice makes the single corrector below
//! wrong by a fixed fraction of the acceleration: for a uniform acceleration field of linear
//! elements M₁ + M₃ = ½M₂, and â = M₂⁻¹(F − ½M₂ M₂⁻¹F) = ½M₂⁻¹F instead of the exact
//! (1.5 M₂)⁻¹F = ⅔M₂⁻¹F, an error that does not shrink with the step (measured in
//! tests/three_level.rs before this change). With the row sum the corrector is exact for a
//! uniform field (â = M₂⁻¹(F − ½M₂ (1.5M₂)⁻¹F) = ⅔M₂⁻¹F) and the scheme consistent.
//! **Corrector** (eqs. 46–47): the forces are taken at the predicted level n+1 and the coupling
//! blocks act on the predicted accelerations of the neighbours,
//! â_i = M₂⁻¹ (F_i(ẽ^{n+1}) − M₁ ã_{i−1} − M₃ ã_{i+1}), and e^{n+1} = (â + C_t1 e^n − C_t0 e^{n−1}) / C_t2.
//!
//! **Hermite lines.** The node-by-node corrector is one Jacobi sweep on the mass matrix. For
//! cubic Hermite elements the coupling of a node's tangent to its neighbours' is strong (the
//! beam mass matrix's tangent entries 4l² per element against 3l² to the neighbour: a Jacobi
//! spectral radius near 0.75 where linear elements have 0.5), so one sweep leaves much of the
//! coupling unresolved. With a `hermite` line in the system both stages therefore solve the
//! banded mass system exactly, ã = M⁻¹F(e^n) and â = M⁻¹F(ẽ^{n+1}), in O(N) by
//! [`crate::linalg::CoupledSystem`]: the same time levels and the same predictor–corrector,
//! with the paper's "inverse matrix method" applied to the whole mass matrix.
//!
//! Two choices the paper leaves open, derived here and documented in docs/fe.md:
//! - the velocities the forces need (drag, damping) are ė^n = (e^n − e^{n−1})/Δt_n + ½Δt_n â^{n−1}
//!   (the backward difference, a velocity at t_{n−½}, advanced by half a step with the last
//!   acceleration) and at the predicted level ė^{n+1} = (ẽ^{n+1} − e^n)/Δt_{n+1} + ½Δt_{n+1} ã;
//! - the first step starts from e^{−1} = e^0 − Δt v^0 + ½Δt² a^0, the Taylor start of the
//!   central difference.
//!
//! Because the corrector evaluates the forces at the predicted level n+1 rather than at n
//! (the paper's "regularisation" after Abarbanel and Zvas), the scheme is first-order accurate
//! and dissipative; `crates/hawser/tests/three_level.rs` measures both.
//!
//! The step (eq. 48) is Δt ≤ C_k l / c over all elements, with c the fastest wave in the
//! element: the paper's eq. 49 prints √(T/ρ_l), the transverse speed; the axial speed
//! √(EA/γ0) is faster in every taut cable and is what limits an explicit scheme, so the larger
//! of the two is used ([`System::wave_step`]). On ẍ = −ω²x the predictor–corrector gives
//! x^{n+1} = (2 − 2h² + h⁴) x^n − (1 − h²) x^{n−1} with h = ωΔt, stable for h ≤ 1; the highest
//! mode of a lumped element chain has ω = 2c/l, so C_k must be at most ½ (the paper allows 1).
//! The run takes the smaller of this step and the stiffness-and-damping bound of
//! [`System::stable_step`] (radius 1), which also covers seabed contact and a consistent mass.

use crate::linalg::EndKind;
use crate::math::{Mat3, Real, Vec3, get3, set3, solve3};
use crate::system::{Location, System, Workspace};

/// The three-level integrator: the previous level and per-node accelerations, sized once.
#[derive(Clone, Debug)]
pub struct ThreeLevel {
    /// Positions at level n − 1 (state layout; velocity entries unused).
    previous: Vec<Real>,
    /// The predicted state at level n + 1.
    trial: Vec<Real>,
    /// Predicted accelerations ã (state layout, position entries).
    predicted: Vec<Real>,
    /// Corrected accelerations â of the last step (state layout, position entries).
    accelerations: Vec<Real>,
    /// Δt_n of the last step (0 before the first).
    last_step: Real,
    /// Per free point: its mass with the line ends' blocks, and its force.
    point_mass: Vec<Mat3>,
    point_force: Vec<Vec3>,
    /// Whether each stage solves the mass system exactly (a `hermite` line is present).
    exact_mass: bool,
}

/// Which accelerations of the neighbours enter a node's equation.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Stage {
    /// Predictor: no coupling.
    Predictor,
    /// Corrector: coupling through the predicted accelerations.
    Corrector,
}

impl ThreeLevel {
    /// Integrator for `system`, whose state has length `n`.
    pub fn new(system: &System, n: usize) -> Self {
        let points = system.free_points.len();
        Self {
            previous: vec![0.0; n],
            trial: vec![0.0; n],
            predicted: vec![0.0; n],
            accelerations: vec![0.0; n],
            last_step: 0.0,
            point_mass: vec![Mat3::zeros(); points],
            point_force: vec![Vec3::zeros(); points],
            exact_mass: system
                .lines
                .iter()
                .any(|l| l.discretisation.bandwidth() > 1),
        }
    }

    /// What the next step needs of the past: the positions at level n − 1 (state layout) and
    /// the last step Δt_n [s] (0 before the first step).
    pub fn history(&self) -> (&[Real], Real) {
        (&self.previous, self.last_step)
    }

    /// Sets the history ([`ThreeLevel::history`]) of a saved run.
    pub fn set_history(&mut self, previous: &[Real], last_step: Real) {
        self.previous.copy_from_slice(previous);
        self.last_step = last_step;
    }

    /// Force evaluations per step.
    pub fn evaluations(&self) -> usize {
        2
    }

    /// Forgets the previous level, so that the next step starts as the first one does (the
    /// Taylor start e^{−1} = e^0 − Δt v^0 + ½Δt² a^0 from the state's positions and
    /// velocities): after a line failure, whose release moves a line end onto a free point of
    /// its own, the previous level no longer belongs to the system being stepped
    /// ([`crate::session`]'s failures).
    pub fn restart(&mut self) {
        self.last_step = 0.0;
    }

    /// The accelerations of one stage: node by node as the paper does for block-tridiagonal
    /// lines (`fe`), or by the exact banded mass solve when a line's mass couples more than
    /// its neighbours (`hermite`, see the module doc).
    fn stage(&mut self, system: &System, ws: &mut Workspace, stage: Stage) -> Result<(), Location> {
        if !self.exact_mass {
            return self.accelerations(system, ws, stage);
        }
        ws.coupled
            .solve(&mut ws.blocks)
            .map_err(|s| system.singular_location(s))?;
        let out = match stage {
            Stage::Predictor => &mut self.predicted,
            Stage::Corrector => &mut self.accelerations,
        };
        for (li, l) in system.lines.iter().enumerate() {
            let o = system.layout.line_offset[li];
            for i in 1..l.vectors() - 1 {
                set3(&mut out[o..], i - 1, &ws.blocks[li].x[i]);
            }
        }
        for (f, &p) in system.free_points.iter().enumerate() {
            let o = system.layout.point_offset[p].expect("free point");
            set3(&mut out[o..], 0, &ws.coupled.point_x[f]);
        }
        Ok(())
    }

    /// Node accelerations from an assembled workspace into `out` (position entries):
    /// predictor with the row-sum masses, corrector with the neighbours' `predicted`
    /// accelerations.
    fn accelerations(
        &mut self,
        system: &System,
        ws: &Workspace,
        stage: Stage,
    ) -> Result<(), Location> {
        let Self {
            predicted,
            accelerations,
            point_mass,
            point_force,
            ..
        } = self;
        // The predictor writes ã and reads no neighbour; the corrector reads ã, writes â.
        let (out, predicted): (&mut [Real], &[Real]) = match stage {
            Stage::Predictor => (predicted, &[]),
            Stage::Corrector => (accelerations, predicted),
        };
        let neighbour = |li: usize, node: usize| -> Vec3 {
            let l = &system.lines[li];
            let n = l.vectors() - 1;
            if node == 0 || node == n {
                let p = if node == 0 { l.end_a } else { l.end_b };
                match system.layout.point_offset[p] {
                    Some(o) => get3(&predicted[o..], 0),
                    None => ws.points[p].acceleration,
                }
            } else {
                get3(&predicted[system.layout.line_offset[li]..], node - 1)
            }
        };
        point_mass.copy_from_slice(&ws.coupled.point_diag);
        point_force.copy_from_slice(&ws.coupled.point_x);
        for (li, l) in system.lines.iter().enumerate() {
            let n = l.vectors() - 1;
            let o = system.layout.line_offset[li];
            let b = &ws.blocks[li];
            let f = &ws.lines[li].force;
            for i in 1..n {
                let mut rhs = f[i];
                let mut mass = b.diag[i];
                match stage {
                    Stage::Predictor => mass += b.lower[i - 1] + b.upper[i],
                    Stage::Corrector => {
                        rhs -= b.lower[i - 1] * neighbour(li, i - 1)
                            + b.upper[i] * neighbour(li, i + 1)
                    }
                }
                let a = solve3(&mass, &rhs).ok_or_else(|| Location {
                    object: l.name.clone(),
                    node: i,
                })?;
                set3(&mut out[o..], i - 1, &a);
            }
            // The ends on free points: their blocks join the point's equation.
            for (kind, end, inner, coupling) in [
                (b.end_a, 0, 1, &b.upper[0]),
                (b.end_b, n, n - 1, &b.lower[n - 1]),
            ] {
                if let EndKind::Free(fi) = kind {
                    point_mass[fi] += b.diag[end];
                    point_force[fi] += f[end];
                    match stage {
                        Stage::Predictor => point_mass[fi] += coupling,
                        Stage::Corrector => point_force[fi] -= coupling * neighbour(li, inner),
                    }
                }
            }
        }
        for (fi, &p) in system.free_points.iter().enumerate() {
            let a = solve3(&point_mass[fi], &point_force[fi]).ok_or_else(|| Location {
                object: system.points[p].name.clone(),
                node: 0,
            })?;
            let o = system.layout.point_offset[p].expect("free point");
            set3(&mut out[o..], 0, &a);
        }
        Ok(())
    }

    /// Applies e^{n+1} = (a + C_t1 e^n − C_t0 e^{n−1}) / C_t2 to every position entry of `y`
    /// (level n) into `next`, and the velocity estimate at n+1 into its velocity entries.
    fn advance(
        system: &System,
        levels: (&[Real], &[Real]),
        acc: &[Real],
        steps: (Real, Real),
        next: &mut [Real],
    ) {
        let (y, previous) = levels;
        let (dt_n, dt) = steps;
        let c0 = 2.0 / ((dt_n + dt) * dt_n);
        let c1 = 2.0 / (dt * dt_n);
        let c2 = 2.0 / ((dt_n + dt) * dt);
        for (o, count) in system.layout.blocks() {
            for i in 0..count {
                let e = get3(&y[o..], i);
                let a = get3(&acc[o..], i);
                let en = (a + e * c1 - get3(&previous[o..], i) * c0) / c2;
                set3(&mut next[o..], i, &en);
                set3(
                    &mut next[o + 3 * count..],
                    i,
                    &((en - e) / dt + a * (0.5 * dt)),
                );
            }
        }
    }

    /// Advances y (positions and the velocity estimate) from t to t + dt.
    pub fn step(
        &mut self,
        system: &System,
        ws: &mut Workspace,
        t: Real,
        dt: Real,
        y: &mut [Real],
    ) -> Result<(), Location> {
        // Level n: forces and masses, predictor accelerations.
        system.assemble(t, y, ws);
        self.stage(system, ws, Stage::Predictor)?;
        if self.last_step == 0.0 {
            // Taylor start: e^{-1} = e^0 − Δt v^0 + ½Δt² a^0, with Δt_0 = Δt.
            self.previous.copy_from_slice(y);
            for (o, count) in system.layout.blocks() {
                for i in 0..count {
                    let e = get3(&y[o..], i);
                    let v = get3(&y[o + 3 * count..], i);
                    let a = get3(&self.predicted[o..], i);
                    set3(
                        &mut self.previous[o..],
                        i,
                        &(e - v * dt + a * (0.5 * dt * dt)),
                    );
                }
            }
            self.last_step = dt;
        }
        let steps = (self.last_step, dt);
        Self::advance(
            system,
            (y, &self.previous),
            &self.predicted,
            steps,
            &mut self.trial,
        );
        // Level n+1 predicted: forces there, corrector accelerations.
        system.assemble(t + dt, &self.trial, ws);
        self.stage(system, ws, Stage::Corrector)?;
        Self::advance(
            system,
            (y, &self.previous),
            &self.accelerations,
            steps,
            &mut self.trial,
        );
        // Shift levels: n − 1 ← n, n ← n + 1.
        self.previous.copy_from_slice(y);
        y.copy_from_slice(&self.trial);
        self.last_step = dt;
        Ok(())
    }
}
