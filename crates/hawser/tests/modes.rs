//! Linearisation and modal analysis: natural frequencies against closed forms,
//! connection stiffness against the elastic catenary and against finite differences of
//! static solutions, and the sparse shift-invert solver against the dense one.
//!
//! The references are formulation-independent (closed forms, statics); the bending string
//! runs the same closed form for `hermite` lines and `dg` lines (through their hermite twin).

mod common;
use common::*;
use hawser::Model;
use hawser::analysis::modes::{EigenMethod, ModalOptions, ModeDirection, Modes, natural_modes};
use hawser::analysis::resonance::{excitations, resonance_report};
use hawser::linearise::{Linearisation, LinearisationOptions, connection_stiffness, linearise};
use hawser::math::{Mat3, Real, Vec3};
use hawser::model::{MassMatrix, Motion, PointKind};
use hawser::physics::environment::Current;
use hawser::statics::{StaticOptions, catenary, solve};
use hawser::system::System;
use std::f64::consts::{PI, TAU};

/// Statics, linearisation and the lowest `count` modes of a model.
fn modes_of(model: &Model, count: usize, method: EigenMethod) -> (System, Linearisation, Modes) {
    let system = System::new(model).unwrap();
    let sol = solve(&system, None, &StaticOptions::default()).expect("statics converges");
    let lin = linearise(&system, &sol.state, LinearisationOptions::default());
    let modes = natural_modes(
        &system,
        &lin,
        &ModalOptions {
            count,
            method,
            ..Default::default()
        },
    )
    .expect("modes");
    (system, lin, modes)
}

/// Exact eigenvalue ratio λ/(k/m) of mode `j` of a fixed–fixed chain of `n` two-node elements
/// with element stiffness k and element mass m: consistent mass 6(1 − cos θ)/(2 + cos θ),
/// lumped 2(1 − cos θ), θ = jπ/n.
fn chain_eigenvalue(j: usize, n: usize, mass: MassMatrix) -> Real {
    let theta = j as Real * PI / n as Real;
    match mass {
        MassMatrix::Consistent => 6.0 * (1.0 - theta.cos()) / (2.0 + theta.cos()),
        MassMatrix::Lumped => 2.0 * (1.0 - theta.cos()),
    }
}

/// A taut string in zero gravity and vacuum: unstretched length L0 = 10 m, γ0 = 1 kg/m,
/// EA = 10⁴ N, stretched 5 % between fixed points, so T = 500 N. Its transverse modes are
/// doubly repeated (y and z); its axial modes follow the same chain formula with the axial
/// element stiffness EA/ℓ0 instead of T/ℓ.
#[test]
fn taut_string_transverse_and_axial_frequencies_match_closed_forms() {
    let (l0, gamma, ea, strain, n) = (10.0, 1.0, 1.0e4, 0.05, 50);
    let span = l0 * (1.0 + strain);
    let tension = ea * strain;
    for mass in [MassMatrix::Consistent, MassMatrix::Lumped] {
        let model = taut_string(l0, gamma, ea, strain, n, mass);
        let count = 14;
        let (_, _, modes) = modes_of(&model, count, EigenMethod::ShiftInvert);
        // Expected: (frequency [Hz], axial?) merged and sorted.
        let (le, l0e) = (span / n as Real, l0 / n as Real);
        let m_e = gamma * l0e;
        let mut expected: Vec<(Real, bool)> = Vec::new();
        for j in 1..n {
            let transverse = (tension / le / m_e * chain_eigenvalue(j, n, mass)).sqrt() / TAU;
            let axial = (ea / l0e / m_e * chain_eigenvalue(j, n, mass)).sqrt() / TAU;
            expected.extend([(transverse, false), (transverse, false), (axial, true)]);
        }
        expected.sort_by(|a, b| a.0.total_cmp(&b.0));
        // Tolerance 1e-8: central differences of the forces err by (h/ℓ0)²·EA/T ≈ 3e-10 and
        // round-off by 1e-16/(h/ℓ0)·EA/T ≈ 5e-10 (h = 4e-6 ℓ0, EA/T = 20).
        for (k, mode) in modes.modes.iter().enumerate() {
            let (f, axial) = expected[k];
            let err = (mode.frequency - f).abs() / f;
            assert!(
                err < 1e-8,
                "{mass:?} mode {k}: {} Hz vs {f} Hz ({err:.2e})",
                mode.frequency
            );
            assert_eq!(
                mode.label.direction == ModeDirection::Axial,
                axial,
                "{mass:?} mode {k}: {}",
                mode.label.text
            );
        }
        let first_axial = modes
            .modes
            .iter()
            .find(|m| m.label.direction == ModeDirection::Axial)
            .expect("an axial mode among the first 14");
        assert_eq!(first_axial.label.text, "first axial mode of line L");
        // The continuum: f_j = j/(2L) √(T/μ) with μ = γ0 L0/L (transverse) and
        // f_j = j/(2 L0) √(EA/γ0) (axial). The chain formulas differ from them by
        // ±θ²/24 + O(θ⁴), θ = jπ/N (consistent above, lumped below): checked to that bound.
        let mu = gamma * l0 / span;
        let sign = if mass == MassMatrix::Consistent {
            1.0
        } else {
            -1.0
        };
        let bound = |j: usize| (j as Real * PI / n as Real).powi(2) / 24.0;
        for j in 1..=4 {
            let string = j as Real / (2.0 * span) * (tension / mu).sqrt();
            let err = (modes.modes[2 * (j - 1)].frequency - string) / string;
            assert!(
                err * sign > 0.0 && err.abs() < 1.1 * bound(j),
                "transverse {j}: {err:.3e} vs ±{:.3e}",
                bound(j)
            );
        }
        let rod = 1.0 / (2.0 * l0) * (ea / gamma).sqrt();
        let err = (first_axial.frequency - rod) / rod;
        assert!(
            err * sign > 0.0 && err.abs() < 1.1 * bound(1),
            "axial: {err:.3e}"
        );
        eprintln!(
            "{mass:?}: transverse 1 {:.6} Hz (string {:.6}), axial 1 {:.6} Hz (rod {rod:.6})",
            modes.modes[0].frequency,
            1.0 / (2.0 * span) * (tension / mu).sqrt(),
            first_axial.frequency
        );
    }
}

/// An inextensible chain hanging in air from a fixed point, its lower end free:
/// ω_n = (j0,n / 2)·√(g/L), j0,n the zeros of J0. Modes come in pairs (x and y).
#[test]
fn hanging_chain_frequencies_match_bessel_zeros() {
    const J0_ZEROS: [Real; 4] = [2.404826, 5.520078, 8.653728, 11.791534];
    let (length, g) = (10.0, 9.80665);
    let chain = |elements: usize, mass: MassMatrix| {
        // EA = 1e6 N against a top tension of 98 N: strain 1e-4, so inextensible to 1e-4
        // (a stiffer EA puts the round-off of EA·δr/ℓ0 above the statics tolerance).
        let mut model = single_line(
            dry_line_type(0.01, 1.0, 1.0e6),
            length,
            elements,
            fixed("top", Vec3::new(0.0, 0.0, 11.0)),
            free("end", Vec3::new(0.0, 0.0, 11.0 - length), 0.0, 0.0),
            mass,
        );
        model.environment = vacuum_environment(g);
        modes_of(&model, 8, EigenMethod::ShiftInvert).2
    };
    let exact = |k: usize| J0_ZEROS[k] / 2.0 * (g / length).sqrt() / TAU;
    for mass in [MassMatrix::Consistent, MassMatrix::Lumped] {
        let modes = chain(100, mass);
        for k in 0..4 {
            for m in &modes.modes[2 * k..2 * k + 2] {
                let err = (m.frequency - exact(k)) / exact(k);
                eprintln!(
                    "{mass:?} hanging chain mode {}: {:.6} Hz vs {:.6} Hz ({err:+.2e}), {}",
                    k + 1,
                    m.frequency,
                    exact(k),
                    m.label.text
                );
                // The 1 %: 100 elements are converged far below it (next check).
                assert!(err.abs() < 0.01);
                assert_eq!(m.label.direction, ModeDirection::Transverse);
            }
        }
        // Mesh convergence: the fourth mode's error falls about fourfold from 50 to 100
        // elements (second order), so the remaining error is discretisation.
        let coarse = chain(50, mass);
        let ratio = (coarse.modes[6].frequency - exact(3)) / (modes.modes[6].frequency - exact(3));
        eprintln!("{mass:?}: error ratio 50 → 100 elements, mode 4: {ratio:.2}");
        assert!((3.5..4.5).contains(&ratio), "{ratio}");
    }
}

/// A sagging taut cable (Irvine): its first mode is out-of-plane (the in-plane symmetric mode
/// is stiffened by the cable's stretching, the antisymmetric one has twice the frequency).
#[test]
fn first_mode_of_a_sagging_cable_is_out_of_plane() {
    let mut model = single_line(
        dry_line_type(0.01, 1.0, 1.0e5),
        100.0,
        40,
        fixed("A", Vec3::new(0.0, 0.0, 10.0)),
        fixed("B", Vec3::new(99.0, 0.0, 10.0)),
        MassMatrix::Consistent,
    );
    model.environment = vacuum_environment(9.80665);
    let (_, _, modes) = modes_of(&model, 4, EigenMethod::Dense);
    assert_eq!(
        modes.modes[0].label.text, "first out-of-plane mode of line L",
        "{:?}",
        modes.modes[0].direction_shares
    );
    assert_eq!(modes.modes[1].label.direction, ModeDirection::InPlane);
}

/// Stiffness of a line at its upper end B from the closed-form elastic catenary: with H and
/// V_B the closed form's tensions at span X and height Z, the line pulls B with
/// (−H, 0, −V_B), so K_xx = ∂H/∂X, K_xz = ∂H/∂Z, K_zx = ∂V_B/∂X, K_zz = ∂V_B/∂Z (central
/// differences of the closed form, which is solved to 1e-12 of the length), and
/// K_yy = H/X: moving B sideways turns the line rigidly about the anchor's vertical.
fn closed_form_stiffness(x: Real, z: Real, l: Real, w: Real, ea: Real, bed: bool) -> Mat3 {
    let d = 1e-3;
    let hv = |x: Real, z: Real| {
        let c = catenary::solve(x, z, l, w, ea, bed).unwrap();
        (c.horizontal, c.vertical_b)
    };
    let (hxp, vxp) = hv(x + d, z);
    let (hxm, vxm) = hv(x - d, z);
    let (hzp, vzp) = hv(x, z + d);
    let (hzm, vzm) = hv(x, z - d);
    let (h, _) = hv(x, z);
    Mat3::new(
        (hxp - hxm) / (2.0 * d),
        0.0,
        (hzp - hzm) / (2.0 * d),
        0.0,
        h / x,
        0.0,
        (vxp - vxm) / (2.0 * d),
        0.0,
        (vzp - vzm) / (2.0 * d),
    )
}

/// The condensed stiffness at point `fairlead` (end B of line 0) and the static force the
/// line exerts there.
fn fairlead_stiffness(model: &Model, fairlead: usize) -> (Mat3, Vec3) {
    let system = System::new(model).unwrap();
    let sol = solve(&system, None, &StaticOptions::default()).unwrap();
    let lin = linearise(&system, &sol.state, LinearisationOptions::default());
    let mut ws = system.workspace();
    hawser::statics::evaluate(&system, &sol.state, &mut ws);
    let k = connection_stiffness(&system, &lin).unwrap();
    (
        k.of_point(fairlead).unwrap(),
        system.end_force(&ws, 0, true),
    )
}

/// K_yy = H/X with the FE model's own horizontal tension: exact for any mesh, since turning
/// the line about the anchor's vertical is an exact equilibrium of the FE model too (the bed
/// is frictionless). Tolerance 1e-6: central differences and the condensation solve.
fn check_sideways(name: &str, k: &Mat3, force: &Vec3, span: Real) {
    let h = force.x.hypot(force.y);
    let err = (k[(1, 1)] - h / span).abs() / (h / span);
    eprintln!(
        "{name}: K_yy {:.9e} vs H/X {:.9e} ({err:.1e})",
        k[(1, 1)],
        h / span
    );
    assert!(err < 1e-6, "{name}: {err:.2e}");
}

fn compare(name: &str, fe: &Mat3, exact: &Mat3, tolerance: Real) {
    let scale = exact.abs().max();
    let err = (fe - exact).abs().max() / scale;
    eprintln!("{name}: FE {fe:.6e} closed form {exact:.6e} largest error {err:.2e} of max|K|");
    assert!(err < tolerance, "{name}: {err:.2e}");
}

/// Suspended, 100 elements: the stiffness converges as O(h²) like the static end tensions
/// (3.6e-5 at this mesh); measured 5.8e-5 of the largest entry, tolerance 3e-4.
///
/// On the bed, 200 elements: measured 1.8e-3 (1.9e-3 at 100 elements, 1.6e-3 at 400, and
/// unchanged for bed stiffnesses 3e7 to 3e9 Pa/m), tolerance 3e-3. The tangent of the FE
/// model keeps its touchdown at a node: the contact springs' boundary layer √(H/(K_g d))
/// (≈ 0.5 m) is far shorter than an element, so the first grounded node acts as an anchor
/// for an infinitesimal move, while the closed form's touchdown slides. This is a property of
/// nodal contact, not of the linearisation (which equals finite differences of the FE
/// statics, see the next test), and it vanishes only when elements are shorter than the
/// boundary layer.
#[test]
fn catenary_fairlead_stiffness_matches_the_closed_form() {
    // Suspended (the catenary test's line).
    let lt = line_type(0.05, 20.0, 5.0e7);
    let w = (20.0 - 1025.0 * PI * 0.05f64.powi(2) / 4.0) * 9.80665;
    let model = single_line(
        lt,
        110.0,
        100,
        fixed("A", Vec3::new(0.0, 0.0, -500.0)),
        fixed("B", Vec3::new(80.0, 0.0, -440.0)),
        MassMatrix::Consistent,
    );
    let (fe, force) = fairlead_stiffness(&model, 1);
    let exact = closed_form_stiffness(80.0, 60.0, 110.0, w, 5.0e7, false);
    compare("suspended catenary", &fe, &exact, 3e-4);
    check_sideways("suspended catenary", &fe, &force, 80.0);

    // OC3 chain resting on a frictionless bed.
    let (d, m, ea) = (0.09, 77.7066, 384.243e6);
    let w = (m - 1025.0 * PI * d * d / 4.0) * 9.80665;
    let model = oc3_chain(200, Vec3::new(0.0, 0.0, -70.0));
    let (fe, force) = fairlead_stiffness(&model, 1);
    let exact = closed_form_stiffness(848.67, 250.0, 902.2, w, ea, true);
    compare("catenary on the seabed", &fe, &exact, 3e-3);
    check_sideways("catenary on the seabed", &fe, &force, 848.67);
}

/// Two chains joined by a clump weight, in a current, from an anchor to a fairlead: the
/// condensed fairlead stiffness equals central differences of the static fairlead force
/// when the fairlead is moved by ±1 cm along each axis and statics solved again.
#[test]
fn connection_stiffness_equals_finite_differences_of_static_solutions() {
    let build = |fairlead: Vec3| {
        let mut model = single_line(
            line_type(0.05, 20.0, 5.0e7),
            80.0,
            40,
            fixed("anchor", Vec3::new(0.0, 0.0, -100.0)),
            free("clump", Vec3::new(60.0, 0.0, -80.0), 800.0, 0.1),
            MassMatrix::Consistent,
        );
        model.points.push(fixed("fairlead", fairlead));
        let mut l2 = model.lines[0].clone();
        l2.name = "L2".into();
        l2.sections[0].length = 50.0;
        l2.sections[0].elements = 25;
        l2.end_a = hawser::model::LineEnd::Point(1);
        l2.end_b = hawser::model::LineEnd::Point(2);
        model.lines.push(l2);
        model.environment.current = Current::Uniform(Vec3::new(0.6, 0.3, 0.0));
        model
    };
    let base = Vec3::new(110.0, 5.0, -40.0);
    let model = build(base);
    let system = System::new(&model).unwrap();
    let sol = solve(&system, None, &StaticOptions::default()).unwrap();
    let lin = linearise(&system, &sol.state, LinearisationOptions::default());
    let k = connection_stiffness(&system, &lin).unwrap();
    let k_fair = k.of_point(2).unwrap();
    // The anchor and fairlead couple only through the clump.
    assert_eq!(k.points.len(), 2);
    let fd = statics_fd(&build, base, 1, &sol.state);
    // Tolerance 1e-5 of the largest entry: statics converges to 1e-9 of the weight scale
    // (≈ 2e-4 N here, 1e-2 N/m after dividing by 2δ), and the O(δ²) truncation is 1e-7.
    let err = (k_fair - fd).abs().max() / fd.abs().max();
    eprintln!(
        "fairlead stiffness\n linearised {k_fair:.6e}\n statics FD {fd:.6e}\n error {err:.2e}"
    );
    assert!(err < 1e-5, "{err:.2e}");
    // The current makes the stiffness non-symmetric, and the linearisation says so.
    assert!(lin.stiffness.asymmetry() > 1e-8);

    // The OC3 chain on the seabed (200 elements): the FE model's own derivative, touchdown
    // included. Tolerance 1e-4: ±1 cm moves no node across the bed level here.
    let build = |fairlead: Vec3| oc3_chain(200, fairlead);
    let base = Vec3::new(0.0, 0.0, -70.0);
    let system = System::new(&build(base)).unwrap();
    let sol = solve(&system, None, &StaticOptions::default()).unwrap();
    let lin = linearise(&system, &sol.state, LinearisationOptions::default());
    let k = connection_stiffness(&system, &lin)
        .unwrap()
        .of_point(1)
        .unwrap();
    let fd = statics_fd(&build, base, 0, &sol.state);
    let err = (k - fd).abs().max() / fd.abs().max();
    eprintln!("on the seabed: linearised vs statics FD error {err:.2e}");
    assert!(err < 1e-4, "{err:.2e}");
}

/// −∂F/∂x of the force line `line` exerts at its end B, by central differences (±1 cm per
/// axis) of static solutions of `build(fairlead position)`, each started from `initial`.
fn statics_fd(build: &dyn Fn(Vec3) -> Model, base: Vec3, line: usize, initial: &[Real]) -> Mat3 {
    let force = |p: Vec3| {
        let system = System::new(&build(p)).unwrap();
        let s = solve(&system, Some(initial), &StaticOptions::default()).unwrap();
        let mut ws = system.workspace();
        hawser::statics::evaluate(&system, &s.state, &mut ws);
        system.end_force(&ws, line, true)
    };
    let delta = 1e-2;
    let mut fd = Mat3::zeros();
    for axis in 0..3 {
        let e = Vec3::ith(axis, delta);
        fd.set_column(
            axis,
            &(-(force(base + e) - force(base - e)) / (2.0 * delta)),
        );
    }
    fd
}

/// The OC3 mooring (three 902.2 m chains on the bed, 30 elements each, with added mass and
/// a current): the shift-invert subspace iteration finds the dense solver's lowest twelve
/// eigenvalues to 1e-9, and its vectors lie in the dense eigenspaces (the 120° symmetry
/// makes some of them repeated).
#[test]
fn shift_invert_equals_the_dense_generalized_solution() {
    let mut model = oc3(30);
    model.environment.current = Current::Uniform(Vec3::new(0.3, 0.1, 0.0));
    let system = System::new(&model).unwrap();
    let sol = solve(&system, None, &StaticOptions::default()).unwrap();
    let lin = linearise(&system, &sol.state, LinearisationOptions::default());
    let options = |method| ModalOptions {
        count: 12,
        method,
        ..Default::default()
    };
    let sparse = natural_modes(&system, &lin, &options(EigenMethod::ShiftInvert)).unwrap();
    let dense = natural_modes(&system, &lin, &options(EigenMethod::Dense)).unwrap();
    assert_eq!(sparse.method, EigenMethod::ShiftInvert);
    let mass = lin.mass.to_dense(&lin.dofs);
    for (j, s) in sparse.modes.iter().enumerate() {
        let d = &dense.modes[j];
        let err = (s.eigenvalue - d.eigenvalue).abs() / d.eigenvalue;
        assert!(
            err < 1e-9,
            "mode {j}: {} vs {} ({err:.2e})",
            s.eigenvalue,
            d.eigenvalue
        );
        // Projection of the sparse vector on the dense eigenspace of the same eigenvalue.
        let phi = nalgebra::DVector::from_column_slice(&s.shape);
        let mut projection = 0.0;
        for other in &dense.modes {
            if (other.eigenvalue - s.eigenvalue).abs() <= 1e-6 * s.eigenvalue {
                let psi = nalgebra::DVector::from_column_slice(&other.shape);
                projection += (psi.transpose() * &mass * &phi)[(0, 0)].powi(2);
            }
        }
        assert!(
            (projection - 1.0).abs() < 1e-8,
            "mode {j}: projection {projection}"
        );
    }
    eprintln!(
        "OC3 30 elements: {} DOFs, {} subspace iterations, f1 = {:.5} Hz ({}), asymmetry {:.1e}",
        sparse.degrees_of_freedom,
        sparse.iterations,
        sparse.modes[0].frequency,
        sparse.modes[0].label.text,
        sparse.stiffness_asymmetry
    );
}

/// The OC3 mooring with `n` elements per line and every fairlead surging (2 m, 10 s).
fn oc3(n: usize) -> Model {
    let (d, m, ea) = (0.09, 77.7066, 384.243e6);
    let mut model = single_line(
        line_type(d, m, ea),
        902.2,
        n,
        fixed("anchor1", Vec3::new(853.87, 0.0, -320.0)),
        fixed("fairlead1", Vec3::new(5.2, 0.0, -70.0)),
        MassMatrix::Consistent,
    );
    model.lines[0].name = "L1".into();
    model.environment.depth = 320.0;
    let anchors = [
        Vec3::new(-426.94, 739.47, -320.0),
        Vec3::new(-426.94, -739.47, -320.0),
    ];
    let fairleads = [Vec3::new(-2.6, 4.5, -70.0), Vec3::new(-2.6, -4.5, -70.0)];
    for k in 0..2 {
        let a = model.points.len();
        model
            .points
            .push(fixed(&format!("anchor{}", k + 2), anchors[k]));
        model
            .points
            .push(fixed(&format!("fairlead{}", k + 2), fairleads[k]));
        let mut line = model.lines[0].clone();
        line.name = format!("L{}", k + 2);
        line.end_a = hawser::model::LineEnd::Point(a);
        line.end_b = hawser::model::LineEnd::Point(a + 1);
        model.lines.push(line);
    }
    for p in model
        .points
        .iter_mut()
        .filter(|p| p.name.starts_with("fairlead"))
    {
        p.kind = PointKind::Prescribed(Motion::Sinusoid {
            centre: p.position,
            amplitude: Vec3::new(2.0, 0.0, 0.0),
            frequency: Vec3::new(0.1, 0.0, 0.0),
            phase: Vec3::zeros(),
            ramp: 0.0,
        });
    }
    model
}

/// The resonance report lists each fairlead's surge at 0.1 Hz against the nearest natural
/// frequency, and warns exactly when one lies within the margin.
#[test]
fn resonance_report_compares_excitations_with_natural_frequencies() {
    let model = oc3(20);
    let (system, _, modes) = modes_of(&model, 12, EigenMethod::Auto);
    let ex = excitations(&system);
    assert_eq!(ex.len(), 3);
    assert!(ex.iter().all(|e| (e.frequency - 0.1).abs() < 1e-15));
    assert_eq!(ex[0].source, "point fairlead1: sinusoid x");
    for margin in [0.01, 0.1, 0.5] {
        let report = resonance_report(&ex, &modes, margin);
        for r in &report {
            let nearest = modes.modes[r.nearest_mode].frequency;
            for (i, m) in modes.modes.iter().enumerate() {
                assert!((m.frequency - 0.1).abs() >= (nearest - 0.1).abs() - 1e-15);
                let near = (m.frequency - 0.1).abs() <= margin * m.frequency;
                assert_eq!(r.within_margin.contains(&i), near);
            }
            assert_eq!(r.warning(), !r.within_margin.is_empty());
        }
    }
}

/// A taut string with bending stiffness, pinned at both ends, in zero gravity: its transverse
/// modes are those of a beam under tension, ω_j = k √((EI k² + T)/γ0), k = jπ/L, each twice
/// (y and z). `hermite` lines are linearised directly (positions and tangents); a `dg` line
/// through its hermite twin (`modal_twin`: the same sections in ⌈P/2⌉ cubic elements per dg
/// element). Labelled modes (the tangents' energy counted with the line; in-plane and
/// out-of-plane of the vertical plane through the chord). Measured −4.5e-5 (hermite) and
/// −4.5e-5 (dg twin) on the first mode, −4.8e-6 and −3.4e-5 on the second: the closed form
/// takes k = jπ/L0 on the unstretched length, 1e-4 shorter than the span (up to 2e-4 in ω),
/// and 10 cubic elements err by O(h⁴); tolerance 2e-4.
#[test]
fn bending_string_modes_for_hermite_and_dg() {
    use hawser::model::Formulation;
    let (l0, gamma, ea, strain, ei) = (10.0, 1.0, 1.0e6, 1.0e-4, 100.0);
    let tension = ea * strain;
    for f in [Formulation::Hermite, Formulation::Dg] {
        let mut model = hawser::verification::taut_string_model(
            f,
            MassMatrix::Consistent,
            (l0, gamma, ea, strain),
            10,
        );
        model.line_types[0].bending_stiffness = ei;
        let twin = hawser::analysis::modes::modal_twin(&model);
        assert_eq!(twin.is_some(), f == Formulation::Dg);
        let model = twin.unwrap_or(model);
        let (system, lin, modes) = modes_of(&model, 6, EigenMethod::Auto);
        assert!(hawser::analysis::modes::supported(&system).is_ok());
        for j in 1..=2usize {
            let k = j as Real * PI / l0;
            let exact = k * ((ei * k * k + tension) / gamma).sqrt() / TAU;
            for m in &modes.modes[2 * (j - 1)..2 * j] {
                let err = (m.frequency - exact) / exact;
                eprintln!(
                    "{f:?} mode {j}: {} Hz vs {exact} Hz ({err:+.2e}), {}",
                    m.frequency, m.label.text
                );
                assert!(err.abs() < 2e-4, "{f:?} mode {j}: {err:.2e}");
                // A straight horizontal line has the vertical plane through its chord.
                assert!(
                    matches!(
                        m.label.direction,
                        ModeDirection::InPlane | ModeDirection::OutOfPlane
                    ),
                    "{}",
                    m.label.text
                );
                assert!(m.largest_displacement(&lin.dofs) > 0.0);
            }
        }
    }
}

/// The band holding 90 % of a Pierson–Moskowitz sea's variance against its closed form: the
/// cumulative moment is m₀(ω)/m₀ = exp(−5/4 (ωp/ω)⁴), so the q-quantile is
/// ω_q = ωp (5/4 / −ln q)^¼ (0.8037 ωp at 5 %, 2.222 ωp at 95 %). Tolerance 1e-4 relative:
/// the band truncates the spectrum at 20 ωp (tail 7.8e-6 of m₀, which moves the upper end by
/// 7.8e-6 / (d F / d ln ω = 0.195) = 4e-5) and interpolates linearly on a 10⁻³ ωp grid.
/// A JONSWAP sea (γ = 3.3) is narrower about the same peak; a regular wave's band is its
/// frequency; given components put their quantiles at the components that cross them.
#[test]
fn wave_band_holds_ninety_percent_of_the_energy() {
    use hawser::analysis::resonance::wave_band;
    use hawser::physics::waves::{
        ComponentSpec, IrregularSea, RegularWave, SeaState, Spectrum, WaveSpec, Waves,
    };
    let build = |sea: SeaState| {
        let spec = WaveSpec {
            sea,
            ramp_time: 0.0,
            stretching: Default::default(),
        };
        Waves::new(&spec, 200.0, 9.80665).unwrap()
    };
    let tp = 10.0;
    let irregular = |spectrum| {
        SeaState::Irregular(IrregularSea {
            spectrum,
            direction: 0.0,
            spreading: None,
            seed: 1,
            components: 200,
            frequency_range: (0.2, 3.0),
        })
    };
    let pm = wave_band(
        &build(irregular(Spectrum::PiersonMoskowitz {
            significant_height: 4.0,
            peak_period: tp,
        })),
        0.9,
    )
    .unwrap();
    let quantile = |q: Real| (1.25 / -q.ln()).powf(0.25) / tp;
    let (lo, hi) = (quantile(0.05), quantile(0.95));
    eprintln!(
        "PM band {} – {} Hz, closed form {lo} – {hi} Hz",
        pm.low, pm.high
    );
    assert!(((pm.low - lo) / lo).abs() < 1e-4, "{} vs {lo}", pm.low);
    assert!(((pm.high - hi) / hi).abs() < 1e-4, "{} vs {hi}", pm.high);
    assert!((pm.peak - 1.0 / tp).abs() < 1e-12);
    let js = wave_band(
        &build(irregular(Spectrum::Jonswap {
            significant_height: 4.0,
            peak_period: tp,
            peak_enhancement: 3.3,
        })),
        0.9,
    )
    .unwrap();
    assert!(js.low > pm.low && js.high < pm.high && js.low < 1.0 / tp && js.high > 1.0 / tp);
    let regular = wave_band(
        &build(SeaState::Regular(RegularWave {
            height: 2.0,
            period: 8.0,
            direction: 0.0,
        })),
        0.9,
    )
    .unwrap();
    assert_eq!((regular.low, regular.high), (0.125, 0.125));
    // Variances ½a²: 1, 8, 1 of 10: the 5 % quantile (0.5) falls in the first component, the
    // 95 % one (9.5) in the last.
    let components = [(0.1_f64, 2.0_f64.sqrt()), (0.2, 4.0), (0.3, 2.0_f64.sqrt())]
        .map(|(f, a)| ComponentSpec {
            amplitude: a,
            angular_frequency: TAU * f,
            direction: 0.0,
            phase: 0.0,
        })
        .to_vec();
    let record = wave_band(&build(SeaState::Components(components)), 0.9).unwrap();
    assert!((record.low - 0.1).abs() < 1e-12 && (record.high - 0.3).abs() < 1e-12);
    assert!((record.peak - 0.2).abs() < 1e-12);
}
