//! tests/c/moordyn_host.c, a host written against MoorDyn v2's C API, compiled with the
//! system's C compiler against include/MoorDyn2.h and linked with this library (libmoordyn.a),
//! runs OC3 in the 2 m, 10 s surge coupled every 0.01 s with MoorDyn's convention (x at the
//! start of each interval, xd the forward difference to the next sample). Its fairlead
//! tensions (|Fnet| of the end node, MoorDyn's FairTen) equal those of hawser's own run of
//! the deck with its fairleads prescribed on the piecewise-linear time series of the same
//! samples to 1e-9 relative: both move the fairleads
//! along the same straight segments, evaluated as x₀ + ẋ(t − t₀) here and by interpolating the
//! table there, which differ by round-off. The C host also saves the state half-way, runs on,
//! loads it back and checks that the second half repeats to the last bit.
//! scripts/c_check.sh runs the same program against MoorDyn 2.7.2's own library.

use hawser::analysis::Channel;
use hawser::math::Vec3;
use hawser::model::{Motion, PointKind};
use hawser::session::Session;
use hawser_io::moordyn::ConvertOptions;
use std::path::{Path, PathBuf};
use std::process::Command;

#[path = "../../../tests/c/cc.rs"]
mod cc;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

#[test]
fn moordyn_host_through_the_layer_equals_hawsers_own_run() {
    let deck = root().join("tests/data/moordyn/oc3_lines.txt");
    let tmp = Path::new(env!("CARGO_TARGET_TMPDIR"));
    let exe = tmp.join("moordyn_host");
    cc::compile(
        &root().join("tests/c/moordyn_host.c"),
        &Path::new(env!("CARGO_MANIFEST_DIR")).join("include"),
        &cc::static_library("moordyn"),
        &exe,
    );
    let (duration, dtc, every) = (20.0, 0.01, 10);
    let state = tmp.join("moordyn_host.state");
    let out = Command::new(&exe)
        .arg(&deck)
        .args([duration.to_string(), dtc.to_string(), every.to_string()])
        .arg(&state)
        .output()
        .expect("run the host");
    eprintln!("{}", String::from_utf8_lossy(&out.stderr));
    assert!(out.status.success(), "the MoorDyn host failed");
    let rows: Vec<Vec<f64>> = String::from_utf8(out.stdout)
        .expect("UTF-8")
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|x| x.parse().expect("number")).collect())
        .collect();
    assert_eq!(rows.len(), 200);

    // hawser's own prescribed run: each fairlead on the piecewise-linear time series of the
    // same samples (`type = "time-series"` in a scenario).
    let (mut loaded, _) =
        hawser_io::input::load_input(&deck, &ConvertOptions::default()).expect("deck");
    let w = 2.0 * std::f64::consts::PI / 10.0;
    let times: Vec<f64> = (0..=2100).map(|k| k as f64 * dtc).collect();
    for p in &mut loaded.model.points {
        if let PointKind::Prescribed(Motion::Fixed { position }) = p.kind {
            let positions = times
                .iter()
                .map(|&t| position + Vec3::new(2.0 * (w * t).sin(), 0.0, 0.0))
                .collect();
            p.kind = PointKind::Prescribed(Motion::TimeSeries {
                times: times.clone(),
                positions,
            });
        }
    }
    let mut session = Session::new(loaded.model).expect("session");
    let mut worst: f64 = 0.0;
    for row in &rows {
        session.advance_to(row[0]).expect("advance");
        let view = session.view().expect("view");
        for l in 0..3 {
            let own = view.value(&Channel::EndNodeForce {
                line: l,
                end_b: true,
            });
            worst = worst.max((row[1 + l] - own).abs());
        }
    }
    // The velocity of the piecewise-linear path jumps at every sample, by up to
    // Δv = A ω² Δt_c; the end segment's damping force c ε̇ with c = ζ l √(EA γ0) jumps with it
    // by ζ √(EA γ0) Δv. At a sample time the layer reports the state with the velocity of the
    // interval just computed and the prescribed run with the next one (and RK4's first stage
    // of each step reads that side too): the runs may differ by that jump, and by nothing more.
    let (zeta, ea, gamma) = (0.8, 384.243e6, 77.7066);
    let jump = zeta * (ea * gamma as f64).sqrt() * 2.0 * w * w * dtc;
    eprintln!(
        "libmoordyn (hawser) vs hawser's prescribed time-series run, FairTen1-3 every 0.1 s \
         over 20 s: largest difference {worst:.1} N; damping jump at a sample {jump:.1} N"
    );
    assert!(worst <= jump, "FairTen differs by {worst:.1} N");
}
