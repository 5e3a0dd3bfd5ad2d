//! A run that diverges stops with the time, line, node and stable-step estimate, exits 1, and
//! keeps the results written so far, marked incomplete.

use std::path::PathBuf;
use std::process::Command;

fn temp_dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("hawser-divergence-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[test]
fn diverging_run_keeps_its_results_marked_incomplete() {
    let dir = temp_dir("snap");
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..");
    let text = std::fs::read_to_string(root.join("examples/snapping_cable_127.toml"))
        .unwrap()
        .replace("time_step = \"auto\"", "time_step = 0.01");
    let file = dir.join("unstable.toml");
    std::fs::write(&file, text).unwrap();
    let out = dir.join("out");
    let result = Command::new(env!("CARGO_BIN_EXE_hawser"))
        .args([
            "run",
            file.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
            "--quiet",
            "--allow-unstable-step",
        ])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&result.stderr);
    assert_eq!(result.status.code(), Some(1), "{stderr}");
    // The message names the time, the line and node, and the stable step.
    assert!(stderr.contains("diverged at t = "), "{stderr}");
    assert!(stderr.contains("on cable node "), "{stderr}");
    assert!(
        stderr.contains("stable time step estimate is 8.196e-4 s"),
        "{stderr}"
    );
    assert!(stderr.contains("marked incomplete"), "{stderr}");
    // Files kept: the time series has the samples before the divergence; status and summary
    // say the run is incomplete and carry the error.
    let ts = std::fs::read_to_string(out.join("timeseries.csv")).unwrap();
    assert!(ts.lines().count() >= 2, "{ts}");
    assert!(
        ts.lines().skip(1).all(|l| l
            .split(',')
            .all(|v| v.parse::<f64>().is_ok_and(f64::is_finite))),
        "non-finite values written:\n{ts}"
    );
    for name in ["status.json", "summary.json"] {
        let v: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(out.join(name)).unwrap()).unwrap();
        assert_eq!(v["complete"], serde_json::Value::Bool(false), "{name}");
        assert!(v["error"].as_str().unwrap().contains("diverged"), "{name}");
    }
    assert_final_state_is_the_last_row(&out);
    let _ = std::fs::remove_dir_all(&dir);
}

/// final_state.json of a diverged run holds the state of the last sample, at its time: its
/// end A tension is the last row's first channel. It said the last sample's time and held the
/// state of the failed step (positions of 1.8e18 m on the snapping cable).
fn assert_final_state_is_the_last_row(out: &std::path::Path) {
    let ts = std::fs::read_to_string(out.join("timeseries.csv")).unwrap();
    let last: Vec<f64> = ts
        .lines()
        .last()
        .unwrap()
        .split(',')
        .map(|v| v.parse().unwrap())
        .collect();
    let v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("final_state.json")).unwrap())
            .unwrap();
    assert_eq!(
        v["time"].as_f64().unwrap(),
        last[0],
        "final state at the last sample"
    );
    let line = v["lines"].as_object().unwrap().values().next().unwrap();
    let tension = line["end_a"]["tension"].as_f64().unwrap();
    assert!(
        (tension - last[1]).abs() <= 1e-12 * last[1].abs(),
        "final state's end A tension {tension} against the last row's {}",
        last[1]
    );
}

#[test]
fn a_blow_up_within_a_step_is_named_as_such() {
    // The catenary mooring at 7 times its stable step: the stages of a step met non-finite
    // positions and the mass solve failed; the run said "singular mass matrix".
    let dir = temp_dir("blowup");
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..");
    let text = std::fs::read_to_string(root.join("examples/catenary_mooring.toml"))
        .unwrap()
        .replace("time_step = \"auto\"", "time_step = 0.003");
    let file = dir.join("blowup.toml");
    std::fs::write(&file, text).unwrap();
    let out = dir.join("out");
    let result = Command::new(env!("CARGO_BIN_EXE_hawser"))
        .args([
            "run",
            file.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
            "--quiet",
            "--allow-unstable-step",
        ])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&result.stderr);
    assert_eq!(result.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("the state blew up"), "{stderr}");
    assert!(!stderr.contains("singular mass matrix"), "{stderr}");
    assert_final_state_is_the_last_row(&out);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn fixed_step_above_the_limit_is_refused_without_the_flag() {
    let dir = temp_dir("refuse");
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..");
    let text = std::fs::read_to_string(root.join("examples/snapping_cable_127.toml"))
        .unwrap()
        .replace("time_step = \"auto\"", "time_step = 0.01");
    let file = dir.join("unstable.toml");
    std::fs::write(&file, text).unwrap();
    let result = Command::new(env!("CARGO_BIN_EXE_hawser"))
        .args([
            "run",
            file.to_str().unwrap(),
            "--out",
            dir.join("out").to_str().unwrap(),
            "--quiet",
        ])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&result.stderr);
    assert_eq!(result.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("simulation.time_step") && stderr.contains("8.1961e-4"),
        "{stderr}"
    );
    assert!(
        !dir.join("out").exists(),
        "no partial output may be written for refused input"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
