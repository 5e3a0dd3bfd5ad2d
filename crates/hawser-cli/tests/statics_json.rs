//! `hawser statics --json`: the documented shape, and tensions equal to the hand calculation
//! for a vertical cable carrying a sphere (weights and buoyancies only).

use std::path::PathBuf;
use std::process::Command;

#[test]
fn statics_json_has_the_documented_shape_and_the_hand_calculated_tensions() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..");
    let out = Command::new(env!("CARGO_BIN_EXE_hawser"))
        .args([
            "statics",
            root.join("examples/snapping_cable_127.toml")
                .to_str()
                .unwrap(),
            "--json",
        ])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let line = &v["lines"]["cable"];
    let positions = line["positions"].as_array().unwrap();
    let tension = line["tension"].as_array().unwrap();
    assert_eq!(positions.len(), 6, "5 elements give 6 nodes");
    assert_eq!(tension.len(), 6);
    assert_eq!(positions[0].as_array().unwrap().len(), 3);
    for end in ["end_a", "end_b"] {
        assert!(line[end]["tension"].is_f64(), "{end}");
        assert_eq!(line[end]["force"].as_array().unwrap().len(), 3, "{end}");
    }
    assert_eq!(
        v["points"]["sphere"]["position"].as_array().unwrap().len(),
        3
    );
    // Hand calculation (fresh water, g = 9.80665): the sphere's wet weight hangs on end B, the
    // cable's wet weight is added at end A. Tolerance 1e-9 relative: statics converges to
    // 1e-9 of the weight scale and the rest is exact arithmetic.
    let g = 9.80665;
    let sphere = (12.2 - 1000.0 * 0.004_393_0) * g;
    let cable = (0.0112 - 1000.0 * std::f64::consts::PI * 0.0016f64.powi(2) / 4.0) * 18.9 * g;
    let tb = line["end_b"]["tension"].as_f64().unwrap();
    let ta = line["end_a"]["tension"].as_f64().unwrap();
    assert!(
        (tb - sphere).abs() < 1e-9 * sphere,
        "end B {tb} vs {sphere}"
    );
    assert!(
        (ta - (sphere + cable)).abs() < 1e-9 * ta,
        "end A {ta} vs {}",
        sphere + cable
    );
    // The end force on the support pulls it down along the cable.
    let fa = line["end_a"]["force"].as_array().unwrap();
    assert!((fa[2].as_f64().unwrap() + ta).abs() < 1e-9 * ta);
}

/// The strength check of `hawser statics`: the snapping cable with a breaking load of 120 N
/// and a safety factor of 2 (permissible 60 N). Its static top tension, the sphere's and the
/// cable's wet weight (about 77.9 N), is above the permissible tension: a warning on standard
/// error naming the line, the section, the tension and the arc length; the table and the JSON
/// give utilisation T/MBL and design utilisation T/(MBL/SF) at s = 0, computed from the
/// JSON's own end tension (equal to the node tension at end A).
#[test]
fn statics_reports_utilisation_and_warns_above_the_permissible_tension() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..");
    let text = std::fs::read_to_string(root.join("examples/snapping_cable_127.toml"))
        .unwrap()
        .replace(
            "tangential_drag = 0.01\n",
            "tangential_drag = 0.01\nminimum_breaking_load = 120.0\ndesign_safety_factor = 2.0\n",
        );
    let dir = std::env::temp_dir().join(format!("hawser_statics_strength_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("cable.toml");
    std::fs::write(&file, text).unwrap();
    let run = |json: bool| {
        let mut args = vec!["statics", file.to_str().unwrap()];
        if json {
            args.push("--json");
        }
        let out = Command::new(env!("CARGO_BIN_EXE_hawser"))
            .args(args)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        (
            String::from_utf8(out.stdout).unwrap(),
            String::from_utf8(out.stderr).unwrap(),
        )
    };
    let (stdout, stderr) = run(false);
    assert!(
        stderr.contains("warning: line `cable` section 0 (steel-7x7-1.6mm): the static tension")
            && stderr
                .contains("at s = 0.000 m exceeds its permissible tension MBL/SF = 6.0000e1 N"),
        "{stderr}"
    );
    assert!(stdout.contains("T/(MBL/SF)"), "{stdout}");
    let (stdout, _) = run(true);
    let v: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    let ta = v["lines"]["cable"]["end_a"]["tension"].as_f64().unwrap();
    let worst = &v["lines"]["cable"]["strength"]["worst"];
    assert_eq!(worst["at"].as_f64(), Some(0.0));
    assert_eq!(worst["max_tension"].as_f64(), Some(ta));
    assert_eq!(worst["utilisation"].as_f64(), Some(ta / 120.0));
    assert_eq!(worst["design_utilisation"].as_f64(), Some(ta / 60.0));
    assert_eq!(worst["permissible_tension"].as_f64(), Some(60.0));
    let text = run(false).0;
    let line = text
        .lines()
        .find(|l| l.starts_with("cable") && l.contains("steel"))
        .expect("a strength row");
    assert!(line.contains(&format!("{:.4}", ta / 60.0)), "{line}");
    std::fs::remove_dir_all(&dir).unwrap();
}
