//! `hawser validate --quick`: the verification suite's CI subset through the binary — every
//! case runs (or says why it cannot), nothing fails, the report and its plots are written;
//! with `--scheme rk4,generalized-alpha` the cases that step in time run with both schemes.

use hawser::verification::CASES;
use hawser_io::verification_report::COLUMNS;
use std::process::Command;

#[test]
fn quick_suite_passes_and_writes_the_report() {
    let dir = std::env::temp_dir().join(format!("hawser_validate_{}", std::process::id()));
    let report = dir.join("verification").join("report.md");
    let out = Command::new(env!("CARGO_BIN_EXE_hawser"))
        .args([
            "validate",
            "--quick",
            "--scheme",
            "rk4,generalized-alpha",
            "--report",
        ])
        .arg(&report)
        .output()
        .expect("hawser runs");
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        out.status.success(),
        "exit {:?}\n{stdout}\n{stderr}",
        out.status
    );
    // One row per case and formulation, with the table's columns.
    assert!(stdout.starts_with("case"), "{stdout}");
    let header = stdout.lines().next().unwrap();
    for column in COLUMNS {
        assert!(header.contains(column), "{header}");
    }
    for case in CASES.iter().map(|c| c.name) {
        for formulation in ["fe", "hermite", "dg"] {
            assert!(
                stdout
                    .lines()
                    .any(|l| l.starts_with(case) && l.contains(&format!(" {formulation} "))),
                "no row for {case} with {formulation}:\n{stdout}"
            );
        }
    }
    // fe runs the analytic cases it supports: they pass; bending is not available to it.
    let fe_passes = stdout
        .lines()
        .filter(|l| l.contains(" fe ") && l.ends_with("pass"))
        .count();
    assert!(fe_passes >= 25, "{fe_passes} passing fe rows:\n{stdout}");
    assert!(
        stdout
            .lines()
            .any(|l| l.starts_with("beam_bending") && l.contains(" fe ") && l.contains("n/a")),
        "{stdout}"
    );
    assert!(!stdout.contains("FAIL"), "{stdout}");
    // The cases that step in time ran with generalized-α too: they pass for fe and hermite,
    // and dg (explicit only) says so; the statics cases ran once.
    for case in CASES.iter().filter(|c| c.steps_in_time).map(|c| c.name) {
        for formulation in ["fe", "hermite"] {
            let label = format!(" {formulation} (generalized-alpha) ");
            let rows: Vec<&str> = stdout
                .lines()
                .filter(|l| l.starts_with(case) && l.contains(&label))
                .collect();
            assert!(
                !rows.is_empty(),
                "no generalized-α row for {case}, {formulation}"
            );
            assert!(
                rows.iter()
                    .all(|l| l.ends_with("pass") || l.contains("n/a")),
                "{rows:#?}"
            );
        }
        assert!(
            stdout.lines().any(|l| l.starts_with(case)
                && l.contains(" dg (generalized-alpha) ")
                && l.contains("n/a: dg lines step explicitly")),
            "{stdout}"
        );
    }
    for case in CASES.iter().filter(|c| !c.steps_in_time).map(|c| c.name) {
        assert!(
            !stdout
                .lines()
                .any(|l| l.starts_with(case) && l.contains("generalized-alpha")),
            "{case} does not step in time:\n{stdout}"
        );
    }
    // The report: the same table in markdown, and the plots it links.
    let md = std::fs::read_to_string(&report).expect("report written");
    assert!(md.contains("| case | formulation | quantity |"), "{md}");
    assert!(md.contains("| fe (generalized-alpha) |"), "{md}");
    let images: Vec<&str> = md
        .lines()
        .filter_map(|l| l.split("](img/").nth(1))
        .map(|rest| rest.trim_end_matches(')'))
        .collect();
    assert!(images.len() >= 5, "{md}");
    for img in images {
        let svg = std::fs::read_to_string(report.parent().unwrap().join("img").join(img))
            .expect("plot written");
        assert!(svg.starts_with("<svg"), "{img}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn an_unknown_formulation_is_refused_with_a_non_zero_exit() {
    let out = Command::new(env!("CARGO_BIN_EXE_hawser"))
        .args(["validate", "--quick", "--no-report", "--formulation", "fem"])
        .output()
        .expect("hawser runs");
    assert!(!out.status.success());
    assert!(
        String::from_utf8_lossy(&out.stderr).contains("unknown formulation `fem`"),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}
