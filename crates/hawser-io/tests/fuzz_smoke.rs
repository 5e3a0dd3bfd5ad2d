//! The smoke run of the fuzz targets (docs/fuzzing.md): the seeds (the bundled examples and
//! MoorDyn decks), the inputs the fuzzers found defects with (`fuzz/regressions/`), and a
//! bounded proptest run of byte-level mutations of the seeds, through the same properties
//! the cargo-fuzz targets check ([`hawser_io::fuzzing`]). About 10 s in release; the long
//! campaign is `cargo fuzz run`.

use hawser_io::fuzzing::{deck_bytes, scenario_bytes};
use proptest::prelude::*;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// The files of `dirs` (not recursive), sorted.
fn files(dirs: &[PathBuf]) -> Vec<Vec<u8>> {
    let mut paths: Vec<PathBuf> = dirs
        .iter()
        .filter(|d| d.is_dir())
        .flat_map(|d| std::fs::read_dir(d).unwrap().map(|e| e.unwrap().path()))
        .filter(|p| p.is_file())
        .collect();
    paths.sort();
    paths.iter().map(|p| std::fs::read(p).unwrap()).collect()
}

fn scenario_seeds() -> &'static [Vec<u8>] {
    static SEEDS: OnceLock<Vec<Vec<u8>>> = OnceLock::new();
    SEEDS.get_or_init(|| files(&[root().join("examples")]))
}

fn deck_seeds() -> &'static [Vec<u8>] {
    static SEEDS: OnceLock<Vec<Vec<u8>>> = OnceLock::new();
    SEEDS.get_or_init(|| {
        files(&[
            root().join("tests/data/moordyn"),
            root().join("crates/hawser-io/tests/moordyn_corpus"),
        ])
    })
}

/// The seed corpus and the defects found: each passes its target's properties.
#[test]
fn seeds_and_regressions_pass() {
    let scenarios = scenario_seeds();
    let decks = deck_seeds();
    assert!(scenarios.len() >= 20 && decks.len() >= 15);
    for s in scenarios {
        scenario_bytes(s);
    }
    for d in decks {
        deck_bytes(d);
    }
    for s in files(&[root().join("fuzz/regressions/scenario")]) {
        scenario_bytes(&s);
    }
    for d in files(&[root().join("fuzz/regressions/deck")]) {
        deck_bytes(&d);
    }
}

/// A byte-level edit, as libFuzzer's mutators make them.
#[derive(Clone, Debug)]
enum Edit {
    /// Overwrite the byte at a position.
    Set(usize, u8),
    /// Insert bytes at a position.
    Insert(usize, Vec<u8>),
    /// Delete a range.
    Delete(usize, usize),
    /// Copy a range over another place.
    Copy(usize, usize, usize),
}

fn edit() -> impl Strategy<Value = Edit> {
    let words = prop_oneof![
        Just(b"1e300".to_vec()),
        Just(b"-1e300".to_vec()),
        Just(b"5e-324".to_vec()),
        Just(b"nan".to_vec()),
        Just(b"\n[[points]]\n".to_vec()),
        Just(b"\n---- LINES ----\n".to_vec()),
        Just(b" = ".to_vec()),
        Just(b"\x07\x1b\x00".to_vec()),
        prop::collection::vec(any::<u8>(), 1..8),
    ];
    prop_oneof![
        (any::<usize>(), any::<u8>()).prop_map(|(a, b)| Edit::Set(a, b)),
        (any::<usize>(), words).prop_map(|(a, w)| Edit::Insert(a, w)),
        (any::<usize>(), 0usize..64).prop_map(|(a, l)| Edit::Delete(a, l)),
        (any::<usize>(), any::<usize>(), 0usize..64).prop_map(|(a, b, l)| Edit::Copy(a, b, l)),
    ]
}

fn apply(mut s: Vec<u8>, e: &Edit) -> Vec<u8> {
    let at = |a: usize, s: &Vec<u8>| a % (s.len() + 1);
    match e {
        Edit::Set(a, b) if !s.is_empty() => {
            let i = a % s.len();
            s[i] = *b;
        }
        Edit::Insert(a, w) => {
            let i = at(*a, &s);
            s.splice(i..i, w.iter().copied());
        }
        Edit::Delete(a, l) => {
            let i = at(*a, &s);
            let j = (i + l).min(s.len());
            s.drain(i..j);
        }
        Edit::Copy(a, b, l) => {
            let (i, j) = (at(*a, &s), at(*b, &s));
            let part: Vec<u8> = s[i..(i + l).min(s.len())].to_vec();
            let end = (j + part.len()).min(s.len());
            s.splice(j..end, part);
        }
        _ => {}
    }
    s
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2048, ..ProptestConfig::default() })]

    #[test]
    fn mutated_scenarios(k in any::<usize>(), edits in prop::collection::vec(edit(), 1..8)) {
        let seeds = scenario_seeds();
        let input = edits.iter().fold(seeds[k % seeds.len()].clone(), apply);
        scenario_bytes(&input);
    }

    #[test]
    fn mutated_decks(k in any::<usize>(), edits in prop::collection::vec(edit(), 1..8)) {
        let seeds = deck_seeds();
        let input = edits.iter().fold(seeds[k % seeds.len()].clone(), apply);
        deck_bytes(&input);
    }
}
