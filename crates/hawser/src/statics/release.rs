//! Release tests: the static equilibrium with some free points held fixed, as the start of a
//! run in which they are free (`simulation.release`).

use super::newton::{StaticOptions, StaticSolution, solve};
use crate::error::StaticsError;
use crate::math::{Real, set3};
use crate::model::{Model, PointKind};
use crate::system::System;

/// The static equilibrium of `model` with the points of `model.settings.release` held fixed
/// at their `position`, as a state of `system` (built from `model` by [`System::new`]), in
/// which those points are free: the line shapes and the other free points are the held
/// equilibrium, the released points sit at their `position`, everything at rest. Without
/// released points this is [`solve`].
///
/// A line's block of the state does not depend on what its ends are attached to (a line owns
/// its interior unknowns; its end positions belong to the points, and a massless point at the
/// end of a single `dg` line is not in the state at all), so the held system's line blocks
/// are copied as they are. At t = 0 the released points feel the line forces of the held
/// equilibrium and nothing holds them: the sudden release of the DG paper's swinging cable
/// (§5), whose second pin is pulled at t = 0.
pub fn solve_with_release(
    model: &Model,
    system: &System,
    options: &StaticOptions,
) -> Result<StaticSolution, StaticsError> {
    if model.settings.release.is_empty() {
        return solve(system, None, options);
    }
    let mut held = model.clone();
    for &p in &model.settings.release {
        held.points[p].kind = PointKind::Fixed;
    }
    held.settings.release.clear();
    let held_system = System::new(&held).expect(
        "holding free points fixed leaves a valid model valid (checked by Model::validate)",
    );
    let sol = solve(&held_system, None, options)?;
    Ok(StaticSolution {
        state: released_state(system, &held_system, &sol.state, model),
        ..sol
    })
}

/// Carries a state `y_held` of `held` (the model with its released points fixed) to `system`:
/// line blocks and the free points of both copied, released points at their `position` and
/// at rest.
fn released_state(system: &System, held: &System, y_held: &[Real], model: &Model) -> Vec<Real> {
    let mut y = vec![0.0; system.layout.len];
    for li in 0..system.lines.len() {
        let (o, len) = (system.layout.line_offset[li], system.layout.line_len[li]);
        let oh = held.layout.line_offset[li];
        debug_assert_eq!(len, held.layout.line_len[li]);
        y[o..o + len].copy_from_slice(&y_held[oh..oh + len]);
    }
    for (p, off) in system.layout.point_offset.iter().enumerate() {
        let Some(o) = *off else { continue };
        match held.layout.point_offset[p] {
            Some(oh) => y[o..o + 6].copy_from_slice(&y_held[oh..oh + 6]),
            None => set3(&mut y[o..], 0, &model.points[p].position),
        }
    }
    y
}
