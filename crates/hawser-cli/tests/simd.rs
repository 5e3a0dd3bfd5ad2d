//! The `fe` element loop's instruction-set versions (`hawser::math::wide_simd_fn`: AVX-512
//! in batches of eight elements for lines of 16 elements or more, AVX2 and SSE2 in batches of
//! four) give the same bits: each scenario is run with the default dispatch (the widest the
//! processor has), with `HAWSER_SIMD=avx2` and with `HAWSER_SIMD=baseline`, and the outputs
//! must match byte for byte (the CSV writes every value in its shortest exact form). On a
//! processor without AVX-512 (or AVX2) the default run repeats a narrower one.
//!
//! The scenarios cover every path of the loop: the OC3 MoorDyn deck (lumped mass, RK4,
//! lines of 20 elements on and off the seabed in fluid at rest, so both the lane-by-lane node
//! sums and the per-element ones, in batches of eight with AVX-512, the last one part full),
//! the README example (136 elements, consistent mass, generalized-α, a current), waves (10
//! elements, batches of four), and drag loading functions.

use std::path::{Path, PathBuf};
use std::process::Command;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// Runs `hawser run` on `args` into `out`, with `HAWSER_SIMD` set to `simd` if given.
fn run(args: &[&str], out: &Path, simd: Option<&str>) {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_hawser"));
    cmd.current_dir(root())
        .arg("run")
        .args(args)
        .args(["--quiet", "--overwrite", "--out"])
        .arg(out);
    match simd {
        Some(level) => cmd.env("HAWSER_SIMD", level),
        None => cmd.env_remove("HAWSER_SIMD"),
    };
    let result = cmd.output().expect("run hawser");
    assert!(
        result.status.success(),
        "hawser run {args:?}: {}",
        String::from_utf8_lossy(&result.stderr)
    );
}

#[test]
fn avx512_avx2_and_sse2_element_loops_give_the_same_bits() {
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
                let widest = dir.join(name).join("widest");
                run(args, &widest, None);
                for level in ["avx2", "baseline"] {
                    let narrower = dir.join(name).join(level);
                    run(args, &narrower, Some(level));
                    for file in ["timeseries.csv", "final_state.json"] {
                        let a = std::fs::read(widest.join(file)).expect("read the default run");
                        let b = std::fs::read(narrower.join(file)).expect("read the capped run");
                        assert!(a.len() > 100, "{name}: {file} is nearly empty");
                        assert!(
                            a == b,
                            "{name}: {file} differs between the widest instruction set and \
                             HAWSER_SIMD={level}"
                        );
                    }
                }
            });
        }
    });
    let _ = std::fs::remove_dir_all(&dir);
}
