//! Fuzzing the MoorDyn deck reader: whatever the bytes, it returns a model or errors that
//! render with a position; it never panics. The corpus in `tests/moordyn_corpus/` keeps the
//! edge cases found so far (CRLF, NaN and infinities, huge counts, unicode, duplicated or
//! missing sections, truncated decks); proptest mutates the real decks around them and keeps
//! its own failures in `proptest-regressions/`.

use hawser_io::moordyn::{self, ConvertOptions};
use proptest::prelude::*;
use std::path::{Path, PathBuf};

fn data() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/data/moordyn")
}

/// Reads `text` as a deck and checks the outcome is well formed: errors carry a line for
/// every span they have and render; a model converts to TOML that reads back.
fn read_checked(text: &str) {
    let file = data().join("fuzzed.txt");
    match moordyn::parse(&file, text, &ConvertOptions::default()) {
        Ok(d) => {
            let toml = moordyn::to_toml(&d, &file);
            let back = hawser_io::scenario::parse(&data().join("fuzzed.toml"), &toml);
            assert!(back.is_ok(), "converted deck does not read back:\n{toml}");
        }
        Err(e) => {
            assert!(!e.diagnostics.is_empty());
            for d in &e.diagnostics {
                if d.span.is_some() {
                    assert!(d.line >= 1, "{d}");
                }
                assert!(!d.message.is_empty());
            }
            let _ = e.to_string();
        }
    }
}

#[test]
fn corpus_never_panics() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/moordyn_corpus");
    let mut n = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        let bytes = std::fs::read(&path).unwrap();
        read_checked(&String::from_utf8_lossy(&bytes));
        n += 1;
    }
    assert!(n >= 10, "corpus missing");
}

fn deck() -> impl Strategy<Value = String> {
    prop_oneof![
        Just(std::fs::read_to_string(data().join("oc3_lines.txt")).unwrap()),
        Just(std::fs::read_to_string(data().join("WD0050_Chain.txt")).unwrap()),
        Just(std::fs::read_to_string(data().join("buoy_oc3.txt")).unwrap()),
    ]
}

/// A word a deck could plausibly contain, or noise.
fn word() -> impl Strategy<Value = String> {
    prop_oneof![
        Just("---".to_string()),
        Just("----- LINES -----".to_string()),
        Just("--- POINTS ---".to_string()),
        Just("--- OPTIONS ---".to_string()),
        Just("--- OUTPUTS ---".to_string()),
        Just("--- BODIES ---".to_string()),
        Just("--- END ---".to_string()),
        Just("\t".to_string()),
        Just("\n".to_string()),
        Just("\r\n".to_string()),
        Just("-1e308".to_string()),
        Just("NaN".to_string()),
        Just("R1A".to_string()),
        Just("Body2".to_string()),
        Just("Body1".to_string()),
        Just("0|0|-2".to_string()),
        Just("|".to_string()),
        Just("CoupledPinned".to_string()),
        Just("B1RY".to_string()),
        Just("FairTen9".to_string()),
        Just("L1N99T".to_string()),
        Just("Currents".to_string()),
        (-1e6f64..1e6).prop_map(|x| x.to_string()),
        (0u32..100).prop_map(|x| x.to_string()),
        "[ -~]{0,12}",
        "\\PC{0,4}",
    ]
}

#[derive(Clone, Debug)]
enum Edit {
    /// Delete bytes [at, at + len) (clamped to char boundaries).
    Delete(usize, usize),
    /// Insert a word at a position.
    Insert(usize, String),
    /// Replace the k-th whitespace-separated word.
    Replace(usize, String),
    /// Duplicate line k.
    DuplicateLine(usize),
    /// Cut the deck at a position.
    Truncate(usize),
}

fn edit() -> impl Strategy<Value = Edit> {
    prop_oneof![
        (any::<usize>(), 0usize..40).prop_map(|(a, l)| Edit::Delete(a, l)),
        (any::<usize>(), word()).prop_map(|(a, w)| Edit::Insert(a, w)),
        (any::<usize>(), word()).prop_map(|(k, w)| Edit::Replace(k, w)),
        any::<usize>().prop_map(Edit::DuplicateLine),
        any::<usize>().prop_map(Edit::Truncate),
    ]
}

fn boundary(s: &str, at: usize) -> usize {
    let mut i = at % (s.len() + 1);
    while !s.is_char_boundary(i) {
        i -= 1;
    }
    i
}

fn apply(mut s: String, e: &Edit) -> String {
    match e {
        Edit::Delete(a, l) => {
            let a = boundary(&s, *a);
            let b = boundary(&s, (a + l).min(s.len()));
            s.replace_range(a..b.max(a), "");
            s
        }
        Edit::Insert(a, w) => {
            let a = boundary(&s, *a);
            s.insert_str(a, w);
            s
        }
        Edit::Replace(k, w) => {
            let words: Vec<(usize, &str)> = s
                .split_whitespace()
                .map(|x| (x.as_ptr() as usize - s.as_ptr() as usize, x))
                .collect();
            if words.is_empty() {
                return s;
            }
            let (at, old) = words[k % words.len()];
            let len = old.len();
            s.replace_range(at..at + len, w);
            s
        }
        Edit::DuplicateLine(k) => {
            let lines: Vec<&str> = s.lines().collect();
            if lines.is_empty() {
                return s;
            }
            let k = k % lines.len();
            let mut out: Vec<&str> = lines[..=k].to_vec();
            out.push(lines[k]);
            out.extend_from_slice(&lines[k + 1..]);
            out.join("\n")
        }
        Edit::Truncate(a) => {
            let a = boundary(&s, *a);
            s.truncate(a);
            s
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 384, ..ProptestConfig::default() })]

    #[test]
    fn mutated_decks_never_panic(d in deck(), edits in prop::collection::vec(edit(), 1..6)) {
        let text = edits.iter().fold(d, apply);
        read_checked(&text);
    }

    #[test]
    fn arbitrary_text_never_panics(words in prop::collection::vec(word(), 0..80)) {
        read_checked(&words.join(" "));
    }
}
