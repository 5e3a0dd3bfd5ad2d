//! hawser against MoorDyn 2.7.2 on MoorDyn's own decks, read by hawser's deck reader.
//!
//! The MoorDyn numbers are in `tests/data/moordyn_reference.json`, recorded by
//! `scripts/moordyn_compare.sh` (MoorDyn from PyPI in a throwaway virtual environment; the
//! script also runs hawser and prints both side by side). The quantities compared are the same
//! in both codes: |F_net| of a line's end node (MoorDyn's FairTen/AnchTen channels).
//!
//! Tolerances: static fairlead and anchor tensions within 0.2 %; the OC3 fairlead
//! tension minimum, maximum and mean in a 2 m, 10 s surge within 0.5 %. Both codes discretise
//! the same line differently (hawser's two-point Gauss drag on elements against MoorDyn's
//! nodal drag on the chord direction; hawser's √(1+ε) on drag), so they agree to the
//! discretisation error, which the refined mesh shows shrinking.

use hawser::analysis::Channel;
use hawser::math::{Real, Vec3};
use hawser::model::{Motion, PointKind, TimeStep};
use hawser::simulation::{Observer, Simulation};
use hawser::statics::{StaticOptions, evaluate, solve};
use hawser::system::{System, Workspace};
use hawser_io::moordyn::{self, ConvertOptions};
use hawser_io::scenario::LoadedScenario;
use serde_json::Value;
use std::path::{Path, PathBuf};

fn data() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/data")
}

fn reference() -> Value {
    let text = std::fs::read_to_string(data().join("moordyn_reference.json")).unwrap();
    serde_json::from_str(&text).unwrap()
}

fn load(deck: &str, options: &ConvertOptions) -> LoadedScenario {
    let path = data().join("moordyn").join(deck);
    moordyn::load(&path, options)
        .unwrap_or_else(|e| panic!("{e}"))
        .loaded
}

fn end_node_force(system: &System, ws: &Workspace, line: usize, end_b: bool) -> Real {
    Channel::EndNodeForce { line, end_b }.value(system, ws)
}

#[test]
fn static_end_tensions_match_moordyn_within_0_2_percent() {
    let r = reference();
    let decks = r["statics"]["decks"].as_object().unwrap();
    assert_eq!(decks.len(), 4);
    for (name, d) in decks {
        let loaded = load(d["deck"].as_str().unwrap(), &ConvertOptions::default());
        let system = System::new(&loaded.model).unwrap();
        let sol = solve(&system, None, &StaticOptions::default()).unwrap();
        let mut ws = system.workspace();
        evaluate(&system, &sol.state, &mut ws);
        for (id, line) in d["lines"].as_object().unwrap() {
            let li = id.parse::<usize>().unwrap() - 1;
            for (end_b, key) in [(true, "fairlead_tension_N"), (false, "anchor_tension_N")] {
                let md = line[key].as_f64().unwrap();
                let h = end_node_force(&system, &ws, li, end_b);
                let rel = (h - md) / md;
                eprintln!(
                    "{name} line {id} {key}: hawser {h:.1} N, MoorDyn {md:.1} N, {:+.3} %",
                    rel * 100.0
                );
                assert!(rel.abs() < 2e-3, "{name} line {id} {key}: {rel:+.2e}");
            }
        }
    }
}

/// Records FairTen (end B node force) of every line at every sample.
struct FairTen {
    times: Vec<Real>,
    values: Vec<Vec<Real>>,
}

impl Observer for FairTen {
    fn sample(
        &mut self,
        view: &hawser::session::View<'_>,
    ) -> Result<(), hawser::session::ObserverError> {
        let (system, time, ws) = (view.system, view.time, view.workspace);
        self.times.push(time);
        self.values.push(
            (0..system.lines.len())
                .map(|l| end_node_force(system, ws, l, true))
                .collect(),
        );
        Ok(())
    }
}

impl FairTen {
    /// Minimum, maximum and mean FairTen of `line` over the samples t0 ≤ t < t1 [N].
    fn min_max_mean(&self, line: usize, t0: Real, t1: Real) -> [Real; 3] {
        let v: Vec<Real> = self
            .times
            .iter()
            .zip(&self.values)
            .filter(|(t, _)| **t >= t0 - 1e-9 && **t < t1 - 1e-9)
            .map(|(_, v)| v[line])
            .collect();
        let min = v.iter().cloned().fold(Real::INFINITY, Real::min);
        let max = v.iter().cloned().fold(Real::NEG_INFINITY, Real::max);
        [min, max, v.iter().sum::<Real>() / v.len() as Real]
    }
}

/// Every prescribed point of `model` in surge x = x0 + 2 sin(2πt/10) for 300 s, driven as the
/// script drives MoorDyn (the piecewise-linear interpolant of samples every 0.01 s), from
/// hawser's statics; FairTen of every line every 0.1 s.
fn surge(model: &mut hawser::model::Model) -> FairTen {
    model.settings.output_interval = 0.1;
    model.settings.duration = 300.0;
    for p in &mut model.points {
        if let PointKind::Prescribed(m) = &mut p.kind {
            let x0 = p.position;
            let times: Vec<Real> = (0..=30_000).map(|i| i as Real * 0.01).collect();
            let positions = times
                .iter()
                .map(|t| x0 + Vec3::new(2.0 * (std::f64::consts::TAU * t / 10.0).sin(), 0.0, 0.0))
                .collect();
            *m = Motion::TimeSeries { times, positions };
        }
    }
    let system = System::new(model).unwrap();
    let y0 = solve(&system, None, &StaticOptions::default())
        .unwrap()
        .state;
    let mut sim = Simulation::new(&system, &model.settings, y0).unwrap();
    let mut rec = FairTen {
        times: Vec::new(),
        values: Vec::new(),
    };
    sim.run(300.0, &mut rec).unwrap();
    rec
}

/// OC3 with every fairlead in surge x = x0 + 2 sin(2πt/10) for 300 s, driven as the script
/// drives MoorDyn: the piecewise-linear interpolant of samples every 0.01 s.
fn oc3_surge(segments: usize) {
    let r = reference();
    let case = &r["oc3_surge"]["cases"][segments.to_string()];
    let mut loaded = load("oc3_lines.txt", &ConvertOptions::default());
    let model = &mut loaded.model;
    for l in &mut model.lines {
        l.sections[0].elements = segments;
    }
    model.settings.time_step = TimeStep::Fixed(case["dtM_s"].as_f64().unwrap());
    let rec = surge(model);
    for (window, t0, t1) in [("all", 0.0, 300.0), ("steady", 250.0, 300.0)] {
        for line in 0..3 {
            let h = rec.min_max_mean(line, t0, t1);
            let md = &case["fairleads"][format!("FairTen{}", line + 1)][window];
            for (i, k) in ["min_N", "max_N", "mean_N"].iter().enumerate() {
                let m = md[k].as_f64().unwrap();
                let rel = (h[i] - m) / m;
                eprintln!(
                    "{segments} segments, {window}, FairTen{} {k}: hawser {:.1}, MoorDyn {m:.1}, {:+.3} %",
                    line + 1,
                    h[i],
                    rel * 100.0
                );
                assert!(
                    rel.abs() < 5e-3,
                    "{segments} segments {window} FairTen{} {k}: {rel:+.2e}",
                    line + 1
                );
            }
        }
    }
}

#[test]
fn oc3_surge_fairlead_tension_matches_moordyn_20_segments() {
    oc3_surge(20);
}

#[test]
fn oc3_surge_fairlead_tension_matches_moordyn_40_segments() {
    oc3_surge(40);
}

/// WD0200 chain under MoorDyn's ZZP1_A1 heave (±2 m, 10 s) for 30 s. Compared half-way
/// between the motion file's samples, where the fairlead velocity is continuous (at the
/// samples it jumps, and the end segment's damping force with it).
#[test]
fn chain_under_zzp1_heave_matches_moordyn() {
    let r = reference();
    let c = &r["chain_wd0200_zzp1_a1"]["mid_interval"];
    let options = ConvertOptions {
        duration: Some(30.0),
        vessel_motion: Some(data().join("moordyn").join("ZZP1_A1.txt")),
    };
    let mut loaded = load("WD0200_Chain.txt", &options);
    loaded.model.settings.output_interval = 0.05;
    let model = &loaded.model;
    let system = System::new(model).unwrap();
    let y0 = solve(&system, None, &StaticOptions::default())
        .unwrap()
        .state;
    let mut sim = Simulation::new(&system, &model.settings, y0).unwrap();
    struct Ends(Vec<(Real, Real, Real)>);
    impl Observer for Ends {
        fn sample(
            &mut self,
            view: &hawser::session::View<'_>,
        ) -> Result<(), hawser::session::ObserverError> {
            let (s, t, ws) = (view.system, view.time, view.workspace);
            self.0.push((
                t,
                end_node_force(s, ws, 0, true),
                end_node_force(s, ws, 0, false),
            ));
            Ok(())
        }
    }
    let mut rec = Ends(Vec::new());
    sim.run(30.0, &mut rec).unwrap();
    let times = c["time_s"].as_array().unwrap();
    let mut worst = [0.0f64; 2];
    let mut range = [(Real::INFINITY, Real::NEG_INFINITY); 2];
    for (k, t) in times.iter().enumerate() {
        let t = t.as_f64().unwrap();
        let h = rec
            .0
            .iter()
            .find(|s| (s.0 - t).abs() < 1e-6)
            .unwrap_or_else(|| panic!("no hawser sample at {t}"));
        for (j, key) in ["fairlead_tension_N", "anchor_tension_N"]
            .iter()
            .enumerate()
        {
            let m = c[key][k].as_f64().unwrap();
            let v = if j == 0 { h.1 } else { h.2 };
            worst[j] = worst[j].max((v - m).abs());
            range[j] = (range[j].0.min(m), range[j].1.max(m));
        }
    }
    for (j, name) in ["fairlead", "anchor"].iter().enumerate() {
        let span = range[j].1 - range[j].0;
        eprintln!(
            "chain {name}: max |hawser − MoorDyn| {:.2} kN over a MoorDyn range of {:.1} kN",
            worst[j] / 1e3,
            span / 1e3
        );
        // 1 % of the tension's range: the two codes step at different time steps (hawser at
        // its stability limit, MoorDyn at CFL 0.1) and discretise drag differently.
        assert!(
            worst[j] < 0.01 * span,
            "{name}: {} N vs range {span} N",
            worst[j]
        );
    }
}

/// A free body (`buoy_oc3.txt`: a 180 t submerged buoy on OC3's lines, pulled by a fourth line
/// from a vessel point): its static pose and end tensions within 0.2 % of MoorDyn's, and the
/// fairlead tension extremes of the three lines on it with the vessel point in a 2 m, 10 s surge
/// within 0.5 %. MoorDyn's body physics is converted exactly (buoyancy at the centre of
/// gravity, added mass and drag at the origin on the speed |v|; docs/moordyn.md), so what is
/// left is the lines' discretisation (the same as for OC3) and MoorDyn's relaxation residual.
/// Cost: statics and 300 s at MoorDyn's dtM of 2 ms (150 000 steps of 80 nodes and a body),
/// about 3 s in release.
#[test]
fn free_body_matches_moordyn() {
    let r = reference();
    let c = &r["free_body"];
    let mut loaded = load(c["deck"].as_str().unwrap(), &ConvertOptions::default());
    let model = &mut loaded.model;
    let system = System::new(model).unwrap();
    let sol = solve(&system, None, &StaticOptions::default()).unwrap();
    let mut ws = system.workspace();
    evaluate(&system, &sol.state, &mut ws);
    let k = &ws.bodies[0];
    let pose = &c["static"]["body_pose"];
    let md = |i: usize| pose[i].as_f64().unwrap();
    let md_position = Vec3::new(md(0), md(1), md(2));
    // MoorDyn's Euler angles: R = R_x(r) R_y(p) R_z(y).
    let md_orientation = hawser::math::Quat::from_axis_angle(&Vec3::x_axis(), md(3))
        * hawser::math::Quat::from_axis_angle(&Vec3::y_axis(), md(4))
        * hawser::math::Quat::from_axis_angle(&Vec3::z_axis(), md(5));
    let dx = (k.position - md_position).norm() / md_position.norm();
    let turn = md_orientation.angle();
    let dturn = k.orientation.angle_to(&md_orientation) / turn;
    eprintln!(
        "body at {:?} (MoorDyn {:?}): |Δr|/|r| {dx:.2e}; turned {:.5}° (MoorDyn {:.5}°), \
         difference {dturn:.2e} of the turn",
        k.position.as_slice(),
        md_position.as_slice(),
        k.orientation.angle().to_degrees(),
        turn.to_degrees()
    );
    // 0.2 %: the tolerance of the issue; MoorDyn's relaxation leaves the buoy heaving at
    // 1e-4 m/s (its log), a few mm from rest.
    assert!(dx < 2e-3 && dturn < 2e-3, "{dx:.2e} {dturn:.2e}");
    for (id, line) in c["static"]["lines"].as_object().unwrap() {
        let li = id.parse::<usize>().unwrap() - 1;
        for (end_b, key) in [(true, "fairlead_tension_N"), (false, "anchor_tension_N")] {
            let m = line[key].as_f64().unwrap();
            let rel = (end_node_force(&system, &ws, li, end_b) - m) / m;
            eprintln!("static line {id} {key}: {:+.4} %", rel * 100.0);
            assert!(rel.abs() < 2e-3, "line {id} {key}: {rel:+.2e}");
        }
    }
    model.settings.time_step = TimeStep::Fixed(c["settings"]["dtM_s"].as_f64().unwrap());
    let rec = surge(model);
    for (window, t0, t1) in [("all", 0.0, 300.0), ("steady", 250.0, 300.0)] {
        for line in 0..3 {
            let h = rec.min_max_mean(line, t0, t1);
            let md = &c["surge"]["fairleads"][format!("FairTen{}", line + 1)][window];
            for (i, key) in ["min_N", "max_N", "mean_N"].iter().enumerate() {
                let m = md[key].as_f64().unwrap();
                let rel = (h[i] - m) / m;
                eprintln!(
                    "body surge {window} FairTen{} {key}: {:+.3} %",
                    line + 1,
                    rel * 100.0
                );
                assert!(
                    rel.abs() < 5e-3,
                    "{window} FairTen{} {key}: {rel:+.2e}",
                    line + 1
                );
            }
        }
    }
}

/// A free rod (`rod_hanging.txt`: MoorDyn's RodHanging test deck, a 20 m rod hanging from two
/// 450 m ropes, with the ropes' upper ends coupled and 20 segments each): the static position
/// of end A and the end tensions within 0.2 % of MoorDyn's, and the fairlead tension extremes
/// with both upper ends in a 2 m, 10 s surge within 0.5 %. The rod is a free body with one
/// member (MoorDyn's lumped rod hydrodynamics, docs/moordyn.md). hawser steps at 2 ms, four
/// times MoorDyn's dtM: the tensions then differ from a run at dtM by at most 49 N (6e-5 of
/// them, measured), and the test costs about 2.5 s in release instead of 10 s.
#[test]
fn free_rod_matches_moordyn() {
    let r = reference();
    let c = &r["free_rod"];
    let mut loaded = load(c["deck"].as_str().unwrap(), &ConvertOptions::default());
    let model = &mut loaded.model;
    let system = System::new(model).unwrap();
    let sol = solve(&system, None, &StaticOptions::default()).unwrap();
    let mut ws = system.workspace();
    evaluate(&system, &sol.state, &mut ws);
    let ends = &c["static"]["rod_ends"];
    let md_a = Vec3::new(
        ends[0].as_f64().unwrap(),
        ends[1].as_f64().unwrap(),
        ends[2].as_f64().unwrap(),
    );
    let a = ws.bodies[0].position;
    let dx = (a - md_a).norm() / md_a.norm();
    eprintln!("rod end A at {a:?}, MoorDyn {md_a:?}: |Δr|/|r| {dx:.2e}");
    // 0.2 %: as for the free body.
    assert!(dx < 2e-3, "{dx:.2e}");
    for (id, line) in c["static"]["lines"].as_object().unwrap() {
        let li = id.parse::<usize>().unwrap() - 1;
        for (end_b, key) in [(true, "fairlead_tension_N"), (false, "anchor_tension_N")] {
            let m = line[key].as_f64().unwrap();
            let rel = (end_node_force(&system, &ws, li, end_b) - m) / m;
            eprintln!("static line {id} {key}: {:+.4} %", rel * 100.0);
            assert!(rel.abs() < 2e-3, "line {id} {key}: {rel:+.2e}");
        }
    }
    model.settings.time_step = TimeStep::Fixed(2e-3);
    let rec = surge(model);
    for (window, t0, t1) in [("all", 0.0, 300.0), ("steady", 250.0, 300.0)] {
        for line in 0..2 {
            let h = rec.min_max_mean(line, t0, t1);
            let md = &c["surge"]["fairleads"][format!("FairTen{}", line + 1)][window];
            for (i, key) in ["min_N", "max_N", "mean_N"].iter().enumerate() {
                let m = md[key].as_f64().unwrap();
                let rel = (h[i] - m) / m;
                eprintln!(
                    "rod surge {window} FairTen{} {key}: {:+.3} %",
                    line + 1,
                    rel * 100.0
                );
                assert!(
                    rel.abs() < 5e-3,
                    "{window} FairTen{} {key}: {rel:+.2e}",
                    line + 1
                );
            }
        }
    }
}
