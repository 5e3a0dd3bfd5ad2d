//! `hawser sweep`: a case writes the files of `hawser run` on the scenario with its overrides,
//! byte for byte, on any number of threads; the summary table holds one row per case with its
//! overrides and the extremes of its `summary.json`; shards split the table; a bad table is
//! refused before any case runs; a failed case is a row with its error; Ctrl-C stops the sweep
//! with a summary of what ran.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// A chain from an anchor to a surging fairlead and a riser with a buoy: short and coarse, so
/// that each case runs in a fraction of a second.
const BASE: &str = r#"[simulation]
duration = 1.0
time_step = "auto"
output_interval = 0.1

[environment]
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
    let dir = std::env::temp_dir().join(format!("hawser-sweep-{}-{test}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("create the temporary directory");
    dir
}

fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, text).expect("write a test file");
    path
}

fn hawser(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_hawser"))
        .args(args)
        .output()
        .expect("run hawser")
}

fn stderr(out: &Output, dir: &Path) -> String {
    String::from_utf8_lossy(&out.stderr).replace(&dir.display().to_string(), "[TMP]")
}

/// `hawser sweep BASE CASES --out OUT --quiet EXTRA...`.
fn sweep(base: &Path, cases: &Path, out: &Path, extra: &[&str]) -> Output {
    let mut args = vec![
        "sweep",
        base.to_str().unwrap(),
        cases.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--quiet",
    ];
    args.extend_from_slice(extra);
    hawser(&args)
}

/// A summary table without quoted cells, as (header, rows of cells).
fn read_summary(path: &Path) -> (Vec<String>, Vec<Vec<String>>) {
    let text = std::fs::read_to_string(path).expect("the summary table");
    let mut lines = text
        .lines()
        .map(|l| l.split(',').map(str::to_string).collect());
    let header = lines.next().expect("a header");
    (header, lines.collect())
}

fn json(path: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(path).expect("a JSON file")).expect("JSON")
}

/// The files of a run folder (status.json left out: it names the scenario file; run.json,
/// what `hawser resume` needs, is not written by a sweep), by relative
/// path, with their bytes.
fn run_files(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut files = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                stack.push(p);
            } else if !["status.json", "run.json"]
                .contains(&p.file_name().unwrap().to_str().unwrap())
            {
                let rel = p.strip_prefix(dir).unwrap().display().to_string();
                files.push((rel, std::fs::read(&p).unwrap()));
            }
        }
    }
    files.sort();
    files
}

/// A case of a sweep on two threads writes what `hawser run` writes for a scenario file with
/// the case's values typed in (not through the override machinery), byte for byte: time
/// series (CSV and Parquet), summary, range graphs, final state, channels; and the summary
/// table of the sweep on one thread is the same, byte for byte.
#[test]
fn a_case_is_bit_identical_to_a_run_of_its_scenario() {
    let dir = temp_dir("identity");
    let base = write(&dir, "base.toml", BASE);
    let cases = write(
        &dir,
        "cases.csv",
        "name,lines.L1.length,points.fairlead.motion.amplitude,environment.current.velocity\n\
         base,,,\n\
         long,425.0,\"[3.0, 0.0, 1.0]\",\"[0.5, 0.1, 0.0]\"\n\
         short,418,,\n",
    );
    let (two, one) = (dir.join("two"), dir.join("one"));
    let out = sweep(&base, &cases, &two, &["--jobs", "2"]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out, &dir));
    let out = sweep(&base, &cases, &one, &["--jobs", "1"]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out, &dir));
    assert_eq!(
        std::fs::read(two.join("sweep_summary.csv")).unwrap(),
        std::fs::read(one.join("sweep_summary.csv")).unwrap()
    );
    let edited = [
        ("base", BASE.to_string()),
        (
            "long",
            BASE.replacen("length = 420.0", "length = 425.0", 1)
                .replacen(
                    "amplitude = [2.0, 0.0, 0.0]",
                    "amplitude = [3.0, 0.0, 1.0]",
                    1,
                )
                .replacen(
                    "velocity = [0.3, 0.0, 0.0]",
                    "velocity = [0.5, 0.1, 0.0]",
                    1,
                ),
        ),
        ("short", BASE.replacen("length = 420.0", "length = 418", 1)),
    ];
    for (name, text) in edited {
        let file = write(&dir, &format!("{name}.toml"), &text);
        let run = dir.join(format!("run_{name}"));
        let out = hawser(&[
            "run",
            file.to_str().unwrap(),
            "--out",
            run.to_str().unwrap(),
            "--quiet",
        ]);
        assert_eq!(out.status.code(), Some(0), "{}", stderr(&out, &dir));
        let (swept, ran) = (run_files(&two.join(name)), run_files(&run));
        let names = |f: &[(String, Vec<u8>)]| f.iter().map(|(n, _)| n.clone()).collect::<Vec<_>>();
        assert_eq!(names(&swept), names(&ran), "case {name}: the same files");
        assert!(names(&ran).contains(&"timeseries.csv".to_string()));
        for ((file, a), (_, b)) in swept.iter().zip(&ran) {
            assert!(a == b, "case {name}: {file} differs from hawser run's");
        }
    }
    // The cases differ from each other (the overrides reached the model).
    assert_ne!(
        std::fs::read(two.join("base/timeseries.csv")).unwrap(),
        std::fs::read(two.join("long/timeseries.csv")).unwrap()
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// One row per case in table order, with its name (given or case_000k), status, override
/// values as written, and every channel's min, max, mean and std and every line's largest
/// tension equal to the values in the case's summary.json (exactly: the numbers are written
/// in their shortest round-trip form). The Parquet table is written beside it.
#[test]
fn the_summary_table_holds_each_cases_overrides_and_extremes() {
    let dir = temp_dir("summary");
    let base = write(&dir, "base.toml", BASE);
    let cases = write(
        &dir,
        "cases.csv",
        "# fairlead depth and line length\n\
         points.fairlead.position.2,lines.L1.length\n\
         -10.0,420.0\n\
         -12.5,\n\
         ,422.5\n",
    );
    let out_dir = dir.join("out");
    let out = sweep(&base, &cases, &out_dir, &[]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out, &dir));
    assert!(out_dir.join("sweep_summary.parquet").exists());
    let (header, rows) = read_summary(&out_dir.join("sweep_summary.csv"));
    assert_eq!(
        header[..6],
        [
            "case",
            "status",
            "error",
            "end_time",
            "points.fairlead.position.2",
            "lines.L1.length"
        ]
    );
    assert_eq!(rows.len(), 3);
    let overrides = [["-10.0", "420.0"], ["-12.5", ""], ["", "422.5"]];
    let column = |name: &str| header.iter().position(|h| h == name);
    for (k, row) in rows.iter().enumerate() {
        let name = format!("case_{:04}", k + 1);
        assert_eq!(row.len(), header.len());
        assert_eq!(row[..4], [name.as_str(), "complete", "", "1.0"]);
        assert_eq!(row[4..6], overrides[k]);
        let summary = json(&out_dir.join(&name).join("summary.json"));
        let channels = summary["channels"].as_object().unwrap();
        assert!(channels.contains_key("L1.end_b.tension"), "{channels:?}");
        for (channel, s) in channels {
            for stat in ["min", "max", "mean", "std"] {
                let c = column(&format!("{channel}.{stat}")).expect("a column per statistic");
                let got: f64 = row[c].parse().unwrap();
                assert_eq!(got, s[stat].as_f64().unwrap(), "{name} {channel}.{stat}");
            }
        }
        for (line, l) in summary["lines"].as_object().unwrap() {
            let c = column(&format!("{line}.max_tension")).unwrap();
            let largest = l["strength"]["sections"]
                .as_array()
                .unwrap()
                .iter()
                .map(|s| s["max_tension"].as_f64().unwrap())
                .fold(f64::MIN, f64::max);
            assert_eq!(row[c].parse::<f64>().unwrap(), largest, "{name} {line}");
        }
    }
    // The overrides reached the cases: a longer line is slacker at the fairlead.
    let tension = |row: &Vec<String>| -> f64 {
        row[column("L1.end_b.tension.mean").unwrap()]
            .parse()
            .unwrap()
    };
    assert!(tension(&rows[2]) < tension(&rows[0]));
    let _ = std::fs::remove_dir_all(&dir);
}

/// `--shard I/N` runs the cases k with k mod N = I − 1 (k from 0 in table order) and writes
/// `sweep_summary.shard-I-of-N.csv`: the shards together hold every case once, with the
/// table's names.
#[test]
fn shards_cover_every_case_exactly_once() {
    let dir = temp_dir("shards");
    let base = write(&dir, "base.toml", BASE);
    let mut table = String::from("simulation.duration\n");
    for k in 0..5 {
        table += &format!("{}\n", 0.2 + 0.1 * k as f64);
    }
    let cases = write(&dir, "cases.csv", &table);
    let out_dir = dir.join("out");
    let mut seen = Vec::new();
    for (shard, expected) in [("1/2", vec![1, 3, 5]), ("2/2", vec![2, 4])] {
        let out = sweep(&base, &cases, &out_dir, &["--shard", shard]);
        assert_eq!(out.status.code(), Some(0), "{}", stderr(&out, &dir));
        let file = format!("sweep_summary.shard-{}-of-2.csv", &shard[..1]);
        let (_, rows) = read_summary(&out_dir.join(file));
        let names: Vec<String> = rows.iter().map(|r| r[0].clone()).collect();
        let want: Vec<String> = expected.iter().map(|k| format!("case_{k:04}")).collect();
        assert_eq!(names, want, "shard {shard}");
        seen.extend(names);
    }
    seen.sort();
    let all: Vec<String> = (1..=5).map(|k| format!("case_{k:04}")).collect();
    assert_eq!(seen, all);
    assert!(!out_dir.join("sweep_summary.csv").exists());
    for bad in ["0/2", "3/2", "1", "a/b"] {
        let out = sweep(&base, &cases, &dir.join("bad"), &["--shard", bad]);
        assert_eq!(out.status.code(), Some(2), "--shard {bad}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// A bad table (an unknown key, a value with a unit, a vector too short, a value out of
/// range, a row with too few cells) is refused with exit code 2 before any case runs: every
/// problem named at its line and cell, with the key, the value, the unit expected and a hint;
/// nothing is written.
#[test]
fn a_bad_table_is_refused_before_any_case_runs() {
    let dir = temp_dir("bad");
    let base = write(&dir, "base.toml", BASE);
    let cases = write(
        &dir,
        "cases.csv",
        "name,lines.L1.lenght,lines.L1.length,points.fairlead.motion.amplitude,environment.depth\n\
         fine,,,,\n\
         a,430.0,425 m,\"[1.0, 0.0]\",100.0\n\
         b,,,,-5\n",
    );
    let out_dir = dir.join("out");
    let out = sweep(&base, &cases, &out_dir, &[]);
    let err = stderr(&out, &dir);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(!out_dir.exists(), "nothing is written");
    insta::assert_snapshot!(err);
    // A TOML table: a case name that cannot name a folder, a row with too few cells in CSV.
    let toml = write(
        &dir,
        "cases.toml",
        "[[cases]]\nname = \"a/b\"\n\"lines.L1.length\" = 425.0\n\n[[cases]]\nname = \"c\"\nlines.L2.lenght = 41.0\n",
    );
    let out = sweep(&base, &toml, &out_dir, &[]);
    let err = stderr(&out, &dir);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("[TMP]/cases.toml:2:8"), "{err}");
    assert!(err.contains("`a/b`"), "{err}");
    let short = write(
        &dir,
        "short.csv",
        "lines.L1.length,environment.depth\n425.0\n",
    );
    let out = sweep(&base, &short, &out_dir, &[]);
    let err = stderr(&out, &dir);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("[TMP]/short.csv:2:1"), "{err}");
    assert!(err.contains("this row has 1 cells, the header 2"), "{err}");
    assert!(!out_dir.exists(), "nothing is written");
    let _ = std::fs::remove_dir_all(&dir);
}

/// A case that fails (here a time step 2.5 times the stability limit, accepted with
/// --allow-unstable-step, that diverges) does not stop the others: it is a row with status
/// `failed` and its error, without extremes; its folder keeps the results up to the
/// divergence, marked incomplete; the exit code is 1.
#[test]
fn a_failed_case_is_a_row_with_its_error() {
    let dir = temp_dir("failed");
    let base = write(&dir, "base.toml", BASE);
    let cases = write(
        &dir,
        "cases.csv",
        "name,simulation.time_step\nfine,\nunstable,0.05\nalso_fine,\"auto\"\n",
    );
    let out_dir = dir.join("out");
    let out = sweep(&base, &cases, &out_dir, &["--allow-unstable-step"]);
    let err = stderr(&out, &dir);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert!(err.contains("error: case `unstable` failed: "), "{err}");
    let text = std::fs::read_to_string(out_dir.join("sweep_summary.csv")).unwrap();
    let rows: Vec<&str> = text.lines().collect();
    assert_eq!(rows.len(), 4, "{text}");
    assert!(rows[1].starts_with("fine,complete,,1.0,"), "{}", rows[1]);
    assert!(
        rows[3].starts_with("also_fine,complete,,1.0,"),
        "{}",
        rows[3]
    );
    assert!(rows[2].starts_with("unstable,failed,"), "{}", rows[2]);
    assert!(rows[2].contains("diverged at t = "), "{}", rows[2]);
    // No extremes for the failed case: after its end time and override, only empty cells.
    let tail = rows[2].rsplit_once("0.05,").expect("its override").1;
    assert!(tail.chars().all(|c| c == ','), "{}", rows[2]);
    let status = json(&out_dir.join("unstable/status.json"));
    assert_eq!(status["complete"], false);
    assert_eq!(status["state"], "stopped");
    let _ = std::fs::remove_dir_all(&dir);
}

/// SIGINT stops the sweep: the cases going stop between two steps with their files marked
/// interrupted, the others are not started, the summary covers them all, and the exit code is
/// 130.
#[test]
fn sigint_stops_the_sweep_with_a_summary() {
    let dir = temp_dir("sigint");
    let base = write(
        &dir,
        "base.toml",
        &BASE.replacen("duration = 1.0", "duration = 600.0", 1),
    );
    let cases = write(&dir, "cases.csv", "name\na\nb\nc\nd\n");
    let out_dir = dir.join("out");
    let child = Command::new(env!("CARGO_BIN_EXE_hawser"))
        .args([
            "sweep",
            base.to_str().unwrap(),
            cases.to_str().unwrap(),
            "--out",
            out_dir.to_str().unwrap(),
            "--quiet",
            "--jobs",
            "2",
        ])
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    // Wait until a case has written rows.
    let started = std::time::Instant::now();
    while !["a", "b", "c", "d"].iter().any(|c| {
        std::fs::read_to_string(out_dir.join(c).join("timeseries.csv"))
            .is_ok_and(|t| t.lines().count() > 3)
    }) {
        assert!(started.elapsed().as_secs() < 120, "no case started");
        std::thread::sleep(std::time::Duration::from_millis(50));
    }
    unsafe { libc::kill(child.id() as i32, libc::SIGINT) };
    let out = child.wait_with_output().unwrap();
    let err = stderr(&out, &dir);
    assert_eq!(out.status.code(), Some(130), "{err}");
    let text = std::fs::read_to_string(out_dir.join("sweep_summary.csv")).unwrap();
    let rows: Vec<Vec<&str>> = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').collect())
        .collect();
    assert_eq!(rows.len(), 4, "{text}");
    let interrupted: Vec<&str> = rows
        .iter()
        .filter(|r| r[1] == "interrupted")
        .map(|r| r[0])
        .collect();
    assert!(!interrupted.is_empty(), "{text}");
    assert!(
        rows.iter()
            .all(|r| r[1] == "interrupted" || r[1] == "not_run"),
        "{text}"
    );
    for c in interrupted {
        let status = json(&out_dir.join(c).join("status.json"));
        assert_eq!(status["state"], "interrupted", "{c}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// `--duration` sets every case's duration as it sets a run's; a `simulation.duration` column
/// wins over it.
#[test]
fn duration_sets_every_case_unless_the_table_does() {
    let dir = temp_dir("duration");
    let base = write(&dir, "base.toml", BASE);
    let cases = write(
        &dir,
        "cases.csv",
        "name,simulation.duration\nflag,\nown,0.3\n",
    );
    let out_dir = dir.join("out");
    let out = sweep(&base, &cases, &out_dir, &["--duration", "0.5"]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out, &dir));
    let (_, rows) = read_summary(&out_dir.join("sweep_summary.csv"));
    assert_eq!(rows[0][..4], ["flag", "complete", "", "0.5"]);
    assert_eq!(rows[1][..4], ["own", "complete", "", "0.3"]);
    let _ = std::fs::remove_dir_all(&dir);
}
