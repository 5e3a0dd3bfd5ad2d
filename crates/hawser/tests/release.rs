//! Release tests (`Settings::release`, `statics::solve_with_release`): the run starts from the
//! equilibrium with the released free points held at their positions, for every formulation.

use hawser::analysis::Channel;
use hawser::math::{Real, Vec3};
use hawser::model::*;
use hawser::statics::{StaticOptions, catenary, solve_with_release};
use hawser::system::System;
use hawser::verification::{dry_line_type, fixed, free, single_line};

/// A 2 m cable in air between a pin and a massless free point 1.8 m away, the free point
/// released.
fn model(formulation: Formulation, elements: usize) -> Model {
    let mut m = single_line(
        dry_line_type(0.01, 0.7, 1500.0),
        2.0,
        elements,
        (
            fixed("pin", Vec3::new(0.0, 0.0, 3.0)),
            free("tail", Vec3::new(1.8, 0.0, 3.0), 0.0, 0.0),
        ),
        formulation,
        MassMatrix::Consistent,
    );
    m.settings.release = vec![1];
    m
}

/// Every formulation starts from the sag between the two points: the pin tension of the
/// start state is the elastic catenary's (closed form) within each formulation's statics
/// accuracy on this mesh (fe 40 elements: second order, 1e-3; hermite 10 elements: 1e-5, its
/// end tension includes the inertia of the end node's share of the line, which the release
/// sets moving (1.2e-6); dg 5 elements of P = 4: 1e-6),
/// the released point is at its position and at rest, and the line's shape is not the
/// hanging one (the tail end is 1.8 m from the pin, not 2 m below it). Without the release the
/// statics let the point fall: the cable hangs straight down.
#[test]
fn release_starts_every_formulation_from_the_held_equilibrium() {
    let w = 0.7 * 9.80665;
    let expected = catenary::solve(1.8, 0.0, 2.0, w, 1500.0, false)
        .unwrap()
        .tension_a();
    for (f, n, tol) in [
        (Formulation::Fe, 40, 1e-3),
        (Formulation::Hermite, 10, 1e-5),
        (Formulation::Dg, 5, 1e-6),
    ] {
        let m = model(f, n);
        let system = System::new(&m).unwrap();
        let sol = solve_with_release(&m, &system, &StaticOptions::default()).unwrap();
        let mut ws = system.workspace();
        system
            .rhs(0.0, &sol.state, &mut vec![0.0; sol.state.len()], &mut ws)
            .unwrap();
        let pin = Channel::EndTension {
            line: 0,
            end_b: false,
        }
        .value(&system, &ws);
        let tail = Vec3::from_fn(|axis, _| {
            Channel::NodePosition {
                line: 0,
                node: n,
                axis,
            }
            .value(&system, &ws)
        });
        eprintln!("{f:?}: pin tension {pin:.6} N (catenary {expected:.6} N), tail at {tail:?}");
        assert!(
            (pin / expected - 1.0).abs() < tol,
            "{f:?}: {pin} vs {expected}"
        );
        assert!(
            (tail - Vec3::new(1.8, 0.0, 3.0)).norm() < 1e-9,
            "{f:?}: {tail:?}"
        );
        if let Some(o) = system.layout.point_offset[1] {
            assert_eq!(&sol.state[o..o + 3], &[1.8, 0.0, 3.0]);
            assert_eq!(&sol.state[o + 3..o + 6], &[0.0; 3]);
        }
        // Without the release the tail hangs below the pin.
        let mut hanging = m.clone();
        hanging.settings.release.clear();
        let hs = System::new(&hanging).unwrap();
        let h = hawser::statics::solve(&hs, None, &StaticOptions::default()).unwrap();
        let mut hws = hs.workspace();
        hs.rhs(0.0, &h.state, &mut vec![0.0; h.state.len()], &mut hws)
            .unwrap();
        let z: Real = Channel::NodePosition {
            line: 0,
            node: n,
            axis: 2,
        }
        .value(&hs, &hws);
        assert!(z < 1.01, "{f:?}: the unreleased tail hangs at z = {z}");
    }
}

/// Only free points can be released, each once.
#[test]
fn release_of_a_fixed_point_is_refused() {
    let mut m = model(Formulation::Fe, 4);
    m.settings.release = vec![0];
    let e = System::new(&m).err().unwrap().to_string();
    assert!(e.contains("not a free point"), "{e}");
    m.settings.release = vec![1, 1];
    let e = System::new(&m).err().unwrap().to_string();
    assert!(e.contains("twice"), "{e}");
}

/// `initial_condition = "as-defined"` with a `dg` line: the catenary seed of its hermite twin,
/// projected onto the dg basis (it used to reach an `unreachable!` in `SystemLine::set_shape`).
/// The seed is the elastic catenary between the ends, so its node positions are within 1 mm of
/// the static equilibrium of this 2 m line (measured 0.13 mm). Its tension is not: the twin's
/// tangents are second-order finite differences of the node positions, whose length is off by
/// O(h²κ²) ≈ 3e-3 on these 0.13 m cubic elements, and EA·3e-3 is half the tension here
/// (measured 16.2 N against 9.0 N). The seed is a start for statics, not an equilibrium: only
/// finiteness and the sign are asserted for it.
#[test]
fn as_defined_start_of_a_dg_line() {
    let mut m = model(Formulation::Dg, 5);
    m.settings.release.clear();
    m.points[1] = fixed("pin2", Vec3::new(1.8, 0.0, -3.0));
    m.points[0].position.z = -3.0;
    let system = System::new(&m).unwrap();
    let mut ws = system.workspace();
    let mut seed = system.straight_state();
    hawser::statics::catenary_seed(&system, &mut seed, &mut ws);
    let sol = hawser::statics::solve(&system, None, &StaticOptions::default()).unwrap();
    let sample = |y: &[Real]| {
        let mut ws = system.workspace();
        system
            .rhs(0.0, y, &mut vec![0.0; y.len()], &mut ws)
            .unwrap();
        let pin = Channel::EndTension {
            line: 0,
            end_b: false,
        }
        .value(&system, &ws);
        let nodes: Vec<Vec3> = (0..=5)
            .map(|node| {
                Vec3::from_fn(|axis, _| {
                    Channel::NodePosition {
                        line: 0,
                        node,
                        axis,
                    }
                    .value(&system, &ws)
                })
            })
            .collect();
        (pin, nodes)
    };
    let (t_seed, r_seed) = sample(&seed);
    let (t_static, r_static) = sample(&sol.state);
    let gap = r_seed
        .iter()
        .zip(&r_static)
        .map(|(a, b)| (a - b).norm())
        .fold(0.0, Real::max);
    eprintln!(
        "as-defined dg: pin tension {t_seed:.4} N vs static {t_static:.4} N; nodes within {gap:.2e} m"
    );
    assert!(t_seed.is_finite() && t_seed > 0.0);
    assert!(gap < 1e-3);
}
