//! Lines in contact with obstacles ([`hawser::physics::obstacles`]): statics
//! over a frictionless cylinder against the exact equilibrium and the frictionless tension
//! law; the capstan equation with friction in steady sliding; a line draped on a sphere with
//! the penetration of the penalty law; a moving cylinder sweeping a slack line, its force
//! channel against the change of the line's momentum and against the dynamics' own node
//! forces; `fe` and `hermite` drapes against each other; a `dg` line's momentum rate against
//! the channels.

use hawser::analysis::Channel;
use hawser::analysis::obstacles::{ObstacleLoad, obstacle_forces};
use hawser::formulation::LoadOptions;
use hawser::math::{Real, Vec3};
use hawser::model::*;
use hawser::physics::material::AxialDamping;
use hawser::physics::obstacles::{Obstacle, ObstacleDamping, ObstacleShape};
use hawser::simulation::Simulation;
use hawser::statics::{StaticOptions, evaluate, solve};
use hawser::system::{System, Workspace};
use hawser::verification as v;
use std::f64::consts::PI;

const G: Real = 9.80665;

/// A fixed cylinder about `centre`.
fn cylinder(
    centre: Vec3,
    radius: Real,
    axis: Vec3,
    length: Option<Real>,
    stiffness: Real,
    mu: Real,
) -> Obstacle {
    Obstacle {
        name: "drum".into(),
        shape: ObstacleShape::Cylinder {
            radius,
            axis,
            length,
        },
        motion: Motion::Fixed { position: centre },
        stiffness,
        damping: ObstacleDamping::Ratio(1.0),
        friction_coefficient: mu,
        friction_velocity: 0.01,
    }
}

/// The total force [N] of the obstacle channels of obstacle `k` at time `t`.
fn channel_force(system: &System, ws: &Workspace, t: Real, k: usize) -> Vec3 {
    Vec3::from_fn(|axis, _| Channel::ObstacleForce { obstacle: k, axis }.value_at(system, ws, t))
}

/// A path of a straight run, an arc and a straight run, as positions at arc length s [m]:
/// from `start` along the unit `first` for `a` metres, round the circle of radius `r` about
/// `centre` in the plane of `e1`, `e2` from the angle `phi0` through the signed angle `arc`
/// (toward `e2` from `e1` when positive), then along the unit `last`.
struct Path {
    centre: Vec3,
    a: Real,
    r: Real,
    arc: Real,
    start: Vec3,
    first: Vec3,
    e1: Vec3,
    e2: Vec3,
    phi0: Real,
    last: Vec3,
}

impl Path {
    fn at(&self, s: Real) -> Vec3 {
        if s <= self.a {
            return self.centre + self.start + self.first * s;
        }
        let arc_end = self.a + self.r * self.arc.abs();
        if s <= arc_end {
            let phi = self.phi0 + (s - self.a) / self.r * self.arc.signum();
            return self.centre + (self.e1 * phi.cos() + self.e2 * phi.sin()) * self.r;
        }
        let phi = self.phi0 + self.arc;
        self.centre
            + (self.e1 * phi.cos() + self.e2 * phi.sin()) * self.r
            + self.last * (s - arc_end)
    }
}

/// The statics of (a): a light line (d = 2 cm, 0.1 kg/m, EA = 1 MN) from an anchor level with
/// the top of a frictionless horizontal drum (axis y, R = 0.5 m, k = 1e6 N/m², in air) runs
/// over it and carries a 20 kg mass hanging on the far side; `elements` of `formulation`.
/// Returns the system, the static state and a workspace holding its evaluation.
fn drum_statics(formulation: Formulation, elements: usize) -> (System, Vec<Real>, Workspace) {
    let (r, d, gamma, mass) = (0.5, 0.02, 0.1, 20.0);
    let rc = r + 0.5 * d;
    let a = 2.0;
    let length = a + 0.5 * PI * rc + a;
    // In air (z > 0), where the line has no buoyancy.
    let centre = Vec3::new(0.0, 0.0, 10.0);
    let path = Path {
        centre,
        a,
        r: rc,
        arc: -0.5 * PI,
        start: Vec3::new(-a, 0.0, rc),
        first: Vec3::x(),
        e1: Vec3::x(),
        e2: Vec3::z(),
        phi0: 0.5 * PI,
        last: -Vec3::z(),
    };
    let mut model = v::single_line(
        v::dry_line_type(d, gamma, 1.0e6),
        length,
        elements,
        (
            v::fixed("anchor", path.at(0.0)),
            v::free("mass", path.at(length), mass, 0.0),
        ),
        formulation,
        MassMatrix::Consistent,
    );
    model.environment = v::vacuum_environment(G);
    model
        .environment
        .obstacles
        .push(cylinder(centre, r, Vec3::y(), None, 1.0e6, 0.0));
    let system = System::new(&model).unwrap();
    let mut y = system.straight_state();
    system.set_line_shape(&mut y, 0, |s| (path.at(s), Vec3::zeros()));
    v::set_point_state(&system, &mut y, 1, path.at(length), Vec3::zeros());
    let sol = solve(&system, Some(&y), &StaticOptions::default()).expect("statics converge");
    let mut ws = system.workspace();
    let residual = evaluate(&system, &sol.state, &mut ws);
    eprintln!(
        "{formulation:?} {elements}: {} in {} iterations, residual {residual:.2e} N",
        sol.method, sol.iterations
    );
    (system, sol.state, ws)
}

/// (a) Statics over a frictionless cylinder ([`drum_statics`]). Checks: (1) the obstacle
/// channel equals the line's weight minus the forces the line puts on its two ends (the
/// line's equilibrium) to the statics tolerance; (2) the mass hangs with T = m g and
/// vertically at the drum's side, x = R + d/2 − δ with 0 ≤ δ ≤ T/(R' k); (3) frictionless
/// contact has no tangential part, so along the line dT/ds = w dz/ds and the anchor tension
/// is T = m g + w (z_A − z_mass) (exact for the continuous cable; the nodal weight and the
/// polygon give an error of order w·l0, which is the tolerance: 0.049 N, 2.5e-4 of T).
#[test]
fn frictionless_drum_in_statics_balances_the_end_forces() {
    let (r, d, gamma, mass, elements) = (0.5, 0.02, 0.1, 20.0, 96);
    let rc = r + 0.5 * d;
    let (system, state, ws) = drum_statics(Formulation::Fe, elements);
    let length = system.lines[0].mesh.length();
    let fa = system.end_force(&ws, 0, false);
    let fb = system.end_force(&ws, 0, true);
    let weight = Vec3::new(0.0, 0.0, -gamma * G * length);
    let channel = channel_force(&system, &ws, 0.0, 0);
    let balance = weight - fa - fb;
    eprintln!("obstacle force {channel:?}, W − F_A − F_B {balance:?}");
    assert!(
        (channel - balance).norm() < 1e-6 * mass * G,
        "{channel:?} vs {balance:?}"
    );
    // The mass hangs on a vertical line from the drum's side (the drum's axis at x = 0). The
    // last node in contact carries between none and a whole node's load: its penetration is
    // between 0 and δ.
    let (p, _) = v::point_state(&system, &state, 1);
    let tension = fb.norm();
    let delta = tension / rc / 1.0e6;
    eprintln!(
        "mass tension {tension:.6} N (m g = {:.6}), x = {:.6} m (R + d/2 − δ = {:.6})",
        mass * G,
        p.x,
        rc - delta
    );
    assert!((tension - mass * G).abs() < 1e-6 * mass * G);
    assert!(p.x > rc - delta - 1e-9 && p.x < rc + 1e-9, "{}", p.x);
    assert!(p.z > 0.0, "the test is set in air");
    // Frictionless: T_A = T_B + w (z_A − z_B).
    let za = system.points[0].position.z;
    let expected = tension + gamma * G * (za - p.z);
    eprintln!(
        "anchor tension {:.6} N, frictionless law {expected:.6} N",
        fa.norm()
    );
    assert!(
        (fa.norm() - expected).abs() < gamma * G * length / elements as Real,
        "{} vs {expected}",
        fa.norm()
    );
    // Both ends pull the drum: toward the anchor (−x) by about T_A, down by about m g.
    assert!(channel.z < -0.95 * mass * G && channel.x < -0.95 * expected);
}

/// (a) The capstan: a weightless line (g = 0, no fluid) wrapped half-way round a vertical
/// drum of radius 1 m with friction μ = 0.3 is hauled at 0.3 m/s at one end against a
/// constant 500 N on a free point at the other. In steady sliding the hauling tension is
/// T_H = T_P e^{μθ}, θ = π (Euler–Eytelwein). Departures, each below 0.3 %: the polygon of
/// nodes (a node turning the line by Δφ = l0/R gives T₂/T₁ = (1 + μ tan(Δφ/2))/(1 − μ
/// tan(Δφ/2)), so ln(T_H/T_P) = μθ (1 + O(Δφ²/12)), 2e-4 at Δφ = 0.05); the tanh
/// regularisation (1 − tanh(π v/v_μ) < 1e-16 at v/v_μ = 6); the centripetal term γv²/T
/// (2e-4); the residual of the start-up oscillation after averaging over the last second.
/// Tolerance 2 %.
#[test]
fn capstan_ratio_in_steady_sliding() {
    let (r, d, gamma, force, mu, speed) = (1.0, 0.02, 1.0, 500.0, 0.3, 0.3);
    let rc = r + 0.5 * d;
    let a = 3.0;
    let length = 2.0 * a + PI * rc;
    let path = Path {
        centre: Vec3::zeros(),
        a,
        r: rc,
        arc: PI,
        start: Vec3::new(-a, -rc, 0.0),
        first: Vec3::x(),
        e1: Vec3::x(),
        e2: Vec3::y(),
        phi0: -0.5 * PI,
        last: -Vec3::x(),
    };
    // The hauling end: x = −a − v t²/(2 t_r) for t < t_r, then at speed v.
    let ramp = 0.5;
    let times: Vec<Real> = (0..=50)
        .map(|i| i as Real * ramp / 50.0)
        .chain([100.0])
        .collect();
    let positions = times
        .iter()
        .map(|&t| {
            let x = if t < ramp {
                speed * t * t / (2.0 * ramp)
            } else {
                speed * (t - 0.5 * ramp)
            };
            path.at(0.0) - Vec3::x() * x
        })
        .collect();
    let mut lt = v::dry_line_type(d, gamma, 2.0e5);
    lt.axial_damping = AxialDamping::Ratio(0.5);
    let elements = (length / 0.05).round() as usize;
    let mut model = v::single_line(
        lt,
        length,
        elements,
        (
            Point {
                name: "haul".into(),
                position: path.at(0.0),
                kind: PointKind::Prescribed(Motion::TimeSeries { times, positions }),
            },
            Point {
                name: "load".into(),
                position: path.at(length),
                kind: PointKind::Free {
                    mass: 5.0,
                    volume: 0.0,
                    drag_area: 0.0,
                    added_mass_coefficient: 0.0,
                    force: Vec3::new(-force, 0.0, 0.0),
                },
            },
        ),
        Formulation::Fe,
        MassMatrix::Lumped,
    );
    model.environment = v::vacuum_environment(0.0);
    let mut drum = cylinder(Vec3::zeros(), r, Vec3::z(), None, 1.0e6, mu);
    drum.friction_velocity = 0.05;
    model.environment.obstacles.push(drum.clone());
    let system = System::new(&model).unwrap();
    let mut y = system.straight_state();
    system.set_line_shape(&mut y, 0, |s| (path.at(s), Vec3::zeros()));
    v::set_point_state(&system, &mut y, 1, path.at(length), Vec3::zeros());
    // The friction slope μ N π/v_μ per unit length at N ≈ T_H/R, on the node mass γ l0.
    let slope = drum.friction_slope(force * (mu * PI).exp() / r);
    let dt = (0.5 * system.stable_step(Scheme::Rk4).0).min(1.0 / (slope / gamma));
    let mut sim = Simulation::new(&system, &v::fixed_step_settings(dt, Scheme::Rk4), y).unwrap();
    let (t_end, t_avg) = (4.0, 3.0);
    let mut x_avg = 0.0;
    let (mut sum_h, mut sum_p, mut sum_c, mut balance, mut count) =
        (0.0, 0.0, Vec3::zeros(), Vec3::zeros(), 0.0);
    while sim.time() < t_end {
        sim.step().unwrap();
        if sim.time() >= t_avg {
            if count == 0.0 {
                x_avg = v::point_state(&system, &sim.state(), 1).0.x;
            }
            let t = sim.time();
            let ws = sim.evaluate().unwrap();
            let (fh, fp) = (
                system.end_force(ws, 0, false),
                system.end_force(ws, 0, true),
            );
            sum_h += fh.norm();
            sum_p += fp.norm();
            sum_c += channel_force(&system, ws, t, 0);
            balance -= fh + fp;
            count += 1.0;
        }
    }
    let (th, tp) = (sum_h / count, sum_p / count);
    let (contact, balance) = (sum_c / count, balance / count);
    let ratio = th / tp;
    let expected = (mu * PI).exp();
    eprintln!(
        "dt {dt:.2e} s: T_haul {th:.2} N, T_load {tp:.2} N, ratio {ratio:.4} vs e^(μπ) \
         {expected:.4} ({:+.3} %); drum force {contact:?}, −(F_H + F_P) {balance:?}",
        100.0 * (ratio / expected - 1.0)
    );
    assert!((tp / force - 1.0).abs() < 0.01, "load tension {tp}");
    assert!(
        (ratio / expected - 1.0).abs() < 0.02,
        "{ratio} vs {expected}"
    );
    // Weightless and steady: the drum takes what the two ends put in.
    assert!((contact - balance).norm() < 0.01 * balance.norm());
    // The line is hauled: the load moved toward the drum at the hauling speed.
    let (p, _) = v::point_state(&system, &sim.state(), 1);
    let mean_speed = (p.x - x_avg) / (sim.time() - t_avg);
    eprintln!("load point at {p:?}, mean speed {mean_speed:.4} m/s");
    // Within the start-up oscillation of the load on the line's elasticity (about 1 cm).
    assert!((mean_speed / speed - 1.0).abs() < 0.03);
}

/// A sphere of radius 1 m at the origin, k = 2e5 N/m², with friction μ = 0.5 to hold the
/// drape in place while it settles, and a 2 m/ line of `formulation` draped over its top in
/// the x–z plane with 1 kg clump weights on both ends, dropped from 5 cm above its rest
/// shape; in water, whose drag settles it. Returns the system, the state after `duration` s
/// and the sphere's load averaged over the last second.
fn drape(
    formulation: Formulation,
    elements: usize,
    duration: Real,
) -> (System, Vec<Real>, ObstacleLoad) {
    drape_with(formulation, elements, duration, 2.0e5, |system| {
        0.5 * system.stable_step(Scheme::Rk4).0
    })
    .expect("the drape settles")
}

/// [`drape`] with the sphere's contact stiffness [N/m²] and the fixed RK4 step [s] chosen by
/// `step`; `Err` with the solver's message if the run diverges.
fn drape_with(
    formulation: Formulation,
    elements: usize,
    duration: Real,
    stiffness: Real,
    step: impl Fn(&System) -> Real,
) -> Result<(System, Vec<Real>, ObstacleLoad), String> {
    let (r, d) = (1.0, 0.03);
    let rc = r + 0.5 * d;
    let a = 1.5;
    let length = 2.0 * a + PI * rc;
    let centre = Vec3::new(0.0, 0.0, -10.0);
    let path = Path {
        centre,
        a,
        r: rc,
        arc: -PI,
        start: Vec3::new(-rc, 0.0, -a),
        first: Vec3::z(),
        e1: Vec3::x(),
        e2: Vec3::z(),
        phi0: PI,
        last: -Vec3::z(),
    };
    let mut lt = v::line_type(d, 2.0, 1.0e5);
    lt.axial_damping = AxialDamping::Ratio(0.5);
    let mut model = v::single_line(
        lt,
        length,
        elements,
        (
            v::free("left", path.at(0.0), 1.0, 0.0),
            v::free("right", path.at(length), 1.0, 0.0),
        ),
        formulation,
        MassMatrix::Consistent,
    );
    model.environment.depth = 50.0;
    model.environment.obstacles.push(Obstacle {
        name: "ball".into(),
        shape: ObstacleShape::Sphere { radius: r },
        motion: Motion::Fixed { position: centre },
        stiffness,
        damping: ObstacleDamping::Ratio(1.0),
        friction_coefficient: 0.5,
        friction_velocity: 0.01,
    });
    let system = System::new(&model).unwrap();
    let shift = Vec3::new(0.0, 0.0, 0.05);
    let mut y = system.straight_state();
    system.set_line_shape(&mut y, 0, |s| (path.at(s) + shift, Vec3::zeros()));
    v::set_point_state(&system, &mut y, 0, path.at(0.0) + shift, Vec3::zeros());
    v::set_point_state(&system, &mut y, 1, path.at(length) + shift, Vec3::zeros());
    let dt = step(&system);
    // Unchecked: the stiff-obstacle test runs a step beyond the estimate on purpose.
    let mut sim =
        Simulation::new_unchecked(&system, &v::fixed_step_settings(dt, Scheme::Rk4), y).unwrap();
    let (mut mean, mut count) = (ObstacleLoad::default(), 0.0);
    let mut loads = [ObstacleLoad::default()];
    while sim.time() < duration {
        sim.step().map_err(|e| e.to_string())?;
        if sim.time() > duration - 1.0 {
            let t = sim.time();
            obstacle_forces(
                &system,
                sim.evaluate().map_err(|e| e.to_string())?,
                t,
                &mut loads,
            );
            mean.force += loads[0].force;
            mean.contact_length += loads[0].contact_length;
            count += 1.0;
        }
    }
    mean.force /= count;
    mean.contact_length /= count;
    let y = sim.state().to_vec();
    Ok((system, y, mean))
}

/// The stable step honours a stiff obstacle. With k = 2e9 N/m² on a 2 kg/m line the contact
/// rate √(k/γ) = 3.2e4 rad/s, and its critical damping's 2√(k/γ), exceed the line's own axial
/// rate, so the automatic step must come from the contact: `stable_step` names it, and the
/// drape runs at 0.9 of that step for 1 s with the sphere carrying it. The step the line alone
/// allows (the same system without the sphere, 14.6× longer) diverges in the same run (at
/// 0.12 s), so the contact term is what keeps the run alive. (At k = 2e8 the line's own step,
/// 4.6× the estimate, happened to survive: the estimate is conservative for a one-sided
/// contact whose force vanishes when the node bounces off.)
#[test]
fn stable_step_honours_a_stiff_obstacle() {
    let stiff = 2.0e9;
    let (_, y, mean) = drape_with(Formulation::Fe, 60, 1.0, stiff, |system| {
        let (dt, culprit) = system.stable_step(Scheme::Rk4);
        eprintln!("stable step {dt:.3e} s, set by {culprit}");
        assert!(culprit.contains("obstacle contact"), "{culprit}");
        0.9 * dt
    })
    .expect("the run at 0.9 of the stable step settles");
    assert!(y.iter().all(|v| v.is_finite()));
    let w = (2.0 - 1025.0 * PI * 0.03 * 0.03 / 4.0) * G;
    eprintln!("mean sphere load over the last 1 s {:?} N", mean.force);
    // Settling within the second: the sphere carries at least the weight of the cable on it.
    assert!(-mean.force.z > w * PI, "{:?}", mean.force);
    let without = drape_with(Formulation::Fe, 60, 1.0, stiff, |system| {
        let mut bare = system.clone();
        bare.environment.obstacles.clear();
        let (dt_line, culprit) = bare.stable_step(Scheme::Rk4);
        let (dt, _) = system.stable_step(Scheme::Rk4);
        eprintln!(
            "without the sphere: {dt_line:.3e} s ({culprit}), {:.2}× longer",
            dt_line / dt
        );
        assert!(dt_line > 2.0 * dt);
        0.9 * dt_line
    });
    assert!(
        without.is_err(),
        "the line's own step should not survive the contact"
    );
}

/// (b) A line dropped on a sphere comes to rest draped over it; at its top the penalty law
/// sets the penetration: δ = N/(k √(1+ε)) with N the normal load per unit unstretched length,
/// the net weight w plus the tension's pull round the curve T (1+ε)/R' (R' = R + d/2 − δ the
/// radius of the cable's axis). This checks the penetration against k, in a shape found by
/// the dynamics; the tension is the simulated one at the top element. Tolerance 0.2 % on δ:
/// a node of the polygon turns the line by 2 asin(l0/2R') rather than l0/R', a relative
/// (l0/R')²/24 = 4e-4 at l0 = 0.1 m, plus the residual motion after settling. "At rest": the
/// kinetic energy left is below 1e-3 of the energy the 5 cm drop released.
#[test]
fn line_dropped_on_a_sphere_rests_with_the_penalty_penetration() {
    let elements = 60;
    let (system, y, mean) = drape(Formulation::Fe, elements, 10.0);
    let mut ws = system.workspace();
    let mut dydt = vec![0.0; y.len()];
    system.rhs(10.0, &y, &mut dydt, &mut ws).unwrap();
    let line = &ws.lines[0];
    // Kinetic energy left of the energy the drop released, ~ w L h (h = 5 cm).
    let mesh = &system.lines[0].mesh;
    let kinetic: Real = (0..=elements)
        .map(|i| {
            let m = mesh.section(i.min(elements - 1)).line_type.mass_per_length
                * mesh.node_length(i)
                + if i == 0 || i == elements { 1.0 } else { 0.0 };
            0.5 * m * line.velocity[i].norm_squared()
        })
        .sum();
    let top = elements / 2;
    let centre = Vec3::new(0.0, 0.0, -10.0);
    let ball = &system.environment.obstacles[0];
    let lt = &system.lines[0].mesh.sections[0];
    let (r, d, k) = (1.0, lt.line_type.diameter, ball.stiffness);
    let w = (lt.line_type.mass_per_length - 1025.0 * lt.area) * G;
    let depth = r + 0.5 * d - (line.position[top] - centre).norm();
    let el = &line.elements;
    let tension = 0.5 * (el.tension[top - 1] + el.tension[top]);
    let strain = 0.5 * (el.strain[top - 1] + el.strain[top]);
    let stretch = 1.0 + strain;
    let normal = w + tension * stretch / (r + 0.5 * d - depth);
    let expected = normal / (k * stretch.sqrt());
    let released = w * mesh.length() * 0.05;
    eprintln!(
        "top node {top}: δ = {depth:.6e} m, (w + T(1+ε)/R')/(k√(1+ε)) = {expected:.6e} m \
         ({:+.3} %), T = {tension:.3} N, w = {w:.3} N/m; kinetic energy {kinetic:.2e} J of \
         {released:.2} J released",
        100.0 * (depth / expected - 1.0)
    );
    assert!(kinetic < 1e-3 * released, "not at rest");
    assert!((depth / expected - 1.0).abs() < 2e-3);
    // At rest the sphere carries the whole net weight of the line and the clump weights (the
    // load averaged over the last second, over the legs' residual vibration).
    let mut loads = [ObstacleLoad::default()];
    obstacle_forces(&system, &ws, 10.0, &mut loads);
    let total = w * mesh.length() + 2.0 * 1.0 * G;
    eprintln!(
        "sphere load {:?} N (mean of the last second {:?} N) against net weight {total:.4} N, \
         contact length {:.3} m",
        loads[0].force, mean.force, loads[0].contact_length
    );
    assert!((mean.force.z + total).abs() < 1e-4 * total);
    assert!(mean.force.xy().norm() < 1e-4 * total);
    // The contact covers the upper half circle: πR' of cable, within a node's share.
    assert!((loads[0].contact_length - PI * (r + 0.5 * d)).abs() < 0.1);
}

/// Momentum [kg·m/s] of line 0's structural mass from the workspace's node vectors: Σ ∫γ s_j
/// ds q̇_j, i.e. γ L0/2 (v_a + v_b) per `fe` element (either mass matrix: their columns sum
/// to the same) and γ l/2 (v_a + v_b) + γ l²/12 (ṫ_a − ṫ_b) per `hermite` element.
fn line_momentum(system: &System, ws: &Workspace) -> Vec3 {
    let l = &system.lines[0];
    let n = l.mesh.elements();
    let qdot = &ws.lines[0].velocity;
    let mut p = Vec3::zeros();
    for e in 0..n {
        let s = l.mesh.section(e);
        let (gamma, le) = (s.line_type.mass_per_length, s.element_length);
        p += match l.discretisation {
            hawser::formulation::Discretisation::Fe { .. } => {
                (qdot[e] + qdot[e + 1]) * (0.5 * gamma * le)
            }
            hawser::formulation::Discretisation::Hermite(_) => {
                let [ra, ta, rb, tb] = hawser::formulation::hermite::element_vectors(e, n);
                (qdot[ra] + qdot[rb]) * (0.5 * gamma * le)
                    + (qdot[ta] - qdot[tb]) * (gamma * le * le / 12.0)
            }
            hawser::formulation::Discretisation::Dg(_) => unreachable!("fe and hermite only"),
        };
    }
    p
}

/// Points along line 0 [m]: the nodes of `fe`, ten points per element of `hermite`.
fn line_points(system: &System, ws: &Workspace) -> Vec<Vec3> {
    let l = &system.lines[0];
    let q = &ws.lines[0].position;
    match l.discretisation {
        hawser::formulation::Discretisation::Fe { .. } => q.clone(),
        hawser::formulation::Discretisation::Hermite(_) => (0..l.mesh.elements())
            .flat_map(|e| {
                (0..10).map(move |k| {
                    hawser::formulation::hermite::point_on_element(&l.mesh, q, e, k as Real / 10.0)
                        .0
                })
            })
            .collect(),
        hawser::formulation::Discretisation::Dg(_) => unreachable!("fe and hermite only"),
    }
}

/// The sum over line 0's node positions of the generalized forces of the line's physics with
/// the system's obstacles minus that without them: the total obstacle force on the line, from
/// the dynamics' own force routine (independent of the channel's recomputation).
fn obstacle_part_of_node_forces(system: &System, ws: &Workspace, t: Real) -> Vec3 {
    let l = &system.lines[0];
    let lw = &ws.lines[0];
    let mut bare = system.environment.clone();
    bare.obstacles.clear();
    let total = |env: &hawser::physics::environment::Environment| {
        let mut forces = vec![Vec3::zeros(); lw.position.len()];
        let mut elements = hawser::formulation::ElementState::new(l.mesh.elements());
        hawser::formulation::line_forces(
            &l.mesh,
            &l.discretisation,
            env,
            t,
            &lw.position,
            &lw.velocity,
            &mut forces,
            &mut elements,
            None,
            LoadOptions::direct(1.0),
        );
        (0..l.nodes())
            .map(|i| forces[l.node_vector(i)])
            .fold(Vec3::zeros(), |a, b| a + b)
    };
    total(&system.environment) - total(&bare)
}

/// (c) A vertical cylinder (R = 0.5 m, 10 m long) sweeps at 1 m/s through a slack line
/// hanging in air between two anchors, with friction μ = 0.2, and pushes it aside. Checked
/// at every step for `fe` and `hermite`: the obstacle channel is minus the obstacle part of
/// the dynamics' node forces (evaluated with and without the obstacle; to round-off, 1e-9 of
/// the force); and over the run, the change of the line's momentum equals the time integral
/// of weight − channel − F_A − F_B (the trapezoidal rule at the step, whose error is of
/// order dt² |d²F/dt²| T, below the 0.1 % of ∫|channel| dt allowed). The line is pushed:
/// its farthest point rides on the cylinder's front, R + d/2 ahead of its axis, within 3 cm
/// (the penetration, and the chords of `fe` and the sampling of `hermite` round the front).
#[test]
fn moving_cylinder_pushes_a_slack_line_and_its_channel_balances_momentum() {
    for formulation in [Formulation::Fe, Formulation::Hermite] {
        let (a, b) = (Vec3::new(0.0, 0.0, 20.0), Vec3::new(10.0, 0.0, 20.0));
        let elements = if formulation == Formulation::Fe {
            40
        } else {
            20
        };
        let mut lt = v::dry_line_type(0.04, 1.5, 1.0e6);
        lt.axial_damping = AxialDamping::Ratio(0.2);
        let mut model = v::single_line(
            lt,
            12.0,
            elements,
            (v::fixed("a", a), v::fixed("b", b)),
            formulation,
            MassMatrix::Lumped,
        );
        model.environment = v::vacuum_environment(G);
        let mut sweeper = cylinder(
            Vec3::new(4.0, -3.0, 17.0),
            0.5,
            Vec3::z(),
            Some(10.0),
            2.0e5,
            0.2,
        );
        sweeper.motion = Motion::ConstantVelocity {
            start: Vec3::new(4.0, -3.0, 17.0),
            velocity: Vec3::y(),
        };
        sweeper.friction_velocity = 0.05;
        model.environment.obstacles.push(sweeper);
        let system = System::new(&model).unwrap();
        let y0 = solve(&system, None, &StaticOptions::default())
            .expect("the catenary")
            .state;
        let dt = 0.4 * system.stable_step(Scheme::Rk4).0;
        let mut sim =
            Simulation::new(&system, &v::fixed_step_settings(dt, Scheme::Rk4), y0).unwrap();
        let weight = Vec3::new(0.0, 0.0, -1.5 * G * 12.0);
        let mut steps = 0;
        let mut rate = |sim: &mut Simulation| {
            let t = sim.time();
            let ws = sim.evaluate().unwrap();
            let mut loads = [ObstacleLoad::default()];
            obstacle_forces(&system, ws, t, &mut loads);
            let c = loads[0].force;
            if steps % 10 == 0 {
                let channel = channel_force(&system, ws, t, 0);
                let independent = obstacle_part_of_node_forces(&system, ws, t);
                assert!(
                    (channel + independent).norm() <= 1e-9 * c.norm().max(1.0)
                        && (channel - c).norm() <= 1e-12 * c.norm(),
                    "{formulation:?} t = {t}: channel {c:?}, node forces {independent:?}"
                );
            }
            steps += 1;
            let net = weight - c - system.end_force(ws, 0, false) - system.end_force(ws, 0, true);
            (net, c, line_momentum(&system, ws))
        };
        let (mut previous, _, p0) = rate(&mut sim);
        let (mut impulse, mut contact_impulse, mut peak) = (Vec3::zeros(), 0.0, Vec3::zeros());
        let duration = 5.0;
        while sim.time() < duration {
            sim.step().unwrap();
            let (net, c, _) = rate(&mut sim);
            impulse += (previous + net) * (0.5 * dt);
            contact_impulse += c.norm() * dt;
            if c.norm() > peak.norm() {
                peak = c;
            }
            previous = net;
        }
        let (_, _, p1) = rate(&mut sim);
        let ws = sim.evaluate().unwrap();
        let farthest = line_points(&system, ws)
            .iter()
            .map(|p| p.y)
            .fold(Real::NEG_INFINITY, Real::max);
        let cylinder_y = -3.0 + sim.time();
        eprintln!(
            "{formulation:?}: Δp {:?}, ∫F dt {impulse:?} (∫|C| dt {contact_impulse:.3} N·s, \
             peak {peak:?}); farthest node y {farthest:.3} m, cylinder at {cylinder_y:.3} m",
            p1 - p0
        );
        assert!(contact_impulse > 1.0, "the cylinder met the line");
        assert!(
            ((p1 - p0) - impulse).norm() < 1e-3 * contact_impulse,
            "{formulation:?}"
        );
        // Pushed: the line's farthest point sits on the cylinder's front.
        assert!(farthest > cylinder_y + 0.5 - 0.05 && farthest < cylinder_y + 0.5 + 0.03);
        // The cylinder feels the line resisting in −y.
        assert!(peak.y < 0.0);
    }
}

/// (d) `fe` and `hermite` drape the same: the static line of (a) over the drum by both. The
/// gap between `fe` at 48 and 96 elements estimates `fe`'s error at 48 (second order: the
/// nodal contact and the chords); `hermite` at 24 elements must agree with `fe` at 96 within
/// that gap, node by node at the same arc lengths, and better still with `fe` extrapolated
/// to zero element length (Richardson, second order).
#[test]
fn fe_and_hermite_drape_the_same() {
    let positions = |(system, _, ws): (System, Vec<Real>, Workspace)| {
        (0..system.lines[0].nodes())
            .map(|i| ws.lines[0].position[system.lines[0].node_vector(i)])
            .collect::<Vec<_>>()
    };
    let coarse = positions(drum_statics(Formulation::Fe, 48));
    let fine = positions(drum_statics(Formulation::Fe, 96));
    let hermite = positions(drum_statics(Formulation::Hermite, 24));
    let gap = |a: &[Vec3], every: usize| {
        a.iter()
            .enumerate()
            .map(|(i, p)| (p - fine[i * every]).norm())
            .fold(0.0, Real::max)
    };
    let (fe_error, between) = (gap(&coarse, 2), gap(&hermite, 4));
    // Richardson: fe's second-order error at 96 elements is a third of the 48–96 gap; the
    // extrapolated fe shape, at hermite's nodes.
    let extrapolated = (0..hermite.len())
        .map(|i| fine[4 * i] + (fine[4 * i] - coarse[2 * i]) / 3.0)
        .collect::<Vec<_>>();
    let to_extrapolated = hermite
        .iter()
        .zip(&extrapolated)
        .map(|(a, b)| (a - b).norm())
        .fold(0.0, Real::max);
    eprintln!(
        "largest node distance from fe 96: fe 48 {fe_error:.3e} m, hermite 24 {between:.3e} m; \
         hermite 24 from fe extrapolated {to_extrapolated:.3e} m"
    );
    assert!(between < fe_error && to_extrapolated < 0.5 * between);
}

/// `dg` lines feel obstacles through the source term of their momentum equation, at their
/// Gauss points, and the obstacle channel sums the same terms. Checked without relying on the
/// channel's code: a `dg` rope (10 elements of order 4, no added mass) lying over a pipe and
/// under a moving sphere with friction, its right-hand side evaluated with and without the
/// obstacles at the same state; the change of the line's total momentum rate, Σ_e h_e v̇_e,0
/// (the integral of the momentum density's rate over each element, its mode-0 coefficient
/// times the element length), is the obstacles' total force on the line, which must equal
/// minus the sum of the two obstacles' channels (to 1e-9, round-off). Both obstacles touch.
#[test]
fn dg_contact_enters_the_momentum_as_the_channels_say() {
    let build = |with_obstacles: bool| {
        let mut lt = v::dry_line_type(0.05, 2.0, 1.0e5);
        lt.axial_damping = AxialDamping::Ratio(0.2);
        let mut model = v::single_line(
            lt,
            10.5,
            10,
            (
                v::fixed("a", Vec3::new(-5.0, 0.0, -8.0)),
                v::fixed("b", Vec3::new(5.0, 0.0, -8.0)),
            ),
            Formulation::Dg,
            MassMatrix::Consistent,
        );
        if with_obstacles {
            let pipe = cylinder(
                Vec3::new(-1.0, 0.0, -9.5),
                0.5,
                Vec3::y(),
                Some(4.0),
                1.0e5,
                0.2,
            );
            let mut ball = pipe.clone();
            ball.name = "ball".into();
            ball.shape = ObstacleShape::Sphere { radius: 0.4 };
            ball.motion = Motion::ConstantVelocity {
                start: Vec3::new(2.0, 0.75, -8.84),
                velocity: Vec3::new(0.5, -1.0, 0.2),
            };
            model.environment.obstacles = vec![pipe, ball];
        }
        System::new(&model).unwrap()
    };
    let (with, without) = (build(true), build(false));
    // A sagging, moving shape through both obstacles.
    let shape = |s: Real| {
        let x = -5.0 + 10.0 * s / 10.5;
        let u = 1.0 - (x / 5.0).powi(2);
        (
            Vec3::new(x, 0.0, -8.0 - 1.1 * u),
            Vec3::new(0.1 * u, 0.3 * u, -0.2 * u),
        )
    };
    let mut y = with.straight_state();
    with.set_line_shape(&mut y, 0, shape);
    let t = 0.7;
    let momentum_rate = |system: &System| {
        let mut ws = system.workspace();
        let mut dydt = vec![0.0; y.len()];
        system.rhs(t, &y, &mut dydt, &mut ws).unwrap();
        let line = system.lines[0].dg().expect("a dg line");
        let o = system.layout.line_offset[0];
        let rate = (0..line.elements.len())
            .map(|e| {
                let (_, v, _) = line.fields(&dydt[o..], e);
                Vec3::new(v[0], v[1], v[2]) * line.elements[e].length
            })
            .fold(Vec3::zeros(), |a, b| a + b);
        (rate, ws)
    };
    let (rate_with, ws) = momentum_rate(&with);
    let (rate_without, _) = momentum_rate(&without);
    let mut loads = [ObstacleLoad::default(); 2];
    obstacle_forces(&with, &ws, t, &mut loads);
    let channels = loads[0].force + loads[1].force;
    let contact = rate_with - rate_without;
    eprintln!(
        "dg: momentum rate change {contact:?} N, channels {:?} + {:?} N, contact lengths {:.3} \
         and {:.3} m",
        loads[0].force, loads[1].force, loads[0].contact_length, loads[1].contact_length
    );
    assert!(loads.iter().all(|l| l.contact_length > 0.0));
    assert!((contact + channels).norm() < 1e-9 * channels.norm());
    // The channels of a moving obstacle are taken at the sample time (value_at).
    let by_channel = Vec3::from_fn(|axis, _| {
        Channel::ObstacleForce { obstacle: 1, axis }.value_at(&with, &ws, t)
    });
    assert!((by_channel - loads[1].force).norm() < 1e-12 * loads[1].force.norm());
}
