//! The ROPOS deep-water tether (DG paper §6, SPEC §7) from `examples/ropos_tether.toml`: the
//! tether's wet weight, slack and snap at 0.2 Hz but not at 0.1 Hz, and the snap's travel
//! time from the cage to the ship. The full study (48 cases) is run by
//! `cargo run --release -p hawser-io --example dg_report -- ropos body` (the cage as a rigid
//! body) and `... -- ropos` (a point mass) (docs/verification/dg.md); `stored_*` check the
//! paper's claims on their stored results without rerunning them.
//!
//! Run in release mode: `cargo test --release -p hawser-io --test ropos_tether` (about 30 s;
//! the ignored test, about 5 min, with `-- --ignored`).

use hawser::math::Real;
use hawser::model::Model;
use hawser::validation::tether::{TetherSummary, case, run_tether, summarise, wave_speed};
use std::path::PathBuf;

fn base() -> Model {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples/ropos_tether.toml");
    hawser_io::scenario::load(&path).unwrap().model
}

/// Runs one case of the study for `periods` periods after the two-period build-up.
fn run(length: Real, alpha: Real, frequency: Real, periods: Real) -> TetherSummary {
    let model = case(&base(), length, alpha, frequency, periods);
    let r = run_tether(&model).unwrap();
    let s = summarise(&r, length, wave_speed(&model), 2.0 / frequency);
    eprintln!(
        "L {length} m, α {alpha}, f {frequency} Hz: ship {:.1}..{:.1} kN, slack {}, cage snap \
         {:?}, ship {:?}, travel {:?} s vs L/c {:.4} s ({:.1} s wall)",
        s.ship_min / 1e3,
        s.ship_max / 1e3,
        s.slack,
        s.cage_snap,
        s.ship_snap,
        s.travel_time(),
        length / wave_speed(&model),
        r.wall_seconds
    );
    s
}

/// The tether's own weight in water at L = 1730 m, ship-end minus cage-end static tension, is
/// the paper's 44 kN (§6.1; it rounds) within 1 %, and equals γ0 (1 − ρ_w/ρ) g L for the
/// steel density ρ = 7153 kg/m³ of Table 3 within 1e-4: the buoyancy acts on γ0/ρ as in the
/// paper's eq. 14 (with the nominal D = 0.03 m it would be 38.8 kN, 12 % low). The cage end
/// carries the cage's wet weight (m − ρ_w V) g within 1e-4. 1e-4 is the statics' tolerance for
/// a vertical line, well above its residual (1e-9 of the weight) and far below a wrong area.
#[test]
fn tether_wet_weight_at_1730_m() {
    let model = base();
    let mut m = model.clone();
    m.settings.duration = 0.0;
    let r = run_tether(&m).unwrap();
    let (ship, cage) = (r.ship_tension[0], r.cage_tension[0]);
    let t = &model.line_types[0];
    let g = model.environment.gravity;
    let rho_w = model.environment.water_density;
    let rho_steel = t.mass_per_length / t.area();
    let expected = t.mass_per_length * (1.0 - rho_w / rho_steel) * g * 1730.0;
    let (mass, volume) = match model.points[1].kind {
        hawser::model::PointKind::Free { mass, volume, .. } => (mass, volume),
        _ => unreachable!("the cage is a free point"),
    };
    let cage_wet = (mass - rho_w * volume) * g;
    eprintln!(
        "static: ship {ship:.1} N, cage {cage:.1} N, tether wet weight {:.1} N (γ0(1 − ρw/ρ)gL = \
         {expected:.1} N, steel density {rho_steel:.1} kg/m³), cage wet weight {cage_wet:.1} N",
        ship - cage
    );
    assert!((rho_steel - 7153.0).abs() < 0.01, "{rho_steel}");
    assert!(((ship - cage) / 44e3 - 1.0).abs() < 0.01);
    assert!(((ship - cage) / expected - 1.0).abs() < 1e-4);
    assert!((cage / cage_wet - 1.0).abs() < 1e-4);
}

/// At L = 1730 m (α = 1): the tether stays taut at 0.1 Hz and goes slack and snaps at 0.2 and
/// 0.25 Hz (the paper's §6.2, confirming Driscoll's analytical model). The snap's front
/// reaches the ship L/c after it leaves the cage, c = √(EA/γ0) = 3888 m/s, within 2 % (the
/// issue's tolerance; the front is smeared by the axial damping over ≈ √(ζ/γ0 · L/c) ≈ 80 m,
/// symmetrically, so its middle keeps the speed). The ship sees a jump about twice the cage's
/// (reflection at a velocity-driven end), so at least 1.5 times it.
#[test]
fn slack_and_snap_at_1730_m() {
    let slow = run(1730.0, 1.0, 0.10, 3.0);
    assert!(!slow.slack, "taut at 0.1 Hz");
    assert!(slow.cage_snap.is_none());
    assert!(slow.ship_min > 0.3 * slow.static_ship);
    for f in [0.20, 0.25] {
        let s = run(1730.0, 1.0, f, 1.0);
        assert!(s.slack, "slack at {f} Hz");
        let (cage, ship) = (s.cage_snap.unwrap(), s.ship_snap.unwrap());
        assert!(s.taut_path, "at 1730 m only the lower tether slackens");
        let tau = 1730.0 / (45.5e6 / 3.01 as Real).sqrt();
        let travel = s.travel_time().unwrap();
        assert!(
            (travel / tau - 1.0).abs() < 0.02,
            "travel time {travel:.4} s vs L/c {tau:.4} s"
        );
        assert!(cage.jump() > 0.5 * s.static_cage, "a real snap: {cage:?}");
        assert!(ship.jump() > 1.5 * cage.jump(), "{ship:?} vs {cage:?}");
    }
}

/// Bending changes the snap only for short tethers (§6.2): between α = 0 and α = 100 the first
/// snap's peak tension at the cage and its time differ more at L = 200 m than at L = 1730 m,
/// where EI = 262 kN·m² is negligible against the tension over the long slack length
/// (measured with the dg modal filter: at 200 m the first cage snap comes 1.1 ms earlier with
/// α = 100 and its peak differs by 0.59 %; at 1730 m by 0.02 ms and 0.03 %; before the filter
/// the 200 m α = 0 run snapped 1.85 s earlier with a 64 % different peak, a solution that was
/// not mesh-converged). 1.5–5 min in release mode, depending on the machine's load
/// (L = 200 m needs a 2e-5 s step).
#[test]
#[ignore]
fn bending_matters_only_for_short_tethers() {
    let change = |length: Real| {
        let a = run(length, 0.0, 0.2, 1.0).cage_snap.unwrap();
        let b = run(length, 100.0, 0.2, 1.0).cage_snap.unwrap();
        ((b.peak - a.peak).abs() / a.peak, (b.time - a.time).abs())
    };
    let (short_peak, short_time) = change(200.0);
    let (long_peak, long_time) = change(1730.0);
    eprintln!(
        "α 0 → 100: L 200 m: peak {short_peak:.3e}, time {short_time:.4} s; L 1730 m: peak \
         {long_peak:.3e}, time {long_time:.4} s"
    );
    assert!(short_peak > 2.0 * long_peak || short_time > 2.0 * long_time);
}

/// A case of the study from `examples/ropos_tether_body.toml` (the cage as a rigid body on a
/// bridle): `case` seeds the body so that its bridle is L below the ship (to 1e-9 m, rounding),
/// and at L = 200 m the statics hang the cage on the shortened tether: the ship end carries the
/// tether's wet weight γ0 (1 − ρ_w/ρ) g L more than the cage end and the cage end the body's
/// wet weight (m − ρ_w V) g, both within the statics' 1e-4 (as in
/// `tether_wet_weight_at_1730_m`). (The statics also find the cage from the 1730 m seed; the
/// seed matters for the initial guess only.)
#[test]
fn rigid_body_cage_follows_the_length() {
    let path =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples/ropos_tether_body.toml");
    let base = hawser_io::scenario::load(&path).unwrap().model;
    let mut m = case(&base, 200.0, 1.0, 0.2, 1.0);
    let body = &m.bodies[0];
    let offset = match m.points[1].kind {
        hawser::model::PointKind::Body { offset, .. } => offset,
        _ => unreachable!("the bridle is a body point"),
    };
    let bridle = body.position + body.orientation * offset;
    let seed_error =
        (bridle - (m.points[0].position - hawser::math::Vec3::new(0.0, 0.0, 200.0))).norm();
    assert!(seed_error < 1e-9, "bridle seeded at {bridle:?}");
    m.settings.duration = 0.0;
    let r = run_tether(&m).unwrap();
    let (ship, cage) = (r.ship_tension[0], r.cage_tension[0]);
    let t = &m.line_types[0];
    let g = m.environment.gravity;
    let rho_w = m.environment.water_density;
    let tether_wet = t.mass_per_length * (1.0 - rho_w / (t.mass_per_length / t.area())) * g * 200.0;
    let body = &m.bodies[0];
    let cage_wet = (body.mass - rho_w * body.displacement.volume()) * g;
    eprintln!(
        "L 200 m, rigid-body cage: ship {ship:.1} N, cage {cage:.1} N; tether wet weight \
         {tether_wet:.1} N, cage wet weight {cage_wet:.1} N"
    );
    assert!(((ship - cage) / tether_wet - 1.0).abs() < 1e-4);
    assert!((cage / cage_wet - 1.0).abs() < 1e-4);
}

/// The stored study of `dg_report ropos [body]` (docs/verification/data/`file`, 48 cases, read
/// and not rerun): every case ran with the dg modal filter; the tether's wet weight at
/// 1730 m (α = 1, 0.2 Hz) is 44 kN within 1 % and γ0 (1 − ρ_w/ρ) g L within 1e-4 (as in
/// `tether_wet_weight_at_1730_m`); every case at 0.2 and 0.25 Hz goes slack and snaps, none
/// at 0.1 Hz; at 1730 m every snap reaches the ship L/c after it leaves the cage within 2 %,
/// c = √(EA/γ0); bending matters more for the short tethers: from α = 0 to 100 the first cage
/// snap's time or peak changes at least twice as much at 200 and 500 m as at 975 and 1730 m,
/// and the steady ship maximum too (the report's criterion, docs/verification/dg.md).
fn check_stored_study(file: &str) {
    use serde_json::Value;
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../docs/verification/data")
        .join(file);
    let text = std::fs::read_to_string(&path).unwrap();
    let records: Vec<Value> = serde_json::from_str(&text).unwrap();
    assert_eq!(records.len(), 48, "{file}: the 48 cases");
    let num = |r: &Value, k: &str| r[k].as_f64().unwrap();
    let find = |l: Real, a: Real, f: Real| {
        records
            .iter()
            .find(|r| num(r, "length") == l && num(r, "alpha") == a && num(r, "frequency") == f)
            .unwrap()
    };
    for r in &records {
        assert!(
            r["modal_filter"].is_number(),
            "{file}: {r:?} predates the filter"
        );
    }
    let model = base();
    let t = &model.line_types[0];
    let g = model.environment.gravity;
    let rho_w = model.environment.water_density;
    let expected = t.mass_per_length * (1.0 - rho_w / (t.mass_per_length / t.area())) * g * 1730.0;
    let r = find(1730.0, 1.0, 0.2);
    let wet = num(r, "static_ship") - num(r, "static_cage");
    assert!(
        (wet / 44e3 - 1.0).abs() < 0.01,
        "{file}: wet weight {wet} N"
    );
    assert!(
        (wet / expected - 1.0).abs() < 1e-4,
        "{file}: {wet} vs {expected} N"
    );
    let c = (t.axial_stiffness.max_tangent() / t.mass_per_length).sqrt();
    for r in &records {
        let (l, f) = (num(r, "length"), num(r, "frequency"));
        let slack = r["slack"].as_bool().unwrap();
        if f < 0.15 {
            assert!(!slack, "{file}: slack at L {l}, f {f}");
        } else {
            assert!(
                slack && r["cage_snap"].is_array(),
                "{file}: no snap at L {l}, f {f}"
            );
        }
        if l == 1730.0 && f > 0.15 {
            assert!(r["taut_path"].as_bool().unwrap());
            let travel = r["ship_snap"][0].as_f64().unwrap() - r["cage_snap"][0].as_f64().unwrap();
            let tau = l / c;
            assert!(
                (travel / tau - 1.0).abs() < 0.02,
                "{file}: L {l}, α {}, f {f}: travel {travel:.4} s vs L/c {tau:.4} s",
                num(r, "alpha")
            );
        }
    }
    // Largest change from α = 0 to 100 of the cage snap's time [s] and relative peak, and of
    // the steady ship maximum, at the short and the long tethers.
    let worst = |lengths: [Real; 2]| {
        let mut m: (Real, Real, Real) = (0.0, 0.0, 0.0);
        for l in lengths {
            for f in [0.2, 0.25] {
                let (a, b) = (find(l, 0.0, f), find(l, 100.0, f));
                let (ca, cb) = (&a["cage_snap"], &b["cage_snap"]);
                let time = (cb[0].as_f64().unwrap() - ca[0].as_f64().unwrap()).abs();
                let peak = (cb[2].as_f64().unwrap() / ca[2].as_f64().unwrap() - 1.0).abs();
                let steady = (num(b, "ship_max") / num(a, "ship_max") - 1.0).abs();
                m = (m.0.max(time), m.1.max(peak), m.2.max(steady));
            }
        }
        m
    };
    let (short, long) = (worst([200.0, 500.0]), worst([975.0, 1730.0]));
    eprintln!("{file}: α 0 → 100, short {short:?}, long {long:?}");
    assert!(short.0 > 2.0 * long.0 || short.1 > 2.0 * long.1);
    assert!(short.2 > 2.0 * long.2);
}

/// `check_stored_study` on the rigid-body cage (the report's primary study).
#[test]
fn stored_rigid_body_study() {
    check_stored_study("ropos_rigid.json");
}

/// `check_stored_study` on the point-mass cage (the report's comparison).
#[test]
fn stored_point_mass_study() {
    check_stored_study("ropos.json");
}
