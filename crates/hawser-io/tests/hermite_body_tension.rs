//! Node tensions of a `hermite` line next to a body. Interior nodes read the mean of their two
//! elements' midpoint tensions, the ends the force the line exerts on its point (the point's
//! share of the end element's load included): on a line whose tension grows away from a body
//! (weight, drag), the node next to the body reads above the end tension by that growth over
//! one element, as the tension itself does. Checked on a vertical line between two free
//! bodies and from a fixed point to a float, where the tension is T_B + w (L − s) exactly
//! (w the wet weight per unstretched metre, s the unstretched arc length from end A).

use hawser::statics::{StaticOptions, evaluate, solve};
use hawser::system::System;
use hawser_io::scenario;
use std::path::Path;

const SCENARIO: &str = r#"
[simulation]
duration = 1.0

[environment]
depth = 500.0

[[line_types]]
name = "rope"
diameter = 0.03
mass_per_length = 2.0
axial_stiffness = 1e7
normal_drag = 1.2
tangential_drag = 0.01

[[points]]
name = "top"
type = "fixed"
position = [0.0, 0.0, 0.0]

[[bodies]]
name = "float"
type = "free"
position = [0.0, 0.0, -51.0]
mass = 500.0
inertia = [100.0, 100.0, 100.0]
displacement = { type = "submerged", volume = 0.2 }

[[points]]
name = "f_top"
type = "body"
body = "float"
position = [0.0, 0.0, 0.5]

[[points]]
name = "f_bot"
type = "body"
body = "float"
position = [0.0, 0.0, -0.5]

[[bodies]]
name = "weight"
type = "free"
position = [0.0, 0.0, -152.0]
mass = 1000.0
inertia = [100.0, 100.0, 100.0]
displacement = { type = "submerged", volume = 0.1 }

[[points]]
name = "hook"
type = "body"
body = "weight"
position = [0.0, 0.0, 0.5]

[[lines]]
name = "upper"
end_a = "top"
end_b = "f_top"
type = "rope"
length = 50.0
elements = 10
formulation = "hermite"

[[lines]]
name = "lower"
end_a = "f_bot"
end_b = "hook"
type = "rope"
length = 100.0
elements = 10
formulation = "hermite"
"#;

#[test]
fn hermite_node_tensions_next_to_bodies_follow_the_tension_profile() {
    let s = scenario::parse(Path::new("bodies.toml"), SCENARIO).unwrap_or_else(|e| panic!("{e}"));
    let system = System::new(&s.model).expect("valid");
    let sol = solve(&system, None, &StaticOptions::default()).expect("statics converge");
    let mut ws = system.workspace();
    evaluate(&system, &sol.state, &mut ws);
    let g = system.environment.gravity;
    let rho = system.environment.water_density;
    // The rope's wet weight per metre [N/m]: 2 kg/m less the water of a 30 mm cylinder.
    let w = (2.0 - rho * std::f64::consts::PI * 0.03f64.powi(2) / 4.0) * g;
    // The weight's wet weight [N]: 1000 kg less 0.1 m³ of water.
    let weight = (1000.0 - rho * 0.1) * g;
    for (li, line) in system.lines.iter().enumerate() {
        let n = line.mesh.elements();
        let length = line.mesh.length();
        let t_b = system.node_tension(&ws, li, n);
        if line.name == "lower" {
            // The bodies' statics accept an imbalance of 1e-3 of their loads.
            assert!(
                (t_b - weight).abs() < 1e-3 * weight,
                "end B {t_b} N, weight {weight} N"
            );
        }
        for i in 0..=n {
            let s = line.mesh.arc_length(i);
            let expected = t_b + w * (length - s);
            let t = system.node_tension(&ws, li, i);
            // The lines' own equilibrium is solved to 1e-9 of the loads: 1e-7 leaves room
            // for the stretch the weight per unstretched metre ignores (none: it is exact on
            // a vertical line) and for round-off.
            assert!(
                (t - expected).abs() < 1e-7 * expected,
                "{} node {i}: {t} N, expected {expected} N",
                line.name
            );
        }
        // Next to the body at end B the node reads above the end by one element's wet weight.
        let above = system.node_tension(&ws, li, n - 1) - t_b;
        let element = w * length / n as f64;
        assert!(
            (above - element).abs() < 1e-6 * element + 1e-7 * t_b,
            "{above} N"
        );
    }
}
