//! Results are never lost or misstated by a fault: a file that cannot be written stops the run
//! at that row with the file's name; a run killed by SIGKILL at any moment leaves whole rows
//! that read back as the uninterrupted run's numbers; a run refused or failed with
//! `--overwrite` leaves no earlier run's results that say "complete".

use hawser_io::results::read_table;
use std::os::unix::process::CommandExt;
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

fn temp_dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("hawser_faults_{name}_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// The catenary mooring example (90 elements, a snapshot every 2 s, 5 channels) run for
/// `duration` s, with the keys of `[simulation]` named in `remove` left out and `extra` lines
/// added (which replace the keys they give), written into `dir`.
fn catenary(dir: &Path, duration: f64, extra: &str, remove: &[&str]) -> PathBuf {
    let text = std::fs::read_to_string(root().join("examples/catenary_mooring.toml")).unwrap();
    let key = |l: &str| l.split('=').next().unwrap_or("").trim().to_string();
    let given: Vec<String> = extra.lines().map(key).collect();
    let mut out = String::new();
    for line in text.lines() {
        let k = key(line);
        if line.contains('=') && (given.contains(&k) || remove.contains(&k.as_str())) {
            continue;
        }
        if k == "duration" {
            out.push_str(&format!("duration = {duration}\n{extra}\n"));
        } else if k == "start" {
            // The statistics window must start within the shortened run.
            out.push_str("start = 0.0\n");
        } else {
            out.push_str(line);
            out.push('\n');
        }
    }
    let path = dir.join("scenario.toml");
    std::fs::write(&path, out).unwrap();
    path
}

fn json(path: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

#[test]
fn a_file_that_cannot_grow_stops_the_run_at_that_row_with_its_name() {
    // A file-size limit (RLIMIT_FSIZE, as a quota or a full disk would) of 6000 bytes: the
    // time series reaches it after about 50 of the 201 rows; the run must stop there, not
    // compute to the end, and say which file.
    let dir = temp_dir("fsize");
    let path = catenary(&dir, 20.0, "", &["snapshot_interval"]);
    let out = dir.join("out");
    let mut cmd = hawser();
    cmd.args(["run", path.to_str().unwrap(), "--quiet", "--out"])
        .arg(&out);
    unsafe {
        cmd.pre_exec(|| {
            // Over the limit a write fails with EFBIG instead of the process being killed.
            libc::signal(libc::SIGXFSZ, libc::SIG_IGN);
            let limit = libc::rlimit {
                rlim_cur: 6000,
                rlim_max: 6000,
            };
            if libc::setrlimit(libc::RLIMIT_FSIZE, &limit) != 0 {
                return Err(std::io::Error::last_os_error());
            }
            Ok(())
        });
    }
    let o = cmd.output().unwrap();
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{stderr}");
    let ts = out.join("timeseries.csv");
    assert!(
        stderr.contains(&format!("cannot write {}", ts.display())),
        "the message names the file:\n{stderr}"
    );
    assert!(stderr.contains("File too large"), "{stderr}");
    // Stopped at the row that failed (rows are about 100 bytes): whole rows up to the limit,
    // far from the end.
    let table = read_table(&ts).unwrap();
    let last = *table.column("time").unwrap().last().unwrap();
    let len = std::fs::metadata(&ts).unwrap().len();
    assert!(!table.torn && last < 10.0, "stopped at t = {last}");
    assert!(len <= 6000 && len > 6000 - 150, "{len} bytes");
    // The status (a small file) says the run stopped, with the file's error; so does the
    // summary where it fits under the limit (with the design statistics and strength of every
    // line it takes about 6.3 kB here, over the 6000 bytes, so it may not be written).
    for name in ["status.json", "summary.json"] {
        if name == "summary.json" && !out.join(name).exists() {
            continue;
        }
        let v = json(&out.join(name));
        assert_eq!(v["complete"], false, "{name}");
        let e = v["error"].as_str().unwrap();
        assert!(
            e.contains("timeseries.csv") && e.contains("File too large"),
            "{name}: {e}"
        );
        assert!(v["end_time"].as_f64().unwrap() <= last, "{name}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// The rows of `a` and `b` (tables of the same columns) agree bit for bit on `b`'s rows.
fn assert_prefix(a: &hawser_io::results::Table, b: &hawser_io::results::Table, what: &str) {
    assert_eq!(a.names, b.names, "{what}: columns");
    assert!(b.rows() <= a.rows(), "{what}: more rows than the whole run");
    for (x, y) in a.columns.iter().zip(&b.columns) {
        for (r, (p, q)) in x.iter().zip(y).enumerate() {
            assert_eq!(p.to_bits(), q.to_bits(), "{what}: row {r} differs");
        }
    }
}

#[test]
fn a_run_killed_at_any_moment_leaves_whole_rows_of_the_right_numbers() {
    // Long rows (80 extra channels, about 2 kB a row) and snapshots with ParaView files; six
    // runs killed by SIGKILL after different numbers of rows. What every reader gets back is
    // a prefix of the uninterrupted run's rows, bit for bit; a last line without its newline
    // would only come from a kill inside a write call, and is dropped by the reader.
    let dir = temp_dir("kill");
    let channels: Vec<String> = (0..80)
        .map(|k| format!("\"chain.node{k}.tension\""))
        .collect();
    let extra = format!(
        "snapshot_interval = 0.5\nchannels = [{}]",
        channels.join(", ")
    );
    let path = catenary(&dir, 4.0, &extra, &[]);
    let whole = dir.join("whole");
    let s = hawser()
        .args(["run", path.to_str().unwrap(), "--quiet", "--out"])
        .arg(&whole)
        .status()
        .unwrap();
    assert!(s.success());
    let reference = read_table(&whole.join("timeseries.csv")).unwrap();
    let reference_snapshot = read_table(&whole.join("snapshots/chain.csv")).unwrap();
    let total = reference.rows();
    let mut torn = 0;
    for (i, after) in [1, 3, 7, 12, 20, 31].into_iter().enumerate() {
        let out = dir.join(format!("killed{i}"));
        let mut child = hawser()
            .args(["run", path.to_str().unwrap(), "--quiet", "--out"])
            .arg(&out)
            .stderr(Stdio::null())
            .spawn()
            .unwrap();
        let ts = out.join("timeseries.csv");
        let start = Instant::now();
        while std::fs::read(&ts).map_or(0, |b| b.iter().filter(|&&c| c == b'\n').count()) <= after {
            assert!(child.try_wait().unwrap().is_none(), "ended before the kill");
            assert!(start.elapsed() < Duration::from_secs(300), "no progress");
            std::thread::sleep(Duration::from_millis(2));
        }
        unsafe { libc::kill(child.id() as i32, libc::SIGKILL) };
        child.wait().unwrap();
        let bytes = std::fs::read(&ts).unwrap();
        torn += usize::from(bytes.last() != Some(&b'\n'));
        let table = read_table(&ts).unwrap();
        assert!(table.rows() > after.min(total - 1) - 1, "rows lost");
        assert_prefix(&reference, &table, "timeseries.csv");
        assert_prefix(
            &reference_snapshot,
            &read_table(&out.join("snapshots/chain.csv")).unwrap(),
            "snapshot",
        );
        // The ParaView collection is whole and names only files that exist.
        let pvd = std::fs::read_to_string(out.join("vtk/run.pvd")).unwrap();
        assert!(pvd.ends_with("</Collection>\n</VTKFile>\n"), "{pvd}");
        for file in pvd.split("file=\"").skip(1) {
            let name = &file[..file.find('"').unwrap()];
            assert!(
                out.join("vtk").join(name).exists(),
                "{name} listed, missing"
            );
        }
        assert_eq!(json(&out.join("status.json"))["state"], "running");
    }
    // Each row is one write call: a kill inside one is a matter of microseconds in seconds.
    assert_eq!(torn, 0, "torn last lines (dropped by the reader)");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_refused_or_failed_run_leaves_no_earlier_run_saying_complete() {
    let dir = temp_dir("overwrite");
    let good = catenary(&dir, 0.3, "", &[]);
    let out = dir.join("out");
    let run = |scenario: &Path, extra: &[&str]| {
        hawser()
            .args([
                "run",
                scenario.to_str().unwrap(),
                "--quiet",
                "--overwrite",
                "--out",
            ])
            .arg(&out)
            .args(extra)
            .output()
            .unwrap()
    };
    let complete =
        || out.join("summary.json").exists() && json(&out.join("summary.json"))["complete"] == true;
    assert!(run(&good, &[]).status.success());
    assert!(complete());
    std::fs::write(out.join("notes.txt"), "mine").unwrap();
    // Refused input: nothing of the earlier run is left to be taken for this one's.
    let bad = dir.join("bad.toml");
    std::fs::write(
        &bad,
        std::fs::read_to_string(&good)
            .unwrap()
            .replace("duration = 0.3", "duration = -1.0"),
    )
    .unwrap();
    let o = run(&bad, &[]);
    assert_eq!(o.status.code(), Some(2));
    assert!(!complete() && !out.join("status.json").exists());
    assert!(
        out.join("notes.txt").exists(),
        "the user's own file was removed"
    );
    // Refused arguments, the same.
    assert!(run(&good, &[]).status.success());
    let o = run(&good, &["--checkpoint-every=-1"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(!complete() && !out.join("timeseries.csv").exists());
    // A run that fails (diverges) says so in its own summary.
    assert!(run(&good, &[]).status.success());
    let unstable = dir.join("unstable.toml");
    std::fs::write(
        &unstable,
        std::fs::read_to_string(root().join("examples/snapping_cable_127.toml"))
            .unwrap()
            .replace("time_step = \"auto\"", "time_step = 0.01"),
    )
    .unwrap();
    let o = run(&unstable, &["--allow-unstable-step"]);
    assert_eq!(o.status.code(), Some(1));
    assert!(!complete());
    assert_eq!(json(&out.join("status.json"))["state"], "stopped");
    let _ = std::fs::remove_dir_all(&dir);
}
