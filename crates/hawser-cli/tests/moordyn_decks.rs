//! MoorDyn decks on the command line: a deck's `dtM` chosen for MoorDyn's integrator that is
//! above hawser's stability limit makes hawser take its automatic step, with a warning, rather
//! than refuse the deck (a hawser scenario with such a step is refused: tests/cli.rs).

use std::path::PathBuf;
use std::process::Command;

#[test]
fn deck_step_above_the_limit_falls_back_to_auto() {
    let dir = std::env::temp_dir().join(format!("hawser-decks-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..");
    let text = std::fs::read_to_string(root.join("tests/data/moordyn/oc3_lines.txt"))
        .unwrap()
        .replace("0.002         dtM", "0.05          dtM");
    let deck = dir.join("oc3_big_step.txt");
    std::fs::write(&deck, text).unwrap();
    let run = |args: &[&str]| {
        let out = Command::new(env!("CARGO_BIN_EXE_hawser"))
            .args(args)
            .output()
            .unwrap();
        (
            out.status.code(),
            String::from_utf8_lossy(&out.stderr).to_string(),
        )
    };
    let (code, stderr) = run(&["check", deck.to_str().unwrap()]);
    assert_eq!(code, Some(0), "{stderr}");
    assert!(
        stderr.contains("dtM = 0.05 s is above hawser's stability limit"),
        "{stderr}"
    );
    let out = dir.join("out");
    let (code, stderr) = run(&[
        "run",
        deck.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--duration",
        "1",
        "--quiet",
    ]);
    assert_eq!(code, Some(0), "{stderr}");
    assert!(stderr.contains("using time_step = \"auto\""), "{stderr}");
    let status = std::fs::read_to_string(out.join("status.json")).unwrap();
    assert!(status.contains("\"complete\": true"), "{status}");
    let _ = std::fs::remove_dir_all(&dir);
}
