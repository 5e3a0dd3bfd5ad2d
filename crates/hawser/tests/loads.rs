//! Distributed loads against closed forms: current drag on a taut line and sliding friction
//! of a chain dragged over the seabed.

mod common;
use common::*;
use hawser::math::{Real, Vec3};
use hawser::model::{MassMatrix, Motion, Point, PointKind, Settings, TimeStep};
use hawser::physics::environment::Current;
use hawser::physics::hydrodynamics::DragModel;
use hawser::physics::seabed::FrictionLaw;
use hawser::simulation::{Observer, ObserverError, Simulation};
use hawser::statics::{StaticOptions, evaluate, solve};
use hawser::system::System;

/// A taut 100 m line across a uniform current: the sum of the end forces equals the total
/// Morison drag ½ ρ d C_dn U² L √(1+ε) (DG paper eq. 17). Tolerance 1e-4: the line bows by
/// q L²/(8T) ≈ 0.09 m, which turns the normal flow by at most 4·sag/L ≈ 3.4e-3 rad and changes
/// the drag by its square, ~1e-5.
#[test]
fn current_drag_on_a_taut_line_equals_the_morison_integral() {
    let mut lt = line_type(0.05, 20.0, 1.0e9);
    lt.drag = DragModel::Morison {
        normal: 1.2,
        tangential: 0.3,
    };
    let strain = 1.0e-3;
    let length = 100.0 / (1.0 + strain);
    let mut model = single_line(
        lt,
        length,
        40,
        fixed("A", Vec3::new(0.0, 0.0, -50.0)),
        fixed("B", Vec3::new(100.0, 0.0, -50.0)),
        MassMatrix::Consistent,
    );
    model.environment.gravity = 0.0;
    let u = 1.5;
    model.environment.current = Current::Uniform(Vec3::new(0.0, u, 0.0));
    let system = System::new(&model).expect("valid model");
    let sol = solve(&system, None, &StaticOptions::default()).expect("statics");
    let mut ws = system.workspace();
    evaluate(&system, &sol.state, &mut ws);
    let total = system.end_force(&ws, 0, false) + system.end_force(&ws, 0, true);
    let stretch: f64 = 1.0 + ws.lines[0].elements.strain.iter().sum::<f64>() / 40.0;
    let expected = 0.5 * 1025.0 * 0.05 * 1.2 * u * u * length * stretch.sqrt();
    let err = (total.y - expected).abs() / expected;
    assert!(err < 1e-4, "drag {} vs {expected} ({err:.2e})", total.y);
    assert!(
        total.x.abs() < 1e-6 * expected && total.z.abs() < 1e-6 * expected,
        "{total}"
    );
}

/// Mean pull along −x at the end B of line 0 over samples from `from` on.
struct MeanPull {
    from: f64,
    sum: f64,
    count: usize,
}
impl Observer for MeanPull {
    fn sample(&mut self, v: &hawser::session::View<'_>) -> Result<(), ObserverError> {
        if v.time >= self.from {
            self.sum -= v.end_force(0, true).x;
            self.count += 1;
        }
        Ok(())
    }
}

/// Mean pull [N] over 15–20 s on a 50 m chain (25 elements) lying on the bed, its tail free,
/// its head pulled along its axis at `v` from t = 0 (critical axial damping, lumped mass),
/// with friction coefficient `mu` and friction `law` (v_μ = `v_mu` for the tanh law).
fn mean_pull_on_bed(v: Real, mu: Real, v_mu: Real, law: FrictionLaw) -> Real {
    let mut lt = dry_line_type(0.05, 20.0, 1.0e8);
    lt.axial_damping = hawser::physics::material::AxialDamping::Ratio(1.0);
    let depth = 100.0;
    let free_end = Point {
        name: "tail".into(),
        position: Vec3::new(0.0, 0.0, -depth),
        kind: PointKind::Free {
            mass: 0.0,
            volume: 0.0,
            drag_area: 0.0,
            added_mass_coefficient: 0.0,
            force: Vec3::zeros(),
        },
    };
    let pulled = Point {
        name: "pull".into(),
        position: Vec3::new(50.0, 0.0, -depth),
        kind: PointKind::Prescribed(Motion::ConstantVelocity {
            start: Vec3::new(50.0, 0.0, -depth),
            velocity: Vec3::new(v, 0.0, 0.0),
        }),
    };
    let mut model = single_line(lt, 50.0, 25, free_end, pulled, MassMatrix::Lumped);
    model.environment.depth = depth;
    model.environment.seabed.friction_coefficient = mu;
    model.environment.seabed.friction_velocity = v_mu;
    model.environment.seabed.friction_law = law;
    model.settings = Settings {
        duration: 20.0,
        time_step: TimeStep::Auto,
        output_interval: 0.5,
        ..Default::default()
    };
    let system = System::new(&model).unwrap();
    let y0 = system.straight_state();
    let mut sim = Simulation::new(&system, &model.settings, y0).unwrap();
    let mut mean = MeanPull {
        from: 15.0,
        sum: 0.0,
        count: 0,
    };
    sim.run(20.0, &mut mean).unwrap();
    mean.sum / mean.count as f64
}

/// Submerged weight per length [N/m] of the dragged chain.
fn chain_wet_weight() -> Real {
    (20.0 - 1025.0 * std::f64::consts::PI * 0.05f64.powi(2) / 4.0) * 9.80665
}

/// A 50 m chain lying on the bed, pulled along its axis at 0.05 m/s: once sliding steadily,
/// the pull equals the friction μ w L' tanh(π v/v_μ) √(1+ε) (DG paper eq. 16), where
/// L' = L − L0/2: the pulled end node is held at the bed surface by the prescribed point, so its
/// half element carries no contact and no friction. Sliding Coulomb
/// friction is constant, so it does not damp the axial ringing of the impulsive start; the
/// chain gets critical axial damping and the pull is averaged over the last 5 s. Tolerance
/// 0.5 %: the strain (5e-5) and the left-over ringing are far smaller.
#[test]
fn chain_dragged_over_the_bed_pulls_with_the_coulomb_friction() {
    let (v, mu, v_mu) = (0.05, 0.6, 0.01);
    let pull = mean_pull_on_bed(v, mu, v_mu, FrictionLaw::Tanh);
    let w = chain_wet_weight();
    let expected = mu * w * (50.0 - 1.0) * (std::f64::consts::PI * v / v_mu).tanh();
    let err = (pull - expected).abs() / expected;
    assert!(err < 5e-3, "pull {pull} vs friction {expected} ({err:.2e})");
}

/// The same chain with MoorDyn's friction law (`FrictionLaw::Viscous`, MoorDyn-C 2.7
/// `Line::getStateDeriv`): each node in contact resists with min(μ c v, μ F_z), c per node.
/// Below saturation (c = 1000 N·s/m: μ c v = 30 N against μ F_z ≈ 211 N) the pull is the 25
/// nodes in contact (all but the held head) times μ c v, independent of their lengths (the
/// tail node carries half an element); saturated (c = 1e5 N·s/m: 3000 N per node) it is
/// Coulomb's μ w L' with F_z the contact force, which carries the node's submerged weight
/// when sliding steadily. Tolerance 0.5 % as above.
#[test]
fn chain_dragged_over_the_bed_with_moordyns_friction() {
    let (v, mu) = (0.05, 0.6);
    let w = chain_wet_weight();
    for (c, expected) in [
        (1.0e3, 25.0 * mu * 1.0e3 * v),
        (1.0e5, mu * w * (50.0 - 1.0)),
    ] {
        let law = FrictionLaw::Viscous {
            damping: c,
            static_scale: 1.0,
        };
        let pull = mean_pull_on_bed(v, mu, 0.01, law);
        let err = (pull - expected).abs() / expected;
        eprintln!("c = {c}: pull {pull:.2} N, expected {expected:.2} N ({err:+.2e})");
        assert!(
            err < 5e-3,
            "c = {c}: pull {pull} vs friction {expected} ({err:.2e})"
        );
    }
}
