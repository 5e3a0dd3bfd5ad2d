//! A steady towed cable against an independent integration of the steady cable equations
//!: the elastic-link paper's system 1 (SPEC §7; docs/towing.md), solved by
//! hawser's statics in the frame of the ship (the water streams past at −V as a uniform
//! current, the body is a free point with drag area and a constant stabiliser force), against
//! [`crate::analysis::steady_cable`], which integrates the steady cable equations from the
//! body to the ship.

use super::*;
use crate::analysis::steady_cable::SteadyTow;
use crate::physics::hydrodynamics::DragModel;
use crate::statics::{StaticOptions, evaluate, solve};

/// System 1: 400 m of 30 mm cable (1.43 kg/m, EA 6.75e7 N, C_n 1.35, C_τ 0.04) towing at
/// 3 m/s a neutrally buoyant 0.8 m × 2 m cylinder (1030.44 kg, C_d A 0.387 m²) with a 1 kN
/// stabiliser drag, with `elements` elements of `formulation`.
pub fn system_1(formulation: Formulation, elements: usize) -> Model {
    let mut lt = line_type(0.030, 1.43, 6.75e7);
    lt.drag = DragModel::Morison {
        normal: 1.35,
        tangential: 0.04,
    };
    let mut body = free("body", Vec3::new(-360.0, 0.0, -120.0), 1030.44, 1.005310);
    if let PointKind::Free {
        drag_area, force, ..
    } = &mut body.kind
    {
        *drag_area = 0.387044;
        *force = Vec3::new(-1000.0, 0.0, 0.0);
    }
    let mut m = single_line(
        lt,
        400.0,
        elements,
        (fixed("ship", Vec3::zeros()), body),
        formulation,
        MassMatrix::Consistent,
    );
    m.environment.current = Current::Uniform(Vec3::new(-3.0, 0.0, 0.0));
    m
}

/// Steady towed cable, system 1 with cable drag: body depth, layback, ship-end and body-end
/// tension against the integration.
///
/// Tolerances: 1e-3 of the cable length on depth and layback and 1e-3 relative on the
/// ship-end tension (the 0.1 % for static tensions). `fe` at 40 elements is measured
/// within 1.3e-5 of it (its error is O(h²), tests/steady_towing.rs), `hermite` at 10 within
/// about the same. The body-end tension equals the body's own load at any mesh: 1e-6.
pub fn steady_towed_cable(f: Formulation, fidelity: Fidelity) -> Result<Findings, CaseError> {
    let elements = match (f, fidelity) {
        (Formulation::Hermite, Fidelity::Quick) => 8,
        (Formulation::Hermite, Fidelity::Full) => 16,
        (_, Fidelity::Quick) => 40,
        (_, Fidelity::Full) => 80,
    };
    let model = system_1(f, elements);
    let system = assemble(&model)?;
    let sol = solve(&system, None, &StaticOptions::default())?;
    let mut ws = system.workspace();
    evaluate(&system, &sol.state, &mut ws);
    let body = ws.points[1].position;
    let reference = SteadyTow::from_model(&model, 0)
        .map_err(|e| CaseError::NotAvailable(format!("steady-cable reference: {e}")))?
        .solve(&[0.0, model.lines[0].length()])
        .map_err(|e| CaseError::Failed(format!("steady-cable reference: {e}")))?;
    let expected_body = reference.body_position();
    let length = model.lines[0].length();
    Ok(Findings {
        checks: vec![
            Check::new(
                "body depth",
                "m",
                -expected_body.z,
                -body.z,
                Tolerance::Absolute(1e-3 * length),
            ),
            Check::new(
                "layback",
                "m",
                -expected_body.x,
                -body.x,
                Tolerance::Absolute(1e-3 * length),
            ),
            Check::new(
                "ship-end tension",
                "N",
                reference.ship_tension(),
                system.end_force(&ws, 0, false).norm(),
                Tolerance::Relative(1e-3),
            ),
            Check::new(
                "body-end tension",
                "N",
                reference.body_tension(),
                system.end_force(&ws, 0, true).norm(),
                Tolerance::Relative(1e-6),
            ),
        ],
        plots: vec![],
    })
}
