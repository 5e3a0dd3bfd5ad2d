//! `initial_condition = "as-defined"`: the lines start as the user drew them. A line in air
//! hangs under its dry weight (it arched upward under its wet weight, as if buoyant, with
//! 1.7 kN of tension), and a line whose length reaches straight between its ends starts
//! straight (a beam under gravity started bowed like a cable).

use hawser::Session;
use hawser::math::Vec3;
use hawser::model::*;
use hawser::verification::{fixed, line_type, single_line};

/// The node heights of the as-defined start of `model`.
fn start_heights(mut model: Model) -> Vec<f64> {
    model.settings.initial_condition = InitialCondition::AsDefined;
    model.settings.duration = 0.0;
    let mut session = Session::new(model).expect("a valid model");
    let view = session.view().expect("evaluates");
    view.line_samples(0).map(|n| n.position.z).collect()
}

#[test]
fn a_line_in_air_sags_under_its_dry_weight() {
    // A hose of 0.3 m diameter and 20 kg/m (buoyant in water: 72.5 kg/m displaced), 55 m
    // between points 50 m apart and 10 m above the water.
    let model = single_line(
        line_type(0.3, 20.0, 1e7),
        55.0,
        20,
        (
            fixed("a", Vec3::new(0.0, 0.0, 10.0)),
            fixed("b", Vec3::new(50.0, 0.0, 10.0)),
        ),
        Formulation::Fe,
        MassMatrix::Consistent,
    );
    let z = start_heights(model);
    assert!(
        z[1..z.len() - 1].iter().all(|&z| z < 10.0),
        "every interior node below the ends: {z:?}"
    );
    // The inextensible catenary of 55 m over 50 m sags 9.9 m whatever its weight; the
    // elastic one a little more.
    let sag = 10.0 - z[10];
    assert!(sag > 9.8 && sag < 10.2, "sag {sag} m");
}

#[test]
fn a_line_that_reaches_straight_starts_straight() {
    // A steel beam with bending stiffness, as long as the distance between its ends, in air.
    let mut lt = line_type(0.1, 60.0, 1e9);
    lt.bending_stiffness = 1e6;
    for formulation in [Formulation::Fe, Formulation::Hermite] {
        let model = single_line(
            lt.clone(),
            10.0,
            10,
            (
                fixed("a", Vec3::new(0.0, 0.0, 5.0)),
                fixed("b", Vec3::new(10.0, 0.0, 5.0)),
            ),
            formulation,
            MassMatrix::Consistent,
        );
        let z = start_heights(model);
        assert!(
            z.iter().all(|&z| (z - 5.0).abs() < 1e-12),
            "{formulation:?}: straight at z = 5 m: {z:?}"
        );
    }
}
