//! tests/c/hawser_host.c, compiled with the system's C compiler against include/hawser.h and
//! the static library, drives OC3's three fairleads through the C ABI in the 2 m, 10 s surge
//! (kinematics at the end of every 0.1 s interval) and prints the coupled forces; the same
//! run through the Rust API ([`Host`], the object the C functions drive) gives the same
//! numbers to 1e-12 relative (the two programs evaluate the same sin and cos; anything but
//! round-off in printing and parsing is a bug in the C layer). The C program checks the rest
//! of the contract itself: checkpoint round trip bit for bit, a short buffer and a damaged
//! checkpoint refused, errors as status codes with messages, line and point queries.

use hawser_capi::host::{Convention, Host};
use std::path::{Path, PathBuf};
use std::process::Command;

#[path = "../../../tests/c/cc.rs"]
mod cc;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn parse(csv: &str) -> Vec<Vec<f64>> {
    csv.lines()
        .skip(1)
        .map(|l| l.split(',').map(|x| x.parse().expect("number")).collect())
        .collect()
}

#[test]
fn c_host_forces_equal_the_rust_sessions() {
    let deck = root().join("tests/data/moordyn/oc3_lines.txt");
    let (duration, dtc) = (20.0, 0.1);
    let exe = Path::new(env!("CARGO_TARGET_TMPDIR")).join("hawser_host");
    cc::compile(
        &root().join("tests/c/hawser_host.c"),
        &Path::new(env!("CARGO_MANIFEST_DIR")).join("include"),
        &cc::static_library("hawser_capi"),
        &exe,
    );
    let out = Command::new(&exe)
        .arg(&deck)
        .args([duration.to_string(), dtc.to_string()])
        .output()
        .expect("run the C host");
    eprintln!("{}", String::from_utf8_lossy(&out.stderr));
    assert!(out.status.success(), "the C host failed");
    let c = parse(&String::from_utf8(out.stdout).expect("UTF-8"));
    // Rows of the first half and of the second half once (the repeat is not printed).
    let steps = (duration / dtc as f64).round() as usize;
    assert_eq!(c.len(), steps);

    let mut host = Host::open(&deck).expect("deck");
    let n = host.coupled_dofs();
    assert_eq!(n, 9);
    let x0 = [5.2, 0.0, -70.0, -2.6, 4.5, -70.0, -2.6, -4.5, -70.0];
    let w = 2.0 * std::f64::consts::PI / 10.0;
    let kin = |t: f64| {
        let x: Vec<f64> = (0..n)
            .map(|i| x0[i] + if i % 3 == 0 { 2.0 * (w * t).sin() } else { 0.0 })
            .collect();
        let xd: Vec<f64> = (0..n)
            .map(|i| {
                if i % 3 == 0 {
                    2.0 * w * (w * t).cos()
                } else {
                    0.0
                }
            })
            .collect();
        (x, xd)
    };
    let (_, xd) = kin(0.0);
    host.init(&x0, &xd).expect("init");
    let mut f = vec![0.0; n];
    let mut worst: f64 = 0.0;
    for (k, row) in c.iter().enumerate() {
        let (x, xd) = kin((k + 1) as f64 * dtc);
        host.step(Convention::End, k as f64 * dtc, dtc, &x, &xd, None, &mut f)
            .expect("step");
        assert_eq!(row[0], (k + 1) as f64 * dtc);
        let scale = f.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        for (a, b) in row[1..].iter().zip(&f) {
            worst = worst.max((a - b).abs() / scale);
        }
    }
    eprintln!("C ABI vs Rust host, 200 intervals: largest relative difference {worst:.2e}");
    assert!(worst <= 1e-12, "C and Rust forces differ by {worst:.2e}");
    // The surge moves the fairleads: the forces are not those of the statics.
    let fx: Vec<f64> = c.iter().map(|r| r[1]).collect();
    let range =
        fx.iter().cloned().fold(f64::MIN, f64::max) - fx.iter().cloned().fold(f64::MAX, f64::min);
    assert!(range > 1e5, "surge force range {range} N");
}
