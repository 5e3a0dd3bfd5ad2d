//! Prescribed rigid-body motions: the ship manoeuvre's track geometry and
//! kinematics, the 6-DOF spline table against an analytic motion (convergence with the
//! sampling interval), the Euler-angle kinematic map, and the RAO motion against the wave
//! field it shares with the lines (regular waves, the phase convention, a JONSWAP response
//! spectrum); every motion's derivatives against finite differences, no allocation, and the
//! points of a system on a motion taking its kinematics at every evaluation's time.

mod alloc_count;
mod common;
use alloc_count::allocations_in;
use hawser::math::{Mat3, Quat, Real, Vec3};
use hawser::model::{
    Manoeuvre, ManoeuvreSpec, MassMatrix, Motion, PointKind, RaoMotion, RaoTable, RigidKinematics,
    RigidMotion, RigidTimeSeries, euler_kinematics,
};
use hawser::physics::waves::{
    IrregularSea, RegularWave, SeaState, Spectrum, Stretching, WaveSpec, Waves,
};
use hawser::validation::signal::fft;
use std::f64::consts::PI;

const G: Real = 9.80665;
const KNOT: Real = 1852.0 / 3600.0;

/// The angular velocity from orientations at t ± h: log(q(t+h) q(t−h)⁻¹) / 2h [rad/s]
/// (global axes), second-order accurate.
fn omega_fd(m: &RigidMotion, t: Real, h: Real) -> Vec3 {
    let q1 = m.kinematics(t + h).orientation;
    let q0 = m.kinematics(t - h).orientation;
    (q1 * q0.inverse()).scaled_axis() / (2.0 * h)
}

/// Largest mismatch of v, a, ω and dω/dt against central differences with step h, each
/// relative to `scale` = (position, velocity, acceleration, angular rate, angular
/// acceleration) magnitudes.
fn fd_errors(m: &RigidMotion, t: Real, h: Real) -> [Real; 4] {
    let k = m.kinematics(t);
    let (p, n) = (m.kinematics(t + h), m.kinematics(t - h));
    [
        ((p.position - n.position) / (2.0 * h) - k.velocity).norm(),
        ((p.velocity - n.velocity) / (2.0 * h) - k.acceleration).norm(),
        (omega_fd(m, t, h) - k.angular_velocity).norm(),
        ((p.angular_velocity - n.angular_velocity) / (2.0 * h) - k.angular_acceleration).norm(),
    ]
}

fn assert_fd(m: &RigidMotion, times: &[Real], h: Real, tol: [Real; 4], what: &str) {
    let mut worst = [0.0f64; 4];
    for &t in times {
        let e = fd_errors(m, t, h);
        for i in 0..4 {
            worst[i] = worst[i].max(e[i]);
            assert!(
                e[i] <= tol[i],
                "{what}: t = {t}: {} mismatch {:.3e} > {:.1e}",
                [
                    "velocity",
                    "acceleration",
                    "angular velocity",
                    "angular acceleration"
                ][i],
                e[i],
                tol[i]
            );
        }
    }
    eprintln!(
        "{what}: worst FD mismatches (v, a, ω, α) {:.2e} {:.2e} {:.2e} {:.2e}",
        worst[0], worst[1], worst[2], worst[3]
    );
}

// ---------------------------------------------------------------------------------------------
// Manoeuvre

/// The position-vector paper's 270° turn at 12 knots, to port or starboard.
fn turn(angle_deg: Real, transition: Real, build_up: Real, after: Option<Real>) -> Manoeuvre {
    Manoeuvre::new(ManoeuvreSpec {
        start: Vec3::new(10.0, -20.0, -3.0),
        heading: 30f64.to_radians(),
        speed: 12.0 * KNOT,
        straight_before: 400.0,
        turn_radius: 250.0,
        turn_angle: angle_deg.to_radians(),
        straight_after: after,
        build_up_time: build_up,
        transition_length: transition,
    })
    .expect("a valid manoeuvre")
}

/// A circular turn (no transitions): before the turn the vessel runs straight on its heading;
/// in the turn the origin stays on the circle of radius R about the analytic centre (start +
/// L1 T0 ± R N0), the heading follows the tangent and the acceleration is the centripetal
/// U²/R toward the centre; at the exit the heading has changed by Θ exactly and the position is
/// the analytic exit point; after it the vessel runs straight at U. To port and to starboard;
/// tolerance 1e-9 m (rounding of ~1e3 m coordinates through a few trigonometric evaluations).
#[test]
fn circular_turn_geometry_is_exact() {
    let u = 12.0 * KNOT;
    for angle in [270.0, -270.0] {
        let m = turn(angle, 0.0, 0.0, None);
        let (r, l1) = (250.0, 400.0);
        let psi0: Real = 30f64.to_radians();
        let theta = (angle as Real).to_radians();
        let side = theta.signum();
        let t0 = Vec3::new(psi0.cos(), psi0.sin(), 0.0);
        let n0 = Vec3::new(-psi0.sin(), psi0.cos(), 0.0);
        let start = Vec3::new(10.0, -20.0, -3.0);
        let entry = start + t0 * l1;
        let centre = entry + n0 * (side * r);
        let (cx, cy) = m.turn_centre().unwrap();
        assert!((Vec3::new(cx, cy, -3.0) - centre).norm() < 1e-9);
        let [s_in, _, _, s_out] = m.turn_arc_lengths();
        assert!((s_in - l1).abs() < 1e-12 && (s_out - (l1 + r * theta.abs())).abs() < 1e-9);
        let rm = RigidMotion::Manoeuvre(Box::new(m.clone()));
        // Straight before: on the line, heading ψ0.
        for t in [0.0, 20.0, l1 / u - 1.0] {
            let k = rm.kinematics(t);
            assert!((k.position - (start + t0 * (u * t))).norm() < 1e-9);
            assert!((k.velocity - t0 * u).norm() < 1e-12 && k.acceleration.norm() < 1e-12);
            assert!(
                (k.orientation
                    .angle_to(&Quat::from_axis_angle(&Vec3::z_axis(), psi0)))
                    < 1e-12
            );
        }
        // In the turn.
        let t_in = l1 / u;
        let t_out = t_in + r * theta.abs() / u;
        for i in 1..50 {
            let t = t_in + (t_out - t_in) * i as Real / 50.0;
            let k = rm.kinematics(t);
            let d = k.position - centre;
            assert!(
                (d.norm() - r).abs() < 1e-9,
                "off the circle by {}",
                d.norm() - r
            );
            let psi = psi0 + side * u * (t - t_in) / r;
            let tangent = Vec3::new(psi.cos(), psi.sin(), 0.0);
            assert!((k.velocity - tangent * u).norm() < 1e-9);
            // Centripetal: U²/R toward the centre.
            let a_want = -d / r * (u * u / r);
            assert!(
                (k.acceleration - a_want).norm() < 1e-12,
                "{}",
                k.acceleration
            );
            assert!((k.angular_velocity.z - side * u / r).abs() < 1e-15);
            let q = Quat::from_axis_angle(&Vec3::z_axis(), psi);
            assert!(k.orientation.angle_to(&q) < 1e-9);
        }
        // Exit and after.
        let psi1 = psi0 + theta;
        let n1 = Vec3::new(-psi1.sin(), psi1.cos(), 0.0);
        let t1 = Vec3::new(psi1.cos(), psi1.sin(), 0.0);
        let exit = centre - n1 * (side * r);
        for dt in [0.0, 10.0, 100.0] {
            let k = rm.kinematics(t_out + dt);
            assert!((k.position - (exit + t1 * (u * dt))).norm() < 1e-9, "{dt}");
            assert!((k.velocity - t1 * u).norm() < 1e-9);
            let q = Quat::from_axis_angle(&Vec3::z_axis(), psi1);
            assert!(k.orientation.angle_to(&q) < 1e-12);
            if dt > 0.0 {
                assert!(k.acceleration.norm() < 1e-12 && k.angular_velocity.norm() < 1e-15);
            }
        }
        // The heading change is Θ: yaw unwrapped over the turn.
        let mut yaw = psi0;
        let mut last = psi0;
        for i in 0..=1000 {
            let t = t_out * i as Real / 1000.0;
            let (_, _, y) = rm.kinematics(t).orientation.euler_angles();
            yaw += (y - last + PI).rem_euclid(2.0 * PI) - PI;
            last = y;
        }
        assert!((yaw - psi1).abs() < 1e-9, "heading change {}", yaw - psi0);
    }
}

/// With a smooth build-up and a stop, and with curvature transitions: velocity, acceleration,
/// angular velocity and angular acceleration match central differences of position,
/// velocity, orientation and angular velocity (h = 1e-3 s: truncation ~h² |d³r/dt³| ~ 1e-8;
/// tolerance 1e-6) everywhere except within h of the instants where an acceleration is
/// discontinuous by design (the ends of a circular turn without transitions).
#[test]
fn manoeuvre_derivatives_match_finite_differences() {
    let u = 12.0 * KNOT;
    for (transition, build_up) in [(0.0, 0.0), (0.0, 60.0), (80.0, 60.0)] {
        let m = turn(270.0, transition, build_up, Some(300.0));
        let [s_in, _, _, s_out] = m.turn_arc_lengths();
        let end = m.track_end();
        let rm = RigidMotion::Manoeuvre(Box::new(m.clone()));
        let t_end = end / u + build_up;
        let times: Vec<Real> = (0..400)
            .map(|i| 0.0013 + (t_end + 20.0) * i as Real / 400.0)
            .filter(|&t| {
                let s = m.arc_length(t).0;
                transition > 0.0 || ((s - s_in).abs() > 0.01 && (s - s_out).abs() > 0.01)
            })
            .collect();
        assert_fd(
            &rm,
            &times,
            1e-3,
            [1e-6, 1e-6, 1e-6, 1e-6],
            &format!("manoeuvre, transitions {transition} m, build-up {build_up} s"),
        );
    }
}

/// The build-up starts from rest with zero acceleration, covers U T_b/2 and reaches U with
/// zero acceleration at T_b; with a `straight_after` the vessel comes to rest exactly at the
/// end of the track, on the exit heading, and stays there.
#[test]
fn build_up_and_stop() {
    let u = 12.0 * KNOT;
    let m = turn(-270.0, 50.0, 60.0, Some(300.0));
    let rm = RigidMotion::Manoeuvre(Box::new(m.clone()));
    let k0 = rm.kinematics(0.0);
    assert_eq!(k0.velocity.norm() + k0.acceleration.norm(), 0.0);
    assert!((k0.position - Vec3::new(10.0, -20.0, -3.0)).norm() == 0.0);
    let (s, sd, sdd) = m.arc_length(60.0);
    assert!((s - 0.5 * u * 60.0).abs() < 1e-9 && (sd - u).abs() < 1e-12 && sdd.abs() < 1e-12);
    let (s, sd, sdd) = m.arc_length(30.0);
    assert!((s - u * 60.0 * (2.5 / 16.0 - 3.0 / 32.0 + 1.0 / 64.0)).abs() < 1e-9);
    assert!((sd - 0.5 * u).abs() < 1e-12 && sdd > 0.0);
    let end = m.track_end();
    let [_, _, _, s_out] = m.turn_arc_lengths();
    assert!((end - s_out - 300.0).abs() < 1e-9);
    let t_stop = end / u + 60.0;
    let k = rm.kinematics(t_stop);
    let k_later = rm.kinematics(t_stop + 100.0);
    assert!(k.velocity.norm() < 1e-12 && k.acceleration.norm() < 1e-12);
    assert!((k.position - k_later.position).norm() < 1e-12);
    assert!((m.arc_length(t_stop).0 - end).abs() < 1e-9);
    let (_, _, yaw) = k.orientation.euler_angles();
    let want = (30.0 - 270.0 as Real).to_radians();
    assert!(
        ((yaw - want).rem_euclid(2.0 * PI)).min(2.0 * PI - (yaw - want).rem_euclid(2.0 * PI))
            < 1e-12
    );
}

/// Curvature transitions: the heading still changes by Θ exactly, the middle arc stays on a
/// circle of radius R, the curvature rises linearly over L_c (acceleration continuous at the
/// four junctions: jumps below 1e-9 m/s² across ±1e-9 s, where the jerk U³/(R L_c) ~ 0.01 m/s³
/// contributes 2e-11; without transitions the jump is U²/R = 0.15 m/s²) and the exit position agrees with an
/// independent integration of the heading (trapezoidal rule, 2e5 steps, error ~1e-7 m).
#[test]
fn curvature_transitions_keep_the_turn_exact() {
    let u = 12.0 * KNOT;
    let (r, lc) = (250.0, 80.0);
    let m = turn(270.0, lc, 0.0, None);
    let rm = RigidMotion::Manoeuvre(Box::new(m.clone()));
    let s = m.turn_arc_lengths();
    assert!((s[1] - s[0] - lc).abs() < 1e-12 && (s[3] - s[2] - lc).abs() < 1e-9);
    assert!((s[2] - s[1] - (r * 1.5 * PI - lc)).abs() < 1e-9);
    let (cx, cy) = m.turn_centre().unwrap();
    for i in 0..=20 {
        let sa = s[1] + (s[2] - s[1]) * i as Real / 20.0;
        let (x, y, _, k, _) = m.track(sa);
        assert!(((x - cx).hypot(y - cy) - r).abs() < 1e-9 && (k - 1.0 / r).abs() < 1e-15);
    }
    for &sj in &s {
        let t = sj / u;
        let a0 = rm.kinematics(t - 1e-9).acceleration;
        let a1 = rm.kinematics(t + 1e-9).acceleration;
        assert!(
            (a1 - a0).norm() < 1e-9,
            "acceleration jumps by {}",
            (a1 - a0).norm()
        );
    }
    // Without transitions it jumps by U²/R.
    let arc = RigidMotion::Manoeuvre(Box::new(turn(270.0, 0.0, 0.0, None)));
    let t = 400.0 / u;
    let jump =
        (arc.kinematics(t + 1e-9).acceleration - arc.kinematics(t - 1e-9).acceleration).norm();
    assert!((jump - u * u / r).abs() < 1e-9);
    let (_, _, psi_end, _, _) = m.track(s[3]);
    assert!((psi_end - (30f64.to_radians() + 1.5 * PI)).abs() < 1e-12);
    // Independent integration of the heading ψ(s) (piecewise polynomial) to the exit.
    let psi = |q: Real| -> Real {
        let psi0 = 30f64.to_radians();
        let k = 1.0 / r;
        let d = q - s[0];
        if d <= 0.0 {
            psi0
        } else if d <= lc {
            psi0 + 0.5 * k / lc * d * d
        } else if q <= s[2] {
            psi0 + 0.5 * k * lc + k * (d - lc)
        } else {
            let e = q - s[2];
            psi0 + 0.5 * k * lc + k * (s[2] - s[1]) + k * e - 0.5 * k / lc * e * e
        }
    };
    let n = 200_000;
    let h = s[3] / n as Real;
    let (mut x, mut y) = (10.0, -20.0);
    for i in 0..n {
        let (a, b) = (psi(i as Real * h), psi((i + 1) as Real * h));
        x += 0.5 * h * (a.cos() + b.cos());
        y += 0.5 * h * (a.sin() + b.sin());
    }
    let (ex, ey, _, _, _) = m.track(s[3]);
    assert!((ex - x).hypot(ey - y) < 1e-5, "exit {ex}, {ey} vs {x}, {y}");
}

/// A valid turn of 1 rad on a 200 m radius without transitions, for the refusal tests.
fn one_radian_turn() -> ManoeuvreSpec {
    ManoeuvreSpec {
        start: Vec3::zeros(),
        heading: 0.0,
        speed: 6.0,
        straight_before: 100.0,
        turn_radius: 200.0,
        turn_angle: 1.0,
        straight_after: None,
        build_up_time: 10.0,
        transition_length: 0.0,
    }
}

#[test]
fn invalid_manoeuvres_are_refused() {
    let ok = one_radian_turn();
    assert!(Manoeuvre::new(ok.clone()).is_ok());
    for bad in [
        ManoeuvreSpec {
            turn_radius: -1.0,
            ..ok.clone()
        },
        ManoeuvreSpec {
            speed: 0.0,
            ..ok.clone()
        },
        ManoeuvreSpec {
            straight_before: -5.0,
            ..ok.clone()
        },
        ManoeuvreSpec {
            transition_length: 201.0,
            ..ok.clone()
        },
        ManoeuvreSpec {
            turn_angle: Real::NAN,
            ..ok.clone()
        },
        ManoeuvreSpec {
            straight_after: Some(0.0),
            straight_before: 0.0,
            turn_angle: 0.0,
            build_up_time: 10.0,
            ..ok.clone()
        },
    ] {
        assert!(Manoeuvre::new(bad.clone()).is_err(), "{bad:?}");
    }
}

/// Manoeuvres whose clothoids cannot be evaluated in bounded work are refused: a subnormal
/// transition length once made the curvature rate κ/L_c infinite and the loader loop for
/// ever; a huge turn angle made each evaluation cost ~|Θ| quadrature panels. At the limits
/// the track is still exact: the exit heading is ψ0 + Θ and the kinematics are finite.
#[test]
fn manoeuvre_limits_bound_the_work() {
    let ok = one_radian_turn();
    let min = Manoeuvre::MIN_TRANSITION_RATIO * ok.turn_radius;
    for lc in [5e-324, 1e-310, 1e-300, 1e-20, 0.99 * min] {
        let bad = ManoeuvreSpec {
            transition_length: lc,
            ..ok.clone()
        };
        assert!(Manoeuvre::new(bad).is_err(), "transition {lc:e} m accepted");
    }
    for angle in [1.0001 * Manoeuvre::MAX_TURN_ANGLE, -1e10, 1e300] {
        let bad = ManoeuvreSpec {
            turn_angle: angle,
            ..ok.clone()
        };
        assert!(Manoeuvre::new(bad).is_err(), "turn {angle:e} rad accepted");
    }
    let max_turn = Manoeuvre::MAX_TURN_ANGLE;
    for (lc, angle) in [(min, 1.0), (ok.turn_radius * max_turn, max_turn)] {
        let m = Manoeuvre::new(ManoeuvreSpec {
            transition_length: lc,
            turn_angle: angle,
            ..ok.clone()
        })
        .unwrap();
        let end = m.turn_arc_lengths()[3];
        for s in [0.0, 0.5 * end, end, 2.0 * end] {
            let (x, y, psi, k, kr) = m.track(s);
            assert!([x, y, psi, k, kr].iter().all(|v| v.is_finite()), "s = {s}");
        }
        // The exit heading is set exactly; 1e-9 rad allows the rounding of a sum of pieces.
        let (_, _, psi, _, _) = m.track(end + 1.0);
        assert!((psi - angle).abs() < 1e-9, "exit heading {psi} vs {angle}");
        let t = 2.0 * end / ok.speed;
        let kin = m.kinematics(t);
        assert!(kin.position.iter().all(|v| v.is_finite()));
    }
}

// ---------------------------------------------------------------------------------------------
// Euler angles and the 6-DOF table

fn rotation_matrix(roll: Real, pitch: Real, yaw: Real) -> Mat3 {
    let (sr, cr) = roll.sin_cos();
    let (sp, cp) = pitch.sin_cos();
    let (sy, cy) = yaw.sin_cos();
    let rx = Mat3::new(1.0, 0.0, 0.0, 0.0, cr, -sr, 0.0, sr, cr);
    let ry = Mat3::new(cp, 0.0, sp, 0.0, 1.0, 0.0, -sp, 0.0, cp);
    let rz = Mat3::new(cy, -sy, 0.0, sy, cy, 0.0, 0.0, 0.0, 1.0);
    rz * ry * rx
}

/// An analytic 6-DOF motion: surge-sway-heave oscillations on a drift, roll and pitch
/// oscillations, and a yaw that turns through ±180° (so a table of it, wrapped into
/// (−180°, 180°], needs unwrapping).
fn analytic(t: Real) -> ([Real; 6], [Real; 6], [Real; 6]) {
    let w = [0.31, 0.47, 0.62, 0.53, 0.41, 0.2];
    let a = [3.0, 2.0, 1.5, 0.2, 0.15, 0.3];
    let drift = [0.8, -0.3, 0.0, 0.0, 0.0, 0.25];
    let mut y = [0.0; 6];
    let mut dy = [0.0; 6];
    let mut ddy = [0.0; 6];
    for c in 0..6 {
        let (s, co) = (w[c] * t + c as Real).sin_cos();
        y[c] = a[c] * s + drift[c] * t;
        dy[c] = a[c] * w[c] * co + drift[c];
        ddy[c] = -a[c] * w[c] * w[c] * s;
    }
    (y, dy, ddy)
}

/// nalgebra's `from_euler_angles` is R_z(ψ) R_y(θ) R_x(φ), the convention of vessel-motion
/// files; and the kinematic map of `euler_kinematics` agrees with finite differences of the
/// orientation (ω) and of ω (dω/dt) along the analytic motion (h = 1e-4 s; tolerance 1e-8
/// rad/s, 1e-7 rad/s² for second-order differences of rates ~0.1 rad/s).
#[test]
fn euler_angle_kinematic_map() {
    for (r, p, y) in [(0.3, -0.7, 2.5), (-1.2, 0.4, -3.0), (0.0, 1.5, 0.1)] {
        let q = Quat::from_euler_angles(r, p, y);
        assert!((q.to_rotation_matrix().into_inner() - rotation_matrix(r, p, y)).norm() < 1e-14);
    }
    let at = |t: Real| {
        let (y, dy, ddy) = analytic(t);
        euler_kinematics(
            [y[3], y[4], y[5]],
            [dy[3], dy[4], dy[5]],
            [ddy[3], ddy[4], ddy[5]],
        )
    };
    let h = 1e-4;
    for i in 0..50 {
        let t = 0.37 * i as Real;
        let (_, w, al) = at(t);
        let (q1, w1, _) = at(t + h);
        let (q0, w0, _) = at(t - h);
        let w_fd = (q1 * q0.inverse()).scaled_axis() / (2.0 * h);
        assert!(
            (w_fd - w).norm() < 1e-8,
            "ω at {t}: {:.2e}",
            (w_fd - w).norm()
        );
        assert!(((w1 - w0) / (2.0 * h) - al).norm() < 1e-7, "α at {t}");
    }
}

/// The not-a-knot spline table of an analytic 6-DOF motion sampled every h (angles wrapped to
/// (−π, π] in the table): errors of position, velocity and acceleration, and of the angular
/// velocity, fall as h⁴, h³, h², h³ (measured orders within 0.4 of these, h from 1 s to 0.125 s,
/// away from the table's ends where the not-a-knot condition is one order weaker); the table
/// reproduces its samples exactly; outside it the pose is held at rest.
#[test]
fn time_series_converges_to_the_analytic_motion() {
    let duration = 40.0;
    let mut errors = Vec::new();
    for h in [1.0, 0.5, 0.25, 0.125] {
        let n = (duration / h) as usize + 1;
        let times: Vec<Real> = (0..n).map(|i| i as Real * h).collect();
        let samples: Vec<[Real; 6]> = times.iter().map(|&t| analytic(t).0).collect();
        let positions: Vec<Vec3> = samples
            .iter()
            .map(|y| Vec3::new(y[0], y[1], y[2]))
            .collect();
        let wrap = |a: Real| a - 2.0 * PI * (a / (2.0 * PI)).round();
        let angles: Vec<[Real; 3]> = samples
            .iter()
            .map(|y| [wrap(y[3]), wrap(y[4]), wrap(y[5])])
            .collect();
        assert!(
            angles.windows(2).any(|w| (w[1][2] - w[0][2]).abs() > PI),
            "no wrap"
        );
        let s = RigidTimeSeries::new(times.clone(), &positions, &angles).unwrap();
        let m = RigidMotion::TimeSeries(s);
        for (t, y) in times.iter().zip(&samples) {
            let k = m.kinematics(*t);
            assert!((k.position - Vec3::new(y[0], y[1], y[2])).norm() < 1e-12);
        }
        let mut e = [0.0f64; 4];
        for i in 0..2000 {
            let t = 5.0 + 30.0 * i as Real / 2000.0 + 0.0123;
            let (y, dy, ddy) = analytic(t);
            let k = m.kinematics(t);
            let (q, w, _) = euler_kinematics(
                [y[3], y[4], y[5]],
                [dy[3], dy[4], dy[5]],
                [ddy[3], ddy[4], ddy[5]],
            );
            e[0] = e[0].max(
                (k.position - Vec3::new(y[0], y[1], y[2])).norm() + k.orientation.angle_to(&q),
            );
            e[1] = e[1].max((k.velocity - Vec3::new(dy[0], dy[1], dy[2])).norm());
            e[2] = e[2].max((k.acceleration - Vec3::new(ddy[0], ddy[1], ddy[2])).norm());
            e[3] = e[3].max((k.angular_velocity - w).norm());
        }
        errors.push(e);
    }
    for (q, want) in [4.0, 3.0, 2.0, 3.0]
        .iter()
        .enumerate()
        .map(|(i, w)| (i, *w))
    {
        let orders: Vec<Real> = errors
            .windows(2)
            .map(|w| (w[0][q] / w[1][q]).log2())
            .collect();
        eprintln!(
            "channel {q}: errors {:?}, orders {orders:.2?}",
            errors.iter().map(|e| e[q]).collect::<Vec<_>>()
        );
        for o in orders {
            assert!((o - want).abs() < 0.4, "order {o} for {want}");
        }
    }
    // Outside the table: held, at rest.
    let times = vec![0.0, 1.0, 2.0, 3.0, 4.0];
    let positions: Vec<Vec3> = times.iter().map(|&t| Vec3::new(t * t, 0.0, 0.0)).collect();
    let angles = vec![[0.0; 3]; 5];
    let m = RigidMotion::TimeSeries(RigidTimeSeries::new(times, &positions, &angles).unwrap());
    let k = m.kinematics(10.0);
    assert_eq!((k.position.x, k.velocity.norm()), (16.0, 0.0));
    // A quadratic is reproduced exactly by the not-a-knot spline, derivatives too.
    let k = m.kinematics(2.5);
    assert!((k.position.x - 6.25).abs() < 1e-12 && (k.velocity.x - 5.0).abs() < 1e-12);
    assert!((k.acceleration.x - 2.0).abs() < 1e-12);
}

/// The analytic motion's rows at `times`: positions [m] and angles [rad], unwrapped.
fn analytic_rows(times: &[Real]) -> (Vec<Vec3>, Vec<[Real; 3]>) {
    times
        .iter()
        .map(|&t| {
            let y = analytic(t).0;
            (Vec3::new(y[0], y[1], y[2]), [y[3], y[4], y[5]])
        })
        .unzip()
}

/// The spline table's derivatives are its own: FD of position, orientation and rates inside
/// intervals (h = 1e-4 s; tolerance 1e-6: the spline's third derivative is ~1 per s³).
#[test]
fn time_series_derivatives_match_finite_differences() {
    let times: Vec<Real> = (0..41).map(|i| i as Real * 0.7).collect();
    let (positions, angles) = analytic_rows(&times);
    let m = RigidMotion::TimeSeries(RigidTimeSeries::new(times, &positions, &angles).unwrap());
    // Off the knots (multiples of 0.7 s), where the spline's third derivative jumps.
    let times: Vec<Real> = (0..100)
        .map(|i| 0.063 + 0.27 * i as Real)
        .filter(|t| (t / 0.7 - (t / 0.7).round()).abs() > 1e-3)
        .collect();
    assert_fd(&m, &times, 1e-4, [1e-6; 4], "6-DOF spline table");
}

/// The table's lookup starts from the interval of its last one: whatever the order of the
/// times asked (forwards a step at a time, the same time twice, backwards, jumps across the
/// table, on knots, outside it, NaN), each answer has the same bits as a fresh table's, whose
/// lookup searches; and inside the table each position is the analytic motion's within the
/// spline's error bound (5/384) h⁴ max|y⁗| = 2.9e-7 (h = 0.1 s, max|y⁗| = 1.5 · 0.62⁴ = 0.22
/// in z), checked at 1e-6 for the not-a-knot ends: the spline of a neighbouring interval,
/// which a wrong lookup would evaluate, is off by about |y‴| h³ = 1e-4 there. The table's
/// `Debug` form (the model's hash, which a checkpoint checks on resume) does not change with
/// its lookups.
#[test]
fn time_series_lookup_order_does_not_change_the_answer() {
    let times: Vec<Real> = (0..301).map(|i| i as Real * 0.1).collect();
    let (positions, angles) = analytic_rows(&times);
    let table = RigidTimeSeries::new(times, &positions, &angles).unwrap();
    let before = format!("{table:?}");
    let mut asked: Vec<Real> = (0..2000).map(|i| i as Real * 0.002).collect(); // forwards
    asked.extend([
        3.9999, 3.9999, 4.0, 4.0, 3.95, 0.05, 29.99, 30.0, 31.0, -1.0, 0.0,
    ]);
    asked.extend((0..300).map(|i| 29.95 - i as Real * 0.0999)); // backwards
    asked.extend((0..200).map(|i| (i * 7919 % 300) as Real * 0.1 + 0.037)); // jumps
    asked.push(Real::NAN);
    asked.push(12.3456);
    let mut worst: Real = 0.0;
    for &t in &asked {
        let fresh = RigidTimeSeries::new(table.times().to_vec(), &positions, &angles).unwrap();
        let (y, dy, ddy) = table.channels(t);
        let (y0, dy0, ddy0) = fresh.channels(t);
        let bits = |a: [Real; 6]| a.map(Real::to_bits);
        assert_eq!(
            (bits(y), bits(dy), bits(ddy)),
            (bits(y0), bits(dy0), bits(ddy0)),
            "t = {t}"
        );
        if (0.0..=30.0).contains(&t) {
            let exact = analytic(t).0;
            for c in 0..3 {
                worst = worst.max((y[c] - exact[c]).abs());
            }
        }
    }
    eprintln!("worst position error inside the table: {worst:.2e} m");
    assert!(worst < 1e-6, "{worst:e}");
    assert_eq!(format!("{table:?}"), before);
}

// ---------------------------------------------------------------------------------------------
// RAO motion

fn regular_wave(height: Real, period: Real, direction: Real, depth: Real, ramp: Real) -> Waves {
    Waves::new(
        &WaveSpec {
            sea: SeaState::Regular(RegularWave {
                height,
                period,
                direction,
            }),
            ramp_time: ramp,
            stretching: Stretching::Wheeler,
        },
        depth,
        G,
    )
    .unwrap()
}

/// A table with the given RAO (amplitude, lag) per DOF at every frequency and heading.
fn flat_table(rao: [(Real, Real); 6], headings: &[Real]) -> RaoTable {
    let freqs = vec![0.2, 0.5, 1.0, 2.0];
    let n = freqs.len() * headings.len();
    let amps = vec![rao.map(|r| r.0); n];
    let phases = vec![rao.map(|r| r.1); n];
    RaoTable::new(freqs, headings, &amps, &phases).unwrap()
}

fn fixed(x: Real, y: Real, heading_deg: Real) -> RigidMotion {
    RigidMotion::Fixed {
        position: Vec3::new(x, y, 0.0),
        orientation: Quat::from_axis_angle(&Vec3::z_axis(), heading_deg.to_radians()),
    }
}

/// A heave RAO of 1 m/m with zero phase: the vessel's heave is the wave elevation at its
/// reference point, for any vessel heading and wave direction, ramp included (to 1e-12 m);
/// the other DOFs stay zero.
#[test]
fn unit_heave_rao_follows_the_surface() {
    let headings: Vec<Real> = (0..12).map(|i| (i as Real * 30.0).to_radians()).collect();
    let table = flat_table(
        [
            (0.0, 0.0),
            (0.0, 0.0),
            (1.0, 0.0),
            (0.0, 0.0),
            (0.0, 0.0),
            (0.0, 0.0),
        ],
        &headings,
    );
    for (dir, heading, depth) in [
        (0.0, 0.0, 80.0),
        (70.0, 40.0, Real::INFINITY),
        (-135.0, 200.0, 30.0),
    ] {
        let waves = regular_wave(3.0, 9.0, (dir as Real).to_radians(), depth, 20.0);
        let m = RaoMotion::new(table.clone(), &waves, fixed(50.0, 20.0, heading)).unwrap();
        let m = RigidMotion::Rao(Box::new(m));
        for i in 0..200 {
            let t = 0.173 * i as Real;
            let k = m.kinematics(t);
            let eta = waves.elevation(50.0, 20.0, t);
            assert!(
                (k.position.z - eta).abs() < 1e-12,
                "t {t}: {} vs {eta}",
                k.position.z
            );
            assert!((k.position.x - 50.0).abs() < 1e-15 && (k.position.y - 20.0).abs() < 1e-15);
            let q = Quat::from_axis_angle(&Vec3::z_axis(), heading.to_radians());
            assert!(k.orientation.angle_to(&q) < 1e-15);
        }
    }
}

/// The phase convention: a pitch RAO of 2°/m lagging 60° in a regular wave gives
/// pitch(t) = a |RAO| cos(ωt − k·x_ref − φ − lag) (checked to 1e-12 rad), so its maximum comes
/// lag/ω after the crest passes the reference point (checked on a fine time grid). The wave
/// travels at 45° to a vessel heading 10°: the table's 30° and 60° rows (RAOs differing) are
/// interpolated at 35°.
#[test]
fn pitch_rao_lags_the_crest() {
    let headings = [
        0.0,
        30f64.to_radians(),
        60f64.to_radians(),
        180f64.to_radians(),
    ];
    let freqs = vec![0.3, 0.9];
    let mut amps = vec![[0.0; 6]; 8];
    let mut phases = vec![[0.0; 6]; 8];
    for f in 0..2 {
        amps[f * 4 + 1][4] = 2f64.to_radians();
        amps[f * 4 + 2][4] = 2f64.to_radians();
        phases[f * 4 + 1][4] = 60f64.to_radians();
        phases[f * 4 + 2][4] = 60f64.to_radians();
        // A different roll at 30° and 60°, to see the interpolation weight.
        amps[f * 4 + 1][3] = 1f64.to_radians();
        amps[f * 4 + 2][3] = 4f64.to_radians();
    }
    let table = RaoTable::new(freqs, &headings, &amps, &phases).unwrap();
    let period = 10.0;
    let waves = regular_wave(2.0, period, 45f64.to_radians(), Real::INFINITY, 0.0);
    let c = &waves.field().unwrap().components()[0];
    let (w, k) = (c.angular_frequency(), c.wavenumber());
    let (xr, yr) = (-30.0, 12.0);
    let m = RaoMotion::new(table, &waves, fixed(xr, yr, 10.0)).unwrap();
    let kx = k * (xr * 45f64.to_radians().cos() + yr * 45f64.to_radians().sin());
    let lag = 60f64.to_radians();
    let mut best = (Real::NEG_INFINITY, 0.0);
    for i in 0..20000 {
        let t = period * i as Real / 20000.0;
        let (xi, _, _, _) = m.responses(t);
        let want = 1.0 * 2f64.to_radians() * (w * t - kx - c.phase() - lag).cos();
        assert!((xi[4] - want).abs() < 1e-12, "pitch at {t}");
        // Roll: 35° is 1/6 of the way from 30° to 60°: 1° + (4° − 1°)/6 = 1.5°, zero lag.
        let roll = 1.5f64.to_radians() * (w * t - kx - c.phase()).cos();
        assert!((xi[3] - roll).abs() < 1e-12, "roll at {t}");
        if xi[4] > best.0 {
            best = (xi[4], t);
        }
    }
    // The crest passes the reference point when w t = kx + φ (mod 2π).
    let crest = ((kx + c.phase()) / w).rem_euclid(period);
    let delay = (best.1 - crest).rem_euclid(period);
    assert!(
        (delay - lag / w).abs() < 2.0 * period / 20000.0,
        "delay {delay} vs {}",
        lag / w
    );
    // And the orientation carries it: R = R_z(10°) R_z(yaw) R_y(pitch) R_x(roll).
    let t = 3.3;
    let (xi, _, _, _) = m.responses(t);
    let k = RigidMotion::Rao(Box::new(m)).kinematics(t);
    let want = rotation_matrix(0.0, 0.0, 10f64.to_radians()) * rotation_matrix(xi[3], xi[4], xi[5]);
    assert!((k.orientation.to_rotation_matrix().into_inner() - want).norm() < 1e-14);
}

/// Interpolation rules: linear in frequency of the complex RAO; below the lowest frequency the
/// lowest row; above the highest zero; headings periodic (between 300° and 0°+360°); 0° and
/// 360° given with equal RAOs are merged, with different RAOs refused.
#[test]
fn rao_table_interpolation_rules() {
    let headings = [0.0, 120f64.to_radians(), 300f64.to_radians()];
    let freqs = vec![0.5, 1.0];
    let amp = |f: usize, h: usize| [1.0 + f as Real, 0.0, 2.0 + h as Real, 0.0, 0.0, 0.0];
    let amps: Vec<[Real; 6]> = (0..2)
        .flat_map(|f| (0..3).map(move |h| amp(f, h)))
        .collect();
    let phases = vec![[0.0; 6]; 6];
    let t = RaoTable::new(freqs.clone(), &headings, &amps, &phases).unwrap();
    assert_eq!(t.at(1.01, 0.0), [[0.0; 2]; 6]);
    assert_eq!(t.at(0.1, 0.0)[0], [1.0, 0.0]);
    assert!((t.at(0.75, 0.0)[0][0] - 1.5).abs() < 1e-15);
    // 330° is half-way from 300° (heave 4) to 360° (heave 2).
    assert!((t.at(0.5, 330f64.to_radians())[2][0] - 3.0).abs() < 1e-12);
    assert!((t.at(0.5, -30f64.to_radians())[2][0] - 3.0).abs() < 1e-12);
    // Complex interpolation: a lag of 0 and of 90° mid-way gives (1 − i)/2.
    let t2 = RaoTable::new(
        vec![0.5, 1.0],
        &[0.0],
        &[[1.0; 6], [1.0; 6]],
        &[[0.0; 6], [PI / 2.0; 6]],
    )
    .unwrap();
    let h = t2.at(0.75, 0.0)[0];
    assert!((h[0] - 0.5).abs() < 1e-15 && (h[1] + 0.5).abs() < 1e-15);
    // 0° and 360° with equal RAOs merge; with different ones they are refused.
    let h4 = [0.0, 120f64.to_radians(), 300f64.to_radians(), 2.0 * PI];
    let amps4: Vec<[Real; 6]> = (0..2)
        .flat_map(|f| (0..4).map(move |h| amp(f, h % 3)))
        .collect();
    let t4 = RaoTable::new(freqs.clone(), &h4, &amps4, &[[0.0; 6]; 8]).unwrap();
    assert_eq!(t4.headings().len(), 3);
    let mut bad = amps4.clone();
    bad[3][2] = 7.0;
    assert!(RaoTable::new(freqs.clone(), &h4, &bad, &[[0.0; 6]; 8]).is_err());
    assert!(RaoTable::new(vec![1.0, 0.5], &headings, &amps, &phases).is_err());
}

fn jonswap(seed: u64, spreading: Option<Real>) -> Waves {
    let spectrum = Spectrum::Jonswap {
        significant_height: 3.0,
        peak_period: 9.0,
        peak_enhancement: 3.3,
    };
    let wp = spectrum.peak_frequency();
    Waves::new(
        &WaveSpec {
            sea: SeaState::Irregular(IrregularSea {
                spectrum,
                direction: 0.4,
                spreading,
                seed,
                components: 200,
                frequency_range: (0.5 * wp, 5.0 * wp),
            }),
            ramp_time: 0.0,
            stretching: Stretching::Wheeler,
        },
        200.0,
        G,
    )
    .unwrap()
}

/// A heave RAO with a resonance-like peak: |H(ω)| = 1/√((1 − (ω/ωn)²)² + (2ζω/ωn)²) with
/// ωn = 0.6 rad/s, ζ = 0.15, and the matching phase lag, tabulated every 0.01 rad/s.
fn heave_rao_table() -> (RaoTable, impl Fn(Real) -> Real) {
    let (wn, zeta) = (0.6, 0.15);
    let h = move |w: Real| {
        let r = w / wn;
        ((1.0 - r * r).powi(2) + (2.0 * zeta * r).powi(2))
            .sqrt()
            .recip()
    };
    let lag = move |w: Real| {
        let r = w / wn;
        (2.0 * zeta * r).atan2(1.0 - r * r)
    };
    let freqs: Vec<Real> = (0..400).map(|i| 0.05 + 0.01 * i as Real).collect();
    let amps: Vec<[Real; 6]> = freqs
        .iter()
        .map(|&w| [0.0, 0.0, h(w), 0.0, 0.0, 0.0])
        .collect();
    let phases: Vec<[Real; 6]> = freqs
        .iter()
        .map(|&w| [0.0, 0.0, lag(w), 0.0, 0.0, 0.0])
        .collect();
    let table = RaoTable::new(freqs, &[0.0], &amps, &phases).unwrap();
    let interpolated = {
        let t = table.clone();
        move |w: Real| {
            let c = t.at(w, 0.0)[2];
            c[0] * c[0] + c[1] * c[1]
        }
    };
    (table, interpolated)
}

/// A JONSWAP sea (Hs 3 m, Tp 9 s, 200 components) drives the heave RAO above; from a 9.1 h
/// record of heave (2^16 samples at 0.5 s), the energy in six bands from 0.6 to 2.5 ωp is the
/// response spectrum |H|² S integrated over the band, in two steps: (1) the periodogram's
/// band energy equals the sea's discrete response Σ ½ a_j² |H(ω_j)|² over the band's
/// components within 1.5 % (as in the sea's own test, tests/waves.rs, band edges on the bins'
/// edges leave leakage and cross terms, 1 % there; the response concentrates its energy in
/// fewer components near the RAO peak, so the cross terms weigh more: measured 0.93 %); (2) that equals ∫ |H|² S dω within four standard
/// deviations of the random placement of each ω_j in its frequency bin (|H|² changes by up to
/// 20 % across a bin near the resonance), plus 0.1 % for quadrature. The record's variance
/// equals Σ ½ a_j² |H(ω_j)|² within four standard deviations of the sample variance (its
/// cross-term scatter computed as for the sea).
#[test]
fn jonswap_heave_response_spectrum_is_rao_squared_times_the_sea() {
    let waves = jonswap(5, None);
    let field = waves.field().unwrap();
    let (table, h2) = heave_rao_table();
    let m = RaoMotion::new(table, &waves, fixed(0.0, 0.0, 25.0)).unwrap();
    let (dt, n) = (0.5, 1usize << 16);
    let duration = dt * n as Real;
    let x: Vec<Real> = (0..n).map(|i| m.responses(i as Real * dt).0[2]).collect();
    let mean = x.iter().sum::<Real>() / n as Real;
    let m0_hat = x.iter().map(|v| (v - mean).powi(2)).sum::<Real>() / n as Real;
    let comps = field.components();
    let resp: Vec<Real> = comps
        .iter()
        .map(|c| c.amplitude() * h2(c.angular_frequency()).sqrt())
        .collect();
    let m0: Real = resp.iter().map(|a| 0.5 * a * a).sum();
    let mut var = 0.0;
    for i in 0..comps.len() {
        for j in i + 1..comps.len() {
            let d = (comps[i].angular_frequency() - comps[j].angular_frequency()) * duration;
            let aa = resp[i] * resp[j];
            var += aa * aa * 2.0 * (0.5 * d).sin().powi(2) / (d * d);
        }
    }
    let sigma = var.sqrt();
    eprintln!("heave m0 {m0_hat:.5} m² vs Σ ½ a² |H|² {m0:.5} (σ {sigma:.1e})");
    assert!((m0_hat - m0).abs() <= 4.0 * sigma);
    // Band energies from the periodogram of the whole record.
    let mut re: Vec<Real> = x.iter().map(|v| v - mean).collect();
    let mut im = vec![0.0; n];
    fft(&mut re, &mut im);
    let SeaState::Irregular(sea) = &field.spec().sea else {
        unreachable!()
    };
    let (w0, w1) = sea.frequency_range;
    let dwc = (w1 - w0) / sea.components as Real;
    let dw = 2.0 * PI / duration;
    let wp = 2.0 * PI / 9.0;
    let density = Spectrum::Jonswap {
        significant_height: 3.0,
        peak_period: 9.0,
        peak_enhancement: 3.3,
    }
    .density_function();
    let mut worst: Real = 0.0;
    let mut worst_sea: Real = 0.0;
    for e in [0.6, 0.8, 0.95, 1.1, 1.3, 1.7, 2.5].windows(2) {
        let wa = w0 + ((e[0] * wp - w0) / dwc).round() * dwc;
        let wb = w0 + ((e[1] * wp - w0) / dwc).round() * dwc;
        let (ia, ib) = ((wa / dw).round() as usize, (wb / dw).round() as usize);
        let est: Real = (ia..ib)
            .map(|i| 2.0 * (re[i] * re[i] + im[i] * im[i]) / (n as Real * n as Real))
            .sum();
        // This sea's response energy in the band, Σ ½ a_j² |H(ω_j)|², and its scatter about
        // ∫|H|²S over the random placement of ω_j in its bin: Var = Σ E_j² Var_bin(|H|²).
        let (mut discrete, mut var_sea) = (0.0, 0.0);
        for c in comps
            .iter()
            .filter(|c| (wa..wb).contains(&c.angular_frequency()))
        {
            let energy = 0.5 * c.amplitude() * c.amplitude();
            discrete += energy * h2(c.angular_frequency());
            let lo = w0 + ((c.angular_frequency() - w0) / dwc).floor() * dwc;
            let samples: Vec<Real> = (0..200)
                .map(|i| h2(lo + (i as Real + 0.5) * dwc / 200.0))
                .collect();
            let mean = samples.iter().sum::<Real>() / 200.0;
            let var = samples.iter().map(|x| (x - mean).powi(2)).sum::<Real>() / 200.0;
            var_sea += energy * energy * var;
        }
        let steps = 4000;
        let hh = (wb - wa) / steps as Real;
        let want: Real = (0..steps)
            .map(|i| {
                let w = wa + (i as Real + 0.5) * hh;
                h2(w) * density(w) * hh
            })
            .sum();
        let err = (est - discrete) / discrete;
        worst = worst.max(err.abs());
        assert!(
            err.abs() <= 0.015,
            "band {e:?} ωp: {est} vs Σ ½a²|H|² {discrete} m²"
        );
        let sigma = var_sea.sqrt();
        worst_sea = worst_sea.max((discrete - want).abs() / sigma);
        assert!(
            (discrete - want).abs() <= 4.0 * sigma + 1e-3 * want,
            "band {e:?} ωp: Σ ½a²|H|² {discrete} vs ∫|H|²S {want} m² (σ {sigma:.2e})"
        );
    }
    eprintln!(
        "heave response band energies within {:.2} % of Σ ½a²|H|²; that within {worst_sea:.2} σ \
         of ∫|H|²S",
        100.0 * worst
    );
}

/// A 6-DOF RAO table varying with heading, in a short-crested sea with a build-up ramp, on a
/// turning manoeuvre (so the relative headings sweep the table and the wave phase moves with
/// the vessel): every derivative matches central differences (h = 1e-4 s; tolerance 2e-6,
/// relative to accelerations ~1 m/s²: the truncation h² d³/dt³ ~1e-8 plus the kinks of the
/// linear heading interpolation, crossed at a rate ψ̇ ~0.025 rad/s, which cost at most
/// h ψ̇ |ΔdH/dβ| ~1e-6).
#[test]
fn rao_motion_derivatives_match_finite_differences() {
    let headings: Vec<Real> = (0..8).map(|i| (i as Real * 45.0).to_radians()).collect();
    let freqs: Vec<Real> = (0..30).map(|i| 0.2 + 0.05 * i as Real).collect();
    let mut amps = Vec::new();
    let mut phases = Vec::new();
    for (fi, _) in freqs.iter().enumerate() {
        for (hi, h) in headings.iter().enumerate() {
            let mut a = [0.0; 6];
            let mut p = [0.0; 6];
            for d in 0..6 {
                let scale = if d < 3 { 1.0 } else { 0.02 };
                a[d] =
                    scale * (0.5 + 0.4 * (h + d as Real).cos()) * (1.0 + 0.1 * fi as Real).recip();
                p[d] = 0.3 * fi as Real + hi as Real * 0.5 + d as Real;
            }
            amps.push(a);
            phases.push(p);
        }
    }
    let table = RaoTable::new(freqs, &headings, &amps, &phases).unwrap();
    let mut waves = jonswap(3, Some(4.0));
    if let Waves::Airy(f) = &waves {
        let mut spec = f.spec().clone();
        spec.ramp_time = 30.0;
        waves = Waves::new(&spec, 200.0, G).unwrap();
    }
    let mean = RigidMotion::Manoeuvre(Box::new(turn(120.0, 40.0, 20.0, None)));
    let m = RigidMotion::Rao(Box::new(RaoMotion::new(table, &waves, mean).unwrap()));
    let times: Vec<Real> = (0..300).map(|i| 0.011 + 0.37 * i as Real).collect();
    assert_fd(&m, &times, 1e-4, [2e-6; 4], "RAO motion on a manoeuvre");
}

/// A point on a rigid motion follows r = r_o + R offset with v, a from
/// RigidKinematics::point, which agree with central differences of its position.
#[test]
fn points_ride_on_rigid_motions() {
    let rigid = RigidMotion::Manoeuvre(Box::new(turn(270.0, 60.0, 30.0, None)));
    let offset = Vec3::new(-40.0, 3.0, -2.0);
    let p = Motion::Rigid {
        motion: Box::new(rigid.clone()),
        offset,
    };
    let h = 1e-3;
    for i in 0..100 {
        let t = 0.3 + 3.1 * i as Real;
        let k: RigidKinematics = rigid.kinematics(t);
        let (r, v, a) = p.kinematics(t);
        assert!((r - (k.position + k.orientation * offset)).norm() < 1e-12);
        let (r1, v1, _) = p.kinematics(t + h);
        let (r0, v0, _) = p.kinematics(t - h);
        assert!(((r1 - r0) / (2.0 * h) - v).norm() < 1e-6, "v at {t}");
        assert!(((v1 - v0) / (2.0 * h) - a).norm() < 1e-6, "a at {t}");
    }
}

/// The points of a system prescribed on one rigid motion (a vessel's fairleads) take the
/// motion's kinematics at each evaluation's time, to the bit, whatever times came before: the
/// workspace's value of the motion at its last time (`Workspace::rigid_motions`) is reused at
/// that time only, and shared by the points on the motion.
#[test]
fn system_points_take_their_motion_at_each_time() {
    let rigid = RigidMotion::Manoeuvre(Box::new(turn(90.0, 20.0, 10.0, None)));
    let on_motion = |offset: Vec3| {
        PointKind::Prescribed(Motion::Rigid {
            motion: Box::new(rigid.clone()),
            offset,
        })
    };
    let offsets = [Vec3::new(-40.0, 3.0, -2.0), Vec3::new(35.0, -8.0, -4.0)];
    let mut model = common::single_line(
        common::line_type(0.05, 20.0, 1.0e7),
        60.0,
        6,
        common::fixed("anchor", Vec3::new(0.0, 0.0, -50.0)),
        common::fixed("fairlead", Vec3::new(-40.0, 3.0, -2.0)),
        MassMatrix::Lumped,
    );
    model.points[1].kind = on_motion(offsets[0]);
    let mut second = common::fixed("second fairlead", Vec3::new(35.0, -8.0, -4.0));
    second.kind = on_motion(offsets[1]);
    model.points.push(second);
    let system = hawser::system::System::new(&model).unwrap();
    assert_eq!(
        system.rigid_motion_source[2],
        Some(1),
        "one motion for both"
    );
    let y = system.straight_state();
    let mut ws = system.workspace();
    for t in [0.5, 0.5, 1.25, 0.5, 7.0, 7.0, 1.25, 0.0, -0.0, 31.0] {
        system.point_kinematics(t, &y, &mut ws);
        for (p, offset) in [(1, offsets[0]), (2, offsets[1])] {
            let (r, v, a) = rigid.kinematics(t).point(&offset);
            let k = &ws.points[p];
            assert_eq!(
                [k.position, k.velocity, k.acceleration],
                [r, v, a],
                "point {p} at {t}"
            );
        }
    }
}

/// Evaluating any of the motions allocates nothing.
#[test]
fn evaluation_allocates_nothing() {
    let times: Vec<Real> = (0..20).map(|i| i as Real).collect();
    let positions: Vec<Vec3> = times.iter().map(|&t| Vec3::new(t, 0.0, 0.0)).collect();
    let angles = vec![[0.1, 0.0, 0.2]; 20];
    let (table, _) = heave_rao_table();
    let motions = vec![
        RigidMotion::Manoeuvre(Box::new(turn(270.0, 60.0, 30.0, Some(100.0)))),
        RigidMotion::TimeSeries(RigidTimeSeries::new(times, &positions, &angles).unwrap()),
        RigidMotion::Rao(Box::new(
            RaoMotion::new(
                table,
                &jonswap(1, Some(3.0)),
                RigidMotion::Manoeuvre(Box::new(turn(90.0, 0.0, 0.0, None))),
            )
            .unwrap(),
        )),
    ];
    let points: Vec<Motion> = motions
        .iter()
        .map(|m| Motion::Rigid {
            motion: Box::new(m.clone()),
            offset: Vec3::new(1.0, 2.0, 3.0),
        })
        .collect();
    let mut sink = 0.0;
    let n = allocations_in(|| {
        for i in 0..1000 {
            let t = 0.1 * i as Real;
            for m in &motions {
                sink += m.kinematics(t).position.x;
            }
            for p in &points {
                sink += p.kinematics(t).0.x;
            }
        }
    });
    assert!(sink.is_finite());
    assert_eq!(n, 0, "{n} allocations in 6000 evaluations");
}
