//! `hawser plot DIR`: the figures and report.html of a finished run and of a run still going,
//! and its errors. The run: the first 120 s of the towed body's 270° turn (two line sections
//! with breaking loads, a free and a prescribed body, snapshots), about 1 s in release.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn hawser(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_hawser"))
        .args(args)
        .output()
        .expect("run hawser")
}

fn temp_dir(test: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("hawser-plot-{}-{test}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Runs the shortened turn into `dir/out`.
fn run(dir: &Path) -> PathBuf {
    let text = std::fs::read_to_string(root().join("examples/turn_270_body.toml"))
        .unwrap()
        .replace(
            "duration = 1000.0",
            "duration = 120.0\nsnapshot_interval = 10.0",
        )
        .replace(
            "axial_stiffness = 2.625e7\n",
            "axial_stiffness = 2.625e7\nminimum_breaking_load = 4.0e5\n",
        )
        .replacen(
            "minimum_breaking_load = 4.0e5\n",
            "minimum_breaking_load = 4.0e5\ndesign_safety_factor = 2.0\n",
            1,
        );
    let file = dir.join("turn.toml");
    std::fs::write(&file, text).unwrap();
    let out = dir.join("out");
    let o = hawser(&[
        "run",
        file.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--quiet",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    out
}

fn assert_figure(out: &Path, stem: &str) {
    let png = std::fs::read(out.join("plots").join(format!("{stem}.png")))
        .unwrap_or_else(|e| panic!("{stem}.png: {e}"));
    assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n", "{stem}.png is a PNG");
    assert!(png.len() > 10_000, "{stem}.png has {} bytes", png.len());
    let svg = std::fs::read_to_string(out.join("plots").join(format!("{stem}.svg"))).unwrap();
    assert!(
        svg.contains("<svg") && svg.trim_end().ends_with("</svg>"),
        "{stem}.svg"
    );
    assert!(svg.contains("<text"), "{stem}.svg has its text");
}

#[test]
fn plot_a_finished_and_a_running_run() {
    let dir = temp_dir("runs");
    let out = run(&dir);
    let o = hawser(&[
        "plot",
        out.to_str().unwrap(),
        "--spectrum",
        "tow.end_a.tension",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let stems = [
        "end_tensions",
        "range_tow",
        "shapes_tow",
        "motions_ship",
        "motions_body",
        "spectrum_tow.end_a.tension",
    ];
    for stem in stems {
        assert_figure(&out, stem);
    }
    let html = std::fs::read_to_string(out.join("report.html")).unwrap();
    assert!(!html.contains("<script"), "no scripts");
    for stem in stems {
        assert!(
            html.contains(&format!("src=\"plots/{stem}.png\"")),
            "{stem} in the report"
        );
        assert!(
            html.contains(&format!("href=\"plots/{stem}.svg\"")),
            "{stem} SVG link"
        );
    }
    // Line strength for both sections, from summary.json; statistics for every channel.
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    let sections = summary["lines"]["tow"]["strength"]["sections"]
        .as_array()
        .unwrap();
    assert_eq!(sections.len(), 2);
    assert_eq!(sections[0]["design_safety_factor"].as_f64(), Some(2.0));
    assert_eq!(sections[1]["design_safety_factor"].as_f64(), None);
    assert!(html.contains("<h2>Line strength</h2>") && html.contains("<td>bare</td>"));
    for name in summary["channels"].as_object().unwrap().keys() {
        assert!(
            html.contains(&format!("<td>{name}</td>")),
            "{name} in the statistics"
        );
    }
    assert!(html.contains("finished"));

    // The same run as if it were still going: no summary or range graphs yet, a row half
    // written. The range graph then comes from the snapshots.
    let going = dir.join("going");
    std::fs::create_dir_all(going.join("snapshots")).unwrap();
    for f in ["timeseries.csv", "channels.json", "run.json"] {
        std::fs::copy(out.join(f), going.join(f)).unwrap();
    }
    std::fs::copy(
        out.join("snapshots/tow.csv"),
        going.join("snapshots/tow.csv"),
    )
    .unwrap();
    let mut ts = std::fs::read_to_string(going.join("timeseries.csv")).unwrap();
    ts += "121.0,5";
    std::fs::write(going.join("timeseries.csv"), ts).unwrap();
    std::fs::write(
        going.join("status.json"),
        r#"{"complete": false, "state": "running", "scenario": "turn.toml"}"#,
    )
    .unwrap();
    let o = hawser(&["plot", going.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_figure(&going, "range_tow");
    let html = std::fs::read_to_string(going.join("report.html")).unwrap();
    assert!(html.contains("still going") && html.contains("snapshots (the run has not finished"));
    assert!(!html.contains("<h2>Line strength</h2>"));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn plot_errors() {
    let dir = temp_dir("errors");
    let o = hawser(&["plot", dir.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("has no timeseries.csv"), "{err}");
    // A folder of result format 1 (units in the column names) is refused, its version named.
    std::fs::write(
        dir.join("timeseries.csv"),
        "time [s],a.end_a.tension [N]\n0,1\n0.1,2\n",
    )
    .unwrap();
    let o = hawser(&["plot", dir.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("format_version 1"), "{err}");
    std::fs::write(
        dir.join("timeseries.csv"),
        "time,a.end_a.tension\n0.0,1.0\n0.1,2.0\n",
    )
    .unwrap();
    std::fs::write(
        dir.join("channels.json"),
        r#"{"format_version": 2, "timeseries": {"time": "s", "a.end_a.tension": "N"}}"#,
    )
    .unwrap();
    let o = hawser(&[
        "plot",
        dir.to_str().unwrap(),
        "--spectrum",
        "a.end_b.tension",
    ]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("--spectrum a.end_b.tension: no such channel")
            && err.contains("a.end_a.tension"),
        "{err}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}
