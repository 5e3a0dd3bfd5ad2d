//! The `fe` element loop's two instruction-set versions (`hawser::math::wide_simd_fn`: AVX2
//! where the processor has it, else SSE2) give the same bits: each scenario is run with the
//! default dispatch and with `HAWSER_SIMD=baseline`, and the outputs must match byte for
//! byte (the CSV writes every value in its shortest exact form).
//!
//! The scenarios cover every path of the loop: the OC3 MoorDyn deck (lumped mass, RK4,
//! elements on and off the seabed in fluid at rest, so both the lane-by-lane node sums and
//! the per-element ones), the README example (consistent mass, generalized-α, a current:
//! drag through `fluid_load`), waves, and drag loading functions.

use std::path::{Path, PathBuf};
use std::process::Command;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// Runs `hawser run` on `args` into `out`, with `HAWSER_SIMD=baseline` if `baseline`.
fn run(args: &[&str], out: &Path, baseline: bool) {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_hawser"));
    cmd.current_dir(root())
        .arg("run")
        .args(args)
        .args(["--quiet", "--overwrite", "--out"])
        .arg(out);
    if baseline {
        cmd.env("HAWSER_SIMD", "baseline");
    } else {
        cmd.env_remove("HAWSER_SIMD");
    }
    let result = cmd.output().expect("run hawser");
    assert!(
        result.status.success(),
        "hawser run {args:?}: {}",
        String::from_utf8_lossy(&result.stderr)
    );
}

#[test]
fn avx2_and_sse2_element_loops_give_the_same_bits() {
    let cases: [(&str, &[&str]); 4] = [
        (
            "oc3_deck",
            &["tests/data/moordyn/oc3_lines.txt", "--duration", "10"],
        ),
        ("readme_current", &["examples/catenary_mooring.toml"]),
        ("waves", &["examples/wave_buoy.toml"]),
        ("loading_functions", &["examples/turn_270.toml"]),
    ];
    let dir = std::env::temp_dir().join(format!("hawser-simd-{}", std::process::id()));
    std::thread::scope(|s| {
        for (name, args) in cases {
            let dir = &dir;
            s.spawn(move || {
                let (wide, base) = (dir.join(name).join("wide"), dir.join(name).join("base"));
                run(args, &wide, false);
                run(args, &base, true);
                for file in ["timeseries.csv", "final_state.json"] {
                    let a = std::fs::read(wide.join(file)).expect("read the default run");
                    let b = std::fs::read(base.join(file)).expect("read the baseline run");
                    assert!(a.len() > 100, "{name}: {file} is nearly empty");
                    assert!(a == b, "{name}: {file} differs between AVX2 and SSE2");
                }
            });
        }
    });
    let _ = std::fs::remove_dir_all(&dir);
}
