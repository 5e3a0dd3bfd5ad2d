//! `hawser convert` output always loads: over MoorDyn decks with arbitrary characters (control
//! characters included) in their comments and names, the converted TOML reads back into the
//! same scenario. Control characters in deck words once went verbatim into the TOML comments
//! that quote them, which TOML forbids, so the converter wrote files it could not read.

use hawser_io::moordyn::{self, ConvertOptions};
use hawser_io::scenario;
use proptest::prelude::*;
use std::path::{Path, PathBuf};

fn data() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/data/moordyn")
}

/// The OC3 deck with `title` as its description line, `comment` after an option, an unknown
/// option named `option`, and the line type named `type_name`.
fn deck(title: &str, comment: &str, option: &str, type_name: &str) -> String {
    let text = std::fs::read_to_string(data().join("oc3_lines.txt")).unwrap();
    let mut out = String::new();
    for (i, line) in text.lines().enumerate() {
        let line = match line.split_whitespace().collect::<Vec<_>>().as_slice() {
            _ if i == 1 => title.to_string(),
            [value, "writeLog", ..] => format!("{value} writeLog {comment}"),
            [value, "WtrDpth", ..] => format!("{value} WtrDpth {comment}\n1.0 {option} {comment}"),
            ["main", rest @ ..] => format!("{type_name} {}", rest.join(" ")),
            [id, "main", rest @ ..] => format!("{id} {type_name} {}", rest.join(" ")),
            _ => line.to_string(),
        };
        out += &line;
        out.push('\n');
    }
    out
}

/// Converts `text`; if it converts, checks the TOML loads and holds the same scenario.
/// Whether it converted.
fn converts_and_loads(text: &str) -> bool {
    let file = data().join("arbitrary.txt");
    let Ok(d) = moordyn::parse(&file, text, &ConvertOptions::default()) else {
        return false;
    };
    let toml_text = moordyn::to_toml(&d, &file);
    let back = scenario::parse(&data().join("arbitrary.toml"), &toml_text)
        .unwrap_or_else(|e| panic!("the converted deck does not load:\n{e}\n\n{toml_text}"));
    let again: scenario::schema::Scenario = toml::from_str(&toml_text).unwrap();
    assert_eq!(
        toml::to_string(&again).unwrap(),
        toml::to_string(&d.scenario).unwrap(),
        "the TOML holds another scenario"
    );
    assert_eq!(back.model.lines.len(), d.loaded.model.lines.len());
    true
}

/// Any text without a line break (comments hold anything).
fn comment() -> impl Strategy<Value = String> {
    prop::collection::vec(any::<char>().prop_filter("one line", |c| *c != '\n'), 0..24)
        .prop_map(|c| c.into_iter().collect())
}

/// Any word: no white space.
fn word() -> impl Strategy<Value = String> {
    prop::collection::vec(
        any::<char>().prop_filter("a word", |c| !c.is_whitespace()),
        1..12,
    )
    .prop_map(|c| c.into_iter().collect())
}

/// The deck's words as a deck writes them, with the control characters of a bad editor.
fn control_word() -> impl Strategy<Value = String> {
    prop::collection::vec(
        prop_oneof![
            Just('\u{1}'),
            Just('\u{7}'),
            Just('\u{1b}'),
            Just('\u{7f}'),
            "[a-z]".prop_map(|s| s.chars().next().unwrap())
        ],
        1..10,
    )
    .prop_map(|c| c.into_iter().collect())
}

/// The case found by hand: a bell, an ANSI colour and a NUL in a deck's words.
#[test]
fn control_characters_in_names_and_comments() {
    let text = deck(
        "MoorDyn \0input\x0cfile",
        "a \x1b[31m comment",
        "write\x07Log",
        "ma\x01in",
    );
    assert!(converts_and_loads(&text));
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    /// Comments have no effect: the deck converts whatever they hold, and the TOML loads.
    #[test]
    fn arbitrary_comments(title in comment(), c in comment()) {
        // A title starting with dashes would be a section header.
        let title = title.trim_start_matches('-').to_string();
        prop_assert!(converts_and_loads(&deck(&title, &c, "unusedOption", "main")));
    }

    /// Names with control characters convert, and the TOML loads.
    #[test]
    fn control_characters_in_names(option in control_word(), name in control_word()) {
        prop_assert!(converts_and_loads(&deck("title", "", &option, &name)));
    }

    /// Names of any characters: whatever converts loads.
    #[test]
    fn arbitrary_names(option in word(), name in word(), c in comment()) {
        converts_and_loads(&deck("title", &c, &option, &name));
    }
}
