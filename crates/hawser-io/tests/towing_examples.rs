//! The steady-towing examples (`examples/towing_system{1,2,3}.toml`, the elastic-link paper's
//! systems 1–3) as the files are, read by the scenario reader and solved by the statics that
//! `hawser statics` runs, against the independent integration of the steady cable equations
//! (`hawser::analysis::steady_cable`) for every tow in them.
//!
//! Tolerance: the `fe` discretisation error, which `crates/hawser/tests/steady_towing.rs`
//! shows to be second order, e ≈ C/N² with C ≤ 0.075 over these cases (relative to the cable
//! length for depth and layback, to the ship-end tension for it). Each tow must agree within
//! 2 C/N², N its element count (6e-5 for the 50 elements of system 1, 2.4e-4 for the 25 of
//! systems 2 and 3). The body-end tension agrees to the statics residual.
//!
//! `cargo test -p hawser-io --release --test towing_examples -- --nocapture` prints the
//! results table of docs/towing.md.

use hawser::analysis::steady_cable::SteadyTow;
use hawser::math::Real;
use hawser::model::{LineEnd, PointKind};
use hawser::physics::hydrodynamics::DragModel;
use hawser::statics::{StaticOptions, evaluate, solve};
use hawser::system::System;
use std::path::Path;

/// Largest second-order error constant C of the refinement study in steady_towing.rs.
const ERROR_CONSTANT: Real = 0.075;

#[test]
fn towing_examples_agree_with_the_steady_cable_integration() {
    println!(
        "| example | tow | cable drag | body force [N] | depth [m] | layback [m] | ship-end T [N] | \
         body-end T [N] | integration: depth, layback, ship T [m, m, N] | largest difference |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|");
    for file in [
        "towing_system1.toml",
        "towing_system2.toml",
        "towing_system3.toml",
    ] {
        let path = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../examples")
            .join(file);
        let model = hawser_io::scenario::load(&path)
            .unwrap_or_else(|e| panic!("{e}"))
            .model;
        let system = System::new(&model).expect("model");
        let sol = solve(&system, None, &StaticOptions::default()).expect("statics");
        let mut ws = system.workspace();
        evaluate(&system, &sol.state, &mut ws);
        assert!(!model.lines.is_empty());
        for (li, line) in model.lines.iter().enumerate() {
            // Every tow runs from its ship (end A) to its body (end B).
            let (LineEnd::Point(ship), LineEnd::Point(body)) = (line.end_a, line.end_b);
            let reference = SteadyTow::from_model(&model, li)
                .expect("a tow")
                .solve(&[])
                .expect("steady cable");
            let r = ws.points[body].position - ws.points[ship].position;
            let hawser = [
                -ws.points[body].position.z,
                -r.x,
                system.end_force(&ws, li, false).norm(),
                system.end_force(&ws, li, true).norm(),
            ];
            let rb = reference.body_position() - reference.ship_position();
            let independent = [
                -reference.body_position().z,
                -rb.x,
                reference.ship_tension(),
                reference.body_tension(),
            ];
            let length = line.length();
            let difference = [
                (hawser[0] - independent[0]).abs() / length,
                (hawser[1] - independent[1]).abs() / length,
                (hawser[2] - independent[2]).abs() / independent[2],
            ];
            let largest = difference.iter().copied().fold(0.0, Real::max);
            let n = line.elements() as Real;
            assert!(
                largest <= 2.0 * ERROR_CONSTANT / (n * n),
                "{file} {}: hawser {hawser:?}, integration {independent:?}",
                line.name
            );
            assert!(
                (hawser[3] - independent[3]).abs() <= sol.residual + 1e-9 * independent[3],
                "{file} {}: body-end tension {} vs {}",
                line.name,
                hawser[3],
                independent[3]
            );
            let drag = match &model.line_types[line.sections[0].line_type].drag {
                DragModel::Morison { normal, .. } => *normal > 0.0,
                DragModel::LoadingFunctions { .. } => true,
            };
            let PointKind::Free { force, .. } = &model.points[body].kind else {
                panic!("{file}: the body of {} is not a free point", line.name)
            };
            println!(
                "| {file} | {} | {} | ({:.1}, {:.1}) | {:.2} | {:.2} | {:.1} | {:.1} | {:.2}, {:.2}, {:.1} | {:.1e} |",
                line.name,
                if drag { "yes" } else { "no" },
                force.x,
                force.z,
                hawser[0],
                hawser[1],
                hawser[2],
                hawser[3],
                independent[0],
                independent[1],
                independent[2],
                largest
            );
        }
    }
}
