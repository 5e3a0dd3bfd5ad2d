//! Rigid bodies in the linearisation (docs/modes.md): the 6×6 mooring stiffness at a body
//! against MoorPy and against finite differences of static solutions, and the coupled modes
//! of a free body on a line against closed forms.

use hawser::analysis::modes::{ModalOptions, ModeDirection, ModeOwner, natural_modes};
use hawser::linearise::{LinearisationOptions, body_stiffness, linearise};
use hawser::math::{Mat6, Quat, Real, Vec3};
use hawser::model::{BodyKind, Model};
use hawser::statics::{StaticOptions, evaluate, solve};
use hawser::system::System;
use hawser_io::moordyn::{self, ConvertOptions};
use std::path::{Path, PathBuf};

fn data() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/data")
}

fn deck(name: &str) -> Model {
    moordyn::load(
        &data().join("moordyn").join(name),
        &ConvertOptions::default(),
    )
    .unwrap_or_else(|e| panic!("{e}"))
    .loaded
    .model
}

/// The 6×6 mooring stiffness of every body of `model` at its static state.
fn stiffness(model: &Model) -> Vec<Mat6> {
    let system = System::new(model).unwrap();
    let sol = solve(&system, None, &StaticOptions::default()).unwrap();
    let lin = linearise(&system, &sol.state, LinearisationOptions::default());
    body_stiffness(&system, &lin)
        .unwrap()
        .into_iter()
        .map(|b| b.matrix)
        .collect()
}

/// Largest |A_ij − B_ij| / √(|B_ii B_jj|): each entry against the geometric mean of its row's
/// and column's diagonal (the scale of a coupling term between two degrees of freedom).
fn normalised_difference(a: &Mat6, b: &Mat6) -> (Real, (usize, usize)) {
    let mut worst = (0.0, (0, 0));
    for i in 0..6 {
        for j in 0..6 {
            let d = (a[(i, j)] - b[(i, j)]).abs() / (b[(i, i)] * b[(j, j)]).abs().sqrt();
            if d > worst.0 {
                worst = (d, (i, j));
            }
        }
    }
    worst
}

/// OC3's three lines (20 segments each, as in the deck) on a coupled body at the origin:
/// hawser's condensed 6×6 stiffness against MoorPy 1.3's analytic coupled stiffness
/// (`tests/data/moorpy_oc3_stiffness.json`, recorded by `scripts/moorpy_stiffness.sh`), every
/// entry within 1 % of its diagonal scale √(K_ii K_jj). The two codes discretise the line
/// differently (hawser's lumped finite elements with seabed springs, MoorPy's closed-form
/// elastic catenary on a rigid bed): measured 1.9e-3 (yaw), 1e-3 (heave); the diagonal
/// entries K11 = 41.20 / 41.20 kN/m, K33 = 11.96 / 11.95 kN/m, K44 = K55 = 3.108e8 / 3.109e8
/// N·m/rad, K66 = 1.1545e7 / 1.1567e7 N·m/rad. The geometric terms make both matrices
/// non-symmetric in the same way (K46 = −5.14e3, K64 = −1.05e4 N·m/rad in both).
#[test]
fn oc3_body_stiffness_matches_moorpy() {
    let text = std::fs::read_to_string(data().join("moorpy_oc3_stiffness.json")).unwrap();
    let reference: serde_json::Value = serde_json::from_str(&text).unwrap();
    let m = &reference["analytic"];
    let moorpy = Mat6::from_fn(|i, j| m[i][j].as_f64().unwrap());
    let k = stiffness(&deck("oc3_body.txt"));
    assert_eq!(k.len(), 1);
    let (worst, at) = normalised_difference(&k[0], &moorpy);
    eprintln!(
        "hawser\n{}MoorPy\n{}worst {worst:.2e} at {at:?}",
        k[0], moorpy
    );
    assert!(worst < 1e-2, "{worst:.2e} at {at:?}");
}

/// The lines' load Q = [F; M_o] on the coupled body of `model` at `pose` (lines solved).
fn line_load(model: &Model, position: Vec3, orientation: Quat) -> [Real; 6] {
    let mut model = model.clone();
    model.bodies[0].position = position;
    model.bodies[0].orientation = orientation;
    let system = System::new(&model).unwrap();
    let options = StaticOptions {
        relative_tolerance: 1e-12,
        ..StaticOptions::default()
    };
    let sol = solve(&system, None, &options).unwrap();
    let mut ws = system.workspace();
    evaluate(&system, &sol.state, &mut ws);
    let view = hawser::session::View {
        system: &system,
        workspace: &ws,
        time: 0.0,
        state: &sol.state,
        channels: &[],
        sample: 0,
        releases: &[],
    };
    view.body_line_load(0)
}

/// The condensed stiffness equals −∂Q/∂q by central differences of static solutions, the body
/// (coupled) moved by ±1 cm and turned by ±10⁻⁴ rad about each global axis with the lines
/// re-solved: OC3 on its body, and the test buoy (buoy_oc3.txt) at its static pose, where the
/// free body's stiffness (the same condensation with the free body held) must equal the
/// coupled one's. Tolerance 10⁻⁴ of the diagonal scale: the differences' truncation
/// (h²/6 K''') and the statics' residual (10⁻⁹ N) over 2h; measured below 3e-6.
#[test]
fn body_stiffness_equals_finite_differences_of_statics() {
    let oc3 = deck("oc3_body.txt");
    // The buoy, free, then held as a coupled body at its static pose.
    let buoy = deck("buoy_oc3.txt");
    let system = System::new(&buoy).unwrap();
    let sol = solve(&system, None, &StaticOptions::default()).unwrap();
    let mut ws = system.workspace();
    evaluate(&system, &sol.state, &mut ws);
    let pose = ws.bodies[0];
    let free = stiffness(&buoy)[0];
    let mut held = buoy.clone();
    held.bodies[0].kind = BodyKind::Coupled;
    held.bodies[0].position = pose.position;
    held.bodies[0].orientation = pose.orientation;
    for (name, model, k) in [
        ("OC3", oc3.clone(), stiffness(&oc3)[0]),
        ("buoy (held)", held.clone(), stiffness(&held)[0]),
        ("buoy (free)", held.clone(), free),
    ] {
        let (x0, q0) = (model.bodies[0].position, model.bodies[0].orientation);
        let mut fd = Mat6::zeros();
        for axis in 0..6 {
            let h = if axis < 3 { 1e-2 } else { 1e-4 };
            let load = |by: Real| {
                let (mut x, mut q) = (x0, q0);
                if axis < 3 {
                    x[axis] += by;
                } else {
                    q = Quat::from_scaled_axis(Vec3::ith(axis - 3, by)) * q;
                }
                line_load(&model, x, q)
            };
            let (plus, minus) = (load(h), load(-h));
            for i in 0..6 {
                fd[(i, axis)] = -(plus[i] - minus[i]) / (2.0 * h);
            }
        }
        let (worst, at) = normalised_difference(&k, &fd);
        eprintln!("{name}: condensed vs finite differences {worst:.2e} at {at:?}");
        assert!(worst < 1e-4, "{name}: {worst:.2e} at {at:?}");
    }
}

/// A buoyant sphere-like body on a vertical tether of neutral buoyancy (γ0 = ρA, no added mass
/// on the line: the tension T is uniform), in still water without current: its coupled modes
/// against the closed forms of a string or rod fixed at the bottom with a mass M at the top,
/// β L tan β L = γ0 L0 / M, with ω = β c, c = √(T L/(γ0 L0)) across on the stretched length
/// L (M = m + A₁₁) and √(EA/γ0) along on the unstretched L0 (M = m + A₃₃); the roll and pitch of the body, whose buoyancy acts 1 m above its origin
/// (where the tether, the weight and the added mass act: `hydrodynamic_centre` at the origin
/// keeps translation and rotation uncoupled), ω² = ρ g V · 1 m / (I + A_rot); yaw has no
/// stiffness (ω = 0). 100 elements: the string's discretisation error θ²/24 with θ = βL/N is
/// below 1e-5. Labels name the body's axes.
#[test]
fn free_body_on_a_tether_has_the_closed_form_modes() {
    let (rho, g) = (1025.0, 9.80665);
    let (d, length, ea) = (0.05, 100.0, 5.0e6);
    let area = std::f64::consts::PI * d * d / 4.0;
    let gamma = rho * area;
    let (mass, volume, added) = (2000.0, 4.0, 1000.0);
    let tension = (rho * volume - mass) * g;
    let text = format!(
        r#"
[simulation]
duration = 1.0

[environment]
depth = 200.0

[[line_types]]
name = "tether"
diameter = {d}
mass_per_length = {gamma}
axial_stiffness = {ea}
normal_drag = 1.0
tangential_drag = 0.0
normal_added_mass = 0.0
tangential_added_mass = 0.0

[[points]]
name = "anchor"
type = "fixed"
position = [0.0, 0.0, -150.0]

[[points]]
name = "eye"
type = "body"
body = "buoy"
position = [0.0, 0.0, 0.0]

[[lines]]
name = "tether"
type = "tether"
length = {length}
elements = 100
end_a = "anchor"
end_b = "eye"

[[bodies]]
name = "buoy"
type = "free"
position = [0.0, 0.0, -50.0]
mass = {mass}
inertia = [500.0, 500.0, 400.0]
displacement = {{ type = "submerged", volume = {volume} }}
centre_of_buoyancy = [0.0, 0.0, 1.0]
hydrodynamic_centre = [0.0, 0.0, 0.0]
added_mass = [{added}, {added}, {added}, 100.0, 100.0, 0.0]
"#
    );
    let path = Path::new("tether.toml");
    let model = hawser_io::scenario::parse(path, &text)
        .unwrap_or_else(|e| panic!("{e}"))
        .model;
    let system = System::new(&model).unwrap();
    let sol = solve(&system, None, &StaticOptions::default()).unwrap();
    let lin = linearise(&system, &sol.state, LinearisationOptions::default());
    let modes = natural_modes(
        &system,
        &lin,
        &ModalOptions {
            count: 12,
            ..Default::default()
        },
    )
    .unwrap();
    // The stretched length L = L0 (1 + T/EA) carries the same mass γ0 L0.
    let stretched = length * (1.0 + tension / ea);
    let line_mass = gamma * length;
    // Smallest root of β L tan β L = μ (μ = line mass / end mass), by bisection on (0, π/2).
    let root = |mu: Real| {
        let (mut lo, mut hi) = (0.0, std::f64::consts::FRAC_PI_2 - 1e-12);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if mid * mid.tan() < mu {
                lo = mid
            } else {
                hi = mid
            }
        }
        0.5 * (lo + hi)
    };
    // Across: the string's mass per stretched length is γ0 L0 / L, so c = √(T L / (γ0 L0)).
    let across = root(line_mass / (mass + added)) / stretched
        * (tension * stretched / (gamma * length)).sqrt()
        / std::f64::consts::TAU;
    // Along the tether the stiffness is EA on the unstretched length (ε = L/L0 − 1).
    let along =
        root(line_mass / (mass + added)) / length * (ea / gamma).sqrt() / std::f64::consts::TAU;
    let rocking = (rho * g * volume * 1.0 / (500.0 + 100.0)).sqrt() / std::f64::consts::TAU;
    let find = |direction: ModeDirection| {
        modes
            .modes
            .iter()
            .filter(|m| m.label.direction == direction)
            .map(|m| m.frequency)
            .collect::<Vec<_>>()
    };
    for m in &modes.modes {
        eprintln!("{:.6} Hz  {}", m.frequency, m.label.text);
    }
    let (surge, sway, heave) = (
        find(ModeDirection::Surge),
        find(ModeDirection::Sway),
        find(ModeDirection::Heave),
    );
    let (roll, pitch, yaw) = (
        find(ModeDirection::Roll),
        find(ModeDirection::Pitch),
        find(ModeDirection::Yaw),
    );
    eprintln!(
        "across {across:.6} Hz: surge {surge:?}, sway {sway:?}; along {along:.6} Hz: heave \
         {heave:?}; rocking {rocking:.6} Hz: roll {roll:?}, pitch {pitch:?}; yaw {yaw:?}"
    );
    let error = |f: &[Real], exact: Real| {
        f.iter()
            .map(|x| ((x - exact) / exact).abs())
            .fold(Real::INFINITY, Real::min)
    };
    eprintln!(
        "relative errors: surge {:.1e}, heave {:.1e}, roll {:.1e}",
        error(&surge, across),
        error(&heave, along),
        error(&roll, rocking)
    );
    let close =
        |f: &[Real], exact: Real, tol: Real| f.iter().any(|x| ((x - exact) / exact).abs() < tol);
    // 1e-5: the closed forms' continuum against 100 elements (θ²/24 ≈ 1e-6 across, less
    // along) and the finite-difference stiffness (1e-9); measured 1.3e-7 and 6e-9.
    assert!(close(&surge, across, 1e-5) && close(&sway, across, 1e-5));
    assert!(close(&heave, along, 1e-5));
    assert!(close(&roll, rocking, 1e-6) && close(&pitch, rocking, 1e-6));
    assert!(yaw.first().is_some_and(|f| *f < 1e-6 * across), "{yaw:?}");
    assert!(
        modes
            .modes
            .iter()
            .any(|m| m.label.owners.contains(&ModeOwner::Body(0))
                && m.label.text.starts_with("first surge mode of body buoy"))
    );
}
