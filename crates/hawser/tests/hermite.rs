//! The `hermite` formulation against closed forms: the elastic catenary
//! (end tensions and the observed order of the position error), simply supported beam
//! frequencies from its bending stiffness, and agreement with `fe` on the same scenario.

mod common;
use common::*;
use hawser::formulation::hermite::point_on_element;
use hawser::linearise::{LinearisationOptions, linearise};
use hawser::math::{Real, Vec3};
use hawser::model::{Formulation, MassMatrix, Model};
use hawser::statics::{StaticOptions, catenary, evaluate, solve};
use hawser::system::System;

const W_WET: Real = (20.0 - 1025.0 * std::f64::consts::PI * 0.05 * 0.05 / 4.0) * 9.80665;

/// The suspended catenary of tests/catenary.rs (110 m between points 80 m apart and 60 m
/// up), with `n` elements of `formulation`.
fn catenary_model(n: usize, formulation: Formulation) -> Model {
    let mut m = single_line(
        line_type(0.05, 20.0, 5.0e7),
        110.0,
        n,
        fixed("A", Vec3::new(0.0, 0.0, -500.0)),
        fixed("B", Vec3::new(80.0, 0.0, -440.0)),
        MassMatrix::Consistent,
    );
    m.lines[0].formulation = formulation;
    m
}

/// Position errors [m] of a static solution against the closed form.
struct PositionErrors {
    /// Largest error at the nodes.
    nodes: Real,
    /// Largest distance from points inside the elements (9 per element, along the Hermite
    /// interpolation) to the exact curve: the error of the shape.
    shape: Real,
    /// Largest error of those points against the exact position of the same material point
    /// (the same unstretched arc length): shape plus the error along the curve.
    material: Real,
}

/// Static end tension errors (relative) and position errors against the closed form.
fn catenary_errors(n: usize) -> (Real, Real, PositionErrors) {
    let model = catenary_model(n, Formulation::Hermite);
    let system = System::new(&model).unwrap();
    let sol = solve(&system, None, &StaticOptions::default()).expect("statics converges");
    let mut ws = system.workspace();
    evaluate(&system, &sol.state, &mut ws);
    let exact = catenary::solve(80.0, 60.0, 110.0, W_WET, 5.0e7, false).unwrap();
    let at = |s: Real| {
        let (x, z) = exact.position(s);
        Vec3::new(x, 0.0, -500.0 + z)
    };
    let ta = system.end_force(&ws, 0, false).norm();
    let tb = system.end_force(&ws, 0, true).norm();
    let l = &system.lines[0];
    let q = &ws.lines[0].position;
    let mut err = PositionErrors {
        nodes: 0.0,
        shape: 0.0,
        material: 0.0,
    };
    for i in 0..=n {
        let d = q[l.node_vector(i)] - at(l.mesh.arc_length(i));
        err.nodes = err.nodes.max(d.norm());
    }
    for e in 0..n {
        for k in 1..10 {
            let xi = k as Real / 10.0;
            let (r, _) = point_on_element(&l.mesh, q, e, xi);
            let s = l.mesh.arc_length(e) + xi * l.mesh.section(e).element_length;
            let d = r - at(s);
            err.material = err.material.max(d.norm());
            // Distance to the curve: remove the component along the exact tangent (the
            // nearest exact point is that far along the curve, to second order).
            let h = 1e-4;
            let t = (at(s + h) - at(s - h)).normalize();
            err.shape = err.shape.max((d - t * d.dot(&t)).norm());
        }
    }
    (
        (ta - exact.tension_a()).abs() / exact.tension_a(),
        (tb - exact.tension_b()).abs() / exact.tension_b(),
        err,
    )
}

/// End tensions within 3e-5 with 8 elements (fe needs 100 elements for 3.6e-5), converging
/// at order 4; nodal positions converge at order 4 (the issue asks 4 for `hermite`
/// positions): the observed order between halvings from N = 8 on must be at least 3.7
/// (4 − 0.3, the tolerance the issues give convergence rates) until round-off (1e-9 m).
///
/// Inside the elements the error converges at order 3.2 only (measured 3.16 and 3.22), both
/// the distance to the exact curve and the error of a material point: this nearly
/// inextensible line (EA/T ≈ 5000) asks |r'| ≈ 1 at every Gauss point, which a curved cubic
/// can meet only approximately (three-point reduced integration of the axial term measured
/// the same order, so it is not the quadrature). Reported, and checked at ≥ 2.9; the
/// nodal values, the end forces and everything computed from them converge at order 4.
#[test]
fn catenary_end_tensions_and_fourth_order_positions() {
    let runs: Vec<_> = [2, 4, 8, 16, 32]
        .iter()
        .map(|&n| (n, catenary_errors(n)))
        .collect();
    for (n, (ea, eb, e)) in &runs {
        eprintln!(
            "N = {n:2}: end tension errors A {ea:.2e}, B {eb:.2e}; position errors nodes \
             {:.2e} m, shape {:.2e} m, material point {:.2e} m",
            e.nodes, e.shape, e.material
        );
    }
    let (ea, eb, _) = &runs[2].1;
    assert!(*ea < 3e-5 && *eb < 3e-5, "{ea:.2e} {eb:.2e}");
    let order = |a: Real, b: Real| (a / b).log2();
    for pair in runs.windows(2) {
        let ((n0, a), (n1, b)) = (&pair[0], &pair[1]);
        let orders = [
            ("end tension A", order(a.0, b.0), b.0 * 1e4, 3.7),
            ("nodes", order(a.2.nodes, b.2.nodes), b.2.nodes, 3.7),
            ("shape", order(a.2.shape, b.2.shape), b.2.shape, 2.9),
            (
                "material point",
                order(a.2.material, b.2.material),
                b.2.material,
                2.9,
            ),
        ];
        for (what, p, size, min) in orders {
            eprintln!("N = {n0} → {n1}: {what} order {p:.2}");
            if size > 1e-9 && *n0 >= 8 {
                assert!(p > min, "{what}: order {p:.2} between N = {n0} and {n1}");
            }
        }
    }
}

/// A straight beam pinned at both ends (fixed points; the end tangents are free, so the
/// moments vanish: simply supported), no gravity and no tension: transverse frequencies
/// ω_n = (nπ/L)² √(EI/γ) (Euler–Bernoulli). Each appears twice (two transverse planes).
/// Eigenvalues of the linearised K and M (the same force and mass code as the dynamics).
/// With 12 elements the Hermite beam element's frequency error grows as (n h)⁴ (measured
/// 4.6e-6, 5.2e-5, 2.6e-4 for n = 1, 2, 3: ratios 11 and 57 against 16 and 81): tolerance
/// 5e-4 on the lowest three, and 1e-5 on the first.
#[test]
fn simply_supported_beam_frequencies() {
    let (length, gamma, ei) = (10.0, 2.0, 500.0);
    let mut lt = dry_line_type(0.05, gamma, 1.0e7);
    lt.bending_stiffness = ei;
    let mut model = single_line(
        lt,
        length,
        12,
        fixed("A", Vec3::zeros()),
        fixed("B", Vec3::new(length, 0.0, 0.0)),
        MassMatrix::Consistent,
    );
    model.environment = vacuum_environment(0.0);
    model.lines[0].formulation = Formulation::Hermite;
    let system = System::new(&model).unwrap();
    let y = system.straight_state();
    let omegas = linearise(&system, &y, LinearisationOptions::default())
        .angular_frequencies()
        .expect("eigen solve");
    for n in 1..=3 {
        let exact = (n as Real * std::f64::consts::PI / length).powi(2) * (ei / gamma).sqrt();
        for plane in 0..2 {
            let w = omegas[2 * (n - 1) + plane];
            let e = (w - exact).abs() / exact;
            eprintln!("mode {n} plane {plane}: ω = {w:.6} rad/s vs {exact:.6} ({e:.2e})");
            assert!(
                e < if n == 1 { 1e-5 } else { 5e-4 },
                "mode {n}: {w} vs {exact}"
            );
        }
    }
}

/// The same catenary mooring with the seabed, solved by `fe` and by `hermite`: static end
/// tensions within 0.1 % on converged meshes (5 m elements for `hermite`,
/// 1.25 m for `fe`; the anchor tension converges slowly in both, through the kink of the
/// shape at the touchdown point: fe 280 → 560 elements and hermite 70 → 140 change it by
/// 0.1–0.5 %), and both within 0.2 % of the closed form with seabed contact.
#[test]
fn fe_and_hermite_agree_on_a_grounded_catenary() {
    let tensions = |formulation: Formulation, n: usize| {
        let mut m = single_line(
            line_type(0.137, 126.0, 5.8e8),
            700.0,
            n,
            fixed("anchor", Vec3::new(-600.0, 0.0, -150.0)),
            fixed("fairlead", Vec3::new(0.0, 0.0, -15.0)),
            MassMatrix::Consistent,
        );
        m.environment.depth = 150.0;
        m.environment.seabed.stiffness = 3.0e6;
        m.lines[0].formulation = formulation;
        let system = System::new(&m).unwrap();
        let sol = solve(&system, None, &StaticOptions::default()).expect("statics converges");
        let mut ws = system.workspace();
        evaluate(&system, &sol.state, &mut ws);
        (
            system.end_force(&ws, 0, false).norm(),
            system.end_force(&ws, 0, true).norm(),
        )
    };
    let fe = tensions(Formulation::Fe, 560);
    let he = tensions(Formulation::Hermite, 140);
    let w = (126.0 - 1025.0 * std::f64::consts::PI * 0.137f64.powi(2) / 4.0) * 9.80665;
    let exact = catenary::solve(600.0, 135.0, 700.0, w, 5.8e8, true).unwrap();
    for (what, a, b, c) in [
        ("anchor", fe.0, he.0, exact.tension_a()),
        ("fairlead", fe.1, he.1, exact.tension_b()),
    ] {
        let e = (a - b).abs() / a;
        eprintln!(
            "{what}: fe {a:.2} N, hermite {b:.2} N ({e:.2e}); closed form {c:.2} N (fe {:+.2e}, hermite {:+.2e})",
            a / c - 1.0,
            b / c - 1.0
        );
        assert!(e < 1e-3, "{what}: fe {a} vs hermite {b}");
        assert!((a / c - 1.0).abs() < 2e-3 && (b / c - 1.0).abs() < 2e-3);
    }
}

/// Records the tension at end B at every output sample.
struct Tensions(Vec<Real>);
impl hawser::simulation::Observer for Tensions {
    fn sample(
        &mut self,
        view: &hawser::session::View<'_>,
    ) -> Result<(), hawser::session::ObserverError> {
        let (system, ws) = (view.system, view.workspace);
        self.0.push(system.end_force(ws, 0, true).norm());
        Ok(())
    }
}

/// A chain hanging between an anchor and a fairlead that surges 2 m at 8 s (ramped over one
/// period), 16 s from the static state, RK4 at the automatic step: the fairlead tension
/// histories of `fe` (80 elements) and `hermite` (20 elements) agree within 1 % RMS of the
/// mean tension, on meshes whose own refinement changes them by less.
#[test]
fn fe_and_hermite_agree_on_a_moving_fairlead() {
    use hawser::model::{Motion, PointKind, Settings, TimeStep};
    let history = |formulation: Formulation, n: usize| {
        let mut fairlead = fixed("fairlead", Vec3::new(0.0, 0.0, -10.0));
        fairlead.kind = PointKind::Prescribed(Motion::Sinusoid {
            centre: Vec3::new(0.0, 0.0, -10.0),
            amplitude: Vec3::new(2.0, 0.0, 0.0),
            frequency: Vec3::new(1.0 / 8.0, 0.0, 0.0),
            phase: Vec3::zeros(),
            ramp: 8.0,
        });
        let mut lt = line_type(0.08, 40.0, 2.0e8);
        lt.axial_damping = hawser::physics::material::AxialDamping::Coefficient(1.0e5);
        let mut m = single_line(
            lt,
            130.0,
            n,
            fixed("anchor", Vec3::new(-110.0, 0.0, -60.0)),
            fairlead,
            MassMatrix::Consistent,
        );
        m.lines[0].formulation = formulation;
        m.settings = Settings {
            duration: 16.0,
            time_step: TimeStep::Auto,
            output_interval: 0.1,
            ..Default::default()
        };
        let system = System::new(&m).unwrap();
        let sol = solve(&system, None, &StaticOptions::default()).expect("statics");
        let mut sim = hawser::simulation::Simulation::new(&system, &m.settings, sol.state).unwrap();
        let mut out = Tensions(Vec::new());
        sim.run(m.settings.duration, &mut out).unwrap();
        out.0
    };
    let fe = history(Formulation::Fe, 80);
    let he = history(Formulation::Hermite, 20);
    let mean = fe.iter().sum::<Real>() / fe.len() as Real;
    let rms = |a: &[Real], b: &[Real]| {
        (a.iter().zip(b).map(|(x, y)| (x - y).powi(2)).sum::<Real>() / a.len() as Real).sqrt()
    };
    let range = fe.iter().cloned().fold(Real::MIN, Real::max)
        - fe.iter().cloned().fold(Real::MAX, Real::min);
    let e = rms(&fe, &he) / mean;
    eprintln!(
        "fairlead tension: mean {mean:.1} N, range {range:.1} N; fe 80 vs hermite 20 RMS difference {:.2e} of the mean",
        e
    );
    assert!(e < 1e-2, "RMS difference {e:.3e} of the mean tension");
}

/// A cantilever clamped horizontally at a wall (`clamp`), its free end on a massless free
/// point, sagging under its own weight in vacuum: statics with the clamp constraint (Newton
/// stalls here and falls back to dynamic relaxation, docs/hermite.md) against Euler–Bernoulli's tip deflection q L⁴/(8 EI) (small deflection: 1.2e-3 of L) and
/// tip slope q L³/(6 EI); then 2 s of RK4 dynamics released from the straight line, whose
/// tip must swing below the static deflection (to about twice it) and keep the clamped
/// tangent on its direction. Tolerance 1 % (geometric nonlinearity is O((δ/L)²) ≈ 1e-6; the
/// elements' error O(h⁴)).
#[test]
fn clamped_cantilever_sags_as_euler_bernoulli() {
    use hawser::model::{PointKind, Settings, TimeStep};
    let (length, gamma, ei) = (10.0, 10.0, 1.0e6);
    let g = 9.80665;
    let mut lt = dry_line_type(0.1, gamma, 1.0e9);
    lt.bending_stiffness = ei;
    // In air of zero density (z > 0): weight only.
    let mut tip = fixed("tip", Vec3::new(length, 0.0, 10.0));
    tip.kind = PointKind::Free {
        mass: 0.0,
        volume: 0.0,
        drag_area: 0.0,
        added_mass_coefficient: 0.0,
        force: Vec3::zeros(),
    };
    let mut m = single_line(
        lt,
        length,
        8,
        fixed("wall", Vec3::new(0.0, 0.0, 10.0)),
        tip,
        MassMatrix::Consistent,
    );
    m.environment = vacuum_environment(g);
    m.lines[0].formulation = Formulation::Hermite;
    m.lines[0].clamp[0] = Some(Vec3::x());
    let system = System::new(&m).unwrap();
    let sol = solve(&system, None, &StaticOptions::default()).expect("statics");
    let mut ws = system.workspace();
    evaluate(&system, &sol.state, &mut ws);
    eprintln!("statics: {} residual {:.2e}", sol.method, sol.residual);
    let q = gamma * g;
    let exact = q * length.powi(4) / (8.0 * ei);
    let l = &system.lines[0];
    let tip_z = 10.0 - ws.lines[0].position[l.node_vector(8)].z;
    let t = ws.lines[0].position[hawser::formulation::hermite::vector_index(8, true, 8)];
    let slope = -t.z / t.x;
    let exact_slope = q * length.powi(3) / (6.0 * ei);
    let clamp = ws.lines[0].position[1];
    eprintln!(
        "tip deflection {tip_z:.6e} m vs {exact:.6e}; tip slope {slope:.6e} vs {exact_slope:.6e}; clamp tangent {clamp:?}"
    );
    assert!((tip_z / exact - 1.0).abs() < 1e-2, "{tip_z} vs {exact}");
    assert!(
        (slope / exact_slope - 1.0).abs() < 1e-2,
        "{slope} vs {exact_slope}"
    );
    assert!(clamp.y.abs() < 1e-12 && clamp.z.abs() < 1e-12, "{clamp:?}");

    let settings = Settings {
        duration: 2.0,
        time_step: TimeStep::Auto,
        output_interval: 0.01,
        ..Default::default()
    };
    let mut sim =
        hawser::simulation::Simulation::new(&system, &settings, system.straight_state()).unwrap();
    struct Tip(Real, Vec3);
    impl hawser::simulation::Observer for Tip {
        fn sample(
            &mut self,
            view: &hawser::session::View<'_>,
        ) -> Result<(), hawser::session::ObserverError> {
            let (s, ws) = (view.system, view.workspace);
            let l = &s.lines[0];
            self.0 = self.0.max(10.0 - ws.lines[0].position[l.node_vector(8)].z);
            let c = ws.lines[0].position[1];
            self.1 = Vec3::new(0.0, self.1.y.max(c.y.abs()), self.1.z.max(c.z.abs()));
            Ok(())
        }
    }
    let mut out = Tip(0.0, Vec3::zeros());
    sim.run(settings.duration, &mut out).unwrap();
    eprintln!(
        "dynamic: largest tip deflection {:.4e} m ({:.3} × static)",
        out.0,
        out.0 / exact
    );
    assert!(
        out.0 > 1.5 * exact && out.0 < 2.5 * exact,
        "{} vs static {exact}",
        out.0
    );
    assert!(
        out.1.norm() < 1e-12,
        "clamped tangent left its direction: {:?}",
        out.1
    );
}

/// The two strain measures on a line stretched 20 % by a hanging mass (in vacuum, a line of
/// negligible mass): with the exact strain ε = |r'| − 1 the stretch λ = |r'| is 1 + T/EA.
/// With the paper's small strain ε = ½(λ² − 1) the energy ½∫EA ε² gives the force along the
/// line EA ε ∂ε/∂λ = EA ε λ, so T = EA ½(λ² − 1) λ: λ³ − λ − 2T/EA = 0 (λ = 1.1597 against
/// 1.2). Each within 1e-6 of its own closed form.
#[test]
fn strain_measures_give_their_closed_form_stretch() {
    use hawser::model::StrainMeasure;
    let (length, ea, mass, g) = (10.0, 1.0e4, 1.0e4 * 0.2 / 9.80665, 9.80665);
    let stretched = |measure: StrainMeasure| {
        let top = Vec3::new(0.0, 0.0, 100.0);
        let mut m = single_line(
            dry_line_type(0.01, 1.0e-6, ea),
            length,
            4,
            fixed("top", top),
            free("weight", top - Vec3::new(0.0, 0.0, length), mass, 0.0),
            MassMatrix::Consistent,
        );
        m.environment = vacuum_environment(g);
        m.lines[0].formulation = Formulation::Hermite;
        m.lines[0].strain_measure = measure;
        let system = System::new(&m).unwrap();
        let sol = solve(&system, None, &StaticOptions::default()).expect("statics");
        let mut ws = system.workspace();
        evaluate(&system, &sol.state, &mut ws);
        // The element tension channel is the force along the line: the weight it carries.
        for (e, t) in ws.lines[0].elements.tension.iter().enumerate() {
            assert!(
                (t / (mass * g) - 1.0).abs() < 1e-6,
                "{measure:?}: element {e} tension {t} vs {}",
                mass * g
            );
        }
        top.z - ws.points[1].position.z
    };
    let ratio = mass * g / ea;
    let exact = stretched(StrainMeasure::Exact);
    let small = stretched(StrainMeasure::SmallStrain);
    // Newton on λ³ − λ − 2T/EA = 0 from λ = 1 + T/EA.
    let mut lambda: Real = 1.0 + ratio;
    for _ in 0..50 {
        lambda -= (lambda.powi(3) - lambda - 2.0 * ratio) / (3.0 * lambda * lambda - 1.0);
    }
    let (e_exact, e_small) = (length * (1.0 + ratio), length * lambda);
    eprintln!(
        "exact strain: {exact:.9} m vs {e_exact:.9}; small strain: {small:.9} m vs {e_small:.9}"
    );
    assert!((exact / e_exact - 1.0).abs() < 1e-6, "{exact} vs {e_exact}");
    assert!((small / e_small - 1.0).abs() < 1e-6, "{small} vs {e_small}");
}
