//! Every number of every bundled example, set to an overflow value (±1e300, as a fuzzer's
//! f64::MAX would be), is refused at its own key with its unit and bounds, never a panic:
//! a free point with a mass near f64::MAX once passed validation and statics then
//! "converged" with an infinite residual.

use hawser_io::scenario;
use std::ops::Range;
use std::path::{Path, PathBuf};
use toml::Spanned;
use toml::de::{DeTable, DeValue};

/// A number written in a scenario: the key path it belongs to (an array's own key for the
/// numbers in it), and its span.
struct Leaf {
    key: String,
    span: Range<usize>,
}

fn leaves_of_table(t: &DeTable, path: &str, out: &mut Vec<Leaf>) {
    for (k, v) in t.iter() {
        let key = match path.is_empty() {
            true => k.get_ref().to_string(),
            false => format!("{path}.{}", k.get_ref()),
        };
        leaves_of_value(v, &key, &key, out);
    }
}

/// `key` is the path of the value, `array_key` that of the array of numbers it is in.
fn leaves_of_value(v: &Spanned<DeValue>, key: &str, array_key: &str, out: &mut Vec<Leaf>) {
    match v.get_ref() {
        DeValue::Table(t) => leaves_of_table(t, key, out),
        DeValue::Array(a) => {
            let tables = a.iter().any(|x| matches!(x.get_ref(), DeValue::Table(_)));
            for (i, item) in a.iter().enumerate() {
                match tables {
                    true => {
                        let k = format!("{key}[{i}]");
                        leaves_of_value(item, &k, &k, out)
                    }
                    false => leaves_of_value(item, key, array_key, out),
                }
            }
        }
        // Integers are counts (elements, order, components) with their own checks, or a seed.
        DeValue::Float(_) => out.push(Leaf {
            key: array_key.to_string(),
            span: v.span(),
        }),
        _ => {}
    }
}

/// The bundled examples, and scenarios with the keys they do not hold.
fn scenarios() -> Vec<PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = Vec::new();
    for dir in [
        root.join("../../examples"),
        root.join("tests/physical_ranges"),
    ] {
        files.extend(
            std::fs::read_dir(&dir)
                .unwrap()
                .map(|e| e.unwrap().path())
                .filter(|p| p.extension().is_some_and(|e| e == "toml")),
        );
    }
    files.sort();
    files
}

#[test]
fn overflow_values_are_refused_at_their_key() {
    let mut tried = 0;
    let mut failures = Vec::new();
    let mut keys = std::collections::BTreeSet::new();
    for path in scenarios() {
        let text = std::fs::read_to_string(&path).unwrap();
        scenario::parse(&path, &text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let doc = DeTable::parse(&text).unwrap();
        let mut leaves = Vec::new();
        leaves_of_table(doc.get_ref(), "", &mut leaves);
        for leaf in &leaves {
            for value in ["1e300", "-1e300"] {
                let bad = format!(
                    "{}{value}{}",
                    &text[..leaf.span.start],
                    &text[leaf.span.end..]
                );
                let where_ = format!("{} with {} = {value}", path.display(), leaf.key);
                let e = match scenario::parse(&path, &bad) {
                    Ok(_) => {
                        failures.push(format!("{where_} accepted"));
                        continue;
                    }
                    Err(e) => e,
                };
                match e.diagnostics.iter().find(|d| d.key == leaf.key) {
                    None => failures.push(format!("{where_}: no error at the key:\n{e}")),
                    Some(d) if d.expected.is_empty() || d.hint.is_empty() || d.line == 0 => {
                        failures.push(format!("{where_}: {d}"))
                    }
                    Some(_) => {}
                }
                tried += 1;
                keys.insert(leaf.key.replace(|c: char| c.is_ascii_digit(), ""));
            }
        }
    }
    assert!(
        failures.is_empty(),
        "{}\n\n{} failures",
        failures.join("\n\n"),
        failures.len()
    );
    // The scenarios hold the schema's numeric keys but those of motions a body or an obstacle
    // cannot have; the range table's own test checks every key of the schema has a range.
    assert!(
        tried > 2000 && keys.len() > 110,
        "{tried} values, {} keys",
        keys.len()
    );
}

/// The physical range errors name the key, its unit and its bounds.
#[test]
fn a_point_mass_near_f64_max_is_refused() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/wave_buoy.toml");
    let text = std::fs::read_to_string(&path).unwrap();
    let at = text.find("mass = ").expect("the buoy has a mass");
    let end = at + text[at..].find('\n').unwrap();
    let bad = format!("{}mass = 1.7e308{}", &text[..at], &text[end..]);
    let e = scenario::parse(Path::new("wave_buoy.toml"), &bad).unwrap_err();
    insta::assert_snapshot!(e.to_string());
}

/// The same in MoorDyn decks: every number of the bundled decks set to 1e300 is refused in
/// the deck's words, or has no effect at all (the mass of a fixed point, an option hawser
/// does not use): the converted scenario is then the unmodified deck's.
#[test]
fn overflow_values_in_decks_are_refused_or_have_no_effect() {
    use hawser_io::moordyn;
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/data/moordyn");
    let options = moordyn::ConvertOptions::default();
    let as_toml = |d: &moordyn::LoadedDeck| toml::to_string(&d.scenario).unwrap();
    let (mut refused, mut without_effect) = (0, 0);
    for name in ["oc3_lines.txt", "WD0050_Chain.txt", "WD0600_Chain.txt"] {
        let path = dir.join(name);
        let text = std::fs::read_to_string(&path).unwrap();
        let reference = as_toml(&moordyn::parse(&path, &text, &options).unwrap());
        let mut offset = 0;
        // Rows of POINTS and LINES start with an ID, a name rather than a number.
        let mut ids_first = false;
        for line in text.split_inclusive('\n') {
            if line.starts_with("--") {
                let title = line.to_uppercase();
                ids_first = (title.contains("POINT") || title.contains("LINES"))
                    && !title.contains("TYPES");
            }
            let mut at = 0;
            for (j, word) in line.split_whitespace().enumerate() {
                let start = offset + at + line[at..].find(word).unwrap();
                at = start - offset + word.len();
                if (ids_first && j == 0) || word.replace(['d', 'D'], "e").parse::<f64>().is_err() {
                    continue;
                }
                let bad = format!("{}1e300{}", &text[..start], &text[start + word.len()..]);
                match moordyn::parse(&path, &bad, &options) {
                    Err(e) => {
                        let d = &e.diagnostics[0];
                        assert!(d.line > 0 && !d.hint.is_empty(), "{name}: {word}: {e}");
                        refused += 1;
                    }
                    Ok(d) => {
                        assert_eq!(
                            as_toml(&d),
                            reference,
                            "{name}: `{word}` at byte {start} set to 1e300 was accepted and used"
                        );
                        without_effect += 1;
                    }
                }
            }
            offset += line.len();
        }
    }
    assert!(
        refused > 80,
        "{refused} refused, {without_effect} without effect"
    );
}
