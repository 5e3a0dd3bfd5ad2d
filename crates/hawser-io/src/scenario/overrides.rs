//! Dotted-key overrides of a scenario: `lines.chain.length = 900.0` sets one value of the
//! scenario's TOML structure, so that a script or a parameter sweep varies keys without
//! writing files. The Python package's `Scenario.with_overrides` and the parameter sweep use
//! this one function.
//!
//! A key is a path of TOML keys joined by `.`. Arrays of tables (`[[lines]]`, `[[points]]`,
//! `[[line_types]]`, `[[bodies]]`, `[[obstacles]]`) are addressed by the `name` of an element
//! (`lines.chain.length`, `points.fairlead.motion.amplitude`), or by a 0-based index where
//! the elements have no names (`lines.chain.sections.1.length`); arrays of numbers by index
//! (`points.fairlead.position.2`). Tables missing on the way are created
//! (`environment.current.speed` in a scenario without current); the scenario's validation
//! then judges the result as it judges a file. An override of `None` removes the key.

use super::diagnostics::{Diagnostic, ScenarioError, closest};
use std::path::{Path, PathBuf};
use toml::{Table, Value};

/// One override: a dotted key and its new value (`None`: remove the key).
pub type Override = (String, Option<Value>);

/// Why an override could not be applied: the message and a hint.
struct Refusal {
    message: String,
    hint: String,
}

fn refuse(message: String, hint: impl Into<String>) -> Refusal {
    Refusal {
        message,
        hint: hint.into(),
    }
}

/// Applies `overrides` in order to `table`, the TOML structure of a scenario read from
/// `file`. Every override is tried; the refused ones come back as diagnostics that name the
/// key, the value and why (a name that no element has, with the names it has; a key below a
/// number), with `file` as their file and no line (the key is not in the file).
pub fn apply_overrides(
    file: &Path,
    table: &mut Table,
    overrides: &[Override],
) -> Result<(), ScenarioError> {
    let mut errors = Vec::new();
    for (key, value) in overrides {
        let segments: Vec<&str> = key.split('.').collect();
        let shown = value.as_ref().map_or("(removed)".to_string(), |v| {
            v.to_string().lines().next().unwrap_or("").to_string()
        });
        let result = if segments.iter().any(|s| s.is_empty()) {
            Err(refuse(
                format!("the override key `{key}` has an empty part"),
                "keys are TOML keys joined by `.`, e.g. `lines.chain.length`",
            ))
        } else {
            set_in_table(table, &segments, "", value.clone())
        };
        if let Err(r) = result {
            errors.push(
                Diagnostic::new(file, "", None, key.as_str(), r.message)
                    .value(shown)
                    .hint(r.hint),
            );
        }
    }
    match errors.is_empty() {
        true => Ok(()),
        false => Err(ScenarioError {
            diagnostics: errors,
        }),
    }
}

/// The name under which a scenario with overrides is validated: `file` followed by
/// ` (with overrides)`, in `file`'s folder, so that files it names (motion tables, current
/// profiles) are found beside it and its diagnostics say that their lines and columns are
/// those of the scenario with the overrides applied, not of the file.
pub fn overridden_path(file: &Path) -> PathBuf {
    let name = file
        .file_name()
        .map_or("scenario".into(), |n| n.to_string_lossy().into_owned());
    if name.ends_with(" (with overrides)") {
        return file.to_path_buf();
    }
    file.with_file_name(format!("{name} (with overrides)"))
}

fn joined(done: &str, segment: &str) -> String {
    match done.is_empty() {
        true => segment.to_string(),
        false => format!("{done}.{segment}"),
    }
}

fn set_in_table(
    table: &mut Table,
    segments: &[&str],
    done: &str,
    value: Option<Value>,
) -> Result<(), Refusal> {
    let (first, rest) = segments.split_first().expect("a key has a part");
    if rest.is_empty() {
        match value {
            Some(v) => {
                table.insert(first.to_string(), v);
            }
            None => {
                table.remove(*first);
            }
        }
        return Ok(());
    }
    let here = joined(done, first);
    match table.get_mut(*first) {
        Some(child) => set_in_value(child, rest, &here, value),
        None if value.is_none() => Ok(()),
        None => {
            let mut child = Value::Table(Table::new());
            set_in_value(&mut child, rest, &here, value)?;
            table.insert(first.to_string(), child);
            Ok(())
        }
    }
}

fn set_in_value(
    node: &mut Value,
    segments: &[&str],
    done: &str,
    value: Option<Value>,
) -> Result<(), Refusal> {
    match node {
        Value::Table(t) => set_in_table(t, segments, done, value),
        Value::Array(items) => {
            let (first, rest) = segments.split_first().expect("a key has a part");
            let index = element(items, first, done)?;
            let here = joined(done, first);
            match (rest.is_empty(), value) {
                (true, Some(v)) => {
                    items[index] = v;
                    Ok(())
                }
                (true, None) => {
                    items.remove(index);
                    Ok(())
                }
                (false, value) => set_in_value(&mut items[index], rest, &here, value),
            }
        }
        other => Err(refuse(
            format!(
                "`{done}` is {} ({other}), which has no key `{}`",
                kind(other),
                segments[0]
            ),
            format!("override `{done}` itself"),
        )),
    }
}

/// The index in `items` (the array at key `done`) that `segment` names: the element whose
/// `name` it is, or a 0-based index.
fn element(items: &[Value], segment: &str, done: &str) -> Result<usize, Refusal> {
    let names: Vec<&str> = items
        .iter()
        .filter_map(|v| v.get("name").and_then(Value::as_str))
        .collect();
    if let Some(i) = items
        .iter()
        .position(|v| v.get("name").and_then(Value::as_str) == Some(segment))
    {
        return Ok(i);
    }
    if let Ok(i) = segment.parse::<usize>() {
        if i < items.len() {
            return Ok(i);
        }
        return Err(refuse(
            format!(
                "`{done}` has {} elements: there is no element {i} (indices from 0)",
                items.len()
            ),
            "index from 0",
        ));
    }
    let hint = match (names.is_empty(), closest(segment, names.iter().copied())) {
        (true, _) => format!("`{done}` has no named elements: address them by index from 0"),
        (false, Some(c)) => format!(
            "did you mean `{c}`? names in `{done}`: {}",
            names.join(", ")
        ),
        (false, None) => format!("names in `{done}`: {}", names.join(", ")),
    };
    Err(refuse(
        format!("`{done}` has no element named `{segment}`"),
        hint,
    ))
}

fn kind(v: &Value) -> &'static str {
    match v {
        Value::String(_) => "a string",
        Value::Integer(_) | Value::Float(_) => "a number",
        Value::Boolean(_) => "a boolean",
        Value::Datetime(_) => "a date",
        Value::Array(_) => "an array",
        Value::Table(_) => "a table",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scenario() -> Table {
        toml::from_str(
            r#"
            [environment]
            depth = 150.0
            [[line_types]]
            name = "chain"
            diameter = 0.1
            [[points]]
            name = "anchor"
            position = [-600.0, 0.0, -150.0]
            [[points]]
            name = "fairlead"
            position = [0.0, 0.0, -15.0]
            motion = { type = "sinusoid", amplitude = [3.0, 0.0, 0.0], period = 12.0 }
            [[lines]]
            name = "mooring"
            sections = [{ type = "chain", length = 300.0, elements = 10 },
                        { type = "chain", length = 380.0, elements = 12 }]
            "#,
        )
        .expect("valid TOML")
    }

    fn set(t: &mut Table, key: &str, v: Option<Value>) -> Result<(), ScenarioError> {
        apply_overrides(Path::new("s.toml"), t, &[(key.to_string(), v)])
    }

    #[test]
    fn keys_address_tables_named_elements_and_indices() {
        let mut t = scenario();
        set(&mut t, "environment.depth", Some(Value::Float(200.0))).unwrap();
        set(
            &mut t,
            "points.fairlead.motion.amplitude.0",
            Some(2.5.into()),
        )
        .unwrap();
        set(
            &mut t,
            "lines.mooring.sections.1.length",
            Some(400.0.into()),
        )
        .unwrap();
        set(&mut t, "environment.waves.seed", Some(Value::Integer(7))).unwrap();
        set(&mut t, "line_types.chain.diameter", None).unwrap();
        assert_eq!(t["environment"]["depth"].as_float(), Some(200.0));
        let fairlead = &t["points"][1];
        assert_eq!(fairlead["motion"]["amplitude"][0].as_float(), Some(2.5));
        assert_eq!(fairlead["motion"]["period"].as_float(), Some(12.0));
        assert_eq!(
            t["lines"][0]["sections"][1]["length"].as_float(),
            Some(400.0)
        );
        assert_eq!(
            t["lines"][0]["sections"][0]["length"].as_float(),
            Some(300.0)
        );
        assert_eq!(t["environment"]["waves"]["seed"].as_integer(), Some(7));
        assert!(t["line_types"][0].get("diameter").is_none());
    }

    #[test]
    fn refusals_name_the_key_and_the_names_there_are() {
        let mut t = scenario();
        let before = t.clone();
        let e = apply_overrides(
            Path::new("s.toml"),
            &mut t,
            &[
                ("points.fairled.position".into(), Some(1.0.into())),
                ("environment.depth.x".into(), Some(1.0.into())),
                ("lines.mooring.sections.5.length".into(), Some(1.0.into())),
                ("lines..length".into(), Some(1.0.into())),
            ],
        )
        .unwrap_err();
        let d = &e.diagnostics;
        assert_eq!(d.len(), 4);
        assert_eq!(d[0].key, "points.fairled.position");
        assert_eq!(d[0].message, "`points` has no element named `fairled`");
        assert_eq!(
            d[0].hint,
            "did you mean `fairlead`? names in `points`: anchor, fairlead"
        );
        assert_eq!(d[0].value, "1.0");
        assert!(
            d[1].message.contains("`environment.depth` is a number"),
            "{}",
            d[1].message
        );
        assert!(d[2].message.contains("no element 5"), "{}", d[2].message);
        assert!(d[3].message.contains("empty part"), "{}", d[3].message);
        assert_eq!(d[0].file, Path::new("s.toml"));
        assert_eq!(d[0].line, 0);
        // Nothing refused was applied.
        assert_eq!(t, before);
    }

    #[test]
    fn the_overridden_path_stays_in_the_folder() {
        let p = overridden_path(Path::new("examples/oc3.toml"));
        assert_eq!(p, Path::new("examples/oc3.toml (with overrides)"));
        assert_eq!(p.parent(), Some(Path::new("examples")));
        assert_eq!(overridden_path(&p), p);
    }
}
