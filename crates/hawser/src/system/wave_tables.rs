//! The run's wave kinematics at the static position: where [`System`] builds the cache of
//! [`StaticPositionKinematics`] for its lines' quadrature points, prepares it at each
//! evaluation time, and hands each line its points ([`FluidPoints`]).

use super::{System, Workspace};
use crate::math::{Real, Vec3};
use crate::physics::static_kinematics::{
    FluidPoints, StaticPositionKinematics, WaveKinematicsMethod,
};
use std::cell::Cell;

/// The workspace's state of the static-position kinematics.
#[derive(Clone, Debug, Default)]
pub enum WavePoints {
    /// Direct summation (the default, and always without waves).
    #[default]
    Direct,
    /// One evaluation is recording the positions of every line's quadrature points.
    Recording(Vec<Vec<Cell<Vec3>>>),
    /// The cache of a run, built by [`System::start_wave_tables`].
    Tables(StaticPositionKinematics),
}

impl WavePoints {
    /// Line `line`'s points for the formulations.
    #[inline]
    pub fn of_line(&self, line: usize) -> FluidPoints<'_> {
        match self {
            WavePoints::Direct => FluidPoints::Direct,
            WavePoints::Recording(cells) => FluidPoints::Record {
                positions: &cells[line],
            },
            WavePoints::Tables(t) => FluidPoints::of_line(Some(t), line),
        }
    }

    /// The cache, once built.
    pub fn tables(&self) -> Option<&StaticPositionKinematics> {
        match self {
            WavePoints::Tables(t) => Some(t),
            _ => None,
        }
    }
}

impl System {
    /// Number of quadrature points at which line `l` evaluates the fluid: 2 per `fe` element,
    /// 4 per `hermite` element, the Gauss points of a `dg` line.
    pub fn fluid_points(&self, l: usize) -> usize {
        self.lines[l].fluid_points()
    }

    /// Starts a run's wave kinematics at time `t` [s] from state `y`: with
    /// [`WaveKinematicsMethod::StaticPosition`] and waves, records where every line quadrature
    /// point is at (t, y) (one evaluation of the right-hand side) and builds the cache there;
    /// otherwise leaves direct summation. Free points and bodies always take direct
    /// summation. Call once before stepping ([`crate::simulation::Simulation`] does).
    pub fn start_wave_tables(&self, t: Real, y: &[Real], ws: &mut Workspace) {
        ws.wave_points = WavePoints::Direct;
        let (WaveKinematicsMethod::StaticPosition { sample_interval }, Some(field)) = (
            self.environment.wave_kinematics,
            self.environment.waves.field(),
        ) else {
            return;
        };
        let nan = Vec3::repeat(Real::NAN);
        ws.wave_points = WavePoints::Recording(
            (0..self.lines.len())
                .map(|l| vec![Cell::new(nan); self.fluid_points(l)])
                .collect(),
        );
        let mut scratch = vec![0.0; y.len()];
        // A singular mass matrix is reported by the run's own first step.
        let _ = self.rhs(t, y, &mut scratch, ws);
        let WavePoints::Recording(cells) = std::mem::take(&mut ws.wave_points) else {
            unreachable!("set above")
        };
        let positions: Vec<Vec<Vec3>> = cells
            .into_iter()
            .map(|l| l.into_iter().map(Cell::into_inner).collect())
            .collect();
        ws.wave_points = WavePoints::Tables(StaticPositionKinematics::new(
            field,
            sample_interval,
            &positions,
        ));
    }

    /// The static positions of every line's quadrature points [m], per line, when the run
    /// uses the static-position cache (what a checkpoint saves to rebuild it).
    pub fn wave_table_positions(&self, ws: &Workspace) -> Option<Vec<Vec<Vec3>>> {
        let t = ws.wave_points.tables()?;
        Some(
            (0..self.lines.len())
                .map(|l| {
                    let first = t.line_first(l);
                    (first..first + self.fluid_points(l))
                        .map(|p| t.position(p))
                        .collect()
                })
                .collect(),
        )
    }

    /// Rebuilds the static-position cache at saved `positions` ([`System::wave_table_positions`]).
    pub fn restore_wave_tables(&self, positions: &[Vec<Vec3>], ws: &mut Workspace) {
        if let (WaveKinematicsMethod::StaticPosition { sample_interval }, Some(field)) = (
            self.environment.wave_kinematics,
            self.environment.waves.field(),
        ) {
            ws.wave_points = WavePoints::Tables(StaticPositionKinematics::new(
                field,
                sample_interval,
                positions,
            ));
        }
    }

    /// Prepares the static-position cache, if any, at evaluation time t [s].
    #[inline]
    pub(super) fn prepare_wave_tables(&self, t: Real, ws: &mut Workspace) {
        if let WavePoints::Tables(table) = &mut ws.wave_points {
            table.prepare(t);
        }
    }
}
