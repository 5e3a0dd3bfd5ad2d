//! The `hawser` binary: exit codes and messages for valid and bad scenario files.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// A valid scenario: a chain from an anchor to a moving fairlead, and a buoy on a riser.
const VALID: &str = r#"[simulation]
duration = 1.0
time_step = "auto"
output_interval = 0.1

[environment]
water_density = 1025.0
depth = 100.0

[environment.seabed]
stiffness = 3.0e6
damping_ratio = 1.0

[environment.current]
type = "uniform"
velocity = [0.3, 0.0, 0.0]

[[line_types]]
name = "chain"
diameter = 0.09
mass_per_length = 77.7
axial_stiffness = 3.84e8
normal_drag = 1.6
tangential_drag = 0.3

[[points]]
name = "anchor"
type = "fixed"
position = [400.0, 0.0, -100.0]

[[points]]
name = "fairlead"
type = "prescribed"
position = [5.0, 0.0, -10.0]
motion = { type = "sinusoid", amplitude = [2.0, 0.0, 0.0], period = 10.0 }

[[points]]
name = "sinker"
type = "fixed"
position = [-50.0, 0.0, -100.0]

[[points]]
name = "buoy"
type = "free"
position = [-50.0, 0.0, -60.0]
mass = 200.0
volume = 2.0

[[lines]]
name = "L1"
end_a = "anchor"
end_b = "fairlead"
type = "chain"
length = 420.0
elements = 10

[[lines]]
name = "L2"
end_a = "sinker"
end_b = "buoy"
type = "chain"
length = 40.0
elements = 4
"#;

/// A fresh, empty directory for one test.
fn temp_dir(test: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("hawser-cli-{}-{test}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("create the temporary directory");
    dir
}

/// Writes `text` to `dir/name` and returns the path.
fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, text).expect("write the scenario");
    path
}

fn hawser(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_hawser"))
        .args(args)
        .output()
        .expect("run hawser")
}

/// `hawser run FILE --out OUT_DIR`, which must succeed (`dir`: the test's directory, for the
/// message).
fn run_ok(dir: &Path, file: &Path, out_dir: &Path) -> Output {
    let out = hawser(&[
        "run",
        file.to_str().unwrap(),
        "--out",
        out_dir.to_str().unwrap(),
    ]);
    assert!(out.status.success(), "{}", stderr(&out, dir));
    out
}

/// Stderr with the temporary directory replaced by `[TMP]`, for stable snapshots.
fn stderr(out: &Output, dir: &Path) -> String {
    String::from_utf8_lossy(&out.stderr).replace(&dir.display().to_string(), "[TMP]")
}

#[test]
fn check_accepts_a_valid_file() {
    let dir = temp_dir("check-valid");
    let file = write(&dir, "valid.toml", VALID);
    let out = hawser(&["check", file.to_str().unwrap()]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out, &dir));
    assert!(stdout.contains("ok"), "{stdout}");
    assert!(stdout.contains("2 line(s), 4 point(s)"), "{stdout}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn check_rejects_a_bad_file_with_exit_code_2() {
    let dir = temp_dir("check-bad");
    let text = VALID
        .replacen("diameter = 0.09", "diamter = 0.09", 1)
        .replacen("elements = 10", "elements = \"10\"", 1);
    let file = write(&dir, "bad.toml", &text);
    let out = hawser(&["check", file.to_str().unwrap()]);
    let err = stderr(&out, &dir);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(out.stdout.is_empty());
    assert!(err.contains("[TMP]/bad.toml:"), "{err}");
    insta::assert_snapshot!(err);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn check_reports_every_error() {
    let dir = temp_dir("check-several");
    let text = VALID
        .replacen("end_b = \"fairlead\"", "end_b = \"fairled\"", 1)
        .replacen("mass_per_length = 77.7", "mass_per_length = -77.7", 1)
        .replacen("elements = 4", "elements = 0", 1);
    let file = write(&dir, "several.toml", &text);
    let out = hawser(&["check", file.to_str().unwrap()]);
    let err = stderr(&out, &dir);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("3 errors in [TMP]/several.toml"), "{err}");
    insta::assert_snapshot!(err);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn check_reports_a_missing_file() {
    let dir = temp_dir("check-missing");
    let file = dir.join("nowhere.toml");
    let out = hawser(&["check", file.to_str().unwrap()]);
    let err = stderr(&out, &dir);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("[TMP]/nowhere.toml"), "{err}");
    assert!(err.contains("hint"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn run_rejects_a_time_step_above_the_stability_limit() {
    let dir = temp_dir("run-step");
    let text = VALID.replacen("time_step = \"auto\"", "time_step = 0.01", 1);
    let file = write(&dir, "step.toml", &text);
    let out_dir = dir.join("out");
    let out = hawser(&[
        "run",
        file.to_str().unwrap(),
        "--out",
        out_dir.to_str().unwrap(),
        "--quiet",
    ]);
    let err = stderr(&out, &dir);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("simulation.time_step"), "{err}");
    assert!(err.contains("stability limit"), "{err}");
    assert!(err.contains("[TMP]/step.toml:3:13"), "{err}");
    insta::assert_snapshot!(err);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn check_rejects_a_time_step_above_the_stability_limit() {
    let dir = temp_dir("check-step");
    let text = VALID.replacen("time_step = \"auto\"", "time_step = 0.01", 1);
    let file = write(&dir, "step.toml", &text);
    let out = hawser(&["check", file.to_str().unwrap()]);
    let err = stderr(&out, &dir);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("[TMP]/step.toml:3:13"), "{err}");
    assert!(err.contains("simulation.time_step"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn help() {
    let out = hawser(&["--help"]);
    assert_eq!(out.status.code(), Some(0));
    insta::assert_snapshot!(String::from_utf8_lossy(&out.stdout));
}

/// `hawser bench --formulation dg --order P` runs every line as `dg` of order P and counts its
/// nodal degrees of freedom as Σ(P + 1) per element; `--order` without dg is refused.
#[test]
fn bench_dg_counts_modal_degrees_of_freedom() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let file = root.join("examples/snapping_cable_127.toml");
    let file = file.to_str().unwrap();
    let out = hawser(&[
        "bench",
        file,
        "--formulation",
        "dg",
        "--order",
        "2",
        "--scheme",
        "ssp-rk3",
        "--duration",
        "0.02",
        "--json",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let runs: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let r = &runs[0];
    assert_eq!(r["formulation"], "dg");
    assert_eq!(r["order"], 2);
    assert_eq!(r["nodes"], 5 * 3, "5 elements of order 2: {r}");
    assert!(r["node_steps_per_s"].as_f64().unwrap() > 0.0);
    let refused = hawser(&["bench", file, "--order", "2", "--duration", "0.02"]);
    assert_eq!(refused.status.code(), Some(2));
}

/// `hawser bench --bodies both` runs the eight buoys as rigid bodies and as point masses on
/// the same lines, `--bodies points --waves all` the same lines in still water, a regular wave
/// and two JONSWAP seas; both print their columns, and the JSON gives each run's difference
/// from the matching baseline and the cost of the fluid kinematics alone. No timing is
/// asserted (the machine is shared); only that the numbers exist and are finite or positive.
#[test]
fn bench_compares_bodies_with_points_and_seas_with_still_water() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let file = root.join("scripts/bench/eight_buoys.toml");
    let file = file.to_str().unwrap();
    let common = ["--mass", "lumped", "--dt", "0.004", "--duration", "0.02"];
    let run = |extra: &[&str], json: bool| {
        let mut args = vec!["bench", file];
        args.extend_from_slice(extra);
        args.extend_from_slice(&common);
        if json {
            args.push("--json");
        }
        let out = hawser(&args);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        out.stdout
    };
    let bodies = ["--bodies", "both"];
    let waves = ["--bodies", "points", "--waves", "all"];
    let text = String::from_utf8_lossy(&run(&bodies, false)).to_string()
        + &String::from_utf8_lossy(&run(&waves, false));
    for column in [
        "waves",
        "bodies",
        "us/step",
        "node-steps/s",
        "us/body/step",
        "ns/node/step",
        "ns per u + a evaluation",
        "jonswap:200",
    ] {
        assert!(text.contains(column), "no {column:?} in\n{text}");
    }
    let b: serde_json::Value = serde_json::from_slice(&run(&bodies, true)).unwrap();
    let w: serde_json::Value = serde_json::from_slice(&run(&waves, true)).unwrap();
    let (b_runs, w_runs) = (b["runs"].as_array().unwrap(), w["runs"].as_array().unwrap());
    assert_eq!(
        (b_runs.len(), w_runs.len()),
        (2, 4),
        "bodies/points; 4 seas"
    );
    let steps = &b_runs[0]["steps"];
    for r in b_runs.iter().chain(w_runs) {
        // The same 8 lines of 10 elements and the same steps every time.
        assert_eq!(r["nodes"], 88, "{r}");
        assert_eq!(&r["steps"], steps, "{r}");
        let points = r["bodies_replaced_by_points"].as_u64().unwrap();
        let bodies = r["free_bodies"].as_u64().unwrap();
        assert_eq!((points, bodies), if points > 0 { (8, 0) } else { (0, 8) });
        assert!(r["us_per_step"].as_f64().unwrap() > 0.0);
        let isa = r["instruction_set"].as_str();
        assert!(
            matches!(isa, Some("avx512" | "avx2" | "sse2" | "baseline")),
            "{r}"
        );
        // `auto`'s switching: numbers when it started with generalized-α, null otherwise.
        let auto_implicit = r["scheme"] == "generalized-alpha" && !r["scheme_switches"].is_null();
        assert_eq!(r["rk4_share"].is_null(), !auto_implicit, "{r}");
        assert!(r.get("scheme_switches").is_some(), "{r}");
        if bodies > 0 {
            assert!(
                r["body_overhead_us_per_body_step"]
                    .as_f64()
                    .unwrap()
                    .is_finite()
            );
        }
        if r["waves"] != "still" && r["waves"] != "as-is" {
            assert!(
                r["kinematics_ns_per_node_step"]
                    .as_f64()
                    .unwrap()
                    .is_finite()
            );
        }
    }
    let k = w["kinematics"].as_array().unwrap();
    let labels: Vec<_> = k.iter().map(|k| k["waves"].as_str().unwrap()).collect();
    assert_eq!(labels, ["still", "regular", "jonswap:50", "jonswap:200"]);
    assert!(
        k.iter()
            .all(|k| k["ns_per_evaluation"].as_f64().unwrap() > 0.0)
    );
    // `--kinematics both`: each sea summed directly and at the static position (still water
    // once), with the paired CPU ratio to still water and the cache's size.
    let both = [
        "--bodies",
        "points",
        "--waves",
        "still,jonswap:50:6:10",
        "--kinematics",
        "both",
    ];
    let k: serde_json::Value = serde_json::from_slice(&run(&both, true)).unwrap();
    let runs = k["runs"].as_array().unwrap();
    let kinds: Vec<_> = runs
        .iter()
        .map(|r| {
            (
                r["waves"].as_str().unwrap(),
                r["kinematics"].as_str().unwrap(),
            )
        })
        .collect();
    assert_eq!(
        kinds,
        [
            ("still", "direct"),
            ("jonswap:50:6:10", "direct"),
            ("jonswap:50:6:10", "static-position")
        ]
    );
    for r in runs {
        assert!(r["cpu_ratio_to_still"].as_f64().unwrap() > 0.0, "{r}");
    }
    // 8 lines × 10 elements × 2 Gauss points, 16 bytes per component and point and more.
    assert_eq!(runs[2]["wave_table_points"], 160);
    assert!(runs[2]["wave_table_bytes"].as_u64().unwrap() > 160 * 16 * 50);
    for bad in [
        ["--bodies", "some"],
        ["--waves", "jonswap:0"],
        ["--waves", "jonswap:50:6"],
        ["--kinematics", "grid"],
    ] {
        let out = hawser(&["bench", file, bad[0], bad[1], "--duration", "0.02"]);
        assert_eq!(out.status.code(), Some(2), "{bad:?}");
    }
}

/// Off a terminal (here standard error is a pipe) a run prints a progress line at every
/// tenth of its duration (and every 10 s of wall time): simulated time, fraction, real-time
/// factor, elapsed time and ETA; `--quiet` hides them.
#[test]
fn run_off_a_terminal_prints_progress_lines() {
    let dir = temp_dir("progress");
    let file = write(&dir, "valid.toml", VALID);
    let out_dir = dir.join("out");
    let out = run_ok(&dir, &file, &out_dir);
    let err = stderr(&out, &dir);
    let lines: Vec<&str> = err
        .lines()
        .filter(|l| l.starts_with("progress: "))
        .collect();
    assert!(lines.len() >= 10, "{err}");
    for tenth in 1..=10 {
        let at = format!(
            "t = {:.2} s of 1.00 s ({} %)",
            tenth as f64 / 10.0,
            10 * tenth
        );
        assert!(
            lines.iter().any(|l| l.contains(&at)),
            "no line at {at}:\n{err}"
        );
    }
    assert!(
        lines
            .iter()
            .all(|l| l.contains("× real time, elapsed ") && l.contains(", ETA "))
    );
    let out = hawser(&[
        "run",
        file.to_str().unwrap(),
        "--out",
        out_dir.to_str().unwrap(),
        "--overwrite",
        "--quiet",
    ]);
    assert!(out.status.success());
    assert!(!stderr(&out, &dir).contains("progress: "));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `summary.json` records what the time integration did: the scheme and why, the steps of
/// every scheme, the step at the end, generalized-α's counts (those `hawser run` prints) and
/// `auto`'s switching, `null` where a scheme did not run.
#[test]
fn summary_records_the_integrator() {
    let dir = temp_dir("integrator");
    let run = |name: &str, simulation: &str| -> (serde_json::Value, String) {
        let text = VALID.replacen(
            "[simulation]\nduration = 1.0\ntime_step = \"auto\"\n",
            &format!("[simulation]\nduration = 1.0\n{simulation}\n"),
            1,
        );
        assert_ne!(text, VALID);
        let file = write(&dir, &format!("{name}.toml"), &text);
        let out_dir = dir.join(name);
        let out = run_ok(&dir, &file, &out_dir);
        let summary = std::fs::read_to_string(out_dir.join("summary.json")).expect("summary");
        let v: serde_json::Value = serde_json::from_str(&summary).expect("JSON");
        (v["integrator"].clone(), stderr(&out, &dir))
    };

    // RK4 at a fixed step: 400 steps of 2.5 ms, nothing of generalized-α or auto.
    let (rk4, _) = run("rk4", "time_step = 0.0025\nscheme = \"rk4\"");
    assert_eq!(rk4["scheme"], "rk4", "{rk4}");
    assert_eq!(rk4["reason"], "set by the scenario", "{rk4}");
    assert_eq!(rk4["steps"], 400, "{rk4}");
    assert_eq!(rk4["time_step"], 0.0025, "{rk4}");
    assert!(rk4["generalized_alpha"].is_null(), "{rk4}");
    assert!(rk4["auto_switching"].is_null(), "{rk4}");

    // Adaptive generalized-α: its counts are the ones `hawser run` prints, every step its own.
    let (ga, err) = run("ga", "time_step = \"auto\"\nscheme = \"generalized-alpha\"");
    assert_eq!(ga["scheme"], "generalized-alpha", "{ga}");
    let g = &ga["generalized_alpha"];
    let count = |key: &str| g[key].as_u64().unwrap_or_else(|| panic!("{key} in {ga}"));
    let printed = format!(
        "generalized-α: {} steps ({} refused), {} Newton iterations, {} Jacobians",
        count("steps"),
        count("refused"),
        count("newton_iterations"),
        count("jacobians")
    );
    assert!(err.contains(&printed), "{printed}\n{err}");
    assert_eq!(ga["steps"].as_u64(), Some(count("steps")), "{ga}");
    assert!(
        count("steps") > 0 && count("newton_iterations") >= count("steps"),
        "{ga}"
    );
    assert!(
        ga["time_step"]
            .as_f64()
            .is_some_and(|h| h > 0.0 && h <= 1.0),
        "{ga}"
    );
    assert!(ga["auto_switching"].is_null(), "{ga}");

    // auto: the scheme it started with, and its switching when that is generalized-α, whose
    // steps and RK4's add up to the run's.
    let (auto, _) = run("auto", "time_step = \"auto\"\nscheme = \"auto\"");
    let reason = auto["reason"].as_str().expect("reason");
    assert!(
        !reason.is_empty() && reason != "set by the scenario",
        "{auto}"
    );
    match auto["scheme"].as_str() {
        Some("generalized-alpha") => {
            let w = &auto["auto_switching"];
            let rk4_time = w["rk4_time"].as_f64().expect("rk4_time");
            assert!((0.0..=1.0).contains(&rk4_time), "{auto}");
            let ga_steps = auto["generalized_alpha"]["steps"].as_u64().expect("steps");
            let steps = auto["steps"].as_u64().expect("steps");
            assert!(ga_steps <= steps, "{auto}");
            assert_eq!(ga_steps == steps, w["switches"] == 0, "{auto}");
        }
        Some("rk4") => {
            assert!(auto["generalized_alpha"].is_null(), "{auto}");
            assert!(auto["auto_switching"].is_null(), "{auto}");
        }
        other => panic!("auto chose {other:?}: {auto}"),
    }
}
