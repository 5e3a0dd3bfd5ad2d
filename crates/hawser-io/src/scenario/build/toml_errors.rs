//! TOML and serde errors of a scenario file turned into diagnostics: the key path at an
//! error's offset, the schema's documentation of that key, and a hint.

#[cfg(test)]
use crate::scenario::diagnostics::work;
use crate::scenario::diagnostics::{Diagnostic, LineIndex, ScenarioError, closest};
use crate::scenario::schema::*;
use std::collections::HashSet;
use std::ops::Range;
use std::path::Path;
use std::sync::OnceLock;
use toml::Spanned;
use toml::de::DeTable;

/// What every error of one file is read against: its text, line index and a best-effort
/// parse, each made once per file (not once per error).
struct Source<'a> {
    file: &'a Path,
    text: &'a str,
    lines: LineIndex,
    doc: Spanned<DeTable<'a>>,
}

/// The first error of the file and, if the TOML itself is valid, the first error of every
/// other table: each section and each `[[...]]` element is checked on its own.
pub(super) fn schema_errors(file: &Path, source: &str, first: &toml::de::Error) -> ScenarioError {
    use serde::Deserialize;
    use toml::de::{DeValue, ValueDeserializer};
    let (doc, _) = DeTable::parse_recoverable(source);
    #[cfg(test)]
    work::add(source.len());
    let src = Source {
        file,
        text: source,
        lines: LineIndex::new(source),
        doc,
    };
    let mut errors = vec![toml_error(&src, first)];
    let mut seen: HashSet<(usize, usize)> = errors.iter().map(|d| (d.line, d.column)).collect();
    if let Ok(doc) = DeTable::parse(source) {
        for (key, value) in doc.get_ref().iter() {
            let items: Vec<&Spanned<DeValue>> = match value.get_ref() {
                DeValue::Array(a) => a.iter().collect(),
                _ => vec![value],
            };
            for item in items {
                let de = || ValueDeserializer::from(item.clone());
                let e = match key.get_ref().as_ref() {
                    "simulation" => SimulationSpec::deserialize(de()).err(),
                    "environment" => EnvironmentSpec::deserialize(de()).err(),
                    "line_types" => LineTypeSpec::deserialize(de()).err(),
                    "points" => PointSpec::deserialize(de()).err(),
                    "lines" => LineSpec::deserialize(de()).err(),
                    "bodies" => BodySpec::deserialize(de()).err(),
                    "obstacles" => ObstacleSpec::deserialize(de()).err(),
                    _ => None,
                };
                let Some(e) = e else { continue };
                let d = toml_error(&src, &e);
                if seen.insert((d.line, d.column)) {
                    errors.push(d);
                }
            }
        }
    }
    errors.sort_by_key(|d| (d.line, d.column));
    ScenarioError {
        diagnostics: errors,
    }
}

/// Turns a TOML or serde error into a diagnostic with a hint.
fn toml_error(src: &Source, e: &toml::de::Error) -> Diagnostic {
    let (file, source) = (src.file, src.text);
    let message = e.message().trim().to_string();
    let quoted: Vec<&str> = message.split('`').skip(1).step_by(2).collect();
    let first = quoted.first().copied().unwrap_or("");
    let span = e.span();
    let mut at = span
        .as_ref()
        .map(|s| key_at(source, src.doc.get_ref(), s.start))
        .unwrap_or_default();
    let syntax = !(message.starts_with("unknown field")
        || message.starts_with("missing field")
        || message.starts_with("invalid type")
        || message.starts_with("invalid length")
        || message.contains("untagged enum")
        || message.starts_with("unknown variant"));
    if syntax {
        // The parser's recovery may have made up array elements after the error.
        while matches!(at.path.last(), Some(Step::Index(_))) {
            at.path.pop();
        }
    }
    let path = path_string(&at.path);
    let leaf = at
        .path
        .iter()
        .rev()
        .find_map(|s| match s {
            Step::Key(k) => Some(k.clone()),
            Step::Index(_) => None,
        })
        .unwrap_or_default();
    let in_array = matches!(at.path.last(), Some(Step::Index(_)));
    let line_of = |offset: usize| src.lines.line(offset);
    let one_of = |known: &[&str]| {
        let list: Vec<String> = known.iter().map(|q| format!("`{q}`")).collect();
        format!("one of {}", list.join(", "))
    };
    let mut d = Diagnostic::indexed(
        file,
        source,
        &src.lines,
        span.clone(),
        path.clone(),
        message.clone(),
    );
    if message.starts_with("unknown field") {
        let known = quoted.get(1..).unwrap_or(&[]);
        let hint = match closest(first, known.iter().copied()) {
            Some(c) => format!("did you mean `{c}`? docs/scenario.md lists every key"),
            None => "remove it; docs/scenario.md lists every key".to_string(),
        };
        d.message = format!("unknown key `{first}`");
        if let Some(v) = at.value.filter(|v| v.end <= source.len()) {
            d = d.value(source[v].lines().next().unwrap_or(""));
        }
        d = d.hint(hint).expected(if known.is_empty() {
            "no keys in this table".to_string()
        } else {
            one_of(known)
        });
    } else if message.starts_with("missing field") {
        let mut field_path = at.path.clone();
        field_path.push(Step::Key(first.to_string()));
        d.key = path_string(&field_path);
        d.message = format!("missing key `{first}`");
        d = d
            .value("")
            .expected(field_doc(&field_path).unwrap_or_default())
            .hint(format!("add `{first} = ...` to this table"));
    } else if !syntax && !message.starts_with("unknown variant") {
        let wanted = if message.contains("untagged enum ScalarOrVec3") {
            "a number or [x, y, z]"
        } else if message.contains("untagged enum InertiaSpec") {
            "[Ixx, Iyy, Izz] or a 3×3 matrix [[Ixx, Ixy, Ixz], [Ixy, Iyy, Iyz], [Ixz, Iyz, Izz]]"
        } else if message.contains("untagged enum TimeStepSpec") {
            "\"auto\" or a number"
        } else {
            match message.rsplit("expected ").next().unwrap_or("") {
                "f64" => "a number",
                "i64" => "a whole number",
                "bool" | "a boolean" => "true or false",
                "a string" => "a quoted string",
                other => other,
            }
        };
        if message.contains("untagged enum") {
            d.message = format!("invalid type, expected {wanted}");
        } else if let Some((found, _)) = message.rsplit_once(", expected ") {
            d.message = format!("{found}, expected {wanted}");
        }
        d = d.expected(match field_doc(&at.path) {
            Some(doc) => format!("{wanted}: {doc}"),
            None => wanted.to_string(),
        });
        let text = d.value.trim().trim_matches('"').to_string();
        let number = text
            .split_whitespace()
            .next()
            .filter(|n| n.parse::<f64>().is_ok());
        let write = |v: &str| match in_array {
            true => format!("`{v}`"),
            false => format!("`{leaf} = {v}`"),
        };
        let hint = if d.value.starts_with('"')
            && let Some(n) = number
        {
            let unit = if n == text { "" } else { " and unit" };
            format!("write the number without quotes{unit}: {}", write(n))
        } else if wanted == "a whole number" {
            match text.parse::<f64>() {
                Ok(x) => format!(
                    "write a whole number without a decimal point, e.g. {}",
                    write(&format!("{}", x.round().max(1.0)))
                ),
                Err(_) => format!("write a whole number, e.g. {}", write("10")),
            }
        } else if message.starts_with("invalid length") {
            format!("write {wanted} in brackets; docs/scenario.md says what each entry is")
        } else if wanted.contains("auto") {
            "write `time_step = \"auto\"` or a step in seconds, e.g. `time_step = 0.001`"
                .to_string()
        } else {
            "numbers are unquoted, names are quoted, vectors are [x, y, z]".to_string()
        };
        d = d.hint(hint);
    } else if message.starts_with("unknown variant") {
        let known = quoted.get(1..).unwrap_or(&[]);
        let hint = match closest(first, known.iter().copied()) {
            Some(c) => format!("did you mean `{c}`?"),
            None => {
                let docs: Vec<String> = variant_docs(&at.path)
                    .iter()
                    .map(|(v, doc)| format!("`{v}`: {doc}"))
                    .collect();
                match docs.is_empty() {
                    true => "use one of the expected values".to_string(),
                    false => docs.join("; "),
                }
            }
        };
        d.message = format!("unknown value `{first}` for `{leaf}`");
        d = d.hint(hint).expected(one_of(known));
    } else {
        // TOML syntax: point at the key being written and say what is usually wrong.
        let hint = if message.starts_with("duplicate key") {
            if let Some(rest) = source
                .lines()
                .nth(d.line.saturating_sub(1))
                .and_then(|l| l.split_once('=').map(|x| x.1.trim().to_string()))
            {
                d = d.value(rest);
            }
            match at
                .key
                .as_ref()
                .filter(|k| Some(k.start) != span.as_ref().map(|s| s.start))
            {
                Some(k) => format!(
                    "a key may appear once per table; `{leaf}` is already set on line {}",
                    line_of(k.start)
                ),
                None => "a key may appear once per table; remove one of them".to_string(),
            }
        } else if message.starts_with("string values must be quoted")
            && let Some(n) = d
                .value
                .split_whitespace()
                .next()
                .filter(|n| n.parse::<f64>().is_ok())
        {
            format!("write the number alone, `{leaf} = {n}`: units are implied (see expected)")
        } else if message.starts_with("string values must be quoted") {
            "quote names and keywords, e.g. `type = \"chain\"`".to_string()
        } else if let (Some(v), Some(s)) = (at.value.as_ref(), span.as_ref())
            && line_of(v.start) < line_of(s.start)
            && source
                .get(v.start..)
                .is_some_and(|t| t.starts_with(['[', '{']))
        {
            format!(
                "`{path}` opens a bracket on line {} that is not closed there",
                line_of(v.start)
            )
        } else {
            "this is not valid TOML (https://toml.io); docs/scenario.md shows the format"
                .to_string()
        };
        if let Some(doc) = field_doc(&at.path) {
            d = d.expected(doc);
        }
        d = d.hint(hint);
    }
    d
}

/// One step of a key path.
#[derive(Clone, Debug)]
enum Step {
    Key(String),
    Index(usize),
}

/// Renders a key path as `lines[0].end_b`.
fn path_string(path: &[Step]) -> String {
    let mut s = String::new();
    for step in path {
        match step {
            Step::Key(k) => {
                if !s.is_empty() {
                    s.push('.');
                }
                s.push_str(k);
            }
            Step::Index(i) => s.push_str(&format!("[{i}]")),
        }
    }
    s
}

/// The innermost key around a byte offset: its path and the spans of the key and its value.
#[derive(Default)]
struct KeyAt {
    path: Vec<Step>,
    key: Option<Range<usize>>,
    value: Option<Range<usize>>,
}

/// Finds the innermost key or value at `offset` in `doc`, a best-effort parse of `source`.
fn key_at<'a>(source: &str, doc: &'a DeTable<'a>, offset: usize) -> KeyAt {
    let mut at = KeyAt::default();
    if find_in_table(doc, offset, &mut at) {
        return at;
    }
    // Not inside a parsed key or value (e.g. a duplicate key, which the parser drops): take
    // the table whose header is the last before `offset`, and the key written at `offset`.
    let mut best = (0, Vec::new(), doc);
    last_header(source, doc, offset, &mut Vec::new(), &mut best);
    let (_, path, table) = best;
    at.path = path;
    let word: String = source
        .get(offset..)
        .unwrap_or("")
        .chars()
        .take_while(|c| c.is_ascii_alphanumeric() || *c == '_' || *c == '-')
        .collect();
    if !word.is_empty() {
        if let Some((k, v)) = table.iter().find(|(k, _)| k.get_ref() == &word) {
            at.key = Some(k.span());
            at.value = Some(v.span());
        }
        at.path.push(Step::Key(word));
    }
    at
}

/// The `[table]` or `[[array]]` header that comes last before `offset`.
fn last_header<'a>(
    source: &str,
    t: &'a toml::de::DeTable,
    offset: usize,
    path: &mut Vec<Step>,
    best: &mut (usize, Vec<Step>, &'a toml::de::DeTable<'a>),
) {
    let mut consider = |v: &'a Spanned<toml::de::DeValue>, path: &mut Vec<Step>| {
        if let toml::de::DeValue::Table(inner) = v.get_ref() {
            let start = v.span().start;
            let inline = source.get(start..).is_some_and(|s| s.starts_with('{'));
            if !inline && start <= offset && start >= best.0 {
                *best = (start, path.clone(), inner);
            }
            last_header(source, inner, offset, path, best);
        }
    };
    for (k, v) in t.iter() {
        path.push(Step::Key(k.get_ref().to_string()));
        if let toml::de::DeValue::Array(a) = v.get_ref() {
            for (i, item) in a.iter().enumerate() {
                path.push(Step::Index(i));
                consider(item, path);
                path.pop();
            }
        } else {
            consider(v, path);
        }
        path.pop();
    }
}

fn find_in_table(t: &toml::de::DeTable, offset: usize, at: &mut KeyAt) -> bool {
    for (k, v) in t.iter() {
        at.path.push(Step::Key(k.get_ref().to_string()));
        if k.span().contains(&offset) || find_in_value(v, offset, at) {
            at.key.get_or_insert(k.span());
            at.value.get_or_insert(v.span());
            return true;
        }
        at.path.pop();
    }
    false
}

fn find_in_value(v: &Spanned<toml::de::DeValue>, offset: usize, at: &mut KeyAt) -> bool {
    #[cfg(test)]
    work::add(1);
    let inner = match v.get_ref() {
        toml::de::DeValue::Table(t) => find_in_table(t, offset, at),
        toml::de::DeValue::Array(a) => {
            // The items of an array are in file order and do not overlap (an element of an
            // array of tables ends where the next one's header starts): the only one that
            // can hold `offset` is the last that starts at or before it. Searching it alone
            // makes n errors in n elements cost O(n log n), not O(n²).
            let last = a.partition_point(|item| item.span().start <= offset);
            last > 0 && {
                at.path.push(Step::Index(last - 1));
                let found = find_in_value(&a[last - 1], offset, at);
                if !found {
                    at.path.pop();
                }
                found
            }
        }
        _ => false,
    };
    inner || v.span().contains(&offset)
}

/// The span of the key at `path` (e.g. `["environment", "seabed"]`), if written.
pub(super) fn key_span(source: &str, path: &[&str]) -> Option<Range<usize>> {
    let (doc, _) = toml::de::DeTable::parse_recoverable(source);
    let mut table = doc.get_ref();
    for (i, name) in path.iter().enumerate() {
        let (k, v) = table.iter().find(|(k, _)| k.get_ref() == name)?;
        if i + 1 == path.len() {
            return Some(k.span());
        }
        match v.get_ref() {
            toml::de::DeValue::Table(t) => table = t,
            _ => return None,
        }
    }
    None
}

/// The JSON Schema node of the key at `path`, and its documentation (with unit).
fn schema_node(path: &[Step]) -> Option<(serde_json::Value, Option<String>)> {
    fn resolve<'a>(
        defs: &'a serde_json::Value,
        mut v: &'a serde_json::Value,
    ) -> &'a serde_json::Value {
        for _ in 0..8 {
            if let Some(r) = v.get("$ref").and_then(|r| r.as_str()) {
                v = &defs[r.trim_start_matches("#/$defs/")];
            } else if let Some(any) = v.get("anyOf").and_then(|a| a.as_array()) {
                match any
                    .iter()
                    .find(|x| x.get("type").and_then(|t| t.as_str()) != Some("null"))
                {
                    Some(x) => v = x,
                    None => break,
                }
            } else {
                break;
            }
        }
        v
    }
    let schema = scenario_schema();
    let defs = &schema["$defs"];
    let mut node = schema;
    let mut doc = None;
    for step in path {
        node = resolve(defs, node);
        node = match step {
            Step::Key(k) => {
                let p = node.get("properties")?.get(k)?;
                doc = p.get("description").and_then(|d| d.as_str());
                p
            }
            Step::Index(_) => node.get("items")?,
        };
    }
    let doc = doc.map(|d| {
        // Doc comments wrapped over several source lines come with their line breaks.
        let d = d.replace('\n', " ");
        let d = d.trim_end_matches('.');
        let mut chars = d.chars();
        match chars.next() {
            Some(c) => c.to_lowercase().chain(chars).collect(),
            None => String::new(),
        }
    });
    Some((resolve(defs, node).clone(), doc))
}

/// The JSON Schema of scenario files as a value, built once per process: every hint of every
/// rejected scenario reads it.
fn scenario_schema() -> &'static serde_json::Value {
    static SCHEMA: OnceLock<serde_json::Value> = OnceLock::new();
    SCHEMA.get_or_init(|| {
        #[cfg(test)]
        schema_builds::add();
        serde_json::to_value(schemars::schema_for!(Scenario)).expect("the schema is JSON")
    })
}

/// How many times this process built the schema of [`scenario_schema`].
#[cfg(test)]
pub(super) fn schema_builds_count() -> usize {
    schema_builds::count()
}

#[cfg(test)]
mod schema_builds {
    use std::sync::atomic::{AtomicUsize, Ordering};
    static BUILDS: AtomicUsize = AtomicUsize::new(0);
    pub fn add() {
        BUILDS.fetch_add(1, Ordering::Relaxed);
    }
    pub fn count() -> usize {
        BUILDS.load(Ordering::Relaxed)
    }
}

/// The documentation (with unit) of the key at `path`, from the JSON Schema of the format.
fn field_doc(path: &[Step]) -> Option<String> {
    schema_node(path)?.1.filter(|d| !d.is_empty())
}

/// The allowed values of the key at `path` with their documentation.
fn variant_docs(path: &[Step]) -> Vec<(String, String)> {
    let Some((node, _)) = schema_node(path) else {
        return Vec::new();
    };
    let variants = node.get("oneOf").and_then(|v| v.as_array());
    variants
        .into_iter()
        .flatten()
        .filter_map(|v| {
            let value = v.get("const")?.as_str()?;
            let doc = v.get("description")?.as_str()?.replace('\n', " ");
            let doc = doc.trim_end_matches('.');
            let mut chars = doc.chars();
            let doc = chars.next()?.to_lowercase().chain(chars).collect();
            Some((value.to_string(), doc))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The search of every item of every array, as it was before it searched only the item
    /// that starts last before the offset.
    fn find_linear_table(t: &DeTable, offset: usize, at: &mut KeyAt) -> bool {
        t.iter().any(|(k, v)| {
            at.path.push(Step::Key(k.get_ref().to_string()));
            if k.span().contains(&offset) || find_linear(v, offset, at) {
                at.key.get_or_insert(k.span());
                at.value.get_or_insert(v.span());
                return true;
            }
            at.path.pop();
            false
        })
    }

    fn find_linear(v: &Spanned<toml::de::DeValue>, offset: usize, at: &mut KeyAt) -> bool {
        let inner = match v.get_ref() {
            toml::de::DeValue::Table(t) => find_linear_table(t, offset, at),
            toml::de::DeValue::Array(a) => a.iter().enumerate().any(|(i, item)| {
                at.path.push(Step::Index(i));
                let found = find_linear(item, offset, at);
                if !found {
                    at.path.pop();
                }
                found
            }),
            _ => false,
        };
        inner || v.span().contains(&offset)
    }

    /// Searching one item per array finds the same key as searching them all, at every
    /// offset of scenarios with arrays of tables, inline arrays, sub-tables of array
    /// elements and tables out of order.
    #[test]
    fn the_item_search_finds_what_the_full_search_finds() {
        let sources = [
            include_str!("../../../../../examples/catenary_mooring.toml"),
            include_str!("../../../../../examples/turn_270_body.toml"),
            "[[points]]\nname = \"a\"\n[points.motion]\ntype = \"fixed\"\n[environment]\ndepth = 1\n\
             [[points]]\nname = \"b\"\nposition = [1, [2, 3], {x = 4}]\n\
             lines = [{name = \"l\", n = [1, 2]}, {name = \"m\"}]\n",
        ];
        for source in sources {
            let (doc, _) = DeTable::parse_recoverable(source);
            for offset in 0..=source.len() {
                let mut fast = KeyAt::default();
                let mut slow = KeyAt::default();
                let found = find_in_table(doc.get_ref(), offset, &mut fast);
                let expected = find_linear_table(doc.get_ref(), offset, &mut slow);
                assert_eq!(found, expected, "offset {offset}");
                if found {
                    assert_eq!(
                        path_string(&fast.path),
                        path_string(&slow.path),
                        "offset {offset}"
                    );
                    assert_eq!(
                        (fast.key, fast.value),
                        (slow.key, slow.value),
                        "offset {offset}"
                    );
                }
            }
        }
    }
}
