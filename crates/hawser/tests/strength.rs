//! Line strength on a hand-computed case: a vertical line hanging in water from a fixed point,
//! 60 m of chain over 40 m of rope, with a weight at its lower end. In static equilibrium the
//! effective tension at unstretched arc length s from the top is the wet weight below s,
//! whatever the stretch (weights are per unit unstretched length):
//!
//!   T(s) = W + w_rope·40 + w_chain·(60 − s)   for 0 ≤ s ≤ 60 m,
//!   T(s) = W + w_rope·(100 − s)               for 60 ≤ s ≤ 100 m,
//!
//! with w = (γ0 − ρ π d²/4) g per type and W = (m − ρ V) g. The chain section's worst point is
//! the top (s = 0), the rope's its top at the joint (s = 60 m); utilisations follow by hand.

use hawser::analysis::strength::{line_strength, worst_section};
use hawser::math::{Real, Vec3};
use hawser::model::*;
use hawser::system::System;
use hawser::verification::{fixed, free, line_type, single_line};

const RHO: Real = 1025.0;
const G: Real = 9.80665;

fn wet(gamma: Real, diameter: Real) -> Real {
    (gamma - RHO * std::f64::consts::PI * diameter * diameter / 4.0) * G
}

fn model(formulation: Formulation) -> Model {
    let mut chain = line_type(0.05, 50.0, 5e8);
    chain.name = "chain".into();
    chain.minimum_breaking_load = Some(2.0e5);
    let mut rope = line_type(0.04, 5.0, 5e7);
    rope.name = "rope".into();
    rope.minimum_breaking_load = Some(3.0e4);
    rope.design_safety_factor = Some(1.5);
    let top = Vec3::new(0.0, 0.0, -10.0);
    let mut m = single_line(
        chain.clone(),
        60.0,
        6,
        (
            fixed("top", top),
            free("weight", top - Vec3::new(0.0, 0.0, 100.0), 500.0, 0.1),
        ),
        formulation,
        MassMatrix::Consistent,
    );
    m.line_types = vec![chain, rope];
    m.lines[0].sections.push(Section {
        line_type: 1,
        length: 40.0,
        elements: 4,
        order: 4,
    });
    m
}

/// The strength check of `fe` and `hermite` lines against the hand computation (both give
/// each element the tension at its midpoint, so the node values are those of the closed
/// form).
#[test]
fn hanging_line_utilisation_by_hand() {
    check(&[Formulation::Fe, Formulation::Hermite]);
}

/// The same with a `dg` line. Its node tensions are those of the closed form along each
/// section (the gradients agree), but every one is low by 50.5 N here (0.15 % at the top,
/// 1.3 % at the weight), and by half as much with twice the elements: a `dg` line of two
/// line types loses part of its weight. A line of one type is exact.
#[test]
#[ignore = "dg lines of two line types lose O(h) of their weight in statics (50.5 N of 33590 N with 10 m elements)"]
fn hanging_dg_line_utilisation_by_hand() {
    check(&[Formulation::Dg]);
}

fn check(formulations: &[Formulation]) {
    let (w_chain, w_rope) = (wet(50.0, 0.05), wet(5.0, 0.04));
    let weight = (500.0 - RHO * 0.1) * G;
    let top_tension = weight + 40.0 * w_rope + 60.0 * w_chain;
    let joint_tension = weight + 40.0 * w_rope;
    // The node at the joint carries the mean of its two elements' tensions, the wet weight
    // below their midpoints s = 55 m and s = 65 m: T(60) + 2.5 m · (w_chain − w_rope), 1085 N
    // above T(60) with these 10 m elements (the joint's discretisation error, O(h) where
    // the wet weight per metre jumps; it counts for both sections).
    let joint_node = joint_tension + 2.5 * (w_chain - w_rope);
    for &formulation in formulations {
        // `dg` gives a node the tension at the element ends (the mean of both sides), T(60).
        let joint_node = match formulation {
            Formulation::Dg => joint_tension,
            _ => joint_node,
        };
        let system = System::new(&model(formulation)).unwrap();
        let sol = hawser::statics::solve(&system, None, &Default::default()).unwrap();
        let mut ws = system.workspace();
        hawser::statics::evaluate(&system, &sol.state, &mut ws);
        let s = line_strength(&system, &ws, 0);
        eprintln!(
            "{formulation:?}: top {:.3} N (hand {top_tension:.3}), joint {:.3} N (hand \
             {joint_node:.3}, T(60) = {joint_tension:.3}), residual {:.1e} N",
            s[0].max_tension, s[1].max_tension, sol.residual
        );
        // The equilibrium holds to the statics residual (relative tolerance 1e-9 of the
        // weight scale): 1e-6 relative leaves three orders of margin.
        let close = |a: Real, b: Real| (a - b).abs() <= 1e-6 * b;
        assert_eq!(
            (s[0].line_type.as_str(), s[1].line_type.as_str()),
            ("chain", "rope")
        );
        assert!(close(s[0].max_tension, top_tension), "{formulation:?} top");
        assert_eq!((s[0].at, s[0].node), (0.0, 0));
        assert!(close(s[1].max_tension, joint_node), "{formulation:?} joint");
        assert!((s[1].at - 60.0).abs() < 1e-12 && s[1].node == 6);
        assert!((s[1].end - 100.0).abs() < 1e-12);
        assert!(close(s[0].utilisation().unwrap(), top_tension / 2.0e5));
        assert_eq!(s[0].design_utilisation(), None);
        assert!(close(s[1].utilisation().unwrap(), joint_node / 3.0e4));
        assert!(close(
            s[1].design_utilisation().unwrap(),
            joint_node * 1.5 / 3.0e4
        ));
        // The rope is the weaker part: its design utilisation (~0.79) beats the chain's
        // utilisation (~0.15).
        assert_eq!(worst_section(&s).map(|w| w.section), Some(1));
    }
}
