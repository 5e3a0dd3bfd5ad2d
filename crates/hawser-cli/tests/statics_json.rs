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
