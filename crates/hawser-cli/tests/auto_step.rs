//! `time_step = "auto"` must be stable: every bundled example, switched to the automatic step
//! (and to RK4 if it names no scheme), runs 10 s, or 20 000 steps when its stability limit is
//! so small that 10 s would take longer (the Koh cable with bending damping: 7e-7 s), to
//! completion, with the data files of
//! examples/data beside it. (An earlier stability estimate took the largest single-term rate
//! and let the OC3 example diverge within 0.2 s.)

use rayon::prelude::*;
use std::path::PathBuf;
use std::process::Command;

#[test]
fn every_example_runs_stably_with_the_automatic_step() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..");
    let dir = std::env::temp_dir().join(format!("hawser-auto-step-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    // Data files the examples refer to by relative paths (RAO tables, ...).
    let data = root.join("examples/data");
    if data.is_dir() {
        std::fs::create_dir_all(dir.join("data")).unwrap();
        for f in std::fs::read_dir(&data).unwrap() {
            let f = f.unwrap().path();
            std::fs::copy(&f, dir.join("data").join(f.file_name().unwrap())).unwrap();
        }
    }
    let mut examples: Vec<_> = std::fs::read_dir(root.join("examples"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    examples.sort();
    assert!(examples.len() >= 4, "{examples:?}");
    // The examples are independent runs: spread over the cores.
    examples.par_iter().for_each(|example| {
        let duration = run_length(example);
        let text = std::fs::read_to_string(example).unwrap();
        // The explicit automatic step is what is tested: an example that names no scheme
        // (the default `auto` would take generalized-α, which has no stability limit) runs RK4.
        let named = text.lines().any(|l| l.starts_with("scheme ="));
        let text: String = text
            .lines()
            .map(|l| {
                if l == "[simulation]" && !named {
                    "[simulation]\nscheme = \"rk4\"".to_string()
                } else if l.starts_with("time_step =") {
                    "time_step = \"auto\"".to_string()
                } else if l.starts_with("duration =") {
                    format!("duration = {duration}")
                } else if l.starts_with("start =") {
                    // The statistics window must start within the shortened run.
                    "start = 0.0".to_string()
                } else {
                    l.to_string()
                }
            })
            .collect::<Vec<_>>()
            .join("\n");
        let name = example.file_stem().unwrap().to_str().unwrap().to_string();
        let file = dir.join(format!("{name}.toml"));
        std::fs::write(&file, text).unwrap();
        let out = dir.join(&name);
        let result = Command::new(env!("CARGO_BIN_EXE_hawser"))
            .args([
                "run",
                file.to_str().unwrap(),
                "--out",
                out.to_str().unwrap(),
                "--quiet",
            ])
            .output()
            .unwrap();
        assert!(
            result.status.success(),
            "{name}: {}",
            String::from_utf8_lossy(&result.stderr)
        );
        let status = std::fs::read_to_string(out.join("status.json")).unwrap();
        assert!(status.contains("\"complete\": true"), "{name}: {status}");
    });
    let _ = std::fs::remove_dir_all(&dir);
}

/// 10 s, or 20 000 steps of the stability limit `hawser check` reports if that is shorter [s].
fn run_length(example: &std::path::Path) -> f64 {
    let out = Command::new(env!("CARGO_BIN_EXE_hawser"))
        .args(["check", example.to_str().unwrap()])
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    let limit: f64 = text
        .split("stable time step ")
        .nth(1)
        .and_then(|s| s.split_whitespace().next())
        .and_then(|s| s.parse().ok())
        .unwrap_or_else(|| panic!("{}: no stable step in `{text}`", example.display()));
    (2e4 * limit).min(10.0)
}
