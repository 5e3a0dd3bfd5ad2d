//! Behaviour guard for refactors: every bundled example, run for 20 output intervals (snapshots
//! every 5), writes the same `timeseries.csv`, `channels.json`, `summary.json`,
//! `line_ranges.json`, `final_state.json`, snapshot and ParaView files, bit for bit, as when the
//! hashes in `tests/data/example_hashes.txt` were recorded (`timeseries.parquet` is made from
//! the CSV; its own test reads it back).
//!
//! A change that is meant to change the numbers (new physics, a different summation order)
//! regenerates the file with `HAWSER_BLESS=1 cargo test --release -p hawser-io --test
//! example_hashes` and says so in its commit; a refactor must leave it unchanged.

mod common;

use rayon::prelude::*;
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// FNV-1a, 64 bits: stable across platforms and Rust versions.
fn fnv1a(bytes: &[u8]) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in bytes {
        h ^= *b as u64;
        h = h.wrapping_mul(0x0000_0100_0000_01b3);
    }
    h
}

/// The files a run wrote, in a fixed order, as (relative path, hash); the ParaView files of
/// `vtk/` as one entry (the hash of their names and contents in order).
fn hashes_of(dir: &Path) -> Vec<(String, u64)> {
    let mut files = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).expect("read the run directory") {
            let p = e.expect("entry").path();
            if p.is_dir() {
                stack.push(p);
            } else {
                files.push(p);
            }
        }
    }
    files.sort();
    files
        .into_iter()
        .filter(|p| {
            let name = p.file_name().and_then(|n| n.to_str()).unwrap_or("");
            // status.json names the scenario path; summary.json and the rest are the results.
            name != "status.json"
        })
        .map(|p| {
            let rel = p
                .strip_prefix(dir)
                .expect("inside")
                .to_string_lossy()
                .replace('\\', "/");
            (rel, std::fs::read(&p).expect("read a result file"))
        })
        .fold(Vec::new(), |mut hashes, (rel, bytes)| {
            match rel.strip_prefix("vtk/") {
                Some(name) => {
                    // Sorted: the files of vtk/ come one after the other.
                    if hashes.last().is_none_or(|(r, _)| r != "vtk/") {
                        hashes.push(("vtk/".to_string(), Vec::new()));
                    }
                    let all = &mut hashes.last_mut().expect("pushed").1;
                    all.extend_from_slice(name.as_bytes());
                    all.extend_from_slice(&bytes);
                }
                None => hashes.push((rel, bytes)),
            }
            hashes
        })
        .into_iter()
        .map(|(rel, bytes)| (rel, fnv1a(&bytes)))
        .collect()
}

#[test]
fn every_example_writes_the_recorded_results() {
    let root = root();
    let mut examples: Vec<PathBuf> = std::fs::read_dir(root.join("examples"))
        .expect("examples/")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    examples.sort();
    // The examples are independent runs: spread over the cores, listed in their order.
    let lines: Vec<String> = examples
        .par_iter()
        .flat_map_iter(|path| {
            let name = path.file_stem().unwrap().to_string_lossy().to_string();
            let dir = std::env::temp_dir().join(format!(
                "hawser_example_hashes_{name}_{}",
                std::process::id()
            ));
            let _ = std::fs::remove_dir_all(&dir);
            common::run_example_briefly(path, &dir, 20, 5);
            let lines: Vec<String> = hashes_of(&dir)
                .into_iter()
                .map(|(file, h)| format!("{name} {file} {h:016x}"))
                .collect();
            let _ = std::fs::remove_dir_all(&dir);
            lines
        })
        .collect();
    let recorded = root.join("tests/data/example_hashes.txt");
    let text = lines.join("\n") + "\n";
    if std::env::var_os("HAWSER_BLESS").is_some() {
        std::fs::write(&recorded, &text).expect("write the hashes");
        return;
    }
    let expected = std::fs::read_to_string(&recorded).expect("tests/data/example_hashes.txt");
    let differing: Vec<_> = text
        .lines()
        .zip(expected.lines())
        .filter(|(a, b)| a != b)
        .collect();
    assert!(
        differing.is_empty() && text.lines().count() == expected.lines().count(),
        "the examples' results changed ({} of {} files differ, first: {:?}); a refactor must \
         not change them (see this file's doc to regenerate after an intended change)",
        differing.len(),
        expected.lines().count(),
        differing.first()
    );
}
