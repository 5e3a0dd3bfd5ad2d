//! Load-case tables for `hawser sweep` (docs/sweep.md): a table of dotted-key overrides
//! ([`crate::scenario::overrides`]), one row per case, read from CSV or TOML and validated
//! case by case against a base scenario before any case runs; and the summary table of a
//! sweep (`sweep_summary.csv`, and `.parquet`): per case its name, override values, status and
//! the extremes its `summary.json` holds.
//!
//! CSV: a header of override keys (`lines.chain.length`) and an optional `name` (or `case`)
//! column; one row per case; RFC 4180 quoting (`"[2.0, 0.0, 0.0]"` for a value with commas);
//! blank lines and lines starting with `#` are skipped. A cell is a TOML value (`690.0`, `7`,
//! `[2.0, 0.0, 0.0]`, `"auto"`); a cell that is not one is taken as a string (`auto`); an empty
//! cell leaves the base scenario's value. TOML: an array of tables `[[cases]]`, each with an
//! optional `name` and quoted dotted keys (`"lines.chain.length" = 690.0`); a nested table
//! stands for its keys one by one.

use crate::input::with_overrides;
use crate::moordyn::ConvertOptions;
pub use crate::results::Column;
use crate::results::{push_number, safe_file_name, write_atomically};
use crate::scenario::overrides::Override;
use crate::scenario::{Diagnostic, LoadedScenario, ScenarioError};
use hawser::math::Real;
use serde_json::Value as Json;
use std::ops::Range;
use std::path::{Path, PathBuf};
use toml::Value;

/// One cell of a case table that sets a key.
#[derive(Clone, Debug)]
pub struct Cell {
    /// The cell as written (without CSV quotes; a TOML value in TOML form).
    pub text: String,
    /// The value it sets.
    pub value: Value,
    /// Byte span of the cell in the table file.
    pub span: Range<usize>,
}

/// One row of a case table.
#[derive(Clone, Debug)]
pub struct Case {
    /// 0-based index of the case in the table (the `k` of `--shard`).
    pub index: usize,
    /// Its name: the `name` column, or `case_0001` … by its 1-based index.
    pub name: String,
    /// Byte span of the start of its row in the table file.
    pub span: Range<usize>,
    /// Per key of the table ([`CaseTable::keys`]) the cell that sets it; `None` leaves the
    /// base scenario's value.
    pub cells: Vec<Option<Cell>>,
}

/// A table of load cases read from a file.
#[derive(Clone, Debug)]
pub struct CaseTable {
    /// The table file.
    pub file: PathBuf,
    /// Its text.
    pub source: String,
    /// The override keys, in column order.
    pub keys: Vec<String>,
    /// The cases, in table order.
    pub cases: Vec<Case>,
}

impl CaseTable {
    /// The overrides of `case`, in column order.
    pub fn overrides(&self, case: &Case) -> Vec<Override> {
        self.keys
            .iter()
            .zip(&case.cells)
            .filter_map(|(k, c)| c.as_ref().map(|c| (k.clone(), Some(c.value.clone()))))
            .collect()
    }

    fn diagnostic(&self, span: Range<usize>, key: &str, message: impl Into<String>) -> Diagnostic {
        Diagnostic::new(&self.file, &self.source, Some(span), key, message)
    }
}

/// Reads and checks a case table: CSV, or TOML for a file ending in `.toml`. Errors name the
/// file, line and column of the cell.
pub fn read_case_table(path: &Path) -> Result<CaseTable, ScenarioError> {
    let source = crate::scenario::read_file(path, "case table")?;
    parse_case_table(path, &source)
}

/// [`read_case_table`] of the text `source`, as if read from `path`.
pub fn parse_case_table(path: &Path, source: &str) -> Result<CaseTable, ScenarioError> {
    let toml = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("toml"));
    let mut table = CaseTable {
        file: path.to_path_buf(),
        source: source.to_string(),
        keys: Vec::new(),
        cases: Vec::new(),
    };
    let (rows, mut errors) = match toml {
        true => (toml_rows(&mut table)?, Vec::new()),
        false => csv_rows(&mut table)?,
    };
    let mut cases = Vec::new();
    for (index, row) in rows.into_iter().enumerate() {
        let name = match row.name {
            Some(cell) if !cell.text.is_empty() => {
                if let Err(why) = check_name(&cell.text) {
                    errors.push(
                        table
                            .diagnostic(cell.span.clone(), "name", why)
                            .value(cell.text.clone())
                            .hint("a case name is a folder name: letters, digits, `-`, `_`, `.`"),
                    );
                }
                cell.text
            }
            _ => format!("case_{:04}", index + 1),
        };
        let mut cells: Vec<Option<Cell>> = vec![None; table.keys.len()];
        for (k, cell) in row.cells {
            if k >= cells.len() {
                cells.resize(k + 1, None);
            }
            cells[k] = Some(cell);
        }
        cases.push(Case {
            index,
            name,
            span: row.span,
            cells,
        });
    }
    let width = table.keys.len();
    for c in &mut cases {
        c.cells.resize(width, None);
    }
    for (i, c) in cases.iter().enumerate() {
        if let Some(first) = cases[..i].iter().find(|d| d.name == c.name) {
            let line = crate::scenario::diagnostics::line_number(source, first.span.start);
            errors.push(
                table
                    .diagnostic(
                        c.span.clone(),
                        "name",
                        format!("a second case named `{}`", c.name),
                    )
                    .value(c.name.clone())
                    .hint(format!(
                        "case names must be unique: each is a folder of the results (the first \
                         is on line {line})"
                    )),
            );
        }
    }
    if cases.is_empty() && errors.is_empty() {
        errors.push(
            Diagnostic::new(path, source, None, "", "the case table has no cases").hint(
                match toml {
                    true => "add `[[cases]]` tables with dotted keys, e.g. `\"lines.chain.length\" = 690.0`",
                    false => "give a header of override keys, then one row per case",
                },
            ),
        );
    }
    if !errors.is_empty() {
        return Err(ScenarioError {
            diagnostics: errors,
        });
    }
    table.cases = cases;
    Ok(table)
}

/// Why `name` cannot name a case's folder, if it cannot.
fn check_name(name: &str) -> Result<(), String> {
    if name.starts_with("sweep_summary") {
        return Err(format!(
            "the case name `{name}` is taken by the summary table's files"
        ));
    }
    if safe_file_name(name) != name || name.trim() != name || name == "." {
        return Err(format!(
            "the case name `{name}` cannot name a folder of the results"
        ));
    }
    Ok(())
}

/// A row before the checks that need every row: its name cell, its cells by key index.
struct Row {
    span: Range<usize>,
    name: Option<Cell>,
    cells: Vec<(usize, Cell)>,
}

/// The value of a CSV cell: the TOML value it is, else the text as a string.
fn cell_value(text: &str) -> Value {
    match toml::from_str::<toml::Table>(&format!("v = {text}")) {
        Ok(mut t) if t.len() == 1 => t.remove("v").unwrap_or(Value::String(text.to_string())),
        _ => Value::String(text.to_string()),
    }
}

/// A field of a CSV record.
struct Field {
    /// The text, unquoted and (outside quotes) trimmed.
    text: String,
    /// Its span in the file (quotes included).
    span: Range<usize>,
}

/// A CSV record: the span of its start and its fields.
type Record = (Range<usize>, Vec<Field>);

/// The records of a CSV text (RFC 4180: `"` quotes, `""` inside quotes is a quote, quoted
/// fields may span lines; blank lines and lines starting with `#` skipped), each as (span of
/// its start, fields).
fn csv_records(table: &CaseTable) -> Result<Vec<Record>, ScenarioError> {
    let s = table.source.as_str();
    let b = s.as_bytes();
    let mut i = if s.starts_with('\u{feff}') { 3 } else { 0 };
    let mut records = Vec::new();
    while i < b.len() {
        // Skip a blank or comment line.
        let line_end = s[i..].find('\n').map_or(b.len(), |n| i + n);
        let trimmed = s[i..line_end].trim();
        if trimmed.is_empty() || trimmed.starts_with('#') {
            i = line_end + 1;
            continue;
        }
        let start = i;
        let mut fields = Vec::new();
        loop {
            while i < b.len() && (b[i] == b' ' || b[i] == b'\t') {
                i += 1;
            }
            if i < b.len() && b[i] == b'"' {
                let open = i;
                let mut text = String::new();
                i += 1;
                loop {
                    let Some(n) = s[i..].find('"') else {
                        return Err(table
                            .diagnostic(open..open + 1, "", "a quoted cell has no closing quote")
                            .hint("close it with `\"`; write a quote inside quotes as `\"\"`")
                            .into());
                    };
                    text.push_str(&s[i..i + n]);
                    i += n + 1;
                    if b.get(i) == Some(&b'"') {
                        text.push('"');
                        i += 1;
                    } else {
                        break;
                    }
                }
                let span = open..i;
                while i < b.len() && (b[i] == b' ' || b[i] == b'\t' || b[i] == b'\r') {
                    i += 1;
                }
                if i < b.len() && b[i] != b',' && b[i] != b'\n' {
                    return Err(table
                        .diagnostic(i..i + 1, "", "text after the closing quote of a cell")
                        .hint("quote the whole cell: `\"[1.0, 2.0]\"`")
                        .into());
                }
                fields.push(Field { text, span });
            } else {
                let end = s[i..].find([',', '\n']).map_or(b.len(), |n| i + n);
                let raw = &s[i..end];
                let text = raw.trim_end_matches([' ', '\t', '\r']);
                fields.push(Field {
                    text: text.to_string(),
                    span: i..i + text.len(),
                });
                i = end;
            }
            match b.get(i) {
                Some(b',') => i += 1,
                Some(b'\n') => {
                    i += 1;
                    break;
                }
                _ => break,
            }
        }
        records.push((start..start + 1, fields));
    }
    Ok(records)
}

/// The rows of a CSV table, and the problems of its header and rows (the rows with a
/// problem left out).
fn csv_rows(table: &mut CaseTable) -> Result<(Vec<Row>, Vec<Diagnostic>), ScenarioError> {
    let records = csv_records(table)?;
    let Some(((_, header), body)) = records.split_first() else {
        return Ok((Vec::new(), Vec::new()));
    };
    let mut errors = Vec::new();
    let mut name_column = None;
    let mut keys = Vec::new();
    // Per field of the header: None for the name column, Some(key index) otherwise.
    let mut columns = Vec::new();
    for (c, f) in header.iter().enumerate() {
        let key = f.text.as_str();
        if key.is_empty() {
            errors.push(
                table
                    .diagnostic(f.span.clone(), "", format!("column {} has no key", c + 1))
                    .hint("the header names a dotted key per column, e.g. `lines.chain.length`"),
            );
            columns.push(None);
        } else if key == "name" || key == "case" {
            if let Some(other) = name_column.replace(key) {
                errors.push(
                    table
                        .diagnostic(f.span.clone(), key, "a second column of case names")
                        .hint(format!("keep one of `{other}` and `{key}`")),
                );
            }
            columns.push(None);
        } else if keys.iter().any(|k| k == key) {
            errors.push(
                table
                    .diagnostic(
                        f.span.clone(),
                        key,
                        format!("the key `{key}` has a second column"),
                    )
                    .hint("give each key one column"),
            );
            columns.push(None);
        } else {
            columns.push(Some(keys.len()));
            keys.push(key.to_string());
        }
    }
    let mut rows = Vec::new();
    for (span, fields) in body {
        if fields.len() != header.len() {
            errors.push(
                table
                    .diagnostic(
                        span.clone(),
                        "",
                        format!(
                            "this row has {} cells, the header {}",
                            fields.len(),
                            header.len()
                        ),
                    )
                    .hint("quote a cell that holds commas: `\"[2.0, 0.0, 0.0]\"`; leave a cell empty to keep the base value"),
            );
            continue;
        }
        let mut row = Row {
            span: span.clone(),
            name: None,
            cells: Vec::new(),
        };
        for (f, column) in fields.iter().zip(&columns) {
            let cell = Cell {
                text: f.text.clone(),
                value: cell_value(&f.text),
                span: f.span.clone(),
            };
            match column {
                Some(k) if !f.text.is_empty() => row.cells.push((*k, cell)),
                Some(_) => {}
                None => row.name = Some(cell),
            }
        }
        rows.push(row);
    }
    table.keys = keys;
    Ok((rows, errors))
}

/// The leaves of `value` under `key` as (dotted key, value): a table stands for its keys.
fn leaves(key: String, value: Value, out: &mut Vec<(String, Value)>) {
    match value {
        Value::Table(t) => {
            for (k, v) in t {
                leaves(format!("{key}.{k}"), v, out);
            }
        }
        v => out.push((key, v)),
    }
}

fn toml_rows(table: &mut CaseTable) -> Result<Vec<Row>, ScenarioError> {
    use std::collections::BTreeMap;
    use toml::Spanned;
    #[derive(serde::Deserialize)]
    #[serde(deny_unknown_fields)]
    struct File {
        cases: Vec<Spanned<BTreeMap<String, Spanned<Value>>>>,
    }
    let file: File = toml::from_str(&table.source).map_err(|e| {
        table
            .diagnostic(e.span().unwrap_or(0..0), "cases", e.message().to_string())
            .hint("a TOML case table is an array `[[cases]]` of tables of dotted keys, e.g. `\"lines.chain.length\" = 690.0`")
    })?;
    let mut errors = Vec::new();
    let mut found: Vec<(usize, String)> = Vec::new();
    let mut rows = Vec::new();
    for case in file.cases {
        let span = case.span();
        let mut row = Row {
            span: span.start..span.start + 1,
            name: None,
            cells: Vec::new(),
        };
        for (key, value) in case.into_inner() {
            let span = value.span();
            let value = value.into_inner();
            if key == "name" || key == "case" {
                match value {
                    Value::String(s) => {
                        row.name = Some(Cell {
                            text: s.clone(),
                            value: Value::String(s),
                            span,
                        })
                    }
                    v => errors.push(
                        table
                            .diagnostic(span, key.as_str(), "a case name is a string")
                            .value(v.to_string())
                            .hint("quote it: `name = \"long\"`"),
                    ),
                }
                continue;
            }
            let mut flat = Vec::new();
            leaves(key, value, &mut flat);
            for (key, value) in flat {
                found.push((span.start, key.clone()));
                row.cells.push((
                    usize::MAX,
                    Cell {
                        text: value.to_string(),
                        value,
                        span: span.clone(),
                    },
                ));
                // The key index is set below, once every key is known.
                let last = row.cells.len() - 1;
                row.cells[last].0 = found.len() - 1;
            }
        }
        rows.push(row);
    }
    if !errors.is_empty() {
        return Err(ScenarioError {
            diagnostics: errors,
        });
    }
    // Keys in the order they first appear in the file.
    let mut order: Vec<usize> = (0..found.len()).collect();
    order.sort_by_key(|&i| found[i].0);
    let mut keys: Vec<String> = Vec::new();
    for &i in &order {
        if !keys.contains(&found[i].1) {
            keys.push(found[i].1.clone());
        }
    }
    for row in &mut rows {
        for (k, _) in &mut row.cells {
            let key = &found[*k].1;
            *k = keys.iter().position(|x| x == key).expect("collected");
        }
    }
    table.keys = keys;
    Ok(rows)
}

/// A case with its overrides applied and validated: the name it was validated under, the
/// scenario text and the loaded scenario ([`with_overrides`]).
pub struct CaseScenario {
    /// The name it was validated under ([`crate::scenario::overrides::overridden_path`]).
    pub path: PathBuf,
    /// The scenario text with the overrides set.
    pub text: String,
    /// The loaded scenario.
    pub loaded: LoadedScenario,
}

/// Applies the overrides of `case` to the base scenario `base` (text `source`; `deck` the
/// choices for a MoorDyn deck, whose `duration` [s] sets every case's `simulation.duration`,
/// before the case's own keys, as `--duration` does for `hawser run`) and validates the
/// result. A refusal is reported at the table's
/// cell: each cell the base refuses on its own gets a diagnostic with the scenario's message,
/// expected unit and range, and hint; when no cell is refused alone, the row gets one with
/// the first of the scenario's diagnostics.
pub fn validate_case(
    base: &Path,
    source: &str,
    deck: &ConvertOptions,
    table: &CaseTable,
    case: &Case,
) -> Result<CaseScenario, Vec<Diagnostic>> {
    let leading: Vec<Override> = deck
        .duration
        .map(|d| ("simulation.duration".to_string(), Some(Value::Float(d))))
        .into_iter()
        .collect();
    let overrides = [leading.clone(), table.overrides(case)].concat();
    let e = match with_overrides(base, source, deck, &overrides) {
        Ok((path, text, loaded)) => return Ok(CaseScenario { path, text, loaded }),
        Err(e) => e,
    };
    let report = |span: Range<usize>, key: &str, value: &str, d: &Diagnostic| {
        let scenario_key = match d.key.is_empty() || d.key == key {
            true => String::new(),
            false => format!(" (scenario key `{}`)", d.key),
        };
        table
            .diagnostic(
                span,
                key,
                format!("case `{}`: {}{scenario_key}", case.name, d.message),
            )
            .value(value)
            .expected(d.expected.clone())
            .hint(d.hint.clone())
    };
    let mut out = Vec::new();
    for (key, cell) in table.keys.iter().zip(&case.cells) {
        let Some(cell) = cell else { continue };
        let alone = [
            leading.clone(),
            vec![(key.clone(), Some(cell.value.clone()))],
        ]
        .concat();
        if let Err(e) = with_overrides(base, source, deck, &alone) {
            out.push(report(
                cell.span.clone(),
                key,
                &cell.text,
                &e.diagnostics[0],
            ));
        }
    }
    if out.is_empty() {
        let d = &e.diagnostics[0];
        let mut d = report(case.span.clone(), &d.key, &d.value, d);
        d.hint = format!(
            "{}{}the overrides of this row are refused together, not one by one",
            d.hint,
            if d.hint.is_empty() { "" } else { "; " }
        );
        out.push(d);
    }
    Err(out)
}

/// How a case of a sweep ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CaseStatus {
    /// It ran to its end and wrote its files.
    Complete,
    /// It stopped with an error (statics, a divergence, a file not written).
    Failed,
    /// Ctrl-C or SIGTERM stopped it; its files hold the results so far.
    Interrupted,
    /// The sweep was stopped before it started.
    NotRun,
}

impl CaseStatus {
    /// The word in the summary table.
    pub fn name(self) -> &'static str {
        match self {
            Self::Complete => "complete",
            Self::Failed => "failed",
            Self::Interrupted => "interrupted",
            Self::NotRun => "not_run",
        }
    }
}

/// What a case came to, for its row of the summary table.
#[derive(Clone, Debug)]
pub struct CaseOutcome {
    /// How it ended.
    pub status: CaseStatus,
    /// Why it failed or stopped.
    pub error: Option<String>,
    /// Its `summary.json`, when it wrote one.
    pub summary: Option<Json>,
}

/// The extremes of a case as columns of the summary table, from its `summary.json`: per
/// channel `CHANNEL.min`, `.max`, `.mean`, `.std` and `.most_probable_maximum` (the design
/// statistics over the statistics window, in the channel's unit); per line `LINE.max_tension`
/// [N] (the largest node tension over the window), `LINE.design_utilisation` (of its worst
/// section: largest tension over MBL/SF; `None` without an MBL), and the counts
/// `LINE.slack_intervals` and `LINE.snap_events`.
pub fn extremes(summary: &Json) -> Vec<(String, Option<Real>)> {
    let mut out = Vec::new();
    if let Some(channels) = summary["channels"].as_object() {
        for (name, s) in channels {
            for stat in ["min", "max", "mean", "std", "most_probable_maximum"] {
                out.push((format!("{name}.{stat}"), s[stat].as_f64()));
            }
        }
    }
    if let Some(lines) = summary["lines"].as_object() {
        for (name, l) in lines {
            let max = l["strength"]["sections"]
                .as_array()
                .into_iter()
                .flatten()
                .filter_map(|s| s["max_tension"].as_f64())
                .reduce(Real::max);
            out.push((format!("{name}.max_tension"), max));
            out.push((
                format!("{name}.design_utilisation"),
                l["strength"]["worst"]["design_utilisation"].as_f64(),
            ));
            for count in ["slack_intervals", "snap_events"] {
                out.push((
                    format!("{name}.{count}"),
                    l[count].as_array().map(|a| a.len() as Real),
                ));
            }
        }
    }
    out
}

/// The summary table of `cases` (rows of `table`) and their `outcomes`: the columns `case`,
/// `status`, `error`, `end_time` [s] (the last sample written), one per override key (the
/// cells as written: numbers where every cell of the column is a number), and the
/// [`extremes`] of the complete cases (left empty for the others: a partial run's extremes
/// are not its result), in order of first appearance.
pub fn summary_columns(
    table: &CaseTable,
    cases: &[&Case],
    outcomes: &[CaseOutcome],
) -> Vec<(String, Column)> {
    let text =
        |f: &dyn Fn(usize) -> Option<String>| Column::Text((0..cases.len()).map(f).collect());
    let mut columns = vec![
        ("case".to_string(), text(&|i| Some(cases[i].name.clone()))),
        (
            "status".to_string(),
            text(&|i| Some(outcomes[i].status.name().to_string())),
        ),
        ("error".to_string(), text(&|i| outcomes[i].error.clone())),
        (
            "end_time".to_string(),
            Column::Number(
                outcomes
                    .iter()
                    .map(|o| o.summary.as_ref().and_then(|s| s["end_time"].as_f64()))
                    .collect(),
            ),
        ),
    ];
    for (k, key) in table.keys.iter().enumerate() {
        let cells: Vec<Option<&Cell>> = cases.iter().map(|c| c.cells[k].as_ref()).collect();
        let number = |c: &Cell| match c.value {
            Value::Float(x) => Some(x),
            Value::Integer(i) => Some(i as Real),
            _ => None,
        };
        let column = match cells.iter().flatten().all(|c| number(c).is_some()) {
            true => Column::Number(cells.iter().map(|c| c.and_then(number)).collect()),
            false => Column::Text(cells.iter().map(|c| c.map(|c| c.text.clone())).collect()),
        };
        columns.push((key.clone(), column));
    }
    let mut names: Vec<String> = Vec::new();
    let mut values: Vec<Vec<Option<Real>>> = Vec::new();
    for (i, o) in outcomes.iter().enumerate() {
        let (CaseStatus::Complete, Some(s)) = (o.status, &o.summary) else {
            continue;
        };
        for (name, x) in extremes(s) {
            let c = match names.iter().position(|n| *n == name) {
                Some(c) => c,
                None => {
                    names.push(name);
                    values.push(vec![None; cases.len()]);
                    names.len() - 1
                }
            };
            values[c][i] = x;
        }
    }
    columns.extend(
        names
            .into_iter()
            .zip(values)
            .map(|(n, v)| (n, Column::Number(v))),
    );
    columns
}

/// `text` as a CSV field: quoted (quotes doubled) when it holds a comma, a quote or a line
/// break, or has spaces at an end.
fn csv_field(out: &mut String, text: &str) {
    if text.contains([',', '"', '\n', '\r']) || text.trim() != text {
        out.push('"');
        out.push_str(&text.replace('"', "\"\""));
        out.push('"');
    } else {
        out.push_str(text);
    }
}

/// The summary table as CSV: a header of the column names, one row per case; numbers as the
/// run files write them (the shortest form that reads back to the same f64), empty cells for
/// missing values, text quoted where needed (RFC 4180).
pub fn summary_csv(columns: &[(String, Column)]) -> String {
    let mut out = String::new();
    for (c, (name, _)) in columns.iter().enumerate() {
        if c > 0 {
            out.push(',');
        }
        csv_field(&mut out, name);
    }
    out.push('\n');
    let rows = columns.first().map_or(0, |(_, c)| match c {
        Column::Text(v) => v.len(),
        Column::Number(v) => v.len(),
    });
    for r in 0..rows {
        for (c, (_, column)) in columns.iter().enumerate() {
            if c > 0 {
                out.push(',');
            }
            match column {
                Column::Text(v) => csv_field(&mut out, v[r].as_deref().unwrap_or("")),
                Column::Number(v) => {
                    if let Some(x) = v[r] {
                        push_number(&mut out, x);
                    }
                }
            }
        }
        out.push('\n');
    }
    out
}

/// Writes the summary table as `dir/STEM.csv` and, with `parquet`, `dir/STEM.parquet` (both
/// atomically); returns the files written.
pub fn write_summary(
    dir: &Path,
    stem: &str,
    columns: &[(String, Column)],
    parquet: bool,
) -> std::io::Result<Vec<PathBuf>> {
    let csv = dir.join(format!("{stem}.csv"));
    write_atomically(&csv, summary_csv(columns).as_bytes())?;
    // Without the `parquet` feature (the library alone) only the CSV is written.
    #[cfg_attr(not(feature = "parquet"), allow(unused_mut))]
    let mut written = vec![csv];
    if parquet {
        #[cfg(feature = "parquet")]
        {
            let path = dir.join(format!("{stem}.parquet"));
            let meta = [(
                "hawser.format_version".to_string(),
                crate::results::FORMAT_VERSION.to_string(),
            )];
            crate::results::write_columns_parquet(&path, columns, &meta)?;
            written.push(path);
        }
    }
    Ok(written)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn csv(text: &str) -> Result<CaseTable, ScenarioError> {
        parse_case_table(Path::new("cases.csv"), text)
    }

    #[test]
    fn csv_cells_are_toml_values_with_quotes_comments_and_empty_cells() {
        let t = csv(
            "\u{feff}# amplitudes\nname, lines.chain.length ,points.f.motion.amplitude,simulation.time_step\n\
             \n\
             short,690,\"[2.0, 0.0, 0.0]\",auto\r\n\
             , 700.5 ,,\"\"\"auto\"\"\"\n",
        )
        .unwrap();
        assert_eq!(
            t.keys,
            [
                "lines.chain.length",
                "points.f.motion.amplitude",
                "simulation.time_step"
            ]
        );
        assert_eq!(t.cases.len(), 2);
        let (a, b) = (&t.cases[0], &t.cases[1]);
        assert_eq!(a.name, "short");
        assert_eq!(b.name, "case_0002");
        assert_eq!(a.cells[0].as_ref().unwrap().value, Value::Integer(690));
        let amp = a.cells[1].as_ref().unwrap();
        assert_eq!(amp.text, "[2.0, 0.0, 0.0]");
        assert_eq!(&t.source[amp.span.clone()], "\"[2.0, 0.0, 0.0]\"");
        assert_eq!(amp.value.as_array().map(Vec::len), Some(3));
        assert_eq!(
            a.cells[2].as_ref().unwrap().value,
            Value::String("auto".into())
        );
        assert_eq!(b.cells[0].as_ref().unwrap().value, Value::Float(700.5));
        assert!(b.cells[1].is_none());
        assert_eq!(
            b.cells[2].as_ref().unwrap().value,
            Value::String("auto".into())
        );
        assert_eq!(t.overrides(b).len(), 2);
    }

    #[test]
    fn toml_tables_flatten_nested_keys_in_file_order() {
        let t = parse_case_table(
            Path::new("cases.toml"),
            "[[cases]]\nname = \"a\"\n\"lines.chain.length\" = 690.0\n\
             environment.waves.seed = 3\n\n[[cases]]\n\"lines.chain.length\" = 700.0\n",
        )
        .unwrap();
        assert_eq!(t.keys, ["lines.chain.length", "environment.waves.seed"]);
        assert_eq!(t.cases[0].name, "a");
        assert_eq!(t.cases[1].name, "case_0002");
        assert_eq!(
            t.cases[0].cells[1].as_ref().unwrap().value,
            Value::Integer(3)
        );
        assert!(t.cases[1].cells[1].is_none());
    }

    #[test]
    fn bad_tables_name_the_line_and_cell() {
        let e = csv("lines.chain.length,name\n690.0\n700,a/b\n1,x\n2,x\n").unwrap_err();
        let d = &e.diagnostics;
        assert_eq!(d.len(), 3, "{e}");
        assert_eq!(
            (d[0].line, d[0].message.as_str()),
            (2, "this row has 1 cells, the header 2")
        );
        assert_eq!(d[1].line, 3);
        assert!(d[1].message.contains("`a/b`"), "{}", d[1].message);
        assert_eq!(d[2].line, 5);
        assert!(d[2].hint.contains("line 4"), "{}", d[2].hint);
        let e = csv("name\nsweep_summary.csv\n").unwrap_err();
        assert!(e.diagnostics[0].message.contains("summary"), "{e}");
        let e = csv("a,a\n1,2\n").unwrap_err();
        assert!(e.diagnostics[0].message.contains("second column"), "{e}");
        let e = csv("a\n\"1,2\n").unwrap_err();
        assert!(e.diagnostics[0].message.contains("no closing quote"), "{e}");
        let e = csv("# nothing\n").unwrap_err();
        assert!(e.diagnostics[0].message.contains("no cases"), "{e}");
    }

    #[test]
    fn summary_csv_quotes_text_and_leaves_missing_values_empty() {
        let columns = vec![
            (
                "case".to_string(),
                Column::Text(vec![Some("a".into()), Some("b".into())]),
            ),
            (
                "error".to_string(),
                Column::Text(vec![None, Some("diverged at t = 1, \"x\"".into())]),
            ),
            ("x.max".to_string(), Column::Number(vec![Some(40.0), None])),
        ];
        assert_eq!(
            summary_csv(&columns),
            "case,error,x.max\na,,40.0\nb,\"diverged at t = 1, \"\"x\"\"\",\n"
        );
    }
}
