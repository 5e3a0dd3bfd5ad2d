//! Interrupt and resume: a run stopped by SIGINT or SIGTERM, or killed (SIGKILL) after a
//! periodic checkpoint, then continued by `hawser resume`, writes a `timeseries.csv`,
//! `timeseries.parquet`, snapshots, ParaView files and `summary.json` byte-identical to the
//! uninterrupted run's: RK4, SSP-RK3, the three-level scheme and adaptive generalized-α on the
//! catenary mooring, and RK4 and generalized-α with a free body in irregular waves (the ROV
//! example). A stopped run exits 130 (SIGINT) or 143 (SIGTERM) with its status
//! "interrupted"; an output folder holding a run is refused without `--overwrite`.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn hawser() -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_hawser"));
    c.current_dir(root());
    c
}

/// A scenario in a fresh folder: `example` with the simulation duration set to `duration`,
/// `extra` lines added to `[simulation]`, and its data files found where they are.
fn scenario(name: &str, example: &str, duration: f64, extra: &str) -> (PathBuf, PathBuf) {
    let dir = std::env::temp_dir().join(format!("hawser_resume_{name}_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let text = std::fs::read_to_string(root().join("examples").join(example)).unwrap();
    let data = root().join("examples/data");
    let mut out = String::new();
    for line in text.lines() {
        if line.trim_start().starts_with("duration =") && !out.contains("duration =") {
            out.push_str(&format!("duration = {duration}\n{extra}\n"));
        } else if line.trim_start().starts_with("start =") {
            // The statistics window must start within the shortened run.
            out.push_str("start = 0.0\n");
        } else {
            out.push_str(&line.replace("\"data/", &format!("\"{}/", data.display())));
            out.push('\n');
        }
    }
    let path = dir.join("scenario.toml");
    std::fs::write(&path, out).unwrap();
    (dir, path)
}

fn rows(csv: &Path) -> usize {
    std::fs::read_to_string(csv).map_or(0, |t| t.lines().count())
}

/// Runs to the end, uninterrupted.
fn run_whole(scenario: &Path, out: &Path) {
    let s = hawser()
        .args(["run", scenario.to_str().unwrap(), "--quiet", "--out"])
        .arg(out)
        .status()
        .unwrap();
    assert!(s.success(), "uninterrupted run failed");
}

/// Starts a run and sends `signal` once its time series has `after` rows (or, with
/// `checkpoint`, once it has written a checkpoint); returns its exit code.
fn run_and_stop(
    scenario: &Path,
    out: &Path,
    signal: i32,
    after: usize,
    checkpoint: Option<f64>,
) -> Option<i32> {
    let mut cmd = hawser();
    cmd.args(["run", scenario.to_str().unwrap(), "--quiet", "--out"])
        .arg(out)
        .stderr(Stdio::piped());
    if let Some(c) = checkpoint {
        cmd.args(["--checkpoint-every", &c.to_string()]);
    }
    let mut child = cmd.spawn().unwrap();
    let start = Instant::now();
    loop {
        let ready = match checkpoint {
            Some(_) => {
                out.join("checkpoint.bin").exists() && rows(&out.join("timeseries.csv")) > after
            }
            None => rows(&out.join("timeseries.csv")) > after,
        };
        if ready {
            break;
        }
        assert!(
            child.try_wait().unwrap().is_none(),
            "the run ended before it could be stopped"
        );
        assert!(start.elapsed() < Duration::from_secs(600), "no progress");
        std::thread::sleep(Duration::from_millis(5));
    }
    unsafe { libc::kill(child.id() as i32, signal) };
    let status = child.wait().unwrap();
    assert!(
        child.try_wait().unwrap().is_some(),
        "the run is still going"
    );
    status.code()
}

fn resume(out: &Path) {
    let o = hawser()
        .args(["resume", "--quiet"])
        .arg(out)
        .output()
        .unwrap();
    assert!(
        o.status.success(),
        "resume failed: {}",
        String::from_utf8_lossy(&o.stderr)
    );
}

/// The run's results, with the scenario path (which `status.json` names) left out.
fn assert_same_results(a: &Path, b: &Path) {
    for f in [
        "timeseries.csv",
        "timeseries.parquet",
        "channels.json",
        "summary.json",
        "final_state.json",
    ] {
        let (x, y) = (
            std::fs::read(a.join(f)).unwrap(),
            std::fs::read(b.join(f)).unwrap(),
        );
        assert!(x == y, "{f} differs between the whole and the resumed run");
    }
    for folder in ["snapshots", "vtk"] {
        if !a.join(folder).exists() {
            continue;
        }
        let files = |d: &Path| {
            let mut v: Vec<_> = std::fs::read_dir(d.join(folder))
                .unwrap()
                .map(|e| e.unwrap().file_name())
                .collect();
            v.sort();
            v
        };
        assert_eq!(files(a), files(b), "{folder}/ holds other files");
        for name in files(a) {
            let (p, q) = (a.join(folder).join(&name), b.join(folder).join(&name));
            assert!(
                std::fs::read(&p).unwrap() == std::fs::read(&q).unwrap(),
                "{} differs",
                p.display()
            );
        }
    }
    let status = std::fs::read_to_string(b.join("status.json")).unwrap();
    assert!(status.contains("\"complete\": true"), "{status}");
    assert!(
        !b.join("checkpoint.bin").exists(),
        "a finished run keeps no checkpoint"
    );
}

fn interrupt_and_resume(name: &str, example: &str, duration: f64, extra: &str, signal: i32) {
    let (dir, path) = scenario(name, example, duration, extra);
    let (whole, parts) = (dir.join("whole"), dir.join("parts"));
    run_whole(&path, &whole);
    let total = rows(&whole.join("timeseries.csv"));
    let code = run_and_stop(&path, &parts, signal, total / 3, None);
    let expected = if signal == libc::SIGINT { 130 } else { 143 };
    assert_eq!(code, Some(expected), "{name}: exit code of the stopped run");
    let status = std::fs::read_to_string(parts.join("status.json")).unwrap();
    assert!(status.contains("\"state\": \"interrupted\""), "{status}");
    assert!(parts.join("summary.json").exists());
    assert!(
        rows(&parts.join("timeseries.csv")) < total,
        "{name}: stopped too late"
    );
    resume(&parts);
    assert_same_results(&whole, &parts);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn rk4_interrupted_by_sigint_resumes_bit_for_bit() {
    interrupt_and_resume("rk4", "catenary_mooring.toml", 12.0, "", libc::SIGINT);
}

#[test]
fn ssp_rk3_interrupted_by_sigterm_resumes_bit_for_bit() {
    interrupt_and_resume(
        "ssp",
        "catenary_mooring.toml",
        12.0,
        "scheme = \"ssp-rk3\"",
        libc::SIGTERM,
    );
}

#[test]
fn three_level_interrupted_resumes_bit_for_bit() {
    interrupt_and_resume(
        "three_level",
        "catenary_mooring.toml",
        12.0,
        "scheme = \"three-level\"",
        libc::SIGINT,
    );
}

#[test]
fn generalized_alpha_interrupted_resumes_bit_for_bit() {
    // Adaptive steps: the acceleration history, the step controller's nominal step and the
    // Jacobian the Newton iterations reuse are all in the checkpoint.
    interrupt_and_resume(
        "generalized_alpha",
        "catenary_mooring.toml",
        60.0,
        "scheme = \"generalized-alpha\"",
        libc::SIGINT,
    );
}

#[test]
fn free_body_in_waves_interrupted_resumes_bit_for_bit() {
    interrupt_and_resume("rov", "rov_irregular_waves.toml", 12.0, "", libc::SIGINT);
}

#[test]
fn killed_after_a_checkpoint_resumes_bit_for_bit() {
    // SIGKILL leaves no chance to flush or save: the periodic checkpoint and the files cut
    // back to their length at that checkpoint carry the run.
    kill_and_resume("kill", "catenary_mooring.toml", 12.0, "");
}

/// Kills a run (SIGKILL) once it has written a checkpoint (every 2 s simulated), resumes it,
/// and compares with the uninterrupted run.
fn kill_and_resume(name: &str, example: &str, duration: f64, extra: &str) {
    let (dir, path) = scenario(name, example, duration, extra);
    let (whole, parts) = (dir.join("whole"), dir.join("parts"));
    run_whole(&path, &whole);
    let total = rows(&whole.join("timeseries.csv"));
    let code = run_and_stop(&path, &parts, libc::SIGKILL, total / 3, Some(2.0));
    assert_eq!(code, None, "killed by a signal");
    resume(&parts);
    assert_same_results(&whole, &parts);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn generalized_alpha_free_body_killed_after_a_checkpoint_resumes_bit_for_bit() {
    // A free body (quaternion state, rotation-group update) with adaptive generalized-α steps.
    kill_and_resume(
        "kill_ga",
        "rov_irregular_waves.toml",
        30.0,
        "scheme = \"generalized-alpha\"",
    );
}

#[test]
fn a_folder_holding_a_run_is_refused_without_overwrite() {
    let (dir, path) = scenario("overwrite", "catenary_mooring.toml", 0.5, "");
    let out = dir.join("out");
    run_whole(&path, &out);
    // A stale snapshot and a file of the user's own.
    std::fs::write(out.join("snapshots/old_line.csv"), "stale").unwrap();
    std::fs::write(out.join("notes.txt"), "mine").unwrap();
    let o = hawser()
        .args(["run", path.to_str().unwrap(), "--quiet", "--out"])
        .arg(&out)
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2));
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(
        e.contains("holds the results of another run") && e.contains("--overwrite"),
        "{e}"
    );
    let o = hawser()
        .args([
            "run",
            path.to_str().unwrap(),
            "--quiet",
            "--overwrite",
            "--out",
        ])
        .arg(&out)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(
        !out.join("snapshots/old_line.csv").exists(),
        "stale snapshot left"
    );
    assert!(
        out.join("notes.txt").exists(),
        "the user's own file was removed"
    );
    // Nothing to resume in a finished run.
    let o = hawser()
        .args(["resume", "--quiet"])
        .arg(&out)
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("the run is complete"));
    let _ = std::fs::remove_dir_all(&dir);
}

/// A line failure across an interruption: the catenary mooring's chain lets go of its
/// fairlead at 5 s; the run is stopped before that (SIGINT at a third of its rows, 4 s), and
/// resumed, and once more killed after a checkpoint past it (every 2 s); both end
/// byte-identical to the uninterrupted run. The uninterrupted run says so on stderr and lists
/// the release in `summary.json` and `status.json`. With RK4 (the example's scheme) and
/// with adaptive generalized-α, whose history restarts at the release (the restarted
/// accelerations and Jacobian, and the controller's step, are in the checkpoint).
#[test]
fn a_line_failure_resumes_bit_for_bit() {
    let ga = "scheme = \"generalized-alpha\"";
    for (name, kill, extra) in [
        ("failure_sigint", false, ""),
        ("failure_kill", true, ""),
        ("failure_ga_sigint", false, ga),
        ("failure_ga_kill", true, ga),
    ] {
        let (dir, path) = scenario(name, "catenary_mooring.toml", 12.0, extra);
        let mut text = std::fs::read_to_string(&path).unwrap();
        text.push_str("\n[lines.failure]\nend = \"B\"\ntime = 5.0\n");
        std::fs::write(&path, text).unwrap();
        let (whole, parts) = (dir.join("whole"), dir.join("parts"));
        let o = hawser()
            .args(["run", path.to_str().unwrap(), "--quiet", "--out"])
            .arg(&whole)
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&o.stderr);
        assert!(o.status.success(), "{stderr}");
        assert!(
            stderr.contains("failure: line chain end b released from point fairlead at t = 5.0"),
            "{stderr}"
        );
        let summary: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(whole.join("summary.json")).unwrap())
                .unwrap();
        let f = &summary["failures"][0];
        assert_eq!(
            (f["line"].as_str(), f["end"].as_str()),
            (Some("chain"), Some("b"))
        );
        assert_eq!(f["attachment"].as_str(), Some("fairlead"));
        assert_eq!(f["cause"].as_str(), Some("time"));
        let t = f["time"].as_f64().unwrap();
        assert!((5.0..5.1).contains(&t), "{t}");
        assert!(f["tension"].as_f64().unwrap() > 1e5, "{f}");
        let status = std::fs::read_to_string(whole.join("status.json")).unwrap();
        assert!(
            status.contains("\"failures\"") && status.contains("\"fairlead\""),
            "{status}"
        );
        let total = rows(&whole.join("timeseries.csv"));
        if kill {
            let code = run_and_stop(&path, &parts, libc::SIGKILL, 2 * total / 3, Some(2.0));
            assert_eq!(code, None, "killed by a signal");
        } else {
            let code = run_and_stop(&path, &parts, libc::SIGINT, total / 3, None);
            assert_eq!(code, Some(130));
        }
        resume(&parts);
        assert_same_results(&whole, &parts);
        let _ = std::fs::remove_dir_all(&dir);
    }
}
