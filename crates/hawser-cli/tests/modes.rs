//! `hawser modes`: the JSON shape, the files of `--out`, the resonance margin option and exit
//! codes. (The numbers themselves are verified in `crates/hawser/tests/modes.rs`.)

use std::path::PathBuf;
use std::process::Command;

fn hawser(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_hawser"))
        .args(args)
        .output()
        .expect("run hawser")
}

/// `hawser modes FILE --count N --json --out DIR` (FILE relative to the repository root, DIR a
/// fresh temporary folder named after `tag`): the JSON document and the folder.
fn modes_json(file: &str, count: usize, tag: &str) -> (serde_json::Value, PathBuf) {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..");
    let scenario = root.join(file);
    let dir = std::env::temp_dir().join(format!("hawser-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let out = hawser(&[
        "modes",
        scenario.to_str().unwrap(),
        "--count",
        &count.to_string(),
        "--json",
        "--out",
        dir.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    (serde_json::from_slice(&out.stdout).unwrap(), dir)
}

#[test]
fn modes_reports_frequencies_stiffness_and_resonance_and_writes_shapes() {
    let file = "examples/oc3_surge.toml";
    let (v, dir) = modes_json(file, 12, "modes");
    let scenario = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join(file);
    // 3 lines × 19 interior nodes × 3 translations.
    assert_eq!(v["degrees_of_freedom"], 171);
    let modes = v["modes"].as_array().unwrap();
    assert_eq!(modes.len(), 12);
    let mut previous = 0.0;
    for (i, m) in modes.iter().enumerate() {
        let f = m["frequency_hz"].as_f64().unwrap();
        let t = m["period_s"].as_f64().unwrap();
        assert!(f >= previous && f > 0.0, "mode {i}: {f}");
        assert!((f * t - 1.0).abs() < 1e-12);
        assert!(m["label"].as_str().unwrap().contains(" mode of line"));
        let shares = m["kinetic_energy_share"]["lines"].as_object().unwrap();
        let total: f64 = shares.values().map(|s| s.as_f64().unwrap()).sum();
        assert!((total - 1.0).abs() < 1e-9, "energy shares sum to {total}");
        previous = f;
    }
    // The three identical lines give near-triple frequencies (the fairleads are not exactly
    // symmetric in the deck: 5.2 m vs 2.6/4.5 m, hence 1e-4).
    let f = |i: usize| modes[i]["frequency_hz"].as_f64().unwrap();
    assert!((f(2) - f(0)).abs() < 1e-4 * f(0));
    // Stiffness: every anchor and fairlead, 3×3; fairlead1's line runs along x, so it is
    // stiffer along x than sideways.
    let stiffness = v["stiffness"].as_object().unwrap();
    assert_eq!(stiffness.len(), 6);
    let k = &stiffness["fairlead1"]["matrix_n_per_m"];
    assert_eq!(stiffness["fairlead1"]["kind"], "prescribed");
    let kxx = k[0][0].as_f64().unwrap();
    let kyy = k[1][1].as_f64().unwrap();
    assert!(kxx > kyy && kyy > 0.0, "{k}");
    // Resonance: each fairlead's 0.1 Hz surge is 7 % below the second out-of-plane modes.
    let checks = v["resonance"]["checks"].as_array().unwrap();
    assert_eq!(checks.len(), 3);
    for c in checks {
        assert_eq!(c["frequency_hz"], 0.1);
        assert_eq!(c["warning"], true);
        let d = c["relative_distance"].as_f64().unwrap();
        assert!((-0.1..0.0).contains(&d), "{d}");
    }
    // Files.
    let summary = std::fs::read_to_string(dir.join("modes.csv")).unwrap();
    assert_eq!(summary.lines().count(), 13);
    assert!(summary.starts_with("mode,frequency [Hz],period [s],label"));
    let shapes = std::fs::read_to_string(dir.join("shapes_L1.csv")).unwrap();
    // 12 modes × 21 nodes + header; the ends on fixed and prescribed points do not move.
    assert_eq!(shapes.lines().count(), 1 + 12 * 21);
    let mut largest: f64 = 0.0;
    for row in shapes.lines().skip(1) {
        let c: Vec<f64> = row.split(',').map(|x| x.parse().unwrap()).collect();
        let u = (c[6] * c[6] + c[7] * c[7] + c[8] * c[8]).sqrt();
        if c[1] == 0.0 || c[1] == 20.0 {
            assert_eq!(u, 0.0);
        }
        largest = largest.max(u);
    }
    assert!(
        (largest - 1.0).abs() < 1e-12,
        "shapes scaled to 1: {largest}"
    );
    let saved: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("modes.json")).unwrap()).unwrap();
    assert_eq!(saved["modes"], v["modes"]);

    // A 5 % margin: 7 % away is clear.
    let out = hawser(&["modes", scenario.to_str().unwrap(), "--margin", "5"]);
    assert!(out.status.success());
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("resonance (margin 5.000 %)"), "{text}");
    assert!(!text.contains("WARNING"), "{text}");
    assert!(
        text.contains("first out-of-plane mode of line L1"),
        "{text}"
    );
    // Bad option: exit code 2.
    let out = hawser(&["modes", scenario.to_str().unwrap(), "--margin", "150"]);
    assert_eq!(out.status.code(), Some(2));
    let _ = std::fs::remove_dir_all(&dir);
}

/// A free body on four lines (the MoorDyn test deck `buoy_oc3.txt`): the body's six degrees of
/// freedom join the modes (labels name it, its energy share is reported), its 6×6 mooring
/// stiffness is in the JSON, and `--out` writes `shapes_bodies.csv`.
#[test]
fn modes_of_a_free_body_give_its_stiffness_and_shapes() {
    let (v, dir) = modes_json("tests/data/moordyn/buoy_oc3.txt", 8, "body-modes");
    // 4 lines × 19 interior nodes × 3, and the body's 6.
    assert_eq!(v["degrees_of_freedom"], 4 * 19 * 3 + 6);
    let modes = v["modes"].as_array().unwrap();
    // The lowest modes are the body's on its mooring (surge, sway, yaw: tens of seconds).
    assert!(
        modes
            .iter()
            .any(|m| m["label"].as_str().unwrap().contains("mode of body B1")),
        "{modes:#?}"
    );
    for m in modes {
        let share = &m["kinetic_energy_share"];
        let total: f64 = ["lines", "points", "bodies"]
            .iter()
            .flat_map(|k| share[k].as_object().unwrap().values())
            .map(|s| s.as_f64().unwrap())
            .sum();
        assert!((total - 1.0).abs() < 1e-9, "energy shares sum to {total}");
    }
    let k = &v["body_stiffness"]["B1"];
    assert_eq!(k["kind"], "free");
    let k = k["matrix_6x6"].as_array().unwrap();
    let entry = |i: usize, j: usize| k[i][j].as_f64().unwrap();
    // A moored body resists translation in every direction.
    assert!(entry(0, 0) > 0.0 && entry(1, 1) > 0.0 && entry(2, 2) > 0.0);
    let csv = std::fs::read_to_string(dir.join("shapes_bodies.csv")).unwrap();
    assert!(csv.starts_with("mode,body,x [m]"));
    assert_eq!(csv.lines().count(), 1 + 8);
    let _ = std::fs::remove_dir_all(&dir);
}
