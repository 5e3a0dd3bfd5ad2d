//! Coupled points driven by a host reproduce the prescribed run they are fed from: OC3's three
//! fairleads in the 2 m, 10 s surge of examples/oc3_surge.toml, made `coupled`, with the host
//! setting each fairlead's position and velocity from the same motion at the end of every
//! coupling interval.
//!
//! - Coupling interval = the time step (2 ms): the state after 20 s equals the prescribed run's
//!   within 1e-9 relative, with positions and velocities only (cubic interpolant) and with the
//!   accelerations too (quintic). The host's kinematics are exact at every step end; inside
//!   the step RK4 reads them at the midpoint, where the cubic is off by O(Δt⁴ ẍ⁗) ≈ 1e-14 m in
//!   position and the acceleration at the ends by O(Δt ẍ‴) ≈ 1e-4 m/s² (measured: 6e-13 of
//!   the state; quintic 6e-15).
//! - Intervals 0.01, 0.05 and 0.1 s: the fairlead tension extremes over 60 s within 0.1 % of
//!   the prescribed run's with the cubic (the interpolation error grows as Δt⁴ in position and
//!   Δt³ in velocity; at 0.1 s the velocity error is ≈ a ω⁴ Δt³ / 24 ≈ 1e-5 m/s of 1.26 m/s),
//!   and within 1e-9 with the quintic, exact for this motion but for round-off.
//! - A repeated interval (a host that corrects its prediction) gives the same answer as the
//!   interval computed once with the corrected kinematics.

use hawser::Model;
use hawser::math::{Real, Vec3};
use hawser::model::{Motion, couple_prescribed_points};
use hawser::session::Session;
use hawser_io::scenario;
use std::path::Path;

fn oc3() -> Model {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/oc3_surge.toml");
    scenario::load(&path).expect("oc3_surge.toml").model
}

/// Feeds the host's kinematics at `t1` to the session: positions and velocities, and the
/// accelerations when `accelerations` (the interpolant is then quintic, else cubic).
fn feed_with(session: &mut Session, motions: &[(usize, Motion)], t1: Real, accelerations: bool) {
    for (p, m) in motions {
        let (x, v, a) = m.kinematics(t1);
        session
            .set_point_kinematics(*p, t1, x, v, accelerations.then_some(a))
            .expect("set");
    }
}

fn feed(session: &mut Session, motions: &[(usize, Motion)], t1: Real) {
    feed_with(session, motions, t1, false);
}

/// Runs the coupled model to `end` at coupling interval `dt_c`, recording the fairlead
/// tensions (end B of every line) at every coupling time.
fn run_coupled(
    model: &Model,
    dt_c: Real,
    end: Real,
    accelerations: bool,
) -> (Session, Vec<Vec<Real>>) {
    let (m, motions) = couple_prescribed_points(model);
    let mut session = Session::new(m).expect("coupled session");
    feed_with(&mut session, &motions, 0.0, accelerations);
    let lines = session.system().lines.len();
    let mut tensions = vec![Vec::new(); lines];
    let steps = (end / dt_c).round() as usize;
    for k in 1..=steps {
        let t1 = k as Real * dt_c;
        feed_with(&mut session, &motions, t1, accelerations);
        session.advance_to(t1).expect("advance");
        for (l, t) in tensions.iter_mut().enumerate() {
            t.push(session.view().unwrap().end_force(l, true).norm());
        }
    }
    (session, tensions)
}

fn run_prescribed(model: &Model, dt_c: Real, end: Real) -> (Session, Vec<Vec<Real>>) {
    let mut session = Session::new(model.clone()).expect("prescribed session");
    let lines = session.system().lines.len();
    let mut tensions = vec![Vec::new(); lines];
    let steps = (end / dt_c).round() as usize;
    for k in 1..=steps {
        session.advance_to(k as Real * dt_c).expect("advance");
        for (l, t) in tensions.iter_mut().enumerate() {
            t.push(session.view().unwrap().end_force(l, true).norm());
        }
    }
    (session, tensions)
}

fn relative_difference(a: &[Real], b: &[Real]) -> Real {
    let scale = a.iter().fold(0.0, |m: Real, x| m.max(x.abs()));
    a.iter()
        .zip(b)
        .fold(0.0, |m: Real, (x, y)| m.max((x - y).abs()))
        / scale
}

#[test]
fn coupled_at_the_time_step_reproduces_the_prescribed_state() {
    let model = oc3();
    let dt = 0.002;
    let (prescribed, _) = run_prescribed(&model, 0.1, 20.0);
    for accelerations in [false, true] {
        let (coupled, _) = run_coupled(&model, dt, 20.0, accelerations);
        assert_eq!(prescribed.time(), coupled.time());
        assert_eq!(prescribed.steps_done(), coupled.steps_done());
        let d = relative_difference(prescribed.state(), coupled.state());
        eprintln!(
            "state after 20 s, coupling interval = step, accelerations given: {accelerations}: \
             relative difference {d:.3e}"
        );
        assert!(d < 1e-9, "relative state difference {d:.3e}");
    }
}

#[test]
fn coupled_tension_extremes_do_not_depend_on_the_coupling_interval() {
    let model = oc3();
    let end = 60.0;
    for (dt_c, accelerations) in [(0.01, false), (0.05, false), (0.1, false), (0.1, true)] {
        // Cubic interpolation (positions and velocities, MoorDyn's coupling data): 0.1 %;
        // quintic (with the accelerations): exact for this motion to round-off, 1e-9.
        let tolerance = if accelerations { 1e-9 } else { 1e-3 };
        let (_, reference) = run_prescribed(&model, dt_c, end);
        let (_, got) = run_coupled(&model, dt_c, end, accelerations);
        for (l, (r, g)) in reference.iter().zip(&got).enumerate() {
            let (rmax, gmax) = (
                r.iter().fold(0.0, |m: Real, x| m.max(*x)),
                g.iter().fold(0.0, |m: Real, x| m.max(*x)),
            );
            let (rmin, gmin) = (
                r.iter().fold(Real::INFINITY, |m: Real, x| m.min(*x)),
                g.iter().fold(Real::INFINITY, |m: Real, x| m.min(*x)),
            );
            let (emax, emin) = ((gmax - rmax).abs() / rmax, (gmin - rmin).abs() / rmin);
            eprintln!(
                "interval {dt_c} s, accelerations {accelerations}, line {l}: max {gmax:.1} N \
                 ({emax:.2e}), min {gmin:.1} N ({emin:.2e})"
            );
            assert!(
                emax < tolerance && emin < tolerance,
                "interval {dt_c} s line {l}"
            );
        }
    }
}

#[test]
fn a_repeated_interval_replaces_the_first_attempt() {
    let model = oc3();
    let (m, motions) = couple_prescribed_points(&model);
    let (mut once, mut twice) = (Session::new(m.clone()).unwrap(), Session::new(m).unwrap());
    for s in [&mut once, &mut twice] {
        feed(s, &motions, 0.0);
    }
    let dt_c = 0.05;
    for k in 1..=40 {
        let t1 = k as Real * dt_c;
        // A wrong prediction first (the fairleads 0.3 m off), then the corrected kinematics.
        for (p, mo) in &motions {
            let (x, v, _) = mo.kinematics(t1);
            twice
                .set_point_kinematics(*p, t1, x + Vec3::new(0.3, 0.0, 0.0), v, None)
                .unwrap();
        }
        twice.advance_to(t1).unwrap();
        feed(&mut twice, &motions, t1);
        twice.advance_to(t1).unwrap();
        feed(&mut once, &motions, t1);
        once.advance_to(t1).unwrap();
    }
    assert_eq!(once.time(), twice.time());
    assert_eq!(once.state(), twice.state(), "bit for bit");
}

#[test]
fn coupling_calls_that_cannot_be_taken_are_errors() {
    let (m, _) = couple_prescribed_points(&oc3());
    let mut s = Session::new(m).unwrap();
    let p = s.coupled_points()[0];
    let anchor = 0;
    let e = s
        .set_point_kinematics(anchor, 0.1, Vec3::zeros(), Vec3::zeros(), None)
        .unwrap_err()
        .to_string();
    assert!(e.contains("not a coupled point"), "{e}");
    let e = s
        .set_point_kinematics(p, 0.1, Vec3::new(Real::NAN, 0.0, 0.0), Vec3::zeros(), None)
        .unwrap_err()
        .to_string();
    assert!(e.contains("not finite"), "{e}");
    s.set_point_kinematics(p, 0.1, Vec3::new(5.2, 0.0, -70.0), Vec3::zeros(), None)
        .unwrap();
    s.advance_to(0.1).unwrap();
    let e = s
        .set_point_kinematics(p, 0.05, Vec3::new(5.2, 0.0, -70.0), Vec3::zeros(), None)
        .unwrap_err()
        .to_string();
    assert!(e.contains("not after"), "{e}");
    let mut f = vec![0.0; 2];
    let e = s.coupled_forces(&mut f).unwrap_err().to_string();
    assert!(e.contains("9 coupled degrees of freedom"), "{e}");
    let mut f = vec![0.0; s.coupled_dofs()];
    s.coupled_forces(&mut f).unwrap();
    // The lines pull the fairleads down and out towards the anchors.
    assert!(f[2] < 0.0 && f[0] > 0.0, "{f:?}");
}

/// The OC3 scenario text with every prescribed fairlead written `type = "coupled"` (its
/// motion removed): what a host's scenario file looks like.
fn oc3_coupled_text() -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/oc3_surge.toml");
    let text = std::fs::read_to_string(path).unwrap();
    text.lines()
        .filter(|l| !l.starts_with("motion = "))
        .map(|l| l.replace("type = \"prescribed\"", "type = \"coupled\""))
        .collect::<Vec<_>>()
        .join("\n")
}

/// `type = "coupled"` in a scenario builds the core's coupled points, at their `position`:
/// the same model as the prescribed one turned coupled by hand.
#[test]
fn coupled_points_come_from_the_scenario_key() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    let loaded = scenario::parse(&dir.join("oc3_coupled.toml"), &oc3_coupled_text()).unwrap();
    let (by_hand, _) = couple_prescribed_points(&oc3());
    assert_eq!(loaded.model.points, by_hand.points);
    let s = Session::new(loaded.model).unwrap();
    assert_eq!(s.coupled_points(), &[3, 4, 5][..]);
    assert_eq!(s.coupled_dofs(), 9);
}

/// Not driven by a host, a coupled point stays where it starts: the run equals the run with
/// the same points fixed, bit for bit.
#[test]
fn an_undriven_coupled_point_stays_at_its_position() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    let text = oc3_coupled_text();
    let coupled = scenario::parse(&dir.join("a.toml"), &text).unwrap().model;
    let fixed = scenario::parse(
        &dir.join("b.toml"),
        &text.replace("type = \"coupled\"", "type = \"fixed\""),
    )
    .unwrap()
    .model;
    let mut a = Session::new(coupled).unwrap();
    let mut b = Session::new(fixed).unwrap();
    a.advance_to(2.0).unwrap();
    b.advance_to(2.0).unwrap();
    assert_eq!(a.state(), b.state());
}

/// A coupled body (a platform whose pose the host sets) with its fairleads on it: six
/// coupled degrees of freedom; a `motion` on it is refused with the key named.
#[test]
fn coupled_bodies_come_from_the_scenario_key() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    let mut text = oc3_coupled_text().replace(
        "type = \"coupled\"\nposition = [5.2, 0.0, -70.0]",
        "type = \"body\"\nbody = \"platform\"\nposition = [5.2, 0.0, 0.0]",
    );
    for (x, y) in [("-2.6", "4.5"), ("-2.6", "-4.5")] {
        text = text.replace(
            &format!("type = \"coupled\"\nposition = [{x}, {y}, -70.0]"),
            &format!("type = \"body\"\nbody = \"platform\"\nposition = [{x}, {y}, 0.0]"),
        );
    }
    text.push_str(
        "\n\n[[bodies]]\nname = \"platform\"\ntype = \"coupled\"\nposition = [0.0, 0.0, -70.0]\n\
         mass = 1.0\ninertia = [1.0, 1.0, 1.0]\n",
    );
    let model = scenario::parse(&dir.join("c.toml"), &text)
        .unwrap_or_else(|e| panic!("{e}"))
        .model;
    assert_eq!(model.bodies[0].kind, hawser::model::BodyKind::Coupled);
    let s = Session::new(model).unwrap();
    assert_eq!(s.coupled_bodies(), &[0][..]);
    assert_eq!(s.coupled_dofs(), 6);
    let bad = text.replace(
        "type = \"coupled\"\nposition = [0.0, 0.0, -70.0]",
        "type = \"coupled\"\nposition = [0.0, 0.0, -70.0]\nmotion = { type = \"fixed\" }",
    );
    let e = scenario::parse(&dir.join("d.toml"), &bad)
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("bodies[0].motion") && e.contains("coupled"),
        "{e}"
    );
}
