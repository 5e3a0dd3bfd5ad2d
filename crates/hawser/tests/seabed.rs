//! Seabed bathymetry (docs/seabed.md): a body and a free point settling on a sloping bed and
//! creeping down it, checked by force balance and the friction law's closed-form sliding
//! speed; a grid that is a plane is that plane.

use hawser::math::{Mat3, Real, Vec3};
use hawser::model::*;
use hawser::physics::environment::Environment;
use hawser::physics::seabed::{Bathymetry, SeabedGrid};
use hawser::session::{Session, SessionOptions};

const G: Real = 9.80665;
const RHO: Real = 1025.0;
/// Slope of the bed along x (rising toward +x) [-].
const SLOPE: Real = 0.1;
/// Friction coefficient and the speed over which it builds up [-, m/s].
const MU: Real = 0.5;
const V_MU: Real = 0.01;

/// 50 m of water over a bed rising at 10 % along x, with tanh friction μ = 0.5.
fn sloping_bed() -> Environment {
    let mut env = Environment {
        depth: 50.0,
        bathymetry: Bathymetry::Plane {
            gradient: [SLOPE, 0.0],
        },
        ..Default::default()
    };
    env.seabed.friction_coefficient = MU;
    env.seabed.friction_velocity = V_MU;
    env
}

/// A model of `bodies` and `points` only, run from where they are (no statics).
fn model(bodies: Vec<Body>, points: Vec<Point>, duration: Real) -> Model {
    Model {
        environment: sloping_bed(),
        bodies,
        points,
        settings: Settings {
            duration,
            output_interval: 0.5,
            initial_condition: InitialCondition::AsDefined,
            ..Default::default()
        },
        ..Default::default()
    }
}

/// On a bed of slope angle α with friction μ tanh(π v/v_μ) under the normal force, a body of
/// weight W in water creeps steadily down the slope at v = (v_μ/π) atanh(tan α/μ): the
/// friction carries W sin α, the bed's normal force W cos α.
fn creep_speed() -> Real {
    V_MU / std::f64::consts::PI * (SLOPE / MU).atanh()
}

/// The bed's upward unit normal and its down-slope unit tangent.
fn bed_axes() -> (Vec3, Vec3) {
    let n = Vec3::new(-SLOPE, 0.0, 1.0).normalize();
    let down = Vec3::new(-1.0, 0.0, -SLOPE).normalize();
    (n, down)
}

/// A 2 m × 2 m × 1 m box of 8 t dropped upright just above the sloping bed (its up-slope
/// corner 5 cm above it) settles flat on the bed and creeps down it. After 10 s, with the
/// transients long gone (the contact's heave rate is ~40 rad/s, critically damped; the
/// friction reaches its steady sliding in ms), in steady creep every patch slides at the same
/// velocity, so the patches' friction adds up to μ N tanh(π v/v_μ) exactly and:
/// - force balance: the seabed's force on the box (its sum over the patches, from
///   `Body::seabed_contact`) is its weight in water, (0, 0, W), to 1e-6 of W (what is left is
///   the drag at the creep speed, ½ ρ C_dA v² ≈ 4e-4 N = 1e-8 W, and the settling's remains);
/// - its parts: the normal force W cos α and the friction W sin α, to 1e-6 of W;
/// - the moment of the bed's force about the centre (where weight and buoyancy act) vanishes
///   to 1e-6 W·m: the box rests on its base, tilted forward by the angle the friction's moment
///   about the centre, W sin α · h/2, needs from the bed's rotational stiffness over the
///   base's patches, K Σ x² A = K · 1.25 m⁴ (the midpoint rule's, for the exact b l³/12 =
///   1.33 m⁴): 5.1e-4 rad, within 1 %;
/// - it creeps down the slope at the closed-form speed within 1e-4 (the drag's share).
#[test]
fn box_settles_flat_on_a_sloping_bed_and_creeps_at_the_friction_speed() {
    let (l, b, h, mass) = (2.0, 2.0, 1.0, 8000.0);
    let weight = (mass - RHO * l * b * h) * G;
    let mut body = Body::new(
        "box",
        mass,
        Mat3::from_diagonal(&Vec3::new(3000.0, 3000.0, 5300.0)),
    );
    body.displacement = Displacement::Box {
        length: l,
        breadth: b,
        height: h,
    };
    body.added_mass = nalgebra::Vector6::new(4000.0, 4000.0, 8000.0, 1000.0, 1000.0, 1000.0);
    body.quadratic_drag = nalgebra::Vector6::new(2.0, 2.0, 4.0, 1.0, 1.0, 1.0);
    // The up-slope bottom corner (x = 1) is over the bed at −50 + 0.1: 5 cm above it.
    body.position = Vec3::new(0.0, 0.0, -50.0 + SLOPE + 0.5 * h + 0.05);
    // RK4, at its stable step, as these balances were set for. The default `auto` chooses
    // generalized-α at tolerance 1e-6 here, whose state after 10 s is 1.3e-6 W off the force
    // balance (0.049 N along the slope against W = 38 246 N): an open finding
    // (docs/implicit.md), not a reason to widen the 1e-6.
    let mut m = model(vec![body], vec![], 10.0);
    m.settings.scheme = Scheme::Rk4;
    let mut session = Session::with_options(m, SessionOptions::default()).expect("the model runs");
    session.run().expect("the run finishes");
    let view = session.view().expect("evaluates");
    let k = *view.body(0);
    let env = &view.system.environment;
    let body = &view.system.bodies[0].body;
    let r = *k.orientation.to_rotation_matrix().matrix();
    let contact = body
        .seabed_contact(&k, &r, env)
        .expect("the box rests on the bed");
    let (n, down) = bed_axes();
    let f = contact.force;
    eprintln!(
        "contact {f:?}, moment {:?}, velocity {:?}",
        contact.moment, k.velocity
    );
    assert!(
        (f - Vec3::new(0.0, 0.0, weight)).norm() < 1e-6 * weight,
        "{f:?} vs W = {weight}"
    );
    let cos = 1.0 / SLOPE.hypot(1.0);
    assert!((f.dot(&n) - weight * cos).abs() < 1e-6 * weight);
    assert!((f.dot(&(-down)) - weight * SLOPE * cos).abs() < 1e-6 * weight);
    assert!(
        contact.moment.norm() < 1e-6 * weight,
        "{:?}",
        contact.moment
    );
    let tilt = (r * Vec3::z()).cross(&n).norm().asin();
    let sin = SLOPE * cos;
    let expected = weight * sin * 0.5 * h / (3.0e6 * 1.25);
    assert!(
        (tilt / expected - 1.0).abs() < 1e-2,
        "tilt {tilt} rad, expected {expected}"
    );
    let v = k.velocity.dot(&down);
    assert!(
        (v / creep_speed() - 1.0).abs() < 1e-4,
        "creeps at {v} m/s, closed form {}",
        creep_speed()
    );
    assert!((k.velocity - down * v).norm() < 1e-4 * v);
}

/// A clump weight (a free point with a volume: a sphere of it on the bed) on the same slope
/// creeps at the same speed (within 1e-4: its drag at the creep speed is 1e-8 of its weight),
/// its contact force along the normal with the friction along the slope: the net force on it
/// vanishes in steady creep, so its acceleration stays below 1e-6 g, and its lowest point sits
/// W cos α / k below the bed along the normal (within 1e-3: the damper's share at the creep's
/// normal velocity, which is zero on a plane).
#[test]
fn clump_weight_creeps_down_a_sloping_bed() {
    let volume = 0.5;
    let mass = 4000.0;
    let radius = (3.0 * volume / (4.0 * std::f64::consts::PI)).cbrt();
    let clump = Point {
        name: "clump".into(),
        position: Vec3::new(0.0, 0.0, -50.0 + radius + 0.02),
        kind: PointKind::Free {
            mass,
            volume,
            drag_area: 0.5,
            added_mass_coefficient: 0.5,
            force: Vec3::zeros(),
        },
    };
    let mut session =
        Session::with_options(model(vec![], vec![clump], 20.0), SessionOptions::default())
            .expect("the model runs");
    session.run().expect("the run finishes");
    let view = session.view().expect("evaluates");
    let p = *view.point(0);
    let (n, down) = bed_axes();
    let v = p.velocity.dot(&down);
    assert!(
        (v / creep_speed() - 1.0).abs() < 1e-4,
        "creeps at {v} m/s, closed form {}",
        creep_speed()
    );
    assert!(p.acceleration.norm() < 1e-6 * G, "{:?}", p.acceleration);
    // The sphere sinks into the bed by W cos α / k along n.
    let weight = (mass - RHO * volume) * G;
    let k = 3.0e6 * std::f64::consts::PI * radius * radius;
    let bed = view
        .system
        .environment
        .seabed_at(p.position.x, p.position.y);
    let depth = (bed.z - p.position.z) * bed.normal.z + radius;
    let cos = n.z;
    assert!(
        (depth - weight * cos / k).abs() < 1e-3 * weight / k,
        "{depth} vs {}",
        weight * cos / k
    );
}

/// A grid sampled from a plane is that plane: heights and normals agree everywhere inside,
/// and beyond the grid the height of its nearest edge holds (level across the edge).
#[test]
fn a_planar_grid_is_its_plane() {
    let (gx, gy, depth) = (0.03, -0.02, 80.0);
    let plane = Bathymetry::Plane { gradient: [gx, gy] };
    let xs = vec![-100.0, -40.0, 0.0, 55.0, 100.0];
    let ys = vec![-80.0, 10.0, 80.0];
    let z = ys
        .iter()
        .flat_map(|&y| xs.iter().map(move |&x| -depth + gx * x + gy * y))
        .collect();
    let grid = Bathymetry::Grid(SeabedGrid::new(xs, ys, z).unwrap());
    for (x, y) in [
        (0.0, 0.0),
        (-99.0, 79.0),
        (12.5, -3.0),
        (54.9, 9.9),
        (55.0, 10.0),
    ] {
        let (a, b) = (plane.at(depth, x, y), grid.at(depth, x, y));
        assert!((a.z - b.z).abs() < 1e-12, "({x}, {y}): {} vs {}", a.z, b.z);
        assert!((a.normal - b.normal).norm() < 1e-12, "({x}, {y})");
    }
    let edge = grid.at(depth, 100.0, 0.0);
    let beyond = grid.at(depth, 150.0, 0.0);
    assert_eq!(edge.z, beyond.z);
    assert!((beyond.normal.x).abs() < 1e-15 && beyond.normal.y != 0.0);
    assert_eq!(grid.top(depth), -depth + gx * 100.0 + gy * -80.0);
}
