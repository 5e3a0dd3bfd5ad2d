//! The committed JSON Schema (docs/scenario.schema.json) matches the scenario types.

use std::path::Path;

#[test]
fn committed_schema_is_up_to_date() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/scenario.schema.json");
    let committed = std::fs::read_to_string(&path).unwrap_or_else(|e| {
        panic!(
            "cannot read {}: {e}\nregenerate it from the workspace root with\n    \
             cargo run -q -p hawser-cli -- schema > docs/scenario.schema.json",
            path.display()
        )
    });
    let generated = hawser_io::scenario::json_schema();
    let normalise = |s: &str| s.replace("\r\n", "\n").trim_end().to_string();
    assert!(
        normalise(&committed) == normalise(&generated),
        "docs/scenario.schema.json is out of date with the scenario types \
         (crates/hawser-io/src/scenario/schema.rs).\nRegenerate it from the workspace root with\n    \
         cargo run -q -p hawser-cli -- schema > docs/scenario.schema.json\nand commit it \
         (update docs/scenario.md too if keys changed)."
    );
}
