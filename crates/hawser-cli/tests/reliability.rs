//! The command line under bad input and faults: steps with which a run cannot end are refused,
//! `check` names the scheme a run takes,
//! warnings reach the terminal and the result files, a closed standard error is no panic,
//! `--duration` is honoured on scenarios and `--vessel-motion` refused there, a vessel-motion
//! file's errors name the right base directory and quote nothing of a file that is no table,
//! `--quiet` hides the step line, and the step line says when the automatic step was lowered.

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// A fresh, empty directory for one test.
fn temp_dir(test: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("hawser-rel-{}-{test}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn hawser(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_hawser"))
        .args(args)
        .output()
        .unwrap()
}

fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).to_string()
}

/// The replacement that makes examples/catenary_mooring.toml run RK4 (the tests of its stable
/// step; the default scheme is `auto`).
const RK4: (&str, &str) = (
    "time_step = \"auto\"",
    "time_step = \"auto\"\nscheme = \"rk4\"",
);

/// examples/catenary_mooring.toml with `from` replaced by `to`, written into `dir`, its
/// statistics window from t = 0 (the example's starts at 24 s, after its ramp, which the
/// shortened runs here do not reach: a window past the end is refused).
fn catenary(dir: &Path, name: &str, replacements: &[(&str, &str)]) -> PathBuf {
    let mut text = std::fs::read_to_string(root().join("examples/catenary_mooring.toml"))
        .unwrap()
        .replacen("start = 24.0", "start = 0.0", 1);
    for (from, to) in replacements {
        assert!(text.contains(from), "no `{from}`");
        text = text.replacen(from, to, 1);
    }
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
fn a_step_with_which_the_run_cannot_end_is_refused() {
    // A friction velocity of 1e-300 m/s makes the stable step 6.8e-302 s, and an element
    // length of 1e-300 m makes it 0: `check` said ok for both.
    let dir = temp_dir("step");
    for (name, from, to) in [
        (
            "friction.toml",
            "friction_velocity = 0.01",
            "friction_velocity = 1e-300",
        ),
        ("length.toml", "length = 680.0", "length = 1e-300"),
    ] {
        // RK4's stable step is what the degenerate values break (the default `auto` would take
        // generalized-α, which has no stability limit).
        let file = catenary(&dir, name, &[(from, to), RK4]);
        let out = hawser(&["check", file.to_str().unwrap()]);
        let err = stderr(&out);
        assert_eq!(out.status.code(), Some(2), "{name}: {err}");
        assert!(err.contains("cannot run the 60 s duration"), "{err}");
        assert!(out.stdout.is_empty(), "{name}: no `ok`");
        let out_dir = dir.join("out");
        let run = hawser(&[
            "run",
            file.to_str().unwrap(),
            "--out",
            out_dir.to_str().unwrap(),
        ]);
        assert_eq!(run.status.code(), Some(2), "{name}: {}", stderr(&run));
        assert!(!out_dir.exists(), "a refused run writes nothing");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn check_names_the_scheme_and_does_not_promise_an_adaptive_run_a_step_count() {
    // The default `auto` takes adaptive generalized-α on the README example: the accuracy step
    // bounds its steps from above only, so `check` gives a lower bound, not RK4's count.
    let out = hawser(&[
        "check",
        root()
            .join("examples/catenary_mooring.toml")
            .to_str()
            .unwrap(),
    ]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    assert!(
        stdout.contains("scheme generalized-alpha (the accuracy step"),
        "{stdout}"
    );
    assert!(stdout.contains("adaptive steps of at most"), "{stdout}");
    assert!(stdout.contains("the response sets how many"), "{stdout}");
    let dir = temp_dir("scheme");
    let file = catenary(&dir, "rk4.toml", &[RK4]);
    let out = hawser(&["check", file.to_str().unwrap()]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        stdout.contains("scheme rk4 (set by the scenario)"),
        "{stdout}"
    );
    assert!(!stdout.contains("adaptive"), "{stdout}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn check_counts_the_steps_and_warns_of_a_run_too_long_to_end() {
    let dir = temp_dir("long");
    // RK4's stable step sets the count (the default `auto` takes adaptive generalized-α).
    let file = catenary(&dir, "ok.toml", &[RK4]);
    let out = hawser(&["check", file.to_str().unwrap()]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    assert!(stdout.contains("steps of at most"), "{stdout}");
    assert!(!stderr(&out).contains("warning"), "{}", stderr(&out));
    // 1e7 s at 2.9e-4 s: 3.4e10 steps of 137 nodes, 4.7e12 node-steps.
    let file = catenary(
        &dir,
        "long.toml",
        &[("duration = 60.0", "duration = 1e7"), RK4],
    );
    let out = hawser(&["check", file.to_str().unwrap()]);
    let err = stderr(&out);
    assert_eq!(out.status.code(), Some(0), "{err}");
    assert!(
        err.contains("warning: the time step") && err.contains("will not end in useful time"),
        "{err}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn statics_and_run_report_their_warnings() {
    // 500 m of chain for 615 m between its ends: 23 % strain and 133 MN of tension.
    let dir = temp_dir("warnings");
    let file = catenary(
        &dir,
        "short.toml",
        &[
            ("length = 680.0", "length = 500.0"),
            ("duration = 60.0", "duration = 0.2"),
        ],
    );
    let out = hawser(&["statics", file.to_str().unwrap()]);
    let err = stderr(&out);
    assert_eq!(out.status.code(), Some(0), "{err}");
    assert!(err.contains("warning: line chain: strain 23.0"), "{err}");
    assert!(
        String::from_utf8_lossy(&out.stdout).contains("tolerance"),
        "the tolerance applied is printed"
    );
    let out = hawser(&["statics", file.to_str().unwrap(), "--json"]);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["warnings"][0]["kind"], "strain-beyond-material", "{v}");
    assert!(v["solver"]["tolerance"].as_f64().unwrap() > 0.0);
    // Which method converged, after how many iterations, to which residual, and why it left
    // Newton (null: it did not).
    assert!(v["solver"]["method"].is_string(), "{v}");
    assert!(v["solver"]["iterations"].as_u64().unwrap() > 0, "{v}");
    assert!(v["solver"]["residual"].as_f64().unwrap().is_finite(), "{v}");
    let fallback = &v["solver"]["fallback"];
    assert!(fallback.is_null() || fallback.is_string(), "{v}");
    let out_dir = dir.join("out");
    let run = hawser(&[
        "run",
        file.to_str().unwrap(),
        "--out",
        out_dir.to_str().unwrap(),
        "--quiet",
    ]);
    let err = stderr(&run);
    assert_eq!(run.status.code(), Some(0), "{err}");
    assert!(
        err.contains("warning: line chain: strain"),
        "--quiet keeps warnings: {err}"
    );
    for name in ["summary.json", "status.json"] {
        let v: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(out_dir.join(name)).unwrap()).unwrap();
        assert_eq!(v["warnings"][0]["kind"], "strain-beyond-material", "{name}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// hawser with standard error a pipe whose reader has gone.
fn with_broken_stderr(args: &[&str]) -> Option<i32> {
    let (reader, writer) = std::io::pipe().unwrap();
    drop(reader);
    Command::new(env!("CARGO_BIN_EXE_hawser"))
        .args(args)
        .stdout(Stdio::null())
        .stderr(writer)
        .status()
        .unwrap()
        .code()
}

#[test]
fn a_broken_standard_error_is_no_panic() {
    // Every error report panicked ("failed printing to stderr") and exited 101.
    let dir = temp_dir("stderr");
    let bad = catenary(
        &dir,
        "bad.toml",
        &[("mass_per_length = 126.0", "mass_per_length = -1.0")],
    );
    assert_eq!(
        with_broken_stderr(&["check", bad.to_str().unwrap()]),
        Some(2)
    );
    let good = catenary(&dir, "good.toml", &[("duration = 60.0", "duration = 0.1")]);
    let out = dir.join("out");
    assert_eq!(
        with_broken_stderr(&[
            "run",
            good.to_str().unwrap(),
            "--out",
            out.to_str().unwrap()
        ]),
        Some(0)
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn duration_is_honoured_and_vessel_motion_refused_on_a_scenario() {
    let dir = temp_dir("duration");
    let file = catenary(&dir, "c.toml", &[]);
    let out_dir = dir.join("out");
    let run = hawser(&[
        "run",
        file.to_str().unwrap(),
        "--out",
        out_dir.to_str().unwrap(),
        "--duration",
        "0.3",
    ]);
    let err = stderr(&run);
    assert_eq!(run.status.code(), Some(0), "{err}");
    assert!(err.contains("--duration 0.3 s replaces"), "{err}");
    let ts = std::fs::read_to_string(out_dir.join("timeseries.csv")).unwrap();
    let last = ts.lines().last().unwrap();
    assert!(last.starts_with("0.3"), "the run ends at 0.3 s: {last}");
    let bad = hawser(&["check", file.to_str().unwrap(), "--duration=-1"]);
    assert_eq!(bad.status.code(), Some(2));
    assert!(stderr(&bad).contains("key: --duration"), "{}", stderr(&bad));
    let motion = dir.join("motion.csv");
    std::fs::write(&motion, "0 0 0 0 0 0 0\n").unwrap();
    let refused = hawser(&[
        "check",
        file.to_str().unwrap(),
        "--vessel-motion",
        motion.to_str().unwrap(),
    ]);
    let err = stderr(&refused);
    assert_eq!(refused.status.code(), Some(2), "{err}");
    assert!(err.contains("applies to MoorDyn decks"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn vessel_motion_errors_name_the_working_directory_and_quote_no_other_file() {
    let dir = temp_dir("vessel");
    let deck = root().join("tests/data/moordyn/oc3_lines.txt");
    let check = |motion: &str| {
        let out = Command::new(env!("CARGO_BIN_EXE_hawser"))
            .args(["check", deck.to_str().unwrap(), "--vessel-motion", motion])
            .current_dir(&dir)
            .output()
            .unwrap();
        (out.status.code(), stderr(&out))
    };
    // A relative path is the working directory's; the hint said "relative to the scenario
    // file", once per coupled point.
    let (code, err) = check("missing.csv");
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("relative to the working directory"), "{err}");
    assert!(!err.contains("relative to the scenario file"), "{err}");
    assert_eq!(err.matches("error:").count(), 1, "reported once: {err}");
    // A file that is no table: its second line was quoted.
    std::fs::write(dir.join("secret.txt"), "user: alice\npassword: hunter2\n").unwrap();
    let (code, err) = check("secret.txt");
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("secret.txt:2: not a table of numbers"),
        "{err}"
    );
    assert!(!err.contains("hunter2") && !err.contains("alice"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn the_step_line_says_when_the_automatic_step_was_lowered_and_quiet_hides_it() {
    let dir = temp_dir("quiet");
    // RK4: the lowered automatic step is the explicit schemes' (generalized-α adapts its own).
    let file = catenary(
        &dir,
        "c.toml",
        &[("duration = 60.0", "duration = 0.1"), RK4],
    );
    let out_dir = dir.join("out");
    let loud = hawser(&[
        "run",
        file.to_str().unwrap(),
        "--out",
        out_dir.to_str().unwrap(),
    ]);
    let err = stderr(&loud);
    assert_eq!(loud.status.code(), Some(0), "{err}");
    // The wanted step, 0.8 of the limit, does not divide the 0.1 s output interval.
    assert!(
        err.contains("time step") && err.contains("lowered from 0.8 × the limit"),
        "{err}"
    );
    let quiet = hawser(&[
        "run",
        file.to_str().unwrap(),
        "--out",
        out_dir.to_str().unwrap(),
        "--overwrite",
        "--quiet",
    ]);
    let err = stderr(&quiet);
    assert_eq!(quiet.status.code(), Some(0), "{err}");
    assert!(!err.contains("time step"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}
