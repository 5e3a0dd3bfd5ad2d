//! Elastic catenary statics against the closed form ([`crate::statics::catenary`]), suspended
//! and resting on the seabed, and the observed order of convergence in h.

use super::*;
use crate::physics::seabed::Bathymetry;
use crate::statics::{StaticOptions, catenary, evaluate, solve};
use std::f64::consts::PI;

/// Suspended line: diameter [m], γ0 [kg/m], EA [N], unstretched length [m].
const SUSPENDED: (Real, Real, Real, Real) = (0.05, 20.0, 5.0e7, 110.0);
/// Its ends: A at 500 m depth, B 80 m along x and 60 m up.
const END_A: Vec3 = Vec3::new(0.0, 0.0, -500.0);
const END_B: Vec3 = Vec3::new(80.0, 0.0, -440.0);

/// The suspended catenary: a 110 m line (d 0.05 m, 20 kg/m, EA 5e7 N) in deep water between
/// fixed points 80 m apart horizontally and 60 m vertically, with `elements` elements.
pub fn suspended_line(formulation: Formulation, mass_matrix: MassMatrix, elements: usize) -> Model {
    let (d, gamma, ea, length) = SUSPENDED;
    single_line(
        line_type(d, gamma, ea),
        length,
        elements,
        (fixed("A", END_A), fixed("B", END_B)),
        formulation,
        mass_matrix,
    )
}

/// The closed form of the suspended case.
fn suspended_exact() -> catenary::Catenary {
    let (d, gamma, ea, length) = SUSPENDED;
    let w = (gamma - 1025.0 * PI * d * d / 4.0) * 9.80665;
    let span = END_B - END_A;
    catenary::solve(span.x, span.z, length, w, ea, false).expect("the closed form solves")
}

/// The OC3 chain (902.2 m, d 0.09 m, 77.7066 kg/m, EA 384.243 MN) from an anchor on the bed
/// at (−848.67, 0, −320) to a fixed fairlead at `fairlead` ((0, 0, −70) in the deck), in
/// 320 m of water on a stiff, frictionless bed (3e7 Pa/m: penetration w/(K_g d) ≈ 0.3 mm, so
/// the touchdown is where the rigid-bed closed form puts it).
pub fn grounded_chain(formulation: Formulation, elements: usize, fairlead: Vec3) -> Model {
    let mut model = single_line(
        line_type(0.09, 77.7066, 384.243e6),
        902.2,
        elements,
        (
            fixed("anchor", Vec3::new(-848.67, 0.0, -320.0)),
            fixed("fairlead", fairlead),
        ),
        formulation,
        MassMatrix::Consistent,
    );
    model.environment.depth = 320.0;
    model.environment.seabed.stiffness = 3.0e7;
    model
}

/// Static end tensions [N] (A, B) and node positions [m] of line 0 of a model.
pub(crate) fn static_ends(
    model: &Model,
    options: &StaticOptions,
) -> Result<(Real, Real, Vec<Vec3>), CaseError> {
    let system = assemble(model)?;
    let sol = solve(&system, None, options)?;
    let mut ws = system.workspace();
    evaluate(&system, &sol.state, &mut ws);
    let nodes = (0..=model.lines[0].elements())
        .map(|i| node_position(&system, &ws, 0, i))
        .collect();
    Ok((
        system.end_force(&ws, 0, false).norm(),
        system.end_force(&ws, 0, true).norm(),
        nodes,
    ))
}

/// The computed shape (markers) against the closed form (line), in the x–z plane relative to
/// end A.
fn shape_plot(
    name: &str,
    title: &str,
    exact: &catenary::Catenary,
    origin: Vec3,
    nodes: &[Vec3],
) -> Plot {
    let length = exact.length;
    let (xe, ze): (Vec<Real>, Vec<Real>) = (0..=200)
        .map(|k| exact.position(length * k as Real / 200.0))
        .unzip();
    let (xn, zn) = nodes
        .iter()
        .map(|p| (p.x - origin.x, p.z - origin.z))
        .unzip();
    Plot {
        name: name.into(),
        title: title.into(),
        x_label: "x from end A [m]".into(),
        y_label: "z from end A [m]".into(),
        log: false,
        series: vec![
            Series {
                label: "closed form".into(),
                x: xe,
                y: ze,
                markers: false,
            },
            Series {
                label: "hawser nodes".into(),
                x: xn,
                y: zn,
                markers: true,
            },
        ],
    }
}

/// Suspended catenary at 100 elements (both fidelities: statics is cheap).
///
/// Tolerances: 0.1 % on end tensions (the issue's; the end force converges as O(h²) and the
/// `fe` error at 100 elements is ~1e-5), 0.05 m on the mid-span node (5e-4 of the length;
/// `fe` nodes sit O(h²) ≈ 1e-3 m off the closed form at 100 elements).
pub fn suspended_catenary(f: Formulation, _fidelity: Fidelity) -> Result<Findings, CaseError> {
    let exact = suspended_exact();
    let elements = 100;
    let model = suspended_line(f, MassMatrix::Consistent, elements);
    let (ta, tb, nodes) = static_ends(&model, &StaticOptions::default())?;
    let (x, z) = exact.position(0.5 * exact.length);
    let mid = nodes[elements / 2] - END_A;
    Ok(Findings {
        checks: vec![
            Check::new(
                "end A tension",
                "N",
                exact.tension_a(),
                ta,
                Tolerance::Relative(1e-3),
            ),
            Check::new(
                "end B tension",
                "N",
                exact.tension_b(),
                tb,
                Tolerance::Relative(1e-3),
            ),
            Check::new("mid-span node x", "m", x, mid.x, Tolerance::Absolute(0.05)),
            Check::new("mid-span node z", "m", z, mid.z, Tolerance::Absolute(0.05)),
        ],
        plots: vec![shape_plot(
            "shape",
            "Suspended elastic catenary, 100 elements",
            &exact,
            END_A,
            &nodes,
        )],
    })
}

/// Catenary on a frictionless seabed (OC3 chain, 200 elements).
///
/// Tolerance 0.1 % on end tensions, as the suspended case; the touchdown point adds an
/// O(h) kink error that the stiff bed keeps below 1e-4 at 200 elements for `fe`.
pub fn grounded_catenary(f: Formulation, _fidelity: Fidelity) -> Result<Findings, CaseError> {
    let (d, m, ea) = (0.09, 77.7066, 384.243e6);
    let w = (m - 1025.0 * PI * d * d / 4.0) * 9.80665;
    let anchor = Vec3::new(-848.67, 0.0, -320.0);
    let model = grounded_chain(f, 200, Vec3::new(0.0, 0.0, -70.0));
    let exact = catenary::solve(848.67, 250.0, 902.2, w, ea, true)
        .ok_or_else(|| CaseError::Failed("the closed form has no solution".into()))?;
    if !(exact.grounded_length > 10.0) {
        return Err(CaseError::Failed(format!(
            "the case must have line on the bed (grounded {:.1} m)",
            exact.grounded_length
        )));
    }
    let (ta, tb, nodes) = static_ends(&model, &StaticOptions::default())?;
    Ok(Findings {
        checks: vec![
            Check::new(
                "anchor tension",
                "N",
                exact.tension_a(),
                ta,
                Tolerance::Relative(1e-3),
            ),
            Check::new(
                "fairlead tension",
                "N",
                exact.tension_b(),
                tb,
                Tolerance::Relative(1e-3),
            ),
        ],
        plots: vec![shape_plot(
            "shape",
            "Catenary on the seabed (OC3 chain), 200 elements",
            &exact,
            anchor,
            &nodes,
        )],
    })
}

/// The OC3 chain of [`grounded_chain`] (anchor on the bed at (−848.67, 0, −320), fairlead at
/// (0, 0, −70)) on a frictionless bed through the anchor that slopes along x at tan α =
/// `slope` (rising toward the fairlead when positive): depth 320 − 848.67 tan α at the origin.
pub fn sloped_chain(formulation: Formulation, elements: usize, slope: Real) -> Model {
    let mut model = grounded_chain(formulation, elements, Vec3::new(0.0, 0.0, -70.0));
    model.environment.depth = 320.0 - 848.67 * slope;
    model.environment.bathymetry = Bathymetry::Plane {
        gradient: [slope, 0.0],
    };
    model
}

/// Catenary on a frictionless sloping seabed (OC3 chain, 200 elements), the bed rising toward
/// the fairlead at tan α = 0.05 and falling at tan α = −0.05, against the closed form of
/// [`catenary::solve_on_slope`] (docs/seabed.md).
///
/// Tolerance 0.1 % on end tensions, as on the flat bed: the stiff bed (3e7 Pa/m) holds the
/// chain 0.3 mm below the plane along its normal, and the touchdown's O(h) kink error stays
/// below 1e-4 at 200 elements.
pub fn sloped_catenary(f: Formulation, _fidelity: Fidelity) -> Result<Findings, CaseError> {
    let (d, m, ea) = (0.09, 77.7066, 384.243e6);
    let w = (m - 1025.0 * PI * d * d / 4.0) * 9.80665;
    let mut checks = Vec::new();
    let mut plots = Vec::new();
    for slope in [0.05, -0.05] {
        let model = sloped_chain(f, 200, slope);
        let anchor = model.points[0].position;
        let exact = catenary::solve_on_slope(848.67, 250.0, 902.2, w, ea, slope)
            .ok_or_else(|| CaseError::Failed("the closed form has no solution".into()))?;
        if !(exact.grounded_length > 10.0) {
            return Err(CaseError::Failed(format!(
                "the case must have line on the bed (grounded {:.1} m)",
                exact.grounded_length
            )));
        }
        let (ta, tb, nodes) = static_ends(&model, &StaticOptions::default())?;
        let name = if slope > 0.0 { "rising" } else { "falling" };
        checks.push(Check::new(
            format!("anchor tension, bed {name} at tan α = {}", slope.abs()),
            "N",
            exact.tension_a(),
            ta,
            Tolerance::Relative(1e-3),
        ));
        checks.push(Check::new(
            format!("fairlead tension, bed {name} at tan α = {}", slope.abs()),
            "N",
            exact.tension_b(),
            tb,
            Tolerance::Relative(1e-3),
        ));
        plots.push(shape_plot(
            &format!("shape_{name}"),
            &format!(
                "Catenary on a frictionless bed {name} toward the fairlead (tan α = {}), 200 elements",
                slope.abs()
            ),
            &exact,
            anchor,
            &nodes,
        ));
    }
    Ok(Findings { checks, plots })
}

/// Errors of one mesh of the convergence study.
#[derive(Clone, Debug, PartialEq)]
pub struct ConvergenceSample {
    /// Elements N.
    pub elements: usize,
    /// |T_A/T_A,exact − 1|.
    pub end_a: Real,
    /// |T_B/T_B,exact − 1|.
    pub end_b: Real,
    /// |r_mid − r_mid,exact| / L of the mid-span node.
    pub mid_node: Real,
    /// Static residual [N].
    pub residual: Real,
}

/// Relative errors of the suspended catenary at each mesh of `meshes` against the closed
/// form.
///
/// Static residual 1e-9 of the line weight (the default): its effect on the results
/// (≈ 1e-9 relative) is far below the smallest discretisation error measured (2.3e-5 for
/// `fe` at N = 64), and it stays above the rounding floor of the force evaluation (positions
/// ≈ 500 m carry ≈ 1e-13 m, times EA/L0 ≈ 4e6–3e7 N/m: ~1e-6 N, 5e-11 of the weight).
pub fn catenary_errors(
    formulation: Formulation,
    mass_matrix: MassMatrix,
    meshes: &[usize],
) -> Result<Vec<ConvergenceSample>, CaseError> {
    catenary_errors_of_order(formulation, mass_matrix, meshes, DG_ORDER)
}

/// The polynomial order of `dg` lines in the verification models (the DG paper's P = 4).
pub const DG_ORDER: usize = 4;

/// [`catenary_errors`] with `dg` sections of polynomial order `order`.
pub fn catenary_errors_of_order(
    formulation: Formulation,
    mass_matrix: MassMatrix,
    meshes: &[usize],
    order: usize,
) -> Result<Vec<ConvergenceSample>, CaseError> {
    let exact = suspended_exact();
    let (mx, mz) = exact.position(0.5 * exact.length);
    let mid_exact = END_A + Vec3::new(mx, 0.0, mz);
    let options = StaticOptions {
        relative_tolerance: 1e-9,
        ..Default::default()
    };
    meshes
        .iter()
        .map(|&n| {
            let mut model = suspended_line(formulation, mass_matrix, n);
            model.lines[0]
                .sections
                .iter_mut()
                .for_each(|s| s.order = order);
            let system = assemble(&model)?;
            let sol = solve(&system, None, &options)?;
            let mut ws = system.workspace();
            evaluate(&system, &sol.state, &mut ws);
            let ta = system.end_force(&ws, 0, false).norm();
            let tb = system.end_force(&ws, 0, true).norm();
            let mid = node_position(&system, &ws, 0, n / 2);
            Ok(ConvergenceSample {
                elements: n,
                end_a: (ta / exact.tension_a() - 1.0).abs(),
                end_b: (tb / exact.tension_b() - 1.0).abs(),
                mid_node: (mid - mid_exact).norm() / exact.length,
                residual: sol.residual,
            })
        })
        .collect()
}

/// Expected order of convergence in h of node positions and end forces: `fe` 2 (linear
/// elements), `hermite` 4 (cubic interpolation); `dg`: not measured on statics (see
/// [`catenary_convergence`]).
pub fn expected_order(f: Formulation) -> Option<Real> {
    match f {
        Formulation::Fe => Some(2.0),
        Formulation::Hermite => Some(4.0),
        Formulation::Dg => None,
    }
}

/// Observed order of convergence in h on the suspended catenary, whose exact solution (the
/// closed-form elastic catenary) is smooth: for second order N = 8, 16, 32, 64 (and 128 in
/// the full suite); for fourth order N = 8, 16, 32, whose errors stay well above the static
/// solution's 1e-9 (at N = 64 a fourth-order error is there).
///
/// Tolerance ±0.2 on each observed order: in a clean asymptotic regime the higher-order
/// terms perturb the ratio of successive errors by a few %; an order 1 lower or higher is a
/// different scheme. Linear elements with the weight lumped at the nodes make the chain a
/// polygon whose nodes are O(h²) off the catenary, and the end force (end element tension
/// plus half an element's weight) is O(h²) too.
pub fn catenary_convergence(f: Formulation, fidelity: Fidelity) -> Result<Findings, CaseError> {
    let Some(expected) = expected_order(f) else {
        return Err(CaseError::NotAvailable(
            "dg statics run through the hermite twin and a Newton refinement on the dg \
             equations, whose errors on coarse meshes are not in a clean asymptotic range \
             (P = 1: 2.7e-2, 5.3e-4, 8.7e-5 at N = 8, 16, 32); the dg order is verified in time \
             by the ring beam (tests/dg_ring.rs: rates 2.05, 3.07, 3.98, 4.96, 5.96 for \
             P = 1..5)"
                .into(),
        ));
    };
    // Meshes in the asymptotic range and above the static solution's accuracy (1e-9):
    // second order from N = 8; fourth order is pre-asymptotic below N = 8 (measured orders
    // 2.9–4.6 for `hermite` at N = 2→4→8) and meets 1e-9 near N = 64.
    let meshes: &[usize] = match (expected > 3.0, fidelity) {
        (false, Fidelity::Quick) => &[8, 16, 32, 64],
        (false, Fidelity::Full) => &[8, 16, 32, 64, 128],
        (true, _) => &[8, 16, 32],
    };
    let samples = catenary_errors(f, MassMatrix::Consistent, meshes)?;
    let mut checks = Vec::new();
    let mut series = Vec::new();
    let h: Vec<Real> = samples
        .iter()
        .map(|s| SUSPENDED.3 / s.elements as Real)
        .collect();
    type Pick = fn(&ConvergenceSample) -> Real;
    let quantities: [(&str, Pick); 3] = [
        ("mid-span node position", |s| s.mid_node),
        ("end A tension", |s| s.end_a),
        ("end B tension", |s| s.end_b),
    ];
    for (what, pick) in quantities {
        let errors: Vec<Real> = samples.iter().map(pick).collect();
        for (k, p) in observed_orders(&errors).into_iter().enumerate() {
            checks.push(Check::new(
                format!(
                    "order of {what}, N = {}→{}",
                    samples[k].elements,
                    samples[k + 1].elements
                ),
                "-",
                expected,
                p,
                Tolerance::Absolute(0.2),
            ));
        }
        series.push(Series {
            label: format!("{what} (relative error)"),
            x: h.clone(),
            y: errors,
            markers: true,
        });
    }
    // The slope of the expected order through the finest mid-node error, for the eye.
    let last = samples.last().expect("meshes");
    series.push(Series {
        label: format!("slope {expected}"),
        x: h.clone(),
        y: h.iter()
            .map(|hk| last.mid_node * (hk / h[h.len() - 1]).powf(expected))
            .collect(),
        markers: false,
    });
    Ok(Findings {
        checks,
        plots: vec![Plot {
            name: "errors".into(),
            title: "Suspended catenary: error against the closed form".into(),
            x_label: "element length h [m]".into(),
            y_label: "relative error [-]".into(),
            log: true,
            series,
        }],
    })
}
