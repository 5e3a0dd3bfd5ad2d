//! The line-load channels of a body, `NAME.fx|fy|fz|mx|my|mz` (the force the lines put on it
//! and its moment about the body origin, global axes), against two computations made here:
//!
//! 1. the sum of the line end forces of the lines attached to the body (their
//!    `LINE.end_a|end_b.fx|fy|fz` channels) and of their moments (R ρ_k) × F_k about the body
//!    origin, with R built from the body's roll, pitch and yaw channels and ρ_k the points'
//!    offsets written in this file;
//! 2. the body's own Newton–Euler balance: the lines' load is M [a_o; α] − F_own, with the
//!    accelerations by central differences of the body's velocity channels and the mass
//!    matrix and own loads (weight, buoyancy, drag, added mass, inertial terms) of
//!    `Body::loads` at the sampled state.
//!
//! A buoyant body ("float", turned, centre of gravity off its origin) is held by three lines at
//! three points: an `fe` line from an anchor (end B on the body), a `hermite` line to a second
//! free body hanging below (end A on the body) and an `fe` line from a second point on the
//! bed, shaken sinusoidally; everything starts as defined, out of equilibrium (every line
//! stretched 0.4 % to 0.65 %), so the bodies accelerate and turn throughout.
//!
//! `cargo test --release -p hawser-io --test body_line_load -- --nocapture`

use hawser::math::{Quat, Real, Vec3, Vec6};
use hawser::model::RigidKinematics;
use hawser::simulation::{Observer, Simulation};
use hawser::system::System;
use hawser_io::scenario;
use std::path::Path;

const SCENARIO: &str = r#"
[simulation]
duration = 3.0
time_step = 1.0e-4
output_interval = 2.0e-4
initial_condition = "as-defined"
channels = [
  "float.fx", "float.fy", "float.fz", "float.mx", "float.my", "float.mz",
  "weight.fx", "weight.fy", "weight.fz", "weight.mx", "weight.my", "weight.mz",
  "L1.end_b.fx", "L1.end_b.fy", "L1.end_b.fz",
  "L2.end_a.fx", "L2.end_a.fy", "L2.end_a.fz",
  "L2.end_b.fx", "L2.end_b.fy", "L2.end_b.fz",
  "L3.end_b.fx", "L3.end_b.fy", "L3.end_b.fz",
  "float.roll", "float.pitch", "float.yaw", "weight.roll", "weight.pitch", "weight.yaw",
]

[environment]
depth = 100.0

[[line_types]]
name = "rope"
diameter = 0.02
mass_per_length = 1.0
axial_stiffness = 2.0e5
axial_damping_ratio = 0.1
bending_stiffness = 5.0
normal_drag = 1.2
tangential_drag = 0.02
normal_added_mass = 1.0

[[bodies]]
name = "float"
type = "free"
position = [0.0, 0.0, -20.0]
orientation = [10.0, -5.0, 30.0]
mass = 500.0
centre_of_gravity = [0.1, 0.05, -0.2]
inertia = [80.0, 120.0, 150.0]
displacement = { type = "submerged", volume = 0.8 }
centre_of_buoyancy = [0.0, 0.0, 0.1]
added_mass = [200.0, 300.0, 400.0, 20.0, 30.0, 40.0]
quadratic_drag = [0.5, 0.8, 1.0, 0.1, 0.1, 0.1]

[[bodies]]
name = "weight"
type = "free"
position = [1.0, 0.5, -28.5]
orientation = [0.0, 20.0, 0.0]
mass = 150.0
centre_of_gravity = [0.0, 0.0, -0.1]
inertia = [5.0, 6.0, 7.0]
displacement = { type = "submerged", volume = 0.02 }
added_mass = [10.0, 10.0, 10.0, 0.0, 0.0, 0.0]
quadratic_drag = [0.1, 0.1, 0.1, 0.0, 0.0, 0.0]

[[points]]
name = "anchor"
type = "fixed"
position = [-2.0, 1.0, -40.0]

[[points]]
name = "shaker"
type = "prescribed"
position = [8.0, -3.0, -38.0]
motion = { type = "sinusoid", amplitude = [0.2, 0.1, 0.15], period = 2.0 }

[[points]]
name = "p1"
type = "body"
body = "float"
position = [0.5, 0.3, -0.4]

[[points]]
name = "p2"
type = "body"
body = "float"
position = [-0.5, 0.2, -0.3]

[[points]]
name = "p3"
type = "body"
body = "float"
position = [0.2, -0.6, 0.3]

[[points]]
name = "w"
type = "body"
body = "weight"
position = [0.1, 0.0, 0.3]

[[lines]]
name = "L1"
end_a = "anchor"
end_b = "p1"
type = "rope"
length = 19.76
elements = 8

[[lines]]
name = "L2"
end_a = "p2"
end_b = "w"
type = "rope"
length = 8.1
elements = 4
formulation = "hermite"

[[lines]]
name = "L3"
end_a = "shaker"
end_b = "p3"
type = "rope"
length = 19.78
elements = 8
"#;

/// Each sample: time, the scenario's channels in order, the bodies' kinematics.
struct Record {
    samples: Vec<(Real, Vec<Real>, Vec<RigidKinematics>)>,
    /// The smallest element strain of any line at each sample.
    min_strain: Vec<Real>,
    channels: Vec<hawser::analysis::Channel>,
    names: Vec<String>,
}

impl Observer for Record {
    fn sample(
        &mut self,
        view: &hawser::session::View<'_>,
    ) -> Result<(), hawser::session::ObserverError> {
        let (system, time, ws) = (view.system, view.time, view.workspace);
        let values = self.channels.iter().map(|c| c.value(system, ws)).collect();
        let strain = ws.lines.iter().flat_map(|l| l.elements.strain.iter());
        self.min_strain
            .push(strain.copied().fold(Real::INFINITY, Real::min));
        self.samples.push((time, values, ws.bodies.clone()));
        Ok(())
    }
}

fn run() -> (scenario::LoadedScenario, Record) {
    let s = scenario::parse(Path::new("scenario.toml"), SCENARIO).unwrap_or_else(|e| panic!("{e}"));
    let system = System::new(&s.model).unwrap();
    // As `hawser run` starts with `initial_condition = "as-defined"`.
    let mut y0 = system.straight_state();
    hawser::statics::catenary_seed(&system, &mut y0, &mut system.workspace());
    let mut sim = Simulation::new(&system, &s.model.settings, y0).unwrap();
    let mut record = Record {
        samples: Vec::new(),
        min_strain: Vec::new(),
        channels: s.model.outputs.iter().map(|c| c.channel).collect(),
        names: s.model.outputs.iter().map(|c| c.name(&system)).collect(),
    };
    sim.run(s.model.settings.duration, &mut record).unwrap();
    drop(sim);
    (s, record)
}

fn vec3(v: &[Real], at: usize) -> Vec3 {
    Vec3::new(v[at], v[at + 1], v[at + 2])
}

/// Checks 1 and 2 (module comment) on one run.
///
/// 1. To round-off: 1e-9 of the largest line load (forces up to some kN, arms up to 0.7 m;
///    the only difference is the order of the sums and the degrees of the angle channels).
/// 2. The central difference (v(t+Δ) − v(t−Δ))/2Δ errs by Δ²/6 v''' : the residual must be
///    below 1e-3 of the largest line load at Δ = 0.2 ms, and its RMS over the run must grow
///    like Δ² (ratio 3 to 5.5 between Δ = 0.4 ms and 0.2 ms; a missing load or a wrong moment
///    arm would give a residual that does not shrink with Δ). The largest residual sits where
///    a line slackens or snaps taut (the start as defined is violent): the tension's kink
///    there is resolved by central differences only to O(Δ).
#[test]
fn body_line_load_channels_are_the_lines_end_loads() {
    let (s, rec) = run();
    let n = rec.samples.len();
    assert_eq!(n, 15001);
    // The start as defined is violent: lines slacken and snap taut again now and then.
    let first = rec.samples.iter().position(|s| s.0 >= 1.0).unwrap();
    let (early, late) = rec.min_strain.split_at(first);
    let slack = |v: &[Real]| v.iter().copied().fold(Real::INFINITY, Real::min);
    eprintln!(
        "smallest element strain of any line: {:.3e} before 1 s, {:.3e} after (slack)",
        slack(early),
        slack(late)
    );

    // Channel indices by name (the default channels come first).
    let at = |name: &str| {
        rec.names
            .iter()
            .position(|n| n == name)
            .unwrap_or_else(|| panic!("no channel {name}"))
    };
    let (float_load, weight_load) = (at("float.fx"), at("weight.fx"));
    let (l1b, l2a, l2b, l3b) = (
        at("L1.end_b.fx"),
        at("L2.end_a.fx"),
        at("L2.end_b.fx"),
        at("L3.end_b.fx"),
    );
    let (float_angles, weight_angles) = (at("float.roll"), at("weight.roll"));
    // Each group of three or six is consecutive.
    for (first, names) in [
        (
            float_load,
            &[
                "float.fx", "float.fy", "float.fz", "float.mx", "float.my", "float.mz",
            ][..],
        ),
        (l2a, &["L2.end_a.fx", "L2.end_a.fy", "L2.end_a.fz"][..]),
        (
            float_angles,
            &["float.roll", "float.pitch", "float.yaw"][..],
        ),
    ] {
        for (k, name) in names.iter().enumerate() {
            assert_eq!(at(name), first + k);
        }
    }
    let offsets = |name: &str| {
        s.model
            .points
            .iter()
            .find(|p| p.name == name)
            .map(|p| p.position)
            .unwrap()
    };
    // The offsets as written above, checked against the model so that a misread offset fails.
    let (p1, p2, p3, w) = (
        Vec3::new(0.5, 0.3, -0.4),
        Vec3::new(-0.5, 0.2, -0.3),
        Vec3::new(0.2, -0.6, 0.3),
        Vec3::new(0.1, 0.0, 0.3),
    );
    assert_eq!(
        (offsets("p1"), offsets("p2"), offsets("p3"), offsets("w")),
        (p1, p2, p3, w)
    );
    let rotation = |v: &[Real], at: usize| {
        Quat::from_euler_angles(
            v[at].to_radians(),
            v[at + 1].to_radians(),
            v[at + 2].to_radians(),
        )
    };

    // 1. Sums of the end forces and their moments.
    let (mut worst1, mut scale) = (0.0 as Real, 0.0 as Real);
    for (_, v, _) in &rec.samples {
        let rf = rotation(v, float_angles);
        let rw = rotation(v, weight_angles);
        let ends_float = [(vec3(v, l1b), p1), (vec3(v, l2a), p2), (vec3(v, l3b), p3)];
        let ends_weight = [(vec3(v, l2b), w)];
        for (ends, r, at) in [
            (&ends_float[..], rf, float_load),
            (&ends_weight[..], rw, weight_load),
        ] {
            let force: Vec3 = ends.iter().map(|(f, _)| *f).sum();
            let moment: Vec3 = ends.iter().map(|(f, rho)| (r * rho).cross(f)).sum();
            worst1 = worst1
                .max((vec3(v, at) - force).norm())
                .max((vec3(v, at + 3) - moment).norm());
            scale = scale.max(force.norm());
        }
    }

    // 2. Newton–Euler: M [a; α] − F_own, central differences at Δ = the output interval
    // (0.2 ms, stride 1) and twice it (stride 2).
    let env = &s.model.environment;
    let residual = |stride: usize| {
        let mut worst = 0.0 as Real;
        let mut when = 0.0;
        let dt = rec.samples[stride].0 - rec.samples[0].0;
        let (mut sum, mut count) = (0.0, 0);
        for i in (2 * stride..n - stride).step_by(stride) {
            for (b, at) in [(0, float_load), (1, weight_load)] {
                let (t, v, k) = &rec.samples[i];
                let (kp, km) = (&rec.samples[i + stride].2[b], &rec.samples[i - stride].2[b]);
                let acc = Vec6::from_iterator(
                    ((kp.velocity - km.velocity) / (2.0 * dt))
                        .iter()
                        .chain(((kp.angular_velocity - km.angular_velocity) / (2.0 * dt)).iter())
                        .copied(),
                );
                let own = s.model.bodies[b].loads(&k[b], env, *t);
                let lines = own.mass * acc - own.generalized();
                let channel = Vec6::from_iterator(v[at..at + 6].iter().copied());
                sum += (lines - channel).norm_squared();
                count += 1;
                if (lines - channel).norm() > worst {
                    worst = (lines - channel).norm();
                    when = *t;
                }
            }
        }
        let rms = (sum / count as Real).sqrt();
        eprintln!("Δ = {dt:.1e} s: largest residual {worst:.3e} at t = {when:.4} s, RMS {rms:.3e}");
        (worst, rms)
    };
    let ((fine, fine_rms), (coarse, coarse_rms)) = (residual(1), residual(2));
    eprintln!(
        "{n} samples; largest line force on a body {scale:.1} N; channel against the summed end \
         loads {worst1:.2e} N (N·m); against Newton–Euler: {fine:.3e} at Δ = 0.2 ms, \
         {coarse:.3e} at 0.4 ms (ratio {:.2}); RMS {fine_rms:.3e}, {coarse_rms:.3e} (ratio {:.2})",
        coarse / fine,
        coarse_rms / fine_rms
    );
    assert!(scale > 100.0, "the lines load the bodies: {scale} N");
    assert!(worst1 < 1e-9 * scale, "{worst1} vs {scale}");
    assert!(fine < 1e-3 * scale, "{fine} vs {scale}");
    assert!(
        (3.0..5.5).contains(&(coarse_rms / fine_rms)),
        "{coarse_rms} / {fine_rms}"
    );
}
